// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/implicit_solving_strategy.h"

#include "core/model/model_part.h"
#include "core/utilities/error.h"

namespace mc {

ImplicitSolvingStrategy::ImplicitSolvingStrategy(ModelPart& model_part, std::shared_ptr<Scheme> scheme,
                                                 std::shared_ptr<BuilderAndSolver> builder_and_solver,
                                                 bool compute_reactions, bool reform_dofs_at_each_step,
                                                 bool move_mesh_flag)
    : SolvingStrategy(model_part, move_mesh_flag),
      scheme_(std::move(scheme)),
      builder_(std::move(builder_and_solver)),
      compute_reactions_(compute_reactions),
      reform_dofs_(reform_dofs_at_each_step) {
  if (!scheme_ || !builder_) throw Error("an implicit strategy needs a scheme and a builder-and-solver");
}

void ImplicitSolvingStrategy::Initialize() {
  if (!scheme_->IsInitialized()) scheme_->Initialize(model_part_);
  SolvingStrategy::Initialize();
}

void ImplicitSolvingStrategy::InitializeSolutionStep() {
  if (!initialized_) Initialize();
  if (!dofs_ready_ || reform_dofs_) {
    builder_->SetUpDofSet(model_part_, *scheme_);
    builder_->SetUpSystem();
    dofs_ready_ = true;
  }
  builder_->ForgetElementMatrix();
  scheme_->InitializeSolutionStep(model_part_);
}

void ImplicitSolvingStrategy::Predict() {
  scheme_->Predict(model_part_, builder_->GetDofSet());
  if (move_mesh_) MoveMesh();
}

void ImplicitSolvingStrategy::FinalizeSolutionStep() {
  if (compute_reactions_) builder_->CalculateReactions(*scheme_, model_part_);
  scheme_->FinalizeSolutionStep(model_part_);
}

void ImplicitSolvingStrategy::Clear() {
  builder_->Clear();
  dofs_ready_ = false;
}

void ImplicitSolvingStrategy::Check() const { scheme_->Check(model_part_); }

void ImplicitSolvingStrategy::SetEchoLevel(int level) {
  SolvingStrategy::SetEchoLevel(level);
  builder_->SetEchoLevel(level);
}

void ImplicitSolvingStrategy::UpdateAndMoveMesh(const Vector& dx) {
  scheme_->Update(model_part_, builder_->GetDofSet(), dx);
  if (move_mesh_) MoveMesh();
}

}  // namespace mc
