// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/conditions/base_load_condition.h"

namespace mc {

/// Distributed load on a line (2D edge or 3D line), with Kratos 10.4's conventions:
/// - LINE_LOAD (nodal historical values interpolated plus the condition's value) is a force per
///   unit length of the current line, in a fixed direction.
/// - The net face pressure p = NEGATIVE_FACE_PRESSURE - POSITIVE_FACE_PRESSURE (nodal
///   historical interpolated plus condition value) is a follower load in 2D: it acts along
///   (-t_y, t_x), t the current tangent, on the current length. 3D lines have no normal: a
///   pressure on them is an InputError.
/// Neither is multiplied by THICKNESS; the axisymmetric variant multiplies by 2 pi r (current
/// radius). Both loads' stiffness (the derivative of the current measure and normal) is in
/// the LHS, except in a linear analysis (ProcessInfo LINEAR_ANALYSIS).
class LineLoadCondition : public BaseLoadCondition {
 public:
  LineLoadCondition(IndexType id, Geometry geometry, Properties* properties)
      : BaseLoadCondition(id, std::move(geometry), properties) {}
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<LineLoadCondition>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }

 protected:
  LineLoadCondition(IndexType id, Geometry geometry, Properties* properties, bool axisymmetric)
      : BaseLoadCondition(id, std::move(geometry), properties), axisymmetric_(axisymmetric) {}
  const char* Stem() const override { return "LineLoadCondition"; }
  void CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info) override;

 private:
  bool axisymmetric_ = false;
};

}  // namespace mc
