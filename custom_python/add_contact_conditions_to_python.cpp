// SPDX-License-Identifier: BSD-3-Clause
#include "core/model/model_part.h"
#include "custom_conditions/contact_condition_utilities.h"
#include "custom_conditions/paired_condition.h"
#include "custom_conditions/register_contact_conditions.h"
#include "custom_python/python_module.h"

namespace mc::python {

void AddContactConditionsToPython(py::module_& m) {
  m.def("RegisterContactConditions", &RegisterContactConditions,
        "Registers the mortar contact pair conditions (ALMFrictionless*, ALMFrictionlessComponents*, "
        "PenaltyFrictionless* MortarContactCondition{2D2N,3D3N,3D4N,3D3N4N,3D4N3N}; NV and Axisym names raise "
        "NotImplementedError when a pair is created). Idempotent.");
  m.def("ComputeExplicitContributions", &ContactConditionUtilities::ComputeExplicitContributions,
        py::arg("pairs_model_part"), py::arg("reset") = true,
        "Adds the weighted gap (WEIGHTED_GAP) and nodal area (NODAL_AREA) of every pair condition of the "
        "model part to its slave nodes; with reset, zeroes both on those nodes first.");
  m.def(
      "AddExplicitContribution",
      [](Condition& condition, const ProcessInfo& info) {
        auto* pair = dynamic_cast<PairedCondition*>(&condition);
        if (!pair)
          throw InputError(Concat("condition ", condition.Id(), " (", condition.Info(), ") is not a pair condition"));
        pair->AddExplicitContribution(info);
      },
      py::arg("condition"), py::arg("process_info"),
      "Adds one pair condition's weighted gap and nodal areas to its slave nodes.");
}

}  // namespace mc::python
