// SPDX-License-Identifier: BSD-3-Clause
#include "core/io/materials_reader.h"
#include "core/io/mdpa_reader.h"
#include "core/io/mdpa_writer.h"
#include "core/model/model.h"
#include "core/parameters/parameters.h"
#include "custom_python/python_module.h"

namespace mc::python {

namespace {
/// Fixities written in NodalData blocks of an mdpa; applied once the solver has added the DoFs.
struct PendingFixities {
  std::vector<FixityRequest> requests;
};
}  // namespace

void AddIoToPython(py::module_& m) {
  py::class_<PendingFixities>(m, "PendingFixities",
                              "The fixities of an mdpa's NodalData blocks, to apply once the solver added the DoFs.")
      .def("__len__", [](const PendingFixities& p) { return p.requests.size(); })
      .def(
          "Apply", [](const PendingFixities& p) { return MdpaReader::ApplyFixityRequests(p.requests); },
          "Fixes the requested DoFs that exist now; returns how many found no DoF.");

  py::class_<MdpaMesh::Piece>(m, "MdpaPiece",
                              "What one rank of a distributed run reads of an mdpa (PlanModelPartPiece): sorted ids.")
      .def_property_readonly(
          "nodes", [](const MdpaMesh::Piece& p) { return p.nodes.size(); }, "How many nodes the piece holds.")
      .def_property_readonly(
          "elements", [](const MdpaMesh::Piece& p) { return p.elements.size(); }, "How many elements it holds.")
      .def_property_readonly(
          "conditions", [](const MdpaMesh::Piece& p) { return p.conditions.size(); }, "How many conditions it holds.");

  m.def(
      "ReadModelPart",
      [](ModelPart& part, const std::string& filename, bool ignore_variables_not_in_solution_step_data,
         const MdpaMesh::Piece* piece) {
        MdpaReaderOptions options;
        options.ignore_variables_not_in_solution_step_data = ignore_variables_not_in_solution_step_data;
        options.piece = piece;
        MdpaReader reader(filename, options);
        {
          py::gil_scoped_release release;
          reader.ReadModelPart(part);
        }
        return PendingFixities{reader.FixityRequests()};
      },
      py::arg("model_part"), py::arg("filename"), py::arg("ignore_variables_not_in_solution_step_data") = false,
      py::arg("piece") = nullptr,
      "Reads a Kratos .mdpa file into the model part; returns the NodalData fixities to apply after AddDofs. With "
      "`piece`, builds only its nodes, elements and conditions, every line read and checked alike.");
  m.def(
      "WriteModelPart", [](const ModelPart& part, const std::string& filename) { MdpaWriter(filename).Write(part); },
      py::arg("model_part"), py::arg("filename"), "Writes the model part as a Kratos .mdpa file (atomically).");
  m.def("ReadMaterials", &ReadMaterials, py::arg("model"), py::arg("materials"), py::arg("origin") = "",
        "Applies a Kratos materials.json (spec 1.8): properties, laws and tables to every element and "
        "condition of each listed model part.");
}

}  // namespace mc::python
