#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 13, explicit contact: the bar impact (mortarcontact.cases.bar_impact, at half the critical
time step) and the shared case explicit_3D_contact_simplest_patch_matching_test, run by
mortarcontact and by Kratos 10.4 on the same files; prints each code's solution-loop time, steps
and cost per step, and what each transmits (the bars' velocities after the impact, the contact
time; the penetration of node 2 into node 5 of the shared case).

    python benchmarks/kratos_cases/explicit_contact.py
Environment: MORTARCONTACT_KRATOS_VENV (as for benchmarks/hertz).
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "benchmarks", "hertz"))

import mortarcontact as mc  # noqa: E402
from mortarcontact.analysis_stage import StructuralMechanicsAnalysis  # noqa: E402
from mortarcontact.cases import bar_impact  # noqa: E402
from mortarcontact.cases.mesh_files import write_kratos_mdpa  # noqa: E402
from mortarcontact.project_parameters import read_project_parameters  # noqa: E402

import harness  # noqa: E402
from case_runner import kratos_parameters  # noqa: E402
from kratos_migration import CSMA_CASES, migrated_case  # noqa: E402

RUNNER = os.path.join(HERE, "explicit_kratos_runner.py")
SHARED = os.path.join(CSMA_CASES, "penalty_frictionless_contact_test_3D",
                      "explicit_3D_contact_simplest_patch_matching_test_parameters.json")
SHARED_NODES = [2, 5]  # node 2 (upper block, z 0.99999) overlaps node 5 (lower block, z 1) by 1e-5


def run_ours(parameters_file: str, speed: float | None, folder: str) -> dict:
    """Our run of the case, from `folder` (where its relative paths start)."""
    rows, recording = [], [0.0]

    class Analysis(StructuralMechanicsAnalysis):
        def Initialize(self):
            super().Initialize()
            if speed is not None:
                bar_impact.set_initial_velocities(self.model["Structure"])

        def FinalizeSolutionStep(self):
            super().FinalizeSolutionStep()
            start = time.perf_counter()
            root = self.model["Structure"]
            row = [root.ProcessInfo.GetValue(mc.GetVariable("TIME")), float(root.Is(mc.CONTACT))]
            if speed is not None:
                state = bar_impact.bar_state(root)
                row += [state[0], state[3]]
            else:
                row += [root.GetNode(i).GetSolutionStepValue(mc.GetVariable("DISPLACEMENT_Z")) for i in SHARED_NODES]
            rows.append(row)
            recording[0] += time.perf_counter() - start

    cwd = os.getcwd()
    os.chdir(folder)
    try:
        params = read_project_parameters(parameters_file)
        if params["processes"].Has("json_check_process"):
            params["processes"].RemoveValue("json_check_process")
        analysis = Analysis(mc.Model(), params)
        analysis.Initialize()
        start = time.perf_counter()
        analysis.RunSolutionLoop()
        loop = time.perf_counter() - start - recording[0]
        analysis.Finalize()
    finally:
        os.chdir(cwd)
    return {"loop_seconds": loop, "rows": rows}


def run_kratos(python: str, parameters_file: str, speed: float | None, folder: str) -> dict:
    request, out = os.path.join(folder, "request.json"), os.path.join(folder, "kratos.json")
    with open(request, "w") as f:
        json.dump({"speed": speed, "nodes": [] if speed is not None else SHARED_NODES}, f)
    subprocess.run([python, RUNNER, parameters_file, request, out], check=True, capture_output=True,
                   env={**os.environ, "OMP_NUM_THREADS": "1"})
    with open(out) as f:
        return json.load(f)


def describe(name: str, result: dict, bar: bool) -> str:
    rows = result["rows"]
    steps = len(rows)
    text = (f"  {name:14s} {result['loop_seconds']:6.2f} s, {steps:6d} steps, "
            f"{1e6 * result['loop_seconds'] / steps:7.1f} us/step")
    touching = [row[0] for row in rows if row[1] > 0.0]
    if bar:
        contact = (touching[-1] - touching[0]) / (2.0 * bar_impact.LENGTH / bar_impact.wave_speed()) if touching else 0
        return text + f"; velocities after {rows[-1][2]:+.3f} {rows[-1][3]:+.3f}, contact time / (2L/c) {contact:.3f}"
    penetration = max(1.0e-5 + row[3] - row[2] for row in rows)
    return text + f"; steps in contact {len(touching)}, largest penetration {penetration:.3g}"


def main() -> int:
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    python = harness.kratos_python()
    with tempfile.TemporaryDirectory() as folder:
        bar = bar_impact.write_case(os.path.join(folder, "bar"), time_step=bar_impact.critical_time_step() / 2)
        # Kratos reads the bars' mesh as the mdpa made of our gmsh file (mesh_files.write_kratos_mdpa).
        write_kratos_mdpa(os.path.dirname(bar))
        bar_kratos = os.path.join(os.path.dirname(bar), "KratosParameters.json")
        with open(bar) as f, open(bar_kratos, "w") as g:
            g.write(kratos_parameters(f.read(), os.path.dirname(bar)))
        shared = migrated_case(SHARED, folder)
        for name, ours_file, kratos_file, speed in (("bar impact", bar, bar_kratos, bar_impact.SPEED),
                                                    ("shared explicit case", SHARED, shared, None)):
            print(name)
            where = os.path.dirname(bar) if speed is not None else CSMA_CASES
            print(describe("mortarcontact", run_ours(ours_file, speed, where), speed is not None))
            print(describe("Kratos 10.4", run_kratos(python, kratos_file, speed, folder), speed is not None))
    return 0


if __name__ == "__main__":
    sys.exit(main())
