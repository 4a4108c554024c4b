// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <Eigen/Core>

namespace mc {

/// Linear interface shape functions templated on the scalar type, so that the mortar kernels
/// can run on doubles or on forward-mode AutoDiff scalars.
///
/// TNumNodes selects the geometry: 2 = line (xi in [-1,1], node 1 at -1), 3 = triangle (area
/// coordinates, N1 = 1 - xi - eta), 4 = quadrilateral ([-1,1]^2, nodes counter-clockwise from
/// (-1,-1)). Same local coordinates and node orderings as core/geometries (Kratos/GiD).
/// Coordinates are rows: x(i, k) is component k of node i.
template <int TNumNodes>
class MortarShapeFunctions {
 public:
  static constexpr int kLocalDim = TNumNodes == 2 ? 1 : 2;

  template <class T>
  using Local = Eigen::Matrix<T, kLocalDim, 1>;
  template <class T>
  using Values = Eigen::Matrix<T, TNumNodes, 1>;
  /// dN(i, a) = dN_i / dxi_a.
  template <class T>
  using Gradients = Eigen::Matrix<T, TNumNodes, kLocalDim>;

  template <class T>
  static Values<T> N(const Local<T>& xi) {
    Values<T> n;
    if constexpr (TNumNodes == 2) {
      n(0) = 0.5 * (1.0 - xi(0));
      n(1) = 0.5 * (1.0 + xi(0));
    } else if constexpr (TNumNodes == 3) {
      n(0) = 1.0 - xi(0) - xi(1);
      n(1) = xi(0);
      n(2) = xi(1);
    } else {
      static_assert(TNumNodes == 4, "linear line, triangle or quadrilateral only");
      n(0) = 0.25 * (1.0 - xi(0)) * (1.0 - xi(1));
      n(1) = 0.25 * (1.0 + xi(0)) * (1.0 - xi(1));
      n(2) = 0.25 * (1.0 + xi(0)) * (1.0 + xi(1));
      n(3) = 0.25 * (1.0 - xi(0)) * (1.0 + xi(1));
    }
    return n;
  }

  template <class T>
  static Gradients<T> DN(const Local<T>& xi) {
    Gradients<T> d;
    if constexpr (TNumNodes == 2) {
      d(0, 0) = T(-0.5);
      d(1, 0) = T(0.5);
    } else if constexpr (TNumNodes == 3) {
      d << T(-1.0), T(-1.0), T(1.0), T(0.0), T(0.0), T(1.0);
    } else {
      d(0, 0) = -0.25 * (1.0 - xi(1));
      d(0, 1) = -0.25 * (1.0 - xi(0));
      d(1, 0) = 0.25 * (1.0 - xi(1));
      d(1, 1) = -0.25 * (1.0 + xi(0));
      d(2, 0) = 0.25 * (1.0 + xi(1));
      d(2, 1) = 0.25 * (1.0 + xi(0));
      d(3, 0) = -0.25 * (1.0 + xi(1));
      d(3, 1) = 0.25 * (1.0 - xi(0));
    }
    return d;
  }

  /// Local coordinates of the element centre (where the condition normal is evaluated).
  template <class T>
  static Local<T> Center() {
    Local<T> c;
    if constexpr (TNumNodes == 3) {
      c << T(1.0 / 3.0), T(1.0 / 3.0);
    } else {
      c.setZero();
    }
    return c;
  }
};

}  // namespace mc
