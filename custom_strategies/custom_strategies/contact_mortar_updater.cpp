// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_strategies/contact_mortar_updater.h"

#include <chrono>

#include "core/model/model_part.h"
#include "core/variables/kernel_variables.h"
#include "custom_conditions/contact_condition_utilities.h"
#include "custom_utilities/adaptive_penalty_utilities.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/normal_calculation_utilities.h"

namespace mc {

namespace {
double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The contact sub-model-parts hang from the root; the strategies may solve on a sub-part.
ModelPart* FindContactPart(ModelPart& model_part, const char* name) {
  ModelPart& root = model_part.GetRootModelPart();
  return root.HasSubModelPart(name) ? &root.GetSubModelPart(name) : nullptr;
}
}  // namespace

void ContactMortarUpdater::ComputeWeightedGap(ModelPart& model_part) {
  ModelPart* pairs = FindContactPart(model_part, "ComputingContact");
  if (!pairs) return;
  const auto start = std::chrono::steady_clock::now();
  ContactConditionUtilities::ComputeExplicitContributions(*pairs, true);
  // A slave node outside the overlap of every pair (or covered by slivers alone) has no mortar
  // operators of its own: it cannot carry contact, so it is ISOLATED and inactive (its
  // multiplier row is then the inactive one).
  for (Condition* pair : pairs->Conditions())
    for (Node* node : pair->GetGeometry().Nodes()) {
      const bool isolated = node->GetValue(NODAL_AREA) <= 0.0;
      node->Set(ISOLATED, isolated);
      if (isolated) node->Set(ACTIVE, false);
    }
  timings_.weighted_gap += SecondsSince(start);
  ++timings_.weighted_gap_calls;
}

void ContactMortarUpdater::UpdateNormals(ModelPart& model_part) {
  ModelPart* interface = FindContactPart(model_part, "Contact");
  if (!interface) return;
  const auto start = std::chrono::steady_clock::now();
  NormalCalculationUtilities::ComputeNodalNormals(*interface);
  timings_.normals += SecondsSince(start);
  ++timings_.normals_calls;
}

void ContactMortarUpdater::UpdateDynamicFactor(ModelPart& model_part) {
  ModelPart* contact = FindContactPart(model_part, "Contact");
  const int step = model_part.GetProcessInfo().GetValue(STEP);
  if (!contact || !contact->HasNodalSolutionStepVariable(WEIGHTED_GAP) || contact->GetBufferSize() < 2 ||
      step == dynamic_factor_step_)
    return;
  dynamic_factor_step_ = step;
  for (Node* node : contact->Nodes()) {
    if (!node->Is(SLAVE)) continue;
    const double start = node->FastGetSolutionStepValue(WEIGHTED_GAP, 1);
    const double predicted = node->FastGetSolutionStepValue(WEIGHTED_GAP);
    const bool closes = node->GetValue(NODAL_AREA) > 0.0 && start > 0.0 && predicted < 0.0;
    node->SetValue(DYNAMIC_FACTOR, closes ? -predicted / (start - predicted) : 1.0);
  }
}

void ContactMortarUpdater::AdaptPenalty(ModelPart& model_part) {
  if (ModelPart* interface = FindContactPart(model_part, "Contact"))
    AdaptivePenaltyUtilities::AdaptNodalPenalties(*interface);
}

}  // namespace mc
