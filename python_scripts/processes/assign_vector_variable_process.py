"""``assign_vector_variable_process`` (spec 4.9): an array-3 variable on the nodes, per component."""
from __future__ import annotations

import json

from .. import _core
from ._assignment import NodalAssignmentProcess, ScalarValue, components_of, defaults, to_python


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


class AssignVectorVariableProcess(NodalAssignmentProcess):
    """Three scalar assignments ``<VAR>_X``, ``<VAR>_Y``, ``<VAR>_Z`` (see
    ``AssignScalarVariableProcess``). A ``null`` entry of ``value`` leaves that component alone:
    nothing is assigned and nothing is fixed.

    Keys (default): ``model_part_name``, ``variable_name`` (array-3), ``value`` (3 entries, each a
    number, an expression or null) (required); ``interval`` ([0.0, 1e30], "End" allowed);
    ``constrained`` ([true, true, true]; a single bool is expanded); ``local_axes``, ``mesh_id``,
    ``help`` (ignored).
    """

    NAME = "assign_vector_variable_process"
    REQUIRED = ("model_part_name", "variable_name", "value")

    @classmethod
    def GetDefaultParameters(cls):
        return defaults("""{
            "help": "", "mesh_id": 0, "model_part_name": null, "variable_name": null,
            "interval": [0.0, 1e30], "constrained": null, "value": null, "local_axes": {}
        }""")

    def __init__(self, model, settings):
        super().__init__(model, settings)
        components = components_of(self.settings["variable_name"].GetString(), self.where)
        values = to_python(self.settings["value"])
        if not isinstance(values, list) or len(values) != 3:
            raise _core.InputError(f"{self.where}: 'value' must have 3 entries (number, expression or null), "
                                   f"got {json.dumps(values)}")
        fixes = expand_constrained(to_python(self.settings["constrained"]), self.where)
        self.assignments = [(variable, ScalarValue(value, f"{self.where}: value[{i}]"), fix)
                            for i, (variable, value, fix) in enumerate(zip(components, values, fixes))
                            if value is not None]

