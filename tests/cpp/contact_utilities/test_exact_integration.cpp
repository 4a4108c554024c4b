// SPDX-License-Identifier: BSD-3-Clause
// Issue 3: exact mortar segmentation reproduces the Kratos integration points and weights
// (cases/mortar_integration_reference.md sections 1-5 and 8): 2D segment overlaps, 3D
// triangle/quadrilateral clipping with fan triangulation, exact overlap areas.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "contact_utilities_test_helpers.h"
#include "core/utilities/error.h"

namespace mc {
namespace {

using mortar_test::ConditionNormals;
using mortar_test::Order;
using mortar_test::Rows;

constexpr double kTol = 1e-12;

// Rows [xi, (eta,) w] in the Kratos test format (2D weights are twice the physical ones).
template <int D, int N1, int N2>
std::vector<std::array<double, 3>> KratosRows(const MortarIntegrationPoints<double, D, N1, N2>& points) {
  std::vector<std::array<double, 3>> rows;
  for (int g = 0; g < points.size; ++g) {
    const auto& p = points.points[g];
    if constexpr (D == 2)
      rows.push_back({p.slave_local(0), 2.0 * p.weight, 0.0});
    else
      rows.push_back({p.slave_local(0), p.slave_local(1), p.weight});
  }
  return rows;
}

void ExpectRows(const std::vector<std::array<double, 3>>& got, const std::vector<std::array<double, 3>>& expected) {
  ASSERT_EQ(got.size(), expected.size());
  for (size_t r = 0; r < got.size(); ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[r][c], expected[r][c], kTol) << "row " << r << " col " << c;
}

template <int D, int N1, int N2>
std::vector<std::array<double, 3>> KratosRows(const MortarPairKinematics<D, N1, N2>& k) {
  return KratosRows(k.points);
}

// The segmentation alone, at an order the pair's dual basis would not accept (order 1).
template <int D, int N1, int N2>
MortarIntegrationPoints<double, D, N1, N2> Segment(const typename MortarPairKinematics<D, N1, N2>::SlaveMatrix& x1,
                                                   const typename MortarPairKinematics<D, N1, N2>::MasterMatrix& x2,
                                                   int order) {
  using K = MortarPairKinematics<D, N1, N2>;
  MortarIntegrationPoints<double, D, N1, N2> points;
  EXPECT_TRUE(
      (ExactMortarIntegrationUtility<D, N1, N2>::Compute(x1, x2, ConditionNormals<K>(x1), Order(order), points)));
  return points;
}

template <int N1, int N2>
MortarPairKinematics<3, N1, N2> Pair3D(const typename MortarPairKinematics<3, N1, N2>::SlaveMatrix& x1,
                                       const typename MortarPairKinematics<3, N1, N2>::MasterMatrix& x2,
                                       int order = 2) {
  using K = MortarPairKinematics<3, N1, N2>;
  K k;
  EXPECT_TRUE(k.Compute(x1, x2, ConditionNormals<K>(x1), Order(order)));
  return k;
}

using K2 = MortarPairKinematics<2, 2, 2>;
using K33 = MortarPairKinematics<3, 3, 3>;
using K44 = MortarPairKinematics<3, 4, 4>;

K2 Pair2D(std::initializer_list<double> slave, std::initializer_list<double> master, int order) {
  const auto x1 = Rows<K2::SlaveMatrix>(slave);
  K2 k;
  EXPECT_TRUE(k.Compute(x1, Rows<K2::MasterMatrix>(master), ConditionNormals<K2>(x1), Order(order)));
  return k;
}

TEST(ExactMortarIntegration, Line2D_L2_1_FullOverlap) {
  const auto k = Pair2D({0, 0, 1, 0}, {0, 0.001, 1, 0.001}, 2);
  ExpectRows(KratosRows(k), {{-0.57735026918963, 1.0, 0}, {0.57735026918963, 1.0, 0}});
  EXPECT_NEAR(k.area, 1.0, kTol);
}

TEST(ExactMortarIntegration, Line2D_L2_2_HalfOverlap) {
  const auto k = Pair2D({0, 0, 1, 0}, {0.5, 0.001, 1.5, 0.001}, 2);
  ExpectRows(KratosRows(k), {{0.21132486540517492, 0.5, 0}, {0.7886751345947951, 0.5, 0}});
  // Master local coordinates: slave xi=0.2113 is x=0.6057 -> master xi = 2*(0.6057-1)
  EXPECT_NEAR(k.points.points[0].master_local(0), 2.0 * (0.5 * (1 + 0.21132486540517492) - 1.0), kTol);
}

TEST(ExactMortarIntegration, Line2D_L2_3_InclinedSlave) {
  const auto k = Pair2D({0, -0.5, 1, 0.5}, {0, 0.5, 1, 0.5}, 2);
  ExpectRows(KratosRows(k), {{0.21132486540517847, 1 / std::sqrt(2.0), 0}, {0.7886751345948, 1 / std::sqrt(2.0), 0}});
  EXPECT_NEAR(k.area, std::sqrt(2.0) / 2, kTol);
}

TEST(ExactMortarIntegration, Line2D_Order1_OlderRevisions) {
  const auto slave = Rows<K2::SlaveMatrix>({0, 0, 1, 0});
  ExpectRows(KratosRows(Segment<2, 2, 2>(slave, Rows<K2::MasterMatrix>({0, 0.001, 1, 0.001}), 1)), {{0.0, 2.0, 0}});
  ExpectRows(KratosRows(Segment<2, 2, 2>(slave, Rows<K2::MasterMatrix>({0.5, 0.001, 1.5, 0.001}), 1)), {{0.5, 1.0, 0}});
  // One point cannot carry the pair's two dual functions: the pair is integrated at a higher order.
  EXPECT_GT(Pair2D({0, 0, 1, 0}, {0, 0.001, 1, 0.001}, 1).points.size, 1);
}

TEST(ExactMortarIntegration, Line2D_NoOverlapAndTouching) {
  K2 k;
  const auto x1 = Rows<K2::SlaveMatrix>({0, 0, 1, 0});
  EXPECT_FALSE(k.Compute(x1, Rows<K2::MasterMatrix>({1.5, 0.1, 2.5, 0.1}), ConditionNormals<K2>(x1), Order(2)));
  EXPECT_FALSE(k.Compute(x1, Rows<K2::MasterMatrix>({1.0, 0.1, 2.0, 0.1}), ConditionNormals<K2>(x1), Order(2)));
  EXPECT_EQ(k.points.size, 0);
  EXPECT_EQ(k.D.norm(), 0.0);
}

TEST(ExactMortarIntegration, Triangle_T3_1_Identical) {
  const auto k = Pair3D<3, 3>(Rows<K33::SlaveMatrix>({0, 0, 0, 1, 0, 0, 0, 1, 0}),
                              Rows<K33::MasterMatrix>({0, 0, 0.01, 1, 0, 0.01, 0, 1, 0.01}));
  ExpectRows(KratosRows(k), {{1. / 6, 1. / 6, 1. / 6}, {4. / 6, 1. / 6, 1. / 6}, {1. / 6, 4. / 6, 1. / 6}});
}

TEST(ExactMortarIntegration, Triangle_T3_2_Crossed) {
  const auto k = Pair3D<3, 3>(Rows<K33::SlaveMatrix>({0, 0, 0, 1, 0, 0, 0, 1, 0}),
                              Rows<K33::MasterMatrix>({0, 0, 0.01, 1, 0, 0.01, 1, 1, 0.01}));
  ExpectRows(KratosRows(k), {{0.25, 1. / 12, 1. / 12}, {0.75, 1. / 12, 1. / 12}, {0.5, 1. / 3, 1. / 12}});
  EXPECT_NEAR(k.area, 0.25, kTol);
  // Order 1 (older utilities test): the overlap centroid with w = overlap area.
  ExpectRows(KratosRows(Segment<3, 3, 3>(Rows<K33::SlaveMatrix>({0, 0, 0, 1, 0, 0, 0, 1, 0}),
                                         Rows<K33::MasterMatrix>({0, 0, 0.01, 1, 0, 0.01, 1, 1, 0.01}), 1)),
             {{0.5, 1. / 6, 0.25}});
}

TEST(ExactMortarIntegration, Triangle_T3_3_AllPairings) {
  const Eigen::Vector3d p[9] = {{0, 0, 0},    {0, 0, 0},    {1, 0, 0},    {0, 1, 0},   {1, 1, 0},
                                {0, 0, 0.01}, {1, 0, 0.01}, {0, 1, 0.01}, {1, 1, 0.01}};
  auto tri = [&](int a, int b, int c) {
    K33::SlaveMatrix m;
    m.row(0) = p[a].transpose();
    m.row(1) = p[b].transpose();
    m.row(2) = p[c].transpose();
    return m;
  };
  const auto c1 = tri(1, 2, 3), c2 = tri(2, 4, 3), c3 = tri(5, 6, 8), c4 = tri(5, 8, 7);
  const double w = 1.0 / 12;
  // The fan start reproduces Kratos' row order exactly; compare rows, then invariants.
  ExpectRows(KratosRows(Pair3D<3, 3>(c1, c3)), {{0.25, 1. / 12, w}, {0.75, 1. / 12, w}, {0.5, 1. / 3, w}});
  ExpectRows(KratosRows(Pair3D<3, 3>(c1, c4)), {{1. / 12, 0.25, w}, {1. / 3, 0.5, w}, {1. / 12, 0.75, w}});
  ExpectRows(KratosRows(Pair3D<3, 3>(c2, c3)), {{1. / 6, 1. / 12, w}, {2. / 3, 1. / 12, w}, {1. / 6, 1. / 3, w}});
  ExpectRows(KratosRows(Pair3D<3, 3>(c2, c4)), {{2. / 3, 0.25, w}, {1. / 6, 0.75, w}, {1. / 6, 0.5, w}});
}

TEST(ExactMortarIntegration, Quadrilateral_Q4_1_Identical) {
  const auto k = Pair3D<4, 4>(Rows<K44::SlaveMatrix>({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}),
                              Rows<K44::MasterMatrix>({0, 0, 0.01, 1, 0, 0.01, 1, 1, 0.01, 0, 1, 0.01}));
  const double w = 1.0 / 6;
  ExpectRows(KratosRows(k), {{-1. / 3, -2. / 3, w},
                             {2. / 3, -2. / 3, w},
                             {2. / 3, 1. / 3, w},
                             {-2. / 3, -1. / 3, w},
                             {1. / 3, 2. / 3, w},
                             {-2. / 3, 2. / 3, w}});
}

TEST(ExactMortarIntegration, Quadrilateral_Q4_2_Shifted) {
  const auto k =
      Pair3D<4, 4>(Rows<K44::SlaveMatrix>({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}),
                   Rows<K44::MasterMatrix>({0.5, 0.5, 0.01, 1.5, 0.5, 0.01, 1.5, 1.5, 0.01, 0.5, 1.5, 0.01}));
  const double w = 1.0 / 24;
  ExpectRows(KratosRows(k), {{2. / 6, 1. / 6, w},
                             {5. / 6, 1. / 6, w},
                             {5. / 6, 4. / 6, w},
                             {1. / 6, 2. / 6, w},
                             {4. / 6, 5. / 6, w},
                             {1. / 6, 5. / 6, w}});
  // Master local coordinates of the first point: physical (0.6667, 0.5833) -> master
  // xi = 2(x-0.5)-1, eta = 2(y-0.5)-1.
  EXPECT_NEAR(k.points.points[0].master_local(0), 2 * (0.5 * (1 + 2. / 6) - 0.5) - 1, kTol);
  EXPECT_NEAR(k.points.points[0].master_local(1), 2 * (0.5 * (1 + 1. / 6) - 0.5) - 1, kTol);
}

// A warped quadrilateral slave is integrated on its fan triangles lifted onto it, as Kratos 10.4
// does: fully covered, the fan from node 0 lifts to the triangles (0,1,2) and (0,2,3) of its
// nodes, whose area follows the tilt of the face; the projection on the mean plane is smaller.
TEST(ExactMortarIntegration, WarpedQuadrilateralIsIntegratedOnTheLiftedFan) {
  const auto x1 = Rows<K44::SlaveMatrix>({0, 0, 0, 1, 0, 0.2, 1, 1, 0, 0, 1, 0.2});
  const auto x2 = Rows<K44::MasterMatrix>({-1, -1, 0.3, 2, -1, 0.3, 2, 2, 0.3, -1, 2, 0.3});
  const auto k = Pair3D<4, 4>(x1, x2);
  auto triangle = [&](int a, int b, int c) {
    return 0.5 * (x1.row(b) - x1.row(a)).cross(x1.row(c) - x1.row(a)).norm();
  };
  const double lifted = triangle(0, 1, 2) + triangle(0, 2, 3);
  EXPECT_NEAR(k.area, lifted, 1e-13);
  EXPECT_NEAR(k.D.sum(), lifted, 1e-13);
  const Eigen::Vector3d n = ConditionNormals<K44>(x1).row(0).transpose();
  const double projected = 0.5 * (x1.row(2) - x1.row(0)).cross(x1.row(3) - x1.row(1)).dot(n.transpose());
  EXPECT_GT(lifted - projected, 1e-2);
}

TEST(ExactMortarIntegration, MasterOrderingAndRuleOrderDoNotChangeInvariants) {
  // Q4-2 with the master listed clockwise, for every order: same area and first moments.
  const auto x1 = Rows<K44::SlaveMatrix>({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  const auto x2 = Rows<K44::MasterMatrix>({0.5, 1.5, 0.01, 1.5, 1.5, 0.01, 1.5, 0.5, 0.01, 0.5, 0.5, 0.01});
  for (int order = 1; order <= 5; ++order) {
    const auto k = Pair3D<4, 4>(x1, x2, order);
    double sw = 0, sx = 0, sy = 0;
    for (int g = 0; g < k.points.size; ++g) {
      const auto& p = k.points.points[g];
      sw += p.weight;
      sx += p.weight * p.slave_local(0);
      sy += p.weight * p.slave_local(1);
    }
    EXPECT_NEAR(sw, 0.25, kTol) << order;
    EXPECT_NEAR(sx, 0.125, kTol) << order;
    EXPECT_NEAR(sy, 0.125, kTol) << order;
  }
}

TEST(ExactMortarIntegration, Section5_NearlyParallelTiltedTriangles) {
  // Slave [3,2,1], master = slave + 0.01 z; Kratos: 0.499925 (relative 1e-4).
  const auto x1 = Rows<K33::SlaveMatrix>({0, 1, 0.01, 1, 0, 0, 0, 0, 0});
  const auto x2 = Rows<K33::MasterMatrix>({0, 0, 0.01, 1, 0, 0.01, 0, 1, 0.02});
  const auto k = Pair3D<3, 3>(x1, x2);
  EXPECT_NEAR(k.area, 0.499925, 0.499925 * 1e-7);
  EXPECT_LE((k.area - 0.499925) / 0.499925, 1e-4);
}

// SUM-3 (quadrilaterals_non_matching.mdpa): pair areas and per-slave sums.
TEST(ExactMortarIntegration, Sum3_NonMatchingQuadrilaterals) {
  using K = K44;
  auto quad = [](std::initializer_list<double> xy) {
    K::SlaveMatrix m;
    auto it = xy.begin();
    for (int i = 0; i < 4; ++i) {
      m(i, 0) = *it++;
      m(i, 1) = *it++;
      m(i, 2) = 0.0;
    }
    return m;
  };
  const K::SlaveMatrix slaves[4] = {quad({6, 6, 6, 5, 5, 5, 5, 6}), quad({5, 6, 5, 5, 4, 5, 4, 6}),
                                    quad({6, 5, 6, 4, 5, 4, 5, 5}), quad({5, 5, 5, 4, 4, 4, 4, 5})};
  const K::MasterMatrix masters[4] = {quad({4, 6, 4, 4.7, 4.7, 4.7, 4.7, 6}), quad({4.7, 6, 4.7, 4.7, 6, 4.7, 6, 6}),
                                      quad({4, 4.7, 4, 4, 4.7, 4, 4.7, 4.7}), quad({4.7, 4.7, 4.7, 4, 6, 4, 6, 4.7})};
  // expected[slave][master] (slaves El 5..8, masters El 1..4)
  const double expected[4][4] = {{0, 1.0, 0, 0}, {0.7, 0.3, 0, 0}, {0, 0.3, 0, 0.7}, {0.21, 0.09, 0.49, 0.21}};
  for (int s = 0; s < 4; ++s) {
    double sum = 0.0;
    for (int m = 0; m < 4; ++m) {
      K k;
      k.Compute(slaves[s], masters[m], ConditionNormals<K>(slaves[s]), Order(2));
      EXPECT_NEAR(k.area, expected[s][m], 1e-12) << "slave " << s << " master " << m;
      sum += k.area;
    }
    EXPECT_NEAR(sum, 1.0, 1e-12) << "slave " << s;
  }
}

// SUM-4 (quadrilaterals_moving_nodes.mdpa): slave edges miss the master lines by 1e-6.
TEST(ExactMortarIntegration, Sum4_SliverPolygons) {
  using K = K44;
  const double h = 0.125;
  auto move = [](double x, double y) {
    const double r = std::max(std::abs(x - 0.5), std::abs(y - 0.5));
    Eigen::Vector3d p(x, y, 0.001);
    if (r > 0 && std::abs(std::abs(x - 0.5) - r) < 1e-12) p(0) += (x > 0.5 ? 1e-6 : -1e-6);
    if (r > 0 && std::abs(std::abs(y - 0.5) - r) < 1e-12) p(1) += (y > 0.5 ? 1e-6 : -1e-6);
    return p;
  };
  double worst = 0.0;
  for (int si = 0; si < 4; ++si)
    for (int sj = 0; sj < 4; ++sj) {
      const double x0 = 0.25 + si * h, y0 = 0.25 + sj * h;
      K::SlaveMatrix x1;  // clockwise seen from +z, as in the mdpa
      x1.row(0) = move(x0, y0).transpose();
      x1.row(1) = move(x0, y0 + h).transpose();
      x1.row(2) = move(x0 + h, y0 + h).transpose();
      x1.row(3) = move(x0 + h, y0).transpose();
      const Eigen::Vector3d d1 = x1.row(2) - x1.row(0), d2 = x1.row(3) - x1.row(1);
      const double slave_area = 0.5 * d1.cross(d2).norm();
      double sum = 0.0;
      for (int mi = 0; mi < 8; ++mi)
        for (int mj = 0; mj < 8; ++mj) {
          K::MasterMatrix x2;
          x2 << mi * h, mj * h, 0, (mi + 1) * h, mj * h, 0, (mi + 1) * h, (mj + 1) * h, 0, mi * h, (mj + 1) * h, 0;
          K k;
          k.ComputeValues(x1, x2, ConditionNormals<K>(x1), Order(3));
          sum += k.area;
        }
      worst = std::max(worst, std::abs(sum - slave_area) / slave_area);
    }
  // Kratos asserts 5e-5; merging vertices closer than the tolerance costs ~1e-11 here.
  EXPECT_LT(worst, 1e-9);
}

// Degenerate clipping (issue 12): a unit slave square and a master square of side a (a = 1 or
// 0.5) whose edges lie on the slave's edges, meet them at a corner or a shared vertex, cover it
// exactly, or miss those positions by 1e-15 .. 1e-7 (aligned meshes after a tangential shift),
// mapped onto an arbitrarily rotated plane with a 1e-3 gap so that no coordinate is exact. Every
// pair is segmented (no "clipped polygon with n vertices"), into at most 8 vertices, and its area
// is the exact overlap (a product of the interval overlaps) to 1e-12; slivers narrower than the
// vertex-merging distance (1e-10 of the face size) may be dropped.
TEST(ExactMortarIntegration, AlignedSharedAndCoincidentQuadrilaterals) {
  using K = K44;
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()))
          .toRotationMatrix();
  const Eigen::Vector3d origin(0.31, -0.27, 0.11);
  auto place = [&](double x, double y, double z) { return (origin + rotation * Eigen::Vector3d(x, y, z)).eval(); };
  K::SlaveMatrix x1;
  const double square[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i) x1.row(i) = place(square[i][0], square[i][1], 0.0).transpose();
  const double offsets[] = {0.0, 1e-15, -1e-15, 1e-11, -1e-11, 1e-9, -1e-7};
  const double positions[] = {-1.0, -0.5, 0.0, 0.25, 0.5, 1.0};
  int pairs = 0, overlapping = 0;
  for (const double side : {1.0, 0.5})
    for (const double px : positions)
      for (const double py : positions)
        for (const double ox : offsets)
          for (const double oy : offsets) {
            const double x0 = px + ox, y0 = py + oy;
            K::MasterMatrix x2;
            for (int l = 0; l < 4; ++l)
              x2.row(l) = place(x0 + side * square[3 - l][0], y0 + side * square[3 - l][1], 1e-3).transpose();
            const double exact = std::max(0.0, std::min(1.0, x0 + side) - std::max(0.0, x0)) *
                                 std::max(0.0, std::min(1.0, y0 + side) - std::max(0.0, y0));
            MortarIntegrationPoints<double, 3, 4, 4> points;
            bool found = false;
            ASSERT_NO_THROW(found = (ExactMortarIntegrationUtility<3, 4, 4>::Compute(x1, x2, ConditionNormals<K>(x1),
                                                                                     Order(2), points)))
                << "master at (" << x0 << ", " << y0 << "), side " << side;
            const double area = found ? points.area : 0.0;
            if (exact > 1e-9 || area > 0.0)
              EXPECT_NEAR(area, exact, 1e-12) << "master at (" << x0 << ", " << y0 << "), side " << side;
            else
              EXPECT_LT(exact, 1e-10) << "master at (" << x0 << ", " << y0 << "), side " << side;
            // At most n + m - 2 = 6 fan triangles of 3 points.
            EXPECT_LE(points.size, 6 * 3);
            ++pairs;
            overlapping += exact > 1e-12;
          }
  EXPECT_EQ(pairs, 2 * 36 * 49);
  EXPECT_GT(overlapping, 1000);
}

// The pair that raised "clipped polygon with 9 vertices" in the frictional sweep
// (3d_hex_flat_r0.5_overhang-none_gap_disp_4steps_fric_mu0.3_shift, step 7, third iteration, after a
// Newton step of |r_u|^2/|r_u0|^2 = 6e20): its master face, 1 in size where it was 0.2, is folded
// seen along the slave normal. The error says so instead of integrating a wrong area.
// The friction block's edge element (ALM_frictional_contact_test_3D/friction_block_test, step 1):
// the slave edge 1-4 lies on the master edge 1-4 (z = 0.125) to 1e-13 and, in one Newton
// iterate, crosses it at a tiny angle. A vertex within the clipping tolerance of the slave edge
// counted as inside while its neighbour did not, both on the outer side of the edge's line, and
// their "crossing" was extrapolated far beyond them: the overlap came out 1.48e-2 (twice the
// element), with a negative nodal area. Now the same as for the iterate before (the edges do not
// cross there) and as the covered rectangle.
TEST(ExactMortarIntegration, NearlyCoincidentCrossingEdges) {
  const auto before = Rows<K44::SlaveMatrix>({-2.817465125852273e-04, 2.499693943279183e-01, 1.250000000000586e-01,
                                              -2.630061137091091e-04, 2.499699878096750e-01, -1.542024951517003e-04,
                                              5.605053944673730e-02, 2.499723725580025e-01, -1.450441754659543e-04,
                                              5.603936222432041e-02, 2.499716596749598e-01, 1.250000000003177e-01});
  const auto crossing = Rows<K44::SlaveMatrix>({-2.817465135257619e-04, 2.499693943279395e-01, 1.249999999999033e-01,
                                                -2.630061143427401e-04, 2.499699878096754e-01, -1.542024951187964e-04,
                                                5.605053944613806e-02, 2.499723725580116e-01, -1.450441754555893e-04,
                                                5.603936222344305e-02, 2.499716596749339e-01, 1.250000000001807e-01});
  const auto master_before = Rows<K44::MasterMatrix>(
      {-1.708552352690099e-05, 2.499694047566575e-01, 1.250000000000000e-01, -1.693713127056040e-05,
       2.499699972767907e-01, 0.000000000000000e+00, 8.887625398904693e-02, 2.499736787279011e-01,
       0.000000000000000e+00, 8.887622339930927e-02, 2.499729053698445e-01, 1.250000000000000e-01});
  const auto master = Rows<K44::MasterMatrix>({-1.708552350238575e-05, 2.499694047566788e-01, 1.250000000000000e-01,
                                               -1.693713126678115e-05, 2.499699972767911e-01, 0.000000000000000e+00,
                                               8.887625398905492e-02, 2.499736787279142e-01, 0.000000000000000e+00,
                                               8.887622339932208e-02, 2.499729053698506e-01, 1.250000000000000e-01});
  const auto master_above = Rows<K44::MasterMatrix>(
      {-1.693713127012413e-05, 2.499699972767421e-01, 2.500000000000000e-01, -1.708552350238575e-05,
       2.499694047566788e-01, 1.250000000000000e-01, 8.887622339932208e-02, 2.499729053698506e-01,
       1.250000000000000e-01, 8.887625398902968e-02, 2.499736787275874e-01, 2.500000000000000e-01});
  K44 reference, k, above;
  ASSERT_TRUE(reference.Compute(before, master_before, ConditionNormals<K44>(before), Order(2)));
  ASSERT_TRUE(k.Compute(crossing, master, ConditionNormals<K44>(crossing), Order(2)));
  EXPECT_NEAR(k.area, reference.area, 1e-9 * reference.area);  // the iterates differ by 1e-12
  // Covered: x from the master's edge (-1.7e-5) to the slave's (0.05604), z from 0 to 0.125.
  EXPECT_NEAR(k.area, (0.05604 + 1.7e-5) * 0.125, 1e-3 * k.area);
  for (int j = 0; j < 4; ++j) {
    EXPECT_GT(k.nodal_area(j), 0.0) << j;
    EXPECT_NEAR(k.nodal_area(j), reference.nodal_area(j), 1e-9 * reference.area) << j;
  }
  EXPECT_NEAR(k.nodal_area.sum(), k.area, 1e-12 * k.area);
  // The master element beyond the shared edge overlaps by a sliver of 1e-13 at most: nothing.
  EXPECT_FALSE(above.Compute(crossing, master_above, ConditionNormals<K44>(crossing), Order(2)));
}

// A master edge on a slave edge (the line y = 0), the master corner (0.5, delta) on it by
// delta = +-1e-9: the overlap is the slave's part x <= 0.5 either way. The order-2 rule is not
// exact for ((xi + 0.3)(eta + 0.7))^2 (degree 4, as N1 N2 in M): Kratos' rule starts the fan at
// the master corner for +1e-9 and at slave node 0 for -1e-9, and the sum jumps by 1.4e-2 of its
// value (the friction block's Newton cycle at t = 1.125). With the step's history the fan follows
// the rule once, to slave node 0, and does not go back to the corner.
TEST(ExactMortarIntegration, FanHistoryDoesNotGoBackToAStartTheStepLeft) {
  const auto x1 = Rows<K44::SlaveMatrix>({0, 0, 0, 1, 0, 0, 1.2, 1, 0, 0, 0.8, 0});
  auto moment = [&](double delta, MortarFanHistory* history) {
    MortarIntegrationSettings settings = Order(2);
    settings.fan_history = history;
    MortarIntegrationPoints<double, 3, 4, 4> points;
    const auto x2 = Rows<K44::MasterMatrix>({-0.5, delta, 0.01, 0.5, delta, 0.01, 0.5, 2, 0.01, -0.5, 2, 0.01});
    EXPECT_TRUE((ExactMortarIntegrationUtility<3, 4, 4>::Compute(x1, x2, ConditionNormals<K44>(x1), settings, points)));
    double sum = 0.0;
    for (int g = 0; g < points.size; ++g) {
      const auto& xi = points.points[g].slave_local;
      sum += points.points[g].weight * std::pow((xi(0) + 0.3) * (xi(1) + 0.7), 2);
    }
    return sum;
  };
  const double above = moment(1e-9, nullptr), below = moment(-1e-9, nullptr);
  EXPECT_GT(std::abs(above - below), 1e-2 * std::abs(below));  // Kratos' rule
  MortarFanHistory history;
  EXPECT_DOUBLE_EQ(moment(1e-9, &history), above);
  EXPECT_EQ(history.current, (MortarFanStart{0, 1}));  // the master corner
  EXPECT_DOUBLE_EQ(moment(-1e-9, &history), below);    // the rule's new start
  EXPECT_EQ(history.current, (MortarFanStart{1, 0}));  // slave node 0
  for (int repeat = 0; repeat < 3; ++repeat) {
    EXPECT_NEAR(moment(1e-9, &history), below, 1e-8 * std::abs(below));  // not back to the corner
    EXPECT_NEAR(moment(-1e-9, &history), below, 1e-8 * std::abs(below));
  }
  EXPECT_EQ(history.left_count, 1);
}

TEST(ExactMortarIntegration, FoldedMasterFaceOfADivergedIterateIsASolutionError) {
  const auto x1 =
      Rows<K44::SlaveMatrix>({0.35786855178134835, -0.22733297504675262, -0.08438905766806408, 0.44918066344109708,
                              -0.23138547302904547, 0.057306946730948993, 0.35801866758089473, -0.29472682400676603,
                              0.18794168939019615, 0.30458745203534759, -0.34406695627128331, 0.034539875089470297});
  const auto x2 =
      Rows<K44::MasterMatrix>({0.22056610750475786, -0.35149835123712392, 0.42221754546887058, 0.6338917167536805,
                               -0.548426321814242, -0.488899243957234, 0.3832963397977398, -0.36836643982492345,
                               0.48717960457888315, 0.33410950341129081, -0.23161639191032182, -0.14522702204877991});
  MortarIntegrationPoints<double, 3, 4, 4> points;
  try {
    ExactMortarIntegrationUtility<3, 4, 4>::Compute(x1, x2, ConditionNormals<K44>(x1), Order(2), points);
    FAIL() << "no error";
  } catch (const SolutionError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("clipped polygon with 9 vertices (at most 8 for convex faces)"), std::string::npos)
        << message;
    EXPECT_NE(message.find("folded or self-intersecting"), std::string::npos) << message;
  }
}

TEST(ExactMortarIntegration, SettingsErrors) {
  K33 k;
  const auto x1 = Rows<K33::SlaveMatrix>({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const auto x2 = Rows<K33::MasterMatrix>({0, 0, 0.01, 1, 0, 0.01, 0, 1, 0.01});
  MortarIntegrationSettings s;
  s.consider_tessellation = true;
  EXPECT_THROW(k.Compute(x1, x2, ConditionNormals<K33>(x1), s), NotImplementedError);
  EXPECT_THROW(k.Compute(x1, x2, ConditionNormals<K33>(x1), Order(6)), InputError);
  EXPECT_THROW(k.Compute(x1, x2, ConditionNormals<K33>(x1), Order(0)), InputError);
}

}  // namespace
}  // namespace mc
