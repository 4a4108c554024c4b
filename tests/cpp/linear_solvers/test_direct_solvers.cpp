// SPDX-License-Identifier: BSD-3-Clause
// Linear solvers area: the direct solvers (UMFPACK, KLU, CHOLMOD, Eigen SparseLU, scaling and
// fallback wrappers) reach the manufactured solution of SPD and non-symmetric systems to 1e-10,
// reuse the symbolic analysis when only values change, and name the equation of a zero pivot;
// UMFPACK analyses a new pattern from the ordering of its factors (mapped by DoF onto the equations
// of a system of another order) and reuses their memory.
#include <gtest/gtest.h>
#include <suitesparse/SuiteSparse_config.h>

#include <cstring>
#include <functional>
#include <memory>
#include <vector>

#include "core/linear_solvers/cholmod_solver.h"
#include "core/linear_solvers/eigen_sparse_lu_solver.h"
#include "core/linear_solvers/factorization_reuse_solver.h"
#include "core/linear_solvers/fallback_solver.h"
#include "core/linear_solvers/klu_solver.h"
#include "core/linear_solvers/scaling_solver.h"
#include "core/linear_solvers/suitesparse_memory.h"
#include "core/linear_solvers/umfpack_solver.h"
#include "core/model/dof.h"
#include "core/model/node.h"
#include "core/variables/kernel_variables.h"
#include "test_matrices.h"

namespace mc {
namespace {

using testing::ConvectionDiffusion2D;
using testing::ManufacturedSolution;
using testing::Poisson2D;
using testing::RelativeError;

constexpr int kGrid = 100;  // 10 000 unknowns

void ExpectExactSolve(LinearSolver& solver, const SparseMatrix& A) {
  const Vector exact = ManufacturedSolution(A.rows());
  const Vector b = A * exact;
  Vector x;
  solver.Initialize(A);
  solver.Solve(A, x, b);
  EXPECT_LT(RelativeError(x, exact), 1e-10) << solver.Name();
}

// Same pattern, other values: off-diagonals scaled by 0.9, diagonal raised by 0.5.
SparseMatrix ChangedValues(const SparseMatrix& A) {
  SparseMatrix B = A;
  for (int j = 0; j < B.outerSize(); ++j) {
    for (SparseMatrix::InnerIterator it(B, j); it; ++it)
      it.valueRef() = it.row() == j ? it.value() + 0.5 : 0.9 * it.value();
  }
  return B;
}

template <class Solver>
void ExpectSymbolicReuse(Solver& solver, const SparseMatrix& A) {
  const Vector exact = ManufacturedSolution(A.rows());
  Vector x;
  solver.Initialize(A);
  solver.Solve(A, x, A * exact);
  EXPECT_LT(RelativeError(x, exact), 1e-10);
  const SparseMatrix B = ChangedValues(A);
  solver.Solve(B, x, B * exact);
  EXPECT_LT(RelativeError(x, exact), 1e-10) << solver.Name() << " after a value change";
  EXPECT_EQ(solver.SymbolicAnalysesNumber(), 1) << solver.Name();
  // A new pattern passed to Solve without Initialize is analysed again, not misused.
  const SparseMatrix C = Poisson2D(20);
  const Vector exact_c = ManufacturedSolution(C.rows());
  solver.Solve(C, x, C * exact_c);
  EXPECT_LT(RelativeError(x, exact_c), 1e-10);
  EXPECT_EQ(solver.SymbolicAnalysesNumber(), 2) << solver.Name();
}

long SingularEquation(LinearSolver& solver, const SparseMatrix& A) {
  Vector x;
  const Vector b = Vector::Ones(A.rows());
  solver.Initialize(A);
  try {
    solver.Solve(A, x, b);
  } catch (const SingularMatrixError& error) {
    return error.Equation();
  }
  ADD_FAILURE() << solver.Name() << " accepted a singular matrix";
  return -2;
}

TEST(DirectSolvers, UmfpackSolvesPoissonAndConvectionDiffusion) {
  UmfpackSolver solver;
  ExpectExactSolve(solver, Poisson2D(kGrid));
  ExpectExactSolve(solver, ConvectionDiffusion2D(kGrid));
}

TEST(DirectSolvers, KluSolvesPoissonAndConvectionDiffusion) {
  KluSolver solver;
  ExpectExactSolve(solver, Poisson2D(kGrid));
  ExpectExactSolve(solver, ConvectionDiffusion2D(kGrid));
}

TEST(DirectSolvers, CholmodSolvesPoisson) {
  CholmodSolver solver;
  ExpectExactSolve(solver, Poisson2D(kGrid));
}

TEST(DirectSolvers, EigenSparseLUSolvesWithColamdAndMetis) {
  EigenSparseLUSolver colamd(EigenSparseLUSolver::Ordering::kColamd);
  ExpectExactSolve(colamd, Poisson2D(kGrid));
  ExpectExactSolve(colamd, ConvectionDiffusion2D(kGrid));
  EigenSparseLUSolver metis(EigenSparseLUSolver::Ordering::kMetis);
  ExpectExactSolve(metis, Poisson2D(kGrid));
  ExpectExactSolve(metis, ConvectionDiffusion2D(kGrid));
}

TEST(DirectSolvers, AcceptUncompressedMatrices) {
  SparseMatrix A = ConvectionDiffusion2D(30);
  A.uncompress();
  UmfpackSolver umfpack;
  ExpectExactSolve(umfpack, A);
  KluSolver klu;
  ExpectExactSolve(klu, A);
  EigenSparseLUSolver sparse_lu;
  ExpectExactSolve(sparse_lu, A);
}

TEST(DirectSolvers, SymbolicAnalysisIsReusedWhenOnlyValuesChange) {
  UmfpackSolver umfpack;
  ExpectSymbolicReuse(umfpack, ConvectionDiffusion2D(kGrid));
  KluSolver klu;
  ExpectSymbolicReuse(klu, ConvectionDiffusion2D(kGrid));
  CholmodSolver cholmod;
  ExpectSymbolicReuse(cholmod, Poisson2D(kGrid));
  EigenSparseLUSolver sparse_lu;
  ExpectSymbolicReuse(sparse_lu, ConvectionDiffusion2D(kGrid));
}

// A new pattern of the same order (the contact pairs of a new step): UMFPACK analyses it from the
// column ordering of the factors it holds, and solves exactly; after Clear the ordering is new.
TEST(DirectSolvers, UmfpackAnalysesANewPatternFromTheOrderingOfItsFactors) {
  const SparseMatrix A = ConvectionDiffusion2D(kGrid);
  SparseMatrix B = A;  // A with one more coupling: another pattern of the same order
  B.coeffRef(0, kGrid * kGrid - 1) = -0.25;
  B.makeCompressed();
  const Vector exact = ManufacturedSolution(A.rows());
  UmfpackSolver umfpack;
  Vector x;
  umfpack.FactorizeNumeric(A);
  EXPECT_FALSE(umfpack.LastAnalysisKeptOrdering());
  umfpack.FactorizeNumeric(B);
  EXPECT_EQ(umfpack.SymbolicAnalysesNumber(), 2);
  EXPECT_TRUE(umfpack.LastAnalysisKeptOrdering());
  umfpack.SubstituteFactors(x, B * exact);
  EXPECT_LT(RelativeError(x, exact), 1e-10);
  umfpack.Clear();
  umfpack.FactorizeNumeric(A);
  EXPECT_FALSE(umfpack.LastAnalysisKeptOrdering());
  umfpack.SubstituteFactors(x, A * exact);
  EXPECT_LT(RelativeError(x, exact), 1e-10);
}

// A with one equation inserted before equation `at` (a new contact multiplier: all later
// equations shift by one), coupled to the equations at and at - 1 of A, and the DoFs of the rows.
struct GrownSystem {
  SparseMatrix matrix;
  std::vector<Dof*> dofs;
};

GrownSystem InsertEquation(const SparseMatrix& A, const std::vector<Dof*>& dofs, Dof* inserted, long at) {
  const auto shifted = [at](long i) { return i < at ? i : i + 1; };
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it)
      entries.emplace_back(shifted(it.row()), shifted(j), it.value());
  for (const long neighbour : {at - 1, at + 1}) {
    entries.emplace_back(at, neighbour, -1.0);
    entries.emplace_back(neighbour, at, -1.0);
  }
  entries.emplace_back(at, at, 4.0);
  GrownSystem grown{SparseMatrix(A.rows() + 1, A.cols() + 1), dofs};
  grown.matrix.setFromTriplets(entries.begin(), entries.end());
  grown.matrix.makeCompressed();
  grown.dofs.insert(grown.dofs.begin() + at, inserted);
  return grown;
}

// A new pattern of another order (contact multipliers added at a new step, equations renumbered):
// with the DoFs of the equations, UMFPACK maps the ordering of its factors onto the new equations
// and places the new one; the solve is exact. Without them it cannot relate the two and orders
// afresh.
TEST(DirectSolvers, UmfpackMapsTheOrderingOfItsFactorsOntoTheEquationsOfAGrownSystem) {
  const SparseMatrix A = ConvectionDiffusion2D(kGrid);
  VariablesList variables;
  variables.Add(TEMPERATURE);
  std::vector<std::unique_ptr<Node>> nodes;
  std::vector<Dof> dof_storage(static_cast<std::size_t>(A.rows()) + 1);
  std::vector<Dof*> dofs;
  for (std::size_t i = 0; i < dof_storage.size(); ++i) {
    nodes.push_back(std::make_unique<Node>(static_cast<IndexType>(i + 1), Array3::Zero(), variables, 1));
    dof_storage[i].node = nodes.back().get();
    dof_storage[i].variable = &TEMPERATURE;
    if (i < static_cast<std::size_t>(A.rows())) dofs.push_back(&dof_storage[i]);
  }
  const GrownSystem grown = InsertEquation(A, dofs, &dof_storage.back(), kGrid * kGrid / 2);
  const Vector exact = ManufacturedSolution(grown.matrix.rows());
  Vector x;

  UmfpackSolver umfpack;
  umfpack.ProvideAdditionalData(A, dofs);
  umfpack.FactorizeNumeric(A);
  EXPECT_FALSE(umfpack.LastAnalysisKeptOrdering());
  umfpack.ProvideAdditionalData(grown.matrix, grown.dofs);
  umfpack.FactorizeNumeric(grown.matrix);
  EXPECT_TRUE(umfpack.LastAnalysisKeptOrdering());
  umfpack.SubstituteFactors(x, grown.matrix * exact);
  EXPECT_LT(RelativeError(x, exact), 1e-10);
  // And back: the new equation removed again.
  umfpack.ProvideAdditionalData(A, dofs);
  umfpack.FactorizeNumeric(A);
  EXPECT_TRUE(umfpack.LastAnalysisKeptOrdering());
  const Vector exact_a = ManufacturedSolution(A.rows());
  umfpack.SubstituteFactors(x, A * exact_a);
  EXPECT_LT(RelativeError(x, exact_a), 1e-10);

  // The same through the solver kept across solves, which passes the DoFs on.
  FactorizationReuseSolver reuse(std::make_unique<UmfpackSolver>());
  EXPECT_TRUE(reuse.AdditionalPhysicalDataIsNeeded());
  reuse.ProvideAdditionalData(A, dofs);
  reuse.Solve(A, x, A * exact_a);
  reuse.ProvideAdditionalData(grown.matrix, grown.dofs);
  reuse.Solve(grown.matrix, x, grown.matrix * exact);
  EXPECT_EQ(reuse.Counters().kept_orderings, 1);
  EXPECT_LT(RelativeError(x, exact), 1e-10);

  UmfpackSolver without_dofs;
  without_dofs.FactorizeNumeric(A);
  without_dofs.FactorizeNumeric(grown.matrix);
  EXPECT_FALSE(without_dofs.LastAnalysisKeptOrdering());
  without_dofs.SubstituteFactors(x, grown.matrix * exact);
  EXPECT_LT(RelativeError(x, exact), 1e-10);
}

// The factors' block of one factorization serves the next one (no fresh pages), with the same
// answer to the last bit.
TEST(DirectSolvers, UmfpackReusesTheMemoryOfItsPreviousFactors) {
  const SparseMatrix A = ConvectionDiffusion2D(150);
  const Vector b = A * ManufacturedSolution(A.rows());
  UmfpackSolver umfpack;
  Vector first, second;
  umfpack.FactorizeNumeric(A);
  umfpack.SubstituteFactors(first, b);
  const long reuses = SuiteSparseMemory::Reuses();
  umfpack.FactorizeNumeric(A);
  umfpack.SubstituteFactors(second, b);
  EXPECT_GT(SuiteSparseMemory::Reuses(), reuses);
  EXPECT_EQ(first, second);
}

TEST(SuiteSparseMemory, KeepsTheLargestFreedBlockForARequestOfAboutItsSize) {
  SuiteSparseMemory::Install();
  // Larger than any block the other tests leave kept, which this request therefore releases.
  constexpr std::size_t kBig = 16 * SuiteSparseMemory::kKeptMinBytes;
  void* block = SuiteSparse_config.malloc_func(kBig);
  ASSERT_NE(block, nullptr);
  std::memset(block, 1, 64);
  // Shrinking keeps the block and its capacity (UMFPACK trims its factors after a factorization).
  EXPECT_EQ(SuiteSparse_config.realloc_func(block, kBig / 2), block);
  SuiteSparse_config.free_func(block);
  EXPECT_EQ(SuiteSparseMemory::KeptBytes(), kBig);
  // A small work array does not take it; a request of at least a quarter of its size does.
  void* small = SuiteSparse_config.malloc_func(SuiteSparseMemory::kKeptMinBytes / 2);
  EXPECT_NE(small, block);
  void* again = SuiteSparse_config.calloc_func(kBig / 8, 2);
  EXPECT_EQ(again, block);
  EXPECT_EQ(static_cast<const char*>(again)[kBig / 4 - 1], 0);  // zeroed as calloc does
  EXPECT_EQ(SuiteSparseMemory::KeptBytes(), 0u);
  // Growing past the capacity moves the contents to a new block.
  static_cast<char*>(again)[10] = 7;
  void* grown = SuiteSparse_config.realloc_func(again, 2 * kBig);
  ASSERT_NE(grown, nullptr);
  EXPECT_EQ(static_cast<const char*>(grown)[10], 7);
  SuiteSparse_config.free_func(grown);
  SuiteSparse_config.free_func(small);
  EXPECT_EQ(SuiteSparseMemory::KeptBytes(), 2 * kBig);
}

TEST(DirectSolvers, ZeroRowAndColumnNamesTheEquation) {
  constexpr int kZero = 1234;
  SparseMatrix A = Poisson2D(kGrid);
  testing::ZeroRowAndColumn(A, kZero);
  UmfpackSolver umfpack;
  EXPECT_EQ(SingularEquation(umfpack, A), kZero);
  KluSolver klu;
  EXPECT_EQ(SingularEquation(klu, A), kZero);
  CholmodSolver cholmod;
  EXPECT_EQ(SingularEquation(cholmod, A), kZero);
  EigenSparseLUSolver sparse_lu;
  EXPECT_EQ(SingularEquation(sparse_lu, A), -1);  // Eigen gives no index

  // The same with the zero entries removed from the pattern (structurally singular).
  A.prune(0.0);
  UmfpackSolver umfpack_structural;
  EXPECT_EQ(SingularEquation(umfpack_structural, A), kZero);
  KluSolver klu_structural;
  EXPECT_EQ(SingularEquation(klu_structural, A), kZero);
}

TEST(DirectSolvers, CholmodRejectsIndefiniteAndNonSymmetricMatrices) {
  // Poisson's eigenvalues lie in (0, 8): shifting by 1 gives an indefinite, regular matrix.
  SparseMatrix shifted = Poisson2D(30);
  for (int j = 0; j < shifted.outerSize(); ++j) shifted.coeffRef(j, j) -= 1.0;
  CholmodSolver cholmod;
  const long equation = SingularEquation(cholmod, shifted);
  EXPECT_GE(equation, 0);
  EXPECT_LT(equation, shifted.rows());

  const SparseMatrix convection = ConvectionDiffusion2D(30);
  Vector x;
  cholmod.Initialize(convection);
  EXPECT_THROW(cholmod.Solve(convection, x, Vector::Ones(convection.rows())), SolutionError);
}

TEST(DirectSolvers, FallbackSwitchesFromCholmodToUmfpackOnce) {
  FallbackSolver solver(std::make_unique<CholmodSolver>(), std::make_unique<UmfpackSolver>());
  EXPECT_EQ(solver.Name(), "cholmod");
  ExpectExactSolve(solver, Poisson2D(30));
  EXPECT_FALSE(solver.UsingFallback());

  SparseMatrix shifted = Poisson2D(30);
  for (int j = 0; j < shifted.outerSize(); ++j) shifted.coeffRef(j, j) -= 1.0;
  ExpectExactSolve(solver, shifted);
  EXPECT_TRUE(solver.UsingFallback());
  EXPECT_EQ(solver.Name(), "umfpack");
  EXPECT_NE(solver.SwitchReason().find("not positive definite"), std::string::npos) << solver.SwitchReason();
  // Stays on UMFPACK, which also solves the SPD system.
  ExpectExactSolve(solver, Poisson2D(30));
  EXPECT_EQ(solver.Name(), "umfpack");
}

TEST(DirectSolvers, ScalingSolverSolvesBadlyScaledSystems) {
  // Rows/columns of very different magnitudes, as with penalty or multiplier blocks: D A D with
  // the solution D^-1 z, so that the scaled unknowns D x are O(1) and measured relative to them.
  const SparseMatrix A0 = ConvectionDiffusion2D(kGrid);
  Vector d(A0.rows());
  for (int i = 0; i < d.size(); ++i) d[i] = (i % 7 == 0) ? 1e8 : 1.0;
  const SparseMatrix A = d.asDiagonal() * A0 * d.asDiagonal();
  const Vector z = ManufacturedSolution(A.rows());
  const Vector b = d.cwiseProduct(A0 * z);
  ScalingSolver solver(std::make_unique<UmfpackSolver>());
  EXPECT_EQ(solver.Name(), "scaling(umfpack)");
  Vector x;
  solver.Initialize(A);
  solver.Solve(A, x, b);
  EXPECT_LT(RelativeError(d.cwiseProduct(x), z), 1e-10);
  // S = |diag|^-1/2: 1 / (2 d_i) here, so the scaled matrix has a unit diagonal.
  EXPECT_DOUBLE_EQ(solver.ScaleFactors()[7], 1.0 / (2.0 * 1e8));
  EXPECT_DOUBLE_EQ(solver.ScaleFactors()[1], 0.5);
}

}  // namespace
}  // namespace mc
