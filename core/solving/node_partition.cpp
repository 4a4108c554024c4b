// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/node_partition.h"

#include <metis.h>

#include <algorithm>
#include <type_traits>

#include "core/io/mdpa_mesh.h"
#include "core/linear_solvers/assembly_communicator.h"
#include "core/model/model_part.h"
#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {

static_assert(std::is_same_v<idx_t, int>, "NodePartition hands METIS arrays of int");

NodePartition::NodePartition(const ModelPart& model_part, const AssemblyCommunicator& communicator)
    : model_part_(&model_part),
      nodes_(model_part.NumberOfNodes()),
      elements_(model_part.NumberOfElements()),
      size_(communicator.Size()) {
  // The element nodes, numbered 0.. in order of first appearance, as METIS' mesh arrays.
  std::vector<IndexType> ids;
  std::vector<int> element_start{0}, element_nodes;
  std::unordered_map<const Node*, int> index;
  for (const Element* element : model_part.Elements()) {
    const Geometry& geometry = element->GetGeometry();
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i) {
      const auto [it, added] = index.emplace(&geometry[i], static_cast<int>(ids.size()));
      if (added) ids.push_back(geometry[i].Id());
      element_nodes.push_back(it->second);
    }
    element_start.push_back(static_cast<int>(element_nodes.size()));
  }
  Partition(ids, element_start, element_nodes, communicator, Concat("model part '", model_part.Name(), "'"));
}

NodePartition::NodePartition(const MdpaMesh& mesh, const AssemblyCommunicator& communicator)
    : size_(communicator.Size()) {
  // As above, from the file's elements in id order (the order a model part holds them in).
  const MdpaMesh::Connectivity& elements = mesh.Elements();
  std::vector<IndexType> ids;
  std::vector<int> element_start{0}, element_nodes;
  element_nodes.reserve(elements.nodes.size());
  std::unordered_map<IndexType, int> index;
  for (std::size_t e = 0; e < elements.Size(); ++e) {
    for (std::size_t k = elements.start[e]; k < elements.start[e + 1]; ++k) {
      const auto [it, added] = index.emplace(elements.nodes[k], static_cast<int>(ids.size()));
      if (added) ids.push_back(elements.nodes[k]);
      element_nodes.push_back(it->second);
    }
    element_start.push_back(static_cast<int>(element_nodes.size()));
  }
  Partition(ids, element_start, element_nodes, communicator, "the mesh read");
}

void NodePartition::Partition(const std::vector<IndexType>& ids, std::vector<int>& element_start,
                              std::vector<int>& element_nodes, const AssemblyCommunicator& communicator,
                              const std::string& what) {
  // Rank 0 partitions; the parts travel to the others as a sum with zeros (exact in doubles).
  std::vector<double> part(ids.size(), 0.0);
  if (communicator.Rank() == 0 && size_ > 1 && static_cast<int>(ids.size()) > size_) {
    idx_t element_count = static_cast<idx_t>(element_start.size()) - 1;
    idx_t node_count = static_cast<idx_t>(ids.size());
    idx_t parts = size_;
    idx_t cut = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    std::vector<idx_t> element_part(static_cast<std::size_t>(element_count)), node_part(ids.size());
    const int status =
        METIS_PartMeshNodal(&element_count, &node_count, element_start.data(), element_nodes.data(), nullptr, nullptr,
                            &parts, nullptr, options, &cut, element_part.data(), node_part.data());
    if (status != METIS_OK)
      throw Error(Concat("METIS could not partition the ", node_count, " nodes of ", what, " into ", parts,
                         " parts (status ", status, ")"));
    for (std::size_t i = 0; i < ids.size(); ++i) part[i] = static_cast<double>(node_part[i]);
  } else if (communicator.Rank() == 0 && size_ > 1) {
    // Fewer nodes than ranks: METIS refuses; one node per rank, the last ranks empty.
    for (std::size_t i = 0; i < ids.size(); ++i) part[i] = static_cast<double>(i);
  }
  communicator.SumToAll(part.data(), part.size());
  owner_.reserve(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) owner_.emplace(ids[i], static_cast<int>(part[i]));
}

int NodePartition::Owner(const Node& node) const { return OwnerOf(node.Id()); }

bool NodePartition::IsFor(const ModelPart& model_part) const {
  return model_part_ == &model_part && nodes_ == model_part.NumberOfNodes() &&
         elements_ == model_part.NumberOfElements();
}

void NodePartition::KeepOnly(const std::vector<IndexType>& node_ids) {
  std::unordered_map<IndexType, int> kept;
  kept.reserve(node_ids.size());
  for (const auto& [id, owner] : owner_)
    if (std::binary_search(node_ids.begin(), node_ids.end(), id)) kept.emplace(id, owner);
  owner_ = std::move(kept);
}

}  // namespace mc
