// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/size_selecting_solver.h"

#include <cassert>

namespace mc {

SizeSelectingSolver::SizeSelectingSolver(std::string name, long max_small_size, std::unique_ptr<LinearSolver> small,
                                         std::unique_ptr<LinearSolver> large)
    : name_(std::move(name)), max_small_size_(max_small_size), small_(std::move(small)), large_(std::move(large)) {
  assert(small_ && large_);
}

void SizeSelectingSolver::Initialize(const SparseMatrix& A) {
  const bool use_large = A.rows() > max_small_size_;
  if (use_large != use_large_) ActiveSolver().Clear();
  use_large_ = use_large;
  rows_ = A.rows();
  ActiveSolver().Initialize(A);
}

void SizeSelectingSolver::Solve(const SparseMatrix& A, Vector& x, const Vector& b) {
  if (A.rows() != rows_) Initialize(A);
  ActiveSolver().Solve(A, x, b);
}

void SizeSelectingSolver::Clear() {
  small_->Clear();
  large_->Clear();
  rows_ = -1;
}

}  // namespace mc
