// SPDX-License-Identifier: BSD-3-Clause
// Issue 17: started by `mpirun -n 2` (the ctest petsc_solver_on_two_ranks), the solver puts the
// ranks' own rows of a matrix into one MPIAIJ system, solves it with MUMPS or a Krylov method, and
// hands every rank the whole solution, the same bits on every rank; a process started alone has
// no communicator. Each rank holds only its rows, as the builder's do. With a model cut to a piece
// per rank the matrix's columns and the vectors are the rank's DoFs (RowPartition::ColumnRows) and
// each rank gets its own rows of the solution.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/linear_solvers/assembly_communicator.h"
#include "core/linear_solvers/row_partition.h"
#include "core/parameters/parameters.h"
#include "petsc/petsc_solver.h"
#include "test_matrices.h"

namespace mc {
namespace {

using testing::ConvectionDiffusion2D;
using testing::ManufacturedSolution;
using testing::RelativeError;

TEST(PetscCommunicator, NoneForAProcessStartedAlone) {
  if (AssemblyCommunicator::LaunchedSize() > 1) GTEST_SKIP() << "for a process started alone";
  PetscSolver solver(PetscSolver::Options{});
  EXPECT_EQ(solver.Communicator(), nullptr);
}

TEST(PetscCommunicator, ExclusiveScanAndExchangeOfListsOfEveryLength) {
  if (AssemblyCommunicator::LaunchedSize() < 2) GTEST_SKIP() << "runs under mpirun -n 2 (petsc_solver_on_two_ranks)";
  PetscSolver solver(PetscSolver::Options{});
  const AssemblyCommunicator& communicator = *solver.Communicator();
  const int size = communicator.Size();
  const int rank = communicator.Rank();
  std::int64_t below = 0;
  for (int r = 0; r < rank; ++r) below += 10 * r + 7;
  EXPECT_EQ(communicator.ExclusiveScan(10 * rank + 7), below);
  // Rank r sends rank s the r + s values 1000 r + s, ... (none from rank 0 to itself).
  const auto list = [](int from, int to) {
    std::vector<std::int64_t> values;
    for (int k = 0; k < from + to; ++k) values.push_back(1000 * from + 10 * to + k);
    return values;
  };
  std::vector<std::vector<std::int64_t>> outgoing;
  for (int s = 0; s < size; ++s) outgoing.push_back(list(rank, s));
  const auto incoming = communicator.Exchange(outgoing);
  ASSERT_EQ(incoming.size(), static_cast<std::size_t>(size));
  for (int r = 0; r < size; ++r) EXPECT_EQ(incoming[static_cast<std::size_t>(r)], list(r, rank)) << "from rank " << r;
}

class PetscDistributed : public ::testing::TestWithParam<const char*> {};

TEST_P(PetscDistributed, OwnRowsMakeTheSystemAndEveryRankGetsTheWholeSolution) {
  if (AssemblyCommunicator::LaunchedSize() < 2) GTEST_SKIP() << "runs under mpirun -n 2 (petsc_solver_on_two_ranks)";
  PetscSolver solver(ReadPetscOptions(Parameters(GetParam())));
  const AssemblyCommunicator* communicator = solver.Communicator();
  ASSERT_NE(communicator, nullptr);
  const int size = communicator->Size();
  const int rank = communicator->Rank();

  const SparseMatrix A = ConvectionDiffusion2D(24);  // non-symmetric, 576 rows
  const Vector expected = ManufacturedSolution(A.rows());
  const Vector b = A * expected;
  // Rows in `size` blocks (the first rank's the shortest, as blocks need not be equal).
  std::vector<int> owner(static_cast<std::size_t>(A.rows()));
  for (std::size_t i = 0; i < owner.size(); ++i) owner[i] = static_cast<int>((i + 50) * size / (owner.size() + 50));
  const RowPartition rows = RowPartition::FromOwners(owner, size, rank);
  solver.SetRowPartition(rows);
  const SparseMatrix share = A.middleRows(rows.Begin(), rows.LocalRows());

  solver.Initialize(share);
  for (int solve = 0; solve < 2; ++solve) {  // the second on the kept structure
    Vector x;
    solver.Solve(share, x, b);
    EXPECT_LT(RelativeError(x, expected), 1e-9) << "solve " << solve;
    // The same bits on every rank: their difference, summed, is zero.
    Vector difference = rank == 0 ? Vector(x) : Vector(-x);
    communicator->SumToAll(difference.data(), static_cast<std::size_t>(difference.size()));
    EXPECT_EQ(difference.cwiseAbs().maxCoeff(), 0.0) << "solve " << solve;
  }
}

TEST_P(PetscDistributed, APieceGivesItsColumnsAsItsDofsAndGetsItsOwnRows) {
  if (AssemblyCommunicator::LaunchedSize() < 2) GTEST_SKIP() << "runs under mpirun -n 2 (petsc_solver_on_two_ranks)";
  PetscSolver solver(ReadPetscOptions(Parameters(GetParam())));
  const AssemblyCommunicator& communicator = *solver.Communicator();
  const int size = communicator.Size();
  const int rank = communicator.Rank();
  const SparseMatrix A = ConvectionDiffusion2D(24);
  const Vector expected = ManufacturedSolution(A.rows());
  const Vector b = A * expected;
  std::vector<std::int64_t> counts;
  for (int r = 0; r < size; ++r) counts.push_back((r + 1) * A.rows() / size - r * A.rows() / size);
  const std::int64_t begin = rank * A.rows() / size;
  const std::int64_t own = counts[static_cast<std::size_t>(rank)];
  // The piece's DoFs: its rows, then the other columns its rows use (the ghosts), last first.
  std::vector<std::int64_t> columns;
  for (std::int64_t i = 0; i < own; ++i) columns.push_back(begin + i);
  const SparseMatrix rows = A.middleRows(begin, own);
  std::vector<std::int64_t> ghosts;
  for (Eigen::Index j = 0; j < rows.outerSize(); ++j)
    if ((j < begin || j >= begin + own) && rows.col(j).nonZeros() > 0) ghosts.push_back(j);
  ASSERT_FALSE(ghosts.empty());
  columns.insert(columns.end(), ghosts.rbegin(), ghosts.rend());
  std::vector<Eigen::Triplet<double, int>> entries;
  for (std::size_t c = 0; c < columns.size(); ++c)
    for (SparseMatrix::InnerIterator it(rows, static_cast<Eigen::Index>(columns[c])); it; ++it)
      entries.emplace_back(static_cast<int>(it.row()), static_cast<int>(c), it.value());
  SparseMatrix piece(own, static_cast<Eigen::Index>(columns.size()));
  piece.setFromTriplets(entries.begin(), entries.end());
  piece.makeCompressed();
  ASSERT_EQ(piece.nonZeros(), rows.nonZeros());
  // The ghosts' right-hand side is not this rank's to give: a value that would show.
  Vector b_piece = Vector::Constant(piece.cols(), 1e300);
  b_piece.head(own) = b.segment(begin, own);
  solver.SetRowPartition(RowPartition::FromCounts(counts, rank, columns));
  for (int solve = 0; solve < 2; ++solve) {
    Vector x;
    solver.Solve(piece, x, b_piece);
    ASSERT_EQ(x.size(), piece.cols());
    EXPECT_LT(RelativeError(x.head(own), expected.segment(begin, own)), 1e-9) << "solve " << solve;
  }
}

INSTANTIATE_TEST_SUITE_P(Solvers, PetscDistributed,
                         ::testing::Values(R"({"tolerance": 1e-6, "max_iteration": 200, "petsc_options": {}})",
                                           R"({"tolerance": 1e-13, "max_iteration": 500,
                                               "petsc_options": {"ksp_type": "gmres", "pc_type": "bjacobi"}})"),
                         [](const auto& info) { return info.index == 0 ? "mumps" : "gmres_bjacobi"; });

}  // namespace
}  // namespace mc
