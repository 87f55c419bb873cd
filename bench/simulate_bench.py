"""netconvert time per map (built-in and, when ../shared is there, the CARLA towns), and the time to
validate each example scene in SUMO once its network is cached.

    python bench/simulate_bench.py [--repeat 3]

Prints medians; these machines are shared and noisy.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

from ttsgc.language import parse_file
from ttsgc.pipeline import compile_scenario, write
from ttsgc.simulate.players.sumo.network import convert
from ttsgc.simulate.sumo import simulate

ROOT = Path(__file__).resolve().parents[1]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    scratch = Path(tempfile.mkdtemp(prefix="ttsgc-bench-"))
    maps = sorted((ROOT / "maps").glob("*.xodr"))
    carla = ROOT.parent / "shared" / "maps" / "carla"
    maps += sorted(carla.glob("*.xodr")) if carla.is_dir() else []
    print(f"{'map':24} {'netconvert (median)':>20}")
    for path in maps:
        times = []
        for _ in range(args.repeat):
            t = time.perf_counter()
            convert(path, scratch / f"{path.stem}.net.xml")
            times.append(time.perf_counter() - t)
        print(f"{path.stem:24} {statistics.median(times) * 1000:17.0f} ms")
    print(f"\n{'example':24} {'validate (median)':>18} {'simulated':>10}  ok")
    medians = []
    for path in sorted((ROOT / "examples").glob("*.tsg")):
        out = scratch / f"{path.stem}.xosc"
        write(compile_scenario(parse_file(path), out), out)
        simulate(out)  # builds and caches the network
        times = []
        for _ in range(args.repeat):
            t = time.perf_counter()
            report = simulate(out)
            times.append(time.perf_counter() - t)
        medians.append(statistics.median(times))
        print(f"{path.stem:24} {medians[-1] * 1000:15.0f} ms {report.simulated_s:8.1f} s  {report.ok}")
    print(f"\nmedian validation of an example scene, network cached: {statistics.median(medians) * 1000:.0f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
