// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"

#include "core/model/model_part.h"
#include "core/variables/kernel_variables.h"
#include "custom_utilities/contact_variables.h"

namespace mc {

DofFamily FamilyOf(const Variable<double>& variable) noexcept {
  const VariableData* source = variable.Source();
  if (source == &ROTATION) return DofFamily::kRotation;
  if (source == &VECTOR_LAGRANGE_MULTIPLIER || &variable == &LAGRANGE_MULTIPLIER_CONTACT_PRESSURE ||
      &variable == &SCALAR_LAGRANGE_MULTIPLIER)
    return DofFamily::kMultiplier;
  return DofFamily::kDisplacement;
}

FamilySumsArray SumByFamily(const std::vector<Dof*>& dofs, const Vector& dx, const Vector& b) {
  FamilySumsArray sums{};
  for (const Dof* dof : dofs) {
    if (dof->fixed) continue;
    FamilySums& s = sums[static_cast<std::size_t>(FamilyOf(*dof->variable))];
    const auto id = dof->equation_id;
    const double value = dof->Value();
    s.increment += dx[id] * dx[id];
    s.value += value * value;
    s.residual += b[id] * b[id];
    ++s.count;
  }
  return sums;
}

ModelPart* FindContactModelPart(ModelPart& model_part) noexcept {
  if (model_part.HasSubModelPart("Contact")) return &model_part.GetSubModelPart("Contact");
  ModelPart& root = model_part.GetRootModelPart();
  if (root.HasSubModelPart("Contact")) return &root.GetSubModelPart("Contact");
  return nullptr;
}

}  // namespace mc
