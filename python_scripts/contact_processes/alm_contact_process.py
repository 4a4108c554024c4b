"""``alm_contact_process``: augmented Lagrangian mortar contact (spec 4.4)."""
from __future__ import annotations

from .. import _core
from ..utilities import warn_about_keys_without_effect
from .search_base_process import SearchBaseProcess

#: normal_variation -> ProcessInfo CONSIDER_NORMAL_VARIATION (spec 4.4)
NORMAL_VARIATIONS = {
    "no_derivatives_computation": 0,
    "elemental_derivatives": 1,
    "nodal_elemental_derivatives": 2,
    "no_derivatives_computation_with_normal_update": 3,
}
NORMAL_UPDATE = "WithNormalUpdate"
#: The values whose tangent includes dn/du: the NV conditions. Kratos' "elemental_derivatives"
#: linearises only each face's own normal, an approximate tangent of the same residual (the
#: normals follow the mesh in every mode); the NV conditions differentiate the averaged nodal
#: normals exactly, so they serve both and Newton keeps its quadratic rate.
NORMAL_DERIVATIVES = ("elemental_derivatives", "nodal_elemental_derivatives")
_FRICTIONAL = "only the frictional formulations read it, and they are not implemented"
_EXPLICIT = "only the explicit penalty process reads it, and it is not implemented"
#: Keys accepted without effect (issue 18): (sub-block or "", key) -> why; warned when given a value
#: other than the default (NoEffectWarnings).
KEYS_WITHOUT_EFFECT = {
    ("", "friction_coefficients"): "FRICTION_COEFFICIENT goes to the pair properties, but " + _FRICTIONAL,
    ("", "not_normal_update_frictional"): _FRICTIONAL,
    ("", "frictional_law"): _FRICTIONAL,
    ("", "tangent_factor"): _FRICTIONAL,
    ("", "operator_threshold"): _FRICTIONAL,
    ("", "slip_augmentation_coefficient"): _FRICTIONAL,
    ("", "slip_threshold"): _FRICTIONAL,
    ("", "slip_step_reset_frequency"): _FRICTIONAL,
    ("advance_ALM_parameters", "max_gap_factor"): "only the adaptive penalty (adapt_penalty) reads it, "
                                                  "which is not implemented",
    **{("advance_explicit_parameters", key): _EXPLICIT
       for key in ("manual_max_gap_theshold", "automatic_gap_factor", "max_gap_threshold", "max_gap_factor",
                   "logistic_exponent_factor")},
}


class ALMContactProcess(SearchBaseProcess):
    """Builds the contact interfaces and searches, computes the ALM penalty and scale factor,
    and runs the search each ``database_step_update`` steps inside ``interval``."""

    python_module = "alm_contact_process"
    penalty_multiplier = 1.0
    penalty_floor = 1.0

    def _check_types(self) -> None:
        contact_type = self.settings["contact_type"]
        # Kratos' "<type>WithNormalUpdate" asks for the normal update of
        # no_derivatives_computation_with_normal_update; the formulation is <type>'s.
        name = contact_type.GetString()
        self.normal_update = name.endswith(NORMAL_UPDATE)
        base = name[:-len(NORMAL_UPDATE)] if self.normal_update else name
        self.formulation = _core.ContactFormulation.OfProcess(
            self.python_module, base, f"{self.python_module}: {contact_type.Where()} '{name}'")
        variation = self.settings["normal_variation"].GetString().lower()
        if variation not in NORMAL_VARIATIONS:
            from ..utilities import nearest
            raise _core.InputError(f"{self.settings['normal_variation'].Where()}: unknown value '{variation}'"
                                   f"{nearest(variation, NORMAL_VARIATIONS)}")
        if self.normal_update and variation == "no_derivatives_computation":
            variation = "no_derivatives_computation_with_normal_update"
        self.normal_variation = variation
        self.axisymmetric = self.settings["alternative_formulations"]["axisymmetric"].GetBool()
        self.condition_stem = self.formulation.ConditionStem(variation in NORMAL_DERIVATIVES, self.axisymmetric)
        warn_about_keys_without_effect(self.settings, self.GetDefaultParameters(), KEYS_WITHOUT_EFFECT)
        if self.settings["advance_ALM_parameters"]["adapt_penalty"].GetBool():
            raise _core.NotImplementedFeatureError(
                f"{self.settings['advance_ALM_parameters'].Where()}.adapt_penalty: the adaptive penalty is not "
                "implemented yet")

    def check_solver_variables(self) -> None:
        """The solver registers its formulation before the mesh is read (spec 2.10): the process's
        must be the same. Axisymmetry needs a 2D model."""
        info = self.root.GetProcessInfo()
        if self.axisymmetric and info.GetValue(_core.DOMAIN_SIZE) != 2:
            raise _core.InputError(f"{self.settings['alternative_formulations'].Where()}.axisymmetric: true needs "
                                   f"domain_size 2 (x = radius, y = axis), got {info.GetValue(_core.DOMAIN_SIZE)}")
        solver = info.GetValue(_core.MORTAR_TYPE)
        if solver != self.formulation.mortar_type:
            found = f"\"{solver}\"" if solver else "none (a solver without contact_settings)"
            raise _core.InputError(
                f"{self.python_module} with contact_type '{self.settings['contact_type'].GetString()}' needs "
                f"solver_settings.contact_settings.mortar_type \"{self.formulation.mortar_type}\"; found {found}")

    def ExecuteInitialize(self) -> None:
        super().ExecuteInitialize()
        info = self.root.GetProcessInfo()
        info.SetValue(_core.CONSIDER_NORMAL_VARIATION, NORMAL_VARIATIONS[self.normal_variation])
        info.SetValue(_core.ACTIVE_SET_CONVERGED, True)
        info.SetValue(_core.TANGENT_FACTOR, self.settings["tangent_factor"].GetDouble())
        info.SetValue(_core.SLIP_THRESHOLD, self.settings["slip_threshold"].GetDouble())
        info.SetValue(_core.SLIP_AUGMENTATION_COEFFICIENT, self.settings["slip_augmentation_coefficient"].GetDouble())
        info.SetValue(_core.OPERATOR_THRESHOLD, self.settings["operator_threshold"].GetDouble())
        alm = self.settings["advance_ALM_parameters"]
        info.SetValue(_core.ADAPT_PENALTY, alm["adapt_penalty"].GetBool())
        info.SetValue(_core.MAX_GAP_FACTOR, alm["max_gap_factor"].GetDouble())
        for name in ("ComputingContact", "Contact"):
            self.root.GetSubModelPart(name).Set(_core.CONTACT, True)
        if alm["manual_ALM"].GetBool():
            info.SetValue(_core.INITIAL_PENALTY, alm["penalty"].GetDouble())
            info.SetValue(_core.SCALE_FACTOR, alm["scale_factor"].GetDouble())
        else:
            _core.ALMVariablesCalculationProcess(self.root, self.root.GetSubModelPart("Contact"), alm,
                                                 penalty_multiplier=self.penalty_multiplier,
                                                 penalty_floor=self.penalty_floor).Execute()
