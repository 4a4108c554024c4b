// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/elements/base_solid_element.h"

namespace mc {

/// Axisymmetric total Lagrangian element (x = radius, hoop stretch r / R). Registered as "AxisymTotalLagrangianElement<dim>D<nodes>N".
class AxisymTotalLagrangianElement : public BaseSolidElement {
 public:
  AxisymTotalLagrangianElement(IndexType id, Geometry geometry, Properties* properties)
      : BaseSolidElement(id, std::move(geometry), properties, Kinematics::TotalLagrangian, true) {}
  std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<AxisymTotalLagrangianElement>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }

 protected:
  const char* Stem() const override { return "AxisymTotalLagrangianElement"; }
};

}  // namespace mc
