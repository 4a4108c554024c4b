// SPDX-License-Identifier: BSD-3-Clause
// Issue 17 (distributed assembly): ranks simulated by threads of one process, each holding the
// whole model and assembling only the entities it owns, give the serial Newton iterations and
// solution with both builders: every entity is assembled exactly once (a missed or doubled spring
// would change the answer), the residual is summed, the Dirichlet diagonal is put once. The row
// partition keeps a node's DoFs on one rank. No MPI: a barrier sums the ranks' vectors.
#include <gtest/gtest.h>

#include <barrier>
#include <thread>

#include "core/linear_solvers/assembly_communicator.h"
#include "core/linear_solvers/row_partition.h"
#include "core/linear_solvers/umfpack_solver.h"
#include "core/model/master_slave_constraint.h"
#include "core/solving/block_builder_and_solver.h"
#include "core/solving/displacement_criteria.h"
#include "core/solving/elimination_builder_and_solver.h"
#include "core/solving/newton_raphson_strategy.h"
#include "core/solving/residual_based_incremental_update_static_scheme.h"
#include "core/variables/kernel_variables.h"
#include "test_elements.h"
#include "tests/cpp/common/error_message.h"

namespace mc {
namespace {

/// `size` ranks as threads: each writes its vector into its slot, and every rank adds the slots
/// in rank order, so all get the same bits, as the MPI implementation promises.
struct ThreadRanks {
  explicit ThreadRanks(int size) : sync(size), slots(static_cast<std::size_t>(size)) {}
  std::barrier<> sync;
  std::vector<std::vector<double>> slots;
};

class ThreadCommunicator : public AssemblyCommunicator {
 public:
  ThreadCommunicator(ThreadRanks& ranks, int rank) : ranks_(ranks), rank_(rank) {}
  int Rank() const override { return rank_; }
  int Size() const override { return static_cast<int>(ranks_.slots.size()); }
  void SumToAll(double* values, std::size_t count) const override {
    ranks_.slots[static_cast<std::size_t>(rank_)].assign(values, values + count);
    ranks_.sync.arrive_and_wait();
    for (std::size_t i = 0; i < count; ++i) {
      double sum = 0.0;
      for (const auto& slot : ranks_.slots) sum += slot[i];
      values[i] = sum;
    }
    ranks_.sync.arrive_and_wait();  // no rank refills its slot before all have read
  }

 private:
  ThreadRanks& ranks_;
  int rank_;
};

/// The distributed contract of LinearSolver::Communicator with a sequential solver: sums the
/// ranks' shares of the matrix, then every rank solves the whole system.
class SummingSolver : public LinearSolver {
 public:
  SummingSolver(ThreadRanks& ranks, int rank) : communicator_(ranks, rank) {}
  std::string Name() const override { return "summing"; }
  bool IsDirect() const override { return true; }
  void Initialize(const SparseMatrix&) override {}
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override {
    SparseMatrix whole = A;
    long share = 0;
    for (Eigen::Index p = 0; p < A.nonZeros(); ++p) share += A.valuePtr()[p] != 0.0;
    communicator_.SumToAll(whole.valuePtr(), static_cast<std::size_t>(whole.nonZeros()));
    long total = 0;
    for (Eigen::Index p = 0; p < whole.nonZeros(); ++p) total += whole.valuePtr()[p] != 0.0;
    smallest_share = std::min(smallest_share, static_cast<double>(share) / static_cast<double>(total));
    largest_share = std::max(largest_share, static_cast<double>(share) / static_cast<double>(total));
    UmfpackSolver lu;
    lu.Initialize(whole);
    lu.Solve(whole, x, b);
  }
  void Clear() override {}
  const AssemblyCommunicator* Communicator() const override { return &communicator_; }
  void SetRowPartition(const RowPartition& rows) override { partition = rows; }

  RowPartition partition;
  double smallest_share = 1.0;  ///< of the nonzeros of the whole matrix, over the solves
  double largest_share = 0.0;

 private:
  ThreadCommunicator communicator_;
};

// A 2D truss of cubic springs: bottom nodes 1..7, top nodes 8..14, bars along both chords, posts
// and diagonals; nodes 1 and 8 fixed, node 14 pulled down by a prescribed DISPLACEMENT_Y, node 7
// loaded along x. Two DoFs per node, 28 rows.
constexpr IndexType kBays = 6;
struct Truss {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  Truss() {
    const IndexType n = kBays + 1;
    for (IndexType i = 1; i <= n; ++i) {
      test::AddNode(mp, i, static_cast<double>(i), 0.0, 2);
      test::AddNode(mp, n + i, static_cast<double>(i), 1.0, 2);
    }
    IndexType id = 0;
    for (IndexType i = 1; i < n; ++i) {
      test::AddSpring(mp, ++id, i, i + 1, 10.0, 50.0, 2);
      test::AddSpring(mp, ++id, n + i, n + i + 1, 10.0, 50.0, 2);
      test::AddSpring(mp, ++id, i, n + i + 1, 7.0, 20.0, 2);
    }
    for (IndexType i = 1; i <= n; ++i) test::AddSpring(mp, ++id, i, n + i, 12.0, 30.0, 2);
    test::AddLoad(mp, 1, n, 3.0);
    for (IndexType node : {IndexType{1}, n + 1}) {
      mp.GetNode(node).Fix(DISPLACEMENT_X);
      mp.GetNode(node).Fix(DISPLACEMENT_Y);
    }
    mp.GetNode(2 * n).Fix(DISPLACEMENT_Y);
  }
};

std::shared_ptr<BuilderAndSolver> MakeBuilder(const std::string& type, std::shared_ptr<LinearSolver> solver) {
  if (type == "block") return std::make_shared<BlockBuilderAndSolver>(std::move(solver));
  return std::make_shared<EliminationBuilderAndSolver>(std::move(solver));
}

struct TrussRun {
  std::vector<int> iterations;
  std::vector<double> u;  ///< DISPLACEMENT_X, _Y of every node, and REACTION_Y of node 14
};

TrussRun SolveTruss(Truss& truss, std::shared_ptr<BuilderAndSolver> builder) {
  ModelPart& mp = truss.mp;
  NewtonRaphsonStrategy strategy(mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                 std::make_shared<DisplacementCriteria>(1e-12, 1e-15), builder, 30, true);
  TrussRun run;
  for (int step = 1; step <= 3; ++step) {
    mp.CloneTimeStep(step);
    mp.GetNode(2 * (kBays + 1)).FastGetSolutionStepValue(DISPLACEMENT_Y) = -0.05 * step;
    EXPECT_TRUE(strategy.Solve());
    run.iterations.push_back(static_cast<int>(strategy.IterationHistory().size()));
  }
  for (const Node* node : mp.Nodes()) {
    run.u.push_back(node->FastGetSolutionStepValue(DISPLACEMENT_X));
    run.u.push_back(node->FastGetSolutionStepValue(DISPLACEMENT_Y));
  }
  run.u.push_back(mp.GetNode(2 * (kBays + 1)).FastGetSolutionStepValue(REACTION_Y));
  return run;
}

class DistributedBuilders : public ::testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(DistributedBuilders, RanksGiveTheSerialIterationsAndSolution) {
  const auto& [type, size] = GetParam();
  Truss serial_truss;
  const TrussRun serial = SolveTruss(serial_truss, MakeBuilder(type, std::make_shared<UmfpackSolver>()));
  ASSERT_GT(serial.iterations.front(), 2);  // nonlinear: the residual is summed at every iteration

  ThreadRanks ranks(size);
  std::vector<std::unique_ptr<Truss>> trusses;
  std::vector<std::shared_ptr<SummingSolver>> solvers;
  std::vector<TrussRun> runs(static_cast<std::size_t>(size));
  for (int r = 0; r < size; ++r) {
    trusses.push_back(std::make_unique<Truss>());
    solvers.push_back(std::make_shared<SummingSolver>(ranks, r));
  }
  std::vector<std::thread> threads;
  for (int r = 0; r < size; ++r)
    threads.emplace_back([&, r] {
      runs[static_cast<std::size_t>(r)] =
          SolveTruss(*trusses[static_cast<std::size_t>(r)], MakeBuilder(type, solvers[static_cast<std::size_t>(r)]));
    });
  for (auto& t : threads) t.join();

  for (int r = 0; r < size; ++r) {
    const TrussRun& run = runs[static_cast<std::size_t>(r)];
    EXPECT_EQ(run.iterations, serial.iterations) << "rank " << r;
    ASSERT_EQ(run.u.size(), serial.u.size());
    for (std::size_t i = 0; i < run.u.size(); ++i) EXPECT_NEAR(run.u[i], serial.u[i], 1e-12) << "rank " << r;
    EXPECT_EQ(run.u, runs.front().u) << "the ranks' models part ways";
    const SummingSolver& solver = *solvers[static_cast<std::size_t>(r)];
    EXPECT_EQ(solver.partition.Rank(), r);
    EXPECT_EQ(solver.partition.Size(), size);
    // Each rank assembled a real part of the matrix, not all of it.
    EXPECT_GT(solver.smallest_share, 0.05) << "rank " << r;
    EXPECT_LT(solver.largest_share, 0.9) << "rank " << r;
  }
}

INSTANTIATE_TEST_SUITE_P(Builders, DistributedBuilders,
                         ::testing::Combine(::testing::Values("block", "elimination"), ::testing::Values(2, 3)));

TEST(DistributedBuilder, MasterSlaveConstraintsAreNotImplementedYet) {
  Truss truss;
  ThreadRanks ranks(1);
  auto builder = MakeBuilder("block", std::make_shared<SummingSolver>(ranks, 0));
  builder->AddConstraint(std::make_shared<MasterSlaveConstraint>(
      1, truss.mp.GetNode(3).GetDof(DISPLACEMENT_Y), std::vector<Dof*>{&truss.mp.GetNode(2).GetDof(DISPLACEMENT_Y)},
      std::vector<double>{1.0}, 0.0));
  const std::string message = test::ErrorMessageOf<NotImplementedError>([&] { SolveTruss(truss, builder); });
  EXPECT_NE(message.find("master-slave constraints"), std::string::npos) << message;
  EXPECT_NE(message.find("one process"), std::string::npos) << message;
}

TEST(RowPartition, CutsBetweenNodesAndCoversEveryRowOnce) {
  Truss truss;  // 14 nodes, 2 DoFs each: 28 rows
  std::vector<Dof*> rows;
  for (Node* node : truss.mp.Nodes()) {
    rows.push_back(&node->GetDof(DISPLACEMENT_X));
    rows.push_back(&node->GetDof(DISPLACEMENT_Y));
  }
  for (int size : {1, 2, 3, 5, 40}) {
    std::vector<int> owned(rows.size(), 0);
    for (int rank = 0; rank < size; ++rank) {
      const RowPartition p = RowPartition::AtNodes(rows, static_cast<std::int64_t>(rows.size()), size, rank);
      EXPECT_EQ(p.Begin(0), 0);
      EXPECT_EQ(p.End(size - 1), 28);
      EXPECT_EQ(p.Begin() % 2, 0) << "a node's DoFs split at rank " << rank << " of " << size;
      for (std::int64_t i = p.Begin(); i < p.End(); ++i) {
        ++owned[static_cast<std::size_t>(i)];
        EXPECT_TRUE(p.Owns(i));
      }
      EXPECT_EQ(p.Owner(1000), size - 1);  // past the system: fixed DoFs of the elimination builder
    }
    for (int count : owned) EXPECT_EQ(count, 1) << size << " ranks";
  }
  // 28 rows on 3 ranks: the cut at row 9 (node 5's Y) moves to row 10.
  const RowPartition three = RowPartition::AtNodes(rows, 28, 3, 0);
  EXPECT_EQ(three.End(0), 10);
  EXPECT_EQ(three.End(1), 18);
}

}  // namespace
}  // namespace mc
