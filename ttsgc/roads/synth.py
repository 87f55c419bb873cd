"""Road synthesis: when no road of the library fits a scene, build an OpenDRIVE map that has what it asks.

The scene's road block says what the ego's approach must offer (lanes, junction, signals and objects, both
required and forbidden); its agents say what else the road needs (the ranker's requirements: the ego's turn,
the roads agents stand on and the turns they make there, neighbouring lanes, a shoulder or sidewalk, a
crossing ahead, room for every queue). `design` turns both into a plain `Design` (the seed varies angles,
lengths, lane widths and curvature among the layouts that fit); `build` writes it with scenariogeneration.xodr,
the same primitives that make the built-in library (maps/generate.py), so one generator serves both.

The ego's approach is road 1: at a junction it drives towards s = 0 (approach "1:bwd"), on a road without a
junction along s (approach "1:fwd") past a mid-block crossing when the scene has one. Every approach towards
the junction (or the crossing) carries the same signals and markings, so whichever one the ranker picks has
exactly what was asked, and nothing forbidden is placed anywhere on the map.

scenariogeneration has no junction controllers, stamps the current date into the header, and netconvert
cannot compute constant-curvature spirals: `finish` fixes those on the XML. Speed limits are the roads' type
speed, as in the built-in maps (lane speeds would make netconvert warn of fast turns and SUMO refuse fast
departures).
"""

from __future__ import annotations

import math
import random
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, replace
from pathlib import Path

from lxml import etree
from scenariogeneration import xodr

from ttsgc import vocabulary as V
from ttsgc.roads.retrieve import NoRoadError

DRIVING_WIDTH, SHOULDER_WIDTH, SIDEWALK_WIDTH = 3.5, 1.5, 2.0
JUNCTION_RADIUS = 18.0
FIXED_DATE = "2026-01-01T00:00:00"
SLOW_KMH = 20  # at or below, junctions are as compact as their roads allow


# -- building blocks (the built-in library uses these too) ------------------------------------------------

@dataclass(frozen=True)
class Side:
    """What one road offers on each side: driving lanes, then a shoulder and/or a sidewalk at the edge.
    lane_lines: the marks between same-direction lanes, innermost first, repeated outward
    ("broken", "solid" or "none")."""

    lanes: int
    shoulder: bool = True
    sidewalk: bool = True
    lane_width: float = DRIVING_WIDTH
    lane_lines: tuple[str, ...] = ("broken",)

    @property
    def width(self) -> float:
        return self.lanes * self.lane_width + self.shoulder * SHOULDER_WIDTH + self.sidewalk * SIDEWALK_WIDTH

    @property
    def carriageway(self) -> float:
        """Driving lanes and shoulder of one side: what a crossing spans."""
        return self.lanes * self.lane_width + self.shoulder * SHOULDER_WIDTH


_MARKS = {"broken": xodr.std_roadmark_broken, "solid": xodr.std_roadmark_solid,
          "none": lambda: xodr.RoadMark(xodr.RoadMarkType.none)}


def make_road(rid: int, length: float, side: Side, speed_kmh: float, geometry=None) -> xodr.Road:
    """A straight road (or the given geometry) with `side` on both sides of the centre line."""
    plan = xodr.PlanView()
    for primitive in geometry or [xodr.Line(length)]:
        plan.add_geometry(primitive)
    centre = xodr.Lane(a=0)
    centre.add_roadmark(xodr.std_roadmark_solid() if side.lanes == 1 else xodr.std_roadmark_solid_solid())
    section = xodr.LaneSection(0, centre)
    for add in (section.add_left_lane, section.add_right_lane):
        for i in range(side.lanes):
            lane = xodr.Lane(lane_type=xodr.LaneType.driving, a=side.lane_width)
            mark = side.lane_lines[i % len(side.lane_lines)] if i < side.lanes - 1 else "solid"
            lane.add_roadmark(_MARKS[mark]())
            add(lane)
        if side.shoulder:
            shoulder = xodr.Lane(lane_type=xodr.LaneType.shoulder, a=SHOULDER_WIDTH)
            shoulder.add_roadmark(xodr.std_roadmark_solid())
            add(shoulder)
        if side.sidewalk:
            add(xodr.Lane(lane_type=xodr.LaneType.sidewalk, a=SIDEWALK_WIDTH))
    lanes = xodr.Lanes()
    lanes.add_lanesection(section)
    road = xodr.Road(rid, plan, lanes)
    road.add_type(xodr.RoadType.town if speed_kmh <= 60 else xodr.RoadType.motorway, speed=speed_kmh,
                  speed_unit="km/h")
    return road


class Numbering:
    """Signal and object ids, unique within one map."""

    def __init__(self, first: int = 1000):
        self._next = first

    def __call__(self) -> str:
        self._next += 1
        return str(self._next - 1)


class Fittings:
    """Signs, signals and markings for the traffic that drives towards s = 0 (at_start) or towards the road's
    end; distances are metres before that end.

    They go straight into the road's lists: Road.add_signal / add_object renumber any id used before anywhere
    in the process, so a second map built in one process would get other ids. Numbering keeps them unique
    within a file, which is all OpenDRIVE asks."""

    def __init__(self, road: xodr.Road, side: Side, ids: Numbering, at_start: bool = True, length: float = 0.0):
        self.road, self.side, self._id = road, side, ids
        # Traffic towards s = 0 drives on the left lanes (t > 0) against s; towards the end, right lanes along s.
        self.sign, self.orientation = (1, xodr.Orientation.negative) if at_start else (-1, xodr.Orientation.positive)
        self.at = (lambda d: d) if at_start else (lambda d: length - d)

    def _signal(self, distance: float, type_code: str, name: str, value=None, dynamic=False, subtype="-1") -> str:
        sid = self._id()
        self.road.signals.append(xodr.Signal(
            s=self.at(distance), t=self.sign * (self.side.width - 0.5), country="DEU", Type=type_code,
            subtype=subtype, id=sid, name=name, value=value, unit="km/h" if value else None,
            dynamic=xodr.Dynamic.yes if dynamic else xodr.Dynamic.no, orientation=self.orientation,
            zOffset=2.0, height=1.0, width=0.6))
        return sid

    def traffic_light(self, distance: float = 3.0) -> str:
        return self._signal(distance, "1000001", "traffic_light", dynamic=True)

    def stop(self, distance: float = 3.0):
        self._signal(distance, "206", "stop_sign")

    def give_way(self, distance: float = 3.0):
        self._signal(distance, "205", "yield_sign")

    def speed(self, kmh: int, distance: float = 40.0):
        self._signal(distance, "274", f"speed_{kmh}", value=kmh, subtype=str(kmh))

    def stop_line(self, distance: float = 1.0):
        half = self.side.lanes * self.side.lane_width
        self.road.objects.append(xodr.Object(
            s=self.at(distance), t=self.sign * half / 2, Type=xodr.ObjectType.roadMark, subtype="stopLine",
            id=self._id(), name="StopLine", orientation=self.orientation, hdg=math.pi / 2, width=0.4, length=half,
            height=0.0))

    def stencil_stop(self, distance: float = 8.0):
        self.road.objects.append(xodr.Object(
            s=self.at(distance), t=self.sign * self.side.lane_width / 2, Type=xodr.ObjectType.roadMark,
            subtype="text", id=self._id(), name="Stencil_STOP", orientation=self.orientation, width=2.5, length=2.5,
            height=0.0))

    def crosswalk(self, kind: str, distance: float = 5.0):
        """A crossing over the whole carriageway; kind: ladder, continental, parallel_open or plain."""
        span = 2 * self.side.carriageway
        name = "".join(part.capitalize() for part in kind.split("_")) + "Crosswalk" if kind != "plain" else "Crosswalk"
        self.road.objects.append(xodr.Object(
            s=self.at(distance), t=0.0, Type=xodr.ObjectType.crosswalk, subtype=kind, id=self._id(), name=name,
            orientation=xodr.Orientation.none, hdg=math.pi / 2, width=4.0, length=span, height=0.0))


def junction(jid: int, arms: list[tuple[xodr.Road, float, str]], lanes: dict[int, int],
             radius: float = JUNCTION_RADIUS, turn_lanes: int = 1) -> xodr.CommonJunctionCreator:
    """A junction of roads at the given angles (lanes: driving lanes a direction, by road id). Straight from
    every lane, left from the `turn_lanes` inner lanes into the inner lanes, right from the outer ones into the
    outer ones. Inner-lane connections go first: scenariogeneration misplaces a road otherwise."""
    creator = xodr.CommonJunctionCreator(id=jid, name=f"junction{jid}", startnum=jid * 100)
    for road, angle, end in arms:
        creator.add_incoming_road_circular_geometry(road, radius, angle, end)
    angle_of = {road.id: angle for road, angle, _ in arms}
    end_of = {road.id: end for road, _, end in arms}

    def incoming(rid: int, k: int) -> int:  # lane +k drives into the junction at a road's start, -k at its end
        return k if end_of[rid] == "predecessor" else -k

    pairs: dict[tuple[int, int], list[tuple[int, int]]] = {}
    for a in angle_of:
        for b in angle_of:
            if a == b:
                continue
            turn = turn_angle(angle_of[a], angle_of[b])
            if abs(turn) < 0.3:
                pairs[a, b] = [(k, k) for k in range(1, min(lanes[a], lanes[b]) + 1)]
            elif turn > 0:  # each into a lane of its own: netconvert drops one of two joining a lane
                pairs[a, b] = [(k, k) for k in range(1, min(turn_lanes, lanes[a], lanes[b]) + 1)]
            else:
                pairs[a, b] = [(lanes[a] - k, lanes[b] - k) for k in range(min(turn_lanes, lanes[a], lanes[b]))]
    # Every lane into and out of the junction gets a connection (netconvert warns of one without): a lane the
    # rules above leave out joins the straightest movement from (or into) its road.
    straightest = lambda a, b: abs(turn_angle(angle_of[a], angle_of[b]))  # noqa: E731
    for a in angle_of:
        for i in range(1, lanes[a] + 1):
            if not any(x == i for (src, _), links in pairs.items() if src == a for x, _ in links):
                b = min((b for b in angle_of if b != a), key=lambda b: straightest(a, b))
                free = [j for j in range(1, lanes[b] + 1) if all(y != j for _, y in pairs[a, b])]
                pairs[a, b].append((i, min(free or [lanes[b]], key=lambda j: abs(j - i))))
    for b in angle_of:
        for j in range(1, lanes[b] + 1):
            if not any(y == j for (_, dst), links in pairs.items() if dst == b for _, y in links):
                a = min((a for a in angle_of if a != b), key=lambda a: straightest(a, b))
                pairs[a, b].append((min(j, lanes[a]), j))
    connections = [(a, b, [incoming(a, i) for i, _ in sorted(links)], [-incoming(b, j) for _, j in sorted(links)])
                   for (a, b), links in pairs.items()]
    connections.sort(key=lambda c: (min(abs(x) for x in c[2]), c[0], c[1]))
    for c in connections:
        creator.add_connection(*c)
    return creator


def turn_angle(from_arm: float, to_arm: float) -> float:
    """Heading change (counter-clockwise positive) driving in on the arm at one angle, out on another."""
    return (to_arm - (from_arm + math.pi) + math.pi) % (2 * math.pi) - math.pi


def finish(odr: xodr.OpenDrive, controls: dict[int, list[str]]) -> bytes:
    """The file's bytes, with what scenariogeneration cannot express: a fixed date, junction controllers, and
    arcs or lines instead of constant-curvature spirals."""
    root = etree.fromstring(ET.tostring(odr.get_element()), etree.XMLParser(remove_blank_text=True))
    root.find("header").set("date", FIXED_DATE)
    for spiral in list(root.iter("spiral")):
        k0, k1 = float(spiral.get("curvStart")), float(spiral.get("curvEnd"))
        if abs(k1 - k0) < 1e-9:
            parent = spiral.getparent()
            parent.remove(spiral)
            if abs(k0) < 1e-9:
                etree.SubElement(parent, "line")
            else:
                etree.SubElement(parent, "arc", curvature=repr(k0))
    for jid, signal_ids in sorted(controls.items()):
        controller_id = str(1000 + jid)
        controller = etree.Element("controller", id=controller_id, name=f"junction{jid}_lights", sequence="0")
        for sid in signal_ids:
            etree.SubElement(controller, "control", signalId=sid, type="0")
        first_junction = root.find("junction")
        (first_junction.addprevious if first_junction is not None else root.append)(controller)
        for j in root.iter("junction"):
            if j.get("id") == str(jid):
                etree.SubElement(j, "controller", id=controller_id, type="0", sequence="0")
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)


# -- what the scene needs ---------------------------------------------------------------------------------

class SynthesisError(NoRoadError):
    """The scene asks for a road no map can have (its road block and its agents contradict each other)."""


SIGNAL_WORDS = ("traffic_light", "stop", "yield")
CROSSWALK_KINDS = {"ladder_crosswalk": "ladder", "continental_crosswalk": "continental",
                   "parallel_open_crosswalk": "parallel_open"}


@dataclass(frozen=True)
class Needs:
    """What the road must offer, from the road block and the ranker's agent requirements."""

    lanes: int
    neighbour_left: bool  # the ego's lane needs a lane on its left, or on its right
    neighbour_right: bool
    junction: bool | None  # True: the ego's approach ends at one; False: it must not; None: either
    movement: str | None  # the ego's turn at the junction
    sides: frozenset[str]  # roads entering from the ego's left / right / straight where agents stand
    side_turns: frozenset[tuple[str, str]]  # (side, turn) an agent standing there makes
    queued: dict[str, float]  # metres each entering road needs for its queue
    ahead_m: float  # the longest queue ahead of the ego, and behind it
    behind_m: float
    ego_length: float
    shoulder: bool
    sidewalk: bool
    crossing: bool  # near_the_crosswalk: a crossing ahead of the ego
    later_stages: int
    signals: tuple[str, ...]
    objects: tuple[str, ...]  # required objects, speed signs included
    forbidden: frozenset[str]


def needs_of(scenario) -> Needs:
    """Reads the scene as the ranker does (rank.py's requirements), so the map meets every column of its table."""
    from ttsgc.binding.rank import (AHEAD, BEHIND, DEFAULT_GAP_M, JUNCTION_SIDE, TURN_OF_ACTION, ego_movement,
                                    lane_needs)

    road = scenario.road
    need_left, need_right = lane_needs(scenario)
    queued: dict[str, float] = {}
    sides, side_turns = set(), set()
    shoulder = sidewalk = crossing = False
    queues: dict[str, float] = {}
    for agent in scenario.agents():
        if agent.is_ego:
            continue
        where = agent.relative_to_ego
        body = V.BODIES[agent.type][0]
        gap = agent.gap_m if agent.gap_m is not None else 2.0 if agent.type == "pedestrian" else \
            DEFAULT_GAP_M[agent.behavior]
        side = JUNCTION_SIDE.get(where)
        if side is not None:
            sides.add(side)
            queued[side] = queued.get(side, 2.0) + body + gap
            if agent.action in TURN_OF_ACTION and agent.road_type == "driving":
                side_turns.add((side, TURN_OF_ACTION[agent.action]))
        elif where in AHEAD + BEHIND:
            queues[where] = queues.get(where, 0.0) + body + gap
        shoulder |= agent.road_type == "shoulder"
        sidewalk |= agent.road_type == "sidewalk" or agent.type == "pedestrian"
        crossing |= where == "near_the_crosswalk"
    movement = ego_movement(scenario)
    junction = road.junction
    if movement is not None or sides:
        junction = True
    if movement is None and any(a.relative_to_ego == "at_the_destination" for a in scenario.agents()):
        if junction:  # the ego does not cross the junction, so its destination is further along its road
            why = "the road block says 'at junction'" if road.junction else "agents stand on roads at a junction"
            raise SynthesisError(f"cannot synthesise a road for the scene: the ego does not cross a junction, so "
                                 f"'at_the_destination' needs a road without one, but {why}")
        junction = False
    return Needs(
        lanes=max(road.lanes, 1 + need_left + need_right), neighbour_left=need_left, neighbour_right=need_right,
        junction=junction, movement=movement,
        sides=frozenset(sides), side_turns=frozenset(side_turns), queued=queued,
        ahead_m=max((queues.get(p, 0.0) for p in AHEAD), default=0.0),
        behind_m=max((queues.get(p, 0.0) for p in BEHIND), default=0.0),
        ego_length=V.BODIES[scenario.ego.type][0], shoulder=shoulder, sidewalk=sidewalk, crossing=crossing,
        later_stages=len(scenario.stages) - 1, signals=tuple(road.required_signals),
        objects=tuple(road.required_objects), forbidden=frozenset(road.without_signals + road.without_objects))


# -- the design -------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Arm:
    """One road of the map, leaving the junction (or the map's only road)."""

    role: str  # "ego", or the side it enters the junction from as the ego sees it: left / right / straight
    angle: float  # radians, the direction it leaves the junction centre in
    lanes: int  # driving lanes a direction
    length: float
    bend: float  # curvature of the arc in its middle (0: straight)


@dataclass(frozen=True)
class Design:
    """Everything the map will have, as plain data; `build` writes it."""

    name: str
    layout: str  # fourway, tee or straight
    arms: tuple[Arm, ...]  # road ids 1, 2, ... in this order; arms[0] is the ego's road
    side: Side  # of the ego's road; other arms differ in lanes only
    radius: float  # of the junction
    speed_kmh: int  # the roads' speed limit (their type's speed; a speed sign says it too when asked)
    speed_signs: tuple[int, ...]
    signals: tuple[str, ...]  # on every approach towards the junction or the crossing
    crosswalks: tuple[str, ...]  # kinds, each a crossing on every such approach
    stop_line: bool
    stencil: bool
    crossing_s: float | None = None  # a road without a junction: where its crossing and signs stand
    ego_approach: str = "1:bwd"


LAYOUTS = {  # arm angles with the ego's arm at 0; the ego drives in towards the centre (heading pi)
    "fourway": (0.0, math.pi / 2, math.pi, 3 * math.pi / 2),
    "tee_stem": (0.0, math.pi / 2, 3 * math.pi / 2),  # the ego on the stem: left and right
    "tee_right": (0.0, math.pi / 2, math.pi),  # the ego on the bar: straight and right
    "tee_left": (0.0, math.pi, 3 * math.pi / 2),  # straight and left
}


def _classify(change: float) -> str:
    return "straight" if abs(change) < math.pi / 4 else "left" if change > 0 else "right"


def _layout_fits(angles: tuple[float, ...], needs: Needs) -> bool:
    side_of = {_classify(turn_angle(angles[0], a)): a for a in angles[1:]}
    if needs.movement is not None and needs.movement not in side_of:
        return False
    if not needs.sides <= set(side_of):
        return False
    for side, turn in needs.side_turns:
        exits = {_classify(turn_angle(side_of[side], a)) for a in angles if a != side_of[side]}
        if turn not in exits:
            return False
    return True


def _words(needs: Needs, rng: random.Random) -> tuple[tuple[str, ...], list[int], tuple[str, ...], bool, bool, tuple]:
    """Signals, speed signs, crossing kinds, stop line, stencil and lane lines for the ego's approach."""
    required = set(needs.signals) | set(needs.objects)
    kinds = [CROSSWALK_KINDS[w] for w in sorted(required) if w in CROSSWALK_KINDS]
    if "crosswalk" in needs.forbidden and (kinds or needs.crossing):
        what = ", ".join(sorted(w for w in required if w in CROSSWALK_KINDS)) or "a crossing near the ego"
        raise SynthesisError(f"cannot synthesise a road for the scene: the road block forbids any crosswalk, but "
                             f"the scene needs {what}")
    if ("crosswalk" in required or needs.crossing) and not kinds:
        allowed = [k for w, k in sorted(CROSSWALK_KINDS.items()) if w not in needs.forbidden]
        kinds = [rng.choice(allowed) if allowed else "plain"]
    lines = []
    for word, mark in (("dashed_single_white", "broken"), ("solid_single_white", "solid")):
        if word in required:
            lines.append(mark)
    if not lines:
        allowed = [m for w, m in (("dashed_single_white", "broken"), ("solid_single_white", "solid"))
                   if w not in needs.forbidden]
        lines = [rng.choice(allowed)] if allowed else ["none"]
    speeds = [int(w[6:]) for w in needs.objects if V.SPEED_SIGN_PATTERN.fullmatch(w)]  # as the block lists them
    signals = tuple(w for w in SIGNAL_WORDS if w in required)
    return signals, speeds, tuple(kinds), "stop_line" in required, "stop_sign_on_road" in required, tuple(lines)


def design(scenario, seed: int, name: str | None = None) -> Design:
    """The map a scene needs; the seed picks among the layouts that fit and varies the geometry."""
    needs = needs_of(scenario)
    rng = random.Random(f"ttsgc-synth:{seed}")
    signals, speeds, kinds, stop_line, stencil, lines = _words(needs, rng)
    lanes = needs.lanes
    if len(lines) == 2 or "dashed_single_white" in needs.objects or "solid_single_white" in needs.objects:
        lanes = max(lanes, len(lines) + 1)  # the index sees lane lines between lanes of one direction
    junction = needs.junction if needs.junction is not None else bool(signals)
    speed = speeds[0] if speeds else rng.choice((30, 40, 50, 60) if junction else (50, 60, 80, 100))
    side = Side(lanes, shoulder=needs.shoulder or rng.random() < 0.5, sidewalk=needs.sidewalk or rng.random() < 0.6,
                lane_width=rng.choice((3.25, 3.5, 3.75)), lane_lines=lines)
    travel = speed / 3.6 * 6.0  # metres covered in six seconds: room to brake and to carry on
    stages = 40.0 * needs.later_stages
    name = name or f"synth_{_slug(scenario.name)}_{seed}"
    if junction:
        fitting = [k for k, angles in LAYOUTS.items() if _layout_fits(angles, needs)]
        if not fitting:
            raise SynthesisError("cannot synthesise a junction for the scene: no 4-way or T layout offers every "
                                 "turn and road its agents need")
        layout = rng.choice(fitting)
        rotation = rng.uniform(0, 2 * math.pi)
        angles = [a + (rng.uniform(-0.2, 0.2) if k else 0.0) + rotation for k, a in enumerate(LAYOUTS[layout])]
        # a turn made from the second lane (the ego's neighbour kept on the turn's side) needs two lanes to enter
        neighbour = needs.neighbour_left if needs.movement == "left" else \
            needs.neighbour_right if needs.movement == "right" else False
        side_lanes = rng.randint(2 if neighbour else 1, min(lanes, 3))
        arms = []
        for k, angle in enumerate(angles):
            role = "ego" if k == 0 else _classify(turn_angle(angles[0], angle))
            arm_lanes = lanes if role in ("ego", "straight") or (layout == "tee_stem" and k) else side_lanes
            if role == "ego":
                need = needs.behind_m + needs.ego_length + max(25.0, needs.ahead_m + 12.0) + 25.0
            else:
                need = needs.queued.get(role, 0.0) + 30.0
            length = max(need, 70.0 + travel + stages) + rng.uniform(0.0, 60.0)
            arms.append(Arm(role, round(angle, 6), arm_lanes, round(length, 1),
                            round(rng.choice((-1, 1)) * rng.uniform(0.0, 1 / 400), 6)))
        widest = max(replace(side, lanes=a.lanes).width for a in arms)
        closest = min(abs(turn_angle(a.angle + math.pi, b.angle)) for a in arms for b in arms if a is not b)
        # as small as the roads allow when slow: players allow about 45 m for a junction movement
        radius = max(rng.uniform(14.0, 20.0) if speed > SLOW_KMH else 0.0, widest / math.tan(closest / 2) + 3.0)
        return Design(name, "fourway" if layout == "fourway" else "tee", tuple(arms), side, round(radius, 3), speed,
                      tuple(speeds), signals, kinds, stop_line, stencil)
    # a road without a junction; a crossing (with whatever signs stand there) ahead of the ego
    crossing_needed = bool(kinds or signals or stop_line or stencil)
    start = needs.behind_m + needs.ego_length + 45.0 + rng.uniform(0.0, 40.0)
    length = start + needs.ahead_m + 60.0 + 2 * travel + stages + rng.uniform(0.0, 100.0)
    bend = round(rng.choice((-1, 1)) * rng.uniform(0.0, 1 / 500), 6)
    arm = Arm("ego", round(rng.uniform(0, 2 * math.pi), 6), lanes, round(length, 1), bend)
    return Design(name, "straight", (arm,), side, 0.0, speed, tuple(speeds), signals, kinds, stop_line, stencil,
                  crossing_s=round(start, 1) if crossing_needed else None, ego_approach="1:fwd")


def _slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", text.lower()).strip("_")[:40] or "scene"


# -- writing it -------------------------------------------------------------------------------------------

def _geometry(arm: Arm) -> list:
    """A straight run from the junction, a gentle bend, then straight again."""
    first = min(40.0, arm.length / 3)
    if abs(arm.bend) < 1e-9:
        return [xodr.Line(arm.length)]
    bend = arm.length / 3
    return [xodr.Line(first), xodr.Arc(arm.bend, length=bend), xodr.Line(arm.length - first - bend)]


def _fit(f: Fittings, d: Design, crossing_at: float, crossings: bool = True) -> str | None:
    """The design's signals and markings on one approach; crossing_at: metres before the junction (or the
    road's end) of the first crossing its traffic meets, the others following 5 m apart; crossings: whether
    to place the crossings too (a mid-block crossing serves both directions once). Returns the traffic
    light's signal id."""
    light = f.traffic_light(crossing_at + 3.0 if d.crosswalks else 3.0) if "traffic_light" in d.signals else None
    if "stop" in d.signals:
        f.stop(crossing_at + 3.5 if d.crosswalks else 3.5)
    if "yield" in d.signals:
        f.give_way(crossing_at + 4.0 if d.crosswalks else 4.0)
    for k, kind in enumerate(d.crosswalks if crossings else ()):
        f.crosswalk(kind, crossing_at - 5.0 * k)
    if d.stop_line:
        f.stop_line(crossing_at + 2.5 if d.crosswalks else 1.0)
    if d.stencil:
        f.stencil_stop(crossing_at + 8.0 if d.crosswalks else 8.0)
    for k, kmh in enumerate(d.speed_signs):
        f.speed(kmh, crossing_at + 30.0 + 5.0 * k)
    return light


def build(d: Design) -> bytes:
    """The OpenDRIVE file of a design."""
    odr = xodr.OpenDrive(d.name, revMajor="1", revMinor="6")
    ids = Numbering()
    roads = [make_road(k + 1, arm.length, replace(d.side, lanes=arm.lanes), d.speed_kmh, _geometry(arm))
             for k, arm in enumerate(d.arms)]
    if d.layout == "straight":
        road, arm = roads[0], d.arms[0]
        road.planview.set_start_point(0.0, 0.0, arm.angle)
        gap = 5.0 * max(len(d.crosswalks) - 1, 0)
        for at_start in (False, True):  # the ego's direction first: along s, towards the road's end
            f = Fittings(road, d.side, ids, at_start=at_start, length=arm.length)
            if d.crossing_s is not None:  # a light at a mid-block crossing needs no junction controller
                crossing = (arm.length - d.crossing_s) if not at_start else d.crossing_s + gap
                _fit(f, d, crossing, crossings=not at_start)
            else:  # signs soon after the road begins
                for k, kmh in enumerate(d.speed_signs):
                    f.speed(kmh, arm.length - 30.0 - 5.0 * k)
        odr.add_road(road)
        odr.adjust_roads_and_lanes()
        return finish(odr, {})
    lights = []
    for road, arm in zip(roads, d.arms):
        first_crossing = 5.0 + 5.0 * max(len(d.crosswalks) - 1, 0)
        light = _fit(Fittings(road, replace(d.side, lanes=arm.lanes), ids), d, first_crossing)
        if light:
            lights.append(light)
        odr.add_road(road)
    odr.add_junction_creator(junction(1, [(r, a.angle, "predecessor") for r, a in zip(roads, d.arms)],
                                      {r.id: a.lanes for r, a in zip(roads, d.arms)}, d.radius, turn_lanes=2))
    odr.adjust_roads_and_lanes()
    return finish(odr, {1: sorted(lights)} if lights else {})


def chosen_seed(scenario, seed: int | None) -> int:
    """The seed binding uses too: --seed, else the scene's seed, else 0."""
    from ttsgc.binding.scene import DEFAULT_SEED

    return seed if seed is not None else scenario.seed if scenario.seed is not None else DEFAULT_SEED


def synthesize(scenario, seed: int, name: str | None = None) -> tuple[Design, bytes]:
    d = design(scenario, seed, name)
    return d, build(d)


def synthesize_map(scenario, seed: int, folder: Path) -> Path:
    """Write the map a scene needs into `folder` (created if missing) and return its path."""
    from ttsgc.files import write_atomic

    d, data = synthesize(scenario, seed)
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{d.name}.xodr"
    write_atomic(path, data)
    return path
