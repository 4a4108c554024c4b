// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/block_builder_and_solver.h"
#include "core/model/parallel_utilities.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/model/master_slave_constraint.h"

namespace mc {

void BlockBuilderAndSolver::NumberDofs() {
  const std::vector<Dof*>& order = NumberingOrder();
  for (std::size_t i = 0; i < order.size(); ++i) order[i]->equation_id = static_cast<std::int64_t>(i);
  n_assembled_ = dofs_.size();
  n_system_ = dofs_.size();
}

void BlockBuilderAndSolver::ApplyDirichletConditions(bool lhs, bool rhs) {
  constrained_.assign(n_system_, 0);
  for (const Dof* d : dofs_)
    if (d->fixed || IsSlave(*d)) constrained_[static_cast<std::size_t>(d->equation_id)] = 1;
  if (rhs)
    for (std::size_t i = 0; i < n_system_; ++i)
      if (constrained_[i]) b_system_[static_cast<Eigen::Index>(i)] = 0.0;
  if (!lhs) return;

  if (!Constraints().empty()) {
    // T^T K T has empty slave rows and columns: give them a diagonal entry.
    SparseMatrix diagonal(A_.rows(), A_.cols());
    std::vector<Eigen::Triplet<double, int>> entries;
    for (std::size_t i = 0; i < n_system_; ++i)
      if (constrained_[i]) entries.emplace_back(static_cast<int>(i), static_cast<int>(i), 0.0);
    diagonal.setFromTriplets(entries.begin(), entries.end());
    A_ = A_ + diagonal;
    A_.makeCompressed();
  }

  // A_'s row i is equation first + i: all rows, or this rank's (BuilderAndSolver's class comment).
  const int* outer = A_.outerIndexPtr();
  const int* inner = A_.innerIndexPtr();
  double* values = A_.valuePtr();
  const long n = static_cast<long>(n_system_);
  const long first = static_cast<long>(FirstRow());
  const char* constrained_row = constrained_.data() + first;
  scale_ = 1.0;
  if (diagonal_ == DirichletDiagonal::kMaxDiagonal) {
    double largest = 0.0;
#pragma omp parallel for reduction(max : largest) if (n >= kMinParallelDofs)
    for (long j = 0; j < n; ++j) {
      if (constrained_[j]) continue;
      for (int p = outer[j]; p < outer[j + 1]; ++p)
        if (inner[p] + first == j) largest = std::max(largest, std::abs(values[p]));
    }
    if (const AssemblyCommunicator* communicator = Communicator()) {
      // Each rank saw the diagonals of its rows: the largest of the ranks' largest.
      std::vector<double> per_rank(static_cast<std::size_t>(communicator->Size()), 0.0);
      per_rank[static_cast<std::size_t>(communicator->Rank())] = largest;
      communicator->SumToAll(per_rank.data(), per_rank.size());
      largest = *std::max_element(per_rank.begin(), per_rank.end());
    }
    if (largest > 0.0) scale_ = largest;
  }
#pragma omp parallel for if (n >= kMinParallelDofs)
  for (long j = 0; j < n; ++j) {
    if (constrained_[j]) {
      for (int p = outer[j]; p < outer[j + 1]; ++p) values[p] = inner[p] + first == j ? scale_ : 0.0;
    } else {
      for (int p = outer[j]; p < outer[j + 1]; ++p)
        if (constrained_row[inner[p]]) values[p] = 0.0;
    }
  }
}

}  // namespace mc
