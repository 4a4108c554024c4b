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
    # Mesh tying (issue 13): no contact_type of its own; the process picks it by the tied variable's kind.
    tying = _core.ContactFormulation.OfProcess("mesh_tying_process", "Components")
    assert tying.mortar_type == "ComponentsMeshTying"
    assert tying.ConditionStem(False, False) == "MeshTyingMortarCondition"
    assert (tying.multiplier, tying.multiplier_blocks, tying.condensable) == ("VECTOR_LAGRANGE_MULTIPLIER", 1, True)
    scalar = _core.ContactFormulation.OfProcess("mesh_tying_process", "Scalar")
    assert scalar.mortar_type == "ScalarMeshTying" and scalar.dofs == [("SCALAR_LAGRANGE_MULTIPLIER",
                                                                         "WEIGHTED_SCALAR_RESIDUAL")]
    assert _core.ContactFormulation.ContactTypes("penalty_contact_process") == [
        "Frictional", "FrictionalPureSlip", "Frictionless"]


def test_frictional_formulations():
    """Issue 12: ALM friction has a vector multiplier in three criteria blocks (normal, stick, slip),
    condensed by MixedULM; penalty friction has none; both keep three steps of history."""
    alm = _core.ContactFormulation.Get("ALMContactFrictional")
    assert (alm.frictional, alm.pure_slip, alm.multiplier_blocks, alm.condensable, alm.buffer_size) == (
        True, False, 3, True, 3)
    assert alm.variables == ["VECTOR_LAGRANGE_MULTIPLIER", "WEIGHTED_GAP", "WEIGHTED_SLIP", "WEIGHTED_VECTOR_RESIDUAL"]
    assert alm.ConditionStem(False, True) == "ALMFrictionalAxisymMortarContactCondition"
    assert _core.ContactFormulation.Get("ALMContactFrictionalWithNormalUpdate").mortar_type == "ALMContactFrictional"
    pure = _core.ContactFormulation.OfProcess("alm_contact_process", "FrictionalPureSlip")
    assert pure.mortar_type == "ALMContactFrictionalPureSlip" and pure.pure_slip
    assert pure.ConditionStem(True, False) == "ALMNVFrictionalMortarContactCondition"  # the same conditions
    penalty = _core.ContactFormulation.Get("PenaltyContactFrictionalPureSlip")
    assert (penalty.frictional, penalty.pure_slip, penalty.multiplier_blocks, penalty.dofs, penalty.buffer_size) == (
        True, True, 0, [], 3)
    assert penalty.variables == ["WEIGHTED_GAP", "WEIGHTED_SLIP"]
    settings = _core.Parameters("{}")
    assert alm.CreateActiveSetCriterion(settings).Name() == "alm_frictional_mortar_criteria"
    assert not _core.ContactFormulation.Get("ALMContactFrictionless").frictional


def test_the_condensing_solver_name_is_registered_by_the_contact_application():
    settings = _core.Parameters('{"solver_type": "mixed_ulm_linear_solver"}')
    with pytest.raises(mc.InputError, match=r"only valid in contact_settings\.mixed_ulm_solver_parameters"):
        _core.CreateLinearSolver(settings)
