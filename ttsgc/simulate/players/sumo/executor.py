"""Play a Plan in SUMO through libsumo: fixed 0.1 s steps, one simulation at a time, deterministic.

The file means what the standard says: lane positions face along their lane, an entity without Init actions
waits for its AddEntityAction, condition edges and delays count, routes are routed, lane changes happen as
written (whoever is alongside). OpenDRIVE lane positions become SUMO lanes through the lanes' original ids
(road_lane) and the net offset; vehicles drive SUMO's car-following model with the speeds and routes the file
commands. Bodies SUMO has no lane for are moved by the player itself: people (along their sidewalk, or along
their trajectory), anything on a lane SUMO has no vehicle lane for (a shoulder, which SUMO's OpenDRIVE import
discards, or a sidewalk) and anything given a trajectory. SUMO's drivers do not see those bodies, so the player
makes them: a vehicle slows for a moved body in its path. Traffic lights run only when the file controls them.
The run becomes a Trace of every body's position, heading and speed.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from functools import cache

from lxml import etree

from ttsgc.roads.opendrive import OpenDrive, load_opendrive
from ttsgc.simulate import trace as T
from ttsgc.simulate.lean_libsumo import load_libsumo
from ttsgc.simulate.plan import Action, Condition, Entity, Event, Plan
from ttsgc.simulate.players.sumo.network import Network, network_for

NAME = "sumo"
STEP_S = 0.1
TIME_LIMIT_S = 180.0
LOOK_AHEAD_M = 30.0  # how far ahead a driver watches for a body the player moves
PATH_HALF_WIDTH_M = 1.8  # a moved body this close to a vehicle's line of travel is in its path
COMFORT_BRAKE = 4.0  # m/s2
SPEED_FACTOR = 10.0  # of the lanes' speed limits: high enough that only the speeds the file sets count
ANTICIPATION_S = 2.0  # how far ahead in time a driver reads a moved body's course
STOP_SHORT_M = 2.5  # how far before a moved body in its way a vehicle stops
# the OpenDRIVE lane types SUMO's import (its opendriveNetconvert typemap) makes lanes for vehicles of;
# shoulders and the like are discarded and sidewalks are the pedestrians': a vehicle there is moved by the player
SUMO_VEHICLE_LANES = {"driving", "stop", "parking", "entry", "exit", "onRamp", "offRamp", "bidirectional"}
VCLASS = {"car": "passenger", "van": "delivery", "truck": "truck", "bus": "bus", "motorbike": "motorcycle",
          "bicycle": "bicycle", "semitrailer": "trailer"}


@dataclass
class Sample:
    t: float
    x: float  # OpenDRIVE world coordinates of the body's centre
    y: float
    heading: float  # radians, counter-clockwise from east
    speed: float
    edge: str
    lane_index: int
    road: str  # OpenDRIVE road, "" inside a junction
    lane: int | None  # OpenDRIVE lane id where known


@dataclass
class Mover:
    """A body the executor moves itself: along its lane, or straight to a target."""

    x: float  # OpenDRIVE world coordinates
    y: float
    heading: float
    speed: float
    road: str
    lane: int
    s: float
    target: tuple[float, float] | None = None
    target_speed: float | None = None
    rate: float | None = None
    path: list[tuple[float, float]] = field(default_factory=list)  # trajectory vertices still ahead
    path_event: str = ""  # the event whose trajectory it follows (ends when the path does)
    goal_s: float | None = None  # routed along its lane to this s of its road (AcquirePositionAction)
    offset: float = 0.0  # from its lane's centre along the road's t, as its position gave it
    offset_to: float | None = None  # the offset it glides to (a lane change), at offset_rate m/s
    offset_rate: float = 0.0


@dataclass
class Collision:
    a: str
    b: str
    t: float
    x: float
    y: float


@dataclass
class Spawn:
    ok: bool
    reason: str
    intended: tuple[str, int] | None = None
    got: tuple[str, int] | None = None
    t: float = 0.0


@dataclass
class Run:
    samples: dict[str, list[Sample]] = field(default_factory=dict)
    spawns: dict[str, Spawn] = field(default_factory=dict)
    fired: dict[str, float] = field(default_factory=dict)  # event -> time
    act_start: dict[str, float] = field(default_factory=dict)
    act_end: dict[str, float] = field(default_factory=dict)
    event_end: dict[str, float] = field(default_factory=dict)
    stopped_by_trigger: bool = False
    out_of_road: set[str] = field(default_factory=set)  # left the network at a dead end, or stood at its end
    collisions: list[Collision] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)  # actions that could not be carried out
    end_time: float = 0.0


@dataclass(frozen=True)
class SumoLane:
    id: str
    edge: str
    index: int
    shape: tuple[tuple[float, float], ...]
    orig: tuple[str, ...]
    allow_pedestrians: bool


@cache
def _lanes(net_path: str) -> tuple[dict[str, SumoLane], dict[str, list[SumoLane]]]:
    by_id, by_orig = {}, {}
    for edge in etree.parse(net_path).getroot().iter("edge"):
        if edge.get("function") == "internal":
            continue
        for lane in edge.iter("lane"):
            orig = next((p.get("value") for p in lane.iter("param") if p.get("key") == "origId"), "")
            shape = tuple(tuple(float(v) for v in point.split(",")[:2]) for point in lane.get("shape").split())
            allow = lane.get("allow", "")
            record = SumoLane(lane.get("id"), edge.get("id"), int(lane.get("index")), shape, tuple(orig.split()),
                              "pedestrian" in allow)
            by_id[record.id] = record
            for o in record.orig:
                by_orig.setdefault(o, []).append(record)
    return by_id, by_orig


def _project(shape, x: float, y: float) -> tuple[float, float]:
    """(distance from the polyline, position along it) of a point."""
    best, total = (math.inf, 0.0), 0.0
    for (ax, ay), (bx, by) in zip(shape, shape[1:]):
        dx, dy = bx - ax, by - ay
        seg = math.hypot(dx, dy)
        f = 0.0 if seg == 0 else max(0.0, min(1.0, ((x - ax) * dx + (y - ay) * dy) / (seg * seg)))
        px, py = ax + f * dx, ay + f * dy
        d = math.hypot(x - px, y - py)
        if d < best[0]:
            best = (d, total + f * seg)
        total += seg
    return best


def _obb_overlap(a: tuple, b: tuple) -> bool:
    """Separating-axis test of two oriented boxes (cx, cy, heading, length, width)."""
    def corners(cx, cy, h, length, width):
        c, s = math.cos(h), math.sin(h)
        return [(cx + c * dl - s * dw, cy + s * dl + c * dw) for dl in (length / 2, -length / 2)
                for dw in (width / 2, -width / 2)]
    ca, cb = corners(*a), corners(*b)
    for h in (a[2], a[2] + math.pi / 2, b[2], b[2] + math.pi / 2):
        ax, ay = math.cos(h), math.sin(h)
        pa = [x * ax + y * ay for x, y in ca]
        pb = [x * ax + y * ay for x, y in cb]
        if max(pa) < min(pb) or max(pb) < min(pa):
            return False
    return True


class Executor:
    def __init__(self, plan: Plan, network: Network | None = None, odr: OpenDrive | None = None, seed: int = 1):
        self.plan = plan
        self.network = network or network_for(plan.xodr)
        self.odr = odr or load_opendrive(plan.xodr)
        self.seed = seed
        self.by_id, self.by_orig = _lanes(str(self.network.path))
        self.run = Run()
        self.movers: dict[str, Mover] = {}  # bodies the executor moves itself
        self.holds: list[tuple[float, str, float]] = []  # (time, vehicle, speed) to hold after a slow-down
        self.present: set[str] = set()  # added to SUMO (perhaps not yet inserted)
        self.joined: set[tuple[str, str]] = set()  # (event, entity) that brought the entity in
        self.active: set[str] = set()  # seen in the simulation at least once
        self.previous: dict[int, bool] = {}  # condition (by identity) -> its value at the last evaluation
        self.since: dict[int, float] = {}  # condition (by identity) -> when its edge was met (its delay runs)
        self.commanded: dict[str, float] = {}  # vehicle -> the speed the file last set
        self.yielding: set[str] = set()  # vehicles slowed for a moved body in their path
        self.pending_routes: dict[str, tuple[Action, Event]] = {}  # routes given before SUMO inserted the vehicle

    # -- coordinates --------------------------------------------------------------------------------------
    def world(self, road: str, lane: int, s: float) -> tuple[float, float, float]:
        """SUMO x, y and heading of an OpenDRIVE lane position."""
        p = self.odr.roads[road].lane_point(s, lane)
        return p.x + self.network.offset[0], p.y + self.network.offset[1], p.hdg

    def to_sumo(self, road: str, lane: int, s: float, pedestrian: bool = False) -> tuple[SumoLane, float] | None:
        x, y, _ = self.world(road, lane, s)
        candidates = [c for c in self.by_orig.get(f"{road}_{lane}", []) if c.allow_pedestrians == pedestrian]
        if not candidates:
            import libsumo as ts
            try:
                edge, pos, index = ts.simulation.convertRoad(x, y, False, "pedestrian" if pedestrian else "passenger")
            except Exception:  # noqa: BLE001 - no lane near
                return None
            lane_id = f"{edge}_{index}"
            return (self.by_id[lane_id], pos) if lane_id in self.by_id else None
        best = min(candidates, key=lambda c: _project(c.shape, x, y)[0])
        return best, _project(best.shape, x, y)[1]

    def odr_of(self, lane_id: str) -> tuple[str, int | None]:
        lane = self.by_id.get(lane_id)
        if lane is None or not lane.orig:
            return "", None
        road, _, lane_number = lane.orig[0].rpartition("_")
        return road, int(lane_number)

    # -- spawning -----------------------------------------------------------------------------------------
    def against_its_lane(self, position: tuple[str, int, float], orientation: tuple[str, float] | None) -> bool:
        """Whether an Orientation turns a body on a lane position against the lane's driving direction: a
        relative h is read against the lane's direction (as esmini and CARLA do), an absolute one in the world."""
        if orientation is None:
            return False
        kind, h = orientation
        if kind == "relative":
            return math.cos(h) < 0
        road, lane, s = position
        lane_heading = self.odr.roads[road].lane_point(s, lane).hdg  # already the lane's driving direction
        return math.cos(h - lane_heading) < 0

    def spawn(self, entity: Entity, position: tuple[str, int, float], speed: float, t: float,
              orientation: tuple[str, float] | None = None, offset: float = 0.0) -> None:
        """Bring a body in at a lane position; the offset (along the road's t) counts for the bodies the player
        moves (SUMO's vehicles keep to their lane's centre)."""
        import libsumo as ts

        road, lane, s = position
        if road not in self.odr.roads or lane not in self.odr.roads[road].section_at(s).lanes:
            self.run.spawns[entity.name] = Spawn(False, f"road {road} has no lane {lane} at s={s:g}", (road, lane))
            return
        if entity.kind == "vehicle" and entity.intent.get("road_type", "driving") == "driving" and \
                self.against_its_lane(position, orientation):
            self.run.spawns[entity.name] = Spawn(False, f"its Orientation turns it against the driving direction "
                                                        f"of road {road} lane {lane}", (road, lane))
            return
        lane_type = self.odr.roads[road].section_at(s).lanes[lane].type
        if entity.kind == "pedestrian" or lane_type not in SUMO_VEHICLE_LANES:
            pose = _lane_pose(self.odr.roads[road], s, lane, offset)
            self.movers[entity.name] = Mover(pose.x, pose.y, pose.hdg, speed, road, lane, s, offset=offset)
            self.present.add(entity.name)
            self.active.add(entity.name)
            self.run.spawns[entity.name] = Spawn(True, "", (road, lane), (road, lane), t)
            return
        pedestrian = False
        mapped = self.to_sumo(road, lane, s, pedestrian)
        if mapped is None:
            self.run.spawns[entity.name] = Spawn(False, f"no SUMO lane near road {road} lane {lane}", (road, lane))
            return
        sumo_lane, pos = mapped
        pos = min(max(pos, 0.1), _length(sumo_lane.shape) - 0.1)
        if True:
            type_id = f"type_{entity.name}"
            ts.vehicletype.copy("DEFAULT_VEHTYPE", type_id)
            ts.vehicletype.setVehicleClass(type_id, VCLASS.get(entity.category, "passenger"))
            ts.vehicletype.setLength(type_id, entity.length)
            ts.vehicletype.setWidth(type_id, entity.width)
            ts.vehicletype.setMinGap(type_id, 1.0)
            ts.vehicletype.setMaxSpeed(type_id, max(self.fastest_commanded(entity.name, speed), 1.0) * 1.5 + 5)
            # the file's speeds, not the lanes' limits (nor a slower turn through a junction): no player reads a
            # SpeedAction as bounded by the road, so the lanes' limits never bind
            ts.vehicletype.setSpeedFactor(type_id, SPEED_FACTOR)
            ts.vehicletype.setSpeedDeviation(type_id, 0.0)
            ts.route.add(f"route_{entity.name}", self._ahead(sumo_lane.id))
            # SUMO places a vehicle by its front bumper
            front = min(pos + entity.length / 2, _length(sumo_lane.shape) - 0.05)
            ts.vehicle.add(entity.name, f"route_{entity.name}", typeID=type_id, depart="now",
                           departLane=str(sumo_lane.index), departPos=f"{front:.2f}", departSpeed=f"{speed:.3f}")
            # no lane changes of its own; the file's lane changes happen as written, whoever is alongside
            ts.vehicle.setLaneChangeMode(entity.name, 0)
            ts.vehicle.setSpeed(entity.name, speed)
            self.commanded[entity.name] = speed
        self.present.add(entity.name)
        got = self.odr_of(sumo_lane.id)
        ok = got == (road, lane)
        reason = "" if ok else f"placed on road {got[0]} lane {got[1]} instead of road {road} lane {lane}"
        self.run.spawns[entity.name] = Spawn(ok, reason, (road, lane), got, t)

    def fastest_commanded(self, name: str, speed: float) -> float:
        """The highest speed the file ever sets for an entity: its vehicle type must allow it (one that enters
        standing still would otherwise be held to a walking pace of SUMO's, whatever the file says)."""
        actions = list(self.plan.init.get(name, []))
        actions += [a for act in self.plan.acts for e in act.events if e.actor == name for a in e.actions]
        return max([speed] + [a.value for a in actions if a.kind == "speed"])

    # -- actions ------------------------------------------------------------------------------------------
    def execute(self, actor: str, action: Action, t: float, event: Event) -> None:
        import libsumo as ts

        entity = self.plan.entities.get(actor)
        if entity is None:
            self.run.problems.append(f"{event.name}: no entity '{actor}'")
            return
        try:
            if action.kind == "add":
                added = self.plan.entities.get(action.entity or actor)
                if added is None:
                    self.run.problems.append(f"{event.name}: no entity '{action.entity}' to add")
                elif added.name in self.present:
                    self.run.problems.append(f"{event.name}: '{added.name}' is already in the scene")
                elif action.lane is not None:
                    speed = next((a.value for a in event.actions if a.kind == "speed"), 0.0)
                    self.spawn(added, action.lane, speed, t, action.orientation, action.offset)
                else:
                    self._appear(added, action, event, t)
                self.joined.add((event.name, added.name) if added is not None else (event.name, actor))
            elif action.kind == "delete":
                self._delete(action.entity or actor)
            elif action.kind == "teleport" and actor not in self.present:
                self.run.problems.append(f"{event.name}: '{actor}' has no Init action, so it is not in the scene "
                                         f"until an AddEntityAction brings it in; a TeleportAction cannot")
            elif action.kind == "speed" and not action.rate and (event.name, actor) in self.joined:
                return  # it entered with this speed
            elif actor not in self.present:
                self.run.problems.append(f"{event.name}: '{actor}' is not in the simulation")
            elif actor in self.movers:
                self._move_order(self.movers[actor], action, event)
            elif action.kind == "speed":
                self._speed(entity, action, t)
            elif action.kind == "trajectory":
                self._follow(entity, action, event)
            elif action.kind == "lane_change":
                index = self._target_index(actor, action)
                lanes = ts.edge.getLaneNumber(ts.vehicle.getRoadID(actor))
                if not 0 <= index < lanes or not self._drivable(ts.vehicle.getRoadID(actor), index):
                    self.run.problems.append(f"{event.name}: '{actor}' has no lane {int(action.value):+d} to change to")
                else:
                    ts.vehicle.changeLane(actor, index, 60.0)
            elif action.kind == "route" and actor not in self.active:
                self.pending_routes[actor] = (action, event)  # added, not yet inserted: routed once it is
            elif action.kind == "route":
                self._route(entity, action, event)
            elif action.kind == "acquire":
                self._route(entity, Action("route", waypoints=(action.lane,)), event)
        except Exception as exc:  # noqa: BLE001 - a command SUMO refuses is a failed action, reported
            self.run.problems.append(f"{event.name}: {action.kind} failed in SUMO: {exc}")

    def _delete(self, name: str) -> None:
        import libsumo as ts

        if name in self.movers:
            del self.movers[name]
        elif name in self.present and name in ts.vehicle.getIDList():
            ts.vehicle.remove(name)
        self.present.discard(name)

    def _target_index(self, actor: str, action: Action) -> int:
        """The SUMO lane index a lane change aims at: relative (lanes to the left) or an OpenDRIVE lane id."""
        import libsumo as ts

        index = ts.vehicle.getLaneIndex(actor)
        if not action.absolute:
            return index + int(action.value)
        edge = ts.vehicle.getRoadID(actor)
        road, _ = self.odr_of(ts.vehicle.getLaneID(actor))
        target = next((lane for lane in self.by_orig.get(f"{road}_{int(action.value)}", []) if lane.edge == edge), None)
        return target.index if target is not None else -1

    def _follow(self, entity: Entity, action: Action, event: Event) -> None:
        """A trajectory: the player moves the body along its vertices at its own speed (a SUMO vehicle leaves
        SUMO's hands for it)."""
        import libsumo as ts

        waypoints = action.waypoints
        if action.relatives:  # resolved now, when the action starts (the standard; esmini freezes them then)
            waypoints = tuple(self.relative_in_opendrive(*relative) for relative in action.relatives)
            if not all(waypoints):
                self.run.problems.append(f"{event.name}: a trajectory vertex relative to an entity that is not on "
                                         f"a road")
                return
        points = []
        for (road, lane, s), offset in zip(waypoints, action.offsets or [0.0] * len(waypoints)):
            if road not in self.odr.roads:
                self.run.problems.append(f"{event.name}: the trajectory names road {road}, which does not exist")
                return
            pose = _lane_pose(self.odr.roads[road], min(max(s, 0.0), self.odr.roads[road].length), lane, offset)
            points.append((pose.x, pose.y))
        mover = self.movers.get(entity.name)
        if mover is None:  # a vehicle: take it out of SUMO where it is
            last = self.last(entity.name)
            if last is None:
                self.run.problems.append(f"{event.name}: '{entity.name}' is not on a road to leave from")
                return
            speed = ts.vehicle.getSpeed(entity.name)
            ts.vehicle.remove(entity.name)
            mover = Mover(last.x, last.y, last.heading, speed, last.road, last.lane or -1, 0.0)
            self.movers[entity.name] = mover
        if points and math.hypot(points[0][0] - mover.x, points[0][1] - mover.y) < 0.5:
            points = points[1:]
        mover.path, mover.target, mover.path_event = points, None, event.name
        if mover.speed <= 0.01 and not mover.target_speed:
            mover.speed = 1.0

    def _move_order(self, mover: Mover, action: Action, event: Event) -> None:
        """An action for a body the executor moves: a speed, or a position to walk (or roll) to."""
        if action.kind == "speed":
            mover.target_speed, mover.rate = action.value, action.rate
            if not action.rate:
                mover.speed = action.value
        elif action.kind == "trajectory":
            self._follow(self.plan.entities[event.actor], action, event)
        elif action.kind == "acquire":
            # routing, as the standard says: along its own lane to the target's s on the same road (a target
            # across the road at the same s is reached where it stands); elsewhere, on along its lane
            road, _, s = action.lane
            mover.goal_s = s if road == mover.road else None
            if mover.speed <= 0.01:
                mover.speed = 1.0
        elif action.kind == "lane_change" and mover.path_event == "" and mover.target is None:
            self._mover_lane_change(mover, action, event)
        else:
            self.run.problems.append(f"{event.name}: {action.kind} is not possible off the SUMO lanes")

    def _mover_lane_change(self, mover: Mover, action: Action, event: Event) -> None:
        """A body moved along its lane (a car leaving the shoulder, which SUMO's network has not) changes lane
        as a driver does: at once it counts in the lane it aims at, and it glides across from where it is over
        the action's time. Left is towards the road's reference line on either side."""
        road = self.odr.roads[mover.road]
        if action.absolute:
            target = int(action.value)
        else:
            steps = int(action.value)
            target = mover.lane + steps if mover.lane < 0 else mover.lane - steps
            if (target >= 0) != (mover.lane >= 0) or target == 0:  # across the reference line: no lane 0
                target += 1 if mover.lane < 0 else -1
        section = road.section_at(min(max(mover.s, 0.0), road.length))
        if target not in section.lanes or section.lanes[target].type not in ("driving", "shoulder", "parking"):
            self.run.problems.append(f"{event.name}: '{event.actor}' has no lane {int(action.value):+d} to change to")
            return
        here = _lane_pose(road, mover.s, mover.lane, mover.offset)
        there = _lane_pose(road, mover.s, target, 0.0)
        across = math.hypot(here.x - there.x, here.y - there.y)
        mover.lane, mover.offset = target, across if mover.lane > target else -across  # t grows with lane id
        mover.offset_to, mover.offset_rate = 0.0, across / max(action.duration, STEP_S)

    def _ahead(self, lane_id: str, limit_m: float = 1000.0) -> list[str]:
        """Until the file gives it a route, a vehicle carries on straight ahead (else the way its lane leads),
        rather than leave the network at the end of its first, perhaps very short, road."""
        import libsumo as ts

        edges, total, lane = [self.by_id[lane_id].edge], 0.0, lane_id
        for _ in range(60):
            links = [k for k in ts.lane.getLinks(lane) if k[6] != "t"]  # never the U-turn netconvert adds
            if not links or total > limit_m:  # at a map's edge: it leaves there, as a player's vehicle does
                break
            link = next((k for k in links if k[6] == "s"), links[0])
            lane = link[0]
            edge = lane.rpartition("_")[0]
            if edge in edges or lane not in self.by_id:
                break
            edges.append(edge)
            total += _length(self.by_id[lane].shape)
        return edges

    def _drivable(self, edge: str, index: int) -> bool:
        lane = self.by_id.get(f"{edge}_{index}")
        return lane is not None and not lane.allow_pedestrians

    def _speed_change_s(self, actor: str, action: Action) -> float:
        """How long a speed change at a rate takes from the actor's speed now."""
        import libsumo as ts

        if actor in self.movers:
            current = self.movers[actor].speed
        elif actor in self.active and actor in ts.vehicle.getIDList():
            current = ts.vehicle.getSpeed(actor)
        else:
            return 0.0  # (a vehicle that has left the network at its route's end changes no speed)
        return abs(current - action.value) / action.rate

    def _speed(self, entity: Entity, action: Action, t: float) -> None:
        import libsumo as ts

        current = ts.vehicle.getSpeed(entity.name)
        if action.rate:
            duration = max(abs(current - action.value) / action.rate, STEP_S)
            ts.vehicle.slowDown(entity.name, action.value, duration)
            self.holds.append((t + duration, entity.name, action.value))
        else:
            ts.vehicle.setSpeed(entity.name, action.value)
        self.commanded[entity.name] = action.value

    def _route(self, entity: Entity, action: Action, event: Event) -> None:
        import libsumo as ts

        current = ts.vehicle.getRoadID(entity.name)
        if current.startswith(":"):
            current = ts.vehicle.getRoute(entity.name)[ts.vehicle.getRouteIndex(entity.name)]
        edges, last_lane = [current], None
        for point in action.waypoints:
            road = self.odr.roads.get(point[0])
            if road is not None and road.junction != "-1":
                # a connecting road inside a junction: SUMO's own connection between the roads before and
                # after it is that road (its internal lanes carry no OpenDRIVE id to map a point to)
                continue
            mapped = self.to_sumo(*point)
            if mapped is not None:
                last_lane = mapped[0].id
            if mapped is None or mapped[0].edge == edges[-1]:
                continue
            found = ts.simulation.findRoute(edges[-1], mapped[0].edge, vType=ts.vehicle.getTypeID(entity.name))
            if not found.edges:
                self.run.problems.append(f"{event.name}: no route from {edges[-1]} to {mapped[0].edge}")
                return
            edges += list(found.edges[1:])
        if last_lane is not None:  # after its last waypoint it carries on, as every player's vehicles do,
            for edge in self._ahead(last_lane)[1:]:  # up to where its way would come back on itself
                if edge in edges:
                    break
                edges.append(edge)
        ts.vehicle.setRoute(entity.name, edges)

    def _can_appear(self, event: Event) -> bool:
        import libsumo as ts

        for action in event.actions:
            ref = action.relative[0] if action.kind == "add" and action.relative else None
            if ref in self.present and ref in self.active and ref not in self.movers:
                if ts.vehicle.getRoadID(ref).startswith(":"):
                    return False
        return True

    def relative_in_opendrive(self, ref: str, dlane: int, ds: float) -> tuple[str, int, float] | None:
        """A RelativeLanePosition as esmini reads it, in the road's terms: dLane lanes from the entity's lane
        counted across the centre line as lanes (no lane 0: lane -1 and 4 lanes is lane 4), ds along s from
        where it is now. None when the entity is on no road (inside a junction, or gone)."""
        sample = self.last(ref)
        if sample is None or not sample.road or sample.lane is None or sample.road not in self.odr.roads:
            return None
        dx, dy = self.network.offset
        road = self.odr.roads[sample.road]
        s = self._s_on_road(sample.road, sample.lane, sample.x + dx, sample.y + dy)
        return sample.road, _lanes_beyond(sample.lane, dlane), round(min(max(s + ds, 0.0), road.length), 3)

    def _appear(self, entity: Entity, action: Action, event: Event, t: float) -> None:
        import libsumo as ts

        ref, dlane, ds = action.relative
        if ref not in self.present:
            self.run.problems.append(f"{event.name}: '{ref}' is not in the simulation to appear beside")
            return
        if entity.kind == "pedestrian":  # on a sidewalk or a shoulder SUMO's lanes may not have: in the road's
            # own lanes, as esmini counts them
            position = self.relative_in_opendrive(ref, dlane, ds)
            if position is None:
                self.run.spawns[entity.name] = Spawn(False, f"'{ref}' is on no road to appear beside at t={t:.1f}")
                return
            speed = next((a.value for a in event.actions if a.kind == "speed"), 0.0)
            self.spawn(entity, position, speed, t)
            return
        edge = ts.vehicle.getRoadID(ref)
        # dLane and ds count in the road's terms (lane ids, s), SUMO's lanes in the driving direction: on an
        # OpenDRIVE lane with a positive id, which drives against s, they turn round
        along = -1 if (self.odr_of(ts.vehicle.getLaneID(ref))[1] or -1) > 0 else 1
        index = ts.vehicle.getLaneIndex(ref) + dlane * along
        lane_id = f"{edge}_{index}"
        if lane_id not in self.by_id:
            self.run.spawns[entity.name] = Spawn(False, f"the ego's lane has no neighbour {dlane:+d} at t={t:.1f}")
            return
        centre = ts.vehicle.getLanePosition(ref) - self.plan.entities[ref].length / 2 + ds * along
        sumo_lane = self.by_id[lane_id]
        length = _length(sumo_lane.shape)
        route, k = ts.vehicle.getRoute(ref), ts.vehicle.getRouteIndex(ref)

        def nearest_vehicle_lane(edge: str):
            lanes = [lane for lane in self.by_id.values() if lane.edge == edge and not lane.allow_pedestrians]
            return min(lanes, key=lambda lane: abs(lane.index - index)) if lanes else None

        while centre >= length and 0 <= k < len(route) - 1:  # beyond the ego's edge: on along its route
            k += 1
            if (ahead := nearest_vehicle_lane(route[k])) is None:
                break
            centre -= length
            sumo_lane, length = ahead, _length(ahead.shape)
        while centre <= 0 and 0 < k <= len(route) - 1:  # behind the ego's edge: back along the way it came
            k -= 1
            if (behind := nearest_vehicle_lane(route[k])) is None:
                break
            sumo_lane, length = behind, _length(behind.shape)
            centre += length
        if not 0 < centre < length:
            self.run.spawns[entity.name] = Spawn(False, f"no room {ds:+.0f} m from the ego on its road at t={t:.1f}")
            return
        road, lane = self.odr_of(sumo_lane.id)
        x, y = _point_at(sumo_lane.shape, centre)
        s = self._s_on_road(road, lane, x, y)
        speed = next((a.value for a in event.actions if a.kind == "speed"), ts.vehicle.getSpeed(ref))
        self.spawn(entity, (road, lane, s), speed, t)

    def _s_on_road(self, road: str, lane: int, x: float, y: float) -> float:
        r = self.odr.roads[road]
        best = min(range(0, int(r.length * 2) + 1), key=lambda k: math.hypot(
            *(a - b for a, b in zip(self.world(road, lane, min(k / 2, r.length))[:2], (x, y)))))
        return min(best / 2, r.length)

    # -- the loop -----------------------------------------------------------------------------------------
    def holds_true(self, condition: Condition, t: float, actor: str = "") -> bool:
        """The condition's own value now, before its edge and delay."""
        if condition.kind == "time":
            return _compared(t, condition.rule, condition.value, slack=1e-9, equal_within=STEP_S / 2)
        if condition.kind == "state":
            ref, state = condition.ref, condition.state
            ended = self.run.act_end.get(ref, self.run.event_end.get(ref))
            started = self.run.act_start.get(ref, self.run.fired.get(ref))
            if state in ("endTransition", "completeState", "stopTransition"):
                return ended is not None and t >= ended - 1e-9 and (state == "completeState"
                                                                     or t - ended < STEP_S + 1e-9)
            if state in ("startTransition", "runningState"):
                return started is not None and (state == "runningState" and ended is None
                                                or state == "startTransition" and t - started < STEP_S + 1e-9)
            if state == "standbyState":
                return False
            return False
        if condition.kind == "reach":
            a = self.last(condition.triggering or actor)
            if a is None or condition.position[0] not in self.odr.roads:
                return False
            p = self.odr.roads[condition.position[0]].lane_point(condition.position[2], condition.position[1])
            return math.hypot(a.x - p.x, a.y - p.y) < condition.value
        if condition.kind == "distance":
            who = condition.triggering or actor
            a, b = self.last(who), self.last(condition.ref)
            if a is None or b is None:
                return False
            apart = math.hypot(a.x - b.x, a.y - b.y)
            return apart > condition.value if condition.rule.startswith("greater") else apart < condition.value
        if condition.kind == "end_of_road":
            return any(name in self.run.out_of_road for name in condition.entities)
        if condition.kind == "speed":
            a = self.last(condition.triggering or actor)
            return a is not None and _compared(a.speed, condition.rule, condition.value, equal_within=0.01)
        return False

    def _met(self, condition: Condition, t: float, actor: str) -> bool:
        """The condition with its edge (a change since the last evaluation) and delay (from when it was met)."""
        key = id(condition)
        if condition.edge == "none" and not condition.delay:
            self.previous[key] = self.holds_true(condition, t, actor)
            return self.previous[key]
        if key not in self.since:
            now = self.holds_true(condition, t, actor)
            before = self.previous.get(key)
            self.previous[key] = now
            edge = {"none": now, "rising": before is False and now, "falling": before is True and not now,
                    "risingOrFalling": before is not None and before != now}.get(condition.edge, now)
            if not edge:
                return False
            self.since[key] = t
        return t >= self.since[key] + condition.delay - 1e-9

    def triggered(self, groups: list[list[Condition]], t: float, actor: str = "") -> bool:
        met = False
        for group in groups:
            results = [self._met(c, t, actor) for c in group]  # every condition is evaluated: edges need it
            met = met or (bool(results) and all(results))
        return met

    def last(self, name: str) -> Sample | None:
        samples = self.run.samples.get(name)
        return samples[-1] if samples and name in self.present and name in self.active else None

    def execute_plan(self) -> Run:
        ts = load_libsumo()  # the first import of libsumo in the process: see lean_libsumo

        ts.start(["sumo", "-n", str(self.network.path), "--step-length", str(STEP_S), "--no-step-log", "true",
                  "--seed", str(self.seed), "--collision.action", "none", "--time-to-teleport", "-1",
                  "--no-warnings", "true",
                  "--insertion-checks", "collision"])  # scenes start agents close on purpose
        try:
            if not self.plan.controls_signals:
                self._lights_without_program()
            for name, actions in self.plan.init.items():
                entity = self.plan.entities.get(name)
                teleport = next((a for a in actions if a.kind == "teleport"), None)
                if entity is None or teleport is None:
                    continue
                speed = next((a.value for a in actions if a.kind == "speed"), 0.0)
                if teleport.relative is not None:
                    self.run.problems.append(f"'{name}': an Init position beside another entity is not supported")
                    continue
                self.spawn(entity, teleport.lane, speed, 0.0, teleport.orientation, teleport.offset)
            ts.simulationStep()  # SUMO inserts what was added on the next step
            t = round(ts.simulation.getTime(), 3)
            self._sample(t)
            self._storyboard(0.0)  # the first evaluation is of the initial state, at t=0, as in esmini
            while t < TIME_LIMIT_S:
                self._storyboard(t)
                if self.triggered(self.plan.stop, t):
                    self.run.stopped_by_trigger = True
                    break
                self._move(t)
                self._yield_to_moved_bodies()
                for when, vehicle, speed in list(self.holds):
                    if t >= when and vehicle in self.present:
                        ts.vehicle.setSpeed(vehicle, speed)
                        self.holds.remove((when, vehicle, speed))
                ts.simulationStep()
                t = round(ts.simulation.getTime(), 3)
                self._sample(t)
                self._collisions(t)
            self.run.end_time = t
        finally:
            ts.close()
        return self.run

    @staticmethod
    def _lights_without_program() -> None:
        """netconvert gives every signalised junction a program of its own, which the file never asked for: a
        file that does not control the signals has lights no player runs (esmini drives through them), so
        every link of every light is green with priority, and nobody stops or yields there."""
        import libsumo as ts

        for light in ts.trafficlight.getIDList():
            ts.trafficlight.setRedYellowGreenState(light, "G" * len(ts.trafficlight.getRedYellowGreenState(light)))

    def _storyboard(self, t: float) -> None:
        for act in self.plan.acts:
            if act.name not in self.run.act_start and self.triggered(act.start, t):
                self.run.act_start[act.name] = t
            if act.name not in self.run.act_start or act.name in self.run.act_end:
                continue
            for event in act.events:
                if event.name in self.run.fired or not self.triggered(event.start, t, event.actor):
                    continue
                if not self._can_appear(event):
                    continue  # wait until the entity it appears beside is on a road
                if event.actor in self.present and event.actor not in self.active and \
                        not any(a.kind in ("add", "teleport") for a in event.actions):
                    continue  # added, not yet inserted: it cannot act before it is on the road
                self.run.fired[event.name] = t
                takes = [a.duration for a in event.actions if a.kind == "lane_change"] + \
                    [self._speed_change_s(event.actor, a) for a in event.actions if a.kind == "speed" and a.rate]
                for action in event.actions:
                    self.execute(event.actor, action, t, event)
                if not any(m.path_event == event.name for m in self.movers.values()):
                    # its actions are commands, done when given; a lane change or a speed change at a rate
                    # when its time is up (esmini: a stop's event completes when the body stands)
                    self.run.event_end[event.name] = t + max(takes, default=0.0)
            if all(self.run.event_end.get(e.name, math.inf) <= t for e in act.events):
                self.run.act_end[act.name] = t

    def _move(self, t: float) -> None:
        """Advance the bodies the player moves: along their trajectory, towards their target, else along
        their lane."""
        for name, mover in self.movers.items():
            if mover.target_speed is not None and mover.rate:
                delta = mover.rate * STEP_S
                mover.speed = max(mover.target_speed, mover.speed - delta) if mover.speed > mover.target_speed \
                    else min(mover.target_speed, mover.speed + delta)
            step = mover.speed * STEP_S
            if step <= 0:
                continue
            if mover.path_event and not mover.path:  # its trajectory is done: it stands where it ends
                continue
            if mover.path:
                while step > 0 and mover.path:
                    tx, ty = mover.path[0]
                    d = math.hypot(tx - mover.x, ty - mover.y)
                    if d > 1e-9:
                        mover.heading = math.atan2(ty - mover.y, tx - mover.x)
                    if d <= step:
                        mover.x, mover.y = tx, ty
                        mover.path.pop(0)
                        step -= d
                    else:
                        mover.x += (tx - mover.x) * step / d
                        mover.y += (ty - mover.y) * step / d
                        step = 0
                if not mover.path:
                    mover.speed = mover.target_speed = 0.0
                    self.run.event_end[mover.path_event] = t
                continue
            if mover.target is not None:
                tx, ty = mover.target
                d = math.hypot(tx - mover.x, ty - mover.y)
                if d <= step:
                    mover.x, mover.y, mover.target, mover.speed = tx, ty, None, 0.0
                    continue
                mover.heading = math.atan2(ty - mover.y, tx - mover.x)
                mover.x += (tx - mover.x) * step / d
                mover.y += (ty - mover.y) * step / d
                continue
            road = self.odr.roads[mover.road]
            if mover.goal_s is not None:
                if abs(mover.goal_s - mover.s) <= step:
                    mover.s, mover.speed, mover.goal_s = mover.goal_s, 0.0, None
                    pose = _lane_pose(road, mover.s, mover.lane, mover.offset)
                    mover.x, mover.y = pose.x, pose.y
                    continue
                s = mover.s + (step if mover.goal_s > mover.s else -step)
            else:
                s = mover.s + (step if mover.lane < 0 else -step)
            if not 0.0 <= s <= road.length:
                if not self._next_road(mover, s - road.length if s > road.length else -s):
                    mover.speed = 0.0  # the end of its way: it stands
                    self.run.out_of_road.add(name)
                continue
            if mover.offset_to is not None:  # gliding into the lane it changed to
                glide = mover.offset_rate * STEP_S
                if abs(mover.offset_to - mover.offset) <= glide:
                    mover.offset, mover.offset_to = mover.offset_to, None
                else:
                    mover.offset += glide if mover.offset_to > mover.offset else -glide
            pose = _lane_pose(road, s, mover.lane, mover.offset)
            mover.x, mover.y, mover.heading, mover.s = pose.x, pose.y, pose.hdg, s

    def _yield_to_moved_bodies(self) -> None:
        """SUMO's drivers do not see the bodies this player moves, so the player makes them: a vehicle whose
        way a moved body will be on while the vehicle gets there (read from the body's course) slows to stop
        short of it, and takes up its commanded speed again once the way is clear. A vehicle that could not
        stop before it anyway keeps its speed, as a committed driver would: braking then would only bring it
        there later, when the body is in its lane (a walker stepping out close in front of it)."""
        import libsumo as ts

        if not self.movers:
            return
        for name in sorted(self.commanded):
            last = self.last(name)
            if last is None or name in self.movers:
                continue
            body = self.plan.entities[name]
            gap = None
            for other, mover in self.movers.items():
                where = self._conflict(last, body, mover, self.plan.entities[other], ts.vehicle.getDecel(name),
                                       name in self.yielding)
                if where is not None:
                    gap = where if gap is None else min(gap, where)
            commanded = self.commanded[name]
            if gap is not None:
                safe = math.sqrt(max(0.0, 2 * COMFORT_BRAKE * (gap - STOP_SHORT_M)))
                ts.vehicle.setSpeed(name, min(commanded, safe))
                self.yielding.add(name)
            elif name in self.yielding:
                ts.vehicle.setSpeed(name, commanded)
                self.yielding.discard(name)

    @staticmethod
    def _conflict(vehicle: Sample, body: Entity, mover: Mover, other: Entity, decel: float,
                  braking: bool = False) -> float | None:
        """The free gap to a moved body the vehicle must stop for, None when there is none: the body is ahead
        within LOOK_AHEAD_M and in the vehicle's way (PATH_HALF_WIDTH_M beside its line) at some time while
        the vehicle reaches and passes it, and the vehicle can still stop short of it (or already crawls, or
        already brakes for it: it does not give up half way)."""
        c, n = math.cos(vehicle.heading), math.sin(vehicle.heading)
        dx, dy = mover.x - vehicle.x, mover.y - vehicle.y
        ahead, side = dx * c + dy * n, -dx * n + dy * c
        vx, vy = math.cos(mover.heading) * mover.speed, math.sin(mover.heading) * mover.speed
        lateral = -vx * n + vy * c
        gap = ahead - body.length / 2 - other.length / 2
        if gap < -1.0 or gap > LOOK_AHEAD_M:
            return None
        half = PATH_HALF_WIDTH_M + body.width / 2
        if abs(lateral) < 1e-6:
            if abs(side) >= half:
                return None
            enters, leaves = 0.0, math.inf
        else:
            first, second = sorted(((-half - side) / lateral, (half - side) / lateral))
            if second < 0:
                return None
            enters, leaves = max(first, 0.0), second
        speed = vehicle.speed
        if speed < 0.5:  # standing or crawling: it waits while the body is, or is about to be, in its way
            return max(gap, 0.0) if enters < ANTICIPATION_S else None
        reaches = max(gap, 0.0) / speed
        passes = (gap + body.length + other.length + 2.0) / speed
        if enters > passes + ANTICIPATION_S / 2 or leaves < reaches - ANTICIPATION_S / 2:
            return None  # it is by before the body comes, or the body is gone before it gets there
        if not braking and (gap - STOP_SHORT_M <= 0 or speed * speed / (2 * (gap - STOP_SHORT_M)) > decel):
            return None  # too late to stop: braking now would only bring it there with the body in its way
        return max(gap, 0.0)

    def _next_road(self, mover: Mover, overshoot: float) -> bool:
        """Carry a body moved along its lane onto the next road, in the same kind of lane at the same side."""
        road = self.odr.roads[mover.road]
        link = road.successor if mover.lane < 0 else road.predecessor
        if link is None or link.element_type != "road" or link.element_id not in self.odr.roads:
            return False
        nxt = self.odr.roads[link.element_id]
        at_start = (link.contact_point or ("start" if mover.lane < 0 else "end")) == "start"
        s = min(overshoot, nxt.length) if at_start else max(nxt.length - overshoot, 0.0)
        kind = road.section_at(mover.s if 0 <= mover.s <= road.length else 0).lanes.get(mover.lane)
        side = nxt.section_at(s).side(-1 if at_start else 1)
        same = [lane for lane in side if kind is None or lane.type == kind.type]
        if not same:
            return False
        pose = nxt.lane_point(s, same[-1].id)
        mover.road, mover.lane, mover.s = nxt.id, same[-1].id, s
        mover.x, mover.y, mover.heading = pose.x, pose.y, pose.hdg
        return True

    def _sample(self, t: float) -> None:
        import libsumo as ts

        vehicles = set(ts.vehicle.getIDList())
        dx, dy = self.network.offset
        for name in list(self.present):
            entity = self.plan.entities[name]
            if name in self.movers:
                m = self.movers[name]
                self.run.samples.setdefault(name, []).append(Sample(t, m.x, m.y, m.heading, m.speed, "", -1,
                                                                    m.road, m.lane))
                continue
            if name in vehicles:
                fx, fy = ts.vehicle.getPosition(name)
                h = math.radians(90.0 - ts.vehicle.getAngle(name))
                x, y = fx - math.cos(h) * entity.length / 2, fy - math.sin(h) * entity.length / 2
                speed, lane_id = ts.vehicle.getSpeed(name), ts.vehicle.getLaneID(name)
            elif name in self.active:  # left the network at the end of its route
                self.present.discard(name)
                self.run.out_of_road.add(name)  # routes run on to the network's end (see _route)
                continue
            else:  # added, not yet inserted
                continue
            self.active.add(name)
            if name in self.pending_routes:
                action, event = self.pending_routes.pop(name)
                try:
                    self._route(entity, action, event)
                except Exception as exc:  # noqa: BLE001 - a route SUMO refuses is a failed action, reported
                    self.run.problems.append(f"{event.name}: route failed in SUMO: {exc}")
            road, lane = self.odr_of(lane_id)
            edge, _, index = lane_id.rpartition("_")
            self.run.samples.setdefault(name, []).append(Sample(
                t, x - dx, y - dy, h, speed, edge, int(index) if index.isdigit() else -1, road, lane))

    def _collisions(self, t: float) -> None:
        known = {(c.a, c.b) for c in self.run.collisions}
        names = sorted(self.present)
        for i, a in enumerate(names):
            sa = self.last(a)
            for b in names[i + 1:]:
                if (a, b) in known:
                    continue
                sb = self.last(b)
                if sa is None or sb is None or math.hypot(sa.x - sb.x, sa.y - sb.y) > 20:
                    continue
                ea, eb = self.plan.entities[a], self.plan.entities[b]
                if _obb_overlap((sa.x, sa.y, sa.heading, ea.length, ea.width),
                                (sb.x, sb.y, sb.heading, eb.length, eb.width)):
                    self.run.collisions.append(Collision(a, b, t, round((sa.x + sb.x) / 2, 2),
                                                         round((sa.y + sb.y) / 2, 2)))


def _compared(x: float, rule: str, value: float, slack: float = 0.0, equal_within: float = 0.0) -> bool:
    """An OpenSCENARIO rule applied to x; slack lets a value met to rounding count as met (a time)."""
    return {"greaterThan": x > value + slack, "greaterOrEqual": x >= value - slack, "lessThan": x < value - slack,
            "lessOrEqual": x <= value + slack, "equalTo": abs(x - value) < equal_within,
            "notEqualTo": abs(x - value) >= equal_within}.get(rule, False)


def _lanes_beyond(lane: int, dlane: int) -> int:
    """The lane id dlane lanes from `lane`, counting across the centre line without a lane 0 (esmini)."""
    target = lane + dlane
    if target == 0 or (target > 0) != (lane > 0):
        target += 1 if dlane > 0 else -1
    return target


def _lane_pose(road, s: float, lane: int, offset: float = 0.0):
    """A lane point moved by a LanePosition's offset, which counts along the road's t (to the left of its
    reference line), whichever side the lane is on."""
    pose = road.lane_point(s, lane)
    if not offset:
        return pose
    normal = road.pose(s).hdg + math.pi / 2
    return dataclasses.replace(pose, x=pose.x + offset * math.cos(normal), y=pose.y + offset * math.sin(normal))


def _length(shape) -> float:
    return sum(math.hypot(bx - ax, by - ay) for (ax, ay), (bx, by) in zip(shape, shape[1:]))


def _point_at(shape, pos: float) -> tuple[float, float]:
    for (ax, ay), (bx, by) in zip(shape, shape[1:]):
        seg = math.hypot(bx - ax, by - ay)
        if pos <= seg and seg > 0:
            return ax + (bx - ax) * pos / seg, ay + (by - ay) * pos / seg
        pos -= seg
    return shape[-1]


def unavailable() -> str:
    """Empty when SUMO can run here (libsumo and the eclipse-sumo netconvert are Python packages)."""
    try:
        load_libsumo()
    except ImportError as exc:
        return f"libsumo cannot be imported: {exc}"
    return ""


def play(plan: Plan, seed: int = 1) -> T.Trace:
    """Play a plan in SUMO; the Trace every player hands the judge."""
    executor = Executor(plan, seed=seed)
    run = executor.execute_plan()
    trace = T.Trace(player=NAME, step_s=STEP_S, end_time=run.end_time, stopped_by_trigger=run.stopped_by_trigger,
                    problems=list(run.problems))
    for name, entity in plan.entities.items():
        trace.bodies[name] = T.Body(entity.length, entity.width, entity.x_offset)
    for name, spawn in sorted(run.spawns.items()):
        if not spawn.ok:
            trace.problems.append(f"'{name}' could not be placed: {spawn.reason}")
    for name, samples in run.samples.items():
        trace.samples[name] = [T.Sample(s.t, s.x, s.y, s.heading, s.speed, s.road, s.lane,
                                      on_road=bool(s.road) or s.edge.startswith(":")) for s in samples]
    trace.started.update(run.act_start)
    trace.started.update(run.fired)
    trace.ended.update(run.act_end)
    trace.ended.update(run.event_end)
    return trace
