"""Shared paths and fixtures. Tests that need ../shared (real maps, the paper's plans) skip without it."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"
SHARED = ROOT.parent / "shared"


def example_scenarios() -> list[Path]:
    return sorted(EXAMPLES.glob("*.tsg"))


@pytest.fixture
def shared() -> Path:
    if not SHARED.is_dir():
        pytest.skip("../shared is not present")
    return SHARED
