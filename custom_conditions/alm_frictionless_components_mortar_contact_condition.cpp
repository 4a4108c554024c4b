// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/alm_frictionless_components_mortar_contact_condition.h"

#include "custom_conditions/generated/mortar_kernels.h"
#include "custom_utilities/mortar_geometry_cases.h"

namespace mc {

template <int TDim, int TNumNodes, int TNumNodesMaster>
std::unique_ptr<Condition> ALMFrictionlessComponentsMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::Create(
    IndexType id, Geometry::NodesArray nodes, Properties* properties) const {
  return this->CreateOfType(*this, id, std::move(nodes), properties);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
std::unique_ptr<PairedCondition>
ALMFrictionlessComponentsMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::CreatePaired(
    IndexType id, Condition& slave, Condition& master, Properties* properties) const {
  return this->template CreatePairedOfType<ALMFrictionlessComponentsMortarContactCondition>(id, slave, master,
                                                                                            properties);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void ALMFrictionlessComponentsMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::AddRHS(const Data& data,
                                                                                               Vector& rhs) const {
  generated::ALMFrictionlessComponentsRHS(data, rhs);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void ALMFrictionlessComponentsMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::AddLHS(
    const Data& data, Matrix& lhs, Matrix* normal_sensitivity) const {
  generated::ALMFrictionlessComponentsLHS(data, lhs, normal_sensitivity);
}

#define MC_INSTANTIATE(D, S, M) template class ALMFrictionlessComponentsMortarContactCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_INSTANTIATE)
#undef MC_INSTANTIATE

}  // namespace mc
