// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/implicit_solving_strategy.h"

namespace mc {

/// `analysis_type: linear`: one build and solve per step, u += dx. Sets ProcessInfo LINEAR_ANALYSIS:
/// configuration-dependent loads then add no stiffness, so K is the elastic stiffness alone (as in
/// Kratos, whose loads have none in any analysis).
class LinearStrategy : public ImplicitSolvingStrategy {
 public:
  LinearStrategy(ModelPart& model_part, std::shared_ptr<Scheme> scheme,
                 std::shared_ptr<BuilderAndSolver> builder_and_solver, bool compute_reactions = true,
                 bool reform_dofs_at_each_step = false, bool move_mesh_flag = false)
      : ImplicitSolvingStrategy(model_part, std::move(scheme), std::move(builder_and_solver), compute_reactions,
                                reform_dofs_at_each_step, move_mesh_flag) {}

  std::string Name() const override { return "linear"; }
  bool SolveSolutionStep() override;
};

}  // namespace mc
