// SPDX-License-Identifier: BSD-3-Clause
#include "core/parameters/no_effect_warnings.h"
#include "core/parameters/parameters.h"
#include "custom_python/python_module.h"

namespace mc::python {

void AddParametersToPython(py::module_& m) {
  py::class_<Parameters>(m, "Parameters",
                         "JSON settings with Kratos' validate-and-assign-defaults semantics (Kratos Parameters): a "
                         "view into a shared document, errors name the file and the dotted key path.")
      .def(py::init<>(), "An empty JSON object.")
      .def(py::init<const std::string&, std::string>(), py::arg("json_text"), py::arg("origin") = "",
           "Parses JSON text; origin (usually a file name) is quoted in errors, parse errors give line and column.")
      .def_static("FromFile", &Parameters::FromFile, py::arg("path"), "Reads and parses a JSON file.")
      .def("Has", &Parameters::Has, py::arg("key"), "Whether this object has the key.")
      .def("__getitem__", py::overload_cast<const std::string&>(&Parameters::operator[], py::const_), py::arg("key"),
           "Sub-view of a key (InputError with the nearest keys when absent).")
      .def("__getitem__", py::overload_cast<std::size_t>(&Parameters::operator[], py::const_), py::arg("index"),
           "Item of an array (InputError when out of range).")
      .def("__contains__", &Parameters::Has, py::arg("key"))
      .def("__len__", &Parameters::size)
      .def("size", &Parameters::size, "Number of keys of an object, or items of an array.")
      .def("keys", &Parameters::Keys, "The keys of an object, in order.")
      .def("Keys", &Parameters::Keys, "The keys of an object, in order.")
      .def(
          "values",
          [](const Parameters& p) {
            std::vector<Parameters> out;
            if (p.IsArray()) {
              for (std::size_t i = 0; i < p.size(); ++i) out.push_back(p[i]);
            } else {
              for (const auto& k : p.Keys()) out.push_back(p[k]);
            }
            return out;
          },
          "Sub-views of the values of an object, or of the items of an array.")
      .def(
          "items",
          [](const Parameters& p) {
            std::vector<std::pair<std::string, Parameters>> out;
            for (const auto& k : p.Keys()) out.emplace_back(k, p[k]);
            return out;
          },
          "(key, sub-view) pairs of an object.")
      .def("__iter__",
           [](const Parameters& p) {
             py::list items;
             if (p.IsArray()) {
               for (std::size_t i = 0; i < p.size(); ++i) items.append(p[i]);
             } else {
               for (const auto& k : p.Keys()) items.append(k);
             }
             return py::iter(items);
           })
      .def("Path", &Parameters::Path, "Dotted path of this view inside its document ('' for the root).")
      .def("Where", &Parameters::Where, "The 'file: path' prefix of error messages about this view.")
      .def("IsNull", &Parameters::IsNull, "Whether the value is null.")
      .def("IsNumber", &Parameters::IsNumber, "Whether the value is a number (int or float).")
      .def("IsDouble", &Parameters::IsDouble,
           "Whether the value is a floating-point number (written with a decimal point or exponent).")
      .def("IsInt", &Parameters::IsInt, "Whether the value is an integer.")
      .def("IsBool", &Parameters::IsBool, "Whether the value is a boolean.")
      .def("IsString", &Parameters::IsString, "Whether the value is a string.")
      .def("IsArray", &Parameters::IsArray, "Whether the value is an array.")
      .def("IsVector", &Parameters::IsVector, "Whether the value is an array of numbers.")
      .def("IsMatrix", &Parameters::IsMatrix, "Whether the value is an array of equally long arrays of numbers.")
      .def("IsSubParameter", &Parameters::IsSubParameter, "Whether the value is a JSON object.")
      .def("IsStringArray", &Parameters::IsStringArray, "Whether the value is an array of strings.")
      .def("GetDouble", &Parameters::GetDouble, "The value as a float (InputError naming path and types otherwise).")
      .def("GetInt", &Parameters::GetInt, "The value as an integer (InputError naming path and types otherwise).")
      .def("GetBool", &Parameters::GetBool, "The value as a boolean (InputError naming path and types otherwise).")
      .def("GetString", &Parameters::GetString, "The value as a string (InputError naming path and types otherwise).")
      .def("GetVector", &Parameters::GetVector, "An array of numbers as a numpy vector.")
      .def("GetMatrix", &Parameters::GetMatrix, "An array of equally long arrays of numbers as a numpy matrix.")
      .def("GetStringArray", &Parameters::GetStringArray, "An array of strings as a list.")
      .def("SetDouble", &Parameters::SetDouble, py::arg("value"), "Replaces the value by a float.")
      .def("SetInt", &Parameters::SetInt, py::arg("value"), "Replaces the value by an integer.")
      .def("SetBool", &Parameters::SetBool, py::arg("value"), "Replaces the value by a boolean.")
      .def("SetString", &Parameters::SetString, py::arg("value"), "Replaces the value by a string.")
      .def("SetVector", &Parameters::SetVector, py::arg("value"), "Replaces the value by an array of numbers.")
      .def("SetMatrix", &Parameters::SetMatrix, py::arg("value"), "Replaces the value by an array of arrays.")
      .def("SetStringArray", &Parameters::SetStringArray, py::arg("value"),
           "Replaces the value by an array of strings.")
      .def("SetValue", py::overload_cast<const Parameters&>(&Parameters::SetValue), py::arg("value"),
           "Replaces the value by a deep copy of another's.")
      .def("SetValue", py::overload_cast<const std::string&, const Parameters&>(&Parameters::SetValue), py::arg("key"),
           py::arg("value"), "Replaces the value of an existing key (InputError if absent).")
      .def("AddValue", &Parameters::AddValue, py::arg("key"), py::arg("value"),
           "Adds a deep copy of value under key (overwrites an existing one).")
      .def("AddEmptyValue", &Parameters::AddEmptyValue, py::arg("key"),
           "Adds a null value under key, to be set (keeps an existing one).")
      .def("AddEmptyArray", &Parameters::AddEmptyArray, py::arg("key"), "Adds an empty array under key.")
      .def("Append", &Parameters::Append, py::arg("value"),
           "Appends a deep copy of value to an array (views of its items become invalid).")
      .def("RemoveValue", &Parameters::RemoveValue, py::arg("key"), "Removes a key; whether it was there.")
      .def("Clone", &Parameters::Clone, "An independent deep copy, keeping origin and path for error messages.")
      .def("ValidateAndAssignDefaults", &Parameters::ValidateAndAssignDefaults, py::arg("defaults"),
           "Rejects keys not in defaults (naming the nearest) and values of another type; copies missing keys.")
      .def("RecursivelyValidateAndAssignDefaults", &Parameters::RecursivelyValidateAndAssignDefaults,
           py::arg("defaults"),
           "ValidateAndAssignDefaults, and recursively in sub-objects whose default is a non-empty object.")
      .def("AddMissingParameters", &Parameters::AddMissingParameters, py::arg("defaults"),
           "Copies missing keys from defaults without rejecting unknown ones.")
      .def("RecursivelyAddMissingParameters", &Parameters::RecursivelyAddMissingParameters, py::arg("defaults"),
           "AddMissingParameters, recursively in sub-objects.")
      .def("CheckKeys", &Parameters::CheckKeys, py::arg("valid_keys"),
           "InputError for a key not in valid_keys, with the nearest valid key.")
      .def("WriteJsonString", &Parameters::WriteJsonString, "Compact JSON text.")
      .def("PrettyPrintJsonString", &Parameters::PrettyPrintJsonString, "Indented JSON text.")
      .def("__repr__", &Parameters::PrettyPrintJsonString);

  py::class_<NoEffectWarnings>(m, "NoEffectWarnings",
                               "The one route for accepted settings that have no effect here: \"key 'X' = value at "
                               "<file>: <path> has no effect in mortarcontact: <why>\" through the C++ log, once per "
                               "key per run.")
      .def_static("IfGiven", &NoEffectWarnings::IfGiven, py::arg("settings"), py::arg("defaults"), py::arg("key"),
                  py::arg("why"),
                  "Warns when settings[key] differs from defaults[key] (a template default stays quiet); "
                  "returns whether it differs.")
      .def_static("Warn", &NoEffectWarnings::Warn, py::arg("settings"), py::arg("key"), py::arg("why"),
                  "Warns whatever the value (a value that runs as another one).")
      .def_static("Reset", &NoEffectWarnings::Reset,
                  "Forgets the keys already reported: a new run reports them again.");
}

}  // namespace mc::python
