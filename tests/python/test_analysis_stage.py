"""StructuralMechanicsAnalysis.OpenStep: the steps before it run as in Run, and the opened step,
solved and finalised by hand, gives the run's answer."""
from __future__ import annotations

import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.project_parameters import read_project_parameters

from csma_cases import CSMA_CASES

PATCH_2D = "ALM_frictionless_contact_test_2D/hyper_simple_patch_test"


def patch(monkeypatch) -> StructuralMechanicsAnalysis:
    """The 2D patch test in two steps."""
    monkeypatch.chdir(CSMA_CASES)
    params = read_project_parameters(f"{PATCH_2D}_parameters.json")
    params["processes"].RemoveValue("json_check_process")
    params["problem_data"]["end_time"].SetDouble(2.0)
    params["solver_settings"]["time_stepping"]["time_step"].SetDouble(1.0)
    return StructuralMechanicsAnalysis(mc.Model(), params, progress=False)


def displacements(analysis: StructuralMechanicsAnalysis) -> np.ndarray:
    part = analysis.solver.GetComputingModelPart()
    return np.array([node.GetSolutionStepValue(mc.GetVariable("DISPLACEMENT")) for node in part.Nodes])


def test_an_opened_step_solved_by_hand_gives_the_run_s_answer(monkeypatch):
    whole = patch(monkeypatch)
    whole.Run()
    opened = patch(monkeypatch)
    opened.Initialize()
    opened.OpenStep(2)
    assert [entry[0] for entry in opened.step_log] == [1] and opened.step == 2
    assert opened.solver.SolveSolutionStep()
    opened.FinalizeSolutionStep()
    assert np.array_equal(displacements(opened), displacements(whole))
    assert np.abs(displacements(whole)).max() > 0.0
    with pytest.raises(ValueError, match="not after the current step 2"):
        opened.OpenStep(2)
