// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_strategies/custom_convergencecriterias/base_mortar_criteria.h"

namespace mc {

/// "penalty_frictional_mortar_criteria": active set and stick/slip set of the penalty formulation
/// with Coulomb friction (ActiveSetUtilities::ComputePenaltyFrictionalActiveSet). Converged, and
/// ProcessInfo[ACTIVE_SET_CONVERGED], when the changes of both sets sum to zero
/// ([SLIP_SET_CONVERGED] still tells the stick/slip part apart). `pure_slip` (the PureSlip
/// formulations) keeps every active node slipping. Settings as the base class.
class PenaltyFrictionalMortarConvergenceCriteria : public BaseMortarConvergenceCriteria {
 public:
  explicit PenaltyFrictionalMortarConvergenceCriteria(Parameters settings = Parameters(), bool pure_slip = false)
      : BaseMortarConvergenceCriteria(std::move(settings)), pure_slip_(pure_slip) {}
  std::string Name() const override { return "penalty_frictional_mortar_criteria"; }
  bool HasSlipSet() const noexcept override { return true; }
  bool PureSlip() const noexcept { return pure_slip_; }

 protected:
  SetChanges UpdateActiveSet(ModelPart& contact_part, ActiveSetUtilities::ChangedNodes* changed) override {
    return ActiveSetUtilities::ComputePenaltyFrictionalActiveSet(contact_part, pure_slip_, echo_level_, changed);
  }

 private:
  bool pure_slip_;
};

}  // namespace mc
