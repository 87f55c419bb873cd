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


@pytest.fixture(scope="session", autouse=True)
def _private_cache(tmp_path_factory):
    """Every test run indexes into a fresh cache of its own, never the user's."""
    import os

    os.environ["TTSGC_CACHE_DIR"] = str(tmp_path_factory.mktemp("cache"))
    yield


def pytest_addoption(parser):
    parser.addoption("--regen-golden", action="store_true",
                     help="rewrite examples/golden/*.xosc from the current compiler (review the diff!)")


@pytest.fixture
def regen_golden(request) -> bool:
    return request.config.getoption("--regen-golden")
