// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/contact_condition_utilities.h"

#include "core/model/model_part.h"
#include "core/variables/kernel_variables.h"
#include "custom_conditions/paired_condition.h"
#include "custom_utilities/contact_variables.h"

namespace mc::ContactConditionUtilities {

void ComputeExplicitContributions(ModelPart& pairs, bool reset) {
  const ProcessInfo& info = pairs.GetProcessInfo();
  if (reset)
    for (Condition* condition : pairs.Conditions()) {
      if (!dynamic_cast<PairedCondition*>(condition)) continue;
      for (Node* node : condition->GetGeometry().Nodes()) {
        if (node->HasSolutionStepValue(WEIGHTED_GAP)) node->FastGetSolutionStepValue(WEIGHTED_GAP) = 0.0;
        node->SetValue(NODAL_AREA, 0.0);
      }
    }
  for (Condition* condition : pairs.Conditions())
    if (auto* pair = dynamic_cast<PairedCondition*>(condition); pair && pair->IsActive())
      pair->AddExplicitContribution(info);
}

}  // namespace mc::ContactConditionUtilities
