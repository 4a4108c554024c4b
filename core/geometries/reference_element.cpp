// SPDX-License-Identifier: BSD-3-Clause
#include "core/geometries/reference_element.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/geometries/quadrature.h"
#include "core/utilities/error.h"

namespace mc {
namespace {

using GT = GeometryType;
static_assert(Quadrature::kMaxOrder - Quadrature::kMinOrder + 1 == 5, "one table per order");

std::vector<Array3> LineNodes(int n) {
  std::vector<Array3> x = {Array3(-1, 0, 0), Array3(1, 0, 0), Array3(0, 0, 0)};
  x.resize(n);
  return x;
}

std::vector<Array3> QuadrilateralNodes(int n) {
  std::vector<Array3> x = {Array3(-1, -1, 0), Array3(1, -1, 0), Array3(1, 1, 0),  Array3(-1, 1, 0), Array3(0, -1, 0),
                           Array3(1, 0, 0),   Array3(0, 1, 0),  Array3(-1, 0, 0), Array3(0, 0, 0)};
  x.resize(n);
  return x;
}

// Corners, the 12 mid-edges (bottom, vertical, top), the 6 face centres (bottom, front y=-1,
// right x=1, back y=1, left x=-1, top), the body centre.
std::vector<Array3> HexahedronNodes(int n) {
  std::vector<Array3> x = {
      Array3(-1, -1, -1), Array3(1, -1, -1), Array3(1, 1, -1),  Array3(-1, 1, -1), Array3(-1, -1, 1), Array3(1, -1, 1),
      Array3(1, 1, 1),    Array3(-1, 1, 1),  Array3(0, -1, -1), Array3(1, 0, -1),  Array3(0, 1, -1),  Array3(-1, 0, -1),
      Array3(-1, -1, 0),  Array3(1, -1, 0),  Array3(1, 1, 0),   Array3(-1, 1, 0),  Array3(0, -1, 1),  Array3(1, 0, 1),
      Array3(0, 1, 1),    Array3(-1, 0, 1),  Array3(0, 0, -1),  Array3(0, -1, 0),  Array3(1, 0, 0),   Array3(0, 1, 0),
      Array3(-1, 0, 0),   Array3(0, 0, 1),   Array3(0, 0, 0)};
  x.resize(n);
  return x;
}

// Corners of a simplex followed by the midpoints of `edges`.
std::vector<Array3> SimplexNodes(int dim, const std::vector<std::array<int, 2>>& edges) {
  std::vector<Array3> x(dim + 1, Array3::Zero());
  for (int d = 0; d < dim; ++d) x[d + 1][d] = 1.0;
  for (const auto& e : edges) x.push_back(0.5 * (x[e[0]] + x[e[1]]));
  return x;
}

using Faces = std::vector<ReferenceElement::Face>;

Faces LineFaces(GT point) { return {{point, {0}}, {point, {1}}}; }

Faces TriangleFaces(GT line, bool quadratic) {
  if (quadratic) return {{line, {0, 1, 3}}, {line, {1, 2, 4}}, {line, {2, 0, 5}}};
  return {{line, {0, 1}}, {line, {1, 2}}, {line, {2, 0}}};
}

Faces QuadrilateralFaces(GT line, bool quadratic) {
  if (quadratic) return {{line, {0, 1, 4}}, {line, {1, 2, 5}}, {line, {2, 3, 6}}, {line, {3, 0, 7}}};
  return {{line, {0, 1}}, {line, {1, 2}}, {line, {2, 3}}, {line, {3, 0}}};
}

// Face i is opposite node i.
Faces TetrahedronFaces(bool quadratic) {
  if (quadratic)
    return {{GT::Triangle3D6, {1, 2, 3, 5, 9, 8}},
            {GT::Triangle3D6, {0, 3, 2, 7, 9, 6}},
            {GT::Triangle3D6, {0, 1, 3, 4, 8, 7}},
            {GT::Triangle3D6, {0, 2, 1, 6, 5, 4}}};
  return {{GT::Triangle3D3, {1, 2, 3}},
          {GT::Triangle3D3, {0, 3, 2}},
          {GT::Triangle3D3, {0, 1, 3}},
          {GT::Triangle3D3, {0, 2, 1}}};
}

// Bottom, front, right, back, left, top; corners, then mid-edges, then the face centre.
Faces HexahedronFaces(int nodes) {
  const std::vector<std::vector<int>> full = {{3, 2, 1, 0, 10, 9, 8, 11, 20},   {0, 1, 5, 4, 8, 13, 16, 12, 21},
                                              {2, 6, 5, 1, 14, 17, 13, 9, 22},  {7, 6, 2, 3, 18, 14, 10, 15, 23},
                                              {7, 3, 0, 4, 15, 11, 12, 19, 24}, {4, 5, 6, 7, 16, 17, 18, 19, 25}};
  const GT type = nodes == 8 ? GT::Quadrilateral3D4 : nodes == 20 ? GT::Quadrilateral3D8 : GT::Quadrilateral3D9;
  const std::size_t face_nodes = nodes == 8 ? 4 : nodes == 20 ? 8 : 9;
  Faces faces;
  for (const auto& f : full) faces.push_back({type, std::vector<int>(f.begin(), f.begin() + face_nodes)});
  return faces;
}

Faces PrismFaces() {
  return {{GT::Triangle3D3, {0, 2, 1}},
          {GT::Triangle3D3, {3, 4, 5}},
          {GT::Quadrilateral3D4, {0, 1, 4, 3}},
          {GT::Quadrilateral3D4, {1, 2, 5, 4}},
          {GT::Quadrilateral3D4, {2, 0, 3, 5}}};
}

// 1D Lagrange factors at the nodes -1, 0, 1 (index c + 1) and their derivatives.
void Lagrange1D(int degree, double x, double* l, double* dl) {
  if (degree == 1) {
    l[0] = 0.5 * (1.0 - x), dl[0] = -0.5;
    l[1] = 0.0, dl[1] = 0.0;
    l[2] = 0.5 * (1.0 + x), dl[2] = 0.5;
  } else {
    l[0] = 0.5 * x * (x - 1.0), dl[0] = x - 0.5;
    l[1] = 1.0 - x * x, dl[1] = -2.0 * x;
    l[2] = 0.5 * x * (x + 1.0), dl[2] = x + 0.5;
  }
}

}  // namespace

const ReferenceElement& ReferenceElement::Get(GeometryType type) {
  static const std::vector<std::unique_ptr<const ReferenceElement>> all = [] {
    std::vector<std::unique_ptr<const ReferenceElement>> v;
    for (int t = 0; t <= static_cast<int>(GT::Prism3D6); ++t)
      v.push_back(std::make_unique<const ReferenceElement>(static_cast<GT>(t)));
    return v;
  }();
  return *all[static_cast<std::size_t>(type)];
}

ReferenceElement::ReferenceElement(GeometryType type) : type_(type) {
  const std::vector<std::array<int, 2>> tri_edges = {{0, 1}, {1, 2}, {2, 0}};
  const std::vector<std::array<int, 2>> tet_edges = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  switch (type) {
    case GT::Point2D:
    case GT::Point3D:
      family_ = GeometryFamily::Point;
      working_dim_ = type == GT::Point2D ? 2 : 3;
      local_dim_ = 0;
      basis_ = Basis::Point;
      nodes_local_ = {Array3::Zero()};
      break;
    case GT::Line2D2:
    case GT::Line2D3:
    case GT::Line3D2:
    case GT::Line3D3: {
      const bool quadratic = type == GT::Line2D3 || type == GT::Line3D3;
      family_ = GeometryFamily::Line;
      working_dim_ = type == GT::Line2D2 || type == GT::Line2D3 ? 2 : 3;
      local_dim_ = 1;
      basis_ = Basis::Lagrange;
      degree_ = quadratic ? 2 : 1;
      default_order_ = quadratic ? 3 : 1;
      nodes_local_ = LineNodes(quadratic ? 3 : 2);
      faces_ = LineFaces(working_dim_ == 2 ? GT::Point2D : GT::Point3D);
      break;
    }
    case GT::Triangle2D3:
    case GT::Triangle2D6:
    case GT::Triangle3D3:
    case GT::Triangle3D6: {
      const bool quadratic = type == GT::Triangle2D6 || type == GT::Triangle3D6;
      family_ = GeometryFamily::Triangle;
      working_dim_ = type == GT::Triangle2D3 || type == GT::Triangle2D6 ? 2 : 3;
      local_dim_ = 2;
      basis_ = Basis::Simplex;
      degree_ = quadratic ? 2 : 1;
      default_order_ = quadratic ? 2 : 1;
      if (quadratic) simplex_edges_ = tri_edges;
      nodes_local_ = SimplexNodes(2, simplex_edges_);
      const GT line =
          working_dim_ == 2 ? (quadratic ? GT::Line2D3 : GT::Line2D2) : (quadratic ? GT::Line3D3 : GT::Line3D2);
      faces_ = TriangleFaces(line, quadratic);
      break;
    }
    case GT::Quadrilateral2D4:
    case GT::Quadrilateral2D8:
    case GT::Quadrilateral2D9:
    case GT::Quadrilateral3D4:
    case GT::Quadrilateral3D8:
    case GT::Quadrilateral3D9: {
      const int n = type == GT::Quadrilateral2D4 || type == GT::Quadrilateral3D4   ? 4
                    : type == GT::Quadrilateral2D8 || type == GT::Quadrilateral3D8 ? 8
                                                                                   : 9;
      family_ = GeometryFamily::Quadrilateral;
      working_dim_ = type <= GT::Quadrilateral2D9 ? 2 : 3;
      local_dim_ = 2;
      basis_ = n == 8 ? Basis::Serendipity : Basis::Lagrange;
      degree_ = n == 4 ? 1 : 2;
      default_order_ = n == 4 ? 2 : 3;
      nodes_local_ = QuadrilateralNodes(n);
      const GT line = working_dim_ == 2 ? (n == 4 ? GT::Line2D2 : GT::Line2D3) : (n == 4 ? GT::Line3D2 : GT::Line3D3);
      faces_ = QuadrilateralFaces(line, n > 4);
      break;
    }
    case GT::Tetrahedra3D4:
    case GT::Tetrahedra3D10: {
      const bool quadratic = type == GT::Tetrahedra3D10;
      family_ = GeometryFamily::Tetrahedron;
      working_dim_ = 3;
      local_dim_ = 3;
      basis_ = Basis::Simplex;
      degree_ = quadratic ? 2 : 1;
      default_order_ = quadratic ? 2 : 1;
      measure_order_ = quadratic ? 3 : 1;  // det J of a curved Tetrahedra3D10 is cubic
      if (quadratic) simplex_edges_ = tet_edges;
      nodes_local_ = SimplexNodes(3, simplex_edges_);
      faces_ = TetrahedronFaces(quadratic);
      break;
    }
    case GT::Hexahedra3D8:
    case GT::Hexahedra3D20:
    case GT::Hexahedra3D27: {
      const int n = type == GT::Hexahedra3D8 ? 8 : type == GT::Hexahedra3D20 ? 20 : 27;
      family_ = GeometryFamily::Hexahedron;
      working_dim_ = 3;
      local_dim_ = 3;
      basis_ = n == 20 ? Basis::Serendipity : Basis::Lagrange;
      degree_ = n == 8 ? 1 : 2;
      default_order_ = n == 8 ? 2 : 3;
      nodes_local_ = HexahedronNodes(n);
      faces_ = HexahedronFaces(n);
      break;
    }
    case GT::Prism3D6:
      family_ = GeometryFamily::Prism;
      working_dim_ = 3;
      local_dim_ = 3;
      basis_ = Basis::Prism;
      default_order_ = 2;
      nodes_local_ = {Array3(0, 0, 0), Array3(1, 0, 0), Array3(0, 1, 0),
                      Array3(0, 0, 1), Array3(1, 0, 1), Array3(0, 1, 1)};
      faces_ = PrismFaces();
      break;
  }
  measure_order_ = std::max(measure_order_, default_order_);

  const int n = NodesNumber();
  double N[kMaxNodes], dN[3 * kMaxNodes];
  for (int order = Quadrature::kMinOrder; order <= Quadrature::kMaxOrder; ++order) {
    Tables& t = tables_[order - Quadrature::kMinOrder];
    t.points = Quadrature::Rule(family_, order);
    const auto ng = static_cast<Eigen::Index>(t.points.size());
    t.N.resize(ng, n);
    t.dN.assign(ng, Matrix(n, local_dim_));
    for (Eigen::Index g = 0; g < ng; ++g) {
      Evaluate(t.points[g].local, N, dN);
      for (int i = 0; i < n; ++i) {
        t.N(g, i) = N[i];
        for (int k = 0; k < local_dim_; ++k) t.dN[g](i, k) = dN[3 * i + k];
      }
    }
  }
}

const char* ReferenceElement::Name() const noexcept { return GeometryTypeName(type_); }

Array3 ReferenceElement::LocalCenter() const noexcept {
  switch (family_) {
    case GeometryFamily::Triangle: return Array3(1.0 / 3.0, 1.0 / 3.0, 0.0);
    case GeometryFamily::Tetrahedron: return Array3(0.25, 0.25, 0.25);
    case GeometryFamily::Prism: return Array3(1.0 / 3.0, 1.0 / 3.0, 0.5);
    default: return Array3::Zero();
  }
}

bool ReferenceElement::IsInside(const Array3& x, double tol) const noexcept {
  switch (family_) {
    case GeometryFamily::Point: return true;
    case GeometryFamily::Line:
    case GeometryFamily::Quadrilateral:
    case GeometryFamily::Hexahedron:
      for (int d = 0; d < local_dim_; ++d)
        if (std::abs(x[d]) > 1.0 + tol) return false;
      return true;
    case GeometryFamily::Triangle: return x[0] >= -tol && x[1] >= -tol && x[0] + x[1] <= 1.0 + tol;
    case GeometryFamily::Tetrahedron:
      return x[0] >= -tol && x[1] >= -tol && x[2] >= -tol && x[0] + x[1] + x[2] <= 1.0 + tol;
    case GeometryFamily::Prism:
      return x[0] >= -tol && x[1] >= -tol && x[0] + x[1] <= 1.0 + tol && x[2] >= -tol && x[2] <= 1.0 + tol;
  }
  return false;
}

void ReferenceElement::Evaluate(const Array3& x, double* N, double* dN) const noexcept {
  const int n = NodesNumber();
  for (int i = 0; i < 3 * n; ++i) dN[i] = 0.0;
  switch (basis_) {
    case Basis::Point: N[0] = 1.0; return;
    case Basis::Lagrange: {
      double l[3][3], dl[3][3];
      for (int d = 0; d < local_dim_; ++d) Lagrange1D(degree_, x[d], l[d], dl[d]);
      for (int i = 0; i < n; ++i) {
        int c[3];
        for (int d = 0; d < local_dim_; ++d) c[d] = static_cast<int>(nodes_local_[i][d]) + 1;
        N[i] = 1.0;
        for (int d = 0; d < local_dim_; ++d) N[i] *= l[d][c[d]];
        for (int k = 0; k < local_dim_; ++k) {
          double g = 1.0;
          for (int d = 0; d < local_dim_; ++d) g *= d == k ? dl[d][c[d]] : l[d][c[d]];
          dN[3 * i + k] = g;
        }
      }
      return;
    }
    case Basis::Serendipity: {
      // Corners: prod(1 + x c) (sum x c - (dim - 1)) / 2^dim; mid-edges (c_m = 0):
      // (1 - x_m^2) prod_{d != m}(1 + x_d c_d) / 2^(dim - 1).
      const int dim = local_dim_;
      for (int i = 0; i < n; ++i) {
        const Array3& c = nodes_local_[i];
        double a[3];
        int zero = -1;
        for (int d = 0; d < dim; ++d) {
          a[d] = 1.0 + x[d] * c[d];
          if (c[d] == 0.0) zero = d;
        }
        if (zero < 0) {
          double f = 1.0, s = 1.0 - dim;
          for (int d = 0; d < dim; ++d) f *= a[d], s += x[d] * c[d];
          const double scale = 1.0 / (1 << dim);
          N[i] = scale * f * s;
          for (int k = 0; k < dim; ++k) {
            double fk = 1.0;
            for (int d = 0; d < dim; ++d)
              if (d != k) fk *= a[d];
            dN[3 * i + k] = scale * c[k] * (fk * s + f);
          }
        } else {
          const double scale = 1.0 / (1 << (dim - 1));
          const double b = 1.0 - x[zero] * x[zero];
          double f = 1.0;
          for (int d = 0; d < dim; ++d)
            if (d != zero) f *= a[d];
          N[i] = scale * b * f;
          for (int k = 0; k < dim; ++k) {
            if (k == zero) {
              dN[3 * i + k] = -2.0 * scale * x[zero] * f;
              continue;
            }
            double fk = 1.0;
            for (int d = 0; d < dim; ++d)
              if (d != zero && d != k) fk *= a[d];
            dN[3 * i + k] = scale * b * c[k] * fk;
          }
        }
      }
      return;
    }
    case Basis::Simplex: {
      const int dim = local_dim_;
      double L[4], dL[4][3] = {};
      L[0] = 1.0;
      for (int d = 0; d < dim; ++d) {
        L[0] -= x[d];
        L[d + 1] = x[d];
        dL[0][d] = -1.0;
        dL[d + 1][d] = 1.0;
      }
      for (int i = 0; i <= dim; ++i) {
        const double f = degree_ == 1 ? 1.0 : 4.0 * L[i] - 1.0;
        N[i] = degree_ == 1 ? L[i] : L[i] * (2.0 * L[i] - 1.0);
        for (int k = 0; k < dim; ++k) dN[3 * i + k] = f * dL[i][k];
      }
      for (std::size_t e = 0; e < simplex_edges_.size(); ++e) {
        const int i = dim + 1 + static_cast<int>(e), a = simplex_edges_[e][0], b = simplex_edges_[e][1];
        N[i] = 4.0 * L[a] * L[b];
        for (int k = 0; k < dim; ++k) dN[3 * i + k] = 4.0 * (dL[a][k] * L[b] + L[a] * dL[b][k]);
      }
      return;
    }
    case Basis::Prism: {
      const double T[3] = {1.0 - x[0] - x[1], x[0], x[1]};
      const double dT[3][2] = {{-1.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}};
      const double Z[2] = {1.0 - x[2], x[2]};
      const double dZ[2] = {-1.0, 1.0};
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) {
          const int node = i + 3 * j;
          N[node] = T[i] * Z[j];
          dN[3 * node + 0] = dT[i][0] * Z[j];
          dN[3 * node + 1] = dT[i][1] * Z[j];
          dN[3 * node + 2] = T[i] * dZ[j];
        }
      return;
    }
  }
}

void ReferenceElement::ShapeFunctionsValues(const Array3& local, Vector& N) const {
  double values[kMaxNodes], gradients[3 * kMaxNodes];
  Evaluate(local, values, gradients);
  const int n = NodesNumber();
  if (N.size() != n) N.resize(n);
  for (int i = 0; i < n; ++i) N[i] = values[i];
}

void ReferenceElement::ShapeFunctionsLocalGradients(const Array3& local, Matrix& dN) const {
  double values[kMaxNodes], gradients[3 * kMaxNodes];
  Evaluate(local, values, gradients);
  const int n = NodesNumber();
  if (dN.rows() != n || dN.cols() != local_dim_) dN.resize(n, local_dim_);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < local_dim_; ++k) dN(i, k) = gradients[3 * i + k];
}

const ReferenceElement::Tables& ReferenceElement::TablesOf(int order) const {
  if (order < Quadrature::kMinOrder || order > Quadrature::kMaxOrder)
    throw InputError(Concat("integration order ", order, " of geometry ", Name(), " is not supported (orders ",
                            Quadrature::kMinOrder, "..", Quadrature::kMaxOrder, ")"));
  return tables_[order - Quadrature::kMinOrder];
}

const std::vector<IntegrationPoint>& ReferenceElement::IntegrationPoints(int order) const {
  return TablesOf(order).points;
}

const Matrix& ReferenceElement::ShapeFunctionsValues(int order) const { return TablesOf(order).N; }

const std::vector<Matrix>& ReferenceElement::ShapeFunctionsLocalGradients(int order) const {
  return TablesOf(order).dN;
}

}  // namespace mc
