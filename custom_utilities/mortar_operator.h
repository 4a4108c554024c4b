// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

#include "custom_utilities/dual_lagrange_multiplier.h"
#include "custom_utilities/exact_mortar_integration_utility.h"

namespace mc {

/// The mortar operators of one (slave, master) pair, integrated over their overlap:
///   D(j, k) = int Phi_j N1_k        (slave x slave; diagonal with the pair's dual basis,
///                                    see DualLagrangeMultiplier)
///   M(j, l) = int Phi_j N2_l        (slave x master; N2 at the projected master point)
///   nodal_area(j) = int N1_j        (standard basis: contribution to NODAL_AREA)
/// with the integration points and weights of ExactMortarIntegrationUtility (physical
/// measure), so that over a whole flat interface sum(D) = sum(M) = slave area.
/// Row j of D x1 - M x2 is the pair's contribution to the weighted gap vector of slave node j.
template <class T, int TDim, int TNumNodes, int TNumNodesMaster>
struct MortarOperator {
  using DMatrix = Eigen::Matrix<T, TNumNodes, TNumNodes>;
  using MMatrix = Eigen::Matrix<T, TNumNodes, TNumNodesMaster>;
  using SlaveVector = Eigen::Matrix<T, TNumNodes, 1>;

  DMatrix D = DMatrix::Zero();
  MMatrix M = MMatrix::Zero();
  SlaveVector nodal_area = SlaveVector::Zero();

  /// Zeroes and integrates D, M, nodal_area over `points` with the dual basis of `ae`.
  void Compute(const MortarIntegrationPoints<T, TDim, TNumNodes, TNumNodesMaster>& points,
               const Eigen::Matrix<T, TNumNodes, TNumNodes>& ae);
};

}  // namespace mc
