// SPDX-License-Identifier: BSD-3-Clause
#include "core/io/mdpa_mesh.h"

#include <algorithm>
#include <numeric>

#include "core/io/mdpa_values.h"
#include "core/utilities/disjoint_sets.h"
#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"

namespace mc {

namespace {

using mdpa::Line;
using mdpa::LineCursor;
using mdpa::NextToken;
using mdpa::ToInteger;

bool Contains(const std::vector<IndexType>& sorted, IndexType id) {
  return std::binary_search(sorted.begin(), sorted.end(), id);
}

void SortUnique(std::vector<IndexType>& ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

/// "id property_id node ids..." appended to `entities`; false (nothing appended) if unreadable.
bool AddEntity(std::string_view first, std::string_view rest, MdpaMesh::Connectivity& entities) {
  IndexType id = 0, property = 0;
  if (!ToInteger(first, id) || !ToInteger(NextToken(rest), property)) return false;
  const std::size_t size = entities.nodes.size();
  for (std::string_view token = NextToken(rest); !token.empty(); token = NextToken(rest)) {
    IndexType node = 0;
    if (!ToInteger(token, node)) {
      entities.nodes.resize(size);
      return false;
    }
    entities.nodes.push_back(node);
  }
  entities.ids.push_back(id);
  entities.start.push_back(entities.nodes.size());
  return true;
}

/// The entities in increasing id order (an mdpa may list them in any order; a model part keeps
/// them by id, and the partition must see them as the model part holds them).
void SortById(MdpaMesh::Connectivity& entities) {
  if (std::is_sorted(entities.ids.begin(), entities.ids.end())) return;
  std::vector<std::size_t> order(entities.Size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return entities.ids[a] < entities.ids[b]; });
  MdpaMesh::Connectivity sorted;
  for (std::size_t i : order) {
    sorted.ids.push_back(entities.ids[i]);
    sorted.nodes.insert(sorted.nodes.end(), entities.nodes.begin() + static_cast<std::ptrdiff_t>(entities.start[i]),
                        entities.nodes.begin() + static_cast<std::ptrdiff_t>(entities.start[i + 1]));
    sorted.start.push_back(sorted.nodes.size());
  }
  entities = std::move(sorted);
}

}  // namespace

bool MdpaMesh::Piece::KeepsNode(IndexType id) const { return Contains(nodes, id); }
bool MdpaMesh::Piece::KeepsElement(IndexType id) const { return Contains(elements, id); }
bool MdpaMesh::Piece::KeepsCondition(IndexType id) const { return Contains(conditions, id); }

MdpaMesh MdpaMesh::Read(const std::string& filename) { return FromText(mdpa::ReadText(filename)); }

MdpaMesh MdpaMesh::FromText(std::string_view text) {
  enum class Block { kOther, kNodes, kElements, kConditions, kPartNodes, kPartConditions };
  MdpaMesh mesh;
  std::vector<std::string_view> blocks;  // the keywords of the blocks open, outermost first
  std::vector<Block> kinds;
  std::vector<std::string> path;                 // the sub model parts open
  std::vector<std::vector<IndexType>*> targets;  // the lists a SubModelPartNodes/Conditions line adds to
  LineCursor cursor(text);
  Line line;
  while (cursor.Next(line)) {
    std::string_view rest = line.text;
    const std::string_view first = NextToken(rest);
    if (first == "Begin") {
      const std::string_view keyword = NextToken(rest);
      Block kind = Block::kOther;
      const bool in_part = !blocks.empty() && blocks.back() == "SubModelPart";
      if (blocks.empty() && keyword == "Nodes") kind = Block::kNodes;
      if (blocks.empty() && keyword == "Elements") kind = Block::kElements;
      if (blocks.empty() && keyword == "Conditions") kind = Block::kConditions;
      if (keyword == "SubModelPart") path.emplace_back(NextToken(rest));
      if (in_part && (keyword == "SubModelPartNodes" || keyword == "SubModelPartConditions")) {
        kind = keyword == "SubModelPartNodes" ? Block::kPartNodes : Block::kPartConditions;
        targets.clear();
        std::string name;
        for (const std::string& part : path) {
          name += (name.empty() ? "" : ".") + part;
          Members& members = mesh.parts_[name];
          targets.push_back(kind == Block::kPartNodes ? &members.nodes : &members.conditions);
        }
      }
      blocks.push_back(keyword);
      kinds.push_back(kind);
      continue;
    }
    if (first == "End") {
      if (blocks.empty()) continue;
      if (blocks.back() == "SubModelPart" && !path.empty()) path.pop_back();
      blocks.pop_back();
      kinds.pop_back();
      continue;
    }
    switch (kinds.empty() ? Block::kOther : kinds.back()) {
      case Block::kNodes:
        if (IndexType id = 0; ToInteger(first, id)) mesh.node_ids_.push_back(id);
        break;
      case Block::kElements: AddEntity(first, rest, mesh.elements_); break;
      case Block::kConditions: AddEntity(first, rest, mesh.conditions_); break;
      case Block::kPartNodes:
      case Block::kPartConditions:
        for (std::string_view token = first; !token.empty(); token = NextToken(rest))
          if (IndexType id = 0; ToInteger(token, id))
            for (std::vector<IndexType>* target : targets) target->push_back(id);
        break;
      case Block::kOther: break;
    }
  }
  SortUnique(mesh.node_ids_);
  SortById(mesh.elements_);
  SortById(mesh.conditions_);
  for (auto& [name, members] : mesh.parts_) {
    SortUnique(members.nodes);
    SortUnique(members.conditions);
  }
  return mesh;
}

const MdpaMesh::Members* MdpaMesh::Resolve(const std::string& root_name, const std::string& name) const {
  // The rules of ContactInterfaceBuilder::ResolvePart, on the names alone.
  const std::string prefix = root_name + ".";
  const std::string relative = name.rfind(prefix, 0) == 0 ? name.substr(prefix.size()) : name;
  if (const auto it = parts_.find(relative); it != parts_.end()) return &it->second;
  const Members* found = nullptr;
  std::size_t matches = 0;
  for (const auto& [path, members] : parts_) {
    const std::size_t dot = path.rfind('.');
    if ((dot == std::string::npos ? path : path.substr(dot + 1)) == relative) {
      found = &members;
      ++matches;
    }
  }
  return matches == 1 ? found : nullptr;
}

MdpaMesh::Piece MdpaMesh::PieceOf(const std::function<int(IndexType)>& owner, int rank, const std::string& root_name,
                                  const std::vector<std::string>& kept_whole) const {
  std::vector<IndexType> interface_nodes, whole_conditions;
  for (const std::string& name : kept_whole) {
    if (name == root_name || name == root_name + ".computing_domain" || name == "computing_domain")
      throw NotImplementedError(Concat("contact model part '", name, "' is the whole model: its skin is found from ",
                                       "every element, which no rank reading its piece holds"));
    const Members* members = Resolve(root_name, name);
    if (!members) continue;
    interface_nodes.insert(interface_nodes.end(), members->nodes.begin(), members->nodes.end());
    whole_conditions.insert(whole_conditions.end(), members->conditions.begin(), members->conditions.end());
  }
  SortUnique(whole_conditions);
  for (IndexType id : whole_conditions) {
    const auto it = std::lower_bound(conditions_.ids.begin(), conditions_.ids.end(), id);
    if (it == conditions_.ids.end() || *it != id) continue;
    const auto i = static_cast<std::size_t>(it - conditions_.ids.begin());
    interface_nodes.insert(interface_nodes.end(),
                           conditions_.nodes.begin() + static_cast<std::ptrdiff_t>(conditions_.start[i]),
                           conditions_.nodes.begin() + static_cast<std::ptrdiff_t>(conditions_.start[i + 1]));
  }
  SortUnique(interface_nodes);

  Piece piece;
  std::vector<IndexType>& nodes = piece.nodes;
  for (IndexType id : node_ids_)
    if (owner(id) == rank) nodes.push_back(id);
  const auto select = [&](const Connectivity& entities, std::vector<IndexType>& kept, const auto& whole) {
    for (std::size_t i = 0; i < entities.Size(); ++i) {
      const auto begin = entities.nodes.begin() + static_cast<std::ptrdiff_t>(entities.start[i]);
      const auto end = entities.nodes.begin() + static_cast<std::ptrdiff_t>(entities.start[i + 1]);
      const bool keep = whole(i) || std::any_of(begin, end, [&](IndexType node) {
                          return owner(node) == rank || Contains(interface_nodes, node);
                        });
      if (!keep) continue;
      kept.push_back(entities.ids[i]);
      nodes.insert(nodes.end(), begin, end);
    }
  };
  select(elements_, piece.elements, [](std::size_t) { return false; });
  select(conditions_, piece.conditions,
         [&](std::size_t i) { return i + 1 == conditions_.Size() || Contains(whole_conditions, conditions_.ids[i]); });
  nodes.insert(nodes.end(), interface_nodes.begin(), interface_nodes.end());
  SortUnique(nodes);
  SortUnique(piece.elements);
  SortUnique(piece.conditions);
  piece.interface_nodes = std::move(interface_nodes);
  return piece;
}

std::pair<std::unordered_map<IndexType, std::size_t>, std::size_t> MdpaMesh::Bodies(
    const std::vector<IndexType>& nodes) const {
  // As ContactSearchProcess::FindBodies on the whole model: a union-find over each element's nodes.
  std::unordered_map<IndexType, std::size_t> index;
  for (IndexType node : elements_.nodes) index.emplace(node, index.size());
  DisjointSets bodies(index.size());
  for (std::size_t i = 0; i < elements_.Size(); ++i)
    for (std::size_t k = elements_.start[i] + 1; k < elements_.start[i + 1]; ++k)
      bodies.Join(index.at(elements_.nodes[k]), index.at(elements_.nodes[elements_.start[i]]));
  std::unordered_map<IndexType, std::size_t> body_of;
  for (IndexType node : nodes)
    if (const auto it = index.find(node); it != index.end()) body_of.emplace(node, bodies.Find(it->second));
  return {std::move(body_of), index.size()};
}

}  // namespace mc
