// SPDX-License-Identifier: BSD-3-Clause
#include "custom_linear_solvers/mixed_ulm_linear_solver.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <tuple>

#include <Eigen/LU>

#include "core/model/dof.h"
#include "core/model/node.h"
#include "core/utilities/logger.h"
#include "core/variables/flags.h"
#include "core/variables/kernel_variables.h"
#include "custom_utilities/contact_variables.h"

namespace mc {

namespace {

using BlockType = MixedULMLinearSolver::BlockType;
/// The block of K(S_A, LM_A) of one node: at most three components.
using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;

BlockType Classify(const Dof& dof) {
  if (dof.fixed) return BlockType::kOther;  // an identity row (block builder): nothing to pair
  const VariableData* source = dof.variable->Source();
  const Node& node = *dof.node;
  if (source == &VECTOR_LAGRANGE_MULTIPLIER) return node.Is(ACTIVE) ? BlockType::kLmActive : BlockType::kLmInactive;
  if (source == &DISPLACEMENT) {
    if (node.Is(SLAVE)) return node.Is(ACTIVE) ? BlockType::kSlaveActive : BlockType::kSlaveInactive;
    if (node.Is(MASTER)) return BlockType::kMaster;
  }
  return BlockType::kOther;
}

}  // namespace

MixedULMLinearSolver::MixedULMLinearSolver(std::unique_ptr<LinearSolver> inner) : inner_(std::move(inner)) {
  assert(inner_);
}

MixedULMLinearSolver::~MixedULMLinearSolver() = default;

std::string MixedULMLinearSolver::Name() const { return Concat("mixed_ulm_linear_solver(", inner_->Name(), ")"); }

void MixedULMLinearSolver::Initialize(const SparseMatrix& A) {
  inner_state_ = InnerState::kNone;
  data_valid_ = false;
  structure_valid_ = false;
}

void MixedULMLinearSolver::Clear() {
  inner_->Clear();
  inner_state_ = InnerState::kNone;
  data_valid_ = false;
  structure_valid_ = false;
  condensed_ = SparseMatrix();
}

std::string MixedULMLinearSolver::DofName(int row) const {
  const Dof& dof = *dofs_[static_cast<std::size_t>(row)];
  return Concat(dof.variable->Name(), " of node ", dof.node->Id());
}

// Classification --------------------------------------------------------------------------------

void MixedULMLinearSolver::ProvideAdditionalData(const SparseMatrix& A, const std::vector<Dof*>& dof_of_equation) {
  const auto n = static_cast<std::size_t>(A.rows());
  if (A.rows() != A.cols() || dof_of_equation.size() < n)
    throw Error(Concat(Name(), ": ", dof_of_equation.size(), " DoFs for a ", A.rows(), " x ", A.cols(), " system"));
  new_types_.resize(n);
  for (std::size_t i = 0; i < n; ++i) new_types_[i] = Classify(*dof_of_equation[i]);
  const bool same = data_valid_ && types_ == new_types_ && dofs_.size() == n &&
                    std::equal(dofs_.begin(), dofs_.end(), dof_of_equation.begin());
  if (!same) {
    types_ = new_types_;  // a copy: both keep their capacity
    dofs_.assign(dof_of_equation.begin(), dof_of_equation.begin() + static_cast<std::ptrdiff_t>(n));
    structure_valid_ = false;
  }
  data_valid_ = true;
}

// Structure -------------------------------------------------------------------------------------

void MixedULMLinearSolver::BuildRowLists(const SparseMatrix& A) {
  const int n = static_cast<int>(A.rows());
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  tracked_row_.assign(static_cast<std::size_t>(n), -1);
  int tracked = 0;
  for (int s : pair_slave_) tracked_row_[static_cast<std::size_t>(s)] = tracked++;
  for (int i : lm_inactive_) tracked_row_[static_cast<std::size_t>(i)] = tracked++;
  row_offsets_.assign(static_cast<std::size_t>(tracked) + 1, 0);
  for (int j = 0; j < n; ++j)
    for (int p = outer[j]; p < outer[j + 1]; ++p)
      if (const int t = tracked_row_[static_cast<std::size_t>(inner[p])]; t >= 0)
        ++row_offsets_[static_cast<std::size_t>(t) + 1];
  for (int t = 0; t < tracked; ++t) row_offsets_[t + 1] += row_offsets_[t];
  row_positions_.resize(static_cast<std::size_t>(row_offsets_.back()));
  row_columns_.resize(static_cast<std::size_t>(row_offsets_.back()));
  std::vector<int> next(row_offsets_.begin(), row_offsets_.end() - 1);
  for (int j = 0; j < n; ++j)
    for (int p = outer[j]; p < outer[j + 1]; ++p)
      if (const int t = tracked_row_[static_cast<std::size_t>(inner[p])]; t >= 0) {
        const int k = next[static_cast<std::size_t>(t)]++;
        row_positions_[static_cast<std::size_t>(k)] = p;
        row_columns_[static_cast<std::size_t>(k)] = j;
      }
}

void MixedULMLinearSolver::BuildStructure(const SparseMatrix& A) {
  const int n = static_cast<int>(A.rows());
  const auto un = static_cast<std::size_t>(n);

  // Pair each LM_A unknown with the S_A row of the same node and component.
  std::vector<std::tuple<IndexType, int, int>> slaves;  // (node id, component, row)
  for (int i = 0; i < n; ++i)
    if (types_[static_cast<std::size_t>(i)] == BlockType::kSlaveActive)
      slaves.emplace_back(dofs_[static_cast<std::size_t>(i)]->node->Id(),
                          dofs_[static_cast<std::size_t>(i)]->variable->ComponentIndex(), i);
  std::sort(slaves.begin(), slaves.end());
  std::vector<std::tuple<IndexType, int, int, int>> pairs;  // (node id, component, slave row, multiplier)
  lm_inactive_.clear();
  for (int l = 0; l < n; ++l) {
    const BlockType type = types_[static_cast<std::size_t>(l)];
    if (type == BlockType::kLmInactive) lm_inactive_.push_back(l);
    if (type != BlockType::kLmActive) continue;
    const Dof& dof = *dofs_[static_cast<std::size_t>(l)];
    const auto key = std::make_tuple(dof.node->Id(), dof.variable->ComponentIndex(), -1);
    const auto it = std::upper_bound(slaves.begin(), slaves.end(), key);
    if (it == slaves.end() || std::get<0>(*it) != std::get<0>(key) || std::get<1>(*it) != std::get<1>(key))
      continue;  // no free slave displacement to pair with: l stays an unknown of the condensed system
    pairs.emplace_back(std::get<0>(key), std::get<1>(key), std::get<2>(*it), l);
  }
  // The pairs of one node form a group: its block of K(S_A, LM_A) is inverted as a whole.
  std::sort(pairs.begin(), pairs.end());
  pair_slave_.clear();
  pair_lm_.clear();
  pair_group_.clear();
  group_start_.assign(1, 0);
  inv_offset_.assign(1, 0);
  for (std::size_t q = 0; q < pairs.size(); ++q) {
    if (q > 0 && std::get<0>(pairs[q]) != std::get<0>(pairs[q - 1])) group_start_.push_back(static_cast<int>(q));
    pair_slave_.push_back(std::get<2>(pairs[q]));
    pair_lm_.push_back(std::get<3>(pairs[q]));
    pair_group_.push_back(static_cast<int>(group_start_.size()) - 1);
  }
  group_start_.push_back(static_cast<int>(pairs.size()));
  if (pairs.empty()) group_start_.assign(1, 0);
  for (std::size_t g = 0; g + 1 < group_start_.size(); ++g) {
    const int m = group_start_[g + 1] - group_start_[g];
    inv_offset_.push_back(inv_offset_.back() + m * m);
  }
  const auto n_pairs = pair_slave_.size();

  // Condensed numbering: unknowns C keep their order; the row of a pair's multiplier takes the
  // place of its slave row (eq. 4.38).
  eliminated_pair_.assign(un, -1);
  std::vector<int> slave_pair(un, -1);
  for (std::size_t q = 0; q < n_pairs; ++q) {
    eliminated_pair_[static_cast<std::size_t>(pair_lm_[q])] = static_cast<int>(q);
    slave_pair[static_cast<std::size_t>(pair_slave_[q])] = static_cast<int>(q);
  }
  column_to_cond_.assign(un, -1);
  cond_to_column_.clear();
  for (int j = 0; j < n; ++j) {
    if (eliminated_pair_[static_cast<std::size_t>(j)] >= 0 ||
        types_[static_cast<std::size_t>(j)] == BlockType::kLmInactive)
      continue;
    column_to_cond_[static_cast<std::size_t>(j)] = static_cast<int>(cond_to_column_.size());
    cond_to_column_.push_back(j);
  }
  row_to_cond_.assign(un, -1);
  for (int r = 0; r < n; ++r) {
    const int q = eliminated_pair_[static_cast<std::size_t>(r)];
    if (q >= 0)
      row_to_cond_[static_cast<std::size_t>(r)] =
          column_to_cond_[static_cast<std::size_t>(pair_slave_[static_cast<std::size_t>(q)])];
    else if (slave_pair[static_cast<std::size_t>(r)] < 0 &&
             types_[static_cast<std::size_t>(r)] != BlockType::kLmInactive)
      row_to_cond_[static_cast<std::size_t>(r)] = column_to_cond_[static_cast<std::size_t>(r)];
  }

  BuildRowLists(A);
  auto find_in_row = [&](int row, int column) {
    const int t = tracked_row_[static_cast<std::size_t>(row)];
    const auto first = row_columns_.begin() + row_offsets_[static_cast<std::size_t>(t)];
    const auto last = row_columns_.begin() + row_offsets_[static_cast<std::size_t>(t) + 1];
    const auto it = std::lower_bound(first, last, column);
    return it != last && *it == column ? row_positions_[static_cast<std::size_t>(it - row_columns_.begin())] : -1;
  };
  // K(s_a, l_b) of each group, row-major at inv_offset_ (the layout of its inverse).
  block_positions_.assign(static_cast<std::size_t>(inv_offset_.back()), -1);
  for (std::size_t g = 0; g + 1 < group_start_.size(); ++g) {
    const int first = group_start_[g];
    const int m = group_start_[g + 1] - first;
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b)
        block_positions_[static_cast<std::size_t>(inv_offset_[g] + a * m + b)] = find_in_row(
            pair_slave_[static_cast<std::size_t>(first + a)], pair_lm_[static_cast<std::size_t>(first + b)]);
  }
  lm_inactive_diag_.resize(lm_inactive_.size());
  for (std::size_t k = 0; k < lm_inactive_.size(); ++k)
    lm_inactive_diag_[k] = find_in_row(lm_inactive_[k], lm_inactive_[k]);

  // Pattern of A' = A_RC - A_RL K_SL^-1 A_SC and, per entry, where its terms come from. Column j
  // of A' holds the R rows of column j of A and, for every pair row s with an entry in column j,
  // the R rows of the columns l of the pairs of its group (K_SL^-1 is block diagonal).
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const auto nc = cond_to_column_.size();
  std::vector<int> old_outer, old_inner;
  if (condensed_.outerSize() > 0) {
    old_outer.assign(condensed_.outerIndexPtr(), condensed_.outerIndexPtr() + condensed_.outerSize() + 1);
    old_inner.assign(condensed_.innerIndexPtr(), condensed_.innerIndexPtr() + condensed_.nonZeros());
  }
  std::vector<int> new_outer(nc + 1, 0), new_inner;
  cond_source_.clear();
  cond_offsets_.assign(1, 0);
  corrections_.clear();
  struct Term {
    int row;
    int source;  // position in A, or -1 for a correction
    Correction correction;
  };
  std::vector<Term> terms;
  for (std::size_t jc = 0; jc < nc; ++jc) {
    const int j = cond_to_column_[jc];
    terms.clear();
    for (int p = outer[j]; p < outer[j + 1]; ++p) {
      const int r = inner[p];
      if (const int cr = row_to_cond_[static_cast<std::size_t>(r)]; cr >= 0) terms.push_back({cr, p, {}});
      const int q = slave_pair[static_cast<std::size_t>(r)];
      if (q < 0) continue;
      const int g = pair_group_[static_cast<std::size_t>(q)];
      const int first = group_start_[static_cast<std::size_t>(g)];
      const int m = group_start_[static_cast<std::size_t>(g) + 1] - first;
      for (int b = 0; b < m; ++b) {
        const int l = pair_lm_[static_cast<std::size_t>(first + b)];
        const int inverse = inv_offset_[static_cast<std::size_t>(g)] + b * m + (q - first);
        for (int p2 = outer[l]; p2 < outer[l + 1]; ++p2)
          if (const int cr = row_to_cond_[static_cast<std::size_t>(inner[p2])]; cr >= 0)
            terms.push_back({cr, -1, {p2, p, inverse}});
      }
    }
    std::stable_sort(terms.begin(), terms.end(), [](const Term& a, const Term& b) { return a.row < b.row; });
    for (std::size_t k = 0; k < terms.size();) {
      const int row = terms[k].row;
      int source = -1;
      for (; k < terms.size() && terms[k].row == row; ++k) {
        if (terms[k].source >= 0)
          source = terms[k].source;
        else
          corrections_.push_back(terms[k].correction);
      }
      new_inner.push_back(row);
      cond_source_.push_back(source);
      cond_offsets_.push_back(static_cast<int>(corrections_.size()));
    }
    new_outer[jc + 1] = static_cast<int>(new_inner.size());
  }
  condensed_ = SparseMatrix(static_cast<Eigen::Index>(nc), static_cast<Eigen::Index>(nc));
  condensed_.resizeNonZeros(static_cast<Eigen::Index>(new_inner.size()));
  std::copy(new_outer.begin(), new_outer.end(), condensed_.outerIndexPtr());
  std::copy(new_inner.begin(), new_inner.end(), condensed_.innerIndexPtr());
  std::fill(condensed_.valuePtr(), condensed_.valuePtr() + new_inner.size(), 0.0);
  if (inner_state_ == InnerState::kCondensed && (old_outer != new_outer || old_inner != new_inner))
    inner_state_ = InnerState::kNone;

  inv_block_.resize(static_cast<Eigen::Index>(inv_offset_.back()));
  group_work_.resize(static_cast<Eigen::Index>(n_pairs));
  b_work_.resize(n);
  b_condensed_.resize(static_cast<Eigen::Index>(nc));
  x_condensed_.setZero(static_cast<Eigen::Index>(nc));
  structure_valid_ = true;
}

// Checks ----------------------------------------------------------------------------------------

std::string MixedULMLinearSolver::CheckDiagonalBlocks(const SparseMatrix& A) {
  const double* v = A.valuePtr();
  auto row_max = [&](int row) {
    const int t = tracked_row_[static_cast<std::size_t>(row)];
    double largest = 0.0;
    for (int k = row_offsets_[static_cast<std::size_t>(t)]; k < row_offsets_[static_cast<std::size_t>(t) + 1]; ++k)
      largest = std::max(largest, std::abs(v[row_positions_[static_cast<std::size_t>(k)]]));
    return largest;
  };
  // The first entry of `row` in a column accepted by `off` that exceeds the tolerance, or -1.
  auto first_off = [&](int row, double limit, auto off) {
    const int t = tracked_row_[static_cast<std::size_t>(row)];
    for (int k = row_offsets_[static_cast<std::size_t>(t)]; k < row_offsets_[static_cast<std::size_t>(t) + 1]; ++k)
      if (off(row_columns_[static_cast<std::size_t>(k)]) &&
          std::abs(v[row_positions_[static_cast<std::size_t>(k)]]) > limit)
        return k;
    return -1;
  };
  for (std::size_t g = 0; g + 1 < group_start_.size(); ++g) {
    const int first = group_start_[g];
    const int m = group_start_[g + 1] - first;
    SmallMatrix block(m, m);
    double block_max = 0.0;
    for (int a = 0; a < m; ++a) {
      const int s = pair_slave_[static_cast<std::size_t>(first + a)];
      const double largest = row_max(s);
      double pivot = 0.0;  // the largest entry of the row within the group
      for (int b = 0; b < m; ++b) {
        const int position = block_positions_[static_cast<std::size_t>(inv_offset_[g] + a * m + b)];
        block(a, b) = position >= 0 ? v[position] : 0.0;
        pivot = std::max(pivot, std::abs(block(a, b)));
      }
      block_max = std::max(block_max, pivot);
      const int l = pair_lm_[static_cast<std::size_t>(first + a)];
      if (!(pivot > kDiagonalTolerance * largest))
        return Concat("K(S_A, LM_A) has no pivot for ", DofName(s), ": its largest entry at the multipliers of node ",
                      dofs_[static_cast<std::size_t>(l)]->node->Id(), " is ", pivot, " against a row maximum of ",
                      largest);
      // Dual multipliers couple a slave row to the multipliers of its own node only.
      const int k = first_off(s, kDiagonalTolerance * largest, [&](int c) {
        const int q = eliminated_pair_[static_cast<std::size_t>(c)];
        return q >= 0 && pair_group_[static_cast<std::size_t>(q)] != static_cast<int>(g);
      });
      if (k >= 0)
        return Concat("K(S_A, LM_A) is not diagonal node by node: row ", DofName(s), " has ",
                      v[row_positions_[static_cast<std::size_t>(k)]], " at ",
                      DofName(row_columns_[static_cast<std::size_t>(k)]), " (multipliers of node ",
                      dofs_[static_cast<std::size_t>(l)]->node->Id(), " expected)");
    }
    Eigen::FullPivLU<SmallMatrix> lu(block);
    lu.setThreshold(kDiagonalTolerance);
    if (!lu.isInvertible())
      return Concat("K(S_A, LM_A) is singular at the multipliers of node ",
                    dofs_[static_cast<std::size_t>(pair_lm_[static_cast<std::size_t>(first)])]->node->Id(),
                    " (largest entry ", block_max, ")");
    const SmallMatrix inverse = lu.inverse();
    for (int b = 0; b < m; ++b)
      for (int a = 0; a < m; ++a) inv_block_[inv_offset_[g] + b * m + a] = inverse(b, a);
  }
  for (std::size_t k = 0; k < lm_inactive_.size(); ++k) {
    const int i = lm_inactive_[k];
    const double largest = row_max(i);
    const double diagonal = lm_inactive_diag_[k] >= 0 ? v[lm_inactive_diag_[k]] : 0.0;
    if (diagonal == 0.0) return Concat("K(LM_I, LM_I) has a zero diagonal at ", DofName(i));
    const int e = first_off(i, kDiagonalTolerance * largest, [&](int c) { return c != i; });
    if (e >= 0)
      return Concat("the inactive multiplier row ", DofName(i),
                    " is not diagonal: ", v[row_positions_[static_cast<std::size_t>(e)]], " at ",
                    DofName(row_columns_[static_cast<std::size_t>(e)]));
  }
  return {};
}

void MixedULMLinearSolver::ApplyInverseBlocks(Vector& values) const {
  double local[3];
  for (std::size_t g = 0; g + 1 < group_start_.size(); ++g) {
    const int first = group_start_[g];
    const int m = group_start_[g + 1] - first;
    for (int a = 0; a < m; ++a) local[a] = values[first + a];
    for (int b = 0; b < m; ++b) {
      double sum = 0.0;
      for (int a = 0; a < m; ++a) sum += inv_block_[inv_offset_[g] + b * m + a] * local[a];
      values[first + b] = sum;
    }
  }
}

// Solve -----------------------------------------------------------------------------------------

void MixedULMLinearSolver::Solve(const SparseMatrix& A, Vector& x, const Vector& b) {
  if (!data_valid_ || static_cast<std::size_t>(A.rows()) != types_.size())
    return SolveFull(A, x, b, "no DoF of the system rows was provided (ProvideAdditionalData)", true);
  if (!structure_valid_) BuildStructure(A);
  if (pair_slave_.empty() && lm_inactive_.empty()) return SolveFull(A, x, b, "no multiplier to condense", false);
  if (std::string reason = CheckDiagonalBlocks(A); !reason.empty()) return SolveFull(A, x, b, std::move(reason), true);
  SolveCondensed(A, x, b);
}

void MixedULMLinearSolver::SolveFull(const SparseMatrix& A, Vector& x, const Vector& b, std::string reason, bool warn) {
  last_condensed_ = false;
  if (warn && !warned_) {  // once: the reason recurs at every iteration of a case
    Logger::Warning(
        Concat(Name(), ": ", reason, "; solving the full system of ", A.rows(), " unknowns instead (reported once)"));
    warned_ = true;
  }
  fallback_reason_ = std::move(reason);
  if (inner_state_ != InnerState::kFull) {
    inner_->Initialize(A);
    ++inner_initializations_;
    inner_state_ = InnerState::kFull;
  }
  inner_->Solve(A, x, b);
}

void MixedULMLinearSolver::SolveCondensed(const SparseMatrix& A, Vector& x, const Vector& b) {
  const double* v = A.valuePtr();
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const int n = static_cast<int>(A.rows());
  if (x.size() != n) x.setZero(n);
  b_work_ = b;

  // Inactive multipliers from their diagonal rows; their columns move to the right-hand side.
  for (std::size_t k = 0; k < lm_inactive_.size(); ++k)
    x[lm_inactive_[k]] = b[lm_inactive_[k]] / v[lm_inactive_diag_[k]];
  for (const int i : lm_inactive_)
    for (int p = outer[i]; p < outer[i + 1]; ++p)
      if (inner[p] != i) b_work_[inner[p]] -= v[p] * x[i];

  // Condensed matrix (eq. 4.38) and right-hand side.
  double* cv = condensed_.valuePtr();
  const auto nnz = static_cast<std::size_t>(condensed_.nonZeros());
  for (std::size_t k = 0; k < nnz; ++k) {
    double value = cond_source_[k] >= 0 ? v[cond_source_[k]] : 0.0;
    for (int c = cond_offsets_[k]; c < cond_offsets_[k + 1]; ++c) {
      const Correction& t = corrections_[static_cast<std::size_t>(c)];
      value -= v[t.rl] * v[t.sc] * inv_block_[t.inverse];
    }
    cv[k] = value;
  }
  for (int r = 0; r < n; ++r)
    if (const int cr = row_to_cond_[static_cast<std::size_t>(r)]; cr >= 0) b_condensed_[cr] = b_work_[r];
  for (std::size_t q = 0; q < pair_slave_.size(); ++q)
    group_work_[static_cast<Eigen::Index>(q)] = b_work_[pair_slave_[q]];
  ApplyInverseBlocks(group_work_);
  for (std::size_t q = 0; q < pair_slave_.size(); ++q) {
    const int l = pair_lm_[q];
    const double factor = group_work_[static_cast<Eigen::Index>(q)];
    for (int p = outer[l]; p < outer[l + 1]; ++p)
      if (const int cr = row_to_cond_[static_cast<std::size_t>(inner[p])]; cr >= 0) b_condensed_[cr] -= v[p] * factor;
  }

  if (inner_state_ != InnerState::kCondensed) {
    inner_->Initialize(condensed_);
    ++inner_initializations_;
    inner_state_ = InnerState::kCondensed;
  }
  x_condensed_.setZero();
  try {
    inner_->Solve(condensed_, x_condensed_, b_condensed_);
  } catch (const SingularMatrixError& e) {
    const long k = e.Equation();
    const long column = k >= 0 && static_cast<std::size_t>(k) < cond_to_column_.size()
                            ? cond_to_column_[static_cast<std::size_t>(k)]
                            : -1;
    throw SingularMatrixError(Concat(e.what(), " (condensed system of ", Name(), ")"), column);
  }
  for (std::size_t k = 0; k < cond_to_column_.size(); ++k)
    x[cond_to_column_[k]] = x_condensed_[static_cast<Eigen::Index>(k)];

  // Active multipliers from their slave rows (eq. 4.40b), node by node.
  for (std::size_t q = 0; q < pair_slave_.size(); ++q) {
    const int s = pair_slave_[q];
    const int t = tracked_row_[static_cast<std::size_t>(s)];
    double sum = b_work_[s];
    for (int k = row_offsets_[static_cast<std::size_t>(t)]; k < row_offsets_[static_cast<std::size_t>(t) + 1]; ++k) {
      const int c = row_columns_[static_cast<std::size_t>(k)];
      if (column_to_cond_[static_cast<std::size_t>(c)] >= 0)
        sum -= v[row_positions_[static_cast<std::size_t>(k)]] * x[c];
    }
    group_work_[static_cast<Eigen::Index>(q)] = sum;
  }
  ApplyInverseBlocks(group_work_);
  for (std::size_t q = 0; q < pair_slave_.size(); ++q) x[pair_lm_[q]] = group_work_[static_cast<Eigen::Index>(q)];
  last_condensed_ = true;
  fallback_reason_.clear();
}

}  // namespace mc
