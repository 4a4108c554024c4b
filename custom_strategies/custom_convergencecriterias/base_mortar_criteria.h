// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "core/parameters/parameters.h"
#include "core/solving/convergence_criteria.h"
#include "custom_utilities/active_set_utilities.h"
#include "custom_utilities/mortar_updater.h"

namespace mc {

/// "base_mortar_criteria": keeps the mortar quantities of the "Contact" sub-model-part in step
/// with the iterate and runs the active-set update of the derived class.
///
///  - PreCriteria (before each build): nodal normals at the current coordinates (always; see the
///    .cpp); weighted gap when ProcessInfo[ADAPT_PENALTY] is set or the problem is dynamic
///    (VELOCITY is historical); dynamic factor (`compute_dynamic_factor`, dynamic problems) and
///    adapted penalty, all through the MortarUpdater.
///  - PostCriteria (after each update): WEIGHTED_GAP is copied to history step 1, zeroed and
///    recomputed at the updated coordinates, then UpdateActiveSet of the derived class runs if
///    the computing model part Is(INTERACTION) (full semi-smooth Newton) or at iteration 1
///    (simplified semi-smooth Newton, the set is frozen afterwards). Converged when no node
///    changed, neither ACTIVE nor (frictional formulations, HasSlipSet) SLIP; ProcessInfo
///    [ACTIVE_SET_CONVERGED] stores that answer and [SLIP_SET_CONVERGED] whether no node
///    switched between stick and slip.
///
/// Settings, keys of Kratos' contact_settings: `compute_dynamic_factor` (false: the MortarUpdater
/// of the contact solver does not compute the factor, so true warns), `gidio_debug` (false:
/// per-iteration dumps are not written, true warns), `print_convergence_criterion` (false).
class BaseMortarConvergenceCriteria : public ConvergenceCriteria {
 public:
  static Parameters GetDefaultParameters();
  /// Reads its keys from `settings` (the solver's validated contact_settings, or any object:
  /// missing keys are added with their defaults; the owner of the block rejects unknown ones).
  explicit BaseMortarConvergenceCriteria(Parameters settings = Parameters());

  std::string Name() const override { return "base_mortar_criteria"; }
  bool PreCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                   const Vector& b) override;
  bool PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                    const Vector& b) override;
  /// {"active set changes", ACTIVE changes at the last check, 0} and, with a slip set,
  /// {"slip set changes", SLIP changes, 0}.
  std::vector<CriterionValue> LastValues() const override;
  /// Whether the formulation has a stick/slip set (frictional): the SLIP/STICK CONV column.
  virtual bool HasSlipSet() const noexcept { return false; }

  void SetMortarUpdater(std::shared_ptr<MortarUpdater> updater) noexcept { updater_ = std::move(updater); }
  const std::shared_ptr<MortarUpdater>& GetMortarUpdater() const noexcept { return updater_; }
  /// Ids of the slave nodes that changed state (ACTIVE or SLIP) at the last evaluation of the set.
  const ActiveSetUtilities::ChangedNodes& LastChangedNodes() const noexcept { return changed_; }
  /// Nodes that switched ACTIVE at the last check.
  std::size_t LastChangeCount() const noexcept { return changes_.active; }
  /// Active nodes that switched between stick and slip at the last check (0 without friction).
  std::size_t LastSlipChangeCount() const noexcept { return changes_.slip; }
  /// What the next PostCriteria would make of the set at the current coordinates, done to the nodes
  /// and not recorded: the weighted gap recomputed, then (full semi-smooth Newton only) the set
  /// updated. The contact strategy's line search evaluates its trial points with it and restores
  /// the nodes afterwards.
  ActiveSetUtilities::SetChanges TrialActiveSet(ModelPart& model_part);
  bool ComputeDynamicFactor() const noexcept { return compute_dynamic_factor_; }
  bool PrintConvergenceCriterion() const noexcept { return print_; }

 protected:
  using SetChanges = ActiveSetUtilities::SetChanges;
  /// The NCP update of the derived formulation on the contact sub-model-part; returns what
  /// changed (the frictionless ones: ACTIVE only). The base class has no active set.
  virtual SetChanges UpdateActiveSet(ModelPart& contact_part, ActiveSetUtilities::ChangedNodes* changed) {
    if (changed) changed->clear();
    return {};
  }

 private:
  std::shared_ptr<MortarUpdater> updater_;
  ActiveSetUtilities::ChangedNodes changed_;
  SetChanges changes_;
  bool compute_dynamic_factor_ = false;
  bool print_ = false;
};

}  // namespace mc
