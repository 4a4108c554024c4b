// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>

#include "custom_utilities/mortar_updater.h"

namespace mc {

/// The MortarUpdater of the ALM and penalty contact processes: nodal normals of the `Contact`
/// interface from its conditions, and the weighted gap (and NODAL_AREA) of the slave nodes from
/// the explicit contribution of every pair condition of `ComputingContact`, and the adapted nodal
/// penalties of the `Contact` slave nodes (AdaptivePenaltyUtilities).
///
/// The dynamic factor (`compute_dynamic_factor`, dynamic problems; the seeds' DynamicFactor, which
/// scales a node's contact force): once per step, at its first iteration, the fraction of the step
/// during which a slave node that is open at the start of the step is in contact, from its weighted
/// gap at the start (buffer position 1), g_n > 0, and at the scheme's prediction (the first
/// iterate: Bossak's x + dt v + dt^2/2 a), g_p < 0: DYNAMIC_FACTOR = -g_p / (g_n - g_p), and 1 for
/// a node that does not close within the step. Kratos compares successive Newton iterates instead
/// and keeps a value once set; with the augmented Lagrangian the iterates converge to g = 0, where
/// that fraction tends to 0 and the contact force with it. Taken from the prediction, the factor
/// stays put while Newton converges.
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
  /// Sets DYNAMIC_FACTOR on the slave nodes of `Contact` at the first call of each STEP (the
  /// weighted gap is then the prediction's).
  void UpdateDynamicFactor(ModelPart& model_part) override;
  void AdaptPenalty(ModelPart& model_part) override;
  const Timings& GetTimings() const noexcept { return timings_; }

 private:
  Timings timings_;
  int dynamic_factor_step_ = -1;  ///< the STEP whose dynamic factors are set
};

}  // namespace mc
