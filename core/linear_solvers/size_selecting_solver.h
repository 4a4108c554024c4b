// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "core/linear_solvers/linear_solver.h"

namespace mc {

/// Chooses by system size at each `Initialize`: the small-system solver up to `max_small_size`
/// equations, the large-system one above. Stands in for Kratos' AMGCL: a direct solve where
/// memory allows (exact, and contact systems are hard for AMG), an ILU-preconditioned Krylov
/// solver beyond.
class SizeSelectingSolver : public LinearSolver {
 public:
  SizeSelectingSolver(std::string name, long max_small_size, std::unique_ptr<LinearSolver> small,
                      std::unique_ptr<LinearSolver> large);

  /// The name given (e.g. "amgcl").
  std::string Name() const override { return name_; }
  /// Of the solver chosen for the last pattern (the small one before any).
  bool IsDirect() const override { return Active().IsDirect(); }
  void Initialize(const SparseMatrix& A) override;
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override;
  void Clear() override;
  int IterationsNumber() const override { return Active().IterationsNumber(); }
  void SetForcingTerm(double eta) override {
    small_->SetForcingTerm(eta);
    large_->SetForcingTerm(eta);
  }
  double LastTolerance() const override { return Active().LastTolerance(); }
  WorkCounters Counters() const override { return Active().Counters(); }

  /// The solver used for the last pattern.
  const LinearSolver& Active() const { return use_large_ ? *large_ : *small_; }

 private:
  LinearSolver& ActiveSolver() { return use_large_ ? *large_ : *small_; }

  std::string name_;
  long max_small_size_;
  std::unique_ptr<LinearSolver> small_;
  std::unique_ptr<LinearSolver> large_;
  bool use_large_ = false;
  long rows_ = -1;
};

}  // namespace mc
