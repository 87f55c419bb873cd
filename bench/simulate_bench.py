"""netconvert time per map (built-in and, when ../shared is there, the CARLA towns), and the time to
validate each example scene in each player available (SUMO; esmini through $TTSGC_ESMINI or PATH) once
its network is cached, beside esmini's own time to play the same file alone (no reading, no judging).

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
from ttsgc.simulate.players import esmini
from ttsgc.simulate.players.sumo.network import convert
from ttsgc.simulate.validate import chosen_players, validate

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
    players, skipped = chosen_players("all")
    for why in skipped:
        print(f"\nnot run: {why}")
    head = "".join(f"{name + ' validate':>18}" for name in players)
    own = "esmini" in players
    print(f"\n{'example':24}{head}{'esmini alone':>14}  ok")
    medians: dict[str, list[float]] = {name: [] for name in players}
    for path in sorted((ROOT / "examples").glob("*.tsg")):
        out = scratch / f"{path.stem}.xosc"
        write(compile_scenario(parse_file(path), out), out)
        validate(out, "sumo")  # builds and caches the network
        row, ok = "", True
        for name in players:
            times = []
            for _ in range(args.repeat):
                t = time.perf_counter()
                report = validate(out, name)
                times.append(time.perf_counter() - t)
            ok = ok and report.ok
            medians[name].append(statistics.median(times))
            row += f"{medians[name][-1] * 1000:15.0f} ms"
        alone = ""
        if own:
            alone = f"{_esmini_alone(out, args.repeat) * 1000:11.0f} ms"
        print(f"{path.stem:24}{row}{alone}  {ok}")
    for name in players:
        print(f"median validation of an example scene in {name} (network cached): "
              f"{statistics.median(medians[name]) * 1000:.0f} ms")
    return 0


def _esmini_alone(xosc: Path, repeat: int) -> float:
    """Median wall time of esmini itself playing the file headless with the player's own command line."""
    import subprocess

    binary = esmini.binary()
    times = []
    for _ in range(repeat):
        record = xosc.with_suffix(".dat")
        t = time.perf_counter()
        subprocess.run(esmini.command(binary, xosc, record), cwd=xosc.parent, capture_output=True,
                       timeout=esmini.WALL_LIMIT_S, check=False)
        times.append(time.perf_counter() - t)
    return statistics.median(times)


if __name__ == "__main__":
    sys.exit(main())
