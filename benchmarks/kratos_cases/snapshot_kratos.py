#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issues 3 and 12: runs the shared Kratos CSMA cases with Kratos 10.4 and stores the values their
reference files check, at the reference's last check time, in tests/cases/kratos_10_4/.

Why: several shared reference files were written by older Kratos revisions and Kratos 10.4 itself
no longer reproduces them (hyper_simple_slope_patch_test: 9e-4; the tri-on-quad patch: 1e-2;
taylor_patch_dynamic_test: up to 60 % on small values). A snapshot of the current reference code
on the same files is the second, reproducible yardstick of tests/python/test_contact_cases.py.

Each frictionless case runs twice, as Kratos' suite does: scalar multiplier (as written) and
components (mortar_type ALMContactFrictionlessComponents, contact_type FrictionlessComponents).
The frictional, mesh-tying and MPC cases run once, as written (<case>_frictional.json, _tying, _mpc). The legacy
layouts of the shared files are migrated with mortarcontact's own reader (Kratos 10.4 rejects
them) and model part names are made absolute; nothing else changes, except that the skyline
solver, absent from the wheels, is replaced by sparse_lu (both are direct): see kratos_migration.py.

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
from csma_cases import FRICTIONAL_CASES, FRICTIONLESS_CASES, MESH_TYING_CASES, MPC_CASES, reference_values  # noqa: E402
from kratos_migration import CSMA_CASES, migrated_case  # noqa: E402

OUTPUT = os.path.join(ROOT, "tests", "cases", "kratos_10_4")
RUNNER = os.path.join(HERE, "kratos_case_runner.py")
#: formulations run as the case is written (no switch of the contact processes)
AS_WRITTEN = ("frictional", "tying", "mpc")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", default="all", help="comma-separated case paths (folder/case) or 'all'")
    args = parser.parse_args(argv)
    python = harness.kratos_python()
    known = dict(FRICTIONLESS_CASES + FRICTIONAL_CASES + MESH_TYING_CASES + MPC_CASES)
    cases = list(known) if args.cases == "all" else args.cases.split(",")
    os.makedirs(OUTPUT, exist_ok=True)
    with tempfile.TemporaryDirectory() as folder:
        for case in cases:
            formulations = known.get(case, ("scalar", "components"))
            time, nodes = reference_values(case)
            request = os.path.join(folder, "request.json")
            with open(request, "w") as f:
                json.dump({"time": time, "nodes": nodes}, f)
            for formulation in formulations:
                parameters = migrated_case(os.path.join(CSMA_CASES, f"{case}_parameters.json"), folder,
                                           None if formulation in AS_WRITTEN else formulation)
                out = os.path.join(OUTPUT, f"{os.path.basename(case)}_{formulation}.json")
                subprocess.run([python, RUNNER, parameters, request, formulation, out], check=True,
                               env={**os.environ, "OMP_NUM_THREADS": "1"})
                with open(out) as f:
                    error = json.load(f).get("error")
                if error:  # a failed run is no yardstick (the friction block: KRATOS_FAILS of the tests)
                    os.remove(out)
                    print(f"{case} ({formulation}): Kratos 10.4 failed: {error}")
                    continue
                print(f"{case} ({formulation}) -> {os.path.relpath(out, ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
