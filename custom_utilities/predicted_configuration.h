// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <utility>
#include <vector>

#include "core/model/node.h"

namespace mc {

class ModelPart;

/// Moves the nodes of a part, for the lifetime of the object, to where the last step's motion
/// takes them within the next step:
///   x_pred = x + dt v + dt^2 / 2 a
/// with v, a the nodal VELOCITY and ACCELERATION and dt the ProcessInfo DELTA_TIME (the free-flight
/// prediction of Kratos' dynamic search). The destructor puts the coordinates back. Without a
/// historical VELOCITY (a static problem) or a positive DELTA_TIME nothing moves (`Moved()` false);
/// ACCELERATION is used when the model has it.
class PredictedConfiguration {
 public:
  explicit PredictedConfiguration(ModelPart& part);
  PredictedConfiguration(const PredictedConfiguration&) = delete;
  PredictedConfiguration& operator=(const PredictedConfiguration&) = delete;
  ~PredictedConfiguration();

  bool Moved() const noexcept { return !saved_.empty(); }

 private:
  std::vector<std::pair<Node*, Array3>> saved_;  ///< each moved node and its coordinates
};

}  // namespace mc
