// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <unordered_map>

#include "core/solving/convergence_criteria.h"
#include "custom_strategies/custom_strategies/mpc_contact_constraints.h"

namespace mc {

/// "mpc_contact_criteria": the active set of the MPC contact route, from the reactions (there are no
/// multipliers). For every SLAVE node of Contact the normal contact force is f_n = REACTION . NORMAL
/// (REACTION of the slave's free DoFs: the force the constraint transmits, written by the MPC strategy
/// before the check), the pressure p_n = f_n / NODAL_MAUX and the gap g = the constraints' nodal gap.
/// An active node stays active while it is pressed, p_n < -REACTION_CHECK_STIFFNESS_FACTOR * E (E the
/// YOUNG_MODULUS of the first element's properties; factor 1e-12 when the ProcessInfo has none); an
/// inactive node becomes active when it penetrates, g < 0. Active nodes get CONTACT_FORCE = f_n n and
/// NORMAL_CONTACT_STRESS = p_n; inactive ones 0. Converged when no node changed.
///
/// Frictional (the constraints' IsFrictional; Coulomb, mu the node's FRICTION_COEFFICIENT, which the
/// interface sets from the materials or friction_coefficients), the normal is the relation's and the
/// node's whole reaction R splits into f_n n and R_t = R - f_n n. A node that becomes active sticks. A
/// sticking node slips when its tie needs more than the cone, |R_t| > mu |f_n| (and is not released in
/// that iteration even if it pulls: the pull may be the drag of its tangential tie); its slip direction is
/// then s = -R_t / |R_t| (the way the tie held it back). A slipping node carries the Coulomb force
/// -mu |f_n| s (MPCContactConstraints::CoulombTerms, in the system with its exact tangent) and sticks
/// again when its slip of the step no longer runs along s (s . slip <= 0: the friction would drive
/// it). Converged when no node changed its active or slip state. CONTACT_FORCE is R (normal and
/// tangential), TANGENTIAL_CONTACT_STRESS |R_t| / NODAL_MAUX. Kratos compares |R_t| / NODAL_MAUX, a
/// pressure, with -mu f_n, a force: here both sides are forces. Only 2D: in 3D the slip direction
/// would change within the step (not implemented, the process says so).
///
/// Differences from Kratos, by design: Kratos tests both conditions on every node, but an active
/// node's gap is the constraint's, zero up to round-off, whose sign would keep it (or not) at random;
/// Kratos adds the master reactions mapped onto the slave (times -1): in a master-slave elimination the
/// slave reaction is the whole contact force and the masters carry it again through T^T, so the sum
/// would count it twice (Kratos 10.4's own CONTACT_FORCE on mpc_contact_tests equals the slave
/// reaction); Kratos divides CONTACT_FORCE by NODAL_PAUX, here it is the nodal force itself.
class MPCContactCriteria : public ConvergenceCriteria {
 public:
  explicit MPCContactCriteria(std::shared_ptr<const MPCContactConstraints> constraints);

  std::string Name() const override { return "mpc_contact_criteria"; }
  bool PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                    const Vector& b) override;
  std::vector<CriterionValue> LastValues() const override;
  /// Active-set changes of the last PostCriteria.
  std::size_t Changes() const noexcept { return changes_; }
  /// Frictional: the unit slip direction s of every active node (of a sticking one, the way it would
  /// slip), held until the next PostCriteria.
  const std::unordered_map<const Node*, Array3>& SlipDirections() const noexcept { return directions_; }

 private:
  /// Frictional: the stick / slip state of a slave node from its tangential reaction (see the class
  /// comment).
  void UpdateSlip(Node& node, bool was_active, const Array3& tangential, double normal_force);

  std::shared_ptr<const MPCContactConstraints> constraints_;
  std::size_t changes_ = 0;
  std::unordered_map<const Node*, Array3> directions_;
};

}  // namespace mc
