"""The road index: what every approach (a road in one driving direction) offers, built once per map.

An approach knows its length, lanes, right edge (shoulder, sidewalk), opposite lanes, the signals and objects
that apply to it, its speed limit, the junction it ends at, the turns that junction allows from it (with the
road each leads to) and the approaches entering the same junction from its left, right and straight ahead.
Indexes are cached as JSON by the map's content hash; a stale or corrupt cache is rebuilt, never trusted.
"""

from __future__ import annotations

import hashlib
import math
import os
import re
from collections import defaultdict
from functools import cached_property
from pathlib import Path
from typing import Literal

from platformdirs import user_cache_dir
from pydantic import BaseModel, ConfigDict, ValidationError

from ttsgc import vocabulary as V
from ttsgc.files import write_atomic
from ttsgc.roads.opendrive import OpenDrive, Road, parsed_map, read_map_bytes

INDEX_VERSION = 6
STRAIGHT_LIMIT_DEG = 45.0  # an exit within this of straight ahead is straight, unless another is straighter
STRAIGHTER_BY_DEG = 5.0
UTURN_DEG = 160.0
Direction = Literal["forward", "backward"]  # forward: the right lanes (ids < 0), driving along s
TurnKind = Literal["left", "right", "straight", "uturn"]


class _Data(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class Turn(_Data):
    direction: TurnKind
    via_road: str  # the connecting road inside the junction
    to_road: str
    to_direction: Direction
    from_lanes: tuple[int, ...]  # lanes of this approach that can take the turn
    via_lanes: tuple[int, ...]  # the connecting road's lanes they enter, in the same order
    heading_change_deg: float  # counter-clockwise positive


class Approach(_Data):
    id: str  # "<road>:fwd" or "<road>:bwd"
    map: str
    road: str
    direction: Direction
    length: float
    run_up: float  # length plus the roads leading into it without a junction between (capped)
    lanes: int  # driving lanes in this direction, minimum over lane sections
    lane_ids: tuple[int, ...]  # driving lanes at the approach's end, innermost first
    opposite_lanes: int
    shoulder: bool
    sidewalk: bool
    signals: tuple[str, ...]  # vocabulary words
    objects: tuple[str, ...]
    crosswalks: tuple[float, ...]  # where crossings are, metres from the approach's start (its end if in the junction)
    speed_limit_kmh: float | None
    junction: str | None  # the junction the approach ends at
    turns: tuple[Turn, ...]
    entering: dict[str, tuple[str, ...]]  # left / right / straight -> approach ids entering the same junction
    end: tuple[float, float, float]  # x, y, heading where it ends (driving direction)

    def turn_kinds(self) -> set[str]:
        return {t.direction for t in self.turns}

    def turns_to(self, kind: str) -> list[Turn]:
        return [t for t in self.turns if t.direction == kind]


class MapIndex(_Data):
    version: int
    name: str
    path: str
    sha256: str
    roads: int
    junctions: int
    approaches: tuple[Approach, ...]

    @cached_property
    def by_id(self) -> dict[str, Approach]:
        return {a.id: a for a in self.approaches}

    @cached_property
    def graph(self) -> "networkx.DiGraph":  # noqa: F821
        """Approaches as nodes; an edge for every turn, labelled with its direction and connecting road.
        networkx is imported here, for route searches, so that no command pays for it at start-up."""
        import networkx as nx

        g = nx.DiGraph()
        for a in self.approaches:
            g.add_node(a.id, approach=a)
        for a in self.approaches:
            for t in a.turns:
                target = approach_id(t.to_road, t.to_direction)
                if target in g:
                    g.add_edge(a.id, target, direction=t.direction, via=t.via_road)
        return g


def approach_id(road: str, direction: str) -> str:
    return f"{road}:{'fwd' if direction == 'forward' else 'bwd'}"


# -- signals and objects as vocabulary words --------------------------------------------------------------

_SPEED_NAME = re.compile(r"sp+e+d_?(?:limit)?_?(\d{1,3})", re.IGNORECASE)


def signal_words(type_code: str, subtype: str, name: str, value: float | None, unit: str | None) -> set[str]:
    """The vocabulary words a signal stands for, from its type code (1000001, 206, 205, 274) or its name."""
    lowered = name.lower()
    words: set[str] = set()
    if type_code == "1000001" or "light" in lowered:
        words.add("traffic_light")
    elif type_code == "206" or lowered in ("sign_stop", "stop_sign", "stop"):
        words.add("stop")
    elif type_code == "205" or "yield" in lowered or "give_way" in lowered:
        words.add("yield")
    elif type_code == "294" or "stopline" in lowered.replace("_", ""):
        words.add("stop_line")
    speed = _speed_of(type_code, subtype, name, value, unit)
    if speed is not None:
        words.add(f"speed_{speed}")
    return words


def _speed_of(type_code, subtype, name, value, unit) -> int | None:
    if type_code == "274":
        if value is not None and value > 0:
            kmh = value * (1.609344 if unit == "mph" else 3.6 if unit == "m/s" else 1.0)
            return int(round(kmh))
        if subtype.isdigit() and 5 <= int(subtype) <= 200:
            return int(subtype)
    match = _SPEED_NAME.search(name)
    if match and V.is_object(f"speed_{int(match.group(1))}"):
        return int(match.group(1))
    return None


def object_words(type_code: str, subtype: str, name: str) -> set[str]:
    """The vocabulary words a road object stands for: crosswalk kinds, lines, stencils, speed signs."""
    text = f"{subtype} {name}".lower().replace("_", "").replace("-", "")
    words: set[str] = set()
    if type_code == "crosswalk" or "crosswalk" in text:
        words.add("crosswalk")
        for kind in ("ladder", "continental", "parallelopen"):
            if kind in text:
                words.add({"parallelopen": "parallel_open_crosswalk"}.get(kind, f"{kind}_crosswalk"))
    if "stopline" in text:
        words.add("stop_line")
    if "stencilstop" in text or "stopsignonroad" in text:
        words.add("stop_sign_on_road")
    if "solidsinglewhite" in text:
        words.add("solid_single_white")
    if "dashedsinglewhite" in text or "brokensinglewhite" in text:
        words.add("dashed_single_white")
    speed = _speed_of("", "", name, None, None)
    if speed is not None:
        words.add(f"speed_{speed}")
    return words


# -- building ---------------------------------------------------------------------------------------------

def build_index(odr: OpenDrive, sha256: str) -> MapIndex:
    roads = odr.roads
    ends: dict[str, str] = {}  # approach id -> junction id it ends at
    for road in roads.values():
        if road.junction != "-1":
            continue
        for direction, link in (("forward", road.successor), ("backward", road.predecessor)):
            if link is not None and link.element_type == "junction":
                ends[approach_id(road.id, direction)] = link.element_id

    skeleton = {}  # approach id -> dict of fields
    for road in roads.values():
        if road.junction != "-1":
            continue
        for direction in ("forward", "backward"):
            lanes = _driving_lane_count(road, direction)
            if lanes == 0:
                continue
            aid = approach_id(road.id, direction)
            sign = -1 if direction == "forward" else 1
            end_s = road.length if direction == "forward" else 0.0
            end_lanes = [l.id for l in road.section_at(end_s if direction == "forward" else 0.0).side(sign)
                         if l.type == "driving"]
            end_pose = road.lane_point(end_s, end_lanes[0]) if end_lanes else road.pose(end_s)
            skeleton[aid] = dict(
                id=aid, map=odr.name, road=road.id, direction=direction, length=round(road.length, 3),
                run_up=round(sum(r.length for r, _ in upstream_chain(odr, road.id, direction)), 3), lanes=lanes,
                lane_ids=tuple(end_lanes), opposite_lanes=_driving_lane_count(road, _other(direction)),
                shoulder=_edge_coverage(road, sign, "shoulder") >= 0.5,
                sidewalk=_edge_coverage(road, sign, "sidewalk") >= 0.5,
                junction=ends.get(aid), end=(round(end_pose.x, 3), round(end_pose.y, 3), round(end_pose.hdg, 6)),
                signals=set(), objects=set(), crosswalks=set(), speed=_lane_speed(road, sign))

    _assign_signals_and_objects(odr, skeleton)
    turns = _turns(odr, skeleton)
    entering = _entering(skeleton)
    approaches = []
    for aid in sorted(skeleton, key=natural_key):
        fields = skeleton[aid]
        signs = sorted(w for w in fields["objects"] | fields["signals"] if w.startswith("speed_"))
        speed_kmh = float(signs[0][6:]) if len(signs) == 1 else (
            round(fields["speed"] * 3.6, 1) if fields["speed"] else None)
        approaches.append(Approach(
            **{k: v for k, v in fields.items() if k not in ("signals", "objects", "crosswalks", "speed")},
            crosswalks=tuple(sorted(fields["crosswalks"])),
            signals=tuple(sorted(fields["signals"] - {"stop_line"} - set(signs))),
            objects=tuple(sorted(fields["objects"] | (fields["signals"] & {"stop_line"}) | set(signs))),
            speed_limit_kmh=speed_kmh, turns=tuple(turns.get(aid, ())), entering=entering.get(aid, {})))
    return MapIndex(version=INDEX_VERSION, name=odr.name, path=odr.path, sha256=sha256, roads=len(roads),
                    junctions=len(odr.junctions), approaches=tuple(approaches))


RUN_UP_LIMIT_M = 300.0


def upstream_chain(odr: OpenDrive, road_id: str, direction: str,
                   limit: float = RUN_UP_LIMIT_M) -> list[tuple[Road, str]]:
    """The approach's road and the roads that lead into it with no junction between, nearest first, as
    (road, driving direction), until `limit` metres or a junction, a dead end or a loop."""
    chain: list[tuple[Road, str]] = []
    seen: set[str] = set()
    total = 0.0
    while road_id in odr.roads and road_id not in seen and total < limit:
        road = odr.roads[road_id]
        if road.junction != "-1" or _driving_lane_count(road, direction) == 0:
            break
        chain.append((road, direction))
        seen.add(road_id)
        total += road.length
        link = road.predecessor if direction == "forward" else road.successor
        if link is None or link.element_type != "road":
            break
        default = "end" if direction == "forward" else "start"
        road_id, direction = link.element_id, ("forward" if (link.contact_point or default) == "end" else "backward")
    return chain


def natural_key(text: str):
    """Sort key that orders '2' before '10'."""
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", text)]


def _other(direction: str) -> str:
    return "backward" if direction == "forward" else "forward"


def _driving_lane_count(road: Road, direction: str) -> int:
    sign = -1 if direction == "forward" else 1
    return min(sum(1 for l in sec.side(sign) if l.type == "driving") for sec in road.sections)


def _edge_coverage(road: Road, sign: int, lane_type: str) -> float:
    """Share of the road's length whose edge on one side has a lane of this type outside the driving lanes."""
    covered = 0.0
    bounds = [sec.s for sec in road.sections] + [road.length]
    for sec, start, stop in zip(road.sections, bounds, bounds[1:]):
        side = sec.side(sign)
        driving = [abs(l.id) for l in side if l.type == "driving"]
        if driving and any(l.type == lane_type and abs(l.id) > max(driving) for l in side):
            covered += max(0.0, stop - start)
    return covered / road.length if road.length > 0 else 0.0


def _lane_speed(road: Road, sign: int) -> float | None:
    speeds = [l.speed_max for sec in road.sections for l in sec.side(sign) if l.type == "driving" and l.speed_max]
    return min(speeds) if speeds else road.speed_max


def _side_of(orientation: str, t: float) -> list[str]:
    """Which driving directions a sign applies to: its orientation, else the side of the road it stands on."""
    if orientation == "+":
        return ["forward"]
    if orientation == "-":
        return ["backward"]
    if t < -0.5:
        return ["forward"]
    if t > 0.5:
        return ["backward"]
    return ["forward", "backward"]


def _assign_signals_and_objects(odr: OpenDrive, skeleton: dict) -> None:
    by_id = {s.id: s for road in odr.roads.values() for s in road.signals if not s.is_reference}
    incoming_of_connecting: dict[str, set[str]] = defaultdict(set)
    ending_at: dict[str, list[str]] = defaultdict(list)
    for aid, fields in skeleton.items():
        if fields["junction"] is not None:
            ending_at[fields["junction"]].append(aid)
    for junction in odr.junctions.values():
        for c in junction.connections:
            for from_lane, _ in c.lane_links:
                incoming_of_connecting[c.connecting_road].add(
                    approach_id(c.incoming_road, "forward" if from_lane < 0 else "backward"))

    for road in odr.roads.values():
        for signal in road.signals:
            source = by_id.get(signal.id, signal) if signal.is_reference else signal
            words = signal_words(source.type, source.subtype, source.name, source.value, source.unit)
            if not words:
                continue
            if road.junction != "-1":  # a signal inside a junction serves the roads entering through it
                targets = incoming_of_connecting.get(road.id, set())
            else:
                targets = {approach_id(road.id, d) for d in _side_of(signal.orientation, signal.t)}
            for aid in targets:
                if aid in skeleton:
                    skeleton[aid]["signals"] |= words
        for obj in road.objects:
            words = object_words(obj.type, obj.subtype, obj.name)
            if not words:
                continue
            if road.junction != "-1":
                targets = set(ending_at.get(road.junction, ()))
            elif "crosswalk" in words:  # a crossing is crossed by both directions
                targets = {approach_id(road.id, "forward"), approach_id(road.id, "backward")}
            else:
                targets = {approach_id(road.id, d) for d in _side_of(obj.orientation, obj.t)}
            for aid in targets:
                if aid in skeleton:
                    fields = skeleton[aid]
                    fields["objects"] |= words
                    if "crosswalk" in words:
                        at = fields["length"] if road.junction != "-1" else (
                            obj.s if fields["direction"] == "forward" else fields["length"] - obj.s)
                        fields["crosswalks"].add(round(min(max(at, 0.0), fields["length"]), 3))

    for junction in odr.junctions.values():
        signals = [by_id[sid] for cid in junction.controllers for sid in odr.controllers.get(cid, ()) if sid in by_id]
        if any("traffic_light" in signal_words(s.type, s.subtype, s.name, s.value, s.unit) for s in signals):
            for aid in ending_at.get(junction.id, ()):
                skeleton[aid]["signals"].add("traffic_light")

    for fields in skeleton.values():  # lane lines between same-direction lanes
        road = odr.roads[fields["road"]]
        if fields["lanes"] < 2:
            continue
        sign = -1 if fields["direction"] == "forward" else 1
        for sec in road.sections:
            inner = [l for l in sec.side(sign) if l.type == "driving"][:-1]
            for lane in inner:
                if lane.road_mark == "broken" and lane.road_mark_color in (None, "white", "standard"):
                    fields["objects"].add("dashed_single_white")
                elif lane.road_mark == "solid" and lane.road_mark_color in (None, "white", "standard"):
                    fields["objects"].add("solid_single_white")


def _turns(odr: OpenDrive, skeleton: dict) -> dict[str, list[Turn]]:
    exits: dict[str, list[dict]] = defaultdict(list)
    for junction in odr.junctions.values():
        for c in junction.connections:
            connecting = odr.roads.get(c.connecting_road)
            incoming = odr.roads.get(c.incoming_road)
            if connecting is None or incoming is None or not c.lane_links:
                continue
            along = c.contact_point != "end"  # the connecting road is driven from its start
            out_link = connecting.successor if along else connecting.predecessor
            if out_link is None or out_link.element_type != "road" or out_link.element_id not in odr.roads:
                continue
            to_direction = "forward" if out_link.contact_point != "end" else "backward"
            entry = connecting.pose(0.0 if along else connecting.length)
            leave = connecting.pose(connecting.length if along else 0.0)
            h_in = entry.hdg if along else entry.hdg + math.pi
            h_out = leave.hdg if along else leave.hdg + math.pi
            change = math.degrees(math.atan2(math.sin(h_out - h_in), math.cos(h_out - h_in)))
            by_side: dict[str, dict[int, int]] = defaultdict(dict)
            end_section = incoming.section_at(incoming.length if along_incoming_end(incoming, junction.id) else 0.0)
            for from_lane, to_lane in c.lane_links:
                lane = end_section.lanes.get(from_lane)
                if lane is None or lane.type != "driving":
                    continue  # shoulders and sidewalks linked through the junction are not turns
                by_side["forward" if from_lane < 0 else "backward"].setdefault(from_lane, to_lane)
            for direction, links in by_side.items():
                aid = approach_id(c.incoming_road, direction)
                if aid not in skeleton:
                    continue
                exits[aid].append(dict(via_road=connecting.id, to_road=out_link.element_id, to_direction=to_direction,
                                       links=links, change=change, uturn=out_link.element_id == c.incoming_road))
    result: dict[str, list[Turn]] = {}
    for aid, options in exits.items():
        merged: dict[tuple, dict] = {}
        for o in options:  # one turn per (connecting road, target); lanes merged
            key = (o["via_road"], o["to_road"], o["to_direction"])
            if key in merged:
                merged[key]["links"] = {**o["links"], **merged[key]["links"]}
            else:
                merged[key] = dict(o)
        options = list(merged.values())
        changes = [o["change"] for o in options if not o["uturn"]]
        turns = []
        for o in options:
            from_lanes = tuple(sorted(o["links"], key=abs))
            turns.append(Turn(direction=_classify_turn(o["change"], o["uturn"], changes), via_road=o["via_road"],
                              to_road=o["to_road"], to_direction=o["to_direction"], from_lanes=from_lanes,
                              via_lanes=tuple(o["links"][lane] for lane in from_lanes),
                              heading_change_deg=round(o["change"], 2)))
        result[aid] = sorted(turns, key=lambda t: (t.direction, natural_key(t.to_road), natural_key(t.via_road)))
    return result


def along_incoming_end(road: Road, junction_id: str) -> bool:
    """Whether a road meets the junction at its end (else at its start)."""
    return road.successor is not None and road.successor.element_type == "junction" and \
        road.successor.element_id == junction_id


def _classify_turn(change: float, uturn: bool, all_changes: list[float]) -> str:
    """Left, right, straight or u-turn from the heading change; 'straight' is the straightest exit only."""
    if uturn or abs(change) >= UTURN_DEG:
        return "uturn"
    if abs(change) < STRAIGHT_LIMIT_DEG:
        straighter = [c for c in all_changes if abs(c) < abs(change) and abs(c - change) > STRAIGHTER_BY_DEG]
        if straighter:
            return "left" if change > min(straighter, key=abs) else "right"
        return "straight"
    return "left" if change > 0 else "right"


def _entering(skeleton: dict) -> dict[str, dict[str, tuple[str, ...]]]:
    """For each approach, the other approaches ending at its junction, by the side they come from."""
    by_junction: dict[str, list[str]] = defaultdict(list)
    for aid, fields in skeleton.items():
        if fields["junction"] is not None:
            by_junction[fields["junction"]].append(aid)
    result = {}
    for aid, fields in skeleton.items():
        if fields["junction"] is None:
            continue
        sides: dict[str, list[str]] = {"left": [], "right": [], "straight": []}
        h = fields["end"][2]
        for other in by_junction[fields["junction"]]:
            if skeleton[other]["road"] == fields["road"]:
                continue
            rel = math.degrees(math.atan2(math.sin(skeleton[other]["end"][2] - h),
                                          math.cos(skeleton[other]["end"][2] - h)))
            if -135 <= rel <= -45:
                sides["left"].append(other)
            elif 45 <= rel <= 135:
                sides["right"].append(other)
            elif abs(rel) > 135:
                sides["straight"].append(other)
        result[aid] = {k: tuple(sorted(v, key=natural_key)) for k, v in sides.items()}
    return result


# -- loading with the cache -------------------------------------------------------------------------------

def cache_dir() -> Path:
    """Where indexes are cached: $TTSGC_CACHE_DIR, else the user cache folder."""
    return Path(os.environ.get("TTSGC_CACHE_DIR") or user_cache_dir("ttsgc")) / "index"


def load_index(path: str | Path, use_cache: bool = True) -> MapIndex:
    """The index of one map, from the cache when a valid entry for this exact content exists."""
    path = Path(path)
    data = read_map_bytes(path)
    sha = hashlib.sha256(data).hexdigest()
    entry = cache_dir() / f"{sha}.v{INDEX_VERSION}.json"
    if use_cache and entry.is_file():
        try:
            index = MapIndex.model_validate_json(entry.read_bytes())
            if index.sha256 == sha and index.version == INDEX_VERSION:
                return index.model_copy(update={"path": str(path)})
        except (ValidationError, ValueError, OSError):
            pass  # corrupt or foreign: rebuilt below
    index = build_index(parsed_map(path, data, sha, use_cache), sha)  # the parsed map is cached too
    index = index.model_copy(update={"path": str(path)})
    if use_cache:
        try:
            entry.parent.mkdir(parents=True, exist_ok=True)
            write_atomic(entry, index.model_dump_json())
        except OSError:
            pass  # a read-only cache only costs speed
    return index
