// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/mortar_pair_kinematics.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/utilities/error.h"
#include "custom_utilities/mortar_autodiff.h"
#include "custom_utilities/mortar_geometry_cases.h"
#include "custom_utilities/mortar_operator.h"

namespace mc {
namespace {

using mortar_detail::ValueOf;

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// An order at which every overlap has enough points for its pair dual basis (6 per sub-triangle,
// for the 4 functions of a quadrilateral).
constexpr int kDualBasisOrder = 4;

/// Values of the pair in scalar type T (double, or AutoDiff seeded by the caller).
template <class T, int TDim, int TNumNodes, int TNumNodesMaster>
struct PairValues {
  MortarIntegrationPoints<T, TDim, TNumNodes, TNumNodesMaster> points;
  Eigen::Matrix<T, TNumNodes, TNumNodes> ae;
  MortarOperator<T, TDim, TNumNodes, TNumNodesMaster> op;
  Eigen::Matrix<T, TNumNodes, TDim> gap_vector;
  Eigen::Matrix<T, TNumNodes, 1> weighted_gap;
  bool sliver = false;
};

/// The pair's dual basis (DualLagrangeMultiplier) from d_j = int N_j and M = int N N^T over its
/// integration points; false when M is singular.
template <class T, int TDim, int TNumNodes, int TNumNodesMaster>
bool PairDualBasis(const MortarIntegrationPoints<T, TDim, TNumNodes, TNumNodesMaster>& points,
                   Eigen::Matrix<T, TNumNodes, TNumNodes>& ae) {
  using SF1 = MortarShapeFunctions<TNumNodes>;
  Eigen::Matrix<T, TNumNodes, 1> d = Eigen::Matrix<T, TNumNodes, 1>::Zero();
  Eigen::Matrix<T, TNumNodes, TNumNodes> m = Eigen::Matrix<T, TNumNodes, TNumNodes>::Zero();
  for (int g = 0; g < points.size; ++g) {
    const auto& p = points.points[g];
    const Eigen::Matrix<T, TNumNodes, 1> n = SF1::template N<T>(p.slave_local);
    d += p.weight * n;
    m += p.weight * n * n.transpose();
  }
  return DualLagrangeMultiplier<TDim, TNumNodes>::FromIntegrals(d, m, ae);
}

template <class T, int TDim, int TNumNodes, int TNumNodesMaster>
bool ComputePair(const Eigen::Matrix<T, TNumNodes, TDim>& x1, const Eigen::Matrix<T, TNumNodesMaster, TDim>& x2,
                 const Eigen::Matrix<T, TNumNodes, TDim>& n1, const MortarIntegrationSettings& settings,
                 PairValues<T, TDim, TNumNodes, TNumNodesMaster>& out) {
  using Exact = ExactMortarIntegrationUtility<TDim, TNumNodes, TNumNodesMaster>;
  using SF1 = MortarShapeFunctions<TNumNodes>;
  if constexpr (TDim == 3)
    if (settings.axisymmetric) throw Error("mortar integration: the axisymmetric formulation exists in 2D only");
  auto segment = [&](int order) {
    MortarIntegrationSettings pair_settings = settings;
    pair_settings.integration_order = order;
    if (!Exact::template Compute<T>(x1, x2, n1, pair_settings, out.points)) return false;
    if constexpr (TDim == 2) {
      // Surfaces of revolution: every integral, the dual basis' included, weighted by 2 pi r.
      if (settings.axisymmetric)
        for (int g = 0; g < out.points.size; ++g) {
          auto& p = out.points.points[g];
          p.weight *= kTwoPi * SF1::template N<T>(p.slave_local).dot(x1.col(0));
        }
    }
    return true;
  };
  if (!segment(settings.integration_order)) return false;
  // The pair basis needs at least as many independent points as slave nodes: a quadrilateral
  // slave whose overlap is one sub-triangle has 3 points at order 2 (and order 1 has one point),
  // so such overlaps are integrated again at kDualBasisOrder. What is still singular there is a
  // sliver, which takes the standard basis (DualLagrangeMultiplier).
  bool regular = PairDualBasis(out.points, out.ae);
  if (!regular && settings.integration_order < kDualBasisOrder) {
    segment(kDualBasisOrder);
    regular = PairDualBasis(out.points, out.ae);
  }
  out.sliver = !regular;
  if (out.sliver) out.ae = Eigen::Matrix<T, TNumNodes, TNumNodes>::Identity();

  out.op.Compute(out.points, out.ae);
  out.gap_vector = out.op.D * x1 - out.op.M * x2;
  for (int j = 0; j < TNumNodes; ++j) out.weighted_gap(j) = -n1.row(j).dot(out.gap_vector.row(j));
  return true;
}

}  // namespace

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>::ClearValues() {
  area = 0.0;
  sliver = false;
  points.size = 0;
  points.area = 0.0;
  Ae.setZero();
  D.setZero();
  M.setZero();
  nodal_area.setZero();
  weighted_gap.setZero();
  gap_vector.setZero();
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>::SkipIntegration(const SlaveMatrix& x1,
                                                                             const MasterMatrix& x2,
                                                                             const SlaveMatrix& n1) {
  slave_coordinates = x1;
  master_coordinates = x2;
  slave_normals = n1;
  has_overlap = false;
  ClearValues();
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
bool MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>::ComputeValues(const SlaveMatrix& x1,
                                                                           const MasterMatrix& x2,
                                                                           const SlaveMatrix& n1,
                                                                           const MortarIntegrationSettings& settings) {
  slave_coordinates = x1;
  master_coordinates = x2;
  slave_normals = n1;
  PairValues<double, TDim, TNumNodes, TNumNodesMaster> v;
  has_overlap = ComputePair<double, TDim, TNumNodes, TNumNodesMaster>(x1, x2, n1, settings, v);
  if (!has_overlap) {
    ClearValues();
    return false;
  }
  points = v.points;
  area = v.points.area;
  sliver = v.sliver;
  Ae = v.ae;
  D = v.op.D;
  M = v.op.M;
  nodal_area = v.op.nodal_area;
  gap_vector = v.gap_vector;
  weighted_gap = v.weighted_gap;
  return true;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
bool MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>::Compute(const SlaveMatrix& x1, const MasterMatrix& x2,
                                                                     const SlaveMatrix& n1,
                                                                     const MortarIntegrationSettings& settings) {
  using AD = mortar_detail::PairAutoDiff<TDim, TNumNodes, TNumNodesMaster>;
  static_assert(mortar_detail::NumDerivatives(TDim, TNumNodes, TNumNodesMaster) == kNumDerivatives);
  slave_coordinates = x1;
  master_coordinates = x2;
  slave_normals = n1;

  Eigen::Matrix<AD, TNumNodes, TDim> x1_ad, n1_ad;
  Eigen::Matrix<AD, TNumNodesMaster, TDim> x2_ad;
  for (int l = 0; l < TNumNodesMaster; ++l)
    for (int c = 0; c < TDim; ++c) x2_ad(l, c) = AD(x2(l, c), kNumDerivatives, MasterDof(l, c));
  for (int i = 0; i < TNumNodes; ++i)
    for (int c = 0; c < TDim; ++c) {
      x1_ad(i, c) = AD(x1(i, c), kNumDerivatives, SlaveDof(i, c));
      n1_ad(i, c) = AD(n1(i, c), kNumDerivatives, SlaveNormalIndex(i, c));
    }

  // Large (AutoDiff through every point); thread_local keeps it off the stack and reused.
  thread_local PairValues<AD, TDim, TNumNodes, TNumNodesMaster> v;
  has_overlap = ComputePair<AD, TDim, TNumNodes, TNumNodesMaster>(x1_ad, x2_ad, n1_ad, settings, v);

  for (auto& m : dD) m.setZero();
  for (auto& m : dM) m.setZero();
  d_weighted_gap.setZero();
  d_nodal_area.setZero();
  d_constraint_gap_correction.setZero();
  d_area.setZero();
  if (!has_overlap) {
    ClearValues();
    return false;
  }

  points.size = v.points.size;
  points.area = v.points.area.value();
  for (int g = 0; g < v.points.size; ++g) {
    const auto& p = v.points.points[g];
    auto& q = points.points[g];
    for (int a = 0; a < TDim - 1; ++a) {
      q.slave_local(a) = p.slave_local(a).value();
      q.master_local(a) = p.master_local(a).value();
    }
    q.weight = p.weight.value();
  }
  area = v.points.area.value();
  sliver = v.sliver;
  d_area = v.points.area.derivatives();
  for (int i = 0; i < TNumNodes; ++i) {
    for (int k = 0; k < TNumNodes; ++k) {
      Ae(i, k) = v.ae(i, k).value();
      D(i, k) = v.op.D(i, k).value();
      for (int q = 0; q < kNumDerivatives; ++q) dD[q](i, k) = v.op.D(i, k).derivatives()(q);
    }
    for (int l = 0; l < TNumNodesMaster; ++l) {
      M(i, l) = v.op.M(i, l).value();
      for (int q = 0; q < kNumDerivatives; ++q) dM[q](i, l) = v.op.M(i, l).derivatives()(q);
    }
    for (int c = 0; c < TDim; ++c) gap_vector(i, c) = v.gap_vector(i, c).value();
    nodal_area(i) = v.op.nodal_area(i).value();
    d_nodal_area.row(i) = v.op.nodal_area(i).derivatives().transpose();
    weighted_gap(i) = v.weighted_gap(i).value();
    d_weighted_gap.row(i) = v.weighted_gap(i).derivatives().transpose();
  }
  return true;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>::SetMeanGaps(const SlaveVector& mean_gap) {
  if (!has_overlap || sliver) return;
  for (int j = 0; j < TNumNodes; ++j) d_constraint_gap_correction.row(j) = -mean_gap(j) * d_nodal_area.row(j);
}

#define MC_INSTANTIATE(D, S, M) template struct MortarPairKinematics<D, S, M>;
MC_FOR_EACH_MORTAR_CASE(MC_INSTANTIATE)
#undef MC_INSTANTIATE

}  // namespace mc
