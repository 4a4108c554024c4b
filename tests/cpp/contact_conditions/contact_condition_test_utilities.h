// SPDX-License-Identifier: BSD-3-Clause
// Builders shared by the contact condition tests (issue 3): a model part with the contact
// variables and DoFs, nodes, pair conditions, DoF perturbation and local-system assembly.
#pragma once

#include <map>
#include <memory>
#include <vector>

#include "core/model/model.h"
#include "core/model/model_part.h"
#include "core/variables/kernel_variables.h"
#include "custom_conditions/mortar_contact_condition.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/normal_calculation_utilities.h"

namespace mc::test {

/// Root model part with DISPLACEMENT, NORMAL, WEIGHTED_GAP and both multiplier variables.
inline ModelPart& MakeContactModelPart(Model& model) {
  ModelPart& root = model.CreateModelPart("Structure");
  for (const VariableData* var : std::initializer_list<const VariableData*>{
           &DISPLACEMENT, &REACTION, &NORMAL, &WEIGHTED_GAP, &LAGRANGE_MULTIPLIER_CONTACT_PRESSURE, &VECTOR_LAGRANGE_MULTIPLIER,
           &WEIGHTED_SCALAR_RESIDUAL, &WEIGHTED_VECTOR_RESIDUAL})
    root.AddNodalSolutionStepVariable(*var);
  return root;
}

/// A node with displacement and multiplier DoFs.
inline Node& MakeNode(ModelPart& part, IndexType id, const Array3& x) {
  Node& node = part.CreateNewNode(id, x[0], x[1], x[2]);
  node.AddDof(DISPLACEMENT_X, &REACTION_X);
  node.AddDof(DISPLACEMENT_Y, &REACTION_Y);
  node.AddDof(DISPLACEMENT_Z, &REACTION_Z);
  node.AddDof(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE, &WEIGHTED_SCALAR_RESIDUAL);
  node.AddDof(VECTOR_LAGRANGE_MULTIPLIER_X, &WEIGHTED_VECTOR_RESIDUAL_X);
  node.AddDof(VECTOR_LAGRANGE_MULTIPLIER_Y, &WEIGHTED_VECTOR_RESIDUAL_Y);
  node.AddDof(VECTOR_LAGRANGE_MULTIPLIER_Z, &WEIGHTED_VECTOR_RESIDUAL_Z);
  return node;
}

/// Sets a DoF value; for displacements also the current coordinates (x = X0 + u).
inline void SetDofValue(Dof& dof, double value) {
  dof.Value() = value;
  const Variable<double>* u[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
  for (int c = 0; c < 3; ++c)
    if (dof.variable == u[c]) dof.node->Coordinates()[c] = dof.node->X0()[c] + value;
}

/// Central finite differences of -RHS with respect to every DoF of the condition.
inline Matrix FiniteDifferenceLhs(Condition& condition, const ProcessInfo& info, double h) {
  DofsVectorType dofs;
  condition.GetDofList(dofs, info);
  const auto n = static_cast<Eigen::Index>(dofs.size());
  Matrix fd(n, n);
  Vector plus, minus;
  for (Eigen::Index q = 0; q < n; ++q) {
    const double value = dofs[q]->Value();
    SetDofValue(*dofs[q], value + h);
    condition.CalculateRightHandSide(plus, info);
    SetDofValue(*dofs[q], value - h);
    condition.CalculateRightHandSide(minus, info);
    SetDofValue(*dofs[q], value);
    fd.col(q) = -(plus - minus) / (2.0 * h);
  }
  return fd;
}

}  // namespace mc::test
