"""Restart: ``save_restart_process`` writes checkpoints; ``model_import_settings.input_type``
``"rest"`` (or the legacy ``restart_options``) resumes from one (see ``checkpoint.py``)."""
from __future__ import annotations

from .checkpoint import Checkpoint, mesh_record, write_checkpoint
from .save_restart_process import SaveRestartProcess, restart_file_name, restart_folder

#: python_module -> class, registered under KratosMultiphysics by the process factory
RESTART_PROCESSES = {"save_restart_process": SaveRestartProcess}


def attach_run(processes, mesh: dict | None, solver=None) -> None:
    """Hands every checkpoint writer among ``processes`` the process list, the mesh record and the
    solver."""
    for process in processes:
        if isinstance(process, SaveRestartProcess):
            process.attach(processes, mesh, solver)


__all__ = ["RESTART_PROCESSES", "Checkpoint", "SaveRestartProcess", "attach_run", "mesh_record",
           "restart_file_name", "restart_folder", "write_checkpoint"]
