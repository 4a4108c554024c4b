// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/forcing_term.h"

namespace mc {

double ForcingTerm::ForIteration(int iteration) const noexcept { return iteration <= loose_solves_ ? loose_ : 0.0; }

}  // namespace mc
