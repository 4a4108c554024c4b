// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/elements/base_solid_element.h"

namespace mc {

/// Total Lagrangian finite-strain solid element (Green-Lagrange strain, PK2 stress). Registered as "TotalLagrangianElement<dim>D<nodes>N".
class TotalLagrangianElement : public BaseSolidElement {
 public:
  TotalLagrangianElement(IndexType id, Geometry geometry, Properties* properties)
      : BaseSolidElement(id, std::move(geometry), properties, Kinematics::TotalLagrangian, false) {}
  std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<TotalLagrangianElement>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }

 protected:
  const char* Stem() const override { return "TotalLagrangianElement"; }
};

}  // namespace mc
