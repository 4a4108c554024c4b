// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/contact_output_utilities.h"

#include "custom_utilities/contact_variables.h"

namespace mc {

std::size_t ComputeContactOutputs(ModelPart& part, bool clear_inactive) {
  const bool has_gap = part.HasNodalSolutionStepVariable(WEIGHTED_GAP);
  std::size_t visited = 0;
  for (Node* p_node : part.Nodes()) {
    Node& node = *p_node;
    if (!node.Is(SLAVE)) continue;
    ++visited;
    const bool active = node.Is(ACTIVE);
    const double stress =
        active && node.Has(AUGMENTED_NORMAL_CONTACT_PRESSURE) ? node.GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE) : 0.0;
    const double area = node.Has(NODAL_AREA) ? node.GetValue(NODAL_AREA) : 0.0;
    node.SetValue(NORMAL_CONTACT_STRESS, stress);
    node.SetValue(CONTACT_PRESSURE, -stress);
    node.SetValue(TANGENTIAL_CONTACT_STRESS, active && node.Has(AUGMENTED_TANGENT_CONTACT_PRESSURE)
                                                 ? node.GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE).norm()
                                                 : 0.0);
    node.SetValue(CONTACT_FORCE, Array3(stress * area * node.FastGetSolutionStepValue(NORMAL)));
    if (has_gap && area > 0.0 && !node.Is(ISOLATED))
      node.SetValue(NORMAL_GAP, node.FastGetSolutionStepValue(WEIGHTED_GAP) / area);
    if (clear_inactive && !active) {
      node.SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, 0.0);
      if (node.Has(AUGMENTED_TANGENT_CONTACT_PRESSURE))
        node.SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, Array3::Zero().eval());
    }
  }
  return visited;
}

}  // namespace mc
