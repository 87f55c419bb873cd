"""Compile latency: English -> proven .xosc as a whole CLI run (a fresh process, as a user sees it) with a cold
and a warm cache, binding on a generated 16x16 grid, and bind + emit in a warm process.

    python bench/compile_bench.py [--repeat 3] [--against OTHER_CHECKOUT]... [--skip-grid] [--skip-cli]

--against runs the same measurements on another checkout (e.g. `git worktree add /tmp/base main`), its runs
alternating with this one's, and prints the ratio. Prints medians; these machines are shared and noisy.
Goals: the whole CLI, cold, 1.0 s or less; bind on the grid 50 ms or less.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from timing import ROOT, checkouts, cold_cache, environment, median, medians, ms, timed, ttsgc, verdict

EXAMPLES = ROOT / "examples"
CLI_GOAL_S, BIND_GOAL_S = 1.0, 0.050
GRID_N = 16

# Bind each example scene that the grid can host, a few times, in one process of the given checkout.
BIND_SCRIPT = """
import json, statistics, sys, time
from ttsgc.binding import bind
from ttsgc.errors import TtsgcError
from ttsgc.language import parse_file
from ttsgc.roads.retrieve import load_library
library = load_library([sys.argv[1]])
times, bound = [], []
for path in sys.argv[3:]:
    scenario = parse_file(path)
    try:
        bind(scenario, library)
    except TtsgcError:
        continue  # the grid has no road for this scene (lights, crosswalks, several lanes)
    bound.append(path)
    for _ in range(int(sys.argv[2])):
        start = time.perf_counter()
        bind(scenario, library)
        times.append(time.perf_counter() - start)
print(json.dumps({"median": statistics.median(times), "bound": len(bound)}))
"""


def whole_cli(trees: dict[str, Path], repeat: int, scratch: Path) -> None:
    prompts = sorted(EXAMPLES.glob("*.txt"))[::3]
    print(f"\n== English -> proven .xosc, whole CLI (`ttsgc compile PROMPT.txt -o OUT.xosc`), "
          f"{len(prompts)} example prompts x {repeat}")
    print("cold: a new process, empty cache but for the SUMO networks (indexes and parsed maps rebuilt);\n"
          "warm: a new process, everything cached")
    primed = {}
    for label, tree in trees.items():  # build the networks and indexes once, outside the timing
        primed[label] = scratch / f"primed-{label}"
        for prompt in prompts:
            timed(ttsgc("compile", prompt, "-o", scratch / label / f"{prompt.stem}.xosc"),
                  environment(tree, primed[label]))
    samples = {(label, kind): [] for label in trees for kind in ("cold", "warm")}
    for _ in range(repeat):
        for prompt in prompts:
            for label, tree in trees.items():
                out = scratch / label / f"{prompt.stem}.xosc"
                cache = cold_cache(primed[label], scratch / f"cold-{label}")
                samples[label, "cold"].append(timed(ttsgc("compile", prompt, "-o", out), environment(tree, cache)))
                samples[label, "warm"].append(timed(ttsgc("compile", prompt, "-o", out),
                                                    environment(tree, primed[label])))
    for kind in ("cold", "warm"):
        for label in trees:
            value, ours = medians(samples[label, kind]), medians(samples["this", kind])
            line = f"  {kind} {label:>12}: median {ms(value.wall)} wall, {ms(value.cpu)} CPU"
            if label != "this":
                line += f"  (this is x{ours.wall / value.wall:.2f} of it in wall time, x{ours.cpu / value.cpu:.2f} in CPU)"
            elif kind == "cold":
                line += f"  {verdict(value.wall, CLI_GOAL_S, ' s')}"
            print(line)


def grid_map(scratch_root: Path) -> Path:
    """The generated grid, kept between runs of the bench (generating it takes about a minute)."""
    path = scratch_root / f"grid_{GRID_N}x{GRID_N}.xodr"
    if not path.is_file():
        sys.path.insert(0, str(ROOT / "bench"))
        from grid_map import write_grid

        print(f"(generating {path.name} ...)", flush=True)
        write_grid(GRID_N, path)
    return path


def bind_on_grid(trees: dict[str, Path], repeat: int, scratch: Path, keep: Path) -> None:
    grid = grid_map(keep)
    scenes = sorted(EXAMPLES.glob("*.tsg"))
    print(f"\n== bind on a generated {GRID_N}x{GRID_N} grid (1088 approaches), in a warm process, "
          f"each example scene the grid can host x {repeat}")
    results = {label: [] for label in trees}
    for label, tree in trees.items():  # index the grid once, outside the timing
        timed([sys.executable, "-c", BIND_SCRIPT, grid, "1", *scenes], environment(tree, scratch / f"g-{label}"))
    for _ in range(3):
        for label, tree in trees.items():
            done = subprocess.run([sys.executable, "-c", BIND_SCRIPT, grid, str(repeat), *scenes],
                                  env=environment(tree, scratch / f"g-{label}"), capture_output=True, text=True,
                                  check=True, cwd=tempfile.gettempdir())
            results[label].append(json.loads(done.stdout.splitlines()[-1]))
    for label in trees:
        value = median([r["median"] for r in results[label]])
        line = f"  {label:>12}: median {ms(value)} over {results[label][0]['bound']} scenes"
        line += f"  (this is x{median([r['median'] for r in results['this']]) / value:.3f} of it)" \
            if label != "this" else f"  {verdict(value * 1000, BIND_GOAL_S * 1000, ' ms')}"
        print(line)


def warm_process(repeat: int, scratch: Path) -> None:
    sys.path.insert(0, str(ROOT))
    from ttsgc.language import parse_file
    from ttsgc.pipeline import compile_scenario
    from ttsgc.roads.retrieve import load_library

    paths = sorted(EXAMPLES.glob("*.tsg"))
    load_library()  # index once: a warm process has its maps
    warm = []
    for path in paths:
        scenario = parse_file(path)
        for _ in range(repeat):
            t = time.perf_counter()
            compile_scenario(scenario, scratch / f"{path.stem}.xosc")
            warm.append(time.perf_counter() - t)
    print(f"\n== warm process, bind + emit + XSD validation, {len(paths)} examples x {repeat} (this checkout)")
    print(f"  median {statistics.median(warm) * 1000:.1f} ms, max {max(warm) * 1000:.1f} ms")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--against", action="append", metavar="CHECKOUT", help="another checkout to compare with")
    parser.add_argument("--skip-grid", action="store_true", help="leave out the grid (generating it takes a minute)")
    parser.add_argument("--skip-cli", action="store_true", help="leave out the whole-CLI runs")
    args = parser.parse_args()
    trees = checkouts(args.against)
    keep = Path(tempfile.gettempdir()) / "ttsgc-bench"
    keep.mkdir(exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="ttsgc-bench-") as work:
        scratch = Path(work)
        if not args.skip_cli:
            whole_cli(trees, args.repeat, scratch)
        if not args.skip_grid:
            bind_on_grid(trees, args.repeat, scratch, keep)
        warm_process(args.repeat, scratch)
    return 0


if __name__ == "__main__":
    sys.exit(main())
