// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/convergence_criteria.h"

namespace mc {

/// "displacement_criterion": over the free DoFs, converged when the relative increment
/// |du|/|u| (u after the update) or the absolute one |du|/sqrt(n) is below its tolerance.
class DisplacementCriteria : public ConvergenceCriteria {
 public:
  /// Kratos' defaults: `displacement_relative_tolerance` 1e-4, `..._absolute_tolerance` 1e-9.
  explicit DisplacementCriteria(double relative_tolerance = 1e-4, double absolute_tolerance = 1e-9)
      : relative_tolerance_(relative_tolerance), absolute_tolerance_(absolute_tolerance) {}

  std::string Name() const override { return "displacement_criterion"; }
  bool PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                    const Vector& b) override;
  std::vector<CriterionValue> LastValues() const override;
  double RelativeTolerance() const noexcept { return relative_tolerance_; }
  double AbsoluteTolerance() const noexcept { return absolute_tolerance_; }

 private:
  double relative_tolerance_;
  double absolute_tolerance_;
  double ratio_ = 0.0;
  double absolute_ = 0.0;
};

}  // namespace mc
