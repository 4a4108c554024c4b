// SPDX-License-Identifier: BSD-3-Clause
// Bindings of the contact interface set-up, search, ALM parameter, mesh-tying and mortar mapping processes.
#include "core/model/model_part.h"
#include "core/parameters/parameters.h"
#include "custom_processes/alm_variables_calculation_process.h"
#include "custom_processes/contact_interface_builder.h"
#include "custom_processes/contact_search_process.h"
#include "custom_processes/mesh_tying_utilities.h"
#include "custom_processes/simple_mortar_mapper_process.h"
#include "custom_python/python_module.h"
#include "custom_utilities/contact_output_utilities.h"

namespace mc::python {

void AddContactProcessesToPython(py::module_& m) {
  py::class_<ContactInterfaceBuilder>(m, "ContactInterfaceBuilder",
                                      "Builds Contact.ContactSub<k> and ComputingContact for one interface slot "
                                      "(spec 4.2): interface conditions, SLAVE / MASTER flags, property, NODAL_H, "
                                      "normals and their checks.")
      .def(py::init<ModelPart&>(), py::arg("root"), py::keep_alive<1, 2>(), "A builder under the root model part.")
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
          py::return_value_policy::reference,
          "Builds (or reuses unless the root is MODIFIED) the slot's interface from the parts (contact_model_part), "
          "their slave ones (assume_master_slave; empty: automatic roles), property id (0: 100 + slot), friction "
          "coefficient and normal_check_proportion; returns Contact.ContactSub<slot>.")
      .def_static("InterfaceProperties", &ContactInterfaceBuilder::InterfaceProperties, py::arg("root"),
                  py::arg("slot"), py::return_value_policy::reference,
                  "The properties of a slot's interface (after Build).")
      .def_static("ComputeNodalH", &ContactInterfaceBuilder::ComputeNodalH, py::arg("root"), py::arg("part"),
                  "NODAL_H of every node of part: the smallest distance to another node of an element holding it "
                  "(Kratos' nodal length).");

  py::class_<ContactSearchProcess>(m, "ContactSearchProcess",
                                   "Contact search of one interface slot (spec 4.3; Kratos "
                                   "BaseContactSearchProcess): creates the pair conditions and predicts the active "
                                   "set.")
      .def(py::init([](ModelPart& root, ModelPart& interface, Parameters search_parameters, std::string slot,
                       std::string condition_name, bool predefined_master_slave, int property_id,
                       std::string final_string) {
             return std::make_unique<ContactSearchProcess>(
                 root, interface, std::move(search_parameters),
                 ContactSearchSlot{std::move(slot), std::move(condition_name), std::move(final_string),
                                   predefined_master_slave, property_id});
           }),
           py::arg("root"), py::arg("interface"), py::arg("search_parameters"), py::arg("slot") = "0",
           py::arg("condition_name") = ContactSearchSlot{}.condition_name, py::arg("predefined_master_slave") = true,
           py::arg("property_id") = 0, py::arg("final_string") = "", py::keep_alive<1, 2>(), py::keep_alive<1, 3>(),
           "search_parameters: the contact process' block (validated here); slot: the interface slot; "
           "condition_name: pair-condition name stem; predefined_master_slave: roles from assume_master_slave; "
           "property_id: properties of the pairs (0: the slave condition's).")
      .def_static("GetDefaultParameters", &ContactSearchProcess::GetDefaultParameters,
                  "Kratos' search_parameters with their defaults.")
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
          "Clears the pairs, searches again and predicts the active set; returns statistics (counts of slave and "
          "master conditions, pairs, active and isolated nodes, search radii, seconds).")
      .def("ClearMortarConditions", &ContactSearchProcess::ClearMortarConditions,
           "Removes this slot's pair conditions.")
      .def("FindBodies", &ContactSearchProcess::FindBodies,
           "Finds the bodies the interface's faces lie on now, on the whole model, before it is cut across the "
           "ranks (the first search does it otherwise).")
      .def("SetBodies", &ContactSearchProcess::SetBodies, py::arg("body_of"), py::arg("labels"),
           "The bodies found on the mesh file before a rank read its piece (PlanModelPartPiece), instead of "
           "FindBodies.")
      .def("SetInterfaceActive", &ContactSearchProcess::SetInterfaceActive, py::arg("active"),
           "Sets ACTIVE on the interface nodes, conditions and pairs (all inactive outside the process interval).")
      .def("InterfacePart", &ContactSearchProcess::InterfacePart, py::return_value_policy::reference,
           "The interface part Contact.ContactSub<slot>.")
      .def("ComputingPart", &ContactSearchProcess::ComputingPart, py::return_value_policy::reference,
           "The pairs' part ComputingContact.ComputingContactSub<slot>.")
      .def("SearchType", &ContactSearchProcess::SearchType, "Canonical search type, e.g. 'in_radius_with_obb'.")
      .def("CheckGap", &ContactSearchProcess::CheckGap, "Canonical gap check, e.g. 'mapping_check'.")
      .def("TotalSeconds", &ContactSearchProcess::TotalSeconds, "Wall-clock seconds of all searches so far.")
      .def("NumberOfSearches", &ContactSearchProcess::NumberOfSearches, "Number of searches so far.");

  py::class_<ALMVariablesCalculationProcess>(m, "ALMVariablesCalculationProcess",
                                             "Automatic ALM penalty and scale factor (thesis eq. 4.11).")
      .def(py::init<ModelPart&, ModelPart&, Parameters, double, double>(), py::arg("root"), py::arg("interface"),
           py::arg("settings"), py::arg("penalty_multiplier") = 1.0, py::arg("penalty_floor") = 1.0,
           py::keep_alive<1, 2>(), py::keep_alive<1, 3>(),
           "settings: the contact process' advance_ALM_parameters; penalty_multiplier / penalty_floor: 1 / 1 "
           "for ALM, 1e4 / 1e16 for penalty.")
      .def_static("GetDefaultParameters", &ALMVariablesCalculationProcess::GetDefaultParameters,
                  "stiffness_factor, penalty_scale_factor, use_scale_factor (Kratos' advance_ALM_parameters).")
      .def("Execute", &ALMVariablesCalculationProcess::Execute,
           "Computes both from E / h of the less stiff side; writes ProcessInfo INITIAL_PENALTY and SCALE_FACTOR "
           "and the nodal INITIAL_PENALTY.")
      .def("Penalty", &ALMVariablesCalculationProcess::Penalty, "The penalty of the last Execute (force / length^3).")
      .def("ScaleFactor", &ALMVariablesCalculationProcess::ScaleFactor, "The scale factor of the last Execute.");

  py::class_<MeshTyingUtilities>(m, "MeshTyingUtilities", "What the mesh-tying process does to its tied pairs.")
      .def_static("UpdateTiedSlaveNodes", &MeshTyingUtilities::UpdateTiedSlaveNodes, py::arg("computing_part"),
                  "Flags the tied slave nodes ACTIVE (for the MixedULM condensation), fixes to zero the tying "
                  "multipliers whose rows have no free DoF in any pair (Dirichlet conditions on both sides there) "
                  "and frees the others; returns how many were fixed.");

  py::class_<SimpleMortarMapperProcess>(
      m, "SimpleMortarMapperProcess",
      "Mortar mapping of a nodal scalar or array variable from an origin surface to a non-matching destination "
      "surface (Kratos' SimpleMortarMapperProcess settings; consistent or conservative, with or without D^-1).")
      .def(py::init<ModelPart&, ModelPart&, Parameters>(), py::arg("origin"), py::arg("destination"),
           py::arg("settings") = Parameters(), py::keep_alive<1, 2>(), py::keep_alive<1, 3>(),
           "A mapper between the faces of the two model parts; settings are validated against the defaults.")
      .def_static("GetDefaultParameters", &SimpleMortarMapperProcess::GetDefaultParameters,
                  "Kratos' keys and defaults, plus conservative (false) and inverse_of_d (true).")
      .def("Execute", &SimpleMortarMapperProcess::Execute, "Maps the current values of origin_variable.")
      .def("NumberOfPairs", &SimpleMortarMapperProcess::NumberOfPairs, "Overlapping pairs of the last Execute.")
      .def("NumberOfMappedNodes", &SimpleMortarMapperProcess::NumberOfMappedNodes,
           "Destination nodes reached by an overlap in the last Execute.");

  m.def("ComputeContactOutputs", &ComputeContactOutputs, py::arg("part"), py::arg("clear_inactive"),
        "The contact tractions, forces and gaps of the slave nodes at the end of a converged step; with "
        "clear_inactive, zero augmented tractions at the inactive ones. Returns the slave nodes visited.");
  m.def("ClearInactiveContactPressures", &ClearInactiveContactPressures, py::arg("part"),
        "Zero augmented tractions at the inactive slave nodes (clear_inactive_for_post alone).");
}

}  // namespace mc::python
