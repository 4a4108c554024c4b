"""Issue 10: the structural substrate against Kratos 10.4, without Kratos.

tests/cases/structural_parity/<case>/ holds small cases of benchmarks/structural_parity (every
load type with each kinematics in 2D, axisymmetry and 3D, every element geometry and law of the
matrix at least once, Bossak and Newmark dynamics, the THICKNESS = 0.1 cantilever) with the nodal
displacements and reactions Kratos 10.4 computed on them (kratos.json, written by
``python benchmarks/structural_parity/run.py --snapshot``). mortarcontact must reproduce both
to 1e-8 relative to the largest Kratos value. The cases where Kratos 10.4 is wrong are not stored
(benchmarks/structural_parity/results.md says why).
"""
from __future__ import annotations

import json
import os

import numpy as np
import pytest

import mortarcontact as mc

CASES = os.path.join(os.path.dirname(__file__), os.pardir, "cases", "structural_parity")
#: The cases of quadratic 3D elements take 0.05-0.2 s each: they run with -m slow.
SLOW = ("3D10N", "3D20N", "3D27N")
TOLERANCE = 1e-8


def _cases():
    names = sorted(n for n in os.listdir(CASES) if os.path.isfile(os.path.join(CASES, n, "kratos.json")))
    return [pytest.param(n, marks=pytest.mark.slow if any(k in n for k in SLOW) else ()) for n in names]


def run_case(name: str):
    """mortarcontact's nodal DISPLACEMENT and REACTION of a stored case, and Kratos' (ids sorted)."""
    folder = os.path.join(CASES, name)
    analysis = mc.run(os.path.join(folder, "ProjectParameters.json"), progress=False)
    part = analysis.model["Structure"]
    with open(os.path.join(folder, "kratos.json")) as f:
        stored = json.load(f)
    kratos = stored["nodes"]
    ids = sorted(kratos, key=int)
    ours = {node.Id: node for node in part.Nodes}
    assert sorted(ours) == [int(i) for i in ids]
    fields = {}
    # Reactions where displacements are prescribed (Kratos also writes residuals at free DoFs).
    for key, variable, where in (("u", mc.DISPLACEMENT, ids), ("r", mc.REACTION, stored["supported"])):
        fields[key] = (np.array([list(ours[int(i)].GetSolutionStepValue(variable)) for i in where]),
                       np.array([kratos[str(i)][key] for i in where]))
    return part, ids, fields


def test_every_kind_of_case_is_stored():
    names = [p.values[0] for p in _cases()]
    for kind in ("loads_ps_", "loads_pe_", "check_ax_", "loads_3d_", "matrix_", "dynamic_pe_bossak",
                 "dynamic_pe_newmark", "cantilever_plane_stress"):
        assert any(n.startswith(kind) for n in names), kind


@pytest.mark.parametrize("name", _cases())
def test_matches_kratos(name):
    _, _, fields = run_case(name)
    for key, (ours, kratos) in fields.items():
        difference = np.abs(ours - kratos).max() / np.abs(kratos).max()
        assert difference <= TOLERANCE, f"{name}: {key} differs from Kratos 10.4 by {difference:.2e}"


def test_plane_stress_cantilever_with_thickness_matches_timoshenko():
    """Issue 10's defect: a plane-stress cantilever with THICKNESS t = 0.1 and a LINE_LOAD q on the
    tip edge (a force per unit length of the edge, without thickness, as Kratos reads it).
    Timoshenko: P = q h, delta = P L^3 / (3 E I) + P L / (k G A), I = t h^3 / 12, A = t h,
    k = 5/6. 20 x 2 eight-node quadrilaterals, fully clamped root: within 0.4 % (the clamp
    stiffens the root), and equal to Kratos 10.4 (test_matches_kratos checks every node)."""
    length, height, thickness, young, poisson, q = 10.0, 1.0, 0.1, 1000.0, 0.3, 0.01
    part, ids, fields = run_case("cantilever_plane_stress")
    x = np.array([part.GetNode(int(i)).X0 for i in ids])
    tip = np.abs(x - length) < 1e-12
    force = q * height
    inertia, area = thickness * height**3 / 12, thickness * height
    shear_modulus = young / (2 * (1 + poisson))
    exact = force * length**3 / (3 * young * inertia) + force * length / (5 / 6 * shear_modulus * area)
    ours, kratos = fields["u"]
    assert -ours[tip, 1].mean() == pytest.approx(exact, rel=4e-3)
    assert ours[tip, 1].mean() == pytest.approx(kratos[tip, 1].mean(), rel=1e-10)
    # THICKNESS multiplying the load would give a tenth of it.
    assert -ours[tip, 1].mean() > 0.9 * exact
