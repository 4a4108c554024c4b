// SPDX-License-Identifier: BSD-3-Clause
#include "core/solving/node_partition.h"

#include <metis.h>

#include <vector>

#include "core/linear_solvers/assembly_communicator.h"
#include "core/model/model_part.h"
#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {

NodePartition::NodePartition(const ModelPart& model_part, const AssemblyCommunicator& communicator)
    : model_part_(&model_part),
      nodes_(model_part.NumberOfNodes()),
      elements_(model_part.NumberOfElements()),
      size_(communicator.Size()) {
  // The element nodes, numbered 0.. in order of first appearance, as METIS' mesh arrays.
  std::vector<const Node*> nodes;
  std::vector<idx_t> element_start{0}, element_nodes;
  std::unordered_map<const Node*, idx_t> index;
  for (const Element* element : model_part.Elements()) {
    const Geometry& geometry = element->GetGeometry();
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i) {
      const auto [it, added] = index.emplace(&geometry[i], static_cast<idx_t>(nodes.size()));
      if (added) nodes.push_back(&geometry[i]);
      element_nodes.push_back(it->second);
    }
    element_start.push_back(static_cast<idx_t>(element_nodes.size()));
  }
  // Rank 0 partitions; the parts travel to the others as a sum with zeros (exact in doubles).
  std::vector<double> part(nodes.size(), 0.0);
  if (communicator.Rank() == 0 && size_ > 1 && static_cast<int>(nodes.size()) > size_) {
    idx_t element_count = static_cast<idx_t>(element_start.size()) - 1;
    idx_t node_count = static_cast<idx_t>(nodes.size());
    idx_t parts = size_;
    idx_t cut = 0;
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    std::vector<idx_t> element_part(static_cast<std::size_t>(element_count)), node_part(nodes.size());
    const int status =
        METIS_PartMeshNodal(&element_count, &node_count, element_start.data(), element_nodes.data(), nullptr, nullptr,
                            &parts, nullptr, options, &cut, element_part.data(), node_part.data());
    if (status != METIS_OK)
      throw Error(Concat("METIS could not partition the ", node_count, " nodes of model part '", model_part.Name(),
                         "' into ", parts, " parts (status ", status, ")"));
    for (std::size_t i = 0; i < nodes.size(); ++i) part[i] = static_cast<double>(node_part[i]);
  } else if (communicator.Rank() == 0 && size_ > 1) {
    // Fewer nodes than ranks: METIS refuses; one node per rank, the last ranks empty.
    for (std::size_t i = 0; i < nodes.size(); ++i) part[i] = static_cast<double>(i);
  }
  communicator.SumToAll(part.data(), part.size());
  owner_.reserve(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) owner_.emplace(nodes[i], static_cast<int>(part[i]));
}

bool NodePartition::IsFor(const ModelPart& model_part) const {
  return model_part_ == &model_part && nodes_ == model_part.NumberOfNodes() &&
         elements_ == model_part.NumberOfElements();
}

}  // namespace mc
