"""Bird's-eye pictures and animations of a played scene: the map around it, every body's box and path.

Drawn only from what every player hands over (a Trace), the parsed map, and the judge's verdicts, so a
picture shows what was played, by any player. matplotlib (Agg) draws; Pillow writes PNG and GIF with no
metadata, imageio-ffmpeg writes MP4; fonts, sizes and resolution are fixed, so the same input gives the
same bytes. matplotlib is imported here only, and this module only by the commands that draw.
"""

from __future__ import annotations

import bisect
import io
import math
import textwrap
from dataclasses import dataclass, field
from pathlib import Path

from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.files import real_path
from ttsgc.roads.opendrive import OpenDrive, Road
from ttsgc.simulate.trace import Sample, Trace

WIDTH_PX, HEIGHT_PX, DPI = 1200, 900, 100
MAP_PX = HEIGHT_PX  # the map is a square on the left; the legend panel takes the rest
MARGIN_M = 18.0  # free map around the bodies' paths
MIN_VIEW_M = 70.0
FRAME_STEP_S = 0.2  # scene time between animation frames (played at FPS: twice real time)
FPS = 10
MAX_FRAMES = 300
FORMATS = (".png", ".gif", ".mp4")

TYPE_COLOURS = {  # fill of each agent type; the ego has its own
    "car": "#3b6fd8", "truck": "#8c564b", "bus": "#f08a24", "motorcycle": "#9b4dca", "cyclist": "#14a3a3",
    "pedestrian": "#2ca02c", "ambulance": "#f4f4f4", "police": "#1d2f6f", "firetruck": "#b0171f",
}
EGO_COLOUR = "#ffd21f"
OTHER_COLOUR = "#7f7f7f"
COLLISION_COLOUR = "#ff1a1a"

SURFACE = {  # lane type -> fill
    "driving": "#4a4a4d", "entry": "#4a4a4d", "exit": "#4a4a4d", "onRamp": "#4a4a4d", "offRamp": "#4a4a4d",
    "connectingRamp": "#4a4a4d", "bidirectional": "#4a4a4d", "stop": "#4a4a4d", "special1": "#4a4a4d",
    "shoulder": "#85857e", "parking": "#5e5e64", "biking": "#8a5050", "sidewalk": "#cfc6b4", "walking": "#cfc6b4",
    "curb": "#b8b0a0", "border": "#9a9a90", "median": "#7d9a6b", "restricted": "#a0928a",
}
JUNCTION_SURFACE = "#5a5a60"
GROUND = "#dfe8d3"
SIGNAL_STYLE = {  # matplotlib marker styles of the signals drawn on the map
    "light": dict(marker="s", markersize=9, color="#111111"),
    "stop": dict(marker="8", markersize=12, color="#c8102e", markeredgecolor="white", markeredgewidth=1.5),
    "yield": dict(marker="v", markersize=11, color="white", markeredgecolor="#c8102e", markeredgewidth=2),
    "speed": dict(marker="o", markersize=13, color="white", markeredgecolor="#c8102e", markeredgewidth=2),
    "other": dict(marker="o", markersize=5, color="#555555"),
}
SIGNAL_WORDS = {"light": "traffic light", "stop": "stop sign", "yield": "yield sign", "speed": "speed limit",
                "other": "other signal"}
MARK_COLOURS = {"yellow": "#f2c230", "white": "#f5f5f5", "standard": "#f5f5f5", "red": "#d03030", "blue": "#3050d0"}


class RenderError(TtsgcError):
    """A bad output name, or a trace with nothing to draw (exit 2, like a bad command line)."""

    exit_code = ExitCode.INVALID_SCENARIO


# -- plain data the picture is made from -------------------------------------------------------------------

@dataclass(frozen=True)
class Cast:
    """Who is who: read from the scene file, never from a player."""

    title: str
    types: dict[str, str]  # entity name -> agent type (car, pedestrian, ...)
    ego: str | None
    stages: tuple[str, ...] = ()  # storyboard acts in order: their start times mark stage changes


@dataclass(frozen=True)
class CollisionMark:
    a: str
    b: str
    time_s: float
    x: float
    y: float
    asked_for: bool = False


@dataclass(frozen=True)
class Verdict:
    """What the judge said, in the words the legend prints."""

    ok: bool | None  # None: not judged
    player: str
    failures: tuple[str, ...] = ()  # "name: reason" of each agent that did not do its action
    collisions: tuple[CollisionMark, ...] = ()
    map_name: str = ""


def verdict_from_report(report, player: str) -> Verdict:
    """The judge's report (any object with ok, agents, collisions, map) as a Verdict."""
    failures = tuple(f"{a.name}: {a.reason}" for a in getattr(report, "agents", []) if not a.achieved)
    collisions = tuple(CollisionMark(c.a, c.b, float(c.time_s), float(c.x), float(c.y), bool(c.asked_for))
                       for c in getattr(report, "collisions", []))
    return Verdict(getattr(report, "ok", None), player, failures, collisions, Path(getattr(report, "map", "")).stem)


@dataclass(frozen=True)
class View:
    """The square of the world the map shows, and where it lands in the picture (pixels from the top left)."""

    x0: float
    y0: float
    size: float

    def pixel(self, x: float, y: float) -> tuple[int, int]:
        col = (x - self.x0) / self.size * MAP_PX
        row = (1.0 - (y - self.y0) / self.size) * MAP_PX
        return int(col), int(row)


def view_of(trace: Trace) -> View:
    xs = [s.x for samples in trace.samples.values() for s in samples]
    ys = [s.y for samples in trace.samples.values() for s in samples]
    if not xs:
        raise RenderError("the trace has no samples: nothing was played, so there is nothing to draw")
    size = max(max(xs) - min(xs), max(ys) - min(ys)) + 2 * MARGIN_M
    size = max(size, MIN_VIEW_M)
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    return View(round(cx - size / 2, 3), round(cy - size / 2, 3), round(size, 3))


# -- the map as shapes -------------------------------------------------------------------------------------

@dataclass
class MapShapes:
    surfaces: list[tuple[str, list[tuple[float, float]]]] = field(default_factory=list)  # (fill, polygon)
    marks: list[tuple[str, str, float, list[tuple[float, float]]]] = field(default_factory=list)  # colour, style, width
    stripes: list[list[tuple[float, float]]] = field(default_factory=list)  # crosswalk bars and stop lines
    signals: list[tuple[str, float, float, str]] = field(default_factory=list)  # kind, x, y, text


def _normal_point(road: Road, s: float, t: float) -> tuple[float, float]:
    ref = road.pose(s)
    return ref.x - t * math.sin(ref.hdg), ref.y + t * math.cos(ref.hdg)


def _near(road: Road, view: View, reach: float = 40.0) -> bool:
    n = max(2, int(road.length / 10.0) + 1)
    for i in range(n + 1):
        p = road.pose(road.length * i / n)
        if view.x0 - reach <= p.x <= view.x0 + view.size + reach and view.y0 - reach <= p.y <= view.y0 + view.size + reach:
            return True
    return False


def _stations(start: float, end: float, step: float = 1.0) -> list[float]:
    n = max(1, math.ceil((end - start) / step))
    return [start + (end - start) * i / n for i in range(n + 1)]


def map_shapes(odr: OpenDrive, view: View) -> MapShapes:
    """Lanes, marks, crossings, stop lines and signals of the roads near the view, in world coordinates."""
    shapes = MapShapes()
    junction_surfaces, road_surfaces = [], []
    for road_id in sorted(odr.roads, key=_road_order):
        road = odr.roads[road_id]
        if road.length <= 0 or not _near(road, view):
            continue
        in_junction = road.junction != "-1"
        ends = [sec.s for sec in road.sections[1:]] + [road.length]
        for section, end in zip(road.sections, ends):
            if end - section.s <= 1e-6:
                continue
            stations = _stations(section.s, end, 1.0 if road.length < 400 else 2.0)
            for sign in (-1, 1):
                inner = [_offset(road, s) for s in stations]
                for lane in section.side(sign):
                    widths = [lane.width(s - section.s) for s in stations]
                    outer = [t + sign * w for t, w in zip(inner, widths)]
                    if max(widths) > 0.05 and lane.type != "none":
                        polygon = [_normal_point(road, s, t) for s, t in zip(stations, inner)] + \
                            [_normal_point(road, s, t) for s, t in zip(reversed(stations), reversed(outer))]
                        drivable = SURFACE.get(lane.type) == SURFACE["driving"]
                        fill = JUNCTION_SURFACE if in_junction and drivable else SURFACE.get(lane.type, "#8f8f8f")
                        (junction_surfaces if in_junction else road_surfaces).append((fill, polygon))
                    if not in_junction and lane.road_mark not in (None, "none", "curb") and max(widths) > 0.05:
                        line = [_normal_point(road, s, t) for s, t in zip(stations, outer)]
                        shapes.marks.append(_mark(lane.road_mark, lane.road_mark_color, line))
                    inner = outer
            if not in_junction and section.center_mark not in (None, "none") and \
                    section.side(-1) and section.side(1):
                line = [_normal_point(road, s, _offset(road, s)) for s in stations]
                shapes.marks.append(_mark(section.center_mark, section.center_mark_color, line))
        for obj in road.objects:
            _object_shapes(road, obj, shapes)
        for signal in road.signals:
            if signal.is_reference:
                continue
            x, y = _normal_point(road, signal.s, signal.t)
            kind, text = _signal_kind(signal)
            shapes.signals.append((kind, x, y, text))
    shapes.surfaces = road_surfaces + junction_surfaces  # junction areas on top of the road ends they overlap
    return shapes


def _road_order(road_id: str):
    return (0, int(road_id), "") if road_id.lstrip("-").isdigit() else (1, 0, road_id)


def _offset(road: Road, s: float) -> float:
    return road.lane_offset(s)


def _mark(kind: str, colour: str | None, line) -> tuple[str, str, float, list]:
    style = "dashed" if "broken" in kind else "solid"
    width = 1.6 if " " in kind else 0.9  # "solid solid", "broken solid": a double line drawn bold
    return MARK_COLOURS.get(colour or "white", "#f5f5f5"), style, width, line


def _object_shapes(road: Road, obj, shapes: MapShapes) -> None:
    name = (obj.name or "").lower()
    kind = (obj.type or "").lower()
    ref = road.pose(obj.s)
    cx, cy = _normal_point(road, obj.s, obj.t)
    heading = ref.hdg + obj.hdg
    c, s = math.cos(heading), math.sin(heading)

    def world(u: float, v: float) -> tuple[float, float]:
        return cx + u * c - v * s, cy + u * s + v * c

    if obj.outline:
        us, vs = [p[0] for p in obj.outline], [p[1] for p in obj.outline]
        u0, u1, v0, v1 = min(us), max(us), min(vs), max(vs)
    else:
        u0, u1, v0, v1 = -obj.length / 2, obj.length / 2, -obj.width / 2, obj.width / 2
    if "crosswalk" in kind or "crosswalk" in name:
        if u1 - u0 < 0.5 or v1 - v0 < 0.5:
            return
        u = u0 + 0.25
        while u + 0.5 <= u1:  # bars across the walking direction, 0.5 m wide, 0.5 m apart
            shapes.stripes.append([world(u, v0), world(u + 0.5, v0), world(u + 0.5, v1), world(u, v1)])
            u += 1.0
    elif "stopline" in (obj.subtype or "").lower() or "stopline" in name:
        half = max(v1 - v0, 0.3) / 2
        vm = (v0 + v1) / 2
        shapes.stripes.append([world(u0, vm - half), world(u1, vm - half), world(u1, vm + half), world(u0, vm + half)])


def _signal_kind(signal) -> tuple[str, str]:
    name = (signal.name or "").lower()
    if signal.type == "1000001" or "light" in name:
        return "light", ""
    if signal.type == "206" or "stop" in name:
        return "stop", ""
    if signal.type == "205" or "yield" in name:
        return "yield", ""
    if signal.type == "274" or name.startswith("speed"):
        value = signal.value if signal.value and signal.value > 0 else None
        if value is None:
            digits = "".join(ch for ch in name if ch.isdigit())
            return "speed", digits
        return "speed", f"{value:g}"
    return "other", ""


# -- bodies through time -----------------------------------------------------------------------------------

def sample_at(samples: list[Sample], t: float, step_s: float) -> Sample | None:
    """The body's last sample at or before t; None before it appears or after it has left."""
    if not samples or t < samples[0].t - 1e-9 or t > samples[-1].t + step_s + 1e-9:
        return None
    times = [s.t for s in samples]
    return samples[max(0, bisect.bisect_right(times, t + 1e-9) - 1)]


def box_corners(sample: Sample, body) -> list[tuple[float, float]]:
    c, s = math.cos(sample.h), math.sin(sample.h)
    cx, cy = sample.x + body.x_offset * c, sample.y + body.x_offset * s
    half_l, half_w = body.length / 2, body.width / 2
    return [(cx + u * c - v * s, cy + u * s + v * c)
            for u, v in ((half_l, half_w), (-half_l, half_w), (-half_l, -half_w), (half_l, -half_w))]


def colour_of(name: str, cast: Cast) -> str:
    return EGO_COLOUR if name == cast.ego else TYPE_COLOURS.get(cast.types.get(name, ""), OTHER_COLOUR)


def _draw_order(trace: Trace, cast: Cast) -> list[str]:
    """Everyone in name order, the ego last so that it is drawn on top."""
    return sorted(trace.samples, key=lambda n: (n == cast.ego, n))


def stage_marks(trace: Trace, cast: Cast) -> list[tuple[str, float, float, float]]:
    """(stage, time, x, y) of the ego when each stage after the first started."""
    ego = trace.samples.get(cast.ego or "", [])
    marks = []
    for stage in cast.stages[1:]:
        t = trace.started.get(stage)
        if t is None:
            continue
        at = sample_at(ego, t, trace.step_s) or (ego[-1] if ego else None)
        if at is not None:
            marks.append((stage, t, at.x, at.y))
    return marks


# -- drawing -----------------------------------------------------------------------------------------------

class _Canvas:
    """One figure: the map axes on the left, the legend panel on the right."""

    def __init__(self, odr: OpenDrive, trace: Trace, cast: Cast, verdict: Verdict, view: View):
        import matplotlib

        matplotlib.use("Agg", force=True)
        from matplotlib.figure import Figure

        self.mpl = matplotlib
        self.trace, self.cast, self.verdict, self.view = trace, cast, verdict, view
        with matplotlib.rc_context(_RC):
            self.figure = Figure(figsize=(WIDTH_PX / DPI, HEIGHT_PX / DPI), dpi=DPI, facecolor="white")
            from matplotlib.backends.backend_agg import FigureCanvasAgg

            self.canvas = FigureCanvasAgg(self.figure)
            self.ax = self.figure.add_axes((0, 0, MAP_PX / WIDTH_PX, 1))
            self.panel = self.figure.add_axes((MAP_PX / WIDTH_PX, 0, 1 - MAP_PX / WIDTH_PX, 1))
            self.panel.set_axis_off()
            self._map(odr)
            self._legend()

    def _map(self, odr: OpenDrive) -> None:
        from matplotlib.collections import LineCollection, PolyCollection

        ax, view = self.ax, self.view
        ax.set_facecolor(GROUND)
        ax.set_xlim(view.x0, view.x0 + view.size)
        ax.set_ylim(view.y0, view.y0 + view.size)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xticks([])
        ax.set_yticks([])
        for spine in ax.spines.values():
            spine.set_visible(False)
        shapes = map_shapes(odr, view)
        self.signal_kinds = sorted({kind for kind, x, y, _ in shapes.signals
                                    if view.x0 <= x <= view.x0 + view.size and view.y0 <= y <= view.y0 + view.size})
        if shapes.surfaces:
            ax.add_collection(PolyCollection([p for _, p in shapes.surfaces], facecolors=[f for f, _ in shapes.surfaces],
                                             edgecolors=[f for f, _ in shapes.surfaces], linewidths=0.3, zorder=1))
        for style in ("solid", "dashed"):
            marks = [m for m in shapes.marks if m[1] == style]
            if marks:
                ax.add_collection(LineCollection([m[3] for m in marks], colors=[m[0] for m in marks],
                                                 linewidths=[m[2] for m in marks],
                                                 linestyles=style if style == "solid" else (0, (5, 7)), zorder=2))
        if shapes.stripes:
            ax.add_collection(PolyCollection(shapes.stripes, facecolors="#f5f5f5", edgecolors="none", zorder=2))
        for kind, x, y, text in shapes.signals:
            if not (view.x0 <= x <= view.x0 + view.size and view.y0 <= y <= view.y0 + view.size):
                continue
            ax.plot([x], [y], zorder=3, **SIGNAL_STYLE[kind])
            if kind == "light":
                ax.plot([x], [y], marker="o", markersize=4, color="#f5b400", zorder=3.1)
            elif kind == "speed":
                ax.text(x, y, text, fontsize=6, ha="center", va="center", zorder=3.1)
        bar = 10.0 if view.size < 150 else 50.0  # a scale bar in the lower left
        bx, by = view.x0 + view.size * 0.03, view.y0 + view.size * 0.03
        ax.plot([bx, bx + bar], [by, by], color="black", linewidth=3, solid_capstyle="butt", zorder=6,
                path_effects=self._outline(3, "white"))
        ax.text(bx + bar / 2, by + view.size * 0.012, f"{bar:g} m", ha="center", va="bottom", fontsize=9, zorder=6,
                bbox=dict(boxstyle="round,pad=0.1", facecolor="white", edgecolor="none", alpha=0.8))

    def paths(self, alpha: float = 0.9) -> None:
        for name in _draw_order(self.trace, self.cast):
            samples = self.trace.samples[name]
            width = 3.0 if name == self.cast.ego else 1.8
            self.ax.plot([s.x for s in samples], [s.y for s in samples], color=colour_of(name, self.cast),
                         linewidth=width, alpha=alpha, zorder=4, solid_capstyle="round",
                         path_effects=self._outline(width))

    def _outline(self, linewidth: float, colour: str = "#222222"):
        """A rim around a line of that width, so it reads on asphalt and on grass alike."""
        from matplotlib import patheffects

        return [patheffects.Stroke(linewidth=linewidth + 2.0, foreground=colour), patheffects.Normal()]

    def box(self, name: str, sample: Sample, filled: bool = True, animated: bool = False):
        from matplotlib.patches import Polygon

        body = self.trace.bodies.get(name)
        if body is None:
            return []
        ego = name == self.cast.ego
        colour = colour_of(name, self.cast)
        patch = Polygon(box_corners(sample, body), closed=True, zorder=7 if ego else 5,
                        facecolor=colour if filled else "none", edgecolor="black" if filled else colour,
                        linewidth=2.4 if ego else 1.0, linestyle="solid" if filled else (0, (3, 2)), animated=animated)
        self.ax.add_patch(patch)
        return [patch]

    def label(self, name: str, sample: Sample, placed: list, animated: bool = False):
        """The name beside the body, in the first corner around it whose box overlaps no label placed yet."""
        from matplotlib.transforms import offset_copy

        ego = name == self.cast.ego
        size = 9 if ego else 8
        col, row = self.view.pixel(sample.x, sample.y)
        width, height, gap = size * 0.75 * (len(name) + 2), size * 2.0, 11
        chosen = None
        for dx, dy in ((1, 1), (1, -1), (-1, 1), (-1, -1), (1, 2.6), (-1, -2.6)):
            left = col + gap if dx > 0 else col - gap - width
            top = row - gap * abs(dy) - height if dy > 0 else row + gap * abs(dy)
            box = (left, top, left + width, top + height)
            if chosen is None:
                chosen = (dx, dy, box)
            if not any(box[0] < b[2] and b[0] < box[2] and box[1] < b[3] and b[1] < box[3] for b in placed):
                chosen = (dx, dy, box)
                break
        dx, dy, box = chosen
        placed.append(box)
        text = self.ax.text(sample.x, sample.y, f" {name} ", fontsize=size, ha="left" if dx > 0 else "right",
                            va="bottom" if dy > 0 else "top", fontweight="bold" if ego else "normal", zorder=8,
                            animated=animated, clip_on=True,
                            bbox=dict(boxstyle="round,pad=0.15", facecolor="white", edgecolor="#333333",
                                      linewidth=0.6, alpha=0.85))
        text.set_transform(offset_copy(self.ax.transData, fig=self.figure, x=8 * dx, y=8 * dy, units="points"))
        return [text]

    def marks(self, until: float | None = None, animated: bool = False):
        artists = []
        for stage, t, x, y in stage_marks(self.trace, self.cast):
            if until is not None and t > until:
                continue
            artists += self.ax.plot([x], [y], marker="D", markersize=9, color="white", markeredgecolor="black",
                                    markeredgewidth=1.5, zorder=9, animated=animated)
            artists.append(self.ax.annotate(f"{stage} ({t:.1f} s)", (x, y), xytext=(8, -14), textcoords="offset points",
                                            fontsize=8, zorder=9, animated=animated,
                                            bbox=dict(boxstyle="round,pad=0.15", facecolor="#ffffe0",
                                                      edgecolor="#333333", linewidth=0.6)))
        for c in self.verdict.collisions:
            if until is not None and c.time_s > until:
                continue
            artists += self.ax.plot([c.x], [c.y], marker="X", markersize=16, color=COLLISION_COLOUR,
                                    markeredgecolor="black", markeredgewidth=1.2, zorder=10, animated=animated)
            artists.append(self.ax.annotate(f"{c.a} / {c.b} ({c.time_s:.1f} s)", (c.x, c.y), xytext=(10, 8),
                                            textcoords="offset points", fontsize=8, color="#8b0000", zorder=10,
                                            animated=animated, bbox=dict(boxstyle="round,pad=0.15", facecolor="white",
                                                                         edgecolor=COLLISION_COLOUR, linewidth=0.8)))
        return artists

    def _legend(self) -> None:
        from matplotlib.lines import Line2D
        from matplotlib.patches import Patch

        panel, verdict = self.panel, self.verdict
        y = 0.97
        title = "\n".join(textwrap.wrap(self.cast.title or "scene", 26)[:3])
        panel.text(0.06, y, title, fontsize=13, fontweight="bold", va="top", transform=panel.transAxes)
        y -= 0.045 * (title.count("\n") + 1) + 0.01
        where = verdict.map_name or "map"
        panel.text(0.06, y, f"{where}, played by {verdict.player}", fontsize=9, va="top", color="#333333",
                   transform=panel.transAxes)
        y -= 0.04
        if verdict.ok is None:
            word, colour = "not judged", "#555555"
        elif verdict.ok:
            word, colour = "verdict: ok", "#1a7f37"
        else:
            word, colour = "verdict: FAILED", "#c8102e"
        panel.text(0.06, y, word, fontsize=12, fontweight="bold", color=colour, va="top", transform=panel.transAxes)
        y -= 0.045
        lines = [textwrap.shorten(f, 90, placeholder="...") for f in verdict.failures]
        lines += [f"collision {c.a} / {c.b} at {c.time_s:.1f} s" + (" (asked for)" if c.asked_for else "")
                  for c in verdict.collisions]
        for line in lines[:6]:
            wrapped = "\n".join(textwrap.wrap(line, 38)[:3])
            panel.text(0.06, y, wrapped, fontsize=8, va="top", color="#333333", transform=panel.transAxes)
            y -= 0.028 * (wrapped.count("\n") + 1) + 0.006
        handles = [Patch(facecolor=EGO_COLOUR, edgecolor="black", linewidth=2.0, label="ego" if self.cast.ego in (None, "ego") else f"ego ({self.cast.ego})")]
        present = sorted({self.cast.types.get(n, "") for n in self.trace.samples if n != self.cast.ego})
        for kind in present:
            handles.append(Patch(facecolor=TYPE_COLOURS.get(kind, OTHER_COLOUR), edgecolor="black",
                                 label=kind or "other"))
        handles.append(Patch(facecolor="none", edgecolor="#555555", linestyle=(0, (3, 2)), label="where it ended"))
        handles.append(Line2D([], [], color="#555555", linewidth=2, label="path"))
        handles.append(Line2D([], [], marker="D", color="white", markeredgecolor="black", linestyle="none",
                              label="stage change"))
        handles.append(Line2D([], [], marker="X", color=COLLISION_COLOUR, markeredgecolor="black", markersize=10,
                              linestyle="none", label="collision"))
        for kind in self.signal_kinds:
            handles.append(Line2D([], [], linestyle="none", label=SIGNAL_WORDS[kind], **SIGNAL_STYLE[kind]))
        panel.legend(handles=handles, loc="upper left", bbox_to_anchor=(0.03, y), fontsize=9, frameon=False)
        self.clock = panel.text(0.06, 0.03, f"{self.trace.end_time:.1f} s played", fontsize=10, color="#333333",
                                transform=panel.transAxes)

    def rgba(self):
        import numpy as np

        self.canvas.draw()
        return np.asarray(self.canvas.buffer_rgba()).copy()


_RC = {"font.family": "DejaVu Sans", "font.size": 9, "svg.hashsalt": "ttsgc", "path.simplify": False,
       "text.antialiased": True, "lines.antialiased": True, "patch.antialiased": True}


def picture(odr: OpenDrive, trace: Trace, cast: Cast, verdict: Verdict):
    """The still: paths, every body where it started (filled) and where it ended (dashed), stage changes and
    collisions. Returns (RGBA pixels, view)."""
    view = view_of(trace)
    canvas = _Canvas(odr, trace, cast, verdict, view)
    with canvas.mpl.rc_context(_RC):
        canvas.paths()
        for name in _draw_order(trace, cast):
            canvas.box(name, trace.samples[name][-1], filled=False)
        placed: list = []
        for name in _draw_order(trace, cast)[::-1]:  # the ego's label first, where it reads best
            first = trace.samples[name][0]
            canvas.box(name, first)
            canvas.label(name, first, placed)
        canvas.marks()
        return canvas.rgba(), view


def frames(odr: OpenDrive, trace: Trace, cast: Cast, verdict: Verdict):
    """The animation, one RGBA frame per FRAME_STEP_S of scene time (fewer when the scene is long): the map and
    faint paths drawn once, each frame adds the bodies where they are at that moment."""
    view = view_of(trace)
    canvas = _Canvas(odr, trace, cast, verdict, view)
    import numpy as np

    with canvas.mpl.rc_context(_RC):
        canvas.paths(alpha=0.35)
        canvas.clock.set_animated(True)
        canvas.canvas.draw()
        background = canvas.canvas.copy_from_bbox(canvas.figure.bbox)
        step = max(FRAME_STEP_S, trace.end_time / MAX_FRAMES)
        count = int(trace.end_time / step + 1e-9) + 1
        for i in range(count):
            t = round(i * step, 6)
            canvas.canvas.restore_region(background)
            artists, placed = [], []
            for name in _draw_order(trace, cast)[::-1]:
                at = sample_at(trace.samples[name], t, trace.step_s)
                if at is None:
                    continue
                artists += canvas.box(name, at, animated=True)
                artists += canvas.label(name, at, placed, animated=True)
            artists += canvas.marks(until=t, animated=True)
            canvas.clock.set_text(f"t = {t:5.1f} s")
            for artist in sorted(artists, key=lambda a: a.get_zorder()) + [canvas.clock]:
                artist.axes.draw_artist(artist) if artist.axes is not None else canvas.figure.draw_artist(artist)
            canvas.canvas.blit(canvas.figure.bbox)
            yield np.asarray(canvas.canvas.buffer_rgba()).copy()
            for artist in artists:
                artist.remove()


# -- files -------------------------------------------------------------------------------------------------

def png_bytes(rgba) -> bytes:
    from PIL import Image

    buffer = io.BytesIO()
    Image.fromarray(rgba[:, :, :3]).save(buffer, format="PNG", optimize=False, compress_level=6)
    return buffer.getvalue()


def gif_bytes(rgba_frames) -> bytes:
    from PIL import Image

    images, palette = [], None
    for frame in rgba_frames:  # one palette, taken from the first frame (the map and every path are in it)
        image = Image.fromarray(frame[:, :, :3])
        if palette is None:
            palette = image.quantize(colors=255, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
        images.append(image.quantize(palette=palette, dither=Image.Dither.NONE))
    if not images:
        raise RenderError("the animation has no frames")
    buffer = io.BytesIO()
    images[0].save(buffer, format="GIF", save_all=True, append_images=images[1:], duration=int(1000 / FPS), loop=0,
                   optimize=False)
    return buffer.getvalue()


def mp4_bytes(rgba_frames) -> bytes:
    """H.264 through the ffmpeg that imageio-ffmpeg ships, one thread and bit-exact flags: the same frames give
    the same file."""
    import subprocess
    import tempfile

    import imageio_ffmpeg

    frames_list = list(rgba_frames)
    if not frames_list:
        raise RenderError("the animation has no frames")
    height, width = frames_list[0].shape[:2]
    with tempfile.TemporaryDirectory(prefix="ttsgc-render-") as scratch:
        out = Path(scratch) / "scene.mp4"
        command = [imageio_ffmpeg.get_ffmpeg_exe(), "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24",
                   "-s", f"{width}x{height}", "-r", str(FPS), "-i", "-", "-an", "-c:v", "libx264", "-preset", "medium",
                   "-pix_fmt", "yuv420p", "-threads", "1", "-x264-params", "threads=1:sliced-threads=0",
                   "-fflags", "+bitexact", "-flags:v", "+bitexact", "-map_metadata", "-1", str(out)]
        payload = b"".join(f[:, :, :3].tobytes() for f in frames_list)
        done = subprocess.run(command, input=payload, capture_output=True)
        if done.returncode != 0:
            raise RenderError(f"ffmpeg could not write the video: {done.stderr.decode(errors='replace')[-300:]}")
        return out.read_bytes()


def render_bytes(odr: OpenDrive, trace: Trace, cast: Cast, verdict: Verdict, suffix: str) -> bytes:
    """The picture (.png) or the animation (.gif, .mp4) as file contents."""
    suffix = suffix.lower()
    if suffix == ".png":
        return png_bytes(picture(odr, trace, cast, verdict)[0])
    if suffix == ".gif":
        return gif_bytes(frames(odr, trace, cast, verdict))
    if suffix == ".mp4":
        return mp4_bytes(frames(odr, trace, cast, verdict))
    raise RenderError(f"cannot draw into a '{suffix or 'nameless'}' file; the output must end in "
                      f"{', '.join(FORMATS)}")


# -- a scene file, played and drawn -----------------------------------------------------------------------

def cast_of(plan) -> Cast:
    """Types, ego and stages from a Plan (the file as read), with the file's description as the title."""
    from lxml import etree

    from ttsgc import intent as I

    types, ego = {}, None
    for name, entity in plan.entities.items():
        declared = entity.intent.get(I.TYPE, "")
        if declared:
            types[name] = declared
        elif entity.kind == "pedestrian":
            types[name] = "pedestrian"
        else:  # a hand-written file: its role (ambulance, police, ...) or category says what it is
            types[name] = entity.role if entity.role in TYPE_COLOURS else {"van": "car", "bicycle": "cyclist"}.get(
                entity.category, entity.category)
        if entity.intent.get(I.IS_EGO) == "true":
            ego = name
    if ego is None:  # without ttsgc intents: the entity named ego, else the first one
        ego = "ego" if "ego" in plan.entities else next(iter(plan.entities), None)
    title = Path(plan.xosc).stem
    try:
        parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False)
        header = etree.parse(str(plan.xosc), parser).find("FileHeader")
        if header is not None and (header.get("description") or "").strip():
            title = header.get("description").strip()
    except (OSError, etree.XMLSyntaxError):
        pass
    stages = [int(e.intent[I.STAGE]) for e in plan.entities.values() if e.intent.get(I.STAGE, "").isdigit()]
    acts = [act.name for act in plan.acts]  # stage acts come first; acts after them only tidy up (map_edge)
    return Cast(title, types, ego, tuple(acts[: max(stages) + 1] if stages else acts))


def render_scene(xosc: str | Path, out: str | Path, player: str = "sumo", seed: int = 1) -> Verdict:
    """Play a scene file in one player, judge the trace, and draw it into out (.png, .gif or .mp4)."""
    from ttsgc.files import write_atomic
    from ttsgc.roads.opendrive import load_opendrive
    from ttsgc.simulate.judge import judge, report
    from ttsgc.simulate.plan import read_plan
    from ttsgc.simulate.players import player as player_module
    from ttsgc.simulate.validate import chosen_players

    out = Path(out)
    if out.suffix.lower() not in FORMATS:
        raise RenderError(f"{out}: cannot draw into a '{out.suffix or 'nameless'}' file; the output must end in "
                          f"{', '.join(FORMATS)}")
    if real_path(out) == real_path(xosc):
        raise RenderError(f"{out}: the picture would overwrite the scene itself")
    plan = read_plan(Path(xosc))
    chosen_players(player)  # a clear error when that player cannot run here
    odr = load_opendrive(plan.xodr)
    trace = player_module(player).play(plan, seed=seed)
    judged = report(plan, [judge(plan, trace, odr)])
    verdict = verdict_from_report(judged, player)
    write_atomic(out, render_bytes(odr, trace, cast_of(plan), verdict, out.suffix))
    return verdict
