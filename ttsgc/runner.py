"""Independent jobs run on every core, or on a Ray cluster: one runner, used by `batch` and by `eval`.

Workers are processes, never threads: libsumo holds one simulation per process. A job is a picklable
top-level function and its argument; results come back as they finish, tagged with the job's index, and the
callers order them by that index, so what they write does not depend on the number of workers or on who
finished first.

A warm scene takes a tenth of a second; starting a process that imports the pipeline and loads the map
library takes seconds. So where the system can fork, this process warms up once (imports, map library) and
the workers are forked from it, starting warm; elsewhere each spawned worker warms up itself.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterator, Sequence
from typing import Any

from ttsgc.errors import ExitCode, TtsgcError


# A thread named so holds no lock a forked worker could need (a served command's client watcher, blocked on its
# socket); any other thread in this process makes the pool spawn its workers instead of forking them.
FORK_SAFE_THREAD = "ttsgc-fork-safe"


class RunnerError(TtsgcError):
    exit_code = ExitCode.INVALID_SCENARIO  # a bad --workers or --ray: a bad command line


def default_workers() -> int:
    """Every core this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


def warm_pipeline(maps=None, versions: tuple[str, ...] = ("1.3",)) -> None:
    """Load what each scene would otherwise load on its first use: every stage's imports, libsumo (with traci
    and sumolib), the scene and expression parsers, the XSD of each OpenSCENARIO version, the map library.
    Done once before forking, workers (and a server's children) start with all of it, shared."""
    import ttsgc.language  # noqa: F401
    import ttsgc.lowering  # noqa: F401
    import ttsgc.pipeline  # noqa: F401
    import ttsgc.simulate.players.sumo  # noqa: F401
    import ttsgc.simulate.validate  # noqa: F401
    from ttsgc import xsd
    from ttsgc.language.parse import grammar_parser
    from ttsgc.roads.retrieve import load_library
    from ttsgc.simulate.lean_libsumo import load_libsumo
    from ttsgc.simulate.resolve import _expression_parser

    load_libsumo()  # no simulation is started, so none is inherited
    grammar_parser()
    _expression_parser()
    for version in versions:
        xsd.schema(version)
        xsd.attribute_types(version)
        xsd.one_of_tags(version)
    load_library(list(maps) if maps else None)


def run(function: Callable[[Any], Any], jobs: Sequence[Any], workers: int | None = None,
        ray_address: str | None = None, warm_up: Callable[[], None] | None = None) -> Iterator[tuple[int, Any]]:
    """Yield (index in jobs, function(job)) as each job finishes. One worker runs in this process; more run
    in a pool of spawned processes; ray_address ('local' starts a private Ray instance) sends them to Ray.
    The caller closes what this returns, even when stopped by an exception of its own: the workers end then,
    not whenever the generator is collected, which may be after the interpreter has begun to wait for them."""
    if workers is not None and workers < 1:
        raise RunnerError(f"--workers must be at least 1, not {workers}")
    if ray_address:
        yield from _on_ray(function, jobs, workers, ray_address)
    elif (workers or default_workers()) == 1 or len(jobs) <= 1:
        for index, job in enumerate(jobs):
            yield index, function(job)
    else:
        yield from _on_pool(function, jobs, workers or default_workers(), warm_up)


def _on_pool(function, jobs, workers: int, warm_up) -> Iterator[tuple[int, Any]]:
    import gc
    import multiprocessing
    from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait

    forkable = can_fork()
    if forkable:  # warm once here; no simulation has been started in this process, so none is inherited
        if warm_up is not None:
            warm_up()
        gc.freeze()  # what is loaded stays shared with the workers, not copied page by page as the collector walks it
        pool = ProcessPoolExecutor(max_workers=min(workers, len(jobs)), mp_context=multiprocessing.get_context("fork"),
                                   initializer=_worker_start)
    else:
        pool = ProcessPoolExecutor(max_workers=min(workers, len(jobs)),
                                   mp_context=multiprocessing.get_context("spawn"), initializer=_worker_start,
                                   initargs=(warm_up,))
    try:
        pending = {pool.submit(function, job): index for index, job in enumerate(jobs)}
        while pending:
            done, _ = wait(pending, return_when=FIRST_COMPLETED)
            for future in sorted(done, key=pending.get):
                index = pending.pop(future)
                yield index, future.result()
        pool.shutdown(wait=True)  # idle workers exit at once, and no thread of the pool outlives it to stop a later fork
    except BaseException:  # interrupted, or the caller stopped: workers only compute, so end them at once
        pool.shutdown(wait=False, cancel_futures=True)  # first, so that no job left is handed to a worker
        processes = list((getattr(pool, "_processes", None) or {}).values())
        for process in processes:
            process.terminate()
        for process in processes:
            process.join(timeout=5)
        manager = getattr(pool, "_executor_manager_thread", None)
        if manager is not None:  # let the pool's own thread see them gone, so that it is not woken at the
            manager.join(timeout=10)  # interpreter's exit through a pipe already closed (a traceback after Ctrl-C)
            if manager.is_alive():  # a worker ended holding one of the pool's locks can leave it waiting forever
                _LEFT_RUNNING.append(manager)
        raise
    finally:
        pool.shutdown(wait=False, cancel_futures=True)
        if forkable:
            gc.unfreeze()


_LEFT_RUNNING: list = []  # the threads of interrupted pools that did not end in time


def pool_left_running() -> bool:
    """An interrupted pool's thread is still running: the interpreter, exiting, would wait for it unbounded."""
    return any(thread.is_alive() for thread in _LEFT_RUNNING)


def can_fork() -> bool:
    """Workers may be forked: the system can, and no other thread of this process (but a fork-safe one) could
    be holding a lock at the moment of the fork, which the worker would inherit held forever."""
    import multiprocessing
    import threading

    return "fork" in multiprocessing.get_all_start_methods() and all(
        t is threading.current_thread() or t.name.startswith(FORK_SAFE_THREAD) for t in threading.enumerate())


def _worker_start(warm_up=None) -> None:
    """Ctrl-C reaches every process of the terminal's group: the main process alone answers it (it stops
    handing out jobs), and a worker finishes the scene it is on instead of dying with a traceback. The main
    process ends its workers with SIGTERM: a forked worker must die of it quietly, not inherit the main
    process's handler that turns SIGTERM into an exception."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    if warm_up is not None:
        warm_up()


def _on_ray(function, jobs, workers: int | None, address: str) -> Iterator[tuple[int, Any]]:
    try:
        import ray
    except ImportError:
        raise RunnerError("--ray needs Ray: pip install 'ttsgc[ray]'") from None
    local = address == "local"
    try:
        if local:  # a private instance on this machine, ended when the run ends
            ray.init(num_cpus=workers or default_workers(), include_dashboard=False, log_to_driver=False,
                     configure_logging=False, runtime_env={"env_vars": _forwarded_environment()})
        else:
            ray.init(address=address, log_to_driver=False, configure_logging=False)
    except (ConnectionError, RuntimeError, ValueError) as exc:
        raise RunnerError(f"cannot reach the Ray cluster at {address}: {exc}") from None
    try:
        remote = ray.remote(num_cpus=1, max_retries=1)(function)
        pending = {remote.remote(job): index for index, job in enumerate(jobs)}
        while pending:
            done, _ = ray.wait(list(pending), num_returns=1)
            for ref in done:
                yield pending.pop(ref), ray.get(ref)
    finally:
        ray.shutdown()


def _forwarded_environment() -> dict[str, str]:
    """What a local Ray worker must see as this process does: where ttsgc is and where its caches are."""
    keep = {"PYTHONPATH": os.pathsep.join(p for p in sys.path if p) or os.environ.get("PYTHONPATH", "")}
    for name in ("TTSGC_CACHE_DIR", "TTSGC_ESMINI", "SUMO_HOME", "ANTHROPIC_API_KEY", "ANTHROPIC_BASE_URL",
                 "TTSGC_MODEL", "TTSGC_MAX_TOKENS", "TTSGC_TEMPERATURE"):
        if os.environ.get(name):
            keep[name] = os.environ[name]
    return keep


def progress_bar(done: int, total: int, label: str) -> None:
    """One line that rewrites itself on a terminal, one line per tenth elsewhere."""
    width = 30
    filled = width * done // total if total else width
    line = f"[{'#' * filled}{'.' * (width - filled)}] {done}/{total} {label}"
    if sys.stderr.isatty():
        print("\r" + line.ljust(90), end="" if done < total else "\n", file=sys.stderr, flush=True)
    elif done == total or done % max(1, total // 10) == 0:
        print(line, file=sys.stderr, flush=True)
