"""Issue 3: the generated contact kernels are reproducible. Regenerates custom_conditions/generated/
with automatic_differentiation/generate.py into a temporary folder and fails on any difference
(stale committed code, hand edits, or a non-deterministic generator)."""
from __future__ import annotations

import filecmp
import os
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
GENERATOR = ROOT / "automatic_differentiation" / "generate.py"
COMMITTED = ROOT / "custom_conditions" / "generated"


def _generate(out: pathlib.Path, hash_seed: str) -> None:
    env = dict(os.environ, PYTHONHASHSEED=hash_seed)
    subprocess.run([sys.executable, str(GENERATOR), "--output-dir", str(out)], check=True, env=env,
                   capture_output=True, text=True, timeout=900)


def test_generated_code_is_up_to_date(tmp_path):
    pytest.importorskip("sympy")
    _generate(tmp_path, "1")
    fresh = sorted(p.name for p in tmp_path.iterdir())
    committed = sorted(p.name for p in COMMITTED.iterdir())
    assert fresh == committed, f"generated file set differs: {set(fresh) ^ set(committed)}"
    stale = [name for name in fresh if not filecmp.cmp(tmp_path / name, COMMITTED / name, shallow=False)]
    assert not stale, f"custom_conditions/generated is stale, rerun {GENERATOR.relative_to(ROOT)}: {stale}"


def test_generated_code_is_stamped():
    for path in COMMITTED.iterdir():
        head = path.read_text(encoding="utf-8").splitlines()[:2]
        assert head[0] == "// SPDX-License-Identifier: BSD-3-Clause"
        assert "do not edit" in head[1] and "automatic_differentiation/" in head[1], path.name


def test_one_branch_per_slave_node():
    # Per-node active/inactive branches, never 2^n combinations.
    text = (COMMITTED / "alm_frictionless_3d_4n_4n.cpp").read_text(encoding="utf-8")
    assert text.count("if (data.active[") == 2 * 4  # RHS and LHS, one per slave node
    # Issue 12: frictional nodes are slip / stick / inactive, one if / else-if / else chain per
    # slave node (never 3^n combinations).
    for name in ("alm_frictional_3d_4n_4n.cpp", "penalty_frictional_3d_4n_4n.cpp"):
        text = (COMMITTED / name).read_text(encoding="utf-8")
        assert text.count("  if (data.active[") == 2 * 4, name
        assert text.count("} else if (data.active[") == 2 * 4, name
        for j in range(4):
            assert text.count(f"if (data.active[{j}] && data.slip[{j}])") == 2, name
