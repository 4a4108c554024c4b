// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <memory>

namespace mc {

class ModelPart;

/// How the mortar criteria and the contact strategies refresh the mortar quantities without
/// knowing the contact conditions. The contact process (or the conditions' owner) provides
/// one; the criteria and strategies call it on the model part they solve:
///
///  - ComputeWeightedGap(model_part): the caller has already zeroed WEIGHTED_GAP (and
///    WEIGHTED_SLIP when present) on the nodes of the "Contact" sub-model-part; the updater
///    adds the weighted gap of every pair of "ComputingContact" to its slave nodes, at the
///    current coordinates (the explicit, right-hand-side-only evaluation of the mortar
///    conditions: g_j = -n_j . (D x1 - M x2)_j).
///  - UpdateNormals(model_part): recomputes the nodal NORMAL (and the paired normals stored in
///    the conditions) of the "Contact" sub-model-part; called before each build (the normals
///    follow the current configuration whatever CONSIDER_NORMAL_VARIATION says).
///  - UpdateDynamicFactor(model_part), AdaptPenalty(model_part): the dynamic factor
///    (`compute_dynamic_factor`, dynamic problems) and the adapted nodal INITIAL_PENALTY
///    (ProcessInfo[ADAPT_PENALTY]), refreshed before each build.
///
/// Without an updater the criteria leave WEIGHTED_GAP and NORMAL as they are (the conditions
/// may write them during assembly).
class MortarUpdater {
 public:
  virtual ~MortarUpdater() = default;
  virtual void ComputeWeightedGap(ModelPart& model_part) = 0;
  virtual void UpdateNormals(ModelPart& model_part) {}
  virtual void UpdateDynamicFactor(ModelPart& model_part) {}
  virtual void AdaptPenalty(ModelPart& model_part) {}
};

/// A MortarUpdater from two callables (either may be empty); what Python code and tests use.
class CallbackMortarUpdater : public MortarUpdater {
 public:
  using Callback = std::function<void(ModelPart&)>;
  explicit CallbackMortarUpdater(Callback compute_weighted_gap, Callback update_normals = {})
      : gap_(std::move(compute_weighted_gap)), normals_(std::move(update_normals)) {}
  void ComputeWeightedGap(ModelPart& model_part) override {
    if (gap_) gap_(model_part);
  }
  void UpdateNormals(ModelPart& model_part) override {
    if (normals_) normals_(model_part);
  }

 private:
  Callback gap_;
  Callback normals_;
};

}  // namespace mc
