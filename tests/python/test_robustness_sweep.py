"""Issue 10: a representative subset of the robustness sweep (benchmarks/robustness) against
Kratos 10.4. Each folder in tests/cases/robustness holds a case's files and Kratos 10.4.4's values
for them (kratos_10_4.json: Newton iterations and convergence per step, every node's displacement,
the slave nodes' contact pressures), written by ``benchmarks/robustness/run_sweep.py --subset test
--snapshots tests/cases/robustness``. The goal on every case Kratos solves: converge in every step
in no more Newton iterations than Kratos in each step (test_convergence), with displacements and
contact pressures within 1e-6 of Kratos' relative to their largest value (test_agreement). Where
we miss a part today, that test is an expected failure (strict, so that a fix shows as XPASS)."""
from __future__ import annotations

import contextlib
import functools
import json
import os

import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.project_parameters import read_project_parameters

CASES = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "cases", "robustness"))
TOLERANCE = 1e-6

#: A few seconds in total: the sweep's coarse cases (the smallest that show each behaviour).
FAST = [
    "2d_quad_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse",
    "2d_quad_flat_r0.5_overhang-none_gap_disp_1step_comp_coarse",
    "2d_quad_flat_r0.5_overhang-none_gap_disp_1step_alm_rot30_coarse",
    "2d_quad_flat_r0.5_overhang-none_pen_line-load_1step_alm_coarse",
    "2d_quad_flat_r0.5_overhang-master_gap_disp_1step_alm_coarse",
    "2d_quad_flat_r1_overhang-both_gap_disp_1step_alm_coarse",
    "2d_quad_curved_r0.5_overhang-none_gap_disp_1step_alm_coarse",
    "2d_tri_curved_r1_overhang-slave_gap_disp_1step_alm_coarse",
    "3d_hex_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse",
    "3d_tet-on-hex_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse",
    "3d_hex_flat_r0.5_overhang-both-xy_gap_disp_1step_alm_coarse",
    "3d_hex_curved_r0.5_overhang-none_gap_disp_1step_alm_coarse",
    "3d_tet-on-hex_curved_r1_overhang-none_gap_disp_1step_alm_coarse",
]
#: The longer ones (run with -m slow).
SLOW = [
    "3d_hex_flat_r0.5_overhang-slave-xy_gap_disp_4steps_alm_coarse",
    "2d_tri_curved_r1_overhang-slave_gap_disp_1step_alm",
    "2d_quad_flat_r0.5_overhang-none_gap_disp_20steps_alm",
    "3d_hex_flat_r0.5_overhang-none_gap_disp_4steps_alm",
]
PARTLY_COVERED = ("the slave faces along the master's edge are only partly covered; our extra iteration "
                  "and pressures there differ")
CLIPPING = "mortar integration raises 'clipped polygon with more than 8 vertices' (3D, curved slave faces)"
#: case -> why we do not converge in every step in no more iterations than Kratos today
CONVERGENCE = {
    "2d_quad_flat_r1_overhang-both_gap_disp_1step_alm_coarse": f"4 iterations, Kratos 3: {PARTLY_COVERED}",
    "3d_hex_flat_r0.5_overhang-both-xy_gap_disp_1step_alm_coarse": f"4 iterations, Kratos 3: {PARTLY_COVERED}",
    "2d_quad_curved_r0.5_overhang-none_gap_disp_1step_alm_coarse":
        "no convergence in 30 iterations (Kratos: 3): the two slave end nodes, 0.13 above the master, "
        "switch between contact and separation in every iteration",
    "3d_hex_flat_r0.5_overhang-slave-xy_gap_disp_4steps_alm_coarse":
        "steps 1, 2 and 4 stop at 30 iterations (Kratos: 2, 3, 2, 3): slave faces partly covered by the "
        "master in two directions",
    "3d_hex_curved_r0.5_overhang-none_gap_disp_1step_alm_coarse": f"{CLIPPING} (Kratos: 4 iterations)",
    "3d_tet-on-hex_curved_r1_overhang-none_gap_disp_1step_alm_coarse":
        f"{CLIPPING}, although no node comes into contact (Kratos: 1 iteration)",
}
EDGES = ("pressures at the slave nodes on the interface's boundary differ by about 1e-3 (the upper body, "
         "softer, expands past the master's edge, so the boundary faces are partly covered); and our "
         "accepted iterate is about 1e-5 from the converged solution, Kratos' about 1e-7")
#: case -> why our solution differs from Kratos' by more than TOLERANCE today
AGREEMENT = {name: EDGES for name in FAST + SLOW if "_flat_" in name and "overhang-none" in name}
AGREEMENT.update({
    "2d_quad_flat_r0.5_overhang-master_gap_disp_1step_alm_coarse":
        "pressure at the slave end nodes (inside the master) differs by 6e-3; accepted iterate less converged",
    "2d_quad_flat_r1_overhang-both_gap_disp_1step_alm_coarse": f"pressures differ by 0.4: {PARTLY_COVERED}",
    "3d_hex_flat_r0.5_overhang-both-xy_gap_disp_1step_alm_coarse": f"pressures differ by 31: {PARTLY_COVERED}",
    "2d_tri_curved_r1_overhang-slave_gap_disp_1step_alm_coarse":
        "curved interface with the master cut short: displacements differ by 3e-2",
    "2d_tri_curved_r1_overhang-slave_gap_disp_1step_alm":
        "curved interface with the master cut short: displacements differ by 7e-3",
})
AGREEMENT.update({name: "does not converge: " + reason for name, reason in CONVERGENCE.items()
                  if name not in AGREEMENT})

def _params(expected_failures: dict):
    for name in FAST + SLOW:
        marks = [pytest.mark.slow] if name in SLOW else []
        if name in expected_failures:
            marks.append(pytest.mark.xfail(strict=True, reason=expected_failures[name]))
        yield pytest.param(name, marks=marks, id=name)


def test_every_stored_case_is_listed():
    stored = sorted(d for d in os.listdir(CASES) if os.path.isdir(os.path.join(CASES, d)))
    assert stored == sorted(FAST + SLOW)
    assert set(CONVERGENCE) | set(AGREEMENT) <= set(stored)


def _kratos(name: str) -> dict:
    with open(os.path.join(CASES, name, "kratos_10_4.json")) as f:
        kratos = json.load(f)
    assert kratos["status"] == "ok"  # a case Kratos does not solve measures nothing
    return kratos


def _pressures(part, formulation: str) -> dict[str, float]:
    """Contact pressure (compression positive) per slave node, as the sweep defines it."""
    scale = part.GetProcessInfo().GetValue(mc.GetVariable("SCALE_FACTOR"))
    out = {}
    for node in part.GetSubModelPart("Contact_slave").Nodes:
        if formulation == "alm":
            p = -scale * node.GetSolutionStepValue(mc.GetVariable("LAGRANGE_MULTIPLIER_CONTACT_PRESSURE"))
        elif formulation == "comp":
            p = scale * np.linalg.norm(node.GetSolutionStepValue(mc.GetVariable("VECTOR_LAGRANGE_MULTIPLIER")))
        else:
            p = -node.GetValue(mc.GetVariable("AUGMENTED_NORMAL_CONTACT_PRESSURE")) if node.Is(mc.ACTIVE) else 0.0
        out[str(node.Id)] = float(p)
    return out


@functools.lru_cache(maxsize=None)
def _run(name: str) -> dict:
    """Runs a case once (both tests read it): iterations and convergence per step, displacements
    and pressures."""
    folder = os.path.join(CASES, name)
    with contextlib.chdir(folder):
        parameters = read_project_parameters(os.path.join(folder, "ProjectParameters.json"))
        analysis = StructuralMechanicsAnalysis(mc.Model(), parameters, progress=False,
                                               stop_on_non_convergence=False, case_dir=folder)
        analysis.Run()
    part = analysis.model["Structure"]
    displacement = mc.GetVariable("DISPLACEMENT")
    return {"iterations": [it for _, _, it, _, _ in analysis.step_log],
            "converged": [converged for _, _, _, converged, _ in analysis.step_log],
            "displacements": {str(node.Id): list(node.GetSolutionStepValue(displacement)) for node in part.Nodes},
            "pressures": _pressures(part, _kratos(name)["formulation"])}


def _relative(ours: dict, theirs: dict) -> float:
    """Largest difference over the largest of Kratos' values (vectors: Euclidean norms)."""
    keys = sorted(theirs)
    a = np.array([ours[k] for k in keys], dtype=float).reshape(len(keys), -1)
    b = np.array([theirs[k] for k in keys], dtype=float).reshape(len(keys), -1)
    return float(np.linalg.norm(a - b, axis=1).max() / np.linalg.norm(b, axis=1).max())


@pytest.mark.parametrize("name", list(_params(CONVERGENCE)))
def test_convergence(name):
    ours, kratos = _run(name), _kratos(name)
    print(f"{name}: Newton iterations {ours['iterations']} (Kratos 10.4: {kratos['iterations']})")
    assert all(ours["converged"])
    assert len(ours["iterations"]) == len(kratos["iterations"])
    assert all(a <= b for a, b in zip(ours["iterations"], kratos["iterations"]))


@pytest.mark.parametrize("name", list(_params(AGREEMENT)))
def test_agreement(name):
    ours, kratos = _run(name), _kratos(name)
    assert all(ours["converged"])
    du = _relative(ours["displacements"], kratos["displacements"])
    dp = _relative(ours["pressures"], kratos["pressures"])
    print(f"{name}: displacements {du:.1e}, contact pressures {dp:.1e} from Kratos 10.4")
    assert du <= TOLERANCE and dp <= TOLERANCE
