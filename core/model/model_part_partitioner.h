// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace mc {

class Entity;
class ModelPart;
class Node;

/// Cuts a model read whole on every rank of a distributed run down to this rank's piece (issue 17,
/// step 3 of benchmarks/mpi/README.md): the elements and conditions with at least one node this
/// rank owns, the nodes they use (the owned nodes and one layer of ghosts owned elsewhere), and the
/// replicated sub model parts whole (the contact interfaces: a contact condition reaches master
/// nodes anywhere, and the search must see every face). Everything else leaves every sub model part
/// and is destroyed. Each element is then owned by exactly one rank, the owner of its first node.
///
/// What reads every element (ContactInterfaceBuilder::ComputeNodalH, ContactSearchProcess::BodyOf
/// and FindMeshNeighbours, mesh_checks.py) must run before the cut or reduce over the ranks.
class ModelPartPartitioner {
 public:
  /// `owner(node)`: the rank owning a node, the same answer on every rank (a NodePartition).
  ModelPartPartitioner(std::function<int(const Node&)> owner, int rank);

  /// What one cut kept on this rank.
  struct Piece {
    std::size_t owned_nodes = 0;
    std::size_t ghost_nodes = 0;  ///< kept nodes owned by another rank
    std::size_t elements = 0;
    std::size_t conditions = 0;
  };

  /// Cuts the tree of `root` in place; `replicated` are sub model parts of it kept whole.
  /// Master-slave constraints are refused (NotImplementedError): a constraint may join DoFs of
  /// nodes no rank keeps together.
  Piece Cut(ModelPart& root, const std::vector<const ModelPart*>& replicated) const;

  /// Whether this rank owns an element or condition (writes its cell in the outputs, counts it
  /// once in a sum over the ranks): the owner of its first node does.
  bool Owns(const Entity& entity) const;

 private:
  std::function<int(const Node&)> owner_;
  int rank_;
};

}  // namespace mc
