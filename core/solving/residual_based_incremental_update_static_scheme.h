// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/scheme.h"

namespace mc {

/// The static scheme: the local systems are the entities' own (tangent and residual) and an
/// iteration adds the increment to the free DoFs, u <- u + dx. The predictor keeps the values
/// of the previous step (prescribed DoFs carry what the processes imposed).
class ResidualBasedIncrementalUpdateStaticScheme : public Scheme {
 public:
  std::string Name() const override { return "static"; }
  bool PassesEntityLeftHandSide() const override { return true; }
};

}  // namespace mc
