"""Run a .xosc in SUMO through libsumo: fixed 0.1 s steps, one simulation at a time, deterministic.

OpenDRIVE lane positions become SUMO lanes through the lanes' original ids (road_lane) and the net offset;
vehicles drive SUMO's car-following model with the speeds, routes and lane changes the file commands.
Bodies SUMO has no lane for are moved by the executor itself: people (along their sidewalk, or in a
straight line across the road, mid-block included) and anything on a shoulder, which SUMO's OpenDRIVE
import discards. SUMO's drivers do not see those bodies; the checks and the collision test do.
The run records every body's position, heading and speed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

from lxml import etree

from ttsgc.roads.opendrive import OpenDrive, load_opendrive
from ttsgc.simulate.network import Network, network_for
from ttsgc.simulate.xosc_plan import Action, Condition, Entity, Event, Plan

STEP_S = 0.1
TIME_LIMIT_S = 180.0
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
    def spawn(self, entity: Entity, position: tuple[str, int, float], speed: float, t: float) -> None:
        import libsumo as ts

        road, lane, s = position
        if road not in self.odr.roads or lane not in self.odr.roads[road].section_at(s).lanes:
            self.run.spawns[entity.name] = Spawn(False, f"road {road} has no lane {lane} at s={s:g}", (road, lane))
            return
        if entity.kind == "pedestrian" or entity.intent.get("road_type") == "shoulder":
            pose = self.odr.roads[road].lane_point(s, lane)
            self.movers[entity.name] = Mover(pose.x, pose.y, pose.hdg, speed, road, lane, s)
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
            ts.vehicletype.setMaxSpeed(type_id, max(speed, 1.0) * 1.5 + 5)
            ts.route.add(f"route_{entity.name}", self._ahead(sumo_lane.id))
            # SUMO places a vehicle by its front bumper
            front = min(pos + entity.length / 2, _length(sumo_lane.shape) - 0.05)
            ts.vehicle.add(entity.name, f"route_{entity.name}", typeID=type_id, depart="now",
                           departLane=str(sumo_lane.index), departPos=f"{front:.2f}", departSpeed=f"{speed:.3f}")
            ts.vehicle.setLaneChangeMode(entity.name, 0b000100000000)  # no lane changes of its own
            ts.vehicle.setSpeed(entity.name, speed)
        self.present.add(entity.name)
        got = self.odr_of(sumo_lane.id)
        ok = got == (road, lane)
        reason = "" if ok else f"placed on road {got[0]} lane {got[1]} instead of road {road} lane {lane}"
        self.run.spawns[entity.name] = Spawn(ok, reason, (road, lane), got, t)

    # -- actions ------------------------------------------------------------------------------------------
    def execute(self, actor: str, action: Action, t: float, event: Event) -> None:
        import libsumo as ts

        entity = self.plan.entities.get(actor)
        if entity is None:
            self.run.problems.append(f"{event.name}: no entity '{actor}'")
            return
        try:
            if action.kind == "teleport" and actor not in self.present:
                speed = next((a.value for a in event.actions if a.kind == "speed"), 0.0)
                self.spawn(entity, action.lane, speed, t)
                self.joined.add((event.name, actor))
            elif action.kind == "appear":
                self._appear(entity, action, event, t)
                self.joined.add((event.name, actor))
            elif action.kind == "speed" and (event.name, actor) in self.joined:
                return  # it entered with this speed
            elif actor not in self.present:
                self.run.problems.append(f"{event.name}: '{actor}' is not in the simulation")
            elif actor in self.movers:
                self._move_order(self.movers[actor], action, event)
            elif action.kind == "speed":
                self._speed(entity, action, t)
            elif action.kind == "lane_change":
                index = ts.vehicle.getLaneIndex(actor) + int(action.value)
                lanes = ts.edge.getLaneNumber(ts.vehicle.getRoadID(actor))
                if not 0 <= index < lanes or not self._drivable(ts.vehicle.getRoadID(actor), index):
                    self.run.problems.append(f"{event.name}: '{actor}' has no lane {int(action.value):+d} to change to")
                else:
                    ts.vehicle.changeLane(actor, index, 60.0)
            elif action.kind == "route":
                self._route(entity, action, event)
            elif action.kind == "acquire":
                self._route(entity, Action("route", waypoints=(action.lane,)), event)
        except Exception as exc:  # noqa: BLE001 - a command SUMO refuses is a failed action, reported
            self.run.problems.append(f"{event.name}: {action.kind} failed in SUMO: {exc}")

    def _move_order(self, mover: Mover, action: Action, event: Event) -> None:
        """An action for a body the executor moves: a speed, or a position to walk (or roll) to."""
        if action.kind == "speed":
            mover.target_speed, mover.rate = action.value, action.rate
            if not action.rate:
                mover.speed = action.value
        elif action.kind == "acquire":
            pose = self.odr.roads[action.lane[0]].lane_point(action.lane[2], action.lane[1])
            mover.target = (pose.x, pose.y)
            if mover.speed <= 0.01:
                mover.speed = 1.0
        else:
            self.run.problems.append(f"{event.name}: {action.kind} is not possible off the SUMO lanes")

    def _ahead(self, lane_id: str, limit_m: float = 1000.0) -> list[str]:
        """Until the file gives it a route, a vehicle carries on straight ahead (else the way its lane leads),
        rather than leave the network at the end of its first, perhaps very short, road."""
        import libsumo as ts

        edges, total, lane = [self.by_id[lane_id].edge], 0.0, lane_id
        for _ in range(60):
            links = ts.lane.getLinks(lane)
            if not links or total > limit_m:
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

    def _speed(self, entity: Entity, action: Action, t: float) -> None:
        import libsumo as ts

        current = ts.vehicle.getSpeed(entity.name)
        if action.rate:
            duration = max(abs(current - action.value) / action.rate, STEP_S)
            ts.vehicle.slowDown(entity.name, action.value, duration)
            self.holds.append((t + duration, entity.name, action.value))
        else:
            ts.vehicle.setSpeed(entity.name, action.value)

    def _route(self, entity: Entity, action: Action, event: Event) -> None:
        import libsumo as ts

        current = ts.vehicle.getRoadID(entity.name)
        if current.startswith(":"):
            current = ts.vehicle.getRoute(entity.name)[ts.vehicle.getRouteIndex(entity.name)]
        edges = [current]
        for point in action.waypoints:
            mapped = self.to_sumo(*point)
            if mapped is None or mapped[0].edge == edges[-1]:
                continue
            found = ts.simulation.findRoute(edges[-1], mapped[0].edge, vType=ts.vehicle.getTypeID(entity.name))
            if not found.edges:
                self.run.problems.append(f"{event.name}: no route from {edges[-1]} to {mapped[0].edge}")
                return
            edges += list(found.edges[1:])
        ts.vehicle.setRoute(entity.name, edges)

    def _can_appear(self, event: Event) -> bool:
        import libsumo as ts

        for action in event.actions:
            ref = action.relative[0] if action.kind == "appear" else None
            if ref in self.present and ref in self.active and ref not in self.movers:
                if ts.vehicle.getRoadID(ref).startswith(":"):
                    return False
        return True

    def _appear(self, entity: Entity, action: Action, event: Event, t: float) -> None:
        import libsumo as ts

        ref, dlane, ds = action.relative
        if ref not in self.present:
            self.run.problems.append(f"{event.name}: '{ref}' is not in the simulation to appear beside")
            return
        edge = ts.vehicle.getRoadID(ref)
        index = ts.vehicle.getLaneIndex(ref) + dlane
        lane_id = f"{edge}_{index}"
        if lane_id not in self.by_id:
            self.run.spawns[entity.name] = Spawn(False, f"the ego's lane has no neighbour {dlane:+d} at t={t:.1f}")
            return
        centre = ts.vehicle.getLanePosition(ref) - self.plan.entities[ref].length / 2 + ds
        sumo_lane = self.by_id[lane_id]
        length = _length(sumo_lane.shape)
        if not 0 < centre < length:
            self.run.spawns[entity.name] = Spawn(False, f"no room {ds:+.0f} m from the ego on its road at t={t:.1f}")
            return
        road, lane = self.odr_of(lane_id)
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
        if condition.kind == "time":
            return t >= condition.value + condition.delay - 1e-9
        if condition.kind == "state":
            times = self.run.act_end if condition.state == "endTransition" else self.run.act_start
            if condition.ref in times:
                return t >= times[condition.ref] + condition.delay - 1e-9
            if condition.ref in self.run.fired and condition.state in ("endTransition", "completeState"):
                return t >= self.run.fired[condition.ref] + condition.delay - 1e-9
            return False
        if condition.kind == "reach":
            a = self.last(condition.triggering or actor)
            if a is None:
                return False
            p = self.odr.roads[condition.position[0]].lane_point(condition.position[2], condition.position[1])
            return math.hypot(a.x - p.x, a.y - p.y) < condition.value
        if condition.kind == "distance":
            who = condition.triggering or actor
            a, b = self.last(who), self.last(condition.ref)
            return a is not None and b is not None and math.hypot(a.x - b.x, a.y - b.y) < condition.value
        return False

    def triggered(self, groups: list[list[Condition]], t: float, actor: str = "") -> bool:
        return any(all(self.holds_true(c, t, actor) for c in group) for group in groups)

    def last(self, name: str) -> Sample | None:
        samples = self.run.samples.get(name)
        return samples[-1] if samples and name in self.present and name in self.active else None

    def execute_plan(self) -> Run:
        import libsumo as ts

        ts.start(["sumo", "-n", str(self.network.path), "--step-length", str(STEP_S), "--no-step-log", "true",
                  "--seed", str(self.seed), "--collision.action", "none", "--time-to-teleport", "-1",
                  "--no-warnings", "true",
                  "--insertion-checks", "collision"])  # scenes start agents close on purpose
        try:
            for name, actions in self.plan.init.items():
                entity = self.plan.entities.get(name)
                teleport = next((a for a in actions if a.kind == "teleport"), None)
                if entity is None or teleport is None:
                    continue
                speed = next((a.value for a in actions if a.kind == "speed"), 0.0)
                self.spawn(entity, teleport.lane, speed, 0.0)
            ts.simulationStep()  # SUMO inserts what was added on the next step
            t = round(ts.simulation.getTime(), 3)
            self._sample(t)
            while t < TIME_LIMIT_S:
                self._storyboard(t)
                if self.triggered(self.plan.stop, t):
                    break
                self._move()
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
                self.run.fired[event.name] = t
                for action in event.actions:
                    self.execute(event.actor, action, t, event)
            if all(e.name in self.run.fired for e in act.events):
                self.run.act_end[act.name] = t

    def _move(self) -> None:
        """Advance the bodies the executor moves: towards their target, else along their lane."""
        for mover in self.movers.values():
            if mover.target_speed is not None and mover.rate:
                delta = mover.rate * STEP_S
                mover.speed = max(mover.target_speed, mover.speed - delta) if mover.speed > mover.target_speed \
                    else min(mover.target_speed, mover.speed + delta)
            step = mover.speed * STEP_S
            if step <= 0:
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
            s = mover.s + (step if mover.lane < 0 else -step)
            if not 0.0 <= s <= road.length:
                if not self._next_road(mover, s - road.length if s > road.length else -s):
                    mover.speed = 0.0  # the end of its way: it stands
                continue
            pose = road.lane_point(s, mover.lane)
            mover.x, mover.y, mover.heading, mover.s = pose.x, pose.y, pose.hdg, s

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
                continue
            else:  # added, not yet inserted
                continue
            self.active.add(name)
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


def _length(shape) -> float:
    return sum(math.hypot(bx - ax, by - ay) for (ax, ay), (bx, by) in zip(shape, shape[1:]))


def _point_at(shape, pos: float) -> tuple[float, float]:
    for (ax, ay), (bx, by) in zip(shape, shape[1:]):
        seg = math.hypot(bx - ax, by - ay)
        if pos <= seg and seg > 0:
            return ax + (bx - ax) * pos / seg, ay + (by - ay) * pos / seg
        pos -= seg
    return shape[-1]


def simulate(xosc: str | Path, seed: int = 1):
    """Read, run and check a scenario file; returns the report (see checks.Report)."""
    from ttsgc.simulate.checks import check
    from ttsgc.simulate.xosc_plan import read_plan

    plan = read_plan(Path(xosc))
    executor = Executor(plan, seed=seed)
    run = executor.execute_plan()
    if not any(entity.intent for entity in plan.entities.values()):  # a file not written by ttsgc
        from ttsgc.simulate.general_verdict import judge_without_intents
        return judge_without_intents(plan, run, executor.odr)
    return check(plan, run, executor.odr)
