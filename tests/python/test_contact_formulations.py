"""Issue 11: the contact formulations are registered once (ContactFormulation), keyed by
mortar_type, with nearest-name errors; the contact application adds its linear solver name to the
core's factory by registration."""
from __future__ import annotations

import pytest

import mortarcontact as mc
from mortarcontact import _core


def test_formulations_are_registered_once():
    names = _core.ContactFormulation.Names()
    assert {"ALMContactFrictionless", "ALMContactFrictionlessComponents", "PenaltyContactFrictionless",
            "ALMContactFrictional", "ScalarMeshTying"} <= set(names)
    components = _core.ContactFormulation.Get("ALMContactFrictionlessComponents")
    assert components.condensable and components.multiplier == "VECTOR_LAGRANGE_MULTIPLIER"
    assert components.ConditionStem(True, False) == "ALMNVFrictionlessComponentsMortarContactCondition"
    # Kratos dispatches on substrings: a suffix keeps the formulation.
    formulation = _core.ContactFormulation.Get("ALMContactFrictionlessWithNormalUpdate")
    assert formulation.mortar_type == "ALMContactFrictionless"
    with pytest.raises(mc.InputError, match="did you mean 'ALMContactFrictionless'"):
        _core.ContactFormulation.Get("ALMContatFrictionless")
    with pytest.raises(mc.NotImplementedFeatureError, match=r"ComponentsMeshTying.*mesh tying"):
        _core.ContactFormulation.Get("ComponentsMeshTying")
    assert _core.ContactFormulation.ContactTypes("penalty_contact_process") == [
        "Frictional", "FrictionalPureSlip", "Frictionless"]


def test_the_condensing_solver_name_is_registered_by_the_contact_application():
    settings = _core.Parameters('{"solver_type": "mixed_ulm_linear_solver"}')
    with pytest.raises(mc.InputError, match=r"only valid in contact_settings\.mixed_ulm_solver_parameters"):
        _core.CreateLinearSolver(settings)
