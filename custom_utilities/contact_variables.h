// SPDX-License-Identifier: BSD-3-Clause
// Variables of the contact formulations (spec section 5), named as in Kratos so that settings,
// mdpa data and outputs carry over.
#pragma once

#include "core/variables/kernel_variables.h"

namespace mc {

// Nodal unknowns and their reactions.
MC_DECLARE_VARIABLE(double, LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
MC_DECLARE_ARRAY3_VARIABLE(VECTOR_LAGRANGE_MULTIPLIER);
MC_DECLARE_VARIABLE(double, SCALAR_LAGRANGE_MULTIPLIER);
MC_DECLARE_VARIABLE(double, WEIGHTED_SCALAR_RESIDUAL);
MC_DECLARE_ARRAY3_VARIABLE(WEIGHTED_VECTOR_RESIDUAL);

// Mortar-integrated kinematics.
MC_DECLARE_VARIABLE(double, WEIGHTED_GAP);
MC_DECLARE_ARRAY3_VARIABLE(WEIGHTED_SLIP);
MC_DECLARE_ARRAY3_VARIABLE(TANGENT_XI);
MC_DECLARE_ARRAY3_VARIABLE(TANGENT_ETA);
MC_DECLARE_VARIABLE(double, NORMAL_GAP);
MC_DECLARE_ARRAY3_VARIABLE(TANGENT_SLIP);
MC_DECLARE_ARRAY3_VARIABLE(AUXILIAR_COORDINATES);
MC_DECLARE_ARRAY3_VARIABLE(DELTA_COORDINATES);

// Tractions and post-processing.
MC_DECLARE_VARIABLE(double, AUGMENTED_NORMAL_CONTACT_PRESSURE);
MC_DECLARE_ARRAY3_VARIABLE(AUGMENTED_TANGENT_CONTACT_PRESSURE);
MC_DECLARE_ARRAY3_VARIABLE(CONTACT_FORCE);
MC_DECLARE_VARIABLE(double, CONTACT_PRESSURE);
MC_DECLARE_VARIABLE(double, NORMAL_CONTACT_STRESS);
MC_DECLARE_VARIABLE(double, TANGENTIAL_CONTACT_STRESS);
MC_DECLARE_VARIABLE(double, NODAL_PAUX);
MC_DECLARE_VARIABLE(double, NODAL_MAUX);

// Penalty, scaling and control (ProcessInfo, nodes, properties).
MC_DECLARE_VARIABLE(double, INITIAL_PENALTY);
MC_DECLARE_VARIABLE(double, SCALE_FACTOR);
MC_DECLARE_VARIABLE(double, DYNAMIC_FACTOR);
MC_DECLARE_VARIABLE(double, TANGENT_FACTOR);
MC_DECLARE_VARIABLE(double, SLIP_THRESHOLD);
MC_DECLARE_VARIABLE(double, SLIP_AUGMENTATION_COEFFICIENT);
MC_DECLARE_VARIABLE(double, OPERATOR_THRESHOLD);
MC_DECLARE_VARIABLE(double, ACTIVE_CHECK_FACTOR);
MC_DECLARE_VARIABLE(double, ZERO_TOLERANCE_FACTOR);
MC_DECLARE_VARIABLE(double, DISTANCE_THRESHOLD);
MC_DECLARE_VARIABLE(int, CONSIDER_NORMAL_VARIATION);
MC_DECLARE_VARIABLE(bool, ACTIVE_SET_CONVERGED);
MC_DECLARE_VARIABLE(bool, SLIP_SET_CONVERGED);
MC_DECLARE_VARIABLE(bool, ACTIVE_SET_COMPUTED);
MC_DECLARE_VARIABLE(bool, ADAPT_PENALTY);
/// ProcessInfo (ours), set by the explicit contact strategy: WEIGHTED_SLIP is the elastic slip a
/// node has accumulated while sticking (return-mapped when it slips), not the step's increment.
MC_DECLARE_VARIABLE(bool, ACCUMULATED_WEIGHTED_SLIP);
/// ProcessInfo (ours), set by mpc_contact_process: contact_type FrictionalPureSlip (every active node slips).
MC_DECLARE_VARIABLE(bool, PURE_SLIP);
MC_DECLARE_VARIABLE(double, MAX_GAP_FACTOR);
MC_DECLARE_VARIABLE(double, MAX_GAP_THRESHOLD);
MC_DECLARE_VARIABLE(int, INNER_LOOP_ITERATION);
/// Slave node, non-historical (ours): its contact state (bit 0 ACTIVE, bit 1 SLIP) at the end of
/// the last converged step, and in bits 2-3 at the end of the step before; read by the
/// extrapolating predictor. On the node rather than in the strategy so that a restart checkpoint
/// carries it.
MC_DECLARE_VARIABLE(int, CONVERGED_CONTACT_STATES);
MC_DECLARE_VARIABLE(double, REACTION_CHECK_STIFFNESS_FACTOR);
/// ProcessInfo: the registered mortar_type of the contact solver (ContactFormulation), which the
/// contact processes check theirs against.
MC_DECLARE_VARIABLE(std::string, MORTAR_TYPE);

// Properties.
MC_DECLARE_VARIABLE(int, INTEGRATION_ORDER_CONTACT);
MC_DECLARE_VARIABLE(bool, CONSIDER_TESSELLATION);
MC_DECLARE_VARIABLE(std::string, TYING_VARIABLE);
MC_DECLARE_VARIABLE(double, TRESCA_FRICTION_THRESHOLD);

}  // namespace mc
