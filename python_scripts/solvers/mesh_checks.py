"""Checks of an imported mesh that the mdpa reader cannot make line by line (issue 16): a mesh
without elements, an element or condition listing a node twice, a condition on nodes that no
element holds (it would only show later as a singular system). Each error names the file, the
entity and the nodes at fault."""
from __future__ import annotations

from .. import _core


def check_imported_mesh(part, path: str) -> None:
    """Raises InputError for the first problem found in ``part`` as read from ``path``."""
    if part.NumberOfElements() == 0:
        raise _core.InputError(f"{path}: the mesh has no elements ({part.NumberOfNodes()} nodes, "
                               f"{part.NumberOfConditions()} conditions); the structure needs an element block")
    in_elements: set[int] = set()
    for kind, entities in (("element", part.Elements), ("condition", part.Conditions)):
        for entity in entities:
            ids = entity.NodeIds()
            if len(set(ids)) != len(ids):
                twice = next(i for i in ids if ids.count(i) > 1)
                raise _core.InputError(f"{path}: {kind} {entity.Id} ({entity.Info()}) lists node {twice} "
                                       f"more than once: nodes {' '.join(map(str, ids))}")
            if kind == "element":
                in_elements.update(ids)
            else:
                orphans = [i for i in ids if i not in in_elements]
                if orphans:
                    raise _core.InputError(f"{path}: condition {entity.Id} ({entity.Info()}): node "
                                           f"{orphans[0]} belongs to no element, so nothing carries its load")
