"""Generate the built-in OpenDRIVE map library with scenariogeneration.xodr.

    python maps/generate.py            # rewrites maps/*.xodr; byte-identical on every run

The library is small but covers every word of the vocabulary somewhere: 4-way and T junctions with 1 to 3
lanes a direction; traffic lights (with junction controllers), stop and yield signs; the crosswalk kinds,
stop lines and STOP stencils; speed signs 30/40/60/90; shoulders and sidewalks; straight multi-lane roads;
and a small town, a row of three junctions, so that road choice has room for diversity.

The building blocks (roads, fittings, junctions, the finishing pass) are ttsgc.roads.synth's, which also
synthesises a map for a scene no library road fits: one generator serves both.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

from scenariogeneration import xodr

from ttsgc.files import write_atomic
from ttsgc.roads.synth import Fittings, Numbering, Side, finish, junction, make_road

HERE = Path(__file__).resolve().parent


def single_junction(name: str, angles: list[float], side: Side, speed: int, fit,
                    ids: Numbering) -> tuple[xodr.OpenDrive, dict]:
    odr = xodr.OpenDrive(name, revMajor="1", revMinor="6")
    roads = [make_road(i + 1, 120.0, side, speed) for i in range(len(angles))]
    controls = {}
    for road in roads:
        lights = fit(Fittings(road, side, ids), road)
        if lights:
            controls[lights] = 1
        odr.add_road(road)
    odr.add_junction_creator(junction(1, [(r, a, "predecessor") for r, a in zip(roads, angles)],
                                      {r.id: side.lanes for r in roads}))
    odr.adjust_roads_and_lanes()
    return odr, {1: sorted(controls)} if controls else {}


def fourway_2lane_lights(ids: Numbering):
    def fit(f: Fittings, road):
        light = f.traffic_light()
        f.stop_line()
        f.crosswalk("continental")
        f.speed(40)
        return light
    return single_junction("fourway_2lane_lights", [0, math.pi / 2, math.pi, 3 * math.pi / 2], Side(2), 40, fit, ids)


def fourway_1lane_stop(ids: Numbering):
    def fit(f: Fittings, road):
        f.stop()
        f.stop_line()
        f.stencil_stop()
        f.crosswalk("ladder")
        f.speed(30)
    return single_junction("fourway_1lane_stop", [0, math.pi / 2, math.pi, 3 * math.pi / 2],
                           Side(1, shoulder=False), 30, fit, ids)


def fourway_3lane_lights(ids: Numbering):
    def fit(f: Fittings, road):
        light = f.traffic_light()
        f.stop_line()
        f.crosswalk("parallel_open")
        f.speed(60)
        return light
    return single_junction("fourway_3lane_lights", [0, math.pi / 2, math.pi, 3 * math.pi / 2], Side(3), 60, fit, ids)


def tjunction_2lane_yield(ids: Numbering):
    def fit(f: Fittings, road):
        if road.id == 2:  # the stem gives way
            f.give_way()
            f.crosswalk("continental")
        f.speed(40)
    return single_junction("tjunction_2lane_yield", [0, math.pi / 2, math.pi], Side(2), 40, fit, ids)


def tjunction_1lane_stop(ids: Numbering):
    def fit(f: Fittings, road):
        if road.id == 2:
            f.stop()
            f.stop_line()
        f.speed(30)
    return single_junction("tjunction_1lane_stop", [0, math.pi / 2, math.pi], Side(1, sidewalk=False), 30, fit, ids)


def motorway_3lane(ids: Numbering):
    odr = xodr.OpenDrive("motorway_3lane", revMajor="1", revMinor="6")
    side = Side(3, shoulder=True, sidewalk=False)
    road = make_road(1, 900.0, side, 90, [xodr.Line(400), xodr.Arc(0.002, angle=0.2), xodr.Line(400)])
    for at_start in (True, False):
        Fittings(road, side, ids, at_start=at_start, length=900.0).speed(90, distance=60.0)
    odr.add_road(road)
    odr.adjust_roads_and_lanes()
    return odr, {}


def avenue_2lane(ids: Numbering):
    odr = xodr.OpenDrive("avenue_2lane", revMajor="1", revMinor="6")
    side = Side(2, shoulder=False, sidewalk=True, lane_lines=("solid",))
    road = make_road(1, 400.0, side, 60)  # no lane changes near the crossing
    start, end = Fittings(road, side, ids, True, 400.0), Fittings(road, side, ids, False, 400.0)
    start.speed(60, distance=30.0)
    end.speed(60, distance=30.0)
    start.crosswalk("continental", distance=200.0)
    odr.add_road(road)
    odr.adjust_roads_and_lanes()
    return odr, {}


def town_row(ids: Numbering):
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
            f = Fittings(road, small, ids)
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
            lights.append(Fittings(east, main, ids).traffic_light())
            lights.append(Fittings(west, main, ids, at_start=False, length=100.0).traffic_light())
            Fittings(east, main, ids).crosswalk("ladder")
            controls[1] = sorted(lights)
        creators.append(junction(k, arms, {west.id: 2, east.id: 2, north.id: 1, south.id: 1}))
    Fittings(pieces[0], main, ids).speed(30)
    Fittings(pieces[3], main, ids, at_start=False, length=100.0).speed(30)
    for road in pieces:
        odr.add_road(road)
    for creator in creators:
        odr.add_junction_creator(creator)
    odr.adjust_roads_and_lanes()
    return odr, controls


MAPS = [fourway_2lane_lights, fourway_1lane_stop, fourway_3lane_lights, tjunction_2lane_yield, tjunction_1lane_stop,
        motorway_3lane, avenue_2lane, town_row]


def main(out: Path = HERE) -> list[Path]:
    written = []
    for number, build in enumerate(MAPS, start=1):
        odr, controls = build(Numbering(1000 * number))  # each map its own id range
        path = out / f"{build.__name__}.xodr"
        write_atomic(path, finish(odr, controls))
        written.append(path)
    return written


if __name__ == "__main__":
    for p in main(Path(sys.argv[1]) if len(sys.argv) > 1 else HERE):
        print(p)
