// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/row_partition.h"

#include <algorithm>

#include "core/model/dof.h"
#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {

RowPartition RowPartition::AtNodes(const std::vector<Dof*>& dof_of_row, std::int64_t rows, int size, int rank) {
  if (size < 1 || rank < 0 || rank >= size) throw Error(Concat("row partition: rank ", rank, " of ", size));
  if (static_cast<std::int64_t>(dof_of_row.size()) < rows)
    throw Error(Concat("row partition: ", dof_of_row.size(), " DoFs for ", rows, " rows"));
  RowPartition partition;
  partition.rank_ = rank;
  partition.starts_.assign(static_cast<std::size_t>(size) + 1, rows);
  partition.starts_[0] = 0;
  for (int r = 1; r < size; ++r) {
    std::int64_t cut = std::max(rows * r / size, partition.starts_[static_cast<std::size_t>(r) - 1]);
    while (cut > 0 && cut < rows &&
           dof_of_row[static_cast<std::size_t>(cut)]->node == dof_of_row[static_cast<std::size_t>(cut) - 1]->node)
      ++cut;
    partition.starts_[static_cast<std::size_t>(r)] = cut;
  }
  return partition;
}

int RowPartition::Owner(std::int64_t row) const {
  // The last start not after `row`; empty blocks (more ranks than nodes) own nothing.
  const auto after = std::upper_bound(starts_.begin(), starts_.end() - 1, row);
  return std::clamp(static_cast<int>(after - starts_.begin()) - 1, 0, Size() - 1);
}

}  // namespace mc
