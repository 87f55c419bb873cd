"""The scenario language: examples, the model's shape, semantic rules, comments, the grammar's keywords."""

from __future__ import annotations

import json

import pytest
from pydantic import ValidationError

from conftest import example_scenarios
from ttsgc import vocabulary as V
from ttsgc.cli import main
from ttsgc.language import ScenarioError, format_scenario, parse, parse_file
from ttsgc.language.parse import grammar_parser
from ttsgc.scenario import Agent, Scenario, Stage, behind_cycles

SKETCH = """\
# Unprotected left turn with oncoming traffic, then the ego is boxed in.
scenario "unprotected left turn"
weather mid_rain night
seed 7                                   # pins the choice among equally ranked roads

road {
    lanes >= 1
    at junction
    has stop_line
    without traffic_light, stop
}

stage approach {
    ego car turn_left cautious
    car oncoming1 at road_of_straight go_straight aggressive
    car oncoming2 at road_of_straight go_straight behind oncoming1 gap 8m
    pedestrian walker at near_the_crosswalk on sidewalk cross_the_road when ego within 15m
}

stage boxed_in {                          # starts when every action of "approach" has ended
    car b1 at front block_the_ego
    car b2 at front block_the_ego behind b1
}
"""


def test_the_design_sketch_parses_to_what_it_says():
    s = parse(SKETCH)
    assert (s.name, s.seed, s.weather.condition, s.weather.time) == ("unprotected left turn", 7, "mid_rain", "night")
    assert s.road.junction is True and s.road.lanes == 1
    assert s.road.required_objects == ("stop_line",)
    assert s.road.without_signals == ("traffic_light", "stop")
    assert [st.name for st in s.stages] == ["approach", "boxed_in"]
    ego, on1, on2, walker = s.stages[0].agents
    assert ego.is_ego and ego.name == "ego" and ego.action == "turn_left" and ego.behavior == "cautious"
    assert ego.relative_to_ego is None
    assert on1.relative_to_ego == "road_of_straight" and on1.behavior == "aggressive"
    assert on2.behind == "oncoming1" and on2.gap_m == 8.0
    assert walker.road_type == "sidewalk" and walker.trigger.within_m == 15.0 and walker.trigger.of == "ego"
    assert s.stages[1].agents[1].behind == "b1"


@pytest.mark.parametrize("path", example_scenarios(), ids=lambda p: p.stem)
def test_every_example_is_valid_and_canonical(path):
    scenario = parse_file(path)
    assert format_scenario(scenario) == path.read_text(encoding="utf-8")
    assert path.with_suffix(".txt").read_text(encoding="utf-8").strip(), "each example has its prompt beside it"


def test_examples_cover_the_paper_scenario_kinds():
    names = {p.stem for p in example_scenarios()}
    diversity = {"blocking", "crushing", "cut_off", "daily_traffic", "emergency", "intersection", "two_wheels",
                 "weather"}
    assert diversity <= names
    assert len(names - diversity) >= 10


def test_check_json_has_the_documented_shape(capsys, tmp_path):
    path = tmp_path / "sketch.tsg"
    path.write_text(SKETCH)
    assert main(["check", "--json", str(path)]) == 0
    data = json.loads(capsys.readouterr().out)
    assert set(data) >= {"name", "seed", "weather", "road", "stages"}
    assert data["weather"] == {"condition": "mid_rain", "time": "night"}
    assert set(data["road"]) >= {"lanes", "junction", "required_signals", "without_signals", "required_objects",
                                 "without_objects"}
    agent = data["stages"][0]["agents"][1]
    assert set(agent) >= {"name", "type", "is_ego", "action", "behavior", "relative_to_ego", "road_type"}
    assert data["stages"][0]["agents"][0]["relative_to_ego"] is None
    assert "comments" not in data


def test_check_json_of_several_files_is_a_list(capsys):
    paths = [str(p) for p in example_scenarios()[:2]]
    assert main(["check", "--json", *paths]) == 0
    assert len(json.loads(capsys.readouterr().out)) == 2


def test_all_errors_of_a_file_in_one_run():
    text = SKETCH.replace("turn_left cautious", "trun_left cautious").replace("gap 8m", "gap 900m")
    text = text.replace("mid_rain", "mid_rian")
    with pytest.raises(ScenarioError) as err:
        parse(text, "x.tsg")
    messages = [d.message for d in err.value.diagnostics]
    assert len(messages) == 3
    assert any("did you mean turn_left?" in m for m in messages)
    assert any("did you mean mid_rain?" in m for m in messages)
    assert any("gap 900m is out of range" in m for m in messages)


def test_syntax_errors_of_several_lines_are_all_reported():
    text = 'scenario "x"\nstage s {\n    ego car go_straight gap 8 km\n    car c at front go_straight @\n}\n'
    with pytest.raises(ScenarioError) as err:
        parse(text)
    assert [d.line for d in err.value.diagnostics] == [3, 4]


@pytest.mark.parametrize("agent_line, message", [
    ("car c1 at front go_straight behind c1", "cannot be behind itself"),
    ("car c1 at front go_straight behind c2\n    car c2 at back go_straight", "same position"),
    ("car c1 at front go_straight behind c2 order 2\n    car c2 at front go_straight", "either 'behind' or 'order'"),
    ("pedestrian p1 at right on driving cross_the_road", "cannot stand on the driving"),
    ("pedestrian p1 at right on shoulder on_the_sidewalk", "needs the agent on the sidewalk"),
    ("car c1 at front go_straight when c9 within 10m", "names no agent"),
    ("car c1 at front go_straight after 900s", "out of range"),
    ("car c1 at front go_straight order 0", "out of range"),
    ("car c1 at front go_straight speed 500 mph", "out of range"),
    ("car c1 at front go_straight at back", "given twice"),
    ("car ego at front go_straight", "used twice"),
])
def test_semantic_rules(agent_line, message):
    text = f'scenario "x"\nstage s {{\n    ego car go_straight\n    {agent_line}\n}}\n'
    with pytest.raises(ScenarioError) as err:
        parse(text)
    assert any(message in d.message for d in err.value.diagnostics), err.value.render()


def test_behind_cycles_are_each_reported_once_and_chains_into_them_are_not_cycles():
    text = ('scenario "x"\nstage s {\n    ego car go_straight\n'
            '    car a at front go_straight behind b\n    car b at front go_straight behind c\n'
            '    car c at front go_straight behind a\n    car d at front go_straight behind a\n'
            '    car e at front go_straight behind d\n'
            '    car f at back go_straight behind g\n    car g at back go_straight behind f\n}\n')
    with pytest.raises(ScenarioError) as err:
        parse(text)
    cycles = [d.message for d in err.value.diagnostics if "cycle" in d.message]
    assert cycles == ["'behind' forms a cycle: a -> b -> c", "'behind' forms a cycle: f -> g"]


def test_behind_cycles_walks_each_link_once():
    follows = {f"c{k}": f"c{k + 1}" for k in range(20000)}  # one long chain: no cycle, no quadratic walk
    follows["c20000"] = "c0"
    assert [len(c) for c in behind_cycles(follows)] == [20001]
    del follows["c20000"]
    assert behind_cycles(follows) == []


def test_the_ego_cannot_block_itself():
    with pytest.raises(ScenarioError, match="the ego cannot block_the_ego"):
        parse('scenario "x"\nstage s {\n    ego car block_the_ego\n}\n')


def test_a_scenario_built_in_code_obeys_the_same_rules():
    ego = Agent(name="ego", type="car", is_ego=True, action="go_straight")
    Scenario(name="ok", stages=(Stage(name="s", agents=(ego,)),))
    bad = ego.model_copy(update={"action": "fly"})
    with pytest.raises(ValidationError, match="unknown action 'fly'"):
        Scenario(name="bad", stages=(Stage(name="s", agents=(bad,)),))


def test_comments_survive_formatting():
    s = parse(SKETCH)
    text = format_scenario(s)
    for comment in ("# Unprotected left turn with oncoming traffic, then the ego is boxed in.",
                    "# pins the choice among equally ranked roads",
                    '# starts when every action of "approach" has ended'):
        assert comment in text
    assert parse(text) == s
    assert format_scenario(parse(text)) == text


def test_comment_inside_a_block_and_at_the_end():
    text = ('scenario "x"\nstage s {\n    ego car go_straight\n    # before the brace\n}  # after it\n'
            '# the very end\n')
    formatted = format_scenario(parse(text))
    assert "    # before the brace\n}  # after it\n" in formatted
    assert formatted.endswith("# the very end\n")


def test_grammar_keywords_are_the_vocabulary_reserved_words():
    parser = grammar_parser()
    keywords = {t.pattern.value for t in parser.terminals
                if t.pattern.type == "str" and t.pattern.value.replace("_", "").isalpha()}
    assert keywords == V.RESERVED_WORDS | V.UNIT_WORDS


def test_every_vocabulary_word_is_accepted_somewhere():
    for word in V.AGENT_TYPES:
        action = sorted(V.ACTIONS_BY_TYPE[word])[0]
        parse(f'scenario "x"\nstage s {{\n    ego car go_straight\n    {word} a at front {action}\n}}\n')
    for word in V.POSITIONS:
        parse(f'scenario "x"\nstage s {{\n    ego car go_straight\n    car a at {word} go_straight\n}}\n')
    for word in list(V.SIGNALS) + V.object_words():
        parse(f'scenario "x"\nroad {{\n    has {word}\n}}\nstage s {{\n    ego car go_straight\n}}\n')
    for condition in V.WEATHER_CONDITIONS:
        for time in V.TIMES_OF_DAY:
            s = parse(f'scenario "x"\nweather {time} {condition}\nstage s {{\n    ego car go_straight\n}}\n')
            assert (s.weather.condition, s.weather.time) == (condition, time)


def test_speed_units_convert_to_metres_per_second():
    s = parse('scenario "x"\nstage s {\n    ego car go_straight speed 36 km/h\n    '
              'car a at front go_straight speed 10 mph\n}\n')
    assert s.ego.speed.mps == pytest.approx(10.0)
    assert s.stages[0].agents[1].speed.mps == pytest.approx(4.4704)


def test_fmt_check_and_rewrite(tmp_path, capsys):
    path = tmp_path / "messy.tsg"
    path.write_text('scenario   "x"\n\n\nstage s {\n  ego car   go_straight normal   # hi\n}')
    assert main(["fmt", "--check", str(path)]) == 7
    assert main(["fmt", str(path)]) == 0
    assert path.read_text() == 'scenario "x"\n\nstage s {\n    ego car go_straight  # hi\n}\n'
    assert main(["fmt", "--check", str(path)]) == 0


def test_fmt_leaves_an_invalid_file_untouched(tmp_path):
    path = tmp_path / "bad.tsg"
    original = 'scenario "x"\nstage s {\n    ego car trun_left\n}\n'
    path.write_text(original)
    assert main(["fmt", str(path)]) == 2
    assert path.read_text() == original
