"""Reading English the way engineers write it: one test group per failure class of the keyword lowering
(positions, actions, extra agents, missed agents, road, stages, repairs), bounded numbers, the lexicon as data,
the one plan inference shared by the offline lowering, the LLM lowering and import-ttsg, and the corpus floors."""

from __future__ import annotations

import json
import statistics
import time
from pathlib import Path

import pytest

from ttsgc.cli import main
from ttsgc.evaluate import agent_accuracy, load_gold, road_accuracy, weather_accuracy
from ttsgc.language import parse
from ttsgc.lowering import lower_prompt
from ttsgc.lowering.infer import infer_plan, language_allows_later_ego
from ttsgc.lowering.lexicon import FOLDER, TOO_LARGE, read_number, tokenize
from ttsgc.lowering.offline import lower
from ttsgc.resources import resource_dir
from ttsgc.ttsg_import import import_plan

CORPUS = Path(__file__).parent / "corpus"


def agents(prompt: str) -> list[tuple[str, str, str]]:
    """(type, action, position) of every agent, the ego as position 'ego'."""
    return sorted((a.type, a.action, a.relative_to_ego or "ego") for a in lower(prompt).scenario.agents())


def road(prompt: str):
    return lower(prompt).scenario.road


# -- positions ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("Two cars from the opposite straight is coming when the ego car is turning left",
     ("car", "go_straight", "road_of_straight")),
    ("An oncoming truck passes on a straight road with no junction.", ("truck", "go_straight", "front_left")),
    ("A fire engine comes from the road on the right and the ego turns left.",
     ("firetruck", "go_straight", "road_of_right_turn")),
    ("A dangerous motorcycle on the right front is trying to turn left.", ("motorcycle", "turn_left", "front_right")),
    ("A bus in the right lane ahead keeps going.", ("bus", "go_straight", "front_right")),
    ("The ego is approached from behind by an ambulance.", ("ambulance", "go_straight", "back")),
    ("A truck in the lane to the left of the ego swerves into the ego's lane.",
     ("truck", "change_lane_to_right", "left")),
    ("A pedestrian on the destination suddenly block the ego while the ego turns left.",
     ("pedestrian", "cross_the_road", "at_the_destination")),
])
def test_positions_are_composed_once_the_whole_text_is_read(prompt, expected):
    assert expected in agents(prompt)


def test_the_junction_context_comes_from_turns_said_after_the_position():
    # "from the road on the right" is a junction road even though the turn comes later in the text
    found = agents("A van from the right goes straight. The ego turns left at the end.")
    assert ("car", "go_straight", "road_of_right_turn") in found


def test_relative_clauses_and_passive_voice_place_the_right_noun():
    found = agents("A pedestrian crosses in front of a truck stopped on the shoulder, front right of the ego.")
    assert ("truck", "stop", "front_right") in found and ("pedestrian", "cross_the_road", "front_right") in found


# -- actions --------------------------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("A cyclist riding alongside swerves into the ego's lane.", ("cyclist", "change_lane_to_left", "right")),
    ("There is a parked truck blocking the lane ahead of the ego.", ("truck", "block_the_ego", "front")),
    ("A car in front does not move for an infinite amount of time.", ("car", "block_the_ego", "front")),
    ("A bus coming from the left road is turning left.", ("bus", "turn_left", "road_of_left_turn")),
    ("A van in the left lane cuts in front of the ego and stops.", ("car", "block_the_ego", "left")),
])
def test_the_main_verb_wins_over_participles_and_adjectives(prompt, expected):
    assert expected in agents(prompt)


def test_an_unknown_verb_is_reported_with_the_nearest_known_word():
    lowered = lower("A car in front of the ego swervs.")
    assert "swervs (did you mean swerve?)" in lowered.unknown


# -- extra agents ---------------------------------------------------------------------------------------

def test_re_mentions_pronouns_and_both_are_not_new_agents():
    found = agents("A truck drives ahead of the ego. The truck brakes hard and it stops. "
                   "A slow car follows the ego; the slow car honks. Both keep their lanes.")
    assert [a for a in found if a[0] == "truck"] == [("truck", "stop", "front")]
    assert [a for a in found if a[0] == "car" and a[2] != "ego"] == [("car", "go_straight", "back")]


def test_the_other_car_names_the_second_one():
    found = agents("A car waits on the left and a car waits on the right. The other car then drives off.")
    assert len([a for a in found if a[2] != "ego"]) == 2


@pytest.mark.parametrize("prompt, count", [
    ("Three cars including the ego car are driving. The car in front go straight. The ego is turning right. "
     "The car behind the ego is turning left", 3),
    ("Four vehicles wait at the light: a car, a bus, a truck and a van.", 5),
    ("Two cars, one in front and one behind, drive with the ego.", 3),
])
def test_counted_groups_are_constraints_not_new_agents(prompt, count):
    assert len(agents(prompt)) == count


@pytest.mark.parametrize("prompt", ["The ego goes straight through an intersection in fog.",
                                    "A car turns right at the junction in the rain."])
def test_a_passing_word_fills_no_scene_kind(prompt):
    lowered = lower(prompt)
    assert lowered.kind is None
    assert len(list(lowered.scenario.agents())) == len(agents(prompt))
    assert len(agents(prompt)) <= 2


@pytest.mark.parametrize("prompt, kind", [("Please create a scene for daily traffic", "daily_traffic"),
                                          ("Create a scene for pedestrian crushing", "crushing"),
                                          ("an emergency vehicles scene at night", "emergency")])
def test_a_scene_kind_asked_for_as_the_scene_fills_its_template(prompt, kind):
    lowered = lower(prompt)
    assert lowered.kind == kind and len(list(lowered.scenario.agents())) > 1


# -- missed agents --------------------------------------------------------------------------------------

@pytest.mark.parametrize("noun, agent_type", [("hatchback", "car"), ("SUV", "car"), ("pram", "pedestrian"),
                                              ("lorry", "truck"), ("HGV", "truck"), ("moped", "motorcycle"),
                                              ("jogger", "pedestrian"), ("fire engine", "firetruck"),
                                              ("patrol car", "police"), ("coach", "bus")])
def test_nouns_engineers_use_are_agents(noun, agent_type):
    assert any(a[0] == agent_type and a[2] != "ego" for a in agents(f"A {noun} is ahead of the ego."))


def test_schoolchildren_counted_and_uncounted():
    assert len(agents("Three schoolchildren cross in front of the ego.")) == 4
    assert len(agents("Schoolchildren cross in front of the ego.")) == 3  # a crowd of unstated size is two


# -- road -----------------------------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, lanes", [("A car drives level with the ego on its left.", 2),
                                           ("The ego changes to the left lane.", 2),
                                           ("An oncoming car passes on a road with no junction.", 1),
                                           ("A cyclist rides on the shoulder ahead on the right.", 1),
                                           ("Three lanes in each direction, a car ahead.", 3)])
def test_lanes_are_inferred_from_agents_beside_the_ego_and_lane_changes(prompt, lanes):
    assert road(prompt).lanes == lanes


@pytest.mark.parametrize("prompt, has, without", [
    ("A child crosses at the zebra crossing.", {"continental_crosswalk"}, set()),
    ("A pedestrian is crossing the road with the parallel open crosswalk.", {"parallel_open_crosswalk"}, set()),
    ("A cyclist uses the ladder crosswalk.", {"ladder_crosswalk"}, set()),
    ("The ego waits at a red light.", {"traffic_light"}, set()),
    ("At a four-way stop the ego turns left.", {"stop"}, set()),
    ("A junction with no signs; a bus turns.", set(), {"stop", "yield"}),
    ("An unsignalised junction; the ego turns right.", set(), {"traffic_light"}),
    ("A give way junction; a car comes from the left.", {"yield"}, set()),
])
def test_signals_and_crosswalk_kinds(prompt, has, without):
    r = road(prompt)
    assert set(r.required_signals + r.required_objects) == has
    assert set(r.without_signals + r.without_objects) == without


def test_a_junction_is_inferred_for_turns_and_junction_positions_and_said_in_the_notes():
    lowered = lower("The ego turns left while a bus waits.")
    assert lowered.scenario.road.junction is True
    assert "inferred: at junction (the ego turns)" in lowered.notes


# -- stages ---------------------------------------------------------------------------------------------

def test_a_condition_starts_a_stage():
    s = lower("The ego waits at the red light. Once the light turns green, a cyclist crosses in front.").scenario
    assert len(s.stages) == 2 and s.stages[1].agents[0].type == "cyclist"
    s = lower("The ego follows a bus. When the ego reaches the junction, a car turns left.").scenario
    assert len(s.stages) == 2


def test_an_agent_re_mentioned_in_a_later_stage_is_not_repeated():
    s = lower("A truck drives ahead of the ego. Then the truck stops and a car overtakes the ego.").scenario
    assert [a.type for a in s.agents()].count("truck") == 1


def test_the_ego_acting_in_a_later_stage():
    lowered = lower("The ego follows a bus. Then the ego overtakes it on the left.")
    if not language_allows_later_ego():
        assert any("later action" in n for n in lowered.notes)  # said, never dropped silently
        pytest.skip("the language has no rule yet for the ego acting in a later stage (`ego TYPE ACTION` in a "
                    "later stage)")
    later = [a for a in lowered.scenario.stages[1].agents if a.is_ego]
    assert later and later[0].action in ("go_straight", "change_lane_to_left")


# -- repairs and the plan inference --------------------------------------------------------------------

def test_an_obstacle_does_not_force_the_ego_to_stop():
    s = lower("A truck is stopped in front of the ego.").scenario
    assert s.ego.action == "go_straight"


def test_a_pedestrian_that_blocks_crosses_into_the_path_with_a_note_in_the_scene():
    lowered = lower_prompt("A pedestrian suddenly blocks the ego.", "offline")
    assert ("pedestrian", "cross_the_road", "front") in agents("A pedestrian suddenly blocks the ego.")
    assert any("cannot block_the_ego" in n and "steps into the ego's path" in n for n in lowered.notes)
    assert "cannot block_the_ego" in lowered.tsg("A pedestrian suddenly blocks the ego.")


def test_a_second_weather_condition_is_reported_not_dropped_silently():
    lowered = lower("On a foggy night in heavy rain a car drives ahead.")
    assert (lowered.scenario.weather.condition, lowered.scenario.weather.time) == ("fog", "night")
    assert any("heavy rain" in n for n in lowered.notes)


def test_a_lane_count_out_of_range_is_clamped_with_a_note():
    lowered = lower("On a 10-lane road a car drives ahead of the ego.")
    assert lowered.scenario.road.lanes == 6 and any("lanes >= 10" in n for n in lowered.notes)


def test_never_a_contradiction_written():
    draft = parse('scenario "x"\nroad {\n    not at junction\n}\nstage s {\n    ego car go_straight\n'
                  '    car c1 at front go_straight\n}\n')
    turned = draft.model_copy(update={"stages": (draft.stages[0].model_copy(update={"agents": (
        draft.ego, draft.stages[0].agents[1].model_copy(update={"action": "turn_left",
                                                                "relative_to_ego": "road_of_straight"}))}),)})
    inferred = infer_plan(turned)
    car = list(inferred.scenario.agents())[1]
    assert (car.action, car.relative_to_ego) == ("go_straight", "front") and len(inferred.notes) == 2


def test_import_ttsg_uses_the_same_inference(tmp_path):
    plan = {"planning": {"env": {"weather": "ClearNoon", "at_junction": None},
                         "agents": [{"type": "car", "is_ego": True, "action": "turn_left"},
                                    {"type": "pedestrian", "action": "block_the_ego", "relative_to_ego": "front"},
                                    {"type": "car", "action": "go_straight", "relative_to_ego": "left"}]},
            "retrieval": {"number_of_lanes": 1}}
    path = tmp_path / "agent_output.json"
    path.write_text(json.dumps(plan))
    imported = import_plan(path)
    kinds = sorted((a.type, a.action) for a in imported.scenario.agents())
    assert ("pedestrian", "cross_the_road") in kinds
    assert imported.scenario.road.lanes == 2 and imported.scenario.road.junction is True
    assert any("lanes >= 2" in n for n in imported.notes) and any("at junction" in n for n in imported.notes)


# -- numbers --------------------------------------------------------------------------------------------

def test_numbers_are_read_through_a_bounded_reader():
    assert read_number("4" * 400) == TOO_LARGE and read_number("30") == 30.0 and read_number("2.5") == 2.5


@pytest.mark.parametrize("prompt, note", [("4" * 400 + " cars drive ahead of the ego.", "too large"),
                                          ("A road with " + "9" * 400 + " lanes.", "too large"),
                                          ("A speed limit of " + "7" * 400 + " km/h.", "too large"),
                                          ("Fifty cars drive ahead of the ego.", "more than 12")])
def test_huge_numbers_clamp_with_a_note_never_an_overflow(prompt, note):
    lowered = lower(prompt)
    assert any(note in n for n in lowered.notes), lowered.notes
    assert len(list(lowered.scenario.agents())) <= 13


def test_number_words_and_units():
    assert road("A road with three lanes in each direction and a limit of forty.").lanes == 3
    assert "speed_40" in road("A road with three lanes in each direction and a limit of forty.").required_objects
    assert "speed_32" in road("The limit is twenty miles per hour.").required_objects


# -- the lexicon as data --------------------------------------------------------------------------------

def test_the_lexicon_is_a_file_per_category_with_british_spellings_and_multiword_phrases():
    names = {p.stem for p in FOLDER.glob("*.txt")}
    assert {"agents", "actions", "positions", "road", "weather", "numbers", "spelling"} <= names
    assert [t.base for t in tokenize("signalised kerb lorries")] == ["signalized", "curb", "lorry"]
    assert agents("A lorry pulls out at the signalised junction.") == agents(
        "A truck pulls out at the signalized junction.")


# -- the whole lowering ---------------------------------------------------------------------------------

def test_the_ego_going_straight_compiles(tmp_path):
    prompt = tmp_path / "p.txt"
    prompt.write_text("The ego car is going straight")
    assert main(["compile", str(prompt), "-o", str(tmp_path / "p.xosc"), "--no-simulate"]) == 0
    assert (tmp_path / "p.xosc").is_file()


def test_no_prompt_with_a_readable_agent_is_refused():
    for text in ("ego", "a bus", "pedestrian!!!", "cars", "The ego car is going straight"):
        assert lower(text).scenario.ego is not None


def test_lowering_is_deterministic_and_fast():
    prompts = sorted((CORPUS / "dev").glob("*/*.txt"))
    if not prompts:
        pytest.skip("the corpus is not in this checkout")
    times = []
    for p in prompts:
        text = p.read_text()
        start = time.perf_counter()
        first = lower_prompt(text, "offline").tsg(text)
        times.append(time.perf_counter() - start)
        assert lower_prompt(text, "offline").tsg(text) == first
    assert statistics.median(times) < 0.05


def _scores(folder: Path):
    aa, ra, wa = [], [], []
    for prompt in sorted(folder.glob("**/*.txt")):
        gold = load_gold(prompt.with_suffix(".tsg"))
        scene = lower(prompt.read_text()).scenario
        aa.append(agent_accuracy(gold, scene))
        ra.append(road_accuracy(gold, scene))
        wa.append(weather_accuracy(gold, scene))
    return (statistics.mean(aa), statistics.mean(ra), statistics.mean(wa)) if aa else None


def test_the_dev_split_floor():
    scores = _scores(CORPUS / "dev")
    if scores is None:
        pytest.skip("the corpus is not in this checkout")
    aa, ra, wa = scores
    assert aa >= 0.9 and ra >= 0.95 and wa >= 0.95, scores


def test_the_papers_ten_prompts_score_at_least_the_papers_best():
    scores = _scores(CORPUS / "paper")
    if scores is None:
        pytest.skip("the paper's prompts are not in this checkout")
    aa, ra, _ = scores
    assert aa >= 0.975 and ra >= 0.94, scores


def test_the_llm_worked_examples_come_from_the_dev_split():
    folder = resource_dir("templates") / "worked_examples"
    examples = sorted(folder.glob("*.txt"))
    assert len(examples) >= 5
    dev = {p.name: p for p in (CORPUS / "dev").glob("*/*")}
    if not dev:
        pytest.skip("the corpus is not in this checkout")
    for prompt in examples:
        for path in (prompt, prompt.with_suffix(".tsg")):
            assert path.read_text() == dev[path.name].read_text(), path.name


def test_misspelt_words_close_to_one_known_word_are_read_as_it_and_reported():
    lowered = lower("pedestrain crosses infront of the ego, a motrocycle comes from the oposite direction at the "
                    "interesection")
    found = sorted((a.type, a.action, a.relative_to_ego or "ego") for a in lowered.scenario.agents())
    assert ("pedestrian", "cross_the_road", "front") in found
    assert ("motorcycle", "go_straight", "road_of_straight") in found
    assert "motrocycle (read as motorcycle)" in lowered.unknown
