"""Issue 3: axisymmetric mortar contact (alternative_formulations.axisymmetric). Two coaxial rings
(a <= r <= b) stacked along the axis with non-matching meshes, the lower one on a frictionless
support, the upper one pushed down: the exact solution is uniaxial stress sigma_zz = E eps with
u_r = -nu eps r (linear, so the bilinear axisymmetric elements represent it exactly). The mortar
operators weighted by 2 pi r must transmit that uniform pressure exactly; the plane operators
cannot."""
from __future__ import annotations

import math
import os

import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.project_parameters import read_project_parameters

from case_builder import (
    fix_process,
    materials,
    project_parameters,
    run_analysis,
    structured_quads,
    write_case,
    write_mdpa,
)
from csma_cases import use_penalty

A, B = 0.5, 1.5          # inner and outer radius
GAP, PUSH = 1e-3, 0.011  # initial gap and imposed top displacement
E, NU = 2.0e5, 0.3


def write_rings(folder: str, axisymmetric: bool) -> str:
    lower, lower_cells = structured_quads(3, 2, B - A, 1.0)
    upper, upper_cells = structured_quads(5, 2, B - A, 1.0 - GAP)
    lower[:, 0] += A
    upper[:, 0] += A
    upper[:, 1] += 1.0 + GAP
    coords = np.vstack([lower, upper])
    offset = len(lower)
    cells = list(lower_cells) + [tuple(i + offset for i in c) for c in upper_cells]
    ids = np.arange(1, len(coords) + 1)
    lower_ids, upper_ids = ids[:offset], ids[offset:]
    on = lambda part, z: [int(i) for i in part if abs(coords[i - 1, 1] - z) < 1e-12]  # noqa: E731
    sub_parts = {
        "lower": {"nodes": lower_ids.tolist(), "elements": list(range(1, len(lower_cells) + 1))},
        "upper": {"nodes": upper_ids.tolist(),
                  "elements": list(range(len(lower_cells) + 1, len(cells) + 1))},
        "support": {"nodes": on(lower_ids, 0.0)},
        "top": {"nodes": on(upper_ids, 2.0)},
        "contact_master": {"nodes": on(lower_ids, 1.0)},
        "contact_slave": {"nodes": on(upper_ids, 1.0 + GAP)},
        "contact": {"nodes": on(lower_ids, 1.0) + on(upper_ids, 1.0 + GAP)},
    }
    write_mdpa(os.path.join(folder, "rings.mdpa"), coords, {"AxisymSmallDisplacementElement2D4N": cells},
               sub_parts=sub_parts)
    contact = {"python_module": "alm_contact_process", "kratos_module": "ContactStructuralMechanicsApplication",
               "Parameters": {"model_part_name": "Structure", "contact_model_part": {"0": ["contact"]},
                              "assume_master_slave": {"0": ["contact_slave"]}, "contact_type": "Frictionless",
                              "alternative_formulations": {"axisymmetric": axisymmetric}}}
    parameters = project_parameters(
        "rings", 2,
        constraints=[fix_process("Structure.support", (0.0, 0.0, 0.0), (False, True, True)),
                     fix_process("Structure.top", (0.0, -PUSH, 0.0), (False, True, True))],
        solver={"convergence_criterion": "contact_residual_criterion",
                "contact_settings": {"mortar_type": "ALMContactFrictionless",
                                     "contact_residual_relative_tolerance": 1e-20,
                                     "contact_residual_absolute_tolerance": 1e-24}})
    parameters["processes"]["contact_process_list"] = [contact]
    materials_data = materials("Structure", "LinearElasticAxisym2DLaw", E, NU)
    materials_data["properties"][0]["model_part_name"] = "Structure.lower"
    upper_block = dict(materials_data["properties"][0], model_part_name="Structure.upper", properties_id=2)
    materials_data["properties"].append(upper_block)
    return write_case(folder, "rings", parameters, materials_data)


def contact_pressures(folder: str, axisymmetric: bool):
    path = write_rings(folder, axisymmetric)
    analysis = run_analysis(folder, path)
    root = analysis.model["Structure"]
    slave = root.GetSubModelPart("contact_slave")
    scale = root.ProcessInfo.GetValue(mc.SCALE_FACTOR)
    pressure = -scale * slave.GetNodalValues(mc.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE)
    return analysis, pressure


def test_axisymmetric_rings_transmit_the_uniform_pressure_exactly(tmp_path):
    analysis, pressure = contact_pressures(str(tmp_path), axisymmetric=True)
    strain = (PUSH - GAP) / (1.0 + (1.0 - GAP))
    sigma = E * strain
    # The contact acts on the current interface, whose radii grew by nu * strain: the same force
    # over a larger area (the small-displacement elements carry sigma on the initial one).
    pressure_exact = sigma / (1.0 + NU * strain) ** 2
    print(f"axisymmetric rings: sigma {sigma:.6g}, expected pressure {pressure_exact:.11g}, "
          f"slave pressures {np.array2string(pressure, precision=11)}")
    assert np.allclose(pressure, pressure_exact, rtol=1e-8)
    # The support reaction equals sigma times the ring area (2 pi r weights in the elements too).
    support = analysis.model["Structure.support"]
    force = support.GetNodalValues(mc.REACTION)[:, 1].sum()
    assert force == pytest.approx(sigma * math.pi * (B * B - A * A), rel=1e-8)


def test_plane_mortar_operators_do_not_pass_the_axisymmetric_patch_test(tmp_path):
    """The same rings with the plane mortar conditions: the pressure is no longer uniform."""
    _, pressure = contact_pressures(str(tmp_path), axisymmetric=False)
    assert np.ptp(pressure) > 1e-2 * np.abs(pressure).max()


@pytest.mark.parametrize("formulation", ["scalar", "penalty"])
def test_axisymmetric_contact_pressure_output_is_physical(tmp_path, monkeypatch, formulation):
    """Issue 15, item 4: CONTACT_PRESSURE (and -NORMAL_CONTACT_STRESS) of the axisymmetric rings is
    the uniform pressure in stress units, on the ALM and on the penalty formulation."""
    path = write_rings(str(tmp_path), axisymmetric=True)
    params = read_project_parameters(path)
    if formulation == "penalty":
        use_penalty(params)
    monkeypatch.chdir(tmp_path)
    analysis = StructuralMechanicsAnalysis(mc.Model(), params, progress=False)
    analysis.Run()
    slave = analysis.model["Structure.contact_slave"]
    strain = (PUSH - GAP) / (1.0 + (1.0 - GAP))
    pressure_exact = E * strain / (1.0 + NU * strain) ** 2
    pressure = slave.GetNodalNonHistoricalValues(mc.CONTACT_PRESSURE)
    assert np.array_equal(pressure, -slave.GetNodalNonHistoricalValues(mc.NORMAL_CONTACT_STRESS))
    # The penalty solution is not exact (0.16 % at the ring's edges); eps g summed over the pairs
    # of a node was up to 3 times the pressure here.
    assert pressure == pytest.approx(pressure_exact, rel=1e-6 if formulation == "scalar" else 3e-3)
