// SPDX-License-Identifier: BSD-3-Clause
#include "core/model/model_part_partitioner.h"

#include <unordered_set>

#include "core/model/model_part.h"
#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"
#include "core/variables/flags.h"

namespace mc {

ModelPartPartitioner::ModelPartPartitioner(std::function<int(const Node&)> owner, int rank)
    : owner_(std::move(owner)), rank_(rank) {}

bool ModelPartPartitioner::Owns(const Entity& entity) const {
  const Geometry& geometry = entity.GetGeometry();
  return geometry.PointsNumber() == 0 ? rank_ == 0 : owner_(geometry[0]) == rank_;
}

ModelPartPartitioner::Piece ModelPartPartitioner::Cut(ModelPart& root,
                                                      const std::vector<const ModelPart*>& replicated) const {
  if (!root.MasterSlaveConstraints().empty())
    throw NotImplementedError(Concat("cutting model part '", root.Name(), "' across the ranks with its ",
                                     root.MasterSlaveConstraints().size(),
                                     " master-slave constraints: run it on one process"));
  std::unordered_set<const Node*> kept_nodes;
  std::unordered_set<const Entity*> kept_conditions;
  for (const ModelPart* part : replicated) {
    for (const Node* node : part->Nodes()) kept_nodes.insert(node);
    for (const Condition* condition : part->Conditions()) kept_conditions.insert(condition);
  }
  // An entity stays when it touches an owned node (it adds to an owned row) or is replicated.
  const auto keep = [&](Entity& entity, bool replicated_entity) {
    const Geometry& geometry = entity.GetGeometry();
    bool touches = replicated_entity;
    for (std::size_t i = 0; i < geometry.PointsNumber() && !touches; ++i) touches = owner_(geometry[i]) == rank_;
    if (!touches) entity.Set(TO_ERASE);
    for (std::size_t i = 0; i < geometry.PointsNumber() && touches; ++i) kept_nodes.insert(&geometry[i]);
    return touches;
  };
  Piece piece;
  for (Element* element : root.Elements()) piece.elements += keep(*element, false);
  for (Condition* condition : root.Conditions())
    piece.conditions += keep(*condition, kept_conditions.count(condition) > 0);
  for (Node* node : root.Nodes()) {
    const bool owned = owner_(*node) == rank_;
    const bool stays = owned || kept_nodes.count(node) > 0;
    if (!stays) node->Set(TO_ERASE);
    piece.owned_nodes += owned;
    piece.ghost_nodes += stays && !owned;
  }
  root.RemoveElementsFlagged(TO_ERASE);
  root.RemoveConditionsFlagged(TO_ERASE);
  root.RemoveNodesFlagged(TO_ERASE);
  return piece;
}

}  // namespace mc
