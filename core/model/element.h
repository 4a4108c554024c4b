// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>

#include "core/model/entity.h"

namespace mc {

/// A finite element of the domain. Concrete classes are registered by name in
/// Registry<Element> with a prototype whose geometry has the right type and no nodes.
class Element : public Entity {
 public:
  using Entity::Entity;
  /// A new element of the same class and geometry type on the given nodes.
  virtual std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const = 0;
  /// True when the left-hand side does not depend on the nodal unknowns, so that within a
  /// solution step (properties and geometry data fixed) it needs computing only once: the
  /// builder then reuses the assembled element matrix over the Newton iterations.
  virtual bool HasConstantLeftHandSide() const { return false; }
};

}  // namespace mc
