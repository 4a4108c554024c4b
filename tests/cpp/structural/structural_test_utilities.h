// SPDX-License-Identifier: BSD-3-Clause
// Helpers of the structural unit tests: nodes with displacement DoFs, properties with a law,
// entities created through the registry, a dense assembler and finite-difference tangents.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/geometries/reference_element.h"
#include "core/model/condition.h"
#include "core/model/constitutive_law.h"
#include "core/model/element.h"
#include "core/model/node.h"
#include "core/model/properties.h"
#include "core/model/registry.h"
#include "core/variables/kernel_variables.h"
#include "structural/application/register_structural_mechanics.h"
#include "tests/cpp/common/finite_differences.h"

namespace mc::test {

/// Owns nodes that store DISPLACEMENT (with DoFs and reactions), loads and body forces.
class NodeSet {
 public:
  NodeSet() {
    for (const VariableData* v : std::initializer_list<const VariableData*>{
             &DISPLACEMENT, &REACTION, &VOLUME_ACCELERATION, &LINE_LOAD, &SURFACE_LOAD, &POINT_LOAD,
             &POSITIVE_FACE_PRESSURE, &NEGATIVE_FACE_PRESSURE})
      variables_.Add(*v);
  }
  Node* Add(const Array3& x) {
    nodes_.push_back(std::make_unique<Node>(nodes_.size() + 1, x, variables_, 1));
    Node* node = nodes_.back().get();
    node->AddDof(DISPLACEMENT_X, &REACTION_X);
    node->AddDof(DISPLACEMENT_Y, &REACTION_Y);
    node->AddDof(DISPLACEMENT_Z, &REACTION_Z);
    return node;
  }
  std::vector<std::unique_ptr<Node>>& Nodes() { return nodes_; }
  Node& operator[](std::size_t i) { return *nodes_[i]; }
  std::size_t size() const { return nodes_.size(); }

 private:
  VariablesList variables_;
  std::vector<std::unique_ptr<Node>> nodes_;
};

inline std::unique_ptr<Properties> MakeProperties(IndexType id, const std::string& law, double young = 100.0,
                                                  double poisson = 0.3) {
  RegisterStructuralMechanics();
  auto properties = std::make_unique<Properties>(id);
  properties->SetValue(YOUNG_MODULUS, young);
  properties->SetValue(POISSON_RATIO, poisson);
  properties->SetValue(DENSITY, 2.5);
  properties->SetConstitutiveLaw(Registry<ConstitutiveLaw>::Instance().GetShared(law));
  return properties;
}

/// Deterministic values in [-1, 1].
inline double Pseudo(int i) { return std::sin(12.9898 * i + 78.233 * std::sin(0.37 * i)); }

/// Nodes of one element of `type` placed by a smooth, mildly non-affine map of the reference
/// element, shifted to x > 0 (axisymmetric meshes).
inline Geometry::NodesArray PlaceNodes(NodeSet& nodes, GeometryType type, bool affine = false) {
  const ReferenceElement& reference = ReferenceElement::Get(type);
  const int dim = reference.WorkingSpaceDimension();
  Eigen::Matrix3d A;
  A << 1.1, 0.2, 0.1, -0.15, 0.9, 0.05, 0.1, -0.1, 1.2;
  if (dim == 2) A.row(2).setZero(), A.col(2).setZero();
  Geometry::NodesArray result;
  for (const Array3& xi : reference.NodesLocalCoordinates()) {
    Array3 x = A * xi + Array3(2.0, 0.5, dim == 3 ? 0.3 : 0.0);
    if (!affine) {
      x[0] += 0.05 * xi[1] * xi[1];
      x[1] += 0.04 * xi[0] * xi[dim - 1];
      if (dim == 3) x[2] += 0.03 * xi[0] * xi[1];
    }
    result.push_back(nodes.Add(x));
  }
  return result;
}

inline void SetDisplacements(const Geometry& geometry, const std::function<Array3(const Array3&, int)>& u) {
  for (std::size_t a = 0; a < geometry.PointsNumber(); ++a) {
    Node& node = geometry[a];
    Array3 value = u(node.X0(), static_cast<int>(a));
    if (geometry.WorkingSpaceDimension() == 2) value[2] = 0.0;
    node.FastGetSolutionStepValue(DISPLACEMENT) = value;
    node.Coordinates() = node.X0() + value;
  }
}

/// max |a - b| / max |a|.
inline double RelativeError(const Matrix& a, const Matrix& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(a.cwiseAbs().maxCoeff(), 1e-300);
}

inline std::string Suffix(GeometryType type) {
  const ReferenceElement& r = ReferenceElement::Get(type);
  return std::to_string(r.WorkingSpaceDimension()) + "D" + std::to_string(r.NodesNumber()) + "N";
}

inline const std::vector<GeometryType>& Solids2D() {
  static const std::vector<GeometryType> types = {GeometryType::Triangle2D3, GeometryType::Triangle2D6,
                                                  GeometryType::Quadrilateral2D4, GeometryType::Quadrilateral2D8,
                                                  GeometryType::Quadrilateral2D9};
  return types;
}

inline const std::vector<GeometryType>& Solids3D() {
  static const std::vector<GeometryType> types = {GeometryType::Tetrahedra3D4, GeometryType::Tetrahedra3D10,
                                                  GeometryType::Hexahedra3D8,  GeometryType::Hexahedra3D20,
                                                  GeometryType::Hexahedra3D27, GeometryType::Prism3D6};
  return types;
}

}  // namespace mc::test
