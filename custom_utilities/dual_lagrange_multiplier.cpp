// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/dual_lagrange_multiplier.h"

#include <numbers>

#include "core/geometries/geometry_type.h"
#include "core/geometries/reference_element.h"
#include "core/utilities/error.h"
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

template <int TDim, int TNumNodes>
template <class T>
typename DualLagrangeMultiplier<TDim, TNumNodes>::template SquareMatrix<T>
DualLagrangeMultiplier<TDim, TNumNodes>::OverElement(const SlaveMatrix<T>& x, bool axisymmetric) {
  using std::sqrt;
  using SF = MortarShapeFunctions<TNumNodes>;
  // Exact for flat elements: N_i N_j detJ has degree 2 (lines, triangles; 3 with the radius of
  // axisymmetry) or 3 per direction (flat quadrilaterals); 3x3 Gauss keeps warped quadrilaterals
  // accurate.
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
    T w;
    if constexpr (TNumNodes == 2) {
      w = gp.weight * sqrt((x.transpose() * dn.col(0)).squaredNorm());
      if (axisymmetric) w *= 2.0 * std::numbers::pi * n.dot(x.col(0));
    } else {
      const Eigen::Matrix<T, 3, 1> a = x.transpose() * dn.col(0);
      const Eigen::Matrix<T, 3, 1> b = x.transpose() * dn.col(1);
      w = gp.weight * sqrt(a.cross(b).squaredNorm());
    }
    d += w * n;
    m += w * n * n.transpose();
  }
  SquareMatrix<T> a;
  if (!FromIntegrals<T>(d, m, a))
    throw SolutionError(Concat("mortar integration: degenerate slave element (zero measure), first node at (",
                               mortar_detail::ValueOf(x(0, 0)), ", ", mortar_detail::ValueOf(x(0, 1)), ")"));
  return a;
}

#define MC_INSTANTIATE_DUAL(D, N, T)                                                                            \
  template bool DualLagrangeMultiplier<D, N>::FromIntegrals<T>(const DualLagrangeMultiplier<D, N>::Values<T>&, \
                                                               const DualLagrangeMultiplier<D, N>::SquareMatrix<T>&, \
                                                               DualLagrangeMultiplier<D, N>::SquareMatrix<T>&);   \
  template DualLagrangeMultiplier<D, N>::SquareMatrix<T> DualLagrangeMultiplier<D, N>::OverElement<T>(          \
      const DualLagrangeMultiplier<D, N>::SlaveMatrix<T>&, bool);

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
