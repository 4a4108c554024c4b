// SPDX-License-Identifier: BSD-3-Clause
#include "structural/conditions/line_load_condition.h"

#include <algorithm>
#include <numbers>

#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"

namespace mc {

void LineLoadCondition::CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info) {
  const Geometry& geometry = GetGeometry();
  const int dim = Dimension();
  const std::size_t n = geometry.PointsNumber();
  const auto ndof = static_cast<Eigen::Index>(n) * dim;
  if (lhs) lhs->setZero(ndof, ndof);
  if (rhs) rhs->setZero(ndof);

  const Array3 condition_load = GetValue(LINE_LOAD);
  const double condition_pressure = ConditionPressure();
  const double two_pi = 2.0 * std::numbers::pi;
  const bool linear = info.GetValue(LINEAR_ANALYSIS);
  // One order above the geometry default: linearly varying loads on linear edges/faces are exact.
  const int order = std::min(5, geometry.DefaultIntegrationOrder() + 1);
  const auto& points = geometry.IntegrationPoints(order);
  const Matrix& Ntable = geometry.ShapeFunctionsValues(order);
  const auto& dNtable = geometry.ShapeFunctionsLocalGradients(order);

  for (std::size_t g = 0; g < points.size(); ++g) {
    const auto N = Ntable.row(static_cast<Eigen::Index>(g));
    const Matrix& dN = dNtable[g];
    Array3 t = Array3::Zero(), load = condition_load;
    double r = 0.0, p = condition_pressure;
    for (std::size_t a = 0; a < n; ++a) {
      const Node& node = geometry[a];
      const auto ia = static_cast<Eigen::Index>(a);
      const Array3 x = node.X0() + Array3(node.FastGetSolutionStepValue(DISPLACEMENT));
      t += dN(ia, 0) * x;
      r += N[ia] * x[0];
      load += N[ia] * NodalVector(LINE_LOAD, a);
      p += N[ia] * NodalPressure(a);
    }
    const double w = points[g].weight;
    const double length = t.norm();
    // Per unit current length (times the current circumference in axisymmetry) and never times
    // THICKNESS: Kratos 10.4's convention, although its plane elements do integrate over
    // THICKNESS. The load keeps its direction: its stiffness is that of the measure only, left out
    // in a linear analysis (Kratos leaves it out always, and converges more slowly).
    const double circumference = axisymmetric_ ? two_pi * r : 1.0;
    if (load.head(dim).squaredNorm() > 0.0) {
      for (std::size_t a = 0; a < n; ++a) {
        const auto ia = static_cast<Eigen::Index>(a);
        if (rhs) rhs->segment(ia * dim, dim) += N[ia] * w * length * circumference * load.head(dim);
        if (!lhs || linear) continue;
        for (std::size_t b = 0; b < n; ++b) {
          const auto ib = static_cast<Eigen::Index>(b);
          Array3 dmeasure = circumference * dN(ib, 0) / length * t;  // d(length circumference)/dx_b
          if (axisymmetric_) dmeasure[0] += two_pi * length * N[ib];
          lhs->block(ia * dim, ib * dim, dim, dim) -= N[ia] * w * load.head(dim) * dmeasure.head(dim).transpose();
        }
      }
    }
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
      const double s = N[ia] * p * w;
      if (rhs) rhs->segment(ia * 2, 2) += s * circumference * normal.head(2);
      if (!lhs || linear) continue;
      for (std::size_t b = 0; b < n; ++b) {
        const auto ib = static_cast<Eigen::Index>(b);
        (*lhs)(ia * 2, ib * 2 + 1) += s * circumference * dN(ib, 0);
        (*lhs)(ia * 2 + 1, ib * 2) -= s * circumference * dN(ib, 0);
        if (axisymmetric_) {
          (*lhs)(ia * 2, ib * 2) -= s * normal[0] * two_pi * N[ib];
          (*lhs)(ia * 2 + 1, ib * 2) -= s * normal[1] * two_pi * N[ib];
        }
      }
    }
  }
}

}  // namespace mc
