"""The structural solver: model import, variables and DoFs, and the C++ strategy built from
``solver_settings`` (static, implicit dynamic with Bossak / Newmark, explicit central differences)."""
from __future__ import annotations

import glob
import json
import os

from .. import _core
from ..processes.model_part_resolution import resolve_model_part
from ..ranks import Ranks
from ..restart import Checkpoint, mesh_record, restart_file_name, restart_folder
from ..utilities import nearest, warn
from .convergence_history import ConvergenceHistory
from .mesh_checks import check_imported_mesh
from .meshio_import import GROUP_KEYS as MESHIO_KEYS
from .meshio_import import import_mesh, read_mesh

BASE_VARIABLES = ["DISPLACEMENT", "REACTION", "POSITIVE_FACE_PRESSURE", "NEGATIVE_FACE_PRESSURE",
                  "POINT_LOAD", "LINE_LOAD", "SURFACE_LOAD", "VOLUME_ACCELERATION"]
ROTATION_VARIABLES = ["ROTATION", "REACTION_MOMENT", "POINT_MOMENT"]
DYNAMIC_VARIABLES = ["VELOCITY", "ACCELERATION"]
IMPLICIT_SCHEMES = ("bossak", "newmark", "pseudo_static", "backward_euler", "bdf1", "bdf2", "bdf3", "bdf4",
                    "bdf5", "relaxation")
#: extensions of mesh files that input_type "mdpa" cannot read
MESHIO_EXTENSIONS = (".msh", ".med", ".inp", ".vtu", ".vtk", ".xdmf", ".xmf", ".h5m", ".mesh", ".obj", ".stl")
CRITERIA = ("displacement_criterion", "residual_criterion", "and_criterion", "or_criterion")


class MechanicalSolver:
    #: convergence_criterion values this solver builds (None: resolved later by a factory)
    criteria_names = CRITERIA

    def __init__(self, model: _core.Model, settings: _core.Parameters, *, dynamic: bool, explicit: bool,
                 case_dir: str | None = None):
        self.model = model
        self.case_dir = case_dir
        self.settings = settings
        self.dynamic = dynamic
        self.explicit = explicit
        self.echo_level = settings["echo_level"].GetInt()
        name = settings["model_part_name"].GetString()
        self.main_model_part = model.GetModelPart(name) if model.HasModelPart(name) else model.CreateModelPart(name)
        self.domain_size = settings["domain_size"].GetInt()
        self.main_model_part.ProcessInfo.SetValue(_core.DOMAIN_SIZE, self.domain_size)
        self.scheme_type = self._scheme_type()
        self._check_names()
        self.strategy = None
        self.pending_fixities = None
        self.checkpoint = None  # the restart checkpoint to resume from (input_type "rest")
        self.ranks = None  # a model cut across the ranks: gathers their results (CutModel)
        self.mesh_record = None  # the mesh file and its import settings, for checkpoints
        self.mesh_path = None  # the mesh file read, named in errors about its entities
        self.sub_step_callbacks = (None, None)
        self._early_linear_solver = None  # made by _read_piece or CutModel, taken by _create_strategy
        self.piece_bodies = None  # a rank read its piece: the interface's bodies (_read_piece)
        self.piece_counts = None  # and each rank's (nodes, elements) read
        self._time_step_checked = False
        self._predicted_time_step = None  # (time step, steps since it was predicted)
        self.convergence_history = ConvergenceHistory.from_settings(settings["convergence_history"])
        self.AddVariables()

    # -- set-up -------------------------------------------------------------------------------
    def _scheme_type(self) -> str:
        requested = self.settings["scheme_type"].GetString()
        if self.explicit:
            scheme = requested or "central_differences"
            if scheme != "central_differences":
                raise _core.InputError(f"{self.settings.Where()}.scheme_type: the explicit solver supports "
                                       f"\"central_differences\", got \"{scheme}\"")
            return scheme
        if not self.dynamic:
            return "static"
        scheme = requested or "bossak"
        if scheme not in IMPLICIT_SCHEMES:
            raise _core.InputError(f"{self.settings.Where()}.scheme_type: unknown scheme \"{scheme}\""
                                   f"{nearest(scheme, IMPLICIT_SCHEMES)}")
        if scheme == "relaxation":
            raise _core.NotImplementedFeatureError(f"{self.settings.Where()}.scheme_type: \"{scheme}\" is not "
                                                   "implemented; use \"bossak\", \"newmark\" or \"bdf1\"..\"bdf5\"")
        return scheme

    def _bdf_order(self) -> int:
        """The BDF order of the scheme (backward_euler is bdf1), 0 for the other schemes."""
        if self.scheme_type == "backward_euler":
            return 1
        return int(self.scheme_type[3:]) if self.scheme_type.startswith("bdf") else 0

    def _check_names(self) -> None:
        criterion = self.settings["convergence_criterion"].GetString().lower()
        self.settings["convergence_criterion"].SetString(criterion)
        if self.criteria_names is not None and criterion not in self.criteria_names:
            hint = " (contact criteria need contact_settings)" if "contact" in criterion else ""
            raise _core.InputError(f"{self.settings.Where()}.convergence_criterion: unknown criterion "
                                   f"\"{criterion}\"{nearest(criterion, CRITERIA)}{hint}")
        for key, valid in (("solving_strategy_settings", ("newton_raphson", "line_search", "arc_length")),
                           ("builder_and_solver_settings", ("block", "block_lagrange", "elimination"))):
            kind = self.settings[key]["type"].GetString()
            if kind not in valid:
                raise _core.InputError(f"{self.settings.Where()}.{key}.type: unknown \"{kind}\"{nearest(kind, valid)}")
        if self.settings["solving_strategy_settings"]["type"].GetString() == "arc_length":
            raise _core.NotImplementedFeatureError(f"{self.settings.Where()}.solving_strategy_settings.type: "
                                                   "\"arc_length\" is not implemented")
        analysis = self.settings["analysis_type"].GetString()
        if analysis not in ("linear", "non_linear"):
            raise _core.InputError(f"{self.settings.Where()}.analysis_type: expected \"linear\" or \"non_linear\", "
                                   f"got \"{analysis}\"")

    def AddVariables(self) -> None:
        names = list(BASE_VARIABLES)
        if self.settings["rotation_dofs"].GetBool():
            names += ROTATION_VARIABLES
        if self.dynamic:
            names += DYNAMIC_VARIABLES
            if self.settings["rotation_dofs"].GetBool():
                names += ["ANGULAR_VELOCITY", "ANGULAR_ACCELERATION"]
        if self.explicit:
            names += ["FORCE"]
        names += self.settings["auxiliary_variables_list"].GetStringArray()
        aux_dofs = self.settings["auxiliary_dofs_list"].GetStringArray()
        aux_reactions = self.settings["auxiliary_reaction_list"].GetStringArray()
        if len(aux_dofs) != len(aux_reactions):
            raise _core.InputError(f"{self.settings.Where()}: auxiliary_dofs_list and auxiliary_reaction_list "
                                   "must have the same length")
        names += aux_dofs + aux_reactions
        for name in names:
            self.main_model_part.AddNodalSolutionStepVariable(_core.GetVariable(name))

    def minimum_buffer_size(self) -> int:
        # A BDF scheme of order p differentiates over p + 1 buffer positions (spec 2.5); the
        # extrapolating static predictor reads the last two steps.
        return max(2, self._bdf_order() + 1, 3 if self._extrapolates() else 2)

    def _extrapolates(self) -> bool:
        """Whether the static scheme extrapolates the last two steps (``displacement_extrapolation``,
        mortarcontact's key: a non-linear static analysis only)."""
        s = self.settings
        return (self.scheme_type in ("static", "pseudo_static") and s["analysis_type"].GetString() == "non_linear"
                and s["displacement_extrapolation"].GetBool())

    def ImportModelPart(self, kept_whole: list[str] | None = None) -> None:
        """Reads the mesh named by ``model_import_settings``: ``input_type`` ``"mdpa"`` (Kratos), or
        mortarcontact's ``"gmsh"`` / ``"meshio"`` with ``element_names``, ``condition_names`` and
        ``properties_ids`` (see ``solvers/meshio_import.py``), then the materials. ``"rest"`` opens
        the checkpoint named by ``input_filename``, ``restart_load_file_label``,
        ``input_output_path`` and ``load_restart_files_from_folder`` (Kratos' keys) and reads the
        mesh it was written for; the analysis stage restores the state after the set-up.
        ``kept_whole``: each rank of a model cut across the ranks reads only its piece of an mdpa,
        keeping these model parts whole (``process_factory.parts_kept_whole``)."""
        imports = self.settings["model_import_settings"]
        # Nodes are created with the buffer in force, so it is set before the mesh is read.
        self.main_model_part.SetBufferSize(max(self.settings["buffer_size"].GetInt(), self.minimum_buffer_size()))
        if imports["input_type"].GetString() == "rest":
            self.checkpoint = self._open_checkpoint(imports)
            recorded = {k: v for k, v in self.checkpoint.mesh.items() if k not in ("mesh_file", "sha256")}
            # The file the saved run read; its own relative name when the case has moved since.
            if os.path.isfile(self.checkpoint.mesh["mesh_file"]):
                recorded["input_filename"] = self.checkpoint.mesh["mesh_file"]
            path = self._import_mesh(_core.Parameters(json.dumps(recorded), f"{self.checkpoint.path} (mesh)"))
            self.checkpoint.check_mesh_file(path)
            self.mesh_record = self.checkpoint.mesh
        else:
            path = self._import_mesh(imports, kept_whole)
            self.mesh_record = mesh_record(imports, path) if path is not None else None
        self.mesh_path = path
        self._import_materials()

    def _open_checkpoint(self, imports) -> Checkpoint:
        where = imports.Where()
        label = imports["restart_load_file_label"].GetString()
        if not label:
            raise _core.InputError(f"{where}.restart_load_file_label: required for input_type \"rest\" (the time "
                                   "or step in the checkpoint's name, e.g. \"0.5\" for Structure_0.5.rest)")
        name = imports["input_filename"].GetString() or self.main_model_part.Name
        folder, stem = restart_folder(name, imports["input_output_path"].GetString(),
                                      imports["load_restart_files_from_folder"].GetBool())
        path = os.path.relpath(os.path.join(folder, restart_file_name(stem, label)))
        found = self._find(path)
        if found is None:
            places = {os.path.dirname(candidate) or "." for candidate in self._candidates(path)}
            saved = sorted({os.path.basename(match) for place in places
                            for match in glob.glob(os.path.join(place, f"{stem}_*.rest"))})
            raise _core.InputError(f"{where}: restart checkpoint not found; looked for "
                                   + " and ".join(os.path.abspath(c) for c in self._candidates(path))
                                   + (f"{nearest(os.path.basename(path), saved)}; saved: {', '.join(saved)}" if saved
                                      else "; no checkpoints of that name were saved there"))
        return Checkpoint(found)

    def _import_mesh(self, imports, kept_whole: list[str] | None = None) -> str | None:
        """Reads the mesh of an mdpa / gmsh / meshio ``imports`` block; the file read, or None.
        With ``kept_whole``, this rank's piece of an mdpa (``_read_piece``)."""
        where = imports.Where()
        input_type = imports["input_type"].GetString()
        if input_type in ("mdpa", "gmsh", "meshio") and not imports["input_filename"].GetString():
            raise _core.InputError(f"{where}.input_filename: required for input_type \"{input_type}\"")
        filename = imports["input_filename"].GetString()
        if input_type == "mdpa":
            given = [key for key in MESHIO_KEYS if imports[key].size() > 0]
            if given:
                raise _core.InputError(f"{where}.{given[0]}: only for input_type \"gmsh\" or \"meshio\", "
                                       "not \"mdpa\" (an mdpa names its elements itself)")
            if (os.path.splitext(filename)[1].lower() in MESHIO_EXTENSIONS
                    and self._find(filename + ".mdpa") is None):
                raise _core.InputError(f"{where}.input_filename: \"{filename}\" is not an mdpa (input_type "
                                       "\"mdpa\" adds .mdpa to the name); read it with input_type \"gmsh\" "
                                       "or \"meshio\"")
            path = self._locate(filename if filename.endswith(".mdpa") else filename + ".mdpa",
                                f"{where}.input_filename")
            ignore = imports["ignore_variables_not_in_solution_step_data"].GetBool()
            if kept_whole is not None:
                self._read_piece(path, ignore, kept_whole)
                return path
            self.pending_fixities = _core.ReadModelPart(self.main_model_part, path, ignore)
            check_imported_mesh(self.main_model_part, path)
            return path
        if input_type in ("gmsh", "meshio"):
            path = self._locate(filename, f"{where}.input_filename")
            mesh, node_ids = read_mesh(path, input_type, where)
            import_mesh(self.main_model_part, mesh, node_ids, imports, self.domain_size, path)
            check_imported_mesh(self.main_model_part, path)
            return path
        if input_type != "use_input_model_part":
            valid = ("mdpa", "gmsh", "meshio", "rest", "use_input_model_part")
            raise _core.NotImplementedFeatureError(f"{where}.input_type: \"{input_type}\" is not supported"
                                                   f"{nearest(input_type, valid)}; valid: {', '.join(valid)}")
        return None

    def _read_piece(self, path: str, ignore: bool, kept_whole: list[str]) -> None:
        """Each rank builds only its piece of the mdpa (issue 17): every rank streams the file's
        connectivity, rank 0 partitions it with METIS as it would the model read whole, and each
        rank reads the entities touching its nodes, the parts ``kept_whole`` (the contact
        interfaces) and what touches their nodes, which the interfaces are built from. The linear
        solver is made first, for its communicator. A bad line stops every rank at the same line;
        an error found on one rank's piece alone stops them all with that rank's message."""
        self._check_explicit_on_one_process()
        self._early_linear_solver = self._new_linear_solver()
        self.ranks = Ranks(self._early_linear_solver)
        piece, body_of, labels = _core.PlanModelPartPiece(self.main_model_part, path, self._early_linear_solver,
                                                          kept_whole)
        self.piece_bodies = (body_of, labels)

        def read() -> None:
            part = self.main_model_part
            self.pending_fixities = _core.ReadModelPart(part, path, ignore, piece)
            check_imported_mesh(part, path, self.ranks.owned_node_ids(part))

        self.ranks.stop_together(read)
        part = self.main_model_part
        self.piece_counts = self.ranks.all_gather((part.NumberOfNodes(), part.NumberOfElements()))

    def _import_materials(self) -> None:
        filename = self.settings["material_import_settings"]["materials_filename"].GetString()
        if not filename:
            return
        filename = self._locate(filename, f"{self.settings['material_import_settings'].Where()}.materials_filename")
        materials = _core.Parameters.FromFile(filename)
        try:
            if materials.Has("properties"):
                for i in range(materials["properties"].size()):
                    entry = materials["properties"][i]
                    if entry.Has("model_part_name"):
                        part = resolve_model_part(self.model, entry["model_part_name"].GetString())
                        entry["model_part_name"].SetString(part.FullName())
            _core.ReadMaterials(self.model, materials, filename)
        except _core.InputError as error:
            if filename in str(error):
                raise
            raise _core.InputError(f"{filename}: {error}") from None

    def _find(self, filename: str) -> str | None:
        """A case's input file: relative to the working directory (Kratos' rule), else to the case folder."""
        for candidate in self._candidates(filename):
            if os.path.isfile(candidate):
                return candidate
        return None

    def _candidates(self, filename: str) -> list[str]:
        candidates = [filename]
        if self.case_dir and not os.path.isabs(filename):
            beside = os.path.join(self.case_dir, filename)
            if os.path.abspath(beside) != os.path.abspath(filename):
                candidates.append(beside)
        return candidates

    def _locate(self, filename: str, key: str) -> str:
        found = self._find(filename)
        if found is None:
            raise _core.InputError(f"{key}: file not found; looked for "
                                   + " and ".join(os.path.abspath(c) for c in self._candidates(filename)))
        return found

    def AddDofs(self) -> None:
        part = self.main_model_part
        pairs = [("DISPLACEMENT_X", "REACTION_X"), ("DISPLACEMENT_Y", "REACTION_Y"), ("DISPLACEMENT_Z", "REACTION_Z")]
        if self.settings["rotation_dofs"].GetBool():
            pairs += [(f"ROTATION_{c}", f"REACTION_MOMENT_{c}") for c in "XYZ"]
        aux_dofs = self.settings["auxiliary_dofs_list"].GetStringArray()
        aux_reactions = self.settings["auxiliary_reaction_list"].GetStringArray()
        pairs += list(zip(aux_dofs, aux_reactions))
        for dof, reaction in pairs:
            _core.VariableUtils.AddDof(part, _core.GetVariable(dof), _core.GetVariable(reaction))
        if self.pending_fixities is not None:
            self.pending_fixities.Apply()

    def GetComputingModelPart(self):
        name = self.settings["computing_sub_model_part_name"].GetString()
        return resolve_model_part(self.model, f"{self.main_model_part.Name}.{name}") if name else self.main_model_part

    # -- strategy -----------------------------------------------------------------------------
    def set_sub_step_callbacks(self, initialize, finalize) -> None:
        """The processes' per-step hooks, re-run in the sub-steps of a split step."""
        self.sub_step_callbacks = (initialize, finalize)

    def Initialize(self) -> None:
        self.strategy = self._create_strategy()
        self.strategy.Initialize()

    def CutModel(self, processes) -> dict:
        """Under mpirun with MORTARCONTACT_PARTITIONED_MODEL=1 (issue 17, step 3), after the
        processes' ExecuteInitialize: cuts the whole model to this rank's piece. The linear solver
        is made first, on the whole model: its communicator partitions the nodes, and what it
        decides from the model's size is what the serial run decides. Each process computes what
        needs the whole model (ExecuteBeforeModelCut) and names the parts every rank keeps whole.
        Returns the piece's counts; ``self.ranks`` then gathers the pieces' results."""
        self._check_explicit_on_one_process()
        if self.checkpoint is not None:
            # Checked (the whole model, or a piece read: its nodes among the saved ones), restored
            # after the set-up on each piece (its nodes' rows), as a serial resumed run restores the
            # whole model after its set-up.
            self.checkpoint.check_model(self.main_model_part, piece=self.piece_counts is not None)
        if self._early_linear_solver is None:  # else made to read the rank's piece
            self._early_linear_solver = self._new_linear_solver()
            self.ranks = Ranks(self._early_linear_solver)
        replicated = [part for process in processes for part in process.ExecuteBeforeModelCut(self.piece_bodies)]
        piece = {}
        # A piece read may hold what the cut refuses (master-slave constraints) on some ranks only.
        self.ranks.stop_together(lambda: piece.update(
            _core.CutModelPart(self.main_model_part, self._early_linear_solver, replicated)))
        return piece

    def _linear_solver(self):
        """The linear solver CutModel made, else a new one."""
        solver, self._early_linear_solver = self._early_linear_solver, None
        return solver if solver is not None else self._new_linear_solver()

    def _new_linear_solver(self):
        return _core.CreateLinearSolver(self.settings["linear_solver_settings"])

    def _create_strategy(self):
        s = self.settings
        part = self.GetComputingModelPart()
        self._check_explicit_on_one_process()
        linear_solver = self._linear_solver()
        if self.explicit:
            return _core.ExplicitStrategy(part, _core.ExplicitCentralDifferencesScheme(),
                                          compute_reactions=s["compute_reactions"].GetBool(),
                                          reform_dofs_at_each_step=s["reform_dofs_at_each_step"].GetBool(),
                                          move_mesh=s["move_mesh_flag"].GetBool(), echo_level=self.echo_level)
        scheme = self._create_scheme(part)
        kind = s["builder_and_solver_settings"]["type"].GetString()
        builder = (_core.BlockBuilderAndSolver(linear_solver) if kind == "block"
                   else _core.EliminationBuilderAndSolver(linear_solver))
        common = {"compute_reactions": s["compute_reactions"].GetBool(),
                  "reform_dofs_at_each_step": s["reform_dofs_at_each_step"].GetBool(),
                  "move_mesh": s["move_mesh_flag"].GetBool(), "echo_level": self.echo_level}
        if s["analysis_type"].GetString() == "linear":
            return _core.LinearStrategy(part, scheme, builder, **common)
        criteria = self._create_criteria()
        newton = dict(max_iteration=s["max_iteration"].GetInt(),
                      use_old_stiffness_in_first_iteration=s["use_old_stiffness_in_first_iteration"].GetBool(),
                      **common)
        if s["solving_strategy_settings"]["type"].GetString() == "line_search":
            newton.pop("use_old_stiffness_in_first_iteration")
            strategy = _core.LineSearchStrategy(part, scheme, criteria, builder,
                                                settings=self._line_search_settings(), **newton)
        else:
            strategy = _core.NewtonRaphsonStrategy(part, scheme, criteria, builder, **newton)
        # mortarcontact's cut-back (Kratos' structural strategies have none): the step restarts
        # as split_factor^s sub-steps, with the processes' hooks run around each.
        strategy.SetStepSplitting(s["step_splitting"])
        strategy.SetSubStepCallbacks(*self.sub_step_callbacks)
        return strategy

    def _check_explicit_on_one_process(self) -> None:
        if self.explicit and _core.LaunchedProcesses() > 1:
            raise _core.NotImplementedFeatureError(
                f"{self.settings.Where()}.time_integration_method: explicit dynamics on {_core.LaunchedProcesses()} "
                "processes (mpirun): it has no linear system to distribute; run it on one process")

    def _create_scheme(self, part):
        s = self.settings
        process_info = part.ProcessInfo
        process_info.SetValue(_core.RAYLEIGH_ALPHA, s["rayleigh_alpha"].GetDouble())
        process_info.SetValue(_core.RAYLEIGH_BETA, s["rayleigh_beta"].GetDouble())
        if self.scheme_type == "static" or self.scheme_type == "pseudo_static":
            scheme = _core.StaticScheme(extrapolate=self._extrapolates())
        elif self._bdf_order():
            scheme = _core.BDFScheme(order=self._bdf_order())
        elif self.scheme_type == "newmark":
            scheme = _core.BossakScheme(alpha_m=0.0, newmark_beta=s["newmark_beta"].GetDouble())
        else:
            # Bossak's beta = (1 - alpha)^2 / 4 follows from alpha_m; newmark_beta is for Newmark only.
            scheme = _core.BossakScheme(alpha_m=s["damp_factor_m"].GetDouble())
        return scheme

    def _line_search_settings(self):
        """Line-search keys of solving_strategy_settings.advanced_settings (Kratos' names)."""
        advanced = self.settings["solving_strategy_settings"]["advanced_settings"]
        settings = _core.LineSearchSettings()
        for key in advanced.keys():  # noqa: SIM118 (a Parameters, not a dict: keys() insists on an object)
            if not hasattr(settings, key):
                valid = [k for k in dir(settings) if not k.startswith("_")]
                raise _core.InputError(f"{advanced.Where()}: unknown key '{key}'{nearest(key, valid)}")
            value = advanced[key]
            setattr(settings, key, value.GetInt() if key == "max_line_search_iterations" else value.GetDouble())
        return settings

    def _create_criteria(self):
        s = self.settings
        name = s["convergence_criterion"].GetString()
        displacement = _core.DisplacementCriteria(s["displacement_relative_tolerance"].GetDouble(),
                                                  s["displacement_absolute_tolerance"].GetDouble())
        residual = _core.ResidualCriteria(s["residual_relative_tolerance"].GetDouble(),
                                          s["residual_absolute_tolerance"].GetDouble())
        criteria = {"displacement_criterion": lambda: displacement,
                    "residual_criterion": lambda: residual,
                    "and_criterion": lambda: _core.AndCriteria(residual, displacement),
                    "or_criterion": lambda: _core.OrCriteria(residual, displacement)}[name]()
        criteria.SetEchoLevel(self.echo_level)
        return criteria

    # -- time loop ----------------------------------------------------------------------------
    def ComputeDeltaTime(self, time: float) -> float:
        if self.explicit and self.settings["time_step_prediction_level"].GetInt() > 0:
            return self._predict_time_step()
        stepping = self.settings["time_stepping"]
        where = stepping.Where()
        if stepping.Has("time_step"):
            return stepping["time_step"].GetDouble()
        if stepping.Has("time_step_table"):
            table = stepping["time_step_table"].GetMatrix()
            import numpy as np

            return float(np.interp(time, table[:, 0], table[:, 1]))
        if stepping.Has("time_step_intervals"):
            intervals = stepping["time_step_intervals"]
            for key in intervals.keys():  # noqa: SIM118 (a Parameters, not a dict: keys() insists on an object)
                item = intervals[key]
                start = item["interval"][0].GetDouble()
                end_item = item["interval"][1]
                end = float("inf") if end_item.IsString() and end_item.GetString() == "End" else end_item.GetDouble()
                if start <= time < end:
                    return item["time_step"].GetDouble()
            raise _core.InputError(f"{where}.time_step_intervals: no interval contains time {time}")
        raise _core.InputError(f"{where}: give time_step, time_step_table or time_step_intervals")

    def AdvanceInTime(self, time: float) -> float:
        dt = self.ComputeDeltaTime(time)
        if not dt > 0.0:
            raise _core.InputError(f"{self.settings['time_stepping'].Where()}: the time step must be positive, "
                                   f"got {dt}")
        new_time = time + dt
        self.main_model_part.CloneTimeStep(new_time)
        return new_time

    def InitializeSolutionStep(self) -> None:
        self.strategy.InitializeSolutionStep()
        if self.explicit and not self._time_step_checked:
            self._time_step_checked = True  # once the lumped masses exist
            self._check_time_step()

    def _predict_time_step(self) -> float:
        """time_step_prediction_level 1: fraction_delta_time x the critical time step (bounded by
        max_delta_time), once, before the first step; 2 and above: again every delta_time_refresh
        steps (the critical step follows the penalty springs of the contact nodes and the
        stiffness of the current state). time_stepping is not read then."""
        s = self.settings
        if self._predicted_time_step is not None:
            dt, steps = self._predicted_time_step
            if s["time_step_prediction_level"].GetInt() < 2 or steps < s["delta_time_refresh"].GetInt():
                self._predicted_time_step = (dt, steps + 1)
                return dt
        else:
            self.strategy.SetUpDofsAndMass()  # the masses of the estimates
        critical, how = self.critical_time_step()
        dt = min(s["max_delta_time"].GetDouble(), s["fraction_delta_time"].GetDouble() * critical)
        if self._predicted_time_step is None and self.echo_level >= 1:
            print(f"{s.Where()}.time_step_prediction_level {s['time_step_prediction_level'].GetInt()}: time step "
                  f"{dt:.4g} (fraction_delta_time {s['fraction_delta_time'].GetDouble():.3g} of the critical "
                  f"time step: {how}; max_delta_time {s['max_delta_time'].GetDouble():g})")
        self._predicted_time_step = (dt, 1)
        return dt

    def critical_time_step(self) -> tuple[float, str]:
        """Explicit: the largest stable time step and how it was estimated (the elements' bound)."""
        dt = self.strategy.ElementStableTimeStep()
        return dt, f"elements (2 / omega_max, element by element) {dt:.3g}"

    def _check_time_step(self) -> None:
        """Central differences diverge above 2 / omega_max: say so before the run blows up."""
        stepping = self.settings["time_stepping"]
        if not stepping.Has("time_step") or self.settings["time_step_prediction_level"].GetInt() > 0:
            return
        time_step = stepping["time_step"].GetDouble()
        critical, how = self.critical_time_step()
        if time_step > critical:
            warn(f"{stepping.Where()}.time_step = {time_step:g} exceeds the critical time step of central differences "
                 f"{critical:.3g} ({how}): the explicit solution will diverge")

    def Predict(self) -> None:
        self.strategy.Predict()

    def SolveSolutionStep(self) -> bool:
        converged = self.strategy.SolveSolutionStep()
        if self.convergence_history:
            step = self.main_model_part.ProcessInfo.GetValue(_core.STEP)
            self.convergence_history.add_step(step, self.strategy.GetIterationHistory())
        return converged

    def FinalizeSolutionStep(self) -> None:
        self.strategy.FinalizeSolutionStep()

    def RestartState(self) -> dict | None:
        """What the strategy carries from step to step beyond the model part's state, for a restart
        checkpoint (JSON-compatible; None: nothing)."""
        return None

    def LoadRestartState(self, state: dict) -> None:
        """Takes back what ``RestartState()`` returned, in a resumed run after ``Initialize``."""

    def ResetLinearSolver(self) -> None:
        """The next linear solve starts without the factorizations kept from earlier steps, as a
        run resumed here does (restart checkpoints call it)."""
        if self.strategy is not None:
            self.strategy.GetBuilderAndSolver().ResetLinearSolver()

    def Check(self) -> None:
        try:
            self.strategy.Check()
        except _core.InputError as error:
            # The elements and conditions name themselves ("element 7 (...) is inverted ..."); the
            # file they were read from is only known here.
            message = str(error)
            if self.mesh_path and message.startswith(("element ", "condition ")):
                raise _core.InputError(f"{self.mesh_path}: {message}") from None
            raise

    def Finalize(self) -> None:
        if self.convergence_history:
            self.convergence_history.finish()
        self.strategy.Clear()

    def OutputFiles(self) -> list[str]:
        """The convergence history files written so far."""
        return list(self.convergence_history.written) if self.convergence_history else []

    def LastIterationCount(self) -> int:
        return self.strategy.GetIterationNumber()

    def LastIterationHistory(self):
        return self.strategy.GetIterationHistory()
