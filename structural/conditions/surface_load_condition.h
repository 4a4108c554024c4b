// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/conditions/base_load_condition.h"

namespace mc {

/// Distributed load on a 3D surface, with Kratos 10.4's conventions:
/// - SURFACE_LOAD (force per unit area; nodal historical values interpolated plus the
///   condition's value) acts on the current area in a fixed direction.
/// - The net face pressure p = NEGATIVE_FACE_PRESSURE - POSITIVE_FACE_PRESSURE is a follower
///   load: f_a = int N_a p (x_,xi x x_,eta) dxi deta on the current surface (normal as
///   Geometry::UnitNormal).
/// The LHS holds both loads' stiffness (the derivative of the current area and normal), except
/// in a linear analysis (ProcessInfo LINEAR_ANALYSIS).
class SurfaceLoadCondition : public BaseLoadCondition {
 public:
  using BaseLoadCondition::BaseLoadCondition;
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<SurfaceLoadCondition>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }

 protected:
  const char* Stem() const override { return "SurfaceLoadCondition"; }
  void CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info) override;
};

}  // namespace mc
