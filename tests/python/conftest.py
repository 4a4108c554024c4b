"""Shared fixtures of the Python tests."""
from __future__ import annotations

import pytest

from csma_cases import CSMA_CASES


@pytest.fixture
def petsc() -> None:
    """Skips the test when the PETSc plugin is not built. Checked when the test runs, not at
    collection: loading the plugin brings MPI into the test process."""
    import mortarcontact as mc

    try:
        mc._core.CreateLinearSolver(mc.Parameters('{"solver_type": "petsc"}'))
    except mc._core.NotImplementedFeatureError:
        pytest.skip("the PETSc plugin is not built (Debian's petsc-dev missing): make deps-petsc, then make install")


@pytest.fixture
def csma_cases() -> str:
    """Folder of the Kratos CSMA reference cases (the working folder their relative paths expect)."""
    return CSMA_CASES
