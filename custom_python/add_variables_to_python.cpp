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
void BindVariable(py::module_& m, const char* name, const char* doc) {
  py::class_<Variable<T>, VariableData>(m, name, doc);
}
}  // namespace

void AddVariablesToPython(py::module_& m) {
  py::enum_<ValueType>(m, "ValueType", "The value type a variable carries.")
      .value("Double", ValueType::Double, "a float")
      .value("Int", ValueType::Int, "an integer")
      .value("Bool", ValueType::Bool, "a boolean")
      .value("String", ValueType::String, "a string")
      .value("Array3", ValueType::Array3, "three floats (a vector in space, e.g. DISPLACEMENT)")
      .value("Vector", ValueType::Vector, "a vector of any size")
      .value("Matrix", ValueType::Matrix, "a dense matrix");

  py::class_<VariableData>(m, "VariableData",
                           "Name, key and value type of a registered variable (Kratos' VariableData); "
                           "module attributes such as DISPLACEMENT are instances.")
      .def("Name", &VariableData::Name, "The variable's name, e.g. 'DISPLACEMENT_X'.")
      .def("Key", &VariableData::Key, "Dense integer key given in registration order.")
      .def("Type", &VariableData::Type, "Its ValueType.")
      .def("IsComponent", &VariableData::IsComponent,
           "Whether it is a component of an Array3 variable (DISPLACEMENT_X of DISPLACEMENT).")
      .def("Source", &VariableData::Source, py::return_value_policy::reference,
           "The Array3 variable a component belongs to (None for a variable).")
      .def("ComponentIndex", &VariableData::ComponentIndex,
           "Index 0, 1 or 2 of a component in its source; -1 otherwise.")
      .def("__repr__", [](const VariableData& v) { return "<Variable " + v.Name() + ">"; })
      .def("__hash__", &VariableData::Key)
      .def(
          "__eq__", [](const VariableData& a, const VariableData& b) { return &a == &b; }, py::arg("other"));
  BindVariable<double>(m, "DoubleVariable", "A variable of floats, or a component of an Array3 variable.");
  BindVariable<int>(m, "IntVariable", "A variable of integers.");
  BindVariable<bool>(m, "BoolVariable", "A variable of booleans.");
  BindVariable<std::string>(m, "StringVariable", "A variable of strings.");
  BindVariable<Array3>(m, "Array3Variable", "A variable of 3-component vectors, with _X, _Y, _Z components.");
  BindVariable<Vector>(m, "VectorVariable", "A variable of vectors of any size.");
  BindVariable<Matrix>(m, "MatrixVariable", "A variable of dense matrices.");

  m.def(
      "GetVariable",
      [](const std::string& name) -> const VariableData& { return VariableRegistry::Instance().Get(name); },
      py::arg("name"), py::return_value_policy::reference,
      "The registered variable of this name (InputError with the nearest names otherwise).");
  m.def(
      "HasVariable", [](const std::string& name) { return VariableRegistry::Instance().Has(name); }, py::arg("name"),
      "Whether a variable of this name is registered.");
  m.def(
      "VariableNames", [] { return VariableRegistry::Instance().Names(); },
      "Names of all registered variables (kernel, structural, contact and plugins').");

  py::class_<Flag>(m, "Flag",
                   "A named boolean property of nodes, elements, conditions and model parts (ACTIVE, SLAVE, ...); "
                   "module attributes such as ACTIVE are instances.")
      .def("Name", &Flag::Name, "The flag's name, e.g. 'ACTIVE'.")
      .def("__repr__", [](const Flag& f) { return "<Flag " + f.Name() + ">"; });
  py::class_<Flags>(m, "Flags", "A set of flags, each set, reset (explicitly false) or undefined.")
      .def("Is", &Flags::Is, py::arg("flag"), "Whether the flag is set.")
      .def("IsDefined", &Flags::IsDefined, py::arg("flag"), "Whether the flag was set or reset.")
      .def("Set", &Flags::Set, py::arg("flag"), py::arg("value") = true, "Sets the flag to value (defines it).")
      .def("Reset", &Flags::Reset, py::arg("flag"), "Makes the flag undefined again (and false).");
  m.def("GetFlag", &Flag::Get, py::arg("name"), py::return_value_policy::reference,
        "The registered flag of this name (InputError with the nearest names otherwise).");
  m.def(
      "FlagNames",
      [] {
        std::vector<std::string> names;
        for (const Flag* f : Flag::All()) names.push_back(f->Name());
        return names;
      },
      "Names of all registered flags.");
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
