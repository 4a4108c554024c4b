// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/solving_strategy.h"

#include "core/model/model_part.h"
#include "core/model/parallel_utilities.h"
#include "core/variables/kernel_variables.h"

namespace mc {

SolvingStrategy::SolvingStrategy(ModelPart& model_part, bool move_mesh_flag)
    : model_part_(model_part), move_mesh_(move_mesh_flag) {}

bool SolvingStrategy::Solve() {
  if (!initialized_) Initialize();
  InitializeSolutionStep();
  Predict();
  const bool converged = SolveSolutionStep();
  FinalizeSolutionStep();
  return converged;
}

void SolvingStrategy::MoveMesh() {
  if (!model_part_.HasNodalSolutionStepVariable(DISPLACEMENT))
    throw InputError(Concat("move_mesh_flag is set but DISPLACEMENT is not a historical variable of model part ",
                            model_part_.Name()));
  ParallelForEachEntity(model_part_.Nodes(), [](Node& node) {
    node.Coordinates() = node.X0() + node.FastGetSolutionStepValue(DISPLACEMENT);
  });
}

}  // namespace mc
