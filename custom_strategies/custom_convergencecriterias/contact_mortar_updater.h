// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_strategies/custom_convergencecriterias/mortar_updater.h"

namespace mc {

/// The MortarUpdater of the ALM and penalty contact processes: nodal normals of the `Contact`
/// interface from its conditions, and the weighted gap (and NODAL_AREA) of the slave nodes from
/// the explicit contribution of every pair condition of `ComputingContact`.
class ContactMortarUpdater : public MortarUpdater {
 public:
  void ComputeWeightedGap(ModelPart& model_part) override;
  void UpdateNormals(ModelPart& model_part) override;
};

}  // namespace mc
