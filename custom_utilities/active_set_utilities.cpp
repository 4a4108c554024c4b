// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/active_set_utilities.h"

#include "core/model/model_part.h"
#include "custom_utilities/contact_variables.h"

namespace mc::ActiveSetUtilities {

namespace {

/// Applies `decide(node, k, eps) -> lambda_bar` to every SLAVE node, toggles ACTIVE (never on for
/// ISOLATED nodes) and calls
/// `activate(node, lambda_bar)` for the nodes that switch on. Serial: the change list and the
/// count are cheap next to the assembly, and the order of `changed` stays deterministic.
template <class Decide, class Activate>
std::size_t UpdateActiveSet(ModelPart& contact_part, ChangedNodes* changed, Decide&& decide, Activate&& activate) {
  const ProcessInfo& info = contact_part.GetProcessInfo();
  const double k = info.GetValue(SCALE_FACTOR);
  const double common_penalty = info.GetValue(INITIAL_PENALTY);
  if (changed) changed->clear();
  std::size_t count = 0;
  for (Node* p_node : contact_part.Nodes()) {
    Node& node = *p_node;
    if (!node.Is(SLAVE)) continue;
    const double eps = node.Has(INITIAL_PENALTY) ? node.GetValue(INITIAL_PENALTY) : common_penalty;
    const double augmented = decide(node, k, eps);
    node.SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, augmented);
    const bool was_active = node.Is(ACTIVE);
    // An ISOLATED slave node lies outside every mortar overlap: it cannot carry contact whatever
    // its multiplier says (a pressure left from an earlier step must not keep it active).
    const bool active = IsActive(augmented) && !node.Is(ISOLATED);
    node.Set(ACTIVE, active);
    if (active == was_active) continue;
    if (active) activate(node, k, augmented);
    ++count;
    if (changed) changed->push_back(node.Id());
  }
  return count;
}

}  // namespace

std::size_t ComputeALMFrictionlessActiveSet(ModelPart& contact_part, ChangedNodes* changed) {
  return UpdateActiveSet(
      contact_part, changed,
      [](Node& node, double k, double eps) {
        return AugmentedNormalPressure(k, node.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE), eps,
                                       node.FastGetSolutionStepValue(WEIGHTED_GAP));
      },
      [](Node& node, double k, double augmented) {
        node.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = ActivationPressure(k, augmented);
      });
}

std::size_t ComputeALMFrictionlessComponentsActiveSet(ModelPart& contact_part, ChangedNodes* changed) {
  return UpdateActiveSet(
      contact_part, changed,
      [](Node& node, double k, double eps) {
        const double normal_pressure =
            node.FastGetSolutionStepValue(NORMAL).dot(node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER));
        return AugmentedNormalPressure(k, normal_pressure, eps, node.FastGetSolutionStepValue(WEIGHTED_GAP));
      },
      [](Node& node, double k, double augmented) {
        const Array3 normal = node.FastGetSolutionStepValue(NORMAL);
        node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = ActivationPressure(k, augmented) * normal;
      });
}

std::size_t ComputePenaltyFrictionlessActiveSet(ModelPart& contact_part, ChangedNodes* changed) {
  return UpdateActiveSet(
      contact_part, changed,
      [](Node& node, double, double eps) {
        return AugmentedNormalPressure(0.0, 0.0, eps, node.FastGetSolutionStepValue(WEIGHTED_GAP));
      },
      [](Node&, double, double) {});
}

}  // namespace mc::ActiveSetUtilities
