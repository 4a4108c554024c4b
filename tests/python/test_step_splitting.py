"""Issue 16, item 4 (failures that recover): a structural step that does not converge is cut back
(``solver_settings.step_splitting``: restarted as sub-steps of DELTA_TIME / split_factor^s, s = 1 ..
max_number_splits, Kratos' contact ``adaptative_strategy`` semantics) and the run goes on; when the
last level fails too, the run stops with exit code 4, a message naming the step and the nodes at
fault, and the results of the last converged step on disk and readable."""
from __future__ import annotations

import json
import os

import meshio
import numpy as np
import pytest
from test_cli import run_cli

import mortarcontact as mc

from case_builder import fix_process, materials, project_parameters, structured_quads, write_case, write_mdpa

ELEMENT = "TotalLagrangianElement2D4N"
LAW = "HyperElasticPlaneStrain2DLaw"


def block_case(folder, *, push: str, time_step: float = 1.0, end_time: float = 1.0, max_iteration: int = 6,
               splitting: dict | None = None) -> str:
    """A 4 x 4 Neo-Hookean block, bottom fixed, top pushed down by ``push`` (an expression of t)
    and sheared sideways by a third of it: large strains, so Newton needs more iterations the
    larger the step."""
    coords, cells = structured_quads(4, 4, 1.0, 1.0)
    bottom = [k + 1 for k, x in enumerate(coords) if abs(x[1]) < 1e-12]
    top = [k + 1 for k, x in enumerate(coords) if abs(x[1] - 1.0) < 1e-12]
    write_mdpa(os.path.join(folder, "block.mdpa"), coords, {ELEMENT: cells}, {},
               {"Parts_solid": {"nodes": range(1, len(coords) + 1), "elements": range(1, len(cells) + 1)},
                "bottom": {"nodes": bottom}, "top": {"nodes": top}})
    solver = {"max_iteration": max_iteration, "residual_relative_tolerance": 1e-9,
              "residual_absolute_tolerance": 1e-11}
    if splitting is not None:
        solver["step_splitting"] = splitting
    params = project_parameters("block", 2, time_step=time_step, end_time=end_time, solver=solver, constraints=[
        fix_process("Structure.bottom", [0.0, 0.0, 0.0]),
        fix_process("Structure.top", [f"({push})/3", push, None], (True, True, False))])
    params["output_processes"] = {"vtk_output": [{
        "python_module": "vtk_output_process", "kratos_module": "KratosMultiphysics",
        "Parameters": {"model_part_name": "Structure", "output_path": "vtk_output", "output_control_type": "step",
                       "output_interval": 1, "nodal_solution_step_data_variables": ["DISPLACEMENT"]}}]}
    params["processes"]["json_output_process"] = [{
        "python_module": "json_output_process", "kratos_module": "KratosMultiphysics",
        "Parameters": {"model_part_name": "Structure.top", "output_file_name": "results.json",
                       "output_variables": ["DISPLACEMENT_Y"], "time_frequency": 0.0}}]
    return write_case(folder, "block", params, materials("Structure.Parts_solid", LAW, 1000.0, 0.3))


def displacements(analysis) -> np.ndarray:
    part = analysis.model.GetModelPart("Structure")
    return np.array([node.GetSolutionStepValue(mc.DISPLACEMENT) for node in part.Nodes])


def test_a_step_that_does_not_converge_is_halved_and_the_run_goes_on(tmp_path, monkeypatch):
    push = "-0.35*t"
    # Without splitting, one step of the whole load does not converge in 6 iterations.
    os.makedirs(tmp_path / "plain")
    result = run_cli("run", block_case(str(tmp_path / "plain"), push=push), cwd=tmp_path / "plain")
    assert result.returncode == 4, result.stdout + result.stderr
    # With halving, the step is redone as sub-steps and the analysis finishes.
    os.makedirs(tmp_path / "split")
    monkeypatch.chdir(tmp_path / "split")
    split = mc.run(block_case(str(tmp_path / "split"), push=push,
                              splitting={"max_number_splits": 4, "split_factor": 2.0}))
    level = split.solver.strategy.SplitLevelUsed()
    assert 1 <= level <= 4
    # The same equilibrium as a run that takes the sub-steps from the start (hyperelastic: the
    # final state does not depend on the path).
    os.makedirs(tmp_path / "small")
    monkeypatch.chdir(tmp_path / "small")
    small = mc.run(block_case(str(tmp_path / "small"), push=push, time_step=0.5 ** level, max_iteration=20))
    np.testing.assert_allclose(displacements(split), displacements(small), rtol=0, atol=1e-9)
    assert abs(displacements(split)[:, 1].min() + 0.35) < 1e-12
    # The split step is one step of the analysis: STEP, TIME and one output for it.
    part = split.model.GetModelPart("Structure")
    assert part.ProcessInfo.GetValue(mc.STEP) == 1
    assert part.ProcessInfo.GetValue(mc.DELTA_TIME) == 1.0
    vtus = sorted(f for f in os.listdir(tmp_path / "split" / "vtk_output") if f.endswith(".vtu"))
    assert len(vtus) == 1, vtus
    assert split.step_log[0][2] == len(split.solver.LastIterationHistory())  # every iteration counted


def test_final_failure_names_the_nodes_and_keeps_the_last_converged_step(tmp_path):
    # Step 1 (t = 0.5) pushes 1 %, step 2 (t = 1) pushes 25 % more: too much for 4 iterations even
    # in quarter steps.
    path = block_case(str(tmp_path), push="t <= 0.5 ? -0.02*t : -0.01-0.5*(t-0.5)", time_step=0.5,
                      max_iteration=4, splitting={"max_number_splits": 2, "split_factor": 2.0})
    result = run_cli("run", path, cwd=tmp_path)
    message = result.stdout + result.stderr
    assert result.returncode == 4, message
    assert "Traceback" not in message, message
    assert "step 2 (time 1) did not converge, not even split 2 times (smallest sub-step 0.125)" in result.stderr, \
        result.stderr
    assert "largest residuals at node " in result.stderr, result.stderr
    # The last converged step (1) is on disk and readable; nothing of the failed step was written.
    folder = tmp_path / "vtk_output"
    vtus = sorted(f for f in os.listdir(folder) if f.endswith(".vtu"))
    assert len(vtus) == 1, vtus
    mesh = meshio.read(folder / vtus[0])
    np.testing.assert_allclose(mesh.point_data["DISPLACEMENT"][:, 1].min(), -0.01, atol=1e-12)
    pvd = next(f for f in os.listdir(folder) if f.endswith(".pvd"))
    assert vtus[0] in (folder / pvd).read_text()
    # The JSON output, written only at the end of a run, is written when it stops too.
    with open(tmp_path / "results.json") as f:
        results = json.load(f)
    assert results["TIME"][0] == 0.5
    assert results["NODE_25"]["DISPLACEMENT_Y"][0] == pytest.approx(-0.01, abs=1e-12)


@pytest.mark.parametrize("settings, fragment", [
    ({"max_number_splits": -1}, "must be 0 (no splitting) or more"),
    ({"split_factor": 1.0}, "must be greater than 1"),
    ({"max_number_splits": 2, "split_facter": 2.0}, "split_factor"),
])
def test_step_splitting_settings_are_checked(tmp_path, settings, fragment):
    result = run_cli("run", block_case(str(tmp_path), push="-0.01*t", splitting=settings), cwd=tmp_path)
    assert result.returncode == 2, result.stdout + result.stderr
    assert "solver_settings.step_splitting" in result.stderr and fragment in result.stderr, result.stderr


def test_converged_results_are_unchanged_by_splitting_settings(tmp_path, monkeypatch):
    # Each run writes its outputs (relative paths) in its own folder, not where pytest was started.
    os.makedirs(tmp_path / "a")
    os.makedirs(tmp_path / "b")
    monkeypatch.chdir(tmp_path / "a")
    plain = mc.run(block_case(str(tmp_path / "a"), push="-0.01*t", max_iteration=20))
    monkeypatch.chdir(tmp_path / "b")
    split = mc.run(block_case(str(tmp_path / "b"), push="-0.01*t", max_iteration=20,
                              splitting={"max_number_splits": 3}))
    assert split.solver.strategy.SplitLevelUsed() == 0
    np.testing.assert_array_equal(displacements(plain), displacements(split))
