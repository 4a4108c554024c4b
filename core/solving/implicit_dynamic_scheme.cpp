// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/implicit_dynamic_scheme.h"

#include "core/model/model_part.h"
#include "core/variables/kernel_variables.h"

namespace mc {

void ImplicitDynamicScheme::Check(const ModelPart& model_part) const {
  Scheme::Check(model_part);
  if (model_part.GetBufferSize() < MinimumBufferSize())
    throw InputError(Concat(Name(), " scheme: buffer_size ", model_part.GetBufferSize(), " of model part ",
                            model_part.Name(), " must be at least ", MinimumBufferSize()));
  for (const VariableData* v :
       {static_cast<const VariableData*>(&VELOCITY), static_cast<const VariableData*>(&ACCELERATION)})
    if (!model_part.HasNodalSolutionStepVariable(*v))
      throw InputError(
          Concat(Name(), " scheme: ", v->Name(), " is not a historical variable of model part ", model_part.Name()));
}

void ImplicitDynamicScheme::InertialAcceleration(const Entity& entity, Vector& acceleration) const {
  entity.GetSecondDerivativesVector(acceleration, 0);
}

void ImplicitDynamicScheme::CalculateSystemContributions(Entity& entity, Matrix& lhs, Vector& rhs,
                                                         EquationIdVectorType& ids, const ProcessInfo& info) {
  entity.CalculateLocalSystem(lhs, rhs, info);
  AddDynamics(entity, &lhs, &rhs, ids, info);
}

void ImplicitDynamicScheme::CalculateLHSContribution(Entity& entity, Matrix& lhs, EquationIdVectorType& ids,
                                                     const ProcessInfo& info) {
  entity.CalculateLeftHandSide(lhs, info);
  AddDynamics(entity, &lhs, nullptr, ids, info);
}

void ImplicitDynamicScheme::CalculateRHSContribution(Entity& entity, Vector& rhs, EquationIdVectorType& ids,
                                                     const ProcessInfo& info) {
  entity.CalculateRightHandSide(rhs, info);
  AddDynamics(entity, nullptr, &rhs, ids, info);
}

void ImplicitDynamicScheme::AddDynamics(Entity& entity, Matrix* lhs, Vector* rhs, EquationIdVectorType& ids,
                                        const ProcessInfo& info) {
  static thread_local Matrix mass;
  static thread_local Matrix damping;
  static thread_local Vector derivative;
  entity.CalculateMassMatrix(mass, info);
  entity.CalculateDampingMatrix(damping, info);
  if (lhs) {
    if (mass.size() > 0) *lhs += MassFactor() * mass;
    if (damping.size() > 0) *lhs += DampingFactor() * damping;
  }
  if (rhs) {
    if (mass.size() > 0) {
      InertialAcceleration(entity, derivative);
      rhs->noalias() -= mass * derivative;
    }
    if (damping.size() > 0) {
      entity.GetFirstDerivativesVector(derivative, 0);
      rhs->noalias() -= damping * derivative;
    }
  }
  entity.EquationIdVector(ids, info);
}

}  // namespace mc
