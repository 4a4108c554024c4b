// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/model/condition.h"
#include "core/model/element.h"
#include "core/model/entity_container.h"
#include "core/model/master_slave_constraint.h"
#include "core/model/node.h"
#include "core/model/process_info.h"
#include "core/model/properties.h"
#include "core/model/table.h"
#include "core/variables/variables_list.h"

namespace mc {

class Model;
class NodePartition;

/// A named set of nodes, elements, conditions and properties, with nested sub-model-parts.
/// The root model part owns every entity; a sub-model-part refers to a subset, and adding an
/// entity to a sub-model-part adds it to all its ancestors. The ProcessInfo, the historical
/// variables list and the buffer size belong to the root and are shared by the whole tree.
class ModelPart {
 public:
  ModelPart(std::string name, int buffer_size, Model* model = nullptr);
  ModelPart(const ModelPart&) = delete;
  ModelPart& operator=(const ModelPart&) = delete;
  ~ModelPart();

  const std::string& Name() const noexcept { return name_; }
  /// Dotted path from the root: "Structure.Contact.ContactSub0".
  std::string FullName() const;
  bool IsSubModelPart() const noexcept { return parent_ != nullptr; }
  ModelPart& GetParentModelPart() const { return parent_ ? *parent_ : const_cast<ModelPart&>(*this); }
  ModelPart& GetRootModelPart();
  const ModelPart& GetRootModelPart() const;
  Model* GetModel() const noexcept { return model_; }

  // Variables, buffer, process info (root data) -----------------------------------------------
  void AddNodalSolutionStepVariable(const VariableData& var);
  bool HasNodalSolutionStepVariable(const VariableData& var) const;
  const VariablesList& GetNodalSolutionStepVariablesList() const;
  int GetBufferSize() const;
  /// Resizes the history of every node of the tree.
  void SetBufferSize(int buffer_size);
  ProcessInfo& GetProcessInfo();
  const ProcessInfo& GetProcessInfo() const;
  /// Advances TIME (and STEP) and shifts the history of every node.
  void CloneTimeStep(double time);
  /// The owners of the nodes when the model was cut to this rank's piece of a distributed run
  /// (ModelPartPartitioner), made on the whole model before the cut: the builder numbers and
  /// assembles the piece with it. Null when every rank holds the whole model.
  void SetNodePartition(std::shared_ptr<const NodePartition> partition);
  const NodePartition* GetNodePartition() const;

  // Nodes -------------------------------------------------------------------------------------
  /// Creates a node in the root and adds it here and to every ancestor. Ids must be unique in
  /// the model; re-creating an id with the same coordinates returns the existing node.
  Node& CreateNewNode(IndexType id, double x, double y, double z);
  void AddNode(Node* node);
  /// Adds existing nodes of the root by id; throws InputError naming a missing id.
  void AddNodes(const std::vector<IndexType>& ids);
  Node* FindNode(IndexType id) const { return nodes_.Find(id); }
  Node& GetNode(IndexType id) const;
  bool HasNode(IndexType id) const { return nodes_.Contains(id); }
  const EntityContainer<Node>& Nodes() const noexcept { return nodes_; }
  std::size_t NumberOfNodes() const { return nodes_.size(); }
  /// Removes (from the whole tree, and destroys) the nodes flagged `flag`: no element or
  /// condition left may use them.
  void RemoveNodesFlagged(const Flag& flag);

  // Elements and conditions -------------------------------------------------------------------
  /// Creates an element of the registered class `name` on the nodes with the given ids.
  Element& CreateNewElement(const std::string& name, IndexType id, const std::vector<IndexType>& node_ids,
                            Properties* properties);
  Condition& CreateNewCondition(const std::string& name, IndexType id, const std::vector<IndexType>& node_ids,
                                Properties* properties);
  /// Adopts an element built elsewhere (it becomes owned by the root).
  Element& AddElement(std::unique_ptr<Element> element);
  Condition& AddCondition(std::unique_ptr<Condition> condition);
  void AddElement(Element* element);
  void AddCondition(Condition* condition);
  void AddElements(const std::vector<IndexType>& ids);
  void AddConditions(const std::vector<IndexType>& ids);
  Element* FindElement(IndexType id) const { return elements_.Find(id); }
  Condition* FindCondition(IndexType id) const { return conditions_.Find(id); }
  Element& GetElement(IndexType id) const;
  Condition& GetCondition(IndexType id) const;
  const EntityContainer<Element>& Elements() const noexcept { return elements_; }
  const EntityContainer<Condition>& Conditions() const noexcept { return conditions_; }
  std::size_t NumberOfElements() const { return elements_.size(); }
  std::size_t NumberOfConditions() const { return conditions_.size(); }
  /// Removes (from the whole tree, and destroys) the conditions flagged TO_ERASE.
  void RemoveConditionsFlagged(const Flag& flag);
  void RemoveElementsFlagged(const Flag& flag);

  // Master-slave constraints ------------------------------------------------------------------
  /// Adds a constraint here and to every ancestor. Builders eliminate the active ones of the
  /// model part they solve, read at each DoF set-up (Kratos' ModelPart::MasterSlaveConstraints).
  void AddMasterSlaveConstraint(std::shared_ptr<MasterSlaveConstraint> constraint);
  const std::vector<std::shared_ptr<MasterSlaveConstraint>>& MasterSlaveConstraints() const noexcept {
    return constraints_;
  }

  // Properties --------------------------------------------------------------------------------
  /// Returns the properties with this id, creating them in the root if needed, and lists them here.
  Properties& GetOrCreateProperties(IndexType id);
  Properties& GetProperties(IndexType id) const;
  bool HasProperties(IndexType id) const;
  std::vector<Properties*> PropertiesList() const;

  // Tables ------------------------------------------------------------------------------------
  void AddTable(IndexType id, Table table) { tables_[id] = std::move(table); }
  bool HasTable(IndexType id) const { return tables_.count(id) > 0; }
  const Table& GetTable(IndexType id) const;
  const std::map<IndexType, Table>& Tables() const noexcept { return tables_; }

  // Sub-model-parts ---------------------------------------------------------------------------
  ModelPart& CreateSubModelPart(const std::string& name);
  /// Accepts dotted paths relative to this part.
  bool HasSubModelPart(const std::string& name) const;
  ModelPart& GetSubModelPart(const std::string& name) const;
  void RemoveSubModelPart(const std::string& name);
  std::vector<ModelPart*> SubModelParts() const;
  std::vector<std::string> SubModelPartNames() const;

  // Flags -------------------------------------------------------------------------------------
  Flags& GetFlags() noexcept { return flags_; }
  bool Is(const Flag& f) const noexcept { return flags_.Is(f); }
  void Set(const Flag& f, bool value = true) noexcept { flags_.Set(f, value); }

 private:
  ModelPart(std::string name, ModelPart* parent);
  template <class T>
  T* CreateEntity(const std::string& name, IndexType id, const std::vector<IndexType>& node_ids,
                  Properties* properties);
  /// Removes the items flagged `flag` from `items` of every part of the tree and destroys them.
  template <class T>
  void RemoveFlaggedFromTree(EntityContainer<T> ModelPart::*items, std::vector<std::unique_ptr<T>>& owned,
                             const Flag& flag);

  std::string name_;
  ModelPart* parent_ = nullptr;
  Model* model_ = nullptr;

  EntityContainer<Node> nodes_;
  EntityContainer<Element> elements_;
  EntityContainer<Condition> conditions_;
  std::vector<std::shared_ptr<MasterSlaveConstraint>> constraints_;
  std::map<IndexType, Properties*> properties_;
  std::map<IndexType, Table> tables_;
  std::map<std::string, std::unique_ptr<ModelPart>> sub_model_parts_;
  Flags flags_;

  // Root-only storage.
  struct RootData;
  std::unique_ptr<RootData> root_;
};

}  // namespace mc
