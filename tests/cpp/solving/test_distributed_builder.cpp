// SPDX-License-Identifier: BSD-3-Clause
// Issue 17 (distributed assembly): ranks simulated by threads of one process, each holding the
// whole model and assembling only its own rows (of the nodes METIS gave it), give the serial
// Newton iterations and solution with both builders: every row gets each of its entities once (a
// missed or doubled spring would change the answer), the residual is summed, the Dirichlet
// diagonal is put once. The node partition is compact and the same on every rank; the row
// partition keeps a node's DoFs on one rank. No MPI: ranks are threads (thread_communicator.h).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <thread>

#include "core/linear_solvers/row_partition.h"
#include "core/linear_solvers/umfpack_solver.h"
#include "core/model/master_slave_constraint.h"
#include "core/model/model_part.h"
#include "core/model/model_part_partitioner.h"
#include "core/solving/block_builder_and_solver.h"
#include "core/solving/displacement_criteria.h"
#include "core/solving/elimination_builder_and_solver.h"
#include "core/solving/newton_raphson_strategy.h"
#include "core/solving/node_partition.h"
#include "core/solving/residual_based_incremental_update_static_scheme.h"
#include "core/variables/kernel_variables.h"
#include "test_elements.h"
#include "tests/cpp/common/error_message.h"
#include "tests/cpp/common/thread_communicator.h"

namespace mc {
namespace {

using test::ThreadCommunicator;
using test::ThreadRanks;

/// The distributed contract of LinearSolver::Communicator with a sequential solver: gathers the
/// ranks' rows of the matrix, then every rank solves the whole system.
class SummingSolver : public LinearSolver {
 public:
  SummingSolver(ThreadRanks& ranks, int rank) : communicator_(ranks, rank) {}
  std::string Name() const override { return "summing"; }
  bool IsDirect() const override { return true; }
  void Initialize(const SparseMatrix&) override {}
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override {
    ASSERT_EQ(A.rows(), partition.LocalRows());
    ASSERT_EQ(A.cols(), partition.Rows());
    Matrix dense = Matrix::Zero(A.cols(), A.cols());
    dense.middleRows(partition.Begin(), A.rows()) = Matrix(A);
    communicator_.SumToAll(dense.data(), static_cast<std::size_t>(dense.size()));
    const SparseMatrix whole = dense.sparseView();
    long own = 0;  // nonzeros: the Dirichlet rows and columns keep zeros of the pattern
    for (Eigen::Index p = 0; p < A.nonZeros(); ++p) own += A.valuePtr()[p] != 0.0;
    const double share = static_cast<double>(own) / static_cast<double>(whole.nonZeros());
    smallest_share = std::min(smallest_share, share);
    largest_share = std::max(largest_share, share);
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
    // Each rank kept a real part of the matrix, not all of it.
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

/// The contract of a cut model (RowPartition::ColumnRows): the matrix's columns and the vectors are
/// the rank's DoFs, the owned rows first; x comes back with the owned rows only (its ghosts NaN, so
/// that a ghost the builder does not take from its owner shows).
class PieceSolver : public LinearSolver {
 public:
  PieceSolver(ThreadRanks& ranks, int rank) : communicator_(ranks, rank) {}
  std::string Name() const override { return "piece"; }
  bool IsDirect() const override { return true; }
  void Initialize(const SparseMatrix&) override {}
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override {
    const std::vector<std::int64_t>& columns = partition.ColumnRows();
    ASSERT_EQ(A.rows(), partition.LocalRows());
    ASSERT_EQ(static_cast<std::size_t>(A.cols()), columns.size());
    ASSERT_EQ(b.size(), A.cols());
    largest_columns = std::max(largest_columns, static_cast<double>(A.cols()) / static_cast<double>(partition.Rows()));
    const Eigen::Index n = partition.Rows();
    Matrix dense = Matrix::Zero(n, n);
    Vector rhs = Vector::Zero(n);
    for (Eigen::Index i = 0; i < A.rows(); ++i) rhs[partition.Begin() + i] = b[i];
    for (Eigen::Index c = 0; c < A.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(A, c); it; ++it)
        dense(partition.Begin() + it.row(), columns[static_cast<std::size_t>(c)]) = it.value();
    communicator_.SumToAll(dense.data(), static_cast<std::size_t>(dense.size()));
    communicator_.SumToAll(rhs.data(), static_cast<std::size_t>(rhs.size()));
    const SparseMatrix whole = dense.sparseView();
    Vector solution(n);
    UmfpackSolver lu;
    lu.Initialize(whole);
    lu.Solve(whole, solution, rhs);
    x.setConstant(A.cols(), std::nan(""));
    for (Eigen::Index i = 0; i < A.rows(); ++i) x[i] = solution[partition.Begin() + i];
  }
  void Clear() override {}
  const AssemblyCommunicator* Communicator() const override { return &communicator_; }
  void SetRowPartition(const RowPartition& rows) override { partition = rows; }

  RowPartition partition;
  double largest_columns = 0.0;  ///< the largest share of the system's columns a rank's matrix had

 private:
  ThreadCommunicator communicator_;
};

/// DISPLACEMENT_X, _Y and REACTION_Y of each node of the model part by id, after SolveTruss.
std::map<IndexType, std::array<double, 3>> NodalResults(const ModelPart& mp) {
  std::map<IndexType, std::array<double, 3>> results;
  for (const Node* node : mp.Nodes())
    results[node->Id()] = {node->FastGetSolutionStepValue(DISPLACEMENT_X),
                           node->FastGetSolutionStepValue(DISPLACEMENT_Y), node->FastGetSolutionStepValue(REACTION_Y)};
  return results;
}

/// What each rank of SolvePieces saw.
struct PieceRun {
  std::vector<int> iterations;
  std::map<IndexType, std::array<double, 3>> results;
  std::size_t nodes = 0;  ///< in the piece
  std::string failure;    ///< the error or the strategy's report of a step that failed
};

/// Each rank cuts its truss (changed by `change`) to its piece (the partition stored with the root
/// model part) and solves it.
std::vector<PieceRun> SolvePieces(int size, std::vector<std::shared_ptr<PieceSolver>>& solvers,
                                  const std::function<void(Truss&)>& change = {}) {
  ThreadRanks ranks(size);
  std::vector<std::unique_ptr<Truss>> trusses;
  for (int r = 0; r < size; ++r) {
    trusses.push_back(std::make_unique<Truss>());
    if (change) change(*trusses.back());
    solvers.push_back(std::make_shared<PieceSolver>(ranks, r));
  }
  std::vector<PieceRun> runs(static_cast<std::size_t>(size));
  std::vector<std::thread> threads;
  for (int r = 0; r < size; ++r)
    threads.emplace_back([&, r] {
      const auto k = static_cast<std::size_t>(r);
      ModelPart& mp = trusses[k]->mp;
      auto partition = std::make_shared<const NodePartition>(mp, ThreadCommunicator(ranks, r));
      mp.SetNodePartition(partition);
      ModelPartPartitioner([&](const Node& node) { return partition->Owner(node); }, r).Cut(mp, {});
      runs[k].nodes = mp.NumberOfNodes();
      NewtonRaphsonStrategy strategy(mp, std::make_shared<ResidualBasedIncrementalUpdateStaticScheme>(),
                                     std::make_shared<DisplacementCriteria>(1e-12, 1e-15),
                                     MakeBuilder("block", solvers[k]), 30, true);
      for (int step = 1; step <= 3; ++step) {
        mp.CloneTimeStep(step);
        if (mp.HasNode(2 * (kBays + 1)))
          mp.GetNode(2 * (kBays + 1)).FastGetSolutionStepValue(DISPLACEMENT_Y) = -0.05 * step;
        try {
          if (!strategy.Solve()) runs[k].failure = strategy.FailureReport();
        } catch (const SolutionError& e) {
          runs[k].failure = e.what();
        }
        if (!runs[k].failure.empty()) break;
        runs[k].iterations.push_back(static_cast<int>(strategy.IterationHistory().size()));
      }
      runs[k].results = NodalResults(mp);
    });
  for (auto& t : threads) t.join();
  return runs;
}

class CutModel : public ::testing::TestWithParam<int> {};

TEST_P(CutModel, EachRankSolvingItsPieceGivesTheSerialIterationsAndSolution) {
  const int size = GetParam();
  Truss serial_truss;
  const TrussRun serial = SolveTruss(serial_truss, MakeBuilder("block", std::make_shared<UmfpackSolver>()));
  const auto whole = NodalResults(serial_truss.mp);
  std::vector<std::shared_ptr<PieceSolver>> solvers;
  const std::vector<PieceRun> runs = SolvePieces(size, solvers);
  std::map<IndexType, int> held;
  for (int r = 0; r < size; ++r) {
    const auto& [iterations, results, nodes, failure] = runs[static_cast<std::size_t>(r)];
    EXPECT_EQ(failure, "") << "rank " << r;
    EXPECT_EQ(iterations, serial.iterations) << "rank " << r;
    EXPECT_LT(nodes, whole.size()) << "rank " << r << " kept the whole truss";
    EXPECT_LT(solvers[static_cast<std::size_t>(r)]->largest_columns, 0.9) << "rank " << r;
    // Every node a rank holds, owned or ghost, has the serial values (the ghosts' from their owners).
    for (const auto& [id, values] : results) {
      ++held[id];
      for (std::size_t c = 0; c < 3; ++c)
        EXPECT_NEAR(values[c], whole.at(id)[c], 1e-12 * (1.0 + std::abs(whole.at(id)[c])))
            << "node " << id << " value " << c << " rank " << r;
    }
  }
  EXPECT_EQ(held.size(), whole.size()) << "a node no rank holds";
}

INSTANTIATE_TEST_SUITE_P(Ranks, CutModel, ::testing::Values(2, 3));

TEST(CutModel, AColumnWithoutStiffnessStopsEveryRankAndItsOwnerNamesIt) {
  // Node 15 hangs on node 7 by a spring without stiffness: its columns are empty.
  const auto loose = [](Truss& truss) {
    test::AddNode(truss.mp, 15, 8.0, 0.0, 2);
    test::AddSpring(truss.mp, 100, kBays + 1, 15, 0.0, 0.0, 2);
  };
  std::vector<std::shared_ptr<PieceSolver>> solvers;
  const std::vector<PieceRun> runs = SolvePieces(2, solvers, loose);
  int named = 0;
  for (int r = 0; r < 2; ++r) {
    const std::string& failure = runs[static_cast<std::size_t>(r)].failure;
    EXPECT_NE(failure.find("singular system: no stiffness for "), std::string::npos) << "rank " << r << ": " << failure;
    named += failure.find("DISPLACEMENT_X of node 15") != std::string::npos;
  }
  EXPECT_EQ(named, 1) << runs[0].failure << " | " << runs[1].failure;
}

TEST(CutModel, TheEliminationBuilderIsNotImplementedOnAPiece) {
  Truss truss;
  ThreadRanks ranks(1);
  truss.mp.SetNodePartition(std::make_shared<const NodePartition>(truss.mp, ThreadCommunicator(ranks, 0)));
  auto builder = MakeBuilder("elimination", std::make_shared<PieceSolver>(ranks, 0));
  const std::string message = test::ErrorMessageOf<NotImplementedError>([&] { SolveTruss(truss, builder); });
  EXPECT_NE(message.find("elimination builder on a model cut across 1 processes"), std::string::npos) << message;
}

TEST(RowPartition, OneBlockPerRankInRankOrder) {
  const std::vector<int> owner{0, 0, 0, 2, 2, 3, 3, 3};  // rank 1 owns nothing
  for (int rank = 0; rank < 4; ++rank) {
    const RowPartition p = RowPartition::FromOwners(owner, 4, rank);
    EXPECT_EQ(p.Rows(), 8);
    for (std::size_t i = 0; i < owner.size(); ++i) {
      EXPECT_EQ(p.Owner(static_cast<std::int64_t>(i)), owner[i]) << "row " << i;
      EXPECT_EQ(p.Owns(static_cast<std::int64_t>(i)), owner[i] == rank) << "row " << i;
    }
  }
  const RowPartition second = RowPartition::FromOwners(owner, 4, 1);
  EXPECT_EQ(second.Begin(), 3);
  EXPECT_EQ(second.LocalRows(), 0);
  EXPECT_EQ(RowPartition::FromOwners(owner, 5, 0).Begin(4), 8);  // a fifth rank, empty, at the end
  const std::string message = test::ErrorMessageOf<Error>([] {
    RowPartition::FromOwners(std::vector<int>{0, 1, 0}, 2, 0);
  });
  EXPECT_NE(message.find("row 2 owned by rank 0 after rows of rank 1"), std::string::npos) << message;
}

TEST(NodePartition, MetisCutsTheTrussAcrossNotAlong) {
  constexpr int kRanks = 2;
  ThreadRanks ranks(kRanks);
  std::vector<std::unique_ptr<Truss>> trusses;
  std::vector<NodePartition> partitions(kRanks);
  for (int r = 0; r < kRanks; ++r) trusses.push_back(std::make_unique<Truss>());
  std::vector<std::thread> threads;
  for (int r = 0; r < kRanks; ++r)
    threads.emplace_back([&, r] {
      partitions[static_cast<std::size_t>(r)] =
          NodePartition(trusses[static_cast<std::size_t>(r)]->mp, ThreadCommunicator(ranks, r));
    });
  for (auto& t : threads) t.join();

  for (int r = 0; r < kRanks; ++r) {
    const ModelPart& mp = trusses[static_cast<std::size_t>(r)]->mp;
    const NodePartition& partition = partitions[static_cast<std::size_t>(r)];
    EXPECT_TRUE(partition.IsFor(mp));
    std::vector<int> nodes_of(kRanks, 0);
    for (const Node* node : mp.Nodes()) {
      const int owner = partition.Owner(*node);
      ASSERT_GE(owner, 0);
      ASSERT_LT(owner, kRanks);
      ++nodes_of[static_cast<std::size_t>(owner)];
      EXPECT_EQ(owner, partitions.front().Owner(trusses.front()->mp.GetNode(node->Id()))) << "ranks disagree";
    }
    EXPECT_EQ(nodes_of, (std::vector<int>{7, 7}));
    // Across the bays the cut meets two chords and at most the diagonal and post of one bay; a
    // block of node ids (the bottom chord against the top one) would cut 7 posts and 6 diagonals.
    int cut = 0;
    for (const Element* spring : mp.Elements())
      cut += partition.Owner(spring->GetGeometry()[0]) != partition.Owner(spring->GetGeometry()[1]);
    EXPECT_LE(cut, 4) << "rank " << r;
  }
}

}  // namespace
}  // namespace mc
