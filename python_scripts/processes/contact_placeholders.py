"""Contact processes of the ContactStructuralMechanicsApplication (spec section 4) that are
registered by name but arrive with later issues: constructing one says so plainly."""
from __future__ import annotations

from .. import _core
from ..process import Process

# python_module -> why it is not there yet
PENDING_CONTACT_PROCESSES = {
    "alm_contact_process": "frictionless mortar contact arrives with issue 3",
    "penalty_contact_process": "penalty mortar contact arrives after the ALM contact of issue 3",
    "explicit_penalty_contact_process": "explicit penalty contact arrives after the ALM contact of issue 3",
    "mpc_contact_process": "MPC contact arrives after the ALM contact of issue 3",
    "mesh_tying_process": "mortar mesh tying arrives after the ALM contact of issue 3",
}


class PendingContactProcess(Process):
    """Raises NotImplementedFeatureError on construction."""

    python_module = ""

    def __init__(self, model, settings=None):
        raise _core.NotImplementedFeatureError(
            f"{self.python_module} is not implemented yet ({PENDING_CONTACT_PROCESSES[self.python_module]})")


def pending_process_class(python_module: str) -> type[PendingContactProcess]:
    name = "".join(part.capitalize() for part in python_module.split("_"))
    return type(name, (PendingContactProcess,), {"python_module": python_module, "__doc__":
                f"``{python_module}``: not implemented yet ({PENDING_CONTACT_PROCESSES[python_module]})."})
