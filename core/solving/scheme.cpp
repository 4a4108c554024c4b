// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/scheme.h"

#include "core/model/model_part.h"
#include "core/model/parallel_utilities.h"

namespace mc {

namespace {

// Runs one life-cycle step of every active element and condition.
void CallOnActiveEntities(ModelPart& model_part, void (Entity::*step)(const ProcessInfo&)) {
  const ProcessInfo& info = model_part.GetProcessInfo();
  ForEachActiveEntity(model_part, [&](Entity& e) { (e.*step)(info); });
}

}  // namespace

void Scheme::Initialize(ModelPart& model_part) {
  CallOnActiveEntities(model_part, &Entity::Initialize);
  initialized_ = true;
}

void Scheme::InitializeSolutionStep(ModelPart& model_part) {
  CallOnActiveEntities(model_part, &Entity::InitializeSolutionStep);
}

void Scheme::InitializeNonLinIteration(ModelPart& model_part) {
  CallOnActiveEntities(model_part, &Entity::InitializeNonLinearIteration);
}

void Scheme::FinalizeNonLinIteration(ModelPart& model_part) {
  CallOnActiveEntities(model_part, &Entity::FinalizeNonLinearIteration);
}

void Scheme::FinalizeSolutionStep(ModelPart& model_part) {
  CallOnActiveEntities(model_part, &Entity::FinalizeSolutionStep);
}

void Scheme::Update(ModelPart& model_part, const DofsArray& dofs, const Vector& dx) {
  const long n = static_cast<long>(dofs.size());
#pragma omp parallel for schedule(static) if (n >= kMinParallelDofs)
  for (long i = 0; i < n; ++i) {
    Dof& dof = *dofs[i];
    if (!dof.fixed) dof.Value() += dx[dof.equation_id];
  }
}

void Scheme::Check(const ModelPart& model_part) const {
  const ProcessInfo& info = model_part.GetProcessInfo();
  for (const Element* e : model_part.Elements()) e->Check(info);
  for (const Condition* c : model_part.Conditions()) c->Check(info);
}

void Scheme::CalculateSystemContributions(Entity& entity, Matrix& lhs, Vector& rhs, EquationIdVectorType& ids,
                                          const ProcessInfo& info) {
  entity.CalculateLocalSystem(lhs, rhs, info);
  entity.EquationIdVector(ids, info);
}

void Scheme::CalculateLHSContribution(Entity& entity, Matrix& lhs, EquationIdVectorType& ids, const ProcessInfo& info) {
  entity.CalculateLeftHandSide(lhs, info);
  entity.EquationIdVector(ids, info);
}

void Scheme::CalculateRHSContribution(Entity& entity, Vector& rhs, EquationIdVectorType& ids, const ProcessInfo& info) {
  entity.CalculateRightHandSide(rhs, info);
  entity.EquationIdVector(ids, info);
}

}  // namespace mc
