// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/numpy.h>

#include <map>

#include "core/model/constitutive_law.h"
#include "core/model/model.h"
#include "core/model/registry.h"
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
  if (var.Type() != ValueType::Double)
    throw InputError(Concat(var.Name(), " is not a scalar (double) variable"));
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
  py::array_t<double> out(width == 3 ? std::vector<py::ssize_t>{py::ssize_t(n), 3} : std::vector<py::ssize_t>{py::ssize_t(n)});
  double* dst = out.mutable_data();
  for (std::size_t i = 0; i < n; ++i) {
    const double* src = nodes[i]->StepData(step) + offset;
    for (std::size_t k = 0; k < width; ++k) dst[i * width + k] = src[k];
  }
  return out;
}

void SetNodalValues(ModelPart& part, const VariableData& var, py::array_t<double, py::array::c_style | py::array::forcecast> values,
                    int step) {
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
    Entity& e = conditions ? static_cast<Entity&>(part.GetCondition(ids[i])) : static_cast<Entity&>(part.GetElement(ids[i]));
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

template <class Container>
py::list AsList(const Container& items) {
  py::list list;
  for (auto* item : items) list.append(py::cast(item, py::return_value_policy::reference));
  return list;
}

}  // namespace

void AddModelToPython(py::module_& m) {
  py::class_<Dof>(m, "Dof")
      .def_property_readonly("variable", [](const Dof& d) { return d.variable; }, py::return_value_policy::reference)
      .def_property_readonly("reaction", [](const Dof& d) { return d.reaction; }, py::return_value_policy::reference)
      .def_readwrite("fixed", &Dof::fixed)
      .def_readonly("equation_id", &Dof::equation_id)
      .def_property_readonly("node_id", [](const Dof& d) { return d.node->Id(); })
      .def("Value", [](const Dof& d, int step) { return d.Value(step); }, py::arg("step") = 0);

  py::class_<Node>(m, "Node")
      .def_property_readonly("Id", &Node::Id)
      .def_property_readonly("X", &Node::X)
      .def_property_readonly("Y", &Node::Y)
      .def_property_readonly("Z", &Node::Z)
      .def_property_readonly("X0", [](const Node& n) { return n.X0()[0]; })
      .def_property_readonly("Y0", [](const Node& n) { return n.X0()[1]; })
      .def_property_readonly("Z0", [](const Node& n) { return n.X0()[2]; })
      .def("Coordinates", [](const Node& n) { return Array3(n.Coordinates()); })
      .def("InitialCoordinates", [](const Node& n) { return Array3(n.X0()); })
      .def("GetSolutionStepValue", &GetHistorical, py::arg("variable"), py::arg("step") = 0)
      .def("SetSolutionStepValue", [](Node& n, const VariableData& v, const py::object& value) { SetHistorical(n, v, value, 0); },
           py::arg("variable"), py::arg("value"))
      .def("SetSolutionStepValue", [](Node& n, const VariableData& v, int step, const py::object& value) { SetHistorical(n, v, value, step); },
           py::arg("variable"), py::arg("step"), py::arg("value"))
      .def("HasSolutionStepValue", &Node::HasSolutionStepValue)
      .def("GetValue", [](const Node& n, const VariableData& v) { return GetGeneric(n.Data(), v); })
      .def("SetValue", [](Node& n, const VariableData& v, const py::object& value) { n.Data().SetGeneric(v, FromPython(v, value)); })
      .def("Has", [](const Node& n, const VariableData& v) {
        return std::any_of(n.Data().Items().begin(), n.Data().Items().end(),
                           [&](const auto& item) { return item.first == (v.IsComponent() ? v.Source() : &v); });
      })
      .def("Is", &Node::Is)
      .def("Set", &Node::Set, py::arg("flag"), py::arg("value") = true)
      .def("AddDof", [](Node& n, const VariableData& v, const VariableData* r) -> Dof& {
             return n.AddDof(AsDouble(v), r ? &AsDouble(*r) : nullptr);
           }, py::arg("variable"), py::arg("reaction") = nullptr, py::return_value_policy::reference_internal)
      .def("HasDofFor", [](const Node& n, const VariableData& v) { return n.HasDofFor(AsDouble(v)); })
      .def("GetDof", [](const Node& n, const VariableData& v) -> Dof& { return n.GetDof(AsDouble(v)); },
           py::return_value_policy::reference_internal)
      .def("Fix", [](Node& n, const VariableData& v) { n.Fix(AsDouble(v)); })
      .def("Free", [](Node& n, const VariableData& v) { n.Free(AsDouble(v)); })
      .def("IsFixed", [](const Node& n, const VariableData& v) { return n.IsFixed(AsDouble(v)); })
      .def("__repr__", [](const Node& n) { return Concat("<Node ", n.Id(), " (", n.X(), ", ", n.Y(), ", ", n.Z(), ")>"); });

  py::class_<Properties>(m, "Properties")
      .def_property_readonly("Id", &Properties::Id)
      .def("GetValue", [](const Properties& p, const VariableData& v) { return GetGeneric(p, v); })
      .def("SetValue", [](Properties& p, const VariableData& v, const py::object& value) { p.SetGeneric(v, FromPython(v, value)); })
      .def("Has", [](const Properties& p, const VariableData& v) {
        return std::any_of(p.Items().begin(), p.Items().end(), [&](const auto& item) { return item.first == &v; });
      })
      .def("HasConstitutiveLaw", &Properties::HasConstitutiveLaw)
      .def("ConstitutiveLawName", [](const Properties& p) { return p.HasConstitutiveLaw() ? p.GetConstitutiveLaw()->Name() : std::string(); });

  py::class_<ProcessInfo>(m, "ProcessInfo")
      .def("GetValue", [](const ProcessInfo& p, const VariableData& v) { return GetGeneric(p, v); })
      .def("SetValue", [](ProcessInfo& p, const VariableData& v, const py::object& value) { p.SetGeneric(v, FromPython(v, value)); })
      .def("Has", [](const ProcessInfo& p, const VariableData& v) {
        return std::any_of(p.Items().begin(), p.Items().end(), [&](const auto& item) { return item.first == &v; });
      })
      .def("Is", &ProcessInfo::Is)
      .def("Set", &ProcessInfo::Set, py::arg("flag"), py::arg("value") = true);

  py::class_<Entity>(m, "Entity")
      .def_property_readonly("Id", &Entity::Id)
      .def("Info", &Entity::Info)
      .def("GetGeometry", py::overload_cast<>(&Entity::GetGeometry), py::return_value_policy::reference_internal)
      .def("GetNodes", [](Entity& e) { return AsList(e.GetGeometry().Nodes()); })
      .def("NodeIds", [](const Entity& e) {
        std::vector<IndexType> ids;
        for (const Node* n : e.GetGeometry().Nodes()) ids.push_back(n->Id());
        return ids;
      })
      .def("GetProperties", &Entity::GetProperties, py::return_value_policy::reference)
      .def("Is", &Entity::Is)
      .def("Set", &Entity::Set, py::arg("flag"), py::arg("value") = true)
      .def("IsActive", &Entity::IsActive)
      .def("GetValue", [](const Entity& e, const VariableData& v) { return GetGeneric(e.Data(), v); })
      .def("SetValue", [](Entity& e, const VariableData& v, const py::object& value) { e.Data().SetGeneric(v, FromPython(v, value)); })
      .def("NumberOfIntegrationPoints", &Entity::NumberOfIntegrationPoints)
      .def("CalculateOnIntegrationPoints", [](Entity& e, const VariableData& v, const ProcessInfo& info) -> py::object {
        switch (v.Type()) {
          case ValueType::Double: { std::vector<double> out; e.CalculateOnIntegrationPoints(static_cast<const Variable<double>&>(v), out, info); return py::cast(out); }
          case ValueType::Array3: { std::vector<Array3> out; e.CalculateOnIntegrationPoints(static_cast<const Variable<Array3>&>(v), out, info); return py::cast(out); }
          case ValueType::Vector: { std::vector<Vector> out; e.CalculateOnIntegrationPoints(static_cast<const Variable<Vector>&>(v), out, info); return py::cast(out); }
          case ValueType::Matrix: { std::vector<Matrix> out; e.CalculateOnIntegrationPoints(static_cast<const Variable<Matrix>&>(v), out, info); return py::cast(out); }
          default: throw InputError(Concat(v.Name(), " cannot be computed on integration points"));
        }
      })
      .def("CalculateLocalSystem", [](Entity& e, const ProcessInfo& info) {
        Matrix lhs;
        Vector rhs;
        e.CalculateLocalSystem(lhs, rhs, info);
        return py::make_tuple(lhs, rhs);
      })
      .def("__repr__", [](const Entity& e) { return Concat("<", e.Info(), " ", e.Id(), ">"); });
  py::class_<Element, Entity>(m, "Element");
  py::class_<Condition, Entity>(m, "Condition");

  py::class_<ModelPart>(m, "ModelPart")
      .def_property_readonly("Name", &ModelPart::Name)
      .def("FullName", &ModelPart::FullName)
      .def("IsSubModelPart", &ModelPart::IsSubModelPart)
      .def("GetRootModelPart", py::overload_cast<>(&ModelPart::GetRootModelPart), py::return_value_policy::reference)
      .def("GetParentModelPart", &ModelPart::GetParentModelPart, py::return_value_policy::reference)
      .def("AddNodalSolutionStepVariable", &ModelPart::AddNodalSolutionStepVariable)
      .def("HasNodalSolutionStepVariable", &ModelPart::HasNodalSolutionStepVariable)
      .def("GetBufferSize", &ModelPart::GetBufferSize)
      .def("SetBufferSize", &ModelPart::SetBufferSize)
      .def_property_readonly("ProcessInfo", py::overload_cast<>(&ModelPart::GetProcessInfo), py::return_value_policy::reference_internal)
      .def("GetProcessInfo", py::overload_cast<>(&ModelPart::GetProcessInfo), py::return_value_policy::reference_internal)
      .def("CloneTimeStep", &ModelPart::CloneTimeStep)
      .def("CreateNewNode", &ModelPart::CreateNewNode, py::return_value_policy::reference)
      .def("AddNodes", &ModelPart::AddNodes)
      .def("GetNode", &ModelPart::GetNode, py::return_value_policy::reference)
      .def("HasNode", &ModelPart::HasNode)
      .def_property_readonly("Nodes", [](const ModelPart& p) { return AsList(p.Nodes()); })
      .def("NumberOfNodes", &ModelPart::NumberOfNodes)
      .def("CreateNewElement", [](ModelPart& p, const std::string& name, IndexType id, const std::vector<IndexType>& nodes, Properties& props) -> Element& {
        return p.CreateNewElement(name, id, nodes, &props);
      }, py::return_value_policy::reference)
      .def("CreateNewCondition", [](ModelPart& p, const std::string& name, IndexType id, const std::vector<IndexType>& nodes, Properties& props) -> Condition& {
        return p.CreateNewCondition(name, id, nodes, &props);
      }, py::return_value_policy::reference)
      .def("AddElements", &ModelPart::AddElements)
      .def("AddConditions", &ModelPart::AddConditions)
      .def("GetElement", &ModelPart::GetElement, py::return_value_policy::reference)
      .def("GetCondition", &ModelPart::GetCondition, py::return_value_policy::reference)
      .def_property_readonly("Elements", [](const ModelPart& p) { return AsList(p.Elements()); })
      .def_property_readonly("Conditions", [](const ModelPart& p) { return AsList(p.Conditions()); })
      .def("NumberOfElements", &ModelPart::NumberOfElements)
      .def("NumberOfConditions", &ModelPart::NumberOfConditions)
      .def("GetProperties", &ModelPart::GetOrCreateProperties, py::return_value_policy::reference)
      .def("HasProperties", &ModelPart::HasProperties)
      .def_property_readonly("Properties", [](const ModelPart& p) { return AsList(p.PropertiesList()); })
      .def("CreateSubModelPart", &ModelPart::CreateSubModelPart, py::return_value_policy::reference)
      .def("HasSubModelPart", &ModelPart::HasSubModelPart)
      .def("GetSubModelPart", &ModelPart::GetSubModelPart, py::return_value_policy::reference)
      .def("RemoveSubModelPart", &ModelPart::RemoveSubModelPart)
      .def_property_readonly("SubModelParts", [](const ModelPart& p) { return AsList(p.SubModelParts()); })
      .def("SubModelPartNames", &ModelPart::SubModelPartNames)
      .def("Is", &ModelPart::Is)
      .def("Set", &ModelPart::Set, py::arg("flag"), py::arg("value") = true)
      // numpy bulk access (copies, in node-id order)
      .def("NodeIds", [](const ModelPart& p) {
        py::array_t<std::int64_t> ids(py::ssize_t(p.NumberOfNodes()));
        auto* d = ids.mutable_data();
        std::size_t i = 0;
        for (const Node* n : p.Nodes()) d[i++] = static_cast<std::int64_t>(n->Id());
        return ids;
      })
      .def("NodeCoordinates", [](const ModelPart& p, bool initial) {
        py::array_t<double> x({py::ssize_t(p.NumberOfNodes()), py::ssize_t(3)});
        auto* d = x.mutable_data();
        std::size_t i = 0;
        for (const Node* n : p.Nodes()) {
          const Array3& c = initial ? n->X0() : n->Coordinates();
          for (int k = 0; k < 3; ++k) d[3 * i + k] = c[k];
          ++i;
        }
        return x;
      }, py::arg("initial") = false)
      .def("GetNodalValues", &NodalValues, py::arg("variable"), py::arg("step") = 0,
           "Historical values of every node, shape (n,) or (n, 3), in node-id order.")
      .def("SetNodalValues", &SetNodalValues, py::arg("variable"), py::arg("values"), py::arg("step") = 0)
      .def("GetNodalNonHistoricalValues", &NodalNonHistoricalValues, py::arg("variable"),
           "Non-historical values of every node, shape (n,) or (n, 3), in node-id order.")
      .def("GetNodalFlags", [](const ModelPart& p, const Flag& flag) {
        py::array_t<bool> out(py::ssize_t(p.NumberOfNodes()));
        auto* d = out.mutable_data();
        std::size_t i = 0;
        for (const Node* n : p.Nodes()) d[i++] = n->Is(flag);
        return out;
      }, py::arg("flag"))
      .def("EntityConnectivity", [](const ModelPart& p, bool conditions) {
        return conditions ? Connectivity(p.Conditions()) : Connectivity(p.Elements());
      }, py::arg("conditions") = false,
         "{geometry name: (entity ids (m,), node ids (m, k))} of the elements (or conditions).")
      .def("IntegrationPointMeans", [](const ModelPart& p, const VariableData& v, const std::vector<IndexType>& ids,
                                       bool conditions) {
        switch (v.Type()) {
          case ValueType::Double: return IntegrationPointMeans<double>(p, v, ids, conditions);
          case ValueType::Array3: return IntegrationPointMeans<Array3>(p, v, ids, conditions);
          case ValueType::Vector: return IntegrationPointMeans<Vector>(p, v, ids, conditions);
          case ValueType::Matrix: return IntegrationPointMeans<Matrix>(p, v, ids, conditions);
          default: throw InputError(Concat(v.Name(), " cannot be computed on integration points"));
        }
      }, py::arg("variable"), py::arg("entity_ids"), py::arg("conditions") = false,
         "Mean over the integration points of each listed entity (see the writers).")
      .def("__repr__", [](const ModelPart& p) {
        return Concat("<ModelPart ", p.FullName(), ": ", p.NumberOfNodes(), " nodes, ", p.NumberOfElements(),
                      " elements, ", p.NumberOfConditions(), " conditions>");
      });

  py::class_<Model>(m, "Model")
      .def(py::init<>())
      .def("CreateModelPart", &Model::CreateModelPart, py::arg("name"), py::arg("buffer_size") = 1,
           py::return_value_policy::reference_internal)
      .def("GetModelPart", &Model::GetModelPart, py::return_value_policy::reference_internal)
      .def("__getitem__", &Model::GetModelPart, py::return_value_policy::reference_internal)
      .def("HasModelPart", &Model::HasModelPart)
      .def("DeleteModelPart", &Model::DeleteModelPart)
      .def("ModelPartNames", &Model::ModelPartNames);

  m.def("ElementNames", [] { return Registry<Element>::Instance().Names(); });
  m.def("ConditionNames", [] { return Registry<Condition>::Instance().Names(); });
  m.def("ConstitutiveLawNames", [] { return Registry<ConstitutiveLaw>::Instance().Names(); });
}

}  // namespace mc::python
