// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/linear_solvers/linear_solver.h"
#include "core/linear_solvers/row_partition.h"
#include "core/linear_solvers/sparse_pattern.h"
#include "core/parameters/parameters.h"

struct _p_KSP;  // PETSc's KSP, without its headers

namespace mc {

class PetscCommunicator;

/// PETSc's KSP on the global system (Debian's PETSc: MUMPS, hypre, SuperLU_dist): a sparse direct
/// solver by default (KSPPREONLY + PCLU with MUMPS), or any Krylov method and preconditioner
/// PETSc offers through `petsc_options` (e.g. {"ksp_type": "gmres", "pc_type": "hypre"}).
/// `Initialize` sets up the matrix structure and the KSP once per pattern; PETSc then keeps the
/// symbolic factorization while only the values change.
///
/// Started by `mpirun -n N` (N > 1) the system is distributed (see LinearSolver::Communicator):
/// an MPIAIJ matrix on PETSC_COMM_WORLD whose rows are split by the builder's RowPartition. Each
/// rank is given its own rows only, complete, and inserts them (zeros included, so that the
/// structure is the pattern's and MUMPS keeps its analysis; nothing travels between ranks). The
/// right-hand side is whole on every rank (each takes its rows), and the solution is gathered to
/// every rank (VecScatterCreateToAll). Alone, it works on PETSC_COMM_SELF as before.
///
/// With {"pc_type": "fieldsplit"} the rows are split by their DoF into the fields "u" (the
/// displacements and every other primal unknown, with the block size of the nodes when their
/// DoFs are contiguous) and "lm" (the contact Lagrange multipliers), and preconditioned by a Schur
/// complement factorization: algebraic multigrid (hypre BoomerAMG) on "u", Jacobi on the
/// "selfp" approximation of the multiplier Schur complement, FGMRES outside. This is the
/// solver for 3D contact systems too large to factorize: a direct LU of the saddle-point system
/// grows like n^2 in work, the multigrid cycle like n. Every piece can be overridden with the
/// usual PETSc options (fieldsplit_u_pc_type, pc_fieldsplit_schur_fact_type, ...).
///
/// A Krylov solve keeps its preconditioner (the displacement block's multigrid in the field split,
/// else the whole one) across the solves of one pattern, i.e. the Newton iterations of a load step:
/// with linear elements the displacement block changes only in the contact rows. It is set up again
/// when the iterations the kept one costs beyond those of its first solve, at the measured time per
/// iteration, add up to more than its measured set-up (hertz3d_50k: 8 BoomerAMG set-ups for 20
/// solves; kept for the whole step, the same 488 FGMRES iterations as set up every solve).
///
/// Lives in its own library, libmortarcontact_petsc, built when pkg-config finds PETSc and loaded
/// by the solver factory only when "petsc" is asked for: linking PETSc and its MPI stack into the
/// core made every process slower to start and raised the peak memory of hertz3d_50k by 400 MB.
class PetscSolver : public LinearSolver {
 public:
  struct Options {
    double tolerance = 1.0e-6;  ///< relative residual of Krylov methods (KSP rtol)
    int max_iteration = 200;
    /// Accept the Newton strategy's forcing term (SetForcingTerm): the first solves of a load step
    /// may stop at a relative residual above `tolerance` (ForcingTerm).
    bool inexact_newton = false;
    /// PETSc options without the leading dash, applied under this solver's own prefix, e.g.
    /// {"ksp_type", "preonly"}, {"pc_type", "lu"}, {"pc_factor_mat_solver_type", "mumps"}.
    std::vector<std::pair<std::string, std::string>> petsc_options;
  };

  explicit PetscSolver(Options options);
  PetscSolver(const PetscSolver&) = delete;
  PetscSolver& operator=(const PetscSolver&) = delete;
  ~PetscSolver() override;

  /// The defaults merged under `given` (given values win): preonly + LU by MUMPS, or the
  /// Schur complement preconditioner described above when pc_type is "fieldsplit".
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
  void SetForcingTerm(double eta) override { forcing_term_ = eta; }
  double LastTolerance() const override { return last_tolerance_; }
  /// Solves by a Krylov method and their iterations, or factorizations (ksp_type preonly).
  WorkCounters Counters() const override { return counters_; }
  /// Only the field split needs the DoF of each row.
  bool AdditionalPhysicalDataIsNeeded() const override { return field_split_; }
  void ProvideAdditionalData(const SparseMatrix& A, const std::vector<Dof*>& dof_of_equation) override;
  const AssemblyCommunicator* Communicator() const override;
  void SetRowPartition(const RowPartition& rows) override;

  /// Rows of the last ProvideAdditionalData: primal unknowns and contact multipliers.
  const std::vector<int>& PrimalRows() const { return primal_rows_; }
  const std::vector<int>& MultiplierRows() const { return multiplier_rows_; }
  /// DoFs per node in the primal field (1 when the nodes' rows are not contiguous).
  int PrimalBlockSize() const { return primal_block_size_; }
  /// Rigid-body modes given to the displacement field at the last set-up as its near-nullspace
  /// (6 in 3D, 3 in 2D; 0 when the primal blocks are not the nodes' displacements).
  int RigidBodyModeCount() const { return rigid_body_modes_; }

 private:
  struct Handles;  // PETSc's Mat and KSP (keeps the PETSc headers private)
  void SetFieldSplits(_p_KSP* ksp);
  /// The KSP whose preconditioner is kept between solves: the displacement block's in a field
  /// split with multipliers (once the outer preconditioner is set up), else the solver's own.
  _p_KSP* KeptPreconditionerKsp() const;
  /// After a Krylov solve: whether the next one keeps the preconditioner (see the class comment);
  /// `rebuilt` says whether this one set it up, `setup` and `krylov` are its CPU seconds, and it
  /// stopped at the relative residual `tolerance`.
  void DecidePreconditionerReuse(bool rebuilt, double setup, double krylov, int iterations, double tolerance);
  void ClearOptions();
  /// After MUMPS ran out of the workspace it estimated (its pivots delayed more than the analysis
  /// foresaw, as in a saddle-point system on 4 ranks): raises its allowance (ICNTL(14)) in the
  /// options for a new set-up; false when the factorization is not MUMPS' or the allowance is
  /// already large. The error is MUMPS' global one, so every rank retries together.
  bool RaiseMumpsWorkspace();
  void CreateDistributedMatrix(Handles& handles) const;
  void FillDistributedMatrix();
  Options options_;
  std::unique_ptr<PetscCommunicator> communicator_;  ///< null on one process
  RowPartition partition_;
  std::string prefix_;
  std::unique_ptr<Handles> handles_;
  SparsePattern pattern_;
  SparseMatrix compressed_;
  int iterations_ = 0;
  double forcing_term_ = 0.0;
  double last_tolerance_ = 0.0;
  WorkCounters counters_;
  bool field_split_ = false;
  std::vector<Dof*> dofs_;  ///< of the last ProvideAdditionalData, whose split depends on nothing else
  std::vector<int> primal_rows_;
  std::vector<int> multiplier_rows_;
  int primal_block_size_ = 1;
  int rigid_body_modes_ = 0;
  /// PETSc reads the options of nested solvers (the fields' KSPs) at their first set-up, inside
  /// the first KSPSolve: this solver's options stay in PETSc's database until then.
  bool options_pending_ = false;
};

/// The options of `linear_solver_settings` (tolerance, max_iteration, petsc_options); throws
/// InputError for malformed petsc_options.
PetscSolver::Options ReadPetscOptions(const Parameters& settings);

}  // namespace mc

/// Entry point the solver factory looks up after loading the library.
extern "C" mc::LinearSolver* mortarcontact_create_petsc_solver(const mc::Parameters& settings);
