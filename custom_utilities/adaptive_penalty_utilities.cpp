// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/adaptive_penalty_utilities.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/model/model_part.h"
#include "core/variables/kernel_variables.h"
#include "custom_utilities/contact_variables.h"

namespace mc::AdaptivePenaltyUtilities {

double AdaptedPenalty(double penalty, double gap, double previous_gap, double max_gap) {
  const double size = std::abs(gap);
  if (gap * previous_gap < 0.0) {
    if (std::abs(previous_gap) > max_gap)
      return std::abs(penalty * previous_gap / gap * (size + max_gap) / (gap - previous_gap));
    return std::abs(penalty * previous_gap / (10.0 * gap));
  }
  if (size <= max_gap) return penalty;
  const double growth = std::sqrt(size / max_gap - 1.0) + 1.0;
  if (std::abs(gap - previous_gap) > std::max({gap / 10.0, previous_gap, 5.0 * max_gap})) return 2.0 * penalty;
  if (size < 10.0 * max_gap) return penalty * growth * growth;
  if (size > 1.01 * std::abs(previous_gap)) return 2.0 * penalty * previous_gap / gap;
  return penalty * growth;
}

void AdaptNodalPenalties(ModelPart& contact_part) {
  const ProcessInfo& info = contact_part.GetProcessInfo();
  const bool first = info.GetValue(STEP) == 1 && info.GetValue(NL_ITERATION_NUMBER) == 1;
  const double common_penalty = info.GetValue(INITIAL_PENALTY);
  const double max_gap_factor = info.GetValue(MAX_GAP_FACTOR);
  for (Node* p_node : contact_part.Nodes()) {
    Node& node = *p_node;
    if (!node.Is(SLAVE)) continue;
    const double penalty = first || !node.Has(INITIAL_PENALTY) ? common_penalty : node.GetValue(INITIAL_PENALTY);
    const double area = node.GetValue(NODAL_AREA);
    if (!(area > std::numeric_limits<double>::epsilon())) {
      node.SetValue(INITIAL_PENALTY, penalty);
      continue;
    }
    const double h =
        node.HasSolutionStepValue(NODAL_H) ? node.FastGetSolutionStepValue(NODAL_H) : node.GetValue(NODAL_H);
    node.SetValue(INITIAL_PENALTY,
                  AdaptedPenalty(penalty, node.FastGetSolutionStepValue(WEIGHTED_GAP) / area,
                                 node.FastGetSolutionStepValue(WEIGHTED_GAP, 1) / area, max_gap_factor * h));
  }
}

}  // namespace mc::AdaptivePenaltyUtilities
