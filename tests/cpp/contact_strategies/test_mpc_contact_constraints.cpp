// SPDX-License-Identifier: BSD-3-Clause
// Issue 13 (MPC contact): MPCContactConstraints on a 2D pair of straight faces, 0.1 apart, overlapping
// over [0.3, 1] of the slave face, the whole set-up rotated (the relation then ties two components):
// the lumped D (NODAL_MAUX) is the exact integral of the slave shape functions over the overlap, the
// nodal gap is the distance, and the relation of each slave node, evaluated for any master translation
// and any tangential slave motion, puts the slave node on the master face (the gap measured again is 0).
// Dependent ties: a node on two interfaces (slave of one, master of the other), both faces of an
// interface slave, and a DoF the model part's own constraint already ties. Mesh tying: every free
// component tied.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <unordered_set>

#include "core/utilities/error.h"

#include "custom_conditions/mpc_mortar_contact_condition.h"
#include "custom_strategies/custom_strategies/mpc_contact_constraints.h"
#include "custom_utilities/contact_variables.h"
#include "tests/cpp/contact_conditions/contact_condition_test_utilities.h"

namespace mc::test {
namespace {

const Variable<double>* const kU[2] = {&DISPLACEMENT_X, &DISPLACEMENT_Y};

struct InclinedPair {
  Model model;
  ModelPart& root = MakeContactModelPart(model);
  ModelPart& contact = root.CreateSubModelPart("Contact");
  ModelPart& computing = root.CreateSubModelPart("ComputingContact");
  double angle;
  Array3 up;

  explicit InclinedPair(double theta) : angle(theta), up(-std::sin(theta), std::cos(theta), 0.0) {
    root.GetProcessInfo().SetValue(DOMAIN_SIZE, 2);
    const auto at = [&](double x, double y) {
      return Array3(std::cos(angle) * x - std::sin(angle) * y, std::sin(angle) * x + std::cos(angle) * y, 0.0);
    };
    Node& s1 = MakeNode(root, 1, at(0.0, 0.0));
    Node& s2 = MakeNode(root, 2, at(1.0, 0.0));
    Node& m1 = MakeNode(root, 11, at(1.2, 0.1));
    Node& m2 = MakeNode(root, 12, at(0.3, 0.1));
    for (Node* node : {&s1, &s2}) node->Set(SLAVE);
    auto pair = std::make_unique<MPCMortarContactCondition<2, 2, 2>>(
        1, Geometry(GeometryType::Line2D2, {&s2, &s1}), nullptr, Geometry(GeometryType::Line2D2, {&m1, &m2}));
    Condition& added = computing.AddCondition(std::move(pair));
    contact.AddCondition(&added);
    contact.AddNodes({1, 2, 11, 12});
  }
};

TEST(MPCContactConstraints, OperatorsAndGapOfAnInclinedPair) {
  InclinedPair pair(0.5);
  MPCContactConstraints constraints(pair.contact, pair.computing);
  constraints.Measure();
  Node& s1 = pair.root.GetNode(1);
  Node& s2 = pair.root.GetNode(2);
  EXPECT_NEAR(NormalCalculationUtilities::GetNodalNormal(s1).dot(pair.up), 1.0, 1e-12);
  // int (1 - x) and int x over [0.3, 1]
  EXPECT_NEAR(s1.GetValue(NODAL_MAUX), 0.245, 1e-12);
  EXPECT_NEAR(s2.GetValue(NODAL_MAUX), 0.455, 1e-12);
  EXPECT_NEAR(constraints.NodalGap(s1), 0.1, 1e-12);
  EXPECT_NEAR(constraints.NodalGap(s2), 0.1, 1e-12);
  EXPECT_EQ(s1.GetValue(NODAL_PAUX), 1.0);
  EXPECT_NEAR(s1.FastGetSolutionStepValue(WEIGHTED_GAP), 0.0245, 1e-12);
}

TEST(MPCContactConstraints, RelationPutsTheSlaveNodeOnTheMasterFace) {
  InclinedPair pair(0.5);
  MPCContactConstraints constraints(pair.contact, pair.computing);
  constraints.Measure();
  // A fixed component cannot be the slave of a relation: node 2's y (the largest normal component) is fixed.
  pair.root.GetNode(2).Fix(DISPLACEMENT_Y);
  constraints.Relate();
  ASSERT_EQ(constraints.Relations().size(), 2u);
  // The masters move rigidly, the slave nodes slide along the face; the relations give the rest.
  const Array3 translation(0.03, -0.07, 0.0);
  const Array3 tangent(std::cos(0.5), std::sin(0.5), 0.0);
  for (IndexType id : {11, 12})
    for (int c = 0; c < 2; ++c) SetDofValue(pair.root.GetNode(id).GetDof(*kU[c]), translation[c]);
  for (IndexType id : {1, 2})
    for (int c = 0; c < 2; ++c) SetDofValue(pair.root.GetNode(id).GetDof(*kU[c]), 0.02 * id * tangent[c]);
  for (const auto& [node, relation] : constraints.Relations()) {
    if (node->Id() == 2) {
      EXPECT_EQ(relation->Slave().variable, &DISPLACEMENT_X);
    }
    double value = relation->Constant();
    for (std::size_t i = 0; i < relation->Masters().size(); ++i)
      value += relation->Weights()[i] * relation->Masters()[i]->Value();
    relation->Slave().Value() = value;
  }
  for (Node* node : pair.root.Nodes()) node->Coordinates() = node->X0() + node->FastGetSolutionStepValue(DISPLACEMENT);
  constraints.Measure();
  EXPECT_NEAR(constraints.NodalGap(pair.root.GetNode(1)), 0.0, 1e-12);
  EXPECT_NEAR(constraints.NodalGap(pair.root.GetNode(2)), 0.0, 1e-12);
}

// Mesh tying: one relation per free component, u_jc = sum_i P_ji u_ic with no constant; P reproduces a
// linear field of the (inclined, 0.1 apart) faces' tangential coordinate and sums to 1, so any master
// field u = a + b s (s the arc length along the face) gives every slave node the same field at its s: the
// gap is kept, a rigid motion and a uniform stretch of the master carry the slave along.
TEST(MPCContactConstraints, MeshTyingTiesEveryFreeComponent) {
  InclinedPair pair(0.5);
  MPCContactConstraints constraints(pair.contact, pair.computing);
  constraints.Measure();
  pair.root.GetNode(2).Fix(DISPLACEMENT_Y);  // held by its support: no relation
  constraints.RelateAllComponents();
  ASSERT_EQ(constraints.Relations().size(), 3u);
  const Array3 tangent(std::cos(0.5), std::sin(0.5), 0.0);
  const auto s = [&](const Node& node) { return node.X0().dot(tangent); };
  const Array3 a(0.03, -0.07, 0.0), b(0.011, 0.005, 0.0);
  for (IndexType id : {11, 12})
    for (int c = 0; c < 2; ++c)
      SetDofValue(pair.root.GetNode(id).GetDof(*kU[c]), a[c] + b[c] * s(pair.root.GetNode(id)));
  for (const auto& [node, relation] : constraints.Relations()) {
    EXPECT_EQ(relation->Constant(), 0.0);
    EXPECT_FALSE(relation->Slave().fixed);
    const int c = relation->Slave().variable == &DISPLACEMENT_X ? 0 : 1;
    double value = 0.0, weights = 0.0;
    for (std::size_t i = 0; i < relation->Masters().size(); ++i) {
      EXPECT_EQ(relation->Masters()[i]->variable, relation->Slave().variable);
      value += relation->Weights()[i] * relation->Masters()[i]->Value();
      weights += relation->Weights()[i];
    }
    EXPECT_NEAR(weights, 1.0, 1e-12);
    EXPECT_NEAR(value, a[c] + b[c] * s(*node), 1e-12) << "node " << node->Id() << " component " << c;
  }
}

/// Three parallel faces y = 0 (nodes 1, 2), 0.1 (11, 12) and 0.2 (21, 22) with the pairs (slave, master)
/// listed by node ids; every slave node ACTIVE after Measure and Relate.
struct Stack {
  Model model;
  ModelPart& root = MakeContactModelPart(model);
  ModelPart& contact = root.CreateSubModelPart("Contact");
  ModelPart& computing = root.CreateSubModelPart("ComputingContact");
  MPCContactConstraints constraints{contact, computing};

  explicit Stack(const std::vector<std::pair<std::array<IndexType, 2>, std::array<IndexType, 2>>>& pairs) {
    root.GetProcessInfo().SetValue(DOMAIN_SIZE, 2);
    MakeNode(root, 1, Array3(0.0, 0.0, 0.0));
    MakeNode(root, 2, Array3(1.0, 0.0, 0.0));
    MakeNode(root, 11, Array3(1.2, 0.1, 0.0));
    MakeNode(root, 12, Array3(0.3, 0.1, 0.0));
    MakeNode(root, 21, Array3(1.3, 0.2, 0.0));
    MakeNode(root, 22, Array3(0.2, 0.2, 0.0));
    IndexType id = 0;
    for (const auto& [slave, master] : pairs) {
      Node& s1 = root.GetNode(slave[0]);
      Node& s2 = root.GetNode(slave[1]);
      for (Node* node : {&s1, &s2}) node->Set(SLAVE);
      auto pair = std::make_unique<MPCMortarContactCondition<2, 2, 2>>(
          ++id, Geometry(GeometryType::Line2D2, {&s1, &s2}), nullptr,
          Geometry(GeometryType::Line2D2, {&root.GetNode(master[0]), &root.GetNode(master[1])}));
      contact.AddCondition(&computing.AddCondition(std::move(pair)));
    }
    contact.AddNodes({1, 2, 11, 12, 21, 22});
    constraints.Measure();
    constraints.Relate();
    for (const auto& [node, relation] : constraints.Relations()) node->Set(ACTIVE);
  }
};

/// The slave values the relations give for the current master values.
void Impose(const std::vector<std::shared_ptr<const MasterSlaveConstraint>>& relations) {
  for (const auto& relation : relations) {
    double value = relation->Constant();
    for (std::size_t i = 0; i < relation->Masters().size(); ++i)
      value += relation->Weights()[i] * relation->Masters()[i]->Value();
    relation->Slave().Value() = value;
  }
}

std::unordered_set<const Dof*> Slaves(const std::vector<std::shared_ptr<const MasterSlaveConstraint>>& relations) {
  std::unordered_set<const Dof*> slaves;
  for (const auto& relation : relations) slaves.insert(&relation->Slave());
  return slaves;
}

TEST(MPCContactConstraints, NodeOnTwoInterfacesIsSubstitutedNotChained) {
  // 1-2 slave on 11-12, and 11-12 slave on 21-22: the relations of 1 and 2 have masters 11 and 12, themselves
  // slaves (the builder rejects chains).
  Stack stack({{{2, 1}, {11, 12}}, {{11, 12}, {21, 22}}});
  const auto tied = stack.constraints.TiedRelations();
  ASSERT_EQ(tied.size(), 4u);
  const auto slaves = Slaves(tied);
  for (const auto& relation : tied)
    for (const Dof* master : relation->Masters()) EXPECT_FALSE(slaves.count(master)) << relation->Id();
  // The substituted relations state the original ties: any master motion, imposed through them, satisfies
  // every original relation.
  SetDofValue(stack.root.GetNode(21).GetDof(DISPLACEMENT_Y), -0.03);
  SetDofValue(stack.root.GetNode(22).GetDof(DISPLACEMENT_Y), -0.05);
  Impose(tied);
  for (const auto& [node, relation] : stack.constraints.Relations()) {
    double value = relation->Constant();
    for (std::size_t i = 0; i < relation->Masters().size(); ++i)
      value += relation->Weights()[i] * relation->Masters()[i]->Value();
    EXPECT_NEAR(relation->Slave().Value(), value, 1e-14) << node->Id();
  }
}

TEST(MPCContactConstraints, FacesSlaveOfEachOtherKeepOneTie) {
  // 1-2 slave on 11-12 and 11-12 slave on 1-2: node 1 is tied to 11 and 12, which are tied back to 1: the
  // later relations (11, 12) are dropped, the ones of 1 and 2 close the gap.
  Stack stack({{{2, 1}, {11, 12}}, {{12, 11}, {1, 2}}});
  ASSERT_EQ(stack.constraints.Relations().size(), 4u);
  const auto tied = stack.constraints.TiedRelations();
  ASSERT_EQ(tied.size(), 2u);
  const auto slaves = Slaves(tied);
  EXPECT_TRUE(slaves.count(&stack.root.GetNode(1).GetDof(DISPLACEMENT_Y)));
  EXPECT_TRUE(slaves.count(&stack.root.GetNode(2).GetDof(DISPLACEMENT_Y)));
  for (const auto& relation : tied)
    for (const Dof* master : relation->Masters()) EXPECT_FALSE(slaves.count(master));
}

TEST(MPCContactConstraints, DofTiedByTheModelPartIsNamed) {
  Stack stack({{{2, 1}, {11, 12}}});
  Node& node = stack.root.GetNode(2);
  stack.root.AddMasterSlaveConstraint(std::make_shared<MasterSlaveConstraint>(
      99, node.GetDof(DISPLACEMENT_Y), std::vector<Dof*>{&node.GetDof(DISPLACEMENT_X)}, std::vector<double>{1.0}));
  try {
    stack.constraints.TiedRelations();
    FAIL() << "no error";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("slave node 2, DISPLACEMENT_Y"), std::string::npos) << message;
    EXPECT_NE(message.find("master-slave constraint 99"), std::string::npos) << message;
  }
}

// Frictional: a slipping node's Coulomb force is -mu |f_n| s on the node and the opposite on the masters
// (summed: the rows of M sum to D over the overlap), from its normal force only; a sticking node is tied
// in both components with no slip of the step.
TEST(MPCContactConstraints, CoulombForceOfASlippingNodeAndTiesOfASticking) {
  InclinedPair pair(0.5);
  pair.root.SetBufferSize(2);  // the stick ties keep the relative position of the step's start
  MPCContactConstraints constraints(pair.contact, pair.computing);
  constraints.SetFrictional(true);
  constraints.Measure();
  constraints.Relate();
  Node& slipping = pair.root.GetNode(1);
  Node& sticking = pair.root.GetNode(2);
  for (Node* node : {&slipping, &sticking}) {
    node->Set(ACTIVE, true);
    node->SetValue(FRICTION_COEFFICIENT, 0.2);
  }
  slipping.Set(SLIP, true);
  sticking.Set(SLIP, false);
  const Array3 tangent(std::cos(0.5), std::sin(0.5), 0.0);
  const auto terms = constraints.CoulombTerms({{&slipping, tangent}, {&sticking, tangent}}, {}).combination;
  ASSERT_FALSE(terms.empty());
  // The force the terms add for a residual r = f_ext - f_int at the slipping node (zero elsewhere).
  const auto forces = [&](const Array3& residual) {
    std::map<IndexType, Array3> added;
    for (const auto& term : terms) {
      EXPECT_EQ(term.from->node, &slipping);
      const int d = term.from->variable == &DISPLACEMENT_X ? 0 : 1;
      const int c = term.to->variable == &DISPLACEMENT_X ? 0 : 1;
      added.try_emplace(term.to->node->Id(), Array3::Zero()).first->second[c] += term.weight * residual[d];
    }
    return added;
  };
  // Pressed with f_n = n . (f_int - f_ext) = -3, plus a tangential part the force must ignore.
  const auto added = forces(3.0 * pair.up - 7.0 * tangent);
  EXPECT_TRUE((added.at(1) - (-0.2 * 3.0 * tangent)).norm() < 1e-12) << added.at(1).transpose();
  const Array3 on_masters = added.at(11) + added.at(12);
  EXPECT_TRUE((on_masters - 0.2 * 3.0 * tangent).norm() < 1e-12) << on_masters.transpose();
  EXPECT_FALSE(added.count(2));
  // The sticking node: both components tied (node 1 slips: its normal relation only).
  const auto tied = constraints.TiedRelations();
  EXPECT_EQ(tied.size(), 3u);
}

// 3D: a slipping node's Coulomb force -mu |f_n| s with s the direction of its tangential slip of the
// step; the stiffness terms (the turn of s, f_n held) are minus the central-difference derivative of
// that force with respect to every displacement of the node and its masters, to 1e-8.
TEST(MPCContactConstraints, TurnStiffnessOfA3DSlipIsTheDerivativeOfItsCoulombForce) {
  Model model;
  ModelPart& root = MakeContactModelPart(model);
  ModelPart& contact = root.CreateSubModelPart("Contact");
  ModelPart& computing = root.CreateSubModelPart("ComputingContact");
  root.GetProcessInfo().SetValue(DOMAIN_SIZE, 3);
  root.SetBufferSize(2);
  std::vector<Node*> slaves;
  std::vector<Node*> masters;
  const double corners[4][2] = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  for (int i = 0; i < 4; ++i) {
    slaves.push_back(&MakeNode(root, 1 + i, Array3(corners[i][0], corners[i][1], 0.0)));
    slaves.back()->Set(SLAVE);
    // The master face: shifted and larger, ordered the other way (its normal points down).
    masters.push_back(
        &MakeNode(root, 11 + i, Array3(1.3 * corners[3 - i][0] - 0.2, 1.2 * corners[3 - i][1] - 0.35, 0.1)));
  }
  Condition& added = computing.AddCondition(std::make_unique<MPCMortarContactCondition<3, 4, 4>>(
      1, Geometry(GeometryType::Quadrilateral3D4, slaves), nullptr, Geometry(GeometryType::Quadrilateral3D4, masters)));
  contact.AddCondition(&added);
  contact.AddNodes({1, 2, 3, 4, 11, 12, 13, 14});
  MPCContactConstraints constraints(contact, computing);
  constraints.SetFrictional(true);
  constraints.Measure();
  constraints.Relate();
  Node& node = root.GetNode(3);
  const double mu = 0.2;
  const double normal_force = -3.0;
  node.Set(ACTIVE, true);
  node.Set(SLIP, true);
  node.SetValue(FRICTION_COEFFICIENT, mu);
  // A slip of the step with a component along the normal (the projection removes it) and masters moved.
  const Array3 moves[5] = {
      {2e-3, 1e-3, 4e-4}, {-3e-4, 5e-4, 0.0}, {1e-4, -2e-4, 0.0}, {0.0, 3e-4, 1e-4}, {2e-4, 0.0, 0.0}};
  std::vector<Node*> moved{&node};
  for (Node* master : masters) moved.push_back(master);
  for (std::size_t i = 0; i < moved.size(); ++i) moved[i]->FastGetSolutionStepValue(DISPLACEMENT) = moves[i];
  const auto force = [&]() {
    const Array3 slip = constraints.TangentialSlip(node);
    return Array3(-mu * std::abs(normal_force) * slip / slip.norm());
  };
  const Array3 slip = constraints.TangentialSlip(node);
  ASSERT_GT(slip.norm(), 1e-4);
  const auto system = constraints.CoulombTerms({{&node, Array3(slip / slip.norm())}},
                                               {{&node, mu * std::abs(normal_force) / slip.norm()}});
  ASSERT_FALSE(system.stiffness.empty());
  std::map<std::pair<const Dof*, const Dof*>, double> stiffness;
  for (const auto& term : system.stiffness) stiffness[{term.to, term.from}] += term.weight;
  const Variable<double>* const u[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
  const double h = 1e-7;
  double largest = 0.0;
  int checked = 0;
  for (Node* other : moved)
    for (int d = 0; d < 3; ++d) {
      double& value = other->FastGetSolutionStepValue(DISPLACEMENT)[d];
      value += h;
      const Array3 plus = force();
      value -= 2.0 * h;
      const Array3 minus = force();
      value += h;
      const Array3 derivative = (plus - minus) / (2.0 * h);
      largest = std::max(largest, derivative.norm());
      for (int c = 0; c < 3; ++c) {
        const auto entry = stiffness.find({&node.GetDof(*u[c]), &other->GetDof(*u[d])});
        const double term = entry == stiffness.end() ? 0.0 : entry->second;
        EXPECT_NEAR(term, -derivative[c], 1e-8 * mu * std::abs(normal_force) / slip.norm())
            << "row " << c << " of node 3, column " << d << " of node " << other->Id();
        ++checked;
      }
    }
  EXPECT_EQ(checked, 45);
  EXPECT_GT(largest, 1.0);  // the derivative is not trivially zero
}

}  // namespace
}  // namespace mc::test
