"""netconvert time per map (built-in and, when ../shared is there, the CARLA towns), the time to validate
each example scene in each player available (SUMO; esmini through $TTSGC_ESMINI or PATH) once its network
is cached beside esmini's own play of the same file alone (no reading, no judging), and `ttsgc validate` as
a whole process against esmini's own play of the same file (../shared/tools/esmini, or $ESMINI), process
start included: run alone, and answered by a warm `ttsgc serve` (paired: the three alternate per scene).

    python bench/simulate_bench.py [--repeat 3] [--against OTHER_CHECKOUT]... [--only-esmini]

Prints medians; these machines are shared and noisy. Goal: validate within 3x of esmini (1.5x to aim for).
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from timing import (ROOT, bytecode_note, bytecode_option, checkouts, environment, median, medians, ms, timed, ttsgc,
                    use_bytecode)

sys.path.insert(0, str(ROOT))
from ttsgc.language import parse_file  # noqa: E402 - this checkout, whatever is installed
from ttsgc.pipeline import compile_scenario, write  # noqa: E402
from ttsgc.simulate.players.sumo.network import convert  # noqa: E402
from ttsgc.simulate.players import esmini as esmini_player  # noqa: E402
from ttsgc.simulate.validate import chosen_players, validate  # noqa: E402

SHARED = ROOT.parent / "shared"
ESMINI_GOAL, ESMINI_AIM = 3.0, 1.5
VALIDATE_SCENES = ["left_turn_oncoming", "blocking", "daily_traffic", "school_zone"]


def esmini_binary() -> Path | None:
    path = Path(os.environ.get("ESMINI") or SHARED / "tools" / "esmini" / "esmini")
    return path if path.is_file() else None


def esmini_play(binary: Path, xosc: Path) -> list[str]:
    """The play its README gives: headless, 0.05 s steps, collisions, a CSV trace to judge from."""
    return [str(binary), "--headless", "--osc", str(xosc), "--fixed_timestep", "0.05", "--collision",
            "--csv_logger", str(xosc.with_suffix(".csv")), "--disable_log"]


def validate_command(tree: Path) -> list[str]:
    """`ttsgc validate --player sumo` where the checkout has players, else plain `ttsgc validate`."""
    done = subprocess.run(ttsgc("validate", "--help"), env=environment(tree, Path(tempfile.gettempdir())),
                          capture_output=True, text=True, cwd=tempfile.gettempdir())
    return ["validate", "--player", "sumo"] if "--player" in done.stdout else ["validate"]


def serves(tree: Path) -> bool:
    """Whether the checkout has `ttsgc serve`."""
    done = subprocess.run(ttsgc("serve", "--help"), env=environment(tree, Path(tempfile.gettempdir())),
                          capture_output=True, text=True, cwd=tempfile.gettempdir())
    return done.returncode == 0


def against_esmini(trees: dict[str, Path], repeat: int, scratch: Path) -> None:
    """Each scene three ways, one after the other in every round (so a busy spell hurts all alike): esmini's
    play, `ttsgc validate` run alone (TTSGC_NO_SERVER=1), and the same command answered by `ttsgc serve`."""
    binary = esmini_binary()
    if binary is None:
        print("\n(esmini not found: set $ESMINI or provide ../shared/tools/esmini)")
        return
    scenes = []
    for name in VALIDATE_SCENES:
        out = scratch / "esmini" / f"{name}.xosc"
        write(compile_scenario(parse_file(ROOT / "examples" / f"{name}.tsg"), out), out)
        scenes.append(out)
    town = SHARED / "maps" / "carla" / "Town10HD.xodr"
    if town.is_file():
        out = scratch / "esmini-town" / "left_turn_oncoming_Town10HD.xosc"
        write(compile_scenario(parse_file(ROOT / "examples" / "left_turn_oncoming.tsg"), out, maps=[town]), out)
        scenes.append(out)
    commands = {label: validate_command(tree) for label, tree in trees.items()}
    caches = {label: scratch / f"cache-{label}" for label in trees}
    alone = {label: environment(tree, caches[label]) | {"TTSGC_NO_SERVER": "1"} for label, tree in trees.items()}
    ways = {f"{label}": (label, alone[label]) for label in trees}  # column -> (checkout, environment)
    served = [label for label, tree in trees.items() if serves(tree)]
    for label in served:
        ways[f"{label} served"] = (label, environment(trees[label], caches[label]))
    for label, tree in trees.items():  # networks and parsed maps built once, outside the timing
        for xosc in scenes:
            timed(ttsgc(*commands[label], xosc), alone[label], check=False)
    try:
        for label in served:
            timed(ttsgc("serve", "--idle", "900"), ways[f"{label} served"][1])
        _compare(binary, scenes, commands, ways, repeat)
    finally:
        for label in served:
            timed(ttsgc("serve", "--stop"), ways[f"{label} served"][1], check=False)


def _compare(binary: Path, scenes: list[Path], commands: dict, ways: dict, repeat: int) -> None:
    print(f"\n== `ttsgc validate` against esmini's play of the same file, whole processes, x {repeat}, medians")
    print(f"esmini: {' '.join(esmini_play(binary, Path('SCENE.xosc')))}")
    print(f"python: {bytecode_note()}")
    for column, (label, env) in ways.items():
        how = "answered by a warm `ttsgc serve`" if column.endswith("served") else "alone (TTSGC_NO_SERVER=1)"
        print(f"{column}: python -m ttsgc {' '.join(commands[label])} SCENE.xosc, {how}")
    print("wall time (CPU time of the process, user + system, in brackets; a served command's work is done in the "
          "server, so its CPU time is the client's alone)")
    print(f"{'scene':30} {'esmini':>18}" + "".join(f" {column:>20} {'ratio':>6}" for column in ways))
    ratios = {column: [] for column in ways}
    paired = {column: [] for column in ways}  # per scene: the median of the ratios of runs made one after the other
    for xosc in scenes:
        times = {"esmini": []} | {column: [] for column in ways}
        for _ in range(repeat):
            times["esmini"].append(timed(["timeout", "120", *esmini_play(binary, xosc)], cwd=xosc.parent,
                                         check=False))
            for column, (label, env) in ways.items():
                times[column].append(timed(ttsgc(*commands[label], xosc), env, cwd=xosc.parent, check=False))
        base = medians(times["esmini"])
        row = f"{xosc.stem:30} {ms(base.wall)} ({ms(base.cpu).strip():>6})"
        for column in ways:
            ours = medians(times[column])
            ratios[column].append(ours.wall / base.wall)
            paired[column].append(median([o.wall / e.wall for o, e in zip(times[column], times["esmini"])]))
            row += f" {ms(ours.wall):>12} ({ms(ours.cpu).strip():>6}) x{ours.wall / base.wall:5.1f}"
        print(row)
    for column in ways:
        value = median(ratios[column])
        print(f"  {column:>14}: median ratio x{value:.1f} in wall time, x{median(paired[column]):.1f} as the median "
              f"of run-by-run ratios ({'meets' if value <= ESMINI_GOAL else 'misses'} the goal of x{ESMINI_GOAL:g}; "
              f"x{ESMINI_AIM:g} is where we want to end up)")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--against", action="append", metavar="CHECKOUT", help="another checkout to compare with")
    parser.add_argument("--only-esmini", action="store_true", help="only the comparison with esmini")
    bytecode_option(parser)
    args = parser.parse_args()
    scratch = Path(tempfile.mkdtemp(prefix="ttsgc-bench-"))
    use_bytecode(args, scratch / "bytecode")
    try:
        if not args.only_esmini:
            in_process(args.repeat, scratch)
        against_esmini(checkouts(args.against), args.repeat, scratch)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    return 0


def in_process(repeat: int, scratch: Path) -> None:
    maps = sorted((ROOT / "maps").glob("*.xodr"))
    carla = ROOT.parent / "shared" / "maps" / "carla"
    maps += sorted(carla.glob("*.xodr")) if carla.is_dir() else []
    print(f"{'map':24} {'netconvert (median)':>20}")
    for path in maps:
        times = []
        for _ in range(repeat):
            t = time.perf_counter()
            convert(path, scratch / f"{path.stem}.net.xml")
            times.append(time.perf_counter() - t)
        print(f"{path.stem:24} {statistics.median(times) * 1000:17.0f} ms")
    players, skipped = chosen_players("all")
    for why in skipped:
        print(f"\nnot run: {why}")
    head = "".join(f"{name + ' validate':>18}" for name in players)
    print(f"\n{'example':24}{head}{'esmini alone':>14}  ok")
    per_player: dict[str, list[float]] = {name: [] for name in players}
    for path in sorted((ROOT / "examples").glob("*.tsg")):
        out = scratch / f"{path.stem}.xosc"
        write(compile_scenario(parse_file(path), out), out)
        validate(out, players="sumo")  # builds and caches the network
        row, ok = "", True
        for name in players:
            times = []
            for _ in range(repeat):
                t = time.perf_counter()
                report = validate(out, players=name)
                times.append(time.perf_counter() - t)
            ok = ok and report.ok
            per_player[name].append(statistics.median(times))
            row += f"{per_player[name][-1] * 1000:15.0f} ms"
        alone = f"{_esmini_alone(out, repeat) * 1000:11.0f} ms" if "esmini" in players else ""
        print(f"{path.stem:24}{row}{alone}  {ok}")
    for name in players:
        print(f"median validation of an example scene in {name} (network cached): "
              f"{statistics.median(per_player[name]) * 1000:.0f} ms")


def _esmini_alone(xosc: Path, repeat: int) -> float:
    """Median wall time of esmini itself playing the file with the player's own command line."""
    binary = esmini_player.binary()
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        subprocess.run(esmini_player.command(binary, xosc, xosc.with_suffix(".dat")), cwd=xosc.parent,
                       capture_output=True, timeout=esmini_player.WALL_LIMIT_S, check=False)
        times.append(time.perf_counter() - t)
    return statistics.median(times)


if __name__ == "__main__":
    sys.exit(main())
