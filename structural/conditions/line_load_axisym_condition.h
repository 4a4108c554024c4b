// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/conditions/line_load_condition.h"

namespace mc {

/// LineLoadCondition in axisymmetry (x = radius): loads integrate with 2 pi R (reference
/// radius, LINE_LOAD) or 2 pi r (current radius, follower pressure).
class LineLoadAxisymCondition : public LineLoadCondition {
 public:
  LineLoadAxisymCondition(IndexType id, Geometry geometry, Properties* properties)
      : LineLoadCondition(id, std::move(geometry), properties, true) {}
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<LineLoadAxisymCondition>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }

 protected:
  const char* Stem() const override { return "LineLoadAxisymCondition"; }
};

}  // namespace mc
