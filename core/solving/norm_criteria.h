// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "core/solving/convergence_criteria.h"

namespace mc {

/// What the displacement and residual criteria share: a norm over the free DoFs, measured as a
/// ratio to a reference norm and as an absolute value |x| / sqrt(n), each against its
/// tolerance; converged when either is at or below it.
class NormCriteria : public ConvergenceCriteria {
 public:
  std::vector<CriterionValue> LastValues() const override;
  double RelativeTolerance() const noexcept { return relative_tolerance_; }
  double AbsoluteTolerance() const noexcept { return absolute_tolerance_; }

 protected:
  /// `ratio_name` and `absolute_name` head the two values ("|du|/|u|", "|du|").
  NormCriteria(double relative_tolerance, double absolute_tolerance, std::string ratio_name, std::string absolute_name)
      : relative_tolerance_(relative_tolerance),
        absolute_tolerance_(absolute_tolerance),
        ratio_name_(std::move(ratio_name)),
        absolute_name_(std::move(absolute_name)) {}

  /// The decision for `norm` over `n` free DoFs: the ratio norm / reference is 1 when only the
  /// reference is zero, 0 when both are. Logs the values at echo level >= 1.
  bool Decide(const ModelPart& model_part, double norm, double reference, long n);

 private:
  double relative_tolerance_;
  double absolute_tolerance_;
  std::string ratio_name_;
  std::string absolute_name_;
  double ratio_ = 0.0;
  double absolute_ = 0.0;
};

}  // namespace mc
