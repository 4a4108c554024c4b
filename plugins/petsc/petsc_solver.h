// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/linear_solvers/linear_solver.h"
#include "core/linear_solvers/sparse_pattern.h"
#include "core/parameters/parameters.h"

namespace mc {

/// PETSc's KSP on the global system (Debian's PETSc: MUMPS, hypre, SuperLU_dist): a sparse direct
/// solver by default (KSPPREONLY + PCLU with MUMPS), or any Krylov method and preconditioner
/// PETSc offers through `petsc_options` (e.g. {"ksp_type": "gmres", "pc_type": "hypre"}). The
/// matrix lives on PETSC_COMM_SELF for now: the step toward a distributed system is the
/// assembly, not this class. `Initialize` sets up the matrix structure and the KSP once per
/// pattern; PETSc then keeps the symbolic factorization while only the values change.
///
/// Lives in its own library, libmortarcontact_petsc, built when pkg-config finds PETSc and loaded
/// by the solver factory only when "petsc" is asked for: linking PETSc and its MPI stack into the
/// core made every process slower to start and raised the peak memory of hertz3d_50k by 400 MB.
class PetscSolver : public LinearSolver {
 public:
  struct Options {
    double tolerance = 1.0e-6;  ///< relative residual of Krylov methods (KSP rtol)
    int max_iteration = 200;
    /// PETSc options without the leading dash, applied under this solver's own prefix, e.g.
    /// {"ksp_type", "preonly"}, {"pc_type", "lu"}, {"pc_factor_mat_solver_type", "mumps"}.
    std::vector<std::pair<std::string, std::string>> petsc_options;
  };

  explicit PetscSolver(Options options);
  PetscSolver(const PetscSolver&) = delete;
  PetscSolver& operator=(const PetscSolver&) = delete;
  ~PetscSolver() override;

  /// The defaults merged under `given` (given values win): preonly + LU by MUMPS.
  static std::vector<std::pair<std::string, std::string>> WithDefaults(
      std::vector<std::pair<std::string, std::string>> given);

  std::string Name() const override { return "petsc"; }
  bool IsDirect() const override;
  void Initialize(const SparseMatrix& A) override;
  /// Throws SingularMatrixError for a zero pivot of the factorization, SolutionError (with
  /// PETSc's reason, the iterations and the residual) when a Krylov method does not converge.
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override;
  void Clear() override;
  int IterationsNumber() const override { return iterations_; }

 private:
  struct Handles;  // PETSc's Mat and KSP (keeps the PETSc headers private)
  Options options_;
  std::unique_ptr<Handles> handles_;
  SparsePattern pattern_;
  SparseMatrix compressed_;
  int iterations_ = 0;
};

/// The options of `linear_solver_settings` (tolerance, max_iteration, petsc_options); throws
/// InputError for malformed petsc_options.
PetscSolver::Options ReadPetscOptions(const Parameters& settings);

}  // namespace mc

/// Entry point the solver factory looks up after loading the library.
extern "C" mc::LinearSolver* mortarcontact_create_petsc_solver(const mc::Parameters& settings);
