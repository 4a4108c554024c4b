// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "core/variables/value_types.h"

namespace mc {

class AssemblyCommunicator;
class MdpaMesh;
class ModelPart;
class Node;

/// Which rank owns each node of a distributed run: a METIS k-way partition of the nodal graph of
/// the model part's elements (two nodes adjacent when they share an element), so that a rank's
/// nodes are a compact piece of the mesh and few of its elements touch another rank's rows. Every
/// DoF of a node is owned with it, the contact multipliers of a slave node included. Nodes in no
/// element (only in conditions) belong to rank 0. Rank 0 partitions and the others receive its
/// answer, so the ranks agree whatever METIS' seeding. Nodes are known by id.
class NodePartition {
 public:
  NodePartition() = default;
  /// Collective: every rank of `communicator` calls it with the same model part.
  NodePartition(const ModelPart& model_part, const AssemblyCommunicator& communicator);
  /// Collective, before any model is built: the partition of the elements of `mesh` (a file
  /// streamed by every rank); the same as of the model part read from that file whole.
  NodePartition(const MdpaMesh& mesh, const AssemblyCommunicator& communicator);

  int Owner(const Node& node) const;
  int OwnerOf(IndexType node_id) const {
    const auto it = owner_.find(node_id);
    return it == owner_.end() ? 0 : it->second;
  }
  int Size() const noexcept { return size_; }
  /// Whether this partition was made for `model_part` as it is now (same nodes and elements).
  bool IsFor(const ModelPart& model_part) const;
  /// Forgets the owners of the nodes other than `node_ids` (sorted): a rank that reads its piece
  /// keeps the owners of its nodes only.
  void KeepOnly(const std::vector<IndexType>& node_ids);

 private:
  /// Partitions the nodes 0..ids.size()-1 of the elements (METIS' mesh arrays) on rank 0 and
  /// hands every rank the owners of `ids`.
  void Partition(const std::vector<IndexType>& ids, std::vector<int>& element_start, std::vector<int>& element_nodes,
                 const AssemblyCommunicator& communicator, const std::string& what);

  std::unordered_map<IndexType, int> owner_;
  const ModelPart* model_part_ = nullptr;
  std::size_t nodes_ = 0;
  std::size_t elements_ = 0;
  int size_ = 0;
};

}  // namespace mc
