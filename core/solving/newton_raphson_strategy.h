// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "core/solving/convergence_criteria.h"
#include "core/solving/implicit_solving_strategy.h"
#include "core/solving/iteration_record.h"

namespace mc {

/// Newton-Raphson on the residual: at each iteration build K and r at the current state,
/// solve K du = r, update, check the criterion, up to `max_iteration` times. The loop is split
/// into overridable pieces (NewtonIteration, SolveIteration, UpdateDatabase) so that the
/// contact strategies add their active-set logic around them.
class NewtonRaphsonStrategy : public ImplicitSolvingStrategy {
 public:
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

 protected:
  /// One iteration: criteria and scheme hooks, solve, update, check. Returns convergence.
  virtual bool NewtonIteration(int iteration);
  /// Builds (or, with the old stiffness, only the residual) and solves.
  virtual void SolveIteration(int iteration);
  /// Applies the increment of the builder; returns the factor applied to it (1 for Newton).
  virtual double UpdateDatabase(int iteration);
  /// Logs the end of a step that did not converge.
  void ReportNonConvergence() const;

  std::shared_ptr<ConvergenceCriteria> criteria_;
  int max_iteration_;
  bool use_old_stiffness_;
  bool has_stiffness_ = false;
  std::vector<IterationRecord> history_;
};

}  // namespace mc
