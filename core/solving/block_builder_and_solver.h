// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/builder_and_solver.h"

namespace mc {

/// Every DoF is an unknown (equation id = position in the DoF set). Fixed DoFs keep their rows
/// and columns, which are zeroed with a positive diagonal and a zero right-hand side, so a
/// symmetric positive definite K stays so (CHOLMOD applies) and the fixed increments are zero.
/// Slave DoFs of constraints are treated the same way and recovered after the solve.
class BlockBuilderAndSolver : public BuilderAndSolver {
 public:
  /// Diagonal put on the rows of fixed DoFs (Kratos' `diagonal_values_for_dirichlet_dofs`):
  /// the largest absolute diagonal of the assembled matrix keeps the conditioning close to
  /// that of the free block; one is the textbook choice.
  enum class DirichletDiagonal { kMaxDiagonal, kUnit };

  explicit BlockBuilderAndSolver(std::shared_ptr<LinearSolver> linear_solver,
                                 DirichletDiagonal diagonal = DirichletDiagonal::kMaxDiagonal)
      : BuilderAndSolver(std::move(linear_solver)), diagonal_(diagonal) {}

  std::string Name() const override { return "block"; }
  /// The diagonal value used for the fixed DoFs in the last build.
  double DirichletScale() const noexcept { return scale_; }

 protected:
  void NumberDofs() override;
  void ApplyDirichletConditions(bool lhs, bool rhs) override;

 private:
  DirichletDiagonal diagonal_;
  double scale_ = 1.0;
  std::vector<char> constrained_;
};

}  // namespace mc
