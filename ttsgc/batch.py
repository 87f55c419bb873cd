"""Many scenes at once: every prompt of a folder or a JSON Lines file compiled, proven and written.

Each scene is one job on the runner (ttsgc/runner.py). Workers only compute: they hand back the scene's file
contents, and this process writes them, each atomically, the .xosc last but one and the scene's result file
last. The result file is the marker of a finished scene: a batch started again skips every scene that has
one, and a scene cut off half-way has none, so it is done again (its files are rewritten, byte-identical).
The summary is built from the result files in input order, so it is the same whatever the number of
workers, whatever finished first, and whether the batch ran in one go or was interrupted and resumed.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import re
import time
from dataclasses import dataclass, field
from pathlib import Path

from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.files import real_path, write_atomic

SUMMARY_JSON = "summary.json"
SUMMARY_CSV = "summary.csv"
RESULT_SUFFIX = ".result.json"
ROW_FIELDS = ["id", "source", "seed", "verdict", "failed_at", "reason", "map", "approach", "xosc", "agents",
              "simulated_s", "seconds_lower", "seconds_compile_prove", "seconds_total"]


class BatchError(TtsgcError):
    exit_code = ExitCode.INVALID_SCENARIO  # unreadable or malformed input lists


@dataclass(frozen=True)
class Job:
    """One scene to make: plain data, sent to a worker process or a Ray node."""

    id: str  # the scene's file stem in the output folder
    source: str  # where it came from: a file, or file:line for JSON Lines
    kind: str  # text | tsg
    text: str
    seed: int | None
    maps: tuple[str, ...] | None
    method: str  # how English is lowered: offline | anthropic
    osc_version: str
    out_dir: str
    players: str = "all"  # who proves it: sumo, esmini, or every player available


@dataclass
class Outcome:
    """What a worker hands back: the row of the summary and the files to write (name -> contents)."""

    row: dict
    files: dict[str, bytes] = field(default_factory=dict)
    map_source: str | None = None  # the map to copy beside the scene (its name is files' map_name)
    map_name: str | None = None
    map_sha256: str | None = None
    report: dict | None = None
    finished: bool = True  # False: an internal fault; no marker, so the scene is tried again next time


# -- inputs ------------------------------------------------------------------------------------------------

_ID = re.compile(r"[^A-Za-z0-9._-]+")


def _safe_id(text: str) -> str:
    cleaned = _ID.sub("_", text).strip("._") or "scene"
    return cleaned[:80]


def read_inputs(prompts: Path) -> list[tuple[str, str, str, str]]:
    """(id, source, kind, text) of every input: the .txt and .tsg files of a folder in name order, or the
    lines of a JSON Lines file ({"prompt": English} or {"tsg": scene}, with an optional "id")."""
    prompts = Path(prompts)
    if prompts.is_dir():
        files = sorted(p for p in prompts.iterdir() if p.suffix.lower() in (".txt", ".tsg") and p.is_file())
        if not files:
            raise BatchError(f"{prompts}: no prompts (*.txt) or scenes (*.tsg) in this folder")
        stems = [p.stem for p in files]
        inputs = []
        for path in files:
            clash = stems.count(path.stem) > 1  # blocking.txt and blocking.tsg: blocking-txt, blocking-tsg
            ident = _safe_id(f"{path.stem}-{path.suffix[1:].lower()}" if clash else path.stem)
            try:
                text = path.read_text(encoding="utf-8")
            except (OSError, UnicodeDecodeError) as exc:
                raise BatchError(f"{path}: cannot read: {exc}") from None
            inputs.append((ident, path.name, "text" if path.suffix.lower() == ".txt" else "tsg", text))
        return inputs
    try:
        lines = prompts.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as exc:
        raise BatchError(f"{prompts}: cannot read: {getattr(exc, 'strerror', None) or exc}") from None
    inputs, seen = [], set()
    for number, line in enumerate(lines, 1):
        if not line.strip():
            continue
        where = f"{prompts.name}:{number}"
        try:
            entry = json.loads(line)
        except json.JSONDecodeError as exc:
            raise BatchError(f"{prompts}:{number}: not JSON: {exc.msg} (column {exc.colno})") from None
        if not isinstance(entry, dict) or (("prompt" in entry) == ("tsg" in entry)):
            raise BatchError(f'{prompts}:{number}: expected an object with "prompt" (English) or "tsg" (a scene), not both')
        text = entry.get("prompt", entry.get("tsg"))
        if not isinstance(text, str) or not text.strip():
            raise BatchError(f"{prompts}:{number}: the {'prompt' if 'prompt' in entry else 'tsg'} must be non-empty text")
        ident = _safe_id(str(entry.get("id") or f"line-{number:05d}"))
        if ident in seen:
            raise BatchError(f"{prompts}:{number}: the id '{ident}' is used twice")
        seen.add(ident)
        inputs.append((ident, where, "text" if "prompt" in entry else "tsg", text))
    if not inputs:
        raise BatchError(f"{prompts}: no prompts in this file")
    return inputs


def plan_jobs(prompts: Path, out_dir: Path, variants: int = 1, maps=None, method: str = "offline",
              osc_version: str = "1.3", players: str = "all") -> list[Job]:
    """Every scene of the batch in a fixed order: inputs in order, then variants (seeds 0..N-1, as compile
    --variants does: scene-1, scene-2...; one variant keeps the scene's own seed)."""
    if variants < 1:
        raise BatchError(f"--variants must be at least 1, not {variants}")
    out_dir, prompts = Path(out_dir), Path(prompts)
    if out_dir.exists() and not out_dir.is_dir():
        raise BatchError(f"{out_dir}: the output must be a folder, and this is a file")
    if prompts.is_dir() and real_path(out_dir) == real_path(prompts):
        raise BatchError(f"{out_dir}: the output folder is the prompts folder; the lowered scenes would overwrite "
                         f"the hand-written ones (choose another -o)")
    if prompts.is_file() and real_path(prompts).parent == real_path(out_dir) and (
            prompts.name in (SUMMARY_JSON, SUMMARY_CSV) or prompts.suffix in (".xosc", ".tsg", ".xodr")):
        raise BatchError(f"{prompts}: the batch would write over its own input (choose another -o)")
    jobs = []
    for ident, source, kind, text in read_inputs(prompts):
        for k in range(variants):
            jobs.append(Job(ident if variants == 1 else f"{ident}-{k + 1}", source, kind, text,
                            None if variants == 1 else k, tuple(maps) if maps else None, method, osc_version,
                            str(out_dir), players))
    return jobs


# -- one scene, in a worker --------------------------------------------------------------------------------

def make_scene(job: Job) -> Outcome:
    """Lower or parse, then compile and prove with the pipeline's policy; never raises for a scene's fault."""
    from ttsgc.language import parse
    from ttsgc.lowering import lower_prompt
    from ttsgc.pipeline import compile_and_prove

    started = time.perf_counter()
    row = {name: "" for name in ROW_FIELDS}
    row.update(id=job.id, source=job.source, seed="" if job.seed is None else job.seed)
    outcome = Outcome(row)
    stage = "lower" if job.kind == "text" else "parse"
    try:
        if job.kind == "text":
            lowering = lower_prompt(job.text, job.method, seed=job.seed or 0)
            scenario = lowering.scenario
            outcome.files[f"{job.id}.tsg"] = lowering.tsg(job.text).encode("utf-8")
        else:
            scenario = parse(job.text, job.source)
        row["seconds_lower"] = round(time.perf_counter() - started, 3)
        middle, stage = time.perf_counter(), "compile"
        out = Path(job.out_dir) / f"{job.id}.xosc"
        compiled, report = compile_and_prove(scenario, out, maps=list(job.maps) if job.maps else None,
                                             seed=job.seed, version=job.osc_version, log=lambda message: None,
                                             players=job.players)
        row["seconds_compile_prove"] = round(time.perf_counter() - middle, 3)
    except TtsgcError as exc:
        row.update(verdict="error", failed_at=stage, reason=str(exc).splitlines()[0][:300],
                   seconds_total=round(time.perf_counter() - started, 3))
        return outcome
    except Exception as exc:  # noqa: BLE001 - an internal fault: reported, and the scene is tried again next run
        row.update(verdict="error", failed_at="internal", reason=f"{type(exc).__name__}: {exc}"[:300],
                   seconds_total=round(time.perf_counter() - started, 3))
        outcome.finished = False
        return outcome
    scene = compiled.scene
    row.update(map=scene.map_name, approach=scene.approach, agents=len(report.agents),
               simulated_s=round(report.simulated_s, 1), seconds_total=round(time.perf_counter() - started, 3))
    outcome.report = report.model_dump(mode="json")
    outcome.report.update(scenario=f"{job.id}.xosc", map=compiled.map_name)
    if report.ok:
        row.update(verdict="ok", xosc=f"{job.id}.xosc")
        outcome.files[f"{job.id}.xosc"] = compiled.xosc
        outcome.map_source, outcome.map_name, outcome.map_sha256 = scene.map_path, compiled.map_name, scene.map_sha256
    else:
        failed = [f"{a.name}: {a.reason}" for a in report.agents if not a.achieved]
        failed += [f"collision {c.a}/{c.b}" for c in report.collisions if not c.asked_for] + report.problems
        row.update(verdict="failed", failed_at="simulate", reason="; ".join(failed)[:300])
    return outcome


# -- writing, in this process ------------------------------------------------------------------------------

def result_path(out_dir: Path, ident: str) -> Path:
    return out_dir / f"{ident}{RESULT_SUFFIX}"


def finished_row(out_dir: Path, ident: str) -> dict | None:
    """The row of a finished scene, or None when it must be made (no marker, or one that cannot be read)."""
    try:
        data = json.loads(result_path(out_dir, ident).read_text(encoding="utf-8"))
        return data["row"] if isinstance(data.get("row"), dict) else None
    except (OSError, ValueError, AttributeError):
        return None


def store(out_dir: Path, outcome: Outcome) -> None:
    """Write a scene's files, each atomically: map copy, lowered scene, .xosc, then the marker."""
    if outcome.map_source and outcome.map_name:
        copy = out_dir / outcome.map_name
        if not copy.exists() or hashlib.sha256(copy.read_bytes()).hexdigest() != outcome.map_sha256:
            write_atomic(copy, Path(outcome.map_source).read_bytes())
    for name in sorted(outcome.files, key=lambda n: n.endswith(".xosc")):
        write_atomic(out_dir / name, outcome.files[name])
    if outcome.finished:
        write_atomic(result_path(out_dir, outcome.row["id"]),
                     json.dumps({"row": outcome.row, "report": outcome.report}, indent=2, sort_keys=True) + "\n")


def summary(rows: list[dict]) -> dict:
    counts = {v: sum(r["verdict"] == v for r in rows) for v in ("ok", "failed", "error")}
    seconds = [r["seconds_total"] for r in rows if isinstance(r.get("seconds_total"), (int, float))]
    return {"scenes": len(rows), **counts,
            "seconds_total": round(sum(seconds), 3), "rows": rows}


def write_summary(out_dir: Path, rows: list[dict]) -> None:
    write_atomic(out_dir / SUMMARY_JSON, json.dumps(summary(rows), indent=2) + "\n")
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=ROW_FIELDS, lineterminator="\n", extrasaction="ignore")
    writer.writeheader()
    writer.writerows(rows)
    write_atomic(out_dir / SUMMARY_CSV, buffer.getvalue())


@dataclass
class BatchResult:
    rows: list[dict]
    skipped: int  # scenes already finished by an earlier run
    made: int
    unfinished: list[str]  # ids whose internal fault leaves them to be tried again


def run_batch(jobs: list[Job], out_dir: Path, workers: int | None = None, ray_address: str | None = None,
              progress=None) -> BatchResult:
    from ttsgc import runner

    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    for stray in out_dir.glob(".*.tmp"):  # what a killed run was writing (files.write_atomic's scratch names)
        stray.unlink(missing_ok=True)
    rows: dict[str, dict] = {}
    todo = []
    for job in jobs:
        row = finished_row(out_dir, job.id)
        if row is not None:
            rows[job.id] = row
        else:
            todo.append(job)
    skipped, unfinished = len(rows), []
    done = 0
    if progress and skipped:
        progress(skipped, len(jobs), f"{skipped} already finished")
    import functools

    warm_up = functools.partial(runner.warm_pipeline, jobs[0].maps if jobs else None)
    durations = load_durations()
    todo = longest_first(todo, durations)
    took: dict[str, float] = {}
    outcomes = runner.run(make_scene, todo, workers, ray_address, warm_up=warm_up)
    try:
        for index, outcome in outcomes:
            store(out_dir, outcome)
            rows[todo[index].id] = outcome.row
            if not outcome.finished:
                unfinished.append(todo[index].id)
            elif isinstance(outcome.row.get("seconds_total"), (int, float)):
                took[job_key(todo[index])] = outcome.row["seconds_total"]
            done += 1
            if progress:
                progress(skipped + done, len(jobs), f"{todo[index].id}: {outcome.row['verdict']}")
    finally:
        outcomes.close()
        save_durations(took)
    ordered = [rows[job.id] for job in jobs if job.id in rows]
    write_summary(out_dir, ordered)
    return BatchResult(ordered, skipped, done, unfinished)


# -- the order scenes are handed out in --------------------------------------------------------------------
# A scene that tries several roads takes ten times one that fits the first: handed out last, it keeps one
# worker busy while the others have nothing left. So scenes go out longest first, by how long the same job
# took before (kept in the cache), and a scene never seen goes out before all of them. Only the order of
# work changes: every file and the summary are the same in any order.

DURATIONS_FILE = "batch-durations.json"
DURATIONS_KEPT = 50_000


def job_key(job: Job) -> str:
    """What makes two jobs the same work, whatever the batch, folder or id."""
    data = json.dumps([job.kind, job.text, job.seed, job.maps, job.method, job.osc_version, job.players])
    return hashlib.sha256(data.encode("utf-8")).hexdigest()[:24]


def _durations_path() -> Path:
    from ttsgc.roads.index import cache_dir

    return cache_dir().parent / DURATIONS_FILE


def load_durations() -> dict[str, float]:
    try:
        data = json.loads(_durations_path().read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return {k: v for k, v in data.items() if isinstance(v, (int, float))} if isinstance(data, dict) else {}


def save_durations(took: dict[str, float]) -> None:
    """Add this run's durations to the cache (the newest kept); a cache that cannot be written costs nothing
    but the order."""
    if not took:
        return
    durations = load_durations()
    for key in took:
        durations.pop(key, None)
    durations.update(took)
    kept = dict(list(durations.items())[-DURATIONS_KEPT:])
    try:
        path = _durations_path()
        path.parent.mkdir(parents=True, exist_ok=True)
        write_atomic(path, json.dumps(kept) + "\n")
    except OSError:
        pass


def longest_first(jobs: list[Job], durations: dict[str, float]) -> list[Job]:
    """Jobs never timed first (in their order), then the others from the longest to the shortest."""
    known = [durations.get(job_key(job)) for job in jobs]
    order = sorted(range(len(jobs)), key=lambda i: (known[i] is not None, -(known[i] or 0.0), i))
    return [jobs[i] for i in order]

