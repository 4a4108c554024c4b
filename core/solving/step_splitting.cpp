// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/step_splitting.h"

#include "core/utilities/error.h"

namespace mc {

Parameters StepSplitting::GetDefaultParameters() {
  return Parameters(R"({
      "max_number_splits" : 0,
      "split_factor"      : 2.0
  })");
}

StepSplitting StepSplitting::Read(Parameters settings) {
  settings.ValidateAndAssignDefaults(GetDefaultParameters());
  StepSplitting s;
  s.max_number_splits = settings["max_number_splits"].GetInt();
  s.split_factor = settings["split_factor"].GetDouble();
  if (s.max_number_splits < 0)
    throw InputError(
        Concat(settings["max_number_splits"].Where(), ": ", s.max_number_splits, " must be 0 (no splitting) or more"));
  if (!(s.split_factor > 1.0))
    throw InputError(Concat(settings["split_factor"].Where(), ": ", s.split_factor, " must be greater than 1"));
  return s;
}

}  // namespace mc
