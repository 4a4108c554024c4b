"""Issue 2: the structural substrate against closed forms, through the whole pipeline
(mdpa + materials + ProjectParameters -> analysis stage -> C++ strategy)."""
from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

import mortarcontact as mc

from case_builder import (
    condition_load_process,
    fix_process,
    materials,
    project_parameters,
    structured_hexes,
    structured_quads,
    write_case,
    write_mdpa,
)


def nodes_where(coords, predicate):
    return [k + 1 for k, x in enumerate(coords) if predicate(x)]


def edge_conditions(coords, cells, on_edge, quadratic: bool):
    """Line conditions on element edges whose nodes all satisfy on_edge, oriented like the element
    (counter-clockwise, so that the normal points outwards). Quadratic: (end, end, middle)."""
    lines = []
    for cell in cells:
        corners = cell[:4]
        for e in range(4):
            a, b = corners[e], corners[(e + 1) % 4]
            nodes = (a, b) + ((cell[4 + e],) if quadratic else ())
            if all(on_edge(coords[n - 1]) for n in nodes):
                lines.append(nodes)
    return lines


def test_cantilever_tip_deflection_matches_timoshenko(tmp_path):
    # LINE_LOAD acts on the current edge length (Kratos' convention): a linear check needs small
    # rotations, here a tip deflection of 0.4 % of the length.
    length, height, young, poisson, load = 10.0, 1.0, 1.0e5, 0.3, 1.0
    coords, cells = structured_quads(20, 2, length, height, order=2)
    tip = edge_conditions(coords, cells, lambda x: abs(x[0] - length) < 1e-9, quadratic=True)
    clamped = nodes_where(coords, lambda x: abs(x[0]) < 1e-9)
    write_mdpa(tmp_path / "beam.mdpa", coords, {"SmallDisplacementElement2D8N": cells},
               {"LineLoadCondition2D3N": tip},
               {"Parts_beam": {"nodes": range(1, len(coords) + 1), "elements": range(1, len(cells) + 1)},
                "clamp": {"nodes": clamped},
                "tip": {"nodes": sorted({n for c in tip for n in c}), "conditions": range(1, len(tip) + 1)}})
    params = project_parameters("beam", 2, constraints=[fix_process("Structure.clamp", [0.0, 0.0, 0.0])],
                                loads=[condition_load_process("Structure.tip", "LINE_LOAD",
                                                              [0.0, -load / height, 0.0])])
    path = write_case(tmp_path, "beam", params,
                      materials("Structure.Parts_beam", "LinearElasticPlaneStress2DLaw", young, poisson, THICKNESS=1.0))
    analysis = mc.run(str(path), progress=False)
    part = analysis.model["Structure"]
    u = part.GetNodalValues(mc.DISPLACEMENT)
    x = part.NodeCoordinates(initial=True)
    tip_deflection = -u[np.abs(x[:, 0] - length) < 1e-9, 1].mean()
    inertia = height**3 / 12
    shear_modulus = young / (2 * (1 + poisson))
    exact = load * length**3 / (3 * young * inertia) + load * length / (5 / 6 * shear_modulus * height)
    assert tip_deflection == pytest.approx(exact, rel=1e-2)
    # The reaction balances the load on the current (slightly stretched) tip edge.
    tip = np.abs(x[:, 0] - length) < 1e-9
    current = (x + u)[tip][np.argsort(x[tip, 1])]
    tip_length = np.linalg.norm(np.diff(current, axis=0), axis=1).sum()
    reaction_y = part.GetNodalValues(mc.REACTION)[np.abs(x[:, 0]) < 1e-9, 1].sum()
    assert reaction_y == pytest.approx(load / height * tip_length, rel=1e-8)


def test_lame_thick_cylinder_in_axisymmetry(tmp_path):
    # The bore load acts on the current radius (Kratos' convention): u / r = 1e-6 keeps the
    # linear closed form valid.
    inner, outer, pressure, young, poisson = 1.0, 2.0, 1.0, 1.0e6, 0.3
    coords, cells = structured_quads(8, 1, outer - inner, 0.25, order=2)
    coords[:, 0] += inner
    bore = edge_conditions(coords, cells, lambda x: abs(x[0] - inner) < 1e-9, quadratic=True)
    write_mdpa(tmp_path / "tube.mdpa", coords, {"AxisymSmallDisplacementElement2D8N": cells},
               {"AxisymLineLoadCondition2D3N": bore},
               {"Parts_tube": {"nodes": range(1, len(coords) + 1), "elements": range(1, len(cells) + 1)},
                "bore": {"nodes": sorted({n for c in bore for n in c}), "conditions": range(1, len(bore) + 1)}})
    # Plane strain along the axis: u_z = 0 everywhere.
    params = project_parameters("tube", 2, constraints=[fix_process("Structure.Parts_tube", [None, 0.0, 0.0],
                                                                    (False, True, True))],
                                loads=[condition_load_process("Structure.bore", "LINE_LOAD", [pressure, 0.0, 0.0])])
    path = write_case(tmp_path, "tube", params,
                      materials("Structure.Parts_tube", "LinearElasticAxisym2DLaw", young, poisson))
    analysis = mc.run(str(path), progress=False)
    part = analysis.model["Structure"]
    r = part.NodeCoordinates(initial=True)[:, 0]
    u_r = part.GetNodalValues(mc.DISPLACEMENT)[:, 0]
    a_coef = pressure * inner**2 / (outer**2 - inner**2)
    b_coef = pressure * inner**2 * outer**2 / (outer**2 - inner**2)
    exact = (1 + poisson) / young * ((1 - 2 * poisson) * a_coef * r + b_coef / r)
    np.testing.assert_allclose(u_r, exact, rtol=1e-3)


@pytest.mark.parametrize("element", ["TotalLagrangianElement3D8N", "UpdatedLagrangianElement3D8N"])
def test_neo_hookean_uniaxial_stretch_and_quadratic_newton(tmp_path, element):
    young, poisson, stretch = 1000.0, 0.3, 1.5
    lam = young * poisson / ((1 + poisson) * (1 - 2 * poisson))
    mu = young / (2 * (1 + poisson))
    coords, cells = structured_hexes(2, 2, 2, 1.0, 1.0, 1.0)
    on = lambda axis, value: nodes_where(coords, lambda x: abs(x[axis] - value) < 1e-9)  # noqa: E731
    write_mdpa(tmp_path / "cube.mdpa", coords, {element: cells}, {},
               {"Parts_cube": {"nodes": range(1, len(coords) + 1), "elements": range(1, len(cells) + 1)},
                "x0": {"nodes": on(0, 0.0)}, "y0": {"nodes": on(1, 0.0)}, "z0": {"nodes": on(2, 0.0)},
                "x1": {"nodes": on(0, 1.0)}})
    constraints = [fix_process("Structure.x0", [0.0, None, None], (True, False, False)),
                   fix_process("Structure.y0", [None, 0.0, None], (False, True, False)),
                   fix_process("Structure.z0", [None, None, 0.0], (False, False, True)),
                   fix_process("Structure.x1", [f"{stretch - 1.0}*t", None, None], (True, False, False))]
    params = project_parameters("cube", 3, constraints=constraints, end_time=1.0, time_step=0.25)
    path = write_case(tmp_path, "cube", params, materials("Structure.Parts_cube", "HyperElastic3DLaw", young, poisson))
    analysis = mc.run(str(path), progress=False)
    part = analysis.model["Structure"]

    # Homogeneous deformation F = diag(stretch, s, s) with a traction-free lateral surface: S_22 = 0.
    def s22(s):
        jac = stretch * s * s
        return mu * (1 - 1 / s**2) + lam * math.log(jac) / s**2

    s = brentq(s22, 0.3, 1.0)
    jac = stretch * s * s
    first_pk = stretch * (mu * (1 - 1 / stretch**2) + lam * math.log(jac) / stretch**2)
    x = part.NodeCoordinates(initial=True)
    u = part.GetNodalValues(mc.DISPLACEMENT)
    far_y = np.abs(x[:, 1] - 1.0) < 1e-9
    np.testing.assert_allclose(u[far_y, 1], s - 1.0, rtol=1e-8)
    reaction = part.GetNodalValues(mc.REACTION)[np.abs(x[:, 0] - 1.0) < 1e-9, 0].sum()
    assert reaction == pytest.approx(first_pk * 1.0, rel=1e-8)

    # Newton converges quadratically in every step: once the residual is small, each iteration
    # roughly squares its relative size (the ratio r_{k+1} / r_k^2 stays bounded).
    history = analysis.solver.LastIterationHistory()
    residuals = [h.residual_norm for h in history if h.residual_norm > 0]
    assert len(residuals) >= 3
    rates = [math.log(residuals[k + 1] / residuals[0]) / math.log(residuals[k] / residuals[0])
             for k in range(1, len(residuals) - 1) if residuals[k + 1] > 1e-13 * residuals[0]]
    assert rates and max(rates) > 1.8, f"residual history {residuals}"
