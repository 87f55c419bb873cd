"""The compiler's stages chained: parse -> bind -> emit -> write. Each stage stays a pure function; this
module only connects them and writes the outputs."""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path

from ttsgc.binding import BoundScene, bind
from ttsgc.binding.scene import candidates
from ttsgc.emit.xosc import CREATION_DATE, DEFAULT_VERSION, emit
from ttsgc.errors import TtsgcError
from ttsgc.files import check_outputs, write_output
from ttsgc.roads.index import MapIndex
from ttsgc.roads.retrieve import NoRoadError, load_library
from ttsgc.scenario import Scenario
from ttsgc.targets import GENERIC, check_scenario, retarget, written_version


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
                     library: list[MapIndex] | None = None, target: str = GENERIC, synthesize: str = "never",
                     log=print) -> Compiled:
    """maps: files and folders as `--maps` takes them; library: the same, already loaded (wins over maps).
    target: the player the file is written for (ttsgc.targets); synthesize: see library_for."""
    check_scenario(scenario, target)
    version = written_version(target, version)
    if library is None:
        library = library_for(scenario, maps, seed, synthesize, log)
    scene = bind(scenario, library, seed=seed, skip=skip, only=only)
    map_name = map_file_name(scene, out.parent)
    return for_target(Compiled(scene, emit(scene, map_name, version), map_name), target)


def for_target(compiled: Compiled, target: str) -> Compiled:
    """The compiled scene with its file made for the target player (the generic file stays what is proven)."""
    if target == GENERIC:
        return compiled
    return Compiled(compiled.scene, retarget(compiled.xosc, compiled.scene, target), compiled.map_name)


def library_for(scenario: Scenario, maps=None, seed: int | None = None, synthesize: str = "never",
                log=print) -> list[MapIndex]:
    """The roads a scene is bound to: the map library, or a map synthesised for the scene when `synthesize`
    is 'always', or 'auto' and binding on the library fails or leaves a requirement unmet (said through log)."""
    from ttsgc.roads.index import load_index

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
    path = synthesize_map(scenario, seed, synth_folder() / key)
    log(f"ttsgc: note: {reason}; synthesised {path.name} for the scene")
    return [load_index(path)]


def synth_folder() -> Path:
    """Where the maps synthesised for scenes are kept (beside the map index cache)."""
    from ttsgc.roads.index import cache_dir

    return cache_dir().parent / "synth"


def is_synthesized(scene) -> bool:
    """Whether a bound scene's map was synthesised for it rather than taken from the library."""
    return synth_folder().resolve() in Path(scene.map_path).resolve().parents


MAX_SIMULATION_TRIES = 3


def simulate_compiled(compiled: Compiled, out: Path, players: str = "all"):
    """Prove a compiled scene in the players (all available by default) from a scratch folder: the file as it
    will be written, the map beside it."""
    import tempfile

    from ttsgc.roads.opendrive import MapError
    from ttsgc.simulate.validate import validate

    with tempfile.TemporaryDirectory(prefix="ttsgc-") as scratch:
        trial = Path(scratch) / out.name
        write(compiled, trial)
        try:
            report = validate(trial, players)
        except MapError as exc:  # name the user's map, not the scratch copy the simulation read
            message = str(exc)
            for copy in {str(trial.parent / compiled.map_name), str(trial.parent.resolve() / compiled.map_name)}:
                message = message.replace(copy, compiled.scene.map_path)
            raise MapError(message) from None
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
                      only: tuple[str, str] | None = None, players: str = "all", target: str = GENERIC,
                      synthesize: str = "never"):
    """Compile, then prove in the players; when the scene fails on its road, compile onto the next-ranked
    road, at most `tries` roads in all. Returns (compiled, report) of the first that passes, else of the
    last tried; the compiled file is the target's, made after the generic file is proven."""
    check_scenario(scenario, target)
    version = written_version(target, version)
    library = library_for(scenario, maps, seed, synthesize, log)

    def compiled_scenes():
        for scene in candidates(scenario, library, seed=seed, only=only):
            map_name = map_file_name(scene, out.parent)
            yield _Labelled(Compiled(scene, emit(scene, map_name, version), map_name))

    labelled, report = prove_first(compiled_scenes(), lambda c: simulate_compiled(c.compiled, out, players),
                                   tries, log)
    return for_target(labelled.compiled, target), report


@dataclass(frozen=True)
class _Labelled:
    compiled: Compiled

    @property
    def label(self) -> str:
        return f"{self.compiled.scene.map_name} {self.compiled.scene.approach}"


def write(compiled: Compiled, out: Path) -> None:
    """Write the map copy, then the .xosc, each atomically: a reader never sees half a file. Both paths are
    checked before either is written."""
    copy = out.parent / compiled.map_name
    check_outputs(out, *([] if copy.exists() else [copy]))
    if not copy.exists():
        write_output(copy, Path(compiled.scene.map_path).read_bytes())
    write_output(out, compiled.xosc)


@dataclass(frozen=True)
class Distribution:
    """N variants of one scene on one road: the scenario with parameters, the ParameterValueDistribution that
    expands it, and each variant's concrete file (the template with its value set), proven."""

    template: bytes
    distribution: bytes
    variants: list[Compiled]
    reports: list  # one per variant; None when not simulated
    names: list[str]
    values: list[list[str]]


def distribution_paths(out: Path, n: int) -> tuple[Path, list[Path]]:
    """Where a distribution goes: OUT.dist.xosc beside OUT.xosc, and the concrete OUT-1.xosc .. OUT-N.xosc."""
    return out.with_name(f"{out.stem}.dist{out.suffix}"), [out.with_name(f"{out.stem}-{k}{out.suffix}")
                                                          for k in range(1, n + 1)]


def compile_distribution(scenario: Scenario, out: Path, n: int, maps=None, seed: int | None = None,
                         version: str = DEFAULT_VERSION, simulate: bool = True, log=print,
                         target: str = GENERIC, players: str = "all") -> tuple[Distribution | None, object]:
    """Compile (and prove) the scene, then n variants of it on the same road. Returns (distribution, None), or
    (None, report) of the first scene or variant that fails in simulation: nothing is to be written then."""
    from ttsgc.roads.opendrive import load_opendrive
    from ttsgc.targets import TargetError
    from ttsgc.variation import (DISTRIBUTION_VERSIONS, DistributionRequestError, distribution_file, expand,
                                 parameterise, variants)

    if target == "carla":
        raise TargetError("CARLA ScenarioRunner reads OpenSCENARIO 1.0, which has no ParameterValueDistribution: "
                          "compile the variants without --distribution for carla")
    if n < 2:
        raise DistributionRequestError(f"--distribution needs --variants 2 or more, not {n}")
    if version not in DISTRIBUTION_VERSIONS:
        raise DistributionRequestError(f"a ParameterValueDistribution is OpenSCENARIO 1.1 or later; --osc-version "
                                       f"{version} cannot hold one (choose one of {', '.join(DISTRIBUTION_VERSIONS)})")
    if simulate:
        nominal, report = compile_and_prove(scenario, out, maps=maps, seed=seed, version=version, log=log,
                                            players=players)
        if not report.ok:
            return None, report
    else:
        nominal = compile_scenario(scenario, out, maps=maps, seed=seed, version=version)
    scene = nominal.scene
    lengths = {road.id: road.length for road in load_opendrive(scene.map_path).roads.values()}
    scenes = variants(scene, n, scene.seed, lengths)
    found = parameterise([emit(s, nominal.map_name, version) for s in scenes])
    _, concrete_paths = distribution_paths(out, n)
    compiled = [for_target(Compiled(s, expand(found.template, found.names, row), nominal.map_name), target)
                for s, row in zip(scenes, found.values)]
    reports = []
    for k, (variant, path) in enumerate(zip(compiled, concrete_paths), start=1):
        report = simulate_compiled(variant, path, players) if simulate else None
        if report is not None and not report.ok:
            values = ", ".join(f"{name}={value}" for name, value in zip(found.names, found.values[k - 1]))
            log(f"ttsgc: variant {k} ({values}) failed in simulation")
            return None, report
        reports.append(report)
    data = distribution_file(found, out.name, version, f"{scenario.name}: {n} variants",
                             CREATION_DATE.isoformat())
    return Distribution(found.template, data, compiled, reports, found.names, found.values), None


def write_distribution(dist: Distribution, out: Path) -> None:
    """The map, the concrete files, the template, then the distribution, each atomically."""
    dist_path, concrete_paths = distribution_paths(out, len(dist.variants))
    for variant, path in zip(dist.variants, concrete_paths):
        write(variant, path)
    check_outputs(out, dist_path)
    write_output(out, dist.template)
    write_output(dist_path, dist.distribution)
