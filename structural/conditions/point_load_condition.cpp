// SPDX-License-Identifier: BSD-3-Clause
#include "structural/conditions/point_load_condition.h"

#include "core/variables/kernel_variables.h"

namespace mc {

void PointLoadCondition::CalculateAll(Matrix* lhs, Vector* rhs, const ProcessInfo& info) {
  const int dim = Dimension();
  if (lhs) lhs->setZero(dim, dim);
  if (rhs) *rhs = (NodalVector(POINT_LOAD, 0) + GetValue(POINT_LOAD)).head(dim);
}

}  // namespace mc
