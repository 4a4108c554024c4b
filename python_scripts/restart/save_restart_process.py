"""``save_restart_process``: writes restart checkpoints during a run (Kratos' settings and file names;
the file is an HDF5 checkpoint of ours, see ``restart/checkpoint.py``)."""
from __future__ import annotations

import os
import re

from .. import _core
from ..process import OutputProcess
from ..processes.model_part_resolution import resolve_model_part
from ..utilities import secondary_process, warn_about_keys_without_effect
from .checkpoint import pretty_time, write_checkpoint

SERIALIZER_TRACES = ("no_trace", "trace_error", "trace_all")
CONTROL_TYPES = ("time", "step")


def restart_folder(model_part_name: str, output_path: str, in_folder: bool) -> tuple[str, str]:
    """(folder, file stem) of the checkpoints of ``model_part_name`` (Kratos' rule): the folder
    ``output_path`` (default ``<name>__restart_files``) under the working directory when
    ``in_folder``, else the working directory; a path in the name is kept."""
    raw_path, stem = os.path.split(model_part_name)
    base = os.path.join(os.getcwd(), raw_path)
    if not in_folder:
        return base, stem
    return os.path.join(base, output_path or f"{stem}__restart_files"), stem


def restart_file_name(stem: str, label) -> str:
    return f"{stem}_{label}.rest"


class SaveRestartProcess(OutputProcess):
    """Writes ``<folder>/<model part>_<label>.rest`` at the end of the steps chosen by
    ``restart_control_type`` ("time": the label is TIME, written when TIME passes the next multiple
    of ``restart_save_frequency``; "step": the label is STEP, written every that many steps; a
    frequency 0 writes every step). Keys (default): ``model_part_name`` (required),
    ``echo_level`` (0), ``serializer_trace`` ("no_trace"; Kratos' serializer option, accepted, no
    effect on HDF5), ``restart_save_frequency`` (0.0), ``restart_control_type`` ("time"),
    ``save_restart_files_in_folder`` (true), ``output_path`` ("": ``<name>__restart_files``;
    legacy ``io_foldername``), ``max_files_to_keep`` (-1: all; n > 0: the newest n).

    Resume with ``model_import_settings`` ``{"input_type": "rest", "input_filename": <model part>,
    "restart_load_file_label": <label>}``."""

    python_module = "save_restart_process"
    after_other_outputs = True

    @classmethod
    def GetDefaultParameters(cls):
        return _core.Parameters("""{
            "help": "", "model_part_name": "", "echo_level": 0, "serializer_trace": "no_trace",
            "restart_save_frequency": 0.0, "restart_control_type": "time", "save_restart_files_in_folder": true,
            "output_path": "", "io_foldername": null, "max_files_to_keep": -1
        }""", "defaults")

    def __init__(self, model, settings):
        super().__init__(model, settings)
        s = self.settings
        where = s.Where()
        self.model_part_name = s["model_part_name"].GetString()
        if not self.model_part_name:
            raise _core.InputError(f"{where}: save_restart_process requires 'model_part_name'")
        for key, valid in (("serializer_trace", SERIALIZER_TRACES), ("restart_control_type", CONTROL_TYPES)):
            value = s[key].GetString()
            if value not in valid:
                raise _core.InputError(f"{where}.{key}: \"{value}\" is not one of {', '.join(valid)}")
        warn_about_keys_without_effect(s, self.GetDefaultParameters(), {
            ("", "serializer_trace"): "checkpoints are HDF5 files, not Kratos' serializer's"})
        self.by_time = s["restart_control_type"].GetString() == "time"
        self.frequency = s["restart_save_frequency"].GetDouble()
        if not 0.0 <= self.frequency < float("inf"):
            raise _core.InputError(f"{where}.restart_save_frequency: must be a non-negative number, "
                                   f"got {self.frequency!r}")
        if not self.by_time:
            self.frequency = float(int(self.frequency))  # STEP is an integer
        self.max_files = s["max_files_to_keep"].GetInt()
        if self.max_files == 0 or self.max_files < -1:
            raise _core.InputError(f"{where}.max_files_to_keep: -1 (keep all) or a positive number, "
                                   f"got {self.max_files}")
        legacy = s["io_foldername"]
        output_path = legacy.GetString() if not legacy.IsNull() else s["output_path"].GetString()
        self.folder, self.stem = restart_folder(self.model_part_name, output_path,
                                                s["save_restart_files_in_folder"].GetBool())
        self.echo_level = s["echo_level"].GetInt()
        self.next_output = self.frequency  # no checkpoint of the initial state
        self.processes = []
        self.mesh = None
        self.solver = None
        self.ranks = None  # a model cut across the ranks: the checkpoint gathers the pieces
        self.written: list[str] = []

    def attach(self, processes, mesh: dict | None, solver=None) -> None:
        """The run's processes (whose states go into the checkpoint), its mesh record
        (``checkpoint.mesh_record``; None when the model was built in Python) and its solver."""
        self.processes = processes
        self.mesh = mesh
        self.solver = solver

    def ExecuteAfterModelCut(self, ranks) -> None:
        self.ranks = ranks

    def _part(self):
        return resolve_model_part(self.model, self.model_part_name).GetRootModelPart()

    def _label(self):
        info = self._part().ProcessInfo
        return pretty_time(info.GetValue(_core.TIME)) if self.by_time else int(info.GetValue(_core.STEP))

    def IsOutputStep(self) -> bool:
        info = self._part().ProcessInfo
        if self.by_time:
            return info.GetValue(_core.TIME) > self.next_output
        return info.GetValue(_core.STEP) >= self.next_output

    def PrintOutput(self) -> None:
        if self.mesh is None:
            raise _core.NotImplementedFeatureError(
                f"{self.settings.Where()}: restart checkpoints need a model read from a mesh file "
                "(model_import_settings.input_type \"mdpa\", \"gmsh\", \"meshio\" or \"rest\")")
        label = self._label()
        if self.frequency > 0.0:
            # Scheduled before writing: the checkpoint holds this process's next output too.
            while self.next_output <= label:
                self.next_output += self.frequency
        path = os.path.join(self.folder, restart_file_name(self.stem, label))
        write_checkpoint(path, self._part(), self.mesh, self.processes, self.solver, self.ranks)
        # The linear solver keeps factorizations across steps, which a run resumed from this
        # checkpoint does not have: both start the next step without them.
        if self.solver is not None:
            self.solver.ResetLinearSolver()
        if path not in self.written:
            self.written.append(path)
        if self.echo_level > 0:
            print(f"save_restart_process: wrote {path}")
        self._remove_old_files()

    def _remove_old_files(self) -> None:
        # Under mpirun with a model cut across the ranks every rank runs this process; rank 0 alone
        # writes the files and prunes them.
        if self.max_files < 0 or secondary_process():
            return
        pattern = re.compile(re.escape(self.stem) + r"_(.+)\.rest$")
        labelled = []
        for name in os.listdir(self.folder):
            match = pattern.match(name)
            if match:
                try:
                    labelled.append((float(match.group(1)), name))
                except ValueError:
                    continue
        for _, name in sorted(labelled)[:-self.max_files]:
            path = os.path.join(self.folder, name)
            os.remove(path)
            if path in self.written:
                self.written.remove(path)

    def OutputFiles(self) -> list[str]:
        return list(self.written)

    def RestartState(self):
        return {"next_output": self.next_output}

    def LoadRestartState(self, state) -> None:
        self.next_output = state["next_output"]
