// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_strategies/line_search_contact_strategy.h"

#include <algorithm>
#include <cmath>

#include "core/utilities/error.h"
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"

namespace mc {

LineSearchContactStrategy::LineSearchContactStrategy(ModelPart& model_part, std::shared_ptr<Scheme> scheme,
                                                     std::shared_ptr<ConvergenceCriteria> criteria,
                                                     std::shared_ptr<BuilderAndSolver> builder_and_solver,
                                                     ContactStrategySettings settings, int max_iteration,
                                                     bool compute_reactions, bool reform_dofs_at_each_step,
                                                     bool move_mesh_flag, double min_step)
    : ResidualBasedNewtonRaphsonContactStrategy(model_part, std::move(scheme), std::move(criteria),
                                                std::move(builder_and_solver), settings, max_iteration,
                                                compute_reactions, reform_dofs_at_each_step, move_mesh_flag),
      min_step_(min_step) {
  if (!(min_step > 0.0 && min_step <= 1.0))
    throw InputError(Concat("line_search_contact_strategy: min_step = ", min_step, " must be in (0, 1]"));
}

void LineSearchContactStrategy::InitializeSolutionStep() {
  ResidualBasedNewtonRaphsonContactStrategy::InitializeSolutionStep();
  steps_.clear();
}

double LineSearchContactStrategy::ParabolaStep(double r_o, double r_h, double r_f, double min_step) {
  if (r_o == 0.0 && r_h == 0.0 && r_f == 0.0) return 1.0;
  const double a = 2.0 * r_f - 4.0 * r_h + 2.0 * r_o;
  const double b = 4.0 * r_h - r_f - 3.0 * r_o;
  if (a > 0.0) return std::clamp(-b / (2.0 * a), min_step, 1.0);
  return r_f < r_o ? 1.0 : min_step;
}

std::pair<double, double> LineSearchContactStrategy::SplitNorms(const Vector& r) const {
  double u = 0.0;
  double lm = 0.0;
  for (const Dof* dof : builder_->GetDofSet()) {
    if (dof->fixed) continue;
    const double value = r[dof->equation_id];
    (FamilyOf(*dof->variable) == DofFamily::kMultiplier ? lm : u) += value * value;
  }
  return {std::sqrt(u), std::sqrt(lm)};
}

void LineSearchContactStrategy::MoveTo(double s_u, double s_lm) {
  step_ = (s_u - current_u_) * direction_u_ + (s_lm - current_lm_) * direction_lm_;
  UpdateAndMoveMesh(step_);
  current_u_ = s_u;
  current_lm_ = s_lm;
}

double LineSearchContactStrategy::UpdateDatabase(int iteration) {
  // Its norms would need a sum over the ranks' owned rows.
  if (builder_->PieceCommunicator())
    throw NotImplementedError(
        "line_search on a model cut across processes: run it without MORTARCONTACT_PARTITIONED_MODEL");
  const Vector& dx = builder_->Increment();
  direction_u_ = dx;
  direction_lm_.setZero(dx.size());
  for (const Dof* dof : builder_->GetDofSet()) {
    if (FamilyOf(*dof->variable) != DofFamily::kMultiplier) continue;
    direction_lm_[dof->equation_id] = dx[dof->equation_id];
    direction_u_[dof->equation_id] = 0.0;
  }
  saved_residual_ = builder_->Residual();
  current_u_ = current_lm_ = 0.0;

  const auto [ro_u, ro_lm] = SplitNorms(saved_residual_);
  MoveTo(0.5, 0.5);
  builder_->BuildRHS(*scheme_, model_part_);
  const auto [rh_u, rh_lm] = SplitNorms(builder_->Residual());
  MoveTo(1.0, 1.0);
  builder_->BuildRHS(*scheme_, model_part_);
  const auto [rf_u, rf_lm] = SplitNorms(builder_->Residual());

  SplitStep step{iteration, ParabolaStep(ro_u, rh_u, rf_u, min_step_), ParabolaStep(ro_lm, rh_lm, rf_lm, min_step_)};
  MoveTo(step.displacement, step.multiplier);
  steps_.push_back(step);
  // Criteria see the increment actually applied and the residual the iteration started from.
  builder_->Increment() = step.displacement * direction_u_ + step.multiplier * direction_lm_;
  builder_->Residual() = saved_residual_;
  return step.displacement;
}

}  // namespace mc
