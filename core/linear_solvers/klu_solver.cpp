// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/klu_solver.h"

#include <suitesparse/klu.h>

namespace mc {

struct KluSolver::Handles {
  klu_common common;
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
};

namespace {

// KLU's API is not const-correct: it takes int* and double* for arrays it only reads.
int* Pointers(const SparseMatrix& M) { return const_cast<int*>(M.outerIndexPtr()); }
int* Indices(const SparseMatrix& M) { return const_cast<int*>(M.innerIndexPtr()); }

}  // namespace

KluSolver::KluSolver() : DirectSolver("KLU"), handles_(std::make_unique<Handles>()) { klu_defaults(&handles_->common); }

KluSolver::~KluSolver() { Release(); }

void KluSolver::Analyze(const SparseMatrix& M) {
  handles_->symbolic = klu_analyze(static_cast<int>(M.rows()), Pointers(M), Indices(M), &handles_->common);
  if (handles_->symbolic == nullptr) {
    throw SolutionError(
        Concat("KLU analysis of a ", M.rows(), "-equation matrix failed (status ", handles_->common.status, ")"));
  }
}

void KluSolver::Factorize(const SparseMatrix& M) {
  FreeNumeric();
  klu_common& common = handles_->common;
  handles_->numeric =
      klu_factor(Pointers(M), Indices(M), const_cast<double*>(M.valuePtr()), handles_->symbolic, &common);
  if (common.status == KLU_SINGULAR) {
    FreeNumeric();
    const long column = common.singular_col < M.cols() ? common.singular_col : -1;
    throw SingularMatrixError(Concat("KLU: singular matrix, zero pivot at equation ", column), column);
  }
  if (handles_->numeric == nullptr || common.status != KLU_OK) {
    FreeNumeric();
    throw SolutionError(Concat("KLU numeric factorization failed (status ", common.status, ")"));
  }
}

void KluSolver::Substitute(Vector& x, const Vector& b) {
  klu_common& common = handles_->common;
  x = b;
  if (klu_solve(handles_->symbolic, handles_->numeric, static_cast<int>(b.size()), 1, x.data(), &common) != 1) {
    throw SolutionError(Concat("KLU solve failed (status ", common.status, ")"));
  }
}

void KluSolver::FreeNumeric() {
  if (handles_->numeric != nullptr) klu_free_numeric(&handles_->numeric, &handles_->common);
  handles_->numeric = nullptr;
}

void KluSolver::Release() {
  FreeNumeric();
  if (handles_->symbolic != nullptr) klu_free_symbolic(&handles_->symbolic, &handles_->common);
  handles_->symbolic = nullptr;
}

}  // namespace mc
