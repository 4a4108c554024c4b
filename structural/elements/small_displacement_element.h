// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "structural/elements/base_solid_element.h"

namespace mc {

/// Small displacement (linear kinematics) solid element. Registered as "SmallDisplacementElement<dim>D<nodes>N".
class SmallDisplacementElement : public BaseSolidElement {
 public:
  SmallDisplacementElement(IndexType id, Geometry geometry, Properties* properties)
      : BaseSolidElement(id, std::move(geometry), properties, Kinematics::SmallDisplacement, false) {}
  std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override {
    return std::make_unique<SmallDisplacementElement>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
  }

 protected:
  const char* Stem() const override { return "SmallDisplacementElement"; }
};

}  // namespace mc
