#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Self-contact (issue 13): the U-shaped clamp of ``mortarcontact.cases.self_contact`` run by
mortarcontact and by Kratos 10.4 on the same files, with automatic roles (one contact part, empty
assume_master_slave) and with the roles given (left inner face slave, right one master).

Writes benchmarks/self_contact/results.md, a Markdown table: converged?, Newton iterations per
step, run time, and the largest displacement difference to mortarcontact's given-roles run
relative to the largest displacement.

    python benchmarks/self_contact/compare.py [--dims 2,3]

Each run is a subprocess of this script in ``--run`` mode, with the Python of the code under
test (Kratos: MORTARCONTACT_KRATOS_VENV's), so that the two codes never share a process.
``--snapshot`` also writes Kratos' run of the 2D case with given roles (iterations, convergence
and final displacements per step) to tests/cases/self_contact/kratos_10_4_2d_given.json, which
tests/python/test_self_contact.py compares with.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "hertz"))
SNAPSHOT = os.path.join(HERE, "..", "..", "tests", "cases", "self_contact", "kratos_10_4_2d_given.json")
RESULTS = os.path.join(HERE, "results.md")


def run(code: str, case_dir: str, output: str) -> None:
    """Runs the case with ``code`` (in this process) and writes its Newton iterations and convergence
    per step and the final displacements."""
    os.chdir(case_dir)
    with open("ProjectParameters.json") as f:
        parameters = json.load(f)
    record = {"steps": [], "walls": []}
    started = time.perf_counter()
    if code == "kratos":
        import KratosMultiphysics as KM
        import KratosMultiphysics.ContactStructuralMechanicsApplication
        import KratosMultiphysics.LinearSolversApplication
        from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
            StructuralMechanicsAnalysis,
        )

        from case_runner import kratos_parameters  # the mdpa Kratos reads in place of our gmsh file

        KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)
        parameters = json.loads(kratos_parameters(json.dumps(parameters), case_dir))

        class Recorded(StructuralMechanicsAnalysis):
            def SolveSolutionStep(self):
                converged = bool(self._GetSolver().SolveSolutionStep())
                info = self._GetSolver().GetComputingModelPart().ProcessInfo
                record["steps"].append((info[KM.NL_ITERATION_NUMBER], converged))
                record["walls"].append(wall_positions(model, KM))
                return converged

        model = KM.Model()
        Recorded(model, KM.Parameters(json.dumps(parameters))).Run()
        api = KM
    else:
        import mortarcontact as mc

        class Recorded(mc.Analysis):
            def FinalizeSolutionStep(self):
                super().FinalizeSolutionStep()
                record["walls"].append(wall_positions(model, mc))

        model = mc.Model()
        analysis = Recorded(model, parameters, stop_on_non_convergence=False)
        analysis.Run()
        record["steps"] = [(iterations, converged) for _, _, iterations, converged, _ in analysis.step_log]
        api = mc
    record["seconds"] = time.perf_counter() - started
    root = model["Structure"]
    record["displacements"] = {str(node.Id): list(node.GetSolutionStepValue(api.DISPLACEMENT)) for node in root.Nodes}
    with open(output, "w") as f:
        json.dump(record, f)


def wall_positions(model, api) -> dict:
    """The current positions of the slot's two inner walls (Contact_left, Contact_right) by node."""
    root = model["Structure"]
    return {part: [[node.X0 + node.GetSolutionStepValue(api.DISPLACEMENT_X),
                    node.Y0 + node.GetSolutionStepValue(api.DISPLACEMENT_Y)]
                   for node in root.GetSubModelPart(part).Nodes]
            for part in ("Contact_left", "Contact_right")}


def overlaps(record: dict) -> list[float]:
    """2D, per step: the deepest a node of one inner wall of the slot lies inside the other arm at the
    end of the step (its horizontal distance past the other wall, taken as a polyline in y; 0 when
    none does)."""
    import numpy as np

    depths = []
    for walls in record["walls"]:
        left, right = (np.array(sorted(walls[part], key=lambda p: p[1])) for part in ("Contact_left", "Contact_right"))
        deepest = 0.0
        for nodes, wall, sign in ((right, left, 1.0), (left, right, -1.0)):
            inside = (nodes[:, 1] >= wall[0, 1]) & (nodes[:, 1] <= wall[-1, 1])
            depth = -sign * (nodes[inside, 0] - np.interp(nodes[inside, 1], wall[:, 1], wall[:, 0]))
            deepest = max(deepest, float(depth.max(initial=0.0)))
        depths.append(deepest)
    return depths


def run_child(python: str, code: str, case_dir: str, output: str) -> dict | str:
    """Runs the case with ``code`` in a subprocess of this script under ``python``: its record
    (see run), or the last error line of a run that crashed."""
    child = subprocess.run([python, os.path.abspath(__file__), "--run", code, case_dir, output],
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if child.returncode != 0:
        error = [line for line in child.stderr.splitlines() if "rror" in line]
        return (error or child.stderr.splitlines() or ["?"])[-1].strip()
    with open(output) as f:
        return json.load(f)


def steps_summary(record: dict) -> tuple[str, str]:
    """("yes" or "no (steps k, ...)" for the steps that did not converge, the Newton iterations per step)."""
    failed = [str(k + 1) for k, (_, converged) in enumerate(record["steps"]) if not converged]
    return ("no (steps " + ",".join(failed) + ")" if failed else "yes",
            ",".join(str(n) for n, _ in record["steps"]))


def displacement_difference(record: dict, reference: dict) -> float:
    """max |u - u_ref| / max |u_ref| over the nodes of ``reference``."""
    import numpy as np

    keys = sorted(reference["displacements"], key=int)
    u, u_ref = (np.array([r["displacements"][k] for k in keys]) for r in (record, reference))
    return float(np.abs(u - u_ref).max() / np.abs(u_ref).max())


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--dims", default="2,3")
    parser.add_argument("--snapshot", action="store_true", help="write the Kratos snapshot of the 2D given case")
    parser.add_argument("--run", nargs=3, metavar=("CODE", "CASE_DIR", "OUTPUT"), help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.run:
        run(*args.run)
        return 0
    from mortarcontact.cases import self_contact
    from mortarcontact.cases.mesh_files import write_kratos_mdpa

    import harness  # the Kratos 10.4 venv of the benchmarks (MORTARCONTACT_KRATOS_VENV), made on first use

    pythons = {"mortarcontact": sys.executable, "Kratos 10.4": harness.kratos_python()}
    lines = ["| case | roles | code | converged | iterations per step | time (s) | max abs(du) / max abs(u) |",
             "|---|---|---|---|---|---|---|"]

    def add(line: str) -> None:
        lines.append(line)
        print(line, flush=True)

    with tempfile.TemporaryDirectory() as scratch:
        for dim in (int(d) for d in args.dims.split(",")):
            reference = None
            for roles in ("given", "automatic"):
                folder = self_contact.write_case(dim, scratch, roles)
                write_kratos_mdpa(folder)
                for label, python in pythons.items():
                    output = os.path.join(scratch, f"{dim}-{roles}-{label.split()[0]}.json")
                    code = "kratos" if label.startswith("Kratos") else "mortarcontact"
                    record = run_child(python, code, folder, output)
                    if isinstance(record, str):
                        add(f"| self_contact_{dim}d | {roles} | {label} | crashed: {record[:120]} | | | |")
                        continue
                    if args.snapshot and code == "kratos" and dim == 2 and roles == "given":
                        record["kratos"] = subprocess.run(
                            [python, "-c", "import importlib.metadata as m; print(m.version('KratosMultiphysics'))"],
                            capture_output=True, text=True, check=True).stdout.strip()
                        with open(SNAPSHOT, "w") as f:
                            json.dump(record, f, indent=0)
                            f.write("\n")
                    if reference is None:
                        reference = record
                    difference = displacement_difference(record, reference)
                    status, iterations = steps_summary(record)
                    add(f"| self_contact_{dim}d | {roles} | {label} | {status} | {iterations} | "
                        f"{record['seconds']:.2f} | {difference:.1e} |")
    load = os.getloadavg()[0]
    with open(RESULTS, "w") as f:
        f.write("# Self-contact: the U-shaped clamp, mortarcontact and Kratos 10.4\n\n"
                "Generated by `benchmarks/self_contact/compare.py` (case: `mortarcontact.cases.self_contact`; 8 load "
                "steps of a pressure on the arms, tolerances 1e-6 relative). Automatic roles: the whole slot as one "
                "contact part and an empty assume_master_slave; given roles: left inner face slave, right one master. "
                "The last column compares with mortarcontact's given-roles run. Kratos' 2D and 3D runs with given "
                "roles end step 2 with the arms' tips overlapping (no active node: its search at the step start finds "
                "no pair); with tolerances 1e-14 in both codes the 2D answers still differ by 1.8e-4 (both tips 1.9e-5 "
                "further right in Kratos, the same gap between them).\n\nTimes: wall seconds of the analysis, all "
                "cores; Kratos with libgomp's default (spinning) wait policy, which costs it most on a busy machine "
                f"(benchmarks/hertz/results_wait_policy.md). Load average {load:.1f} at the end of the run "
                f"({os.cpu_count()} cores).\n\n" + "\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
