# SPDX-License-Identifier: BSD-3-Clause
"""Issue 4 (time per phase): the benchmark runner records mortarcontact's time in the contact
search, the mortar weighted gap and normals, the condition and element loops of the assembly and
the linear solve; each phase was entered, and together they fit inside the analysis time."""
from __future__ import annotations

import importlib.util
import json
import os
import sys

import pytest

pytestmark = pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")

HERTZ_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks", "hertz"))
sys.path.insert(0, HERTZ_DIR)

import case_runner  # noqa: E402
import compare  # noqa: E402
import generate_cases  # noqa: E402


def test_runner_records_every_phase(tmp_path, monkeypatch):
    folder = generate_cases.write_case("hertz2d", "2k", str(tmp_path))
    monkeypatch.chdir(tmp_path)  # the runner changes into the case folder
    output = tmp_path / "run.json"
    assert case_runner.main(["--code", "mortarcontact", folder, str(output)]) == 0
    record = json.loads(output.read_text())
    assert record["status"] == "ok", record.get("error")
    phases = record["phases"]
    for key in ("search", "weighted_gap", "normals", "conditions", "elements", "solve", "dof_setup"):
        assert phases[key] > 0.0, key
    assert phases["build_other"] >= 0.0
    timed = sum(v for k, v in phases.items() if k != "rest")
    assert timed <= record["analysis_seconds"]
    assert phases["rest"] == pytest.approx(record["analysis_seconds"] - timed, abs=1e-12)

    # The comparison's phase table: one row, shares of the total that add up to 100 %.
    with open(os.path.join(folder, "hertz.json")) as f:
        hertz = json.load(f)
    summary = {"mortarcontact": {"status": "ok", "analysis_seconds": record["analysis_seconds"], "phases": phases,
                                 "iterations": [s["iterations"] for s in record["steps"]]}}
    rows = compare.phase_table([("hertz2d_2k", hertz, summary)]).splitlines()
    assert len(rows) == 3
    cells = [c.strip() for c in rows[2].strip("|").split("|")]
    shares = [float(c.split("(")[1].rstrip(" %)")) for c in cells[3:3 + len(compare.PHASE_COLUMNS)]]
    assert sum(shares) == pytest.approx(100.0, abs=0.5 * len(shares))
    assert int(cells[-1]) == sum(s["iterations"] for s in record["steps"])
