"""``assign_vector_by_direction_process`` (spec 4.9): modulus times a unit direction, on nodes."""
from __future__ import annotations

from ._assignment import (NodalAssignmentProcess, ScalarValue, components_of, defaults, parse_direction,
                          to_python)


class AssignVectorByDirectionProcess(NodalAssignmentProcess):
    """Component i of ``variable_name`` = direction_i · ``modulus`` on every node, with the
    numeric ``direction`` normalised; otherwise as ``AssignScalarVariableProcess`` per component
    (all three components are assigned and, if ``constrained``, fixed).

    Keys (default): ``model_part_name``, ``variable_name`` (array-3), ``modulus`` (number or
    expression), ``direction`` (3-vector; ``automatic_inwards_normal`` /
    ``automatic_outwards_normal`` raise NotImplementedFeatureError) (required); ``interval``
    ([0.0, 1e30]); ``constrained`` (true); ``local_axes``, ``mesh_id``, ``help`` (ignored).
    """

    NAME = "assign_vector_by_direction_process"
    REQUIRED = ("model_part_name", "variable_name", "modulus", "direction")

    @classmethod
    def GetDefaultParameters(cls):
        return defaults("""{
            "help": "", "mesh_id": 0, "model_part_name": null, "variable_name": null,
            "interval": [0.0, 1e30], "modulus": null, "direction": null, "constrained": true,
            "local_axes": {}
        }""")

    def __init__(self, model, settings):
        super().__init__(model, settings)
        components = components_of(self.settings["variable_name"].GetString(), self.where)
        direction = parse_direction(to_python(self.settings["direction"]), self.where)
        modulus = ScalarValue(to_python(self.settings["modulus"]), f"{self.where}: modulus")
        fix = self.settings["constrained"].GetBool()
        self.assignments = [(variable, modulus.scaled(float(d), f"{self.where}: modulus"), fix)
                            for variable, d in zip(components, direction)]

