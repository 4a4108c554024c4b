// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/model/parallel_utilities.h"
#include "core/solving/scheme.h"
#include "core/solving/time_derivatives.h"

namespace mc {

/// What the implicit dynamic schemes (Bossak / Newmark, BDF) share: each entity's effective
/// local system
///   LHS = K + m M + d D,   RHS = f_ext - f_int - M a* - D v,
/// with M and D from the entity (Rayleigh damping is its damping matrix), the scheme's factors
/// m = d acc / d u and d = d v / d u, a* the acceleration the inertia force takes (the current
/// one, or Bossak's blend with the last step's) and v the current velocity; and the check of the
/// time-derivative variables and of the buffer the scheme differentiates over.
class ImplicitDynamicScheme : public Scheme {
 public:
  /// InputError unless the buffer holds MinimumBufferSize() steps and VELOCITY and ACCELERATION
  /// are historical.
  void Check(const ModelPart& model_part) const override;

  void CalculateSystemContributions(Entity& entity, Matrix& lhs, Vector& rhs, EquationIdVectorType& ids,
                                    const ProcessInfo& info) override;
  void CalculateLHSContribution(Entity& entity, Matrix& lhs, EquationIdVectorType& ids,
                                const ProcessInfo& info) override;
  void CalculateRHSContribution(Entity& entity, Vector& rhs, EquationIdVectorType& ids,
                                const ProcessInfo& info) override;

 protected:
  virtual int MinimumBufferSize() const = 0;
  /// m: the factor of the mass matrix in the LHS.
  virtual double MassFactor() const = 0;
  /// d: the factor of the damping matrix in the LHS.
  virtual double DampingFactor() const = 0;
  /// a*: by default the entity's current acceleration.
  virtual void InertialAcceleration(const Entity& entity, Vector& acceleration) const;

  /// fn(dof, velocity, acceleration variable) for each DoF (each free one with `free_only`) whose
  /// node holds both time derivatives of its variable, in parallel for large sets.
  template <class F>
  static void ForEachDynamicDof(const DofsArray& dofs, bool free_only, F&& fn) {
    const long n = static_cast<long>(dofs.size());
#pragma omp parallel for schedule(static) if (n >= kMinParallelDofs)
    for (long i = 0; i < n; ++i) {
      const Dof& d = *dofs[i];
      if (free_only && d.fixed) continue;
      const Variable<double>* vel = TimeDerivativeOf(*d.variable, 1);
      const Variable<double>* acc = TimeDerivativeOf(*d.variable, 2);
      if (!vel || !d.node->HasSolutionStepValue(*vel) || !d.node->HasSolutionStepValue(*acc)) continue;
      fn(d, *vel, *acc);
    }
  }

 private:
  /// Adds the inertia and damping terms of `entity` to the LHS and / or RHS given, then its
  /// equation ids.
  void AddDynamics(Entity& entity, Matrix* lhs, Vector* rhs, EquationIdVectorType& ids, const ProcessInfo& info);
};

}  // namespace mc
