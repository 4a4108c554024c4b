// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/linear_solvers/linear_solver.h"
#include "core/linear_solvers/sparse_pattern.h"

namespace mc {

/// What the direct solvers (UMFPACK, KLU, CHOLMOD, Eigen SparseLU) share: the symbolic analysis
/// is run by `Initialize` and reused by every `Solve` on the same pattern; a `Solve` on another
/// pattern (or before any analysis) analyses again instead of factorizing with a stale analysis.
/// The library calls are the derived class's: Analyze, Factorize, Substitute, Release.
class DirectSolver : public LinearSolver {
 public:
  DirectSolver(const DirectSolver&) = delete;
  DirectSolver& operator=(const DirectSolver&) = delete;
  /// Derived destructors call Release themselves (it is virtual).
  ~DirectSolver() override = default;

  bool IsDirect() const final { return true; }
  /// Frees any earlier analysis; throws SolutionError for a non-square matrix.
  void Initialize(const SparseMatrix& A) final;
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) final;
  void Clear() final;

  /// Numeric factorization of `A` alone (analysing its pattern first when it is not the analysed
  /// one, from the ordering of the factors held when the solver keeps it); `SubstituteFactors` then solves with it,
  /// also after A has changed: the factors of an earlier matrix precondition a Krylov solve (FactorizationReuseSolver).
  void FactorizeNumeric(const SparseMatrix& A);
  /// Forward and back substitution with the factors of the last factorization.
  void SubstituteFactors(Vector& x, const Vector& b);
  /// Whether factors are held (a factorization succeeded since the last Initialize or Clear).
  bool HasFactors() const noexcept { return has_factors_; }
  /// Order of the factorized matrix (-1 without factors).
  long FactorsSize() const noexcept { return has_factors_ ? factors_size_ : -1; }
  /// Symbolic analyses run so far (tests check the reuse across value changes).
  int SymbolicAnalysesNumber() const noexcept { return symbolic_count_; }
  /// Numeric factorizations run so far.
  int NumericFactorizationsNumber() const noexcept { return numeric_count_; }
  /// Symbolic analyses that started from the ordering of the factors held.
  int KeptOrderingsNumber() const noexcept { return kept_orderings_; }
  WorkCounters Counters() const override {
    return {.factorizations = numeric_count_, .kept_orderings = kept_orderings_};
  }

  /// The DoF (node and variable) of each equation, so that a pattern of another order than the
  /// factors held (contact multipliers added or removed at a new step) is still analysed from
  /// their ordering, mapped equation by equation. Without it, only a pattern of the same order is.
  bool AdditionalPhysicalDataIsNeeded() const override { return true; }
  void ProvideAdditionalData(const SparseMatrix& A, const std::vector<Dof*>& dof_of_equation) override;

 protected:
  /// `library` names the solver in error messages ("UMFPACK").
  explicit DirectSolver(std::string library) : library_(std::move(library)) {}

  /// Symbolic phase: orderings and analysis of the pattern of `A` (compressed and square).
  virtual void Analyze(const SparseMatrix& A) = 0;
  /// Numeric phase for the values of `A`, analysed before. Throws SingularMatrixError naming the
  /// equation at fault, SolutionError for any other failure.
  virtual void Factorize(const SparseMatrix& A) = 0;
  /// Forward and back substitution with the last factorization (which needs only the factors).
  virtual void Substitute(Vector& x, const Vector& b) = 0;
  /// Frees the library's symbolic and numeric objects (no-op when there are none).
  virtual void Release() = 0;
  /// Called before the analysis of a new pattern when factors are held: a solver may keep their
  /// column ordering for that analysis (UMFPACK). `new_of_old` maps each equation of the factors
  /// to that of the new pattern (-1: gone); empty when the equations are the same. Not called
  /// after Clear.
  virtual void KeepOrderingForNextAnalysis(const std::vector<long>& new_of_old) {}
  /// Whether the last analysis used the ordering kept by KeepOrderingForNextAnalysis.
  virtual bool AnalysisKeptOrdering() const { return false; }

 private:
  /// The equations of the new pattern for those of the factors (see KeepOrderingForNextAnalysis);
  /// false when they cannot be related (no DoFs provided and another order).
  bool MapEquations(long rows, std::vector<long>& new_of_old) const;

  /// Node id and variable of an equation.
  using EquationKey = std::pair<long, const void*>;

  std::string library_;
  std::vector<EquationKey> equations_;           ///< of the last ProvideAdditionalData
  std::vector<EquationKey> factored_equations_;  ///< of the factors held
  SparsePattern pattern_;
  SparseMatrix compressed_;
  int symbolic_count_ = 0;
  int numeric_count_ = 0;
  int kept_orderings_ = 0;
  bool has_factors_ = false;
  long factors_size_ = -1;
};

}  // namespace mc
