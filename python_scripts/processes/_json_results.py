"""What the JSON result writer and checker share: which nodes, which keys, which values.

Reference format: ``{"TIME": [t1, ...], "NODE_<id>": {"DISPLACEMENT_X": [v(t1), ...], ...},
"ELEMENT_<id>": {"VAR": {"<gauss point>": [...]}}}``; array-3 variables are stored per
component (``<VAR>_X/_Y/_Z``); with ``use_node_coordinates`` the node key is
``NODE_X_<X0>_Y_<Y0>_Z_<Z0>`` with 6 decimals.
"""
from __future__ import annotations

import json

import numpy as np

from .. import _core
from ..process import Process
from ..utilities import write_text_atomically
from .bulk_data import (
    UnsetVariableWarning,
    check_historical,
    is_array3,
    nodal_flags,
    nodal_values,
    variable_by_name,
)
from .model_part_resolution import resolve_model_part


def results_model_part(model, settings):
    """``model_part_name`` plus the optional ``sub_model_part_name``."""
    part = resolve_model_part(model, settings["model_part_name"].GetString())
    sub = settings["sub_model_part_name"].GetString()
    return part.GetSubModelPart(sub) if sub else part


def node_mask(part, flag_name: str) -> np.ndarray:
    """Nodes (node-id order) selected by ``check_for_flag`` ("" = all)."""
    if not flag_name:
        return np.ones(part.NumberOfNodes(), dtype=bool)
    return nodal_flags(part, _core.GetFlag(flag_name))


def node_keys(part, mask: np.ndarray, use_coordinates: bool) -> list[str]:
    if use_coordinates:
        coordinates = part.NodeCoordinates(True)[mask]
        return [f"NODE_X_{x:.6f}_Y_{y:.6f}_Z_{z:.6f}" for x, y, z in coordinates]
    return [f"NODE_{i}" for i in part.NodeIds()[mask]]


def value_columns(part, variable_name: str, historical: bool, mask: np.ndarray,
                  unset: UnsetVariableWarning) -> dict[str, np.ndarray]:
    """``{key: values of the selected nodes}``; array-3 variables split into components. A
    variable that no node holds is reported through ``unset``."""
    variable = variable_by_name(variable_name)
    if is_array3(variable) or variable.Type() == _core.ValueType.Double:
        values = nodal_values(part, variable, historical)
        unset.check(part, variable, historical, values)
        if is_array3(variable):
            return {f"{variable_name}_{axis}": values[mask][:, k] for k, axis in enumerate("XYZ")}
        return {variable_name: values[mask]}
    unset.check(part, variable, historical)
    if historical:
        raise _core.InputError(f"{variable_name} is a {variable.Type().name} variable, which cannot be historical; "
                               "set historical_value to false")
    nodes = [node for node, keep in zip(part.Nodes, mask) if keep]
    return {variable_name: np.asarray([float(node.GetValue(variable)) for node in nodes])}


def gauss_point_columns(element, variable_name: str, info) -> dict[str, list[float]]:
    """``{key: value per integration point}`` of one element; array-3 split into components."""
    variable = variable_by_name(variable_name)
    values = element.CalculateOnIntegrationPoints(variable, info)
    if is_array3(variable):
        return {f"{variable_name}_{axis}": [float(v[k]) for v in values] for k, axis in enumerate("XYZ")}
    if variable.Type() == _core.ValueType.Double:
        return {variable_name: [float(v) for v in values]}
    raise _core.InputError(f"{variable_name}: only double and array-3 variables can be written or checked "
                           "on integration points")


def owned_mask(ranks, part, mask: np.ndarray) -> np.ndarray:
    """``mask`` restricted to the nodes this rank reports (all of them without ``ranks``)."""
    return mask if ranks is None else mask & ranks.owned_nodes(part)


def selected_elements(part, flag_name: str, ranks) -> list:
    """The elements with the ``check_for_flag`` flag ("" = all) that this rank reports."""
    flag = _core.GetFlag(flag_name) if flag_name else None
    owned = None if ranks is None else ranks.owned_elements(part)
    return [element for element in part.Elements
            if (flag is None or element.Is(flag)) and (owned is None or element.Id in owned)]


def merge_pieces(pieces: list[tuple[dict, dict]]) -> dict:
    """The serial run's results from each rank's ``(results of the entities it owns, {node key:
    node id})``: the times, the resultants summed over the ranks, the nodes in node-id order, then
    the elements in id order. A resultant sums the ranks' partial sums: it differs from the serial
    sum in the last bits only."""
    merged: dict = {"TIME": pieces[0][0]["TIME"]}
    resultants = [data["RESULTANT"] for data, _ in pieces if "RESULTANT" in data]
    if resultants:
        merged["RESULTANT"] = _summed(resultants)
    entities, node_ids = {}, {}
    for data, ids in pieces:
        entities.update((key, value) for key, value in data.items() if key not in ("TIME", "RESULTANT"))
        node_ids.update(ids)
    nodes = sorted((key for key in entities if key in node_ids), key=node_ids.__getitem__)
    elements = sorted((key for key in entities if key not in node_ids), key=lambda key: int(key.split("_")[1]))
    merged.update((key, entities[key]) for key in (*nodes, *elements))
    return merged


def _summed(series: list):
    """The element-wise sum of equally nested ``{key: [...] or {...}}`` (a key some lack counts 0)."""
    if isinstance(series[0], list):
        return [float(sum(values)) for values in zip(*series)]
    keys = list(dict.fromkeys(key for entry in series for key in entry))
    return {key: _summed([entry[key] for entry in series if key in entry]) for key in keys}


def write_json_atomically(path: str, data) -> None:
    write_text_atomically(path, json.dumps(data, indent=4))


class TimeCounter:
    """Kratos' sampling rule: DELTA_TIME accumulates every step; a step is sampled when the sum
    exceeds ``frequency`` strictly, and the sum then restarts from zero (``frequency`` 0 samples
    every step with a positive time step)."""

    def __init__(self, frequency: float):
        self.frequency = frequency
        self.elapsed = 0.0

    def step(self, delta_time: float) -> bool:
        self.elapsed += delta_time
        if self.elapsed > self.frequency:
            self.elapsed = 0.0
            return True
        return False


class JsonResultsProcess(Process):
    """The settings the JSON writer and checker share: their file (FILE_KEY), the nodal and
    integration-point variables (VARIABLES_KEY, GAUSS_KEY), ``historical_value``,
    ``check_for_flag``, ``use_node_coordinates`` and ``time_frequency``."""

    NAME = ""
    FILE_KEY = ""
    VARIABLES_KEY = ""
    GAUSS_KEY = ""

    def __init__(self, model, settings):
        super().__init__(model, settings)
        s = self.settings
        for key in (self.FILE_KEY, "model_part_name"):
            if not s[key].GetString():
                raise _core.InputError(f"{s.Where()}: {self.NAME} requires '{key}'")
        self.file_name = s[self.FILE_KEY].GetString()
        self.variables = s[self.VARIABLES_KEY].GetStringArray()
        self.gauss_variables = s[self.GAUSS_KEY].GetStringArray()
        self.historical = s["historical_value"].GetBool()
        self.flag = s["check_for_flag"].GetString()
        self.use_coordinates = s["use_node_coordinates"].GetBool()
        self.counter = TimeCounter(s["time_frequency"].GetDouble())
        self.model_part = None
        self.unset = UnsetVariableWarning(self.NAME)
        self.ranks = None  # a model cut across the ranks: each reports what it owns

    def ExecuteAfterModelCut(self, ranks) -> None:
        self.ranks = ranks

    def RestartState(self):
        return {"elapsed": self.counter.elapsed}

    def LoadRestartState(self, state) -> None:
        self.counter.elapsed = state["elapsed"]

    def Check(self) -> None:
        if self.historical and self.model_part is not None:
            check_historical(self.model_part, [variable_by_name(name) for name in self.variables],
                             self.settings[self.VARIABLES_KEY].Where(), "set historical_value to false")

    def ExecuteFinalize(self) -> None:
        self.unset.finish()
