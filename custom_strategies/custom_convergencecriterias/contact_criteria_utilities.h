// SPDX-License-Identifier: BSD-3-Clause
// What the contact criteria and strategies share: the split of the DoF set into families by DoF
// variable, the per-family norms, the lookup of the contact sub-model-part and the refresh of its
// weighted gaps.
#pragma once

#include <array>
#include <vector>

#include "core/linear_solvers/sparse_types.h"
#include "core/model/dof.h"

namespace mc {

class ModelPart;
class MortarUpdater;

/// DoF families measured separately: their magnitudes differ by orders (metres, radians,
/// pascals), so one global norm would hide the slowest of them. The frictional criteria split
/// the vector multipliers further, node by node: kMultiplier then holds their normal part, and
/// the tangential part goes to kStickMultiplier or kSlipMultiplier (see SumByFamily).
enum class DofFamily { kDisplacement = 0, kRotation = 1, kMultiplier = 2, kStickMultiplier = 3, kSlipMultiplier = 4 };
inline constexpr std::size_t kDofFamilies = 5;

/// Whether SumByFamily splits VECTOR_LAGRANGE_MULTIPLIER into normal and tangential parts, the
/// tangential one by the SLIP flag of the node (kFrictional) or all to slip (kFrictionalPureSlip).
enum class MultiplierSplit { kNone, kFrictional, kFrictionalPureSlip };

/// ROTATION_X/Y/Z -> rotation; LAGRANGE_MULTIPLIER_CONTACT_PRESSURE, VECTOR_LAGRANGE_MULTIPLIER_X/
/// Y/Z and SCALAR_LAGRANGE_MULTIPLIER -> multiplier; any other variable (DISPLACEMENT_X/Y/Z and
/// whatever else the structure solves for) -> displacement. Never the stick or slip families.
DofFamily FamilyOf(const Variable<double>& variable) noexcept;

/// Sums over the free DoFs of one family: |dx|^2, |x|^2 (values after the update), |b|^2, count.
struct FamilySums {
  double increment = 0.0;
  double value = 0.0;
  double residual = 0.0;
  long count = 0;
};
using FamilySumsArray = std::array<FamilySums, kDofFamilies>;

/// One pass over the DoF set; `dx` and `b` are indexed by Dof::equation_id. With a frictional
/// `split`, the free VECTOR_LAGRANGE_MULTIPLIER components of each node are gathered into
/// vectors v (value, increment, residual) and projected on the unit nodal NORMAL n: (n.v)^2 goes
/// to kMultiplier, |v - (n.v) n|^2 to kStickMultiplier or kSlipMultiplier; each free component
/// counts once in both.
FamilySumsArray SumByFamily(const std::vector<Dof*>& dofs, const Vector& dx, const Vector& b,
                            MultiplierSplit split = MultiplierSplit::kNone);

/// The "Contact" sub-model-part of `model_part` or, failing that, of its root; null when there
/// is none (no contact defined yet: the active set is empty and trivially converged).
ModelPart* FindContactModelPart(ModelPart& model_part) noexcept;

/// Zeroes WEIGHTED_GAP (and WEIGHTED_SLIP where the part has it) of the nodes of `contact_part`
/// and asks `updater` to integrate them again at the current coordinates of `model_part`.
void RecomputeWeightedGap(ModelPart& model_part, ModelPart& contact_part, MortarUpdater& updater);

}  // namespace mc
