# SPDX-License-Identifier: BSD-3-Clause
"""Issue 2 (speed): the block benchmark runs end to end at its smallest size (as a script), writes
its table, and its solution matches the exact uniaxial-compression field to round-off, so the
benchmark code cannot rot."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

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


def test_scaling_model_reads_the_measured_phases():
    """benchmarks/mpi/scaling_model.py parses the 3D Hertz per-phase table it is built on (so that
    a change of that table's layout cannot silently break it), and its distributed design divides
    every phase but the communication: on one rank both designs cost the same, and the distributed
    iteration is faster on more ranks."""
    sys.path.insert(0, str(BENCHMARK.parent / "mpi"))
    try:
        import scaling_model
    finally:
        sys.path.pop(0)
    model = scaling_model.Model(scaling_model.read_measured())
    assert len(model.inputs) >= 2 and 1.0 < model.solve_g < 2.0 and 0.5 < model.pairs_g < 0.8
    one = [sum(model.iteration(1.0e6, 1, distributed).values()) for distributed in (False, True)]
    assert one[0] == one[1]
    many = [sum(model.iteration(1.0e6, 64, distributed).values()) for distributed in (False, True)]
    assert many[1] < many[0] < one[0]


def test_hertz_match_compares_every_node_and_step_in_the_serial_order():
    """benchmarks/mpi/hertz_match.py (issue 17's done-when): the largest difference over every node,
    component and step, relative to the largest serial value; a 2-rank file with the nodes in
    another order is refused, not compared."""
    sys.path.insert(0, str(BENCHMARK.parent / "mpi"))
    try:
        import hertz_match
    finally:
        sys.path.pop(0)
    serial = {"TIME": [0.5, 1.0], "NODE_1": {"DISPLACEMENT_X": [1.0, -4.0]}, "NODE_2": {"DISPLACEMENT_X": [0.0, 2.0]}}
    cut = {"TIME": [0.5, 1.0], "NODE_1": {"DISPLACEMENT_X": [1.0, -4.0]}, "NODE_2": {"DISPLACEMENT_X": [0.0, 2.4]}}
    assert hertz_match.largest_relative_difference(serial, cut) == pytest.approx(0.1)
    with pytest.raises(SystemExit, match="another order"):
        hertz_match.largest_relative_difference(serial, {"TIME": cut["TIME"], "NODE_2": cut["NODE_2"],
                                                         "NODE_1": cut["NODE_1"]})
