"""Issue 10, item 4: after a converged step every contact variable holds what Kratos 10.4 holds
there, or the quantity we compute where Kratos leaves a stale or meaningless value, and a
requested output variable that nothing computes is reported.

The Kratos values (tests/cases/kratos_10_4/contact_outputs) were written by
benchmarks/kratos_cases/snapshot_contact_outputs.py from the same case files; each records the
last step "finalized" (what json_output_process reads) and at "output" (what vtk_output writes).
Kratos is not needed here."""
from __future__ import annotations

import json
import os

import numpy as np
import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
from mortarcontact.project_parameters import read_project_parameters

from csma_cases import CSMA_CASES, KRATOS_SNAPSHOTS, use_components, use_penalty

SNAPSHOTS = os.path.join(KRATOS_SNAPSHOTS, "contact_outputs")
PATCH_2D = "ALM_frictionless_contact_test_2D/hyper_simple_patch_test"
#: stored record -> relative tolerance of the tractions and multipliers, and of the normals. The
#: tri-on-quad patch agrees to 0.9 % only: Kratos' nodal normals of its master quads lean by up
#: to 0.07 where ours stay within 0.002 of the face normal.
RECORDS = {"patch_2d_scalar": (1e-8, 1e-9), "patch_2d_components": (1e-8, 1e-9), "patch_2d_penalty": (1e-7, 1e-9),
           "patch_3d_penalty": (1e-3, 1e-9), "triquad_3d_scalar": (2e-2, 0.1), "triquad_3d_components": (2e-2, 0.1)}


def run_case(case: str, formulation: str, change=None) -> StructuralMechanicsAnalysis:
    """Runs a shared case in `formulation` (its own reference checks removed) and returns the
    finished analysis; `change(params)` may edit the parameters first."""
    params = read_project_parameters(f"{case}_parameters.json")
    if params["processes"].Has("json_check_process"):
        params["processes"].RemoveValue("json_check_process")
    {"scalar": lambda p: None, "components": use_components, "penalty": use_penalty}[formulation](params)
    if change:
        change(params)
    analysis = StructuralMechanicsAnalysis(mc.Model(), params, progress=False)
    analysis.Run()
    assert all(converged for _, _, _, converged, _ in analysis.step_log)
    return analysis


def value(node, name: str, historical: bool):
    """What an output process writes: a value that a node does not hold is written as zeros."""
    variable = mc.GetVariable(name)
    if historical:
        return np.asarray(node.GetSolutionStepValue(variable), dtype=float)
    return np.asarray(node.GetValue(variable), dtype=float) if node.Has(variable) else np.zeros(
        3 if variable.Type() == mc.ValueType.Array3 else ())


@pytest.fixture(scope="module", params=sorted(RECORDS))
def compared(request):
    """(Kratos' record, our finished root model part, tolerances) of one stored case."""
    with open(os.path.join(SNAPSHOTS, f"{request.param}.json")) as f:
        kratos = json.load(f)
    cwd = os.getcwd()
    os.chdir(CSMA_CASES)
    try:
        analysis = run_case(kratos["case"], kratos["formulation"])
    finally:
        os.chdir(cwd)
    part = analysis.solver.GetComputingModelPart().GetRootModelPart()
    assert part.ProcessInfo.GetValue(mc.TIME) == pytest.approx(kratos["time"])
    return kratos, part, RECORDS[request.param]


def interface_nodes(kratos: dict, stage: str = "finalized"):
    """(id, Kratos' entry) of the interface nodes (Kratos also flags SLAVE the other nodes of the
    slave body named in assume_master_slave; we flag the interface only)."""
    return [(int(i), node) for i, node in kratos[stage]["nodes"].items() if node["flags"]["INTERFACE"]]


def scales(kratos: dict) -> dict:
    """The sizes that tell a difference from round-off: the largest traction, mortar area, nodal
    length; forces are traction x area."""
    nodes = [node for _, node in interface_nodes(kratos, "output")]
    pressure = max(abs(n["non_historical"].get("AUGMENTED_NORMAL_CONTACT_PRESSURE", 0.0)) for n in nodes)
    area = max(n["non_historical"].get("NODAL_AREA", 0.0) for n in nodes)
    length = max(n["historical"]["NODAL_H"] for n in nodes)
    return {"pressure": pressure, "area": area, "length": length, "force": pressure * area}


def test_flags_match_kratos(compared):
    kratos, part, _ = compared
    for i, node in interface_nodes(kratos):
        for flag in ("ACTIVE", "SLAVE", "MASTER", "ISOLATED"):
            assert part.GetNode(i).Is(mc.GetFlag(flag)) == node["flags"][flag], f"node {i} {flag}"


def test_process_info_matches_kratos(compared):
    kratos, part, _ = compared
    info = kratos["finalized"]["process_info"]
    assert part.ProcessInfo.GetValue(mc.INITIAL_PENALTY) == pytest.approx(info["INITIAL_PENALTY"], rel=1e-9)
    if kratos["formulation"] != "penalty":  # unused there; Kratos leaves 0 on the 3D case, the ALM value on 2D
        assert part.ProcessInfo.GetValue(mc.SCALE_FACTOR) == pytest.approx(info["SCALE_FACTOR"], rel=1e-9)


def test_tractions_and_multipliers_match_kratos(compared):
    """Multipliers (scaled units) and the augmented pressure as the output processes see it:
    Kratos' value at "output" (its inactive nodes cleared) is ours from the end of the step on;
    NORMAL_CONTACT_STRESS / CONTACT_PRESSURE (absent in Kratos) are that pressure in physical units
    on the ALM formulations (penalty: the applied traction, see test_contact_pressure_output.py)."""
    kratos, part, (rtol, _) = compared
    scale = scales(kratos)
    k = part.ProcessInfo.GetValue(mc.SCALE_FACTOR)
    checked = 0
    for i, node in interface_nodes(kratos, "output"):
        ours = part.GetNode(i)
        for name in ("LAGRANGE_MULTIPLIER_CONTACT_PRESSURE", "VECTOR_LAGRANGE_MULTIPLIER"):
            if name in node["historical"]:
                # relative to the vector's size: its tangential components follow the normals
                expected = np.asarray(node["historical"][name])
                size = rtol * np.max(np.abs(expected)) + 1e-9 * scale["pressure"] / k
                assert value(ours, name, True) == pytest.approx(expected, abs=size), f"node {i} {name}"
        expected = node["non_historical"].get("AUGMENTED_NORMAL_CONTACT_PRESSURE", 0.0)
        augmented = value(ours, "AUGMENTED_NORMAL_CONTACT_PRESSURE", False)
        assert augmented == pytest.approx(expected, rel=rtol, abs=1e-9 * scale["pressure"]), f"node {i}"
        if node["flags"]["SLAVE"]:
            if kratos["formulation"] != "penalty":
                assert value(ours, "NORMAL_CONTACT_STRESS", False) == pytest.approx(expected, rel=rtol,
                                                                                    abs=1e-9 * scale["pressure"])
            assert value(ours, "CONTACT_PRESSURE", False) == -value(ours, "NORMAL_CONTACT_STRESS", False)
            assert value(ours, "TANGENTIAL_CONTACT_STRESS", False) == 0.0
            checked += 1
    assert checked >= 2


def test_mortar_quantities_match_kratos(compared):
    """NORMAL, WEIGHTED_GAP and the nodal penalty as Kratos; NODAL_AREA as Kratos up to the
    configuration (Kratos measures it when its search runs, at the start of the step: 0.3 % on
    the 2D patch, 3 % on the tri-on-quad patch; ours is of the converged configuration). Kratos'
    penalty formulation adds to NODAL_AREA at every iteration (2.503 = 5 x 0.5006 on the 2D
    patch): not compared there, the force balance below checks ours."""
    kratos, part, (_, normal_tolerance) = compared
    scale = scales(kratos)
    penalty = kratos["formulation"] == "penalty"
    for i, node in interface_nodes(kratos):
        ours = part.GetNode(i)
        assert value(ours, "NORMAL", True) == pytest.approx(np.asarray(node["historical"]["NORMAL"]),
                                                             abs=normal_tolerance), f"node {i}"
        if not node["flags"]["SLAVE"]:
            continue
        gap_tolerance = 1e-6 * scale["area"] * scale["length"]
        if penalty:  # the gap is the penalty's penetration, not round-off
            gap_tolerance = 1e-3 * abs(node["historical"]["WEIGHTED_GAP"])
        assert value(ours, "WEIGHTED_GAP", True) == pytest.approx(node["historical"]["WEIGHTED_GAP"],
                                                                  abs=gap_tolerance), f"node {i}"
        assert value(ours, "INITIAL_PENALTY", False) == pytest.approx(node["non_historical"]["INITIAL_PENALTY"],
                                                                      rel=1e-9)
        if node["flags"]["ACTIVE"] and not penalty:
            assert value(ours, "NODAL_AREA", False) == pytest.approx(node["non_historical"]["NODAL_AREA"], rel=0.05)


def test_residuals_and_reactions_match_kratos(compared):
    """At the free interface DoFs both codes hold the converged residual: round-off next to the
    contact forces (REACTION) and to k x mortar area x nodal length (the multiplier rows)."""
    kratos, part, _ = compared
    scale = scales(kratos)
    k = part.ProcessInfo.GetValue(mc.SCALE_FACTOR)
    tolerances = {"REACTION": 1e-3 * scale["force"],
                  "WEIGHTED_SCALAR_RESIDUAL": 1e-3 * k * scale["area"] * scale["length"],
                  "WEIGHTED_VECTOR_RESIDUAL": 1e-3 * k * scale["area"] * scale["length"]}
    for i, node in interface_nodes(kratos):
        for name, tolerance in tolerances.items():
            if name in node["historical"]:
                assert value(part.GetNode(i), name, True) == pytest.approx(np.asarray(node["historical"][name]),
                                                                           abs=tolerance), f"node {i} {name}"


def test_gap_and_force_are_of_the_converged_state(compared):
    """NORMAL_GAP is the mortar mean gap at the end of the step (Kratos keeps the gap its search
    measured before the step: 0.001 on the closed 2D patch); CONTACT_FORCE is traction x area x
    normal."""
    kratos, part, _ = compared
    for i, node in interface_nodes(kratos):
        if not node["flags"]["SLAVE"]:
            continue
        ours = part.GetNode(i)
        area = value(ours, "NODAL_AREA", False)
        assert value(ours, "NORMAL_GAP", False) == pytest.approx(value(ours, "WEIGHTED_GAP", True) / area)
        force = value(ours, "NORMAL_CONTACT_STRESS", False) * area * value(ours, "NORMAL", True)
        assert value(ours, "CONTACT_FORCE", False) == pytest.approx(force)


def test_contact_force_balances_the_supports(monkeypatch):
    """2D patch: the slave block (nodes 1-4) is held at nodes 1, 2 and pushed at 3, 4 by the
    master; its support reactions and the contact forces on it sum to zero."""
    monkeypatch.chdir(CSMA_CASES)

    def with_reactions(params):
        params["solver_settings"]["compute_reactions"].SetBool(True)

    for formulation in ("scalar", "components", "penalty"):
        part = run_case(PATCH_2D, formulation, with_reactions).solver.GetComputingModelPart().GetRootModelPart()
        reaction = sum(value(part.GetNode(i), "REACTION", True) for i in (1, 2))
        contact = sum(value(part.GetNode(i), "CONTACT_FORCE", False) for i in (3, 4))
        assert np.linalg.norm(contact) > 1e8
        # to the Newton tolerance of the case (1e-4; the penalty formulation ends at 1.4e-5)
        assert reaction + contact == pytest.approx(np.zeros(3), abs=1e-4 * np.linalg.norm(contact)), formulation
        pressure = [value(part.GetNode(i), "CONTACT_PRESSURE", False) for i in (3, 4)]
        assert min(pressure) > 0.0  # positive in compression
        assert value(part.GetNode(3), "NORMAL_GAP", False) == pytest.approx(
            0.0, abs=2e-3 if formulation == "penalty" else 1e-9)


def test_open_slave_nodes_hold_no_pressure(monkeypatch):
    """2D patch pushed by 0.0004 only (gap 0.001): the slave nodes stay open; their augmented
    pressure eps x weighted gap (about 4e7 here) is not a pressure and reads 0 after the step,
    as do the contact stresses; the gap reads 0.0006."""
    monkeypatch.chdir(CSMA_CASES)

    def push_less(params):
        constraints = params["processes"]["constraints_process_list"]
        constraints[2]["Parameters"]["value"][1].SetDouble(-0.0004)

    for formulation in ("scalar", "components", "penalty"):
        part = run_case(PATCH_2D, formulation, push_less).solver.GetComputingModelPart().GetRootModelPart()
        for i in (3, 4):
            node = part.GetNode(i)
            assert node.Is(mc.SLAVE) and not node.Is(mc.ACTIVE)
            assert value(node, "WEIGHTED_GAP", True) > 1e-4
            for name in ("AUGMENTED_NORMAL_CONTACT_PRESSURE", "NORMAL_CONTACT_STRESS", "CONTACT_PRESSURE"):
                assert value(node, name, False) == 0.0, f"{formulation} node {i} {name}"
            assert value(node, "CONTACT_FORCE", False) == pytest.approx(np.zeros(3))
            assert value(node, "NORMAL_GAP", False) == pytest.approx(0.0006, rel=1e-3)


def test_unset_output_variable_is_reported(monkeypatch, tmp_path, capsys):
    """A requested variable that nothing in the run computes (NODAL_PAUX) is named in a warning
    by each process that writes or checks it; the computed contact variables raise none."""
    monkeypatch.chdir(CSMA_CASES)
    reference = tmp_path / "reference.json"
    reference.write_text(json.dumps({"TIME": [1.1], **{f"NODE_{i}": {"NODAL_PAUX": [0.0]} for i in (3, 4, 5, 6)}}))

    def add_outputs(params):
        params.AddValue("output_processes", mc.Parameters(json.dumps({"vtk_output": [{
            "python_module": "vtk_output_process", "kratos_module": "KratosMultiphysics",
            "Parameters": {"model_part_name": "Structure.Contact_Part", "output_path": str(tmp_path / "vtk"),
                           "nodal_data_value_variables": ["NODAL_PAUX", "NORMAL_CONTACT_STRESS", "CONTACT_PRESSURE",
                                                          "AUGMENTED_NORMAL_CONTACT_PRESSURE", "NODAL_AREA"]}}]})))
        params["processes"].AddValue("json_check_process", mc.Parameters(json.dumps([{
            "python_module": "from_json_check_result_process", "kratos_module": "KratosMultiphysics",
            "Parameters": {"model_part_name": "Structure.Contact_Part", "input_file_name": str(reference),
                           "check_variables": ["NODAL_PAUX"], "historical_value": False, "time_frequency": 1.0}}])))

    run_case(PATCH_2D, "scalar", add_outputs)
    warnings = [line for line in capsys.readouterr().err.splitlines() if "is not computed" in line]
    assert len(warnings) == 2
    assert any("vtk_output_process" in line and "NODAL_PAUX" in line for line in warnings)
    assert any("from_json_check_result_process" in line and "NODAL_PAUX" in line for line in warnings)


@pytest.mark.parametrize("case, formulation", [
    ("ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_test", "scalar"),
    ("ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_test", "components"),
    ("penalty_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_test", "penalty")])
def test_3d_contact_force_balances_the_supports(monkeypatch, case, formulation):
    """Issue 15, item 4, in 3D: the tractions times the mortar areas (CONTACT_FORCE) sum to the
    support reaction of each block, on every formulation. (The matching meshes put each slave node
    in one pair, where eps g is the penalty traction too; test_contact_pressure_output.py and the
    axisymmetric rings tell the two apart.)"""
    monkeypatch.chdir(CSMA_CASES)
    part = run_case(case, formulation).solver.GetComputingModelPart().GetRootModelPart()  # reactions by default
    contact = sum(value(node, "CONTACT_FORCE", False) for node in part.Nodes if node.Is(mc.SLAVE))
    support = part.GetSubModelPart("DISPLACEMENT_Displacement_Auto1").GetNodalValues(mc.REACTION).sum(axis=0)
    assert abs(contact[2]) > 0.0
    assert abs(contact[2]) == pytest.approx(abs(support[2]), rel=1e-3), (contact, support)
