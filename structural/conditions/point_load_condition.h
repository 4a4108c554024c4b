// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/conditions/base_load_condition.h"

namespace mc {

/// A nodal force: POINT_LOAD of the node (historical, when stored) plus the condition's own
/// POINT_LOAD value.
class PointLoadCondition : public BaseLoadCondition {
 public:
  using BaseLoadCondition::BaseLoadCondition;
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<PointLoadCondition>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }

 protected:
  const char* Stem() const override { return "PointLoadCondition"; }
  void CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info) override;
};

}  // namespace mc
