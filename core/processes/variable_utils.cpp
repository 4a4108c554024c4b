// SPDX-License-Identifier: BSD-3-Clause
#include "core/processes/variable_utils.h"

#include "core/variables/kernel_variables.h"

namespace mc {

namespace {
void CheckHistorical(const ModelPart& part, const Variable<double>& var) {
  if (!part.HasNodalSolutionStepVariable(var))
    throw InputError(Concat(var.Name(), " is not a historical (solution-step) variable of ", part.FullName(),
                            ": it cannot be assigned to nodes"));
}
void FixIfPossible(Node& node, const Variable<double>& var, bool fix) {
  if (!fix) return;
  if (Dof* dof = node.FindDof(var)) dof->fixed = true;
}
}  // namespace

void VariableUtils::AssignNodalScalar(ModelPart& part, const Variable<double>& var,
                                      const FunctionExpression& expression, double time, bool fix) {
  CheckHistorical(part, var);
  for (Node* node : part.Nodes()) {
    const Array3& x = node->Coordinates();
    const Array3& x0 = node->X0();
    node->FastGetSolutionStepValue(var) = expression.Evaluate(x[0], x[1], x[2], time, x0[0], x0[1], x0[2]);
    FixIfPossible(*node, var, fix);
  }
}

void VariableUtils::AssignNodalScalar(ModelPart& part, const Variable<double>& var, double value, bool fix) {
  CheckHistorical(part, var);
  for (Node* node : part.Nodes()) {
    node->FastGetSolutionStepValue(var) = value;
    FixIfPossible(*node, var, fix);
  }
}

void VariableUtils::FreeDof(ModelPart& part, const Variable<double>& var) {
  for (Node* node : part.Nodes())
    if (Dof* dof = node->FindDof(var)) dof->fixed = false;
}

void VariableUtils::AssignConditionScalar(ModelPart& part, const Variable<double>& var,
                                          const FunctionExpression& expression, double time) {
  for (Condition* condition : part.Conditions()) {
    const Geometry& g = condition->GetGeometry();
    const Array3 c = g.Center(Configuration::Current);
    const Array3 c0 = g.Center(Configuration::Initial);
    condition->Data().GetValueRef(var) = expression.Evaluate(c[0], c[1], c[2], time, c0[0], c0[1], c0[2]);
  }
}

void VariableUtils::AssignConditionScalar(ModelPart& part, const Variable<double>& var, double value) {
  for (Condition* condition : part.Conditions()) condition->Data().GetValueRef(var) = value;
}

void VariableUtils::AddDof(ModelPart& part, const Variable<double>& var, const Variable<double>* reaction) {
  for (Node* node : part.Nodes()) node->AddDof(var, reaction);
}

void VariableUtils::UpdateCurrentPosition(ModelPart& part) {
  if (!part.HasNodalSolutionStepVariable(DISPLACEMENT)) return;
  for (Node* node : part.Nodes()) node->Coordinates() = node->X0() + node->FastGetSolutionStepValue(DISPLACEMENT);
}

}  // namespace mc
