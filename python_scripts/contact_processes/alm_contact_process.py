"""``alm_contact_process``: augmented Lagrangian mortar contact (spec 4.4)."""
from __future__ import annotations

import math
import sys

from .. import _core
from ..utilities import nearest, warn_about_keys_without_effect
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
#: normals follow the mesh in every mode, and the residual uses the averaged nodal ones); the NV
#: conditions differentiate the averaged nodal normals exactly, at the same assembly cost, so
#: they serve both, Newton keeps its quadratic rate, and "elemental_derivatives" warns that it
#: runs as "nodal_elemental_derivatives" (issue 18).
NORMAL_DERIVATIVES = ("elemental_derivatives", "nodal_elemental_derivatives")
ELEMENTAL_DERIVATIVES_RUN_AS_NODAL = (
    "it runs as \"nodal_elemental_derivatives\": the derivative of each face's own normal is an approximate "
    "tangent of a residual built on the averaged nodal normals; the exact derivative of those costs the same and "
    "keeps Newton quadratic")
_FRICTIONAL = "only the frictional formulations (contact_type Frictional*) read it"
_EXPLICIT = ("Kratos' explicit process feeds it (MAX_GAP_THRESHOLD) to its dynamic factor only; the explicit "
             "contact here applies the full penalty force at every step")
#: Read by the frictional formulations only: without effect on the frictionless ones.
FRICTIONAL_KEYS_WITHOUT_EFFECT = {
    ("", "friction_coefficients"): "FRICTION_COEFFICIENT goes to the pair properties, but " + _FRICTIONAL,
    ("", "not_normal_update_frictional"): _FRICTIONAL,
    ("", "frictional_law"): _FRICTIONAL,
    ("", "tangent_factor"): _FRICTIONAL,
    ("", "slip_augmentation_coefficient"): _FRICTIONAL,
    ("", "slip_threshold"): _FRICTIONAL,
    ("", "slip_step_reset_frequency"): _FRICTIONAL,
}
#: Keys accepted without effect (issue 18): (sub-block or "", key) -> why; warned when given a value
#: other than the default (NoEffectWarnings).
KEYS_WITHOUT_EFFECT = {
    ("", "operator_threshold"): "no condition reads it: the frictional conditions always take the mortar operators "
                                "of the last converged step as the previous ones",
    **{("advance_explicit_parameters", key): _EXPLICIT
       for key in ("manual_max_gap_theshold", "automatic_gap_factor", "max_gap_threshold", "max_gap_factor",
                   "logistic_exponent_factor")},
}
#: Kratos' frictional laws: Coulomb (the bound of the tangent traction is mu times the normal
#: pressure, FRICTION_COEFFICIENT) and Tresca (a constant bound, TRESCA_FRICTION_THRESHOLD in the
#: materials, whatever the pressure; Kratos 10.4 has it as work in progress only).
FRICTIONAL_LAWS = ("Coulomb", "Tresca")


def is_pure_slip(formulation, contact_part) -> bool:
    """Kratos' pure-slip detection (spec 4.4): the ``PureSlip`` formulations, or a frictional one
    whose interface nodes (``contact_part``, built) all have a zero FRICTION_COEFFICIENT and no
    Tresca threshold: nothing can stick."""
    if not formulation.frictional:
        return False
    if formulation.pure_slip:
        return True
    bounds = (contact_part.GetNodalNonHistoricalValues(_core.FRICTION_COEFFICIENT) +
              contact_part.GetNodalNonHistoricalValues(_core.TRESCA_FRICTION_THRESHOLD))
    return bool((bounds < sys.float_info.epsilon).all())


class ALMContactProcess(SearchBaseProcess):
    """Builds the contact interfaces and searches, computes the ALM penalty and scale factor,
    and runs the search each ``database_step_update`` steps inside ``interval``."""

    python_module = "alm_contact_process"
    #: the process the formulations are registered under, when not python_module
    formulation_process = None
    penalty_multiplier = 1.0
    penalty_floor = 1.0
    pure_slip = False  # decided at ExecuteInitialize, once the interface coefficients are known
    _steps_since_slip_reset = 0

    def _check_types(self) -> None:
        contact_type = self.settings["contact_type"]
        # Kratos' "<type>WithNormalUpdate" asks for the normal update of
        # no_derivatives_computation_with_normal_update; the formulation is <type>'s. Frictional
        # types have it unless not_normal_update_frictional.
        name = contact_type.GetString()
        self.normal_update = name.endswith(NORMAL_UPDATE)
        base = name[:-len(NORMAL_UPDATE)] if self.normal_update else name
        self.formulation = _core.ContactFormulation.OfProcess(
            self.formulation_process or self.python_module, base,
            f"{self.python_module}: {contact_type.Where()} '{name}'")
        self.frictional = self.formulation.frictional
        if self.frictional and not self.settings["not_normal_update_frictional"].GetBool():
            self.normal_update = True
        variation = self.settings["normal_variation"].GetString().lower()
        if variation not in NORMAL_VARIATIONS:
            raise _core.InputError(f"{self.settings['normal_variation'].Where()}: unknown value '{variation}'"
                                   f"{nearest(variation, NORMAL_VARIATIONS)}")
        if self.normal_update and variation == "no_derivatives_computation":
            variation = "no_derivatives_computation_with_normal_update"
        self.normal_variation = variation
        if variation == "elemental_derivatives":
            _core.NoEffectWarnings.Warn(self.settings, "normal_variation", ELEMENTAL_DERIVATIVES_RUN_AS_NODAL)
        self.axisymmetric = self.settings["alternative_formulations"]["axisymmetric"].GetBool()
        self.condition_stem = self.formulation.ConditionStem(variation in NORMAL_DERIVATIVES, self.axisymmetric)
        without_effect = dict(KEYS_WITHOUT_EFFECT)
        if not self.frictional:
            without_effect.update(FRICTIONAL_KEYS_WITHOUT_EFFECT)
        if not self.settings["advance_ALM_parameters"]["adapt_penalty"].GetBool():
            without_effect[("advance_ALM_parameters", "max_gap_factor")] = \
                "only the adaptive penalty reads it, and adapt_penalty is false"
        warn_about_keys_without_effect(self.settings, self.GetDefaultParameters(), without_effect)
        self._check_friction_settings()

    def _check_friction_settings(self) -> None:
        """The friction keys (spec 4.4), checked whatever the contact_type: a wrong value is wrong
        input even where it has no effect."""
        s = self.settings
        law = s["frictional_law"].GetString()
        if law not in FRICTIONAL_LAWS:
            raise _core.InputError(f"{s['frictional_law'].Where()}: unknown frictional law '{law}'"
                                   f"{nearest(law, FRICTIONAL_LAWS)} (valid: {', '.join(FRICTIONAL_LAWS)})")
        for key, low, high, closed in (("tangent_factor", 0.0, math.inf, False),
                                       ("slip_augmentation_coefficient", 0.0, math.inf, True),
                                       ("slip_threshold", 0.0, 1.0, True),
                                       ("operator_threshold", 0.0, math.inf, True)):
            _check_range(s[key], low, high, closed)
        mus = s["friction_coefficients"]
        for slot in mus.Keys():
            _check_range(mus[slot], 0.0, math.inf, True)
        reset = s["slip_step_reset_frequency"]
        if self.frictional and reset.GetInt() < 0:
            raise _core.NotImplementedFeatureError(
                f"{reset.Where()}: {reset.GetInt()} (slip direction from WEIGHTED_SLIP) is not implemented yet; "
                "use 0 (never reset the SLIP flags) or N > 0 (reset every N steps)")

    def check_solver_variables(self) -> None:
        """The solver's mortar_type must be this process's; axisymmetry needs a 2D model."""
        info = self.root.GetProcessInfo()
        if self.axisymmetric and info.GetValue(_core.DOMAIN_SIZE) != 2:
            raise _core.InputError(f"{self.settings['alternative_formulations'].Where()}.axisymmetric: true needs "
                                   f"domain_size 2 (x = radius, y = axis), got {info.GetValue(_core.DOMAIN_SIZE)}")
        self._check_mortar_type(f"contact_type '{self.settings['contact_type'].GetString()}'")

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
        # The conditions, criteria and strategy tell a frictional problem by the SLIP flag of the
        # model parts (as Kratos does).
        for part in (self.root, self.root.GetSubModelPart("Contact"), self.root.GetSubModelPart("ComputingContact")):
            part.Set(_core.CONTACT, True)
            part.Set(_core.SLIP, self.frictional)
        if self.frictional:
            self._apply_frictional_law()
        self.pure_slip = is_pure_slip(self.formulation, self.root.GetSubModelPart("Contact"))
        if self.frictional:
            zero = [0.0, 0.0, 0.0]
            for node in self.root.GetSubModelPart("Contact").Nodes:
                node.SetValue(_core.AUGMENTED_TANGENT_CONTACT_PRESSURE, zero)
        if alm["manual_ALM"].GetBool():
            info.SetValue(_core.INITIAL_PENALTY, alm["penalty"].GetDouble())
            info.SetValue(_core.SCALE_FACTOR, alm["scale_factor"].GetDouble())
        else:
            _core.ALMVariablesCalculationProcess(self.root, self.root.GetSubModelPart("Contact"), alm,
                                                 penalty_multiplier=self.penalty_multiplier,
                                                 penalty_floor=self.penalty_floor).Execute()

    def _apply_frictional_law(self) -> None:
        """One bound per node for the conditions and the active set: Coulomb's uses the nodal
        FRICTION_COEFFICIENT only (a threshold in the materials has no effect), Tresca's the nodal
        TRESCA_FRICTION_THRESHOLD only, which every slave node must have, from the materials of
        its interface."""
        law = self.settings["frictional_law"]
        tresca = law.GetString() == "Tresca"
        for node in self.root.GetSubModelPart("Contact").Nodes:
            if not tresca:
                node.SetValue(_core.TRESCA_FRICTION_THRESHOLD, 0.0)
                continue
            threshold = node.GetValue(_core.TRESCA_FRICTION_THRESHOLD)
            if node.Is(_core.SLAVE) and not threshold > 0.0:
                raise _core.InputError(
                    f"{law.Where()}: 'Tresca' needs a positive TRESCA_FRICTION_THRESHOLD in the materials of the "
                    f"contact parts; slave node {node.Id} has {threshold}")
            node.SetValue(_core.FRICTION_COEFFICIENT, 0.0)

    def ExecuteInitializeSolutionStep(self) -> None:
        super().ExecuteInitializeSolutionStep()
        self._reset_slip_flags()

    def _reset_slip_flags(self) -> None:
        """Every ``slip_step_reset_frequency`` steps the interface nodes start the step sticking
        again (0: never); the active-set update decides anew. Not in pure slip."""
        if not self.frictional or self.pure_slip:
            return
        frequency = self.settings["slip_step_reset_frequency"].GetInt()
        if frequency <= 0:
            return
        self._steps_since_slip_reset += 1
        if self._steps_since_slip_reset >= frequency:
            for node in self.root.GetSubModelPart("Contact").Nodes:
                node.Set(_core.SLIP, False)
            self._steps_since_slip_reset = 0


def _check_range(value, low: float, high: float, closed: bool) -> None:
    """``value`` (a Parameters number) in [low, high) (``closed``) or (low, high)."""
    number = value.GetDouble()
    inside = (low <= number if closed else low < number) and number < high
    if not inside:
        bounds = f"{'[' if closed else '('}{low:g}, {high:g})"
        raise _core.InputError(f"{value.Where()}: must be in {bounds}, got {number!r}")
