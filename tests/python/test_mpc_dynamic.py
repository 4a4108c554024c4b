"""Issue 13: implicit dynamic MPC contact (Bossak: solver_type "Dynamic", time_integration_method
"implicit", scheme_type "bossak") against frictionless ALM on the same mesh.

An elastic block (3 x 2 elements) flies at 1 onto a base (4 x 2 elements, clamped at its bottom) across a
non-matching interface, hits it, bounces off and flies away; the same run with ALM multipliers and with
MPC constraints: the base's reaction history, the displacement history and the contact states.
"""
from __future__ import annotations

import os

import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.project_parameters import read_project_parameters

from case_builder import fix_process, materials, project_parameters, structured_quads, write_case, write_mdpa

GAP, SPEED, DT, STEPS = 0.045, 1.0, 0.01, 20
LAW = "LinearElasticPlaneStrain2DLaw"


def _impact_case(folder: str, mpc: bool, edit=None) -> str:
    """Base [0,1]x[0,1] (slave face on top), block [0.1,0.9]x[1+GAP, 2+GAP] moving down at SPEED (x held)."""
    c1, q1 = structured_quads(4, 2, 1.0, 1.0)
    c2, q2 = structured_quads(3, 2, 0.8, 1.0)
    c2 = c2 + np.array([0.1, 1.0 + GAP])
    coords = np.vstack([c1, c2])
    n1 = len(c1)
    ids = np.arange(1, len(coords) + 1)
    q2 = [tuple(n + n1 for n in q) for q in q2]
    parts = {"base": {"nodes": ids[:n1], "elements": range(1, len(q1) + 1)},
             "block": {"nodes": ids[n1:], "elements": range(len(q1) + 1, len(q1) + len(q2) + 1)},
             "bottom": {"nodes": ids[:n1][np.isclose(c1[:, 1], 0.0)]},
             "base_top": {"nodes": ids[:n1][np.isclose(c1[:, 1], 1.0)]},
             "block_bottom": {"nodes": ids[n1:][np.isclose(c2[:, 1], 1.0 + GAP)]}}
    write_mdpa(os.path.join(folder, "impact.mdpa"), coords, {"SmallDisplacementElement2D4N": q1 + q2}, {}, parts)
    constraints = [fix_process("Structure.bottom", [0.0, 0.0, 0.0]),
                   fix_process("Structure.block", [0.0, None, None], (True, False, False)),
                   fix_process("Structure.block", [None, -SPEED, None], (False, False, False), variable="VELOCITY",
                               interval=(0.0, 0.0))]
    if mpc:
        contact = {"mpc_contact_settings": {"contact_type": "Frictionless"},
                   "convergence_criterion": "residual_criterion"}
    else:
        contact = {"contact_settings": {"mortar_type": "ALMContactFrictionless",
                                        "contact_residual_relative_tolerance": 1e-10,
                                        "contact_residual_absolute_tolerance": 1e-14},
                   "convergence_criterion": "contact_residual_criterion"}
    params = project_parameters("impact", 2, constraints=constraints, end_time=STEPS * DT, time_step=DT, solver={
        "solver_type": "Dynamic", "time_integration_method": "implicit", "scheme_type": "bossak",
        "residual_relative_tolerance": 1e-8, "residual_absolute_tolerance": 1e-12, "max_iteration": 30, **contact})
    params["processes"]["contact_process_list"] = [{
        "python_module": "mpc_contact_process" if mpc else "alm_contact_process",
        "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
        "Parameters": {"model_part_name": "Structure", "assume_master_slave": {"0": ["base_top"]},
                       "contact_model_part": {"0": ["base_top", "block_bottom"]}, "contact_type": "Frictionless",
                       "search_parameters": {"active_check_factor": 0.01}}}]
    if edit:
        edit(params)
    mats = materials("Structure.base", LAW, 1e4, 0.3, DENSITY=1.0)
    mats["properties"].append({**materials("Structure.block", LAW, 1e4, 0.3, DENSITY=1.0)["properties"][0],
                               "properties_id": 2})
    return write_case(folder, "impact", params, mats)


class _Recording(StructuralMechanicsAnalysis):
    """After each step: the base's vertical reaction, every nodal displacement, the active slave nodes."""

    def __init__(self, model, params):
        super().__init__(model, params, progress=False)
        self.reactions, self.displacements, self.active = [], [], []

    def FinalizeSolutionStep(self):
        super().FinalizeSolutionStep()
        root = self.model.GetModelPart("Structure")
        self.reactions.append(sum(n.GetSolutionStepValue(mc.GetVariable("REACTION_Y"))
                                  for n in root.GetSubModelPart("bottom").Nodes))
        self.displacements.append(root.GetNodalValues(mc.DISPLACEMENT)[:, :2].copy())
        self.active.append(sorted(n.Id for n in root.GetSubModelPart("base_top").Nodes if n.Is(mc.ACTIVE)))


def _run(folder, mpc: bool, edit=None) -> _Recording:
    folder.mkdir()
    path = _impact_case(str(folder), mpc, edit)
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        analysis = _Recording(mc.Model(), read_project_parameters(path))
        analysis.Run()
    finally:
        os.chdir(cwd)
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    return analysis


def test_bossak_impact_mpc_against_alm(tmp_path):
    """The same impact with MPC constraints and with ALM multipliers (its contact residual converged to
    1e-10): the same active nodes at every step, the base's reaction history within 5e-4 of its peak
    (measured 1.9e-4) and every displacement within 5e-4 of the largest (measured 1.2e-4, 1.8e-6 absolute).
    Not closer because the two close different gaps once the faces deform: MPC ties each slave node's
    nodal-normal gap with D^-1 M measured at the step's start, ALM zeroes the weighted gap integrated with
    the interpolated normals at the converged configuration (with update_each_nl_iteration and an
    and_criterion, which make MPC iterate its relations at the contact onset, the reactions come within
    3e-5 of the peak). The block comes in, is stopped and flies away."""
    alm, mpc = _run(tmp_path / "alm", False), _run(tmp_path / "mpc", True)
    reactions = np.array([alm.reactions, mpc.reactions])
    displacements = np.array([alm.displacements, mpc.displacements])
    force = np.abs(reactions[0] - reactions[1]).max() / np.abs(reactions[0]).max()
    motion = np.abs(displacements[0] - displacements[1]).max() / np.abs(displacements[0]).max()
    in_contact = [step + 1 for step, nodes in enumerate(alm.active) if nodes]
    print(f"Bossak impact: steps in contact {in_contact}; MPC to ALM: base reaction {force:.1e} of its peak "
          f"{np.abs(reactions[0]).max():.4g}, displacements {motion:.1e}; Newton iterations "
          f"MPC {[it for _, _, it, _, _ in mpc.step_log]}, ALM {[it for _, _, it, _, _ in alm.step_log]}")
    assert mpc.active == alm.active
    assert in_contact and in_contact[0] == 5 and in_contact[-1] < STEPS  # hits at t = 0.045, leaves again
    assert force < 5e-4 and motion < 5e-4
    # Before the hit the block flies freely and the base is at rest; at the end it moves up (bounced).
    assert np.abs(reactions[:, :4]).max() == 0.0
    root = mpc.model.GetModelPart("Structure")
    velocity = [n.GetSolutionStepValue(mc.VELOCITY)[1] for n in root.GetSubModelPart("block").Nodes]
    assert min(velocity) > 0.0


def test_what_mpc_dynamics_does_not_do(tmp_path):
    """Explicit MPC contact and step splitting name the option and what to use instead."""
    def explicit(params):
        params["solver_settings"]["time_integration_method"] = "explicit"
        params["solver_settings"]["scheme_type"] = "central_differences"

    with pytest.raises(mc.NotImplementedFeatureError,
                       match=r"time_integration_method: \"explicit\" with mpc_contact_settings.*use \"implicit\""):
        _run(tmp_path / "explicit", True, explicit)

    def split(params):
        params["solver_settings"]["step_splitting"] = {"max_number_splits": 2}

    with pytest.raises(mc.NotImplementedFeatureError, match=r"step_splitting: .*smaller time_stepping\.time_step"):
        _run(tmp_path / "split", True, split)
