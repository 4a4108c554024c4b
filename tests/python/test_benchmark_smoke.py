# SPDX-License-Identifier: BSD-3-Clause
"""Issue 2 (speed): the block benchmark runs end to end at its smallest size, writes its table,
and its solution matches the exact uniaxial-compression field to round-off, so the benchmark
code cannot rot."""
from __future__ import annotations

import re
import sys
from pathlib import Path

import numpy as np
import pytest

BENCHMARKS = Path(__file__).resolve().parents[2] / "benchmarks"
sys.path.insert(0, str(BENCHMARKS))
import run_benchmarks  # noqa: E402

mc = pytest.importorskip("mortarcontact")


def test_mesh_is_conforming_and_positively_oriented():
    coords, tets = run_benchmarks.block_mesh(2, "tet")
    assert coords.shape == (27, 3) and tets.shape == (48, 4)
    run_benchmarks.check_orientation(coords, tets)
    # Conforming: every interior triangle is shared by exactly two tetrahedra, every boundary
    # triangle (2 per boundary square, 6 faces x 4 squares) by one.
    faces = np.sort(np.concatenate([tets[:, [0, 1, 2]], tets[:, [0, 1, 3]], tets[:, [0, 2, 3]], tets[:, [1, 2, 3]]]), axis=1)
    _, counts = np.unique(faces, axis=0, return_counts=True)
    assert set(counts) == {1, 2} and (counts == 1).sum() == 6 * 4 * 2
    volume = 0.0
    for t in tets - 1:
        a, b, c, d = coords[t]
        volume += np.dot(np.cross(b - a, c - a), d - a) / 6.0
    assert volume == pytest.approx(1.0, abs=1e-14)


def test_sizes():
    assert run_benchmarks.parse_size("0.1M") == 100_000
    assert run_benchmarks.parse_size("500k") == 500_000
    assert 3 * (run_benchmarks.cells_for(100_000) + 1) ** 3 == 98_304


def test_quick_run_writes_table_with_exact_solution(tmp_path):
    output = tmp_path / "results.md"
    status = run_benchmarks.main(["--quick", "--umfpack-up-to", "0", "--output", str(output)])
    assert status == 0
    text = output.read_text()
    assert "Machine:" in text and "cores" in text
    rows = [line for line in text.splitlines() if line.startswith("| hex") or line.startswith("| tet")]
    assert len(rows) == 2  # hex and tet, CHOLMOD
    for row in rows:
        cells = [c.strip() for c in row.strip("|").split("|")]
        assert cells[1] == "3,000" and cells[9] == "cholmod" and cells[-1] == "ok"
        assert float(cells[8]) > 0.0  # assembly seconds
        error = float(cells[-2])
        assert error < 1e-10
        assert re.fullmatch(r"\d+", cells[12])  # peak RSS in MB
