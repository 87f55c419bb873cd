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
  ScenarioRunner's EndOfRoadCondition fails its trigger as soon as the vehicle leaves its first road.
The generic emitter already writes what both players read alike (no lane-relative headings, trigger states
ScenarioRunner accepts); the result is validated against the 1.0 XSD and linted against carla.toml, and
anything left that ScenarioRunner does not read is an error naming it, raised before anything is written.
"""

from __future__ import annotations

import re

from lxml import etree

from ttsgc.binding.scene import BoundScene
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
    _entities(root, scene)
    _lane_changes(root, scene)
    _rain(root, scene)
    _drop_map_edge_exits(root)
    unreadable_stops = _stop_in_acts(root)
    _criteria(root, scene)
    data = etree.tostring(root, xml_declaration=True, encoding="utf-8", pretty_print=True)
    reparsed = etree.fromstring(data)  # line numbers of the file as written
    left = [f"line {f.line}: {f.what}" for f in errors(lint_tree(reparsed, "carla"))]
    return data, unreadable_stops + left


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
