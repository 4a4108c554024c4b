// SPDX-License-Identifier: BSD-3-Clause
// Finite-difference tangents, against which the tests check every analytical LHS.
#pragma once

#include <vector>

#include "core/model/entity.h"
#include "core/model/node.h"
#include "core/variables/kernel_variables.h"

namespace mc::test {

/// Sets a DoF value; for displacements also the current coordinates (x = X0 + u).
inline void SetDofValue(Dof& dof, double value) {
  dof.Value() = value;
  const Variable<double>* u[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
  for (int c = 0; c < 3; ++c)
    if (dof.variable == u[c]) dof.node->Coordinates()[c] = dof.node->X0()[c] + value;
}

/// Central finite differences of -residual() with respect to each of `dofs`, step h.
template <class Residual>
Matrix FiniteDifferenceJacobian(const std::vector<Dof*>& dofs, double h, Residual residual) {
  const auto n = static_cast<Eigen::Index>(dofs.size());
  Matrix fd(n, n);
  for (Eigen::Index q = 0; q < n; ++q) {
    Dof& dof = *dofs[static_cast<std::size_t>(q)];
    const double value = dof.Value();
    SetDofValue(dof, value + h);
    const Vector plus = residual();
    SetDofValue(dof, value - h);
    const Vector minus = residual();
    SetDofValue(dof, value);
    fd.col(q) = -(plus - minus) / (2.0 * h);
  }
  return fd;
}

/// Central finite differences of -RHS of `entity` with respect to its own DoFs.
inline Matrix FiniteDifferenceTangent(Entity& entity, double h, const ProcessInfo& info = ProcessInfo()) {
  DofsVectorType dofs;
  entity.GetDofList(dofs, info);
  return FiniteDifferenceJacobian(dofs, h, [&] {
    Vector rhs;
    entity.CalculateRightHandSide(rhs, info);
    return rhs;
  });
}

}  // namespace mc::test
