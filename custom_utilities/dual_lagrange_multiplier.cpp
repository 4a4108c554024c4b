// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/dual_lagrange_multiplier.h"

#include <cassert>

#include "core/geometries/geometry_type.h"
#include "core/geometries/reference_element.h"
#include "custom_utilities/mortar_autodiff.h"

namespace mc {

template <int TDim, int TNumNodes>
template <class T>
typename DualLagrangeMultiplier<TDim, TNumNodes>::template SquareMatrix<T>
DualLagrangeMultiplier<TDim, TNumNodes>::ComputeAe(const SlaveMatrix<T>& x) {
  using std::sqrt;
  using SF = MortarShapeFunctions<TNumNodes>;
  // Exact for flat elements: N_i N_j detJ has degree 2 (lines, triangles) or 3 per direction
  // (flat quadrilaterals); 3x3 Gauss keeps warped quadrilaterals accurate.
  const GeometryType type = TNumNodes == 2   ? GeometryType::Line2D2
                            : TNumNodes == 3 ? GeometryType::Triangle2D3
                                             : GeometryType::Quadrilateral2D4;
  const auto& rule = ReferenceElement::Get(type).IntegrationPoints(TNumNodes == 4 ? 3 : 2);
  Values<T> d = Values<T>::Zero();
  SquareMatrix<T> m = SquareMatrix<T>::Zero();
  for (const auto& gp : rule) {
    typename SF::template Local<T> xi;
    for (int a = 0; a < SF::kLocalDim; ++a) xi(a) = T(gp.local(a));
    const Values<T> n = SF::template N<T>(xi);
    const auto dn = SF::template DN<T>(xi);
    T det_j;
    if constexpr (TNumNodes == 2) {
      det_j = sqrt((x.transpose() * dn.col(0)).squaredNorm());
    } else {
      const Eigen::Matrix<T, 3, 1> a = x.transpose() * dn.col(0);
      const Eigen::Matrix<T, 3, 1> b = x.transpose() * dn.col(1);
      det_j = sqrt(a.cross(b).squaredNorm());
    }
    const T w = gp.weight * det_j;
    d += w * n;
    m += w * n * n.transpose();
  }
  return AeFromIntegrals<T>(d, m);
}

template <int TDim, int TNumNodes>
template <class T>
typename DualLagrangeMultiplier<TDim, TNumNodes>::template SquareMatrix<T>
DualLagrangeMultiplier<TDim, TNumNodes>::AeFromIntegrals(const Values<T>& d,
                                                       const SquareMatrix<T>& m) {
  // A_e = diag(d) M^-1  <=>  A_e^T = M^-1 diag(d) (M symmetric).
  SquareMatrix<T> rhs = SquareMatrix<T>::Zero();
  for (int i = 0; i < TNumNodes; ++i) rhs(i, i) = d(i);
  if (!mortar_detail::SolveSmall<T, TNumNodes, TNumNodes>(m, rhs, 1e-10))
    return SquareMatrix<T>::Constant(T(std::numeric_limits<double>::quiet_NaN()));
  return rhs.transpose();
}

#define MC_INSTANTIATE_DUAL(D, N, T)                                                          \
  template DualLagrangeMultiplier<D, N>::SquareMatrix<T>                                      \
  DualLagrangeMultiplier<D, N>::ComputeAe<T>(const DualLagrangeMultiplier<D, N>::SlaveMatrix<T>&); \
  template DualLagrangeMultiplier<D, N>::SquareMatrix<T>                                      \
  DualLagrangeMultiplier<D, N>::AeFromIntegrals<T>(const DualLagrangeMultiplier<D, N>::Values<T>&, \
                                                   const DualLagrangeMultiplier<D, N>::SquareMatrix<T>&);

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
