// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/contact_search_geometry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace mc {

namespace {

constexpr int kMaxFaceNodes = 9;

// Unit tangent of the face along its first edge, orthogonal to `normal`.
Array3 FirstTangent(const Geometry& geometry, const Array3& normal) {
  Array3 t = geometry[1].Coordinates() - geometry[0].Coordinates();
  t -= t.dot(normal) * normal;
  const double norm = t.norm();
  if (norm > 0.0) return t / norm;
  // Degenerate first edge: any direction orthogonal to the normal.
  Array3 any = std::abs(normal.x()) < 0.9 ? Array3::UnitX() : Array3::UnitY();
  return normal.cross(any).normalized();
}

// Corner nodes in cyclic order (quadratic faces list their corners first).
int CornerCount(const Geometry& geometry) {
  switch (geometry.Family()) {
    case GeometryFamily::Line: return 2;
    case GeometryFamily::Triangle: return 3;
    case GeometryFamily::Quadrilateral: return 4;
    default: return static_cast<int>(geometry.PointsNumber());
  }
}

// Interval of the projections of a convex polygon on direction d.
void ProjectPolygon(const Eigen::Vector2d* poly, int n, const Eigen::Vector2d& d, double& lo, double& hi) {
  lo = std::numeric_limits<double>::max();
  hi = -lo;
  for (int i = 0; i < n; ++i) {
    const double s = poly[i].dot(d);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
}

}  // namespace

double InterfaceCharacteristicLength(const Geometry& geometry) {
  const double size = geometry.DomainSize();
  return geometry.LocalSpaceDimension() == 1 ? size : std::sqrt(size);
}

OrientedBox BuildOrientedBox(const Geometry& geometry, const Array3& normal, double inflation,
                             double normal_inflation) {
  OrientedBox box;
  box.center = geometry.Center();
  const Array3 t1 = FirstTangent(geometry, normal);
  box.axes.col(0) = t1;
  box.axes.col(1) = normal.cross(t1);
  box.axes.col(2) = normal;
  Array3 lo = Array3::Constant(std::numeric_limits<double>::max());
  Array3 hi = -lo;
  for (std::size_t i = 0; i < geometry.PointsNumber(); ++i) {
    const Array3 local = box.axes.transpose() * (geometry[i].Coordinates() - box.center);
    lo = lo.cwiseMin(local);
    hi = hi.cwiseMax(local);
  }
  box.center += box.axes * (0.5 * (lo + hi));
  box.half = (0.5 * (hi - lo)).array() + inflation;
  if (normal_inflation >= 0.0) box.half[2] = 0.5 * (hi[2] - lo[2]) + normal_inflation;
  return box;
}

bool Intersect(const OrientedBox& a, const OrientedBox& b) {
  // Rotation of b in a's frame and the centre offset, as in the classic SAT formulation.
  const Eigen::Matrix3d R = a.axes.transpose() * b.axes;
  const Eigen::Matrix3d absR = R.cwiseAbs().array() + 1e-12;
  const Array3 t = a.axes.transpose() * (b.center - a.center);
  for (int i = 0; i < 3; ++i)
    if (std::abs(t[i]) > a.half[i] + absR.row(i).dot(b.half)) return false;
  for (int j = 0; j < 3; ++j)
    if (std::abs(t.dot(R.col(j))) > absR.col(j).dot(a.half) + b.half[j]) return false;
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double ra = a.half[i1] * absR(i2, j) + a.half[i2] * absR(i1, j);
      const double rb = b.half[j1] * absR(i, j2) + b.half[j2] * absR(i, j1);
      if (std::abs(t[i2] * R(i1, j) - t[i1] * R(i2, j)) > ra + rb) return false;
    }
  }
  return true;
}

double ProjectedOverlap(const Geometry& reference, const Array3& normal, const Geometry& other) {
  const Array3 origin = reference.Center();
  const Array3 t1 = FirstTangent(reference, normal);
  if (reference.LocalSpaceDimension() == 1) {
    double lo_r = std::numeric_limits<double>::max(), hi_r = -lo_r, lo_o = lo_r, hi_o = -lo_r;
    for (std::size_t i = 0; i < reference.PointsNumber(); ++i) {
      const double s = (reference[i].Coordinates() - origin).dot(t1);
      lo_r = std::min(lo_r, s);
      hi_r = std::max(hi_r, s);
    }
    for (std::size_t i = 0; i < other.PointsNumber(); ++i) {
      const double s = (other[i].Coordinates() - origin).dot(t1);
      lo_o = std::min(lo_o, s);
      hi_o = std::max(hi_o, s);
    }
    return std::min(hi_r, hi_o) - std::max(lo_r, lo_o);
  }
  const Array3 t2 = normal.cross(t1);
  Eigen::Vector2d polys[2][kMaxFaceNodes];
  const Geometry* geometries[2] = {&reference, &other};
  int counts[2];
  for (int g = 0; g < 2; ++g) {
    counts[g] = std::min(CornerCount(*geometries[g]), kMaxFaceNodes);
    for (int i = 0; i < counts[g]; ++i) {
      const Array3 d = (*geometries[g])[i].Coordinates() - origin;
      polys[g][i] = Eigen::Vector2d(d.dot(t1), d.dot(t2));
    }
  }
  double depth = std::numeric_limits<double>::max();
  for (int g = 0; g < 2; ++g) {
    for (int i = 0; i < counts[g]; ++i) {
      const Eigen::Vector2d edge = polys[g][(i + 1) % counts[g]] - polys[g][i];
      const double length = edge.norm();
      if (!(length > 0.0)) continue;
      const Eigen::Vector2d axis(-edge.y() / length, edge.x() / length);
      double lo_a, hi_a, lo_b, hi_b;
      ProjectPolygon(polys[0], counts[0], axis, lo_a, hi_a);
      ProjectPolygon(polys[1], counts[1], axis, lo_b, hi_b);
      depth = std::min(depth, std::min(hi_a, hi_b) - std::max(lo_a, lo_b));
    }
  }
  return depth;
}

}  // namespace mc
