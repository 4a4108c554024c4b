"""Shared fixtures of the Python tests."""
from __future__ import annotations

import os

import pytest

from shared_cases import SHARED_CASES


@pytest.fixture
def shared_cases() -> str:
    """Folder of the Kratos CSMA reference cases (the working folder their relative paths expect)."""
    if not os.path.isdir(SHARED_CASES):
        pytest.skip(f"the shared Kratos cases are not at {SHARED_CASES}")
    return SHARED_CASES
