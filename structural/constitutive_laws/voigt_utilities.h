// SPDX-License-Identifier: BSD-3-Clause
// Voigt notation helpers shared by the elastic laws and the solid elements. The full 3D order
// is (xx, yy, zz, xy, yz, xz) with engineering shear strains; reduced laws use a subset of it:
// plane (xx, yy, xy) = 3D components {0, 1, 3}, axisymmetric (rr, zz, rz, theta-theta) with
// x = r, y = z, z = theta = 3D components {0, 1, 3, 2}.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <span>

namespace mc::voigt {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
/// Reduced (law-sized) vectors and matrices without heap allocation.
using StrainVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
using TangentMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;

/// Tensor index pairs of the 3D Voigt components.
inline constexpr int kPairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};

/// Positions in the 3D Voigt order of the components of a law of `strain_size` 3, 4 or 6.
inline std::span<const int> Components(int strain_size) {
  static constexpr int plane[3] = {0, 1, 3};
  static constexpr int axisym[4] = {0, 1, 3, 2};
  static constexpr int full[6] = {0, 1, 2, 3, 4, 5};
  if (strain_size == 3) return plane;
  if (strain_size == 4) return axisym;
  return full;
}

/// Symmetric strain tensor -> 3D Voigt with engineering shears.
inline Vector6 StrainToVoigt(const Eigen::Matrix3d& e) {
  Vector6 v;
  for (int a = 0; a < 6; ++a) {
    const int i = kPairs[a][0], j = kPairs[a][1];
    v[a] = i == j ? e(i, j) : e(i, j) + e(j, i);
  }
  return v;
}

/// Reduced stress vector -> symmetric 3x3 tensor (missing components are zero).
template <class V>
Eigen::Matrix3d StressToTensor(const V& s) {
  const auto comps = Components(static_cast<int>(s.size()));
  Eigen::Matrix3d t = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < comps.size(); ++k) {
    const int i = kPairs[comps[k]][0], j = kPairs[comps[k]][1];
    t(i, j) = t(j, i) = s[static_cast<Eigen::Index>(k)];
  }
  return t;
}

/// T with tau = T S for tau = F S F^T (stress Voigt vectors); the spatial tangent of a
/// material tangent C (engineering-strain Voigt) is T C T^T.
inline Matrix6 PushForwardMatrix(const Eigen::Matrix3d& F) {
  Matrix6 T;
  for (int a = 0; a < 6; ++a) {
    const int i = kPairs[a][0], j = kPairs[a][1];
    for (int b = 0; b < 6; ++b) {
      const int I = kPairs[b][0], J = kPairs[b][1];
      T(a, b) = I == J ? F(i, I) * F(j, I) : F(i, I) * F(j, J) + F(i, J) * F(j, I);
    }
  }
  return T;
}

/// Von Mises equivalent of a symmetric stress tensor.
inline double VonMises(const Eigen::Matrix3d& s) {
  const Eigen::Matrix3d dev = s - s.trace() / 3.0 * Eigen::Matrix3d::Identity();
  return std::sqrt(1.5 * dev.cwiseProduct(dev).sum());
}

}  // namespace mc::voigt
