"""Issue 18, item 2: the dynamic contact aids of Kratos' search and mortar criterion act.

An impact: an elastic block flies at 1 towards a fixed one, 0.045 away, with the Bossak scheme
and dt 0.01, so its face arrives 4.5 steps in; before that it moves rigidly (constant velocity).
- dynamic_search: the search at the start of step 4 sees the face where the step's motion takes
  it (0.005 away) and predicts the slave nodes active, one step before the plain search does;
- compute_dynamic_factor: in step 5 the face closes halfway through the step, so the slave nodes'
  DYNAMIC_FACTOR is 0.5, and the multipliers, which the factor divides, are twice those of the run
  without it;
- adapt_search: search_factor and active_check_factor grow by the interface's NODAL_H ratio;
- static_check_movement: a node at rest 1e-4 away is predicted active at the second search.
"""
from __future__ import annotations

import os

import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.project_parameters import read_project_parameters

from case_builder import fix_process, materials, project_parameters, write_case, write_mdpa

ELEMENT = "SmallDisplacementElement2D4N"
LAW = "LinearElasticPlaneStrain2DLaw"
GAP, SPEED, DT = 0.045, 1.0, 0.01


def impact_case(folder, *, upper_height=1.0, gap=GAP, speed=SPEED, dynamic=True, end_time=0.07,
                search=None, contact=None, active_check_factor=0.01) -> str:
    """Lower unit block fixed at its base (slave face on top), upper block ``gap`` above it moving
    down at ``speed`` (its x fixed; all of it fixed in a static run), frictionless ALM."""
    top = 1.0 + gap
    coords = [(0, 0), (1, 0), (1, 1), (0, 1), (0, top), (1, top), (1, top + upper_height), (0, top + upper_height)]
    write_mdpa(os.path.join(folder, "impact.mdpa"), coords, {ELEMENT: [(1, 2, 3, 4), (5, 6, 7, 8)]}, {},
               {"lower": {"nodes": [1, 2, 3, 4], "elements": [1]}, "upper": {"nodes": [5, 6, 7, 8], "elements": [2]},
                "Contact_Part": {"nodes": [3, 4, 5, 6]}, "base": {"nodes": [1, 2]}})
    # The upper block flies in y (held in statics, where a free body would be singular).
    constraints = [fix_process("Structure.base", [0.0, 0.0, 0.0]),
                   fix_process("Structure.upper", [0.0, None if dynamic else 0.0, None], (True, not dynamic, False))]
    if speed:
        constraints.append(fix_process("Structure.upper", [None, -speed, None], (False, False, False),
                                       variable="VELOCITY", interval=(0.0, 0.0)))
    params = project_parameters("impact", 2, constraints=constraints, end_time=end_time, time_step=DT, solver={
        "solver_type": "Dynamic" if dynamic else "Static", "scheme_type": "bossak",
        "contact_settings": {"mortar_type": "ALMContactFrictionless", **(contact or {})},
        "convergence_criterion": "contact_residual_criterion",
        "residual_relative_tolerance": 1e-6, "residual_absolute_tolerance": 1e-12, "max_iteration": 30})
    params["processes"]["contact_process_list"] = [{
        "python_module": "alm_contact_process",
        "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
        "Parameters": {"model_part_name": "Structure", "assume_master_slave": {"0": ["lower"]},
                       "contact_model_part": {"0": ["Contact_Part"]}, "contact_type": "Frictionless",
                       "search_parameters": {"active_check_factor": active_check_factor, **(search or {})}}}]
    mats = materials("Structure.lower", LAW, 1e4, 0.3, DENSITY=1.0)
    mats["properties"].append({**materials("Structure.upper", LAW, 1e4, 0.3, DENSITY=1.0)["properties"][0],
                               "properties_id": 2})
    return write_case(folder, "impact", params, mats)


class RecordingAnalysis(StructuralMechanicsAnalysis):
    """Keeps, after each step, the slave nodes' DYNAMIC_FACTOR and contact multiplier."""

    def __init__(self, model, params):
        super().__init__(model, params, progress=False)
        self.steps = []

    def FinalizeSolutionStep(self):
        super().FinalizeSolutionStep()
        root = self.model.GetModelPart("Structure")
        self.steps.append({node: (root.GetNode(node).GetValue(mc.DYNAMIC_FACTOR),
                                  root.GetNode(node).GetSolutionStepValue(mc.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE),
                                  root.GetNode(node).GetSolutionStepValue(mc.DISPLACEMENT)[1])
                           for node in (3, 4)})


def run(folder, **case):
    folder.mkdir(parents=True, exist_ok=True)
    path = impact_case(str(folder), **case)
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        analysis = RecordingAnalysis(mc.Model(), read_project_parameters(path))
        analysis.Run()
    finally:
        os.chdir(cwd)
    return analysis


def contact_process(analysis):
    return next(p for p in analysis.processes if type(p).__name__ == "ALMContactProcess")


def predicted_active(analysis) -> dict:
    """STEP -> slave nodes the search predicted active."""
    return {step: stats["active_nodes"] for step, stats in contact_process(analysis).search_statistics}


def test_dynamic_search_predicts_the_impact_one_step_earlier(tmp_path):
    plain = predicted_active(run(tmp_path / "plain", end_time=0.05))
    dynamic = predicted_active(run(tmp_path / "dynamic", end_time=0.05, search={"dynamic_search": True}))
    # Start of step 4: 0.015 apart (above the check length 0.01), 0.005 after the step's motion.
    assert [plain[s] for s in (3, 4, 5)] == [0, 0, 2], plain
    assert [dynamic[s] for s in (3, 4, 5)] == [0, 2, 2], dynamic


def test_dynamic_search_in_a_static_problem_warns(tmp_path, capfd):
    from test_bad_input import contact_case
    from test_settings_audit import NO_EFFECT, _run_logged

    def edit(params):
        params["processes"]["contact_process_list"][0]["Parameters"]["search_parameters"] = {"dynamic_search": True}
    _, log = _run_logged(tmp_path, base=contact_case, edit=edit)
    assert [m["key"] for m in NO_EFFECT.finditer(log)] == ["dynamic_search"], log


def test_compute_dynamic_factor_is_the_share_of_the_step_in_contact(tmp_path):
    plain = run(tmp_path / "plain")
    factored = run(tmp_path / "factored", contact={"compute_dynamic_factor": True})
    # Step 5 (t 0.04 -> 0.05): open by 0.005 at its start, closed after half of it.
    impact = 4
    for node in (3, 4):
        factor, multiplier, _ = factored.steps[impact][node]
        assert factor == pytest.approx(0.5, abs=1e-9)
        assert multiplier == pytest.approx(2.0 * plain.steps[impact][node][1], rel=1e-6)
        assert plain.steps[impact][node][1] < 0.0  # pressed
    # Before the impact nothing closes within a step.
    assert all(factored.steps[s][node][0] == 1.0 for s in range(impact) for node in (3, 4))


def test_compute_dynamic_factor_in_a_static_problem_warns(tmp_path):
    from test_bad_input import contact_case
    from test_settings_audit import NO_EFFECT, _run_logged

    def edit(params):
        params["solver_settings"]["contact_settings"]["compute_dynamic_factor"] = True
    _, log = _run_logged(tmp_path, base=contact_case, edit=edit)
    assert [m["key"] for m in NO_EFFECT.finditer(log)] == ["compute_dynamic_factor"], log


def test_adapt_search_scales_the_factors_by_the_nodal_length_ratio(tmp_path, capfd):
    # A half-height upper block: NODAL_H 0.5 on its face, 1 on the lower one.
    static = {"dynamic": False, "speed": 0.0, "gap": 0.001, "end_time": 0.01, "upper_height": 0.5}
    plain = contact_process(run(tmp_path / "plain", **static))
    adapted = contact_process(run(tmp_path / "adapted", search={"adapt_search": True}, **static))
    assert "adapt_search" in capfd.readouterr().err
    sp = adapted.settings["search_parameters"]
    assert sp["search_factor"].GetDouble() == pytest.approx(2 * 3.5)
    assert sp["active_check_factor"].GetDouble() == pytest.approx(2 * 0.01)
    radius = [stats["min_search_radius"] for _, stats in plain.search_statistics]
    adapted_radius = [stats["min_search_radius"] for _, stats in adapted.search_statistics]
    assert adapted_radius == pytest.approx([2 * r for r in radius])


def test_static_check_movement_predicts_a_node_at_rest_active(tmp_path):
    # 1e-4 apart and at rest; the active check length 1e-5 alone keeps the nodes open.
    static = {"dynamic": False, "speed": 0.0, "gap": 1e-4, "end_time": 0.02, "active_check_factor": 1e-5}
    plain = predicted_active(run(tmp_path / "plain", **static))
    checked = predicted_active(run(tmp_path / "checked", search={"static_check_movement": True}, **static))
    assert plain == {1: 0, 2: 0}
    assert checked == {1: 0, 2: 2}  # the second search sees that the gap did not close
