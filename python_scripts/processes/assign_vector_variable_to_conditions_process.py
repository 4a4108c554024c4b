"""``assign_vector_variable_to_conditions_process`` (spec 4.9): an array-3 value on conditions."""
from __future__ import annotations

import json

from .. import _core
from ._assignment import ConditionAssignmentProcess, ScalarValue, components_of, defaults, to_python


class AssignVectorVariableToConditionsProcess(ConditionAssignmentProcess):
    """Inside ``interval`` sets the non-historical ``<VAR>_X/_Y/_Z`` (e.g. LINE_LOAD,
    SURFACE_LOAD) of every condition; a ``null`` entry leaves that component alone; values persist.

    Keys (default): ``model_part_name``, ``variable_name``, ``value`` (3 entries) (required);
    ``interval`` ([0.0, 1e30]); ``local_axes``, ``mesh_id``, ``help`` (ignored).
    """

    NAME = "assign_vector_variable_to_conditions_process"
    REQUIRED = ("model_part_name", "variable_name", "value")

    @classmethod
    def GetDefaultParameters(cls):
        return defaults("""{
            "help": "", "mesh_id": 0, "model_part_name": null, "variable_name": null,
            "interval": [0.0, 1e30], "value": null, "local_axes": {}
        }""")

    def __init__(self, model, settings):
        super().__init__(model, settings)
        components = components_of(self.settings["variable_name"].GetString(), self.where)
        values = to_python(self.settings["value"])
        if not isinstance(values, list) or len(values) != 3:
            raise _core.InputError(f"{self.where}: 'value' must have 3 entries (number, expression or null), "
                                   f"got {json.dumps(values)}")
        self.assignments = [(variable, ScalarValue(value, f"{self.where}: value[{i}]"))
                            for i, (variable, value) in enumerate(zip(components, values)) if value is not None]

