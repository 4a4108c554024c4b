"""``assign_scalar_variable_to_conditions_process`` (spec 4.9): a double on the conditions."""
from __future__ import annotations

from ._assignment import ConditionAssignmentProcess, ScalarValue, defaults, scalar_variable, to_python


class AssignScalarVariableToConditionsProcess(ConditionAssignmentProcess):
    """Inside ``interval`` sets the non-historical value ``variable_name`` (e.g.
    POSITIVE_FACE_PRESSURE) of every condition of ``model_part_name`` to ``value`` (expressions
    are evaluated at the condition centre); the value persists after the interval.

    Keys (default): ``model_part_name``, ``variable_name``, ``value`` (required); ``interval``
    ([0.0, 1e30]); ``local_axes``, ``mesh_id``, ``help`` (ignored).
    """

    NAME = "assign_scalar_variable_to_conditions_process"
    REQUIRED = ("model_part_name", "variable_name", "value")

    @classmethod
    def GetDefaultParameters(cls):
        return defaults("""{
            "help": "", "mesh_id": 0, "model_part_name": null, "variable_name": null,
            "interval": [0.0, 1e30], "value": null, "local_axes": {}
        }""")

    def __init__(self, model, settings):
        super().__init__(model, settings)
        variable = scalar_variable(self.settings["variable_name"].GetString(), self.where)
        self.assignments = [(variable, ScalarValue(to_python(self.settings["value"]), f"{self.where}: value"))]

