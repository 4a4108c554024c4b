"""``assign_vector_by_direction_to_condition_process`` (spec 4.9): modulus·direction on conditions."""
from __future__ import annotations

from ._assignment import ConditionAssignmentProcess, ScalarValue, components_of, defaults, parse_direction, to_python


class AssignVectorByDirectionToConditionProcess(ConditionAssignmentProcess):
    """Component i of the non-historical condition value ``variable_name`` = direction_i ·
    ``modulus`` (direction normalised) inside ``interval``; values persist afterwards.

    Keys (default): ``model_part_name``, ``variable_name``, ``modulus``, ``direction`` (required);
    ``interval`` ([0.0, 1e30]); ``local_axes``, ``mesh_id``, ``help`` (ignored).
    """

    NAME = "assign_vector_by_direction_to_condition_process"
    REQUIRED = ("model_part_name", "variable_name", "modulus", "direction")

    @classmethod
    def GetDefaultParameters(cls):
        return defaults("""{
            "help": "", "mesh_id": 0, "model_part_name": null, "variable_name": null,
            "interval": [0.0, 1e30], "modulus": null, "direction": null, "local_axes": {}
        }""")

    def __init__(self, model, settings):
        super().__init__(model, settings)
        components = components_of(self.settings["variable_name"].GetString(), self.where)
        direction = parse_direction(to_python(self.settings["direction"]), self.where)
        modulus = ScalarValue(to_python(self.settings["modulus"]), f"{self.where}: modulus")
        self.assignments = [(variable, modulus.scaled(float(d), f"{self.where}: modulus"))
                            for variable, d in zip(components, direction)]

