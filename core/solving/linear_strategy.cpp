// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/linear_strategy.h"

#include "core/model/model_part.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"

namespace mc {

bool LinearStrategy::SolveSolutionStep() {
  model_part_.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 1);
  model_part_.GetProcessInfo().SetValue(LINEAR_ANALYSIS, true);
  scheme_->InitializeNonLinIteration(model_part_);
  builder_->BuildAndSolve(*scheme_, model_part_);
  UpdateAndMoveMesh(builder_->Increment());
  scheme_->FinalizeNonLinIteration(model_part_);
  if (echo_level_ >= 1)
    Logger::Info(Concat("  linear solve: |r| = ", builder_->Norm(builder_->Residual()),
                        "  |du| = ", builder_->Norm(builder_->Increment())));
  return true;
}

}  // namespace mc
