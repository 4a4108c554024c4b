"""Issue 3: Newton converges quadratically once the active set is fixed, on a real contact case
(the gmsh Hertz cylinder, 2k DoFs) with the exact normal variation (normal_variation
"nodal_elemental_derivatives", NV conditions). Without it the refreshed nodal normals are not
linearised and the rate drops to linear: the same check then fails, which the second test shows.
(The components formulation with NV converges to round-off as fast in iterations, but its order
estimates scatter between 0.8 and 2.8 before the last iteration; noted on issue 3.)"""
from __future__ import annotations

import importlib.util
import math
import os

import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.cases import hertz
from mortarcontact.project_parameters import read_project_parameters

pytestmark = pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")


class HistoryAnalysis(StructuralMechanicsAnalysis):
    """Keeps the Newton history (increment norms, active-set changes) of every step."""

    def __init__(self, model, params):
        super().__init__(model, params, progress=False)
        self.histories = []

    def FinalizeSolutionStep(self):
        super().FinalizeSolutionStep()
        self.histories.append([(r.increment_norm, {c.name: c.value for c in r.criteria})
                               for r in self.solver.LastIterationHistory()])


def run_hertz(folder: str, normal_variation: str, formulation: str = "ALMContactFrictionless"):
    case = hertz.write_case("hertz2d", "2k", folder)
    params = read_project_parameters(os.path.join(case, "ProjectParameters.json"))
    solver = params["solver_settings"]
    # Converge to round-off so that the tail of every step shows the rate.
    for key in ("residual_relative_tolerance", "residual_absolute_tolerance"):
        solver[key].SetDouble(1e-30)
    contact = solver["contact_settings"]
    for key in ("contact_residual_relative_tolerance", "contact_residual_absolute_tolerance"):
        contact.AddEmptyValue(key)
        contact[key].SetDouble(1e-30)
    contact["mortar_type"].SetString(formulation)
    process = params["processes"]["contact_process_list"][0]["Parameters"]
    process.AddEmptyValue("normal_variation")
    process["normal_variation"].SetString(normal_variation)
    if formulation.endswith("Components"):
        process["contact_type"].SetString("FrictionlessComponents")
    cwd = os.getcwd()
    os.chdir(case)
    try:
        analysis = HistoryAnalysis(mc.Model(), params)
        analysis.Run()
    finally:
        os.chdir(cwd)
    return analysis.histories


def orders(history) -> list[float]:
    """Convergence order estimates log(e_k+1 / e_k) / log(e_k / e_k-1) from the increments after
    the last active-set change, while they are above round-off (1e-12 of the step's first one):
    about 2 for quadratic, 1 for linear convergence. The first increment of a step is the load
    increment itself, not an error of the Newton iteration, so it never enters an estimate (when
    the predicted active set is already right, the set settles in the first iteration)."""
    last_change = max((i for i, (_, c) in enumerate(history) if c.get("active set changes", 0) > 0), default=-1)
    first = history[0][0]
    e = [norm for norm, _ in history[max(last_change, 1):] if norm > 1e-12 * first]
    return [math.log(c / b) / math.log(b / a) for a, b, c in zip(e, e[1:], e[2:]) if b < a]


def test_newton_is_quadratic_with_the_normal_variation(tmp_path):
    formulation = "ALMContactFrictionless"
    histories = run_hertz(str(tmp_path), "nodal_elemental_derivatives", formulation)
    measured = [r for h in histories for r in orders(h)]
    print(f"{formulation} NV: increments per step "
          f"{[[f'{n:.1e}' for n, _ in h] for h in histories]}; orders {[f'{r:.2f}' for r in measured]}")
    assert len(measured) >= 4
    assert sum(measured) / len(measured) > 1.8
    assert min(measured) > 1.5


def test_fixed_normal_tangent_converges_only_linearly(tmp_path):
    histories = run_hertz(str(tmp_path), "no_derivatives_computation")
    measured = [r for h in histories for r in orders(h)]
    print(f"without NV: orders {[f'{r:.2f}' for r in measured]}")
    assert measured and sum(measured) / len(measured) < 1.5
