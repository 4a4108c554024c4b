// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/conditions/line_load_condition.h"

namespace mc {

/// LineLoadCondition in axisymmetry (x = radius), Kratos' AxisymLineLoadCondition2D<n>N: LINE_LOAD
/// and the face pressure are per unit area of the current surface of revolution, so they
/// integrate with 2 pi r ds on the current edge. THICKNESS plays no part: Kratos 10.4 divides
/// these loads by THICKNESS when the properties have one, which its axisymmetric elements ignore
/// (a 1/t error that is not reproduced here).
class AxisymLineLoadCondition : public LineLoadCondition {
 public:
  AxisymLineLoadCondition(IndexType id, Geometry geometry, Properties* properties)
      : LineLoadCondition(id, std::move(geometry), properties, true) {}
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<AxisymLineLoadCondition>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }

 protected:
  const char* Stem() const override { return "AxisymLineLoadCondition"; }
};

}  // namespace mc
