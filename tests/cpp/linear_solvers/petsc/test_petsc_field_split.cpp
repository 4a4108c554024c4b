// SPDX-License-Identifier: BSD-3-Clause
// Issue 4 (large 3D contact): {"pc_type": "fieldsplit"} splits a real contact system by its DoFs
// into displacements (block size of the nodes) and Lagrange multipliers, and its Schur complement
// preconditioner (BoomerAMG on the displacements) solves it to the direct solution; without
// multipliers the displacement preconditioner takes the whole system.
#include <gtest/gtest.h>

#include "core/linear_solvers/umfpack_solver.h"
#include "petsc/petsc_solver.h"
#include "tests/cpp/contact_linear_solvers/contact_system_fixture.h"

namespace mc::test {
namespace {

double RelativeDifference(const Vector& x, const Vector& y) { return (x - y).norm() / y.norm(); }

Vector DirectSolution(const SparseMatrix& A, const Vector& b) {
  UmfpackSolver umfpack;
  Vector x;
  umfpack.Initialize(A);
  umfpack.Solve(A, x, b);
  return x;
}

PetscSolver::Options FieldSplitOptions() {
  PetscSolver::Options options;
  options.tolerance = 1e-12;
  options.max_iteration = 500;
  options.petsc_options = {{"pc_type", "fieldsplit"}};
  return options;
}

TEST(PetscFieldSplit, ContactSystemSplitByDofsSolvesToTheDirectSolution) {
  AssembledSystem<ContactSystem<3, 4, 4>> assembled(std::vector<bool>{true, false, true, true});
  auto& [system, A, b, dofs] = assembled;
  b.setLinSpaced(b.size(), -1.0, 2.0);

  PetscSolver petsc(FieldSplitOptions());
  EXPECT_TRUE(petsc.AdditionalPhysicalDataIsNeeded());
  EXPECT_FALSE(petsc.IsDirect());
  Vector x;
  petsc.Initialize(A);
  EXPECT_THROW(petsc.Solve(A, x, b), SolutionError);  // no DoFs given: the rows cannot be split
  petsc.ProvideAdditionalData(A, dofs);
  std::size_t multipliers = 0;
  for (const Dof* dof : dofs) multipliers += dof->variable->Name().starts_with("VECTOR_LAGRANGE_MULTIPLIER");
  EXPECT_EQ(petsc.MultiplierRows().size(), multipliers);
  EXPECT_EQ(petsc.PrimalRows().size() + multipliers, static_cast<std::size_t>(A.rows()));
  EXPECT_GT(multipliers, 0u);
  EXPECT_EQ(petsc.PrimalBlockSize(), 3);
  petsc.Solve(A, x, b);
  const Vector direct = DirectSolution(A, b);
  EXPECT_LT(RelativeDifference(x, direct), 1e-9);
  EXPECT_GT(petsc.IterationsNumber(), 1);

  // New values on the same pattern and splits: the KSP is kept and the values are used.
  A.coeffs() *= 2.0;
  petsc.ProvideAdditionalData(A, dofs);
  petsc.Solve(A, x, b);
  EXPECT_LT(RelativeDifference(x, 0.5 * direct), 1e-9);
}

TEST(PetscFieldSplit, TheDisplacementMultigridIsKeptOverTheSolvesOfOnePattern) {
  AssembledSystem<ContactSystem<3, 4, 4>> assembled(std::vector<bool>{true, false, true, true});
  auto& [system, A, b, dofs] = assembled;
  b.setLinSpaced(b.size(), -1.0, 2.0);
  PetscSolver petsc(FieldSplitOptions());
  petsc.ProvideAdditionalData(A, dofs);
  Vector x;
  petsc.Solve(A, x, b);
  EXPECT_EQ(petsc.Counters().preconditioner_setups, 1);
  const int first = petsc.IterationsNumber();

  // The same matrix again: the kept multigrid costs no iteration more, so it stays.
  const Vector c = Vector::LinSpaced(b.size(), 3.0, -1.0);
  petsc.Solve(A, x, c);
  EXPECT_LT(RelativeDifference(x, DirectSolution(A, c)), 1e-9);
  EXPECT_LE(petsc.IterationsNumber(), first + 1);
  EXPECT_EQ(petsc.Counters().preconditioner_setups, 1);

  // Changed values (the contact rows of a Newton iteration): the answer is that of the new matrix.
  SparseMatrix B = A;
  for (Eigen::Index j = 0; j < B.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(B, j); it; ++it)
      if (it.row() == it.col()) it.valueRef() *= 1.0 + 0.01 * static_cast<double>(j % 3);
  petsc.Solve(B, x, b);
  EXPECT_LT(RelativeDifference(x, DirectSolution(B, b)), 1e-9);
  EXPECT_EQ(petsc.Counters().krylov_solves, 3);

  // Another pattern is another KSP: set up afresh.
  petsc.Clear();
  petsc.Solve(A, x, b);
  EXPECT_LT(RelativeDifference(x, DirectSolution(A, b)), 1e-9);
  EXPECT_GE(petsc.Counters().preconditioner_setups, 2);
}

TEST(PetscFieldSplit, InexactNewtonStopsAtTheForcingTermNeverBeforeItsOwnTolerance) {
  AssembledSystem<ContactSystem<3, 4, 4>> assembled(std::vector<bool>{true, false, true, true});
  auto& [system, A, b, dofs] = assembled;
  b.setLinSpaced(b.size(), -1.0, 2.0);
  auto solve = [&](bool inexact_newton, double eta) {
    PetscSolver::Options options = FieldSplitOptions();
    options.inexact_newton = inexact_newton;
    PetscSolver petsc(options);
    petsc.ProvideAdditionalData(A, dofs);
    petsc.SetForcingTerm(eta);
    Vector x;
    petsc.Solve(A, x, b);
    EXPECT_LE((A * x - b).norm(), petsc.LastTolerance() * b.norm() * (1.0 + 1e-9));
    return std::pair{petsc.LastTolerance(), petsc.IterationsNumber()};
  };
  const auto [tight, tight_iterations] = solve(true, 0.0);
  EXPECT_EQ(tight, 1e-12);
  const auto [loose, loose_iterations] = solve(true, 1e-3);
  EXPECT_EQ(loose, 1e-3);
  EXPECT_LT(loose_iterations, tight_iterations);
  EXPECT_EQ(solve(true, 1e-15).first, 1e-12);  // never below its own tolerance
  EXPECT_EQ(solve(false, 1e-3).first, 1e-12);  // not asked for: the forcing term is ignored
}

TEST(PetscFieldSplit, SmoothedAggregationGetsTheRigidBodyModesOfTheDisplacements) {
  AssembledSystem<ContactSystem<3, 4, 4>> assembled(std::vector<bool>{true, true, false, true});
  auto& [system, A, b, dofs] = assembled;
  b.setLinSpaced(b.size(), 1.0, -2.0);
  PetscSolver::Options gamg = FieldSplitOptions();
  gamg.petsc_options.emplace_back("fieldsplit_u_pc_type", "gamg");
  PetscSolver petsc(gamg);
  petsc.ProvideAdditionalData(A, dofs);
  Vector x;
  petsc.Solve(A, x, b);
  EXPECT_EQ(petsc.RigidBodyModeCount(), 6);
  EXPECT_LT(RelativeDifference(x, DirectSolution(A, b)), 1e-9);

  // Primal rows that are not each node's x, y, z displacements in order get no modes.
  std::vector<Dof*> swapped = dofs;
  for (std::size_t i = 0; i + 1 < swapped.size(); ++i)
    if (swapped[i]->variable->Name() == "DISPLACEMENT_X" && swapped[i + 1]->variable->Name() == "DISPLACEMENT_Y") {
      std::swap(swapped[i], swapped[i + 1]);
      break;
    }
  PetscSolver unnamed(gamg);
  unnamed.ProvideAdditionalData(A, swapped);
  unnamed.Solve(A, x, b);
  EXPECT_EQ(unnamed.PrimalBlockSize(), 3);
  EXPECT_EQ(unnamed.RigidBodyModeCount(), 0);
}

TEST(PetscFieldSplit, WithoutMultipliersTheDisplacementPreconditionerTakesTheSystem) {
  AssembledSystem<ContactSystem<3, 4, 4>> assembled(std::vector<bool>{false, false, false, false});
  auto& [system, full, b_full, all] = assembled;
  std::vector<int> keep;
  std::vector<Dof*> dofs;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i]->variable->Name().starts_with("DISPLACEMENT")) {
      keep.push_back(static_cast<int>(i));
      dofs.push_back(all[i]);
    }
  const auto n = static_cast<Eigen::Index>(keep.size());
  Matrix dense(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) dense(i, j) = full.coeff(keep[i], keep[j]);
  const SparseMatrix A = dense.sparseView();
  const Vector b = Vector::LinSpaced(n, 1.0, 3.0);

  PetscSolver petsc(FieldSplitOptions());
  petsc.ProvideAdditionalData(A, dofs);
  EXPECT_TRUE(petsc.MultiplierRows().empty());
  Vector x;
  petsc.Solve(A, x, b);
  EXPECT_LT(RelativeDifference(x, DirectSolution(A, b)), 1e-9);
  const int multigrid_iterations = petsc.IterationsNumber();

  // The displacement field's options apply: Jacobi instead of BoomerAMG needs more iterations.
  PetscSolver::Options jacobi = FieldSplitOptions();
  jacobi.petsc_options.emplace_back("fieldsplit_u_pc_type", "jacobi");
  PetscSolver weaker(jacobi);
  weaker.ProvideAdditionalData(A, dofs);
  weaker.Solve(A, x, b);
  EXPECT_LT(RelativeDifference(x, DirectSolution(A, b)), 1e-9);
  EXPECT_GT(weaker.IterationsNumber(), multigrid_iterations);

  // So do BoomerAMG's own options: a misspelt one is rejected, not silently ignored.
  PetscSolver::Options misspelt = FieldSplitOptions();
  misspelt.petsc_options.emplace_back("fieldsplit_u_pc_hypre_boomeramg_coarsen_type", "HMSI");
  PetscSolver rejected(misspelt);
  rejected.ProvideAdditionalData(A, dofs);
  EXPECT_THROW(rejected.Solve(A, x, b), SolutionError);
}

}  // namespace
}  // namespace mc::test
