// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <vector>

namespace mc {

struct Dof;

/// Which rank owns which rows of a distributed system: contiguous blocks of the equation ids,
/// rank r owning [Begin(r), End(r)), as PETSc's MPIAIJ matrices store them. Equation ids follow
/// the node ids, so a block of rows is a block of nodes; the cuts fall between two nodes, so a
/// node's DoFs (and the field split's blocks) stay on one rank.
class RowPartition {
 public:
  RowPartition() = default;
  /// `rows` rows in `size` blocks of about rows / size, each cut moved forward to the next row of
  /// another node (`dof_of_row[i]` is the DoF of row i). This rank is `rank`.
  static RowPartition AtNodes(const std::vector<Dof*>& dof_of_row, std::int64_t rows, int size, int rank);

  int Rank() const noexcept { return rank_; }
  int Size() const noexcept { return static_cast<int>(starts_.size()) - 1; }
  std::int64_t Rows() const noexcept { return starts_.empty() ? 0 : starts_.back(); }
  std::int64_t Begin(int rank) const { return starts_[static_cast<std::size_t>(rank)]; }
  std::int64_t End(int rank) const { return starts_[static_cast<std::size_t>(rank) + 1]; }
  std::int64_t Begin() const { return Begin(rank_); }
  std::int64_t End() const { return End(rank_); }
  /// The rank that owns `row`; rows past the system (the fixed DoFs the elimination builder
  /// leaves out) belong to the last rank.
  int Owner(std::int64_t row) const;
  bool Owns(std::int64_t row) const { return Owner(row) == rank_; }
  bool operator==(const RowPartition& other) const = default;

 private:
  std::vector<std::int64_t> starts_;  ///< Size() + 1 entries, 0 first, Rows() last
  int rank_ = 0;
};

}  // namespace mc
