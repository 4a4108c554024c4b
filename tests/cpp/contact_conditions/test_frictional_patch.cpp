// SPDX-License-Identifier: BSD-3-Clause
// Issue 12 (Coulomb frictional mortar conditions), on a flat 2D patch: a slave line y = 0 (body
// below, normals +y) of two segments, pressed by 0.01 into a non-matching master line of two
// segments; every slave node ACTIVE. The pairs store D_n, M_n at InitializeSolutionStep.
//  - stick patch: after a rigid rotation and translation of both bodies the weighted slip is zero
//    (frame indifference) and so is every tangential force, while the normal force is not;
//  - sliding patch: with the master moved along the interface, the stick force resists the
//    relative motion, and in slip the total tangential force is mu times the total normal force,
//    dragging the slave along with the master (ALM with c_slip = 1 and a normal multiplier, so that
//    the slip direction comes from the weighted slip; penalty);
//  - a pair created within the step takes D_n, M_n from the previous step's coordinates;
//  - a missing TANGENT_FACTOR or FRICTION_COEFFICIENT is an input error naming it.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "contact_condition_test_utilities.h"
#include "core/utilities/error.h"
#include "custom_conditions/alm_frictional_mortar_contact_condition.h"
#include "custom_conditions/penalty_frictional_mortar_contact_condition.h"

namespace mc::test {
namespace {

constexpr double kMu = 0.3;

template <class TCondition>
struct Patch {
  Model model;
  ModelPart& root = MakeContactModelPart(model);
  std::vector<Node*> slave, master;
  std::vector<std::unique_ptr<TCondition>> pairs;

  explicit Patch(bool slip, bool friction_coefficient = true) {
    for (int i = 0; i < 3; ++i) slave.push_back(&MakeNode(root, 1 + i, Array3(1.0 * i, 0.0, 0.0)));
    // Facing the slave: listed right to left, 0.01 below y = 0 (penetrating).
    const double xm[] = {2.6, 1.3, -0.6};
    for (int l = 0; l < 3; ++l) master.push_back(&MakeNode(root, 11 + l, Array3(xm[l], -0.01, 0.0)));
    SetFrictionParameters(root, friction_coefficient ? slave : std::vector<Node*>{}, 1.0);
    for (Node* node : slave) {
      NormalCalculationUtilities::SetNodalNormal(*node, Array3(0.0, 1.0, 0.0));
      node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(0.0, -0.5, 0.0);
      node->SetValue(INITIAL_PENALTY, 100.0);
      if (friction_coefficient) node->SetValue(FRICTION_COEFFICIENT, kMu);
      node->Set(ACTIVE, true);
      node->Set(SLIP, slip);
    }
    Properties& properties = root.GetOrCreateProperties(1);
    root.GetProcessInfo().SetValue(SCALE_FACTOR, 2.0);
    IndexType id = 1;
    for (int s = 0; s < 2; ++s)
      for (int m = 0; m < 2; ++m)
        pairs.push_back(std::make_unique<TCondition>(id++, Geometry(GeometryType::Line2D2, {slave[s], slave[s + 1]}),
                                                     &properties,
                                                     Geometry(GeometryType::Line2D2, {master[m], master[m + 1]})));
    for (auto& pair : pairs) pair->InitializeSolutionStep(root.GetProcessInfo());
  }

  /// Moves every node (and the slave normals) by x -> R x + t.
  void Move(const std::vector<Node*>& nodes, double angle, const Array3& t) {
    Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
    r.topLeftCorner<2, 2>() << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    for (Node* node : nodes) {
      node->Coordinates() = r * node->Coordinates() + t;
      node->FastGetSolutionStepValue(DISPLACEMENT) = node->Coordinates() - node->X0();
      if (node->Id() < 10) {
        NormalCalculationUtilities::SetNodalNormal(*node, r * NormalCalculationUtilities::GetNodalNormal(*node));
        node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) =
            r * Array3(node->FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER));
      }
    }
  }

  /// Assembled force on each slave node (displacement rows of the RHS) and the multiplier rows.
  void Forces(std::vector<Array3>& force, std::vector<Array3>& multiplier_rows) {
    force.assign(3, Array3::Zero());
    multiplier_rows.assign(3, Array3::Zero());
    const ProcessInfo& info = root.GetProcessInfo();
    for (auto& pair : pairs) {
      pair->Check(info);
      Vector rhs;
      pair->CalculateRightHandSide(rhs, info);
      const int components = (rhs.size() - 8) / 2;  // 2 master + 2 slave nodes x 2 components first
      for (int i = 0; i < 2; ++i) {
        const int node = static_cast<int>(pair->GetGeometry()[i].Id()) - 1;
        force[node].head<2>() += rhs.segment<2>(4 + 2 * i);
        if (components > 0) multiplier_rows[node].head<2>() += rhs.segment<2>(8 + 2 * i);
      }
    }
  }

  std::vector<Node*> AllNodes() const {
    std::vector<Node*> nodes = slave;
    nodes.insert(nodes.end(), master.begin(), master.end());
    return nodes;
  }
};

template <class TCondition>
class FrictionalPatch : public ::testing::Test {};
using Conditions =
    ::testing::Types<ALMFrictionalMortarContactCondition<2, 2, 2>, PenaltyFrictionalMortarContactCondition<2, 2, 2>>;
TYPED_TEST_SUITE(FrictionalPatch, Conditions);

TYPED_TEST(FrictionalPatch, RigidMotionGivesNoTangentialForce) {
  Patch<TypeParam> patch(false);
  patch.Move(patch.AllNodes(), 0.4, Array3(0.3, -0.2, 0.0));
  for (auto& pair : patch.pairs) pair->AddExplicitContribution(patch.root.GetProcessInfo());
  std::vector<Array3> force, multiplier_rows;
  patch.Forces(force, multiplier_rows);
  double normal = 0.0;
  for (int j = 0; j < 3; ++j) {
    const Node& node = *patch.slave[j];
    const Array3 n = NormalCalculationUtilities::GetNodalNormal(node);
    EXPECT_LE(node.FastGetSolutionStepValue(WEIGHTED_SLIP).norm(), 1e-14) << "node " << node.Id();
    normal = std::max(normal, std::abs(force[j].dot(n)));
    EXPECT_LE((force[j] - n * n.dot(force[j])).norm(), 1e-12) << "node " << node.Id();
    EXPECT_LE((multiplier_rows[j] - n * n.dot(multiplier_rows[j])).norm(), 1e-12) << "node " << node.Id();
  }
  EXPECT_GT(normal, 0.1);
}

TYPED_TEST(FrictionalPatch, StickResistsSliding) {
  Patch<TypeParam> patch(false);
  patch.Move(patch.master, 0.0, Array3(0.05, 0.0, 0.0));
  std::vector<Array3> force, multiplier_rows;
  patch.Forces(force, multiplier_rows);
  // The master moved +x: the stick force drags the slave along +x.
  double tangential = 0.0;
  for (const Array3& f : force) tangential += f[0];
  EXPECT_GT(tangential, 1e-3);
}

TYPED_TEST(FrictionalPatch, SlipForceIsMuTimesNormalForce) {
  Patch<TypeParam> patch(true);
  patch.Move(patch.master, 0.0, Array3(0.05, 0.0, 0.0));
  std::vector<Array3> force, multiplier_rows;
  patch.Forces(force, multiplier_rows);
  Array3 total = Array3::Zero();
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(std::abs(force[j][0]), kMu * std::abs(force[j][1]), 1e-12) << "node " << patch.slave[j]->Id();
    total += force[j];
  }
  EXPECT_GT(std::abs(total[1]), 0.1);
  EXPECT_NEAR(total[0], kMu * std::abs(total[1]), 1e-12 * std::abs(total[1]));  // along the master's motion
}

// Tresca (FRICTION_COEFFICIENT 0, TRESCA_FRICTION_THRESHOLD tau): the slipping slave carries the
// tangential traction tau over its mortar area, whatever the normal pressure: a total force of
// tau x 2 (the slave line's length), for two penetrations of the master.
TYPED_TEST(FrictionalPatch, TrescaSlipForceIsThresholdTimesArea) {
  constexpr double kTau = 0.35;
  for (const double push : {0.0, 0.02}) {
    Patch<TypeParam> patch(true);
    for (Node* node : patch.slave) {
      node->SetValue(FRICTION_COEFFICIENT, 0.0);
      node->SetValue(TRESCA_FRICTION_THRESHOLD, kTau);
    }
    patch.Move(patch.master, 0.0, Array3(0.05, -push, 0.0));
    std::vector<Array3> force, multiplier_rows;
    patch.Forces(force, multiplier_rows);
    Array3 total = Array3::Zero();
    for (const Array3& f : force) total += f;
    EXPECT_GT(std::abs(total[1]), 0.1);
    EXPECT_NEAR(total[0], kTau * 2.0, 1e-12);  // along the master's motion
  }
}

// A pair created after InitializeSolutionStep (a new search within the step) takes D_n, M_n from
// the previous step's coordinates X0 + DISPLACEMENT(1): the same weighted slip as a pair that
// stored them at the start of the step.
TEST(FrictionalPreviousOperators, PairCreatedLaterUsesThePreviousStepCoordinates) {
  using Pair = PenaltyFrictionalMortarContactCondition<2, 2, 2>;
  Patch<Pair> patch(false);  // its pairs stored D_n, M_n in the initial configuration
  patch.root.SetBufferSize(2);
  for (Node* node : patch.AllNodes()) node->FastGetSolutionStepValue(DISPLACEMENT, 1) = Array3::Zero();
  patch.Move(patch.master, 0.0, Array3(0.05, 0.0, 0.0));
  Properties& properties = patch.root.GetProperties(1);
  // pairs[1]: the first slave segment and the master segment it overlaps.
  Pair late(99, patch.pairs[1]->GetGeometry(), &properties, patch.pairs[1]->GetPairedGeometry());
  const ProcessInfo& info = patch.root.GetProcessInfo();
  auto explicit_slip = [&](PairedCondition& pair) {
    for (Node* node : patch.slave) node->FastGetSolutionStepValue(WEIGHTED_SLIP) = Array3::Zero();
    pair.AddExplicitContribution(info);
    return Array3(patch.slave[0]->FastGetSolutionStepValue(WEIGHTED_SLIP));
  };
  const Array3 stored = explicit_slip(*patch.pairs[1]);
  EXPECT_GT(stored.norm(), 1e-3);
  EXPECT_LE((explicit_slip(late) - stored).norm(), 1e-14);
  Vector rhs_stored, rhs_late;
  patch.pairs[1]->CalculateRightHandSide(rhs_stored, info);
  late.CalculateRightHandSide(rhs_late, info);
  EXPECT_LE((rhs_stored - rhs_late).norm(), 1e-14 * rhs_stored.norm());
}

// Bad input names the condition, the node and the missing value.
TEST(FrictionalParameters, MissingTangentFactorOrFrictionCoefficientIsAnInputError) {
  auto expect_error = [](Patch<PenaltyFrictionalMortarContactCondition<2, 2, 2>>& patch, const char* what) {
    Vector rhs;
    try {
      patch.pairs[0]->CalculateRightHandSide(rhs, patch.root.GetProcessInfo());
      ADD_FAILURE() << "missing " << what << " should be an error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  Patch<PenaltyFrictionalMortarContactCondition<2, 2, 2>> no_tangent_factor(false);
  no_tangent_factor.root.GetProcessInfo().SetValue(TANGENT_FACTOR, 0.0);
  expect_error(no_tangent_factor, "TANGENT_FACTOR");
  Patch<PenaltyFrictionalMortarContactCondition<2, 2, 2>> no_friction_coefficient(false, false);
  expect_error(no_friction_coefficient, "FRICTION_COEFFICIENT");
}

}  // namespace
}  // namespace mc::test
