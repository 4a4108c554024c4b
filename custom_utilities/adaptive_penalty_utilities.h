// SPDX-License-Identifier: BSD-3-Clause
// The adapted augmented Lagrangian / adaptive penalty (ADAPT_PENALTY): every Newton iteration
// each slave node rescales its own penalty from the change of its gap (Bussetta, Marceau &
// Ponthot 2012, "The adapted augmented Lagrangian method"; Mataix's thesis, App. D.4.3.1).
#pragma once

namespace mc {

class ModelPart;

namespace AdaptivePenaltyUtilities {

/// The next penalty of a node from its current one `penalty`, its mean gaps (weighted gap over
/// nodal area) `gap` now and `previous_gap` one iteration before, and the gap it may keep,
/// `max_gap` = MAX_GAP_FACTOR x NODAL_H:
///  - the gap changed sign (the node crossed the surface): the penalty that would have stopped it
///    within max_gap, |eps g_p / g (|g| + max_gap) / (g - g_p)|, or |eps g_p / (10 g)| when the
///    previous gap was already within max_gap;
///  - the node stays penetrated (or open) by more than max_gap: 2 eps when the gap jumped by more
///    than max(g / 10, g_p, 5 max_gap); eps (sqrt(|g| / max_gap - 1) + 1)^2 while |g| < 10 max_gap;
///    2 eps g_p / g when the gap grew by more than 1 %; else eps (sqrt(|g| / max_gap - 1) + 1);
///  - otherwise eps is kept.
/// The comparisons are Kratos': the jump test takes g and g_p with their signs, and the second
/// test of the paper, |g| within 1 % of |g_p|, is written there as an "or" that always holds, so
/// that only |g| < 10 max_gap decides it. Both are kept, so that a Kratos case with adapt_penalty
/// runs through the same penalties.
double AdaptedPenalty(double penalty, double gap, double previous_gap, double max_gap);

/// Applies AdaptedPenalty to the nodal INITIAL_PENALTY of every SLAVE node of `contact_part` with a
/// positive NODAL_AREA, from its WEIGHTED_GAP now and in buffer position 1, with max_gap =
/// ProcessInfo[MAX_GAP_FACTOR] x NODAL_H. The first iteration of the first step starts from
/// ProcessInfo[INITIAL_PENALTY], later ones from the node's own value.
void AdaptNodalPenalties(ModelPart& contact_part);

}  // namespace AdaptivePenaltyUtilities

}  // namespace mc
