// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/numpy.h>

#include <map>
#include <numeric>
#include <optional>
#include <set>

#include "core/model/constitutive_law.h"
#include "core/model/model.h"
#include "core/model/registry.h"
#include "core/variables/variable_registry.h"
#include "custom_python/python_module.h"

namespace mc::python {

namespace {

py::object GetHistorical(const Node& node, const VariableData& var, int step) {
  if (var.Type() == ValueType::Double)
    return py::cast(node.GetSolutionStepValue(static_cast<const Variable<double>&>(var), step));
  if (var.Type() == ValueType::Array3)
    return py::cast(Array3(node.GetSolutionStepValue(static_cast<const Variable<Array3>&>(var), step)));
  throw InputError(Concat(var.Name(), " cannot be historical"));
}

void SetHistorical(Node& node, const VariableData& var, const py::handle& value, int step) {
  if (var.Type() == ValueType::Double) {
    node.GetSolutionStepValue(static_cast<const Variable<double>&>(var), step) = value.cast<double>();
  } else if (var.Type() == ValueType::Array3) {
    node.GetSolutionStepValue(static_cast<const Variable<Array3>&>(var), step) =
        std::get<Array3>(FromPython(var, value));
  } else {
    throw InputError(Concat(var.Name(), " cannot be historical"));
  }
}

const Variable<double>& AsDouble(const VariableData& var) {
  if (var.Type() != ValueType::Double) throw InputError(Concat(var.Name(), " is not a scalar (double) variable"));
  return static_cast<const Variable<double>&>(var);
}

/// Historical values of all nodes of a part as an (n,) or (n, 3) array, in node-id order.
py::array_t<double> NodalValues(const ModelPart& part, const VariableData& var, int step) {
  const auto& nodes = part.Nodes();
  const std::size_t n = nodes.size();
  if (n > 0 && !nodes[0]->HasSolutionStepValue(var))
    throw InputError(Concat(var.Name(), " is not a historical variable of ", part.FullName()));
  const VariablesList& list = part.GetNodalSolutionStepVariablesList();
  const int offset = list.Offset(var);
  const std::size_t width = var.Type() == ValueType::Array3 ? 3 : 1;
  py::array_t<double> out(width == 3 ? std::vector<py::ssize_t>{py::ssize_t(n), 3}
                                     : std::vector<py::ssize_t>{py::ssize_t(n)});
  double* dst = out.mutable_data();
  for (std::size_t i = 0; i < n; ++i) {
    const double* src = nodes[i]->StepData(step) + offset;
    for (std::size_t k = 0; k < width; ++k) dst[i * width + k] = src[k];
  }
  return out;
}

void SetNodalValues(ModelPart& part, const VariableData& var,
                    py::array_t<double, py::array::c_style | py::array::forcecast> values, int step) {
  const auto& nodes = part.Nodes();
  const std::size_t width = var.Type() == ValueType::Array3 ? 3 : 1;
  if (static_cast<std::size_t>(values.size()) != nodes.size() * width)
    throw InputError(Concat("expected ", nodes.size() * width, " values for ", var.Name(), " on ", part.FullName(),
                            ", got ", values.size()));
  const int offset = part.GetNodalSolutionStepVariablesList().Offset(var);
  if (offset < 0) throw InputError(Concat(var.Name(), " is not a historical variable of ", part.FullName()));
  const double* src = values.data();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    double* dst = nodes[i]->StepData(step) + offset;
    for (std::size_t k = 0; k < width; ++k) dst[k] = src[i * width + k];
  }
}

/// Non-historical nodal values as (n,) or (n, 3), node-id order.
py::array_t<double> NodalNonHistoricalValues(const ModelPart& part, const VariableData& var) {
  const auto& nodes = part.Nodes();
  const std::size_t n = nodes.size();
  if (var.Type() == ValueType::Array3) {
    py::array_t<double> out({py::ssize_t(n), py::ssize_t(3)});
    auto* d = out.mutable_data();
    const auto& v3 = static_cast<const Variable<Array3>&>(var);
    for (std::size_t i = 0; i < n; ++i) {
      const Array3 value = nodes[i]->GetValue(v3);
      for (int k = 0; k < 3; ++k) d[3 * i + k] = value[k];
    }
    return out;
  }
  py::array_t<double> out{py::ssize_t(n)};
  auto* d = out.mutable_data();
  for (std::size_t i = 0; i < n; ++i) {
    switch (var.Type()) {
      case ValueType::Double: d[i] = nodes[i]->GetValue(static_cast<const Variable<double>&>(var)); break;
      case ValueType::Int: d[i] = nodes[i]->GetValue(static_cast<const Variable<int>&>(var)); break;
      case ValueType::Bool: d[i] = nodes[i]->GetValue(static_cast<const Variable<bool>&>(var)); break;
      default: throw InputError(Concat(var.Name(), " (", ValueTypeName(var.Type()), ") cannot be written per node"));
    }
  }
  return out;
}

/// Sets non-historical nodal values from (n,) or (n, 3) in node-id order; with `held`, the nodes
/// marked false lose their value of the variable instead (as a checkpoint records them).
void SetNodalNonHistoricalValues(
    ModelPart& part, const VariableData& var, py::array_t<double, py::array::c_style | py::array::forcecast> values,
    const std::optional<py::array_t<bool, py::array::c_style | py::array::forcecast>>& held) {
  const auto& nodes = part.Nodes();
  const std::size_t n = nodes.size();
  const std::size_t width = var.Type() == ValueType::Array3 ? 3 : 1;
  if (static_cast<std::size_t>(values.size()) != n * width)
    throw InputError(
        Concat("expected ", n * width, " values for ", var.Name(), " on ", part.FullName(), ", got ", values.size()));
  if (held && static_cast<std::size_t>(held->size()) != n)
    throw InputError(
        Concat("expected ", n, " entries of 'held' for ", var.Name(), " on ", part.FullName(), ", got ", held->size()));
  const double* v = values.data();
  const bool* mask = held ? held->data() : nullptr;
  for (std::size_t i = 0; i < n; ++i) {
    DataValueContainer& data = nodes[i]->Data();
    if (mask && !mask[i]) {
      data.Erase(var.IsComponent() ? *var.Source() : var);
      continue;
    }
    switch (var.Type()) {
      case ValueType::Double: data.SetValue(static_cast<const Variable<double>&>(var), v[i]); break;
      case ValueType::Int: data.SetValue(static_cast<const Variable<int>&>(var), static_cast<int>(v[i])); break;
      case ValueType::Bool: data.SetValue(static_cast<const Variable<bool>&>(var), v[i] != 0.0); break;
      case ValueType::Array3:
        data.SetValue(static_cast<const Variable<Array3>&>(var), Array3(v[3 * i], v[3 * i + 1], v[3 * i + 2]));
        break;
      default: throw InputError(Concat(var.Name(), " (", ValueTypeName(var.Type()), ") cannot be set per node here"));
    }
  }
}

/// -1 flag undefined, 0 reset, 1 set: the three states of a flag, per node in node-id order.
py::array_t<std::int8_t> NodalFlagStates(const ModelPart& part, const Flag& flag) {
  py::array_t<std::int8_t> out(py::ssize_t(part.NumberOfNodes()));
  auto* d = out.mutable_data();
  std::size_t i = 0;
  for (const Node* n : part.Nodes())
    d[i++] = n->GetFlags().IsDefined(flag) ? static_cast<std::int8_t>(n->Is(flag)) : std::int8_t(-1);
  return out;
}

void SetNodalFlagStates(ModelPart& part, const Flag& flag,
                        py::array_t<std::int8_t, py::array::c_style | py::array::forcecast> states) {
  const auto& nodes = part.Nodes();
  if (static_cast<std::size_t>(states.size()) != nodes.size())
    throw InputError(Concat("expected ", nodes.size(), " states of ", flag.Name(), " on ", part.FullName(), ", got ",
                            states.size()));
  const std::int8_t* s = states.data();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (s[i] < 0)
      nodes[i]->GetFlags().Reset(flag);
    else
      nodes[i]->Set(flag, s[i] > 0);
  }
}

/// -1 no DoF of the variable, 0 free, 1 fixed; per node in node-id order.
py::array_t<std::int8_t> NodalFixity(const ModelPart& part, const VariableData& var) {
  const auto& dof_variable = AsDouble(var);
  py::array_t<std::int8_t> out(py::ssize_t(part.NumberOfNodes()));
  auto* d = out.mutable_data();
  std::size_t i = 0;
  for (const Node* n : part.Nodes()) {
    const Dof* dof = n->FindDof(dof_variable);
    d[i++] = dof ? static_cast<std::int8_t>(dof->fixed) : std::int8_t(-1);
  }
  return out;
}

void SetNodalFixity(ModelPart& part, const VariableData& var,
                    py::array_t<bool, py::array::c_style | py::array::forcecast> fixed) {
  const auto& dof_variable = AsDouble(var);
  const auto& nodes = part.Nodes();
  if (static_cast<std::size_t>(fixed.size()) != nodes.size())
    throw InputError(Concat("expected ", nodes.size(), " fixities of ", var.Name(), " on ", part.FullName(), ", got ",
                            fixed.size()));
  const bool* f = fixed.data();
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (Dof* dof = nodes[i]->FindDof(dof_variable)) dof->fixed = f[i];
}

/// Elements or conditions grouped by geometry name: {name: (ids (m,), node ids (m, k))}.
template <class Container>
py::dict Connectivity(const Container& entities) {
  std::map<std::string, std::pair<std::vector<std::int64_t>, std::vector<std::int64_t>>> groups;
  std::map<std::string, std::size_t> widths;
  for (const auto* e : entities) {
    const Geometry& g = e->GetGeometry();
    auto& [ids, nodes] = groups[g.Name()];
    widths[g.Name()] = g.PointsNumber();
    ids.push_back(static_cast<std::int64_t>(e->Id()));
    for (const Node* node : g.Nodes()) nodes.push_back(static_cast<std::int64_t>(node->Id()));
  }
  py::dict out;
  for (auto& [name, group] : groups) {
    const py::ssize_t m = py::ssize_t(group.first.size());
    const py::ssize_t k = py::ssize_t(widths[name]);
    py::array_t<std::int64_t> ids(m, group.first.data());
    py::array_t<std::int64_t> conn({m, k}, group.second.data());
    out[py::str(name)] = py::make_tuple(ids, conn);
  }
  return out;
}

/// Mean over the integration points of each listed entity: (m,) for doubles, (m, 3) for Array3,
/// (m, w) for vectors (zero-padded to the widest) and (m, 9) for matrices (row-major, padded to 3x3).
template <class T>
py::array_t<double> IntegrationPointMeans(const ModelPart& part, const VariableData& var,
                                          const std::vector<IndexType>& ids, bool conditions) {
  const ProcessInfo& info = part.GetProcessInfo();
  std::vector<Vector> means(ids.size());
  Eigen::Index width = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    Entity& e =
        conditions ? static_cast<Entity&>(part.GetCondition(ids[i])) : static_cast<Entity&>(part.GetElement(ids[i]));
    std::vector<T> values;
    e.CalculateOnIntegrationPoints(static_cast<const Variable<T>&>(var), values, info);
    Vector mean;
    for (const T& v : values) {
      Vector flat;
      if constexpr (std::is_same_v<T, double>) {
        flat = Vector::Constant(1, v);
      } else if constexpr (std::is_same_v<T, Matrix>) {
        Matrix padded = Matrix::Zero(3, 3);
        padded.topLeftCorner(std::min<Eigen::Index>(3, v.rows()), std::min<Eigen::Index>(3, v.cols())) =
            v.topLeftCorner(std::min<Eigen::Index>(3, v.rows()), std::min<Eigen::Index>(3, v.cols()));
        flat = Eigen::Map<const Eigen::Matrix<double, 9, 1>>(Matrix(padded.transpose()).data());
      } else {
        flat = v;
      }
      if (mean.size() < flat.size()) mean.conservativeResizeLike(Vector::Zero(flat.size()));
      mean.head(flat.size()) += flat / static_cast<double>(values.size());
    }
    width = std::max(width, mean.size());
    means[i] = std::move(mean);
  }
  if constexpr (std::is_same_v<T, Array3>) width = 3;
  if constexpr (std::is_same_v<T, Matrix>) width = 9;
  const bool scalar = std::is_same_v<T, double>;
  py::array_t<double> out(scalar ? std::vector<py::ssize_t>{py::ssize_t(ids.size())}
                                 : std::vector<py::ssize_t>{py::ssize_t(ids.size()), py::ssize_t(width)});
  auto* d = out.mutable_data();
  const Eigen::Index stride = scalar ? 1 : width;
  std::fill(d, d + ids.size() * stride, 0.0);
  for (std::size_t i = 0; i < ids.size(); ++i)
    for (Eigen::Index k = 0; k < means[i].size() && k < stride; ++k) d[i * stride + k] = means[i][k];
  return out;
}

DataValueContainer& ValuesOf(DataValueContainer& values) { return values; }
DataValueContainer& ValuesOf(Node& node) { return node.Data(); }
DataValueContainer& ValuesOf(Entity& entity) { return entity.Data(); }

/// GetValue, SetValue and Has of the non-historical values (a component reads its source).
template <class Class>
Class& BindValues(Class& cls) {
  using Owner = typename Class::type;
  return cls
      .def(
          "GetValue", [](Owner& o, const VariableData& v) { return GetGeneric(ValuesOf(o), v); }, py::arg("variable"),
          "The non-historical value of a variable (its zero when not set).")
      .def(
          "SetValue",
          [](Owner& o, const VariableData& v, const py::object& value) {
            ValuesOf(o).SetGeneric(v, FromPython(v, value));
          },
          py::arg("variable"), py::arg("value"), "Sets the non-historical value of a variable.")
      .def(
          "Has",
          [](Owner& o, const VariableData& v) {
            const auto& items = ValuesOf(o).Items();
            return std::any_of(items.begin(), items.end(),
                               [&](const auto& item) { return item.first == (v.IsComponent() ? v.Source() : &v); });
          },
          py::arg("variable"), "Whether a non-historical value of the variable is set.")
      .def(
          "ValueNames",
          [](Owner& o) {
            std::vector<std::string> names;
            for (const auto& item : ValuesOf(o).Items()) names.push_back(item.first->Name());
            return names;
          },
          "Names of the variables that have a non-historical value here, in insertion order.");
}

/// Is and Set of the flags of a node, entity, model part or process info.
template <class Class>
Class& BindFlags(Class& cls) {
  using Owner = typename Class::type;
  return cls
      .def(
          "Is", [](const Owner& o, const Flag& flag) { return o.Is(flag); }, py::arg("flag"),
          "Whether the flag is set.")
      .def(
          "Set", [](Owner& o, const Flag& flag, bool value) { o.Set(flag, value); }, py::arg("flag"),
          py::arg("value") = true, "Sets the flag to value.");
}

using IntArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

/// Ids from an integer array of any shape (row-major), checked positive.
std::vector<IndexType> PositiveIds(const IntArray& values, const char* what) {
  std::vector<IndexType> ids(static_cast<std::size_t>(values.size()));
  const std::int64_t* v = values.data();
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (v[i] < 1) throw InputError(Concat(what, " must be positive integers, found ", v[i]));
    ids[i] = static_cast<IndexType>(v[i]);
  }
  return ids;
}

/// Indices of `ids` in increasing id order, after checking that none is given twice or exists
/// already (`exists`): a bulk creation fails before creating anything. Creating in increasing id
/// order keeps the part's sorted containers sorted, so each lookup stays logarithmic.
template <class Exists>
std::vector<std::size_t> NewIdOrder(const std::vector<IndexType>& ids, const char* kind, const ModelPart& part,
                                    Exists exists) {
  std::vector<std::size_t> order(ids.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&ids](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i > 0 && ids[order[i]] == ids[order[i - 1]])
      throw InputError(Concat(part.FullName(), ": ", kind, " ", ids[order[i]], " is given twice"));
    if (exists(ids[order[i]]))
      throw InputError(Concat(part.FullName(), ": ", kind, " ", ids[order[i]], " exists already"));
  }
  return order;
}

void CreateNodes(ModelPart& part, const IntArray& ids,
                 const py::array_t<double, py::array::c_style | py::array::forcecast>& xyz) {
  if (ids.ndim() != 1) throw InputError(Concat("node ids: expected a 1-D array, got ", ids.ndim(), " dimensions"));
  const py::ssize_t n = ids.shape(0);
  if (xyz.ndim() != 2 || xyz.shape(0) != n || xyz.shape(1) < 1 || xyz.shape(1) > 3)
    throw InputError(Concat("coordinates: expected an array (", n, ", 3) or (", n, ", 2), one row per node"));
  const std::vector<IndexType> node_ids = PositiveIds(ids, "node ids");
  const ModelPart& root = part.GetRootModelPart();
  const auto order = NewIdOrder(node_ids, "node", part, [&root](IndexType id) { return root.HasNode(id); });
  const py::ssize_t width = xyz.shape(1);
  const double* c = xyz.data();
  for (const std::size_t i : order) {
    double x[3] = {0.0, 0.0, 0.0};
    for (py::ssize_t k = 0; k < width; ++k) x[k] = c[static_cast<py::ssize_t>(i) * width + k];
    part.CreateNewNode(node_ids[i], x[0], x[1], x[2]);
  }
}

/// The properties of this id listed by the part; InputError naming the ids it has otherwise.
Properties& ListedProperties(ModelPart& part, IndexType id) {
  if (part.HasProperties(id)) return part.GetProperties(id);
  std::string listed;
  for (const Properties* p : part.PropertiesList()) listed += Concat(listed.empty() ? "" : ", ", p->Id());
  throw InputError(Concat("model part ", part.FullName(), " has no properties ", id, " (",
                          listed.empty() ? std::string("it has none") : "it has " + listed,
                          "); create them with CreateNewProperties(", id, ")"));
}

/// The properties a bulk creation names: a Properties object, or the id of properties this part lists.
Properties& PropertiesOf(ModelPart& part, const py::handle& properties) {
  if (py::isinstance<Properties>(properties)) return properties.cast<Properties&>();
  if (py::isinstance<py::int_>(properties)) {
    const auto id = properties.cast<std::int64_t>();
    if (id < 0) throw InputError(Concat("properties ids are non-negative, got ", id));
    return ListedProperties(part, static_cast<IndexType>(id));
  }
  throw InputError(
      Concat("properties: expected a Properties or a properties id, got ", std::string(py::str(properties))));
}

/// The variable of a name or a variable object (the key of a values dict).
const VariableData& VariableOf(const py::handle& key) {
  if (py::isinstance<py::str>(key)) return VariableRegistry::Instance().Get(key.cast<std::string>());
  if (py::isinstance<VariableData>(key)) return key.cast<const VariableData&>();
  throw InputError(Concat("values: a key must be a variable or its name, got ", std::string(py::repr(key))));
}

using ValueList = std::vector<std::pair<const VariableData*, DataValueContainer::Value>>;

/// The values of a dict {variable or its name: value}, converted (and so checked) before any is set.
ValueList ConvertedValues(const py::dict& values) {
  ValueList converted;
  for (const auto& [key, value] : values) {
    const VariableData& var = VariableOf(key);
    converted.emplace_back(&var, FromPython(var, value));
  }
  return converted;
}

void SetPropertiesValues(Properties& properties, const py::dict& values) {
  for (const auto& [var, value] : ConvertedValues(values)) properties.SetGeneric(*var, value);
}

std::shared_ptr<const ConstitutiveLaw> LawOf(const std::string& name) {
  return std::shared_ptr<const ConstitutiveLaw>(Registry<ConstitutiveLaw>::Instance().GetShared(name)->Clone());
}

void SetConstitutiveLaw(Properties& properties, const std::string& name) { properties.SetConstitutiveLaw(LawOf(name)); }

/// Entities of one registered class from ids (m,) and a connectivity (m, k) of node ids.
void CreateEntities(ModelPart& part, const std::string& name, const IntArray& ids, const IntArray& connectivity,
                    const py::handle& properties, bool conditions) {
  const char* kind = conditions ? "condition" : "element";
  if (ids.ndim() != 1) throw InputError(Concat(kind, " ids: expected a 1-D array, got ", ids.ndim(), " dimensions"));
  if (connectivity.ndim() != 2 || connectivity.shape(0) != ids.shape(0))
    throw InputError(Concat("connectivity: expected an array (", ids.shape(0), ", nodes per ", kind,
                            ") of node ids, one row per ", kind));
  const std::vector<IndexType> entity_ids = PositiveIds(ids, Concat(kind, " ids").c_str());
  const std::vector<IndexType> node_ids = PositiveIds(connectivity, "node ids");
  Properties& props = PropertiesOf(part, properties);
  const auto k = static_cast<std::size_t>(connectivity.shape(1));
  const ModelPart& root = part.GetRootModelPart();
  const auto order = NewIdOrder(entity_ids, kind, part, [&](IndexType id) {
    return conditions ? root.FindCondition(id) != nullptr : root.FindElement(id) != nullptr;
  });
  // A connectivity of the wrong width fails at the first entity (the geometry checks its nodes).
  std::vector<IndexType> nodes(k);
  for (const std::size_t i : order) {
    std::copy_n(node_ids.begin() + static_cast<std::ptrdiff_t>(i * k), k, nodes.begin());
    if (conditions)
      part.CreateNewCondition(name, entity_ids[i], nodes, &props);
    else
      part.CreateNewElement(name, entity_ids[i], nodes, &props);
  }
}

template <class Container>
py::list AsList(const Container& items) {
  py::list list;
  for (auto* item : items) list.append(py::cast(item, py::return_value_policy::reference));
  return list;
}

}  // namespace

void AddModelToPython(py::module_& m) {
  py::class_<Dof>(m, "Dof", "One degree of freedom: a double variable of a node, its reaction, fixity and equation id.")
      .def_property_readonly(
          "variable", [](const Dof& d) { return d.variable; }, py::return_value_policy::reference,
          "The unknown, e.g. DISPLACEMENT_X.")
      .def_property_readonly(
          "reaction", [](const Dof& d) { return d.reaction; }, py::return_value_policy::reference,
          "Its reaction variable, e.g. REACTION_X (None without one).")
      .def_readwrite("fixed", &Dof::fixed, "Whether the value is prescribed.")
      .def_readonly("equation_id", &Dof::equation_id, "Row of the global system (-1 before the DoF set-up).")
      .def_property_readonly(
          "node_id", [](const Dof& d) { return d.node->Id(); }, "Id of its node.")
      .def(
          "Value", [](const Dof& d, int step) { return d.Value(step); }, py::arg("step") = 0,
          "Historical value of the variable, step 0 the current one.");

  py::class_<Node> node(m, "Node",
                        "A mesh node (Kratos Node): initial and current coordinates, historical values of the last "
                        "buffer_size steps, non-historical values, flags and DoFs.");
  node.def_property_readonly("Id", &Node::Id, "The node's id.")
      .def_property_readonly("X", &Node::X, "Current x coordinate.")
      .def_property_readonly("Y", &Node::Y, "Current y coordinate.")
      .def_property_readonly("Z", &Node::Z, "Current z coordinate.")
      .def_property_readonly(
          "X0", [](const Node& n) { return n.X0()[0]; }, "Initial x coordinate.")
      .def_property_readonly(
          "Y0", [](const Node& n) { return n.X0()[1]; }, "Initial y coordinate.")
      .def_property_readonly(
          "Z0", [](const Node& n) { return n.X0()[2]; }, "Initial z coordinate.")
      .def(
          "Coordinates", [](const Node& n) { return Array3(n.Coordinates()); }, "Current coordinates (x, y, z).")
      .def(
          "InitialCoordinates", [](const Node& n) { return Array3(n.X0()); }, "Initial coordinates (X0, Y0, Z0).")
      .def("GetSolutionStepValue", &GetHistorical, py::arg("variable"), py::arg("step") = 0,
           "Historical value of a double or Array3 variable, step 0 the current one.")
      .def(
          "SetSolutionStepValue",
          [](Node& n, const VariableData& v, const py::object& value) { SetHistorical(n, v, value, 0); },
          py::arg("variable"), py::arg("value"), "Sets the current historical value of a variable.")
      .def(
          "SetSolutionStepValue",
          [](Node& n, const VariableData& v, int step, const py::object& value) { SetHistorical(n, v, value, step); },
          py::arg("variable"), py::arg("step"), py::arg("value"), "Sets the historical value of a variable at a step.")
      .def("HasSolutionStepValue", &Node::HasSolutionStepValue, py::arg("variable"),
           "Whether the variable is historical in this node's model part.");
  BindFlags(BindValues(node))
      .def(
          "AddDof",
          [](Node& n, const VariableData& v, const VariableData* r) -> Dof& {
            return n.AddDof(AsDouble(v), r ? &AsDouble(*r) : nullptr);
          },
          py::arg("variable"), py::arg("reaction") = nullptr, py::return_value_policy::reference_internal,
          "Adds (or returns the existing) DoF of a double variable, with an optional reaction variable.")
      .def(
          "HasDofFor", [](const Node& n, const VariableData& v) { return n.HasDofFor(AsDouble(v)); },
          py::arg("variable"), "Whether the node has a DoF of the variable.")
      .def(
          "GetDof", [](const Node& n, const VariableData& v) -> Dof& { return n.GetDof(AsDouble(v)); },
          py::arg("variable"), py::return_value_policy::reference_internal,
          "The DoF of the variable (InputError naming node and variable otherwise).")
      .def(
          "Fix", [](Node& n, const VariableData& v) { n.Fix(AsDouble(v)); }, py::arg("variable"),
          "Prescribes the DoF of the variable.")
      .def(
          "Free", [](Node& n, const VariableData& v) { n.Free(AsDouble(v)); }, py::arg("variable"),
          "Releases the DoF of the variable.")
      .def(
          "IsFixed", [](const Node& n, const VariableData& v) { return n.IsFixed(AsDouble(v)); }, py::arg("variable"),
          "Whether the node has a fixed DoF of the variable.")
      .def("__repr__",
           [](const Node& n) { return Concat("<Node ", n.Id(), " (", n.X(), ", ", n.Y(), ", ", n.Z(), ")>"); });

  py::class_<Properties> properties(m, "Properties",
                                    "Material and numerical properties shared by elements and conditions (Kratos "
                                    "Properties): values, the constitutive law and tables.");
  properties.def_property_readonly("Id", &Properties::Id, "The properties' id.");
  BindValues(properties)
      .def("SetValues", &SetPropertiesValues, py::arg("values"),
           "Sets several values at once from a dict {variable or its name: value}, e.g. {'YOUNG_MODULUS': 210e9, "
           "'POISSON_RATIO': 0.3, 'THICKNESS': 1.0} (SI units as the case uses them; the materials file's "
           "'Variables' block).")
      .def("SetConstitutiveLaw", &SetConstitutiveLaw, py::arg("name"),
           "Assigns a registered constitutive law by name, e.g. 'LinearElasticPlaneStrain2DLaw' (see "
           "ConstitutiveLawNames()).")
      .def("HasConstitutiveLaw", &Properties::HasConstitutiveLaw, "Whether a constitutive law is assigned.")
      .def(
          "ConstitutiveLawName",
          [](const Properties& p) { return p.HasConstitutiveLaw() ? p.GetConstitutiveLaw()->Name() : std::string(); },
          "Registered name of the constitutive law ('' without one).");

  py::class_<ProcessInfo> process_info(m, "ProcessInfo",
                                       "Global state shared by all parts of a model (Kratos ProcessInfo): TIME, "
                                       "DELTA_TIME, STEP, DOMAIN_SIZE, iteration counters, flags.");
  BindFlags(BindValues(process_info));

  py::class_<Entity> entity(m, "Entity",
                            "What elements and conditions have in common: geometry, properties, flags, values and "
                            "the finite-element interface.");
  entity.def_property_readonly("Id", &Entity::Id, "The entity's id.")
      .def("Info", &Entity::Info, "Registered name of its class, e.g. 'SmallDisplacementElement'.")
      .def("GetGeometry", py::overload_cast<>(&Entity::GetGeometry), py::return_value_policy::reference_internal,
           "Its Geometry.")
      .def(
          "GetNodes", [](Entity& e) { return AsList(e.GetGeometry().Nodes()); }, "Its nodes, in local order.")
      .def(
          "NodeIds",
          [](const Entity& e) {
            std::vector<IndexType> ids;
            for (const Node* n : e.GetGeometry().Nodes()) ids.push_back(n->Id());
            return ids;
          },
          "Ids of its nodes, in local order.")
      .def("GetProperties", &Entity::GetProperties, py::return_value_policy::reference, "Its Properties.")
      .def("IsActive", &Entity::IsActive, "False only when ACTIVE is explicitly reset; builders skip inactive ones.")
      .def("NumberOfIntegrationPoints", &Entity::NumberOfIntegrationPoints,
           "Number of integration points CalculateOnIntegrationPoints returns values for.")
      .def(
          "CalculateOnIntegrationPoints",
          [](Entity& e, const VariableData& v, const ProcessInfo& info) -> py::object {
            switch (v.Type()) {
              case ValueType::Double: {
                std::vector<double> out;
                e.CalculateOnIntegrationPoints(static_cast<const Variable<double>&>(v), out, info);
                return py::cast(out);
              }
              case ValueType::Array3: {
                std::vector<Array3> out;
                e.CalculateOnIntegrationPoints(static_cast<const Variable<Array3>&>(v), out, info);
                return py::cast(out);
              }
              case ValueType::Vector: {
                std::vector<Vector> out;
                e.CalculateOnIntegrationPoints(static_cast<const Variable<Vector>&>(v), out, info);
                return py::cast(out);
              }
              case ValueType::Matrix: {
                std::vector<Matrix> out;
                e.CalculateOnIntegrationPoints(static_cast<const Variable<Matrix>&>(v), out, info);
                return py::cast(out);
              }
              default: throw InputError(Concat(v.Name(), " cannot be computed on integration points"));
            }
          },
          py::arg("variable"), py::arg("process_info"),
          "The values of a result variable (stress, strain, ...) at each integration point.")
      .def(
          "CalculateLocalSystem",
          [](Entity& e, const ProcessInfo& info) {
            Matrix lhs;
            Vector rhs;
            e.CalculateLocalSystem(lhs, rhs, info);
            return py::make_tuple(lhs, rhs);
          },
          py::arg("process_info"),
          "(LHS, RHS): LHS = d(residual)/d(unknowns), RHS = external - internal forces, in GetDofList order.")
      .def(
          "GetDofList",
          [](const Entity& e, const ProcessInfo& info) {
            DofsVectorType dofs;
            e.GetDofList(dofs, info);
            return dofs;
          },
          py::arg("process_info"), py::return_value_policy::reference,
          "Its Dofs in the order of CalculateLocalSystem's rows (e.g. to assemble a tangent by hand).")
      .def("__repr__", [](const Entity& e) { return Concat("<", e.Info(), " ", e.Id(), ">"); });
  BindFlags(BindValues(entity));
  py::class_<Element, Entity>(m, "Element", "A finite element of the domain, created by its registered name.");
  py::class_<Condition, Entity>(m, "Condition",
                                "A boundary or interface entity (loads, skins, contact pairs), created by its "
                                "registered name.");

  py::class_<ModelPart> model_part(m, "ModelPart",
                                   "A named set of nodes, elements, conditions and properties with nested sub-model "
                                   "parts (Kratos ModelPart); the root owns every entity.");
  model_part.def_property_readonly("Name", &ModelPart::Name, "Its name, e.g. 'ContactSub0'.")
      .def("FullName", &ModelPart::FullName, "Dotted path from the root, e.g. 'Structure.Contact.ContactSub0'.")
      .def("IsSubModelPart", &ModelPart::IsSubModelPart, "Whether it has a parent.")
      .def("GetRootModelPart", py::overload_cast<>(&ModelPart::GetRootModelPart), py::return_value_policy::reference,
           "The root of its tree.")
      .def("GetParentModelPart", &ModelPart::GetParentModelPart, py::return_value_policy::reference,
           "Its parent (itself for a root).")
      .def("AddNodalSolutionStepVariable", &ModelPart::AddNodalSolutionStepVariable, py::arg("variable"),
           "Makes a variable historical on the nodes of the whole tree (before nodes are created).")
      .def("HasNodalSolutionStepVariable", &ModelPart::HasNodalSolutionStepVariable, py::arg("variable"),
           "Whether a variable is historical.")
      .def(
          "NodalSolutionStepVariableNames",
          [](const ModelPart& p) {
            std::vector<std::string> names;
            for (const VariableData* v : p.GetNodalSolutionStepVariablesList().Variables()) names.push_back(v->Name());
            return names;
          },
          "Names of the historical variables, in the order of their storage.")
      .def("GetBufferSize", &ModelPart::GetBufferSize, "Number of steps of nodal history kept.")
      .def("SetBufferSize", &ModelPart::SetBufferSize, py::arg("buffer_size"),
           "Resizes the history of every node of the tree.")
      .def_property_readonly("ProcessInfo", py::overload_cast<>(&ModelPart::GetProcessInfo),
                             py::return_value_policy::reference_internal, "The ProcessInfo of its tree.")
      .def("GetProcessInfo", py::overload_cast<>(&ModelPart::GetProcessInfo),
           py::return_value_policy::reference_internal, "The ProcessInfo of its tree.")
      .def("CloneTimeStep", &ModelPart::CloneTimeStep, py::arg("time"),
           "Advances TIME (and STEP) and shifts the history of every node.")
      .def("CreateNewNode", &ModelPart::CreateNewNode, py::arg("id"), py::arg("x"), py::arg("y"), py::arg("z"),
           py::return_value_policy::reference,
           "Creates a node in the root and adds it here and to every ancestor (ids unique in the model).")
      .def("CreateNewNodes", &CreateNodes, py::arg("ids"), py::arg("coordinates"),
           "Creates many nodes in one call: ids (n,) integers, coordinates (n, 3) or (n, 2) (z = 0) in the "
           "model's length unit. Like CreateNewNode, in the root, here and in every ancestor; every id must be "
           "new (InputError naming the first that is not, before any node is created). 100k nodes: 0.06 s "
           "(CreateNewNode in a Python loop: 0.14 s).")
      .def("AddNodes", &ModelPart::AddNodes, py::arg("ids"), "Adds existing nodes of the root by id.")
      .def("GetNode", &ModelPart::GetNode, py::arg("id"), py::return_value_policy::reference,
           "The node of this id (InputError otherwise).")
      .def("HasNode", &ModelPart::HasNode, py::arg("id"), "Whether it holds the node of this id.")
      .def_property_readonly(
          "Nodes", [](const ModelPart& p) { return AsList(p.Nodes()); }, "Its nodes, in id order.")
      .def("NumberOfNodes", &ModelPart::NumberOfNodes, "Number of its nodes.")
      .def(
          "CreateNewElement",
          [](ModelPart& p, const std::string& name, IndexType id, const std::vector<IndexType>& nodes,
             Properties& props) -> Element& { return p.CreateNewElement(name, id, nodes, &props); },
          py::arg("name"), py::arg("id"), py::arg("node_ids"), py::arg("properties"),
          py::return_value_policy::reference,
          "Creates an element of a registered name (e.g. 'SmallDisplacementElement2D4N') on the nodes of these ids.")
      .def(
          "CreateNewCondition",
          [](ModelPart& p, const std::string& name, IndexType id, const std::vector<IndexType>& nodes,
             Properties& props) -> Condition& { return p.CreateNewCondition(name, id, nodes, &props); },
          py::arg("name"), py::arg("id"), py::arg("node_ids"), py::arg("properties"),
          py::return_value_policy::reference,
          "Creates a condition of a registered name (e.g. 'LineLoadCondition2D2N') on the nodes of these ids.")
      .def(
          "CreateNewElements",
          [](ModelPart& p, const std::string& name, const IntArray& ids, const IntArray& connectivity,
             const py::object& properties) { CreateEntities(p, name, ids, connectivity, properties, false); },
          py::arg("name"), py::arg("ids"), py::arg("connectivity"), py::arg("properties"),
          "Creates many elements of one registered name in one call: ids (m,), connectivity (m, k) of node ids "
          "in the element's local order (Kratos' = VTK's for linear cells), properties a Properties or the id "
          "of properties this part lists. Ids checked first (new, given once), as for nodes.")
      .def(
          "CreateNewConditions",
          [](ModelPart& p, const std::string& name, const IntArray& ids, const IntArray& connectivity,
             const py::object& properties) { CreateEntities(p, name, ids, connectivity, properties, true); },
          py::arg("name"), py::arg("ids"), py::arg("connectivity"), py::arg("properties"),
          "Creates many conditions of one registered name in one call (e.g. 'LineLoadCondition2D2N'); "
          "arguments as for CreateNewElements.")
      .def("AddElements", &ModelPart::AddElements, py::arg("ids"), "Adds existing elements of the root by id.")
      .def("AddConditions", &ModelPart::AddConditions, py::arg("ids"), "Adds existing conditions of the root by id.")
      .def("GetElement", &ModelPart::GetElement, py::arg("id"), py::return_value_policy::reference,
           "The element of this id (InputError otherwise).")
      .def("GetCondition", &ModelPart::GetCondition, py::arg("id"), py::return_value_policy::reference,
           "The condition of this id (InputError otherwise).")
      .def_property_readonly(
          "Elements", [](const ModelPart& p) { return AsList(p.Elements()); }, "Its elements, in id order.")
      .def_property_readonly(
          "Conditions", [](const ModelPart& p) { return AsList(p.Conditions()); }, "Its conditions, in id order.")
      .def("AddMasterSlaveConstraint", &ModelPart::AddMasterSlaveConstraint, py::arg("constraint"),
           "Adds a MasterSlaveConstraint here and to every ancestor; the builders eliminate the active ones.")
      .def_property_readonly("MasterSlaveConstraints", &ModelPart::MasterSlaveConstraints,
                             "Its master-slave constraints, in the order they were added.")
      .def("NumberOfElements", &ModelPart::NumberOfElements, "Number of its elements.")
      .def("NumberOfConditions", &ModelPart::NumberOfConditions, "Number of its conditions.")
      .def("GetProperties", &ListedProperties, py::arg("id"), py::return_value_policy::reference,
           "The properties of this id that the part lists; InputError naming the ids it has otherwise (create "
           "them with CreateNewProperties).")
      .def(
          "CreateNewProperties",
          [](ModelPart& p, IndexType id, const std::optional<py::dict>& values,
             const std::optional<std::string>& constitutive_law) -> Properties& {
            if (p.HasProperties(id))
              throw InputError(Concat("model part ", p.FullName(), ": properties ", id, " exist already"));
            // Checked first: a wrong value or law name creates nothing.
            const ValueList converted = values ? ConvertedValues(*values) : ValueList{};
            const auto law = constitutive_law ? LawOf(*constitutive_law) : nullptr;
            Properties& properties = p.GetOrCreateProperties(id);
            for (const auto& [var, value] : converted) properties.SetGeneric(*var, value);
            if (law) properties.SetConstitutiveLaw(law);
            return properties;
          },
          py::arg("id"), py::arg("values") = py::none(), py::arg("constitutive_law") = py::none(),
          py::return_value_policy::reference,
          "Creates properties of this id (one set per id in the whole tree: the root's, when it has them "
          "already, are listed here), with optional values {variable or name: value} and constitutive law "
          "name, e.g. CreateNewProperties(1, {'YOUNG_MODULUS': 210e9, 'POISSON_RATIO': 0.3}, "
          "'LinearElastic3DLaw'). InputError if this part lists the id already.")
      .def("HasProperties", &ModelPart::HasProperties, py::arg("id"), "Whether it lists the properties of this id.")
      .def_property_readonly(
          "Properties", [](const ModelPart& p) { return AsList(p.PropertiesList()); }, "Its properties.")
      .def("CreateSubModelPart", &ModelPart::CreateSubModelPart, py::arg("name"), py::return_value_policy::reference,
           "Creates a sub-model part of this name.")
      .def("HasSubModelPart", &ModelPart::HasSubModelPart, py::arg("name"),
           "Whether the sub-model part exists (dotted paths relative to this part accepted).")
      .def("GetSubModelPart", &ModelPart::GetSubModelPart, py::arg("name"), py::return_value_policy::reference,
           "The sub-model part of this name or dotted path (InputError with suggestions otherwise).")
      .def("RemoveSubModelPart", &ModelPart::RemoveSubModelPart, py::arg("name"), "Removes a sub-model part.")
      .def_property_readonly(
          "SubModelParts", [](const ModelPart& p) { return AsList(p.SubModelParts()); }, "Its direct sub-model parts.")
      .def("SubModelPartNames", &ModelPart::SubModelPartNames, "Names of its direct sub-model parts.")
      // numpy bulk access (copies, in node-id order)
      .def(
          "NodeIds",
          [](const ModelPart& p) {
            py::array_t<std::int64_t> ids(py::ssize_t(p.NumberOfNodes()));
            auto* d = ids.mutable_data();
            std::size_t i = 0;
            for (const Node* n : p.Nodes()) d[i++] = static_cast<std::int64_t>(n->Id());
            return ids;
          },
          "Node ids as an int64 array (n,), in id order.")
      .def(
          "NodeCoordinates",
          [](const ModelPart& p, bool initial) {
            py::array_t<double> x({py::ssize_t(p.NumberOfNodes()), py::ssize_t(3)});
            auto* d = x.mutable_data();
            std::size_t i = 0;
            for (const Node* n : p.Nodes()) {
              const Array3& c = initial ? n->X0() : n->Coordinates();
              for (int k = 0; k < 3; ++k) d[3 * i + k] = c[k];
              ++i;
            }
            return x;
          },
          py::arg("initial") = false, "Current (or initial) coordinates of every node, shape (n, 3), in node-id order.")
      .def("GetNodalValues", &NodalValues, py::arg("variable"), py::arg("step") = 0,
           "Historical values of every node, shape (n,) or (n, 3), in node-id order.")
      .def("SetNodalValues", &SetNodalValues, py::arg("variable"), py::arg("values"), py::arg("step") = 0,
           "Sets the historical values of every node from an array (n,) or (n, 3) in node-id order.")
      .def("GetNodalNonHistoricalValues", &NodalNonHistoricalValues, py::arg("variable"),
           "Non-historical values of every node, shape (n,) or (n, 3), in node-id order.")
      .def(
          "GetNodalFlags",
          [](const ModelPart& p, const Flag& flag) {
            py::array_t<bool> out(py::ssize_t(p.NumberOfNodes()));
            auto* d = out.mutable_data();
            std::size_t i = 0;
            for (const Node* n : p.Nodes()) d[i++] = n->Is(flag);
            return out;
          },
          py::arg("flag"), "Whether each node has the flag set, shape (n,), in node-id order.")
      .def(
          "SetNodeCoordinates",
          [](ModelPart& p, py::array_t<double, py::array::c_style | py::array::forcecast> coordinates, bool initial) {
            const auto& nodes = p.Nodes();
            if (static_cast<std::size_t>(coordinates.size()) != 3 * nodes.size())
              throw InputError(Concat("expected coordinates of shape (", nodes.size(), ", 3) for ", p.FullName(),
                                      ", got ", coordinates.size(), " values"));
            const double* c = coordinates.data();
            for (std::size_t i = 0; i < nodes.size(); ++i) {
              Array3& x = initial ? nodes[i]->X0() : nodes[i]->Coordinates();
              x = Array3(c[3 * i], c[3 * i + 1], c[3 * i + 2]);
            }
          },
          py::arg("coordinates"), py::arg("initial") = false,
          "Sets the current (or initial) coordinates of every node from an array (n, 3) in node-id order.")
      .def(
          "NodalNonHistoricalVariableNames",
          [](const ModelPart& p) {
            std::set<std::string> names;
            for (const Node* n : p.Nodes())
              for (const auto& item : n->Data().Items()) names.insert(item.first->Name());
            return std::vector<std::string>(names.begin(), names.end());
          },
          "Sorted names of the variables of which some node of the part holds a non-historical value.")
      .def(
          "HasNodalNonHistoricalValues",
          [](const ModelPart& p, const VariableData& v) {
            const VariableData* key = v.IsComponent() ? v.Source() : &v;
            py::array_t<bool> out(py::ssize_t(p.NumberOfNodes()));
            auto* d = out.mutable_data();
            std::size_t i = 0;
            for (const Node* n : p.Nodes()) {
              const auto& items = n->Data().Items();
              d[i++] = std::any_of(items.begin(), items.end(), [&](const auto& item) { return item.first == key; });
            }
            return out;
          },
          py::arg("variable"), "Whether each node holds a non-historical value of the variable, shape (n,).")
      .def("SetNodalNonHistoricalValues", &SetNodalNonHistoricalValues, py::arg("variable"), py::arg("values"),
           py::arg("held") = py::none(),
           "Sets non-historical values (double, int, bool or Array3) of every node from an array (n,) or (n, 3) "
           "in node-id order; with 'held' (bool (n,)) the nodes marked false lose their value instead.")
      .def("GetNodalFlagStates", &NodalFlagStates, py::arg("flag"),
           "State of a flag on each node, int8 (n,): -1 undefined, 0 reset, 1 set.")
      .def("SetNodalFlagStates", &SetNodalFlagStates, py::arg("flag"), py::arg("states"),
           "Sets the flag of every node from int8 states (n,): -1 undefined, 0 reset, 1 set.")
      .def("GetNodalFixity", &NodalFixity, py::arg("variable"),
           "Fixity of the DoF of a double variable on each node, int8 (n,): -1 no such DoF, 0 free, 1 fixed.")
      .def("SetNodalFixity", &SetNodalFixity, py::arg("variable"), py::arg("fixed"),
           "Fixes (true) or frees (false) the DoF of a double variable on each node that has it; bool (n,).")
      .def(
          "EntityConnectivity",
          [](const ModelPart& p, bool conditions) {
            return conditions ? Connectivity(p.Conditions()) : Connectivity(p.Elements());
          },
          py::arg("conditions") = false,
          "{geometry name: (entity ids (m,), node ids (m, k))} of the elements (or conditions).")
      .def(
          "IntegrationPointMeans",
          [](const ModelPart& p, const VariableData& v, const std::vector<IndexType>& ids, bool conditions) {
            switch (v.Type()) {
              case ValueType::Double: return IntegrationPointMeans<double>(p, v, ids, conditions);
              case ValueType::Array3: return IntegrationPointMeans<Array3>(p, v, ids, conditions);
              case ValueType::Vector: return IntegrationPointMeans<Vector>(p, v, ids, conditions);
              case ValueType::Matrix: return IntegrationPointMeans<Matrix>(p, v, ids, conditions);
              default: throw InputError(Concat(v.Name(), " cannot be computed on integration points"));
            }
          },
          py::arg("variable"), py::arg("entity_ids"), py::arg("conditions") = false,
          "Mean over the integration points of each listed entity (see the writers).")
      .def("__repr__", [](const ModelPart& p) {
        return Concat("<ModelPart ", p.FullName(), ": ", p.NumberOfNodes(), " nodes, ", p.NumberOfElements(),
                      " elements, ", p.NumberOfConditions(), " conditions>");
      });
  BindFlags(model_part);

  py::class_<Model>(m, "Model",
                    "Owner of the root model parts of a simulation, addressed by dotted names (Kratos Model).")
      .def(py::init<>(), "An empty model.")
      .def("CreateModelPart", &Model::CreateModelPart, py::arg("name"), py::arg("buffer_size") = 1,
           py::return_value_policy::reference_internal,
           "Creates a root model part keeping buffer_size steps of nodal history.")
      .def("GetModelPart", &Model::GetModelPart, py::arg("name"), py::return_value_policy::reference_internal,
           "A model part by name or dotted path ('Structure.Contact'); InputError with suggestions otherwise.")
      .def("__getitem__", &Model::GetModelPart, py::arg("name"), py::return_value_policy::reference_internal,
           "A model part by name or dotted path.")
      .def("HasModelPart", &Model::HasModelPart, py::arg("name"), "Whether the model part exists.")
      .def("DeleteModelPart", &Model::DeleteModelPart, py::arg("name"), "Deletes a root model part.")
      .def("ModelPartNames", &Model::ModelPartNames, "Names of the root model parts.");

  m.def(
      "ElementNames", [] { return Registry<Element>::Instance().Names(); }, "Names of all registered elements.");
  m.def(
      "ConditionNames", [] { return Registry<Condition>::Instance().Names(); }, "Names of all registered conditions.");
  m.def(
      "ConstitutiveLawNames", [] { return Registry<ConstitutiveLaw>::Instance().Names(); },
      "Names of all registered constitutive laws.");
}

}  // namespace mc::python
