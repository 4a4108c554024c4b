"""Issue 13: mesh tying by multipoint constraints (mpc_contact_process, contact_type "MeshTying").

Every slave node is tied in every free displacement component to the mortar projection (D^-1 M) of
the master from the first step, for good: no active set, no release.

- tied patch tests on non-matching interfaces (2D quads; 3D hexahedra on quad and triangle faces): the
  exact linear field at every node and the exact traction in CONTACT_FORCE / NODAL_MAUX, to 1e-10;
  the same displacements as the dual-mortar mesh_tying_process on the same mesh;
- the tied cantilever against beam theory and against the dual-mortar answer (the same discrete tie);
- the shared 2D MPC case tied: Kratos 10.4's displacements in compression (the initial gap kept); in
  tension the tie holds, where Kratos 10.4 releases it (a defect);
- what stays unsupported (a scalar variable) names the option and what to use.
"""
from __future__ import annotations

import os

import numpy as np
import pytest
from test_mesh_tying import (
    VARIANTS_3D,
    _cantilever_run,
    _linear_field,
    _outer_nodes,
    _run,
    _two_blocks_2d,
    _two_blocks_3d,
    exact_patch,
)

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.project_parameters import read_project_parameters

import case_builder as cb
from csma_cases import KRATOS_SNAPSHOTS

OWN_CASES = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "cases", "mpc"))
CASE = "2D_mesh_tying_patch_test"


def _iterations(analysis) -> list[int]:
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    return [it for _, _, it, _, _ in analysis.step_log]


def _check_mpc_patch(analysis, gradient, slave_normal, dim, held) -> int:
    """Every node at u = G x, and at every tied slave component CONTACT_FORCE / NODAL_MAUX = sigma n_slave
    (the reaction of a slave node is the consistent force of the traction, D_jj t with the dual basis);
    held(x0, c): component c of the node at x0 is prescribed (not tied; the processes free their DoFs at
    the end of the step, so IsFixed cannot tell). The number of tied components checked."""
    stress, traction = exact_patch(analysis, gradient, slave_normal, dim)
    root = analysis.model["Structure"]
    checked = 0
    for node in root.GetSubModelPart("Contact").Nodes:
        if not node.Is(mc.SLAVE):
            continue
        tied = [c for c in range(dim) if not held(np.array([node.X0, node.Y0, node.Z0]), c)]
        assert node.Is(mc.ACTIVE) == bool(tied), node.Id
        force = np.asarray(node.GetValue(mc.GetVariable("CONTACT_FORCE"))) / node.GetValue(mc.GetVariable("NODAL_MAUX"))
        for c in tied:
            assert abs(force[c] - traction[c]) <= 1e-10 * np.abs(stress).max(), (node.Id, c)
            checked += 1
    return checked


def test_mpc_tied_patch_2d(tmp_path):
    """Non-matching 2D interface (3 slave segments against 2 master ones), u = G x on the outer boundary
    (tension, compression and shear): the exact field and traction, one linear solve, and the dual-mortar
    mesh_tying_process' displacements on the same mesh."""
    gradient = [[1.0e-3, 4.0e-4], [-2.0e-4, -1.5e-3]]
    coords, elements, parts = _two_blocks_2d()
    parts["Outer"] = {"nodes": _outer_nodes(coords, ([0.0, 0.0], [1.0, 2.0]))}
    fix = cb.fix_process("Outer", [*_linear_field(gradient), 0.0])
    runs = [_run(str(tmp_path), f"patch2d_{mpc}", coords, elements, parts, "LinearElasticPlaneStrain2DLaw",
                 {"constraints": [fix]}, mpc=mpc) for mpc in (True, False)]
    # the two interior slave nodes in both components; the end ones are on the boundary
    outer = {tuple(coords[i - 1]) for i in parts["Outer"]["nodes"]}
    assert _check_mpc_patch(runs[0], gradient, [0.0, 1.0], 2, lambda x, c: tuple(x[:2]) in outer) == 4
    # One linear solve: the second iteration corrects nothing; it is there because the MPC solver's plain
    # residual criterion takes its reference at the first residual, before the solve (the dual-mortar tie's
    # contact residual criterion reports 1).
    assert _iterations(runs[0]) == [2] and _iterations(runs[1]) == [1]
    increments = [record.increment_norm for record in runs[0].solver.strategy.GetIterationHistory()]
    assert increments[1] <= 1e-10 * increments[0]
    constrained, multipliers = (r.model["Structure"].GetNodalValues(mc.DISPLACEMENT) for r in runs)
    assert np.abs(constrained - multipliers).max() <= 1e-10 * np.abs(multipliers).max()


@pytest.mark.parametrize("variant", list(VARIANTS_3D))
def test_mpc_tied_patch_3d(tmp_path, variant):
    """Non-matching 3D interface at z = 1 (2 x 2 slave faces against 3 x 3 master ones; quadrilaterals,
    triangles and mixed pairs), rollers on three faces and the normal displacement of a triaxial u = G x on
    the three others: the exact field at every node, the exact traction at every tied slave component."""
    gradient = np.diag([1.0e-3, -1.5e-3, 8.0e-4])
    lower_tets, upper_tets = VARIANTS_3D[variant]
    coords, elements, parts = _two_blocks_3d(lower_tets=lower_tets, upper_tets=upper_tets)
    constraints = []
    ids = np.arange(1, len(coords) + 1)
    for axis, (low, high) in enumerate(((0.0, 1.0), (0.0, 1.0), (0.0, 2.0))):
        for side, plane in (("low", low), ("high", high)):
            name = f"{'XYZ'[axis]}_{side}"
            parts[name] = {"nodes": ids[np.isclose(coords[:, axis], plane)]}
            value = [None, None, None]
            value[axis] = gradient[axis][axis] * plane
            constraints.append(cb.fix_process(name, value))
    analysis = _run(str(tmp_path), "patch3d", coords, elements, parts, "LinearElastic3DLaw",
                    {"constraints": constraints}, mpc=True)
    # 9 slave nodes x 3 components, less the x (y) components of the 6 nodes on the x (y) rollers
    held = lambda x, c: c < 2 and (np.isclose(x[c], 0.0) or np.isclose(x[c], 1.0))  # noqa: E731
    assert _check_mpc_patch(analysis, gradient, [0.0, 0.0, 1.0], 3, held) == 27 - 12
    increments = [record.increment_norm for record in analysis.solver.strategy.GetIterationHistory()]
    assert _iterations(analysis) == [2] and increments[1] <= 1e-10 * increments[0]  # one solve


def test_mpc_tied_cantilever(tmp_path):
    """The cantilever (L/h = 10) cut at mid-length into non-matching meshes (8 against 10 elements through
    the height), tied by constraints: within 1.5 % of Timoshenko's PL^3/(3EI) + PL/(kGA) (measured 0.93 %)
    and the dual-mortar tie's deflection to 1e-8 (measured 8.5e-11): the multipliers' tie D u_s = M u_m,
    with D diagonal (dual basis), is the constraint u_s = D^-1 M u_m itself, so the two differ only in how
    the system is solved (the constraint eliminates the slave DoFs, the multipliers are condensed)."""
    from test_mesh_tying import NU, E

    length, height, load = 10.0, 1.0, -10.0
    mpc, mpc_tip = _cantilever_run(str(tmp_path), "mpc", True, length, height, load, mpc=True)
    dual, dual_tip = _cantilever_run(str(tmp_path), "dual", True, length, height, load)
    tied, multipliers = (np.mean([u[1] for u in tip]) for tip in (mpc_tip, dual_tip))
    inertia = height ** 3 / 12.0
    shear = E / (2 * (1 + NU))
    theory = load * length ** 3 / (3 * E * inertia) + load * length / (5.0 / 6.0 * shear * height)
    print(f"tip deflection: MPC tie {tied:.6e} ({_iterations(mpc)} iterations), dual mortar tie {multipliers:.6e} "
          f"({_iterations(dual)}), Timoshenko {theory:.6e}: MPC/theory {tied / theory:.5f}, MPC/dual "
          f"{tied / multipliers - 1:+.1e}")
    assert tied == pytest.approx(theory, rel=1.5e-2)
    assert tied == pytest.approx(multipliers, rel=1e-8)
    # The same Newton path (the tip LINE_LOAD follows the moving mesh: not quite linear); the MPC solver's
    # plain residual criterion (ratio 4.4e-4 > 1e-4 at the second iteration) takes one more than the
    # contact residual criterion of the multipliers.
    paths = [[record.residual_norm for record in run.solver.strategy.GetIterationHistory()] for run in (mpc, dual)]
    assert len(paths[0]) == len(paths[1]) + 1
    assert np.allclose(paths[0][:len(paths[1])], paths[1], rtol=1e-6, atol=0.0)
    # The tie transmits the tip load to the left (slave) half, which only the clamp holds: the slave nodes'
    # forces are the clamp's reaction, the load on the deformed tip (to 4.4e-4, the follower effect above).
    root = mpc.model["Structure"]
    slaves = [n for n in root.GetSubModelPart("Contact").Nodes if n.Is(mc.SLAVE)]
    transmitted = sum(n.GetValue(mc.GetVariable("CONTACT_FORCE"))[1] for n in slaves)
    clamp = sum(n.GetSolutionStepValue(mc.GetVariable("REACTION_Y")) for n in root.GetSubModelPart("Clamp").Nodes)
    assert transmitted == pytest.approx(-clamp, rel=1e-9)
    assert transmitted == pytest.approx(load, rel=1e-3)


class _TipHistory(StructuralMechanicsAnalysis):
    """The mean vertical displacement of the Tip nodes after each step."""

    def __init__(self, model, params, **kwargs):
        super().__init__(model, params, **kwargs)
        self.tip = []

    def FinalizeSolutionStep(self):
        super().FinalizeSolutionStep()
        nodes = self.model["Structure"].GetSubModelPart("Tip").Nodes
        self.tip.append(np.mean([n.GetSolutionStepValue(mc.DISPLACEMENT)[1] for n in nodes]))


def test_mpc_tied_cantilever_bossak(tmp_path):
    """The cut cantilever loaded suddenly, implicit Bossak dynamics (dt 0.05 over 0.6, about half its first
    period): the tie by constraints follows the dual-mortar tie's tip history within 1e-5 of its largest
    deflection (measured 1.1e-6: the same discrete tie, but the multiplier run accepts every step after one
    solve, its contact residual criterion content with what the tip load, which follows the deforming mesh,
    leaves, where the MPC solver's residual criterion iterates it to 1e-10), and the tip overshoots the
    static deflection (an undamped start)."""
    runs = [_cantilever_run(str(tmp_path), f"bossak_{mpc}", True, mpc=mpc, dynamic=(0.05, 0.6),
                            analysis_class=_TipHistory)[0] for mpc in (True, False)]
    constrained, multipliers = (np.array(run.tip) for run in runs)
    difference = np.abs(constrained - multipliers).max() / np.abs(multipliers).max()
    print(f"Bossak tip history: largest deflection {multipliers.min():.5g}; MPC to dual mortar {difference:.1e}")
    assert len(constrained) == 12 and difference < 1e-5
    assert multipliers.min() < 1.2 * -0.1997  # beyond the static -0.1997


def _run_case(value: str):
    """The shared 2D MPC case (tests/cases/mpc/README.md) tied, its upper block moved by value (y)."""
    params = read_project_parameters(os.path.join(OWN_CASES, f"{CASE}_parameters.json"))
    params["processes"]["constraints_process_list"][1]["Parameters"]["value"][1].SetString(value)
    analysis = StructuralMechanicsAnalysis(mc.Model(), params, progress=False)
    analysis.Run()
    return analysis


def test_shared_2d_case_tied(monkeypatch):
    """The two blocks 0.001 apart, the upper one pushed down 0.2 then pulled up 0.2: the slave nodes move
    with the master ones in both components (the gap is kept, not closed), the force crosses the tie, and
    pressed it is Kratos 10.4's answer on the same files; pulled the tie holds, where Kratos 10.4
    releases it (its reaction check runs on tied nodes too: a defect) and leaves the lower block
    unloaded."""
    import json

    monkeypatch.chdir(OWN_CASES)
    with open(os.path.join(KRATOS_SNAPSHOTS, f"{CASE}_mpc.json")) as f:
        kratos = json.load(f)
    for sign in (-1, 1):
        analysis = _run_case(f"{sign * 0.2}*t")
        root = analysis.model["Structure"]
        u = {i: np.asarray(root.GetNode(i).GetSolutionStepValue(mc.DISPLACEMENT))[:2] for i in range(3, 9)}
        # slave nodes 4 (x = 0) and 3 (x = 1) against master nodes 5 and 6
        assert np.abs(u[4] - u[5]).max() < 1e-15 and np.abs(u[3] - u[6]).max() < 1e-15
        assert sign * u[3][1] > 0.09
        force = sum(root.GetNode(i).GetValue(mc.GetVariable("CONTACT_FORCE"))[1] for i in (3, 4))
        support = sum(root.GetNode(i).GetSolutionStepValue(mc.GetVariable("REACTION_Y")) for i in (1, 2))
        assert force == pytest.approx(-support, rel=1e-9) and sign * force > 0
        if sign < 0:
            worst = max(abs(u[int(key[5:])][k] - value[name]) for key, value in kratos["nodes"].items()
                        for k, name in enumerate(("DISPLACEMENT_X", "DISPLACEMENT_Y")))
            print(f"pressed: {_iterations(analysis)} Newton iterations (Kratos 10.4 {kratos['newton_iterations']}), "
                  f"largest difference to Kratos 10.4 {worst:.1e}")
            assert worst < 1e-9 * 0.2


def test_mesh_tying_input(monkeypatch, capfd):
    """A scalar variable is mesh_tying_process' (ScalarMeshTying); a tie whose process and solver disagree is
    named; reaction_check_stiffness_factor (a tie is never released) and update_each_nl_iteration (the
    relations are built once) warn that they have no effect."""
    monkeypatch.chdir(OWN_CASES)
    params = read_project_parameters(os.path.join(OWN_CASES, f"{CASE}_parameters.json"))
    params["processes"]["contact_process_list"][0]["Parameters"].AddValue(
        "reaction_check_stiffness_factor", mc.Parameters("1.0"))
    params["solver_settings"]["mpc_contact_settings"].AddValue("update_each_nl_iteration", mc.Parameters("true"))
    capfd.readouterr()
    StructuralMechanicsAnalysis(mc.Model(), params, progress=False).Run()
    log = capfd.readouterr().err
    assert "key 'reaction_check_stiffness_factor' = 1.0" in log and "key 'update_each_nl_iteration' = true" in log
    params = read_project_parameters(os.path.join(OWN_CASES, f"{CASE}_parameters.json"))
    params["processes"]["contact_process_list"][0]["Parameters"].AddValue(
        "variable_name", mc.Parameters('"TEMPERATURE"'))
    with pytest.raises(mc.NotImplementedFeatureError, match=r"variable_name.*ScalarMeshTying"):
        StructuralMechanicsAnalysis(mc.Model(), params, progress=False).Run()
    params = read_project_parameters(os.path.join(OWN_CASES, f"{CASE}_parameters.json"))
    params["solver_settings"]["mpc_contact_settings"]["contact_type"].SetString("Frictionless")
    with pytest.raises(mc.InputError, match=r"mpc_contact_process needs .*\"MeshTying\""):
        StructuralMechanicsAnalysis(mc.Model(), params, progress=False).Run()
