// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/contact_interface_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>
#include <unordered_set>

#include "core/geometries/reference_element.h"
#include "core/utilities/error.h"
#include "core/utilities/logger.h"
#include "core/utilities/string_utilities.h"
#include "core/variables/kernel_variables.h"
#include "custom_utilities/contact_search_geometry.h"
#include "custom_utilities/contact_search_tree.h"
#include "custom_utilities/contact_variables.h"
#include "custom_utilities/normal_calculation_utilities.h"
#include "structural/application/register_structural_mechanics.h"

namespace mc {

namespace {

const char* SkinConditionName(GeometryType type) {
  switch (type) {
    case GeometryType::Line2D2: return "LineCondition2D2N";
    case GeometryType::Line2D3: return "LineCondition2D3N";
    case GeometryType::Triangle3D3: return "SurfaceCondition3D3N";
    case GeometryType::Quadrilateral3D4: return "SurfaceCondition3D4N";
    default: return nullptr;
  }
}

bool IsInterfaceGeometry(const Geometry& geometry) {
  return geometry.LocalSpaceDimension() + 1 == geometry.WorkingSpaceDimension();
}

bool IsSolid(const Geometry& geometry) { return geometry.LocalSpaceDimension() == geometry.WorkingSpaceDimension(); }

std::string NodeIds(const Geometry& geometry) {
  std::string ids;
  for (const Node* node : geometry.Nodes()) ids += (ids.empty() ? "" : " ") + std::to_string(node->Id());
  return ids;
}

void CollectParts(ModelPart& part, std::vector<ModelPart*>& out) {
  for (ModelPart* sub : part.SubModelParts()) {
    out.push_back(sub);
    CollectParts(*sub, out);
  }
}

}  // namespace

ModelPart& ContactInterfaceBuilder::ResolvePart(ModelPart& root, const std::string& name) {
  if (name == root.Name() || name == root.Name() + ".computing_domain" || name == "computing_domain") return root;
  const std::string prefix = root.Name() + ".";
  const std::string relative = name.rfind(prefix, 0) == 0 ? name.substr(prefix.size()) : name;
  if (root.HasSubModelPart(relative)) return root.GetSubModelPart(relative);
  std::vector<ModelPart*> parts;
  CollectParts(root, parts);
  std::vector<ModelPart*> matches;
  std::vector<std::string> names;
  for (ModelPart* part : parts) {
    if (part->Name() == relative) matches.push_back(part);
    names.push_back(part->FullName().substr(prefix.size()));
  }
  if (matches.size() == 1) return *matches.front();
  if (matches.size() > 1)
    throw InputError(Concat("contact model part '", name, "' is ambiguous: ", matches[0]->FullName(), " and ",
                            matches[1]->FullName(), "; write the full dotted path"));
  throw InputError(
      Concat("contact model part '", name, "' does not exist in '", root.Name(), "'", DidYouMean(name, names)));
}

Properties& ContactInterfaceBuilder::InterfaceProperties(ModelPart& root, const std::string& slot) {
  ModelPart& sub = root.GetSubModelPart("Contact.ContactSub" + slot);
  const std::vector<Properties*> list = sub.PropertiesList();
  if (list.empty()) throw Error(Concat(sub.FullName(), " has no interface property; call Build first"));
  return *list.front();
}

ModelPart& ContactInterfaceBuilder::Build(const ContactInterfaceSettings& settings) {
  RegisterStructuralMechanics();
  ModelPart& contact =
      root_.HasSubModelPart("Contact") ? root_.GetSubModelPart("Contact") : root_.CreateSubModelPart("Contact");
  const std::string name = "ContactSub" + settings.slot;
  if (contact.HasSubModelPart(name)) {
    if (!root_.Is(MODIFIED)) return contact.GetSubModelPart(name);
    contact.RemoveSubModelPart(name);
  }
  ModelPart& sub = contact.CreateSubModelPart(name);
  ModelPart& computing = root_.HasSubModelPart("ComputingContact") ? root_.GetSubModelPart("ComputingContact")
                                                                   : root_.CreateSubModelPart("ComputingContact");
  if (!computing.HasSubModelPart("ComputingContactSub" + settings.slot))
    computing.CreateSubModelPart("ComputingContactSub" + settings.slot);

  int slot_index = 0;
  try {
    slot_index = std::stoi(settings.slot);
  } catch (const std::exception&) {
    throw InputError(Concat("contact interface slot '", settings.slot, "' must be a number 0..9"));
  }
  const IndexType property_id = settings.property_id > 0 ? static_cast<IndexType>(settings.property_id)
                                                         : static_cast<IndexType>(100 + slot_index);
  const bool new_property = !root_.HasProperties(property_id);
  Properties& properties = sub.GetOrCreateProperties(property_id);

  if (settings.parts.empty()) {
    AddPart(sub, root_, properties);  // the skin of the whole model (spec 4.1)
  } else {
    for (const std::string& part_name : settings.parts) AddPart(sub, ResolvePart(root_, part_name), properties);
  }
  if (sub.NumberOfConditions() == 0)
    throw InputError(Concat("contact interface ", settings.slot, ": no interface condition could be built from ",
                            settings.parts.empty() ? std::string("the model skin") : settings.parts.front(),
                            " (its nodes hold no complete element face)"));

  if (new_property && settings.property_id == 0) {
    const Properties* source = nullptr;
    for (const Condition* condition : sub.Conditions())
      if (condition->pGetProperties() && condition->pGetProperties() != &properties &&
          condition->GetProperties().Size() > 0) {
        source = condition->pGetProperties();
        break;
      }
    if (!source)
      for (const Element* element : FindParentElements(root_, sub))
        if (element && element->pGetProperties() && element->GetProperties().Size() > 0) {
          source = element->pGetProperties();
          break;
        }
    if (source) static_cast<DataValueContainer&>(properties) = static_cast<const DataValueContainer&>(*source);
  }
  if (!properties.Has(FRICTION_COEFFICIENT)) properties.SetValue(FRICTION_COEFFICIENT, settings.friction_coefficient);
  // The frictional conditions and active-set utilities read the coefficient (and the Tresca
  // threshold, when the properties have one) per node.
  const double friction_coefficient = properties.GetValue(FRICTION_COEFFICIENT);
  for (Node* node : sub.Nodes()) node->SetValue(FRICTION_COEFFICIENT, friction_coefficient);
  if (properties.Has(TRESCA_FRICTION_THRESHOLD))
    for (Node* node : sub.Nodes())
      node->SetValue(TRESCA_FRICTION_THRESHOLD, properties.GetValue(TRESCA_FRICTION_THRESHOLD));

  // Roles (spec 4.1: the listed parts are the slave side).
  std::unordered_set<const Node*> slave_nodes;
  for (const std::string& part_name : settings.slave_parts) {
    const ModelPart& slave_part = ResolvePart(root_, part_name);
    for (const Node* node : slave_part.Nodes()) slave_nodes.insert(node);
    for (const Condition* condition : slave_part.Conditions())
      for (const Node* node : condition->GetGeometry().Nodes()) slave_nodes.insert(node);
  }
  const bool automatic = settings.slave_parts.empty();
  for (Node* node : sub.Nodes()) {
    node->Set(INTERFACE, true);
    const bool slave = automatic || slave_nodes.count(node) > 0;
    node->Set(SLAVE, slave);
    node->Set(MASTER, automatic || !slave);
  }
  for (Condition* condition : sub.Conditions()) {
    condition->Set(INTERFACE, true);
    bool slave = true;
    for (const Node* node : condition->GetGeometry().Nodes()) slave = slave && node->Is(SLAVE);
    condition->Set(SLAVE, automatic || slave);
    condition->Set(MASTER, automatic || !slave);
  }
  if (!automatic) {
    bool any_slave = false;
    for (const Condition* condition : sub.Conditions()) any_slave = any_slave || condition->Is(SLAVE);
    if (!any_slave)
      throw InputError(Concat("contact interface ", settings.slot, ": no interface condition lies entirely in the ",
                              "slave parts (assume_master_slave ", settings.slave_parts.front(),
                              "); list the part holding the slave surface"));
  }

  ComputeNodalH(root_, sub);
  NormalCalculationUtilities::ComputeNodalNormals(sub);
  CheckNormals(sub, settings);
  return sub;
}

void ContactInterfaceBuilder::AddPart(ModelPart& sub, ModelPart& part, Properties& properties) {
  for (Node* node : part.Nodes()) sub.AddNode(node);
  bool has_interface_conditions = false;
  for (Condition* condition : part.Conditions()) {
    if (!IsInterfaceGeometry(condition->GetGeometry())) continue;
    sub.AddCondition(condition);
    for (Node* node : condition->GetGeometry().Nodes()) sub.AddNode(node);
    has_interface_conditions = true;
  }
  if (has_interface_conditions) return;

  // Faces of the root's solid elements whose nodes all belong to the part; faces met twice
  // are inner faces and are skipped.
  std::unordered_set<const Node*> in_part(part.Nodes().begin(), part.Nodes().end());
  struct FaceCandidate {
    const Element* element;
    std::size_t face;
  };
  std::vector<FaceCandidate> found;
  std::map<std::vector<IndexType>, int> count;
  for (const Element* element : root_.Elements()) {
    const Geometry& geometry = element->GetGeometry();
    if (!IsSolid(geometry)) continue;
    const auto& faces = geometry.Reference().Faces();
    for (std::size_t f = 0; f < faces.size(); ++f) {
      bool inside = true;
      for (int local : faces[f].nodes) inside = inside && in_part.count(geometry.pGetNode(local)) > 0;
      if (!inside) continue;
      std::vector<IndexType> key;
      for (int local : faces[f].nodes) key.push_back(geometry[local].Id());
      std::sort(key.begin(), key.end());
      ++count[key];
      found.push_back({element, f});
    }
  }
  IndexType next_id = 1;
  if (root_.NumberOfConditions() > 0) next_id = root_.Conditions()[root_.NumberOfConditions() - 1]->Id() + 1;
  for (const FaceCandidate& candidate : found) {
    const Geometry& geometry = candidate.element->GetGeometry();
    const ReferenceElement::Face& face = geometry.Reference().Faces()[candidate.face];
    std::vector<IndexType> ids, key;
    for (int local : face.nodes) ids.push_back(geometry[local].Id());
    key = ids;
    std::sort(key.begin(), key.end());
    if (count[key] != 1) continue;
    const char* name = SkinConditionName(face.type);
    if (!name)
      throw NotImplementedError(Concat("contact interface of ", part.FullName(), ": faces of type ",
                                       GeometryTypeName(face.type), " (element ", candidate.element->Id(),
                                       ") are not supported as contact surfaces yet"));
    sub.CreateNewCondition(name, next_id++, ids, &properties);
  }
}

void ContactInterfaceBuilder::ComputeNodalH(ModelPart& root, ModelPart& part) {
  std::unordered_map<Node*, double> h;
  h.reserve(part.NumberOfNodes());
  for (Node* node : part.Nodes()) h.emplace(node, std::numeric_limits<double>::max());
  for (const Element* element : root.Elements()) {
    const Geometry& geometry = element->GetGeometry();
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i) {
      auto it = h.find(geometry.pGetNode(i));
      if (it == h.end()) continue;
      for (std::size_t j = 0; j < geometry.PointsNumber(); ++j)
        if (j != i) it->second = std::min(it->second, (geometry[i].Coordinates() - geometry[j].Coordinates()).norm());
    }
  }
  // Interfaces without elements (surfaces given alone): the shortest edge of the part's faces.
  std::unordered_map<Node*, double> from_faces;
  for (const Condition* condition : part.Conditions()) {
    const Geometry& geometry = condition->GetGeometry();
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i) {
      auto it = h.find(geometry.pGetNode(i));
      if (it == h.end() || it->second != std::numeric_limits<double>::max()) continue;
      auto [face_it, inserted] = from_faces.try_emplace(it->first, std::numeric_limits<double>::max());
      for (std::size_t j = 0; j < geometry.PointsNumber(); ++j)
        if (j != i)
          face_it->second = std::min(face_it->second, (geometry[i].Coordinates() - geometry[j].Coordinates()).norm());
    }
  }
  for (auto& [node, value] : h) {
    if (auto it = from_faces.find(node); it != from_faces.end()) value = it->second;
    if (value == std::numeric_limits<double>::max())
      throw InputError(Concat("interface node ", node->Id(), " of ", part.FullName(),
                              " belongs to no element and no interface face: its nodal length NODAL_H is undefined"));
    if (node->HasSolutionStepValue(NODAL_H))
      node->FastGetSolutionStepValue(NODAL_H) = value;
    else
      node->SetValue(NODAL_H, value);
  }
}

double ContactInterfaceBuilder::GetNodalH(const Node& node) {
  return node.HasSolutionStepValue(NODAL_H) ? node.FastGetSolutionStepValue(NODAL_H) : node.GetValue(NODAL_H);
}

std::vector<Element*> ContactInterfaceBuilder::FindParentElements(ModelPart& root, ModelPart& part) {
  std::unordered_map<const Node*, std::vector<Element*>> elements_of;
  for (const Node* node : part.Nodes()) elements_of[node];
  for (Element* element : root.Elements()) {
    if (!IsSolid(element->GetGeometry())) continue;
    for (const Node* node : element->GetGeometry().Nodes()) {
      auto it = elements_of.find(node);
      if (it != elements_of.end()) it->second.push_back(element);
    }
  }
  std::vector<Element*> parents;
  parents.reserve(part.NumberOfConditions());
  for (const Condition* condition : part.Conditions()) {
    const Geometry& face = condition->GetGeometry();
    Element* parent = nullptr;
    auto it = elements_of.find(face.pGetNode(0));
    if (it != elements_of.end())
      for (Element* element : it->second) {
        bool all = true;
        for (const Node* node : face.Nodes()) {
          const auto& nodes = element->GetGeometry().Nodes();
          all = all && std::find(nodes.begin(), nodes.end(), node) != nodes.end();
        }
        if (all) {
          parent = element;
          break;
        }
      }
    parents.push_back(parent);
  }
  return parents;
}

void ContactInterfaceBuilder::CheckNormals(ModelPart& sub, const ContactInterfaceSettings& settings) {
  // (1) Each condition's normal must leave its parent element: a point a small step inside
  // along -n lies in the element, a step along +n does not. As Kratos' normal check does, a
  // condition written the other way round is flipped (its node order reversed), with a warning
  // naming it; normal_check_proportion 0 turns the check off (Kratos' zero-length probe sees
  // nothing either). Only linear faces can be flipped; another inverted face is an InputError.
  if (settings.normal_check_proportion > 0.0) {
    const std::vector<Element*> parents = FindParentElements(root_, sub);
    std::string flipped;
    std::size_t flipped_count = 0;
    std::size_t i = 0;
    for (Condition* condition : sub.Conditions()) {
      const Element* parent = parents[i++];
      if (!parent) continue;
      Geometry& face = condition->GetGeometry();
      const Array3 n = condition->GetValue(NORMAL);
      const double step = settings.normal_check_proportion * InterfaceCharacteristicLength(face);
      const Array3 center = face.Center();
      Array3 local;
      const Geometry& body = parent->GetGeometry();
      const bool inner =
          body.PointLocalCoordinates(Array3(center - step * n), local) && body.IsInsideLocal(local, 1e-9);
      const bool outer =
          body.PointLocalCoordinates(Array3(center + step * n), local) && body.IsInsideLocal(local, 1e-9);
      if (inner || !outer) continue;
      const std::string description =
          Concat("condition ", condition->Id(), " (nodes ", NodeIds(face), ") points into element ", parent->Id());
      auto& nodes = face.Nodes();
      if (face.Type() == GeometryType::Line2D2)
        std::swap(nodes[0], nodes[1]);
      else if (face.Type() == GeometryType::Triangle3D3 || face.Type() == GeometryType::Quadrilateral3D4)
        std::reverse(nodes.begin() + 1, nodes.end());
      else
        throw InputError(Concat("contact interface ", sub.FullName(), ": ", description,
                                "; its node order must make the normal leave the body"));
      if (++flipped_count <= 10) flipped += Concat("\n  ", description, "; now nodes ", NodeIds(face));
    }
    if (flipped_count > 0) {
      NormalCalculationUtilities::ComputeNodalNormals(sub);
      Logger::Warning(Concat("contact interface ", sub.FullName(), ": ", flipped_count,
                             " interface conditions had inverted normals and were flipped (node order reversed, as "
                             "Kratos does; normal_check_proportion 0 turns the check off):",
                             flipped, flipped_count > 10 ? "\n  ..." : ""));
    }
  }

  // (2) Slave and master sides must face each other: compare every slave condition with the
  // nearest master condition.
  if (settings.slave_parts.empty()) return;
  std::vector<const Condition*> slaves, masters;
  std::vector<Array3> centers;
  for (const Condition* condition : sub.Conditions()) {
    if (condition->Is(SLAVE)) slaves.push_back(condition);
    if (condition->Is(MASTER)) {
      masters.push_back(condition);
      centers.push_back(condition->GetGeometry().Center());
    }
  }
  if (masters.empty())
    throw InputError(Concat("contact interface ", sub.FullName(), ": every interface condition is on the slave side (",
                            settings.slave_parts.front(), "); contact_model_part must also hold the master surface"));
  const ContactSearchTree tree(std::move(centers), 4);
  std::size_t facing = 0, same_way = 0;
  std::string examples;
  for (const Condition* slave : slaves) {
    double distance = 0.0;
    const Condition* master = masters[tree.Nearest(slave->GetGeometry().Center(), distance)];
    const double dot = slave->GetValue(NORMAL).dot(master->GetValue(NORMAL));
    if (dot < 0.0) {
      ++facing;
    } else if (dot > 0.5) {
      if (++same_way <= 3)
        examples += Concat("\n  slave condition ", slave->Id(), " (nodes ", NodeIds(slave->GetGeometry()),
                           ") and master condition ", master->Id(), " (nodes ", NodeIds(master->GetGeometry()),
                           ") have normals with dot product ", dot);
    }
  }
  if (same_way > facing)
    throw InputError(Concat("contact interface ", sub.FullName(), ": the slave side (", settings.slave_parts.front(),
                            ") and the master side have normals pointing the same way in ", same_way, " of ",
                            slaves.size(),
                            " slave conditions; the surfaces must face each other (check the node "
                            "order of the interface conditions, or which parts are listed in contact_model_part):",
                            examples));
}

}  // namespace mc
