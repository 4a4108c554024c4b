#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 10: the state of the contact interface after K Newton iterations of one load step, with
Kratos 10.4 or mortarcontact, to find where the two codes' iterations part (README.md, partly
covered slave edges). The earlier steps run as usual; in step STEP the strategy stops after K
iterations (K = 0: before the first solve, with the predicted active set) and every node of
Contact_slave and Contact_master is written: coordinates, ACTIVE, the scalar multiplier,
WEIGHTED_GAP, AUGMENTED_NORMAL_CONTACT_PRESSURE, NODAL_AREA, DISPLACEMENT, NORMAL, and for friction
SLIP, WEIGHTED_SLIP and VECTOR_LAGRANGE_MULTIPLIER (stick_slide.py reads two such dumps). Other
parts: --parts, e.g. Contact_right Contact_left for the self-contact clamp.

    python iterates.py --code mortarcontact CASE_DIR STEP K OUT.json [--set KEY.PATH=JSON ...]
    $MORTARCONTACT_KRATOS_VENV/bin/python iterates.py --code kratos CASE_DIR STEP K OUT.json

Run it with the Python of the code (Kratos: its own virtual environment; the case folder needs the
mdpa that mortarcontact.cases.mesh_files.write_kratos_mdpa writes, as run_sweep.py leaves it).
"""
from __future__ import annotations

import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "hertz"))
import case_runner


def interface_state(model, get_variable, active_flag, slip_flag, parts) -> list[dict]:
    root = model.GetModelPart("Structure")
    rows = []
    for part in parts:
        for node in root.GetSubModelPart(part).Nodes:
            def value(name, historical=True, node=node):
                try:
                    variable = get_variable(name)
                    return float(node.GetSolutionStepValue(variable) if historical else node.GetValue(variable))
                except Exception:  # absent in this code, formulation or node
                    return None
            def vector(name, node=node):
                try:
                    return [float(c) for c in node.GetSolutionStepValue(get_variable(name))]
                except Exception:  # frictionless or absent in this code
                    return None
            rows.append({"part": part, "id": node.Id, "x": node.X0, "y": node.Y0, "z": node.Z0,
                         "active": bool(node.Is(active_flag)),
                         "lm": value("LAGRANGE_MULTIPLIER_CONTACT_PRESSURE"), "gap": value("WEIGHTED_GAP"),
                         "augmented": value("AUGMENTED_NORMAL_CONTACT_PRESSURE", False),
                         "nodal_area": value("NODAL_AREA", False),
                         "u": [float(c) for c in node.GetSolutionStepValue(get_variable("DISPLACEMENT"))],
                         "normal": [float(c) for c in node.GetSolutionStepValue(get_variable("NORMAL"))],
                         "slip": bool(node.Is(slip_flag)), "weighted_slip": vector("WEIGHTED_SLIP"),
                         "lm_vector": vector("VECTOR_LAGRANGE_MULTIPLIER")})
    return rows


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--code", choices=("kratos", "mortarcontact"), required=True)
    parser.add_argument("case_dir")
    parser.add_argument("step", type=int)
    parser.add_argument("iterations", type=int)
    parser.add_argument("output")
    parser.add_argument("--parts", nargs=2, default=("Contact_slave", "Contact_master"), metavar=("SLAVE", "MASTER"),
                        help="the sub-model parts written (default: the sweep cases' Contact_slave Contact_master)")
    parser.add_argument("--set", action="append", default=[], metavar="KEY.PATH=JSON",
                        help="override one entry of ProjectParameters.json (repeatable)")
    args = parser.parse_args(argv)
    case_dir, output = os.path.abspath(args.case_dir), os.path.abspath(args.output)
    parameters_path = os.path.join(case_dir, "ProjectParameters.json")
    os.chdir(case_dir)

    def write(model, get_variable, active_flag, slip_flag):
        with open(output, "w") as f:
            json.dump(interface_state(model, get_variable, active_flag, slip_flag, args.parts), f)

    if args.code == "kratos":
        import KratosMultiphysics as KM
        import KratosMultiphysics.ConstitutiveLawsApplication  # registers the laws
        import KratosMultiphysics.ContactStructuralMechanicsApplication
        import KratosMultiphysics.LinearSolversApplication  # registers sparse_lu
        from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
            StructuralMechanicsAnalysis,
        )

        KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)
        with open(parameters_path) as f:
            text = case_runner.kratos_parameters(case_runner.overridden(f.read(), args.set), case_dir)
        model = KM.Model()
        stage_class, parameters = StructuralMechanicsAnalysis, KM.Parameters(text)
        get_variable, active_flag, slip_flag = KM.KratosGlobals.GetVariable, KM.ACTIVE, KM.SLIP

        def strategy(stage):
            return stage._GetSolver()._GetSolutionStrategy()

        def solver(stage):
            return stage._GetSolver()

        def step_of(stage):
            return stage._GetSolver().GetComputingModelPart().ProcessInfo[KM.STEP]
    else:
        import mortarcontact as mc
        from mortarcontact.analysis_stage import StructuralMechanicsAnalysis

        model = mc.Model()
        stage_class = StructuralMechanicsAnalysis
        parameters = case_runner.mortarcontact_parameters(parameters_path, None, args.set)
        get_variable, active_flag, slip_flag = mc.GetVariable, mc.ACTIVE, mc.SLIP

        def strategy(stage):
            return stage.solver.strategy

        def solver(stage):
            return stage.solver

        def step_of(stage):
            return model.GetModelPart("Structure").ProcessInfo.GetValue(mc.STEP)

    class Stopped(Exception):
        pass

    class Instrumented(stage_class):
        def InitializeSolutionStep(self):
            super().InitializeSolutionStep()
            if step_of(self) != args.step:
                return
            strategy(self).SetMaxIterationNumber(max(args.iterations, 1))
            if args.iterations == 0:
                def stop():
                    write(model, get_variable, active_flag, slip_flag)
                    raise Stopped
                solver(self).SolveSolutionStep = stop

        def FinalizeSolutionStep(self):
            if step_of(self) == args.step:
                write(model, get_variable, active_flag, slip_flag)
                raise Stopped
            super().FinalizeSolutionStep()

    if args.code == "kratos":
        stage = Instrumented(model, parameters)
    else:
        stage = Instrumented(model, parameters, progress=False, stop_on_non_convergence=False, case_dir=case_dir)
    try:
        stage.Initialize()
        stage.RunSolutionLoop()
    except Stopped:
        return 0
    print(f"step {args.step} was not reached", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main())
