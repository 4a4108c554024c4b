// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/variables/value_types.h"

namespace mc {

/// The connectivity of an mdpa file, streamed without building a model (issue 17: each rank of a
/// distributed run reads only its piece): the node ids, the elements' and conditions' node ids in
/// id order (flat arrays), and which nodes and conditions each sub model part lists. The scan is
/// lenient: a line it cannot read is skipped, and MdpaReader, which reads the file after it on
/// every rank alike, names it with its file and line.
class MdpaMesh {
 public:
  /// Entities in increasing id order; the nodes of entity i are nodes[start[i] .. start[i + 1]).
  struct Connectivity {
    std::vector<IndexType> ids;
    std::vector<std::size_t> start{0};
    std::vector<IndexType> nodes;
    std::size_t Size() const noexcept { return ids.size(); }
  };

  /// What one rank reads (MdpaReaderOptions::piece): sorted ids.
  struct Piece {
    std::vector<IndexType> nodes;
    std::vector<IndexType> elements;
    std::vector<IndexType> conditions;
    /// The nodes of the parts kept whole (and of their conditions): the contact interfaces.
    std::vector<IndexType> interface_nodes;
    bool KeepsNode(IndexType id) const;
    bool KeepsElement(IndexType id) const;
    bool KeepsCondition(IndexType id) const;
  };

  static MdpaMesh Read(const std::string& filename);
  static MdpaMesh FromText(std::string_view text);

  const std::vector<IndexType>& NodeIds() const noexcept { return node_ids_; }
  const Connectivity& Elements() const noexcept { return elements_; }
  const Connectivity& Conditions() const noexcept { return conditions_; }

  /// The piece of `rank`, `owner(node id)` giving each node's rank: the elements and conditions
  /// touching a node it owns (what ModelPartPartitioner keeps), the sub model parts `kept_whole`
  /// (named as a contact process names them: "Root.A.B", "A.B" or a unique "B") whole with their
  /// conditions, the elements and conditions touching their nodes (what the interface is built
  /// from: its faces, NODAL_H, the parents' properties and normals, as on the whole model), the
  /// file's last condition (so that the faces an interface makes get the serial run's ids), and
  /// every node of those. A name that does not resolve is left for the interface builder to report.
  Piece PieceOf(const std::function<int(IndexType)>& owner, int rank, const std::string& root_name,
                const std::vector<std::string>& kept_whole) const;

  /// The body (connected set of elements, labelled alike on every rank) of each of `nodes` that
  /// lies on an element, and the number of element nodes: every label is below it.
  std::pair<std::unordered_map<IndexType, std::size_t>, std::size_t> Bodies(const std::vector<IndexType>& nodes) const;

 private:
  struct Members {
    std::vector<IndexType> nodes;
    std::vector<IndexType> conditions;
  };
  /// The part `name` names, null for none or several.
  const Members* Resolve(const std::string& root_name, const std::string& name) const;

  std::vector<IndexType> node_ids_;
  Connectivity elements_;
  Connectivity conditions_;
  /// Keyed by the dotted path below the root ("A.B"); a part lists its descendants' members too.
  std::map<std::string, Members> parts_;
};

}  // namespace mc
