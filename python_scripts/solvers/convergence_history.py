"""The Newton convergence history of a run as a CSV file (optionally JSON and a PNG plot):
``solver_settings.convergence_history``.

One row per Newton iteration with the step, the (sub-)step time, the iteration number as the
convergence table prints it, every value of the criteria (the ratios and norms of the table, with
their tolerances), the active-set changes and the active slave nodes of contact runs, whether the
criteria were met, and the residual and increment norms. The files are rewritten atomically after
every step, so a run stopped by a step that did not converge keeps the rows up to that step; the
plot is drawn at the end of the run.
"""
from __future__ import annotations

import csv
import importlib.util
import io
import json
import os

from .. import _core
from ..utilities import publish_file, warn, write_text_atomically

FIXED_COLUMNS = ["step", "time", "iteration"]
TRAILING_COLUMNS = ["active_nodes", "converged", "residual_norm", "increment_norm", "step_length"]


class ConvergenceHistory:
    """Collects the iteration records of each step and writes ``<stem>.csv`` (``write_json``:
    also ``<stem>.json``, a list of the same rows; ``plot``: also ``<stem>.png``)."""

    @staticmethod
    def GetDefaultParameters() -> _core.Parameters:
        """file_name: the CSV file ("" writes no history), relative to the working directory like
        the output processes' paths; write_json: also the rows as JSON; plot: also a PNG of the
        criteria over the iterations (needs matplotlib)."""
        return _core.Parameters("""{
            "file_name": "",
            "write_json": false,
            "plot": false
        }""")

    @classmethod
    def from_settings(cls, settings: _core.Parameters) -> ConvergenceHistory | None:
        """The history asked for by a validated ``convergence_history`` block, or None."""
        file_name = settings["file_name"].GetString()
        if not file_name:
            for key in ("write_json", "plot"):
                if settings[key].GetBool():
                    raise _core.InputError(f"{settings.Where()}.{key}: needs a file_name (the CSV file)")
            return None
        stem, extension = os.path.splitext(file_name)
        if extension not in ("", ".csv"):
            raise _core.InputError(f"{settings.Where()}.file_name: '{file_name}' must end with .csv "
                                   f"(the JSON and PNG files take its name with their own extension)")
        plot = settings["plot"].GetBool()
        if plot and importlib.util.find_spec("matplotlib") is None:
            warn(f"{settings.Where()}.plot: matplotlib is not installed (pip install matplotlib); "
                 f"{stem}.csv is written, {stem}.png is not")
            plot = False
        return cls(stem, settings["write_json"].GetBool(), plot)

    def __init__(self, stem: str, write_json: bool, plot: bool):
        self.stem = stem
        self.write_json = write_json
        self.plot = plot
        self.rows: list[dict] = []
        self.written: list[str] = []

    def add_step(self, step: int, history) -> None:
        """Appends the IterationRecords of one step (its failed attempt and sub-steps included)
        and rewrites the files."""
        for record in history:
            row = {"step": step, "time": record.time, "iteration": record.iteration}
            for value in record.criteria:
                if value.tolerance > 0.0:
                    row[value.name] = value.value
                    row[f"{value.name} tolerance"] = value.tolerance
                else:  # a count (active set changes) or a diagnostic (COND.NUM.)
                    row[value.name] = int(value.value) if float(value.value).is_integer() else value.value
            row.update(active_nodes=record.active_nodes if record.active_nodes >= 0 else None,
                       converged=int(record.converged), residual_norm=record.residual_norm,
                       increment_norm=record.increment_norm, step_length=record.step_length)
            self.rows.append(row)
        self._write_tables()

    def columns(self) -> list[str]:
        """The fixed columns, the criteria in the order the table prints them, then the rest."""
        middle = []
        for row in self.rows:
            middle += [key for key in row if key not in FIXED_COLUMNS + TRAILING_COLUMNS and key not in middle]
        trailing = [key for key in TRAILING_COLUMNS if key != "active_nodes"
                    or any(row["active_nodes"] is not None for row in self.rows)]
        return FIXED_COLUMNS + middle + trailing

    def _write_tables(self) -> None:
        columns = self.columns()
        text = io.StringIO()
        writer = csv.DictWriter(text, fieldnames=columns, extrasaction="ignore", lineterminator="\n")
        writer.writeheader()
        for row in self.rows:
            writer.writerow({key: ("" if row.get(key) is None else repr(row[key])) for key in columns})
        self._publish(f"{self.stem}.csv", text.getvalue())
        if self.write_json:
            rows = [{key: row.get(key) for key in columns} for row in self.rows]
            self._publish(f"{self.stem}.json", json.dumps(rows, indent=1) + "\n")

    def _publish(self, path: str, text: str) -> None:
        write_text_atomically(path, text)
        if path not in self.written:
            self.written.append(path)

    def finish(self) -> None:
        """At the end of the run: the PNG, when asked for."""
        if self.plot and self.rows:
            self._plot(f"{self.stem}.png")

    def _plot(self, path: str) -> None:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        contact = any(row.get("active_nodes") is not None for row in self.rows)
        figure, axes = plt.subplots(2 if contact else 1, 1, sharex=True, squeeze=False,
                                    figsize=(8, 6 if contact else 4))
        x = list(range(1, len(self.rows) + 1))
        ratios = axes[0][0]
        for name in self.columns():
            if not name.endswith(" tolerance"):
                continue
            criterion = name[:-len(" tolerance")]
            points = [(i, row[criterion] / row[name]) for i, row in zip(x, self.rows)
                      if row.get(name) and row[criterion] > 0.0]
            if points:
                ratios.semilogy(*zip(*points), marker=".", label=criterion)
        ratios.axhline(1.0, color="black", linewidth=0.8)
        ratios.set_ylabel("value / tolerance (met below 1)")
        ratios.legend(fontsize="small")
        for i in range(1, len(self.rows)):
            if self.rows[i]["step"] != self.rows[i - 1]["step"]:
                for row_axes in axes:
                    row_axes[0].axvline(i + 0.5, color="grey", linewidth=0.5)
        if contact:
            nodes = axes[1][0]
            nodes.step(x, [row["active_nodes"] for row in self.rows], where="mid", label="active slave nodes")
            if any("active set changes" in row for row in self.rows):
                nodes.step(x, [row.get("active set changes", 0) for row in self.rows], where="mid",
                           label="active-set changes")
            nodes.set_ylabel("nodes")
            nodes.legend(fontsize="small")
        axes[-1][0].set_xlabel("Newton iteration (over the run; grey lines: step boundaries)")
        figure.tight_layout()
        folder = os.path.dirname(os.path.abspath(path))
        os.makedirs(folder, exist_ok=True)
        temporary = os.path.join(folder, f".{os.path.basename(path)}.partial.png")
        try:
            figure.savefig(temporary, dpi=100)
            publish_file(temporary, path)
        finally:
            plt.close(figure)
            if os.path.exists(temporary):
                os.remove(temporary)
        if path not in self.written:
            self.written.append(path)
