# SPDX-License-Identifier: BSD-3-Clause
"""Self-contact: a U-shaped clamp whose two arms are pushed together until their inner faces touch.

One elastic body (plane strain in 2D, hexahedra in 3D): a base [-HALF_WIDTH, HALF_WIDTH] x
[0, BASE] clamped at its bottom, and two arms of thickness HALF_WIDTH - GAP rising to BASE + ARM
on either side of a slot of width 2 GAP. A pressure on the outer faces of the upper half of the
arms bends them inward; their tips close the slot and the contact zone then spreads down the
inner faces. The contact surface is the whole boundary of the slot (both inner faces and its
bottom) as one sub model part, and ``assume_master_slave`` is empty: the search assigns the roles
itself (a self-contacting group pairs each face only with faces of higher id). ``roles="given"``
writes the same body with the two inner faces as separate slave and master parts instead, the
two-body route whose answer the automatic roles must reproduce.

The problem is symmetric about x = 0 while the mortar discretisation is not (one side is slave);
the checks are the ones that hold for any run: global equilibrium, equal and opposite contact
forces on the two faces, the mirror symmetry of the displacements to discretisation accuracy, and
the answer of the given roles.

    python -m mortarcontact.cases.self_contact --dim 2 --out /tmp/cases
"""
from __future__ import annotations

import argparse
import os
import sys

import numpy as np

from . import hertz
from .mesh_files import write_case_mesh, write_json_files

HALF_WIDTH, GAP, BASE, ARM = 0.5, 0.1, 0.5, 2.0
DEPTH = 0.4  # 3D: thickness along z
YOUNG, POISSON = 1000.0, 0.3
PRESSURE = 1.0  # on the outer faces of the arms' upper halves; free tips deflect 0.27 each (2D)
STEPS = 8
SIZE = {2: 0.05, 3: 0.1}  # element size
RIGHT_ARM_GRADING = 0.8  # exponent of the right arm's row spacing


def _axis(lo: float, hi: float, h: float) -> np.ndarray:
    return np.linspace(lo, hi, round((hi - lo) / h) + 1)


def mesh(dim: int, numbering: str = "columns"):
    """(coordinates (n, 3), cells) of the clamp on a structured grid whose lines pass through the
    slot's walls, the right arm's rows graded: quadrilaterals in 2D, hexahedra (DEPTH along z) in
    3D, counter-clockwise.
    ``numbering`` "columns" numbers the cells column by column (the left arm's before the right
    arm's), "rows" row by row (the two arms' cells, and so their faces, interleave)."""
    h = SIZE[dim]
    x = np.concatenate([_axis(-HALF_WIDTH, -GAP, h), _axis(-GAP, GAP, h)[1:-1], _axis(GAP, HALF_WIDTH, h)])
    y = _axis(0.0, BASE + ARM, h)
    z = _axis(0.0, DEPTH, h) if dim == 3 else np.zeros(1)
    nx, ny = len(x), len(y)
    grid = np.stack(np.meshgrid(x, y, z, indexing="ij"), axis=-1).reshape(-1, 3)

    def node(i, j, k):
        return (i * ny + j) * len(z) + k

    if numbering not in ("columns", "rows"):
        raise ValueError(f"numbering: expected 'columns' or 'rows', got {numbering!r}")
    j, i = np.meshgrid(np.arange(ny - 1), np.arange(nx - 1), indexing="ij" if numbering == "rows" else "xy")
    centre_x, centre_y = 0.5 * (x[i] + x[i + 1]), 0.5 * (y[j] + y[j + 1])
    keep = ~((np.abs(centre_x) < GAP) & (centre_y > BASE))
    i, j = i[keep], j[keep]
    quads = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
    if dim == 2:
        cells = np.column_stack([node(a, b, 0) for a, b in quads])
    else:
        cells = np.vstack([np.column_stack([node(a, b, k) for a, b in quads] + [node(a, b, k + 1) for a, b in quads])
                           for k in range(len(z) - 1)])
    # The right arm's rows are graded (finer towards its tip), so the two inner faces do not match.
    right_arm = (grid[:, 0] > GAP - 1e-9) & (grid[:, 1] > BASE)
    grid[right_arm, 1] = BASE + ARM * ((grid[right_arm, 1] - BASE) / ARM) ** RIGHT_ARM_GRADING
    used = np.unique(cells)
    local = np.full(len(grid), -1, dtype=np.int64)
    local[used] = np.arange(len(used))
    return grid[used], local[cells]


def boundary_faces(coords: np.ndarray, cells: np.ndarray, on: np.ndarray) -> np.ndarray:
    """Faces (2D: edges) on the body's boundary whose nodes all satisfy the mask ``on``, numbered
    so that their normal points out of the body."""
    if cells.shape[1] == 4:
        local = [[0, 1], [1, 2], [2, 3], [3, 0]]
    else:
        local = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    faces = np.vstack([cells[:, f] for f in local])
    keys = np.sort(faces, axis=1)
    _, index, counts = np.unique(keys, axis=0, return_index=True, return_counts=True)
    faces = faces[index[counts == 1]]
    return faces[on[faces].all(axis=1)]


def write_case(dim: int, out_dir: str, roles: str = "automatic", steps: int = STEPS,
               numbering: str = "columns", friction: float = 0.0, slave: str = "left") -> str:
    """Writes ``out_dir/self_contact_<dim>d_<roles>[_rows][_fric]/`` (gmsh mesh, materials,
    ProjectParameters.json) and returns the folder; ``numbering`` as in ``mesh``; a ``friction``
    coefficient above 0 makes the contact Coulomb-frictional (ALMContactFrictional); ``slave``: the
    inner face ("left" or "right") that is slave with the roles given."""
    if roles not in ("automatic", "given"):
        raise ValueError(f"roles: expected 'automatic' or 'given', got {roles!r}")
    if slave not in ("left", "right"):
        raise ValueError(f"slave: expected 'left' or 'right', got {slave!r}")
    name = f"self_contact_{dim}d_{roles}" + ("_rows" if numbering == "rows" else "")
    name += ("_fric" if friction else "") + ("_right" if roles == "given" and slave == "right" else "")
    folder = os.path.join(out_dir, name)
    os.makedirs(folder, exist_ok=True)
    coords, cells = mesh(dim, numbering)
    x, y = coords[:, 0], coords[:, 1]
    tol = 1e-9
    in_slot_wall = (np.abs(np.abs(x) - GAP) < tol) & (y > BASE - tol)
    slot_bottom = (np.abs(y - BASE) < tol) & (np.abs(x) < GAP + tol)
    loaded = (np.abs(np.abs(x) - HALF_WIDTH) < tol) & (y > BASE + 0.5 * ARM - tol)
    parts = {"Parts_clamp": {"nodes": np.arange(len(coords)), "elements": 1 + np.arange(len(cells))},
             "DISPLACEMENT_bottom": {"nodes": np.flatnonzero(np.abs(y) < tol)}}
    if dim == 3:
        parts["DISPLACEMENT_back"] = {"nodes": np.flatnonzero(np.abs(coords[:, 2]) < tol)}
    if roles == "automatic":
        parts["Contact_slot"] = {"nodes": np.flatnonzero(in_slot_wall | slot_bottom)}
        contact = {"contact_model_part": {"0": ["Contact_slot"]}, "assume_master_slave": {}}
    else:
        parts["Contact_left"] = {"nodes": np.flatnonzero(in_slot_wall & (x < 0.0))}
        parts["Contact_right"] = {"nodes": np.flatnonzero(in_slot_wall & (x > 0.0))}
        contact = {"contact_model_part": {"0": ["Contact_left", "Contact_right"]},
                   "assume_master_slave": {"0": [f"Contact_{slave}"]}}
    load_faces = boundary_faces(coords, cells, loaded)
    stem = "LineLoadCondition2D2N" if dim == 2 else "SurfaceLoadCondition3D4N"
    condition_blocks = []
    for side, sign in (("left", 1.0), ("right", -1.0)):
        faces = load_faces[sign * coords[load_faces[:, 0], 0] < 0.0]
        first = 1 + sum(len(block[2]) for block in condition_blocks)
        condition_blocks.append((stem, first, faces))
        parts[f"LOAD_{side}"] = {"nodes": np.unique(faces), "conditions": first + np.arange(len(faces))}
    element = f"SmallDisplacementElement{dim}D{cells.shape[1]}N"
    model_import = write_case_mesh(os.path.join(folder, f"{name}.msh"), coords, [(element, 1, cells)], parts,
                                   condition_blocks)
    law = "LinearElasticPlaneStrain2DLaw" if dim == 2 else "LinearElastic3DLaw"
    variables = {"YOUNG_MODULUS": YOUNG, "POISSON_RATIO": POISSON, "DENSITY": 1.0}
    if friction:
        variables["FRICTION_COEFFICIENT"] = friction
    if dim == 2:
        variables["THICKNESS"] = 1.0
    materials = {"properties": [{"model_part_name": "Structure.Parts_clamp", "properties_id": 1,
                                 "Material": {"name": "clamp", "constitutive_law": {"name": law},
                                              "Variables": variables, "Tables": {}}}]}
    load_variable = "LINE_LOAD" if dim == 2 else "SURFACE_LOAD"
    loads = [{"python_module": "assign_vector_variable_to_conditions_process", "kratos_module": "KratosMultiphysics",
              "process_name": "AssignVectorVariableToConditionsProcess",
              "Parameters": {"model_part_name": f"Structure.LOAD_{side}", "variable_name": load_variable,
                             "interval": [0.0, "End"], "value": [f"{sign * PRESSURE!r}*t", 0.0, 0.0]}}
             for side, sign in (("left", 1.0), ("right", -1.0))]
    constraints = [hertz.assign_displacement("DISPLACEMENT_bottom", [True, True, True], [0.0, 0.0, 0.0])]
    if dim == 3:
        constraints.append(hertz.assign_displacement("DISPLACEMENT_back", [False, False, True], [0.0, 0.0, 0.0]))
    parameters = {
        "problem_data": {"problem_name": name, "parallel_type": "OpenMP", "echo_level": 0,
                         "start_time": 0.0, "end_time": 1.0},
        "solver_settings": {
            "model_part_name": "Structure", "domain_size": dim, "solver_type": "Static", "echo_level": 0,
            "analysis_type": "non_linear", "buffer_size": 3 if friction else 2,
            "model_import_settings": model_import,
            "material_import_settings": {"materials_filename": f"{name}_materials.json"},
            "contact_settings": {"mortar_type": "ALMContactFrictional" if friction else "ALMContactFrictionless"},
            "time_stepping": {"time_step": 1.0 / steps},
            "block_builder": True, "line_search": False, "compute_reactions": True,
            "convergence_criterion": "contact_residual_criterion",
            "displacement_relative_tolerance": 1e-6, "displacement_absolute_tolerance": 1e-12,
            "residual_relative_tolerance": 1e-6, "residual_absolute_tolerance": 1e-12,
            "max_iteration": 30,
            "linear_solver_settings": {"solver_type": "LinearSolversApplication.sparse_lu"}},
        "processes": {
            "constraints_process_list": constraints,
            "loads_process_list": loads,
            "contact_process_list": [{
                "python_module": "alm_contact_process",
                "kratos_module": "KratosMultiphysics.ContactStructuralMechanicsApplication",
                "process_name": "ALMContactProcess",
                "Parameters": {"model_part_name": "Structure",
                               "contact_type": "Frictional" if friction else "Frictionless", **contact}}]},
        "output_processes": {}}
    write_json_files(folder, {f"{name}_materials.json": materials, "ProjectParameters.json": parameters})
    return folder


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--dim", type=int, choices=(2, 3), default=2)
    parser.add_argument("--roles", choices=("automatic", "given"), default="automatic")
    parser.add_argument("--out", required=True, help="output folder")
    args = parser.parse_args(argv)
    print(write_case(args.dim, args.out, args.roles))
    return 0


if __name__ == "__main__":
    sys.exit(main())
