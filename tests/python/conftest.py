"""Shared fixtures of the Python tests."""
from __future__ import annotations

import pytest

from csma_cases import CSMA_CASES


@pytest.fixture
def csma_cases() -> str:
    """Folder of the Kratos CSMA reference cases (the working folder their relative paths expect)."""
    return CSMA_CASES
