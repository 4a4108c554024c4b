// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/frictional_mortar_contact_condition.h"

#include <atomic>

#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/mortar_geometry_cases.h"
#include "custom_utilities/nodal_normal_support.h"

namespace mc {

template <int TDim, int TNumNodes, int TNumNodesMaster>
void FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::StorePreviousOperators(
    const typename Kinematics::SlaveMatrix& x1, const typename Kinematics::MasterMatrix& x2, const ProcessInfo& info) {
  // Not the thread's kinematics of the pair system: this may run between its Compute and its use.
  thread_local Kinematics previous;
  typename Kinematics::SlaveMatrix n1;
  this->GatherSlaveNormals(n1);
  previous.ComputeValues(x1, x2, n1, this->IntegrationSettings(info));
  previous_D_ = previous.D;
  previous_M_ = previous.M;
  has_previous_ = true;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::InitializeSolutionStep(
    const ProcessInfo& info) {
  if (info.GetValue(ACCUMULATED_WEIGHTED_SLIP)) {
    // Computed at first use from the previous step's coordinates (EnsurePreviousOperators).
    has_previous_ = false;
    return;
  }
  typename Kinematics::SlaveMatrix x1;
  typename Kinematics::MasterMatrix x2;
  this->GatherCoordinates(x1, x2);
  StorePreviousOperators(x1, x2, info);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::EnsurePreviousOperators(
    const ProcessInfo& info) {
  if (has_previous_) return;
  // An explicit step is evaluated at the coordinates of its start, which buffer position 1 also
  // holds then: the previous step's are one further back.
  const std::size_t back = info.GetValue(ACCUMULATED_WEIGHTED_SLIP) ? 2 : 1;
  auto previous_coordinates = [back](const Node& node) -> Array3 {
    if (node.BufferSize() <= back) return node.Coordinates();
    return node.X0() + node.FastGetSolutionStepValue(DISPLACEMENT, back);
  };
  typename Kinematics::SlaveMatrix x1;
  typename Kinematics::MasterMatrix x2;
  for (int i = 0; i < TNumNodes; ++i)
    x1.row(i) = previous_coordinates(this->GetGeometry()[i]).template head<TDim>().transpose();
  for (int l = 0; l < TNumNodesMaster; ++l)
    x2.row(l) = previous_coordinates(this->GetPairedGeometry()[l]).template head<TDim>().transpose();
  StorePreviousOperators(x1, x2, info);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::AccumulatedWeightedSlip(Data& data) const {
  // The pair's share of node j is its part of the nodal area, as for the weighted gap.
  const Geometry& slave = this->GetGeometry();
  for (int j = 0; j < TNumNodes; ++j) {
    const Node& node = slave[j];
    const double area = node.Has(NODAL_AREA) ? node.GetValue(NODAL_AREA) : 0.0;
    const double share = area > 0.0 && !data.kinematics->sliver ? data.kinematics->nodal_area(j) / area : 0.0;
    data.weighted_slip.row(j) = share * node.FastGetSolutionStepValue(WEIGHTED_SLIP).template head<TDim>().transpose();
  }
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::SymmetryMasks(Data& data) const {
  for (int j = 0; j < TNumNodes; ++j)
    data.symmetry_mask.row(j) =
        NodalNormalSupport::SymmetryMask(this->GetGeometry()[j]).template head<TDim>().transpose();
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
double FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::FrictionCoefficient(const Node& node) const {
  if (node.Has(FRICTION_COEFFICIENT)) return node.GetValue(FRICTION_COEFFICIENT);
  if (this->HasProperties() && this->GetProperties().Has(FRICTION_COEFFICIENT))
    return this->GetProperties().GetValue(FRICTION_COEFFICIENT);
  throw InputError(Concat("condition ", this->Id(), " (", this->Info(), "), slave node ", node.Id(),
                          ": no FRICTION_COEFFICIENT on the node nor in the condition's properties"));
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
double FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::TangentFactor(
    const ProcessInfo& info) const {
  const double c_tau = info.Has(TANGENT_FACTOR) ? info.GetValue(TANGENT_FACTOR) : 0.0;
  if (!(c_tau > 0.0))
    throw InputError(Concat("condition ", this->Id(), " (", this->Info(), "): TANGENT_FACTOR = ", c_tau,
                            info.Has(TANGENT_FACTOR) ? " must be positive" : " is not set in the ProcessInfo"));
  return c_tau;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::CompleteKernelData(Data& data,
                                                                                            const ProcessInfo& info) {
  EnsurePreviousOperators(info);
  data.previous_D = previous_D_;
  data.previous_M = previous_M_;
  SymmetryMasks(data);
  ComputeWeightedSlip(data);
  if (info.GetValue(ACCUMULATED_WEIGHTED_SLIP)) AccumulatedWeightedSlip(data);
  data.tangent_factor = TangentFactor(info);
  data.slip_augmentation = info.Has(SLIP_AUGMENTATION_COEFFICIENT) ? info.GetValue(SLIP_AUGMENTATION_COEFFICIENT) : 0.0;
  const Geometry& slave = this->GetGeometry();
  for (int j = 0; j < TNumNodes; ++j) {
    data.friction_coefficient(j) = FrictionCoefficient(slave[j]);
    data.friction_threshold(j) =
        slave[j].Has(TRESCA_FRICTION_THRESHOLD) ? slave[j].GetValue(TRESCA_FRICTION_THRESHOLD) : 0.0;
    // Without an augmented tangent pressure the slip direction is undefined; the stick branch is
    // then the regular one (its tangential traction vanishes with it). Without friction (mu = tau
    // = 0, so b = 0) no direction is needed: the slip branch takes dir = 0 and frees the node.
    const bool frictionless = data.friction_coefficient(j) == 0.0 && data.friction_threshold(j) == 0.0;
    data.slip[j] = slave[j].Is(SLIP) && (frictionless || AugmentedTangentPressure(data, j).norm() > 0.0);
  }
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::AddExplicitNodalValues(
    const Kinematics& kinematics, const ProcessInfo& info) {
  EnsurePreviousOperators(info);
  Data data;
  data.kinematics = &kinematics;
  data.previous_D = previous_D_;
  data.previous_M = previous_M_;
  SymmetryMasks(data);
  ComputeWeightedSlip(data);
  Geometry& slave = this->GetGeometry();
  for (int j = 0; j < TNumNodes; ++j) {
    auto weighted_slip = slave[j].FastGetSolutionStepValue(WEIGHTED_SLIP);
    for (int c = 0; c < TDim; ++c) std::atomic_ref<double>(weighted_slip[c]).fetch_add(data.weighted_slip(j, c));
  }
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void FrictionalMortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::Check(const ProcessInfo& info) const {
  Base::Check(info);
  TangentFactor(info);
  for (int j = 0; j < TNumNodes; ++j) {
    const Node& node = this->GetGeometry()[j];
    if (!node.HasSolutionStepValue(WEIGHTED_SLIP))
      throw InputError(Concat("condition ", this->Id(), " (", this->Info(), "): node ", node.Id(),
                              " has no solution-step variable WEIGHTED_SLIP"));
    FrictionCoefficient(node);
  }
}

#define MC_INSTANTIATE(D, S, M) template class FrictionalMortarContactCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_INSTANTIATE)
#undef MC_INSTANTIATE

}  // namespace mc
