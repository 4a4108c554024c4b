// SPDX-License-Identifier: BSD-3-Clause
#include "structural/conditions/line_load_condition.h"

#include <numbers>

#include "core/utilities/error.h"
#include <algorithm>

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
  const double thickness = dim == 2 && !axisymmetric_ ? Thickness() : 1.0;
  const double two_pi = 2.0 * std::numbers::pi;
  // One order above the geometry default: linearly varying loads on linear edges/faces are exact.
  const int order = std::min(5, geometry.DefaultIntegrationOrder() + 1);
  const auto& points = geometry.IntegrationPoints(order);
  const Matrix& Ntable = geometry.ShapeFunctionsValues(order);
  const auto& dNtable = geometry.ShapeFunctionsLocalGradients(order);

  for (std::size_t g = 0; g < points.size(); ++g) {
    const auto N = Ntable.row(static_cast<Eigen::Index>(g));
    const Matrix& dN = dNtable[g];
    Array3 T0 = Array3::Zero(), t = Array3::Zero(), load = condition_load;
    double R = 0.0, r = 0.0, p = condition_pressure;
    for (std::size_t a = 0; a < n; ++a) {
      const Node& node = geometry[a];
      const auto ia = static_cast<Eigen::Index>(a);
      const Array3 x = node.X0() + Array3(node.FastGetSolutionStepValue(DISPLACEMENT));
      T0 += dN(ia, 0) * node.X0();
      t += dN(ia, 0) * x;
      R += N[ia] * node.X0()[0];
      r += N[ia] * x[0];
      load += N[ia] * NodalVector(LINE_LOAD, a);
      p += N[ia] * NodalPressure(a);
    }
    const double w = points[g].weight;
    if (rhs) {
      const double dead = w * T0.norm() * (axisymmetric_ ? two_pi * R : thickness);
      for (std::size_t a = 0; a < n; ++a)
        rhs->segment(static_cast<Eigen::Index>(a) * dim, dim) += N[static_cast<Eigen::Index>(a)] * dead * load.head(dim);
    }
    if (p == 0.0) continue;
    if (dim == 3)
      throw InputError(Concat("condition ", Id(), " (", Info(), "): a face pressure (", p,
                              ") needs a normal, which a line in 3D does not have; use LINE_LOAD"));
    // Follower pressure on the current configuration: f_a = N_a p n w factor, n = (t_y, -t_x).
    const Array3 normal(t[1], -t[0], 0.0);
    const double factor = axisymmetric_ ? two_pi * r : thickness;
    for (std::size_t a = 0; a < n; ++a) {
      const auto ia = static_cast<Eigen::Index>(a);
      const double s = N[ia] * p * w;
      if (rhs) rhs->segment(ia * 2, 2) += s * factor * normal.head(2);
      if (!lhs) continue;
      for (std::size_t b = 0; b < n; ++b) {
        const auto ib = static_cast<Eigen::Index>(b);
        (*lhs)(ia * 2, ib * 2 + 1) -= s * factor * dN(ib, 0);
        (*lhs)(ia * 2 + 1, ib * 2) += s * factor * dN(ib, 0);
        if (axisymmetric_) {
          (*lhs)(ia * 2, ib * 2) -= s * normal[0] * two_pi * N[ib];
          (*lhs)(ia * 2 + 1, ib * 2) -= s * normal[1] * two_pi * N[ib];
        }
      }
    }
  }
}

}  // namespace mc
