// SPDX-License-Identifier: BSD-3-Clause
// Issue 14, item 3: the static scheme's extrapolating predictor. Free DoFs start a step from
// u_n + (dt_{n+1} / dt_n) (u_n - u_{n-1}); fixed DoFs keep their imposed value; the first step
// and the plain scheme keep the last values; the buffer must hold 3 steps.
#include <gtest/gtest.h>

#include <string>

#include "core/solving/residual_based_incremental_update_static_scheme.h"
#include "core/utilities/error.h"
#include "core/variables/kernel_variables.h"
#include "test_elements.h"

namespace mc {
namespace {

struct TwoNodes {
  Model model;
  ModelPart& mp;
  Scheme::DofsArray dofs;
  explicit TwoNodes(int buffer_size = 3) : mp(test::MakeModelPart(model, buffer_size)) {
    test::AddNode(mp, 1, 0.0, 0.0);
    test::AddNode(mp, 2, 1.0, 0.0);
    mp.GetNode(1).Fix(DISPLACEMENT_X);
    dofs = {&mp.GetNode(1).GetDof(DISPLACEMENT_X), &mp.GetNode(2).GetDof(DISPLACEMENT_X)};
  }
  double& U(IndexType node) { return mp.GetNode(node).FastGetSolutionStepValue(DISPLACEMENT_X); }
  // Converges a step to the given values (what a Newton loop would leave).
  void Step(double time, double u1, double u2) {
    mp.CloneTimeStep(time);
    U(1) = u1;
    U(2) = u2;
  }
};

TEST(StaticPredictor, ExtrapolatesTheFreeDofsWithTheTimeStepRatio) {
  TwoNodes t;
  ResidualBasedIncrementalUpdateStaticScheme scheme(true);
  t.Step(1.0, 0.1, 0.5);
  t.Step(1.5, 0.2, 0.7);    // dt_n = 0.5
  t.mp.CloneTimeStep(2.5);  // dt_{n+1} = 1.0: ratio 2
  t.U(1) = 0.4;             // the Dirichlet value a process imposes for the step
  scheme.Predict(t.mp, t.dofs);
  EXPECT_DOUBLE_EQ(t.U(2), 0.7 + 2.0 * (0.7 - 0.5));
  EXPECT_DOUBLE_EQ(t.U(1), 0.4);  // fixed: kept
  EXPECT_DOUBLE_EQ(t.mp.GetProcessInfo().GetValue(PREVIOUS_DELTA_TIME), 0.5);
}

TEST(StaticPredictor, FirstStepAndPlainSchemeKeepTheLastValues) {
  TwoNodes t;
  t.U(2) = 0.3;  // an initial state
  ResidualBasedIncrementalUpdateStaticScheme extrapolating(true);
  t.mp.CloneTimeStep(1.0);
  extrapolating.Predict(t.mp, t.dofs);  // no step before the first one
  EXPECT_DOUBLE_EQ(t.U(2), 0.3);
  t.U(2) = 0.5;
  t.mp.CloneTimeStep(2.0);
  ResidualBasedIncrementalUpdateStaticScheme plain;
  plain.Predict(t.mp, t.dofs);
  EXPECT_DOUBLE_EQ(t.U(2), 0.5);
  extrapolating.Predict(t.mp, t.dofs);
  EXPECT_DOUBLE_EQ(t.U(2), 0.7);
}

TEST(StaticPredictor, NeedsThreeBufferSteps) {
  TwoNodes t(2);
  ResidualBasedIncrementalUpdateStaticScheme plain;
  EXPECT_NO_THROW(plain.Check(t.mp));
  ResidualBasedIncrementalUpdateStaticScheme extrapolating(true);
  try {
    extrapolating.Check(t.mp);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has buffer_size 2, it needs 3"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mc
