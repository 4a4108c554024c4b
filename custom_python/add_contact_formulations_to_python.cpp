// SPDX-License-Identifier: BSD-3-Clause
// Bindings of custom_formulations: the registry of contact formulations (mortar_type).
#include "custom_formulations/contact_formulation.h"
#include "custom_formulations/register_contact_formulations.h"
#include "custom_python/python_module.h"

namespace mc::python {

void AddContactFormulationsToPython(py::module_& m) {
  RegisterContactFormulations();
  py::class_<ContactFormulation>(
      m, "ContactFormulation",
      "A mortar contact formulation registered under its Kratos mortar_type: its variables and DoFs, pair "
      "conditions, active-set criterion, multiplier blocks and whether MixedULM can condense it.")
      .def_static("Get", &ContactFormulation::Get, py::arg("mortar_type"), py::arg("where") = "mortar_type",
                  py::return_value_policy::reference,
                  "The formulation of a contact_settings.mortar_type (the registered name or the longest one it "
                  "starts with); InputError with the nearest names when unknown, NotImplementedFeatureError when "
                  "not implemented yet.")
      .def_static("OfProcess", &ContactFormulation::OfProcess, py::arg("process"), py::arg("contact_type"),
                  py::arg("where") = "contact_type", py::return_value_policy::reference,
                  "The formulation of a contact process (python_module) and its contact_type.")
      .def_static("Names", &ContactFormulation::Names, "Every registered mortar_type, implemented or not, sorted.")
      .def_static("ContactTypes", &ContactFormulation::ContactTypes, py::arg("process"),
                  "The contact_type values a contact process accepts.")
      .def_property_readonly("mortar_type", &ContactFormulation::MortarType,
                             "Its contact_settings.mortar_type, e.g. 'ALMContactFrictionless'.")
      .def_property_readonly(
          "process", [](const ContactFormulation& f) { return f.Describe().process; },
          "python_module of its contact process, e.g. 'alm_contact_process'.")
      .def_property_readonly(
          "contact_type", [](const ContactFormulation& f) { return f.Describe().contact_type; },
          "That process' contact_type, e.g. 'Frictionless'.")
      .def_property_readonly(
          "variables", [](const ContactFormulation& f) { return f.Describe().variables; },
          "Nodal solution-step variables the solver adds.")
      .def_property_readonly(
          "dofs", [](const ContactFormulation& f) { return f.Describe().dofs; }, "(DoF, reaction) variable names.")
      .def_property_readonly(
          "multiplier", [](const ContactFormulation& f) { return f.Describe().multiplier; },
          "The nodal multiplier variable ('' without multipliers).")
      .def_property_readonly(
          "multiplier_blocks", [](const ContactFormulation& f) { return f.Describe().multiplier_blocks; },
          "Multiplier blocks of the contact convergence criteria (0: none).")
      .def_property_readonly(
          "condensable", [](const ContactFormulation& f) { return f.Describe().condensable; },
          "Whether the MixedULM solver can condense its multipliers.")
      .def_property_readonly("frictional", &ContactFormulation::IsFrictional,
                             "Coulomb friction: SLIP and FRICTION_COEFFICIENT matter, the model part carries SLIP.")
      .def_property_readonly(
          "pure_slip", [](const ContactFormulation& f) { return f.Describe().pure_slip; },
          "Every active node slips (the 'PureSlip' formulations).")
      .def_property_readonly(
          "buffer_size", [](const ContactFormulation& f) { return f.Describe().buffer_size; },
          "Smallest nodal history (buffer_size) the formulation needs.")
      .def("ConditionStem", &ContactFormulation::ConditionStem, py::arg("normal_variation"), py::arg("axisymmetric"),
           "Name stem of its pair conditions, e.g. 'ALMNVFrictionlessMortarContactCondition'.")
      .def("CreateActiveSetCriterion", &ContactFormulation::CreateActiveSetCriterion, py::arg("contact_settings"),
           "Its mortar (active-set) criterion, reading its keys from contact_settings.");
}

}  // namespace mc::python
