"""The MPC contact solver (spec 2.1, 2.8): chosen by ``solver_settings.mpc_contact_settings``; the
structural solver with the MPC contact strategy, whose contact constraints replace the multipliers."""
from __future__ import annotations

import json

from .. import _core
from ..contact_processes.mpc_contact_process import MESH_TYING, mpc_formulation
from ..contact_strategies.strategy_factory import create_builder_and_solver
from ..utilities import warn_about_keys_without_effect
from .mechanical_solver import MechanicalSolver

#: Keys accepted without effect (issue 18): (sub-block or "", key) -> why; warned by the solver settings'
#: validation, whichever solver runs.
KEYS_WITHOUT_EFFECT = {
    ("", "enforce_ntn"): "Kratos 10.4 accepts it without effect too (its node-to-node enforcement is disabled)",
}

_NO_ACTIVE_SET = ("mesh tying (contact_type \"MeshTying\") has no active set: the relations are built once and "
                  "the Newton loop runs on them")
#: Keys of mpc_contact_settings without effect with contact_type "MeshTying".
MESH_TYING_KEYS_WITHOUT_EFFECT = {
    ("", "simplified_semi_smooth_newton"): _NO_ACTIVE_SET,
    ("", "inner_loop_iterations"): _NO_ACTIVE_SET,
    ("", "update_each_nl_iteration"): "mesh tying ties the faces as they were meshed: the relations are built once",
}


def mpc_contact_settings_defaults() -> _core.Parameters:
    """Every key of mpc_contact_settings, each declared once by its reader: contact_type by the solver,
    the others by the MPC strategy."""
    defaults = _core.Parameters('{"contact_type": "Frictionless"}')
    defaults.AddMissingParameters(_core.ResidualBasedNewtonRaphsonMPCContactStrategy.GetDefaultParameters())
    return defaults


class MPCContactMechanicalSolver(MechanicalSolver):
    def __init__(self, model, settings, **kwargs):
        mpc = settings["mpc_contact_settings"]
        self.formulation = mpc_formulation(mpc["contact_type"], "the MPC contact solver")
        if self.formulation.contact_type == MESH_TYING:
            warn_about_keys_without_effect(mpc, mpc_contact_settings_defaults(), MESH_TYING_KEYS_WITHOUT_EFFECT)
        # The active set is decided from the reactions; the DoF numbering follows the constraints.
        for key in ("compute_reactions", "clear_storage", "reform_dofs_at_each_step"):
            settings[key].SetBool(True)
        super().__init__(model, settings, **kwargs)
        if self.explicit:
            raise _core.NotImplementedFeatureError(
                f"{settings['time_integration_method'].Where()}: \"explicit\" with mpc_contact_settings: explicit MPC "
                "contact is not implemented (nor in Kratos); use \"implicit\" (scheme_type \"bossak\", \"newmark\") "
                "for dynamic MPC contact, or contact_settings with explicit_penalty_contact_process for explicit "
                "contact")

    def AddVariables(self) -> None:
        super().AddVariables()
        for name in ["NORMAL", "NODAL_H", *self.formulation.variables]:
            self.main_model_part.AddNodalSolutionStepVariable(_core.GetVariable(name))
        # mpc_contact_process checks that it runs under this solver.
        self.main_model_part.ProcessInfo.SetValue(_core.MORTAR_TYPE, self.formulation.mortar_type)

    def RestartState(self) -> dict:
        """The slip directions (frictional) and the tie's operators (mesh tying) of the MPC strategy."""
        return json.loads(self.strategy.RestartState().WriteJsonString())

    def LoadRestartState(self, state: dict) -> None:
        self.strategy.LoadRestartState(_core.Parameters(json.dumps(state), "restart checkpoint (solver state)"))

    def _create_strategy(self):
        s = self.settings
        part = self.GetComputingModelPart()
        if s["analysis_type"].GetString() == "linear":
            raise _core.NotImplementedFeatureError(
                f"{s['analysis_type'].Where()}: \"linear\" with mpc_contact_settings: MPC contact needs its Newton "
                "loop to find the active set; use \"non_linear\"")
        if s["step_splitting"].size() > 0:
            raise _core.NotImplementedFeatureError(
                f"{s.Where()}.step_splitting: step splitting is not implemented with mpc_contact_settings; remove it "
                "and give a smaller time_stepping.time_step, or use ALM contact (contact_settings, whose "
                "adaptative_strategy, split_factor and max_number_splits split a step that does not converge)")
        builder = create_builder_and_solver(s, self._linear_solver())
        return _core.ResidualBasedNewtonRaphsonMPCContactStrategy(
            part, self._create_scheme(part), self._create_criteria(), builder, settings=s["mpc_contact_settings"],
            max_iteration=s["max_iteration"].GetInt(), compute_reactions=True, reform_dofs_at_each_step=True,
            move_mesh=s["move_mesh_flag"].GetBool(), echo_level=self.echo_level)
