// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/direct_solver.h"

#include <cassert>

namespace mc {

void DirectSolver::Initialize(const SparseMatrix& A) {
  Clear();
  if (A.rows() != A.cols())
    throw SolutionError(Concat(library_, ": matrix is ", A.rows(), "x", A.cols(), ", not square"));
  const SparseMatrix& M = CompressedView(A, compressed_);
  Analyze(M);
  pattern_.Assign(M);
  ++symbolic_count_;
}

void DirectSolver::Solve(const SparseMatrix& A, Vector& x, const Vector& b) {
  assert(b.size() == A.rows());
  const SparseMatrix& M = CompressedView(A, compressed_);
  if (pattern_.Empty() || !pattern_.Matches(M)) Initialize(M);
  Factorize(M);
  Substitute(M, x, b);
}

void DirectSolver::Clear() {
  Release();
  pattern_.Clear();
}

}  // namespace mc
