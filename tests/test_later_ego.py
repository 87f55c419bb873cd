"""The ego acting in a later stage: the `ego TYPE ACTION` line of a later stage is parsed, formatted and
checked; binding keeps one ego and asks the road for what the action needs; the file carries the action as an
event of that stage's act; every player is judged on it, in a row of its own."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from conftest import SHARED
from ttsgc import intent as I
from ttsgc.binding.place import PlacementError
from ttsgc.binding.rank import lane_needs, requirements
from ttsgc.binding.scene import bind
from ttsgc.language import ScenarioError, format_scenario, parse
from ttsgc.pipeline import compile_scenario, write
from ttsgc.roads.retrieve import load_library
from ttsgc.simulate.validate import validate

ESMINI = SHARED / "tools" / "esmini" / "esmini"

FOLLOW_THEN_PASS = '''scenario "the ego follows a bus, then changes lane to the left"

stage follow {
    ego car go_straight
    bus b1 at front go_straight
}

stage pass {
    ego car change_lane_to_left
}
'''


def _scene(later: str, first: str = "ego car go_straight") -> str:
    return (f'scenario "x"\n\nstage a {{\n    {first}\n    bus b1 at front go_straight\n}}\n\n'
            f'stage b {{\n    {later}\n}}\n')


def _errors(text: str) -> list[tuple[int, int, str]]:
    with pytest.raises(ScenarioError) as caught:
        parse(text, "x.tsg")
    return [(d.line, d.column, d.message) for d in caught.value.diagnostics]


# -- the language -------------------------------------------------------------------------------------------

def test_a_later_ego_line_is_the_egos_action_in_that_stage():
    s = parse(FOLLOW_THEN_PASS)
    later = [a for a in s.stages[1].agents if a.is_ego]
    assert [(a.type, a.action) for a in later] == [("car", "change_lane_to_left")]
    assert s.ego.action == "go_straight"  # the ego is still the first stage's line


def test_a_later_ego_line_round_trips_with_its_clauses_and_comments():
    text = _scene("ego car stop aggressive speed 20 km/h when b1 within 12m after 2s  # then it brakes")
    text = text.replace("stage b {\n", "stage b {\n    # the ego's turn\n")
    s = parse(text)
    assert format_scenario(s) == text
    assert parse(format_scenario(s)) == s


@pytest.mark.parametrize("later, column, words", [
    ("ego truck change_lane_to_left", 9, "must say 'ego car'"),
    ("ego car at front stop", 16, "no position relative to itself"),
    ("ego car stop on driving", 21, "has no 'on'"),
    ("ego car stop gap 5m", 22, "has no 'gap'"),
    ("ego car cross_the_road", 13, "a car cannot cross_the_road"),
    ("ego car block_the_ego", 13, "the ego cannot block_the_ego"),
])
def test_a_wrong_later_ego_line_is_shown_at_its_token(later, column, words):
    [(line, col, message)] = _errors(_scene(later))
    assert (line, col) == (9, column) and words in message


def test_a_second_ego_line_in_one_stage_is_shown_at_it():
    [(line, col, message)] = _errors(_scene("ego car change_lane_to_left\n    ego car stop"))
    assert (line, col) == (10, 5) and "a second ego line in one stage" in message


# -- binding --------------------------------------------------------------------------------------------------

def test_a_later_lane_change_asks_for_the_adjacent_lane_and_adds_no_body():
    s = parse(FOLLOW_THEN_PASS)
    assert lane_needs(s) == (True, False)
    assert "lanes>=2" in [r.column for r in requirements(s)]
    scene = bind(s, load_library(None))
    assert [a.name for a in scene.agents] == ["ego", "b1"]
    [step] = scene.agent("ego").later
    assert (step.stage, step.action, step.lane_change) == (1, "change_lane_to_left", 1)


def test_a_later_turn_is_refused_unless_the_ego_stopped_first_and_says_what_to_write():
    with pytest.raises(PlacementError, match=r"turn_left in stage 'b'.*ego car stop in the first stage"):
        bind(parse(_scene("ego car turn_left")), load_library(None))
    twice = _scene("ego car turn_left", first="ego car stop") + "\nstage c {\n    ego car turn_right\n}\n"
    with pytest.raises(PlacementError, match=r"turn_right in stage 'c'.*is made once"):
        bind(parse(twice), load_library(None))


def test_a_later_turn_after_a_stop_asks_for_the_turn_and_is_proven_in_sumo(tmp_path):
    s = parse('scenario "x"\n\nstage wait {\n    ego car stop\n}\n\nstage go {\n    ego car turn_right\n}\n')
    assert "ego right" in [r.column for r in requirements(s)]
    out = tmp_path / "turn.xosc"
    write(compile_scenario(s, out), out)
    row = _ego_row(validate(out, "sumo"))
    assert row.achieved and "went right" in row.reason


# -- the file and the players -------------------------------------------------------------------------------

def _compiled(folder: Path) -> Path:
    out = folder / "pass.xosc"
    write(compile_scenario(parse(FOLLOW_THEN_PASS), out), out)
    return out


def _ego_row(report):
    return next(a for a in report.agents if a.name == "ego (stage 2)")


def test_the_later_action_is_an_event_of_its_stage_for_the_ego(tmp_path):
    root = etree.parse(str(_compiled(tmp_path))).getroot()
    act = root.find(".//Act[@name='pass']")
    event = act.find(f".//Event[@name='{I.later_event_name('ego', 1, 'change_lane_to_left')}']")
    assert event is not None
    assert event.getparent().getparent().find("Actors/EntityRef").get("entityRef") == "ego"
    assert event.find(".//RelativeTargetLane").attrib == {"value": "1", "entityRef": "ego"}
    assert len(root.findall(".//Entities/ScenarioObject[@name='ego']")) == 1
    ego = root.find(".//Entities/ScenarioObject[@name='ego']")
    assert ego.find(f".//Property[@name='ttsgc:{I.STAGE_ACTIONS}']").get("value") == "1:change_lane_to_left"


def _no_change(root):  # the same event, now changing no lane (the file stays valid)
    root.find(".//RelativeTargetLane[@entityRef='ego']").set("value", "0")


def _edited(path: Path) -> Path:
    tree = etree.parse(str(path))
    _no_change(tree.getroot())
    tree.write(str(path))
    return path


def test_sumo_proves_the_later_lane_change_and_fails_a_file_without_it(tmp_path):
    scene = _compiled(tmp_path)
    report = validate(scene, "sumo")
    assert report.ok and "changed 1 lane(s) to the left" in _ego_row(report).reason
    assert "ego (stage 2)" in report.table()
    report = validate(_edited(scene), "sumo")
    assert not report.ok and not _ego_row(report).achieved
    assert "did not change to the left" in _ego_row(report).reason


def test_esmini_proves_the_later_lane_change_and_fails_a_file_without_it(tmp_path, monkeypatch):
    if not ESMINI.is_file():
        pytest.skip("../shared/tools/esmini is not present")
    monkeypatch.setenv("TTSGC_ESMINI", str(ESMINI))
    scene = _compiled(tmp_path)
    report = validate(scene, "esmini")
    assert report.players == ["esmini"]
    assert report.ok and "changed 1 lane(s) to the left" in _ego_row(report).reason
    report = validate(_edited(scene), "esmini")
    assert not report.ok and "did not change to the left" in _ego_row(report).reason


def test_a_later_stop_is_judged_from_its_stage(tmp_path):
    out = tmp_path / "stop.xosc"
    write(compile_scenario(parse(_scene("ego car stop")), out), out)
    row = _ego_row(validate(out, "sumo"))
    assert row.achieved and "standstill" in row.reason


def test_a_stage_action_the_checks_do_not_know_is_refused(tmp_path):
    from ttsgc.simulate.xosc_check import XoscFileError, load_scenario

    scene = _compiled(tmp_path)
    scene.write_text(scene.read_text().replace('value="1:change_lane_to_left"', 'value="1:fly"'))
    with pytest.raises(XoscFileError, match=r"ttsgc:stage_actions = '1:fly' is not a list of STAGE:ACTION"):
        load_scenario(scene)
