// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <vector>

#include "core/geometries/geometry.h"

namespace mc {

/// Everything about a geometry type that does not depend on the nodes: dimensions, node
/// local coordinates, shape functions, faces, and per-order tables of quadrature points,
/// shape-function values and local gradients. One instance per type, built once (thread-safe)
/// and shared by every Geometry of the type.
///
/// Local coordinates and node orderings follow Kratos/GiD (the .mdpa connectivities use them):
/// lines xi in [-1,1] (quadratic: end, end, middle); triangles and tetrahedra in area/volume
/// coordinates (N1 = 1 - xi - eta [- zeta]); quadrilaterals and hexahedra in [-1,1]^d, corners
/// counter-clockwise, then mid-edges, face centres and body centre; prisms are the triangle
/// (xi, eta) times zeta in [0,1], nodes 1-3 at zeta = 0 and 4-6 at zeta = 1.
class ReferenceElement {
 public:
  static constexpr int kMaxNodes = 27;

  /// A boundary entity: its type and the element-local indices of its nodes, ordered so that
  /// its normal points out of a positively oriented element.
  struct Face {
    GeometryType type;
    std::vector<int> nodes;
  };

  /// The shared instance of a type (built on first use, thread-safe).
  static const ReferenceElement& Get(GeometryType type);

  /// Builds the tables; prefer Get(), which shares one instance per type.
  explicit ReferenceElement(GeometryType type);

  GeometryType Type() const noexcept { return type_; }
  const char* Name() const noexcept;
  GeometryFamily Family() const noexcept { return family_; }
  int WorkingSpaceDimension() const noexcept { return working_dim_; }
  int LocalSpaceDimension() const noexcept { return local_dim_; }
  int NodesNumber() const noexcept { return static_cast<int>(nodes_local_.size()); }
  int DefaultIntegrationOrder() const noexcept { return default_order_; }
  /// Lowest order that integrates |det J| of a straight-or-curved solid exactly (at least the
  /// default order); surfaces and lines have non-polynomial measures.
  int MeasureIntegrationOrder() const noexcept { return measure_order_; }

  const std::vector<Array3>& NodesLocalCoordinates() const noexcept { return nodes_local_; }
  /// Barycentre of the reference element.
  Array3 LocalCenter() const noexcept;
  bool IsInside(const Array3& local, double tolerance) const noexcept;

  /// Shape functions N[i] and local gradients dN[3 * i + k] (k >= local dim set to zero) into
  /// caller buffers of NodesNumber() and 3 * NodesNumber() doubles. No allocation.
  void Evaluate(const Array3& local, double* N, double* dN) const noexcept;
  /// Resizes only when the size differs.
  void ShapeFunctionsValues(const Array3& local, Vector& N) const;
  /// dN(i, k), NodesNumber() x LocalSpaceDimension(); resizes only when the size differs.
  void ShapeFunctionsLocalGradients(const Array3& local, Matrix& dN) const;

  /// Tables for orders Quadrature::kMinOrder..kMaxOrder; throws InputError outside.
  const std::vector<IntegrationPoint>& IntegrationPoints(int order) const;
  const Matrix& ShapeFunctionsValues(int order) const;
  const std::vector<Matrix>& ShapeFunctionsLocalGradients(int order) const;

  const std::vector<Face>& Faces() const noexcept { return faces_; }

 private:
  enum class Basis { Point, Lagrange, Serendipity, Simplex, Prism };

  struct Tables {
    std::vector<IntegrationPoint> points;
    Matrix N;
    std::vector<Matrix> dN;
  };

  const Tables& TablesOf(int order) const;

  GeometryType type_;
  GeometryFamily family_;
  int working_dim_ = 0;
  int local_dim_ = 0;
  int default_order_ = 1;
  int measure_order_ = 1;
  Basis basis_ = Basis::Point;
  int degree_ = 1;  // polynomial degree of the basis
  std::vector<Array3> nodes_local_;
  std::vector<std::array<int, 2>> simplex_edges_;  // corner pairs of quadratic simplex mid-nodes
  std::vector<Face> faces_;
  std::array<Tables, 5> tables_;
};

}  // namespace mc
