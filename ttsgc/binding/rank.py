"""Plan-aware road ranking (TTSG section 3.2): score each candidate approach by the agent requirements it meets.

Every requirement is one column of the explanation table: the turns the ego and the agents need exist, the
roads where agents stand exist, adjacent lanes exist for side positions and lane changes, a shoulder or
sidewalk exists for agents standing there, a crosswalk for near_the_crosswalk, and the ego's lane is long
enough for every agent queued in it. The best total wins; ties are spread over the library's roads by the seed.
"""

from __future__ import annotations

import math
import zlib
from dataclasses import dataclass
from typing import Callable

from ttsgc import vocabulary as V
from ttsgc.roads.index import Approach, MapIndex, natural_key
from ttsgc.roads.retrieve import JUNCTION_CLEARANCE_M
from ttsgc.scenario import Agent, Scenario

LEFT_SIDE = {"left", "front_left", "back_left"}
RIGHT_SIDE = {"right", "front_right", "back_right"}
AHEAD = ("front", "front_left", "front_right")
BEHIND = ("back", "back_left", "back_right")
JUNCTION_SIDE = {"road_of_left_turn": "left", "road_of_right_turn": "right", "road_of_straight": "straight"}
TURN_OF_ACTION = {"turn_left": "left", "turn_right": "right", "go_straight": "straight"}
CROSSWALK_RUN_UP_M = 20.0
DEFAULT_GAP_M = {"cautious": 12.0, "normal": 8.0, "aggressive": 4.0}


@dataclass(frozen=True)
class Requirement:
    column: str  # header of the explanation table
    test: Callable[[Approach, MapIndex], bool]


def ego_movement(scenario: Scenario) -> str | None:
    """The junction movement the ego makes: left, right or straight (straight only at a junction)."""
    ego = scenario.ego
    if ego.action in ("turn_left", "turn_right"):
        return TURN_OF_ACTION[ego.action]
    later_turn = later_ego_turn(scenario)
    if later_turn is not None and ego.action == "stop":  # it stops before the junction, then turns
        return TURN_OF_ACTION[later_turn]
    if ego.action != "go_straight":
        return None
    if scenario.road.junction or any(a.relative_to_ego in JUNCTION_SIDE or a.relative_to_ego == "at_the_destination"
                                     for a in scenario.agents()):
        return "straight"
    return None


def later_ego_turn(scenario: Scenario) -> str | None:
    """The turn the ego makes in a later stage, if any (the first such line)."""
    return next((a.action for st in scenario.stages[1:] for a in st.agents
                 if a.is_ego and a.action in ("turn_left", "turn_right")), None)


def lane_needs(scenario: Scenario) -> tuple[bool, bool]:
    """Whether the ego's lane needs a neighbour on its left and on its right."""
    left = right = False
    for a in scenario.agents():
        where = "ego" if a.is_ego else a.relative_to_ego
        if a.road_type != "driving":
            continue
        left |= where in LEFT_SIDE or (where in ("ego", "front", "back") and a.action == "change_lane_to_left")
        right |= where in RIGHT_SIDE or (where in ("ego", "front", "back") and a.action == "change_lane_to_right")
    return left, right


def lane_space_needed(scenario: Scenario) -> float:
    """Metres of the ego's lane the ego and the agents queued in it occupy, with their gaps."""
    total = V.BODIES[scenario.ego.type][0] + 4.0  # as placement reckons it
    for a in scenario.stages[0].agents:
        if not a.is_ego and a.relative_to_ego in ("front", "back") and a.road_type == "driving":
            total += V.BODIES[a.type][0] + (a.gap_m if a.gap_m is not None else DEFAULT_GAP_M[a.behavior])
    return total


def entering(approach: Approach, index: MapIndex, side: str) -> Approach | None:
    ids = approach.entering.get(side, ())
    return index.by_id.get(ids[0]) if ids else None


def requirements(scenario: Scenario) -> list[Requirement]:
    out: list[Requirement] = []
    movement = ego_movement(scenario)
    if movement is not None:
        out.append(Requirement(f"ego {movement}", lambda a, i, m=movement: bool(a.turns_to(m))))
    need_left, need_right = lane_needs(scenario)
    if need_left or need_right:
        lanes = 1 + need_left + need_right
        out.append(Requirement(f"lanes>={lanes}", lambda a, i, n=lanes: a.lanes >= n))
    queued: dict[str, float] = {}  # metres each junction road needs for the agents standing on it
    for agent in scenario.agents():
        if agent.is_ego:
            continue
        where = agent.relative_to_ego
        if where in JUNCTION_SIDE and agent.road_type == "driving":
            queued[where] = queued.get(where, 2.0) + V.BODIES[agent.type][0] + (
                agent.gap_m if agent.gap_m is not None else DEFAULT_GAP_M[agent.behavior])
        out += _agent_requirements(agent, movement, queued, away=scenario.road.junction is False)
    space = lane_space_needed(scenario)
    if scenario.road.junction is False:  # and well before the junction, where the road ends at one
        out.append(Requirement(f"length>={space:.0f}m", lambda a, i, n=space: a.run_up >= n + (
            JUNCTION_CLEARANCE_M if a.junction is not None else 0.0)))
    else:
        out.append(Requirement(f"length>={space:.0f}m", lambda a, i, n=space: a.run_up >= n))
    return out


def _agent_requirements(agent: Agent, movement: str | None, queued: dict[str, float], away: bool = False
                        ) -> list[Requirement]:
    """away: the scene is not at a junction, so a crossing must be mid-block, well before any junction."""
    out = []
    where, name = agent.relative_to_ego, agent.name
    side = JUNCTION_SIDE.get(where or "")
    if side is not None:  # the road exists and is long enough for everyone queued on it
        out.append(Requirement(f"{where} ({name})",
                               lambda a, i, s=side, w=where: (e := entering(a, i, s)) is not None
                               and e.run_up >= queued.get(w, 0.0)))
        turn = TURN_OF_ACTION.get(agent.action)
        if turn is not None and agent.road_type == "driving":
            out.append(Requirement(f"{turn} from {where} ({name})",
                                   lambda a, i, s=side, t=turn: (e := entering(a, i, s)) is not None
                                   and bool(e.turns_to(t))))
    elif (where in LEFT_SIDE | RIGHT_SIDE | set(AHEAD) | set(BEHIND) and agent.road_type == "driving"
          and agent.action in ("turn_left", "turn_right")):  # it turns where the ego's road meets a junction
        turn = TURN_OF_ACTION[agent.action]
        out.append(Requirement(f"{turn} ({name})", lambda a, i, t=turn: bool(a.turns_to(t))))
    elif where == "at_the_destination":
        out.append(Requirement(f"destination ({name})",
                               lambda a, i, m=movement: a.junction is None if m is None else bool(a.turns_to(m))))
    elif where == "near_the_crosswalk":  # a crossing the ego has yet to reach
        out.append(Requirement(f"{'mid-block ' if away else ''}crosswalk ({name})",
                               lambda a, i: any(a.run_up - a.length + u >= CROSSWALK_RUN_UP_M
                                                and (not away or mid_block(a, u)) for u in a.crosswalks)))
    if agent.road_type == "shoulder" and side is None:
        out.append(Requirement(f"shoulder ({name})", lambda a, i: a.shoulder))
    elif agent.action == "on_the_sidewalk" and side is None:  # walking a sidewalk needs one: a shoulder is not
        out.append(Requirement(f"sidewalk ({name})", lambda a, i: a.sidewalk))
    elif agent.road_type == "sidewalk" and side is None:  # people stand on a sidewalk, else on a shoulder
        out.append(Requirement(f"kerb ({name})", lambda a, i: a.sidewalk or a.shoulder))
    return out


def mid_block(approach: Approach, u: float) -> bool:
    """A crossing at u (metres from the approach's start) well before the junction the approach ends at."""
    return approach.junction is None or approach.length - u >= JUNCTION_CLEARANCE_M


@dataclass(frozen=True)
class Ranked:
    approach: Approach
    index: MapIndex
    met: tuple[bool, ...]

    @property
    def score(self) -> int:
        return sum(self.met)


def rank(scenario: Scenario, candidates: list[tuple[Approach, MapIndex]], seed: int
         ) -> tuple[list[Requirement], list[Ranked]]:
    """Candidates best first; equal scores in the order `spread` gives them for this seed."""
    reqs = requirements(scenario)
    scored = [Ranked(a, i, tuple(r.test(a, i) for r in reqs)) for a, i in candidates]
    ranked: list[Ranked] = []
    for score in sorted({r.score for r in scored}, reverse=True):
        ranked += spread([r for r in scored if r.score == score], seed, scenario.name)
    return reqs, ranked


def spread(tied: list[Ranked], seed: int, salt: str = "") -> list[Ranked]:
    """Equally ranked candidates in the order seed `seed` offers them. The roads (both directions of a road
    are one road, as the paper counts them) are dealt one map at a time in turn, maps and each map's roads
    in a fixed pseudo-random order (a hash of their names and `salt`, the scene's name; not the seed). Seed s
    starts the deal at the fraction s x 0.618... (mod 1) of the way along it and goes on from there: any five
    seeds start at least a seventh of the deal apart, on roads spread over every map of the library, and a
    seed whose road cannot host the scene tries the roads right after its own, which no other seed starts on.
    A seed's scene can differ from another's (what a prompt leaves open is sampled per seed), and so can its
    tied roads: starting at a fraction, not at place s, keeps seeds apart in any deal of a similar set, where
    places 1 and 2 of two such deals are often one road. The same seed always gives the same order; seed 0
    takes the deal's first road. A road's other direction is offered after every road was once."""
    def shuffled(*key: str) -> int:  # a fixed pseudo-random order, the same in every subset of the library
        return zlib.crc32("/".join((salt,) + key).encode())

    roads: dict[tuple[str, str], list[Ranked]] = {}
    for r in sorted(tied, key=lambda r: (r.index.name, natural_key(r.approach.id))):
        roads.setdefault((r.index.name, r.approach.road), []).append(r)
    by_map: dict[str, list[tuple[str, str]]] = {}
    for key in sorted(roads, key=lambda k: shuffled(*k)):
        by_map.setdefault(key[0], []).append(key)
    maps = sorted(by_map, key=shuffled)
    dealt = [by_map[m][k] for k in range(max((len(v) for v in by_map.values()), default=0))
             for m in maps if k < len(by_map[m])]
    if not dealt:
        return []
    n = len(dealt)
    turn = seed // n  # seeds beyond the number of roads start on the other direction
    start = quantile_start(seed, n)
    dealt = [dealt[(start + k) % n] for k in range(n)]
    directions = [roads[key][turn % len(roads[key]):] + roads[key][:turn % len(roads[key])] for key in dealt]
    return [d[k] for k in range(max(len(d) for d in directions)) for d in directions if k < len(d)]


GOLDEN_FRACTION = (math.sqrt(5) - 1) / 2


def quantile_start(seed: int, n: int) -> int:
    """Where in a deal of n roads seed `seed` starts: the fraction seed x 0.618... (mod 1) of the way along.
    The first five such fractions are at least 0.146 apart, so five seeds take five roads of any deal of
    five or more."""
    return int((seed * GOLDEN_FRACTION) % 1.0 * n) % n


def explain(reqs: list[Requirement], ranked: list[Ranked], limit: int = 15) -> str:
    """The paper's table: one row per candidate, one column per requirement, and the total."""
    headers = ["#", "map", "approach"] + [r.column for r in reqs] + ["total"]
    rows = [[str(k), r.index.name, r.approach.id] + ["✓" if m else "✗" for m in r.met] + [f"{r.score}/{len(reqs)}"]
            for k, r in enumerate(ranked[:limit], start=1)]
    widths = [max(len(str(x)) for x in col) for col in zip(headers, *rows)]
    lines = ["  ".join(str(x).ljust(w) for x, w in zip(row, widths)).rstrip() for row in [headers, *rows]]
    more = f"\n... and {len(ranked) - limit} more candidate(s)" if len(ranked) > limit else ""
    return "\n".join(lines) + more
