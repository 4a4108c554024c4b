// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>

#include "custom_utilities/mortar_updater.h"

namespace mc {

/// The MortarUpdater of the ALM and penalty contact processes: nodal normals of the `Contact`
/// interface from its conditions, and the weighted gap (and NODAL_AREA) of the slave nodes from
/// the explicit contribution of every pair condition of `ComputingContact`, and the adapted nodal
/// penalties of the `Contact` slave nodes (AdaptivePenaltyUtilities).
class ContactMortarUpdater : public MortarUpdater {
 public:
  /// Cumulative wall-clock seconds and calls, for benchmarks.
  struct Timings {
    double weighted_gap = 0.0;
    double normals = 0.0;
    std::size_t weighted_gap_calls = 0;
    std::size_t normals_calls = 0;
  };

  void ComputeWeightedGap(ModelPart& model_part) override;
  void UpdateNormals(ModelPart& model_part) override;
  void AdaptPenalty(ModelPart& model_part) override;
  const Timings& GetTimings() const noexcept { return timings_; }

 private:
  Timings timings_;
};

}  // namespace mc
