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


def check_contact_pairing(solver_settings: "_core.Parameters", processes) -> None:
    """Start-up check of spec 2.10: each ALM / penalty contact process needs the matching
    ``contact_settings.mortar_type`` (substring dispatch as in Kratos, so suffixes such as
    ``WithNormalUpdate`` pass). Call it once the solver settings and the processes exist."""
    mortar_type = ""
    if solver_settings.Has("contact_settings") and solver_settings["contact_settings"].Has("mortar_type"):
        mortar_type = solver_settings["contact_settings"]["mortar_type"].GetString()
    for process in processes:
        if not isinstance(process, ALMContactProcess):
            continue
        expected = process.mortar_type
        compatible = mortar_type.startswith(expected) and (
            "Components" in expected or "Components" not in mortar_type)
        if not compatible:
            raise _core.InputError(
                f"{process.python_module} with contact_type '{process.settings['contact_type'].GetString()}' needs "
                f"solver_settings.contact_settings.mortar_type \"{expected}\", got \"{mortar_type}\"")


__all__ = ["ALMContactProcess", "CONTACT_PROCESSES", "ExplicitPenaltyContactProcess", "MPCContactProcess",
           "MeshTyingProcess", "PenaltyContactProcess", "check_contact_pairing", "register_contact_processes"]
