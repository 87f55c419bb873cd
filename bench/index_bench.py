"""Index the six CARLA towns cold and from the cache, and time a retrieval over all of them.

    python bench/index_bench.py [--repeat 5]

Prints medians (these machines are shared and noisy: read ratios and medians, not single runs).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

from ttsgc.roads import load_index, retrieve
from ttsgc.scenario import RoadSpec

TOWNS = ["Town01", "Town02", "Town04", "Town06", "Town07", "Town10HD"]
QUERIES = [RoadSpec(lanes=2, junction=True, required_signals=("traffic_light",)),
           RoadSpec(lanes=1, junction=True, required_signals=("stop",), without_signals=("traffic_light",)),
           RoadSpec(lanes=3, junction=False, required_objects=("speed_90",))]


def median_ms(samples: list[float]) -> str:
    return f"{statistics.median(samples) * 1000:8.1f} ms"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--carla", type=Path, default=Path(__file__).resolve().parents[2] / "shared" / "maps" / "carla")
    args = parser.parse_args()
    paths = [args.carla / f"{t}.xodr" for t in TOWNS]
    if not all(p.is_file() for p in paths):
        print(f"CARLA towns not found in {args.carla}", file=sys.stderr)
        return 2
    os.environ["TTSGC_CACHE_DIR"] = tempfile.mkdtemp(prefix="ttsgc-bench-")
    print(f"{'town':10} {'MB':>5} {'approaches':>10} {'cold':>12} {'cached':>12}")
    cold_total, warm_total = [], []
    for path in paths:
        cold = []
        for _ in range(args.repeat):
            t = time.perf_counter()
            index = load_index(path, use_cache=False)
            cold.append(time.perf_counter() - t)
        load_index(path)  # fill the cache
        warm = []
        for _ in range(args.repeat):
            t = time.perf_counter()
            load_index(path)
            warm.append(time.perf_counter() - t)
        cold_total.append(statistics.median(cold))
        warm_total.append(statistics.median(warm))
        print(f"{path.stem:10} {path.stat().st_size / 1e6:5.1f} {len(index.approaches):10} {median_ms(cold)} "
              f"{median_ms(warm)}")
    print(f"{'all six':10} {'':5} {'':10} {sum(cold_total) * 1000:8.1f} ms {sum(warm_total) * 1000:8.1f} ms  "
          f"(cache {sum(cold_total) / sum(warm_total):.1f}x faster)")
    library = [load_index(p) for p in paths]
    timings = []
    for _ in range(args.repeat * 20):
        t = time.perf_counter()
        for query in QUERIES:
            retrieve(library, query)
        timings.append((time.perf_counter() - t) / len(QUERIES))
    print(f"retrieval over all six towns ({sum(len(m.approaches) for m in library)} approaches): "
          f"{statistics.median(timings) * 1e6:.0f} us per query (median)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
