"""Contact processes whose settings are validated with their exact defaults (spec 4.7) but whose
formulation arrives with later issues: MPC contact."""
from __future__ import annotations

from .. import _core
from . import _settings
from .search_base_process import NotImplementedContactProcess


class MPCContactProcess(NotImplementedContactProcess):
    python_module = "mpc_contact_process"
    feature = "multipoint-constraint (MPC) contact"

    @classmethod
    def GetDefaultParameters(cls) -> _core.Parameters:
        common = _settings.common_defaults()
        common.update({
            "contact_type": "Frictionless",
            "not_normal_update_frictional": False,
            "normal_variation": "no_derivatives_computation",
            "frictional_law": "Coulomb",
            "tangent_factor": 1.0e-1,
            "zero_tolerance_factor": 1.0e2,
            "reaction_check_stiffness_factor": 1.0e-10,
            "integration_order": 2,
            "clear_inactive_for_post": True,
            "update_condition_relation_step": False,
        })
        return _settings.to_parameters(common)

    def __init__(self, model, settings=None):
        settings = self._normalised(settings)
        settings.RecursivelyValidateAndAssignDefaults(self.GetDefaultParameters())
        contact_type = settings["contact_type"].GetString()
        raise _core.NotImplementedFeatureError(
            f"{self.python_module}: {self.feature} (contact_type '{contact_type}') is not implemented yet")
