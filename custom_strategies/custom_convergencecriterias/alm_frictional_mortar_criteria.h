// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/model/model_part.h"
#include "custom_strategies/custom_convergencecriterias/base_mortar_criteria.h"
#include "custom_utilities/contact_variables.h"

namespace mc {

/// "alm_frictional_mortar_criteria": active set and stick/slip set of the vector augmented
/// Lagrangian with Coulomb friction (ActiveSetUtilities::ComputeALMFrictionalActiveSet). The two
/// sets are reported separately: ProcessInfo[ACTIVE_SET_CONVERGED] when no node switched ACTIVE,
/// [SLIP_SET_CONVERGED] when no active node switched between stick and slip; converged when both
/// hold. `pure_slip` (the PureSlip formulations) keeps every active node slipping. Settings as
/// the base class.
class ALMFrictionalMortarConvergenceCriteria : public BaseMortarConvergenceCriteria {
 public:
  explicit ALMFrictionalMortarConvergenceCriteria(Parameters settings = Parameters(), bool pure_slip = false)
      : BaseMortarConvergenceCriteria(std::move(settings)), pure_slip_(pure_slip) {}
  std::string Name() const override { return "alm_frictional_mortar_criteria"; }
  bool HasSlipSet() const noexcept override { return true; }
  bool PureSlip() const noexcept { return pure_slip_; }

  bool PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                    const Vector& b) override {
    const bool converged = BaseMortarConvergenceCriteria::PostCriteria(model_part, dofs, A, dx, b);
    model_part.GetProcessInfo().SetValue(ACTIVE_SET_CONVERGED, LastChangeCount() == 0);
    return converged;
  }

 protected:
  SetChanges UpdateActiveSet(ModelPart& contact_part, ActiveSetUtilities::ChangedNodes* changed) override {
    return ActiveSetUtilities::ComputeALMFrictionalActiveSet(contact_part, pure_slip_, echo_level_, changed);
  }

 private:
  bool pure_slip_;
};

}  // namespace mc
