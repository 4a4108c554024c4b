// SPDX-License-Identifier: BSD-3-Clause
#include "structural/conditions/surface_load_condition.h"

#include <Eigen/Geometry>

#include <algorithm>

#include "core/variables/kernel_variables.h"

namespace mc {

namespace {

// [v]x with [v]x w = v x w.
Eigen::Matrix3d Skew(const Array3& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v[2], v[1], v[2], 0.0, -v[0], -v[1], v[0], 0.0;
  return s;
}

}  // namespace

void SurfaceLoadCondition::CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info) {
  const Geometry& geometry = GetGeometry();
  const std::size_t n = geometry.PointsNumber();
  const auto ndof = static_cast<Eigen::Index>(n) * 3;
  if (lhs) lhs->setZero(ndof, ndof);
  if (rhs) rhs->setZero(ndof);

  const Array3 condition_load = GetValue(SURFACE_LOAD);
  const double condition_pressure = ConditionPressure();
  // One order above the geometry default: linearly varying loads on linear edges/faces are exact.
  const int order = std::min(5, geometry.DefaultIntegrationOrder() + 1);
  const auto& points = geometry.IntegrationPoints(order);
  const Matrix& Ntable = geometry.ShapeFunctionsValues(order);
  const auto& dNtable = geometry.ShapeFunctionsLocalGradients(order);

  for (std::size_t g = 0; g < points.size(); ++g) {
    const auto N = Ntable.row(static_cast<Eigen::Index>(g));
    const Matrix& dN = dNtable[g];
    Array3 a1 = Array3::Zero(), a2 = Array3::Zero();
    Array3 load = condition_load;
    double p = condition_pressure;
    for (std::size_t a = 0; a < n; ++a) {
      const Node& node = geometry[a];
      const auto ia = static_cast<Eigen::Index>(a);
      const Array3 x = node.X0() + Array3(node.FastGetSolutionStepValue(DISPLACEMENT));
      a1 += dN(ia, 0) * x;
      a2 += dN(ia, 1) * x;
      load += N[ia] * NodalVector(SURFACE_LOAD, a);
      p += N[ia] * NodalPressure(a);
    }
    const double w = points[g].weight;
    const Array3 normal = a1.cross(a2);
    const double area = normal.norm();
    // SURFACE_LOAD is per unit current area in a fixed direction (as in Kratos 10.4); the stiffness
    // of that area and of the pressure's normal is left out in a linear analysis.
    if (rhs) {
      for (std::size_t a = 0; a < n; ++a) {
        const auto ia = static_cast<Eigen::Index>(a);
        rhs->segment<3>(ia * 3) += N[ia] * w * (area * load + p * normal);
      }
    }
    const bool has_load = load.squaredNorm() > 0.0;
    if (!lhs || info.GetValue(LINEAR_ANALYSIS) || (p == 0.0 && !has_load)) continue;
    // d(a1 x a2)/dx_b = dN_b,eta [a1]x - dN_b,xi [a2]x (e_j x a2 = -[a2]x e_j, a1 x e_j = [a1]x e_j);
    // the area's derivative is its projection on the unit normal.
    const Eigen::Matrix3d S1 = Skew(a1), S2 = Skew(a2);
    for (std::size_t b = 0; b < n; ++b) {
      const auto ib = static_cast<Eigen::Index>(b);
      const Eigen::Matrix3d dnormal = dN(ib, 1) * S1 - dN(ib, 0) * S2;
      const Eigen::Matrix3d dforce = p * dnormal + (has_load ? Eigen::Matrix3d(load * (normal.transpose() * dnormal) / area)
                                                             : Eigen::Matrix3d::Zero());
      for (std::size_t a = 0; a < n; ++a) {
        const auto ia = static_cast<Eigen::Index>(a);
        lhs->block<3, 3>(ia * 3, ib * 3) -= N[ia] * w * dforce;
      }
    }
  }
}

}  // namespace mc
