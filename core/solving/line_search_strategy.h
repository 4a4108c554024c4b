// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/newton_raphson_strategy.h"

namespace mc {

/// Settings of the line search (Kratos' `line_search` strategy keys and defaults).
struct LineSearchSettings {
  int max_line_search_iterations = 5;  ///< secant iterations after the two first trial steps
  double first_alpha_value = 0.5;      ///< first trial step length
  double second_alpha_value = 1.0;     ///< second trial step length
  double min_alpha = 0.1;              ///< step lengths are clamped to [min_alpha, max_alpha]
  double max_alpha = 2.0;
  double line_search_tolerance = 0.5;  ///< stop when |phi(s)| <= tolerance |phi(0)|
};

/// Newton-Raphson whose increment du is scaled by the step length s that zeroes the residual
/// projected on the search direction, phi(s) = du . r(u + s du), found by secant iterations
/// from two trial steps (each evaluation rebuilds the residual only). When du is not a
/// descent direction (phi(0) <= 0) the full step is taken.
class LineSearchStrategy : public NewtonRaphsonStrategy {
 public:
  LineSearchStrategy(ModelPart& model_part, std::shared_ptr<Scheme> scheme,
                     std::shared_ptr<ConvergenceCriteria> criteria,
                     std::shared_ptr<BuilderAndSolver> builder_and_solver, LineSearchSettings settings = {},
                     int max_iteration = 10, bool compute_reactions = true, bool reform_dofs_at_each_step = false,
                     bool move_mesh_flag = true);

  std::string Name() const override { return "line_search"; }
  const LineSearchSettings& Settings() const noexcept { return settings_; }

 protected:
  double UpdateDatabase(int iteration) override;

 private:
  /// Moves the DoFs from step length `current_` to `s` along the saved direction.
  void MoveTo(double s);
  /// phi(s), rebuilding the residual at u + s du.
  double Phi(double s);

  LineSearchSettings settings_;
  Vector direction_;
  Vector saved_residual_;
  Vector step_;
  double current_ = 0.0;
};

}  // namespace mc
