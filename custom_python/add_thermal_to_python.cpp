// SPDX-License-Identifier: BSD-3-Clause
#include "custom_python/python_module.h"
#include "thermal/application/register_thermal.h"

namespace mc::python {

void AddThermalToPython(py::module_& m) {
  m.def("RegisterThermal", &RegisterThermal,
        "Registers the heat conduction elements (LaplacianElement*) by name (idempotent; done at import).");
}

}  // namespace mc::python
