"""``explicit_penalty_contact_process``: penalty mortar contact for the explicit central-difference
solver (spec 4.6). The process builds the interface, sets the penalty and runs the search every
``database_step_update`` steps, as the penalty process does; the explicit contact strategy
(``ExplicitPenaltyContactStrategy``) updates the normals, weighted gaps and active set before every
step's residual; with ``contact_type`` ``Frictional`` it accumulates the slip of sticking nodes."""
from __future__ import annotations

from .. import _core
from . import _settings
from .penalty_contact_process import PenaltyContactProcess, penalty_defaults


class ExplicitPenaltyContactProcess(PenaltyContactProcess):
    """Kratos' explicit defaults but tangent_factor; the automatic penalty is the ALM estimate E/h
    itself (floor 1e13)."""

    python_module = "explicit_penalty_contact_process"
    formulation_process = "penalty_contact_process"
    penalty_multiplier = 1.0
    penalty_floor = 1.0e13

    @classmethod
    def GetDefaultParameters(cls) -> _core.Parameters:
        defaults = penalty_defaults()
        # Kratos' explicit default is 1e-4. Here the stick traction is c_tau eps times the slip
        # accumulated while sticking (ExplicitPenaltyContactStrategy), so c_tau is the ratio of the
        # tangential to the normal stiffness: at 1e-4 a node sticks over 1e4 times its penetration,
        # and whenever the normal force drops the traction falls back inside the cone (a block
        # sliding on a plane felt 40 % less friction than Coulomb's). 1 gives Coulomb's law.
        defaults["tangent_factor"] = 1.0
        defaults["search_parameters"]["type_search"] = "octree_with_obb"
        defaults["advance_ALM_parameters"]["max_gap_factor"] = 1.0e-3
        return _settings.to_parameters(defaults)

    def ExecuteFinalizeSolutionStep(self) -> None:
        # The explicit strategy computed the contact outputs right after the step's residual, at
        # u_n (the force that acted in the step); recomputing them here would take u_{n+1}.
        if self.root is not None and self.settings["clear_inactive_for_post"].GetBool():
            _core.ClearInactiveContactPressures(self.root.GetSubModelPart("Contact"))
