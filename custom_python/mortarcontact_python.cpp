// SPDX-License-Identifier: BSD-3-Clause
// The extension module `mortarcontact._core`.
#include "custom_python/python_module.h"

#include <cstdlib>
#include <string>

#include "core/utilities/heap_tuning.h"

namespace py = pybind11;

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

  mc::python::AddVariablesToPython(m);
  mc::python::AddParametersToPython(m);
  mc::python::AddGeometriesToPython(m);
  mc::python::AddModelToPython(m);
  mc::python::AddIoToPython(m);
  mc::python::AddLinearSolversToPython(m);
  mc::python::AddSolvingToPython(m);
  mc::python::AddStructuralToPython(m);
  mc::python::AddUtilitiesToPython(m);
  mc::python::AddContactConditionsToPython(m);
  mc::python::AddContactProcessesToPython(m);
  mc::python::AddContactStrategiesToPython(m);
  mc::python::AddContactLinearSolversToPython(m);
  mc::python::AddContactFormulationsToPython(m);
  mc::python::ExportRegisteredNames(m);
  m.def("ExportRegisteredNames", [m]() mutable { mc::python::ExportRegisteredNames(m); },
        "Re-exports registered variables and flags as module attributes (after loading a plugin).");
}
