#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 12: the direction of the tangential multipliers on the friction block
(ALM_frictional_contact_test_3D/friction_block_test), in both codes. Coulomb's law wants k lambda_t
of a slipping node along its weighted slip s (s = -D a for a slave sliding by a, so that
k lambda_t along s opposes the sliding); the slip equation k lambda_t = b lbar_t / |lbar_t|,
lbar_t = k lambda_t + c s, also has the root k lambda_t = -b s / |s| where c |s| < b (README.md).

For mortarcontact, with the given slip_augmentation_coefficient and slip_threshold: the Newton
iterations of every step, or the step that failed, and at the end time, per slave node, the angle
between k lambda_t and s and |k lambda_t| / b (b = mu |lbar_n|). For Kratos 10.4 (--kratos, the
migrated files, kratos_case_runner.py): its iterations and the largest |lambda_t| / |lambda_n|
of its slave nodes (mu = 0.1 at the Coulomb limit).

    python benchmarks/robustness/slip_direction.py [--end-time 0.005] [--slip-augmentation C]
        [--slip-threshold T] [--nodes] [--kratos]
Environment: MORTARCONTACT_KRATOS_VENV (as for benchmarks/hertz) with --kratos.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "benchmarks", "hertz"))
sys.path.insert(0, os.path.join(ROOT, "benchmarks", "kratos_cases"))
sys.path.insert(0, os.path.join(ROOT, "tests", "python"))

from csma_cases import CSMA_CASES  # noqa: E402

CASE = "ALM_frictional_contact_test_3D/friction_block_test"
FRICTION = 0.1  # the case's FRICTION_COEFFICIENT
VARIABLES = ["VECTOR_LAGRANGE_MULTIPLIER", "WEIGHTED_SLIP", "NORMAL"]


def run_ours(end_time: float, slip_augmentation: float | None, slip_threshold: float | None) -> dict:
    """Iterations per step, the error of a failed step, and (id, SLIP, angle in degrees,
    |k lambda_t| / b) of every slave node at the last converged step."""
    import mortarcontact as mc
    from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
    from mortarcontact.project_parameters import read_project_parameters

    params = read_project_parameters(os.path.join(CSMA_CASES, f"{CASE}_parameters.json"))
    params["problem_data"]["end_time"].SetDouble(end_time)
    params["processes"].RemoveValue("json_check_process")
    contact = params["processes"]["contact_process_list"][0]["Parameters"]
    for key, value in (("slip_augmentation_coefficient", slip_augmentation), ("slip_threshold", slip_threshold)):
        if value is not None:
            contact.AddEmptyValue(key)
            contact[key].SetDouble(value)
    cwd = os.getcwd()
    os.chdir(CSMA_CASES)
    analysis = StructuralMechanicsAnalysis(mc.Model(), params, progress=False)
    error = None
    try:
        analysis.Run()
    except Exception as e:  # a failed step is a result here
        error = f"{type(e).__name__}: {str(e).splitlines()[0]}"
    finally:
        os.chdir(cwd)
    part = analysis.model["Structure"]
    k = part.ProcessInfo.GetValue(mc.GetVariable("SCALE_FACTOR"))
    nodes = []
    for node in part.Nodes:
        if not node.Is(mc.SLAVE) or not node.Is(mc.ACTIVE):
            continue
        lm, slip, normal = (np.array(node.GetSolutionStepValue(mc.GetVariable(name))) for name in VARIABLES)
        traction = k * (lm - normal.dot(lm) * normal)
        bound = FRICTION * abs(node.GetValue(mc.GetVariable("AUGMENTED_NORMAL_CONTACT_PRESSURE")))
        nodes.append((node.Id, node.Is(mc.SLIP), angle(traction, slip), np.linalg.norm(traction) / bound))
    return {"iterations": [it for _, _, it, _, _ in analysis.step_log], "error": error, "nodes": nodes}


def angle(a: np.ndarray, b: np.ndarray) -> float:
    norms = np.linalg.norm(a) * np.linalg.norm(b)
    return math.degrees(math.acos(max(-1.0, min(1.0, a.dot(b) / norms)))) if norms > 0.0 else float("nan")


def run_kratos(end_time: float, slave_ids: list[int]) -> dict:
    """Kratos 10.4's iterations and its largest |lambda_t| / |lambda_n| over `slave_ids` at the end time."""
    import harness
    from kratos_migration import migrated_case

    runner = os.path.join(ROOT, "benchmarks", "kratos_cases", "kratos_case_runner.py")
    with tempfile.TemporaryDirectory() as folder:
        migrated = migrated_case(os.path.join(CSMA_CASES, f"{CASE}_parameters.json"), folder)
        with open(migrated) as f:
            params = json.load(f)
        params["problem_data"]["end_time"] = end_time
        with open(migrated, "w") as f:
            json.dump(params, f, indent=1)
        request = os.path.join(folder, "request.json")
        with open(request, "w") as f:
            json.dump({"time": end_time, "nodes": {f"NODE_{i}": VARIABLES for i in slave_ids}}, f)
        out = os.path.join(folder, "kratos.json")
        subprocess.run([harness.kratos_python(), runner, migrated, request, "frictional", out], check=True,
                       capture_output=True, env={**os.environ, "OMP_NUM_THREADS": "1"})
        with open(out) as f:
            result = json.load(f)
    ratio = 0.0
    for values in result["nodes"].values():
        lm, normal = np.array(values["VECTOR_LAGRANGE_MULTIPLIER"]), np.array(values["NORMAL"])
        ratio = max(ratio, np.linalg.norm(lm - normal.dot(lm) * normal) / abs(normal.dot(lm)))
    return {"iterations": result["newton_iterations"], "error": result.get("error"), "ratio": ratio}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--end-time", type=float, default=0.005)
    parser.add_argument("--slip-augmentation", type=float, help="slip_augmentation_coefficient (default: the case's)")
    parser.add_argument("--slip-threshold", type=float, help="slip_threshold (default: the case's)")
    parser.add_argument("--nodes", action="store_true", help="print every active slave node")
    parser.add_argument("--kratos", action="store_true", help="run Kratos 10.4 beside")
    args = parser.parse_args(argv)
    ours = run_ours(args.end_time, args.slip_augmentation, args.slip_threshold)
    its = ours["iterations"]
    print(f"mortarcontact: {sum(its)} iterations over {len(its)} steps {its}" +
          (f"; {ours['error']}" if ours["error"] else ""))
    if args.nodes:
        for node_id, slip, degrees, ratio in ours["nodes"]:
            state = "slip " if slip else "stick"
            print(f"  node {node_id}: {state} angle {degrees:6.1f} deg, |k lambda_t| / b {ratio:.4f}")
    sliding = [degrees for _, slip, degrees, _ in ours["nodes"] if slip]
    if sliding:
        print(f"  largest angle between k lambda_t and s over {len(sliding)} slipping nodes: {max(sliding):.1f} deg")
    if args.kratos:
        kratos = run_kratos(args.end_time, [node_id for node_id, *_ in ours["nodes"]])
        print(f"Kratos 10.4: {sum(kratos['iterations'])} iterations {kratos['iterations']}" +
              (f"; {kratos['error']}" if kratos["error"] else "") +
              f"; largest |lambda_t| / |lambda_n| {kratos['ratio']:.1e} (Coulomb limit {FRICTION})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
