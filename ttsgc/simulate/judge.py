"""Did every agent do what the file says? Plan intents + a player's Trace -> a Verdict; several verdicts -> a Report.

The judge knows no player: it reads what the file declares (ttsgc:* Properties, see ttsgc.intent) and the
evidence of one trace. What each agent must do follows from its declared action (a turn_left must go left);
properties that contradict each other are an error of the file, named. Collisions and closeness use the exact
distance between the bodies' oriented boxes; a collision is asked for only when the scene asks for danger (an
aggressive agent, block_the_ego, a cut-in) and only for a collision that agent is in. Every list comes out in a
fixed order, so a report is the same from run to run.
"""

from __future__ import annotations

import dataclasses
import math
from collections import defaultdict

from pydantic import BaseModel

from ttsgc import intent as I
from ttsgc.roads.opendrive import OpenDrive
from ttsgc.simulate.general_verdict import (NO_INTENTS, NONE_DECLARED, declares_intents, entity_result,
                                             file_failures)
from ttsgc.simulate.plan import Plan
from ttsgc.simulate.trace import Body, Sample, Trace

STOPPED_MPS = 0.1
STOPPED_FOR_S = 1.0
TURN_MIN_DEG = 30.0
SETTLE_S = 1.0  # how long after reaching its target road a turning body's heading is read
GRID_M = 10.0  # cell size of the collision broad phase: larger than any body's half diagonal plus its step
# events that are not the agent's own action
SETUP_EVENTS = ("_enters", "_route", "_appears", "_leaves", "_arrives", "_sets_off", "_draws_level")


class AgentResult(BaseModel):
    name: str
    type: str
    action: str
    achieved: bool
    reason: str


class CollisionResult(BaseModel):
    a: str
    b: str
    time_s: float
    x: float
    y: float
    road: str
    asked_for: bool  # one of the two is an agent whose declared action or behaviour seeks danger


class Verdict(BaseModel):
    """One player's evidence judged."""

    player: str
    ok: bool
    agents: list[AgentResult]
    collisions: list[CollisionResult]
    min_distance_to_ego: float | None
    min_distance_agent: str | None
    min_ttc_to_ego: float | None
    min_ttc_agent: str | None
    problems: list[str]
    simulated_s: float


class Report(BaseModel):
    """Every player's verdict on one file. ok: no contradiction in the file, and every player that ran agrees
    that every agent did its action with no collision the scene did not ask for."""

    ok: bool
    scenario: str
    map: str
    verdicts: list[Verdict]
    not_run: list[str]  # players that could not be run here, with why
    contradictions: list[str]  # properties of the file that say different things
    unsupported: list[str]
    intents_declared: bool = True  # False: a file not written by ttsgc, judged on what every scene must do
    notes: list[str] = []  # what the file does that the standard does not, read as esmini reads it

    @property
    def agents(self) -> list[AgentResult]:
        """Per agent, achieved only when every player says so; the reasons of those that disagree."""
        if not self.verdicts:
            return []
        merged = []
        for k, first in enumerate(self.verdicts[0].agents):
            results = [v.agents[k] for v in self.verdicts]
            achieved = all(r.achieved for r in results)
            shown = results if len(results) == 1 else [r for r in results if r.achieved == achieved] or results
            reason = "; ".join(r.reason if len(self.verdicts) == 1 else f"{v.player}: {r.reason}"
                               for v, r in zip(self.verdicts, results) if r in shown)
            merged.append(first.model_copy(update={"achieved": achieved, "reason": reason}))
        return merged

    @property
    def collisions(self) -> list[CollisionResult]:
        return [c for v in self.verdicts for c in v.collisions]

    @property
    def problems(self) -> list[str]:
        return [f"{v.player}: {p}" for v in self.verdicts for p in v.problems] + self.contradictions

    @property
    def simulated_s(self) -> float:
        return max((v.simulated_s for v in self.verdicts), default=0.0)

    @property
    def players(self) -> list[str]:
        return [v.player for v in self.verdicts]

    def table(self) -> str:
        names = [a.name for a in self.verdicts[0].agents] if self.verdicts else []
        width = max([len(n) for n in names] + [5])
        actions = [a.action for a in self.verdicts[0].agents] if self.verdicts else []
        action = max([len(a) for a in actions] + [6])
        lines = [] if self.intents_declared else [NO_INTENTS, ""]
        for problem in self.contradictions:
            lines.append(f"error in the file: {problem}")
        head = f"{'agent'.ljust(width)}  {'action'.ljust(action)}  " + "  ".join(v.player for v in self.verdicts)
        lines += [head, "-" * max(len(head), width + action + 30)]
        for k, name in enumerate(names):
            marks = "  ".join(("✓" if v.agents[k].achieved else "✗").ljust(len(v.player)) for v in self.verdicts)
            reasons = " | ".join(f"{v.player}: {v.agents[k].reason}" if len(self.verdicts) > 1 else v.agents[k].reason
                                 for v in self.verdicts)
            lines.append(f"{name.ljust(width)}  {actions[k].ljust(action)}  {marks}  {reasons}")
        for v in self.verdicts:
            tag = f"{v.player}: " if len(self.verdicts) > 1 else ""
            for c in v.collisions:
                lines.append(f"{tag}collision: {c.a} and {c.b} at t={c.time_s:.1f} s, road {c.road or '?'} "
                             f"({c.x:.1f}, {c.y:.1f}){' (the scene asks for it)' if c.asked_for else ''}")
            if not v.collisions:
                lines.append(f"{tag}collisions: none")
            if v.min_distance_to_ego is not None:
                lines.append(f"{tag}closest to the ego: {v.min_distance_to_ego:.1f} m ({v.min_distance_agent})")
            if v.min_ttc_to_ego is not None:
                lines.append(f"{tag}least time to collision with the ego: {v.min_ttc_to_ego:.1f} s "
                             f"({v.min_ttc_agent})")
            for item in v.problems:
                lines.append(f"{tag}problem: {item}")
        for item in self.notes:
            lines.append(f"note: {item}")
        for item in self.unsupported:
            lines.append(f"not read from the file: {item}")
        for item in self.not_run:
            lines.append(f"not run: {item}")
        for v in self.verdicts:
            done = "agents did what they were told" if self.intents_declared else \
                "entities entered the road and stayed on it (no intents declared)"
            lines.append(f"{v.player}: {'OK' if v.ok else 'FAILED'}: {sum(a.achieved for a in v.agents)}/"
                         f"{len(v.agents)} {done}, {v.simulated_s:.1f} s played")
        lines.append("OK" if self.ok else "FAILED")
        return "\n".join(lines)


def report(plan: Plan, verdicts: list[Verdict], not_run: list[str] | None = None) -> Report:
    wrong = contradictions(plan)
    ok = bool(verdicts) and all(v.ok for v in verdicts) and not wrong
    return Report(ok=ok, scenario=str(plan.xosc), map=str(plan.xodr), verdicts=verdicts, not_run=not_run or [],
                  contradictions=wrong, unsupported=list(plan.unsupported), intents_declared=declares_intents(plan),
                  notes=list(plan.notes))


def contradictions(plan: Plan) -> list[str]:
    return [f"entity '{name}': {p}" for name, e in plan.entities.items() for p in I.contradictions(e.intent)]


# -- geometry -------------------------------------------------------------------------------------------------

def _wrap_deg(angle: float) -> float:
    return math.degrees(math.atan2(math.sin(angle), math.cos(angle)))


def corners(s: Sample, body: Body) -> list[tuple[float, float]]:
    c, n = math.cos(s.h), math.sin(s.h)
    half_l, half_w = body.length / 2, body.width / 2
    return [(s.x + c * dl - n * dw, s.y + n * dl + c * dw)
            for dl, dw in ((half_l, half_w), (half_l, -half_w), (-half_l, -half_w), (-half_l, half_w))]


def _overlap(a: list, b: list) -> bool:
    """Separating-axis test of two convex quadrilaterals."""
    for poly in (a, b):
        for (x1, y1), (x2, y2) in zip(poly, poly[1:] + poly[:1]):
            ax, ay = y1 - y2, x2 - x1
            pa = [x * ax + y * ay for x, y in a]
            pb = [x * ax + y * ay for x, y in b]
            if max(pa) < min(pb) or max(pb) < min(pa):
                return False
    return True


def _point_segment(p, a, b) -> float:
    dx, dy = b[0] - a[0], b[1] - a[1]
    seg = dx * dx + dy * dy
    f = 0.0 if seg == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / seg))
    return math.hypot(p[0] - a[0] - f * dx, p[1] - a[1] - f * dy)


def box_distance(a: Sample, body_a: Body, b: Sample, body_b: Body) -> float:
    """The exact free distance between two oriented boxes (0 when they touch or overlap)."""
    ca, cb = corners(a, body_a), corners(b, body_b)
    if _overlap(ca, cb):
        return 0.0
    return min(min(_point_segment(p, q1, q2) for p in ca for q1, q2 in zip(cb, cb[1:] + cb[:1])),
               min(_point_segment(p, q1, q2) for p in cb for q1, q2 in zip(ca, ca[1:] + ca[:1])))


def _lateral(odr: OpenDrive, road: str, x: float, y: float) -> tuple[float, float]:
    """(s, t) of a point relative to a road's reference line, by sampling the line every 0.5 m."""
    r = odr.roads[road]
    best = (math.inf, 0.0, 0.0)
    steps = max(2, int(r.length * 2))
    for k in range(steps + 1):
        s = r.length * k / steps
        p = r.pose(s)
        dx, dy = x - p.x, y - p.y
        d = dx * dx + dy * dy
        if d < best[0]:
            best = (d, s, -dx * math.sin(p.hdg) + dy * math.cos(p.hdg))
    return best[1], best[2]


# -- the verdict ----------------------------------------------------------------------------------------------

def ego_of(plan: Plan) -> str | None:
    return next((n for n, e in plan.entities.items() if e.intent.get(I.IS_EGO) == "true"), None)


def seeks_danger(plan: Plan, name: str) -> bool:
    """The scene asks this agent for danger: aggressive, blocking the ego, or cutting in (a lane change by
    anyone but the ego)."""
    intent = plan.entities[name].intent
    action = intent.get(I.ACTION, "")
    return (intent.get(I.BEHAVIOR) == "aggressive" or action in I.DANGEROUS_ACTIONS
            or (action.startswith("change_lane") and intent.get(I.IS_EGO) != "true"))


def asked_for(plan: Plan, a: str, b: str) -> bool:
    """A collision the scene asks for: one of the two seeks danger."""
    return any(n in plan.entities and seeks_danger(plan, n) for n in (a, b))


def judge(plan: Plan, trace: Trace, odr: OpenDrive) -> Verdict:
    ego = ego_of(plan)
    bodies = {n: trace.bodies.get(n) or Body(e.length, e.width) for n, e in plan.entities.items()}
    intents = declares_intents(plan)
    if intents:
        results = [_check_agent(plan, trace, odr, name, ego, bodies) for name in plan.entities]
        if ego is not None:
            results += _check_later_ego_actions(plan, trace, ego, odr)
    else:  # a file not written by ttsgc: each entity is judged only on entering the road and staying on it
        results = [AgentResult(name=name, type=e.category, action=NONE_DECLARED, achieved=ok, reason=why)
                   for name, e in plan.entities.items() for ok, why in [entity_result(trace, name)]]
    overlaps = _spawn_overlaps(trace, bodies)
    for r in results:
        if r.name in overlaps and r.achieved:
            r.achieved, r.reason = False, f"appeared overlapping {overlaps[r.name]}"
    collisions = []
    for t, a, b, x, y, road in find_collisions(trace, bodies):
        collisions.append(CollisionResult(a=a, b=b, time_s=round(t, 3), x=round(x, 2), y=round(y, 2), road=road,
                                          asked_for=asked_for(plan, a, b)))
    distance, distance_agent, ttc, ttc_agent = criticality(trace, bodies, ego)
    problems = list(trace.problems)
    if not intents:
        problems += file_failures(plan, trace, odr)
    elif not trace.stopped_by_trigger:
        problems.append("the stop trigger never fired (the player's time limit ended the run)")
    ok = all(r.achieved for r in results) and all(c.asked_for for c in collisions) and not problems
    return Verdict(player=trace.player, ok=ok, agents=results, collisions=collisions,
                   min_distance_to_ego=distance, min_distance_agent=distance_agent, min_ttc_to_ego=ttc,
                   min_ttc_agent=ttc_agent, problems=problems, simulated_s=round(trace.end_time, 3))


def action_start(plan: Plan, trace: Trace, name: str) -> float | None:
    """When the agent's own action started: the first of its events that is more than entering or routing."""
    times = [trace.started[e.name] for act in plan.acts for e in act.events
             if e.actor == name and e.name in trace.started and not e.name.endswith(SETUP_EVENTS)]
    return min(times) if times else None


def _start_position(plan: Plan, name: str) -> tuple[str, int, float] | None:
    for action in plan.init.get(name, []):
        if action.kind == "teleport" and action.lane is not None:
            return action.lane
    for act in plan.acts:
        for event in act.events:
            for action in event.actions:
                if action.kind == "add" and action.entity == name and action.lane is not None:
                    return action.lane
    return None


def _check_agent(plan: Plan, trace: Trace, odr: OpenDrive, name: str, ego: str | None,
                 bodies: dict[str, Body]) -> AgentResult:
    entity = plan.entities[name]
    action = entity.intent.get(I.ACTION, "")
    result = lambda ok, why: AgentResult(name=name, type=entity.intent.get(I.TYPE, entity.category),  # noqa: E731
                                         action=action or "(none)", achieved=ok, reason=why)
    samples = trace.samples.get(name, [])
    if not samples:
        return result(False, "never appeared in the scene")
    if not action:
        return result(True, "no intent recorded in the file (nothing to check)")
    wrong = I.contradictions(entity.intent)
    if wrong:
        return result(False, "the file contradicts itself: " + "; ".join(wrong))
    start = action_start(plan, trace, name)
    if start is None:
        return result(False, "its action never started: the trigger never fired")
    after = [s for s in samples if s.t >= start - 1e-9]
    if not after:
        return result(False, f"left the scene before its action started at t={start:.1f} s")
    movement = entity.intent.get(I.MOVEMENT, "")
    expected = I.MOVEMENT_OF_ACTION.get(action)
    if movement and expected:  # its route is its action: read from where it appeared
        return result(*_movement(samples, expected, entity.intent.get(I.TARGET_ROAD, ""), odr))
    if action in ("turn_left", "turn_right"):
        return result(False, "was given no junction to turn at (its road does not lead to one)")
    if action == "go_straight":
        travelled = sum(math.hypot(b.x - a.x, b.y - a.y) for a, b in zip(after, after[1:]))
        return result(travelled >= 5.0, f"drove {travelled:.0f} m" + ("" if travelled >= 5 else ", too little"))
    if action in ("change_lane_to_left", "change_lane_to_right"):
        placed = _start_position(plan, name)
        if placed is not None and after[0] is samples[0]:
            # a change that starts with the scene: a player (esmini) reports the lane it changes to from its
            # first sample on, so the lane it was placed on is where the change begins
            after = [dataclasses.replace(samples[0], road=placed[0], lane=placed[1])] + after
        return result(*_lane_change(after, 1 if action.endswith("left") else -1))
    if action == "stop":
        return result(*_stopped(after))
    if action == "block_the_ego":
        standing = [trail[-1] for other, trail in trace.samples.items()
                    if other not in (name, ego) and trail and trail[-1].speed < STOPPED_MPS]
        return result(*_blocked(after, trace.samples.get(ego, []) if ego else [], bodies.get(ego), bodies[name],
                                standing))
    position = _start_position(plan, name)
    road = position[0] if position else samples[0].road
    if action in ("cross_the_road", "on_the_sidewalk") and road not in odr.roads:
        return result(False, "its road could not be told")
    if action == "cross_the_road":
        return result(*_crossed(odr, road, samples[0], after))
    if action == "on_the_sidewalk":
        return result(*_walked_on_sidewalk(odr, road, position, samples[0], after))
    return result(False, f"no check for action '{action}'")


LATER_CHECKS = ("go_straight", "stop", "change_lane_to_left", "change_lane_to_right", "turn_left", "turn_right")


def _check_later_ego_actions(plan: Plan, trace: Trace, ego: str, odr: OpenDrive | None = None) -> list[AgentResult]:
    """One row per later stage the ego acts in ('ego (stage 2)', stages counted from 1), judged from the start
    of that stage's ego event."""
    entity = plan.entities[ego]
    samples = trace.samples.get(ego, [])
    out = []
    for stage, action in I.parse_stage_actions(entity.intent.get(I.STAGE_ACTIONS, "")):
        result = lambda ok, why: AgentResult(name=f"{ego} (stage {stage + 1})",  # noqa: E731
                                             type=entity.intent.get(I.TYPE, entity.category), action=action,
                                             achieved=ok, reason=why)
        start = trace.started.get(I.later_event_name(ego, stage, action))
        after = [s for s in samples if start is not None and s.t >= start - 1e-9]
        if action not in LATER_CHECKS:
            out.append(result(False, f"no check for a later action '{action}' of the ego"))
        elif start is None:
            out.append(result(False, "its action in this stage never started: the stage or its trigger never came"))
        elif not after:
            out.append(result(False, f"left the scene before its action started at t={start:.1f} s"))
        elif action in ("turn_left", "turn_right"):
            target = entity.intent.get(I.TARGET_ROAD, "")
            if not target:
                out.append(result(False, "was given no junction to turn at (its road does not lead to one)"))
            else:
                out.append(result(*_movement(after, I.MOVEMENT_OF_ACTION[action], target, odr)))
        elif action == "go_straight":
            travelled = sum(math.hypot(b.x - a.x, b.y - a.y) for a, b in zip(after, after[1:]))
            out.append(result(travelled >= 5.0, f"drove {travelled:.0f} m from t={start:.1f} s"
                              + ("" if travelled >= 5 else ", too little")))
        elif action == "stop":
            out.append(result(*_stopped(after)))
        else:
            ok, why = _lane_change(after, 1 if action.endswith("left") else -1)
            out.append(result(ok, f"{why} from t={start:.1f} s"))
    return out


SHORT_ROAD_M = 10.0  # a road this short may lie between two samples of a fast body


def _movement(after: list[Sample], movement: str, target: str, odr: OpenDrive | None = None) -> tuple[bool, str]:
    roads = [s.road for s in after if s.road]
    start_road = roads[0] if roads else ""
    reached = next((i for i, s in enumerate(after) if s.road == target and s.road != start_road), None)
    if reached is None and odr is not None and target in odr.roads and odr.roads[target].length < SHORT_ROAD_M \
            and target != start_road:
        reached = _passed_over(odr, target, after)
    if reached is None:
        beyond = [r for r in dict.fromkeys(roads) if r != start_road]
        where = f"ended on road {beyond[-1]}" if beyond else f"stayed on road {start_road or '?'}"
        return False, f"{where}, not on road {target} where a {movement} movement leads"
    settled = next((s for s in after[reached:] if s.t >= after[reached].t + SETTLE_S), after[-1])
    change = _wrap_deg(settled.h - after[0].h)
    went = "left" if change >= TURN_MIN_DEG else "right" if change <= -TURN_MIN_DEG else "straight"
    return went == movement, f"went {went} onto road {target} (heading {change:+.0f}°)"


def _passed_over(odr: OpenDrive, road: str, after: list[Sample]) -> int | None:
    """The first sample past the middle of a short road the body crossed between two samples (a player that
    samples every 0.1 s reports no sample on a 1.5 m road passed at 19 m/s), None when it never did."""
    middle = odr.roads[road].length / 2
    previous = None
    for i, sample in enumerate(after):
        s, t = _lateral(odr, road, sample.x, sample.y)
        if previous is not None and abs(t) < 6.0 and abs(previous[1]) < 6.0 and \
                (previous[0] - middle) * (s - middle) <= 0 and previous[0] != s:
            return i
        previous = (s, t)
    return None


def _lane_change(after: list[Sample], direction: int) -> tuple[bool, str]:
    """Net lanes moved to the left: on either side of a road the lane nearer the centre line is to the left
    of the driving direction, so a move to the left lowers |lane id|."""
    net = most = 0  # most: the furthest it got the named way (a lane section further on may renumber lanes)
    known = [s for s in after if s.road and s.lane]  # a sample with no lane (a player's link between two pieces
    # of one road) does not break the count: the lanes before and after it are compared
    for a, b in zip(known, known[1:]):
        if a.road == b.road and (a.lane > 0) == (b.lane > 0):
            net += abs(a.lane) - abs(b.lane)
            most = max(most, net * direction)
    side = "left" if direction > 0 else "right"
    if most >= 1:
        return True, f"changed {most} lane(s) to the {side}"
    return False, f"did not change to the {side} (net lane change {net:+d})"


def _standstill(after: list[Sample]) -> float | None:
    """When the body first stood still for STOPPED_FOR_S."""
    since = None
    for s in after:
        if s.speed < STOPPED_MPS:
            since = s.t if since is None else since
            if s.t - since >= STOPPED_FOR_S - 1e-9:
                return since
        else:
            since = None
    return None


def _stopped(after: list[Sample]) -> tuple[bool, str]:
    since = _standstill(after)
    if since is not None:
        return True, f"came to a standstill by t={since:.1f} s"
    return False, f"never stood still (slowest {min(s.speed for s in after):.1f} m/s)"


def _blocked(after: list[Sample], ego: list[Sample], ego_body: Body | None, body: Body,
             standing: list[Sample] = ()) -> tuple[bool, str]:
    """Ahead of the ego when its action started, it came to stand on the ego's path: the ego then stopped
    behind it, came up behind it and went round it, or (a player whose ego does not brake) ran into it or
    through its place, or it stands at the
    head of a queue the ego stopped behind ("boxed in": the ego stops behind the nearest blocker, the others
    stand on beyond it). `standing`: the last samples of the other bodies that ended standing."""
    since = _standstill(after)
    if since is None:
        return False, f"never stood still (slowest {min(s.speed for s in after):.1f} m/s)"
    stop = next(s for s in after if s.t >= since)
    ego_after = [e for e in ego if e.t >= after[0].t - 1e-9]
    if not ego_after:
        return False, "stopped, but the ego was not in the scene"
    first = ego_after[0]
    if _in_frame_of(first, after[0])[0] <= 0:
        return False, "was not ahead of the ego when its action started"
    reach = (ego_body.length if ego_body else 4.5) / 2 + body.length / 2
    held_up = max(40.0, HELD_UP_S * first.speed)
    on_path = []
    for e in ego_after:
        ahead, side = _in_frame_of(e, stop)
        if abs(side) < 2.0 and (-reach < ahead < reach or (e.t >= since and 0 < ahead < held_up)):
            on_path.append(e)
    if not on_path and _heads_a_queue(stop, ego_after[-1], standing):
        return True, "stopped in the ego's path, beyond another that stands in it"
    if not on_path:
        return False, "stopped, but never in front of the ego"
    initial, slowest = first.speed, min(e.speed for e in on_path)
    return True, f"stopped in the ego's path (the ego went from {initial:.1f} to {slowest:.1f} m/s there)"


HELD_UP_S = 3.0  # a body standing this many seconds ahead of the ego in its lane, at the speed the ego had when
# the body's action began, holds it up (40 m at least): an ego going round it pulls out some 2 s before it
# would reach it, and may have braked a little first


QUEUE_REACH_M = 150.0  # how far down the ego's line a blocker beyond others may stand and still block it


def _heads_a_queue(stop: Sample, ego: Sample, standing: list[Sample]) -> bool:
    """Whether `stop` lies in line ahead of the standing ego, within QUEUE_REACH_M, with another standing body
    in line between them (the one the ego stopped behind): the bodies a blocker ran on past during its pull-in
    (some 60 m at motorway speed) are no gap the ego could use."""
    ahead, side = _in_frame_of(ego, stop)
    if ego.speed >= STOPPED_MPS or not 0 < ahead < QUEUE_REACH_M or abs(side) >= 2.0:
        return False
    return any(0 < a < ahead and abs(b) < 2.0 for a, b in (_in_frame_of(ego, s) for s in standing))


def _in_frame_of(viewer: Sample, seen: Sample) -> tuple[float, float]:
    """Where `seen` is from `viewer`: metres ahead along its heading, and to its left."""
    dx, dy = seen.x - viewer.x, seen.y - viewer.y
    c, n = math.cos(viewer.h), math.sin(viewer.h)
    return dx * c + dy * n, -dx * n + dy * c


def _crossed(odr: OpenDrive, road: str, first: Sample, after: list[Sample]) -> tuple[bool, str]:
    _, t0 = _lateral(odr, road, first.x, first.y)
    _, t1 = _lateral(odr, road, after[-1].x, after[-1].y)
    sides = lambda t: "left" if t > 0 else "right"  # noqa: E731
    if t0 * t1 < 0 and abs(t1) > 0.5:
        return True, f"crossed road {road} from its {sides(t0)} side to its {sides(t1)} side"
    return False, f"stayed on the {sides(t0)} side of road {road} (t {t0:+.1f} -> {t1:+.1f} m)"


def _walked_on_sidewalk(odr: OpenDrive, road: str, position, first: Sample, after: list[Sample]) -> tuple[bool, str]:
    if position is not None:
        r = odr.roads[road]
        lane = r.section_at(min(max(position[2], 0.0), r.length)).lanes.get(position[1])
        if lane is None or lane.type != "sidewalk":
            return False, f"stands on road {road} lane {position[1]}, a {lane.type if lane else 'missing'} lane, " \
                          f"not a sidewalk"
    _, t0 = _lateral(odr, road, first.x, first.y)
    walked = math.hypot(after[-1].x - first.x, after[-1].y - first.y)
    drift = max(abs(_lateral(odr, road, s.x, s.y)[1] - t0) for s in after[:: 10] + [after[-1]])
    if walked >= 5.0 and drift < 1.5:
        return True, f"walked {walked:.0f} m along the sidewalk"
    return False, f"walked {walked:.0f} m, straying {drift:.1f} m off its sidewalk"


# -- bodies against each other --------------------------------------------------------------------------------

def _frames(trace: Trace) -> list[tuple[float, list[tuple[str, Sample]]]]:
    """The trace as time steps: (t, [(name, sample)] in name order)."""
    at: dict[float, list[tuple[str, Sample]]] = defaultdict(list)
    for name in sorted(trace.samples):
        for s in trace.samples[name]:
            at[round(s.t, 3)].append((name, s))
    return sorted(at.items())


def _near_pairs(frame: list[tuple[str, Sample]]):
    """Pairs of bodies in the same or neighbouring grid cells, each once, in name order: linear in the number
    of bodies when they are spread out, rather than every pair."""
    cells: dict[tuple[int, int], list[int]] = defaultdict(list)
    for k, (_, s) in enumerate(frame):
        cells[(math.floor(s.x / GRID_M), math.floor(s.y / GRID_M))].append(k)
    pairs = set()
    for (cx, cy), members in cells.items():
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for j in cells.get((cx + dx, cy + dy), ()):
                    for i in members:
                        if i < j:
                            pairs.add((i, j))
    return sorted(pairs)


def _reach(body: Body) -> float:
    """How far from its centre a box reaches, with a margin far above rounding."""
    return math.hypot(body.length, body.width) / 2 + 1e-6


def find_collisions(trace: Trace, bodies: dict[str, Body]):
    """(t, a, b, x, y, road) of each pair's first contact, in time then name order."""
    seen, found = set(), []
    for t, frame in _frames(trace):
        for i, j in _near_pairs(frame):
            (a, sa), (b, sb) = frame[i], frame[j]
            if (a, b) in seen or a not in bodies or b not in bodies:
                continue
            if math.hypot(sa.x - sb.x, sa.y - sb.y) > _reach(bodies[a]) + _reach(bodies[b]):
                continue  # farther apart than their half-diagonals: they cannot touch (the exact test is costly)
            if box_distance(sa, bodies[a], sb, bodies[b]) <= 0.0:
                seen.add((a, b))
                found.append((t, a, b, (sa.x + sb.x) / 2, (sa.y + sb.y) / 2, sa.road or sb.road))
    return found


def _spawn_overlaps(trace: Trace, bodies: dict[str, Body]) -> dict[str, str]:
    """Bodies that overlap another in the first sample either has (a scene that starts in a crash)."""
    out = {}
    firsts = {n: s[0] for n, s in sorted(trace.samples.items()) if s and n in bodies}
    positions = {n: {round(x.t, 3): x for x in trace.samples[n]} for n in firsts}
    names = sorted(firsts)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            t = max(firsts[a].t, firsts[b].t)
            sa, sb = positions[a].get(round(t, 3)), positions[b].get(round(t, 3))
            if sa is None or sb is None or math.hypot(sa.x - sb.x, sa.y - sb.y) > GRID_M * 2:
                continue
            if box_distance(sa, bodies[a], sb, bodies[b]) <= 0.0:
                out.setdefault(a, b)
                out.setdefault(b, a)
    return out


def criticality(trace: Trace, bodies: dict[str, Body], ego: str | None):
    """Least exact box distance to the ego, and least time to collision (distance over closing speed while
    closing in); ties go to the first name."""
    if ego is None or ego not in trace.samples or ego not in bodies:
        return None, None, None, None
    ego_at = {round(s.t, 3): s for s in trace.samples[ego]}
    best_d = best_ttc = None
    who_d = who_ttc = None
    for name in sorted(trace.samples):
        if name == ego or name not in bodies:
            continue
        previous = None
        for s in trace.samples[name]:
            e = ego_at.get(round(s.t, 3))
            if e is None:
                previous = None
                continue
            gap = box_distance(e, bodies[ego], s, bodies[name])
            if best_d is None or gap < best_d:
                best_d, who_d = gap, name
            if previous is not None and s.t > previous[0]:
                closing = (previous[1] - gap) / (s.t - previous[0])
                if closing > 0.1:
                    ttc = gap / closing
                    if best_ttc is None or ttc < best_ttc:
                        best_ttc, who_ttc = ttc, name
            previous = (s.t, gap)
    return (round(best_d, 2) if best_d is not None else None, who_d,
            round(best_ttc, 2) if best_ttc is not None else None, who_ttc)
