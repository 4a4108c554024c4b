// SPDX-License-Identifier: BSD-3-Clause
// CreateLinearSolver and NormalizeLinearSolverName: Kratos `linear_solver_settings` (spec 7)
// mapped onto the solvers we have.
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <string_view>
#include <vector>

#include "core/linear_solvers/assembly_communicator.h"
#include "core/linear_solvers/cholmod_solver.h"
#include "core/linear_solvers/eigen_sparse_lu_solver.h"
#include "core/linear_solvers/factorization_reuse_solver.h"
#include "core/linear_solvers/fallback_solver.h"
#include "core/linear_solvers/iterative_solver.h"
#include "core/linear_solvers/klu_solver.h"
#include "core/linear_solvers/linear_solver.h"
#include "core/linear_solvers/scaling_solver.h"
#include "core/linear_solvers/size_selecting_solver.h"
#include "core/linear_solvers/umfpack_solver.h"
#include "core/parameters/no_effect_warnings.h"
#include "core/parameters/parameters.h"
#include "core/utilities/string_utilities.h"

namespace mc {

namespace {

/// Above this many equations "amgcl" runs BiCGSTAB + ILUT instead of UMFPACK (a 3D model of
/// 200k equations factorizes in a few seconds and a few GB).
constexpr long kAmgclDirectSizeLimit = 200000;

const std::map<std::string, std::string>& DeprecatedSolverNames() {
  static const std::map<std::string, std::string> names = {
      {"CGSolver", "cg"},
      {"BICGSTABSolver", "bicgstab"},
      {"DeflatedCGSolver", "deflated_cg"},
      {"TFQMRSolver", "tfqmr"},
      {"SkylineLUFactorizationSolver", "skyline_lu_factorization"},
      {"AMGCL", "amgcl"},
      {"AMGCLSolver", "amgcl"},
      {"AMGCL_NS_Solver", "amgcl_ns"},
      {"ScalingSolver", "scaling"},
      {"GMRESSolver", "gmres"},
      {"Super_LU", "super_lu"},
      {"SuperLUSolver", "super_lu"},
      {"SuperLUIterativeSolver", "super_lu_iterative"},
      {"PastixSolver", "pastix"},
      {"SparseLUSolver", "sparse_lu"},
      {"eigen_sparse_lu", "sparse_lu"},
      {"SparseQRSolver", "sparse_qr"},
      {"PardisoLLTSolver", "pardiso_llt"},
      {"eigen_pardiso_llt", "pardiso_llt"},
      {"PardisoLDLTSolver", "pardiso_ldlt"},
      {"eigen_pardiso_ldlt", "pardiso_ldlt"},
      {"PardisoLUSolver", "pardiso_lu"},
      {"eigen_pardiso_lu", "pardiso_lu"},
  };
  return names;
}

enum class Backend {
  kUmfpack,
  kKlu,
  kCholmod,
  kEigenSparseLU,
  kCg,
  kBicgstab,
  kGmres,
  kAmgcl,
  kScaling,
  kSparseQr,
  kPetsc
};

/// Every accepted normalised name and what runs for it (spec 7.2).
const std::map<std::string, Backend>& SolverBackends() {
  static const std::map<std::string, Backend> backends = {
      {"skyline_lu_factorization", Backend::kUmfpack},
      {"sparse_lu", Backend::kUmfpack},
      {"pardiso_lu", Backend::kUmfpack},
      {"super_lu", Backend::kUmfpack},
      {"pastix", Backend::kUmfpack},
      {"mumps", Backend::kUmfpack},
      {"umfpack", Backend::kUmfpack},
      {"pardiso_ldlt", Backend::kUmfpack},  // LDL^T of an indefinite matrix: never assume SPD
      {"klu", Backend::kKlu},
      {"cholmod", Backend::kCholmod},
      {"pardiso_llt", Backend::kCholmod},
      {"sparse_lu_eigen", Backend::kEigenSparseLU},
      {"cg", Backend::kCg},
      {"deflated_cg", Backend::kCg},
      {"bicgstab", Backend::kBicgstab},
      {"tfqmr", Backend::kBicgstab},
      {"gmres", Backend::kGmres},
      {"super_lu_iterative", Backend::kGmres},  // SuperLU's iterative mode is ILU-preconditioned GMRES
      {"amgcl", Backend::kAmgcl},
      {"amgcl_ns", Backend::kAmgcl},
      {"scaling", Backend::kScaling},
      {"sparse_qr", Backend::kSparseQr},
      {"petsc", Backend::kPetsc},
  };
  return backends;
}

const std::map<std::string, IterativeSolver::Preconditioner>& Preconditioners() {
  static const std::map<std::string, IterativeSolver::Preconditioner> names = {
      {"none", IterativeSolver::Preconditioner::kNone},
      {"diagonal", IterativeSolver::Preconditioner::kDiagonal},
      {"ilu0", IterativeSolver::Preconditioner::kIlu0},
      {"ilu", IterativeSolver::Preconditioner::kIlu},
  };
  return names;
}

std::string NormalizePreconditionerName(const std::string& name) {
  static const std::map<std::string, std::string> deprecated = {
      {"None", "none"},
      {"DiagonalPreconditioner", "diagonal"},
      {"ILU0Preconditioner", "ilu0"},
      {"ILUPreconditioner", "ilu"},
  };
  const auto found = deprecated.find(name);
  return found == deprecated.end() ? name : found->second;
}

/// Defaults of every accepted key. The AMGCL keys (null: any value) are accepted so that AMGCL
/// inputs run, and ignored: "amgcl" maps to UMFPACK or BiCGSTAB + ILUT.
Parameters DefaultSettings() {
  return Parameters(R"({
    "solver_type": "",
    "tolerance": 1.0e-6,
    "max_iteration": 200,
    "max_iteration_number": null,
    "preconditioner_type": "none",
    "scaling": false,
    "verbosity": 0,
    "echo_level": 0,
    "gmres_krylov_space_dimension": 100,
    "ordering": "colamd",
    "smoother_type": null,
    "krylov_type": null,
    "coarsening_type": null,
    "block_size": null,
    "use_block_matrices_if_possible": null,
    "coarse_enough": null,
    "max_levels": null,
    "pre_sweeps": null,
    "post_sweeps": null,
    "provide_coordinates": null,
    "use_gpgpu": null,
    "gpgpu_backend": null,
    "petsc_options": {},
    "inexact_newton": false,
    "reuse_factorization": true
  })");
}

/// The creators registered by the applications, by name.
std::map<std::string, LinearSolverCreator>& RegisteredSolvers() {
  static std::map<std::string, LinearSolverCreator> creators;
  return creators;
}

std::vector<std::string> ValidSolverNames() {
  std::vector<std::string> names;
  for (const auto& [name, backend] : SolverBackends()) names.push_back(name);
  for (const auto& [name, create] : RegisteredSolvers()) names.push_back(name);
  for (const auto& [name, normalised] : DeprecatedSolverNames()) names.push_back(name);
  return names;
}

IterativeSolver::Options ReadIterativeOptions(const Parameters& settings, IterativeSolver::Method method) {
  IterativeSolver::Options options;
  options.method = method;
  options.tolerance = settings["tolerance"].GetDouble();
  if (!(options.tolerance > 0.0)) {
    throw InputError(Concat(settings.Where(), ".tolerance: must be positive, got ", options.tolerance));
  }
  options.max_iteration = settings["max_iteration"].GetInt();
  if (options.max_iteration <= 0) {
    throw InputError(Concat(settings.Where(), ".max_iteration: must be positive, got ", options.max_iteration));
  }
  options.krylov_space_dimension = settings["gmres_krylov_space_dimension"].GetInt();
  if (options.krylov_space_dimension <= 0) {
    throw InputError(Concat(settings.Where(), ".gmres_krylov_space_dimension: must be positive, got ",
                            options.krylov_space_dimension));
  }
  const std::string given = settings["preconditioner_type"].GetString();
  const std::string preconditioner = NormalizePreconditionerName(given);
  const auto found = Preconditioners().find(preconditioner);
  if (found == Preconditioners().end()) {
    std::vector<std::string> valid = {
        "none", "diagonal", "ilu0", "ilu", "None", "DiagonalPreconditioner", "ILU0Preconditioner", "ILUPreconditioner"};
    throw InputError(Concat(settings.Where(), ".preconditioner_type: unknown preconditioner '", given, "'",
                            DidYouMean(given, valid)));
  }
  options.preconditioner = found->second;
  return options;
}

// The PETSc backend is a library of its own, loaded on first use: PETSc brings MPI and a dozen
// libraries that every process would otherwise load (and that raised the peak memory of a 50k
// 3D case by 400 MB). It sits next to the core library; MORTARCONTACT_PETSC_PLUGIN overrides.
std::unique_ptr<LinearSolver> CreatePetscSolver(const Parameters& settings) {
  using Creator = LinearSolver* (*)(const Parameters&);
  static Creator create = nullptr;
  static std::string failure;
  static std::once_flag once;
  std::call_once(once, [] {
    constexpr const char* kLibrary = "libmortarcontact_petsc.so";
    std::string path;
    if (const char* given = std::getenv("MORTARCONTACT_PETSC_PLUGIN")) {
      path = given;
    } else {
      Dl_info info;
      if (dladdr(reinterpret_cast<void*>(&CreatePetscSolver), &info) && info.dli_fname)
        path = (std::filesystem::path(info.dli_fname).parent_path() / kLibrary).string();
      if (path.empty() || !std::filesystem::exists(path)) path = kLibrary;
    }
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      failure = dlerror();
      return;
    }
    create = reinterpret_cast<Creator>(dlsym(handle, "mortarcontact_create_petsc_solver"));
    if (!create) failure = dlerror();
  });
  if (!create)
    throw NotImplementedError(Concat(settings.Where(), ".solver_type: 'petsc' is not available in this build (",
                                     failure,
                                     "); install Debian's petsc-dev (make deps-petsc) and rebuild (make install)"));
  return std::unique_ptr<LinearSolver>(create(settings));
}

/// A direct sparse LU (UMFPACK, KLU) whose factorization is kept across solves as the
/// preconditioner of GMRES, unless `reuse_factorization` is false (mortarcontact's key).
std::unique_ptr<LinearSolver> CreateSparseLu(const Parameters& settings, std::unique_ptr<DirectSolver> direct) {
  if (!settings["reuse_factorization"].GetBool()) return direct;
  return std::make_unique<FactorizationReuseSolver>(std::move(direct));
}

}  // namespace

std::string NormalizeLinearSolverName(const std::string& name) {
  std::string_view view = name;
  constexpr std::string_view kKratos = "KratosMultiphysics.";
  if (view.starts_with(kKratos)) view.remove_prefix(kKratos.size());
  constexpr std::string_view kApplication = "Application.";
  if (const auto at = view.find(kApplication); at != std::string_view::npos)
    view.remove_prefix(at + kApplication.size());
  const std::string stripped(view);
  const auto found = DeprecatedSolverNames().find(stripped);
  return found == DeprecatedSolverNames().end() ? stripped : found->second;
}

void RegisterLinearSolver(const std::string& name, LinearSolverCreator create) {
  RegisteredSolvers()[name] = std::move(create);
}

namespace {

std::unique_ptr<LinearSolver> CreateSerialOrDistributed(const Parameters& user_settings) {
  if (user_settings.Has("solver_type") && user_settings["solver_type"].IsString()) {
    const auto registered =
        RegisteredSolvers().find(NormalizeLinearSolverName(user_settings["solver_type"].GetString()));
    if (registered != RegisteredSolvers().end()) return registered->second(user_settings);
  }
  Parameters settings = user_settings.Clone();
  const Parameters defaults = DefaultSettings();
  settings.ValidateAndAssignDefaults(defaults);
  for (const char* key : {"verbosity", "echo_level"})
    NoEffectWarnings::IfGiven(user_settings, defaults, key, "the linear solvers print nothing");
  for (const char* key : {"smoother_type", "krylov_type", "coarsening_type", "block_size",
                          "use_block_matrices_if_possible", "coarse_enough", "max_levels", "pre_sweeps", "post_sweeps",
                          "provide_coordinates", "use_gpgpu", "gpgpu_backend"})
    NoEffectWarnings::IfGiven(user_settings, defaults, key,
                              "there is no AMG solver: 'amgcl' runs UMFPACK up to a size limit, else BiCGSTAB with "
                              "an incomplete LU");
  // "max_iteration_number" is the spelling of mixed_ulm_solver_parameters (spec 2.7.1).
  if (user_settings.Has("max_iteration_number") && !user_settings.Has("max_iteration")) {
    settings["max_iteration"].SetValue(settings["max_iteration_number"]);
  }

  const std::string given = settings["solver_type"].GetString();
  // No solver_type: Kratos takes the fastest direct solver available, for us UMFPACK.
  const std::string name = given.empty() ? std::string("umfpack") : NormalizeLinearSolverName(given);
  const auto found = SolverBackends().find(name);
  if (found == SolverBackends().end()) {
    throw InputError(Concat(settings.Where(), ".solver_type: unknown linear solver '", given, "'",
                            DidYouMean(given, ValidSolverNames())));
  }

  const Backend backend = found->second;
  if (backend != Backend::kUmfpack && backend != Backend::kKlu && backend != Backend::kAmgcl &&
      backend != Backend::kScaling)
    NoEffectWarnings::IfGiven(user_settings, defaults, "reuse_factorization",
                              "only the sparse LU solvers (umfpack, klu and the names that map to them) keep a "
                              "factorization between solves");
  std::unique_ptr<LinearSolver> solver;
  switch (backend) {
    case Backend::kUmfpack: solver = CreateSparseLu(settings, std::make_unique<UmfpackSolver>()); break;
    case Backend::kKlu: solver = CreateSparseLu(settings, std::make_unique<KluSolver>()); break;
    case Backend::kCholmod:
      // CHOLMOD needs SPD; an indefinite or non-symmetric system switches to UMFPACK for good.
      solver = std::make_unique<FallbackSolver>(std::make_unique<CholmodSolver>(), std::make_unique<UmfpackSolver>());
      break;
    case Backend::kEigenSparseLU: {
      const std::string ordering = settings["ordering"].GetString();
      if (ordering != "colamd" && ordering != "metis") {
        throw InputError(Concat(settings.Where(), ".ordering: unknown ordering '", ordering, "'",
                                DidYouMean(ordering, {"colamd", "metis"})));
      }
      solver = std::make_unique<EigenSparseLUSolver>(ordering == "metis" ? EigenSparseLUSolver::Ordering::kMetis
                                                                         : EigenSparseLUSolver::Ordering::kColamd);
      break;
    }
    case Backend::kCg:
      solver = std::make_unique<IterativeSolver>(ReadIterativeOptions(settings, IterativeSolver::Method::kCg));
      break;
    case Backend::kBicgstab:
      solver = std::make_unique<IterativeSolver>(ReadIterativeOptions(settings, IterativeSolver::Method::kBicgstab));
      break;
    case Backend::kGmres:
      solver = std::make_unique<IterativeSolver>(ReadIterativeOptions(settings, IterativeSolver::Method::kGmres));
      break;
    case Backend::kAmgcl: {
      IterativeSolver::Options options = ReadIterativeOptions(settings, IterativeSolver::Method::kBicgstab);
      options.preconditioner = IterativeSolver::Preconditioner::kIlu;
      solver = std::make_unique<SizeSelectingSolver>(name, kAmgclDirectSizeLimit,
                                                     CreateSparseLu(settings, std::make_unique<UmfpackSolver>()),
                                                     std::make_unique<IterativeSolver>(options));
      break;
    }
    case Backend::kScaling:
      // Kratos' ScalingSolver wraps another solver; as a solver_type of its own it wraps UMFPACK.
      return std::make_unique<ScalingSolver>(CreateSparseLu(settings, std::make_unique<UmfpackSolver>()));
    case Backend::kSparseQr:
      throw NotImplementedError(
          Concat(settings.Where(), ".solver_type: '", given,
                 "' (sparse QR) is not implemented; use 'umfpack' or 'skyline_lu_factorization'"));
    case Backend::kPetsc: solver = CreatePetscSolver(settings); break;
  }
  if (settings["scaling"].GetBool()) {
    // Row scaling needs whole rows, which a distributed run's ranks hold only in part.
    if (solver->Communicator())
      throw NotImplementedError(Concat(settings.Where(), ".scaling: not available in a run on ",
                                       solver->Communicator()->Size(),
                                       " processes (and contact_settings.rescale_linear_solver, which sets it)"));
    solver = std::make_unique<ScalingSolver>(std::move(solver));
  }
  return solver;
}

}  // namespace

std::unique_ptr<LinearSolver> CreateLinearSolver(const Parameters& user_settings) {
  std::unique_ptr<LinearSolver> solver = CreateSerialOrDistributed(user_settings);
  // Under mpirun a solver of one process would run the whole problem N times over.
  if (const int processes = AssemblyCommunicator::LaunchedSize(); processes > 1 && !solver->Communicator()) {
    const std::string given = user_settings.Has("solver_type") && user_settings["solver_type"].IsString()
                                  ? user_settings["solver_type"].GetString()
                                  : std::string("umfpack");
    throw InputError(Concat(user_settings.Where(), ".solver_type: '", given, "' solves on one process, and this run ",
                            "was started on ", processes,
                            " processes (mpirun): only \"petsc\" distributes the system (MUMPS LU by default, "
                            "\"petsc_options\": {\"pc_type\": \"fieldsplit\"} for the field split with BoomerAMG)"));
  }
  return solver;
}

}  // namespace mc
