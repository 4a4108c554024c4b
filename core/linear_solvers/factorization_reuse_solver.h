// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/linear_solvers/direct_solver.h"
#include "core/linear_solvers/linear_solver.h"

namespace mc {

/// A direct solver that factorizes less: a factorization is kept across solves (Newton iterations
/// and load steps) and preconditions GMRES on the later matrices, refactorizing only when the
/// Krylov iterations say that the factors have drifted too far from the matrix.
///
/// Why it pays: with linear elements the bulk stiffness is constant and contact changes only the
/// rows and columns of the interface, so the preconditioned operator F^-1 A is the identity plus
/// a perturbation of low rank or small size, and GMRES converges in a few iterations, each one
/// substitution with the kept factors (a small fraction of a factorization).
///
/// Each Solve:
///  - no factors or factors of another size: factorize A and substitute (the direct solve);
///  - the kept factors have used up their budget, or more rows changed since the factorized
///    matrix (changed_row_fraction) than the budget has left: the direct solve;
///  - else GMRES, left-preconditioned by the factors, from x = 0. It stops when the
///    preconditioned residual |F^-1 (b - A x)|, which estimates the error of x since F ~ A, is
///    below `tolerance` times |F^-1 b| (~ |x|): the answer is the direct one to that relative
///    accuracy;
///  - a Krylov solve that stalls (its convergence rate cannot meet the tolerance within the
///    budget left), breaks down or runs out of it falls back to a fresh factorization of A, and
///    the direct solve answers.
/// The budget compares measured costs: the factors are kept while the substitutions GMRES has
/// made with them (beyond the one a direct solve makes), at the measured time of a substitution,
/// have cost less than their factorization took (so at most twice the work of the better choice
/// in hindsight). Thread CPU times, so a loaded machine does not skew them.
/// Singular matrices are reported by the factorization as before (SingularMatrixError).
class FactorizationReuseSolver : public LinearSolver {
 public:
  struct Options {
    /// Relative size of the preconditioned residual that ends the Krylov solve.
    double tolerance = 1.0e-14;
    /// Bounds of the budget in substitutions per factorization (the measured cost ratio): at
    /// least a few tries, at most a GMRES basis of max_iterations vectors.
    int min_iterations = 4;
    int max_iterations = 60;
    /// A row of A whose change since the factorized matrix exceeds this fraction of its norm
    /// counts as changed. GMRES needs about one iteration per changed row (a rank-one change
    /// each; measured on the Hertz systems: 2 to 67 changed rows, 2 to 55 iterations), so when
    /// they are at least the budget left the solve refactorizes without trying.
    double changed_row_fraction = 0.1;
  };

  FactorizationReuseSolver(std::unique_ptr<DirectSolver> direct, const Options& options);
  explicit FactorizationReuseSolver(std::unique_ptr<DirectSolver> direct)
      : FactorizationReuseSolver(std::move(direct), Options()) {}

  /// The direct solver's name ("umfpack").
  std::string Name() const override { return direct_->Name(); }
  bool IsDirect() const override { return true; }
  /// Records the pattern; the kept factors stay valid as a preconditioner of the new pattern.
  void Initialize(const SparseMatrix& A) override;
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override;
  /// The direct solver's: the DoFs of the equations relate a new pattern to the kept ordering.
  bool AdditionalPhysicalDataIsNeeded() const override { return direct_->AdditionalPhysicalDataIsNeeded(); }
  void ProvideAdditionalData(const SparseMatrix& A, const std::vector<Dof*>& dof_of_equation) override {
    direct_->ProvideAdditionalData(A, dof_of_equation);
  }
  /// Frees the factors and the Krylov basis.
  void Clear() override;
  /// GMRES iterations of the last solve (1 for a direct solve).
  int IterationsNumber() const override { return last_iterations_; }

  WorkCounters Counters() const override;
  const DirectSolver& Direct() const noexcept { return *direct_; }
  /// Substitutions a factorization is worth: its measured time over that of a substitution,
  /// within [min_iterations, max_iterations].
  int Budget() const;
  /// What is left of the budget of the kept factors: the iterations the next Krylov solve may take.
  int BudgetLeft() const { return Budget() - spent_substitutions_; }
  /// CPU seconds of the last numeric factorization, and of a substitution with its factors (mean).
  double FactorizationSeconds() const noexcept { return factorization_seconds_; }
  double SubstitutionSeconds() const noexcept;
  const Options& GetOptions() const noexcept { return options_; }
  /// Numeric factorizations so far.
  int FactorizationsNumber() const noexcept { return direct_->NumericFactorizationsNumber(); }
  /// Solves answered by GMRES with kept factors, and their iterations in total (those of solves
  /// that fell back included).
  int KrylovSolvesNumber() const noexcept { return krylov_solves_; }
  long KrylovIterationsNumber() const noexcept { return krylov_iterations_; }
  /// Krylov solves that did not converge and fell back to a fresh factorization.
  int FallbacksNumber() const noexcept { return fallbacks_; }
  /// Whether the last solve was a GMRES one that converged.
  bool LastSolveReusedFactors() const noexcept { return last_reused_; }

 private:
  /// Rows of A that changed by more than changed_row_fraction of their norm since the
  /// factorized matrix (the estimate of the Krylov iterations needed).
  long ChangedRows(const SparseMatrix& A);
  /// Left-preconditioned GMRES (no restart) within `budget` iterations; false when it did not
  /// meet the tolerance (x is then undefined).
  bool SolveWithKrylov(const SparseMatrix& A, Vector& x, const Vector& b, int budget);
  void SolveDirect(const SparseMatrix& A, Vector& x, const Vector& b);

  /// Substitutes with the kept factors, timed.
  void Substitute(Vector& x, const Vector& b, double& clock);

  std::unique_ptr<DirectSolver> direct_;
  Options options_;
  double factorization_seconds_ = 0.0;
  double substitution_seconds_ = 0.0;  ///< all substitutions with the kept factors
  int substitutions_ = 0;
  int spent_substitutions_ = 0;  ///< by GMRES with the kept factors
  int last_iterations_ = 0;
  bool last_reused_ = false;
  int krylov_solves_ = 0;
  long krylov_iterations_ = 0;
  int fallbacks_ = 0;

  SparseMatrix factorized_;  ///< the matrix of the kept factors
  Vector factorized_row_norms_;
  Vector changed_row_norms_;  ///< squared norms of the rows of A - F

  // GMRES work space, kept between solves (no allocation once the basis has grown).
  std::vector<Vector> basis_;
  Eigen::MatrixXd hessenberg_;
  Vector cosines_, sines_, rotated_rhs_, work_;
};

}  // namespace mc
