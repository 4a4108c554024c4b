// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/residual_based_incremental_update_static_scheme.h"

#include "core/model/model_part.h"
#include "core/model/parallel_utilities.h"
#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"

namespace mc {

void ResidualBasedIncrementalUpdateStaticScheme::Predict(ModelPart& model_part, const DofsArray& dofs) {
  if (!extrapolate_) return;
  const ProcessInfo& info = model_part.GetProcessInfo();
  const double previous = info.GetValue(PREVIOUS_DELTA_TIME);
  // The first step has no previous step (its buffer positions 1 and 2 both hold the initial state).
  if (!(previous > 0.0)) return;
  const double ratio = info.GetValue(DELTA_TIME) / previous;
  const long n = static_cast<long>(dofs.size());
#pragma omp parallel for schedule(static) if (n >= kMinParallelDofs)
  for (long i = 0; i < n; ++i) {
    const Dof& dof = *dofs[i];
    if (!dof.fixed) dof.Value() = dof.Value(1) + ratio * (dof.Value(1) - dof.Value(2));
  }
}

void ResidualBasedIncrementalUpdateStaticScheme::Check(const ModelPart& model_part) const {
  Scheme::Check(model_part);
  if (extrapolate_ && model_part.GetBufferSize() < 3)
    throw InputError(Concat("the static scheme's extrapolating predictor reads the last two steps: model part '",
                            model_part.Name(), "' has buffer_size ", model_part.GetBufferSize(), ", it needs 3"));
}

}  // namespace mc
