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
template <int D, int S, int M>
const char* AxisymmetricStem(const ALMFrictionalMortarContactCondition<D, S, M>*) {
  return "ALMFrictionalAxisymMortarContactCondition";
}
template <int D, int S, int M>
const char* AxisymmetricStem(const PenaltyFrictionalMortarContactCondition<D, S, M>*) {
  return "PenaltyFrictionalAxisymMortarContactCondition";
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
  return this->CreateOfType(*this, id, std::move(nodes), properties);
}

template <class TFormulation>
std::unique_ptr<PairedCondition> AxisymmetricMortarContactCondition<TFormulation>::CreatePaired(
    IndexType id, Condition& slave, Condition& master, Properties* properties) const {
  return this->template CreatePairedOfType<AxisymmetricMortarContactCondition>(id, slave, master, properties);
}

template class AxisymmetricMortarContactCondition<ALMFrictionlessMortarContactCondition<2, 2, 2>>;
template class AxisymmetricMortarContactCondition<PenaltyFrictionlessMortarContactCondition<2, 2, 2>>;
template class AxisymmetricMortarContactCondition<ALMFrictionalMortarContactCondition<2, 2, 2>>;
template class AxisymmetricMortarContactCondition<PenaltyFrictionalMortarContactCondition<2, 2, 2>>;

}  // namespace mc
