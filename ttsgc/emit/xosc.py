"""BoundScene -> OpenSCENARIO XML (1.0 to 1.3) with scenariogeneration.xosc, validated against the ASAM XSD.

Entities carry a category and body per type (and their role from 1.2 on); Init teleports every first-stage
agent to its lane position and sets its speed; one Story holds one Act per stage, each starting a stage's
estimated duration after the previous act ends; every action is an Event triggered at once, after a delay or
when an entity comes within a distance; the weather is an EnvironmentAction; a stop trigger always fires.
Each agent's intent is written into its Properties (ttsgc:*) so a checker can read it from the file alone.
"""

from __future__ import annotations

import datetime as dt
import functools
import math
import importlib.util
from pathlib import Path
from xml.etree import ElementTree

from lxml import etree

from ttsgc import vocabulary as V
from ttsgc.binding.place import BoundAgent, LanePos
from ttsgc.binding.scene import BoundScene
from ttsgc.emit.lean_import import openscenario_writer
from ttsgc.errors import TtsgcError

xosc = openscenario_writer()
VersionBase = xosc.VersionBase

VERSIONS = ("1.0", "1.1", "1.2", "1.3")
DEFAULT_VERSION = "1.3"
CREATION_DATE = dt.datetime(2026, 1, 1, 0, 0, 0)
PROPERTY_PREFIX = "ttsgc:"

CATEGORY = {"car": "car", "police": "car", "truck": "truck", "firetruck": "truck", "ambulance": "van", "bus": "bus",
            "motorcycle": "motorbike", "cyclist": "bicycle"}
ROLE = {"ambulance": "ambulance", "police": "police", "firetruck": "fire", "bus": "publicTransport"}
CLOUDS = {"clear": ("free", "zeroOktas"), "cloudy": ("overcast", "sixOktas"), "wet": ("free", "oneOktas"),
          "wet_cloudy": ("overcast", "sixOktas"), "soft_rain": ("rainy", "sevenOktas"),
          "mid_rain": ("rainy", "sevenOktas"), "hard_rain": ("rainy", "eightOktas"), "fog": ("overcast", "eightOktas"),
          "snow": ("overcast", "eightOktas")}
RAIN_MM_H = {"soft_rain": 1.0, "mid_rain": 4.0, "hard_rain": 12.0, "snow": 2.0}
FRICTION = {"clear": 1.0, "cloudy": 1.0, "wet": 0.75, "wet_cloudy": 0.75, "soft_rain": 0.75, "mid_rain": 0.7,
            "hard_rain": 0.6, "fog": 0.9, "snow": 0.4}
HOUR = {"dawn": 6, "noon": 12, "sunset": 19, "night": 23}
SUN = {"dawn": (0.3, 1.6, 0.1), "noon": (1.0, 3.1, 1.2), "sunset": (0.3, 4.7, 0.05), "night": (0.0, 0.0, -0.5)}


class EmitError(TtsgcError):
    """The emitted file does not validate: a fault in ttsgc, never in the input."""


def emit(scene: BoundScene, roadfile: str, version: str = DEFAULT_VERSION) -> bytes:
    """The .xosc for a bound scene; roadfile is written verbatim (the path relative to the .xosc)."""
    if version not in VERSIONS:
        raise TtsgcError(f"OpenSCENARIO {version} is not supported; choose one of {', '.join(VERSIONS)}")
    minor = int(version.split(".")[1])
    VersionBase().setVersion(1, minor)  # scenariogeneration checks every element against a global version
    entities = xosc.Entities()
    for agent in scene.agents:
        entities.add_scenario_object(agent.name, _entity(agent, scene, minor))
    init = xosc.Init()
    weather = scene.scenario.weather
    init.add_global_action(xosc.EnvironmentAction(_environment(weather.condition if weather else V.DEFAULT_CONDITION,
                                                               weather.time if weather else V.DEFAULT_TIME, minor)))
    step = xosc.TransitionDynamics(xosc.DynamicsShapes.step, xosc.DynamicsDimension.time, 0)
    for agent in scene.agents:
        if agent.stage == 0 and agent.start is not None:
            init.add_init_action(agent.name, xosc.TeleportAction(_lane_position(agent.start)))
            init.add_init_action(agent.name, xosc.AbsoluteSpeedAction(agent.speed_mps, step))
    story = xosc.Story("story")
    durations = stage_durations(scene)
    for k, stage in enumerate(scene.scenario.stages):
        story.add_act(_act(scene, k, stage.name, durations, minor))
    stop = xosc.ValueTrigger("end", 0, xosc.ConditionEdge.rising,
                             xosc.SimulationTimeCondition(round(sum(durations) + 10.0, 3), xosc.Rule.greaterThan),
                             "stop")
    board = xosc.StoryBoard(init, stop)
    board.add_story(story)
    document = xosc.Scenario(scene.scenario.name, "ttsgc", xosc.ParameterDeclarations(), entities, board,
                             xosc.RoadNetwork(roadfile=roadfile), xosc.Catalog(), osc_minor_version=minor,
                             creation_date=CREATION_DATE)
    tree = etree.fromstring(ElementTree.tostring(document.get_element(), encoding="utf-8"))
    data = etree.tostring(tree, xml_declaration=True, encoding="utf-8", pretty_print=True)
    validate(data, version)
    return data


def _lane_position(pos: LanePos) -> xosc.LanePosition:
    # Left lanes (ids > 0) drive against s: face along the lane's driving direction.
    heading = xosc.Orientation(h=math.pi, reference=xosc.ReferenceContext.relative) if pos.lane > 0 else None
    return xosc.LanePosition(pos.s, pos.offset, pos.lane, pos.road, heading) if heading else \
        xosc.LanePosition(pos.s, pos.offset, pos.lane, pos.road)


def _entity(agent: BoundAgent, scene: BoundScene, minor: int):
    box = xosc.BoundingBox(agent.width, agent.length, agent.height, agent.length * 0.15, 0.0, agent.height / 2)
    role = getattr(xosc.Role, ROLE[agent.type]) if agent.type in ROLE and minor >= 2 else None
    if agent.type == "pedestrian":
        entity = xosc.Pedestrian(agent.name, 75, xosc.PedestrianCategory.pedestrian, box, model="pedestrian")
    else:
        wheel = 0.35 if agent.type in ("motorcycle", "cyclist") else 0.4
        track = agent.width * 0.85
        front = xosc.Axle(0.5, wheel * 2, track, agent.length * 0.65, wheel)
        rear = xosc.Axle(0.0, wheel * 2, track, 0.0, wheel)
        max_speed = 10.0 if agent.type == "cyclist" else 70.0
        entity = xosc.Vehicle(agent.name, getattr(xosc.VehicleCategory, CATEGORY[agent.type]), box, front, rear,
                              max_speed, 6.0, 9.0, role=role)
    intent = {"action": agent.action, "position": agent.relative_to_ego or "ego", "road_type": agent.road_type,
              "behavior": agent.behavior, "type": agent.type, "stage": str(agent.stage),
              "is_ego": str(agent.is_ego).lower(), "movement": agent.movement or "",
              "target_road": agent.target_road or "", "map": scene.map_name, "approach": scene.approach}
    for key, value in intent.items():
        entity.add_property(PROPERTY_PREFIX + key, value)
    return entity


def _environment(condition: str, time: str, minor: int) -> xosc.Environment:
    state, oktas = CLOUDS[condition]
    clouds = getattr(xosc.FractionalCloudCover, oktas) if minor >= 2 else getattr(xosc.CloudState, state)
    intensity, azimuth, elevation = SUN[time]
    precipitation = xosc.Precipitation(
        xosc.PrecipitationType.snow if condition == "snow" else
        xosc.PrecipitationType.rain if condition in RAIN_MM_H else xosc.PrecipitationType.dry,
        RAIN_MM_H.get(condition, 0.0))
    weather = xosc.Weather(cloudstate=clouds,
                           sun=xosc.Sun(intensity, azimuth, elevation),
                           fog=xosc.Fog(150 if condition == "fog" else 100000),
                           precipitation=precipitation)
    return xosc.Environment(f"{condition}_{time}", xosc.TimeOfDay(False, 2026, 6, 21, HOUR[time], 0, 0), weather,
                            xosc.RoadCondition(FRICTION[condition]))


SIGNAL_WAIT_S = 50.0  # a red light can hold a junction movement for most of a signal cycle


def stage_durations(scene: BoundScene) -> list[float]:
    """How long each stage takes: its slowest agent's action, waiting for its trigger included, bounded;
    the next stage starts after it and the stop trigger after them all."""
    ego = next(a for a in scene.agents if a.is_ego)
    signalised = "traffic_light" in scene.approach_signals
    durations = []
    for k, _ in enumerate(scene.scenario.stages):
        longest = 4.0
        for agent in scene.agents:
            if agent.stage != k:
                continue
            wait = agent.trigger.after_s if agent.trigger and agent.trigger.after_s else 0.0
            if agent.trigger and agent.trigger.within_m is not None:
                wait += max(0.0, agent.distance_to_ego_m - agent.trigger.within_m) / max(ego.speed_mps, 1.0)
            speed = max(agent.speed_mps, 1.0)
            if agent.movement:
                action = 45.0 / speed + (SIGNAL_WAIT_S if signalised else 0.0)
            elif agent.cross_to is not None:
                action = 25.0 / speed
            else:
                action = 6.0
            longest = max(longest, wait + action)
        durations.append(round(min(longest, 120.0), 3))
    return durations


def _act(scene: BoundScene, k: int, name: str, durations: list[float], minor: int) -> xosc.Act:
    acts = scene.scenario.stages
    if k == 0:
        start = xosc.ValueTrigger(f"{name}_start", 0, xosc.ConditionEdge.none,
                                  xosc.SimulationTimeCondition(0, xosc.Rule.greaterOrEqual if minor >= 1
                                                               else xosc.Rule.greaterThan))
    else:
        ego = next(a for a in scene.agents if a.is_ego)
        if k == 1 and ego.route:  # the ego's movement ends the first stage: when it reaches the far road
            start = xosc.EntityTrigger(f"{name}_start", 0, xosc.ConditionEdge.rising,
                                       xosc.DistanceCondition(10.0, xosc.Rule.lessThan, _lane_position(ego.route[-1]),
                                                              alongroute=False, freespace=False,
                                                              distance_type=_EUCLIDEAN[minor >= 1]), ego.name)
        else:
            start = xosc.ValueTrigger(f"{name}_start", durations[k - 1], xosc.ConditionEdge.rising,
                                      xosc.StoryboardElementStateCondition(xosc.StoryboardElementType.act,
                                                                           acts[k - 1].name,
                                                                           xosc.StoryboardElementState.endTransition))
    act = xosc.Act(name, start)
    priority = xosc.Priority.override if minor >= 2 else xosc.Priority.overwrite
    for agent in scene.agents:
        if agent.stage != k:
            continue
        maneuver = xosc.Maneuver(f"{agent.name}_maneuver")
        for event_name, actions, trigger in _events(agent, scene, name, minor):
            event = xosc.Event(event_name, priority)
            for action_name, action in actions:
                event.add_action(action_name, action)
            event.add_trigger(trigger)
            maneuver.add_event(event)
        group = xosc.ManeuverGroup(f"{agent.name}_group")
        group.add_actor(agent.name)
        group.add_maneuver(maneuver)
        act.add_maneuver_group(group)
    return act


def _start_trigger(agent: BoundAgent, stage_name: str, label: str, minor: int):
    """When the agent's action starts: at once, after a delay, when someone is within reach, or both."""
    t = agent.trigger
    conditions = []
    if t is not None and t.within_m is not None:
        conditions.append(xosc.EntityTrigger(f"{label}_near", 0, xosc.ConditionEdge.rising,
                                             xosc.RelativeDistanceCondition(t.within_m, xosc.Rule.lessThan,
                                                                            _EUCLIDEAN[minor >= 1],
                                                                            t.of, alongroute=False, freespace=False),
                                             agent.name))
    delay = t.after_s if t is not None and t.after_s is not None else 0.0
    if delay or not conditions:
        conditions.append(xosc.ValueTrigger(f"{label}_time", delay, xosc.ConditionEdge.none,
                                            xosc.StoryboardElementStateCondition(
                                                xosc.StoryboardElementType.act, stage_name,
                                                xosc.StoryboardElementState.runningState)))
    if len(conditions) == 1:
        return conditions[0]
    group = xosc.ConditionGroup()
    for condition in conditions:
        group.add_condition(condition)
    trigger = xosc.Trigger()
    trigger.add_conditiongroup(group)
    return trigger


_EUCLIDEAN = {False: xosc.RelativeDistanceType.cartesianDistance, True: xosc.RelativeDistanceType.euclidianDistance}


def _events(agent: BoundAgent, scene: BoundScene, stage_name: str, minor: int):
    """(event name, [(action name, action)], trigger) for each step of the agent's action."""
    now = xosc.ValueTrigger(f"{agent.name}_at_once", 0, xosc.ConditionEdge.none,
                            xosc.StoryboardElementStateCondition(xosc.StoryboardElementType.act, stage_name,
                                                                 xosc.StoryboardElementState.runningState))
    step = xosc.TransitionDynamics(xosc.DynamicsShapes.step, xosc.DynamicsDimension.time, 0)
    events = []
    if agent.appear is not None:  # joins the scene now, beside the ego as it is at this moment
        ego = next(a.name for a in scene.agents if a.is_ego)
        position = xosc.RelativeLanePosition(agent.appear.dlane, ego, 0, ds=agent.appear.ds)
        events.append((f"{agent.name}_appears", [("appear", xosc.TeleportAction(position)),
                                                 ("set_speed", xosc.AbsoluteSpeedAction(agent.speed_mps, step))],
                       now))
    label = f"{agent.name}_{agent.action}"
    start = _start_trigger(agent, stage_name, label, minor)
    actions = []
    if agent.route:  # where it drives is set at once; the action itself may wait for its trigger
        route = xosc.Route(f"{agent.name}_route")
        for point in agent.route:
            route.add_waypoint(_lane_position(point), xosc.RouteStrategy.shortest)
        route_action = ("route", xosc.AssignRouteAction(route))
        if agent.trigger is None:
            actions.append(route_action)
        else:
            events.append((f"{agent.name}_route", [route_action], now))
    if agent.lane_change is not None:
        actions.append(("lane_change", xosc.RelativeLaneChangeAction(
            agent.lane_change, agent.name,
            xosc.TransitionDynamics(xosc.DynamicsShapes.sinusoidal, xosc.DynamicsDimension.time, 3.0))))
    if agent.cross_to is not None:
        actions.append(("cross", xosc.AcquirePositionAction(_lane_position(agent.cross_to))))
    if agent.walk_to is not None:
        actions.append(("walk", xosc.AcquirePositionAction(_lane_position(agent.walk_to))))
    if agent.action in ("stop", "block_the_ego"):
        brake = {"cautious": 3.0, "normal": 5.0, "aggressive": 8.0}[agent.behavior]
        actions.append(("brake", xosc.AbsoluteSpeedAction(
            0, xosc.TransitionDynamics(xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, brake))))
    if not actions:  # go_straight on an open road: hold the speed
        actions.append(("keep_speed", xosc.AbsoluteSpeedAction(agent.speed_mps, step)))
    events.append((label, actions, start))
    return events


@functools.cache
def _schema(version: str) -> etree.XMLSchema:
    folder = {"1.0": "1.0.0", "1.1": "1.1.0", "1.2": "1.2.0", "1.3": "1.3.0"}[version]
    # the package's folder, found without importing it (its __init__ loads the whole checker bundle)
    package = Path(importlib.util.find_spec("qc_openscenario").submodule_search_locations[0])
    path = package / "schema" / folder / "OpenSCENARIO.xsd"
    return etree.XMLSchema(etree.parse(str(path)))


def validate(data: bytes, version: str) -> None:
    """Validate against the official ASAM XSD of the version; a failure is a fault in ttsgc."""
    schema = _schema(version)
    document = etree.fromstring(data)
    if not schema.validate(document):
        errors = "; ".join(f"line {e.line}: {e.message}" for e in list(schema.error_log)[:5])
        raise EmitError(f"the emitted OpenSCENARIO {version} does not validate against the ASAM XSD: {errors}")
