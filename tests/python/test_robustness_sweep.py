"""Issue 10: a representative subset of the robustness sweep (benchmarks/robustness) against
Kratos 10.4. Each folder in tests/cases/robustness holds a case's files and Kratos 10.4.4's values
for them (kratos_10_4.json: Newton iterations and convergence per step, every node's displacement,
the slave nodes' contact pressures, as written and for the tight run), written by
``benchmarks/robustness/run_sweep.py --subset test --snapshots tests/cases/robustness``. The goal
on every case Kratos solves: converge in every step in no more Newton iterations than Kratos in
each step (test_convergence), with displacements and contact pressures within 1e-6 of Kratos'
relative to their largest value when both codes solve the case with the tight run's overrides
(test_agreement: tolerances 1e-12, normals updated before every iteration in Kratos too). Where
we miss a part today, or where Kratos' answer is the one that is off (the reason says which), that
test is an expected failure (strict, so that a change shows as XPASS)."""
from __future__ import annotations

import contextlib
import functools
import json
import os
import sys

import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.project_parameters import migrate_project_parameters

sys.path.insert(0, os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks", "hertz")))
from case_runner import overridden

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
    "2d_quad_flat_r0.5_overhang-both_gap_disp_4steps_alm",
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
    "2d_quad_flat_r0.5_overhang-none_pen_line-load_4steps_penalty":
        "penalty: after the first solve the weighted gap of the 4 outer slave nodes is +1e-9 (Kratos -4e-9), "
        "they leave the set and come back: 5 iterations in step 1, Kratos 4. Kratos' tangent there is not the "
        "derivative of its residual (1e-2 of |K|, benchmarks/robustness/kratos_tangent_check.py); ours is",
}
#: Kratos 10.4 leaves out, until its next step's search, the mortar overlaps a slave face gains by
#: sliding within the step onto a master face it only touched at the start (a slave node over a
#: master edge): its 1-step answers move with the number of load steps, ours do not
#: (test_answer_does_not_depend_on_the_load_steps; benchmarks/robustness/README.md).
KRATOS_ONE_STEP = "Kratos' 1-step answer misses the overlaps gained within the step: pressures differ by "
#: case -> why our solution differs from tight K1 Kratos' by more than TOLERANCE today
#: (benchmarks/robustness/README.md: the classes of remaining differences)
AGREEMENT = {
    "2d_quad_flat_r0.5_overhang-both_gap_disp_4steps_alm": "Kratos' tight run stops at 50 iterations in step 2",
    "3d_hex_flat_r0.5_overhang-both-xy_gap_disp_1step_alm_coarse": "both bodies overhanging in 3D: 3.2e-6",
    "3d_hex_flat_r0.5_overhang-none_gap_disp_4steps_alm":
        "Kratos leaves out the corner overlap (4.5e-6 of a slave face) a slave node over a master node gains: its "
        "pressure at the four nodes (+-0.1, +-0.1) is 4.4e-6 higher",
    "3d_hex_flat_r0.5_overhang-slave-xy_gap_disp_4steps_alm_coarse":
        "Kratos' tight run (K1): the four nodes of the slave face at 0 < x < 1/6, -1/6 < y < 0 carry 1.33 times "
        "our multipliers (9.4e-2 of the peak pressure) with weighted gaps of 5e-12 (1e-18 elsewhere), displacements "
        "within 1.7e-6; Kratos as written (K0) is ours there to 5e-5",
    "3d_hex_flat_r1.001_overhang-none_gap_disp_4steps_alm": "nearly matching 3D meshes: pressures differ by 7.1e-6",
    **{name: KRATOS_ONE_STEP + difference for name, difference in (
        ("2d_quad_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse", "7.9e-3"),
        ("2d_quad_flat_r0.5_overhang-none_gap_disp_1step_comp_coarse", "7.9e-3"),
        ("2d_quad_flat_r0.5_overhang-none_gap_disp_1step_alm_rot30_coarse", "7.9e-3"),
        ("2d_quad_flat_r0.5_overhang-none_pen_line-load_1step_alm_coarse", "6.6e-3"),
        ("2d_quad_flat_r0.5_overhang-master_gap_disp_1step_alm_coarse", "4.3e-2"),
        ("2d_quad_curved_r0.5_overhang-none_gap_disp_1step_alm_coarse", "4.7e-3"),
        ("2d_tri_curved_r1_overhang-slave_gap_disp_1step_alm_coarse", "7.4e-3"),
        ("2d_tri_curved_r1_overhang-slave_gap_disp_1step_alm", "9.1e-3"),
        ("3d_hex_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse", "4.0e-3"),
        ("3d_hex_curved_r0.5_overhang-none_gap_disp_1step_alm_coarse", "2.3e-4"),
        ("3d_tet-on-hex_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse", "4.7e-3"))},
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
def _run(name: str, tight: bool = False, steps: int = 0, search_factor: float = 0.0) -> dict:
    """Runs a case once per variant (as written, or with the overrides of Kratos' tight run; in
    `steps` equal load steps and with `search_factor` if given): iterations and convergence per
    step, displacements and pressures."""
    folder = os.path.join(CASES, name)
    overrides = _kratos(name)["tight"]["overrides"] if tight else []
    if steps:
        overrides = [*overrides, f"solver_settings.time_stepping.time_step={1.0 / steps!r}"]
    if search_factor:
        overrides = [*overrides, "processes.contact_process_list.0.Parameters.search_parameters.search_factor="
                     f"{search_factor!r}"]
    with contextlib.chdir(folder):
        with open("ProjectParameters.json") as f:
            parameters = mc.Parameters(overridden(f.read(), overrides))
        migrate_project_parameters(parameters)
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
    """Both codes at tight tolerances with the nodal normals updated before every iteration
    (Kratos' normal_variation no_derivatives_computation_with_normal_update): the same discrete
    problem solved to round-off, so the results must agree."""
    ours, kratos = _run(name, tight=True), _kratos(name)["tight"]
    assert kratos["status"] == "ok"
    assert all(ours["converged"])
    du = _relative(ours["displacements"], kratos["displacements"])
    dp = _relative(ours["pressures"], kratos["pressures"])
    print(f"{name}: displacements {du:.1e}, contact pressures {dp:.1e} from Kratos 10.4 (tight)")
    assert du <= TOLERANCE and dp <= TOLERANCE


#: 1-step cases whose slave slides over master edges within the step. Kratos 10.4's 1-step answers
#: (tight) are 7.9e-3 and 4.0e-3 (pressures) from the answer we give in 1 and in 4 steps.
PATH_INDEPENDENCE = ["2d_quad_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse",
                     "3d_hex_flat_r0.5_overhang-none_gap_disp_1step_alm_coarse"]


@pytest.mark.parametrize("name", PATH_INDEPENDENCE)
def test_answer_does_not_depend_on_the_load_steps(name):
    """Frictionless elastic contact has one answer whatever the load steps. The slave faces start
    over master edges, touching the master faces beyond; as the bodies deform the slave slides onto
    them within the step, before a search could pair them. Kratos 10.4 leaves those overlaps out
    until its next step's search: its answer moves with the number of steps and reaches ours as
    they get small (2d_tri_curved_r2_overhang-none_gap_disp_4steps_alm: 8.8e-3 from ours in 1
    step, 8.7e-4 in 4, 3.8e-9 in 16). Ours pairs them (ContactSearchProcess) and must give the same
    answer in 1 and in 4 steps."""
    one, four = _run(name, tight=True), _run(name, tight=True, steps=4)
    assert all(one["converged"]) and all(four["converged"])
    du = _relative(one["displacements"], four["displacements"])
    dp = _relative(one["pressures"], four["pressures"])
    print(f"{name}: 1 against 4 steps: displacements {du:.1e}, contact pressures {dp:.1e}")
    assert du <= 1e-9 and dp <= 1e-9


def test_answer_does_not_depend_on_the_search_factor():
    """The master faces are four times the slave's, and every fourth slave node starts over a master
    node: as the bodies spread, one of its faces slides past that node onto the next master face,
    whose centre is 2.5 slave faces away. Kratos 10.4 takes as candidates only the master faces
    whose centre lies within search_factor x half the slave face's size: with its default 3.5 it
    never pairs that face, and the pressure at those nodes is too high by the overlap it leaves out
    of their nodal area (1.6e-2 here; with search_factor 10 its answer is ours to 3.4e-9).
    Ours reaches every master face whose bounding ball meets the search ball, so the default
    factor already finds them."""
    name = "2d_quad_flat_r0.25_overhang-none_gap_disp_4steps_alm_coarse"
    default, wide = _run(name, tight=True, search_factor=3.5), _run(name, tight=True, search_factor=10.0)
    assert all(default["converged"]) and all(wide["converged"])
    du = _relative(default["displacements"], wide["displacements"])
    dp = _relative(default["pressures"], wide["pressures"])
    print(f"{name}: search_factor 3.5 against 10: displacements {du:.1e}, contact pressures {dp:.1e}")
    assert du <= 1e-12 and dp <= 1e-12
