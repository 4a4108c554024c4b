// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

namespace mc {

class AssemblyCommunicator;
class Node;
struct Dof;

/// Equation ids when each rank holds only its piece of the model (issue 17, step 3, part 2 of
/// benchmarks/mpi/README.md): a rank numbers the DoFs of its owned nodes in the order given, from
/// the exclusive scan of the ranks' owned counts, and learns its ghosts' ids from their owners (one
/// request and one answer per neighbour, the lists kept for UpdateGhosts). With the DoF sets in the
/// builder's order (node id, then variable key) this is the replicated builder's numbering rank by
/// rank: the same DoF gets the same id on every rank that holds it.
class DistributedDofNumbering {
 public:
  /// Collective. `dofs`: this rank's DoF set sorted by node id then variable key; `owner(node)`: the
  /// rank owning a node (the same on every rank). Sets every DoF's equation_id. Throws Error naming
  /// the node and variable when the owner does not hold a DoF a ghost asks for.
  DistributedDofNumbering(const std::vector<Dof*>& dofs, const std::function<int(const Node&)>& owner,
                          const AssemblyCommunicator& communicator);

  /// This rank's rows: [Begin(), End()) of Rows() in all.
  std::int64_t Begin() const noexcept { return begin_; }
  std::int64_t End() const noexcept { return end_; }
  std::int64_t Rows() const noexcept { return rows_; }
  std::size_t Ghosts() const noexcept { return ghosts_; }

  /// Collective. `values[i]` belongs to dofs[i] of the constructor; the ghosts' entries are
  /// overwritten with their owners' (the solution increment's scatter to the ghosts).
  void UpdateGhosts(std::vector<double>& values) const;
  /// Collective, the reverse of UpdateGhosts: each ghost's entry is added to its owner's entry (in
  /// rank order), the ghosts' left as they were (a sum of what the ranks found for a DoF).
  void AddGhostsToOwners(std::vector<double>& values) const;

 private:
  /// Sends rank r the values at positions[r]; returns what each rank sent here.
  std::vector<std::vector<std::int64_t>> Send(const std::vector<double>& values,
                                              const std::vector<std::vector<std::size_t>>& positions) const;
  const AssemblyCommunicator* communicator_;
  std::int64_t begin_ = 0;
  std::int64_t end_ = 0;
  std::int64_t rows_ = 0;
  std::size_t ghosts_ = 0;
  std::vector<std::vector<std::size_t>> send_positions_;     ///< [rank]: owned DoFs that rank ghosts
  std::vector<std::vector<std::size_t>> receive_positions_;  ///< [rank]: ghost DoFs that rank owns
};

}  // namespace mc
