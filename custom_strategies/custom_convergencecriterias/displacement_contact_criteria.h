// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "custom_strategies/custom_convergencecriterias/block_contact_criteria.h"

namespace mc {

/// "displacement_contact_criteria": Displacement (and rotation) increments; the criterion of the
/// penalty formulations, which have no multipliers. Settings (Kratos' names and defaults):
/// `ensure_contact` (false), `print_convergence_criterion` (false) and the tolerance pairs (1e-4
/// relative, 1e-9 absolute) `displacement_relative_tolerance` / `displacement_absolute_tolerance`,
/// `rotation_relative_tolerance` / `rotation_absolute_tolerance`.
class DisplacementContactCriteria : public BlockContactCriteria {
 public:
  static std::string DefaultParametersJson() {
    return R"({
      "name"                            : "displacement_contact_criteria",
      "ensure_contact"                  : false,
      "print_convergence_criterion"     : false,
      "displacement_relative_tolerance" : 1.0e-4,
      "displacement_absolute_tolerance" : 1.0e-9,
      "rotation_relative_tolerance"     : 1.0e-4,
      "rotation_absolute_tolerance"     : 1.0e-9
    })";
  }
  explicit DisplacementContactCriteria(Parameters settings = Parameters())
      : DisplacementContactCriteria(settings,
            ReadBlocks(settings, DefaultParametersJson(),
                       {BlockKeys{Measure::kIncrement, "displacement_relative_tolerance",
                                  "displacement_absolute_tolerance"},
                        BlockKeys{Measure::kIncrement, "rotation_relative_tolerance",
                                  "rotation_absolute_tolerance"},
                        std::nullopt})) {}
  std::string Name() const override { return "displacement_contact_criteria"; }

 private:
  DisplacementContactCriteria(Parameters& settings, const Blocks& blocks)
      : BlockContactCriteria(blocks, settings["ensure_contact"].GetBool(),
                             settings["print_convergence_criterion"].GetBool()) {}
};

}  // namespace mc
