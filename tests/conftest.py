"""Shared paths and fixtures. Tests that need ../shared (real maps, the paper's plans) skip without it."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"
SHARED = ROOT.parent / "shared"


def asam_errors(tool: str, bundle: str, document: Path, folder: Path) -> list[str]:
    """Run an ASAM quality checker (qc_opendrive / xodrBundle, qc_openscenario / xoscBundle) on a file and
    return the descriptions of its error-level issues; skips when the checker is not installed."""
    import subprocess
    import sys

    from lxml import etree

    checker = Path(sys.executable).parent / tool
    if not checker.exists():
        pytest.skip(f"{tool} is not installed")
    report = folder / f"{document.stem}.{bundle}.xqar"
    config = folder / f"{document.stem}.{bundle}.xml"
    config.write_text(f'<?xml version="1.0" encoding="UTF-8"?><Config><Param name="InputFile" value="{document}"/>'
                      f'<CheckerBundle application="{bundle}"><Param name="resultFile" value="{report}"/>'
                      f'</CheckerBundle></Config>')
    subprocess.run([str(checker), "-c", str(config)], capture_output=True, check=True, cwd=folder)
    results = etree.parse(str(report))
    assert [c for c in results.iter("Checker") if c.get("status") == "completed"], "no check ran"
    return [i.get("description") or "" for i in results.iter("Issue") if i.get("level") == "1"]


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
