"""Contact processes whose settings are validated with their exact defaults (spec 4.6-4.8) but
whose formulation arrives with later issues: explicit penalty, MPC contact, mesh tying."""
from __future__ import annotations

from .. import _core
from . import _settings
from .search_base_process import NotImplementedContactProcess


class ExplicitPenaltyContactProcess(NotImplementedContactProcess):
    python_module = "explicit_penalty_contact_process"
    feature = "explicit penalty contact (solver_type explicit)"

    @classmethod
    def GetDefaultParameters(cls) -> _core.Parameters:
        defaults = _settings.alm_defaults()
        defaults["tangent_factor"] = 1.0e-4
        defaults["search_parameters"]["type_search"] = "octree_with_obb"
        defaults["advance_ALM_parameters"]["penalty"] = 1.0e16
        defaults["advance_ALM_parameters"]["max_gap_factor"] = 1.0e-3
        return _settings.to_parameters(defaults)

    def __init__(self, model, settings=None):
        settings = self._normalised(settings)
        settings.RecursivelyValidateAndAssignDefaults(self.GetDefaultParameters())
        raise _core.NotImplementedFeatureError(f"{self.python_module}: {self.feature} is not implemented yet")


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


class MeshTyingProcess(NotImplementedContactProcess):
    python_module = "mesh_tying_process"
    feature = "mortar mesh tying"

    @staticmethod
    def _slot_keys():
        return ("mesh_tying_model_part", "assume_master_slave", "mesh_tying_property_ids")

    @classmethod
    def GetDefaultParameters(cls) -> _core.Parameters:
        search = _settings.search_defaults()
        search["database_step_update"] = 999999999
        del search["octree_search_parameters"]["build_from_bounding_box"]
        for key in ("simple_search", "adapt_search", "static_check_movement", "normal_orientation_threshold",
                    "consider_gap_threshold", "predict_correct_lagrange_multiplier"):
            del search[key]
        return _settings.to_parameters({
            **_settings.IGNORED_KEYS,
            "model_part_name": "Structure",
            **_settings.pair_defaults("mesh_tying"),
            "interval": [0.0, "End"],
            "variable_name": "DISPLACEMENT",
            "consider_static_condensation": False,
            "zero_tolerance_factor": 1.0,
            "integration_order": 2,
            "consider_tessellation": True,
            "normal_check_proportion": 0.1,
            "search_parameters": search,
            "scale_factor_parameters": {"manual_scale_factor": False, "stiffness_factor": 1.0, "scale_factor": 1.0},
        })

    def __init__(self, model, settings=None):
        # Non-recursive at the top (spec 4.8): a partial search_parameters is completed from the
        # base search defaults, not from the tying ones.
        settings = self._normalised(settings)
        user_search = settings.Has("search_parameters")
        settings.ValidateAndAssignDefaults(self.GetDefaultParameters())
        if user_search:
            settings["search_parameters"].RecursivelyValidateAndAssignDefaults(
                _core.ContactSearchProcess.GetDefaultParameters())
        for key in ("mesh_tying_model_part", "assume_master_slave", "mesh_tying_property_ids"):
            settings[key].ValidateAndAssignDefaults(self.GetDefaultParameters()[key])
        variable = settings["variable_name"].GetString()
        raise _core.NotImplementedFeatureError(
            f"{self.python_module}: {self.feature} (variable_name '{variable}') is not implemented yet")
