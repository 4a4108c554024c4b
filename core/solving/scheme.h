// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

#include "core/model/entity.h"

namespace mc {

class ModelPart;

/// Time integration of the unknowns: what a builder assembles for each entity (the static
/// residual and tangent, or their dynamic effective versions), how the DoF values move with
/// a solution increment, and the per-step/per-iteration calls to the entities.
///
/// Increments and residuals are full-size vectors indexed by Dof::equation_id (every DoF of
/// the set, fixed ones included, whatever the builder's system numbering).
class Scheme {
 public:
  using DofsArray = std::vector<Dof*>;

  virtual ~Scheme() = default;
  virtual std::string Name() const = 0;

  /// Once, before the first step: calls Entity::Initialize.
  virtual void Initialize(ModelPart& model_part);
  bool IsInitialized() const noexcept { return initialized_; }
  virtual void InitializeSolutionStep(ModelPart& model_part);
  virtual void InitializeNonLinIteration(ModelPart& model_part);
  virtual void FinalizeNonLinIteration(ModelPart& model_part);
  virtual void FinalizeSolutionStep(ModelPart& model_part);
  /// First guess of the step for the free DoFs; the static default keeps the last values.
  virtual void Predict(ModelPart& model_part, const DofsArray& dofs) {}
  /// Whether Predict only extrapolates the last steps' values (no state of its own to make
  /// consistent), so that a strategy that knows the path turned in the last step may skip it.
  virtual bool Extrapolates() const { return false; }
  /// u += dx on the free DoFs (and whatever depends on u in derived schemes).
  virtual void Update(ModelPart& model_part, const DofsArray& dofs, const Vector& dx);
  /// Validates the entities (Entity::Check) and the scheme's own data.
  virtual void Check(const ModelPart& model_part) const;

  // Local contributions (called concurrently from the builder's threads) --------------------
  virtual void GetDofList(const Entity& entity, DofsVectorType& dofs, const ProcessInfo& info) const {
    entity.GetDofList(dofs, info);
  }
  /// True when the LHS contribution of an entity is its own left-hand side, with no term of
  /// the scheme added (inertia, damping): a constant element LHS then gives a constant
  /// contribution. Defaults to false, the safe answer for a scheme that adds terms.
  virtual bool PassesEntityLeftHandSide() const { return false; }
  virtual void CalculateSystemContributions(Entity& entity, Matrix& lhs, Vector& rhs, EquationIdVectorType& ids,
                                            const ProcessInfo& info);
  virtual void CalculateLHSContribution(Entity& entity, Matrix& lhs, EquationIdVectorType& ids,
                                        const ProcessInfo& info);
  virtual void CalculateRHSContribution(Entity& entity, Vector& rhs, EquationIdVectorType& ids,
                                        const ProcessInfo& info);

 private:
  bool initialized_ = false;
};

}  // namespace mc
