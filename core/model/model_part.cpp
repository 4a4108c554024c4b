// SPDX-License-Identifier: BSD-3-Clause
#include "core/model/model_part.h"

#include <algorithm>
#include <mutex>
#include <set>

#include "core/model/registry.h"
#include "core/utilities/error.h"
#include "core/utilities/string_utilities.h"
#include "core/variables/kernel_variables.h"

namespace mc {

struct ModelPart::RootData {
  VariablesList variables;
  int buffer_size = 1;
  ProcessInfo process_info;
  std::vector<std::unique_ptr<Node>> nodes;
  std::vector<std::unique_ptr<Element>> elements;
  std::vector<std::unique_ptr<Condition>> conditions;
  std::map<IndexType, std::unique_ptr<Properties>> properties;
  std::shared_ptr<const NodePartition> node_partition;
};

ModelPart::ModelPart(std::string name, int buffer_size, Model* model)
    : name_(std::move(name)), model_(model), root_(std::make_unique<RootData>()) {
  if (name_.empty() || name_.find('.') != std::string::npos)
    throw InputError(Concat("invalid model part name '", name_, "': it must be non-empty and contain no '.'"));
  root_->buffer_size = std::max(1, buffer_size);
}

ModelPart::ModelPart(std::string name, ModelPart* parent)
    : name_(std::move(name)), parent_(parent), model_(parent->model_) {}

ModelPart::~ModelPart() = default;

std::string ModelPart::FullName() const { return parent_ ? parent_->FullName() + "." + name_ : name_; }

ModelPart& ModelPart::GetRootModelPart() { return parent_ ? parent_->GetRootModelPart() : *this; }
const ModelPart& ModelPart::GetRootModelPart() const { return parent_ ? parent_->GetRootModelPart() : *this; }

void ModelPart::AddNodalSolutionStepVariable(const VariableData& var) {
  ModelPart& root = GetRootModelPart();
  if (root.root_->variables.IsLocked() && !root.root_->variables.Has(var))
    throw Error(Concat("model part ", root.Name(), ": cannot add historical variable ", var.Name(),
                       " once nodes exist; add variables before reading the mesh"));
  root.root_->variables.Add(var);
}

bool ModelPart::HasNodalSolutionStepVariable(const VariableData& var) const {
  return GetRootModelPart().root_->variables.Has(var);
}

const VariablesList& ModelPart::GetNodalSolutionStepVariablesList() const {
  return GetRootModelPart().root_->variables;
}

int ModelPart::GetBufferSize() const { return GetRootModelPart().root_->buffer_size; }

void ModelPart::SetBufferSize(int buffer_size) {
  ModelPart& root = GetRootModelPart();
  root.root_->buffer_size = std::max(1, buffer_size);
  for (auto& node : root.root_->nodes) node->SetBufferSize(root.root_->buffer_size);
}

void ModelPart::SetNodePartition(std::shared_ptr<const NodePartition> partition) {
  GetRootModelPart().root_->node_partition = std::move(partition);
}

const NodePartition* ModelPart::GetNodePartition() const { return GetRootModelPart().root_->node_partition.get(); }

ProcessInfo& ModelPart::GetProcessInfo() { return GetRootModelPart().root_->process_info; }
const ProcessInfo& ModelPart::GetProcessInfo() const { return GetRootModelPart().root_->process_info; }

void ModelPart::CloneTimeStep(double time) {
  ModelPart& root = GetRootModelPart();
  ProcessInfo& info = root.GetProcessInfo();
  if (info.GetValue(STEP) > 0) info.SetValue(PREVIOUS_DELTA_TIME, info.GetValue(DELTA_TIME));
  info.SetValue(DELTA_TIME, time - info.GetValue(TIME));
  info.SetValue(TIME, time);
  info.SetValue(STEP, info.GetValue(STEP) + 1);
  for (auto& node : root.root_->nodes) node->CloneSolutionStep();
}

Node& ModelPart::CreateNewNode(IndexType id, double x, double y, double z) {
  ModelPart& root = GetRootModelPart();
  if (Node* existing = root.nodes_.Find(id)) {
    const Array3 x_new(x, y, z);
    if ((existing->X0() - x_new).norm() > 1e-12 * (1.0 + x_new.norm()))
      throw InputError(Concat("node ", id, " is defined twice with different coordinates"));
    AddNode(existing);
    return *existing;
  }
  root.root_->variables.Lock();
  root.root_->nodes.push_back(
      std::make_unique<Node>(id, Array3(x, y, z), root.root_->variables, root.root_->buffer_size));
  Node* node = root.root_->nodes.back().get();
  AddNode(node);
  return *node;
}

void ModelPart::AddNode(Node* node) {
  for (ModelPart* part = this; part; part = part->parent_) part->nodes_.Add(node);
}

namespace {
// Looks every id up before adding any: adding to a part also adds to the root, which then needs
// sorting again before its next lookup (one lookup per addition made this quadratic).
template <class T, class Find>
std::vector<T*> FindAll(const ModelPart& part, const std::vector<IndexType>& ids, const char* kind, Find find) {
  std::vector<T*> found;
  found.reserve(ids.size());
  for (IndexType id : ids) {
    T* item = find(id);
    if (!item) throw InputError(Concat("model part ", part.FullName(), ": ", kind, " ", id, " does not exist"));
    found.push_back(item);
  }
  return found;
}
}  // namespace

void ModelPart::AddNodes(const std::vector<IndexType>& ids) {
  const ModelPart& root = GetRootModelPart();
  for (Node* node : FindAll<Node>(*this, ids, "node", [&root](IndexType id) { return root.FindNode(id); }))
    AddNode(node);
}

Node& ModelPart::GetNode(IndexType id) const {
  if (Node* node = nodes_.Find(id)) return *node;
  throw InputError(Concat("model part ", FullName(), " has no node ", id));
}

namespace {
// One stable copy of each registered name, so that entities keep a pointer instead of a string.
const std::string* InternName(const std::string& name) {
  static std::mutex mutex;
  static std::set<std::string> names;
  const std::lock_guard<std::mutex> lock(mutex);
  return &*names.insert(name).first;
}
}  // namespace

template <class T>
T* ModelPart::CreateEntity(const std::string& name, IndexType id, const std::vector<IndexType>& node_ids,
                           Properties* properties) {
  const ModelPart& root = GetRootModelPart();
  const T& prototype = Registry<T>::Instance().Get(name);
  Geometry::NodesArray nodes;
  nodes.reserve(node_ids.size());
  for (IndexType nid : node_ids) {
    Node* node = root.FindNode(nid);
    if (!node) throw InputError(Concat(name, " ", id, " refers to node ", nid, ", which does not exist"));
    nodes.push_back(node);
  }
  if (nodes.size() != prototype.GetGeometry().PointsNumber() && prototype.GetGeometry().PointsNumber() != 0)
    throw InputError(
        Concat(name, " ", id, " has ", nodes.size(), " nodes, expected ", prototype.GetGeometry().PointsNumber()));
  T* entity = prototype.Create(id, std::move(nodes), properties).release();
  entity->SetRegisteredName(InternName(name));
  return entity;
}

Element& ModelPart::CreateNewElement(const std::string& name, IndexType id, const std::vector<IndexType>& node_ids,
                                     Properties* properties) {
  if (GetRootModelPart().elements_.Contains(id))
    throw InputError(Concat("element ", id, " (", name, ") is defined twice"));
  return AddElement(std::unique_ptr<Element>(CreateEntity<Element>(name, id, node_ids, properties)));
}

Condition& ModelPart::CreateNewCondition(const std::string& name, IndexType id, const std::vector<IndexType>& node_ids,
                                         Properties* properties) {
  if (GetRootModelPart().conditions_.Contains(id))
    throw InputError(Concat("condition ", id, " (", name, ") is defined twice"));
  return AddCondition(std::unique_ptr<Condition>(CreateEntity<Condition>(name, id, node_ids, properties)));
}

Element& ModelPart::AddElement(std::unique_ptr<Element> element) {
  Element* raw = element.get();
  GetRootModelPart().root_->elements.push_back(std::move(element));
  AddElement(raw);
  return *raw;
}

Condition& ModelPart::AddCondition(std::unique_ptr<Condition> condition) {
  Condition* raw = condition.get();
  GetRootModelPart().root_->conditions.push_back(std::move(condition));
  AddCondition(raw);
  return *raw;
}

void ModelPart::AddElement(Element* element) {
  for (ModelPart* part = this; part; part = part->parent_) part->elements_.Add(element);
}

void ModelPart::AddCondition(Condition* condition) {
  for (ModelPart* part = this; part; part = part->parent_) part->conditions_.Add(condition);
}

void ModelPart::AddMasterSlaveConstraint(std::shared_ptr<MasterSlaveConstraint> constraint) {
  for (ModelPart* part = this; part; part = part->parent_) part->constraints_.push_back(constraint);
}

void ModelPart::AddElements(const std::vector<IndexType>& ids) {
  const ModelPart& root = GetRootModelPart();
  for (Element* e : FindAll<Element>(*this, ids, "element", [&root](IndexType id) { return root.FindElement(id); }))
    AddElement(e);
}

void ModelPart::AddConditions(const std::vector<IndexType>& ids) {
  const ModelPart& root = GetRootModelPart();
  for (Condition* c :
       FindAll<Condition>(*this, ids, "condition", [&root](IndexType id) { return root.FindCondition(id); }))
    AddCondition(c);
}

Element& ModelPart::GetElement(IndexType id) const {
  if (Element* e = elements_.Find(id)) return *e;
  throw InputError(Concat("model part ", FullName(), " has no element ", id));
}

Condition& ModelPart::GetCondition(IndexType id) const {
  if (Condition* c = conditions_.Find(id)) return *c;
  throw InputError(Concat("model part ", FullName(), " has no condition ", id));
}

template <class T>
void ModelPart::RemoveFlaggedFromTree(EntityContainer<T> ModelPart::*items, std::vector<std::unique_ptr<T>>& owned,
                                      const Flag& flag) {
  std::vector<ModelPart*> stack{&GetRootModelPart()};
  while (!stack.empty()) {
    ModelPart* part = stack.back();
    stack.pop_back();
    (part->*items).RemoveIf([&](const T* item) { return item->Is(flag); });
    for (auto& [name, sub] : part->sub_model_parts_) stack.push_back(sub.get());
  }
  owned.erase(std::remove_if(owned.begin(), owned.end(), [&](const auto& item) { return item->Is(flag); }),
              owned.end());
}

void ModelPart::RemoveConditionsFlagged(const Flag& flag) {
  RemoveFlaggedFromTree(&ModelPart::conditions_, GetRootModelPart().root_->conditions, flag);
}

void ModelPart::RemoveNodesFlagged(const Flag& flag) {
  RemoveFlaggedFromTree(&ModelPart::nodes_, GetRootModelPart().root_->nodes, flag);
}

void ModelPart::RemoveElementsFlagged(const Flag& flag) {
  RemoveFlaggedFromTree(&ModelPart::elements_, GetRootModelPart().root_->elements, flag);
}

Properties& ModelPart::GetOrCreateProperties(IndexType id) {
  ModelPart& root = GetRootModelPart();
  auto& owned = root.root_->properties;
  auto it = owned.find(id);
  if (it == owned.end()) it = owned.emplace(id, std::make_unique<Properties>(id)).first;
  for (ModelPart* part = this; part; part = part->parent_) part->properties_[id] = it->second.get();
  return *it->second;
}

Properties& ModelPart::GetProperties(IndexType id) const {
  const auto it = properties_.find(id);
  if (it == properties_.end()) throw InputError(Concat("model part ", FullName(), " has no properties ", id));
  return *it->second;
}

bool ModelPart::HasProperties(IndexType id) const { return properties_.count(id) > 0; }

std::vector<Properties*> ModelPart::PropertiesList() const {
  std::vector<Properties*> list;
  for (const auto& [id, p] : properties_) list.push_back(p);
  return list;
}

const Table& ModelPart::GetTable(IndexType id) const {
  const auto it = tables_.find(id);
  if (it == tables_.end()) throw InputError(Concat("model part ", FullName(), " has no table ", id));
  return it->second;
}

ModelPart& ModelPart::CreateSubModelPart(const std::string& name) {
  const auto dot = name.find('.');
  if (dot != std::string::npos) {
    const std::string head = name.substr(0, dot);
    ModelPart& first = HasSubModelPart(head) ? GetSubModelPart(head) : CreateSubModelPart(head);
    return first.CreateSubModelPart(name.substr(dot + 1));
  }
  if (name.empty()) throw InputError(Concat("model part ", FullName(), ": empty sub model part name"));
  auto it = sub_model_parts_.find(name);
  if (it != sub_model_parts_.end()) return *it->second;
  auto part = std::unique_ptr<ModelPart>(new ModelPart(name, this));
  ModelPart& ref = *part;
  sub_model_parts_.emplace(name, std::move(part));
  return ref;
}

bool ModelPart::HasSubModelPart(const std::string& name) const {
  const auto dot = name.find('.');
  const auto it = sub_model_parts_.find(name.substr(0, dot));
  if (it == sub_model_parts_.end()) return false;
  return dot == std::string::npos ? true : it->second->HasSubModelPart(name.substr(dot + 1));
}

ModelPart& ModelPart::GetSubModelPart(const std::string& name) const {
  const auto dot = name.find('.');
  const std::string head = name.substr(0, dot);
  const auto it = sub_model_parts_.find(head);
  if (it == sub_model_parts_.end())
    throw InputError(Concat("model part ", FullName(), " has no sub model part '", head, "'",
                            DidYouMean(head, SubModelPartNames())));
  return dot == std::string::npos ? *it->second : it->second->GetSubModelPart(name.substr(dot + 1));
}

void ModelPart::RemoveSubModelPart(const std::string& name) { sub_model_parts_.erase(name); }

std::vector<ModelPart*> ModelPart::SubModelParts() const {
  std::vector<ModelPart*> parts;
  for (const auto& [name, part] : sub_model_parts_) parts.push_back(part.get());
  return parts;
}

std::vector<std::string> ModelPart::SubModelPartNames() const {
  std::vector<std::string> names;
  for (const auto& [name, part] : sub_model_parts_) names.push_back(name);
  return names;
}

}  // namespace mc
