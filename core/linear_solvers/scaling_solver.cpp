// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/scaling_solver.h"

#include <cassert>
#include <cmath>

namespace mc {

ScalingSolver::ScalingSolver(std::unique_ptr<LinearSolver> inner) : inner_(std::move(inner)) { assert(inner_); }

std::string ScalingSolver::Name() const { return Concat("scaling(", inner_->Name(), ")"); }

void ScalingSolver::Scale(const SparseMatrix& A) {
  scaled_ = A;
  scaled_.makeCompressed();
  scale_.setZero(A.cols());
  Vector column_max = Vector::Zero(A.cols());
  for (int j = 0; j < scaled_.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator it(scaled_, j); it; ++it) {
      column_max[j] = std::max(column_max[j], std::abs(it.value()));
      if (it.row() == j) scale_[j] = std::abs(it.value());
    }
  }
  for (int j = 0; j < scale_.size(); ++j) {
    const double d = scale_[j] > 0.0 ? scale_[j] : (column_max[j] > 0.0 ? column_max[j] : 1.0);
    scale_[j] = 1.0 / std::sqrt(d);
  }
  for (int j = 0; j < scaled_.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator it(scaled_, j); it; ++it) it.valueRef() *= scale_[it.row()] * scale_[j];
  }
}

void ScalingSolver::Initialize(const SparseMatrix& A) {
  Scale(A);
  inner_->Initialize(scaled_);
}

void ScalingSolver::Solve(const SparseMatrix& A, Vector& x, const Vector& b) {
  Scale(A);
  scaled_rhs_ = scale_.cwiseProduct(b);
  inner_->Solve(scaled_, scaled_solution_, scaled_rhs_);
  x = scale_.cwiseProduct(scaled_solution_);
}

void ScalingSolver::Clear() {
  inner_->Clear();
  scaled_.resize(0, 0);
}

}  // namespace mc
