// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_strategies/custom_convergencecriterias/base_mortar_criteria.h"

namespace mc {

/// "penalty_frictionless_mortar_criteria": Active set of the penalty formulation: active when the weighted gap is
/// negative. Converged when no slave node changed state (see BaseMortarConvergenceCriteria for when the set is
/// evaluated). Settings as the base class.
class PenaltyFrictionlessMortarConvergenceCriteria : public BaseMortarConvergenceCriteria {
 public:
  explicit PenaltyFrictionlessMortarConvergenceCriteria(Parameters settings = Parameters())
      : BaseMortarConvergenceCriteria(std::move(settings)) {}
  std::string Name() const override { return "penalty_frictionless_mortar_criteria"; }

 protected:
  SetChanges UpdateActiveSet(ModelPart& contact_part, ActiveSetUtilities::ChangedNodes* changed) override {
    return {ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet(contact_part, changed), 0};
  }
};

}  // namespace mc
