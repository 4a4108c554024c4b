# SPDX-License-Identifier: BSD-3-Clause
"""Runs one explicit contact case with Kratos 10.4 (called by explicit_contact.py with the Kratos
venv's Python) and writes the wall time of the solution loop, the steps, and the values the driver
compares:

    python explicit_kratos_runner.py PARAMETERS REQUEST OUTPUT
REQUEST: {"speed": v or null (bar impact: +v on Structure.left, -v on Structure.right at t = 0),
"nodes": [ids whose DISPLACEMENT_Z is recorded]}. Per step: TIME, the CONTACT flag of the root,
each bar's mean velocity (the end nodes of a bar weigh half: lumped hexahedra in a row), and the
recorded displacements. The recording is timed apart from the run.
"""
import json
import os
import sys
import time

import KratosMultiphysics as KM
import KratosMultiphysics.ContactStructuralMechanicsApplication  # registers the contact classes
import KratosMultiphysics.StructuralMechanicsApplication as SMA
from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import StructuralMechanicsAnalysis


def main(parameters_file, request_file, output):
    with open(request_file) as f:
        request = json.load(f)
    with open(parameters_file) as f:
        params = KM.Parameters(f.read())
    model = KM.Model()
    rows, recording = [], [0.0]
    speed = request.get("speed")

    class Analysis(StructuralMechanicsAnalysis):
        def Initialize(self):
            super().Initialize()
            if speed is None:
                return
            root = model["Structure"]
            for bar, v in (("left", speed), ("right", -speed)):
                for node in root.GetSubModelPart(bar).Nodes:
                    for position in (0, 1):  # Kratos' central differences start from MIDDLE_VELOCITY
                        node.SetSolutionStepValue(KM.VELOCITY, position, [v, 0.0, 0.0])
                        node.SetSolutionStepValue(SMA.MIDDLE_VELOCITY, position, [v, 0.0, 0.0])

        def FinalizeSolutionStep(self):
            super().FinalizeSolutionStep()
            start = time.perf_counter()
            root = model["Structure"]
            row = [root.ProcessInfo[KM.TIME], float(root.Is(KM.CONTACT))]
            if speed is not None:
                for bar in ("left", "right"):
                    nodes = list(root.GetSubModelPart(bar).Nodes)
                    xs = [n.X0 for n in nodes]
                    weights = [0.5 if x in (min(xs), max(xs)) else 1.0 for x in xs]
                    row.append(sum(w * n.GetSolutionStepValue(KM.VELOCITY_X) for w, n in zip(weights, nodes))
                               / sum(weights))
            row += [root.GetNode(i).GetSolutionStepValue(KM.DISPLACEMENT_Z) for i in request.get("nodes", [])]
            rows.append(row)
            recording[0] += time.perf_counter() - start

    KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)
    cwd = os.getcwd()
    os.chdir(os.path.dirname(os.path.abspath(parameters_file)))
    try:
        analysis = Analysis(model, params)
        analysis.Initialize()
        start = time.perf_counter()
        analysis.RunSolutionLoop()
        loop = time.perf_counter() - start - recording[0]
        analysis.Finalize()
    finally:
        os.chdir(cwd)
    with open(output, "w") as f:
        json.dump({"kratos": "10.4", "loop_seconds": loop, "rows": rows}, f)


if __name__ == "__main__":
    main(*sys.argv[1:])
