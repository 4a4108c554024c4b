// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/adaptive_penalty_utilities.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/model/model_part.h"
#include "core/variables/kernel_variables.h"
#include "custom_utilities/contact_variables.h"

namespace mc::AdaptivePenaltyUtilities {

namespace {

/// Non-historical memory of AdaptNodalPenalties: the last mean gap that answered the node's
/// penalty, and whether the node is active in the solve that follows the last call.
const Variable<double> kAnsweredGap("ADAPTIVE_PENALTY_ANSWERED_GAP");
const Variable<bool> kPressed("ADAPTIVE_PENALTY_PRESSED");

}  // namespace

double AdaptedPenalty(double penalty, double gap, double previous_gap, double max_gap) {
  const double size = std::abs(gap);
  if (size <= max_gap) return penalty;
  if (gap > 0.0) {
    if (previous_gap >= 0.0) return penalty;
    if (-previous_gap > max_gap)
      return std::abs(penalty * previous_gap / gap * (size + max_gap) / (gap - previous_gap));
    return std::abs(penalty * previous_gap / (10.0 * gap));
  }
  const double previous_size = std::abs(previous_gap);
  const double growth = std::sqrt(size / max_gap - 1.0) + 1.0;
  if (std::abs(gap - previous_gap) > std::max({size / 10.0, previous_size, 5.0 * max_gap})) return 2.0 * penalty;
  if (size < 10.0 * max_gap) return penalty * growth * growth;
  if (size > 1.01 * previous_size) return 2.0 * penalty * previous_size / size;
  return penalty * growth;
}

void AdaptNodalPenalties(ModelPart& contact_part) {
  const ProcessInfo& info = contact_part.GetProcessInfo();
  const bool first_iteration = info.GetValue(NL_ITERATION_NUMBER) == 1;
  const bool first = info.GetValue(STEP) == 1 && first_iteration;
  const bool predicted = first_iteration && info.GetValue(INNER_LOOP_ITERATION) <= 1;
  const double common_penalty = info.GetValue(INITIAL_PENALTY);
  const double max_gap_factor = info.GetValue(MAX_GAP_FACTOR);
  for (Node* p_node : contact_part.Nodes()) {
    Node& node = *p_node;
    if (!node.Is(SLAVE)) continue;
    const double penalty = first || !node.Has(INITIAL_PENALTY) ? common_penalty : node.GetValue(INITIAL_PENALTY);
    node.SetValue(INITIAL_PENALTY, penalty);
    const bool pressed = !predicted && node.Has(kPressed) && node.GetValue(kPressed);
    node.SetValue(kPressed, node.Is(ACTIVE));
    const double area = node.GetValue(NODAL_AREA);
    if (!(area > std::numeric_limits<double>::epsilon())) continue;
    if (predicted) {
      // Buffer 1 still holds the last step's converged gap (PostCriteria overwrites it later).
      node.SetValue(kAnsweredGap, node.FastGetSolutionStepValue(WEIGHTED_GAP, 1) / area);
      continue;
    }
    if (!pressed) continue;
    const double gap = node.FastGetSolutionStepValue(WEIGHTED_GAP) / area;
    const double previous_gap =
        node.Has(kAnsweredGap) ? node.GetValue(kAnsweredGap) : node.FastGetSolutionStepValue(WEIGHTED_GAP, 1) / area;
    const double h =
        node.HasSolutionStepValue(NODAL_H) ? node.FastGetSolutionStepValue(NODAL_H) : node.GetValue(NODAL_H);
    node.SetValue(INITIAL_PENALTY, AdaptedPenalty(penalty, gap, previous_gap, max_gap_factor * h));
    node.SetValue(kAnsweredGap, gap);
  }
}

}  // namespace mc::AdaptivePenaltyUtilities
