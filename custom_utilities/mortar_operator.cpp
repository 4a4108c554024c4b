// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/mortar_operator.h"

#include "custom_utilities/mortar_autodiff.h"

namespace mc {

template <class T, int TDim, int TNumNodes, int TNumNodesMaster>
void MortarOperator<T, TDim, TNumNodes, TNumNodesMaster>::Compute(
    const MortarIntegrationPoints<T, TDim, TNumNodes, TNumNodesMaster>& points,
    const Eigen::Matrix<T, TNumNodes, TNumNodes>& ae) {
  using SF1 = MortarShapeFunctions<TNumNodes>;
  using SF2 = MortarShapeFunctions<TNumNodesMaster>;
  D.setZero();
  M.setZero();
  nodal_area.setZero();
  for (int g = 0; g < points.size; ++g) {
    const auto& p = points.points[g];
    const SlaveVector n1 = SF1::template N<T>(p.slave_local);
    const Eigen::Matrix<T, TNumNodesMaster, 1> n2 = SF2::template N<T>(p.master_local);
    const SlaveVector phi = ae * n1;
    const SlaveVector w_phi = p.weight * phi;
    D += w_phi * n1.transpose();
    M += w_phi * n2.transpose();
    nodal_area += p.weight * n1;
  }
}

template struct MortarOperator<double, 2, 2, 2>;
template struct MortarOperator<double, 3, 3, 3>;
template struct MortarOperator<double, 3, 3, 4>;
template struct MortarOperator<double, 3, 4, 3>;
template struct MortarOperator<double, 3, 4, 4>;
template struct MortarOperator<mortar_detail::PairAutoDiff<2, 2, 2>, 2, 2, 2>;
template struct MortarOperator<mortar_detail::PairAutoDiff<3, 3, 3>, 3, 3, 3>;
template struct MortarOperator<mortar_detail::PairAutoDiff<3, 3, 4>, 3, 3, 4>;
template struct MortarOperator<mortar_detail::PairAutoDiff<3, 4, 3>, 3, 4, 3>;
template struct MortarOperator<mortar_detail::PairAutoDiff<3, 4, 4>, 3, 4, 4>;

}  // namespace mc
