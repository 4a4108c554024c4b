// SPDX-License-Identifier: BSD-3-Clause
#include "core/processes/variable_utils.h"
#include "core/utilities/function_expression.h"
#include "core/utilities/logger.h"
#include "custom_python/python_module.h"

namespace mc::python {

namespace {
const Variable<double>& AsDouble(const VariableData& var) {
  if (var.Type() != ValueType::Double)
    throw InputError(Concat(var.Name(), " is not a scalar (double) variable or component"));
  return static_cast<const Variable<double>&>(var);
}
}  // namespace

void AddUtilitiesToPython(py::module_& m) {
  py::class_<FunctionExpression>(m, "FunctionExpression",
                                 "A compiled expression of x, y, z, X, Y, Z and t (muparser; never Python eval).")
      .def(py::init<const std::string&>(), py::arg("expression"),
           "Compiles a Kratos expression, e.g. '-0.15*t'; InputError quoting the position of a mistake.")
      .def("Evaluate", &FunctionExpression::Evaluate, py::arg("x"), py::arg("y"), py::arg("z"), py::arg("t"),
           py::arg("X") = 0.0, py::arg("Y") = 0.0, py::arg("Z") = 0.0,
           "Value at current coordinates (x, y, z), time t and initial coordinates (X, Y, Z).")
      .def("DependsOnSpace", &FunctionExpression::DependsOnSpace, "Whether it uses x, y, z, X, Y or Z.")
      .def("DependsOnTime", &FunctionExpression::DependsOnTime, "Whether it uses t.")
      .def("Text", &FunctionExpression::Text, "The expression as written.");

  py::class_<VariableUtils>(m, "VariableUtils",
                            "Bulk operations on the nodes and conditions of a model part (Kratos VariableUtils), for "
                            "the assignment processes.")
      .def_static(
          "AssignNodalScalar",
          [](ModelPart& p, const VariableData& v, const FunctionExpression& e, double t, bool fix) {
            VariableUtils::AssignNodalScalar(p, AsDouble(v), e, t, fix);
          },
          py::arg("model_part"), py::arg("variable"), py::arg("expression"), py::arg("time"), py::arg("fix"),
          "Sets a historical double (or component) on every node to the expression at (x, y, z, time); "
          "with fix, fixes its DoF.")
      .def_static(
          "AssignNodalScalar",
          [](ModelPart& p, const VariableData& v, double value, bool fix) {
            VariableUtils::AssignNodalScalar(p, AsDouble(v), value, fix);
          },
          py::arg("model_part"), py::arg("variable"), py::arg("value"), py::arg("fix"),
          "Sets a historical double (or component) on every node to value; with fix, fixes its DoF.")
      .def_static(
          "FreeDof", [](ModelPart& p, const VariableData& v) { VariableUtils::FreeDof(p, AsDouble(v)); },
          py::arg("model_part"), py::arg("variable"), "Frees the DoF of the variable on every node having it.")
      .def_static(
          "AssignConditionScalar",
          [](ModelPart& p, const VariableData& v, const FunctionExpression& e, double t) {
            VariableUtils::AssignConditionScalar(p, AsDouble(v), e, t);
          },
          py::arg("model_part"), py::arg("variable"), py::arg("expression"), py::arg("time"),
          "Sets a non-historical double (or component) on every condition to the expression at its centre.")
      .def_static(
          "AssignConditionScalar",
          [](ModelPart& p, const VariableData& v, double value) {
            VariableUtils::AssignConditionScalar(p, AsDouble(v), value);
          },
          py::arg("model_part"), py::arg("variable"), py::arg("value"),
          "Sets a non-historical double (or component) on every condition to value.")
      .def_static(
          "AddDof",
          [](ModelPart& p, const VariableData& v, const VariableData* r) {
            VariableUtils::AddDof(p, AsDouble(v), r ? &AsDouble(*r) : nullptr);
          },
          py::arg("model_part"), py::arg("variable"), py::arg("reaction") = nullptr,
          "Adds the DoF of the variable (with its reaction) to every node.")
      .def_static("UpdateCurrentPosition", &VariableUtils::UpdateCurrentPosition, py::arg("model_part"),
                  "Sets every node's current coordinates to X0 + DISPLACEMENT.");

  py::enum_<Logger::Level>(m, "LogLevel", "Level of a message of the C++ log.")
      .value("Info", Logger::Level::Info, "progress and results")
      .value("Warning", Logger::Level::Warning, "something the user should look at")
      .value("Detail", Logger::Level::Detail, "verbose output (echo levels above 1)");
  m.def(
      "SetLogSink",
      [](py::function sink) {
        Logger::SetSink([sink](Logger::Level level, const std::string& message) {
          py::gil_scoped_acquire gil;
          sink(level, message);
        });
      },
      py::arg("sink"), "Routes C++ log messages to a Python callable(level, message).");
  m.def("ResetLogSink", &Logger::ResetSink, "Routes C++ log messages to stdout / stderr again.");
}

}  // namespace mc::python
