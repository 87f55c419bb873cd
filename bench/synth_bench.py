"""Time road synthesis: a map built for each example scene and for a few demanding road blocks.

    python bench/synth_bench.py [--repeat 7] [--seeds 3]

For each scene and seed: the design (what the map needs), the build (scenariogeneration and the finishing
pass, the file's bytes) and their sum, the synthesis time (goal: under 100 ms a map); then indexing the
result. Prints medians over the repeats (these machines are shared and noisy: read medians, not single runs).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

from ttsgc.language import parse, parse_file
from ttsgc.roads.index import load_index
from ttsgc.roads.synth import build, design

ROOT = Path(__file__).resolve().parents[1]
DEMANDING = {
    "six_lanes_every_word": """scenario "six lanes, every word"
road {
    lanes >= 6
    at junction
    has traffic_light, stop, yield, ladder_crosswalk, continental_crosswalk, parallel_open_crosswalk, stop_line
    has stop_sign_on_road, speed_200, dashed_single_white, solid_single_white
}
stage one {
    ego car turn_right
    car c1 at road_of_left_turn turn_left
    pedestrian p at near_the_crosswalk cross_the_road
}
""",
    "mid_block_crossing": """scenario "mid-block crossing"
road {
    lanes >= 2
    not at junction
    has traffic_light, crosswalk, stop_line, speed_5
}
stage one {
    ego car go_straight
    pedestrian p at near_the_crosswalk cross_the_road
}
""",
}


def median_ms(samples: list[float]) -> float:
    return statistics.median(samples) * 1000


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--seeds", type=int, default=3)
    args = parser.parse_args()
    os.environ["TTSGC_CACHE_DIR"] = tempfile.mkdtemp(prefix="ttsgc-bench-")
    scenes = [(p.stem, parse_file(p)) for p in sorted((ROOT / "examples").glob("*.tsg"))]
    scenes += [(name, parse(text, f"{name}.tsg")) for name, text in DEMANDING.items()]
    folder = Path(tempfile.mkdtemp(prefix="ttsgc-synth-"))
    print(f"{'scene':26} {'seed':>4} {'layout':>8} {'roads':>5} {'design':>9} {'build':>9} {'synthesis':>10} "
          f"{'index':>9}")
    totals = []
    for name, scenario in scenes:
        for seed in range(args.seeds):
            designing, building, indexing = [], [], []
            for _ in range(args.repeat):
                t0 = time.perf_counter()
                d = design(scenario, seed)
                t1 = time.perf_counter()
                data = build(d)
                t2 = time.perf_counter()
                path = folder / f"{d.name}.xodr"
                path.write_bytes(data)
                t3 = time.perf_counter()
                load_index(path, use_cache=False)
                indexing.append(time.perf_counter() - t3)
                designing.append(t1 - t0)
                building.append(t2 - t1)
            total = median_ms([a + b for a, b in zip(designing, building)])
            totals.append(total)
            print(f"{name:26} {seed:4} {d.layout:>8} {data.count(b'<road '):5} "
                  f"{median_ms(designing):6.1f} ms {median_ms(building):6.1f} ms {total:7.1f} ms "
                  f"{median_ms(indexing):6.1f} ms")
    print(f"median synthesis time over {len(totals)} maps: {statistics.median(totals):.1f} ms; "
          f"slowest: {max(totals):.1f} ms (goal: under 100 ms)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
