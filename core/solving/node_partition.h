// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <unordered_map>

namespace mc {

class AssemblyCommunicator;
class ModelPart;
class Node;

/// Which rank owns each node of a distributed run: a METIS k-way partition of the nodal graph of
/// the model part's elements (two nodes adjacent when they share an element), so that a rank's
/// nodes are a compact piece of the mesh and few of its elements touch another rank's rows. Every
/// DoF of a node is owned with it, the contact multipliers of a slave node included. Nodes in no
/// element (only in conditions) belong to rank 0. Rank 0 partitions and the others receive its
/// answer, so the ranks agree whatever METIS' seeding.
class NodePartition {
 public:
  NodePartition() = default;
  /// Collective: every rank of `communicator` calls it with the same model part.
  NodePartition(const ModelPart& model_part, const AssemblyCommunicator& communicator);

  int Owner(const Node& node) const {
    const auto it = owner_.find(&node);
    return it == owner_.end() ? 0 : it->second;
  }
  int Size() const noexcept { return size_; }
  /// Whether this partition was made for `model_part` as it is now (same nodes and elements).
  bool IsFor(const ModelPart& model_part) const;

 private:
  std::unordered_map<const Node*, int> owner_;
  const ModelPart* model_part_ = nullptr;
  std::size_t nodes_ = 0;
  std::size_t elements_ = 0;
  int size_ = 0;
};

}  // namespace mc
