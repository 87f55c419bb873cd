"""Draw every example scene as SUMO plays it: examples/pictures/<example>.png.

    python examples/pictures/draw.py [NAME...]

Each example .tsg is compiled and proven as `ttsgc compile --render` does, in a scratch folder, and its
picture is kept here. The pictures are reviewed by eye when they change.
"""

from __future__ import annotations

import shutil
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parent


def main(names: list[str]) -> int:
    from ttsgc.cli import main as ttsgc

    scenes = [EXAMPLES / f"{n}.tsg" for n in names] if names else sorted(EXAMPLES.glob("*.tsg"))
    failed = []
    with tempfile.TemporaryDirectory(prefix="ttsgc-pictures-") as scratch:
        for scene in scenes:
            out = Path(scratch) / f"{scene.stem}.xosc"
            if ttsgc(["compile", str(scene), "-o", str(out), "--player", "sumo", "--render"]) != 0:
                failed.append(scene.stem)
                continue
            shutil.copy(out.with_suffix(".png"), HERE / f"{scene.stem}.png")
    if failed:
        print(f"not drawn (the scene failed): {', '.join(failed)}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
