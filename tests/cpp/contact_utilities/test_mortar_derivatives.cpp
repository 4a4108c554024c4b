// SPDX-License-Identifier: BSD-3-Clause
// Issue 3: exact derivatives of the mortar pair data (D, M, weighted gap, nodal area, overlap
// area) with respect to master/slave displacements and slave nodal normals, checked against
// central finite differences (relative 1e-6) on partially overlapping 2D (also axisymmetric) and
// 3D pairs.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "contact_utilities_test_helpers.h"

namespace mc {
namespace {

using mortar_test::ConditionNormals;
using mortar_test::Order;
using mortar_test::Rows;

struct Errors {
  double max_error = 0.0;
  double max_value = 0.0;
  void Add(double ad, double fd) {
    max_error = std::max(max_error, std::abs(ad - fd));
    max_value = std::max(max_value, std::abs(ad));
  }
  double Relative() const { return max_error / max_value; }
};

template <class K>
void CheckAgainstFiniteDifferences(const typename K::SlaveMatrix& x1, const typename K::MasterMatrix& x2,
                                   const typename K::SlaveMatrix& n1, int order, bool axisymmetric = false) {
  MortarIntegrationSettings settings = Order(order);
  settings.axisymmetric = axisymmetric;
  K k;
  ASSERT_TRUE(k.Compute(x1, x2, n1, settings));
  const double h = 1e-6;
  Errors e_d, e_m, e_gap, e_area, e_nodal;
  K plus, minus;
  for (int q = 0; q < K::kNumDerivatives; ++q) {
    auto perturbed = [&](double delta, K& out) {
      typename K::SlaveMatrix y1 = x1, m1 = n1;
      typename K::MasterMatrix y2 = x2;
      if (q < K::kNumMasterDofs)
        y2(q / K::kDim, q % K::kDim) += delta;
      else if (q < K::kNumDisplacementDofs)
        y1((q - K::kNumMasterDofs) / K::kDim, (q - K::kNumMasterDofs) % K::kDim) += delta;
      else
        m1((q - K::kNumDisplacementDofs) / K::kDim, (q - K::kNumDisplacementDofs) % K::kDim) += delta;
      ASSERT_TRUE(out.ComputeValues(y1, y2, m1, settings));
      ASSERT_EQ(out.points.size, k.points.size) << "segmentation pattern changed at q = " << q;
    };
    perturbed(h, plus);
    perturbed(-h, minus);
    const typename K::DMatrix fd_d = (plus.D - minus.D) / (2 * h);
    const typename K::MMatrix fd_m = (plus.M - minus.M) / (2 * h);
    for (int i = 0; i < K::kNumSlaveNodes; ++i) {
      for (int j = 0; j < K::kNumSlaveNodes; ++j) e_d.Add(k.dD[q](i, j), fd_d(i, j));
      for (int l = 0; l < K::kNumMasterNodes; ++l) e_m.Add(k.dM[q](i, l), fd_m(i, l));
      e_gap.Add(k.d_weighted_gap(i, q), (plus.weighted_gap(i) - minus.weighted_gap(i)) / (2 * h));
      e_nodal.Add(k.d_nodal_area(i, q), (plus.nodal_area(i) - minus.nodal_area(i)) / (2 * h));
    }
    e_area.Add(k.d_area(q), (plus.area - minus.area) / (2 * h));
  }
  EXPECT_LT(e_d.Relative(), 1e-6) << "dD, max " << e_d.max_value;
  EXPECT_LT(e_m.Relative(), 1e-6) << "dM, max " << e_m.max_value;
  EXPECT_LT(e_gap.Relative(), 1e-6) << "d weighted gap, max " << e_gap.max_value;
  EXPECT_LT(e_nodal.Relative(), 1e-6) << "d nodal area, max " << e_nodal.max_value;
  EXPECT_LT(e_area.Relative(), 1e-6) << "d area, max " << e_area.max_value;
  // The check must be able to fail: the derivatives are not trivially zero.
  EXPECT_GT(e_d.max_value, 1e-3);
  EXPECT_GT(e_m.max_value, 1e-3);
  EXPECT_GT(e_gap.max_value, 1e-3);
}

// Nodal normals tilted differently at every node (a curved interface).
template <class K>
typename K::SlaveMatrix TiltedNormals(const typename K::SlaveMatrix& x1) {
  typename K::SlaveMatrix n = ConditionNormals<K>(x1);
  for (int i = 0; i < K::kNumSlaveNodes; ++i) {
    for (int c = 0; c < K::kDim; ++c) n(i, c) += 0.07 * std::sin(1.3 * i + 2.1 * c + 0.4);
    n.row(i).normalize();
  }
  return n;
}

TEST(MortarDerivatives, Line2D2PartialOverlap) {
  using K = MortarPairKinematics<2, 2, 2>;
  const auto x1 = Rows<K::SlaveMatrix>({1.0, 0.05, 0.0, -0.02});
  const auto x2 = Rows<K::MasterMatrix>({0.4, 0.1, 1.6, 0.2});
  CheckAgainstFiniteDifferences<K>(x1, x2, TiltedNormals<K>(x1), 2);
  CheckAgainstFiniteDifferences<K>(x1, x2, TiltedNormals<K>(x1), 3);
  // Master inside the slave (both master ends projected inside).
  const auto x2_inside = Rows<K::MasterMatrix>({0.7, 0.1, 0.2, 0.08});
  CheckAgainstFiniteDifferences<K>(x1, x2_inside, TiltedNormals<K>(x1), 2);
}

// The constraint rows' correction (SetMeanGaps) with the pair's own mean gaps wg_j / a_j gives
// a_j d(wg_j / a_j): the derivative of the mean gap, scaled by the nodal area.
template <class K>
void CheckMeanGapCorrection(const typename K::SlaveMatrix& x1, const typename K::MasterMatrix& x2,
                            const typename K::SlaveMatrix& n1) {
  const MortarIntegrationSettings settings = Order(3);
  K k;
  ASSERT_TRUE(k.Compute(x1, x2, n1, settings));
  ASSERT_FALSE(k.sliver);
  const typename K::SlaveVector mean_gap = k.weighted_gap.cwiseQuotient(k.nodal_area);
  k.SetMeanGaps(mean_gap);
  const double h = 1e-6;
  Errors e_mean, e_change;
  K plus, minus;
  for (int q = 0; q < K::kNumDisplacementDofs; ++q) {
    typename K::SlaveMatrix y1 = x1;
    typename K::MasterMatrix y2 = x2;
    auto& value = q < K::kNumMasterDofs ? y2(q / K::kDim, q % K::kDim)
                                        : y1((q - K::kNumMasterDofs) / K::kDim, (q - K::kNumMasterDofs) % K::kDim);
    const double original = value;
    value = original + h;
    ASSERT_TRUE(plus.ComputeValues(y1, y2, n1, settings));
    value = original - h;
    ASSERT_TRUE(minus.ComputeValues(y1, y2, n1, settings));
    for (int j = 0; j < K::kNumSlaveNodes; ++j) {
      const double fd_mean =
          (plus.weighted_gap(j) / plus.nodal_area(j) - minus.weighted_gap(j) / minus.nodal_area(j)) / (2 * h);
      e_mean.Add(k.d_weighted_gap(j, q) + k.d_constraint_gap_correction(j, q), k.nodal_area(j) * fd_mean);
      e_change.Add(k.d_constraint_gap_correction(j, q), 0.0);
    }
  }
  EXPECT_LT(e_mean.Relative(), 1e-6) << "a d(wg / a), max " << e_mean.max_value;
  EXPECT_GT(e_change.max_value, 1e-3 * e_mean.max_value);  // the correction is not trivially zero
}

TEST(MortarDerivatives, MeanGapCorrection) {
  using K2 = MortarPairKinematics<2, 2, 2>;
  const auto x1 = Rows<K2::SlaveMatrix>({1.0, 0.05, 0.0, -0.02});
  CheckMeanGapCorrection<K2>(x1, Rows<K2::MasterMatrix>({0.4, 0.1, 1.6, 0.2}), TiltedNormals<K2>(x1));
  using K3 = MortarPairKinematics<3, 4, 4>;
  const auto q1 = Rows<K3::SlaveMatrix>({0, 0, 0, 1, 0.1, 0.03, 1.1, 0.9, -0.02, -0.1, 1, 0.04});
  const auto q2 = Rows<K3::MasterMatrix>({0.3, 0.2, 0.1, 1.4, 0.3, 0.12, 1.3, 1.2, 0.09, 0.2, 1.1, 0.11});
  CheckMeanGapCorrection<K3>(q1, q2, TiltedNormals<K3>(q1));
}

TEST(MortarDerivatives, AxisymmetricLine2D2) {
  // x = radius: the 2 pi r weight and the r-weighted dual basis are differentiated too.
  using K = MortarPairKinematics<2, 2, 2>;
  const auto x1 = Rows<K::SlaveMatrix>({1.8, 0.05, 0.6, -0.02});
  const auto x2 = Rows<K::MasterMatrix>({0.9, 0.1, 2.2, 0.2});
  CheckAgainstFiniteDifferences<K>(x1, x2, TiltedNormals<K>(x1), 2, true);
  CheckAgainstFiniteDifferences<K>(x1, x2, TiltedNormals<K>(x1), 3, true);
}

TEST(MortarDerivatives, TrianglesCrossing) {
  using K = MortarPairKinematics<3, 3, 3>;
  const auto x1 = Rows<K::SlaveMatrix>({0, 0, 0, 1, 0.05, 0.02, 0.1, 0.9, -0.03});
  const auto x2 = Rows<K::MasterMatrix>({0.2, -0.2, 0.05, 1.0, 0.6, 0.08, -0.1, 0.5, 0.03});
  CheckAgainstFiniteDifferences<K>(x1, x2, TiltedNormals<K>(x1), 2);
  CheckAgainstFiniteDifferences<K>(x1, x2, TiltedNormals<K>(x1), 3);
}

TEST(MortarDerivatives, QuadrilateralsRotatedAndWarped) {
  using K = MortarPairKinematics<3, 4, 4>;
  // Warped distorted slave; master rotated in-plane and shifted (octagon-like overlap).
  const auto x1 = Rows<K::SlaveMatrix>({0, 0, 0, 1, 0.1, 0.03, 1.1, 0.9, -0.02, -0.1, 1, 0.04});
  K::MasterMatrix x2;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d c(0.55, 0.5, 0.1);
  const Eigen::Vector3d corners[4] = {{-0.5, -0.5, 0}, {0.5, -0.5, 0.01}, {0.5, 0.5, -0.01}, {-0.5, 0.5, 0}};
  for (int l = 0; l < 4; ++l) x2.row(l) = (c + R * corners[l]).transpose();
  CheckAgainstFiniteDifferences<K>(x1, x2, TiltedNormals<K>(x1), 2);
}

TEST(MortarDerivatives, MixedTriangleQuadrilateral) {
  using KTQ = MortarPairKinematics<3, 3, 4>;
  const auto t1 = Rows<KTQ::SlaveMatrix>({0, 0, 0, 1, 0.05, 0.02, 0.1, 0.9, -0.03});
  const auto q2 = Rows<KTQ::MasterMatrix>({0.3, 0.2, 0.05, 1.3, 0.1, 0.02, 1.2, 1.1, 0.06, 0.25, 0.9, 0.04});
  CheckAgainstFiniteDifferences<KTQ>(t1, q2, TiltedNormals<KTQ>(t1), 3);

  using KQT = MortarPairKinematics<3, 4, 3>;
  const auto q1 = Rows<KQT::SlaveMatrix>({0, 0, 0, 1, 0.1, 0.02, 1.1, 0.9, -0.01, -0.1, 1, 0.03});
  const auto t2 = Rows<KQT::MasterMatrix>({0.3, 0.2, 0.05, 1.4, 0.5, 0.09, 0.2, 1.3, 0.02});
  CheckAgainstFiniteDifferences<KQT>(q1, t2, TiltedNormals<KQT>(q1), 2);
  // A master triangle inside the slave quadrilateral: one sub-triangle, whose 3 points at order 2
  // cannot carry a 4-node dual basis; the pair is integrated at the dual-basis order instead.
  const auto t_inside = Rows<KQT::MasterMatrix>({0.2, 0.25, 0.05, 0.8, 0.3, 0.06, 0.4, 0.7, 0.04});
  CheckAgainstFiniteDifferences<KQT>(q1, t_inside, TiltedNormals<KQT>(q1), 2);
}

}  // namespace
}  // namespace mc
