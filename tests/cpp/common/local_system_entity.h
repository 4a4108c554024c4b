// SPDX-License-Identifier: BSD-3-Clause
// Base of the test elements and conditions that compute their LHS and RHS together.
#pragma once

#include "core/model/entity.h"

namespace mc::test {

/// An Element or Condition (`Base`) whose CalculateLeftHandSide and CalculateRightHandSide are
/// its CalculateLocalSystem.
template <class Base>
class LocalSystemEntity : public Base {
 public:
  using Base::Base;
  void CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) override {
    Vector rhs;
    this->CalculateLocalSystem(lhs, rhs, info);
  }
  void CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) override {
    Matrix lhs;
    this->CalculateLocalSystem(lhs, rhs, info);
  }
};

}  // namespace mc::test
