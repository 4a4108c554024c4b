// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/fallback_solver.h"

#include <cassert>

namespace mc {

FallbackSolver::FallbackSolver(std::unique_ptr<LinearSolver> primary, std::unique_ptr<LinearSolver> fallback)
    : primary_(std::move(primary)), fallback_(std::move(fallback)) {
  assert(primary_ && fallback_);
}

void FallbackSolver::Initialize(const SparseMatrix& A) { Active().Initialize(A); }

void FallbackSolver::Solve(const SparseMatrix& A, Vector& x, const Vector& b) {
  if (switched_) {
    fallback_->Solve(A, x, b);
    return;
  }
  try {
    primary_->Solve(A, x, b);
  } catch (const SolutionError& error) {
    switched_ = true;
    reason_ = error.what();
    primary_->Clear();
    fallback_->Initialize(A);
    fallback_->Solve(A, x, b);
  }
}

void FallbackSolver::Clear() {
  primary_->Clear();
  fallback_->Clear();
}

}  // namespace mc
