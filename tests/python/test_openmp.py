# SPDX-License-Identifier: BSD-3-Clause
"""The OpenMP runtime as `import mortarcontact` leaves it (python_scripts/__init__.py)."""
from __future__ import annotations

import os
import subprocess
import sys

import pytest


@pytest.mark.parametrize("given, expected", [(None, "PASSIVE"), ("active", "ACTIVE")])
def test_openmp_waits_passively_unless_told_otherwise(given, expected):
    """libgomp sleeps at barriers (spinning cost 10x and more on busy cores:
    benchmarks/hertz/results_wait_policy.md) unless the user chose a policy, and no
    OMP_WAIT_POLICY is left behind for child processes. libgomp prints its settings with
    OMP_DISPLAY_ENV."""
    env = {k: v for k, v in os.environ.items() if k not in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT")}
    env["OMP_DISPLAY_ENV"] = "TRUE"
    if given:
        env["OMP_WAIT_POLICY"] = given
    probe = "import os, mortarcontact; print(os.environ.get('OMP_WAIT_POLICY'))"
    result = subprocess.run([sys.executable, "-c", probe], env=env, capture_output=True, text=True, check=True)
    assert f"OMP_WAIT_POLICY = '{expected}'" in result.stderr
    assert result.stdout.strip() == str(given)
