#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 3: runs the frictionless shared Kratos CSMA cases with Kratos 10.4 and stores the values
their reference files check, at the reference's last check time, in tests/cases/kratos_10_4/.

Why: several shared reference files were written by older Kratos revisions and Kratos 10.4 itself
no longer reproduces them (hyper_simple_slope_patch_test: 9e-4; the tri-on-quad patch: 1e-2;
taylor_patch_dynamic_test: up to 60 % on small values). A snapshot of the current reference code
on the same files is the second, reproducible yardstick of tests/python/test_contact_cases.py.

Each case runs twice, as Kratos' suite does: scalar multiplier (as written) and components
(mortar_type ALMContactFrictionlessComponents, contact_type FrictionlessComponents). The legacy
layouts of the shared files are migrated with mortarcontact's own reader (Kratos 10.4 rejects
them) and model part names are made absolute; nothing else changes, except that the skyline
solver, absent from the wheels, is replaced by sparse_lu (both are direct).

    python benchmarks/kratos_cases/snapshot_kratos.py [--cases NAME,...]
Environment: MORTARCONTACT_KRATOS_VENV (as for benchmarks/hertz).
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "benchmarks", "hertz"))
sys.path.insert(0, os.path.join(ROOT, "tests", "python"))

import harness  # noqa: E402
from csma_cases import FRICTIONLESS_CASES, CSMA_CASES, reference_values  # noqa: E402

OUTPUT = os.path.join(ROOT, "tests", "cases", "kratos_10_4")
RUNNER = os.path.join(HERE, "kratos_case_runner.py")
#: HyperElastic3DLaw lives in this application since Kratos 9
EXTRA_PACKAGES = ["KratosConstitutiveLawsApplication"]


def migrated_case(case: str, folder: str) -> str:
    """Writes a Kratos-10.4-readable copy of the case's parameters and materials into `folder`."""
    from mortarcontact.project_parameters import read_project_parameters

    cwd = os.getcwd()
    os.chdir(CSMA_CASES)
    try:
        params = json.loads(read_project_parameters(f"{case}_parameters.json").WriteJsonString())
        root = params["solver_settings"]["model_part_name"]
        imports = params["solver_settings"]
        with open(imports["material_import_settings"]["materials_filename"]) as f:
            materials = json.load(f)
        imports["model_import_settings"]["input_filename"] = os.path.abspath(
            imports["model_import_settings"]["input_filename"])
    finally:
        os.chdir(cwd)

    def absolute(name: str) -> str:
        return name if name == root or name.startswith(root + ".") else f"{root}.{name}"

    for block in materials["properties"]:
        block["model_part_name"] = absolute(block["model_part_name"])
    stem = os.path.join(folder, os.path.basename(case))
    with open(stem + "_materials.json", "w") as f:
        json.dump(materials, f, indent=1)
    imports["material_import_settings"]["materials_filename"] = stem + "_materials.json"

    def fix(node):
        if isinstance(node, dict):
            node.pop("mesh_id", None)  # accepted by mortarcontact, rejected by Kratos 10.4
            for key, value in node.items():
                if key == "model_part_name" and isinstance(value, str):
                    node[key] = absolute(value)
                else:
                    fix(value)
            if node.get("python_module") == "assign_vector_by_direction_to_condition_process":
                node["kratos_module"] = "KratosMultiphysics"  # moved to the core since the files were written
        elif isinstance(node, list):
            for value in node:
                fix(value)

    fix(params["processes"])
    params["processes"].pop("json_check_process", None)
    solver = params["solver_settings"]["linear_solver_settings"]
    if "skyline" in solver.get("solver_type", "").lower():
        solver["solver_type"] = "LinearSolversApplication.sparse_lu"
    with open(stem + "_parameters.json", "w") as f:
        json.dump(params, f, indent=1)
    return stem + "_parameters.json"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", default="all", help="comma-separated case paths (folder/case) or 'all'")
    args = parser.parse_args(argv)
    python = harness.kratos_python()
    subprocess.run([python, "-m", "pip", "install", "-q", "--disable-pip-version-check"]
                   + [f"{p}=={harness.KRATOS_VERSION}" for p in EXTRA_PACKAGES], check=True)
    cases = [c for c, _ in FRICTIONLESS_CASES] if args.cases == "all" else args.cases.split(",")
    os.makedirs(OUTPUT, exist_ok=True)
    with tempfile.TemporaryDirectory() as folder:
        for case in cases:
            formulations = dict(FRICTIONLESS_CASES).get(case, ("scalar", "components"))
            time, nodes = reference_values(case)
            request = os.path.join(folder, "request.json")
            with open(request, "w") as f:
                json.dump({"time": time, "nodes": nodes}, f)
            parameters = migrated_case(case, folder)
            for formulation in formulations:
                out = os.path.join(OUTPUT, f"{os.path.basename(case)}_{formulation}.json")
                subprocess.run([python, RUNNER, parameters, request, formulation, out], check=True,
                               env={**os.environ, "OMP_NUM_THREADS": "1"})
                print(f"{case} ({formulation}) -> {os.path.relpath(out, ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
