// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_strategies/residualbased_newton_raphson_mpc_contact_strategy.h"

#include "core/utilities/error.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/normal_calculation_utilities.h"

namespace mc {

Parameters ResidualBasedNewtonRaphsonMPCContactStrategy::GetDefaultParameters() {
  return Parameters(R"({
      "simplified_semi_smooth_newton" : false,
      "inner_loop_iterations"         : 10,
      "update_each_nl_iteration"      : false,
      "enforce_ntn"                   : false
  })");
}

MPCContactStrategySettings ResidualBasedNewtonRaphsonMPCContactStrategy::ReadSettings(Parameters settings) {
  settings.AddMissingParameters(GetDefaultParameters());
  MPCContactStrategySettings s;
  s.inner_loop_iterations = settings["inner_loop_iterations"].GetInt();
  s.update_each_nl_iteration = settings["update_each_nl_iteration"].GetBool();
  s.simplified_semi_smooth_newton = settings["simplified_semi_smooth_newton"].GetBool();
  if (s.inner_loop_iterations < 1)
    throw InputError(
        Concat(settings["inner_loop_iterations"].Where(), ": ", s.inner_loop_iterations, " must be at least 1"));
  return s;
}

ResidualBasedNewtonRaphsonMPCContactStrategy::ResidualBasedNewtonRaphsonMPCContactStrategy(
    ModelPart& model_part, std::shared_ptr<Scheme> scheme, std::shared_ptr<ConvergenceCriteria> criteria,
    std::shared_ptr<BuilderAndSolver> builder_and_solver, MPCContactStrategySettings settings, int max_iteration,
    bool compute_reactions, bool reform_dofs_at_each_step, bool move_mesh_flag)
    : NewtonRaphsonStrategy(model_part, std::move(scheme), std::move(criteria), std::move(builder_and_solver),
                            max_iteration, compute_reactions, reform_dofs_at_each_step, move_mesh_flag),
      settings_(settings) {}

void ResidualBasedNewtonRaphsonMPCContactStrategy::Initialize() {
  NewtonRaphsonStrategy::Initialize();
  ModelPart& root = model_part_.GetRootModelPart();
  contact_ = FindContactModelPart(model_part_);
  if (!contact_ || !root.HasSubModelPart("ComputingContact"))
    throw InputError(Concat(Name(), ": ", root.Name(),
                            " has no Contact interface: the MPC contact solver needs an mpc_contact_process"));
  constraints_ = std::make_shared<MPCContactConstraints>(*contact_, root.GetSubModelPart("ComputingContact"));
  // mpc_contact_process flags the root SLIP for contact_type Frictional.
  constraints_->SetFrictional(root.Is(SLIP));
  mpc_criteria_ = std::make_shared<MPCContactCriteria>(constraints_);
  const ProcessInfo& info = root.GetProcessInfo();
  mpc_criteria_->SetPureSlip(root.Is(SLIP) && info.Has(PURE_SLIP) && info.GetValue(PURE_SLIP));
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::InitializeSolutionStep() {
  NewtonRaphsonStrategy::InitializeSolutionStep();
  passes_ = 0;
  tying_ = model_part_.GetRootModelPart().Is(RIGID);
  if (tying_) {
    TieInterface();
    return;
  }
  mpc_criteria_->InitializeSolutionStep(model_part_, builder_->GetDofSet(), builder_->SystemMatrix(),
                                        builder_->Increment(), builder_->Residual());
  constraints_->Measure();
  constraints_->Relate();
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::TieInterface() {
  if (!tied_) {
    constraints_->Measure();
    constraints_->RelateAllComponents();
    if (constraints_->Relations().empty())
      throw InputError(Concat(Name(), ": mesh tying: no slave node of ", contact_->FullName(),
                              " faces a master face (or every slave component is fixed): nothing to tie; check ",
                              "contact_model_part, assume_master_slave and search_parameters of mpc_contact_process"));
    tied_ = true;
  }
  // The search of each step guesses the set from the gaps: the tied nodes stay active whatever it says.
  for (Node* node : contact_->Nodes()) node->Set(ACTIVE, false);
  for (const auto& [node, relation] : constraints_->Relations()) node->Set(ACTIVE, true);
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::Predict() {
  NewtonRaphsonStrategy::Predict();
  if (tying_) return;  // no active set to predict
  // One constrained linear solve on the search's guess of the set, whose reactions give the set Newton
  // starts from. The solve only decides the set: Newton starts from the predicted state again, so that
  // its first residual (the residual criterion's reference) is the step's, not the round-off left by
  // a linear solve that already solved a linear problem.
  ApplyConstraints();
  builder_->BuildAndSolve(*scheme_, model_part_);
  const Vector increment = builder_->Increment();
  UpdateAndMoveMesh(increment);
  UpdateActiveSet();
  UpdateAndMoveMesh(-increment);
}

bool ResidualBasedNewtonRaphsonMPCContactStrategy::NewtonIteration(int iteration) {
  if (tying_) {
    ApplyConstraints();
    return NewtonRaphsonStrategy::NewtonIteration(iteration);
  }
  if (settings_.update_each_nl_iteration && iteration > 1) {
    constraints_->Measure();
    constraints_->Relate();
  }
  ApplyConstraints();
  const bool converged = NewtonRaphsonStrategy::NewtonIteration(iteration);
  if (settings_.simplified_semi_smooth_newton) return converged;
  const bool unchanged = UpdateActiveSet() || HoldCycle();
  history_.back().converged = converged && unchanged;
  for (const CriterionValue& value : mpc_criteria_->LastValues()) history_.back().criteria.push_back(value);
  return history_.back().converged;
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::ApplyConstraints() {
  constraints_->Apply(*builder_);
  if (!constraints_->IsFrictional()) return;
  auto coulomb = constraints_->CoulombTerms(mpc_criteria_->SlipDirections(), mpc_criteria_->TurnStiffness());
  builder_->SetResidualCombination(std::move(coulomb.combination), std::move(coulomb.stiffness));
}

bool ResidualBasedNewtonRaphsonMPCContactStrategy::SolveStepAttempt() {
  if (tying_) {
    passes_ = 1;
    if (!NewtonRaphsonStrategy::SolveStepAttempt()) return false;
    WriteTyingForces();
    return true;
  }
  const int passes = settings_.simplified_semi_smooth_newton ? settings_.inner_loop_iterations : 1;
  cycle_ = ContactStateCycle(ContactStates(*contact_));
  held_ = false;
  for (passes_ = 1; passes_ <= passes; ++passes_) {
    if (!NewtonRaphsonStrategy::SolveStepAttempt()) return false;
    if (!settings_.simplified_semi_smooth_newton || UpdateActiveSet()) return true;
  }
  passes_ = passes;
  return false;
}

bool ResidualBasedNewtonRaphsonMPCContactStrategy::UpdateActiveSet() {
  builder_->BuildRHS(*scheme_, model_part_);
  WriteInterfaceReactions();
  constraints_->Measure();
  const auto& dofs = builder_->GetDofSet();
  return mpc_criteria_->PostCriteria(model_part_, dofs, builder_->SystemMatrix(), builder_->Increment(),
                                     builder_->Residual());
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::WriteInterfaceReactions() {
  const Vector& raw = builder_->RawResidual();
  const Variable<double>* const reactions[3] = {&REACTION_X, &REACTION_Y, &REACTION_Z};
  const Variable<double>* const displacements[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
  for (Node* node : contact_->Nodes())
    for (int c = 0; c < 3; ++c)
      if (node->HasDofFor(*displacements[c])) {
        const Dof& dof = node->GetDof(*displacements[c]);
        if (dof.equation_id >= 0 && dof.equation_id < raw.size())
          node->FastGetSolutionStepValue(*reactions[c]) = -raw[dof.equation_id];
      }
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::WriteTyingForces() {
  builder_->BuildRHS(*scheme_, model_part_);
  WriteInterfaceReactions();
  for (Node* node : contact_->Nodes()) {
    if (!node->Is(SLAVE)) continue;
    const double area = node->GetValue(NODAL_MAUX);
    const Array3 force = node->Is(ACTIVE) ? node->FastGetSolutionStepValue(REACTION) : Array3(Array3::Zero());
    node->SetValue(CONTACT_FORCE, force);
    node->SetValue(NORMAL_CONTACT_STRESS,
                   area > 0.0 ? force.dot(NormalCalculationUtilities::GetNodalNormal(*node)) / area : 0.0);
  }
}

bool ResidualBasedNewtonRaphsonMPCContactStrategy::HoldCycle() {
  if (held_) {
    SetContactStates(*contact_, held_states_);
    return true;
  }
  std::vector<char> states = ContactStates(*contact_);
  const std::vector<char> decided = states;
  if (cycle_.Close(states) < 0) return false;
  // A node the criterion has just stuck is held stuck, not slipping as the union would: it sticks
  // because its slip ran against s, and held slipping it has no answer (as pure slip under a weak push:
  // s flips every iteration; 15k Cattaneo-Mindlin, step 15, node 977: |s_new - s_old| 1.7-2.0 for 20
  // iterations). Tied, it always has one, its tangential force a little outside the cone.
  for (std::size_t i = 0; i < states.size(); ++i)
    if ((decided[i] & kActiveState) && !(decided[i] & kSlipState))
      states[i] = static_cast<char>(states[i] & ~kSlipState);
  held_states_ = states;
  SetContactStates(*contact_, states);
  held_ = true;
  if (echo_level_ >= 1)
    Logger::Info(Concat(Name(), ": the active set cycles; the union of the cycle's sets is held for this step"));
  return false;
}

Parameters ResidualBasedNewtonRaphsonMPCContactStrategy::RestartState() const {
  if (!constraints_) throw Error(Concat(Name(), ": RestartState before Initialize"));
  Parameters state;
  state.AddBool("tied", tied_);
  state.AddValue("tying_operators", tied_ ? constraints_->TyingOperators() : Parameters("[]"));
  mpc_criteria_->SaveState(state);
  return state;
}

void ResidualBasedNewtonRaphsonMPCContactStrategy::LoadRestartState(const Parameters& state) {
  if (!constraints_) throw Error(Concat(Name(), ": LoadRestartState before Initialize"));
  mpc_criteria_->LoadState(state, *contact_);
  tied_ = state["tied"].GetBool();
  if (tied_) constraints_->RelateAllComponents(state["tying_operators"]);
}

std::size_t ResidualBasedNewtonRaphsonMPCContactStrategy::NumberOfActiveNodes() const {
  std::size_t count = 0;
  if (contact_)
    for (const Node* node : contact_->Nodes())
      if (node->Is(SLAVE) && node->Is(ACTIVE)) ++count;
  return count;
}

}  // namespace mc
