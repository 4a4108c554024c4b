"""``penalty_contact_process``: penalty mortar contact (spec 4.5): the ALM process with its own
defaults and the automatic penalty times 1e4 (floor 1e16)."""
from __future__ import annotations

from .. import _core
from . import _settings
from .alm_contact_process import ALMContactProcess


def penalty_defaults() -> dict:
    defaults = _settings.alm_defaults()
    defaults["tangent_factor"] = 1.0e-3
    defaults["advance_ALM_parameters"]["penalty"] = 1.0e16
    defaults["advance_ALM_parameters"]["max_gap_factor"] = 5.0e-4
    return defaults


class PenaltyContactProcess(ALMContactProcess):
    """No multiplier DoFs; the scale factor is unused."""

    python_module = "penalty_contact_process"
    penalty_multiplier = 1.0e4
    penalty_floor = 1.0e16

    @classmethod
    def GetDefaultParameters(cls) -> _core.Parameters:
        return _settings.to_parameters(penalty_defaults())
