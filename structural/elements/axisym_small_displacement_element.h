// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/elements/base_solid_element.h"

namespace mc {

/// Axisymmetric small displacement element (x = radius, hoop strain u_r / R). Registered as "AxisymSmallDisplacementElement<dim>D<nodes>N".
class AxisymSmallDisplacementElement : public BaseSolidElement {
 public:
  AxisymSmallDisplacementElement(IndexType id, Geometry geometry, Properties* properties)
      : BaseSolidElement(id, std::move(geometry), properties, Kinematics::SmallDisplacement, true) {}
  std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<AxisymSmallDisplacementElement>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }

 protected:
  const char* Stem() const override { return "AxisymSmallDisplacementElement"; }
};

}  // namespace mc
