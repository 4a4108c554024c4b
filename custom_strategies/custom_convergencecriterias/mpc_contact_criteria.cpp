// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/custom_convergencecriterias/mpc_contact_criteria.h"

#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"
#include "custom_strategies/custom_convergencecriterias/contact_criteria_utilities.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/normal_calculation_utilities.h"

namespace mc {

namespace {

double YoungModulus(const ModelPart& root) {
  for (const Element* element : root.Elements())
    if (element->HasProperties() && element->GetProperties().Has(YOUNG_MODULUS))
      return element->GetProperties().GetValue(YOUNG_MODULUS);
  return 0.0;
}

}  // namespace

MPCContactCriteria::MPCContactCriteria(std::shared_ptr<const MPCContactConstraints> constraints)
    : constraints_(std::move(constraints)) {
  if (!constraints_) throw Error("mpc_contact_criteria needs the MPC contact constraints");
}

bool MPCContactCriteria::PostCriteria(ModelPart& model_part, const DofsArray&, const SparseMatrix&, const Vector&,
                                      const Vector&) {
  ModelPart* contact = FindContactModelPart(model_part);
  if (!contact) throw Error(Concat("mpc_contact_criteria: no Contact model part above ", model_part.FullName()));
  const ModelPart& root = model_part.GetRootModelPart();
  const ProcessInfo& info = root.GetProcessInfo();
  const double factor =
      info.Has(REACTION_CHECK_STIFFNESS_FACTOR) ? info.GetValue(REACTION_CHECK_STIFFNESS_FACTOR) : 1.0e-12;
  const double threshold = -factor * YoungModulus(root);
  changes_ = 0;
  for (Node* node : contact->Nodes()) {
    if (!node->Is(SLAVE)) continue;
    const double area = node->GetValue(NODAL_MAUX);
    const Array3 normal = NormalCalculationUtilities::GetNodalNormal(*node);
    const double force = node->FastGetSolutionStepValue(REACTION).dot(normal);
    const double pressure = area > 0.0 ? force / area : 0.0;
    const bool was_active = node->Is(ACTIVE);
    const bool active = area > 0.0 && (was_active ? pressure < threshold : constraints_->NodalGap(*node) < 0.0);
    if (active != was_active) ++changes_;
    node->Set(ACTIVE, active);
    node->SetValue(CONTACT_FORCE, active ? Array3(force * normal) : Array3(Array3::Zero()));
    node->SetValue(NORMAL_CONTACT_STRESS, active ? pressure : 0.0);
  }
  return changes_ == 0;
}

std::vector<CriterionValue> MPCContactCriteria::LastValues() const {
  return {{"active set changes", static_cast<double>(changes_), 0.0}};
}

}  // namespace mc
