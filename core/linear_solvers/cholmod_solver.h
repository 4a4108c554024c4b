// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "core/linear_solvers/direct_solver.h"

namespace mc {

/// Supernodal sparse Cholesky by CHOLMOD, for symmetric positive definite systems (structural
/// problems without multipliers). Only the upper triangle of A is read, so `Solve` first checks
/// that A is symmetric. The symbolic analysis is the ordering and the supernodal structure.
///
/// Failures: a non-symmetric matrix raises SolutionError; a matrix that is not positive definite
/// raises SingularMatrixError naming the original equation of the column where the
/// factorization stopped (its diagonal was zero or negative).
class CholmodSolver : public DirectSolver {
 public:
  CholmodSolver();
  ~CholmodSolver() override;

  std::string Name() const override { return "cholmod"; }

 private:
  void Analyze(const SparseMatrix& A) override;
  void Factorize(const SparseMatrix& A) override;
  void Substitute(Vector& x, const Vector& b) override;
  void Release() override;

  struct Handles;  // CHOLMOD's common block and factor (keeps cholmod.h private)
  std::unique_ptr<Handles> handles_;
};

}  // namespace mc
