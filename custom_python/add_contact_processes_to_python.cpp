// SPDX-License-Identifier: BSD-3-Clause
// Bindings of the contact interface set-up, search and ALM parameter processes.
#include "core/model/model_part.h"
#include "core/parameters/parameters.h"
#include "custom_processes/alm_variables_calculation_process.h"
#include "custom_processes/contact_interface_builder.h"
#include "custom_processes/contact_output_utilities.h"
#include "custom_processes/contact_search_process.h"
#include "custom_python/python_module.h"
#include "custom_utilities/normal_calculation_utilities.h"

namespace mc::python {

void AddContactProcessesToPython(py::module_& m) {
  py::class_<ContactInterfaceBuilder>(m, "ContactInterfaceBuilder",
                                      "Builds Contact.ContactSub<k> and ComputingContact for one interface slot.")
      .def(py::init<ModelPart&>(), py::arg("root"), py::keep_alive<1, 2>())
      .def(
          "Build",
          [](ContactInterfaceBuilder& self, const std::string& slot, std::vector<std::string> parts,
             std::vector<std::string> slave_parts, int property_id, double friction_coefficient,
             double normal_check_proportion) -> ModelPart& {
            ContactInterfaceSettings settings;
            settings.slot = slot;
            settings.parts = std::move(parts);
            settings.slave_parts = std::move(slave_parts);
            settings.property_id = property_id;
            settings.friction_coefficient = friction_coefficient;
            settings.normal_check_proportion = normal_check_proportion;
            return self.Build(settings);
          },
          py::arg("slot"), py::arg("parts"), py::arg("slave_parts"), py::arg("property_id") = 0,
          py::arg("friction_coefficient") = 0.0, py::arg("normal_check_proportion") = 0.1,
          py::return_value_policy::reference, "Returns the interface part Contact.ContactSub<slot>.")
      .def_static("InterfaceProperties", &ContactInterfaceBuilder::InterfaceProperties, py::arg("root"),
                  py::arg("slot"), py::return_value_policy::reference)
      .def_static("ComputeNodalH", &ContactInterfaceBuilder::ComputeNodalH, py::arg("root"), py::arg("part"));

  py::class_<ContactSearchProcess>(m, "ContactSearchProcess",
                                   "Contact search of one interface slot: creates the pair conditions.")
      .def(py::init<ModelPart&, ModelPart&, Parameters>(), py::arg("root"), py::arg("interface"),
           py::arg("settings"), py::keep_alive<1, 2>(), py::keep_alive<1, 3>())
      .def_static("GetDefaultParameters", &ContactSearchProcess::GetDefaultParameters)
      .def(
          "UpdateMortarConditions",
          [](ContactSearchProcess& self) {
            const ContactSearchStatistics s = self.UpdateMortarConditions();
            py::dict stats;
            stats["slave_conditions"] = s.slave_conditions;
            stats["master_conditions"] = s.master_conditions;
            stats["pairs"] = s.pairs;
            stats["active_nodes"] = s.active_nodes;
            stats["isolated_nodes"] = s.isolated_nodes;
            stats["min_search_radius"] = s.min_search_radius;
            stats["max_search_radius"] = s.max_search_radius;
            stats["seconds"] = s.seconds;
            return stats;
          },
          "Clears the pairs, searches again and predicts the active set; returns statistics.")
      .def("ClearMortarConditions", &ContactSearchProcess::ClearMortarConditions)
      .def("SetInterfaceActive", &ContactSearchProcess::SetInterfaceActive, py::arg("active"))
      .def("InterfacePart", &ContactSearchProcess::InterfacePart, py::return_value_policy::reference)
      .def("ComputingPart", &ContactSearchProcess::ComputingPart, py::return_value_policy::reference)
      .def("SearchType", &ContactSearchProcess::SearchType)
      .def("CheckGap", &ContactSearchProcess::CheckGap)
      .def("TotalSeconds", &ContactSearchProcess::TotalSeconds, "Wall-clock seconds of all searches so far.")
      .def("NumberOfSearches", &ContactSearchProcess::NumberOfSearches);

  py::class_<ALMVariablesCalculationProcess>(m, "ALMVariablesCalculationProcess",
                                             "Automatic ALM penalty and scale factor (thesis eq. 4.11).")
      .def(py::init<ModelPart&, ModelPart&, Parameters>(), py::arg("root"), py::arg("interface"),
           py::arg("settings"), py::keep_alive<1, 2>(), py::keep_alive<1, 3>())
      .def_static("GetDefaultParameters", &ALMVariablesCalculationProcess::GetDefaultParameters)
      .def("Execute", &ALMVariablesCalculationProcess::Execute)
      .def("Penalty", &ALMVariablesCalculationProcess::Penalty)
      .def("ScaleFactor", &ALMVariablesCalculationProcess::ScaleFactor);

  py::class_<NormalCalculationUtilities>(m, "NormalCalculationUtilities")
      .def_static("ComputeNodalNormals", &NormalCalculationUtilities::ComputeNodalNormals, py::arg("part"))
      .def_static("ComputeConditionsNormals", &NormalCalculationUtilities::ComputeConditionsNormals, py::arg("part"));

  m.def("ComputeContactOutputs", &ComputeContactOutputs, py::arg("part"), py::arg("clear_inactive"),
        "The contact tractions, forces and gaps of the slave nodes at the end of a converged step; with "
        "clear_inactive, zero augmented tractions at the inactive ones. Returns the slave nodes visited.");
}

}  // namespace mc::python
