// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "core/solving/builder_and_solver.h"

namespace mc {

/// Only the free DoFs are unknowns: they are numbered first (then constraint slaves, then the
/// fixed DoFs), and entries of fixed rows and columns are never assembled into the matrix.
/// The residual is still assembled for every DoF, which gives the reactions. The numbering
/// depends on the fixity, so a change of fixity renumbers the system at the next build.
class EliminationBuilderAndSolver : public BuilderAndSolver {
 public:
  using BuilderAndSolver::BuilderAndSolver;
  std::string Name() const override { return "elimination"; }

 protected:
  void NumberDofs() override;
  bool NumberingIsStale() const override;
};

}  // namespace mc
