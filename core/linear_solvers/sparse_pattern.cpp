// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/sparse_pattern.h"

#include <algorithm>
#include <cassert>

namespace mc {

void SparsePattern::Assign(const SparseMatrix& A) {
  assert(A.isCompressed());
  rows_ = A.rows();
  outer_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
  inner_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
}

bool SparsePattern::Matches(const SparseMatrix& A) const {
  if (!A.isCompressed() || A.rows() != rows_ || static_cast<std::size_t>(A.outerSize()) + 1 != outer_.size() ||
      static_cast<std::size_t>(A.nonZeros()) != inner_.size()) {
    return false;
  }
  return std::equal(outer_.begin(), outer_.end(), A.outerIndexPtr()) &&
         std::equal(inner_.begin(), inner_.end(), A.innerIndexPtr());
}

void SparsePattern::Clear() {
  rows_ = 0;
  outer_.clear();
  inner_.clear();
}

const SparseMatrix& CompressedView(const SparseMatrix& A, SparseMatrix& buffer) {
  if (A.isCompressed()) return A;
  buffer = A;
  buffer.makeCompressed();
  return buffer;
}

}  // namespace mc
