// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/contact_output_utilities.h"

#include "custom_utilities/contact_variables.h"

namespace mc {

std::size_t ClearInactiveForPost(ModelPart& part) {
  std::size_t cleared = 0;
  for (Node* node : part.Nodes()) {
    if (!node->Is(SLAVE) || node->Is(ACTIVE)) continue;
    if (node->Has(AUGMENTED_NORMAL_CONTACT_PRESSURE)) node->SetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE, 0.0);
    if (node->Has(AUGMENTED_TANGENT_CONTACT_PRESSURE))
      node->SetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE, Array3::Zero().eval());
    ++cleared;
  }
  return cleared;
}

}  // namespace mc
