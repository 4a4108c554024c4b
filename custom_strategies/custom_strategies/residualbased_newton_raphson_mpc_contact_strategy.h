// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/parameters/parameters.h"
#include "core/solving/newton_raphson_strategy.h"
#include "custom_strategies/custom_convergencecriterias/mpc_contact_criteria.h"
#include "custom_strategies/custom_strategies/mpc_contact_constraints.h"
#include "custom_utilities/contact_state_cycle.h"

namespace mc {

/// The keys of mpc_contact_settings the MPC strategy reads (spec 2.8).
struct MPCContactStrategySettings {
  int inner_loop_iterations;           ///< active-set passes of the simplified semi-smooth Newton
  bool update_each_nl_iteration;       ///< relations rebuilt at every Newton iteration, not once per step
  bool simplified_semi_smooth_newton;  ///< active set frozen within a pass, checked between passes
};

/// "newton_raphson_mpc_contact_strategy" (Kratos' ResidualBasedNewtonRaphsonMPCContactStrategy): Newton
/// with the contact imposed by master-slave constraints (MPCContactConstraints) on the ACTIVE slave
/// nodes, whose set MPCContactCriteria updates from the reactions.
///
/// A step: the relations are built at the step's start configuration (and again at every iteration
/// with update_each_nl_iteration); the predictor adds one constrained linear solve whose reactions give
/// the active set Newton starts with (rather than the search's gap guess); then Newton from the
/// predicted state. Without
/// simplified_semi_smooth_newton the set is updated after every iteration and the step has converged
/// when the mechanical criterion has and no node changed; with it, up to inner_loop_iterations passes
/// of a Newton loop on a frozen set, each followed by the update.
///
/// Cycle guard (as the mortar contact strategy's): an edge node can be released by its pull and then
/// re-activated by its penetration, iteration after iteration. When the set comes back to one of an
/// earlier iteration (not the previous one), the union of the sets of the cycle is held active for the
/// rest of the step (a held node may carry a small pull); frictional, a node the last check stuck is held
/// stuck (its tangential force may end a little outside the cone), any other node of the cycle that
/// slipped is held slipping.
///
/// Frictional (contact_type Frictional), a sticking node is tied in every component and a slipping one
/// in the normal, with its Coulomb force in the system (see MPCContactCriteria for the switch).
///
/// Mesh tying (root flag RIGID, set by mpc_contact_process with contact_type "MeshTying"): at the first
/// step every slave node an overlap reaches is tied in every free displacement component
/// (MPCContactConstraints::RelateAllComponents) and ACTIVE for good; the relations are kept for every
/// later step (the faces stay glued where they were meshed: the tie is between material points; a
/// resumed run takes them from its checkpoint, RestartState),
/// there is no predictor solve, no active set and no release. CONTACT_FORCE is the slave node's reaction
/// (all its components) and NORMAL_CONTACT_STRESS its normal part over NODAL_MAUX. Kratos 10.4 runs its
/// reaction check on tied nodes too, and releases a tie that pulls: a defect (a tie holds in tension).
///
/// Kratos checks the reactions twice per iteration (the strategy's own MPCContactCriteria, and a second
/// one the Python solver puts in an AndCriteria with the mechanical criterion): a defect, the second
/// check only repeats the first. Here the strategy owns the one MPCContactCriteria, and the criterion it
/// is given is the mechanical one.
class ResidualBasedNewtonRaphsonMPCContactStrategy : public NewtonRaphsonStrategy {
 public:
  /// The mpc_contact_settings keys it reads, with the solver's defaults (Kratos' strategy's own
  /// inner_loop_iterations default, 5, is replaced by the solver's 10 before it sees it).
  static Parameters GetDefaultParameters();
  static MPCContactStrategySettings ReadSettings(Parameters settings);

  ResidualBasedNewtonRaphsonMPCContactStrategy(ModelPart& model_part, std::shared_ptr<Scheme> scheme,
                                               std::shared_ptr<ConvergenceCriteria> criteria,
                                               std::shared_ptr<BuilderAndSolver> builder_and_solver,
                                               MPCContactStrategySettings settings, int max_iteration = 10,
                                               bool compute_reactions = true, bool reform_dofs_at_each_step = true,
                                               bool move_mesh_flag = true);

  std::string Name() const override { return "newton_raphson_mpc_contact_strategy"; }
  void Initialize() override;
  void InitializeSolutionStep() override;
  void Predict() override;

  const MPCContactStrategySettings& Settings() const noexcept { return settings_; }
  /// Passes of the last step (1 without simplified_semi_smooth_newton).
  int InnerLoopIterations() const noexcept { return passes_; }
  /// ACTIVE slave nodes now.
  std::size_t NumberOfActiveNodes() const;
  /// What the next step takes from the steps before, beyond the nodal values and flags a restart checkpoint
  /// holds: the criterion's slip directions and turn stiffnesses (frictional), and with mesh tying the
  /// operators of the tie, measured at the first step ({"tied": ..., "tying_operators": ..., "directions":
  /// ..., "turn_stiffness": ...}). After Initialize.
  Parameters RestartState() const;
  /// Takes back RestartState's state in a resumed run (after Initialize): the resumed run continues as
  /// the uninterrupted one, its tie that of the first step, not one measured again where it resumes.
  void LoadRestartState(const Parameters& state);

 protected:
  bool NewtonIteration(int iteration) override;
  bool SolveStepAttempt() override;

 private:
  /// The reactions of the interface nodes at the current state (minus the residual: the force the
  /// constraints transmit), the operators measured again, and the criterion's update of the active set;
  /// true when no node changed.
  bool UpdateActiveSet();
  /// The relations of the current set to the builder, and frictional, the Coulomb force of the
  /// slipping nodes (MPCContactConstraints::CoulombTerms) with the directions of the last update.
  void ApplyConstraints();
  /// REACTION of the Contact nodes' displacement DoFs from the raw residual of the current state.
  void WriteInterfaceReactions();
  /// Mesh tying: ties the interface at the first step, marks its tied slave nodes ACTIVE.
  void TieInterface();
  /// Mesh tying: CONTACT_FORCE and NORMAL_CONTACT_STRESS of the tied slave nodes at the current state.
  void WriteTyingForces();
  /// After a change of the set in full semi-smooth Newton: the cycle guard (see the class comment); true
  /// while the held set stands in for the criterion's.
  bool HoldCycle();

  MPCContactStrategySettings settings_;
  std::shared_ptr<MPCContactConstraints> constraints_;
  std::shared_ptr<MPCContactCriteria> mpc_criteria_;
  ModelPart* contact_ = nullptr;
  int passes_ = 0;
  ContactStateCycle cycle_{{}};    ///< the sets of this step's iterations
  bool held_ = false;              ///< a cycle's union is held
  std::vector<char> held_states_;  ///< the states held (the union, a node just stuck held stuck)
  bool tying_ = false;             ///< mesh tying (root flag RIGID)
  bool tied_ = false;              ///< the tying relations are built
};

}  // namespace mc
