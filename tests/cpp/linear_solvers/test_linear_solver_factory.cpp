// SPDX-License-Identifier: BSD-3-Clause
// Linear solvers area, spec 7: Kratos solver names are normalised (7.1) and mapped to our
// solvers (7.2); unknown names and keys raise InputError with the nearest valid one.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

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
#include "core/utilities/logger.h"
#include "test_matrices.h"
#include "tests/cpp/common/error_message.h"

namespace mc {
namespace {

std::unique_ptr<LinearSolver> Create(const std::string& json) { return CreateLinearSolver(Parameters(json)); }

std::string CreateName(const std::string& solver_type) {
  return Create("{\"solver_type\": \"" + solver_type + "\"}")->Name();
}

template <class ErrorType>
std::string ErrorMessage(const std::string& json) {
  const std::string message = test::ErrorMessageOf<ErrorType>([&] { Create(json); });
  if (message.empty()) ADD_FAILURE() << "no error for " << json;
  return message;
}

TEST(LinearSolverFactory, NormalisesEveryKratosSpelling) {
  const std::vector<std::pair<std::string, std::string>> table = {
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
      {"skyline_lu_factorization", "skyline_lu_factorization"},
      {"KratosMultiphysics.skyline_lu_factorization", "skyline_lu_factorization"},
      {"LinearSolversApplication.sparse_lu", "sparse_lu"},
      {"EigenSolversApplication.pardiso_lu", "pardiso_lu"},
      {"ExternalSolversApplication.super_lu", "super_lu"},
      {"KratosMultiphysics.ExternalSolversApplication.SuperLUSolver", "super_lu"},
      {"KratosMultiphysics.AMGCLSolver", "amgcl"},
  };
  for (const auto& [kratos, normalised] : table) EXPECT_EQ(NormalizeLinearSolverName(kratos), normalised) << kratos;
}

TEST(LinearSolverFactory, MapsNamesToOurSolvers) {
  const std::vector<std::pair<std::string, std::string>> table = {
      {"skyline_lu_factorization", "umfpack"},
      {"SkylineLUFactorizationSolver", "umfpack"},
      {"sparse_lu", "umfpack"},
      {"LinearSolversApplication.sparse_lu", "umfpack"},
      {"pardiso_lu", "umfpack"},
      {"super_lu", "umfpack"},
      {"pastix", "umfpack"},
      {"mumps", "umfpack"},
      {"umfpack", "umfpack"},
      {"pardiso_ldlt", "umfpack"},
      {"eigen_sparse_lu", "umfpack"},
      {"klu", "klu"},
      {"cholmod", "cholmod"},
      {"pardiso_llt", "cholmod"},
      {"sparse_lu_eigen", "sparse_lu_eigen"},
      {"cg", "cg"},
      {"deflated_cg", "cg"},
      {"CGSolver", "cg"},
      {"bicgstab", "bicgstab"},
      {"tfqmr", "bicgstab"},
      {"gmres", "gmres"},
      {"super_lu_iterative", "gmres"},
      {"amgcl", "amgcl"},
      {"AMGCL_NS_Solver", "amgcl_ns"},
      {"scaling", "scaling(umfpack)"},
  };
  for (const auto& [kratos, ours] : table) EXPECT_EQ(CreateName(kratos), ours) << kratos;
  EXPECT_EQ(Create("{}")->Name(), "umfpack");
  EXPECT_TRUE(Create("{}")->IsDirect());
  EXPECT_NE(dynamic_cast<FallbackSolver*>(Create(R"({"solver_type": "cholmod"})").get()), nullptr);
}

TEST(LinearSolverFactory, SparseLuKeepsItsFactorizationUnlessToldNot) {
  for (const char* name : {"", "sparse_lu", "skyline_lu_factorization", "umfpack", "klu"}) {
    const auto solver = Create(std::string(R"({"solver_type": ")") + name + "\"}");
    const auto* reuse = dynamic_cast<const FactorizationReuseSolver*>(solver.get());
    ASSERT_NE(reuse, nullptr) << name;
    EXPECT_EQ(reuse->Name(), std::string(name) == "klu" ? "klu" : "umfpack");
  }
  EXPECT_NE(dynamic_cast<UmfpackSolver*>(Create(R"({"solver_type": "sparse_lu", "reuse_factorization": false})").get()),
            nullptr);
  EXPECT_NE(dynamic_cast<KluSolver*>(Create(R"({"solver_type": "klu", "reuse_factorization": false})").get()), nullptr);
  // Other solvers keep no factorization: the key warns that it has no effect there.
  std::vector<std::string> warnings;
  Logger::SetSink([&warnings](Logger::Level level, const std::string& message) {
    if (level == Logger::Level::Warning) warnings.push_back(message);
  });
  NoEffectWarnings::Reset();
  Create(R"({"solver_type": "cg", "reuse_factorization": false})");
  Create(R"({"solver_type": "umfpack", "reuse_factorization": false})");
  Logger::ResetSink();
  NoEffectWarnings::Reset();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("'reuse_factorization' = false"), std::string::npos) << warnings[0];
}

TEST(LinearSolverFactory, ReadsIterativeSettingsAndPreconditionerNames) {
  const auto solver = Create(R"({"solver_type": "BICGSTABSolver", "tolerance": 1e-9, "max_iteration": 77,
                                 "preconditioner_type": "ILU0Preconditioner", "gmres_krylov_space_dimension": 40})");
  const auto* iterative = dynamic_cast<const IterativeSolver*>(solver.get());
  ASSERT_NE(iterative, nullptr);
  EXPECT_EQ(iterative->GetOptions().tolerance, 1e-9);
  EXPECT_EQ(iterative->GetOptions().max_iteration, 77);
  EXPECT_EQ(iterative->GetOptions().krylov_space_dimension, 40);
  EXPECT_EQ(iterative->GetOptions().preconditioner, IterativeSolver::Preconditioner::kIlu0);
  const auto alias = Create(R"({"solver_type": "gmres", "max_iteration_number": 33})");
  EXPECT_EQ(dynamic_cast<const IterativeSolver&>(*alias).GetOptions().max_iteration, 33);
  const std::vector<std::pair<std::string, IterativeSolver::Preconditioner>> names = {
      {"None", IterativeSolver::Preconditioner::kNone},
      {"DiagonalPreconditioner", IterativeSolver::Preconditioner::kDiagonal},
      {"ILU0Preconditioner", IterativeSolver::Preconditioner::kIlu0},
      {"ILUPreconditioner", IterativeSolver::Preconditioner::kIlu},
      {"diagonal", IterativeSolver::Preconditioner::kDiagonal},
  };
  for (const auto& [name, expected] : names) {
    const auto made = Create(R"({"solver_type": "cg", "preconditioner_type": ")" + name + "\"}");
    EXPECT_EQ(dynamic_cast<const IterativeSolver&>(*made).GetOptions().preconditioner, expected) << name;
  }
}

TEST(LinearSolverFactory, ScalingKeyWrapsTheSolver) {
  const auto solver = Create(R"({"solver_type": "klu", "scaling": true})");
  EXPECT_EQ(solver->Name(), "scaling(klu)");
  const SparseMatrix A = testing::ConvectionDiffusion2D(20);
  const Vector exact = testing::ManufacturedSolution(A.rows());
  Vector x;
  solver->Initialize(A);
  solver->Solve(A, x, A * exact);
  EXPECT_LT(testing::RelativeError(x, exact), 1e-10);
}

TEST(LinearSolverFactory, AmgclIsDirectForSmallSystems) {
  const auto solver = Create(R"({"solver_type": "amgcl", "smoother_type": "ilu0", "krylov_type": "lgmres",
                                 "coarsening_type": "aggregation", "block_size": 3, "max_iteration": 100,
                                 "tolerance": 1e-6, "verbosity": 1, "use_block_matrices_if_possible": true})");
  const SparseMatrix A = testing::ConvectionDiffusion2D(30);
  const Vector exact = testing::ManufacturedSolution(A.rows());
  Vector x;
  solver->Initialize(A);
  solver->Solve(A, x, A * exact);
  EXPECT_TRUE(solver->IsDirect());
  EXPECT_EQ(dynamic_cast<const SizeSelectingSolver&>(*solver).Active().Name(), "umfpack");
  EXPECT_LT(testing::RelativeError(x, exact), 1e-10);
}

TEST(LinearSolverFactory, CholmodFallsBackToUmfpackOnIndefiniteSystems) {
  const auto solver = Create(R"({"solver_type": "cholmod"})");
  const SparseMatrix A = testing::ConvectionDiffusion2D(30);  // not symmetric
  const Vector exact = testing::ManufacturedSolution(A.rows());
  Vector x;
  solver->Initialize(A);
  solver->Solve(A, x, A * exact);
  EXPECT_LT(testing::RelativeError(x, exact), 1e-10);
  EXPECT_EQ(solver->Name(), "umfpack");
}

TEST(LinearSolverFactory, UnknownNameSuggestsTheNearest) {
  const std::string message = ErrorMessage<InputError>(R"({"solver_type": "umfpak"})");
  EXPECT_NE(message.find("solver_type"), std::string::npos) << message;
  EXPECT_NE(message.find("'umfpak'"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean 'umfpack'"), std::string::npos) << message;
  const std::string kratos = ErrorMessage<InputError>(R"({"solver_type": "SkylineLUFactorisationSolver"})");
  EXPECT_NE(kratos.find("'SkylineLUFactorizationSolver'"), std::string::npos) << kratos;
}

TEST(LinearSolverFactory, UnknownKeySuggestsTheNearest) {
  const std::string message = ErrorMessage<InputError>(R"({"solver_type": "cg", "tolerence": 1e-8})");
  EXPECT_NE(message.find("tolerence"), std::string::npos) << message;
  EXPECT_NE(message.find("'tolerance'"), std::string::npos) << message;
  const std::string wrong_type = ErrorMessage<InputError>(R"({"solver_type": "cg", "max_iteration": "many"})");
  EXPECT_NE(wrong_type.find("max_iteration"), std::string::npos) << wrong_type;
  const std::string preconditioner =
      ErrorMessage<InputError>(R"({"solver_type": "cg", "preconditioner_type": "ilu1"})");
  EXPECT_NE(preconditioner.find("'ilu0'"), std::string::npos) << preconditioner;
}

TEST(LinearSolverFactory, SparseQrIsNotImplemented) {
  const std::string message = ErrorMessage<NotImplementedError>(R"({"solver_type": "SparseQRSolver"})");
  EXPECT_NE(message.find("SparseQRSolver"), std::string::npos) << message;
}

TEST(LinearSolverFactory, RegisteredSolversAreCreatedWithTheUsersSettings) {
  std::string seen;
  RegisterLinearSolver("test_registered_solver", [&seen](const Parameters& settings) -> std::unique_ptr<LinearSolver> {
    seen = settings["own_key"].GetString();
    return std::make_unique<UmfpackSolver>();
  });
  // The creator owns its keys: the core's validation does not see them.
  const auto solver = CreateLinearSolver(Parameters(R"({"solver_type": "test_registered_solver", "own_key": "x"})"));
  EXPECT_EQ(solver->Name(), "umfpack");
  EXPECT_EQ(seen, "x");
  const std::string message = ErrorMessage<InputError>(R"({"solver_type": "test_registered_solvr"})");
  EXPECT_NE(message.find("did you mean 'test_registered_solver'"), std::string::npos) << message;
}

}  // namespace
}  // namespace mc
