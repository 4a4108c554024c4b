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

#: A few seconds in total: the sweep's coarse cases (the smallest that show each behaviour) and a
#: few small ones from its families.
FAST = [
    "2d_quad_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse",
    "2d_quad_flat_r0.5_overhang-none_gap_disp_1step_comp_coarse",
    "2d_quad_flat_r0.5_overhang-none_gap_disp_1step_alm_rot30_coarse",
    "2d_quad_flat_r0.5_overhang-none_pen_line-load_1step_alm_coarse",
    "2d_quad_flat_r0.5_overhang-master_gap_disp_1step_alm_coarse",
    "2d_quad_flat_r1_overhang-both_gap_disp_1step_alm_coarse",
    "2d_quad_flat_r0.25_overhang-none_gap_disp_4steps_alm_coarse",
    "2d_quad_curved_r0.5_overhang-none_gap_disp_1step_alm_coarse",
    "2d_tri_curved_r1_overhang-slave_gap_disp_1step_alm_coarse",
    "3d_hex_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse",
    "3d_tet-on-hex_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse",
    "3d_hex_flat_r0.5_overhang-both-xy_gap_disp_1step_alm_coarse",
    "3d_hex_curved_r0.5_overhang-none_gap_disp_1step_alm_coarse",
    "3d_tet-on-hex_curved_r1_overhang-none_gap_disp_1step_alm_coarse",
    "3d_hex_flat_r4_overhang-none_gap_disp_4steps_alm",
    "3d_hex_flat_r1.001_overhang-none_gap_disp_4steps_alm",
    "3d_hex_inclined_r2_overhang-none_gap_disp_4steps_alm",
    "2d_quad_flat_r0.5_overhang-none_gap_disp_4steps_penalty",
    "2d_quad_flat_r0.5_overhang-none_pen_line-load_4steps_penalty",
]
#: The longer ones (run with -m slow).
SLOW = [
    "3d_hex_flat_r0.5_overhang-slave-xy_gap_disp_4steps_alm_coarse",
    "2d_tri_curved_r1_overhang-slave_gap_disp_1step_alm",
    "2d_quad_flat_r0.5_overhang-none_gap_disp_20steps_alm",
    "3d_hex_flat_r0.5_overhang-none_gap_disp_4steps_alm",
]
#: case -> why we do not converge in every step in no more iterations than Kratos today
CONVERGENCE = {
    "3d_hex_flat_r1.001_overhang-none_gap_disp_4steps_alm":
        "nearly matching meshes (nodes 5e-4 apart): 3 iterations in step 1, Kratos 2",
    "3d_hex_inclined_r2_overhang-none_gap_disp_4steps_alm": "inclined interface: 3 iterations in step 1, Kratos 2",
    "2d_quad_flat_r0.5_overhang-none_pen_line-load_4steps_penalty": "penalty: 6 iterations in step 1, Kratos 4",
    "3d_hex_flat_r0.5_overhang-slave-xy_gap_disp_4steps_alm_coarse":
        "slave faces partly covered by the master in two directions: 3, 4 iterations in steps 1, 2, Kratos 2, 3",
}
FLAT = "flat interface: displacements and pressures differ by about 1e-5 (at a 1e-10 tolerance too)"
CURVED = "curved interface: displacements differ by 2e-3 to 4e-3 (at a 1e-10 tolerance too)"
PARTLY_COVERED = "slave faces partly covered by the master: displacements differ by 5e-4 to 7e-3"
#: case -> why our solution differs from Kratos' by more than TOLERANCE today (the two cases not
#: listed agree: 3d_hex_flat_r4, and the curved tet-on-hex case where no node touches in either code)
AGREEMENT = {
    **dict.fromkeys(["2d_quad_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse",
                     "2d_quad_flat_r0.5_overhang-none_gap_disp_1step_comp_coarse",
                     "2d_quad_flat_r0.5_overhang-none_gap_disp_1step_alm_rot30_coarse",
                     "2d_quad_flat_r0.5_overhang-none_pen_line-load_1step_alm_coarse",
                     "3d_tet-on-hex_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse",
                     "3d_hex_flat_r1.001_overhang-none_gap_disp_4steps_alm",
                     "2d_quad_flat_r0.5_overhang-none_gap_disp_4steps_penalty",
                     "2d_quad_flat_r0.5_overhang-none_pen_line-load_4steps_penalty",
                     "2d_quad_flat_r0.5_overhang-none_gap_disp_20steps_alm",
                     "3d_hex_flat_r0.5_overhang-none_gap_disp_4steps_alm"], FLAT),
    **dict.fromkeys(["2d_quad_curved_r0.5_overhang-none_gap_disp_1step_alm_coarse",
                     "3d_hex_curved_r0.5_overhang-none_gap_disp_1step_alm_coarse"], CURVED),
    **dict.fromkeys(["2d_quad_flat_r1_overhang-both_gap_disp_1step_alm_coarse",
                     "3d_hex_flat_r0.5_overhang-both-xy_gap_disp_1step_alm_coarse",
                     "3d_hex_flat_r0.5_overhang-slave-xy_gap_disp_4steps_alm_coarse",
                     "2d_tri_curved_r1_overhang-slave_gap_disp_1step_alm_coarse",
                     "2d_tri_curved_r1_overhang-slave_gap_disp_1step_alm"], PARTLY_COVERED),
    "2d_quad_flat_r0.5_overhang-master_gap_disp_1step_alm_coarse":
        "slave ends inside the master: the pressure at x = -0.1 differs by 6e-3",
    "2d_quad_flat_r0.25_overhang-none_gap_disp_4steps_alm_coarse":
        "fine slave: the pressure at x = +-0.3 (above master nodes) differs by 1.6e-2",
    "3d_hex_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse":
        "one load step: displacements differ by 3e-3 at any tolerance (2e-6 in four steps on the finer mesh)",
    "3d_hex_inclined_r2_overhang-none_gap_disp_4steps_alm": "inclined interface: displacements differ by 1.3e-4",
}

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


@functools.cache
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
    """Largest difference over the largest of Kratos' values (vectors: Euclidean norms); the
    difference itself where Kratos' values are all zero (no contact)."""
    keys = sorted(theirs)
    a = np.array([ours[k] for k in keys], dtype=float).reshape(len(keys), -1)
    b = np.array([theirs[k] for k in keys], dtype=float).reshape(len(keys), -1)
    worst, scale = np.linalg.norm(a - b, axis=1).max(), np.linalg.norm(b, axis=1).max()
    return float(worst / scale if scale > 0.0 else worst)


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
