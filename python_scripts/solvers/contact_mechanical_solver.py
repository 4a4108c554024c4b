"""The contact solver (spec 2.9, 2.10): the structural solver plus the variables and DoFs of the
formulation registered under ``contact_settings.mortar_type`` (``ContactFormulation``), the contact
convergence criteria and the semi-smooth Newton contact strategy."""
from __future__ import annotations

from .. import _core
from ..contact_processes.alm_contact_process import is_pure_slip
from ..contact_strategies import CRITERIA_SETTINGS, create_contact_convergence_criteria, create_contact_strategy
from ..utilities import warn, warn_about_keys_without_effect
from .mechanical_solver import MechanicalSolver

#: The solver's own keys of contact_settings (Kratos' names and defaults). The keys of the classes
#: that read the block themselves are theirs: see contact_settings_defaults().
CONTACT_SETTINGS = """{
    "mortar_type": "",
    "inner_loop_adaptive": false,
    "silent_strategy": true,
    "simplified_semi_smooth_newton": false,
    "rescale_linear_solver": false,
    "use_mixed_ulm_solver": true,
    "mixed_ulm_solver_parameters": {
        "solver_type": "mixed_ulm_linear_solver",
        "tolerance": 1.0e-6,
        "max_iteration_number": 200,
        "echo_level": 0
    },
    "fallback_if_dual_lm_not_valid": true,
    "delta_time_factor_for_contact": 0.5
}"""


_FRICTIONAL = "only the criteria of the frictional multiplier formulations (ALMContactFrictional*) read it"
#: Read by the criteria with normal, stick and slip multiplier blocks only: without effect on the others.
FRICTIONAL_KEYS_WITHOUT_EFFECT = {
    ("", "frictional_decomposed"): _FRICTIONAL,
    **{("", f"frictional_{block}_contact_{kind}_{which}_tolerance"): _FRICTIONAL
       for block in ("stick", "slip") for kind in ("displacement", "residual") for which in ("relative", "absolute")},
    ("", "ratio_normal_tangent_threshold"): _FRICTIONAL,
}
#: The solver's keys accepted without effect (issue 18): (sub-block or "", key) -> why; warned when
#: given a value other than the default (NoEffectWarnings).
KEYS_WITHOUT_EFFECT = {
    ("", "inner_loop_adaptive"): "the time step is not divided by the inner-loop count (INNER_LOOP_ITERATION)",
    ("", "fallback_if_dual_lm_not_valid"): "no fallback from the dual multipliers is implemented (the key comes "
                                           "from a secondary reference only)",
    **{("mixed_ulm_solver_parameters", key): "the condensed system is solved by the solver of "
                                             "linear_solver_settings, with its own settings"
       for key in ("tolerance", "max_iteration_number", "echo_level")},
}


#: Kratos' direct solvers, which run UMFPACK here: a case naming one of them (or none) has not chosen
#: a solver for a large 3D contact problem. Naming "umfpack" does.
KRATOS_DIRECT_SOLVERS = {"skyline_lu_factorization", "sparse_lu", "pardiso_lu", "pardiso_ldlt", "super_lu",
                         "pastix", "mumps"}
#: Estimated equations (3 per node, one multiplier per contact node) from which such a 3D problem is
#: solved by LARGE_3D_LINEAR_SOLVER. The field split took 0.83 x UMFPACK's CPU time on 6.1k
#: equations, 0.63 x (and 0.57 x the memory) on 14.9k, 22 s against 337 s on 51k, in the same
#: Newton iterations (benchmarks/hertz/results_3d_multigrid.md); below 10k the exact direct solve
#: is kept: a second or two either way.
LARGE_3D_EQUATIONS = 10000
#: PETSc's field split with the rigid-body modes for the multigrid of the displacements (issue 14),
#: the first two FGMRES solves of a load step stopped at 1e-6, the later ones at 1e-8 (ForcingTerm).
LARGE_3D_LINEAR_SOLVER = """{
    "solver_type": "petsc",
    "tolerance": 1e-8,
    "max_iteration": 500,
    "inexact_newton": true,
    "petsc_options": {"pc_type": "fieldsplit"}
}"""


def contact_settings_defaults() -> _core.Parameters:
    """Every key of contact_settings, each declared once by its reader: the solver's, the criteria
    factory's, the block criteria's, the contact strategy's and the active-set criteria's."""
    defaults = _core.Parameters(CONTACT_SETTINGS)
    for owned in (_core.Parameters(CRITERIA_SETTINGS), _core.BlockContactCriteria.GetContactSettingsDefaults(),
                  _core.ResidualBasedNewtonRaphsonContactStrategy.GetDefaultParameters(),
                  _core.BaseMortarConvergenceCriteria.GetDefaultParameters()):
        defaults.AddMissingParameters(owned)
    return defaults


class ContactMechanicalSolver(MechanicalSolver):
    #: contact criteria names are resolved by the contact factory (spec 3.2)
    criteria_names = None

    def __init__(self, model, settings, **kwargs):
        mortar_type = settings["contact_settings"]["mortar_type"]
        self.formulation = _core.ContactFormulation.Get(mortar_type.GetString(), mortar_type.Where())
        if self.formulation.process == "mpc_contact_process":
            raise _core.InputError(f"{mortar_type.Where()}: \"{mortar_type.GetString()}\" is not a mortar_type: "
                                   "MPC contact is chosen by solver_settings.mpc_contact_settings (without "
                                   "contact_settings)")
        # The DoF set follows the contact pairs, which change from step to step (the explicit penalty
        # strategy keeps the elements' DoFs and lumped mass: penalty contact adds no DoFs).
        settings["clear_storage"].SetBool(True)
        settings["reform_dofs_at_each_step"].SetBool(True)
        super().__init__(model, settings, **kwargs)
        if self.explicit and self.formulation.multiplier_blocks != 0:
            mortar_type = settings["contact_settings"]["mortar_type"]
            raise _core.NotImplementedFeatureError(
                f"{mortar_type.Where()}: explicit contact with \"{mortar_type.GetString()}\" is not implemented; the "
                "explicit solver runs the penalty formulations (explicit_penalty_contact_process)")
        without_effect = dict(KEYS_WITHOUT_EFFECT)
        if self.formulation.multiplier_blocks != 3:
            without_effect.update(FRICTIONAL_KEYS_WITHOUT_EFFECT)
        if not self.explicit:
            without_effect[("", "delta_time_factor_for_contact")] = "only the explicit contact solver reads it"
        if not self.dynamic:
            without_effect[("", "compute_dynamic_factor")] = ("the problem is static: the dynamic factor (the share of "
                                                              "a step a node spends in contact) needs velocities")
        elif self.explicit:
            without_effect[("", "compute_dynamic_factor")] = ("the explicit contact applies the full penalty force at "
                                                              "every step (the steps are short next to the impact)")
        warn_about_keys_without_effect(settings["contact_settings"], contact_settings_defaults(), without_effect)

    def AddVariables(self) -> None:
        super().AddVariables()
        for name in ["NORMAL", "NODAL_H", *self.formulation.variables]:
            self.main_model_part.AddNodalSolutionStepVariable(_core.GetVariable(name))
        # The contact processes check their formulation against the solver's.
        self.main_model_part.ProcessInfo.SetValue(_core.MORTAR_TYPE, self.formulation.mortar_type)

    def minimum_buffer_size(self) -> int:
        # Kratos raises a frictional buffer_size to 3 only when it is already >= 3 (spec, trap 6);
        # the intended rule is the minimum.
        return max(super().minimum_buffer_size(), self.formulation.buffer_size)

    def AddDofs(self) -> None:
        super().AddDofs()
        for dof, reaction in self.formulation.dofs:
            _core.VariableUtils.AddDof(self.main_model_part, _core.GetVariable(dof), _core.GetVariable(reaction))

    def _create_strategy(self):
        s = self.settings
        part = self.GetComputingModelPart()
        if self.explicit:
            self._check_explicit_on_one_process()
            self.mortar_updater = _core.ContactMortarUpdater()
            return _core.ExplicitPenaltyContactStrategy(part, _core.ExplicitCentralDifferencesScheme(),
                                                        self.mortar_updater,
                                                        compute_reactions=s["compute_reactions"].GetBool(),
                                                        move_mesh=s["move_mesh_flag"].GetBool(),
                                                        echo_level=self.echo_level,
                                                        pure_slip=self._formulation_of_run().pure_slip)
        if s["step_splitting"].size() > 0:
            raise _core.InputError(f"{s.Where()}.step_splitting: the contact solvers split steps with Kratos' "
                                   "contact_settings keys adaptative_strategy, split_factor and max_number_splits")
        updater = _core.ContactMortarUpdater()
        self.mortar_updater = updater  # its timings are read by the benchmarks
        criteria = create_contact_convergence_criteria(s, self._formulation_of_run(), self.echo_level, updater)
        linear_solver = self._linear_solver()
        self.contact_linear_solver = linear_solver  # the tests read whether MixedULM condensed
        initialize, finalize = self.sub_step_callbacks
        return create_contact_strategy(part, s, self._create_scheme(part), linear_solver, criteria,
                                       self.echo_level, updater, initialize, finalize)

    def _formulation_of_run(self):
        """The formulation whose active set runs: a frictional one whose interfaces all have a zero
        friction coefficient is its pure-slip variant (registered as "<mortar_type>PureSlip"), as
        Kratos' solver decides once the contact processes have built the interfaces."""
        root = self.main_model_part
        if self.formulation.pure_slip or not root.HasSubModelPart("Contact") or \
                not is_pure_slip(self.formulation, root.GetSubModelPart("Contact")):
            return self.formulation
        return _core.ContactFormulation.Get(self.formulation.mortar_type + "PureSlip")

    def _new_linear_solver(self):
        """The user's solver, optionally rescaled, wrapped in the condensing MixedULM solver for the
        vector-multiplier formulations (spec 2.7.1): the scalar system cannot be condensed."""
        s = self.settings
        contact = s["contact_settings"]
        settings = s["linear_solver_settings"].Clone()
        if contact["rescale_linear_solver"].GetBool():
            if not settings.Has("scaling"):
                settings.AddValue("scaling", _core.Parameters("false"))
            settings["scaling"].SetBool(True)
        linear_solver = self._large_3d_linear_solver(settings) or _core.CreateLinearSolver(settings)
        if linear_solver.Processes() > 1:
            # A rank holds only part of each row: condensing node by node needs whole rows. PETSc
            # solves the saddle-point system as it is (MUMPS, or the field split of the multipliers).
            if contact["condn_convergence_criterion"].GetBool():
                raise _core.NotImplementedFeatureError(
                    f"{contact.Where()}.condn_convergence_criterion: the condition number needs the whole "
                    f"matrix, which a run on {linear_solver.Processes()} processes does not assemble anywhere")
            return linear_solver
        mixed = contact["mixed_ulm_solver_parameters"]
        if self.formulation.condensable and contact["use_mixed_ulm_solver"].GetBool():
            if mixed["solver_type"].GetString() == "mixed_ulm_linear_solver":
                return _core.CreateMixedULMLinearSolver(linear_solver)
            warn(f"{mixed.Where()}.solver_type: \"{mixed['solver_type'].GetString()}\" is not "
                 "\"mixed_ulm_linear_solver\": the contact system is solved without condensation")
        return linear_solver

    def _large_3d_linear_solver(self, settings):
        """PETSc's field split instead of UMFPACK for a 3D problem of the scalar frictionless
        multipliers from LARGE_3D_EQUATIONS on, when the case names no solver or one of Kratos'
        direct ones and the PETSc plugin is built: a sparse LU of such a saddle-point system grows
        like n^2 in time and n^1.5 in memory (hertz3d_50k: 5.6 min of CPU and 1.2 GB, the field
        split 21 s and 0.43 GB). Same Newton iterations; the answers differ within the Newton
        tolerances (each linear solve stops at 1e-8 of its residual). None when the user's
        settings stand."""
        given = settings["solver_type"].GetString() if settings.Has("solver_type") else ""
        chosen = bool(given) and _core.NormalizeLinearSolverName(given) not in KRATOS_DIRECT_SOLVERS
        # Row scaling, or our key of the sparse LU, configure the direct solver: it stays.
        configured = settings.Has("reuse_factorization") or (settings.Has("scaling") and settings["scaling"].GetBool())
        measured = (self.domain_size == 3 and not self.formulation.frictional
                    and self.formulation.multiplier == "LAGRANGE_MULTIPLIER_CONTACT_PRESSURE")
        if chosen or configured or not measured or _core.LaunchedProcesses() > 1:
            return None
        part = self.main_model_part
        slaves = part.GetSubModelPart("Contact").NumberOfNodes() if part.HasSubModelPart("Contact") else 0
        equations = 3 * part.NumberOfNodes() + slaves
        if equations < LARGE_3D_EQUATIONS:
            return None
        large = _core.Parameters(LARGE_3D_LINEAR_SOLVER)
        try:
            solver = _core.CreateLinearSolver(large)
        except _core.NotImplementedFeatureError:  # PETSc plugin not built
            return None
        print(f"{settings.Where()}: 3D contact of about {equations} equations: PETSc field split (FGMRES, "
              f"multigrid on the displacements) instead of {given or 'the default direct solver'} "
              '(\"solver_type\": \"umfpack\" keeps the direct solver)')
        return solver

    def ComputeDeltaTime(self, time: float) -> float:
        """Explicit: the time step times delta_time_factor_for_contact while the last step had a
        node in contact (the model part's CONTACT flag, set by the explicit strategy), as Kratos."""
        dt = super().ComputeDeltaTime(time)
        if self.explicit and self.main_model_part.Is(_core.CONTACT):
            dt *= self.settings["contact_settings"]["delta_time_factor_for_contact"].GetDouble()
        return dt

    def critical_time_step(self) -> tuple[float, str]:
        dt, what = super().critical_time_step()
        with_contact = self.strategy.ContactStableTimeStep(dt)
        penalty = self.main_model_part.ProcessInfo.GetValue(_core.INITIAL_PENALTY)
        # Not divided by delta_time_factor_for_contact: the factor acts from the step after the
        # first contact, and the step on which a node closes is taken at the full time_step.
        return (min(dt, with_contact),
                f"{what}; with the contact penalty (INITIAL_PENALTY {penalty:.3g}) {with_contact:.3g}")

    def Initialize(self) -> None:
        super().Initialize()
        if self.settings["contact_settings"]["silent_strategy"].GetBool():
            self.strategy.SetEchoLevel(0)
