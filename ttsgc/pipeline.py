"""The compiler's stages chained: parse -> bind -> emit -> write. Each stage stays a pure function; this
module only connects them and writes the outputs."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path

from ttsgc.binding import BoundScene, bind
from ttsgc.emit.xosc import DEFAULT_VERSION, emit
from ttsgc.errors import TtsgcError
from ttsgc.files import write_atomic
from ttsgc.roads.index import MapIndex
from ttsgc.roads.retrieve import NoRoadError, load_library
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
                     library: list[MapIndex] | None = None, synthesize: str = "never", log=print) -> Compiled:
    """maps: files and folders as `--maps` takes them; library: the same, already loaded (wins over maps)."""
    if library is None:
        library = library_for(scenario, maps, seed, synthesize, log)
    scene = bind(scenario, library, seed=seed, skip=skip, only=only)
    map_name = map_file_name(scene, out.parent)
    return Compiled(scene, emit(scene, map_name, version), map_name)


def library_for(scenario: Scenario, maps=None, seed: int | None = None, synthesize: str = "never",
                log=print) -> list[MapIndex]:
    """The roads a scene is bound to: the map library, or a map synthesised for the scene when `synthesize`
    is 'always', or 'auto' and binding on the library fails or leaves a requirement unmet (said through log)."""
    from ttsgc.roads.index import cache_dir, load_index

    reason = "--synthesize always"
    if synthesize != "always":
        library = load_library(maps)
        if synthesize == "never":
            return library
        try:
            unmet = bind(scenario, library, seed=seed).unmet
        except NoRoadError as exc:
            reason = str(exc).splitlines()[0].rstrip(": ")
        else:
            if not unmet:
                return library
            reason = f"the best road of the library does not meet {', '.join(unmet)}"
    from ttsgc.roads.synth import chosen_seed, synthesize_map

    seed = chosen_seed(scenario, seed)
    key = hashlib.sha256(f"{scenario.model_dump_json()}|{seed}".encode()).hexdigest()[:16]
    path = synthesize_map(scenario, seed, cache_dir().parent / "synth" / key)
    log(f"ttsgc: note: {reason}; synthesised {path.name} for the scene")
    return [load_index(path)]


MAX_SIMULATION_TRIES = 3


def simulate_compiled(compiled: Compiled, out: Path):
    """Run a compiled scene in SUMO from a scratch folder (the file as it will be written, map beside it)."""
    import tempfile

    from ttsgc.simulate.sumo import simulate

    with tempfile.TemporaryDirectory(prefix="ttsgc-") as scratch:
        trial = Path(scratch) / out.name
        write(compiled, trial)
        report = simulate(trial)
    return report.model_copy(update={"scenario": str(out), "map": str(out.parent / compiled.map_name)})


def compile_and_prove(scenario: Scenario, out: Path, maps=None, seed: int | None = None,
                      version: str = DEFAULT_VERSION, tries: int = MAX_SIMULATION_TRIES, log=print,
                      only: tuple[str, str] | None = None, synthesize: str = "never"):
    """Compile, then simulate; when the scene fails on its road, compile onto the next-ranked road, at most
    `tries` roads in all. Returns (compiled, report) of the first that passes, else of the last tried."""
    compiled = report = None
    library = library_for(scenario, maps, seed, synthesize, log)
    for attempt in range(tries):
        try:
            compiled = compile_scenario(scenario, out, seed=seed, version=version, skip=attempt, only=only,
                                        library=library)
        except TtsgcError:
            if attempt == 0:
                raise
            break  # no further candidate road
        report = simulate_compiled(compiled, out)
        if report.ok:
            break
        failed = [f"{a.name} ({a.reason})" for a in report.agents if not a.achieved] + \
            [f"collision {c.a}/{c.b}" for c in report.collisions if not c.asked_for]
        log(f"ttsgc: {compiled.scene.map_name} {compiled.scene.approach}: the scene failed in simulation: "
            f"{'; '.join(failed) or '; '.join(report.problems)}"
            + ("; trying the next-ranked road" if attempt + 1 < tries else ""))
    return compiled, report


def write(compiled: Compiled, out: Path) -> None:
    """Write the map copy, then the .xosc, each atomically: a reader never sees half a file."""
    out.parent.mkdir(parents=True, exist_ok=True)
    copy = out.parent / compiled.map_name
    if not copy.exists():
        write_atomic(copy, Path(compiled.scene.map_path).read_bytes())
    write_atomic(out, compiled.xosc)
