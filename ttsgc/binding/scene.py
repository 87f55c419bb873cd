"""Scenario + map library -> BoundScene: retrieve, rank, then place on the best candidate that fits."""

from __future__ import annotations

from collections.abc import Iterator

from pydantic import BaseModel, ConfigDict

from ttsgc.binding.place import BoundAgent, PlacementError, later_actions, place
from ttsgc.binding.rank import Ranked, Requirement, explain, rank
from ttsgc.roads.index import MapIndex
from ttsgc.roads.opendrive import load_opendrive
from ttsgc.roads.retrieve import NoRoadError, retrieve
from ttsgc.scenario import Scenario

DEFAULT_SEED = 0
MAX_PLACEMENT_TRIES = 10


class BoundScene(BaseModel):
    """A scene on a road: every agent with a lane position on the map, plus how the road was chosen."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    scenario: Scenario
    seed: int
    map_name: str
    map_path: str
    map_sha256: str
    approach: str
    approach_signals: tuple[str, ...]  # the signals controlling the chosen approach
    score: int
    requirements: int
    agents: tuple[BoundAgent, ...]
    unmet: tuple[str, ...]  # requirements the chosen road does not meet (another candidate meets each)
    explanation: str

    def agent(self, name: str) -> BoundAgent:
        return next(a for a in self.agents if a.name == name)


def bind(scenario: Scenario, library: list[MapIndex], seed: int | None = None, skip: int = 0,
         only: tuple[str, str] | None = None) -> BoundScene:
    """Bind a scenario to the best-ranked approach that placement can realise.

    seed: --seed, else the scenario's seed, else 0. skip: leave out the first `skip` placeable candidates.
    only: (map name, approach id) to bind to that road alone (a TTSG plan's own road), or fail."""
    for k, scene in enumerate(candidates(scenario, library, seed, only)):
        if k == skip:
            return scene
    raise NoRoadError(f"no further candidate road for '{scenario.name}'")


def candidates(scenario: Scenario, library: list[MapIndex], seed: int | None = None,
               only: tuple[str, str] | None = None) -> Iterator[BoundScene]:
    """The scene bound to each placeable approach, best-ranked first, placed only when asked for (lazily):
    the caller takes the next when the scene fails on a road. Raises NoRoadError when no road can host the
    scene at all (naming why), before yielding anything."""
    seed = seed if seed is not None else scenario.seed if scenario.seed is not None else DEFAULT_SEED
    later_actions(scenario)  # what no road can change is refused before any is tried
    retrieved = {id(a) for a in retrieve(library, scenario.road)}  # by identity: equality compares every field
    pool = [(a, m) for m in library for a in m.approaches if id(a) in retrieved]
    if only is not None:
        pool = [(a, m) for a, m in pool if (m.name, a.id) == only]
        if not pool:
            raise NoRoadError(f"{only[0]} {only[1]} does not meet the scene's road block")
    requirements, ranked = rank(scenario, pool, seed)
    unmeetable = [r.column for j, r in enumerate(requirements) if not any(c.met[j] for c in ranked)]
    if unmeetable:
        raise NoRoadError(f"no road can host the scene: of the {len(ranked)} approaches that meet the road block, "
                          f"none meets {', '.join(repr(c) for c in unmeetable)}\n"
                          + explain(requirements, ranked, limit=5))
    return _placed(scenario, seed, requirements, ranked)


def _placed(scenario: Scenario, seed: int, requirements: list[Requirement], ranked: list[Ranked]):
    reasons: list[str] = []
    placed = 0
    for candidate in ranked:
        if placed == 0 and len(reasons) >= MAX_PLACEMENT_TRIES:
            break
        odr = load_opendrive(candidate.index.path, sha256=candidate.index.sha256)  # the geometry the index saw
        try:
            agents = place(scenario, candidate.approach, candidate.index, odr)
        except PlacementError as exc:
            reasons.append(f"{candidate.index.name} {candidate.approach.id}: {exc}")
            continue
        placed += 1
        yield _scene(scenario, seed, candidate, requirements, ranked, agents)
    if not placed:
        raise NoRoadError("no candidate road can host the scene; the best candidates failed:\n  "
                          + "\n  ".join(reasons))


def _scene(scenario: Scenario, seed: int, chosen: Ranked, requirements: list[Requirement], ranked: list[Ranked],
           agents: list[BoundAgent]) -> BoundScene:
    unmet = tuple(r.column for r, met in zip(requirements, chosen.met) if not met)
    return BoundScene(scenario=scenario, seed=seed, map_name=chosen.index.name, map_path=chosen.index.path,
                      map_sha256=chosen.index.sha256, approach=chosen.approach.id,
                      approach_signals=chosen.approach.signals, score=chosen.score,
                      requirements=len(requirements), agents=tuple(agents), unmet=unmet,
                      explanation=explain(requirements, ranked))
