"""What the benches share: timing fresh processes of a checkout, side by side with another one.

A checkout is a folder holding the ttsgc package (this repository, or e.g. `git worktree add /tmp/base main`
to compare against); its commands run as `python -m ttsgc` with that folder first on the path. Runs of the
checkouts alternate, so a load that comes and goes on a shared machine falls on both alike.
"""

from __future__ import annotations

import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import NamedTuple

ROOT = Path(__file__).resolve().parents[1]


def checkouts(against: list[str] | None) -> dict[str, Path]:
    """'this' (the repository holding this bench) and each --against folder, by a short label."""
    found = {"this": ROOT}
    for folder in against or []:
        path = Path(folder).resolve()
        if not (path / "ttsgc" / "__init__.py").is_file():
            raise SystemExit(f"{folder}: not a ttsgc checkout (no ttsgc/__init__.py)")
        found[path.name] = path
    return found


_BYTECODE: list[Path] = []  # set by use_bytecode: where compiled modules are kept between timed runs


def bytecode_option(parser) -> None:
    parser.add_argument("--bytecode", choices=["installed", "none"], default="installed",
                        help="installed (default): processes start with their modules compiled, as an installed "
                             "copy does; none: as the environment says (PYTHONDONTWRITEBYTECODE recompiles each time)")


def use_bytecode(args, folder: Path) -> None:
    """With --bytecode installed, time processes as an installed copy runs: its modules compiled once (pip does
    it on install), not on every start as a checkout is when PYTHONDONTWRITEBYTECODE is set (this machine sets
    it). The bytecode goes to a scratch folder (PYTHONPYCACHEPREFIX), never into the checkout; the first,
    untimed run writes it."""
    if args.bytecode == "installed":
        _BYTECODE[:] = [folder]


def bytecode_note() -> str:
    if _BYTECODE:
        return "modules compiled once, as installed (--bytecode installed)"
    return f"modules compiled {'on every start' if os.environ.get('PYTHONDONTWRITEBYTECODE') else 'as Python does'}" \
           f" (--bytecode none: the environment as it is)"


def with_bytecode(env: dict[str, str]) -> dict[str, str]:
    if _BYTECODE:
        env = dict(env, PYTHONPYCACHEPREFIX=str(_BYTECODE[0]))
        env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env


def environment(checkout: Path, cache: Path) -> dict[str, str]:
    env = dict(os.environ, PYTHONPATH=str(checkout), TTSGC_CACHE_DIR=str(cache))
    env.pop("ANTHROPIC_API_KEY", None)  # the offline lowering: deterministic and free
    return with_bytecode(env)


class Sample(NamedTuple):
    wall: float  # seconds, start-up included
    cpu: float  # user + system seconds of the process: far less sensitive than wall time to a loaded machine


def timed(command: list[str], env: dict[str, str] | None = None, cwd: Path | None = None, timeout: float = 600,
          check: bool = True) -> Sample:
    """One process, timed. It runs in a neutral folder by default: `python -m` puts the working folder first
    on the path, which would hide the checkout's PYTHONPATH."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(command, env=env, cwd=cwd or tempfile.gettempdir(), capture_output=True, timeout=timeout)
    elapsed = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if check and done.returncode != 0:
        raise SystemExit(f"failed ({done.returncode}): {' '.join(map(str, command))}\n"
                         f"{done.stderr.decode(errors='replace')[-2000:]}")
    return Sample(elapsed, after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)


def ttsgc(*args: str) -> list[str]:
    return [sys.executable, "-m", "ttsgc", *map(str, args)]


def cold_cache(primed: Path, into: Path) -> Path:
    """An empty ttsgc cache but for the SUMO networks of `primed` (netconvert is a once-per-map cost, timed
    by simulate_bench.py): road indexes and parsed maps are rebuilt, as on a first run."""
    if into.exists():
        shutil.rmtree(into)
    into.mkdir(parents=True)
    if (primed / "net").is_dir():
        shutil.copytree(primed / "net", into / "net")
    return into


def median(samples: list[float]) -> float:
    return statistics.median(samples)


def medians(samples: list[Sample]) -> Sample:
    return Sample(median([s.wall for s in samples]), median([s.cpu for s in samples]))


def ms(seconds: float) -> str:
    return f"{seconds * 1000:7.0f} ms"


def verdict(value: float, goal: float, unit: str = "") -> str:
    return f"{'meets' if value <= goal else 'misses'} the goal of {goal:g}{unit}"
