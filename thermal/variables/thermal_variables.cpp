// SPDX-License-Identifier: BSD-3-Clause
#include "thermal/variables/thermal_variables.h"

namespace mc {

MC_DEFINE_VARIABLE(double, CONDUCTIVITY);
MC_DEFINE_VARIABLE(double, HEAT_FLUX);
MC_DEFINE_VARIABLE(double, REACTION_FLUX);

}  // namespace mc
