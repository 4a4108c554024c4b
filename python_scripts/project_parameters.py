"""Reading ProjectParameters.json: the top-level whitelist and the legacy layouts of spec 1.1-1.2
and 2.3, translated into the current layout before anything is validated."""
from __future__ import annotations

import os

from . import _core

TOP_LEVEL_KEYS = ["problem_data", "solver_settings", "processes", "output_processes", "modelers",
                  "restart_options", "constraints_data", "constraints_process_list",
                  "loads_process_list", "contact_processes", "output_configuration"]
LEGACY_PROCESS_LISTS = ["constraints_process_list", "loads_process_list", "contact_processes"]
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
        if key.startswith("_") or key in ("restart_options", "constraints_data"):
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
    if problem_data["parallel_type"].GetString() not in ("OpenMP", "MPI"):
        raise _core.InputError(f"{problem_data.Where()}.parallel_type: expected \"OpenMP\" or \"MPI\", "
                               f"got \"{problem_data['parallel_type'].GetString()}\"")
    if problem_data["parallel_type"].GetString() == "MPI":
        raise _core.NotImplementedFeatureError(
            f"{problem_data.Where()}.parallel_type: \"MPI\" runs are not implemented yet; use \"OpenMP\"")
