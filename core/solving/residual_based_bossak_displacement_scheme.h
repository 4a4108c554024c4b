// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <optional>

#include "core/solving/implicit_dynamic_scheme.h"

namespace mc {

/// Implicit dynamics by the Bossak (alpha_m) variant of Newmark's method:
///   M [(1 - a) acc_{n+1} + a acc_n] + D v_{n+1} + f_int(u_{n+1}) = f_ext,
///   u_{n+1} = u_n + dt v_n + dt^2 [(1/2 - beta) acc_n + beta acc_{n+1}],
///   v_{n+1} = v_n + dt [(1 - gamma) acc_n + gamma acc_{n+1}],
/// with a = alpha_m (`damp_factor_m`, Kratos default -0.3), beta = (1 - a)^2 / 4 unless
/// given (`newmark_beta`), gamma = 1/2 - a. Newmark's average acceleration is a = 0
/// (beta 1/4, gamma 1/2): no numerical dissipation. The local systems are
///   LHS = K + c0 M + c1 D,  c0 = (1 - a) / (beta dt^2),  c1 = gamma / (beta dt),
///   RHS = f_ext - f_int - M [(1 - a) acc + a acc_n] - D v,
/// with M and D from the entities (Rayleigh damping is the entities' damping matrix).
/// Velocities and accelerations of DISPLACEMENT / ROTATION DoFs follow the displacements.
class ResidualBasedBossakDisplacementScheme : public ImplicitDynamicScheme {
 public:
  explicit ResidualBasedBossakDisplacementScheme(double alpha_m = -0.3,
                                                 std::optional<double> newmark_beta = std::nullopt);
  /// Newmark's average acceleration (alpha_m 0, beta 1/4, gamma 1/2), `scheme_type: newmark`.
  static std::shared_ptr<ResidualBasedBossakDisplacementScheme> Newmark() {
    return std::make_shared<ResidualBasedBossakDisplacementScheme>(0.0, 0.25);
  }

  std::string Name() const override { return alpha_ == 0.0 ? "newmark" : "bossak"; }
  double Alpha() const noexcept { return alpha_; }
  double Beta() const noexcept { return beta_; }
  double Gamma() const noexcept { return gamma_; }

  /// Reads DELTA_TIME (InputError if not positive), computes the coefficients and stores
  /// BOSSAK_ALPHA, NEWMARK_BETA, NEWMARK_GAMMA in the ProcessInfo.
  void InitializeSolutionStep(ModelPart& model_part) override;
  /// Constant-acceleration guess for free DoFs; derivatives of fixed DoFs follow their values.
  void Predict(ModelPart& model_part, const DofsArray& dofs) override;
  void Update(ModelPart& model_part, const DofsArray& dofs, const Vector& dx) override;

 protected:
  int MinimumBufferSize() const override { return 2; }
  double MassFactor() const override { return c0_; }
  double DampingFactor() const override { return c1_; }
  /// (1 - alpha) acc + alpha acc_n.
  void InertialAcceleration(const Entity& entity, Vector& acceleration) const override;

 private:
  /// Velocity and acceleration of every DoF with time derivatives, from its current value.
  void UpdateDerivatives(const DofsArray& dofs) const;

  double alpha_;
  double beta_;
  double gamma_;
  double dt_ = 0.0;
  double c0_ = 0.0;  ///< d acc / d u, times (1 - alpha): the mass factor
  double c1_ = 0.0;  ///< d v / d u: the damping factor
};

}  // namespace mc
