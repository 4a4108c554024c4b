// SPDX-License-Identifier: BSD-3-Clause
// What the contact criteria share: the split of the DoF set into families by DoF variable, the
// per-family norms, and the lookup of the contact sub-model-part.
#pragma once

#include <array>
#include <vector>

#include "core/linear_solvers/sparse_types.h"
#include "core/model/dof.h"

namespace mc {

class ModelPart;

/// DoF families measured separately: their magnitudes differ by orders (metres, radians,
/// pascals), so one global norm would hide the slowest of them.
enum class DofFamily { kDisplacement = 0, kRotation = 1, kMultiplier = 2 };
inline constexpr std::size_t kDofFamilies = 3;

/// ROTATION_X/Y/Z -> rotation; LAGRANGE_MULTIPLIER_CONTACT_PRESSURE, VECTOR_LAGRANGE_MULTIPLIER_X/
/// Y/Z and SCALAR_LAGRANGE_MULTIPLIER -> multiplier; any other variable (DISPLACEMENT_X/Y/Z and
/// whatever else the structure solves for) -> displacement.
DofFamily FamilyOf(const Variable<double>& variable) noexcept;

/// Sums over the free DoFs of one family: |dx|^2, |x|^2 (values after the update), |b|^2, count.
struct FamilySums {
  double increment = 0.0;
  double value = 0.0;
  double residual = 0.0;
  long count = 0;
};
using FamilySumsArray = std::array<FamilySums, kDofFamilies>;

/// One pass over the DoF set; `dx` and `b` are indexed by Dof::equation_id.
FamilySumsArray SumByFamily(const std::vector<Dof*>& dofs, const Vector& dx, const Vector& b);

/// The "Contact" sub-model-part of `model_part` or, failing that, of its root; null when there
/// is none (no contact defined yet: the active set is empty and trivially converged).
ModelPart* FindContactModelPart(ModelPart& model_part) noexcept;

}  // namespace mc
