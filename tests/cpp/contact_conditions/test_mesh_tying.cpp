// SPDX-License-Identifier: BSD-3-Clause
// Issue 13 (mortar mesh tying): MeshTyingMortarCondition's LHS is the exact derivative of its RHS
// (central finite differences, every geometry case, components and scalar tying), the tie is linear
// (RHS = -LHS x) and uses the initial configuration, and on non-matching flat interfaces (2D lines,
// 3D quads on triangles) the assembled tie reproduces a linear field exactly and transmits a
// constant traction exactly: the slave and master nodal forces are the consistent ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include <Eigen/LU>

#include "contact_condition_test_utilities.h"
#include "custom_conditions/mesh_tying_mortar_condition.h"

namespace mc::test {
namespace {

const Variable<double>* const kU[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};

// Nodes with DISPLACEMENT, TEMPERATURE and both tying multipliers as DoFs.
Node& MakeTyingNode(ModelPart& root, IndexType id, const Array3& x) {
  Node& node = MakeNode(root, id, x);
  node.AddDof(TEMPERATURE, &NODAL_MASS);
  node.AddDof(SCALAR_LAGRANGE_MULTIPLIER, &WEIGHTED_SCALAR_RESIDUAL);
  return node;
}

ModelPart& MakeTyingModelPart(Model& model) {
  ModelPart& root = MakeContactModelPart(model);
  root.AddNodalSolutionStepVariable(TEMPERATURE);
  root.AddNodalSolutionStepVariable(NODAL_MASS);
  root.AddNodalSolutionStepVariable(SCALAR_LAGRANGE_MULTIPLIER);
  return root;
}

GeometryType FaceType(int dim, int nodes) {
  return dim == 2 ? GeometryType::Line2D2 : (nodes == 3 ? GeometryType::Triangle3D3 : GeometryType::Quadrilateral3D4);
}

template <int TDim, int TSlave, int TMaster>
struct PairFixture {
  using Pair = MeshTyingMortarCondition<TDim, TSlave, TMaster>;
  Model model;
  ModelPart& root = MakeTyingModelPart(model);
  std::unique_ptr<Pair> pair;

  explicit PairFixture(const std::string& variable) {
    // Overlapping, non-matching, slightly apart, with tilted nodal normals (M depends on them).
    std::vector<Array3> xs, xm;
    if (TDim == 2) {
      xs = {{0.0, 0.0, 0.0}, {1.0, 0.05, 0.0}};
      xm = {{1.2, 0.03, 0.0}, {0.3, -0.02, 0.0}};
    } else {
      xs = TSlave == 3 ? std::vector<Array3>{{0.0, 0.0, 0.0}, {1.0, 0.1, 0.02}, {0.2, 0.9, -0.01}}
                       : std::vector<Array3>{{0.0, 0.0, 0.0}, {1.0, 0.05, 0.02}, {1.1, 1.0, 0.0}, {0.05, 0.95, -0.01}};
      xm = TMaster == 3
               ? std::vector<Array3>{{0.1, 0.15, 0.02}, {0.3, 1.1, -0.01}, {1.2, 0.3, 0.01}}
               : std::vector<Array3>{{0.25, 0.2, 0.02}, {0.2, 1.2, -0.01}, {1.3, 1.1, 0.015}, {1.2, 0.1, -0.02}};
    }
    const Array3 tilt[4] = {{0.05, -0.03, 1.0}, {-0.04, 0.02, 1.0}, {0.03, 0.06, 1.0}, {-0.02, -0.05, 1.0}};
    Geometry::NodesArray slave, master;
    for (int i = 0; i < TSlave; ++i) {
      Node& node = MakeTyingNode(root, 1 + i, xs[i]);
      const Array3 n = TDim == 2 ? Array3(tilt[i][0], 1.0, 0.0) : tilt[i];
      NormalCalculationUtilities::SetNodalNormal(node, n.normalized());
      node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.3 * i - 0.2, 0.1 + 0.2 * i, -0.5);
      node.FastGetSolutionStepValue(SCALAR_LAGRANGE_MULTIPLIER) = 0.4 - 0.3 * i;
      slave.push_back(&node);
    }
    for (int l = 0; l < TMaster; ++l) master.push_back(&MakeTyingNode(root, 10 + l, xm[l]));
    int k = 0;
    for (Node* node : root.Nodes()) {
      ++k;
      node->FastGetSolutionStepValue(TEMPERATURE) = 0.1 * k - 0.3;
      for (int c = 0; c < TDim; ++c) SetDofValue(node->GetDof(*kU[c]), 0.01 * (k + c) * (c % 2 ? 1.0 : -1.0));
    }
    Properties& properties = root.GetOrCreateProperties(1);
    properties.SetValue(INTEGRATION_ORDER_CONTACT, 3);
    properties.SetValue(TYING_VARIABLE, variable);
    root.GetProcessInfo().SetValue(SCALE_FACTOR, 2.5);
    pair = std::make_unique<Pair>(1, Geometry(FaceType(TDim, TSlave), slave), &properties,
                                  Geometry(FaceType(TDim, TMaster), master));
  }

  void CheckTangent(int components) {
    const ProcessInfo& info = root.GetProcessInfo();
    pair->Check(info);
    ASSERT_EQ(pair->Components(), components);
    Matrix lhs;
    Vector rhs;
    pair->CalculateLocalSystem(lhs, rhs, info);
    ASSERT_EQ(lhs.rows(), (TMaster + 2 * TSlave) * components);
    ASSERT_GT(rhs.norm(), 0.0);
    ASSERT_GT(pair->D(info).diagonal().minCoeff(), 0.0);
    // Dual basis: D is diagonal.
    EXPECT_LT((pair->D(info) - Matrix(pair->D(info).diagonal().asDiagonal())).norm(), 1e-14);
    const Matrix fd = FiniteDifferenceTangent(*pair, 1e-6, info);
    EXPECT_LT((lhs - fd).cwiseAbs().maxCoeff(), 1e-9 * std::max(1.0, lhs.cwiseAbs().maxCoeff()));
    EXPECT_LT((lhs - lhs.transpose()).norm(), 1e-14);
    // Linear and homogeneous: RHS = -LHS x.
    DofsVectorType dofs;
    pair->GetDofList(dofs, info);
    Vector x(dofs.size());
    for (std::size_t i = 0; i < dofs.size(); ++i) x(static_cast<Eigen::Index>(i)) = dofs[i]->Value();
    EXPECT_LT((rhs + lhs * x).norm(), 1e-13 * std::max(1.0, rhs.norm()));
  }
};

template <class T>
class MeshTyingTangent : public ::testing::Test {};
struct Case222 {
  using F = PairFixture<2, 2, 2>;
};
struct Case333 {
  using F = PairFixture<3, 3, 3>;
};
struct Case344 {
  using F = PairFixture<3, 4, 4>;
};
struct Case334 {
  using F = PairFixture<3, 3, 4>;
};
struct Case343 {
  using F = PairFixture<3, 4, 3>;
};
using Cases = ::testing::Types<Case222, Case333, Case344, Case334, Case343>;
TYPED_TEST_SUITE(MeshTyingTangent, Cases);

TYPED_TEST(MeshTyingTangent, ComponentsTangentEqualsFiniteDifferences) {
  typename TypeParam::F f("DISPLACEMENT");
  f.CheckTangent(TypeParam::F::Pair::Kinematics::kDim);
  EXPECT_EQ(f.pair->Info().rfind("MeshTyingMortarCondition", 0), 0u);
}

TYPED_TEST(MeshTyingTangent, ScalarTangentEqualsFiniteDifferences) {
  typename TypeParam::F f("TEMPERATURE");
  f.CheckTangent(1);
}

TYPED_TEST(MeshTyingTangent, OperatorsAreThoseOfTheInitialConfiguration) {
  typename TypeParam::F f("DISPLACEMENT");
  const ProcessInfo& info = f.root.GetProcessInfo();
  Matrix before, after;
  Vector rhs;
  f.pair->CalculateLocalSystem(before, rhs, info);
  for (Node* node : f.root.Nodes()) {
    node->Coordinates() += Array3(0.3, -0.2, 0.1 * node->Id());
    NormalCalculationUtilities::SetNodalNormal(*node, Array3(1.0, 0.0, 0.0));
  }
  f.pair->CalculateLocalSystem(after, rhs, info);
  EXPECT_EQ((before - after).norm(), 0.0);
}

TEST(MeshTying, UnknownOrWrongTypeOfVariableIsAnInputError) {
  Model model;
  ModelPart& root = MakeTyingModelPart(model);
  Properties& properties = root.GetOrCreateProperties(1);
  properties.SetValue(TYING_VARIABLE, std::string("DISPLACMENT"));
  auto make = [&] {
    return MeshTyingMortarCondition<2, 2, 2>(1, Geometry(GeometryType::Line2D2, {}), &properties,
                                             Geometry(GeometryType::Line2D2, {}));
  };
  EXPECT_THROW(make(), InputError);
  properties.SetValue(TYING_VARIABLE, std::string("STEP"));
  EXPECT_THROW(make(), InputError);
}

// A whole non-matching flat interface: slave faces x master faces, every overlapping pair tied.
struct Interface {
  Model model;
  ModelPart& root = MakeTyingModelPart(model);
  std::vector<std::unique_ptr<Condition>> pairs;
  std::vector<Node*> slave_nodes, master_nodes;
  std::map<const Dof*, Eigen::Index> index;
  std::vector<const Dof*> dofs;

  Node& AddNode(std::vector<Node*>& side, IndexType id, const Array3& x, const Array3& normal) {
    Node& node = MakeTyingNode(root, id, x);
    NormalCalculationUtilities::SetNodalNormal(node, normal);
    side.push_back(&node);
    return node;
  }

  // Global system of the tie alone (rows of every DoF any pair lists).
  void Assemble(Matrix& lhs, Vector& rhs) {
    const ProcessInfo& info = root.GetProcessInfo();
    index.clear();
    dofs.clear();
    for (auto& pair : pairs) {
      DofsVectorType local;
      pair->GetDofList(local, info);
      for (Dof* dof : local)
        if (index.emplace(dof, static_cast<Eigen::Index>(dofs.size())).second) dofs.push_back(dof);
    }
    const auto n = static_cast<Eigen::Index>(dofs.size());
    lhs.setZero(n, n);
    rhs.setZero(n);
    for (auto& pair : pairs) {
      DofsVectorType local;
      pair->GetDofList(local, info);
      Matrix k;
      Vector r;
      pair->CalculateLocalSystem(k, r, info);
      for (std::size_t a = 0; a < local.size(); ++a) {
        rhs(index[local[a]]) += r(static_cast<Eigen::Index>(a));
        for (std::size_t b = 0; b < local.size(); ++b)
          lhs(index[local[a]], index[local[b]]) += k(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
      }
    }
  }
};

// 2D: slave y = 0 with nodes at x = 0, 0.4, 1.0; master y = 0 (coincident, facing) at x = 0, 0.25, 0.7, 1.0.
void Build2D(Interface& s) {
  const std::vector<double> xs = {0.0, 0.4, 1.0}, xm = {0.0, 0.25, 0.7, 1.0};
  for (std::size_t i = 0; i < xs.size(); ++i) s.AddNode(s.slave_nodes, 1 + i, {xs[i], 0.0, 0.0}, {0.0, 1.0, 0.0});
  for (std::size_t i = 0; i < xm.size(); ++i) s.AddNode(s.master_nodes, 10 + i, {xm[i], 0.0, 0.0}, {0.0, -1.0, 0.0});
  Properties& properties = s.root.GetOrCreateProperties(1);
  properties.SetValue(TYING_VARIABLE, std::string("DISPLACEMENT"));
  IndexType id = 1;
  // Slave lines run so that the normal (t_y, -t_x) is +y: from right to left; master lines left to right.
  for (std::size_t a = 0; a + 1 < xs.size(); ++a)
    for (std::size_t b = 0; b + 1 < xm.size(); ++b)
      s.pairs.push_back(std::make_unique<MeshTyingMortarCondition<2, 2, 2>>(
          id++, Geometry(GeometryType::Line2D2, {s.slave_nodes[a + 1], s.slave_nodes[a]}), &properties,
          Geometry(GeometryType::Line2D2, {s.master_nodes[b], s.master_nodes[b + 1]})));
}

// Bilinear Laplacian (conductivity 1) of the axis-aligned rectangle [x0, x1] x [y0, y1], nodes counter-
// clockwise from (x0, y0): 2 x 2 Gauss.
Matrix RectangleLaplacian(double a, double b) {
  Matrix k = Matrix::Zero(4, 4);
  const double xi[4] = {-1, 1, 1, -1}, eta[4] = {-1, -1, 1, 1}, g = 1.0 / std::sqrt(3.0);
  for (double p : {-g, g})
    for (double q : {-g, g})
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
          const double dxi = xi[i] * (1 + eta[i] * q) / 4 * 2 / a, dyi = eta[i] * (1 + xi[i] * p) / 4 * 2 / b;
          const double dxj = xi[j] * (1 + eta[j] * q) / 4 * 2 / a, dyj = eta[j] * (1 + xi[j] * p) / 4 * 2 / b;
          k(i, j) += (dxi * dxj + dyi * dyj) * a * b / 4;
        }
  return k;
}

// Issue 13 (ScalarMeshTying): a scalar field (TEMPERATURE) across a non-matching interface. Two blocks of
// the unit square cut at x = 0.5 (left 1 x 2 rectangles, right 1 x 3, own interface nodes), Laplacian,
// T = 1 at x = 0 and T = 0 at x = 1: the tied solution is T = 1 - x at every node (the Kratos test
// test_mesh_tying_condition.cpp has T = 0.5 on the interface) and k lambda the flux dT/dn = -1 on the
// slave side, to 1e-12.
TEST(MeshTyingScalar, LaplacianAcrossNonMatchingInterface) {
  Interface s;
  Properties& properties = s.root.GetOrCreateProperties(1);
  properties.SetValue(TYING_VARIABLE, std::string("TEMPERATURE"));
  s.root.GetProcessInfo().SetValue(SCALE_FACTOR, 4.0);
  // The interface nodes of each block go to the slave / master lists, the outer ones (x = 0 on the
  // left, x = 1 on the right, where T is given) to left / right.
  std::vector<Node*> left, right;
  IndexType id = 1;
  for (double x : {0.0, 0.5})
    for (double y : {0.0, 0.5, 1.0}) s.AddNode(x == 0.5 ? s.slave_nodes : left, id++, {x, y, 0.0}, {1.0, 0.0, 0.0});
  for (double x : {0.5, 1.0})
    for (double y : {0.0, 1.0 / 3, 2.0 / 3, 1.0})
      s.AddNode(x == 0.5 ? s.master_nodes : right, id++, {x, y, 0.0}, {-1.0, 0.0, 0.0});
  // Slave lines (left block's right edge) run downwards: normal (t_y, -t_x) = +x; master lines upwards.
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 3; ++b)
      s.pairs.push_back(std::make_unique<MeshTyingMortarCondition<2, 2, 2>>(
          id++, Geometry(GeometryType::Line2D2, {s.slave_nodes[a + 1], s.slave_nodes[a]}), &properties,
          Geometry(GeometryType::Line2D2, {s.master_nodes[b], s.master_nodes[b + 1]})));
  Matrix lhs;
  Vector rhs;
  s.Assemble(lhs, rhs);  // the tie's DoFs: the interface temperatures and the slave multipliers
  // Add the rectangles: left (node indices by (x, y) grid of 2 x 3), right (2 x 4).
  auto index_of = [&](Node* node) {
    const Dof* dof = &node->GetDof(TEMPERATURE);
    const auto [it, inserted] = s.index.emplace(dof, static_cast<Eigen::Index>(s.dofs.size()));
    if (inserted) s.dofs.push_back(dof);
    return it->second;
  };
  std::vector<std::pair<std::array<Node*, 4>, Matrix>> elements;
  const std::vector<Node*> all_left = {left[0], left[1], left[2], s.slave_nodes[0], s.slave_nodes[1], s.slave_nodes[2]};
  for (int j = 0; j < 2; ++j)
    elements.push_back(
        {{all_left[j], all_left[3 + j], all_left[4 + j], all_left[j + 1]}, RectangleLaplacian(0.5, 0.5)});
  const std::vector<Node*> all_right = {s.master_nodes[0], s.master_nodes[1], s.master_nodes[2], s.master_nodes[3],
                                        right[0],          right[1],          right[2],          right[3]};
  for (int j = 0; j < 3; ++j)
    elements.push_back(
        {{all_right[j], all_right[4 + j], all_right[5 + j], all_right[j + 1]}, RectangleLaplacian(0.5, 1.0 / 3)});
  for (auto& [nodes, k] : elements)
    for (Node* node : nodes) index_of(node);
  const auto n = static_cast<Eigen::Index>(s.dofs.size());
  Matrix a = Matrix::Zero(n, n);
  a.topLeftCorner(lhs.rows(), lhs.cols()) = lhs;
  for (auto& [nodes, k] : elements)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) a(index_of(nodes[i]), index_of(nodes[j])) += k(i, j);
  // Dirichlet: T = 1 at x = 0, T = 0 at x = 1; the system is linear: a x = b with b from them.
  Vector x = Vector::Zero(n);
  std::vector<bool> fixed(static_cast<std::size_t>(n), false);
  for (Node* node : left) {
    fixed[static_cast<std::size_t>(index_of(node))] = true;
    x(index_of(node)) = 1.0;
  }
  for (Node* node : right) fixed[static_cast<std::size_t>(index_of(node))] = true;
  std::vector<Eigen::Index> free;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!fixed[static_cast<std::size_t>(i)]) free.push_back(i);
  const auto m = static_cast<Eigen::Index>(free.size());
  Matrix a_ff(m, m);
  Vector b_f(m);
  const Vector b = -a * x;
  for (Eigen::Index i = 0; i < m; ++i) {
    b_f(i) = b(free[i]);
    for (Eigen::Index j = 0; j < m; ++j) a_ff(i, j) = a(free[i], free[j]);
  }
  const Vector x_f = a_ff.fullPivLu().solve(b_f);
  ASSERT_LT((a_ff * x_f - b_f).norm(), 1e-12);
  for (Eigen::Index i = 0; i < m; ++i) x(free[i]) = x_f(i);
  int multipliers = 0;
  for (const Dof* dof : s.dofs) {
    const double value = x(s.index.at(dof));
    if (dof->variable == &TEMPERATURE) {
      EXPECT_NEAR(value, 1.0 - dof->node->X0()[0], 1e-12) << "node " << dof->node->Id();
    } else {
      ASSERT_EQ(dof->variable, &SCALAR_LAGRANGE_MULTIPLIER);
      EXPECT_NEAR(4.0 * value, -1.0, 1e-12) << "node " << dof->node->Id();
      ++multipliers;
    }
  }
  EXPECT_EQ(multipliers, 3);
}

// 3D: slave = two quads on [0,1] x [0,1] (split at x = 0.6) at z = 0; master = four triangles of
// the square split at (0.3, 0.45) at z = 0, facing.
void Build3D(Interface& s) {
  const Array3 up(0.0, 0.0, 1.0), down(0.0, 0.0, -1.0);
  const std::vector<Array3> xs = {{0, 0, 0}, {0.6, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.6, 1, 0}, {1, 1, 0}};
  for (std::size_t i = 0; i < xs.size(); ++i) s.AddNode(s.slave_nodes, 1 + i, xs[i], up);
  const std::vector<Array3> xm = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.3, 0.45, 0}};
  for (std::size_t i = 0; i < xm.size(); ++i) s.AddNode(s.master_nodes, 10 + i, xm[i], down);
  Properties& properties = s.root.GetOrCreateProperties(1);
  properties.SetValue(TYING_VARIABLE, std::string("DISPLACEMENT"));
  auto& sn = s.slave_nodes;
  auto& mn = s.master_nodes;
  const std::vector<Geometry::NodesArray> slave = {{sn[0], sn[1], sn[4], sn[3]}, {sn[1], sn[2], sn[5], sn[4]}};
  // Clockwise seen from +z, so that their normals point down.
  const std::vector<Geometry::NodesArray> master = {
      {mn[0], mn[4], mn[1]}, {mn[1], mn[4], mn[2]}, {mn[2], mn[4], mn[3]}, {mn[3], mn[4], mn[0]}};
  IndexType id = 1;
  for (const auto& a : slave)
    for (const auto& b : master)
      s.pairs.push_back(std::make_unique<MeshTyingMortarCondition<3, 4, 3>>(
          id++, Geometry(GeometryType::Quadrilateral3D4, a), &properties, Geometry(GeometryType::Triangle3D3, b)));
}

// Slave values from the tie with the master values given: the tie rows solved for the slave DoFs.
void CheckLinearFieldIsReproduced(Interface& s, int dim) {
  auto field = [](const Array3& x, int c) { return 0.3 + 1.7 * x[0] - 0.8 * x[1] + 0.1 * c * x[0]; };
  for (Node* node : s.master_nodes)
    for (int c = 0; c < dim; ++c) SetDofValue(node->GetDof(*kU[c]), field(node->X0(), c));
  Matrix lhs;
  Vector rhs;
  s.Assemble(lhs, rhs);
  // Unknowns: the slave DoFs of the tied variable; equations: the multiplier rows.
  std::vector<Eigen::Index> unknowns, rows;
  for (const Dof* dof : s.dofs) {
    const bool multiplier = dof->variable->Source() == &VECTOR_LAGRANGE_MULTIPLIER;
    const bool slave = std::find(s.slave_nodes.begin(), s.slave_nodes.end(), dof->node) != s.slave_nodes.end();
    if (multiplier)
      rows.push_back(s.index[dof]);
    else if (slave)
      unknowns.push_back(s.index[dof]);
  }
  ASSERT_EQ(rows.size(), unknowns.size());
  ASSERT_EQ(rows.size(), s.slave_nodes.size() * static_cast<std::size_t>(dim));
  // rhs rows = k (D u_s - M u_m) with u_s = 0: solve -K_rs u_s = rhs_r.
  const auto n = static_cast<Eigen::Index>(rows.size());
  Matrix a(n, n);
  Vector b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    b(i) = rhs(rows[i]);
    for (Eigen::Index j = 0; j < n; ++j) a(i, j) = lhs(rows[i], unknowns[j]);
  }
  const Vector us = a.fullPivLu().solve(b);
  for (Eigen::Index j = 0; j < n; ++j) {
    const Dof* dof = s.dofs[static_cast<std::size_t>(unknowns[j])];
    const int c = dof->variable->ComponentIndex();
    EXPECT_NEAR(us(j), field(dof->node->X0(), c), 1e-13) << "node " << dof->node->Id() << " component " << c;
  }
}

// Constant multiplier lambda (traction k lambda): slave forces k D^T lambda and master forces
// -k M^T lambda are the consistent nodal forces of the traction on each side, int N_j k lambda.
void CheckConstantTractionIsTransmitted(Interface& s, const std::map<IndexType, double>& slave_areas,
                                        const std::map<IndexType, double>& master_areas) {
  const Array3 traction_multiplier(0.4, -1.3, 0.7);
  const double k = 2.5;
  s.root.GetProcessInfo().SetValue(SCALE_FACTOR, k);
  for (Node* node : s.root.Nodes()) {
    node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = traction_multiplier;
    node->FastGetSolutionStepValue(DISPLACEMENT) = Array3::Zero();
  }
  Matrix lhs;
  Vector rhs;
  s.Assemble(lhs, rhs);
  for (const Dof* dof : s.dofs) {
    if (dof->variable->Source() != &DISPLACEMENT) continue;
    const int c = dof->variable->ComponentIndex();
    const bool slave = std::find(s.slave_nodes.begin(), s.slave_nodes.end(), dof->node) != s.slave_nodes.end();
    const double area = (slave ? slave_areas : master_areas).at(dof->node->Id());
    const double expected = (slave ? 1.0 : -1.0) * k * traction_multiplier[c] * area;
    EXPECT_NEAR(rhs(s.index.at(dof)), expected, 1e-12) << "node " << dof->node->Id() << " component " << c;
  }
}

TEST(MeshTyingInterface, LinearField2D) {
  Interface s;
  Build2D(s);
  CheckLinearFieldIsReproduced(s, 2);
}

TEST(MeshTyingInterface, ConstantTraction2D) {
  Interface s;
  Build2D(s);
  // int N_j over each side: half of the adjacent segment lengths.
  CheckConstantTractionIsTransmitted(s, {{1, 0.2}, {2, 0.5}, {3, 0.3}},
                                     {{10, 0.125}, {11, 0.35}, {12, 0.375}, {13, 0.15}});
}

TEST(MeshTyingInterface, LinearField3DQuadsOnTriangles) {
  Interface s;
  Build3D(s);
  CheckLinearFieldIsReproduced(s, 3);
}

TEST(MeshTyingInterface, ConstantTraction3DQuadsOnTriangles) {
  Interface s;
  Build3D(s);
  // Slave: bilinear quads 0.6 x 1 and 0.4 x 1: a quarter of each adjacent quad's area.
  const std::map<IndexType, double> slave = {{1, 0.15}, {2, 0.25}, {3, 0.1}, {4, 0.15}, {5, 0.25}, {6, 0.1}};
  // Master: a third of each adjacent triangle's area; the triangles have areas 0.225 (bottom, top:
  // base 1, heights 0.45 and 0.55 -> 0.225, 0.275) and 0.35, 0.15 (right, left: heights 0.7, 0.3).
  const double bottom = 0.5 * 0.45, right = 0.5 * 0.7, top = 0.5 * 0.55, left = 0.5 * 0.3;
  const std::map<IndexType, double> master = {{10, (bottom + left) / 3},
                                              {11, (bottom + right) / 3},
                                              {12, (right + top) / 3},
                                              {13, (top + left) / 3},
                                              {14, (bottom + right + top + left) / 3}};
  CheckConstantTractionIsTransmitted(s, slave, master);
}

}  // namespace
}  // namespace mc::test
