// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "core/linear_solvers/linear_solver.h"

namespace mc {

/// Symmetric diagonal scaling around an inner solver: solves (S A S) y = S b, x = S y with
/// S = D^-1/2, d_i = |a_ii| (the largest |a_ji| of column i when the diagonal is zero, as for
/// multiplier rows; 1 for an empty column). Balances systems that mix stiffness and penalty or
/// multiplier scales ("scaling": true, or contact's `rescale_linear_solver`).
class ScalingSolver : public LinearSolver {
 public:
  explicit ScalingSolver(std::unique_ptr<LinearSolver> inner);

  /// "scaling(<inner name>)".
  std::string Name() const override;
  bool IsDirect() const override { return inner_->IsDirect(); }
  void Initialize(const SparseMatrix& A) override;
  /// The inner solver's errors propagate unchanged (equation indices are not permuted).
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override;
  void Clear() override;
  int IterationsNumber() const override { return inner_->IterationsNumber(); }
  void SetForcingTerm(double eta) override { inner_->SetForcingTerm(eta); }
  double LastTolerance() const override { return inner_->LastTolerance(); }
  WorkCounters Counters() const override { return inner_->Counters(); }

  const LinearSolver& Inner() const noexcept { return *inner_; }
  /// The factors S of the last Solve.
  const Vector& ScaleFactors() const noexcept { return scale_; }

 private:
  void Scale(const SparseMatrix& A);

  std::unique_ptr<LinearSolver> inner_;
  Vector scale_;
  SparseMatrix scaled_;
  Vector scaled_rhs_;
  Vector scaled_solution_;
};

}  // namespace mc
