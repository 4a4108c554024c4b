// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/model/model_part.h"

namespace mc {

/// What the mesh-tying process does to the pairs of its ComputingContact part between searches.
class MeshTyingUtilities {
 public:
  /// Flags ACTIVE every slave node that an overlapping pair ties (the MixedULM solver condenses the
  /// multipliers of the ACTIVE slave nodes), fixes to zero the multipliers of the tie rows that have
  /// no free DoF in any pair (a Dirichlet
  /// condition on both sides of the interface at that node and component: the row is satisfied by the
  /// prescribed values and the support takes its load, so the multiplier would be undetermined and the
  /// system singular) and frees the multipliers of every other tied row. Mortar methods drop such rows
  /// (Wohlmuth 2000: multipliers at Dirichlet slave nodes); dropping every fixed slave DoF's row would
  /// also untie a free master DoF there, hence the test on the whole row. Call it after the Dirichlet
  /// conditions of the step are set. Returns the number of fixed multipliers.
  static std::size_t UpdateTiedSlaveNodes(ModelPart& computing_part);
};

}  // namespace mc
