// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/linear_solvers/sparse_types.h"
#include "core/utilities/error.h"

namespace mc {

class AssemblyCommunicator;
class Parameters;
class RowPartition;
struct Dof;

/// Raised by a direct solver whose factorization met a zero pivot; `Equation()` is the row or
/// column of the system at fault (-1 if unknown), which the builder translates into the node
/// and DoF name for the user.
class SingularMatrixError : public SolutionError {
 public:
  SingularMatrixError(const std::string& what, long equation) : SolutionError(what), equation_(equation) {}
  long Equation() const noexcept { return equation_; }

 private:
  long equation_;
};

/// Solves A x = b for the global system. The builder calls `Initialize` whenever the sparsity
/// pattern changes (symbolic analysis, orderings) and `Solve` every iteration (numeric
/// factorization or iterations, then the solve), so direct solvers reuse their symbolic work.
class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// The normalised name from the settings (e.g. "umfpack", "cg").
  virtual std::string Name() const = 0;
  virtual bool IsDirect() const = 0;
  /// Symbolic phase for the pattern of A.
  virtual void Initialize(const SparseMatrix& A) = 0;
  /// Numeric phase and solve. Throws SingularMatrixError, or SolutionError when an iterative
  /// solver does not reach its tolerance (with the iterations and the residual reached).
  virtual void Solve(const SparseMatrix& A, Vector& x, const Vector& b) = 0;
  /// Frees factorizations (the next Solve starts afresh).
  virtual void Clear() = 0;
  /// Iterations of the last solve (1 for direct solvers).
  virtual int IterationsNumber() const { return 1; }
  /// Inexact Newton (ForcingTerm): the relative residual at which the next solves may stop. A
  /// Krylov solver that accepts it ("inexact_newton") never stops before its own tolerance;
  /// the others ignore it.
  virtual void SetForcingTerm(double eta) {}
  /// The relative residual the last solve was asked to reach; 0 for a direct solve.
  virtual double LastTolerance() const { return 0.0; }
  /// Work done since construction, for benchmarks and tests: numeric factorizations, solves
  /// answered by a Krylov method preconditioned with kept factors, their iterations (including
  /// those of solves that fell back), fallbacks to a fresh factorization, and the set-ups of a
  /// Krylov method's preconditioner (PETSc: solves that kept the last one do not count).
  struct WorkCounters {
    long factorizations = 0;
    long krylov_solves = 0;
    long krylov_iterations = 0;
    long fallbacks = 0;
    long preconditioner_setups = 0;
    long kept_orderings = 0;  ///< symbolic analyses from the ordering of the factors held (UMFPACK)
  };
  /// Zero for solvers that do not count (iterative ones); wrappers report their inner solver's.
  virtual WorkCounters Counters() const { return {}; }
  /// Whether the solver needs the DoF of each row (e.g. to split the system into physical
  /// blocks); the builder then calls ProvideAdditionalData before every Solve.
  virtual bool AdditionalPhysicalDataIsNeeded() const { return false; }
  /// `dof_of_equation[i]` is the DoF of row i of A (entries beyond A.rows() are not rows).
  virtual void ProvideAdditionalData(const SparseMatrix& A, const std::vector<Dof*>& dof_of_equation) {}

  /// Non-null when the system is distributed over several processes (PETSc under `mpirun -n N`,
  /// N > 1). The contract of Initialize and Solve then changes: A is this rank's rows of the
  /// matrix, complete (row i is system row rows.Begin() + i; every column), b is whole and the
  /// same on every rank, and Solve returns the whole x on every rank, the same bits everywhere.
  /// SetRowPartition tells, before Initialize, which rows each rank owns.
  virtual const AssemblyCommunicator* Communicator() const { return nullptr; }
  virtual void SetRowPartition(const RowPartition& rows) {}
};

/// Builds a solver from `linear_solver_settings` (Kratos names, normalised as in spec 7.1:
/// "skyline_lu_factorization", "SkylineLUFactorizationSolver", "sparse_lu", "umfpack", "klu",
/// "cholmod", "cg", "bicgstab", "gmres", "amgcl", ...). An empty object gives UMFPACK.
/// Unknown names and keys raise InputError with the nearest valid names.
std::unique_ptr<LinearSolver> CreateLinearSolver(const Parameters& settings);

/// The normalised solver name for a Kratos spelling (spec 7.1), without validation.
std::string NormalizeLinearSolverName(const std::string& name);

/// How the applications above the core add their solvers to CreateLinearSolver (contact adds
/// `mixed_ulm_linear_solver`): `create` receives the user's settings, unvalidated (the creator
/// owns its keys). Registering a name again replaces its creator.
using LinearSolverCreator = std::function<std::unique_ptr<LinearSolver>(const Parameters& settings)>;
void RegisterLinearSolver(const std::string& name, LinearSolverCreator create);

}  // namespace mc
