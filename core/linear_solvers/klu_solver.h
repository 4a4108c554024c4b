// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "core/linear_solvers/linear_solver.h"
#include "core/linear_solvers/sparse_pattern.h"

namespace mc {

/// Sparse LU by KLU (block triangular form + left-looking LU), suited to circuit-like and
/// small systems. `Initialize` computes the BTF and fill-reducing orderings, reused by every
/// `Solve` on the same pattern; `Solve` factorizes afresh with partial pivoting.
class KluSolver : public LinearSolver {
 public:
  KluSolver();
  KluSolver(const KluSolver&) = delete;
  KluSolver& operator=(const KluSolver&) = delete;
  ~KluSolver() override;

  std::string Name() const override { return "klu"; }
  bool IsDirect() const override { return true; }
  void Initialize(const SparseMatrix& A) override;
  /// Throws SingularMatrixError naming the original column of the first zero pivot.
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override;
  void Clear() override;

  int SymbolicAnalysesNumber() const noexcept { return symbolic_count_; }

 private:
  void FreeNumeric();

  struct Handles;  // KLU's common block, symbolic and numeric objects (keeps klu.h private)
  std::unique_ptr<Handles> handles_;
  SparsePattern pattern_;
  SparseMatrix compressed_;
  int symbolic_count_ = 0;
};

}  // namespace mc
