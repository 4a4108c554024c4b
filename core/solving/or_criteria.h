// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/combined_criteria.h"

namespace mc {

/// "or_criterion": converged when either criterion is (Kratos: residual OR displacement).
class OrCriteria : public CombinedCriteria {
 public:
  using CombinedCriteria::CombinedCriteria;
  std::string Name() const override { return "or_criterion"; }

 protected:
  bool Combine(bool a, bool b) const override { return a || b; }
};

}  // namespace mc
