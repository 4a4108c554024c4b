// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/residual_criteria.h"
#include "core/model/parallel_utilities.h"

#include <cmath>

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
  double sums[] = {norm, static_cast<double>(n)};
  SumOverRanks(sums, 2);
  norm = std::sqrt(sums[0]);
  n = static_cast<long>(sums[1]);
  if (!initial_set_) {
    initial_norm_ = norm;
    initial_set_ = true;
  }
  return Decide(model_part, norm, initial_norm_, n);
}

}  // namespace mc
