// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_strategies/custom_convergencecriterias/base_mortar_criteria.h"

namespace mc {

/// "alm_frictionless_mortar_criteria": Active set of the scalar augmented Lagrangian
/// (LAGRANGE_MULTIPLIER_CONTACT_PRESSURE): active when k lambda_n + eps g < 0. Converged when no slave node changed
/// state (see BaseMortarConvergenceCriteria for when the set is evaluated). Settings as the base class.
class ALMFrictionlessMortarConvergenceCriteria : public BaseMortarConvergenceCriteria {
 public:
  explicit ALMFrictionlessMortarConvergenceCriteria(Parameters settings = Parameters())
      : BaseMortarConvergenceCriteria(std::move(settings)) {}
  std::string Name() const override { return "alm_frictionless_mortar_criteria"; }

 protected:
  SetChanges UpdateActiveSet(ModelPart& contact_part, ActiveSetUtilities::ChangedNodes* changed) override {
    return {ActiveSetUtilities::ComputeALMFrictionlessActiveSet(contact_part, changed), 0};
  }
};

}  // namespace mc
