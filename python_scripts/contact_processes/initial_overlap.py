"""Start-up check of a contact interface (issue 16): a slave node that starts behind its nearest
master condition by more than that condition's size. The bodies then overlap by more than an
element in the initial mesh -- a mesh or placement mistake the search cannot resolve (it pairs
nothing, or pairs the wrong side), so the case would run without contact. Small initial
penetrations, which the formulation closes, are left alone."""
from __future__ import annotations

import numpy as np

from .. import _core


def _faces(conditions):
    """(ids, node ids, centres, unit normals, sizes, bounding boxes) of the conditions."""
    ids, nodes, centres, normals, sizes, lows, highs = [], [], [], [], [], [], []
    for condition in conditions:
        geometry = condition.GetGeometry()
        x = np.array([[n.X0, n.Y0, n.Z0] for n in condition.GetNodes()])
        ids.append(condition.Id)
        nodes.append(condition.NodeIds())
        centres.append(x.mean(axis=0))
        normals.append(np.asarray(geometry.UnitNormal([0.0, 0.0, 0.0], _core.Configuration.Initial), dtype=float))
        sizes.append(max(np.linalg.norm(a - b) for a in x for b in x))
        lows.append(x.min(axis=0))
        highs.append(x.max(axis=0))
    return ids, nodes, np.array(centres), np.array(normals), np.array(sizes), np.array(lows), np.array(highs)


def check_initial_overlap(interface, slot: str) -> None:
    """Raises InputError naming the first slave node found behind the nearest master condition of
    ``interface`` it projects onto, by more than that condition's size. Only the nearest counts:
    a node in front of one master face is behind the faces beyond it (the far side of the body)."""
    masters = [c for c in interface.Conditions if c.Is(_core.MASTER)]
    slaves = [c for c in interface.Conditions if c.Is(_core.SLAVE)]
    if not masters or not slaves:
        return
    ids, nodes, centres, normals, sizes, lows, highs = _faces(masters)
    slave_position = {node.Id: np.array([node.X0, node.Y0, node.Z0])
                      for condition in slaves for node in condition.GetNodes()}
    tolerance = 1e-9 * sizes.max()
    for node_id in sorted(slave_position):
        x = slave_position[node_id]
        depth = np.einsum("ij,ij->i", x - centres, normals)
        projected = x - depth[:, None] * normals
        inside = np.all((projected >= lows - tolerance) & (projected <= highs + tolerance), axis=1)
        if not inside.any():
            continue
        k = int(np.argmin(np.where(inside, np.abs(depth), np.inf)))
        if depth[k] < -sizes[k]:
            raise _core.InputError(
                f"contact interface {slot}: slave node {node_id} starts {-depth[k]:.4g} behind master condition "
                f"{ids[k]} (nodes {' '.join(map(str, nodes[k]))}), more than the condition's size {sizes[k]:.4g}: "
                "the bodies overlap by more than an element in the initial mesh; move them apart or check "
                "which parts are slave and master")
