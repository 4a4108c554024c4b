// SPDX-License-Identifier: BSD-3-Clause
// Issue 17, step 3 (the model partitioned), parts 1 and 2 on their own: ranks simulated by threads
// each read the whole model, cut it to their piece (ModelPartPartitioner) and number their DoFs by
// an exclusive scan (DistributedDofNumbering). Checked against the whole model: each rank keeps
// exactly the elements touching its nodes, their nodes (owned + one ghost layer) and the whole
// contact interface; the ranks' owned elements are the model exactly once; every DoF gets the
// replicated builder's equation id (its owner's block, node id then variable order) on every rank
// holding it; the ghost scatter brings the owners' values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <thread>

#include "core/io/mdpa_mesh.h"
#include "core/model/model.h"
#include "core/model/model_part.h"
#include "core/model/model_part_partitioner.h"
#include "core/solving/distributed_dof_numbering.h"
#include "core/solving/node_partition.h"
#include "core/utilities/string_utilities.h"
#include "core/variables/kernel_variables.h"
#include "test_elements.h"
#include "tests/cpp/common/error_message.h"
#include "tests/cpp/common/thread_communicator.h"

namespace mc {
namespace {

using test::ThreadCommunicator;
using test::ThreadRanks;

// A grid of kNx x kNy nodes joined by springs along both directions and one diagonal a cell, a
// load on every node of the top row ("Loads") and an interface "Contact" on the bottom row: load
// conditions on all its nodes but the last (an interface node in no condition stays too).
constexpr IndexType kNx = 9;
constexpr IndexType kNy = 6;
constexpr IndexType kContactFirst = 1000;

struct Grid {
  Model model;
  ModelPart& mp = test::MakeModelPart(model);
  Grid() {
    const auto id = [](IndexType i, IndexType j) { return j * kNx + i + 1; };
    for (IndexType j = 0; j < kNy; ++j)
      for (IndexType i = 0; i < kNx; ++i)
        test::AddNode(mp, id(i, j), static_cast<double>(i), static_cast<double>(j), 2);
    IndexType element = 0;
    for (IndexType j = 0; j < kNy; ++j)
      for (IndexType i = 0; i < kNx; ++i) {
        if (i + 1 < kNx) test::AddSpring(mp, ++element, id(i, j), id(i + 1, j), 1.0, 0.0, 2);
        if (j + 1 < kNy) test::AddSpring(mp, ++element, id(i, j), id(i, j + 1), 1.0, 0.0, 2);
        if (i + 1 < kNx && j + 1 < kNy) test::AddSpring(mp, ++element, id(i, j), id(i + 1, j + 1), 1.0, 0.0, 2);
      }
    ModelPart& loads = mp.CreateSubModelPart("Loads");
    for (IndexType i = 0; i < kNx; ++i) {
      test::AddLoad(mp, i + 1, id(i, kNy - 1), 1.0);
      loads.AddNodes({id(i, kNy - 1)});
      loads.AddConditions({i + 1});
    }
    ModelPart& contact = mp.CreateSubModelPart("Contact");
    for (IndexType i = 0; i < kNx; ++i) {
      contact.AddNodes({id(i, 0)});
      if (i + 1 == kNx) continue;
      test::AddLoad(mp, kContactFirst + i, id(i, 0), 1.0);
      contact.AddConditions({kContactFirst + i});
    }
  }
};

template <class Container>
std::set<IndexType> Ids(const Container& items) {
  std::set<IndexType> ids;
  for (const auto* item : items) ids.insert(item->Id());
  return ids;
}

/// This rank's DoF set in the builder's order (node id, then variable key).
std::vector<Dof*> DofSet(const ModelPart& mp) {
  std::vector<Dof*> dofs;
  DofsVectorType local;
  for (const Element* e : mp.Elements()) {
    e->GetDofList(local, mp.GetProcessInfo());
    dofs.insert(dofs.end(), local.begin(), local.end());
  }
  for (const Condition* c : mp.Conditions()) {
    c->GetDofList(local, mp.GetProcessInfo());
    dofs.insert(dofs.end(), local.begin(), local.end());
  }
  const auto less = [](const Dof* a, const Dof* b) {
    return std::pair{a->node->Id(), a->variable->Key()} < std::pair{b->node->Id(), b->variable->Key()};
  };
  std::sort(dofs.begin(), dofs.end(), less);
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

/// What one rank saw: the owners before the cut (every rank computes the same), its piece after.
struct RankView {
  std::map<IndexType, int> owner;
  ModelPartPartitioner::Piece piece;
  std::set<IndexType> nodes, elements, conditions, owned_elements, loads_nodes, contact_nodes, contact_conditions;
  std::map<std::pair<IndexType, std::size_t>, std::int64_t> equation_id;
  std::int64_t begin = 0, end = 0, rows = 0;
  std::vector<double> scattered;
  std::vector<std::int64_t> scattered_ids;
};

constexpr double Tagged(std::int64_t id) { return 1.5 * static_cast<double>(id) + 0.25; }

RankView RunRank(Grid& grid, ThreadRanks& ranks, int rank) {
  ThreadCommunicator communicator(ranks, rank);
  ModelPart& mp = grid.mp;
  const NodePartition partition(mp, communicator);
  RankView view;
  for (const Node* node : mp.Nodes()) view.owner[node->Id()] = partition.Owner(*node);
  const ModelPartPartitioner partitioner([&](const Node& node) { return partition.Owner(node); }, rank);
  view.piece = partitioner.Cut(mp, {&mp.GetSubModelPart("Contact")});
  view.nodes = Ids(mp.Nodes());
  view.elements = Ids(mp.Elements());
  view.conditions = Ids(mp.Conditions());
  for (const Element* e : mp.Elements())
    if (partitioner.Owns(*e)) view.owned_elements.insert(e->Id());
  view.loads_nodes = Ids(mp.GetSubModelPart("Loads").Nodes());
  view.contact_nodes = Ids(mp.GetSubModelPart("Contact").Nodes());
  view.contact_conditions = Ids(mp.GetSubModelPart("Contact").Conditions());

  const std::vector<Dof*> dofs = DofSet(mp);
  const DistributedDofNumbering numbering(
      dofs, [&](const Node& node) { return partition.Owner(node); }, communicator);
  view.begin = numbering.Begin();
  view.end = numbering.End();
  view.rows = numbering.Rows();
  for (const Dof* d : dofs) view.equation_id[{d->node->Id(), d->variable->Key()}] = d->equation_id;
  view.scattered.assign(dofs.size(), std::nan(""));
  for (std::size_t i = 0; i < dofs.size(); ++i)
    if (partition.Owner(*dofs[i]->node) == rank) view.scattered[i] = Tagged(dofs[i]->equation_id);
  numbering.UpdateGhosts(view.scattered);
  for (const Dof* d : dofs) view.scattered_ids.push_back(d->equation_id);
  return view;
}

std::vector<RankView> RunRanks(int size) {
  ThreadRanks ranks(size);
  std::vector<std::unique_ptr<Grid>> grids;
  for (int r = 0; r < size; ++r) grids.push_back(std::make_unique<Grid>());
  std::vector<RankView> views(static_cast<std::size_t>(size));
  std::vector<std::thread> threads;
  for (int r = 0; r < size; ++r)
    threads.emplace_back(
        [&, r] { views[static_cast<std::size_t>(r)] = RunRank(*grids[static_cast<std::size_t>(r)], ranks, r); });
  for (auto& t : threads) t.join();
  return views;
}

class PartitionedModel : public ::testing::TestWithParam<int> {};

TEST_P(PartitionedModel, EachRankKeepsItsElementsTheirNodesAndTheWholeInterface) {
  const int size = GetParam();
  const Grid whole;
  const std::vector<RankView> views = RunRanks(size);
  std::map<IndexType, int> owned_by;  // element id -> how many ranks own it
  for (int r = 0; r < size; ++r) {
    const RankView& view = views[static_cast<std::size_t>(r)];
    EXPECT_EQ(view.owner, views.front().owner) << "the ranks disagree on the node owners";
    std::set<IndexType> elements, nodes, owned_nodes;
    for (const auto& [id, owner] : view.owner)
      if (owner == r) owned_nodes.insert(id);
    ASSERT_FALSE(owned_nodes.empty()) << "rank " << r;
    for (const Element* e : whole.mp.Elements()) {
      const Geometry& g = e->GetGeometry();
      const bool touches = view.owner.at(g[0].Id()) == r || view.owner.at(g[1].Id()) == r;
      if (!touches) continue;
      elements.insert(e->Id());
      nodes.insert({g[0].Id(), g[1].Id()});
    }
    EXPECT_EQ(view.elements, elements) << "rank " << r;
    EXPECT_LT(view.elements.size(), whole.mp.NumberOfElements()) << "rank " << r << " kept the whole mesh";
    // Nodes: owned, the ghost layer of its elements, the whole interface; nothing else.
    nodes.insert(owned_nodes.begin(), owned_nodes.end());
    const std::set<IndexType> contact_nodes = Ids(whole.mp.GetSubModelPart("Contact").Nodes());
    nodes.insert(contact_nodes.begin(), contact_nodes.end());
    EXPECT_EQ(view.nodes, nodes) << "rank " << r;
    EXPECT_EQ(view.piece.owned_nodes, owned_nodes.size());
    EXPECT_EQ(view.piece.owned_nodes + view.piece.ghost_nodes, view.nodes.size());
    EXPECT_EQ(view.piece.elements, view.elements.size());
    EXPECT_EQ(view.contact_nodes, contact_nodes) << "rank " << r;
    EXPECT_EQ(view.contact_conditions, Ids(whole.mp.GetSubModelPart("Contact").Conditions())) << "rank " << r;
    // The loads of the top row stay with the ranks owning their node, in the sub model part too.
    for (IndexType i = 1; i <= kNx; ++i) {
      const IndexType node = whole.mp.GetCondition(i).GetGeometry()[0].Id();
      EXPECT_EQ(view.conditions.count(i), view.owner.at(node) == r ? 1U : 0U) << "load " << i << " rank " << r;
      if (view.owner.at(node) == r) {
        EXPECT_EQ(view.loads_nodes.count(node), 1U);
      }
    }
    for (const IndexType id : view.loads_nodes) EXPECT_EQ(view.nodes.count(id), 1U) << "node " << id;
    for (const IndexType id : view.owned_elements) ++owned_by[id];
  }
  EXPECT_EQ(owned_by.size(), whole.mp.NumberOfElements());
  for (const auto& [id, count] : owned_by) EXPECT_EQ(count, 1) << "element " << id;
}

TEST_P(PartitionedModel, EveryRankGivesADofTheReplicatedEquationIdAndTheGhostsTheOwnersValues) {
  const int size = GetParam();
  Grid whole;
  const std::vector<RankView> views = RunRanks(size);
  // The replicated builder's numbering: the whole DoF set in order, grouped by owner rank.
  std::map<std::pair<IndexType, std::size_t>, std::int64_t> expected;
  std::int64_t next = 0;
  const std::vector<Dof*> all = DofSet(whole.mp);
  for (int r = 0; r < size; ++r)
    for (const Dof* d : all)
      if (views.front().owner.at(d->node->Id()) == r) expected[{d->node->Id(), d->variable->Key()}] = next++;
  std::int64_t begin = 0;
  std::size_t ghosts = 0;
  for (int r = 0; r < size; ++r) {
    const RankView& view = views[static_cast<std::size_t>(r)];
    EXPECT_EQ(view.begin, begin) << "rank " << r;
    EXPECT_EQ(view.rows, static_cast<std::int64_t>(all.size()));
    begin = view.end;
    for (const auto& [key, id] : view.equation_id) {
      EXPECT_EQ(id, expected.at(key)) << "node " << key.first << " rank " << r;
      ghosts += view.owner.at(key.first) != r;
    }
    for (std::size_t i = 0; i < view.scattered.size(); ++i)
      EXPECT_EQ(view.scattered[i], Tagged(view.scattered_ids[i])) << "rank " << r;
  }
  EXPECT_EQ(begin, static_cast<std::int64_t>(all.size()));
  EXPECT_GT(ghosts, 0U);
}

TEST_P(PartitionedModel, TheFileStreamedBeforeReadingIsPartitionedAsTheModelReadWhole) {
  // Issue 17: a rank reading only its piece partitions the mdpa's connectivity (MdpaMesh), listed
  // here in another order than the ids, and must find the owners the model read whole gets.
  const int size = GetParam();
  std::string text = "Begin Nodes\n";
  const Grid grid;
  for (const Node* node : grid.mp.Nodes()) text += Concat(node->Id(), " ", node->X0()[0], " ", node->X0()[1], " 0\n");
  text += "End Nodes\nBegin Elements Spring\n";
  const std::size_t count = grid.mp.NumberOfElements();
  for (std::size_t k = 0; k < count; ++k) {
    const Element& element = *grid.mp.Elements()[(k * 11) % count];  // 11 and the count are coprime
    text += Concat(element.Id(), " 0 ", element.GetGeometry()[0].Id(), " ", element.GetGeometry()[1].Id(), "\n");
  }
  text += "End Elements\n";
  ASSERT_NE(count % 11, 0U);
  const MdpaMesh mesh = MdpaMesh::FromText(text);
  ThreadRanks ranks(size);
  std::vector<std::map<IndexType, int>> from_model(static_cast<std::size_t>(size)), from_file(from_model);
  std::vector<std::thread> threads;
  for (int r = 0; r < size; ++r)
    threads.emplace_back([&, r] {
      ThreadCommunicator communicator(ranks, r);
      const NodePartition model_partition(grid.mp, communicator);
      const NodePartition file_partition(mesh, communicator);
      for (const Node* node : grid.mp.Nodes()) {
        from_model[static_cast<std::size_t>(r)][node->Id()] = model_partition.Owner(*node);
        from_file[static_cast<std::size_t>(r)][node->Id()] = file_partition.OwnerOf(node->Id());
      }
    });
  for (auto& t : threads) t.join();
  std::set<int> parts;
  for (const auto& [id, owner] : from_model.front()) parts.insert(owner);
  EXPECT_EQ(parts.size(), static_cast<std::size_t>(size));
  for (int r = 0; r < size; ++r) EXPECT_EQ(from_file[static_cast<std::size_t>(r)], from_model.front()) << "rank " << r;
}

INSTANTIATE_TEST_SUITE_P(Ranks, PartitionedModel, ::testing::Values(2, 3, 4));

TEST(PartitionedModel, AGhostDofItsOwnerLacksIsNamedOnBothRanks) {
  // Rank 1 holds DISPLACEMENT_Y of node 1, which rank 0 owns with DISPLACEMENT_X only.
  ThreadRanks ranks(2);
  std::vector<std::string> messages(2);
  std::vector<std::thread> threads;
  for (int r = 0; r < 2; ++r)
    threads.emplace_back([&, r] {
      Model model;
      ModelPart& mp = test::MakeModelPart(model);
      Node& node = test::AddNode(mp, 1, 0.0, 0.0, r == 0 ? 1 : 2);
      std::vector<Dof*> dofs{&node.GetDof(DISPLACEMENT_X)};
      if (r == 1) dofs.push_back(&node.GetDof(DISPLACEMENT_Y));
      ThreadCommunicator communicator(ranks, r);
      messages[static_cast<std::size_t>(r)] = test::ErrorMessageOf<Error>([&] {
        DistributedDofNumbering(
            dofs, [](const Node&) { return 0; }, communicator);
      });
    });
  for (auto& t : threads) t.join();
  EXPECT_NE(messages[0].find("rank 1 ghosts node 1"), std::string::npos) << messages[0];
  EXPECT_NE(messages[0].find("rank 0 owns but has no such DoF"), std::string::npos) << messages[0];
  EXPECT_NE(messages[1].find("rank 0 owns node 1 but not its DISPLACEMENT_Y, which rank 1 holds"), std::string::npos)
      << messages[1];
}

TEST(PartitionedModel, MasterSlaveConstraintsAreRefused) {
  Grid grid;
  grid.mp.AddMasterSlaveConstraint(std::make_shared<MasterSlaveConstraint>(
      1, grid.mp.GetNode(1).GetDof(DISPLACEMENT_X), std::vector<Dof*>{&grid.mp.GetNode(2).GetDof(DISPLACEMENT_X)},
      std::vector<double>{1.0}, 0.0));
  const ModelPartPartitioner partitioner([](const Node& node) { return node.Id() % 2 == 0 ? 1 : 0; }, 0);
  const std::string message = test::ErrorMessageOf<NotImplementedError>([&] { partitioner.Cut(grid.mp, {}); });
  EXPECT_NE(message.find("1 master-slave constraints"), std::string::npos) << message;
}

}  // namespace
}  // namespace mc
