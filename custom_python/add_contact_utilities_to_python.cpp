// SPDX-License-Identifier: BSD-3-Clause
// Bindings of custom_utilities: nodal and condition normals, and the MortarUpdater hook through
// which criteria and strategies refresh the mortar quantities.
#include "core/model/model_part.h"
#include "custom_python/python_module.h"
#include "custom_utilities/mortar_updater.h"
#include "custom_utilities/normal_calculation_utilities.h"

namespace mc::python {

namespace {

/// Python subclasses of MortarUpdater override ComputeWeightedGap / UpdateNormals / ...
class PyMortarUpdater : public MortarUpdater {
 public:
  void ComputeWeightedGap(ModelPart& model_part) override {
    py::gil_scoped_acquire gil;
    PYBIND11_OVERRIDE_PURE(void, MortarUpdater, ComputeWeightedGap, model_part);
  }
  void UpdateNormals(ModelPart& model_part) override {
    py::gil_scoped_acquire gil;
    PYBIND11_OVERRIDE(void, MortarUpdater, UpdateNormals, model_part);
  }
  void UpdateDynamicFactor(ModelPart& model_part) override {
    py::gil_scoped_acquire gil;
    PYBIND11_OVERRIDE(void, MortarUpdater, UpdateDynamicFactor, model_part);
  }
  void AdaptPenalty(ModelPart& model_part) override {
    py::gil_scoped_acquire gil;
    PYBIND11_OVERRIDE(void, MortarUpdater, AdaptPenalty, model_part);
  }
};

}  // namespace

void AddContactUtilitiesToPython(py::module_& m) {
  py::class_<NormalCalculationUtilities>(
      m, "NormalCalculationUtilities",
      "Unit normals of interface conditions and nodes in the current configuration (Kratos "
      "NormalCalculationUtils; nodal normal: normalised sum of the conditions' unit normals, Popp's definition).")
      .def_static("ComputeNodalNormals", &NormalCalculationUtilities::ComputeNodalNormals, py::arg("part"),
                  "Writes the condition NORMAL and the nodal NORMAL of every node of the part's conditions "
                  "(historical when the model has it, spec 5.1).")
      .def_static("ComputeConditionsNormals", &NormalCalculationUtilities::ComputeConditionsNormals, py::arg("part"),
                  "Writes NORMAL on every condition of the part (its unit normal at the local centre).");

  py::class_<MortarUpdater, PyMortarUpdater, std::shared_ptr<MortarUpdater>>(
      m, "MortarUpdater",
      "Hook through which the mortar criteria and contact strategies refresh WEIGHTED_GAP "
      "(ComputeWeightedGap, after the caller zeroed it on the Contact nodes), NORMAL (UpdateNormals), "
      "DYNAMIC_FACTOR (UpdateDynamicFactor) and the adapted INITIAL_PENALTY (AdaptPenalty).")
      .def(py::init<>(), "For Python subclasses, which override the methods.")
      .def("ComputeWeightedGap", &MortarUpdater::ComputeWeightedGap, py::arg("model_part"),
           "Adds the weighted gap g_j = -n_j . (D x1 - M x2)_j of every ComputingContact pair to its slave nodes.")
      .def("UpdateNormals", &MortarUpdater::UpdateNormals, py::arg("model_part"),
           "Recomputes the nodal NORMAL of the Contact part (before each build with normal variation).")
      .def("UpdateDynamicFactor", &MortarUpdater::UpdateDynamicFactor, py::arg("model_part"),
           "Refreshes DYNAMIC_FACTOR (compute_dynamic_factor, dynamic problems); nothing by default.")
      .def("AdaptPenalty", &MortarUpdater::AdaptPenalty, py::arg("model_part"),
           "Refreshes the adapted nodal INITIAL_PENALTY (ProcessInfo ADAPT_PENALTY); nothing by default.");
  py::class_<CallbackMortarUpdater, MortarUpdater, std::shared_ptr<CallbackMortarUpdater>>(
      m, "CallbackMortarUpdater", "A MortarUpdater from two callables taking the model part (either may be None).")
      .def(py::init([](py::object compute_weighted_gap, py::object update_normals) {
             return std::make_shared<CallbackMortarUpdater>(PythonCallback<ModelPart>(std::move(compute_weighted_gap)),
                                                            PythonCallback<ModelPart>(std::move(update_normals)));
           }),
           py::arg("compute_weighted_gap"), py::arg("update_normals") = py::none(),
           "compute_weighted_gap(model_part) and update_normals(model_part) serve the methods of those names.");
}

}  // namespace mc::python
