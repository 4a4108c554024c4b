// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace mc {

class ModelPart;

/// Loops over the pair conditions of a model part (typically "ComputingContact").
namespace ContactConditionUtilities {

/// Explicit (RHS-only) update of the mortar nodal quantities: every PairedCondition of `pairs`
/// adds its weighted gap to WEIGHTED_GAP and its nodal areas to NODAL_AREA of its slave nodes
/// (PairedCondition::AddExplicitContribution). With `reset`, both are first zeroed on the slave
/// nodes of the pairs (nodes without pairs are left alone). Inactive pairs are skipped.
/// This is what the MortarUpdater callback of the criteria and the strategy's Predict call.
void ComputeExplicitContributions(ModelPart& pairs, bool reset = true);

}  // namespace ContactConditionUtilities
}  // namespace mc
