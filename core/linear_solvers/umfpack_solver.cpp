// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/umfpack_solver.h"

#include <suitesparse/umfpack.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/linear_solvers/suitesparse_memory.h"

namespace mc {

namespace {

std::string UmfpackStatusText(int status) {
  switch (status) {
    case UMFPACK_ERROR_out_of_memory: return "out of memory";
    case UMFPACK_ERROR_invalid_matrix: return "invalid matrix (unsorted or duplicate indices)";
    case UMFPACK_ERROR_different_pattern: return "pattern changed since the symbolic analysis";
    default: return Concat("status ", status);
  }
}

// Whether every diagonal entry is positive, as in a stiffness matrix. Saddle-point systems (the
// multiplier rows of active contact nodes have a zero diagonal) legitimately factor with tiny
// pivots, so the round-off singularity test applies only to the former.
bool HasPositiveDiagonal(const SparseMatrix& M) {
  for (Eigen::Index j = 0; j < M.outerSize(); ++j) {
    double diagonal = 0.0;
    for (SparseMatrix::InnerIterator it(M, j); it; ++it)
      if (it.row() == j) diagonal = it.value();
    if (!(diagonal > 0.0)) return false;
  }
  return true;
}

static_assert(UMFPACK_CONTROL == 20, "UmfpackSolver::control_ holds UMFPACK_CONTROL parameters");

/// From this many equations the symbolic analysis orders with METIS (nested dissection) instead
/// of AMD: on the 2D and 3D contact benchmarks (7k-26k equations) it halves the factorization
/// flops; below, both orderings give about the same fill and AMD is quicker to compute.
constexpr Eigen::Index kMetisOrderingMinEquations = 5000;

/// UMFPACK's defaults except: the ordering (above), and no iterative refinement. Refinement
/// costs two more triangular solves and a residual per solve; a Newton loop corrects the
/// increment anyway, and on the benchmarks the solutions agree to round-off without it.
void SetControl(double (&control)[UMFPACK_CONTROL], Eigen::Index equations) {
  umfpack_dl_defaults(control);
  control[UMFPACK_IRSTEP] = 0;
  if (equations >= kMetisOrderingMinEquations) control[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
}

/// `ordering` (a column ordering of some of M's columns) completed with the others, each placed
/// right after the last of its neighbours (the rows of its column) already ordered: eliminated
/// once they are, it adds about as little fill as it can without reordering the rest. False when
/// `ordering` is not a partial permutation of M's columns.
bool CompleteOrdering(const SparseMatrix& M, std::vector<long>& ordering) {
  const Eigen::Index n = M.cols();
  if (static_cast<Eigen::Index>(ordering.size()) > n) return false;
  std::vector<long> position(static_cast<std::size_t>(n), -1);
  for (std::size_t k = 0; k < ordering.size(); ++k) {
    const long column = ordering[k];
    if (column < 0 || column >= n || position[column] >= 0) return false;
    position[column] = static_cast<long>(k);
  }
  if (static_cast<Eigen::Index>(ordering.size()) == n) return true;
  // Sort key: 2 k for the k-th ordered column, 2 k + 1 for a new one after the ordered column k.
  std::vector<std::pair<long, long>> keyed;
  keyed.reserve(static_cast<std::size_t>(n));
  for (std::size_t k = 0; k < ordering.size(); ++k) keyed.emplace_back(2 * static_cast<long>(k), ordering[k]);
  const long last = static_cast<long>(ordering.size()) - 1;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (position[j] >= 0) continue;
    long after = -1;
    for (SparseMatrix::InnerIterator it(M, j); it; ++it) after = std::max(after, position[it.row()]);
    keyed.emplace_back(2 * (after < 0 ? last : after) + 1, static_cast<long>(j));
  }
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  ordering.resize(static_cast<std::size_t>(n));
  for (std::size_t k = 0; k < keyed.size(); ++k) ordering[k] = keyed[k].second;
  return true;
}

}  // namespace

UmfpackSolver::UmfpackSolver() : DirectSolver("UMFPACK") { SuiteSparseMemory::Install(); }

void UmfpackSolver::Analyze(const SparseMatrix& M) {
  // The 64-bit interface: with 32-bit sizes UMFPACK runs out of addressable workspace on 3D
  // problems of ~1e5 equations long before memory is exhausted.
  outer_.assign(M.outerIndexPtr(), M.outerIndexPtr() + M.outerSize() + 1);
  inner_.assign(M.innerIndexPtr(), M.innerIndexPtr() + M.nonZeros());
  SetControl(control_, M.rows());
  double info[UMFPACK_INFO];
  std::vector<long> ordering;
  ordering.swap(kept_ordering_);
  ordering_kept_ = !ordering.empty() && CompleteOrdering(M, ordering);
  if (ordering_kept_) {
    // Without its strategy the symmetric ordering would be postordered as an unsymmetric one,
    // with row pivoting off the diagonal: 10 times the flops on hertz2d_30k.
    control_[UMFPACK_STRATEGY] = kept_strategy_;
    const auto status = umfpack_dl_qsymbolic(M.rows(), M.cols(), outer_.data(), inner_.data(), M.valuePtr(),
                                             ordering.data(), &symbolic_, control_, info);
    SetControl(control_, M.rows());
    if (status == UMFPACK_OK) {
      strategy_used_ = kept_strategy_;
      return;
    }
    symbolic_ = nullptr;  // analysed afresh below
    ordering_kept_ = false;
  }
  auto status =
      umfpack_dl_symbolic(M.rows(), M.cols(), outer_.data(), inner_.data(), M.valuePtr(), &symbolic_, control_, info);
  if (status == UMFPACK_ERROR_ordering_failed && control_[UMFPACK_ORDERING] == UMFPACK_ORDERING_METIS) {
    control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_AMD;  // a UMFPACK built without METIS
    status =
        umfpack_dl_symbolic(M.rows(), M.cols(), outer_.data(), inner_.data(), M.valuePtr(), &symbolic_, control_, info);
  }
  strategy_used_ = info[UMFPACK_STRATEGY_USED];
  if (status != UMFPACK_OK) {
    symbolic_ = nullptr;
    throw SolutionError(
        Concat("UMFPACK symbolic analysis of a ", M.rows(), "-equation matrix failed: ", UmfpackStatusText(status)));
  }
}

void UmfpackSolver::Factorize(const SparseMatrix& M) {
  FreeNumeric();
  double info[UMFPACK_INFO];
  const auto status =
      umfpack_dl_numeric(outer_.data(), inner_.data(), M.valuePtr(), symbolic_, &numeric_, control_, info);
  if (status == UMFPACK_WARNING_singular_matrix) {
    const long column = SmallestPivotColumn();
    FreeNumeric();
    throw SingularMatrixError(Concat("UMFPACK: singular matrix, zero pivot at equation ", column), column);
  }
  // A structure free to move as a rigid body gives a pivot that is zero up to round-off rather
  // than exactly zero; its solution would be meaningless, so it is reported as singular too.
  if (status == UMFPACK_OK && info[UMFPACK_RCOND] < kSingularReciprocalCondition && HasPositiveDiagonal(M)) {
    const long column = SmallestPivotColumn();
    FreeNumeric();
    throw SingularMatrixError(Concat("UMFPACK: numerically singular matrix (reciprocal condition estimate ",
                                     info[UMFPACK_RCOND], "), smallest pivot at equation ", column),
                              column);
  }
  if (status != UMFPACK_OK) {
    FreeNumeric();
    throw SolutionError(Concat("UMFPACK numeric factorization failed: ", UmfpackStatusText(status)));
  }
  last_flops_ = info[UMFPACK_FLOPS];
  if (!ordering_kept_) fresh_flops_ = last_flops_;
}

// Without iterative refinement (UMFPACK_IRSTEP 0) umfpack_dl_solve does not read the matrix, so a
// substitution needs only the factors: they serve as a preconditioner after A has changed.
void UmfpackSolver::Substitute(Vector& x, const Vector& b) {
  x.resize(b.size());
  const auto solve_status =
      umfpack_dl_solve(UMFPACK_A, nullptr, nullptr, nullptr, x.data(), b.data(), numeric_, control_, nullptr);
  if (solve_status != UMFPACK_OK)
    throw SolutionError(Concat("UMFPACK solve failed: ", UmfpackStatusText(solve_status)));
}

void UmfpackSolver::KeepOrderingForNextAnalysis(const std::vector<long>& new_of_old) {
  kept_ordering_.clear();
  if (last_flops_ > kMaxFlopsGrowth * fresh_flops_) return;  // the ordering has aged: a fresh one
  kept_strategy_ = strategy_used_;
  SuiteSparse_long n_row = 0, n_col = 0, nz_diag = 0, lnz = 0, unz = 0, recip = 0;
  if (numeric_ == nullptr || umfpack_dl_get_lunz(&lnz, &unz, &n_row, &n_col, &nz_diag, numeric_) != UMFPACK_OK) return;
  if (!new_of_old.empty() && static_cast<SuiteSparse_long>(new_of_old.size()) != n_col) return;
  std::vector<SuiteSparse_long> q(static_cast<std::size_t>(n_col));
  if (umfpack_dl_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, q.data(), nullptr, &recip,
                             nullptr, numeric_) == UMFPACK_OK)
    for (const SuiteSparse_long column : q) {
      const long kept = new_of_old.empty() ? static_cast<long>(column) : new_of_old[static_cast<std::size_t>(column)];
      if (kept >= 0) kept_ordering_.push_back(kept);
    }
}

// The diagonal of U in pivot order, with the column permutation Q, gives the original column of
// the smallest pivot (the first zero one when there are exact zeros).
long UmfpackSolver::SmallestPivotColumn() const {
  SuiteSparse_long n_row = 0, n_col = 0, nz_diag = 0, lnz = 0, unz = 0, recip = 0;
  if (umfpack_dl_get_lunz(&lnz, &unz, &n_row, &n_col, &nz_diag, numeric_) != UMFPACK_OK) return -1;
  std::vector<SuiteSparse_long> q(n_col);
  std::vector<double> diagonal(std::min(n_row, n_col));
  if (umfpack_dl_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, q.data(), diagonal.data(),
                             &recip, nullptr, numeric_) != UMFPACK_OK) {
    return -1;
  }
  if (diagonal.empty()) return -1;
  std::size_t smallest = 0;
  for (std::size_t k = 0; k < diagonal.size(); ++k) {
    if (diagonal[k] == 0.0) return q[k];
    if (std::abs(diagonal[k]) < std::abs(diagonal[smallest])) smallest = k;
  }
  return q[smallest];
}

void UmfpackSolver::FreeNumeric() {
  if (numeric_ != nullptr) umfpack_dl_free_numeric(&numeric_);
  numeric_ = nullptr;
}

void UmfpackSolver::Release() {
  FreeNumeric();
  if (symbolic_ != nullptr) umfpack_dl_free_symbolic(&symbolic_);
  symbolic_ = nullptr;
}

}  // namespace mc
