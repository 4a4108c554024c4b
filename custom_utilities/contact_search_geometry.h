// SPDX-License-Identifier: BSD-3-Clause
// Small pure geometric kernels of the contact search: sizes, oriented boxes and the overlap of
// two interface faces seen along a normal.
#pragma once

#include <Eigen/Core>

#include "core/geometries/geometry.h"

namespace mc {

/// A box with orthonormal axes (columns of `axes`) and half extents along them.
struct OrientedBox {
  Array3 center;
  Eigen::Matrix3d axes;
  Array3 half;
};

/// Length of a line; square root of the area of a surface.
double InterfaceCharacteristicLength(const Geometry& geometry);

/// The tightest box aligned with the face (first edge, the other tangent, the normal) around
/// its nodes, grown by `inflation` along the tangents and by `normal_inflation` along the
/// normal (the same as `inflation` when negative).
OrientedBox BuildOrientedBox(const Geometry& geometry, const Array3& normal, double inflation,
                             double normal_inflation = -1.0);

/// Separating-axis test of two oriented boxes (15 candidate axes).
bool Intersect(const OrientedBox& a, const OrientedBox& b);

/// Overlap of the projections of `reference` and `other` on the plane (3D) or line (2D)
/// through `reference`'s centre with normal `normal`: the length of the common interval in 2D,
/// the smallest penetration depth over the separating axes of the two projected convex
/// polygons in 3D. Positive when they overlap, zero or negative otherwise.
double ProjectedOverlap(const Geometry& reference, const Array3& normal, const Geometry& other);

}  // namespace mc
