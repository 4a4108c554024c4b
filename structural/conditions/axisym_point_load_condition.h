// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/conditions/point_load_condition.h"

namespace mc {

/// A ring load in axisymmetry (x = radius), Kratos' AxisymPointLoadCondition2D1N: POINT_LOAD is a
/// force per unit length of the circle through the node, so the nodal force is 2 pi r POINT_LOAD
/// with r the current radius (its derivative is the LHS, except in a linear analysis). THICKNESS
/// plays no part (Kratos 10.4 divides by it when present, as for AxisymLineLoadCondition).
class AxisymPointLoadCondition : public PointLoadCondition {
 public:
  using PointLoadCondition::PointLoadCondition;
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<AxisymPointLoadCondition>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }

 protected:
  const char* Stem() const override { return "AxisymPointLoadCondition"; }
  void CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info) override;
};

}  // namespace mc
