// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (contact strategies): the semi-smooth Newton strategy on a node pushed into a rigid
// circular obstacle (scalar ALM, exact tangent) reaches the exact contact point and force,
// settles the active set and converges quadratically once the set is fixed; the simplified
// variant converges too; a node whose state keeps switching is named in the failure; the
// split line search uses different step lengths and converges where Newton diverges; the
// adaptive strategy splits a step that does not converge and fails clearly when splitting
// does not help.
#include <gtest/gtest.h>

#include <cmath>

#include "contact_test_problem.h"
#include "core/linear_solvers/umfpack_solver.h"
#include "core/solving/block_builder_and_solver.h"
#include "core/solving/residual_based_incremental_update_static_scheme.h"
#include "core/variables/kernel_variables.h"
#include "custom_strategies/custom_convergencecriterias/alm_frictionless_mortar_criteria.h"
#include "custom_strategies/custom_convergencecriterias/block_contact_criteria.h"
#include "custom_strategies/custom_convergencecriterias/mortar_and_criteria.h"
#include "custom_strategies/custom_strategies/line_search_contact_strategy.h"
#include "custom_strategies/custom_strategies/residualbased_newton_raphson_contact_strategy.h"
#include "custom_utilities/contact_variables.h"
#include "tests/cpp/common/error_message.h"

namespace mc {
namespace {

using test::AnchorSpring;
using test::ContactProblem;
using test::Obstacle;

std::shared_ptr<MortarAndConvergenceCriteria> Criteria(ContactProblem& p, double tolerance = 1e-12) {
  auto mechanical = std::make_shared<DisplacementLagrangeMultiplierContactCriteria>(Parameters(
      Concat(R"({"displacement_relative_tolerance": )", tolerance, R"(, "displacement_absolute_tolerance": 0.0,
          "contact_displacement_relative_tolerance": )",
             tolerance, R"(, "contact_displacement_absolute_tolerance": 0.0})")));
  auto mortar = std::make_shared<ALMFrictionlessMortarConvergenceCriteria>();
  auto criteria = std::make_shared<MortarAndConvergenceCriteria>(mechanical, mortar);
  criteria->SetMortarUpdater(p.Updater());
  return criteria;
}

ContactStrategySettings Defaults() { return ResidualBasedNewtonRaphsonContactStrategy::ReadSettings(Parameters()); }

template <class Strategy = ResidualBasedNewtonRaphsonContactStrategy, class... Args>
std::unique_ptr<Strategy> MakeStrategy(ContactProblem& p, ContactStrategySettings settings, int max_iteration,
                                       std::shared_ptr<ConvergenceCriteria> criteria, Args... args) {
  auto s = std::make_unique<Strategy>(p.mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                      std::move(criteria),
                                      std::make_shared<BlockBuilderAndSolver>(std::make_shared<UmfpackSolver>()),
                                      settings, max_iteration, true, false, true, args...);
  s->SetMortarUpdater(p.Updater());
  return s;
}

// Node at the origin, linear anisotropic anchor K = diag(1, 3), load F = (2, 0): the free
// position (2, 0) lies inside the circle c = (2.3, 0.6), R = 1, so the node stops on the circle
// where the energy 1/2 u.K u - F.u is least (found here by bisection on the circle's angle), and
// the contact pressure balances the spring: lambda_bar = n . (F - K u), lambda = lambda_bar / k.
struct Hit {
  Array3 c{2.3, 0.6, 0.0};
  double R = 1.0;
  Array3 F{2.0, 0.0, 0.0};
  Array3 K{1.0, 3.0, 0.0};
  double k = 2.0;
  double eps = 1.0;
  Array3 OnCircle(double theta) const { return c + R * Array3(std::cos(theta), std::sin(theta), 0.0); }
  // dE/dtheta of the energy 1/2 u.K u - F.u on the circle (u = x, the node starts at 0).
  double Slope(double theta) const {
    const Array3 x = OnCircle(theta);
    return (K.cwiseProduct(x) - F).dot(R * Array3(-std::sin(theta), std::cos(theta), 0.0));
  }
  Array3 ExactPosition() const {
    // Bisection on the slope around the direction of the free position: machine precision.
    const Array3 p = F.cwiseQuotient(Array3(K[0], K[1], 1.0));
    double lo = std::atan2(p[1] - c[1], p[0] - c[0]) - 1.0, hi = lo + 2.0;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (Slope(mid) > 0.0 ? hi : lo) = mid;
    }
    return OnCircle(0.5 * (lo + hi));
  }
  double ExactPressure() const {
    const Array3 x = ExactPosition();
    return (x - c).normalized().dot(F - K.cwiseProduct(x)) / k;
  }
  void Add(ContactProblem& p, IndexType id = 1) const {
    p.AddContactNode(id, Array3::Zero(), K, AnchorSpring::Law::kLinear, F, Obstacle{c, R});
  }
  // The exact position and pressure at node `id` of `p`, to 1e-12.
  void ExpectSolution(const ContactProblem& p, IndexType id = 1) const {
    const Array3 x = ExactPosition();
    EXPECT_NEAR(p.U(id)[0], x[0], 1e-12);
    EXPECT_NEAR(p.U(id)[1], x[1], 1e-12);
    EXPECT_NEAR(p.Lm(id), ExactPressure(), 1e-12);
  }
};

// The Hit problem at node 1 solved with the full (`interaction`) or the simplified semi-smooth
// Newton: either way the exact solution, the node activated once, after the first (separated)
// iteration, and never again, in one inner loop.
struct SolvedHit {
  Hit hit;
  ContactProblem p{hit.k, hit.eps};
  std::unique_ptr<ResidualBasedNewtonRaphsonContactStrategy> strategy;
  explicit SolvedHit(bool interaction) {
    hit.Add(p);
    p.mp.Set(INTERACTION, interaction);
    strategy = MakeStrategy(p, Defaults(), 30, Criteria(p));
    EXPECT_TRUE(strategy->Solve()) << strategy->FailureReport();
    hit.ExpectSolution(p);
    EXPECT_EQ(strategy->ActiveSetFlipCounts().at(1), 1);
    EXPECT_EQ(strategy->InnerLoopIterations(), 1);
  }
};

TEST(ContactNewton, FullSemiSmoothNewtonFindsTheExactContactAndConvergesQuadratically) {
  SolvedHit s(true);
  const Array3 x = s.hit.ExactPosition();
  // The pressure is compressive and the energy search found a point on the circle.
  EXPECT_LT(s.p.Lm(1), -0.1);
  EXPECT_NEAR((x - s.hit.c).norm(), s.hit.R, 1e-14);
  EXPECT_TRUE(s.p.mp.GetNode(1).Is(ACTIVE));
  EXPECT_TRUE(s.p.mp.GetProcessInfo().GetValue(ACTIVE_SET_CONVERGED));

  // Quadratic rate with the set fixed (iterations >= 2): |dx_{k+1}| / |dx_k|^2 stays of order 1
  // while |dx| drops from 0.3 to 1e-10.
  const auto& h = s.strategy->IterationHistory();
  ASSERT_GE(h.size(), 4u);
  int checked = 0;
  for (std::size_t i = 1; i + 1 < h.size(); ++i) {
    const double e = h[i].increment_norm;
    const double next = h[i + 1].increment_norm;
    if (e > 0.3 || e < 1e-7) continue;
    // Measured: 0.82, 0.93, 0.92, 0.99 (|dx| = 0.30, 7.2e-2, 4.8e-3, 2.1e-5, 4.4e-10).
    EXPECT_GT(next / (e * e), 0.1) << "iteration " << h[i].iteration;
    EXPECT_LT(next / (e * e), 10.0) << "iteration " << h[i].iteration;
    ++checked;
  }
  EXPECT_GE(checked, 3);
  EXPECT_LE(h.size(), 9u);
}

TEST(ContactNewton, SimplifiedSemiSmoothNewtonConvergesWithAFrozenSet) {
  SolvedHit s(false);
  EXPECT_EQ(s.p.mp.GetProcessInfo().GetValue(INNER_LOOP_ITERATION), 1);
}

TEST(ContactNewton, SeparatedNodeStaysInactiveWithZeroPressure) {
  Hit hit;
  hit.F = Array3(-1.0, 0.0, 0.0);  // pulled away from the obstacle
  ContactProblem p(hit.k, hit.eps);
  hit.Add(p);
  p.mp.Set(INTERACTION, true);
  auto strategy = MakeStrategy(p, Defaults(), 10, Criteria(p));
  ASSERT_TRUE(strategy->Solve());
  EXPECT_NEAR(p.U(1)[0], -1.0, 1e-14);
  EXPECT_FALSE(p.mp.GetNode(1).Is(ACTIVE));
  EXPECT_EQ(p.Lm(1), 0.0);
  EXPECT_TRUE(strategy->ActiveSetFlipCounts().empty());
}

TEST(ContactNewton, FlipFloppingNodeIsNamedInTheFailure) {
  Hit hit;
  ContactProblem p(hit.k, hit.eps);
  hit.Add(p, 3);
  p.AddContactNode(7, Array3(0.0, 10.0, 0.0), Array3(1.0, 1.0, 0.0), AnchorSpring::Law::kLinear, Array3::Zero(),
                   Obstacle{Array3(0.0, 20.0, 0.0), 1.0});
  p.mp.Set(INTERACTION, true);
  // The gap reported for node 7 alternates in sign at every evaluation.
  auto lying = std::make_shared<CallbackMortarUpdater>([&p, calls = 0](ModelPart& part) mutable {
    p.Updater()->ComputeWeightedGap(part);
    p.mp.GetNode(7).FastGetSolutionStepValue(WEIGHTED_GAP) = (++calls % 2) ? -0.1 : 0.1;
  });
  auto criteria = Criteria(p);
  criteria->SetMortarUpdater(lying);
  auto strategy = MakeStrategy(p, Defaults(), 8, criteria);
  strategy->SetMortarUpdater(lying);
  EXPECT_FALSE(strategy->Solve());
  const std::string report = strategy->FailureReport();
  EXPECT_NE(report.find("active set did not settle"), std::string::npos) << report;
  EXPECT_NE(report.find("nodes still switching between contact and separation: 7 (3 changes)"), std::string::npos)
      << report;
  EXPECT_EQ(report.find("3 ("), std::string::npos) << report;
  // Node 7 switches on, off and on again: the set of iteration 3 is that of iteration 1, so the
  // strategy keeps it (the union of the cycle) until Newton converges, which the lying gap prevents.
  EXPECT_EQ(strategy->ActiveSetFlipCounts().at(7), 3);
  EXPECT_EQ(strategy->ActiveSetFlipCounts().at(3), 1);
}

TEST(ContactLineSearch, ParabolaStep) {
  // y = (x - 0.4)^2 + 0.1: r_o = 0.26, r_h = 0.11, r_f = 0.46 -> minimum at 0.4.
  EXPECT_NEAR(LineSearchContactStrategy::ParabolaStep(0.26, 0.11, 0.46, 0.1), 0.4, 1e-14);
  EXPECT_DOUBLE_EQ(LineSearchContactStrategy::ParabolaStep(0.26, 0.11, 0.46, 0.5), 0.5);  // clamped
  EXPECT_DOUBLE_EQ(LineSearchContactStrategy::ParabolaStep(1.0, 0.5, 0.1, 0.1), 1.0);     // minimum beyond 1
  EXPECT_DOUBLE_EQ(LineSearchContactStrategy::ParabolaStep(1.0, 0.9, 0.5, 0.1), 1.0);     // concave, decreasing
  EXPECT_DOUBLE_EQ(LineSearchContactStrategy::ParabolaStep(1.0, 1.5, 1.2, 0.1), 0.1);     // concave, increasing
  EXPECT_DOUBLE_EQ(LineSearchContactStrategy::ParabolaStep(0.0, 0.0, 0.0, 0.1), 1.0);
}

// k atan(u) = 0 from u = 2: Newton overshoots to -3.53, 13.9, ... and diverges; the obstacle is
// far away, so the multiplier block (inactive, zero residual) keeps the full step.
struct ArcTangent {
  ContactProblem p{2.0, 5.0};
  ArcTangent() {
    p.AddContactNode(1, Array3::Zero(), Array3(1.0, 1.0, 0.0), AnchorSpring::Law::kArcTangent, Array3::Zero(),
                     Obstacle{Array3(100.0, 100.0, 0.0), 1.0});
    p.mp.GetNode(1).FastGetSolutionStepValue(DISPLACEMENT_X) = 2.0;
    p.mp.Set(INTERACTION, true);
  }
};

TEST(ContactLineSearch, SplitStepLengthsDifferAndTheSearchConvergesWhereNewtonDiverges) {
  ArcTangent newton_case;
  auto newton = MakeStrategy(newton_case.p, Defaults(), 8, Criteria(newton_case.p, 1e-10));
  bool newton_converged = true;
  try {
    newton_converged = newton->Solve();
  } catch (const SolutionError&) {
    newton_converged = false;
  }
  EXPECT_FALSE(newton_converged);

  ArcTangent search_case;
  auto search = MakeStrategy<LineSearchContactStrategy>(search_case.p, {}, 30, Criteria(search_case.p, 1e-10), 0.1);
  ASSERT_TRUE(search->Solve()) << search->FailureReport();
  EXPECT_NEAR(search_case.p.U(1)[0], 0.0, 1e-10);
  const auto& steps = search->SplitSteps();
  ASSERT_FALSE(steps.empty());
  // First iteration: |r_u| at 0, 1/2, 1 of the step -> parabola minimum x = 1.992 / 4.36 ~ 0.457
  // (hand computation from atan(2), atan(-0.77), atan(-3.53)); the multiplier block keeps 1.
  const double d = -std::atan(2.0) * 5.0;
  const double ro = std::atan(2.0), rh = std::abs(std::atan(2.0 + 0.5 * d)), rf = std::abs(std::atan(2.0 + d));
  const double a = 2 * rf - 4 * rh + 2 * ro, b = 4 * rh - rf - 3 * ro;
  EXPECT_NEAR(steps[0].displacement, -b / (2 * a), 1e-12);
  EXPECT_NEAR(steps[0].displacement, 0.457, 2e-3);
  EXPECT_DOUBLE_EQ(steps[0].multiplier, 1.0);
  EXPECT_DOUBLE_EQ(search->IterationHistory()[0].step_length, steps[0].displacement);
}

// Adaptive splitting on k atan(u) = F: step 1 (F = atan 5) converges from u = 0; step 2 (F = 0)
// diverges from u = 5 in one step but converges in 10 sub-steps of the load ramp.
struct Ramp {
  ContactProblem p{2.0, 5.0};
  int initialize_calls = 0;
  int finalize_calls = 0;
  Ramp() {
    p.AddContactNode(1, Array3::Zero(), Array3(1.0, 1.0, 0.0), AnchorSpring::Law::kArcTangent, Array3::Zero(),
                     Obstacle{Array3(100.0, 100.0, 0.0), 1.0});
    p.mp.Set(INTERACTION, true);
  }
  // F(t) = atan(5) (2 - t) for t in [1, 2].
  void ApplyLoad() {
    const double t = p.mp.GetProcessInfo().GetValue(TIME);
    p.springs[1]->SetForce(Array3(std::atan(5.0) * std::min(1.0, 2.0 - t), 0.0, 0.0));
  }
  // The adaptive strategy with the splitting keys `splitting` of contact_settings, the load ramp
  // as its sub-step callbacks.
  std::unique_ptr<ResidualBasedNewtonRaphsonContactStrategy> AdaptiveStrategy(const std::string& splitting) {
    const ContactStrategySettings settings = ResidualBasedNewtonRaphsonContactStrategy::ReadSettings(
        Parameters(R"({"adaptative_strategy": true, )" + splitting + "}"));
    auto strategy = MakeStrategy(p, settings, 12, Criteria(p, 1e-10));
    strategy->SetSubStepCallbacks({[this] {
                                     ++initialize_calls;
                                     ApplyLoad();
                                   },
                                   [this] { ++finalize_calls; }});
    return strategy;
  }
  // Starts the step at time t.
  void Advance(double t) {
    p.mp.CloneTimeStep(t);
    ApplyLoad();
  }
};

TEST(ContactAdaptive, SplitsAStepThatDoesNotConverge) {
  Ramp r;
  auto strategy = r.AdaptiveStrategy(R"("max_number_splits": 2)");
  r.Advance(1.0);
  ASSERT_TRUE(strategy->Solve());
  EXPECT_NEAR(r.p.U(1)[0], 5.0, 1e-8);
  EXPECT_EQ(strategy->SplitLevelUsed(), 0);

  r.Advance(2.0);
  ASSERT_TRUE(strategy->Solve()) << strategy->FailureReport();
  EXPECT_EQ(strategy->SplitLevelUsed(), 1);
  EXPECT_NEAR(r.p.U(1)[0], 0.0, 1e-8);
  EXPECT_EQ(r.initialize_calls, 10);
  EXPECT_EQ(r.finalize_calls, 9);
  const ProcessInfo& info = r.p.mp.GetProcessInfo();
  EXPECT_EQ(info.GetValue(STEP), 2);
  EXPECT_DOUBLE_EQ(info.GetValue(TIME), 2.0);
  EXPECT_DOUBLE_EQ(info.GetValue(DELTA_TIME), 1.0);
  // The history was rebuilt by the sub-steps: step 1 holds the ninth sub-step (t = 1.9).
  EXPECT_NEAR(r.p.mp.GetNode(1).FastGetSolutionStepValue(DISPLACEMENT_X, 1), std::tan(0.1 * std::atan(5.0)), 1e-8);
}

TEST(ContactAdaptive, FailsClearlyWhenSplittingDoesNotHelp) {
  Ramp r;
  auto strategy = r.AdaptiveStrategy(R"("split_factor": 2.0, "max_number_splits": 1)");
  r.Advance(1.0);
  ASSERT_TRUE(strategy->Solve());
  r.Advance(2.0);
  const std::string message = test::ErrorMessageOf<SolutionError>([&] { strategy->Solve(); });
  EXPECT_NE(message.find("not even split 1 times (smallest sub-step 0.5)"), std::string::npos) << message;
  EXPECT_NE(message.find("newton_raphson_contact_strategy: step"), std::string::npos) << message;
}

TEST(ContactStrategySettingsTest, DefaultsAndValidation) {
  const ContactStrategySettings s = ResidualBasedNewtonRaphsonContactStrategy::ReadSettings(Parameters());
  EXPECT_FALSE(s.adaptative_strategy);
  EXPECT_EQ(s.split_factor, 10.0);
  EXPECT_EQ(s.max_number_splits, 3);
  EXPECT_EQ(s.inner_loop_iterations, 5);
  // Its keys are read from contact_settings, whose other keys the solver validates; a value out of
  // range names its JSON path.
  try {
    ResidualBasedNewtonRaphsonContactStrategy::ReadSettings(
        Parameters(R"({"contact_settings": {"mortar_type": "ALMContactFrictionless", "split_factor": 1.0}})",
                   "ProjectParameters.json")["contact_settings"]);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ProjectParameters.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("contact_settings.split_factor: 1 must be greater than 1"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace mc
