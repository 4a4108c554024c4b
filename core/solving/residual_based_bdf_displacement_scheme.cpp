// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/residual_based_bdf_displacement_scheme.h"

#include "core/model/model_part.h"
#include "core/model/parallel_utilities.h"
#include "core/solving/time_derivatives.h"

namespace mc {

ResidualBasedBDFDisplacementScheme::ResidualBasedBDFDisplacementScheme(int order) : order_(order) {
  if (order < 1 || order > kMaxOrder)
    throw InputError(Concat("BDF scheme: order ", order, " is outside 1..", kMaxOrder, " (bdf1 to bdf5)"));
}

void ResidualBasedBDFDisplacementScheme::FillInitialHistory(ModelPart& model_part) const {
  // After the first CloneTimeStep the initial state is at buffer position 1.
  struct Triple {
    const Variable<Array3>* u;
    const Variable<Array3>* v;
    const Variable<Array3>* a;
  };
  const int buffer = model_part.GetBufferSize();
  for (const Triple& t :
       {Triple{&DISPLACEMENT, &VELOCITY, &ACCELERATION}, Triple{&ROTATION, &ANGULAR_VELOCITY, &ANGULAR_ACCELERATION}}) {
    if (!model_part.HasNodalSolutionStepVariable(*t.u) || !model_part.HasNodalSolutionStepVariable(*t.v) ||
        !model_part.HasNodalSolutionStepVariable(*t.a))
      continue;
    for (Node* node : model_part.Nodes()) {
      const Array3 u = node->FastGetSolutionStepValue(*t.u, 1);
      const Array3 v = node->FastGetSolutionStepValue(*t.v, 1);
      const Array3 a = node->FastGetSolutionStepValue(*t.a, 1);
      for (int step = 2; step < buffer; ++step) {
        const double s = (step - 1) * dt_;
        node->FastGetSolutionStepValue(*t.u, step) = u - s * v + 0.5 * s * s * a;
        node->FastGetSolutionStepValue(*t.v, step) = v - s * a;
        node->FastGetSolutionStepValue(*t.a, step) = a;
      }
    }
  }
}

void ResidualBasedBDFDisplacementScheme::InitializeSolutionStep(ModelPart& model_part) {
  dt_ = model_part.GetProcessInfo().GetValue(DELTA_TIME);
  if (!(dt_ > 0.0))
    throw InputError(Concat(Name(), " scheme: DELTA_TIME = ", dt_, " must be positive (check time_stepping)"));
  // Times relative to t_{n+1}: tau_0 = 0, tau_i = -(dt + dt_{n} + ... ).
  std::array<double, kMaxOrder + 1> tau{};
  for (int i = 1; i <= order_; ++i) {
    const double h = i == 1 ? dt_ : previous_dt_[static_cast<std::size_t>(i - 2)];
    tau[static_cast<std::size_t>(i)] = tau[static_cast<std::size_t>(i - 1)] - (h > 0.0 ? h : dt_);
  }
  // c_j = L_j'(0) of the Lagrange basis through tau_0..tau_p.
  c_.fill(0.0);
  for (int k = 1; k <= order_; ++k) c_[0] -= 1.0 / tau[static_cast<std::size_t>(k)];
  for (int j = 1; j <= order_; ++j) {
    double value = 1.0 / tau[static_cast<std::size_t>(j)];
    for (int k = 1; k <= order_; ++k)
      if (k != j)
        value *=
            -tau[static_cast<std::size_t>(k)] / (tau[static_cast<std::size_t>(j)] - tau[static_cast<std::size_t>(k)]);
    c_[static_cast<std::size_t>(j)] = value;
  }
  if (!history_filled_) {
    FillInitialHistory(model_part);
    history_filled_ = true;
  }
  Scheme::InitializeSolutionStep(model_part);
}

void ResidualBasedBDFDisplacementScheme::FinalizeSolutionStep(ModelPart& model_part) {
  Scheme::FinalizeSolutionStep(model_part);
  for (std::size_t i = previous_dt_.size() - 1; i > 0; --i) previous_dt_[i] = previous_dt_[i - 1];
  previous_dt_[0] = dt_;
}

void ResidualBasedBDFDisplacementScheme::UpdateDerivatives(const DofsArray& dofs) const {
  const long n = static_cast<long>(dofs.size());
#pragma omp parallel for schedule(static) if (n >= kMinParallelDofs)
  for (long i = 0; i < n; ++i) {
    const Dof& d = *dofs[i];
    const Variable<double>* vel = TimeDerivativeOf(*d.variable, 1);
    const Variable<double>* acc = TimeDerivativeOf(*d.variable, 2);
    if (!vel || !d.node->HasSolutionStepValue(*vel) || !d.node->HasSolutionStepValue(*acc)) continue;
    Node& node = *d.node;
    double v = 0.0;
    for (int k = 0; k <= order_; ++k) v += c_[static_cast<std::size_t>(k)] * d.Value(k);
    node.FastGetSolutionStepValue(*vel) = v;
    double a = 0.0;
    for (int k = 0; k <= order_; ++k) a += c_[static_cast<std::size_t>(k)] * node.FastGetSolutionStepValue(*vel, k);
    node.FastGetSolutionStepValue(*acc) = a;
  }
}

void ResidualBasedBDFDisplacementScheme::Predict(ModelPart& model_part, const DofsArray& dofs) {
  const long n = static_cast<long>(dofs.size());
#pragma omp parallel for schedule(static) if (n >= kMinParallelDofs)
  for (long i = 0; i < n; ++i) {
    const Dof& d = *dofs[i];
    if (d.fixed) continue;
    const Variable<double>* vel = TimeDerivativeOf(*d.variable, 1);
    if (!vel || !d.node->HasSolutionStepValue(*vel)) continue;
    d.Value(0) = d.Value(1) + dt_ * d.node->FastGetSolutionStepValue(*vel, 1);
  }
  UpdateDerivatives(dofs);
}

void ResidualBasedBDFDisplacementScheme::Update(ModelPart& model_part, const DofsArray& dofs, const Vector& dx) {
  Scheme::Update(model_part, dofs, dx);
  UpdateDerivatives(dofs);
}

void ResidualBasedBDFDisplacementScheme::Check(const ModelPart& model_part) const {
  Scheme::Check(model_part);
  if (model_part.GetBufferSize() < static_cast<std::size_t>(order_) + 1)
    throw InputError(Concat(Name(), " scheme: buffer_size ", model_part.GetBufferSize(), " of model part ",
                            model_part.Name(), " must be at least ", order_ + 1));
  for (const VariableData* v :
       {static_cast<const VariableData*>(&VELOCITY), static_cast<const VariableData*>(&ACCELERATION)})
    if (!model_part.HasNodalSolutionStepVariable(*v))
      throw InputError(
          Concat(Name(), " scheme: ", v->Name(), " is not a historical variable of model part ", model_part.Name()));
}

void ResidualBasedBDFDisplacementScheme::CalculateSystemContributions(Entity& entity, Matrix& lhs, Vector& rhs,
                                                                      EquationIdVectorType& ids,
                                                                      const ProcessInfo& info) {
  entity.CalculateLocalSystem(lhs, rhs, info);
  AddDynamics(entity, &lhs, &rhs, ids, info);
}

void ResidualBasedBDFDisplacementScheme::CalculateLHSContribution(Entity& entity, Matrix& lhs,
                                                                  EquationIdVectorType& ids, const ProcessInfo& info) {
  entity.CalculateLeftHandSide(lhs, info);
  AddDynamics(entity, &lhs, nullptr, ids, info);
}

void ResidualBasedBDFDisplacementScheme::CalculateRHSContribution(Entity& entity, Vector& rhs,
                                                                  EquationIdVectorType& ids, const ProcessInfo& info) {
  entity.CalculateRightHandSide(rhs, info);
  AddDynamics(entity, nullptr, &rhs, ids, info);
}

void ResidualBasedBDFDisplacementScheme::AddDynamics(Entity& entity, Matrix* lhs, Vector* rhs,
                                                     EquationIdVectorType& ids, const ProcessInfo& info) {
  static thread_local Matrix mass;
  static thread_local Matrix damping;
  static thread_local Vector derivative;
  entity.CalculateMassMatrix(mass, info);
  entity.CalculateDampingMatrix(damping, info);
  const double c0 = c_[0];
  if (lhs) {
    if (mass.size() > 0) *lhs += c0 * c0 * mass;
    if (damping.size() > 0) *lhs += c0 * damping;
  }
  if (rhs) {
    if (mass.size() > 0) {
      entity.GetSecondDerivativesVector(derivative, 0);
      rhs->noalias() -= mass * derivative;
    }
    if (damping.size() > 0) {
      entity.GetFirstDerivativesVector(derivative, 0);
      rhs->noalias() -= damping * derivative;
    }
  }
  entity.EquationIdVector(ids, info);
}

}  // namespace mc
