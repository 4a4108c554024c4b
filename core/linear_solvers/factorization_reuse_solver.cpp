// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/factorization_reuse_solver.h"

#include <algorithm>
#include <cmath>

#include "core/linear_solvers/solve_clocks.h"

namespace mc {

namespace {

/// Relative true residual |b - A x| / |b| above which a converged Krylov solve is not trusted. On
/// the Hertz contact systems the solves that meet the tolerance leave at most 2e-8.
constexpr double kMaxTrueResidual = 1e-6;

}  // namespace

FactorizationReuseSolver::FactorizationReuseSolver(std::unique_ptr<DirectSolver> direct, const Options& options)
    : direct_(std::move(direct)), options_(options) {
  if (!direct_) throw Error("FactorizationReuseSolver: no direct solver given");
  if (!(options_.tolerance > 0.0) || options_.min_iterations < 1 || options_.max_iterations < options_.min_iterations ||
      !(options_.changed_row_fraction > 0.0))
    throw Error(Concat("FactorizationReuseSolver: invalid options (tolerance ", options_.tolerance, ", iterations ",
                       options_.min_iterations, " to ", options_.max_iterations, ", changed_row_fraction ",
                       options_.changed_row_fraction, ")"));
}

void FactorizationReuseSolver::Initialize(const SparseMatrix& A) {
  if (A.rows() != A.cols())
    throw SolutionError(Concat(direct_->Name(), ": matrix is ", A.rows(), "x", A.cols(), ", not square"));
}

void FactorizationReuseSolver::Solve(const SparseMatrix& A, Vector& x, const Vector& b) {
  last_reused_ = false;
  const int budget = BudgetLeft();
  if (!direct_->HasFactors() || direct_->FactorsSize() != A.rows() || budget < 1) {
    SolveDirect(A, x, b);
    return;
  }
  long changed = 0;
  {
    SolveClocks::Scope clock(SolveClocks::Process().comparison);
    changed = ChangedRows(A);
  }
  if (changed >= budget) {
    SolveDirect(A, x, b);
    return;
  }
  SolveClocks& clocks = SolveClocks::Process();
  const double substitutions_before = clocks.krylov_substitution;
  double krylov = 0.0;
  bool converged = false;
  {
    SolveClocks::Scope clock(krylov);
    converged = SolveWithKrylov(A, x, b, budget);
  }
  clocks.krylov_other += krylov - (clocks.krylov_substitution - substitutions_before);
  krylov_iterations_ += last_iterations_;
  spent_substitutions_ += last_iterations_;
  if (converged) {
    ++krylov_solves_;
    last_reused_ = true;
    return;
  }
  ++fallbacks_;
  SolveDirect(A, x, b);
}

void FactorizationReuseSolver::Clear() {
  direct_->Clear();
  basis_.clear();
  basis_.shrink_to_fit();
  factorized_ = SparseMatrix();
}

LinearSolver::WorkCounters FactorizationReuseSolver::Counters() const {
  return {.factorizations = direct_->NumericFactorizationsNumber(),
          .krylov_solves = krylov_solves_,
          .krylov_iterations = krylov_iterations_,
          .fallbacks = fallbacks_,
          .kept_orderings = direct_->KeptOrderingsNumber()};
}

double FactorizationReuseSolver::SubstitutionSeconds() const noexcept {
  return substitutions_ > 0 ? substitution_seconds_ / substitutions_ : 0.0;
}

int FactorizationReuseSolver::Budget() const {
  const double ratio = factorization_seconds_ / SubstitutionSeconds();
  return std::clamp(std::isfinite(ratio) ? static_cast<int>(ratio) : 0, options_.min_iterations,
                    options_.max_iterations);
}

void FactorizationReuseSolver::Substitute(Vector& x, const Vector& b, double& clock) {
  const double before = clock;
  {
    SolveClocks::Scope scope(clock);
    direct_->SubstituteFactors(x, b);
  }
  substitution_seconds_ += clock - before;
  ++substitutions_;
}

namespace {

// Euclidean norm of each row of a column-major matrix, into `norms` (resized).
void RowNorms(const SparseMatrix& M, Vector& norms) {
  norms.setZero(M.rows());
  for (Eigen::Index j = 0; j < M.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(M, j); it; ++it) norms[it.row()] += it.value() * it.value();
  norms = norms.cwiseSqrt();
}

}  // namespace

// Row norms of A - F by merging the two columns (row indices sorted in both), without forming
// the difference: a pattern that changed is fine.
long FactorizationReuseSolver::ChangedRows(const SparseMatrix& A) {
  changed_row_norms_.setZero(A.rows());
  for (Eigen::Index j = 0; j < A.outerSize(); ++j) {
    SparseMatrix::InnerIterator a(A, j), f(factorized_, j);
    while (a || f) {
      double difference;
      Eigen::Index row;
      if (a && (!f || a.row() < f.row())) {
        row = a.row(), difference = a.value();
        ++a;
      } else if (!a || f.row() < a.row()) {
        row = f.row(), difference = -f.value();
        ++f;
      } else {
        row = a.row(), difference = a.value() - f.value();
        ++a, ++f;
      }
      changed_row_norms_[row] += difference * difference;
    }
  }
  const double fraction2 = options_.changed_row_fraction * options_.changed_row_fraction;
  return (changed_row_norms_.array() > fraction2 * factorized_row_norms_.array().square()).count();
}

void FactorizationReuseSolver::SolveDirect(const SparseMatrix& A, Vector& x, const Vector& b) {
  // The numeric factorization only: a symbolic analysis comes with a new pattern, whatever the rule.
  SolveClocks& clocks = SolveClocks::Process();
  const double before = clocks.factorization;
  direct_->FactorizeNumeric(A);
  factorization_seconds_ = clocks.factorization - before;
  substitution_seconds_ = 0.0;
  substitutions_ = 0;
  spent_substitutions_ = 0;
  Substitute(x, b, clocks.direct_substitution);
  SolveClocks::Scope clock(clocks.comparison);
  factorized_ = A;
  RowNorms(factorized_, factorized_row_norms_);
  last_iterations_ = 1;
}

// GMRES on F^-1 A x = F^-1 b (Saad, Iterative Methods for Sparse Linear Systems, alg. 6.9, with
// Givens rotations), Arnoldi by modified Gram-Schmidt applied twice: the basis stays orthogonal
// to round-off, so the recurrence residual is the true preconditioned residual.
bool FactorizationReuseSolver::SolveWithKrylov(const SparseMatrix& A, Vector& x, const Vector& b, int budget) {
  const Eigen::Index n = b.size();
  last_iterations_ = 0;
  if (basis_.size() < static_cast<std::size_t>(budget) + 1) basis_.resize(static_cast<std::size_t>(budget) + 1);
  hessenberg_.setZero(budget + 1, budget);
  cosines_.setZero(budget);
  sines_.setZero(budget);
  rotated_rhs_.setZero(budget + 1);

  double& substitution = SolveClocks::Process().krylov_substitution;
  Substitute(basis_[0], b, substitution);
  const double beta = basis_[0].norm();
  if (beta == 0.0) {
    x.setZero(n);
    return true;
  }
  if (!std::isfinite(beta)) return false;
  basis_[0] /= beta;
  rotated_rhs_[0] = beta;
  const double target = options_.tolerance * beta;

  int k = 0;
  bool converged = false;
  for (int j = 0; j < budget; ++j) {
    work_.noalias() = A * basis_[j];
    Vector& w = basis_[j + 1];
    Substitute(w, work_, substitution);
    for (int pass = 0; pass < 2; ++pass) {
      for (int i = 0; i <= j; ++i) {
        const double h = basis_[i].dot(w);
        w.noalias() -= h * basis_[i];
        hessenberg_(i, j) += h;
      }
    }
    const double h_next = w.norm();
    hessenberg_(j + 1, j) = h_next;
    for (int i = 0; i < j; ++i) {
      const double upper = cosines_[i] * hessenberg_(i, j) + sines_[i] * hessenberg_(i + 1, j);
      hessenberg_(i + 1, j) = -sines_[i] * hessenberg_(i, j) + cosines_[i] * hessenberg_(i + 1, j);
      hessenberg_(i, j) = upper;
    }
    const double radius = std::hypot(hessenberg_(j, j), h_next);
    if (!(radius > 0.0) || !std::isfinite(radius)) return false;  // breakdown
    cosines_[j] = hessenberg_(j, j) / radius;
    sines_[j] = h_next / radius;
    hessenberg_(j, j) = radius;
    hessenberg_(j + 1, j) = 0.0;
    rotated_rhs_[j + 1] = -sines_[j] * rotated_rhs_[j];
    rotated_rhs_[j] *= cosines_[j];
    k = j + 1;
    last_iterations_ = k;
    const double residual = std::abs(rotated_rhs_[j + 1]);
    if (residual <= target) {
      converged = true;
      break;
    }
    if (h_next == 0.0) return false;  // an invariant subspace without the solution: A is singular
    // Stalled: at the mean rate so far, the tolerance is out of reach within the budget.
    if (2 * k >= budget) {
      const double rate = std::pow(residual / beta, 1.0 / k);
      if (!(rate < 1.0) || std::log(options_.tolerance) / std::log(rate) > budget) return false;
    }
    w /= h_next;
  }
  if (!converged) return false;
  const Vector y = hessenberg_.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(rotated_rhs_.head(k));
  x.setZero(n);
  for (int i = 0; i < k; ++i) x.noalias() += y[i] * basis_[i];
  if (!x.allFinite()) return false;
  // The preconditioned residual is small; a true residual that is not means the factors amplify
  // a direction in which A is (nearly) singular: the direct solve decides.
  work_.noalias() = b - A * x;
  return work_.norm() <= kMaxTrueResidual * b.norm();
}

}  // namespace mc
