// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>

#include "core/model/entity.h"

namespace mc {

/// A boundary or interface entity: loads, geometry-only skins, contact pairs. Registered by
/// name in Registry<Condition> like elements.
class Condition : public Entity {
 public:
  using Entity::Entity;
  virtual std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const = 0;
};

}  // namespace mc
