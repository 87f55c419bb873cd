"""Generate the built-in OpenDRIVE map library with scenariogeneration.xodr.

    python maps/generate.py            # rewrites maps/*.xodr; byte-identical on every run

The library is small but covers every word of the vocabulary somewhere: 4-way and T junctions with 1 to 3
lanes a direction; traffic lights (with junction controllers), stop and yield signs; the crosswalk kinds,
stop lines and STOP stencils; speed signs 30/40/60/90; shoulders and sidewalks; straight multi-lane roads;
and a small town, a row of three junctions, so that road choice has room for diversity.

scenariogeneration has no junction controllers and stamps the current date into the header, and
netconvert cannot compute constant-curvature spirals: a short lxml pass after writing fixes those three.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

from lxml import etree
from scenariogeneration import xodr

HERE = Path(__file__).resolve().parent
DRIVING_WIDTH, SHOULDER_WIDTH, SIDEWALK_WIDTH = 3.5, 1.5, 2.0
JUNCTION_RADIUS = 18.0
FIXED_DATE = "2026-01-01T00:00:00"


class Side:
    """What one road offers on each side: driving lanes, then a shoulder and/or a sidewalk at the edge."""

    def __init__(self, lanes: int, shoulder: bool = True, sidewalk: bool = True):
        self.lanes, self.shoulder, self.sidewalk = lanes, shoulder, sidewalk

    @property
    def width(self) -> float:
        return self.lanes * DRIVING_WIDTH + self.shoulder * SHOULDER_WIDTH + self.sidewalk * SIDEWALK_WIDTH


def make_road(rid: int, length: float, side: Side, speed_kmh: float, geometry=None,
              lane_line: str = "broken") -> xodr.Road:
    """A straight road (or the given geometry); lane_line: the mark between same-direction lanes."""
    plan = xodr.PlanView()
    for primitive in geometry or [xodr.Line(length)]:
        plan.add_geometry(primitive)
    centre = xodr.Lane(a=0)
    centre.add_roadmark(xodr.std_roadmark_solid() if side.lanes == 1 else xodr.std_roadmark_solid_solid())
    section = xodr.LaneSection(0, centre)
    for add in (section.add_left_lane, section.add_right_lane):
        for i in range(side.lanes):
            lane = xodr.Lane(lane_type=xodr.LaneType.driving, a=DRIVING_WIDTH)
            inner = xodr.std_roadmark_broken() if lane_line == "broken" else xodr.std_roadmark_solid()
            lane.add_roadmark(inner if i < side.lanes - 1 else xodr.std_roadmark_solid())
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


class Fittings:
    """Signs, signals and markings for the traffic that drives towards s = 0 (towards a junction there)."""

    def __init__(self, road: xodr.Road, side: Side, at_start: bool = True, length: float = 0.0):
        self.road, self.side = road, side
        # Traffic towards s = 0 drives on the left lanes (t > 0) against s; towards the end, right lanes along s.
        self.sign, self.orientation = (1, xodr.Orientation.negative) if at_start else (-1, xodr.Orientation.positive)
        self.at = (lambda d: d) if at_start else (lambda d: length - d)

    ids = iter(())  # a counter for the map being built: signal and object ids are unique in the file

    def _id(self) -> str:
        return str(next(Fittings.ids))

    def _signal(self, distance: float, type_code: str, name: str, value=None, dynamic=False, subtype="-1") -> str:
        sid = self._id()
        self.road.add_signal(xodr.Signal(
            s=self.at(distance), t=self.sign * (self.side.width - 0.5), country="DEU", Type=type_code,
            subtype=subtype, id=sid, name=name, value=value, unit="km/h" if value else None,
            dynamic=xodr.Dynamic.yes if dynamic else xodr.Dynamic.no, orientation=self.orientation,
            zOffset=2.0, height=1.0, width=0.6))
        return sid

    def traffic_light(self) -> str:
        return self._signal(3.0, "1000001", "traffic_light", dynamic=True)

    def stop(self):
        self._signal(3.0, "206", "stop_sign")

    def give_way(self):
        self._signal(3.0, "205", "yield_sign")

    def speed(self, kmh: int, distance: float = 40.0):
        self._signal(distance, "274", f"speed_{kmh}", value=kmh, subtype=str(kmh))

    def stop_line(self):
        half = self.side.lanes * DRIVING_WIDTH
        self.road.add_object(xodr.Object(
            s=self.at(1.0), t=self.sign * half / 2, Type=xodr.ObjectType.roadMark, subtype="stopLine",
            id=self._id(), name="StopLine", orientation=self.orientation, hdg=math.pi / 2, width=0.4, length=half,
            height=0.0))

    def stencil_stop(self):
        self.road.add_object(xodr.Object(
            s=self.at(8.0), t=self.sign * DRIVING_WIDTH / 2, Type=xodr.ObjectType.roadMark, subtype="text",
            id=self._id(), name="Stencil_STOP", orientation=self.orientation, width=2.5, length=2.5, height=0.0))

    def crosswalk(self, kind: str, distance: float = 5.0):
        """A crossing over the whole carriageway; kind: ladder, continental or parallel_open."""
        span = 2 * self.side.lanes * DRIVING_WIDTH + 2 * self.side.shoulder * SHOULDER_WIDTH
        name = "".join(part.capitalize() for part in kind.split("_")) + "Crosswalk"
        self.road.add_object(xodr.Object(
            s=self.at(distance), t=0.0, Type=xodr.ObjectType.crosswalk, subtype=kind, id=self._id(), name=name,
            orientation=xodr.Orientation.none, hdg=math.pi / 2, width=4.0, length=span, height=0.0))


def junction(jid: int, arms: list[tuple[xodr.Road, float, str]], lanes: dict[int, int]) -> xodr.CommonJunctionCreator:
    """A junction of roads at the given angles (lanes: driving lanes a direction, by road id). Straight from
    every lane, left from the inner lane into the inner lane, right from the outer lane into the outer lane.
    Inner-lane connections go first: scenariogeneration misplaces a road otherwise."""
    creator = xodr.CommonJunctionCreator(id=jid, name=f"junction{jid}", startnum=jid * 100)
    for road, angle, end in arms:
        creator.add_incoming_road_circular_geometry(road, JUNCTION_RADIUS, angle, end)
    angle_of = {road.id: angle for road, angle, _ in arms}
    end_of = {road.id: end for road, _, end in arms}

    def incoming(rid: int, k: int) -> int:  # lane +k drives into the junction at a road's start, -k at its end
        return k if end_of[rid] == "predecessor" else -k

    connections = []
    for a in angle_of:
        for b in angle_of:
            if a == b:
                continue
            turn = (angle_of[b] - (angle_of[a] + math.pi) + math.pi) % (2 * math.pi) - math.pi
            if abs(turn) < 0.3:
                pairs = [(k, k) for k in range(1, min(lanes[a], lanes[b]) + 1)]
            else:
                pairs = [(1, 1)] if turn > 0 else [(lanes[a], lanes[b])]
            connections.append((a, b, [incoming(a, i) for i, _ in pairs], [-incoming(b, j) for _, j in pairs]))
    connections.sort(key=lambda c: (min(abs(x) for x in c[2]), c[0], c[1]))
    for c in connections:
        creator.add_connection(*c)
    return creator


def single_junction(name: str, angles: list[float], side: Side, speed: int, fit) -> tuple[xodr.OpenDrive, dict]:
    odr = xodr.OpenDrive(name, revMajor="1", revMinor="6")
    roads = [make_road(i + 1, 120.0, side, speed) for i in range(len(angles))]
    controls = {}
    for road in roads:
        lights = fit(Fittings(road, side), road)
        if lights:
            controls[lights] = 1
        odr.add_road(road)
    odr.add_junction_creator(junction(1, [(r, a, "predecessor") for r, a in zip(roads, angles)],
                                      {r.id: side.lanes for r in roads}))
    odr.adjust_roads_and_lanes()
    return odr, {1: sorted(controls)} if controls else {}


def fourway_2lane_lights():
    def fit(f: Fittings, road):
        light = f.traffic_light()
        f.stop_line()
        f.crosswalk("continental")
        f.speed(40)
        return light
    return single_junction("fourway_2lane_lights", [0, math.pi / 2, math.pi, 3 * math.pi / 2], Side(2), 40, fit)


def fourway_1lane_stop():
    def fit(f: Fittings, road):
        f.stop()
        f.stop_line()
        f.stencil_stop()
        f.crosswalk("ladder")
        f.speed(30)
    return single_junction("fourway_1lane_stop", [0, math.pi / 2, math.pi, 3 * math.pi / 2],
                           Side(1, shoulder=False), 30, fit)


def fourway_3lane_lights():
    def fit(f: Fittings, road):
        light = f.traffic_light()
        f.stop_line()
        f.crosswalk("parallel_open")
        f.speed(60)
        return light
    return single_junction("fourway_3lane_lights", [0, math.pi / 2, math.pi, 3 * math.pi / 2], Side(3), 60, fit)


def tjunction_2lane_yield():
    def fit(f: Fittings, road):
        if road.id == 2:  # the stem gives way
            f.give_way()
            f.crosswalk("continental")
        f.speed(40)
    return single_junction("tjunction_2lane_yield", [0, math.pi / 2, math.pi], Side(2), 40, fit)


def tjunction_1lane_stop():
    def fit(f: Fittings, road):
        if road.id == 2:
            f.stop()
            f.stop_line()
        f.speed(30)
    return single_junction("tjunction_1lane_stop", [0, math.pi / 2, math.pi], Side(1, sidewalk=False), 30, fit)


def motorway_3lane():
    odr = xodr.OpenDrive("motorway_3lane", revMajor="1", revMinor="6")
    side = Side(3, shoulder=True, sidewalk=False)
    road = make_road(1, 900.0, side, 90, [xodr.Line(400), xodr.Arc(0.002, angle=0.2), xodr.Line(400)])
    for at_start in (True, False):
        Fittings(road, side, at_start=at_start, length=900.0).speed(90, distance=60.0)
    odr.add_road(road)
    odr.adjust_roads_and_lanes()
    return odr, {}


def avenue_2lane():
    odr = xodr.OpenDrive("avenue_2lane", revMajor="1", revMinor="6")
    side = Side(2, shoulder=False, sidewalk=True)
    road = make_road(1, 400.0, side, 60, lane_line="solid")  # no lane changes near the crossing
    start, end = Fittings(road, side, True, 400.0), Fittings(road, side, False, 400.0)
    start.speed(60, distance=30.0)
    end.speed(60, distance=30.0)
    start.crosswalk("continental", distance=200.0)
    odr.add_road(road)
    odr.adjust_roads_and_lanes()
    return odr, {}


def town_row():
    """Three 4-way junctions in a row on a two-lane main street, one-lane side streets: lights, stop, yield."""
    odr = xodr.OpenDrive("town_row", revMajor="1", revMinor="6")
    main, small = Side(2), Side(1, shoulder=False)
    # main street pieces 1..4 run west to east; junction k sits between piece k and piece k+1
    pieces = [make_road(k, 100.0, main, 30) for k in (1, 2, 3, 4)]
    controls = {}
    creators = []
    for k in (1, 2, 3):
        north, south = make_road(10 * k + 1, 80.0, small, 30), make_road(10 * k + 2, 80.0, small, 30)
        west, east = pieces[k - 1], pieces[k]
        arms = [(west, math.pi, "successor"), (east, 0.0, "predecessor"),
                (north, math.pi / 2, "predecessor"), (south, 3 * math.pi / 2, "predecessor")]
        lights = []
        for road in (north, south):
            f = Fittings(road, small)
            if k == 1:
                lights.append(f.traffic_light())
                f.stop_line()
            elif k == 2:
                f.stop()
                f.stop_line()
            else:
                f.give_way()
            f.speed(30)
            odr.add_road(road)
        if k == 1:
            lights.append(Fittings(east, main).traffic_light())
            lights.append(Fittings(west, main, at_start=False, length=100.0).traffic_light())
            Fittings(east, main).crosswalk("ladder")
            controls[1] = sorted(lights)
        creators.append(junction(k, arms, {west.id: 2, east.id: 2, north.id: 1, south.id: 1}))
    Fittings(pieces[0], main).speed(30)
    Fittings(pieces[3], main, at_start=False, length=100.0).speed(30)
    for road in pieces:
        odr.add_road(road)
    for creator in creators:
        odr.add_junction_creator(creator)
    odr.adjust_roads_and_lanes()
    return odr, controls


MAPS = [fourway_2lane_lights, fourway_1lane_stop, fourway_3lane_lights, tjunction_2lane_yield, tjunction_1lane_stop,
        motorway_3lane, avenue_2lane, town_row]


def finish(path: Path, controls: dict[int, list[str]]) -> None:
    """Post-process what scenariogeneration cannot express: a fixed date, controllers, no flat spirals."""
    tree = etree.parse(str(path), etree.XMLParser(remove_blank_text=True))
    root = tree.getroot()
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
    tree.write(str(path), xml_declaration=True, encoding="utf-8", pretty_print=True)


def main(out: Path = HERE) -> list[Path]:
    written = []
    for number, build in enumerate(MAPS, start=1):
        # scenariogeneration remembers ids for the whole process: give each map its own range
        Fittings.ids = iter(range(1000 * number, 1000 * (number + 1)))
        odr, controls = build()
        path = out / f"{build.__name__}.xodr"
        odr.write_xml(str(path))
        finish(path, controls)
        written.append(path)
    return written


if __name__ == "__main__":
    for p in main(Path(sys.argv[1]) if len(sys.argv) > 1 else HERE):
        print(p)
