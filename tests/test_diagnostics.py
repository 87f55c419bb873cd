"""Golden diagnostics: each broken .tsg in tests/diagnostics must give exactly its .expected text, exit 2."""

from __future__ import annotations

from pathlib import Path

import pytest

from ttsgc.cli import main

CASES = sorted((Path(__file__).parent / "diagnostics").glob("*.tsg"))


def test_there_are_enough_cases():
    assert len(CASES) >= 15


@pytest.mark.parametrize("case", CASES, ids=[c.stem for c in CASES])
def test_diagnostic_text(case: Path, monkeypatch, capsys):
    monkeypatch.chdir(case.parent)
    code = main(["check", case.name])
    captured = capsys.readouterr()
    assert code == 2
    assert captured.out == ""
    assert captured.err == case.with_suffix(".expected").read_text(encoding="utf-8")
