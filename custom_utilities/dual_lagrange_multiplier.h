// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

#include "custom_utilities/mortar_shape_functions.h"

namespace mc {

/// Where the matrices defining the dual basis are integrated.
enum class DualBasisDomain {
  /// The whole slave element (Popp, Wohlmuth): one basis per slave element, independent of
  /// the master; D of a single pair is diagonal only if the pair covers the whole element,
  /// the sum over all pairs of an element always is.
  kSlaveElement,
  /// The overlap of the current pair (Kratos' conditions): D of every pair is diagonal; falls
  /// back to kSlaveElement when the overlap matrix is singular (tiny or sliver overlaps).
  kPairOverlap,
};

/// Dual Lagrange multiplier basis Phi = A_e N on a linear slave element (Line2D2,
/// Triangle3D3, Quadrilateral3D4), biorthogonal to the standard basis:
///   int Phi_i N_j = delta_ij D_e(j,j),   A_e = D_e M_e^-1,
///   D_e = diag(int N_j),  M_e(i,j) = int N_i N_j  (integrals over the chosen domain).
/// On lines and triangles A_e is constant (e.g. [[2,-1],[-1,2]] on lines); on distorted
/// quadrilaterals it depends on the geometry, which the AutoDiff path differentiates.
template <int TDim, int TNumNodes>
class DualLagrangeMultiplier {
 public:
  template <class T>
  using SlaveMatrix = Eigen::Matrix<T, TNumNodes, TDim>;
  template <class T>
  using SquareMatrix = Eigen::Matrix<T, TNumNodes, TNumNodes>;
  template <class T>
  using Values = Eigen::Matrix<T, TNumNodes, 1>;

  /// A_e over the whole slave element (current coordinates, rows = nodes). Integrates with
  /// a rule exact for flat elements (warped quadrilaterals: 3x3 Gauss).
  template <class T>
  static SquareMatrix<T> ComputeAe(const SlaveMatrix<T>& slave_coordinates);

  /// A_e = diag(d) M^-1 from accumulated integrals d_j = int N_j and M = int N N^T.
  template <class T>
  static SquareMatrix<T> AeFromIntegrals(const Values<T>& d, const SquareMatrix<T>& m);

  /// Phi = A_e N.
  template <class T>
  static Values<T> Phi(const SquareMatrix<T>& ae, const Values<T>& n) {
    return ae * n;
  }
};

}  // namespace mc
