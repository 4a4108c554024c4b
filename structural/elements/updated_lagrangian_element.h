// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/elements/base_solid_element.h"

namespace mc {

/// Updated Lagrangian finite-strain solid element (spatial gradients, Kirchhoff stress). Registered as "UpdatedLagrangianElement<dim>D<nodes>N".
class UpdatedLagrangianElement : public BaseSolidElement {
 public:
  UpdatedLagrangianElement(IndexType id, Geometry geometry, Properties* properties)
      : BaseSolidElement(id, std::move(geometry), properties, Kinematics::UpdatedLagrangian, false) {}
  std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<UpdatedLagrangianElement>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }

 protected:
  const char* Stem() const override { return "UpdatedLagrangianElement"; }
};

}  // namespace mc
