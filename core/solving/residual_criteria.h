// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/norm_criteria.h"

namespace mc {

/// "residual_criterion": over the free DoFs, converged when |r|/|r0| or |r|/sqrt(n) is below
/// its tolerance; r0 is the residual of the first iteration of the step (the out-of-balance
/// force the step starts from). `r` is the residual the strategy passes: by default the one
/// assembled at the start of the iteration, so a linear problem converges at iteration 2.
class ResidualCriteria : public NormCriteria {
 public:
  /// Kratos' defaults: `residual_relative_tolerance` 1e-4, `residual_absolute_tolerance` 1e-9.
  explicit ResidualCriteria(double relative_tolerance = 1e-4, double absolute_tolerance = 1e-9)
      : NormCriteria(relative_tolerance, absolute_tolerance, "|r|/|r0|", "|r|") {}

  std::string Name() const override { return "residual_criterion"; }
  void InitializeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                              const Vector& b) override;
  bool PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                    const Vector& b) override;
  double InitialResidualNorm() const noexcept { return initial_norm_; }

 private:
  bool initial_set_ = false;
  double initial_norm_ = 0.0;
};

}  // namespace mc
