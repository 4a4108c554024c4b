// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/convergence_criteria.h"

namespace mc {

/// "mesh_tying_mortar_criteria": mesh tying has no inequality, hence no active set; this
/// criterion always converges. It exists so that tying composes with the mechanical criterion
/// in a MortarAndConvergenceCriteria exactly like contact.
class MeshTyingMortarConvergenceCriteria : public ConvergenceCriteria {
 public:
  std::string Name() const override { return "mesh_tying_mortar_criteria"; }
  bool PostCriteria(ModelPart&, const DofsArray&, const SparseMatrix&, const Vector&, const Vector&) override {
    return true;
  }
  std::vector<CriterionValue> LastValues() const override { return {}; }
};

}  // namespace mc
