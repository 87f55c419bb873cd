"""Later stages for CARLA ScenarioRunner: it spawns every entity when the run starts, so an entity that enters
later is spawned parked below its place with its physics off and teleported to a fixed lane position when its
stage starts. That position is where the generic file's players put the entity when it enters."""

from __future__ import annotations

import math
from importlib import resources
from pathlib import Path

import pytest
import xmlschema
from lxml import etree

from conftest import EXAMPLES, SHARED
from ttsgc.cli import main
from ttsgc.errors import ExitCode
from ttsgc.language import parse, parse_file
from ttsgc.pipeline import compile_scenario, for_target, write
from ttsgc.roads.opendrive import load_opendrive
from ttsgc.simulate.plan import read_plan
from ttsgc.simulate.players import player
from ttsgc.targets import carla
from ttsgc.targets.coverage import errors, lint_tree

ESMINI = SHARED / "tools" / "esmini" / "esmini"

# The ego drives a right lane (id < 0, along s) in boxed_in, a left lane (against s) in this scene's best road.
STRAIGHT_THEN_BOXED_IN = """scenario "straight on, then boxed in"

road {
}

stage first {
    ego car go_straight
}

stage second {
    car c2 at front block_the_ego
    car c3 at front_left go_straight
}
"""

# The third stage starts a time after the second: where the ego is then is known only by playing the scene.
THIRD_STAGE_ON_TIME = STRAIGHT_THEN_BOXED_IN.rstrip() + """

stage third {
    car c4 at front go_straight
}
"""


def _scene(text_or_path):
    return parse_file(text_or_path) if isinstance(text_or_path, Path) else parse(text_or_path)


def _story_teleports(root) -> dict[str, etree._Element]:
    """entity name -> the LanePosition its Story TeleportAction moves it to."""
    places = {}
    for teleport in root.iter("TeleportAction"):
        if any(a.tag == "Story" for a in teleport.iterancestors()):
            group = next(a for a in teleport.iterancestors() if a.tag == "ManeuverGroup")
            places[group.find("Actors/EntityRef").get("entityRef")] = teleport.find("Position/LanePosition")
    return places


def test_boxed_in_compiles_for_carla_and_lints_clean(tmp_path, capsys):
    out = tmp_path / "boxed_in.xosc"
    assert main(["compile", str(EXAMPLES / "boxed_in.tsg"), "-o", str(out), "--target", "carla",
                 "--no-simulate"]) == 0
    schema = xmlschema.XMLSchema(str(resources.files("qc_openscenario") / "schema" / "1.0.0" / "OpenSCENARIO.xsd"))
    schema.validate(str(out))
    root = etree.parse(str(out)).getroot()
    assert errors(lint_tree(root, "carla")) == []
    assert not list(root.iter("AddEntityAction"))
    assert main(["lint", "--target", "carla", str(out)]) == 0


def test_a_late_entity_is_parked_below_its_place_without_physics_until_its_stage(tmp_path):
    scenario = parse_file(EXAMPLES / "boxed_in.tsg")
    compiled = compile_scenario(scenario, tmp_path / "b.xosc", target="carla")
    root = etree.fromstring(compiled.xosc)
    late = [a.name for a in compiled.scene.agents if a.stage > 0]
    odr = load_opendrive(compiled.scene.map_path)
    places = _story_teleports(root)
    assert sorted(places) == sorted(late)
    for name in late:
        body = next(o for o in root.iter("ScenarioObject") if o.get("name") == name)
        assert body.find(".//Property[@name='physics']").get("value") == "off"
        parked = root.find(f"Storyboard/Init/Actions/Private[@entityRef='{name}']//WorldPosition")
        place = places[name]
        pose = odr.roads[place.get("roadId")].lane_point(float(place.get("s")), int(place.get("laneId")))
        assert float(parked.get("z")) <= -100  # out of every town's reach
        assert math.hypot(float(parked.get("x")) - pose.x, float(parked.get("y")) - pose.y) < 0.01
        # its stage's act holds the teleport: the entity arrives when the stage starts, not before
        act = next(a for a in places[name].iterancestors() if a.tag == "Act")
        stage = next(a.stage for a in compiled.scene.agents if a.name == name)
        assert act.get("name") == scenario.stages[stage].name


def _reference_point(trace, name: str, sample) -> tuple[float, float]:
    """A sample is the body's centre; a position in the file is its reference point, x_offset behind it."""
    back = trace.bodies[name].x_offset
    return sample.x - back * math.cos(sample.h), sample.y - back * math.sin(sample.h)


def _players():
    yield "sumo"
    if ESMINI.is_file():
        yield "esmini"


# (scene, CARLA town or None for the built-in library, the approach to bind to)
LATE_ENTRY_CASES = {"boxed_in": (EXAMPLES / "boxed_in.tsg", None, None),
                    "left_lane": (STRAIGHT_THEN_BOXED_IN, None, None),
                    "Town04": (EXAMPLES / "boxed_in.tsg", "Town04", ("Town04", "28:fwd"))}  # a left lane too


@pytest.mark.parametrize("case", list(LATE_ENTRY_CASES))
@pytest.mark.parametrize("player_name", list(_players()))
def test_late_entities_in_the_carla_file_are_where_the_generic_file_puts_them(case, player_name, tmp_path,
                                                                              monkeypatch, request):
    """The generic file places a late car relative to the ego as its stage starts; the player's trace of that
    file says where the ego was then and where the car entered. The carla file's fixed places must agree, to
    within what the players' steps allow: the trigger is checked once a step, and the car enters a step later
    (so the ego may be up to a step past the trigger point, the car a step further on when first sampled)."""
    if player_name == "esmini":
        monkeypatch.setenv("TTSGC_ESMINI", str(ESMINI))
    source, town, only = LATE_ENTRY_CASES[case]
    maps = None
    if town is not None:
        maps = [request.getfixturevalue("shared") / "maps" / "carla" / f"{town}.xodr"]
    scenario = _scene(source)
    out = tmp_path / "generic.xosc"
    compiled = compile_scenario(scenario, out, maps=maps, version="1.0", only=only)
    write(compiled, out)
    trace = player(player_name).play(read_plan(out))
    root = etree.fromstring(for_target(compiled, "carla").xosc)
    odr = load_opendrive(compiled.scene.map_path)
    ego = next(a for a in compiled.scene.agents if a.is_ego)
    step_travel = ego.speed_mps * trace.step_s

    stage = scenario.stages[1].name
    act = next(a for a in etree.fromstring(compiled.xosc).iter("Act") if a.get("name") == stage)
    expected_ego = carla.ego_at_stage_start(act, ego.name, odr)
    started = trace.started[stage]
    ego_then = min(trace.samples[ego.name], key=lambda q: abs(q.t - started))
    ego_pose = odr.roads[expected_ego.road].lane_point(expected_ego.s, expected_ego.lane)
    ego_x, ego_y = _reference_point(trace, ego.name, ego_then)
    assert math.hypot(ego_x - ego_pose.x, ego_y - ego_pose.y) <= step_travel + 0.1, (ego_then, ego_pose)

    places = _story_teleports(root)
    late = [a for a in compiled.scene.agents if a.stage > 0]
    assert late and sorted(places) == sorted(a.name for a in late)
    for agent in late:
        place = places[agent.name]
        pose = odr.roads[place.get("roadId")].lane_point(float(place.get("s")), int(place.get("laneId")))
        entered = trace.samples[agent.name][0]
        if entered.road:
            assert (entered.road, entered.lane) == (place.get("roadId"), int(place.get("laneId"))), agent.name
        x, y = _reference_point(trace, agent.name, entered)
        tolerance = 2 * step_travel + agent.speed_mps * trace.step_s + 0.1
        assert math.hypot(x - pose.x, y - pose.y) <= tolerance, (agent.name, entered, pose)
        turn = math.remainder(entered.h - pose.hdg, math.tau)  # facing its lane's way, as the carla file has it
        assert abs(turn) < 0.3, (agent.name, entered, pose)


def test_a_late_entity_beside_the_ego_in_a_stage_that_starts_on_time_is_refused(tmp_path, capsys):
    """Where the ego is a time after the previous stage is known only by playing the scene: refused, naming
    the act and the entity, with nothing written."""
    source = tmp_path / "three.tsg"
    source.write_text(THIRD_STAGE_ON_TIME)
    out = tmp_path / "three.xosc"
    code = main(["compile", str(source), "-o", str(out), "--target", "carla", "--no-simulate"])
    err = capsys.readouterr().err
    assert code == int(ExitCode.UNSUPPORTED_BY_TARGET)
    assert "act 'third': 'c4' enters beside the ego" in err and not out.exists()


def test_lanes_beside_are_lane_id_differences_across_the_centre(tmp_path):
    """dLane adds to the lane id, the centre lane (0) skipped: +1 is the driver's left on a right lane (id < 0),
    the driver's right on a left lane."""
    scenario = parse(STRAIGHT_THEN_BOXED_IN)
    compiled = compile_scenario(scenario, tmp_path / "s.xosc")
    odr = load_opendrive(compiled.scene.map_path)
    road = next(r for r in odr.roads.values() if r.junction == "-1" and len(r.sections[0].lanes) >= 4
                and {-2, -1, 1, 2} <= set(r.sections[0].lanes))
    right = carla.LanePos(road=road.id, lane=-1, s=road.length / 2)
    left = carla.LanePos(road=road.id, lane=1, s=road.length / 2)
    assert carla.lane_position_beside(right, 1, 0.0, odr).lane == 1  # across the centre line
    assert carla.lane_position_beside(right, -1, 0.0, odr).lane == -2
    assert carla.lane_position_beside(left, 1, 0.0, odr).lane == 2
    assert carla.lane_position_beside(left, -1, 0.0, odr).lane == -1
    # ds runs along the road's s whichever way the lane is driven
    assert carla.lane_position_beside(right, 0, 5.0, odr).s == pytest.approx(road.length / 2 + 5.0)
    assert carla.lane_position_beside(left, 0, -5.0, odr).s == pytest.approx(road.length / 2 - 5.0)
    assert "past its end" in carla.lane_position_beside(right, 0, road.length, odr)


def test_a_late_car_ahead_of_an_ego_on_a_left_lane_is_ahead_of_it_in_every_player(tmp_path, monkeypatch):
    """OpenSCENARIO's RelativeLanePosition counts ds along the road's s and dLane in lane ids, as esmini reads
    it: ahead of an ego driving a left lane (against s) is a negative ds. Written as a positive ds, esmini put
    the blocking car behind the ego (and onto the road beyond the map's end) while SUMO put it ahead."""
    if not ESMINI.is_file():
        pytest.skip("../shared/tools/esmini is not present")
    monkeypatch.setenv("TTSGC_ESMINI", str(ESMINI))
    from ttsgc.simulate.validate import validate

    out = tmp_path / "left.xosc"
    compiled = compile_scenario(parse(STRAIGHT_THEN_BOXED_IN), out)
    write(compiled, out)
    assert compiled.scene.agent("ego").start.lane > 0  # the case: the ego drives against s
    report = validate(out, "all")
    assert {v.player for v in report.verdicts} == {"sumo", "esmini"}
    for verdict in report.verdicts:
        assert all(a.achieved for a in verdict.agents), (verdict.player, [a.reason for a in verdict.agents])


def test_a_late_entity_at_a_fixed_place_is_teleported_to_that_place(tmp_path):
    """An agent of a later stage standing on a junction road enters at the generic file's own lane position."""
    text = (EXAMPLES / "boxed_in.tsg").read_text().replace(
        "behind c2", "behind c2\n    car c4 at road_of_left_turn stop")
    compiled = compile_scenario(parse(text), tmp_path / "f.xosc", version="1.0")
    generic = etree.fromstring(compiled.xosc)
    entered = next(e for e in generic.iter("EntityAction") if e.get("entityRef") == "c4")
    fixed = entered.find("AddEntityAction/Position/LanePosition")
    assert fixed is not None
    place = _story_teleports(etree.fromstring(for_target(compiled, "carla").xosc))["c4"]
    assert dict(place.attrib) == dict(fixed.attrib)
