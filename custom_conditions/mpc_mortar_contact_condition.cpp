// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mpc_mortar_contact_condition.h"

#include <atomic>

#include "custom_conditions/mortar_geometry_token.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/mortar_pair_coordinates.h"
#include "custom_utilities/normal_calculation_utilities.h"

namespace mc {

namespace {

/// Values only: one kinematics object per thread (it is large: derivative arrays).
template <int TDim, int TNumNodes, int TNumNodesMaster>
bool ComputeKinematics(const PairedCondition& pair, const ProcessInfo& info,
                       MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>& kinematics) {
  using Kinematics = MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>;
  typename Kinematics::SlaveMatrix x1, n1;
  typename Kinematics::MasterMatrix x2;
  const Geometry& slave = pair.GetGeometry();
  MortarPairCoordinates<TDim, TNumNodes, TNumNodesMaster>(slave, pair.GetPairedGeometry(), x1, x2);
  for (int j = 0; j < TNumNodes; ++j)
    n1.row(j) = NormalCalculationUtilities::GetNodalNormal(slave[j]).template head<TDim>().transpose();
  return kinematics.ComputeValues(x1, x2, n1, pair.PairIntegrationSettings(info));
}

}  // namespace

template <int TDim, int TNumNodes, int TNumNodesMaster>
std::string MPCMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::Info() const {
  return "MPCMortarContactCondition" + MortarGeometryToken(TDim, TNumNodes, TNumNodesMaster);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
std::unique_ptr<Condition> MPCMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::Create(
    IndexType id, Geometry::NodesArray nodes, Properties* properties) const {
  return CreateOfType(*this, id, std::move(nodes), properties);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
std::unique_ptr<PairedCondition> MPCMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::CreatePaired(
    IndexType id, Condition& slave, Condition& master, Properties* properties) const {
  return CreatePairedOfType<MPCMortarContactCondition>(id, slave, master, properties);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MPCMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::CalculateLocalSystem(Matrix& lhs, Vector& rhs,
                                                                                       const ProcessInfo& info) {
  lhs.resize(0, 0);
  rhs.resize(0);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MPCMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::AddExplicitContribution(const ProcessInfo& info) {
  thread_local Kinematics kinematics;
  if (!ComputeKinematics(*this, info, kinematics) || kinematics.sliver) return;
  const Geometry& slave = GetGeometry();
  for (int j = 0; j < TNumNodes; ++j)
    std::atomic_ref<double>(slave[j].GetValueRef(NODAL_AREA)).fetch_add(kinematics.nodal_area(j));
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
bool MPCMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::ComputeOperators(MPCPairOperators& operators,
                                                                                   const ProcessInfo& info) const {
  thread_local Kinematics kinematics;
  if (!ComputeKinematics(*this, info, kinematics)) return false;
  operators = MPCPairOperators{};
  // The row sum: D itself with the pair's dual basis, the lumped D of a sliver's standard basis (as the
  // mortar mapping does).
  operators.d.template head<TNumNodes>() = kinematics.D.rowwise().sum();
  operators.m.template topLeftCorner<TNumNodes, TNumNodesMaster>() = kinematics.M;
  return true;
}

#define MC_INSTANTIATE(D, S, M) template class MPCMortarContactCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_INSTANTIATE)
#undef MC_INSTANTIATE

}  // namespace mc
