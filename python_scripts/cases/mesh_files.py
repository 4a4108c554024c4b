# SPDX-License-Identifier: BSD-3-Clause
"""The one route from a generated mesh to the files of a case.

mortarcontact reads the mesh as gmsh writes it: a ``.msh`` file (gmsh 2.2, ASCII, coordinates to
the last bit) with one named physical group per sub model part, read with
``model_import_settings.input_type`` ``"gmsh"`` (``solvers/meshio_import.py``). Kratos reads mdpa
only: ``write_kratos_mdpa`` reads the case's mesh exactly as mortarcontact does and writes that
model part with the kernel's mdpa writer (``mc.WriteModelPart``), so both codes see the same nodes,
elements, conditions and sub model parts, and no generator writes mdpa by hand. The Kratos runner
(``benchmarks/hertz/case_runner.py``) then reads that mdpa in place of the case's mesh.
"""
from __future__ import annotations

import json
import os
import re

import numpy as np

#: dimension of the meshio cell types the generators write
CELL_DIMENSION = {"vertex": 0, "line": 1, "triangle": 2, "quad": 2, "tetra": 3, "hexahedron": 3, "wedge": 3}


def write_gmsh(path: str, points: np.ndarray, groups: list) -> None:
    """Writes a gmsh 2.2 ``.msh``: node tags 1..n in the order of ``points`` (n, 3); ``groups`` is a
    list of (physical group name, meshio cell type, 0-based connectivity (m, k)), each written as
    one block of cells with its own physical and geometrical tag, in list order (so the entities
    mortarcontact creates from them are numbered in that order). A group of nodes only is a
    ``"vertex"`` block (connectivity (m, 1)). A name may appear once."""
    import meshio

    names = [name for name, _, _ in groups]
    if len(set(names)) != len(names):
        raise ValueError(f"{path}: a physical group name appears twice in {names}")
    cells = [(cell_type, np.asarray(connectivity, dtype=np.int64)) for _, cell_type, connectivity in groups]
    tags = [np.full(len(connectivity), i + 1, dtype=np.int64) for i, (_, connectivity) in enumerate(cells)]
    mesh = meshio.Mesh(np.asarray(points, dtype=float), cells,
                       cell_data={"gmsh:physical": tags, "gmsh:geometrical": tags},
                       field_data={name: np.array([i + 1, CELL_DIMENSION[cell_type]])
                                   for i, (name, cell_type, _) in enumerate(groups)})
    meshio.write(path, mesh, file_format="gmsh22", binary=False)


#: (dimension of the cells, nodes per cell) -> meshio cell type of the linear cells the generators make
LINEAR_CELLS = {(0, 1): "vertex", (1, 2): "line", (2, 3): "triangle", (2, 4): "quad", (3, 4): "tetra",
                (3, 6): "wedge", (3, 8): "hexahedron"}


def write_case_mesh(path: str, coords: np.ndarray, element_blocks, parts: dict, condition_blocks=()) -> dict:
    """Writes a generated mesh as a gmsh file and returns the ``model_import_settings`` that read it.

    ``coords`` (n, 3): node ids 1..n in this order. ``element_blocks`` and ``condition_blocks``:
    (registered name, first id, 0-based connectivity (m, k)), numbered consecutively from their
    first id, in list order (ids as an mdpa of them would number them). ``parts``: sub model part
    name -> 0-based "nodes" and, optionally, the "elements" or "conditions" ids of exactly one
    block, whose nodes are then the part's nodes. Every entity uses properties 0 (materials.json
    assigns properties per sub model part)."""
    groups, element_names, condition_names = [], {}, {}
    claimed = {}
    for kind, blocks, names in (("elements", element_blocks, element_names),
                                ("conditions", condition_blocks, condition_names)):
        expected_first = 1
        for name, first, cells in blocks:
            if first != expected_first:
                raise ValueError(f"{path}: {kind} block {name} starts at id {first}, expected {expected_first}")
            expected_first += len(cells)
            ids = first + np.arange(len(cells))
            owners = [part for part, content in parts.items() if np.array_equal(content.get(kind, []), ids)]
            if len(owners) != 1:
                raise ValueError(f"{path}: {kind} {first}..{ids[-1]} ({name}) must be the {kind} of exactly one "
                                 f"sub model part, found {owners}")
            part = owners[0]
            cells = np.asarray(cells)
            if not np.array_equal(np.unique(cells), np.unique(parts[part]["nodes"])):
                raise ValueError(f"{path}: the nodes of {part} are not those of its {kind}")
            # elements fill the domain (the d of their <d>D<n>N name); conditions are one dimension
            # lower at most: points, lines or surfaces, told apart by their node count
            dimension = (int(re.search(r"(\d)D\d+N$", name).group(1)) if kind == "elements"
                         else {1: 0, 2: 1, 3: 2, 4: 2}[cells.shape[1]])
            groups.append((part, LINEAR_CELLS[(dimension, cells.shape[1])], cells))
            names[part] = name
            claimed[part] = kind
    for part, content in parts.items():
        other = {"elements", "conditions"} & set(content) - {claimed.get(part)}
        if any(len(content[k]) for k in other):
            raise ValueError(f"{path}: {part} holds {sorted(other)} of no block")
        if part not in claimed:
            groups.append((part, "vertex", np.asarray(content["nodes"])[:, None]))
    write_gmsh(path, coords, groups)
    settings = {"input_type": "gmsh", "input_filename": os.path.basename(path), "element_names": element_names}
    if condition_names:
        settings["condition_names"] = condition_names
    return settings


def write_json_files(folder: str, files: dict) -> None:
    """Writes each ``{file name: JSON content}`` of ``files`` into ``folder`` (indent 2, newline at
    the end): a case's materials and ProjectParameters.json."""
    for name, content in files.items():
        with open(os.path.join(folder, name), "w") as f:
            json.dump(content, f, indent=2)
            f.write("\n")


def write_kratos_mdpa(case_dir: str) -> str:
    """Writes the mdpa Kratos reads for the case in ``case_dir`` (its ProjectParameters.json reads a
    gmsh / meshio file): the mesh file's name with ``.mdpa`` in place of its extension, next to it.
    Rewritten only when older than the mesh file. Returns its path."""
    import mortarcontact as mc
    from mortarcontact.solvers.meshio_import import import_meshio, read_mesh

    with open(os.path.join(case_dir, "ProjectParameters.json")) as f:
        settings = json.load(f)["solver_settings"]
    imports = settings["model_import_settings"]
    mesh_path = os.path.join(case_dir, imports["input_filename"])
    mdpa = os.path.splitext(mesh_path)[0] + ".mdpa"
    if os.path.exists(mdpa) and os.path.getmtime(mdpa) >= os.path.getmtime(mesh_path):
        return mdpa
    mesh, node_ids = read_mesh(mesh_path, imports["input_type"], "model_import_settings")
    part = mc.Model().CreateModelPart(settings.get("model_part_name", "Structure"))
    import_meshio(part, mesh, element_names=imports.get("element_names", {}),
                  condition_names=imports.get("condition_names"), properties_ids=imports.get("properties_ids"),
                  domain_size=settings["domain_size"], node_ids=node_ids)
    partial = mdpa + ".partial"
    mc.WriteModelPart(part, partial)
    os.replace(partial, mdpa)
    return mdpa
