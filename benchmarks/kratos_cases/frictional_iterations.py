#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 12: the frictional shared Kratos cases in both codes, side by side: Newton iterations per
step (mortarcontact against Kratos 10.4 on the same files) and the largest difference of the
checked values to Kratos 10.4 and to the case's reference file (max |a - b| over the checked nodes
divided by the largest |b|, worst variable; as tests/python/test_contact_cases.py measures it).

Both codes run the case as written, without its json check processes (so that a case whose
values differ still reports its iterations); Kratos reads the migrated copy of
benchmarks/kratos_cases/kratos_migration.py, in its own virtual environment, one thread.

    python benchmarks/kratos_cases/frictional_iterations.py [--cases NAME,...] [--output FILE]
Environment: MORTARCONTACT_KRATOS_VENV (as for benchmarks/hertz). Writes
benchmarks/kratos_cases/frictional_iterations.md.
"""
from __future__ import annotations

import argparse
import datetime
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "benchmarks", "hertz"))
sys.path.insert(0, os.path.join(ROOT, "tests", "python"))

import harness  # noqa: E402
from csma_cases import CSMA_CASES, FRICTIONAL_CASES, reference_nodes, reference_values, worst_difference  # noqa: E402
from kratos_migration import migrated_case  # noqa: E402

RUNNER = os.path.join(HERE, "kratos_case_runner.py")
OUTPUT = os.path.join(HERE, "frictional_iterations.md")


def run_ours(case: str, time_: float, request: dict) -> dict:
    """Our run, in process: iterations per step, the values at `time_`, the wall time, or the error."""
    import mortarcontact as mc
    from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
    from mortarcontact.project_parameters import read_project_parameters

    snapshot = {}

    class Analysis(StructuralMechanicsAnalysis):
        def FinalizeSolutionStep(self):
            super().FinalizeSolutionStep()
            part = self.model[self.parameters["solver_settings"]["model_part_name"].GetString()]
            now = part.ProcessInfo.GetValue(mc.GetVariable("TIME"))
            if abs(now - time_) > 1e-9 * max(1.0, abs(now)):
                return
            for key, names in request.items():
                node = part.GetNode(int(key[len("NODE_"):]))
                snapshot[key] = {name: node.GetSolutionStepValue(mc.GetVariable(name)) for name in names}

    params = read_project_parameters(os.path.join(CSMA_CASES, f"{case}_parameters.json"))
    if params["processes"].Has("json_check_process"):
        params["processes"].RemoveValue("json_check_process")
    cwd = os.getcwd()
    os.chdir(CSMA_CASES)
    start = time.perf_counter()
    analysis = Analysis(mc.Model(), params, progress=False)
    error = None
    try:
        analysis.Run()
    except Exception as e:  # a failed run is a result of the benchmark, reported in the table
        error = f"{type(e).__name__}: {str(e).splitlines()[0]}"
    finally:
        os.chdir(cwd)
    return {"iterations": [it for _, _, it, _, _ in analysis.step_log], "nodes": snapshot,
            "seconds": time.perf_counter() - start, "error": error}


def run_kratos(python: str, case: str, time_: float, request: dict, folder: str) -> dict:
    """Kratos 10.4 on the migrated files (kratos_case_runner.py; the migration leaves the json
    checks out), or its error."""
    migrated = migrated_case(os.path.join(CSMA_CASES, f"{case}_parameters.json"), folder)
    request_file = os.path.join(folder, "request.json")
    with open(request_file, "w") as f:
        json.dump({"time": time_, "nodes": request}, f)
    out = os.path.join(folder, "kratos.json")
    start = time.perf_counter()
    done = subprocess.run([python, RUNNER, migrated, request_file, "frictional", out], capture_output=True,
                          text=True, env={**os.environ, "OMP_NUM_THREADS": "1"})
    seconds = time.perf_counter() - start
    if done.returncode != 0 or not os.path.exists(out):
        lines = [line for line in (done.stderr + done.stdout).splitlines() if line.strip()]
        return {"error": lines[-1] if lines else f"exit code {done.returncode}", "seconds": seconds}
    with open(out) as f:
        result = json.load(f)  # with "error" when it failed after the check time
    result["seconds"] = seconds
    return result


def iterations_text(iterations: list) -> str:
    if not iterations:
        return "-"
    return f"{sum(iterations)} ({len(iterations)} steps, max {max(iterations)})"


def difference_text(value) -> str:
    return "-" if value is None else f"{value:.1e}"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cases", default="all", help="comma-separated case paths (folder/case) or 'all'")
    parser.add_argument("--output", default=OUTPUT)
    args = parser.parse_args(argv)
    python = harness.kratos_python()
    cases = [c for c, _ in FRICTIONAL_CASES] if args.cases == "all" else args.cases.split(",")
    rows, details = [], []
    for case in cases:
        time_, request = reference_values(case)
        expected = reference_nodes(case)
        print(f"{case}: mortarcontact ...", flush=True)
        ours = run_ours(case, time_, request)
        print(f"{case}: Kratos 10.4 ...", flush=True)
        with tempfile.TemporaryDirectory() as folder:
            kratos = run_kratos(python, case, time_, request, folder)
        ours_ok = bool(ours["nodes"])
        kratos_ok = bool(kratos.get("nodes"))
        name = os.path.basename(case)
        rows.append("| " + " | ".join([
            f"{os.path.dirname(case)}/{name}",
            iterations_text(ours["iterations"]) + ("" if ours["error"] is None else " **failed**"),
            iterations_text(kratos.get("newton_iterations", [])) + (" **failed**" if "error" in kratos else ""),
            difference_text(worst_difference(ours["nodes"], kratos["nodes"]) if ours_ok and kratos_ok else None),
            difference_text(worst_difference(ours["nodes"], expected) if ours_ok else None),
            difference_text(worst_difference(kratos["nodes"], expected) if kratos_ok else None),
            f"{ours['seconds']:.2f} / {kratos['seconds']:.2f}",
        ]) + " |")
        details.append(f"- `{name}`: ours {ours['iterations']}" + (f" ({ours['error']})" if ours["error"] else "")
                       + f"; Kratos 10.4 {kratos.get('newton_iterations', [])}"
                       + (f" ({kratos['error']})" if "error" in kratos else ""))
        print(rows[-1], flush=True)
    text = "\n".join([
        "# Frictional shared cases: Newton iterations and differences, mortarcontact vs Kratos 10.4",
        "",
        f"Generated by `python benchmarks/kratos_cases/frictional_iterations.py` on "
        f"{datetime.date.today().isoformat()}. Both codes run each case as written (json checks left out), "
        "Kratos 10.4.4 from its wheels with one thread. Differences: max |a - b| over the checked nodes "
        "over the largest |b|, worst checked variable, at the reference file's last time.",
        "",
        "| case | Newton iterations, ours | Kratos 10.4 | ours vs Kratos | ours vs reference | Kratos vs reference "
        "| seconds, ours / Kratos |",
        "|---|---|---|---|---|---|---|",
        *rows,
        "",
        "Iterations per step:",
        "",
        *details,
        "",
    ])
    with open(args.output, "w") as f:
        f.write(text)
    print(f"wrote {os.path.relpath(args.output, ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
