// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/scheme.h"

namespace mc {

/// The static scheme: the local systems are the entities' own (tangent and residual) and an
/// iteration adds the increment to the free DoFs, u <- u + dx.
///
/// The predictor keeps the values of the previous step (prescribed DoFs carry what the
/// processes imposed), as Kratos does; with `extrapolate` the free DoFs start the step from the
/// linear extrapolation of the last two converged steps,
///   u_{n+1}^0 = u_n + (dt_{n+1} / dt_n) (u_n - u_{n-1}),
/// read from buffer positions 1 and 2 (so the buffer must hold 3 steps) with dt_n =
/// ProcessInfo[PREVIOUS_DELTA_TIME]. On a smooth load path this is the converged answer up to
/// the curvature of the path, which saves Newton iterations (issue 14; not a Kratos option).
/// Every free DoF is extrapolated, the contact multipliers too: keeping them at the last step's
/// values while the displacements move on took more iterations on the measured cases
/// (benchmarks/hertz/results_predictor.md). The contact strategy skips this predictor after a
/// step in which the contact state changed (Extrapolates()). After a split step dt_n is the full step while
/// u_n - u_{n-1} is the last sub-step's increment: the next step extrapolates too little, which
/// costs iterations, not accuracy.
class ResidualBasedIncrementalUpdateStaticScheme : public Scheme {
 public:
  explicit ResidualBasedIncrementalUpdateStaticScheme(bool extrapolate = false) : extrapolate_(extrapolate) {}

  std::string Name() const override { return "static"; }
  bool PassesEntityLeftHandSide() const override { return true; }
  bool Extrapolates() const override { return extrapolate_; }
  void Predict(ModelPart& model_part, const DofsArray& dofs) override;
  /// With `extrapolate`, also an InputError unless the buffer holds 3 steps.
  void Check(const ModelPart& model_part) const override;

 private:
  bool extrapolate_;
};

}  // namespace mc
