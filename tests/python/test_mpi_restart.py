"""Issue 17: restart checkpoints of a model cut across the ranks (``MORTARCONTACT_PARTITIONED_MODEL=1``
under ``mpirun -n 2``). A checkpoint written there is the serial run's file: every node's state
gathered from its owner in node-id order, the processes' states merged (datasets within 1e-12 of the
serial run's with MUMPS, integers and flags exactly). A run resumed on 2 ranks from a checkpoint
written by the serial or the 2-rank run, and a serial run resumed from the 2-rank run's, end with
the uninterrupted serial run's answers in its Newton iterations. Skipped as test_mpi.py is."""
from __future__ import annotations

import csv
import json
import os
import re
import shutil

import h5py
import numpy as np
import pytest
from test_mpi import ENV, PARTITIONED, _json_file, _run, _write_cut_case
from test_mpi import pytestmark as mpi_marks
from test_restart import checkpoint_path, resume_settings

pytestmark = mpi_marks

#: Kratos' 2D Hertz case (MUMPS, the block builder), Bossak dynamics in 4 steps: the buffer holds
#: velocities and accelerations, and the contact zone is closed from step 1 on.
STEPS, TIME_STEP = 4, 0.125
#: The step a resumed run starts after.
RESUMED_AFTER = 2
#: MUMPS factors the distributed system in another order than the serial one: over the 4 steps the
#: displacements differ by 1.2e-13 at most (relative to their largest), the multipliers, contact
#: pressures and accelerations (Newmark's 1 / (beta dt^2) on the displacements) by 1.9e-12 at most.
TOLERANCE = 1e-11
OUTPUTS = ("displacements.json", "pressures.json", "resultant.json")


def _checkpointed(resume_label=None):
    """Adds to a case's parameters a checkpoint at every step and, with ``resume_label``, the import
    of that checkpoint."""
    def more(parameters, part):
        parameters["problem_data"].update(time_step=TIME_STEP, end_time=STEPS * TIME_STEP * (1 - 1e-9))
        parameters.setdefault("output_processes", {})["restart_processes"] = [
            {"python_module": "save_restart_process", "kratos_module": "KratosMultiphysics",
             "Parameters": {"model_part_name": part, "restart_control_type": "step", "restart_save_frequency": 1}}]
        if resume_label is not None:
            parameters["solver_settings"]["model_import_settings"] = resume_settings(resume_label)
    return more


def _run_case(folder, processes: int, resume_label=None):
    folder.mkdir(exist_ok=True)
    _write_cut_case(folder, "hertz2d-mumps", _checkpointed(resume_label))
    done = _run(folder, processes, ENV if processes == 1 else PARTITIONED)
    assert done.returncode == 0, done.stdout + done.stderr


def _history(folder) -> list[tuple[str, str]]:
    with open(os.path.join(folder, "history.csv")) as f:
        return [(row["step"], row["iteration"]) for row in csv.DictReader(f)]


@pytest.fixture(scope="module")
def uninterrupted(tmp_path_factory):
    """The case run whole on one process and on 2 ranks with the model cut: {processes: folder}."""
    root = tmp_path_factory.mktemp("uninterrupted")
    folders = {}
    for processes in (1, 2):
        folders[processes] = root / f"ranks{processes}"
        _run_case(folders[processes], processes)
    return folders


def _numbers(value, found: dict, key: str = ""):
    """``value`` (parsed JSON) with its numbers replaced by None, collected into ``found`` under the
    variable of the key they are under (e.g. every node's DISPLACEMENT_X, _Y and _Z together)."""
    if isinstance(value, dict):
        return {name: _numbers(entry, found, re.sub("_[XYZ]$", "", name)) for name, entry in value.items()}
    if isinstance(value, list):
        return [_numbers(entry, found, key) for entry in value]
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        found.setdefault(key, []).append(value)
        return None
    return value


def _assert_close(serial, cut, where: str) -> None:
    """Floats within TOLERANCE of the serial values' largest (exactly when it is 0); anything else
    exactly."""
    serial, cut = np.asarray(serial), np.asarray(cut)
    assert (serial.shape, serial.dtype) == (cut.shape, cut.dtype), where
    if serial.dtype.kind == "f":
        scale = np.abs(serial).max(initial=0.0)
        worst = np.abs(serial - cut).max(initial=0.0)
        assert worst <= TOLERANCE * scale, f"{where}: {worst:.3g} against {scale:.3g}"
    else:
        assert np.array_equal(serial, cut), where


def _assert_close_json(serial: str, cut: str, where: str) -> None:
    """The same JSON structure, its numbers close (``_assert_close``, those under one key together)."""
    serial_numbers, cut_numbers = {}, {}
    assert _numbers(json.loads(serial), serial_numbers) == _numbers(json.loads(cut), cut_numbers), where
    for key, values in serial_numbers.items():
        _assert_close(np.asarray(values, float), np.asarray(cut_numbers[key], float), f"{where} {key}")


def _run_folder(checkpoint: str) -> str:
    return os.path.dirname(os.path.dirname(checkpoint))


def _assert_same_checkpoint(serial_path: str, cut_path: str) -> None:
    with h5py.File(serial_path, "r") as serial, h5py.File(cut_path, "r") as cut:
        serial_mesh, cut_mesh = (json.loads(f.attrs["mesh"]) for f in (serial, cut))
        for mesh in (serial_mesh, cut_mesh):
            mesh.pop("mesh_file")  # each run's own folder
        assert serial_mesh == cut_mesh
        assert {k: v for k, v in serial.attrs.items() if k != "mesh"} == \
               {k: v for k, v in cut.attrs.items() if k != "mesh"}
        names, cut_names = [], []
        serial.visit(names.append)
        cut.visit(cut_names.append)
        assert names == cut_names
        for name in names:
            if not isinstance(serial[name], h5py.Dataset):
                continue
            if serial[name].dtype.kind == "O":  # the processes' and the solver's JSON states, which name
                # the run's folder
                states = (f[name][()].decode().replace(_run_folder(path), "")
                          for f, path in ((serial, serial_path), (cut, cut_path)))
                _assert_close_json(*states, name)
            else:
                _assert_close(serial[name][()], cut[name][()], name)
        info, cut_info = serial["process_info"].attrs, cut["process_info"].attrs
        assert sorted(info) == sorted(cut_info)
        for key, value in info.items():
            _assert_close(value, cut_info[key], f"process_info {key}")


@pytest.mark.parametrize("step", range(1, STEPS + 1))
def test_the_checkpoint_of_a_cut_model_is_the_serial_runs(uninterrupted, step):
    serial, cut = (checkpoint_path(uninterrupted[n], step) for n in (1, 2))
    with h5py.File(serial, "r") as f:  # a contact case, or the test proves little
        assert np.count_nonzero(f["nodes/flags/ACTIVE"][()] == 1) >= 2
        assert np.abs(f["nodes/historical/ACCELERATION"][0]).max() > 0.0
    _assert_same_checkpoint(serial, cut)
    # Gathered exactly: the 2-rank checkpoint holds the values that run wrote for every node.
    with h5py.File(cut, "r") as f:
        ids = f["nodes/ids"][()]
        for name, variable, values in (
                ("displacements.json", "DISPLACEMENT_Y", f["nodes/historical/DISPLACEMENT"][0][:, 1]),
                ("pressures.json", "CONTACT_PRESSURE", f["nodes/non_historical/CONTACT_PRESSURE/values"][()])):
            written = {int(key[len("NODE_"):]): node[variable][step - 1]
                       for key, node in _json_file(uninterrupted[2], name).items() if key.startswith("NODE_")}
            rows = np.searchsorted(ids, sorted(written))
            assert np.array_equal(values[rows], [written[node] for node in sorted(written)]), name


@pytest.mark.parametrize(("written_by", "resumed_on"), [(1, 2), (2, 2), (2, 1)])
def test_a_run_resumed_across_ranks_ends_with_the_uninterrupted_answers(uninterrupted, tmp_path, written_by,
                                                                         resumed_on):
    """Resumed after step 2 from a checkpoint of the serial or the cut run, on 2 ranks with the model
    cut or on one process: the uninterrupted serial run's JSON files (the series of the saved steps
    restored, the rest computed, the keys in the serial order) and Newton iterations."""
    folder = tmp_path / "resumed"
    saved = checkpoint_path(folder, RESUMED_AFTER)
    os.makedirs(os.path.dirname(saved))
    shutil.copy(checkpoint_path(uninterrupted[written_by], RESUMED_AFTER), saved)
    _run_case(folder, resumed_on, RESUMED_AFTER)
    serial = uninterrupted[1]
    for name in OUTPUTS:
        expected, resumed = _json_file(serial, name), _json_file(folder, name)
        assert list(resumed) == list(expected), f"{name}: other entities or another order"
        assert resumed["TIME"] == expected["TIME"]
        _assert_close_json(json.dumps(expected), json.dumps(resumed), name)
    assert _history(folder) == [row for row in _history(serial) if int(row[0]) > RESUMED_AFTER]
