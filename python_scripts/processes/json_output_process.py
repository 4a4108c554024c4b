"""``json_output_process``: records nodal (and integration-point) values in the reference format
read by ``from_json_check_result_process``."""
from __future__ import annotations

import numpy as np

from .. import _core
from ._json_results import (
    JsonResultsProcess,
    gauss_point_columns,
    merge_pieces,
    node_keys,
    node_mask,
    owned_mask,
    results_model_part,
    selected_elements,
    value_columns,
    write_json_atomically,
)
from .bulk_data import variable_by_name


class JsonOutputProcess(JsonResultsProcess):
    """Samples ``output_variables`` at ``ExecuteFinalizeSolutionStep`` (see ``TimeCounter`` for
    ``time_frequency``) and writes ``output_file_name`` at ``ExecuteFinalize`` in one atomic
    replace, so a failed run never leaves a half-written reference.

    Keys (default): ``output_variables`` ([]), ``gauss_points_output_variables`` ([]),
    ``output_file_name`` (required), ``model_part_name`` (required), ``sub_model_part_name`` (""),
    ``time_frequency`` (1.0), ``historical_value`` (true), ``resultant_solution`` (false: one
    entry per node; true: the sum over the nodes under ``RESULTANT``), ``check_for_flag`` ("" or
    a flag name: only nodes with that flag), ``use_node_coordinates`` (false), ``help``. A non-historical
    variable that no node holds is recorded as zeros with a warning.
    """

    NAME = "json_output_process"
    FILE_KEY = "output_file_name"
    VARIABLES_KEY = "output_variables"
    GAUSS_KEY = "gauss_points_output_variables"

    @classmethod
    def GetDefaultParameters(cls):
        return _core.Parameters("""{
            "help": "", "output_variables": [], "gauss_points_output_variables": [],
            "output_file_name": "", "model_part_name": "", "sub_model_part_name": "",
            "time_frequency": 1.0, "historical_value": true, "resultant_solution": false,
            "check_for_flag": "", "use_node_coordinates": false
        }""", "defaults")

    def __init__(self, model, settings):
        super().__init__(model, settings)
        self.resultant = self.settings["resultant_solution"].GetBool()
        self.data: dict = {"TIME": []}
        self.node_ids: dict[str, int] = {}  # node key -> id, to merge the pieces of a cut model
        self.written = False

    def ExecuteInitialize(self) -> None:
        self.model_part = results_model_part(self.model, self.settings)

    def ExecuteFinalizeSolutionStep(self) -> None:
        if self.model_part is None:
            self.ExecuteInitialize()
        info = self.model_part.ProcessInfo
        if not self.counter.step(float(info.GetValue(_core.DELTA_TIME))):
            return
        self.data["TIME"].append(float(info.GetValue(_core.TIME)))
        self._sample_nodes()
        self._sample_gauss_points()

    def _sample_nodes(self) -> None:
        if not self.variables:
            return
        mask = owned_mask(self.ranks, self.model_part, node_mask(self.model_part, self.flag))
        keys = node_keys(self.model_part, mask, self.use_coordinates)
        if self.ranks is not None and not self.resultant:
            self.node_ids.update(zip(keys, self.model_part.NodeIds()[mask].tolist()))
        for name in self.variables:
            for key, values in value_columns(self.model_part, name, self.historical, mask, self.unset).items():
                if self.resultant:
                    self.data.setdefault("RESULTANT", {}).setdefault(key, []).append(float(np.sum(values)))
                    continue
                for node_key, value in zip(keys, values):
                    self.data.setdefault(node_key, {}).setdefault(key, []).append(float(value))

    def _sample_gauss_points(self) -> None:
        if not self.gauss_variables:
            return
        info = self.model_part.ProcessInfo
        for element in selected_elements(self.model_part, self.flag, self.ranks):
            for name in self.gauss_variables:
                try:
                    columns = gauss_point_columns(element, name, info)
                except _core.NotImplementedFeatureError as error:  # not written for this element
                    self.unset.not_computed(self.model_part, variable_by_name(name), str(error))
                    continue
                for key, values in columns.items():
                    if self.resultant:
                        entry = self.data.setdefault("RESULTANT", {}).setdefault(key, {})
                    else:
                        entry = self.data.setdefault(f"ELEMENT_{element.Id}", {}).setdefault(key, {})
                    for gp, value in enumerate(values):
                        series = entry.setdefault(str(gp), [])
                        if self.resultant and len(series) == len(self.data["TIME"]):
                            series[-1] += value
                        else:
                            series.append(value)

    def write(self) -> None:
        """Writes what was recorded so far (atomically); of a cut model, what the ranks recorded,
        merged on every rank (collective) and written by rank 0."""
        write_json_atomically(self.file_name, self._merged())
        self.written = True

    def _merged(self) -> dict:
        """What was recorded so far; of a cut model, the ranks' records merged (collective)."""
        return self.data if self.ranks is None else merge_pieces(self.ranks.all_gather((self.data, self.node_ids)))

    def OutputFiles(self) -> list[str]:
        return [self.file_name] if self.written else []

    def RestartState(self):
        """The values recorded so far: a resumed run writes the whole series. Of a cut model, the
        serial run's (collective)."""
        return {**super().RestartState(), "data": self._merged()}

    def LoadRestartState(self, state) -> None:
        super().LoadRestartState(state)
        self.data = state["data"] if self.ranks is None else self._own_piece(state["data"])

    def _own_piece(self, data: dict) -> dict:
        """Of the serial series ``data``, what this rank of a cut model records: its owned nodes and
        elements, and the resultants on rank 0 only (as zeros elsewhere: the ranks' series are summed)."""
        mask = owned_mask(self.ranks, self.model_part, np.ones(self.model_part.NumberOfNodes(), dtype=bool))
        keys = node_keys(self.model_part, mask, self.use_coordinates)
        self.node_ids = dict(zip(keys, self.model_part.NodeIds()[mask].tolist()))
        elements = {f"ELEMENT_{element}" for element in self.ranks.owned_elements(self.model_part)}
        piece = {key: value for key, value in data.items() if key in self.node_ids or key in elements}
        piece["TIME"] = data["TIME"]
        if "RESULTANT" in data:
            piece["RESULTANT"] = data["RESULTANT"] if self.ranks.rank == 0 else _zeros(data["RESULTANT"])
        return piece

    def ExecuteFinalize(self) -> None:
        self.write()
        super().ExecuteFinalize()

    def ExecuteAfterFailure(self) -> None:
        self.write()


def _zeros(series):
    """``series`` (nested ``{key: [...] or {...}}``) with every value 0."""
    if isinstance(series, list):
        return [0.0] * len(series)
    return {key: _zeros(entry) for key, entry in series.items()}
