// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (active set): the frictionless NCP (thesis eqs. 4.41-4.44) on hand-made nodes:
// activation, deactivation, initialisation of the multiplier, nodal penalty, change count.
// Issue 12 (friction): the Coulomb stick/slip set (eqs. 4.75-4.77), one test per transition.
#include <gtest/gtest.h>

#include <string>

#include "core/model/model.h"
#include "core/utilities/logger.h"
#include "custom_utilities/active_set_utilities.h"
#include "custom_utilities/contact_variables.h"

namespace mc {
namespace {

using namespace ActiveSetUtilities;

TEST(ActiveSet, NcpKernels) {
  EXPECT_DOUBLE_EQ(AugmentedNormalPressure(2.0, -3.0, 10.0, 0.5), -1.0);
  // Active branch: C = -eps g; inactive branch: C = k lambda.
  EXPECT_DOUBLE_EQ(FrictionlessNcp(2.0, -3.0, 10.0, 0.5), 5.0 * -1.0);
  EXPECT_DOUBLE_EQ(FrictionlessNcp(2.0, -3.0, 10.0, 0.7), 2.0 * -3.0);
  // KKT points are zeros: separated (lambda = 0, g > 0) and in contact (lambda < 0, g = 0).
  EXPECT_DOUBLE_EQ(FrictionlessNcp(2.0, 0.0, 10.0, 0.3), 0.0);
  EXPECT_DOUBLE_EQ(FrictionlessNcp(2.0, -4.0, 10.0, 0.0), 0.0);
  // Tension with a closed gap and penetration without pressure are not.
  EXPECT_NE(FrictionlessNcp(2.0, 1.0, 10.0, 0.0), 0.0);
  EXPECT_NE(FrictionlessNcp(2.0, 0.0, 10.0, -0.1), 0.0);
  EXPECT_TRUE(IsActive(-1e-300));
  EXPECT_FALSE(IsActive(0.0));
  EXPECT_DOUBLE_EQ(ActivationPressure(4.0, -2.0), -0.5);
}

struct Nodes {
  Model model;
  ModelPart& root = model.CreateModelPart("Structure", 2);
  ModelPart* contact = nullptr;
  Nodes() {
    root.AddNodalSolutionStepVariable(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE);
    root.AddNodalSolutionStepVariable(VECTOR_LAGRANGE_MULTIPLIER);
    root.AddNodalSolutionStepVariable(WEIGHTED_GAP);
    root.AddNodalSolutionStepVariable(NORMAL);
    contact = &root.CreateSubModelPart("Contact");
    root.GetProcessInfo().SetValue(SCALE_FACTOR, 2.0);
    root.GetProcessInfo().SetValue(INITIAL_PENALTY, 10.0);
    for (IndexType id = 1; id <= 5; ++id) {
      Node& n = contact->CreateNewNode(id, double(id), 0.0, 0.0);
      n.Set(SLAVE, id != 5);  // node 5 is a master node: never touched
      n.FastGetSolutionStepValue(NORMAL) = Array3(0.0, 1.0, 0.0);
    }
  }
  Node& N(IndexType id) { return root.GetNode(id); }
  double& Lm(IndexType id) { return N(id).FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE); }
  double& Gap(IndexType id) { return N(id).FastGetSolutionStepValue(WEIGHTED_GAP); }
};

TEST(ActiveSet, ScalarAlmActivatesDeactivatesAndCounts) {
  Nodes s;
  // 1: inactive, penetrating -> activates, lambda = (0 + 10 * -0.2) / 2 = -1.
  s.Gap(1) = -0.2;
  // 2: active, pressure -1 with open gap 0.3 -> 2*-1 + 10*0.3 = 1 > 0 -> deactivates, lambda kept.
  s.N(2).Set(ACTIVE, true);
  s.Lm(2) = -1.0;
  s.Gap(2) = 0.3;
  // 3: active and stays: 2*-1 + 10*0.1 = -1 < 0; its multiplier is not reset.
  s.N(3).Set(ACTIVE, true);
  s.Lm(3) = -1.0;
  s.Gap(3) = 0.1;
  // 4: inactive, open gap with its own penalty 1: 0 + 1 * 0.05 > 0 -> stays inactive.
  s.Gap(4) = 0.05;
  s.N(4).SetValue(INITIAL_PENALTY, 1.0);
  // 5: master node with a penetration: ignored.
  s.Gap(5) = -1.0;

  ChangedNodes changed;
  EXPECT_EQ(ComputeALMFrictionlessActiveSet(*s.contact, &changed), 2u);
  EXPECT_EQ(changed, (ChangedNodes{1, 2}));
  EXPECT_TRUE(s.N(1).Is(ACTIVE));
  EXPECT_DOUBLE_EQ(s.Lm(1), -1.0);
  EXPECT_DOUBLE_EQ(s.N(1).GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), -2.0);
  EXPECT_FALSE(s.N(2).Is(ACTIVE));
  EXPECT_DOUBLE_EQ(s.Lm(2), -1.0);
  EXPECT_DOUBLE_EQ(s.N(2).GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), 1.0);
  EXPECT_TRUE(s.N(3).Is(ACTIVE));
  EXPECT_DOUBLE_EQ(s.Lm(3), -1.0);
  EXPECT_DOUBLE_EQ(s.N(3).GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), -1.0);
  EXPECT_FALSE(s.N(4).Is(ACTIVE));
  EXPECT_DOUBLE_EQ(s.N(4).GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), 0.05);
  EXPECT_FALSE(s.N(5).Is(ACTIVE));
  EXPECT_FALSE(s.N(5).Has(AUGMENTED_NORMAL_CONTACT_PRESSURE));
  // Same data again: nothing changes.
  EXPECT_EQ(ComputeALMFrictionlessActiveSet(*s.contact, &changed), 0u);
  EXPECT_TRUE(changed.empty());
  // The nodal penalty decides: node 4 with eps = 1 and g = -0.01 activates, lambda = -0.005.
  s.Gap(4) = -0.01;
  EXPECT_EQ(ComputeALMFrictionlessActiveSet(*s.contact), 1u);
  EXPECT_DOUBLE_EQ(s.Lm(4), -0.005);
}

TEST(ActiveSet, ComponentsUseTheNormalProjection) {
  Nodes s;
  // n = (0, 1, 0); lambda = (5, -0.4, 0): n.lambda = -0.4 -> 2 * -0.4 + 10 * 0.05 = -0.3 -> active.
  s.N(1).FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(5.0, -0.4, 0.0);
  s.Gap(1) = 0.05;
  // Node 2: inactive, penetrating: lambda := n * (10 * -0.1) / 2 = (0, -0.5, 0).
  s.N(2).FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = Array3(1.0, 0.0, 0.0);
  s.Gap(2) = -0.1;
  s.Gap(3) = 0.2;
  s.Gap(4) = 0.2;
  EXPECT_EQ(ComputeALMFrictionlessComponentsActiveSet(*s.contact), 2u);
  EXPECT_TRUE(s.N(1).Is(ACTIVE));
  EXPECT_DOUBLE_EQ(s.N(1).GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), -0.3);
  EXPECT_TRUE(s.N(2).Is(ACTIVE));
  const Array3 lm2 = s.N(2).FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER);
  EXPECT_DOUBLE_EQ(lm2[0], 0.0);
  EXPECT_DOUBLE_EQ(lm2[1], -0.5);
  // Node 1 was activated too: its multiplier is reset to n * lambda_bar / k = (0, -0.15, 0).
  EXPECT_DOUBLE_EQ(s.N(1).FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER)[0], 0.0);
  EXPECT_DOUBLE_EQ(s.N(1).FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER)[1], -0.15);
}

TEST(ActiveSet, PenaltyFollowsTheSignOfTheGap) {
  Nodes s;
  s.Gap(1) = -1e-6;
  s.Gap(2) = 0.0;
  s.N(3).Set(ACTIVE, true);
  s.Gap(3) = 1e-6;
  s.N(4).Set(ACTIVE, true);
  s.Lm(4) = 100.0;  // multipliers play no role
  s.Gap(4) = -1e-3;
  ChangedNodes changed;
  EXPECT_EQ(ComputePenaltyFrictionlessActiveSet(*s.contact, &changed), 2u);
  EXPECT_EQ(changed, (ChangedNodes{1, 3}));
  EXPECT_TRUE(s.N(1).Is(ACTIVE));
  EXPECT_FALSE(s.N(2).Is(ACTIVE));
  EXPECT_FALSE(s.N(3).Is(ACTIVE));
  EXPECT_TRUE(s.N(4).Is(ACTIVE));
  EXPECT_DOUBLE_EQ(s.N(4).GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), -1e-2);
  EXPECT_DOUBLE_EQ(s.Lm(1), 0.0);
}

TEST(ActiveSet, FrictionKernels) {
  const Array3 n(0.0, 1.0, 0.0);
  const Array3 t = TangentialPart(Array3(3.0, -2.0, 4.0), n);
  EXPECT_EQ(t, Array3(3.0, 0.0, 4.0));
  EXPECT_EQ(AugmentedTangentPressure(2.0, Array3(1.0, 0.0, 0.0), 0.5, 8.0, Array3(0.0, 0.0, 1.0)),
            Array3(2.0, 0.0, 4.0));
  EXPECT_DOUBLE_EQ(SlipTestFactor(false, 0.25), 1.0);
  EXPECT_DOUBLE_EQ(SlipTestFactor(true, 0.25), 0.75);
  // Coulomb limit mu |lbar_n| = 0.5 for lbar_n = -2, mu = 0.25: at the limit a node sticks.
  EXPECT_DOUBLE_EQ(FrictionBound(0.25, 0.0, -2.0), 0.5);  // Coulomb: -mu lbar_n
  EXPECT_DOUBLE_EQ(FrictionBound(0.0, 0.7, -2.0), 0.7);   // Tresca: the threshold
  EXPECT_DOUBLE_EQ(FrictionBound(0.0, 0.7, -9.0), 0.7);   // whatever the pressure
  EXPECT_FALSE(IsSlip(0.5, FrictionBound(0.25, 0.0, -2.0), 1.0));
  EXPECT_TRUE(IsSlip(0.5 + 1e-12, FrictionBound(0.25, 0.0, -2.0), 1.0));
  EXPECT_TRUE(IsSlip(0.4, FrictionBound(0.25, 0.0, -2.0), 0.75));
  // Without friction a node slips whatever its tangential pressure, zero included: none sticks.
  EXPECT_TRUE(IsSlip(1e-300, FrictionBound(0.0, 0.0, -2.0), 1.0));
  EXPECT_TRUE(IsSlip(0.0, FrictionBound(0.0, 0.0, -2.0), 1.0));
  EXPECT_TRUE(IsSlip(0.0, FrictionBound(0.0, 0.0, -2.0), 0.75));
  EXPECT_FALSE(IsSlip(0.0, FrictionBound(0.0, 1e-300, -2.0), 1.0));  // Tresca, however small the threshold
  EXPECT_EQ(FrictionLimit(FrictionBound(0.25, 0.0, -2.0), Array3(0.0, 0.0, 3.0)), Array3(0.0, 0.0, 0.5));
  EXPECT_EQ(FrictionLimit(0.5, Array3::Zero()), Array3::Zero());
}

// k = 2, eps = 8, c_tau = 0.5 (c_tau eps = 4), mu = 0.25, n = (0, 1, 0): an active node with
// n . lambda = -1 and a closed gap has lbar_n = -2 and the Coulomb limit mu |lbar_n| = 0.5.
struct FrictionalNodes {
  Model model;
  ModelPart& root = model.CreateModelPart("Structure", 3);
  ModelPart* contact = nullptr;
  explicit FrictionalNodes(std::size_t count) {
    for (const VariableData* v : std::initializer_list<const VariableData*>{&VECTOR_LAGRANGE_MULTIPLIER, &WEIGHTED_GAP,
                                                                            &WEIGHTED_SLIP, &NORMAL})
      root.AddNodalSolutionStepVariable(*v);
    contact = &root.CreateSubModelPart("Contact");
    ProcessInfo& info = root.GetProcessInfo();
    info.SetValue(SCALE_FACTOR, 2.0);
    info.SetValue(INITIAL_PENALTY, 8.0);
    info.SetValue(TANGENT_FACTOR, 0.5);
    for (IndexType id = 1; id <= count; ++id) {
      Node& node = contact->CreateNewNode(id, double(id), 0.0, 0.0);
      node.Set(SLAVE, true);
      node.FastGetSolutionStepValue(NORMAL) = Array3(0.0, 1.0, 0.0);
      node.SetValue(FRICTION_COEFFICIENT, 0.25);
    }
  }
  Node& N(IndexType id) { return root.GetNode(id); }
  Eigen::Map<Array3> Lm(IndexType id) { return N(id).FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER); }
  Eigen::Map<Array3> Slip(IndexType id) { return N(id).FastGetSolutionStepValue(WEIGHTED_SLIP); }
  double& Gap(IndexType id) { return N(id).FastGetSolutionStepValue(WEIGHTED_GAP); }
  Array3 Tangent(IndexType id) { return N(id).GetValue(AUGMENTED_TANGENT_CONTACT_PRESSURE); }
  void State(IndexType id, bool active, bool slip) {
    N(id).Set(ACTIVE, active);
    N(id).Set(SLIP, slip);
  }
};

TEST(ActiveSet, AlmFrictionalTransitions) {
  FrictionalNodes s(8);
  s.root.GetProcessInfo().SetValue(SLIP_THRESHOLD, 0.25);
  s.root.GetProcessInfo().SetValue(SLIP_AUGMENTATION_COEFFICIENT, 0.5);  // slip nodes: c_slip c_tau eps = 2
  // 1: inactive -> stick. lbar_n = 8 * -0.25 = -2; lbar_t = 4 * 0.0625 = 0.25 <= 0.5; the multiplier
  // starts from (n lbar_n + lbar_t) / k = (0.125, -1, 0).
  s.Gap(1) = -0.25;
  s.Slip(1) = Array3(0.0625, 0.0, 0.0);
  // 2: stick at the Coulomb limit: k lambda_t + 4 s = 0.25 + 0.25 = 0.5, not above it: stays stick.
  s.State(2, true, false);
  s.Lm(2) = Array3(0.125, -1.0, 0.0);
  s.Slip(2) = Array3(0.0625, 0.0, 0.0);
  // 3: stick -> slip (theta = 1): lbar_t = (0, 0, 0.25) + (0.5, 0, 0), |lbar_t| = 0.559 > 0.5. The
  // stored traction is the limit along lambda_t = (0, 0, 0.125): (0, 0, 0.5).
  s.State(3, true, false);
  s.Lm(3) = Array3(0.0, -1.0, 0.125);
  s.Slip(3) = Array3(0.125, 0.0, 0.0);
  // 4: slipping with |lbar_t| = 0.4 = 0.8 of the limit, above 1 - SLIP_THRESHOLD = 0.75: stays slip.
  s.State(4, true, true);
  s.Lm(4) = Array3(0.2, -1.0, 0.0);
  // 5: slip -> stick below 0.75: lbar_t = 0.25 + 2 * 0.03125 = 0.3125 (0.625 of the limit; with
  // the stick factor 4 it would have been 0.375).
  s.State(5, true, true);
  s.Lm(5) = Array3(0.125, -1.0, 0.0);
  s.Slip(5) = Array3(0.03125, 0.0, 0.0);
  // 6: slipping node that opens (lbar_n = -2 + 8 = 6): deactivates, loses SLIP and its slip.
  s.State(6, true, true);
  s.Lm(6) = Array3(0.5, -1.0, 0.0);
  s.Gap(6) = 1.0;
  s.Slip(6) = Array3(0.5, 0.0, 0.0);
  // 7: master node; 8: ISOLATED and penetrating. Neither is touched.
  s.N(7).Set(SLAVE, false);
  s.Gap(7) = -1.0;
  s.N(8).Set(ISOLATED, true);
  s.Gap(8) = -1.0;

  ChangedNodes changed;
  const SetChanges changes = ComputeALMFrictionalActiveSet(*s.contact, false, 0, &changed);
  EXPECT_EQ(changes.active, 2u);
  EXPECT_EQ(changes.slip, 2u);
  EXPECT_EQ(changed, (ChangedNodes{1, 3, 5, 6}));

  EXPECT_TRUE(s.N(1).Is(ACTIVE));
  EXPECT_FALSE(s.N(1).Is(SLIP));
  EXPECT_EQ(s.Lm(1), Array3(0.125, -1.0, 0.0));
  EXPECT_DOUBLE_EQ(s.N(1).GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), -2.0);
  EXPECT_EQ(s.Tangent(1), Array3(0.25, 0.0, 0.0));

  EXPECT_FALSE(s.N(2).Is(SLIP));
  EXPECT_EQ(s.Tangent(2), Array3(0.5, 0.0, 0.0));

  EXPECT_TRUE(s.N(3).Is(SLIP));
  EXPECT_EQ(s.Tangent(3), Array3(0.0, 0.0, 0.5));
  EXPECT_EQ(s.Lm(3), Array3(0.0, -1.0, 0.125));  // an active node keeps its multiplier

  EXPECT_TRUE(s.N(4).Is(SLIP));
  EXPECT_EQ(s.Tangent(4), Array3(0.5, 0.0, 0.0));

  EXPECT_TRUE(s.N(5).Is(ACTIVE));
  EXPECT_FALSE(s.N(5).Is(SLIP));
  EXPECT_EQ(s.Tangent(5), Array3(0.3125, 0.0, 0.0));

  EXPECT_FALSE(s.N(6).Is(ACTIVE));
  EXPECT_FALSE(s.N(6).Is(SLIP));
  EXPECT_EQ(s.Slip(6), Array3::Zero());
  EXPECT_DOUBLE_EQ(s.N(6).GetValue(AUGMENTED_NORMAL_CONTACT_PRESSURE), 6.0);

  EXPECT_FALSE(s.N(7).Is(ACTIVE));
  EXPECT_FALSE(s.N(7).Has(AUGMENTED_NORMAL_CONTACT_PRESSURE));
  EXPECT_FALSE(s.N(8).Is(ACTIVE));

  // Node 4 alone again, now at 0.7 of the limit: below 0.75, it sticks (node 3, slipping now with
  // the slip factor 2, is kept above the limit); a second pass with the same data changes nothing.
  s.Lm(4) = Array3(0.175, -1.0, 0.0);
  s.Slip(3) = Array3(0.25, 0.0, 0.0);
  EXPECT_EQ(ComputeALMFrictionalActiveSet(*s.contact, false).slip, 1u);
  EXPECT_FALSE(s.N(4).Is(SLIP));
  const SetChanges again = ComputeALMFrictionalActiveSet(*s.contact, false);
  EXPECT_EQ(again.active + again.slip, 0u);
}

TEST(ActiveSet, AlmFrictionalWithoutFrictionOmitsTheTangentialStart) {
  FrictionalNodes s(3);
  for (IndexType id : {1, 2, 3}) s.N(id).SetValue(FRICTION_COEFFICIENT, 0.0);
  // 1: activates with a slip: lambda = n lbar_n / k only; any tangential pressure slips, with a
  // zero traction (the Coulomb limit).
  s.Gap(1) = -0.25;
  s.Slip(1) = Array3(0.0625, 0.0, 0.0);
  // 2: slipping, no tangential pressure at all: nothing holds it, it keeps slipping (issue 12: it
  // used to stick, and the condition then imposed a stick constraint on a frictionless node).
  s.State(2, true, true);
  s.Lm(2) = Array3(0.0, -1.0, 0.0);
  // 3: sticking (e.g. activated with zero slip), no tangential pressure: slips.
  s.State(3, true, false);
  s.Lm(3) = Array3(0.0, -1.0, 0.0);
  const SetChanges changes = ComputeALMFrictionalActiveSet(*s.contact, false);
  EXPECT_EQ(changes.active, 1u);
  EXPECT_EQ(changes.slip, 2u);  // nodes 1 and 3
  EXPECT_EQ(s.Lm(1), Array3(0.0, -1.0, 0.0));
  for (IndexType id : {1, 2, 3}) {
    EXPECT_TRUE(s.N(id).Is(SLIP)) << id;
    EXPECT_EQ(s.Tangent(id), Array3::Zero()) << id;
  }
  // The penalty update decides alike (lbar_n = eps g < 0, lbar_t = c_tau eps s = 0 at node 3).
  s.State(3, true, false);
  s.Gap(3) = -0.25;
  s.Slip(3) = Array3::Zero();
  ComputePenaltyFrictionalActiveSet(*s.contact, false);
  EXPECT_TRUE(s.N(3).Is(SLIP));
}

TEST(ActiveSet, PureSlipKeepsEveryActiveNodeSlippingAndWarns) {
  FrictionalNodes s(2);
  s.Gap(1) = -0.25;  // activates; would stick (0.25 <= 0.5)
  s.Slip(1) = Array3(0.0625, 0.0, 0.0);
  s.State(2, true, true);  // slipping node that would stick
  s.Lm(2) = Array3(0.0, -1.0, 0.0);
  std::vector<std::string> warnings;
  Logger::SetSink([&warnings](Logger::Level level, const std::string& message) {
    if (level == Logger::Level::Warning) warnings.push_back(message);
  });
  const SetChanges quiet = ComputeALMFrictionalActiveSet(*s.contact, true, 0);
  EXPECT_TRUE(warnings.empty());
  const SetChanges loud = ComputeALMFrictionalActiveSet(*s.contact, true, 1);
  Logger::ResetSink();
  EXPECT_EQ(quiet.active, 1u);
  EXPECT_EQ(quiet.slip, 0u);
  EXPECT_EQ(loud.active + loud.slip, 0u);
  EXPECT_TRUE(s.N(1).Is(SLIP));
  EXPECT_TRUE(s.N(2).Is(SLIP));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("slave node 1 would stick"), std::string::npos) << warnings[0];
}

TEST(ActiveSet, PenaltyFrictionalUsesTheGapAndTheSlipOnly) {
  FrictionalNodes s(3);
  // Multipliers play no role. 1: g = -0.25 -> lbar_n = -2, lbar_t = 4 * 0.0625 = 0.25 <= 0.5: stick.
  s.Lm(1) = Array3(10.0, 10.0, 10.0);
  s.Gap(1) = -0.25;
  s.Slip(1) = Array3(0.0625, 0.0, 0.0);
  // 2: active stick, lbar_t = 4 * (0, 0, -0.25) = 1 > 0.5: slips, traction 0.5 along -z.
  s.State(2, true, false);
  s.Gap(2) = -0.25;
  s.Slip(2) = Array3(0.0, 0.0, -0.25);
  // 3: slipping, lbar_t = 0.46875 = 0.94 of the limit: no hysteresis in the penalty test, sticks.
  s.State(3, true, true);
  s.Gap(3) = -0.25;
  s.Slip(3) = Array3(0.1171875, 0.0, 0.0);
  s.root.GetProcessInfo().SetValue(SLIP_THRESHOLD, 0.25);
  const SetChanges changes = ComputePenaltyFrictionalActiveSet(*s.contact, false);
  EXPECT_EQ(changes.active, 1u);
  EXPECT_EQ(changes.slip, 2u);
  EXPECT_TRUE(s.N(1).Is(ACTIVE));
  EXPECT_FALSE(s.N(1).Is(SLIP));
  EXPECT_EQ(s.Lm(1), Array3(10.0, 10.0, 10.0));
  EXPECT_EQ(s.Tangent(1), Array3(0.25, 0.0, 0.0));
  EXPECT_TRUE(s.N(2).Is(SLIP));
  EXPECT_EQ(s.Tangent(2), Array3(0.0, 0.0, -0.5));
  EXPECT_FALSE(s.N(3).Is(SLIP));
  // Opening releases the node and clears its slip.
  s.Gap(2) = 0.125;
  EXPECT_EQ(ComputePenaltyFrictionalActiveSet(*s.contact, false).active, 1u);
  EXPECT_FALSE(s.N(2).Is(ACTIVE));
  EXPECT_FALSE(s.N(2).Is(SLIP));
  EXPECT_EQ(s.Slip(2), Array3::Zero());
}

}  // namespace
}  // namespace mc
