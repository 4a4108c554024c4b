#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Self-contact (issue 13): the U-shaped clamp of ``mortarcontact.cases.self_contact`` run by
mortarcontact and by Kratos 10.4 on the same files, with automatic roles (one contact part, empty
assume_master_slave) and with the roles given (left inner face slave, right one master).

Prints a Markdown table: converged?, Newton iterations per step, run time, and the largest
displacement difference to mortarcontact's given-roles run relative to the largest displacement.

    MORTARCONTACT_KRATOS_VENV=/path/to/venv python benchmarks/self_contact/compare.py [--dims 2,3]

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

SNAPSHOT = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "cases", "self_contact",
                        "kratos_10_4_2d_given.json")


def run(code: str, case_dir: str, output: str) -> None:
    """Runs the case with ``code`` (in this process) and writes its Newton iterations and convergence
    per step and the final displacements."""
    os.chdir(case_dir)
    with open("ProjectParameters.json") as f:
        parameters = json.load(f)
    record = {"steps": []}
    started = time.perf_counter()
    if code == "kratos":
        import KratosMultiphysics as KM
        import KratosMultiphysics.ContactStructuralMechanicsApplication  # noqa: F401 (registers the solver)
        import KratosMultiphysics.LinearSolversApplication  # noqa: F401 (registers sparse_lu)
        from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
            StructuralMechanicsAnalysis,
        )

        KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)
        imports = parameters["solver_settings"]["model_import_settings"]
        parameters["solver_settings"]["model_import_settings"] = {
            "input_type": "mdpa", "input_filename": os.path.splitext(imports["input_filename"])[0]}

        class Recorded(StructuralMechanicsAnalysis):
            def SolveSolutionStep(self):  # noqa: N802 (Kratos' name)
                converged = bool(self._GetSolver().SolveSolutionStep())
                info = self._GetSolver().GetComputingModelPart().ProcessInfo
                record["steps"].append((info[KM.NL_ITERATION_NUMBER], converged))
                return converged

        model = KM.Model()
        Recorded(model, KM.Parameters(json.dumps(parameters))).Run()
        displacement = KM.DISPLACEMENT
    else:
        import mortarcontact as mc

        model = mc.Model()
        analysis = mc.Analysis(model, parameters, stop_on_non_convergence=False)
        analysis.Run()
        record["steps"] = [(iterations, converged) for _, _, iterations, converged, _ in analysis.step_log]
        displacement = mc.DISPLACEMENT
    record["seconds"] = time.perf_counter() - started
    root = model["Structure"]
    record["displacements"] = {str(node.Id): list(node.GetSolutionStepValue(displacement)) for node in root.Nodes}
    with open(output, "w") as f:
        json.dump(record, f)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--dims", default="2,3")
    parser.add_argument("--snapshot", action="store_true", help="write the Kratos snapshot of the 2D given case")
    parser.add_argument("--run", nargs=3, metavar=("CODE", "CASE_DIR", "OUTPUT"), help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.run:
        run(*args.run)
        return 0
    import numpy as np
    from mortarcontact.cases import self_contact
    from mortarcontact.cases.mesh_files import write_kratos_mdpa

    venv = os.environ.get("MORTARCONTACT_KRATOS_VENV")
    pythons = {"mortarcontact": sys.executable}
    if venv:
        pythons["Kratos 10.4"] = os.path.join(venv, "bin", "python")
    print("| case | roles | code | converged | iterations per step | time (s) | max |du| / max |u| |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as scratch:
        for dim in (int(d) for d in args.dims.split(",")):
            reference = None
            for roles in ("given", "automatic"):
                folder = self_contact.write_case(dim, scratch, roles)
                write_kratos_mdpa(folder)
                for label, python in pythons.items():
                    output = os.path.join(scratch, f"{dim}-{roles}-{label.split()[0]}.json")
                    code = "kratos" if label.startswith("Kratos") else "mortarcontact"
                    subprocess.run([python, os.path.abspath(__file__), "--run", code, folder, output], check=True,
                                   stdout=subprocess.DEVNULL)
                    with open(output) as f:
                        record = json.load(f)
                    if args.snapshot and code == "kratos" and dim == 2 and roles == "given":
                        record["kratos"] = subprocess.run(
                            [python, "-c", "import importlib.metadata as m; print(m.version('KratosMultiphysics'))"],
                            capture_output=True, text=True, check=True).stdout.strip()
                        with open(SNAPSHOT, "w") as f:
                            json.dump(record, f, indent=0)
                            f.write("\n")
                    u = np.array([record["displacements"][k] for k in sorted(record["displacements"], key=int)])
                    if reference is None:
                        reference = u
                    difference = np.abs(u - reference).max() / np.abs(reference).max()
                    failed = [str(k + 1) for k, (_, converged) in enumerate(record["steps"]) if not converged]
                    status = "no (steps " + ",".join(failed) + ")" if failed else "yes"
                    print(f"| self_contact_{dim}d | {roles} | {label} | {status} | "
                          f"{','.join(str(n) for n, _ in record['steps'])} | {record['seconds']:.2f} | {difference:.1e} |",
                          flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
