// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/conditions/base_load_condition.h"

namespace mc {

/// Distributed load on a 3D surface.
/// - SURFACE_LOAD (force per unit area; nodal historical values interpolated plus the
///   condition's value) is a dead load on the reference area.
/// - The net face pressure p = NEGATIVE_FACE_PRESSURE - POSITIVE_FACE_PRESSURE is a follower
///   load: f_a = int N_a p (x_,xi x x_,eta) dxi deta on the current surface (normal as
///   Geometry::UnitNormal), with its load stiffness in the LHS.
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
