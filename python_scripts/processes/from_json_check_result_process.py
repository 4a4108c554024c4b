"""``from_json_check_result_process``: the test oracle of the Kratos cases (spec 4.9)."""
from __future__ import annotations

import json
import os

import numpy as np

from .. import _core
from ._json_results import (
    JsonResultsProcess,
    gauss_point_columns,
    node_keys,
    node_mask,
    owned_mask,
    results_model_part,
    selected_elements,
    value_columns,
)


class CheckResultError(AssertionError):
    """A computed value differs from the reference beyond the tolerances."""


def is_close(value, reference, tolerance: float, relative_tolerance: float):
    """Kratos' (and ``math.isclose``'s) rule, element-wise:
    ``|value - reference| <= max(relative_tolerance * max(|value|, |reference|), tolerance)``,
    i.e. a value passes if it is within the absolute ``tolerance`` OR within
    ``relative_tolerance`` relative to the larger magnitude of the two."""
    value, reference = np.asarray(value, dtype=float), np.asarray(reference, dtype=float)
    bound = np.maximum(relative_tolerance * np.maximum(np.abs(value), np.abs(reference)), tolerance)
    return np.abs(value - reference) <= bound


def interpolation_weights(times: np.ndarray, time: float) -> tuple[int, int, float]:
    """Indices i, j and weight w such that the reference at ``time`` is
    (1 - w)·v[i] + w·v[j]; constant outside the stored range."""
    if len(times) == 1 or time <= times[0]:
        return 0, 0, 0.0
    if time >= times[-1]:
        return len(times) - 1, len(times) - 1, 0.0
    j = int(np.searchsorted(times, time, side="right"))
    i = j - 1
    span = times[j] - times[i]
    return i, j, 0.0 if span == 0.0 else (time - times[i]) / span


class FromJsonCheckResultProcess(JsonResultsProcess):
    """At ``ExecuteFinalizeSolutionStep``, on sampled steps (DELTA_TIME accumulates and a step
    is checked once the sum exceeds ``time_frequency`` strictly, then the sum restarts; 0 = every
    step), compares every node's ``check_variables`` (and every element's
    ``gauss_points_check_variables``) with the reference file, interpolated linearly in TIME and
    held constant outside the stored times. A value passes when
    ``|value - ref| <= max(relative_tolerance * max(|value|, |ref|), tolerance)``; otherwise
    ``CheckResultError`` (an AssertionError) names the node, the variable, the time, the value,
    the reference and both tolerances.

    Keys (default): ``check_variables`` ([]), ``gauss_points_check_variables`` ([]),
    ``input_file_name`` (required), ``model_part_name`` (required), ``sub_model_part_name`` (""),
    ``check_for_flag`` (""), ``historical_value`` (true), ``tolerance`` (1e-3, absolute),
    ``relative_tolerance`` (1e-6), ``time_frequency`` (1.0), ``use_node_coordinates`` (false),
    ``check_only_local_entities`` (false; without effect: every entity is checked once, on a model
    cut across the ranks by its owner), ``help``. A non-historical variable that no node holds is
    checked as zeros, with a warning.
    """

    NAME = "from_json_check_result_process"
    FILE_KEY = "input_file_name"
    VARIABLES_KEY = "check_variables"
    GAUSS_KEY = "gauss_points_check_variables"

    @classmethod
    def GetDefaultParameters(cls):
        return _core.Parameters("""{
            "help": "", "check_variables": [], "gauss_points_check_variables": [],
            "input_file_name": "", "model_part_name": "", "sub_model_part_name": "",
            "check_for_flag": "", "historical_value": true, "tolerance": 1e-3,
            "relative_tolerance": 1e-6, "time_frequency": 1.0, "use_node_coordinates": false,
            "check_only_local_entities": false
        }""", "defaults")

    def __init__(self, model, settings):
        super().__init__(model, settings)
        self.tolerance = self.settings["tolerance"].GetDouble()
        self.relative_tolerance = self.settings["relative_tolerance"].GetDouble()
        self.checks_done = 0

    def ExecuteInitialize(self) -> None:
        if not os.path.isfile(self.file_name):
            raise _core.InputError(f"{self.settings.Where()}: reference file '{self.file_name}' does not exist")
        with open(self.file_name) as stream:
            self.reference = json.load(stream)
        if "TIME" not in self.reference:
            raise _core.InputError(f"{self.file_name}: the reference has no 'TIME' list")
        self.times = np.asarray(self.reference["TIME"], dtype=float)
        self.model_part = results_model_part(self.model, self.settings)

    def _reference_series(self, entity_key: str, key: str, *gauss_point: str) -> np.ndarray:
        try:
            entry = self.reference[entity_key][key]
            for gp in gauss_point:
                entry = entry[gp]
        except KeyError:
            what = f"{entity_key} {key}" + (f" point {gauss_point[0]}" if gauss_point else "")
            raise _core.InputError(f"{self.file_name}: no reference values for {what}") from None
        series = np.asarray(entry, dtype=float)
        if series.shape != self.times.shape:
            raise _core.InputError(f"{self.file_name}: {entity_key} {key} has {series.size} values for "
                                   f"{self.times.size} times")
        return series

    def ExecuteFinalizeSolutionStep(self) -> None:
        if self.model_part is None:
            self.ExecuteInitialize()
        info = self.model_part.ProcessInfo
        if not self.counter.step(float(info.GetValue(_core.DELTA_TIME))):
            return
        time = float(info.GetValue(_core.TIME))
        i, j, w = interpolation_weights(self.times, time)
        failures = self._failures(time, i, j, w)
        self.checks_done += 1
        if failures:
            shown = "\n  ".join(failures[:10])
            more = f"\n  ... and {len(failures) - 10} more" if len(failures) > 10 else ""
            raise CheckResultError(f"{self.file_name}: {len(failures)} value(s) differ from the reference "
                                   f"at time {time:.10g} (tolerance {self.tolerance:g}, relative_tolerance "
                                   f"{self.relative_tolerance:g}):\n  {shown}{more}")

    def _failures(self, time, i, j, w) -> list[str]:
        """The failed comparisons in the serial run's order. Of a model cut across the ranks, each
        rank compares the entities it owns and every rank gets all the failures (and the first
        rank's reference error), so that every rank passes or stops together, with one message."""
        failures: list[tuple[tuple, str]] = []  # (place in the serial order, message)
        problem = ""
        try:
            self._check_nodes(time, i, j, w, failures)
            self._check_gauss_points(time, i, j, w, failures)
        except _core.InputError as error:
            if self.ranks is None:
                raise
            problem = str(error)
        if self.ranks is not None:
            pieces = self.ranks.all_gather((failures, problem))
            problem = next((piece_problem for _, piece_problem in pieces if piece_problem), "")
            if problem:
                raise _core.InputError(problem)
            failures = sorted(failure for piece_failures, _ in pieces for failure in piece_failures)
        return [message for _, message in failures]

    def RestartState(self):
        return {**super().RestartState(), "checks_done": self.checks_done}

    def LoadRestartState(self, state) -> None:
        super().LoadRestartState(state)
        self.checks_done = state["checks_done"]

    def _failure(self, entity: str, key: str, time: float, value: float, reference: float) -> str:
        return (f"{entity}, {key}, time {time:.10g}: value {value:.10g} != reference {reference:.10g} "
                f"(difference {abs(value - reference):.3g}; tolerance {self.tolerance:g}, "
                f"relative_tolerance {self.relative_tolerance:g})")

    def _check_nodes(self, time, i, j, w, failures) -> None:
        if not self.variables:
            return
        mask = owned_mask(self.ranks, self.model_part, node_mask(self.model_part, self.flag))
        keys = node_keys(self.model_part, mask, self.use_coordinates)
        ids = self.model_part.NodeIds()[mask]
        for v, name in enumerate(self.variables):
            columns = value_columns(self.model_part, name, self.historical, mask, self.unset)
            for c, (key, values) in enumerate(columns.items()):
                series = np.asarray([self._reference_series(node_key, key) for node_key in keys]).reshape(len(keys), -1)
                reference = (1.0 - w) * series[:, i] + w * series[:, j] if len(keys) else np.zeros(0)
                bad = np.flatnonzero(~is_close(values, reference, self.tolerance, self.relative_tolerance))
                failures.extend(((0, v, c, int(ids[k]), 0), self._failure(f"node {ids[k]}", key, time, values[k],
                                                                          reference[k])) for k in bad)

    def _check_gauss_points(self, time, i, j, w, failures) -> None:
        if not self.gauss_variables:
            return
        info = self.model_part.ProcessInfo
        for element in selected_elements(self.model_part, self.flag, self.ranks):
            for v, name in enumerate(self.gauss_variables):
                for c, (key, values) in enumerate(gauss_point_columns(element, name, info).items()):
                    for gp, value in enumerate(values):
                        series = self._reference_series(f"ELEMENT_{element.Id}", key, str(gp))
                        reference = (1.0 - w) * series[i] + w * series[j]
                        if not is_close(value, reference, self.tolerance, self.relative_tolerance):
                            failures.append(((1, element.Id, v, c, gp), self._failure(
                                f"element {element.Id} point {gp}", key, time, value, reference)))
