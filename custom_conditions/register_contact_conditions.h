// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace mc {

/// Registers the mortar contact pair conditions in Registry<Condition> (idempotent):
///   {ALM, ALMNV}Frictionless[Components]MortarContactCondition, {Penalty, PenaltyNV}Frictionless-
///   MortarContactCondition x {2D2N, 3D3N, 3D4N, 3D3N4N, 3D4N3N}, and the axisymmetric
///   {ALM, ALMNV, Penalty, PenaltyNV}FrictionlessAxisymMortarContactCondition2D2N.
void RegisterContactConditions();

}  // namespace mc
