// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"

#include <map>

#include "core/model/model_part.h"
#include "core/variables/kernel_variables.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/mortar_updater.h"

namespace mc {

DofFamily FamilyOf(const Variable<double>& variable) noexcept {
  const VariableData* source = variable.Source();
  if (source == &ROTATION) return DofFamily::kRotation;
  if (source == &VECTOR_LAGRANGE_MULTIPLIER || &variable == &LAGRANGE_MULTIPLIER_CONTACT_PRESSURE ||
      &variable == &SCALAR_LAGRANGE_MULTIPLIER)
    return DofFamily::kMultiplier;
  return DofFamily::kDisplacement;
}

namespace {

/// The free vector-multiplier components of one node, as vectors (missing components zero).
struct NodeMultiplier {
  const Node* node = nullptr;
  Array3 value = Array3::Zero();
  Array3 increment = Array3::Zero();
  Array3 residual = Array3::Zero();
  long count = 0;
};

void AddSquares(FamilySums& s, const Array3& value, const Array3& increment, const Array3& residual, long count) {
  s.value += value.squaredNorm();
  s.increment += increment.squaredNorm();
  s.residual += residual.squaredNorm();
  s.count += count;
}

}  // namespace

FamilySumsArray SumByFamily(const std::vector<Dof*>& dofs, const Vector& dx, const Vector& b, MultiplierSplit split) {
  FamilySumsArray sums{};
  // Ordered by node id, so that the sums do not depend on the DoF order.
  std::map<IndexType, NodeMultiplier> multipliers;
  for (const Dof* dof : dofs) {
    if (dof->fixed) continue;
    const auto id = dof->equation_id;
    const double value = dof->Value();
    if (split != MultiplierSplit::kNone && dof->variable->Source() == &VECTOR_LAGRANGE_MULTIPLIER) {
      NodeMultiplier& m = multipliers[dof->node->Id()];
      m.node = dof->node;
      const int c = dof->variable->ComponentIndex();
      m.value[c] = value;
      m.increment[c] = dx[id];
      m.residual[c] = b[id];
      ++m.count;
      continue;
    }
    FamilySums& s = sums[static_cast<std::size_t>(FamilyOf(*dof->variable))];
    s.increment += dx[id] * dx[id];
    s.value += value * value;
    s.residual += b[id] * b[id];
    ++s.count;
  }
  for (const auto& [node_id, m] : multipliers) {
    const Array3 n = m.node->FastGetSolutionStepValue(NORMAL);
    const auto normal_part = [&n](const Array3& v) -> Array3 { return n.dot(v) * n; };
    const Array3 value_n = normal_part(m.value);
    const Array3 increment_n = normal_part(m.increment);
    const Array3 residual_n = normal_part(m.residual);
    AddSquares(sums[static_cast<std::size_t>(DofFamily::kMultiplier)], value_n, increment_n, residual_n, m.count);
    const bool slip = split == MultiplierSplit::kFrictionalPureSlip || m.node->Is(SLIP);
    AddSquares(sums[static_cast<std::size_t>(slip ? DofFamily::kSlipMultiplier : DofFamily::kStickMultiplier)],
               m.value - value_n, m.increment - increment_n, m.residual - residual_n, m.count);
  }
  return sums;
}

ModelPart* FindContactModelPart(ModelPart& model_part) noexcept {
  if (model_part.HasSubModelPart("Contact")) return &model_part.GetSubModelPart("Contact");
  ModelPart& root = model_part.GetRootModelPart();
  if (root.HasSubModelPart("Contact")) return &root.GetSubModelPart("Contact");
  return nullptr;
}

void RecomputeWeightedGap(ModelPart& model_part, ModelPart& contact_part, MortarUpdater& updater) {
  const bool has_slip = contact_part.HasNodalSolutionStepVariable(WEIGHTED_SLIP);
  for (Node* p_node : contact_part.Nodes()) {
    Node& node = *p_node;
    node.FastGetSolutionStepValue(WEIGHTED_GAP) = 0.0;
    if (has_slip) node.FastGetSolutionStepValue(WEIGHTED_SLIP).setZero();
  }
  updater.ComputeWeightedGap(model_part);
}

}  // namespace mc
