// SPDX-License-Identifier: BSD-3-Clause
#include "core/linear_solvers/iterative_solver.h"

#include <Eigen/IterativeLinearSolvers>
#include <type_traits>
#include <unsupported/Eigen/IterativeSolvers>

namespace mc {

namespace {

const char* MethodName(IterativeSolver::Method method) {
  switch (method) {
    case IterativeSolver::Method::kCg: return "cg";
    case IterativeSolver::Method::kBicgstab: return "bicgstab";
    case IterativeSolver::Method::kGmres: return "gmres";
  }
  return "";
}

const char* PreconditionerName(IterativeSolver::Preconditioner preconditioner) {
  switch (preconditioner) {
    case IterativeSolver::Preconditioner::kNone: return "none";
    case IterativeSolver::Preconditioner::kDiagonal: return "diagonal";
    case IterativeSolver::Preconditioner::kIlu0: return "ilu0";
    case IterativeSolver::Preconditioner::kIlu: return "ilu";
  }
  return "";
}

}  // namespace

struct IterativeSolver::Backend {
  virtual ~Backend() = default;
  virtual void Analyze(const SparseMatrix& A) = 0;
  virtual void Factorize(const SparseMatrix& A) = 0;
  /// Eigen's status after the solve.
  virtual Eigen::ComputationInfo Solve(const Vector& b, Vector& x, int& iterations, double& residual) = 0;
};

template <class Solver>
struct IterativeSolver::BackendFor : IterativeSolver::Backend {
  static constexpr bool kIlut = std::is_same_v<typename Solver::Preconditioner, Eigen::IncompleteLUT<double, int>>;
  explicit BackendFor(const Options& options) {
    solver.setTolerance(options.tolerance);
    solver.setMaxIterations(options.max_iteration);
    if constexpr (requires(Solver s) { s.set_restart(30); }) solver.set_restart(options.krylov_space_dimension);
    if constexpr (kIlut) {
      if (options.preconditioner == Preconditioner::kIlu0) solver.preconditioner().setFillfactor(1);
    }
  }
  // Eigen 3.4.0's IncompleteLUT::analyzePattern leaves its m_info uninitialised, and the Krylov solver's
  // analyzePattern copies it (an invalid enum load under UBSan). Its compute() analyses and factorizes
  // in one call and sets m_info, at the price of redoing the fill-reducing ordering for each matrix.
  void Analyze(const SparseMatrix& A) override {
    if constexpr (!kIlut) solver.analyzePattern(A);
  }
  void Factorize(const SparseMatrix& A) override {
    if constexpr (kIlut)
      solver.compute(A);
    else
      solver.factorize(A);
  }
  Eigen::ComputationInfo Solve(const Vector& b, Vector& x, int& iterations, double& residual) override {
    if (solver.info() != Eigen::Success) return solver.info();  // preconditioner breakdown
    x = solver.solve(b);
    iterations = static_cast<int>(solver.iterations());
    residual = solver.error();
    return solver.info();
  }
  Solver solver;
};

IterativeSolver::IterativeSolver(const Options& options) : options_(options) {}

IterativeSolver::~IterativeSolver() = default;

std::string IterativeSolver::Name() const { return MethodName(options_.method); }

void IterativeSolver::Initialize(const SparseMatrix& A) {
  using Identity = Eigen::IdentityPreconditioner;
  using Jacobi = Eigen::DiagonalPreconditioner<double>;
  using Ilu = Eigen::IncompleteLUT<double, int>;
  // CG needs a symmetric preconditioner; threshold ILU is not, its symmetric analogue is.
  using Ichol = Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>;
  constexpr int kFull = Eigen::Lower | Eigen::Upper;
  const Preconditioner p = options_.preconditioner;
  const bool ilu = p == Preconditioner::kIlu0 || p == Preconditioner::kIlu;
  switch (options_.method) {
    case Method::kCg:
      if (p == Preconditioner::kNone)
        backend_ = std::make_unique<BackendFor<Eigen::ConjugateGradient<SparseMatrix, kFull, Identity>>>(options_);
      else if (ilu)
        backend_ = std::make_unique<BackendFor<Eigen::ConjugateGradient<SparseMatrix, kFull, Ichol>>>(options_);
      else
        backend_ = std::make_unique<BackendFor<Eigen::ConjugateGradient<SparseMatrix, kFull, Jacobi>>>(options_);
      break;
    case Method::kBicgstab:
      if (p == Preconditioner::kNone)
        backend_ = std::make_unique<BackendFor<Eigen::BiCGSTAB<SparseMatrix, Identity>>>(options_);
      else if (ilu)
        backend_ = std::make_unique<BackendFor<Eigen::BiCGSTAB<SparseMatrix, Ilu>>>(options_);
      else
        backend_ = std::make_unique<BackendFor<Eigen::BiCGSTAB<SparseMatrix, Jacobi>>>(options_);
      break;
    case Method::kGmres:
      if (p == Preconditioner::kNone)
        backend_ = std::make_unique<BackendFor<Eigen::GMRES<SparseMatrix, Identity>>>(options_);
      else if (ilu)
        backend_ = std::make_unique<BackendFor<Eigen::GMRES<SparseMatrix, Ilu>>>(options_);
      else
        backend_ = std::make_unique<BackendFor<Eigen::GMRES<SparseMatrix, Jacobi>>>(options_);
      break;
  }
  backend_->Analyze(A);
  analysed_rows_ = A.rows();
}

void IterativeSolver::Solve(const SparseMatrix& A, Vector& x, const Vector& b) {
  if (!backend_ || A.rows() != analysed_rows_) Initialize(A);
  backend_->Factorize(A);
  iterations_ = 0;
  residual_ = 0.0;
  const Eigen::ComputationInfo info = backend_->Solve(b, x, iterations_, residual_);
  if (info == Eigen::Success) return;
  const std::string what = Concat(Name(), " with preconditioner ", PreconditionerName(options_.preconditioner), " on ",
                                  A.rows(), " equations");
  if (info == Eigen::NoConvergence) {
    throw SolutionError(Concat(what, " did not converge: relative residual ", residual_, " after ", iterations_,
                               " iterations (tolerance ", options_.tolerance, ", max_iteration ",
                               options_.max_iteration, ")"));
  }
  throw SolutionError(
      Concat(what, " broke down (numerical issue) after ", iterations_, " iterations, relative residual ", residual_));
}

void IterativeSolver::Clear() {
  backend_.reset();
  analysed_rows_ = -1;
}

}  // namespace mc
