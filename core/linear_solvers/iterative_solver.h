// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "core/linear_solvers/linear_solver.h"

namespace mc {

/// Krylov solvers from Eigen: conjugate gradients (SPD only; reads the full matrix), BiCGSTAB
/// and restarted GMRES, with no, Jacobi ("diagonal") or incomplete-LU preconditioning. The
/// tolerance bounds the relative residual |b - A x| / |b|, as in Kratos; every solve starts
/// from x = 0.
class IterativeSolver : public LinearSolver {
 public:
  enum class Method { kCg, kBicgstab, kGmres };
  /// kIlu0 keeps about the fill of ILU(0) (Eigen IncompleteLUT, fill factor 1); kIlu uses
  /// Eigen's default threshold ILU (fill factor 10). With CG both are Eigen's incomplete
  /// Cholesky, since CG needs a symmetric preconditioner.
  enum class Preconditioner { kNone, kDiagonal, kIlu0, kIlu };

  struct Options {
    Method method = Method::kBicgstab;
    Preconditioner preconditioner = Preconditioner::kNone;
    double tolerance = 1.0e-6;
    int max_iteration = 200;
    int krylov_space_dimension = 100;  ///< GMRES restart length
  };

  explicit IterativeSolver(const Options& options);
  ~IterativeSolver() override;

  std::string Name() const override;
  bool IsDirect() const override { return false; }
  /// Preconditioner pattern work (ILU ordering).
  void Initialize(const SparseMatrix& A) override;
  /// Throws SolutionError with the iterations and the relative residual reached when the
  /// tolerance is not met within max_iteration, or when the method breaks down.
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override;
  void Clear() override;
  int IterationsNumber() const override { return iterations_; }
  /// Relative residual estimated by the last solve.
  double AchievedResidual() const noexcept { return residual_; }
  const Options& GetOptions() const noexcept { return options_; }

 private:
  struct Backend;
  template <class Solver>
  struct BackendFor;

  Options options_;
  std::unique_ptr<Backend> backend_;
  long analysed_rows_ = -1;
  int iterations_ = 0;
  double residual_ = 0.0;
};

}  // namespace mc
