"""Issue 3 (contact criteria factory, spec 3.2 and 2.9): every row of the composition table,
the tolerance source of each block, case-insensitive names, unsupported names and formulations,
and the contact strategy assembly. The composition rules run against a recording stand-in of
the extension; the tolerances each recorded criterion would read, and one whole composition, are
checked on the real objects."""
from __future__ import annotations

import importlib
import json
import os
import sys
import types

import pytest

import mortarcontact as mc

SOURCE = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "python_scripts"))


def _load_from_source():
    """The contact_strategies subpackage from the source tree, without importing the extension."""
    if "_mc_src" not in sys.modules:
        package = types.ModuleType("_mc_src")
        package.__path__ = [SOURCE]
        sys.modules["_mc_src"] = package
    return importlib.import_module("_mc_src.contact_strategies")


cs = _load_from_source()


# -- a recording stand-in of mortarcontact._core -------------------------------------------------
class InputError(Exception):
    pass


class NotImplementedFeatureError(Exception):
    pass


class FakeParameters:
    """The part of mortarcontact.Parameters the factories use, over a dict."""

    def __init__(self, text="{}"):
        self.data = json.loads(text) if isinstance(text, str) else text

    def __getitem__(self, key):
        value = self.data[key]
        return FakeParameters(value) if isinstance(value, dict) else _Leaf(value)

    def Has(self, key):
        return key in self.data


class _Leaf:
    def __init__(self, value):
        self.value = value

    def GetString(self):
        assert isinstance(self.value, str)
        return self.value

    def GetBool(self):
        assert isinstance(self.value, bool)
        return self.value

    def GetDouble(self):
        return float(self.value)

    def GetInt(self):
        return int(self.value)


class Recorded:
    def __init__(self, *args, **kwargs):
        self.args = args
        self.kwargs = kwargs
        self.updater = None
        self.echo = None
        self.callbacks = None

    def settings(self):
        return self.args[0].data if self.args else {}

    def SetMortarUpdater(self, updater):
        self.updater = updater

    def SetEchoLevel(self, level):
        self.echo = level

    def SetSubStepCallbacks(self, initialize, finalize):
        self.callbacks = (initialize, finalize)


def _fake_core():
    core = types.SimpleNamespace(InputError=InputError, NotImplementedFeatureError=NotImplementedFeatureError,
                                 Parameters=FakeParameters, INTERACTION="INTERACTION")
    for name in ("DisplacementContactCriteria", "DisplacementResidualContactCriteria",
                 "DisplacementLagrangeMultiplierContactCriteria",
                 "DisplacementLagrangeMultiplierResidualContactCriteria",
                 "DisplacementLagrangeMultiplierMixedContactCriteria",
                 "DisplacementLagrangeMultiplierFrictionalContactCriteria",
                 "DisplacementLagrangeMultiplierResidualFrictionalContactCriteria",
                 "DisplacementLagrangeMultiplierMixedFrictionalContactCriteria",
                 "ALMFrictionlessMortarConvergenceCriteria", "ALMFrictionlessComponentsMortarConvergenceCriteria",
                 "PenaltyFrictionlessMortarConvergenceCriteria",
                 "MeshTyingMortarConvergenceCriteria", "MortarAndConvergenceCriteria", "AndCriteria", "OrCriteria",
                 "DisplacementCriteria", "ResidualCriteria", "BlockBuilderAndSolver", "EliminationBuilderAndSolver",
                 "LinearStrategy", "ResidualBasedNewtonRaphsonContactStrategy", "LineSearchContactStrategy"):
        setattr(core, name, type(name, (Recorded,), {}))
    core.ALMFrictionalMortarConvergenceCriteria = type(
        "ALMFrictionalMortarConvergenceCriteria", (Recorded,),
        {"PureSlip": lambda self: self.kwargs.get("pure_slip", False)})
    return core


core = _fake_core()


def settings(criterion="contact_mixed_criterion", mortar_type="ALMContactFrictionless", **contact):
    """solver_settings with distinct tolerances so that each block's source is visible."""
    base_contact = {
        "mortar_type": mortar_type, "condn_convergence_criterion": False, "fancy_convergence_criterion": True,
        "print_convergence_criterion": False, "ensure_contact": False, "frictional_decomposed": True,
        "compute_dynamic_factor": False, "gidio_debug": False, "simplified_semi_smooth_newton": False,
        "adaptative_strategy": False, "split_factor": 10.0, "max_number_splits": 3, "inner_loop_iterations": 5,
        "rotation_relative_tolerance": 3e-4, "rotation_absolute_tolerance": 3e-9,
        "rotation_residual_relative_tolerance": 4e-4, "rotation_residual_absolute_tolerance": 4e-9,
        "contact_displacement_relative_tolerance": 5e-4, "contact_displacement_absolute_tolerance": 5e-9,
        "contact_residual_relative_tolerance": 6e-4, "contact_residual_absolute_tolerance": 6e-9,
        "frictional_stick_contact_displacement_relative_tolerance": 7e-4,
        "frictional_stick_contact_displacement_absolute_tolerance": 7e-9,
        "frictional_stick_contact_residual_relative_tolerance": 8e-4,
        "frictional_stick_contact_residual_absolute_tolerance": 8e-9,
        "frictional_slip_contact_displacement_relative_tolerance": 9e-4,
        "frictional_slip_contact_displacement_absolute_tolerance": 9e-9,
        "frictional_slip_contact_residual_relative_tolerance": 1.1e-3,
        "frictional_slip_contact_residual_absolute_tolerance": 1.1e-8,
        "ratio_normal_tangent_threshold": 0.5}
    base_contact.update(contact)
    return FakeParameters({
        "convergence_criterion": criterion, "contact_settings": base_contact,
        "displacement_relative_tolerance": 1e-4, "displacement_absolute_tolerance": 1e-9,
        "residual_relative_tolerance": 2e-4, "residual_absolute_tolerance": 2e-9,
        "builder_and_solver_settings": {"type": "block"}, "solving_strategy_settings": {"type": "newton_raphson"},
        "analysis_type": "non_linear", "compute_reactions": True, "move_mesh_flag": True, "max_iteration": 15})


# {family: (measure, relative, absolute)} as BlockContactCriteria.Tolerances() gives them
DISP_INC = {"displacement": ("increment", 1e-4, 1e-9)}
DISP_RES = {"displacement": ("residual", 2e-4, 2e-9)}
ROT_INC = {"rotation": ("increment", 3e-4, 3e-9)}
ROT_RES = {"rotation": ("residual", 4e-4, 4e-9)}
LM_INC = {"multiplier": ("increment", 5e-4, 5e-9)}
LM_RES = {"multiplier": ("residual", 6e-4, 6e-9)}
STICK_INC = {"stick": ("increment", 7e-4, 7e-9)}
STICK_RES = {"stick": ("residual", 8e-4, 8e-9)}
SLIP_INC = {"slip": ("increment", 9e-4, 9e-9)}
SLIP_RES = {"slip": ("residual", 1.1e-3, 1.1e-8)}
# Kratos' mixed frictional criterion: increments, with the residual absolute tolerances.
STICK_MIXED = {"stick": ("increment", 7e-4, 8e-9)}
SLIP_MIXED = {"slip": ("increment", 9e-4, 1.1e-8)}


#: what the tests need of the registered formulations (ContactFormulation): multiplier blocks and
#: active-set criterion (the registry itself is tested in test_contact_formulations.py).
FORMULATIONS = {
    "ALMContactFrictionless": (1, "ALMFrictionlessMortarConvergenceCriteria"),
    "ALMContactFrictionlessComponents": (1, "ALMFrictionlessComponentsMortarConvergenceCriteria"),
    "ComponentsMeshTying": (1, "MeshTyingMortarConvergenceCriteria"),
    "ScalarMeshTying": (1, "MeshTyingMortarConvergenceCriteria"),
    "PenaltyContactFrictionless": (0, "PenaltyFrictionlessMortarConvergenceCriteria"),
    # multiplier_blocks = 3 is what the frictional ALM entries of the registry declare.
    "ALMContactFrictional": (3, "ALMFrictionalMortarConvergenceCriteria"),
    "ALMContactFrictionalPureSlip": (3, "ALMFrictionalMortarConvergenceCriteria"),
}


class FakeFormulation:
    def __init__(self, mortar_type):
        self.multiplier_blocks, self.criterion = FORMULATIONS[mortar_type]
        self.pure_slip = mortar_type.endswith("PureSlip")

    def CreateActiveSetCriterion(self, contact_settings):
        if self.multiplier_blocks == 3:
            return getattr(core, self.criterion)(contact_settings, pure_slip=self.pure_slip)
        return getattr(core, self.criterion)(contact_settings)


def build(*args, **kwargs):
    s = settings(*args, **kwargs)
    formulation = FakeFormulation(s["contact_settings"]["mortar_type"].GetString())
    return cs.create_contact_convergence_criteria(s, formulation, echo_level=2, core=core)


def expect(criterion, cls, tolerances):
    """``criterion`` is a ``cls`` given solver_settings and its contact_settings, and the real
    ``cls`` reads ``tolerances`` from them (each block from its source)."""
    assert type(criterion).__name__ == cls
    solver_settings, contact_settings = criterion.args
    assert contact_settings.data is solver_settings.data["contact_settings"]
    real_settings = mc.Parameters(json.dumps(solver_settings.data))
    real = getattr(mc._core, cls)(real_settings, real_settings["contact_settings"], **criterion.kwargs)
    assert real.Tolerances() == tolerances
    return real


# -- table rows: "otherwise" column (ALM scalar / components, mesh tying) -----------------------
@pytest.mark.parametrize("mortar_type, mortar", [
    ("ALMContactFrictionless", "ALMFrictionlessMortarConvergenceCriteria"),
    ("ALMContactFrictionlessComponents", "ALMFrictionlessComponentsMortarConvergenceCriteria"),
    ("ComponentsMeshTying", "MeshTyingMortarConvergenceCriteria"),
])
def test_multiplier_rows(mortar_type, mortar):
    c = build("contact_displacement_criterion", mortar_type)
    assert type(c).__name__ == "MortarAndConvergenceCriteria"
    assert type(c.args[1]).__name__ == mortar
    assert c.kwargs == {"print_convergence_criterion": False, "condition_number": False, "print_table": True}
    assert c.echo == 2
    expect(c.args[0], "DisplacementLagrangeMultiplierContactCriteria", {**DISP_INC, **ROT_INC, **LM_INC})
    expect(build("contact_residual_criterion", mortar_type).args[0],
           "DisplacementLagrangeMultiplierResidualContactCriteria", {**DISP_RES, **ROT_RES, **LM_RES})
    # Mixed: residual for displacements, increment (contact_displacement_*) for multipliers.
    expect(build("contact_mixed_criterion", mortar_type).args[0],
           "DisplacementLagrangeMultiplierMixedContactCriteria", {**DISP_RES, **ROT_RES, **LM_INC})
    for name, combiner in (("contact_and_criterion", "AndCriteria"), ("contact_or_criterion", "OrCriteria")):
        combined = build(name, mortar_type).args[0]
        assert type(combined).__name__ == combiner
        expect(combined.args[0], "DisplacementLagrangeMultiplierResidualContactCriteria",
               {**DISP_RES, **ROT_RES, **LM_RES})
        expect(combined.args[1], "DisplacementLagrangeMultiplierContactCriteria", {**DISP_INC, **ROT_INC, **LM_INC})


def test_mortar_settings_come_from_contact_settings():
    c = build("contact_mixed_criterion", print_convergence_criterion=True, compute_dynamic_factor=True,
              condn_convergence_criterion=True, fancy_convergence_criterion=False)
    # The active-set criterion reads its keys from contact_settings itself.
    assert c.args[1].settings()["print_convergence_criterion"] is True
    assert c.args[1].settings()["compute_dynamic_factor"] is True
    assert c.kwargs == {"print_convergence_criterion": True, "condition_number": True, "print_table": False}
    assert c.args[0].args[1].data["print_convergence_criterion"] is True


# -- "ALMContactFrictional* and frictional_decomposed" column ------------------------------------
@pytest.mark.parametrize("mortar_type", ["ALMContactFrictional", "ALMContactFrictionalPureSlip"])
def test_frictional_rows(mortar_type):
    pure_slip = mortar_type.endswith("PureSlip")
    c = build("contact_displacement_criterion", mortar_type)
    assert type(c.args[1]).__name__ == "ALMFrictionalMortarConvergenceCriteria"
    assert c.args[1].PureSlip() is pure_slip
    assert c.args[0].kwargs == {"pure_slip": pure_slip}
    real = expect(c.args[0], "DisplacementLagrangeMultiplierFrictionalContactCriteria",
                  {**DISP_INC, **ROT_INC, **LM_INC, **STICK_INC, **SLIP_INC})
    assert real.PureSlip() is pure_slip
    assert real.RatioNormalTangentThreshold() == 0.5
    expect(build("contact_residual_criterion", mortar_type).args[0],
           "DisplacementLagrangeMultiplierResidualFrictionalContactCriteria",
           {**DISP_RES, **ROT_RES, **LM_RES, **STICK_RES, **SLIP_RES})
    expect(build("contact_mixed_criterion", mortar_type).args[0],
           "DisplacementLagrangeMultiplierMixedFrictionalContactCriteria",
           {**DISP_RES, **ROT_RES, **LM_INC, **STICK_MIXED, **SLIP_MIXED})
    # and / or keep one multiplier block, as in Kratos.
    combined = build("contact_and_criterion", mortar_type).args[0]
    expect(combined.args[0], "DisplacementLagrangeMultiplierResidualContactCriteria", {**DISP_RES, **ROT_RES, **LM_RES})
    expect(combined.args[1], "DisplacementLagrangeMultiplierContactCriteria", {**DISP_INC, **ROT_INC, **LM_INC})


def test_frictional_decomposed_false_keeps_one_multiplier_block():
    c = build("contact_mixed_criterion", "ALMContactFrictional", frictional_decomposed=False)
    expect(c.args[0], "DisplacementLagrangeMultiplierMixedContactCriteria", {**DISP_RES, **ROT_RES, **LM_INC})


def test_real_frictional_composition():
    """The real classes, with a stand-in for the frictional registry entry (friction-process
    registers the real one with multiplier_blocks = 3)."""
    class Frictional:
        multiplier_blocks = 3

        @staticmethod
        def CreateActiveSetCriterion(contact_settings):
            return mc._core.ALMFrictionalMortarConvergenceCriteria(contact_settings, pure_slip=True)

    s = mc.Parameters(json.dumps({**settings(mortar_type="ALMContactFrictionalPureSlip").data,
                                  "convergence_criterion": "contact_residual_criterion"}))
    c = cs.create_contact_convergence_criteria(s, Frictional(), core=mc._core)
    assert c.Mechanical().Name() == "displacement_lagrangemultiplier_ressidual_frictional_contact_criteria"
    assert c.Mechanical().PureSlip()
    assert c.Mortar().Name() == "alm_frictional_mortar_criteria"
    assert c.Mortar().HasSlipSet()


# -- "Penalty" column ------------------------------------------------------------------------------
def test_penalty_rows():
    p = "PenaltyContactFrictionless"
    c = build("contact_displacement_criterion", p)
    assert type(c.args[1]).__name__ == "PenaltyFrictionlessMortarConvergenceCriteria"
    expect(c.args[0], "DisplacementContactCriteria", {**DISP_INC, **ROT_INC})
    expect(build("contact_residual_criterion", p).args[0], "DisplacementResidualContactCriteria",
           {**DISP_RES, **ROT_RES})
    # Mixed reuses the residual criterion.
    expect(build("contact_mixed_criterion", p).args[0], "DisplacementResidualContactCriteria",
           {**DISP_RES, **ROT_RES})
    for name, combiner in (("contact_and_criterion", "AndCriteria"), ("contact_or_criterion", "OrCriteria")):
        combined = build(name, p).args[0]
        assert type(combined).__name__ == combiner
        expect(combined.args[0], "DisplacementResidualContactCriteria", {**DISP_RES, **ROT_RES})
        expect(combined.args[1], "DisplacementContactCriteria", {**DISP_INC, **ROT_INC})


# -- unsupported names -------------------------------------------------------------------------------
def test_adaptative_remesh_criteria_is_out_of_scope():
    with pytest.raises(NotImplementedFeatureError, match="adaptive remeshing"):
        build("adaptative_remesh_criteria")


def test_unknown_names_suggest_the_nearest():
    with pytest.raises(InputError, match="did you mean 'contact_mixed_criterion'"):
        build("contact_mixd_criterion")


def test_names_are_case_insensitive():
    c = build("Contact_Residual_criterion")
    assert type(c.args[0]).__name__ == "DisplacementLagrangeMultiplierResidualContactCriteria"
    assert type(build("Residual_criterion", "PenaltyContactFrictionless")).__name__ == "ResidualCriteria"


# -- "any other name" row ----------------------------------------------------------------------------
@pytest.mark.parametrize("mortar_type", ["ALMContactFrictionless", "ALMContactFrictionlessComponents",
                                         "ScalarMeshTying"])
def test_structural_names_are_anded_with_the_mortar_criterion(mortar_type):
    c = build("residual_criterion", mortar_type)
    assert type(c).__name__ == "MortarAndConvergenceCriteria"
    assert c.kwargs["print_table"] is False
    assert type(c.args[0]).__name__ == "ResidualCriteria" and c.args[0].args == (2e-4, 2e-9)
    combined = build("and_criterion", mortar_type).args[0]
    assert type(combined).__name__ == "AndCriteria"
    assert [type(x).__name__ for x in combined.args] == ["ResidualCriteria", "DisplacementCriteria"]
    assert combined.args[1].args == (1e-4, 1e-9)
    assert type(build("or_criterion", mortar_type).args[0]).__name__ == "OrCriteria"
    assert type(build("displacement_criterion", mortar_type).args[0]).__name__ == "DisplacementCriteria"


def test_structural_names_with_penalty_stay_structural():
    c = build("displacement_criterion", "PenaltyContactFrictionless")
    assert type(c).__name__ == "DisplacementCriteria"
    assert c.args == (1e-4, 1e-9)


def test_updater_reaches_the_composite():
    updater = object()
    c = cs.create_contact_convergence_criteria(settings(), FakeFormulation("ALMContactFrictionless"),
                                               mortar_updater=updater, core=core)
    assert c.updater is updater


# -- strategy (spec 2.9) -------------------------------------------------------------------------------
class FakeModelPart:
    def __init__(self):
        self.flags = {}

    def Set(self, flag, value):
        self.flags[flag] = value


def make_strategy(builder="block", kind="newton_raphson", analysis="non_linear", **contact):
    s = settings(**contact)
    s.data["builder_and_solver_settings"]["type"] = builder
    s.data["solving_strategy_settings"]["type"] = kind
    s.data["analysis_type"] = analysis
    part = FakeModelPart()
    strategy = cs.create_contact_strategy(part, s, "scheme", "solver", "criteria", echo_level=1,
                                          mortar_updater="updater", initialize_sub_step=print, core=core)
    return part, strategy


def test_strategy_newton_and_its_settings():
    part, strategy = make_strategy(adaptative_strategy=True, split_factor=4.0, max_number_splits=2,
                                   inner_loop_iterations=7)
    assert type(strategy).__name__ == "ResidualBasedNewtonRaphsonContactStrategy"
    assert part.flags == {"INTERACTION": True}
    assert strategy.args[:2] == (part, "scheme") and strategy.args[2] == "criteria"
    assert type(strategy.args[3]).__name__ == "BlockBuilderAndSolver"
    contact = strategy.kwargs["settings"].data  # the strategy reads its keys from contact_settings
    assert {k: contact[k] for k in ("adaptative_strategy", "split_factor", "max_number_splits",
                                    "inner_loop_iterations")} == {"adaptative_strategy": True, "split_factor": 4.0,
                                                                  "max_number_splits": 2, "inner_loop_iterations": 7}
    assert strategy.kwargs["max_iteration"] == 15
    assert strategy.kwargs["reform_dofs_at_each_step"] is True
    assert strategy.updater == "updater" and strategy.callbacks == (print, None)


@pytest.mark.parametrize("builder", ["elimination", "block_lagrange"])
def test_strategy_non_block_builders_eliminate(builder):
    _, strategy = make_strategy(builder=builder)
    assert type(strategy.args[3]).__name__ == "EliminationBuilderAndSolver"


def test_strategy_line_search_simplified_and_linear():
    part, strategy = make_strategy(kind="line_search", simplified_semi_smooth_newton=True)
    assert type(strategy).__name__ == "LineSearchContactStrategy"
    assert part.flags == {"INTERACTION": False}
    _, linear = make_strategy(analysis="linear")
    assert type(linear).__name__ == "LinearStrategy"
    with pytest.raises(NotImplementedFeatureError):
        make_strategy(kind="arc_length")


# -- with the real extension -------------------------------------------------------------------------
def test_real_objects():
    s = mc.Parameters(json.dumps({**settings().data, "convergence_criterion": "contact_mixed_criterion"}))
    c = cs.create_contact_convergence_criteria(s, mc._core.ContactFormulation.Get("ALMContactFrictionless"),
                                               core=mc._core)
    assert c.Name() == "mortar_and_criteria"
    assert c.Mechanical().Name() == "displacement_lagrange_multiplier_mixed_contact_criteria"
    assert c.Mortar().Name() == "alm_frictionless_mortar_criteria"


def test_legacy_single_friction_block_feeds_stick_and_slip():
    """Spec 2.7: the frictional_contact_* keys of older CSMA versions are copied to the stick and
    the slip keys, which the frictional block criteria then read."""
    from mortarcontact.solvers.solver_settings import validate_solver_settings

    s = mc.Parameters(json.dumps({"model_part_name": "Structure", "domain_size": 2, "contact_settings": {
        "mortar_type": "ALMContactFrictional", "frictional_contact_residual_absolute_tolerance": 3e-7,
        "frictional_contact_residual_relative_tolerance": 2e-3}}))
    validate_solver_settings(s)
    contact = s["contact_settings"]
    assert not contact.Has("frictional_contact_residual_absolute_tolerance")
    real = mc._core.DisplacementLagrangeMultiplierResidualFrictionalContactCriteria(s, contact)
    assert real.Tolerances()["stick"] == ("residual", 2e-3, 3e-7)
    assert real.Tolerances()["slip"] == ("residual", 2e-3, 3e-7)
