"""Reading ProjectParameters.json: the top-level whitelist and the legacy layouts of spec 1.1-1.2
and 2.3, translated into the current layout before anything is validated."""
from __future__ import annotations

import json
import os

from . import _core

TOP_LEVEL_KEYS = ["problem_data", "solver_settings", "processes", "output_processes", "modelers",
                  "restart_options", "constraints_data", "constraints_process_list",
                  "loads_process_list", "contact_processes", "output_configuration"]
LEGACY_PROCESS_LISTS = ["constraints_process_list", "loads_process_list", "contact_processes"]
#: The legacy top-level restart block (pre-2018 CSMA inputs; Kratos no longer reads it, we do)
RESTART_OPTIONS_DEFAULTS = """{
    "SaveRestart": false,
    "RestartFrequency": 0,
    "LoadRestart": false,
    "Restart_Step": 0
}"""
PROBLEM_DATA_DEFAULTS = """{
    "problem_name": "",
    "parallel_type": "OpenMP",
    "echo_level": 0,
    "start_time": 0.0,
    "end_time": 1.0,
    "model_part_name": null,
    "domain_size": null,
    "time_step": null
}"""


def read_project_parameters(path: str) -> _core.Parameters:
    """The parameters of a case, migrated to the current layout and with problem_data validated."""
    if not os.path.isfile(path):
        raise _core.InputError(f"{path}: no such file")
    params = _core.Parameters.FromFile(path)
    migrate_project_parameters(params)
    return params


def migrate_project_parameters(params: _core.Parameters) -> None:
    """Applies spec 1.1/1.2 in place: ignores commented-out ('_') and never-read keys, rejects
    unknown top-level keys, moves legacy process lists into ``processes`` and legacy
    ``problem_data`` keys into ``solver_settings``."""
    for key in list(params.keys()):
        if key.startswith("_") or key == "constraints_data":
            params.RemoveValue(key)
    params.CheckKeys(TOP_LEVEL_KEYS)
    for key in ("problem_data", "solver_settings"):
        if not params.Has(key):
            raise _core.InputError(f"{params.Where()}: the required block '{key}' is missing")
    if params.Has("modelers"):
        raise _core.NotImplementedFeatureError(
            f"{params.Where()}: 'modelers' are not supported; import the mesh through "
            "solver_settings.model_import_settings")

    legacy = [k for k in LEGACY_PROCESS_LISTS if params.Has(k)]
    if legacy:
        if params.Has("processes"):
            raise _core.InputError(
                f"{params.Where()}: {', '.join(legacy)} at the top level cannot be mixed with 'processes'; "
                "move them inside 'processes'")
        params.AddValue("processes", _core.Parameters())
        for key in legacy:
            params["processes"].AddValue(key, params[key])
            params.RemoveValue(key)
    if params.Has("output_configuration"):
        _core.NoEffectWarnings.Warn(params, "output_configuration", "GiD output of old inputs is not written; "
                                    "add a vtk_output block to output_processes for ParaView files")
        params.RemoveValue("output_configuration")

    problem_data = params["problem_data"]
    problem_data.ValidateAndAssignDefaults(_core.Parameters(PROBLEM_DATA_DEFAULTS))
    start, end = problem_data["start_time"].GetDouble(), problem_data["end_time"].GetDouble()
    if not end >= start:
        raise _core.InputError(f"{problem_data.Where()}.end_time: must not be before start_time ({start!r}), "
                               f"got {end!r}")
    solver = params["solver_settings"]
    moves = {"model_part_name": "model_part_name", "domain_size": "domain_size"}
    for old, new in moves.items():
        if not problem_data[old].IsNull():
            if solver.Has(new):
                raise _core.InputError(
                    f"{params.Where()}: '{old}' is given both in problem_data and in solver_settings; keep one")
            solver.AddValue(new, problem_data[old])
        problem_data.RemoveValue(old)
    if not problem_data["time_step"].IsNull():
        stepping = solver["time_stepping"] if solver.Has("time_stepping") else None
        if stepping is not None and stepping.Has("time_step"):
            raise _core.InputError(
                f"{params.Where()}: 'time_step' is given both in problem_data and in solver_settings.time_stepping")
        if stepping is None:
            solver.AddValue("time_stepping", _core.Parameters())
            stepping = solver["time_stepping"]
        stepping.AddValue("time_step", problem_data["time_step"])
    problem_data.RemoveValue("time_step")
    if params.Has("restart_options"):
        _migrate_restart_options(params)
    if problem_data["parallel_type"].GetString() not in ("OpenMP", "MPI"):
        raise _core.InputError(f"{problem_data.Where()}.parallel_type: expected \"OpenMP\" or \"MPI\", "
                               f"got \"{problem_data['parallel_type'].GetString()}\"")
    if problem_data["parallel_type"].GetString() == "MPI":
        raise _core.NotImplementedFeatureError(
            f"{problem_data.Where()}.parallel_type: \"MPI\" runs are not implemented yet; use \"OpenMP\"")


def _migrate_restart_options(params: _core.Parameters) -> None:
    """``restart_options`` into today's settings: ``SaveRestart`` adds a ``save_restart_process``
    writing every ``RestartFrequency`` steps (output list ``restart_options``); ``LoadRestart``
    resumes from the checkpoint of step ``Restart_Step`` (``model_import_settings.input_type``
    \"rest\"). Both name the checkpoints after solver_settings.model_part_name."""
    options = params["restart_options"]
    options.ValidateAndAssignDefaults(_core.Parameters(RESTART_OPTIONS_DEFAULTS))
    solver = params["solver_settings"]
    name = solver["model_part_name"].GetString() if solver.Has("model_part_name") else ""
    if options["SaveRestart"].GetBool():
        if not params.Has("output_processes"):
            params.AddValue("output_processes", _core.Parameters())
        save = {"python_module": "save_restart_process", "kratos_module": "KratosMultiphysics",
                "Parameters": {"model_part_name": name, "restart_control_type": "step",
                               "restart_save_frequency": float(options["RestartFrequency"].GetInt())}}
        params["output_processes"].AddValue("restart_options", _core.Parameters(json.dumps([save])))
    if options["LoadRestart"].GetBool():
        if not solver.Has("model_import_settings"):
            solver.AddValue("model_import_settings", _core.Parameters())
        imports = solver["model_import_settings"]
        for key, value in (("input_type", "rest"), ("input_filename", name),
                           ("restart_load_file_label", str(options["Restart_Step"].GetInt()))):
            if imports.Has(key):
                imports.RemoveValue(key)
            imports.AddValue(key, _core.Parameters(json.dumps(value)))
    params.RemoveValue("restart_options")
