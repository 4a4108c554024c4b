"""``assign_scalar_variable_process`` (spec 4.9): a double variable or a component on the nodes."""
from __future__ import annotations

from ._assignment import NodalAssignmentProcess, ScalarValue, defaults, scalar_variable, to_python


class AssignScalarVariableProcess(NodalAssignmentProcess):
    """At ``ExecuteBeforeSolutionLoop`` and every ``ExecuteInitializeSolutionStep`` whose TIME lies
    in ``interval``: sets the historical value of ``variable_name`` on every node of
    ``model_part_name`` to ``value`` (number, expression of x, y, z, X, Y, Z, t, or CSV table) and
    fixes the DoF if ``constrained``; the DoF is freed again at ``ExecuteFinalizeSolutionStep``.

    Keys (default): ``model_part_name``, ``variable_name``, ``value`` (required);
    ``interval`` ([0.0, 1e30], "End" allowed); ``constrained`` (true); ``local_axes``, ``mesh_id``,
    ``help`` (ignored).
    """

    NAME = "assign_scalar_variable_process"
    REQUIRED = ("model_part_name", "variable_name", "value")

    @classmethod
    def GetDefaultParameters(cls):
        return defaults("""{
            "help": "", "mesh_id": 0, "model_part_name": null, "variable_name": null,
            "interval": [0.0, 1e30], "constrained": true, "value": null, "local_axes": {}
        }""")

    def __init__(self, model, settings):
        super().__init__(model, settings)
        variable = scalar_variable(self.settings["variable_name"].GetString(), self.where)
        value = ScalarValue(to_python(self.settings["value"]), f"{self.where}: value")
        self.assignments = [(variable, value, self.settings["constrained"].GetBool())]

