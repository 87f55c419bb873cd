"""OpenDRIVE (.xodr) -> roads: reference-line geometry, lane sections, links, signals, objects, junctions.

Parsing is safe by construction: no DTD, no entities, no network, a size limit. Unknown elements and vendor
extensions are ignored. The geometry of every planView primitive (line, arc, spiral, poly3, paramPoly3) is
evaluated, so headings and lane positions come from the file alone, for any map.
"""

from __future__ import annotations

import bisect
import hashlib
import math
import pickle
from dataclasses import dataclass, field, replace
from functools import cache, cached_property
from pathlib import Path

from lxml import etree

from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.numbers import MAX_MAGNITUDE, NumberError, parse_float, parse_int

MAX_MAP_BYTES = 256 << 20
# Geometry is evaluated by sampling (the index, placement, the simulation's checks every 0.5 m), so its size is
# bounded where it is read: any real road is far shorter, and a map past these is refused, not sampled for minutes.
MAX_ROAD_LENGTH_M = 100_000.0
MAX_MAP_ROAD_LENGTH_M = 2_000_000.0  # all roads of one map together (CARLA's Town04: 11 km)
MAX_COORDINATE_M = 1e7
MAX_LANES_A_SIDE = 100
MAX_SPIRAL_STEPS = 64  # Simpson steps per clothoid evaluation: one every 0.5 m up to 32 m, then fixed


class MapError(TtsgcError):
    """An OpenDRIVE file that cannot be read, is malformed, or is refused as hostile."""

    exit_code = ExitCode.MAP_ERROR


# -- geometry ---------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Pose:
    x: float
    y: float
    hdg: float


@dataclass(frozen=True)
class Geometry:
    s: float
    x: float
    y: float
    hdg: float
    length: float
    kind: str  # line | arc | spiral | poly3 | paramPoly3
    params: tuple[float, ...] = ()
    normalized: bool = True  # paramPoly3: pRange normalized (p in 0..1) or arcLength (p in 0..length)

    def at(self, ds: float) -> Pose:
        """The pose ds metres along this primitive."""
        ds = min(max(ds, 0.0), self.length)
        if self.kind == "line":
            return Pose(self.x + ds * math.cos(self.hdg), self.y + ds * math.sin(self.hdg), self.hdg)
        if self.kind == "arc":
            k = self.params[0]
            if abs(k) < 1e-12:
                return Geometry(self.s, self.x, self.y, self.hdg, self.length, "line").at(ds)
            h = self.hdg + k * ds
            return Pose(self.x + (math.sin(h) - math.sin(self.hdg)) / k,
                        self.y - (math.cos(h) - math.cos(self.hdg)) / k, h)
        if self.kind == "spiral":
            return self._spiral(ds)
        return self._polynomial(ds)

    def _spiral(self, ds: float) -> Pose:
        """Clothoid: curvature linear in s; position by Simpson integration of the heading."""
        k0, k1 = self.params
        rate = (k1 - k0) / self.length if self.length > 0 else 0.0
        heading = lambda u: self.hdg + k0 * u + 0.5 * rate * u * u  # noqa: E731
        steps = min(MAX_SPIRAL_STEPS, max(8, 2 * math.ceil(ds / 0.5)))
        h = ds / steps
        sx = sy = 0.0
        for i in range(steps + 1):
            w = 1 if i in (0, steps) else (4 if i % 2 else 2)
            a = heading(i * h)
            sx += w * math.cos(a)
            sy += w * math.sin(a)
        return Pose(self.x + sx * h / 3, self.y + sy * h / 3, heading(ds))

    def _polynomial(self, ds: float) -> Pose:
        """poly3 and paramPoly3 in the local (u, v) frame; arc length mapped to the parameter by sampling."""
        p = self._parameter_at(ds)
        u, v, du, dv = self._uv(p)
        c, s = math.cos(self.hdg), math.sin(self.hdg)
        return Pose(self.x + u * c - v * s, self.y + u * s + v * c, self.hdg + math.atan2(dv, du))

    def _uv(self, p: float) -> tuple[float, float, float, float]:
        if self.kind == "poly3":
            a, b, c, d = self.params
            return p, a + b * p + c * p * p + d * p ** 3, 1.0, b + 2 * c * p + 3 * d * p * p
        au, bu, cu, du, av, bv, cv, dv = self.params
        return (au + bu * p + cu * p * p + du * p ** 3, av + bv * p + cv * p * p + dv * p ** 3,
                bu + 2 * cu * p + 3 * du * p * p, bv + 2 * cv * p + 3 * dv * p * p)

    def _parameter_at(self, ds: float) -> float:
        table = self._arc_table
        lengths = [t[0] for t in table]
        i = bisect.bisect_left(lengths, ds)
        if i <= 0:
            return table[0][1]
        if i >= len(table):
            return table[-1][1]
        (l0, p0), (l1, p1) = table[i - 1], table[i]
        return p0 + (p1 - p0) * ((ds - l0) / (l1 - l0) if l1 > l0 else 0.0)

    @cached_property
    def _arc_table(self) -> list[tuple[float, float]]:
        end = self._parameter_end()
        n = 64
        table, total = [(0.0, 0.0)], 0.0
        prev = self._uv(0.0)
        for i in range(1, n + 1):
            p = end * i / n
            cur = self._uv(p)
            total += math.hypot(cur[0] - prev[0], cur[1] - prev[1])
            table.append((total, p))
            prev = cur
        if total > 0:  # scale so that the table's end is the declared length
            table = [(l * self.length / total, p) for l, p in table]
        return table

    def _parameter_end(self) -> float:
        if self.kind == "paramPoly3":
            return 1.0 if self.normalized else self.length
        # poly3: u runs until the curve's arc length reaches the declared length; u <= length always
        lo, hi = 0.0, self.length
        for _ in range(40):
            mid = (lo + hi) / 2
            if _poly_length(self.params, mid) < self.length:
                lo = mid
            else:
                hi = mid
        return hi


def _poly_length(params: tuple[float, ...], u_end: float, n: int = 64) -> float:
    a, b, c, d = params
    total, prev = 0.0, (0.0, a)
    for i in range(1, n + 1):
        u = u_end * i / n
        cur = (u, a + b * u + c * u * u + d * u ** 3)
        total += math.hypot(cur[0] - prev[0], cur[1] - prev[1])
        prev = cur
    return total


@dataclass(frozen=True)
class Cubic:
    """a + b ds + c ds^2 + d ds^3, valid from s_offset on (lane widths, lane offsets, elevation)."""

    s_offset: float
    a: float
    b: float = 0.0
    c: float = 0.0
    d: float = 0.0

    def value(self, s: float) -> float:
        ds = s - self.s_offset
        return self.a + self.b * ds + self.c * ds * ds + self.d * ds ** 3


def _piecewise(records: list[Cubic], s: float) -> float:
    if not records:
        return 0.0
    offsets = [r.s_offset for r in records]
    i = max(0, bisect.bisect_right(offsets, s + 1e-9) - 1)
    return records[i].value(s)


# -- roads ------------------------------------------------------------------------------------------------

@dataclass
class Lane:
    id: int
    type: str
    widths: list[Cubic]  # s_offset relative to the lane section start
    road_mark: str | None = None  # type of the lane's outer road mark: solid, broken, ...
    road_mark_color: str | None = None
    speed_max: float | None = None  # m/s

    def width(self, ds: float) -> float:
        return max(0.0, _piecewise(self.widths, ds))


@dataclass
class LaneSection:
    s: float
    lanes: dict[int, Lane]  # lane id -> lane, centre lane 0 excluded
    center_mark: str | None = None  # type of the centre lane's road mark (the line between the two directions)
    center_mark_color: str | None = None

    def side(self, sign: int) -> list[Lane]:
        """Lanes of one side ordered from the centre outwards (sign -1: right, +1: left)."""
        return sorted((l for l in self.lanes.values() if (l.id > 0) == (sign > 0)), key=lambda l: abs(l.id))


@dataclass
class Link:
    element_type: str  # road | junction
    element_id: str
    contact_point: str | None = None  # start | end (roads only)


@dataclass
class Signal:
    id: str
    s: float
    t: float
    orientation: str  # + | - | none
    type: str
    subtype: str
    name: str
    value: float | None
    unit: str | None
    country: str
    is_reference: bool = False


@dataclass
class RoadObject:
    id: str
    s: float
    t: float
    orientation: str
    type: str
    subtype: str
    name: str
    hdg: float = 0.0  # relative to the road's heading at s
    length: float = 0.0  # extent along the object's own heading (u)
    width: float = 0.0  # extent across it (v)
    outline: tuple[tuple[float, float], ...] = ()  # cornerLocal (u, v) points, where the map gives them


@dataclass
class Road:
    id: str
    name: str
    length: float
    junction: str  # "-1" when the road is not inside a junction
    geometry: list[Geometry]
    lane_offsets: list[Cubic]
    sections: list[LaneSection]
    predecessor: Link | None = None
    successor: Link | None = None
    signals: list[Signal] = field(default_factory=list)
    objects: list[RoadObject] = field(default_factory=list)
    speed_max: float | None = None  # m/s, from <type><speed>
    line: int = 0

    def pose(self, s: float) -> Pose:
        """The reference line's pose at s."""
        s = min(max(s, 0.0), self.length)
        starts = [g.s for g in self.geometry]
        i = max(0, bisect.bisect_right(starts, s + 1e-9) - 1)
        g = self.geometry[i]
        return g.at(s - g.s)

    def lane_offset(self, s: float) -> float:
        """Lateral offset of the centre lane (the line between the two directions) from the reference line."""
        return _piecewise(self.lane_offsets, s)

    def section_at(self, s: float) -> LaneSection:
        starts = [sec.s for sec in self.sections]
        return self.sections[max(0, bisect.bisect_right(starts, s + 1e-9) - 1)]

    def lane_t(self, s: float, lane_id: int, fraction: float = 0.5) -> float:
        """Lateral offset of a point across a lane (fraction 0 at its inner edge, 1 at its outer edge)."""
        section = self.section_at(s)
        ds = s - section.s
        sign = 1 if lane_id > 0 else -1
        t = _piecewise(self.lane_offsets, s)
        for lane in section.side(sign):
            w = lane.width(ds)
            if lane.id == lane_id:
                return t + sign * w * fraction
            t += sign * w
        raise KeyError(f"road {self.id} has no lane {lane_id} at s={s:.1f}")

    def lane_point(self, s: float, lane_id: int, fraction: float = 0.5) -> Pose:
        """World pose of a point in a lane, heading along the lane's driving direction."""
        ref = self.pose(s)
        t = self.lane_t(s, lane_id, fraction)
        hdg = ref.hdg if lane_id < 0 else ref.hdg + math.pi
        return Pose(ref.x - t * math.sin(ref.hdg), ref.y + t * math.cos(ref.hdg), _wrap(hdg))


@dataclass
class Connection:
    id: str
    incoming_road: str
    connecting_road: str
    contact_point: str  # where the connecting road touches the incoming road: start | end
    lane_links: list[tuple[int, int]]  # (from lane on the incoming road, to lane on the connecting road)


@dataclass
class Junction:
    id: str
    name: str
    connections: list[Connection]
    controllers: list[str]


@dataclass
class OpenDrive:
    path: str
    name: str
    roads: dict[str, Road]
    junctions: dict[str, Junction]
    controllers: dict[str, list[str]]  # controller id -> signal ids


def _wrap(angle: float) -> float:
    return math.atan2(math.sin(angle), math.cos(angle))


_CACHED_CLASSES = {c.__name__: c for c in (Pose, Geometry, Cubic, Lane, LaneSection, Link, Signal, RoadObject, Road,
                                            Connection, Junction, OpenDrive)}


# -- reading ----------------------------------------------------------------------------------------------

def read_map_bytes(path: str | Path) -> bytes:
    """A map file's bytes, refusing one over the size limit before reading it."""
    path = Path(path)
    try:
        size = path.stat().st_size
        if size > MAX_MAP_BYTES:
            raise MapError(f"{path}: the map is {size} bytes; the limit is {MAX_MAP_BYTES}")
        return path.read_bytes()
    except OSError as exc:
        raise MapError(f"{path}: cannot read the map: {exc.strerror or exc}") from None


_PARSED: dict[str, OpenDrive] = {}  # by content hash, the most recent last
PARSED_KEPT = 8


def load_opendrive(path: str | Path, use_cache: bool = True, sha256: str | None = None) -> OpenDrive:
    """read_opendrive, remembered by content: binding, retries and simulation of one scene read the same map
    several times, and a CARLA town takes about 0.15 s to parse. The parsed map is also kept beside the road
    index's cache entries for later processes, where it loads several times faster than it parses.
    sha256: the content hash the caller's road index was built from, so that the map the index describes is
    found without reading and hashing the file again (a large map takes tens of milliseconds)."""
    path = Path(path)
    odr = _remembered(sha256, use_cache) if sha256 is not None else None
    if odr is not None:
        return replace(odr, path=str(path))
    data = read_map_bytes(path)
    return parsed_map(path, data, hashlib.sha256(data).hexdigest(), use_cache)


def parsed_map(path: Path, data: bytes, sha: str, use_cache: bool = True) -> OpenDrive:
    """load_opendrive for a caller that has already read and hashed the file."""
    odr = _remembered(sha, use_cache)
    if odr is None:
        odr = read_opendrive(path, data)
        _keep(sha, odr)
        if use_cache:
            _write_parsed(_parsed_entry(sha), sha, odr)
    return replace(odr, path=str(path))


def _remembered(sha: str, use_cache: bool) -> OpenDrive | None:
    """The parse of this content from this process's memory, else from the cache; None when neither has it."""
    odr = _PARSED.pop(sha, None)
    if odr is None and use_cache:
        odr = _read_parsed(_parsed_entry(sha), sha)
    if odr is not None:
        _keep(sha, odr)
    return odr


def _keep(sha: str, odr: OpenDrive) -> None:
    _PARSED[sha] = odr
    while len(_PARSED) > PARSED_KEPT:
        del _PARSED[next(iter(_PARSED))]


@cache
def _reader_fingerprint() -> str:
    """Any change to this module (the reader or the classes) makes the cached parsed maps someone else's."""
    try:
        return hashlib.sha256(Path(__file__).read_bytes()).hexdigest()[:12]
    except OSError:  # installed where the source cannot be read: the package version stands for it
        from ttsgc import __version__

        return f"v{__version__}"


def _parsed_entry(sha: str) -> Path:
    from ttsgc.roads.index import cache_dir  # the index's cache folder; imported here, index imports this module

    return cache_dir() / f"{sha}.parsed-{_reader_fingerprint()}.pickle"


class _MapUnpickler(pickle.Unpickler):
    """Builds only this module's map classes (and the tuples, lists and dicts they hold): a cache entry
    written by anyone else cannot run foreign code, it can only fail to load, and is then rebuilt."""

    def find_class(self, module: str, name: str):
        if module == __name__ and name in _CACHED_CLASSES:
            return _CACHED_CLASSES[name]
        raise pickle.UnpicklingError(f"{module}.{name} is not part of a parsed map")


def _read_parsed(entry: Path, sha: str) -> OpenDrive | None:
    try:
        with entry.open("rb") as f:
            stored_sha, odr = _MapUnpickler(f).load()
    except Exception:  # noqa: BLE001 - absent, corrupt, truncated or foreign: parsed again and rewritten
        # (pickle raises many kinds of error on damaged input; none of them may stop a compile)
        return None
    return odr if stored_sha == sha and isinstance(odr, OpenDrive) else None


def _write_parsed(entry: Path, sha: str, odr: OpenDrive) -> None:
    from ttsgc.files import write_atomic

    try:
        entry.parent.mkdir(parents=True, exist_ok=True)
        write_atomic(entry, pickle.dumps((sha, odr), protocol=pickle.HIGHEST_PROTOCOL))
    except OSError:
        pass  # a read-only cache only costs speed


def read_opendrive(path: str | Path, data: bytes | None = None) -> OpenDrive:
    """Parse an OpenDRIVE file safely; MapError names the file, the line and what is wrong."""
    path = Path(path)
    if data is None:
        data = read_map_bytes(path)
    elif len(data) > MAX_MAP_BYTES:
        raise MapError(f"{path}: the map is {len(data)} bytes; the limit is {MAX_MAP_BYTES}")
    prolog = data[: data.find(b"<OpenDRIVE")] if b"<OpenDRIVE" in data[:65536] else data[:65536]
    if b"<!DOCTYPE" in prolog or b"<!ENTITY" in prolog:
        raise MapError(f"{path}:1: refused: the file declares a DOCTYPE or entities, which OpenDRIVE never needs "
                       f"(entity expansion and external entities are a known attack)")
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, dtd_validation=False,
                             huge_tree=False, remove_comments=True, remove_pis=True)
    try:
        root = etree.fromstring(data, parser)
    except etree.XMLSyntaxError as exc:
        line = exc.position[0] if exc.position else exc.lineno
        raise MapError(f"{path}:{line}: not well-formed XML: {exc.msg}") from None
    if root.getroottree().docinfo.doctype:  # a DOCTYPE the prolog scan missed (e.g. in another encoding)
        raise MapError(f"{path}:1: refused: the file declares a DOCTYPE, which OpenDRIVE never needs")
    if _local(root.tag) != "OpenDRIVE":
        raise MapError(f"{path}:{root.sourceline}: the root element is <{_local(root.tag)}>, not <OpenDRIVE>")
    reader = _Reader(path)
    return reader.read(root)


def _local(tag) -> str:
    return etree.QName(tag).localname if isinstance(tag, str) else ""


class _Reader:
    def __init__(self, path: Path):
        self.path = path

    def fail(self, element, message: str):
        raise MapError(f"{self.path}:{element.sourceline}: <{_local(element.tag)}>: {message}")

    def num(self, element, name: str, default: float | None = None, low: float = -MAX_MAGNITUDE,
            high: float = MAX_MAGNITUDE) -> float:
        raw = element.get(name)
        if raw is None:
            if default is None:
                self.fail(element, f"missing attribute '{name}'")
            return default
        try:
            return parse_float(raw, low, high)
        except NumberError as exc:
            self.fail(element, f"attribute {name}={exc}")

    def length(self, element, name: str, default: float | None = None) -> float:
        """A length or an s along a road: 0..MAX_ROAD_LENGTH_M."""
        return self.num(element, name, default, 0.0, MAX_ROAD_LENGTH_M)

    def lane_id(self, element, name: str) -> int:
        try:
            return parse_int(element.get(name, ""), -MAX_LANES_A_SIDE, MAX_LANES_A_SIDE)
        except NumberError as exc:
            self.fail(element, f"lane {name}={exc}")

    def coordinate(self, element, name: str) -> float:
        return self.num(element, name, None, -MAX_COORDINATE_M, MAX_COORDINATE_M)

    def children(self, element, name: str):
        return [c for c in element if _local(c.tag) == name]

    def child(self, element, name: str):
        found = self.children(element, name)
        return found[0] if found else None

    def read(self, root) -> OpenDrive:
        header = self.child(root, "header")
        name = (header.get("name") if header is not None else None) or self.path.stem
        controllers = {}
        for ctrl in self.children(root, "controller"):
            controllers[ctrl.get("id", "")] = [c.get("signalId", "") for c in self.children(ctrl, "control")]
        roads = {}
        for element in self.children(root, "road"):
            road = self.road(element)
            if road.id in roads:
                self.fail(element, f"road id {road.id!r} is used twice")
            roads[road.id] = road
        if not roads:
            raise MapError(f"{self.path}:{root.sourceline}: the map has no <road>")
        total = sum(road.length for road in roads.values())
        if total > MAX_MAP_ROAD_LENGTH_M:
            raise MapError(f"{self.path}: refused: its roads are {total:.0f} m long in all; the limit is "
                           f"{MAX_MAP_ROAD_LENGTH_M:.0f} m")
        junctions = {}
        for element in self.children(root, "junction"):
            junction = self.junction(element)
            junctions[junction.id] = junction
        return OpenDrive(str(self.path), name, roads, junctions, controllers)

    def road(self, element) -> Road:
        rid = element.get("id")
        if rid is None:
            self.fail(element, "missing attribute 'id'")
        length = self.length(element, "length")
        plan = self.child(element, "planView")
        if plan is None:
            self.fail(element, f"road {rid} has no <planView>")
        geometry = [self.geometry(g) for g in self.children(plan, "geometry")]
        if not geometry:
            self.fail(plan, f"road {rid} has no <geometry>")
        geometry.sort(key=lambda g: g.s)
        lanes = self.child(element, "lanes")
        if lanes is None:
            self.fail(element, f"road {rid} has no <lanes>")
        offsets = sorted((self.cubic(o, "s") for o in self.children(lanes, "laneOffset")), key=lambda c: c.s_offset)
        sections = sorted((self.section(sec) for sec in self.children(lanes, "laneSection")), key=lambda x: x.s)
        if not sections:
            self.fail(lanes, f"road {rid} has no <laneSection>")
        link = self.child(element, "link")
        predecessor = successor = None
        if link is not None:
            predecessor = self.link(self.child(link, "predecessor"))
            successor = self.link(self.child(link, "successor"))
        speed = None
        for road_type in self.children(element, "type"):
            speed_el = self.child(road_type, "speed")
            if speed_el is not None and speed_el.get("max") not in (None, "no limit", "undefined"):
                speed = _to_mps(self.num(speed_el, "max"), speed_el.get("unit", "m/s"))
        road = Road(rid, element.get("name", ""), length, element.get("junction", "-1"), geometry, offsets, sections,
                    predecessor, successor, speed_max=speed, line=element.sourceline or 0)
        signals = self.child(element, "signals")
        if signals is not None:
            road.signals = [self.signal(s) for s in self.children(signals, "signal")]
            road.signals += [self.signal_reference(s) for s in self.children(signals, "signalReference")]
        objects = self.child(element, "objects")
        if objects is not None:
            road.objects = [self.road_object(o) for o in self.children(objects, "object")]
        return road

    def geometry(self, g) -> Geometry:
        base = (self.length(g, "s"), self.coordinate(g, "x"), self.coordinate(g, "y"), self.num(g, "hdg"),
                self.length(g, "length"))
        for shape in g:
            kind = _local(shape.tag)
            if kind == "line":
                return Geometry(*base, "line")
            if kind == "arc":
                return Geometry(*base, "arc", (self.num(shape, "curvature"),))
            if kind == "spiral":
                return Geometry(*base, "spiral", (self.num(shape, "curvStart"), self.num(shape, "curvEnd")))
            if kind == "poly3":
                return Geometry(*base, "poly3", tuple(self.num(shape, k) for k in "abcd"))
            if kind == "paramPoly3":
                params = tuple(self.num(shape, k + axis) for axis in "UV" for k in "abcd")
                return Geometry(*base, "paramPoly3", params, shape.get("pRange", "normalized") != "arcLength")
        self.fail(g, "has no line, arc, spiral, poly3 or paramPoly3")

    def cubic(self, element, s_name: str) -> Cubic:
        return Cubic(self.length(element, s_name), self.num(element, "a", 0.0), self.num(element, "b", 0.0),
                     self.num(element, "c", 0.0), self.num(element, "d", 0.0))

    def section(self, element) -> LaneSection:
        lanes: dict[int, Lane] = {}
        for side in ("left", "right"):
            holder = self.child(element, side)
            if holder is None:
                continue
            for lane_el in self.children(holder, "lane"):
                lane_id = self.lane_id(lane_el, "id")
                if (side == "left") != (lane_id > 0) or lane_id == 0:
                    self.fail(lane_el, f"lane id {lane_id} does not belong on the {side} side")
                widths = sorted((self.cubic(w, "sOffset") for w in self.children(lane_el, "width")),
                                key=lambda c: c.s_offset)
                mark = self.child(lane_el, "roadMark")
                speed_el = self.child(lane_el, "speed")
                speed = _to_mps(self.num(speed_el, "max"), speed_el.get("unit", "m/s")) if speed_el is not None else None
                lanes[lane_id] = Lane(lane_id, lane_el.get("type", "none"), widths,
                                      mark.get("type") if mark is not None else None,
                                      mark.get("color") if mark is not None else None, speed)
        center = self.child(element, "center")
        center_lane = self.child(center, "lane") if center is not None else None
        mark = self.child(center_lane, "roadMark") if center_lane is not None else None
        return LaneSection(self.length(element, "s"), lanes, mark.get("type") if mark is not None else None,
                           mark.get("color") if mark is not None else None)

    def link(self, element) -> Link | None:
        if element is None:
            return None
        kind, target = element.get("elementType"), element.get("elementId")
        if kind not in ("road", "junction") or target is None:
            return None
        return Link(kind, target, element.get("contactPoint"))

    def signal(self, element) -> Signal:
        raw_value = element.get("value")
        try:
            value = parse_float(raw_value) if raw_value not in (None, "") else None
        except NumberError:
            value = None  # a sign's value is optional; one that is not a number says nothing
        return Signal(element.get("id", ""), self.num(element, "s", 0.0), self.num(element, "t", 0.0),
                      element.get("orientation", "none"), element.get("type", ""), element.get("subtype", ""),
                      element.get("name", ""), value, element.get("unit"), element.get("country", ""))

    def signal_reference(self, element) -> Signal:
        return Signal(element.get("id", ""), self.num(element, "s", 0.0), self.num(element, "t", 0.0),
                      element.get("orientation", "none"), "", "", "", None, None, "", is_reference=True)

    def road_object(self, element) -> RoadObject:
        outline = self.child(element, "outline")
        corners = tuple((self.num(c, "u"), self.num(c, "v")) for c in self.children(outline, "cornerLocal")) \
            if outline is not None else ()
        return RoadObject(element.get("id", ""), self.num(element, "s", 0.0), self.num(element, "t", 0.0),
                          element.get("orientation", "none"), element.get("type", ""), element.get("subtype", ""),
                          element.get("name", ""), self.num(element, "hdg", 0.0), self.num(element, "length", 0.0),
                          self.num(element, "width", 0.0), corners)

    def junction(self, element) -> Junction:
        connections = []
        for c in self.children(element, "connection"):
            links = []
            for ll in self.children(c, "laneLink"):
                links.append((self.lane_id(ll, "from"), self.lane_id(ll, "to")))
            connections.append(Connection(c.get("id", ""), c.get("incomingRoad", ""), c.get("connectingRoad", ""),
                                          c.get("contactPoint", "start"), links))
        controllers = [c.get("id", "") for c in self.children(element, "controller")]
        return Junction(element.get("id", ""), element.get("name", ""), connections, controllers)


def _to_mps(value: float, unit: str) -> float:
    return value * {"km/h": 1 / 3.6, "mph": 0.44704, "m/s": 1.0}.get(unit or "m/s", 1.0)
