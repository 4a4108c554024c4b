// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>

#include "core/solving/block_builder_and_solver.h"
#include "core/solving/explicit_central_differences_scheme.h"
#include "core/solving/solving_strategy.h"

namespace mc {

/// Explicit dynamics: per step one residual assembly and a nodal update with the lumped mass,
/// no linear system. The lumped mass of every DoF is assembled once (and again when the DoFs
/// are reformed) from the entities' mass matrices with COMPUTE_LUMPED_MASS_MATRIX set; each
/// node's mass is written to its NODAL_MASS value. The time step is the solver's (its
/// `time_stepping`, or its prediction from ElementStableTimeStep).
class ExplicitStrategy : public SolvingStrategy {
 public:
  ExplicitStrategy(ModelPart& model_part, std::shared_ptr<ExplicitCentralDifferencesScheme> scheme,
                   bool compute_reactions = true, bool reform_dofs_at_each_step = false, bool move_mesh_flag = true);

  std::string Name() const override { return "explicit"; }
  void Initialize() override;
  void InitializeSolutionStep() override;
  bool SolveSolutionStep() override;
  void FinalizeSolutionStep() override;
  void Clear() override;
  void Check() const override;

  /// Lumped mass of each DoF, by equation id.
  const Vector& LumpedMass() const noexcept { return mass_; }
  const BuilderAndSolver& GetBuilderAndSolver() const noexcept { return builder_; }

  /// The critical time step of central differences bounded element by element: 2 / omega_e,
  /// omega_e^2 the largest eigenvalue of M_e^-1 K_e with each element's stiffness at the current
  /// state and its lumped (row-sum) mass. The largest frequency of the assembled mesh never
  /// exceeds the largest element frequency (Irons' bound), so a time step below this one is
  /// stable for the elements; for a hexahedron of edge h it is about h / c with the dilatational
  /// wave speed c. Elements without a mass of their own (a spring between mass elements) are not
  /// bounded; infinity when none is.
  double ElementStableTimeStep() const;

  /// The DoF set and the lumped mass (and NODAL_MASS). InitializeSolutionStep calls it at the first
  /// step, and at every step when the DoFs are reformed; a time-step prediction needs the masses
  /// before the first step.
  void SetUpDofsAndMass();

 protected:
  /// Called at the start of every step's residual, at u_n (after the boundary conditions of the
  /// step are imposed): the explicit contact strategy updates the contact state here.
  virtual void UpdateBeforeResidual() {}
  /// Called right after the residual is assembled, before the update: the state is still u_n.
  virtual void UpdateAfterResidual() {}

 private:
  std::shared_ptr<ExplicitCentralDifferencesScheme> scheme_;
  BlockBuilderAndSolver builder_{nullptr};  ///< DoF numbering and residual assembly only
  bool compute_reactions_;
  bool reform_dofs_;
  bool dofs_ready_ = false;
  Vector mass_;
};

}  // namespace mc
