// SPDX-License-Identifier: BSD-3-Clause
#include "core/geometries/geometry.h"
#include "custom_python/python_module.h"

namespace mc::python {

void AddGeometriesToPython(py::module_& m) {
  py::enum_<Configuration>(m, "Configuration")
      .value("Initial", Configuration::Initial)
      .value("Current", Configuration::Current);

  py::class_<Geometry>(m, "Geometry")
      .def("Name", &Geometry::Name)
      .def("PointsNumber", &Geometry::PointsNumber)
      .def("WorkingSpaceDimension", &Geometry::WorkingSpaceDimension)
      .def("LocalSpaceDimension", &Geometry::LocalSpaceDimension)
      .def("DefaultIntegrationOrder", &Geometry::DefaultIntegrationOrder)
      .def("DomainSize", &Geometry::DomainSize, py::arg("configuration") = Configuration::Current)
      .def("Center", &Geometry::Center, py::arg("configuration") = Configuration::Current)
      .def("UnitNormal", &Geometry::UnitNormal, py::arg("local"), py::arg("configuration") = Configuration::Current)
      .def("GlobalCoordinates", &Geometry::GlobalCoordinates, py::arg("local"),
           py::arg("configuration") = Configuration::Current)
      .def("PointLocalCoordinates", [](const Geometry& g, const Array3& x, Configuration c) -> py::object {
        Array3 local;
        if (!g.PointLocalCoordinates(x, local, c)) return py::none();
        return py::cast(local);
      }, py::arg("point"), py::arg("configuration") = Configuration::Current)
      .def("IntegrationPoints", [](const Geometry& g, int order) {
        std::vector<std::pair<Array3, double>> points;
        for (const auto& p : g.IntegrationPoints(order)) points.emplace_back(p.local, p.weight);
        return points;
      }, py::arg("order"))
      .def("ShapeFunctionsValues", [](const Geometry& g, const Array3& local) {
        Vector N;
        g.ShapeFunctionsValues(local, N);
        return N;
      }, py::arg("local"))
      .def("Faces", &Geometry::Faces)
      .def("__len__", &Geometry::PointsNumber)
      .def("__getitem__", [](const Geometry& g, std::size_t i) -> Node& {
        if (i >= g.PointsNumber()) throw py::index_error();
        return g[i];
      }, py::return_value_policy::reference);
}

}  // namespace mc::python
