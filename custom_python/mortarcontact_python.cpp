// SPDX-License-Identifier: BSD-3-Clause
// The extension module `mortarcontact._core`.
#include "custom_python/python_module.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "core/utilities/heap_tuning.h"

namespace py = pybind11;
using namespace mc::python;

namespace {

/// A binding area: the submodule `_core.<name>`, bound by custom_python/add_<name>_to_python.cpp.
struct Area {
  const char* name;
  const char* doc;
  void (*add)(py::module_&);
};

/// Binds each area into its submodule, then makes the submodules' public names attributes of
/// `_core` too (`_core.ModelPart` is `_core.model.ModelPart`); two areas may not bind one name.
template <std::size_t N>
void AddAreas(py::module_& m, const Area (&areas)[N]) {
  for (const Area& area : areas) {
    py::module_ submodule = m.def_submodule(area.name, area.doc);
    area.add(submodule);
    for (const auto& [key, value] : py::dict(submodule.attr("__dict__"))) {
      const std::string name = py::str(key);
      if (name.starts_with("_")) continue;
      if (py::hasattr(m, name.c_str()))
        throw std::logic_error(mc::Concat("_core.", area.name, ".", name, " is bound by another area too"));
      m.attr(key) = value;
    }
  }
}

/// `__all__`: what `from _core import *` exports, the public names but not the submodules (whose
/// names are those of modules of the Python package: utilities, contact_processes, ...).
void ListPublicNames(py::module_& m) {
  py::list names;
  for (const auto& [key, value] : py::dict(m.attr("__dict__")))
    if (!py::str(key).cast<std::string>().starts_with("_") && !py::isinstance<py::module_>(value)) names.append(key);
  m.attr("__all__") = names;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "mortarcontact C++ core: kernel, structural substrate and solvers";

  const char* heap_tuning = std::getenv("MORTARCONTACT_HEAP_TUNING");
  const bool tuned = !(heap_tuning && std::string(heap_tuning) == "0") && mc::TuneHeapForRepeatedFactorizations();
  m.attr("HEAP_TUNED") = tuned;
  m.def("TuneHeapForRepeatedFactorizations", &mc::TuneHeapForRepeatedFactorizations,
        "Keep freed heap memory for the next factorization (glibc); applied on import unless "
        "MORTARCONTACT_HEAP_TUNING=0.");

  // User mistakes, missing features and failed solutions map to their own Python types so
  // that the command line can print them without a traceback.
  static py::exception<mc::Error> error(m, "Error", PyExc_RuntimeError);
  static py::exception<mc::InputError> input_error(m, "InputError", error.ptr());
  static py::exception<mc::NotImplementedError> not_implemented(m, "NotImplementedFeatureError", error.ptr());
  static py::exception<mc::SolutionError> solution_error(m, "SolutionError", error.ptr());
  error.doc() = "Base of every error raised by mortarcontact (a RuntimeError).";
  input_error.doc() = "A mistake in the input (files, settings, names, values); the message names where and what.";
  not_implemented.doc() = "A documented option that this version does not implement yet.";
  solution_error.doc() = "A solution that could not be computed: singular system, non-convergence, inverted element.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const mc::InputError& e) {
      py::set_error(input_error, e.what());
    } catch (const mc::NotImplementedError& e) {
      py::set_error(not_implemented, e.what());
    } catch (const mc::SolutionError& e) {
      py::set_error(solution_error, e.what());
    } catch (const mc::Error& e) {
      py::set_error(error, e.what());
    }
  });

  // One submodule per binding area, in layer order: a base class is bound before the classes
  // derived from it (pybind11's type registry is global, so areas use each other's types).
  static constexpr Area areas[] = {
      {"variables", "Variables, components and flags (core/variables).", &AddVariablesToPython},
      {"parameters", "JSON settings with defaults and validation (core/parameters).", &AddParametersToPython},
      {"geometries", "Geometries: shape functions, quadrature, normals (core/geometries).", &AddGeometriesToPython},
      {"model", "Model, model parts, nodes, DoFs, properties, elements and conditions (core/model).",
       &AddModelToPython},
      {"io", "Kratos .mdpa and materials.json reading and writing (core/io).", &AddIoToPython},
      {"linear_solvers", "Sparse linear solvers created from linear_solver_settings (core/linear_solvers).",
       &AddLinearSolversToPython},
      {"solving", "Schemes, convergence criteria, builder-and-solvers and strategies (core/solving).",
       &AddSolvingToPython},
      {"structural", "Registration of the structural elements, conditions and laws (structural/).",
       &AddStructuralToPython},
      {"thermal", "Registration of the heat conduction elements (thermal/).", &AddThermalToPython},
      {"utilities", "Function expressions, nodal assignments and the log sink (core/utilities, core/processes).",
       &AddUtilitiesToPython},
      {"contact_utilities", "Normals of contact interfaces and the MortarUpdater hook (custom_utilities).",
       &AddContactUtilitiesToPython},
      {"contact_conditions", "Mortar contact pair conditions (custom_conditions).", &AddContactConditionsToPython},
      {"contact_processes", "Contact interface set-up, search, ALM parameters and outputs (custom_processes).",
       &AddContactProcessesToPython},
      {"contact_strategies",
       "Contact convergence criteria, the contact mortar updater and contact strategies "
       "(custom_strategies).",
       &AddContactStrategiesToPython},
      {"contact_linear_solvers", "The mixed ULM linear solver: condensed dual multipliers (custom_linear_solvers).",
       &AddContactLinearSolversToPython},
      {"contact_formulations", "The registry of contact formulations by mortar_type (custom_formulations).",
       &AddContactFormulationsToPython},
  };
  AddAreas(m, areas);
  ExportRegisteredNames(m);
  m.def(
      "ExportRegisteredNames",
      [m]() mutable {
        ExportRegisteredNames(m);
        ListPublicNames(m);
      },
      "Re-exports registered variables and flags as module attributes (after loading a plugin).");
  ListPublicNames(m);
}
