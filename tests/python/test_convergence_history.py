"""Issue 15, item 4: solver_settings.convergence_history writes the Newton convergence history as
CSV (JSON, PNG on request): one row per iteration that the convergence table prints, with its
values, and a final row that meets the tolerances; kept up to a step that fails."""
from __future__ import annotations

import csv
import json
import os
import re
import sys

import pytest

import mortarcontact as mc
from mortarcontact.analysis_stage import ConvergenceFailure, StructuralMechanicsAnalysis
from mortarcontact.project_parameters import read_project_parameters

from csma_cases import CSMA_CASES

PATCH_2D = "ALM_frictionless_contact_test_2D/hyper_simple_patch_test"
#: a row of the convergence table: the iteration, the criteria values, CONVERGENCE, ACTIVE SET CONV
TABLE_ROW = re.compile(r"^\s+(\d+)((?:\s+-?\d\.\d{3}e[+-]\d+)+)\s+(yes|no)\s+(yes|no(?: \(\d+\))?)\s*$")


def run_patch(monkeypatch, history: dict, change=None) -> StructuralMechanicsAnalysis:
    """The 2D patch test (two steps) with convergence_history `history`, echo level 1."""
    monkeypatch.chdir(CSMA_CASES)
    params = read_project_parameters(f"{PATCH_2D}_parameters.json")
    params["processes"].RemoveValue("json_check_process")
    params["problem_data"]["echo_level"].SetInt(1)
    params["problem_data"]["end_time"].SetDouble(2.0)
    params["solver_settings"]["time_stepping"]["time_step"].SetDouble(1.0)
    params["solver_settings"]["echo_level"].SetInt(1)
    params["solver_settings"].AddValue("convergence_history", mc.Parameters(json.dumps(history)))
    if change:
        change(params)
    analysis = StructuralMechanicsAnalysis(mc.Model(), params, progress=False)
    analysis.Run()
    return analysis


def read_rows(path) -> list[dict]:
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_one_row_per_printed_iteration_and_the_last_meets_the_tolerances(monkeypatch, tmp_path, capfd):
    path = tmp_path / "history" / "patch.csv"
    analysis = run_patch(monkeypatch, {"file_name": str(path), "write_json": True})
    printed = [TABLE_ROW.match(line) for line in capfd.readouterr().out.splitlines()]
    printed = [match for match in printed if match]
    rows = read_rows(path)
    assert len(rows) == len(printed) == sum(entry[2] for entry in analysis.step_log) >= 2
    assert [int(row["iteration"]) for row in rows] == [int(match.group(1)) for match in printed]
    assert [int(row["step"]) for row in rows if row["converged"] == "1"] == [1, 2]
    assert [float(row["time"]) for row in rows if row["converged"] == "1"] == [1.0, 2.0]

    columns = list(rows[0])
    criteria = [name for name in columns if f"{name} tolerance" in columns]
    assert len(criteria) == 4  # |r_u|^2/|r_u0|^2, |r_u|^2/n, |r_lm|^2/|r_lm0|^2, |r_lm|^2/n: the table's
    for row, match in zip(rows, printed):  # the values the table prints, to its 4 digits
        assert [f"{float(row[name]):.3e}" for name in criteria] == match.group(2).split()
        assert (match.group(4) == "yes") == (row["active set changes"] == "0")

    last = rows[-1]
    assert last["converged"] == "1" and last["active set changes"] == "0" and int(last["active_nodes"]) == 2
    # each family (displacement, multiplier) meets its relative or its absolute tolerance
    families = {}
    for name in criteria:
        families.setdefault(name.split("/")[0], []).append(float(last[name]) <= float(last[f"{name} tolerance"]))
    assert len(families) == 2 and all(any(met) for met in families.values()), families

    assert str(path) in analysis.Summary() and str(path.with_suffix(".json")) in analysis.Summary()


def test_json_rows_are_the_csv_rows(monkeypatch, tmp_path):
    path = tmp_path / "patch.csv"
    run_patch(monkeypatch, {"file_name": str(path), "write_json": True})
    with open(path.with_suffix(".json")) as f:
        rows = json.load(f)
    csv_rows = read_rows(path)
    assert len(rows) == len(csv_rows)
    for row, csv_row in zip(rows, csv_rows):
        assert list(row) == list(csv_row)
        assert all(float(csv_row[key]) == value for key, value in row.items() if value is not None)


def test_plot(monkeypatch, tmp_path):
    pytest.importorskip("matplotlib")
    path = tmp_path / "patch.csv"
    analysis = run_patch(monkeypatch, {"file_name": str(path), "plot": True})
    png = path.with_suffix(".png")
    with open(png, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n"
    assert str(png) in analysis.Summary()


def test_plot_without_matplotlib_says_so_and_writes_the_csv(monkeypatch, tmp_path, capsys):
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # as if not installed
    path = tmp_path / "patch.csv"
    run_patch(monkeypatch, {"file_name": str(path), "plot": True})
    err = capsys.readouterr().err
    assert "convergence_history.plot: matplotlib is not installed" in err
    assert path.exists() and not path.with_suffix(".png").exists()


def test_rows_are_kept_up_to_a_failed_step(monkeypatch, tmp_path):
    path = tmp_path / "patch.csv"

    def one_iteration(params):
        params["solver_settings"]["max_iteration"].SetInt(1)

    with pytest.raises(ConvergenceFailure):
        run_patch(monkeypatch, {"file_name": str(path)}, one_iteration)
    rows = read_rows(path)
    assert [(row["step"], row["iteration"], row["converged"]) for row in rows] == [("1", "1", "0")]


@pytest.mark.parametrize("history, message", [
    ({"file_name": "history.txt"}, "file_name: 'history.txt' must end with .csv"),
    ({"plot": True}, "plot: needs a file_name"),
    ({"file_name": "h.csv", "plots": True}, "plot"),
])
def test_bad_settings(monkeypatch, history, message):
    with pytest.raises(mc.InputError, match=re.escape(message)):
        run_patch(monkeypatch, history)
    assert not os.path.exists(os.path.join(CSMA_CASES, "history.txt"))
