// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/block_builder_and_solver.h"
#include "core/model/parallel_utilities.h"

#include <cmath>

#include "core/model/master_slave_constraint.h"

namespace mc {

void BlockBuilderAndSolver::NumberDofs() {
  for (std::size_t i = 0; i < dofs_.size(); ++i) dofs_[i]->equation_id = static_cast<std::int64_t>(i);
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

  const int* outer = A_.outerIndexPtr();
  const int* inner = A_.innerIndexPtr();
  double* values = A_.valuePtr();
  const long n = static_cast<long>(n_system_);
  scale_ = 1.0;
  const AssemblyCommunicator* communicator = Communicator();
  if (diagonal_ == DirichletDiagonal::kMaxDiagonal && communicator) {
    // The diagonal is the sum of the ranks' shares: sum it before taking the largest.
    std::vector<double> diagonal(n_system_, 0.0);
    for (long j = 0; j < n; ++j) {
      if (constrained_[j]) continue;
      for (int p = outer[j]; p < outer[j + 1]; ++p)
        if (inner[p] == j) diagonal[static_cast<std::size_t>(j)] = values[p];
    }
    communicator->SumToAll(diagonal.data(), diagonal.size());
    double largest = 0.0;
    for (const double d : diagonal) largest = std::max(largest, std::abs(d));
    if (largest > 0.0) scale_ = largest;
  } else if (diagonal_ == DirichletDiagonal::kMaxDiagonal) {
    // Without the buffer above: a serial build allocates nothing after the first.
    double largest = 0.0;
#pragma omp parallel for reduction(max : largest) if (n >= kMinParallelDofs)
    for (long j = 0; j < n; ++j) {
      if (constrained_[j]) continue;
      for (int p = outer[j]; p < outer[j + 1]; ++p)
        if (inner[p] == j) largest = std::max(largest, std::abs(values[p]));
    }
    if (largest > 0.0) scale_ = largest;
  }
#pragma omp parallel for if (n >= kMinParallelDofs)
  for (long j = 0; j < n; ++j) {
    if (constrained_[j]) {
      // Distributed: the rank owning the row puts the diagonal, the others' shares add zero.
      const double diagonal = communicator && !Partition().Owns(j) ? 0.0 : scale_;
      for (int p = outer[j]; p < outer[j + 1]; ++p) values[p] = inner[p] == j ? diagonal : 0.0;
    } else {
      for (int p = outer[j]; p < outer[j + 1]; ++p)
        if (constrained_[inner[p]]) values[p] = 0.0;
    }
  }
}

}  // namespace mc
