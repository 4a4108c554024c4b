// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/elements/base_solid_element.h"

namespace mc {

/// Axisymmetric updated Lagrangian element (x = radius). Registered as "AxisymUpdatedLagrangianElement<dim>D<nodes>N".
class AxisymUpdatedLagrangianElement : public BaseSolidElement {
 public:
  AxisymUpdatedLagrangianElement(IndexType id, Geometry geometry, Properties* properties)
      : BaseSolidElement(id, std::move(geometry), properties, Kinematics::UpdatedLagrangian, true) {}
  std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<AxisymUpdatedLagrangianElement>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }

 protected:
  const char* Stem() const override { return "AxisymUpdatedLagrangianElement"; }
};

}  // namespace mc
