// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>

#include "core/model/model_part.h"

namespace mc {

/// The contact results of the SLAVE nodes of `part` (the "Contact" interface) at the state the
/// step's residual was built at: the converged one of an implicit step (the contact processes call
/// this at the end of the step), u_n of an explicit step (the explicit contact strategy calls it
/// right after the residual, before the update: the force that acted during the step). In the units
/// of the bodies' stresses (the multipliers are scaled by ProcessInfo[SCALE_FACTOR]; these are not).
/// Kratos 10.4 computes none of them in its implicit mortar formulations (measured: a requested
/// column is all zeros), so they are ours:
///
///  - NORMAL_CONTACT_STRESS: the normal traction on the slave body, negative in compression like
///    the multipliers, where ACTIVE (0 elsewhere). ALM formulations: the augmented pressure
///    lambda_bar = k lambda_n + eps g that the active set was decided on; at a converged active
///    node eps g is within the gap tolerance, so it is k lambda_n. Penalty: the normal force that
///    the pairs of ComputingContact apply to the node (their right-hand sides) over NODAL_AREA.
///    eps g, summed over the pairs, is not that traction: each pair applies eps times its own
///    share of the weighted gap, so where a node's mortar area is split among P pairs, eps g is
///    up to P times the traction (2.1 times on the Hertz cylinder).
///  - CONTACT_PRESSURE: -NORMAL_CONTACT_STRESS, the contact pressure (positive in compression).
///  - TANGENTIAL_CONTACT_STRESS: the magnitude of the tangential traction where ACTIVE, 0
///    elsewhere: |AUGMENTED_TANGENT_CONTACT_PRESSURE|, the augmented tangent pressure the stick /
///    slip state was decided on (k T(lambda) + c_tau eps s at a stick node, the Coulomb limit
///    mu |lambda_bar_n| at a slip node; penalty: c_tau eps s), in stress units like
///    NORMAL_CONTACT_STRESS. 0 for the frictionless formulations, which never set it.
///  - CONTACT_FORCE: NORMAL_CONTACT_STRESS NODAL_AREA NORMAL, the force on the slave body at the
///    node; summed over the interface it balances the reactions.
///  - NORMAL_GAP: WEIGHTED_GAP / NODAL_AREA, the mortar mean of the normal gap around the node at
///    the converged configuration, where the node has a mortar area (elsewhere the search's value
///    is kept). Kratos holds the gap its search measured at the start of the step, and only at
///    the nodes active then (0 at open ones), which says nothing about the converged state.
///
/// With `clear_inactive` (clear_inactive_for_post) the augmented tractions of the inactive slave
/// nodes (AUGMENTED_NORMAL_CONTACT_PRESSURE, AUGMENTED_TANGENT_CONTACT_PRESSURE) are set to 0:
/// there lambda_bar = eps g > 0 is the active-set indicator, not a pressure. Kratos clears them
/// only before the output processes write, so its json_output_process and
/// from_json_check_result_process still read eps g there; here every reader after the step sees 0.
/// Returns the number of slave nodes visited.
std::size_t ComputeContactOutputs(ModelPart& part, bool clear_inactive);

/// The clear_inactive part alone: AUGMENTED_NORMAL_CONTACT_PRESSURE and
/// AUGMENTED_TANGENT_CONTACT_PRESSURE set to 0 at the SLAVE nodes of `part` that are not ACTIVE.
void ClearInactiveContactPressures(ModelPart& part);

}  // namespace mc
