// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/contact_search_process.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <set>
#include <unordered_map>
#include <utility>

#include "core/geometries/reference_element.h"
#include "core/model/parallel_utilities.h"
#include "core/model/registry.h"
#include "core/parameters/no_effect_warnings.h"
#include "core/utilities/disjoint_sets.h"
#include "core/utilities/error.h"
#include "core/utilities/logger.h"
#include "core/utilities/string_utilities.h"
#include "core/variables/kernel_variables.h"
#include "custom_conditions/paired_condition.h"
#include "custom_processes/contact_interface_builder.h"
#include "custom_utilities/contact_search_geometry.h"
#include "custom_utilities/contact_search_tree.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/nodal_normal_support.h"
#include "custom_utilities/normal_calculation_utilities.h"
#include "custom_utilities/predicted_configuration.h"

namespace mc {

namespace {

// How far, as a fraction of the slave face's size, a master face's projection may lie from the
// slave's and still be paired with it (the mapping check, below).
constexpr double kSlideMargin = 0.1;

// Accepted spellings -> canonical names (spec 4.3).
const std::map<std::string, std::string>& SearchTypeNames() {
  static const std::map<std::string, std::string> names = {
      {"in_radius", "in_radius"},
      {"InRadius", "in_radius"},
      {"in_box", "in_box"},
      {"InBox", "in_box"},
      {"in_radius_with_obb", "in_radius_with_obb"},
      {"InRadiusWithOBB", "in_radius_with_obb"},
      {"in_box_with_obb", "in_box_with_obb"},
      {"InBoxWithOBB", "in_box_with_obb"},
      // An octree of OBBs finds the same pairs as the KD-tree plus the OBB test.
      {"octree_with_obb", "in_radius_with_obb"},
      {"OctreeWithOBB", "in_radius_with_obb"},
  };
  return names;
}

const std::map<std::string, std::string>& CheckGapNames() {
  static const std::map<std::string, std::string> names = {
      {"no_check", "no_check"},           {"NoCheck", "no_check"},
      {"direct_check", "direct_check"},   {"DirectCheck", "direct_check"},
      {"mapping_check", "mapping_check"}, {"MappingCheck", "mapping_check"},
      {"check_mapping", "mapping_check"},
  };
  return names;
}

std::vector<std::string> Keys(const std::map<std::string, std::string>& map) {
  std::vector<std::string> keys;
  for (const auto& [key, value] : map) keys.push_back(key);
  return keys;
}

bool ShareNode(const Geometry& a, const Geometry& b) {
  for (const Node* na : a.Nodes())
    for (const Node* nb : b.Nodes())
      if (na == nb) return true;
  return false;
}

// "2D2N", "3D3N", "3D3N4N" (spec 6.2).
std::string GeometryToken(const Geometry& slave, const Geometry& master) {
  std::string token = Concat(slave.WorkingSpaceDimension(), "D", slave.PointsNumber(), "N");
  if (master.PointsNumber() != slave.PointsNumber()) token += Concat(master.PointsNumber(), "N");
  return token;
}

struct Box {
  Array3 lo, hi;
};

Box BoundingBox(const Geometry& geometry, double grow) {
  Box box{Array3::Constant(std::numeric_limits<double>::max()), Array3::Constant(-std::numeric_limits<double>::max())};
  for (const Node* node : geometry.Nodes()) {
    box.lo = box.lo.cwiseMin(node->Coordinates());
    box.hi = box.hi.cwiseMax(node->Coordinates());
  }
  box.lo.array() -= grow;
  box.hi.array() += grow;
  return box;
}

bool Overlap(const Box& a, const Box& b) {
  return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

// Per-condition data computed once per search.
struct FaceData {
  Condition* condition;
  Array3 center;
  Array3 normal;
  double length;
  double radius;  // of the ball around the centre holding the nodes
  std::size_t body;
};

FaceData MakeFaceData(Condition* condition, std::size_t body) {
  const Geometry& geometry = condition->GetGeometry();
  FaceData data{condition, geometry.Center(), condition->GetValue(NORMAL), InterfaceCharacteristicLength(geometry), 0.0,
                body};
  for (const Node* node : geometry.Nodes())
    data.radius = std::max(data.radius, (node->Coordinates() - data.center).norm());
  return data;
}

ModelPart& ComputingSubPart(ModelPart& root, const std::string& id) {
  ModelPart& computing = root.HasSubModelPart("ComputingContact") ? root.GetSubModelPart("ComputingContact")
                                                                  : root.CreateSubModelPart("ComputingContact");
  const std::string name = "ComputingContactSub" + id;
  return computing.HasSubModelPart(name) ? computing.GetSubModelPart(name) : computing.CreateSubModelPart(name);
}

}  // namespace

Parameters ContactSearchProcess::GetDefaultParameters() {
  return Parameters(R"({
    "type_search": "in_radius_with_obb",
    "simple_search": false,
    "adapt_search": false,
    "search_factor": 3.5,
    "active_check_factor": 0.01,
    "max_number_results": 1000,
    "bucket_size": 4,
    "dynamic_search": false,
    "static_check_movement": false,
    "database_step_update": 1,
    "normal_orientation_threshold": 0.1,
    "consider_gap_threshold": false,
    "debug_mode": false,
    "predict_correct_lagrange_multiplier": false,
    "check_gap": "check_mapping",
    "octree_search_parameters": {
      "bounding_box_factor": 0.1,
      "debug_obb": false,
      "OBB_intersection_type": "SeparatingAxisTheorem",
      "build_from_bounding_box": true,
      "lower_bounding_box_coefficient": 0.0,
      "higher_bounding_box_coefficient": 1.0
    }
  })");
}

ContactSearchProcess::ContactSearchProcess(ModelPart& root, ModelPart& interface, Parameters search_parameters,
                                           ContactSearchSlot slot)
    : root_(root),
      interface_(interface),
      computing_(ComputingSubPart(root, slot.id)),
      settings_(std::move(search_parameters)),
      slot_(std::move(slot)) {
  settings_.RecursivelyValidateAndAssignDefaults(GetDefaultParameters());
  WarnAboutKeysWithoutEffect();
  const std::string type = settings_["type_search"].GetString();
  if (ToLower(type) == "kdop")
    throw NotImplementedError(Concat(settings_.Where(), ".type_search: 'kdop' is not implemented (as in Kratos); use ",
                                     "'in_radius_with_obb'"));
  const auto& types = SearchTypeNames();
  if (auto it = types.find(type); it != types.end()) {
    type_search_ = it->second;
    if (ToLower(type).rfind("octree", 0) == 0)
      NoEffectWarnings::Warn(settings_, "type_search",
                             "no octree is built; the search runs as 'in_radius_with_obb' (KD-tree of the master "
                             "centres plus the same oriented-box test), which finds the same pairs");
  } else {
    type_search_ = "in_radius";
    Logger::Warning(Concat(settings_.Where(), ".type_search: unknown value '", type, "', using 'in_radius'",
                           DidYouMean(type, Keys(types))));
  }
  const std::string check = settings_["check_gap"].GetString();
  const auto& checks = CheckGapNames();
  if (auto it = checks.find(check); it != checks.end()) {
    check_gap_ = it->second;
  } else {
    check_gap_ = "mapping_check";
    Logger::Warning(Concat(settings_.Where(), ".check_gap: unknown value '", check, "', using 'mapping_check'",
                           DidYouMean(check, Keys(checks))));
  }
  if (!(settings_["search_factor"].GetDouble() > 0.0))
    throw InputError(
        Concat(settings_.Where(), ".search_factor: must be positive, got ", settings_["search_factor"].GetDouble()));
}

void ContactSearchProcess::WarnAboutKeysWithoutEffect() const {
  const Parameters defaults = GetDefaultParameters();
  if (!root_.HasNodalSolutionStepVariable(VELOCITY))
    NoEffectWarnings::IfGiven(settings_, defaults, "dynamic_search",
                              "the problem is static: there is no velocity to predict the positions with");
  NoEffectWarnings::IfGiven(settings_, defaults, "debug_mode", "the search writes no debug output");
  NoEffectWarnings::IfGiven(settings_, defaults, "predict_correct_lagrange_multiplier",
                            "the multipliers are not predicted (Kratos does not read the key either)");
  const Parameters octree = settings_["octree_search_parameters"];
  const Parameters octree_defaults = defaults["octree_search_parameters"];
  for (const char* key :
       {"debug_obb", "build_from_bounding_box", "lower_bounding_box_coefficient", "higher_bounding_box_coefficient"})
    NoEffectWarnings::IfGiven(octree, octree_defaults, key,
                              "the oriented boxes are built from the face geometry grown by bounding_box_factor, "
                              "the only key of octree_search_parameters read here");
  NoEffectWarnings::IfGiven(octree, octree_defaults, "OBB_intersection_type",
                            "the oriented boxes are always intersected with the separating-axis theorem");
}

void ContactSearchProcess::ClearMortarConditions() {
  if (computing_.NumberOfConditions() == 0) return;
  for (Condition* condition : computing_.Conditions()) condition->Set(TO_ERASE, true);
  root_.RemoveConditionsFlagged(TO_ERASE);
}

void ContactSearchProcess::SetInterfaceActive(bool active) {
  for (Node* node : interface_.Nodes()) node->Set(ACTIVE, active && node->Is(ACTIVE));
  for (Condition* condition : interface_.Conditions()) condition->Set(ACTIVE, active);
  for (Condition* condition : computing_.Conditions()) condition->Set(ACTIVE, active);
}

const PairedCondition& ContactSearchProcess::Prototype(const Geometry& slave, const Geometry& master,
                                                       const std::string** interned) {
  // Entities refer to their registered name by pointer: keep one copy per name for the
  // program's lifetime.
  static std::mutex mutex;
  static std::set<std::string> names;
  const std::string name = slot_.condition_name + GeometryToken(slave, master) + slot_.final_string;
  const auto& registry = Registry<Condition>::Instance();
  if (!registry.Has(name)) {
    std::vector<std::string> paired;
    for (const std::string& n : registry.Names())
      if (n.find("Mortar") != std::string::npos) paired.push_back(n);
    throw NotImplementedError(Concat("contact search of ", interface_.FullName(), ": pair condition '", name,
                                     "' is not registered", DidYouMean(name, paired)));
  }
  const auto* prototype = dynamic_cast<const PairedCondition*>(&registry.Get(name));
  if (!prototype) throw Error(Concat("condition '", name, "' is registered but is not a PairedCondition"));
  {
    std::lock_guard<std::mutex> lock(mutex);
    *interned = &*names.insert(name).first;
  }
  return *prototype;
}

void ContactSearchProcess::AssignAutomaticRoles(const std::vector<Condition*>& conditions,
                                                std::vector<std::vector<std::size_t>>& candidates) {
  const std::size_t n = conditions.size();
  // Groups of conditions connected through shared nodes.
  DisjointSets groups(n);
  std::unordered_map<const Node*, std::vector<std::size_t>> faces_at_node;
  for (std::size_t i = 0; i < n; ++i)
    for (const Node* node : conditions[i]->GetGeometry().Nodes()) {
      std::vector<std::size_t>& faces = faces_at_node[node];
      if (!faces.empty()) groups.Join(i, faces.front());
      faces.push_back(i);
    }
  // The role of a group is decided by the first search that finds it a partner in another group,
  // and kept: the group of lowest id with a partner becomes slave and its partners' groups master.
  // Until then a group is slave, provisionally (every face may still meet any other).
  if (decided_role_.size() != n) decided_role_.assign(n, kUndecided);
  std::vector<char> group_role(n, kUndecided);
  for (std::size_t i = 0; i < n; ++i)
    if (decided_role_[i] != kUndecided) group_role[groups.Find(i)] = decided_role_[i];
  // Conditions are in id order, so visiting them visits the groups by their lowest id.
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t g = groups.Find(i);
    if (group_role[g] == kDecidedMaster) continue;
    for (std::size_t m : candidates[i]) {
      const std::size_t gm = groups.Find(m);
      if (gm == g || group_role[gm] == kDecidedSlave) continue;
      group_role[g] = kDecidedSlave;
      if (group_role[gm] == kUndecided) group_role[gm] = kDecidedMaster;
    }
  }
  for (std::size_t i = 0; i < n; ++i) decided_role_[i] = group_role[groups.Find(i)];

  // Within a group (self contact), each pair of facing faces is found from both sides, and all
  // pairs of one contact zone must take the same side as slave: per-face choices (e.g. the lower
  // id of each pair) mix the sides wherever the ids interleave, constraining one gap twice. The
  // faces with a partner in their own group form sheets (joined through shared nodes where their
  // normals agree); the sheets that face each other are coloured slave / master alternately, from
  // the sheet that was slave at earlier searches, or else the one holding the lowest id. A zone
  // can hold several sheets on one side (a face without a partner splits a sheet), which the
  // colouring keeps on the same side.
  std::vector<char> self_paired(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t m : candidates[i])
      if (groups.Find(m) == groups.Find(i)) self_paired[i] = self_paired[m] = 1;
  DisjointSets sheets(n);
  for (const auto& [node, faces] : faces_at_node)
    for (std::size_t a = 0; a < faces.size(); ++a)
      for (std::size_t b = a + 1; b < faces.size(); ++b)
        if (self_paired[faces[a]] && self_paired[faces[b]] &&
            conditions[faces[a]]->GetValue(NORMAL).dot(conditions[faces[b]]->GetValue(NORMAL)) > 0.5)
          sheets.Join(faces[a], faces[b]);
  if (self_side_.size() != n) self_side_.assign(n, kSideUnknown);
  std::vector<std::size_t> lowest(n, n);
  std::vector<long> memory(n, 0);  // per sheet: faces that were slave minus faces that were master
  std::vector<std::vector<std::size_t>> facing(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t sheet = sheets.Find(i);
    lowest[sheet] = std::min(lowest[sheet], i);
    memory[sheet] += self_side_[i] == kSideSlave ? 1 : self_side_[i] == kSideMaster ? -1 : 0;
    // Both ways: a face may find its partner without being found by it (search radii differ).
    for (std::size_t m : candidates[i])
      if (groups.Find(m) == groups.Find(i) && sheets.Find(m) != sheet) {
        facing[sheet].push_back(sheets.Find(m));
        facing[sheets.Find(m)].push_back(sheet);
      }
  }
  // Breadth-first colouring of each zone of facing sheets, from its strongest former slave.
  std::vector<std::size_t> order;
  for (std::size_t sheet = 0; sheet < n; ++sheet)
    if (sheets.Find(sheet) == sheet && !facing[sheet].empty()) order.push_back(sheet);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return memory[a] != memory[b] ? memory[a] > memory[b] : lowest[a] < lowest[b];
  });
  enum Colour : char { kUncoloured, kSlaveSheet, kMasterSheet };
  std::vector<char> colour(n, kUncoloured);
  for (std::size_t start : order) {
    if (colour[start] != kUncoloured) continue;
    colour[start] = kSlaveSheet;
    std::vector<std::size_t> queue{start};
    for (std::size_t q = 0; q < queue.size(); ++q)
      for (std::size_t next : facing[queue[q]])
        if (colour[next] == kUncoloured) {
          colour[next] = colour[queue[q]] == kSlaveSheet ? kMasterSheet : kSlaveSheet;
          queue.push_back(next);
        }
  }
  // The slave side of the pair (i, m) of one group. Where the colouring does not separate them (a
  // surface folded so tightly that a sheet faces itself, or an odd cycle of sheets), the lower id.
  auto slave_side = [&](std::size_t i, std::size_t m) {
    const char ci = colour[sheets.Find(i)], cm = colour[sheets.Find(m)];
    if (ci == cm) return std::min(i, m);
    return ci == kSlaveSheet ? i : m;
  };

  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t g = groups.Find(i);
    std::vector<std::size_t> kept;
    if (group_role[g] != kDecidedMaster)
      for (std::size_t m : candidates[i]) {
        const std::size_t gm = groups.Find(m);
        if ((gm != g && group_role[gm] == kDecidedMaster) || (gm == g && slave_side(i, m) == i)) kept.push_back(m);
      }
    candidates[i] = std::move(kept);
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t m : candidates[i])
      if (groups.Find(m) == groups.Find(i)) {
        self_side_[i] = kSideSlave;
        self_side_[m] = kSideMaster;
      }
  for (std::size_t i = 0; i < n; ++i) {
    const bool slave = group_role[groups.Find(i)] != kDecidedMaster;
    conditions[i]->Set(SLAVE, slave);
    conditions[i]->Set(MASTER, !slave);
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t m : candidates[i]) conditions[m]->Set(MASTER, true);
  }
  for (Node* node : interface_.Nodes()) {
    node->Set(SLAVE, false);
    node->Set(MASTER, false);
  }
  for (Condition* condition : conditions)
    for (Node* node : condition->GetGeometry().Nodes()) {
      if (condition->Is(SLAVE)) node->Set(SLAVE, true);
      if (condition->Is(MASTER)) node->Set(MASTER, true);
    }
}

void ContactSearchProcess::FindBodies() {
  // Union-find over the nodes of each element: the bodies are the connected sets of elements.
  std::unordered_map<const Node*, std::size_t> index;
  for (const Element* element : root_.Elements())
    for (const Node* node : element->GetGeometry().Nodes()) index.emplace(node, index.size());
  DisjointSets bodies(index.size());
  for (const Element* element : root_.Elements()) {
    const Geometry& geometry = element->GetGeometry();
    for (std::size_t k = 1; k < geometry.PointsNumber(); ++k)
      bodies.Join(index.at(&geometry[k]), index.at(&geometry[0]));
  }
  std::unordered_map<std::size_t, std::size_t> numbers;
  body_of_node_.clear();
  for (const auto& [node, i] : index)
    body_of_node_.emplace(node, numbers.emplace(bodies.Find(i), numbers.size()).first->second);
  bodiless_offset_ = body_of_node_.size();
  // Only the faces' first nodes are looked up: kept alone, no pointer outlives a cut of the model
  // across the ranks (the interface is replicated, the rest mostly destroyed).
  std::unordered_map<const Node*, std::size_t> of_faces;
  for (const Condition* condition : interface_.Conditions())
    if (const auto it = body_of_node_.find(&condition->GetGeometry()[0]); it != body_of_node_.end())
      of_faces.emplace(*it);
  body_of_node_ = std::move(of_faces);
  bodies_found_ = true;
}

void ContactSearchProcess::SetBodies(const std::unordered_map<IndexType, std::size_t>& body_of, std::size_t labels) {
  body_of_node_.clear();
  for (const Condition* condition : interface_.Conditions()) {
    const Node& first = condition->GetGeometry()[0];
    if (const auto it = body_of.find(first.Id()); it != body_of.end()) body_of_node_.emplace(&first, it->second);
  }
  bodiless_offset_ = labels;
  bodies_found_ = true;
}

std::size_t ContactSearchProcess::BodyOf(const Condition& condition) {
  if (!bodies_found_) FindBodies();
  // A face whose nodes belong to no element (a contact surface without a body) is a body of its own.
  const auto it = body_of_node_.find(&condition.GetGeometry()[0]);
  return it != body_of_node_.end() ? it->second : bodiless_offset_ + condition.Id();
}

void ContactSearchProcess::FindMeshNeighbours() {
  // On a piece of a cut model the paths leave the piece: NearInMesh refuses instead.
  if (!mesh_neighbours_.empty() || root_.GetNodePartition()) return;
  for (const Element* element : root_.Elements())
    for (const Node* node : element->GetGeometry().Nodes()) {
      auto& around = mesh_neighbours_[node];
      for (const Node* other : element->GetGeometry().Nodes())
        if (other != node) around.push_back(other);
    }
  for (auto& [_, around] : mesh_neighbours_) {
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
  }
}

bool ContactSearchProcess::NearInMesh(const Geometry& from, const Geometry& to, double reach) const {
  // Dijkstra over the element edges (current lengths), stopped at `reach`: the far side of a body
  // lies about its thickness away through it; the other arm of a bent body, or the other side of
  // a self contact, only by the long way round.
  std::unordered_map<const Node*, double> distance;
  using Entry = std::pair<double, const Node*>;
  std::vector<Entry> queue;
  for (const Node* node : from.Nodes()) {
    distance[node] = 0.0;
    queue.emplace_back(0.0, node);
  }
  std::make_heap(queue.begin(), queue.end(), std::greater<>());
  while (!queue.empty()) {
    std::pop_heap(queue.begin(), queue.end(), std::greater<>());
    const auto [d, node] = queue.back();
    queue.pop_back();
    if (d > distance[node]) continue;
    for (const Node* target : to.Nodes())
      if (target == node) return true;
    const auto it = mesh_neighbours_.find(node);
    if (it == mesh_neighbours_.end()) continue;
    for (const Node* other : it->second) {
      const double next = d + (other->Coordinates() - node->Coordinates()).norm();
      if (next > reach) continue;
      const auto known = distance.find(other);
      if (known != distance.end() && known->second <= next) continue;
      distance[other] = next;
      queue.emplace_back(next, other);
      std::push_heap(queue.begin(), queue.end(), std::greater<>());
    }
  }
  return false;
}

ContactSearchStatistics ContactSearchProcess::UpdateMortarConditions() {
  const auto start = std::chrono::steady_clock::now();
  ContactSearchStatistics stats;
  ClearMortarConditions();
  std::optional<PredictedConfiguration> predicted;
  if (settings_["dynamic_search"].GetBool()) predicted.emplace(interface_);
  NormalCalculationUtilities::ComputeNodalNormals(interface_);

  const bool automatic = !slot_.predefined_master_slave;
  std::vector<Condition*> all(interface_.Conditions().begin(), interface_.Conditions().end());
  std::vector<std::size_t> slaves, masters;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (automatic || all[i]->Is(SLAVE)) slaves.push_back(i);
    if (automatic || all[i]->Is(MASTER)) masters.push_back(i);
  }
  stats.slave_conditions = slaves.size();
  stats.master_conditions = masters.size();

  std::vector<std::size_t> bodies(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) bodies[i] = BodyOf(*all[i]);
  // The mesh paths are needed only where a slave face may meet a face of its own body.
  std::set<std::size_t> slave_bodies, master_bodies;
  for (std::size_t i : slaves) slave_bodies.insert(bodies[i]);
  for (std::size_t i : masters) master_bodies.insert(bodies[i]);
  if (std::any_of(slave_bodies.begin(), slave_bodies.end(), [&](std::size_t b) { return master_bodies.count(b); }))
    FindMeshNeighbours();
  std::vector<FaceData> faces(all.size());
  ParallelForEachIndex(all.size(), [&](std::size_t i) { faces[i] = MakeFaceData(all[i], bodies[i]); });

  std::vector<Array3> centers;
  centers.reserve(masters.size());
  double max_master_radius = 0.0;
  for (std::size_t m : masters) {
    centers.push_back(faces[m].center);
    max_master_radius = std::max(max_master_radius, faces[m].radius);
  }
  const ContactSearchTree tree(std::move(centers), settings_["bucket_size"].GetInt());

  const double search_factor = settings_["search_factor"].GetDouble();
  const double threshold = settings_["normal_orientation_threshold"].GetDouble();
  const double box_factor = settings_["octree_search_parameters"]["bounding_box_factor"].GetDouble();
  const bool in_box = type_search_ == "in_box" || type_search_ == "in_box_with_obb";
  const bool with_obb = type_search_ == "in_radius_with_obb" || type_search_ == "in_box_with_obb";
  const bool simple = settings_["simple_search"].GetBool();
  const std::string check = simple ? std::string("no_check") : check_gap_;
  const bool gap_threshold = settings_["consider_gap_threshold"].GetBool();
  const double distance_threshold =
      root_.GetProcessInfo().Has(DISTANCE_THRESHOLD) ? root_.GetProcessInfo().GetValue(DISTANCE_THRESHOLD) : 1e24;
  const auto allocation = static_cast<std::size_t>(std::max(1, settings_["max_number_results"].GetInt()));

  // Master faces around each node, to complete the coverage of the slave faces (below).
  std::unordered_map<const Node*, std::vector<std::size_t>> masters_at_node;
  for (std::size_t m : masters)
    for (const Node* node : all[m]->GetGeometry().Nodes()) masters_at_node[node].push_back(m);

  // candidates[i] for interface condition i (only slaves get any).
  std::vector<std::vector<std::size_t>> candidates(all.size());
  double min_radius = std::numeric_limits<double>::max(), max_radius = 0.0;
  std::size_t truncated = 0;
  // Every rank of a cut model searches the whole (replicated) interface and must decide alike, but
  // a mesh walk may cross nodes its piece lacks: refused after the loop, alike on every rank.
  const bool cut = root_.GetNodePartition() != nullptr;
  bool walk_on_piece = false;
#pragma omp parallel reduction(min : min_radius) reduction(max : max_radius) reduction(+ : truncated) \
    reduction(|| : walk_on_piece)
  {
    std::vector<std::size_t> found;
#pragma omp for schedule(dynamic, 64)
    for (std::size_t k = 0; k < slaves.size(); ++k) {
      const std::size_t s = slaves[k];
      const FaceData& slave = faces[s];
      const Geometry& slave_geometry = slave.condition->GetGeometry();
      const double radius = search_factor * slave.length;
      min_radius = std::min(min_radius, radius);
      max_radius = std::max(max_radius, radius);
      Box slave_box;
      if (in_box) {
        slave_box = BoundingBox(slave_geometry, radius);
        tree.RadiusSearch(slave.center, slave.radius + radius * std::sqrt(3.0) + max_master_radius, found);
      } else {
        tree.RadiusSearch(slave.center, radius + max_master_radius, found);
      }
      OrientedBox slave_obb;
      // Along its normal the slave box reaches as far as the search radius: a face near the edge of
      // a contact zone that is re-searched with the bodies already pressed together must keep the
      // masters it will touch later in the step; the thin lateral padding still rejects far faces.
      if (with_obb) slave_obb = BuildOrientedBox(slave_geometry, slave.normal, box_factor * slave.length, radius);
      // Tests shared by the search and the coverage walk below: the master faces the slave (opposite
      // normals, no common node, not behind it: the far side of the slave's own body has opposite
      // normals too, as on a whole-skin interface), and its projection on the slave's plane overlaps
      // the slave or comes near it (below). Another body's face may lie behind the slave by up to a
      // face's size (an initial penetration); so may a face of the slave's own body that lies far
      // from it along the mesh (self contact, or two given parts of one body, whose step crossed:
      // the bent clamp's arms, 0.0134 across faces of 0.02, were left unpaired and cycled, where
      // Kratos pairs them and converges). A face of its own body reached through the mesh within
      // twice that is the far side of a thin body, kept only up to a tenth of a face behind (a
      // whole-skin interface on a block one element thick paired its bottom face with its top: a
      // singular system).
      auto opposite = [&](const FaceData& master) {
        const Geometry& master_geometry = master.condition->GetGeometry();
        if (!(slave.normal.dot(master.normal) < -threshold) || ShareNode(slave_geometry, master_geometry)) return false;
        const double depth = (slave.center - master.center).dot(slave.normal);  // > 0: behind the slave
        if (master.body != slave.body) return depth <= std::max(slave.length, master.length);
        const double face = std::min(slave.length, master.length);
        if (depth <= 0.1 * face) return true;
        if (!(depth <= face)) return false;
        if (cut) {
          walk_on_piece = true;
          return false;
        }
        return !NearInMesh(slave_geometry, master_geometry, 2.0 * face);
      };
      // How far the master's projection overlaps the slave's (negative: apart by about that much).
      auto overlap = [&](const FaceData& master) {
        return ProjectedOverlap(slave_geometry, slave.normal, master.condition->GetGeometry());
      };
      const double margin = kSlideMargin * slave.length;
      std::vector<std::size_t>& kept = candidates[s];
      bool over_master = false;
      for (std::size_t f : found) {
        const std::size_t m = masters[f];
        if (m == s) continue;
        const FaceData& master = faces[m];
        // In radius: the search ball meets the ball around the master's nodes.
        if (!in_box && (master.center - slave.center).norm() - master.radius > radius) continue;
        const Geometry& master_geometry = master.condition->GetGeometry();
        if (!opposite(master)) continue;
        if (in_box && !Overlap(slave_box, BoundingBox(master_geometry, 0.0))) continue;
        if (with_obb &&
            !Intersect(slave_obb, BuildOrientedBox(master_geometry, master.normal, box_factor * master.length)))
          continue;
        if (check == "mapping_check") {
          const double depth = overlap(master);
          if (depth <= -margin) continue;
          over_master = over_master || depth > 0.0;
        }
        const double tolerance = 1e-6 * std::min(slave.length, master.length);
        if (check == "direct_check" && !(ProjectedOverlap(master_geometry, master.normal, slave_geometry) > tolerance))
          continue;
        if (gap_threshold && std::abs((master.center - slave.center).dot(slave.normal)) > distance_threshold) continue;
        kept.push_back(m);
      }
      // A mapped slave face is paired with the master faces beneath it and with those its
      // projection comes within kSlideMargin of: faces that only touch it (a slave node over a
      // master edge, as aligned meshes have) gain an overlap as soon as it slides, and pairs are not
      // searched again within the step. Kept only when they overlapped, the 1-step cases of the
      // sweep lost up to 4 % of a nodal area and 1e-2 to 4e-2 of the pressures, where the same load
      // in 4 steps gives another answer (Kratos 10.4 does this; ours now agrees with itself to
      // 1e-14). A face that is not over the master yet (beyond its end) is left to the next search:
      // paired for the step, its first overlaps are slivers of the master's end, which cost the
      // overhanging cases of the sweep one or two Newton iterations per step.
      if (check == "mapping_check" && !over_master) kept.clear();
      // A slave face at the edge of the searched zone can reach only some of the master faces
      // beneath it. Partly covered, its dual basis (negative over part of the face) gives its
      // nodes weighted gaps of the wrong sign however open the gap, and the active set then
      // pulls far nodes into contact (hertz2d_100k cycled so). Walk from the kept masters to
      // their neighbours that lie beneath the slave face too, until the face is covered or the
      // master surface ends.
      for (std::size_t q = 0; q < kept.size(); ++q) {
        for (const Node* node : faces[kept[q]].condition->GetGeometry().Nodes()) {
          const auto around = masters_at_node.find(node);  // find: the map is shared by the threads
          for (std::size_t m : around->second) {
            if (m == s || std::find(kept.begin(), kept.end(), m) != kept.end()) continue;
            if (opposite(faces[m]) && overlap(faces[m]) > -margin) kept.push_back(m);
          }
        }
      }
      std::sort(kept.begin(), kept.end());
      if (kept.size() > allocation) {
        kept.resize(allocation);
        ++truncated;
      }
    }
  }
  if (walk_on_piece)
    throw NotImplementedError(Concat("the contact search of ", interface_.FullName(),
                                     ": telling a thin body's far side from a self contact walks the mesh, which a "
                                     "model cut across the ranks (MORTARCONTACT_PARTITIONED_MODEL=1) does not hold; "
                                     "run without MORTARCONTACT_PARTITIONED_MODEL"));
  if (truncated > 0)
    Logger::Warning(Concat("contact search of ", interface_.FullName(), ": ", truncated,
                           " slave conditions had more candidates than max_number_results ", allocation,
                           "; the extra ones were dropped"));
  if (automatic) {
    AssignAutomaticRoles(all, candidates);
    stats.slave_conditions = stats.master_conditions = 0;
    for (const Condition* condition : all) {
      stats.slave_conditions += condition->Is(SLAVE) ? 1 : 0;
      stats.master_conditions += condition->Is(MASTER) ? 1 : 0;
    }
  }

  // Pair conditions, created serially with consecutive ids after the largest in the model.
  std::vector<std::pair<Condition*, Condition*>> pairs;
  for (std::size_t s = 0; s < all.size(); ++s)
    for (std::size_t m : candidates[s]) pairs.emplace_back(all[s], all[m]);
  IndexType next_id = 1;
  if (root_.NumberOfConditions() > 0) next_id = root_.Conditions()[root_.NumberOfConditions() - 1]->Id() + 1;
  const int property_id = slot_.property_id;
  Properties* pair_properties = property_id > 0 ? &root_.GetProperties(property_id) : nullptr;
  // NV pairs: the faces around each slave node, from the part whose nodal NORMAL the mortar
  // updater refreshes ("Contact"), built once per search and shared.
  std::shared_ptr<const NodalNormalSupport> normal_support;
  for (const auto& [slave, master] : pairs) {
    const std::string* name = nullptr;
    const PairedCondition& prototype = Prototype(slave->GetGeometry(), master->GetGeometry(), &name);
    Properties* properties = pair_properties ? pair_properties : slave->pGetProperties();
    std::unique_ptr<PairedCondition> pair = prototype.CreatePaired(next_id++, *slave, *master, properties);
    if (pair->NeedsNodalNormalSupport()) {
      if (!normal_support)
        normal_support = std::make_shared<const NodalNormalSupport>(
            root_.HasSubModelPart("Contact") ? root_.GetSubModelPart("Contact") : interface_);
      pair->SetNodalNormalSupport(normal_support);
    }
    pair->SetRegisteredName(name);
    pair->Set(SLAVE, true);
    computing_.AddCondition(std::unique_ptr<Condition>(std::move(pair)));
  }
  stats.pairs = pairs.size();
  stats.min_search_radius = slaves.empty() ? 0.0 : min_radius;
  stats.max_search_radius = max_radius;

  PredictActiveSet(pairs, stats);
  if (predicted && predicted->Moved()) {
    predicted.reset();
    NormalCalculationUtilities::ComputeNodalNormals(interface_);
  }

  if (pairs.empty() && stats.slave_conditions > 0) {
    Logger::Warning(Concat("contact search of ", interface_.FullName(), ": no master condition found for any of the ",
                           stats.slave_conditions, " slave conditions (search radius = search_factor ", search_factor,
                           " x slave size = ", stats.min_search_radius, " .. ", stats.max_search_radius,
                           ", type_search ", type_search_, ", check_gap ", check,
                           "). If the surfaces should touch, increase search_parameters.search_factor "
                           "(or check assume_master_slave and the distance between the surfaces)"));
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  total_seconds_ += stats.seconds;
  ++searches_;
  return stats;
}

void ContactSearchProcess::PredictActiveSet(const std::vector<std::pair<Condition*, Condition*>>& pairs,
                                            ContactSearchStatistics& stats) {
  std::unordered_map<Node*, std::vector<std::pair<Condition*, Condition*>>> pairs_of;
  for (const auto& pair : pairs)
    for (Node* node : pair.first->GetGeometry().Nodes()) pairs_of[node].push_back(pair);
  // Every search predicts the set again, as Kratos does: a slave node is active when its gap
  // along the nodal normal is below active_check_factor times the mean NODAL_H of the master
  // interface. That one master length, not the slave node's own NODAL_H, is what Kratos 10.4
  // compares with (measured: on hertz2d_30k its predicted set changes between
  // active_check_factor 0.0066 and 0.007 exactly as with h = 6.53e-3..6.64e-3; the mean master
  // NODAL_H is 6.56e-3, the slave nodes' own values are near 3.3e-3). Predicting again at each
  // step puts the nodes that the new load increment closes into the set before the first solve;
  // starting from the previous converged set instead costs one more active-set ring per side,
  // i.e. one more Newton iteration (hertz2d_8k step 2, hertz2d_30k step 4, hertz3d_15k step 3).
  double master_h = 0.0;
  std::size_t masters = 0;
  for (const Node* node : interface_.Nodes())
    if (node->Is(MASTER)) {
      master_h += ContactInterfaceBuilder::GetNodalH(*node);
      ++masters;
    }
  if (masters > 0) master_h /= static_cast<double>(masters);
  const double factor = settings_["active_check_factor"].GetDouble();
  const bool static_check = settings_["static_check_movement"].GetBool();
  for (Node* node : interface_.Nodes()) {
    if (!node->Is(SLAVE)) continue;
    auto it = pairs_of.find(node);
    if (it == pairs_of.end()) {
      node->Set(ISOLATED, true);
      node->Set(ACTIVE, false);
      ++stats.isolated_nodes;
      continue;
    }
    node->Set(ISOLATED, false);
    const Array3 normal = NormalCalculationUtilities::GetNodalNormal(*node);
    const Array3& x = node->Coordinates();
    // The gap along the nodal normal to the master faces of the node's pairs. A node whose ray
    // misses them all (a slave edge over the master's edge, an inclined or slightly larger slave)
    // can still overlap them through its faces; Kratos measures it with the master coordinates
    // mortar-mapped onto the slave, which such a node has. Here it is measured to the plane of
    // the overlapping paired master face whose ray intersection lies nearest to its centre.
    double gap = std::numeric_limits<double>::max();
    double nearest_plane_gap = std::numeric_limits<double>::max();
    double nearest_distance = std::numeric_limits<double>::max();
    for (const auto& [slave, master] : it->second) {
      const Geometry& geometry = master->GetGeometry();
      const Array3 master_normal = master->GetValue(NORMAL);
      const double denominator = normal.dot(master_normal);
      if (std::abs(denominator) < 1e-12) continue;
      const Array3 center = geometry.Center();
      const double t = (center - x).dot(master_normal) / denominator;
      const Array3 hit = x + t * normal;
      Array3 local;
      if (geometry.PointLocalCoordinates(hit, local) && geometry.IsInsideLocal(local, 1e-6)) {
        if (std::abs(t) < std::abs(gap)) gap = t;
      } else if (const double distance = (hit - center).norm();
                 distance < nearest_distance &&
                 ProjectedOverlap(slave->GetGeometry(), slave->GetValue(NORMAL), geometry) > 0.0) {
        nearest_distance = distance;
        nearest_plane_gap = t;
      }
    }
    if (gap == std::numeric_limits<double>::max()) gap = nearest_plane_gap;
    if (gap == std::numeric_limits<double>::max()) {
      // Every paired face parallel to the normal, or none beneath the node's faces yet (paired
      // for the step's sliding only): nothing to press on.
      node->Set(ACTIVE, false);
      continue;
    }
    node->SetValue(NORMAL_GAP, gap);
    double threshold = factor * (masters > 0 ? master_h : ContactInterfaceBuilder::GetNodalH(*node));
    if (static_check) {
      // At rest or opening since the last search: close enough to be pressed again.
      const auto previous = previous_gap_.find(node);
      if (previous != previous_gap_.end() && gap - previous->second > -1e-3 * std::abs(gap))
        threshold = std::max(threshold, kStaticCheckGap);
      previous_gap_[node] = gap;
    }
    // As in Kratos, a node that is active stays so while its weighted gap per unit nodal area (of
    // the last iterate, i.e. the previous step's solution) is below the threshold too: the
    // pressure it carries is not dropped because its nodal gap has opened by a little.
    bool stays_active = false;
    if (node->Is(ACTIVE) && node->HasSolutionStepValue(WEIGHTED_GAP) && node->Has(NODAL_AREA) &&
        node->GetValue(NODAL_AREA) > 0.0)
      stays_active = node->FastGetSolutionStepValue(WEIGHTED_GAP) / node->GetValue(NODAL_AREA) < threshold;
    node->Set(ACTIVE, gap < threshold || stays_active);
  }
  for (Node* node : interface_.Nodes()) stats.active_nodes += (node->Is(SLAVE) && node->Is(ACTIVE)) ? 1 : 0;
}

}  // namespace mc
