// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <array>

#include "core/variables/value_types.h"
#include "custom_utilities/mortar_pair_kinematics.h"

namespace mc {

/// Inputs of the generated frictionless mortar kernels (custom_conditions/generated/) for one
/// pair: the mortar kinematics and the nodal values of the slave nodes.
/// Signs: weighted gap positive when open; contact pressure negative in compression.
template <int TDim, int TNumNodes, int TNumNodesMaster>
struct FrictionlessMortarData {
  using Kinematics = MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>;

  const Kinematics* kinematics = nullptr;  ///< computed with derivatives for the LHS
  Eigen::Matrix<double, TNumNodes, 1> normal_pressure = Eigen::Matrix<double, TNumNodes, 1>::Zero();
  Eigen::Matrix<double, TNumNodes, TDim> vector_multiplier = Eigen::Matrix<double, TNumNodes, TDim>::Zero();
  Eigen::Matrix<double, TNumNodes, 1> penalty = Eigen::Matrix<double, TNumNodes, 1>::Ones();         ///< eps_j
  Eigen::Matrix<double, TNumNodes, 1> dynamic_factor = Eigen::Matrix<double, TNumNodes, 1>::Ones();  ///< 1 in statics
  std::array<bool, TNumNodes> active{};  ///< ACTIVE flag of each slave node
  double scale_factor = 1.0;             ///< k
};

/// Chain rule through the mortar operators of slave node j, used by the generated LHS kernels:
///   lhs(r, q) += sum_b cD(r, b) dD[q](j, b) + sum_l cM(r, l) dM[q](j, l) + cG(r) dg_j/dq
/// for every displacement DoF q, where cD, cM, cG are the (negated) partial derivatives of the
/// residual rows with respect to D(j, :), M(j, :) and the weighted gap g_j.
template <class TKinematics, class TCD, class TCM, class TCG>
void AddOperatorChainRule(const TKinematics& kinematics, int j, const TCD& cD, const TCM& cM, const TCG& cG,
                          Matrix& lhs) {
  for (int q = 0; q < TKinematics::kNumDisplacementDofs; ++q) {
    const auto dD = kinematics.dD[q].row(j).transpose();
    const auto dM = kinematics.dM[q].row(j).transpose();
    lhs.col(q).noalias() += cD * dD + cM * dM + cG * kinematics.d_weighted_gap(j, q);
  }
}

/// The same contraction over the slave-normal indices, plus the explicit normal partials cN of
/// branch j, for the normal variation: with p = (i, c) the slave normal component (node-major)
/// and q = SlaveNormalIndex(i, c),
///   S(r, p) += sum_b cD(r, b) dD[q](j, b) + sum_l cM(r, l) dM[q](j, l) + cG(r) dg_j/dq
///              + [i == j] cN(r, c),
/// so that S = -d rhs / d n in total; the NV conditions chain it with dn/du.
template <class TKinematics, class TCD, class TCM, class TCG, class TCN>
void AddNormalChainRule(const TKinematics& kinematics, int j, const TCD& cD, const TCM& cM, const TCG& cG,
                        const TCN& cN, Matrix& sensitivity) {
  for (int p = 0; p < TKinematics::kNumSlaveDofs; ++p) {
    const int q = TKinematics::kNumDisplacementDofs + p;
    const auto dD = kinematics.dD[q].row(j).transpose();
    const auto dM = kinematics.dM[q].row(j).transpose();
    sensitivity.col(p).noalias() += cD * dD + cM * dM + cG * kinematics.d_weighted_gap(j, q);
  }
  sensitivity.middleCols(j * TKinematics::kDim, TKinematics::kDim) += cN;
}

}  // namespace mc
