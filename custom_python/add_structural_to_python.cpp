// SPDX-License-Identifier: BSD-3-Clause
#include "custom_python/python_module.h"
#include "structural/application/register_structural_mechanics.h"

namespace mc::python {

void AddStructuralToPython(py::module_& m) {
  m.def("RegisterStructuralMechanics", &RegisterStructuralMechanics,
        "Registers the structural laws, elements and conditions by name (idempotent; done at import).");
}

}  // namespace mc::python
