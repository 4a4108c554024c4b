// SPDX-License-Identifier: BSD-3-Clause
// Issue 3 part 7: MixedULMLinearSolver, the static condensation of the dual multipliers of the
// components system (thesis eqs. 4.36-4.40). On real ALMFrictionlessComponents pairs (2D2N,
// 3D3N, 3D4N) with active and inactive slave nodes, the condensed solution equals the
// monolithic UMFPACK solution to 1e-10; a non-diagonal K_{S_A,LM_A} or LM_I row takes the
// full-system fallback and still matches; fixed multipliers and slave displacements (block
// and elimination builders) are handled; the builder hook provides the DoFs at every solve and
// refuses master-slave constraints. Issue 12: frictional active nodes, whose multiplier block is
// full (stick: constraint rows on every component; slip: K_{S_A,LM_A} full within the node),
// still condense and match.
#include <gtest/gtest.h>

#include <iostream>

#include "contact_system_fixture.h"
#include "core/linear_solvers/umfpack_solver.h"
#include "core/model/master_slave_constraint.h"
#include "core/solving/block_builder_and_solver.h"
#include "core/solving/elimination_builder_and_solver.h"
#include "core/solving/residual_based_incremental_update_static_scheme.h"
#include "custom_linear_solvers/mixed_ulm_linear_solver.h"

namespace mc::test {
namespace {

using BlockType = MixedULMLinearSolver::BlockType;

double g_max_error = 0.0;  // largest relative difference condensed vs monolithic, printed at the end

MixedULMLinearSolver MakeMixed() { return MixedULMLinearSolver(std::make_unique<UmfpackSolver>()); }

Vector SolveMonolithic(const SparseMatrix& A, const Vector& b) {
  UmfpackSolver solver;
  solver.Initialize(A);
  Vector x = Vector::Zero(b.size());
  solver.Solve(A, x, b);
  return x;
}

Vector SolveMixed(MixedULMLinearSolver& solver, const SparseMatrix& A, const std::vector<Dof*>& dofs, const Vector& b) {
  solver.Initialize(A);
  solver.ProvideAdditionalData(A, dofs);
  Vector x = Vector::Zero(b.size());
  solver.Solve(A, x, b);
  return x;
}

double RelativeDifference(const Vector& x, const Vector& reference) {
  const double error = (x - reference).lpNorm<Eigen::Infinity>() / reference.lpNorm<Eigen::Infinity>();
  g_max_error = std::max(g_max_error, error);
  return error;
}

/// The assembled residual plus a random part, so that every block (LM_I included) has a load.
Vector RandomRhs(const Vector& assembled, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Vector b = assembled;
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] += uniform(generator);
  return b;
}

Eigen::Index RowOf(const std::vector<Dof*>& dofs, const Node& node, const Variable<double>& var) {
  for (std::size_t i = 0; i < dofs.size(); ++i)
    if (dofs[i]->node == &node && dofs[i]->variable == &var) return static_cast<Eigen::Index>(i);
  ADD_FAILURE() << var.Name() << " of node " << node.Id() << " is not in the system";
  return -1;
}

template <class TSystem>
class CondensationTest : public ::testing::Test {};

template <int D, int S, int M>
struct Case {
  static constexpr int kDim = D;
  static constexpr int kSlave = S;
  using System = ContactSystem<D, S, M>;
};
using Cases = ::testing::Types<Case<2, 2, 2>, Case<3, 3, 3>, Case<3, 4, 4>>;
TYPED_TEST_SUITE(CondensationTest, Cases);

TYPED_TEST(CondensationTest, MatchesMonolithicForEveryActivePattern) {
  constexpr int kDim = TypeParam::kDim;
  constexpr int kSlave = TypeParam::kSlave;
  for (int pattern = 0; pattern < 3; ++pattern) {  // mixed, all active, all inactive
    std::vector<bool> active(kSlave);
    for (int i = 0; i < kSlave; ++i) active[i] = pattern == 1 || (pattern == 0 && i % 2 == 0);
    const int n_active = static_cast<int>(std::count(active.begin(), active.end(), true));
    AssembledSystem<typename TypeParam::System> assembled(active);
    const auto& [system, A, residual, dofs] = assembled;
    const Vector b = RandomRhs(residual, 11 + pattern);
    const Vector reference = SolveMonolithic(A, b);
    MixedULMLinearSolver solver = MakeMixed();
    const Vector x = SolveMixed(solver, A, dofs, b);

    ASSERT_TRUE(solver.LastSolveWasCondensed()) << solver.FallbackReason();
    EXPECT_LE(RelativeDifference(x, reference), 1e-10) << "pattern " << pattern;
    const long n = A.rows();
    const long n_lm = kDim * kSlave;
    EXPECT_EQ(n, kDim * (kSlave + static_cast<long>(system.masters.size()) + 2) + n_lm);
    EXPECT_EQ(solver.CondensedSize(), n - n_lm);
    EXPECT_EQ(solver.NumberOfPairs(), kDim * n_active);

    // Classification from the flags, row by row.
    int counts[6] = {0, 0, 0, 0, 0, 0};
    for (BlockType t : solver.BlockTypes()) ++counts[static_cast<int>(t)];
    EXPECT_EQ(counts[static_cast<int>(BlockType::kOther)], 2 * kDim);
    EXPECT_EQ(counts[static_cast<int>(BlockType::kMaster)], static_cast<int>(system.masters.size()) * kDim);
    EXPECT_EQ(counts[static_cast<int>(BlockType::kSlaveActive)], kDim * n_active);
    EXPECT_EQ(counts[static_cast<int>(BlockType::kSlaveInactive)], kDim * (kSlave - n_active));
    EXPECT_EQ(counts[static_cast<int>(BlockType::kLmActive)], kDim * n_active);
    EXPECT_EQ(counts[static_cast<int>(BlockType::kLmInactive)], kDim * (kSlave - n_active));
    if (pattern == 0)
      std::cout << "[ figures  ] " << kDim << "D" << kSlave << "N mixed: full " << n << ", condensed "
                << solver.CondensedSize() << ", error " << RelativeDifference(x, reference) << "\n";
  }
}

TYPED_TEST(CondensationTest, NonDiagonalSlaveMultiplierBlockFallsBackToFullSystem) {
  constexpr int kSlave = TypeParam::kSlave;
  AssembledSystem<typename TypeParam::System> assembled(std::vector<bool>(kSlave, true));
  auto& [system, A, residual, dofs] = assembled;
  const Vector b = RandomRhs(residual, 3);

  // K(slave node 1 DISPLACEMENT_X, VECTOR_LAGRANGE_MULTIPLIER_Y of slave node 2) != 0.
  const Eigen::Index s = RowOf(dofs, *system.slaves[0], DISPLACEMENT_X);
  const Eigen::Index l = RowOf(dofs, *system.slaves[1], VECTOR_LAGRANGE_MULTIPLIER_Y);
  EXPECT_EQ(A.coeff(s, l), 0.0);
  A.coeffRef(s, l) = 0.3;
  A.makeCompressed();
  const Vector reference = SolveMonolithic(A, b);
  MixedULMLinearSolver solver = MakeMixed();
  const Vector x = SolveMixed(solver, A, dofs, b);
  EXPECT_FALSE(solver.LastSolveWasCondensed());
  EXPECT_NE(solver.FallbackReason().find("not diagonal"), std::string::npos) << solver.FallbackReason();
  EXPECT_NE(solver.FallbackReason().find("DISPLACEMENT_X of node 1"), std::string::npos) << solver.FallbackReason();
  EXPECT_LE(RelativeDifference(x, reference), 1e-10);

  // Within the tolerance the entry counts as zero: condensed again.
  A.coeffRef(s, l) = 1e-13;
  const Vector x_small = SolveMixed(solver, A, dofs, b);
  EXPECT_TRUE(solver.LastSolveWasCondensed()) << solver.FallbackReason();
  const Vector difference = x_small - SolveMonolithic(A, b);
  EXPECT_LE(difference.lpNorm<Eigen::Infinity>() / reference.lpNorm<Eigen::Infinity>(), 1e-10);
}

// A frictional system: node 1 slips (its 2x2 / 3x3 block of K_{S_A,LM_A} gets off-diagonal
// entries, as the Coulomb traction -mu lbar_n dir does), node 2 sticks (its multiplier rows get
// entries at every multiplier component of the node and at the master displacements, as the
// stick constraint k T(lambda) + c_tau eps s does), the others stay as they are.
TYPED_TEST(CondensationTest, FrictionalSlipAndStickBlocksCondense) {
  constexpr int kDim = TypeParam::kDim;
  constexpr int kSlave = TypeParam::kSlave;
  AssembledSystem<typename TypeParam::System> assembled(std::vector<bool>(kSlave, true));
  auto& [system, A, residual, dofs] = assembled;
  const Vector b = RandomRhs(residual, 17);
  const Variable<double>* u[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
  const Variable<double>* lm[3] = {&VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y,
                                   &VECTOR_LAGRANGE_MULTIPLIER_Z};
  const Node& slip = *system.slaves[0];
  const Node& stick = *system.slaves[1];
  for (int a = 0; a < kDim; ++a) {
    const double pivot = A.coeff(RowOf(dofs, slip, *u[a]), RowOf(dofs, slip, *lm[a]));
    ASSERT_NE(pivot, 0.0);
    for (int c = 0; c < kDim; ++c) {
      if (c != a) A.coeffRef(RowOf(dofs, slip, *u[a]), RowOf(dofs, slip, *lm[c])) = (0.3 + 0.1 * a - 0.2 * c) * pivot;
      A.coeffRef(RowOf(dofs, stick, *lm[a]), RowOf(dofs, stick, *lm[c])) += 0.5 + 0.25 * a - 0.125 * c;
      A.coeffRef(RowOf(dofs, stick, *lm[a]), RowOf(dofs, *system.masters[0], *u[c])) += 0.2 * (a + 1) - 0.1 * c;
    }
  }
  A.makeCompressed();
  const Vector reference = SolveMonolithic(A, b);
  MixedULMLinearSolver solver = MakeMixed();
  const Vector x = SolveMixed(solver, A, dofs, b);
  ASSERT_TRUE(solver.LastSolveWasCondensed()) << solver.FallbackReason();
  EXPECT_EQ(solver.NumberOfPairs(), kDim * kSlave);
  EXPECT_EQ(solver.CondensedSize(), A.rows() - kDim * kSlave);
  EXPECT_LE(RelativeDifference(x, reference), 1e-10);

  // A singular slip block (two equal rows) cannot be condensed: full system, named node.
  for (int c = 0; c < kDim; ++c)
    A.coeffRef(RowOf(dofs, slip, *u[1]), RowOf(dofs, slip, *lm[c])) =
        A.coeff(RowOf(dofs, slip, *u[0]), RowOf(dofs, slip, *lm[c]));
  const Vector x_singular = SolveMixed(solver, A, dofs, b);
  EXPECT_FALSE(solver.LastSolveWasCondensed());
  EXPECT_NE(solver.FallbackReason().find("singular at the multipliers of node 1"), std::string::npos)
      << solver.FallbackReason();
  EXPECT_LE(RelativeDifference(x_singular, SolveMonolithic(A, b)), 1e-10);
}

TYPED_TEST(CondensationTest, NonDiagonalInactiveMultiplierRowFallsBack) {
  constexpr int kSlave = TypeParam::kSlave;
  std::vector<bool> active(kSlave, true);
  active[1] = false;
  AssembledSystem<typename TypeParam::System> assembled(active);
  auto& [system, A, residual, dofs] = assembled;
  const Vector b = RandomRhs(residual, 5);
  const Eigen::Index i = RowOf(dofs, *system.slaves[1], VECTOR_LAGRANGE_MULTIPLIER_X);
  const Eigen::Index j = RowOf(dofs, *system.masters[0], DISPLACEMENT_Y);
  A.coeffRef(i, j) = -0.2;
  A.makeCompressed();
  MixedULMLinearSolver solver = MakeMixed();
  const Vector x = SolveMixed(solver, A, dofs, b);
  EXPECT_FALSE(solver.LastSolveWasCondensed());
  EXPECT_NE(solver.FallbackReason().find("VECTOR_LAGRANGE_MULTIPLIER_X of node 2 is not diagonal"), std::string::npos)
      << solver.FallbackReason();
  EXPECT_LE(RelativeDifference(x, SolveMonolithic(A, b)), 1e-10);
}

TYPED_TEST(CondensationTest, FixedMultiplierAndFixedSlaveDisplacementStayUncondensed) {
  constexpr int kDim = TypeParam::kDim;
  constexpr int kSlave = TypeParam::kSlave;
  typename TypeParam::System system(std::vector<bool>(kSlave, true));
  system.slaves[0]->Fix(VECTOR_LAGRANGE_MULTIPLIER_X);
  system.slaves[1]->Fix(DISPLACEMENT_Y);
  SparseMatrix A;
  Vector assembled;
  std::vector<Dof*> dofs;
  system.Assemble(A, assembled, dofs);
  Vector b = RandomRhs(assembled, 9);
  for (std::size_t i = 0; i < dofs.size(); ++i)
    if (dofs[i]->fixed) b[static_cast<Eigen::Index>(i)] = 0.0;  // prescribed increments are zero
  const Vector reference = SolveMonolithic(A, b);
  MixedULMLinearSolver solver = MakeMixed();
  const Vector x = SolveMixed(solver, A, dofs, b);
  ASSERT_TRUE(solver.LastSolveWasCondensed()) << solver.FallbackReason();
  // Two pairs lost: the fixed multiplier's slave row and the fixed slave row's multiplier stay.
  EXPECT_EQ(solver.NumberOfPairs(), kDim * kSlave - 2);
  EXPECT_EQ(solver.CondensedSize(), A.rows() - (kDim * kSlave - 2));
  EXPECT_EQ(solver.BlockTypes()[RowOf(dofs, *system.slaves[0], VECTOR_LAGRANGE_MULTIPLIER_X)], BlockType::kOther);
  EXPECT_EQ(solver.BlockTypes()[RowOf(dofs, *system.slaves[1], DISPLACEMENT_Y)], BlockType::kOther);
  EXPECT_LE(RelativeDifference(x, reference), 1e-10);
  EXPECT_EQ(x[RowOf(dofs, *system.slaves[0], VECTOR_LAGRANGE_MULTIPLIER_X)], 0.0);
  EXPECT_EQ(x[RowOf(dofs, *system.slaves[1], DISPLACEMENT_Y)], 0.0);
}

// A warped slave quadrilateral (non-affine): the mortar integrals over its triangulated overlap are
// not exact for its rational shape functions, but each pair's dual basis is biorthogonal in the
// pair's own quadrature, so D stays diagonal and the system condenses.
TEST(MixedULMLinearSolver, WarpedSlaveQuadrilateralCondensesAndMatches) {
  const AssembledSystem<ContactSystem<3, 4, 4>> assembled(std::vector<bool>{true, true, true, false}, true);
  const auto& [system, A, residual, dofs] = assembled;
  const Vector b = RandomRhs(residual, 13);
  MixedULMLinearSolver solver = MakeMixed();
  const Vector x = SolveMixed(solver, A, dofs, b);
  EXPECT_TRUE(solver.LastSolveWasCondensed()) << solver.FallbackReason();
  EXPECT_LE(RelativeDifference(x, SolveMonolithic(A, b)), 1e-10);
}

TEST(MixedULMLinearSolver, NameDirectnessAndSolveWithoutDofData) {
  MixedULMLinearSolver solver = MakeMixed();
  EXPECT_EQ(solver.Name(), "mixed_ulm_linear_solver(umfpack)");
  EXPECT_TRUE(solver.IsDirect());
  EXPECT_TRUE(solver.AdditionalPhysicalDataIsNeeded());
  const AssembledSystem<ContactSystem<2, 2, 2>> assembled(std::vector<bool>{true, false});
  const auto& [system, A, residual, dofs] = assembled;
  const Vector b = RandomRhs(residual, 1);
  solver.Initialize(A);
  Vector x = Vector::Zero(b.size());
  solver.Solve(A, x, b);  // e.g. LinearSolver.Solve from Python: no DoFs, full system
  EXPECT_FALSE(solver.LastSolveWasCondensed());
  EXPECT_NE(solver.FallbackReason().find("ProvideAdditionalData"), std::string::npos);
  EXPECT_LE(RelativeDifference(x, SolveMonolithic(A, b)), 1e-12);
}

// Through the builders: the hook gives the DoFs at each solve; fixed DoFs are identity rows
// (block) or absent (elimination); the inner solver is initialized again only when the
// condensed pattern changes.
class Builders : public ::testing::TestWithParam<std::string> {};

std::shared_ptr<BuilderAndSolver> MakeBuilder(const std::string& type, std::shared_ptr<LinearSolver> solver) {
  if (type == "block") return std::make_shared<BlockBuilderAndSolver>(std::move(solver));
  return std::make_shared<EliminationBuilderAndSolver>(std::move(solver));
}

std::map<const Dof*, double> BuildAndSolve(BuilderAndSolver& builder, ModelPart& part) {
  ResidualBasedIncrementalUpdateStaticScheme scheme;
  builder.SetUpDofSet(part, scheme);
  builder.SetUpSystem();
  builder.Build(scheme, part);
  builder.SolveSystem();
  std::map<const Dof*, double> dx;
  for (const Dof* d : builder.GetDofSet()) dx[d] = builder.Increment()[d->equation_id];
  return dx;
}

double MaxRelativeDifference(const std::map<const Dof*, double>& x, const std::map<const Dof*, double>& reference) {
  double largest = 0.0, error = 0.0;
  for (const auto& [dof, value] : reference) {
    largest = std::max(largest, std::abs(value));
    error = std::max(error, std::abs(x.at(dof) - value));
  }
  g_max_error = std::max(g_max_error, error / largest);
  return error / largest;
}

TEST_P(Builders, FixedDofsAndActiveSetChangesMatchMonolithic) {
  ContactSystem<3, 4, 4> system({true, true, false, true});
  system.slaves[0]->Fix(VECTOR_LAGRANGE_MULTIPLIER_X);  // as in hyper_simple_triangle_patch_test
  system.slaves[3]->Fix(DISPLACEMENT_Z);
  system.others[1]->Fix(DISPLACEMENT_X);
  auto mixed = std::make_shared<MixedULMLinearSolver>(std::make_unique<UmfpackSolver>());
  auto builder = MakeBuilder(GetParam(), mixed);
  auto reference_builder = MakeBuilder(GetParam(), std::make_shared<UmfpackSolver>());

  auto x = BuildAndSolve(*builder, system.root);
  ASSERT_TRUE(mixed->LastSolveWasCondensed()) << mixed->FallbackReason();
  EXPECT_EQ(mixed->NumberOfPairs(), 3 * 3 - 2);
  EXPECT_LE(MaxRelativeDifference(x, BuildAndSolve(*reference_builder, system.root)), 1e-10);
  const int initializations = mixed->InnerInitializations();

  // Same pattern and active set: no new symbolic analysis.
  ResidualBasedIncrementalUpdateStaticScheme scheme;
  builder->Build(scheme, system.root);
  builder->SolveSystem();
  EXPECT_EQ(mixed->InnerInitializations(), initializations);
  EXPECT_TRUE(mixed->LastSolveWasCondensed());

  // The active set changes, the matrix pattern does not.
  const auto solve_and_compare = [&] {
    builder->Build(scheme, system.root);
    builder->SolveSystem();
    ASSERT_TRUE(mixed->LastSolveWasCondensed()) << mixed->FallbackReason();
    std::map<const Dof*, double> changed;
    for (const Dof* d : builder->GetDofSet()) changed[d] = builder->Increment()[d->equation_id];
    EXPECT_LE(MaxRelativeDifference(changed, BuildAndSolve(*reference_builder, system.root)), 1e-10);
  };
  // Swapping two nodes keeps the condensed pattern (the pair's local block is dense): new
  // classification and values, same symbolic analysis.
  system.slaves[2]->Set(ACTIVE, true);
  system.slaves[1]->Set(ACTIVE, false);
  solve_and_compare();
  EXPECT_EQ(mixed->NumberOfPairs(), 3 * 3 - 2);
  EXPECT_EQ(mixed->InnerInitializations(), initializations);
  // Releasing a node removes its unpaired multiplier from the condensed system: new pattern.
  system.slaves[3]->Set(ACTIVE, false);
  solve_and_compare();
  EXPECT_EQ(mixed->NumberOfPairs(), 2 * 3 - 1);
  EXPECT_EQ(mixed->InnerInitializations(), initializations + 1);
}

// Master-slave constraints (issue 18): the rows of T^T K T are those of the unconstrained DoFs,
// each holding its slaves' rows. Tying two DoFs off the interface leaves the dual blocks alone:
// condensed. Tying a slave node's displacement to another slave node's: the elimination builder
// drops the tied row, its node's multiplier is left unpaired and stays in the condensed system
// (condensed); the block builder keeps it as an identity row without a multiplier pivot, and the
// block check sends the system to the full solve. Every answer equals the monolithic one with the
// same constraint.
TEST_P(Builders, MasterSlaveConstraintsCondenseOrSolveInFull) {
  for (const bool on_slave_side : {false, true}) {
    ContactSystem<2, 2, 2> system({true, true});
    auto constrain = [&](BuilderAndSolver& builder) {
      Node& tied = on_slave_side ? *system.slaves[1] : *system.others[1];
      Node& master = on_slave_side ? *system.slaves[0] : *system.others[0];
      builder.AddConstraint(std::make_shared<MasterSlaveConstraint>(1, tied.GetDof(DISPLACEMENT_X),
                                                                    std::vector<Dof*>{&master.GetDof(DISPLACEMENT_X)},
                                                                    std::vector<double>{-1.0}));
    };
    auto mixed = std::make_shared<MixedULMLinearSolver>(std::make_unique<UmfpackSolver>());
    auto builder = MakeBuilder(GetParam(), mixed);
    auto reference_builder = MakeBuilder(GetParam(), std::make_shared<UmfpackSolver>());
    constrain(*builder);
    constrain(*reference_builder);
    const auto x = BuildAndSolve(*builder, system.root);
    const bool condensed = !on_slave_side || std::string(GetParam()) == "elimination";
    EXPECT_EQ(mixed->LastSolveWasCondensed(), condensed) << mixed->FallbackReason();
    if (!condensed) {
      EXPECT_NE(mixed->FallbackReason().find("K(S_A, LM_A)"), std::string::npos) << mixed->FallbackReason();
    }
    EXPECT_LE(MaxRelativeDifference(x, BuildAndSolve(*reference_builder, system.root)), 1e-10) << on_slave_side;
  }
}

INSTANTIATE_TEST_SUITE_P(MixedULM, Builders, ::testing::Values("block", "elimination"));

// The figure of the report, printed after every test has run.
class Figures : public ::testing::Environment {
 public:
  void TearDown() override {
    std::cout << "[ figures  ] max relative error condensed vs monolithic: " << g_max_error << "\n";
  }
};
[[maybe_unused]] const auto* const g_figures = ::testing::AddGlobalTestEnvironment(new Figures);

}  // namespace
}  // namespace mc::test
