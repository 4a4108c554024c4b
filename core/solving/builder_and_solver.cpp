// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/builder_and_solver.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <type_traits>

#include "core/linear_solvers/solve_clocks.h"
#include "core/model/master_slave_constraint.h"
#include "core/model/model_part.h"
#include "core/model/parallel_utilities.h"
#include "core/solving/scheme.h"
#include "core/solving/singular_system_error.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"

namespace mc {

namespace {

/// Adds the wall-clock time of its scope to an accumulator.
class ScopedTimer {
 public:
  explicit ScopedTimer(double& seconds) : seconds_(seconds), start_(std::chrono::steady_clock::now()) {}
  ~ScopedTimer() { seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  double& seconds_;
  std::chrono::steady_clock::time_point start_;
};

bool DofLess(const Dof* a, const Dof* b) {
  if (a->node->Id() != b->node->Id()) return a->node->Id() < b->node->Id();
  return a->variable->Key() < b->variable->Key();
}

std::string DofName(const Dof& dof) { return Concat(dof.variable->Name(), " of node ", dof.node->Id()); }

}  // namespace

BuilderAndSolver::BuilderAndSolver(std::shared_ptr<LinearSolver> linear_solver)
    : linear_solver_(std::move(linear_solver)),
      communicator_(linear_solver_ ? linear_solver_->Communicator() : nullptr) {}

BuilderAndSolver::~BuilderAndSolver() = default;

// DoFs ------------------------------------------------------------------------------------------

void BuilderAndSolver::SetUpDofSet(ModelPart& model_part, const Scheme& scheme) {
  ScopedTimer timer(timings_.dof_setup);
  const ProcessInfo& info = model_part.GetProcessInfo();
  std::vector<std::vector<Dof*>> per_thread(static_cast<std::size_t>(omp_get_max_threads()));
  ForEachActiveEntity(model_part, [&](Entity& e) {
    static thread_local DofsVectorType local;
    scheme.GetDofList(e, local, info);
    auto& mine = per_thread[static_cast<std::size_t>(omp_get_thread_num())];
    mine.insert(mine.end(), local.begin(), local.end());
  });
  dofs_.clear();
  for (auto& v : per_thread) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    dofs_.insert(dofs_.end(), v.begin(), v.end());
  }
  if (communicator_ && model_part.GetNodePartition()) {
    // A piece keeps its contact interface whole, but a node of it that no entity of the piece uses
    // would get no displacement update here: its position would go stale, and this rank's contact
    // search would see another master surface than its owner's (hertz2d_250k on 2 ranks took another
    // contact zone from step 3). Its displacement DoFs join the piece as ghosts, which follow their
    // owner's increments like the others. Only the components the entities solve for (a 2D model's
    // nodes also carry DISPLACEMENT_Z, which no entity uses and no owner numbers).
    std::vector<const Variable<double>*> solved;
    for (const Dof* dof : dofs_)
      if (dof->variable->Source() == &DISPLACEMENT &&
          std::find(solved.begin(), solved.end(), dof->variable) == solved.end())
        solved.push_back(dof->variable);
    const NodePartition& owners = *model_part.GetNodePartition();
    const int rank = communicator_->Rank();
    for (Node* node : model_part.Nodes())
      if (owners.Owner(*node) != rank)
        for (const Variable<double>* variable : solved)
          if (Dof* dof = node->FindDof(*variable)) dofs_.push_back(dof);
  }
  std::vector<std::shared_ptr<const MasterSlaveConstraint>> constraints = added_constraints_;
  constraints.insert(constraints.end(), model_part.MasterSlaveConstraints().begin(),
                     model_part.MasterSlaveConstraints().end());
  if (constraints != constraints_) {
    constraints_ = std::move(constraints);
    constraints_changed_ = true;
  }
  for (const auto& c : constraints_) {
    if (!c->IsActive()) continue;
    dofs_.push_back(&c->Slave());
    dofs_.insert(dofs_.end(), c->Masters().begin(), c->Masters().end());
  }
  std::sort(dofs_.begin(), dofs_.end(), DofLess);
  dofs_.erase(std::unique(dofs_.begin(), dofs_.end()), dofs_.end());
  piece_owners_ = communicator_ ? model_part.GetNodePartition() : nullptr;
  numbering_.reset();
  if (communicator_) {
    if (!piece_owners_ && !node_partition_.IsFor(model_part))
      node_partition_ = NodePartition(model_part, *communicator_);
    // Grouped by owner, each group in the order of dofs_ (a counting sort: one look-up a DoF). A
    // piece puts its own DoFs first: the group of this rank, then the other groups.
    const int rank = communicator_->Rank();
    const auto group = [&](int owner) {
      return !piece_owners_ ? owner : owner == rank ? 0 : owner < rank ? owner + 1 : owner;
    };
    std::vector<int> owner(dofs_.size());
    std::vector<std::size_t> start(static_cast<std::size_t>(communicator_->Size()) + 1, 0);
    for (std::size_t i = 0; i < dofs_.size(); ++i) {
      owner[i] = group(Owners().Owner(*dofs_[i]->node));
      ++start[static_cast<std::size_t>(owner[i]) + 1];
    }
    for (std::size_t r = 1; r < start.size(); ++r) start[r] += start[r - 1];
    ordered_dofs_.resize(dofs_.size());
    for (std::size_t i = 0; i < dofs_.size(); ++i)
      ordered_dofs_[start[static_cast<std::size_t>(owner[i])]++] = dofs_[i];
    if (piece_owners_)
      owned_dofs_.assign(ordered_dofs_.begin(), ordered_dofs_.begin() + static_cast<std::ptrdiff_t>(start[0]));
  }
  numbered_ = false;
  pattern_valid_ = false;
  if (echo_level_ >= 2) Logger::Detail(Concat(Name(), " builder: ", dofs_.size(), " DoFs"));
}

void BuilderAndSolver::SetUpSystem() {
  ScopedTimer timer(timings_.dof_setup);
  slave_of_.clear();
  for (const auto& c : constraints_) {
    if (!c->IsActive()) continue;
    const Dof& s = c->Slave();
    if (!std::binary_search(dofs_.begin(), dofs_.end(), &c->Slave(), DofLess) ||
        std::any_of(c->Masters().begin(), c->Masters().end(),
                    [&](Dof* m) { return !std::binary_search(dofs_.begin(), dofs_.end(), m, DofLess); }))
      throw Error(Concat("master-slave constraint ", c->Id(),
                         " uses DoFs outside the DoF set: call SetUpDofSet after adding constraints"));
    auto [it, inserted] = slave_of_.emplace(&s, c.get());
    if (!inserted)
      throw InputError(Concat("master-slave constraints ", it->second->Id(), " and ", c->Id(), " both constrain ",
                              DofName(s), "; a DoF may be the slave of one constraint only"));
  }
  for (const auto& c : constraints_) {
    if (!c->IsActive()) continue;
    for (const Dof* m : c->Masters()) {
      auto it = slave_of_.find(m);
      if (it != slave_of_.end())
        throw InputError(Concat("master-slave constraint ", c->Id(), ": master ", DofName(*m),
                                " is the slave of constraint ", it->second->Id(),
                                " (chained constraints are not supported)"));
    }
  }
  if (piece_owners_)
    NumberPiece();
  else
    NumberDofs();
  const std::size_t n = dofs_.size();
  dofs_by_equation_.assign(n, nullptr);
  fixed_at_numbering_.assign(n, 0);
  for (Dof* d : dofs_) {
    assert(d->equation_id >= 0 && static_cast<std::size_t>(d->equation_id) < n);
    dofs_by_equation_[static_cast<std::size_t>(d->equation_id)] = d;
    fixed_at_numbering_[static_cast<std::size_t>(d->equation_id)] = d->fixed;
  }
  if (numbering_) {
    owned_.assign(n, 0);
    std::fill(owned_.begin(), owned_.begin() + static_cast<std::ptrdiff_t>(owned_dofs_.size()), 1);
  } else if (communicator_) {
    std::vector<int> owner(n);
    for (std::size_t i = 0; i < n; ++i) owner[i] = node_partition_.Owner(*dofs_by_equation_[i]->node);
    owned_.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) owned_[i] = owner[i] == communicator_->Rank();
    owner.resize(n_system_);
    partition_ = RowPartition::FromOwners(owner, communicator_->Size(), communicator_->Rank());
  }
  rhs_raw_.setZero(static_cast<Eigen::Index>(n));
  rhs_effective_.setZero(static_cast<Eigen::Index>(n));
  residual_.setZero(static_cast<Eigen::Index>(n));
  dx_.setZero(static_cast<Eigen::Index>(n));
  g_.setZero(static_cast<Eigen::Index>(n_assembled_));
  b_system_.setZero(static_cast<Eigen::Index>(n_system_));
  x_system_.setZero(static_cast<Eigen::Index>(n_system_));
  numbered_ = true;
  constraints_changed_ = false;
  pattern_valid_ = false;
  if (echo_level_ >= 2)
    Logger::Detail(
        Concat(Name(), " builder: ", n, " DoFs, ", n_system_, " unknowns, ", slave_of_.size(), " constrained DoFs"));
}

void BuilderAndSolver::NumberPiece() {
  if (Name() != "block")
    throw NotImplementedError(Concat("the ", Name(), " builder on a model cut across ", communicator_->Size(),
                                     " processes: use the block builder (\"block_builder\": true)"));
  const NodePartition& owners = *piece_owners_;
  numbering_ = std::make_unique<DistributedDofNumbering>(
      dofs_, [&owners](const Node& node) { return owners.Owner(node); }, *communicator_);
  const std::size_t owned = owned_dofs_.size();
  std::vector<std::int64_t> rows(ordered_dofs_.size());
  for (std::size_t i = 0; i < ordered_dofs_.size(); ++i) {
    rows[i] = ordered_dofs_[i]->equation_id;
    ordered_dofs_[i]->equation_id = static_cast<std::int64_t>(i);
  }
  // Every rank's count, exact in doubles.
  std::vector<double> counts(static_cast<std::size_t>(communicator_->Size()), 0.0);
  counts[static_cast<std::size_t>(communicator_->Rank())] = static_cast<double>(owned);
  communicator_->SumToAll(counts.data(), counts.size());
  std::vector<std::int64_t> rows_per_rank(counts.begin(), counts.end());
  partition_ = RowPartition::FromCounts(rows_per_rank, communicator_->Rank(), std::move(rows));
  n_assembled_ = dofs_.size();
  n_system_ = dofs_.size();
}

void BuilderAndSolver::UpdateGhosts(Vector& v) const {
  // DistributedDofNumbering sees the DoFs in the order of dofs_.
  std::vector<double> values(dofs_.size());
  for (std::size_t i = 0; i < dofs_.size(); ++i) values[i] = v[dofs_[i]->equation_id];
  numbering_->UpdateGhosts(values);
  for (std::size_t i = 0; i < dofs_.size(); ++i) v[dofs_[i]->equation_id] = values[i];
}

double BuilderAndSolver::Norm(const Vector& v) const {
  if (!numbering_) return v.norm();
  std::vector<double> sum{v.head(static_cast<Eigen::Index>(owned_dofs_.size())).squaredNorm()};
  communicator_->SumToAll(sum.data(), 1);
  return std::sqrt(sum[0]);
}

// Constraints -----------------------------------------------------------------------------------

void BuilderAndSolver::AddConstraint(std::shared_ptr<const MasterSlaveConstraint> constraint) {
  added_constraints_.push_back(constraint);
  constraints_.push_back(std::move(constraint));
  constraints_changed_ = true;
}

void BuilderAndSolver::ClearConstraints() {
  added_constraints_.clear();
  constraints_.clear();
  constraints_changed_ = true;
}

void BuilderAndSolver::SetResidualCombination(std::vector<ResidualTerm> terms, std::vector<ResidualTerm> stiffness) {
  combination_ = std::move(terms);
  combination_stiffness_ = std::move(stiffness);
}

void BuilderAndSolver::BuildCombinationMatrix() {
  std::vector<std::pair<int, int>> structure;
  const auto n = static_cast<std::int64_t>(n_assembled_);
  const auto matrix = [&](const std::vector<ResidualTerm>& terms, SparseMatrix& out) {
    std::vector<Eigen::Triplet<double, int>> entries;
    const auto first = static_cast<std::ptrdiff_t>(structure.size());
    for (const ResidualTerm& term : terms) {
      if (term.to->equation_id < 0 || term.from->equation_id < 0 ||
          term.to->equation_id >= static_cast<std::int64_t>(dofs_.size()) ||
          term.from->equation_id >= static_cast<std::int64_t>(dofs_.size()))
        throw Error(Concat("residual combination: ", DofName(*term.to), " <- ", DofName(*term.from),
                           " is outside the DoF set"));
      // A fixed DoF without a row (elimination) has no matrix entry; its residual still combines.
      if (term.to->equation_id >= n || term.from->equation_id >= n) continue;
      entries.emplace_back(static_cast<int>(term.to->equation_id), static_cast<int>(term.from->equation_id),
                           term.weight);
      structure.emplace_back(static_cast<int>(term.to->equation_id), static_cast<int>(term.from->equation_id));
    }
    std::sort(structure.begin() + first, structure.end());
    out = SparseMatrix(static_cast<Eigen::Index>(n_assembled_), static_cast<Eigen::Index>(n_assembled_));
    out.setFromTriplets(entries.begin(), entries.end());
    out.makeCompressed();
  };
  matrix(combination_, C_);
  structure.emplace_back(-1, -1);  // separates the two structures
  matrix(combination_stiffness_, S_);
  if (structure != C_structure_) {
    C_structure_ = std::move(structure);
    ++combination_version_;
  }
}

// Pattern ---------------------------------------------------------------------------------------

void BuilderAndSolver::PrepareBuild() {
  // T^T K T and T^T (r - K g) would mix the ranks' shares of K with the whole residual.
  if (communicator_ && !constraints_.empty())
    throw NotImplementedError(Concat("master-slave constraints (", constraints_.size(),
                                     ", e.g. from impose_rigid_movement_process) in a run on ", communicator_->Size(),
                                     " processes: run them on one process"));
  if (!numbered_ || constraints_changed_ || NumberingIsStale()) SetUpSystem();
  for (const auto& [slave, c] : slave_of_)
    if (slave->fixed)
      throw InputError(Concat("master-slave constraint ", c->Id(), ": its slave ", DofName(*slave),
                              " is fixed; fix the masters instead"));
}

void BuilderAndSolver::BuildPattern(ModelPart& model_part) {
  ScopedTimer timer(timings_.sparsity);
  const int n = static_cast<int>(n_assembled_);
  // Rows [first, first + rows) of the system: all of them, or this rank's (class comment).
  const auto first = static_cast<int>(FirstRow());
  const int rows = communicator_ ? static_cast<int>(partition_.LocalRows()) : n;
  const ProcessInfo& info = model_part.GetProcessInfo();
  std::vector<std::vector<int>> columns(static_cast<std::size_t>(n));
  for (int i = 0; i < rows; ++i) columns[static_cast<std::size_t>(first + i)].push_back(i);  // diagonal always present
  std::vector<omp_lock_t> locks(static_cast<std::size_t>(n));
  for (auto& l : locks) omp_init_lock(&l);
  ForEachActiveEntity(model_part, [&](Entity& e) {
    static thread_local EquationIdVectorType ids;
    e.EquationIdVector(ids, info);
    for (const auto J : ids) {
      if (J < 0 || J >= n) continue;
      auto& column = columns[static_cast<std::size_t>(J)];
      omp_set_lock(&locks[static_cast<std::size_t>(J)]);
      for (const auto I : ids) {
        const auto row = static_cast<int>(I) - first;
        if (I < 0 || row < 0 || row >= rows) continue;
        auto pos = std::lower_bound(column.begin(), column.end(), row);
        if (pos == column.end() || *pos != row) column.insert(pos, row);
      }
      omp_unset_lock(&locks[static_cast<std::size_t>(J)]);
    }
  });
  for (auto& l : locks) omp_destroy_lock(&l);

  SparseMatrix& target = constraints_.empty() ? A_ : K_;
  std::size_t nnz = 0;
  for (const auto& c : columns) nnz += c.size();
  target = SparseMatrix(rows, n);
  target.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = target.outerIndexPtr();
  int* inner = target.innerIndexPtr();
  outer[0] = 0;
  for (int j = 0; j < n; ++j) {
    const auto& c = columns[static_cast<std::size_t>(j)];
    std::copy(c.begin(), c.end(), inner + outer[j]);
    outer[j + 1] = outer[j] + static_cast<int>(c.size());
  }
  std::fill(target.valuePtr(), target.valuePtr() + nnz, 0.0);
  if (!constraints_.empty()) BuildConstraintMatrix();
  ++pattern_builds_;
  ++pattern_version_;
  pattern_valid_ = true;
  if (echo_level_ >= 2) Logger::Detail(Concat(Name(), " builder: sparsity pattern with ", nnz, " entries"));
}

void BuilderAndSolver::BuildConstraintMatrix() {
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(n_assembled_ + 4 * slave_of_.size());
  for (std::size_t i = 0; i < n_assembled_; ++i) {
    const Dof* dof = dofs_by_equation_[i];
    auto it = slave_of_.find(dof);
    if (it == slave_of_.end()) {
      entries.emplace_back(static_cast<int>(i), static_cast<int>(i), 1.0);
      continue;
    }
    const MasterSlaveConstraint& c = *it->second;
    for (std::size_t k = 0; k < c.Masters().size(); ++k) {
      const auto m = c.Masters()[k]->equation_id;
      if (m < static_cast<std::int64_t>(n_system_))  // fixed masters (elimination) have no unknown
        entries.emplace_back(static_cast<int>(i), static_cast<int>(m), c.Weights()[k]);
    }
  }
  T_ = SparseMatrix(static_cast<Eigen::Index>(n_assembled_), static_cast<Eigen::Index>(n_system_));
  T_.setFromTriplets(entries.begin(), entries.end());
  T_.makeCompressed();
}

// Assembly --------------------------------------------------------------------------------------

bool BuilderAndSolver::ElementMatrixIsConstant(const Scheme& scheme, const ModelPart& model_part) const {
  if (!scheme.PassesEntityLeftHandSide()) return false;
  const auto& elements = model_part.Elements();
  return std::all_of(elements.begin(), elements.end(),
                     [](const Element* e) { return !e->IsActive() || e->HasConstantLeftHandSide(); });
}

// out += sign * K_e u, with K_e the kept element matrix (on the pattern of `target`, whose row i
// is equation FirstRow() + i) and u the current DoF values; used only when every DoF has a matrix
// row (n_assembled_ == all).
void BuilderAndSolver::AddElementMatrixProduct(const SparseMatrix& target, double sign, Vector& out) {
  values_.resize(static_cast<Eigen::Index>(dofs_.size()));
  for (const Dof* dof : dofs_) values_[dof->equation_id] = dof->Value();
  const int* outer = target.outerIndexPtr();
  const int* inner = target.innerIndexPtr();
  const double* k = element_matrix_.data();
  double* rows = out.data() + FirstRow();
  for (Eigen::Index j = 0; j < target.outerSize(); ++j) {
    const double uj = sign * values_[j];
    if (uj == 0.0) continue;
    for (int p = outer[j]; p < outer[j + 1]; ++p) rows[inner[p]] += k[p] * uj;
  }
}

void BuilderAndSolver::Assemble(Scheme& scheme, ModelPart& model_part, Mode mode) {
  const bool lhs = mode != Mode::kRhs;
  const bool rhs = mode != Mode::kLhs;
  SparseMatrix& target = constraints_.empty() ? A_ : K_;
  const auto nnz = static_cast<std::size_t>(target.nonZeros());
  const bool cached =
      element_matrix_valid_ && element_matrix_pattern_ == pattern_version_ && element_matrix_.size() == nnz;
  const bool reuse = lhs && cached;
  const bool affine_rhs = rhs && cached && element_force_valid_;
  if (reuse)
    std::copy(element_matrix_.begin(), element_matrix_.end(), target.valuePtr());
  else if (lhs)
    std::fill(target.valuePtr(), target.valuePtr() + nnz, 0.0);
  if (rhs) rhs_raw_.setZero();
  const int* outer = target.outerIndexPtr();
  const int* inner = target.innerIndexPtr();
  double* values = target.valuePtr();
  double* b = rhs_raw_.data();
  const std::int64_t n_matrix = static_cast<std::int64_t>(n_assembled_);
  const std::int64_t n_all = static_cast<std::int64_t>(dofs_.size());
  // The matrix's rows [first, first + rows) and the residual rows this rank adds (all when serial).
  const std::int64_t first = FirstRow();
  const std::int64_t rows = communicator_ ? partition_.LocalRows() : n_matrix;
  const char* owned = communicator_ ? owned_.data() : nullptr;
  const ProcessInfo& info = model_part.GetProcessInfo();

  // Elements and conditions keep separate per-thread buffers (one instantiation each): their
  // local systems usually differ in size and a shared buffer would be reallocated at each switch.
  // Scatter adds are atomic only when threads share the loop: an atomic add of a double is a
  // compare-and-swap loop, several times the cost of the plain add of a serial run.
  auto assemble = [&](auto& e, Mode entity_mode, auto concurrent) {
    if (!e.IsActive() || (communicator_ && !TouchesOwnRows(e, info))) return;
    const bool with_lhs = entity_mode != Mode::kRhs;
    const bool with_rhs = entity_mode != Mode::kLhs;
    static thread_local Matrix local_lhs;
    static thread_local Vector local_rhs;
    static thread_local EquationIdVectorType ids;
    if (entity_mode == Mode::kBoth)
      scheme.CalculateSystemContributions(e, local_lhs, local_rhs, ids, info);
    else if (with_lhs)
      scheme.CalculateLHSContribution(e, local_lhs, ids, info);
    else
      scheme.CalculateRHSContribution(e, local_rhs, ids, info);
    const auto n = static_cast<Eigen::Index>(ids.size());
    if ((with_lhs && (local_lhs.rows() != n || local_lhs.cols() != n)) || (with_rhs && local_rhs.size() != n))
      throw Error(Concat(e.Info(), " ", e.Id(), ": local system of size ",
                         with_lhs ? local_lhs.rows() : local_rhs.size(), " for ", n, " equation ids"));
    for (const auto id : ids)
      if (id < 0 || id >= n_all)
        throw Error(Concat(e.Info(), " ", e.Id(),
                           " has a DoF outside the DoF set: call SetUpDofSet after "
                           "changing elements, conditions or their DoFs"));
    auto add = [](double& target, double value) {
      if constexpr (decltype(concurrent)::value) {
#pragma omp atomic
        target += value;
      } else {
        target += value;
      }
    };
    if (with_rhs) {
      for (Eigen::Index i = 0; i < n; ++i) {
        const auto I = ids[static_cast<std::size_t>(i)];
        if (!owned || owned[I]) add(b[I], local_rhs[i]);
      }
    }
    if (!with_lhs) return;
    for (Eigen::Index j = 0; j < n; ++j) {
      const auto J = ids[static_cast<std::size_t>(j)];
      if (J >= n_matrix) continue;
      const int* begin = inner + outer[J];
      const int* end = inner + outer[J + 1];
      for (Eigen::Index i = 0; i < n; ++i) {
        const auto row = ids[static_cast<std::size_t>(i)] - first;
        if (row < 0 || row >= rows) continue;
        const int* pos = std::lower_bound(begin, end, static_cast<int>(row));
        assert(pos != end && *pos == row);
        add(values[pos - inner], local_lhs(i, j));
      }
    }
  };
  // Mirrors the condition under which ParallelForEachEntity starts a thread team.
  auto shared = [](const auto& items) {
    return omp_get_max_threads() > 1 && static_cast<long>(items.size()) >= kMinParallelEntities;
  };
  auto assemble_all = [&](auto& items, Mode items_mode) {
    using Item = std::remove_reference_t<decltype(*items[0])>;
    if (shared(items))
      ParallelForEachEntity(items, [&](Item& e) { assemble(e, items_mode, std::true_type{}); });
    else
      ParallelForEachEntity(items, [&](Item& e) { assemble(e, items_mode, std::false_type{}); });
  };
  {
    ScopedTimer timer(timings_.elements);
    if (reuse) ++element_matrix_reuses_;
    if (affine_rhs) {
      AddElementMatrixProduct(target, -1.0, rhs_raw_);
      rhs_raw_ += element_force_;
    }
    if (!reuse && lhs) {
      assemble_all(model_part.Elements(), mode);
      if (ElementMatrixIsConstant(scheme, model_part)) {
        element_matrix_.assign(target.valuePtr(), target.valuePtr() + nnz);
        element_matrix_pattern_ = pattern_version_;
        element_matrix_valid_ = true;
        // rhs_raw_ holds the element residual f - K u only: keep f = rhs_raw_ + K u.
        element_force_valid_ = rhs && n_matrix == n_all;
        if (element_force_valid_) {
          element_force_ = rhs_raw_;
          AddElementMatrixProduct(target, 1.0, element_force_);
        }
      }
    } else if (rhs && !affine_rhs) {
      assemble_all(model_part.Elements(), Mode::kRhs);
    }
  }
  ScopedTimer timer(timings_.conditions);
  assemble_all(model_part.Conditions(), mode);
}

bool BuilderAndSolver::TouchesOwnRows(const Entity& entity, const ProcessInfo& info) const {
  static thread_local EquationIdVectorType ids;
  entity.EquationIdVector(ids, info);
  if (ids.empty()) return partition_.Rank() == 0;
  return std::any_of(ids.begin(), ids.end(), [&](auto id) {
    return id >= 0 && static_cast<std::size_t>(id) < owned_.size() && owned_[static_cast<std::size_t>(id)];
  });
}

void BuilderAndSolver::SumResidualOverRanks() {
  // A piece's rows are complete on their owners.
  if (communicator_ && !numbering_) communicator_->SumToAll(rhs_raw_.data(), static_cast<std::size_t>(rhs_raw_.size()));
}

void BuilderAndSolver::FinishResidual() {
  rhs_effective_ = rhs_raw_;
  if (!combination_.empty() && constraints_.empty())
    throw Error(Concat(Name(), " builder: a residual combination needs master-slave constraints"));
  if (!combination_.empty()) BuildCombinationMatrix();
  for (const ResidualTerm& term : combination_)
    rhs_effective_[term.to->equation_id] += term.weight * rhs_raw_[term.from->equation_id];
  for (const auto& c : constraints_) {
    if (!c->IsActive()) continue;
    const auto s = c->Slave().equation_id;
    for (std::size_t k = 0; k < c->Masters().size(); ++k)
      rhs_effective_[c->Masters()[k]->equation_id] += c->Weights()[k] * rhs_effective_[s];
    rhs_effective_[s] = 0.0;
  }
  residual_ = rhs_effective_;
  for (const Dof* d : dofs_)
    if (d->fixed) residual_[d->equation_id] = 0.0;
}

void BuilderAndSolver::ReduceSystem(Mode mode) {
  const bool lhs = mode != Mode::kRhs;
  const bool rhs = mode != Mode::kLhs;
  if (constraints_.empty()) {
    if (rhs) b_system_ = residual_.head(static_cast<Eigen::Index>(n_system_));
    return;
  }
  g_.setZero();
  for (const auto& c : constraints_)
    if (c->IsActive()) g_[c->Slave().equation_id] = c->Violation();
  if (!combination_.empty()) BuildCombinationMatrix();
  const bool combined = !combination_.empty();
  if (lhs) {
    SparseMatrix KT = K_ * T_;
    if (combined) KT = KT + C_ * KT + S_ * T_;
    A_ = T_.transpose() * KT;
    A_.makeCompressed();
  }
  if (rhs) {
    Vector r = rhs_raw_.head(static_cast<Eigen::Index>(n_assembled_));
    r.noalias() -= K_ * g_;
    if (combined) {
      const Vector combined_part = C_ * r;
      r += combined_part;
    }
    b_system_.noalias() = T_.transpose() * r;
  }
}

void BuilderAndSolver::Build(Scheme& scheme, ModelPart& model_part) {
  PrepareBuild();
  if (!pattern_valid_) BuildPattern(model_part);
  ScopedTimer timer(timings_.build);
  Assemble(scheme, model_part, Mode::kBoth);
  SumResidualOverRanks();
  FinishResidual();
  ReduceSystem(Mode::kBoth);
  ApplyDirichletConditions(true, true);
  CheckEmptyColumns();
}

void BuilderAndSolver::BuildLHS(Scheme& scheme, ModelPart& model_part) {
  PrepareBuild();
  if (!pattern_valid_) BuildPattern(model_part);
  ScopedTimer timer(timings_.build);
  Assemble(scheme, model_part, Mode::kLhs);
  ReduceSystem(Mode::kLhs);
  ApplyDirichletConditions(true, false);
  CheckEmptyColumns();
}

void BuilderAndSolver::BuildRHS(Scheme& scheme, ModelPart& model_part) {
  PrepareBuild();
  ScopedTimer timer(timings_.build);
  Assemble(scheme, model_part, Mode::kRhs);
  SumResidualOverRanks();
  FinishResidual();
  if (pattern_valid_ || constraints_.empty()) {
    ReduceSystem(Mode::kRhs);
    ApplyDirichletConditions(false, true);
  }
}

// Singular systems ------------------------------------------------------------------------------

void BuilderAndSolver::CheckEmptyColumns() const {
  std::vector<const Dof*> empty;
  const int* outer = A_.outerIndexPtr();
  const double* values = A_.valuePtr();
  if (numbering_) {
    // The piece's columns: a ghost's column may be filled here only; its owner names it.
    std::vector<double> filled(dofs_.size(), 0.0);
    for (Eigen::Index j = 0; j < A_.outerSize(); ++j)
      for (int p = outer[j]; p < outer[j + 1] && filled[static_cast<std::size_t>(j)] == 0.0; ++p)
        if (values[p] != 0.0) filled[static_cast<std::size_t>(j)] = 1.0;
    std::vector<double> by_dof(dofs_.size());
    for (std::size_t i = 0; i < dofs_.size(); ++i) by_dof[i] = filled[static_cast<std::size_t>(dofs_[i]->equation_id)];
    numbering_->AddGhostsToOwners(by_dof);
    for (std::size_t i = 0; i < dofs_.size(); ++i)
      if (by_dof[i] == 0.0 && owned_[static_cast<std::size_t>(dofs_[i]->equation_id)]) empty.push_back(dofs_[i]);
    // Every rank stops when one finds an empty column.
    std::vector<double> count{static_cast<double>(empty.size())};
    communicator_->SumToAll(count.data(), 1);
    if (count[0] > 0.0 && empty.empty())
      throw SolutionError(Concat("singular system: no stiffness for ", count[0],
                                 " DoFs of nodes other ranks own (their owners name them)"));
  } else if (communicator_) {
    // A column empty in this rank's share may be filled by another's: count the ranks filling it.
    std::vector<double> filled(static_cast<std::size_t>(A_.outerSize()), 0.0);
    for (Eigen::Index j = 0; j < A_.outerSize(); ++j)
      for (int p = outer[j]; p < outer[j + 1]; ++p)
        if (values[p] != 0.0) {
          filled[static_cast<std::size_t>(j)] = 1.0;
          break;
        }
    communicator_->SumToAll(filled.data(), filled.size());
    for (std::size_t j = 0; j < filled.size(); ++j)
      if (filled[j] == 0.0) empty.push_back(dofs_by_equation_[j]);
  } else {
    // Kept apart from the loop above: a serial build allocates nothing after the first
    // (AssemblyAllocations.LaterBuildsAllocateNothingOnOneThread).
    for (Eigen::Index j = 0; j < A_.outerSize(); ++j) {
      bool any = false;
      for (int p = outer[j]; p < outer[j + 1] && !any; ++p) any = values[p] != 0.0;
      if (!any) empty.push_back(dofs_by_equation_[static_cast<std::size_t>(j)]);
    }
  }
  if (!empty.empty()) ThrowSingular(empty, "");
}

void BuilderAndSolver::ThrowSingular(const std::vector<const Dof*>& dofs, const std::string& detail) const {
  constexpr std::size_t kMaxListed = 10;
  // Group the first DoFs by variable, keeping the order in which the variables appear.
  std::vector<std::pair<std::string, std::vector<IndexType>>> groups;
  for (std::size_t i = 0; i < std::min(dofs.size(), kMaxListed); ++i) {
    const std::string& name = dofs[i]->variable->Name();
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == name; });
    if (it == groups.end()) {
      groups.push_back({name, {}});
      it = groups.end() - 1;
    }
    it->second.push_back(dofs[i]->node->Id());
  }
  std::string list;
  for (const auto& [name, nodes] : groups) {
    if (!list.empty()) list += "; ";
    list += name + (nodes.size() == 1 ? " of node " : " of nodes ");
    for (std::size_t k = 0; k < nodes.size(); ++k) list += (k ? ", " : "") + std::to_string(nodes[k]);
  }
  if (dofs.size() > kMaxListed) list += Concat(" and ", dofs.size() - kMaxListed, " more DoFs");
  const bool one = dofs.size() == 1;
  std::string message = detail.empty() ? Concat("singular system: no stiffness for ", list)
                                       : Concat("singular system: zero pivot at ", list);
  message += one ? " (is it constrained?)" : " (are they constrained?)";
  if (!detail.empty()) message += Concat("; linear solver: ", detail);
  std::vector<SingularSystemError::DofName> names;
  names.reserve(dofs.size());
  for (const Dof* dof : dofs) names.emplace_back(dof->node->Id(), dof->variable->Name());
  throw SingularSystemError(message, std::move(names));
}

// Solve -----------------------------------------------------------------------------------------

void BuilderAndSolver::SolveSystem() {
  if (!linear_solver_) throw Error(Concat(Name(), " builder: no linear solver was given"));
  {
    ScopedTimer timer(timings_.solve);
    SolveClocks::Scope clock(SolveClocks::Process().phase);
    if (solver_pattern_version_ != pattern_version_ || solver_combination_version_ != combination_version_) {
      if (communicator_) linear_solver_->SetRowPartition(partition_);
      linear_solver_->Initialize(A_);
      solver_pattern_version_ = pattern_version_;
      solver_combination_version_ = combination_version_;
    }
    // System row i is the equation of dofs_by_equation_[i]. With master-slave constraints the
    // row of a master also holds its slaves' rows (T^T K T): a solver that splits the system by
    // DoF (MixedULM) must check the blocks it relies on, and solves in full where they fail.
    if (linear_solver_->AdditionalPhysicalDataIsNeeded()) linear_solver_->ProvideAdditionalData(A_, dofs_by_equation_);
    x_system_.setZero(static_cast<Eigen::Index>(n_system_));
    try {
      linear_solver_->Solve(A_, x_system_, b_system_);
    } catch (const SingularMatrixError& e) {
      const long eq = e.Equation();
      if (eq >= 0 && static_cast<std::size_t>(eq) < n_system_) ThrowSingular({dofs_by_equation_[eq]}, e.what());
      throw SolutionError(Concat("singular system; linear solver: ", e.what()));
    }
  }
  // A piece's solver returns its owned rows only; the ghosts' come from their owners below.
  const auto solved = static_cast<Eigen::Index>(piece_owners_ ? owned_dofs_.size() : n_system_);
  if (!x_system_.head(solved).allFinite())
    throw SolutionError(
        Concat("linear solver ", linear_solver_->Name(), " returned non-finite values for ", n_system_, " unknowns"));
  const auto n_matrix = static_cast<Eigen::Index>(n_assembled_);
  if (constraints_.empty()) {
    dx_.head(n_matrix) = x_system_;
  } else {
    dx_.head(n_matrix).noalias() = T_ * x_system_;
    dx_.head(n_matrix) += g_;
  }
  dx_.tail(dx_.size() - n_matrix).setZero();
  for (const Dof* d : dofs_)
    if (d->fixed) dx_[d->equation_id] = 0.0;
  if (numbering_) UpdateGhosts(dx_);
}

void BuilderAndSolver::BuildAndSolve(Scheme& scheme, ModelPart& model_part) {
  Build(scheme, model_part);
  SolveSystem();
}

void BuilderAndSolver::BuildRHSAndSolve(Scheme& scheme, ModelPart& model_part) {
  const bool had_pattern = pattern_valid_;
  BuildRHS(scheme, model_part);
  if (!had_pattern || !pattern_valid_) {
    Build(scheme, model_part);  // no matrix to reuse yet
  }
  SolveSystem();
}

// Reactions -------------------------------------------------------------------------------------

void BuilderAndSolver::CalculateReactions(Scheme& scheme, ModelPart& model_part) {
  BuildRHS(scheme, model_part);
  WriteReactions();
}

void BuilderAndSolver::WriteReactions() {
  // A ghost's row is complete on its owner only.
  if (numbering_) UpdateGhosts(rhs_effective_);
  for (const Dof* d : dofs_)
    if (d->fixed && d->HasReaction()) d->ReactionValue() = -rhs_effective_[d->equation_id];
}

void BuilderAndSolver::ResetLinearSolver() {
  if (linear_solver_) linear_solver_->Clear();
  solver_pattern_version_ = -1;
}

void BuilderAndSolver::Clear() {
  dofs_.clear();
  dofs_by_equation_.clear();
  slave_of_.clear();
  A_ = SparseMatrix();
  K_ = SparseMatrix();
  T_ = SparseMatrix();
  numbered_ = false;
  pattern_valid_ = false;
  solver_pattern_version_ = -1;
  ordered_dofs_.clear();
  owned_.clear();
  node_partition_ = NodePartition();
  piece_owners_ = nullptr;
  numbering_.reset();
  owned_dofs_.clear();
  element_matrix_.clear();
  element_matrix_.shrink_to_fit();
  element_matrix_valid_ = false;
  element_force_valid_ = false;
  if (linear_solver_) linear_solver_->Clear();
}

}  // namespace mc
