// SPDX-License-Identifier: BSD-3-Clause
#include "test_matrices.h"

#include <cmath>
#include <vector>

namespace mc::testing {

namespace {

SparseMatrix FivePoint(int n, double east, double west, double north, double south) {
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(5 * static_cast<std::size_t>(n) * n);
  const auto index = [n](int i, int j) { return i * n + j; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const int row = index(i, j);
      entries.emplace_back(row, row, 4.0);
      if (j + 1 < n) entries.emplace_back(row, index(i, j + 1), east);
      if (j > 0) entries.emplace_back(row, index(i, j - 1), west);
      if (i + 1 < n) entries.emplace_back(row, index(i + 1, j), north);
      if (i > 0) entries.emplace_back(row, index(i - 1, j), south);
    }
  }
  SparseMatrix A(n * n, n * n);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}

}  // namespace

SparseMatrix Poisson2D(int n) { return FivePoint(n, -1.0, -1.0, -1.0, -1.0); }

SparseMatrix ConvectionDiffusion2D(int n) { return FivePoint(n, -1.0 + 0.3, -1.0 - 0.3, -1.0 - 0.2, -1.0 + 0.2); }

Vector ManufacturedSolution(long size) {
  Vector x(size);
  for (long i = 0; i < size; ++i) x[i] = 1.0 + std::sin(0.37 * static_cast<double>(i)) + static_cast<double>(i) / size;
  return x;
}

double RelativeError(const Vector& x, const Vector& y) { return (x - y).norm() / y.norm(); }

double RelativeResidual(const SparseMatrix& A, const Vector& x, const Vector& b) {
  return (b - A * x).norm() / b.norm();
}

void ZeroRowAndColumn(SparseMatrix& A, int k) {
  for (int j = 0; j < A.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      if (it.row() == k || it.col() == k) it.valueRef() = 0.0;
    }
  }
}

}  // namespace mc::testing
