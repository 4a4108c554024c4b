# SPDX-License-Identifier: BSD-3-Clause
"""Runs one contact case with Kratos 10.4 or mortarcontact and writes, after the last step, what
every contact variable holds at the interface nodes (issue 10, item 4: output parity).

    python contact_outputs_runner.py --code kratos|mortarcontact PARAMETERS OUTPUT.json

Run by snapshot_contact_outputs.py with the Python of the code under test; only the standard
library is imported here besides that code, and both codes are read through the same calls.

Three moments of the last step are recorded, because the values change between them:
"solved" (after the solver's FinalizeSolutionStep: strategy, criteria, reactions), "finalized"
(after every process' ExecuteFinalizeSolutionStep: what json_output_process and
from_json_check_result_process read) and "output" (after every process' ExecuteBeforeOutputStep:
what vtk_output writes). The case's own output processes are removed; the output hooks are called
here at every step. Per moment: the ProcessInfo values of INFO_VARIABLES, and for every node
flagged SLAVE or MASTER its flags and every variable of NODAL_VARIABLES that it holds, historical
(when the model part has it) and non-historical (when the node has it), each apart.
"""
from __future__ import annotations

import argparse
import json
import os

NODAL_VARIABLES = (
    "DISPLACEMENT", "REACTION", "NORMAL", "NODAL_H", "NODAL_AREA",
    "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE", "VECTOR_LAGRANGE_MULTIPLIER", "SCALAR_LAGRANGE_MULTIPLIER",
    "WEIGHTED_SCALAR_RESIDUAL", "WEIGHTED_VECTOR_RESIDUAL", "WEIGHTED_GAP", "WEIGHTED_SLIP", "TANGENT_XI",
    "TANGENT_ETA", "NORMAL_GAP", "TANGENT_SLIP", "AUXILIAR_COORDINATES", "DELTA_COORDINATES",
    "AUGMENTED_NORMAL_CONTACT_PRESSURE", "AUGMENTED_TANGENT_CONTACT_PRESSURE", "CONTACT_FORCE",
    "CONTACT_PRESSURE", "NORMAL_CONTACT_STRESS", "TANGENTIAL_CONTACT_STRESS", "NODAL_PAUX", "NODAL_MAUX",
    "INITIAL_PENALTY", "SCALE_FACTOR", "DYNAMIC_FACTOR",
)
INFO_VARIABLES = (
    "SCALE_FACTOR", "INITIAL_PENALTY", "ACTIVE_CHECK_FACTOR", "TANGENT_FACTOR", "MAX_GAP_FACTOR",
    "ZERO_TOLERANCE_FACTOR", "CONSIDER_NORMAL_VARIATION", "ACTIVE_SET_CONVERGED", "ACTIVE_SET_COMPUTED",
    "ADAPT_PENALTY", "DISTANCE_THRESHOLD", "INNER_LOOP_ITERATION", "NL_ITERATION_NUMBER",
)
FLAGS = ("ACTIVE", "SLAVE", "MASTER", "ISOLATED", "INTERFACE", "CONTACT", "VISITED", "MARKER")


class Code:
    """The few calls that differ between the two codes."""

    def __init__(self, name: str):
        self.name = name
        if name == "kratos":
            import KratosMultiphysics as KM
            import KratosMultiphysics.ConstitutiveLawsApplication  # registers HyperElastic3DLaw
            import KratosMultiphysics.ContactStructuralMechanicsApplication  # registers the contact classes
            import KratosMultiphysics.LinearSolversApplication  # registers sparse_lu
            from KratosMultiphysics.StructuralMechanicsApplication.structural_mechanics_analysis import (
                StructuralMechanicsAnalysis,
            )

            KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)
            self.module, self.Analysis = KM, StructuralMechanicsAnalysis
            self.has_variable, self.variable = KM.KratosGlobals.HasVariable, KM.KratosGlobals.GetVariable
            self.flag = lambda name: getattr(KM, name)
        else:
            import mortarcontact as mc
            from mortarcontact.analysis_stage import StructuralMechanicsAnalysis

            self.module, self.Analysis = mc, StructuralMechanicsAnalysis
            self.has_variable, self.variable = mc.HasVariable, mc.GetVariable
            self.flag = mc.GetFlag

    def parameters(self, path: str):
        if self.name == "kratos":
            with open(path) as f:
                return self.module.Parameters(f.read())
        from mortarcontact.project_parameters import read_project_parameters

        return read_project_parameters(path)

    def analysis(self, model, parameters, case_dir: str, hooks):
        """The code's analysis stage, with `hooks(stage)` called at the three moments."""
        kratos = self.name == "kratos"

        class Probed(self.Analysis):
            def FinalizeSolutionStep(self):
                (self._GetSolver() if kratos else self.solver).FinalizeSolutionStep()
                hooks("solved")
                for process in self.processes_of_step():
                    process.ExecuteFinalizeSolutionStep()
                hooks("finalized")

            def OutputSolutionStep(self):
                for process in self.processes_of_step():
                    process.ExecuteBeforeOutputStep()
                hooks("output")
                for process in self.processes_of_step():
                    process.ExecuteAfterOutputStep()

            def processes_of_step(self):
                return self._GetListOfProcesses() if kratos else self._all_processes()

        if kratos:
            return Probed(model, parameters)
        return Probed(model, parameters, progress=False, case_dir=case_dir)

    @staticmethod
    def plain(value):
        try:
            return [float(value[k]) for k in range(3)]
        except TypeError:
            return value if isinstance(value, bool) else float(value)

    def info_value(self, info, variable):
        return self.plain(info[variable] if self.name == "kratos" else info.GetValue(variable))


def snapshot(code: Code, part) -> dict:
    """The interface nodes' flags and contact variables and the ProcessInfo values, now."""
    info = part.ProcessInfo
    process_info = {}
    for name in INFO_VARIABLES:
        if code.has_variable(name) and info.Has(code.variable(name)):
            process_info[name] = code.info_value(info, code.variable(name))
    variables = [(name, code.variable(name)) for name in NODAL_VARIABLES if code.has_variable(name)]
    historical = [(name, v) for name, v in variables if part.HasNodalSolutionStepVariable(v)]
    flags = [(name, code.flag(name)) for name in FLAGS]
    nodes = {}
    for node in part.Nodes:
        if not (node.Is(code.flag("SLAVE")) or node.Is(code.flag("MASTER"))):
            continue
        nodes[str(node.Id)] = {
            "flags": {name: bool(node.Is(flag)) for name, flag in flags},
            "historical": {name: code.plain(node.GetSolutionStepValue(v)) for name, v in historical},
            "non_historical": {name: code.plain(node.GetValue(v)) for name, v in variables if node.Has(v)},
        }
    return {"process_info": process_info, "nodes": nodes}


def run(code_name: str, parameters_path: str) -> dict:
    code = Code(code_name)
    parameters = code.parameters(parameters_path)
    if parameters.Has("output_processes"):
        parameters.RemoveValue("output_processes")
    root = parameters["solver_settings"]["model_part_name"].GetString()
    model = code.module.Model()
    record = {"code": code_name, "steps": 0}

    def hooks(stage: str) -> None:
        part = model.GetModelPart(root)
        if stage == "solved":
            record["steps"] += 1
            record["time"] = float(code.info_value(part.ProcessInfo, code.variable("TIME")))
        record[stage] = snapshot(code, part)

    case_dir = os.path.dirname(os.path.abspath(parameters_path))
    cwd = os.getcwd()
    os.chdir(case_dir)
    try:
        code.analysis(model, parameters, case_dir, hooks).Run()
    finally:
        os.chdir(cwd)
    return record


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description="Contact variables at the interface nodes after the last step.")
    parser.add_argument("--code", choices=("kratos", "mortarcontact"), required=True)
    parser.add_argument("parameters")
    parser.add_argument("output")
    args = parser.parse_args(argv)
    record = run(args.code, args.parameters)
    with open(args.output, "w") as f:
        json.dump(record, f, indent=1, sort_keys=True)
        f.write("\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
