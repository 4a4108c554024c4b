// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "core/linear_solvers/linear_solver.h"
#include "core/linear_solvers/sparse_pattern.h"

namespace mc {

/// Sparse LU by UMFPACK (unsymmetric multifrontal), the default direct solver. `Initialize`
/// runs the symbolic analysis (column ordering), which every later `Solve` on the same pattern
/// reuses; `Solve` factorizes the current values and solves (no iterative refinement).
class UmfpackSolver : public LinearSolver {
 public:
  UmfpackSolver() = default;
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;
  ~UmfpackSolver() override;

  std::string Name() const override { return "umfpack"; }
  bool IsDirect() const override { return true; }
  void Initialize(const SparseMatrix& A) override;
  /// Throws SingularMatrixError naming the column (unknown) of the first zero pivot, or of the
  /// smallest pivot when UMFPACK's reciprocal condition estimate is below
  /// kSingularReciprocalCondition for a matrix with a positive diagonal (a stiffness matrix
  /// singular up to round-off: a rigid-body mode).
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override;
  void Clear() override;

  /// Symbolic analyses run so far (tests check the reuse across value changes).
  int SymbolicAnalysesNumber() const noexcept { return symbolic_count_; }

 private:
  /// Below this, min|U_ii| / max|U_ii| of the row-scaled factorization is round-off: a rigid-body
  /// mode, not an ill-conditioned but meaningful system.
  static constexpr double kSingularReciprocalCondition = 1e-15;

  long SmallestPivotColumn() const;
  void FreeNumeric();

  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  SparsePattern pattern_;
  SparseMatrix compressed_;
  std::vector<long> outer_;  ///< column pointers and row indices widened for umfpack_dl_*
  std::vector<long> inner_;
  int symbolic_count_ = 0;
  double control_[20] = {};  ///< UMFPACK_CONTROL parameters, set by Initialize
};

}  // namespace mc
