// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/conditions/base_load_condition.h"

namespace mc {

/// Distributed load on a line (2D edge or 3D line).
/// - LINE_LOAD (force per unit length; nodal historical values interpolated plus the
///   condition's value) is a dead load on the reference length.
/// - The net face pressure p = NEGATIVE_FACE_PRESSURE - POSITIVE_FACE_PRESSURE (nodal
///   historical interpolated plus condition value) is a follower load in 2D: it acts along the
///   current normal (the tangent rotated by -90 degrees, as Geometry::UnitNormal) on the
///   current length, and its load stiffness is in the LHS. 3D lines have no normal: a
///   pressure on them is an InputError.
/// 2D plane problems multiply by THICKNESS (default 1); the axisymmetric variant by 2 pi r.
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
