// SPDX-License-Identifier: BSD-3-Clause
// Issue 12 (adapt_penalty): the adapted penalty of one node, one test per branch with the value
// worked out by hand, and the nodal loop (first iteration of the run, nodal values, nodal area and
// NODAL_H, master nodes untouched).
#include <gtest/gtest.h>

#include <cmath>

#include "core/model/model.h"
#include "core/variables/kernel_variables.h"
#include "custom_utilities/adaptive_penalty_utilities.h"
#include "custom_utilities/contact_variables.h"

namespace mc {
namespace {

using AdaptivePenaltyUtilities::AdaptedPenalty;

TEST(AdaptivePenalty, SignChangeFromFarScalesToStopWithinMaxGap) {
  // g_p = 0.02 open, g = -0.01 penetrated, max_gap 1e-3:
  // |100 * 0.02 / -0.01 * (0.01 + 0.001) / (-0.01 - 0.02)| = 200 * 0.011 / 0.03 = 73.333...
  EXPECT_NEAR(AdaptedPenalty(100.0, -0.01, 0.02, 1e-3), 200.0 * 0.011 / 0.03, 1e-12);
  // The same from penetration to open.
  EXPECT_NEAR(AdaptedPenalty(100.0, 0.01, -0.02, 1e-3), 200.0 * 0.011 / 0.03, 1e-12);
}

TEST(AdaptivePenalty, SignChangeFromNearDividesByTen) {
  // |g_p| = 5e-4 <= max_gap: |100 * 5e-4 / (10 * -1e-3)| = 5.
  EXPECT_NEAR(AdaptedPenalty(100.0, -1e-3, 5e-4, 1e-3), 5.0, 1e-12);
}

TEST(AdaptivePenalty, WithinMaxGapKeepsThePenalty) {
  EXPECT_EQ(AdaptedPenalty(100.0, -8e-4, -6e-4, 1e-3), 100.0);
  EXPECT_EQ(AdaptedPenalty(100.0, 1e-3, 2e-3, 1e-3), 100.0);  // |g| = max_gap is within
  EXPECT_EQ(AdaptedPenalty(100.0, 0.0, 0.0, 1e-3), 100.0);
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

TEST(AdaptivePenalty, FirstIterationStartsFromTheProcessInfoPenalty) {
  Interface s;
  s.root.GetProcessInfo().SetValue(STEP, 1);
  s.root.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 1);
  s.Gaps(1, -0.06, -0.006);  // a jump with max_gap = 1e-3 x NODAL_H 2 = 2e-3: doubles
  s.Gaps(2, -1e-3, -1e-3);   // within max_gap: keeps
  s.Gaps(3, -0.06, -0.006);  // master: untouched
  AdaptivePenaltyUtilities::AdaptNodalPenalties(*s.contact);
  EXPECT_EQ(s.N(1).GetValue(INITIAL_PENALTY), 200.0);
  EXPECT_EQ(s.N(2).GetValue(INITIAL_PENALTY), 100.0);
  EXPECT_EQ(s.N(3).GetValue(INITIAL_PENALTY), 7.0);
}

TEST(AdaptivePenalty, LaterIterationsStartFromTheNodalPenalty) {
  Interface s;
  s.root.GetProcessInfo().SetValue(STEP, 1);
  s.root.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 2);
  s.Gaps(1, -0.06, -0.006);
  // max_gap = 2e-3: g = -0.01, g_p = -0.009 -> 7 (sqrt(5 - 1) + 1)^2 = 63.
  s.Gaps(2, -0.01, -0.009);
  AdaptivePenaltyUtilities::AdaptNodalPenalties(*s.contact);
  EXPECT_EQ(s.N(1).GetValue(INITIAL_PENALTY), 14.0);
  EXPECT_NEAR(s.N(2).GetValue(INITIAL_PENALTY), 63.0, 1e-12);
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
