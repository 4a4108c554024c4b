// SPDX-License-Identifier: BSD-3-Clause
#include "structural/conditions/load_condition.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <numbers>

#include "core/geometries/reference_element.h"
#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"
#include "structural/elements/displacement_dofs.h"

namespace mc {

struct LoadCondition::BoundaryPoint {
  double weight;
  Matrix::ConstRowXpr N;
  const Matrix& dN;
  Array3 dx[2];     ///< current tangents dx/dxi (and dx/deta on a surface)
  double radius;    ///< current x
  Array3 load;      ///< the load variable: nodal values interpolated plus the condition's value
  double pressure;  ///< net face pressure: nodal values interpolated plus the condition's value
};

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// One order above the geometry default: linearly varying loads on linear edges/faces are exact.
int LoadIntegrationOrder(const Geometry& geometry) { return std::min(5, geometry.DefaultIntegrationOrder() + 1); }

// [v]x with [v]x w = v x w.
Eigen::Matrix3d Skew(const Array3& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v[2], v[1], v[2], 0.0, -v[0], -v[1], v[0], 0.0;
  return s;
}

}  // namespace

std::unique_ptr<Condition> LoadCondition::Create(IndexType id, Geometry::NodesArray nodes,
                                                 Properties* properties) const {
  return std::make_unique<LoadCondition>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties, load_,
                                         axisymmetric_);
}

int LoadCondition::Dimension() const noexcept { return GetGeometry().Reference().WorkingSpaceDimension(); }

std::string LoadCondition::Info() const {
  static constexpr const char* kStem[] = {"PointLoadCondition", "LineLoadCondition", "SurfaceLoadCondition"};
  return StructuralEntityName(kStem[static_cast<int>(load_)], axisymmetric_, GetGeometry());
}

void LoadCondition::GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const {
  GetDisplacementDofList(GetGeometry(), dofs);
}

void LoadCondition::CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) {
  CalculateAll(&lhs, &rhs, info);
}

void LoadCondition::CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) { CalculateAll(&lhs, nullptr, info); }

void LoadCondition::CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) { CalculateAll(nullptr, &rhs, info); }

void LoadCondition::CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info) {
  const auto ndof = static_cast<Eigen::Index>(GetGeometry().PointsNumber()) * Dimension();
  if (lhs) lhs->setZero(ndof, ndof);
  if (rhs) rhs->setZero(ndof);
  switch (load_) {
    case Load::kPoint: return CalculatePointLoad(lhs, rhs, info);
    case Load::kLine: return CalculateLineLoad(lhs, rhs, info);
    case Load::kSurface: return CalculateSurfaceLoad(lhs, rhs, info);
  }
}

void LoadCondition::Check(const ProcessInfo& info) const {
  CheckDisplacementDofs(GetGeometry(), Concat("condition ", Id(), " (", Info(), ")"));
}

Array3 LoadCondition::NodalVector(const Variable<Array3>& var, std::size_t a) const {
  const Node& node = GetGeometry()[a];
  return node.HasSolutionStepValue(var) ? Array3(node.FastGetSolutionStepValue(var)) : Array3::Zero();
}

double LoadCondition::NodalPressure(std::size_t a) const {
  const Node& node = GetGeometry()[a];
  double p = 0.0;
  if (node.HasSolutionStepValue(NEGATIVE_FACE_PRESSURE)) p += node.FastGetSolutionStepValue(NEGATIVE_FACE_PRESSURE);
  if (node.HasSolutionStepValue(POSITIVE_FACE_PRESSURE)) p -= node.FastGetSolutionStepValue(POSITIVE_FACE_PRESSURE);
  return p;
}

double LoadCondition::ConditionPressure() const {
  return GetValue(NEGATIVE_FACE_PRESSURE) - GetValue(POSITIVE_FACE_PRESSURE);
}

LoadCondition::BoundaryPoint LoadCondition::Interpolate(const Variable<Array3>& var, int order, std::size_t g) const {
  const Geometry& geometry = GetGeometry();
  BoundaryPoint point{geometry.IntegrationPoints(order)[g].weight,
                      geometry.ShapeFunctionsValues(order).row(static_cast<Eigen::Index>(g)),
                      geometry.ShapeFunctionsLocalGradients(order)[g],
                      {Array3::Zero(), Array3::Zero()},
                      0.0,
                      GetValue(var),
                      ConditionPressure()};
  const auto local_dimension = std::min<Eigen::Index>(2, point.dN.cols());
  for (std::size_t a = 0; a < geometry.PointsNumber(); ++a) {
    const Node& node = geometry[a];
    const auto ia = static_cast<Eigen::Index>(a);
    const Array3 x = node.X0() + Array3(node.FastGetSolutionStepValue(DISPLACEMENT));
    for (Eigen::Index k = 0; k < local_dimension; ++k) point.dx[k] += point.dN(ia, k) * x;
    point.radius += point.N[ia] * x[0];
    point.load += point.N[ia] * NodalVector(var, a);
    point.pressure += point.N[ia] * NodalPressure(a);
  }
  return point;
}

void LoadCondition::CalculatePointLoad(Matrix* lhs, Vector* rhs, const ProcessInfo& info) const {
  const int dim = Dimension();
  const Array3 load = NodalVector(POINT_LOAD, 0) + GetValue(POINT_LOAD);
  if (!axisymmetric_) {
    if (rhs) *rhs = load.head(dim);
    return;
  }
  const Node& node = GetGeometry()[0];
  const double radius = node.X0()[0] + node.FastGetSolutionStepValue(DISPLACEMENT_X);
  if (rhs) *rhs = kTwoPi * radius * load.head(2);
  if (lhs && !info.GetValue(LINEAR_ANALYSIS)) lhs->col(0) = -kTwoPi * load.head(2);
}

void LoadCondition::CalculateLineLoad(Matrix* lhs, Vector* rhs, const ProcessInfo& info) const {
  const int dim = Dimension();
  const std::size_t n = GetGeometry().PointsNumber();
  const bool linear = info.GetValue(LINEAR_ANALYSIS);
  const int order = LoadIntegrationOrder(GetGeometry());
  for (std::size_t g = 0; g < GetGeometry().IntegrationPoints(order).size(); ++g) {
    const BoundaryPoint q = Interpolate(LINE_LOAD, order, g);
    const Array3 t = q.dx[0];
    const Array3 load = q.load;
    const double length = t.norm();
    // Per unit current length (times the current circumference in axisymmetry) and never times
    // THICKNESS: Kratos 10.4's convention, although its plane elements do integrate over
    // THICKNESS. The load keeps its direction: its stiffness is that of the measure only, left out
    // in a linear analysis (Kratos leaves it out always, and converges more slowly).
    const double circumference = axisymmetric_ ? kTwoPi * q.radius : 1.0;
    if (load.head(dim).squaredNorm() > 0.0) {
      for (std::size_t a = 0; a < n; ++a) {
        const auto ia = static_cast<Eigen::Index>(a);
        if (rhs) rhs->segment(ia * dim, dim) += q.N[ia] * q.weight * length * circumference * load.head(dim);
        if (!lhs || linear) continue;
        for (std::size_t b = 0; b < n; ++b) {
          const auto ib = static_cast<Eigen::Index>(b);
          Array3 dmeasure = circumference * q.dN(ib, 0) / length * t;  // d(length circumference)/dx_b
          if (axisymmetric_) dmeasure[0] += kTwoPi * length * q.N[ib];
          lhs->block(ia * dim, ib * dim, dim, dim) -=
              q.N[ia] * q.weight * load.head(dim) * dmeasure.head(dim).transpose();
        }
      }
    }
    const double p = q.pressure;
    if (p == 0.0) continue;
    if (dim == 3)
      throw InputError(Concat("condition ", Id(), " (", Info(), "): a face pressure (", p,
                              ") needs a normal, which a line in 3D does not have; use LINE_LOAD"));
    // Follower pressure f_a = N_a p n w circumference on the current edge, with Kratos' 2D line
    // normal n = (-t_y, t_x): the tangent turned by +90 degrees. On edges ordered
    // counter-clockwise around the solid it points inwards, so POSITIVE_FACE_PRESSURE pulls
    // the boundary outwards in 2D, whereas in 3D (outward face normals) it pushes inwards.
    const Array3 normal(-t[1], t[0], 0.0);
    for (std::size_t a = 0; a < n; ++a) {
      const auto ia = static_cast<Eigen::Index>(a);
      const double s = q.N[ia] * p * q.weight;
      if (rhs) rhs->segment(ia * 2, 2) += s * circumference * normal.head(2);
      if (!lhs || linear) continue;
      for (std::size_t b = 0; b < n; ++b) {
        const auto ib = static_cast<Eigen::Index>(b);
        (*lhs)(ia * 2, ib * 2 + 1) += s * circumference * q.dN(ib, 0);
        (*lhs)(ia * 2 + 1, ib * 2) -= s * circumference * q.dN(ib, 0);
        if (axisymmetric_) {
          (*lhs)(ia * 2, ib * 2) -= s * normal[0] * kTwoPi * q.N[ib];
          (*lhs)(ia * 2 + 1, ib * 2) -= s * normal[1] * kTwoPi * q.N[ib];
        }
      }
    }
  }
}

void LoadCondition::CalculateSurfaceLoad(Matrix* lhs, Vector* rhs, const ProcessInfo& info) const {
  const std::size_t n = GetGeometry().PointsNumber();
  const int order = LoadIntegrationOrder(GetGeometry());
  for (std::size_t g = 0; g < GetGeometry().IntegrationPoints(order).size(); ++g) {
    const BoundaryPoint q = Interpolate(SURFACE_LOAD, order, g);
    const Array3& a1 = q.dx[0];
    const Array3& a2 = q.dx[1];
    const Array3& load = q.load;
    const double p = q.pressure;
    const Array3 normal = a1.cross(a2);
    const double area = normal.norm();
    // SURFACE_LOAD is per unit current area in a fixed direction (as in Kratos 10.4); the stiffness
    // of that area and of the pressure's normal is left out in a linear analysis.
    if (rhs) {
      for (std::size_t a = 0; a < n; ++a) {
        const auto ia = static_cast<Eigen::Index>(a);
        rhs->segment<3>(ia * 3) += q.N[ia] * q.weight * (area * load + p * normal);
      }
    }
    const bool has_load = load.squaredNorm() > 0.0;
    if (!lhs || info.GetValue(LINEAR_ANALYSIS) || (p == 0.0 && !has_load)) continue;
    // d(a1 x a2)/dx_b = dN_b,eta [a1]x - dN_b,xi [a2]x (e_j x a2 = -[a2]x e_j, a1 x e_j = [a1]x e_j);
    // the area's derivative is its projection on the unit normal.
    const Eigen::Matrix3d S1 = Skew(a1), S2 = Skew(a2);
    for (std::size_t b = 0; b < n; ++b) {
      const auto ib = static_cast<Eigen::Index>(b);
      const Eigen::Matrix3d dnormal = q.dN(ib, 1) * S1 - q.dN(ib, 0) * S2;
      const Eigen::Matrix3d dforce =
          p * dnormal +
          (has_load ? Eigen::Matrix3d(load * (normal.transpose() * dnormal) / area) : Eigen::Matrix3d::Zero());
      for (std::size_t a = 0; a < n; ++a) {
        const auto ia = static_cast<Eigen::Index>(a);
        lhs->block<3, 3>(ia * 3, ib * 3) -= q.N[ia] * q.weight * dforce;
      }
    }
  }
}

}  // namespace mc
