// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace mc {

class ModelPart;

/// Advances one model part by one time (or load) step. The analysis calls Initialize once,
/// then per step InitializeSolutionStep, Predict, SolveSolutionStep, FinalizeSolutionStep
/// (or Solve, which does the four).
class SolvingStrategy {
 public:
  SolvingStrategy(ModelPart& model_part, bool move_mesh_flag);
  SolvingStrategy(const SolvingStrategy&) = delete;
  SolvingStrategy& operator=(const SolvingStrategy&) = delete;
  virtual ~SolvingStrategy() = default;

  /// The settings name ("linear", "newton_raphson", "line_search", "explicit").
  virtual std::string Name() const = 0;

  virtual void Initialize() { initialized_ = true; }
  bool IsInitialized() const noexcept { return initialized_; }
  virtual void InitializeSolutionStep() {}
  virtual void Predict() {}
  /// Returns false when the step did not converge; the model keeps the last iterate.
  virtual bool SolveSolutionStep() = 0;
  virtual void FinalizeSolutionStep() {}
  /// Initialize (first time), InitializeSolutionStep, Predict, SolveSolutionStep,
  /// FinalizeSolutionStep; returns whether the step converged.
  virtual bool Solve();
  /// Frees the system and the DoF set; the next step sets them up again.
  virtual void Clear() {}
  /// Validates the model (entities, variables) before the first step.
  virtual void Check() const {}

  virtual void SetEchoLevel(int level) { echo_level_ = level; }
  int GetEchoLevel() const noexcept { return echo_level_; }
  bool MoveMeshFlag() const noexcept { return move_mesh_; }
  void SetMoveMeshFlag(bool value) noexcept { move_mesh_ = value; }
  /// Current coordinates = initial coordinates + DISPLACEMENT, for every node.
  void MoveMesh();

  ModelPart& GetModelPart() const noexcept { return model_part_; }

 protected:
  ModelPart& model_part_;
  int echo_level_ = 0;
  bool move_mesh_;
  bool initialized_ = false;
};

}  // namespace mc
