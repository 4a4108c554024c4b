// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/residual_criteria.h"
#include "core/solving/parallel_utilities.h"

#include <cmath>

#include "core/model/model_part.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"

namespace mc {

void ResidualCriteria::InitializeSolutionStep(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                              const Vector& dx, const Vector& b) {
  initial_set_ = false;
}

bool ResidualCriteria::PostCriteria(ModelPart& model_part, const DofsArray& dofs, const SparseMatrix& A,
                                    const Vector& dx, const Vector& b) {
  double norm = 0.0;
  long n = 0;
  const long size = static_cast<long>(dofs.size());
#pragma omp parallel for reduction(+ : norm, n) if (size >= kMinParallelDofs)
  for (long i = 0; i < size; ++i) {
    const Dof& d = *dofs[i];
    if (d.fixed) continue;
    const double r = b[d.equation_id];
    norm += r * r;
    ++n;
  }
  norm = std::sqrt(norm);
  if (!initial_set_) {
    initial_norm_ = norm;
    initial_set_ = true;
  }
  ratio_ = initial_norm_ > 0.0 ? norm / initial_norm_ : (norm > 0.0 ? 1.0 : 0.0);
  absolute_ = n > 0 ? norm / std::sqrt(static_cast<double>(n)) : 0.0;
  const bool converged = ratio_ <= relative_tolerance_ || absolute_ <= absolute_tolerance_;
  if (echo_level_ >= 1)
    Logger::Info(FormatLine(model_part.GetProcessInfo().GetValue(NL_ITERATION_NUMBER), LastValues(), converged));
  return converged;
}

std::vector<CriterionValue> ResidualCriteria::LastValues() const {
  return {{"|r|/|r0|", ratio_, relative_tolerance_}, {"|r|", absolute_, absolute_tolerance_}};
}

}  // namespace mc
