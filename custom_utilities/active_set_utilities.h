// SPDX-License-Identifier: BSD-3-Clause
// Primal-dual active set of the mortar formulations: frictionless (thesis eqs. 4.41-4.44) and
// Coulomb frictional with its stick/slip set (eqs. 4.75-4.77).
#pragma once

#include <algorithm>
#include <cmath>
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

/// Coulomb and Tresca friction. With the unit normal n, the tangential multiplier lambda_t = lambda - (n . lambda) n
/// and the weighted slip s (tangential), the augmented tangent pressure is
///   lbar_t = k lambda_t + c eps s,   c = c_tau (stick node), c_slip c_tau (slip node)
/// (k = 0 and c = c_tau for the penalty formulation). The node slips when |lbar_t| exceeds the
/// friction bound b (FrictionBound) times theta, theta = 1 for a sticking node and 1 - SLIP_THRESHOLD for
/// one that already slips: the small hysteresis keeps a node at the limit from chattering.

/// The part of `v` orthogonal to the unit `normal`.
inline Array3 TangentialPart(const Array3& v, const Array3& normal) { return v - normal.dot(v) * normal; }

/// lbar_t = k lambda_t + c eps s.
inline Array3 AugmentedTangentPressure(double scale_factor, const Array3& tangent_multiplier, double coefficient,
                                       double penalty, const Array3& weighted_slip) {
  return scale_factor * tangent_multiplier + coefficient * penalty * weighted_slip;
}

/// theta of the slip test: 1 for a sticking node, 1 - slip_threshold for a slipping one.
constexpr double SlipTestFactor(bool was_slip, double slip_threshold) noexcept {
  return was_slip ? 1.0 - slip_threshold : 1.0;
}

/// The largest tangent traction of a node: b = tau - mu lbar_n (Coulomb: tau = 0; Tresca: mu = 0,
/// tau = TRESCA_FRICTION_THRESHOLD, whatever the normal pressure).
constexpr double FrictionBound(double friction_coefficient, double friction_threshold,
                               double augmented_normal_pressure) noexcept {
  return friction_threshold - friction_coefficient * augmented_normal_pressure;
}

/// |lbar_t| > theta b. Without friction (b = 0) the node slips whatever its tangent pressure, zero
/// included: nothing can hold it. (Kratos 10.4 divides |lbar_t| by mu |lbar_n|, so a frictionless
/// node with a zero lbar_t, e.g. just activated, tests 0 / 0 and sticks: held by a stick
/// constraint it does not have.)
inline bool IsSlip(double tangent_pressure_norm, double friction_bound, double theta) noexcept {
  return !(friction_bound > 0.0) || tangent_pressure_norm > theta * friction_bound;
}

/// The tangent traction of a slipping node: the bound b along `direction` (normalised here; a
/// zero direction gives a zero traction).
inline Array3 FrictionLimit(double friction_bound, const Array3& direction) {
  const double norm = direction.norm();
  if (!(norm > 0.0)) return Array3::Zero();
  return (friction_bound / norm) * direction;
}

/// What an update changed: nodes that switched ACTIVE and (frictional formulations) active nodes
/// that switched between stick and slip (SLIP).
struct SetChanges {
  std::size_t active = 0;
  std::size_t slip = 0;
};

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

/// Vector ALM with friction, on the SLAVE nodes of `contact_part`: AUGMENTED_NORMAL_CONTACT_PRESSURE
/// and AUGMENTED_TANGENT_CONTACT_PRESSURE (non-historical) as above, ACTIVE from lbar_n; a node that
/// switches on starts from lambda = n lbar_n / k + lbar_t / k (normal part only when mu = 0). An
/// active node is set SLIP by the slip test, and then its tangent pressure is stored at the
/// friction bound along its tangential multiplier. With `pure_slip` every active node is SLIP
/// (a node the test finds sticking is reported at echo level >= 1) and no stick/slip change is
/// counted. Inactive nodes lose SLIP and their WEIGHTED_SLIP. FRICTION_COEFFICIENT and
/// TRESCA_FRICTION_THRESHOLD (0 when absent) are nodal (non-historical); TANGENT_FACTOR, SLIP_THRESHOLD,
/// SLIP_AUGMENTATION_COEFFICIENT come from the ProcessInfo (the last two 0 when absent). `changed`: the nodes whose
/// ACTIVE or SLIP changed.
SetChanges ComputeALMFrictionalActiveSet(ModelPart& contact_part, bool pure_slip, int echo_level = 0,
                                         ChangedNodes* changed = nullptr);

/// Penalty with friction: lbar_n = eps g, lbar_t = c_tau eps s, slip when |lbar_t| > theta b; otherwise as
/// ComputeALMFrictionalActiveSet, the slip traction directed along lbar_t.
SetChanges ComputePenaltyFrictionalActiveSet(ModelPart& contact_part, bool pure_slip, int echo_level = 0,
                                             ChangedNodes* changed = nullptr);

}  // namespace ActiveSetUtilities
}  // namespace mc
