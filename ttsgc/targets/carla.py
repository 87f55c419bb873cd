"""The carla target: the OpenSCENARIO 1.0 that CARLA ScenarioRunner reads, as a thin layer over the generic
1.0 emission. Its rules, and what they rest on, are data in carla.toml; this module applies them:

- the map: a CARLA town (file stem Town01..Town10HD) is named by its town name in LogicFile, so ScenarioRunner
  loads the town itself; any other map keeps its .xodr file;
- entities: each agent type's CARLA blueprint (Vehicle name, Pedestrian model); the ego is named `hero` (the
  role name CARLA's clients attach to; unless an agent already has that name) and marked with the Property
  type=ego_vehicle, the others simulation;
- lane changes: over a distance (the speed times the generic file's duration), since ScenarioRunner drops a
  time; the shape is never read (written linear, as its table says);
- weather: in Init (the only place its table says it is read; every part of it there, as the parser needs); rain's intensity on 1.0's 0..1 scale; snow cannot be expressed;
- pass/fail: ScenarioRunner's criteria, each a ParameterCondition named criteria_<Test> in a condition group
  of its own in the Storyboard's StopTrigger (the form of ScenarioRunner's own examples): CollisionTest for the
  ego always, RunningRedLightTest on an approach with traffic lights, RunningStopTest on one with a stop sign.
  ScenarioRunner never evaluates the Storyboard's StopTrigger as a trigger (it only takes the criteria from it);
- the end: a run ends when every Act has ended, so each Act's StopTrigger gets a copy of the scene's stop groups
  (an Act's group is any-of there, so a group of several conditions is an error);
- the map edge: the generic file's events that delete a vehicle at the end of its road are dropped, since
  ScenarioRunner's EndOfRoadCondition fails its trigger as soon as the vehicle leaves its first road;
- later stages: ScenarioRunner spawns every entity when the run starts, so an entity that enters later
  (the generic file's Story AddEntityAction) is spawned parked below its place with its physics off and
  teleported to a fixed lane position when its stage starts (carla.toml [late_entry]). An entity placed
  relative to the ego gets the lane position it would have beside the ego when the ego's arrival starts the
  stage; any other start leaves the ego's place unknown before the run, and the scene is refused.
The generic emitter already writes what both players read alike (no lane-relative headings, trigger states
ScenarioRunner accepts); the result is validated against the 1.0 XSD and linted against carla.toml, and
anything left that ScenarioRunner does not read is an error naming it, raised before anything is written.
"""

from __future__ import annotations

import math
import re

from lxml import etree

from ttsgc.binding.place import LanePos
from ttsgc.binding.scene import BoundScene
from ttsgc.roads.opendrive import OpenDrive, load_opendrive
from ttsgc.scenario import Scenario
from ttsgc.targets.coverage import coverage, errors, lint_tree

EGO_ROLE_NAME = "hero"
LANE_CHANGE_S = 3.0  # the generic file's lane change duration, turned into a distance at the body's speed
MIN_LANE_CHANGE_M = 10.0
RAIN_INTENSITY = {"soft_rain": 0.3, "mid_rain": 0.6, "hard_rain": 1.0}  # 1.0's Precipitation intensity, 0..1
UNEXPRESSIBLE_WEATHER = {"snow": "CARLA's weather has no snow (carla.toml: Precipitation precipitationType)"}


def _data() -> dict:
    return coverage("carla").data


def blueprint(agent_type: str) -> str:
    return _data()["blueprints"][agent_type]


def town(map_path: str) -> str | None:
    """The CARLA town a map file is, by its stem, else None."""
    stem = re.sub(r"\.xodr$", "", map_path.replace("\\", "/").rsplit("/", 1)[-1], flags=re.IGNORECASE)
    return stem if stem in _data()["towns"]["names"] else None


def needs(scenario: Scenario) -> list[str]:
    """What the scene needs that ScenarioRunner cannot express, each named as the scene says it."""
    problems = []
    weather = scenario.weather
    if weather is not None and weather.condition in UNEXPRESSIBLE_WEATHER:
        problems.append(f"weather {weather.condition}: {UNEXPRESSIBLE_WEATHER[weather.condition]}")
    return problems


def criteria(scene: BoundScene) -> list[str]:
    """ScenarioRunner's tests for this scene (carla.toml [criteria]): always, and per signal of the ego's approach."""
    table = _data()["criteria"]
    names = list(table["always"])
    for signal in scene.approach_signals:
        names += [n for n in table.get(signal, []) if n not in names]
    return names


def adapt(generic: bytes, scene: BoundScene) -> tuple[bytes, list[str]]:
    """The CARLA file made from the generic 1.0 file of the same scene, and what in it ScenarioRunner would not
    read (empty when it reads all of it)."""
    root = etree.fromstring(generic, etree.XMLParser(remove_blank_text=True))  # re-indented when written
    _map(root, scene)
    late = _late_entries(root, scene)
    _entities(root, scene)
    _lane_changes(root, scene)
    _rain(root, scene)
    _drop_map_edge_exits(root)
    unreadable_stops = _stop_in_acts(root)
    _criteria(root, scene)
    data = etree.tostring(root, xml_declaration=True, encoding="utf-8", pretty_print=True)
    reparsed = etree.fromstring(data)  # line numbers of the file as written
    left = [f"line {f.line}: {f.what}" for f in errors(lint_tree(reparsed, "carla"))]
    return data, late + unreadable_stops + left


def _map(root: etree._Element, scene: BoundScene) -> None:
    name = town(scene.map_path)
    if name is not None:
        root.find("RoadNetwork/LogicFile").set("filepath", name)


def _rename(root: etree._Element, old: str, new: str) -> None:
    for element in root.iter():
        if not isinstance(element.tag, str):
            continue
        for attribute in ("entityRef", "masterEntityRef"):
            if element.get(attribute) == old:
                element.set(attribute, new)
        if element.tag == "ScenarioObject" and element.get("name") == old:
            element.set("name", new)


def _entities(root: etree._Element, scene: BoundScene) -> None:
    objects = {o.get("name"): o for o in root.iter("ScenarioObject")}
    names = {a.name for a in scene.agents}
    for agent in scene.agents:
        body = objects[agent.name]
        print_name = blueprint(agent.type)
        pedestrian = body.find("Pedestrian")
        if pedestrian is not None:
            pedestrian.set("model", print_name)
            pedestrian.set("name", print_name)
            holder = pedestrian
        else:
            vehicle = body.find("Vehicle")
            vehicle.set("name", print_name)
            holder = vehicle
        properties = holder.find("Properties")
        if properties is None:
            properties = etree.SubElement(holder, "Properties")
        role = etree.Element("Property", name="type", value="ego_vehicle" if agent.is_ego else "simulation")
        properties.insert(0, role)
    ego = next(a for a in scene.agents if a.is_ego)
    if EGO_ROLE_NAME not in names:
        _rename(root, ego.name, EGO_ROLE_NAME)


def _late_entries(root: etree._Element, scene: BoundScene) -> list[str]:
    """Turn each Story AddEntityAction into ScenarioRunner's way of a late entry (carla.toml [late_entry]):
    the entity parked below its place from the start, physics off, and a TeleportAction to a LanePosition when
    its stage starts. Returns what cannot be turned so, each named."""
    rule = _data()["late_entry"]
    entries = [a for a in root.iter("AddEntityAction") if any(p.tag == "Story" for p in a.iterancestors())]
    if not entries:
        return []
    odr = load_opendrive(scene.map_path)
    ego = next(a for a in scene.agents if a.is_ego)
    problems = []
    for add in entries:
        entity_action = add.getparent()
        name = entity_action.get("entityRef")
        action = entity_action.getparent().getparent()  # Action / GlobalAction / EntityAction
        act = next(p for p in add.iterancestors() if p.tag == "Act")
        if _actor_of(add) != name:
            problems.append(f"act '{act.get('name')}': the AddEntityAction of '{name}' is not in its own "
                            f"maneuver group (a TeleportAction acts on the group's actor)")
            continue
        place = _entry_place(add.find("Position"), act, ego.name, odr)
        if isinstance(place, str):
            problems.append(f"act '{act.get('name')}': '{name}' enters {place}")
            continue
        for child in list(action):
            action.remove(child)
        teleport = etree.SubElement(etree.SubElement(action, "PrivateAction"), "TeleportAction")
        etree.SubElement(etree.SubElement(teleport, "Position"), "LanePosition", roadId=place.road,
                         laneId=str(place.lane), s=_number(place.s), offset=_number(place.offset))
        pose = odr.roads[place.road].lane_point(place.s, place.lane)
        private = etree.SubElement(root.find("Storyboard/Init/Actions"), "Private", entityRef=name)
        parked = etree.SubElement(etree.SubElement(etree.SubElement(private, "PrivateAction"), "TeleportAction"),
                                  "Position")
        etree.SubElement(parked, "WorldPosition", x=_number(pose.x), y=_number(pose.y),
                         z=_number(-rule["parking_depth_m"]), h=_number(pose.hdg))
        body = next(o for o in root.iter("ScenarioObject") if o.get("name") == name)
        holder = body.find("Vehicle") if body.find("Vehicle") is not None else body.find("Pedestrian")
        properties = holder.find("Properties")
        if properties is None:
            properties = etree.SubElement(holder, "Properties")
        properties.append(etree.Element("Property", name=rule["physics_property"], value=rule["physics_off"]))
    return problems


def _number(value: float) -> str:
    return f"{round(value, 3) + 0.0}"  # + 0.0: never -0.0


def _entry_place(position: etree._Element, act: etree._Element, ego: str, odr: OpenDrive) -> LanePos | str:
    """Where an entity enters, as a fixed lane position, else why it cannot be fixed before the run."""
    fixed = position.find("LanePosition")
    if fixed is not None:
        return LanePos(road=fixed.get("roadId"), lane=int(fixed.get("laneId")), s=float(fixed.get("s")),
                       offset=float(fixed.get("offset", "0") or 0))
    relative = position.find("RelativeLanePosition")
    if relative is None or relative.get("entityRef") != ego or float(relative.get("offset", "0") or 0) != 0:
        return "at a position that is neither a lane position nor one in a lane beside the ego"
    at_start = ego_at_stage_start(act, ego, odr)
    if isinstance(at_start, str):
        return at_start
    return lane_position_beside(at_start, int(relative.get("dLane")), float(relative.get("ds")), odr)


def ego_at_stage_start(act: etree._Element, ego: str, odr: OpenDrive) -> LanePos | str:
    """The ego's lane position when the act starts, when its start is the ego's arrival: the act's one
    condition is the ego coming within d of a lane position P, so the ego is on P's lane, upstream of P, at
    straight-line distance d from it. Else why the ego's place is not known before the run."""
    conditions = act.findall("StartTrigger/ConditionGroup/Condition")
    arrival = conditions[0].find("ByEntityCondition") if len(conditions) == 1 else None
    distance = arrival.find("EntityCondition/DistanceCondition") if arrival is not None else None
    target = distance.find("Position/LanePosition") if distance is not None else None
    if (target is None or distance.get("rule") != "lessThan"
            or [e.get("entityRef") for e in arrival.iter("EntityRef")] != [ego]):
        return ("beside the ego, and the stage does not start on the ego's arrival at a place, so where the ego "
                "is then is known only when the scene is played")
    road = odr.roads[target.get("roadId")]
    lane, s_target, within = int(target.get("laneId")), float(target.get("s")), float(distance.get("value"))
    goal = road.lane_point(s_target, lane)
    upstream = 1.0 if lane > 0 else -1.0  # a right lane (id < 0) is driven towards larger s
    limit = road.length - s_target if upstream > 0 else s_target

    def apart(u: float) -> float:
        p = road.lane_point(s_target + upstream * u, lane)
        return math.hypot(p.x - goal.x, p.y - goal.y)

    if apart(limit) < within:
        return (f"beside the ego, and the ego comes within {within:g} m of road {road.id} s={s_target:g} before "
                f"it is on that road")
    low, high = 0.0, limit
    for _ in range(60):
        middle = (low + high) / 2
        low, high = (middle, high) if apart(middle) < within else (low, middle)
    return LanePos(road=road.id, lane=lane, s=round(s_target + upstream * high, 3))


def lane_position_beside(origin: LanePos, dlane: int, ds: float, odr: OpenDrive) -> LanePos | str:
    """The lane position a RelativeLanePosition names, as OpenSCENARIO defines it and esmini reads it: ds
    along the road's s from origin, dlane added to origin's lane id (the centre lane, 0, skipped)."""
    road = odr.roads[origin.road]
    s = origin.s + ds
    if not 0.0 <= s <= road.length:
        return f"beside the ego {ds:+g} m along road {road.id}, past its end"
    lane = origin.lane + dlane
    if lane == 0 or (lane > 0) != (origin.lane > 0):
        lane += 1 if dlane > 0 else -1
    if lane not in road.section_at(s).lanes:
        return f"beside the ego {dlane:+d} lane ids across, where road {road.id} has no lane {lane}"
    return LanePos(road=road.id, lane=lane, s=round(s, 3))


def _actor_of(element: etree._Element) -> str | None:
    """The entity a private action acts on: its Private's entityRef in Init, its ManeuverGroup's actor in a
    Story."""
    for ancestor in element.iterancestors():
        if ancestor.tag == "Private":
            return ancestor.get("entityRef")
        if ancestor.tag == "ManeuverGroup":
            actor = ancestor.find("Actors/EntityRef")
            return actor.get("entityRef") if actor is not None else None
    return None


def _lane_changes(root: etree._Element, scene: BoundScene) -> None:
    speeds = {a.name: a.speed_mps for a in scene.agents}
    ego = next(a for a in scene.agents if a.is_ego)
    speeds.setdefault(EGO_ROLE_NAME, ego.speed_mps)
    for dynamics in root.iter("LaneChangeActionDynamics"):
        speed = speeds.get(_actor_of(dynamics) or "", 0.0)
        dynamics.set("dynamicsShape", "linear")
        dynamics.set("dynamicsDimension", "distance")
        dynamics.set("value", f"{max(MIN_LANE_CHANGE_M, round(speed * LANE_CHANGE_S, 1))}")


def _rain(root: etree._Element, scene: BoundScene) -> None:
    condition = scene.scenario.weather.condition if scene.scenario.weather else None
    for precipitation in root.iter("Precipitation"):
        if precipitation.get("precipitationType") == "rain":
            precipitation.set("intensity", f"{RAIN_INTENSITY.get(condition, 1.0)}")


def _drop_map_edge_exits(root: etree._Element) -> None:
    """Drop the events that delete a vehicle at the end of its road (the generic file's map_edge act), and what
    they leave empty. ScenarioRunner reads EndOfRoadCondition as an inverted EndofRoadTest: it fires when the
    entity leaves the road it was on (a junction's connecting road counts), and then returns FAILURE, so the
    event never runs and the failure ends the story (carla.toml: EndOfRoadCondition)."""
    for event in list(root.iter("Event")):
        trigger = event.find("StartTrigger")
        actions = event.findall("Action")
        if (trigger is not None and trigger.find(".//EndOfRoadCondition") is not None and actions
                and all(a.find("GlobalAction/EntityAction/DeleteEntityAction") is not None for a in actions)):
            event.getparent().remove(event)
    for tag, child in (("Maneuver", "Event"), ("ManeuverGroup", "Maneuver"), ("Act", "ManeuverGroup")):
        for element in list(root.iter(tag)):
            if element.find(child) is None:
                element.getparent().remove(element)


def _stop_in_acts(root: etree._Element) -> list[str]:
    """Copy the Storyboard's stop conditions into each Act's StopTrigger, and name what cannot be copied.
    ScenarioRunner never evaluates the Storyboard's StopTrigger (it only takes its criteria_* conditions); it
    ends a run when every Act has ended, and an Act's StopTrigger ends it. It reads an Act's condition group as
    any-of, so only groups of one condition keep their meaning (open_scenario.py: _create_behavior,
    _create_condition_container)."""
    stop = root.find("Storyboard/StopTrigger")
    groups = [g for g in stop.findall("ConditionGroup") if g.find("Condition") is not None] if stop is not None else []
    problems = [f"Storyboard StopTrigger: a ConditionGroup of {len(g.findall('Condition'))} conditions "
                f"(ScenarioRunner reads an Act's StopTrigger group as any-of, not all-of)"
                for g in groups if len(g.findall("Condition")) > 1]
    if problems:
        return problems
    for act in root.iter("Act"):
        act_stop = act.find("StopTrigger")
        if act_stop is None:
            act_stop = etree.SubElement(act, "StopTrigger")
        for group in groups:
            copy = etree.fromstring(etree.tostring(group))
            for condition in copy.iter("Condition"):
                condition.set("name", f"{condition.get('name')}_{act.get('name')}")
            act_stop.append(copy)
    return problems


def _criteria(root: etree._Element, scene: BoundScene) -> None:
    stop = root.find("Storyboard/StopTrigger")
    group = etree.SubElement(stop, "ConditionGroup")
    for name in criteria(scene):
        condition = etree.SubElement(group, "Condition", name=f"criteria_{name}", delay="0",
                                     conditionEdge="rising")
        by_value = etree.SubElement(condition, "ByValueCondition")
        etree.SubElement(by_value, "ParameterCondition", parameterRef="", value="", rule="lessThan")
