// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "core/linear_solvers/direct_solver.h"

namespace mc {

/// Sparse LU by KLU (block triangular form + left-looking LU), suited to circuit-like and
/// small systems. The symbolic analysis is the BTF and fill-reducing orderings; `Solve`
/// factorizes afresh with partial pivoting. A singular matrix raises SingularMatrixError naming
/// the original column of the first zero pivot.
class KluSolver : public DirectSolver {
 public:
  KluSolver();
  ~KluSolver() override;

  std::string Name() const override { return "klu"; }

 private:
  void Analyze(const SparseMatrix& A) override;
  void Factorize(const SparseMatrix& A) override;
  void Substitute(Vector& x, const Vector& b) override;
  void Release() override;
  void FreeNumeric();

  struct Handles;  // KLU's common block, symbolic and numeric objects (keeps klu.h private)
  std::unique_ptr<Handles> handles_;
};

}  // namespace mc
