// SPDX-License-Identifier: BSD-3-Clause
#include "structural/conditions/base_load_condition.h"

#include "core/geometries/reference_element.h"
#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"

namespace mc {

namespace {
const Variable<double>* const kDisplacement[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
}  // namespace

int BaseLoadCondition::Dimension() const noexcept { return GetGeometry().Reference().WorkingSpaceDimension(); }

std::string BaseLoadCondition::Info() const {
  return Concat(Stem(), Dimension(), "D", GetGeometry().Reference().NodesNumber(), "N");
}

void BaseLoadCondition::GetDofList(DofsVectorType& dofs, const ProcessInfo& info) const {
  const int dim = Dimension();
  const Geometry& geometry = GetGeometry();
  dofs.resize(geometry.PointsNumber() * static_cast<std::size_t>(dim));
  for (std::size_t a = 0; a < geometry.PointsNumber(); ++a)
    for (int k = 0; k < dim; ++k) dofs[a * dim + k] = &geometry[a].GetDof(*kDisplacement[k]);
}

void BaseLoadCondition::CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo& info) {
  CalculateAll(&lhs, &rhs, info);
}

void BaseLoadCondition::CalculateLeftHandSide(Matrix& lhs, const ProcessInfo& info) {
  CalculateAll(&lhs, nullptr, info);
}

void BaseLoadCondition::CalculateRightHandSide(Vector& rhs, const ProcessInfo& info) {
  CalculateAll(nullptr, &rhs, info);
}

void BaseLoadCondition::Check(const ProcessInfo& info) const {
  const Geometry& geometry = GetGeometry();
  for (std::size_t a = 0; a < geometry.PointsNumber(); ++a) {
    const Node& node = geometry[a];
    if (!node.HasSolutionStepValue(DISPLACEMENT))
      throw InputError(Concat("condition ", Id(), " (", Info(), "): node ", node.Id(),
                              " has no solution-step variable DISPLACEMENT"));
    for (int k = 0; k < Dimension(); ++k)
      if (!node.HasDofFor(*kDisplacement[k]))
        throw InputError(Concat("condition ", Id(), " (", Info(), "): node ", node.Id(), " has no DoF ",
                                kDisplacement[k]->Name()));
  }
}

Array3 BaseLoadCondition::NodalVector(const Variable<Array3>& var, std::size_t a) const {
  const Node& node = GetGeometry()[a];
  return node.HasSolutionStepValue(var) ? Array3(node.FastGetSolutionStepValue(var)) : Array3::Zero();
}

double BaseLoadCondition::NodalPressure(std::size_t a) const {
  const Node& node = GetGeometry()[a];
  double p = 0.0;
  if (node.HasSolutionStepValue(NEGATIVE_FACE_PRESSURE)) p += node.FastGetSolutionStepValue(NEGATIVE_FACE_PRESSURE);
  if (node.HasSolutionStepValue(POSITIVE_FACE_PRESSURE)) p -= node.FastGetSolutionStepValue(POSITIVE_FACE_PRESSURE);
  return p;
}

double BaseLoadCondition::ConditionPressure() const {
  return GetValue(NEGATIVE_FACE_PRESSURE) - GetValue(POSITIVE_FACE_PRESSURE);
}

}  // namespace mc
