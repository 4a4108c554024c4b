// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/newton_raphson_strategy.h"

#include <algorithm>
#include <cmath>

#include "core/linear_solvers/linear_solver.h"
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
  // The iterations of the failed attempt and of the sub-steps all belong to the step's history.
  std::vector<IterationRecord> earlier = in_sub_step_ ? std::move(history_) : std::vector<IterationRecord>{};
  ImplicitSolvingStrategy::InitializeSolutionStep();
  if (reform) has_stiffness_ = false;
  history_ = std::move(earlier);
  failure_.clear();
  if (!in_sub_step_) {
    split_level_ = 0;
    if (splitting_.Enabled()) SaveStepStart();
  }
  criteria_->SetPieceCommunicator(builder_->PieceCommunicator());
  criteria_->InitializeSolutionStep(model_part_, builder_->OwnedDofs(), builder_->SystemMatrix(), builder_->Increment(),
                                    builder_->Residual());
}

bool NewtonRaphsonStrategy::SolveSolutionStep() {
  bool converged = TrySolveStepAttempt();
  if (!converged && splitting_.Enabled() && !in_sub_step_) converged = SplitStep();
  failure_ = converged ? std::string() : DescribeFailure();
  if (!converged) ReportNonConvergence();
  return converged;
}

bool NewtonRaphsonStrategy::SolveStepAttempt() {
  for (int it = 1; it <= max_iteration_; ++it)
    if (NewtonIteration(it)) return true;
  return false;
}

bool NewtonRaphsonStrategy::TrySolveStepAttempt() {
  solver_error_.clear();
  if (!splitting_.Enabled()) return SolveStepAttempt();
  // A diverging iterate can make the system singular or invert an element: with splitting on,
  // that is one more reason to split, not the end of the analysis.
  try {
    return SolveStepAttempt();
  } catch (const SolutionError& e) {
    solver_error_ = e.what();
    return false;
  }
}

bool NewtonRaphsonStrategy::SplitStep() {
  ModelPart& root = model_part_.GetRootModelPart();
  ProcessInfo& info = root.GetProcessInfo();
  const double end_time = start_time_;
  const double delta_time = start_delta_time_;
  const double begin_time = end_time - delta_time;
  std::string last_failure = DescribeFailure();
  if (!callbacks_.initialize_solution_step && echo_level_ >= 1)
    Logger::Warning(Concat(Name(),
                           ": no process callbacks were given; boundary conditions and loads are not "
                           "updated in the sub-steps of a split step"));
  in_sub_step_ = true;
  for (int level = 1; level <= splitting_.max_number_splits; ++level) {
    const double sub_dt = delta_time / std::pow(splitting_.split_factor, level);
    if (echo_level_ >= 1)
      Logger::Info(Concat(Name(), ": step ", start_step_, " did not converge (", last_failure,
                          "); splitting it into sub-steps of ", sub_dt));
    RestoreStepStart();
    bool ok = true;
    double time = begin_time;
    const double tiny = 1e-9 * sub_dt;
    while (ok && time < end_time - tiny) {
      time = std::min(time + sub_dt, end_time);
      if (end_time - time < tiny) time = end_time;
      const bool last = time == end_time;
      root.CloneTimeStep(time);
      if (callbacks_.initialize_solution_step) callbacks_.initialize_solution_step();
      InitializeSolutionStep();
      Predict();
      ok = TrySolveStepAttempt();
      if (ok && !last) {
        FinalizeSolutionStep();
        if (callbacks_.finalize_solution_step) callbacks_.finalize_solution_step();
      }
      if (!ok) last_failure = DescribeFailure();
    }
    if (ok) {
      in_sub_step_ = false;
      split_level_ = level;
      info.SetValue(STEP, start_step_);
      info.SetValue(DELTA_TIME, delta_time);
      return true;
    }
  }
  in_sub_step_ = false;
  info.SetValue(STEP, start_step_);
  info.SetValue(DELTA_TIME, delta_time);
  throw SolutionError(Concat(Name(), ": step ", start_step_, " (time ", end_time, ") did not converge, not even split ",
                             splitting_.max_number_splits, " times (smallest sub-step ",
                             delta_time / std::pow(splitting_.split_factor, splitting_.max_number_splits),
                             "); the last attempt: ", last_failure));
}

void NewtonRaphsonStrategy::SaveStepStart() {
  ModelPart& root = model_part_.GetRootModelPart();
  const ProcessInfo& info = root.GetProcessInfo();
  start_time_ = info.GetValue(TIME);
  start_delta_time_ = info.GetValue(DELTA_TIME);
  start_step_ = info.GetValue(STEP);
  start_.clear();
  start_.reserve(root.NumberOfNodes());
  for (Node* p_node : root.Nodes()) {
    Node& node = *p_node;
    const std::size_t size = node.SolutionStepVariables().Stride() * static_cast<std::size_t>(node.BufferSize());
    start_.push_back({&node, std::vector<double>(node.StepData(0), node.StepData(0) + size)});
  }
}

void NewtonRaphsonStrategy::RestoreStepStart() {
  // The step started after the analysis cloned the time step (step 0 = copy of the converged
  // state, step k = converged state k-1 steps ago); going back one step shifts the history
  // forward, so that the sub-steps' CloneTimeStep rebuilds the same buffer.
  for (NodeStart& start : start_) {
    Node& node = *start.node;
    const std::size_t stride = node.SolutionStepVariables().Stride();
    const int buffer = node.BufferSize();
    for (int k = 0; k < buffer; ++k) {
      const int source = std::min(k + 1, buffer - 1);
      std::copy_n(start.history.begin() + static_cast<std::ptrdiff_t>(source * stride), stride, node.StepData(k));
    }
  }
  ProcessInfo& info = model_part_.GetRootModelPart().GetProcessInfo();
  info.SetValue(TIME, start_time_ - start_delta_time_);
  info.SetValue(STEP, start_step_ - 1);
  if (move_mesh_) MoveMesh();
}

std::string NewtonRaphsonStrategy::DescribeFailure() const {
  const ProcessInfo& info = model_part_.GetProcessInfo();
  const std::string step = Concat(Name(), ": step ", info.GetValue(STEP), " (time ", info.GetValue(TIME), ")");
  if (!solver_error_.empty()) return Concat(step, ": ", solver_error_);
  std::string norms;
  if (!history_.empty())
    norms = Concat("; last |r| = ", history_.back().residual_norm, ", |du| = ", history_.back().increment_norm);
  return Concat(step, ": not converged in ", max_iteration_, " iterations", norms, LargestResidualNodes(5));
}

std::string NewtonRaphsonStrategy::LargestResidualNodes(std::size_t count) const {
  const Vector& residual = builder_->Residual();
  std::vector<std::pair<double, const Dof*>> entries;
  for (const Dof* dof : builder_->GetDofSet())
    if (!dof->fixed && dof->equation_id >= 0 && dof->equation_id < residual.size())
      entries.emplace_back(std::abs(residual[dof->equation_id]), dof);
  // One entry per node: its largest DoF.
  std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string text;
  std::vector<IndexType> shown;
  for (const auto& [value, dof] : entries) {
    if (shown.size() == count || !(value > 0.0)) break;
    if (std::find(shown.begin(), shown.end(), dof->node->Id()) != shown.end()) continue;
    shown.push_back(dof->node->Id());
    text += Concat(shown.size() == 1 ? "; largest residuals at node " : ", node ", dof->node->Id(), " (",
                   dof->variable->Name(), " ", residual[dof->equation_id], ")");
  }
  return text;
}

bool NewtonRaphsonStrategy::NewtonIteration(int iteration) {
  model_part_.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, iteration);
  const auto& dofs = builder_->OwnedDofs();
  scheme_->InitializeNonLinIteration(model_part_);
  criteria_->InitializeNonLinearIteration(model_part_, dofs, builder_->SystemMatrix(), builder_->Increment(),
                                          builder_->Residual());
  criteria_->PreCriteria(model_part_, dofs, builder_->SystemMatrix(), builder_->Increment(), builder_->Residual());

  SolveIteration(iteration);
  IterationRecord record;
  record.iteration = iteration;
  if (const LinearSolver* solver = builder_->GetLinearSolver()) {
    record.linear_tolerance = solver->LastTolerance();
    record.linear_iterations = solver->IterationsNumber();
  }
  record.time = model_part_.GetProcessInfo().GetValue(TIME);
  record.residual_norm = builder_->Norm(builder_->Residual());
  record.step_length = UpdateDatabase(iteration);
  record.increment_norm = builder_->Norm(builder_->Increment());

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
  if (LinearSolver* solver = builder_->GetLinearSolver()) solver->SetForcingTerm(forcing_.ForIteration(iteration));
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
  criteria_->FinalizeSolutionStep(model_part_, builder_->OwnedDofs(), builder_->SystemMatrix(), builder_->Increment(),
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
  if (echo_level_ >= 1) Logger::Warning(failure_);
}

}  // namespace mc
