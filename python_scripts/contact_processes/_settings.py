"""Defaults and input layouts shared by the contact processes (spec 4.1-4.8).

Every process owns its defaults as JSON text built here, so the documented numbers live in one
place; the per-process differences (spec 4.5-4.8) are applied on top of the common ones. Blocks
read by C++ classes take those classes' own defaults (search_parameters, the automatic ALM
estimate).
"""
from __future__ import annotations

import json

from .. import _core

SLOTS = [str(k) for k in range(10)]



def search_defaults() -> dict:
    """Kratos' search_parameters, declared by the C++ search that reads them."""
    return json.loads(_core.ContactSearchProcess.GetDefaultParameters().WriteJsonString())


# Keys accepted and ignored by every process (spec 4.2).
IGNORED_KEYS = {"help": "", "mesh_id": 0, "computing_model_part_name": ""}


def slots_of(value) -> dict:
    """Ten empty slots."""
    return dict.fromkeys(SLOTS, value)


def pair_defaults(prefix: str = "contact") -> dict:
    return {
        f"{prefix}_model_part": slots_of([]),
        "assume_master_slave": slots_of([]),
        f"{prefix}_property_ids": slots_of(0),
    }


def common_defaults() -> dict:
    return {
        **IGNORED_KEYS,
        "model_part_name": "Structure",
        **pair_defaults(),
        "friction_coefficients": slots_of(0.0),
        "interval": [0.0, "End"],
        "zero_tolerance_factor": 1.0,
        "integration_order": 2,
        "consider_tessellation": False,
        "normal_check_proportion": 0.1,
        "search_parameters": search_defaults(),
    }


def alm_defaults() -> dict:
    return {
        **common_defaults(),
        "contact_type": "Frictionless",
        "not_normal_update_frictional": False,
        "normal_variation": "no_derivatives_computation",
        "frictional_law": "Coulomb",
        "tangent_factor": 2.5e-2,
        "operator_threshold": 1.0e-3,
        "slip_augmentation_coefficient": 0.0,
        "slip_threshold": 2.0e-2,
        "clear_inactive_for_post": True,
        "slip_step_reset_frequency": 1,
        "advance_explicit_parameters": {
            "manual_max_gap_theshold": False,
            "automatic_gap_factor": 1.0e-1,
            "max_gap_threshold": 5.0e-2,
            "max_gap_factor": 1.0e2,
            "logistic_exponent_factor": 6.0,
        },
        # manual_ALM, penalty and scale_factor are the process'; the keys of the automatic
        # estimate are the C++ calculation's.
        "advance_ALM_parameters": {
            "manual_ALM": False,
            "penalty": 1.0e-12,
            "scale_factor": 1.0,
            "adapt_penalty": False,
            "max_gap_factor": 1.0e-3,
            **json.loads(_core.ALMVariablesCalculationProcess.GetDefaultParameters().WriteJsonString()),
        },
        "alternative_formulations": {"axisymmetric": False},
    }


def to_parameters(defaults: dict) -> _core.Parameters:
    return _core.Parameters(json.dumps(defaults))


def normalise_pair_layouts(settings: _core.Parameters, keys) -> None:
    """Accepts every layout of the slot keys found in CSMA inputs, in place: the slot
    dictionary ``{"0": [...], ...}``, a plain list of part names or a single name (slot 0), and
    for numeric keys a single number (slot 0)."""
    for key in keys:
        if not settings.Has(key):
            continue
        value = settings[key]
        if value.IsSubParameter():
            for slot in value.Keys():
                item = value[slot]
                if item.IsString():
                    name = item.GetString()
                    value.AddValue(slot, _core.Parameters(json.dumps([name] if name else [])))
            continue
        if value.IsString():
            name = value.GetString()
            replacement = _core.Parameters(json.dumps({"0": [name] if name else []}))
        elif value.IsArray():
            replacement = _core.Parameters(json.dumps({"0": value.GetStringArray()}))
        elif value.IsNumber():
            number = value.GetInt() if value.IsInt() else value.GetDouble()
            replacement = _core.Parameters(json.dumps({"0": number}))
        else:
            continue
        settings.AddValue(key, replacement)


def interval_of(settings: _core.Parameters) -> tuple[float, float]:
    """``[start, end]`` with ``"End"`` (any case) meaning 1e30."""
    interval = settings["interval"]
    if interval.size() != 2:
        raise _core.InputError(f"{interval.Where()}: expected [start, end], got {interval.WriteJsonString()}")
    bounds = []
    for i in range(2):
        item = interval[i]
        if item.IsString():
            if item.GetString().lower() != "end":
                raise _core.InputError(f"{item.Where()}: expected a number or \"End\", got '{item.GetString()}'")
            bounds.append(1e30)
        else:
            bounds.append(item.GetDouble())
    return bounds[0], bounds[1]
