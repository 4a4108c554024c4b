// SPDX-License-Identifier: BSD-3-Clause
// What the structural elements and load conditions share: their DISPLACEMENT unknowns, the
// check that the nodes carry them, and their Kratos names.
#pragma once

#include <string>
#include <string_view>

#include "core/geometries/geometry.h"
#include "core/model/entity.h"

namespace mc {

/// The DISPLACEMENT DoFs of the working dimension of `geometry`, node by node.
void GetDisplacementDofList(const Geometry& geometry, DofsVectorType& dofs);

/// InputError "<who>: node 7 has no solution-step variable DISPLACEMENT" (or "... has no DoF
/// DISPLACEMENT_Y") for the first node that lacks them.
void CheckDisplacementDofs(const Geometry& geometry, const std::string& who);

/// Kratos' name of a structural entity on `geometry`: ["Axisym"]<stem><dim>D<nodes>N, e.g.
/// "TotalLagrangianElement2D4N", "AxisymLineLoadCondition2D2N".
std::string StructuralEntityName(std::string_view stem, bool axisymmetric, const Geometry& geometry);

}  // namespace mc
