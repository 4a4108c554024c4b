// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "core/geometries/geometry.h"
#include "core/geometries/reference_element.h"
#include "core/model/node.h"

namespace mc::test {

inline std::vector<GeometryType> AllGeometryTypes() {
  std::vector<GeometryType> types;
  for (int t = 0; t <= static_cast<int>(GeometryType::Prism3D6); ++t) types.push_back(static_cast<GeometryType>(t));
  return types;
}

/// Measure (length, area, volume) of the reference element.
inline double ReferenceMeasure(GeometryFamily family) {
  switch (family) {
    case GeometryFamily::Point: return 1.0;
    case GeometryFamily::Line: return 2.0;
    case GeometryFamily::Triangle: return 0.5;
    case GeometryFamily::Quadrilateral: return 4.0;
    case GeometryFamily::Tetrahedron: return 1.0 / 6.0;
    case GeometryFamily::Hexahedron: return 8.0;
    case GeometryFamily::Prism: return 0.5;
  }
  return 0.0;
}

/// Owns nodes placed at F(local coordinates of the reference nodes) and the geometry on them.
class MappedGeometry {
 public:
  MappedGeometry(GeometryType type, const std::function<Array3(const Array3&)>& map) {
    const ReferenceElement& ref = ReferenceElement::Get(type);
    Geometry::NodesArray pointers;
    for (std::size_t i = 0; i < ref.NodesLocalCoordinates().size(); ++i) {
      nodes_.push_back(std::make_unique<Node>(i + 1, map(ref.NodesLocalCoordinates()[i]), list_, 1));
      pointers.push_back(nodes_.back().get());
    }
    geometry_ = std::make_unique<Geometry>(type, pointers);
  }
  const Geometry& operator*() const { return *geometry_; }
  const Geometry* operator->() const { return geometry_.get(); }
  Node& node(std::size_t i) { return *nodes_[i]; }

 private:
  VariablesList list_;
  std::vector<std::unique_ptr<Node>> nodes_;
  std::unique_ptr<Geometry> geometry_;
};

}  // namespace mc::test
