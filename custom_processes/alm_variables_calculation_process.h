// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/model/model_part.h"
#include "core/parameters/parameters.h"

namespace mc {

/// Automatic penalty and scale factor of the augmented Lagrangian (thesis eq. 4.11, spec 4.4):
/// for each side of the interface (SLAVE and MASTER conditions of `interface`),
///   E_side = volume-weighted mean YOUNG_MODULUS of the elements owning its faces,
///   h_side = area-weighted mean NODAL_H of its faces (mean of the face's nodes),
/// and with v = min(E_slave / h_slave, E_master / h_master) (the less stiff side; a side
/// without stiffness is ignored):
///   penalty      = penalty_multiplier * stiffness_factor * v        (below eps: penalty_floor)
///   scale factor = penalty_scale_factor * stiffness_factor * v      (below eps, or
///                  use_scale_factor false: 1)
/// The ALM process uses multiplier 1 / floor 1, the penalty process 1e4 / 1e16, the explicit
/// penalty process 1 / 1e13. Results go to ProcessInfo INITIAL_PENALTY and SCALE_FACTOR and to
/// the non-historical INITIAL_PENALTY of every interface node.
class ALMVariablesCalculationProcess {
 public:
  /// `settings`: the contact process' advance_ALM_parameters (its other keys are the process');
  /// the keys of GetDefaultParameters are read where they live, missing ones added.
  ALMVariablesCalculationProcess(ModelPart& root, ModelPart& interface, Parameters settings,
                                 double penalty_multiplier = 1.0, double penalty_floor = 1.0);
  /// stiffness_factor, penalty_scale_factor, use_scale_factor (Kratos' advance_ALM_parameters).
  static Parameters GetDefaultParameters();

  void Execute();
  double Penalty() const noexcept { return penalty_; }
  double ScaleFactor() const noexcept { return scale_factor_; }

 private:
  ModelPart& root_;
  ModelPart& interface_;
  Parameters settings_;
  double penalty_multiplier_;
  double penalty_floor_;
  double penalty_ = 0.0;
  double scale_factor_ = 0.0;
};

}  // namespace mc
