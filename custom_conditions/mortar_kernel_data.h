// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <array>

#include "core/variables/value_types.h"
#include "custom_utilities/mortar_pair_kinematics.h"

namespace mc {

/// Inputs of the generated mortar contact kernels (custom_conditions/generated/) for one pair:
/// the mortar kinematics and the nodal values of the slave nodes. The frictionless kernels read
/// the first block only; the frictional ones also the friction block.
/// Signs: weighted gap positive when open; contact pressure negative in compression.
template <int TDim, int TNumNodes, int TNumNodesMaster>
struct MortarKernelData {
  using Kinematics = MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>;
  using SlaveVector = Eigen::Matrix<double, TNumNodes, 1>;
  using SlaveMatrix = Eigen::Matrix<double, TNumNodes, TDim>;

  const Kinematics* kinematics = nullptr;  ///< computed with derivatives for the LHS
  SlaveVector normal_pressure = SlaveVector::Zero();
  SlaveMatrix vector_multiplier = SlaveMatrix::Zero();
  SlaveVector penalty = SlaveVector::Ones();         ///< eps_j
  SlaveVector dynamic_factor = SlaveVector::Ones();  ///< 1 in statics
  std::array<bool, TNumNodes> active{};              ///< ACTIVE flag of each slave node
  double scale_factor = 1.0;                         ///< k

  // Friction (Coulomb, Gitterle et al. 2010).
  typename Kinematics::DMatrix previous_D = Kinematics::DMatrix::Zero();  ///< D_n: last converged configuration
  typename Kinematics::MMatrix previous_M = Kinematics::MMatrix::Zero();  ///< M_n
  /// s_j = T_j [(D - D_n) x1 - (M - M_n) x2]_j (WeightedSlip): this pair's weighted, frame-indifferent
  /// tangential slip increment of the step; T_j = I - n_j n_j^T.
  SlaveMatrix weighted_slip = SlaveMatrix::Zero();
  /// P_j (NodalNormalSupport::SymmetryMask of each slave node, as rows): s_j = P_j T_j [...]_j. On a
  /// symmetry plane the mirrored half, missing from the model, would cancel s_j's component across it.
  SlaveMatrix symmetry_mask = SlaveMatrix::Ones();
  SlaveVector friction_coefficient = SlaveVector::Zero();  ///< mu_j (Coulomb)
  SlaveVector friction_threshold = SlaveVector::Zero();    ///< tau_j (Tresca)
  std::array<bool, TNumNodes> slip{};                      ///< SLIP flag of each (active) slave node
  double tangent_factor = 1.0;                             ///< c_tau
  double slip_augmentation = 0.0;                          ///< c_slip
};

/// Row j of (D - D_n) x1 - (M - M_n) x2 at the kinematics' coordinates (before the tangential projection).
template <class TData>
Eigen::Matrix<double, TData::Kinematics::kDim, 1> SlipIncrement(const TData& data, int j) {
  const auto& kinematics = *data.kinematics;
  return ((kinematics.D.row(j) - data.previous_D.row(j)) * kinematics.slave_coordinates -
          (kinematics.M.row(j) - data.previous_M.row(j)) * kinematics.master_coordinates)
      .transpose();
}

/// Fills data.weighted_slip from the kinematics and the previous operators.
template <class TData>
void ComputeWeightedSlip(TData& data) {
  const auto& n1 = data.kinematics->slave_normals;
  for (int j = 0; j < TData::Kinematics::kNumSlaveNodes; ++j) {
    const auto v = SlipIncrement(data, j);
    const auto n = n1.row(j).transpose();
    data.weighted_slip.row(j) = (v - n * n.dot(v)).transpose().cwiseProduct(data.symmetry_mask.row(j));
  }
}

/// Chain rule through the mortar operators of slave node j, used by the generated LHS kernels:
///   lhs(r, q) += sum_b cD(r, b) dD[q](j, b) + sum_l cM(r, l) dM[q](j, l) + cG(r) dg_j/dq
/// for every displacement DoF q, where cD, cM, cG are the (negated) partial derivatives of the
/// residual rows with respect to D(j, :), M(j, :) and the weighted gap g_j.
template <class TKinematics, class TCD, class TCM, class TCG>
void AddOperatorChainRule(const TKinematics& kinematics, int j, const TCD& cD, const TCM& cM, const TCG& cG,
                          Matrix& lhs) {
  const Eigen::Index multipliers = cG.size() - TKinematics::kNumDisplacementDofs;
  for (int q = 0; q < TKinematics::kNumDisplacementDofs; ++q) {
    const auto dD = kinematics.dD[q].row(j).transpose();
    const auto dM = kinematics.dM[q].row(j).transpose();
    lhs.col(q).noalias() += cD * dD + cM * dM + cG * kinematics.d_weighted_gap(j, q);
    lhs.col(q).tail(multipliers) += cG.tail(multipliers) * kinematics.d_constraint_gap_correction(j, q);
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
  const Eigen::Index multipliers = cG.size() - TKinematics::kNumDisplacementDofs;
  for (int p = 0; p < TKinematics::kNumSlaveDofs; ++p) {
    const int q = TKinematics::kNumDisplacementDofs + p;
    const auto dD = kinematics.dD[q].row(j).transpose();
    const auto dM = kinematics.dM[q].row(j).transpose();
    sensitivity.col(p).noalias() += cD * dD + cM * dM + cG * kinematics.d_weighted_gap(j, q);
    sensitivity.col(p).tail(multipliers) += cG.tail(multipliers) * kinematics.d_constraint_gap_correction(j, q);
  }
  sensitivity.middleCols(j * TKinematics::kDim, TKinematics::kDim) += cN;
}

/// Chain rule through the weighted slip s_j (frictional kernels): lhs(r, q) += cS(r, :) . ds_j/dq for
/// every displacement DoF q, with cS = -d rhs / ds_j and, for v = [(D - D_n) x1 - (M - M_n) x2]_j,
///   ds_j/dq = P_j T_j dv/dq,  dv/dq = dD[q](j, :) x1 - dM[q](j, :) x2 + (D - D_n)(j, i) e_c [q = slave (i, c)]
///                                                                  - (M - M_n)(j, l) e_c [q = master (l, c)].
template <class TData, class TCS>
void AddSlipChainRule(const TData& data, int j, const TCS& cS, Matrix& lhs) {
  using K = typename TData::Kinematics;
  const K& kinematics = *data.kinematics;
  const Eigen::Matrix<double, K::kDim, 1> n = kinematics.slave_normals.row(j).transpose();
  const Eigen::Matrix<double, K::kDim, 1> mask = data.symmetry_mask.row(j).transpose();
  for (int q = 0; q < K::kNumDisplacementDofs; ++q) {
    Eigen::Matrix<double, K::kDim, 1> dv = (kinematics.dD[q].row(j) * kinematics.slave_coordinates -
                                            kinematics.dM[q].row(j) * kinematics.master_coordinates)
                                               .transpose();
    const int c = q % K::kDim;
    if (q < K::kNumMasterDofs)
      dv(c) -= kinematics.M(j, q / K::kDim) - data.previous_M(j, q / K::kDim);
    else
      dv(c) +=
          kinematics.D(j, (q - K::kNumMasterDofs) / K::kDim) - data.previous_D(j, (q - K::kNumMasterDofs) / K::kDim);
    lhs.col(q).noalias() += cS * (dv - n * n.dot(dv)).cwiseProduct(mask);
  }
}

/// The same over the slave-normal indices (normal variation): S(r, p) += cS(r, :) . ds_j/dn_p with
/// p = (i, c) node-major, through D and M, and for i == j through T_j: d(T_j v)/dn_j[c] =
/// -e_c (n_j . v) - n_j v_c; then P_j.
template <class TData, class TCS>
void AddSlipNormalChainRule(const TData& data, int j, const TCS& cS, Matrix& sensitivity) {
  using K = typename TData::Kinematics;
  const K& kinematics = *data.kinematics;
  const Eigen::Matrix<double, K::kDim, 1> n = kinematics.slave_normals.row(j).transpose();
  const Eigen::Matrix<double, K::kDim, 1> v = SlipIncrement(data, j);
  const Eigen::Matrix<double, K::kDim, 1> mask = data.symmetry_mask.row(j).transpose();
  for (int p = 0; p < K::kNumSlaveDofs; ++p) {
    const int q = K::kNumDisplacementDofs + p;
    const Eigen::Matrix<double, K::kDim, 1> dv = (kinematics.dD[q].row(j) * kinematics.slave_coordinates -
                                                  kinematics.dM[q].row(j) * kinematics.master_coordinates)
                                                     .transpose();
    Eigen::Matrix<double, K::kDim, 1> ds = dv - n * n.dot(dv);
    if (p / K::kDim == j) {
      const int c = p % K::kDim;
      ds(c) -= n.dot(v);
      ds -= n * v(c);
    }
    sensitivity.col(p).noalias() += cS * ds.cwiseProduct(mask);
  }
}

}  // namespace mc
