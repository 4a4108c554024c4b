"""The contact strategy from ``solver_settings`` (spec 2.9)."""
from __future__ import annotations

from .convergence_criteria_factory import _core_module, _value


def create_builder_and_solver(solver_settings, linear_solver, core=None):
    """``block`` -> block builder; any other type (``elimination``, ``block_lagrange``) ->
    elimination builder, as the Kratos contact solvers do."""
    core = _core_module(core)
    kind = _value(solver_settings["builder_and_solver_settings"], "type", "String")
    if kind == "block":
        return core.BlockBuilderAndSolver(linear_solver)
    return core.EliminationBuilderAndSolver(linear_solver)


def create_contact_strategy(model_part, solver_settings, scheme, linear_solver, criteria, echo_level: int = 0,
                            mortar_updater=None, initialize_sub_step=None, finalize_sub_step=None, core=None):
    """The strategy of a contact solver.

    - ``analysis_type: linear`` -> plain LinearStrategy (no active-set loop);
    - ``solving_strategy_settings.type``: ``newton_raphson`` -> ResidualBasedNewtonRaphsonContactStrategy,
      ``line_search`` -> LineSearchContactStrategy (split displacement / multiplier steps),
      ``arc_length`` -> not implemented;
    - the strategy reads its keys (``adaptative_strategy``, ``split_factor``, ``max_number_splits``,
      ``inner_loop_iterations``) from ``contact_settings``;
    - the computing model part gets INTERACTION unless ``simplified_semi_smooth_newton``
      (full semi-smooth Newton by default);
    - ``initialize_sub_step`` / ``finalize_sub_step`` (callables without arguments: the processes'
      ExecuteInitializeSolutionStep / ExecuteFinalizeSolutionStep, and the output) are run around
      the sub-steps of the adaptive splitting.

    ``clear_storage`` and ``reform_dofs_at_each_step`` are forced true for contact (the DoF set
    follows the contact pairs). ``silent_strategy`` (echo 0 after Initialize) is the caller's.
    """
    core = _core_module(core)
    s = solver_settings
    contact = s["contact_settings"]
    builder = create_builder_and_solver(s, linear_solver, core)
    common = {"compute_reactions": _value(s, "compute_reactions", "Bool"), "reform_dofs_at_each_step": True,
              "move_mesh": _value(s, "move_mesh_flag", "Bool"), "echo_level": echo_level}
    model_part.Set(core.INTERACTION, not _value(contact, "simplified_semi_smooth_newton", "Bool"))
    if _value(s, "analysis_type", "String") == "linear":
        return core.LinearStrategy(model_part, scheme, builder, **common)
    kind = _value(s["solving_strategy_settings"], "type", "String")
    # The strategy reads its keys from contact_settings itself.
    args = dict(settings=contact, max_iteration=_value(s, "max_iteration", "Int"), **common)
    if kind == "newton_raphson":
        strategy = core.ResidualBasedNewtonRaphsonContactStrategy(model_part, scheme, criteria, builder, **args)
    elif kind == "line_search":
        strategy = core.LineSearchContactStrategy(model_part, scheme, criteria, builder, **args)
    elif kind == "arc_length":
        raise core.NotImplementedFeatureError("solver_settings.solving_strategy_settings.type: \"arc_length\" is "
                                              "not implemented for contact")
    else:
        raise core.InputError(f"solver_settings.solving_strategy_settings.type: unknown type \"{kind}\"; valid: "
                              "newton_raphson, line_search, arc_length")
    if mortar_updater is not None:
        strategy.SetMortarUpdater(mortar_updater)
    if initialize_sub_step is not None or finalize_sub_step is not None:
        strategy.SetSubStepCallbacks(initialize_sub_step, finalize_sub_step)
    return strategy
