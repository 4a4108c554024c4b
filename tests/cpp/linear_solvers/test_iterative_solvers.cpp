// SPDX-License-Identifier: BSD-3-Clause
// Linear solvers area: Eigen's CG, BiCGSTAB and GMRES with each preconditioner reach their
// tolerance on the Poisson and convection-diffusion systems, and non-convergence raises
// SolutionError with the iterations and the residual reached.
#include <gtest/gtest.h>

#include <string>

#include "core/linear_solvers/iterative_solver.h"
#include "test_matrices.h"

namespace mc {
namespace {

using Method = IterativeSolver::Method;
using Preconditioner = IterativeSolver::Preconditioner;
using testing::ManufacturedSolution;
using testing::RelativeResidual;

constexpr int kGrid = 100;
constexpr double kTolerance = 1e-10;

IterativeSolver::Options Options(Method method, Preconditioner preconditioner) {
  IterativeSolver::Options options;
  options.method = method;
  options.preconditioner = preconditioner;
  options.tolerance = kTolerance;
  options.max_iteration = 5000;
  options.krylov_space_dimension = 100;
  return options;
}

// The true residual may exceed the recursively updated one the solver checks by round-off.
void ExpectConverged(Method method, Preconditioner preconditioner, const SparseMatrix& A) {
  IterativeSolver solver(Options(method, preconditioner));
  const Vector exact = ManufacturedSolution(A.rows());
  const Vector b = A * exact;
  Vector x;
  solver.Initialize(A);
  solver.Solve(A, x, b);
  const double residual = RelativeResidual(A, x, b);
  EXPECT_LE(solver.AchievedResidual(), kTolerance);
  EXPECT_LT(residual, 2.0 * kTolerance) << solver.Name() << " preconditioner " << static_cast<int>(preconditioner);
  EXPECT_GT(solver.IterationsNumber(), 0);
  // Same pattern, other values: the second solve is as accurate.
  SparseMatrix B = A;
  for (int k = 0; k < B.nonZeros(); ++k) B.valuePtr()[k] *= 2.0;
  solver.Solve(B, x, b);
  EXPECT_LT(testing::RelativeError(x, 0.5 * exact), 1e-6);
}

TEST(IterativeSolvers, ConjugateGradientOnPoisson) {
  const SparseMatrix A = testing::Poisson2D(kGrid);
  for (Preconditioner p : {Preconditioner::kNone, Preconditioner::kDiagonal, Preconditioner::kIlu0}) {
    ExpectConverged(Method::kCg, p, A);
  }
}

TEST(IterativeSolvers, BicgstabAndGmresOnConvectionDiffusion) {
  const SparseMatrix A = testing::ConvectionDiffusion2D(kGrid);
  for (Method m : {Method::kBicgstab, Method::kGmres}) {
    for (Preconditioner p :
         {Preconditioner::kNone, Preconditioner::kDiagonal, Preconditioner::kIlu0, Preconditioner::kIlu}) {
      ExpectConverged(m, p, A);
    }
  }
}

TEST(IterativeSolvers, IluNeedsFewerIterationsThanNoPreconditioner) {
  const SparseMatrix A = testing::ConvectionDiffusion2D(kGrid);
  const Vector b = A * ManufacturedSolution(A.rows());
  Vector x;
  IterativeSolver plain(Options(Method::kBicgstab, Preconditioner::kNone));
  plain.Solve(A, x, b);
  IterativeSolver ilu(Options(Method::kBicgstab, Preconditioner::kIlu));
  ilu.Solve(A, x, b);
  EXPECT_LT(ilu.IterationsNumber() * 3, plain.IterationsNumber());
}

TEST(IterativeSolvers, NonConvergenceReportsIterationsAndResidual) {
  const SparseMatrix A = testing::Poisson2D(kGrid);
  IterativeSolver::Options options = Options(Method::kCg, Preconditioner::kNone);
  options.max_iteration = 3;
  IterativeSolver solver(options);
  Vector x;
  try {
    solver.Solve(A, x, Vector::Ones(A.rows()));
    FAIL() << "CG converged in 3 iterations";
  } catch (const SolutionError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("after 3 iterations"), std::string::npos) << message;
    EXPECT_NE(message.find("relative residual"), std::string::npos) << message;
    EXPECT_EQ(solver.IterationsNumber(), 3);
    EXPECT_GT(solver.AchievedResidual(), kTolerance);
  }
}

}  // namespace
}  // namespace mc
