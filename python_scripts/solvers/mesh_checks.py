"""Checks of an imported mesh that the mdpa reader cannot make line by line (issue 16): nothing
that gives stiffness, an element or condition listing a node twice, a load on nodes that nothing
carries (it would only show later as a singular system). Each error names the file, the entity
and the nodes at fault."""
from __future__ import annotations

from .. import _core

#: the built-in conditions that add no stiffness: loads, and the geometric skin conditions
LOAD_CONDITIONS = frozenset(
    ["PointLoadCondition2D1N", "PointLoadCondition3D1N", "AxisymPointLoadCondition2D1N",
     "LineLoadCondition2D2N", "LineLoadCondition2D3N", "LineLoadCondition3D2N",
     "AxisymLineLoadCondition2D2N", "AxisymLineLoadCondition2D3N",
     "SurfaceLoadCondition3D3N", "SurfaceLoadCondition3D4N", "SurfaceLoadCondition3D6N",
     "SurfaceLoadCondition3D8N", "SurfaceLoadCondition3D9N"])
NO_STIFFNESS = LOAD_CONDITIONS | {"LineCondition2D2N", "LineCondition2D3N", "SurfaceCondition3D3N",
                                  "SurfaceCondition3D4N"}


def check_imported_mesh(part, path: str, owned=None) -> None:
    """Raises InputError for the first problem found in ``part`` as read from ``path``. Nodes are
    carried by elements and by conditions that give stiffness (springs of a plugin, ...). On a
    rank's piece of a distributed run, ``owned`` (the ids of the nodes it owns): a load's node is
    checked by its owner only, which holds every entity carrying it."""
    carried: set[int] = set()
    loads = []
    for kind, entities in (("element", part.Elements), ("condition", part.Conditions)):
        for entity in entities:
            ids = entity.NodeIds()
            if len(set(ids)) != len(ids):
                twice = next(i for i in ids if ids.count(i) > 1)
                raise _core.InputError(f"{path}: {kind} {entity.Id} ({entity.Info()}) lists node {twice} "
                                       f"more than once: nodes {' '.join(map(str, ids))}")
            name = entity.Info() if kind == "condition" else ""
            if name in LOAD_CONDITIONS:
                loads.append((entity, name, ids))
            elif name not in NO_STIFFNESS:
                carried.update(ids)
    if not carried:
        raise _core.InputError(f"{path}: the mesh has no elements ({part.NumberOfNodes()} nodes, "
                               f"{part.NumberOfConditions()} conditions, none of which gives stiffness); "
                               "the structure needs an element block")
    for condition, name, ids in loads:
        orphans = [i for i in ids if i not in carried and (owned is None or i in owned)]
        if orphans:
            raise _core.InputError(f"{path}: condition {condition.Id} ({name}): node {orphans[0]} belongs to "
                                   "no element, so nothing carries its load")
