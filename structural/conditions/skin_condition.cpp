// SPDX-License-Identifier: BSD-3-Clause
#include "structural/conditions/skin_condition.h"

#include "core/geometries/reference_element.h"
#include "core/utilities/error.h"

namespace mc {

std::string SkinCondition::Info() const {
  const ReferenceElement& reference = GetGeometry().Reference();
  return Concat(reference.Family() == GeometryFamily::Line ? "LineCondition" : "SurfaceCondition",
                reference.WorkingSpaceDimension(), "D", reference.NodesNumber(), "N");
}

std::unique_ptr<Condition> SkinCondition::Create(IndexType id, Geometry::NodesArray nodes,
                                                 Properties* properties) const {
  return std::make_unique<SkinCondition>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
}

void SkinCondition::CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) {
  lhs.resize(0, 0);
  rhs.resize(0);
}

}  // namespace mc
