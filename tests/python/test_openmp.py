# SPDX-License-Identifier: BSD-3-Clause
"""The OpenMP runtime as `import mortarcontact` leaves it (python_scripts/__init__.py)."""
from __future__ import annotations

import os
import subprocess
import sys

import pytest


@pytest.mark.parametrize("given, expected", [({}, "GOMP_SPINCOUNT = '1000'"),
                                             ({"OMP_WAIT_POLICY": "active"}, "OMP_WAIT_POLICY = 'ACTIVE'"),
                                             ({"GOMP_SPINCOUNT": "50"}, "GOMP_SPINCOUNT = '50'")])
def test_openmp_spins_briefly_unless_told_otherwise(given, expected):
    """libgomp spins 1000 rounds at a barrier before it sleeps (its default spinning cost 6-10x on
    busy cores: benchmarks/hertz/results_wait_policy.md) unless the user chose a policy or a spin
    count, and no variable is left behind for child processes. libgomp prints its settings with
    OMP_DISPLAY_ENV=VERBOSE."""
    env = {k: v for k, v in os.environ.items() if k not in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT")}
    env.update(given, OMP_DISPLAY_ENV="VERBOSE")
    probe = "import os, mortarcontact; print(os.environ.get('GOMP_SPINCOUNT'), os.environ.get('OMP_WAIT_POLICY'))"
    result = subprocess.run([sys.executable, "-c", probe], env=env, capture_output=True, text=True, check=True)
    assert expected in result.stderr
    assert result.stdout.split() == [given.get("GOMP_SPINCOUNT", "None"), given.get("OMP_WAIT_POLICY", "None")]
