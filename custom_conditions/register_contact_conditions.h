// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace mc {

/// Registers the mortar contact pair conditions in Registry<Condition> (idempotent):
///   {ALMFrictionless, ALMFrictionlessComponents, PenaltyFrictionless}MortarContactCondition
///   x {2D2N, 3D3N, 3D4N, 3D3N4N, 3D4N3N};
/// and, as NotImplementedPairCondition placeholders that raise NotImplementedError when a pair
/// is created, the normal-variation names (ALMNVFrictionless..., ALMNVFrictionlessComponents...,
/// PenaltyNVFrictionless...) and the axisymmetric 2D2N names (...FrictionlessAxisym...).
void RegisterContactConditions();

}  // namespace mc
