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
    """Warns, once per part and variable, that a requested output variable is computed by nothing in the
    run, so that it is written or checked as zeros:

    - a non-historical nodal variable that no node of the part holds when it is first read;
    - a historical nodal variable that is no unknown (DoF) of the part's nodes and held zero on
      every node at every read (said by ``finish``, at the end of the run: a reaction or a load
      may become non-zero only in a later step);
    - an integration-point variable that the part's elements or conditions do not compute
      (``not_computed``, when it is read).

    (A historical variable that the model part does not store is an input error.)"""

    def __init__(self, process_name: str):
        self.process_name = process_name
        self.checked: set[tuple[str, str]] = set()  # (part, variable)
        self.pending: set[tuple[str, str]] = set()  # historical ones that have held only zeros

    def check(self, part, variable, historical: bool, values: np.ndarray | None = None) -> None:
        """Reports ``variable`` of ``part`` if nothing computes it; ``values``: what was read."""
        variable = variable.Source() if variable.IsComponent() else variable
        name = variable.Name()
        key = (part.FullName(), name)
        if key in self.checked:
            if key in self.pending and values is not None and np.any(values != 0.0):
                self.pending.discard(key)
            return
        self.checked.add(key)
        if not historical:
            if not any(node.Has(variable) for node in part.Nodes):
                warn(f"{self.process_name} ({part.FullName()}): {name} is not computed on any node of the part; "
                     "its values are zeros")
            return
        dof = _core.GetVariable(f"{name}_X") if is_array3(variable) else variable if is_scalar(variable) else None
        unknown = dof is not None and any(node.HasDofFor(dof) for node in part.Nodes)
        if not unknown and (values is None or not np.any(values != 0.0)):
            self.pending.add(key)

    def not_computed(self, part, variable, reason: str) -> None:
        """Reports an integration-point variable that an entity of ``part`` does not compute."""
        key = (part.FullName(), variable.Name())
        if key in self.checked:
            return
        self.checked.add(key)
        warn(f"{self.process_name} ({part.FullName()}): {variable.Name()} is not computed ({reason}); "
             "its values are zeros")

    def finish(self) -> None:
        """At the end of the run: the historical variables that held only zeros."""
        for part, name in sorted(self.pending):
            warn(f"{self.process_name} ({part}): {name} is no unknown of the part and was zero on every node "
                 "whenever it was read: nothing in the run computes it there")
        self.pending.clear()


def check_historical(part, variables, where: str, remedy: str) -> None:
    """InputError for the first of ``variables`` that ``part`` does not store as historical
    (at Check, before the first step, rather than at the first read, after a solve)."""
    for variable in variables:
        source = variable.Source() if variable.IsComponent() else variable
        if not part.HasNodalSolutionStepVariable(source):
            raise _core.InputError(
                f"{where}: {source.Name()} is not a historical (solution step) variable of {part.FullName()}; for "
                f"values that are not historical, such as the contact results NORMAL_CONTACT_STRESS and "
                f"CONTACT_PRESSURE, {remedy}")


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
