"""Defaults and legacy translation of ``solver_settings`` (spec 2.2-2.5, 2.7, 2.8). The defaults are
the single source for validation and for the documentation tables."""
from __future__ import annotations

from .. import _core
from ..utilities import warn_about_keys_without_effect
from .contact_mechanical_solver import contact_settings_defaults
from .convergence_history import ConvergenceHistory
from .mpc_contact_mechanical_solver import KEYS_WITHOUT_EFFECT as MPC_KEYS_WITHOUT_EFFECT
from .mpc_contact_mechanical_solver import mpc_contact_settings_defaults

STRUCTURAL_DEFAULTS = """{
    "solver_type": "mechanical_solver",
    "model_part_name": "",
    "computing_sub_model_part_name": "",
    "domain_size": -1,
    "echo_level": 0,
    "buffer_size": 2,
    "analysis_type": "non_linear",
    "time_integration_method": "implicit",
    "model_import_settings": {
        "input_type": "mdpa",
        "input_filename": "",
        "skip_timer": true,
        "ignore_variables_not_in_solution_step_data": false,
        "reorder": false,
        "reorder_consecutive": false,
        "element_names": {},
        "condition_names": {},
        "properties_ids": {},
        "restart_load_file_label": "",
        "input_output_path": "",
        "load_restart_files_from_folder": true,
        "serializer_trace": "no_trace"
    },
    "material_import_settings": {
        "materials_filename": ""
    },
    "time_stepping": {},
    "rotation_dofs": false,
    "volumetric_strain_dofs": false,
    "strain_dofs": false,
    "pressure_dofs": false,
    "displacement_control": false,
    "use_orthogonal_subscales": false,
    "reform_dofs_at_each_step": false,
    "use_old_stiffness_in_first_iteration": false,
    "displacement_extrapolation": false,
    "compute_reactions": true,
    "solving_strategy_settings": {
        "type": "newton_raphson",
        "advanced_settings": {}
    },
    "builder_and_solver_settings": {
        "type": "block",
        "advanced_settings": {}
    },
    "clear_storage": false,
    "move_mesh_flag": true,
    "multi_point_constraints_used": true,
    "convergence_criterion": "residual_criterion",
    "displacement_relative_tolerance": 1.0e-4,
    "displacement_absolute_tolerance": 1.0e-9,
    "residual_relative_tolerance": 1.0e-4,
    "residual_absolute_tolerance": 1.0e-9,
    "max_iteration": 10,
    "linear_solver_settings": {},
    "auxiliary_variables_list": [],
    "auxiliary_dofs_list": [],
    "auxiliary_reaction_list": [],
    "scheme_type": "",
    "damp_factor_m": -0.3,
    "newmark_beta": 0.25,
    "rayleigh_alpha": 0.0,
    "rayleigh_beta": 0.0,
    "time_step_prediction_level": 0,
    "delta_time_refresh": 1000,
    "max_delta_time": 1.0,
    "fraction_delta_time": 0.333333333333333333333333333333333333,
    "contact_settings": {},
    "mpc_contact_settings": {},
    "convergence_history": {},
    "step_splitting": {}
}"""

# Obsolete keys dropped with a warning (spec 2.3): the solve always happens on the root part.
DROPPED_KEYS = ["computing_model_part_name", "problem_domain_sub_model_part_list",
                "processes_sub_model_part_list", "use_computing_model_part", "solution_type"]
LEGACY_FRICTION_KEYS = {
    f"frictional_contact_{kind}_{which}_tolerance": [f"frictional_{block}_contact_{kind}_{which}_tolerance"
                                                     for block in ("stick", "slip")]
    for kind in ("displacement", "residual") for which in ("relative", "absolute")}


_PREDICTION = "only the explicit solver's time-step prediction (time_step_prediction_level > 0) reads it"
#: Keys of STRUCTURAL_DEFAULTS accepted without effect (issue 18): (sub-block or "", key) -> why;
#: warned when given a value other than the default (NoEffectWarnings).
KEYS_WITHOUT_EFFECT = {
    ("model_import_settings", "skip_timer"): "the import is not timed",
    ("model_import_settings", "reorder"): "the nodes keep their ids; the linear solvers order the system themselves",
    ("model_import_settings", "reorder_consecutive"): "the nodes keep their ids",
    ("model_import_settings", "serializer_trace"): "restart checkpoints are HDF5 files, not Kratos' serializer's",
    ("", "multi_point_constraints_used"): "both builders eliminate the model part's master-slave constraints "
                                          "whenever it has some",
}
#: Keys the explicit solver's time-step prediction reads, and from which time_step_prediction_level.
PREDICTION_KEYS = {"max_delta_time": 1, "fraction_delta_time": 1, "delta_time_refresh": 2}
#: The structural solver keeps its storage between steps; the contact solver clears it, as Kratos.
CLEAR_STORAGE_WITHOUT_EFFECT = "the strategy keeps its storage between steps (the results are the same)"
#: Only the static scheme reads it (the dynamic schemes predict from the velocity and acceleration).
EXTRAPOLATION_WITHOUT_EFFECT = "only the static scheme of a non-linear analysis extrapolates the last two steps"
#: The contact strategies build the matrix at every iteration (the contact pairs change it).
OLD_STIFFNESS_WITHOUT_EFFECT = "the contact strategies build the matrix at every iteration"


def translate_legacy_solver_settings(settings: _core.Parameters) -> None:
    """Spec 2.3 in place: block_builder, builder_and_solver_settings.use_block_builder,
    line_search, analysis_type spellings, obsolete computing-part keys."""
    where = settings.Where()
    if settings.Has("block_builder"):
        if settings.Has("builder_and_solver_settings"):
            raise _core.InputError(f"{where}: 'block_builder' (legacy) and 'builder_and_solver_settings' "
                                   "are both given; keep builder_and_solver_settings.type")
        kind = "block" if settings["block_builder"].GetBool() else "elimination"
        settings.AddValue("builder_and_solver_settings", _core.Parameters(f'{{"type": "{kind}"}}'))
        settings.RemoveValue("block_builder")
    if settings.Has("builder_and_solver_settings"):
        bs = settings["builder_and_solver_settings"]
        if bs.Has("use_block_builder"):
            block = bs["use_block_builder"].GetBool()
            lagrange = bs.Has("use_lagrange_BS") and bs["use_lagrange_BS"].GetBool()
            kind = ("block_lagrange" if lagrange else "block") if block else "elimination"
            for key in ("use_block_builder", "use_lagrange_BS"):
                if bs.Has(key):
                    bs.RemoveValue(key)
            if not bs.Has("type"):
                bs.AddValue("type", _core.Parameters(f'"{kind}"'))
        if not bs.Has("type"):
            bs.AddValue("type", _core.Parameters('"block"'))
    if settings.Has("line_search"):
        if settings["line_search"].GetBool():
            settings.AddValue("solving_strategy_settings", _core.Parameters('{"type": "line_search"}'))
        settings.RemoveValue("line_search")
    if settings.Has("analysis_type"):
        legacy = {"Non-Linear": "non_linear", "Linear": "linear"}
        value = settings["analysis_type"].GetString()
        if value in legacy:
            settings["analysis_type"].SetString(legacy[value])
    for key in DROPPED_KEYS:
        if settings.Has(key):
            if key != "solution_type":
                _core.NoEffectWarnings.Warn(settings, key, "obsolete; the solve runs on the root model part")
            settings.RemoveValue(key)
    if settings.Has("contact_settings"):
        contact = settings["contact_settings"]
        for old, new_keys in LEGACY_FRICTION_KEYS.items():
            if contact.Has(old):
                for new in new_keys:
                    if not contact.Has(new):
                        contact.AddValue(new, contact[old])
                contact.RemoveValue(old)


def validate_solver_settings(settings: _core.Parameters) -> None:
    """Translates legacy keys, then validates against the defaults (unknown keys are errors)."""
    translate_legacy_solver_settings(settings)
    settings.RecursivelyValidateAndAssignDefaults(_core.Parameters(STRUCTURAL_DEFAULTS))
    for key, defaults in (("contact_settings", contact_settings_defaults()),
                          ("mpc_contact_settings", mpc_contact_settings_defaults())):
        if settings[key].size() > 0:
            settings[key].RecursivelyValidateAndAssignDefaults(defaults)
    settings["convergence_history"].ValidateAndAssignDefaults(ConvergenceHistory.GetDefaultParameters())
    if not settings["model_part_name"].GetString():
        raise _core.InputError(f"{settings.Where()}.model_part_name: must name the model part (e.g. \"Structure\")")
    if settings["domain_size"].GetInt() not in (2, 3):
        raise _core.InputError(f"{settings.Where()}.domain_size: must be 2 or 3, "
                               f"got {settings['domain_size'].GetInt()}")
    _check_numbers(settings)
    _warn_about_keys_without_effect(settings)
    for key in ("volumetric_strain_dofs", "strain_dofs", "pressure_dofs", "displacement_control",
                "use_orthogonal_subscales"):
        if settings[key].GetBool():
            raise _core.NotImplementedFeatureError(f"{settings.Where()}.{key}: mixed formulations are not implemented")


def _warn_about_keys_without_effect(settings: _core.Parameters) -> None:
    defaults = _core.Parameters(STRUCTURAL_DEFAULTS)
    warn_about_keys_without_effect(settings, defaults, KEYS_WITHOUT_EFFECT)
    explicit = settings["solver_type"].GetString() == "Dynamic" and \
        settings["time_integration_method"].GetString() == "explicit"
    level = settings["time_step_prediction_level"].GetInt() if explicit else 0
    for key, needed in PREDICTION_KEYS.items():
        if level < needed:
            _core.NoEffectWarnings.IfGiven(settings, defaults, key, _PREDICTION.replace("> 0", f">= {needed}"))
    if settings["solver_type"].GetString() != "Static" or settings["analysis_type"].GetString() != "non_linear":
        _core.NoEffectWarnings.IfGiven(settings, defaults, "displacement_extrapolation", EXTRAPOLATION_WITHOUT_EFFECT)
    if settings["mpc_contact_settings"].size() > 0:
        warn_about_keys_without_effect(settings["mpc_contact_settings"], mpc_contact_settings_defaults(),
                                       MPC_KEYS_WITHOUT_EFFECT)
    contact = settings["contact_settings"]
    if contact.size() > 0 and contact["mortar_type"].GetString():
        _core.NoEffectWarnings.IfGiven(settings, defaults, "use_old_stiffness_in_first_iteration",
                                       OLD_STIFFNESS_WITHOUT_EFFECT)
    else:
        _core.NoEffectWarnings.IfGiven(settings, defaults, "clear_storage", CLEAR_STORAGE_WITHOUT_EFFECT)


TIME_STEPPING_KEYS = ["time_step", "time_step_table", "time_step_intervals"]
TOLERANCE_KEYS = ["displacement_relative_tolerance", "displacement_absolute_tolerance",
                  "residual_relative_tolerance", "residual_absolute_tolerance"]


def _check_numbers(settings: _core.Parameters) -> None:
    """Keys of time_stepping, the sign of the tolerances, time step and iteration limit (issue 16:
    each of these was accepted and failed later, or never)."""
    where = settings.Where()
    stepping = settings["time_stepping"]
    stepping.CheckKeys(TIME_STEPPING_KEYS)
    if stepping.Has("time_step") and stepping["time_step"].IsNumber():
        dt = stepping["time_step"].GetDouble()
        if not 0.0 < dt < float("inf"):
            raise _core.InputError(f"{where}.time_stepping.time_step: must be a positive number, got {dt!r}")
    for key in TOLERANCE_KEYS:
        value = settings[key].GetDouble()
        if not 0.0 <= value < float("inf"):
            raise _core.InputError(f"{where}.{key}: must be a non-negative number, got {value!r}")
    if settings["max_iteration"].GetInt() < 1:
        raise _core.InputError(f"{where}.max_iteration: must be at least 1, got {settings['max_iteration'].GetInt()}")
