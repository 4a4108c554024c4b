// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/parameters/parameters.h"

namespace mc {

/// Cutting back a step that does not converge, with the semantics of Kratos' contact
/// `adaptative_strategy`: the step restarts from its initial state as sub-steps of
/// DELTA_TIME / split_factor^s, for s = 1 .. max_number_splits, until one level converges.
/// The structural solvers read it from `solver_settings.step_splitting` (mortarcontact's keys;
/// Kratos' structural strategies have no splitting), the contact strategies from Kratos'
/// contact_settings keys.
struct StepSplitting {
  int max_number_splits = 0;  ///< split levels tried before giving up; 0: no splitting
  double split_factor = 2.0;  ///< DELTA_TIME divisor per level (2: halved)

  bool Enabled() const noexcept { return max_number_splits > 0; }

  /// {"max_number_splits": 0, "split_factor": 2.0}
  static Parameters GetDefaultParameters();
  /// Validates `settings` against the defaults (unknown keys are errors) and checks the ranges.
  static StepSplitting Read(Parameters settings);
};

}  // namespace mc
