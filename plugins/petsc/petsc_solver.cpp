// SPDX-License-Identifier: BSD-3-Clause
#include "petsc/petsc_solver.h"

#include <dlfcn.h>
#include <petscksp.h>

#include <algorithm>
#include <cassert>
#include <cstdio>
#include <cstdlib>
#include <mutex>

#include "core/utilities/string_utilities.h"

namespace mc {

std::vector<std::pair<std::string, std::string>> PetscSolver::WithDefaults(
    std::vector<std::pair<std::string, std::string>> given) {
  auto value_of = [&](const std::string& key) -> const std::string* {
    for (const auto& [k, v] : given)
      if (k == key) return &v;
    return nullptr;
  };
  if (!value_of("ksp_type")) given.emplace_back("ksp_type", "preonly");
  if (!value_of("pc_type")) given.emplace_back("pc_type", "lu");
  // MUMPS factors only: an ILU or ICC preconditioner keeps PETSc's own factorization.
  const std::string pc = *value_of("pc_type");
  if ((pc == "lu" || pc == "cholesky") && !value_of("pc_factor_mat_solver_type"))
    given.emplace_back("pc_factor_mat_solver_type", "mumps");
  return given;
}

namespace {

constexpr const char* kPrefix = "mortarcontact_";

void Check(PetscErrorCode code, const char* call) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw SolutionError(Concat("PETSc: ", call, " failed: ", text ? text : "error", " (code ", static_cast<int>(code), ")"));
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

}  // namespace

struct PetscSolver::Handles {
  Mat matrix = nullptr;
  KSP ksp = nullptr;
  Eigen::SparseMatrix<double, Eigen::RowMajor, PetscInt> rows;  // A by rows, as AIJ stores it
  ~Handles() {
    if (ksp) KSPDestroy(&ksp);
    if (matrix) MatDestroy(&matrix);
  }
};

PetscSolver::PetscSolver(Options options) : options_(std::move(options)) {
  options_.petsc_options = WithDefaults(std::move(options_.petsc_options));
}

PetscSolver::~PetscSolver() = default;

bool PetscSolver::IsDirect() const {
  for (const auto& [key, value] : options_.petsc_options)
    if (key == "ksp_type") return value == "preonly";
  return true;
}

void PetscSolver::Initialize(const SparseMatrix& A) {
  EnsureInitialized();
  Clear();
  if (A.rows() != A.cols()) throw SolutionError(Concat("PETSc: matrix is ", A.rows(), "x", A.cols(), ", not square"));
  const SparseMatrix& M = CompressedView(A, compressed_);
  auto handles = std::make_unique<Handles>();
  handles->rows = M;
  handles->rows.makeCompressed();
  const auto n = static_cast<PetscInt>(M.rows());
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
    throw SolutionError(Concat("PETSc: the AIJ matrix holds ", info.nz_used, " entries for ",
                               handles->rows.nonZeros(), " given"));

  Check(KSPCreate(PETSC_COMM_SELF, &handles->ksp), "KSPCreate");
  Check(KSPSetOptionsPrefix(handles->ksp, kPrefix), "KSPSetOptionsPrefix");
  for (const auto& [key, value] : options_.petsc_options) {
    const std::string option = Concat("-", kPrefix, key);
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
  for (const auto& [key, value] : options_.petsc_options) {
    const std::string option = Concat("-", kPrefix, key);
    PetscOptionsClearValue(nullptr, option.c_str());
  }
  handles_ = std::move(handles);
  pattern_.Assign(M);
}

void PetscSolver::Solve(const SparseMatrix& A, Vector& x, const Vector& b) {
  assert(b.size() == A.rows());
  const SparseMatrix& M = CompressedView(A, compressed_);
  if (!handles_ || !pattern_.Matches(M)) Initialize(M);
  // Same pattern: refresh the values in place (PETSc keeps its symbolic factorization).
  Eigen::SparseMatrix<double, Eigen::RowMajor, PetscInt>& rows = handles_->rows;
  rows = M;
  PetscScalar* values = nullptr;
  Check(MatSeqAIJGetArray(handles_->matrix, &values), "MatSeqAIJGetArray");
  std::copy(rows.valuePtr(), rows.valuePtr() + rows.nonZeros(), values);
  Check(MatSeqAIJRestoreArray(handles_->matrix, &values), "MatSeqAIJRestoreArray");
  Check(KSPSetOperators(handles_->ksp, handles_->matrix, handles_->matrix), "KSPSetOperators");

  x.setZero(M.cols());
  const auto n = static_cast<PetscInt>(M.rows());
  Vec rhs = nullptr, solution = nullptr;
  Check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, b.data(), &rhs), "VecCreateSeqWithArray");
  Check(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, n, x.data(), &solution), "VecCreateSeqWithArray");
  const PetscErrorCode solved = KSPSolve(handles_->ksp, rhs, solution);
  VecDestroy(&rhs);
  VecDestroy(&solution);
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  KSPGetConvergedReason(handles_->ksp, &reason);
  PetscInt iterations = 0;
  KSPGetIterationNumber(handles_->ksp, &iterations);
  iterations_ = std::max<int>(1, static_cast<int>(iterations));
  if (reason == KSP_DIVERGED_PC_FAILED) {
    PC pc = nullptr;
    KSPGetPC(handles_->ksp, &pc);
    PCFailedReason failed = PC_NOERROR;
    PCGetFailedReason(pc, &failed);
    if (failed == PC_FACTOR_NUMERIC_ZEROPIVOT || failed == PC_FACTOR_STRUCT_ZEROPIVOT)
      throw SingularMatrixError("PETSc: singular matrix, zero pivot in the factorization", -1);
    throw SolutionError(Concat("PETSc: the preconditioner failed (", PCFailedReasons[failed], ")"));
  }
  Check(solved, "KSPSolve");
  if (reason < 0) {
    PetscReal residual = 0.0;
    KSPGetResidualNorm(handles_->ksp, &residual);
    throw SolutionError(Concat("PETSc: ", KSPConvergedReasons[reason], " after ", iterations,
                               " iterations (residual norm ", residual, ", rtol ", options_.tolerance,
                               ", max_iteration ", options_.max_iteration, ")"));
  }
}

void PetscSolver::Clear() {
  handles_.reset();
  pattern_.Clear();
}

PetscSolver::Options ReadPetscOptions(const Parameters& settings) {
  PetscSolver::Options options;
  options.tolerance = settings["tolerance"].GetDouble();
  options.max_iteration = settings["max_iteration"].GetInt();
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
