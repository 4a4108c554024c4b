// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/solving/convergence_criteria.h"
#include "core/solving/forcing_term.h"
#include "core/solving/implicit_solving_strategy.h"
#include "core/solving/iteration_record.h"
#include "core/solving/step_splitting.h"

namespace mc {

/// Newton-Raphson on the residual: at each iteration build K and r at the current state,
/// solve K du = r, update, check the criterion, up to `max_iteration` times. The loop is split
/// into overridable pieces (NewtonIteration, SolveIteration, UpdateDatabase) so that the
/// contact strategies add their active-set logic around them.
///
/// With StepSplitting enabled, a step that does not converge (or whose solve throws a
/// SolutionError: a singular system, an inverted element) is restarted from its initial state
/// and marched in DELTA_TIME / split_factor^s sub-steps, s = 1 .. max_number_splits. Each
/// sub-step clones the time step, runs the initialize callback, InitializeSolutionStep, Predict
/// and the Newton loop; all but the last also run FinalizeSolutionStep and the finalize callback
/// (the analysis finalizes the last one). STEP and DELTA_TIME are restored afterwards. If the last
/// level fails too, a SolutionError says why, naming the nodes or elements at fault.
class NewtonRaphsonStrategy : public ImplicitSolvingStrategy {
 public:
  /// Callbacks run around the sub-steps of a split step (from Python: the processes'
  /// ExecuteInitializeSolutionStep / ExecuteFinalizeSolutionStep).
  struct SubStepCallbacks {
    std::function<void()> initialize_solution_step;
    std::function<void()> finalize_solution_step;
  };

  /// Kratos' settings: `max_iteration` (10), `compute_reactions` (true),
  /// `reform_dofs_at_each_step` (false), `move_mesh_flag` (true),
  /// `use_old_stiffness_in_first_iteration` (false: reuse the last matrix at iteration 1).
  NewtonRaphsonStrategy(ModelPart& model_part, std::shared_ptr<Scheme> scheme,
                        std::shared_ptr<ConvergenceCriteria> criteria,
                        std::shared_ptr<BuilderAndSolver> builder_and_solver, int max_iteration = 10,
                        bool compute_reactions = true, bool reform_dofs_at_each_step = false,
                        bool move_mesh_flag = true, bool use_old_stiffness_in_first_iteration = false);

  std::string Name() const override { return "newton_raphson"; }
  void Initialize() override;
  void InitializeSolutionStep() override;
  bool SolveSolutionStep() override;
  void FinalizeSolutionStep() override;
  void Clear() override;
  void Check() const override;

  int GetMaxIterationNumber() const noexcept { return max_iteration_; }
  void SetMaxIterationNumber(int value) noexcept { max_iteration_ = value; }
  bool UseOldStiffnessInFirstIteration() const noexcept { return use_old_stiffness_; }
  ConvergenceCriteria& GetConvergenceCriteria() const noexcept { return *criteria_; }
  /// The iterations of the current (last) step.
  const std::vector<IterationRecord>& IterationHistory() const noexcept { return history_; }

  void SetStepSplitting(const StepSplitting& splitting) noexcept { splitting_ = splitting; }
  const StepSplitting& GetStepSplitting() const noexcept { return splitting_; }
  void SetSubStepCallbacks(SubStepCallbacks callbacks) { callbacks_ = std::move(callbacks); }
  /// Split level that made the last step converge (0: no split needed).
  int SplitLevelUsed() const noexcept { return split_level_; }
  /// Why the last step failed ("" if it converged).
  const std::string& FailureReport() const noexcept { return failure_; }

 protected:
  /// One attempt at the step from the current state: the Newton loop. True when converged.
  virtual bool SolveStepAttempt();
  /// Why the last attempt failed: step, time, the solver error or the last norms, and the
  /// nodes with the largest residuals.
  virtual std::string DescribeFailure() const;
  /// The state a split step restarts from: every node's historical buffer.
  virtual void SaveStepStart();
  virtual void RestoreStepStart();
  /// "; largest residuals at node 12 (DISPLACEMENT_Y 3.1e+02), ..." for the free DoFs of the
  /// last system, `count` nodes at most ("" before the first build).
  std::string LargestResidualNodes(std::size_t count) const;

  /// One iteration: criteria and scheme hooks, solve, update, check. Returns convergence.
  virtual bool NewtonIteration(int iteration);
  /// Builds (or, with the old stiffness, only the residual) and solves, to the relative residual
  /// of the forcing term when the linear solver accepts one (inexact Newton).
  virtual void SolveIteration(int iteration);
  /// Applies the increment of the builder; returns the factor applied to it (1 for Newton).
  virtual double UpdateDatabase(int iteration);
  /// Logs the end of a step that did not converge (FailureReport()).
  virtual void ReportNonConvergence() const;

  std::shared_ptr<ConvergenceCriteria> criteria_;
  int max_iteration_;
  bool use_old_stiffness_;
  bool has_stiffness_ = false;
  std::vector<IterationRecord> history_;
  ForcingTerm forcing_;
  StepSplitting splitting_;
  bool in_sub_step_ = false;
  /// The message of the SolutionError that ended the last attempt ("" if none).
  std::string solver_error_;

 private:
  /// SolveStepAttempt; with splitting on, a SolutionError counts as non-convergence.
  bool TrySolveStepAttempt();
  bool SplitStep();

  SubStepCallbacks callbacks_;
  int split_level_ = 0;
  std::string failure_;
  struct NodeStart {
    Node* node;
    std::vector<double> history;
  };
  std::vector<NodeStart> start_;
  double start_time_ = 0.0;
  double start_delta_time_ = 0.0;
  int start_step_ = 0;
};

}  // namespace mc
