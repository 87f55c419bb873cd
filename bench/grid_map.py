"""A generated N x N grid of 4-way junctions, for measuring how binding scales with the size of a map.

    python bench/grid_map.py [N] [OUT.xodr]     # default 16: 544 roads, 1088 approaches

Built with the same road and junction makers as the built-in library (maps/generate.py): one-lane roads
100 m long between junctions, a short stub road on every arm at the border, traffic lights nowhere, a stop
sign on every north-south arm so that the road blocks of the examples find candidates.
"""

from __future__ import annotations

import importlib.util
import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
ROAD_M, STUB_M = 100.0, 60.0


def _generator():
    spec = importlib.util.spec_from_file_location("generate_maps", ROOT / "maps" / "generate.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def write_grid(n: int, out: Path) -> Path:
    """Write the grid's OpenDRIVE file; the same n gives the same bytes."""
    g = _generator()
    from scenariogeneration import xodr

    g.Fittings.ids = iter(range(10**6, 10**7))
    odr = xodr.OpenDrive(f"grid_{n}x{n}", revMajor="1", revMinor="6")
    side = g.Side(1, shoulder=False)
    ids = iter(range(1, 10**6))
    arms: dict[tuple[int, int], list] = {(i, j): [] for i in range(n) for j in range(n)}
    # east-west roads run along s from junction (i, j) to (i, j+1); north-south ones from (i, j) to (i+1, j)
    for i in range(n):
        for j in range(-1, n):
            length = ROAD_M if 0 <= j < n - 1 else STUB_M
            road = g.make_road(next(ids), length, side, 50)
            odr.add_road(road)
            if j >= 0:
                arms[i, j].append((road, 0.0, "predecessor"))
            if j + 1 < n:
                arms[i, j + 1].append((road, math.pi, "successor"))
    for j in range(n):
        for i in range(-1, n):
            length = ROAD_M if 0 <= i < n - 1 else STUB_M
            road = g.make_road(next(ids), length, side, 50)
            odr.add_road(road)
            if i + 1 < n:  # the road ends at junction (i+1, j), entering it from the south: a stop sign there
                g.Fittings(road, side, at_start=False, length=length).stop()
                arms[i + 1, j].append((road, 3 * math.pi / 2, "successor"))
            if i >= 0:
                arms[i, j].append((road, math.pi / 2, "predecessor"))
    for k, (key, roads) in enumerate(sorted(arms.items()), start=1):
        odr.add_junction_creator(g.junction(10_000 + k, roads, {road.id: 1 for road, _, _ in roads}))
    odr.adjust_roads_and_lanes()
    out.parent.mkdir(parents=True, exist_ok=True)
    odr.write_xml(str(out))
    g.finish(out, {})
    return out


def main() -> int:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 16
    out = Path(sys.argv[2]) if len(sys.argv) > 2 else Path(f"grid_{n}x{n}.xodr")
    print(write_grid(n, out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
