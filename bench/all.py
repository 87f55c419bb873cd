"""The whole performance picture at once: indexing, compiling, simulating, lowering quality, evaluation.

    python bench/all.py

Runs the other scripts of bench/ in turn (each prints medians) and times `ttsgc eval` on the examples and,
when ../shared is present, on the paper's 40 plans over the CARLA towns.
"""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"


def section(title: str, command: list[str]) -> None:
    print(f"\n== {title}\n$ {' '.join(command)}", flush=True)
    start = time.perf_counter()
    subprocess.run(command, cwd=ROOT, check=False, stderr=subprocess.DEVNULL)
    print(f"({time.perf_counter() - start:.1f} s)", flush=True)


def main() -> int:
    python = sys.executable
    ttsgc = str(Path(python).parent / "ttsgc")
    if (SHARED / "maps" / "carla").is_dir():
        section("road index: CARLA towns, cold and cached", [python, "bench/index_bench.py"])
    section("compile latency", [python, "bench/compile_bench.py"])
    section("netconvert and SUMO validation", [python, "bench/simulate_bench.py"])
    section("offline lowering quality (AA, RA)", [python, "bench/lowering_eval.py"])
    section("evaluation: examples, 5 seeds", [ttsgc, "eval", "examples", "--seeds", "5", "--show-failures", "0"])
    if (SHARED / "ttsg-plans").is_dir():
        section("evaluation: the paper's 40 plans on the CARLA towns",
                [ttsgc, "eval", str(SHARED / "ttsg-plans"), "--seeds", "1", "--maps", str(SHARED / "maps" / "carla"),
                 "--show-failures", "40"])
        section("evaluation: the paper's 40 plans on the CARLA towns alone (no synthesised roads)",
                [ttsgc, "eval", str(SHARED / "ttsg-plans"), "--seeds", "1", "--maps", str(SHARED / "maps" / "carla"),
                 "--synthesize", "never", "--show-failures", "40"])
    return 0


if __name__ == "__main__":
    sys.exit(main())
