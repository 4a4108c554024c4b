// SPDX-License-Identifier: BSD-3-Clause
#include "core/geometries/geometry.h"
#include "custom_python/python_module.h"

namespace mc::python {

void AddGeometriesToPython(py::module_& m) {
  py::enum_<Configuration>(m, "Configuration", "Which node coordinates a geometry evaluates with.")
      .value("Initial", Configuration::Initial, "the initial (reference) coordinates X0")
      .value("Current", Configuration::Current, "the current (deformed) coordinates");

  py::class_<Geometry>(m, "Geometry",
                       "The geometry of an element or condition: its nodes and the reference element of its type "
                       "(shape functions, quadrature, faces).")
      .def("Name", &Geometry::Name, "Kratos geometry name, e.g. 'Triangle2D3'.")
      .def("PointsNumber", &Geometry::PointsNumber, "Number of nodes.")
      .def("WorkingSpaceDimension", &Geometry::WorkingSpaceDimension, "Dimension of the space of the nodes (2 or 3).")
      .def("LocalSpaceDimension", &Geometry::LocalSpaceDimension,
           "Dimension of the parametric space (1 lines, 2 surfaces, 3 solids).")
      .def("DefaultIntegrationOrder", &Geometry::DefaultIntegrationOrder,
           "Default quadrature order of the type (Kratos': 1 linear simplices, 2 quads/hexes, ...).")
      .def("DomainSize", &Geometry::DomainSize, py::arg("configuration") = Configuration::Current,
           "Length, area or volume (model units).")
      .def("Center", &Geometry::Center, py::arg("configuration") = Configuration::Current,
           "The geometry's centre, the image of the local centre.")
      .def("UnitNormal", &Geometry::UnitNormal, py::arg("local"), py::arg("configuration") = Configuration::Current,
           "Unit normal at a local point: of a line in 2D (tangent rotated by -90 degrees, Kratos' orientation) or a "
           "surface in 3D.")
      .def("GlobalCoordinates", &Geometry::GlobalCoordinates, py::arg("local"),
           py::arg("configuration") = Configuration::Current, "The global coordinates of a local point.")
      .def(
          "PointLocalCoordinates",
          [](const Geometry& g, const Array3& x, Configuration c) -> py::object {
            Array3 local;
            if (!g.PointLocalCoordinates(x, local, c)) return py::none();
            return py::cast(local);
          },
          py::arg("point"), py::arg("configuration") = Configuration::Current,
          "The local coordinates of a global point (Newton inversion); None when it does not converge.")
      .def(
          "IntegrationPoints",
          [](const Geometry& g, int order) {
            std::vector<std::pair<Array3, double>> points;
            for (const auto& p : g.IntegrationPoints(order)) points.emplace_back(p.local, p.weight);
            return points;
          },
          py::arg("order"), "(local coordinates, weight) of the quadrature points of an order 1 to 5.")
      .def(
          "ShapeFunctionsValues",
          [](const Geometry& g, const Array3& local) {
            Vector N;
            g.ShapeFunctionsValues(local, N);
            return N;
          },
          py::arg("local"), "The shape functions N_i at a local point.")
      .def("Faces", &Geometry::Faces,
           "Local node indices of each face (edges in 2D), ordered so that face normals point outwards.")
      .def("__len__", &Geometry::PointsNumber)
      .def(
          "__getitem__",
          [](const Geometry& g, std::size_t i) -> Node& {
            if (i >= g.PointsNumber()) throw py::index_error();
            return g[i];
          },
          py::arg("index"), py::return_value_policy::reference, "The node at a local index.");
}

}  // namespace mc::python
