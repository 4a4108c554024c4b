#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 10: runs structural cases with Kratos or mortarcontact and writes their nodal results.

Executed by run.py in a subprocess with the Python of the code under test (Kratos: its own
virtual environment), so that only the standard library is imported here besides that code;
both codes expose the same Kratos-like Python API.

    python runner.py --code kratos|mortarcontact CASES_DIR NAME[,NAME...] OUTPUT.json

Per case: status ("ok", "not converged", "not available" for a feature the code does not have,
"failed"), the error message, wall time of the analysis, Newton iterations per step, and per
node its id with DISPLACEMENT and REACTION at the end time. One case failing does not stop the
others.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
import traceback


def _kratos():
    import KratosMultiphysics as KM
    import KratosMultiphysics.ConstitutiveLawsApplication  # registers HyperElastic3DLaw, KirchhoffSaintVenant3DLaw
    import KratosMultiphysics.LinearSolversApplication  # registers sparse_lu
    from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
        StructuralMechanicsAnalysis,
    )

    KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)

    def run(folder: str, record: dict):
        with open(os.path.join(folder, "ProjectParameters.json")) as f:
            parameters = KM.Parameters(f.read())
        model = KM.Model()

        class Recorded(StructuralMechanicsAnalysis):
            def Initialize(self):
                super().Initialize()
                solver = self._GetSolver()
                solve = solver.SolveSolutionStep

                def solve_and_record():
                    converged = bool(solve())
                    record["converged"].append(converged)
                    record["iterations"].append(solver.GetComputingModelPart().ProcessInfo[KM.NL_ITERATION_NUMBER])
                    return converged

                solver.SolveSolutionStep = solve_and_record

        Recorded(model, parameters).Run()
        return model["Structure"], KM.DISPLACEMENT, KM.REACTION

    return run


def _mortarcontact():
    import mortarcontact as mc
    from mortarcontact.analysis_stage import StructuralMechanicsAnalysis
    from mortarcontact.project_parameters import read_project_parameters

    def run(folder: str, record: dict):
        path = os.path.join(folder, "ProjectParameters.json")
        model = mc.Model()
        analysis = StructuralMechanicsAnalysis(model, read_project_parameters(path), progress=False,
                                               stop_on_non_convergence=False, case_dir=folder)
        analysis.Run()
        for _, _, iterations, converged, _ in analysis.step_log:
            record["iterations"].append(iterations)
            record["converged"].append(bool(converged))
        return model["Structure"], mc.DISPLACEMENT, mc.REACTION

    return run


def run_case(run, folder: str) -> dict:
    record = {"status": "ok", "iterations": [], "converged": []}
    cwd = os.getcwd()
    started = time.perf_counter()
    try:
        os.chdir(folder)  # relative paths inside a case resolve from its folder, as in Kratos
        part, displacement, reaction = run(folder, record)
        record["nodes"] = {str(node.Id): {"u": [float(v) for v in node.GetSolutionStepValue(displacement)],
                                          "r": [float(v) for v in node.GetSolutionStepValue(reaction)]}
                           for node in part.Nodes}
        if False in record["converged"]:
            record["status"] = "not converged"
    except Exception as error:  # reported, not raised: run.py tabulates it
        name = type(error).__name__
        unavailable = "NotImplemented" in name or "not implemented" in str(error).lower()
        record["status"] = "not available" if unavailable else "failed"
        record["error"] = f"{name}: {str(error).strip()[:2000]}"
        record["traceback"] = traceback.format_exc()[-4000:]
    finally:
        os.chdir(cwd)
    record["seconds"] = time.perf_counter() - started
    return record


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description="Runs structural cases and writes nodal results (JSON).")
    parser.add_argument("--code", choices=("kratos", "mortarcontact"), required=True)
    parser.add_argument("cases_dir")
    parser.add_argument("names", help="comma-separated case folder names")
    parser.add_argument("output")
    args = parser.parse_args(argv)
    run = _kratos() if args.code == "kratos" else _mortarcontact()
    results = {}
    for name in args.names.split(","):
        results[name] = run_case(run, os.path.abspath(os.path.join(args.cases_dir, name)))
        with open(args.output, "w") as f:  # after every case: a crash loses only the case that crashed
            json.dump(results, f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
