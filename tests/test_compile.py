"""Binding and emission: golden files, validity in every version, positions, actions, no overlap, outputs."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import pytest
from lxml import etree

from conftest import EXAMPLES, asam_errors, example_scenarios
from ttsgc.binding import bind
from ttsgc.cli import main
from ttsgc.emit.xosc import VERSIONS, emit
from ttsgc.language import parse, parse_file
from ttsgc.pipeline import compile_scenario
from ttsgc.roads import load_library
from ttsgc.roads.opendrive import read_opendrive

GOLDEN = EXAMPLES / "golden"


@pytest.fixture(scope="module")
def library():
    return load_library()


def _scene(body: str, road: str = "") -> str:
    return f'scenario "t"\n{road}stage s {{\n    {body}\n}}\n'


@pytest.mark.parametrize("path", example_scenarios(), ids=lambda p: p.stem)
def test_golden_files(path, tmp_path, regen_golden):
    out = tmp_path / f"{path.stem}.xosc"
    compiled = compile_scenario(parse_file(path), out)
    golden = GOLDEN / f"{path.stem}.xosc"
    if regen_golden:
        GOLDEN.mkdir(exist_ok=True)
        golden.write_bytes(compiled.xosc)
    assert golden.is_file(), f"no golden file for {path.name}: run pytest --regen-golden and review it"
    assert compiled.xosc == golden.read_bytes(), f"{path.name} compiles differently from its golden file"


def test_compiling_is_deterministic(tmp_path):
    path = EXAMPLES / "intersection.tsg"
    first = compile_scenario(parse_file(path), tmp_path / "a.xosc").xosc
    second = compile_scenario(parse_file(path), tmp_path / "b.xosc").xosc
    assert first == second


@pytest.mark.parametrize("version", VERSIONS)
def test_every_example_is_xsd_and_checker_clean_in_every_version(version, tmp_path, library):
    for path in example_scenarios():
        out = tmp_path / f"{path.stem}.xosc"
        scene = bind(parse_file(path), library)
        shutil.copy(scene.map_path, tmp_path / Path(scene.map_path).name)
        out.write_bytes(emit(scene, Path(scene.map_path).name, version))  # emit validates against the XSD
        assert etree.parse(str(out)).getroot().find("FileHeader").get("revMinor") == version[-1]
        assert asam_errors("qc_openscenario", "xoscBundle", out, tmp_path) == [], (path.name, version)


def test_all_examples_compile_on_the_carla_towns(shared, tmp_path):
    carla = load_library([shared / "maps" / "carla"])
    for path in example_scenarios():
        scene = bind(parse_file(path), carla)
        assert scene.map_name.startswith("Town") and not scene.unmet, (path.name, scene.unmet)


# -- where agents stand ---------------------------------------------------------------------------------

def _frame(odr, pos):
    p = odr.roads[pos.road].lane_point(pos.s, pos.lane)
    return p.x, p.y, p.hdg


def _relative(odr, ego, other) -> tuple[float, float]:
    """(ahead, left) of the other body in the ego's frame, metres."""
    ex, ey, eh = _frame(odr, ego)
    ox, oy, _ = _frame(odr, other)
    dx, dy = ox - ex, oy - ey
    return dx * math.cos(eh) + dy * math.sin(eh), -dx * math.sin(eh) + dy * math.cos(eh)


@pytest.mark.parametrize("position, ahead, left", [
    ("front", ">", "same"), ("back", "<", "same"), ("left", "beside", "+"), ("right", "beside", "-"),
    ("front_left", ">", "+"), ("front_right", ">", "-"), ("back_left", "<", "+"), ("back_right", "<", "-"),
])
def test_side_positions_are_on_the_right_lane_and_side(library, position, ahead, left):
    scenario = parse(_scene(f"ego car go_straight\n    car a at {position} go_straight", "road {\n    lanes >= 3\n}\n"))
    scene = bind(scenario, library)
    odr = read_opendrive(scene.map_path)
    ego, other = scene.agent("ego"), scene.agent("a")
    x, y = _relative(odr, ego.start, other.start)
    if ahead == ">":
        assert x > (ego.length + other.length) / 2
    elif ahead == "<":
        assert x < -(ego.length + other.length) / 2
    else:
        assert abs(x) < 1.0
    if left == "same":
        assert abs(y) < 0.5 and other.start.lane == ego.start.lane
    else:
        assert 2.5 < (y if left == "+" else -y) < 4.5  # one lane width over


def test_a_neighbour_lane_beside_an_ego_crossing_the_junction(library):
    """Each lane has its own connecting road: the ego keeps a lane free beside it and turns from its own lane."""
    scene = parse('scenario "t"\nroad {\n    at junction\n}\nstage s {\n    ego car go_straight\n'
                  '    car c at left go_straight\n}\n')
    bound = bind(scene, library)
    ego, c = bound.agent("ego"), bound.agent("c")
    assert c.start.road == ego.start.road and abs(c.start.lane) == abs(ego.start.lane) - 1 >= 1  # nearer the centre
    assert ego.movement == "straight" and ego.route[1].road != c.route[1].road


@pytest.mark.parametrize("position, side", [("road_of_left_turn", "left"), ("road_of_right_turn", "right"),
                                            ("road_of_straight", "straight")])
def test_junction_positions_stand_on_the_road_entering_from_that_side(library, position, side):
    scenario = parse(_scene(f"ego car go_straight\n    car a at {position} go_straight", "road {\n    at junction\n}\n"))
    scene = bind(scenario, library)
    index = next(m for m in library if m.path == scene.map_path)
    approach = index.by_id[scene.approach]
    entering = index.by_id[approach.entering[side][0]]
    a = scene.agent("a")
    assert a.start.road == entering.road
    assert (a.start.lane < 0) == (entering.direction == "forward")  # in the lanes that drive to the junction
    # the road entering from the left is where the ego's left turn leads
    assert entering.road in {t.to_road for t in approach.turns_to(side)}


def test_at_the_destination_is_where_the_ego_turn_leads(library):
    scenario = parse(_scene("ego car turn_left\n    car a at at_the_destination stop"))
    scene = bind(scenario, library)
    ego, a = scene.agent("ego"), scene.agent("a")
    assert a.start.road == ego.target_road == ego.route[-1].road


def test_near_the_crosswalk_is_on_the_sidewalk_by_the_crossing(library):
    scenario = parse(_scene("ego car go_straight\n    pedestrian p at near_the_crosswalk cross_the_road",
                            "road {\n    has crosswalk\n}\n"))
    scene = bind(scenario, library)
    odr = read_opendrive(scene.map_path)
    p = scene.agent("p")
    road = odr.roads[p.start.road]
    lane = road.section_at(p.start.s).lanes[p.start.lane]
    assert lane.type == "sidewalk"
    crossings = [o.s for o in road.objects if o.type == "crosswalk"]
    assert min(abs(p.start.s - s) for s in crossings) < 6.0
    x, _ = _relative(odr, scene.agent("ego").start, p.start)
    assert x > 20  # ahead of the ego, which has yet to reach it


# -- what agents do -------------------------------------------------------------------------------------

def _xosc(scenario_text: str, library) -> tuple[etree._Element, object]:
    scene = bind(parse(scenario_text), library)
    return etree.fromstring(emit(scene, "map.xodr")), scene


def _actions(root, name: str) -> list[etree._Element]:
    group = root.find(f".//ManeuverGroup[@name='{name}_group']")
    return list(group.iter("PrivateAction"))


@pytest.mark.parametrize("action", ["turn_left", "turn_right", "go_straight"])
def test_junction_movements_route_into_the_road_the_index_says(library, action):
    root, scene = _xosc(_scene(f"ego car {action}", "road {\n    at junction\n}\n"), library)
    index = next(m for m in library if m.path == scene.map_path)
    kind = {"turn_left": "left", "turn_right": "right", "go_straight": "straight"}[action]
    targets = {t.to_road for t in index.by_id[scene.approach].turns_to(kind)}
    waypoints = _actions(root, "ego")[0].findall(".//Waypoint/Position/LanePosition")
    assert waypoints[-1].get("roadId") in targets
    via = {t.via_road for t in index.by_id[scene.approach].turns_to(kind)}
    assert waypoints[1].get("roadId") in via  # through the junction's connecting road


@pytest.mark.parametrize("action, value", [("change_lane_to_left", "1"), ("change_lane_to_right", "-1")])
def test_lane_changes(library, action, value):
    root, scene = _xosc(_scene(f"ego car go_straight\n    car a at front {action}", "road {\n    lanes >= 2\n}\n"),
                        library)
    change = _actions(root, "a")[0].find(".//RelativeTargetLane")
    assert change.get("value") == value and change.get("entityRef") == "a"


def test_stop_and_block_the_ego_brake_to_zero(library):
    root, _ = _xosc(_scene("ego car go_straight\n    car a at front stop\n    car b at front_left block_the_ego",
                           "road {\n    lanes >= 2\n}\n"), library)
    for event in ("a_stop", "b_brakes"):  # b brakes once it is in the ego's lane
        speeds = [float(t.get("value")) for t in root.find(f".//Event[@name='{event}']").iter("AbsoluteTargetSpeed")]
        assert speeds == [0.0]
    block = root.find(".//Event[@name='b_block_the_ego']")
    assert block.find(".//RelativeTargetLane").get("value") == "-1"  # from the left lane into the ego's
    after = root.find(".//Event[@name='b_brakes']//StoryboardElementStateCondition")
    assert after.get("storyboardElementRef") == "b_block_the_ego" and after.get("state") == "completeState"


def test_cross_the_road_goes_to_the_far_side(library):
    _, scene = _xosc(_scene("ego car go_straight\n    pedestrian p at front_right cross_the_road"), library)
    p = scene.agent("p")
    assert (p.start.lane > 0) != (p.cross_to.lane > 0) and p.cross_to.s == p.start.s


def test_on_the_sidewalk_walks_along_its_sidewalk(library):
    _, scene = _xosc(_scene("ego car go_straight\n    pedestrian p at right on_the_sidewalk"), library)
    p = scene.agent("p")
    assert p.walk_to.lane == p.start.lane and abs(p.walk_to.s - p.start.s) > 10


def test_triggers_and_stages(library):
    root, scene = _xosc('scenario "t"\nstage one {\n    ego car go_straight\n    car a at front stop when ego within 12m\n'
                    '    car b at back stop after 2.5s\n}\nstage two {\n    car c at front_left block_the_ego\n}\n'
                    .replace("stage one {", 'road {\n    lanes >= 2\n}\nstage one {'), library)
    near = root.find(".//Event[@name='a_stop']//RelativeDistanceCondition")
    assert near.get("value") == "12.0" and near.get("entityRef") == "ego"
    delayed = root.find(".//Event[@name='b_stop']//Condition")
    assert delayed.get("delay") == "2.5"
    acts = root.findall(".//Act")
    assert [a.get("name") for a in acts] == ["one", "two", "following", "map_edge"]
    # the ego behind a, which stops when the ego is within 12 m, brakes once a has begun and it is near
    behind = root.find(".//Event[@name='ego_stops_behind_a']")
    assert behind is not None and behind.find(".//Condition[@name='ego_stops_behind_a_leader_near']") is not None
    follows = acts[1].find("StartTrigger//StoryboardElementStateCondition")
    assert follows.get("storyboardElementRef") == "one" and follows.get("state") == "completeState"
    appear = root.find(".//Event[@name='c_enters']//AddEntityAction//RelativeLanePosition")
    # one lane to the ego's left and ahead, as OpenSCENARIO counts: lane ids and the road's s, so both negative
    # on a left lane (id > 0), which the ego drives against s
    toward_s = 1 if scene.agent("ego").start.lane < 0 else -1
    assert appear.get("entityRef") == "ego" and int(appear.get("dLane")) == toward_s
    assert float(appear.get("ds")) * toward_s > 0
    assert root.find(".//Init//Private[@entityRef='c']") is None  # inactive until its stage adds it
    assert root.find(".//StopTrigger//SimulationTimeCondition") is not None


def test_intent_is_written_into_entity_properties(library):
    root, scene = _xosc(_scene("ego car turn_left\n    ambulance a at road_of_straight go_straight aggressive",
                               "road {\n    at junction\n}\n"), library)
    props = {p.get("name"): p.get("value") for p in root.find(".//ScenarioObject[@name='a']").iter("Property")}
    assert props["ttsgc:action"] == "go_straight" and props["ttsgc:position"] == "road_of_straight"
    assert props["ttsgc:movement"] == "straight" and props["ttsgc:target_road"] == scene.agent("a").target_road
    assert root.find(".//ScenarioObject[@name='a']/Vehicle").get("role") == "ambulance"


@pytest.mark.parametrize("path", example_scenarios(), ids=lambda p: p.stem)
def test_no_two_bodies_overlap_at_the_start(path, library):
    scene = bind(parse_file(path), library)
    odr = read_opendrive(scene.map_path)
    placed = [a for a in scene.agents if a.start is not None]
    for i, a in enumerate(placed):
        for b in placed[i + 1:]:
            pa = odr.roads[a.start.road].lane_point(a.start.s, a.start.lane)
            pb = odr.roads[b.start.road].lane_point(b.start.s, b.start.lane)
            gap = math.hypot(pa.x - pb.x, pa.y - pb.y)
            lateral = (a.width + b.width) / 2
            assert gap >= min((a.length + b.length) / 2, lateral), (a.name, b.name, gap)


def test_every_start_position_exists_on_the_map(library):
    for path in example_scenarios():
        scene = bind(parse_file(path), library)
        odr = read_opendrive(scene.map_path)
        for a in scene.agents:
            for pos in [a.start, a.cross_to, a.walk_to, *a.route]:
                if pos is not None:
                    road = odr.roads[pos.road]
                    assert 0 <= pos.s <= road.length and pos.lane in road.section_at(pos.s).lanes, (path.name, a.name)


def test_seed_spreads_scenes_over_equally_good_roads(library):
    scenario = parse_file(EXAMPLES / "intersection.tsg")
    roads = {(bind(scenario, library, seed=seed).map_name, bind(scenario, library, seed=seed).approach)
             for seed in range(6)}
    assert len(roads) >= 3


# -- the command ----------------------------------------------------------------------------------------

def test_compile_writes_the_map_beside_the_output_and_runs_anywhere(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    out = tmp_path / "deep" / "scene.xosc"
    assert main(["compile", str(EXAMPLES / "stop_sign_right_turn.tsg"), "-o", str(out), "--no-simulate"]) == 0
    logic = etree.parse(str(out)).find(".//LogicFile").get("filepath")
    assert (out.parent / logic).is_file() and "/" not in logic


def test_compile_explain_prints_the_ranking_table(tmp_path, capsys):
    assert main(["compile", str(EXAMPLES / "emergency.tsg"), "-o", str(tmp_path / "e.xosc"), "--explain"]) == 0
    out = capsys.readouterr().out
    assert "road_of_left_turn (po1)" in out and "total" in out and "8/8" in out


def test_no_road_is_its_own_exit_code_and_leaves_outputs_alone(tmp_path, capsys):
    src = tmp_path / "x.tsg"
    src.write_text(_scene("ego car go_straight", "road {\n    lanes >= 6\n}\n"))
    out = tmp_path / "x.xosc"
    out.write_text("previous")
    assert main(["compile", str(src), "-o", str(out), "--synthesize", "never"]) == 4
    assert "none meets 'lanes >= 6'" in capsys.readouterr().err
    assert out.read_text() == "previous" and sorted(p.name for p in tmp_path.iterdir()) == ["x.tsg", "x.xosc"]


def test_requirement_no_candidate_meets_is_named(tmp_path, capsys):
    src = tmp_path / "x.tsg"
    src.write_text(_scene("ego car go_straight\n    truck t at front_right on shoulder stop",
                          "road {\n    not at junction\n    has solid_single_white\n}\n"))
    assert main(["compile", str(src), "-o", str(tmp_path / "x.xosc"), "--synthesize", "never"]) == 4
    assert "none meets 'shoulder (t)'" in capsys.readouterr().err


def test_osc_version_flag(tmp_path):
    out = tmp_path / "v.xosc"
    assert main(["compile", str(EXAMPLES / "cut_off.tsg"), "-o", str(out), "--osc-version", "1.0"]) == 0
    assert etree.parse(str(out)).find("FileHeader").get("revMinor") == "0"


def test_a_later_walker_beside_the_ego_with_a_trigger_is_written_without_an_empty_event(tmp_path):
    """It enters beside the ego and has nothing to do until its way across is known; the event that would hold
    its crossing was empty, which scenariogeneration refuses (an internal error, exit 1)."""
    scene = tmp_path / "s.tsg"
    scene.write_text('scenario "x"\nstage one {\n    ego car go_straight\n}\nstage two {\n'
                     '    pedestrian p1 at front_right cross_the_road when ego within 20m\n}\n')
    assert main(["compile", str(scene), "-o", str(tmp_path / "s.xosc"), "--no-simulate"]) == 0
    events = etree.parse(str(tmp_path / "s.xosc")).findall(".//Event")
    assert events and all(e.find("Action") is not None for e in events)


def test_later_agents_beside_the_ego_queue_behind_the_first_instead_of_overlapping(library):
    """Three later vehicles 'at left' all appeared abreast of the ego at ds 0, on top of one another."""
    _, scene = _xosc('scenario "t"\nroad {\n    lanes >= 2\n}\nstage one {\n    ego car go_straight\n}\n'
                     'stage two {\n    car c1 at left go_straight\n    car c2 at left go_straight behind c1\n'
                     '    bus b1 at left go_straight\n}\n', library)
    c1, c2, b1 = (scene.agent(n) for n in ("c1", "c2", "b1"))
    assert c1.appear.ds == 0 and c2.appear.ds < 0 and b1.appear.ds < c2.appear.ds
    assert c1.appear.ds - c2.appear.ds >= (c1.length + c2.length) / 2
    assert c2.appear.ds - b1.appear.ds >= (c2.length + b1.length) / 2


def test_an_ego_that_leaves_the_road_before_its_later_stage_is_a_verdict_not_a_crash(tmp_path):
    """A later stage's speed change for a vehicle SUMO has already taken off the network at its route's end is no
    internal error: the verdict says it left the scene, and the next road is tried."""
    src = tmp_path / "s.tsg"
    src.write_text('scenario "walkers at a mid-block zebra"\nroad {\n    lanes >= 2\n    not at junction\n'
                   '    has continental_crosswalk\n}\nstage first {\n    ego car go_straight\n'
                   '    pedestrian p1 at near_the_crosswalk cross_the_road\n'
                   '    pedestrian p2 at near_the_crosswalk cross_the_road\n'
                   '    pedestrian p3 at right on_the_sidewalk\n}\n'
                   'stage second {\n    ego car stop\n}\n')
    assert main(["compile", str(src), "-o", str(tmp_path / "s.xosc")]) in (0, 5)
