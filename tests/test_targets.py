"""Targets and lint: the carla target writes the 1.0 that CARLA ScenarioRunner reads, and `ttsgc lint` names
every element a player's documented coverage does not hold, with its line."""

from __future__ import annotations

import re
from importlib import resources
from pathlib import Path

import pytest
import xmlschema
from lxml import etree

from conftest import EXAMPLES, example_scenarios
from ttsgc.cli import main
from ttsgc.errors import ExitCode
from ttsgc.language import parse, parse_file
from ttsgc.pipeline import compile_scenario
from ttsgc.roads import load_library
from ttsgc.targets import carla
from ttsgc.targets.coverage import coverage, errors, lint_file

UNSUPPORTED = int(ExitCode.UNSUPPORTED_BY_TARGET)


@pytest.fixture(scope="module")
def library():
    return load_library()


@pytest.fixture(scope="module")
def schema_1_0():
    path = resources.files("qc_openscenario") / "schema" / "1.0.0" / "OpenSCENARIO.xsd"
    return xmlschema.XMLSchema(str(path))


@pytest.fixture(scope="module")
def carla_files(library, tmp_path_factory):
    """Every example, compiled for carla onto the built-in library (proving is tested elsewhere)."""
    folder = tmp_path_factory.mktemp("carla")
    files = {}
    for path in example_scenarios():
        out = folder / f"{path.stem}.xosc"
        compiled = compile_scenario(parse_file(path), out, library=library, target="carla")
        out.write_bytes(compiled.xosc)
        files[path.stem] = (out, compiled)
    return files


def test_every_example_for_carla_is_1_0_xsd_valid_and_lints_clean(carla_files, schema_1_0):
    for stem, (out, _) in carla_files.items():
        schema_1_0.validate(str(out))  # raises, naming the element, on any XSD error
        assert etree.parse(str(out)).find("FileHeader").get("revMinor") == "0"
        assert errors(lint_file(out, "carla")) == [], stem
        assert main(["lint", "--target", "carla", str(out)]) == 0


def test_carla_entities_are_blueprints_and_the_ego_is_the_hero(carla_files):
    out, compiled = carla_files["intersection"]
    root = etree.parse(str(out)).getroot()
    objects = {o.get("name"): o for o in root.iter("ScenarioObject")}
    assert "hero" in objects and "ego" not in objects
    for agent in compiled.scene.agents:
        body = objects["hero" if agent.is_ego else agent.name]
        kind = body.find("Pedestrian") if agent.type == "pedestrian" else body.find("Vehicle")
        expected = carla.blueprint(agent.type)
        assert kind.get("model" if agent.type == "pedestrian" else "name") == expected
        assert expected.startswith("walker." if agent.type == "pedestrian" else "vehicle.")
        role = [p.get("value") for p in kind.iter("Property") if p.get("name") == "type"]
        assert role == ["ego_vehicle" if agent.is_ego else "simulation"]
    refs = {e.get("entityRef") for e in root.iter() if e.get("entityRef") is not None}
    assert "ego" not in refs and "hero" in refs


def test_an_agent_called_hero_keeps_its_name_and_the_ego_keeps_its_own(library):
    scenario = parse('scenario "h"\nstage s {\n    ego car go_straight\n    car hero at front go_straight\n}\n')
    root = etree.fromstring(compile_scenario(scenario, Path("h.xosc"), library=library, target="carla").xosc)
    roles = {o.get("name"): [p.get("value") for p in o.iter("Property") if p.get("name") == "type"]
             for o in root.iter("ScenarioObject")}
    assert roles == {"ego": ["ego_vehicle"], "hero": ["simulation"]}


def test_carla_emergency_vehicles_get_their_blueprints(carla_files):
    names = {v.get("name") for out, _ in carla_files.values() for v in etree.parse(str(out)).iter("Vehicle")}
    assert {"vehicle.ford.ambulance", "vehicle.dodge.charger_police", "vehicle.carlamotors.firetruck"} <= names


def test_carla_criteria_and_weather(carla_files):
    out, compiled = carla_files["rainy_night_cut_in"]
    root = etree.parse(str(out)).getroot()
    stop_groups = root.findall("Storyboard/StopTrigger/ConditionGroup")
    criteria = [c.get("name") for c in stop_groups[-1].iter("Condition")]
    assert criteria[0] == "criteria_CollisionTest" and all(c.startswith("criteria_") for c in criteria)
    assert ("criteria_RunningRedLightTest" in criteria) == ("traffic_light" in compiled.scene.approach_signals)
    assert not any(c.get("name", "").startswith("criteria_") for c in stop_groups[0].iter("Condition"))
    assert root.find("Storyboard/Init/Actions/GlobalAction/EnvironmentAction") is not None
    assert not list(root.find("Storyboard/Story").iter("EnvironmentAction"))
    rain = root.find(".//Precipitation")
    assert rain.get("precipitationType") == "rain" and 0 < float(rain.get("intensity")) <= 1
    dynamics = root.find(".//LaneChangeActionDynamics")
    assert (dynamics.get("dynamicsShape"), dynamics.get("dynamicsDimension")) == ("linear", "distance")
    assert float(dynamics.get("value")) >= carla.MIN_LANE_CHANGE_M
    assert not [o for o in root.iter("Orientation") if o.getparent().tag == "LanePosition"]


def test_criteria_follow_the_signals_of_the_egos_approach(carla_files):
    seen = set()
    for out, compiled in carla_files.values():
        group = etree.parse(str(out)).findall("Storyboard/StopTrigger/ConditionGroup")[-1]
        names = {c.get("name") for c in group.iter("Condition")}
        signals = set(compiled.scene.approach_signals)
        assert ("criteria_RunningStopTest" in names) == ("stop" in signals), out.name
        assert ("criteria_RunningRedLightTest" in names) == ("traffic_light" in signals), out.name
        assert "criteria_CollisionTest" in names
        seen |= signals
    assert {"stop", "traffic_light"} <= seen  # the examples exercise both


def test_a_carla_town_is_named_in_logicfile(shared, tmp_path):
    out = tmp_path / "i.xosc"
    assert main(["compile", str(EXAMPLES / "cut_off.tsg"), "-o", str(out), "--target", "carla", "--maps",
                 str(shared / "maps" / "carla"), "--no-simulate"]) == 0
    logic = etree.parse(str(out)).find("RoadNetwork/LogicFile").get("filepath")
    assert re.fullmatch(r"Town\d\d(HD)?", logic)


def test_a_map_that_is_no_carla_town_keeps_its_file(carla_files):
    out, compiled = carla_files["cut_off"]
    assert etree.parse(str(out)).find("RoadNetwork/LogicFile").get("filepath") == compiled.map_name
    assert carla.town("/maps/Town10HD.xodr") == "Town10HD" and carla.town("town_row.xodr") is None


def test_compile_for_carla_is_proven_on_its_generic_file(tmp_path, capsys):
    out = tmp_path / "c.xosc"
    assert main(["compile", str(EXAMPLES / "cut_off.tsg"), "-o", str(out), "--target", "carla"]) == 0
    assert "proven in" in capsys.readouterr().out
    assert etree.parse(str(out)).find(".//ScenarioObject").get("name") == "hero"


# -- what the carla target cannot express: errors naming it, nothing written --------------------------------

def test_snow_cannot_be_written_for_carla(tmp_path, capsys):
    src = tmp_path / "s.tsg"
    src.write_text('scenario "snowy"\nweather snow noon\nstage s {\n    ego car go_straight\n}\n')
    out = tmp_path / "s.xosc"
    assert main(["compile", str(src), "-o", str(out), "--target", "carla"]) == UNSUPPORTED
    err = capsys.readouterr().err
    assert "weather snow" in err and "CARLA" in err
    assert not out.exists() and list(tmp_path.iterdir()) == [src]


def test_carla_refuses_another_osc_version(tmp_path, capsys):
    out = tmp_path / "v.xosc"
    assert main(["compile", str(EXAMPLES / "cut_off.tsg"), "-o", str(out), "--target", "carla",
                 "--osc-version", "1.2"]) == UNSUPPORTED
    assert "--osc-version 1.2" in capsys.readouterr().err and not out.exists()


def test_what_the_adapter_leaves_unsupported_is_an_error_naming_it(library, monkeypatch):
    """A construct the carla layer does not turn into ScenarioRunner's form (here, a lane change it is told to
    leave over a time) is refused before writing, naming the element and its line."""
    from ttsgc.targets import TargetError

    monkeypatch.setattr(carla, "_lane_changes", lambda root, scene: None)
    with pytest.raises(TargetError, match=r'line \d+: LaneChangeActionDynamics dynamicsDimension="time"'):
        compile_scenario(parse_file(EXAMPLES / "rainy_night_cut_in.tsg"), Path("x.xosc"), library=library,
                         target="carla")


def test_carla_acts_carry_the_scenes_stop_condition(carla_files):
    """ScenarioRunner never evaluates the Storyboard's StopTrigger: each Act's StopTrigger must end the run."""
    for stem, (out, _) in carla_files.items():
        root = etree.parse(str(out)).getroot()
        scene_stop = [c for c in root.find("Storyboard/StopTrigger").iter("Condition")
                      if not c.get("name").startswith("criteria_")]
        assert scene_stop, stem
        for act in root.iter("Act"):
            copied = [c for c in act.find("StopTrigger").iter("Condition")]
            assert len(copied) == len(scene_stop), (stem, act.get("name"))
            for mine, theirs in zip(copied, scene_stop):
                assert mine.get("name") == f"{theirs.get('name')}_{act.get('name')}"
                assert etree.tostring(mine[0], with_tail=False).split() == \
                    etree.tostring(theirs[0], with_tail=False).split()


def test_a_scene_stop_group_of_several_conditions_is_refused_for_carla():
    """An Act's condition group is any-of in ScenarioRunner, so an all-of stop group cannot be carried over."""
    root = etree.fromstring(b"<OpenSCENARIO><Storyboard><Story><Act name='a'><StopTrigger/></Act></Story>"
                            b"<StopTrigger><ConditionGroup><Condition name='x'/><Condition name='y'/></ConditionGroup>"
                            b"</StopTrigger></Storyboard></OpenSCENARIO>")
    problems = carla._stop_in_acts(root)
    assert problems and "ConditionGroup of 2 conditions" in problems[0]
    assert root.find(".//Act/StopTrigger/ConditionGroup") is None


def test_carla_files_drop_the_map_edge_exits(carla_files):
    """EndOfRoadCondition fails its trigger in ScenarioRunner; the events deleting a vehicle at its road's end go,
    and nothing empty is left behind."""
    for stem, (out, _) in carla_files.items():
        root = etree.parse(str(out)).getroot()
        assert not list(root.iter("EndOfRoadCondition")) and not list(root.iter("DeleteEntityAction")), stem
        for parent, child in (("Act", "ManeuverGroup"), ("ManeuverGroup", "Maneuver"), ("Maneuver", "Event")):
            assert all(e.find(child) is not None for e in root.iter(parent)), (stem, parent)
        assert root.find("Storyboard/Story/Act") is not None


# -- lint: one test per construct a player does not support ---------------------------------------------------

def _carla_base(carla_files) -> bytes:
    return carla_files["rainy_night_cut_in"][0].read_bytes()


def _mutate(data: bytes, change) -> bytes:
    root = etree.fromstring(data, etree.XMLParser(remove_blank_text=True))
    change(root)
    return etree.tostring(root, pretty_print=True)


def _state(root, state):
    condition = etree.SubElement(root.find(".//Event/StartTrigger/ConditionGroup"), "Condition", name="x",
                                 delay="0", conditionEdge="none")
    etree.SubElement(etree.SubElement(condition, "ByValueCondition"), "StoryboardElementStateCondition",
                     storyboardElementType="act", storyboardElementRef="main", state=state)


def _story_weather(root):
    action = etree.SubElement(root.find(".//Event"), "Action", name="w")
    action.append(etree.fromstring(etree.tostring(root.find(".//Init/Actions/GlobalAction"))))


def _absolute_lane(root):
    target = root.find(".//LaneChangeTarget")
    target.remove(target[0])
    etree.SubElement(target, "AbsoluteTargetLane", value="-2")


def _trajectory(shape: str, timed: bool):
    def change(root):
        action = etree.SubElement(root.find(".//Event"), "Action", name="t")
        follow = etree.SubElement(etree.SubElement(etree.SubElement(action, "PrivateAction"), "RoutingAction"),
                                  "FollowTrajectoryAction")
        trajectory = etree.SubElement(follow, "Trajectory", name="p", closed="false")
        shape_el = etree.SubElement(etree.SubElement(trajectory, "Shape"), shape)
        if shape == "Clothoid":
            shape_el.attrib.update({"curvature": "0", "curvatureDot": "0", "length": "10"})
        reference = etree.SubElement(follow, "TimeReference")
        if timed:
            etree.SubElement(reference, "Timing", domainAbsoluteRelative="absolute", scale="1", offset="0")
        else:
            etree.SubElement(reference, "None")
        etree.SubElement(follow, "TrajectoryFollowingMode", followingMode="position")
    return change


def _revision(root):
    root.find("FileHeader").set("revMinor", "2")


def _snow(root):
    root.find(".//Precipitation").set("precipitationType", "snow")


def _swarm(root):
    action = etree.SubElement(root.find(".//Event"), "Action", name="s")
    etree.SubElement(etree.SubElement(etree.SubElement(action, "GlobalAction"), "TrafficAction"), "TrafficSwarmAction")


def _variables(root):
    declarations = etree.Element("VariableDeclarations")
    etree.SubElement(declarations, "VariableDeclaration", name="v", variableType="double", value="0")
    root.insert(1, declarations)


def _user_condition(root):
    condition = etree.SubElement(root.find(".//Event/StartTrigger/ConditionGroup"), "Condition", name="u",
                                 delay="0", conditionEdge="none")
    etree.SubElement(etree.SubElement(condition, "ByValueCondition"), "UserDefinedValueCondition", name="k",
                     value="1", rule="equalTo")


def _story_add_entity(root):
    action = etree.SubElement(root.find(".//Event"), "Action", name="a")
    entity = etree.SubElement(etree.SubElement(action, "GlobalAction"), "EntityAction", entityRef="c1")
    position = etree.SubElement(etree.SubElement(entity, "AddEntityAction"), "Position")
    etree.SubElement(position, "RelativeLanePosition", entityRef="hero", ds="20", offset="0", dLane="0")


def _end_of_road(root):
    condition = etree.SubElement(root.find(".//Event/StartTrigger/ConditionGroup"), "Condition", name="e",
                                 delay="0", conditionEdge="none")
    by_entity = etree.SubElement(condition, "ByEntityCondition")
    etree.SubElement(etree.SubElement(by_entity, "TriggeringEntities", triggeringEntitiesRule="any"), "EntityRef",
                     entityRef="hero")
    etree.SubElement(etree.SubElement(by_entity, "EntityCondition"), "EndOfRoadCondition", duration="0")


def _time_gap(root):
    action = etree.SubElement(root.find(".//Event"), "Action", name="g")
    longitudinal = etree.SubElement(etree.SubElement(action, "PrivateAction"), "LongitudinalAction")
    etree.SubElement(longitudinal, "LongitudinalDistanceAction", entityRef="c1", freespace="false",
                     continuous="true", timeGap="2")


def _lane_change_in_init(root):
    private = root.find(".//Init/Actions/Private")
    action = etree.SubElement(private, "PrivateAction")
    action.append(etree.fromstring(etree.tostring(root.find(".//LaneChangeAction").getparent())))


@pytest.mark.parametrize("change, named", [
    (lambda root: _state(root, "runningState"), 'StoryboardElementStateCondition state="runningState"'),
    (lambda root: _state(root, "standbyState"), 'StoryboardElementStateCondition state="standbyState"'),
    (_absolute_lane, "AbsoluteTargetLane"),
    (lambda root: root.find(".//LaneChangeActionDynamics").set("dynamicsDimension", "time"),
     'LaneChangeActionDynamics dynamicsDimension="time"'),
    (_story_add_entity, "AddEntityAction"),
    (_end_of_road, "EndOfRoadCondition"),
    (_time_gap, 'LongitudinalDistanceAction timeGap="2"'),
    (_lane_change_in_init, "LaneChangeAction"),
    (_trajectory("Polyline", True), "Timing"),
    (_trajectory("Clothoid", False), "Clothoid"),
    (_revision, 'FileHeader revMinor="2"'),
    (_snow, 'Precipitation precipitationType="snow"'),
    (_swarm, "TrafficSwarmAction"),
    (_user_condition, "UserDefinedValueCondition"),
    (_variables, "VariableDeclarations"),
], ids=["runningState", "standbyState", "absolute-lane", "timed-lane-change", "story-add-entity", "end-of-road",
        "time-gap", "lane-change-in-init",
        "timed-trajectory", "clothoid", "osc-1.2", "snow", "traffic-swarm", "user-condition", "variables"])
def test_carla_lint_names_each_unsupported_construct(carla_files, tmp_path, capsys, change, named):
    path = tmp_path / "m.xosc"
    path.write_bytes(_mutate(_carla_base(carla_files), change))
    assert main(["lint", "--target", "carla", str(path)]) == UNSUPPORTED
    lines = [line for line in capsys.readouterr().out.splitlines() if named in line]
    assert lines, named
    line = int(lines[0].split(":")[1])
    assert named.split()[0] in path.read_text().splitlines()[line - 1]  # the line is the element's own
    assert "error" in lines[0] and "CARLA ScenarioRunner" in lines[0]


def test_esmini_lint_cites_its_coverage_list(tmp_path, capsys):
    source = (EXAMPLES / "golden" / "cut_off.xosc").read_bytes()
    assert main(["lint", "--target", "esmini", str(EXAMPLES / "golden" / "cut_off.xosc")]) == 0

    def time_of_day(root):
        condition = etree.SubElement(root.find(".//Event/StartTrigger/ConditionGroup"), "Condition", name="d",
                                     delay="0", conditionEdge="none")
        etree.SubElement(etree.SubElement(condition, "ByValueCondition"), "TimeOfDayCondition",
                         dateTime="2026-01-01T12:00:00", rule="greaterThan")
    path = tmp_path / "t.xosc"
    path.write_bytes(_mutate(source, time_of_day))
    capsys.readouterr()
    assert main(["lint", "--target", "esmini", str(path)]) == UNSUPPORTED
    out = capsys.readouterr().out
    assert "TimeOfDayCondition: not supported by esmini" in out and "osc_coverage.txt line" in out


def test_lint_of_a_file_that_is_not_xml_is_a_bad_input(tmp_path, capsys):
    path = tmp_path / "bad.xosc"
    path.write_text("<OpenSCENARIO>")
    assert main(["lint", "--target", "carla", str(path)]) == int(ExitCode.INVALID_SCENARIO)
    assert f"{path}:1" in capsys.readouterr().err


def test_every_esmini_rule_cites_a_line_of_osc_coverage_that_says_so(shared):
    lines = (shared / "tools" / "esmini" / "osc_coverage.txt").read_text().splitlines()
    for rule in coverage("esmini").rules:
        cited = re.match(r"osc_coverage\.txt lines? ([\d ,\-]+):", rule.source)
        assert cited, rule.source
        numbers = []
        for part in cited.group(1).replace(" ", "").strip(",").split(","):
            first, _, last = part.partition("-")
            numbers += range(int(first), int(last or first) + 1)
        for n in numbers:
            words = lines[n - 1].split()
            assert words and words[0] in rule.source, (n, lines[n - 1], rule.source)
            assert re.search(r"\b(No|Yes|Partly|Incomplete|yes)\b", lines[n - 1]), lines[n - 1]


def test_every_carla_rule_says_where_it_comes_from():
    data = coverage("carla").data
    for rule in coverage("carla").rules:
        assert re.match(r"\[(support|parser|config|scenario|atomics)\]", rule.source), rule.source
        assert rule.certainty == "checked", rule.elements
    for table in ("criteria", "towns", "late_entry"):
        assert data[table]["certainty"] == "checked", table


def test_carla_output_is_deterministic(library):
    scenario = parse_file(EXAMPLES / "rainy_night_cut_in.tsg")
    first = compile_scenario(scenario, Path("a.xosc"), library=library, target="carla").xosc
    assert compile_scenario(scenario, Path("b.xosc"), library=library, target="carla").xosc == first


def test_the_esmini_target_is_the_generic_file_held_against_its_coverage(library):
    scenario = parse_file(EXAMPLES / "two_wheels.tsg")
    generic = compile_scenario(scenario, Path("g.xosc"), library=library).xosc
    assert compile_scenario(scenario, Path("g.xosc"), library=library, target="esmini").xosc == generic
    assert errors(lint_file_bytes(generic, "esmini")) == []


def lint_file_bytes(data: bytes, target: str):
    from ttsgc.targets.coverage import lint_tree

    return lint_tree(etree.fromstring(data), target)


@pytest.mark.parametrize("change, named", [
    (lambda root: [e.set("priority", "overwrite") for e in root.iter("Event")], 'Event priority="overwrite"'),
    (_story_weather, "EnvironmentAction"),
    (lambda root: root.find(".//LaneChangeActionDynamics").set("dynamicsShape", "sinusoidal"),
     'LaneChangeActionDynamics dynamicsShape="sinusoidal"'),
], ids=["overwrite-priority", "story-weather", "sinusoidal-lane-change"])
def test_carla_lint_warns_of_what_scenario_runner_reads_its_own_way(carla_files, tmp_path, capsys, change, named):
    path = tmp_path / "w.xosc"
    path.write_bytes(_mutate(_carla_base(carla_files), change))
    assert main(["lint", "--target", "carla", str(path), "--all"]) == 0
    lines = [line for line in capsys.readouterr().out.splitlines() if named in line]
    assert lines and "warning" in lines[0], named


def test_carla_lint_notes_that_condition_edges_are_not_read(carla_files, tmp_path, capsys):
    path = tmp_path / "e.xosc"
    path.write_bytes(_carla_base(carla_files))
    assert main(["lint", "--target", "carla", str(path), "--all"]) == 0
    lines = [line for line in capsys.readouterr().out.splitlines() if 'conditionEdge="rising"' in line]
    assert lines and all("error" not in line and "warning" not in line for line in lines)
    assert "never its conditionEdge" in lines[0]
