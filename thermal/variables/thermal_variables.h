// SPDX-License-Identifier: BSD-3-Clause
// Heat conduction variables, named as in Kratos' ConvectionDiffusionApplication (TEMPERATURE
// itself is a kernel variable).
#pragma once

#include "core/variables/kernel_variables.h"

namespace mc {

/// Properties: the thermal conductivity k (isotropic).
MC_DECLARE_VARIABLE(double, CONDUCTIVITY);
/// Node, historical: the volumetric heat source Q, interpolated over the elements.
MC_DECLARE_VARIABLE(double, HEAT_FLUX);
/// Node, historical: the reaction of TEMPERATURE, the heat that enters where it is fixed.
MC_DECLARE_VARIABLE(double, REACTION_FLUX);

}  // namespace mc
