"""The kernel processes of a ProjectParameters.json (``KratosMultiphysics`` module: assignments,
JSON output and check), the structural ones (``StructuralMechanicsApplication``:
impose_rigid_movement_process) and the helpers that the contact processes and writers share. The process
factory (``mortarcontact.process_factory``) builds them by name."""
from __future__ import annotations

from .assignment_processes import ASSIGNMENT_PROCESSES
from .from_json_check_result_process import CheckResultError, FromJsonCheckResultProcess
from .impose_rigid_movement_process import STRUCTURAL_PROCESSES
from .json_output_process import JsonOutputProcess
from .model_part_resolution import resolve_model_part

#: python_module -> class, registered under KratosMultiphysics by the process factory
KERNEL_PROCESSES = {
    **ASSIGNMENT_PROCESSES,
    "from_json_check_result_process": FromJsonCheckResultProcess,
    "json_output_process": JsonOutputProcess,
}

__all__ = ["KERNEL_PROCESSES", "STRUCTURAL_PROCESSES", "CheckResultError", "FromJsonCheckResultProcess",
           "JsonOutputProcess", "resolve_model_part"]
