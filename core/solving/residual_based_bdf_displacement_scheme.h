// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <string>

#include "core/solving/implicit_dynamic_scheme.h"

namespace mc {

/// Implicit dynamics by the backward differentiation formula of order p = 1..5
/// (`scheme_type` `bdf1`..`bdf5`; `backward_euler` is `bdf1`), as Kratos'
/// ResidualBasedBDFDisplacementScheme: the velocity is the BDF derivative of the displacements
/// and the acceleration the same derivative of the velocities,
///   v_{n+1} = sum_{i=0..p} c_i u_{n+1-i},   a_{n+1} = sum_{i=0..p} c_i v_{n+1-i},
/// where c_i = L_i'(t_{n+1}) are the derivatives of the Lagrange polynomials through the last
/// p + 1 times, so a changing DELTA_TIME (adaptive sub-steps) keeps the order. The local systems
/// are
///   LHS = K + c_0^2 M + c_0 D,   RHS = f_ext - f_int - M a_{n+1} - D v_{n+1}.
/// Needs buffer_size >= p + 1. At the first step the older buffer positions hold no past
/// (Kratos leaves them zero, which turns an initial displacement into a jump and an initial
/// velocity into an O(dt) error that drifts over the run, first order globally): they are
/// filled with the Taylor expansion of the initial state backwards in time,
/// u(-s) = u_0 - s v_0 + s^2/2 a_0, v(-s) = v_0 - s a_0, consistent to second order.
class ResidualBasedBDFDisplacementScheme : public ImplicitDynamicScheme {
 public:
  static constexpr int kMaxOrder = 5;

  /// InputError unless 1 <= order <= 5.
  explicit ResidualBasedBDFDisplacementScheme(int order = 2);

  std::string Name() const override { return "bdf" + std::to_string(order_); }
  int Order() const noexcept { return order_; }
  /// c_i of the current step (valid after InitializeSolutionStep), in 1 / time.
  double Coefficient(int i) const { return c_.at(static_cast<std::size_t>(i)); }

  /// Reads DELTA_TIME (InputError if not positive) and computes the coefficients from it and
  /// the step sizes of the previous steps; at the first step, fills the history.
  void InitializeSolutionStep(ModelPart& model_part) override;
  /// Records the step size for the coefficients of the next steps.
  void FinalizeSolutionStep(ModelPart& model_part) override;
  /// u_{n+1} = u_n + dt v_n for free DoFs; derivatives of every DoF follow its value.
  void Predict(ModelPart& model_part, const DofsArray& dofs) override;
  void Update(ModelPart& model_part, const DofsArray& dofs, const Vector& dx) override;

 protected:
  int MinimumBufferSize() const override { return order_ + 1; }
  double MassFactor() const override { return c_[0] * c_[0]; }
  double DampingFactor() const override { return c_[0]; }

 private:
  void UpdateDerivatives(const DofsArray& dofs) const;
  void FillInitialHistory(ModelPart& model_part) const;

  int order_;
  double dt_ = 0.0;
  std::array<double, kMaxOrder + 1> c_{};
  /// Sizes of the last steps, newest first; 0 before a step was taken (taken as the current one).
  std::array<double, kMaxOrder> previous_dt_{};
  bool history_filled_ = false;
};

}  // namespace mc
