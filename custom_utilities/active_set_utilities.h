// SPDX-License-Identifier: BSD-3-Clause
// Primal-dual active set of the frictionless mortar formulations (thesis eqs. 4.41-4.44).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/variables/value_types.h"

namespace mc {

class ModelPart;

/// The nodal complementarity logic of the semi-smooth Newton method, as small pure kernels
/// plus the loops that apply them to the SLAVE nodes of a contact model part.
///
/// Sign convention (Kratos'): the contact pressure lambda_n is negative in compression and the
/// weighted gap g is positive when open. With the scale factor k and the penalty eps, the
/// augmented pressure is  lambda_bar = k lambda_n + eps g  and a node is active (in contact)
/// exactly when lambda_bar < 0. The Karush-Kuhn-Tucker conditions lambda_n <= 0, g >= 0,
/// lambda_n g = 0 are the zero set of the NCP function below.
namespace ActiveSetUtilities {

/// lambda_bar = k lambda_n + eps g.
constexpr double AugmentedNormalPressure(double scale_factor, double normal_pressure, double penalty,
                                         double weighted_gap) noexcept {
  return scale_factor * normal_pressure + penalty * weighted_gap;
}

/// C(lambda_n, g) = k lambda_n - min(0, k lambda_n + eps g): zero iff the KKT conditions hold
/// (active branch: C = -eps g, the gap closes; inactive branch: C = k lambda_n, the pressure
/// vanishes).
constexpr double FrictionlessNcp(double scale_factor, double normal_pressure, double penalty,
                                 double weighted_gap) noexcept {
  return scale_factor * normal_pressure -
         std::min(0.0, AugmentedNormalPressure(scale_factor, normal_pressure, penalty, weighted_gap));
}

/// The state the NCP selects: compressive augmented pressure means contact.
constexpr bool IsActive(double augmented_pressure) noexcept { return augmented_pressure < 0.0; }

/// Pressure a node starts from when it switches on, so that k lambda_n = lambda_bar: the first
/// Newton step after the activation starts from a consistent contact pressure.
constexpr double ActivationPressure(double scale_factor, double augmented_pressure) noexcept {
  return augmented_pressure / scale_factor;
}

/// Nodes whose ACTIVE flag was changed by the last call of the functions below, if requested.
using ChangedNodes = std::vector<IndexType>;

/// Scalar ALM (LAGRANGE_MULTIPLIER_CONTACT_PRESSURE): for every SLAVE node of `contact_part`,
/// stores lambda_bar in AUGMENTED_NORMAL_CONTACT_PRESSURE (non-historical), sets ACTIVE from
/// its sign and, on activation, initialises the pressure to lambda_bar / k. The penalty eps is
/// the nodal INITIAL_PENALTY when the node has one, else ProcessInfo[INITIAL_PENALTY]; k is
/// ProcessInfo[SCALE_FACTOR]. Returns the number of nodes that changed state.
std::size_t ComputeALMFrictionlessActiveSet(ModelPart& contact_part, ChangedNodes* changed = nullptr);

/// Vector ALM (VECTOR_LAGRANGE_MULTIPLIER): lambda_n = NORMAL . lambda; on activation the
/// multiplier becomes NORMAL lambda_bar / k.
std::size_t ComputeALMFrictionlessComponentsActiveSet(ModelPart& contact_part, ChangedNodes* changed = nullptr);

/// Penalty: lambda_bar = eps g, i.e. the sign of the weighted gap.
std::size_t ComputePenaltyFrictionlessActiveSet(ModelPart& contact_part, ChangedNodes* changed = nullptr);

}  // namespace ActiveSetUtilities
}  // namespace mc
