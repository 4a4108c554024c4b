// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/combined_criteria.h"

namespace mc {

/// "and_criterion": converged when both criteria are (Kratos: residual AND displacement).
class AndCriteria : public CombinedCriteria {
 public:
  using CombinedCriteria::CombinedCriteria;
  std::string Name() const override { return "and_criterion"; }

 protected:
  bool Combine(bool a, bool b) const override { return a && b; }
};

}  // namespace mc
