// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

#include "custom_utilities/mortar_shape_functions.h"

namespace mc {

/// Dual Lagrange multiplier basis Phi = A N of a linear slave interface element (Line2D2,
/// Triangle3D3, Quadrilateral3D4), biorthogonal to the standard basis N on a domain:
///   int Phi_j N_k = delta_jk d_j,   A = diag(d) M^-1,   d_j = int N_j,  M(j, k) = int N_j N_k.
/// Sum_j Phi_j = 1, so a constant pressure is transmitted exactly.
///
/// The mortar conditions take the domain to be the overlap of each (slave, master) pair, with
/// the pair's own integration points (so D of every pair is diagonal in that quadrature):
/// FromIntegrals. Why per pair and not per slave element (Wohlmuth's element-wise basis,
/// OverElement): a slave element that the master covers only in part, at the edge of a contact
/// surface, has element dual functions that are negative over part of it. Integrated over the
/// covered part alone they give weighted gaps of the wrong sign however open the gap, and
/// activate nodes that cannot touch. An element basis restricted to the covered part (Cichosz &
/// Bischoff 2011, Popp et al. 2013) depends on every master of the element and couples them in
/// the tangent. The pair basis weights a gap that is linear along the element exactly (weighted
/// gap_j = d_j g_j) on any overlap, needs only the pair's own nodes for its exact derivatives,
/// and is the basis of Kratos' conditions, whose answers we reproduce. An overlap too thin for a
/// regular M (a sliver) falls back to the element basis: its share of the interface is
/// negligible, and the element basis keeps sum(D) and constant-pressure transmission exact.
template <int TDim, int TNumNodes>
class DualLagrangeMultiplier {
 public:
  template <class T>
  using SlaveMatrix = Eigen::Matrix<T, TNumNodes, TDim>;
  template <class T>
  using SquareMatrix = Eigen::Matrix<T, TNumNodes, TNumNodes>;
  template <class T>
  using Values = Eigen::Matrix<T, TNumNodes, 1>;

  /// A = diag(d) M^-1 from integrals over the domain. Returns false when M is singular to
  /// working precision (fewer integration points than nodes, or a domain too thin to tell the
  /// shape functions apart); A is then undefined.
  template <class T>
  static bool FromIntegrals(const Values<T>& d, const SquareMatrix<T>& m, SquareMatrix<T>& a);

  /// A over the whole slave element at current coordinates x (rows = nodes); in axisymmetry
  /// (2D, x = radius) in the inner product int (.) 2 pi r ds. Throws for a degenerate element.
  template <class T>
  static SquareMatrix<T> OverElement(const SlaveMatrix<T>& x, bool axisymmetric);

  /// Phi = A N.
  template <class T>
  static Values<T> Phi(const SquareMatrix<T>& a, const Values<T>& n) {
    return a * n;
  }
};

}  // namespace mc
