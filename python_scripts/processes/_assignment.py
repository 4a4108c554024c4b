"""Shared machinery of the assignment processes: intervals, values and per-component work.

Per-node work goes through ``VariableUtils`` (C++); Python only decides what to assign when.
"""
from __future__ import annotations

import json
import os
from typing import ClassVar

import numpy as np

from .. import _core
from .bulk_data import is_array3, is_scalar, variable_by_name

END_OF_TIME = 1e30


def to_python(settings):
    """A plain Python value (dict, list, float, str, None) of a Parameters view."""
    return json.loads(settings.WriteJsonString())


def require_keys(settings, process_name: str, keys) -> None:
    for key in keys:
        if not settings.Has(key) or settings[key].IsNull():
            raise _core.InputError(f"{settings.Where()}: {process_name} requires the key '{key}'")


class Interval:
    """A closed time window ``[begin, end]`` from ``interval`` (``"Begin"``/``"End"`` allowed),
    with Kratos' tolerance max(1e-14·|bound|, 1e-30) on both sides."""

    def __init__(self, value, where: str = ""):
        if value is None:
            value = [0.0, END_OF_TIME]
        if not isinstance(value, list) or len(value) != 2:
            raise _core.InputError(f"{where}: 'interval' must be [begin, end], got {json.dumps(value)}")
        begin, end = value
        if begin == "Begin":
            begin = -END_OF_TIME
        if end == "End":
            end = END_OF_TIME
        if not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in (begin, end)):
            raise _core.InputError(f"{where}: 'interval' entries must be numbers, \"Begin\" or \"End\", "
                                   f"got {json.dumps(value)}")
        if end < begin:
            raise _core.InputError(f"{where}: 'interval' ends before it begins: {json.dumps(value)}")
        self.begin, self.end = float(begin), float(end)

    def contains(self, time: float) -> bool:
        low = self.begin - max(1e-14 * abs(self.begin), 1e-30)
        high = self.end + max(1e-14 * abs(self.end), 1e-30)
        return low < time < high


class CsvTable:
    """A time table read from a CSV file (``{"name": "csv_table", "filename": ...}``), linearly
    interpolated in ``t`` and held constant outside its range."""

    DEFAULTS: ClassVar[dict] = {"name": "csv_table", "filename": None, "delimiter": ",", "skiprows": 0,
                                "first_column_id": 0, "second_column_id": 1, "table_id": -1, "na_replace": 0.0}

    def __init__(self, spec: dict, where: str):
        unknown = set(spec) - set(self.DEFAULTS)
        if unknown:
            raise _core.InputError(f"{where}: unknown key(s) {sorted(unknown)} in a table value; valid keys: "
                                   f"{sorted(self.DEFAULTS)}")
        spec = {**self.DEFAULTS, **spec}
        if not spec["filename"] or not os.path.isfile(spec["filename"]):
            raise _core.InputError(f"{where}: table file '{spec['filename']}' does not exist")
        data = np.genfromtxt(spec["filename"], delimiter=spec["delimiter"], skip_header=int(spec["skiprows"]),
                             filling_values=float(spec["na_replace"]), ndmin=2)
        self.t = data[:, int(spec["first_column_id"])]
        self.v = data[:, int(spec["second_column_id"])]
        order = np.argsort(self.t, kind="stable")
        self.t, self.v = self.t[order], self.v[order]

    def __call__(self, time: float) -> float:
        return float(np.interp(time, self.t, self.v))


class ScalarValue:
    """A number, an expression of x, y, z, X, Y, Z, t (compiled by ``FunctionExpression``, never
    Python's eval) or a CSV time table."""

    def __init__(self, value, where: str):
        self.constant: float | None = None
        self.expression = None
        self.table: CsvTable | None = None
        if isinstance(value, bool) or value is None:
            raise _core.InputError(f"{where}: expected a number or an expression string, got {json.dumps(value)}")
        if isinstance(value, (int, float)):
            self.constant = float(value)
        elif isinstance(value, str):
            self.expression = _core.FunctionExpression(value)
            if not self.expression.DependsOnSpace() and not self.expression.DependsOnTime():
                self.constant = self.expression.Evaluate(0.0, 0.0, 0.0, 0.0)
                self.expression = None
        elif isinstance(value, dict):
            self.table = CsvTable(value, where)
        else:
            raise _core.InputError(f"{where}: expected a number or an expression string, got {json.dumps(value)}")

    def scaled(self, factor: float, where: str) -> ScalarValue:
        """This value times ``factor`` (used to split a modulus along a direction)."""
        if self.expression is not None:
            return ScalarValue(f"({factor!r})*({self.expression.Text()})", where)
        if self.table is not None:
            scaled = ScalarValue(0.0, where)
            scaled.constant = None
            scaled.table = _ScaledTable(self.table, factor)
            return scaled
        return ScalarValue(factor * self.constant, where)

    def assign_to_nodes(self, part, variable, time: float, fix: bool) -> None:
        if self.expression is not None:
            _core.VariableUtils.AssignNodalScalar(part, variable, self.expression, time, fix)
        else:
            _core.VariableUtils.AssignNodalScalar(part, variable, self.at(time), fix)

    def assign_to_conditions(self, part, variable, time: float) -> None:
        if self.expression is not None:
            _core.VariableUtils.AssignConditionScalar(part, variable, self.expression, time)
        else:
            _core.VariableUtils.AssignConditionScalar(part, variable, self.at(time))

    def at(self, time: float) -> float:
        return self.table(time) if self.table is not None else self.constant


class _ScaledTable:
    def __init__(self, table: CsvTable, factor: float):
        self.table, self.factor = table, factor

    def __call__(self, time: float) -> float:
        return self.factor * self.table(time)


def components_of(variable_name: str, where: str):
    """The X, Y, Z component variables of an array-3 variable."""
    variable = variable_by_name(variable_name)
    if not is_array3(variable):
        raise _core.InputError(f"{where}: variable_name '{variable_name}' is not an array-3 variable")
    return [variable_by_name(f"{variable_name}_{axis}") for axis in "XYZ"]


def scalar_variable(variable_name: str, where: str):
    variable = variable_by_name(variable_name)
    if not is_scalar(variable):
        raise _core.InputError(f"{where}: variable_name '{variable_name}' is not a scalar (double) variable "
                               "or a component such as DISPLACEMENT_X")
    return variable


def parse_direction(direction, where: str) -> np.ndarray:
    if isinstance(direction, str):
        if direction in ("automatic_inwards_normal", "automatic_outwards_normal"):
            raise _core.NotImplementedFeatureError(
                f"{where}: direction '{direction}' is not implemented yet; give the direction as a 3-vector")
        raise _core.InputError(f"{where}: direction must be a 3-vector, 'automatic_inwards_normal' or "
                               f"'automatic_outwards_normal', got '{direction}'")
    if (not isinstance(direction, list) or len(direction) != 3
            or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in direction)):
        raise _core.InputError(f"{where}: direction must be a 3-vector of numbers, got {json.dumps(direction)}")
    vector = np.asarray(direction, dtype=float)
    norm = np.linalg.norm(vector)
    if norm == 0.0:
        raise _core.InputError(f"{where}: direction {json.dumps(direction)} has zero length")
    return vector / norm


def current_time(part) -> float:
    return float(part.ProcessInfo.GetValue(_core.TIME))


def defaults(text: str):
    return _core.Parameters(text, "defaults")
