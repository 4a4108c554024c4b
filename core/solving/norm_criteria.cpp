// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/norm_criteria.h"

#include <cmath>

#include "core/model/model_part.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"

namespace mc {

bool NormCriteria::Decide(const ModelPart& model_part, double norm, double reference, long n) {
  ratio_ = reference > 0.0 ? norm / reference : (norm > 0.0 ? 1.0 : 0.0);
  absolute_ = n > 0 ? norm / std::sqrt(static_cast<double>(n)) : 0.0;
  const bool converged = ratio_ <= relative_tolerance_ || absolute_ <= absolute_tolerance_;
  if (echo_level_ >= 1)
    Logger::Info(FormatLine(model_part.GetProcessInfo().GetValue(NL_ITERATION_NUMBER), LastValues(), converged));
  return converged;
}

std::vector<CriterionValue> NormCriteria::LastValues() const {
  return {{ratio_name_, ratio_, relative_tolerance_}, {absolute_name_, absolute_, absolute_tolerance_}};
}

}  // namespace mc
