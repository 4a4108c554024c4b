"""Array access to nodal and elemental data for the processes and writers.

Every function prefers a bulk call of the C++ core and only falls back to a Python loop when
that call does not exist yet. The fallbacks are named ``_..._fallback`` so that they are easy to
find and delete once the core provides:

- ``ModelPart.GetNodalNonHistoricalValues(variable) -> ndarray (n,) | (n, 3)`` (node-id order)
- ``ModelPart.GetNodalFlags(flag) -> ndarray[bool] (n,)`` (node-id order)
- ``ModelPart.EntityConnectivity(conditions: bool = False) -> dict[str, (ids: ndarray[int64] (m,),
  node_ids: ndarray[int64] (m, k))]`` keyed by geometry type name ("Triangle2D3", ...)
- ``ModelPart.IntegrationPointValues(variable, conditions: bool = False) -> ndarray (m, g, ...)``
"""
from __future__ import annotations

import re

import numpy as np

from .. import _core


def variable_by_name(name: str):
    """The registered variable ``name`` (InputError with the nearest names otherwise)."""
    return _core.GetVariable(name)


def is_array3(variable) -> bool:
    return variable.Type() == _core.ValueType.Array3


def is_scalar(variable) -> bool:
    return variable.Type() == _core.ValueType.Double


def nodal_values(part, variable, historical: bool = True) -> np.ndarray:
    """Values of ``variable`` on every node of ``part`` in node-id order: shape (n,) for a
    double or a component (DISPLACEMENT_X), (n, 3) for an array-3 variable."""
    if variable.IsComponent():
        return nodal_values(part, variable.Source(), historical)[:, variable.ComponentIndex()]
    if historical:
        return np.asarray(part.GetNodalValues(variable), dtype=float)
    if hasattr(part, "GetNodalNonHistoricalValues"):
        return np.asarray(part.GetNodalNonHistoricalValues(variable), dtype=float)
    return _nodal_non_historical_fallback(part, variable)


def _nodal_non_historical_fallback(part, variable) -> np.ndarray:
    values = [node.GetValue(variable) for node in part.Nodes]
    width = 3 if is_array3(variable) else None
    if not values:
        return np.zeros((0, 3) if width else (0,))
    return np.asarray(values, dtype=float).reshape((len(values), 3) if width else (len(values),))


def nodal_flags(part, flag) -> np.ndarray:
    """Whether each node of ``part`` (node-id order) has ``flag`` set."""
    if hasattr(part, "GetNodalFlags"):
        return np.asarray(part.GetNodalFlags(flag), dtype=bool)
    return np.fromiter((node.Is(flag) for node in part.Nodes), dtype=bool, count=part.NumberOfNodes())


# Node count and dimension of the name suffix ("...2D4N") -> geometry type, used only when the
# geometry name itself is not reachable from Python.
_ELEMENT_GEOMETRY_BY_SUFFIX = {
    (2, 3): "Triangle2D3", (2, 4): "Quadrilateral2D4", (2, 6): "Triangle2D6",
    (2, 8): "Quadrilateral2D8", (2, 9): "Quadrilateral2D9", (3, 4): "Tetrahedra3D4",
    (3, 10): "Tetrahedra3D10", (3, 8): "Hexahedra3D8", (3, 20): "Hexahedra3D20",
    (3, 27): "Hexahedra3D27", (3, 6): "Prism3D6",
}
_CONDITION_GEOMETRY_BY_SUFFIX = {
    (2, 1): "Point2D", (3, 1): "Point3D", (2, 2): "Line2D2", (2, 3): "Line2D3", (3, 2): "Line3D2",
    (3, 3): "Triangle3D3", (3, 4): "Quadrilateral3D4", (3, 6): "Triangle3D6",
    (3, 8): "Quadrilateral3D8", (3, 9): "Quadrilateral3D9",
}
_SUFFIX = re.compile(r"([23])D(\d+)N$")


def entity_connectivity(part, conditions: bool = False) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Elements (or conditions) of ``part`` grouped by geometry type name:
    ``{name: (entity ids (m,), node ids (m, k))}``, entities in container order."""
    if hasattr(part, "EntityConnectivity"):
        raw = part.EntityConnectivity(conditions)
        return {name: (np.asarray(ids, dtype=np.int64), np.asarray(conn, dtype=np.int64))
                for name, (ids, conn) in raw.items()}
    return _entity_connectivity_fallback(part, conditions)


def _geometry_name_fallback(entity, conditions: bool) -> str:
    try:
        return str(entity.GetGeometry().Name())
    except (TypeError, AttributeError):  # Geometry not bound to Python yet
        pass
    nodes = len(entity.NodeIds())
    match = _SUFFIX.search(entity.Info())
    dim = int(match.group(1)) if match else 3
    table = _CONDITION_GEOMETRY_BY_SUFFIX if conditions else _ELEMENT_GEOMETRY_BY_SUFFIX
    name = table.get((dim, nodes))
    if name is None:
        raise _core.InputError(f"{entity.Info()} {entity.Id}: cannot tell the geometry of an entity with "
                               f"{nodes} nodes")
    return name


def _entity_connectivity_fallback(part, conditions: bool) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    groups: dict[str, tuple[list[int], list[list[int]]]] = {}
    for entity in (part.Conditions if conditions else part.Elements):
        ids, conn = groups.setdefault(_geometry_name_fallback(entity, conditions), ([], []))
        ids.append(entity.Id)
        conn.append(list(entity.NodeIds()))
    return {name: (np.asarray(ids, dtype=np.int64), np.asarray(conn, dtype=np.int64))
            for name, (ids, conn) in groups.items()}


def integration_point_means(part, variable, entity_ids: np.ndarray, conditions: bool = False) -> np.ndarray:
    """Mean over the integration points of ``variable`` for the listed entities: shape (m,) for
    doubles, (m, 3) for array-3 values, (m, w) for vectors (zero-padded to the widest) and
    (m, 9) for matrices (row-major, padded to 3x3)."""
    info = part.ProcessInfo
    get = part.GetCondition if conditions else part.GetElement
    means = []
    for entity_id in entity_ids:
        values = get(int(entity_id)).CalculateOnIntegrationPoints(variable, info)
        means.append(_mean_of(values, variable))
    return _stack(means, variable)


def _mean_of(values, variable):
    kind = variable.Type()
    if len(values) == 0:
        return None
    if kind == _core.ValueType.Matrix:
        padded = np.zeros((3, 3))
        mean = np.mean([np.asarray(v, dtype=float) for v in values], axis=0)
        padded[: mean.shape[0], : mean.shape[1]] = mean
        return padded.reshape(9)
    return np.mean(np.asarray([np.asarray(v, dtype=float) for v in values]), axis=0)


def _stack(means, variable) -> np.ndarray:
    kind = variable.Type()
    if kind == _core.ValueType.Double:
        return np.asarray([0.0 if m is None else float(m) for m in means])
    if kind == _core.ValueType.Array3:
        width = 3
    elif kind == _core.ValueType.Matrix:
        width = 9
    else:
        width = max((np.size(m) for m in means if m is not None), default=1)
    out = np.zeros((len(means), width))
    for i, m in enumerate(means):
        if m is not None:
            flat = np.ravel(m)
            out[i, : flat.size] = flat
    return out
