// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/model/element.h"

namespace mc {

/// Steady heat conduction, Kratos' LaplacianElement<dim>D<n>N: the nodal unknown TEMPERATURE
/// (reaction REACTION_FLUX), the conductivity matrix K_ab = int k grad N_a . grad N_b with k the
/// properties' CONDUCTIVITY, and the source f_a = int N_a Q with Q the nodal HEAT_FLUX
/// interpolated (0 where the nodes do not store it). The right-hand side is the residual f - K T.
/// In 2D per unit thickness, as Kratos. Its use here: the scalar field that ScalarMeshTying ties
/// across non-matching meshes.
class LaplacianElement : public Element {
 public:
  using Element::Element;
  std::string Info() const override;
  std::unique_ptr<Element> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  bool HasConstantLeftHandSide() const override { return true; }
  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override;
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override;
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override;
  /// A positive CONDUCTIVITY in the properties, and TEMPERATURE (a DoF) at every node.
  void Check(const ProcessInfo& info) const override;

 private:
  /// K and f (without the -K T of the residual).
  void ConductivityAndSource(Matrix& conductivity, Vector& source) const;
};

}  // namespace mc
