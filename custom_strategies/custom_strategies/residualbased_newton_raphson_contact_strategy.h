// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/parameters/parameters.h"
#include "core/solving/newton_raphson_strategy.h"
#include "custom_utilities/mortar_updater.h"

namespace mc {

class SingularSystemError;
class BaseMortarConvergenceCriteria;

/// Settings of the contact Newton strategy, read from its keys of `contact_settings`
/// (ResidualBasedNewtonRaphsonContactStrategy::ReadSettings; defaults in GetDefaultParameters).
struct ContactStrategySettings {
  bool adaptative_strategy;     ///< split the step when it does not converge
  double split_factor;          ///< DELTA_TIME divisor per split level
  int max_number_splits;        ///< split levels tried before giving up
  int inner_loop_iterations;    ///< active-set passes of the simplified semi-smooth Newton
  bool active_set_line_search;  ///< damp the increments that change the set (see UpdateDatabase)
};

/// "newton_raphson_contact_strategy": Newton-Raphson for mortar contact, i.e. the semi-smooth
/// Newton method of thesis Algorithm 2, with the active-set update done by the mortar criterion
/// (BaseMortarConvergenceCriteria::PostCriteria) inside a MortarAndConvergenceCriteria.
///
///  - Full semi-smooth Newton when the computing model part Is(INTERACTION): one Newton loop
///    in which the active set is updated after every iteration. If the set returns to that of an
///    earlier iteration (a cycle), the union of the sets of the cycle is kept until Newton
///    converges on it and checked then, as in the simplified method (Kratos stops at
///    max_iteration). With `active_set_line_search` (ours, off by default) an increment that
///    would change the active set must decrease the residual, or is damped (UpdateDatabase).
///  - Simplified semi-smooth Newton otherwise: up to `inner_loop_iterations` passes, each a
///    complete Newton loop (the active set is updated after its first iteration, then frozen),
///    followed by an active-set check with NL_ITERATION_NUMBER = 1; done when the set no longer
///    changes. ProcessInfo[INNER_LOOP_ITERATION] holds the pass.
///  - Predict: the scheme's predictor (dynamic schemes: the first guess and its velocities and
///    accelerations), then zeroes WEIGHTED_GAP on the "Contact" nodes, asks the MortarUpdater to
///    integrate it at the coordinates of the last converged step, and moves the mesh to
///    X0 + DISPLACEMENT. An extrapolating predictor (the static scheme's
///    displacement_extrapolation) is skipped after a step in which the contact state of a slave
///    node changed: the path turned there, and extrapolating it carries the turn on.
///  - With `adaptative_strategy`: a step that does not converge (or inverts an element: the
///    Jacobian determinant of every solid element is checked after each update) is split as
///    NewtonRaphsonStrategy's StepSplitting does (split_factor, max_number_splits); the active
///    and stick / slip sets are restored with the state at the start of the step.
///  - A step that does not converge logs (and keeps in FailureReport) why: inverted element,
///    the slave nodes whose state keeps switching (per-node flip counts over the step), or the
///    last criterion values.
class ResidualBasedNewtonRaphsonContactStrategy : public NewtonRaphsonStrategy {
 public:
  /// The shortest step the active-set line search tries.
  static constexpr double kMinStepLength = 0.0625;
  /// Its keys of Kratos' contact_settings: adaptative_strategy (false), split_factor (10),
  /// max_number_splits (3), inner_loop_iterations (5); and ours, active_set_line_search (false).
  static Parameters GetDefaultParameters();
  /// Reads its keys from `settings` (the solver's validated contact_settings, or any object:
  /// missing keys are added with their defaults; the owner of the block rejects unknown ones)
  /// and checks their ranges.
  static ContactStrategySettings ReadSettings(Parameters settings);

  ResidualBasedNewtonRaphsonContactStrategy(ModelPart& model_part, std::shared_ptr<Scheme> scheme,
                                            std::shared_ptr<ConvergenceCriteria> criteria,
                                            std::shared_ptr<BuilderAndSolver> builder_and_solver,
                                            ContactStrategySettings settings = ReadSettings(Parameters()),
                                            int max_iteration = 10, bool compute_reactions = true,
                                            bool reform_dofs_at_each_step = false, bool move_mesh_flag = true);

  std::string Name() const override { return "newton_raphson_contact_strategy"; }
  void InitializeSolutionStep() override;
  void Predict() override;
  /// The base step end; with an extrapolating scheme each slave node's CONVERGED_CONTACT_STATES
  /// then takes the step's state, for the next Predict.
  void FinalizeSolutionStep() override;

  const ContactStrategySettings& Settings() const noexcept { return settings_; }
  void SetMortarUpdater(std::shared_ptr<MortarUpdater> updater) noexcept { updater_ = std::move(updater); }

  /// How many times each slave node changed state during the current (last) step.
  const std::map<IndexType, int>& ActiveSetFlipCounts() const noexcept { return flips_; }
  /// Active-set passes of the last step (1 in full semi-smooth Newton).
  int InnerLoopIterations() const noexcept { return passes_; }

 protected:
  /// Base iteration, plus the active-set flip bookkeeping and the inverted-element guard.
  bool NewtonIteration(int iteration) override;
  /// With `active_set_line_search`, in full semi-smooth Newton: an increment after which the
  /// active-set update would change the set is accepted only if it decreases the merit |F|, the
  /// residual assembled with the set the update takes there (the complementarity rows included),
  /// by the Armijo fraction; otherwise it is halved, down to kMinStepLength, and the trial with
  /// the least merit is taken. The reference is the larger of |F| now and at the last iteration
  /// of the step (a non-monotone test: a single rise, as when contact spreads, passes). An
  /// increment that changes no node's ACTIVE flag is taken whole (stick / slip changes are left
  /// out: checked too, they cost shift steps up to 10 more iterations).
  double UpdateDatabase(int iteration) override;
  /// Rethrows `error` in contact terms when every DoF it names is the multiplier of an active slave node.
  void ExplainLostOverlap(const SingularSystemError& error, int iteration) const;
  /// Full or simplified semi-smooth Newton, per the INTERACTION flag.
  bool SolveStepAttempt() override;
  /// Why the step failed: inverted element, the slave nodes whose state keeps switching (per-node
  /// flip counts over the step), or the last criterion values and the largest residuals.
  std::string DescribeFailure() const override;
  /// The base state plus the ACTIVE and SLIP flags and CONVERGED_CONTACT_STATES of every node.
  void SaveStepStart() override;
  void RestoreStepStart() override;
  /// Always logged: a contact step that fails is worth a line even when silent.
  void ReportNonConvergence() const override;

 private:
  /// Newton loop of one pass; false when it did not converge or an element got inverted.
  bool RunNewtonLoop();
  /// The Newton loop of the full semi-smooth Newton, with the guard against a cycling set.
  bool RunFullNewtonLoop();
  /// Active-set check at the current (converged) state; true when no node changed.
  bool RecheckActiveSet();
  /// Contact state of every slave node of the contact part, in container order: bit 1 if
  /// ACTIVE, bit 2 if SLIP (the stick / slip set belongs to the state of a frictional node).
  std::vector<char> ContactStates() const;
  /// Sets the ACTIVE and SLIP flags of every slave node of the contact part (the order of ContactStates).
  void SetContactStates(const std::vector<char>& states);
  /// Adds one flip to every slave node whose ACTIVE flag differs from `before`; returns how many.
  std::size_t CountFlips(const std::vector<char>& before);
  /// Whether no slave node changed its contact state in the last converged step (false when
  /// that is not known: the first step).
  bool LastStepKeptContactStates() const;
  /// Id of an element with a negative Jacobian determinant at an integration point, or 0.
  IndexType FindInvertedElement() const;
  /// Merit of the current coordinates for UpdateDatabase: |F| if the set update changes the set there,
  /// else -1. The contact nodes are left as they were.
  double TrialMerit(BaseMortarConvergenceCriteria& mortar, ModelPart& contact);

  ContactStrategySettings settings_;
  std::shared_ptr<MortarUpdater> updater_;
  std::map<IndexType, int> flips_;
  std::size_t last_changes_ = 0;
  IndexType inverted_element_ = 0;
  int passes_ = 0;
  /// ACTIVE and SLIP flags and CONVERGED_CONTACT_STATES (-1: none) of every node of the root
  /// model part at the start of the step.
  struct StartFlags {
    Node* node;
    bool active;
    bool slip;
    int converged_states;
  };
  std::vector<StartFlags> start_flags_;
};

}  // namespace mc
