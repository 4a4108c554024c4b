// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_strategies/custom_convergencecriterias/block_contact_criteria.h"

namespace mc {

/// "displacement_residual_contact_criteria": Displacement (and rotation) residuals; the penalty
/// formulations' residual criterion. Settings (Kratos' names and defaults): `ensure_contact`
/// (false), `print_convergence_criterion` (false) and the tolerance pairs (1e-4 relative, 1e-9
/// absolute) `residual_relative_tolerance` / `residual_absolute_tolerance`,
/// `rotation_residual_relative_tolerance` / `rotation_residual_absolute_tolerance`.
class DisplacementResidualContactCriteria : public BlockContactCriteria {
 public:
  static std::string DefaultParametersJson() {
    return R"({
      "name"                                 : "displacement_residual_contact_criteria",
      "ensure_contact"                       : false,
      "print_convergence_criterion"          : false,
      "residual_relative_tolerance"          : 1.0e-4,
      "residual_absolute_tolerance"          : 1.0e-9,
      "rotation_residual_relative_tolerance" : 1.0e-4,
      "rotation_residual_absolute_tolerance" : 1.0e-9
    })";
  }
  explicit DisplacementResidualContactCriteria(Parameters settings = Parameters())
      : DisplacementResidualContactCriteria(settings,
            ReadBlocks(settings, DefaultParametersJson(),
                       {BlockKeys{Measure::kResidual, "residual_relative_tolerance",
                                  "residual_absolute_tolerance"},
                        BlockKeys{Measure::kResidual, "rotation_residual_relative_tolerance",
                                  "rotation_residual_absolute_tolerance"},
                        std::nullopt})) {}
  std::string Name() const override { return "displacement_residual_contact_criteria"; }

 private:
  DisplacementResidualContactCriteria(Parameters& settings, const Blocks& blocks)
      : BlockContactCriteria(blocks, settings["ensure_contact"].GetBool(),
                             settings["print_convergence_criterion"].GetBool()) {}
};

}  // namespace mc
