"""Issue 13: restart of MPC contact. Beyond the nodal state every checkpoint holds, the MPC strategy
carries from step to step the slip direction s of every frictional node (the Coulomb force of a
slipping node in the next step's predictor solve, and its slip / stick decision, use it) and, with mesh
tying, the tie's operators D^-1 M measured at the first step (the faces are glued as they were meshed).
Both go into the checkpoint (its ``solver`` dataset), so that a run resumed at step 2 gives the
uninterrupted run's steps 3 and 4: the same Newton iterations and the same answers to 1e-10."""
from __future__ import annotations

import json
import os
import shutil

import h5py
import numpy as np
from test_mesh_tying import _cantilever_run
from test_restart import checkpoint_path, resume_settings

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis

from case_builder import fix_process, run_analysis, write_block_on_base

STEPS = 4


class _Saving(StructuralMechanicsAnalysis):
    """The analysis with a checkpoint at every step; resumed from the one of step ``resume`` if set."""

    resume = None

    def __init__(self, model, parameters, **kwargs):
        parameters.AddValue("output_processes", mc.Parameters(json.dumps({"restart_processes": [{
            "python_module": "save_restart_process", "kratos_module": "KratosMultiphysics",
            "Parameters": {"model_part_name": "Structure", "restart_control_type": "step",
                           "restart_save_frequency": 1}}]})))
        if self.resume is not None:
            parameters["solver_settings"].AddValue("model_import_settings",
                                                   mc.Parameters(json.dumps(resume_settings(self.resume))))
        super().__init__(model, parameters, **kwargs)


class _Resumed(_Saving):
    resume = 2


def _compare(folder, kept: str, whole, resumed) -> float:
    """The resumed run's last checkpoint against the uninterrupted run's (kept): the same flags and
    iterations; the largest difference of the displacements and reactions, relative to their largest
    value (returned)."""
    assert [entry[0] for entry in resumed.step_log] == [3, 4]
    assert [entry[2] for entry in resumed.step_log] == [entry[2] for entry in whole.step_log[2:]]
    assert all(entry[3] for entry in whole.step_log + resumed.step_log)
    largest = 0.0
    with h5py.File(kept, "r") as a, h5py.File(checkpoint_path(folder, STEPS), "r") as b:
        for flag in ("ACTIVE", "SLIP"):
            if f"nodes/flags/{flag}" in a:
                assert np.array_equal(a[f"nodes/flags/{flag}"][()], b[f"nodes/flags/{flag}"][()]), flag
        for name in ("DISPLACEMENT", "REACTION"):
            expected = a[f"nodes/historical/{name}"][0]
            difference = np.max(np.abs(b[f"nodes/historical/{name}"][0] - expected)) / np.max(np.abs(expected))
            largest = max(largest, difference)
    return largest


def _run_and_resume(folder, run):
    """run(analysis_class) -> analysis, in `folder`: the uninterrupted run, then the one resumed at step 2."""
    whole = run(_Saving)
    kept = os.path.join(folder, "uninterrupted.rest")
    shutil.copy(checkpoint_path(folder, STEPS), kept)
    with h5py.File(kept, "r") as f:
        state = json.loads(f["solver"][()])
    return whole, run(_Resumed), kept, state


def test_resumed_frictional_mpc_run_is_the_uninterrupted_one(tmp_path):
    """The 2D block pressed by its weight and pushed at its top corner by 2.5e-5 t: the rear nodes slip
    from step 1, the others follow; resumed at step 2, steps 3 and 4 take the uninterrupted run's Newton
    iterations (2, 3) and answers (measured: 1.9e-15 apart). Without s in the checkpoint the slipping
    nodes had no Coulomb force in the predictor solve of step 3 and started it sticking: 3 iterations
    instead of 2."""
    path = write_block_on_base(
        str(tmp_path), "block", block=(0.5, 0.1), base=(1.0, 0.25), cells=(8, 4, 12, 3), friction=0.3,
        gravity=(1.0e3, (0.0, -1.0, 0.0)), end_time=STEPS * (1 - 1e-9), time_step=1.0,
        solver={"solver_type": "Static", "mpc_contact_settings": {"contact_type": "Frictional"},
                "residual_relative_tolerance": 1e-12, "residual_absolute_tolerance": 1e-14, "max_iteration": 30},
        contact=("mpc_contact_process", {"contact_type": "Frictional"}))
    with open(os.path.join(tmp_path, path)) as f:
        parameters = json.load(f)
    parameters["processes"]["constraints_process_list"].append(
        fix_process("Structure.block_corner", ["2.5e-5*t", 0.0, 0.0], constrained=(True, False, False)))
    with open(os.path.join(tmp_path, path), "w") as f:
        json.dump(parameters, f)
    whole, resumed, kept, state = _run_and_resume(tmp_path, lambda cls: run_analysis(str(tmp_path), path, cls))
    slaves = [n for n in whole.model["Structure"].GetSubModelPart("Contact").Nodes if n.Is(mc.SLAVE)]
    slipping = [n.Id for n in slaves if n.Is(mc.ACTIVE) and n.Is(mc.SLIP)]
    difference = _compare(tmp_path, kept, whole, resumed)
    print(f"frictional MPC: iterations {[e[2] for e in whole.step_log]} / resumed {[e[2] for e in resumed.step_log]}; "
          f"{len(slipping)} of {len(slaves)} slave nodes slip at step {STEPS}; largest difference {difference:.1e}")
    assert slipping and len(slipping) < len(slaves)
    assert {row[0] for row in state["directions"]} >= set(slipping) and not state["tied"]
    assert difference < 1e-10


def test_resumed_mpc_mesh_tying_keeps_the_first_steps_tie(tmp_path):
    """The cut cantilever tied by constraints, loaded suddenly (Bossak, 4 steps of 0.05): resumed at step
    2, it keeps the tie of step 1 (its operators in the checkpoint) and gives the uninterrupted run's
    steps 3 and 4 (measured: 2.4e-14 apart; tied again at the deformed configuration of step 2, as
    before, 1.2e-6 apart)."""

    def run(cls):
        return _cantilever_run(str(tmp_path), "cantilever", True, mpc=True, dynamic=(0.05, 0.2 * (1 - 1e-9)),
                               analysis_class=cls)[0]

    whole, resumed, kept, state = _run_and_resume(tmp_path, run)
    difference = _compare(tmp_path, kept, whole, resumed)
    print(f"MPC mesh tying: iterations {[e[2] for e in whole.step_log]} / resumed "
          f"{[e[2] for e in resumed.step_log]}; largest difference {difference:.1e}")
    assert state["tied"] and len(state["tying_operators"]) == 9  # the slave side's 9 nodes across the cut
    assert difference < 1e-10

