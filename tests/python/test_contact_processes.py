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
from mortarcontact.project_parameters import read_project_parameters
from mortarcontact.solvers import create_solver

IMPLEMENTED = {("alm_contact_process", "Frictionless"), ("penalty_contact_process", "Frictionless"),
               ("alm_contact_process", "Frictional"), ("alm_contact_process", "FrictionalPureSlip"),
               ("penalty_contact_process", "Frictional"), ("explicit_penalty_contact_process", "Frictionless"),
               ("mpc_contact_process", "Frictionless"), ("mpc_contact_process", "Frictional"),
               ("mesh_tying_process", "Frictionless")}  # mesh tying has no contact_type: the key's default


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
    MeshTyingProcess(_core.Model(), settings)
    assert settings["search_parameters"]["database_step_update"].GetInt() == 1
    assert settings["consider_tessellation"].GetBool() is True
    assert MeshTyingProcess.GetDefaultParameters()["search_parameters"]["database_step_update"].GetInt() == 999999999


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


# == friction (issue 12) ============================================================================
def _process(cls, **settings):
    return cls(_core.Model(), _core.Parameters(json.dumps(settings)))


@pytest.mark.parametrize("cls,settings,stem,variation", [
    (ALMContactProcess, {"contact_type": "Frictional"}, "ALMFrictionalMortarContactCondition",
     "no_derivatives_computation_with_normal_update"),
    (ALMContactProcess, {"contact_type": "Frictional", "not_normal_update_frictional": True},
     "ALMFrictionalMortarContactCondition", "no_derivatives_computation"),
    (ALMContactProcess, {"contact_type": "FrictionalPureSlipWithNormalUpdate", "not_normal_update_frictional": True},
     "ALMFrictionalMortarContactCondition", "no_derivatives_computation_with_normal_update"),
    (PenaltyContactProcess, {"contact_type": "Frictional", "normal_variation": "nodal_elemental_derivatives"},
     "PenaltyNVFrictionalMortarContactCondition", "nodal_elemental_derivatives"),
    (ALMContactProcess, {"contact_type": "Frictionless"}, "ALMFrictionlessMortarContactCondition",
     "no_derivatives_computation"),
])
def test_frictional_contact_types(cls, settings, stem, variation):
    """Frictional types update the normals unless not_normal_update_frictional (spec 4.4); pure slip
    and the WithNormalUpdate suffix keep the frictional conditions."""
    process = _process(cls, **settings)
    assert process.condition_stem == stem
    assert process.normal_variation == variation
    assert process.frictional == settings["contact_type"].startswith("Frictional")
    assert process.formulation.pure_slip == ("PureSlip" in settings["contact_type"])


@pytest.mark.parametrize("settings,fragments", [
    ({"tangent_factor": 0.0}, ["tangent_factor", "(0, inf)", "0.0"]),
    ({"slip_threshold": 1.0}, ["slip_threshold", "[0, 1)", "1.0"]),
    ({"slip_augmentation_coefficient": -0.5}, ["slip_augmentation_coefficient", "-0.5"]),
    ({"operator_threshold": -1.0}, ["operator_threshold", "-1.0"]),
    ({"friction_coefficients": {"0": 0.1, "2": -0.3}}, ["friction_coefficients.2", "-0.3"]),
    ({"friction_coefficients": -0.3}, ["friction_coefficients.0", "-0.3"]),
    ({"frictional_law": "Colomb"}, ["frictional_law", "'Colomb'", "did you mean 'Coulomb'"]),
])
def test_friction_keys_are_checked(settings, fragments):
    """Every friction key is checked, frictional or not: the message names the key and the value."""
    for contact_type in ("Frictional", "Frictionless"):
        with pytest.raises(mc.InputError) as error:
            _process(PenaltyContactProcess, contact_type=contact_type, **settings)
        for fragment in fragments:
            assert fragment in str(error.value)


def test_friction_options_not_implemented_yet():
    with pytest.raises(mc.NotImplementedFeatureError, match=r"slip_step_reset_frequency: -1"):
        _process(ALMContactProcess, contact_type="Frictional", slip_step_reset_frequency=-1)
    # Without friction they have no effect.
    _process(ALMContactProcess, contact_type="Frictionless", frictional_law="Tresca", slip_step_reset_frequency=-1)


def _frictional_patch(csma_cases, settings, mu=None, threshold=None):
    """The frictional 2D patch (two unit squares 1e-3 apart), its interface set up by an ALM process
    with `settings`; `mu` (and the Tresca `threshold`) on the bodies' properties as materials.json
    gives them."""
    model = _core.Model()
    root = model.CreateModelPart("Structure", 3)
    for var in (_core.DISPLACEMENT, _core.NORMAL, _core.NODAL_H, _core.WEIGHTED_GAP, _core.WEIGHTED_SLIP,
                _core.VECTOR_LAGRANGE_MULTIPLIER):
        root.AddNodalSolutionStepVariable(var)
    _core.ReadModelPart(root, os.path.join(csma_cases, "ALM_frictional_contact_test_2D",
                                           "hyper_simple_patch_test.mdpa"))
    for variable, value in ((_core.FRICTION_COEFFICIENT, mu), (_core.TRESCA_FRICTION_THRESHOLD, threshold)):
        if value is not None:
            for element in root.Elements:
                element.GetProperties().SetValue(variable, value)
    process = ALMContactProcess(model, _core.Parameters(json.dumps({
        "assume_master_slave": {"0": ["Parts_Parts_Auto2"]}, "contact_model_part": {"0": ["Contact_Part"]},
        **settings})))
    root.GetProcessInfo().SetValue(_core.MORTAR_TYPE, process.formulation.mortar_type)  # as the solver does
    process.ExecuteInitialize()
    return process, root


@needs_bindings
def test_frictional_process_sets_up_the_interface(csma_cases, capsys):
    """SLIP on the model parts, the friction controls in ProcessInfo, the materials' friction
    coefficient on every interface node (friction_coefficients, different, is said to be unused),
    the augmented tangent pressure initialised."""
    process, root = _frictional_patch(csma_cases, {"contact_type": "Frictional", "tangent_factor": 0.5,
                                                   "slip_threshold": 0.1, "slip_augmentation_coefficient": 2.0,
                                                   "friction_coefficients": {"0": 0.7}}, mu=0.01)
    contact = root.GetSubModelPart("Contact")
    assert root.Is(_core.SLIP) and contact.Is(_core.SLIP) and root.GetSubModelPart("ComputingContact").Is(_core.SLIP)
    info = root.GetProcessInfo()
    assert (info.GetValue(_core.TANGENT_FACTOR), info.GetValue(_core.SLIP_THRESHOLD),
            info.GetValue(_core.SLIP_AUGMENTATION_COEFFICIENT)) == (0.5, 0.1, 2.0)
    assert info.GetValue(_core.CONSIDER_NORMAL_VARIATION) == 3  # the frictional normal update
    assert contact.NumberOfNodes() == 4
    assert list(contact.GetNodalNonHistoricalValues(_core.FRICTION_COEFFICIENT)) == [0.01] * 4  # materials win
    assert not contact.GetNodalNonHistoricalValues(_core.AUGMENTED_TANGENT_CONTACT_PRESSURE).any()
    assert not process.pure_slip
    unused = "friction_coefficients.0: 0.7 is not used: the interface property 100 already has FRICTION_COEFFICIENT"
    assert f"{unused} 0.01" in capsys.readouterr().err


@needs_bindings
def test_frictionless_process_clears_slip(csma_cases):
    _, root = _frictional_patch(csma_cases, {"contact_type": "Frictionless"}, mu=0.3)
    assert root.Is(_core.CONTACT) and not root.Is(_core.SLIP)
    assert not root.GetSubModelPart("Contact").Is(_core.SLIP)


@needs_bindings
@pytest.mark.parametrize("contact_type,mu,pure_slip", [
    ("Frictional", None, True),  # no coefficient anywhere: nothing can stick
    ("Frictional", 0.2, False),
    ("FrictionalPureSlip", 0.2, True),
])
def test_pure_slip_detection(csma_cases, contact_type, mu, pure_slip):
    process, _ = _frictional_patch(csma_cases, {"contact_type": contact_type}, mu=mu)
    assert process.pure_slip == pure_slip


@needs_bindings
def test_frictional_law_sets_the_nodal_bounds(csma_cases):
    """Tresca: the materials' threshold on every interface node and no Coulomb coefficient (not pure
    slip although mu = 0); Coulomb: the coefficient only; Tresca without a threshold: an input error
    naming the key, the variable and the node."""
    process, root = _frictional_patch(csma_cases, {"contact_type": "Frictional", "frictional_law": "Tresca"},
                                      mu=0.2, threshold=5.0)
    contact = root.GetSubModelPart("Contact")
    assert list(contact.GetNodalNonHistoricalValues(_core.TRESCA_FRICTION_THRESHOLD)) == [5.0] * 4
    assert not contact.GetNodalNonHistoricalValues(_core.FRICTION_COEFFICIENT).any()
    assert not process.pure_slip
    process, root = _frictional_patch(csma_cases, {"contact_type": "Frictional"}, mu=0.2, threshold=5.0)
    contact = root.GetSubModelPart("Contact")
    assert not contact.GetNodalNonHistoricalValues(_core.TRESCA_FRICTION_THRESHOLD).any()
    assert list(contact.GetNodalNonHistoricalValues(_core.FRICTION_COEFFICIENT)) == [0.2] * 4
    with pytest.raises(mc.InputError, match=r"frictional_law: 'Tresca' needs a positive TRESCA_FRICTION_THRESHOLD"
                                            r".*slave node \d+ has 0"):
        _frictional_patch(csma_cases, {"contact_type": "Frictional", "frictional_law": "Tresca"}, mu=0.2)


@needs_bindings
@pytest.mark.parametrize("frequency,contact_type,cleared", [
    (1, "Frictional", [True, True, True]),
    (2, "Frictional", [False, True, False]),
    (0, "Frictional", [False, False, False]),
    (1, "FrictionalPureSlip", [False, False, False]),
])
def test_slip_flags_reset(csma_cases, frequency, contact_type, cleared):
    """slip_step_reset_frequency: every N steps the interface nodes start the step sticking (spec 4.4);
    never with 0, nor in pure slip."""
    process, root = _frictional_patch(csma_cases, {"contact_type": contact_type,
                                                   "slip_step_reset_frequency": frequency}, mu=0.2)
    contact = root.GetSubModelPart("Contact")
    for expected in cleared:
        for node in contact.Nodes:
            node.Set(_core.SLIP, True)
        process._reset_slip_flags()
        assert not contact.GetNodalFlags(_core.SLIP).any() if expected else contact.GetNodalFlags(_core.SLIP).all()


def test_frictional_solver_keeps_three_steps_of_history(csma_cases, monkeypatch):
    """Friction measures the slip from the last converged step: buffer_size is raised to 3 (spec 2.10;
    Kratos' own rule is inverted, trap 6)."""
    monkeypatch.chdir(csma_cases)
    settings = read_project_parameters(os.path.join(
        csma_cases, "ALM_frictional_contact_test_2D", "hyper_simple_patch_test_parameters.json"))["solver_settings"]
    settings["buffer_size"].SetInt(2)
    solver = create_solver(_core.Model(), settings)
    solver.ImportModelPart()
    assert solver.main_model_part.GetBufferSize() == 3


def test_interfaces_without_friction_run_the_pure_slip_variant(csma_cases, monkeypatch):
    """A frictional case whose interface nodes all have mu = 0 runs the pure-slip formulation (its
    active-set criterion never lets a node stick), as Kratos' solver decides."""
    monkeypatch.chdir(csma_cases)
    settings = read_project_parameters(os.path.join(
        csma_cases, "ALM_frictional_contact_test_2D", "hyper_simple_patch_test_parameters.json"))["solver_settings"]
    solver = create_solver(_core.Model(), settings)
    solver.ImportModelPart()
    contact = solver.main_model_part.CreateSubModelPart("Contact")
    contact.AddNodes([3, 4, 5, 6])
    for node in contact.Nodes:
        node.SetValue(_core.FRICTION_COEFFICIENT, 0.0)
    assert solver._formulation_of_run().mortar_type == "ALMContactFrictionalPureSlip"
    contact.GetNode(4).SetValue(_core.FRICTION_COEFFICIENT, 0.2)
    assert solver._formulation_of_run().mortar_type == "ALMContactFrictional"
