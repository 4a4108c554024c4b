// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/active_set_utilities.h"

#include "core/model/model_part.h"
#include "core/utilities/logger.h"
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

/// The frictional update shared by ALM (`alm`: vector multiplier, k from the ProcessInfo) and
/// penalty (no multiplier: k = 0, lbar_t = c_tau eps s, no hysteresis, no slip augmentation).
SetChanges UpdateFrictionalSet(ModelPart& contact_part, bool alm, bool pure_slip, int echo_level,
                               ChangedNodes* changed) {
  const ProcessInfo& info = contact_part.GetProcessInfo();
  const double k = alm ? info.GetValue(SCALE_FACTOR) : 0.0;
  const double common_penalty = info.GetValue(INITIAL_PENALTY);
  const double tangent_factor = info.GetValue(TANGENT_FACTOR);
  const double slip_factor = alm ? info.GetValue(SLIP_AUGMENTATION_COEFFICIENT) * tangent_factor : tangent_factor;
  const double slip_threshold = alm ? info.GetValue(SLIP_THRESHOLD) : 0.0;
  const bool has_slip = contact_part.HasNodalSolutionStepVariable(WEIGHTED_SLIP);
  if (changed) changed->clear();
  SetChanges changes;
  for (Node* p_node : contact_part.Nodes()) {
    Node& node = *p_node;
    if (!node.Is(SLAVE)) continue;
    const double eps = node.Has(INITIAL_PENALTY) ? node.GetValue(INITIAL_PENALTY) : common_penalty;
    const Array3 normal = node.FastGetSolutionStepValue(NORMAL);
    const Array3 multiplier =
        alm ? Array3(node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER)) : Array3(Array3::Zero());
    const double augmented_normal =
        AugmentedNormalPressure(k, normal.dot(multiplier), eps, node.FastGetSolutionStepValue(WEIGHTED_GAP));
    node.SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, augmented_normal);
    const bool was_active = node.Is(ACTIVE);
    const bool was_slip = node.Is(SLIP);
    // ISOLATED: outside every mortar overlap, see UpdateActiveSet.
    const bool active = IsActive(augmented_normal) && !node.Is(ISOLATED);
    node.Set(ACTIVE, active);
    if (!active) {
      // An open node neither sticks nor slips, and carries no slip into its next contact.
      node.Set(SLIP, false);
      if (has_slip) node.FastGetSolutionStepValue(WEIGHTED_SLIP).setZero();
      node.SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, Array3::Zero());
      if (was_active) {
        ++changes.active;
        if (changed) changed->push_back(node.Id());
      }
      continue;
    }
    const double mu = node.GetValue(FRICTION_COEFFICIENT);
    const double bound = FrictionBound(
        mu, node.Has(TRESCA_FRICTION_THRESHOLD) ? node.GetValue(TRESCA_FRICTION_THRESHOLD) : 0.0, augmented_normal);
    const Array3 slip = has_slip ? Array3(node.FastGetSolutionStepValue(WEIGHTED_SLIP)) : Array3(Array3::Zero());
    const Array3 augmented_tangent = AugmentedTangentPressure(k, TangentialPart(multiplier, normal),
                                                              was_slip ? slip_factor : tangent_factor, eps, slip);
    if (!was_active) {
      ++changes.active;
      // The multiplier the node starts from reproduces the augmented pressures: k lambda = lbar.
      if (alm)
        node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) =
            ActivationPressure(k, augmented_normal) * normal +
            (bound > 0.0 ? Array3(augmented_tangent / k) : Array3(Array3::Zero()));
    }
    const double theta = SlipTestFactor(was_slip, slip_threshold);
    const bool slips = IsSlip(augmented_tangent.norm(), bound, theta);
    Array3 traction = augmented_tangent;
    if (slips) {
      // ALM: along the tangential multiplier (after a possible activation), else along lbar_t.
      const Array3 along =
          alm ? TangentialPart(node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER), normal) : augmented_tangent;
      traction = FrictionLimit(bound, along.norm() > 0.0 ? along : augmented_tangent);
    }
    node.SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, traction);
    bool slip_now = slips;
    if (pure_slip) {
      if (!slips && echo_level >= 1)
        Logger::Warning(Concat("pure slip: slave node ", node.Id(), " would stick (|lbar_t| = ",
                               augmented_tangent.norm(), " <= its friction bound ", bound, "); kept slipping"));
      slip_now = true;
    }
    node.Set(SLIP, slip_now);
    const bool slip_changed = !pure_slip && slip_now != was_slip;
    if (slip_changed) ++changes.slip;
    if (changed && (slip_changed || !was_active)) changed->push_back(node.Id());
  }
  return changes;
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

SetChanges ComputeALMFrictionalActiveSet(ModelPart& contact_part, bool pure_slip, int echo_level,
                                         ChangedNodes* changed) {
  return UpdateFrictionalSet(contact_part, true, pure_slip, echo_level, changed);
}

SetChanges ComputePenaltyFrictionalActiveSet(ModelPart& contact_part, bool pure_slip, int echo_level,
                                             ChangedNodes* changed) {
  return UpdateFrictionalSet(contact_part, false, pure_slip, echo_level, changed);
}

}  // namespace mc::ActiveSetUtilities
