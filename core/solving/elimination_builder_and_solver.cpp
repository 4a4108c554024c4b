// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/elimination_builder_and_solver.h"

namespace mc {

void EliminationBuilderAndSolver::NumberDofs() {
  const std::vector<Dof*>& order = NumberingOrder();
  std::int64_t next = 0;
  for (Dof* d : order)
    if (!d->fixed && !IsSlave(*d)) d->equation_id = next++;
  n_system_ = static_cast<std::size_t>(next);
  for (Dof* d : order)
    if (!d->fixed && IsSlave(*d)) d->equation_id = next++;
  n_assembled_ = static_cast<std::size_t>(next);
  for (Dof* d : order)
    if (d->fixed) d->equation_id = next++;
}

bool EliminationBuilderAndSolver::NumberingIsStale() const {
  for (const Dof* d : dofs_)
    if (static_cast<bool>(fixed_at_numbering_[static_cast<std::size_t>(d->equation_id)]) != d->fixed) return true;
  return false;
}

}  // namespace mc
