// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "core/model/model_part.h"
#include "core/utilities/function_expression.h"

namespace mc {

/// Bulk operations on the nodes and conditions of a model part, used by the assignment
/// processes so that per-node work stays in C++.
class VariableUtils {
 public:
  /// Sets a historical double (or a component) on every node to the value of `expression`
  /// at (x, y, z, t) — current and initial coordinates — and fixes the DoF if `fix`. A node
  /// without that DoF is fixed only when it has it (the error names the first such node when
  /// `fix` is true and none has it).
  static void AssignNodalScalar(ModelPart& part, const Variable<double>& var, const FunctionExpression& expression,
                                double time, bool fix);
  static void AssignNodalScalar(ModelPart& part, const Variable<double>& var, double value, bool fix);
  /// Frees the DoF of `var` on every node of the part (if present).
  static void FreeDof(ModelPart& part, const Variable<double>& var);
  /// Sets a non-historical double (or component) on every condition, evaluating the expression
  /// at the condition's center.
  static void AssignConditionScalar(ModelPart& part, const Variable<double>& var, const FunctionExpression& expression,
                                    double time);
  static void AssignConditionScalar(ModelPart& part, const Variable<double>& var, double value);
  /// Adds the DoF of `var` (with reaction) to every node of the part.
  static void AddDof(ModelPart& part, const Variable<double>& var, const Variable<double>* reaction);
  /// Sets every node's current coordinates to X0 + DISPLACEMENT (step 0).
  static void UpdateCurrentPosition(ModelPart& part);
};

}  // namespace mc
