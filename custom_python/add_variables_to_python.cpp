// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "core/variables/flags.h"
#include "core/variables/kernel_variables.h"
#include "core/variables/variable_registry.h"
#include "custom_python/python_module.h"

namespace py = pybind11;

namespace mc::python {

namespace {
template <class T>
void BindVariable(py::module_& m, const char* name) {
  py::class_<Variable<T>, VariableData>(m, name);
}
}  // namespace

void AddVariablesToPython(py::module_& m) {
  py::enum_<ValueType>(m, "ValueType")
      .value("Double", ValueType::Double)
      .value("Int", ValueType::Int)
      .value("Bool", ValueType::Bool)
      .value("String", ValueType::String)
      .value("Array3", ValueType::Array3)
      .value("Vector", ValueType::Vector)
      .value("Matrix", ValueType::Matrix);

  py::class_<VariableData>(m, "VariableData")
      .def("Name", &VariableData::Name)
      .def("Key", &VariableData::Key)
      .def("Type", &VariableData::Type)
      .def("IsComponent", &VariableData::IsComponent)
      .def("Source", &VariableData::Source, py::return_value_policy::reference)
      .def("ComponentIndex", &VariableData::ComponentIndex)
      .def("__repr__", [](const VariableData& v) { return "<Variable " + v.Name() + ">"; })
      .def("__hash__", &VariableData::Key)
      .def("__eq__", [](const VariableData& a, const VariableData& b) { return &a == &b; });
  BindVariable<double>(m, "DoubleVariable");
  BindVariable<int>(m, "IntVariable");
  BindVariable<bool>(m, "BoolVariable");
  BindVariable<std::string>(m, "StringVariable");
  BindVariable<Array3>(m, "Array3Variable");
  BindVariable<Vector>(m, "VectorVariable");
  BindVariable<Matrix>(m, "MatrixVariable");

  m.def(
      "GetVariable", [](const std::string& name) -> const VariableData& { return VariableRegistry::Instance().Get(name); },
      py::arg("name"), py::return_value_policy::reference,
      "The registered variable of this name (InputError with the nearest names otherwise).");
  m.def("HasVariable", [](const std::string& name) { return VariableRegistry::Instance().Has(name); },
        py::arg("name"));
  m.def("VariableNames", [] { return VariableRegistry::Instance().Names(); });

  py::class_<Flag>(m, "Flag")
      .def("Name", &Flag::Name)
      .def("__repr__", [](const Flag& f) { return "<Flag " + f.Name() + ">"; });
  py::class_<Flags>(m, "Flags")
      .def("Is", &Flags::Is)
      .def("IsDefined", &Flags::IsDefined)
      .def("Set", &Flags::Set, py::arg("flag"), py::arg("value") = true)
      .def("Reset", &Flags::Reset);
  m.def("GetFlag", &Flag::Get, py::arg("name"), py::return_value_policy::reference);
  m.def("FlagNames", [] {
    std::vector<std::string> names;
    for (const Flag* f : Flag::All()) names.push_back(f->Name());
    return names;
  });
}

/// Exposes every registered variable and flag as a module attribute (mc.DISPLACEMENT, mc.ACTIVE).
/// Called at import and again after a plugin registers more.
void ExportRegisteredNames(py::module_& m) {
  const auto& registry = VariableRegistry::Instance();
  for (std::size_t key = 0; key < registry.Size(); ++key) {
    const VariableData& var = registry.GetByKey(key);
    m.attr(var.Name().c_str()) = py::cast(&var, py::return_value_policy::reference);
  }
  for (const Flag* f : Flag::All()) m.attr(f->Name().c_str()) = py::cast(f, py::return_value_policy::reference);
}

}  // namespace mc::python
