"""Restart checkpoints: the state of a run at the end of a step, in an HDF5 file of our own layout.

A checkpoint does not hold the mesh. A resumed run reads the original mesh again (the checkpoint
records which file and its SHA-256), builds the interface, the processes and the strategy as a
fresh run does, and then overwrites the state with the checkpoint's:

``/nodes``           ``ids``; ``coordinates`` and ``initial_coordinates`` (n, 3);
                     ``historical/<VAR>``: every buffer position, (buffer, n) or (buffer, n, 3);
                     ``non_historical/<VAR>/{values, held}`` (held: which nodes have a value);
                     ``flags/<FLAG>`` int8 (-1 undefined, 0 reset, 1 set);
                     ``fixity/<DOF VAR>`` int8 (-1 no DoF, 0 free, 1 fixed)
``/process_info``    one attribute per ProcessInfo value (TIME, STEP, DELTA_TIME, SCALE_FACTOR,
                     INITIAL_PENALTY, ...) and ``flags``, the names of its set flags
``/processes``       one JSON string per process of the run, in creation order: its class,
                     its place in ProjectParameters.json and the state it returned from
                     ``RestartState()`` (output collections, sampling counters, ...)
``/solver``          JSON of what the solver's ``RestartState()`` returned (the MPC strategy's slip
                     directions and mesh tie; null for the others)
root attributes      ``format``, ``version``, ``model_part_name``, ``buffer_size``, ``time``, ``step``,
                     ``mesh``: JSON of the import settings, the mesh file and its SHA-256

Contact pairs are not stored: the contact search rebuilds them from the restored coordinates at
the first resumed step, as the uninterrupted run does at every step (``database_step_update`` 1).
"""
from __future__ import annotations

import hashlib
import json
import os
import tempfile

import numpy as np

from .. import _core
from ..utilities import publish_file

FORMAT = "mortarcontact restart checkpoint"
VERSION = 1


def file_sha256(path: str) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as stream:
        for block in iter(lambda: stream.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def mesh_record(import_settings: _core.Parameters, path: str) -> dict:
    """What a checkpoint remembers of the mesh: the import settings as the run used them, the file
    found (absolute) and its SHA-256."""
    record = json.loads(import_settings.WriteJsonString())
    record["mesh_file"] = os.path.abspath(path)
    record["sha256"] = file_sha256(path)
    return record


def _dof_variables(part) -> list[str]:
    """Double variables (or components) of the historical list that some node has a DoF of."""
    names = []
    for name in part.NodalSolutionStepVariableNames():
        variable = _core.GetVariable(name)
        candidates = [f"{name}_{c}" for c in "XYZ"] if variable.Type() == _core.ValueType.Array3 else [name]
        names += [c for c in candidates if np.any(part.GetNodalFixity(_core.GetVariable(c)) >= 0)]
    return names


def write_checkpoint(path: str, part, mesh: dict, processes, solver=None, ranks=None) -> None:
    """Writes the state of the root model part ``part``, of ``processes`` and of ``solver`` (what its
    ``RestartState()`` returns) to ``path`` atomically (temporary file in the same folder, then renamed).
    ``ranks`` (a ``Ranks``): ``part`` is this rank's piece of a model cut across the ranks; collective,
    the owners' nodal states are gathered and rank 0 writes the serial run's file."""
    import h5py

    nodes = _node_state(part) if ranks is None else _gathered_node_state(part, ranks)
    # Every rank: a process of a cut model gathers its state from the ranks.
    records = [json.dumps({"class": type(process).__name__, "where": getattr(process, "item_where", ""),
                           "state": process.RestartState()}) for process in processes]
    solver_state = json.dumps(solver.RestartState() if solver is not None else None)
    if ranks is not None and ranks.rank > 0:
        return
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix=".", suffix=".rest.tmp", dir=folder)
    os.close(handle)
    try:
        with h5py.File(temporary, "w") as f:
            _write(f, part, mesh, nodes, records, solver_state)
        publish_file(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.remove(temporary)
        raise


def _node_state(part, rows=None) -> dict:
    """The datasets of ``/nodes`` of the nodes of ``part`` selected by the boolean ``rows`` (all
    without): a value, a flag or a fixity only where some selected node has it."""
    take = slice(None) if rows is None else rows
    state = {"ids": part.NodeIds()[take], "coordinates": part.NodeCoordinates(initial=False)[take],
             "initial_coordinates": part.NodeCoordinates(initial=True)[take], "historical": {},
             "non_historical": {}, "flags": {}, "fixity": {}}
    for name in part.NodalSolutionStepVariableNames():
        variable = _core.GetVariable(name)
        state["historical"][name] = np.stack([part.GetNodalValues(variable, step=s)[take]
                                              for s in range(part.GetBufferSize())])
    for name in part.NodalNonHistoricalVariableNames():
        variable = _core.GetVariable(name)
        if variable.Type() not in (_core.ValueType.Double, _core.ValueType.Int, _core.ValueType.Bool,
                                   _core.ValueType.Array3):
            raise _core.NotImplementedFeatureError(
                f"restart: the nodal value {name} ({variable.Type().name}) cannot be saved in a checkpoint")
        held = part.HasNodalNonHistoricalValues(variable)[take]
        if np.any(held):
            state["non_historical"][name] = (part.GetNodalNonHistoricalValues(variable)[take], held)
    for name in _core.FlagNames():
        states = part.GetNodalFlagStates(_core.GetFlag(name))[take]
        if np.any(states >= 0):
            state["flags"][name] = states
    for name in _dof_variables(part):
        fixity = part.GetNodalFixity(_core.GetVariable(name))[take]
        if np.any(fixity >= 0):
            state["fixity"][name] = fixity
    return state


def _gathered_node_state(part, ranks) -> dict:
    """The serial run's ``/nodes`` datasets from the pieces of a model cut across the ranks: each node's
    state from its owner (a contact-interface node every rank holds, too), in node-id order. A value,
    flag or DoF no node of a rank has is filled as the serial run reads it there: not held, undefined,
    no DoF."""
    pieces = ranks.all_gather(_node_state(part, ranks.owned_nodes(part)))
    order = np.argsort(np.concatenate([piece["ids"] for piece in pieces]), kind="stable")

    def joined(arrays, axis=0):
        return np.take(np.concatenate(arrays, axis=axis), order, axis=axis)

    state = {key: joined([piece[key] for piece in pieces])
             for key in ("ids", "coordinates", "initial_coordinates")}
    state["historical"] = {name: joined([piece["historical"][name] for piece in pieces], axis=1)
                           for name in pieces[0]["historical"]}

    def union(group: str, fill) -> dict:
        """Every name some piece has in ``group``, the pieces lacking it given ``fill(piece, name)``."""
        names = dict.fromkeys(name for piece in pieces for name in piece[group])
        return {name: [piece[group][name] if name in piece[group] else fill(piece, name) for piece in pieces]
                for name in names}

    def not_held(piece, name):
        values = next(other["non_historical"][name][0] for other in pieces if name in other["non_historical"])
        return np.zeros((piece["ids"].size, *values.shape[1:]), values.dtype), np.zeros(piece["ids"].size, bool)

    def undefined(piece, name):
        return np.full(piece["ids"].size, -1, np.int8)

    state["non_historical"] = {name: tuple(joined(list(arrays)) for arrays in zip(*entries))
                               for name, entries in union("non_historical", not_held).items()}
    for group in ("flags", "fixity"):
        state[group] = {name: joined(entries) for name, entries in union(group, undefined).items()}
    return state


def _write(f, part, mesh: dict, nodes: dict, process_records: list[str], solver_state: str) -> None:
    info = part.ProcessInfo
    f.attrs.update(format=FORMAT, version=VERSION, model_part_name=part.Name, buffer_size=part.GetBufferSize(),
                   time=float(info.GetValue(_core.TIME)), step=int(info.GetValue(_core.STEP)),
                   mesh=json.dumps(mesh))
    group = f.create_group("nodes")
    for key in ("ids", "coordinates", "initial_coordinates"):
        group[key] = nodes[key]
    historical = group.create_group("historical")
    for name, values in nodes["historical"].items():
        historical[name] = values
    non_historical = group.create_group("non_historical")
    for name, (values, held) in nodes["non_historical"].items():
        entry = non_historical.create_group(name)
        entry["values"] = values
        entry["held"] = held
    for key in ("flags", "fixity"):
        entries = group.create_group(key)
        for name, states in nodes[key].items():
            entries[name] = states
    group = f.create_group("process_info")
    for name in info.ValueNames():
        if name == "IS_RESTARTED":  # says how this run started, not what state it is in
            continue
        value = info.GetValue(_core.GetVariable(name))
        group.attrs[name] = value if isinstance(value, str) else np.asarray(value)
    group.attrs["flags"] = json.dumps([name for name in _core.FlagNames() if info.Is(_core.GetFlag(name))])
    states = f.create_group("processes")
    for index, record in enumerate(process_records):
        # A dataset, not an attribute: a JSON output's series outgrows HDF5's 64 kB attribute limit.
        states[str(index)] = record
    f["solver"] = solver_state


class Checkpoint:
    """A checkpoint opened for loading; every check names the file and what differs."""

    def __init__(self, path: str):
        import h5py

        self.path = path
        if not os.path.isfile(path):
            raise _core.InputError(f"restart: checkpoint {path} not found")
        try:
            self.file = h5py.File(path, "r")
        except OSError as error:
            raise _core.InputError(f"restart: {path} is not a readable checkpoint (HDF5: {error}); "
                                   "Kratos' serializer .rest files cannot be read") from None
        attrs = self.file.attrs
        if attrs.get("format") != FORMAT:
            raise _core.InputError(f"restart: {path} is an HDF5 file but not a mortarcontact checkpoint")
        if int(attrs["version"]) != VERSION:
            raise _core.InputError(f"restart: {path} has checkpoint version {int(attrs['version'])}; "
                                   f"this mortarcontact reads version {VERSION}")
        try:
            self.mesh = json.loads(attrs["mesh"])
            self.time = float(attrs["time"])
            self.step = int(attrs["step"])
            self.model_part_name = str(attrs["model_part_name"])
            self.buffer_size = int(attrs["buffer_size"])
            missing = [group for group in ("nodes", "process_info", "processes") if group not in self.file]
            if missing:
                raise KeyError(f"no group {missing[0]}")
        except (KeyError, ValueError) as error:
            raise _core.InputError(f"restart: {path} is incomplete or corrupt ({error})") from None

    def close(self) -> None:
        self.file.close()

    # -- checks -------------------------------------------------------------------------------
    def check_mesh_file(self, path: str) -> None:
        """The mesh read for the resumed run must be the one the checkpoint was written for."""
        if file_sha256(path) != self.mesh["sha256"]:
            raise _core.InputError(f"restart: {self.path} was written for the mesh {self.mesh['mesh_file']} "
                                   f"(SHA-256 {self.mesh['sha256'][:12]}...), but {os.path.abspath(path)} differs "
                                   "from it; resume with the mesh the checkpoint was written for")

    def check_model(self, part, piece: bool = False) -> None:
        """The whole model read for the resumed run (the root model part ``part``) is the saved one;
        ``piece``: ``part`` is the piece a rank read, whose nodes must be among the saved ones."""
        where = f"restart: {self.path}"
        if part.Name != self.model_part_name:
            raise _core.InputError(f"{where} holds model part '{self.model_part_name}', not '{part.Name}'")
        ids = self.file["nodes/ids"][()]
        if piece:
            self._rows(part)
        else:
            if ids.shape != (part.NumberOfNodes(),):
                raise _core.InputError(f"{where} has {ids.size} nodes; {part.Name} has {part.NumberOfNodes()}")
            differ = np.flatnonzero(ids != part.NodeIds())
            if differ.size:
                raise _core.InputError(f"{where}: node ids differ from {part.Name}'s, first at position {differ[0]} "
                                       f"({ids[differ[0]]} in the checkpoint, {part.NodeIds()[differ[0]]} in the "
                                       "model)")
        if self.buffer_size != part.GetBufferSize():
            raise _core.InputError(f"{where} has buffer_size {self.buffer_size}; the solver uses "
                                   f"{part.GetBufferSize()} (solver_settings.buffer_size and the scheme)")
        saved = sorted(self.file["nodes/historical"].keys())
        present = sorted(part.NodalSolutionStepVariableNames())
        if saved != present:
            missing = sorted(set(saved) - set(present))
            extra = sorted(set(present) - set(saved))
            raise _core.InputError(f"{where}: the nodal (historical) variables differ: in the checkpoint only "
                                   f"{missing or 'none'}, in the model only {extra or 'none'} (same solver "
                                   "settings and contact formulation as the saved run needed)")

    # -- restore ------------------------------------------------------------------------------
    def restore_model(self, part, piece: bool = False) -> None:
        """Overwrites the nodal data and the ProcessInfo of the root model part ``part``. ``piece``:
        ``part`` is this rank's piece of a model cut across the ranks, whose whole model passed
        ``check_model`` before the cut; its nodes take their rows of the checkpoint."""
        if piece:
            rows = self._rows(part)
        else:
            self.check_model(part)
            rows = slice(None)
        nodes = self.file["nodes"]
        part.SetNodeCoordinates(nodes["initial_coordinates"][()][rows], initial=True)
        part.SetNodeCoordinates(nodes["coordinates"][()][rows], initial=False)
        for name, values in nodes["historical"].items():
            variable = _core.GetVariable(name)
            for step, step_values in enumerate(values[()]):
                part.SetNodalValues(variable, step_values[rows], step=step)
        no_node = np.zeros(part.NumberOfNodes(), dtype=bool)
        for name in part.NodalNonHistoricalVariableNames():
            if name not in nodes["non_historical"]:  # set by the fresh set-up, absent from the saved run
                variable = _core.GetVariable(name)
                part.SetNodalNonHistoricalValues(variable, part.GetNodalNonHistoricalValues(variable), held=no_node)
        for name, group in nodes["non_historical"].items():
            variable = _core.GetVariable(self._known(name, "variable"))
            part.SetNodalNonHistoricalValues(variable, group["values"][()][rows], held=group["held"][()][rows])
        saved_flags = nodes["flags"]
        for name in _core.FlagNames():
            flag = _core.GetFlag(name)
            if name in saved_flags:
                part.SetNodalFlagStates(flag, saved_flags[name][()][rows])
            elif np.any(part.GetNodalFlagStates(flag) >= 0):
                part.SetNodalFlagStates(flag, np.full(part.NumberOfNodes(), -1, dtype=np.int8))
        for name, fixed in nodes["fixity"].items():
            part.SetNodalFixity(_core.GetVariable(self._known(name, "variable")), fixed[()][rows] > 0)
        info = part.ProcessInfo
        attrs = self.file["process_info"].attrs
        for name, value in attrs.items():
            if name == "flags":
                continue
            variable = _core.GetVariable(self._known(name, "variable"))
            info.SetValue(variable, value.item() if isinstance(value, np.ndarray) and value.ndim == 0 else value)
        set_flags = set(json.loads(attrs["flags"]))
        for name in _core.FlagNames():
            if info.Is(_core.GetFlag(name)) or name in set_flags:
                info.Set(_core.GetFlag(name), name in set_flags)
        info.SetValue(_core.IS_RESTARTED, True)

    def _rows(self, part) -> np.ndarray:
        """The checkpoint's rows of the nodes of ``part`` (a piece: a subset of the saved nodes)."""
        ids = self.file["nodes/ids"][()]
        wanted = part.NodeIds()
        rows = np.minimum(np.searchsorted(ids, wanted), ids.size - 1)
        missing = np.flatnonzero(ids[rows] != wanted)
        if missing.size:
            raise _core.InputError(f"restart: {self.path} holds no node {wanted[missing[0]]} of {part.Name}")
        return rows

    def restore_processes(self, processes) -> None:
        """Hands each process the state it saved; the process lists must be those of the saved run."""
        saved = self.file["processes"]
        records = [json.loads(saved[str(i)][()]) for i in range(len(saved))]
        now = [type(p).__name__ for p in processes]
        if [r["class"] for r in records] != now:
            raise _core.InputError(f"restart: {self.path} was saved with the processes "
                                   f"{[r['class'] for r in records]}; this run has {now} (the process lists of "
                                   "ProjectParameters.json must be those of the saved run)")
        for process, record in zip(processes, records):
            if record["state"] is not None:
                process.LoadRestartState(record["state"])

    def restore_solver(self, solver) -> None:
        """Hands the solver the state it saved (checkpoints written before the solver had one hold none)."""
        state = json.loads(self.file["solver"][()]) if "solver" in self.file else None
        if state is not None:
            solver.LoadRestartState(state)

    def _known(self, name: str, kind: str) -> str:
        known = _core.VariableNames() if kind == "variable" else _core.FlagNames()
        if name not in known:
            raise _core.InputError(f"restart: {self.path} holds the {kind} {name}, which is not registered here "
                                   "(a plugin of the saved run not loaded?)")
        return name


def pretty_time(time: float) -> float:
    """The label of a time-controlled checkpoint: the time with 12 significant digits (Kratos' rule)."""
    return float(f"{time:.12g}")


__all__ = ["FORMAT", "VERSION", "Checkpoint", "file_sha256", "mesh_record", "pretty_time", "write_checkpoint"]
