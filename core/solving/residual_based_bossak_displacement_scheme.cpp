// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/residual_based_bossak_displacement_scheme.h"

#include "core/model/model_part.h"

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
  ForEachDynamicDof(dofs, false, [&](const Dof& d, const Variable<double>& vel, const Variable<double>& acc) {
    Node& node = *d.node;
    const double du = d.Value(0) - d.Value(1);
    const double v_old = node.FastGetSolutionStepValue(vel, 1);
    const double a_old = node.FastGetSolutionStepValue(acc, 1);
    const double a_new = a0 * du - a2 * v_old - a3 * a_old;
    node.FastGetSolutionStepValue(acc) = a_new;
    node.FastGetSolutionStepValue(vel) = v_old + dt_ * ((1.0 - gamma_) * a_old + gamma_ * a_new);
  });
}

void ResidualBasedBossakDisplacementScheme::Predict(ModelPart& model_part, const DofsArray& dofs) {
  ForEachDynamicDof(dofs, true, [&](const Dof& d, const Variable<double>& vel, const Variable<double>& acc) {
    const double v_old = d.node->FastGetSolutionStepValue(vel, 1);
    const double a_old = d.node->FastGetSolutionStepValue(acc, 1);
    d.Value(0) = d.Value(1) + dt_ * v_old + 0.5 * dt_ * dt_ * a_old;
  });
  UpdateDerivatives(dofs);
}

void ResidualBasedBossakDisplacementScheme::Update(ModelPart& model_part, const DofsArray& dofs, const Vector& dx) {
  Scheme::Update(model_part, dofs, dx);
  UpdateDerivatives(dofs);
}

void ResidualBasedBossakDisplacementScheme::InertialAcceleration(const Entity& entity, Vector& acceleration) const {
  static thread_local Vector previous;
  entity.GetSecondDerivativesVector(acceleration, 0);
  entity.GetSecondDerivativesVector(previous, 1);
  acceleration *= 1.0 - alpha_;
  acceleration += alpha_ * previous;
}

}  // namespace mc
