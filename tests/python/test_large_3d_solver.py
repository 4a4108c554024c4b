"""Issue 14: a large 3D contact problem of the scalar frictionless multipliers whose case names no
linear solver, or one of Kratos' direct ones, is solved by PETSc's field split instead of UMFPACK
(one line of output says so); naming "umfpack" keeps the direct solver. The rules on a model part
of the right size, and (slow) UMFPACK's Newton iterations and answers, within the Newton
tolerances, on hertz3d_15k."""
from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
from types import SimpleNamespace

import pytest

import mortarcontact as mc
from mortarcontact.solvers import contact_mechanical_solver as contact_solver


def _solver_of(nodes: int, domain_size: int = 3, mortar_type: str = "ALMContactFrictionless", contact: int = 0):
    """What _large_3d_linear_solver reads of a contact solver: its model part, dimension and formulation."""
    part = mc.Model().CreateModelPart("Structure", domain_size)
    for i in range(1, nodes + 1):
        part.CreateNewNode(i, float(i), 0.0, 0.0)
    if contact:
        part.CreateSubModelPart("Contact").AddNodes(list(range(1, contact + 1)))
    return SimpleNamespace(main_model_part=part, domain_size=domain_size,
                           formulation=mc._core.ContactFormulation.Get(mortar_type))


def _choose(solver, settings: str):
    return contact_solver.ContactMechanicalSolver._large_3d_linear_solver(solver, mc.Parameters(settings))


ABOVE = contact_solver.LARGE_3D_EQUATIONS // 3 + 1  # nodes whose displacements exceed the threshold


@pytest.mark.parametrize("settings", ['{}', '{"solver_type": "LinearSolversApplication.sparse_lu"}',
                                      '{"solver_type": "skyline_lu_factorization"}'])
def test_large_3d_frictionless_contact_takes_the_field_split(petsc, capsys, settings):
    chosen = _choose(_solver_of(ABOVE), settings)
    assert chosen is not None and chosen.Name() == "petsc" and not chosen.IsDirect()
    line = capsys.readouterr().out
    assert line.count("\n") == 1 and "PETSc field split" in line and '"umfpack" keeps' in line
    assert f"about {3 * ABOVE} equations" in line


def test_the_multipliers_count_towards_the_threshold(petsc):
    below = contact_solver.LARGE_3D_EQUATIONS // 3 - 10
    assert _choose(_solver_of(below), "{}") is None
    assert _choose(_solver_of(below, contact=40), "{}").Name() == "petsc"


@pytest.mark.parametrize("case", [
    {"settings": '{"solver_type": "umfpack"}'},  # the user's explicit choice
    {"settings": '{"solver_type": "klu"}'},
    {"settings": '{"solver_type": "sparse_lu", "scaling": true}'},
    {"settings": '{"solver_type": "sparse_lu", "reuse_factorization": false}'},
    {"nodes": ABOVE - 2},
    {"domain_size": 2},
    {"mortar_type": "ALMContactFrictional"},
    {"mortar_type": "ALMContactFrictionlessComponents"},  # condensed by MixedULM instead
])
def test_otherwise_the_settings_stand(petsc, capsys, case):
    solver = _solver_of(case.get("nodes", ABOVE), case.get("domain_size", 3), case.get("mortar_type",
                                                                                       "ALMContactFrictionless"))
    assert _choose(solver, case.get("settings", "{}")) is None
    assert capsys.readouterr().out == ""


RUNNER = os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks", "hertz", "case_runner.py")


@pytest.mark.slow
@pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")
def test_hertz3d_15k_with_its_own_settings_matches_umfpack(petsc, tmp_path):
    """The case names Kratos' sparse_lu: the field split runs it in UMFPACK's Newton iterations, to
    its answers within the case's Newton tolerances (1e-4 relative): each linear solve stops at
    1e-8 of its residual, so the last iterates differ (measured: 4.3e-5 of the peak pressure)."""
    from mortarcontact.cases import hertz

    folder = hertz.write_case("hertz3d", "15k", str(tmp_path))
    records = {}
    for name, solver in (("umfpack", ["--linear-solver", '{"solver_type": "umfpack"}']), ("default", [])):
        output = tmp_path / f"{name}.json"
        run = subprocess.run([sys.executable, RUNNER, "--code", "mortarcontact", *solver, folder, str(output)],
                             check=True, capture_output=True, text=True)
        assert ("PETSc field split" in run.stdout) == (name == "default")
        records[name] = json.loads(output.read_text())
        assert records[name]["status"] == "ok", records[name].get("error")
    umfpack, default = records["umfpack"], records["default"]
    assert default["linear_solver_counters"]["krylov_solves"] == sum(s["iterations"] for s in default["steps"])
    assert [s["iterations"] for s in default["steps"]] == [s["iterations"] for s in umfpack["steps"]]
    lm = {k: [node["lm"] for node in r["slave"]] for k, r in records.items()}
    scale = max(abs(v) for v in lm["umfpack"])
    assert max(abs(a - b) for a, b in zip(lm["default"], lm["umfpack"])) < 1e-4 * scale
    assert default["reactions"]["DISPLACEMENT_bottom"] == pytest.approx(umfpack["reactions"]["DISPLACEMENT_bottom"],
                                                                        rel=1e-4)
