"""The six assignment processes of Kratos' kernel (spec 4.9): a scalar, an array-3 value component
by component, or a modulus along a direction, assigned inside ``interval`` (at
``ExecuteBeforeSolutionLoop`` and every ``ExecuteInitializeSolutionStep`` whose TIME lies in it)

- on the nodes: historical values, fixing the DoFs that are ``constrained`` and freeing them again
  at the end of every step in which they were fixed;
- on the conditions (``*_to_condition(s)_process``): non-historical values (e.g. LINE_LOAD,
  POSITIVE_FACE_PRESSURE), which persist after the interval.

A value is a number, an expression of x, y, z, X, Y, Z, t (evaluated at the node or the condition
centre) or a CSV time table. Keys: ``model_part_name``, ``variable_name`` and the value keys of
the kind (required); ``interval`` ([0.0, 1e30], "Begin" / "End" allowed); ``constrained`` (nodes
only); ``mesh_id``, ``help`` (ignored); ``local_axes`` (warns: global axes only).
"""
from __future__ import annotations

import json

from .. import _core
from ..process import Process
from ._assignment import (
    Interval,
    ScalarValue,
    components_of,
    current_time,
    defaults,
    parse_direction,
    require_keys,
    scalar_variable,
    to_python,
)
from .model_part_resolution import resolve_model_part

_COMMON_DEFAULTS = ('"help": "", "mesh_id": 0, "model_part_name": null, "variable_name": null, '
                    '"interval": [0.0, 1e30], "local_axes": {}')


def expand_constrained(constrained, where: str) -> list[bool]:
    """``constrained`` as three booleans (a single bool applies to all three components)."""
    if constrained is None:
        return [True, True, True]
    if isinstance(constrained, bool):
        return [constrained] * 3
    if isinstance(constrained, list) and len(constrained) == 3 and all(isinstance(c, bool) for c in constrained):
        return list(constrained)
    raise _core.InputError(f"{where}: 'constrained' must be a bool or a list of three bools, "
                           f"got {json.dumps(constrained)}")


class AssignmentProcess(Process):
    """The machinery; a subclass names its kind of value (``values``) and its target."""

    NAME = "assignment process"
    #: the value keys of the kind, with their defaults (a JSON fragment)
    VALUE_DEFAULTS = '"value": null'
    #: the default of ``constrained`` on nodes
    CONSTRAINED_DEFAULT = "true"
    ON_CONDITIONS = False

    @classmethod
    def GetDefaultParameters(cls):
        keys = [_COMMON_DEFAULTS, cls.VALUE_DEFAULTS]
        if not cls.ON_CONDITIONS:
            keys.append(f'"constrained": {cls.CONSTRAINED_DEFAULT}')
        return defaults("{" + ", ".join(keys) + "}")

    @classmethod
    def required_keys(cls) -> list[str]:
        value_keys = json.loads("{" + cls.VALUE_DEFAULTS + "}")
        return ["model_part_name", "variable_name", *value_keys]

    def __init__(self, model, settings):
        settings = settings if settings is not None else _core.Parameters()
        require_keys(settings, self.NAME, self.required_keys())
        super().__init__(model, settings)
        self.where = self.settings.Where()
        _core.NoEffectWarnings.IfGiven(self.settings, self.GetDefaultParameters(), "local_axes",
                                       "values and expressions are taken in the global axes")
        self.model_part = resolve_model_part(model, self.settings["model_part_name"].GetString())
        self.interval = Interval(to_python(self.settings["interval"]), self.where)
        fixes = [False] * 3 if self.ON_CONDITIONS else expand_constrained(to_python(self.settings["constrained"]),
                                                                            self.where)
        # (component variable, ScalarValue, fix)
        self.assignments = [(variable, value, fixes[i]) for i, variable, value in self.values()]
        self._fixed_in_step = False

    def values(self) -> list[tuple[int, object, ScalarValue]]:
        """(component index, variable, value) of what is assigned."""
        raise NotImplementedError

    def _assign(self) -> None:
        time = current_time(self.model_part)
        if not self.interval.contains(time):
            return
        for variable, value, fix in self.assignments:
            if self.ON_CONDITIONS:
                value.assign_to_conditions(self.model_part, variable, time)
            else:
                value.assign_to_nodes(self.model_part, variable, time, fix)
                self._fixed_in_step = self._fixed_in_step or fix

    def ExecuteBeforeSolutionLoop(self) -> None:
        self._assign()

    def ExecuteInitializeSolutionStep(self) -> None:
        self._assign()

    def ExecuteFinalizeSolutionStep(self) -> None:
        if not self._fixed_in_step:
            return
        for variable, _, fix in self.assignments:
            if fix:
                _core.VariableUtils.FreeDof(self.model_part, variable)
        self._fixed_in_step = False


class AssignScalarVariableProcess(AssignmentProcess):
    """A double variable or a component (DISPLACEMENT_X) set to ``value``."""

    NAME = "assign_scalar_variable_process"

    def values(self):
        variable = scalar_variable(self.settings["variable_name"].GetString(), self.where)
        return [(0, variable, ScalarValue(to_python(self.settings["value"]), f"{self.where}: value"))]


class AssignVectorVariableProcess(AssignmentProcess):
    """``<VAR>_X``, ``_Y``, ``_Z`` of an array-3 variable set to the three entries of ``value``; a
    ``null`` entry leaves that component alone (nothing assigned, nothing fixed). ``constrained``
    may be one bool or three (default: all three)."""

    NAME = "assign_vector_variable_process"
    CONSTRAINED_DEFAULT = "null"

    def values(self):
        components = components_of(self.settings["variable_name"].GetString(), self.where)
        values = to_python(self.settings["value"])
        if not isinstance(values, list) or len(values) != 3:
            raise _core.InputError(f"{self.where}: 'value' must have 3 entries (number, expression or null), "
                                   f"got {json.dumps(values)}")
        return [(i, variable, ScalarValue(value, f"{self.where}: value[{i}]"))
                for i, (variable, value) in enumerate(zip(components, values)) if value is not None]


class AssignVectorByDirectionProcess(AssignmentProcess):
    """Component i of an array-3 variable set to direction_i times ``modulus``, the numeric
    ``direction`` normalised (``automatic_inwards_normal`` / ``automatic_outwards_normal`` raise
    NotImplementedFeatureError); all three components are assigned."""

    NAME = "assign_vector_by_direction_process"
    VALUE_DEFAULTS = '"modulus": null, "direction": null'

    def values(self):
        components = components_of(self.settings["variable_name"].GetString(), self.where)
        direction = parse_direction(to_python(self.settings["direction"]), self.where)
        modulus = ScalarValue(to_python(self.settings["modulus"]), f"{self.where}: modulus")
        return [(i, variable, modulus.scaled(float(d), f"{self.where}: modulus"))
                for i, (variable, d) in enumerate(zip(components, direction))]


class AssignScalarVariableToConditionsProcess(AssignScalarVariableProcess):
    NAME = "assign_scalar_variable_to_conditions_process"
    ON_CONDITIONS = True


class AssignVectorVariableToConditionsProcess(AssignVectorVariableProcess):
    NAME = "assign_vector_variable_to_conditions_process"
    ON_CONDITIONS = True


class AssignVectorByDirectionToConditionProcess(AssignVectorByDirectionProcess):
    NAME = "assign_vector_by_direction_to_condition_process"
    ON_CONDITIONS = True


#: python_module -> class
ASSIGNMENT_PROCESSES = {cls.NAME: cls for cls in (
    AssignScalarVariableProcess, AssignVectorVariableProcess, AssignVectorByDirectionProcess,
    AssignScalarVariableToConditionsProcess, AssignVectorVariableToConditionsProcess,
    AssignVectorByDirectionToConditionProcess)}
