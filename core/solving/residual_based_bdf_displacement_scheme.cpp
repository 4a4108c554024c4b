// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/residual_based_bdf_displacement_scheme.h"

#include "core/model/model_part.h"

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
  ForEachDynamicDof(dofs, false, [&](const Dof& d, const Variable<double>& vel, const Variable<double>& acc) {
    Node& node = *d.node;
    double v = 0.0;
    for (int k = 0; k <= order_; ++k) v += c_[static_cast<std::size_t>(k)] * d.Value(k);
    node.FastGetSolutionStepValue(vel) = v;
    double a = 0.0;
    for (int k = 0; k <= order_; ++k) a += c_[static_cast<std::size_t>(k)] * node.FastGetSolutionStepValue(vel, k);
    node.FastGetSolutionStepValue(acc) = a;
  });
}

void ResidualBasedBDFDisplacementScheme::Predict(ModelPart& model_part, const DofsArray& dofs) {
  ForEachDynamicDof(dofs, true, [&](const Dof& d, const Variable<double>& vel, const Variable<double>&) {
    d.Value(0) = d.Value(1) + dt_ * d.node->FastGetSolutionStepValue(vel, 1);
  });
  UpdateDerivatives(dofs);
}

void ResidualBasedBDFDisplacementScheme::Update(ModelPart& model_part, const DofsArray& dofs, const Vector& dx) {
  Scheme::Update(model_part, dofs, dx);
  UpdateDerivatives(dofs);
}

}  // namespace mc
