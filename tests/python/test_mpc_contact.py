"""Issue 13, item 2: multipoint-constraint (MPC) contact (mpc_contact_settings, mpc_contact_process).

- the shared 3D case passes its reference file (from an older Kratos revision, which closes the
  initial penetration as we do) and runs in Kratos 10.4's Newton iterations;
- the shared 2D case closes its initial gap exactly and transmits the support reaction; Kratos 10.4
  ties the displacements without the gap, so its answer is the same problem without a gap, which
  ours matches on the zero-gap copy of the case (tests/cases/mpc);
- a pulled interface is released by the reaction check; the settings are validated;
- the 2D Hertz cylinder with MPC gives ALM's pressure and contact width, both close to Hertz.

Newton iterations: ours are Kratos 10.4's or one more per step (_at_most_one_more).
"""
from __future__ import annotations

import json
import os

import numpy as np
import pytest
from test_contact_cases import SnapshotAnalysis, run_csma_case

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.project_parameters import read_project_parameters

from case_builder import fix_process, project_parameters, run_analysis, structured_quads, write_case, write_mdpa
from csma_cases import CSMA_CASES, KRATOS_SNAPSHOTS, reference_nodes, reference_values

CASE_3D = "mpc_contact_tests/3D_contact_simplest_patch_matching_test"
CASE_2D = "mpc_contact_tests/2D_contact_simplest_patch_matching_test"
ZERO_GAP = "../mpc/2D_zero_gap_patch_test"
OWN_CASES = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "cases", "mpc"))
# Both codes solve the same linear constrained system at convergence: round-off of the direct solvers.
KRATOS_TOLERANCE = 1e-9


def _kratos(case: str) -> dict:
    with open(os.path.join(KRATOS_SNAPSHOTS, f"{os.path.basename(case)}_mpc.json")) as f:
        return json.load(f)


def _difference(values: dict, expected: dict) -> float:
    """max |value - expected| relative to the largest expected magnitude."""
    pairs = [(values[key][name], node[name]) for key, node in expected.items() for name in node]
    return max(abs(v - e) for v, e in pairs) / max(abs(e) for _, e in pairs)


def _iterations(analysis) -> list[int]:
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    return [it for _, _, it, _, _ in analysis.step_log]


def _at_most_one_more(ours: list[int], kratos: list[int]) -> bool:
    """Per step, Kratos 10.4's Newton iterations or one more: our residual criterion takes its reference
    at the first iteration's residual (before the solve), so even a linear step needs a second
    iteration to see the residual fall; Kratos 10.4 reports one there."""
    return len(ours) == len(kratos) and all(k <= o <= k + 1 for o, k in zip(ours, kratos))


def _node(analysis, node_id: int):
    return analysis.model["Structure"].GetNode(node_id)


def test_shared_3d_case(csma_cases, monkeypatch):
    """Passes its own json check (1e-3) and the reference to 1e-6 relative: the interface starts 1e-5
    inside, and the reference (an older Kratos) closes it as we do; Kratos 10.4 keeps it (5e-5 away)."""
    monkeypatch.chdir(csma_cases)
    analysis, _ = run_csma_case(CASE_3D, "mpc")
    kratos = _kratos(CASE_3D)
    reference = reference_nodes(CASE_3D)
    to_reference = _difference(analysis.snapshot, reference)
    kratos_to_reference = _difference(kratos["nodes"], reference)
    print(f"3D MPC: {_iterations(analysis)} Newton iterations (Kratos 10.4: {kratos['newton_iterations']}); "
          f"to the reference {to_reference:.1e} (Kratos 10.4 {kratos_to_reference:.1e})")
    assert to_reference < 1e-6 < kratos_to_reference
    assert _at_most_one_more(_iterations(analysis), kratos["newton_iterations"])
    # Every slave node pressed, the same pressure (a uniform state), the force balancing the support.
    root = analysis.model["Structure"]
    slaves = list(root.GetSubModelPart("Contact_Part_Slave").Nodes)
    stresses = [n.GetValue(mc.GetVariable("NORMAL_CONTACT_STRESS")) for n in slaves]
    assert all(n.Is(mc.ACTIVE) for n in slaves)
    assert max(stresses) < 0 and (max(stresses) - min(stresses)) < 1e-9 * abs(min(stresses))
    force = sum(n.GetValue(mc.GetVariable("CONTACT_FORCE"))[2] for n in slaves)
    support = sum(n.GetSolutionStepValue(mc.GetVariable("REACTION_Z"))
                  for n in root.GetSubModelPart("DISPLACEMENT_Displacement_Auto1").Nodes)
    assert force == pytest.approx(-support, rel=1e-9)


def test_shared_2d_case_closes_the_gap(csma_cases, monkeypatch):
    """The 0.001 gap closes exactly (slave and master faces meet), the contact force is the support's,
    and the lateral displacements are free to differ (frictionless)."""
    monkeypatch.chdir(csma_cases)
    analysis, _ = run_csma_case(CASE_2D, "mpc", own_checks=False)
    uy = {i: _node(analysis, i).GetSolutionStepValue(mc.GetVariable("DISPLACEMENT_Y")) for i in (3, 4, 5, 6)}
    # Slave nodes 4 (x = 0) and 3 (x = 1) face master nodes 5 (x = 0) and 6 (x = 1).
    assert uy[4] - uy[5] == pytest.approx(0.001, abs=1e-12)
    assert uy[3] - uy[6] == pytest.approx(0.001, abs=1e-12)
    root = analysis.model["Structure"]
    force = sum(_node(analysis, i).GetValue(mc.GetVariable("CONTACT_FORCE"))[1] for i in (3, 4))
    support = sum(_node(analysis, i).GetSolutionStepValue(mc.GetVariable("REACTION_Y")) for i in (1, 2))
    assert force == pytest.approx(-support, rel=1e-9) and force < 0
    # The pressure is the node's force over its share of the current overlap: the master face, which
    # expands laterally a little less than the slave face, bounds it.
    node = root.GetNode(3)
    assert node.GetValue(mc.GetVariable("NORMAL_CONTACT_STRESS")) == pytest.approx(
        node.GetValue(mc.GetVariable("CONTACT_FORCE"))[1] / node.GetValue(mc.GetVariable("NODAL_MAUX")), rel=1e-12)
    assert node.GetValue(mc.GetVariable("NODAL_MAUX")) == pytest.approx(
        0.5 + root.GetNode(6).GetSolutionStepValue(mc.GetVariable("DISPLACEMENT_X")), rel=1e-12)
    kratos = _kratos(CASE_2D)
    kratos_gap = kratos["nodes"]["NODE_3"]["DISPLACEMENT_Y"] - kratos["nodes"]["NODE_6"]["DISPLACEMENT_Y"]
    print(f"2D MPC: {_iterations(analysis)} Newton iterations (Kratos 10.4: {kratos['newton_iterations']}); "
          f"Kratos 10.4 leaves the gap at {0.001 + kratos_gap:.6f}")
    assert _at_most_one_more(_iterations(analysis), kratos["newton_iterations"])


def test_zero_gap_2d_case_matches_kratos(monkeypatch):
    """Without a gap Kratos 10.4's tie and ours are the same constraint: the same displacements."""
    monkeypatch.chdir(OWN_CASES)
    params = read_project_parameters(os.path.join(OWN_CASES, "2D_zero_gap_patch_test_parameters.json"))
    time, nodes = reference_values(ZERO_GAP)
    analysis = SnapshotAnalysis(mc.Model(), params, time, nodes)
    analysis.Run()
    kratos = _kratos(ZERO_GAP)
    difference = _difference(analysis.snapshot, kratos["nodes"])
    print(f"2D zero gap: {_iterations(analysis)} Newton iterations (Kratos 10.4: {kratos['newton_iterations']}); "
          f"difference to Kratos 10.4 {difference:.1e}")
    assert difference < KRATOS_TOLERANCE
    assert _at_most_one_more(_iterations(analysis), kratos["newton_iterations"])


def _run_2d(folder, edit):
    """The shared 2D case (run from the shared folder) with its parameters edited by ``edit`` (a dict)."""
    with open(os.path.join(CSMA_CASES, f"{CASE_2D}_parameters.json")) as f:
        params = json.load(f)
    params["processes"].pop("json_check_process")
    edit(params)
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, "parameters.json")
    with open(path, "w") as f:
        json.dump(params, f)
    analysis = StructuralMechanicsAnalysis(mc.Model(), read_project_parameters(path), progress=False)
    analysis.Run()
    return analysis


def _mpc_settings(**keys):
    return lambda params: params["solver_settings"]["mpc_contact_settings"].update(keys)


def _process_settings(**keys):
    return lambda params: params["processes"]["contact_process_list"][0]["Parameters"].update(keys)


def test_pulled_interface_is_released(csma_cases, monkeypatch, tmp_path):
    """Pulling the upper block away: the search predicts contact (gap 0.001 < 0.01 h), the predictor's
    reactions pull, the reaction check releases both slave nodes and the lower block stays unloaded."""
    monkeypatch.chdir(csma_cases)

    def pull(params):
        params["processes"]["constraints_process_list"][1]["Parameters"]["value"] = [0.0, "2.0e-1*t", 0.0]
    analysis = _run_2d(tmp_path, pull)
    root = analysis.model["Structure"]
    assert not any(root.GetNode(i).Is(mc.ACTIVE) for i in (3, 4))
    assert all(abs(root.GetNode(i).GetSolutionStepValue(mc.GetVariable("DISPLACEMENT_Y"))) < 1e-15 for i in (3, 4))
    assert all(root.GetNode(i).GetValue(mc.GetVariable("NORMAL_CONTACT_STRESS")) == 0.0 for i in (3, 4))


def test_mpc_contact_settings(csma_cases, monkeypatch, tmp_path):
    """solver_settings.mpc_contact_settings: the simplified semi-smooth Newton (passes of
    inner_loop_iterations on a frozen set) and update_each_nl_iteration give the same answer on the
    2D case; PureSlip is a variant of Frictional only; an unknown key names the nearest one."""
    monkeypatch.chdir(csma_cases)
    base = _run_2d(tmp_path / "base", lambda p: None)
    uy = base.model["Structure"].GetNode(3).GetSolutionStepValue(mc.GetVariable("DISPLACEMENT_Y"))
    for keys in ({"simplified_semi_smooth_newton": True, "inner_loop_iterations": 3},
                 {"update_each_nl_iteration": True}):
        analysis = _run_2d(tmp_path / str(len(keys)), _mpc_settings(**keys))
        strategy = analysis.solver.strategy
        assert strategy.InnerLoopIterations() == 1  # the predictor's set holds
        node = analysis.model["Structure"].GetNode(3)
        assert node.GetSolutionStepValue(mc.GetVariable("DISPLACEMENT_Y")) == pytest.approx(uy, rel=1e-12)
    with pytest.raises(mc.InputError, match=r"mpc_contact_settings\.contact_type.*did you mean 'FrictionalPureSlip'"):
        _run_2d(tmp_path, _mpc_settings(contact_type="FrictionlessPureSlip"))
    with pytest.raises(mc.InputError, match="inner_loop_iterations"):
        _run_2d(tmp_path, _mpc_settings(inner_loop_iteration=3))
    with pytest.raises(mc.InputError, match=r"inner_loop_iterations: 0 must be at least 1"):
        _run_2d(tmp_path, _mpc_settings(inner_loop_iterations=0))


def test_mpc_contact_process_keys(csma_cases, monkeypatch, tmp_path):
    """mpc_contact_process: reaction_check_stiffness_factor reaches the active-set check (a threshold
    above the contact pressure releases the pressed nodes, which then penetrate and come back: the
    cycle guard holds them, at the cost of iterations); the contact types and the other keys are
    validated, naming the key and the nearest valid value."""
    monkeypatch.chdir(csma_cases)
    # E = 2.069e11; the pressure is about 2.3e10: a factor 1 releases the nodes, which then penetrate.
    base = _run_2d(tmp_path / "base", lambda p: None)
    released = _run_2d(tmp_path / "released", _process_settings(reaction_check_stiffness_factor=1.0))
    assert _iterations(released)[0] > _iterations(base)[0]
    for i in (3, 4):
        assert released.model["Structure"].GetNode(i).Is(mc.ACTIVE)
    with pytest.raises(mc.InputError, match=r"reaction_check_stiffness_factor: must be a non-negative number"):
        _run_2d(tmp_path, _process_settings(reaction_check_stiffness_factor=-1.0))
    with pytest.raises(mc.InputError, match=r"contact_type.*did you mean 'Frictionless'"):
        _run_2d(tmp_path, _process_settings(contact_type="Frictionles"))
    with pytest.raises(mc.InputError, match=r"contact_type: 'FrictionlessPureSlip'.*did you mean 'FrictionalPureSlip'"):
        _run_2d(tmp_path, _process_settings(contact_type="FrictionlessPureSlip"))
    with pytest.raises(mc.InputError, match=r"normal_variation: unknown value"):
        _run_2d(tmp_path, _process_settings(normal_variation="nodal"))
    with pytest.raises(mc.InputError, match=r"mpc_contact_process needs solver_settings\.mpc_contact_settings"):
        _run_2d(tmp_path, lambda p: p["solver_settings"].pop("mpc_contact_settings"))


def _hertz_run(folder: str) -> tuple[dict, list[int]]:
    """Runs a generated Hertz case; its evaluation against Hertz and its Newton iterations per step."""
    from mortarcontact.cases import hertz

    analysis = StructuralMechanicsAnalysis(
        mc.Model(), read_project_parameters(os.path.join(folder, "ProjectParameters.json")), progress=False)
    analysis.Run()
    root = analysis.model["Structure"]
    slave = [{"x": n.X0, "y": n.Y0, "active": n.Is(mc.ACTIVE), "augmented": None,
              "lm": (n.GetSolutionStepValue(mc.GetVariable("LAGRANGE_MULTIPLIER_CONTACT_PRESSURE"))
                     if n.HasSolutionStepValue(mc.GetVariable("LAGRANGE_MULTIPLIER_CONTACT_PRESSURE")) else None),
              "normal_contact_stress": n.GetValue(mc.GetVariable("NORMAL_CONTACT_STRESS"))}
             for n in root.GetSubModelPart("Contact_slave").Nodes]
    reference = hertz.load_reference(folder)
    component = mc.GetVariable("REACTION_" + "XYZ"[reference["dimension"] - 1])
    force = sum(n.GetSolutionStepValue(component) for n in root.GetSubModelPart("DISPLACEMENT_bottom").Nodes)
    record = {"status": "ok", "reactions": {"DISPLACEMENT_bottom": force}, "slave": slave,
              "process_info": {"SCALE_FACTOR": root.ProcessInfo.GetValue(mc.GetVariable("SCALE_FACTOR"))}}
    return hertz.evaluate(record, reference), _iterations(analysis)


def _hertz_alm_and_mpc(family: str, label: str, tmp_path, monkeypatch):
    """(evaluation, iterations) of the generated Hertz case with ALM, then with MPC contact."""
    pytest.importorskip("gmsh")
    from mortarcontact.cases import hertz

    results = []
    for mpc in (False, True):
        folder = hertz.write_case(family, label, str(tmp_path), linear_solver="umfpack", mpc=mpc)
        monkeypatch.chdir(folder)
        results.append(_hertz_run(folder))
    return results


def test_hertz_cylinder_mpc_against_alm(tmp_path, monkeypatch):
    """The 2D Hertz cylinder (hertz2d_2k: 35 slave nodes, 15 in contact) with MPC contact: the same
    force, peak pressure and contact half-width as ALM to 0.1 %, both within 2 % of Hertz, in the same
    Newton iterations (Kratos 10.4's MPC does not converge on these files:
    benchmarks/hertz/results_mpc.md)."""
    (alm, alm_iterations), (ours, iterations) = _hertz_alm_and_mpc("hertz2d", "2k", tmp_path, monkeypatch)
    print(f"Hertz 2D MPC: peak {ours['peak_pressure']:.4g} ({ours['peak_pressure_error']:+.2%} to Hertz), half-width "
          f"{ours['half_width_fit']:.4g} ({ours['half_width_fit_error']:+.2%}), iterations {iterations}; ALM: peak "
          f"{alm['peak_pressure']:.4g}, half-width {alm['half_width_fit']:.4g}, iterations {alm_iterations}")
    for key in ("force", "peak_pressure", "half_width_fit", "half_width_edge"):
        assert ours[key] == pytest.approx(alm[key], rel=1e-3), key
    assert abs(ours["peak_pressure_error"]) < 0.02 and abs(ours["half_width_fit_error"]) < 0.02
    # The pressure integrated over the interface is the support's force.
    assert ours["force_from_pressure"] == pytest.approx(ours["force"], rel=0.02)
    assert iterations == alm_iterations


def test_hertz_sphere_mpc_against_alm(tmp_path, monkeypatch):
    """The 3D Hertz sphere (hertz3d_15k, quarter model, tetrahedra): MPC gives ALM's force, peak pressure
    and contact radius to 0.1 % (the nodal peak is +7.6 % to Hertz in both: the scatter of unstructured
    tetrahedra, mortarcontact.cases.hertz). At the third step an edge node is released by its pull and
    re-activated by its penetration in turn: the cycle guard holds the union of the cycle's sets, and the
    step converges in one iteration more than ALM's (30 without the guard, not converged)."""
    (alm, alm_iterations), (ours, iterations) = _hertz_alm_and_mpc("hertz3d", "15k", tmp_path, monkeypatch)
    print(f"Hertz 3D MPC: peak {ours['peak_pressure']:.4g}, p0 fit {ours['p0_fit_error']:+.2%} to Hertz, radius "
          f"{ours['half_width_fit_error']:+.2%}, iterations {iterations}; ALM: peak {alm['peak_pressure']:.4g}, "
          f"iterations {alm_iterations}")
    for key in ("force", "peak_pressure", "p0_fit", "half_width_fit"):
        assert ours[key] == pytest.approx(alm[key], rel=1e-3), key
    assert abs(ours["p0_fit_error"]) < 0.03 and abs(ours["half_width_fit_error"]) < 0.01
    assert _at_most_one_more(iterations, alm_iterations)


def _write_chain(folder) -> str:
    """Blocks B and C (1 x 1) pressed down onto the two halves of a base A (2 x 1, clamped at its
    bottom) by their tops (B 0.01, C 0.02, x held): interface 0 has B's bottom as slave on A's left
    half, interface 1 A's right half as slave under C (shifted by 0.1). A's top node at x = 1 is a
    master of interface 0 and a slave of interface 1 in the same component, u_y."""
    blocks = {"A": ((0.0, 0.0), (2.0, 1.0), (4, 2)), "B": ((0.0, 1.0), (1.0, 1.0), (2, 2)),
              "C": ((1.1, 1.0), (1.0, 1.0), (2, 2))}
    coords, cells, parts = [], [], {}
    for name, ((x0, y0), (lx, ly), (nx, ny)) in blocks.items():
        xy, connectivity = structured_quads(nx, ny, lx, ly)
        xy += np.array([x0, y0])
        ids = np.arange(len(coords) + 1, len(coords) + len(xy) + 1)
        first = len(cells) + 1
        cells += [tuple(int(i) + len(coords) for i in c) for c in connectivity]
        top, bottom = np.abs(xy[:, 1] - y0 - ly) < 1e-12, np.abs(xy[:, 1] - y0) < 1e-12
        parts.update({f"Parts_{name}": {"nodes": ids, "elements": range(first, len(cells) + 1)},
                      f"{name}_bottom": {"nodes": ids[bottom]}, f"{name}_top": {"nodes": ids[top]}})
        if name == "A":
            parts["A_top_left"] = {"nodes": ids[top & (xy[:, 0] <= 1.0 + 1e-12)]}
            parts["A_top_right"] = {"nodes": ids[top & (xy[:, 0] >= 1.0 - 1e-12)]}
        coords += list(xy)
    write_mdpa(os.path.join(folder, "chain.mdpa"), coords, {"SmallDisplacementElement2D4N": cells}, sub_parts=parts)
    params = project_parameters("chain", 2, constraints=[
        fix_process("Structure.A_bottom", [0.0, 0.0, 0.0]), fix_process("Structure.B_top", [0.0, -0.01, 0.0]),
        fix_process("Structure.C_top", [0.0, -0.02, 0.0])],
        solver={"mpc_contact_settings": {"contact_type": "Frictionless"}, "compute_reactions": True})
    params["processes"]["contact_process_list"] = [{
        "python_module": "mpc_contact_process",
        "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
        "Parameters": {"model_part_name": "Structure",
                       "contact_model_part": {"0": ["B_bottom", "A_top_left"], "1": ["A_top_right", "C_bottom"]},
                       "assume_master_slave": {"0": ["B_bottom"], "1": ["A_top_right"]}}}]
    variables = {"YOUNG_MODULUS": 1e6, "POISSON_RATIO": 0.3, "THICKNESS": 1.0}
    return write_case(folder, "chain", params, {"properties": [
        {"model_part_name": f"Structure.Parts_{name}", "properties_id": k + 1,
         "Material": {"constitutive_law": {"name": "LinearElasticPlaneStrain2DLaw"}, "Variables": variables,
                      "Tables": {}}} for k, name in enumerate("ABC")]})


def test_node_on_two_interfaces(tmp_path):
    """A node that is a master of one interface and a slave of the other (MPCContactConstraints::
    TiedRelations substitutes its tie; before, the builder stopped at 'chained constraints'): both
    interfaces close, every slave node is active, and the base carries both blocks' forces."""
    analysis = run_analysis(tmp_path, _write_chain(tmp_path))
    assert _iterations(analysis) == [2]
    root = analysis.model["Structure"]
    left, right = ({n.Id for n in root.GetSubModelPart(part).Nodes} for part in ("A_top_left", "A_top_right"))
    assert len(left & right) == 1
    reaction = mc.GetVariable("REACTION_Y")
    force = {part: sum(n.GetSolutionStepValue(reaction) for n in root.GetSubModelPart(part).Nodes)
             for part in ("A_bottom", "B_top", "C_top")}
    assert force["B_top"] < 0.0 and force["C_top"] < 0.0
    assert force["A_bottom"] == pytest.approx(-(force["B_top"] + force["C_top"]), rel=1e-9)
    displacement = mc.GetVariable("DISPLACEMENT")

    def surface(part):
        nodes = root.GetSubModelPart(part).Nodes
        return np.array(sorted((n.X0 + n.GetSolutionStepValue(displacement)[0],
                                n.Y0 + n.GetSolutionStepValue(displacement)[1]) for n in nodes))

    # Each slave node on its master surface to 0.5 % of the indentation (measured 2.4e-6 under B,
    # 3.7e-5 under C): the ties hold the gaps weighted over non-matching faces that slide as the
    # blocks spread, not node by node.
    for slave, master in (("B_bottom", "A_top"), ("A_top_right", "C_bottom")):
        nodes, surface_points = surface(slave), surface(master)
        inside = (nodes[:, 0] >= surface_points[0, 0]) & (nodes[:, 0] <= surface_points[-1, 0])
        gaps = nodes[inside, 1] - np.interp(nodes[inside, 0], surface_points[:, 0], surface_points[:, 1])
        print(f"{slave} on {master}: largest gap {np.abs(gaps).max():.1e}")
        assert np.abs(gaps).max() < 1e-4
    assert all(n.Is(mc.ACTIVE) for part in ("B_bottom", "A_top_right") for n in root.GetSubModelPart(part).Nodes)

