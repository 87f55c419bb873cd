"""BoundScene -> OpenSCENARIO XML (1.0 to 1.3) with scenariogeneration.xosc, validated against the ASAM XSD.

A file means what the standard and the real players read in it, not what ttsgc's own player meant:
- a lane position faces along its lane's driving direction with no Orientation of its own (esmini reads a
  relative heading against the lane's direction, CARLA ScenarioRunner adds any h to it whatever its type);
- Init places the first stage's agents; the agents of a later stage get no Init action (so they are inactive)
  and enter with an AddEntityAction when their stage starts;
- every trigger can fire: edge `none` on conditions that may already hold at the first evaluation, and
  StoryboardElementStates CARLA accepts (completeState, endTransition);
- people and bikes that cross or walk follow a polyline trajectory at their speed, standing until their trigger
  (AcquirePositionAction is routing and collapses to no movement across a road);
- the events of one maneuver run in parallel, so a later one never stops an earlier one;
- the ego stops for a crosser who is not aggressive because the file says so (binding's EgoYield), not
  because a player's driver would; a vehicle behind one that stops brakes behind it, for the same reason.
One Story holds one Act per stage, each starting when the previous act completes and what that does not wait
for (a movement through the junction) is done; the weather is an EnvironmentAction; a stop trigger always
fires. Each agent's intent is written into its Properties (ttsgc.intent) so a judge can read it from the file alone.
"""

from __future__ import annotations

import datetime as dt
import math
from xml.etree import ElementTree

from lxml import etree

from ttsgc import intent as I
from ttsgc import xsd
from ttsgc import vocabulary as V
from ttsgc.binding.place import (COMING_UP_IN_THE_LANE_CHANGED_TO, LANE_CHANGE_ROOM_M, YIELD_SET_OFF_MPS2,
                                 BoundAgent, LanePos, LaterAction)
from ttsgc.binding.scene import BoundScene
from ttsgc.emit.lean_import import openscenario_writer
from ttsgc.errors import TtsgcError

xosc = openscenario_writer()
VersionBase = xosc.VersionBase

VERSIONS = ("1.0", "1.1", "1.2", "1.3")
DEFAULT_VERSION = "1.3"
CREATION_DATE = dt.datetime(2026, 1, 1, 0, 0, 0)

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
            init.add_init_action(agent.name, xosc.AbsoluteSpeedAction(_initial_speed(agent), step))
    story = xosc.Story("story")
    durations = stage_durations(scene)
    for k, stage in enumerate(scene.scenario.stages):
        story.add_act(_act(scene, k, stage.name, minor))
    for extra in (_ego_yields_act(scene, minor), _following_act(scene, minor)):
        if extra is not None:
            story.add_act(extra)
    edge = _map_edge_act(scene, minor)
    if edge is not None:
        story.add_act(edge)
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
    """No Orientation: every player then faces the body along its lane's driving direction (left lanes,
    ids > 0, included); any h would be added to that direction by esmini and CARLA alike."""
    return xosc.LanePosition(pos.s, pos.offset, pos.lane, pos.road)


DRIVES_ON_M = 40.0  # how far a vehicle drives on past the end of its move through a junction before it leaves


def _map_edge_act(scene: BoundScene, minor: int) -> xosc.Act | None:
    """A vehicle that runs out of road leaves the scene (DeleteEntityAction), as it leaves SUMO's network:
    at a map's edge esmini stops it dead, and whoever follows would pile into it. A vehicle other than the
    ego that moved through a junction leaves too, DRIVES_ON_M past its route's end: beyond its last waypoint
    a player picks its way at random (esmini), and vehicles done with their moves would meet far from the
    scene while it lasts. An act of its own, never waited for, so the stages do not wait for a vehicle to
    leave."""
    vehicles = [a for a in scene.agents if a.type != "pedestrian"]
    if not vehicles:
        return None
    act = xosc.Act("map_edge", _always("map_edge_start", 0.0, minor))
    for agent in vehicles:
        trigger = xosc.Trigger()
        trigger.add_conditiongroup(xosc.ConditionGroup().add_condition(
            xosc.EntityTrigger(f"{agent.name}_out_of_road", 0, xosc.ConditionEdge.none, xosc.EndOfRoadCondition(0),
                               agent.name)))
        if len(agent.route) >= 2 and not agent.is_ego:
            drives_on = round(max(3.0, DRIVES_ON_M / max(agent.speed_mps, 1.0)), 3)
            trigger.add_conditiongroup(xosc.ConditionGroup().add_condition(
                xosc.EntityTrigger(f"{agent.name}_moved_through", drives_on, xosc.ConditionEdge.none,
                                   xosc.DistanceCondition(5.0, xosc.Rule.lessThan, _lane_position(agent.route[-1]),
                                                          alongroute=False, freespace=False,
                                                          distance_type=_EUCLIDEAN[minor >= 1]), agent.name)))
        leaves = (f"{agent.name}_leaves", [("leave", xosc.DeleteEntityAction(agent.name))], trigger)
        act.add_maneuver_group(_group(agent.name, f"{agent.name}_edge", f"{agent.name}_edge_group", [leaves]))
    return act


def _ego_yields_act(scene: BoundScene, minor: int) -> xosc.Act | None:
    """The ego stopping for whoever crosses its way (binding's EgoYield), in the file itself so that every
    player plays it alike: one event brakes the ego once the crosser has set off (it has left its start
    towards the far side: a state that lasts, unlike the crossing event's one-step startTransition) and the
    ego is in the stretch short of the crossing; another sets it off again at a brisk rate once that crossing
    event is complete and none of the same stage's other crossers it yields to is still on the road. An act
    of its own, never waited for: a crosser that never comes leaves its events standing, as map_edge does."""
    ego = next(a for a in scene.agents if a.is_ego)
    crossers = [a for a in scene.agents if a.ego_yield is not None and _ego_speed_in_stage(ego, a.stage) > 0]
    if not crossers:
        return None
    events = []
    for crosser in crossers:
        y = crosser.ego_yield
        crossing = f"{crosser.name}_{crosser.action}"
        brakes = f"{ego.name}_yields_to_{crosser.name}"
        set_off = xosc.EntityTrigger(f"{crosser.name}_set_off", 0, xosc.ConditionEdge.none, _within(
            y.crossing_m - 0.1, crosser.cross_to, minor), crosser.name)
        near = xosc.EntityTrigger(f"{brakes}_near", 0, xosc.ConditionEdge.none,
                                  _within(y.radius_m, y.centre, minor), ego.name)
        events.append((brakes, [("brake", xosc.AbsoluteSpeedAction(0, xosc.TransitionDynamics(
            xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, y.rate_mps2)))], _all_of([set_off, near])))
        done = [_state(f"{crosser.name}_crossed", xosc.StoryboardElementType.event, crossing),
                _state(f"{brakes}_done", xosc.StoryboardElementType.event, brakes)]
        others = [o for o in crossers if o is not crosser and o.stage == crosser.stage][:4]
        trigger = xosc.Trigger()
        for k in range(2 ** len(others)):  # each other crosser: either across already or not yet set off
            group = xosc.ConditionGroup()
            for condition in done:
                group.add_condition(condition)
            for n, other in enumerate(others):
                if k >> n & 1:
                    group.add_condition(_state(f"{other.name}_crossed_{k}", xosc.StoryboardElementType.event,
                                               f"{other.name}_{other.action}"))
                else:
                    group.add_condition(xosc.EntityTrigger(f"{other.name}_waits_{k}", 0, xosc.ConditionEdge.none,
                                                           _within(0.1, other.start, minor), other.name))
            trigger.add_conditiongroup(group)
        events.append((f"{ego.name}_goes_on_after_{crosser.name}", [("set_off", xosc.AbsoluteSpeedAction(
            _ego_speed_in_stage(ego, crosser.stage), xosc.TransitionDynamics(
                xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, YIELD_SET_OFF_MPS2)))], trigger))
    act = xosc.Act("ego_yields", _always("ego_yields_start", 0.0, minor))
    act.add_maneuver_group(_group(ego.name, f"{ego.name}_yields", f"{ego.name}_yields_group", events))
    return act


def _ego_speed_in_stage(ego: BoundAgent, stage: int) -> float:
    """The speed the ego drives at in a stage: its own, or the last one a later line of it gave it."""
    speed = ego.speed_mps
    for step in ego.later:
        if step.stage <= stage and step.speed_mps is not None:
            speed = step.speed_mps
    return speed


def _within(value: float, position: LanePos, minor: int) -> xosc.DistanceCondition:
    return xosc.DistanceCondition(round(value, 3), xosc.Rule.lessThan, _lane_position(position), alongroute=False,
                                  freespace=False, distance_type=_EUCLIDEAN[minor >= 1])


def _state(label: str, kind, ref: str) -> xosc.ValueTrigger:
    return xosc.ValueTrigger(label, 0, xosc.ConditionEdge.none, xosc.StoryboardElementStateCondition(
        kind, ref, xosc.StoryboardElementState.completeState))


def _all_of(conditions) -> xosc.Trigger:
    group = xosc.ConditionGroup()
    for condition in conditions:
        group.add_condition(condition)
    trigger = xosc.Trigger()
    trigger.add_conditiongroup(group)
    return trigger


FOLLOW_MARGIN_M = 2.0  # free road a follower keeps to the vehicle it stops behind
LEADER_BRAKING = 0.95  # a leader that only follows has begun to brake once below this share of its speed


def followers_of_stopping(scene: BoundScene) -> list[tuple[BoundAgent, BoundAgent]]:
    """(follower, leader): a vehicle placed behind one that stops, in the same lane, or whose route through the
    junction leads into its lane, that itself drives on in that lane; the leader nearest ahead. A follower is
    a leader in turn: the car behind an ego that brakes for a broken-down car brakes too. A player's
    car-following (SUMO) stops it in time; esmini has none and drives it into the stopped body, so the file
    must say it."""
    def vehicle(agent: BoundAgent) -> bool:
        return agent.stage == 0 and agent.start is not None and agent.type != "pedestrian" \
            and not _trajectory_bound(agent) and agent.lane_change is None

    def gap(follower: BoundAgent, leader: BoundAgent) -> float | None:
        """How far ahead the leader stands, when the follower drives into it; None when it does not."""
        lane = (leader.start.road, leader.start.lane)
        along = 1 if leader.start.lane < 0 else -1  # a right lane (id < 0) drives along s
        if (follower.start.road, follower.start.lane) == lane and (leader.start.s - follower.start.s) * along > 0:
            return (leader.start.s - follower.start.s) * along
        if len(follower.route) >= 2 and follower.route[-1].road != follower.start.road and \
                (follower.route[-1].road, follower.route[-1].lane) == lane:  # in the lane its route leads into
            return math.inf
        return None

    def sets_off_later(agent: BoundAgent) -> bool:  # an ego that waits, then drives on ('once green, we turn')
        return agent.is_ego and agent.action == "stop" and any(
            step.action in DRIVING_ON for step in agent.later)

    movers = [a for a in scene.agents if vehicle(a) and (a.action not in ("stop", "block_the_ego") or
                                                         sets_off_later(a))
              and not a.start_delay_s and a.speed_mps > 0]
    leaders = [a for a in scene.agents if vehicle(a) and a.action == "stop"]
    led: dict[str, BoundAgent] = {}
    while True:  # leaders only join, so each follower's nearest leader only comes nearer: this settles
        nearest = {}
        for follower in movers:
            ahead = [(gap(follower, leader), k, leader) for k, leader in enumerate(leaders) if leader is not follower]
            ahead = [x for x in ahead if x[0] is not None]
            if ahead:
                nearest[follower.name] = min(ahead, key=lambda x: x[:2])[2]
        if nearest.keys() == led.keys() and all(nearest[n] is led[n] for n in led):
            break
        led = nearest
        leaders += [f for f in movers if f.name in led and f not in leaders]
    return [(follower, led[follower.name]) for follower in movers if follower.name in led]


def _following_act(scene: BoundScene, minor: int) -> xosc.Act | None:
    """A vehicle behind one that stops brakes at its own rate once that one has begun to stop and it is within
    its braking distance of it (centre to centre, with both half lengths and FOLLOW_MARGIN_M), so it stands
    behind it. An act of its own, never waited for: a follower that turns off before never brakes."""
    pairs = followers_of_stopping(scene)
    if not pairs:
        return None
    act = xosc.Act("following", _always("following_start", 0.0, minor))
    rule = xosc.Rule.greaterOrEqual if minor >= 1 else xosc.Rule.greaterThan
    for follower, leader in pairs:
        rate = BRAKE_RATE[follower.behavior]
        reach = follower.speed_mps ** 2 / (2 * rate) + (follower.length + leader.length) / 2 + FOLLOW_MARGIN_M
        group = xosc.ConditionGroup()
        label = f"{follower.name}_stops_behind_{leader.name}"
        t = leader.trigger
        if leader.action != "stop":  # a follower itself: it stops once it brakes, for the one ahead of it
            group.add_condition(xosc.EntityTrigger(
                f"{label}_leader_brakes", 0, xosc.ConditionEdge.none,
                xosc.SpeedCondition(round(leader.speed_mps * LEADER_BRAKING, 3), xosc.Rule.lessThan), leader.name))
        else:
            group.add_condition(xosc.ValueTrigger(f"{label}_after", 0, xosc.ConditionEdge.none,
                                                  xosc.SimulationTimeCondition(
                                                      round(t.after_s if t is not None and t.after_s else 0.0, 3), rule)))
        if leader.action == "stop" and t is not None and t.within_m is not None:  # it stops when someone is within reach of it
            group.add_condition(xosc.EntityTrigger(
                f"{label}_leader_near", 0, xosc.ConditionEdge.none,
                xosc.RelativeDistanceCondition(t.within_m, xosc.Rule.lessThan, _EUCLIDEAN[minor >= 1], t.of,
                                               alongroute=False, freespace=False), leader.name))
        group.add_condition(xosc.EntityTrigger(
            f"{label}_near", 0, xosc.ConditionEdge.none,
            xosc.RelativeDistanceCondition(round(reach, 3), xosc.Rule.lessThan, _EUCLIDEAN[minor >= 1], leader.name,
                                           alongroute=False, freespace=False), follower.name))
        trigger = xosc.Trigger()
        trigger.add_conditiongroup(group)
        brake = ("brake", xosc.AbsoluteSpeedAction(0, xosc.TransitionDynamics(
            xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, rate)))
        act.add_maneuver_group(_group(follower.name, f"{label}_maneuver", f"{label}_group",
                                      [(label, [brake], trigger)]))
    return act


def _group(actor: str, maneuver_name: str, group_name: str, events) -> xosc.ManeuverGroup:
    """One actor's maneuver group: each (event name, [(action name, action)], trigger) an event of one maneuver,
    all events parallel (none overrides another)."""
    maneuver = xosc.Maneuver(maneuver_name)
    for event_name, actions, trigger in events:
        event = xosc.Event(event_name, xosc.Priority.parallel)
        for action_name, action in actions:
            event.add_action(action_name, action)
        event.add_trigger(trigger)
        maneuver.add_event(event)
    group = xosc.ManeuverGroup(group_name)
    group.add_actor(actor)
    group.add_maneuver(maneuver)
    return group


def _trajectory_bound(agent: BoundAgent) -> bool:
    """Whether the agent moves along a trajectory of its own (crossing, or walking the sidewalk)."""
    return agent.cross_to is not None or agent.walk_to is not None or _crosses_relative_to_the_ego(agent)


def _crosses_relative_to_the_ego(agent: BoundAgent) -> bool:
    """A later crosser whose start and far side are known only relative to the ego when its stage starts."""
    return agent.appear is not None and agent.appear.cross_dlane is not None


def _initial_speed(agent: BoundAgent) -> float:
    """Bodies that follow a trajectory or wait for their turn through a junction stand until then; the rest
    drive at their speed (a vehicle routed through the junction drives on whatever its trigger: its route is
    its action)."""
    if _trajectory_bound(agent) or agent.start_delay_s:
        return 0.0
    return agent.speed_mps


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
    intent = {I.ACTION: agent.action, I.POSITION: agent.relative_to_ego or "ego", I.ROAD_TYPE: agent.road_type,
              I.BEHAVIOR: agent.behavior, I.TYPE: agent.type, I.STAGE: str(agent.stage),
              I.IS_EGO: str(agent.is_ego).lower(), I.MOVEMENT: agent.movement or "",
              I.TARGET_ROAD: agent.target_road or "", I.MAP: scene.map_name, I.APPROACH: scene.approach}
    if agent.later:
        intent[I.STAGE_ACTIONS] = I.format_stage_actions([(step.stage, step.action) for step in agent.later])
    for name, value in I.properties(intent):
        entity.add_property(name, value)
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


LATER_ACTION_S = 8.0  # the ego's lane change (3 s) or stop, and time to see it done


def stage_durations(scene: BoundScene) -> list[float]:
    """How long each stage takes: its slowest agent's action, waiting for its trigger included, bounded;
    the next stage starts after it and the stop trigger after them all. No time is allowed for red lights:
    the file gives the lights no program, and no player holds a movement at a light nobody runs (a longer
    scene only lets vehicles that finished their moves meet far beyond the junction)."""
    ego = next(a for a in scene.agents if a.is_ego)
    durations = []
    for k, _ in enumerate(scene.scenario.stages):
        longest = 4.0
        for agent in scene.agents:
            if agent.stage != k:
                continue
            wait = agent.start_delay_s + (agent.trigger.after_s if agent.trigger and agent.trigger.after_s else 0.0)
            if agent.trigger and agent.trigger.within_m is not None:
                wait += max(0.0, agent.distance_to_ego_m - agent.trigger.within_m) / max(ego.speed_mps, 1.0)
            speed = max(agent.speed_mps, 1.0)
            if agent.movement:
                action = 45.0 / speed
            elif agent.cross_to is not None or _crosses_relative_to_the_ego(agent):
                action = 40.0 / speed  # wide roads: a crossing may be 30 m and more
            elif agent.walk_to is not None and agent.start is not None:
                action = abs(agent.walk_to.s - agent.start.s) / speed + 2.0  # a walk along the sidewalk: its act
                # completes when the walk does, and the next stage waits for it
            else:
                action = 6.0
            longest = max(longest, wait + action)
        for step in ego.later:
            if step.stage == k:
                wait = step.trigger.after_s if step.trigger and step.trigger.after_s else 0.0
                turn = 45.0 / max(ego.speed_mps, 1.0) if step.action in V.TURN_ACTIONS else 0.0
                longest = max(longest, wait + LATER_ACTION_S + turn)
        durations.append(round(min(longest, 120.0), 3))
    return durations


MIN_STAGE_PAUSE_S = 4.0  # a stage whose actions are done at once (a speed held) still plays a while


def stage_pause_s(scene: BoundScene, k: int) -> float:
    """How long after stage k's act completes the next stage starts: what its completion does not already
    wait for. An act completes once every event is done, so a crossing, a stop, a lane change, a trigger
    or a wait are behind it; a route (assigned at once) is not, so a movement through the junction still
    needs its way there and through. Waiting the whole estimated duration again let a slow stage (a walker
    crossing) push the next one past the stop trigger."""
    pause = MIN_STAGE_PAUSE_S
    for agent in scene.agents:
        if agent.stage == k and agent.movement:
            pause = max(pause, 45.0 / max(agent.speed_mps, 1.0))
    ego = next(a for a in scene.agents if a.is_ego)
    for step in ego.later:
        if step.stage == k and step.action in V.TURN_ACTIONS:
            pause = max(pause, 45.0 / max(ego.speed_mps, 1.0))
    return round(min(pause, 120.0), 3)


def _act(scene: BoundScene, k: int, name: str, minor: int) -> xosc.Act:
    acts = scene.scenario.stages
    if k == 0:
        start = _always(f"{name}_start", 0.0, minor)
    else:
        ego = next(a for a in scene.agents if a.is_ego)
        later_turn = any(step.action in V.TURN_ACTIONS for step in ego.later)
        if k == 1 and _drives_its_route_first(scene) and not later_turn:  # the ego's movement ends the first
            # stage: at the far road
            start = xosc.EntityTrigger(f"{name}_start", 0, xosc.ConditionEdge.none,
                                       xosc.DistanceCondition(_on_the_far_road_m(ego), xosc.Rule.lessThan,
                                                              _lane_position(ego.route[-1]),
                                                              alongroute=False, freespace=False,
                                                              distance_type=_EUCLIDEAN[minor >= 1]), ego.name)
        else:
            start = xosc.ValueTrigger(f"{name}_start", stage_pause_s(scene, k - 1), xosc.ConditionEdge.none,
                                      xosc.StoryboardElementStateCondition(xosc.StoryboardElementType.act,
                                                                           acts[k - 1].name,
                                                                           xosc.StoryboardElementState.completeState))
    act = xosc.Act(name, start)
    for agent in scene.agents:
        if agent.stage != k:
            continue
        act.add_maneuver_group(_group(agent.name, f"{agent.name}_maneuver", f"{agent.name}_group",
                                      _events(agent, scene, minor)))
    ego = next(a for a in scene.agents if a.is_ego)
    for agent in scene.agents:
        if agent.stage == k and _crosses_relative_to_the_ego(agent) and agent.appear.yield_within_m is not None \
                and _ego_speed_in_stage(ego, k) > 0:
            act.add_maneuver_group(_ego_yields_to_later_crosser(ego, agent, k, minor))
    for step in ego.later:
        if step.stage == k:
            act.add_maneuver_group(_later_ego_group(ego, step, minor, _ego_stands_before(scene, step)))
            for queued in _queue_ahead_of_a_waiting_ego(scene, step):
                act.add_maneuver_group(_moves_off_with_the_ego(queued, ego, step, minor))
    return act


def _ego_yields_to_later_crosser(ego: BoundAgent, crosser: BoundAgent, k: int, minor: int) -> xosc.ManeuverGroup:
    """The ego's stop for a crosser placed relative to it (binding's _ahead_of_the_moving_ego), as the
    ego_yields act writes it for a crosser with a fixed way: it brakes once it is near the walker, who
    enters beyond that distance and steps out at once, and sets off again once the crossing is done. In the
    crosser's act, so the walker is in the scene when the distance is first read."""
    appear = crosser.appear
    brakes = f"{ego.name}_yields_to_{crosser.name}"
    near = xosc.EntityTrigger(f"{brakes}_near", 0, xosc.ConditionEdge.none, xosc.RelativeDistanceCondition(
        appear.yield_within_m, xosc.Rule.lessThan, _EUCLIDEAN[minor >= 1], crosser.name, alongroute=False,
        freespace=False), ego.name)
    brake = xosc.AbsoluteSpeedAction(0, xosc.TransitionDynamics(xosc.DynamicsShapes.linear,
                                                                xosc.DynamicsDimension.rate, appear.yield_rate_mps2))
    done = _all_of([_state(f"{crosser.name}_crossed", xosc.StoryboardElementType.event,
                           f"{crosser.name}_{crosser.action}"),
                    _state(f"{brakes}_done", xosc.StoryboardElementType.event, brakes)])
    set_off = xosc.AbsoluteSpeedAction(_ego_speed_in_stage(ego, k), xosc.TransitionDynamics(
        xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, YIELD_SET_OFF_MPS2))
    return _group(ego.name, f"{brakes}_maneuver", f"{brakes}_group",
                  [(brakes, [("brake", brake)], near), (f"{ego.name}_goes_on_after_{crosser.name}",
                                                        [("set_off", set_off)], done)])


def _ego_stands_before(scene: BoundScene, step: LaterAction) -> bool:
    """Whether the ego stands when `step` begins: told to stop (and nothing since), or stopped behind a vehicle
    that stops."""
    ego = next(a for a in scene.agents if a.is_ego)
    earlier = [x for x in ego.later if x.stage < step.stage]
    if earlier:
        return earlier[-1].action == "stop"
    return ego.action == "stop" or any(follower.is_ego for follower, _ in followers_of_stopping(scene))


def _queue_ahead_of_a_waiting_ego(scene: BoundScene, step: LaterAction) -> list[BoundAgent]:
    """The vehicles standing ahead of the ego in its lane, when the ego stood until `step` and then drives on
    ('three cars incl. the ego stopped at a red light ... when it goes green the ego goes straight'): the queue
    it waited in moves off with it; left standing, the ego drives into it (in every player)."""
    ego = next(a for a in scene.agents if a.is_ego)
    if ego.start is None or ego.action != "stop" or step.action not in DRIVING_ON or \
            any(x.action != "stop" for x in ego.later if x.stage < step.stage):
        return []
    along = 1 if ego.start.lane < 0 else -1  # a right lane (id < 0) drives along s
    return [a for a in scene.agents if a.stage == 0 and not a.is_ego and a.action == "stop" and a.start is not None
            and a.type != "pedestrian" and a.road_type == "driving" and a.lane_change is None
            and (a.start.road, a.start.lane) == (ego.start.road, ego.start.lane)
            and (a.start.s - ego.start.s) * along > 0]


def _moves_off_with_the_ego(queued: BoundAgent, ego: BoundAgent, step: LaterAction, minor: int) -> xosc.ManeuverGroup:
    """One of the queue ahead sets off when the ego does, at the ego's speed, so the gaps stay as they stood."""
    speed = step.speed_mps if step.speed_mps is not None else ego.speed_mps
    label = f"{queued.name}_moves_off_in_stage_{step.stage}"
    set_off = xosc.AbsoluteSpeedAction(speed, xosc.TransitionDynamics(xosc.DynamicsShapes.step,
                                                                      xosc.DynamicsDimension.time, 0))
    trigger = _start_trigger(queued.model_copy(update={"trigger": step.trigger}), label, minor)
    return _group(queued.name, f"{queued.name}_maneuver_in_stage_{step.stage}",
                  f"{queued.name}_group_in_stage_{step.stage}", [(label, [("set_off", set_off)], trigger)])


def _drives_its_route_first(scene: BoundScene) -> bool:
    """Whether the ego drives its route through the junction in the first stage: an ego told to stop there
    (at a red light), or one that stops behind a vehicle that stops, holds its route but stands before the
    junction, so no later stage may wait for it to reach the far road."""
    ego = next(a for a in scene.agents if a.is_ego)
    stops_behind = any(follower.is_ego for follower, _ in followers_of_stopping(scene))
    return bool(ego.route) and ego.action != "stop" and not stops_behind


def _on_the_far_road_m(ego: BoundAgent) -> float:
    """How near the end of its route the ego is on the road it turned onto, out of the junction: a later
    stage's agents appear relative to the ego in its road's terms, so the stage must not start while the ego
    is still on a connecting road of the junction (10 m at most, 2 m at least)."""
    into = ego.route_end_into_m if ego.route_end_into_m is not None else 10.5
    return round(max(2.0, min(10.0, into - 0.5)), 3)


BRAKE_RATE = V.BRAKE_RATE  # m/s² of a stop
DRIVING_ON = frozenset({"go_straight", *V.TURN_ACTIONS})  # what an ego that waited does when it sets off


def _later_ego_group(ego: BoundAgent, step: LaterAction, minor: int, standing: bool = False) -> xosc.ManeuverGroup:
    """The ego's action in a later stage, one event written as any agent's: the lane change relative to
    itself (setting off first when it stands), a speed it is given, a stop braking at its behaviour's rate;
    going straight holds its speed."""
    step_dynamics = xosc.TransitionDynamics(xosc.DynamicsShapes.step, xosc.DynamicsDimension.time, 0)
    actions = []
    if step.lane_change is not None:
        actions.append(("lane_change", xosc.RelativeLaneChangeAction(
            step.lane_change, ego.name,
            xosc.TransitionDynamics(xosc.DynamicsShapes.sinusoidal, xosc.DynamicsDimension.time, 3.0))))
    if step.action == "stop":
        actions.append(("brake", xosc.AbsoluteSpeedAction(0, xosc.TransitionDynamics(
            xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, BRAKE_RATE[step.behavior]))))
    elif step.action in V.TURN_ACTIONS:  # it waited before the junction on the route it was given: sets off
        actions.append(("set_off", xosc.AbsoluteSpeedAction(
            step.speed_mps if step.speed_mps is not None else ego.speed_mps, step_dynamics)))
    elif step.speed_mps is not None:
        actions.append(("set_speed", xosc.AbsoluteSpeedAction(step.speed_mps, xosc.TransitionDynamics(
            xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, BRAKE_RATE[step.behavior]))))
    elif step.lane_change is not None and standing:  # "the hatchback stops, then I go round it": a body that
        # stands changes no lane (esmini moves it sideways only as it moves on)
        actions.append(("set_off", xosc.AbsoluteSpeedAction(ego.speed_mps, xosc.TransitionDynamics(
            xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, YIELD_SET_OFF_MPS2))))
    elif not actions:
        actions.append(("keep_speed", xosc.AbsoluteSpeedAction(ego.speed_mps, step_dynamics)))
    label = I.later_event_name(ego.name, step.stage, step.action)
    trigger = _start_trigger(ego.model_copy(update={"trigger": step.trigger}), label, minor)
    return _group(ego.name, f"{ego.name}_maneuver_in_stage_{step.stage}", f"{ego.name}_group_in_stage_{step.stage}",
                  [(label, actions, trigger)])


def _always(label: str, delay: float, minor: int) -> xosc.ValueTrigger:
    """A condition true from the moment it is first evaluated (when its act runs), firing `delay` s later.
    1.0 has no greaterOrEqual: there it holds from the first step after t = 0."""
    rule = xosc.Rule.greaterOrEqual if minor >= 1 else xosc.Rule.greaterThan
    return xosc.ValueTrigger(label, delay, xosc.ConditionEdge.none, xosc.SimulationTimeCondition(0, rule))


def _start_trigger(agent: BoundAgent, label: str, minor: int, wait: float = 0.0,
                   clear_of: tuple[tuple[str, float], ...] = (), after: str | None = None):
    """When the agent's action starts: at once, after a delay, when someone is within reach, or both; and once
    it is clear of each (name, distance) of clear_of, after the event `after` is done. Edge `none`: someone
    already within reach at the first evaluation starts the action then (a rising edge would wait for ever)."""
    t = agent.trigger
    conditions = [] if after is None else [xosc.ValueTrigger(
        f"{label}_after_{after}", 0, xosc.ConditionEdge.none, xosc.StoryboardElementStateCondition(
            xosc.StoryboardElementType.event, after, xosc.StoryboardElementState.completeState))]
    conditions += [xosc.EntityTrigger(f"{label}_clear_of_{name}", 0, xosc.ConditionEdge.none,
                                     xosc.RelativeDistanceCondition(distance, xosc.Rule.greaterThan,
                                                                    _EUCLIDEAN[minor >= 1], name, alongroute=False,
                                                                    freespace=False), agent.name)
                  for name, distance in clear_of]
    if t is not None and t.within_m is not None:
        conditions.append(xosc.EntityTrigger(f"{label}_near", 0, xosc.ConditionEdge.none,
                                             xosc.RelativeDistanceCondition(t.within_m, xosc.Rule.lessThan,
                                                                            _EUCLIDEAN[minor >= 1],
                                                                            t.of, alongroute=False, freespace=False),
                                             agent.name))
    delay = wait + (t.after_s if t is not None and t.after_s is not None else 0.0)
    if delay or not conditions:
        conditions.append(_always(f"{label}_time", delay, minor))
    if len(conditions) == 1:
        return conditions[0]
    return _all_of(conditions)


_EUCLIDEAN = {False: xosc.RelativeDistanceType.cartesianDistance, True: xosc.RelativeDistanceType.euclidianDistance}
WALK_VERTEX_M = 5.0  # vertex spacing of a walk along a sidewalk, so the polyline follows a curved road


def _trajectory(agent: BoundAgent, minor: int, ego: BoundAgent | None = None,
                along_s: int = 1) -> xosc.FollowTrajectoryAction:
    """A polyline from where it stands to where it goes, followed at the body's own speed (TimeReference None;
    1.0 requires a time on every vertex: their order, which the players then ignore). A crosser placed
    relative to the ego crosses between two positions relative to the ego: the standard resolves a
    trajectory's relative positions when the action starts (esmini freezes them then), which is when it
    enters, so they are where it stands and the far side level with it. Its vertices have no Orientation:
    esmini then heads the walker along the polyline (given one, it stood at its start)."""
    start = agent.start
    if _crosses_relative_to_the_ego(agent):
        appear = agent.appear
        points = [_relative_to(ego, dlane, appear.ds, along_s, facing=False)
                  for dlane in (appear.dlane, appear.cross_dlane)]
        trajectory = xosc.Trajectory(f"{agent.name}_path", False)
        trajectory.add_shape(xosc.Polyline([0.0, 1.0] if minor == 0 else [], points))
        return xosc.FollowTrajectoryAction(trajectory, xosc.FollowingMode.position)
    if agent.cross_to is not None:
        points = [start, agent.cross_to]
    else:
        end = agent.walk_to
        steps = max(1, math.ceil(abs(end.s - start.s) / WALK_VERTEX_M))
        points = [start.model_copy(update={"s": round(start.s + (end.s - start.s) * k / steps, 3)})
                  for k in range(steps + 1)]
    trajectory = xosc.Trajectory(f"{agent.name}_path", False)
    times = [float(k) for k in range(len(points))] if minor == 0 else []
    trajectory.add_shape(xosc.Polyline(times, [_lane_position(p) for p in points]))
    return xosc.FollowTrajectoryAction(trajectory, xosc.FollowingMode.position)


def _relative_to(ego: BoundAgent, dlane: int, ds: float, along_s: int,
                 facing: bool = True) -> xosc.RelativeLanePosition:
    """A place `dlane` lanes to the ego's left and `ds` m ahead of it, in the road's terms (along_s: -1 when the
    ego drives against s); facing its lane's way (as ego_lane_when_stage_starts says) unless told not to."""
    facing = {} if along_s > 0 or not facing else {"orientation": xosc.Orientation(  # the left lane's way, against s
        h=math.pi, reference=xosc.ReferenceContext.relative)}
    return xosc.RelativeLanePosition(dlane * along_s, ego.name, 0, ds=ds * along_s + 0.0, **facing)


def ego_lane_when_stage_starts(scene: BoundScene, k: int) -> int:
    """The ego's lane id when stage k starts: where its route ends once it has made its turn (in the first
    stage, or in a later one before k), else the lane it started in. A RelativeLanePosition's ds runs along
    the road's reference line and its dLane is a difference of lane ids (OpenSCENARIO's definitions, and
    esmini's reading), so on a left lane (id > 0) ahead of the ego is a negative ds, its left a negative dLane;
    and without an Orientation the body faces along s (esmini), so one on a left lane is turned round (h = pi,
    relative)."""
    ego = next(a for a in scene.agents if a.is_ego)
    later_turn = next((step.stage for step in ego.later if step.action in V.TURN_ACTIONS), None)
    turned = _drives_its_route_first(scene) if later_turn is None else bool(ego.route) and later_turn < k
    return ego.route[-1].lane if turned else ego.start.lane


MAKING_ROOM_SHARE = 0.7  # of its speed, while one drops back behind a vehicle level with it in the other lane
MAKING_ROOM_RATE = 2.0  # m/s², easing off and back on


def _level_in_the_lane_it_changes_into(agent: BoundAgent, scene: BoundScene) -> list[BoundAgent]:
    """'a truck is right next to it in that lane, so the ego has to slot in behind it': vehicles level with the
    ego on the side it changes lane to, driving on. A player changes lane when told, into whatever is there;
    the file makes the ego drop back and change in behind them."""
    side = {"change_lane_to_left": "left", "change_lane_to_right": "right"}.get(agent.action)
    if not agent.is_ego or agent.stage != 0 or side is None or agent.lane_change is None:
        return []
    return [a for a in scene.agents if not a.is_ego and a.stage == 0 and a.relative_to_ego == side
            and a.type != "pedestrian" and a.action == "go_straight" and not _trajectory_bound(a)
            and a.speed_mps > 0 and not a.start_delay_s]


def _coming_up_in_the_lane_it_changes_into(agent: BoundAgent, scene: BoundScene) -> list[BoundAgent]:
    """'V1 changes lanes to the left; V3, behind and to its left, is doing 45 mph': vehicles behind the ego on
    the side it changes lane to that drive faster, so they come up level. A player changes lane when told,
    into them (esmini); the ego lets them pass first, as a driver who looks in the mirror does."""
    side = COMING_UP_IN_THE_LANE_CHANGED_TO.get(agent.action)
    if not agent.is_ego or agent.stage != 0 or side is None or agent.lane_change is None:
        return []
    return [a for a in scene.agents if not a.is_ego and a.stage == 0 and a.relative_to_ego == side
            and a.type != "pedestrian" and a.action == "go_straight" and not _trajectory_bound(a)
            and a.speed_mps > agent.speed_mps and not a.start_delay_s and a.trigger is None]


def _passes_the_ego_first(agent: BoundAgent, scene: BoundScene) -> BoundAgent | None:
    """The ego, when the agent comes up faster from behind in the lane beside and changes into the ego's lane
    ('comes speeding up on the left, overtakes and cuts in'): a player changes lane when told, into the ego;
    the file makes it draw level first and change in once clear ahead."""
    ego = next(a for a in scene.agents if a.is_ego)
    into_egos_lane = {"back_left": -1, "back_right": 1}.get(agent.relative_to_ego or "")
    if agent.is_ego or agent.stage != 0 or agent.lane_change is None or agent.lane_change != into_egos_lane or \
            agent.trigger is not None or agent.speed_mps <= ego.speed_mps or agent.start_delay_s:
        return None
    return ego


def _blocker_pulling_in(agent: BoundAgent, scene: BoundScene) -> str | None:
    """The event an ego told to stop waits for when a vehicle pulls into its lane to block it ("a car pulls out
    of a parking spot and blocks me, so I stop"): braking at once, the ego stood 40 m and more short of where
    the blocker came to stand, which blocked nothing; it brakes once the blocker is in its lane."""
    if not agent.is_ego or agent.action != "stop" or agent.trigger is not None:
        return None
    blocker = next((a for a in scene.agents if a.stage == 0 and a.action == "block_the_ego" and a.lane_change),
                   None)
    return f"{blocker.name}_{blocker.action}" if blocker is not None else None


def _events(agent: BoundAgent, scene: BoundScene, minor: int):
    """(event name, [(action name, action)], trigger) for each step of the agent's action; the events of one
    maneuver run in parallel."""
    step = xosc.TransitionDynamics(xosc.DynamicsShapes.step, xosc.DynamicsDimension.time, 0)
    events = []
    setup = []  # done when its act starts: entering (later stages) and the route
    ego = next(a for a in scene.agents if a.is_ego)
    along_s = 1 if agent.stage == 0 or ego_lane_when_stage_starts(scene, agent.stage) < 0 else -1
    if agent.stage > 0:  # inactive until its stage: it enters now, where it stands or beside the ego as it is now
        if agent.appear is not None:
            position = _relative_to(ego, agent.appear.dlane, agent.appear.ds, along_s)
        else:
            position = _lane_position(agent.start)
        setup += [("enter", xosc.AddEntityAction(agent.name, position)),
                  ("set_speed", xosc.AbsoluteSpeedAction(_initial_speed(agent), step))]
    if agent.route:
        route = xosc.Route(f"{agent.name}_route")
        for point in agent.route:
            route.add_waypoint(_lane_position(point), xosc.RouteStrategy.shortest)
        setup.append(("route", xosc.AssignRouteAction(route)))
    label = f"{agent.name}_{agent.action}"
    actions = []
    if agent.lane_change is not None:
        actions.append(("lane_change", xosc.RelativeLaneChangeAction(
            agent.lane_change, agent.name,
            xosc.TransitionDynamics(xosc.DynamicsShapes.sinusoidal, xosc.DynamicsDimension.time, 3.0))))
    if _trajectory_bound(agent):
        actions += [("walk_speed", xosc.AbsoluteSpeedAction(agent.speed_mps, step)),
                    ("path", _trajectory(agent, minor, ego, along_s))]
    braking = []
    if agent.action in ("stop", "block_the_ego"):
        brake = BRAKE_RATE[agent.behavior]
        braking.append(("brake", xosc.AbsoluteSpeedAction(
            0, xosc.TransitionDynamics(xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, brake))))
    if braking and actions:  # into the ego's lane first, then stop there
        after_change = xosc.ValueTrigger(f"{agent.name}_in_lane", 0, xosc.ConditionEdge.none,
                                         xosc.StoryboardElementStateCondition(
                                             xosc.StoryboardElementType.event, f"{agent.name}_{agent.action}",
                                             xosc.StoryboardElementState.completeState))
        later = [(f"{agent.name}_brakes", braking, after_change)]
    else:
        actions += braking
        later = []
    if not actions and agent.stage == 0 and not agent.start_delay_s:  # go_straight: hold the speed (a later
        # agent enters with it, a waiting one sets off with it)
        actions.append(("keep_speed", xosc.AbsoluteSpeedAction(agent.speed_mps, step)))
    if setup and (agent.trigger is not None or (agent.stage > 0 and actions)):  # entering and the route at
        # once; the action waits for its trigger, or for the body to be in the scene
        events.append((f"{agent.name}_{'enters' if agent.stage > 0 else 'route'}", setup,
                       _always(f"{agent.name}_setup", 0.0, minor)))
        setup = []
    walker_waits = agent.start_delay_s if _trajectory_bound(agent) else 0.0  # steps out when its turn comes
    if setup + actions:  # an agent with nothing left to do once it has entered (a walker placed beside the
        # ego, whose way across is unknown until it stands somewhere) has no event: a file may not hold an empty one
        beside = _level_in_the_lane_it_changes_into(agent, scene)
        clear_of = tuple((other.name, round((agent.length + other.length) / 2 + LANE_CHANGE_ROOM_M, 3))
                         for other in beside)
        passed = _passes_the_ego_first(agent, scene)
        level = None
        if passed is not None:  # it holds its lane until level with the ego, then changes in once clear ahead
            level = f"{agent.name}_draws_level"
            events.append((level, [("hold", xosc.AbsoluteSpeedAction(agent.speed_mps, step))], xosc.EntityTrigger(
                f"{level}_near", 0, xosc.ConditionEdge.none, xosc.RelativeDistanceCondition(
                    round((agent.length + passed.length) / 2 + 1.0, 3), xosc.Rule.lessThan, _EUCLIDEAN[minor >= 1],
                    passed.name, alongroute=False, freespace=False), agent.name)))
            clear_of += ((passed.name, round((agent.length + passed.length) / 2 + LANE_CHANGE_ROOM_M, 3)),)
        passers = _coming_up_in_the_lane_it_changes_into(agent, scene)
        if passers:  # it waits for the last of them to draw level, then changes in once they are all past
            last = max(passers, key=lambda a: a.distance_to_ego_m / (a.speed_mps - agent.speed_mps))
            level = f"{agent.name}_passed_by_{last.name}"
            events.append((level, [("hold", xosc.AbsoluteSpeedAction(agent.speed_mps, step))], xosc.EntityTrigger(
                f"{level}_near", 0, xosc.ConditionEdge.none, xosc.RelativeDistanceCondition(
                    round((agent.length + last.length) / 2 + 1.0, 3), xosc.Rule.lessThan, _EUCLIDEAN[minor >= 1],
                    last.name, alongroute=False, freespace=False), agent.name)))
            clear_of += tuple((a.name, round((agent.length + a.length) / 2 + LANE_CHANGE_ROOM_M, 3))
                              for a in passers)
        after = level or _blocker_pulling_in(agent, scene)
        events.append((label, setup + actions, _start_trigger(agent, label, minor, walker_waits, clear_of, after)))
        if beside:  # it drops back to change in behind them, then drives on at its own speed
            events.append((f"{agent.name}_makes_room", [("slow", xosc.AbsoluteSpeedAction(
                round(agent.speed_mps * MAKING_ROOM_SHARE, 3), xosc.TransitionDynamics(
                    xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate, MAKING_ROOM_RATE)))],
                _always(f"{agent.name}_makes_room_start", 0.0, minor)))
            events.append((f"{agent.name}_drives_on", [("resume", xosc.AbsoluteSpeedAction(
                agent.speed_mps, xosc.TransitionDynamics(xosc.DynamicsShapes.linear, xosc.DynamicsDimension.rate,
                                                         MAKING_ROOM_RATE)))],
                xosc.ValueTrigger(f"{agent.name}_changed", 0, xosc.ConditionEdge.none,
                                  xosc.StoryboardElementStateCondition(xosc.StoryboardElementType.event, label,
                                                                       xosc.StoryboardElementState.completeState))))
    if _trajectory_bound(agent):  # it stands where its path ends (a player would walk on along the lane)
        events.append((f"{agent.name}_arrives", [("stand", xosc.AbsoluteSpeedAction(0.0, step))],
                       xosc.ValueTrigger(f"{agent.name}_path_done", 0, xosc.ConditionEdge.none,
                                         xosc.StoryboardElementStateCondition(
                                             xosc.StoryboardElementType.event, label,
                                             xosc.StoryboardElementState.completeState))))
    events += later
    if agent.start_delay_s and not walker_waits:  # it waits for its turn through the junction, then sets off
        events.append((f"{agent.name}_sets_off", [("set_off", xosc.AbsoluteSpeedAction(agent.speed_mps, step))],
                       _always(f"{agent.name}_waited", agent.start_delay_s, minor)))
    return events


def validate(data: bytes, version: str) -> None:
    """Validate against the official ASAM XSD of the version; a failure is a fault in ttsgc."""
    schema = xsd.schema(version)
    document = etree.fromstring(data)
    if not schema.validate(document):
        errors = "; ".join(f"line {e.line}: {e.message}" for e in list(schema.error_log)[:5])
        raise EmitError(f"the emitted OpenSCENARIO {version} does not validate against the ASAM XSD: {errors}")
