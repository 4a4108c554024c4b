// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/direct_solver.h"

#include <cassert>

#include "core/linear_solvers/solve_clocks.h"

namespace mc {

void DirectSolver::Initialize(const SparseMatrix& A) {
  Clear();
  if (A.rows() != A.cols())
    throw SolutionError(Concat(library_, ": matrix is ", A.rows(), "x", A.cols(), ", not square"));
  SolveClocks::Scope clock(SolveClocks::Process().analysis);
  const SparseMatrix& M = CompressedView(A, compressed_);
  Analyze(M);
  pattern_.Assign(M);
  ++symbolic_count_;
}

void DirectSolver::Solve(const SparseMatrix& A, Vector& x, const Vector& b) {
  assert(b.size() == A.rows());
  FactorizeNumeric(A);
  SolveClocks::Scope clock(SolveClocks::Process().direct_substitution);
  Substitute(x, b);
}

void DirectSolver::FactorizeNumeric(const SparseMatrix& A) {
  SolveClocks& clocks = SolveClocks::Process();
  const SparseMatrix* M = nullptr;
  bool analysed = false;
  {
    SolveClocks::Scope clock(clocks.pattern_check);
    M = &CompressedView(A, compressed_);
    analysed = !pattern_.Empty() && pattern_.Matches(*M);
  }
  if (!analysed) {
    if (has_factors_ && factors_size_ == M->rows()) KeepOrderingForNextAnalysis();
    Initialize(*M);
  }
  has_factors_ = false;
  {
    SolveClocks::Scope clock(clocks.factorization);
    Factorize(*M);
  }
  has_factors_ = true;
  factors_size_ = M->rows();
  ++numeric_count_;
}

void DirectSolver::SubstituteFactors(Vector& x, const Vector& b) {
  if (!has_factors_) throw Error(Concat(library_, ": substitution requested without a factorization"));
  assert(b.size() == factors_size_);
  Substitute(x, b);
}

void DirectSolver::Clear() {
  Release();
  pattern_.Clear();
  has_factors_ = false;
}

}  // namespace mc
