// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/klu_solver.h"

#include <suitesparse/klu.h>

#include <cassert>

namespace mc {

struct KluSolver::Handles {
  klu_common common;
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
};

KluSolver::KluSolver() : handles_(std::make_unique<Handles>()) { klu_defaults(&handles_->common); }

KluSolver::~KluSolver() { Clear(); }

void KluSolver::Initialize(const SparseMatrix& A) {
  Clear();
  if (A.rows() != A.cols()) throw SolutionError(Concat("KLU: matrix is ", A.rows(), "x", A.cols(), ", not square"));
  SparseMatrix& M = const_cast<SparseMatrix&>(CompressedView(A, compressed_));  // KLU's API is not const-correct
  handles_->symbolic = klu_analyze(static_cast<int>(M.rows()), M.outerIndexPtr(), M.innerIndexPtr(), &handles_->common);
  if (handles_->symbolic == nullptr) {
    throw SolutionError(Concat("KLU analysis of a ", M.rows(), "-equation matrix failed (status ",
                               handles_->common.status, ")"));
  }
  pattern_.Assign(M);
  ++symbolic_count_;
}

void KluSolver::Solve(const SparseMatrix& A, Vector& x, const Vector& b) {
  assert(b.size() == A.rows());
  SparseMatrix& M = const_cast<SparseMatrix&>(CompressedView(A, compressed_));
  if (handles_->symbolic == nullptr || !pattern_.Matches(M)) Initialize(M);
  FreeNumeric();
  klu_common& common = handles_->common;
  handles_->numeric = klu_factor(M.outerIndexPtr(), M.innerIndexPtr(), M.valuePtr(), handles_->symbolic, &common);
  if (common.status == KLU_SINGULAR) {
    FreeNumeric();
    const long column = common.singular_col < M.cols() ? common.singular_col : -1;
    throw SingularMatrixError(Concat("KLU: singular matrix, zero pivot at equation ", column), column);
  }
  if (handles_->numeric == nullptr || common.status != KLU_OK) {
    FreeNumeric();
    throw SolutionError(Concat("KLU numeric factorization failed (status ", common.status, ")"));
  }
  x = b;
  if (klu_solve(handles_->symbolic, handles_->numeric, static_cast<int>(M.rows()), 1, x.data(), &common) != 1) {
    throw SolutionError(Concat("KLU solve failed (status ", common.status, ")"));
  }
}

void KluSolver::FreeNumeric() {
  if (handles_->numeric != nullptr) klu_free_numeric(&handles_->numeric, &handles_->common);
  handles_->numeric = nullptr;
}

void KluSolver::Clear() {
  FreeNumeric();
  if (handles_->symbolic != nullptr) klu_free_symbolic(&handles_->symbolic, &handles_->common);
  handles_->symbolic = nullptr;
  pattern_.Clear();
}

}  // namespace mc
