"""How much faster `ttsgc batch` and `ttsgc eval` get with more workers.

    python bench/batch_bench.py [--repeats 3] [--workers 1 2] [--variants 1 5] [--skip-eval] [--modes alone served]

Runs `ttsgc batch examples` into a fresh folder with each number of workers, alternating so that a busy
spell of a shared machine hurts every setting alike, and prints the median wall time of each, the speed-up
against one worker (of the medians, and the median of the run-by-run ratios), and the spread of the runs and
the machine's load average (how noisy the figures are). Processes start with their modules compiled, as an
installed copy does (--bytecode none: as the environment says).
Then the same for `ttsgc eval examples --seeds 5`. Caches (map indexes, SUMO networks) are warmed first.

A warm scene takes about 0.05 s, while starting the pipeline (Python, the imports, libsumo, the map library)
takes about 0.45 s that no number of workers shortens; the speed-up of a batch run alone therefore grows with
the number of scenes (--variants). Each run is timed two ways (--modes): "alone", the command starting cold in
its own process, and "served", handed to a warm `ttsgc serve` (started for the bench on its own cache folder,
stopped at the end), where that fixed part is gone.
"cores had" is CPU time over wall time: on a shared machine whose kernel shares the CPU between sessions
(sched_autogroup), a busy neighbour caps what the workers get, and the speed-up with it.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from timing import ROOT, bytecode_note, bytecode_option, use_bytecode, with_bytecode


def machine_busy_seconds() -> float:
    """CPU seconds the whole machine has spent busy since boot (Linux; 0 elsewhere)."""
    try:
        with open("/proc/stat") as stat:
            fields = [int(x) for x in stat.readline().split()[1:]]
    except (OSError, ValueError):
        return 0.0
    idle = fields[3] + (fields[4] if len(fields) > 4 else 0)
    return (sum(fields[:8]) - idle) / os.sysconf("SC_CLK_TCK")


OTHERS: list[float] = []  # cores other sessions kept busy during each timed run
ENV: dict[str, str] = {}  # every command's environment: set up in main()
SERVER: list[int] = []  # the pid of the warm server while the served runs are timed


def process_tree_cpu(pid: int) -> float:
    """CPU seconds of a process and of its children it has reaped (a served command's child and its workers)."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return 0.0
    return sum(int(x) for x in fields[11:15]) / os.sysconf("SC_CLK_TCK")  # utime stime cutime cstime


def children_of(pid: int) -> bool:
    try:
        return any((task / "children").read_text().strip() for task in Path(f"/proc/{pid}/task").iterdir())
    except OSError:
        return False


def timed(command: list[str]) -> tuple[float, float]:
    """(wall seconds, CPU seconds of the command and its workers, in the server when it was served)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    server_before = process_tree_cpu(SERVER[0]) if SERVER else 0.0
    busy = machine_busy_seconds()
    start = time.perf_counter()
    done = subprocess.run(command, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=ENV)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit(f"failed ({done.returncode}): {' '.join(command)}")
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if SERVER:  # the served command's child ends just after answering: its CPU counts once the server reaped it
        deadline = time.monotonic() + 2.0
        while children_of(SERVER[0]) and time.monotonic() < deadline:
            time.sleep(0.01)
        cpu += process_tree_cpu(SERVER[0]) - server_before
    OTHERS.append(max(0.0, machine_busy_seconds() - busy - cpu) / wall)
    return wall, cpu


def measure(name: str, make_command, workers: list[int], repeats: int, quiet: float | None = None,
            patience: int = 6) -> None:
    """Rounds of one run per number of workers. With `quiet`, a round counts only when other work kept fewer
    than `quiet` cores busy during each of its runs (tried up to patience x repeats rounds); the others are
    set aside and counted."""
    times: dict[int, list[float]] = {w: [] for w in workers}
    cores: dict[int, list[float]] = {w: [] for w in workers}
    loads, others, set_aside = [], [], 0
    for _ in range(repeats * (patience if quiet is not None else 1)):
        if len(times[workers[0]]) >= repeats:
            break
        round_ = {}
        for w in workers:
            loads.append(os.getloadavg()[0])
            round_[w] = timed(make_command(w)) + (OTHERS[-1],)
        if quiet is not None and max(r[2] for r in round_.values()) >= quiet:
            set_aside += 1
            continue
        for w, (wall, cpu, other) in round_.items():
            times[w].append(wall)
            cores[w].append(cpu / wall)
            others.append(other)
    print(f"\n{name}: median wall time of {len(times[workers[0]])} round(s)"
          + (f" while other work kept under {quiet:g} core busy ({set_aside} busier round(s) set aside)"
             if quiet is not None else ""))
    if not times[workers[0]]:
        print("  no round was quiet enough")
        return
    base = statistics.median(times[workers[0]])
    print(f"{'workers':>8} {'median s':>9} {'min s':>7} {'max s':>7} {'speed-up':>9} {'paired':>7} {'cores had':>10}")
    for w in workers:
        median = statistics.median(times[w])
        paired = statistics.median(a / b for a, b in zip(times[workers[0]], times[w]))  # run by run
        print(f"{w:>8} {median:9.2f} {min(times[w]):7.2f} {max(times[w]):7.2f} {base / median:8.2f}x "
              f"{paired:6.2f}x {statistics.median(cores[w]):10.2f}")
    print(f"load average (1 min) before each run: min {min(loads):.1f}, median {statistics.median(loads):.1f}, "
          f"max {max(loads):.1f} on {os.cpu_count()} core(s); 'paired' is the median of the ratios of runs made "
          f"one after the other")
    print(f"cores kept busy by other work during the runs counted: median {statistics.median(others):.2f}, max "
          f"{max(others):.2f} (near 0: the figures are the machine's; near or above 1 on 2 cores: a second worker "
          f"had no core of its own)")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--variants", type=int, nargs="+", default=[1, 5], help="batch sizes: scenes per input")
    parser.add_argument("--skip-eval", action="store_true")
    parser.add_argument("--quiet", type=float, metavar="CORES",
                        help="count only rounds during which other work kept fewer than CORES cores busy (a shared "
                             "machine); up to 6 x --repeats rounds are tried")
    parser.add_argument("--modes", nargs="+", choices=["alone", "served"], default=["alone", "served"],
                        help="alone: each command starts cold in its own process; served: a warm server runs it")
    bytecode_option(parser)
    args = parser.parse_args()
    ttsgc = [sys.executable, "-m", "ttsgc"]
    with tempfile.TemporaryDirectory(prefix="ttsgc-bench-") as scratch:
        use_bytecode(args, Path(scratch) / "bytecode")
        base = with_bytecode(dict(os.environ, TTSGC_CACHE_DIR=f"{scratch}/cache"))
        base.pop("ANTHROPIC_API_KEY", None)  # the offline lowering
        print(f"python: {bytecode_note()}; runs of 1 and 2 workers alternate (paired), medians")
        runs = iter(range(10**6))
        scenes = len([p for p in (ROOT / "examples").iterdir() if p.suffix in (".txt", ".tsg")])
        for mode in args.modes:
            ENV.clear()
            ENV.update(base, TTSGC_NO_SERVER="0" if mode == "served" else "1")
            if mode == "served":
                started = subprocess.run(ttsgc + ["serve", "--idle", "0"], cwd=ROOT, env=ENV, check=True,
                                         capture_output=True, text=True).stdout
                SERVER[:] = [int(started.rsplit("pid ", 1)[1].split(";")[0])]
            try:
                timed(ttsgc + ["batch", "examples", "-o", f"{scratch}/warm-{mode}", "--workers", str(max(args.workers))])
                for variants in args.variants:
                    measure(f"{mode}: ttsgc batch examples --variants {variants} ({scenes * variants} scenes)",
                            lambda w, v=variants: ttsgc + ["batch", "examples", "-o", f"{scratch}/batch-{next(runs)}",
                                                           "--variants", str(v), "--workers", str(w)],
                            args.workers, args.repeats, args.quiet)
                if not args.skip_eval:
                    measure(f"{mode}: ttsgc eval examples --seeds 5 (90 runs)",
                            lambda w: ttsgc + ["eval", "examples", "--seeds", "5", "--workers", str(w)],
                            args.workers, args.repeats, args.quiet)
            finally:
                if mode == "served":
                    subprocess.run(ttsgc + ["serve", "--stop"], cwd=ROOT, env=ENV, stdout=subprocess.DEVNULL)
                    SERVER.clear()
    return 0


if __name__ == "__main__":
    sys.exit(main())
