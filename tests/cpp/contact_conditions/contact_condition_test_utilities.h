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
#include "tests/cpp/common/finite_differences.h"

namespace mc::test {

/// Root model part with DISPLACEMENT, NORMAL, WEIGHTED_GAP, WEIGHTED_SLIP and both multiplier variables.
inline ModelPart& MakeContactModelPart(Model& model) {
  ModelPart& root = model.CreateModelPart("Structure");
  for (const VariableData* var : std::initializer_list<const VariableData*>{
           &DISPLACEMENT, &REACTION, &NORMAL, &WEIGHTED_GAP, &WEIGHTED_SLIP, &LAGRANGE_MULTIPLIER_CONTACT_PRESSURE,
           &VECTOR_LAGRANGE_MULTIPLIER, &WEIGHTED_SCALAR_RESIDUAL, &WEIGHTED_VECTOR_RESIDUAL})
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

/// Friction inputs for the frictional pair conditions: nodal FRICTION_COEFFICIENT on `nodes`,
/// TANGENT_FACTOR and SLIP_AUGMENTATION_COEFFICIENT in the ProcessInfo.
inline void SetFrictionParameters(ModelPart& root, const std::vector<Node*>& nodes, double c_slip = 0.3) {
  int j = 0;
  for (Node* node : nodes) node->SetValue(FRICTION_COEFFICIENT, 0.3 + 0.05 * j++);
  root.GetProcessInfo().SetValue(TANGENT_FACTOR, 0.7);
  root.GetProcessInfo().SetValue(SLIP_AUGMENTATION_COEFFICIENT, c_slip);
}

/// Stores the pair's previous mortar operators D_n, M_n (InitializeSolutionStep) with its master
/// nodes moved by `offset`, so that the weighted slip of the current configuration is not zero.
inline void InitializeWithMasterOffset(Condition& pair, const Geometry& master, const Array3& offset,
                                       const ProcessInfo& info) {
  for (Node* node : master.Nodes()) node->Coordinates() += offset;
  pair.InitializeSolutionStep(info);
  for (Node* node : master.Nodes()) node->Coordinates() -= offset;
}

}  // namespace mc::test
