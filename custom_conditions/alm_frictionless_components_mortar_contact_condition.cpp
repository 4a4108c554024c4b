// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/alm_frictionless_components_mortar_contact_condition.h"

#include "custom_conditions/generated/frictionless_mortar_kernels.h"
#include "custom_utilities/contact_variables.h"
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
const Variable<double>&
ALMFrictionlessComponentsMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::MultiplierVariable(int c) const {
  static const Variable<double>* const components[3] = {&VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y,
                                                        &VECTOR_LAGRANGE_MULTIPLIER_Z};
  return *components[c];
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void ALMFrictionlessComponentsMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::GatherMultipliers(
    Data& data) const {
  const Geometry& slave = this->GetGeometry();
  for (int j = 0; j < TNumNodes; ++j)
    data.vector_multiplier.row(j) =
        slave[j].FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER).template head<TDim>().transpose();
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
