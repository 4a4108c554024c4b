// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (active set): the frictionless NCP (thesis eqs. 4.41-4.44) on hand-made nodes:
// activation, deactivation, initialisation of the multiplier, nodal penalty, change count.
#include <gtest/gtest.h>

#include "core/model/model.h"
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

}  // namespace
}  // namespace mc
