// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_convergencecriterias/base_mortar_criteria.h"

#include "core/model/model_part.h"
#include "core/parameters/no_effect_warnings.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"
#include "custom_utilities/contact_variables.h"

namespace mc {

Parameters BaseMortarConvergenceCriteria::GetDefaultParameters() {
  return Parameters(R"({
      "compute_dynamic_factor"      : false,
      "gidio_debug"                 : false,
      "print_convergence_criterion" : false
  })");
}

BaseMortarConvergenceCriteria::BaseMortarConvergenceCriteria(Parameters settings) {
  const Parameters defaults = GetDefaultParameters();
  settings.AddMissingParameters(defaults);
  compute_dynamic_factor_ = settings["compute_dynamic_factor"].GetBool();
  NoEffectWarnings::IfGiven(settings, defaults, "gidio_debug", "no per-iteration debug files are written");
  print_ = settings["print_convergence_criterion"].GetBool();
}

bool BaseMortarConvergenceCriteria::PreCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                                const Vector& dx, const Vector& b) {
  ModelPart* contact = FindContactModelPart(model_part);
  if (!contact || !updater_) return true;
  const ProcessInfo& info = model_part.GetProcessInfo();
  // The constraints live in the current configuration, so the nodal normals follow the mesh at
  // every iteration; CONSIDER_NORMAL_VARIATION only decides whether the tangent includes their
  // derivatives. (Kratos' text refreshes them only with normal variation, but its reference
  // results — e.g. the inclined patch test's contact pressure — match current normals.)
  updater_->UpdateNormals(model_part);
  const bool dynamic = model_part.HasNodalSolutionStepVariable(VELOCITY);
  const bool adapt_penalty = info.GetValue(ADAPT_PENALTY);
  if ((adapt_penalty || dynamic) && contact->HasNodalSolutionStepVariable(WEIGHTED_GAP))
    RecomputeWeightedGap(model_part, *contact, *updater_);
  if (dynamic && compute_dynamic_factor_) updater_->UpdateDynamicFactor(model_part);
  if (adapt_penalty) updater_->AdaptPenalty(model_part);
  return true;
}

bool BaseMortarConvergenceCriteria::PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                                 const Vector& dx, const Vector& b) {
  ModelPart* contact = FindContactModelPart(model_part);
  ProcessInfo& info = model_part.GetProcessInfo();
  changed_.clear();
  changes_ = {};
  if (!contact) {
    info.SetValue(ACTIVE_SET_CONVERGED, true);
    if (HasSlipSet()) info.SetValue(SLIP_SET_CONVERGED, true);
    return true;
  }
  if (contact->HasNodalSolutionStepVariable(WEIGHTED_GAP) && updater_) {
    if (contact->GetBufferSize() > 1)
      for (Node* node : contact->Nodes())
        node->FastGetSolutionStepValue(WEIGHTED_GAP, 1) = node->FastGetSolutionStepValue(WEIGHTED_GAP);
    RecomputeWeightedGap(model_part, *contact, *updater_);
  }
  if (model_part.Is(INTERACTION) || info.GetValue(NL_ITERATION_NUMBER) == 1)
    changes_ = UpdateActiveSet(*contact, &changed_);
  const bool converged = changes_.active + changes_.slip == 0;
  info.SetValue(ACTIVE_SET_CONVERGED, converged);
  if (HasSlipSet()) info.SetValue(SLIP_SET_CONVERGED, changes_.slip == 0);
  if (echo_level_ >= 1 && print_)
    Logger::Info(Concat(Name(), ": ", changes_.active, " slave node(s) changed contact state",
                        HasSlipSet() ? Concat(", ", changes_.slip, " changed between stick and slip") : ""));
  return converged;
}

ActiveSetUtilities::SetChanges BaseMortarConvergenceCriteria::TrialActiveSet(ModelPart& model_part) {
  ModelPart* contact = FindContactModelPart(model_part);
  if (!contact) return {};
  if (contact->HasNodalSolutionStepVariable(WEIGHTED_GAP) && updater_)
    RecomputeWeightedGap(model_part, *contact, *updater_);
  ActiveSetUtilities::ChangedNodes changed;
  return model_part.Is(INTERACTION) ? UpdateActiveSet(*contact, &changed) : SetChanges{};
}

std::vector<CriterionValue> BaseMortarConvergenceCriteria::LastValues() const {
  std::vector<CriterionValue> values{{"active set changes", static_cast<double>(changes_.active), 0.0}};
  if (HasSlipSet()) values.push_back({"slip set changes", static_cast<double>(changes_.slip), 0.0});
  return values;
}

}  // namespace mc
