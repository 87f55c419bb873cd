"""The verdict on a scene that declares no intents (no ttsgc:* properties): a file written by hand or by
another tool. Nothing says what each agent should do, so the scene is judged on what every scene must do:
it plays to its end (its StopTrigger fires), nobody collides, every entity enters the road and stays on it,
and every lane position the file names exists on its map. An empty judgement is never a pass.

Like the intent checks, it reads only the plan, one player's Trace and the map: it knows no player.
"""

from __future__ import annotations

import math

from ttsgc.roads.opendrive import OpenDrive
from ttsgc.simulate.plan import Plan
from ttsgc.simulate.trace import Trace

S_TOLERANCE_M = 0.01
NONE_DECLARED = "(none declared)"

NO_INTENTS = ("no intents were declared in this file (no ttsgc:* properties), so no agent's behaviour is judged; "
              "it is judged only on playing to its end, without collisions, on the road, from positions that exist")


def declares_intents(plan: Plan) -> bool:
    return any(entity.intent for entity in plan.entities.values())


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


def file_failures(plan: Plan, trace: Trace, odr: OpenDrive) -> list[str]:
    """What the scene as a whole failed to do in this trace, in words."""
    failures: list[str] = []
    if not plan.stop:
        failures.append(f"the file has no StopTrigger, so it never ends by itself (stopped at the {trace.player} "
                        f"time limit, {trace.end_time:.0f} s)")
    elif not trace.stopped_by_trigger:
        cause = f" ({len(plan.unsupported)} of its elements are not read by ttsgc and may be why)" \
            if plan.unsupported else ""
        failures.append(f"its StopTrigger never fired within {trace.end_time:.0f} s{cause}")
    never = [a.name for a in plan.acts if a.name not in trace.started]
    if never:
        failures.append(f"act{'s' if len(never) > 1 else ''} {', '.join(never)} never started")
    for where, position in _lane_positions(plan):
        why = missing_position(odr, position)
        if why is not None:
            failures.append(f"{where} names a lane position that does not exist: {why}")
    if not plan.entities:
        failures.append("no entity of the file could be played, so nothing could be judged")
    return list(dict.fromkeys(failures))


def entity_result(trace: Trace, name: str) -> tuple[bool, str]:
    """(on the road throughout, why): whether the entity entered the road and stayed on it."""
    samples = trace.samples.get(name, [])
    placed = next((p for p in trace.problems if p.startswith(f"'{name}' could not be placed")), None)
    if placed is not None:
        return False, placed.split(": ", 1)[-1]
    if not samples:
        return False, "never entered the road (no start position the player could use)"
    off = next((s for s in samples if s.on_road is False), None)
    if off is not None:
        return False, f"left the road at t={off.t:.1f} s ({off.x:.1f}, {off.y:.1f})"
    travelled = sum(math.hypot(b.x - a.x, b.y - a.y) for a, b in zip(samples, samples[1:]))
    return True, f"on the road from t={samples[0].t:.1f} to {samples[-1].t:.1f} s, {travelled:.0f} m"
