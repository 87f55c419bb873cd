"""The SUMO player and the judge: every example proves itself, each action's check passes and fails when it
should, collisions are reported, unsupported content is named, the commands' exit codes."""

from __future__ import annotations

import json
import math

import pytest
from lxml import etree

from conftest import compiled_example as _compiled, edit_xosc as _edit
from conftest import EXAMPLES, example_scenarios
from ttsgc.cli import main
from ttsgc.language import parse_file
from ttsgc.pipeline import compile_and_prove
from ttsgc.simulate.validate import validate


def simulate(path):
    return validate(path, "sumo")




def _result(report, name):
    return next(a for a in report.agents if a.name == name)


@pytest.mark.parametrize("path", example_scenarios(), ids=lambda p: p.stem)
def test_every_example_proves_itself_in_sumo(path, tmp_path):
    """As `ttsgc compile` proves it: on its best-ranked road, else on the next ones (three roads in all)."""
    _, report = compile_and_prove(parse_file(path), tmp_path / f"{path.stem}.xosc", log=lambda m: None)
    assert report.ok, report.table()
    assert not report.unsupported and not report.problems and report.players == ["sumo"]


def test_simulation_is_deterministic(tmp_path):
    scene = _compiled("intersection", tmp_path)
    first, second = simulate(scene), simulate(scene)
    assert first.model_dump() == second.model_dump()


# -- each action: it passes, and an edited file fails it ------------------------------------------------

def _last_waypoint(root, name):
    return root.find(f".//ManeuverGroup[@name='{name}_group']//Route").findall(".//LanePosition")[-1]


def test_turn_left_fails_when_the_car_goes_straight_instead(tmp_path):
    scene = _compiled("left_turn_oncoming", tmp_path)
    assert _result(simulate(scene), "ego").achieved
    # send the ego where the oncoming cars come from: straight across instead of left
    def straight(root):
        oncoming = _last_waypoint(root, "c1")
        road_ego = root.find(".//Private[@entityRef='ego']//LanePosition").get("roadId")
        target = _last_waypoint(root, "ego")
        target.set("roadId", root.find(".//Private[@entityRef='c1']//LanePosition").get("roadId"))
        target.set("laneId", str(-int(root.find(".//Private[@entityRef='c1']//LanePosition").get("laneId"))))
        assert road_ego != target.get("roadId") and oncoming is not None
        for waypoint in root.find(".//ManeuverGroup[@name='ego_group']//Route").findall("Waypoint")[1:-1]:
            waypoint.getparent().remove(waypoint)
    result = _result(simulate(_edit(scene, straight)), "ego")
    assert not result.achieved and "where a left movement leads" in result.reason


def test_lane_change_and_its_failure(tmp_path):
    scene = _compiled("cut_off", tmp_path)
    assert "changed 1 lane(s) to the right" in _result(simulate(scene), "c1").reason
    def no_change(root):  # the same event, now changing no lane (the file stays valid)
        root.find(".//Event[@name='c1_change_lane_to_right']//RelativeTargetLane").set("value", "0")
    result = _result(simulate(_edit(scene, no_change)), "c1")
    assert not result.achieved and "did not change to the right" in result.reason


def test_stop_and_its_failure(tmp_path):
    scene = _compiled("yield_sudden_stop", tmp_path)
    assert _result(simulate(scene), "c1").achieved
    def keep_going(root):
        for target in root.find(".//Event[@name='c1_stop']").iter("AbsoluteTargetSpeed"):
            target.set("value", "6.0")
    result = _result(simulate(_edit(scene, keep_going)), "c1")
    assert not result.achieved and "never stood still" in result.reason


def test_block_the_ego_and_its_failure(tmp_path):
    scene = _compiled("blocking", tmp_path)
    assert "stopped in the ego's path" in _result(simulate(scene), "c1").reason
    def drive_off(root):
        for target in root.find(".//Event[@name='c1_block_the_ego']").iter("AbsoluteTargetSpeed"):
            target.set("value", "15.0")
    assert not _result(simulate(_edit(scene, drive_off)), "c1").achieved


def test_a_blocker_standing_beyond_another_in_the_egos_path_heads_the_queue_the_ego_stopped_behind():
    """'Boxed in': the ego (a braking player's) stops behind the nearest blocker; one that stands on beyond it,
    in line, blocks too. One standing off the line, far down the road, or with nobody between, does not."""
    from ttsgc.simulate.judge import _heads_a_queue
    from ttsgc.simulate.trace import Sample
    ego = Sample(t=9.0, x=0.0, y=0.0, h=0.0, speed=0.0)
    near = Sample(t=9.0, x=7.0, y=0.1, h=0.0, speed=0.0)
    assert _heads_a_queue(Sample(t=9.0, x=50.0, y=-0.2, h=0.0, speed=0.0), ego, [near])
    assert not _heads_a_queue(Sample(t=9.0, x=50.0, y=3.5, h=0.0, speed=0.0), ego, [near])  # the next lane
    assert not _heads_a_queue(Sample(t=9.0, x=200.0, y=0.0, h=0.0, speed=0.0), ego, [near])  # far beyond
    assert not _heads_a_queue(Sample(t=9.0, x=50.0, y=0.0, h=0.0, speed=0.0), ego, [])  # nobody between
    moving = Sample(t=9.0, x=0.0, y=0.0, h=0.0, speed=5.0)
    assert not _heads_a_queue(Sample(t=9.0, x=50.0, y=0.0, h=0.0, speed=0.0), moving, [near])  # stopped for none


def test_cross_the_road_and_its_failure(tmp_path):
    scene = _compiled("crushing", tmp_path)
    assert "crossed road" in _result(simulate(scene), "p1").reason
    def stay(root):
        start = root.find(".//Private[@entityRef='p1']//LanePosition")
        target = root.find(".//Event[@name='p1_cross_the_road']//Polyline").findall(".//LanePosition")[-1]
        target.set("laneId", start.get("laneId"))
    result = _result(simulate(_edit(scene, stay)), "p1")
    assert not result.achieved and "stayed on the" in result.reason


def test_on_the_sidewalk_and_its_failure(tmp_path):
    scene = _compiled("daily_traffic", tmp_path)
    assert "along the sidewalk" in _result(simulate(scene), "p1").reason
    def into_the_road(root):
        for target in root.find(".//Event[@name='p1_on_the_sidewalk']//Polyline").findall(".//LanePosition")[1:]:
            target.set("laneId", "-1" if int(target.get("laneId")) < 0 else "1")
    result = _result(simulate(_edit(scene, into_the_road)), "p1")
    assert not result.achieved and "straying" in result.reason


def test_go_straight_through_a_junction_and_its_failure(tmp_path):
    scene = _compiled("emergency", tmp_path)
    assert "went straight" in _result(simulate(scene), "a1").reason
    def turn_instead(root):  # into the side road the police car comes from, leaving the junction
        side_road = root.find(".//Private[@entityRef='po1']//LanePosition").get("roadId")
        target = _last_waypoint(root, "a1")
        target.set("roadId", side_road)
        target.set("laneId", "-1")
        for waypoint in root.find(".//ManeuverGroup[@name='a1_group']//Route").findall("Waypoint")[1:-1]:
            waypoint.getparent().remove(waypoint)
    result = _result(simulate(_edit(scene, turn_instead)), "a1")
    assert not result.achieved and "where a straight movement leads" in result.reason


def test_a_spawn_on_a_lane_that_does_not_exist_fails(tmp_path):
    scene = _compiled("cut_off", tmp_path)
    def bad_lane(root):
        root.find(".//Private[@entityRef='c2']//LanePosition").set("laneId", "-9")
    report = simulate(_edit(scene, bad_lane))
    result = _result(report, "c2")
    assert not result.achieved and "never appeared" in result.reason
    assert any("road" in p and "no lane -9" in p for p in report.problems)


# -- collisions, unsupported content, criticality --------------------------------------------------------

def test_a_normal_crossing_is_no_crash_the_ego_slows_for_the_walker(tmp_path):
    report = simulate(_compiled("intersection", tmp_path))
    assert report.ok and not report.collisions, report.table()
    ego = report.verdicts[0]
    assert ego.min_distance_to_ego is not None and ego.min_distance_to_ego > 0


def test_unsupported_content_is_reported_by_name(tmp_path):
    scene = _compiled("cut_off", tmp_path)
    def visibility(root):  # a second Action of the event (an Action holds one PrivateAction)
        first = root.find(".//Event[@name='c2_go_straight']/Action")
        action = etree.Element("Action", name="c2_visibility")
        first.addnext(action)
        private = etree.SubElement(action, "PrivateAction")
        etree.SubElement(private, "VisibilityAction", graphics="false", traffic="true", sensors="true")
    report = simulate(_edit(scene, visibility))
    assert "action VisibilityAction" in report.unsupported


def test_criticality_to_the_ego(tmp_path):
    verdict = simulate(_compiled("cut_off", tmp_path, only=("fourway_2lane_lights", "1:fwd"))).verdicts[0]
    assert verdict.min_distance_to_ego is not None and verdict.min_distance_agent in ("c1", "c2")
    assert verdict.min_ttc_to_ego is not None and verdict.min_ttc_to_ego > 0


# -- commands -------------------------------------------------------------------------------------------

def test_validate_command_and_its_report(tmp_path, capsys):
    scene = _compiled("stop_sign_right_turn", tmp_path)
    report_path = tmp_path / "report.json"
    assert main(["validate", str(scene), "--player", "sumo", "--report", str(report_path)]) == 0
    assert "✓" in capsys.readouterr().out
    data = json.loads(report_path.read_text())
    verdict = data["verdicts"][0]
    assert data["ok"] is True and {"name", "action", "achieved", "reason"} <= set(verdict["agents"][0])
    assert verdict["player"] == "sumo" and "collisions" in verdict and "min_ttc_to_ego" in verdict
    _edit(scene, lambda root: root.find(".//Private[@entityRef='k1']//LanePosition").set("laneId", "-9"))
    assert main(["validate", str(scene), "--player", "sumo"]) == 5


def test_compile_proves_the_scene_and_writes_the_report(tmp_path):
    out, report = tmp_path / "s.xosc", tmp_path / "r.json"
    assert main(["compile", str(EXAMPLES / "left_turn_oncoming.tsg"), "-o", str(out), "--report", str(report)]) == 0
    data = json.loads(report.read_text())
    assert data["ok"] and data["scenario"] == str(out)


def test_compile_tries_the_next_road_when_the_scene_fails(tmp_path, monkeypatch):
    import ttsgc.pipeline as pipeline

    real = pipeline.simulate_compiled
    seen = []

    def failing_first(compiled, out, players="all"):
        report = real(compiled, out, "sumo")
        seen.append(compiled.scene.approach)
        return report.model_copy(update={"ok": len(seen) > 1})
    monkeypatch.setattr(pipeline, "simulate_compiled", failing_first)
    messages = []
    compiled, report = compile_and_prove(parse_file(EXAMPLES / "intersection.tsg"), tmp_path / "x.xosc",
                                         log=messages.append)
    assert report.ok and len(seen) == 2 and seen[0] != seen[1]
    assert "trying the next-ranked road" in messages[0]


def test_the_sumo_player_walks_a_trajectory_at_its_vertices_offsets_as_esmini_does(tmp_path):
    """A trajectory's vertices were read without their offsets: a walker told to keep to the pavement's outer
    half walked its centre in SUMO (through people waiting at the kerb), at its outer half in esmini."""
    from ttsgc.roads.opendrive import load_opendrive
    from ttsgc.simulate.players import player
    from ttsgc.simulate.validate import read_plan

    scene = _compiled("daily_traffic", tmp_path)
    plan = read_plan(scene)
    walk = next(a for act in plan.acts for e in act.events if e.name == "p1_on_the_sidewalk" for a in e.actions
                if a.kind == "trajectory")
    assert len(set(walk.offsets)) == 1 and walk.offsets[0] != 0
    road = load_opendrive(plan.xodr).roads[walk.waypoints[0][0]]
    last = player("sumo").play(plan, seed=1).samples["p1"][-1]

    def lateral(vertex):  # (distance along, the sample's offset from the lane's centre at that vertex)
        _, lane, s = vertex
        centre, hdg = road.lane_point(s, lane), road.pose(s).hdg
        dx, dy = last.x - centre.x, last.y - centre.y
        return abs(dx * math.cos(hdg) + dy * math.sin(hdg)), -dx * math.sin(hdg) + dy * math.cos(hdg)

    assert abs(min(map(lateral, walk.waypoints))[1] - walk.offsets[0]) < 0.1
