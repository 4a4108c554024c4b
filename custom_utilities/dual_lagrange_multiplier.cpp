// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/dual_lagrange_multiplier.h"

#include "custom_utilities/mortar_autodiff.h"

namespace mc {

namespace {
// Pivot threshold relative to the largest entry of M. M of a domain of relative thickness delta
// has pivots of order delta^2 (delta^4 for a small corner of a quadrilateral): below this, A
// would lose its digits.
constexpr double kPivotTolerance = 1e-10;
}  // namespace

template <int TDim, int TNumNodes>
template <class T>
bool DualLagrangeMultiplier<TDim, TNumNodes>::FromIntegrals(const Values<T>& d, const SquareMatrix<T>& m,
                                                            SquareMatrix<T>& a) {
  // A = diag(d) M^-1  <=>  A^T = M^-1 diag(d) (M symmetric).
  SquareMatrix<T> rhs = SquareMatrix<T>::Zero();
  for (int i = 0; i < TNumNodes; ++i) rhs(i, i) = d(i);
  if (!mortar_detail::SolveSmall<T, TNumNodes, TNumNodes>(m, rhs, kPivotTolerance)) return false;
  a = rhs.transpose();
  return true;
}

#define MC_INSTANTIATE_DUAL(D, N, T)                                                                                 \
  template bool DualLagrangeMultiplier<D, N>::FromIntegrals<T>(const DualLagrangeMultiplier<D, N>::Values<T>&,       \
                                                               const DualLagrangeMultiplier<D, N>::SquareMatrix<T>&, \
                                                               DualLagrangeMultiplier<D, N>::SquareMatrix<T>&);

using AutoDiff222 = mortar_detail::PairAutoDiff<2, 2, 2>;
using AutoDiff333 = mortar_detail::PairAutoDiff<3, 3, 3>;
using AutoDiff334 = mortar_detail::PairAutoDiff<3, 3, 4>;
using AutoDiff343 = mortar_detail::PairAutoDiff<3, 4, 3>;
using AutoDiff344 = mortar_detail::PairAutoDiff<3, 4, 4>;

MC_INSTANTIATE_DUAL(2, 2, double)
MC_INSTANTIATE_DUAL(2, 2, AutoDiff222)
MC_INSTANTIATE_DUAL(3, 3, double)
MC_INSTANTIATE_DUAL(3, 3, AutoDiff333)
MC_INSTANTIATE_DUAL(3, 3, AutoDiff334)
MC_INSTANTIATE_DUAL(3, 4, double)
MC_INSTANTIATE_DUAL(3, 4, AutoDiff343)
MC_INSTANTIATE_DUAL(3, 4, AutoDiff344)

}  // namespace mc
