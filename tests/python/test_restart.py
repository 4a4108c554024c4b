"""Issue 15, item 5: restart. ``save_restart_process`` writes HDF5 checkpoints; a run resumed from
one (``model_import_settings.input_type`` "rest", or the legacy ``restart_options``) ends bit for
bit where the uninterrupted run ends: every nodal value of every buffer position, the flags, the
non-historical values and the ProcessInfo, and its VTU/PVD output goes on where the saved run
stopped. Bad checkpoints fail with a message naming the file and what differs."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import run_case
from mortarcontact.restart import Checkpoint

from csma_cases import CSMA_CASES

#: the Hertz cylinder on a plate of Kratos' CSMA suite (2D, ALM frictionless, line load ramp)
HERTZ = os.path.join(CSMA_CASES, "ALM_frictionless_contact_test_2D", "simple_hertz_sphere_plate_test")
#: Kratos' dynamic (Bossak) patch of the same suite
TAYLOR = os.path.join(CSMA_CASES, "ALM_frictionless_contact_test_2D", "taylor_patch_dynamic_test")


def write_case(folder, case: str, *, solver_type: str, time_step: float, end_time: float,
               import_settings: dict | None = None, restart_every: int = 2, extra: dict | None = None) -> str:
    """The case's parameters with our time stepping, VTU output, a checkpoint every
    ``restart_every`` steps and no json check (its reference has other time steps)."""
    with open(f"{case}_parameters.json") as f:
        params = json.load(f)
    params["problem_data"]["end_time"] = end_time
    solver = params["solver_settings"]
    stepping = solver["time_stepping"] if "time_stepping" in solver else params["problem_data"]
    stepping["time_step"] = time_step
    # The kept factorization (reuse_factorization) refactorizes when the measured CPU time of its
    # substitutions exceeds that of a factorization: whether step 3 of the uninterrupted run is
    # solved by GMRES on step 2's factors or afresh, as the resumed run does, depends on the machine,
    # and the two answers then agree to the Krylov tolerance, not bit for bit. The direct solve at
    # every iteration makes the comparison exact.
    solver.setdefault("linear_solver_settings", {})["reuse_factorization"] = False
    solver["solver_type"] = solver_type
    solver["model_import_settings"] = import_settings or {"input_type": "mdpa", "input_filename": case}
    materials = solver.get("material_import_settings", {}).get("materials_filename")
    if materials:
        solver["material_import_settings"]["materials_filename"] = os.path.join(CSMA_CASES, materials)
    params["processes"].pop("json_check_process", None)
    params["processes"]["json_output"] = [{
        "python_module": "json_output_process", "kratos_module": "KratosMultiphysics",
        "Parameters": {"model_part_name": "Structure", "output_file_name": "results.json",
                       "output_variables": ["DISPLACEMENT_Y"], "time_frequency": 0.0}}]
    params["output_processes"] = {
        "restart_processes": [{"python_module": "save_restart_process", "kratos_module": "KratosMultiphysics",
                               "Parameters": {"model_part_name": "Structure", "restart_control_type": "step",
                                              "restart_save_frequency": restart_every}}],
        "vtk_output": [{"python_module": "vtk_output_process", "kratos_module": "KratosMultiphysics",
                        "Parameters": {"model_part_name": "Structure.Contact",
                                       "nodal_solution_step_data_variables": ["DISPLACEMENT"],
                                       "nodal_flags": ["ACTIVE"]}}]}
    params.update(extra or {})
    path = os.path.join(folder, "ProjectParameters.json")
    with open(path, "w") as f:
        json.dump(params, f, indent=2)
    return path


def resume_settings(label) -> dict:
    return {"input_type": "rest", "input_filename": "Structure", "restart_load_file_label": str(label)}


def checkpoint_path(folder, label) -> str:
    return os.path.join(folder, "Structure__restart_files", f"Structure_{label}.rest")


def assert_same_checkpoints(first: str, second: str) -> None:
    """Every dataset and attribute of two checkpoints equal bit for bit (the mesh record and the
    process states included)."""
    with h5py.File(first, "r") as a, h5py.File(second, "r") as b:
        assert dict(a.attrs) == dict(b.attrs)
        names_a, names_b = [], []
        a.visit(names_a.append)
        b.visit(names_b.append)
        assert names_a == names_b
        for name in names_a:
            if isinstance(a[name], h5py.Dataset):
                assert a[name].dtype == b[name].dtype, name
                assert np.array_equal(a[name][()], b[name][()]), name
            assert {k: np.asarray(v).tolist() for k, v in a[name].attrs.items()} == \
                   {k: np.asarray(v).tolist() for k, v in b[name].attrs.items()}, name


def run_cli(folder, parameters: str, threads: int = 1) -> str:
    """``mortarcontact run`` in a subprocess with ``threads`` OpenMP threads; its output."""
    env = {**os.environ, "OMP_NUM_THREADS": str(threads)}
    done = subprocess.run([sys.executable, "-m", "mortarcontact", "run", parameters, "--no-progress"], cwd=folder,
                          env=env, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return done.stdout


def run_and_resume(folder, case: str, solver_type: str, time_step: float, steps: int = 4, threads: int = 1):
    """Runs ``steps`` steps saving a checkpoint every 2, keeps the last checkpoint, resumes from
    step 2 and returns (kept checkpoint of the uninterrupted run, the resumed run's output)."""
    end = steps * time_step * (1 - 1e-9)
    run_cli(folder, write_case(folder, case, solver_type=solver_type, time_step=time_step, end_time=end), threads)
    kept = str(folder / "uninterrupted.rest")
    shutil.copy(checkpoint_path(folder, steps), kept)
    shutil.copy(folder / "results.json", folder / "uninterrupted.json")
    resumed = run_cli(folder, write_case(folder, case, solver_type=solver_type, time_step=time_step, end_time=end,
                                         import_settings=resume_settings(2)), threads)
    return kept, resumed


def nodal(path: str, name: str, step: int = 0) -> np.ndarray:
    """A flag's states (``nodes/flags/<FLAG>``) or a historical variable at a buffer position."""
    with h5py.File(path, "r") as f:
        return f[name][()] if name.startswith("nodes/flags") else f[f"nodes/historical/{name}"][step]


# One thread: the parallel assembly adds the contributions of elements and contact pairs in the
# order the threads reach them (atomic adds), so two uninterrupted runs with several threads differ
# in the last bits already; test_resumed_run_with_threads_differs_by_round_off measures it.
@pytest.mark.parametrize(("solver_type", "time_step"), [("Static", 0.025), ("Dynamic", 0.125)])
def test_resumed_hertz_run_is_bit_identical(tmp_path, solver_type, time_step):
    kept, resumed = run_and_resume(tmp_path, HERTZ, solver_type, time_step)
    assert f"2 steps to t = {4 * time_step:g}" in resumed
    # A contact case at the end, or the test proves little.
    assert np.count_nonzero(nodal(kept, "nodes/flags/ACTIVE") == 1) >= 4
    assert np.max(np.abs(nodal(kept, "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE"))) > 0.0
    if solver_type == "Dynamic":
        assert np.max(np.abs(nodal(kept, "ACCELERATION", step=1))) > 0.0
    assert_same_checkpoints(kept, checkpoint_path(tmp_path, 4))
    # The output continues: 4 VTU files and a collection listing all of them.
    with open(tmp_path / "VTK_Output" / "Structure.Contact.pvd") as f:
        pvd = f.read()
    assert [f"Structure.Contact_{i}.vtu" in pvd for i in range(1, 5)] == [True] * 4
    # The JSON series holds the four steps, as the uninterrupted run's.
    with open(tmp_path / "results.json") as f, open(tmp_path / "uninterrupted.json") as g:
        series = json.load(f)
        assert len(series["TIME"]) == 4 and series == json.load(g)


def test_resumed_dynamic_patch_is_bit_identical(tmp_path):
    """Kratos' Bossak patch test: the velocities and accelerations of the buffer carry over."""
    kept, _ = run_and_resume(tmp_path, TAYLOR, "Dynamic", 0.11)
    assert np.max(np.abs(nodal(kept, "VELOCITY"))) > 0.0
    assert_same_checkpoints(kept, checkpoint_path(tmp_path, 4))


#: The robustness sweep's 20-step flat punch: its contact zone stops changing after step 3, so the
#: extrapolating predictor acts from then on (one Newton iteration per step).
PUNCH = os.path.join(os.path.dirname(__file__), "..", "cases", "robustness",
                     "2d_quad_flat_r0.5_overhang-none_gap_disp_20steps_alm")


def test_resumed_run_with_the_extrapolating_predictor_is_bit_identical(tmp_path):
    """solver_settings.displacement_extrapolation skips a step that follows a change of contact
    state; that history is on the slave nodes (CONVERGED_CONTACT_STATES), so a checkpoint carries
    it and the resumed run extrapolates where the uninterrupted one did."""
    for name in os.listdir(PUNCH):
        if name.endswith((".msh", ".mdpa", "_materials.json")):
            shutil.copy(os.path.join(PUNCH, name), tmp_path)
    with open(os.path.join(PUNCH, "ProjectParameters.json")) as f:
        params = json.load(f)
    params["problem_data"]["end_time"] = 8 * params["solver_settings"]["time_stepping"]["time_step"] * (1 - 1e-9)
    params["solver_settings"]["displacement_extrapolation"] = True
    params["output_processes"] = {"restart_processes": [{
        "python_module": "save_restart_process", "kratos_module": "KratosMultiphysics",
        "Parameters": {"model_part_name": "Structure", "restart_control_type": "step", "restart_save_frequency": 2}}]}
    path = os.path.join(tmp_path, "ProjectParameters.json")
    for import_settings in (None, resume_settings(4)):
        if import_settings:
            params["solver_settings"]["model_import_settings"] = import_settings
        with open(path, "w") as f:
            json.dump(params, f)
        output = run_cli(tmp_path, path)
        if not import_settings:
            kept = str(tmp_path / "uninterrupted.rest")
            shutil.copy(checkpoint_path(tmp_path, 8), kept)
    assert "4 steps to t = 0.4" in output
    assert_same_checkpoints(kept, checkpoint_path(tmp_path, 8))
    with h5py.File(kept, "r") as f:
        states = f["nodes/non_historical/CONVERGED_CONTACT_STATES/values"][()]
        held = f["nodes/non_historical/CONVERGED_CONTACT_STATES/held"][()]
    # Contact at the end, unchanged in the last step: the state the predictor needs.
    assert np.count_nonzero(held) > 0 and np.count_nonzero(states[held.astype(bool)] == 0b0101) >= 4


def test_resumed_run_with_threads_differs_by_round_off(tmp_path):
    kept, _ = run_and_resume(tmp_path, HERTZ, "Dynamic", 0.125, threads=2)
    resumed = checkpoint_path(tmp_path, 4)
    assert np.array_equal(nodal(kept, "nodes/flags/ACTIVE"), nodal(resumed, "nodes/flags/ACTIVE"))
    for name in ("DISPLACEMENT", "VELOCITY", "ACCELERATION", "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE"):
        expected = nodal(kept, name)
        assert np.max(np.abs(nodal(resumed, name) - expected)) <= 1e-12 * np.max(np.abs(expected)), name


def test_resumed_run_in_process(tmp_path, monkeypatch):
    """The Python route (mc.run): the analysis goes on from the checkpoint's TIME and STEP."""
    monkeypatch.chdir(tmp_path)
    whole = run_case(write_case(tmp_path, HERTZ, solver_type="Static", time_step=0.025, end_time=0.1 * (1 - 1e-9)),
                     progress=False)
    resumed = run_case(write_case(tmp_path, HERTZ, solver_type="Static", time_step=0.025, end_time=0.1 * (1 - 1e-9),
                                  import_settings=resume_settings(2)), progress=False)
    assert [entry[0] for entry in resumed.step_log] == [3, 4]
    assert resumed.time == whole.time
    assert resumed.model["Structure"].ProcessInfo.GetValue(mc.IS_RESTARTED)
    assert not whole.model["Structure"].ProcessInfo.GetValue(mc.IS_RESTARTED)


def test_checkpoint_contents(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    run_case(write_case(tmp_path, HERTZ, solver_type="Static", time_step=0.025, end_time=0.05), progress=False)
    with h5py.File(checkpoint_path(tmp_path, 2), "r") as f:
        assert f.attrs["step"] == 2 and f.attrs["time"] == pytest.approx(0.05)
        assert f["nodes/historical/DISPLACEMENT"].shape[:2] == (2, f["nodes/ids"].size)  # both buffer positions
        assert {"ACTIVE", "SLAVE", "MASTER", "INTERFACE"} <= set(f["nodes/flags"])
        for name in ("TIME", "STEP", "DELTA_TIME", "SCALE_FACTOR", "INITIAL_PENALTY"):
            assert name in f["process_info"].attrs
        mesh = json.loads(f.attrs["mesh"])
        assert mesh["mesh_file"] == f"{HERTZ}.mdpa" and len(mesh["sha256"]) == 64
    assert oct(os.stat(checkpoint_path(tmp_path, 2)).st_mode & 0o777) == oct(0o666 & ~_umask())
    assert not [name for name in os.listdir(tmp_path / "Structure__restart_files") if name.endswith(".tmp")]


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def test_time_control_labels_and_max_files(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    path = write_case(tmp_path, HERTZ, solver_type="Static", time_step=0.025, end_time=0.1 * (1 - 1e-9))
    with open(path) as f:
        params = json.load(f)
    params["output_processes"]["restart_processes"][0]["Parameters"] = {
        "model_part_name": "Structure", "restart_control_type": "time", "restart_save_frequency": 0.03,
        "max_files_to_keep": 2, "output_path": "checkpoints"}
    with open(path, "w") as f:
        json.dump(params, f)
    analysis = run_case(path, progress=False)
    # time control: written when TIME passes 0.03 (t = 0.05), then 0.06 (0.075), then 0.09 (0.1);
    # the oldest of the three is removed
    assert sorted(os.listdir(tmp_path / "checkpoints")) == ["Structure_0.075.rest", "Structure_0.1.rest"]
    summary = analysis.Summary()
    assert "Structure_0.1.rest" in summary and "Structure_0.05.rest" not in summary


def test_legacy_restart_options(tmp_path):
    """The pre-2018 top-level block: SaveRestart every RestartFrequency steps, LoadRestart at Restart_Step
    (one thread, as in the bit-identity tests above)."""
    options = {"SaveRestart": True, "RestartFrequency": 2, "LoadRestart": False, "Restart_Step": 0}
    path = write_case(tmp_path, HERTZ, solver_type="Static", time_step=0.025, end_time=0.1 * (1 - 1e-9),
                      extra={"restart_options": options})
    with open(path) as f:
        params = json.load(f)
    del params["output_processes"]["restart_processes"]
    with open(path, "w") as f:
        json.dump(params, f)
    run_cli(tmp_path, path)
    assert sorted(os.listdir(tmp_path / "Structure__restart_files")) == ["Structure_2.rest", "Structure_4.rest"]
    kept = str(tmp_path / "uninterrupted.rest")
    shutil.copy(checkpoint_path(tmp_path, 4), kept)
    params["restart_options"]["LoadRestart"] = True
    params["restart_options"]["Restart_Step"] = 2
    with open(path, "w") as f:
        json.dump(params, f)
    assert "2 steps to t = 0.1" in run_cli(tmp_path, path)
    assert_same_checkpoints(kept, checkpoint_path(tmp_path, 4))


@pytest.fixture()
def saved_case(tmp_path, monkeypatch):
    """A folder with a checkpoint of step 2 and the parameters to resume from it."""
    monkeypatch.chdir(tmp_path)
    run_case(write_case(tmp_path, HERTZ, solver_type="Static", time_step=0.025, end_time=0.05), progress=False)
    return tmp_path


def _resume(folder, **changes):
    return run_case(write_case(folder, HERTZ, solver_type=changes.pop("solver_type", "Static"), time_step=0.025,
                               end_time=0.1, import_settings=changes.pop("import_settings", None)
                               or resume_settings(changes.pop("label", 2)), **changes),
                    progress=False)


def test_missing_checkpoint_names_the_file(saved_case):
    with pytest.raises(mc.InputError, match=r"restart checkpoint not found; looked for .*Structure_3\.rest "
                                            r"\(did you mean 'Structure_2\.rest'\?\); saved: Structure_2\.rest"):
        _resume(saved_case, label=3)


def test_cli_reports_a_bad_checkpoint_without_traceback(saved_case):
    with open(checkpoint_path(saved_case, 2), "r+b") as f:
        f.truncate(300)
    parameters = write_case(saved_case, HERTZ, solver_type="Static", time_step=0.025, end_time=0.1,
                            import_settings=resume_settings(2))
    done = subprocess.run([sys.executable, "-m", "mortarcontact", "run", parameters, "--no-progress"],
                          cwd=saved_case, capture_output=True, text=True, timeout=600)
    assert done.returncode == 2
    assert "Structure_2.rest is not a readable checkpoint" in done.stderr and "Traceback" not in done.stderr


def test_label_is_required(saved_case):
    with pytest.raises(mc.InputError, match="restart_load_file_label: required for input_type \"rest\""):
        _resume(saved_case, label="")


def test_corrupt_checkpoint(saved_case):
    path = checkpoint_path(saved_case, 2)
    with open(path, "r+b") as f:
        f.truncate(300)
    with pytest.raises(mc.InputError, match=r"Structure_2\.rest is not a readable checkpoint"):
        _resume(saved_case)


def test_foreign_hdf5_file(saved_case):
    with h5py.File(checkpoint_path(saved_case, 2), "w") as f:
        f["x"] = [1.0]
    with pytest.raises(mc.InputError, match="an HDF5 file but not a mortarcontact checkpoint"):
        _resume(saved_case)


def test_changed_mesh_is_refused(saved_case):
    with h5py.File(checkpoint_path(saved_case, 2), "r+") as f:
        mesh = json.loads(f.attrs["mesh"])
        mesh["sha256"] = "0" * 64
        f.attrs["mesh"] = json.dumps(mesh)
    with pytest.raises(mc.InputError, match=r"was written for the mesh .*simple_hertz_sphere_plate_test\.mdpa"):
        _resume(saved_case)


def test_node_count_mismatch(saved_case):
    with h5py.File(checkpoint_path(saved_case, 2), "r+") as f:
        ids = f["nodes/ids"][()]
        del f["nodes/ids"]
        f["nodes/ids"] = ids[:-1]
    with pytest.raises(mc.InputError, match=rf"has {ids.size - 1} nodes; Structure has {ids.size}"):
        _resume(saved_case)


def test_variable_list_mismatch(saved_case):
    """A checkpoint of a static run resumed by a dynamic solver: VELOCITY and ACCELERATION are missing."""
    with pytest.raises(mc.InputError, match=r"nodal \(historical\) variables differ: in the checkpoint only none, "
                                            r"in the model only \['ACCELERATION', 'VELOCITY'\]"):
        _resume(saved_case, solver_type="Dynamic")


def test_process_list_mismatch(saved_case):
    with pytest.raises(mc.InputError, match="must be those of the saved run"):
        _resume(saved_case, extra={"output_processes": {}})


def test_bad_save_settings(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    model = mc.Model()
    model.CreateModelPart("Structure")
    from mortarcontact.restart import SaveRestartProcess

    for settings, message in (({"restart_control_type": "steps"}, r"restart_control_type: \"steps\" is not one of"),
                              ({"max_files_to_keep": 0}, "max_files_to_keep: -1 .keep all. or a positive number"),
                              ({"restart_save_frequency": -1.0}, "restart_save_frequency: must be a non-negative")):
        with pytest.raises(mc.InputError, match=message):
            SaveRestartProcess(model, mc.Parameters(json.dumps({"model_part_name": "Structure", **settings})))


def test_checkpoint_class_reads_what_it_wrote(saved_case):
    checkpoint = Checkpoint(checkpoint_path(saved_case, 2))
    assert (checkpoint.step, checkpoint.model_part_name, checkpoint.buffer_size) == (2, "Structure", 2)
    checkpoint.close()


def test_resume_a_case_read_from_msh(tmp_path):
    """The checkpoint records the gmsh import settings; the resumed run reads the msh the same way."""
    from test_meshio_input import blocks_case

    parameters = blocks_case(str(tmp_path))
    with open(parameters) as f:
        params = json.load(f)
    params["problem_data"]["end_time"] = 4.0 * (1 - 1e-9)
    params["processes"]["constraints_process_list"][1]["Parameters"]["value"] = [None, "-0.01*t", None]
    params["output_processes"]["restart"] = [{"python_module": "save_restart_process",
                                              "Parameters": {"model_part_name": "Structure",
                                                             "restart_control_type": "step",
                                                             "restart_save_frequency": 2}}]
    with open(parameters, "w") as f:
        json.dump(params, f)
    run_cli(tmp_path, parameters)
    kept = str(tmp_path / "uninterrupted.rest")
    shutil.copy(checkpoint_path(tmp_path, 4), kept)
    with h5py.File(kept, "r") as f:
        assert json.loads(f.attrs["mesh"])["input_type"] == "gmsh"
    params["solver_settings"]["model_import_settings"] = resume_settings(2)
    with open(parameters, "w") as f:
        json.dump(params, f)
    assert "2 steps to t = 4" in run_cli(tmp_path, parameters)
    assert_same_checkpoints(kept, checkpoint_path(tmp_path, 4))


def test_xdmf_output_of_a_resumed_run_warns(tmp_path, monkeypatch, capsys):
    """An XDMF series is written whole at the end of a run: the resumed run's holds its own steps."""
    monkeypatch.chdir(tmp_path)
    for settings in (None, resume_settings(2)):
        path = write_case(tmp_path, HERTZ, solver_type="Static", time_step=0.025, end_time=0.05 if settings is None
                          else 0.1 * (1 - 1e-9), import_settings=settings)
        with open(path) as f:
            params = json.load(f)
        params["output_processes"]["vtk_output"][0]["Parameters"]["file_format"] = "xdmf"
        with open(path, "w") as f:
            json.dump(params, f)
        run_case(path, progress=False)
    assert "the XDMF series Structure.Contact.xdmf of a resumed run holds only the steps after the restart" in \
        capsys.readouterr().err


def test_file_names_follow_kratos(tmp_path, monkeypatch):
    """<cwd>/<output_path or name__restart_files>/<name>_<label>.rest; a path in the name is kept."""
    from mortarcontact.restart import restart_file_name, restart_folder

    monkeypatch.chdir(tmp_path)
    assert restart_folder("Structure", "", True) == (str(tmp_path / "Structure__restart_files"), "Structure")
    assert restart_folder("Structure", "saved", True) == (str(tmp_path / "saved"), "Structure")
    assert restart_folder("runs/Structure", "", False) == (str(tmp_path / "runs"), "Structure")
    assert restart_file_name("Structure", 0.5) == "Structure_0.5.rest"


def test_folder_keys_of_saving_and_loading(tmp_path, monkeypatch):
    """save_restart_files_in_folder false saves next to the case, found with
    load_restart_files_from_folder false only; a legacy io_foldername is found with
    input_output_path."""
    monkeypatch.chdir(tmp_path)
    for place in ({"save_restart_files_in_folder": False}, {"io_foldername": "saved"}):
        path = write_case(tmp_path, HERTZ, solver_type="Static", time_step=0.025, end_time=0.05)
        with open(path) as f:
            params = json.load(f)
        params["output_processes"]["restart_processes"][0]["Parameters"].update(place)
        with open(path, "w") as f:
            json.dump(params, f)
        run_case(path, progress=False)
    assert os.path.isfile(tmp_path / "Structure_2.rest") and os.path.isfile(tmp_path / "saved" / "Structure_2.rest")
    beside = {**resume_settings(2), "load_restart_files_from_folder": False}
    with pytest.raises(mc.InputError, match="restart checkpoint not found"):
        _resume(tmp_path, import_settings={**beside, "load_restart_files_from_folder": True})
    assert _resume(tmp_path, import_settings=beside).step == 4
    assert _resume(tmp_path, import_settings={**resume_settings(2), "input_output_path": "saved"}).step == 4


def test_echo_level_and_serializer_trace_of_the_save_process(tmp_path, monkeypatch, capsys):
    """echo_level 1 names each checkpoint written; Kratos' serializer_trace is accepted and warns
    that it has no effect."""
    monkeypatch.chdir(tmp_path)
    path = write_case(tmp_path, HERTZ, solver_type="Static", time_step=0.025, end_time=0.05)
    with open(path) as f:
        params = json.load(f)
    params["output_processes"]["restart_processes"][0]["Parameters"].update(echo_level=1, serializer_trace="trace_all")
    with open(path, "w") as f:
        json.dump(params, f)
    messages = []
    mc._core.SetLogSink(lambda level, message: messages.append(message))
    try:
        run_case(path, progress=False)
    finally:
        mc._core.ResetLogSink()
    assert "save_restart_process: wrote" in capsys.readouterr().out
    assert any("key 'serializer_trace' = \"trace_all\"" in m and "has no effect in mortarcontact" in m
               for m in messages), messages
