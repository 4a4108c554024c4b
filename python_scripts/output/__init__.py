"""Result writers run as output processes (``output_processes`` of a ProjectParameters.json)."""
from __future__ import annotations

from .vtk_output_process import VTK_CELL_TYPES, GidOutputProcess, VtkOutputProcess

#: python_module -> class, registered under KratosMultiphysics by the process factory
OUTPUT_PROCESSES = {
    "vtk_output_process": VtkOutputProcess,
    "gid_output_process": GidOutputProcess,
}

__all__ = ["OUTPUT_PROCESSES", "VTK_CELL_TYPES", "GidOutputProcess", "VtkOutputProcess"]
