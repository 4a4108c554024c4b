// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>

#include "core/solving/builder_and_solver.h"
#include "core/solving/scheme.h"
#include "core/solving/solving_strategy.h"

namespace mc {

/// What the linear and Newton-Raphson strategies share: a scheme, a builder-and-solver, the
/// DoF set (set up on the first step, or every step with `reform_dofs_at_each_step`) and the
/// reactions after each step (`compute_reactions`).
class ImplicitSolvingStrategy : public SolvingStrategy {
 public:
  ImplicitSolvingStrategy(ModelPart& model_part, std::shared_ptr<Scheme> scheme,
                          std::shared_ptr<BuilderAndSolver> builder_and_solver, bool compute_reactions,
                          bool reform_dofs_at_each_step, bool move_mesh_flag);

  void Initialize() override;
  void InitializeSolutionStep() override;
  void Predict() override;
  void FinalizeSolutionStep() override;
  void Clear() override;
  void Check() const override;
  void SetEchoLevel(int level) override;

  Scheme& GetScheme() const noexcept { return *scheme_; }
  BuilderAndSolver& GetBuilderAndSolver() const noexcept { return *builder_; }
  bool ComputeReactions() const noexcept { return compute_reactions_; }
  void SetComputeReactions(bool value) noexcept { compute_reactions_ = value; }
  bool ReformDofsAtEachStep() const noexcept { return reform_dofs_; }
  void SetReformDofsAtEachStep(bool value) noexcept { reform_dofs_ = value; }

 protected:
  /// Adds dx to the DoFs through the scheme and moves the mesh if requested.
  void UpdateAndMoveMesh(const Vector& dx);

  std::shared_ptr<Scheme> scheme_;
  std::shared_ptr<BuilderAndSolver> builder_;
  bool compute_reactions_;
  bool reform_dofs_;
  bool dofs_ready_ = false;
};

}  // namespace mc
