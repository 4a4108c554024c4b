"""Issue 3: the frictionless Kratos CSMA cases run unchanged, pass their own
from_json_check_result_process and match the reference values to 1e-3 relative; the 2D Hertz case
matches Hertz theory."""
from __future__ import annotations

import importlib.util
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.cases import hertz
from mortarcontact.project_parameters import read_project_parameters

from csma_cases import (
    CSMA_CASES,
    FRICTIONAL_CASES,
    FRICTIONLESS_CASES,
    KRATOS_SNAPSHOTS,
    check_blocks,
    reference_nodes,
    reference_values,
    use_components,
    worst_difference,
)

HERTZ_RUNNER = os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks", "hertz", "case_runner.py")

# Strict relative tolerance against the reference files, per case. Kratos 10.4 itself no
# longer reproduces some of them (benchmarks/kratos_cases/snapshot_kratos.py): the slope patch
# reference is 9e-4 from the exact -0.15 / -0.05 that both Kratos 10.4 and we compute, and the
# tri-on-quad reference is 3.7e-3 from us and 9.6e-3 from Kratos 10.4. The dynamic Taylor patch
# reference differs from Kratos 10.4 by up to 60 % and is compared with Kratos 10.4 only.
SHARED_TOLERANCE = {
    "hyper_simple_patch_test": 1e-3,
    "hyper_simple_patch_test_with_elimination_with_constraints": 1e-3,
    "hyper_simple_slope_patch_test": 1e-3,
    "hyper_simple_triangle_patch_test": 1e-3,
    "3D_contact_simplest_patch_matching_triquad_test": 5e-3,
}
# Tolerance against Kratos 10.4.4 on the same files (tests/cases/kratos_10_4), relative to the
# largest magnitude of each variable over the checked nodes. The tri-on-quad case differs by 7.6e-3:
# Kratos 10.4's master normals there are tilted by 0.1 although the deformed master face is flat
# to 3e-3, and its converged weighted gaps stay at 1e-6 (ours close to 1e-11); noted on issue 3.
KRATOS_TOLERANCE = {
    "hyper_simple_patch_test": 1e-9,
    "hyper_simple_patch_test_with_elimination_with_constraints": 1e-9,
    "hyper_simple_slope_patch_test": 1e-9,
    "hyper_simple_triangle_patch_test": 1e-9,
    "3D_contact_simplest_patch_matching_triquad_test": 1e-2,
    "taylor_patch_dynamic_test": 1e-3,
    # 50 % compression of two hyperelastic cubes (the law alone matches Kratos 10.4 to 3e-12 there)
    "3D_contact_simplest_patch_matching_test": 3e-3,
}
# Kratos 10.4's components run of this case stops at max_iteration in its second step with zero
# lateral displacements (its scalar run gives 0.146): both formulations must give the same
# solution, so ours is held to Kratos' scalar run.
KRATOS_YARDSTICK = {("3D_contact_simplest_patch_matching_test", "components"): "scalar"}
RUNS = [(case, formulation) for case, formulations in FRICTIONLESS_CASES for formulation in formulations]


#: Checked variables read with GetValue (the reference files mark them historical_value false).
NON_HISTORICAL = {"AUGMENTED_NORMAL_CONTACT_PRESSURE"}


class SnapshotAnalysis(StructuralMechanicsAnalysis):
    """Keeps the requested nodal values at one time (the reference's check time)."""

    def __init__(self, model, params, time, nodes):
        super().__init__(model, params, progress=False)
        self.snapshot_time, self.snapshot_nodes, self.snapshot = time, nodes, {}

    def FinalizeSolutionStep(self):
        super().FinalizeSolutionStep()
        part = self.model[self.parameters["solver_settings"]["model_part_name"].GetString()]
        time = part.ProcessInfo.GetValue(mc.GetVariable("TIME"))
        if abs(time - self.snapshot_time) > 1e-9 * max(1.0, abs(time)):
            return
        for key, names in self.snapshot_nodes.items():
            node = part.GetNode(int(key[len("NODE_"):]))
            self.snapshot[key] = {
                name: node.GetValue(mc.GetVariable(name)) if name in NON_HISTORICAL
                else node.GetSolutionStepValue(mc.GetVariable(name)) for name in names}



def run_csma_case(case: str, formulation: str = "scalar", own_checks: bool = True):
    """Runs the case as written (``scalar``, ``frictional``) or switched to ``components``; without
    its json check processes if not ``own_checks``."""
    params = read_project_parameters(os.path.join(CSMA_CASES, f"{case}_parameters.json"))
    if not own_checks:
        params["processes"].RemoveValue("json_check_process")
    if formulation == "components":
        use_components(params)
    time, nodes = reference_values(case)
    analysis = SnapshotAnalysis(mc.Model(), params, time, nodes)
    analysis.Run()  # the case's own json checks raise on failure
    assert analysis.snapshot, f"{case}: the check time {time} was never reached"
    return analysis, params


@pytest.mark.parametrize("case,formulation", RUNS, ids=[f"{os.path.basename(c)}-{f}" for c, f in RUNS])
def test_frictionless_case(csma_cases, monkeypatch, case, formulation):
    """Runs unchanged (its own Kratos checks pass), in no more Newton iterations than Kratos 10.4;
    matches the reference file to the strict tolerance and Kratos 10.4 on the same run."""
    monkeypatch.chdir(csma_cases)
    analysis, params = run_csma_case(case, formulation)
    name = os.path.basename(case)
    iterations = [it for _, _, it, _, _ in analysis.step_log]
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    assert max(iterations) <= params["solver_settings"]["max_iteration"].GetInt()

    if name in SHARED_TOLERANCE:
        compared = 0
        for input_file, _, variables, _ in check_blocks(case):
            with open(input_file) as f:
                reference = json.load(f)
            for key, node in analysis.snapshot.items():
                for variable in variables:
                    if key not in reference or variable not in reference[key]:
                        continue
                    expected = reference[key][variable][-1]
                    assert node[variable] == pytest.approx(expected, rel=SHARED_TOLERANCE[name],
                                                           abs=1e-9 * max(1.0, abs(expected))), f"{key} {variable}"
                    compared += 1
        assert compared >= 4

    yardstick = KRATOS_YARDSTICK.get((name, formulation), formulation)
    with open(os.path.join(KRATOS_SNAPSHOTS, f"{name}_{yardstick}.json")) as f:
        kratos = json.load(f)
    assert kratos["time"] == pytest.approx(analysis.snapshot_time)
    difference = worst_difference(analysis.snapshot, kratos["nodes"])
    print(f"{name} ({formulation}): {sum(iterations)} Newton iterations in {len(iterations)} steps "
          f"(Kratos 10.4: {sum(kratos['newton_iterations'])}), difference to Kratos 10.4: {difference:.1e}")
    assert difference <= KRATOS_TOLERANCE[name]
    assert len(iterations) == len(kratos["newton_iterations"])
    assert sum(iterations) <= sum(kratos["newton_iterations"])


# Issue 12. Kratos 10.4.4 itself differs from the frictional reference files (older revisions) by
# FRICTIONAL_REFERENCE_GAP (worst_difference, measured with benchmarks/kratos_cases/snapshot_kratos.py);
# ours is held to that gap plus 1e-3 against the reference, and to FRICTIONAL_KRATOS_TOLERANCE
# against Kratos 10.4 on the same files. The friction block has its own test (test_friction_block).
FRICTIONAL_REFERENCE_GAP = {
    "hyper_simple_patch_test": 1.3e-2,
    "threshold_slip_hyper_simple_patch_test": 5.6e-3,
    "mesh_moving_matching_test": 6.4e-3,
    "hyper_simple_slip_patch_test": 1.7e-2,
}
FRICTIONAL_KRATOS_TOLERANCE = {
    "hyper_simple_patch_test": 1e-3,
    "threshold_slip_hyper_simple_patch_test": 1e-3,
    "mesh_moving_matching_test": 1e-3,
    "hyper_simple_slip_patch_test": 1e-3,
}
# Kratos 10.4's penalty friction takes the virtual work of the tangential traction on the variation
# of the slip increment ((D - D_n) w1 - (M - M_n) w2), not on the virtual jump (D w1 - M w2): on the
# penalty slip patch it transmits no friction at all (the same displacements to 12 digits for
# FRICTION_COEFFICIENT 0, 0.01 and 0.05, and our run with mu = 0 to 3e-5), so its values and its 4
# Newton iterations are those of a frictionless problem. The reference file (an older revision)
# transmits it, and is the yardstick (ours: 1.1e-2 from it at the case's residual tolerance, Kratos
# 10.4: 1.7e-2); ours converges in 7 iterations (the first one sticks, the
# tangential spring releases the interface, which opens once and closes again).
KRATOS_WITHOUT_FRICTION = {"hyper_simple_slip_patch_test": 7}
# The pure-slip moving-mesh case checks its reference file at every t = 1, 2, 3.05, ...: at t = 1
# Kratos 10.4 misses it as we do (u_x of nodes 15, 20, 26 by 2.6e-3, tolerance 1e-3; we match
# Kratos 10.4 there to 6e-6), so its own json check is left out; the last time (17.3) is compared
# with the reference and Kratos 10.4 as for every case.
KRATOS_MISSES_OWN_CHECK = {"mesh_moving_matching_test"}
#: The penalty stick patch (adapt_penalty) is tested in test_adaptive_penalty.py: Kratos 10.4 and its
#: reference file check a collapsed penalty there (the blocks overlap by 64 times max_gap). The
#: friction block: test_friction_block below.
CHECKED_ELSEWHERE = {"hyper_simple_stick_patch_test", "friction_block_test"}
#: Hundreds of steps: run with -m slow.
SLOW = {"mesh_moving_matching_test"}


def _frictional_params(case: str):
    name = os.path.basename(case)
    marks = []
    if name in SLOW:
        marks.append(pytest.mark.slow)
    return pytest.param(case, id=name, marks=marks)


@pytest.mark.parametrize("case", [_frictional_params(case) for case, _ in FRICTIONAL_CASES
                                  if os.path.basename(case) not in CHECKED_ELSEWHERE])
def test_frictional_case(csma_cases, monkeypatch, case):
    """The frictional Kratos cases (ALM stick/slip and threshold slip, ALM pure slip on a moving
    mesh, penalty stick and slip) run unchanged, their own json checks pass,
    and the checked values match the reference file and Kratos 10.4 on the same files, in no more
    Newton iterations than Kratos 10.4."""
    monkeypatch.chdir(csma_cases)
    name = os.path.basename(case)
    analysis, _ = run_csma_case(case, "frictional", own_checks=name not in KRATOS_MISSES_OWN_CHECK)
    iterations = [it for _, _, it, _, _ in analysis.step_log]
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    to_reference = worst_difference(analysis.snapshot, reference_nodes(case))
    print(f"{name}: {sum(iterations)} Newton iterations in {len(iterations)} steps, difference to the "
          f"reference {to_reference:.1e}")
    assert to_reference <= FRICTIONAL_REFERENCE_GAP[name] + 1e-3
    if name in KRATOS_WITHOUT_FRICTION:
        assert sum(iterations) <= KRATOS_WITHOUT_FRICTION[name]
        return
    with open(os.path.join(KRATOS_SNAPSHOTS, f"{name}_frictional.json")) as f:
        kratos = json.load(f)
    to_kratos = worst_difference(analysis.snapshot, kratos["nodes"])
    print(f"{name}: Kratos 10.4 {sum(kratos['newton_iterations'])} Newton iterations, difference {to_kratos:.1e}")
    assert to_kratos <= FRICTIONAL_KRATOS_TOLERANCE[name]
    assert len(iterations) == len(kratos["newton_iterations"])
    assert sum(iterations) <= sum(kratos["newton_iterations"])


# The 3D friction block (ALM_frictional_contact_test_3D, Bossak, mu = 0.1): an elastic block pressed
# on a softer one and dragged along x by t - 0.01, its bottom reactions checked every 0.1 s up to
# t = 1.32. Neither the reference file nor Kratos 10.4 is a yardstick (issue 12):
# - Kratos 10.4 transmits no friction on it: at t = 0.1 (20 steps, the first check) the total
#   bottom reaction is (+594, 576276, 0) N with mu = 0.1 and (-3.2, 577530, 0) N with mu = 0, where
#   every slave node slides and Coulomb alone gives 0.1 x 576 kN = 58 kN along x; it stops at t =
#   0.19 (a structurally singular matrix). Our mu = 0 run matches its mu = 0 run to 1.3e-3 of the
#   largest value of each component (node 4: REACTION_X -61.3 in both). Its first step took 10
#   iterations (max_iteration; Kratos 5), and with mu = 0.01 it did not converge: the slave's edge
#   at z = 0.125 lies on the master's to 1e-13, and an iterate in which they crossed at a tiny
#   angle clipped the edge element's overlap to twice its area (test_exact_integration.cpp,
#   NearlyCoincidentCrossingEdges). Now 6 and 5 iterations (test_friction_block_first_step).
# - The reference file (an older revision) transmits some: -22.7 kN (node 4: -74.0); ours -54.6 kN
#   (node 4: -123.7), 0.089 of the normal reaction, the rest being the lower block's inertia.
# So the test runs the case to its first check (t = 0.1) and holds ours to Coulomb's law, which
# has a closed form at every slipping node: |k lambda_t| = mu |lbar_n|.
# The direction of the tangential multiplier is not right yet (test_friction_block_traction_opposes_slip).
FRICTION_BLOCK = "ALM_frictional_contact_test_3D/friction_block_test"


def friction_block(end_time: float, friction: float | None = None, folder: str = "") -> StructuralMechanicsAnalysis:
    """The friction block run to end_time (its json check left out), with FRICTION_COEFFICIENT
    `friction` in both materials (a copy of the materials file in `folder`) when given."""
    params = read_project_parameters(os.path.join(CSMA_CASES, f"{FRICTION_BLOCK}_parameters.json"))
    params["problem_data"]["end_time"].SetDouble(end_time)
    params["processes"].RemoveValue("json_check_process")  # checks the reference file at t = 0.1
    if friction is not None:
        materials_setting = params["solver_settings"]["material_import_settings"]["materials_filename"]
        with open(os.path.join(CSMA_CASES, materials_setting.GetString())) as f:
            materials = json.load(f)
        for entry in materials["properties"]:
            entry["Material"]["Variables"]["FRICTION_COEFFICIENT"] = friction
        materials_setting.SetString(os.path.join(folder, "materials.json"))
        with open(materials_setting.GetString(), "w") as f:
            json.dump(materials, f)
    analysis = StructuralMechanicsAnalysis(mc.Model(), params, progress=False)
    analysis.Run()
    return analysis


def tangential_tractions(analysis) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """(id, k lambda_t, weighted slip) of every slave node."""
    part = analysis.model["Structure"]
    k = part.ProcessInfo.GetValue(mc.GetVariable("SCALE_FACTOR"))
    rows = []
    for node in part.Nodes:
        if not node.Is(mc.SLAVE):
            continue
        normal = np.array(node.GetSolutionStepValue(mc.GetVariable("NORMAL")))
        lm = np.array(node.GetSolutionStepValue(mc.GetVariable("VECTOR_LAGRANGE_MULTIPLIER")))
        slip = np.array(node.GetSolutionStepValue(mc.GetVariable("WEIGHTED_SLIP")))
        rows.append((node.Id, k * (lm - normal.dot(lm) * normal), slip))
    return rows


#: The friction block's first step: 25 nodes turn from stick to slip at its first iteration, and the
#: system of the second is singular across the slip direction of the nodes at the Coulomb limit
#: (slip_augmentation_coefficient 0, issue 12); round-off decides how far that step goes. With the
#: overlaps of the frictional pairs integrated exactly (degree 4) it goes to |r_u|^2 ratio 1.2e14 and
#: the step takes 7 iterations; at the degree-2 rule it took 4 (every later step the same).
FIRST_STEP_ITERATIONS = 7


def test_friction_block(csma_cases, monkeypatch):
    """The 3D friction block up to its first check: every step after the first converges in at most 4
    Newton iterations (Kratos 10.4: 3 to 5), every slave node slides, and its tangential multiplier
    is at the Coulomb limit mu |lbar_n| to 1e-5 and opposes the sliding."""
    monkeypatch.chdir(csma_cases)
    analysis = friction_block(0.1)
    iterations = [it for _, _, it, _, _ in analysis.step_log]
    assert len(iterations) == 20 and all(converged for _, _, _, converged, _ in analysis.step_log)
    assert iterations[0] <= FIRST_STEP_ITERATIONS and max(iterations[1:]) <= 4
    part = analysis.model["Structure"]
    k = part.ProcessInfo.GetValue(mc.GetVariable("SCALE_FACTOR"))
    slave = [n for n in part.Nodes if n.Is(mc.SLAVE)]
    assert len(slave) == 27 and all(n.Is(mc.ACTIVE) and n.Is(mc.SLIP) for n in slave)
    for node in slave:
        normal = np.array(node.GetSolutionStepValue(mc.GetVariable("NORMAL")))
        lm = np.array(node.GetSolutionStepValue(mc.GetVariable("VECTOR_LAGRANGE_MULTIPLIER")))
        tangential = k * (lm - normal.dot(lm) * normal)
        limit = 0.1 * abs(node.GetValue(mc.GetVariable("AUGMENTED_NORMAL_CONTACT_PRESSURE")))
        assert np.linalg.norm(tangential) == pytest.approx(limit, rel=1e-5), node.Id
        assert tangential[0] < -0.3 * limit, node.Id  # the master drags the slave back along -x


@pytest.mark.slow
def test_friction_block_whole_run(csma_cases, monkeypatch):
    """The whole friction block (to t = 1.405, where the block climbs the lower one's ramp):
    every step after the first converges in at most 5 iterations (1007 in all, 1004 at the degree-2
    rule: FIRST_STEP_ITERATIONS). Before the fan start of the mortar segmentation was held through
    a step, t = 1.125 and 1.13 took 10 (the limit) and did not converge: Newton cycled through
    three iterates with fixed active and slip sets."""
    monkeypatch.chdir(csma_cases)
    analysis = friction_block(1.405)
    iterations = [it for _, _, it, _, _ in analysis.step_log]
    assert len(iterations) >= 281 and all(converged for _, _, _, converged, _ in analysis.step_log)
    assert iterations[0] <= FIRST_STEP_ITERATIONS and max(iterations[1:]) <= 5


@pytest.mark.parametrize("friction, most", [(0.0, 6), (0.01, 5)])
def test_friction_block_first_step(csma_cases, monkeypatch, tmp_path, friction, most):
    """The friction block's first step (t = 0.005) with little or no friction converges in a
    handful of iterations (Kratos 10.4, mu = 0: 5); before the clipping of nearly coincident
    crossing edges was fixed, 10 (max_iteration) and not converged."""
    monkeypatch.chdir(csma_cases)
    analysis = friction_block(0.005, friction, str(tmp_path))
    (_, _, iterations, converged, _), = analysis.step_log
    assert converged and iterations <= most


@pytest.mark.xfail(strict=True, reason="the slip direction is not tied to the slip (issue 12): with "
                   "slip_augmentation_coefficient 0 the slip constraint fixes only |k lambda_t| (its Jacobian "
                   "row is singular across the direction); the converged first step has 17 of 27 nodes more "
                   "than 10 degrees off s, 3 at 180 (71 degrees at t = 0.1). benchmarks/robustness/README.md "
                   "lists the rules and coefficients tried")
def test_friction_block_traction_opposes_slip(csma_cases, monkeypatch):
    """Coulomb's law in direction: at every sliding node of the first step the tangential
    multiplier lies within 10 degrees of the weighted slip s (s = -D a for a slave sliding by a, so
    k lambda_t along s is the friction opposing the sliding)."""
    monkeypatch.chdir(csma_cases)
    analysis = friction_block(0.005)
    for node_id, traction, slip in tangential_tractions(analysis):
        cosine = traction.dot(slip) / (np.linalg.norm(traction) * np.linalg.norm(slip))
        assert cosine >= math.cos(math.radians(10.0)), node_id


def run_hertz(kind: str, size: str, folder: str) -> dict:
    """Runs a gmsh-generated Hertz case with the benchmarks' runner (as a script, as a user would)
    and evaluates it against Hertz theory."""
    case = hertz.write_case(kind, size, folder)
    output = os.path.join(folder, "record.json")
    subprocess.run([sys.executable, HERTZ_RUNNER, "--code", "mortarcontact", case, output], check=True)
    with open(output) as f:
        record = json.load(f)
    assert record["status"] == "ok", record.get("error")
    assert all(step["converged"] for step in record["steps"])
    result = hertz.evaluate(record, hertz.load_reference(case))
    result["iterations"] = [s["iterations"] for s in record["steps"]]
    scale = record["process_info"]["SCALE_FACTOR"]
    result["axis_pressure"] = max(-scale * n["lm"] for n in record["slave"]
                                  if abs(n["x"]) < 1e-12 and (dim_is_2d(kind) or abs(n["y"]) < 1e-12))
    print(f"{kind} {size}: peak pressure error {result['peak_pressure_error']:+.2%}, fitted p0 error "
          f"{result['p0_fit_error']:+.2%}, half-width error {result['half_width_fit_error']:+.2%}, "
          f"iterations {result['iterations']}")
    return result


def dim_is_2d(kind: str) -> bool:
    return kind.startswith("hertz2d")


@pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")
def test_hertz_2d_cylinder_matches_theory(tmp_path):
    """Plane-strain cylinder on a block (gmsh mesh, ~2k DoFs, 4 displacement steps): peak pressure
    within 3 % and contact half-width within 5 % of Hertz for the computed force."""
    result = run_hertz("hertz2d", "2k", str(tmp_path))
    assert abs(result["peak_pressure_error"]) < 0.03
    assert abs(result["half_width_fit_error"]) < 0.05
    assert math.isclose(result["force_from_pressure"], result["force"], rel_tol=0.03)


@pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")
def test_hertz_3d_sphere_matches_theory(tmp_path):
    """Quarter sphere on a block, unstructured mesh (15k DoFs, about 15 s): contact radius within
    5 % of Hertz, fitted p0 within 3 %, and the nodal peak pressure within 8 %. The nodal pressures
    of this mesh scatter by about +-5 % around the Hertz profile (a node's pressure follows the
    number and shapes of its tetrahedra): the peak, +7.6 % here (Kratos 10.4: the same), is a node
    on the symmetry plane y = 0 at r = 0.11 a, 8 % above Hertz there, while the axis node is 1 %
    below p0. hertz3dgrid (test below) meets the 3 % on the nodal peak. Newton iterations: 5, 4, 3, 3,
    as Kratos 10.4, since every search predicts the active set again."""
    result = run_hertz("hertz3d", "15k", str(tmp_path))
    assert abs(result["half_width_fit_error"]) < 0.05
    assert abs(result["p0_fit_error"]) < 0.03
    assert abs(result["peak_pressure_error"]) < 0.08
    assert sum(result["iterations"]) <= 15


def _check_hertz_3d_grid(result: dict) -> None:
    assert abs(result["peak_pressure_error"]) < 0.03
    assert abs(result["p0_fit_error"]) < 0.03
    assert abs(result["half_width_fit_error"]) < 0.05
    assert abs(result["axis_pressure"] / result["hertz_peak_pressure"] - 1.0) < 0.03
    assert math.isclose(result["force_from_pressure"], result["force"], rel_tol=0.03)


@pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")
def test_hertz_3d_structured_zone_matches_theory(tmp_path):
    """Quarter sphere on a block with structured contact zones (hertz3dgrid_15k, about 15 s): the
    nodal pressures follow the Hertz profile without scatter, so the nodal peak pressure (and the
    pressure of the axis node) is within 3 % of Hertz, as are the fitted p0 and, within 5 %, the
    contact radius."""
    result = run_hertz("hertz3dgrid", "15k", str(tmp_path))
    _check_hertz_3d_grid(result)
    assert sum(result["iterations"]) <= 20


@pytest.mark.slow
@pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")
def test_hertz_3d_structured_zone_converges(tmp_path):
    """hertz3dgrid at 15k, 30k and 50k DoFs (about 4 minutes single-threaded): the nodal peak within
    3 % of Hertz at every level and converging (measured +1.14 %, +1.42 %, +1.62 %, and +1.73 % at
    80k: the first nodes off the axis reach the +2 % by which the centre of the profile exceeds
    Hertz at every level, finite bodies and a/R = 0.1 against Hertz's half-spaces), and the axis
    node, below the profile on the coarse levels, rising towards it (-0.79 %, -0.45 %, -0.04 %,
    +0.22 % at 80k)."""
    results = [run_hertz("hertz3dgrid", size, str(tmp_path / size)) for size in ("15k", "30k", "50k")]
    for result in results:
        _check_hertz_3d_grid(result)
    peak = [r["peak_pressure_error"] for r in results]
    assert abs(peak[2] - peak[1]) < abs(peak[1] - peak[0])
    axis = [r["axis_pressure"] / r["hertz_peak_pressure"] for r in results]
    assert axis[0] < axis[1] < axis[2]


def test_penalty_3d_patch_closes_the_gap(csma_cases, monkeypatch):
    """Penalty contact of two hexahedra (its reference file is not among the copied cases): the slave and
    master faces end up together to within the penalty's penetration."""
    monkeypatch.chdir(csma_cases)
    params = read_project_parameters(os.path.join(
        csma_cases, "penalty_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_test_parameters.json"))
    params["processes"].RemoveValue("json_check_process")
    analysis = StructuralMechanicsAnalysis(mc.Model(), params, progress=False)
    analysis.Run()
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    contact = analysis.model["Structure.Contact"]
    z = contact.NodeCoordinates(initial=False)[:, 2]
    assert np.ptp(z) < 1e-4 * (1.0 + np.abs(z).max())


#: components runs of the frictionless patches -> whether MixedULM solves a system in full
#: (custom_linear_solvers/mixed_ulm_linear_solver.h: only a sliver pair, which has no dual basis,
#: couples two nodes in K(S_A, LM_A))
MIXED_ULM_FULL_SOLVES = {
    "ALM_frictionless_contact_test_2D/hyper_simple_patch_test": False,
    "ALM_frictionless_contact_test_2D/hyper_simple_slope_patch_test": False,
    "ALM_frictionless_contact_test_2D/hyper_simple_triangle_patch_test": False,
    "ALM_frictionless_contact_test_2D/taylor_patch_dynamic_test": True,
}


@pytest.mark.parametrize("case", list(MIXED_ULM_FULL_SOLVES), ids=os.path.basename)
def test_mixed_ulm_condenses_the_components_patches(csma_cases, monkeypatch, case):
    """Issue 18, item 6: the condensing solver condenses every system of the components patches
    without slivers; the dynamic Taylor patch meets one, whose standard basis couples two slave
    nodes by an entry tiny against its row (the reason names them), and solves that system in full."""
    monkeypatch.chdir(csma_cases)
    messages = []
    mc._core.SetLogSink(lambda level, message: messages.append(message))
    try:
        run_csma_case(case, "components")
    finally:
        mc._core.ResetLogSink()
    full = [m for m in messages if "solving the full system" in m]
    assert bool(full) == MIXED_ULM_FULL_SOLVES[case], full
    for message in full:
        entry = float(message.split(" has ")[1].split(" at ")[0])
        assert "K(S_A, LM_A) is not diagonal node by node" in message and abs(entry) < 1e-6, message
