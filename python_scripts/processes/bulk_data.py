"""Array access to nodal and elemental data for the processes and writers, through the bulk
calls of the C++ core (no Python loops over nodes or elements)."""
from __future__ import annotations

import numpy as np

from .. import _core
from ..utilities import warn


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
    return np.asarray(part.GetNodalNonHistoricalValues(variable), dtype=float)


class UnsetVariableWarning:
    """Warns, once per variable, that a requested non-historical nodal variable is held by no node
    of the part: nothing in the run has computed it (yet), so it would be written or checked as
    zeros. (A historical variable that the model part does not store is an input error when read.)"""

    def __init__(self, process_name: str):
        self.process_name = process_name
        self.checked: set[str] = set()

    def check(self, part, variable, historical: bool) -> None:
        variable = variable.Source() if variable.IsComponent() else variable
        if historical or variable.Name() in self.checked:
            return
        self.checked.add(variable.Name())
        if not any(node.Has(variable) for node in part.Nodes):
            warn(f"{self.process_name} ({part.FullName()}): {variable.Name()} is not computed on any node of the "
                 "part; its values are zeros")


def nodal_flags(part, flag) -> np.ndarray:
    """Whether each node of ``part`` (node-id order) has ``flag`` set."""
    return np.asarray(part.GetNodalFlags(flag), dtype=bool)


def entity_connectivity(part, conditions: bool = False) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Elements (or conditions) of ``part`` grouped by geometry type name:
    ``{name: (entity ids (m,), node ids (m, k))}``, entities in container order."""
    return dict(part.EntityConnectivity(conditions))


def integration_point_means(part, variable, entity_ids: np.ndarray, conditions: bool = False) -> np.ndarray:
    """Mean over the integration points of ``variable`` for the listed entities: shape (m,) for
    doubles, (m, 3) for array-3 values, (m, w) for vectors (zero-padded to the widest) and
    (m, 9) for matrices (row-major, padded to 3x3)."""
    return part.IntegrationPointMeans(variable, [int(i) for i in entity_ids], conditions)
