// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/predicted_configuration.h"

#include "core/model/model_part.h"
#include "core/variables/kernel_variables.h"

namespace mc {

PredictedConfiguration::PredictedConfiguration(ModelPart& part) {
  const double dt = part.GetProcessInfo().GetValue(DELTA_TIME);
  if (!part.HasNodalSolutionStepVariable(VELOCITY) || !(dt > 0.0)) return;
  const bool acceleration = part.HasNodalSolutionStepVariable(ACCELERATION);
  saved_.reserve(part.NumberOfNodes());
  for (Node* node : part.Nodes()) {
    saved_.emplace_back(node, node->Coordinates());
    Array3 step = dt * Array3(node->FastGetSolutionStepValue(VELOCITY));
    if (acceleration) step += 0.5 * dt * dt * Array3(node->FastGetSolutionStepValue(ACCELERATION));
    node->Coordinates() += step;
  }
}

PredictedConfiguration::~PredictedConfiguration() {
  for (auto& [node, coordinates] : saved_) node->Coordinates() = coordinates;
}

}  // namespace mc
