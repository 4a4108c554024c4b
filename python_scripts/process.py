"""Base class of every process (boundary conditions, loads, contact, checks, outputs).

The analysis stage calls the hooks in this order (spec 1.7): ``ExecuteInitialize``,
``ExecuteBeforeModelCut`` (only when the model is cut across the ranks), ``Check``,
``ExecuteBeforeSolutionLoop``; per step ``ExecuteInitializeSolutionStep``, then after the solve
``ExecuteFinalizeSolutionStep``; around output ``ExecuteBeforeOutputStep`` / ``PrintOutput`` /
``ExecuteAfterOutputStep``; at the end ``ExecuteFinalize``, or ``ExecuteAfterFailure`` when a
solution error stops the run. Each process owns its defaults in
``GetDefaultParameters()`` and validates its settings against them.
"""
from __future__ import annotations

from . import _core


class Process:
    """Does nothing at every hook; subclasses override the hooks they need."""

    def __init__(self, model: _core.Model, settings: _core.Parameters | None = None):
        self.model = model
        self.settings = settings if settings is not None else _core.Parameters()
        defaults = self.GetDefaultParameters()
        if defaults is not None:
            self.settings.ValidateAndAssignDefaults(defaults)

    @classmethod
    def GetDefaultParameters(cls) -> _core.Parameters | None:
        return None

    def ExecuteInitialize(self) -> None: ...
    def Check(self) -> None: ...
    def ExecuteBeforeSolutionLoop(self) -> None: ...
    def ExecuteInitializeSolutionStep(self) -> None: ...
    def ExecuteFinalizeSolutionStep(self) -> None: ...
    def ExecuteBeforeOutputStep(self) -> None: ...
    def ExecuteAfterOutputStep(self) -> None: ...
    def ExecuteFinalize(self) -> None: ...

    @classmethod
    def parts_kept_whole(cls, settings: _core.Parameters) -> list[str] | None:
        """Under mpirun with MORTARCONTACT_PARTITIONED_MODEL=1, before the mesh is read (each rank
        reads its piece): the model parts, named as in ``settings``, whose ExecuteInitialize needs
        them whole on every rank, with what touches their nodes (the contact interfaces); None when
        it needs the whole model (every rank then reads it whole and cuts it after)."""
        return []

    def ExecuteBeforeModelCut(self, bodies) -> list:
        """Under mpirun with MORTARCONTACT_PARTITIONED_MODEL=1, after every ExecuteInitialize and
        before the model is cut into the ranks' pieces: computes what needs the whole model and
        returns the model parts every rank must keep whole (the contact interfaces). ``bodies``:
        None when every rank read the model whole, else ``(body_of, labels)`` of the interface nodes
        found on the mesh file before a rank read its piece (``PlanModelPartPiece``)."""
        return []

    def ExecuteAfterModelCut(self, ranks) -> None:
        """Right after the model is cut (see ``ExecuteBeforeModelCut``): ``ranks`` (a ``Ranks``)
        gathers what a process reports on the whole model from the ranks' pieces."""

    def ExecuteAfterFailure(self) -> None:
        """The run stops on a solution error (mortarcontact's hook, not Kratos'): a process that
        writes its results only at the end writes what the converged steps produced."""

    def OutputFiles(self) -> list[str]:
        """The result files this process has written so far (for the end-of-run summary)."""
        return []

    def RestartState(self) -> dict | None:
        """What a restart checkpoint keeps of this process at the end of a step (JSON-serialisable;
        None: nothing, the process works from the model state alone)."""
        return None

    def LoadRestartState(self, state: dict) -> None:
        """Takes back what ``RestartState()`` returned, after ``ExecuteBeforeSolutionLoop`` of a
        resumed run."""


class OutputProcess(Process):
    """A process that also writes results when ``IsOutputStep()`` is true. With
    ``after_other_outputs`` it writes after the others of the step (a checkpoint records their
    finished state)."""

    after_other_outputs = False

    def IsOutputStep(self) -> bool:
        return False

    def PrintOutput(self) -> None: ...
