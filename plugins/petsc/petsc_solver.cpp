// SPDX-License-Identifier: BSD-3-Clause
#include "petsc/petsc_solver.h"

#include <dlfcn.h>
#include <petscksp.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <unordered_set>

#include "core/linear_solvers/solve_clocks.h"
#include "core/model/dof.h"
#include "core/model/node.h"
#include "core/utilities/string_utilities.h"
#include "petsc/petsc_communicator.h"

namespace mc {

std::vector<std::pair<std::string, std::string>> PetscSolver::WithDefaults(
    std::vector<std::pair<std::string, std::string>> given) {
  auto value_of = [&](const std::string& key) -> std::string {
    for (const auto& [k, v] : given)
      if (k == key) return v;
    return {};
  };
  auto add = [&](const char* key, const char* value) {
    if (value_of(key).empty()) given.emplace_back(key, value);
  };
  const std::string pc = value_of("pc_type");
  if (pc == "fieldsplit") {
    // The multiplier block has zero diagonals at active nodes: it cannot be smoothed or
    // coarsened with the displacements, hence the Schur complement. The preconditioner is
    // not a fixed linear operator (nested cycles), hence the flexible GMRES.
    add("ksp_type", "fgmres");
    add("pc_fieldsplit_type", "schur");
    add("pc_fieldsplit_schur_fact_type", "lower");
    add("pc_fieldsplit_schur_precondition", "selfp");
    add("fieldsplit_u_ksp_type", "preonly");
    add("fieldsplit_u_pc_type", "hypre");
    // BoomerAMG's set for 3D elasticity (hertz3d_15k: 5.3 s of solve with these against 14.5 s
    // with hypre's defaults and 8.8 s with UMFPACK, same Newton iterations).
    add("fieldsplit_u_pc_hypre_boomeramg_coarsen_type", "HMIS");
    add("fieldsplit_u_pc_hypre_boomeramg_interp_type", "ext+i");
    add("fieldsplit_u_pc_hypre_boomeramg_P_max", "4");
    add("fieldsplit_u_pc_hypre_boomeramg_strong_threshold", "0.5");
    add("fieldsplit_u_pc_hypre_boomeramg_agg_nl", "1");
    // One Gauss-Seidel sweep each way instead of hypre's symmetric one down and up: hertz3d_50k
    // 521 FGMRES iterations instead of 488 for 0.86 x the CPU time of the solves.
    add("fieldsplit_u_pc_hypre_boomeramg_relax_type_down", "SOR/Jacobi");
    add("fieldsplit_u_pc_hypre_boomeramg_relax_type_up", "backward-SOR/Jacobi");
    add("fieldsplit_lm_ksp_type", "preonly");
    add("fieldsplit_lm_pc_type", "jacobi");
    return given;
  }
  add("ksp_type", "preonly");
  add("pc_type", "lu");
  // MUMPS factors only: an ILU or ICC preconditioner keeps PETSc's own factorization.
  const std::string factorization = value_of("pc_type");
  if (factorization == "lu" || factorization == "cholesky") add("pc_factor_mat_solver_type", "mumps");
  return given;
}

namespace {

// PETSc's options database is global: each solver sets its options under a prefix of its own.
std::string UniquePrefix() {
  static std::atomic<int> count{0};
  return Concat("mortarcontact", count++, "_");
}

void Check(PetscErrorCode code, const char* call) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw SolutionError(
      Concat("PETSc: ", call, " failed: ", text ? text : "error", " (code ", static_cast<int>(code), ")"));
}

// PETSc and MPI are initialized once per process, on first use, and finalized at exit. MPI's
// plugins look up libmpi's symbols globally, which a library loaded by Python (RTLD_LOCAL)
// does not provide: libmpi is promoted to global scope first.
void EnsureInitialized() {
  static std::once_flag once;
  static PetscErrorCode status = 0;
  std::call_once(once, [] {
    for (const char* name : {"libmpi.so.40", "libmpi.so"})
      if (dlopen(name, RTLD_NOW | RTLD_GLOBAL | RTLD_NOLOAD)) break;
    PetscBool initialized = PETSC_FALSE;
    PetscInitialized(&initialized);
    if (initialized) return;
    status = PetscInitializeNoArguments();
    if (status == 0) {
      // Errors come back as codes that Check turns into exceptions, without PETSc's traceback.
      PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
      std::atexit([] { PetscFinalize(); });
    }
  });
  Check(status, "PetscInitialize");
}

// Current coordinates of the node of each block of `rows` (block consecutive rows per node), when
// every block holds its node's displacement components in the order x, y[, z]; else empty.
std::vector<double> BlockCoordinates(const std::vector<Dof*>& dofs, const std::vector<PetscInt>& rows, int block) {
  static constexpr const char* kComponents[] = {"DISPLACEMENT_X", "DISPLACEMENT_Y", "DISPLACEMENT_Z"};
  if (block != 2 && block != 3) return {};
  std::vector<double> coordinates;
  coordinates.reserve(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Dof* dof = dofs[static_cast<std::size_t>(rows[k])];
    const std::size_t component = k % static_cast<std::size_t>(block);
    if (dof->variable->Name() != kComponents[component]) return {};
    coordinates.push_back(dof->node->Coordinates()[component]);
  }
  return coordinates;
}

// The rigid-body modes (3 in 2D, 6 in 3D) of the nodes at `coordinates` (dimension per node).
MatNullSpace RigidBodyModes(MPI_Comm comm, const std::vector<double>& coordinates, int dimension) {
  Vec points = nullptr;
  const auto local = static_cast<PetscInt>(coordinates.size());
  Check(VecCreateMPIWithArray(comm, dimension, local, PETSC_DECIDE, coordinates.data(), &points),
        "VecCreateMPIWithArray");
  MatNullSpace modes = nullptr;
  const PetscErrorCode code = MatNullSpaceCreateRigidBody(points, &modes);
  VecDestroy(&points);
  Check(code, "MatNullSpaceCreateRigidBody");
  return modes;
}

}  // namespace

struct PetscSolver::Handles {
  Mat matrix = nullptr;
  KSP ksp = nullptr;
  Eigen::SparseMatrix<double, Eigen::RowMajor, PetscInt> rows;  // A by rows, as AIJ stores it
  // Distributed: this rank's part of the solution, the whole solution, the gather between them
  // (a model cut to pieces: no whole solution, the builder takes the ghosts from their owners).
  Vec solution = nullptr;
  std::vector<PetscInt> global_columns;  // a cut model: `rows`' column indices as the system's rows
  Vec whole = nullptr;
  VecScatter to_all = nullptr;
  // The kept preconditioner of this KSP (DecidePreconditionerReuse): whether the next solve keeps
  // it, the CPU seconds of the solve that set it up and of the last one that kept it, the
  // iterations per decade of residual of its first solve, and the CPU seconds of the iterations
  // beyond that rate since.
  bool keep_preconditioner = false;
  double rebuild_setup_seconds = 0.0;
  double kept_setup_seconds = -1.0;
  double first_iterations_per_decade = 0.0;
  double excess_seconds = 0.0;
  ~Handles() {
    if (to_all) VecScatterDestroy(&to_all);
    if (whole) VecDestroy(&whole);
    if (solution) VecDestroy(&solution);
    if (ksp) KSPDestroy(&ksp);
    if (matrix) MatDestroy(&matrix);
  }
};

PetscSolver::PetscSolver(Options options) : options_(std::move(options)), prefix_(UniquePrefix()) {
  options_.petsc_options = WithDefaults(std::move(options_.petsc_options));
  for (const auto& [key, value] : options_.petsc_options)
    if (key == "pc_type") field_split_ = value == "fieldsplit";
  // A process started alone never loads MPI before its first solve, as before.
  if (const int launched = AssemblyCommunicator::LaunchedSize(); launched > 1) {
    EnsureInitialized();
    communicator_ = std::make_unique<PetscCommunicator>(PETSC_COMM_WORLD);
    if (communicator_->Size() != launched)
      throw SolutionError(Concat("PETSc: the launcher started ", launched, " processes, MPI sees ",
                                 communicator_->Size(), " (is mpirun the one of the MPI that PETSc was built with?)"));
  }
}

const AssemblyCommunicator* PetscSolver::Communicator() const { return communicator_.get(); }

void PetscSolver::SetRowPartition(const RowPartition& rows) {
  if (rows == partition_) return;
  partition_ = rows;
  Clear();
}

PetscSolver::~PetscSolver() {
  handles_.reset();  // before the communicator the matrix lives on
  ClearOptions();
}

void PetscSolver::ClearOptions() {
  if (!options_pending_) return;
  for (const auto& [key, value] : options_.petsc_options) {
    const std::string option = Concat("-", prefix_, key);
    PetscOptionsClearValue(nullptr, option.c_str());
  }
  options_pending_ = false;
}

void PetscSolver::ProvideAdditionalData(const SparseMatrix& A, const std::vector<Dof*>& dof_of_equation) {
  const auto n = static_cast<std::size_t>(A.cols());  // distributed, A holds this rank's rows only
  if (dof_of_equation.size() < n)
    throw SolutionError(Concat("PETSc: ", dof_of_equation.size(), " DoFs for a system of ", n, " rows"));
  // Called before every solve; the DoFs change only with the pattern.
  if (dofs_.size() == n && std::equal(dofs_.begin(), dofs_.end(), dof_of_equation.begin())) return;
  dofs_.assign(dof_of_equation.begin(), dof_of_equation.begin() + static_cast<std::ptrdiff_t>(n));
  std::vector<int> primal, multipliers;
  primal.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool multiplier = dof_of_equation[i]->variable->Name().find("LAGRANGE_MULTIPLIER") != std::string::npos;
    (multiplier ? multipliers : primal).push_back(static_cast<int>(i));
  }
  // Block size: every node owns the same number of consecutive primal rows, once.
  int block = 0;
  std::unordered_set<const Node*> seen;
  for (std::size_t k = 0; k < primal.size() && block >= 0;) {
    const Node* node = dof_of_equation[static_cast<std::size_t>(primal[k])]->node;
    std::size_t end = k + 1;
    while (end < primal.size() && dof_of_equation[static_cast<std::size_t>(primal[end])]->node == node &&
           primal[end] == primal[end - 1] + 1)
      ++end;
    const int count = static_cast<int>(end - k);
    if ((block != 0 && count != block) || !seen.insert(node).second)
      block = -1;
    else
      block = count;
    k = end;
  }
  block = std::max(block, 1);
  if (primal != primal_rows_ || multipliers != multiplier_rows_ || block != primal_block_size_) {
    primal_rows_ = std::move(primal);
    multiplier_rows_ = std::move(multipliers);
    primal_block_size_ = block;
    Clear();  // the splits are fixed at the KSP's set-up
  }
}

bool PetscSolver::IsDirect() const {
  for (const auto& [key, value] : options_.petsc_options)
    if (key == "ksp_type") return value == "preonly";
  return true;
}

void PetscSolver::Initialize(const SparseMatrix& A) {
  EnsureInitialized();
  Clear();
  if (!communicator_ && A.rows() != A.cols())
    throw SolutionError(Concat("PETSc: matrix is ", A.rows(), "x", A.cols(), ", not square"));
  const SparseMatrix& M = CompressedView(A, compressed_);
  auto handles = std::make_unique<Handles>();
  handles->rows = M;
  handles->rows.makeCompressed();
  const auto n = static_cast<PetscInt>(M.rows());
  if (communicator_) {
    CreateDistributedMatrix(*handles);
  } else {
    Check(MatCreate(PETSC_COMM_SELF, &handles->matrix), "MatCreate");
    Check(MatSetSizes(handles->matrix, n, n, n, n), "MatSetSizes");
    Check(MatSetType(handles->matrix, MATSEQAIJ), "MatSetType");
    Check(MatSeqAIJSetPreallocationCSR(handles->matrix, handles->rows.outerIndexPtr(), handles->rows.innerIndexPtr(),
                                       handles->rows.valuePtr()),
          "MatSeqAIJSetPreallocationCSR");
    // Solve copies values straight into AIJ's array: the entry count must be ours, zeros included.
    MatInfo info;
    Check(MatGetInfo(handles->matrix, MAT_LOCAL, &info), "MatGetInfo");
    if (static_cast<long>(info.nz_used) != static_cast<long>(handles->rows.nonZeros()))
      throw SolutionError(
          Concat("PETSc: the AIJ matrix holds ", info.nz_used, " entries for ", handles->rows.nonZeros(), " given"));
  }

  Check(KSPCreate(communicator_ ? communicator_->Comm() : PETSC_COMM_SELF, &handles->ksp), "KSPCreate");
  Check(KSPSetOptionsPrefix(handles->ksp, prefix_.c_str()), "KSPSetOptionsPrefix");
  ClearOptions();
  options_pending_ = true;
  for (const auto& [key, value] : options_.petsc_options) {
    const std::string option = Concat("-", prefix_, key);
    Check(PetscOptionsSetValue(nullptr, option.c_str(), value.empty() ? nullptr : value.c_str()),
          "PetscOptionsSetValue");
  }
  Check(KSPSetTolerances(handles->ksp, options_.tolerance, PETSC_DEFAULT, PETSC_DEFAULT, options_.max_iteration),
        "KSPSetTolerances");
  Check(KSPSetOperators(handles->ksp, handles->matrix, handles->matrix), "KSPSetOperators");
  if (const PetscErrorCode code = KSPSetFromOptions(handles->ksp); code != 0) {
    std::string given;
    for (const auto& [key, value] : options_.petsc_options) given += Concat(given.empty() ? "" : ", ", key, " ", value);
    Check(code, Concat("KSPSetFromOptions with petsc_options {", given, "}").c_str());
  }
  if (field_split_) SetFieldSplits(handles->ksp);
  handles_ = std::move(handles);
  pattern_.Assign(M);
}

void PetscSolver::Solve(const SparseMatrix& A, Vector& x, const Vector& b) {
  assert(b.size() == A.cols());
  const SparseMatrix& M = CompressedView(A, compressed_);
  if (field_split_ && primal_rows_.size() + multiplier_rows_.size() != static_cast<std::size_t>(M.cols()))
    throw SolutionError(Concat("PETSc: pc_type 'fieldsplit' splits the rows by their DoF, given for ",
                               primal_rows_.size() + multiplier_rows_.size(), " of the ", M.cols(),
                               " rows (ProvideAdditionalData)"));
  bool rebuild = !handles_ || !pattern_.Matches(M);
  if (communicator_) {
    // Setting up is collective, but each rank sees its own rows: on a piece of a cut model a new
    // contact pair may change one rank's pattern alone (the ranks then waited in different
    // collectives: hertz3d_50k, field split, 2 ranks).
    double any = rebuild ? 1.0 : 0.0;
    communicator_->SumToAll(&any, 1);
    rebuild = any > 0.0;
  }
  if (rebuild) Initialize(M);
  // Same pattern: refresh the values in place (PETSc keeps its symbolic factorization).
  Eigen::SparseMatrix<double, Eigen::RowMajor, PetscInt>& rows = handles_->rows;
  rows = M;
  if (communicator_) {
    FillDistributedMatrix();
  } else {
    PetscScalar* values = nullptr;
    Check(MatSeqAIJGetArray(handles_->matrix, &values), "MatSeqAIJGetArray");
    std::copy(rows.valuePtr(), rows.valuePtr() + rows.nonZeros(), values);
    Check(MatSeqAIJRestoreArray(handles_->matrix, &values), "MatSeqAIJRestoreArray");
  }
  Check(KSPSetOperators(handles_->ksp, handles_->matrix, handles_->matrix), "KSPSetOperators");

  x.setZero(M.cols());
  const bool krylov = !IsDirect();
  const bool rebuilt = !handles_->keep_preconditioner;
  double setup_seconds = 0.0, krylov_seconds = 0.0;
  PetscReal tolerance = 0.0;
  if (krylov && options_.inexact_newton)
    Check(KSPSetTolerances(handles_->ksp, std::max(options_.tolerance, forcing_term_), PETSC_DEFAULT, PETSC_DEFAULT,
                           PETSC_DEFAULT),
          "KSPSetTolerances");
  if (krylov) Check(KSPGetTolerances(handles_->ksp, &tolerance, nullptr, nullptr, nullptr), "KSPGetTolerances");
  last_tolerance_ = tolerance;
  if (krylov) {
    // Set up apart from the iterations, to weigh the one against the other: the outer
    // preconditioner, then the kept one (in the field split PETSc would otherwise set up the
    // displacement block lazily, inside its first application).
    SolveClocks::Scope clock(setup_seconds);
    Check(KSPSetUp(handles_->ksp), "KSPSetUp");
    if (KSP kept = KeptPreconditionerKsp(); kept != handles_->ksp) Check(KSPSetUp(kept), "KSPSetUp");
  }
  std::optional<SolveClocks::Scope> solve_clock;
  if (krylov) solve_clock.emplace(krylov_seconds);
  const auto n = static_cast<PetscInt>(M.cols());
  Vec rhs = nullptr, solution = nullptr;
  PetscErrorCode solved = 0;
  if (communicator_) {
    const auto begin = static_cast<PetscInt>(partition_.Begin());
    const auto local = static_cast<PetscInt>(partition_.End()) - begin;
    const bool piece = !partition_.ColumnRows().empty();  // b and x: this rank's DoFs, owned rows first
    Check(VecCreateMPIWithArray(communicator_->Comm(), 1, local, static_cast<PetscInt>(partition_.Rows()),
                                b.data() + (piece ? 0 : begin), &rhs),
          "VecCreateMPIWithArray");
    solved = KSPSolve(handles_->ksp, rhs, handles_->solution);
    if (solved == 0 && piece) {
      const PetscScalar* owned = nullptr;
      Check(VecGetArrayRead(handles_->solution, &owned), "VecGetArrayRead");
      std::copy(owned, owned + local, x.data());
      Check(VecRestoreArrayRead(handles_->solution, &owned), "VecRestoreArrayRead");
    } else if (solved == 0) {
      Check(VecScatterBegin(handles_->to_all, handles_->solution, handles_->whole, INSERT_VALUES, SCATTER_FORWARD),
            "VecScatterBegin");
      Check(VecScatterEnd(handles_->to_all, handles_->solution, handles_->whole, INSERT_VALUES, SCATTER_FORWARD),
            "VecScatterEnd");
      const PetscScalar* whole = nullptr;
      Check(VecGetArrayRead(handles_->whole, &whole), "VecGetArrayRead");
      std::copy(whole, whole + n, x.data());
      Check(VecRestoreArrayRead(handles_->whole, &whole), "VecRestoreArrayRead");
    }
  } else {
    Check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, b.data(), &rhs), "VecCreateSeqWithArray");
    Check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, x.data(), &solution), "VecCreateSeqWithArray");
    solved = KSPSolve(handles_->ksp, rhs, solution);
  }
  solve_clock.reset();
  ClearOptions();  // read by now, the nested solvers' ones included
  VecDestroy(&rhs);
  if (solution) VecDestroy(&solution);
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  KSPGetConvergedReason(handles_->ksp, &reason);
  PetscInt iterations = 0;
  KSPGetIterationNumber(handles_->ksp, &iterations);
  iterations_ = std::max<int>(1, static_cast<int>(iterations));
  if (IsDirect()) {
    ++counters_.factorizations;
  } else {
    ++counters_.krylov_solves;
    counters_.krylov_iterations += iterations;
  }
  if (reason == KSP_DIVERGED_PC_FAILED) {
    PC pc = nullptr;
    KSPGetPC(handles_->ksp, &pc);
    PCFailedReason failed = PC_NOERROR;
    PCGetFailedReason(pc, &failed);
    if (failed == PC_FACTOR_NUMERIC_ZEROPIVOT || failed == PC_FACTOR_STRUCT_ZEROPIVOT)
      throw SingularMatrixError("PETSc: singular matrix, zero pivot in the factorization", -1);
    if (failed == PC_FACTOR_OUTMEMORY && RaiseMumpsWorkspace()) {
      Clear();  // set up again with the larger workspace
      Solve(A, x, b);
      return;
    }
    throw SolutionError(Concat("PETSc: the preconditioner failed (", PCFailedReasons[failed], ")"));
  }
  Check(solved, "KSPSolve");
  if (reason < 0 && krylov && !rebuilt) {
    // The kept preconditioner may have drifted too far: one more try with a fresh one.
    handles_->keep_preconditioner = false;
    Check(KSPSetReusePreconditioner(KeptPreconditionerKsp(), PETSC_FALSE), "KSPSetReusePreconditioner");
    Solve(A, x, b);
    return;
  }
  if (reason < 0) {
    PetscReal residual = 0.0;
    KSPGetResidualNorm(handles_->ksp, &residual);
    throw SolutionError(Concat("PETSc: ", KSPConvergedReasons[reason], " after ", iterations,
                               " iterations (residual norm ", residual, ", rtol ", tolerance, ", max_iteration ",
                               options_.max_iteration, ")"));
  }
  if (krylov)
    DecidePreconditionerReuse(rebuilt, setup_seconds, krylov_seconds, static_cast<int>(iterations), tolerance);
}

KSP PetscSolver::KeptPreconditionerKsp() const {
  if (!field_split_ || multiplier_rows_.empty()) return handles_->ksp;
  PC pc = nullptr;
  Check(KSPGetPC(handles_->ksp, &pc), "KSPGetPC");
  PetscInt count = 0;
  KSP* blocks = nullptr;
  Check(PCFieldSplitGetSubKSP(pc, &count, &blocks), "PCFieldSplitGetSubKSP");
  KSP displacements = count > 0 ? blocks[0] : handles_->ksp;
  PetscFree(blocks);
  return displacements;
}

// Keeping costs iterations, setting up costs its set-up: the preconditioner is kept while the
// iterations beyond those of its first solve, at this solve's time per iteration, have cost less
// than one set-up (at most twice the work of the better choice made in hindsight). Its set-up is
// the set-up time of the solve that built it less that of a solve that kept it (the outer
// preconditioner, rebuilt every time). Iterations are compared per decade of the residual they
// reduced: under a forcing term the tolerance changes from solve to solve. Processes decide
// together: a rank alone would hang the rest.
void PetscSolver::DecidePreconditionerReuse(bool rebuilt, double setup, double krylov, int iterations,
                                            double tolerance) {
  Handles& h = *handles_;
  const double decades = std::max(1.0, -std::log10(tolerance));
  if (rebuilt) {
    ++counters_.preconditioner_setups;
    h.rebuild_setup_seconds = setup;
    h.first_iterations_per_decade = iterations / decades;
    h.excess_seconds = 0.0;
  } else {
    h.kept_setup_seconds = setup;
    const double excess = std::max(0.0, iterations - h.first_iterations_per_decade * decades);
    h.excess_seconds += excess * krylov / std::max(1, iterations);
  }
  const double setup_cost = h.rebuild_setup_seconds - std::max(0.0, h.kept_setup_seconds);
  int rebuild = h.excess_seconds > setup_cost ? 1 : 0;
  if (communicator_) MPI_Allreduce(MPI_IN_PLACE, &rebuild, 1, MPI_INT, MPI_MAX, communicator_->Comm());
  h.keep_preconditioner = rebuild == 0;
  Check(KSPSetReusePreconditioner(KeptPreconditionerKsp(), h.keep_preconditioner ? PETSC_TRUE : PETSC_FALSE),
        "KSPSetReusePreconditioner");
}

void PetscSolver::CreateDistributedMatrix(Handles& handles) const {
  const std::vector<std::int64_t>& columns = partition_.ColumnRows();
  const auto n = static_cast<PetscInt>(columns.empty() ? handles.rows.cols() : partition_.Rows());
  if (partition_.Rows() != n || partition_.LocalRows() != handles.rows.rows() ||
      (!columns.empty() && columns.size() != static_cast<std::size_t>(handles.rows.cols())) ||
      partition_.Size() != communicator_->Size())
    throw SolutionError(Concat("PETSc: a row partition of ", partition_.Rows(), " rows (", partition_.LocalRows(),
                               " here) on ", partition_.Size(), " ranks for a system of ", n, " rows (",
                               handles.rows.rows(), " here) on ", communicator_->Size(),
                               " (SetRowPartition before Initialize)"));
  const auto begin = static_cast<PetscInt>(partition_.Begin());
  const auto end = static_cast<PetscInt>(partition_.End());
  // Exact preallocation of this rank's rows: entries in its own columns, and the others.
  std::vector<PetscInt> diagonal(static_cast<std::size_t>(end - begin), 0), off(diagonal.size(), 0);
  const PetscInt* outer = handles.rows.outerIndexPtr();
  const PetscInt* inner = handles.rows.innerIndexPtr();
  if (!columns.empty()) {
    handles.global_columns.resize(static_cast<std::size_t>(handles.rows.nonZeros()));
    for (std::size_t p = 0; p < handles.global_columns.size(); ++p)
      handles.global_columns[p] = static_cast<PetscInt>(columns[static_cast<std::size_t>(inner[p])]);
    inner = handles.global_columns.data();
  }
  for (PetscInt i = 0; i < end - begin; ++i)
    for (PetscInt p = outer[i]; p < outer[i + 1]; ++p)
      ++(inner[p] >= begin && inner[p] < end ? diagonal : off)[static_cast<std::size_t>(i)];
  const MPI_Comm comm = communicator_->Comm();
  Check(MatCreateAIJ(comm, end - begin, end - begin, n, n, 0, diagonal.data(), 0, off.data(), &handles.matrix),
        "MatCreateAIJ");
  Check(MatSetOption(handles.matrix, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE), "MatSetOption");
  Check(VecCreateMPI(comm, end - begin, n, &handles.solution), "VecCreateMPI");
  if (columns.empty())
    Check(VecScatterCreateToAll(handles.solution, &handles.to_all, &handles.whole), "VecScatterCreateToAll");
}

void PetscSolver::FillDistributedMatrix() {
  const auto& rows = handles_->rows;
  const auto begin = static_cast<PetscInt>(partition_.Begin());
  const PetscInt* outer = rows.outerIndexPtr();
  const PetscInt* inner = handles_->global_columns.empty() ? rows.innerIndexPtr() : handles_->global_columns.data();
  const double* values = rows.valuePtr();
  Mat matrix = handles_->matrix;
  // Every entry of the pattern is set: nothing is left of the previous values.
  for (PetscInt i = 0; i < static_cast<PetscInt>(rows.rows()); ++i) {
    const PetscInt row = begin + i;
    Check(MatSetValues(matrix, 1, &row, outer[i + 1] - outer[i], inner + outer[i], values + outer[i], INSERT_VALUES),
          "MatSetValues");
  }
  Check(MatAssemblyBegin(matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  Check(MatAssemblyEnd(matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

bool PetscSolver::RaiseMumpsWorkspace() {
  constexpr const char* key = "mat_mumps_icntl_14";
  bool mumps = false;
  auto given = options_.petsc_options.end();
  for (auto it = options_.petsc_options.begin(); it != options_.petsc_options.end(); ++it) {
    if (it->first == "pc_factor_mat_solver_type") mumps = it->second == "mumps";
    if (it->first == key) given = it;
  }
  if (!mumps) return false;
  // MUMPS' default is 20 %; each retry allows four times as much, at most 1280 %.
  constexpr int largest = 1280;
  const int percent = given == options_.petsc_options.end() ? 20 : std::atoi(given->second.c_str());
  if (percent <= 0 || percent >= largest) return false;
  const std::string raised = std::to_string(std::min(percent * 4, largest));
  if (given == options_.petsc_options.end())
    options_.petsc_options.emplace_back(key, raised);
  else
    given->second = raised;
  return true;
}

void PetscSolver::Clear() {
  handles_.reset();
  pattern_.Clear();
}

void PetscSolver::SetFieldSplits(KSP ksp) {
  PC pc = nullptr;
  Check(KSPGetPC(ksp, &pc), "KSPGetPC");
  rigid_body_modes_ = 0;
  if (primal_rows_.empty() && multiplier_rows_.empty()) return;  // before ProvideAdditionalData: see Solve
  if (multiplier_rows_.empty()) {
    // No contact multipliers (yet): the displacement preconditioner, with its own options
    // (fieldsplit_u_pc_...), on the whole system.
    Check(PCSetOptionsPrefix(pc, Concat(prefix_, "fieldsplit_u_").c_str()), "PCSetOptionsPrefix");
    Check(PCSetFromOptions(pc), "PCSetFromOptions");
    return;
  }
  const MPI_Comm comm = communicator_ ? communicator_->Comm() : PETSC_COMM_SELF;
  auto set = [&](const char* name, const std::vector<int>& rows, int block) {
    // Distributed: each rank names the rows it owns (whole nodes: the partition cuts between them).
    // A cut model: rows are the rank's DoFs, its own first (RowPartition::ColumnRows).
    const std::vector<std::int64_t>& columns = partition_.ColumnRows();
    std::vector<PetscInt> indices, local;
    indices.reserve(rows.size());
    for (const int row : rows)
      if (!communicator_ || (columns.empty() ? partition_.Owns(row) : row < partition_.LocalRows()))
        local.push_back(row);
    for (const PetscInt row : local)
      indices.push_back(columns.empty() ? row : static_cast<PetscInt>(columns[static_cast<std::size_t>(row)]));
    IS is = nullptr;
    Check(ISCreateGeneral(comm, static_cast<PetscInt>(indices.size()), indices.data(), PETSC_COPY_VALUES, &is),
          "ISCreateGeneral");
    if (block > 1) Check(ISSetBlockSize(is, block), "ISSetBlockSize");
    if (block > 1) {
      // The field split hands a near-nullspace composed on a split's IS to its block's matrix,
      // where smoothed-aggregation multigrid (GAMG) takes its coarse spaces from (BoomerAMG
      // ignores it unless told to interpolate vectors).
      const std::vector<double> coordinates = BlockCoordinates(dofs_, local, block);
      if (!coordinates.empty()) {
        MatNullSpace modes = RigidBodyModes(comm, coordinates, block);
        PetscObjectCompose(reinterpret_cast<PetscObject>(is), "nearnullspace", reinterpret_cast<PetscObject>(modes));
        MatNullSpaceDestroy(&modes);
        rigid_body_modes_ = block == 3 ? 6 : 3;
      }
    }
    const PetscErrorCode code = PCFieldSplitSetIS(pc, name, is);
    ISDestroy(&is);
    Check(code, "PCFieldSplitSetIS");
  };
  set("u", primal_rows_, primal_block_size_);
  set("lm", multiplier_rows_, 1);
}

PetscSolver::Options ReadPetscOptions(const Parameters& settings) {
  PetscSolver::Options options;
  options.tolerance = settings["tolerance"].GetDouble();
  options.max_iteration = settings["max_iteration"].GetInt();
  // The factory's settings always hold it; the entry point's direct callers may leave it out.
  options.inexact_newton = settings.Has("inexact_newton") && settings["inexact_newton"].GetBool();
  const Parameters given = settings["petsc_options"];
  if (!given.IsSubParameter())
    throw InputError(Concat(given.Where(), ": must be an object of PETSc options, e.g. {\"pc_type\": \"hypre\"}"));
  for (const std::string& key : given.Keys()) {
    const Parameters value = given[key];
    std::string text;
    if (value.IsString()) {
      text = value.GetString();
    } else if (value.IsBool()) {
      text = value.GetBool() ? "true" : "false";
    } else if (value.IsInt()) {
      text = std::to_string(value.GetInt());
    } else if (value.IsNumber()) {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.17g", value.GetDouble());
      text = buffer;
    } else if (!value.IsNull()) {
      throw InputError(Concat(value.Where(), ": a PETSc option takes a string, number, boolean or null"));
    }
    options.petsc_options.emplace_back(key.starts_with("-") ? key.substr(1) : key, text);
  }
  return options;
}

}  // namespace mc

extern "C" mc::LinearSolver* mortarcontact_create_petsc_solver(const mc::Parameters& settings) {
  return new mc::PetscSolver(mc::ReadPetscOptions(settings));
}
