// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "core/linear_solvers/linear_solver.h"

namespace mc {

/// Tries a primary solver and, the first time it fails with a SolutionError (for CHOLMOD: a
/// matrix that is not symmetric positive definite), switches to the fallback for good: the
/// failed system is solved again by the fallback, and so is every later one, since a matrix
/// found indefinite once stays so along a Newton loop. Errors of the fallback propagate.
/// Kratos' "cholmod" / "pardiso_llt" become CHOLMOD falling back to UMFPACK this way.
class FallbackSolver : public LinearSolver {
 public:
  FallbackSolver(std::unique_ptr<LinearSolver> primary, std::unique_ptr<LinearSolver> fallback);

  /// The primary's name until the switch, then the fallback's.
  std::string Name() const override { return Active().Name(); }
  bool IsDirect() const override { return Active().IsDirect(); }
  void Initialize(const SparseMatrix& A) override;
  void Solve(const SparseMatrix& A, Vector& x, const Vector& b) override;
  void Clear() override;
  int IterationsNumber() const override { return Active().IterationsNumber(); }
  void SetForcingTerm(double eta) override {
    primary_->SetForcingTerm(eta);
    fallback_->SetForcingTerm(eta);
  }
  double LastTolerance() const override { return Active().LastTolerance(); }
  WorkCounters Counters() const override { return Active().Counters(); }

  bool UsingFallback() const noexcept { return switched_; }
  /// The primary's error message that caused the switch (empty before).
  const std::string& SwitchReason() const noexcept { return reason_; }

 private:
  LinearSolver& Active() const { return switched_ ? *fallback_ : *primary_; }

  std::unique_ptr<LinearSolver> primary_;
  std::unique_ptr<LinearSolver> fallback_;
  bool switched_ = false;
  std::string reason_;
};

}  // namespace mc
