# SPDX-License-Identifier: BSD-3-Clause
"""Copies of contact cases that Kratos 10.4 reads, in the frictionless formulation asked for.

The shared Kratos CSMA cases (tests/cases/kratos_csma) use legacy layouts that Kratos 10.4 rejects:
they are migrated with mortarcontact's own reader and their model part names made absolute;
nothing else changes, except that the skyline solver, absent from the wheels, is replaced by
sparse_lu (both are direct). Both codes then run the same files.
"""
from __future__ import annotations

import json
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CSMA_CASES = os.path.join(ROOT, "tests", "cases", "kratos_csma")

#: formulation -> (mortar_type, contact process module, Kratos process name, contact_type); the
#: switch of Kratos' components test classes, and the same case with the penalty process
FORMULATIONS = {
    "scalar": ("ALMContactFrictionless", "alm_contact_process", "ALMContactProcess", "Frictionless"),
    "components": ("ALMContactFrictionlessComponents", "alm_contact_process", "ALMContactProcess",
                   "FrictionlessComponents"),
    "penalty": ("PenaltyContactFrictionless", "penalty_contact_process", "PenaltyContactProcess", "Frictionless"),
}


def switch_formulation(params: dict, formulation: str) -> None:
    """Runs every contact process of `params` (a parameters dict) in `formulation`."""
    mortar_type, module, process_name, contact_type = FORMULATIONS[formulation]
    params["solver_settings"]["contact_settings"]["mortar_type"] = mortar_type
    for process in params["processes"]["contact_process_list"]:
        process["python_module"] = module
        process["process_name"] = process_name
        process["Parameters"]["contact_type"] = contact_type


def migrated_case(parameters_file: str, folder: str, formulation: str | None = None) -> str:
    """Writes a Kratos-10.4-readable copy of the case's parameters and materials into `folder`
    (relative paths inside the case resolve from the folder of `parameters_file`, or from
    CSMA_CASES for the shared cases, whose paths start with their sub-folder) and returns the
    parameters' path. `formulation` (a key of FORMULATIONS) switches the contact processes."""
    from mortarcontact.project_parameters import read_project_parameters

    parameters_file = os.path.abspath(parameters_file)
    base = CSMA_CASES if parameters_file.startswith(CSMA_CASES + os.sep) else os.path.dirname(parameters_file)
    cwd = os.getcwd()
    os.chdir(base)
    try:
        params = json.loads(read_project_parameters(parameters_file).WriteJsonString())
        root = params["solver_settings"]["model_part_name"]
        imports = params["solver_settings"]
        with open(imports["material_import_settings"]["materials_filename"]) as f:
            materials = json.load(f)
        imports["model_import_settings"]["input_filename"] = os.path.abspath(
            imports["model_import_settings"]["input_filename"])
    finally:
        os.chdir(cwd)

    def absolute(name: str) -> str:
        return name if name == root or name.startswith(root + ".") else f"{root}.{name}"

    for block in materials["properties"]:
        block["model_part_name"] = absolute(block["model_part_name"])
    stem = os.path.join(folder, os.path.basename(parameters_file).removesuffix("_parameters.json").removesuffix(
        ".json"))
    with open(stem + "_materials.json", "w") as f:
        json.dump(materials, f, indent=1)
    imports["material_import_settings"]["materials_filename"] = stem + "_materials.json"

    def fix(node):
        if isinstance(node, dict):
            node.pop("mesh_id", None)  # accepted by mortarcontact, rejected by Kratos 10.4
            # This one names a sub part of main_model_part_name, as Kratos 10.4 looks it up.
            relative = node.get("python_module") == "impose_rigid_movement_process"
            for key, value in node.items():
                if key == "Parameters" and relative:
                    continue
                if key == "model_part_name" and isinstance(value, str):
                    node[key] = absolute(value)
                else:
                    fix(value)
            if node.get("python_module") == "assign_vector_by_direction_to_condition_process":
                node["kratos_module"] = "KratosMultiphysics"  # moved to the core since the files were written
        elif isinstance(node, list):
            for value in node:
                fix(value)

    fix(params["processes"])
    params["processes"].pop("json_check_process", None)
    if formulation is not None:
        switch_formulation(params, formulation)
    solver = params["solver_settings"].get("linear_solver_settings", {})  # absent: both codes' default
    if "skyline" in solver.get("solver_type", "").lower():
        solver["solver_type"] = "LinearSolversApplication.sparse_lu"
    with open(stem + "_parameters.json", "w") as f:
        json.dump(params, f, indent=1)
    return stem + "_parameters.json"
