"""Compile latency of the examples: in a warm process (bind + emit, maps indexed and cached) and as a whole
CLI run (a fresh `ttsgc compile` process, as a user sees it).

    python bench/compile_bench.py [--repeat 5]

Prints medians; these machines are shared and noisy.
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from ttsgc.language import parse_file
from ttsgc.pipeline import compile_scenario
from ttsgc.roads.retrieve import load_library

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    paths = sorted(EXAMPLES.glob("*.tsg"))
    out_dir = Path(tempfile.mkdtemp(prefix="ttsgc-bench-"))
    load_library()  # index once: a warm process has its maps
    warm, cli = [], []
    for path in paths:
        scenario = parse_file(path)
        for _ in range(args.repeat):
            t = time.perf_counter()
            compile_scenario(scenario, out_dir / f"{path.stem}.xosc")
            warm.append(time.perf_counter() - t)
    ttsgc = Path(sys.executable).parent / "ttsgc"
    for path in paths[:: max(1, len(paths) // 6)]:
        for _ in range(max(1, args.repeat // 2)):
            t = time.perf_counter()
            subprocess.run([str(ttsgc), "compile", str(path), "-o", str(out_dir / f"{path.stem}.xosc")],
                           check=True, capture_output=True)
            cli.append(time.perf_counter() - t)
    print(f"{len(paths)} examples x {args.repeat}")
    print(f"warm process, bind + emit + XSD validation: median {statistics.median(warm) * 1000:.1f} ms, "
          f"max {max(warm) * 1000:.1f} ms")
    print(f"whole CLI run (new process, cached map index): median {statistics.median(cli) * 1000:.0f} ms "
          f"over {len(cli)} runs")
    return 0


if __name__ == "__main__":
    sys.exit(main())
