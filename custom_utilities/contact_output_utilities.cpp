// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/contact_output_utilities.h"

#include <unordered_map>

#include "core/variables/kernel_variables.h"
#include "custom_utilities/contact_variables.h"

namespace mc {

namespace {

/// The force that the pairs of ComputingContact apply to each SLAVE node (the displacement rows
/// of their right-hand sides).
std::unordered_map<const Node*, Array3> AppliedSlaveForces(ModelPart& part) {
  std::unordered_map<const Node*, Array3> forces;
  ModelPart& root = part.GetRootModelPart();
  if (!root.HasSubModelPart("ComputingContact")) return forces;
  const ProcessInfo& info = root.GetProcessInfo();
  DofsVectorType dofs;
  Vector rhs;
  for (Condition* condition : root.GetSubModelPart("ComputingContact").Conditions()) {
    if (!condition->IsActive()) continue;
    condition->GetDofList(dofs, info);
    condition->CalculateRightHandSide(rhs, info);
    for (std::size_t i = 0; i < dofs.size(); ++i) {
      const Dof& dof = *dofs[i];
      if (!dof.node->Is(SLAVE) || dof.variable->Source() != &DISPLACEMENT) continue;
      auto [entry, added] = forces.try_emplace(dof.node, Array3::Zero());
      entry->second[dof.variable->ComponentIndex()] += rhs[static_cast<Eigen::Index>(i)];
    }
  }
  return forces;
}

}  // namespace

std::size_t ComputeContactOutputs(ModelPart& part, bool clear_inactive) {
  const bool has_gap = part.HasNodalSolutionStepVariable(WEIGHTED_GAP);
  const bool multipliers = part.HasNodalSolutionStepVariable(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) ||
                           part.HasNodalSolutionStepVariable(VECTOR_LAGRANGE_MULTIPLIER);
  const auto applied = multipliers ? std::unordered_map<const Node*, Array3>{} : AppliedSlaveForces(part);
  std::size_t visited = 0;
  for (Node* p_node : part.Nodes()) {
    Node& node = *p_node;
    if (!node.Is(SLAVE)) continue;
    ++visited;
    const bool active = node.Is(ACTIVE);
    const double area = node.Has(NODAL_AREA) ? node.GetValue(NODAL_AREA) : 0.0;
    const Array3 normal = node.FastGetSolutionStepValue(NORMAL);
    double stress = 0.0;
    if (active && multipliers) {
      stress = node.Has(AUGMENTED_NORMAL_CONTACT_PRESSURE) ? node.GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE) : 0.0;
    } else if (active && area > 0.0) {
      const auto force = applied.find(&node);
      if (force != applied.end()) stress = force->second.dot(normal) / area;
    }
    node.SetValue(NORMAL_CONTACT_STRESS, stress);
    node.SetValue(CONTACT_PRESSURE, -stress);
    node.SetValue(TANGENTIAL_CONTACT_STRESS, active && node.Has(AUGMENTED_TANGENT_CONTACT_PRESSURE)
                                                 ? node.GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE).norm()
                                                 : 0.0);
    node.SetValue(CONTACT_FORCE, Array3(stress * area * normal));
    if (has_gap && area > 0.0 && !node.Is(ISOLATED))
      node.SetValue(NORMAL_GAP, node.FastGetSolutionStepValue(WEIGHTED_GAP) / area);
  }
  if (clear_inactive) ClearInactiveContactPressures(part);
  return visited;
}

void ClearInactiveContactPressures(ModelPart& part) {
  for (Node* node : part.Nodes()) {
    if (!node->Is(SLAVE) || node->Is(ACTIVE)) continue;
    node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, 0.0);
    if (node->Has(AUGMENTED_TANGENT_CONTACT_PRESSURE))
      node->SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, Array3::Zero().eval());
  }
}

}  // namespace mc
