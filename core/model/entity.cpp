// SPDX-License-Identifier: BSD-3-Clause
#include "core/model/entity.h"

#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"

namespace mc {

const std::string& Entity::RegisteredName() const noexcept {
  static const std::string empty;
  return registered_name_ ? *registered_name_ : empty;
}

void Entity::EquationIdVector(EquationIdVectorType& ids, const ProcessInfo& info) const {
  thread_local DofsVectorType dofs;
  GetDofList(dofs, info);
  ids.resize(dofs.size());
  for (std::size_t i = 0; i < dofs.size(); ++i) ids[i] = dofs[i]->equation_id;
}

void Entity::CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) {
  CalculateLeftHandSide(lhs, info);
  CalculateRightHandSide(rhs, info);
}

void Entity::CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) {
  throw NotImplementedError(Concat(Info(), " ", Id(), ": CalculateLeftHandSide is not implemented"));
}

void Entity::CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) {
  throw NotImplementedError(Concat(Info(), " ", Id(), ": CalculateRightHandSide is not implemented"));
}

void Entity::CalculateMassMatrix(Matrix& mass, const ProcessInfo& info) { mass.resize(0, 0); }

void Entity::CalculateDampingMatrix(Matrix& damping, const ProcessInfo& info) { damping.resize(0, 0); }

namespace {

// The time derivative of order `order` (1 or 2) of a DoF variable, or null when it has none.
const Variable<double>* TimeDerivative(const Variable<double>& var, int order) {
  if (!var.IsComponent()) return nullptr;
  const VariableData* source = var.Source();
  const Variable<Array3>* target = nullptr;
  if (source == &DISPLACEMENT) target = order == 1 ? &VELOCITY : &ACCELERATION;
  if (source == &ROTATION) target = order == 1 ? &ANGULAR_VELOCITY : &ANGULAR_ACCELERATION;
  if (!target) return nullptr;
  static const Variable<double>* components[4][3] = {
      {&VELOCITY_X, &VELOCITY_Y, &VELOCITY_Z},
      {&ACCELERATION_X, &ACCELERATION_Y, &ACCELERATION_Z},
      {&ANGULAR_VELOCITY_X, &ANGULAR_VELOCITY_Y, &ANGULAR_VELOCITY_Z},
      {&ANGULAR_ACCELERATION_X, &ANGULAR_ACCELERATION_Y, &ANGULAR_ACCELERATION_Z}};
  const int row = (target == &VELOCITY) ? 0 : (target == &ACCELERATION) ? 1 : (target == &ANGULAR_VELOCITY) ? 2 : 3;
  return components[row][var.ComponentIndex()];
}

void GatherDerivatives(const Entity& entity, int order, int step, Vector& values) {
  thread_local DofsVectorType dofs;
  entity.GetDofList(dofs, ProcessInfo{});
  values.resize(static_cast<Eigen::Index>(dofs.size()));
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    const Variable<double>* d = TimeDerivative(*dofs[i]->variable, order);
    values[static_cast<Eigen::Index>(i)] =
        (d && dofs[i]->node->HasSolutionStepValue(*d)) ? dofs[i]->node->FastGetSolutionStepValue(*d, step) : 0.0;
  }
}

}  // namespace

void Entity::GetValuesVector(Vector& values, int step) const {
  thread_local DofsVectorType dofs;
  GetDofList(dofs, ProcessInfo{});
  values.resize(static_cast<Eigen::Index>(dofs.size()));
  for (std::size_t i = 0; i < dofs.size(); ++i) values[static_cast<Eigen::Index>(i)] = dofs[i]->Value(step);
}

void Entity::GetFirstDerivativesVector(Vector& values, int step) const { GatherDerivatives(*this, 1, step, values); }

void Entity::GetSecondDerivativesVector(Vector& values, int step) const { GatherDerivatives(*this, 2, step, values); }

void Entity::CalculateOnIntegrationPoints(const Variable<double>& var, std::vector<double>& out,
                                          const ProcessInfo& info) {
  throw NotImplementedError(Concat(Info(), " ", Id(), " does not compute ", var.Name()));
}
void Entity::CalculateOnIntegrationPoints(const Variable<Array3>& var, std::vector<Array3>& out,
                                          const ProcessInfo& info) {
  throw NotImplementedError(Concat(Info(), " ", Id(), " does not compute ", var.Name()));
}
void Entity::CalculateOnIntegrationPoints(const Variable<Vector>& var, std::vector<Vector>& out,
                                          const ProcessInfo& info) {
  throw NotImplementedError(Concat(Info(), " ", Id(), " does not compute ", var.Name()));
}
void Entity::CalculateOnIntegrationPoints(const Variable<Matrix>& var, std::vector<Matrix>& out,
                                          const ProcessInfo& info) {
  throw NotImplementedError(Concat(Info(), " ", Id(), " does not compute ", var.Name()));
}

int Entity::NumberOfIntegrationPoints() const {
  return static_cast<int>(geometry_.IntegrationPoints(geometry_.DefaultIntegrationOrder()).size());
}

}  // namespace mc
