// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>
#include <array>

#include "custom_utilities/dual_lagrange_multiplier.h"
#include "custom_utilities/exact_mortar_integration_utility.h"
#include "custom_utilities/mortar_geometry_cases.h"

namespace mc {

/// Everything a mortar contact condition needs for one (slave condition, master condition)
/// pair, with exact first derivatives (forward-mode AutoDiff through the whole computation:
/// normals, projections, clipping, dual basis, quadrature).
///
/// Independent variables q (the derivative index), in Kratos' condition DoF order:
///   [ master displacements (node-major: node 0 x,y[,z], node 1 ...),
///     slave displacements  (same layout),
///     slave nodal normals  (same layout; for CONSIDER_NORMAL_VARIATION, chain with dn/du) ]
/// Displacement derivatives equal current-coordinate derivatives (x = X + u). The slave
/// multipliers, which follow the slave displacements in the condition's DoF list, do not
/// enter D, M or the gap. Use MasterDof / SlaveDof / SlaveNormalIndex, never hard-coded offsets.
///
/// Conventions:
/// - slave_normals are the unit nodal normals n_j (historical NORMAL), pointing out of the
///   slave body towards the master.
/// - weighted_gap(j) = -n_j . (D x1 - M x2)_j: the pair's contribution to WEIGHTED_GAP,
///   positive when open (master ahead of the slave along n_j), negative when penetrating.
/// - nodal_area(j) = int N1_j over the overlap: contribution to NODAL_AREA.
/// - All quantities are this pair's contributions; the caller sums over the pairs of a node.
///
/// Usage (per pair, no heap allocation; the object is large, keep one per thread):
///   MortarPairKinematics<3, 4, 4> k;
///   if (k.Compute(x1, x2, n1, settings)) { ... k.D, k.M, k.dD[k.SlaveDof(i, c)] ... }
/// ComputeValues() fills the same values without derivatives (cheaper; explicit gap updates).
template <int TDim, int TNumNodes, int TNumNodesMaster>
struct MortarPairKinematics {
  static constexpr int kDim = TDim;
  static constexpr int kNumSlaveNodes = TNumNodes;
  static constexpr int kNumMasterNodes = TNumNodesMaster;
  static constexpr int kNumMasterDofs = TDim * TNumNodesMaster;
  static constexpr int kNumSlaveDofs = TDim * TNumNodes;
  static constexpr int kNumDisplacementDofs = kNumMasterDofs + kNumSlaveDofs;
  static constexpr int kNumDerivatives = kNumDisplacementDofs + kNumSlaveDofs;

  static constexpr int MasterDof(int node, int component) { return node * TDim + component; }
  static constexpr int SlaveDof(int node, int component) { return kNumMasterDofs + node * TDim + component; }
  static constexpr int SlaveNormalIndex(int node, int component) {
    return kNumDisplacementDofs + node * TDim + component;
  }

  using SlaveMatrix = Eigen::Matrix<double, TNumNodes, TDim>;  ///< row i = node i
  using MasterMatrix = Eigen::Matrix<double, TNumNodesMaster, TDim>;
  using DMatrix = Eigen::Matrix<double, TNumNodes, TNumNodes>;
  using MMatrix = Eigen::Matrix<double, TNumNodes, TNumNodesMaster>;
  using SlaveVector = Eigen::Matrix<double, TNumNodes, 1>;
  using DerivativeRows = Eigen::Matrix<double, TNumNodes, kNumDerivatives>;

  // Inputs as given to Compute (current configuration).
  SlaveMatrix slave_coordinates = SlaveMatrix::Zero();
  MasterMatrix master_coordinates = MasterMatrix::Zero();
  SlaveMatrix slave_normals = SlaveMatrix::Zero();

  // Values.
  bool has_overlap = false;
  double area = 0.0;  ///< overlap length (2D) / area (3D)
  /// The overlap is too thin to carry its own dual basis and took the standard basis
  /// (DualLagrangeMultiplier): it cannot carry contact by itself.
  bool sliver = false;
  MortarIntegrationPoints<double, TDim, TNumNodes, TNumNodesMaster> points;
  DMatrix Ae = DMatrix::Zero();
  DMatrix D = DMatrix::Zero();
  MMatrix M = MMatrix::Zero();
  SlaveVector nodal_area = SlaveVector::Zero();
  SlaveVector weighted_gap = SlaveVector::Zero();
  SlaveMatrix gap_vector = SlaveMatrix::Zero();  ///< row j = (D x1 - M x2)_j

  // Derivatives, index q as above (filled by Compute only).
  std::array<DMatrix, kNumDerivatives> dD{};
  std::array<MMatrix, kNumDerivatives> dM{};
  DerivativeRows d_weighted_gap = DerivativeRows::Zero();  ///< (j, q) = d weighted_gap(j)/dq
  DerivativeRows d_nodal_area = DerivativeRows::Zero();
  DerivativeRows d_constraint_gap_correction = DerivativeRows::Zero();  ///< SetMeanGaps
  Eigen::Matrix<double, kNumDerivatives, 1> d_area = Eigen::Matrix<double, kNumDerivatives, 1>::Zero();

  /// Values and derivatives. Returns has_overlap; without overlap (or with one too thin to carry
  /// the pair's dual basis, see DualLagrangeMultiplier) every output is zero.
  bool Compute(const SlaveMatrix& x1, const MasterMatrix& x2, const SlaveMatrix& n1,
               const MortarIntegrationSettings& settings);

  /// Values only (derivative members untouched).
  bool ComputeValues(const SlaveMatrix& x1, const MasterMatrix& x2, const SlaveMatrix& n1,
                     const MortarIntegrationSettings& settings);

  /// The constraint rows' correction of the weighted-gap derivatives, from node j's mean gap
  /// (the caller's choice; MortarContactCondition: its WEIGHTED_GAP over its NODAL_AREA where that
  /// is negative, else 0):
  ///   d_constraint_gap_correction(j, q) = -mean_gap(j) d nodal_area(j)/dq.
  /// With the pair dual basis weighted_gap(j) = nodal_area(j) x (the gap at node j), so constraint
  /// rows linearised with it solve the mean gap for zero, scaled by the nodal area: the same
  /// solutions, and the exact tangent again once the node's gap is closed. What they leave out is
  /// the growth of an overlap that only begins to cover the node (an element over the master's
  /// edge), whose nodal area can double in a step. Derivatives (Compute) needed; zero for a sliver
  /// (standard basis) and until this is called.
  void SetMeanGaps(const SlaveVector& mean_gap);

  /// A pair left unintegrated (its kernels read no mortar quantity): the inputs are stored, every
  /// value is zero as without overlap, the derivative members are untouched.
  void SkipIntegration(const SlaveMatrix& x1, const MasterMatrix& x2, const SlaveMatrix& n1);

 private:
  /// The values of a pair without overlap (all zero).
  void ClearValues();
};

#define MC_EXTERN(D, S, M) extern template struct MortarPairKinematics<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_EXTERN)
#undef MC_EXTERN

}  // namespace mc
