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
/// regular M (a sliver) takes the standard basis N instead (Phi = N, A = I, as Kratos does): its
/// share of the interface is negligible, constant pressures are still transmitted exactly, and
/// like the pair basis it weighs the gap with the shape functions of the nodes it lies at. The
/// element basis would not: a sliver along an edge of an element next to an open gap gave the
/// element's far nodes, active ones included, weighted gaps of the order of sliver area x gap
/// (3d_hex_curved_r0.5_overhang-none_gap_disp_1step_alm_coarse: 5e-5 of the peak pressure).
template <int TDim, int TNumNodes>
class DualLagrangeMultiplier {
 public:
  template <class T>
  using SquareMatrix = Eigen::Matrix<T, TNumNodes, TNumNodes>;
  template <class T>
  using Values = Eigen::Matrix<T, TNumNodes, 1>;

  /// A = diag(d) M^-1 from integrals over the domain. Returns false when M is singular to
  /// working precision (fewer integration points than nodes, or a domain too thin to tell the
  /// shape functions apart); A is then undefined.
  template <class T>
  static bool FromIntegrals(const Values<T>& d, const SquareMatrix<T>& m, SquareMatrix<T>& a);

  /// Phi = A N.
  template <class T>
  static Values<T> Phi(const SquareMatrix<T>& a, const Values<T>& n) {
    return a * n;
  }
};

}  // namespace mc
