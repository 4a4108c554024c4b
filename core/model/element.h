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
  /// True when the left-hand side does not depend on the nodal unknowns and is the exact
  /// derivative of -RHS, so that the residual is affine, f - K u, with f fixed within a solution
  /// step (properties, loads and reference geometry change only between steps). The builder
  /// then assembles K once per step and forms the later residuals from it.
  virtual bool HasConstantLeftHandSide() const { return false; }
};

}  // namespace mc
