"""esmini's own example scenarios, played by `ttsgc validate`: none may crash or hang, and nearly all must
end in a verdict. The folder is esmini's resources/ (xosc/, xodr/, catalogs); TTSGC_ESMINI_EXAMPLES names
it, else ../esmini-resources beside the repository. The test skips without it.

A verdict is a played scene (exit 0, or 5 with the failures stated) or a refusal that states its reason
(exit 2 or 3: no road network, a missing catalog, a value not of its type, ...). Each file runs in its own
process so that a hang is caught and ended.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PER_FILE_S = 240


def corpus() -> Path:
    folder = Path(os.environ.get("TTSGC_ESMINI_EXAMPLES", ROOT.parent / "esmini-resources"))
    if not (folder / "xosc").is_dir():
        pytest.skip(f"esmini's example scenarios are not at {folder} (set TTSGC_ESMINI_EXAMPLES)")
    return folder


def play(scene: Path) -> tuple[int, str]:
    try:
        done = subprocess.run([sys.executable, "-m", "ttsgc", "validate", str(scene)], capture_output=True,
                              text=True, timeout=PER_FILE_S, cwd=ROOT, env={**os.environ, "PYTHONPATH": str(ROOT)})
    except subprocess.TimeoutExpired:
        return -1, f"no verdict within {PER_FILE_S} s"
    return done.returncode, done.stdout + done.stderr


def test_esmini_examples_end_in_a_verdict():
    scenes = sorted((corpus() / "xosc").glob("*.xosc"))
    results = {scene.name: play(scene) for scene in scenes}
    crashed = {name: out[-300:] for name, (code, out) in results.items() if code not in (0, 2, 3, 5)}
    assert not crashed, crashed
    assert all("Traceback" not in out for _, out in results.values())
    played = sum(code in (0, 5) for code, _ in results.values())
    stated = sum(code in (0, 2, 3, 5) for code, _ in results.values())
    print(f"\n{len(scenes)} esmini scenes: {played} played to a verdict ({played / len(scenes):.0%}), "
          f"{stated} with a verdict or a stated refusal ({stated / len(scenes):.0%})")
    assert stated == len(scenes)  # SUMO's netconvert refuses two of esmini's maps: a map error, exit 3
    assert played >= 0.75 * len(scenes)
    for code, out in results.values():
        if code in (0, 5):
            assert "0/0" not in out
        if code == 0 and "no intents were declared" not in out:
            pytest.fail("a scene without intents passed without saying so")
