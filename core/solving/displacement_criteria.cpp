// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/displacement_criteria.h"
#include "core/model/parallel_utilities.h"

#include <cmath>

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
  double sums[] = {increment, value, static_cast<double>(n)};
  SumOverRanks(sums, 3);
  return Decide(model_part, std::sqrt(sums[0]), std::sqrt(sums[1]), static_cast<long>(sums[2]));
}

}  // namespace mc
