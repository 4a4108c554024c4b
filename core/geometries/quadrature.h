// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "core/geometries/geometry.h"

namespace mc {

/// Quadrature rules on the reference elements, for orders kMinOrder..kMaxOrder.
///
/// Tensor-product families (line [-1,1], quadrilateral [-1,1]^2, hexahedron [-1,1]^3) follow
/// Kratos' GI_GAUSS_n: order n uses n Gauss-Legendre points per direction, exact for degree
/// 2n-1 >= n in each direction. Simplices use symmetric rules with positive weights, exact for
/// total degree >= order: triangle (area coordinates, weights sum to 1/2) and tetrahedron
/// (weights sum to 1/6). The prism [triangle] x [0,1] combines the triangle rule of the order
/// with n Gauss points in zeta.
class Quadrature {
 public:
  static constexpr int kMinOrder = 1;
  static constexpr int kMaxOrder = 5;

  /// Builds the rule (not cached: ReferenceElement keeps the tables).
  static std::vector<IntegrationPoint> Rule(GeometryFamily family, int order);

  /// n Gauss-Legendre points and weights on [-1,1], n >= 1.
  static void GaussLegendre(int n, std::vector<double>& points, std::vector<double>& weights);

  /// Highest total degree (simplices) or per-direction degree (tensor families, prism in zeta)
  /// integrated exactly by the rule of `order`.
  static int ExactDegree(GeometryFamily family, int order);
};

}  // namespace mc
