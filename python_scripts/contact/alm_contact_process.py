"""``alm_contact_process``: augmented Lagrangian mortar contact (spec 4.4)."""
from __future__ import annotations

from .. import _core
from .search_base_process import SearchBaseProcess

#: normal_variation -> ProcessInfo CONSIDER_NORMAL_VARIATION (spec 4.4)
NORMAL_VARIATIONS = {
    "no_derivatives_computation": 0,
    "elemental_derivatives": 1,
    "nodal_elemental_derivatives": 2,
    "no_derivatives_computation_with_normal_update": 3,
}
CONTACT_TYPES = ("Frictionless", "FrictionlessComponents", "Frictional", "FrictionalPureSlip")


def split_contact_type(contact_type: str, where: str) -> tuple[str, bool]:
    """``"FrictionalWithNormalUpdate"`` -> (``"Frictional"``, True); unknown -> InputError."""
    suffix = "WithNormalUpdate"
    base = contact_type[:-len(suffix)] if contact_type.endswith(suffix) else contact_type
    if base not in CONTACT_TYPES:
        from ..utilities import nearest
        raise _core.InputError(f"{where}: unknown contact_type '{contact_type}'"
                               f"{nearest(contact_type, CONTACT_TYPES, cutoff=0.4)} "
                               f"(valid: {', '.join(CONTACT_TYPES)}, optionally + '{suffix}')")
    return base, contact_type.endswith(suffix)


class ALMContactProcess(SearchBaseProcess):
    """Builds the contact interfaces and searches, computes the ALM penalty and scale factor,
    and runs the search each ``database_step_update`` steps inside ``interval``."""

    python_module = "alm_contact_process"
    method = "ALM"
    #: mortar_type the solver must use, per contact type (spec 2.10)
    mortar_types = {"Frictionless": "ALMContactFrictionless",
                    "FrictionlessComponents": "ALMContactFrictionlessComponents",
                    "Frictional": "ALMContactFrictional", "FrictionalPureSlip": "ALMContactFrictionalPureSlip"}
    implemented = ("Frictionless", "FrictionlessComponents")
    penalty_multiplier = 1.0
    penalty_floor = 1.0

    def _check_types(self) -> None:
        where = f"{self.python_module}: contact_type"
        self.contact_type, self.normal_update = split_contact_type(self.settings["contact_type"].GetString(), where)
        variation = self.settings["normal_variation"].GetString().lower()
        if variation not in NORMAL_VARIATIONS:
            from ..utilities import nearest
            raise _core.InputError(f"{self.settings['normal_variation'].Where()}: unknown value '{variation}'"
                                   f"{nearest(variation, NORMAL_VARIATIONS)}")
        if self.normal_update and variation == "no_derivatives_computation":
            variation = "no_derivatives_computation_with_normal_update"
        self.normal_variation = variation
        if self.contact_type not in self.implemented:
            raise _core.NotImplementedFeatureError(
                f"{self.python_module}: contact_type '{self.settings['contact_type'].GetString()}' is not "
                f"implemented yet (available: {', '.join(self.implemented)})")
        self.axisymmetric = self.settings["alternative_formulations"]["axisymmetric"].GetBool()
        if self.axisymmetric and self.contact_type != "Frictionless":
            raise _core.NotImplementedFeatureError(
                f"{self.python_module}: alternative_formulations.axisymmetric exists for contact_type "
                f"'Frictionless' only (got '{self.settings['contact_type'].GetString()}')")
        if self.settings["advance_ALM_parameters"]["adapt_penalty"].GetBool():
            raise _core.NotImplementedFeatureError(
                f"{self.python_module}: advance_ALM_parameters.adapt_penalty is not implemented yet")

    @property
    def multiplier_variable(self):
        """The multiplier of the contact type: a scalar pressure or a vector (components)."""
        vector = self.contact_type != "Frictionless"
        return _core.VECTOR_LAGRANGE_MULTIPLIER if vector else _core.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE

    @property
    def mortar_type(self) -> str:
        return self.mortar_types[self.contact_type]

    def condition_stem(self) -> str:
        nv = "NV" if self.normal_variation == "nodal_elemental_derivatives" else ""
        friction = self.contact_type.replace("PureSlip", "")
        axisym = "Axisym" if self.axisymmetric else ""
        return f"{self.method}{nv}{friction}{axisym}MortarContactCondition"

    def check_solver_variables(self) -> None:
        """The solver adds the variables of its mortar_type before the mesh is read (spec 2.10):
        their absence reveals a missing or mismatched mortar_type. Axisymmetry needs a 2D model."""
        dimension = self.root.GetProcessInfo().GetValue(_core.DOMAIN_SIZE)
        if self.axisymmetric and dimension != 2:
            raise _core.InputError(f"{self.settings['alternative_formulations'].Where()}.axisymmetric: true needs "
                                   f"domain_size 2 (x = radius, y = axis), got {dimension}")
        has = self.root.HasNodalSolutionStepVariable
        expected = self.mortar_type
        if not has(_core.WEIGHTED_GAP):
            problem = "adds no contact variables (mortar_type empty?)"
        elif self.method == "ALM" and not has(self.multiplier_variable):
            problem = f"has no {self.multiplier_variable.Name()} (mortar_type of another family?)"
        elif self.method == "Penalty" and has(_core.LAGRANGE_MULTIPLIER_CONTACT_PRESSURE):
            problem = "has LAGRANGE_MULTIPLIER_CONTACT_PRESSURE (an ALM mortar_type?)"
        else:
            return
        raise _core.InputError(
            f"{self.python_module} with contact_type '{self.settings['contact_type'].GetString()}' needs "
            f"solver_settings.contact_settings.mortar_type \"{expected}\"; the solver's model part {problem}")

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
            calculation = _core.Parameters()
            for key in ("stiffness_factor", "penalty_scale_factor", "use_scale_factor"):
                calculation.AddValue(key, alm[key])
            calculation.AddValue("penalty_multiplier", _core.Parameters(repr(float(self.penalty_multiplier))))
            calculation.AddValue("penalty_floor", _core.Parameters(repr(float(self.penalty_floor))))
            _core.ALMVariablesCalculationProcess(self.root, self.root.GetSubModelPart("Contact"), calculation).Execute()
