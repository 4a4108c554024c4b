// SPDX-License-Identifier: BSD-3-Clause
#include "structural/elements/membrane_element.h"

#include "core/geometries/reference_element.h"
#include "core/utilities/error.h"

namespace mc {

std::string MembraneElement::Info() const {
  return Concat("MembraneElement3D", GetGeometry().Reference().NodesNumber(), "N");
}

std::unique_ptr<Element> MembraneElement::Create(IndexType id, Geometry::NodesArray nodes,
                                                 Properties* properties) const {
  return std::make_unique<MembraneElement>(id, Geometry(GetGeometry().Type(), std::move(nodes)), properties);
}

void MembraneElement::Unsupported() const {
  throw NotImplementedError(
      Concat("element ", Id(), " (", Info(), ") is a geometry carrier only: membrane mechanics is not implemented"));
}

void MembraneElement::CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) { Unsupported(); }
void MembraneElement::CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) { Unsupported(); }
void MembraneElement::CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) { Unsupported(); }

}  // namespace mc
