"""Issue 13: frictional MPC contact (mpc_contact_process and mpc_contact_settings with contact_type
Frictional or FrictionalPureSlip, Coulomb, 2D and 3D).

- a block pressed on a clamped base by its weight and pushed sideways (an imposed displacement of a
  node of its left side, at mid-height or at its top corner): a small push sticks (the interface
  carries the push, below mu times the weight, no node slips); a large one slides (the push needs
  exactly mu times the normal force, to 1e-8);
- Newton converges: once the stick / slip state stops changing, the next iteration's residual is
  round-off (the Coulomb force is in the system with its exact tangent);
- the shared 2D frictional MPC case: the right state is stick (the interface needs 3e-5 of the normal
  force tangentially, mu = 0.1); ours passes the reference file to 1e-3. Kratos 10.4 ties every
  component without closing the 0.001 gap, 0.5 % from that reference;
- Cattaneo-Mindlin in 2D against ALM frictional on the same mesh (about 12 s for both runs);
- 3D: the block pushed at its top sticks or slides (every slipping node's friction against its slip);
- FrictionalPureSlip, 2D and 3D: the pushed block slides with mu times the normal force, the way it is
  pushed; under a push where Coulomb sticks somewhere pure slip has no answer, and the step stops with
  an error naming the nodes whose slip direction keeps reversing.
"""
from __future__ import annotations

import importlib.util
import json
import os

import numpy as np
import pytest
from test_contact_cases import run_csma_case

import mortarcontact as mc

from case_builder import fix_process, run_analysis, write_block_on_base, write_block_on_base_3d
from csma_cases import reference_nodes

V = mc.GetVariable
FRICTION = 0.3
GRAVITY = 1.0e3
BLOCK, BASE = (0.5, 0.1), (1.0, 0.25)
WEIGHT = BLOCK[0] * BLOCK[1] * GRAVITY  # density 1, thickness 1
CASE_2D = "mpc_contact_tests/2D_contact_simplest_with_friction_patch_matching_test"


def _pushed_block(folder, where: str, push: float, contact_type: str = "Frictional"):
    """The static block pressed by its weight; the node(s) of sub-part `where` moved by `push` along x."""
    analysis = run_analysis(str(folder), _pushed_block_case(folder, where, push, contact_type))
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    return analysis


def _pushed_block_case(folder, where: str, push: float, contact_type: str) -> str:
    """The project parameters' file of _pushed_block's case."""
    os.makedirs(folder, exist_ok=True)
    path = write_block_on_base(
        str(folder), "block", block=BLOCK, base=BASE, cells=(8, 4, 12, 3), friction=FRICTION,
        gravity=(GRAVITY, (0.0, -1.0, 0.0)), end_time=1.0, time_step=1.0,
        solver={"solver_type": "Static", "mpc_contact_settings": {"contact_type": contact_type},
                "residual_relative_tolerance": 1e-12, "residual_absolute_tolerance": 1e-14, "max_iteration": 30},
        contact=("mpc_contact_process", {"contact_type": contact_type}))
    with open(os.path.join(folder, path)) as f:
        parameters = json.load(f)
    parameters["processes"]["constraints_process_list"].append(
        fix_process(f"Structure.{where}", [push, 0.0, 0.0], constrained=(True, False, False)))
    with open(os.path.join(folder, path), "w") as f:
        json.dump(parameters, f)
    return path


def _interface(analysis):
    """(slave nodes, their summed CONTACT_FORCE)."""
    root = analysis.model["Structure"]
    slaves = [n for n in root.GetSubModelPart("Contact").Nodes if n.Is(mc.SLAVE)]
    force = sum(np.array(n.GetValue(V("CONTACT_FORCE"))) for n in slaves)
    return slaves, force


def _push(analysis, where):
    """REACTION_X of the pushed node(s): the push the block needs."""
    nodes = analysis.model["Structure"].GetSubModelPart(where).Nodes
    return sum(n.GetSolutionStepValue(V("REACTION_X")) for n in nodes)


def _history(analysis):
    return [record.residual_norm for record in analysis.solver.strategy.GetIterationHistory()]


@pytest.mark.parametrize("where", ["block_side", "block_corner"])
def test_small_push_sticks(tmp_path, where):
    """A push of 2e-6 needs less than mu times the weight: every node sticks, the interface carries the
    push and the weight (to 1e-9), and the slave nodes keep their place on the master."""
    analysis = _pushed_block(tmp_path, where, 2.0e-6)
    slaves, force = _interface(analysis)
    push = _push(analysis, where)
    print(f"stick, pushed at {where}: push {push:.6g} (mu W = {FRICTION * WEIGHT}), "
          f"{analysis.step_log[0][2]} Newton iterations, residuals {_history(analysis)}")
    assert 0.0 < push < FRICTION * WEIGHT
    assert all(n.Is(mc.ACTIVE) and not n.Is(mc.SLIP) for n in slaves)
    assert force[0] == pytest.approx(-push, rel=1e-9)
    assert force[1] == pytest.approx(WEIGHT, rel=1e-9)


@pytest.mark.parametrize("where", ["block_side", "block_corner"])
def test_large_push_slides_with_the_coulomb_force(tmp_path, where):
    """A push of 1e-3 (the block's elastic shear at mu times the weight is of order 1e-5): every node in
    contact slips (pushed at the top corner, the rear corner node lifts a little), the push needs mu times
    the normal force to 1e-8, and Newton's iteration after the stick / slip state settles brings the
    residual to round-off (the Coulomb force's tangent is exact)."""
    analysis = _pushed_block(tmp_path, where, 1.0e-3)
    slaves, force = _interface(analysis)
    push = _push(analysis, where)
    history = _history(analysis)
    print(f"slide, pushed at {where}: push {push:.10g} (mu W = {FRICTION * WEIGHT}), "
          f"{analysis.step_log[0][2]} Newton iterations, residuals {history}")
    active = [n for n in slaves if n.Is(mc.ACTIVE)]
    assert len(active) >= len(slaves) - 1 and all(n.Is(mc.SLIP) for n in active)
    assert all(np.linalg.norm(n.GetValue(V("CONTACT_FORCE"))) == 0.0 for n in slaves if not n.Is(mc.ACTIVE))
    assert force[1] == pytest.approx(WEIGHT, rel=1e-9)
    assert push == pytest.approx(FRICTION * force[1], rel=1e-8)
    assert -force[0] == pytest.approx(FRICTION * force[1], rel=1e-8)
    assert history[-1] < 1e-12 * max(history) < history[-2]


def test_shared_2d_frictional_case(csma_cases, monkeypatch):
    """The shared case runs unchanged and passes its reference file (its own json check, 1e-3): the
    interface needs a tangential force 3e-5 of the normal one, well inside mu = 0.1, so every node
    sticks and the 0.001 gap is closed. The reference equals the frictionless answer of the older
    Kratos that wrote it; Kratos 10.4 leaves the gap open (0.5 % from it)."""
    monkeypatch.chdir(csma_cases)
    analysis, _ = run_csma_case(CASE_2D, "mpc")
    root = analysis.model["Structure"]
    slaves = list(root.GetSubModelPart("Contact_Part_Slave").Nodes)
    assert all(n.Is(mc.ACTIVE) and not n.Is(mc.SLIP) for n in slaves)
    tangential = sum(abs(n.GetValue(V("CONTACT_FORCE"))[0]) for n in slaves)
    normal = sum(abs(n.GetValue(V("CONTACT_FORCE"))[1]) for n in slaves)
    reference = reference_nodes(CASE_2D)
    difference = max(abs(analysis.snapshot[node][name] - value) for node, values in reference.items()
                     for name, value in values.items()) / max(abs(v) for values in reference.values()
                                                               for v in values.values())
    print(f"2D frictional MPC: {[it for _, _, it, _, _ in analysis.step_log]} Newton iterations; tangential / "
          f"normal force {tangential / normal:.2e}; to the reference {difference:.1e}")
    assert tangential < 0.1 * normal
    assert difference < 1e-3
    uy = {i: root.GetNode(i).GetSolutionStepValue(V("DISPLACEMENT_Y")) for i in (3, 4, 5, 6)}
    assert uy[4] - uy[5] == pytest.approx(0.001, abs=1e-12)
    assert uy[3] - uy[6] == pytest.approx(0.001, abs=1e-12)


@pytest.mark.parametrize("push", [1.0e-3, -1.0e-3])
def test_pure_slip_slides_the_way_it_is_pushed(tmp_path, push):
    """FrictionalPureSlip in 2D: every node in contact slips, the push needs mu times the normal force
    (1e-8) and the friction opposes the push, either way."""
    analysis = _pushed_block(tmp_path, "block_side", push, contact_type="FrictionalPureSlip")
    slaves, force = _interface(analysis)
    reaction = _push(analysis, "block_side")
    history = _history(analysis)
    print(f"pure slip, push {push}: {reaction:.10g} (mu W = {FRICTION * WEIGHT}), {analysis.step_log[0][2]} "
          f"Newton iterations, residuals {history}")
    active = [n for n in slaves if n.Is(mc.ACTIVE)]
    assert len(active) == len(slaves) and all(n.Is(mc.SLIP) for n in active)
    assert force[1] == pytest.approx(WEIGHT, rel=1e-9)
    assert reaction == pytest.approx(np.sign(push) * FRICTION * force[1], rel=1e-8)
    assert -force[0] == pytest.approx(reaction, rel=1e-8)
    assert analysis.step_log[0][2] <= 2


def test_pure_slip_under_the_weakest_push_that_slides(tmp_path):
    """A push of 7e-5, of the order of the block's own Poisson slip (the slip of the interface varies by
    1.6e-5 across it): Coulomb slides every node there, and so pure slip converges to the same answer,
    every node's friction mu |f_n| (1e-8) against its slip, in 2 iterations."""
    coulomb = _pushed_block(tmp_path / "coulomb", "block_side", 7.0e-5)
    analysis = _pushed_block(tmp_path / "pure", "block_side", 7.0e-5, contact_type="FrictionalPureSlip")
    slaves, force = _interface(analysis)
    assert all(n.Is(mc.ACTIVE) and n.Is(mc.SLIP) for n in _interface(coulomb)[0])
    assert all(n.Is(mc.ACTIVE) and n.Is(mc.SLIP) for n in slaves)
    for n in slaves:
        f = np.array(n.GetValue(V("CONTACT_FORCE")))
        assert abs(f[0]) == pytest.approx(FRICTION * f[1], rel=1e-8)
        assert f[0] * n.GetSolutionStepValue(V("DISPLACEMENT_X")) < 0.0
    assert -force[0] == pytest.approx(FRICTION * force[1], rel=1e-8)
    assert force[1] == pytest.approx(WEIGHT, rel=1e-9)
    assert analysis.step_log[0][2] <= 2


@pytest.mark.parametrize("push", [1.0e-5, -3.0e-5, 5.0e-5])
def test_pure_slip_under_a_weak_push_stops_with_a_clear_error(tmp_path, push):
    """Under a push too small to slide the whole block (the Coulomb answer sticks somewhere), pure slip
    has no answer: with the normal forces held, a pure-slip answer would be an answer of the Coulomb
    problem, which is unique. The iterations flip the slip directions for ever (before: 30 iterations
    and a bare non-convergence); now the step stops after 3 reversals with a SolutionError naming the
    reversing nodes and contact_type "Frictional"."""
    coulomb = _pushed_block(tmp_path / "coulomb", "block_side", push)
    sticking = {n.Id for n in _interface(coulomb)[0] if n.Is(mc.ACTIVE) and not n.Is(mc.SLIP)}
    assert sticking
    path = _pushed_block_case(tmp_path / "pure", "block_side", push, "FrictionalPureSlip")
    with pytest.raises(mc.SolutionError) as error:
        run_analysis(str(tmp_path / "pure"), path)
    message = str(error.value)
    print(f"push {push}: Coulomb sticks at {sorted(sticking)}; {message}")
    assert '"FrictionalPureSlip"' in message and 'contact_type "Frictional"' in message
    assert "reversed in each of the last 3 iterations" in message
    named = {int(i) for i in message.split("slave node(s) ")[1].split(" reversed")[0].split(", ")}
    slaves = {n.Id for n in _interface(coulomb)[0]}
    assert named and named <= slaves


def test_pure_slip_3d_under_a_weak_push_stops_with_a_clear_error(tmp_path):
    """3D: the top pushed by (2e-6, 1e-6), where Coulomb sticks (test_3d_block_pushed_at_its_top): the
    directions reverse as in 2D and the step stops with the same error (a push of (2e-5, 1e-5) slides,
    and pure slip converges there in 6 iterations)."""
    with pytest.raises(mc.SolutionError, match=r'reversed in each of the last 3 iterations.*"Frictional"'):
        _pushed_block_3d(tmp_path, (2.0e-6, 1.0e-6), contact_type="FrictionalPureSlip")


@pytest.mark.parametrize("push", [(1.0e-3, 5.0e-4), (-1.0e-3, 5.0e-4)])
def test_pure_slip_3d_slides_the_way_it_is_pushed(tmp_path, push):
    """FrictionalPureSlip in 3D: every node in contact slips; the friction forces sum to mu W in
    magnitude (1e-8) and their resultant opposes the push (1e-4: the directions differ slightly)."""
    analysis = _pushed_block_3d(tmp_path, push, contact_type="FrictionalPureSlip")
    slaves, force = _interface(analysis)
    print(f"3D pure slip, push {push}: {analysis.step_log[0][2]} Newton iterations, residuals {_history(analysis)}")
    active = [n for n in slaves if n.Is(mc.ACTIVE)]
    assert len(active) == len(slaves) and all(n.Is(mc.SLIP) for n in active)
    total = sum(np.linalg.norm(np.array(n.GetValue(V("CONTACT_FORCE")))[:2]) for n in active)
    assert total == pytest.approx(FRICTION * WEIGHT_3D, rel=1e-8)
    direction = np.array(push) / np.linalg.norm(push)
    assert np.dot(-force[:2], direction) == pytest.approx(FRICTION * WEIGHT_3D, rel=1e-4)
    assert analysis.step_log[0][2] <= 7


def _pushed_block_3d(folder, push, contact_type: str = "Frictional"):
    """The 3D block (0.4 x 0.4 x 0.1 on a 0.8 x 0.8 x 0.2 base) pressed by its weight, its top face moved
    by `push` in the plane."""
    path = write_block_on_base_3d(
        str(folder), "block3d", block=BLOCK_3D, base=(0.8, 0.8, 0.2), cells=(4, 4, 2, 6, 6, 2), friction=FRICTION,
        gravity=(GRAVITY, (0.0, 0.0, -1.0)),
        solver={"mpc_contact_settings": {"contact_type": contact_type},
                "residual_relative_tolerance": 1e-12, "residual_absolute_tolerance": 1e-14, "max_iteration": 30},
        contact=("mpc_contact_process", {"contact_type": contact_type}))
    with open(os.path.join(folder, path)) as f:
        parameters = json.load(f)
    parameters["processes"]["constraints_process_list"].append(
        fix_process("Structure.block_top", [*push, 0.0], constrained=(True, True, False)))
    with open(os.path.join(folder, path), "w") as f:
        json.dump(parameters, f)
    analysis = run_analysis(str(folder), path)
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    return analysis


BLOCK_3D = (0.4, 0.4, 0.1)
WEIGHT_3D = BLOCK_3D[0] * BLOCK_3D[1] * BLOCK_3D[2] * GRAVITY


@pytest.mark.parametrize("push", [(2.0e-6, 1.0e-6), (1.0e-3, 5.0e-4)], ids=["stick", "slide"])
def test_3d_block_pushed_at_its_top(tmp_path, push):
    """3D: the block pressed by its weight, its top face pushed along (2, 1). A small push sticks: the
    interface carries the push, below mu W. A large one slides: every node in contact slips, its
    tangential force mu times its normal one (1e-8) against its slip, and the forces balance the push
    and the weight; once the state has settled, Newton converges quadratically."""
    analysis = _pushed_block_3d(tmp_path, push)
    slaves, force = _interface(analysis)
    reaction = sum(np.array(n.GetSolutionStepValue(V("REACTION")))
                   for n in analysis.model["Structure"].GetSubModelPart("block_top").Nodes)
    history = _history(analysis)
    print(f"3D {'stick' if push[0] < 1e-5 else 'slide'}: push {reaction[:2]} (mu W = {FRICTION * WEIGHT_3D}), "
          f"{analysis.step_log[0][2]} Newton iterations, residuals {history}")
    assert force[2] == pytest.approx(WEIGHT_3D, rel=1e-9)
    assert np.linalg.norm(force[:2] + reaction[:2]) < 1e-9 * WEIGHT_3D
    active = [n for n in slaves if n.Is(mc.ACTIVE)]
    if push[0] < 1e-5:
        assert len(active) == len(slaves)
        assert np.linalg.norm(reaction[:2]) < FRICTION * WEIGHT_3D
        # Corner nodes slip under the Poisson mismatch with s held within an iteration: superlinear
        # (2.3, 1.8e-3, 1.1e-5, 1.4e-8, 7e-14).
        assert analysis.step_log[0][2] <= 5
        return
    assert active and all(n.Is(mc.SLIP) for n in active)
    for n in active:
        f = np.array(n.GetValue(V("CONTACT_FORCE")))
        assert f[2] > 0.0
        assert np.linalg.norm(f[:2]) == pytest.approx(FRICTION * f[2], rel=1e-8, abs=1e-10 * WEIGHT_3D)
        slip = np.array(n.GetSolutionStepValue(V("DISPLACEMENT")))[:2]
        assert np.dot(f[:2], slip) < 0.0
    # The Coulomb forces sum to mu W in magnitude; their directions differ slightly (the block shears).
    total = sum(np.linalg.norm(np.array(n.GetValue(V("CONTACT_FORCE")))[:2]) for n in active)
    assert total == pytest.approx(FRICTION * WEIGHT_3D, rel=1e-8)
    assert np.linalg.norm(force[:2]) == pytest.approx(FRICTION * WEIGHT_3D, rel=1e-4)
    # 7 iterations: 312, 10, 0.06, 0.32 (the state settled), 3.5e-4, 5.8e-9, 2.4e-13: quadratic.
    assert analysis.step_log[0][2] <= 7
    scaled = np.array(history) / history[0]
    assert scaled[-2] < 100 * scaled[-3] ** 2


@pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")
def test_cattaneo_mindlin_2d_against_alm(tmp_path):
    """The 2D Cattaneo-Mindlin run (hertz2d_8k pressed, then shifted) with frictional MPC against ALM
    frictional on the same mesh. Measured: the stick zone c/a is ALM's at every shift step (0.937 ...
    0.346, closed form 0.940 ... 0.359), the tangential tractions are as close to the closed form (rms
    0.036-0.043 mu p0 for both), in 3 Newton iterations per shift step (ALM: 3, and 4 at the last)."""
    from test_cattaneo_mindlin import run

    alm, _ = run(2, "8k", str(tmp_path / "alm"))
    ours, _ = run(2, "8k", str(tmp_path / "mpc"), mpc=True)
    for label, results in (("ALM", alm), ("MPC", ours)):
        print(label + ": " + "; ".join(
            f"Q/muP {r['load_ratio']:.3f} c/a {r['c'] / r['a']:.3f} (theory {r['c_theory'] / r['a']:.3f}) "
            f"q rms {r['traction_error_rms']:.3f} max {r['traction_error_max']:.3f} mu p0, {r['iterations']} it"
            for r in results))
    assert len(ours) == len(alm)
    for mine, theirs in zip(ours, alm):
        assert mine["load_ratio"] == pytest.approx(theirs["load_ratio"], abs=0.02)
        # Coulomb holds in the relation's normal up to the Newton tolerance (measured: 1.2e-8 p0 at most)
        assert mine["slip_rule_error"] < 1e-6
        assert abs(mine["c_error"]) < 0.03
        assert abs(mine["c"] - theirs["c"]) < 0.01 * theirs["a"]
        assert mine["traction_error_rms"] < 0.05
        assert abs(mine["traction_error_rms"] - theirs["traction_error_rms"]) < 0.005
        assert mine["iterations"] <= theirs["iterations"]


@pytest.mark.slow
@pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")
def test_cattaneo_mindlin_3d(tmp_path, monkeypatch):
    """The 3D Cattaneo-Mindlin run (the half hertz3dgrid sphere on a coarse mesh, spacing twice the
    15k one's: 41 slave nodes in contact) with frictional MPC against ALM frictional on the same
    mesh, about 100 s. The stick radius (from the nodal areas, over the contact radius measured the
    same way) is ALM's within 0.01 a at every shift step (measured 0.964, 0.895, 0.811, 0.757, 0.688,
    0.603, 0.516, 0.474 against ALM's 0.964, 0.895, 0.811, 0.766, 0.698, 0.611, 0.524, 0.474) and the
    closed form's within 0.05 a, as ALM's is (test_cattaneo_mindlin.py). MPC takes 7-9 Newton
    iterations per shift step, ALM 3-6."""
    from test_cattaneo_mindlin import run

    from mortarcontact.cases import hertz

    monkeypatch.setitem(hertz.SIZES["hertz3dgrid"], "coarse", 2.0)
    results, _ = run(3, "coarse", str(tmp_path / "mpc"), mpc=True)
    alm, _ = run(3, "coarse", str(tmp_path / "alm"))
    print("; ".join(f"Q/muP {r['load_ratio']:.3f} c/a {r['c'] / r['a_from_areas']:.3f} (ALM "
                    f"{s['c'] / s['a_from_areas']:.3f}, theory {r['c_theory'] / r['a']:.3f}) slip rule "
                    f"{r['slip_rule_error']:.1e} p0, {r['iterations']} it (ALM {s['iterations']})"
                    for r, s in zip(results, alm)))
    ratios = [r["load_ratio"] for r in results]
    assert len(results) == len(alm) and ratios == sorted(ratios) and 0.85 < ratios[-1] < 1.0
    for r, s in zip(results, alm):
        assert abs(r["c"] / r["a_from_areas"] - s["c"] / s["a_from_areas"]) < 0.015
        assert abs(r["c"] / r["a_from_areas"] - r["c_theory"] / r["a"]) < 0.05
        assert r["slip_rule_error"] < 5e-3
        assert r["iterations"] <= 9


@pytest.mark.slow
@pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")
def test_cattaneo_mindlin_3d_15k(tmp_path):
    """The 15k half sphere (hertz3dgrid_15k) with frictional MPC, about 400 s under load. It stopped at
    step 15 (Q = 0.83 mu P: 30 iterations, |r| 1.9e-3): node 977 at the stick zone's edge started to
    slip with a slip of 2e-8, stuck again when that slip turned against s, and the cycle guard held it
    slipping, where its s flipped every iteration (|s_new - s_old| 1.7-2.0) and dragged nodes 966 and
    978 along. Held stuck, every shift step converges in 7-10 iterations: stick radius 0.938 ... 0.433 a
    (closed form 0.950 ... 0.457, within 0.03 a), the slipping nodes on the cone to 9.4e-4 p0 (the
    relation's normal against the step's end one) and the sticking ones at most 9.5e-4 p0 outside it."""
    from test_cattaneo_mindlin import run

    results, _ = run(3, "15k", str(tmp_path), mpc=True)
    print("; ".join(f"Q/muP {r['load_ratio']:.3f} c/a {r['c'] / r['a_from_areas']:.3f} (theory "
                    f"{r['c_theory'] / r['a']:.3f}) slip rule {r['slip_rule_error']:.1e} stick excess "
                    f"{r['stick_excess']:.1e} p0, {r['iterations']} it" for r in results))
    ratios = [r["load_ratio"] for r in results]
    assert len(results) == 8 and ratios == sorted(ratios) and 0.85 < ratios[-1] < 1.0
    for r in results:
        assert abs(r["c"] / r["a_from_areas"] - r["c_theory"] / r["a"]) < 0.05
        assert r["slip_rule_error"] < 2e-3 and r["stick_excess"] < 2e-3
        assert r["iterations"] <= 10
