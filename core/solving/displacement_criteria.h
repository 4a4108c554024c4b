// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/norm_criteria.h"

namespace mc {

/// "displacement_criterion": over the free DoFs, converged when the relative increment
/// |du|/|u| (u after the update) or the absolute one |du|/sqrt(n) is below its tolerance.
class DisplacementCriteria : public NormCriteria {
 public:
  /// Kratos' defaults: `displacement_relative_tolerance` 1e-4, `..._absolute_tolerance` 1e-9.
  explicit DisplacementCriteria(double relative_tolerance = 1e-4, double absolute_tolerance = 1e-9)
      : NormCriteria(relative_tolerance, absolute_tolerance, "|du|/|u|", "|du|") {}

  std::string Name() const override { return "displacement_criterion"; }
  bool PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A, const Vector& dx,
                    const Vector& b) override;
};

}  // namespace mc
