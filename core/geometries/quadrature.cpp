// SPDX-License-Identifier: BSD-3-Clause
#include "core/geometries/quadrature.h"

#include <cassert>
#include <cmath>
#include <numbers>

namespace mc {
namespace {

using PointList = std::vector<IntegrationPoint>;

void Add(PointList& rule, double x, double y, double z, double w) { rule.push_back({Array3(x, y, z), w}); }

// Symmetric orbits in barycentric coordinates of the triangle: the centroid, the 3
// permutations of (a, a, 1-2a). Weights below are for the reference area 1/2.
void TriangleCentroid(PointList& rule, double w) { Add(rule, 1.0 / 3.0, 1.0 / 3.0, 0.0, w); }
void TriangleOrbit3(PointList& rule, double a, double w) {
  const double b = 1.0 - 2.0 * a;
  Add(rule, a, a, 0.0, w);
  Add(rule, b, a, 0.0, w);
  Add(rule, a, b, 0.0, w);
}

PointList TriangleRule(int order) {
  PointList rule;
  switch (order) {
    case 1: TriangleCentroid(rule, 0.5); break;
    case 2: TriangleOrbit3(rule, 1.0 / 6.0, 1.0 / 6.0); break;
    case 3:
    case 4:  // 6 points, degree 4 (Strang-Fix / Dunavant)
      TriangleOrbit3(rule, 0.44594849091596488632, 0.5 * 0.22338158967801146570);
      TriangleOrbit3(rule, 0.09157621350977074346, 0.5 * 0.10995174365532186764);
      break;
    default: {  // 7 points, degree 5 (Radon)
      const double s = std::sqrt(15.0);
      TriangleCentroid(rule, 0.5 * 9.0 / 40.0);
      TriangleOrbit3(rule, (6.0 - s) / 21.0, 0.5 * (155.0 - s) / 1200.0);
      TriangleOrbit3(rule, (6.0 + s) / 21.0, 0.5 * (155.0 + s) / 1200.0);
    }
  }
  return rule;
}

// Tetrahedron orbits: 4 permutations of (a, a, a, 1-3a) and 6 of (a, a, 1/2-a, 1/2-a); the
// local coordinates are the last three barycentric coordinates.
void TetOrbit4(PointList& rule, double a, double w) {
  const double b = 1.0 - 3.0 * a;
  Add(rule, a, a, a, w);
  Add(rule, b, a, a, w);
  Add(rule, a, b, a, w);
  Add(rule, a, a, b, w);
}
void TetOrbit6(PointList& rule, double a, double w) {
  const double b = 0.5 - a;
  Add(rule, a, a, b, w);
  Add(rule, a, b, a, w);
  Add(rule, b, a, a, w);
  Add(rule, a, b, b, w);
  Add(rule, b, a, b, w);
  Add(rule, b, b, a, w);
}

PointList TetrahedronRule(int order) {
  PointList rule;
  switch (order) {
    case 1: Add(rule, 0.25, 0.25, 0.25, 1.0 / 6.0); break;
    case 2: {
      const double a = (5.0 - std::sqrt(5.0)) / 20.0;
      TetOrbit4(rule, a, 1.0 / 24.0);
      break;
    }
    default:  // 14 points, degree 5, positive weights (Walkington)
      TetOrbit4(rule, 0.09273525031089122640, 0.01224884051939365826);
      TetOrbit4(rule, 0.31088591926330060980, 0.01878132095300264180);
      TetOrbit6(rule, 0.04550370412564964949, 0.00709100346284691107);
  }
  return rule;
}

}  // namespace

void Quadrature::GaussLegendre(int n, std::vector<double>& points, std::vector<double>& weights) {
  assert(n >= 1);
  points.assign(n, 0.0);
  weights.assign(n, 0.0);
  // Legendre P_n(x) and P_{n-1}(x) by the three-term recurrence.
  const auto legendre = [n](double x, double& pn, double& pm) {
    pm = 1.0;
    pn = x;
    for (int k = 2; k <= n; ++k) {
      const double next = ((2.0 * k - 1.0) * x * pn - (k - 1.0) * pm) / k;
      pm = pn;
      pn = next;
    }
  };
  for (int i = 0; i < n; ++i) {
    // Newton on P_n from the asymptotic guess of the i-th largest root.
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), pn, pm;
    for (int it = 0; it < 50; ++it) {
      legendre(x, pn, pm);
      const double dx = pn / (n * (x * pn - pm) / (x * x - 1.0));
      x -= dx;
      if (std::abs(dx) < 1e-15) break;
    }
    legendre(x, pn, pm);
    const double dp = n * (x * pn - pm) / (x * x - 1.0);
    points[n - 1 - i] = x;  // ascending
    weights[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
}

int Quadrature::ExactDegree(GeometryFamily family, int order) {
  switch (family) {
    case GeometryFamily::Point: return 0;
    case GeometryFamily::Line:
    case GeometryFamily::Quadrilateral:
    case GeometryFamily::Hexahedron: return 2 * order - 1;
    case GeometryFamily::Triangle: return order == 3 ? 4 : order;
    case GeometryFamily::Tetrahedron: return order >= 3 ? 5 : order;
    case GeometryFamily::Prism: return ExactDegree(GeometryFamily::Triangle, order);
  }
  return 0;
}

std::vector<IntegrationPoint> Quadrature::Rule(GeometryFamily family, int order) {
  assert(order >= kMinOrder && order <= kMaxOrder);
  std::vector<double> x, w;
  GaussLegendre(order, x, w);
  const int n = order;
  PointList rule;
  switch (family) {
    case GeometryFamily::Point: Add(rule, 0.0, 0.0, 0.0, 1.0); break;
    case GeometryFamily::Line:
      for (int i = 0; i < n; ++i) Add(rule, x[i], 0.0, 0.0, w[i]);
      break;
    case GeometryFamily::Quadrilateral:
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) Add(rule, x[i], x[j], 0.0, w[i] * w[j]);
      break;
    case GeometryFamily::Hexahedron:
      for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) Add(rule, x[i], x[j], x[k], w[i] * w[j] * w[k]);
      break;
    case GeometryFamily::Triangle: rule = TriangleRule(order); break;
    case GeometryFamily::Tetrahedron: rule = TetrahedronRule(order); break;
    case GeometryFamily::Prism: {
      const PointList tri = TriangleRule(order);
      for (int k = 0; k < n; ++k)
        for (const IntegrationPoint& p : tri)
          Add(rule, p.local[0], p.local[1], 0.5 * (1.0 + x[k]), 0.5 * w[k] * p.weight);
      break;
    }
  }
  return rule;
}

}  // namespace mc
