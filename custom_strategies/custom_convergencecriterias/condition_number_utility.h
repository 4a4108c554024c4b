// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/linear_solvers/sparse_types.h"

namespace mc {

/// Estimate of the condition number |lambda|_max / |lambda|_min of a square sparse matrix:
/// power iteration for the eigenvalue of largest modulus, inverse power iteration (one sparse
/// LU factorisation, then solves) for the smallest. Exact for symmetric matrices with distinct
/// extreme eigenvalues; for the non-symmetric contact matrices it is the usual diagnostic (the
/// dominant eigenvalues are real in practice). Expensive: for `condn_convergence_criterion`
/// only. Returns +infinity for a singular matrix, 0 for an empty one.
struct ConditionNumberUtility {
  int max_iterations = 200;
  double tolerance = 1e-9;  ///< relative change of the eigenvalue estimate between iterations

  double Estimate(const SparseMatrix& A) const;
  double LargestEigenvalueModulus(const SparseMatrix& A) const;
  double SmallestEigenvalueModulus(const SparseMatrix& A) const;
};

}  // namespace mc
