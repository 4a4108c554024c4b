// SPDX-License-Identifier: BSD-3-Clause
#include "core/parameters/parameters.h"
#include "custom_python/python_module.h"

namespace mc::python {

void AddParametersToPython(py::module_& m) {
  py::class_<Parameters>(m, "Parameters", "JSON settings with Kratos' validate-and-assign-defaults semantics.")
      .def(py::init<>())
      .def(py::init<const std::string&, std::string>(), py::arg("json_text"), py::arg("origin") = "")
      .def_static("FromFile", &Parameters::FromFile, py::arg("path"))
      .def("Has", &Parameters::Has)
      .def("__getitem__", py::overload_cast<const std::string&>(&Parameters::operator[], py::const_))
      .def("__getitem__", py::overload_cast<std::size_t>(&Parameters::operator[], py::const_))
      .def("__contains__", &Parameters::Has)
      .def("__len__", &Parameters::size)
      .def("size", &Parameters::size)
      .def("keys", &Parameters::Keys)
      .def("Keys", &Parameters::Keys)
      .def("values", [](const Parameters& p) {
        std::vector<Parameters> out;
        if (p.IsArray()) {
          for (std::size_t i = 0; i < p.size(); ++i) out.push_back(p[i]);
        } else {
          for (const auto& k : p.Keys()) out.push_back(p[k]);
        }
        return out;
      })
      .def("items", [](const Parameters& p) {
        std::vector<std::pair<std::string, Parameters>> out;
        for (const auto& k : p.Keys()) out.emplace_back(k, p[k]);
        return out;
      })
      .def("__iter__", [](const Parameters& p) {
        py::list items;
        if (p.IsArray()) {
          for (std::size_t i = 0; i < p.size(); ++i) items.append(p[i]);
        } else {
          for (const auto& k : p.Keys()) items.append(k);
        }
        return py::iter(items);
      })
      .def("Path", &Parameters::Path)
      .def("Where", &Parameters::Where)
      .def("IsNull", &Parameters::IsNull)
      .def("IsNumber", &Parameters::IsNumber)
      .def("IsDouble", &Parameters::IsDouble)
      .def("IsInt", &Parameters::IsInt)
      .def("IsBool", &Parameters::IsBool)
      .def("IsString", &Parameters::IsString)
      .def("IsArray", &Parameters::IsArray)
      .def("IsVector", &Parameters::IsVector)
      .def("IsMatrix", &Parameters::IsMatrix)
      .def("IsSubParameter", &Parameters::IsSubParameter)
      .def("IsStringArray", &Parameters::IsStringArray)
      .def("GetDouble", &Parameters::GetDouble)
      .def("GetInt", &Parameters::GetInt)
      .def("GetBool", &Parameters::GetBool)
      .def("GetString", &Parameters::GetString)
      .def("GetVector", &Parameters::GetVector)
      .def("GetMatrix", &Parameters::GetMatrix)
      .def("GetStringArray", &Parameters::GetStringArray)
      .def("SetDouble", &Parameters::SetDouble)
      .def("SetInt", &Parameters::SetInt)
      .def("SetBool", &Parameters::SetBool)
      .def("SetString", &Parameters::SetString)
      .def("SetVector", &Parameters::SetVector)
      .def("SetMatrix", &Parameters::SetMatrix)
      .def("SetStringArray", &Parameters::SetStringArray)
      .def("SetValue", py::overload_cast<const Parameters&>(&Parameters::SetValue))
      .def("SetValue", py::overload_cast<const std::string&, const Parameters&>(&Parameters::SetValue))
      .def("AddValue", &Parameters::AddValue)
      .def("AddEmptyValue", &Parameters::AddEmptyValue)
      .def("AddEmptyArray", &Parameters::AddEmptyArray)
      .def("Append", &Parameters::Append)
      .def("RemoveValue", &Parameters::RemoveValue)
      .def("Clone", &Parameters::Clone)
      .def("ValidateAndAssignDefaults", &Parameters::ValidateAndAssignDefaults)
      .def("RecursivelyValidateAndAssignDefaults", &Parameters::RecursivelyValidateAndAssignDefaults)
      .def("AddMissingParameters", &Parameters::AddMissingParameters)
      .def("RecursivelyAddMissingParameters", &Parameters::RecursivelyAddMissingParameters)
      .def("CheckKeys", &Parameters::CheckKeys)
      .def("WriteJsonString", &Parameters::WriteJsonString)
      .def("PrettyPrintJsonString", &Parameters::PrettyPrintJsonString)
      .def("__repr__", &Parameters::PrettyPrintJsonString);
}

}  // namespace mc::python
