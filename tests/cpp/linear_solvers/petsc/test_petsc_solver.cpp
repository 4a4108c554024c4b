// SPDX-License-Identifier: BSD-3-Clause
// Issue 4 (PETSc backend): "petsc" from linear_solver_settings solves SPD, non-symmetric and
// saddle-point systems like UMFPACK (MUMPS LU by default, Krylov methods through petsc_options),
// keeps its structure when only values change, reports zero pivots and non-converging Krylov
// runs, and rejects malformed options. Built with the plugin (when PETSc is found).
#include <gtest/gtest.h>

#include "core/linear_solvers/umfpack_solver.h"
#include "core/parameters/parameters.h"
#include "petsc/petsc_solver.h"
#include "test_matrices.h"

namespace mc {
namespace {

using testing::ConvectionDiffusion2D;
using testing::ManufacturedSolution;
using testing::Poisson2D;
using testing::RelativeError;

// [K B^T; B 0]: a Poisson block with a multiplier per 10th unknown fixing it, as contact
// multipliers do (zero diagonal in the multiplier rows).
SparseMatrix SaddlePoint(int grid) {
  const SparseMatrix K = Poisson2D(grid);
  const int n = static_cast<int>(K.rows());
  const int m = n / 10;
  std::vector<Eigen::Triplet<double, int>> entries;
  for (int j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it) entries.emplace_back(it.row(), j, it.value());
  for (int k = 0; k < m; ++k) {
    entries.emplace_back(n + k, 10 * k, 2.0);
    entries.emplace_back(10 * k, n + k, 2.0);
  }
  SparseMatrix A(n + m, n + m);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}

Vector SolveWith(LinearSolver& solver, const SparseMatrix& A, const Vector& b) {
  Vector x;
  solver.Initialize(A);
  solver.Solve(A, x, b);
  return x;
}

TEST(PetscSolver, DefaultMumpsLuMatchesUmfpackOnSaddlePointAndNonSymmetricSystems) {
  for (const SparseMatrix& A : {SaddlePoint(40), ConvectionDiffusion2D(60)}) {
    const Vector exact = ManufacturedSolution(A.rows());
    const Vector b = A * exact;
    PetscSolver petsc({});
    UmfpackSolver umfpack;
    const Vector x = SolveWith(petsc, A, b);
    EXPECT_LT(RelativeError(x, exact), 1e-10);
    EXPECT_LT(RelativeError(x, SolveWith(umfpack, A, b)), 1e-10);
    EXPECT_TRUE(petsc.IsDirect());
    EXPECT_EQ(petsc.IterationsNumber(), 1);
  }
}

TEST(PetscSolver, NewValuesOnTheSamePatternAreUsed) {
  SparseMatrix A = ConvectionDiffusion2D(40);
  PetscSolver petsc({});
  const Vector exact = ManufacturedSolution(A.rows());
  Vector x;
  petsc.Initialize(A);
  petsc.Solve(A, x, A * exact);
  EXPECT_LT(RelativeError(x, exact), 1e-10);
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) it.valueRef() *= it.row() == j ? 1.5 : 0.8;
  petsc.Solve(A, x, A * exact);
  EXPECT_LT(RelativeError(x, exact), 1e-10);
}

TEST(PetscSolver, KrylovMethodThroughPetscOptions) {
  const SparseMatrix A = Poisson2D(60);
  const Vector exact = ManufacturedSolution(A.rows());
  PetscSolver::Options options;
  options.tolerance = 1e-12;
  options.max_iteration = 1000;
  options.petsc_options = {{"ksp_type", "cg"}, {"pc_type", "icc"}};
  PetscSolver petsc(options);
  const Vector x = SolveWith(petsc, A, A * exact);
  EXPECT_FALSE(petsc.IsDirect());
  EXPECT_GT(petsc.IterationsNumber(), 1);
  EXPECT_LT(RelativeError(x, exact), 1e-8);
}

TEST(PetscSolver, ZeroPivotAndNonConvergenceAreReported) {
  SparseMatrix A = Poisson2D(30);
  testing::ZeroRowAndColumn(A, 100);
  PetscSolver lu({});
  EXPECT_THROW(SolveWith(lu, A, Vector::Ones(A.rows())), SingularMatrixError);

  PetscSolver::Options options;
  options.max_iteration = 3;
  options.tolerance = 1e-12;
  options.petsc_options = {{"ksp_type", "gmres"}, {"pc_type", "none"}};
  PetscSolver krylov(options);
  const SparseMatrix B = ConvectionDiffusion2D(40);
  try {
    SolveWith(krylov, B, Vector::Ones(B.rows()));
    ADD_FAILURE() << "3 unpreconditioned GMRES iterations reported convergence";
  } catch (const SolutionError& error) {
    EXPECT_NE(std::string(error.what()).find("DIVERGED_ITS"), std::string::npos) << error.what();
  }
}

// MUMPS' workspace is its analysis' estimate plus ICNTL(14) percent; pivots delayed beyond the
// estimate (the saddle point's zero diagonals kept in place: ICNTL(6) 0) stop it with
// FACTOR_OUTMEMORY, as the friction block did on 4 ranks. The solver sets up again with more.
TEST(PetscSolver, MumpsOutOfItsWorkspaceIsFactoredAgainWithMore) {
  const SparseMatrix A = SaddlePoint(40);
  const Vector exact = ManufacturedSolution(A.rows());
  PetscSolver::Options options;
  options.petsc_options = {{"mat_mumps_icntl_14", "1"}, {"mat_mumps_icntl_6", "0"}, {"mat_mumps_icntl_8", "0"}};
  PetscSolver petsc(options);
  const Vector x = SolveWith(petsc, A, A * exact);
  EXPECT_LT(RelativeError(x, exact), 1e-10);
  EXPECT_GE(petsc.Counters().factorizations, 2) << "MUMPS did not run out of its workspace: the test tests nothing";
}

TEST(PetscSolver, FromLinearSolverSettingsThroughThePluginEntryPoint) {
  auto create = [](const char* json) {
    Parameters settings(json);
    settings.AddValue("max_iteration", Parameters("200"));
    if (!settings.Has("tolerance")) settings.AddValue("tolerance", Parameters("1e-6"));
    return std::unique_ptr<LinearSolver>(mortarcontact_create_petsc_solver(settings));
  };
  auto solver = create(R"({"tolerance": 1e-10, "petsc_options": {"ksp_type": "gmres", "pc_type": "ilu",
                           "ksp_gmres_restart": 50}})");
  EXPECT_EQ(solver->Name(), "petsc");
  EXPECT_FALSE(solver->IsDirect());
  const SparseMatrix A = ConvectionDiffusion2D(40);
  const Vector exact = ManufacturedSolution(A.rows());
  EXPECT_LT(RelativeError(SolveWith(*solver, A, A * exact), exact), 1e-7);

  EXPECT_THROW(create(R"({"petsc_options": "gmres"})"), InputError);
  auto unknown = create(R"({"petsc_options": {"pc_type": "no_such_pc"}})");
  try {
    SolveWith(*unknown, A, A * exact);
    ADD_FAILURE() << "an unknown preconditioner was accepted";
  } catch (const SolutionError& error) {
    EXPECT_NE(std::string(error.what()).find("no_such_pc"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace mc
