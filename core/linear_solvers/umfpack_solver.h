// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "core/linear_solvers/direct_solver.h"

namespace mc {

/// Sparse LU by UMFPACK (unsymmetric multifrontal), the default direct solver. The symbolic
/// analysis is the column ordering; `Solve` factorizes the current values and solves (no
/// iterative refinement).
///
/// A singular matrix raises SingularMatrixError naming the column (unknown) of the first zero
/// pivot, or of the smallest pivot when UMFPACK's reciprocal condition estimate is below
/// kSingularReciprocalCondition for a matrix with a positive diagonal (a stiffness matrix
/// singular up to round-off: a rigid-body mode).
class UmfpackSolver : public DirectSolver {
 public:
  UmfpackSolver() : DirectSolver("UMFPACK") {}
  ~UmfpackSolver() override { Release(); }

  std::string Name() const override { return "umfpack"; }
  /// From the flops of the factorization per entry of L and U (see the .cpp for the fit).
  double FactorizationCostInSubstitutions() const override;

 private:
  /// Below this, min|U_ii| / max|U_ii| of the row-scaled factorization is round-off: a rigid-body
  /// mode, not an ill-conditioned but meaningful system.
  static constexpr double kSingularReciprocalCondition = 1e-15;

  void Analyze(const SparseMatrix& A) override;
  void Factorize(const SparseMatrix& A) override;
  void Substitute(Vector& x, const Vector& b) override;
  void Release() override;
  long SmallestPivotColumn() const;
  void FreeNumeric();

  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  std::vector<long> outer_;  ///< column pointers and row indices widened for umfpack_dl_*
  std::vector<long> inner_;
  double control_[20] = {};              ///< UMFPACK_CONTROL parameters, set by Initialize
  double flops_per_factor_entry_ = 0.0;  ///< of the last numeric factorization
};

}  // namespace mc
