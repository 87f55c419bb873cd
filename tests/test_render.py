"""Pictures of a scene: drawn from a Trace, the map and the verdicts, and checked pixel by pixel."""

from __future__ import annotations

import io
import math

import pytest

pytest.importorskip("matplotlib")
from PIL import Image  # noqa: E402

from ttsgc import render as R  # noqa: E402
from ttsgc.roads.opendrive import load_opendrive  # noqa: E402
from ttsgc.simulate.trace import Body, Sample, Trace  # noqa: E402

from conftest import ROOT  # noqa: E402

MAP = ROOT / "maps" / "fourway_2lane_lights.xodr"


def _rgb(colour: str) -> tuple[int, int, int]:
    colour = colour.lstrip("#")
    return tuple(int(colour[i:i + 2], 16) for i in (0, 2, 4))


def _lane_path(road, lane: int, s0: float, s1: float, t0: float = 0.0, n: int = 30, dt: float = 0.25):
    samples = []
    for i in range(n + 1):
        s = s0 + (s1 - s0) * i / n
        p = road.lane_point(s, lane)
        samples.append(Sample(t0 + i * dt, p.x, p.y, p.hdg, abs(s1 - s0) / (n * dt), road.id, lane, s))
    return samples


@pytest.fixture(scope="module")
def scene():
    odr = load_opendrive(MAP)
    road = odr.roads["1"]
    trace = Trace("test", 0.25,
                  bodies={"ego": Body(4.5, 1.9, 1.4), "t1": Body(8.0, 2.5, 2.0), "late": Body(4.5, 1.9, 1.4)},
                  samples={"ego": _lane_path(road, -1, 20, 90), "t1": _lane_path(road, 1, 100, 40),
                           "late": _lane_path(road, -2, 30, 60, t0=4.0, n=8)},
                  started={"first": 0.0, "second": 4.0}, end_time=7.5)
    cast = R.Cast("a test scene", {"ego": "car", "t1": "truck", "late": "car"}, "ego", ("first", "second"))
    hit = trace.samples["ego"][20]
    verdict = R.Verdict(False, "test", ("t1: did not stop",), (R.CollisionMark("ego", "t1", 5.0, hit.x, hit.y),),
                        "fourway_2lane_lights")
    return odr, road, trace, cast, verdict


def _near(pixels, col: int, row: int, colour: str, radius: int = 0, tolerance: int = 12) -> bool:
    want = _rgb(colour)
    for dr in range(-radius, radius + 1):
        for dc in range(-radius, radius + 1):
            got = pixels[row + dr][col + dc][:3]
            if all(abs(int(g) - w) <= tolerance for g, w in zip(got, want)):
                return True
    return False


def test_the_ego_box_is_drawn_in_its_colour_where_it_starts(scene):
    odr, road, trace, cast, verdict = scene
    pixels, view = R.picture(odr, trace, cast, verdict)
    assert pixels.shape == (R.HEIGHT_PX, R.WIDTH_PX, 4)
    start = trace.samples["ego"][0]
    body = trace.bodies["ego"]
    centre = (start.x + body.x_offset * math.cos(start.h), start.y + body.x_offset * math.sin(start.h))
    assert _near(pixels, *view.pixel(*centre), R.EGO_COLOUR)
    truck = trace.samples["t1"][0]
    assert _near(pixels, *view.pixel(truck.x + 2.0 * math.cos(truck.h), truck.y + 2.0 * math.sin(truck.h)),
                 R.TYPE_COLOURS["truck"])
    # the ego's start is not drawn in the truck's colour, nor the ground's: the test can fail
    assert not _near(pixels, *view.pixel(*centre), R.TYPE_COLOURS["truck"])


def test_lane_marks_and_asphalt_are_where_the_map_puts_them(scene):
    odr, road, trace, cast, verdict = scene
    pixels, view = R.picture(odr, trace, cast, verdict)
    s = 110.0  # past every body's path
    ref = road.pose(s)
    centre_line = view.pixel(ref.x, ref.y)  # the centre mark between the two directions
    assert _near(pixels, *centre_line, R.MARK_COLOURS["white"], radius=1, tolerance=40)
    lane = road.lane_point(s, -2)  # the middle of the outer lane: plain asphalt
    assert _near(pixels, *view.pixel(lane.x, lane.y), R.SURFACE["driving"])
    sidewalk = road.lane_point(s, -4) if -4 in road.section_at(s).lanes else None
    if sidewalk is not None and road.section_at(s).lanes[-4].type == "sidewalk":
        assert _near(pixels, *view.pixel(sidewalk.x, sidewalk.y), R.SURFACE["sidewalk"])


def test_collision_point_is_marked(scene):
    odr, road, trace, cast, verdict = scene
    pixels, view = R.picture(odr, trace, cast, verdict)
    c = verdict.collisions[0]
    assert _near(pixels, *view.pixel(c.x, c.y), R.COLLISION_COLOUR, radius=3)


def test_same_input_same_bytes(scene):
    odr, road, trace, cast, verdict = scene
    first = R.render_bytes(odr, trace, cast, verdict, ".png")
    assert first == R.render_bytes(odr, trace, cast, verdict, ".png")
    image = Image.open(io.BytesIO(first))
    assert image.size == (R.WIDTH_PX, R.HEIGHT_PX)
    assert not {k for k in image.info if k.lower() in ("software", "creation time", "date")}


def test_animation_steps_through_the_trace(scene):
    odr, road, trace, cast, verdict = scene
    frames = list(R.frames(odr, trace, cast, verdict))
    assert len(frames) == int(trace.end_time / R.FRAME_STEP_S) + 1
    view = R.view_of(trace)
    late = trace.samples["late"][0]
    where = view.pixel(late.x + 1.4 * math.cos(late.h), late.y + 1.4 * math.sin(late.h))
    colour = R.TYPE_COLOURS["car"]
    assert not _near(frames[0], *where, colour)  # not there before it appears at 4 s
    assert _near(frames[int(4.0 / R.FRAME_STEP_S)], *where, colour)
    gif = R.gif_bytes(frames[:5])
    assert gif == R.gif_bytes(frames[:5])
    assert Image.open(io.BytesIO(gif)).n_frames == 5
    video = R.mp4_bytes(frames[:3])
    assert video[4:8] == b"ftyp" and video == R.mp4_bytes(frames[:3])


def test_an_unknown_output_kind_is_refused(scene):
    odr, road, trace, cast, verdict = scene
    with pytest.raises(R.RenderError, match="must end in .png"):
        R.render_bytes(odr, trace, cast, verdict, ".jpeg")


def test_an_empty_trace_is_refused(scene):
    odr, road, trace, cast, verdict = scene
    with pytest.raises(R.RenderError, match="no samples"):
        R.view_of(Trace("test", 0.1))


def test_every_example_has_a_picture():
    from conftest import example_scenarios

    pictures = ROOT / "examples" / "pictures"
    missing = [p.stem for p in example_scenarios() if not (pictures / f"{p.stem}.png").is_file()]
    assert not missing, f"no picture for {missing}: run python examples/pictures/draw.py and look at them"
    for picture in pictures.glob("*.png"):
        assert Image.open(picture).size == (R.WIDTH_PX, R.HEIGHT_PX)


def test_render_command_draws_a_played_scene_and_refuses_bad_outputs(tmp_path, capsys):
    from ttsgc.cli import main

    scene = tmp_path / "blocking.xosc"
    assert main(["compile", str(ROOT / "examples" / "blocking.tsg"), "-o", str(scene), "--player", "sumo",
                 "--render"]) == 0
    first = (tmp_path / "blocking.png").read_bytes()  # compile --render: the picture beside the scene
    assert "verdict ok" in capsys.readouterr().out
    assert main(["render", str(scene), "-o", str(tmp_path / "again.png"), "--player", "sumo"]) == 0
    assert (tmp_path / "again.png").read_bytes() == first  # played again, drawn again: the same bytes
    assert main(["render", str(scene), "-o", str(tmp_path / "blocking.jpg")]) == 2
    assert "must end in .png, .gif, .mp4" in capsys.readouterr().err
    assert not (tmp_path / "blocking.jpg").exists()
    assert main(["render", str(tmp_path / "missing.xosc")]) == 2
