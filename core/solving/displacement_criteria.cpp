// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/displacement_criteria.h"
#include "core/solving/parallel_utilities.h"

#include <cmath>

#include "core/model/model_part.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"

namespace mc {

bool DisplacementCriteria::PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                        const Vector& dx, const Vector& b) {
  double increment = 0.0;
  double value = 0.0;
  long n = 0;
  const long size = static_cast<long>(dofs.size());
#pragma omp parallel for reduction(+ : increment, value, n) if (size >= kMinParallelDofs)
  for (long i = 0; i < size; ++i) {
    const Dof& d = *dofs[i];
    if (d.fixed) continue;
    const double du = dx[d.equation_id];
    const double u = d.Value();
    increment += du * du;
    value += u * u;
    ++n;
  }
  increment = std::sqrt(increment);
  value = std::sqrt(value);
  ratio_ = value > 0.0 ? increment / value : (increment > 0.0 ? 1.0 : 0.0);
  absolute_ = n > 0 ? increment / std::sqrt(static_cast<double>(n)) : 0.0;
  const bool converged = ratio_ <= relative_tolerance_ || absolute_ <= absolute_tolerance_;
  if (echo_level_ >= 1)
    Logger::Info(FormatLine(model_part.GetProcessInfo().GetValue(NL_ITERATION_NUMBER), LastValues(), converged));
  return converged;
}

std::vector<CriterionValue> DisplacementCriteria::LastValues() const {
  return {{"|du|/|u|", ratio_, relative_tolerance_}, {"|du|", absolute_, absolute_tolerance_}};
}

}  // namespace mc
