"""Contact processes of the ContactStructuralMechanicsApplication (spec section 4), registered
in the process registry by ``register_contact_processes()``."""
from __future__ import annotations

from .. import _core
from .alm_contact_process import ALMContactProcess
from .not_implemented_processes import ExplicitPenaltyContactProcess, MeshTyingProcess, MPCContactProcess
from .penalty_contact_process import PenaltyContactProcess

CONTACT_MODULE = "ContactStructuralMechanicsApplication"

CONTACT_PROCESSES = {
    "alm_contact_process": ALMContactProcess,
    "penalty_contact_process": PenaltyContactProcess,
    "explicit_penalty_contact_process": ExplicitPenaltyContactProcess,
    "mpc_contact_process": MPCContactProcess,
    "mesh_tying_process": MeshTyingProcess,
}


def register_contact_processes(registry: dict) -> None:
    """Adds the contact processes to ``registry`` ((module, python_module) -> class)."""
    for name, cls in CONTACT_PROCESSES.items():
        registry[(CONTACT_MODULE, name)] = cls


__all__ = ["ALMContactProcess", "CONTACT_PROCESSES", "ExplicitPenaltyContactProcess", "MPCContactProcess",
           "MeshTyingProcess", "PenaltyContactProcess", "register_contact_processes"]
