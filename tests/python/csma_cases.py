"""The Kratos CSMA reference cases (tests/cases/kratos_csma): the frictionless ones and how to run
them in either multiplier formulation, and the frictional ones; used by test_contact_cases.py and
by benchmarks/kratos_cases/snapshot_kratos.py, which stores Kratos 10.4's values for the same runs."""
from __future__ import annotations

import json
import os

CSMA_CASES = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "cases", "kratos_csma"))
KRATOS_SNAPSHOTS = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "cases", "kratos_10_4"))

#: case -> formulations Kratos' suite runs it with (the triangle patch fixes vector multiplier
#: components, so it exists in the components formulation only)
FRICTIONLESS_CASES = [
    ("ALM_frictionless_contact_test_2D/hyper_simple_patch_test", ("scalar", "components")),
    # impose_rigid_movement_process ties u_x of the contact nodes pairwise (issue 18)
    ("ALM_frictionless_contact_test_2D/hyper_simple_patch_test_with_elimination_with_constraints",
     ("scalar", "components")),
    ("ALM_frictionless_contact_test_2D/hyper_simple_slope_patch_test", ("scalar", "components")),
    ("ALM_frictionless_contact_test_2D/hyper_simple_triangle_patch_test", ("components",)),
    ("ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_triquad_test", ("scalar", "components")),
    ("ALM_frictionless_contact_test_2D/taylor_patch_dynamic_test", ("scalar", "components")),
    ("ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_test", ("scalar", "components")),
]

#: The frictional cases, run as written ("frictional": Kratos' suite switches no formulation).
FRICTIONAL_CASES = [
    ("ALM_frictional_contact_test_2D/hyper_simple_patch_test", ("frictional",)),
    ("ALM_frictional_contact_test_2D/threshold_slip_hyper_simple_patch_test", ("frictional",)),
    ("ALM_frictional_contact_test_2D/mesh_moving_matching_test", ("frictional",)),
    ("ALM_frictional_contact_test_3D/friction_block_test", ("frictional",)),
    ("penalty_frictional_contact_test_2D/hyper_simple_stick_patch_test", ("frictional",)),
    ("penalty_frictional_contact_test_2D/hyper_simple_slip_patch_test", ("frictional",)),
]

#: The mesh-tying cases (issue 13), run as written ("tying": ComponentsMeshTying, mesh_tying_process).
MESH_TYING_CASES = [
    ("mesh_tying_test/simple_patch_test_2D", ("tying",)),
    ("mesh_tying_test/hyper_simple_slope_patch_test_2D", ("tying",)),
    ("mesh_tying_test/3D_contact_simplest_patch_matching_test", ("tying",)),
]

#: The MPC contact cases (issue 13), run as written ("mpc": mpc_contact_settings, mpc_contact_process). The
#: 2D one has no reference file; the zero-gap and mesh-tying copies of it are ours (tests/cases/mpc/README.md).
MPC_CASES = [
    ("mpc_contact_tests/3D_contact_simplest_patch_matching_test", ("mpc",)),
    ("mpc_contact_tests/2D_contact_simplest_patch_matching_test", ("mpc",)),
    ("../mpc/2D_zero_gap_patch_test", ("mpc",)),
    ("../mpc/2D_mesh_tying_patch_test", ("mpc",)),
]
_MPC_2D_NODES = {f"NODE_{i}": ["DISPLACEMENT_X", "DISPLACEMENT_Y"] for i in range(3, 9)}
#: (time, nodes) of the Kratos snapshot of a case without a reference file
SNAPSHOT_REQUESTS = {"mpc_contact_tests/2D_contact_simplest_patch_matching_test": (1.0, _MPC_2D_NODES),
                     "../mpc/2D_zero_gap_patch_test": (1.0, _MPC_2D_NODES),
                     "../mpc/2D_mesh_tying_patch_test": (1.0, _MPC_2D_NODES)}

#: Cases whose reference time is never reached with their own time stepping: the reference file
#: (t = 1.1) and the parameters (dt 0.5 up to 0.99) come from different Kratos revisions. The
#: values are taken at the last step instead, for the comparison with Kratos 10.4 only.
SNAPSHOT_TIME = {"ALM_frictionless_contact_test_3D/3D_contact_simplest_patch_matching_test": 1.0}


def use_components(params) -> None:
    """The switch of Kratos' components test classes: vector multiplier for every contact process."""
    params["solver_settings"]["contact_settings"]["mortar_type"].SetString("ALMContactFrictionlessComponents")
    processes = params["processes"]["contact_process_list"]
    for i in range(processes.size()):
        processes[i]["Parameters"]["contact_type"].SetString("FrictionlessComponents")


def use_penalty(params) -> None:
    """Every contact process of the case as penalty_contact_process (frictionless)."""
    params["solver_settings"]["contact_settings"]["mortar_type"].SetString("PenaltyContactFrictionless")
    processes = params["processes"]["contact_process_list"]
    for i in range(processes.size()):
        processes[i]["python_module"].SetString("penalty_contact_process")
        processes[i]["Parameters"]["contact_type"].SetString("Frictionless")


def check_blocks(case: str):
    """(input file, model part, variables, historical) of each json check of the case's parameters."""
    with open(os.path.join(CSMA_CASES, f"{case}_parameters.json")) as f:
        params = json.load(f)
    blocks = []
    for check in params["processes"].get("json_check_process", []):
        settings = check["Parameters"]
        blocks.append((settings["input_file_name"], settings["model_part_name"], settings["check_variables"],
                       settings.get("historical_value", True)))
    return blocks


def reference_values(case: str):
    """(last check time, {"NODE_<id>": [variables]}) over every reference file of the case; the
    time is SNAPSHOT_TIME's when the case has one; SNAPSHOT_REQUESTS' for a case without a file."""
    if case in SNAPSHOT_REQUESTS:
        return SNAPSHOT_REQUESTS[case]
    time, nodes = None, {}
    for input_file, _, variables, _ in check_blocks(case):
        with open(os.path.join(CSMA_CASES, input_file)) as f:
            reference = json.load(f)
        time = reference["TIME"][-1]
        for key in reference:
            if key.startswith("NODE_"):
                nodes.setdefault(key, [])
                nodes[key] += [v for v in variables if v in reference[key] and v not in nodes[key]]
    return SNAPSHOT_TIME.get(case, time), nodes


def reference_nodes(case: str) -> dict:
    """{"NODE_<id>": {variable: value at the last time}} over every reference file of the case."""
    nodes = {}
    for input_file, _, variables, _ in check_blocks(case):
        with open(os.path.join(CSMA_CASES, input_file)) as f:
            values = json.load(f)
        for key, node in values.items():
            if key.startswith("NODE_"):
                nodes.setdefault(key, {}).update({v: node[v][-1] for v in variables if v in node})
    return nodes


def worst_difference(values: dict, expected: dict) -> float:
    """max |value - expected| / max |expected| per variable, over the nodes; the worst variable."""
    worst = 0.0
    for name in {n for node in expected.values() for n in node}:
        pairs = [(values[key][name], node[name]) for key, node in expected.items() if name in node]
        scale = max(abs(e) for _, e in pairs) or 1.0
        worst = max(worst, max(abs(v - e) for v, e in pairs) / scale)
    return worst
