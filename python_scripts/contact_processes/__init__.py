"""Contact processes of the ContactStructuralMechanicsApplication (spec section 4), registered
under their module by the process factory."""
from __future__ import annotations

from .alm_contact_process import ALMContactProcess
from .explicit_penalty_contact_process import ExplicitPenaltyContactProcess
from .mesh_tying_process import MeshTyingProcess
from .mpc_contact_process import MPCContactProcess
from .penalty_contact_process import PenaltyContactProcess

CONTACT_MODULE = "ContactStructuralMechanicsApplication"

CONTACT_PROCESSES = {
    "alm_contact_process": ALMContactProcess,
    "penalty_contact_process": PenaltyContactProcess,
    "explicit_penalty_contact_process": ExplicitPenaltyContactProcess,
    "mpc_contact_process": MPCContactProcess,
    "mesh_tying_process": MeshTyingProcess,
}


__all__ = ["ALMContactProcess", "CONTACT_MODULE", "CONTACT_PROCESSES", "ExplicitPenaltyContactProcess",
           "MPCContactProcess", "MeshTyingProcess", "PenaltyContactProcess"]
