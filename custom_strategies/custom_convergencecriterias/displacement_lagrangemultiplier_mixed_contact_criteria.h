// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_strategies/custom_convergencecriterias/block_contact_criteria.h"

namespace mc {

/// "displacement_lagrange_multiplier_mixed_contact_criteria": Residual of the displacement (and
/// rotation) rows, increment of the multipliers: usually the most robust choice for ALM, because
/// the multiplier residual (the weak gap) is a poor indicator while the active set still changes.
/// Settings (Kratos' names and defaults): `ensure_contact` (false), `print_convergence_criterion`
/// (false) and the tolerance pairs (1e-4 relative, 1e-9 absolute) `residual_relative_tolerance` /
/// `residual_absolute_tolerance`, `rotation_residual_relative_tolerance` /
/// `rotation_residual_absolute_tolerance`, `contact_displacement_relative_tolerance` /
/// `contact_displacement_absolute_tolerance`.
class DisplacementLagrangeMultiplierMixedContactCriteria : public BlockContactCriteria {
 public:
  static std::string DefaultParametersJson() {
    return R"({
      "name"                                    : "displacement_lagrange_multiplier_mixed_contact_criteria",
      "ensure_contact"                          : false,
      "print_convergence_criterion"             : false,
      "residual_relative_tolerance"             : 1.0e-4,
      "residual_absolute_tolerance"             : 1.0e-9,
      "rotation_residual_relative_tolerance"    : 1.0e-4,
      "rotation_residual_absolute_tolerance"    : 1.0e-9,
      "contact_displacement_relative_tolerance" : 1.0e-4,
      "contact_displacement_absolute_tolerance" : 1.0e-9
    })";
  }
  explicit DisplacementLagrangeMultiplierMixedContactCriteria(Parameters settings = Parameters())
      : DisplacementLagrangeMultiplierMixedContactCriteria(settings,
            ReadBlocks(settings, DefaultParametersJson(),
                       {BlockKeys{Measure::kResidual, "residual_relative_tolerance",
                                  "residual_absolute_tolerance"},
                        BlockKeys{Measure::kResidual, "rotation_residual_relative_tolerance",
                                  "rotation_residual_absolute_tolerance"},
                        BlockKeys{Measure::kIncrement, "contact_displacement_relative_tolerance",
                                  "contact_displacement_absolute_tolerance"}})) {}
  std::string Name() const override { return "displacement_lagrange_multiplier_mixed_contact_criteria"; }

 private:
  DisplacementLagrangeMultiplierMixedContactCriteria(Parameters& settings, const Blocks& blocks)
      : BlockContactCriteria(blocks, settings["ensure_contact"].GetBool(),
                             settings["print_convergence_criterion"].GetBool()) {}
};

}  // namespace mc
