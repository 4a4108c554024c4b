// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/newton_raphson_strategy.h"

#include "core/model/model_part.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"

namespace mc {

NewtonRaphsonStrategy::NewtonRaphsonStrategy(ModelPart& model_part, std::shared_ptr<Scheme> scheme,
                                             std::shared_ptr<ConvergenceCriteria> criteria,
                                             std::shared_ptr<BuilderAndSolver> builder_and_solver, int max_iteration,
                                             bool compute_reactions, bool reform_dofs_at_each_step, bool move_mesh_flag,
                                             bool use_old_stiffness_in_first_iteration)
    : ImplicitSolvingStrategy(model_part, std::move(scheme), std::move(builder_and_solver), compute_reactions,
                              reform_dofs_at_each_step, move_mesh_flag),
      criteria_(std::move(criteria)),
      max_iteration_(max_iteration),
      use_old_stiffness_(use_old_stiffness_in_first_iteration) {
  if (!criteria_) throw Error("the Newton-Raphson strategy needs a convergence criterion");
  if (max_iteration < 1) throw InputError(Concat("max_iteration = ", max_iteration, " must be at least 1"));
}

void NewtonRaphsonStrategy::Initialize() {
  ImplicitSolvingStrategy::Initialize();
  if (!criteria_->IsInitialized()) criteria_->Initialize(model_part_);
}

void NewtonRaphsonStrategy::InitializeSolutionStep() {
  const bool reform = !dofs_ready_ || reform_dofs_;
  ImplicitSolvingStrategy::InitializeSolutionStep();
  if (reform) has_stiffness_ = false;
  history_.clear();
  criteria_->InitializeSolutionStep(model_part_, builder_->GetDofSet(), builder_->SystemMatrix(), builder_->Increment(),
                                    builder_->Residual());
}

bool NewtonRaphsonStrategy::SolveSolutionStep() {
  for (int it = 1; it <= max_iteration_; ++it)
    if (NewtonIteration(it)) return true;
  ReportNonConvergence();
  return false;
}

bool NewtonRaphsonStrategy::NewtonIteration(int iteration) {
  model_part_.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, iteration);
  const auto& dofs = builder_->GetDofSet();
  scheme_->InitializeNonLinIteration(model_part_);
  criteria_->InitializeNonLinearIteration(model_part_, dofs, builder_->SystemMatrix(), builder_->Increment(),
                                          builder_->Residual());
  criteria_->PreCriteria(model_part_, dofs, builder_->SystemMatrix(), builder_->Increment(), builder_->Residual());

  SolveIteration(iteration);
  IterationRecord record;
  record.iteration = iteration;
  record.time = model_part_.GetProcessInfo().GetValue(TIME);
  record.residual_norm = builder_->Residual().norm();
  record.step_length = UpdateDatabase(iteration);
  record.increment_norm = builder_->Increment().norm();

  scheme_->FinalizeNonLinIteration(model_part_);
  criteria_->FinalizeNonLinearIteration(model_part_, dofs, builder_->SystemMatrix(), builder_->Increment(),
                                        builder_->Residual());
  if (criteria_->GetActualizeRHSFlag()) builder_->BuildRHS(*scheme_, model_part_);
  record.converged =
      criteria_->PostCriteria(model_part_, dofs, builder_->SystemMatrix(), builder_->Increment(), builder_->Residual());
  record.criteria = criteria_->LastValues();
  history_.push_back(std::move(record));
  return history_.back().converged;
}

void NewtonRaphsonStrategy::SolveIteration(int iteration) {
  if (iteration == 1 && use_old_stiffness_ && has_stiffness_) {
    builder_->BuildRHSAndSolve(*scheme_, model_part_);
  } else {
    builder_->BuildAndSolve(*scheme_, model_part_);
    has_stiffness_ = true;
  }
}

double NewtonRaphsonStrategy::UpdateDatabase(int iteration) {
  UpdateAndMoveMesh(builder_->Increment());
  return 1.0;
}

void NewtonRaphsonStrategy::FinalizeSolutionStep() {
  criteria_->FinalizeSolutionStep(model_part_, builder_->GetDofSet(), builder_->SystemMatrix(), builder_->Increment(),
                                  builder_->Residual());
  ImplicitSolvingStrategy::FinalizeSolutionStep();
}

void NewtonRaphsonStrategy::Clear() {
  ImplicitSolvingStrategy::Clear();
  has_stiffness_ = false;
}

void NewtonRaphsonStrategy::Check() const {
  ImplicitSolvingStrategy::Check();
  criteria_->Check(model_part_);
}

void NewtonRaphsonStrategy::ReportNonConvergence() const {
  if (echo_level_ < 1 || history_.empty()) return;
  const ProcessInfo& info = model_part_.GetProcessInfo();
  const IterationRecord& last = history_.back();
  Logger::Warning(Concat(Name(), ": step ", info.GetValue(STEP), " (time ", info.GetValue(TIME),
                         ") did not converge in ", max_iteration_, " iterations; last |r| = ", last.residual_norm,
                         ", |du| = ", last.increment_norm));
}

}  // namespace mc
