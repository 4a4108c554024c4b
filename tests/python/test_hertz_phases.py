# SPDX-License-Identifier: BSD-3-Clause
"""Issue 4 (time per phase): the benchmark runner (run as a script) records mortarcontact's time
in the contact search, the mortar weighted gap and normals, the condition and element loops of
the assembly and the linear solve; each phase was entered, and together they fit inside the
analysis time."""
from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys

import pytest

from mortarcontact.cases import hertz

pytestmark = pytest.mark.skipif(importlib.util.find_spec("gmsh") is None, reason="gmsh is not installed")

RUNNER = os.path.join(os.path.dirname(__file__), "..", "..", "benchmarks", "hertz", "case_runner.py")


def test_runner_records_every_phase(tmp_path):
    folder = hertz.write_case("hertz2d", "2k", str(tmp_path))
    output = tmp_path / "run.json"
    subprocess.run([sys.executable, RUNNER, "--code", "mortarcontact", folder, str(output)], check=True)
    record = json.loads(output.read_text())
    assert record["status"] == "ok", record.get("error")
    phases = record["phases"]
    for key in ("search", "weighted_gap", "normals", "conditions", "elements", "solve", "dof_setup"):
        assert phases[key] > 0.0, key
    assert phases["build_other"] >= 0.0
    timed = sum(v for k, v in phases.items() if k != "rest")
    assert timed <= record["analysis_seconds"]
    assert phases["rest"] == pytest.approx(record["analysis_seconds"] - timed, abs=1e-12)

