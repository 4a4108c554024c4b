# SPDX-License-Identifier: BSD-3-Clause
"""Issue 2 (speed): the block benchmark runs end to end at its smallest size (as a script), writes
its table, and its solution matches the exact uniaxial-compression field to round-off, so the
benchmark code cannot rot."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

BENCHMARK = Path(__file__).resolve().parents[2] / "benchmarks" / "run_benchmarks.py"


def test_quick_run_writes_table_with_exact_solution(tmp_path):
    output = tmp_path / "results.md"
    subprocess.run([sys.executable, str(BENCHMARK), "--quick", "--umfpack-up-to", "0", "--output", str(output)],
                   check=True)
    text = output.read_text()
    assert "Machine:" in text and "cores" in text
    rows = [line for line in text.splitlines() if line.startswith(("| hex", "| tet"))]
    assert len(rows) == 2  # hex and tet, CHOLMOD
    for row in rows:
        cells = [c.strip() for c in row.strip("|").split("|")]
        assert cells[1] == "3,000" and cells[9] == "cholmod" and cells[-1] == "ok"
        assert float(cells[8]) > 0.0  # assembly seconds
        error = float(cells[-2])
        assert error < 1e-10
        assert re.fullmatch(r"\d+", cells[12])  # peak RSS in MB
