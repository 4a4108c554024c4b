"""Issue 12 (advance_ALM_parameters.adapt_penalty): the adapted penalty runs in the penalty and ALM
formulations, frictional and frictionless. Its arithmetic is tested branch by branch in
tests/cpp/contact_utilities/test_adaptive_penalty.cpp; here its effect on whole cases."""
from __future__ import annotations

import json
import os

import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.project_parameters import read_project_parameters

from csma_cases import CSMA_CASES, KRATOS_SNAPSHOTS

STICK_CASE = "penalty_frictional_contact_test_2D/hyper_simple_stick_patch_test"
#: ALM cases and how close the run with adapt_penalty stays to the one without: the ALM solution
#: does not depend on the penalty, so only by the Newton tolerance of the case (the stick/slip
#: patch stops at |r|^2/|r_0|^2 < 1e-4 in both runs, from different iterates).
ALM_CASES = {"ALM_frictionless_contact_test_2D/hyper_simple_patch_test": 1e-8,
             "ALM_frictional_contact_test_2D/threshold_slip_hyper_simple_patch_test": 1e-8,
             "ALM_frictional_contact_test_2D/hyper_simple_patch_test": 1e-4}


class GapRecorder(StructuralMechanicsAnalysis):
    """After each step: the largest |WEIGHTED_GAP / NODAL_AREA| over the active slave nodes, over
    MAX_GAP_FACTOR x NODAL_H, and the nodal penalties of the slave nodes."""

    def __init__(self, model, params):
        super().__init__(model, params, progress=False)
        self.gap_ratios, self.penalties, self.displacements = [], [], {}

    def FinalizeSolutionStep(self):
        super().FinalizeSolutionStep()
        part = self.model["Structure"]
        max_gap_factor = part.ProcessInfo.GetValue(mc.MAX_GAP_FACTOR)
        ratio, penalties = 0.0, []
        for node in part.GetSubModelPart("Contact").Nodes:
            if not node.Is(mc.SLAVE):
                continue
            penalties.append(node.GetValue(mc.INITIAL_PENALTY))
            if node.Is(mc.ACTIVE):
                gap = node.GetSolutionStepValue(mc.WEIGHTED_GAP) / node.GetValue(mc.NODAL_AREA)
                ratio = max(ratio, abs(gap) / (max_gap_factor * node.GetSolutionStepValue(mc.NODAL_H)))
        self.gap_ratios.append(ratio)
        self.penalties.append(penalties)
        self.displacements = {node.Id: node.GetSolutionStepValue(mc.DISPLACEMENT) for node in part.Nodes}


def _run(case: str, keep_checks: bool = True, **advance_alm) -> GapRecorder:
    """Runs `case` with the given advance_ALM_parameters of its (first) contact process."""
    params = read_project_parameters(os.path.join(CSMA_CASES, f"{case}_parameters.json"))
    if not keep_checks:
        params["processes"].RemoveValue("json_check_process")
    process = params["processes"]["contact_process_list"][0]["Parameters"]
    if not process.Has("advance_ALM_parameters"):
        process.AddValue("advance_ALM_parameters", mc.Parameters("{}"))
    alm = process["advance_ALM_parameters"]
    for key, value in advance_alm.items():
        if alm.Has(key):
            alm.RemoveValue(key)
        alm.AddValue(key, mc.Parameters(json.dumps(value)))
    analysis = GapRecorder(mc.Model(), params)
    analysis.Run()
    return analysis


#: Since the dynamic scheme's predictor runs before each step (issue 18, as in Kratos 10.4), the
#: first iterate of the stick patch carries the imposed motion's velocity and acceleration, the
#: converged gaps of steps 1-2 are round-off, and the adapted penalty takes Kratos' erratic path
#: (2.9e18 in step 1, Kratos 4.9e19; collapse to 2e10 at step 3, Kratos 2.6e9 at step 10) and the
#: run stops at step 14 (t = 1.54e-3), where Kratos converges in 3 iterations. Issue 12.
ERRATIC_ADAPTED_PENALTY = pytest.mark.xfail(
    strict=True, raises=mc.ConvergenceFailure,
    reason="adapted penalty collapses on the dynamic stick patch since the scheme predictor runs (issue 12)")


@ERRATIC_ADAPTED_PENALTY
def test_penalty_stick_case_keeps_the_penetration_near_max_gap(csma_cases, monkeypatch):
    """The penalty stick patch (adapt_penalty true, max_gap_factor 5e-4) converges in every step
    in no more Newton iterations than Kratos 10.4 (48 both), and the adapted penalties let every
    active node penetrate up to, not beyond, max_gap = 5e-4 NODAL_H (at most 0.98 of it): the
    penalty goes from the automatic 2.07e15 to 2.45e13 in step 1, and the penetration at
    t = 1.1e-3 from 0.0095 max_gap (without adaptation) to 0.79 max_gap.

    Kratos 10.4 (and the reference file, which it matches to 1.8e-6) do not keep it: with the
    penalty raised to 4.9e19 in step 1, its converged weighted gaps are round-off (5e-12), and at
    the first sign change of those (t = 1.1e-3) the rescaling |eps g_p / g ...| drops the penalty
    to 2.6e9: the blocks then overlap by 0.032, 64 times max_gap. That is the value its files
    check, so the case's own json check is left out here."""
    monkeypatch.chdir(csma_cases)
    analysis = _run(STICK_CASE, keep_checks=False)
    iterations = [it for _, _, it, _, _ in analysis.step_log]
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    with open(os.path.join(KRATOS_SNAPSHOTS, "hyper_simple_stick_patch_test_frictional.json")) as f:
        kratos = json.load(f)
    assert len(iterations) == len(kratos["newton_iterations"])
    assert sum(iterations) <= sum(kratos["newton_iterations"])
    assert max(analysis.gap_ratios) < 1.0
    assert analysis.gap_ratios[9] > 0.5
    # The penalties did adapt, from the automatic 2.069e15.
    assert all(eps < 0.1 * 2.069e15 for step in analysis.penalties for eps in step)
    # The stick interface drags the lower block's top along with the upper block (no friction
    # would leave it at x = 0, as in Kratos 10.4's run).
    assert min(analysis.displacements[3][0], analysis.displacements[4][0]) > 1e-4

    fixed = _run(STICK_CASE, keep_checks=False, adapt_penalty=False)
    assert fixed.gap_ratios[9] < 0.02


@ERRATIC_ADAPTED_PENALTY
def test_max_gap_factor_sets_the_penetration_allowed(csma_cases, monkeypatch):
    """Halving max_gap_factor (5e-4 in the case) halves the penetration the adapted penalty
    allows: every active node stays within the new max_gap, and the penetration at t = 1.1e-3
    (relative to the old one) drops below 0.6."""
    monkeypatch.chdir(csma_cases)
    case = _run(STICK_CASE, keep_checks=False)
    halved = _run(STICK_CASE, keep_checks=False, max_gap_factor=2.5e-4)
    assert all(converged for _, _, _, converged, _ in halved.step_log)
    assert max(halved.gap_ratios) < 1.0
    assert halved.gap_ratios[9] * 2.5e-4 < 0.6 * case.gap_ratios[9] * 5e-4


@pytest.mark.parametrize("case", list(ALM_CASES), ids=[os.path.basename(os.path.dirname(c)) + "/" +
                                                     os.path.basename(c) for c in ALM_CASES])
def test_alm_solution_does_not_depend_on_the_adapted_penalty(csma_cases, monkeypatch, case):
    """The ALM solution satisfies the contact conditions exactly whatever the penalty: with
    adapt_penalty the ALM patches (frictionless, Coulomb stick/slip and slip) pass their own json
    checks, in as many Newton iterations, with the displacements of the runs without it, although
    their nodal penalties changed (by a factor of about 10 to 40)."""
    monkeypatch.chdir(csma_cases)
    adapted = _run(case, adapt_penalty=True)
    plain = _run(case, adapt_penalty=False)
    scale = max(abs(c) for u in plain.displacements.values() for c in u)
    for node, u in plain.displacements.items():
        assert adapted.displacements[node] == pytest.approx(u, abs=ALM_CASES[case] * scale)
    assert [s[2] for s in adapted.step_log] == [s[2] for s in plain.step_log]
    assert all(abs(a / p - 1.0) > 1.0 for a, p in zip(adapted.penalties[-1], plain.penalties[-1]))
