// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/variables/kernel_variables.h"

namespace mc {

/// First (order 1) or second (order 2) time derivative of a DoF variable: VELOCITY_X /
/// ACCELERATION_X for DISPLACEMENT_X, ANGULAR_VELOCITY_Y / ANGULAR_ACCELERATION_Y for
/// ROTATION_Y; null for DoFs without one (multipliers, temperatures), which dynamic schemes
/// treat as quasi-static.
inline const Variable<double>* TimeDerivativeOf(const Variable<double>& var, int order) {
  if (!var.IsComponent()) return nullptr;
  const int c = var.ComponentIndex();
  static const Variable<double>* const kLinear[2][3] = {{&VELOCITY_X, &VELOCITY_Y, &VELOCITY_Z},
                                                        {&ACCELERATION_X, &ACCELERATION_Y, &ACCELERATION_Z}};
  static const Variable<double>* const kAngular[2][3] = {
      {&ANGULAR_VELOCITY_X, &ANGULAR_VELOCITY_Y, &ANGULAR_VELOCITY_Z},
      {&ANGULAR_ACCELERATION_X, &ANGULAR_ACCELERATION_Y, &ANGULAR_ACCELERATION_Z}};
  if (var.Source() == &DISPLACEMENT) return kLinear[order - 1][c];
  if (var.Source() == &ROTATION) return kAngular[order - 1][c];
  return nullptr;
}

}  // namespace mc
