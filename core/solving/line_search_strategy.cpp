// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/line_search_strategy.h"

#include <algorithm>
#include <cmath>

#include "core/utilities/error.h"

namespace mc {

LineSearchStrategy::LineSearchStrategy(ModelPart& model_part, std::shared_ptr<Scheme> scheme,
                                       std::shared_ptr<ConvergenceCriteria> criteria,
                                       std::shared_ptr<BuilderAndSolver> builder_and_solver,
                                       LineSearchSettings settings, int max_iteration, bool compute_reactions,
                                       bool reform_dofs_at_each_step, bool move_mesh_flag)
    : NewtonRaphsonStrategy(model_part, std::move(scheme), std::move(criteria), std::move(builder_and_solver),
                            max_iteration, compute_reactions, reform_dofs_at_each_step, move_mesh_flag),
      settings_(settings) {
  if (!(settings_.min_alpha > 0.0) || settings_.max_alpha < settings_.min_alpha)
    throw InputError(Concat("line search: min_alpha = ", settings_.min_alpha, " and max_alpha = ", settings_.max_alpha,
                            " must satisfy 0 < min_alpha <= max_alpha"));
  if (settings_.first_alpha_value == settings_.second_alpha_value)
    throw InputError(Concat("line search: first_alpha_value and second_alpha_value are both ",
                            settings_.first_alpha_value, "; the secant needs two different steps"));
}

void LineSearchStrategy::MoveTo(double s) {
  step_ = (s - current_) * direction_;
  UpdateAndMoveMesh(step_);
  current_ = s;
}

double LineSearchStrategy::Phi(double s) {
  MoveTo(s);
  builder_->BuildRHS(*scheme_, model_part_);
  return direction_.dot(builder_->Residual());
}

double LineSearchStrategy::UpdateDatabase(int iteration) {
  // Its dot products would need a sum over the ranks' owned rows.
  if (builder_->PieceCommunicator())
    throw NotImplementedError(
        "line_search on a model cut across processes: run it without MORTARCONTACT_PARTITIONED_MODEL");
  direction_ = builder_->Increment();
  saved_residual_ = builder_->Residual();
  current_ = 0.0;
  const double phi0 = direction_.dot(saved_residual_);
  double best = 1.0;
  if (phi0 > 0.0) {
    double s1 = settings_.first_alpha_value;
    double phi1 = Phi(s1);
    double s2 = settings_.second_alpha_value;
    double phi2 = Phi(s2);
    double best_phi = std::abs(phi2);
    best = s2;
    if (std::abs(phi1) < best_phi) {
      best_phi = std::abs(phi1);
      best = s1;
    }
    for (int k = 0; k < settings_.max_line_search_iterations && best_phi > settings_.line_search_tolerance * phi0;
         ++k) {
      if (phi2 == phi1) break;
      const double s3 = std::clamp(s2 - phi2 * (s2 - s1) / (phi2 - phi1), settings_.min_alpha, settings_.max_alpha);
      if (s3 == s2) break;
      s1 = s2;
      phi1 = phi2;
      s2 = s3;
      phi2 = Phi(s2);
      if (std::abs(phi2) < best_phi) {
        best_phi = std::abs(phi2);
        best = s2;
      }
    }
  }
  MoveTo(best);
  // Criteria see the increment actually applied and the residual the iteration started from.
  builder_->Increment() = best * direction_;
  builder_->Residual() = saved_residual_;
  return best;
}

}  // namespace mc
