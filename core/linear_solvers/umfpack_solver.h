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
/// A new pattern (the contact pairs changed at a new step) is analysed from the column ordering
/// of the factors held, its equations mapped to the new ones by their DoFs when the order changed
/// (contact multipliers added or removed; a new equation is placed right after the last of its
/// neighbours in that ordering), with the strategy (symmetric or not)
/// of the analysis that ordered them, instead of a fresh METIS / AMD ordering: the patterns differ
/// only at the interface, so the ordering stays about as good (hertz2d_30k, steps 2-4: factor
/// flops +11 % to -12 % of a fresh ordering's) while the analysis takes a fifth of the time (the
/// ordering was most of it). Once the factors of a kept ordering cost kMaxFlopsGrowth times
/// those of the last fresh one, the next analysis orders afresh. After Clear (a restart point)
/// the ordering is computed afresh too.
///
/// A singular matrix raises SingularMatrixError naming the column (unknown) of the first zero
/// pivot, or of the smallest pivot when UMFPACK's reciprocal condition estimate is below
/// kSingularReciprocalCondition for a matrix with a positive diagonal (a stiffness matrix
/// singular up to round-off: a rigid-body mode).
class UmfpackSolver : public DirectSolver {
 public:
  /// Installs SuiteSparseMemory (the factors' memory reused from one factorization to the next).
  UmfpackSolver();
  ~UmfpackSolver() override { Release(); }

  std::string Name() const override { return "umfpack"; }
  /// Whether the last symbolic analysis started from the ordering of the previous factors.
  bool LastAnalysisKeptOrdering() const noexcept { return ordering_kept_; }

 private:
  /// Below this, min|U_ii| / max|U_ii| of the row-scaled factorization is round-off: a rigid-body
  /// mode, not an ill-conditioned but meaningful system.
  static constexpr double kSingularReciprocalCondition = 1e-15;
  /// Factor flops against those of the last fresh ordering beyond which an ordering is not kept.
  static constexpr double kMaxFlopsGrowth = 1.25;

  void Analyze(const SparseMatrix& A) override;
  void Factorize(const SparseMatrix& A) override;
  void Substitute(Vector& x, const Vector& b) override;
  void Release() override;
  void KeepOrderingForNextAnalysis(const std::vector<long>& new_of_old) override;
  bool AnalysisKeptOrdering() const override { return ordering_kept_; }
  long SmallestPivotColumn() const;
  void FreeNumeric();

  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  std::vector<long> outer_;  ///< column pointers and row indices widened for umfpack_dl_*
  std::vector<long> inner_;
  /// Column ordering for the next analysis (empty: compute one); without the new equations when
  /// the order changed, which the analysis places.
  std::vector<long> kept_ordering_;
  double kept_strategy_ = 0.0;  ///< UMFPACK_STRATEGY of the analysis that ordered the factors
  double strategy_used_ = 0.0;  ///< UMFPACK_STRATEGY_USED of the last analysis
  bool ordering_kept_ = false;
  double fresh_flops_ = 0.0;  ///< flops of the last factorization with a fresh ordering
  double last_flops_ = 0.0;   ///< flops of the last factorization
  double control_[20] = {};   ///< UMFPACK_CONTROL parameters, set by Initialize
};

}  // namespace mc
