// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/explicit_strategy.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "core/model/model_part.h"
#include "core/model/parallel_utilities.h"
#include "core/variables/kernel_variables.h"

namespace mc {

ExplicitStrategy::ExplicitStrategy(ModelPart& model_part, std::shared_ptr<ExplicitCentralDifferencesScheme> scheme,
                                   bool compute_reactions, bool reform_dofs_at_each_step, bool move_mesh_flag)
    : SolvingStrategy(model_part, move_mesh_flag),
      scheme_(std::move(scheme)),
      compute_reactions_(compute_reactions),
      reform_dofs_(reform_dofs_at_each_step) {
  if (!scheme_) throw Error("the explicit strategy needs a scheme");
}

void ExplicitStrategy::Initialize() {
  if (!scheme_->IsInitialized()) scheme_->Initialize(model_part_);
  SolvingStrategy::Initialize();
}

void ExplicitStrategy::SetUpDofsAndMass() {
  builder_.SetUpDofSet(model_part_, *scheme_);
  builder_.SetUpSystem();
  const auto& dofs = builder_.GetDofSet();
  mass_.setZero(static_cast<Eigen::Index>(dofs.size()));
  double* mass = mass_.data();
  const ProcessInfo& info = model_part_.GetProcessInfo();
  ForEachActiveEntity(model_part_, [&](Entity& e) {
    static thread_local Matrix local;
    static thread_local DofsVectorType entity_dofs;
    e.CalculateMassMatrix(local, info);
    if (local.size() == 0) return;
    scheme_->GetDofList(e, entity_dofs, info);
    for (std::size_t i = 0; i < entity_dofs.size(); ++i) {
      // The row sum is the lumped value whether the entity returns a lumped or consistent matrix.
      const double m = local.row(static_cast<Eigen::Index>(i)).sum();
#pragma omp atomic
      mass[entity_dofs[i]->equation_id] += m;
    }
  });
  for (Node* node : model_part_.Nodes()) {
    const Dof* d = node->FindDof(DISPLACEMENT_X);
    if (!d && !node->Dofs().empty()) d = node->Dofs().front().get();
    if (d && d->equation_id >= 0 && static_cast<std::size_t>(d->equation_id) < dofs.size() &&
        dofs[static_cast<std::size_t>(d->equation_id)] == d)
      node->SetValue(NODAL_MASS, mass_[d->equation_id]);
  }
  dofs_ready_ = true;
}

void ExplicitStrategy::InitializeSolutionStep() {
  if (!initialized_) Initialize();
  if (!dofs_ready_ || reform_dofs_) SetUpDofsAndMass();
  scheme_->InitializeSolutionStep(model_part_);
}

bool ExplicitStrategy::SolveSolutionStep() {
  scheme_->InitializeNonLinIteration(model_part_);
  UpdateBeforeResidual();
  builder_.BuildRHS(*scheme_, model_part_);
  UpdateAfterResidual();
  scheme_->Advance(model_part_, builder_.GetDofSet(), builder_.Residual(), mass_);
  if (move_mesh_) MoveMesh();
  scheme_->FinalizeNonLinIteration(model_part_);
  return true;
}

void ExplicitStrategy::FinalizeSolutionStep() {
  // Reactions of the residual this step was driven by (at the start of the step).
  if (compute_reactions_) builder_.WriteReactions();
  scheme_->FinalizeSolutionStep(model_part_);
}

void ExplicitStrategy::Clear() {
  builder_.Clear();
  dofs_ready_ = false;
}

double ExplicitStrategy::ElementStableTimeStep() const {
  const ProcessInfo& info = model_part_.GetProcessInfo();
  double omega2 = 0.0;
  for (Element* e : model_part_.Elements()) {
    if (!e->IsActive()) continue;
    Matrix stiffness, mass;
    e->CalculateLeftHandSide(stiffness, info);
    e->CalculateMassMatrix(mass, info);
    if (stiffness.size() == 0 || mass.rows() != stiffness.rows()) continue;
    const Vector lumped = mass.rowwise().sum();
    if (!(lumped.minCoeff() > 0.0)) continue;
    const Vector scale = lumped.cwiseSqrt().cwiseInverse();
    const Matrix scaled = scale.asDiagonal() * (0.5 * (stiffness + stiffness.transpose())) * scale.asDiagonal();
    const Eigen::SelfAdjointEigenSolver<Matrix> eigen(scaled, Eigen::EigenvaluesOnly);
    omega2 = std::max(omega2, eigen.eigenvalues().maxCoeff());
  }
  return omega2 > 0.0 ? 2.0 / std::sqrt(omega2) : std::numeric_limits<double>::infinity();
}

void ExplicitStrategy::Check() const { scheme_->Check(model_part_); }

}  // namespace mc
