// SPDX-License-Identifier: BSD-3-Clause
// Issue 17, step 3, part 1 on a real contact case (Kratos' 2D Hertz sphere on a plate): each rank
// cut from the model read whole keeps the elements touching its nodes, the conditions (pressure
// loads) likewise, and the whole contact interface (its nodes and conditions, on both bodies,
// reaching nodes other ranks own); the ranks' owned elements are the model exactly once, and each
// rank keeps a real share of it. Owners here: slabs of the x coordinate, as many as ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "core/model/model_part_partitioner.h"
#include "tests/cpp/contact_processes/contact_processes_test_utilities.h"

namespace mc {
namespace {

constexpr const char* kCase = "ALM_frictionless_contact_test_2D/simple_hertz_sphere_plate_test.mdpa";

template <class Container>
std::set<IndexType> Ids(const Container& items) {
  std::set<IndexType> ids;
  for (const auto* item : items) ids.insert(item->Id());
  return ids;
}

/// Node id -> rank: `size` slabs of x with as many nodes each.
std::map<IndexType, int> SlabOwners(const ModelPart& root, int size) {
  std::vector<const Node*> nodes(root.Nodes().begin(), root.Nodes().end());
  std::stable_sort(nodes.begin(), nodes.end(), [](const Node* a, const Node* b) { return a->X0().x() < b->X0().x(); });
  std::map<IndexType, int> owner;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    owner[nodes[i]->Id()] = static_cast<int>(i * static_cast<std::size_t>(size) / nodes.size());
  return owner;
}

class PartitionedInterface : public ::testing::TestWithParam<int> {};

TEST_P(PartitionedInterface, EachRankKeepsItsShareAndTheWholeInterface) {
  const int size = GetParam();
  Model whole_model;
  ModelPart& whole = test::ReadCase(whole_model, kCase);
  const ModelPart& whole_interface = test::BuildInterface(whole, {"Contact_Part"});
  const std::map<IndexType, int> owner = SlabOwners(whole, size);
  ASSERT_GT(whole_interface.NumberOfConditions(), 10U);

  std::map<IndexType, int> owned_by;
  for (int rank = 0; rank < size; ++rank) {
    Model model;
    ModelPart& root = test::ReadCase(model, kCase);
    ModelPart& interface = test::BuildInterface(root, {"Contact_Part"});
    const ModelPartPartitioner partitioner([&](const Node& node) { return owner.at(node.Id()); }, rank);
    const auto piece = partitioner.Cut(root, {&interface, &root.GetSubModelPart("Contact_Part")});

    std::set<IndexType> elements, conditions;
    const auto touches = [&](const Entity& entity) {
      const Geometry& g = entity.GetGeometry();
      for (std::size_t i = 0; i < g.PointsNumber(); ++i)
        if (owner.at(g[i].Id()) == rank) return true;
      return false;
    };
    for (const Element* e : whole.Elements())
      if (touches(*e)) elements.insert(e->Id());
    for (const Condition* c : whole.Conditions())
      if (touches(*c) || whole_interface.FindCondition(c->Id()) == c) conditions.insert(c->Id());
    EXPECT_EQ(Ids(root.Elements()), elements) << "rank " << rank;
    EXPECT_EQ(Ids(root.Conditions()), conditions) << "rank " << rank;
    EXPECT_EQ(Ids(interface.Nodes()), Ids(whole_interface.Nodes())) << "rank " << rank;
    EXPECT_EQ(Ids(interface.Conditions()), Ids(whole_interface.Conditions())) << "rank " << rank;
    // Every sub model part keeps only what the root kept; the loads' part its share.
    for (const ModelPart* part : root.SubModelParts())
      for (const Node* node : part->Nodes()) EXPECT_EQ(root.FindNode(node->Id()), node) << part->Name();
    EXPECT_LT(root.GetSubModelPart("LineLoad2D_bc_pressure").NumberOfConditions(),
              whole.GetSubModelPart("LineLoad2D_bc_pressure").NumberOfConditions());
    // A real share: at most the owned part and its border, not the whole model.
    EXPECT_LT(static_cast<double>(piece.elements), 0.75 * static_cast<double>(whole.NumberOfElements()))
        << "rank " << rank;
    EXPECT_EQ(piece.owned_nodes + piece.ghost_nodes, root.NumberOfNodes());
    for (const Element* e : root.Elements())
      if (partitioner.Owns(*e)) ++owned_by[e->Id()];
  }
  EXPECT_EQ(owned_by.size(), whole.NumberOfElements());
  for (const auto& [id, count] : owned_by) EXPECT_EQ(count, 1) << "element " << id;
}

INSTANTIATE_TEST_SUITE_P(Ranks, PartitionedInterface, ::testing::Values(2, 3));

}  // namespace
}  // namespace mc
