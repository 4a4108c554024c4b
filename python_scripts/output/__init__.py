"""Result writers run as output processes (``output_processes`` of a ProjectParameters.json)."""
from __future__ import annotations

from .vtk_output_process import VTK_CELL_TYPES, GidOutputProcess, VtkOutputProcess

__all__ = ["VTK_CELL_TYPES", "GidOutputProcess", "VtkOutputProcess"]
