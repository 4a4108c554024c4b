// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_strategies/contact_mortar_updater.h"

#include <algorithm>
#include <chrono>
#include <unordered_set>
#include <vector>

#include "core/model/model_part.h"
#include "core/variables/kernel_variables.h"
#include "custom_conditions/contact_condition_utilities.h"
#include "custom_conditions/paired_condition.h"
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

void ContactMortarUpdater::ReleaseUncoveredNodes(ModelPart& model_part) {
  // The active set was decided at the gaps of the last iterate taken with the normals before it;
  // the new normals can take a node's whole overlap away (the bent clamp at 3 x the load, step 4:
  // 14 active nodes with NODAL_AREA 0.048 at the gap evaluation and 0 at the build). Active, such
  // a node's multiplier row has no entry (D_jj = 0, M row 0): the system is singular. Without a
  // master partner the node carries no contact, which is the inactive row (lambda_j = 0). Only
  // the pairs that hold an active node are integrated: they hold every overlap of such a node.
  ModelPart* pairs = FindContactPart(model_part, "ComputingContact");
  if (!pairs) return;
  std::vector<PairedCondition*> touched;
  for (Condition* pair : pairs->Conditions()) {
    auto* paired = dynamic_cast<PairedCondition*>(pair);
    if (!paired || !paired->IsActive()) continue;
    const auto& nodes = pair->GetGeometry().Nodes();
    if (std::any_of(nodes.begin(), nodes.end(), [](const Node* node) { return node->Is(ACTIVE); }))
      touched.push_back(paired);
  }
  if (touched.empty()) return;
  const auto start = std::chrono::steady_clock::now();
  struct Saved {
    Node* node;
    double gap, area;
    Array3 slip;
  };
  std::vector<Saved> saved;
  std::unordered_set<const Node*> seen;
  for (PairedCondition* pair : touched)
    for (Node* node : pair->GetGeometry().Nodes()) {
      if (!seen.insert(node).second) continue;
      const bool slip = node->HasSolutionStepValue(WEIGHTED_SLIP);
      saved.push_back({node, node->FastGetSolutionStepValue(WEIGHTED_GAP), node->GetValue(NODAL_AREA),
                       slip ? Array3(node->FastGetSolutionStepValue(WEIGHTED_SLIP)) : Array3(Array3::Zero())});
      node->SetValue(NODAL_AREA, 0.0);
    }
  const ProcessInfo& info = model_part.GetProcessInfo();
  for (PairedCondition* pair : touched) pair->AddExplicitContribution(info);
  for (const Saved& s : saved) {
    Node& node = *s.node;
    if (node.Is(ACTIVE) && node.GetValue(NODAL_AREA) <= 0.0) {
      node.Set(ACTIVE, false);
      node.Set(SLIP, false);
      node.Set(ISOLATED, true);
    }
    node.FastGetSolutionStepValue(WEIGHTED_GAP) = s.gap;
    node.SetValue(NODAL_AREA, s.area);
    if (node.HasSolutionStepValue(WEIGHTED_SLIP)) node.FastGetSolutionStepValue(WEIGHTED_SLIP) = s.slip;
  }
  timings_.weighted_gap += SecondsSince(start);
  ++timings_.weighted_gap_calls;
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
