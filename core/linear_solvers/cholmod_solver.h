// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "core/linear_solvers/linear_solver.h"
#include "core/linear_solvers/sparse_pattern.h"

namespace mc {

/// Supernodal sparse Cholesky by CHOLMOD, for symmetric positive definite systems (structural
/// problems without multipliers). Only the upper triangle of A is read, so `Solve` first checks
/// that A is symmetric. `Initialize` orders and analyses the pattern once; `Solve` factorizes.
///
/// Failures: a non-symmetric matrix raises SolutionError; a matrix that is not positive definite
/// raises SingularMatrixError naming the original equation of the column where the
/// factorization stopped (its diagonal was zero or negative).
class CholmodSolver : public LinearSolver {
 public:
  CholmodSolver();
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;
  ~CholmodSolver() override;

  std::string Name() const override { return "cholmod"; }
  bool IsDirect() const override { return true; }
  void Initialize(const SparseMatrix& A) override;
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override;
  void Clear() override;

  int SymbolicAnalysesNumber() const noexcept { return symbolic_count_; }

 private:
  struct Handles;  // CHOLMOD's common block and factor (keeps cholmod.h private)
  std::unique_ptr<Handles> handles_;
  SparsePattern pattern_;
  SparseMatrix compressed_;
  int symbolic_count_ = 0;
};

}  // namespace mc
