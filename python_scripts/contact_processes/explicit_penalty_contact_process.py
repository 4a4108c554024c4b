"""``explicit_penalty_contact_process``: penalty mortar contact for the explicit central-difference
solver (spec 4.6). The process builds the interface, sets the penalty and runs the search every
``database_step_update`` steps, as the penalty process does; the explicit contact strategy
(``ExplicitPenaltyContactStrategy``) updates the normals, weighted gaps and active set before every
step's residual."""
from __future__ import annotations

from .. import _core
from . import _settings
from .penalty_contact_process import PenaltyContactProcess, penalty_defaults


class ExplicitPenaltyContactProcess(PenaltyContactProcess):
    """Kratos' explicit defaults; the automatic penalty is the ALM estimate E/h itself (floor 1e13)."""

    python_module = "explicit_penalty_contact_process"
    formulation_process = "penalty_contact_process"
    penalty_multiplier = 1.0
    penalty_floor = 1.0e13

    @classmethod
    def GetDefaultParameters(cls) -> _core.Parameters:
        defaults = penalty_defaults()
        defaults["tangent_factor"] = 1.0e-4
        defaults["search_parameters"]["type_search"] = "octree_with_obb"
        defaults["advance_ALM_parameters"]["max_gap_factor"] = 1.0e-3
        return _settings.to_parameters(defaults)

    def _check_types(self) -> None:
        super()._check_types()
        if self.frictional:
            contact_type = self.settings["contact_type"]
            raise _core.NotImplementedFeatureError(
                f"{self.python_module}: {contact_type.Where()} '{contact_type.GetString()}': frictional explicit "
                "contact is not implemented yet; use 'Frictionless'")

