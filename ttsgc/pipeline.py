"""The compiler's stages chained: parse -> bind -> emit -> write. Each stage stays a pure function; this
module only connects them and writes the outputs."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path

from ttsgc.binding import BoundScene, bind
from ttsgc.binding.scene import candidates
from ttsgc.emit.xosc import DEFAULT_VERSION, emit
from ttsgc.errors import TtsgcError
from ttsgc.files import write_atomic
from ttsgc.roads.index import MapIndex
from ttsgc.roads.retrieve import load_library
from ttsgc.scenario import Scenario


@dataclass(frozen=True)
class Compiled:
    scene: BoundScene
    xosc: bytes
    map_name: str  # the map file's name beside the .xosc


def map_file_name(scene: BoundScene, out_dir: Path) -> str:
    """The copy of the map beside the output: <map>.xodr, or <map>-<hash>.xodr when another file has that name."""
    source = Path(scene.map_path)
    name = source.name
    existing = out_dir / name
    if existing.exists() and hashlib.sha256(existing.read_bytes()).hexdigest() != scene.map_sha256:
        name = f"{source.stem}-{scene.map_sha256[:8]}{source.suffix}"
    return name


def compile_scenario(scenario: Scenario, out: Path, maps=None, seed: int | None = None,
                     version: str = DEFAULT_VERSION, skip: int = 0, only: tuple[str, str] | None = None,
                     library: list[MapIndex] | None = None) -> Compiled:
    """maps: files and folders as `--maps` takes them; library: the same, already loaded (wins over maps)."""
    scene = bind(scenario, library if library is not None else load_library(maps), seed=seed, skip=skip, only=only)
    map_name = map_file_name(scene, out.parent)
    return Compiled(scene, emit(scene, map_name, version), map_name)


MAX_SIMULATION_TRIES = 3


def simulate_compiled(compiled: Compiled, out: Path, players: str = "all"):
    """Prove a compiled scene in the players (all available by default) from a scratch folder: the file as it
    will be written, the map beside it."""
    import tempfile

    from ttsgc.simulate.validate import validate

    with tempfile.TemporaryDirectory(prefix="ttsgc-") as scratch:
        trial = Path(scratch) / out.name
        write(compiled, trial)
        report = validate(trial, players)
    return report.model_copy(update={"scenario": str(out), "map": str(out.parent / compiled.map_name)})


def failure_summary(report) -> str:
    failed = [f"{a.name} ({a.reason})" for a in report.agents if not a.achieved] + \
        [f"collision {c.a}/{c.b}" for c in report.collisions if not c.asked_for]
    return "; ".join(failed) or "; ".join(report.problems)


def prove_first(scenes, prove, tries: int = MAX_SIMULATION_TRIES, log=print):
    """The one "try the next road when the scene fails" policy: prove each candidate in turn (scenes is
    consumed lazily, so roads after the first that passes are never placed) and return (candidate, report)
    of the first that passes, else of the last tried. The first candidate's error propagates; a later
    candidate that cannot be built ends the search."""
    chosen = report = None
    iterator = iter(scenes)
    for attempt in range(tries):
        try:
            candidate = next(iterator)
        except StopIteration:
            break
        except TtsgcError:
            if attempt == 0:
                raise
            break
        chosen, report = candidate, prove(candidate)
        if report.ok:
            break
        log(f"ttsgc: {getattr(candidate, 'label', candidate)}: the scene failed: {failure_summary(report)}"
            + ("; trying the next-ranked road" if attempt + 1 < tries else ""))
    if chosen is None:
        raise TtsgcError("no candidate to prove")
    return chosen, report


def compile_and_prove(scenario: Scenario, out: Path, maps=None, seed: int | None = None,
                      version: str = DEFAULT_VERSION, tries: int = MAX_SIMULATION_TRIES, log=print,
                      only: tuple[str, str] | None = None, players: str = "all"):
    """Compile, then prove in the players; when the scene fails on its road, compile onto the next-ranked
    road, at most `tries` roads in all. Returns (compiled, report) of the first that passes, else of the
    last tried."""
    library = load_library(maps)

    def compiled_scenes():
        for scene in candidates(scenario, library, seed=seed, only=only):
            map_name = map_file_name(scene, out.parent)
            yield _Labelled(Compiled(scene, emit(scene, map_name, version), map_name))

    labelled, report = prove_first(compiled_scenes(), lambda c: simulate_compiled(c.compiled, out, players),
                                   tries, log)
    return labelled.compiled, report


@dataclass(frozen=True)
class _Labelled:
    compiled: Compiled

    @property
    def label(self) -> str:
        return f"{self.compiled.scene.map_name} {self.compiled.scene.approach}"


def write(compiled: Compiled, out: Path) -> None:
    """Write the map copy, then the .xosc, each atomically: a reader never sees half a file."""
    out.parent.mkdir(parents=True, exist_ok=True)
    copy = out.parent / compiled.map_name
    if not copy.exists():
        write_atomic(copy, Path(compiled.scene.map_path).read_bytes())
    write_atomic(out, compiled.xosc)
