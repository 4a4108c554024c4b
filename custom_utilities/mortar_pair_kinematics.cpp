// SPDX-License-Identifier: BSD-3-Clause
#include "custom_utilities/mortar_pair_kinematics.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/utilities/error.h"
#include "custom_utilities/mortar_autodiff.h"
#include "custom_utilities/mortar_operator.h"

namespace mc {
namespace {

using mortar_detail::ValueOf;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// A_e of a 2D slave line for the axisymmetric inner product int (.) 2 pi r ds (N_i N_j r is cubic
/// on the line, so 2-point Gauss is exact).
template <class T, int TNumNodes>
Eigen::Matrix<T, TNumNodes, TNumNodes> AxisymmetricAe(const Eigen::Matrix<T, TNumNodes, 2>& x1) {
  using SF1 = MortarShapeFunctions<TNumNodes>;
  const T half_length = 0.5 * (x1.row(1) - x1.row(0)).norm();
  Eigen::Matrix<T, TNumNodes, 1> d = Eigen::Matrix<T, TNumNodes, 1>::Zero();
  Eigen::Matrix<T, TNumNodes, TNumNodes> m = Eigen::Matrix<T, TNumNodes, TNumNodes>::Zero();
  for (const double xi : {-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)}) {
    typename SF1::template Local<T> local;
    local(0) = T(xi);
    const Eigen::Matrix<T, TNumNodes, 1> n = SF1::template N<T>(local);
    const T weight = half_length * kTwoPi * n.dot(x1.col(0));
    d += weight * n;
    m += weight * n * n.transpose();
  }
  return DualLagrangeMultiplier<2, TNumNodes>::template AeFromIntegrals<T>(d, m);
}

/// Values of the pair in scalar type T (double, or AutoDiff seeded by the caller).
template <class T, int TDim, int TNumNodes, int TNumNodesMaster>
struct PairValues {
  MortarIntegrationPoints<T, TDim, TNumNodes, TNumNodesMaster> points;
  Eigen::Matrix<T, TNumNodes, TNumNodes> ae;
  MortarOperator<T, TDim, TNumNodes, TNumNodesMaster> op;
  Eigen::Matrix<T, TNumNodes, TDim> gap_vector;
  Eigen::Matrix<T, TNumNodes, 1> weighted_gap;
};

template <class T, int TDim, int TNumNodes, int TNumNodesMaster>
bool ComputePair(const Eigen::Matrix<T, TNumNodes, TDim>& x1,
                 const Eigen::Matrix<T, TNumNodesMaster, TDim>& x2,
                 const Eigen::Matrix<T, TNumNodes, TDim>& n1,
                 const MortarIntegrationSettings& settings, DualBasisDomain dual_basis,
                 PairValues<T, TDim, TNumNodes, TNumNodesMaster>& out) {
  using Exact = ExactMortarIntegrationUtility<TDim, TNumNodes, TNumNodesMaster>;
  using Dual = DualLagrangeMultiplier<TDim, TNumNodes>;
  using SF1 = MortarShapeFunctions<TNumNodes>;
  if (!Exact::template Compute<T>(x1, x2, n1, settings, out.points)) return false;
  if constexpr (TDim == 2) {
    if (settings.axisymmetric)
      for (int g = 0; g < out.points.size; ++g) {
        auto& p = out.points.points[g];
        p.weight *= kTwoPi * SF1::template N<T>(p.slave_local).dot(x1.col(0));
      }
  } else if (settings.axisymmetric) {
    throw Error("mortar integration: the axisymmetric formulation exists in 2D only");
  }

  bool have_ae = false;
  if (dual_basis == DualBasisDomain::kPairOverlap) {
    Eigen::Matrix<T, TNumNodes, 1> d = Eigen::Matrix<T, TNumNodes, 1>::Zero();
    Eigen::Matrix<T, TNumNodes, TNumNodes> m = Eigen::Matrix<T, TNumNodes, TNumNodes>::Zero();
    for (int g = 0; g < out.points.size; ++g) {
      const auto& p = out.points.points[g];
      const Eigen::Matrix<T, TNumNodes, 1> n = SF1::template N<T>(p.slave_local);
      d += p.weight * n;
      m += p.weight * n * n.transpose();
    }
    out.ae = Dual::template AeFromIntegrals<T>(d, m);
    have_ae = std::isfinite(ValueOf(out.ae(0, 0)));
  }
  if (!have_ae) {
    // The dual basis must be biorthogonal in the inner product of D and M (2 pi r weighted in
    // axisymmetry), or D would not be diagonal.
    if constexpr (TDim == 2)
      out.ae = settings.axisymmetric ? AxisymmetricAe<T, TNumNodes>(x1) : Dual::template ComputeAe<T>(x1);
    else
      out.ae = Dual::template ComputeAe<T>(x1);
  }
  if (!std::isfinite(ValueOf(out.ae(0, 0))))
    throw Error(Concat("mortar integration: degenerate slave element (zero or negative measure), "
                       "first node at (",
                       ValueOf(x1(0, 0)), ", ", ValueOf(x1(0, 1)), ")"));

  out.op.Compute(out.points, out.ae);
  out.gap_vector = out.op.D * x1 - out.op.M * x2;
  for (int j = 0; j < TNumNodes; ++j) out.weighted_gap(j) = -n1.row(j).dot(out.gap_vector.row(j));
  return true;
}

}  // namespace

template <int TDim, int TNumNodes, int TNumNodesMaster>
void MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>::ClearValues() {
  area = 0.0;
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
bool MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>::ComputeValues(
    const SlaveMatrix& x1, const MasterMatrix& x2, const SlaveMatrix& n1,
    const MortarIntegrationSettings& settings, DualBasisDomain dual_basis) {
  slave_coordinates = x1;
  master_coordinates = x2;
  slave_normals = n1;
  PairValues<double, TDim, TNumNodes, TNumNodesMaster> v;
  has_overlap = ComputePair<double, TDim, TNumNodes, TNumNodesMaster>(x1, x2, n1, settings,
                                                                      dual_basis, v);
  if (!has_overlap) {
    ClearValues();
    return false;
  }
  points = v.points;
  area = v.points.area;
  Ae = v.ae;
  D = v.op.D;
  M = v.op.M;
  nodal_area = v.op.nodal_area;
  gap_vector = v.gap_vector;
  weighted_gap = v.weighted_gap;
  return true;
}

template <int TDim, int TNumNodes, int TNumNodesMaster>
bool MortarPairKinematics<TDim, TNumNodes, TNumNodesMaster>::Compute(
    const SlaveMatrix& x1, const MasterMatrix& x2, const SlaveMatrix& n1,
    const MortarIntegrationSettings& settings, DualBasisDomain dual_basis) {
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
  has_overlap =
      ComputePair<AD, TDim, TNumNodes, TNumNodesMaster>(x1_ad, x2_ad, n1_ad, settings, dual_basis, v);

  for (auto& m : dD) m.setZero();
  for (auto& m : dM) m.setZero();
  d_weighted_gap.setZero();
  d_nodal_area.setZero();
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

template struct MortarPairKinematics<2, 2, 2>;
template struct MortarPairKinematics<3, 3, 3>;
template struct MortarPairKinematics<3, 3, 4>;
template struct MortarPairKinematics<3, 4, 3>;
template struct MortarPairKinematics<3, 4, 4>;

}  // namespace mc
