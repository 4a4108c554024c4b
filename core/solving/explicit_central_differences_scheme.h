// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/scheme.h"

namespace mc {

/// Explicit central differences with a lumped mass (half-step velocities): at each step
///   acc_n = (f_ext - f_int)(u_n) / m - alpha v_{n-1/2},
///   v_{n+1/2} = v_{n-1/2} + (dt_{n-1/2} + dt_{n+1/2}) / 2 acc_n   (first step: v_{1/2} = v_0 + dt/2 acc_0),
///   u_{n+1} = u_n + dt v_{n+1/2}.
/// VELOCITY holds the half-step velocity v_{n+1/2}, ACCELERATION acc_n. The mass-proportional
/// Rayleigh coefficient alpha is lagged by half a step; stiffness-proportional damping (beta)
/// is not implemented. Stable for dt below 2 / omega_max.
class ExplicitCentralDifferencesScheme : public Scheme {
 public:
  /// Throws NotImplementedError for a non-zero `rayleigh_beta`.
  explicit ExplicitCentralDifferencesScheme(double rayleigh_alpha = 0.0, double rayleigh_beta = 0.0);

  std::string Name() const override { return "central_differences"; }
  /// Sets COMPUTE_LUMPED_MASS_MATRIX in the ProcessInfo, then initializes the entities.
  void Initialize(ModelPart& model_part) override;
  void Check(const ModelPart& model_part) const override;

  /// One time step of the free DoFs from the residual (f_ext - f_int at u_n, by equation id)
  /// and the lumped mass of each DoF.
  void Advance(ModelPart& model_part, const DofsArray& dofs, const Vector& residual, const Vector& mass);
  /// The next step starts from a full-step velocity again (after a restart or reset).
  void Restart() noexcept { started_ = false; }

 private:
  double rayleigh_alpha_;
  bool started_ = false;
  double previous_dt_ = 0.0;  ///< dt_{n-1/2}, the step that produced v_{n-1/2}
};

}  // namespace mc
