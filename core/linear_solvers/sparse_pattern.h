// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "core/linear_solvers/sparse_types.h"

namespace mc {

/// A copy of the compressed index arrays of a matrix. Direct solvers keep one to notice when
/// `Solve` receives a pattern other than the analysed one and redo the symbolic phase instead
/// of factorizing with a stale analysis.
class SparsePattern {
 public:
  /// Requires a compressed matrix.
  void Assign(const SparseMatrix& A);
  bool Matches(const SparseMatrix& A) const;
  void Clear();
  bool Empty() const noexcept { return outer_.empty(); }

 private:
  long rows_ = 0;
  std::vector<int> outer_;
  std::vector<int> inner_;
};

/// `A` itself when compressed, else a compressed copy kept in `buffer` (the C solvers read the
/// compressed arrays directly).
const SparseMatrix& CompressedView(const SparseMatrix& A, SparseMatrix& buffer);

}  // namespace mc
