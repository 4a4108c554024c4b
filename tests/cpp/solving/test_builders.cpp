// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 (solving): block and elimination builders give the same solution and reactions,
// reactions balance the loads, the sparsity pattern is built once per DoF set, linear element
// matrices are reused within a step (issue 4), master-slave
// constraints give the exact tied solution, singular systems name the free node/variable.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Dense>

#include "core/linear_solvers/umfpack_solver.h"
#include "core/model/master_slave_constraint.h"
#include "core/solving/block_builder_and_solver.h"
#include "core/solving/displacement_criteria.h"
#include "core/solving/elimination_builder_and_solver.h"
#include "core/solving/linear_strategy.h"
#include "core/solving/newton_raphson_strategy.h"
#include "core/solving/residual_based_incremental_update_static_scheme.h"
#include "core/variables/kernel_variables.h"
#include "test_elements.h"
#include "tests/cpp/common/error_message.h"

namespace mc {
namespace {

using test::AddLoad;
using test::AddNode;
using test::AddSpring;

std::shared_ptr<BuilderAndSolver> MakeBuilder(const std::string& type) {
  auto solver = std::make_shared<UmfpackSolver>();
  if (type == "block") return std::make_shared<BlockBuilderAndSolver>(solver);
  return std::make_shared<EliminationBuilderAndSolver>(solver);
}

// Chain 1-2-3-4-5 of springs k = 1, 2, 3, 4; node 1 fixed at 0, node 5 prescribed at 0.1,
// load P = 5 at node 3.
struct Chain {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  Chain() {
    for (IndexType i = 1; i <= 5; ++i) AddNode(mp, i, static_cast<double>(i), 0.0);
    for (IndexType i = 1; i <= 4; ++i) AddSpring(mp, i, i, i + 1, static_cast<double>(i));
    AddLoad(mp, 1, 3, 5.0);
    mp.GetNode(1).Fix(DISPLACEMENT_X);
    mp.GetNode(5).Fix(DISPLACEMENT_X);
    mp.GetNode(5).FastGetSolutionStepValue(DISPLACEMENT_X) = 0.1;
  }
};

// The same chain solved densely: free unknowns u2, u3, u4.
Eigen::Vector3d ChainReference() {
  const double k[4] = {1, 2, 3, 4};
  Eigen::Matrix3d K;
  K << k[0] + k[1], -k[1], 0, -k[1], k[1] + k[2], -k[2], 0, -k[2], k[2] + k[3];
  const Eigen::Vector3d f(0.0, 5.0, k[3] * 0.1);
  return K.lu().solve(f);
}

// A bar: node 1 at x = 0, node 2 at x = 1, spring 1 of stiffness k between them.
void AddBar(ModelPart& mp, double k) {
  AddNode(mp, 1, 0.0, 0.0);
  AddNode(mp, 2, 1.0, 0.0);
  AddSpring(mp, 1, 1, 2, k);
}

// The message of the `Error` a linear static solve of `mp` throws ("" when it solves).
template <class Error>
std::string SolveError(ModelPart& mp, std::shared_ptr<BuilderAndSolver> builder) {
  LinearStrategy strategy(mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(), std::move(builder));
  return test::ErrorMessageOf<Error>([&] { strategy.Solve(); });
}

class BothBuilders : public ::testing::TestWithParam<std::string> {};

TEST_P(BothBuilders, LinearChainMatchesDenseSolutionAndReactionsBalanceLoads) {
  Chain c;
  LinearStrategy strategy(c.mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                          MakeBuilder(GetParam()));
  ASSERT_TRUE(strategy.Solve());
  const Eigen::Vector3d ref = ChainReference();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(c.mp.GetNode(i + 2).FastGetSolutionStepValue(DISPLACEMENT_X), ref[i], 1e-13);
  EXPECT_DOUBLE_EQ(c.mp.GetNode(5).FastGetSolutionStepValue(DISPLACEMENT_X), 0.1);
  // REACTION is the force the support exerts on the structure.
  const double r1 = c.mp.GetNode(1).FastGetSolutionStepValue(REACTION_X);
  const double r5 = c.mp.GetNode(5).FastGetSolutionStepValue(REACTION_X);
  EXPECT_NEAR(r1, -1.0 * ref[0], 1e-12);         // spring 1 stretched by u2 pulls node 1 to +x
  EXPECT_NEAR(r5, 4.0 * (0.1 - ref[2]), 1e-12);  // support holds node 5 at 0.1
  EXPECT_NEAR(r1 + r5 + 5.0, 0.0, 1e-12);        // equilibrium of the whole chain
  EXPECT_DOUBLE_EQ(c.mp.GetNode(3).FastGetSolutionStepValue(REACTION_X), 0.0);
}

TEST_P(BothBuilders, BarUnderPointLoadReactionOpposesLoad) {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  AddBar(mp, 100.0);
  AddLoad(mp, 1, 2, 7.0);
  mp.GetNode(1).Fix(DISPLACEMENT_X);
  LinearStrategy strategy(mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(), MakeBuilder(GetParam()));
  ASSERT_TRUE(strategy.Solve());
  EXPECT_NEAR(mp.GetNode(2).FastGetSolutionStepValue(DISPLACEMENT_X), 0.07, 1e-15);
  EXPECT_NEAR(mp.GetNode(1).FastGetSolutionStepValue(REACTION_X), -7.0, 1e-12);
}

TEST_P(BothBuilders, PatternIsBuiltOncePerDofSet) {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  for (IndexType i = 1; i <= 4; ++i) AddNode(mp, i, static_cast<double>(i), 0.0);
  for (IndexType i = 1; i <= 3; ++i) AddSpring(mp, i, i, i + 1, 1.0, 1.0);
  auto& load = AddLoad(mp, 1, 4, 0.0);
  mp.GetNode(1).Fix(DISPLACEMENT_X);
  auto builder = MakeBuilder(GetParam());
  NewtonRaphsonStrategy strategy(mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                 std::make_shared<DisplacementCriteria>(1e-10, 1e-14), builder, 30);
  int iterations = 0;
  for (int step = 1; step <= 3; ++step) {
    mp.CloneTimeStep(step);
    load.SetForce(2.0 * step);
    ASSERT_TRUE(strategy.Solve());
    iterations += static_cast<int>(strategy.IterationHistory().size());
  }
  EXPECT_GT(iterations, 6);
  EXPECT_EQ(builder->PatternBuildCount(), 1);
  const auto& t = builder->GetTimings();
  EXPECT_GT(t.build, 0.0);
  EXPECT_GT(t.solve, 0.0);
  EXPECT_GE(t.sparsity, 0.0);
  // Issue 4: the element and condition loops are timed apart, both inside `build`.
  EXPECT_GT(t.elements, 0.0);
  EXPECT_GT(t.conditions, 0.0);
  EXPECT_LE(t.elements + t.conditions, t.build);

  strategy.SetReformDofsAtEachStep(true);
  for (int step = 4; step <= 5; ++step) {
    mp.CloneTimeStep(step);
    ASSERT_TRUE(strategy.Solve());
  }
  EXPECT_EQ(builder->PatternBuildCount(), 3);
}

// A support on the DISPLACEMENT_X of one node pulling back with the force c u^3: the nonlinear
// part of the problem sits in a condition, as contact does, so that the springs stay linear.
class CubicSupport : public test::LocalSystemEntity<Condition> {
 public:
  CubicSupport(IndexType id, Geometry geometry, double c)
      : LocalSystemEntity(id, std::move(geometry), nullptr), c_(c) {}
  std::string Info() const override { return "CubicSupport"; }
  std::unique_ptr<Condition> Create(IndexType id, Geometry::NodesArray nodes, Properties*) const override {
    return std::make_unique<CubicSupport>(id, Geometry(GetGeometry().Type(), std::move(nodes)), c_);
  }
  void GetDofList(DofsVectorType& dofs, const ProcessInfo&) const override {
    dofs.assign(1, &GetGeometry()[0].GetDof(DISPLACEMENT_X));
  }
  void CalculateLocalSystem(Matrix& lhs, Vector& rhs, const ProcessInfo&) override {
    const double u = GetGeometry()[0].FastGetSolutionStepValue(DISPLACEMENT_X);
    lhs.setConstant(1, 1, 3.0 * c_ * u * u);
    rhs.setConstant(1, -c_ * u * u * u);
  }

 private:
  double c_;
};

// A static scheme that does not promise to pass element matrices through unchanged.
class OpaqueStaticScheme : public ResidualBasedIncrementalUpdateStaticScheme {
 public:
  bool PassesEntityLeftHandSide() const override { return false; }
};

// Springs 1-2-3-4 (k = 1, 2, 3), node 1 fixed, cubic support c = 5 and load F at node 4:
// k_eq u4 + c u4^3 = F with 1/k_eq = 1 + 1/2 + 1/3.
struct StiffeningChain {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  test::TestLoad* load = nullptr;
  StiffeningChain() {
    for (IndexType i = 1; i <= 4; ++i) AddNode(mp, i, static_cast<double>(i), 0.0);
    for (IndexType i = 1; i <= 3; ++i) AddSpring(mp, i, i, i + 1, static_cast<double>(i));
    load = &AddLoad(mp, 1, 4, 0.0);
    mp.AddCondition(std::make_unique<CubicSupport>(2, Geometry(GeometryType::Point2D, {&mp.GetNode(4)}), 5.0));
    mp.GetNode(1).Fix(DISPLACEMENT_X);
  }
  double U4() const { return mp.GetNode(4).FastGetSolutionStepValue(DISPLACEMENT_X); }
};

// Issue 4: linear elements are assembled once per step and their matrix copied at the next
// Newton iterations; the iterates are those of a full assembly.
TEST_P(BothBuilders, LinearElementMatrixIsReusedWithinAStepWithTheSameIterates) {
  StiffeningChain reused, rebuilt;
  auto builder = MakeBuilder(GetParam());
  auto reference_builder = MakeBuilder(GetParam());
  NewtonRaphsonStrategy strategy(reused.mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                 std::make_shared<DisplacementCriteria>(1e-12, 1e-15), builder, 30);
  NewtonRaphsonStrategy reference(rebuilt.mp, std::make_shared<OpaqueStaticScheme>(),
                                  std::make_shared<DisplacementCriteria>(1e-12, 1e-15), reference_builder, 30);
  const double k_eq = 1.0 / (1.0 + 1.0 / 2.0 + 1.0 / 3.0);
  int expected_reuses = 0;
  for (int step = 1; step <= 2; ++step) {
    for (StiffeningChain* c : {&reused, &rebuilt}) {
      c->mp.CloneTimeStep(step);
      c->load->SetForce(4.0 * step);
    }
    ASSERT_TRUE(strategy.Solve());
    ASSERT_TRUE(reference.Solve());
    const auto& h = strategy.IterationHistory();
    const auto& h_ref = reference.IterationHistory();
    ASSERT_EQ(h.size(), h_ref.size());
    ASSERT_GE(h.size(), 3u);
    for (std::size_t k = 0; k < h.size(); ++k)
      EXPECT_NEAR(h[k].increment_norm, h_ref[k].increment_norm, 1e-14 * (1.0 + h_ref[k].increment_norm));
    const double u = reused.U4();
    EXPECT_NEAR(k_eq * u + 5.0 * u * u * u, 4.0 * step, 1e-9);
    // The first build of each step assembles the elements; every later one reuses them.
    expected_reuses += static_cast<int>(h.size()) - 1;
    EXPECT_EQ(builder->ElementMatrixReuses(), expected_reuses) << "step " << step;
  }
  EXPECT_EQ(reference_builder->ElementMatrixReuses(), 0);
}

// A nonlinear element anywhere turns the reuse off.
TEST(BlockBuilder, NonlinearElementDisablesElementMatrixReuse) {
  StiffeningChain c;
  AddSpring(c.mp, 4, 2, 3, 1.0, 1.0);
  auto builder = MakeBuilder("block");
  NewtonRaphsonStrategy strategy(c.mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                 std::make_shared<DisplacementCriteria>(1e-12, 1e-15), builder, 30);
  c.mp.CloneTimeStep(1);
  c.load->SetForce(4.0);
  ASSERT_TRUE(strategy.Solve());
  EXPECT_GE(strategy.IterationHistory().size(), 3u);
  EXPECT_EQ(builder->ElementMatrixReuses(), 0);
}

// Two springs 1-2 (k1) and 3-4 (k2), nodes 1 and 3 fixed, u4 = 2 u2 + 0.01, load P at node 2.
// Energy minimisation gives u2 = (P - 2 k2 c) / (k1 + 4 k2).
TEST_P(BothBuilders, MasterSlaveConstraintGivesTiedSolution) {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  for (IndexType i = 1; i <= 4; ++i) AddNode(mp, i, static_cast<double>(i), 0.0);
  const double k1 = 10.0, k2 = 3.0, P = 4.0, w = 2.0, offset = 0.01;
  AddSpring(mp, 1, 1, 2, k1);
  AddSpring(mp, 2, 3, 4, k2);
  AddLoad(mp, 1, 2, P);
  mp.GetNode(1).Fix(DISPLACEMENT_X);
  mp.GetNode(3).Fix(DISPLACEMENT_X);
  auto builder = MakeBuilder(GetParam());
  builder->AddConstraint(std::make_shared<MasterSlaveConstraint>(
      1, mp.GetNode(4).GetDof(DISPLACEMENT_X), std::vector<Dof*>{&mp.GetNode(2).GetDof(DISPLACEMENT_X)},
      std::vector<double>{w}, offset));
  LinearStrategy strategy(mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(), builder);
  ASSERT_TRUE(strategy.Solve());
  const double u2 = (P - w * k2 * offset) / (k1 + w * w * k2);
  EXPECT_NEAR(mp.GetNode(2).FastGetSolutionStepValue(DISPLACEMENT_X), u2, 1e-14);
  EXPECT_NEAR(mp.GetNode(4).FastGetSolutionStepValue(DISPLACEMENT_X), w * u2 + offset, 1e-14);
  const double r1 = mp.GetNode(1).FastGetSolutionStepValue(REACTION_X);
  const double r3 = mp.GetNode(3).FastGetSolutionStepValue(REACTION_X);
  EXPECT_NEAR(r1, -k1 * u2, 1e-12);
  EXPECT_NEAR(r3, -k2 * (w * u2 + offset), 1e-12);
  EXPECT_EQ(builder->SystemSize(), GetParam() == "block" ? 4u : 1u);
}

// A residual combination (frictional MPC contact's Coulomb force) on a nonlinear chain with a
// constraint: springs 1-2-3-4-5, node 1 fixed, the cubic support at node 3, u5 = 0.5 u4 + 0.01, node 2
// taking 0.3 of node 3's residual and node 4 -0.2 of the slave node 5's. The system matrix is the
// exact derivative of the system residual (central differences over every unknown), and Newton
// converges quadratically to the state where the combined residual vanishes.
TEST_P(BothBuilders, ResidualCombinationHasItsExactTangent) {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  for (IndexType i = 1; i <= 5; ++i) AddNode(mp, i, static_cast<double>(i), 0.0);
  for (IndexType i = 1; i <= 4; ++i) AddSpring(mp, i, i, i + 1, static_cast<double>(i));
  mp.AddCondition(std::make_unique<CubicSupport>(9, Geometry(GeometryType::Point2D, {&mp.GetNode(3)}), 5.0));
  AddLoad(mp, 10, 4, 2.0);
  mp.GetNode(1).Fix(DISPLACEMENT_X);
  auto builder = MakeBuilder(GetParam());
  const auto dof = [&](IndexType id) { return &mp.GetNode(id).GetDof(DISPLACEMENT_X); };
  builder->AddConstraint(
      std::make_shared<MasterSlaveConstraint>(1, *dof(5), std::vector<Dof*>{dof(4)}, std::vector<double>{0.5}, 0.01));
  builder->SetResidualCombination({{dof(2), dof(3), 0.3}, {dof(4), dof(5), -0.2}});
  ResidualBasedIncrementalUpdateStaticScheme scheme;
  builder->SetUpDofSet(mp, scheme);
  const double state[5] = {0.0, 0.1, 0.4, -0.2, 0.3};
  for (IndexType i = 1; i <= 5; ++i) mp.GetNode(i).FastGetSolutionStepValue(DISPLACEMENT_X) = state[i - 1];
  builder->Build(scheme, mp);
  const Eigen::MatrixXd A(builder->SystemMatrix());
  const double h = 1e-6;
  double largest = 0.0, error = 0.0;
  for (IndexType i = 2; i <= 4; ++i) {
    double& u = mp.GetNode(i).FastGetSolutionStepValue(DISPLACEMENT_X);
    const double u0 = u;
    u = u0 + h;
    builder->BuildRHS(scheme, mp);
    const Vector plus = builder->SystemRhs();
    u = u0 - h;
    builder->BuildRHS(scheme, mp);
    const Vector minus = builder->SystemRhs();
    u = u0;
    const Eigen::Index column = dof(i)->equation_id;
    for (IndexType j = 2; j <= 4; ++j) {
      const Eigen::Index row = dof(j)->equation_id;
      const double derivative = -(plus[row] - minus[row]) / (2.0 * h);
      largest = std::max(largest, std::abs(A(row, column)));
      error = std::max(error, std::abs(derivative - A(row, column)));
    }
  }
  EXPECT_LT(error, 1e-8 * largest);
  // Without the combination in the matrix the difference would be of the size of its terms.
  EXPECT_GT(largest, 1.0);

  mp.CloneTimeStep(1.0);
  NewtonRaphsonStrategy strategy(mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                 std::make_shared<DisplacementCriteria>(1e-13, 1e-16), builder, 30);
  ASSERT_TRUE(strategy.Solve());
  const auto& history = strategy.IterationHistory();
  ASSERT_GE(history.size(), 4u);
  // Quadratic: each increment at most a multiple of the square of the one before, once small.
  for (std::size_t k = 2; k + 1 < history.size(); ++k) {
    if (history[k - 1].increment_norm < 1e-2 && history[k].increment_norm > 1e-12) {
      EXPECT_LT(history[k].increment_norm, 10.0 * std::pow(history[k - 1].increment_norm, 2)) << "iteration " << k;
    }
  }
  // The combined residual vanishes: node 2's own row plus 0.3 of node 3's.
  const auto u = [&](IndexType id) { return mp.GetNode(id).FastGetSolutionStepValue(DISPLACEMENT_X); };
  const double r2 = -(1.0 * (u(2) - u(1)) - 2.0 * (u(3) - u(2)));
  const double r3 = -(2.0 * (u(3) - u(2)) - 3.0 * (u(4) - u(3)) + 5.0 * std::pow(u(3), 3));
  EXPECT_NEAR(r2 + 0.3 * r3, 0.0, 1e-10);
  EXPECT_NEAR(u(5), 0.5 * u(4) + 0.01, 1e-14);
}

// The model part's constraints (what impose_rigid_movement_process adds) join the builder's at
// each DoF set-up; an inactive one is left out at the next set-up.
TEST_P(BothBuilders, ModelPartConstraintsAreEliminatedWhileActive) {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  for (IndexType i = 1; i <= 3; ++i) AddNode(mp, i, static_cast<double>(i), 0.0);
  const double k = 10.0, P = 4.0;
  AddSpring(mp, 1, 1, 2, k);
  AddSpring(mp, 2, 2, 3, k);
  AddLoad(mp, 1, 3, P);
  mp.GetNode(1).Fix(DISPLACEMENT_X);
  auto constraint = std::make_shared<MasterSlaveConstraint>(1, mp.GetNode(3).GetDof(DISPLACEMENT_X),
                                                            std::vector<Dof*>{&mp.GetNode(2).GetDof(DISPLACEMENT_X)},
                                                            std::vector<double>{1.0});
  mp.CreateSubModelPart("Tied").AddMasterSlaveConstraint(constraint);
  ASSERT_EQ(mp.MasterSlaveConstraints().size(), 1u);
  auto builder = MakeBuilder(GetParam());
  LinearStrategy strategy(mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(), builder, false, true);
  ASSERT_TRUE(strategy.Solve());
  // Node 3 moves with node 2: the second spring is unstretched, the first carries P.
  EXPECT_NEAR(mp.GetNode(2).FastGetSolutionStepValue(DISPLACEMENT_X), P / k, 1e-14);
  EXPECT_NEAR(mp.GetNode(3).FastGetSolutionStepValue(DISPLACEMENT_X), P / k, 1e-14);
  constraint->SetActive(false);
  mp.CloneTimeStep(2.0);
  ASSERT_TRUE(strategy.Solve());
  EXPECT_NEAR(mp.GetNode(3).FastGetSolutionStepValue(DISPLACEMENT_X), 2.0 * P / k, 1e-14);
}

TEST_P(BothBuilders, SingularSystemNamesTheFreeDofs) {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  AddNode(mp, 4, 0.0, 0.0, 2);
  AddNode(mp, 7, 1.0, 0.0, 2);
  AddSpring(mp, 1, 4, 7, 1.0, 0.0, 2);  // along x: no stiffness in y
  AddLoad(mp, 1, 7, 1.0);
  mp.GetNode(4).Fix(DISPLACEMENT_X);
  EXPECT_EQ(SolveError<SolutionError>(mp, MakeBuilder(GetParam())),
            "singular system: no stiffness for DISPLACEMENT_Y of nodes 4, 7 (are they constrained?)");
}

TEST_P(BothBuilders, SingularListIsCappedAtTenDofs) {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  for (IndexType i = 1; i <= 16; ++i) AddNode(mp, i, static_cast<double>(i), 0.0, 2);
  for (IndexType i = 1; i <= 15; ++i) AddSpring(mp, i, i, i + 1, 1.0, 0.0, 2);
  mp.GetNode(1).Fix(DISPLACEMENT_X);
  EXPECT_EQ(SolveError<SolutionError>(mp, MakeBuilder(GetParam())),
            "singular system: no stiffness for DISPLACEMENT_Y of nodes 1, 2, 3, 4, 5, 6, 7, 8, 9, 10 and 6 "
            "more DoFs (are they constrained?)");
}

TEST_P(BothBuilders, FloatingStructureIsReportedBySolverPivot) {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  AddBar(mp, 1.0);
  const std::string message = SolveError<SolutionError>(mp, MakeBuilder(GetParam()));
  EXPECT_NE(message.find("singular system"), std::string::npos) << message;
  EXPECT_NE(message.find("DISPLACEMENT_X of node"), std::string::npos) << message;
}

TEST_P(BothBuilders, FixedSlaveIsAnInputError) {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  AddBar(mp, 1.0);
  mp.GetNode(1).Fix(DISPLACEMENT_X);
  mp.GetNode(2).Fix(DISPLACEMENT_X);
  auto builder = MakeBuilder(GetParam());
  builder->AddConstraint(std::make_shared<MasterSlaveConstraint>(
      9, mp.GetNode(2).GetDof(DISPLACEMENT_X), std::vector<Dof*>{&mp.GetNode(1).GetDof(DISPLACEMENT_X)},
      std::vector<double>{1.0}));
  const std::string message = SolveError<InputError>(mp, builder);
  EXPECT_NE(message.find("constraint 9"), std::string::npos) << message;
  EXPECT_NE(message.find("DISPLACEMENT_X of node 2 is fixed"), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(Builders, BothBuilders, ::testing::Values("block", "elimination"));

TEST(BlockBuilder, DirichletRowsAndColumnsAreZeroedKeepingSymmetry) {
  Chain c;
  auto builder = std::make_shared<BlockBuilderAndSolver>(std::make_shared<UmfpackSolver>());
  ResidualBasedIncrementalUpdateStaticScheme scheme;
  builder->SetUpDofSet(c.mp, scheme);
  builder->SetUpSystem();
  builder->Build(scheme, c.mp);
  const Eigen::MatrixXd A(builder->SystemMatrix());
  EXPECT_EQ((A - A.transpose()).norm(), 0.0);
  EXPECT_DOUBLE_EQ(builder->DirichletScale(), 7.0);  // largest free diagonal: k3 + k4
  for (int fixed : {0, 4}) {
    EXPECT_DOUBLE_EQ(A(fixed, fixed), 7.0);
    EXPECT_DOUBLE_EQ(A.row(fixed).cwiseAbs().sum(), 7.0);
    EXPECT_DOUBLE_EQ(builder->SystemRhs()[fixed], 0.0);
  }
  EXPECT_TRUE(A.selfadjointView<Eigen::Lower>().llt().info() == Eigen::Success);
}

TEST(EliminationBuilder, FixityChangeRenumbers) {
  Chain c;
  auto builder = std::make_shared<EliminationBuilderAndSolver>(std::make_shared<UmfpackSolver>());
  ResidualBasedIncrementalUpdateStaticScheme scheme;
  builder->SetUpDofSet(c.mp, scheme);
  builder->SetUpSystem();
  builder->Build(scheme, c.mp);
  EXPECT_EQ(builder->SystemSize(), 3u);
  c.mp.GetNode(5).Free(DISPLACEMENT_X);
  builder->Build(scheme, c.mp);
  EXPECT_EQ(builder->SystemSize(), 4u);
  EXPECT_EQ(builder->PatternBuildCount(), 2);
}

}  // namespace
}  // namespace mc
