// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/geometries/geometry_type.h"
#include "core/model/node.h"

namespace mc {

/// A point of a quadrature rule in local (parametric) coordinates.
struct IntegrationPoint {
  Array3 local;  ///< unused coordinates are zero
  double weight;
};

class ReferenceElement;

/// An element geometry: the nodes plus the reference element of its type (shape functions,
/// quadrature, faces). One class for all types; the type selects a ReferenceElement whose
/// tables (shape functions and gradients at quadrature points, per order) are computed once
/// and shared, so element loops read precomputed values.
class Geometry {
 public:
  using NodesArray = std::vector<Node*>;

  /// Throws InputError when the number of nodes does not match the type.
  Geometry(GeometryType type, NodesArray nodes);

  GeometryType Type() const noexcept;
  GeometryFamily Family() const noexcept;
  const char* Name() const noexcept;
  /// Dimension of the space the nodes live in (2 or 3).
  int WorkingSpaceDimension() const noexcept;
  /// Dimension of the parametric space (1 for lines, 2 for surfaces, 3 for solids).
  int LocalSpaceDimension() const noexcept;
  std::size_t PointsNumber() const noexcept { return nodes_.size(); }
  /// Default quadrature order of the type (Kratos' defaults: 1 for linear simplices, 2 for
  /// quadrilaterals/hexahedra and quadratic simplices, 3 for quadratic quads/hexes).
  int DefaultIntegrationOrder() const noexcept;

  Node& operator[](std::size_t i) const noexcept { return *nodes_[i]; }
  Node* pGetNode(std::size_t i) const noexcept { return nodes_[i]; }
  const NodesArray& Nodes() const noexcept { return nodes_; }
  NodesArray& Nodes() noexcept { return nodes_; }

  // Quadrature and shape-function tables, supported orders 1..5 -----------------------------
  const std::vector<IntegrationPoint>& IntegrationPoints(int order) const;
  /// N(g, i): shape function i at integration point g.
  const Matrix& ShapeFunctionsValues(int order) const;
  /// dN[g](i, k): derivative of shape function i w.r.t. local coordinate k at point g.
  const std::vector<Matrix>& ShapeFunctionsLocalGradients(int order) const;

  // Evaluation at any local point -----------------------------------------------------------
  void ShapeFunctionsValues(const Array3& local, Vector& N) const;
  void ShapeFunctionsLocalGradients(const Array3& local, Matrix& dN) const;

  /// J(i, k) = sum_n x_n,i dN(n, k): working-dim x local-dim.
  void Jacobian(const Matrix& dN, Matrix& J, Configuration c = Configuration::Current) const;
  /// Local to global coordinates.
  Array3 GlobalCoordinates(const Array3& local, Configuration c = Configuration::Current) const;
  /// Newton inversion of the map; returns false when it does not converge.
  bool PointLocalCoordinates(const Array3& global, Array3& local, Configuration c = Configuration::Current) const;
  /// Whether a local point lies inside the reference element (with tolerance).
  bool IsInsideLocal(const Array3& local, double tolerance = 1e-12) const;

  /// Length, area or volume.
  double DomainSize(Configuration c = Configuration::Current) const;
  Array3 Center(Configuration c = Configuration::Current) const;
  /// Unit normal of a line (in 2D: tangent rotated by -90 degrees, Kratos' orientation) or of a
  /// surface in 3D (cross product of the tangents) at a local point.
  Array3 UnitNormal(const Array3& local, Configuration c = Configuration::Current) const;

  /// Boundary entities: local node indices of each face (edges in 2D, faces in 3D), ordered so
  /// that face normals point outwards, and the geometry type of each face.
  std::vector<std::vector<int>> Faces() const;
  GeometryType FaceType(std::size_t face) const;

  const ReferenceElement& Reference() const noexcept { return *reference_; }

 private:
  const ReferenceElement* reference_;
  NodesArray nodes_;
};

}  // namespace mc
