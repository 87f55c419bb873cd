"""The verdict on a scene that declares no intents (no ttsgc:* properties): a file written by hand or by
another tool. Nothing says what each agent should do, so the scene is judged on what every scene must do:
it plays to its end (its StopTrigger fires), nobody collides, every entity enters the road and stays on it,
and every lane position the file names exists on its map. An empty judgement is never a pass.

The judge reads only the reader's plan, the player's run and the map, so it can move beside the intent
checks unchanged.
"""

from __future__ import annotations

import math

from ttsgc.roads.opendrive import OpenDrive
from ttsgc.simulate.checks import AgentResult, CollisionResult, Report
from ttsgc.simulate.sumo import TIME_LIMIT_S, Run
from ttsgc.simulate.xosc_plan import Plan

S_TOLERANCE_M = 0.01

NO_INTENTS = ("no intents were declared in this file (no ttsgc:* properties), so no agent's behaviour is judged; "
              "it is judged only on playing to its end, without collisions, on the road, from positions that exist")


class GeneralReport(Report):
    intents_declared: bool = False
    stop_trigger_fired: bool
    failures: list[str]  # each reason the scene failed, in words
    notes: list[str]  # what the file does that the standard does not, read leniently

    def table(self) -> str:
        lines = [NO_INTENTS, ""]
        body = super().table().splitlines()[:-1]  # its last line counts agents against intents: there are none
        lines += body
        for note in self.notes:
            lines.append(f"note: {note}")
        for failure in self.failures:
            lines.append(f"failure: {failure}")
        if self.ok:
            lines.append(f"OK: played to its stop trigger at t={self.simulated_s:.1f} s; {len(self.agents)} entities "
                         f"on the road throughout, no collision (no intents declared)")
        else:
            lines.append(f"FAILED: {len(self.failures)} failure{'s' if len(self.failures) > 1 else ''} above, "
                         f"{self.simulated_s:.1f} s simulated (no intents declared)")
        return "\n".join(lines)


def _lane_positions(plan: Plan):
    """(where it is used, (road, lane, s)) for every lane position the plan holds."""
    for name, actions in plan.init.items():
        for action in actions:
            if action.lane is not None:
                yield f"the start of {name}", action.lane
    for act in plan.acts:
        for event in act.events:
            for action in event.actions:
                if action.lane is not None:
                    yield f"event {event.name}", action.lane
                for point in action.waypoints:
                    yield f"the route of event {event.name}", point
            for group in event.start:
                for condition in group:
                    if condition.position is not None:
                        yield f"the trigger of event {event.name}", condition.position


def missing_position(odr: OpenDrive, position: tuple[str, int, float]) -> str | None:
    """Why a lane position does not exist on the map, or None when it does."""
    road_id, lane, s = position
    road = odr.roads.get(str(road_id))
    if road is None:
        return f"road {road_id} is not on the map"
    if not -S_TOLERANCE_M <= s <= road.length + S_TOLERANCE_M:
        return f"s={s:g} is off road {road_id}, which is {road.length:.1f} m long"
    section = road.section_at(min(max(s, 0.0), road.length))
    if lane not in section.lanes:
        return f"road {road_id} has no lane {lane} at s={s:g} (lanes {sorted(section.lanes)})"
    return None


def judge_without_intents(plan: Plan, run: Run, odr: OpenDrive) -> GeneralReport:
    failures: list[str] = []
    stopped = bool(plan.stop) and run.end_time < TIME_LIMIT_S - 1e-6
    if not plan.stop:
        failures.append(f"the file has no StopTrigger, so it never ends by itself (stopped at the "
                        f"{TIME_LIMIT_S:.0f} s limit)")
    elif not stopped:
        cause = f" ({len(plan.unsupported)} of its elements are not supported by the SUMO executor and may be why)" \
            if plan.unsupported else ""
        failures.append(f"its StopTrigger never fired within {TIME_LIMIT_S:.0f} s{cause}")
    never = [a.name for a in plan.acts if a.name not in run.act_start]
    if never:
        failures.append(f"act{'s' if len(never) > 1 else ''} {', '.join(never)} never started")
    for where, position in _lane_positions(plan):
        why = missing_position(odr, position)
        if why is not None:
            failures.append(f"{where} names a lane position that does not exist: {why}")
    agents = [_entity(plan, run, name) for name in plan.entities]
    failures += [f"{a.name} {a.reason}" for a in agents if not a.achieved]
    if not plan.entities:
        failures.append("no entity of the file could be played, so nothing could be judged")
    collisions = []
    for c in run.collisions:
        sample = next((s for s in reversed(run.samples.get(c.a, [])) if s.t <= c.t), None)
        collisions.append(CollisionResult(a=c.a, b=c.b, time_s=c.t, x=c.x, y=c.y,
                                          road=sample.road if sample else "", asked_for=False))
        failures.append(f"{c.a} and {c.b} collided at t={c.t:.1f} s")
    failures += [f"the player could not carry out: {p}" for p in run.problems]
    failures = list(dict.fromkeys(failures))
    return GeneralReport(ok=not failures, scenario=str(plan.xosc), map=str(plan.xodr), agents=agents,
                         collisions=collisions, min_distance_to_ego=None, min_distance_agent=None,
                         min_ttc_to_ego=None, min_ttc_agent=None, unsupported=list(plan.unsupported),
                         problems=list(run.problems), simulated_s=run.end_time, stop_trigger_fired=stopped,
                         failures=failures, notes=list(plan.notes))


def _entity(plan: Plan, run: Run, name: str) -> AgentResult:
    entity = plan.entities[name]
    result = lambda ok, why: AgentResult(name=name, type=entity.category, action="(none declared)",  # noqa: E731
                                         achieved=ok, reason=why)
    spawn = run.spawns.get(name)
    samples = run.samples.get(name, [])
    if spawn is not None and not spawn.ok:
        return result(False, f"could not be placed: {spawn.reason}")
    if not samples:
        return result(False, "never entered the road (no start position the player could use)")
    off = next((s for s in samples if not s.road and not s.edge.startswith(":")), None)
    if off is not None:
        return result(False, f"left the road at t={off.t:.1f} s ({off.x:.1f}, {off.y:.1f})")
    travelled = sum(math.hypot(b.x - a.x, b.y - a.y) for a, b in zip(samples, samples[1:]))
    return result(True, f"on the road from t={samples[0].t:.1f} to {samples[-1].t:.1f} s, {travelled:.0f} m")
