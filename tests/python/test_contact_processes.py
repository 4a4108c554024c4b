"""Issue 3 (parts 1 and 4): the contact processes — every key of spec 4.4-4.8 validated with its
default, the legacy slot layouts, nearest-name errors, the not-yet-implemented contact types, and
(when the C++ contact bindings and a pair condition are available) the interface set-up and
search driven from Python."""
from __future__ import annotations

import glob
import json
import os

import pytest

import mortarcontact as mc
from mortarcontact import _core
from mortarcontact.contact_processes import ALMContactProcess, MeshTyingProcess, PenaltyContactProcess
from mortarcontact.process_factory import PROCESS_REGISTRY, create_process

IMPLEMENTED = {("alm_contact_process", "Frictionless"), ("penalty_contact_process", "Frictionless")}


def _contact_items(parameters: dict):
    lists = parameters.get("processes", parameters)
    return lists.get("contact_process_list", [])


def _case_files(csma_cases):
    return sorted(glob.glob(os.path.join(csma_cases, "*", "*_parameters.json")))


def test_every_csma_case_contact_list_validates(csma_cases):
    seen = 0
    for path in _case_files(csma_cases):
        with open(path) as stream:
            parameters = json.load(stream)
        for item in _contact_items(parameters):
            seen += 1
            model = _core.Model()
            settings = item.get("Parameters", {})
            key = (item["python_module"], settings.get("contact_type", "Frictionless"))
            if key in IMPLEMENTED:
                process = create_process(_core.Parameters(json.dumps(item)), model)
                assert process.settings["search_parameters"]["search_factor"].GetDouble() > 0
            else:
                with pytest.raises(mc.NotImplementedFeatureError, match=item["python_module"]):
                    create_process(_core.Parameters(json.dumps(item)), model)
    assert seen >= 15


def test_contact_processes_are_registered():
    for name in ("alm_contact_process", "penalty_contact_process", "explicit_penalty_contact_process",
                 "mpc_contact_process", "mesh_tying_process"):
        assert ("ContactStructuralMechanicsApplication", name) in PROCESS_REGISTRY


def test_unknown_key_names_the_nearest_one():
    with pytest.raises(mc.InputError, match="contact_model_part"):
        ALMContactProcess(_core.Model(), _core.Parameters('{"contact_model_prt": {"0": ["A"]}}'))
    with pytest.raises(mc.InputError, match="search_factor"):
        ALMContactProcess(_core.Model(), _core.Parameters('{"search_parameters": {"search_factr": 2.0}}'))
    with pytest.raises(mc.InputError, match="'Frictionless'"):
        ALMContactProcess(_core.Model(), _core.Parameters('{"contact_type": "Frictionles"}'))


@pytest.mark.parametrize("layout", ['{"0": ["Contact_Part"]}', '["Contact_Part"]', '"Contact_Part"'])
def test_slot_layouts(layout):
    settings = _core.Parameters(f'{{"contact_model_part": {layout}, "assume_master_slave": {layout},'
                                f' "contact_property_ids": 3}}')
    process = ALMContactProcess(_core.Model(), settings)
    assert process.interface_slots() == [("0", ["Contact_Part"], ["Contact_Part"], 3, 0.0)]


def test_all_slots_empty_means_the_model_skin():
    process = ALMContactProcess(_core.Model(), _core.Parameters("{}"))
    assert process.interface_slots() == [("0", [], [], 0, 0.0)]


def test_defaults_of_each_process():
    alm = ALMContactProcess(_core.Model(), _core.Parameters("{}")).settings
    assert alm["tangent_factor"].GetDouble() == 2.5e-2
    assert alm["advance_ALM_parameters"]["penalty"].GetDouble() == 1.0e-12
    assert alm["search_parameters"]["type_search"].GetString() == "in_radius_with_obb"
    assert alm["search_parameters"]["check_gap"].GetString() == "check_mapping"
    assert alm["search_parameters"]["octree_search_parameters"]["bounding_box_factor"].GetDouble() == 0.1
    penalty = PenaltyContactProcess(_core.Model(), _core.Parameters('{"advance_ALM_parameters": {}}')).settings
    assert penalty["tangent_factor"].GetDouble() == 1.0e-3
    assert penalty["advance_ALM_parameters"]["penalty"].GetDouble() == 1.0e16
    assert penalty["advance_ALM_parameters"]["max_gap_factor"].GetDouble() == 5.0e-4
    assert PenaltyContactProcess(_core.Model()).condition_stem == "PenaltyFrictionlessMortarContactCondition"


def test_mesh_tying_partial_search_parameters_come_from_the_base_defaults():
    settings = _core.Parameters('{"mesh_tying_model_part": {"0": ["Tying_Part"]}, '
                                '"search_parameters": {"search_factor": 2.0}}')
    with pytest.raises(mc.NotImplementedFeatureError, match="mesh_tying_process"):
        MeshTyingProcess(_core.Model(), settings)
    assert settings["search_parameters"]["database_step_update"].GetInt() == 1
    assert settings["consider_tessellation"].GetBool() is True
    assert MeshTyingProcess.GetDefaultParameters()["search_parameters"]["database_step_update"].GetInt() == 999999999


@pytest.mark.parametrize("contact_type", ["Frictional", "FrictionalPureSlip", "FrictionalWithNormalUpdate"])
def test_not_yet_implemented_contact_types(contact_type):
    with pytest.raises(mc.NotImplementedFeatureError, match=contact_type):
        ALMContactProcess(_core.Model(), _core.Parameters(json.dumps({"contact_type": contact_type})))


def test_mortar_type_pairing():
    """The process checks its formulation against the one the solver registered (spec 2.10)."""
    process = ALMContactProcess(_core.Model(), _core.Parameters("{}"))
    process.root = _core.Model().CreateModelPart("Structure", 2)
    info = process.root.GetProcessInfo()
    info.SetValue(_core.MORTAR_TYPE, "ALMContactFrictionless")
    process.check_solver_variables()
    for wrong, found in (("PenaltyContactFrictionless", '"PenaltyContactFrictionless"'),
                         ("ALMContactFrictionlessComponents", '"ALMContactFrictionlessComponents"'),
                         ("", "none")):
        info.SetValue(_core.MORTAR_TYPE, wrong)
        with pytest.raises(mc.InputError, match=f'needs solver_settings.contact_settings.mortar_type '
                                                 f'"ALMContactFrictionless"; found {found}'):
            process.check_solver_variables()


needs_bindings = pytest.mark.skipif(
    not hasattr(_core, "ContactInterfaceBuilder") or "ALMFrictionlessMortarContactCondition2D2N" not in
    _core.ConditionNames(), reason="contact bindings or ALM pair conditions not built yet")


@needs_bindings
def test_alm_process_builds_interface_and_pairs(csma_cases):
    model = _core.Model()
    root = model.CreateModelPart("Structure", 2)
    for var in (_core.DISPLACEMENT, _core.NORMAL, _core.NODAL_H, _core.WEIGHTED_GAP,
                _core.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE):
        root.AddNodalSolutionStepVariable(var)
    _core.ReadModelPart(root, os.path.join(csma_cases, "ALM_frictionless_contact_test_2D",
                                           "hyper_simple_patch_test.mdpa"))
    root.GetProcessInfo().SetValue(_core.MORTAR_TYPE, "ALMContactFrictionless")  # as the contact solver does
    process = ALMContactProcess(model, _core.Parameters(
        '{"assume_master_slave": {"0": ["Parts_Parts_Auto2"]}, "contact_model_part": {"0": ["Contact_Part"]}}'))
    process.ExecuteInitialize()
    info = root.GetProcessInfo()
    assert info.GetValue(_core.DISTANCE_THRESHOLD) == 1e24
    assert info.GetValue(_core.INITIAL_PENALTY) == 1.0  # no YOUNG_MODULUS: the floor
    assert root.GetSubModelPart("Contact.ContactSub0").NumberOfConditions() == 2
    process.ExecuteInitializeSolutionStep()
    assert root.GetSubModelPart("ComputingContact").NumberOfConditions() == 1
