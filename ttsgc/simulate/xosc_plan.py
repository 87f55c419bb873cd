""".xosc -> a plan the SUMO executor can run, read from the file itself (not from the compiler's data), so
hand-edited files run too. Everything the executor cannot do is listed by name instead of being ignored."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from lxml import etree

from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.simulate.xosc_check import load_scenario

PREFIX = "ttsgc:"


class ScenarioFileError(TtsgcError):
    exit_code = ExitCode.INVALID_SCENARIO


@dataclass(frozen=True)
class Condition:
    kind: str  # time | state | distance | reach | never
    delay: float = 0.0
    value: float = 0.0
    ref: str = ""  # act name (state) or entity (distance)
    state: str = ""
    triggering: str = ""  # the entity whose distance counts
    position: tuple[str, int, float] | None = None  # reach: the lane position to come within value of


@dataclass(frozen=True)
class Action:
    kind: str  # teleport | appear | speed | lane_change | route | acquire | environment
    lane: tuple[str, int, float] | None = None  # (road, lane, s)
    relative: tuple[str, int, float] | None = None  # (entity, dlane, ds)
    value: float = 0.0
    rate: float | None = None  # m/s2 for linear speed changes
    duration: float = 0.0
    waypoints: tuple[tuple[str, int, float], ...] = ()


@dataclass
class Event:
    name: str
    actor: str
    actions: list[Action]
    start: list[list[Condition]]  # OR of AND groups


@dataclass
class Act:
    name: str
    start: list[list[Condition]]
    events: list[Event]


@dataclass
class Entity:
    name: str
    kind: str  # vehicle | pedestrian
    category: str
    role: str
    length: float
    width: float
    intent: dict[str, str]


@dataclass
class Plan:
    xosc: Path
    xodr: Path
    entities: dict[str, Entity]
    init: dict[str, list[Action]]
    acts: list[Act]
    stop: list[list[Condition]]
    unsupported: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)  # what the file does that the standard does not, read leniently


def _lane(position) -> tuple[str, int, float] | None:
    lane = position.find("LanePosition") if position is not None else None
    if lane is None:
        return None
    return lane.get("roadId"), int(lane.get("laneId")), float(lane.get("s"))


class _Reader:
    def __init__(self):
        self.unsupported: list[str] = []

    def missing(self, what: str) -> None:
        if what not in self.unsupported:
            self.unsupported.append(what)

    def trigger(self, element) -> list[list[Condition]]:
        if element is None:
            return [[Condition("time", value=0.0)]]
        groups = []
        for group in element.findall("ConditionGroup"):
            groups.append([self.condition(c) for c in group.findall("Condition")])
        return groups

    def condition(self, c) -> Condition:
        delay = float(c.get("delay", "0") or 0)
        value_condition = c.find("ByValueCondition")
        entity_condition = c.find("ByEntityCondition")
        if value_condition is not None:
            inner = value_condition[0]
            tag = etree.QName(inner).localname
            if tag == "SimulationTimeCondition":
                return Condition("time", delay, float(inner.get("value")))
            if tag == "StoryboardElementStateCondition":
                return Condition("state", delay, ref=inner.get("storyboardElementRef"), state=inner.get("state"))
            self.missing(f"condition {tag}")
            return Condition("never")
        if entity_condition is not None:
            triggering = entity_condition.find("TriggeringEntities/EntityRef")
            inner = entity_condition.find("EntityCondition")[0]
            tag = etree.QName(inner).localname
            if tag == "DistanceCondition" and inner.get("rule") in ("lessThan", "lessOrEqual") and \
                    _lane(inner.find("Position")) is not None:
                return Condition("reach", delay, float(inner.get("value")), position=_lane(inner.find("Position")),
                                 triggering=triggering.get("entityRef") if triggering is not None else "")
            if tag == "RelativeDistanceCondition" and inner.get("rule") in ("lessThan", "lessOrEqual"):
                return Condition("distance", delay, float(inner.get("value")), ref=inner.get("entityRef"),
                                 triggering=triggering.get("entityRef") if triggering is not None else "")
            self.missing(f"condition {tag}")
            return Condition("never")
        self.missing("condition of unknown kind")
        return Condition("never")

    def action(self, private) -> Action | None:
        first = private[0]
        tag = etree.QName(first).localname
        if tag == "TeleportAction":
            position = first.find("Position")
            lane = _lane(position)
            if lane is not None:
                return Action("teleport", lane=lane)
            relative = position.find("RelativeLanePosition") if position is not None else None
            if relative is not None:
                return Action("appear", relative=(relative.get("entityRef"), int(relative.get("dLane")),
                                                  float(relative.get("ds", "0"))))
            self.missing("TeleportAction to a position other than LanePosition / RelativeLanePosition")
            return None
        if tag == "LongitudinalAction" and first.find("SpeedAction") is not None:
            speed = first.find("SpeedAction")
            target = speed.find("SpeedActionTarget/AbsoluteTargetSpeed")
            if target is None:
                self.missing("SpeedAction with a relative target")
                return None
            if float(target.get("value")) < 0:
                self.missing("SpeedAction to a negative speed (driving backwards)")
                return None
            dynamics = speed.find("SpeedActionDynamics")
            rate = None
            if dynamics is not None and dynamics.get("dynamicsDimension") == "rate" and float(dynamics.get("value")) > 0:
                rate = float(dynamics.get("value"))
            return Action("speed", value=float(target.get("value")), rate=rate)
        if tag == "LateralAction" and first.find("LaneChangeAction") is not None:
            change = first.find("LaneChangeAction")
            target = change.find("LaneChangeTarget/RelativeTargetLane")
            if target is None:
                self.missing("LaneChangeAction with an absolute target lane")
                return None
            dynamics = change.find("LaneChangeActionDynamics")
            return Action("lane_change", value=float(target.get("value")),
                          duration=float(dynamics.get("value", "3")) if dynamics is not None else 3.0)
        if tag == "RoutingAction":
            route = first.find("AssignRouteAction/Route")
            if route is not None:
                points = tuple(p for p in (_lane(w.find("Position")) for w in route.findall("Waypoint")) if p)
                return Action("route", waypoints=points)
            acquire = first.find("AcquirePositionAction/Position")
            if acquire is not None and _lane(acquire) is not None:
                return Action("acquire", lane=_lane(acquire))
        self.missing(f"action {tag}" + (f"/{etree.QName(first[0]).localname}" if len(first) else ""))
        return None


def read_plan(path: str | Path) -> Plan:
    path = Path(path)
    scenario = load_scenario(path)  # checked, parameters and catalogs resolved; raises with file:line
    root, xodr = scenario.root, scenario.xodr
    reader = _Reader()
    entities = {}
    for obj in root.findall("Entities/ScenarioObject"):
        body = obj.find("Vehicle")
        kind = "vehicle"
        if body is None:
            body, kind = obj.find("Pedestrian"), "pedestrian"
        if body is None:
            reader.missing("a ScenarioObject that is neither Vehicle nor Pedestrian (catalog references)")
            continue
        dims = body.find("BoundingBox/Dimensions")
        intent = {p.get("name")[len(PREFIX):]: p.get("value") for p in body.findall("Properties/Property")
                  if p.get("name", "").startswith(PREFIX)}
        entities[obj.get("name")] = Entity(obj.get("name"), kind, body.get("vehicleCategory") or
                                           body.get("pedestrianCategory") or "pedestrian", body.get("role", "none"),
                                           float(dims.get("length")), float(dims.get("width")), intent)
    for controller in root.iterfind("Entities/ScenarioObject/ObjectController/Controller"):
        reader.missing(f"controller {controller.get('name')} (SUMO's driver model drives its entity)")
    for action in root.iterfind("Storyboard/Init/Actions/GlobalAction/*"):
        if action.tag != "EnvironmentAction":  # weather: written, not simulated (README, known limits)
            reader.missing(f"initial GlobalAction/{etree.QName(action).localname}")
    init: dict[str, list[Action]] = {}
    for private in root.findall("Storyboard/Init/Actions/Private"):
        for action in private.findall("PrivateAction"):
            parsed = reader.action(action)
            if parsed is not None:
                init.setdefault(private.get("entityRef"), []).append(parsed)
    acts = []
    for act in root.findall("Storyboard/Story/Act"):
        events = []
        for group in act.findall("ManeuverGroup"):
            actors = [e.get("entityRef") for e in group.findall("Actors/EntityRef")]
            for event in group.iter("Event"):
                actions = [reader.action(a) for a in event.iter("PrivateAction")]
                if any(etree.QName(a).localname == "GlobalAction" for a in event.iter("Action") for a in a):
                    reader.missing("a GlobalAction inside an event")
                events.append(Event(event.get("name"), actors[0] if actors else "",
                                    [a for a in actions if a is not None], reader.trigger(event.find("StartTrigger"))))
        acts.append(Act(act.get("name"), reader.trigger(act.find("StartTrigger")), events))
    stop_trigger = root.find("Storyboard/StopTrigger")
    stop = reader.trigger(stop_trigger) if stop_trigger is not None else []  # none: only the time limit ends it
    return Plan(path, xodr, entities, init, acts, stop, reader.unsupported, list(scenario.notes))
