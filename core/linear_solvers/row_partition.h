// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <vector>

namespace mc {

/// Which rank owns which rows of a distributed system: contiguous blocks of the equation ids,
/// rank r owning [Begin(r), End(r)), as PETSc's MPIAIJ matrices store them. The builder numbers
/// the DoFs rank by rank (the ranks' nodes from a NodePartition), so a block of rows is the DoFs of
/// one rank's nodes, and a node's DoFs (and the field split's blocks) stay on one rank.
class RowPartition {
 public:
  RowPartition() = default;
  /// The partition of `owner_of_row.size()` rows where row i belongs to rank owner_of_row[i];
  /// the owners must not decrease (each rank's rows one block, in rank order). This rank is `rank`.
  static RowPartition FromOwners(const std::vector<int>& owner_of_row, int size, int rank);
  /// Rank r owning the `rows_per_rank[r]` rows after those of the ranks before it, for a matrix
  /// whose columns are this rank's DoFs (a model cut to a piece per rank): column c is row
  /// `column_rows[c]` of the whole system, the first LocalRows() of them this rank's own rows in order.
  static RowPartition FromCounts(const std::vector<std::int64_t>& rows_per_rank, int rank,
                                 std::vector<std::int64_t> column_rows);

  int Rank() const noexcept { return rank_; }
  int Size() const noexcept { return static_cast<int>(starts_.size()) - 1; }
  std::int64_t Rows() const noexcept { return starts_.empty() ? 0 : starts_.back(); }
  std::int64_t Begin(int rank) const { return starts_[static_cast<std::size_t>(rank)]; }
  std::int64_t End(int rank) const { return starts_[static_cast<std::size_t>(rank) + 1]; }
  std::int64_t Begin() const { return Begin(rank_); }
  std::int64_t End() const { return End(rank_); }
  /// Rows this rank owns.
  std::int64_t LocalRows() const { return End() - Begin(); }
  /// The rank that owns `row` (in [0, Rows())).
  int Owner(std::int64_t row) const;
  bool Owns(std::int64_t row) const { return Owner(row) == rank_; }
  /// Empty: the matrix has a column per row of the whole system. Else the matrix's column c is
  /// the system's row ColumnRows()[c] (FromCounts), and so is entry c of the vectors passed with it.
  const std::vector<std::int64_t>& ColumnRows() const noexcept { return column_rows_; }
  bool operator==(const RowPartition& other) const = default;

 private:
  std::vector<std::int64_t> starts_;  ///< Size() + 1 entries, 0 first, Rows() last
  int rank_ = 0;
  std::vector<std::int64_t> column_rows_;
};

}  // namespace mc
