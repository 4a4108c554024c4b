// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/mortar_contact_condition.h"

#include <algorithm>
#include <atomic>
#include <cassert>

#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"
#include "custom_conditions/mortar_geometry_token.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/mortar_geometry_cases.h"
#include "custom_utilities/mortar_pair_coordinates.h"
#include "custom_utilities/normal_calculation_utilities.h"

namespace mc {

namespace {

const Variable<double>* const kDisplacement[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};

// The triangle rule of this order (6 points) is exact to degree 4: dual basis times master shape
// function of flat quadrilaterals (IntegratesQuadrilateralsExactly).
constexpr int kExactQuadrilateralOrder = 3;

// The kinematics object holds the derivative arrays (a few kB): one per thread, reused by
// every pair of that thread.
template <class TKinematics>
TKinematics& ThreadKinematics() {
  thread_local TKinematics kinematics;
  return kinematics;
}

void AtomicAdd(double& target, double value) { std::atomic_ref<double>(target).fetch_add(value); }

}  // namespace

template <int TDim, int TNumNodes, int TNumNodesMaster>
std::string MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::GeometryToken() {
  return MortarGeometryToken(TDim, TNumNodes, TNumNodesMaster);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
std::string MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::Info() const {
  return Stem() + GeometryToken();
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
const Variable<double>& MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::MultiplierVariable(int) const {
  throw Error(Concat(Info(), " has no multiplier DoFs"));
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
const Variable<double>& MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::VectorMultiplierComponent(int c) {
  static const Variable<double>* const components[3] = {&VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y,
                                                        &VECTOR_LAGRANGE_MULTIPLIER_Z};
  return *components[c];
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::GatherVectorMultipliers(Data& data) const {
  const Geometry& slave = GetGeometry();
  for (int j = 0; j < TNumNodes; ++j)
    data.vector_multiplier.row(j) =
        slave[j].FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER).template head<TDim>().transpose();
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::GetDofList(DofsVectorType& dofs,
                                                                          const ProcessInfo&) const {
  const Geometry& slave = GetGeometry();
  const Geometry& master = GetPairedGeometry();
  const int multipliers = MultiplierComponents();
  dofs.resize(LocalSize());
  std::size_t i = 0;
  for (int l = 0; l < TNumNodesMaster; ++l)
    for (int c = 0; c < TDim; ++c) dofs[i++] = &master[l].GetDof(*kDisplacement[c]);
  for (int s = 0; s < TNumNodes; ++s)
    for (int c = 0; c < TDim; ++c) dofs[i++] = &slave[s].GetDof(*kDisplacement[c]);
  for (int s = 0; s < TNumNodes; ++s)
    for (int c = 0; c < multipliers; ++c) dofs[i++] = &slave[s].GetDof(MultiplierVariable(c));
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::CalculateLocalSystem(Matrix& lhs, Vector& rhs,
                                                                                    const ProcessInfo& info) {
  CalculateAll(&lhs, &rhs, info);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::CalculateLeftHandSide(Matrix& lhs,
                                                                                     const ProcessInfo& info) {
  CalculateAll(&lhs, nullptr, info);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::CalculateRightHandSide(Vector& rhs,
                                                                                      const ProcessInfo& info) {
  CalculateAll(nullptr, &rhs, info);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
MortarIntegrationSettings MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::IntegrationSettings(
    const ProcessInfo& info) const {
  MortarIntegrationSettings settings = PairIntegrationSettings(info);
  if (HasProperties() && GetProperties().Has(CONSIDER_TESSELLATION))
    settings.consider_tessellation = GetProperties().GetValue(CONSIDER_TESSELLATION);
  settings.axisymmetric = IsAxisymmetric();
  if constexpr (TDim == 3 && (TNumNodes == 4 || TNumNodesMaster == 4))
    if (IntegratesQuadrilateralsExactly())
      settings.integration_order = std::max(settings.integration_order, kExactQuadrilateralOrder);
  const double time = info.GetValue(TIME);
  if (fan_history_.time != time) fan_history_ = MortarFanHistory{time, HoldsFanStart()};
  settings.fan_history = &fan_history_;
  return settings;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::GatherKinematicsInput(
    typename Kinematics::SlaveMatrix& x1, typename Kinematics::MasterMatrix& x2,
    typename Kinematics::SlaveMatrix& n1) const {
  GatherCoordinates(x1, x2);
  GatherSlaveNormals(n1);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::GatherSlaveNormals(
    typename Kinematics::SlaveMatrix& n1) const {
  const Geometry& slave = GetGeometry();
  for (int i = 0; i < TNumNodes; ++i)
    n1.row(i) = NormalCalculationUtilities::GetNodalNormal(slave[i]).template head<TDim>().transpose();
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::GatherCoordinates(
    typename Kinematics::SlaveMatrix& x1, typename Kinematics::MasterMatrix& x2) const {
  MortarPairCoordinates<TDim, TNumNodes, TNumNodesMaster>(GetGeometry(), GetPairedGeometry(), x1, x2);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::FillData(Data& data, const ProcessInfo& info) const {
  data.scale_factor = info.Has(SCALE_FACTOR) ? info.GetValue(SCALE_FACTOR) : 1.0;
  if (!(data.scale_factor > 0.0))
    throw InputError(
        Concat("condition ", Id(), " (", Info(), "): SCALE_FACTOR = ", data.scale_factor, " must be positive"));
  const Geometry& slave = GetGeometry();
  for (int j = 0; j < TNumNodes; ++j) {
    const Node& node = slave[j];
    const double eps = node.Has(INITIAL_PENALTY) ? node.GetValue(INITIAL_PENALTY) : info.GetValue(INITIAL_PENALTY);
    if (!(eps > 0.0))
      throw InputError(Concat("condition ", Id(), " (", Info(), "), slave node ", node.Id(), ": INITIAL_PENALTY = ",
                              eps, " must be positive (set it in the ProcessInfo or on the node)"));
    data.penalty(j) = eps;
    data.dynamic_factor(j) = node.Has(DYNAMIC_FACTOR) ? node.GetValue(DYNAMIC_FACTOR) : 1.0;
    data.active[j] = node.Is(ACTIVE);
  }
  GatherMultipliers(data);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::CalculateAll(Matrix* lhs, Vector* rhs,
                                                                            const ProcessInfo& info) {
  typename Kinematics::SlaveMatrix x1, n1;
  typename Kinematics::MasterMatrix x2;
  GatherKinematicsInput(x1, x2, n1);
  CalculatePairSystem(lhs, rhs, info, n1, nullptr);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::CalculatePairSystem(
    Matrix* lhs, Vector* rhs, const ProcessInfo& info, const typename Kinematics::SlaveMatrix& n1,
    Matrix* normal_sensitivity) {
  assert(!normal_sensitivity || lhs);
  const int size = LocalSize();
  if (lhs) lhs->setZero(size, size);
  if (rhs) rhs->setZero(size);
  if (normal_sensitivity) normal_sensitivity->setZero(size, TDim * TNumNodes);

  Kinematics& kinematics = ThreadKinematics<Kinematics>();
  typename Kinematics::SlaveMatrix x1;
  typename Kinematics::MasterMatrix x2;
  GatherCoordinates(x1, x2);
  const MortarIntegrationSettings settings = IntegrationSettings(info);
  Data data;
  data.kinematics = &kinematics;
  FillData(data, info);
  // A pair that does not touch still owns the multipliers of its slave nodes. With every mortar
  // quantity zero the kernels add only the inactive rows (lambda = 0), which keeps the system
  // regular for slave nodes that lie outside every overlap (Kratos instead flags them ISOLATED
  // and its block builder fixes their multipliers). The inactive rows read no mortar quantity
  // (ALM: -k^2/eps lambda_j, penalty: nothing), so a pair whose slave nodes are all inactive is
  // not integrated at all: most pairs of an interface lie outside the contact zone (15 of 16 on
  // the Hertz cases, where the contact assembly was 23 % of hertz3d_15k's time).
  if (std::none_of(data.active.begin(), data.active.end(), [](bool active) { return active; })) {
    kinematics.SkipIntegration(x1, x2, n1);
  } else if (lhs) {
    kinematics.Compute(x1, x2, n1, settings);
    // Only the multiplier (constraint) rows read the mean gaps.
    if (MultiplierComponents() > 0) kinematics.SetMeanGaps(PenetratingMeanGaps());
  } else {
    kinematics.ComputeValues(x1, x2, n1, settings);
  }
  CompleteKernelData(data, info);

  if (rhs) AddRHS(data, *rhs);
  if (lhs) AddLHS(data, *lhs, normal_sensitivity);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
typename MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::Kinematics::SlaveVector
MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::PenetratingMeanGaps() const {
  // Held fixed only where the node penetrates: there the exact linearisation of a growing area x
  // gap pushes the node out beyond closure, into tension, and it leaves the active set to come
  // back an iteration later (2d_quad_flat_r0.5_overhang-both_gap_disp_4steps_alm, step 2: the
  // slave node next to the master's corner, whose overlap grows from 2.4 % of its element; 4
  // iterations, 3 held fixed). An open node predicted to close keeps the exact linearisation:
  // holding its weight cost an iteration in the contact onset of
  // 3d_hex_flat_r0.5_overhang-slave-xy_gap_disp_4steps_alm_coarse (3 against 2; not isolated).
  typename Kinematics::SlaveVector mean_gap = Kinematics::SlaveVector::Zero();
  const Geometry& slave = GetGeometry();
  for (int j = 0; j < TNumNodes; ++j) {
    const Node& node = slave[j];
    const double area = node.Has(NODAL_AREA) ? node.GetValue(NODAL_AREA) : 0.0;
    if (area > 0.0) mean_gap(j) = std::min(0.0, node.FastGetSolutionStepValue(WEIGHTED_GAP) / area);
  }
  return mean_gap;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::AddExplicitContribution(const ProcessInfo& info) {
  Kinematics& kinematics = ThreadKinematics<Kinematics>();
  typename Kinematics::SlaveMatrix x1, n1;
  typename Kinematics::MasterMatrix x2;
  GatherKinematicsInput(x1, x2, n1);
  if (kinematics.ComputeValues(x1, x2, n1, IntegrationSettings(info))) {
    Geometry& slave = GetGeometry();
    for (int j = 0; j < TNumNodes; ++j) {
      Node& node = slave[j];
      AtomicAdd(node.GetSolutionStepValue(WEIGHTED_GAP), kinematics.weighted_gap(j));
      // A sliver's area does not count: a node covered by slivers alone keeps NODAL_AREA = 0 and is
      // ISOLATED: its multiplier row would carry D_jj of the order of the sliver's area.
      if (!kinematics.sliver) AtomicAdd(node.GetValueRef(NODAL_AREA), kinematics.nodal_area(j));
    }
  }
  AddExplicitNodalValues(kinematics, info);
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarContactCondition<TDim, TNumNodes, TNumNodesMaster>::Check(const ProcessInfo& info) const {
  auto fail = [&](const Node& node, const std::string& what) {
    throw InputError(Concat("condition ", Id(), " (", Info(), "): node ", node.Id(), " ", what));
  };
  auto check_displacement = [&](const Node& node) {
    if (!node.HasSolutionStepValue(DISPLACEMENT)) fail(node, "has no solution-step variable DISPLACEMENT");
    for (int c = 0; c < TDim; ++c)
      if (!node.HasDofFor(*kDisplacement[c])) fail(node, Concat("has no DoF ", kDisplacement[c]->Name()));
  };
  for (int l = 0; l < TNumNodesMaster; ++l) check_displacement(GetPairedGeometry()[l]);
  for (int j = 0; j < TNumNodes; ++j) {
    const Node& node = GetGeometry()[j];
    check_displacement(node);
    if (!node.HasSolutionStepValue(WEIGHTED_GAP)) fail(node, "has no solution-step variable WEIGHTED_GAP");
    for (int c = 0; c < MultiplierComponents(); ++c)
      if (!node.HasDofFor(MultiplierVariable(c))) fail(node, Concat("has no DoF ", MultiplierVariable(c).Name()));
    const double eps = node.Has(INITIAL_PENALTY) ? node.GetValue(INITIAL_PENALTY) : info.GetValue(INITIAL_PENALTY);
    if (!(eps > 0.0)) fail(node, Concat("has INITIAL_PENALTY = ", eps, " (must be positive)"));
  }
}

#define MC_INSTANTIATE(D, S, M) template class MortarContactCondition<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_INSTANTIATE)
#undef MC_INSTANTIATE

}  // namespace mc
