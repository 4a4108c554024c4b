// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_convergencecriterias/mpc_contact_criteria.h"

#include <cmath>

#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/normal_calculation_utilities.h"

namespace mc {

namespace {

double YoungModulus(const ModelPart& root) {
  for (const Element* element : root.Elements())
    if (element->HasProperties() && element->GetProperties().Has(YOUNG_MODULUS))
      return element->GetProperties().GetValue(YOUNG_MODULUS);
  return 0.0;
}

}  // namespace

MPCContactCriteria::MPCContactCriteria(std::shared_ptr<const MPCContactConstraints> constraints)
    : constraints_(std::move(constraints)) {
  if (!constraints_) throw Error("mpc_contact_criteria needs the MPC contact constraints");
}

bool MPCContactCriteria::PostCriteria(ModelPart& model_part, const DofsArray&, const SparseMatrix&, const Vector&,
                                      const Vector&) {
  ModelPart* contact = FindContactModelPart(model_part);
  if (!contact) throw Error(Concat("mpc_contact_criteria: no Contact model part above ", model_part.FullName()));
  const ModelPart& root = model_part.GetRootModelPart();
  const ProcessInfo& info = root.GetProcessInfo();
  const double factor =
      info.Has(REACTION_CHECK_STIFFNESS_FACTOR) ? info.GetValue(REACTION_CHECK_STIFFNESS_FACTOR) : 1.0e-12;
  const double threshold = -factor * YoungModulus(root);
  changes_ = 0;
  const bool frictional = constraints_->IsFrictional();
  for (Node* node : contact->Nodes()) {
    if (!node->Is(SLAVE)) continue;
    const double area = node->GetValue(NODAL_MAUX);
    const Array3 normal =
        frictional ? constraints_->RelationNormal(*node) : NormalCalculationUtilities::GetNodalNormal(*node);
    const Array3 reaction = node->FastGetSolutionStepValue(REACTION);
    const double force = reaction.dot(normal);
    const double pressure = area > 0.0 ? force / area : 0.0;
    const bool was_active = node->Is(ACTIVE);
    bool active = area > 0.0 && (was_active ? pressure < threshold : constraints_->NodalGap(*node) < 0.0);
    // A sticking node outside the cone slips before it may be released: its pull can be the drag of its
    // tangential tie (released, it would penetrate again and stick again: a cycle).
    if (frictional && was_active && !active && area > 0.0 && !node->Is(SLIP) &&
        (reaction - force * normal).norm() > node->GetValue(FRICTION_COEFFICIENT) * std::abs(force))
      active = true;
    if (active != was_active) ++changes_;
    node->Set(ACTIVE, active);
    node->SetValue(CONTACT_FORCE, active ? Array3(force * normal) : Array3(Array3::Zero()));
    node->SetValue(NORMAL_CONTACT_STRESS, active ? pressure : 0.0);
    if (frictional) UpdateSlip(*node, was_active, reaction - force * normal, force);
  }
  return changes_ == 0;
}

void MPCContactCriteria::UpdateSlip(Node& node, bool was_active, const Array3& tangential, double normal_force) {
  const bool active = node.Is(ACTIVE);
  const bool was_slipping = node.Is(SLIP);
  const double length = tangential.norm();
  bool slip = false;
  if (active && was_active) {
    const auto held = directions_.find(&node);
    if (was_slipping && held != directions_.end())
      slip = held->second.dot(constraints_->TangentialSlip(node)) > 0.0;
    else
      slip = length > node.GetValue(FRICTION_COEFFICIENT) * std::abs(normal_force);
    // A slipping node keeps its direction (2D: the slip can only reverse, and then the node sticks).
    if (!(was_slipping && slip && held != directions_.end()) && length > 0.0) directions_[&node] = -tangential / length;
  }
  if (!active) directions_.erase(&node);
  if (slip != was_slipping) ++changes_;
  node.Set(SLIP, slip);
  if (active) node.SetValue(CONTACT_FORCE, Array3(node.GetValue(CONTACT_FORCE) + tangential));
  node.SetValue(TANGENTIAL_CONTACT_STRESS,
                active && node.GetValue(NODAL_MAUX) > 0.0 ? length / node.GetValue(NODAL_MAUX) : 0.0);
}

std::vector<CriterionValue> MPCContactCriteria::LastValues() const {
  return {{"active set changes", static_cast<double>(changes_), 0.0}};
}

}  // namespace mc
