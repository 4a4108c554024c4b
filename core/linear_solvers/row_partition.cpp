// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/row_partition.h"

#include <algorithm>

#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {

RowPartition RowPartition::FromOwners(const std::vector<int>& owner_of_row, int size, int rank) {
  if (size < 1 || rank < 0 || rank >= size) throw Error(Concat("row partition: rank ", rank, " of ", size));
  RowPartition partition;
  partition.rank_ = rank;
  const auto rows = static_cast<std::int64_t>(owner_of_row.size());
  partition.starts_.assign(static_cast<std::size_t>(size) + 1, rows);
  partition.starts_[0] = 0;
  int current = 0;
  for (std::int64_t i = 0; i < rows; ++i) {
    const int owner = owner_of_row[static_cast<std::size_t>(i)];
    if (owner < current || owner >= size)
      throw Error(Concat("row partition: row ", i, " owned by rank ", owner, " after rows of rank ", current, " (",
                         size, " ranks): the rows must be numbered rank by rank"));
    for (; current < owner; ++current) partition.starts_[static_cast<std::size_t>(current) + 1] = i;
  }
  return partition;
}

RowPartition RowPartition::FromCounts(const std::vector<std::int64_t>& rows_per_rank, int rank,
                                      std::vector<std::int64_t> column_rows) {
  const auto size = static_cast<int>(rows_per_rank.size());
  if (size < 1 || rank < 0 || rank >= size) throw Error(Concat("row partition: rank ", rank, " of ", size));
  RowPartition partition;
  partition.rank_ = rank;
  partition.starts_.assign(1, 0);
  for (const std::int64_t rows : rows_per_rank) partition.starts_.push_back(partition.starts_.back() + rows);
  const std::int64_t own = partition.LocalRows();
  if (static_cast<std::int64_t>(column_rows.size()) < own)
    throw Error(Concat("row partition: ", column_rows.size(), " columns for the ", own, " rows of rank ", rank));
  for (std::int64_t c = 0; c < own; ++c)
    if (column_rows[static_cast<std::size_t>(c)] != partition.Begin() + c)
      throw Error(Concat("row partition: column ", c, " of rank ", rank, " is row ",
                         column_rows[static_cast<std::size_t>(c)], ", not its own row ", partition.Begin() + c));
  partition.column_rows_ = std::move(column_rows);
  return partition;
}

int RowPartition::Owner(std::int64_t row) const {
  // The last start not after `row`; empty blocks (ranks without nodes) own nothing.
  const auto after = std::upper_bound(starts_.begin(), starts_.end() - 1, row);
  return std::clamp(static_cast<int>(after - starts_.begin()) - 1, 0, Size() - 1);
}

}  // namespace mc
