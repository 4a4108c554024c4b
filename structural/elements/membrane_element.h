// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/model/element.h"

namespace mc {

/// Placeholder for Kratos' membrane elements (MembraneElement3D3N/3D4N), which appear in
/// mortar-mapping meshes only as geometry carriers: no DoFs; computing a local system throws
/// NotImplementedError naming the element.
class MembraneElement : public Element {
 public:
  using Element::Element;
  std::string Info() const override;
  std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override { dofs.clear(); }
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override;
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override;

 private:
  [[noreturn]] void Unsupported() const;
};

}  // namespace mc
