// SPDX-License-Identifier: BSD-3-Clause
// Internal helpers of the mortar kernels: the AutoDiff scalar used for the pair derivatives,
// value extraction for branch decisions, and a tiny dense solver that works on any scalar.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

namespace mc::mortar_detail {

/// Number of independent variables of a pair: master u, slave u, slave nodal normals.
constexpr int NumDerivatives(int dim, int num_slave, int num_master) { return dim * (num_master + 2 * num_slave); }

template <int TDim, int TNumNodes, int TNumNodesMaster>
using PairAutoDiff = Eigen::AutoDiffScalar<Eigen::Matrix<double, NumDerivatives(TDim, TNumNodes, TNumNodesMaster), 1>>;

inline double ValueOf(double x) { return x; }
template <class D>
double ValueOf(const Eigen::AutoDiffScalar<D>& x) {
  return x.value();
}

/// Solves A X = B in place (X returned in B) by Gaussian elimination with partial pivoting
/// on the values. Returns false if a pivot is below rel_tol times the largest |A| entry.
template <class T, int N, int NRhs>
bool SolveSmall(Eigen::Matrix<T, N, N> A, Eigen::Matrix<T, N, NRhs>& B, double rel_tol) {
  double scale = 0.0;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) scale = std::max(scale, std::abs(ValueOf(A(i, j))));
  if (!(scale > 0.0)) return false;
  for (int k = 0; k < N; ++k) {
    int p = k;
    for (int i = k + 1; i < N; ++i)
      if (std::abs(ValueOf(A(i, k))) > std::abs(ValueOf(A(p, k)))) p = i;
    if (std::abs(ValueOf(A(p, k))) <= rel_tol * scale) return false;
    if (p != k) {
      A.row(p).swap(A.row(k));
      B.row(p).swap(B.row(k));
    }
    for (int i = k + 1; i < N; ++i) {
      const T f = A(i, k) / A(k, k);
      for (int j = k; j < N; ++j) A(i, j) -= f * A(k, j);
      for (int j = 0; j < NRhs; ++j) B(i, j) -= f * B(k, j);
    }
  }
  for (int k = N - 1; k >= 0; --k) {
    for (int j = 0; j < NRhs; ++j) {
      T s = B(k, j);
      for (int i = k + 1; i < N; ++i) s -= A(k, i) * B(i, j);
      B(k, j) = s / A(k, k);
    }
  }
  return true;
}

}  // namespace mc::mortar_detail
