// SPDX-License-Identifier: BSD-3-Clause
// Shared declarations of the binding translation units (one per area).
#pragma once

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <functional>
#include <memory>

#include "core/utilities/error.h"
#include "core/variables/data_value_container.h"
#include "core/variables/variable.h"

namespace mc::python {

namespace py = pybind11;

void AddVariablesToPython(py::module_& m);
void AddParametersToPython(py::module_& m);
void AddModelToPython(py::module_& m);
void AddGeometriesToPython(py::module_& m);
void AddIoToPython(py::module_& m);
void AddLinearSolversToPython(py::module_& m);
void AddSolvingToPython(py::module_& m);
void AddStructuralToPython(py::module_& m);
void AddThermalToPython(py::module_& m);
void AddUtilitiesToPython(py::module_& m);
void AddContactUtilitiesToPython(py::module_& m);
void AddContactProcessesToPython(py::module_& m);
void AddContactConditionsToPython(py::module_& m);
void AddContactStrategiesToPython(py::module_& m);
void AddContactLinearSolversToPython(py::module_& m);
void AddContactFormulationsToPython(py::module_& m);
void ExportRegisteredNames(py::module_& m);

/// Runs f with the GIL released: strategy calls assemble and solve in OpenMP threads, and the
/// log sink or Python callbacks take the GIL back when they need it.
template <class F>
auto WithoutGil(F&& f) {
  py::gil_scoped_release release;
  return f();
}

/// A std::function calling a Python callable with the GIL held, its arguments passed by reference
/// (an empty function for None): C++ hooks set from Python.
template <class... Args>
std::function<void(Args&...)> PythonCallback(py::object callable) {
  if (callable.is_none()) return {};
  auto shared = std::make_shared<py::object>(std::move(callable));
  return [shared](Args&... args) {
    py::gil_scoped_acquire gil;
    (*shared)(py::cast(&args, py::return_value_policy::reference)...);
  };
}

/// A Python value for a value of any variable type.
inline py::object ToPython(const DataValueContainer::Value& value) {
  return std::visit([](const auto& v) -> py::object { return py::cast(v); }, value);
}

/// Converts a Python value to the type of `var` (numbers, sequences of 3, arrays, matrices).
inline DataValueContainer::Value FromPython(const VariableData& var, const py::handle& obj) {
  try {
    switch (var.Type()) {
      case ValueType::Double: return obj.cast<double>();
      case ValueType::Int: return obj.cast<int>();
      case ValueType::Bool: return obj.cast<bool>();
      case ValueType::String: return obj.cast<std::string>();
      case ValueType::Array3: {
        const Vector v = obj.cast<Vector>();
        if (v.size() != 3) throw InputError(Concat(var.Name(), " expects 3 components, got ", v.size()));
        return Array3(v);
      }
      case ValueType::Vector: return obj.cast<Vector>();
      case ValueType::Matrix: return obj.cast<Matrix>();
    }
  } catch (const py::cast_error&) {
    throw InputError(Concat(var.Name(), " expects a ", ValueTypeName(var.Type()), ", got ", std::string(py::str(obj))));
  }
  throw InputError(Concat("unsupported type of ", var.Name()));
}

/// Generic getter / setter of non-historical data for any container-like owner.
template <class Owner>
py::object GetGeneric(const Owner& owner, const VariableData& var) {
  switch (var.Type()) {
    case ValueType::Double: return py::cast(owner.GetValue(static_cast<const Variable<double>&>(var)));
    case ValueType::Int: return py::cast(owner.GetValue(static_cast<const Variable<int>&>(var)));
    case ValueType::Bool: return py::cast(owner.GetValue(static_cast<const Variable<bool>&>(var)));
    case ValueType::String: return py::cast(owner.GetValue(static_cast<const Variable<std::string>&>(var)));
    case ValueType::Array3: return py::cast(owner.GetValue(static_cast<const Variable<Array3>&>(var)));
    case ValueType::Vector: return py::cast(owner.GetValue(static_cast<const Variable<Vector>&>(var)));
    case ValueType::Matrix: return py::cast(owner.GetValue(static_cast<const Variable<Matrix>&>(var)));
  }
  return py::none();
}

}  // namespace mc::python
