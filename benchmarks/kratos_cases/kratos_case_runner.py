# SPDX-License-Identifier: BSD-3-Clause
"""Runs one migrated case with Kratos 10.4 (called by snapshot_kratos.py with the venv's Python)
and writes the requested nodal values at the requested time:

    python kratos_case_runner.py PARAMETERS REQUEST FORMULATION OUTPUT
REQUEST: {"time": t, "nodes": {"NODE_<id>": ["VAR", ...]}}; FORMULATION: scalar | components |
frictional or tying (as written), the formulation PARAMETERS were migrated to (recorded only).
Non-historical variables (AUGMENTED_NORMAL_CONTACT_PRESSURE) are read with GetValue. The Newton
iterations of every step are stored too. A run that fails still writes what it has (the values if
it reached the requested time, and the iterations of its converged steps), with the error (its first
line) under "error".
"""
import json
import os
import sys

import KratosMultiphysics as KM
import KratosMultiphysics.ConstitutiveLawsApplication  # registers HyperElastic3DLaw
import KratosMultiphysics.ContactStructuralMechanicsApplication  # registers the contact classes
import KratosMultiphysics.LinearSolversApplication  # registers sparse_lu
from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import StructuralMechanicsAnalysis

NON_HISTORICAL = {"AUGMENTED_NORMAL_CONTACT_PRESSURE"}


def plain(value):
    """A JSON-writable copy: a number, or the components of a Kratos array (Array3)."""
    return value if isinstance(value, (int, float)) else [float(c) for c in value]


def main(parameters_file, request_file, formulation, output):
    with open(parameters_file) as f:
        params = KM.Parameters(f.read())
    with open(request_file) as f:
        request = json.load(f)
    model = KM.Model()
    root = params["solver_settings"]["model_part_name"].GetString()
    snapshot, iterations = {}, []

    class Analysis(StructuralMechanicsAnalysis):
        def FinalizeSolutionStep(self):
            super().FinalizeSolutionStep()
            part = model[root]
            iterations.append(part.ProcessInfo[KM.NL_ITERATION_NUMBER])
            time = part.ProcessInfo[KM.TIME]
            if abs(time - request["time"]) > 1e-9 * max(1.0, abs(time)):
                return
            for key, names in request["nodes"].items():
                node = part.GetNode(int(key[len("NODE_"):]))
                snapshot[key] = {name: plain((node.GetValue if name in NON_HISTORICAL else node.GetSolutionStepValue)(
                    KM.KratosGlobals.GetVariable(name))) for name in names}

    KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)
    cwd = os.getcwd()
    os.chdir(os.path.dirname(parameters_file))
    error = None
    try:
        Analysis(model, params).Run()
    except Exception as e:  # Kratos raises plain RuntimeErrors; reported with what was computed
        error = str(e).strip().splitlines()[0] if str(e).strip() else type(e).__name__
    finally:
        os.chdir(cwd)
    if not snapshot and not error:
        raise SystemExit(f"{parameters_file}: time {request['time']} was never reached")
    result = {"kratos": "10.4.4", "formulation": formulation, "time": request["time"], "nodes": snapshot,
              "newton_iterations": iterations}
    if error:
        result["error"] = error
    with open(output, "w") as f:
        json.dump(result, f, indent=1, sort_keys=True)
        f.write("\n")


if __name__ == "__main__":
    main(*sys.argv[1:])
