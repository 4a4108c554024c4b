// SPDX-License-Identifier: BSD-3-Clause
// The adapted augmented Lagrangian / adaptive penalty (ADAPT_PENALTY): every Newton iteration
// each slave node rescales its own penalty from the change of its gap (Bussetta, Marceau &
// Ponthot 2012, "The adapted augmented Lagrangian method"; Mataix's thesis, App. D.4.3.1).
#pragma once

namespace mc {

class ModelPart;

namespace AdaptivePenaltyUtilities {

/// The next penalty of a node from its current one `penalty`, its mean gaps (weighted gap over
/// nodal area, negative when penetrating) `gap` now and `previous_gap` one answer before, and the
/// gap it may keep, `max_gap` = MAX_GAP_FACTOR x NODAL_H:
///  - |g| <= max_gap: eps is kept;
///  - open by more than max_gap after a penetration (bounced out): the penalty that would have
///    stopped it within max_gap, |eps g_p / g (|g| + max_gap) / (g - g_p)|, or |eps g_p / (10 g)|
///    when the previous gap was already within max_gap; open otherwise: eps is kept;
///  - penetrated by more than max_gap: 2 eps when the gap jumped by more than
///    max(|g| / 10, |g_p|, 5 max_gap); eps (sqrt(|g| / max_gap - 1) + 1)^2 while |g| < 10 max_gap;
///    2 eps |g_p / g| when |g| grew by more than 1 %; else eps (sqrt(|g| / max_gap - 1) + 1).
/// Where this differs from Kratos 10.4 (the same branches, tested in the other order, on signed
/// gaps) it is on purpose; on the dynamic stick patch Kratos' order made the penalty a ratio of
/// round-off gaps (4.9e19 for steps 1-9, then 2.6e9 at step 10: 64 max_gap of overlap):
///  - the band test comes first, so that no term divides by a gap within max_gap (a sign change of
///    round-off gaps multiplied eps by 1200 and then by 6.4e-9 in one step);
///  - a node that ends penetrated is never softened by the crossing formulas, which are meant for
///    a node pushed out (the crossing from 1e-3 max_gap open to 28.9 max_gap deep cut eps by
///    2.5e5); an open node's penalty, which pushes nothing, is not raised;
///  - the jump and growth tests compare sizes (Kratos compares signed gaps, so any change beyond
///    5 max_gap doubled eps: 8 iterations of doubling from 90 max_gap, and step 14 did not
///    converge).
double AdaptedPenalty(double penalty, double gap, double previous_gap, double max_gap);

/// Applies AdaptedPenalty to the nodal INITIAL_PENALTY of every SLAVE node of `contact_part` with a
/// positive NODAL_AREA, with max_gap = ProcessInfo[MAX_GAP_FACTOR] x NODAL_H, from gaps that
/// answer the node's penalty: the gap now, after a solve in which the node was ACTIVE, and the
/// previous such answer (the last iteration's, or at the second iteration of a step the last
/// step's converged gap). The first iteration of a step adapts nothing: its configuration is the
/// scheme's prediction (Bossak: u_n + dt v + dt^2/2 a), which no solve with this penalty produced;
/// Kratos compares it with the last converged gap and on the stick patch a predicted opening of
/// 8 max_gap after a converged -7e-7 max_gap divided eps by 1.2e8. Neither is a node's gap after a
/// solve in which it was inactive (no penalty acted on it). The first iteration of the first step
/// starts from ProcessInfo[INITIAL_PENALTY], later ones from the node's own value.
void AdaptNodalPenalties(ModelPart& contact_part);

}  // namespace AdaptivePenaltyUtilities

}  // namespace mc
