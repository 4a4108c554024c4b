// SPDX-License-Identifier: BSD-3-Clause
// Issue 3: dual Lagrange multipliers and mortar operators D, M, weighted gap and nodal area:
// biorthogonality, sum(D) = sum(M) = area on non-matching flat interfaces, linear patch test
// (D^-1 M reproduces linear master fields), rigid-motion invariance, weighted-gap sign, and
// the mortar mapping cases MAP-P1/MAP-P2 of cases/mortar_integration_reference.md section 7.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "contact_utilities_test_helpers.h"
#include "core/geometries/geometry_type.h"
#include "core/geometries/reference_element.h"
#include "custom_utilities/dual_lagrange_multiplier.h"

namespace mc {
namespace {

using mortar_test::ConditionNormals;
using mortar_test::Order;
using mortar_test::Rows;

// ---------------------------------------------------------------------------------------
// Dual basis of a pair

// A master covering the whole slave element gives the element's classic dual basis.
TEST(DualLagrangeMultiplier, FullOverlapGivesTheElementBasis) {
  using KL = MortarPairKinematics<2, 2, 2>;
  const auto line = Rows<KL::SlaveMatrix>({0.3, 0.1, 2.0, 0.7});
  KL kl;
  ASSERT_TRUE(kl.Compute(line, Rows<KL::MasterMatrix>({2.5, 0.9, -0.2, 0.0}), ConditionNormals<KL>(line), Order(2)));
  Eigen::Matrix2d expected_line;
  expected_line << 2, -1, -1, 2;
  EXPECT_LT((kl.Ae - expected_line).norm(), 1e-12);

  using KT = MortarPairKinematics<3, 3, 3>;
  const auto tri = Rows<KT::SlaveMatrix>({-0.2, 0.1, 0.3, 1.0, 0.1, -0.2, 0.2, 1.2, 0.5});
  KT::MasterMatrix big;  // the slave triangle scaled by 3 about its centroid, 0.01 off its plane
  const Eigen::RowVector3d centre = tri.colwise().mean();
  const Eigen::RowVector3d offset = 0.01 * ConditionNormals<KT>(tri).row(0);
  for (int l = 0; l < 3; ++l) big.row(2 - l) = centre + 3.0 * (tri.row(l) - centre) + offset;
  KT kt;
  ASSERT_TRUE(kt.Compute(tri, big, ConditionNormals<KT>(tri), Order(2)));
  Eigen::Matrix3d expected_tri;
  expected_tri << 3, -1, -1, -1, 3, -1, -1, -1, 3;
  EXPECT_LT((kt.Ae - expected_tri).norm(), 1e-11);

  // Unit square, integrated exactly (order 5): the tensor product of the line's basis.
  using KQ = MortarPairKinematics<3, 4, 4>;
  const auto square = Rows<KQ::SlaveMatrix>({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  const auto cover = Rows<KQ::MasterMatrix>({-0.5, -0.5, 0.1, -0.5, 1.5, 0.1, 1.5, 1.5, 0.1, 1.5, -0.5, 0.1});
  KQ kq;
  ASSERT_TRUE(kq.Compute(square, cover, ConditionNormals<KQ>(square), Order(5)));
  Eigen::Matrix4d expected_square;
  expected_square << 4, -2, 1, -2, -2, 4, -2, 1, 1, -2, 4, -2, -2, 1, -2, 4;
  EXPECT_LT((kq.Ae - expected_square).norm(), 1e-11);
}

// Issue 10: a slave element covered only in part (the end of the master surface). The pair's
// dual functions are biorthogonal on the covered part, so a gap that is linear along the element
// is weighted exactly: weighted gap_j = (int_overlap N_j) g_j, of the sign of the nodal gap g_j,
// also at the node the master does not reach. An element-wise dual basis gave that node a
// negative weighted gap however open the gap (Phi_j < 0 near the far node), and the active set
// pulled it into contact.
TEST(DualLagrangeMultiplier, PartlyCoveredElementWeightsALinearGapExactly) {
  using K = MortarPairKinematics<2, 2, 2>;
  // Slave from x = 0 to 1 rising as y = 0.2 x (normal pointing down, towards the master), flat
  // master y = -0.01 over x in [0.7, 2]: node 1 (x = 0) is outside the master's end.
  const auto x1 = Rows<K::SlaveMatrix>({1.0, 0.2, 0.0, 0.0});
  const auto x2 = Rows<K::MasterMatrix>({0.7, -0.01, 2.0, -0.01});
  K::SlaveMatrix down;
  down << 0.0, -1.0, 0.0, -1.0;
  K k;
  ASSERT_TRUE(k.Compute(x1, x2, down, Order(2)));
  const double nodal_gap[2] = {0.21, 0.01};  // vertical distance from each slave node to y = -0.01
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(k.weighted_gap(j), k.nodal_area(j) * nodal_gap[j], 1e-15) << "node " << j;
    EXPECT_GT(k.weighted_gap(j), 0.0) << "node " << j;
    EXPECT_NEAR(k.D(j, j), k.nodal_area(j), 1e-15);
  }
  EXPECT_NEAR(k.D(0, 1), 0.0, 1e-15);
}

// An overlap too thin to tell the shape functions apart (a sliver) cannot carry its own dual
// basis and takes the standard one, which keeps constant pressures exact; its nodal areas are
// negligible (hertz2d cut at 3a: a sliver of 7e-10 of a slave element gave its outer node
// D_jj = 5e-21; the contact updater flags such nodes ISOLATED). Like the pair basis, it weighs
// the gap with the shape functions of the nodes it lies at: the far node, whose shape function
// vanishes on the sliver, gets no share of the master's gap there (the element basis gave it
// -area x gap).
TEST(DualLagrangeMultiplier, SliverOverlapTakesTheStandardBasis) {
  using K = MortarPairKinematics<2, 2, 2>;
  const auto x1 = Rows<K::SlaveMatrix>({1.0, 0.0, 0.0, 0.0});
  K::SlaveMatrix down;
  down << 0.0, -1.0, 0.0, -1.0;
  K k;
  const double gap = 0.3;
  ASSERT_TRUE(k.Compute(x1, Rows<K::MasterMatrix>({1.0 - 1e-9, -gap, 3.0, -gap}), down, Order(2)));
  EXPECT_TRUE(k.sliver);
  EXPECT_LT((k.Ae - Eigen::Matrix2d::Identity()).norm(), 1e-15);
  EXPECT_NEAR(k.area, 1e-9, 1e-16);
  EXPECT_LT(k.nodal_area(1), 1e-17);
  EXPECT_NEAR(k.D.sum(), k.area, 1e-22);
  EXPECT_LT(std::abs(k.weighted_gap(1)), 1e-6 * gap * k.area);
  EXPECT_NEAR(k.weighted_gap(0), gap * k.area, 1e-6 * gap * k.area);
  // With the standard basis D = M couples the two nodes (why MixedULM solves such a system in full).
  EXPECT_GT(std::abs(k.D(0, 1)), 0.0);
  EXPECT_NEAR(k.D(0, 1), k.D(1, 0), 1e-30);
  // A thin but regular overlap keeps its own basis.
  ASSERT_TRUE(k.Compute(x1, Rows<K::MasterMatrix>({1.0 - 1e-3, -gap, 3.0, -gap}), down, Order(2)));
  EXPECT_FALSE(k.sliver);
  EXPECT_GT((k.Ae - Eigen::Matrix2d::Identity()).norm(), 1.0);
  EXPECT_NEAR(k.D(0, 1), 0.0, 1e-18);
}

// ---------------------------------------------------------------------------------------
// Interface assembly helpers

struct Mesh {
  std::vector<Eigen::Vector3d> nodes;
  std::vector<std::vector<int>> elements;
};

struct Assembled {
  Eigen::MatrixXd D, M;
  Eigen::VectorXd gap, area;
};

// Sums the pair contributions of every (slave, master) element pair; flat interfaces, nodal
// normals = condition normal.
template <int TDim, int N1, int N2>
void AddPairs(const Mesh& slave, const Mesh& master, Assembled& a,
              const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  using K = MortarPairKinematics<TDim, N1, N2>;
  K k;
  for (const auto& se : slave.elements) {
    if (static_cast<int>(se.size()) != N1) continue;
    for (const auto& me : master.elements) {
      if (static_cast<int>(me.size()) != N2) continue;
      typename K::SlaveMatrix x1;
      typename K::MasterMatrix x2;
      for (int i = 0; i < N1; ++i) x1.row(i) = (rotation * slave.nodes[se[i]]).head(TDim).transpose();
      for (int l = 0; l < N2; ++l) x2.row(l) = (rotation * master.nodes[me[l]]).head(TDim).transpose();
      if (!k.Compute(x1, x2, ConditionNormals<K>(x1), Order(2))) continue;
      for (int i = 0; i < N1; ++i) {
        for (int j = 0; j < N1; ++j) a.D(se[i], se[j]) += k.D(i, j);
        for (int l = 0; l < N2; ++l) a.M(se[i], me[l]) += k.M(i, l);
        a.gap(se[i]) += k.weighted_gap(i);
        a.area(se[i]) += k.nodal_area(i);
      }
    }
  }
}

Assembled Init(const Mesh& slave, const Mesh& master) {
  const int ns = static_cast<int>(slave.nodes.size()), nm = static_cast<int>(master.nodes.size());
  return {Eigen::MatrixXd::Zero(ns, ns), Eigen::MatrixXd::Zero(ns, nm), Eigen::VectorXd::Zero(ns),
          Eigen::VectorXd::Zero(ns)};
}

// Structured grid on [x0,x1]x[y0,y1] at height z, perturbed interior nodes, quads or triangles;
// `reverse` lists nodes clockwise (normal -z).
Mesh Grid(int nx, int ny, double x0, double x1, double y0, double y1, double z, bool triangles, bool reverse,
          double perturb) {
  Mesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      double x = x0 + (x1 - x0) * i / nx, y = y0 + (y1 - y0) * j / ny;
      if (i > 0 && i < nx && j > 0 && j < ny) {
        x += perturb * std::sin(3.1 * i + 1.7 * j) * (x1 - x0) / nx;
        y += perturb * std::cos(2.3 * i + 0.9 * j) * (y1 - y0) / ny;
      }
      m.nodes.emplace_back(x, y, z);
    }
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      std::vector<std::vector<int>> cells;
      if (triangles && (i + j) % 2 == 0) {
        cells = {{id(i, j), id(i + 1, j), id(i + 1, j + 1)}, {id(i, j), id(i + 1, j + 1), id(i, j + 1)}};
      } else if (triangles) {
        cells = {{id(i, j), id(i + 1, j), id(i, j + 1)}, {id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}};
      } else {
        cells = {{id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}};
      }
      for (auto& c : cells) {
        if (reverse) std::reverse(c.begin(), c.end());
        m.elements.push_back(c);
      }
    }
  return m;
}

Mesh Line(const std::vector<double>& xs, double y, bool reverse) {
  Mesh m;
  for (double x : xs) m.nodes.emplace_back(x, y, 0.0);
  for (size_t i = 0; i + 1 < xs.size(); ++i) {
    std::vector<int> e = {static_cast<int>(i), static_cast<int>(i + 1)};
    if (reverse) std::swap(e[0], e[1]);
    m.elements.push_back(e);
  }
  return m;
}

// The slave mesh area (flat, z-plane) from its elements.
double PlanarArea(const Mesh& m) {
  double area = 0.0;
  for (const auto& e : m.elements) {
    double a = 0.0;
    for (size_t k = 0; k < e.size(); ++k) {
      const auto& p = m.nodes[e[k]];
      const auto& q = m.nodes[e[(k + 1) % e.size()]];
      a += p.x() * q.y() - q.x() * p.y();
    }
    area += 0.5 * std::abs(a);
  }
  return area;
}

// Checks sum(D) = sum(M) = area, D diagonal, the linear patch test, the weighted gap and
// nodal area on a fully covered flat slave at distance `gap` along its normal.
// Every pair's dual basis is biorthogonal in the pair's own quadrature, so D is diagonal to
// round-off on any mesh.
void CheckInterface(const Assembled& a, const Mesh& slave, const Mesh& master, double area,
                    const Eigen::Vector3d& normal, double gap) {
  constexpr double biorthogonal_tol = 1e-12;
  EXPECT_NEAR(a.D.sum(), area, 1e-12 * area);
  EXPECT_NEAR(a.M.sum(), area, 1e-12 * area);
  EXPECT_NEAR(a.area.sum(), area, 1e-12 * area);
  const Eigen::MatrixXd off = a.D - Eigen::MatrixXd(a.D.diagonal().asDiagonal());
  EXPECT_LT(off.cwiseAbs().maxCoeff(), biorthogonal_tol * area);
  // Linear master field f = 0.3 + 1.1 x - 0.7 y + 0.4 z; the slave gets f(x_j + gap n).
  auto f = [](const Eigen::Vector3d& p) { return 0.3 + 1.1 * p.x() - 0.7 * p.y() + 0.4 * p.z(); };
  Eigen::VectorXd f2(master.nodes.size());
  for (size_t l = 0; l < master.nodes.size(); ++l) f2(l) = f(master.nodes[l]);
  const Eigen::VectorXd mapped = a.D.fullPivLu().solve(a.M * f2);
  for (size_t j = 0; j < slave.nodes.size(); ++j) {
    EXPECT_NEAR(mapped(j), f(slave.nodes[j] + gap * normal), 1e-11) << "slave node " << j;
    EXPECT_NEAR(a.gap(j) / a.D.row(j).sum(), gap, 1e-12) << "slave node " << j;
    EXPECT_NEAR(a.gap(j) / a.area(j), gap, gap * biorthogonal_tol) << "slave node " << j;
  }
}

TEST(MortarOperator, NonMatchingLines2D) {
  // Slave listed right to left: normal (t_y, -t_x) = +y, master 0.01 above: open gap.
  const Mesh slave = Line({0.0, 0.3, 0.55, 1.0}, 0.0, true);
  const Mesh master = Line({-0.1, 0.2, 0.45, 0.6, 0.93, 1.2}, 0.01, false);
  Assembled a = Init(slave, master);
  AddPairs<2, 2, 2>(slave, master, a);
  CheckInterface(a, slave, master, 1.0, Eigen::Vector3d(0, 1, 0), 0.01);
}

TEST(MortarOperator, NonMatchingSurfaces3D) {
  struct Case {
    bool slave_triangles, master_triangles;
  };
  for (const Case c : {Case{false, false}, Case{true, true}, Case{false, true}, Case{true, false}}) {
    // Slave normal +z (counter-clockwise), master 0.02 above, clockwise (its own normal -z).
    const Mesh slave = Grid(3, 2, 0.0, 1.0, 0.0, 0.8, 0.0, c.slave_triangles, false, 0.2);
    const Mesh master = Grid(4, 5, -0.1, 1.15, -0.05, 0.9, 0.02, c.master_triangles, true, 0.25);
    Assembled a = Init(slave, master);
    AddPairs<3, 3, 3>(slave, master, a);
    AddPairs<3, 3, 4>(slave, master, a);
    AddPairs<3, 4, 3>(slave, master, a);
    AddPairs<3, 4, 4>(slave, master, a);
    SCOPED_TRACE(::testing::Message() << "slave tri " << c.slave_triangles << " master tri " << c.master_triangles);
    // Quadrilateral slaves under triangular masters have overlaps of one sub-triangle, which are
    // integrated at the dual-basis order (3 points cannot carry 4 dual functions).
    CheckInterface(a, slave, master, PlanarArea(slave), Eigen::Vector3d(0, 0, 1), 0.02);
  }
}

TEST(MortarOperator, PartialOverlapGivesDiagonalDPerPair) {
  using K = MortarPairKinematics<3, 4, 3>;
  const auto x1 = Rows<K::SlaveMatrix>({0, 0, 0, 1, 0.1, 0, 1.1, 0.9, 0, -0.1, 1, 0});
  const auto x2 = Rows<K::MasterMatrix>({0.3, 0.2, 0.05, 1.4, 0.5, 0.05, 0.2, 1.3, 0.05});
  K k;
  ASSERT_TRUE(k.Compute(x1, x2, ConditionNormals<K>(x1), Order(2)));
  const K::DMatrix off = k.D - K::DMatrix(k.D.diagonal().asDiagonal());
  EXPECT_LT(off.cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(k.D.sum(), k.area, 1e-14);
  EXPECT_NEAR(k.M.sum(), k.area, 1e-14);
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(k.D(j, j), k.nodal_area(j), 1e-14);
}

TEST(MortarOperator, WeightedGapSignAndRigidMotionInvariance) {
  using K = MortarPairKinematics<3, 4, 3>;
  // Warped slave quad, tilted master triangle, partial overlap.
  const auto x1 = Rows<K::SlaveMatrix>({0, 0, 0, 1, 0.1, 0.02, 1.1, 0.9, -0.01, -0.1, 1, 0.03});
  const auto x2 = Rows<K::MasterMatrix>({0.3, 0.2, 0.05, 1.4, 0.5, 0.09, 0.2, 1.3, 0.02});
  K::SlaveMatrix n1 = ConditionNormals<K>(x1);
  // A non-flat interface: one nodal normal tilted away from the condition normal.
  n1.row(0) = (n1.row(0) + Eigen::RowVector3d(0.05, -0.02, 0)).normalized();
  K k;
  ASSERT_TRUE(k.Compute(x1, x2, n1, Order(3)));
  // Master above the slave (+z normal). Each node of the partly covered element weighs the gap
  // of the master's plane extended to it: open at nodes 0-2, while the plane passes 0.016 below
  // node 3 (an element dual basis gives signs that follow no gap at all).
  for (int j = 0; j < 3; ++j) EXPECT_GT(k.weighted_gap(j), 0.0) << "node " << j;
  EXPECT_LT(k.weighted_gap(3), 0.0);

  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -0.5).normalized())).toRotationMatrix();
  const Eigen::RowVector3d t(3.0, -1.5, 2.2);
  K r;
  ASSERT_TRUE(
      r.Compute((x1 * R.transpose()).rowwise() + t, (x2 * R.transpose()).rowwise() + t, n1 * R.transpose(), Order(3)));
  EXPECT_LT((r.D - k.D).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((r.M - k.M).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((r.weighted_gap - k.weighted_gap).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((r.nodal_area - k.nodal_area).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(r.area, k.area, 1e-12);

  // Penetration: master moved below the slave gives negative weighted gaps.
  K p;
  ASSERT_TRUE(p.Compute(x1, (x2.rowwise() - Eigen::RowVector3d(0, 0, 0.2)).eval(), n1, Order(3)));
  for (int j = 0; j < 4; ++j) EXPECT_LT(p.weighted_gap(j), 0.0) << "node " << j;
}

TEST(MortarOperator, RigidMotionInvariance2D) {
  using K = MortarPairKinematics<2, 2, 2>;
  const auto x1 = Rows<K::SlaveMatrix>({1.0, 0.05, 0.0, -0.02});
  const auto x2 = Rows<K::MasterMatrix>({0.4, 0.1, 1.6, 0.2});
  K k, r;
  ASSERT_TRUE(k.Compute(x1, x2, ConditionNormals<K>(x1), Order(2)));
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(2.1).toRotationMatrix();
  const Eigen::RowVector2d t(-4.0, 7.5);
  const K::SlaveMatrix y1 = (x1 * R.transpose()).rowwise() + t;
  ASSERT_TRUE(r.Compute(y1, (x2 * R.transpose()).rowwise() + t, ConditionNormals<K>(y1), Order(2)));
  EXPECT_LT((r.D - k.D).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((r.M - k.M).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((r.weighted_gap - k.weighted_gap).cwiseAbs().maxCoeff(), 1e-12);
}

// MAP-P1 / MAP-P2: one slave element mapped from the parallel master 0.1 above in z.
template <int N>
Eigen::Matrix<double, N, 4> MapPair(const Eigen::Matrix<double, N, 3>& x1, const Eigen::Matrix<double, N, 3>& x2) {
  using K = MortarPairKinematics<3, N, N>;
  K k;
  EXPECT_TRUE(k.Compute(x1, x2, ConditionNormals<K>(x1), Order(2)));
  Eigen::Matrix<double, N, 4> master_fields;  // T = z, DISPLACEMENT = (x, y, z)
  for (int l = 0; l < N; ++l) master_fields.row(l) << x2(l, 2), x2(l, 0), x2(l, 1), x2(l, 2);
  return k.D.fullPivLu().solve(k.M * master_fields);
}

TEST(MortarOperator, MortarMapping_MAP_P1_Triangle) {
  const auto x1 = Rows<Eigen::Matrix3d>({0, 1, 0.1, 1, 0, 0, 0, 0, 0});  // [3,2,1]
  const auto x2 = Rows<Eigen::Matrix3d>({0, 0, 0.1, 1, 0, 0.1, 0, 1, 0.2});
  const auto mapped = MapPair<3>(x1, x2);
  // Rows = slave nodes 3, 2, 1; columns T, DISP_X, DISP_Y, DISP_Z.
  const double expected[3][4] = {{0.19900990099009902, 0.0, 0.9900990099009901, 0.19900990099009902},
                                 {0.09900990099009903, 1.0, -0.009900990099009833, 0.09900990099009903},
                                 {0.09900990099009897, 0.0, -0.009900990099009983, 0.09900990099009897}};
  for (int j = 0; j < 3; ++j)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(mapped(j, c), expected[j][c], 1e-12) << j << "," << c;
}

TEST(MortarOperator, MortarMapping_MAP_P2_Quadrilateral) {
  const auto x1 = Rows<Eigen::Matrix<double, 4, 3>>({0, 1, 0.1, 1, 1, 0.1, 1, 0, 0, 0, 0, 0});  // [4,3,2,1]
  const auto x2 = Rows<Eigen::Matrix<double, 4, 3>>({0, 0, 0.1, 1, 0, 0.1, 1, 1, 0.2, 0, 1, 0.2});
  const auto mapped = MapPair<4>(x1, x2);
  const double expected[4][4] = {{0.19900990099009902, 0.0, 0.9900990099009899, 0.19900990099009902},
                                 {0.19900990099009894, 1.0, 0.9900990099009899, 0.19900990099009894},
                                 {0.099009900990099, 1.0, -0.009900990099009972, 0.099009900990099},
                                 {0.09900990099009901, 0.0, -0.0099009900990098, 0.09900990099009901}};
  for (int j = 0; j < 4; ++j)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(mapped(j, c), expected[j][c], 1e-12) << j << "," << c;
}

}  // namespace
}  // namespace mc
