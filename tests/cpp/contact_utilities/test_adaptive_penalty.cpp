// SPDX-License-Identifier: BSD-3-Clause
// Issue 12 (adapt_penalty): the adapted penalty of one node, one test per branch with the value
// worked out by hand (and Kratos' value where ours differs), and the nodal loop (the predicted
// first iterate, answers only from active nodes, nodal area and NODAL_H, master nodes untouched).
#include <gtest/gtest.h>

#include <cmath>

#include "core/model/model.h"
#include "core/variables/kernel_variables.h"
#include "custom_utilities/adaptive_penalty_utilities.h"
#include "custom_utilities/contact_variables.h"

namespace mc {
namespace {

using AdaptivePenaltyUtilities::AdaptedPenalty;

TEST(AdaptivePenalty, BounceFromFarScalesToStopWithinMaxGap) {
  // g_p = -0.02 penetrated, g = 0.01 open, max_gap 1e-3:
  // |100 * -0.02 / 0.01 * (0.01 + 0.001) / (0.01 + 0.02)| = 200 * 0.011 / 0.03 = 73.333...
  EXPECT_NEAR(AdaptedPenalty(100.0, 0.01, -0.02, 1e-3), 200.0 * 0.011 / 0.03, 1e-12);
}

TEST(AdaptivePenalty, BounceFromNearDividesByTen) {
  // |g_p| = 5e-4 <= max_gap, g = 5e-3 open: |100 * 5e-4 / (10 * 5e-3)| = 1.
  EXPECT_NEAR(AdaptedPenalty(100.0, 5e-3, -5e-4, 1e-3), 1.0, 1e-12);
}

TEST(AdaptivePenalty, WithinMaxGapKeepsThePenalty) {
  EXPECT_EQ(AdaptedPenalty(100.0, -8e-4, -6e-4, 1e-3), 100.0);
  EXPECT_EQ(AdaptedPenalty(100.0, 1e-3, 2e-3, 1e-3), 100.0);  // |g| = max_gap is within
  EXPECT_EQ(AdaptedPenalty(100.0, 0.0, 0.0, 1e-3), 100.0);
}

TEST(AdaptivePenalty, SignChangeOfRoundOffGapsKeepsThePenalty) {
  // Kratos: |100 * -2.6e-6 / (10 * 2.2e-10)| = 1.2e5 (and the way back 8.5e-6).
  EXPECT_EQ(AdaptedPenalty(100.0, 2.2e-10, -2.6e-6, 1e-3), 100.0);
  EXPECT_EQ(AdaptedPenalty(100.0, -2.6e-6, 2.2e-10, 1e-3), 100.0);
}

TEST(AdaptivePenalty, OpenNodeKeepsThePenalty) {
  // Open beyond max_gap and not penetrated before: its penalty pushes nothing (Kratos: x 4).
  EXPECT_EQ(AdaptedPenalty(100.0, 2e-3, 0.0, 1e-3), 100.0);
  EXPECT_EQ(AdaptedPenalty(100.0, 8e-3, 5e-4, 1e-3), 100.0);
}

TEST(AdaptivePenalty, PenetrationAfterOpeningGrows) {
  // g_p = 5e-4 open, g = -3e-3: not the crossing formula (Kratos: |100 * 5e-4 / (10 * -3e-3)| =
  // 1.67) but the growth of a penetration: jump 3.5e-3 < 5e-3, |g| < 10 max_gap:
  // 100 (sqrt(3 - 1) + 1)^2 = 100 (3 + 2 sqrt(2)).
  EXPECT_NEAR(AdaptedPenalty(100.0, -3e-3, 5e-4, 1e-3), 100.0 * (3.0 + 2.0 * std::sqrt(2.0)), 1e-9);
  // From far: g_p = 0.02 open, g = -0.01 jumps by 0.03 > 0.02: doubles (Kratos: 73.3).
  EXPECT_EQ(AdaptedPenalty(100.0, -0.01, 0.02, 1e-3), 200.0);
}

TEST(AdaptivePenalty, JumpComparesSizes) {
  // g = -0.02, g_p = -0.012: the change 8e-3 is below |g_p| (Kratos, with signed gaps, takes
  // max(-2e-3, -0.012, 5e-3) and doubles); |g| > 1.01 |g_p|: 2 * 100 * 0.012 / 0.02 = 120.
  EXPECT_NEAR(AdaptedPenalty(100.0, -0.02, -0.012, 1e-3), 120.0, 1e-9);
}

TEST(AdaptivePenalty, JumpDoublesThePenalty) {
  // g = -0.03, g_p = -0.003: |g - g_p| = 0.027 > max(-0.003, -0.003, 5e-3).
  EXPECT_EQ(AdaptedPenalty(100.0, -0.03, -0.003, 1e-3), 200.0);
}

TEST(AdaptivePenalty, SmallPenetrationGrowsWithTheSquaredRoot) {
  // g = -0.005, g_p = -0.004: jump 1e-3 < 5e-3; |g| < 10 max_gap:
  // 100 (sqrt(5 - 1) + 1)^2 = 900.
  EXPECT_NEAR(AdaptedPenalty(100.0, -0.005, -0.004, 1e-3), 900.0, 1e-9);
}

TEST(AdaptivePenalty, LargeGrowingPenetrationScalesByTheGapRatio) {
  // g = -0.0125, g_p = -0.01 (jump 2.5e-3 < 5e-3, |g| > 10 max_gap and > 1.01 |g_p|):
  // 2 * 100 * (-0.01 / -0.0125) = 160.
  EXPECT_NEAR(AdaptedPenalty(100.0, -0.0125, -0.01, 1e-3), 160.0, 1e-9);
}

TEST(AdaptivePenalty, LargeSteadyPenetrationGrowsWithTheRoot) {
  // g = -0.017, g_p = -0.0171 (|g| <= 1.01 |g_p|): 100 (sqrt(17 - 1) + 1) = 500.
  EXPECT_NEAR(AdaptedPenalty(100.0, -0.017, -0.0171, 1e-3), 500.0, 1e-9);
}

struct Interface {
  Model model;
  ModelPart& root = model.CreateModelPart("Structure", 2);
  ModelPart* contact = nullptr;
  Interface() {
    root.AddNodalSolutionStepVariable(WEIGHTED_GAP);
    root.AddNodalSolutionStepVariable(NODAL_H);
    root.SetBufferSize(2);
    contact = &root.CreateSubModelPart("Contact");
    ProcessInfo& info = root.GetProcessInfo();
    info.SetValue(INITIAL_PENALTY, 100.0);
    info.SetValue(MAX_GAP_FACTOR, 1e-3);
    for (IndexType id = 1; id <= 3; ++id) {
      Node& node = contact->CreateNewNode(id, double(id), 0.0, 0.0);
      node.Set(SLAVE, id != 3);  // 3 is a master node
      node.FastGetSolutionStepValue(NODAL_H) = 2.0;
      node.SetValue(NODAL_AREA, 0.5);
      node.SetValue(INITIAL_PENALTY, 7.0);
    }
  }
  Node& N(IndexType id) { return root.GetNode(id); }
  // Mean gaps g (now) and g_p (buffer 1), weighted with the nodal area 0.5.
  void Gaps(IndexType id, double gap, double previous_gap) {
    N(id).FastGetSolutionStepValue(WEIGHTED_GAP) = 0.5 * gap;
    N(id).FastGetSolutionStepValue(WEIGHTED_GAP, 1) = 0.5 * previous_gap;
  }
};

TEST(AdaptivePenalty, FirstIterationStartsFromTheProcessInfoPenaltyAndAdaptsNothing) {
  // The first iterate is the scheme's prediction: no solve answered the penalty yet.
  Interface s;
  s.root.GetProcessInfo().SetValue(STEP, 1);
  s.root.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 1);
  s.N(1).Set(ACTIVE);
  s.Gaps(1, -0.06, -0.006);  // max_gap = 1e-3 x NODAL_H 2 = 2e-3: would double
  s.Gaps(3, -0.06, -0.006);  // master: untouched
  AdaptivePenaltyUtilities::AdaptNodalPenalties(*s.contact);
  EXPECT_EQ(s.N(1).GetValue(INITIAL_PENALTY), 100.0);
  EXPECT_EQ(s.N(2).GetValue(INITIAL_PENALTY), 100.0);
  EXPECT_EQ(s.N(3).GetValue(INITIAL_PENALTY), 7.0);
}

TEST(AdaptivePenalty, SecondIterationComparesWithTheLastConvergedGap) {
  Interface s;
  ProcessInfo& info = s.root.GetProcessInfo();
  info.SetValue(STEP, 3);
  info.SetValue(NL_ITERATION_NUMBER, 1);
  s.N(1).Set(ACTIVE);  // node 2 is inactive in the first solve
  // Step start: buffer 1 holds the last step's converged gap, buffer 0 the predicted one.
  s.Gaps(1, 0.05, -0.009);
  s.Gaps(2, 0.05, -0.009);
  AdaptivePenaltyUtilities::AdaptNodalPenalties(*s.contact);
  EXPECT_EQ(s.N(1).GetValue(INITIAL_PENALTY), 7.0);
  // Iteration 2: PostCriteria copied the predicted gap into buffer 1. Node 1 is compared with
  // -0.009: 7 (sqrt(5 - 1) + 1)^2 = 63 (Kratos: a sign change from 0.05, 7 * 0.05 / 0.01 *
  // 0.012 / 0.06 = 7). Node 2's penetration answers no penalty; it is active from now on.
  s.N(2).Set(ACTIVE);
  info.SetValue(NL_ITERATION_NUMBER, 2);
  s.Gaps(1, -0.01, 0.05);
  s.Gaps(2, -0.01, 0.05);
  AdaptivePenaltyUtilities::AdaptNodalPenalties(*s.contact);
  EXPECT_NEAR(s.N(1).GetValue(INITIAL_PENALTY), 63.0, 1e-12);
  EXPECT_EQ(s.N(2).GetValue(INITIAL_PENALTY), 7.0);
  // Iteration 3: node 1, 63 (sqrt(5.5 - 1) + 1)^2; node 2 answers now, compared with its last
  // answer, -0.009: the change 0.021 > max(3e-3, 9e-3, 0.01) doubles.
  info.SetValue(NL_ITERATION_NUMBER, 3);
  s.Gaps(1, -0.011, -0.01);
  s.Gaps(2, -0.03, -0.01);
  AdaptivePenaltyUtilities::AdaptNodalPenalties(*s.contact);
  EXPECT_NEAR(s.N(1).GetValue(INITIAL_PENALTY), 63.0 * std::pow(std::sqrt(4.5) + 1.0, 2), 1e-9);
  EXPECT_EQ(s.N(2).GetValue(INITIAL_PENALTY), 14.0);
}

TEST(AdaptivePenalty, NodeWithoutAreaKeepsItsPenalty) {
  Interface s;
  s.root.GetProcessInfo().SetValue(STEP, 2);
  s.N(1).SetValue(NODAL_AREA, 0.0);
  s.Gaps(1, -0.06, -0.006);
  AdaptivePenaltyUtilities::AdaptNodalPenalties(*s.contact);
  EXPECT_EQ(s.N(1).GetValue(INITIAL_PENALTY), 7.0);
}

}  // namespace
}  // namespace mc
