// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/residual_based_bossak_displacement_scheme.h"
#include "core/model/parallel_utilities.h"

#include "core/model/model_part.h"
#include "core/solving/time_derivatives.h"

namespace mc {

ResidualBasedBossakDisplacementScheme::ResidualBasedBossakDisplacementScheme(double alpha_m,
                                                                             std::optional<double> newmark_beta)
    : alpha_(alpha_m),
      beta_(newmark_beta ? *newmark_beta : 0.25 * (1.0 - alpha_m) * (1.0 - alpha_m)),
      gamma_(0.5 - alpha_m) {
  if (alpha_m < -1.0 / 3.0 || alpha_m > 0.0)
    throw InputError(Concat("damp_factor_m = ", alpha_m, " is outside [-1/3, 0], where the Bossak scheme is stable"));
  if (!(beta_ > 0.0)) throw InputError(Concat("newmark_beta = ", beta_, " must be positive"));
}

void ResidualBasedBossakDisplacementScheme::InitializeSolutionStep(ModelPart& model_part) {
  ProcessInfo& info = model_part.GetProcessInfo();
  dt_ = info.GetValue(DELTA_TIME);
  if (!(dt_ > 0.0))
    throw InputError(Concat(Name(), " scheme: DELTA_TIME = ", dt_, " must be positive (check time_stepping)"));
  c0_ = (1.0 - alpha_) / (beta_ * dt_ * dt_);
  c1_ = gamma_ / (beta_ * dt_);
  info.SetValue(BOSSAK_ALPHA, alpha_);
  info.SetValue(NEWMARK_BETA, beta_);
  info.SetValue(NEWMARK_GAMMA, gamma_);
  Scheme::InitializeSolutionStep(model_part);
}

void ResidualBasedBossakDisplacementScheme::UpdateDerivatives(const DofsArray& dofs) const {
  const double a0 = 1.0 / (beta_ * dt_ * dt_);
  const double a2 = 1.0 / (beta_ * dt_);
  const double a3 = 0.5 / beta_ - 1.0;
  const long n = static_cast<long>(dofs.size());
#pragma omp parallel for schedule(static) if (n >= kMinParallelDofs)
  for (long i = 0; i < n; ++i) {
    const Dof& d = *dofs[i];
    const Variable<double>* vel = TimeDerivativeOf(*d.variable, 1);
    const Variable<double>* acc = TimeDerivativeOf(*d.variable, 2);
    if (!vel || !d.node->HasSolutionStepValue(*vel) || !d.node->HasSolutionStepValue(*acc)) continue;
    Node& node = *d.node;
    const double du = d.Value(0) - d.Value(1);
    const double v_old = node.FastGetSolutionStepValue(*vel, 1);
    const double a_old = node.FastGetSolutionStepValue(*acc, 1);
    const double a_new = a0 * du - a2 * v_old - a3 * a_old;
    node.FastGetSolutionStepValue(*acc) = a_new;
    node.FastGetSolutionStepValue(*vel) = v_old + dt_ * ((1.0 - gamma_) * a_old + gamma_ * a_new);
  }
}

void ResidualBasedBossakDisplacementScheme::Predict(ModelPart& model_part, const DofsArray& dofs) {
  const long n = static_cast<long>(dofs.size());
#pragma omp parallel for schedule(static) if (n >= kMinParallelDofs)
  for (long i = 0; i < n; ++i) {
    const Dof& d = *dofs[i];
    if (d.fixed) continue;
    const Variable<double>* vel = TimeDerivativeOf(*d.variable, 1);
    const Variable<double>* acc = TimeDerivativeOf(*d.variable, 2);
    if (!vel || !d.node->HasSolutionStepValue(*vel) || !d.node->HasSolutionStepValue(*acc)) continue;
    const double v_old = d.node->FastGetSolutionStepValue(*vel, 1);
    const double a_old = d.node->FastGetSolutionStepValue(*acc, 1);
    d.Value(0) = d.Value(1) + dt_ * v_old + 0.5 * dt_ * dt_ * a_old;
  }
  UpdateDerivatives(dofs);
}

void ResidualBasedBossakDisplacementScheme::Update(ModelPart& model_part, const DofsArray& dofs, const Vector& dx) {
  Scheme::Update(model_part, dofs, dx);
  UpdateDerivatives(dofs);
}

void ResidualBasedBossakDisplacementScheme::Check(const ModelPart& model_part) const {
  Scheme::Check(model_part);
  if (model_part.GetBufferSize() < 2)
    throw InputError(Concat(Name(), " scheme: buffer_size ", model_part.GetBufferSize(), " of model part ",
                            model_part.Name(), " must be at least 2"));
  for (const VariableData* v :
       {static_cast<const VariableData*>(&VELOCITY), static_cast<const VariableData*>(&ACCELERATION)})
    if (!model_part.HasNodalSolutionStepVariable(*v))
      throw InputError(
          Concat(Name(), " scheme: ", v->Name(), " is not a historical variable of model part ", model_part.Name()));
}

void ResidualBasedBossakDisplacementScheme::AddDynamicsToLHS(Matrix& lhs, const Matrix& mass,
                                                             const Matrix& damping) const {
  if (mass.size() > 0) lhs += c0_ * mass;
  if (damping.size() > 0) lhs += c1_ * damping;
}

void ResidualBasedBossakDisplacementScheme::AddDynamicsToRHS(const Entity& entity, Vector& rhs, const Matrix& mass,
                                                             const Matrix& damping) const {
  static thread_local Vector current;
  static thread_local Vector previous;
  if (mass.size() > 0) {
    entity.GetSecondDerivativesVector(current, 0);
    entity.GetSecondDerivativesVector(previous, 1);
    current *= 1.0 - alpha_;
    current += alpha_ * previous;
    rhs.noalias() -= mass * current;
  }
  if (damping.size() > 0) {
    entity.GetFirstDerivativesVector(current, 0);
    rhs.noalias() -= damping * current;
  }
}

void ResidualBasedBossakDisplacementScheme::CalculateSystemContributions(Entity& entity, Matrix& lhs, Vector& rhs,
                                                                         EquationIdVectorType& ids,
                                                                         const ProcessInfo& info) {
  entity.CalculateLocalSystem(lhs, rhs, info);
  AddDynamics(entity, &lhs, &rhs, ids, info);
}

void ResidualBasedBossakDisplacementScheme::CalculateLHSContribution(Entity& entity, Matrix& lhs,
                                                                     EquationIdVectorType& ids,
                                                                     const ProcessInfo& info) {
  entity.CalculateLeftHandSide(lhs, info);
  AddDynamics(entity, &lhs, nullptr, ids, info);
}

void ResidualBasedBossakDisplacementScheme::CalculateRHSContribution(Entity& entity, Vector& rhs,
                                                                     EquationIdVectorType& ids,
                                                                     const ProcessInfo& info) {
  entity.CalculateRightHandSide(rhs, info);
  AddDynamics(entity, nullptr, &rhs, ids, info);
}

void ResidualBasedBossakDisplacementScheme::AddDynamics(Entity& entity, Matrix* lhs, Vector* rhs,
                                                        EquationIdVectorType& ids, const ProcessInfo& info) {
  static thread_local Matrix mass;
  static thread_local Matrix damping;
  entity.CalculateMassMatrix(mass, info);
  entity.CalculateDampingMatrix(damping, info);
  if (lhs) AddDynamicsToLHS(*lhs, mass, damping);
  if (rhs) AddDynamicsToRHS(entity, *rhs, mass, damping);
  entity.EquationIdVector(ids, info);
}

}  // namespace mc
