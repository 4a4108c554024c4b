// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/axisymmetric_mortar_contact_condition.h"

namespace mc {

namespace {

// Names of the axisymmetric variants (spec 6.2), chosen by overload on the formulation.
template <int D, int S, int M>
const char* AxisymmetricStem(const ALMFrictionlessMortarContactCondition<D, S, M>*) {
  return "ALMFrictionlessAxisymMortarContactCondition";
}
template <int D, int S, int M>
const char* AxisymmetricStem(const PenaltyFrictionlessMortarContactCondition<D, S, M>*) {
  return "PenaltyFrictionlessAxisymMortarContactCondition";
}

}  // namespace

template <class TFormulation>
const char* AxisymmetricMortarContactCondition<TFormulation>::Stem() const {
  return AxisymmetricStem(static_cast<const TFormulation*>(nullptr));
}

template <class TFormulation>
std::unique_ptr<Condition> AxisymmetricMortarContactCondition<TFormulation>::Create(IndexType id,
                                                                                  Geometry::NodesArray nodes,
                                                                                  Properties* properties) const {
  return std::make_unique<AxisymmetricMortarContactCondition>(
      id, Geometry(this->GetGeometry().Type(), std::move(nodes)), properties, this->GetPairedGeometry());
}

template <class TFormulation>
std::unique_ptr<PairedCondition> AxisymmetricMortarContactCondition<TFormulation>::CreatePaired(
    IndexType id, Condition& slave, Condition& master, Properties* properties) const {
  auto pair = std::make_unique<AxisymmetricMortarContactCondition>(id, slave.GetGeometry(), properties,
                                                                   master.GetGeometry());
  pair->SetPair(&slave, &master);
  return pair;
}

template class AxisymmetricMortarContactCondition<ALMFrictionlessMortarContactCondition<2, 2, 2>>;
template class AxisymmetricMortarContactCondition<PenaltyFrictionlessMortarContactCondition<2, 2, 2>>;

}  // namespace mc
