// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/direct_solver.h"

#include <cassert>
#include <unordered_map>

#include "core/model/dof.h"
#include "core/model/node.h"

#include "core/linear_solvers/solve_clocks.h"

namespace mc {

void DirectSolver::Initialize(const SparseMatrix& A) {
  Clear();
  if (A.rows() != A.cols())
    throw SolutionError(Concat(library_, ": matrix is ", A.rows(), "x", A.cols(), ", not square"));
  SolveClocks::Scope clock(SolveClocks::Process().analysis);
  const SparseMatrix& M = CompressedView(A, compressed_);
  Analyze(M);
  pattern_.Assign(M);
  ++symbolic_count_;
}

void DirectSolver::Solve(const SparseMatrix& A, Vector& x, const Vector& b) {
  assert(b.size() == A.rows());
  FactorizeNumeric(A);
  SolveClocks::Scope clock(SolveClocks::Process().direct_substitution);
  Substitute(x, b);
}

void DirectSolver::FactorizeNumeric(const SparseMatrix& A) {
  SolveClocks& clocks = SolveClocks::Process();
  const SparseMatrix* M = nullptr;
  bool analysed = false;
  {
    SolveClocks::Scope clock(clocks.pattern_check);
    M = &CompressedView(A, compressed_);
    analysed = !pattern_.Empty() && pattern_.Matches(*M);
  }
  if (!analysed) {
    std::vector<long> new_of_old;
    if (has_factors_ && MapEquations(M->rows(), new_of_old)) KeepOrderingForNextAnalysis(new_of_old);
    Initialize(*M);
    if (AnalysisKeptOrdering()) ++kept_orderings_;
  }
  has_factors_ = false;
  {
    SolveClocks::Scope clock(clocks.factorization);
    Factorize(*M);
  }
  has_factors_ = true;
  factors_size_ = M->rows();
  factored_equations_ = equations_;
  ++numeric_count_;
}

void DirectSolver::ProvideAdditionalData(const SparseMatrix& A, const std::vector<Dof*>& dof_of_equation) {
  equations_.clear();
  if (static_cast<Eigen::Index>(dof_of_equation.size()) < A.rows()) return;  // not a DoF per row
  equations_.reserve(static_cast<std::size_t>(A.rows()));
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    equations_.emplace_back(static_cast<long>(dof_of_equation[i]->node->Id()), dof_of_equation[i]->variable);
}

bool DirectSolver::MapEquations(long rows, std::vector<long>& new_of_old) const {
  new_of_old.clear();
  const bool known =
      static_cast<long>(equations_.size()) == rows && static_cast<long>(factored_equations_.size()) == factors_size_;
  if (!known || equations_ == factored_equations_) return factors_size_ == rows;
  struct KeyHash {
    std::size_t operator()(const EquationKey& k) const noexcept {
      return std::hash<long>()(k.first) * 31 + std::hash<const void*>()(k.second);
    }
  };
  std::unordered_map<EquationKey, long, KeyHash> new_equation;
  new_equation.reserve(equations_.size());
  for (std::size_t i = 0; i < equations_.size(); ++i) new_equation.emplace(equations_[i], static_cast<long>(i));
  new_of_old.resize(factored_equations_.size());
  for (std::size_t i = 0; i < factored_equations_.size(); ++i) {
    const auto found = new_equation.find(factored_equations_[i]);
    new_of_old[i] = found == new_equation.end() ? -1 : found->second;
  }
  return true;
}

void DirectSolver::SubstituteFactors(Vector& x, const Vector& b) {
  if (!has_factors_) throw Error(Concat(library_, ": substitution requested without a factorization"));
  assert(b.size() == factors_size_);
  Substitute(x, b);
}

void DirectSolver::Clear() {
  Release();
  pattern_.Clear();
  has_factors_ = false;
}

}  // namespace mc
