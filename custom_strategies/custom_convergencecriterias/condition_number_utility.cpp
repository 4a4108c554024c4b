// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_convergencecriterias/condition_number_utility.h"

#include <Eigen/SparseLU>
#include <cmath>
#include <limits>

namespace mc {

namespace {

/// Power iteration with the map `apply` (v -> A v or v -> A^-1 v); returns |mu| of the dominant
/// eigenvalue mu of that map, from the Rayleigh-like ratio |A v| / |v| with |v| = 1.
template <class Apply>
double DominantModulus(Eigen::Index n, Apply&& apply, int max_iterations, double tolerance) {
  // A fixed, non-symmetric start vector: not orthogonal to the dominant eigenvector in practice.
  Vector v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = 1.0 + 0.1 * std::sin(1.0 + static_cast<double>(i));
  v.normalize();
  double estimate = 0.0;
  Vector w(n);
  for (int it = 0; it < max_iterations; ++it) {
    apply(v, w);
    const double next = w.norm();
    if (!(next > 0.0)) return 0.0;
    v = w / next;
    if (std::abs(next - estimate) <= tolerance * next) return next;
    estimate = next;
  }
  return estimate;
}

}  // namespace

double ConditionNumberUtility::LargestEigenvalueModulus(const SparseMatrix& A) const {
  return DominantModulus(
      A.rows(), [&](const Vector& v, Vector& w) { w = A * v; }, max_iterations, tolerance);
}

double ConditionNumberUtility::SmallestEigenvalueModulus(const SparseMatrix& A) const {
  Eigen::SparseLU<SparseMatrix> lu;
  lu.compute(A);
  if (lu.info() != Eigen::Success) return 0.0;
  const double inverse = DominantModulus(
      A.rows(), [&](const Vector& v, Vector& w) { w = lu.solve(v); }, max_iterations, tolerance);
  return inverse > 0.0 ? 1.0 / inverse : 0.0;
}

double ConditionNumberUtility::Estimate(const SparseMatrix& A) const {
  if (A.rows() == 0) return 0.0;
  const double smallest = SmallestEigenvalueModulus(A);
  if (!(smallest > 0.0)) return std::numeric_limits<double>::infinity();
  return LargestEigenvalueModulus(A) / smallest;
}

}  // namespace mc
