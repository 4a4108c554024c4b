"""Mesh input through meshio: ``model_import_settings.input_type`` ``"gmsh"`` and ``"meshio"``.

These input types and the three keys below are mortarcontact's, not Kratos' (Kratos reads mdpa).
``input_filename`` keeps Kratos' meaning, the mesh file relative to the working directory (else to
the case folder), but here it includes its extension: ``"block.msh"``. ``"gmsh"`` reads the file
as a gmsh mesh (msh 2.2 or 4.1) whatever its extension; ``"meshio"`` reads any format meshio
knows from the extension (msh, med, inp, vtu, xdmf, ...).

What becomes what:

* every point of the file is a node of the root model part; its id is gmsh's node tag for gmsh
  files (the number gmsh shows), else its 1-based position in the file, as in an mdpa;
* each group of the file is a sub model part of the same name: gmsh physical groups (by their
  names), meshio ``cell_sets`` (Abaqus ELSET, MED families, ...) and ``point_sets`` (NSET); a dotted
  name (``Parts.block``) is a nested sub model part, as in an mdpa. Unnamed groups are not read;
* cells of the model's dimension (``domain_size``) of a group become elements, named by
  ``element_names``; lower-dimensional cells (facets, edges, points) become conditions only when
  ``condition_names`` names them, otherwise the group has their nodes only, which is what
  Dirichlet and contact parts need;
* elements and conditions are numbered 1, 2, ... in file order (block by block, cell by cell);
  a cell in several groups is one entity, added to each of them.

Keys (objects keyed by group name; a name unknown to the file is an error):

``element_names``  ``{"Parts_block": "SmallDisplacementElement2D3N"}``: the element of the
    group's cells of dimension ``domain_size``. A name without its ``<d>D<n>N`` suffix
    (``"SmallDisplacementElement"``) takes the one of each cell type, which suits groups mixing
    triangles and quadrilaterals. Required for every group holding cells of the model's dimension
    (no silent default: a cell without element would leave its nodes without stiffness).
``condition_names``  ``{"Load_top": "LineLoadCondition2D2N"}``: the condition of the group's
    lower-dimensional cells (suffix rule as above). Without it those cells give nodes only.
``properties_ids``  ``{"Parts_block": 1}``: the properties id of the group's elements and conditions
    (default 0). materials.json assigns its properties to every entity of the model part it names,
    exactly as for an mdpa.
"""
from __future__ import annotations

import contextlib
import json
import re

import numpy as np

from .. import _core
from ..output.vtk_cell_types import VTK_CELL_TYPES, VTK_NODE_ORDER
from ..utilities import nearest

GROUP_KEYS = ("element_names", "condition_names", "properties_ids")
READ_ERRORS = (ValueError, KeyError, IndexError, TypeError, OSError, EOFError, AssertionError)


def _space_dimension(geometry: str) -> int:
    return int(re.search(r"(\d)D", geometry).group(1))


#: (meshio cell type, domain size) -> Kratos geometry name
CELL_GEOMETRY = {(cell, _space_dimension(geometry)): geometry for geometry, cell in VTK_CELL_TYPES.items()}
#: meshio cell type -> dimension of its reference cell
CELL_DIMENSION = {"vertex": 0, "line": 1, "line3": 1, "triangle": 2, "triangle6": 2, "quad": 2, "quad8": 2,
                  "quad9": 2, "tetra": 3, "tetra10": 3, "hexahedron": 3, "hexahedron20": 3, "hexahedron27": 3,
                  "wedge": 3}
try:  # the dimension of the cell types we cannot read, for the messages
    from meshio._mesh import topological_dimension as _MESHIO_DIMENSION
except ImportError:
    _MESHIO_DIMENSION = {}
#: meshio (VTK) node order -> ours: our node j is column _FROM_VTK[type][j] of the meshio cell
_FROM_VTK = {cell: list(np.argsort(order)) for cell, order in VTK_NODE_ORDER.items()}


def name_suffix(cell_type: str, domain_size: int) -> str:
    """The ``<d>D<n>N`` ending of the registered names for a cell type, e.g. ``2D3N`` for triangles."""
    geometry = CELL_GEOMETRY[(cell_type, domain_size)]
    points = 1 if cell_type == "vertex" else int(re.search(r"(\d+)$", geometry).group(1))
    return f"{domain_size}D{points}N"


def read_mesh(path: str, input_type: str, where: str):
    """The meshio.Mesh of a file and the id of each of its points: gmsh's node tags for gmsh files
    (so that node ids are those gmsh shows), else 1, 2, ... in file order. InputError (no traceback)
    when meshio is missing or cannot read the file."""
    try:
        import meshio
    except ImportError:
        raise _core.InputError(f"{where}.input_type: \"{input_type}\" needs the Python package meshio, a "
                               "dependency of mortarcontact that is not installed (pip install meshio)") from None
    captured = []
    try:
        with _node_tags_of_gmsh_readers(captured):
            mesh = meshio.read(path, file_format="gmsh" if input_type == "gmsh" else None)
    except (meshio.ReadError, *READ_ERRORS) as error:
        raise _core.InputError(f"{path}: meshio cannot read it as {input_type!r} input "
                               f"({type(error).__name__}: {error})") from None
    ids = np.arange(1, len(mesh.points) + 1, dtype=np.int64)
    if len(captured) == 1 and len(captured[0]) == len(ids):
        ids = np.asarray(captured[0], dtype=np.int64)
        if len(np.unique(ids)) != len(ids) or ids.min() < 1:
            raise _core.InputError(f"{path}: node tags must be distinct positive integers")
    return mesh, ids


@contextlib.contextmanager
def _node_tags_of_gmsh_readers(captured: list):
    """meshio's gmsh readers number points in file order and drop gmsh's node tags; this keeps the
    tags their node-section readers return (second item; 0-based in msh 4), for one read."""
    try:
        from meshio.gmsh import _gmsh22, _gmsh41
    except ImportError:  # another meshio layout: file order it is
        yield
        return
    originals = [(module, getattr(module, "_read_nodes", None), offset) for module, offset in ((_gmsh22, 0),
                                                                                               (_gmsh41, 1))]

    def capturing(original, offset):
        def read_nodes(*args, **kwargs):
            result = original(*args, **kwargs)
            captured.append(np.asarray(result[1]).astype(np.int64) + offset)
            return result
        return read_nodes

    for module, original, offset in originals:
        if original is not None:
            module._read_nodes = capturing(original, offset)
    try:
        yield
    finally:
        for module, original, _ in originals:
            if original is not None:
                module._read_nodes = original


def mesh_groups(mesh) -> tuple[dict, dict]:
    """({group: [cell indices or None, one per cell block]}, {group: point indices})."""
    cell_groups = {name: [None if ids is None or len(ids) == 0 else np.asarray(ids, dtype=np.int64)
                          for ids in per_block]
                   for name, per_block in mesh.cell_sets.items() if not name.startswith("gmsh:")}
    physical = mesh.cell_data.get("gmsh:physical")
    if not cell_groups and physical is not None:
        # gmsh readers that give tags but no cell_sets: a physical name is a (tag, dimension) pair.
        for name, (tag, dimension) in mesh.field_data.items():
            per_block = [np.flatnonzero(tags == tag) if CELL_DIMENSION.get(block.type) == dimension else None
                         for block, tags in zip(mesh.cells, physical)]
            cell_groups[name] = [ids if ids is not None and len(ids) else None for ids in per_block]
    point_groups = {name: np.asarray(ids, dtype=np.int64) for name, ids in mesh.point_sets.items()
                    if not name.startswith("gmsh:")}
    return cell_groups, point_groups


class _EntityNames:
    """Resolves element / condition names per cell type and checks their geometry once each."""

    def __init__(self, domain_size: int):
        self.domain_size = domain_size
        self.registered = {"element": set(_core.ElementNames()), "condition": set(_core.ConditionNames())}
        self.probe_model = _core.Model()
        self.probe = self.probe_model.CreateModelPart("probe")
        self.probe_properties = self.probe.CreateNewProperties(0)
        self.geometries = {}

    def resolve(self, kind: str, name: str, cell_type: str, group: str, key: str, path: str) -> str:
        geometry = CELL_GEOMETRY[(cell_type, self.domain_size)]
        suffix = name_suffix(cell_type, self.domain_size)
        points = int(suffix.split("D")[1][:-1])
        registered = self.registered[kind]
        full = name if name in registered or re.search(r"\dD\d+N$", name) else name + suffix
        if full not in registered:
            raise _core.InputError(f"{key}.{group}: unknown {kind} '{name}'{nearest(full, registered)}")
        actual = self._geometry(kind, full, points)
        if actual != geometry:
            raise _core.InputError(f"{key}.{group}: {kind} '{full}' has the geometry {actual}, but the group's "
                                   f"{cell_type} cells in {path} are {geometry}")
        return full

    def _geometry(self, kind: str, name: str, points: int) -> str:
        if name not in self.geometries:
            for node_id in range(self.probe.NumberOfNodes() + 1, points + 1):
                self.probe.CreateNewNode(node_id, 0.1 * node_id, 0.01 * node_id ** 2, 0.001 * node_id ** 3)
            create = self.probe.CreateNewElement if kind == "element" else self.probe.CreateNewCondition
            try:
                entity = create(name, len(self.geometries) + 1, list(range(1, points + 1)), self.probe_properties)
                self.geometries[name] = entity.GetGeometry().Name()
            except _core.InputError as error:  # another number of nodes
                self.geometries[name] = f"'{error}'"
        return self.geometries[name]


def _group_settings(imports, cell_groups: dict, point_groups: dict, path: str) -> dict:
    """{key: {group: value}} of the three group keys, checked against the groups of the file."""
    known = sorted(set(cell_groups) | set(point_groups))
    values = {}
    for key in GROUP_KEYS:
        block = imports[key]
        where = f"{imports.Where()}.{key}"
        values[key] = {}
        for group in block.keys():  # noqa: SIM118 (a Parameters object, not a dict)
            if group not in known:
                listed = ", ".join(repr(g) for g in known) or "none"
                raise _core.InputError(f"{where}: no group '{group}' in {path}{nearest(group, known)}; "
                                       f"its groups: {listed}")
            value = block[group]
            if key == "properties_ids":
                if not value.IsInt() or value.GetInt() < 0:
                    raise _core.InputError(f"{where}.{group}: expected a non-negative integer, "
                                           f"found {value.WriteJsonString()}")
                values[key][group] = value.GetInt()
            else:
                if not value.IsString():
                    raise _core.InputError(f"{where}.{group}: expected a registered name (string), "
                                           f"found {value.WriteJsonString()}")
                values[key][group] = value.GetString()
    return values


def import_mesh(part, mesh, node_ids, imports, domain_size: int, path: str) -> None:
    """Fills the (empty) root model part ``part`` from a meshio.Mesh whose point k is the node
    ``node_ids[k]``, per the module's rules."""
    where = imports.Where()
    cell_groups, point_groups = mesh_groups(mesh)
    settings = _group_settings(imports, cell_groups, point_groups, path)
    names = _EntityNames(domain_size)

    part.CreateNewNodes(node_ids, np.asarray(mesh.points, dtype=float))

    members = {group: {"nodes": [], "element": [], "condition": []} for group in set(cell_groups) | set(point_groups)}
    counters = {"element": 0, "condition": 0}
    for block_index, block in enumerate(mesh.cells):
        in_block = [(group, per_block[block_index]) for group, per_block in sorted(cell_groups.items())
                    if block_index < len(per_block) and per_block[block_index] is not None]
        if not in_block:
            continue
        connectivity = np.asarray(block.data, dtype=np.int64)
        dimension = CELL_DIMENSION.get(block.type, _MESHIO_DIMENSION.get(block.type))
        supported = (block.type, domain_size) in CELL_GEOMETRY
        kind = "element" if dimension == domain_size else "condition"
        key = f"{where}.{kind}_names"
        cell_name = np.full(len(connectivity), None, dtype=object)
        cell_properties = np.zeros(len(connectivity), dtype=np.int64)
        for group, cells in in_block:
            members[group]["nodes"].append(node_ids[np.unique(connectivity[cells])])
            if dimension is not None and dimension > domain_size:
                raise _core.InputError(f"{path}: group '{group}' has {block.type} cells, of dimension {dimension}, "
                                       f"in a model of {where.rsplit('.', 1)[0]}.domain_size {domain_size}")
            requested = settings[f"{kind}_names"].get(group)
            if not requested:
                continue
            if not supported:
                raise _core.NotImplementedFeatureError(
                    f"{path}: group '{group}' has {block.type} cells, which mortarcontact cannot make {kind}s of "
                    f"in {domain_size}D; supported: "
                    + ", ".join(sorted(cell for cell, d in CELL_GEOMETRY if d == domain_size)))
            full = names.resolve(kind, requested, block.type, group, key, path)
            clash = [other for other in set(cell_name[cells]) if other is not None and other != full]
            if clash:
                raise _core.InputError(f"{path}: {block.type} cells of group '{group}' are given two {kind}s, "
                                       f"'{full}' and '{clash[0]}' (from another group)")
            cell_name[cells] = full
            cell_properties[cells] = settings["properties_ids"].get(group, 0)
        if kind == "element":
            orphan = [group for group, cells in in_block if np.any(cell_name[cells] == None)]  # noqa: E711
            if orphan:
                if not supported:
                    raise _core.NotImplementedFeatureError(
                        f"{path}: group '{orphan[0]}' has {block.type} cells, which mortarcontact cannot read")
                example = f"\"{orphan[0]}\": \"SmallDisplacementElement{name_suffix(block.type, domain_size)}\""
                raise _core.InputError(f"{key}: group '{orphan[0]}' has {block.type} cells of the model's dimension "
                                       f"in {path} but no element; name one, e.g. {{{example}}}")
        entity_ids = _create_entities(part, kind, block.type, node_ids[connectivity], cell_name, cell_properties,
                                      counters)
        for group, cells in in_block:
            ids = entity_ids[cells]
            members[group][kind].append(ids[ids > 0])
    for group, ids in point_groups.items():
        members[group]["nodes"].append(node_ids[ids])

    _add_members(part, members, path)


def import_meshio(model_part, mesh, *, element_names: dict, condition_names: dict | None = None,
                  properties_ids: dict | None = None, domain_size: int | None = None, node_ids=None) -> None:
    """Fills an empty model part from a ``meshio.Mesh`` in memory, by the rules of
    ``input_type`` ``"meshio"`` (this module's docstring): each named group (gmsh physical group,
    cell set, point set) becomes a sub model part; its cells of dimension ``domain_size`` become
    elements named by ``element_names`` {group: name}, its lower-dimensional cells conditions
    where ``condition_names`` {group: name} names them (else the sub model part has their nodes
    only); ``properties_ids`` {group: id} gives their properties (default 0, created when the
    part does not list them). The equivalent of a ``ModelPart.from_meshio``.

    model_part: an empty root model part, its historical variables already added (an
      ``mc.Analysis`` adds its solver's when it is created: build the mesh after it).
    mesh: the meshio.Mesh (``meshio.read(...)``, or built from numpy arrays); coordinates in the
      model's length unit.
    domain_size: 2 or 3; default the largest dimension of the mesh's cells. Also set as the
      ProcessInfo's DOMAIN_SIZE.
    node_ids: the id of each point (default 1, 2, ... in point order).
    """
    if model_part.NumberOfNodes() or model_part.NumberOfElements() or model_part.NumberOfConditions():
        raise _core.InputError(f"import_meshio: model part {model_part.FullName()} is not empty")
    if domain_size is None:
        domain_size = max((CELL_DIMENSION.get(block.type, 0) for block in mesh.cells), default=0)
    if domain_size not in (2, 3):
        raise _core.InputError(f"import_meshio: domain_size must be 2 or 3, got {domain_size}")
    ids = (np.arange(1, len(mesh.points) + 1, dtype=np.int64) if node_ids is None
           else np.asarray(node_ids, dtype=np.int64))
    if ids.shape != (len(mesh.points),):
        raise _core.InputError(f"import_meshio: node_ids has shape {ids.shape}, expected ({len(mesh.points)},)")
    groups = {"element_names": element_names, "condition_names": condition_names or {},
              "properties_ids": properties_ids or {}}
    imports = _core.Parameters(json.dumps(groups), "import_meshio")
    import_mesh(model_part, mesh, ids, imports, domain_size, "the mesh")
    model_part.ProcessInfo.SetValue(_core.DOMAIN_SIZE, domain_size)


def _add_members(part, members: dict, path: str) -> None:
    """Creates the sub model parts (nested by dots) and fills them with their node, element and
    condition ids."""
    for group in sorted(members):
        if not group or any(c.isspace() for c in group) or "" in group.split("."):
            raise _core.InputError(f"{path}: group name {group!r} cannot name a sub model part (no spaces, "
                                   "no empty names between dots)")
        sub = part
        for name in group.split("."):
            sub = sub.GetSubModelPart(name) if sub.HasSubModelPart(name) else sub.CreateSubModelPart(name)
        content = members[group]
        for what, add in (("nodes", sub.AddNodes), ("element", sub.AddElements), ("condition", sub.AddConditions)):
            if content.get(what):
                add(np.unique(np.concatenate(content[what])).tolist())


def _create_entities(part, kind, cell_type, connectivity, cell_name, cell_properties, counters) -> np.ndarray:
    """Creates the named cells (``connectivity`` in node ids) of one block in order; returns their
    ids (0: no entity)."""
    ids = np.zeros(len(connectivity), dtype=np.int64)
    named = np.flatnonzero(cell_name != None)  # noqa: E711
    if len(named) == 0:
        return ids
    nodes = connectivity[:, _FROM_VTK[cell_type]] if cell_type in _FROM_VTK else connectivity
    create = part.CreateNewElements if kind == "element" else part.CreateNewConditions
    first = counters[kind] + 1
    ids[named] = np.arange(first, first + len(named))
    for name, props in sorted(set(zip(cell_name[named].tolist(), cell_properties[named].tolist()))):
        cells = named[(cell_name[named] == name) & (cell_properties[named] == props)]
        properties = part.GetProperties(props) if part.HasProperties(props) else part.CreateNewProperties(props)
        create(name, ids[cells], nodes[cells], properties)
    counters[kind] += len(named)
    return ids
