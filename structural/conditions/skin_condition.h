// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/model/condition.h"

namespace mc {

/// Geometry-only skin (LineCondition2D2N/2D3N, SurfaceCondition3D3N/3D4N) that mdpa files use
/// to carry contact and tying surfaces: no DoFs, empty local systems.
class SkinCondition : public Condition {
 public:
  using Condition::Condition;
  std::string Info() const override;
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties* properties) const override;
  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override { dofs.clear(); }
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override { lhs.resize(0, 0); }
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override { rhs.resize(0); }
};

}  // namespace mc
