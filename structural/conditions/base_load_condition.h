// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "core/model/condition.h"

namespace mc {

/// Shared part of the structural load conditions: DISPLACEMENT DoFs of the working dimension,
/// the name "<Stem><dim>D<nodes>N", and the nodal load gathering.
/// Sign conventions as for elements: RHS = f_ext, LHS = -d f_ext / du (load stiffness).
class BaseLoadCondition : public Condition {
 public:
  std::string Info() const override;
  void GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const override;
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) override;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override;
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override;
  /// Nodes carry DISPLACEMENT and its DoFs.
  void Check(const ProcessInfo& info) const override;

 protected:
  using Condition::Condition;
  virtual const char* Stem() const = 0;
  virtual void CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info) = 0;

  int Dimension() const noexcept;
  /// Nodal historical value of `var` (zero when the nodes do not store it) of node a.
  Array3 NodalVector(const Variable<Array3>& var, std::size_t a) const;
  /// Net face pressure NEGATIVE_FACE_PRESSURE - POSITIVE_FACE_PRESSURE of node a (historical).
  double NodalPressure(std::size_t a) const;
  /// Net face pressure set on the condition itself.
  double ConditionPressure() const;
};

}  // namespace mc
