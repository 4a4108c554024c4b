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
      .def(py::init<const std::string&>(), py::arg("expression"))
      .def("Evaluate", &FunctionExpression::Evaluate, py::arg("x"), py::arg("y"), py::arg("z"), py::arg("t"),
           py::arg("X") = 0.0, py::arg("Y") = 0.0, py::arg("Z") = 0.0)
      .def("DependsOnSpace", &FunctionExpression::DependsOnSpace)
      .def("DependsOnTime", &FunctionExpression::DependsOnTime)
      .def("Text", &FunctionExpression::Text);

  py::class_<VariableUtils>(m, "VariableUtils")
      .def_static("AssignNodalScalar",
                  [](ModelPart& p, const VariableData& v, const FunctionExpression& e, double t, bool fix) {
                    VariableUtils::AssignNodalScalar(p, AsDouble(v), e, t, fix);
                  }, py::arg("model_part"), py::arg("variable"), py::arg("expression"), py::arg("time"), py::arg("fix"))
      .def_static("AssignNodalScalar",
                  [](ModelPart& p, const VariableData& v, double value, bool fix) {
                    VariableUtils::AssignNodalScalar(p, AsDouble(v), value, fix);
                  }, py::arg("model_part"), py::arg("variable"), py::arg("value"), py::arg("fix"))
      .def_static("FreeDof", [](ModelPart& p, const VariableData& v) { VariableUtils::FreeDof(p, AsDouble(v)); })
      .def_static("AssignConditionScalar",
                  [](ModelPart& p, const VariableData& v, const FunctionExpression& e, double t) {
                    VariableUtils::AssignConditionScalar(p, AsDouble(v), e, t);
                  }, py::arg("model_part"), py::arg("variable"), py::arg("expression"), py::arg("time"))
      .def_static("AssignConditionScalar",
                  [](ModelPart& p, const VariableData& v, double value) {
                    VariableUtils::AssignConditionScalar(p, AsDouble(v), value);
                  }, py::arg("model_part"), py::arg("variable"), py::arg("value"))
      .def_static("AddDof", [](ModelPart& p, const VariableData& v, const VariableData* r) {
        VariableUtils::AddDof(p, AsDouble(v), r ? &AsDouble(*r) : nullptr);
      }, py::arg("model_part"), py::arg("variable"), py::arg("reaction") = nullptr)
      .def_static("UpdateCurrentPosition", &VariableUtils::UpdateCurrentPosition);

  py::enum_<Logger::Level>(m, "LogLevel")
      .value("Info", Logger::Level::Info)
      .value("Warning", Logger::Level::Warning)
      .value("Detail", Logger::Level::Detail);
  m.def("SetLogSink", [](py::function sink) {
    Logger::SetSink([sink](Logger::Level level, const std::string& message) {
      py::gil_scoped_acquire gil;
      sink(level, message);
    });
  }, "Routes C++ log messages to a Python callable(level, message).");
  m.def("ResetLogSink", &Logger::ResetSink);
}

}  // namespace mc::python
