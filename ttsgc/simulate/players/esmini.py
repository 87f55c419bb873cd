"""esmini, the reference OpenSCENARIO player, as a player: Plan -> Trace.

esmini is found through TTSGC_ESMINI (the binary) or on PATH; its trace converter dat2csv is taken from the
same folder (else PATH). It plays the file headless with a fixed step from the file's own folder (the map path
is relative to it), under a wall-clock limit since a scene whose stop trigger never fires runs for ever. The
recording (.dat) converted with `dat2csv --extended` gives road, lane and s beside x, y, heading and speed;
esmini's log gives the storyboard's state changes. The trace is read, never the exit code: esmini exits 0
even when a position names a road that does not exist.
"""

from __future__ import annotations

import csv
import math
import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

from ttsgc.errors import TtsgcError
from ttsgc.simulate.plan import Plan
from ttsgc.simulate.trace import Body, Sample, Trace

NAME = "esmini"
STEP_S = 0.05
WALL_LIMIT_S = 120.0
ENV = "TTSGC_ESMINI"
# "[12.350] [info] c1_turn_left standbyState -> startTransition -> runningState"
_STATE = re.compile(r"^\[(?P<t>[0-9.]+)\] \[\w+\] (?P<name>.+?) (?P<from>\w+State) -> (?P<via>\w+Transition) -> "
                    r"(?P<to>\w+State)\s*$")


class EsminiError(TtsgcError):
    """esmini could not be run at all (not the scene failing: that is in the trace)."""


def binary() -> Path | None:
    """The esmini binary: $TTSGC_ESMINI, else `esmini` on PATH, else None."""
    named = os.environ.get(ENV)
    if named:
        path = Path(named).expanduser()
        return path.resolve() if path.is_file() and os.access(path, os.X_OK) else None
    found = shutil.which("esmini")
    return Path(found).resolve() if found else None


def unavailable() -> str:
    """Empty when esmini can run here, else why not."""
    esmini = binary()
    if esmini is None:
        return f"esmini was not found (set {ENV} to its binary or put it on PATH)"
    if _dat2csv(esmini) is None:
        return f"dat2csv was not found beside {esmini} nor on PATH"
    return ""


def _dat2csv(esmini: Path) -> Path | None:
    beside = esmini.parent / "dat2csv"
    if beside.is_file() and os.access(beside, os.X_OK):
        return beside
    found = shutil.which("dat2csv")
    return Path(found) if found else None


def command(esmini: Path, xosc: Path, record: Path, seed: int = 1) -> list[str]:
    return [str(esmini), "--headless", "--osc", xosc.name, "--fixed_timestep", str(STEP_S), "--record", str(record),
            "--seed", str(seed), "--disable_log"]


def play(plan: Plan, seed: int = 1, wall_limit_s: float = WALL_LIMIT_S) -> Trace:
    esmini = binary()
    if esmini is None:
        raise EsminiError(f"esmini was not found (set {ENV} to its binary or put it on PATH)")
    converter = _dat2csv(esmini)
    if converter is None:
        raise EsminiError(f"dat2csv was not found beside {esmini} nor on PATH")
    trace = Trace(player=NAME, step_s=STEP_S)
    for name, entity in plan.entities.items():
        trace.bodies[name] = Body(entity.length, entity.width, entity.x_offset)
    with tempfile.TemporaryDirectory(prefix="ttsgc-esmini-") as scratch:
        record = Path(scratch) / "run.dat"
        try:
            done = subprocess.run(command(esmini, plan.xosc, record, seed), cwd=plan.xosc.parent,
                                  capture_output=True, text=True, errors="replace", timeout=wall_limit_s)
            log = done.stdout
        except subprocess.TimeoutExpired as exc:
            out = exc.stdout or b""
            log = out.decode(errors="replace") if isinstance(out, bytes) else out
            trace.problems.append(f"esmini did not finish within {wall_limit_s:.0f} s of wall time")
        except OSError as exc:
            raise EsminiError(f"cannot run {esmini}: {exc}") from None
        _read_log(log, trace)
        if not record.is_file():
            trace.problems.append("esmini wrote no recording: " + _last_error(log))
            return trace
        table = Path(scratch) / "run.csv"
        subprocess.run([str(converter), "--file", str(record), "--extended", "--csv", str(table), "--precision", "4"],
                       cwd=scratch, capture_output=True, timeout=wall_limit_s, check=False)
        if not table.is_file():
            trace.problems.append("dat2csv could not convert esmini's recording")
            return trace
        _read_table(table, trace)
    return trace


def _last_error(log: str) -> str:
    errors = [line for line in log.splitlines() if "[error]" in line]
    return errors[-1].strip() if errors else "no reason given"


def _read_log(log: str, trace: Trace) -> None:
    """Storyboard element start and end times (the first of each), and whether the stop trigger fired.
    esmini's error lines are mostly about the map (object types it does not know): the trace, not the log,
    says whether the scene played."""
    for line in log.splitlines():
        match = _STATE.match(line.strip())
        if not match:
            continue
        t, name, via, to = float(match["t"]), match["name"], match["via"], match["to"]
        if name == "storyBoard" and via == "stopTransition":
            trace.stopped_by_trigger = True
            trace.end_time = max(trace.end_time, t)
        if to == "runningState":
            trace.started.setdefault(name, t)
        elif to == "completeState":
            trace.ended.setdefault(name, t)


def _read_table(table: Path, trace: Trace) -> None:
    with table.open(newline="") as handle:
        rows = csv.reader(handle)
        header = [h.strip() for h in next(rows, [])]
        col = {name: k for k, name in enumerate(header)}
        for row in rows:
            if len(row) < len(header):
                continue
            name = row[col["name"]].strip()
            t = float(row[col["time"]])
            x, y, h = float(row[col["x"]]), float(row[col["y"]]), float(row[col["h"]])
            body = trace.bodies.get(name)
            if body is not None and body.x_offset:  # the recorded point is the reference point, not the centre
                x, y = x + body.x_offset * math.cos(h), y + body.x_offset * math.sin(h)
            road = row[col["roadId"]].strip()
            lane = row[col["laneId"]].strip()
            trace.samples.setdefault(name, []).append(Sample(
                t, x, y, h, float(row[col["speed"]]), road, int(lane) if lane.lstrip("-").isdigit() else None,
                float(row[col["s"]])))
            trace.end_time = max(trace.end_time, t)
