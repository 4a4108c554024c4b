// SPDX-License-Identifier: BSD-3-Clause
// Issue 3: axisymmetric mortar operators (x = radius, y = axis): every integral is taken over the
// surface of revolution (weight 2 pi r), with the dual basis biorthogonal in that inner product.
// Checked against closed forms on an annular interface: D diagonal with D_jj = 2 pi int N_j r ds,
// sum D = annulus area, M rows summing to D (constant pressure transmitted exactly across
// non-matching meshes), weighted gap = D_jj times a uniform gap.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact_utilities_test_helpers.h"
#include "core/utilities/error.h"

namespace mc {
namespace {

using K = MortarPairKinematics<2, 2, 2>;
using mortar_test::Order;
using mortar_test::Rows;
constexpr double kPi = std::numbers::pi;

MortarIntegrationSettings Axisymmetric(int order) {
  MortarIntegrationSettings s = Order(order);
  s.axisymmetric = true;
  return s;
}

// The slave annulus a <= r <= b on z = 0 faces +z (its body lies below).
constexpr double a = 0.5, b = 2.0, gap = 1e-3;
K::SlaveMatrix Slave() { return Rows<K::SlaveMatrix>({a, 0.0, b, 0.0}); }
K::SlaveMatrix Up() { return Rows<K::SlaveMatrix>({0.0, 1.0, 0.0, 1.0}); }

TEST(AxisymmetricMortar, MatchingAnnulusHasClosedFormOperators) {
  K k;
  // The master is the same annulus, a uniform gap above, nodes in the opposite order.
  const auto x2 = Rows<K::MasterMatrix>({b, gap, a, gap});
  {
    ASSERT_TRUE(k.Compute(Slave(), x2, Up(), Axisymmetric(2)));
    const double length = b - a;
    const double d0 = 2 * kPi * length * (2 * a + b) / 6, d1 = 2 * kPi * length * (a + 2 * b) / 6;
    EXPECT_NEAR(k.D(0, 0), d0, 1e-13);
    EXPECT_NEAR(k.D(1, 1), d1, 1e-13);
    EXPECT_NEAR(k.D(0, 1), 0.0, 1e-13);
    EXPECT_NEAR(k.D(1, 0), 0.0, 1e-13);
    EXPECT_NEAR(k.D.sum(), kPi * (b * b - a * a), 1e-12);
    // Matching nodes: M is D with the master numbering.
    EXPECT_NEAR(k.M(0, 1), d0, 1e-13);
    EXPECT_NEAR(k.M(1, 0), d1, 1e-13);
    EXPECT_NEAR(k.M(0, 0), 0.0, 1e-13);
    EXPECT_NEAR(k.weighted_gap(0), gap * d0, 1e-15);
    EXPECT_NEAR(k.weighted_gap(1), gap * d1, 1e-15);
    EXPECT_NEAR(k.nodal_area.sum(), kPi * (b * b - a * a), 1e-12);
  }
}

TEST(AxisymmetricMortar, NonMatchingMastersTransmitAConstantPressure) {
  // Two master segments split the annulus at r = 1.3: each slave row of M sums to D_jj over the
  // pairs, and sum_j D_jj is the annulus area whatever the split.
  const double split = 1.3;
  K left, right;
  ASSERT_TRUE(left.Compute(Slave(), Rows<K::MasterMatrix>({split, gap, a - 0.1, gap}), Up(), Axisymmetric(2)));
  ASSERT_TRUE(right.Compute(Slave(), Rows<K::MasterMatrix>({b + 0.2, gap, split, gap}), Up(), Axisymmetric(2)));
  const K::DMatrix D = left.D + right.D;
  EXPECT_NEAR(D(0, 1), 0.0, 1e-13);  // each pair's dual basis makes its own D diagonal
  EXPECT_NEAR(D(1, 0), 0.0, 1e-13);
  for (int j = 0; j < 2; ++j) EXPECT_NEAR(left.M.row(j).sum() + right.M.row(j).sum(), D(j, j), 1e-13);
  EXPECT_NEAR(D.sum(), kPi * (b * b - a * a), 1e-12);
  // The partial overlaps integrate 2 pi r over each part: int_a^split 2 pi r dr.
  EXPECT_NEAR(left.nodal_area.sum(), kPi * (split * split - a * a), 1e-12);
}

TEST(AxisymmetricMortar, PlaneFormulationIsUnchangedAndAxisymmetryNeeds2D) {
  K plane;
  ASSERT_TRUE(plane.Compute(Slave(), Rows<K::MasterMatrix>({b, gap, a, gap}), Up(), Order(2)));
  EXPECT_NEAR(plane.D.sum(), b - a, 1e-14);
  using K3 = MortarPairKinematics<3, 3, 3>;
  K3 k3;
  const auto x1 = Rows<K3::SlaveMatrix>({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const auto x2 = Rows<K3::MasterMatrix>({0, 0, 0.1, 0, 1, 0.1, 1, 0, 0.1});
  const auto n1 = Rows<K3::SlaveMatrix>({0, 0, 1, 0, 0, 1, 0, 0, 1});
  MortarIntegrationSettings settings;
  settings.axisymmetric = true;
  EXPECT_THROW(k3.Compute(x1, x2, n1, settings), Error);
}

}  // namespace
}  // namespace mc
