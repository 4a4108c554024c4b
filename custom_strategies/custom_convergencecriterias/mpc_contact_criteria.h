// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <unordered_map>

#include "core/parameters/parameters.h"
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
/// node's whole reaction R splits into f_n n and R_t = R - f_n n. A node that becomes active sticks
/// (unless it touches down while it moves, below). A sticking node slips when its tie needs more than
/// the cone, |R_t| > mu |f_n| (and is not released in that iteration even if it pulls: the pull may be
/// the drag of its tangential tie); its slip direction is then s = -R_t / |R_t| (the way the tie held it back). A
/// slipping node carries the Coulomb force -mu |f_n| s (MPCContactConstraints::CoulombTerms, in the system with its
/// exact tangent) and sticks again when its slip of the step no longer runs along s (s . slip <= 0: the friction would
/// drive it). While it slips, s is the direction of that slip (in 2D it stays; in 3D it may turn), held within an
/// iteration with its turn stiffness (CoulombTerms); a node that turned back keeps the direction of its last slip, so
/// that if the cycle guard holds it slipping, it slips the way it moves. A node that touches down within the step while
/// it moves (its slip of the step above 1e-6 of its size) slips the way it moves: tied where the step started it would
/// be dragged back the whole way. The fixed components of R_t are left out (the support carries them: a symmetry
/// plane's force is no friction). Converged when no node changed its active or slip state and no direction turned by
/// more than 1e-8. CONTACT_FORCE is R (normal and tangential), TANGENTIAL_CONTACT_STRESS |R_t| / NODAL_MAUX. Kratos
/// compares |R_t| / NODAL_MAUX, a pressure, with -mu f_n, a force: here both sides are forces.
///
/// PureSlip (SetPureSlip; contact_type FrictionalPureSlip): every active node slips. A node that
/// becomes active (not moving) is tied in every component for one iteration, its trial: its tangential
/// reaction gives s = -R_t / |R_t| (a normal-only tie would leave its tangential DoFs free, with no
/// reaction to take a direction from); from then on it slips, s following its slip of the step, also
/// when it reverses. Pure slip has no solution where the interface must stick in part: with the normal
/// forces held, a pure-slip answer (every node's friction mu |f_n| against its nonzero slip) is an answer
/// of the Coulomb (Tresca) problem, whose answer is unique; so where Coulomb sticks somewhere (a push
/// smaller than what slides the body, e.g. against its own Poisson slip), s = +t gives a slip along -t
/// and s = -t one along +t, and the iterations flip every node's s for ever (measured: the 2D block
/// pushed by 1e-5, the whole interface alternating between slips of -4e-5 and +8e-5). A node whose s
/// reverses (s_new . s_old < 0) in kReversals successive iterations stops the step with a
/// SolutionError naming the nodes and contact_type "Frictional".
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
  /// Every active node slips (contact_type FrictionalPureSlip); only with frictional constraints.
  void SetPureSlip(bool pure_slip) noexcept { pure_slip_ = pure_slip; }
  /// Active-set changes of the last PostCriteria.
  std::size_t Changes() const noexcept { return changes_; }
  /// Frictional: the unit slip direction s of every active node (of a sticking one, the way it would
  /// slip), held until the next PostCriteria.
  const std::unordered_map<const Node*, Array3>& SlipDirections() const noexcept { return directions_; }
  /// Frictional: mu |f_n| / |slip| of the slipping nodes whose direction is that of their slip of the
  /// step (see MPCContactConstraints::CoulombTerms); E sqrt(NODAL_MAUX) for one that starts slipping.
  const std::unordered_map<const Node*, double>& TurnStiffness() const noexcept { return turn_stiffness_; }
  /// What a later step reads of the steps before (a restart checkpoint's part): the slip direction s and
  /// the turn stiffness of every node that has one, as {"directions": [[id, s_x, s_y, s_z], ...],
  /// "turn_stiffness": [[id, k], ...]} in node id order.
  void SaveState(Parameters& state) const;
  /// Takes back what SaveState wrote; the nodes are looked up by id in `model_part` (an InputError names
  /// a missing one).
  void LoadState(const Parameters& state, const ModelPart& model_part);
  /// Forgets the reversals of the slip directions counted in the last step (pure slip).
  void InitializeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                              const Vector& b) override;

 private:
  /// Frictional: the stick / slip state of a slave node from its tangential reaction (see the class
  /// comment).
  void UpdateSlip(Node& node, bool was_active, const Array3& tangential, double normal_force);
  /// Pure slip: throws the SolutionError of the class comment when an active node's s reversed in each of
  /// the last kReversals iterations.
  void StopPureSlipCycle(const ProcessInfo& info) const;

  std::shared_ptr<const MPCContactConstraints> constraints_;
  std::size_t changes_ = 0;
  std::unordered_map<const Node*, Array3> directions_;
  std::unordered_map<const Node*, double> turn_stiffness_;
  double young_modulus_ = 0.0;  ///< of the last PostCriteria
  bool pure_slip_ = false;
  /// Frictional: the largest change |s_new - s_old| of a slipping node's direction in the last PostCriteria.
  double turn_ = 0.0;
  static constexpr double kTurnTolerance = 1e-8;
  /// Pure slip: successive iterations in which a node's s reversed, and how many make a cycle.
  std::unordered_map<const Node*, int> reversals_;
  static constexpr int kReversals = 3;
  /// A node touching down slips when its slip of the step exceeds this fraction of its size sqrt(NODAL_MAUX).
  static constexpr double kMovingSlip = 1e-6;
};

}  // namespace mc
