// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "core/solving/convergence_criteria.h"

namespace mc {

/// One Newton iteration as the strategy saw it: what Python prints as the convergence table
/// and tests use to measure convergence rates.
struct IterationRecord {
  int iteration = 0;
  double time = 0.0;              ///< TIME of the step (of the sub-step when the step is split)
  double residual_norm = 0.0;     ///< |f_ext - f_int| over free DoFs at the start of the iteration
  double increment_norm = 0.0;    ///< |du| applied in the iteration
  double step_length = 1.0;       ///< line-search factor applied to the Newton increment
  double linear_tolerance = 0.0;  ///< relative residual the linear solve was asked for (0: direct)
  int linear_iterations = 0;      ///< of the linear solve (1: direct)
  std::vector<CriterionValue> criteria;
  bool converged = false;
  int active_nodes = -1;  ///< slave nodes in contact (ACTIVE) after the iteration; -1 without a contact interface
};

}  // namespace mc
