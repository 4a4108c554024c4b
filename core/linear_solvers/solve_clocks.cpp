// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/solve_clocks.h"

namespace mc {

SolveClocks& SolveClocks::Process() {
  static SolveClocks clocks;
  return clocks;
}

}  // namespace mc
