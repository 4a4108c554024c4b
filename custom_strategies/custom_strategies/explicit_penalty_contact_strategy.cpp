// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_strategies/explicit_penalty_contact_strategy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "core/model/model_part.h"
#include "core/variables/kernel_variables.h"
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"
#include "custom_utilities/active_set_utilities.h"
#include "custom_utilities/contact_output_utilities.h"
#include "custom_utilities/contact_variables.h"

namespace mc {

ExplicitPenaltyContactStrategy::ExplicitPenaltyContactStrategy(ModelPart& model_part,
                                                               std::shared_ptr<ExplicitCentralDifferencesScheme> scheme,
                                                               std::shared_ptr<MortarUpdater> updater,
                                                               bool compute_reactions, bool move_mesh_flag,
                                                               bool pure_slip)
    // Penalty contact adds no DoFs: the DoF set and the lumped mass stay those of the elements.
    : ExplicitStrategy(model_part, std::move(scheme), compute_reactions, false, move_mesh_flag),
      updater_(std::move(updater)),
      pure_slip_(pure_slip) {
  if (!updater_) throw Error("the explicit penalty contact strategy needs a mortar updater");
}

void ExplicitPenaltyContactStrategy::Initialize() {
  ExplicitStrategy::Initialize();
  // The contact processes set CONTACT when they build the interface; Kratos then takes its first
  // step with delta_time_factor_for_contact although nothing touches yet.
  model_part_.GetRootModelPart().Set(CONTACT, false);
  frictional_ = model_part_.GetRootModelPart().Is(SLIP);
  if (frictional_ && model_part_.GetBufferSize() < 3)
    throw InputError(
        Concat("explicit frictional contact reads the slip of the previous step and the coordinates of "
               "the one before from the buffer: solver_settings.buffer_size must be at least 3, got ",
               model_part_.GetBufferSize()));
  model_part_.GetProcessInfo().SetValue(ACCUMULATED_WEIGHTED_SLIP, frictional_);
}

void ExplicitPenaltyContactStrategy::UpdateBeforeResidual() {
  ModelPart* contact = FindContactModelPart(model_part_);
  if (!contact) return;
  updater_->UpdateNormals(model_part_);
  RecomputeWeightedGap(model_part_, *contact, *updater_);
  if (frictional_)
    UpdateFrictionalState(*contact);
  else
    ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet(*contact);
  model_part_.GetRootModelPart().Set(CONTACT,
                                     std::any_of(contact->Nodes().begin(), contact->Nodes().end(),
                                                 [](const Node* node) { return node->Is(SLAVE) && node->Is(ACTIVE); }));
}

void ExplicitPenaltyContactStrategy::UpdateAfterResidual() {
  // clear_inactive_for_post is the process's: it clears at the end of the step.
  if (ModelPart* contact = FindContactModelPart(model_part_)) ComputeContactOutputs(*contact, false);
}

void ExplicitPenaltyContactStrategy::UpdateFrictionalState(ModelPart& contact) const {
  // RecomputeWeightedGap left this step's increment in WEIGHTED_SLIP.
  for (Node* node : contact.Nodes()) {
    if (!node->Is(SLAVE)) continue;
    const Array3 normal = node->FastGetSolutionStepValue(NORMAL);
    node->FastGetSolutionStepValue(WEIGHTED_SLIP) +=
        ActiveSetUtilities::TangentialPart(node->FastGetSolutionStepValue(WEIGHTED_SLIP, 1), normal);
  }
  ActiveSetUtilities::ComputePenaltyFrictionalActiveSet(contact, pure_slip_);
  const ProcessInfo& info = contact.GetProcessInfo();
  const double tangent_factor = info.GetValue(TANGENT_FACTOR);
  for (Node* node : contact.Nodes()) {
    if (!node->Is(SLAVE) || !node->Is(ACTIVE) || !node->Is(SLIP)) continue;
    const double eps = node->Has(INITIAL_PENALTY) ? node->GetValue(INITIAL_PENALTY) : info.GetValue(INITIAL_PENALTY);
    node->FastGetSolutionStepValue(WEIGHTED_SLIP) =
        node->GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE) / (tangent_factor * eps);
  }
}

double ExplicitPenaltyContactStrategy::ContactStableTimeStep(double element_time_step) const {
  ModelPart* contact = FindContactModelPart(const_cast<ModelPart&>(model_part_));
  const double omega_e = 2.0 / element_time_step;
  if (!contact) return element_time_step;
  const ProcessInfo& info = model_part_.GetProcessInfo();
  // Each slave node's share of the slave faces, for nodes not paired yet.
  std::unordered_map<const Node*, double> share;
  for (Condition* face : contact->Conditions()) {
    if (!face->Is(SLAVE)) continue;
    const Geometry& geometry = face->GetGeometry();
    const double part = geometry.DomainSize() / static_cast<double>(geometry.PointsNumber());
    for (const Node* node : geometry.Nodes()) share[node] += part;
  }
  double master_mass = std::numeric_limits<double>::infinity();
  for (const Node* node : contact->Nodes())
    if (node->Is(MASTER) && node->Has(NODAL_MASS) && node->GetValue(NODAL_MASS) > 0.0)
      master_mass = std::min(master_mass, node->GetValue(NODAL_MASS));
  const double stiffness_factor = frictional_ ? std::max(1.0, info.GetValue(TANGENT_FACTOR)) : 1.0;
  double omega_c2 = 0.0;
  for (const Node* node : contact->Nodes()) {
    if (!node->Is(SLAVE) || !node->Has(NODAL_MASS) || !(node->GetValue(NODAL_MASS) > 0.0)) continue;
    const double eps = node->Has(INITIAL_PENALTY) ? node->GetValue(INITIAL_PENALTY) : info.GetValue(INITIAL_PENALTY);
    const double paired = node->Has(NODAL_AREA) ? node->GetValue(NODAL_AREA) : 0.0;
    const auto found = share.find(node);
    const double area = paired > 0.0 ? paired : (found != share.end() ? found->second : 0.0);
    const double inverse_mass =
        1.0 / node->GetValue(NODAL_MASS) + (std::isfinite(master_mass) ? 1.0 / master_mass : 0.0);
    omega_c2 = std::max(omega_c2, stiffness_factor * eps * area * area * inverse_mass);
  }
  return 2.0 / std::sqrt(omega_e * omega_e + omega_c2);
}

}  // namespace mc
