// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "custom_strategies/custom_strategies/residualbased_newton_raphson_contact_strategy.h"

namespace mc {

/// "line_search_contact_strategy": the contact Newton strategy whose update is a line search
/// split by DoF family. Displacements and Lagrange multipliers differ by orders of magnitude,
/// so one step length fitted to the norm of the whole residual would follow the larger block
/// only. Instead, with d = (d_u, d_lm) the Newton increment:
///
///  1. the residual is evaluated at the iterate (r_o, from the build), at half of the increment
///     (r_h) and at the full increment (r_f), rebuilding the right-hand side, and each is split
///     into its displacement and multiplier norms;
///  2. per block, the parabola y(x) = a x^2 + b x + c through (0, r_o), (1/2, r_h), (1, r_f)
///     (c = r_o, b = 4 r_h - r_f - 3 r_o, a = 2 r_f - 4 r_h + 2 r_o) gives the step length
///     x = -b / (2a) clamped to [min_step, 1] when a > 0, otherwise 1 if r_f < r_o and
///     min_step if not; a block whose three norms are zero keeps x = 1;
///  3. the iterate moves by x_u d_u + x_lm d_lm.
///
/// The two step lengths really differ here. The reference implementation passes its two step
/// variables to the parabola fit in swapped order, so the fitted optimum is written into the
/// variable it then ignores and its final correction is always zero: its "split line search"
/// is the full Newton step. Both blocks are probed together at 1/2 and 1, so each block's
/// parabola includes the other block's coupling at the same fraction: a heuristic, exact when
/// the blocks decouple.
///
/// Derives from the contact Newton strategy (contact predictor, simplified / full semi-smooth
/// Newton, adaptive splitting); the reference derives from the plain line search instead.
class LineSearchContactStrategy : public ResidualBasedNewtonRaphsonContactStrategy {
 public:
  /// The step lengths of one iteration.
  struct SplitStep {
    int iteration = 0;
    double displacement = 1.0;
    double multiplier = 1.0;
  };

  LineSearchContactStrategy(ModelPart& model_part, std::shared_ptr<Scheme> scheme,
                            std::shared_ptr<ConvergenceCriteria> criteria,
                            std::shared_ptr<BuilderAndSolver> builder_and_solver,
                            ContactStrategySettings settings = ReadSettings(Parameters()), int max_iteration = 10,
                            bool compute_reactions = true, bool reform_dofs_at_each_step = false,
                            bool move_mesh_flag = true, double min_step = 0.1);

  std::string Name() const override { return "line_search_contact_strategy"; }
  void InitializeSolutionStep() override;
  /// Step lengths of the iterations of the current (last) step.
  const std::vector<SplitStep>& SplitSteps() const noexcept { return steps_; }
  double MinStep() const noexcept { return min_step_; }

  /// Step 2 above: the step length of one block from its residual norms at 0, 1/2 and 1.
  static double ParabolaStep(double r_o, double r_h, double r_f, double min_step);

 protected:
  /// Returns the displacement step length (recorded as IterationRecord::step_length).
  double UpdateDatabase(int iteration) override;

 private:
  /// Displacement and multiplier norms of a residual over the free DoFs.
  std::pair<double, double> SplitNorms(const Vector& r) const;
  /// Moves the DoFs from the current fractions to (s_u, s_lm) of the saved increment.
  void MoveTo(double s_u, double s_lm);

  double min_step_;
  std::vector<SplitStep> steps_;
  Vector direction_u_;
  Vector direction_lm_;
  Vector saved_residual_;
  Vector step_;
  double current_u_ = 0.0;
  double current_lm_ = 0.0;
};

}  // namespace mc
