"""Placement: every agent of a scene gets a lane position that exists on the chosen road, with no two bodies
overlapping at t = 0, and a route where it crosses a junction.

Positions are measured by u, metres along the stretch that leads to the chosen approach (the approach and
the roads running into it, which real maps cut into short pieces) in its driving direction; lanes are named by
kind and rank, and resolved to a road, lane id and s wherever a body stands. Agents queue in lanes: `order 1`
is nearest the ego (or, on a road entering the junction, nearest the junction), and `behind X` stands just
upstream of X in X's driving direction. `gap` is the free distance to whatever is next in the queue towards
that reference (X, the ego or the junction). A slot search moves a body outward until it overlaps nothing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from pydantic import BaseModel, ConfigDict

from ttsgc import vocabulary as V
from ttsgc.binding.rank import (AHEAD, BEHIND, DEFAULT_GAP_M, JUNCTION_SIDE, LEFT_SIDE, RIGHT_SIDE, TURN_OF_ACTION,
                                ego_movement, mid_block)
from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.roads.index import Approach, MapIndex, Turn, approach_id, upstream_chain
from ttsgc.roads.opendrive import OpenDrive, Road
from ttsgc.roads.retrieve import JUNCTION_CLEARANCE_M
from ttsgc.scenario import Agent, Scenario, Trigger

CLEARANCE_M = 1.0
PAVEMENT_MARGIN_M = 0.1  # a person keeping to one side of the pavement keeps this far inside its edge
MAX_OVERHANG_M = 0.5  # how far a vehicle standing in an edge lane reaches into the driving lane beside it at most
MIN_DRIVING_WIDTH_M = 2.5  # narrower, a lane is still opening or closing there: no vehicle starts on it
PEDESTRIAN_SPEED = {"cautious": 1.0, "normal": 1.4, "aggressive": 2.5}
CYCLIST_SPEED = {"cautious": 3.5, "normal": 5.0, "aggressive": 7.0}
SPEED_FACTOR = {"cautious": 0.6, "normal": 0.85, "aggressive": 1.1}
DEFAULT_LIMIT_KMH = 50.0


class PlacementError(TtsgcError):
    exit_code = ExitCode.NO_ROAD


class _Data(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class LanePos(_Data):
    road: str
    lane: int
    s: float
    offset: float = 0.0


class RelativePos(_Data):
    """Where a later-stage agent appears, relative to the ego when its stage starts."""

    dlane: int  # +1: one lane to the ego's left (lanes counted as a player counts a dLane: lane 0 is none)
    ds: float  # metres ahead of the ego (negative: behind)
    cross_dlane: int | None = None  # a crosser: the lane its crossing ends in, from the ego's as dlane is
    yield_within_m: float | None = None  # the ego brakes once it is this near the crosser (its centre)...
    yield_rate_mps2: float | None = None  # ... at this rate, and sets off again once the crossing is done


class LaterAction(_Data):
    """The ego's action in a later stage: it keeps its one start and body, and acts again from there."""

    stage: int
    action: str
    behavior: str
    speed_mps: float | None  # the speed the line sets (0 for a stop), None: it keeps its speed
    lane_change: int | None = None  # +1 left, -1 right
    trigger: Trigger | None = None


class EgoYield(_Data):
    """Where the ego yields to a body crossing its way: it brakes at rate_mps2 once it is within radius_m of
    centre (a point of its lane, short of the crossing) while the body crosses."""

    centre: LanePos
    radius_m: float
    rate_mps2: float
    crossing_m: float  # from the crosser's start to its far side: less than this from there, it has set off
    hold_s: float  # how much later the ego is through, for stopping (junction traffic takes turns after it)


class BoundAgent(_Data):
    name: str
    type: str
    is_ego: bool
    action: str
    behavior: str
    relative_to_ego: str | None
    road_type: str
    stage: int
    start: LanePos | None  # None: appears relative to the ego when its stage starts
    appear: RelativePos | None = None
    speed_mps: float
    length: float
    width: float
    height: float
    movement: str | None = None  # left / right / straight through a junction
    route: tuple[LanePos, ...] = ()
    target_road: str | None = None  # where its movement ends, by the index
    lane_change: int | None = None  # +1 left, -1 right
    cross_to: LanePos | None = None
    walk_to: LanePos | None = None
    trigger: Trigger | None = None
    distance_to_ego_m: float = 0.0  # at the start, centre to centre
    route_end_into_m: float | None = None  # how far its route's last point lies into the road it ends on
    start_delay_s: float = 0.0  # stands this long before it sets off, so that junction traffic takes turns
    later: tuple[LaterAction, ...] = ()  # the ego's actions in later stages, in stage order
    ego_yield: EgoYield | None = None  # a crossing body the ego stops for (the ego's brake, on the crosser)


@dataclass(frozen=True)
class LaneRef:
    """A lane by what it is rather than by id, so that it can be followed across roads and lane sections:
    the n-th lane of a type counted from the centre (-1: the outermost), on this side or the far side."""

    type: str = "driving"
    rank: int = 0
    far_side: bool = False


@dataclass
class _Frame:
    """An approach and the roads leading into it, as one stretch measured by u: metres from the upstream
    start of the stretch, in the driving direction, to the approach's end (its junction, if any)."""

    approach: Approach
    segments: list[tuple[Road, str, float]]  # upstream first: (road, direction, u where it starts)
    length: float

    @classmethod
    def build(cls, approach: Approach, odr: OpenDrive) -> "_Frame":
        chain = list(reversed(upstream_chain(odr, approach.road, approach.direction)))
        segments, u = [], 0.0
        for road, direction in chain:
            segments.append((road, direction, u))
            u += road.length
        return cls(approach, segments, u)

    @property
    def road(self) -> Road:
        return self.segments[-1][0]

    def locate(self, u: float) -> tuple[Road, str, float]:
        """The road, direction and s at u."""
        for road, direction, start in reversed(self.segments):
            if u >= start - 1e-9:
                local = min(max(u - start, 0.0), road.length)
                return road, direction, local if direction == "forward" else road.length - local
        road, direction, _ = self.segments[0]
        return road, direction, 0.0 if direction == "forward" else road.length

    def u_on_approach(self, s: float) -> float:
        """u of a point at s on the approach's own road."""
        road, direction, start = self.segments[-1]
        return start + (s if direction == "forward" else road.length - s)

    def lanes_at(self, u: float, lane_type: str = "driving", far_side: bool = False) -> list[int]:
        """Lane ids of one type at u, innermost first, on this direction's side (or the far side)."""
        road, direction, s = self.locate(u)
        sign = -1 if direction == "forward" else 1
        section = road.section_at(s)
        return [l.id for l in section.side(-sign if far_side else sign) if l.type == lane_type
                and (lane_type != "driving" or l.width(s - section.s) >= MIN_DRIVING_WIDTH_M)]

    def lane_id(self, ref: LaneRef, u: float) -> int | None:
        """The id of a referenced lane at u, None where the road has no such lane."""
        lanes = self.lanes_at(u, ref.type, ref.far_side)
        return lanes[ref.rank] if -len(lanes) <= ref.rank < len(lanes) else None

    def resolve(self, ref: LaneRef, u: float) -> LanePos:
        road, _, s = self.locate(u)
        lane = self.lane_id(ref, u)
        if lane is None:
            raise PlacementError(f"road {road.id} has no {ref.type} lane {ref.rank + 1} at s={s:.1f}")
        return LanePos(road=road.id, lane=lane, s=round(s, 3))


@dataclass
class _Occupancy:
    """Bodies already placed, per stretch and lane, as intervals of u."""

    taken: dict[tuple[str, LaneRef], list[tuple[float, float]]] = field(default_factory=dict)

    def slot(self, frame: _Frame, lane: LaneRef, u: float, length: float, outward: int) -> float:
        """The first free centre at or beyond u (moving outward) within the stretch, where the lane exists."""
        lo_limit, hi_limit = length / 2 + 0.5, frame.length - length / 2 - 0.5
        spans = self.taken.setdefault((frame.approach.id, lane), [])
        step = 0.5 * (outward or 1)
        for _ in range(4000):
            if not lo_limit <= u <= hi_limit:
                break
            free = all(u + length / 2 + CLEARANCE_M <= a or u - length / 2 - CLEARANCE_M >= b for a, b in spans)
            if free and frame.lane_id(lane, u) is not None:
                spans.append((u - length / 2, u + length / 2))
                return u
            u += step
        raise PlacementError(f"no room for a {length:.1f} m body in the {lane.type} lane of approach "
                             f"{frame.approach.id} (the stretch leading to it is {frame.length:.0f} m)")


def _queue(agents: list[Agent], downstream: bool = False) -> list[Agent]:
    """Agents at one position in placing order, from the reference outward. Heads by order, then as
    written; each is followed by the chain of agents behind it. Behind means upstream, so on a queue that
    grows downstream (ahead of the ego) a chain is placed from its last follower to its head."""
    names = {a.name for a in agents}
    heads = [a for a in agents if a.behind not in names]
    heads.sort(key=lambda a: (a.order if a.order is not None else 1000, agents.index(a)))
    out: list[Agent] = []
    for head in heads:
        chain = [head]
        while nxt := next((a for a in agents if a.behind == chain[-1].name and a not in chain), None):
            chain.append(nxt)
        out += reversed(chain) if downstream else chain
    return out


def _spacing(previous: Agent | None, agent: Agent) -> float:
    """Free distance between consecutive bodies of a queue: the gap of whichever one is behind the other."""
    if previous is not None and previous.behind == agent.name:
        return _gap(previous)
    if agent.behind is not None and (previous is None or agent.behind != previous.name):
        return _default_gap(agent)  # its own gap is to the one it is behind, elsewhere in the queue
    return _gap(agent)


GOING_ROUND_S = 2.0  # how long before it would reach a body standing in its lane an ego going round it starts
# its 3 s lane change: three quarters across by then (a sinusoid), clear of a truck's width
LANE_CHANGE_ROOM_M = 3.0  # centre to centre beyond both half lengths: clear to change in beside another
STANDING_FIRST_S = 1.5  # how long the body it goes round has stood when the ego pulls out
COMING_UP_IN_THE_LANE_CHANGED_TO = {"change_lane_to_left": "back_left", "change_lane_to_right": "back_right"}
# where vehicles that come up level in the lane the ego changes into start (the ego lets the faster pass first)


def _pulls_in_ahead(agent: Agent) -> bool:
    """Blocks the ego from a lane beside it (not from behind: that one overtakes first)."""
    where = agent.relative_to_ego
    return agent.action == "block_the_ego" and where in LEFT_SIDE | RIGHT_SIDE and where not in BEHIND


def _gap(agent: Agent) -> float:
    return agent.gap_m if agent.gap_m is not None else _default_gap(agent)


def _default_gap(agent: Agent) -> float:
    return 2.0 if agent.type == "pedestrian" else DEFAULT_GAP_M[agent.behavior]


def _speed(agent: Agent, limit_kmh: float | None) -> float:
    if agent.speed is not None:
        return agent.speed.mps
    if agent.type == "pedestrian":
        return PEDESTRIAN_SPEED[agent.behavior]
    if agent.type == "cyclist":
        return CYCLIST_SPEED[agent.behavior]
    if agent.road_type == "shoulder" and agent.action == "stop":
        return 0.0  # already stopped on the shoulder
    return round((limit_kmh or DEFAULT_LIMIT_KMH) / 3.6 * SPEED_FACTOR[agent.behavior], 3)


LANE_CHANGE_OF_ACTION = {"change_lane_to_left": 1, "change_lane_to_right": -1}


def later_actions(scenario: Scenario) -> tuple[LaterAction, ...]:
    """The ego's `ego TYPE ACTION` lines of later stages. The ego's one route through a junction is laid from
    its start, so a later turn is bound only after a first-stage stop (it waits before the junction, then
    turns), and only one."""
    out = []
    turns = 0
    for k, stage in enumerate(scenario.stages[1:], start=1):
        for a in stage.agents:
            if not a.is_ego:
                continue
            if a.action in ("turn_left", "turn_right"):
                turns += 1
                if scenario.ego.action != "stop" or turns > 1:
                    raise PlacementError(
                        f"the ego's {a.action} in stage '{stage.name}' cannot be bound: a later turn of the ego needs "
                        f"it to stop before the junction first (ego {a.type} stop in the first stage) and is made "
                        f"once; else write the turn on the first stage's ego line (ego {a.type} {a.action})")
            speed = 0.0 if a.action == "stop" else a.speed.mps if a.speed is not None else None
            out.append(LaterAction(stage=k, action=a.action, behavior=a.behavior, speed_mps=speed,
                                   lane_change=LANE_CHANGE_OF_ACTION.get(a.action), trigger=a.trigger))
    return tuple(out)


class Placer:
    """Places one scenario on one approach of one map."""

    def __init__(self, scenario: Scenario, approach: Approach, index: MapIndex, odr: OpenDrive):
        self.scenario, self.index, self.odr = scenario, index, odr
        self.frames: dict[str, _Frame] = {}
        self.frame = self.frame_of(approach)
        self.occupied = _Occupancy()
        self.last_in_queue: dict[tuple, tuple[Agent, float, float]] = {}  # (stretch, lane, outward) -> last body
        self._later: list[tuple[str, Agent, float]] = []  # later-stage agents placed so far
        self.ego_start: LanePos | None = None
        self.ego_route: tuple[LanePos, ...] = ()
        self.movement = ego_movement(scenario)
        self.ego_turn = self._pick_turn(approach, self.movement) if self.movement else None
        if self.movement and self.ego_turn is None:
            raise PlacementError(f"approach {approach.id} of {index.name} has no {self.movement} turn")

    def frame_of(self, approach: Approach) -> _Frame:
        if approach.id not in self.frames:
            self.frames[approach.id] = _Frame.build(approach, self.odr)
        return self.frames[approach.id]

    @staticmethod
    def _pick_turn(approach: Approach, movement: str) -> Turn | None:
        turns = approach.turns_to(movement)
        if not turns:
            return None
        if movement == "right":
            return sorted(turns, key=lambda t: (-max(map(abs, t.from_lanes)), t.via_road))[0]
        return sorted(turns, key=lambda t: (min(map(abs, t.from_lanes)), t.via_road))[0]

    # -- the ego ------------------------------------------------------------------------------------------
    def place(self) -> list[BoundAgent]:
        s = self.scenario
        by_position: dict[str, list[Agent]] = {}
        for a in s.stages[0].agents:
            if not a.is_ego:
                by_position.setdefault(a.relative_to_ego, []).append(a)
        ego = s.ego
        ego_len = V.BODIES[ego.type][0]
        def space(positions: tuple[str, ...]) -> float:  # the longest queue ahead of (or behind) the ego
            return max(sum(V.BODIES[a.type][0] + _gap(a) for a in by_position.get(p, ())) for p in positions)
        front_space = space(AHEAD)
        back_space = space(BEHIND)
        frame = self.frame
        need = ego_len + front_space + back_space + 4.0
        if need > frame.length:
            raise PlacementError(f"approach {frame.approach.id} of {self.index.name} and the roads leading to it are "
                                 f"{frame.length:.0f} m long; the ego's lane needs {need:.0f} m")
        lowest = back_space + ego_len / 2 + 1.0
        if self.movement is not None:  # reach the junction within a few seconds
            u_ego = frame.length - max(25.0, front_space + 12.0)
        else:  # on the chosen road itself when it is long enough, leaving the road ahead free
            u_ego = min(frame.segments[-1][2] + back_space + ego_len / 2 + 10.0,
                        frame.length - front_space - ego_len / 2 - 20.0)
        if s.road.junction is False and frame.approach.junction is not None:  # well before the junction
            u_ego = min(u_ego, frame.length - front_space - ego_len / 2 - JUNCTION_CLEARANCE_M)
            if u_ego < lowest:
                raise PlacementError(f"approach {frame.approach.id} of {self.index.name} leaves no room for the "
                                     f"scene {JUNCTION_CLEARANCE_M:.0f} m before its junction")
        crosswalk = self._crosswalk_u()
        if crosswalk is not None and "near_the_crosswalk" in by_position:
            u_ego = min(u_ego, crosswalk - 25.0)
        self.u_ego = max(u_ego, lowest)
        self.ego_lane = LaneRef("driving", self._ego_lane_rank())
        if self.ego_turn is not None:  # the turn taken from the ego's own lane
            lane = frame.approach.lane_ids[self.ego_lane.rank] if self.ego_lane.rank < len(frame.approach.lane_ids) \
                else None
            self.ego_turn = next((t for t in frame.approach.turns_to(self.movement) if lane in t.from_lanes),
                                 self.ego_turn)
        self.u_ego = self.occupied.slot(frame, self.ego_lane, self.u_ego, ego_len, -1)
        self.ego_start = frame.resolve(self.ego_lane, self.u_ego)
        placed = [self._bound(ego, 0, self.ego_start, frame).model_copy(update={"later": later_actions(s)})]
        self.ego_route = placed[0].route
        for position in sorted(by_position, key=lambda p: list(V.POSITIONS).index(p)):
            downstream = position in AHEAD
            for agent in _queue(by_position[position], downstream):
                placed.append(self._place_agent(agent, 0))
        placed[0] = self._ego_goes_round(placed[0], placed[1:])
        for k, stage in enumerate(s.stages[1:], start=1):
            groups: dict[str, list[Agent]] = {}
            for agent in stage.agents:
                if not agent.is_ego:  # the ego's later action is no new body (later_actions)
                    groups.setdefault(agent.relative_to_ego, []).append(agent)
            for position, group in groups.items():
                for agent in _queue(group, position in AHEAD):
                    placed.append(self._place_later(agent, k))
        order: dict[str, int] = {}
        for n, a in enumerate(s.agents()):
            order.setdefault(a.name, n)
        placed = sorted(placed, key=lambda b: order[b.name])
        placed = ego_yields(placed, self.odr, timed_by_trigger=True)  # before the turns: the ego's wait counts
        placed = stagger_at_junction(no_faster_than_the_one_ahead(walkers_keep_their_gap(placed)), self.odr)
        capped = no_faster_onto_one_road(placed, self.odr)
        if capped != placed:  # slower, they hold the junction longer: the turns are taken again
            placed = stagger_at_junction(capped, self.odr)
        return ego_yields(let_the_traffic_pass(placed, self.odr), self.odr, timed_by_trigger=False)

    def _ego_lane_rank(self) -> int:
        from ttsgc.binding.rank import lane_needs

        approach = self.frame.approach
        n = len(approach.lane_ids)
        need_left, need_right = lane_needs(self.scenario)
        allowed = list(range(n))
        if self.ego_turn is not None:  # any lane the movement can be made from (maps give each lane its own turn)
            turning = {lane for turn in approach.turns_to(self.movement) for lane in turn.from_lanes}
            allowed = [i for i in allowed if approach.lane_ids[i] in turning] or allowed
        if self.movement == "right":
            allowed.reverse()
        fits = [i for i in allowed if (not need_left or i >= 1) and (not need_right or i <= n - 2)]
        return (fits or allowed)[0]

    def _crosswalk_u(self) -> float | None:
        """The crossing nearest the approach's end, in stretch coordinates."""
        start = self.frame.segments[-1][2]
        approach = self.frame.approach
        away = self.scenario.road.junction is False  # then the crossing is mid-block, well before a junction
        spots = [start + u for u in approach.crosswalks if not away or mid_block(approach, u)]
        return max(spots) if spots else None

    # -- other agents -------------------------------------------------------------------------------------
    def _place_agent(self, agent: Agent, stage: int) -> BoundAgent:
        where = agent.relative_to_ego
        side = JUNCTION_SIDE.get(where)
        if side is not None:
            return self._on_entering_road(agent, side, stage)
        if where == "at_the_destination":
            return self._at_destination(agent, stage)
        frame, ego_len = self.frame, V.BODIES[self.scenario.ego.type][0]
        length = V.BODIES[agent.type][0]
        lane = self._lane_for(agent, frame)
        if where == "near_the_crosswalk":
            crosswalk = self._crosswalk_u()
            target = (crosswalk - 1.5 - length / 2) if crosswalk is not None else min(
                self.u_ego + 20.0, frame.length - length)
            outward = -1
        elif _pulls_in_ahead(agent):
            return self._ahead_to_pull_in(agent, stage, lane)
        elif where in AHEAD:
            edge = self.u_ego + ego_len / 2
            if stage == 0 and agent.action == "cross_the_road" and self.scenario.ego.action == "stop":
                edge += self._ego_stopping_m()  # it crosses ahead of where the ego comes to stand, not under it
            if stage == 0 and lane == self.ego_lane and self._goes_round(agent) and \
                    (frame.approach.id, lane, +1) not in self.last_in_queue:
                edge += self._room_to_go_round(agent)
            target, outward = self._after(frame, lane, edge, agent, +1), +1
        elif where in BEHIND:
            target, outward = self._after(frame, lane, self.u_ego - ego_len / 2, agent, -1), -1
        else:  # left / right: beside the ego
            target, outward = self.u_ego, -1
        return self._put(agent, stage, frame, lane, target, outward)

    def _goes_round(self, agent: Agent) -> bool:
        """Whether the ego, changing lane in the first stage at no trigger of its own, goes round this agent:
        one that comes to stand ahead in its lane ('a stopped truck blocks my lane; I change left to go
        round it')."""
        ego = self.scenario.ego
        return ego.action in LANE_CHANGE_OF_ACTION and ego.trigger is None and \
            agent.relative_to_ego == "front" and agent.action in ("stop", "block_the_ego")

    def _room_to_go_round(self, agent: Agent) -> float:
        """How much farther ahead than its gap the body the ego goes round starts: its own braking distance and
        what the ego runs before it starts its lane change, so the ego comes up behind it standing and then
        pulls out (told to change at once, it changed before the body was in its way: blocked nothing)."""
        limit = self.frame.approach.speed_limit_kmh
        speed, ego_speed = _speed(agent, limit), _speed(self.scenario.ego, limit)
        return speed ** 2 / (2 * V.BRAKE_RATE[agent.behavior]) + \
            (GOING_ROUND_S + STANDING_FIRST_S + self._passing_first_s(ego_speed, limit)) * ego_speed

    def _passing_first_s(self, ego_speed: float, limit: float | None) -> float:
        """How long the ego waits for the faster vehicles coming up behind in the lane it changes into to draw
        level and get clear ahead (the emitter makes it let them pass first): the body it goes round stands
        that much farther ahead, or the ego reaches it still waiting (a player's ego drives into it)."""
        ego = self.scenario.ego
        side = COMING_UP_IN_THE_LANE_CHANGED_TO[ego.action]
        ego_len, behind, longest = V.BODIES[ego.type][0], 0.0, 0.0
        for other in self.scenario.stages[0].agents:
            if other.is_ego or other.relative_to_ego != side or other.action != "go_straight":
                continue
            length = V.BODIES[other.type][0]
            behind += _gap(other) + length  # queued one behind the other in that lane
            faster = _speed(other, limit) - ego_speed
            if faster > 0:
                longest = max(longest, (behind + ego_len + LANE_CHANGE_ROOM_M) / faster)
        return longest

    def _ego_goes_round(self, ego: BoundAgent, others: list[BoundAgent]) -> BoundAgent:
        """The ego's lane change starts once it is about to reach the body it goes round (the nearest such)."""
        agents = {a.name: a for a in self.scenario.stages[0].agents}
        ahead = [a for a in others if a.stage == 0 and a.name in agents and self._goes_round(agents[a.name])]
        if not ahead:
            return ego
        body = min(ahead, key=lambda a: a.distance_to_ego_m)
        reach = GOING_ROUND_S * ego.speed_mps + (V.BODIES[ego.type][0] + V.BODIES[body.type][0]) / 2 + 2.0
        return ego.model_copy(update={"trigger": Trigger(within_m=round(reach, 3), of=body.name)})

    def _ahead_to_pull_in(self, agent: Agent, stage: int, lane: LaneRef) -> BoundAgent:
        """A vehicle that blocks the ego from a side lane starts ahead of the ego, or its pull-in would land on
        the ego (a player changes lane when told, into whatever is there), and ahead of every body already
        queued in the ego's lane, so that two blockers ("boxed in: one in front, one on each side") never pull
        into one gap: it is counted into the ego lane's queue as well as its own."""
        ego_len = V.BODIES[self.scenario.ego.type][0]
        target = self._after(self.frame, self.ego_lane, self.u_ego + ego_len / 2, agent, +1)
        bound = self._put(agent, stage, self.frame, lane, target, +1)
        self.last_in_queue[(self.frame.approach.id, self.ego_lane, +1)] = \
            self.last_in_queue[(self.frame.approach.id, lane, +1)]
        return bound

    def _put(self, agent: Agent, stage: int, frame: _Frame, lane: LaneRef, target: float, outward: int,
             turn: Turn | None = None) -> BoundAgent:
        length = V.BODIES[agent.type][0]
        u = self.occupied.slot(frame, lane, target, length, outward)
        self.last_in_queue[(frame.approach.id, lane, outward)] = (agent, u, length)
        start = frame.resolve(lane, u)
        if lane.type != "driving" and agent.type != "pedestrian":
            start = self._clear_of_the_driving_lane(agent, start)
        elif lane.type == "sidewalk" and agent.type == "pedestrian":
            start = self._keeping_to_a_side(agent, start)
        return self._bound(agent, stage, start, frame, turn=turn, far_side=lane.far_side)

    def _clear_of_the_driving_lane(self, agent: Agent, start: LanePos) -> LanePos:
        """A vehicle standing in an edge lane (a shoulder) narrower than itself stands outward, over the kerb,
        so that it reaches no more than MAX_OVERHANG_M into the driving lane: centred on a 0.3 m shoulder, a
        2.5 m truck would stand 1.1 m into it, and passing traffic (which does not swerve) would hit it. The
        LanePosition's offset counts along the road's t, to the left of its reference line."""
        section = self.odr.roads[start.road].section_at(start.s)
        width = section.lanes[start.lane].width(start.s - section.s)
        shift = (V.BODIES[agent.type][1] - width) / 2 - MAX_OVERHANG_M
        if shift <= 0:
            return start
        return start.model_copy(update={"offset": round(shift if start.lane > 0 else -shift, 3)})

    def _keeping_to_a_side(self, agent: Agent, start: LanePos) -> LanePos:
        """One about to cross waits at the kerb, one walking along keeps to the pavement's outer half, as people
        do: so a walker passes those waiting to cross instead of walking through them. The offset counts along
        the road's t (outward is toward -t on a right lane)."""
        section = self.odr.roads[start.road].section_at(start.s)
        width = section.lanes[start.lane].width(start.s - section.s)
        shift = (width - V.BODIES[agent.type][1]) / 2 - PAVEMENT_MARGIN_M
        if shift <= 0 or agent.action not in ("cross_the_road", "on_the_sidewalk"):
            return start
        outward = (1 if agent.action == "on_the_sidewalk" else -1) * (-1 if start.lane < 0 else 1)
        return start.model_copy(update={"offset": round(outward * shift, 3)})

    def _after(self, frame: _Frame, lane: LaneRef, edge: float, agent: Agent, outward: int) -> float:
        """Desired centre of the next body in a queue: beyond the previous one (or the given edge) by the gap."""
        previous = self.last_in_queue.get((frame.approach.id, lane, outward))
        if previous is not None:
            _, u, length = previous
            edge = u + outward * length / 2
        return edge + outward * (_spacing(previous[0] if previous else None, agent) + V.BODIES[agent.type][0] / 2)

    def _lane_for(self, agent: Agent, frame: _Frame, rank: int | None = None) -> LaneRef:
        """The lane an agent stands in: people and parked vehicles at the road's edge, others by position."""
        where = agent.relative_to_ego
        if agent.road_type in ("sidewalk", "shoulder"):
            far = where in LEFT_SIDE
            u = self.u_ego if frame is self.frame else frame.length - 1.0
            for lane_type in (agent.road_type, "sidewalk", "shoulder"):
                if frame.lanes_at(u, lane_type, far_side=far):
                    return LaneRef(lane_type, -1, far)
            return LaneRef("driving", -1, far)  # no edge lane: the outermost driving lane
        if rank is not None:
            return LaneRef("driving", rank)
        rank = self.ego_lane.rank if frame is self.frame else 0
        if where in LEFT_SIDE:
            rank -= 1
        elif where in RIGHT_SIDE:
            rank += 1
        if rank < 0 or rank >= len(frame.lanes_at(self.u_ego if frame is self.frame else frame.length - 1.0)):
            raise PlacementError(f"approach {frame.approach.id} has no lane to the "
                                 f"{'left' if where in LEFT_SIDE else 'right'} of the ego's lane for '{agent.name}'")
        return LaneRef("driving", rank)

    def _on_entering_road(self, agent: Agent, side: str, stage: int) -> BoundAgent:
        ids = self.frame.approach.entering.get(side, ())
        if not ids:
            raise PlacementError(f"no road enters junction {self.frame.approach.junction} from the {side} of "
                                 f"approach {self.frame.approach.id} for '{agent.name}'")
        entering = self.index.by_id[ids[0]]
        frame = self.frame_of(entering)
        movement = TURN_OF_ACTION.get(agent.action)
        turn = self._pick_turn(entering, movement) if movement and agent.road_type == "driving" else None
        if turn is None and agent.road_type == "driving" and agent.action in ("turn_left", "turn_right"):
            # as for the ego: a turning agent needs its turn, else it would only drive on (another road may have it)
            raise PlacementError(f"approach {entering.id} of {self.index.name}, the {side} road of junction "
                                 f"{self.frame.approach.junction}, has no {movement} turn for '{agent.name}'")
        rank = None
        if agent.road_type == "driving":
            ranks = [i for i, lane in enumerate(entering.lane_ids) if turn is None or lane in turn.from_lanes] or [0]
            rank = ranks[-1] if movement == "right" else ranks[0]
        lane = self._lane_for(agent, frame, rank)
        target = self._after(frame, lane, frame.length, agent, -1)
        return self._put(agent, stage, frame, lane, target, -1, turn=turn)

    def _at_destination(self, agent: Agent, stage: int) -> BoundAgent:
        length = V.BODIES[agent.type][0]
        if self.ego_turn is None:  # no junction: far ahead on the ego's road
            lane = self._lane_for(agent, self.frame) if agent.road_type != "driving" else self.ego_lane
            target = min(self.u_ego + 60.0, self.frame.length - length)
            return self._put(agent, stage, self.frame, lane, target, -1)
        destination = self.index.by_id.get(approach_id(self.ego_turn.to_road, self.ego_turn.to_direction))
        if destination is None:
            raise PlacementError(f"the ego's {self.movement} turn leads to road {self.ego_turn.to_road}, which has "
                                 f"no driving lanes in that direction")
        frame = self.frame_of(destination)
        lane = self._lane_for(agent, frame, -1 if self.movement == "right" else 0)
        start = frame.segments[-1][2]  # the destination road begins at the junction
        return self._put(agent, stage, frame, lane, start + 15.0 + length / 2, +1)

    def _place_later(self, agent: Agent, stage: int) -> BoundAgent:
        """A later-stage agent: relative to the ego when its stage starts, or at a fixed junction road."""
        where = agent.relative_to_ego
        if where in JUNCTION_SIDE or where in ("at_the_destination", "near_the_crosswalk"):
            return self._place_agent(agent, stage)
        if agent.action == "cross_the_road" and self._ego_stands_until(stage):
            return self._beside_the_standing_ego(agent, stage)
        if agent.action == "cross_the_road" and where in AHEAD and agent.type == "pedestrian":
            return self._ahead_of_the_moving_ego(agent, stage)
        length, ego_len = V.BODIES[agent.type][0], V.BODIES[self.scenario.ego.type][0]
        dlane = 1 if where in LEFT_SIDE else -1 if where in RIGHT_SIDE else 0
        ahead = where in AHEAD
        behind = where in BEHIND
        keeping_pace = [(a, V.BODIES[a.type][0]) for a in self.scenario.stages[0].agents
                        if not a.is_ego and a.relative_to_ego == where and a.action == "go_straight"]
        previous = keeping_pace + [(a, l) for w, a, l in self._later if w == where]  # "an ambulance behind the
        # ego; then a fire engine comes up behind as well": behind the ambulance, which still follows
        extra = sum(l + _spacing(p, a) for (p, _), (a, l) in zip([(None, 0)] + previous, previous))
        last = previous[-1][0] if previous else None
        ds = (ego_len / 2 + extra + _spacing(last, agent) + length / 2) * (1 if ahead else -1 if behind else 0)
        if not ahead and not behind and previous:  # beside the ego: the first abreast, the rest queued behind it
            first = previous[0][1] / 2 + sum(l + _spacing(p, a) for (p, _), (a, l) in zip(previous, previous[1:]))
            ds = -(first + _spacing(last, agent) + length / 2)
        self._later.append((where, agent, length))
        return self._bound(agent, stage, None, self.frame, appear=RelativePos(dlane=dlane, ds=round(ds, 3)))

    def _ego_stands_until(self, stage: int) -> bool:
        """Whether the ego stops in the first stage and is told nothing but to stop until `stage`."""
        return self.scenario.ego.action == "stop" and all(
            step.action == "stop" for step in later_actions(self.scenario) if step.stage <= stage)

    def _ego_stopping_m(self) -> float:
        """How far the ego runs from its start when told to stop: it brakes at once, at its behaviour's rate."""
        ego = self.scenario.ego
        return _speed(ego, self.frame.approach.speed_limit_kmh) ** 2 / (2 * V.BRAKE_RATE[ego.behavior])

    def _beside_the_standing_ego(self, agent: Agent, stage: int) -> BoundAgent:
        """A later walker that crosses, placed where the ego will stand by then (its braking distance on): a
        crossing needs a fixed start and far side, which a place relative to the ego when the stage starts
        has not (the walker appeared there and stood)."""
        placed_at = self.u_ego
        self.u_ego = placed_at + self._ego_stopping_m()
        try:
            return self._place_agent(agent, stage)
        finally:
            self.u_ego = placed_at

    def _ego_when_stage_starts(self, stage: int) -> tuple[LanePos, float]:
        """Where the ego drives (road, lane, about where on it) once a later stage starts, and at what speed:
        past the junction when its route leads through one (the emitter starts the next stage there), else on
        its own road; in the lane its lane changes of the stages before have taken it to."""
        ego = self.scenario.ego
        speed = _speed(ego, self.frame.approach.speed_limit_kmh)
        steps = [step for step in later_actions(self.scenario) if step.stage < stage]
        speed = next((step.speed_mps for step in reversed(steps) if step.speed_mps is not None), speed)
        at = self.ego_route[-1] if self.ego_route and ego.action != "stop" else self.ego_start
        to_the_left = LANE_CHANGE_OF_ACTION.get(ego.action, 0) + sum(step.lane_change or 0 for step in steps)
        if to_the_left:  # left is towards the centre line on either side
            lane = at.lane - to_the_left if at.lane > 0 else at.lane + to_the_left
            at = at.model_copy(update={"lane": lane if lane * at.lane > 0 else at.lane})
        return at, speed

    def _ahead_of_the_moving_ego(self, agent: Agent, stage: int) -> BoundAgent:
        """A later walker that crosses ahead of an ego driving on: it enters at the kerb on the ego's side, far
        enough ahead that the ego stops for it as for a first-stage crosser (ego_yields: its comfortable brake
        ending YIELD_MARGIN_M short of the walker's way), and crosses to the outermost lane of the far side.
        Its start and far side are written relative to the ego when its stage starts (a RelativeLanePosition,
        which a player resolves when the entry or the trajectory starts, esmini's Trajectory::Freeze), since
        where the ego is then the binding cannot know to the metre."""
        at, speed = self._ego_when_stage_starts(stage)
        road = self.odr.roads[at.road]
        s = min(max(at.s, 0.0), road.length)
        section = road.section_at(s)
        side = -1 if at.lane < 0 else 1
        own, other = section.side(side), section.side(-side)  # each side's lanes, from the centre line out
        if not own or not other or at.lane not in section.lanes:
            raise PlacementError(f"road {at.road} has no far side for '{agent.name}' to cross to")
        rank = [lane.id for lane in own].index(at.lane)
        kerb = -(len(own) - 1 - rank)  # to the ego's right, out to its side's edge
        far = rank + len(other)  # to its left, across the centre line to the far edge
        centre = road.lane_point(s, at.lane)
        edge = road.lane_point(s, own[-1].id)
        lateral = math.hypot(edge.x - centre.x, edge.y - centre.y)
        ego = self.scenario.ego
        rate = YIELD_DECEL[ego.behavior]
        braking = speed * speed / (2 * rate)
        stop_short = V.BODIES[ego.type][0] / 2 + V.BODIES[agent.type][1] / 2 + YIELD_MARGIN_M
        along = braking + stop_short  # where the brake starts, along the ego's lane from the walker's way
        runs_out = agent.behavior == "aggressive"  # as ego_yields: the ego is not told to stop, a collision is asked for
        relative = RelativePos(dlane=kerb, ds=round(along + LATER_CROSSER_LEAD_M, 3), cross_dlane=far,
                               yield_within_m=None if runs_out else round(math.hypot(along, lateral), 3),
                               yield_rate_mps2=None if runs_out else rate)
        return self._bound(agent, stage, None, self.frame, appear=relative)

    # -- building the record ------------------------------------------------------------------------------
    def _bound(self, agent: Agent, stage: int, start: LanePos | None, frame: _Frame, turn: Turn | None = None,
               far_side: bool = False, appear: RelativePos | None = None) -> BoundAgent:
        length, width, height = V.BODIES[agent.type]
        movement = target_road = None
        route: list[LanePos] = []
        if agent.is_ego:
            turn = self.ego_turn
        into_turn_lane = None  # lanes to move left (negative: right) first, when its own lane has not its turn
        if turn is not None and start is not None and agent.road_type == "driving":
            movement, target_road = turn.direction, turn.to_road
            route = self._route(start, frame, turn)
        elif start is not None and frame is self.frame and agent.road_type == "driving":
            own = TURN_OF_ACTION.get(agent.action) if agent.action in ("turn_left", "turn_right") else None
            turn, from_lane = self._turn_from(self.frame.approach, own, start.lane) if own else (None, start.lane)
            if own and turn is None:  # it could only drive on: another road may have its turn
                raise PlacementError(f"approach {frame.approach.id} of {self.index.name} has no {own} turn for "
                                     f"'{agent.name}'")
            if turn is not None:  # it turns at the ego's junction, from a lane that has its turn
                movement, target_road = turn.direction, turn.to_road
                route = self._route(start, frame, turn, from_lane)
                into_turn_lane = (abs(start.lane) - abs(from_lane)) or None  # lanes to the left: -2 to -1 is one
            elif self.frame.approach.junction is not None:  # traffic on the ego's road carries on through it
                through = self._pick_turn(self.frame.approach, "straight") or self.ego_turn
                if through is not None:
                    route = self._route(start, frame, through)
        lane_change = {"change_lane_to_left": 1, "change_lane_to_right": -1}.get(agent.action, into_turn_lane)
        if agent.action == "block_the_ego" and agent.relative_to_ego in LEFT_SIDE | RIGHT_SIDE:
            lane_change = -1 if agent.relative_to_ego in LEFT_SIDE else 1  # into the ego's lane
            ego = self.ego_start
            if start is not None and ego is not None and start.road == ego.road and \
                    (start.lane > 0) == (ego.lane > 0) and abs(start.lane) != abs(ego.lane):
                lane_change = abs(start.lane) - abs(ego.lane)  # as many lanes as lie between (left is towards the
                # reference line on either side): "a van parked on the hard shoulder pulls out and blocks the ego"
                # in the far lane crosses the near one too
        cross_to = walk_to = None
        if start is not None and agent.action == "cross_the_road":
            cross_to = self._far_side(start)
        if start is not None and agent.action == "on_the_sidewalk":
            road_length = self.odr.roads[start.road].length
            ahead = 30.0 if start.lane < 0 else -30.0  # along its side's driving direction, or back the other
            ends = [min(max(start.s + way, 0.5), road_length - 0.5) for way in (ahead, -ahead)]  # way when the
            end = max(ends, key=lambda s: abs(s - start.s) > abs(ahead) / 2)  # road ends first (a crosswalk at
            walk_to = start.model_copy(update={"s": round(end, 3)})  # the junction): a walk, not a step
        distance = 0.0
        if start is not None and not agent.is_ego and self.ego_start is not None:
            distance = round(distance_between(self.odr, start, self.ego_start), 3)
        into = None
        if len(route) >= 2:  # how far its route's end lies into the road it leads onto, past the junction
            end = route[-1]
            into = round(end.s if end.lane < 0 else self.odr.roads[end.road].length - end.s, 3)
        return BoundAgent(
            distance_to_ego_m=distance, route_end_into_m=into,
            name=agent.name, type=agent.type, is_ego=agent.is_ego, action=agent.action, behavior=agent.behavior,
            relative_to_ego=agent.relative_to_ego, road_type=agent.road_type, stage=stage, start=start,
            appear=appear, speed_mps=_speed(agent, frame.approach.speed_limit_kmh), length=length, width=width,
            height=height, movement=movement, route=tuple(route), target_road=target_road, lane_change=lane_change,
            cross_to=cross_to, walk_to=walk_to, trigger=agent.trigger)

    @staticmethod
    def _turn_from(approach: Approach, movement: str, lane: int) -> tuple[Turn | None, int]:
        """(turn, the lane it is taken from): the turn to `movement` from `lane`; when that lane has none (a
        right lane for a left turn), the one from the nearest lane that has, which the agent moves into first,
        as a driver does before the junction: a player follows its lane's own links and takes no other turn."""
        turns = approach.turns_to(movement)
        own = [t for t in turns if lane in t.from_lanes]
        if own or not turns:
            return (sorted(own, key=lambda t: t.via_road)[0] if own else None), lane
        nearest = lambda t: min(t.from_lanes, key=lambda x: (abs(abs(x) - abs(lane)), abs(x)))  # noqa: E731
        best = min(turns, key=lambda t: (abs(abs(nearest(t)) - abs(lane)), t.via_road))
        return best, nearest(best)

    def _route(self, start: LanePos, frame: _Frame, turn: Turn, from_lane: int | None = None) -> list[LanePos]:
        """Start, the middle of the connecting road in the junction, and a point on the road it leads to;
        from_lane: the lane it turns from, when it changes into it first."""
        via = self.odr.roads[turn.via_road]
        approach_lanes = list(frame.approach.lane_ids)
        lane_of_turn = start.lane if from_lane is None else from_lane
        rank = approach_lanes.index(lane_of_turn) if lane_of_turn in approach_lanes else 0
        k = next((i for i, lane in enumerate(turn.from_lanes) if lane == lane_of_turn), 0)
        points = [start, LanePos(road=via.id, lane=turn.via_lanes[k], s=round(via.length / 2, 3))]
        target = self.index.by_id.get(approach_id(turn.to_road, turn.to_direction))
        if target is not None:
            out = self.frame_of(target)
            u = out.segments[-1][2] + min(20.0, target.length / 2)
            lanes = out.lanes_at(u)
            lane = lanes[-1] if turn.direction == "right" else lanes[min(rank, len(lanes) - 1)]
            points.append(LanePos(road=turn.to_road, lane=lane, s=out.resolve(LaneRef(), u).s))
        return points

    def _far_side(self, start: LanePos) -> LanePos:
        """The outermost lane on the other side of the road, across from a start position."""
        road = self.odr.roads[start.road]
        section = road.section_at(start.s)
        other = section.side(1 if start.lane < 0 else -1)
        if other:
            return LanePos(road=road.id, lane=other[-1].id, s=start.s)
        # a one-way road: its other edge is the innermost lane of this side
        return LanePos(road=road.id, lane=section.side(-1 if start.lane < 0 else 1)[0].id, s=start.s)


def place(scenario: Scenario, approach: Approach, index: MapIndex, odr: OpenDrive) -> list[BoundAgent]:
    return Placer(scenario, approach, index, odr).place()


JUNCTION_GAP_S = 1.5  # between one road's traffic leaving the junction and the next road's entering it


def stagger_at_junction(agents: list[BoundAgent], odr: OpenDrive) -> list[BoundAgent]:
    """Traffic from different roads takes turns through the junction: a road's vehicles that would be in the
    junction while the ego's road's (or an earlier road's) are there wait at their start. A scene file has no
    right of way, and a player whose drivers do not yield (esmini) would otherwise play a crash no scene asked
    for. Vehicles of one road and direction share a delay, so that none waits in front of its follower. Each
    stage takes turns on its own, from its start (a later stage's agents enter together)."""
    delays: dict[tuple[int, str, bool], float] = {}
    for stage in sorted({a.stage for a in agents}):
        delays.update(_turns(agents, stage, odr))
    out = []
    for agent in agents:
        key = _turn_key(agent, agents) if agent.start is not None else None
        delay = delays.get(key, 0.0) if len(agent.route) >= 2 else 0.0
        out.append(agent.model_copy(update={"start_delay_s": delay}) if delay != agent.start_delay_s else agent)
    return out


def _reaches_junction_s(agent: BoundAgent, odr: OpenDrive) -> float:
    """When a vehicle with a route through a junction enters it: its wait, then its way there at its speed."""
    via = agent.route[1]
    road = odr.roads[via.road]
    entry = road.lane_point(0.0 if via.lane < 0 else road.length, via.lane)
    here = odr.roads[agent.start.road].lane_point(agent.start.s, agent.start.lane)
    return agent.start_delay_s + max(0.0, math.hypot(entry.x - here.x, entry.y - here.y) - agent.length / 2) / \
        max(agent.speed_mps, 0.1)


def no_faster_onto_one_road(agents: list[BoundAgent], odr: OpenDrive) -> list[BoundAgent]:
    """Vehicles whose moves through a junction end on one road, in one direction, get there one after the
    other: a later one drives no faster than those before it, unless it is aggressive. A player whose drivers
    do not follow (esmini) would otherwise play a rear-end crash far beyond the junction, long after both did
    their moves."""
    onto: dict[tuple[int, str, bool], list[BoundAgent]] = {}
    for agent in agents:
        if agent.start is not None and len(agent.route) >= 2 and agent.type != "pedestrian" and \
                agent.road_type == "driving" and agent.speed_mps > 0:
            end = agent.route[-1]
            onto.setdefault((agent.stage, end.road, end.lane > 0), []).append(agent)
    capped: dict[str, float] = {}
    for group in onto.values():
        limit = None
        for agent in sorted(group, key=lambda a: (_reaches_junction_s(a, odr), a.name)):
            speed = agent.speed_mps
            if limit is not None and agent.behavior != "aggressive" and speed > limit:
                speed = capped[agent.name] = limit
            limit = speed if limit is None else min(limit, speed)
    return [a.model_copy(update={"speed_mps": capped[a.name]}) if a.name in capped else a for a in agents]


def _turn_key(agent: BoundAgent, agents: list[BoundAgent]) -> tuple[int, str, bool]:
    """Whose turn through the junction a vehicle shares: its road and direction's, and a vehicle in front
    of the ego in its lane the ego's (placed on a road further on, it would otherwise wait for its turn while
    the ego, behind it, drives into it)."""
    ego = next((a for a in agents if a.is_ego and a.start is not None), None)
    if ego is not None and agent.relative_to_ego == "front" and agent.stage == ego.stage == 0:
        agent = ego
    return agent.stage, agent.start.road, agent.start.lane > 0


def _turns(agents: list[BoundAgent], stage: int, odr: OpenDrive) -> dict[tuple[int, str, bool], float]:
    windows: dict[tuple[int, str, bool], list[float]] = {}
    first = None  # the ego's road goes first in its stage
    for agent in agents:
        if agent.stage != stage or agent.start is None or len(agent.route) < 2 or agent.speed_mps <= 0 or \
                (agent.trigger is not None and not agent.is_ego):  # a trigger times its agent itself
            continue
        via = agent.route[1]
        road = odr.roads[via.road]
        entry = road.lane_point(0.0 if via.lane < 0 else road.length, via.lane)
        here = odr.roads[agent.start.road].lane_point(agent.start.s, agent.start.lane)
        arrive = max(0.0, math.hypot(entry.x - here.x, entry.y - here.y) - agent.length / 2) / agent.speed_mps
        leave = arrive + (road.length + agent.length + 2.0) / agent.speed_mps
        if agent.is_ego:  # it stops for whoever crosses its way first
            leave += sum(a.ego_yield.hold_s for a in agents if a.ego_yield is not None and a.stage == stage)
        key = _turn_key(agent, agents)
        window = windows.setdefault(key, [arrive, leave])
        window[0], window[1] = min(window[0], arrive), max(window[1], leave)
        if agent.is_ego:
            first = key
    later_turn = _egos_later_turn(agents, stage, odr)
    if later_turn is not None:  # the ego stood until now and turns: its road goes first in this stage too
        key, window = later_turn
        windows[key], first = window, key
    delays: dict[tuple[int, str, bool], float] = {}
    taken: list[tuple[float, float]] = []
    for key in sorted(windows, key=lambda k: (k != first, windows[k][0], k)):
        arrive, leave = windows[key]
        delay = 0.0
        for start, end in sorted(taken):
            if arrive + delay < end + JUNCTION_GAP_S and leave + delay > start - JUNCTION_GAP_S:
                delay = end + JUNCTION_GAP_S - arrive
        delays[key] = round(delay, 2)
        taken.append((arrive + delay, leave + delay))
    return delays


SETTING_OFF_MPS2 = 2.0  # a standing ego's pull-away, for how long it holds the junction (a low estimate)


def _egos_later_turn(agents: list[BoundAgent], stage: int, odr: OpenDrive):
    """(turn key, [arrive, leave]) of an ego that stood until `stage` and turns in it: 'once it turns green we
    turn left while an oncoming van goes straight'. The van enters with the stage; with no turn taken, both
    were in the junction at once (a crash in esmini)."""
    ego = next((a for a in agents if a.is_ego), None)
    step = next((x for x in ego.later if x.stage == stage), None) if ego is not None else None
    if stage == 0 or step is None or step.action not in V.TURN_ACTIONS or ego.start is None or \
            len(ego.route) < 2 or ego.action != "stop" or any(x.action != "stop" for x in ego.later if x.stage < stage):
        return None
    speed = step.speed_mps or ego.speed_mps
    if speed <= 0:
        return None
    via = odr.roads[ego.route[1].road]
    entry = via.lane_point(0.0 if ego.route[1].lane < 0 else via.length, ego.route[1].lane)
    here = odr.roads[ego.start.road].lane_point(ego.start.s, ego.start.lane)
    way = math.hypot(entry.x - here.x, entry.y - here.y) + via.length + ego.length + 2.0
    return (stage, ego.start.road, ego.start.lane > 0), [0.0, way / speed + speed / SETTING_OFF_MPS2]


def no_faster_than_the_one_ahead(agents: list[BoundAgent]) -> list[BoundAgent]:
    """In one lane, a vehicle drives no faster than the one ahead of it, unless it is aggressive (its
    collisions are asked for) or the one ahead leaves the lane or stops on purpose: a player whose drivers
    do not follow (esmini) would otherwise play a rear-end crash no scene asked for."""
    lanes: dict[tuple[str, int], list[BoundAgent]] = {}
    for agent in agents:
        if agent.stage == 0 and agent.start is not None and agent.type not in ("pedestrian",) and \
                agent.road_type == "driving":
            lanes.setdefault((agent.start.road, agent.start.lane), []).append(agent)
    capped: dict[str, float] = {}
    for (_, lane), queue in lanes.items():
        queue.sort(key=lambda a: -a.start.s if lane < 0 else a.start.s)  # the front first
        limit = None
        for agent in queue:
            speed = agent.speed_mps
            if limit is not None and agent.behavior != "aggressive" and speed > limit:
                speed = capped[agent.name] = limit
            leaves = agent.lane_change is not None or agent.action in ("stop", "block_the_ego")
            limit = None if leaves else speed
    return [a.model_copy(update={"speed_mps": capped[a.name]}) if a.name in capped else a for a in agents]


WALKER_GAP_M = 2.0  # the least gap kept between two people walking one after the other on a sidewalk


def walkers_keep_their_gap(agents: list[BoundAgent]) -> list[BoundAgent]:
    """People walking one after the other along one sidewalk end their walk as far apart as they started, and
    none walks faster than the one ahead: where the road ends before a whole walk, every walk stops at its
    end, and the one behind would walk into the one ahead (a collision in both players)."""
    walks: dict[tuple[str, int, bool], list[BoundAgent]] = {}
    for agent in agents:
        if agent.walk_to is not None and agent.start is not None and agent.walk_to.road == agent.start.road:
            forward = agent.walk_to.s >= agent.start.s
            walks.setdefault((agent.start.road, agent.start.lane, forward), []).append(agent)
    changed: dict[str, dict] = {}
    for (_, _, forward), line in walks.items():
        sign = 1.0 if forward else -1.0
        line.sort(key=lambda a: -sign * a.start.s)  # the front first
        for ahead, agent in zip(line, line[1:]):
            ahead_end = changed.get(ahead.name, {}).get("walk_to", ahead.walk_to).s
            ahead_speed = changed.get(ahead.name, {}).get("speed_mps", ahead.speed_mps)
            gap = max(sign * (ahead.start.s - agent.start.s), WALKER_GAP_M)
            update = {}
            if sign * (ahead_end - agent.walk_to.s) < gap:
                update["walk_to"] = agent.walk_to.model_copy(update={"s": round(ahead_end - sign * gap, 3)})
            if agent.speed_mps > ahead_speed:
                update["speed_mps"] = ahead_speed
            if update:
                changed[agent.name] = update
    return [a.model_copy(update=changed[a.name]) if a.name in changed else a for a in agents]


def let_the_traffic_pass(agents: list[BoundAgent], odr: OpenDrive) -> list[BoundAgent]:
    """A walker or rider told to cross with no trigger of its own steps out once the vehicles that would pass
    its crossing while it is on the road have gone by (the ego first of all): nothing in a file makes a driver
    brake for it, and esmini's drivers do not (a crossing that asks for danger says so with a trigger:
    `when ego within 20m`)."""
    passing = [(a, _way(a, odr)) for a in agents if a.stage == 0 and a.start is not None and a.speed_mps > 0
               and a.cross_to is None and a.type != "pedestrian" and (a.trigger is None or a.is_ego)]
    out = []
    for agent in agents:
        if agent.cross_to is None or agent.trigger is not None or agent.stage != 0 or agent.speed_mps <= 0:
            out.append(agent)
            continue
        start = odr.roads[agent.start.road].lane_point(agent.start.s, agent.start.lane)
        end = odr.roads[agent.cross_to.road].lane_point(agent.cross_to.s, agent.cross_to.lane)
        crossing = math.hypot(end.x - start.x, end.y - start.y) / agent.speed_mps
        windows = []
        for vehicle, way in passing:
            at = _first_crossing(way, (start.x, start.y), (end.x, end.y))
            if at is not None:
                reach = vehicle.length / 2 + agent.width
                windows.append((vehicle.start_delay_s + (at - reach) / vehicle.speed_mps,
                                vehicle.start_delay_s + (at + reach) / vehicle.speed_mps))
        delay = agent.start_delay_s
        for passes, gone in sorted(windows):
            if delay < gone + JUNCTION_GAP_S and delay + crossing > passes - JUNCTION_GAP_S:
                delay = gone + JUNCTION_GAP_S
        out.append(agent.model_copy(update={"start_delay_s": round(delay, 2)}) if delay != agent.start_delay_s
                   else agent)
    return out


WAY_ON_M = 150.0  # how far a vehicle's way is followed past its last waypoint (or its road's end)


def _way(agent: BoundAgent, odr: OpenDrive) -> list[tuple[float, float]]:
    """Where a vehicle drives, as a polyline: through its route's waypoints, else along its lane to the end of
    its road; then straight on for WAY_ON_M."""
    if len(agent.route) >= 2:
        poses = [odr.roads[p.road].lane_point(p.s, p.lane) for p in (agent.start, *agent.route[1:])]
    else:
        road = odr.roads[agent.start.road]
        ahead = road.length - agent.start.s if agent.start.lane < 0 else agent.start.s
        steps = max(1, int(ahead // 5.0))
        direction = 1 if agent.start.lane < 0 else -1
        poses = [road.lane_point(min(max(agent.start.s + direction * ahead * k / steps, 0.0), road.length),
                                 agent.start.lane) for k in range(steps + 1)]
    last = poses[-1]
    return [(p.x, p.y) for p in poses] + [(last.x + WAY_ON_M * math.cos(last.hdg),
                                           last.y + WAY_ON_M * math.sin(last.hdg))]


def _first_crossing(way: list[tuple[float, float]], a: tuple[float, float], b: tuple[float, float]) -> float | None:
    """How far along the polyline it first meets the segment a-b, None when it never does."""
    travelled = 0.0
    for (px, py), (qx, qy) in zip(way, way[1:]):
        rx, ry, sx, sy = qx - px, qy - py, b[0] - a[0], b[1] - a[1]
        denominator = rx * sy - ry * sx
        if abs(denominator) > 1e-9:
            u = ((a[0] - px) * sy - (a[1] - py) * sx) / denominator
            v = ((a[0] - px) * ry - (a[1] - py) * rx) / denominator
            if 0.0 <= u <= 1.0 and 0.0 <= v <= 1.0:
                return travelled + u * math.hypot(rx, ry)
        travelled += math.hypot(rx, ry)
    return None


def distance_between(odr: OpenDrive, a: LanePos, b: LanePos) -> float:
    pa, pb = odr.roads[a.road].lane_point(a.s, a.lane), odr.roads[b.road].lane_point(b.s, b.lane)
    return math.hypot(pa.x - pb.x, pa.y - pb.y)


YIELD_DECEL = {"cautious": 3.0, "normal": 3.5, "aggressive": 4.0}  # m/s², the ego's comfortable stop
HARDEST_YIELD_DECEL = 4.5  # m/s², a firm stop (a SUMO car's own limit): stepping out later, the ego drives on
YIELD_MARGIN_M = 2.0  # between the ego's front and the crosser's path when it has stopped
YIELD_SET_OFF_MPS2 = 2.5  # how briskly the ego gets back to its speed once the crossing is clear
LATER_CROSSER_LEAD_M = 10.0  # a later crosser enters this much beyond where the ego starts braking for it
SET_OFF_M = 0.1  # how far a crosser has moved when the ego takes it as crossing


def ego_yields(agents: list[BoundAgent], odr: OpenDrive, timed_by_trigger: bool) -> list[BoundAgent]:
    """The ego stops short of a person or rider who crosses its way and is not aggressive (an aggressive one
    runs out: the collision is asked for), when it would reach the crossing while the crosser is on it, and
    the file says so (EgoYield), so that every player brakes the same. A crosser that steps out once the ego
    has passed (let_the_traffic_pass) or is done before the ego comes gets none. The brake is the ego's
    comfortable rate, firmer when the crosser steps out late (`when ego within 15m`), up to a firm stop; one
    who steps out so late that a firm stop would still end on the crossing is passed (stopping there would
    stand the ego in its way). The brake starts where its rate stops the ego YIELD_MARGIN_M short of the
    crosser's path.
    timed_by_trigger: the crossers whose start a trigger or a later stage sets (before junction turns are
    taken, which then wait for the ego), else the rest (timed by let_the_traffic_pass)."""
    ego = next((a for a in agents if a.is_ego), None)
    if ego is None or ego.start is None or ego.speed_mps <= 0 or ego.action == "stop":
        return agents
    way = _way(ego, odr)
    return [_with_yield(agent, ego, way, odr) if agent.cross_to is not None and agent.start is not None
            and agent.behavior != "aggressive" and agent.speed_mps > 0
            and (agent.trigger is not None or agent.stage > 0) == timed_by_trigger else agent for agent in agents]


def _with_yield(agent: BoundAgent, ego: BoundAgent, way: list[tuple[float, float]], odr: OpenDrive) -> BoundAgent:
    road = odr.roads[agent.start.road]
    start, end = road.lane_point(agent.start.s, agent.start.lane), road.lane_point(agent.cross_to.s,
                                                                                 agent.cross_to.lane)
    at = _first_crossing(way, (start.x, start.y), (end.x, end.y))
    if ego.start.road == road.id:  # in the lane it changes into, if it does (left: towards the centre line)
        lane = ego.start.lane - (1 if ego.start.lane > 0 else -1) * (ego.lane_change or 0)
    else:
        lane = next((p.lane for p in ego.route if p.road == road.id), None)
    if at is None or lane is None:  # it crosses no road the ego drives on
        return agent
    v = ego.speed_mps
    stop_line = at - ego.length / 2 - agent.width / 2 - YIELD_MARGIN_M  # where the ego's centre stops
    crossing_m = math.hypot(end.x - start.x, end.y - start.y)
    crossing_s = crossing_m / agent.speed_mps
    setting_off = _ego_when_crosser_sets_off(agent, ego, way, start)
    room = math.inf
    if setting_off is not None:
        if setting_off >= stop_line or (stop_line - setting_off) / v > crossing_s + 1.0:
            return agent  # the ego is past it, or comes once the crosser is done
        room = stop_line - setting_off - v * SET_OFF_M / agent.speed_mps
    needed = v * v / (2 * max(room, 0.1))
    if needed > HARDEST_YIELD_DECEL:
        return agent  # too close to stop: it keeps going, and is by before the crosser reaches its lane
    rate = max(YIELD_DECEL[ego.behavior], needed)
    braking = v * v / (2 * rate)
    # a ball around a point of the ego's lane, from where braking starts to just past the stop line
    direction = 1 if lane < 0 else -1
    s_cross = agent.start.s
    centre_along = stop_line + 0.5 - (braking + 1.0) / 2
    s_centre = min(max(s_cross - direction * (at - centre_along), 0.0), road.length)
    centre_along = at - abs(s_cross - s_centre)
    radius = stop_line + 0.5 - centre_along
    if radius <= 0.5:  # the stop line is off the road it crosses (inside the junction): no lane to hold it
        return agent
    if 2 * radius - 0.5 < braking:  # the ball was cut at the road's start: less room, a harder brake
        rate = v * v / (2 * (2 * radius - 0.5))
        if rate > HARDEST_YIELD_DECEL:
            return agent
    centre = LanePos(road=road.id, lane=lane, s=round(s_centre, 3))
    arrives = at / v  # where it would have been, had it not stopped
    done = (setting_off / v + crossing_s) if setting_off is not None else arrives + crossing_s
    hold = max(0.0, done - arrives) + v / (2 * rate) + v / (2 * YIELD_SET_OFF_MPS2)
    return agent.model_copy(update={"ego_yield": EgoYield(centre=centre, radius_m=round(radius, 3),
                                                          rate_mps2=round(rate, 3),
                                                          crossing_m=round(crossing_m, 3), hold_s=round(hold, 2))})


def _ego_when_crosser_sets_off(agent: BoundAgent, ego: BoundAgent, way: list[tuple[float, float]],
                               start) -> float | None:
    """How far along its way the ego is when the crosser steps out (at its own speed from its start); None
    when that depends on more than the binding knows (a later stage, a trigger on another agent)."""
    if agent.stage != 0:
        return None
    trigger = agent.trigger
    after = (trigger.after_s or 0.0) if trigger is not None else 0.0
    if trigger is not None and trigger.within_m is not None:
        if trigger.of != ego.name:
            return None
        reached = _first_within(way, (start.x, start.y), float(trigger.within_m))
        if reached is None:
            return math.inf  # the ego never comes near: it never sets off
        return reached + ego.speed_mps * float(after)
    return ego.speed_mps * max(0.0, float(after) + agent.start_delay_s - ego.start_delay_s)


def _first_within(way: list[tuple[float, float]], point: tuple[float, float], radius: float) -> float | None:
    """How far along the polyline it first comes within radius of the point (0.25 m steps)."""
    travelled = 0.0
    for (px, py), (qx, qy) in zip(way, way[1:]):
        length = math.hypot(qx - px, qy - py)
        steps = max(1, math.ceil(length / 0.25))
        for k in range(steps + 1):
            x, y = px + (qx - px) * k / steps, py + (qy - py) * k / steps
            if math.hypot(x - point[0], y - point[1]) < radius:
                return travelled + length * k / steps
        travelled += length
    return None
