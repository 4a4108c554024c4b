"""ParaView output: ``vtk_output_process`` (VTU files + a PVD collection, or XDMF + HDF5).

Kratos' ``vtk_output`` settings are accepted unchanged (spec 1.5). Every file appears
atomically: VTU and PVD files are written to a temporary name and renamed; the XDMF/HDF5 pair is
built in a hidden staging folder and moved into place at ``ExecuteFinalize``.
"""
from __future__ import annotations

import json
import logging
import os
import pathlib
import shutil
import tempfile
from xml.sax.saxutils import quoteattr

import meshio
import numpy as np

from .. import _core
from ..process import OutputProcess
from ..processes.bulk_data import (
    UnsetVariableWarning,
    check_historical,
    entity_connectivity,
    integration_point_means,
    nodal_flags,
    nodal_values,
    variable_by_name,
)
from ..processes.model_part_resolution import resolve_model_part
from ..utilities import publish_file, warn, write_text_atomically
from .vtk_cell_types import VTK_CELL_TYPES
from .vtk_cell_types import VTK_NODE_ORDER as _VTK_ORDER

LOG = logging.getLogger("mortarcontact")


class _StagedTimeSeriesWriter(meshio.xdmf.TimeSeriesWriter):
    """meshio's writer, with the HDF5 file next to the XDMF file instead of in the working folder."""

    def __enter__(self):
        import h5py

        self.h5_filename = str(self.filename.with_suffix(".h5"))
        self.h5_file = h5py.File(self.h5_filename, "w")
        return self


class _PartWriter:
    """Output of one model part: the file names, its PVD entries or XDMF series, cached cells."""

    def __init__(self, part, folder: str, base_name: str, file_format: str):
        self.part = part
        self.folder = folder
        self.base_name = base_name
        self.file_format = file_format
        self.pvd_entries: list[tuple[float, str]] = []
        self.xdmf_written = False
        self.series = None
        self.staging = None
        self.series_mesh_key = None
        self._cells_key = None
        self._cells = None
        self.ranks = None  # a model cut across the ranks: this rank writes its piece under a PVTU

    # --- mesh ----------------------------------------------------------------------------------
    def cells(self, entity_type: str):
        """[(meshio type, connectivity as point indices, entity ids)], whether they are conditions,
        and the points: the indices of the part's nodes they are (all of them but on a piece) and
        whether each is a ghost; cached while the numbers of nodes / elements / conditions do not
        change. A piece of a cut model holds the entities whose first node the rank owns, the nodes
        it owns and the ghosts those entities use (flagged, so that ParaView shows each node once)."""
        part = self.part
        key = (entity_type, part.NumberOfNodes(), part.NumberOfElements(), part.NumberOfConditions())
        if key == self._cells_key:
            return self._cells
        use_conditions = entity_type == "condition" or (entity_type == "automatic" and part.NumberOfElements() == 0)
        node_ids = part.NodeIds()
        owned = self.ranks.owned_nodes(part) if self.ranks is not None else np.ones(len(node_ids), dtype=bool)
        groups = entity_connectivity(part, conditions=use_conditions) if entity_type != "none" else {}
        blocks = []
        for geometry, (ids, connectivity) in sorted(groups.items()):
            cell_type = VTK_CELL_TYPES.get(geometry)
            if cell_type is None:
                raise _core.NotImplementedFeatureError(f"vtk_output: geometry {geometry} has no VTK cell type here")
            index = np.searchsorted(node_ids, connectivity)
            index = np.minimum(index, max(len(node_ids) - 1, 0))
            inside = np.all(node_ids[index] == connectivity, axis=1) if len(node_ids) else np.zeros(len(ids), bool)
            if not np.all(inside):
                LOG.warning("vtk_output: %d %s of %s use nodes outside the part and are not written",
                            int(np.count_nonzero(~inside)), "conditions" if use_conditions else "elements",
                            part.FullName())
                index, ids = index[inside], ids[inside]
            if self.ranks is not None:  # the entities whose first node this rank owns
                index, ids = index[owned[index[:, 0]]], ids[owned[index[:, 0]]]
                if not len(ids):  # meshio writes no empty block
                    continue
            if cell_type in _VTK_ORDER:
                index = index[:, _VTK_ORDER[cell_type]]
            blocks.append((cell_type, index.astype(np.int64), ids))
        if not blocks:
            # A part of nodes only: one vertex per (owned) node so that ParaView shows them.
            index = np.flatnonzero(owned)
            blocks.append(("vertex", index.astype(np.int64).reshape(-1, 1), node_ids[index]))
            use_conditions = None
        # The points: the owned nodes and the ghosts the cells use, renumbered in node order.
        used = owned.copy()
        for _, connectivity, _ in blocks:
            used[connectivity.ravel()] = True
        points = np.flatnonzero(used)
        renumbered = np.full(len(node_ids), -1, dtype=np.int64)
        renumbered[points] = np.arange(len(points))
        blocks = [(cell_type, renumbered[connectivity], ids) for cell_type, connectivity, ids in blocks]
        self._cells_key, self._cells = key, (blocks, use_conditions, points, ~owned[points])
        return self._cells

    # --- files ---------------------------------------------------------------------------------
    def write_vtu(self, label: int, time: float, mesh: meshio.Mesh, binary: bool) -> None:
        """The step's VTU file; of a cut model, this rank's piece ``<name>_<rank>_<label>.vtu``
        (Kratos' naming of its MPI pieces) and, by rank 0, the ``<name>_<label>.pvtu`` of them all."""
        if self.ranks is None:
            name = f"{self.base_name}_{label}.vtu"
            piece = name
        else:
            name = f"{self.base_name}_{label}.pvtu"
            piece = f"{self.base_name}_{self.ranks.rank}_{label}.vtu"
        handle, temporary = tempfile.mkstemp(prefix=".", suffix=".vtu", dir=self.folder)
        os.close(handle)
        try:
            meshio.vtu.write(temporary, mesh, binary=binary)
            publish_file(temporary, os.path.join(self.folder, piece), every_rank=self.ranks is not None)
        except BaseException:
            if os.path.exists(temporary):
                os.remove(temporary)
            raise
        if self.ranks is not None:
            pieces = [f"{self.base_name}_{rank}_{label}.vtu" for rank in range(self.ranks.size)]
            write_text_atomically(os.path.join(self.folder, name), _pvtu(mesh, pieces))
        self.pvd_entries = [(t, f) for t, f in self.pvd_entries if f != name] + [(time, name)]
        self.write_pvd()

    def write_pvd(self) -> None:
        lines = ['<?xml version="1.0"?>',
                 '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">', "  <Collection>"]
        lines += [f'    <DataSet timestep="{time!r}" group="" part="0" file={quoteattr(name)}/>'
                  for time, name in self.pvd_entries]
        lines += ["  </Collection>", "</VTKFile>", ""]
        write_text_atomically(os.path.join(self.folder, f"{self.base_name}.pvd"), "\n".join(lines))

    def write_xdmf(self, time: float, mesh: meshio.Mesh) -> None:
        mesh_key = (mesh.points.shape, tuple((block.type, block.data.shape) for block in mesh.cells))
        if self.series is None:
            self.staging = tempfile.mkdtemp(prefix=f".{self.base_name}.", suffix=".partial", dir=self.folder)
            path = pathlib.Path(self.staging) / f"{self.base_name}.xdmf"
            self.series = _StagedTimeSeriesWriter(path).__enter__()
            self.series.write_points_cells(mesh.points, mesh.cells)
            self.series_mesh_key = mesh_key
        elif mesh_key != self.series_mesh_key:
            raise _core.NotImplementedFeatureError(
                f"vtk_output: file_format 'xdmf' needs a fixed mesh, but {self.part.FullName()} changed; "
                "use file_format 'binary' (VTU) for parts whose entities change")
        self.series.write_data(time, point_data=mesh.point_data, cell_data=mesh.cell_data)

    def close(self) -> None:
        if self.series is None:
            return
        self.series.__exit__(None, None, None)
        for suffix in (".h5", ".xdmf"):
            name = f"{self.base_name}{suffix}"
            os.replace(os.path.join(self.staging, name), os.path.join(self.folder, name))
        shutil.rmtree(self.staging, ignore_errors=True)
        self.series = None
        self.xdmf_written = True

    def written(self) -> list[str]:
        """The PVD collection, or the XDMF file once closed, when anything was written."""
        if self.xdmf_written:
            return [os.path.join(self.folder, f"{self.base_name}.xdmf")]
        return [os.path.join(self.folder, f"{self.base_name}.pvd")] if self.pvd_entries else []


def _pvtu(mesh: meshio.Mesh, pieces: list[str]) -> str:
    """The PUnstructuredGrid over ``pieces``, which hold the arrays of ``mesh`` (this rank's piece:
    every piece has the same arrays), typed as meshio writes them (points always 3D)."""

    def vtk_type(dtype: np.dtype) -> str:  # Float64, Int64, UInt8, ...
        return f"{ {'f': 'Float', 'u': 'UInt'}.get(dtype.kind, 'Int')}{dtype.itemsize * 8}"

    def declarations(arrays) -> list[str]:
        return [f'      <PDataArray type="{vtk_type(data.dtype)}" Name={quoteattr(name)} '
                f'NumberOfComponents="{data.shape[1] if data.ndim == 2 else 1}"/>' for name, data in arrays]

    cells = [(name, np.concatenate(blocks)) for name, blocks in mesh.cell_data.items()]
    lines = ['<?xml version="1.0"?>',
             '<VTKFile type="PUnstructuredGrid" version="0.1" byte_order="LittleEndian">',
             '  <PUnstructuredGrid GhostLevel="0">',  # no ghost cells; ghost points flagged in the pieces
             "    <PPointData>", *declarations(mesh.point_data.items()), "    </PPointData>",
             "    <PCellData>", *declarations(cells), "    </PCellData>",
             "    <PPoints>",
             f'      <PDataArray type="{vtk_type(mesh.points.dtype)}" NumberOfComponents="3"/>',
             "    </PPoints>",
             *(f"    <Piece Source={quoteattr(piece)}/>" for piece in pieces),
             "  </PUnstructuredGrid>", "</VTKFile>", ""]
    return "\n".join(lines)


class VtkOutputProcess(OutputProcess):
    """Writes one VTU file per output step (``<path>/<prefix><part><postfix>_<step>.vtu``) and a
    ``.pvd`` collection listing every step with its TIME, rewritten after each step so that
    ParaView can open it during the run. ``file_format`` ``"xdmf"`` writes one XDMF + HDF5 time
    series per part instead (mesh fixed in time). Of a model cut across the ranks, each rank writes
    its piece ``<...>_<rank>_<step>.vtu`` and rank 0 the ``<...>_<step>.pvtu`` the PVD lists.

    Cells: the elements of the part (``entity_type`` "automatic": the conditions if there are no
    elements; a part with neither is written as vertices). Point data: the historical variables
    ``nodal_solution_step_data_variables`` and the non-historical ``nodal_data_value_variables``
    (array-3 values as 3-component arrays; a historical variable the part does not store is an input
    error at ``Check``), ``nodal_flags`` as 0/1 arrays. A requested variable that nothing in the run
    computes is written as zeros with a warning (``UnsetVariableWarning``). Cell data:
    ``gauss_point_variables_extrapolated_to_nodes`` and ``gauss_point_variables_in_elements``
    are written **per cell as the mean over its integration points** (not extrapolated to the
    nodes); vectors keep their components, matrices (stress / strain tensors) become 9
    row-major components; ``element_data_value_variables`` / ``element_flags`` (or the
    condition ones when conditions are written).

    Keys (default): ``model_part_name`` (required), ``file_format`` ("binary"; "ascii",
    "xdmf"), ``output_precision`` (7; warns when given: meshio chooses the digits),
    ``output_control_type`` ("step" or "time"), ``output_interval`` (1.0; legacy
    ``output_frequency``), ``output_sub_model_parts`` (false: true also writes each direct sub
    model part), ``output_path`` ("VTK_Output"; legacy ``folder_name``),
    ``save_output_files_in_folder`` (true), ``custom_name_prefix`` / ``custom_name_postfix``
    (""), ``entity_type`` ("automatic", "element", "condition"), ``write_deformed_configuration``
    (false: initial coordinates), ``write_ids`` (false), and the variable lists above plus
    ``condition_data_value_variables`` / ``condition_flags`` ([]).
    """

    python_module = "vtk_output_process"

    @classmethod
    def GetDefaultParameters(cls):
        return _core.Parameters("""{
            "help": "", "model_part_name": "", "file_format": "binary", "output_precision": 7,
            "output_control_type": "step", "output_interval": 1.0, "output_frequency": null,
            "output_sub_model_parts": false, "output_path": "VTK_Output", "folder_name": null,
            "custom_name_prefix": "", "custom_name_postfix": "", "save_output_files_in_folder": true,
            "entity_type": "automatic", "write_deformed_configuration": false, "write_ids": false,
            "nodal_solution_step_data_variables": [], "nodal_data_value_variables": [], "nodal_flags": [],
            "element_data_value_variables": [], "element_flags": [],
            "condition_data_value_variables": [], "condition_flags": [],
            "gauss_point_variables_extrapolated_to_nodes": [], "gauss_point_variables_in_elements": []
        }""", "defaults")

    def __init__(self, model, settings):
        super().__init__(model, settings)
        s = self.settings
        where = s.Where()
        if not s["model_part_name"].GetString():
            raise _core.InputError(f"{where}: vtk_output requires 'model_part_name'")
        _core.NoEffectWarnings.IfGiven(s, self.GetDefaultParameters(), "output_precision",
                                       "meshio chooses the digits of the VTU/XDMF values")
        self.file_format = s["file_format"].GetString()
        if self.file_format not in ("binary", "ascii", "xdmf"):
            raise _core.InputError(f"{where}: file_format '{self.file_format}' is not one of binary, ascii, xdmf")
        self.control = s["output_control_type"].GetString()
        if self.control not in ("step", "time"):
            raise _core.InputError(f"{where}: output_control_type '{self.control}' is not 'step' or 'time'")
        interval = s["output_frequency"] if not s["output_frequency"].IsNull() else s["output_interval"]
        self.interval = interval.GetDouble()
        if self.interval <= 0.0:
            raise _core.InputError(f"{where}: the output interval must be positive, got {self.interval}")
        self.entity_type = s["entity_type"].GetString()
        if self.entity_type not in ("automatic", "element", "condition"):
            raise _core.InputError(f"{where}: entity_type '{self.entity_type}' is not automatic, element or condition")
        folder = s["folder_name"].GetString() if not s["folder_name"].IsNull() else s["output_path"].GetString()
        self.folder = folder if s["save_output_files_in_folder"].GetBool() else "."
        lists = ("nodal_solution_step_data_variables", "nodal_data_value_variables", "element_data_value_variables",
                 "condition_data_value_variables", "gauss_point_variables_extrapolated_to_nodes",
                 "gauss_point_variables_in_elements")
        self.variables = {key: [variable_by_name(n) for n in s[key].GetStringArray()] for key in lists}
        self.flags = {key: [_core.GetFlag(n) for n in s[key].GetStringArray()]
                      for key in ("nodal_flags", "element_flags", "condition_flags")}
        self.writers: list[_PartWriter] = []
        self.unset = UnsetVariableWarning(self.python_module)
        self.step_count = 0
        self.next_output = None

    # --- process hooks -------------------------------------------------------------------------
    def ExecuteInitialize(self) -> None:
        # The folder is made at the first output, so that a case stopped by bad input during the
        # set-up (issue 16) leaves no output behind.
        root = resolve_model_part(self.model, self.settings["model_part_name"].GetString())
        parts = [root]
        if self.settings["output_sub_model_parts"].GetBool():
            parts += list(root.SubModelParts)
        prefix = self.settings["custom_name_prefix"].GetString()
        postfix = self.settings["custom_name_postfix"].GetString()
        self.writers = [_PartWriter(part, self.folder, f"{prefix}{part.FullName()}{postfix}", self.file_format)
                        for part in parts]

    def ExecuteAfterModelCut(self, ranks) -> None:
        if self.file_format == "xdmf":
            raise _core.NotImplementedFeatureError(
                f"{self.settings['file_format'].Where()}: 'xdmf' of a model cut across {ranks.size} processes "
                "(MORTARCONTACT_PARTITIONED_MODEL=1); use \"binary\" or \"ascii\" (a VTU piece per process)")
        if not self.writers:
            self.ExecuteInitialize()
        for writer in self.writers:
            writer.ranks = ranks

    def Check(self) -> None:
        key = "nodal_solution_step_data_variables"
        for writer in self.writers:
            check_historical(writer.part, self.variables[key], self.settings[key].Where(),
                             "list them in nodal_data_value_variables")

    def ExecuteBeforeSolutionLoop(self) -> None:
        if not self.writers:
            self.ExecuteInitialize()
        start = self._time() if self.control == "time" else 0.0
        self.next_output = start + self.interval

    def ExecuteInitializeSolutionStep(self) -> None:
        self.step_count += 1

    def IsOutputStep(self) -> bool:
        if self.next_output is None:
            self.ExecuteBeforeSolutionLoop()
        current = self._time() if self.control == "time" else float(self.step_count)
        return current >= self.next_output - 1e-10 * self.interval

    def PrintOutput(self) -> None:
        if not self.writers:
            self.ExecuteInitialize()
        time = self._time()
        os.makedirs(self.folder, exist_ok=True)
        for writer in self.writers:
            mesh = self._mesh(writer)
            if self.file_format == "xdmf":
                writer.write_xdmf(time, mesh)
            else:
                writer.write_vtu(self.step_count, time, mesh, binary=self.file_format == "binary")
        if self.next_output is None:
            self.ExecuteBeforeSolutionLoop()
        current = self._time() if self.control == "time" else float(self.step_count)
        while self.next_output <= current + 1e-10 * self.interval:
            self.next_output += self.interval

    def ExecuteFinalize(self) -> None:
        for writer in self.writers:
            writer.close()
        self.unset.finish()

    def ExecuteAfterFailure(self) -> None:
        # The XDMF/HDF5 pair of the converged steps moves into place; VTU and PVD already are.
        for writer in self.writers:
            writer.close()

    def OutputFiles(self) -> list[str]:
        return [path for writer in self.writers for path in writer.written()]

    def RestartState(self):
        """The step counter, the next output and each PVD collection, so that a resumed run goes on
        with the same file labels and appends to the collections."""
        return {"step_count": self.step_count, "next_output": self.next_output,
                "pvd_entries": {writer.base_name: writer.pvd_entries for writer in self.writers}}

    def LoadRestartState(self, state) -> None:
        self.step_count = state["step_count"]
        self.next_output = state["next_output"]
        for writer in self.writers:
            writer.pvd_entries = [(time, name) for time, name in state["pvd_entries"].get(writer.base_name, [])]
            if self.file_format == "xdmf":
                warn(f"{self.python_module}: the XDMF series {writer.base_name}.xdmf of a resumed run holds only "
                     "the steps after the restart; use file_format \"binary\" (VTU + PVD) to append to the "
                     "saved run's collection")

    # --- data ----------------------------------------------------------------------------------
    def _time(self) -> float:
        root = self.writers[0].part if self.writers else resolve_model_part(
            self.model, self.settings["model_part_name"].GetString())
        return float(root.ProcessInfo.GetValue(_core.TIME))

    def _mesh(self, writer: _PartWriter) -> meshio.Mesh:
        part = writer.part
        entity = "none" if part.NumberOfElements() == 0 and part.NumberOfConditions() == 0 else self.entity_type
        blocks, conditions, nodes, ghosts = writer.cells(entity)
        deformed = self.settings["write_deformed_configuration"].GetBool()
        points = np.asarray(part.NodeCoordinates(not deformed), dtype=float)[nodes]
        point_data = {}
        for key, historical in (("nodal_solution_step_data_variables", True), ("nodal_data_value_variables", False)):
            for variable in self.variables[key]:
                values = nodal_values(part, variable, historical=historical)
                self.unset.check(part, variable, historical, values)
                point_data[variable.Name()] = values[nodes]
        for flag in self.flags["nodal_flags"]:
            point_data[flag.Name()] = nodal_flags(part, flag)[nodes].astype(np.float64)
        if self.settings["write_ids"].GetBool():
            point_data["KRATOS_NODE_ID"] = part.NodeIds()[nodes].astype(np.int64)
        if writer.ranks is not None:  # VTK's flag of a point another piece holds (vtkDataSetAttributes)
            point_data["vtkGhostType"] = np.where(ghosts, 1, 0).astype(np.uint8)
        cell_data = self._cell_data(part, blocks, conditions)
        cells = [(cell_type, connectivity) for cell_type, connectivity, _ in blocks]
        return meshio.Mesh(points, cells, point_data=point_data, cell_data=cell_data)

    def _integration_point_means(self, part, variable, ids, conditions: bool) -> np.ndarray:
        """The means of one block; zeros, reported once, where its entities do not compute
        ``variable``."""
        try:
            return integration_point_means(part, variable, ids, conditions)
        except _core.NotImplementedFeatureError as error:
            self.unset.not_computed(part, variable, str(error))
            width = {_core.ValueType.Array3: 3, _core.ValueType.Matrix: 9}.get(variable.Type())
            return np.zeros((len(ids), width) if width else len(ids))

    def _cell_data(self, part, blocks, conditions) -> dict[str, list[np.ndarray]]:
        if conditions is None:  # vertices standing for nodes: no entity data
            return {}
        kind = "condition" if conditions else "element"
        get = part.GetCondition if conditions else part.GetElement
        cell_data: dict[str, list[np.ndarray]] = {}
        gauss = (self.variables["gauss_point_variables_extrapolated_to_nodes"]
                 + self.variables["gauss_point_variables_in_elements"])
        for variable in gauss:
            means = [self._integration_point_means(part, variable, ids, conditions) for _, _, ids in blocks]
            width = max((m.shape[1] if m.ndim == 2 else 0) for m in means)
            if width:  # vectors of different lengths per block: pad to the widest
                means = [np.pad(m.reshape(len(m), -1), ((0, 0), (0, width - m.reshape(len(m), -1).shape[1])))
                         for m in means]
            cell_data[variable.Name()] = means
        for variable in self.variables[f"{kind}_data_value_variables"]:
            cell_data[variable.Name()] = [np.asarray([np.asarray(get(int(i)).GetValue(variable), dtype=float)
                                                      for i in ids]) for _, _, ids in blocks]
        for flag in self.flags[f"{kind}_flags"]:
            cell_data[flag.Name()] = [np.asarray([float(get(int(i)).Is(flag)) for i in ids]) for _, _, ids in blocks]
        if self.settings["write_ids"].GetBool():
            cell_data[f"KRATOS_{kind.upper()}_ID"] = [ids.astype(np.int64) for _, _, ids in blocks]
        return cell_data


class GidOutputProcess(VtkOutputProcess):
    """``gid_output_process``: GiD files are not written; the same results go to VTU/PVD files in
    ``<output_name>_vtk/`` with a warning. Translated keys: ``model_part_name``, ``output_name``,
    and from ``postprocess_parameters.result_file_configuration``: ``nodal_results``,
    ``nodal_nonhistorical_results``, ``nodal_flags_results``, ``gauss_point_results``,
    ``output_control_type`` ("step"/"time"), ``output_frequency`` / ``output_interval``. The
    other GiD options (``gidpost_flags``, ``file_label``, ``body_output``, ``point_data_configuration``
    ...) have no VTU meaning and are ignored."""

    python_module = "gid_output_process"

    def __init__(self, model, settings):
        settings = settings if settings is not None else _core.Parameters()
        settings.CheckKeys(["help", "model_part_name", "output_name", "postprocess_parameters"])
        output_name = settings["output_name"].GetString() if settings.Has("output_name") else "gid_output"
        results = _core.Parameters()
        if (settings.Has("postprocess_parameters")
                and settings["postprocess_parameters"].Has("result_file_configuration")):
            results = settings["postprocess_parameters"]["result_file_configuration"]
        model_part_name = settings["model_part_name"].GetString() if settings.Has("model_part_name") else ""
        vtk: dict = {"model_part_name": model_part_name,
                     "output_path": f"{output_name}_vtk"}
        translation = {"nodal_results": "nodal_solution_step_data_variables",
                       "nodal_nonhistorical_results": "nodal_data_value_variables",
                       "nodal_flags_results": "nodal_flags", "gauss_point_results": "gauss_point_variables_in_elements"}
        for gid_key, vtk_key in translation.items():
            if results.Has(gid_key):
                vtk[vtk_key] = results[gid_key].GetStringArray()
        if results.Has("output_control_type"):
            control = results["output_control_type"].GetString()
            vtk["output_control_type"] = "time" if control.startswith("time") else "step"
        for key in ("output_interval", "output_frequency"):
            if results.Has(key):
                vtk["output_interval"] = results[key].GetDouble()
        LOG.warning("gid_output_process: GiD files are not written; writing the same results as VTU/PVD to '%s'",
                    f"{output_name}_vtk")
        super().__init__(model, _core.Parameters(json.dumps(vtk)))
