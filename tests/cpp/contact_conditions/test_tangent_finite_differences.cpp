// SPDX-License-Identifier: BSD-3-Clause
// Issues 3 and 12 (mortar contact conditions): the generated LHS of every condition (ALM scalar,
// ALM components, penalty; ALM and penalty Coulomb frictional) x geometry (2D2N, 3D3N, 3D4N,
// 3D3N4N, 3D4N3N; the frictional 2D2N also axisymmetric) x state pattern (all active, all inactive, mixed; frictional
// also all slip and stick / slip) equals central finite differences of its RHS with respect to every DoF (displacements
// perturbed with the coordinates, multipliers). The frictional pairs store their previous mortar operators with the
// master offset, so that the weighted slip is not zero.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <type_traits>

#include "contact_condition_test_utilities.h"
#include "custom_conditions/alm_frictional_mortar_contact_condition.h"
#include "custom_conditions/alm_frictionless_components_mortar_contact_condition.h"
#include "custom_conditions/alm_frictionless_mortar_contact_condition.h"
#include "custom_conditions/axisymmetric_mortar_contact_condition.h"
#include "custom_conditions/penalty_frictional_mortar_contact_condition.h"
#include "custom_conditions/penalty_frictionless_mortar_contact_condition.h"

namespace mc::test {
namespace {

// ACTIVE / SLIP per slave node i (frictionless conditions read ACTIVE only): all active and stick,
// all inactive, mixed (active for even i, slip for i % 4 == 0), all slip, stick / slip (all active,
// slip for even i).
enum class Pattern { kAllActive, kAllInactive, kMixed, kAllSlip, kStickSlip };

template <class TCondition>
constexpr bool kFrictional = std::is_base_of_v<
    FrictionalMortarContactCondition<TCondition::Kinematics::kDim, TCondition::Kinematics::kNumSlaveNodes,
                                     TCondition::Kinematics::kNumMasterNodes>,
    TCondition>;

// Non-matching, slightly penetrating pairs with tilted nodal normals (so that M depends on them).
struct PairGeometry {
  std::vector<Array3> slave, master, normals;
};

PairGeometry Geometry2D() {
  return {{{0.0, 0.0, 0.0}, {1.0, 0.05, 0.0}},
          {{1.2, 0.03, 0.0}, {0.3, -0.02, 0.0}},
          {{-0.05, 1.0, 0.0}, {0.08, 1.0, 0.0}}};
}

PairGeometry Geometry3D(int slave_nodes, int master_nodes) {
  PairGeometry g;
  if (slave_nodes == 3)
    g.slave = {{0.0, 0.0, 0.0}, {1.0, 0.1, 0.02}, {0.2, 0.9, -0.01}};
  else
    g.slave = {{0.0, 0.0, 0.0}, {1.0, 0.05, 0.02}, {1.1, 1.0, 0.0}, {0.05, 0.95, -0.01}};
  // Master listed clockwise seen from the slave (as a facing surface), rotated and shifted.
  if (master_nodes == 3)
    g.master = {{0.1, 0.15, 0.02}, {0.3, 1.1, -0.01}, {1.2, 0.3, 0.01}};
  else
    g.master = {{0.25, 0.2, 0.02}, {0.2, 1.2, -0.01}, {1.3, 1.1, 0.015}, {1.2, 0.1, -0.02}};
  const Array3 tilts[4] = {{0.05, -0.03, 1.0}, {-0.04, 0.02, 1.0}, {0.03, 0.06, 1.0}, {-0.02, -0.05, 1.0}};
  for (int i = 0; i < slave_nodes; ++i) g.normals.push_back(tilts[i]);
  return g;
}

template <class TCondition>
struct Fixture {
  static constexpr int kDim = TCondition::Kinematics::kDim;
  static constexpr int kSlave = TCondition::Kinematics::kNumSlaveNodes;
  static constexpr int kMaster = TCondition::Kinematics::kNumMasterNodes;

  Model model;
  ModelPart& root = MakeContactModelPart(model);
  std::unique_ptr<TCondition> pair;

  explicit Fixture(Pattern pattern) {
    const PairGeometry g = kDim == 2 ? Geometry2D() : Geometry3D(kSlave, kMaster);
    Geometry::NodesArray slave, master;
    for (int i = 0; i < kSlave; ++i) {
      Node& node = MakeNode(root, 1 + i, g.slave[i]);
      NormalCalculationUtilities::SetNodalNormal(node, g.normals[i].normalized());
      node.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = -0.7 - 0.2 * i;
      node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.1 * i - 0.05, 0.2 - 0.1 * i, -0.8 - 0.1 * i);
      node.SetValue(INITIAL_PENALTY, 12.0 + 3.0 * i);
      node.SetValue(DYNAMIC_FACTOR, 1.0 + 0.1 * i);
      const bool mixed = pattern == Pattern::kMixed;
      node.Set(ACTIVE, pattern != Pattern::kAllInactive && (!mixed || i % 2 == 0));
      node.Set(SLIP,
               pattern == Pattern::kAllSlip || (pattern == Pattern::kStickSlip && i % 2 == 0) || (mixed && i % 4 == 0));
      slave.push_back(&node);
    }
    for (int l = 0; l < kMaster; ++l) master.push_back(&MakeNode(root, 10 + l, g.master[l]));
    if (kDim == 2)  // the 2D vector multiplier lives in the plane
      for (Node* node : slave) node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER)[2] = 0.0;
    const GeometryType slave_type =
        kDim == 2 ? GeometryType::Line2D2 : (kSlave == 3 ? GeometryType::Triangle3D3 : GeometryType::Quadrilateral3D4);
    const GeometryType master_type =
        kDim == 2 ? GeometryType::Line2D2 : (kMaster == 3 ? GeometryType::Triangle3D3 : GeometryType::Quadrilateral3D4);
    Properties& properties = root.GetOrCreateProperties(1);
    properties.SetValue(INTEGRATION_ORDER_CONTACT, 3);
    pair = std::make_unique<TCondition>(1, Geometry(slave_type, slave), &properties, Geometry(master_type, master));
    ProcessInfo& info = root.GetProcessInfo();
    info.SetValue(INITIAL_PENALTY, 1.0);
    info.SetValue(SCALE_FACTOR, 2.5);
    if constexpr (kFrictional<TCondition>) {
      SetFrictionParameters(root, slave);
      const Array3 offset = kDim == 2 ? Array3(0.12, 0.01, 0.0) : Array3(0.1, -0.07, 0.01);
      InitializeWithMasterOffset(*pair, pair->GetPairedGeometry(), offset, info);
    }
  }

  void CheckTangent() {
    const ProcessInfo& info = root.GetProcessInfo();
    pair->Check(info);
    Matrix lhs;
    Vector rhs;
    pair->CalculateLocalSystem(lhs, rhs, info);
    ASSERT_EQ(lhs.rows(), pair->LocalSize());
    ASSERT_GT(rhs.norm(), 0.0);

    // The separate LHS / RHS calls agree with the local system (the RHS alone is evaluated
    // without derivatives, hence round-off only).
    Matrix lhs_only;
    Vector rhs_only;
    pair->CalculateLeftHandSide(lhs_only, info);
    pair->CalculateRightHandSide(rhs_only, info);
    EXPECT_EQ((lhs - lhs_only).norm(), 0.0);
    EXPECT_LE((rhs - rhs_only).norm(), 1e-13 * rhs.norm());

    const Matrix fd = FiniteDifferenceTangent(*pair, 1e-6, info);
    const double scale = lhs.cwiseAbs().maxCoeff();
    ASSERT_GT(scale, 0.0);
    for (Eigen::Index r = 0; r < lhs.rows(); ++r)
      for (Eigen::Index c = 0; c < lhs.cols(); ++c)
        EXPECT_NEAR(lhs(r, c), fd(r, c), 1e-6 * std::abs(fd(r, c)) + 1e-7 * scale)
            << pair->Info() << " entry (" << r << ", " << c << ")";
  }
};

template <class TCondition>
class TangentTest : public ::testing::Test {};

template <int D, int S, int M>
struct Cases {
  using ALM = ALMFrictionlessMortarContactCondition<D, S, M>;
  using Components = ALMFrictionlessComponentsMortarContactCondition<D, S, M>;
  using Penalty = PenaltyFrictionlessMortarContactCondition<D, S, M>;
  using ALMFrictional = ALMFrictionalMortarContactCondition<D, S, M>;
  using PenaltyFrictional = PenaltyFrictionalMortarContactCondition<D, S, M>;
};

using AllConditions = ::testing::Types<
    Cases<2, 2, 2>::ALM, Cases<3, 3, 3>::ALM, Cases<3, 4, 4>::ALM, Cases<3, 3, 4>::ALM, Cases<3, 4, 3>::ALM,
    Cases<2, 2, 2>::Components, Cases<3, 3, 3>::Components, Cases<3, 4, 4>::Components, Cases<3, 3, 4>::Components,
    Cases<3, 4, 3>::Components, Cases<2, 2, 2>::Penalty, Cases<3, 3, 3>::Penalty, Cases<3, 4, 4>::Penalty,
    Cases<3, 3, 4>::Penalty, Cases<3, 4, 3>::Penalty, Cases<2, 2, 2>::ALMFrictional, Cases<3, 3, 3>::ALMFrictional,
    Cases<3, 4, 4>::ALMFrictional, Cases<3, 3, 4>::ALMFrictional, Cases<3, 4, 3>::ALMFrictional,
    Cases<2, 2, 2>::PenaltyFrictional, Cases<3, 3, 3>::PenaltyFrictional, Cases<3, 4, 4>::PenaltyFrictional,
    Cases<3, 3, 4>::PenaltyFrictional, Cases<3, 4, 3>::PenaltyFrictional,
    ALMFrictionalAxisymMortarContactCondition<2, 2, 2>, PenaltyFrictionalAxisymMortarContactCondition<2, 2, 2>>;
using FrictionalConditions =
    ::testing::Types<Cases<2, 2, 2>::ALMFrictional, Cases<3, 3, 3>::ALMFrictional, Cases<3, 4, 4>::ALMFrictional,
                     Cases<3, 3, 4>::ALMFrictional, Cases<3, 4, 3>::ALMFrictional, Cases<2, 2, 2>::PenaltyFrictional,
                     Cases<3, 3, 3>::PenaltyFrictional, Cases<3, 4, 4>::PenaltyFrictional,
                     Cases<3, 3, 4>::PenaltyFrictional, Cases<3, 4, 3>::PenaltyFrictional,
                     ALMFrictionalAxisymMortarContactCondition<2, 2, 2>,
                     PenaltyFrictionalAxisymMortarContactCondition<2, 2, 2>>;
TYPED_TEST_SUITE(TangentTest, AllConditions);

TYPED_TEST(TangentTest, AllActive) { Fixture<TypeParam>(Pattern::kAllActive).CheckTangent(); }
TYPED_TEST(TangentTest, AllInactive) {
  Fixture<TypeParam> fixture(Pattern::kAllInactive);
  if (fixture.pair->LocalSize() == TypeParam::kNumDisplacementDofs) {
    // Penalty: open nodes contribute nothing at all.
    Matrix lhs;
    Vector rhs;
    fixture.pair->CalculateLocalSystem(lhs, rhs, fixture.root.GetProcessInfo());
    EXPECT_EQ(lhs.norm(), 0.0);
    EXPECT_EQ(rhs.norm(), 0.0);
    return;
  }
  fixture.CheckTangent();
}
TYPED_TEST(TangentTest, Mixed) { Fixture<TypeParam>(Pattern::kMixed).CheckTangent(); }
template <class TCondition>
class FrictionalTangentTest : public ::testing::Test {};
TYPED_TEST_SUITE(FrictionalTangentTest, FrictionalConditions);

TYPED_TEST(FrictionalTangentTest, AllSlip) {
  Fixture<TypeParam> fixture(Pattern::kAllSlip);
  fixture.CheckTangent();
  // The weighted slip (the penalty slip direction, part of the ALM one) is not zero at any node.
  fixture.pair->AddExplicitContribution(fixture.root.GetProcessInfo());
  for (Node* node : fixture.pair->GetGeometry().Nodes())
    EXPECT_GT(node->FastGetSolutionStepValue(WEIGHTED_SLIP).norm(), 1e-3) << "node " << node->Id();
}
TYPED_TEST(FrictionalTangentTest, StickSlip) { Fixture<TypeParam>(Pattern::kStickSlip).CheckTangent(); }

// A slave node on a symmetry plane (its multiplier component across the plane fixed, as the half
// model of cases.cattaneo_mindlin does): its weighted slip has no component across the plane,
// the others' are untouched, and the tangent still equals the finite differences.
TYPED_TEST(FrictionalTangentTest, SlipOnASymmetryPlane) {
  Fixture<TypeParam> fixture(Pattern::kAllSlip);
  const ProcessInfo& info = fixture.root.GetProcessInfo();
  auto nodal_slips = [&] {
    for (Node* node : fixture.pair->GetGeometry().Nodes()) node->FastGetSolutionStepValue(WEIGHTED_SLIP).setZero();
    fixture.pair->AddExplicitContribution(info);
    std::vector<Array3> slips;
    for (Node* node : fixture.pair->GetGeometry().Nodes())
      slips.push_back(node->FastGetSolutionStepValue(WEIGHTED_SLIP));
    return slips;
  };
  Node& on_plane = fixture.pair->GetGeometry()[0];
  Dof& across = on_plane.AddDof(VECTOR_LAGRANGE_MULTIPLIER_Y);
  across.fixed = true;
  fixture.CheckTangent();
  const std::vector<Array3> masked = nodal_slips();
  across.fixed = false;
  const std::vector<Array3> free = nodal_slips();
  EXPECT_GT(std::abs(free[0].y()), 1e-3);
  EXPECT_EQ(masked[0].y(), 0.0);
  EXPECT_EQ(masked[0].x(), free[0].x());
  for (std::size_t j = 1; j < free.size(); ++j) EXPECT_EQ(masked[j], free[j]) << "node " << j;
}

// Tresca (mu = 0, a nodal threshold) and the general bound tau - mu lbar_n (both non-zero).
TYPED_TEST(FrictionalTangentTest, TrescaSlip) {
  for (const bool coulomb : {false, true}) {
    Fixture<TypeParam> fixture(Pattern::kStickSlip);
    int j = 0;
    for (Node* node : fixture.pair->GetGeometry().Nodes()) {
      if (!coulomb) node->SetValue(FRICTION_COEFFICIENT, 0.0);
      node->SetValue(TRESCA_FRICTION_THRESHOLD, 0.4 + 0.1 * j++);
    }
    fixture.CheckTangent();
  }
}

// Issue 12: without friction (mu = tau = 0) a slipping node with a zero tangential multiplier (ALM,
// c_slip = 0: lbar_t = 0, no slip direction) takes the slip branch with a zero direction, not the
// stick branch: its tangential multiplier residual is zero (the stick one, k s . T(wl), is not,
// as s is not), and the tangent still equals the finite differences.
TYPED_TEST(FrictionalTangentTest, FrictionlessSlipWithZeroTangentPressure) {
  Fixture<TypeParam> fixture(Pattern::kAllSlip);
  fixture.root.GetProcessInfo().SetValue(SLIP_AUGMENTATION_COEFFICIENT, 0.0);
  for (Node* node : fixture.pair->GetGeometry().Nodes()) {
    node->SetValue(FRICTION_COEFFICIENT, 0.0);
    const Array3 n = node->FastGetSolutionStepValue(NORMAL);
    Array3 lm = node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER);
    node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = n.dot(lm) * n;
  }
  fixture.CheckTangent();
  constexpr int kDim = Fixture<TypeParam>::kDim;
  const int multipliers = fixture.pair->LocalSize() - TypeParam::kNumDisplacementDofs;
  if (multipliers == 0) return;  // penalty: no multiplier rows
  Vector rhs;
  fixture.pair->CalculateRightHandSide(rhs, fixture.root.GetProcessInfo());
  int j = 0;
  for (Node* node : fixture.pair->GetGeometry().Nodes()) {
    const Array3 n = node->FastGetSolutionStepValue(NORMAL);
    Array3 row = Array3::Zero();
    for (int c = 0; c < kDim; ++c) row[c] = rhs[TypeParam::kNumDisplacementDofs + kDim * j + c];
    EXPECT_GT(std::abs(n.dot(row)), 1e-6) << "node " << j;  // the normal constraint k g (n . wl)
    EXPECT_LE((row - n.dot(row) * n).norm(), 1e-12 * row.norm()) << "node " << j;
    ++j;
  }
}

// The kinematics behind the tangent really has an overlap and non-trivial operator derivatives,
// so that the test above exercises the chain rule through D, M and the gap.
TYPED_TEST(TangentTest, OverlapIsNonTrivial) {
  Fixture<TypeParam> fixture(Pattern::kAllActive);
  using K = typename TypeParam::Kinematics;
  K kinematics;
  typename K::SlaveMatrix x1, n1;
  typename K::MasterMatrix x2;
  for (int i = 0; i < K::kNumSlaveNodes; ++i) {
    x1.row(i) = fixture.pair->GetGeometry()[i].Coordinates().template head<K::kDim>().transpose();
    n1.row(i) =
        NormalCalculationUtilities::GetNodalNormal(fixture.pair->GetGeometry()[i]).template head<K::kDim>().transpose();
  }
  for (int l = 0; l < K::kNumMasterNodes; ++l)
    x2.row(l) = fixture.pair->GetPairedGeometry()[l].Coordinates().template head<K::kDim>().transpose();
  MortarIntegrationSettings settings;
  ASSERT_TRUE(kinematics.Compute(x1, x2, n1, settings));
  double dm = 0.0;
  for (int q = 0; q < K::kNumDisplacementDofs; ++q) dm += kinematics.dM[q].norm();
  EXPECT_GT(dm, 1e-3);
  EXPECT_GT(kinematics.area, 0.1);
}

}  // namespace
}  // namespace mc::test
