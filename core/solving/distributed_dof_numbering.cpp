// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/distributed_dof_numbering.h"

#include <algorithm>
#include <bit>
#include <string>

#include "core/linear_solvers/assembly_communicator.h"
#include "core/model/dof.h"
#include "core/model/node.h"
#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {

namespace {

auto Key(const Dof* dof) {
  return std::pair{static_cast<std::int64_t>(dof->node->Id()), static_cast<std::int64_t>(dof->variable->Key())};
}

}  // namespace

DistributedDofNumbering::DistributedDofNumbering(const std::vector<Dof*>& dofs,
                                                 const std::function<int(const Node&)>& owner,
                                                 const AssemblyCommunicator& communicator)
    : communicator_(&communicator) {
  const auto ranks = static_cast<std::size_t>(communicator.Size());
  const int rank = communicator.Rank();
  if (!std::is_sorted(dofs.begin(), dofs.end(), [](const Dof* a, const Dof* b) { return Key(a) < Key(b); }))
    throw Error("distributed DoF numbering: the DoF set must be sorted by node id, then variable key");
  send_positions_.assign(ranks, {});
  receive_positions_.assign(ranks, {});
  // The owned DoFs in order; the ghosts' (node id, variable key) to their owners.
  std::vector<std::vector<std::int64_t>> requests(ranks);
  std::vector<Dof*> owned_dofs;
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    const int r = owner(*dofs[i]->node);
    if (r == rank) {
      owned_dofs.push_back(dofs[i]);
      continue;
    }
    const auto [node, variable] = Key(dofs[i]);
    requests[static_cast<std::size_t>(r)].insert(requests[static_cast<std::size_t>(r)].end(), {node, variable});
    receive_positions_[static_cast<std::size_t>(r)].push_back(i);
    ++ghosts_;
  }
  const auto owned = static_cast<std::int64_t>(owned_dofs.size());
  begin_ = communicator.ExclusiveScan(owned);
  end_ = begin_ + owned;
  for (std::int64_t k = 0; k < owned; ++k) owned_dofs[static_cast<std::size_t>(k)]->equation_id = begin_ + k;
  // The total: a sum of counts, exact in doubles.
  std::vector<double> total{static_cast<double>(owned)};
  communicator.SumToAll(total.data(), 1);
  rows_ = static_cast<std::int64_t>(total[0]);

  // A DoF asked for and not held is answered -1 and reported on both sides after the answers,
  // so that no rank waits in the second exchange for one that has thrown.
  const auto asked = communicator.Exchange(requests);
  std::vector<std::vector<std::int64_t>> answers(ranks);
  std::string missing;
  for (std::size_t r = 0; r < ranks; ++r) {
    for (std::size_t k = 0; k + 1 < asked[r].size(); k += 2) {
      const std::pair wanted{asked[r][k], asked[r][k + 1]};
      const auto it = std::lower_bound(dofs.begin(), dofs.end(), wanted,
                                       [](const Dof* d, const auto& key) { return Key(d) < key; });
      if (it == dofs.end() || Key(*it) != wanted || owner(*(*it)->node) != rank) {
        if (missing.empty())
          missing = Concat("rank ", r, " ghosts node ", wanted.first, " (variable key ", wanted.second,
                           "), which rank ", rank, " owns but has no such DoF: its piece lacks an entity of that node");
        answers[r].push_back(-1);
        continue;
      }
      answers[r].push_back((*it)->equation_id);
      send_positions_[r].push_back(static_cast<std::size_t>(it - dofs.begin()));
    }
  }
  const auto ids = communicator.Exchange(answers);
  if (!missing.empty()) throw Error(Concat("distributed DoF numbering: ", missing));
  for (std::size_t r = 0; r < ranks; ++r)
    for (std::size_t k = 0; k < ids[r].size(); ++k) {
      Dof* dof = dofs[receive_positions_[r][k]];
      if (ids[r][k] < 0)
        throw Error(Concat("distributed DoF numbering: rank ", r, " owns node ", dof->node->Id(), " but not its ",
                           dof->variable->Name(), ", which rank ", rank, " holds"));
      dof->equation_id = ids[r][k];
    }
}

std::vector<std::vector<std::int64_t>> DistributedDofNumbering::Send(
    const std::vector<double>& values, const std::vector<std::vector<std::size_t>>& positions) const {
  // Doubles travel as their bits: exact, and one exchange for both kinds of list.
  std::vector<std::vector<std::int64_t>> outgoing(positions.size());
  for (std::size_t r = 0; r < positions.size(); ++r)
    for (const std::size_t i : positions[r]) outgoing[r].push_back(std::bit_cast<std::int64_t>(values[i]));
  return communicator_->Exchange(outgoing);
}

void DistributedDofNumbering::UpdateGhosts(std::vector<double>& values) const {
  const auto incoming = Send(values, send_positions_);
  for (std::size_t r = 0; r < receive_positions_.size(); ++r)
    for (std::size_t k = 0; k < incoming[r].size(); ++k)
      values[receive_positions_[r][k]] = std::bit_cast<double>(incoming[r][k]);
}

void DistributedDofNumbering::AddGhostsToOwners(std::vector<double>& values) const {
  // A rank's list comes back in the order of its requests, which is send_positions_' order.
  const auto incoming = Send(values, receive_positions_);
  for (std::size_t r = 0; r < send_positions_.size(); ++r)
    for (std::size_t k = 0; k < incoming[r].size(); ++k)
      values[send_positions_[r][k]] += std::bit_cast<double>(incoming[r][k]);
}

}  // namespace mc
