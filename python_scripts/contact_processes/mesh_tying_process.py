"""``mesh_tying_process``: dual-mortar tying of a nodal variable across non-matching interface
meshes (spec 4.8). The interfaces and their searches are those of the contact processes; the
pairs are ``MeshTyingMortarCondition<geometry>`` and tie ``variable_name``: an array variable
(DISPLACEMENT) component by component with VECTOR_LAGRANGE_MULTIPLIER (``ComponentsMeshTying``),
a scalar one (TEMPERATURE) with SCALAR_LAGRANGE_MULTIPLIER (``ScalarMeshTying``)."""
from __future__ import annotations

from .. import _core
from ..utilities import warn_about_keys_without_effect
from . import _settings
from .search_base_process import SearchBaseProcess

#: variable_name's value type -> the formulation's contact_type in the registry
TYING_KINDS = {_core.ValueType.Array3: "Components", _core.ValueType.Double: "Scalar"}

#: Keys accepted without effect (issue 18): (sub-block or "", key) -> why.
KEYS_WITHOUT_EFFECT = {
    # Kratos' default is true here (false for contact). The tied D and M do not depend on how a
    # clipped polygon is cut on a flat interface; the fan is used either way.
    ("", "consider_tessellation"): "the clipped polygons of the tied pairs are cut as a fan either way",
    # Kratos condenses inside the conditions with their parent elements; here the MixedULM solver
    # condenses the multipliers of the components tie (contact_settings.use_mixed_ulm_solver).
    ("", "consider_static_condensation"): "the multipliers of ComponentsMeshTying are condensed by the MixedULM "
                                          "solver (contact_settings.use_mixed_ulm_solver) whatever its value",
}


class MeshTyingProcess(SearchBaseProcess):
    """Builds the tied interfaces and their searches (once: ``database_step_update`` is 999999999),
    sets TYING_VARIABLE on the pair properties and the scale factor of the multipliers."""

    python_module = "mesh_tying_process"
    pair_prefix = "mesh_tying"
    condition_stem = "MeshTyingMortarCondition"

    @classmethod
    def GetDefaultParameters(cls) -> _core.Parameters:
        search = _settings.search_defaults()
        search["database_step_update"] = 999999999
        del search["octree_search_parameters"]["build_from_bounding_box"]
        for key in ("simple_search", "adapt_search", "static_check_movement", "normal_orientation_threshold",
                    "consider_gap_threshold", "predict_correct_lagrange_multiplier"):
            del search[key]
        return _settings.to_parameters({
            **_settings.IGNORED_KEYS,
            "model_part_name": "Structure",
            **_settings.pair_defaults("mesh_tying"),
            "interval": [0.0, "End"],
            "variable_name": "DISPLACEMENT",
            "consider_static_condensation": False,
            "zero_tolerance_factor": 1.0,
            "integration_order": 2,
            "consider_tessellation": True,
            "normal_check_proportion": 0.1,
            "search_parameters": search,
            "scale_factor_parameters": {"manual_scale_factor": False, "stiffness_factor": 1.0, "scale_factor": 1.0},
        })

    def __init__(self, model, settings=None):
        settings = settings if settings is not None else _core.Parameters()
        keys = (f"{self.pair_prefix}_model_part", "assume_master_slave", f"{self.pair_prefix}_property_ids")
        _settings.normalise_pair_layouts(settings, keys)
        defaults = self.GetDefaultParameters()
        # Non-recursive at the top (spec 4.8): a partial search_parameters is completed from the
        # base search defaults, not from the tying ones (so database_step_update becomes 1).
        user_search = settings.Has("search_parameters")
        settings.ValidateAndAssignDefaults(defaults)
        if user_search:
            settings["search_parameters"].RecursivelyValidateAndAssignDefaults(
                _core.ContactSearchProcess.GetDefaultParameters())
        for key in (*keys, "scale_factor_parameters"):
            settings[key].ValidateAndAssignDefaults(defaults[key])
        self.model = model
        self.settings = settings
        self.interval = _settings.interval_of(settings)
        self._init_search_state()
        self._check_factors()
        self.variable = self._tied_variable()
        self.formulation = _core.ContactFormulation.OfProcess(
            self.python_module, TYING_KINDS[self.variable.Type()],
            f"{self.python_module}: {settings['variable_name'].Where()} '{self.variable.Name()}'")
        warn_about_keys_without_effect(settings, defaults, KEYS_WITHOUT_EFFECT)
        scale = settings["scale_factor_parameters"]
        for key in ("stiffness_factor", "scale_factor"):
            if not 0.0 < scale[key].GetDouble() < float("inf"):
                raise _core.InputError(f"{scale.Where()}.{key}: must be a positive number, got "
                                       f"{scale[key].GetDouble()!r}")

    def _tied_variable(self):
        value = self.settings["variable_name"]
        variable = _core.GetVariable(value.GetString())  # InputError with the nearest names
        if variable.Type() not in TYING_KINDS:
            raise _core.InputError(f"{value.Where()}: '{value.GetString()}' is a {variable.Type().name} variable; "
                                   "mesh tying ties a scalar (e.g. TEMPERATURE) or an array (e.g. DISPLACEMENT)")
        return variable

    def check_solver_variables(self) -> None:
        """The solver's mortar_type must be the tying of this variable's kind."""
        self._check_mortar_type(f"variable_name '{self.variable.Name()}'")

    def ExecuteInitialize(self) -> None:
        super().ExecuteInitialize()
        self._check_dofs()
        name = self.variable.Name()
        for slot, *_ in self.interface_slots():
            _core.ContactInterfaceBuilder.InterfaceProperties(self.root, slot).SetValue(_core.TYING_VARIABLE, name)
        info = self.root.GetProcessInfo()
        scale = self.settings["scale_factor_parameters"]
        if scale["manual_scale_factor"].GetBool():
            info.SetValue(_core.SCALE_FACTOR, scale["scale_factor"].GetDouble())
        else:
            # stiffness_factor * E / h of the softer side (spec 4.8), as the ALM scale factor.
            automatic = _core.Parameters(f'{{"stiffness_factor": {scale["stiffness_factor"].GetDouble()!r}}}')
            _core.ALMVariablesCalculationProcess(self.root, self.root.GetSubModelPart("Contact"), automatic).Execute()

    def _check_dofs(self) -> None:
        """The tied variable must be an unknown of the analysis on the interface: tying a variable
        that nothing solves for would leave its multipliers without equations."""
        name = self.variable.Name()
        components = [f"{name}_{axis}" for axis in "XYZ"[:self.root.GetProcessInfo().GetValue(_core.DOMAIN_SIZE)]] \
            if self.variable.Type() == _core.ValueType.Array3 else [name]
        for node in self.root.GetSubModelPart("Contact").Nodes:
            for component in components:
                if not node.HasDofFor(_core.GetVariable(component)):
                    raise _core.InputError(
                        f"{self.settings['variable_name'].Where()}: '{name}' is not an unknown of this analysis "
                        f"(interface node {node.Id} has no DoF {component}): nothing solves for it")

    def ExecuteInitializeSolutionStep(self) -> None:
        super().ExecuteInitializeSolutionStep()
        if self._inside:
            # After the constraints processes (their list runs first) have set the step's fixities.
            _core.MeshTyingUtilities.UpdateTiedSlaveNodes(self.root.GetSubModelPart("ComputingContact"))

    def ExecuteFinalizeSolutionStep(self) -> None:
        """No contact outputs: a tie has no gap, pressure or active set."""
