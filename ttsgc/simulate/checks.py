"""Did every agent do what it was told? Each agent's intent comes from the .xosc (ttsgc:* Properties); the
evidence is the run's trace. Also: spawns, collisions (and whether the scene asked for one), and how close
the scene came to the ego (minimum distance and time to collision)."""

from __future__ import annotations

import math

from pydantic import BaseModel

from ttsgc.roads.opendrive import OpenDrive
from ttsgc.simulate.sumo import Run, Sample, _obb_overlap
from ttsgc.simulate.xosc_plan import Plan

STOPPED_MPS = 0.1
STOPPED_FOR_S = 1.0
TURN_MIN_DEG = 30.0
COLLISION_SEEKING = {"block_the_ego", "cross_the_road", "change_lane_to_left", "change_lane_to_right"}


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
    asked_for: bool  # the ego and an agent whose action aims at its path


class Report(BaseModel):
    ok: bool
    scenario: str
    map: str
    agents: list[AgentResult]
    collisions: list[CollisionResult]
    min_distance_to_ego: float | None
    min_distance_agent: str | None
    min_ttc_to_ego: float | None
    min_ttc_agent: str | None
    unsupported: list[str]
    problems: list[str]
    simulated_s: float

    def table(self) -> str:
        width = max([len(a.name) for a in self.agents] + [5])
        action = max([len(a.action) for a in self.agents] + [6])
        lines = [f"{'agent'.ljust(width)}  {'action'.ljust(action)}     why", "-" * (width + action + 30)]
        for a in self.agents:
            lines.append(f"{a.name.ljust(width)}  {a.action.ljust(action)}  {'✓' if a.achieved else '✗'}  {a.reason}")
        if self.collisions:
            for c in self.collisions:
                lines.append(f"collision: {c.a} and {c.b} at t={c.time_s:.1f} s, road {c.road or '(junction)'} "
                             f"({c.x:.1f}, {c.y:.1f}){' (the scene aims at the ego)' if c.asked_for else ''}")
        else:
            lines.append("collisions: none")
        if self.min_distance_to_ego is not None:
            lines.append(f"closest to the ego: {self.min_distance_to_ego:.1f} m ({self.min_distance_agent})")
        if self.min_ttc_to_ego is not None:
            lines.append(f"least time to collision with the ego: {self.min_ttc_to_ego:.1f} s ({self.min_ttc_agent})")
        for item in self.unsupported:
            lines.append(f"not supported by the SUMO executor: {item}")
        for item in self.problems:
            lines.append(f"problem: {item}")
        lines.append(f"{'OK' if self.ok else 'FAILED'}: {sum(a.achieved for a in self.agents)}/{len(self.agents)} "
                     f"agents did what they were told, {self.simulated_s:.1f} s simulated")
        return "\n".join(lines)


def _wrap_deg(angle: float) -> float:
    return math.degrees(math.atan2(math.sin(angle), math.cos(angle)))


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


def _action_start(plan: Plan, run: Run, name: str) -> float | None:
    times = [run.fired[e.name] for act in plan.acts for e in act.events
             if e.actor == name and e.name in run.fired and not e.name.endswith("_appears")]
    return min(times) if times else None


def check(plan: Plan, run: Run, odr: OpenDrive) -> Report:
    ego = next((n for n, e in plan.entities.items() if e.intent.get("is_ego") == "true"), None)
    results = [_check_agent(plan, run, odr, name, ego) for name in plan.entities]
    overlaps = _spawn_overlaps(plan, run)
    for r in results:
        if r.name in overlaps and r.achieved:
            r.achieved, r.reason = False, f"spawned overlapping {overlaps[r.name]}"
    collisions = []
    for c in run.collisions:
        other = c.b if c.a == ego else c.a if c.b == ego else None
        asked = other is not None and (plan.entities[other].intent.get("action") in COLLISION_SEEKING or
                                       plan.entities[other].intent.get("behavior") == "aggressive")
        sample = next((s for s in reversed(run.samples.get(c.a, [])) if s.t <= c.t), None)
        collisions.append(CollisionResult(a=c.a, b=c.b, time_s=c.t, x=c.x, y=c.y,
                                          road=sample.road if sample else "", asked_for=asked))
    distance, distance_agent, ttc, ttc_agent = _criticality(plan, run, ego)
    ok = all(r.achieved for r in results) and not any(not c.asked_for for c in collisions) and not run.problems
    return Report(ok=ok, scenario=str(plan.xosc), map=str(plan.xodr), agents=results, collisions=collisions,
                  min_distance_to_ego=distance, min_distance_agent=distance_agent, min_ttc_to_ego=ttc,
                  min_ttc_agent=ttc_agent, unsupported=list(plan.unsupported), problems=list(run.problems),
                  simulated_s=run.end_time)


def _check_agent(plan: Plan, run: Run, odr: OpenDrive, name: str, ego: str | None) -> AgentResult:
    entity = plan.entities[name]
    action = entity.intent.get("action", "")
    result = lambda ok, why: AgentResult(name=name, type=entity.intent.get("type", entity.category),  # noqa: E731
                                         action=action or "(none)", achieved=ok, reason=why)
    spawn = run.spawns.get(name)
    samples = run.samples.get(name, [])
    if spawn is None and not samples:
        return result(False, "never entered the simulation")
    if spawn is not None and not spawn.ok:
        return result(False, f"could not be spawned: {spawn.reason}")
    if not action:
        return result(True, "no intent recorded in the file (nothing to check)")
    start = _action_start(plan, run, name)
    if start is None:
        return result(False, "its action never started: the trigger never fired")
    after = [s for s in samples if s.t >= start]
    if not after:
        return result(False, f"left the simulation before its action started at t={start:.1f} s")
    movement = entity.intent.get("movement", "")
    if movement:
        return result(*_movement(after, movement, entity.intent.get("target_road", "")))
    if action in ("turn_left", "turn_right"):
        return result(False, "was given no junction to turn at (its road does not lead to one)")
    if action == "go_straight":
        travelled = sum(math.hypot(b.x - a.x, b.y - a.y) for a, b in zip(after, after[1:]))
        return result(travelled >= 5.0, f"drove {travelled:.0f} m" + ("" if travelled >= 5 else ", too little"))
    if action in ("change_lane_to_left", "change_lane_to_right"):
        return result(*_lane_change(after, 1 if action.endswith("left") else -1))
    if action == "stop":
        return result(*_stopped(after))
    if action == "block_the_ego":
        return result(*_blocked(after, run.samples.get(ego, []) if ego else [], entity))
    road = spawn.intended[0] if spawn is not None and spawn.intended else samples[0].road
    if action in ("cross_the_road", "on_the_sidewalk") and road not in odr.roads:
        return result(False, "its road could not be told")
    if action == "cross_the_road":
        return result(*_crossed(odr, road, samples[0], after))
    if action == "on_the_sidewalk":
        return result(*_walked_on_sidewalk(odr, road, samples[0], after))
    return result(False, f"no check for action '{action}'")


def _movement(after: list[Sample], movement: str, target: str) -> tuple[bool, str]:
    roads = [s.road for s in after if s.road]
    start_road = roads[0] if roads else ""
    reached = next((i for i, s in enumerate(after) if s.road == target and s.road != start_road), None)
    if reached is None:
        beyond = [r for r in dict.fromkeys(roads) if r != start_road]
        where = f"ended on road {beyond[-1]}" if beyond else f"stayed on road {start_road or '?'}"
        return False, f"{where}, not on road {target} where its {movement} movement leads"
    change = _wrap_deg(after[min(reached + 5, len(after) - 1)].heading - after[0].heading)
    expected = {"left": change >= TURN_MIN_DEG, "right": change <= -TURN_MIN_DEG,
                "straight": abs(change) < TURN_MIN_DEG}[movement]
    went = "left" if change >= TURN_MIN_DEG else "right" if change <= -TURN_MIN_DEG else "straight"
    return expected, f"went {went} onto road {target} (heading {change:+.0f}°)"


def _lane_change(after: list[Sample], direction: int) -> tuple[bool, str]:
    net = 0
    for a, b in zip(after, after[1:]):
        if a.edge == b.edge and a.lane_index >= 0 and b.lane_index >= 0:
            net += b.lane_index - a.lane_index
    side = "left" if direction > 0 else "right"
    if net * direction >= 1:
        return True, f"changed {abs(net)} lane(s) to the {side}"
    return False, f"did not change to the {side} (net lane change {net:+d})"


def _stopped(after: list[Sample]) -> tuple[bool, str]:
    run_length, needed = 0, round(STOPPED_FOR_S / 0.1)
    for s in after:
        run_length = run_length + 1 if s.speed < STOPPED_MPS else 0
        if run_length >= needed:
            return True, f"came to a standstill by t={s.t - STOPPED_FOR_S:.1f} s"
    return False, f"never stood still (slowest {min(s.speed for s in after):.1f} m/s)"


def _blocked(after: list[Sample], ego: list[Sample], entity) -> tuple[bool, str]:
    stopped, why = _stopped(after)
    if not stopped:
        return False, why
    stop_time = next(s.t for s in after if s.speed < STOPPED_MPS)
    initial = ego[0].speed if ego else 0.0
    behind = []
    for e in ego:
        if e.t < stop_time:
            continue
        agent = next((s for s in after if abs(s.t - e.t) < 1e-6), None)
        if agent is None:
            continue
        dx, dy = agent.x - e.x, agent.y - e.y
        ahead = dx * math.cos(e.heading) + dy * math.sin(e.heading)
        side = -dx * math.sin(e.heading) + dy * math.cos(e.heading)
        if 0 < ahead < 40 and abs(side) < 2.0:
            behind.append(e)
    if not behind:
        return False, "stopped, but never in front of the ego"
    slowest = min(e.speed for e in behind)
    if slowest < max(1.0, 0.5 * initial):
        return True, f"stopped in the ego's path; the ego slowed from {initial:.1f} to {slowest:.1f} m/s behind it"
    return False, f"stopped ahead of the ego, which kept {slowest:.1f} m/s"


def _crossed(odr: OpenDrive, road: str, first: Sample, after: list[Sample]) -> tuple[bool, str]:
    _, t0 = _lateral(odr, road, first.x, first.y)
    _, t1 = _lateral(odr, road, after[-1].x, after[-1].y)
    sides = lambda t: "left" if t > 0 else "right"  # noqa: E731
    if t0 * t1 < 0 and abs(t1) > 1.0:
        return True, f"crossed road {road} from its {sides(t0)} side to its {sides(t1)} side"
    return False, f"stayed on the {sides(t0)} side of road {road} (t {t0:+.1f} -> {t1:+.1f} m)"


def _walked_on_sidewalk(odr: OpenDrive, road: str, first: Sample, after: list[Sample]) -> tuple[bool, str]:
    _, t0 = _lateral(odr, road, first.x, first.y)
    walked = math.hypot(after[-1].x - first.x, after[-1].y - first.y)
    drift = max(abs(_lateral(odr, road, s.x, s.y)[1] - t0) for s in after[:: 10] + [after[-1]])
    if walked >= 5.0 and drift < 1.5:
        return True, f"walked {walked:.0f} m along the sidewalk"
    return False, f"walked {walked:.0f} m, straying {drift:.1f} m off its sidewalk"


def _spawn_overlaps(plan: Plan, run: Run) -> dict[str, str]:
    firsts = {n: s[0] for n, s in run.samples.items() if s}
    out = {}
    names = sorted(firsts)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            sa, sb = firsts[a], firsts[b]
            if abs(sa.t - sb.t) > 1e-6:
                continue
            ea, eb = plan.entities[a], plan.entities[b]
            if _obb_overlap((sa.x, sa.y, sa.heading, ea.length, ea.width), (sb.x, sb.y, sb.heading, eb.length, eb.width)):
                out[a], out[b] = b, a
    return out


def _gap(a: Sample, body_a, b: Sample, body_b) -> float:
    """Free distance between two boxes along the line joining their centres."""
    dx, dy = b.x - a.x, b.y - a.y
    d = math.hypot(dx, dy)
    line = math.atan2(dy, dx)
    extent = lambda s, body: abs(math.cos(line - s.heading)) * body.length / 2 + \
        abs(math.sin(line - s.heading)) * body.width / 2  # noqa: E731
    return max(0.0, d - extent(a, body_a) - extent(b, body_b))


def _criticality(plan: Plan, run: Run, ego: str | None):
    """Least bumper-to-bumper distance to the ego, and least time to collision while closing in."""
    if ego is None or ego not in run.samples:
        return None, None, None, None
    ego_at = {round(s.t, 3): s for s in run.samples[ego]}
    ego_body = plan.entities[ego]
    best_d = best_ttc = None
    who_d = who_ttc = None
    for name, samples in run.samples.items():
        if name == ego:
            continue
        body = plan.entities[name]
        previous = None
        for s in samples:
            e = ego_at.get(round(s.t, 3))
            if e is None:
                continue
            gap = _gap(e, ego_body, s, body)
            if best_d is None or gap < best_d:
                best_d, who_d = gap, name
            if previous is not None:
                closing = (previous - gap) / 0.1
                if closing > 0.1:
                    ttc = gap / closing
                    if best_ttc is None or ttc < best_ttc:
                        best_ttc, who_ttc = ttc, name
            previous = gap
    return (round(best_d, 2) if best_d is not None else None, who_d,
            round(best_ttc, 2) if best_ttc is not None else None, who_ttc)
