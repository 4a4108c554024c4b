// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (solving): Newton-Raphson converges quadratically with an exact tangent, the line
// search helps where plain Newton struggles, the iteration history keeps the norms when a
// step does not converge, the residual criterion needs two iterations on a linear problem.
#include <gtest/gtest.h>

#include <cmath>

#include "core/linear_solvers/umfpack_solver.h"
#include "core/solving/block_builder_and_solver.h"
#include "core/solving/displacement_criteria.h"
#include "core/solving/elimination_builder_and_solver.h"
#include "core/solving/line_search_strategy.h"
#include "core/solving/newton_raphson_strategy.h"
#include "core/solving/residual_based_incremental_update_static_scheme.h"
#include "core/solving/residual_criteria.h"
#include "core/variables/kernel_variables.h"
#include "test_elements.h"

namespace mc {
namespace {

// One cubic spring 1-2 (N = k e + c e^3), node 1 fixed, force F at node 2.
struct CubicSpring {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  CubicSpring(double k, double c, double force) {
    test::AddNode(mp, 1, 0.0, 0.0);
    test::AddNode(mp, 2, 1.0, 0.0);
    test::AddSpring(mp, 1, 1, 2, k, c);
    test::AddLoad(mp, 1, 2, force);
    mp.GetNode(1).Fix(DISPLACEMENT_X);
  }
  double U() const { return mp.GetNode(2).FastGetSolutionStepValue(DISPLACEMENT_X); }
};

// Root of k u + c u^3 = F by bisection (independent of the code under test).
double CubicRoot(double k, double c, double force) {
  double lo = 0.0, hi = force / k;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (k * mid + c * mid * mid * mid > force ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

std::shared_ptr<BuilderAndSolver> Block() {
  return std::make_shared<BlockBuilderAndSolver>(std::make_shared<UmfpackSolver>());
}

TEST(NewtonRaphson, CubicSpringConvergesQuadratically) {
  CubicSpring s(1.0, 1.0, 10.0);
  NewtonRaphsonStrategy strategy(s.mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                 std::make_shared<DisplacementCriteria>(1e-14, 0.0), Block(), 30);
  ASSERT_TRUE(strategy.Solve());
  const double exact = CubicRoot(1.0, 1.0, 10.0);
  EXPECT_NEAR(s.U(), exact, 1e-13);
  // e_k ~ |du_{k+1}|: the ratio |du_{k+1}| / |du_k|^2 tends to |f''/(2 f')| = 3u/(1+3u^2) ~ 0.46.
  const auto& h = strategy.IterationHistory();
  int checked = 0;
  for (std::size_t k = 0; k + 1 < h.size(); ++k) {
    const double e = h[k].increment_norm;
    if (e > 0.5 || e < 1e-7) continue;
    const double ratio = h[k + 1].increment_norm / (e * e);
    EXPECT_GT(ratio, 0.01) << "iteration " << h[k].iteration;
    EXPECT_LT(ratio, 100.0) << "iteration " << h[k].iteration;
    ++checked;
  }
  EXPECT_GE(checked, 2);
}

// UMFPACK standing in for a Krylov solver that accepts a forcing term: it records the tolerances.
class ForcingRecorder : public UmfpackSolver {
 public:
  void SetForcingTerm(double eta) override { eta_ = eta; }
  double LastTolerance() const override { return eta_; }

 private:
  double eta_ = 0.0;
};

TEST(NewtonRaphson, TheFirstSolvesOfAStepAreAskedForTheLooseToleranceTheLaterOnesForTheSolvers) {
  CubicSpring s(1.0, 1.0, 10.0);
  NewtonRaphsonStrategy strategy(s.mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                 std::make_shared<DisplacementCriteria>(1e-14, 0.0),
                                 std::make_shared<BlockBuilderAndSolver>(std::make_shared<ForcingRecorder>()), 30);
  ASSERT_TRUE(strategy.Solve());
  const auto& h = strategy.IterationHistory();
  ASSERT_GT(h.size(), static_cast<std::size_t>(ForcingTerm::kLooseSolves));
  for (const IterationRecord& record : h) {
    EXPECT_EQ(record.linear_tolerance, record.iteration <= ForcingTerm::kLooseSolves ? ForcingTerm::kLoose : 0.0)
        << record.iteration;
    EXPECT_EQ(record.linear_iterations, 1);
  }
}

TEST(NewtonRaphson, ADirectSolveRecordsNoTolerance) {
  CubicSpring s(1.0, 1.0, 10.0);
  NewtonRaphsonStrategy strategy(s.mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                 std::make_shared<DisplacementCriteria>(1e-14, 0.0), Block(), 30);
  ASSERT_TRUE(strategy.Solve());
  for (const IterationRecord& record : strategy.IterationHistory()) EXPECT_EQ(record.linear_tolerance, 0.0);
}

TEST(ForcingTerm, LooseForTheFirstSolvesOfALoop) {
  const ForcingTerm forcing(2, 1e-5);
  EXPECT_EQ(forcing.ForIteration(1), 1e-5);
  EXPECT_EQ(forcing.ForIteration(2), 1e-5);
  EXPECT_EQ(forcing.ForIteration(3), 0.0);  // the solver's own tolerance
}

TEST(NewtonRaphson, ResidualCriterionNeedsTwoIterationsOnALinearProblem) {
  CubicSpring s(4.0, 0.0, 2.0);
  NewtonRaphsonStrategy strategy(s.mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                 std::make_shared<ResidualCriteria>(), Block());
  ASSERT_TRUE(strategy.Solve());
  ASSERT_EQ(strategy.IterationHistory().size(), 2u);
  EXPECT_DOUBLE_EQ(strategy.IterationHistory()[0].residual_norm, 2.0);
  EXPECT_LT(strategy.IterationHistory()[1].residual_norm, 1e-14);
  EXPECT_DOUBLE_EQ(s.U(), 0.5);
  EXPECT_NEAR(s.mp.GetNode(1).FastGetSolutionStepValue(REACTION_X), -2.0, 1e-14);
}

TEST(NewtonRaphson, NonConvergenceReturnsFalseAndKeepsNorms) {
  CubicSpring s(1.0, 1.0, 1e6);
  NewtonRaphsonStrategy strategy(s.mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                 std::make_shared<DisplacementCriteria>(1e-10, 1e-14), Block(), 3);
  EXPECT_FALSE(strategy.Solve());
  const auto& h = strategy.IterationHistory();
  ASSERT_EQ(h.size(), 3u);
  EXPECT_DOUBLE_EQ(h[0].residual_norm, 1e6);
  EXPECT_DOUBLE_EQ(h[0].increment_norm, 1e6);  // first tangent is k = 1
  for (const auto& r : h) {
    EXPECT_FALSE(r.converged);
    ASSERT_EQ(r.criteria.size(), 2u);
    EXPECT_EQ(r.criteria[0].name, "|du|/|u|");
    EXPECT_GT(r.criteria[0].value, 1e-10);
  }
}

// Counts the local systems requested from the entities, with and without the LHS.
class CountingScheme : public ResidualBasedIncrementalUpdateStaticScheme {
 public:
  void CalculateSystemContributions(Entity& e, Matrix& lhs, Vector& rhs, EquationIdVectorType& ids,
                                    const ProcessInfo& info) override {
#pragma omp atomic
    ++full;
    ResidualBasedIncrementalUpdateStaticScheme::CalculateSystemContributions(e, lhs, rhs, ids, info);
  }
  void CalculateRHSContribution(Entity& e, Vector& rhs, EquationIdVectorType& ids, const ProcessInfo& info) override {
#pragma omp atomic
    ++rhs_only;
    ResidualBasedIncrementalUpdateStaticScheme::CalculateRHSContribution(e, rhs, ids, info);
  }
  int full = 0;
  int rhs_only = 0;
};

TEST(NewtonRaphson, OldStiffnessInFirstIterationSkipsTheFirstMatrixBuild) {
  CubicSpring s(1.0, 1.0, 2.0);
  auto scheme = std::make_shared<CountingScheme>();
  NewtonRaphsonStrategy strategy(s.mp, scheme, std::make_shared<DisplacementCriteria>(1e-12, 0.0), Block(), 30, false,
                                 false, true, true);
  ASSERT_TRUE(strategy.Solve());
  EXPECT_EQ(scheme->rhs_only, 0);  // no previous matrix in the first step
  EXPECT_EQ(scheme->full, 2 * static_cast<int>(strategy.IterationHistory().size()));  // spring + load
  static_cast<test::TestLoad&>(*s.mp.Conditions()[0]).SetForce(10.0);
  s.mp.CloneTimeStep(2.0);
  scheme->full = 0;
  ASSERT_TRUE(strategy.Solve());
  EXPECT_NEAR(s.U(), CubicRoot(1.0, 1.0, 10.0), 1e-12);
  EXPECT_EQ(scheme->rhs_only, 2);
  EXPECT_EQ(scheme->full, 2 * (static_cast<int>(strategy.IterationHistory().size()) - 1));
  EXPECT_NEAR(strategy.IterationHistory()[0].residual_norm, 8.0, 1e-10);
}

TEST(LineSearch, NeedsFewerIterationsOnAStiffeningSpring) {
  const double exact = CubicRoot(1.0, 1.0, 1e6);
  CubicSpring plain(1.0, 1.0, 1e6);
  NewtonRaphsonStrategy newton(plain.mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                               std::make_shared<DisplacementCriteria>(1e-12, 0.0), Block(), 100);
  ASSERT_TRUE(newton.Solve());
  CubicSpring searched(1.0, 1.0, 1e6);
  // With the default tolerance 0.5 the full step is accepted as soon as it halves phi; ask
  // for a near-exact line search so that the search reaches max_alpha.
  LineSearchSettings settings;
  settings.line_search_tolerance = 1e-3;
  settings.max_line_search_iterations = 10;
  LineSearchStrategy line_search(searched.mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                 std::make_shared<DisplacementCriteria>(1e-12, 0.0),
                                 std::make_shared<EliminationBuilderAndSolver>(std::make_shared<UmfpackSolver>()),
                                 settings, 100);
  ASSERT_TRUE(line_search.Solve());
  EXPECT_NEAR(plain.U(), exact, 1e-10 * exact);
  EXPECT_NEAR(searched.U(), exact, 1e-10 * exact);
  const auto n_newton = newton.IterationHistory().size();
  const auto n_search = line_search.IterationHistory().size();
  EXPECT_LE(n_search + 10, n_newton) << "Newton " << n_newton << ", line search " << n_search;
  EXPECT_LT(line_search.IterationHistory()[0].step_length, 1.0);
  EXPECT_NEAR(searched.mp.GetNode(1).FastGetSolutionStepValue(REACTION_X), -1e6, 1e-3);
}

TEST(LineSearch, ExactLineSearchOnAQuadraticEnergyKeepsTheNewtonStep) {
  CubicSpring s(3.0, 0.0, 6.0);
  LineSearchStrategy strategy(s.mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                              std::make_shared<DisplacementCriteria>(), Block());
  ASSERT_TRUE(strategy.Solve());
  EXPECT_NEAR(s.U(), 2.0, 1e-14);
  EXPECT_NEAR(strategy.IterationHistory()[0].step_length, 1.0, 1e-12);
}

}  // namespace
}  // namespace mc
