// SPDX-License-Identifier: BSD-3-Clause
#include "structural/conditions/axisym_point_load_condition.h"

#include <numbers>

#include "core/variables/kernel_variables.h"

namespace mc {

void AxisymPointLoadCondition::CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info) {
  const Node& node = GetGeometry()[0];
  const Array3 load = NodalVector(POINT_LOAD, 0) + GetValue(POINT_LOAD);
  const double two_pi = 2.0 * std::numbers::pi;
  const double radius = node.X0()[0] + node.FastGetSolutionStepValue(DISPLACEMENT_X);
  if (rhs) *rhs = two_pi * radius * load.head(2);
  if (lhs) {
    lhs->setZero(2, 2);
    if (!info.GetValue(LINEAR_ANALYSIS)) lhs->col(0) = -two_pi * load.head(2);
  }
}

}  // namespace mc
