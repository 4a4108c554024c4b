"""The analysis stage: runs a Kratos-format case in the order of spec 1.7.

construct:  read and migrate ProjectParameters.json, choose and validate the solver, add variables
Initialize: import mdpa (under mpirun with MORTARCONTACT_PARTITIONED_MODEL=1 each rank reads its piece)
            and materials, add DoFs, create the processes (lists in alphabetical
            order of their names, file order inside a list; outputs last), ExecuteInitialize,
            [under mpirun with MORTARCONTACT_PARTITIONED_MODEL=1: the model cut to the rank's piece],
            solver Initialize, Check, ExecuteBeforeSolutionLoop
each step:  advance time, ExecuteInitializeSolutionStep, solver InitializeSolutionStep, Predict,
            SolveSolutionStep, solver FinalizeSolutionStep, ExecuteFinalizeSolutionStep, output
Finalize:   ExecuteFinalize, solver Finalize
A resumed run (model_import_settings.input_type "rest") does all of Initialize, then overwrites the
state with the checkpoint's and goes on from its TIME and STEP.
"""
from __future__ import annotations

import json
import os
import time as wallclock
from contextlib import contextmanager

from . import _core
from .process_factory import create_process_lists, naming_the_item, parts_kept_whole
from .project_parameters import migrate_project_parameters, read_project_parameters
from .restart import attach_run
from .solvers import create_solver
from .utilities import partitioned_model, secondary_process, warn


class ConvergenceFailure(_core.SolutionError):
    """Newton did not converge in a step (the message gives the step, time, iterations and norms)."""


class StructuralMechanicsAnalysis:
    """Runs one case. ``model`` may be shared with other stages; ``parameters`` are the migrated
    project parameters (see ``read_project_parameters``)."""

    def __init__(self, model: _core.Model, parameters: _core.Parameters, *, progress: bool = True,
                 stop_on_non_convergence: bool = True, case_dir: str | None = None):
        self.model = model
        self.parameters = parameters
        problem_data = parameters["problem_data"]
        self.echo_level = problem_data["echo_level"].GetInt()
        self.start_time = problem_data["start_time"].GetDouble()
        self.end_time = problem_data["end_time"].GetDouble()
        self.problem_name = problem_data["problem_name"].GetString()
        self.progress = progress
        self.stop_on_non_convergence = stop_on_non_convergence
        # A new run: settings without effect are reported again, once each.
        _core.NoEffectWarnings.Reset()
        self.solver = create_solver(model, parameters["solver_settings"], case_dir=case_dir)
        self.processes = []
        self.output_processes = []
        self.time = self.start_time
        self.step = 0
        self.step_log = []  # (step, time, iterations, converged, seconds)

    # -- driver -----------------------------------------------------------------------------
    def Run(self) -> None:
        self.Initialize()
        try:
            self.RunSolutionLoop()
        except _core.SolutionError:
            # The results of the converged steps are kept: processes that write only at the end
            # write now.
            for process in self._all_processes():
                process.ExecuteAfterFailure()
            raise
        self.Finalize()

    def Initialize(self) -> None:
        self.solver.ImportModelPart(kept_whole=self._parts_kept_whole())
        self.solver.AddDofs()
        self.processes = self._create_processes("processes")
        # Under mpirun the ranks hold the same model: only rank 0 writes it out. A model cut across
        # the ranks is written by every rank (its piece) and gathered: every rank makes them.
        writes = not secondary_process() or partitioned_model()
        self.output_processes = self._create_processes("output_processes") if writes else []
        attach_run(self._all_processes(), self.solver.mesh_record, self.solver)

        def initialize() -> None:
            for process in self._all_processes():
                with naming_the_item(getattr(process, "item_where", "")):
                    process.ExecuteInitialize()

        # On the ranks' pieces an error may show on some ranks only: all stop with it.
        initialize() if self.solver.ranks is None else self.solver.ranks.stop_together(initialize)
        if partitioned_model():
            self._cut_model()
        self.solver.set_sub_step_callbacks(self._initialize_sub_step, self._finalize_sub_step)
        self.solver.Initialize()
        self.Check()
        for process in self._all_processes():
            with naming_the_item(getattr(process, "item_where", "")):
                process.ExecuteBeforeSolutionLoop()
        checkpoint = self.solver.checkpoint
        if checkpoint is None:
            self.time = self.start_time
            self.solver.GetComputingModelPart().ProcessInfo.SetValue(_core.TIME, self.time)
            return
        # A resumed run: everything above was built as in a fresh run; the state is the checkpoint's.
        checkpoint.restore_model(self.solver.main_model_part, piece=partitioned_model())
        checkpoint.restore_processes(self._all_processes())
        checkpoint.restore_solver(self.solver)
        checkpoint.close()
        self.time, self.step = checkpoint.time, checkpoint.step

    def Check(self) -> None:
        self.solver.Check()
        for process in self._all_processes():
            with naming_the_item(getattr(process, "item_where", "")):
                process.Check()

    def KeepAdvancingSolutionLoop(self) -> bool:
        return self.time < self.end_time

    def RunSolutionLoop(self) -> None:
        with self._progress_display() as advance:
            while self.KeepAdvancingSolutionLoop():
                self._run_next_step(advance)

    def OpenStep(self, step: int) -> None:
        """Runs the steps before ``step`` as ``RunSolutionLoop`` does, then opens ``step`` (time
        advanced, processes and solver initialised, the prediction made) without solving it: to
        look inside a load step from a script, a notebook or a test. Next, e.g.,
        ``solver.strategy.SetMaxIterationNumber(k)`` and ``solver.SolveSolutionStep()`` to stop
        after k Newton iterations, or ``solver.strategy.BuildSystem(model_part)``. After
        ``Initialize``."""
        if step <= self.step:
            raise ValueError(f"step {step} is not after the current step {self.step}")
        while self.step + 1 < step:
            self._run_next_step(lambda *_: None)
        self._open_next_step()

    def _open_next_step(self) -> None:
        self.time = self.solver.AdvanceInTime(self.time)
        self.step += 1
        self.InitializeSolutionStep()
        self.solver.Predict()

    def _run_next_step(self, advance) -> None:
        started = wallclock.perf_counter()
        self._open_next_step()
        converged = self.solver.SolveSolutionStep()
        iterations = self.solver.LastIterationCount()
        if not converged:
            self._report_non_convergence()
        self.FinalizeSolutionStep()
        self.OutputSolutionStep()
        self.step_log.append((self.step, self.time, iterations, converged, wallclock.perf_counter() - started))
        advance(self.time, iterations)

    def InitializeSolutionStep(self) -> None:
        if self.echo_level >= 1 and not self.progress:
            print(f"STEP {self.step}  TIME {self.time:.6g}")
        self._initialize_processes_step()
        self.solver.InitializeSolutionStep()

    def FinalizeSolutionStep(self) -> None:
        self.solver.FinalizeSolutionStep()
        self._finalize_processes_step()

    def _initialize_processes_step(self) -> None:
        for process in self._all_processes():
            process.ExecuteInitializeSolutionStep()

    def _finalize_processes_step(self) -> None:
        for process in self._all_processes():
            process.ExecuteFinalizeSolutionStep()

    # The sub-steps of a split step need the boundary conditions, loads and contact search of
    # their time, but are no steps of the output: the output processes (whose step counters name
    # the files) see only the step they make up.
    def _initialize_sub_step(self) -> None:
        for process in self.processes:
            process.ExecuteInitializeSolutionStep()

    def _finalize_sub_step(self) -> None:
        for process in self.processes:
            process.ExecuteFinalizeSolutionStep()

    def OutputSolutionStep(self) -> None:
        writing = [p for p in self.output_processes if p.IsOutputStep()]
        if not writing:
            return
        for process in self._all_processes():
            process.ExecuteBeforeOutputStep()
        for process in sorted(writing, key=lambda p: p.after_other_outputs):
            process.PrintOutput()
        for process in self._all_processes():
            process.ExecuteAfterOutputStep()

    def Finalize(self) -> None:
        for process in self._all_processes():
            process.ExecuteFinalize()
        self.solver.Finalize()

    def Summary(self) -> str:
        """One paragraph on the finished run: steps, Newton iterations, time, files written."""
        steps = len(self.step_log)
        iterations = [entry[2] for entry in self.step_log]
        failed = sum(1 for entry in self.step_log if not entry[3])
        seconds = sum(entry[4] for entry in self.step_log)
        text = f"{self.problem_name or 'analysis'}: {steps} step{'s' if steps != 1 else ''} to t = {self.time:.6g}"
        if iterations and max(iterations) > 1:
            spread = f"{min(iterations)} to {max(iterations)}" if min(iterations) < max(iterations) else max(iterations)
            text += f", {sum(iterations)} Newton iterations ({spread} per step)"
        if failed:
            text += f", {failed} not converged"
        text += f", {seconds:.3g} s in the solution loop"
        files = [path for process in self._all_processes() for path in process.OutputFiles()]
        files += self.solver.OutputFiles()
        return text + (f"; wrote {', '.join(files)}" if files else "; no result files written")

    # -- helpers ----------------------------------------------------------------------------
    def _cut_model(self) -> None:
        """Each rank keeps its piece of the model from here on (docs/DESIGN.md, several processes);
        the processes are handed the ranks to gather their results from the pieces."""
        piece = self.solver.CutModel(self._all_processes())
        for process in self._all_processes():
            process.ExecuteAfterModelCut(self.solver.ranks)
        if self.echo_level >= 1:
            print(f"model cut across {_core.LaunchedProcesses()} processes; rank 0 keeps {piece['owned_nodes']} "
                  f"owned and {piece['ghost_nodes']} ghost nodes, {piece['elements']} elements")
            if self.solver.piece_counts is not None:
                print("each rank read its piece of the mesh: " + "; ".join(
                    f"rank {rank} {nodes} nodes, {elements} elements"
                    for rank, (nodes, elements) in enumerate(self.solver.piece_counts)))

    def _parts_kept_whole(self) -> list[str] | None:
        """A model cut across the ranks: the parts each rank reads whole beside its piece; None: the
        model is read whole (one process, or a process that needs every element, e.g. a contact
        interface over the skin of the whole model), then cut after ExecuteInitialize."""
        if not partitioned_model():
            return None
        return parts_kept_whole(self.parameters["processes"]) if self.parameters.Has("processes") else []

    def _all_processes(self):
        return [*self.processes, *self.output_processes]

    def _create_processes(self, block: str):
        return create_process_lists(self.parameters[block], self.model) if self.parameters.Has(block) else []

    def _report_non_convergence(self) -> None:
        history = self.solver.LastIterationHistory()
        last = history[-1] if history else None
        norms = f"; last iteration: {last}" if last else ""
        message = (f"step {self.step} (time {self.time:.6g}) did not converge in "
                   f"{self.solver.LastIterationCount()} iterations{norms}")
        # The strategy's own account names the nodes or elements at fault.
        report = getattr(self.solver.strategy, "FailureReport", None)
        if report is not None and report():
            message += f"\n  {report()}"
        if self.stop_on_non_convergence:
            raise ConvergenceFailure(message + ". The results of the last converged step were written.")
        warn(message)

    @contextmanager
    def _progress_display(self):
        if not self.progress:
            yield lambda t, it: None
            return
        from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

        columns = (TextColumn("[bold]{task.description}"), BarColumn(),
                   TextColumn("t = {task.completed:.4g} / {task.total:.4g}"),
                   TextColumn("step {task.fields[step]}, {task.fields[iterations]} it"), TimeElapsedColumn())
        with Progress(*columns, transient=False) as bar:
            task = bar.add_task(self.problem_name or "analysis", total=self.end_time - self.start_time,
                                step=0, iterations=0)
            _core.SetLogSink(lambda level, message: bar.console.print(message, markup=False, highlight=False))
            try:
                yield lambda t, it: bar.update(task, completed=min(t, self.end_time) - self.start_time,
                                               step=self.step, iterations=it)
            finally:
                _core.ResetLogSink()


class Analysis(StructuralMechanicsAnalysis):
    """A contact or structural analysis over a model, the public face of the analysis stage.

    ``Analysis(model, parameters)`` reads and checks the parameters and creates the solver, which
    creates the model part ``solver_settings.model_part_name`` (or takes the model's) and adds the
    historical variables and, at ``Initialize``, the DoFs the formulation needs. ``Run()`` is
    ``Initialize()``, ``RunSolutionLoop()`` and ``Finalize()``; ``Summary()`` describes the finished
    run. Results are read from ``model`` (``model["Structure"].GetNodalValues(mc.DISPLACEMENT)``).

    model: an ``mc.Model``; a model part built in Python is used as it is with
      ``"model_import_settings": {"input_type": "use_input_model_part"}``. Build it after creating
      the Analysis (its nodes need the solver's historical variables), e.g. with
      ``mc.import_meshio`` or ``ModelPart.CreateNewNodes`` / ``CreateNewElements``.
    parameters: the project parameters, as a dict, as a path of a ProjectParameters.json, or as an
      ``mc.Parameters``; the layout and keys of Kratos' ProjectParameters.json (reference:
      the documentation's parameter pages). Relative file names inside are looked up in the working
      directory, then next to the file.
    progress: show a progress bar (rich) and route the C++ log through it.
    stop_on_non_convergence: raise ``ConvergenceFailure`` when a step does not converge; False
      warns and goes on.
    """

    def __init__(self, model: _core.Model, parameters, *, progress: bool = False,
                 stop_on_non_convergence: bool = True):
        case_dir = None
        if isinstance(parameters, dict):
            parameters = _core.Parameters(json.dumps(parameters), "parameters")
            migrate_project_parameters(parameters)
        elif isinstance(parameters, (str, os.PathLike)):
            path = os.path.abspath(os.fspath(parameters))
            parameters = read_project_parameters(path)
            case_dir = os.path.dirname(path)
        elif isinstance(parameters, _core.Parameters):
            migrate_project_parameters(parameters)
        else:
            raise _core.InputError("Analysis: parameters must be a dict, a ProjectParameters.json path or an "
                                   f"mc.Parameters, got {type(parameters).__name__}")
        super().__init__(model, parameters, progress=progress, stop_on_non_convergence=stop_on_non_convergence,
                         case_dir=case_dir)


def run_case(project_parameters: str, *, progress: bool = True, stop_on_non_convergence: bool = True):
    """Runs the case of ``project_parameters`` and returns the finished analysis. As in Kratos,
    relative paths inside the case are relative to the working directory; input files not found
    there are looked up next to ``project_parameters``."""
    path = os.path.abspath(project_parameters)
    parameters = read_project_parameters(path)
    analysis = StructuralMechanicsAnalysis(_core.Model(), parameters, progress=progress,
                                           stop_on_non_convergence=stop_on_non_convergence,
                                           case_dir=os.path.dirname(path))
    analysis.Run()
    return analysis
