"""Issue 14, item 3: the extrapolating static predictor (solver_settings.displacement_extrapolation).
Free DoFs start each load step from the linear extrapolation of the last two converged steps
(the C++ unit test, tests/cpp/solving/test_static_predictor.cpp, checks the formula). Here: on
contact cases it takes no more Newton iterations per step, fewer in total where the load path is
smooth, and converges to the same answer; it is skipped after a change of contact state; the
key raises the buffer to 3 steps; it warns where it has no effect."""
from __future__ import annotations

import contextlib
import importlib.util
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
#: Displacement-controlled flat punch in 20 load steps (0.3 s a run).
TWENTY_STEPS = "2d_quad_flat_r0.5_overhang-none_gap_disp_20steps_alm"
#: Tolerances at which two runs from different first guesses reach the same discrete solution
#: (both criteria: the residual one alone compares squared norms, |r|^2 / |r0|^2).
TIGHT = ["solver_settings.convergence_criterion=\"contact_and_criterion\"",
         "solver_settings.displacement_relative_tolerance=1e-12", "solver_settings.residual_relative_tolerance=1e-12",
         "solver_settings.displacement_absolute_tolerance=1e-20", "solver_settings.residual_absolute_tolerance=1e-20",
         "solver_settings.contact_settings.contact_displacement_relative_tolerance=1e-12",
         "solver_settings.contact_settings.contact_residual_relative_tolerance=1e-12",
         "solver_settings.contact_settings.contact_displacement_absolute_tolerance=1e-20",
         "solver_settings.contact_settings.contact_residual_absolute_tolerance=1e-20",
         "solver_settings.max_iteration=50"]


def _run(folder: str, extrapolate: bool, overrides=()) -> dict:
    with contextlib.chdir(folder):
        with open("ProjectParameters.json") as f:
            key = f"solver_settings.displacement_extrapolation={json.dumps(extrapolate)}"
            text = overridden(f.read(), [*overrides, key])
        parameters = mc.Parameters(text)
        migrate_project_parameters(parameters)
        analysis = StructuralMechanicsAnalysis(mc.Model(), parameters, progress=False, case_dir=folder)
        analysis.Run()
    part = analysis.model["Structure"]
    displacement = mc.GetVariable("DISPLACEMENT")
    multiplier = mc.GetVariable("LAGRANGE_MULTIPLIER_CONTACT_PRESSURE")
    slave = part.GetSubModelPart("Contact_slave") if part.HasNodalSolutionStepVariable(multiplier) else None
    return {"iterations": [it for _, _, it, _, _ in analysis.step_log],
            "converged": [converged for _, _, _, converged, _ in analysis.step_log],
            "buffer_size": part.GetBufferSize(),
            "u": np.array([node.GetSolutionStepValue(displacement) for node in part.Nodes]),
            "lm": np.array([node.GetSolutionStepValue(multiplier) for node in slave.Nodes] if slave else [])}


def _relative(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.abs(a - b).max() / np.abs(b).max())


@pytest.mark.parametrize("tight", [False, True], ids=["as-written", "tight"])
def test_fewer_iterations_and_the_same_answer_on_a_twenty_step_punch(tight):
    """solver_settings.displacement_extrapolation true against false on the same case."""
    folder = os.path.join(CASES, TWENTY_STEPS)
    overrides = TIGHT if tight else []
    before, after = _run(folder, False, overrides), _run(folder, True, overrides)
    assert all(before["converged"]) and all(after["converged"])
    assert (before["buffer_size"], after["buffer_size"]) == (2, 3)
    assert len(after["iterations"]) == len(before["iterations"]) == 20
    assert all(a <= b for a, b in zip(after["iterations"], before["iterations"]))
    # Measured: 38 -> 21 as written (one iteration per step from step 4 on: the contact zone no
    # longer changes and the extrapolation is nearly the answer), 114 -> 102 tight.
    assert sum(after["iterations"]) <= sum(before["iterations"]) - (10 if tight else 15)
    tolerance = 1e-8 if tight else 1e-4  # the cases' Newton tolerance as written
    assert _relative(after["u"], before["u"]) < tolerance
    assert _relative(after["lm"], before["lm"]) < tolerance


#: case -> (iterations per step without, with the predictor). Extrapolated across the step in
#: which contact began, step 2 took 3 (penalty) and 4 (overhanging slave) iterations: the contact
#: strategy skips the extrapolation after a step in which a node's contact state changed.
AFTER_CONTACT_ONSET = {"2d_quad_flat_r0.5_overhang-none_gap_disp_4steps_penalty": ([4, 2, 2, 2], [4, 2, 2, 2]),
                       "3d_hex_flat_r0.5_overhang-slave-xy_gap_disp_4steps_alm_coarse": ([2, 2, 2, 2], [2, 2, 1, 1])}


@pytest.mark.parametrize("name", sorted(AFTER_CONTACT_ONSET))
def test_no_extrapolation_across_a_change_of_contact_state(name):
    before, after = (_run(os.path.join(CASES, name), extrapolate)["iterations"] for extrapolate in (False, True))
    assert (before, after) == AFTER_CONTACT_ONSET[name]


@pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")
def test_same_hertz_answer_in_no_more_iterations(tmp_path):
    from mortarcontact.cases import hertz

    folder = hertz.write_case("hertz2d", "2k", str(tmp_path))
    before, after = _run(folder, False, TIGHT), _run(folder, True, TIGHT)
    assert all(before["converged"]) and all(after["converged"])
    assert all(a <= b for a, b in zip(after["iterations"], before["iterations"]))
    assert _relative(after["u"], before["u"]) < 1e-8
    assert _relative(after["lm"], before["lm"]) < 1e-8


def test_no_effect_in_a_dynamic_analysis_warns(capfd):
    from mortarcontact.solvers.solver_settings import validate_solver_settings

    mc.NoEffectWarnings.Reset()
    settings = mc.Parameters(json.dumps({"model_part_name": "Structure", "domain_size": 2, "solver_type": "Dynamic",
                                         "displacement_extrapolation": True}))
    validate_solver_settings(settings)
    assert "'displacement_extrapolation' = true" in capfd.readouterr().err
