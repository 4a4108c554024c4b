// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (solving): the arithmetic of the displacement and residual criteria (over free DoFs,
// relative OR absolute), r0 taken at the first check of each step, And/Or combinations, the
// spec names and defaults, and the readable log line.
#include <gtest/gtest.h>

#include <cmath>

#include "core/solving/and_criteria.h"
#include "core/solving/displacement_criteria.h"
#include "core/solving/or_criteria.h"
#include "core/solving/residual_criteria.h"
#include "core/utilities/logger.h"
#include "core/variables/kernel_variables.h"
#include "test_elements.h"

namespace mc {
namespace {

// Three DoFs with values (3, 4, 100); the third is fixed and must be ignored.
struct ThreeDofs {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  std::vector<Dof*> dofs;
  SparseMatrix A;
  ThreeDofs() {
    const double values[3] = {3.0, 4.0, 100.0};
    for (IndexType i = 1; i <= 3; ++i) {
      Node& n = test::AddNode(mp, i, 0.0, 0.0);
      n.FastGetSolutionStepValue(DISPLACEMENT_X) = values[i - 1];
      Dof& d = n.GetDof(DISPLACEMENT_X);
      d.equation_id = static_cast<std::int64_t>(i - 1);
      dofs.push_back(&d);
    }
    mp.GetNode(3).Fix(DISPLACEMENT_X);
  }
};

Vector Vec(double a, double b, double c) { return (Vector(3) << a, b, c).finished(); }

TEST(DisplacementCriteria, RelativeOrAbsoluteOverFreeDofs) {
  ThreeDofs s;
  const Vector dx = Vec(0.3, 0.4, 50.0);
  DisplacementCriteria loose(0.2, 1e-9);
  EXPECT_TRUE(loose.PostCriteria(s.mp, s.dofs, s.A, dx, dx));
  const auto v = loose.LastValues();
  EXPECT_DOUBLE_EQ(v[0].value, 0.1);
  EXPECT_DOUBLE_EQ(v[1].value, 0.5 / std::sqrt(2.0));
  EXPECT_TRUE(DisplacementCriteria(0.05, 0.36).PostCriteria(s.mp, s.dofs, s.A, dx, dx));
  EXPECT_FALSE(DisplacementCriteria(0.05, 0.35).PostCriteria(s.mp, s.dofs, s.A, dx, dx));
  DisplacementCriteria defaults;
  EXPECT_EQ(defaults.Name(), "displacement_criterion");
  EXPECT_DOUBLE_EQ(defaults.RelativeTolerance(), 1e-4);
  EXPECT_DOUBLE_EQ(defaults.AbsoluteTolerance(), 1e-9);
}

TEST(ResidualCriteria, RatioToTheFirstResidualOfTheStep) {
  ThreeDofs s;
  const Vector dx = Vector::Zero(3);
  ResidualCriteria c(0.1, 1e-12);
  EXPECT_EQ(c.Name(), "residual_criterion");
  c.InitializeSolutionStep(s.mp, s.dofs, s.A, dx, dx);
  EXPECT_FALSE(c.PostCriteria(s.mp, s.dofs, s.A, dx, Vec(3.0, 4.0, 1e6)));
  EXPECT_DOUBLE_EQ(c.InitialResidualNorm(), 5.0);
  EXPECT_DOUBLE_EQ(c.LastValues()[0].value, 1.0);
  EXPECT_TRUE(c.PostCriteria(s.mp, s.dofs, s.A, dx, Vec(0.3, 0.4, 1e6)));
  EXPECT_NEAR(c.LastValues()[0].value, 0.1, 1e-15);
  EXPECT_DOUBLE_EQ(c.LastValues()[1].value, 0.5 / std::sqrt(2.0));
  c.InitializeSolutionStep(s.mp, s.dofs, s.A, dx, dx);
  EXPECT_FALSE(c.PostCriteria(s.mp, s.dofs, s.A, dx, Vec(0.3, 0.4, 0.0)));  // new r0
  EXPECT_DOUBLE_EQ(c.InitialResidualNorm(), 0.5);
}

TEST(CombinedCriteria, AndNeedsBothOrNeedsOne) {
  ThreeDofs s;
  const Vector dx = Vec(0.3, 0.4, 0.0);
  const Vector b = Vec(3.0, 4.0, 0.0);
  auto passes = std::make_shared<DisplacementCriteria>(0.2, 1e-9);  // ratio 0.1
  auto fails = std::make_shared<ResidualCriteria>(1e-4, 1e-9);      // first check: ratio 1
  AndCriteria both(passes, fails);
  OrCriteria either(passes, fails);
  EXPECT_EQ(both.Name(), "and_criterion");
  EXPECT_EQ(either.Name(), "or_criterion");
  EXPECT_FALSE(both.PostCriteria(s.mp, s.dofs, s.A, dx, b));
  EXPECT_TRUE(either.PostCriteria(s.mp, s.dofs, s.A, dx, b));
  EXPECT_EQ(both.LastValues().size(), 4u);
  EXPECT_EQ(both.LastValues()[2].name, "|r|/|r0|");
}

TEST(ConvergenceCriteria, LogLineNamesMeasuresAndTolerances) {
  ThreeDofs s;
  s.mp.GetProcessInfo().SetValue(NL_ITERATION_NUMBER, 3);
  std::vector<std::string> lines;
  Logger::SetSink([&](Logger::Level, const std::string& m) { lines.push_back(m); });
  DisplacementCriteria c(0.2, 1e-9);
  c.SetEchoLevel(1);
  const Vector dx = Vec(0.3, 0.4, 0.0);
  c.PostCriteria(s.mp, s.dofs, s.A, dx, dx);
  Logger::ResetSink();
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "  it 3  |du|/|u| = 1.0e-01 (tol 2e-01)  |du| = 3.5e-01 (tol 1e-09)  converged");
}

}  // namespace
}  // namespace mc
