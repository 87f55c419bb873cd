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
from ttsgc.lowering.lexicon import FOLDER, TOO_LARGE, one_line_records, read_number, tokenize
from ttsgc.lowering.narration import read_narration
from ttsgc.lowering.offline import lower
from ttsgc.resources import resource_dir
from ttsgc.ttsg_import import import_plan

CORPUS = Path(__file__).parent / "corpus"


def agents(prompt: str) -> list[tuple[str, str, str]]:
    """(type, action, position) of every agent, the ego as position 'ego'."""
    return sorted((a.type, a.action, a.relative_to_ego or "ego") for a in lower(prompt).scenario.agents())


def stages(prompt: str) -> list[list[tuple[str, str, str | None]]]:
    """Stage by stage, (type or 'ego', action, position) as the whole lowering writes them, plan inference too."""
    scenario = lower_prompt(prompt, "offline").scenario
    return [[("ego" if a.is_ego else a.type, a.action, a.relative_to_ego) for a in st.agents] for st in scenario.stages]


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


@pytest.mark.parametrize("prompt, expected", [
    ("Can you make a test where the ego drives straight with a taxi in front of the ego braking hard?",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("The ego slows down with a bus ahead of the ego stopping.", [("bus", "stop", "front"), ("car", "go_straight", "ego")]),
])
def test_a_participle_after_a_noun_placed_by_the_ego_is_that_nouns(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_an_unknown_verb_one_slip_from_a_known_one_is_read_as_it_and_reported():
    lowered = lower("A car in front of the ego swervs.")
    assert "swervs (read as swerves)" in lowered.unknown


# -- extra agents ---------------------------------------------------------------------------------------

def test_re_mentions_pronouns_and_both_are_not_new_agents():
    found = agents("A truck drives ahead of the ego. The truck brakes hard and it stops. "
                   "A slow car follows the ego; the slow car honks. Both keep their lanes.")
    assert [a for a in found if a[0] == "truck"] == [("truck", "stop", "front")]
    assert [a for a in found if a[0] == "car" and a[2] != "ego"] == [("car", "go_straight", "back")]


@pytest.mark.parametrize("prompt, others", [
    ("I saw a pickup truck on my left. A white van was parked on the right. The pickup turned left in front of me.", 2),
    ("There was a woman ahead of me. The pedestrian stopped suddenly.", 1),
])
def test_a_compounds_first_word_or_another_name_said_again_is_the_same_agent(prompt, others):
    found = agents(prompt)
    assert sum(where != "ego" for _, _, where in found) == others
    assert all(t == "pedestrian" for t, _, where in found if where != "ego") or "woman" not in prompt


@pytest.mark.parametrize("prompt, expected", [
    ("A car ahead and another behind.", [("car", "go_straight", "back"), ("car", "go_straight", "front")]),
    ("One car is ahead and another is behind.", [("car", "go_straight", "back"), ("car", "go_straight", "front")]),
    ("There is a truck on the left and another on the right.",
     [("truck", "go_straight", "left"), ("truck", "go_straight", "right")]),
    ("A cyclist crosses from the left, then another from the right.",
     [("cyclist", "cross_the_road", "front_left"), ("cyclist", "cross_the_road", "front_right")]),
    ("Two mopeds weave through traffic. One of them cuts in front of me, and another is undertaking on the right.",
     [("motorcycle", "change_lane_to_right", "front_left"), ("motorcycle", "go_straight", "back_right")]),
])
def test_another_said_alone_is_one_more_of_the_kind_named_before_or_the_groups_next_member(prompt, expected):
    assert [a for a in agents(prompt) if a[2] != "ego"] == sorted(expected)


@pytest.mark.parametrize("prompt, expected", [
    ("Two pedestrians cross at the crosswalk in front of the ego while a third walks along the sidewalk on its "
     "right.", [("pedestrian", "cross_the_road", "near_the_crosswalk")] * 2 + [("pedestrian", "on_the_sidewalk",
                                                                                 "right")]),
    ("A sedan pulled up on your left a second before you did.", [("car", "stop", "left")]),
    ("Some bloke speeding in a white hatchback in the lane to my left cuts in front of me.",
     [("car", "change_lane_to_right", "left")]),
    ("A pedestrian stands on the sidewalk next to a zebra crossing.", [("pedestrian", "on_the_sidewalk",
                                                                        "near_the_crosswalk")]),
])
def test_a_third_said_alone_a_driver_speeding_in_a_car_and_a_place_next_to_a_crossing(prompt, expected):
    assert [a for a in agents(prompt) if a[2] != "ego"] == sorted(expected)


@pytest.mark.parametrize("prompt, expected", [
    ("I was on the 7.5 tonne lorry last night and crept along behind another lorry for ten miles.",
     [("truck", "go_straight", "ego"), ("truck", "go_straight", "front")]),
    ("SC-07: an ambulance approaches the ADS vehicle from behind; the ADS vehicle changes lane to the right.",
     [("ambulance", "go_straight", "back"), ("car", "change_lane_to_right", "ego")]),
    ("Just me on a wet country road at night, not another car around.", [("car", "go_straight", "ego")]),
])
def test_a_weight_a_document_identifier_and_not_another_count_nothing(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Three-lane motorway, I'm in the middle lane on the bike doing about 70. An ambulance is coming up behind me, "
     "so I moved over to the left lane.", [("ambulance", "go_straight", "back"), ("motorcycle", "change_lane_to_left",
                                                                                 "ego")]),
    ("I saw a kid on a bike cross in front of me.", [("car", "go_straight", "ego"), ("cyclist", "cross_the_road",
                                                                                     "front")]),
])
def test_the_bike_a_speaker_is_on_is_their_motorbike_and_someone_elses_bike_is_a_bicycle(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("I'm in the middle lane doing 70, and a semi in the left lane just ahead of me starts drifting into my lane. "
     "Car braked and moved over to the right lane.",
     [("car", "change_lane_to_right", "ego"), ("truck", "change_lane_to_right", "front_left")]),
    ("I stopped at the junction. Car came from the right.",
     [("car", "go_straight", "road_of_right_turn"), ("car", "stop", "ego")]),
])
def test_a_bare_car_opening_a_speakers_note_is_the_speakers_unless_it_comes_from_somewhere(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Two cyclists, one of whom is a child, ride on the right.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "right"), ("cyclist", "go_straight", "right")]),
    ("Three pedestrians, two of whom are children, cross ahead.",
     [("car", "go_straight", "ego")] + [("pedestrian", "cross_the_road", "front")] * 3),
])
def test_what_some_members_of_a_group_are_said_in_passing_is_no_agent_beside_it(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("School bus stopped in front of you with three kids crossing road in front of it. You stopped. Don't move "
     "again even if kids look clear.",
     [("bus", "stop", "front"), ("car", "stop", "ego")] + [("pedestrian", "cross_the_road", "front")] * 3),
    ("At 06:10 vehicle under test was travelling east when jogger ran across road from north side and was struck "
     "by vehicle's front left corner.", [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left")]),
])
def test_a_bare_noun_said_again_without_its_article_is_the_one_said_before(prompt, expected):
    """Notes drop their articles: 'kids' after 'three kids', 'vehicle' after 'vehicle under test'."""
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "The ego goes straight and there isn't a car around.",
    "The ego goes straight and there is not a single car around.",
    "The ego goes straight; not one car in sight.",
])
def test_not_a_car_names_no_car(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("residential street, jogger on right sidewalk, parked cars, dusk",
     [("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "right")]),
    ("Van driver on a residential street, cars parked both sides. A kid steps out in front of the van.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("Two parked cars on the right; a child runs out.",
     [("car", "go_straight", "ego"), ("car", "stop", "front_right"), ("car", "stop", "front_right"),
      ("pedestrian", "cross_the_road", "front")]),
])
def test_parked_vehicles_said_with_no_count_are_scenery_and_counted_ones_are_agents(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("phrase, kind", [
    ("a quad bike", "motorcycle"), ("a digger", "truck"), ("a street sweeper", "truck"), ("a hearse", "car"),
    ("a paramedic car", "ambulance"), ("a U-Haul", "truck"), ("a man pushing a pram", "pedestrian"),
])
def test_less_common_road_users_are_read_as_their_kind(phrase, kind):
    found = agents(f"The ego drives straight and {phrase} ahead stops.")
    assert [t for t, _, where in found if where != "ego"] == [kind]


@pytest.mark.parametrize("prompt, expected", [
    ("The L4 vehicle turns left at the junction.", [("car", "turn_left", "ego")]),
    ("A Level 4 shuttle turns right.", [("bus", "turn_right", "ego")]),
])
def test_an_automation_level_names_the_automated_vehicle_not_a_label(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A car parks on the left.", [("car", "go_straight", "ego"), ("car", "stop", "front_left")]),
    ("The car parks are full, and a truck ahead stops.", [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
])
def test_a_car_that_parks_is_a_car_and_car_parks_are_places(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "One car waits on the left and one turns right.",
    "One car waits on the left, and one turns right at the junction.",
])
def test_one_opening_a_clause_of_its_own_after_one_car_is_another_car(prompt):
    found = agents(prompt)
    assert sum(where != "ego" for _, _, where in found) == 2 and ("car", "stop", "road_of_left_turn") in found


def test_a_passive_with_an_adverb_before_its_verb_is_a_passive_and_the_ego_driving_on_is_nothing_new():
    found = agents("The ego's lane is blocked by a parked delivery van. The van is then passed by the ego, which "
                   "moves over into the left lane.")
    assert found == [("car", "block_the_ego", "front"), ("car", "change_lane_to_left", "ego"),
                     ("car", "go_straight", "ego")]
    assert agents("A van is parked ahead. The van is then passed by the ego.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front")]


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

@pytest.mark.parametrize("prompt, without, position", [
    ("A pedestrian crosses from the right, no marked crosswalk.", ("crosswalk",), "front_right"),
    ("No painted crosswalk; a pedestrian crosses.", ("crosswalk",), "front"),
])
def test_a_denial_reaches_past_the_kind_of_what_it_denies(prompt, without, position):
    scene = lower(prompt).scenario
    assert scene.road.without_objects == without and scene.road.required_objects == ()
    assert [a.relative_to_ego for a in scene.agents() if not a.is_ego] == [position]


@pytest.mark.parametrize("prompt, lanes, objects", [
    ("The ego drives on a 60 km/h arterial.", 1, ("speed_60",)),
    ("The ego drives on a 40 mph dual carriageway.", 2, ("speed_64",)),
    ("The ego drives on a 50 km/h residential street.", 1, ("speed_50",)),
    ("A van cuts in on a divided highway.", 2, ()),
])
def test_the_limit_of_a_road_named_by_its_class_and_the_lanes_of_a_divided_road(prompt, lanes, objects):
    road = lower(prompt).scenario.road
    assert (road.lanes, road.required_objects) == (lanes, objects)


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


def test_no_phrase_of_a_category_file_is_listed_under_two_meanings():
    """The first line that names a phrase owns it; a later line naming it otherwise is dead text that reads as a
    rule ('other vehicle' as a car after it was made generic), so none may be written."""
    from ttsgc.lowering import lexicon as lexicon_module
    twice = []
    for category in lexicon_module.CATEGORIES:
        seen: dict = {}
        for meaning, words in lexicon_module._entries(category):
            if seen.setdefault(words, meaning) != meaning:
                twice.append((category, " ".join(words), seen[words], meaning))
    assert twice == []


# -- the whole lowering ---------------------------------------------------------------------------------

def test_the_ego_going_straight_compiles(tmp_path):
    prompt = tmp_path / "p.txt"
    prompt.write_text("The ego car is going straight")
    assert main(["compile", str(prompt), "-o", str(tmp_path / "p.xosc"), "--no-simulate"]) == 0
    assert (tmp_path / "p.xosc").is_file()


# -- English written by German engineers --------------------------------------------------------------

@pytest.mark.parametrize("noun, agent_type", [("PKW", "car"), ("LKW", "truck"), ("Motorrad", "motorcycle"),
                                              ("Linienbus", "bus"), ("Radfahrer", "cyclist"),
                                              ("Fußgänger", "pedestrian"), ("Streifenwagen", "police")])
def test_german_vehicle_words_are_agents(noun, agent_type):
    assert (agent_type, "stop", "front") in agents(f"A {noun} waits in front of the ego vehicle.")


@pytest.mark.parametrize("prompt, expected", [
    ("The ego turns left at the crossroads. From the opposite direction comes a van.",
     ("car", "go_straight", "road_of_straight")),
    ("The ego waits at the junction. From the right comes a motorbike.",
     ("motorcycle", "go_straight", "road_of_right_turn")),
    ("The ego drives on. Behind the ego truck follows a small car.", ("car", "go_straight", "back")),
])
def test_a_place_then_its_verb_then_who_comes_there(prompt, expected):
    assert expected in agents(prompt) and len(agents(prompt)) == 2


def test_an_order_after_a_place_keeps_the_ego_as_the_one_who_acts():
    assert agents("In the left lane, follow a car.") == [("car", "go_straight", "ego"), ("car", "go_straight", "front")]


@pytest.mark.parametrize("prompt, ego_type", [("Ego LKW turns right, a PKW in front turns also right.", "truck"),
                                              ("The ego bus turns right, a car in front turns also right.", "bus")])
def test_a_vehicle_noun_after_ego_is_the_egos_own(prompt, ego_type):
    assert agents(prompt) == sorted([("car", "turn_right", "front"), (ego_type, "turn_right", "ego")])


def test_a_driver_who_gets_out_walks_and_over_the_street_is_across_it():
    assert ("pedestrian", "cross_the_road", "front_right") in agents(
        "A van stands on the hard shoulder ahead on the right. The driver gets out and walks over the street in "
        "front of the ego.")


def test_behind_it_before_its_noun_places_the_noun_behind_the_one_named_before():
    assert agents("At a crossroads the ego turns left. From the opposite direction comes a car, and directly "
                  "behind it a second car.") == [("car", "go_straight", "road_of_straight")] * 2 + [
        ("car", "turn_left", "ego")]


def test_the_edge_of_the_road_is_no_side_lane_and_the_side_of_an_overtake_may_come_late():
    assert agents("A cyclist rides on the right border of the road in front of the ego.") == [
        ("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]
    assert ("car", "change_lane_to_left", "ego") in agents(
        "The ego drives behind a bus. The ego overtakes the standing bus over the left lane.")


def test_letters_with_marks_are_read_as_plain_letters():
    assert [t.word for t in tokenize("Der Fußgänger, a coupé")] == ["der", "fussganger", ",", "a", "coupe"]
    assert agents("On the Bundesstraße a coupé is parked ahead.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front")]


# -- news reports -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("Police said a pickup stopped in front of a driverless shuttle on Main Street.",
     [("bus", "go_straight", "ego"), ("car", "stop", "front")]),
    ("According to parents who were there, a robotaxi slowed behind a bus.",
     [("bus", "go_straight", "front"), ("car", "go_straight", "ego")]),
])
def test_the_automated_vehicle_of_a_news_report_is_the_ego_and_its_sources_are_no_agents(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "A bus stopped ahead of a driverless taxi on Main Street. The taxi waited.",
    "A driverless taxi passed a parked van. The taxi behaved as designed.",
])
def test_the_egos_own_noun_said_again_is_the_ego(prompt):
    assert [a for a in agents(prompt) if a[2] != "ego"] != [] and len(agents(prompt)) == 2


# -- what the ego is, said in passing -------------------------------------------------------------------

@pytest.mark.parametrize("prompt", [
    "My car is a 2017 Camry and a bus waits ahead.",
    "A 2019 white Tesla waits ahead of the ego.",
])
def test_a_model_year_is_no_count(prompt):
    assert len(agents(prompt)) == 2


@pytest.mark.parametrize("prompt, ego_type", [
    ("The ego car, a beat-up Volvo, crawls along behind a cyclist.", "car"),
    ("Sam's old coach -- the ego -- rolls along behind a cyclist.", "bus"),
    ("The pickup (our ego car) rolls along behind a cyclist.", "car"),
])
def test_a_noun_phrase_set_off_beside_the_ego_says_what_the_ego_is(prompt, ego_type):
    assert agents(prompt) == sorted([(ego_type, "go_straight", "ego"), ("cyclist", "go_straight", "front")])


def test_a_list_beside_the_ego_is_not_what_the_ego_is():
    assert len(agents("A truck, the ego, and a van wait at the light.")) == 3


# -- screenplays -------------------------------------------------------------------------------------------

SCREENPLAY = """EXT. MARKET SQUARE - DAY - RAIN

The ego car idles at the kerb. A LORRY rumbles past on the right.

                    JO
          (muttering)
     Kids these days, cycling everywhere.

CUT TO:

INT. THE LORRY CAB - CONTINUOUS

The driver yawns."""


def test_a_scene_heading_says_where_and_when_and_dialogue_is_no_description():
    scene = lower(SCREENPLAY).scenario
    assert (scene.weather.condition, scene.weather.time) == ("mid_rain", "noon")
    assert agents(SCREENPLAY) == [("car", "stop", "ego"), ("truck", "go_straight", "right")]


def test_a_screenplay_character_who_drives_is_at_the_ego_wheel_and_their_kin_ride_along():
    page = ("EXT. DOCK ROAD - NIGHT\n\nJO and her little brother SAM sit in silence. The ego car waits at a red "
            "light while a VAN crosses from the left.\n\nOnce the van is gone, Jo pulls straight ahead.")
    assert agents(page) == [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn"),
                            ("car", "stop", "ego")]


def test_the_pronoun_of_a_screenplay_character_at_the_wheel_is_the_ego():
    page = ("EXT. HARBOUR ROAD - NIGHT\n\nMAYA's hatchback idles at the give-way line. A TAXI sweeps past from the "
            "right. Maya waits.\n\nOnce the taxi has gone, she turns left.")
    assert agents(page) == [("car", "go_straight", "road_of_right_turn"), ("car", "stop", "ego"),
                            ("car", "turn_left", "ego")]


def test_the_storys_hero_and_their_pronoun_are_the_ego():
    found = agents("A tipper truck is parked just ahead of our heroine. She glances in her mirror and eases out "
                   "into the right lane. A cyclist in that lane is coming up behind her.")
    assert found == [("car", "change_lane_to_right", "ego"), ("cyclist", "go_straight", "back_right"),
                     ("truck", "stop", "front")], found


@pytest.mark.parametrize("prompt, expected", [
    ("A bus stops ahead. My trusty old Volvo pulls into the left lane.", ("car", "change_lane_to_left", "ego")),
    ("I swing our little Fiat out into the right lane.", ("car", "change_lane_to_right", "ego")),
    ("I steer my hatchback into the left lane.", ("car", "change_lane_to_left", "ego")),
])
def test_the_speakers_own_vehicle_however_described_is_the_ego_and_steering_it_into_a_lane_changes_lane(
        prompt, expected):
    found = agents(prompt)
    assert expected in found and sum(a[2] == "ego" for a in found) == 1, found


def test_whose_the_ego_car_is_in_a_screenplay_is_at_its_wheel():
    page = ("EXT. BYPASS - NIGHT\n\nThe ego car, DEV's battered estate, rolls along the left lane. A white VAN in "
            "the right lane pulls level with him and lurches left into his lane.")
    assert agents(page) == [("car", "change_lane_to_left", "right"), ("car", "go_straight", "ego")]


def test_the_kin_of_a_screenplay_driver_named_by_her_pronoun_ride_along():
    page = ("EXT. QUAYSIDE - NIGHT\n\nANA and her grumpy teenage son sit in silence. A LORRY rumbles past on "
            "the left. Ana waits, then pulls out behind it.")
    found = agents(page)
    assert not any(a[0] == "pedestrian" for a in found) and [a[0] for a in found].count("truck") == 1, found


@pytest.mark.parametrize("prompt, condition", [("Rain hammers the windscreen as the ego drives.", "hard_rain"),
                                               ("Rain patters on the roof as the ego drives.", "soft_rain")])
def test_rain_said_by_what_it_does(prompt, condition):
    assert lower(prompt).scenario.weather.condition == condition


def test_the_heros_own_vehicle_is_the_ego():
    assert agents("Our hero's taxi cruises along behind a bus.") == [("bus", "go_straight", "front"),
                                                                    ("car", "go_straight", "ego")]


def test_doing_the_same_as_the_ego_is_its_action_from_ones_own_place():
    assert agents("A van crosses from the left. The ego car waits at the line. Two cars behind it do the same.") == [
        ("car", "go_straight", "road_of_left_turn"), ("car", "stop", "back"), ("car", "stop", "back"),
        ("car", "stop", "ego")]


@pytest.mark.parametrize("prompt, action", [
    ("The ego follows a coach, then eases into the left lane.", "change_lane_to_left"),
    ("The ego follows a coach, then slides over into the right lane.", "change_lane_to_right"),
])
def test_gentle_verbs_of_a_lane_change(prompt, action):
    assert ("car", action, "ego") in agents(prompt)


def test_a_drivers_shoulder_is_no_road_shoulder():
    van = list(lower("He checks over his shoulder and sees a van waiting on the left.").scenario.agents())[1]
    assert (van.relative_to_ego, van.road_type) == ("left", "driving")


def test_police_lights_are_no_traffic_light():
    assert "traffic_light" not in road("Red and blue light washes over the road as the ego passes a police car.") \
        .required_signals


# -- insurance claims: what happened after, and what the car is --------------------------------------------

@pytest.mark.parametrize("prompt, count", [
    ("The car behind me (gray Ford Escape) hit me.", 2),
    ("The car behind me (silver Honda, older gentleman driving) hit me.", 2),
    ("The ego waits while a van (and a bus behind it) passes.", 3),
])
def test_a_bracket_saying_an_agents_make_names_no_second_agent(prompt, count):
    assert len(agents(prompt)) == count


def test_right_into_the_back_of_me_is_no_side():
    assert ("car", "go_straight", "back") in agents("The van behind me rolled right into the back of me.")


@pytest.mark.parametrize("prompt", [
    "I was heading down Lincoln St when a bus pulled out.",
    "A bus waits ahead. The cab company was no help.",
    "A semi drifted over and hit my driver side mirror.",
    "A man stepped out in front of me and I gave a statement to the police.",
    "A taxi came in from the right. There is a yield sign there for people entering.",
    "A bus full of people passes the ego.",
])
def test_streets_firms_car_parts_the_police_afterwards_and_people_in_general_are_no_agents(prompt):
    assert len(agents(prompt)) == 2


def test_people_crossing_are_still_agents():
    assert len(agents("The ego gives way to people crossing in front of it.")) == 3


@pytest.mark.parametrize("prompt, has, without", [
    ("A man stepped out in the middle of the block, nowhere near a crosswalk.", set(), {"crosswalk"}),
    ("It was about 6 am and just getting light out when a van pulled out.", set(), set()),
])
def test_far_from_a_crossing_and_first_light_are_no_objects(prompt, has, without):
    spec = road(prompt)
    assert set(spec.required_signals + spec.required_objects) == has
    assert set(spec.without_signals + spec.without_objects) == without


@pytest.mark.parametrize("prompt, expected", [
    ("A kid on a bike cut across the road right in front of me.", ("cyclist", "cross_the_road", "front")),
    ("I swerved but still clipped a man who stepped out in front of me.", ("car", "go_straight", "ego")),
    ("I was in the roundabout going around when a taxi came in from the right.", ("car", "go_straight", "ego")),
    ("An ambulance came up behind me with the lights and siren going so I pulled over to the right and stopped.",
     ("car", "stop", "ego")),
])
def test_claim_narratives_read(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt", ["A van pulled out. The van driver waved.",
                                    "A minivan pulled out. The minivan driver waved."])
def test_the_driver_of_a_named_vehicle_is_that_vehicle(prompt):
    assert len(agents(prompt)) == 2


def test_a_date_is_no_time_of_day():
    assert lower("On 6/14 a bus stopped in front of me.").scenario.weather is None


def test_an_ambulances_lights_are_no_traffic_light_but_the_green_is():
    assert road("An ambulance comes up behind me with the lights and siren going.").required_signals == ()
    assert road("You've got the green but a fire truck crosses.").required_signals == ("traffic_light",)


def test_cutting_in_and_forcing_the_ego_to_stop_blocks_it():
    assert agents("A van cut in front of the ego, forcing it to stop.") == [("car", "block_the_ego", "front"),
                                                                           ("car", "stop", "ego")]


def test_a_clock_time_written_with_dots_ends_no_sentence_and_a_crowd_said_again_is_the_same_people():
    prompt = "After 10 p.m. a crowd of fans crossed while the ego waited. Once the crowd had cleared, the ego went."
    assert lower(prompt).scenario.weather.time == "night"
    assert len([a for a in agents(prompt) if a[0] == "pedestrian"]) == 2


def test_a_counted_group_with_the_ego_set_off_in_it_includes_the_ego():
    assert agents("Three cars, the ego car bringing up the rear, crawl toward the bridge.") == [
        ("car", "go_straight", "ego"), ("car", "go_straight", "front"), ("car", "go_straight", "front")]


@pytest.mark.parametrize("side", ["left", "right"])
def test_pulling_out_of_a_side_road_and_turning_into_the_egos_lane_is_a_turn_towards_it(side):
    prompt = f"A van pulled out of a side road on my {side} and turned into my lane right in front of me."
    assert ("car", f"turn_{side}", f"road_of_{side}_turn") in agents(prompt)


def test_the_narrators_kin_are_passengers_unless_on_foot():
    assert len(agents("I was taking my mother to her appointment when a van hit me. My mother is fine.")) == 2
    assert ("pedestrian", "cross_the_road", "front") in agents("My son was crossing the road when a van came.")


@pytest.mark.parametrize("prompt", [
    "We were three cars stopped at the red light, mine was the second one.",
    "We were three cars stopped at the red light, mine was the second one. Then the first car went.",
])
def test_we_were_n_cars_counts_the_ego_and_its_place_splits_the_rest(prompt):
    assert sorted(a for a in agents(prompt) if a[2] != "ego") == [("car", "stop", "back"), ("car", "stop", "front")]


def test_a_parked_vehicle_with_its_lights_flashing_stays_parked():
    assert ("truck", "stop", "front_right") in agents(
        "There was a tow truck parked up ahead on my right with all its lights flashing.")


def test_what_the_narrator_thought_an_agent_did_is_not_what_it_did():
    assert ("car", "go_straight", "road_of_straight") in agents(
        "I was turning left. I thought the oncoming van was turning, so I started my turn, and it came straight "
        "through.")
    assert ("car", "turn_left", "road_of_straight") in agents("I was turning left. The oncoming van was turning too.")


def test_it_inside_a_place_is_the_ego_only_when_the_ego_is_named():
    assert agents("Give me a scene, ego in the right lane with a truck ahead of it.") == [
        ("car", "go_straight", "ego"), ("truck", "go_straight", "front")]


def test_an_ego_opening_its_clause_with_a_participle_takes_the_finite_verb():
    assert agents("A robotaxi travelling behind the truck stopped for twenty seconds.") == [
        ("car", "stop", "ego"), ("truck", "go_straight", "front")]


def test_any_name_the_ego_was_given_names_it_again():
    prompt = ("Outside the Elm Park gates, a driverless shuttle bus waited for a cyclist crossing from the right. "
              "Once the cyclist had passed, the shuttle pulled away.")
    assert [a for a in agents(prompt) if a[0] == "bus"] == [("bus", "go_straight", "ego"), ("bus", "stop", "ego")]


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
    """A guard against reading worse: a little under where the dev split stands (it grows with each new hand's
    voices, which are hard on arrival)."""
    scores = _scores(CORPUS / "dev")
    if scores is None:
        pytest.skip("the corpus is not in this checkout")
    aa, ra, wa = scores
    assert aa >= 0.88 and ra >= 0.95 and wa >= 0.95, scores


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


@pytest.mark.parametrize("prompt, expected", [
    # an inflected verb with a slip in its stem: a letter missed, one doubled, two swapped
    ("the ego car is truning lfet at teh junction adn a van is comming from the oposite direciton",
     [("car", "go_straight", "road_of_straight"), ("car", "turn_left", "ego")]),
    ("bsu stoped ahaed of me so i chnaged lanes to the left",
     [("bus", "stop", "front"), ("car", "change_lane_to_left", "ego")]),
    ("a pedestrain is crosing infront of me, i stoped",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "front")]),
])
def test_typing_slips_in_verbs_and_short_words_are_read_as_the_words_meant(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    # "doubler": to overtake, with its side said "by the left"; "le sens": the direction
    ("On the motorway a lorry doubles us by the right while a van circulates in the other sense.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "front_left"), ("truck", "go_straight", "back_right")]),
    # "s'arrêter", "au feu rouge", "traverser"
    ("My car is arrested at the feu rouge and an old man traverses the street in front of it.",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "front")]),
    # "stationné en double file", "se rabattre sur la voie de droite"
    ("A taxi is stationed in double file ahead of the ego vehicle, so the ego vehicle goes back on the left lane.",
     [("car", "change_lane_to_left", "ego"), ("car", "stop", "front")]),
    # "un poids lourd", "à contresens": an oncoming vehicle on a road without junction
    ("Far from the crossroads, a heavy weight arrives in the opposite sense.",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "front_left")]),
])
def test_calques_of_french_are_read_as_the_english_meant(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    # "arriver par la droite", "brûler le feu rouge"
    ("At the crossroad a van arrives by the right and burns the feu rouge.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_right_turn")]),
    # "le feu passe au vert": a later stage
    ("My car waits at the feu rouge; when the feu passes to green I turn at right.",
     [("car", "stop", "ego"), ("car", "turn_right", "ego")]),
    # "derrière un ballon": after it, into the road ahead
    ("A little girl runs on the roadway behind a ball.", [("car", "go_straight", "ego"),
                                                         ("pedestrian", "cross_the_road", "front")]),
    # "le véhicule ego", "arriver en face": one ego, and an oncoming car
    ("On the narrow road the vehicle ego must stop on the side because a van arrives in face of it.",
     [("car", "go_straight", "front_left"), ("car", "stop", "ego")]),
    # "se rabattre": to pull back in ahead of the one passed
    ("A scooter doubles my car by the left and folds back brutally in front of it.",
     [("car", "go_straight", "ego"), ("motorcycle", "change_lane_to_right", "back_left")]),
])
def test_calques_of_french_signals_sides_and_sequences(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("The car which is ahead of the ego vehicle brakes hard.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("The van that is in front of me stops suddenly.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("The lorry which drives behind us flashes its lights.", [("car", "go_straight", "ego"), ("truck", "go_straight", "back")]),
    # the relative ends at its own verb: what the main clause says of the ego is no place of the car
    ("The car which turns left is the ego.", [("car", "turn_left", "ego")]),
])
def test_a_definite_noun_placed_by_the_ego_in_its_relative_clause_is_another_road_user(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Two vans wait in a queue ahead of us, we are the last one. The first one turns left, the second one turns right.",
     [("car", "go_straight", "ego"), ("car", "turn_left", "front"), ("car", "turn_right", "front")]),
    ("We are three cars in a line, I am the last one. Suddenly the first one brakes, the second one stops behind it.",
     [("car", "go_straight", "ego"), ("car", "stop", "front"), ("car", "stop", "front")]),
    ("Three cars including the ego drive in a line, the ego is the last one. The first one stops. The second one "
     "turns right.", [("car", "go_straight", "ego"), ("car", "stop", "front"), ("car", "turn_right", "front")]),
])
def test_the_first_one_and_the_second_one_are_members_of_the_group_the_ego_is_the_last_of(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A pickup backs out of a driveway on the left as I drive past.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "front_left")]),
    ("A taxi pulls out of a parking space on the right and blocks me, so I stop.",
     [("car", "block_the_ego", "front_right"), ("car", "stop", "ego")]),
    # said to be behind, it is behind
    ("A car reverses out of a parking space behind me.", [("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
])
def test_a_vehicle_out_of_a_place_off_the_road_joins_it_ahead_on_its_side(prompt, expected):
    assert agents(prompt) == expected


def test_a_calque_is_read_only_where_it_means_nothing_else_in_english():
    assert "folded" in [t.word for t in tokenize("Wait until the stop arm has folded back in.")]
    assert agents("A double parked van is ahead of a double decker bus.") == agents(
        "A double-parked van is ahead of a double decker bus.")
    assert road("At the crossroad with feux tricolores, I turn left.").required_signals == ("traffic_light",)
    assert road("The ego marks the stop at the crossroad and then turns at right.").required_signals == ("stop",)
    scene = lower("At the crossroad a van which comes from the right does not respect the stop.").scenario
    assert scene.road.required_signals == ("stop",) and [a.behavior for a in scene.agents() if not a.is_ego] == [
        "aggressive"]


@pytest.mark.parametrize("prompt, expected", [
    # two words typed as one
    ("ego turnsleft at the junction and a bus goes straightahead from the opposite side",
     [("bus", "go_straight", "road_of_straight"), ("car", "turn_left", "ego")]),
    # a letter missed in a four-letter word
    ("car on my rigt merges into my lane", [("car", "change_lane_to_left", "right"), ("car", "go_straight", "ego")]),
])
def test_words_run_together_and_short_words_missing_a_letter_are_read_apart_and_whole(prompt, expected):
    assert agents(prompt) == expected


def test_a_run_together_sign_is_read_and_english_compounds_stay_whole():
    assert road("theres a stopsign and a ped crossing, im going strait").required_signals == ("stop",)
    assert [t.word for t in tokenize("somewhere nowhere sideways")] == ["somewhere", "nowhere", "sideways"]
    assert "targetvehicle" in [t.word for t in tokenize("the targetvehicle changes lane")]  # an identifier


def test_a_stage_opens_when_the_traffic_light_named_in_full_turns_green_without_a_comma():
    for prompt in ("The ego waits at the line. When the traffic light goes green it turns right.",
                   "I wait at the junction and as soon as the traffic lights turn green I turn right."):
        scene = lower(prompt).scenario
        assert [[a.action for a in s.agents if a.is_ego] for s in scene.stages] == [["stop"], ["turn_right"]]


def test_a_slip_that_spells_another_word_is_read_as_meant_only_among_its_words():
    assert agents("a lorry came form the left at the junction") == [("car", "go_straight", "ego"),
                                                                  ("truck", "go_straight", "road_of_left_turn")]
    assert "form" in [t.word for t in tokenize("the cars form a queue ahead of me")]
    assert agents("the van infront suddenly breaks hard") == [("car", "go_straight", "ego"), ("car", "stop", "front")]
    assert ("truck", "stop", "front") in agents("a lorry ahead of us broke down")


@pytest.mark.parametrize("prompt, expected", [
    # articles dropped: a bare noun said to be there is introduced, not the ego named again
    ("ego car turning right and theres car coming from the other direction",
     [("car", "go_straight", "road_of_straight"), ("car", "turn_right", "ego")]),
    ("ego car going straight and there is car parked on the right",
     [("car", "go_straight", "ego"), ("car", "stop", "front_right")]),
    # and the first one, the second one, with no article
    ("three cars incl ego in a line, ego is last one. first one stops. second one turns left",
     [("car", "go_straight", "ego"), ("car", "stop", "front"), ("car", "turn_left", "front")]),
])
def test_terse_typing_without_articles(prompt, expected):
    assert agents(prompt) == expected


def test_a_word_of_english_is_never_read_as_a_slip_of_another():
    words = {t.word for t in tokenize("he was tuning the radio, touring the form of the speedo during a commute")}
    assert {"tuning", "touring", "form", "speedo", "during", "commute"} <= words
    assert not any(t.misspelt for t in tokenize("he was tuning the radio, touring the form of the speedo"))


# -- general classes: reports, instructions, later stages ------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    # a person crossing from a side with no junction named is ahead on that side, and makes no junction
    ("jaywalker crossing from the left on a foggy night",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left")]),
    # 'the vehicle' named before anyone else is the report's protagonist, the ego
    ("The vehicle had been travelling at about 30 km/h when a pedestrian stepped off the kerb on the right "
     "and crossed in front of it.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right")]),
    # the ego braking without coming to a halt is a reaction, not its action; "directly ahead" after "merged into
    # its lane" is where the merge ends, so the SUV starts in the lane to its left (CONVENTIONS: "in the lane to my
    # left" that cuts in is left)
    ("The AV was travelling in the right lane when a silver SUV in the lane to its left merged into its lane "
     "directly ahead. The AV braked to avoid a collision.",
     [("car", "change_lane_to_right", "left"), ("car", "go_straight", "ego")]),
    # a bare verb opening a clause and done to the agent just named is an instruction to the ego
    ("stopped bus ahead, overtake it on the left",
     [("bus", "stop", "front"), ("car", "change_lane_to_left", "ego")]),
])
def test_general_reading_of_reports_and_instructions(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_a_braked_halt_is_still_a_stop():
    assert ("car", "stop", "ego") in agents("The test car braked to a halt behind a parked van.")


def test_heavy_rain_as_an_adverb():
    assert lower("It was dark and raining heavily; a cyclist rode ahead.").scenario.weather.condition == "hard_rain"


def test_a_turn_the_ego_makes_in_a_later_stage_puts_the_scene_at_a_junction():
    scene = lower("My car is waiting at a red light, and once it turns green we turn left while an oncoming "
                  "van goes straight.").scenario
    assert scene.road.junction is True
    assert ("car", "go_straight", "road_of_straight") in [(a.type, a.action, a.relative_to_ego)
                                                          for a in scene.agents()]


def test_a_vehicles_own_lights_are_no_traffic_light():
    assert "traffic_light" not in road("The school bus in front of you has stopped with its red lights "
                                       "flashing.").required_signals
    assert "traffic_light" in road("The bus in front of you has stopped at a red light.").required_signals


def test_a_participle_then_a_past_tense_is_the_subjects_finite_verb():
    assert ("cyclist", "change_lane_to_left", "front") in agents(
        "The test vehicle was travelling along a two-lane road. A cyclist riding ahead of it in the same lane "
        "swerved left to avoid an opening car door.")


@pytest.mark.parametrize("prompt, position", [
    ("A tractor unit emerged from a junction on its left and turned right in front of the test vehicle.",
     "road_of_left_turn"),
    ("A taxi came out of a side street to our right and went straight across.", "road_of_right_turn"),
])
def test_a_road_on_a_side_is_a_junction_road_not_the_lane_beside(prompt, position):
    assert any(p == position for _, _, p in agents(prompt))
    assert road(prompt).junction is True


def test_a_driveway_on_a_side_is_no_junction_road():
    assert road("A delivery van pulled out of a driveway on the right in front of the test car.").junction is not True


def test_parked_vehicles_after_from_between_are_scenery():
    assert agents("Two children ran out into the road from between parked vehicles on the left.") == sorted([
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left"),
        ("pedestrian", "cross_the_road", "front_left")])


def test_the_narrator_is_the_ego_and_a_lane_named_by_its_side_is_one_of_several():
    lowered = lower("ugh, rainy evening, I'm in the slow lane and there's a pickup glued to my bumper the whole way")
    assert agents("I'm in the slow lane and there's a pickup glued to my bumper") == sorted([
        ("car", "go_straight", "ego"), ("car", "go_straight", "back")])
    assert lowered.scenario.road.lanes == 2
    assert any("lanes >= 2" in note for note in lowered.notes)
    assert road("I'm driving and a pickup is glued to my bumper").lanes < 2


def test_drifting_towards_the_ego_from_a_side_is_a_lane_change_into_its_lane():
    scene = lower("Our car was cruising along when a lorry on our left began to drift towards us.").scenario
    assert ("truck", "change_lane_to_right") in [(a.type, a.action) for a in scene.agents()]
    assert scene.road.lanes >= 2


@pytest.mark.parametrize("prompt, time_of_day", [
    ("At 3 pm a bus pulled out in front of the test car.", "noon"),
    ("The sun was going down when a cyclist crossed in front of the ego.", "sunset"),
    ("In the early hours a van stopped ahead of the ego.", "night"),
    ("The sun had just set when our car rolled up to the crossroads.", "sunset"),
    ("At approximately 7:45 PM, the test vehicle was struck from behind by a motorcycle.", "sunset"),
    ("At 12:30 am a bus stopped ahead of the ego.", "night"),
])
def test_times_of_day_as_people_write_them(prompt, time_of_day):
    assert lower(prompt).scenario.weather.time == time_of_day


def test_the_pedestrian_crossing_ahead_is_a_crossing_when_a_verb_follows():
    scene = lower("The pedestrian crossing ahead is blocked by a van that has broken down.").scenario
    assert [a.type for a in scene.agents() if not a.is_ego] == ["car"]
    assert "crosswalk" in scene.road.required_objects
    assert ("pedestrian", "cross_the_road", "front") in agents("A pedestrian crossing ahead of the ego.")


def test_a_car_pulled_over_on_the_shoulder_stands_and_the_next_sentences_verb_is_an_instruction():
    found = agents("A cop car is pulled over on the shoulder up ahead with its lights flashing. "
                   "Slow down and move over to the left lane.")
    assert ("police", "stop", "front_right") in found and ("car", "change_lane_to_left", "ego") in found


def test_a_side_after_the_ego_named_as_a_reference_is_the_subjects():
    assert ("cyclist", "go_straight", "back_right") in agents(
        "You want to turn right on red. A bicyclist is coming up behind you on your right.")


def test_walking_out_into_the_road_is_crossing_it():
    assert ("pedestrian", "cross_the_road", "front") in agents(
        "this dude on his phone just walks straight out into the road in front of me")


def test_those_the_ego_queues_behind_stand_too():
    found = agents("motorway, night, ego stopped in queue behind two lorries")
    assert found.count(("truck", "stop", "front")) == 2
    assert ("truck", "go_straight", "front") in agents("ego stopped behind a lorry that keeps going")


def test_a_side_after_the_place_an_agent_moves_into_is_the_places():
    assert ("truck", "go_straight", "front") in agents(
        "A lorry ahead is reversing into a loading bay on the left, so the ego has to wait behind it.")


@pytest.mark.parametrize("prompt, action", [
    ("we enter a roundabout and take the first exit", "turn_right"),
    ("the ego takes the third exit at the roundabout", "turn_left"),
    ("the ego takes the second exit at the roundabout", "go_straight"),
])
def test_roundabout_exits_are_turns(prompt, action):
    assert ("car", action, "ego") in agents(prompt)


def test_a_hand_held_stop_sign_is_not_the_roads():
    assert "stop" not in road("A crossing guard is standing in the crosswalk holding a stop sign.").required_signals
    assert "stop" in road("The ego waits at a stop sign.").required_signals


def test_a_rural_road_says_nothing_about_junctions():
    assert road("rural road, two cyclists riding abreast ahead, ego overtakes").junction is None
    assert road("rural road with no junctions, a cyclist ahead").junction is False


def test_the_vehicles_possessive_names_the_ego_not_a_new_car():
    found = agents("The vehicle under test was travelling when a jogger ran across the road and was struck by "
                   "the vehicle's front left corner.")
    assert [t for t, _, _ in found].count("car") == 1


def test_an_infinitive_after_a_past_tense_leaves_it_the_main_verb():
    assert ("car", "change_lane_to_left", "ego") in agents(
        "A truck was parked partially in the lane ahead, so the test vehicle moved into the left lane to pass it.")


def test_reports_and_level_crossings_are_no_agents_or_crosswalks():
    assert [t for t, _, _ in agents("The police report states that the AV was stopped at a red light.")] == ["car"]
    assert "crosswalk" not in road("The ego approaches a railroad crossing.").required_objects


@pytest.mark.parametrize("prompt", [
    "The police report states that vehicle 1 (the AV) was stopped at a red signal when vehicle 2, a pickup, "
    "failed to stop and struck it from behind.",
    "Unit 1, the test vehicle, was stopped at a red light. Unit 2, a pickup, struck it from behind.",
])
def test_numbered_vehicles_of_police_reports_are_labels(prompt):
    assert agents(prompt) == sorted([("car", "stop", "ego"), ("car", "go_straight", "back")])


def test_people_waiting_at_a_crossing_are_at_it():
    assert ("pedestrian", "stop", "near_the_crosswalk") in agents(
        "A woman with a stroller is waiting at the zebra crossing as the ego approaches.")


def test_a_bare_noun_after_the_ego_and_a_comma_is_another_agent_not_an_apposition():
    assert ("car", "go_straight", "road_of_straight") in agents(
        "Scenario: unprotected left turn. Actors: ego, oncoming SUV (going straight), pedestrian on the far crosswalk.")
    assert [t for t, _, _ in agents("The ego, a city bus, turns left.")] == ["bus"]


def test_those_the_ego_waits_behind_in_traffic_or_at_a_red_light_stand_too():
    assert agents("The ego waits at a red light behind a bus.") == sorted([("car", "stop", "ego"),
                                                                          ("bus", "stop", "front")])
    assert agents("The ego vehicle is stuck in traffic behind two cars.").count(("car", "stop", "front")) == 2


@pytest.mark.parametrize("prompt", [
    "Oncoming traffic: a car and a motorcycle. The ego turns left at the lights.",
    "ego turns left at the lights; oncoming: a car and a motorcycle",
])
def test_a_heading_of_places_places_the_agents_listed_after_it(prompt):
    assert agents(prompt) == sorted([("car", "turn_left", "ego"), ("car", "go_straight", "road_of_straight"),
                                     ("motorcycle", "go_straight", "road_of_straight")])


@pytest.mark.parametrize("prompt, expected", [
    ("dude, a cop just flew past me on the left with sirens blaring", ("police", "go_straight", "back_left")),
    ("a cop just passed us on the left", ("police", "go_straight", "back_left")),
    ("The ego car gets cut off by a black SUV from the left lane.", ("car", "block_the_ego", "front_left")),
])
def test_chat_interjections_pronoun_objects_and_cut_offs(prompt, expected):
    found = agents(prompt)
    assert expected in found and len(found) == 2


def test_a_speed_and_unit_before_a_road_noun_is_its_limit():
    assert "speed_64" in road("The AV was doing 45 on a 40 mph road.").required_objects + \
        road("The AV was doing 45 on a 40 mph road.").required_signals
    assert not any(w.startswith("speed_") for w in road("The ego drives at 40 km/h behind a bus.").required_objects)


def test_traffic_circles_are_junctions():
    assert road("At the traffic circle, the ego yields to a car.").junction is True


def test_an_adverb_between_a_noun_and_its_participle_keeps_it_the_nouns():
    assert agents("At the traffic circle, the ego yields to a car already circulating from the left.") == sorted([
        ("car", "stop", "ego"), ("car", "go_straight", "road_of_left_turn")])


def test_a_pronoun_takes_no_participle_so_the_past_tense_after_it_is_finite():
    assert ("car", "stop", "front") in agents(
        "A learner driver in front of me stalled at the mini roundabout, and the van behind me nearly went into "
        "the back of me.")


def test_my_lane_is_the_egos_lane():
    assert ("truck", "change_lane_to_right", "left") in agents(  # indicating: traffic keeps left, nearside is left
        "The lorry in the nearside lane indicated right and started to move across into my lane.")
    assert ("truck", "change_lane_to_left", "right") in agents(
        "The truck in the right lane started to move across into my lane.")


def test_a_verb_with_by_after_a_copula_is_a_passive():
    assert agents("A parked van is passed by the ego on a narrow street.") == sorted([
        ("car", "go_straight", "ego"), ("car", "stop", "front")])


def test_a_adjective_one_is_another_agent_of_the_same_kind():
    found = agents("A red car is being driven in front of the ego, and a blue one behind it.")
    assert [t for t, _, _ in found].count("car") == 3 and ("car", "go_straight", "front") in found


@pytest.mark.parametrize("prompt, kind", [
    ("An HGV was in lane 1 ahead of me. The artic then braked hard.", "truck"),
    ("A tractor-trailer was ahead in the right lane. The semi braked hard.", "truck"),
    ("A jogger ran across the road. The runner was wearing headphones.", "pedestrian"),
])
def test_a_definite_other_name_for_the_only_one_of_its_kind_named_before_is_that_one(prompt, kind):
    assert [t for t, _, _ in agents(prompt)].count(kind) == 1, agents(prompt)


def test_a_definite_other_name_in_the_same_clause_is_another_one():
    assert [t for t, _, _ in agents("The oncoming SUV and the pickup behind it both stop.")].count("car") == 3


def test_a_second_agent_after_and_then_by_repeats_the_passive():
    found = agents("The ego is overtaken on the right by an ambulance and then by a fire engine.")
    assert ("firetruck", "go_straight", "back_right") in found


def test_a_place_of_traffic_places_the_vehicles_it_counts():
    assert agents("unprotected left turn, oncoming traffic two cars").count(("car", "go_straight",
                                                                            "road_of_straight")) == 2


def test_numbered_stage_markers_start_stages_and_count_nothing():
    scene = lower("Stage 1: the ego follows a bus. Stage 2: the bus stops and a car overtakes the ego on the "
                  "left.").scenario
    assert len(scene.stages) == 2
    assert sorted(a.type for a in scene.agents()) == ["bus", "car", "car"]


def test_a_vague_person_doing_what_only_vehicles_do_drives_a_car():
    assert ("car", "turn_left", "front") in agents("some guy turns left in front of the ego")
    assert ("pedestrian", "cross_the_road", "front") in agents("a man crosses the road in front of the ego")


def test_the_side_the_ego_passes_on_is_its_manoeuvre_not_the_place_of_what_it_passes():
    assert agents("the ego drives around the parked van on the left") == sorted([
        ("car", "change_lane_to_left", "ego"), ("car", "stop", "front")])


def test_the_verb_after_forced_the_ego_to_is_the_egos():
    assert agents("A box truck double-parked in the travel lane forced the AV to change lanes to the left.") == \
        sorted([("car", "change_lane_to_left", "ego"), ("truck", "stop", "front")])


def test_a_vehicle_named_then_said_what_it_is_in_brackets_is_one_agent():
    found = agents("AV stationary at red light. Third-party vehicle (silver hatchback) made contact with the rear "
                   "of the AV at low speed.")
    assert found == sorted([("car", "stop", "ego"), ("car", "go_straight", "back")])


def test_people_crossing_outside_the_crosswalk_are_not_at_it():
    prompt = ("While proceeding straight through the intersection, a pedestrian entered the roadway from the left "
              "outside of the crosswalk.")
    assert ("pedestrian", "cross_the_road", "front_left") in agents(prompt)
    assert "crosswalk" in road(prompt).required_objects


def test_pulling_out_from_a_side_at_a_junction_comes_from_that_road():
    assert ("car", "stop", "road_of_right_turn") in agents(  # waiting: pulling out is still to come
        "A taxi on our right was waiting to pull out at the crossroads.")
    assert ("cyclist", "go_straight", "right") in agents("a cyclist coming up fast on its inside")


def test_a_couple_on_its_own_is_two_people():
    assert agents("an elderly couple cross the road ahead").count(("pedestrian", "cross_the_road", "front")) == 2
    assert agents("a couple of cars wait at the light").count(("car", "stop", "front")) == 2


@pytest.mark.parametrize("prompt, condition", [
    ("Under grey skies after a shower, a cyclist overtakes the ego.", "wet_cloudy"),
    ("The tarmac was still damp from the morning rain when a bus pulled out.", "wet"),
])
def test_rain_that_has_fallen_leaves_the_road_wet(prompt, condition):
    scene = lower(prompt).scenario
    assert scene.weather.condition == condition and len(scene.stages) == 1


def test_a_manoeuvre_said_to_be_impossible_does_not_happen():
    assert ("truck", "go_straight", "front") in agents("slow tractor on a country road, overtaking not possible")


def test_crossing_from_a_side_through_a_signal_is_at_a_junction():
    assert ("cyclist", "go_straight", "road_of_left_turn") in agents("cyclist running the red light from the left")
    assert road("cyclist running the red light from the left").junction is True
    assert road("a car from the left lane cuts in at a red light").junction is not True


def test_oncoming_traffic_at_the_lights_is_at_a_junction_and_without_them_is_not():
    assert ("car", "go_straight", "road_of_straight") in agents(
        "The ego waits at a red light while an oncoming car goes straight.")
    assert ("bus", "go_straight", "front_left") in agents(
        "In snowy conditions, the ego is followed by a truck while a bus coming the other way passes on the left.")


def test_a_speed_someone_is_doing_is_no_limit():
    assert [w for w in road("I was stuck behind a learner doing 20 in a 40 zone for ages").required_objects +
            road("I was stuck behind a learner doing 20 in a 40 zone for ages").required_signals
            if w.startswith("speed_")] == ["speed_40"]


def test_ride_hailing_cars_and_e_scooters_and_the_people_they_pick_up():
    assert agents("bro the Uber in front of me just stopped dead in the middle of the road to pick someone up") \
        == sorted([("car", "go_straight", "ego"), ("car", "stop", "front")])
    assert [t for t, _, _ in agents("this e-scooter guy comes flying down the road")].count("cyclist") == 1


def test_a_test_case_name_is_no_agent_but_a_prompt_of_only_a_case_name_is_read():
    assert agents("Test case CCRs: car-to-car rear stationary, target vehicle stationary in ego lane, VUT "
                  "approaching at 50 km/h.") == sorted([("car", "go_straight", "ego"), ("car", "stop", "front")])
    assert "pedestrian" in [t for t, _, _ in agents(
        "CPLA: car-to-pedestrian longitudinal adult walking along the road in the same direction as the VUT.")]


def test_bracketed_descriptions_of_the_ego_and_a_vru():
    assert agents("Actors: EGO (sedan, turning right), VRU (cyclist, straight, from behind on the right).") == \
        sorted([("car", "turn_right", "ego"), ("cyclist", "go_straight", "back_right")])


@pytest.mark.parametrize("prompt, expected", [
    ("50 m ahead a bus stops", [("bus", "stop", "front"), ("car", "go_straight", "ego")]),
    ("twenty-five metres ahead a lorry sits in the left lane",
     [("car", "go_straight", "ego"), ("truck", "stop", "front_left")]),
    ("the ego passes two bus stops", [("car", "go_straight", "ego")]),
])
def test_a_fronted_distance_and_place_then_the_subject(prompt, expected):
    assert agents(prompt) == sorted(expected)


@pytest.mark.parametrize("prompt, expected", [
    ("a van undertakes the ego", ("car", "go_straight", "back_right")),
    ("Say there's a bus pulling away from a stop on our left.", ("bus", "change_lane_to_right", "front_left")),
])
def test_undertaking_is_on_the_kerb_side_and_pulling_away_from_a_stop_is_an_origin(prompt, expected):
    assert expected in agents(prompt)


def test_an_alternative_said_with_or_maybe_is_no_second_agent():
    assert len(agents("I think there might be a truck coming from the left, or maybe a van, it's hard to say.")) == 2


@pytest.mark.parametrize("prompt, condition", [
    ("It was a murky morning when a lorry drifted into our lane.", "cloudy"),
    ("It was mizzling as the ego approached the roundabout.", "soft_rain"),
    ("The weather was fine and dry; a bus stops.", "clear"),
])
def test_british_weather_words(prompt, condition):
    assert lower(prompt).scenario.weather.condition == condition


def test_a_flashing_signal_is_a_traffic_light_and_a_vehicles_flashing_lights_are_not():
    assert "traffic_light" in road("You approach an intersection with a flashing red light.").required_signals
    assert "traffic_light" not in road("the bus has stopped with flashing lights").required_signals
    assert ("bus", "stop", "front") in agents("the bus has stopped with flashing lights")


def test_a_limit_said_after_the_road_it_belongs_to():
    assert "speed_105" in road("Four-lane divided highway, 65 mph. A semi is merging.").required_objects + \
        road("Four-lane divided highway, 65 mph. A semi is merging.").required_signals
    found = road("The ego drives on the highway at 65 mph.")
    assert not any(w.startswith("speed_") for w in found.required_objects + found.required_signals)


@pytest.mark.parametrize("prompt, expected", [
    ("R turn, ped crossing side street", ("car", "turn_right", "ego")),
    ("motorbike overtaking on R, wet", ("motorcycle", "go_straight", "back_right")),
    ("jct, no signals, ego straight, car from R turning L", ("car", "turn_left", "road_of_right_turn")),
    ("ego stopped, amb behind, sirens", ("ambulance", "go_straight", "back")),
])
def test_terse_one_letter_sides_and_abbreviations(prompt, expected):
    assert expected in agents(prompt)


def test_car_makes_are_cars_and_the_kerb_is_the_right_side():
    assert ("car", "go_straight", "back") in agents("a BMW came up behind me flashing its headlights")
    assert ("car", "change_lane_to_left", "front_right") in agents("a Ford Focus pulls out from the curb ahead")


# -- generalisation: constructions and words, each with sentences of its own --------------------------------

def test_it_inside_a_place_phrase_names_the_agent_before_not_the_ego():
    found = agents("A removal lorry heads towards us on a straight road with a moped behind it.")
    assert ("motorcycle", "go_straight", "front_left") in found and ("truck", "go_straight", "front_left") in found


@pytest.mark.parametrize("prompt", ["By the time we reach the crossroads the signal has turned amber, so we stop.",
                                    "The light turns green and the ego goes straight through the junction."])
def test_a_signal_changing_colour_is_nobodys_turn(prompt):
    assert not any(action.startswith("turn") for _, action, _ in agents(prompt))


def test_a_condition_said_in_full_ends_at_its_colour_and_starts_a_stage():
    scene = lower("We sit at the lights; when they go green we turn right.").scenario
    assert [[a.action for a in s.agents] for s in scene.stages] == [["stop"], ["turn_right"]]
    assert "traffic_light" in scene.road.required_signals
    scene = lower("Our car waits at a red light, and once it turns green we hang a left.").scenario
    assert [[a.action for a in s.agents] for s in scene.stages] == [["stop"], ["turn_left"]]


@pytest.mark.parametrize("prompt, expected", [
    ("NPC1 is a delivery van stopped on the right ahead.", [("car", "stop", "front_right")]),
    ("Actors:\n- hero: drives straight\n- NPC2: cyclist crossing in front\n- NPC3: stopped bus ahead",
     [("cyclist", "cross_the_road", "front"), ("bus", "stop", "front")]),
])
def test_a_singular_npc_label_is_one_agent_said_what_it_is(prompt, expected):
    assert agents(prompt) == sorted([("car", "go_straight", "ego")] + expected)


@pytest.mark.parametrize("noun, agent_type", [
    ("minivan", "car"), ("station wagon", "car"), ("people carrier", "car"), ("panel van", "car"),
    ("box truck", "truck"), ("tipper truck", "truck"), ("articulated lorry", "truck"), ("18-wheeler", "truck"),
    ("tram", "bus"), ("bendy bus", "bus"), ("e-scooter rider", "cyclist"), ("cargo bike", "cyclist"),
    ("moped rider", "motorcycle"), ("wheelchair user", "pedestrian"), ("toddler", "pedestrian"),
    ("dog walker", "pedestrian"), ("state trooper", "police"), ("fire tender", "firetruck"),
])
def test_a_wide_vocabulary_of_road_users(noun, agent_type):
    assert agent_type in [t for t, _, p in agents(f"There is a {noun} ahead of the ego.") if p != "ego"]


@pytest.mark.parametrize("prompt, expected", [
    ("The estate car ahead of us comes to a standstill.", ("car", "stop", "front")),
    ("A hatchback in the left lane nudges into our lane.", ("car", "change_lane_to_right", "left")),
    ("A van on the right drifts over into the ego's lane ahead of it.", ("car", "change_lane_to_left", "right")),
    # ("ahead of it" after "into the ego's lane" is where the drift ends: it starts level, on the right)
    ("A pensioner steps off the kerb in front of us.", ("pedestrian", "cross_the_road", "front")),
    ("A lorry sits idling ahead of the ego.", ("truck", "stop", "front")),
    ("A pickup on the offside overtakes us.", ("car", "go_straight", "back_right")),  # the offside: a British word
    ("A cyclist rides along on our kerb side.", ("cyclist", "go_straight", "right")),
])
def test_verbs_and_places_as_drivers_say_them(prompt, expected):
    assert expected in agents(prompt)


def test_a_dash_between_words_is_a_pause_and_4x4_is_a_car():
    assert ("car", "go_straight", "back") in agents("A 4x4 sits right on our tail.")
    found = agents("we merge right \u2014 is there a lorry in the lane we're moving into, well behind us?")
    assert ("truck", "go_straight", "back_right") in found


def test_a_child_running_into_the_vuts_path_from_a_side_keeps_that_side():
    assert ("pedestrian", "cross_the_road", "front_left") in agents(
        "A boy runs from the far side into the VUT's path.")
    assert ("car", "block_the_ego", "front_left") in agents(
        "The target car cuts off the ego from the left adjacent lane and halts in the ego lane.")


def test_no_crossing_is_a_crossing_denied_and_a_crossing_kind_is_not_doubled():
    scene = lower("ped: dashes across from the right, no crossing").scenario
    assert "crosswalk" in scene.road.without_objects
    assert ("pedestrian", "cross_the_road", "front_right") in agents("ped: dashes across from the right, no crossing")
    assert lower("Ladder crosswalk ahead; the ego stops before the crossing.").scenario.road.required_objects == \
        ("ladder_crosswalk",)


def test_a_short_word_is_not_corrected_into_an_agent():
    assert len(agents("how would the car cope with a moped behind us")) == 2


def test_the_ego_that_pulls_in_and_stops_stops():
    assert ("car", "stop", "ego") in agents("An ambulance closes in behind, so the ego pulls in and stops.")


def test_a_crossing_from_a_compass_side_is_from_the_egos_side():
    assert ("pedestrian", "cross_the_road", "front_right") in agents(
        "The test car was heading north when a man walked across the road from the east side.")


@pytest.mark.parametrize("prompt, ego_action, other", [
    ("tractor crawling ahead, overtake it on the left", "change_lane_to_left", ("truck", "go_straight", "front")),
    ("police car behind with blues on, pull over to the right", "change_lane_to_right",
     ("police", "go_straight", "back")),
    ("A fire engine is behind us and we move over to the left.", "change_lane_to_left",
     ("firetruck", "go_straight", "back")),
])
def test_an_order_after_a_description_and_a_new_subject_after_a_copula_are_the_egos(prompt, ego_action, other):
    found = agents(prompt)
    assert ("car", ego_action, "ego") in found and other in found


def test_the_queue_ahead_of_a_waiting_ego():
    assert agents("we're sat at a red light with 2 cars in front of us") == sorted(
        [("car", "stop", "ego"), ("car", "stop", "front"), ("car", "stop", "front")])
    assert agents("fifth in the queue at the lights") == sorted([("car", "stop", "ego")] + [("car", "stop", "front")] * 4)
    assert agents("third in line behind a coach") == sorted(
        [("car", "stop", "ego"), ("bus", "stop", "front"), ("car", "stop", "front")])


@pytest.mark.parametrize("prompt, expected", [
    ("Ego: turning left. Bus: oncoming, going straight.", [("car", "turn_left", "ego"),
                                                          ("bus", "go_straight", "road_of_straight")]),
    ("cyclist: riding on our right; lorry: parked ahead", [("car", "go_straight", "ego"),
                                                           ("cyclist", "go_straight", "right"),
                                                           ("truck", "stop", "front")]),
    ("ped: strolls across in front from the left", [("car", "go_straight", "ego"),
                                                    ("pedestrian", "cross_the_road", "front_left")]),
    ("Actor_2 - motorbike - behind the ego - overtakes on the right", [("car", "go_straight", "ego"),
                                                                     ("motorcycle", "go_straight", "back_right")]),
])
def test_keys_that_name_agents_on_one_line_are_their_subjects(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_a_clock_time_or_a_case_title_is_no_agent_key():
    assert agents("At 7:15 am a van stopped ahead of the ego.") == sorted(
        [("car", "go_straight", "ego"), ("car", "stop", "front")])
    assert agents("Cut-in: a target vehicle in the right lane cuts in.") == sorted(
        [("car", "go_straight", "ego"), ("car", "change_lane_to_left", "right")])


def test_a_ticket_title_line_oracle_lines_and_role_tags_name_no_agents():
    prompt = ("Tractor overtake on a B road\n\nSetup: hero follows a tractor (NPC1) on a two-lane road.\n"
              "Actors: tractor is slow, hero overtakes it on the right.\n"
              "Expected: hero brakes, no collision.\nAC: overtake completes within 8 s.")
    assert agents(prompt) == sorted([("car", "change_lane_to_right", "ego"), ("truck", "go_straight", "front")])


@pytest.mark.parametrize("prompt, expected", [
    ("The VUT approaches a child pedestrian target crossing from the farside.",
     ("pedestrian", "cross_the_road", "front_left")),
    ("police NPC stops in front of the hero", ("police", "stop", "front")),
    ("A bicyclist target (EBT) rides ahead of the VUT in the same lane.", ("cyclist", "go_straight", "front")),
])
def test_a_role_noun_after_a_noun_keeps_the_nouns_type(prompt, expected):
    found = agents(prompt)
    assert expected in found and len(found) == 2


def test_a_short_name_in_brackets_is_the_same_agent_and_names_it_later():
    found = agents("The VUT closes on a slow Soft Car Target (SCT) in its lane. After 3 s the SCT brakes to a stop.")
    assert found == sorted([("car", "go_straight", "ego"), ("car", "stop", "front")])


def test_a_manoeuvre_named_after_a_preposition_is_nobodys_predicate():
    assert ("car", "go_straight", "ego") in agents(
        "A lorry in the left lane cuts in; the gap at the start of the manoeuvre is 20 m.")


def test_in_which_after_a_lane_change_is_the_lane_moved_into():
    assert ("bus", "go_straight", "back_right") in agents(
        "The ego makes a lane change to the right adjacent lane, in which a coach comes up from behind.")


def test_a_verb_after_without_is_denied_so_the_past_tense_before_it_is_finite():
    assert ("car", "turn_right", "road_of_left_turn") in agents(
        "At the crossroads a hatchback from the left turned right in front of us without even signalling.")


def test_i_takes_no_participle():
    assert ("car", "change_lane_to_right", "ego") in agents(
        "A bin lorry was stopped in my lane, so I pulled over into the right lane to get past it.")


def test_a_crossing_cyclist_from_a_side_at_a_junction_comes_from_that_road():
    assert ("cyclist", "cross_the_road", "road_of_right_turn") in agents(
        "I was turning left at the junction when a lad on a bike shot across from the right.")


def test_a_riders_own_lamps_are_no_traffic_light():
    assert "traffic_light" not in road("A cyclist crossed ahead at dusk; she had no lights on.").without_signals


def test_the_driver_is_the_vehicle_named_before():
    assert len(agents("A minibus pulled out in front of us. The driver never looked.")) == 2


def test_a_vague_person_in_the_queue_drives():
    assert ("car", "go_straight", "back") in agents(
        "We stopped at the lights and the bloke behind us rolled into our back bumper.")


def test_doing_the_same_repeats_the_previous_agents_manoeuvre_and_place():
    found = agents("At the lights a van coming the other way turned left, then a second van did the same.")
    assert found.count(("car", "turn_left", "road_of_straight")) == 2


def test_labelled_members_of_a_list_are_separate_agents():
    assert agents("Actors: veh_1, veh_2 (cars) park ahead on the right.").count(("car", "stop", "front_right")) == 2
    assert ("pedestrian", "cross_the_road", "front") in agents("Actor_3 = jogger crossing in front of the hero")


def test_what_the_ego_follows_shares_its_lane():
    assert ("truck", "go_straight", "front") in agents("We follow a tanker in the left lane of a dual carriageway.")


@pytest.mark.parametrize("prompt, expected", [
    ("could u make a van cutting in from the right lane in front of me pls", ("car", "go_straight", "ego")),
    ("Can you please build a scene where a bus stops ahead of me?", ("car", "go_straight", "ego")),
])
def test_you_asked_to_make_a_scene_is_not_the_ego(prompt, expected):
    assert expected in agents(prompt)


def test_a_greeting_is_no_time_of_day_and_chat_abbreviations_are_read():
    scene = lower("morning! 3 ppl standing on the pavement on the left, ego drives by").scenario
    assert scene.weather is None
    assert [(a.type, a.action) for a in scene.agents()].count(("pedestrian", "on_the_sidewalk")) == 3


@pytest.mark.parametrize("prompt, expected", [
    ("Lead car changed lane R at the last moment.", ("car", "change_lane_to_right", "front")),
    ("Ego in L lane, truck overtaking in R lane.", ("truck", "go_straight", "back_right")),
    ("kid ran out from the L kerb", ("pedestrian", "cross_the_road", "front_left")),
])
def test_one_letter_sides_in_driving_phrases(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("Ego is taking right turn. One bus is coming from front side and going straight.",
     ("bus", "go_straight", "road_of_straight")),
    ("Ego is going to left lane because an ambulance is coming behind of ego.", ("car", "change_lane_to_left", "ego")),
    ("The ego is keeping left on a country road while a tractor comes the other way.", ("car", "go_straight", "ego")),
    ("A man is standing on footpath of the road in which ego is turning, ego turns left.",
     ("pedestrian", "on_the_sidewalk", "at_the_destination")),
])
def test_non_native_phrasings_of_positions_and_manoeuvres(prompt, expected):
    assert expected in agents(prompt)


def test_a_vehicle_stopped_in_front_of_the_ego_stands_and_its_warning_lights_are_its_own():
    scene = lower("A police car is stopped in front of the ego with its warning lights on.").scenario
    assert ("police", "stop", "front") in [(a.type, a.action, a.relative_to_ego) for a in scene.agents()]
    assert "traffic_light" not in scene.road.required_signals


def test_a_condition_in_the_past_tense_starts_a_stage_and_the_road_the_ego_turned_into_is_its_destination():
    scene = lower("We sat at the lights behind a lorry. When they went green we turned right, and a man was "
                  "crossing the street we were turning into.").scenario
    assert [a.action for a in scene.stages[-1].agents if a.is_ego] == ["turn_right"]
    assert ("pedestrian", "cross_the_road", "at_the_destination") in [
        (a.type, a.action, a.relative_to_ego) for a in scene.agents()]


def test_stopped_traffic_holds_the_ego_and_those_beside_it_at_a_red_light_wait_too():
    assert ("car", "stop", "ego") in agents("a moped weaving between lanes in a traffic jam")
    assert ("car", "stop", "left") in agents("We're held at a red light with a van alongside in the left lane.")


def test_a_denial_ends_with_its_sentence():
    found = road("ped: darts out from the right, no crossing. road: mid-block, no junction.")
    assert found.junction is False and "crosswalk" in found.without_objects


@pytest.mark.parametrize("prompt, expected", [
    ("ped crossing front at dusk", ("pedestrian", "cross_the_road", "front")),
    ("The ego goes straight on the cross-road while a van comes from the opposite side.",
     ("car", "go_straight", "road_of_straight")),
    ("You have a green arrow for a protected right.", ("car", "turn_right", "ego")),
])
def test_short_forms_of_crossing_people_crossroads_and_turns(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("Ego merging R onto the dual carriageway.", ("car", "change_lane_to_right", "ego")),
    ("SIM-7 cut-in\n\nActors:\n- Ped_2: crosses from the right in front of the hero",
     ("pedestrian", "cross_the_road", "front_right")),
    ("a jogger ran straight out in front of me", ("pedestrian", "cross_the_road", "front")),
    ("One van is overtaking from right side and after overtake it is coming in ego lane.",
     ("car", "change_lane_to_left", "back_right")),
])
def test_more_short_forms_keys_with_underscores_and_after_a_bare_verb(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("If a scooter is in your blind spot on the right, don't change lanes.", ("motorcycle", "go_straight", "back_right")),
    ("ego straight, van from R runs red", ("car", "go_straight", "road_of_right_turn")),
    ("Unit 2, a grey hatchback, turned left across the path of Unit 1, the AV, which was going straight.",
     ("car", "turn_left", "road_of_straight")),
    ("A car waiting on the road on the left pulls out and turns right across our path.",
     ("car", "turn_right", "road_of_left_turn")),
    ("ego R, oncoming bus straight, ped at dest", ("pedestrian", "cross_the_road", "at_the_destination")),
    ("A Vauxhall in lane two undertook us.", ("car", "go_straight", "back_right")),
    ("A dog walker is standing on the verge to our right.", ("pedestrian", "on_the_sidewalk", "right")),
])
def test_places_said_in_other_ways(prompt, expected):
    assert expected in agents(prompt)


def test_pulling_out_at_a_junction_enters_it_and_the_tail_of_a_jam_is_approached():
    assert ("car", "go_straight", "ego") in agents("At the give-way we pull out to go straight; a van comes from the right.")
    assert ("car", "go_straight", "ego") in agents("The tail end of a traffic jam: two cars stationary in our lane ahead.")


def test_one_on_each_side_behind_and_a_counted_list_after_a_colon():
    assert agents("Two scooters come up behind us, one on each side.") == sorted(
        [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "back_left"),
         ("motorcycle", "go_straight", "back_right")])
    assert agents("There are three vans: one in front of the ego, one behind and one on the left.") == sorted(
        [("car", "go_straight", "ego"), ("car", "go_straight", "front"), ("car", "go_straight", "back"),
         ("car", "go_straight", "left")])


def test_and_then_keeps_the_subject_and_the_car_behind_it_is_another_car():
    assert ("truck", "turn_left", "front") in agents("The lorry ahead signals left and then turns left into a yard.")
    assert len(agents("A cab pulls up on the right, and the car behind it goes round it.")) == 3


def test_a_crossing_patrol_is_a_person_and_zooming_out_is_crossing():
    assert ("pedestrian", "cross_the_road", "front") in agents("A school crossing patrol steps out in front of us.")
    assert ("cyclist", "cross_the_road", "front_left") in agents("a kid on a bike zooms out from the left")


def test_the_first_and_the_second_are_members_of_the_group_just_counted():
    assert agents("We are passed by two vans, the first on the left and the second on the right.") == sorted(
        [("car", "go_straight", "ego"), ("car", "go_straight", "back_left"), ("car", "go_straight", "back_right")])


def test_a_vehicle_crossing_left_to_right_is_cross_traffic_at_a_junction():
    scene = lower("ego waits at the stop line, bus crossing L to R").scenario
    assert ("bus", "go_straight", "road_of_left_turn") in [(a.type, a.action, a.relative_to_ego) for a in scene.agents()]
    assert scene.road.junction is True


def test_jargon_abbreviations_ev_lv_and_a_vru_crossing():
    assert ("ambulance", "go_straight", "back") in agents("EV approaching from the rear with sirens on.")
    assert ("car", "stop", "front") in agents("LV decelerates to a standstill.")
    assert ("pedestrian", "cross_the_road", "front_left") in agents("VRU crossing from the farside, no crosswalk.")
    assert ("bus", "stop", "front_right") in agents("a bus at a bus stop on the right")


@pytest.mark.parametrize("prompt, expected", [
    ("Ego is following slow-moving tractor on country road.", [("car", "go_straight", "ego"),
                                                               ("truck", "go_straight", "front")]),
    ("VUT approaches stationary target car in same lane.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("Police car came up from behind, passed ego on left and carried on.", [("car", "go_straight", "ego"),
                                                                           ("police", "go_straight", "back_left")]),
    ("White van parked on verge ahead, child hidden behind van runs out.", [("car", "go_straight", "ego"),
                                                                          ("car", "stop", "front_right"),
                                                                          ("pedestrian", "cross_the_road", "front_right")]),
])
def test_sentences_without_articles(prompt, expected):
    assert agents(prompt) == sorted(expected)


@pytest.mark.parametrize("prompt, expected", [
    ("The AV turns right and a cyclist crosses the road the AV is turning into.",
     ("cyclist", "cross_the_road", "at_the_destination")),
    ("A van ahead in the AV lane brakes to a halt.", ("car", "stop", "front")),
    ("The ego turns left; a woman crosses on the zebra crossing of the street it turns into.",
     ("pedestrian", "cross_the_road", "near_the_crosswalk")),
    ("Left on red here: the ego turns left after stopping.", ("car", "turn_left", "ego")),
    ("The ego bus pulls out right from the stop.", ("bus", "change_lane_to_right", "ego")),
    ("ambulance behind with siren, pull over to the left", ("car", "change_lane_to_left", "ego")),
])
def test_the_ego_named_any_way_and_mirror_images_read_alike(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("lead car ahead of the hero changed lane L at the last moment", ("car", "change_lane_to_left", "front")),
    ("A man is waiting on the pavement of the road in which the hero is turning; the hero turns right.",
     ("pedestrian", "on_the_sidewalk", "at_the_destination")),
    ("Could my lorry turn left at the lights?", ("truck", "turn_left", "ego")),
    ("Fire lorry coming from the right at the junction.", ("firetruck", "go_straight", "road_of_right_turn")),
])
def test_the_ego_takes_no_participle_and_names_of_its_vehicle(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A motorbike filtered between the lanes on our right.", ("motorcycle", "go_straight", "back_right")),
    ("the bloke in front slams on", ("car", "stop", "front")),
    ("mate in front pulled out onto the main road without looking", ("car", "go_straight", "ego")),
    ("jct, ego L turn, van opp straight", ("car", "go_straight", "road_of_straight")),
    ("ego 40kph, ped pavement L", ("pedestrian", "on_the_sidewalk", "left")),
])
def test_british_and_terse_idioms(prompt, expected):
    assert expected in agents(prompt)


def test_a_group_of_n_is_n_agents_and_counted_parked_cars_between_are_agents():
    assert agents("a family of three crosses at the zebra").count(
        ("pedestrian", "cross_the_road", "near_the_crosswalk")) == 3
    assert [t for t, _, _ in agents("A boy runs out from between two parked vans.")].count("car") == 3  # ego + 2


def test_a_state_in_the_past_perfect_is_before_the_story_and_a_singular_car_is_no_heading():
    assert ("car", "change_lane_to_left", "right") in agents(
        "We were cut up by an Audi that had been sitting in the right lane.")
    assert ("pedestrian", "on_the_sidewalk", "right") in agents("ego 30kph, van R lane behind, ped pavement R")


def test_one_of_them_is_a_member_of_a_counted_group_and_n_of_them_counts_a_bare_plural():
    assert agents("Four cyclists wait at the lights ahead; one of them rides off.").count(
        ("cyclist", "stop", "front")) == 3
    assert agents("Children are crossing in front of us, five of them.").count(
        ("pedestrian", "cross_the_road", "front")) == 5


def test_the_car_from_the_other_side_is_another_car():
    found = agents("At the crossroads the car from the left and the car from the right both stop.")
    assert ("car", "stop", "road_of_left_turn") in found and ("car", "stop", "road_of_right_turn") in found
    assert ("cyclist", "cross_the_road", "front") in agents("A kid on a bike wobbles off the kerb in front of us.")


def test_a_manoeuvre_naming_a_test_is_nobodys_predicate():
    assert ("car", "change_lane_to_right", "ego") in agents("Merge test. Ego merging R onto the main road.")


def test_a_vehicle_the_ego_queues_behind_stands_in_the_first_stage_whatever_it_does_later():
    scene = lower("First we wait at a red light behind a lorry. Then the light turns green and we both go.").scenario
    assert ("truck", "stop", "front") in [(a.type, a.action, a.relative_to_ego) for a in scene.stages[0].agents]


def test_parts_of_a_counted_group_and_one_lane_each_way():
    found = agents("Six cyclists: two on the left, four behind us.")
    assert found.count(("cyclist", "go_straight", "left")) == 2 and found.count(("cyclist", "go_straight", "back")) == 4
    assert agents("Two vans come the other way on a road with one lane each way.").count(
        ("car", "go_straight", "front_left")) == 2
    assert sorted(agents("Of the three lorries ahead, the first turns right, the second stops and the third goes "
                         "straight.")) == sorted([("car", "go_straight", "ego"), ("truck", "turn_right", "front"),
                                                  ("truck", "stop", "front"), ("truck", "go_straight", "front")])


def test_the_driver_of_a_vehicle_is_that_vehicle_with_what_it_was_said_to_do():
    assert agents("A child was waved across by the driver of a parked lorry on the right.") == sorted(
        [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front"), ("truck", "stop", "front_right")])


def test_the_ego_at_a_red_light_or_a_stop_line_stands_and_a_new_subject_after_and_has_its_own_clause():
    assert agents("What happens when an ambulance is behind us and we're at a red light?") == sorted(
        [("ambulance", "go_straight", "back"), ("car", "stop", "ego")])
    assert ("car", "go_straight", "ego") in agents("There are no stop signs, and the ego is at the junction.")


def test_the_noun_after_a_verb_and_before_a_participle_is_an_object():
    assert ("car", "go_straight", "ego") in agents("How would the AV avoid a cyclist swerving into its lane?")


def test_a_fronted_side_is_a_place_not_the_owner_of_the_noun_after_it():
    assert agents("On the right-hand side a man with a dog waits to cross.") == sorted(
        [("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "front_right")])
    assert ("car", "go_straight", "ego") in agents("A van in the lane to the left of the ego cuts in front of it.")


@pytest.mark.parametrize("prompt, expected", [
    ("there's a bin lorry sitting in my lane and I gotta go around it", ("car", "change_lane_to_left", "ego")),
    ("bloke in a pickup cut me off", ("car", "block_the_ego", "front")),
    ("right turn, oncoming traffic, 3 cars", ("car", "go_straight", "road_of_straight")),
    ("scooter lane splitting on the left at a red", ("motorcycle", "go_straight", "back_left")),
    ("fire engine coming up fast behind, everyone pulling over to the right", ("car", "change_lane_to_right", "ego")),
])
def test_casual_phrasings_of_drivers_detours_and_traffic(prompt, expected):
    assert expected in agents(prompt)


def test_the_ego_that_waits_then_goes_waits_first_and_turns_after():
    scene = lower("Run 4: ego turning right out of a side road. Ego waited, then went once the gap opened.").scenario
    assert [[a.action for a in s.agents if a.is_ego] for s in scene.stages] == [["stop"], ["turn_right"]]


def test_run_numbers_and_written_ordinals():
    assert len(agents("R7 - two vans from the left; ego waits for the 2nd van.")) == 3  # the 2nd is one of them
    assert not any(p == "right" for _, _, p in agents("R12: a bus stops ahead."))


def test_the_egos_right_and_the_languages_own_position_names():
    assert ("cyclist", "go_straight", "right") in agents("Then a cyclist on the ego's right goes straight.")
    assert ("bus", "go_straight", "road_of_straight") in agents(
        "ego=car, action=turn_right; agent1=bus, position=road_of_straight, action=go_straight")


def test_an_order_after_a_conditional_sentence_is_the_egos():
    found = agents("If you're on the motorway and a van in the lane to your right starts drifting into your lane, "
                   "sound your horn and brake.")
    assert ("car", "change_lane_to_left", "right") in found  # the braking is the ego's, so the van cuts in only


def test_a_bare_car_after_a_bare_ego_is_another_car():
    assert ("car", "go_straight", "road_of_straight") in agents(
        "Ego want to turn left but opposite car is coming so ego must wait.")


def test_mirror_images_read_alike_for_overtaking_then_blocking_and_merging_then_moving_over():
    for side in ("left", "right"):
        assert (("police", "block_the_ego", f"back_{side}") in agents(
            f"A patrol car overtook the ego on the {side}, pulled in ahead of it and stopped."))
        assert ("car", f"change_lane_to_{side}", "ego") in agents(
            f"We're merging onto the motorway from the slip road; we move {side} into the lane.")


@pytest.mark.parametrize("noun, agent_type", [("car", "car"), ("lorry", "truck"), ("taxi", "car"),
                                              ("motorcyclist", "motorcycle")])
def test_a_grid_of_lane_manoeuvres_reads_alike_for_every_vehicle(noun, agent_type):
    for text, action, position in [
            ("in the left lane cuts in front of us", "change_lane_to_right", "left"),
            ("from the right lane cuts in ahead of us", "change_lane_to_left", "right"),
            ("overtakes us on the left", "go_straight", "back_left"),
            ("swerves into our lane from the left and stops", "block_the_ego", "front_left"),
            ("is tailgating us", "go_straight", "back"),
            ("comes towards us on a straight road", "go_straight", "front_left")]:
        for sentence in (f"A {noun} {text}.", f"the {noun} {text}"):
            assert (agent_type, action, position) in agents(sentence), sentence


def test_a_vehicle_stopped_on_the_road_is_no_stop_painted_on_it():
    scene = lower("The ego turns right while a lorry is stopped on the road we turn into.").scenario
    assert ("truck", "stop", "at_the_destination") in [(a.type, a.action, a.relative_to_ego) for a in scene.agents()]
    assert "stop_sign_on_road" not in scene.road.required_objects + scene.road.required_signals


# -- voices written by other hands: research papers, witness statements, transcripts, briefs, forums ----------

def test_a_research_papers_subject_vehicle_is_the_ego():
    found = agents("Case B: the SV turns right at a signalised crossroads while a POV coming from the SV's left "
                   "continues straight.")
    assert found == [("car", "go_straight", "road_of_left_turn"), ("car", "turn_right", "ego")]


def test_numbered_svs_beside_a_named_ego_stay_surrounding_vehicles():
    found = agents("The ego keeps its lane; SV1 in the right adjacent lane slows down and SV2 follows the ego.")
    assert sum(1 for a in found if a[2] == "ego") == 1 and len(found) == 3


@pytest.mark.parametrize("prompt, ego_type", [
    ("I am a bus driver and a pickup overtook me on the right.", "bus"),
    ("At the time I was employed as a lorry driver. A moped pulled out in front of me.", "truck"),
    ("The SV is an ambulance; a hatchback ahead of the SV pulls over to let it pass.", "ambulance"),
])
def test_a_first_person_or_subject_vehicle_says_what_the_ego_is(prompt, ego_type):
    scene = lower(prompt).scenario
    assert scene.ego.type == ego_type
    assert [a.type for a in scene.agents() if not a.is_ego].count(ego_type) == 0


@pytest.mark.parametrize("prompt, expected, gone", [
    ("uh I'm turning left and a bus, no wait, a lorry is coming the other way", ("truck", "go_straight",
                                                                                 "road_of_straight"), "bus"),
    ("so a skateboarder I mean a pensioner walks out in front of me", ("pedestrian", "cross_the_road", "front"),
     "cyclist"),
    ("there's a lorry sorry a coach parked just ahead of me", ("bus", "stop", "front"), "truck"),
    ("A motorbike, not a scooter rider, filters past me on the right.", ("motorcycle", "go_straight", "back_right"),
     None),
])
def test_speech_that_corrects_itself_keeps_only_the_corrected_agent(prompt, expected, gone):
    found = agents(prompt)
    assert expected in found
    assert len(found) == 2, found
    if gone:
        assert all(a[0] != gone for a in found)


@pytest.mark.parametrize("prompt, expected", [
    ("Can someone explain this junction? I was going straight and a bus turned right across me.",
     [("bus", "turn_right", "road_of_straight"), ("car", "go_straight", "ego")]),
    ("Why do people even bother indicating. A pickup swerved into my lane from the right.",
     [("car", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]),
])
def test_a_forum_posts_questions_to_its_readers_name_nobody_in_the_scene(prompt, expected):
    assert agents(prompt) == expected


def test_a_driver_sounding_the_horn_drives_and_driving_like_a_maniac_is_aggressive():
    found = agents("A minivan overtakes me on the right, driving like a maniac, and the bloke behind me leans on "
                   "his horn.")
    assert found == [("car", "go_straight", "back"), ("car", "go_straight", "back_right"),
                     ("car", "go_straight", "ego")]
    scene = lower("A minivan overtakes me on the right, driving like a maniac.").scenario
    assert [a.behavior for a in scene.agents() if not a.is_ego] == ["aggressive"]


@pytest.mark.parametrize("prompt, expected", [
    ("One of our artics is sat at a red light waiting to turn right.", [("truck", "turn_right", "ego")]),
    ("Driver in one of our 44-tonne artics is sat at a red light waiting to turn right at the crossroads. Two cars "
     "coming the other way. Once the light goes green he starts his turn.",
     [("car", "go_straight", "road_of_straight"), ("car", "go_straight", "road_of_straight"), ("truck", "stop", "ego"),
      ("truck", "turn_right", "ego")]),
])
def test_one_of_our_vehicles_is_the_fleets_vehicle_the_scene_is_told_from(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Two children walk along the pavement on the car's left.",
     [("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "left"), ("pedestrian", "on_the_sidewalk", "left")]),
    ("A cyclist rides on the bus's right.", [("bus", "go_straight", "ego"), ("cyclist", "go_straight", "right")]),
])
def test_a_side_said_of_a_vehicle_by_its_possessive_places_the_subject_from_that_vehicle(prompt, expected):
    assert agents(prompt) == expected


def test_a_witness_on_foot_is_a_pedestrian_and_the_vehicle_described_is_the_ego():
    found = agents("I was standing on the pavement a little way ahead when I saw a green minibus heading east. "
                   "A moped was travelling just in front of the minibus, and the minibus ran into it.")
    assert found == [("bus", "go_straight", "ego"), ("motorcycle", "go_straight", "front"),
                     ("pedestrian", "on_the_sidewalk", "front_left")]


def test_a_driving_witness_stays_the_ego():
    found = agents("I was driving along the high street when I saw a delivery van pull out in front of me.")
    assert ("car", "go_straight", "ego") in found and all(a[0] != "pedestrian" for a in found)


def test_a_make_and_a_ridden_vehicle_are_re_mentions():
    assert agents("A grey Toyota Corolla was ahead of us. The Toyota braked hard.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front")]
    assert len(agents("A cyclist was riding in front of us and a taxi clipped the back wheel of the bicycle.")) == 3


def test_what_a_witness_saw_does_the_verb_that_follows():
    assert agents("I noticed a coach in front of me stop without warning.") == [
        ("bus", "stop", "front"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("You sat in the middle lane for ages, with a tanker in the right lane level with you.",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "right")]),
    ("The player car sits in the left lane; a bus ahead in the right lane moves across in front of it.",
     [("bus", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]),
])
def test_the_ego_sitting_in_a_named_lane_is_where_it_drives_not_a_stop(prompt, expected):
    assert agents(prompt) == expected


def test_a_cars_width_is_a_measure_not_a_car():
    assert agents("You overtook a cyclist and left a car's width.") == [
        ("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]


def test_numbered_lanes_say_the_lane_count_and_which_side():
    scene = lower("Dual carriageway. I was in lane one of two and a minibus in lane two came level with me.").scenario
    assert scene.road.lanes == 2
    assert [(a.type, a.relative_to_ego) for a in scene.agents() if not a.is_ego] == [("bus", "right")]
    scene = lower("On the M1 in lane three of four, a tanker in lane two just ahead of me moved into my lane.").scenario
    assert scene.road.lanes == 4
    assert [(a.type, a.action, a.relative_to_ego) for a in scene.agents() if not a.is_ego] == [
        ("truck", "change_lane_to_right", "front_left")]


def test_a_role_in_brackets_names_the_agent_before_it():
    assert agents("The SV meets an oncoming minivan (POV) on a rural road with no junction.") == [
        ("car", "go_straight", "ego"), ("car", "go_straight", "front_left")]
    assert agents("The SV comes upon a principal other vehicle (POV) stationary in its lane ahead.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("Schoolchild Dash. A boy runs out from behind a parked lorry on the left in front of the ego.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left"), ("truck", "stop", "front_left")]),
    ("Level 7 (Taxi Rank Rumble). The player drives behind a bus.", [("bus", "go_straight", "front"),
                                                                   ("car", "go_straight", "ego")]),
])
def test_a_title_case_headline_names_the_case_not_its_agents(prompt, expected):
    assert agents(prompt) == expected


def test_hyphenated_role_labels_and_a_verb_after_the_subject_vehicles_side():
    assert agents("POV-2, a white minivan in the right lane ahead of the SV, moves into the SV's lane.") == [
        ("car", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]
    assert ("bus", "turn_right", "road_of_right_turn") in agents(
        "A bus approaching from the SV's right turns right while the SV goes straight over the crossroads.")
    assert lower("The SV is a marked police car; a taxi ahead pulls over.").scenario.ego.type == "police"


@pytest.mark.parametrize("prompt, ego_action", [
    ("The player is stuck behind a crawling milk float van on a narrow lane.", "go_straight"),
    ("honestly I'm stuck doing fifteen behind a tractor", "go_straight"),
    ("We're stuck at the lights behind a lorry.", "stop"),
])
def test_stuck_behind_something_still_moving_is_driving_slowly(prompt, ego_action):
    assert lower(prompt).scenario.ego.action == ego_action


@pytest.mark.parametrize("prompt, ego_action", [
    ("A moped shot out of a side road on my left right in front of me. Should I have stopped?", "go_straight"),
    ("Two vans were coming the other way and a skip lorry was parked on my side. Do I have to wait?",
     "go_straight"),
    ("Can I have a scene where the ego turns right at a junction?", "turn_right"),
])
def test_a_question_about_what_ought_to_happen_is_no_account_of_what_did(prompt, ego_action):
    assert lower(prompt).scenario.ego.action == ego_action


def test_counted_people_in_a_question_are_still_agents():
    assert len(agents("how about three people waiting at the kerb on the left while we pass?")) == 4


@pytest.mark.parametrize("prompt, ego_action", [
    ("Could you build a scenario where the ego turns left at a roundabout?", "turn_left"),
    ("Set up a level where the ego turns right while a tram waits.", "turn_right"),
])
def test_a_scene_where_the_ego_turns_is_what_the_ego_does(prompt, ego_action):
    assert lower(prompt).scenario.ego.action == ego_action


def test_a_game_briefs_player_is_the_ego():
    scene = lower("Spawn the player at a crossroads with lights, waiting on red.").scenario
    assert scene.ego.action == "stop" and len(list(scene.agents())) == 1
    assert agents("Drop two vans in the right lane ahead of the player that both cut across in front of it.") == [
        ("car", "change_lane_to_left", "front_right"), ("car", "change_lane_to_left", "front_right"),
        ("car", "go_straight", "ego")]


def test_a_sentence_before_a_colon_is_no_title_and_a_slot_in_keeps_its_side():
    assert agents("The player turns right across the traffic: a coach coming the other way.")[-1] == (
        "car", "turn_right", "ego")
    scene = lower("The player merges right from the slip road and has to slot in between two lorries.").scenario
    assert scene.ego.action == "change_lane_to_right"


def test_the_nearside_is_the_kerb_side_of_the_traffic_described():
    british = agents("I was on the dual carriageway in the offside lane; a lorry in the nearside lane was level with "
                     "me.")
    assert ("truck", "go_straight", "left") in british
    protocol = agents("A pedestrian target walks across from the nearside in front of the VUT at 5 km/h.")
    assert ("pedestrian", "cross_the_road", "front_right") in protocol


@pytest.mark.parametrize("prompt, ego_type", [
    ("I was on duty in a marked police vehicle when a hatchback ahead of me went through the red light.", "police"),
    ("I was driving a coach along the ring road when a van ahead of me braked.", "bus"),
])
def test_the_vehicle_i_was_in_is_the_ego(prompt, ego_type):
    scene = lower(prompt).scenario
    assert scene.ego.type == ego_type
    assert [a.type for a in scene.agents() if not a.is_ego] == ["car"]


def test_where_traffic_keeps_left_an_unsaid_overtaking_is_on_the_right():
    assert ("car", "change_lane_to_right", "ego") in agents(
        "Along the dual carriageway you pulled out to get past a slow tractor.")
    assert ("bus", "go_straight", "back_right") in agents("A minibus overtook us on the motorway.")
    assert ("car", "go_straight", "back_left") in agents("On the interstate a pickup overtook us.")


@pytest.mark.parametrize("prompt, expected", [
    ("A moped was ahead of us, puttering along right in the middle of the lane.",
     ("motorcycle", "go_straight", "front")),
    ("You changed into the left lane and there was a van right there, level with you.",
     ("car", "go_straight", "left")),
])
def test_right_as_exactly_is_no_side(prompt, expected):
    assert expected in agents(prompt)


def test_a_place_then_this_guy_and_his_verb_is_a_new_subject():
    found = agents("so I'm on the bypass two lanes my side and this bloke in the lane on my right just swerves into "
                   "my lane")
    assert found == [("car", "change_lane_to_left", "right"), ("car", "go_straight", "ego")]


def test_a_statements_24_hour_clock_and_a_dark_colour():
    assert lower("At about 0640 hours a lorry stopped ahead of me.").scenario.weather.time == "dawn"
    assert lower("At 2230 hrs a cyclist crossed in front of me.").scenario.weather.time == "night"
    assert lower("A dark grey estate car pulled out in front of me.").scenario.weather is None


def test_vehicles_in_general_in_a_question_are_no_agents_and_straight_at_me_is_oncoming():
    assert agents("A road train was level with me on my left. Why do lorries never let you in?") == [
        ("car", "go_straight", "ego"), ("truck", "go_straight", "left")]
    assert ("car", "go_straight", "road_of_straight") in agents(
        "I was waiting to turn right and a hatchback was coming straight at me.")


def test_drifting_towards_the_kerb_stays_in_the_lane():
    assert lower("All along the high street you kept drifting over towards the kerb.").scenario.ego.action == \
        "go_straight"


def test_coming_round_a_roundabout_is_driving_not_rounding_the_ego():
    assert ("bus", "go_straight", "road_of_left_turn") in agents(
        "On the mini roundabout you waited for a coach coming round from your left.")


def test_a_placed_vehicle_then_what_it_is_in_commas_is_one_agent():
    assert agents("The car behind us, a grey hatchback, braked sharply to a halt.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "back")]
    assert len(agents("A car behind us, a bus and a van are all stopped.")) == 4  # a list, no apposition


@pytest.mark.parametrize("prompt", [
    "The taxi ahead of us pulls over and stops.",
    "A delivery van in front of me pulled over to the kerb and stopped.",
    "The lorry in front pulls in and parks.",
])
def test_pulling_over_to_stop_ends_in_a_stop(prompt):
    assert ("car" if "lorry" not in prompt else "truck", "stop", "front") in agents(prompt)


def test_a_blocker_is_never_placed_straight_behind_the_ego():
    assert agents("The van behind me blocks me in.") == [("car", "block_the_ego", "front"), ("car", "go_straight", "ego")]
    assert ("car", "block_the_ego", "back_left") in agents(  # the lane beside, where it passed: playable
        "A saloon overtakes me on the left, cuts me up and stops dead in front of me.")


def test_counted_vehicles_a_person_steps_out_from_between_are_agents_at_that_kerb():
    assert agents("A boy darts out from the right between two parked vans.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front_right"), ("car", "stop", "front_right"),
        ("pedestrian", "cross_the_road", "front_right")]
    assert road("A boy darts out from the right between two parked vans.").lanes < 2  # parked at the kerb
    assert agents("A lad on a bike shot out from between two lorries on my left.") == [
        ("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "front_left"),
        ("truck", "stop", "front_left"), ("truck", "stop", "front_left")]
    assert len(agents("A kid runs out between parked cars.")) == 2  # uncounted: scenery


def test_the_far_side_of_a_junction_is_across_it():
    assert ("bus", "go_straight", "road_of_straight") in agents(
        "At the crossroads I wait to turn right while a bus comes through from the far side.")
    assert ("truck", "stop", "at_the_destination") in agents(
        "Going straight over the lights, a lorry is parked on the far side of the junction.")
    assert ("car", "stop", "left") in agents("On the dual carriageway a van sits in the far side lane.")


def test_a_vehicle_placed_by_the_ego_is_another_and_what_it_is_follows_in_commas():
    assert agents("The car on my left at the 4-way stop went straight.") == [
        ("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]
    assert agents("At a four-way stop the vehicle on my left, a red minivan, proceeded first.") == [
        ("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]
    assert agents("The car on our right, a silver estate, turned left.") == [
        ("car", "go_straight", "ego"), ("car", "turn_left", "road_of_right_turn")]


def test_a_place_named_by_the_ego_turning_makes_the_ego_turn():
    assert agents("A woman crosses the road where the ego turns left.") == [
        ("car", "turn_left", "ego"), ("pedestrian", "cross_the_road", "at_the_destination")]
    assert lower("a jogger runs across the side road where we are turning right").scenario.ego.action == "turn_right"


def test_braking_in_time_is_an_ego_stop_and_braking_to_avoid_is_a_reaction():
    assert lower("The lorry ahead stopped suddenly but I braked in time.").scenario.ego.action == "stop"
    assert lower("A kid ran out and the AV braked just in time.").scenario.ego.action == "stop"
    assert lower("The AV braked to avoid a collision with the van.").scenario.ego.action == "go_straight"


def test_a_counted_list_shares_the_first_items_oncoming():
    assert agents("At the junction: 2 oncoming cars + 1 scooter, ego turning left.").count(
        ("motorcycle", "go_straight", "road_of_straight")) == 1
    assert ("cyclist", "go_straight", "right") in agents("Two oncoming cars and a cyclist on the right.")


def test_going_around_on_a_side_is_a_lane_change_to_that_side():
    assert lower("A bus was stopped in my lane so I went around on the right.").scenario.ego.action == \
        "change_lane_to_right"
    assert lower("There's a bin lorry stopped ahead, we go round it on the left.").scenario.ego.action == \
        "change_lane_to_left"


def test_no_signal_after_a_manoeuvre_is_no_indicator_not_a_road_without_lights():
    assert "traffic_light" not in road("At the junction the car in front turned left without any signal.").without_signals
    assert "traffic_light" in road("A crossroads with no signals; a truck comes from the left.").without_signals


def test_a_person_pushing_their_bike_is_one_pedestrian():
    assert agents("A lad pushing his bike across the road in front of me.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]
    assert agents("a man walks his bike over the crossing") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]


@pytest.mark.parametrize("prompt, later", [
    ("The ego waits for the cyclist to pass; once clear it makes the turn.", "turn_"),
    ("We hold at the line for the bus; when safe, we turn right.", "turn_right"),
])
def test_a_one_word_condition_ends_where_the_main_clause_begins(prompt, later):
    stages = lower(prompt).scenario.stages
    assert len(stages) == 2 and stages[0].agents[0].action == "stop"
    assert stages[1].agents[0].is_ego and stages[1].agents[0].action.startswith(later)


def test_a_parent_and_her_little_ones_are_counted_people_and_someone_in_a_rule_is_nobody():
    assert agents("A mum and her two little ones cross at the zebra.").count(
        ("pedestrian", "cross_the_road", "near_the_crosswalk")) == 3
    assert [a for a in agents("A girl was on the crossing. Once someone is on a crossing, you stop.")
            if a[2] != "ego"] == [("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_a_blocker_out_of_a_side_road_blocks_from_the_front_and_the_junction_stays():
    lowered = lower("a van pulls out of the road on the right and stops there blocking me")
    assert ("car", "block_the_ego", "front") in agents("a van pulls out of the road on the right and stops there "
                                                       "blocking me")
    assert lowered.scenario.road.junction is True
    assert any("blocks from the front" in note for note in lowered.notes)


def test_the_side_signalled_is_the_side_of_a_turn_or_lane_change_said_without_one():
    assert ("cyclist", "turn_right", "front") in agents(
        "The cyclist ahead of me signalled right and moved out into the middle of the road to turn.")
    assert lower("I indicated right and made the turn into the side road.").scenario.ego.action == "turn_right"
    assert ("bus", "change_lane_to_right", "front") in agents("The bus in front indicates right and changes lane.")


def test_pulling_back_in_after_overtaking_is_a_cut_in_and_a_schoolbus_is_a_bus():
    assert ("truck", "change_lane_to_left", "back_right") in agents(
        "An HGV overtakes us on the motorway and pulls back in too early, forcing us to brake.")
    assert ("bus", "stop", "front_left") in agents("A schoolbus has stopped on the opposite side of the road.")


def test_a_vehicle_in_front_pulling_out_leaves_the_ego_lane_and_overtaking_someone_else_is_no_overtake_of_the_ego():
    assert ("car", "change_lane_to_left", "front") in agents("The car in front pulls out to overtake a cyclist.")
    assert ("cyclist", "change_lane_to_left", "front") in agents(
        "Two cyclists riding side by side ahead of the ego, one of them swerves out to avoid a pothole.")
    assert ("truck", "change_lane_to_right", "front") in agents("On the motorway the lorry in front pulls out.")
    assert ("car", "change_lane_to_right", "front_left") in agents("A car pulls out in front of me.")


def test_vehicles_doing_something_after_with_are_agents_and_speed_as_a_noun_is_no_haste():
    assert agents("I keep stalling when turning left at a busy junction with cars coming from the right.").count(
        ("car", "go_straight", "road_of_right_turn")) == 2
    lowered = lower("Lorry to my left, coach to my right, both doing the same speed as me.")
    assert all(a.behavior != "aggressive" for a in lowered.scenario.agents())


def test_a_percentage_of_the_vehicle_width_counts_no_vehicles_and_stepping_onto_the_crossing_crosses():
    assert agents("An adult pedestrian walks from the nearside into the path of the VUT, struck at 25% of the "
                  "vehicle width.") == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right")]
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in agents(
        "An elderly man is waiting at the zebra crossing; he steps onto the crossing as the player arrives.")
    assert ("pedestrian", "on_the_sidewalk", "right") in agents("A woman steps onto the pavement.")


def test_a_rider_on_a_two_wheeler_is_one_agent_and_running_back_is_no_place_behind():
    assert agents("A delivery rider on an e-bike went through the red from the opposite direction as I turned "
                  "left.") == [("car", "turn_left", "ego"), ("cyclist", "go_straight", "road_of_straight")]
    assert agents("A rider on a motorbike overtakes me.") == [
        ("car", "go_straight", "ego"), ("motorcycle", "go_straight", "back_left")]
    assert ("pedestrian", "cross_the_road", "front") in agents(
        "The pedestrian hesitates in the middle of the road, then runs back to the kerb.")


def test_where_the_ego_ends_in_a_later_stage_does_not_move_what_it_passed():
    stages = lower("The ego overtakes a slow bus by changing to the left lane, then returns to the right lane "
                   "ahead of the bus.").scenario.stages
    assert [(a.type, a.action, a.relative_to_ego) for a in stages[0].agents] == [
        ("car", "change_lane_to_left", None), ("bus", "go_straight", "front")]
    assert stages[1].agents[0].action == "change_lane_to_right"


def test_a_cut_in_from_alongside_starts_level():
    assert ("car", "change_lane_to_left", "right") in agents(
        "A red Audi which had been driving beside me on my right moved across into my lane, directly in front of "
        "me, which made me brake hard.")
    assert ("car", "change_lane_to_left", "right") in agents(
        "A red Audi which was alongside me, on my right, moved into my lane just ahead of me.")


def test_a_light_turning_green_in_its_own_sentence_starts_a_stage():
    stages = lower("Ego stopped at red. Light goes green. Ego turns left. Cyclist on the left goes straight.").scenario.stages
    assert [a.action for a in stages[0].agents] == ["stop"]
    assert ("turn_left", "go_straight") == tuple(a.action for a in stages[1].agents)


def test_a_parked_vehicle_at_the_kerb_ahead_needs_no_second_lane():
    assert road("A pedestrian emerges from behind a parked bus on the right and crosses in front of the ego.").lanes < 2
    assert road("A van is driving on the left ahead of us.").lanes >= 2


def test_vehicles_chasing_the_ego_are_behind_it():
    assert agents("Two police cars chase the player down the highway.") == [
        ("car", "go_straight", "ego"), ("police", "go_straight", "back"), ("police", "go_straight", "back")]
    assert ("police", "go_straight", "back") in agents("A police car is pursuing us.")


def test_running_along_the_pavement_is_no_haste_but_running_across_is():
    assert all(a.behavior != "aggressive" for a in lower(
        "Two joggers are running side by side on the pavement to our left.").scenario.agents())
    assert [a.behavior for a in lower("A child runs across the road.").scenario.agents() if not a.is_ego] == [
        "aggressive"]


@pytest.mark.parametrize("prompt", [
    "A van cuts in from the left lane and then stops dead right in front of us.",
    "The hatchback pulls in from the right, then slams on its brakes in front of me.",
])
def test_a_cut_in_then_a_sudden_stop_in_front_blocks_the_ego(prompt):
    actions = {a.action for a in lower(prompt).scenario.agents() if not a.is_ego}
    assert actions == {"block_the_ego"}


def test_a_cut_in_then_a_gentle_stop_stays_a_cut_in():
    actions = {a.action for a in lower("A taxi cuts in from the left lane, and then it brakes to a stop in "
                                       "front of our car.").scenario.agents() if not a.is_ego}
    assert actions == {"change_lane_to_right"}


def test_pulling_out_to_the_right_on_an_open_road_changes_lane_to_the_right():
    assert ("car", "change_lane_to_right", "ego") in agents("Stuck behind a slow lorry, I pull out to the right "
                                                            "to get past it.")


@pytest.mark.parametrize("prompt, turn", [
    ("I wait at the give way line, then pull out to the left onto the main road while a van comes from the "
     "right.", "turn_left"),
    ("At the T-junction I pull out to the right and a car comes from the left.", "turn_right"),
])
def test_pulling_out_of_a_junction_is_a_turn(prompt, turn):
    scene = lower(prompt).scenario
    assert turn in {a.action for a in scene.agents() if a.is_ego}
    assert scene.road.junction is True


@pytest.mark.parametrize("prompt", [
    "At the crossroads I am going straight on green, but the exit is blocked by a van parked on the far side.",
    "We turn left at the junction and a broken down truck is parked in the road we turn into, obstructing it.",
])
def test_a_parked_vehicle_blocking_the_road_ahead_of_a_junction_stands_at_the_destination(prompt):
    others = [a for a in lower(prompt).scenario.agents() if not a.is_ego]
    assert [(a.action, a.relative_to_ego) for a in others] == [("stop", "at_the_destination")]


def test_a_stopped_car_said_to_block_the_ego_at_the_destination_still_blocks():
    others = [a for a in lower("The ego turns right at the lights. On the road it turns into a car has stopped "
                               "and is blocking the ego.").scenario.agents() if not a.is_ego]
    assert [a.action for a in others] == ["block_the_ego"]


@pytest.mark.parametrize("prompt, kind", [
    ("Two kids on scooters ride along the road ahead of us.", "motorcycle"),
    ("A kid on a scooter and a child on a scooter ride along the road ahead of us.", "motorcycle"),  # conventions
    ("Two teenagers on bikes ride past me on the left.", "cyclist"),
])
def test_people_on_two_wheelers_are_the_riders_counted_once(prompt, kind):
    others = [a.type for a in lower(prompt).scenario.agents() if not a.is_ego]
    assert others == [kind, kind]


@pytest.mark.parametrize("prompt", [
    "A fire engine comes up behind me and I pull over.",
    "A patrol car flashed its lights and we pulled over.",
])
def test_only_the_ego_pulls_over_for_the_vehicle_that_made_it(prompt):
    others = [a.action for a in lower(prompt).scenario.agents() if not a.is_ego]
    assert others == ["go_straight"]
    assert ("car", "change_lane_to_right", "ego") in agents(prompt)


@pytest.mark.parametrize("prompt, kind", [
    ("I let the van merge in front of me.", "car"),
    ("We let a bus pull out.", "bus"),
])
def test_the_verb_after_let_is_the_let_agents_not_the_egos(prompt, kind):
    read = agents(prompt)
    assert ("car", "go_straight", "ego") in read
    assert [(t, a.startswith("change_lane")) for t, a, p in read if p != "ego"] == [(kind, True)]


@pytest.mark.parametrize("prompt", [
    "A ped crossing on the zebra ahead, so the ego yields.",
    "Pedestrian crossing along the crosswalk in front of us while we wait.",
])
def test_a_pedestrian_crossing_on_a_crosswalk_is_a_person_crossing(prompt):
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in agents(prompt)


def test_a_pedestrian_crossing_placed_elsewhere_stays_a_crosswalk():
    assert [a for a in agents("There is a pedestrian crossing on the left of the road ahead.") if a[2] != "ego"] == []


@pytest.mark.parametrize("prompt, kind", [
    ("We overtake a slow tractor on the country lane.", "truck"),
    ("A really slow van is in front of the ego.", "car"),
])
def test_slow_before_a_noun_is_how_the_agent_drives(prompt, kind):
    others = [(a.type, a.behavior) for a in lower(prompt).scenario.agents() if not a.is_ego]
    assert others == [(kind, "cautious")]


# -- the account inside its document, and who its ego is -------------------------------------------------------

def test_a_letters_greeting_and_signature_name_no_agents():
    prompt = ("Hello Rosa,\n\nA cyclist was riding ahead of me on Mill Lane.\n\nBest wishes,\nBus Depot Team\n"
              "Coach Hire Ltd")
    assert agents(prompt) == [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]


def test_a_first_line_about_the_morning_is_no_greeting():
    assert lower("Morning rush hour on the ring road\nA lorry stopped ahead of me.").scenario.weather.time == "dawn"
    assert lower("Morning,\n\nA lorry stopped ahead of me.\n\nThanks,\nJo").scenario.weather is None


def test_a_declared_ego_vehicle_its_fleet_number_and_its_named_driver_are_the_ego():
    prompt = ("Hi all,\n\nCoach 51 (driver: Piotr Zielinski) was in the right lane when a van in the lane to his left "
              "moved across in front of him. Piotr braked.\nPlease use our coach as the ego.\n\nThanks,\nMo")
    assert agents(prompt) == [("bus", "go_straight", "ego"), ("car", "change_lane_to_right", "left")]
    assert agents("Cab 3 (Li Wei driving) was waiting when a lorry came towards her. Use the cab as the ego.")[0] == \
        ("car", "stop", "ego")
    told = read_narration("The white van is the ego. The grey van ahead of the white van stops.").text
    assert "The grey van ahead of the ego" in told  # another van, told apart by its colour


def test_a_drivers_name_in_lower_case_or_that_is_also_a_word():
    told = read_narration("van 5 (driver marek nowak) stopped and marek waited. our van is the ego.").text
    assert "marek" not in told
    told = read_narration("Van 5 (driver Will Hart) stopped as a car will turn left. Our van is the ego.").text
    assert "a car will turn left" in told and "Will" not in told


def test_the_drivers_pronoun_is_the_ego_unless_another_person_of_it_was_named():
    told = read_narration("Van 5 (driver Ann Bell) saw a cyclist ahead of her. Our van is the ego.").text
    assert "ahead of the ego" in told and "Ann" not in told
    told = read_narration("Our taxi is the ego. A man crossed in front of the taxi and he stopped.").text
    assert "he stopped" in told and "in front of the ego" in told


def test_a_passengers_driver_and_their_car_are_the_ego():
    assert agents("Four stars. My driver slowed down for a jogger crossing ahead of us. Car was spotless.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]
    assert agents("Driver was lovely and a motorbike passed us on the left.") == [
        ("car", "go_straight", "ego"), ("motorcycle", "go_straight", "back_left")]
    assert len(agents("A lorry pulled out. The driver waved at us.")) == 2  # that lorry's driver
    assert agents("Car was clean, driver was friendly. A bus stopped ahead of us.") == [
        ("bus", "stop", "front"), ("car", "go_straight", "ego")]


def test_a_number_naming_a_vehicle_counts_nothing():
    assert agents("I was driving the number 7 bus when a car stopped ahead of me.") == [
        ("bus", "go_straight", "ego"), ("car", "stop", "front")]


def test_a_late_night_pickup_is_a_fare_not_a_pickup_truck():
    assert agents("Late night pickup downtown, a bus stopped ahead of us.") == [
        ("bus", "stop", "front"), ("car", "go_straight", "ego")]
    assert agents("A pickup from the left turned right in front of me.") == [
        ("car", "go_straight", "ego"), ("car", "turn_right", "road_of_left_turn")]


def test_a_transcripts_interjections_are_no_account_and_a_no_answers_the_question():
    prompt = ("Q: Was there a bus behind you?\nA: No.\nQ: What happened?\n"
              "A: A jogger ran across in front of me.\nMS. DOYLE: Objection, the lorry driver is not on trial.\n")
    assert agents(prompt) == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]


def test_a_question_answered_no_says_what_was_not_there():
    prompt = ("Q: Were there other cars near you when you turned left?\nA: None. It was late.\n"
              "Q: And the light?\nA: Red.")
    assert agents(prompt) == [("car", "turn_left", "ego")]
    assert road("Q: Was there a stop sign?\nA: No, sir.\nQ: Did you stop?\nA: Yes.").without_signals == ("stop",)


def test_a_question_the_answer_tells_or_denies_names_no_agent_itself():
    told = "Q: Were there other cars at the junction?\nA: There was one van waiting on my right.\nQ: Go on.\nA: I went."
    assert agents(told) == [("car", "go_straight", "ego"), ("car", "stop", "road_of_right_turn")]
    unseen = "Q: Did you see the bus at that point?\nA: Not yet.\nQ: Then?\nA: A cyclist crossed ahead of me."
    assert agents(unseen) == [("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "front")]


def test_small_hours_in_the_morning_are_night():
    assert lower("It was three in the morning and a taxi stopped ahead of me.").scenario.weather.time == "night"


def test_the_addressees_vehicle_is_the_ego():
    assert agents("Your car is waiting at the lights and a bus pulls up behind your vehicle.") == [
        ("bus", "stop", "back"), ("car", "stop", "ego")]
    assert ("motorcycle", "go_straight", "ego") in agents(
        "I was riding my motorcycle when a van pulled out in front of me.")


def test_a_likeness_and_a_model_year_add_no_vehicles():
    assert agents("A big lorry, like a removal truck, was parked ahead of me.") == [
        ("car", "go_straight", "ego"), ("truck", "stop", "front")]
    assert agents("A 2015 Ducati was parked ahead of me.") == [
        ("car", "go_straight", "ego"), ("motorcycle", "stop", "front")]


def test_a_text_messages_spellings_read_as_their_words():
    told = read_narration("theres a bus ahead and it doesnt go, im stuck and i cant pass").text
    assert "there's a bus" in told and "doesn't go" in told and "i'm stuck" in told and "can't pass" in told
    assert agents("i waited like 4 light cycles behind a bus") == [
        ("bus", "go_straight", "front"), ("car", "stop", "ego")]


def test_place_names_that_are_traffic_words_name_no_agent_or_stop():
    assert agents("i drove past the park and a bus came the other way") == [
        ("bus", "go_straight", "front_left"), ("car", "go_straight", "ego")]
    assert agents("the cyclist by target was crossing in front of me") == [
        ("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "front")]
    scene = lower("a kid ran out from behind an ice cream truck parked on my right").scenario
    assert scene.weather is None and ("truck", "stop", "front_right") in [
        (a.type, a.action, a.relative_to_ego) for a in scene.agents()]


def test_the_guy_after_a_rider_is_that_rider():
    assert agents("A cyclist wobbled in the bike lane ahead of us until the guy turned right.") == [
        ("car", "go_straight", "ego"), ("cyclist", "turn_right", "front_right")]  # the bike lane is at the kerb


def test_easing_into_a_lane_changes_lane():
    assert ("car", "change_lane_to_left", "ego") in agents("Then I eased into the left lane behind the bus.")


def test_an_answer_that_names_again_what_was_asked_about_adds_no_agent():
    prompt = ("Q: A van stopped ahead of you?\nA: A white van, yes.\nQ: What were you driving?\n"
              "A: My lorry. A big Scania.")
    assert agents(prompt) == [("car", "stop", "front"), ("truck", "go_straight", "ego")]


def test_the_vehicle_one_operates_is_the_egos():
    assert agents("You were operating the bus when a car stopped ahead of you.") == [
        ("bus", "go_straight", "ego"), ("car", "stop", "front")]


def test_sliding_into_a_lane_changes_lane_and_sliding_right_through_goes_straight():
    assert agents("The van ahead of me slid across into the left lane on the ice.") == [
        ("car", "change_lane_to_left", "front"), ("car", "go_straight", "ego")]
    assert ("car", "go_straight", "road_of_left_turn") in agents(
        "At the crossroads a car from the left slid right through the stop sign.")


def test_what_the_narrator_feared_or_asks_for_is_no_manoeuvre():
    assert agents("A police car stopped behind me and i thought i was getting pulled over lol") == [
        ("car", "go_straight", "ego"), ("police", "stop", "back")]
    assert agents("A bus stopped ahead of us. Could you turn this into a test scene?") == [
        ("bus", "stop", "front"), ("car", "go_straight", "ego")]


def test_the_witness_label_answers():
    prompt = "Q: Were there other cars around you?\nTHE WITNESS: None.\nQ: Then?\nTHE WITNESS: A van stopped ahead."
    assert agents(prompt) == [("car", "go_straight", "ego"), ("car", "stop", "front")]


def test_a_transcripts_how_many_unknown_and_procedural_lines():
    prompt = ("Q: How many lanes were there?\nA: Three.\nQ: Was there a cyclist beside you?\n"
              "MR. LEE: Objection.\nQ: You can answer.\nA: I couldn't tell.\nQ: What happened?\n"
              "A: A bus pulled out in front of me.")
    scene = lower(prompt).scenario
    assert scene.road.lanes == 3 and [a.type for a in scene.agents()] == ["car", "bus"]
    assert "traffic_light" in road("Q: Is there a signal there?\nA: No light.\nQ: Go on.\nA: I stopped.")\
        .without_signals


def test_two_streets_named_together_are_their_intersection():
    assert road("The light at Elm and Ninth was red and a car stopped ahead of me.").junction is True
    assert road("At Fern and Alder a cyclist stopped ahead of me.").junction is True


def test_a_vehicle_turning_at_the_corner_is_at_the_junction_not_on_the_pavement():
    scene = lower("A cyclist rode ahead of us on the right and turned right at the next corner.").scenario
    assert [(a.type, a.action, a.relative_to_ego, a.road_type) for a in scene.agents() if not a.is_ego] == [
        ("cyclist", "turn_right", "front_right", "driving")]


def test_making_ones_left_is_a_left_turn():
    assert ("car", "turn_left", "ego") in agents("I waited for the bus to pass, then I pulled out and made my left.")
    assert ("car", "turn_right", "ego") in agents("At the lights we made our right turn.")


def test_the_officer_is_the_patrol_car_and_lights_in_the_mirror_are_no_signal():
    scene = lower("A police car was behind me. Then the officer stopped ahead of a van.").scenario
    assert sorted(a.type for a in scene.agents()) == ["car", "car", "police"]
    assert road("When I saw the lights in my rearview, a police car was behind me.").required_signals == ()


def test_standing_water_puts_no_witness_on_foot():
    assert agents("I was alone. I hit standing water and a van came towards me.") == [
        ("car", "go_straight", "ego"), ("car", "go_straight", "front_left")]


def test_a_bus_letting_people_off_brings_no_pedestrians():
    assert agents("A bus was stopped at the stop ahead of me, letting people off.") == [
        ("bus", "stop", "front"), ("car", "go_straight", "ego")]


def test_never_coming_all_the_way_to_a_stop_is_no_stop():
    assert ("car", "go_straight", "ego") in agents("I never came all the way to a stop when a van cut in ahead of me.")


def test_tell_us_what_the_van_did_names_what_the_answer_is_about():
    prompt = "Q: Tell us what the grey van did.\nA: It came the other way and it turned left across my path."
    assert agents(prompt) == [("car", "go_straight", "ego"), ("car", "turn_left", "road_of_straight")]


def test_a_vehicle_stuck_sideways_or_jackknifed_blocks_the_ego():
    assert agents("A delivery van was stuck sideways in our lane.") == [
        ("car", "block_the_ego", "front"), ("car", "go_straight", "ego")]
    assert agents("A lorry had jackknifed across the road ahead of us.") == [
        ("car", "go_straight", "ego"), ("truck", "block_the_ego", "front")]


def test_the_named_lane_of_a_count_gives_the_lanes():
    assert road("I was in the middle lane of three when a car cut in front of me.").lanes == 3


def test_it_turned_out_is_no_turn():
    assert agents("A police car stopped behind me. Turned out it was a mistake.") == [
        ("car", "go_straight", "ego"), ("police", "stop", "back")]


# -- spoken and narrated English: discourse words, asides, counterfactuals ------------------------------------

@pytest.mark.parametrize("prompt", [
    "right so there's a bus coming up behind me and I keep going",
    "Okay, right, a bus is behind me.",
])
def test_a_right_that_opens_spoken_talk_is_no_side(prompt):
    assert [a for a in agents(prompt) if a[2] != "ego"] == [("bus", "go_straight", "back")]
    assert road(prompt).lanes < 2


def test_right_opening_a_sentence_before_a_noun_is_still_a_side():
    assert ("car", "go_straight", "right") in agents("Right beside me a car keeps pace.")


@pytest.mark.parametrize("prompt", [
    "The street was still icy from this morning when a van stopped ahead of us.",
    "The car park is wet since last night and a bus waits in front of me.",
])
def test_a_time_that_says_when_the_road_got_so_is_not_the_scenes_time(prompt):
    weather = lower(prompt).scenario.weather
    assert weather is not None and weather.time == "noon"


def test_a_time_of_day_after_from_that_follows_no_road_state_is_the_scenes_time():
    assert lower("From dawn onwards, a bus waits at the stop ahead.").scenario.weather.time == "dawn"


def test_a_condition_without_a_comma_ends_where_its_main_clause_starts():
    scene = lower("We pull out to pass the tractor. Once we are past the tractor we move back into the left lane.")
    assert [[a.action for a in s.agents if a.is_ego] for s in scene.scenario.stages][1] == ["change_lane_to_left"]


@pytest.mark.parametrize("prompt", [
    "You changed lanes to pass the van without a glance over your left shoulder.",
    "Do a shoulder check before you pass the van.",
])
def test_the_drivers_shoulder_is_no_road_shoulder(prompt):
    van = next(a for a in lower(prompt).scenario.agents() if a.type == "car" and not a.is_ego)
    assert van.road_type == "driving" and van.relative_to_ego == "front"


def test_sitting_in_a_lane_beside_or_behind_the_ego_keeps_pace():
    assert ("truck", "go_straight", "back_left") in agents("A lorry was sitting in the left lane just behind us.")
    assert ("car", "stop", "front_right") in agents("A broken down van is sitting in the right lane ahead.")


# -- cut-ins told by the one cut up ---------------------------------------------------------------------------

def test_a_vehicle_on_the_egos_side_drifting_into_its_lane_starts_level():
    assert ("car", "change_lane_to_right", "left") in agents("A van on my left starts drifting into my lane.")
    assert ("motorcycle", "change_lane_to_left", "front_right") in agents(
        "A moped pulling out of a bus stop on the right, in the wet.")  # from where it stood, ahead


def test_let_it_in_ahead_places_the_one_let_in():
    assert ("bus", "change_lane_to_right", "front_left") in agents(
        "A coach in the lane to our left began to drift towards us, so we let it in ahead.")


@pytest.mark.parametrize("prompt", [
    "A taxi in the lane on my right suddenly swerves left in front of me.",
    "A taxi in the right-hand lane pulled across in front of us.",
])
def test_in_front_of_the_ego_after_a_swerve_is_where_it_ends(prompt):
    assert [a for a in agents(prompt) if a[2] != "ego"] == [("car", "change_lane_to_left", "right")]


def test_a_cut_in_from_behind_keeps_its_place_behind():
    assert ("car", "change_lane_to_right", "back_left") in agents(
        "A taxi was in the left lane well behind me. The taxi sped past me and cut into my lane directly in front of me.")


def test_a_subject_before_then_keeps_its_verb():
    scene = lower("A truck drives ahead of us. The truck then brakes to a stop.").scenario
    assert [a.action for a in scene.agents() if a.is_ego] == ["go_straight"]


def test_without_indicating_says_traffic_keeps_left():
    assert ("car", "change_lane_to_left", "right") in agents(
        "A Ford beside me on my offside moved into my lane without indicating.")


def test_the_egos_own_make_in_apposition_is_no_other_agent():
    assert agents("I was driving my car, a silver Ford Focus, north along the high street.") == [
        ("car", "go_straight", "ego")]


def test_a_place_where_a_cut_in_ends_up_is_not_where_it_starts():
    assert ("car", "change_lane_to_left", "front_right") in agents(
        "Some guy in the right lane slightly ahead of me drifts into my lane. I sped up and he ended up behind me.")


def test_a_pronoun_and_its_copula_after_a_comma_start_a_new_subject():
    read = agents("There is a guy behind me. I'm in the left lane, he's in the right lane and starts to move over "
                  "into my lane.")
    assert ("car", "go_straight", "ego") in read and ("car", "change_lane_to_left", "back_right") in read


@pytest.mark.parametrize("prompt, limit", [
    ("The run is on a 2-lane avenue posted at 35 mph.", "speed_56"),
    ("Keep an eye on your speed, it's a 55 along there.", "speed_89"),
    ("He was doing 70 in a 45, so we pulled over.", "speed_72"),
])
def test_a_limit_said_as_drivers_say_it(prompt, limit):
    assert limit in road(prompt).required_signals + road(prompt).required_objects


def test_a_topic_naming_the_agent_with_the_introduces_it():
    assert ("cyclist", "go_straight", "front") in agents("Passing the cyclist on the bypass: you gave him room.")
    assert [a for a in agents("Cut-in: a car in the left lane ahead cuts in.") if a[2] != "ego"] == [
        ("car", "change_lane_to_right", "front_left")]


def test_a_vague_part_of_the_group_said_before_is_no_new_group():
    read = agents("A coach stopped to let pupils off. Some of the pupils began to cross in front of it.")
    assert [a for a in read if a[0] == "pedestrian"] == [("pedestrian", "cross_the_road", "front")] * 2


def test_a_rule_of_the_road_and_what_would_have_happened_are_no_events():
    stages = lower("You waited at the zebra. Once somebody is on a crossing, you stop and you wait.").scenario.stages
    assert len(stages) == 1
    assert [a.action for a in lower("We moved off on green. We would have had to stop if the lights had changed.")
            .scenario.agents() if a.is_ego] == ["go_straight"]


def test_a_slow_walk_across_crosses_and_a_walking_aid_is_no_walk():
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in agents(
        "The ego waits at a zebra while a woman with a walking frame hobbles slowly across.")
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in agents(
        "The ego waits at a zebra while an old man trudges slowly across.")


# -- junctions told from the driver's seat ----------------------------------------------------------------------

def test_a_riders_own_bike_is_no_second_rider():
    read = agents("A cyclist came from the right at the crossroads and rode right in front of me, no bell on his bike.")
    assert [a for a in read if a[0] == "cyclist"] == [("cyclist", "cross_the_road", "road_of_right_turn")]


@pytest.mark.parametrize("prompt, expected", [
    ("At the lights a lorry on my right is turning right.", ("truck", "turn_right", "right")),
    ("At the all-way stop a van on my right turns left in front of me.", ("car", "turn_left", "road_of_right_turn")),
])
def test_a_turner_on_the_egos_side_is_beside_it_unless_it_turns_across_its_path(prompt, expected):
    assert expected in agents(prompt)


def test_a_turner_ahead_turning_in_front_of_the_ego_stays_ahead():
    assert ("bus", "turn_left", "front") in agents("A bus turns left in front of me.")


def test_a_relative_clause_with_its_own_subject_leaves_the_verb_after_it_to_its_noun():
    read = agents("A van is parked ahead. A woman, whom I now know to be the driver of the van, stepped out into the "
                  "road in front of me.")
    assert sorted(read) == [("car", "go_straight", "ego"), ("car", "stop", "front"),
                            ("pedestrian", "cross_the_road", "front")]


def test_the_hard_shoulder_is_on_the_left_where_traffic_keeps_left():
    assert ("truck", "stop", "front_left") in agents("On the M1 a lorry is stopped on the hard shoulder ahead of me.")
    assert ("truck", "stop", "front_right") in agents("On the interstate a truck is stopped on the shoulder ahead.")


def test_a_participle_after_scenery_is_the_scenerys():
    assert [a for a in agents("A narrow lane with vans parked on both sides. I'm heading east.")] == [
        ("car", "go_straight", "ego")]


def test_a_side_of_the_verge_is_no_lane_of_the_ego():
    assert road("I lost grip on the ice and came to a stop against the nearside verge.").lanes < 2


def test_no_option_but_to_is_the_verb_of_the_one_left_without_a_choice():
    read = agents("A lorry pulled out in front of me and stopped, leaving me no choice but to make an emergency stop.")
    assert ("car", "stop", "ego") in read


# -- logs, papers and level briefs ------------------------------------------------------------------------------

def test_a_multi_actor_case_names_no_actor_and_outside_any_crosswalk_says_none_is_there():
    scene = lower("Case 7 (multi-actor). A child crosses the road in front of the SV from the right, outside any "
                  "crosswalk.").scenario
    assert sorted((a.type, a.relative_to_ego) for a in scene.agents() if not a.is_ego) == [("pedestrian", "front_right")]
    assert "crosswalk" not in scene.road.required_objects


def test_a_turner_from_a_side_into_the_egos_destination_comes_from_that_side():
    assert ("car", "turn_left", "road_of_right_turn") in agents(
        "The player turns right. A taxi from the right turning left into the street the player is heading into.")


def test_standing_across_the_lane_blocks_and_going_around_from_behind_changes_lane():
    assert ("truck", "block_the_ego", "front") in agents("A lorry ahead of us has stopped across the road.")
    assert ("car", "change_lane_to_left", "back") in agents(
        "A van came up fast behind us and went around on the left.")


def test_a_noun_naming_the_case_is_no_agent_when_the_agent_comes_later():
    assert agents("Run 4, parked car test. A hatchback is parked in our lane ahead.") == sorted([
        ("car", "go_straight", "ego"), ("car", "stop", "front")])
    assert ("cyclist", "go_straight", "front") in agents("Make a cyclist scenario on a country road.")


def test_mirror_signal_manoeuvre_is_the_drivers_routine_not_a_traffic_light():
    assert "traffic_light" not in road("You turned left at the junction. Remember: mirror, signal, manoeuvre.") \
        .required_signals


@pytest.mark.parametrize("prompt, expected", [
    ("The player comes down the on-ramp and merges right. A bus is in the motorway's left lane just ahead of the "
     "player.", ("bus", "go_straight", "front_right")),
    ("We joined from the slip road, moving left into lane two, with a van behind in lane two.",
     ("car", "go_straight", "back_left")),
])
def test_the_lanes_of_the_road_the_ego_joins_lie_on_the_side_it_merges_to(prompt, expected):
    assert expected in agents(prompt)


def test_moving_from_one_numbered_lane_into_another_changes_lane_that_way():
    assert ("bus", "change_lane_to_right", "back") in agents(
        "On the motorway a coach behind me in lane one pulled out into lane two.")


@pytest.mark.parametrize("prompt, expected", [
    ("The ego turns left. Buses often use this road in the mornings.", [("car", "turn_left", "ego")]),
    ("A taxi cut in front of us from the left. Taxis do that all the time around here.",
     [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]),
    ("The ego drives straight. If a cyclist had been there, it would have been a disaster.",
     [("car", "go_straight", "ego")]),
    # a test's condition, and counted or named agents doing something habitually, stay in the scene
    ("If a pedestrian steps out in front of the ego, it brakes.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("Two cyclists often ride side by side ahead of the ego.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front"), ("cyclist", "go_straight", "front")]),
])
def test_kinds_spoken_of_in_general_and_someone_in_what_did_not_happen_are_no_agents(prompt, expected):
    assert agents(prompt) == expected


def test_behind_where_it_was_is_at_the_place_of_the_one_that_left():
    assert ("car", "stop", "front") in agents(
        "The van ahead of us moves into the left lane and there is a broken down car behind where it was.")


def test_pulling_up_at_a_stop_then_moving_off_later_stops_first_and_the_turn_keeps_its_side():
    stages = lower("The player pulls up to a give way line and wants to go left. A bus passes from the right. "
                   "Once it has gone, the player makes the turn.").scenario.stages
    assert [[a.action for a in s.agents if a.is_ego] for s in stages] == [["stop"], ["turn_left"]]


def test_a_participle_after_at_which_point_belongs_to_that_clauses_subject():
    read = agents("I arrived at the four-way stop. I then went straight, at which point a van also entered the "
                  "junction from the opposite direction, turning left across my path.")
    assert ("car", "turn_left", "road_of_straight") in read


def test_one_after_another_is_an_order_not_a_stage():
    scene = lower("Three vans in the right lane ahead cut in front of the player, one after another, all going far "
                  "too fast.").scenario
    assert len(scene.stages) == 1
    assert [a.action for a in scene.agents() if not a.is_ego] == ["change_lane_to_left"] * 3


def test_waiting_to_turn_without_a_side_is_a_stop_and_a_give_way_line_is_a_yield():
    scene = lower("I was stationary at the give way line, waiting to turn out, when a bus passed from my right.")
    assert [a.action for a in scene.scenario.agents() if a.is_ego] == ["stop"]
    assert "yield" in scene.scenario.road.required_signals
    assert ("car", "turn_left", "ego") in agents("I was stopped at the lights, waiting to turn left.")


def test_an_overtaker_said_to_come_up_behind_is_behind():
    assert ("motorcycle", "go_straight", "back") in agents(
        "On a country road with no junctions a motorbike came up behind me and overtook on a bend.")


def test_a_turn_made_with_a_wait_in_advice_is_still_the_turn():
    assert ("car", "turn_left", "ego") in agents(
        "Your left at the lights. You turned across an oncoming van. When there is oncoming traffic, you wait in "
        "the junction till it is clear.")


@pytest.mark.parametrize("prompt", [
    "I was driving my car, red Ford Focus, north along the high street.",
    "i was driving my car, a red ford focus, north along the high street",
])
def test_the_egos_own_make_without_an_article_is_no_other_agent(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego")]


def test_a_topic_naming_its_agent_without_an_article_introduces_it_when_the_rest_says_him():
    assert [t for t, _, p in agents("Passing cyclist on the bypass: you gave him room.") if p != "ego"] == ["cyclist"]


def test_sitting_in_a_lane_without_an_article_keeps_pace_too():
    assert ("truck", "go_straight", "back_left") in agents("There was a lorry sitting in left lane just behind us.")


def test_a_stop_junction_and_a_sign_that_says_stop_are_stop_signs_and_even_when_is_no_stage():
    scene = lower("Stop junction by the church. The sign says stop, even when it's clear. You turned right with a van "
                  "coming from the left.").scenario
    assert "stop" in scene.road.required_signals and len(scene.stages) == 1
    assert [a.action for a in scene.agents() if a.is_ego] == ["turn_right"]


def test_standing_advice_is_no_event():
    assert ("car", "go_straight", "ego") in agents(
        "You came up to the roundabout too fast with a cyclist on it. Always look right and give way.")


def test_flashing_his_lights_is_no_traffic_light():
    assert "traffic_light" not in road("A van came up behind me flashing his lights.").required_signals
    assert "traffic_light" in road("A van ran a red light in front of me.").required_signals


def test_a_hedge_neither_acts_nor_adds_an_agent():
    assert agents("then a lorry on the left, I think it was a lorry, pulls out in front of me") == sorted([
        ("car", "go_straight", "ego"), ("truck", "change_lane_to_right", "left")])
    assert [t for t, _, p in agents("a car, well actually it was a van, stops in front of me") if p != "ego"] == ["car"]


def test_an_animal_running_out_is_nobody_and_the_guy_behind_drives():
    assert agents("I was driving along when a fox ran out, and the guy behind me went straight into the back of me.") \
        == sorted([("car", "go_straight", "ego"), ("car", "go_straight", "back")])


def test_stationary_in_a_marked_police_car_is_the_ego_and_next_time_is_advice():
    assert agents("I was stationary in a marked police car at the lights.") == [("police", "stop", "ego")]
    assert ("car", "change_lane_to_left", "ego") in agents("You pulled out in front of the van. Next time wait.")


def test_he_after_a_vehicle_in_first_person_talk_is_its_driver():
    assert ("bus", "change_lane_to_right", "left") in agents(
        "A coach in the left lane started indicating right. I slowed down so he could merge.")


def test_story_words_and_passengers_in_the_back_are_no_scene():
    scene = lower("Long story short, I was heading home, kids arguing in the back, when a bus pulled out ahead.")
    assert scene.scenario.weather is None
    assert [a.type for a in scene.scenario.agents() if not a.is_ego] == ["bus"]


def test_the_next_bit_names_a_part_of_the_lesson_not_a_stage():
    assert len(lower("The next bit was the roundabout. A lorry came from the right and you waited.")
               .scenario.stages) == 1


def test_vehicles_on_both_sides_stand_level_and_one_in_our_lane_is_on_neither():
    read = agents("The player is in the middle of three lanes. Cars on both sides, and a van ahead in the player's "
                  "lane stops.")
    assert sorted(p for _, _, p in read if p != "ego") == ["front", "left", "right"]


def test_a_named_parking_manoeuvre_is_no_stop():
    assert [a for a in agents("Your bay park was tidy. You drove past a parked van.") if a[2] == "ego"] == [
        ("car", "go_straight", "ego")]


def test_a_request_for_one_where_is_no_question_and_a_late_make_it_retypes():
    read = agents("could we do one where the ego turns left at a roundabout and a cyclist is on its left? or actually "
                  "make it a motorbike")
    assert ("car", "turn_left", "ego") in read and ("motorcycle", "go_straight", "left") in read
    assert not any(t == "cyclist" for t, _, _ in read)


def test_a_wobbling_rider_is_the_one_who_moves_and_my_braking_is_mine():
    read = agents("Two cyclists rode ahead of me. One of them wobbled towards the kerb and I had to brake.")
    assert [a for a in read if a[0] == "cyclist"] == [("cyclist", "go_straight", "front")] * 2


def test_a_rough_time_a_bit_later_is_no_stage():
    assert len(lower("It was around 6pm, maybe a bit later. A taxi in front of me stopped suddenly.")
               .scenario.stages) == 1


def test_the_vans_driver_is_the_van():
    assert [t for t, _, p in agents("A white van is parked on the left ahead. The van's driver opens his door.")
            if p != "ego"] == ["car"]


def test_the_egos_numbered_lane_said_after_the_road_places_the_others():
    assert ("truck", "change_lane_to_left", "front_right") in agents(
        "The ego is on a motorway in lane one. A lorry in lane two moves left into lane one ahead of the ego.")


def test_a_road_feature_wondered_about_then_taken_back_is_denied():
    scene = lower("maybe a man crossing from the left in front of us? at a zebra crossing, probably not.").scenario
    assert "continental_crosswalk" in scene.road.without_objects
    assert ("pedestrian", "cross_the_road", "front_left") in agents(
        "maybe a man crossing from the left in front of us? at a crosswalk, probably not.")


def test_no_interaction_in_a_log_is_no_intersection():
    assert road("Run 4. Cyclist on the right kerb throughout, no interaction.").junction is None
# -- exam questions, catalogue entries, user stories and chat requests -------------------------------------

def test_the_answers_of_a_multiple_choice_question_are_not_the_scene():
    stem = "You are waiting at a red light. A van stops behind you. What should you do?\n\n"
    for answers in ("A  Reverse into the van\nB  Wait for green\nC  Sound your horn\n",
                    "(a) reverse into the van\n(b) turn left at once\n",
                    "Mark one answer\n[ ] Reverse into the van\n[ ] Turn left at once\n"):
        assert agents(stem + answers) == [("car", "stop", "back"), ("car", "stop", "ego")]


def test_a_line_that_only_starts_with_a_letter_is_still_read():
    found = agents("Is this a good test?\nA bus turns left from the road on the right.\n")
    assert ("bus", "turn_left", "road_of_right_turn") in found


def test_a_question_about_what_one_should_do_names_no_action():
    assert agents("You are driving behind a cyclist on a narrow road. Where should you stop?") == [
        ("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]


def test_a_person_waiting_to_cross_still_stands_on_the_pavement():
    assert ("pedestrian", "on_the_sidewalk") in [
        (a.type, a.action) for a in lower("An old man stands on the pavement, waiting to cross.").scenario.agents()]


def test_a_user_storys_frame_names_neither_an_agent_nor_the_weather():
    story = ("Story: cyclist crossing\nAs a bus fleet engineer I want a cyclist to cross in front of the ego, "
             "so that the braking logic can be validated.")
    scene = lower(story).scenario
    assert scene.weather is None  # "story" is no misspelt "stormy"
    assert sorted((a.type, a.action, a.relative_to_ego or "ego") for a in scene.agents()) == [
        ("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "front")]


def test_the_purpose_of_a_test_is_cut_only_where_a_story_asks_for_it():
    assert ("pedestrian", "cross_the_road", "front") not in agents(
        "As a tester I want the ego to drive past a parked van so that pedestrian detection can be checked.")
    assert ("truck", "stop", "front") in agents(
        "A truck stops in front so that the ego can overtake it.")


@pytest.mark.parametrize("prompt, expected", [
    ("I want a van to cut in from the left just ahead of the ego.", ("car", "change_lane_to_right", "front_left")),
    ("We need a lorry to stop ahead of us.", ("truck", "stop", "front")),
])
def test_the_one_wanted_to_act_is_the_one_that_acts(prompt, expected):
    found = agents(prompt)
    assert expected in found and ("car", "go_straight", "ego") in found


def test_a_key_whose_value_starts_with_a_verb_is_that_verbs_subject():
    assert agents("Ego: follows lorry. Lorry: stationary later on.") == [
        ("car", "go_straight", "ego"), ("truck", "stop", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("EV: turns left at the crossroads\nTV: car from the opposite approach, straight on\n",
     [("car", "go_straight", "road_of_straight"), ("car", "turn_left", "ego")]),
    ("An EV with its sirens on comes up behind us.", [("ambulance", "go_straight", "back"),
                                                     ("car", "go_straight", "ego")]),
])
def test_ev_is_the_ego_vehicle_unless_there_is_an_emergency(prompt, expected):
    assert agents(prompt) == expected


def test_a_capital_letter_after_an_agent_noun_names_it():
    # "Car A" is a car named A, not a car and then an article
    assert agents("Car A is waiting on the road to your right. Car B comes from the opposite direction "
                  "and turns left. You go straight.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "road_of_right_turn"), ("car", "turn_left", "road_of_straight")]


@pytest.mark.parametrize("prompt", ["The picture shows three cars at a crossroads, including yours.",
                                    "Three cars wait at the crossroads, including yours.",
                                    "Three cars wait at the lights, including the ego."])
def test_a_group_counted_with_the_ego_further_on_in_the_sentence(prompt):
    assert [a.type for a in lower(prompt).scenario.agents()] == ["car", "car", "car"]


def test_a_note_that_says_what_to_check_is_not_the_scene():
    assert agents("Ego: drives straight on\nTruck: parked ahead on the right\nNotes: check the ego stops "
                  "for the truck\n") == [("car", "go_straight", "ego"), ("truck", "stop", "front_right")]


def test_ev_starting_a_line_is_the_ego_even_where_the_ego_is_also_named():
    assert ("car", "turn_left", "ego") in agents("Junction: ego gives way at the sign\nEV: turns left\n")


def test_a_speed_in_a_road_line_is_its_limit_and_in_an_agents_line_its_speed():
    scene = lower("Road: two-lane rural road, 80 km/h\nEgo: drives ahead in lane, 60 km/h\n").scenario
    assert "speed_80" in scene.road.required_objects + scene.road.required_signals
    assert "speed_60" not in scene.road.required_objects + scene.road.required_signals
    assert scene.ego.speed is not None and scene.ego.speed.value == 60


@pytest.mark.parametrize("prompt, expected", [
    ("A cyclist rides across from the RHS.", ("cyclist", "cross_the_road", "front_right")),
    ("A pedestrian walks along the footway on the LHS.", ("pedestrian", "on_the_sidewalk", "left")),
])
def test_lhs_and_rhs_are_the_left_and_right_hand_sides(prompt, expected):
    assert expected in agents(prompt)


def test_the_short_name_of_a_target_named_through_a_role_is_no_second_agent():
    assert agents("Target: child pedestrian dummy (EPTc) running across the road from the left") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left")]


@pytest.mark.parametrize("prompt, expected", [
    ("some kids cross the road ahead of the ego. ego brakes. actually make it 3 kids not some",
     [("car", "go_straight", "ego")] + [("pedestrian", "cross_the_road", "front")] * 3),
    ("a van cuts in from the left. oh wait make it a bus", [("bus", "change_lane_to_right", "front_left"),
                                                           ("car", "go_straight", "ego")]),
    ("two motorbikes overtake us on the left. no, make it three",
     [("car", "go_straight", "ego")] + [("motorcycle", "go_straight", "back_left")] * 3),
])
def test_a_later_correction_replaces_what_was_said_first(prompt, expected):
    assert agents(prompt) == expected


def test_police_chase_names_the_scene_not_a_second_police_car():
    found = agents("police chase scene, cop car comes from behind and overtakes the ego")
    assert [(t, p == "ego") for t, _, p in found] == [("car", True), ("police", False)], found


def test_traffic_coming_straight_at_the_ego_is_oncoming():
    assert ("truck", "go_straight", "road_of_straight") in agents(
        "the ego turns right at a junction while a truck is coming straight at it")


def test_a_condition_ends_at_its_verb_when_a_new_subject_and_verb_follow():
    scene = lower("ego waits at the give way line, and after the bus has passed ego turns left").scenario
    assert [[(a.type, a.action) for a in s.agents if a.is_ego] for s in scene.stages] == [
        [("car", "stop")], [("car", "turn_left")]]


def test_a_lane_count_then_a_speed_is_still_a_limit():
    assert "speed_64" in road("The road is down to one lane and 40 mph through the works.").required_objects


def test_a_label_in_a_column_of_its_own_keys_its_line():
    assert ("bus", "stop", "front") in agents(
        "Ego: queueing, left lane\nActors:\n  TV1  bus stopped ahead of ego\n  TV2  van stopped beside ego\n")


def test_a_place_after_the_ego_in_its_own_line_heads_no_later_agent():
    found = agents("Ego: queueing, left lane. Van: stopped in the right lane beside the ego.")
    assert ("car", "stop", "right") in found


@pytest.mark.parametrize("prompt", [
    "Target: child dummy crossing from the left, perpendicular to the ego path, on a straight road",
    "On a straight road, a jogger crossing from the left is in front of the ego.",
])
def test_a_person_crossing_from_a_side_crosses_the_road(prompt):
    found = agents(prompt)
    assert any(a[1] == "cross_the_road" and a[2] == "front_left" for a in found), found
    assert not lower(prompt).scenario.road.junction


def test_the_lane_the_ev_merges_into_is_the_egos_target_lane_and_the_next_lane_no_later_stage():
    scene = lower("EV: merges right into the next lane\nTV: van in the lane the EV merges into, "
                  "behind and to the right of the EV\n").scenario
    assert len(scene.stages) == 1
    assert sorted((a.type, a.action, a.relative_to_ego or "ego") for a in scene.agents()) == [
        ("car", "change_lane_to_right", "ego"), ("car", "go_straight", "back_right")]


def test_numbered_phases_tell_the_order_and_phase_one_goes_on_with_the_setup():
    scene = lower("Ego: follows a tractor, then overtakes it\nActors: tractor ahead in the ego lane\n"
                  "Phase 1: ego follows the tractor at 40 km/h\nPhase 2: ego changes to the right lane\n").scenario
    assert [[(a.type, a.action, a.relative_to_ego or "ego") for a in s.agents] for s in scene.stages] == [
        [("car", "go_straight", "ego"), ("truck", "go_straight", "front")], [("car", "change_lane_to_right", "ego")]]


def test_a_bare_noun_placed_where_that_agent_already_is_names_it_again():
    assert agents("Ego: follows HGV\nActors: HGV ahead, slow\n") == [("car", "go_straight", "ego"),
                                                                    ("truck", "go_straight", "front")]


def test_a_signal_controlled_junction_keeps_its_lights_when_a_manoeuvre_line_follows():
    assert "traffic_light" in road("Road: crossroads, signal controlled\nEgo manoeuvre: right turn\n").required_signals


def test_what_one_is_signalled_to_do_is_still_to_come():
    assert agents("A police car behind us flashes its lights and signals us to pull over.") == [
        ("car", "go_straight", "ego"), ("police", "go_straight", "back")]


def test_an_agent_said_to_be_beside_stays_beside_when_the_ego_later_drops_behind_it():
    assert ("bus", "go_straight", "right") in agents(
        "the ego merges into the right lane, but a bus is right next to it in that lane, so the ego has to tuck in "
        "behind it")


def test_one_of_a_group_then_the_other_one_are_its_members_and_not_the_ego():
    assert agents("There is an all-way stop with three cars including the ego. The ego turns right. One of the "
                  "other cars is waiting on the road to our left, and the other one goes straight from the opposite "
                  "approach.") == [
        ("car", "go_straight", "road_of_straight"), ("car", "stop", "road_of_left_turn"), ("car", "turn_right", "ego")]


def test_a_give_way_line_is_the_give_way_marking_not_a_stop_line():
    spec = road("The ego waits at the give way line of a roundabout.")
    assert "yield" in spec.required_signals and "stop_line" not in spec.required_objects


def test_a_vehicle_waiting_to_pull_out_waits():
    assert ("bus", "stop", "road_of_left_turn") in agents("A bus is waiting to pull out of the side road on our left.")


def test_a_person_standing_on_the_pavement_near_the_crossing_stays_on_the_pavement_by_it():
    assert ("pedestrian", "on_the_sidewalk", "near_the_crosswalk") in agents(
        "A man is standing on the pavement to our right near the zebra crossing.")


def test_one_of_them_corrected_to_both_of_them_is_both():
    assert agents("two kids wait at the crossing and one of them, no, both of them run across") == [
        ("car", "go_straight", "ego")] + [("pedestrian", "cross_the_road", "near_the_crosswalk")] * 2


@pytest.mark.parametrize("prompt", [
    "One of our minibuses was turning right at the lights when a cyclist came up on its inside. "
    "Please build a scene with our minibus as the ego.",
    "Our driver Ana was turning right in one of our minibuses at the lights when a cyclist came up on its inside. "
    "The minibus is the ego.",
])
def test_the_vehicle_named_as_the_ego_is_the_ego_wherever_it_is_mentioned(prompt):
    found = agents(prompt)
    assert ("bus", "turn_right", "ego") in found and len(found) == 2, found


def test_another_vehicle_of_the_kind_named_as_the_ego_is_not_the_ego():
    found = agents("Our van is the ego. A white van overtakes it on the left.")
    assert ("car", "go_straight", "back_left") in found and len(found) == 2, found


def test_a_letters_greeting_and_signature_are_not_the_scene():
    letter = ("Dear road safety team,\n\nA lorry parks on the pavement outside our school every morning.\n\n"
              "Kind regards,\nJo Bloggs\nChair, Parents of Riverside Cyclists and Walkers\n")
    assert agents(letter) == [("car", "go_straight", "ego"), ("truck", "stop", "front")]


def test_the_named_driver_of_the_vehicle_that_is_the_ego_is_the_ego():
    email = ("Bus 12 (Sam Okoro driving) had a near miss today. A girl stepped out onto the zebra crossing outside "
             "the bank and Sam only just pulled up in time. Please make a scene with the bus as the ego.")
    assert agents(email) == [("bus", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]


@pytest.mark.parametrize("prompt", [
    "Great ride. My driver stopped dead when a van pulled out in front of us.",
    "Two cars were queued at the lights, including ours. Our driver waited while a van pulled out in front of us.",
])
def test_my_driver_and_ours_are_the_ego(prompt):
    found = agents(prompt)
    assert [a for a in found if a[2] == "ego"] == [("car", "stop", "ego")] and not any(
        a == ("car", "go_straight", "front") for a in found), found


def test_waiting_to_pass_behind_a_rider_is_following_it():
    found = agents("We were behind a tractor, waiting to pass, when a motorbike came the other way.")
    assert ("car", "go_straight", "ego") in found and ("truck", "go_straight", "front") in found, found


def test_an_oncoming_vehicle_of_the_kind_named_as_the_ego_is_not_the_ego():
    found = agents("Our van is the ego. It was on a country road when an oncoming van came round the bend.")
    assert ("car", "go_straight", "front_left") in found and len(found) == 2, found


# -- formal and after-the-fact accounts: letters, depositions, claims, disengagement reports -----------------

@pytest.mark.parametrize("prompt, expected", [
    ("A taxi in the right-hand lane beside me pulled sharply across in front of me.",
     ("car", "change_lane_to_left", "right")),
    ("A bus on the right pulled slowly out in front of me.", ("bus", "change_lane_to_left", "right")),
    ("A van in the lane to my left pulled abruptly across in front of us.", ("car", "change_lane_to_right", "left")),
])
def test_a_manner_adverb_between_a_verb_and_its_particle_keeps_the_verb_phrase(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A van in the lane to my right crossed the dashed line and clipped my mirror.", ("car", "go_straight", "right")),
    ("The lorry on my left drifted over and crossed the solid white line into my lane.",
     ("truck", "change_lane_to_right", "left")),
])
def test_crossing_a_painted_line_is_a_drift_out_of_the_lane_not_a_road_crossing(prompt, expected):
    found = agents(prompt)
    assert expected in found and not any(p.startswith("road_of") for _, _, p in found), found
    assert lower(prompt).scenario.road.junction is not True


@pytest.mark.parametrize("prompt", [
    "On a country road with one lane each way, an oncoming pickup crossed the centre line into my lane.",
    "A lorry coming the other way veered into our lane on the narrow road near the farm.",
])
def test_an_oncoming_vehicle_over_the_centre_line_changes_lane_towards_its_offside(prompt):
    scene = lower(prompt).scenario
    others = [(a.action, a.relative_to_ego) for a in scene.agents() if not a.is_ego]
    assert others == [("change_lane_to_left", "front_left")], others
    assert scene.road.lanes == 1  # the opposite lane it moves into is no second lane of the ego's direction


@pytest.mark.parametrize("prompt", [
    "I was doing 45 mph when I steered right onto the gravel and stopped.",
    "The AV swerved left onto the grass verge and came to a stop.",
])
def test_steering_onto_the_roadside_and_stopping_is_a_stop_not_a_lane_change(prompt):
    scene = lower(prompt).scenario
    assert [(a.action, a.relative_to_ego) for a in scene.agents()] == [("stop", None)]
    assert scene.road.lanes == 1


@pytest.mark.parametrize("prompt, limit", [
    ("I was doing 35 mph in a 40 zone when a car pulled out of a driveway.", "speed_64"),
    ("Northbound on Lake Shore the limit is forty, and a pickup turned left across my path.", "speed_64"),
    ("On I-80 westbound, speed limit 65, a semi in the lane to my right drifted into my lane.", "speed_105"),
    ("The speed limit is 70 on this road and a bus pulls out in front of the ego.", "speed_70"),
])
def test_a_limit_with_no_unit_is_in_miles_when_the_text_measures_in_miles(prompt, limit):
    assert road(prompt).required_objects == (limit,)  # and a road's number ("I-80") is no speed


@pytest.mark.parametrize("prompt, later", [
    ("I waited at the stop sign until the bus had passed, then turned right.", "turn_right"),
    ("The operator held the AV at the line until the fire engine cleared, then proceeded straight.", "go_straight"),
])
def test_after_an_until_clause_a_bare_verb_is_the_waiters_not_the_one_waited_for(prompt, later):
    scene = lower(prompt).scenario
    assert [a.action for a in scene.stages[-1].agents] == [later] and scene.stages[-1].agents[0].is_ego


def test_an_ego_said_to_stay_as_it_was_in_a_later_stage_gets_no_new_line():
    scene = lower("I was stopped at the red light. The light turned green but I kept the car stopped until the "
                  "ambulance had cleared, then went straight.").scenario
    egos = [a.action for s in scene.stages for a in s.agents if a.is_ego]
    assert egos == ["stop", "go_straight"], egos


@pytest.mark.parametrize("prompt", [
    "Two cars stopped in my lane ahead after a minor collision between them. I stopped behind them.",
    "A lorry had stopped in the lane in front of us after a breakdown. We stopped behind it.",
])
def test_an_after_phrase_said_after_its_clause_opens_no_later_stage(prompt):
    scene = lower(prompt).scenario
    assert len(scene.stages) == 1 and scene.stages[0].agents[0].action == "stop", scene.stages


@pytest.mark.parametrize("prompt", ["a car cuts in after 5 seconds", "A van pulls out in front of us after 3 s."])
def test_an_after_said_with_a_time_at_the_end_of_its_clause_is_its_trigger(prompt):
    scene = lower(prompt).scenario
    other = next(a for a in scene.agents() if not a.is_ego)
    assert len(scene.stages) == 1 and other.trigger is not None and other.trigger.after_s in (5, 3), other


@pytest.mark.parametrize("prompt, turn", [
    ("I was waiting in the junction to turn right while a bus came the other way. Once it had passed I completed "
     "the turn.", "turn_right"),
    ("The AV was stopped at the line, waiting to turn left. A van crossed from the right, then the AV completed "
     "the left.", "turn_left"),
])
def test_completing_a_turn_waited_for_is_the_turn_made_in_the_later_stage(prompt, turn):
    egos = [a.action for s in lower(prompt).scenario.stages for a in s.agents if a.is_ego]
    assert egos == ["stop", turn], egos


@pytest.mark.parametrize("prompt, expected", [
    ("The residents' association objected, and an ambulance came up behind me.",
     [("ambulance", "go_straight", "back"), ("car", "go_straight", "ego")]),
    ("The drivers' union complained to the council. A cyclist crossed in front of me.",
     [("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "front")]),
    ("We waited at the crossing for ages, but the bus never arrived.", [("car", "stop", "ego")]),
    ("The gritting lorry never comes up our road, and on Thursday my car slid on the ice.",
     [("car", "go_straight", "ego")]),
])
def test_owners_of_an_organisation_and_vehicles_that_never_come_are_nobody_in_the_scene(prompt, expected):
    assert agents(prompt) == expected


def test_a_vehicle_that_never_came_to_a_stop_is_still_there():
    assert ("car", "go_straight", "back") in agents("The car behind never came to a stop and hit me.")


@pytest.mark.parametrize("prompt", [
    "I was stopped at the red light when an ambulance came up behind me. There was nowhere for any of us to pull "
    "over.",
    "I had stopped in the queue. There was no room for me to move over when the fire engine arrived behind us.",
])
def test_a_manoeuvre_there_was_no_room_for_is_not_made(prompt):
    assert [a.action for a in lower(prompt).scenario.agents() if a.is_ego] == ["stop"]
    assert lower(prompt).scenario.road.lanes == 1


@pytest.mark.parametrize("prompt, without", [
    ("The council removed the stop sign and the stop line at the end of our road. My car slid across the junction.",
     ("stop", "stop_line")),
    ("Last year they scrapped the traffic lights at the crossroads, and today I drove straight across the "
     "intersection.", ("traffic_light",)),
])
def test_a_removed_sign_is_without_and_the_ego_going_across_a_junction_is_at_one(prompt, without):
    found = road(prompt)
    assert found.junction is True and tuple(found.without_signals + found.without_objects) == without, found


@pytest.mark.parametrize("prompt, expected", [
    ("The AV was following a bus at 30 mph. The planner queued a lane change to the right, but the operator took "
     "over.", [("bus", "go_straight", "front"), ("car", "go_straight", "ego")]),
    ("We were behind a tractor and I planned a lane change to the left to get past it, then thought better of it.",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "front")]),
])
def test_a_manoeuvre_planned_or_queued_is_not_made_and_queued_with_an_object_is_no_wait(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "Heavy stop-and-go traffic on US-101. A motorcycle came up behind us on the left.",
    "Bumper to bumper on I-5 this morning, and a motorbike came up behind me on my left.",
])
def test_the_flow_of_traffic_is_no_ones_manoeuvre_and_a_us_highway_is_not_the_narrators(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "back_left")]


@pytest.mark.parametrize("prompt, expected", [
    ("A jogger was running on the pavement just ahead on the right. The jogger never left the pavement.",
     [("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "front_right")]),
    ("The van ahead of me left the junction and a cyclist came up on my left.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "front"), ("cyclist", "go_straight", "left")]),
])
def test_left_with_an_object_after_its_subject_is_the_verb_leave_not_a_side(prompt, expected):
    assert agents(prompt) == expected


def test_a_sequence_word_after_a_sentence_ending_in_a_place_opens_its_stage():
    scene = lower("I stopped at the crossing. Once the children had crossed, I continued straight.").scenario
    assert [[a.action for a in s.agents if a.is_ego] for s in scene.stages] == [["stop"], ["go_straight"]]


@pytest.mark.parametrize("prompt, bus", [
    ("A boy darted out onto the zebra crossing from behind a bus which had stopped just ahead of me.",
     ("bus", "stop", "front")),
    ("An old man stepped onto the crosswalk from in front of a truck that was waiting ahead of us.",
     ("truck", "stop", "front")),
])
def test_a_vehicle_a_crosser_comes_from_behind_keeps_its_own_place_ahead(prompt, bus):
    found = agents(prompt)
    assert bus in found and ("pedestrian", "cross_the_road", "near_the_crosswalk") in found, found


@pytest.mark.parametrize("prompt, expected", [
    ("Q: When did you first notice the police car? A: When I checked my mirror. It was coming up behind me.",
     ("police", "go_straight", "back")),
    ("I noticed the bus when I looked in my mirror. It was right behind me.", ("bus", "go_straight", "back")),
])
def test_it_after_a_clause_of_the_narrators_is_the_vehicle_named_before_not_the_narrator(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, other", [
    ("I wanted to get past a slow tractor in front of me, so I signalled and I pulled out to the right.",
     ("truck", "go_straight", "front")),
    ("I wanted to get around a bus ahead of me, so I indicated and I moved left.", ("bus", "go_straight", "front")),
])
def test_a_vehicle_named_in_a_verbless_clause_does_not_join_the_subject_of_a_so_clause(prompt, other):
    assert other in agents(prompt)


@pytest.mark.parametrize("prompt, vehicle", [
    ("The bus was stopped at the bus stop, letting people off, and I went around it. Then a kid came running out "
     "from in front of the bus, right into my lane.", ("bus", "stop", "front")),
    ("The lorry was stopped in the road, unloading, and we went round it. Then a man came running out from behind "
     "the lorry, right into our lane.", ("truck", "stop", "front")),
])
def test_a_vehicle_the_ego_went_around_stays_ahead_when_someone_runs_out_from_it(prompt, vehicle):
    assert vehicle in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A broken-down van was left in the lane ahead of us.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("A delivery van stopped dead in front of me and stayed there for a quarter of an hour. I was left sitting "
     "behind it.", [("car", "block_the_ego", "front"), ("car", "stop", "ego")]),
])
def test_left_after_been_or_was_is_left_standing_there_not_a_side(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "A lorry had been left on the hard shoulder ahead of me on my left. As I drew level, a man climbed down from "
    "the cab and walked straight across in front of me.",
    "The lorry had broken down on the hard shoulder ahead of us on the left. Its driver climbed down from the cab "
    "and walked across in front of us.",
])
def test_a_person_out_of_a_lorrys_cab_starts_where_the_lorry_stands_and_the_cab_is_no_taxi(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left"),
                              ("truck", "stop", "front_left")]


@pytest.mark.parametrize("prompt, expected", [
    ("The tractor-trailer was on the right shoulder, hazards on, stopped. The driver walked out from in front of it, "
     "into my lane.", [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right"),
                       ("truck", "stop", "front_right")]),
    ("A police car was parked on the hard shoulder on the left.",
     [("car", "go_straight", "ego"), ("police", "stop", "front_left")]),
])
def test_a_vehicle_stopped_on_the_shoulder_is_ahead_and_its_driver_walking_is_on_foot(prompt, expected):
    assert agents(prompt) == expected


def test_then_after_a_subject_and_its_participle_keeps_that_subject():
    found = agents("Three cars including mine were waiting at the give-way sign. A motorcyclist coming along the "
                   "main road from our right then turned left into our road.")
    assert ("motorcycle", "turn_left", "road_of_right_turn") in found and ("car", "stop", "ego") in found, found
    assert not any(a == ("car", "turn_left", "ego") for a in found), found


@pytest.mark.parametrize("prompt", [
    "A van parked on the left then pulled out in front of me.",
    "The bus stopped then pulled away.",
])
def test_then_right_after_a_finite_verb_goes_on_with_the_same_subject(prompt):
    egos = [a.action for a in lower(prompt).scenario.agents() if a.is_ego]
    assert egos == ["go_straight"], egos


@pytest.mark.parametrize("prompt, expected", [
    ("I admit I was looking at my phone and did not notice the van in front of me had stopped. I hit it at 20 mph.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("We were chatting and I never saw that the lorry ahead of us had stopped. I ran into the back of it.",
     [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
])
def test_what_the_narrator_did_not_notice_is_done_by_the_one_noticed(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A van in the lane to my right drifted into my lane and clipped my mirror. The van did stop, and the driver "
     "gave me his insurance details.", ("car", "change_lane_to_left", "right")),
    ("A car behind me ran into the back of me at the lights. The driver stopped to exchange details.",
     ("car", "go_straight", "back")),
])
def test_a_stop_to_settle_up_after_the_collision_is_not_the_scenes(prompt, expected):
    assert expected in agents(prompt)


def test_the_one_placed_before_is_that_member_and_both_drivers_are_the_vehicles_named():
    found = agents("I was stuck between two buses on I-70, one in front of me and one behind. The one in front "
                   "braked hard and stopped, and the one behind ran into me. Both drivers work for the same firm.")
    assert sorted(found) == [("bus", "go_straight", "back"), ("bus", "stop", "front"), ("car", "stop", "ego")]


@pytest.mark.parametrize("prompt", [
    "A van behind me ran into me at the lights. Car is badly damaged.",
    "A van behind me ran into me at the lights. Vehicle is totaled, bumper is gone.",
])
def test_a_bare_vehicle_said_to_be_damaged_afterwards_is_no_new_agent(prompt):
    assert agents(prompt) == [("car", "go_straight", "back"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("I stopped for a lady on the zebra crossing. Then the van behind me pulled out to overtake me on the right.",
     ("car", "change_lane_to_right", "back")),
    ("The car behind me pulled out and overtook me on the left.", ("car", "change_lane_to_left", "back")),
    ("A motorbike behind us overtook us on the right.", ("motorcycle", "go_straight", "back_right")),
])
def test_one_behind_that_pulls_out_to_pass_on_a_side_changes_lane_to_it_from_behind(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt", [
    "An ambulance approached from behind in the same lane with its siren on. I pulled to the right and stopped. "
    "The ambulance passed on the left.",
    "A police car came up behind me in my lane, lights on. I pulled over and it passed me on the right.",
])
def test_one_said_to_come_from_behind_in_the_ego_lane_starts_there_whichever_side_it_passes(prompt):
    found = [a for a in agents(prompt) if a[2] != "ego"]
    assert len(found) == 1 and found[0][2] == "back", found


@pytest.mark.parametrize("prompt, expected", [
    ("At the all-way stop, a sedan on the left had stopped first and was proceeding straight across.",
     ("car", "go_straight", "road_of_left_turn")),
    ("A car had stopped ahead of me.", ("car", "stop", "front")),
    ("A van cut in front of me and I had to stop dead.", ("car", "stop", "ego")),
])
def test_what_an_agent_had_done_before_yields_to_what_it_is_doing(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, crosswalk", [
    ("Q: Was there a crosswalk where you turned? A: There's a crosswalk, the ladder-style one. Q: And Mrs. Feeney was "
     "in that crosswalk? A: I didn't see her. She was crossing from my left, but the pillar blocks your view.",
     "ladder_crosswalk"),
    ("There is a zebra crossing at the junction. I turned right, and he walked out from my right.",
     "continental_crosswalk"),
])
def test_a_person_named_only_by_a_pronoun_crossing_where_the_road_has_a_crosswalk_is_on_it(prompt, crosswalk):
    scene = lower(prompt).scenario
    people = [(a.type, a.action, a.relative_to_ego) for a in scene.agents() if not a.is_ego]
    assert people == [("pedestrian", "cross_the_road", "near_the_crosswalk")], people
    assert scene.road.required_objects == (crosswalk,)


# -- documents by other hands: log stamps, letters' dates, emergency lights, a vehicle's own speed ---------------

@pytest.mark.parametrize("prompt, time", [
    ("Event 17 — 14:40, Park Ave. The AV stopped behind a parked van.", None),  # a log entry's stamp
    ("At 14:40 the AV stopped behind a parked van.", "noon"),
    ("TimeOfDay 22:00. The ego stops behind a parked van.", "night"),
])
def test_a_clock_time_is_the_scenes_time_only_when_said_as_when_it_happened(prompt, time):
    weather = lower(prompt).scenario.weather
    assert (weather.time if weather else None) == time


@pytest.mark.parametrize("prompt, time", [
    ("On Tuesday afternoon a lorry stopped in front of me.", None),
    ("On the morning of the 3rd a lorry stopped in front of me.", None),
    ("On a misty morning a lorry stopped in front of me.", "dawn"),
    ("Early on Tuesday morning a lorry stopped in front of me.", "dawn"),
])
def test_the_morning_of_a_named_day_dates_the_event_and_says_nothing_of_the_light(prompt, time):
    weather = lower(prompt).scenario.weather
    assert (weather.time if weather else None) == time


def test_an_emergency_vehicles_lights_and_siren_are_no_traffic_light():
    assert "traffic_light" not in road("A police car came up behind me, lights and siren, and I let it pass.") \
        .required_signals
    assert "traffic_light" in road("Though you have got the green, you wait for the bus from the left.") \
        .required_signals


@pytest.mark.parametrize("prompt, limit", [
    ("The AV was cruising in the left lane at about 40 mph when a van ahead braked.", None),
    ("Ego in lane 2, ~35 mph, a van ahead brakes.", None),
    ("The road narrows to one lane and 40 mph; a van ahead brakes.", "speed_64"),
])
def test_a_vehicles_speed_in_its_lane_is_no_speed_limit(prompt, limit):
    limits = [s for s in road(prompt).required_objects if s.startswith("speed_")]
    assert limits == ([limit] if limit else [])


@pytest.mark.parametrize("prompt, expected", [
    ("Init: SlowTruck in the Ego lane, 50 m ahead. Act 1: SlowTruck brakes to a stop.",
     [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
    ("Entities: Ego (car), Blocker (van). Init: Blocker parked ahead of Ego in its lane. Blocker never moves.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("Walker_2 (pedestrianCategory pedestrian) starts on the right kerb ahead of Ego. Walker_2 crosses in front "
     "of the Ego.", [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right")]),
    ("Ambulance_7 (vehicleCategory car, role ambulance) waits behind Ego in its lane. Ego stops, then "
     "Ambulance_7 stops too.", [("ambulance", "stop", "back"), ("car", "stop", "ego")]),
])
def test_an_agent_named_by_an_identifier_is_one_agent_at_every_mention(prompt, expected):
    assert agents(prompt) == expected


def test_a_scenario_keyword_made_of_words_names_no_agent():
    assert agents("Ego keeps its lane. MotoX_2 on the left lane behind Ego, AbsoluteTargetSpeed 120 km/h, "
                  "overtakes staying in its lane.") == [("car", "go_straight", "ego"),
                                                        ("motorcycle", "go_straight", "back_left")]


def test_a_named_agent_ends_a_phrase():
    assert agents("Bus_3 stops in front of the Ego. The Ego waits.") == [("bus", "stop", "front"),
                                                                          ("car", "stop", "ego")]


@pytest.mark.parametrize("prompt", [
    "The ego keeps the middle lane. A van in the right lane, 10 m ahead. Then a lane change of the van into the "
    "ego lane.",
    "The ego keeps the middle lane. A van in the right lane, 10 m ahead. Then a lane change action by the van "
    "into the ego lane.",
])
def test_an_action_named_as_a_noun_is_done_by_whom_of_or_by_names(prompt):
    assert agents(prompt) == [("car", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", [
    "Our car is driving down a high street and a cyclist ahead wobbles. The car just holds its speed.",
    "Our car is driving down a high street and a cyclist ahead wobbles. Does the car judge that well?",
])
def test_the_car_said_again_without_a_new_place_is_the_ego(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]


def test_one_after_another_names_no_member_of_the_group():
    assert agents("Three cars in the left lane ahead of the ego swerve right across in front of it, one after "
                  "another, all driving like lunatics.") == \
        [("car", "change_lane_to_right", "front_left")] * 3 + [("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", [
    "We wait at a junction. Two cars come from the right and turn left. The second one is coming fast.",
    "We wait at a junction. Two cars come from the right and turn left, and the second is coming fast.",
])
def test_a_member_that_is_only_coming_keeps_the_groups_manoeuvre(prompt):
    assert [a for _, a, p in agents(prompt) if p != "ego"] == ["turn_left", "turn_left"]


def test_a_transcripts_speaker_labels_are_not_read_as_subjects():
    words = [t.word for t in tokenize("HOST A: Our car waits at the lights.\nHOST B: Here we go.\n"
                                      "HOST A: A cyclist comes up on the left.")]
    assert "host" not in words and "is" not in words


@pytest.mark.parametrize("prompt", [
    "A lorry pulled out in front of me and I reported it to the police.",
    "A lorry pulled out in front of me. I do not blame the fire brigade, who were miles away.",
    "A lorry pulled out in front of me. Lorries are a menace on this road.",
    "A lorry pulled out in front of me, which is harder to avoid than cyclists think.",
    "A lorry pulled out in front of me. The cycle courier was banned from the road in 2018.",
    "A lorry pulled out in front of me as I left the car park.",
])
def test_agents_only_talked_about_are_nobody_in_the_scene(prompt):
    assert [t for t, _, p in agents(prompt) if p != "ego"] == ["truck"]


def test_a_topic_said_alone_is_no_agent_but_a_heading_of_actors_still_counts():
    assert [t for t, _, p in agents("A: Buses.\nB: Go on.\nA: A bus pulls out in front of us.") if p != "ego"] \
        == ["bus"]


def test_holding_the_lane_centre_drives_on_and_speed_zero_never_moving_stops():
    assert agents("The AV held lane centre while a motorbike passed on its left.") == \
        [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "back_left")]
    assert ("truck", "stop", "front") in agents("A lorry in the ego lane 60 m ahead, speed 0, never moves.")


@pytest.mark.parametrize("prompt", ["Dual carriageway, no interchanges for miles, the AV drives on.",
                                    "Main St, no cross streets in this segment, the AV drives on."])
def test_no_interchanges_or_cross_streets_is_no_junction(prompt):
    assert road(prompt).junction is False


def test_a_target_road_and_crossing_intent_name_no_agent():
    assert [t for t, _, _ in agents("The ego turns right into the target road. A pedestrian waits at the kerb "
                                    "with no crossing intent.")] == ["car", "pedestrian"]
    assert "crosswalk" not in road("A pedestrian waits at the kerb with no crossing intent.").without_objects


def test_then_as_in_that_case_is_no_later_stage():
    assert len(lower("A: A bus overtakes us on the left.\nB: Then honestly that is fine, the car just holds its "
                     "line.").scenario.stages) == 1


def test_two_names_joined_by_a_hyphen_are_two_agents():
    assert agents("Ego drives on in its lane. SlowTruck ahead of Ego in the same lane never moves. Trigger: "
                  "distance Ego-SlowTruck < 30 m.") == [("car", "go_straight", "ego"), ("truck", "stop", "front")]


def test_going_around_as_the_purpose_of_a_lane_change_keeps_its_side():
    assert ("car", "change_lane_to_right", "ego") in agents(
        "A van is broken down ahead of us. The AV changed lanes to the right to go around the van.")


def test_a_wait_of_minutes_opens_a_later_stage_not_a_trigger():
    stages = lower("A truck stopped ahead and we stopped behind it. After ~3 min we changed lanes to the left."
                   ).scenario.stages
    assert [[a.action for a in s.agents if a.is_ego] for s in stages] == [["stop"], ["change_lane_to_left"]]
    assert len(lower("A truck stopped ahead. After 3 s a car cuts in from the left.").scenario.stages) == 1


def test_a_bare_vehicle_held_by_the_operator_is_the_ego():
    assert sorted(t for t, _, _ in agents("AV waiting at red. Operator kept vehicle stopped until the bus had "
                                          "cleared.")) == ["bus", "car"]


@pytest.mark.parametrize("prompt", ["Ford & 5th. The AV waited at the red light.",
                                    "Near 5th and Ford, the AV waited at the red light."])
def test_a_make_joined_to_a_numbered_street_is_a_street_corner(prompt):
    assert [t for t, _, _ in agents(prompt)] == ["car"]


def test_a_letters_greeting_with_its_addressee_and_a_german_closing_are_not_the_scene():
    letter = ("Good morning, team,\n\nA lorry parks on the pavement outside our school every morning.\n\n"
              "Mit freundlichen Gr\u00fc\u00dfen\nJo Bloggs\nRiverside Cyclists and Walkers\n")
    assert agents(letter) == [("car", "go_straight", "ego"), ("truck", "stop", "front")]


def test_the_driver_a_vehicle_is_driven_by_is_the_ego_when_it_is_named_again():
    email = ("The minibus, driven by Marek, was on the high street. At the lights Marek turned left and a cyclist "
             "came up on the inside. The minibus is the ego.")
    assert agents(email) == [("bus", "turn_left", "ego"), ("cyclist", "go_straight", "right")]


@pytest.mark.parametrize("prompt, ego", [
    ("One of our ambulances was turning right when a cyclist came up on its inside. "
     "Please build a scene with our ambulance as the ego.", ("ambulance", "turn_right", "ego")),
    ("One of our trams was turning right when a cyclist came up on its inside. Our tram is the ego.",
     ("bus", "turn_right", "ego")),
])
def test_a_vehicle_named_as_the_ego_by_any_vehicle_noun_is_the_ego(prompt, ego):
    found = agents(prompt)
    assert ego in found and len(found) == 2, found


def test_our_vehicle_with_more_words_before_its_noun_is_the_ego_named_so():
    found = agents("Our white delivery van stops at the crossing and a bus overtakes it. Our van is the ego.")
    assert found == [("bus", "go_straight", "back_left"), ("car", "stop", "ego")]


@pytest.mark.parametrize("prompt, action", [
    ("A removal lorry stopped ahead of me on Mill Lane and then sat there for twenty minutes.", "block_the_ego"),
    ("A removal lorry stopped ahead of me on Mill Lane for a few seconds and drove on.", "stop"),
])
def test_a_vehicle_that_stays_in_front_of_the_ego_for_minutes_blocks_it(prompt, action):
    assert ("truck", action, "front") in agents(prompt)


def test_mine_among_a_counted_group_is_the_ego():
    found = agents("Four cars including mine were queuing at the lights on Bridge Street.")
    assert found.count(("car", "stop", "front")) == 3 and ("car", "stop", "ego") in found and len(found) == 4, found


def test_the_ego_said_to_be_included_after_its_group_is_one_of_it():
    found = agents("We sat at the level crossing barrier in a line of four cars, my own included.")
    assert found.count(("car", "stop", "front")) == 3 and ("car", "stop", "ego") in found and len(found) == 4, found


@pytest.mark.parametrize("prompt, later", [
    ("The ego waits behind a bus that is stopped at a bus stop, then overtakes it.", ("car", "go_straight", "ego")),
    ("The ego follows a van which brakes suddenly, and then swerves around it.",
     ("car", "change_lane_to_left", "ego")),
])
def test_a_verb_on_the_relatives_noun_after_a_relative_clause_is_the_main_subjects(prompt, later):
    found = agents(prompt)
    assert later in found and len(found) == 3 and not any(a[2] == "front" and a[1] == later[1] for a in found), found


# -- spoken, texted and reviewed descriptions ----------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("I stopped for a kid on the crossing and the van stopped behind me kept beeping at me.", ("car", "stop", "back")),
    ("We waited at the red and a taxi parked behind us was honking like crazy.", ("car", "stop", "back")),
    ("The bloke behind me leaned on his horn the whole way down the high street.", ("car", "go_straight", "back")),
])
def test_a_horn_says_a_driver_is_there_but_not_where_it_goes(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt", [
    "Night, and a scooter with no lights was weaving about in the lane ahead of us.",
    "A hatchback in the right lane shoots across into my lane, no signal, nothing.",
    "This lorry drifts over into our lane. Just like that. No signal whatsoever.",
])
def test_a_vehicle_without_lights_or_signal_is_its_own_lamps_not_the_road(prompt):
    assert "traffic_light" not in road(prompt).without_signals


def test_no_signal_where_a_junction_is_named_is_the_junctions():
    assert "traffic_light" in road("T-junction, no signal. A car from the left cuts into my lane.").without_signals


@pytest.mark.parametrize("prompt", [
    "Lunch hour on Mill Street, and a bus pulls out in front of us.",
    "It was the lunch rush and a van was double parked ahead of me.",
])
def test_the_lunch_hour_is_midday(prompt):
    scene = lower(prompt).scenario
    assert scene.weather is not None and scene.weather.time == "noon"


@pytest.mark.parametrize("prompt, expected", [
    ("Two joggers are running along the pavement ahead on our left. They might step out though.",
     ("pedestrian", "on_the_sidewalk", "front_left")),
    ("A scooter is riding along on our right and may well swerve left at any moment.",
     ("motorcycle", "go_straight", "right")),
    ("There's a van in front of us that might be turning left.", ("car", "turn_left", "front")),
])
def test_what_an_agent_might_do_is_weaker_than_what_it_is_said_to_do(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, limit", [
    ("Thirty mile an hour limit on this bit, and a bus pulls out ahead of us.", "speed_48"),
    ("It's a forty miles an hour road and a van is parked ahead.", "speed_64"),
])
def test_a_limit_in_miles_an_hour_said_aloud_is_converted(prompt, limit):
    assert limit in road(prompt).required_objects


def test_a_crosswalk_described_by_its_ladder_stripes_is_a_ladder_crosswalk():
    found = road("One of those crossings with the big ladder stripes, and a kid is crossing.")
    assert "ladder_crosswalk" in found.required_objects and "crosswalk" not in found.required_objects


@pytest.mark.parametrize("prompt, expected", [
    ("An old man was on the crossing and I didn't budge till he was over.", ("car", "stop", "ego")),
    ("The lorry in front of us did not budge an inch for a whole minute.", ("truck", "stop", "front")),
    ("A coach on my right wouldn't budge, so I couldn't get over.", ("bus", "go_straight", "right")),
])
def test_not_budging_is_standing_still_but_refusing_to_budge_is_not_making_room(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("heading to the gym this morning a taxi pulled out in front of me and stopped dead",
     [("car", "block_the_ego", "front"), ("car", "go_straight", "ego")]),
    ("waiting at the lights on main st a cyclist came up on my right",
     [("car", "stop", "ego"), ("cyclist", "go_straight", "right")]),
])
def test_an_opening_participle_with_no_comma_is_the_narrators_and_the_clause_after_has_its_own_subject(
        prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "a truck ran the red right in front of me, dad said i did good to stop",
    "a van pulled out on me at the roundabout and grandma told me to calm down",
])
def test_kin_named_like_a_name_is_not_on_the_road_unless_on_foot(prompt):
    assert not any(a[0] == "pedestrian" for a in agents(prompt))


def test_kin_named_like_a_name_on_foot_is_on_the_road():
    assert ("pedestrian", "cross_the_road", "front") in agents("dad was crossing the street ahead of me")


@pytest.mark.parametrize("prompt", [
    "a bike swerved out and missed me by like a foot mom was not happy",
    "the bus stopped maybe two metres ahead of me dad said nothing",
])
def test_a_measure_ends_the_noun_phrase_before_it(prompt):
    assert not any(a[0] == "pedestrian" for a in agents(prompt)), agents(prompt)


@pytest.mark.parametrize("prompt, kind", [
    ("A whole crowd of people spilled across the crossing in front of us.", "pedestrian"),
    ("A big group of cyclists rode past us on the left.", "cyclist"),
])
def test_a_group_sized_by_an_adjective_is_a_group_of_unstated_size(prompt, kind):
    assert sum(a[0] == kind for a in agents(prompt)) == 2


@pytest.mark.parametrize("prompt", [
    "we were three cars including mine sat at the red and I was in the middle",
    "Three vans including ours queued at the lights on Hill Road. We were in the middle.",
])
def test_the_ego_in_the_middle_of_a_group_including_it_has_one_ahead_and_one_behind(prompt):
    found = agents(prompt)
    assert ("car", "stop", "ego") in found and ("car", "stop", "front") in found and \
        ("car", "stop", "back") in found and len(found) == 3, found


@pytest.mark.parametrize("prompt, expected", [
    ("A van waiting to turn left sat in the left lane beside me at the lights.", ("car", "stop", "left")),
    ("Two taxis were waiting to turn right at the red ahead of me.", ("car", "stop", "front")),
])
def test_another_vehicle_waiting_to_turn_waits(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A bin lorry was right next to us on the right and my driver couldn't get over.", ("truck", "go_straight", "right")),
    ("A coach was alongside me on the left and I had to stay in my lane.", ("bus", "go_straight", "left")),
])
def test_a_new_subject_with_a_modal_after_a_placed_agent_opens_its_own_clause(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("some van cut me off today, it was in the right lane and swerved left into my lane", ("car", "change_lane_to_left", "right")),
    ("A taxi cut me off. It swerved into my lane from the right and stopped dead.", ("car", "block_the_ego", "front_right")),
    ("A car swerved into my lane from the left and blocked me.", ("car", "block_the_ego", "front_left")),
])
def test_a_cut_off_told_as_a_lane_change_without_a_stop_is_that_lane_change(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A taxi cut me off: it swerved into my lane from the right and stopped dead.", ("car", "block_the_ego", "front_right")),
    ("A lorry overtook me: it came past on the right and pulled in.", ("truck", "change_lane_to_left", "back_right")),
])
def test_a_first_person_clause_before_a_colon_is_a_sentence_not_a_title(prompt, expected):
    assert expected in agents(prompt)


def test_a_police_car_that_has_pulled_over_a_vehicle_stands_and_so_does_the_vehicle():
    found = agents("There's a patrol car on the hard shoulder ahead on our right, and it's pulled over a lorry. "
                   "We move into the left lane.")
    assert ("police", "stop", "front_right") in found and ("truck", "stop", "front_right") in found, found


@pytest.mark.parametrize("prompt, expected", [
    ("A squad car pulled over a taxi in the lane ahead of us.", ("car", "stop", "front")),
    ("The van in front pulled over to let the fire engine through.", ("car", "change_lane_to_right", "front")),
])
def test_pulling_over_another_vehicle_stops_it_but_pulling_over_is_a_move_to_the_side(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt", [
    "Too much American TV, honestly. Anyway, a cab pulls up behind us.",
    "Saw this on a TV show once: a cab pulls up behind us.",
])
def test_television_is_no_target_vehicle(prompt):
    found = agents(prompt)
    assert len(found) == 2 and [a[2] for a in found].count("back") == 1, found


def test_a_target_vehicle_abbreviated_tv_is_still_one():
    assert ("car", "stop", "front") in agents("The TV brakes to a stop in front of the VUT.")


def test_swinging_over_in_front_of_the_ego_is_a_cut_in():
    assert ("car", "change_lane_to_left", "right") in agents("A minivan in the right lane swings over in front of us.")


def test_it_after_an_agent_named_in_the_same_clause_is_that_agent():
    found = agents("We're cruising in the middle lane. A lorry in the right lane decides it wants our lane and "
                   "swings over.")
    assert ("car", "go_straight", "ego") in found and ("truck", "change_lane_to_left", "right") in found, found


@pytest.mark.parametrize("prompt", [
    "The one that really gets me is the cut-in. A hatchback on our left dives into our lane.",
    "Honestly, my least favourite is the merge. A bus on our left moves into our lane.",
])
def test_a_manoeuvre_named_as_the_topic_is_nobodys_act(prompt):
    found = agents(prompt)
    assert ("car", "go_straight", "ego") in found and len(found) == 2, found


@pytest.mark.parametrize("prompt, expected", [
    ("There's a van in the left lane right next to us. We wait until that van's gone past, and then our car "
     "moves over into the left lane.", ("car", "go_straight", "left")),
    ("A taxi is in the right lane right beside us. We hang on until the taxi has gone past, then our car moves "
     "over to the right.", ("car", "go_straight", "right")),
])
def test_a_vehicle_placed_beside_the_ego_that_goes_past_starts_beside_it(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, action", [
    ("A bin lorry is stopped in front of me and it is not moving, basically forever.", "block_the_ego"),
    ("HOST A: A removal van is parked in our lane and it's not moving.\nHOST B: Forever.\nHOST A: Pretty much.",
     "block_the_ego"),
    ("A removal van is parked in our lane and it's not moving. We wait a second and it drives off.", "stop"),
])
def test_a_vehicle_stopped_in_front_of_the_ego_forever_blocks_it(prompt, action):
    assert ("truck", action, "front") in agents(prompt)


@pytest.mark.parametrize("prompt, kind", [
    ("On the A38 a lorry is stuck just ahead of me.", "truck"),
    ("Northbound on SR-99 a bus stops ahead of the ego.", "bus"),
    ("On the B1234 a tractor crawls along in front of us.", "truck"),
])
def test_a_roads_number_before_an_agent_counts_nothing(prompt, kind):
    found = agents(prompt)
    assert [a[0] for a in found].count(kind) == 1 and len(found) == 2, found


@pytest.mark.parametrize("prompt", [
    "Warm light on the shop windows. A cyclist pedals along ahead of us.",
    "Pale light over the fields as a tractor trundles along in front of us.",
])
def test_light_that_lights_the_scene_is_no_traffic_light(prompt):
    assert "traffic_light" not in road(prompt).required_signals


def test_a_light_named_by_its_street_is_still_a_traffic_light():
    assert "traffic_light" in road("At the Elm Street light a pickup is stalled in front of us.").required_signals


def test_an_oncoming_lane_beside_a_signal_is_no_junction():
    scene = lower("A red light flashes at the level crossing ahead. A tractor comes towards us in the oncoming lane.")
    assert scene.scenario.road.junction is not True
    assert ("car", "go_straight", "front_left") in agents(
        "A red light flashes at the level crossing ahead. A van comes towards us in the oncoming lane.")


@pytest.mark.parametrize("prompt, action", [
    ("a kid chased a ball into the road and i slammed the brakes like three feet from him", "stop"),
    ("A deer leapt out and I braked hard about two metres short of it.", "stop"),
    ("A deer leapt out and I braked hard to avoid it.", "go_straight"),
])
def test_a_brake_that_ends_a_distance_short_of_someone_is_a_stop(prompt, action):
    assert ("car", action, "ego") in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("I was waiting to turn right and a scooter came up on my right. After it passed, I turned.",
     ("motorcycle", "go_straight", "right")),
    ("A van is in the lane to my left. Once it has gone past I pull out.", ("car", "go_straight", "left")),
])
def test_going_by_said_as_a_condition_is_no_overtaking_of_the_ego(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("I'm waiting to turn left, a lorry is parked on the street I'm turning into and a man is standing on the "
     "pavement there.", ("pedestrian", "on_the_sidewalk", "at_the_destination")),
    ("A van is coming from the road on the right and a cyclist is there too.", ("cyclist", "go_straight",
                                                                                 "road_of_right_turn")),
])
def test_there_is_the_junction_road_of_the_one_named_before(prompt, expected):
    assert expected in agents(prompt)


def test_there_is_with_a_copula_names_no_place():
    found = agents("A van is coming from the road on the right and there is a cyclist ahead of me.")
    assert ("cyclist", "go_straight", "front") in found, found


@pytest.mark.parametrize("prompt, expected", [
    ("My car drives in the middle lane, and behind my car there is a lorry.", ("truck", "go_straight", "back")),
    ("Child runs out from behind parked van in front of my car.", ("pedestrian", "cross_the_road", "front")),
])
def test_a_vehicle_or_child_with_its_own_article_or_none_is_no_kin_and_not_the_ego(prompt, expected):
    assert expected in agents(prompt)


def test_a_bare_guy_riding_after_a_cyclist_is_the_cyclist():
    found = agents("a cyclist was coming up on my left. guy was riding right next to us and then he went straight on")
    assert [a[0] for a in found] == ["car", "cyclist"], found


@pytest.mark.parametrize("prompt, expected", [
    ("4.2 Cyclist crossing test\n4.2.1 The subject vehicle shall travel at 40 km/h.\n"
     "4.2.2 A cyclist target shall cross the road in front of the subject vehicle.",
     [("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "front")]),
    ("2.1.3 A bus shall be stopped ahead of the subject vehicle.\n2.1.4 The subject vehicle shall stop behind it.",
     [("car", "stop", "ego"), ("bus", "stop", "front")]),
    ("12.3.4 A pedestrian shall walk on the pavement to the right of the vehicle under test.",
     [("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "right")]),
    ("9.1 A truck shall overtake the ego on the left.", [("car", "go_straight", "ego"),
                                                         ("truck", "go_straight", "back_left")]),
])
def test_the_clause_numbers_of_a_formal_document_count_nothing(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_a_numbered_section_heading_gives_no_speed_limit():
    found = road("5.3 Speed limit information\n5.3.1 The subject vehicle shall drive straight at 60 km/h.")
    assert not found.required_objects and not found.required_signals, found


@pytest.mark.parametrize("prompt, expected", [
    ("Left turn case. The ego turns left at the lights, a van comes the other way. Priya suggested a cyclist as "
     "well, not in this version.", [("car", "turn_left", "ego"), ("car", "go_straight", "road_of_straight")]),
    ("Cut-in case: a truck in the right lane cuts in front of the ego. Marco wanted a second truck behind it: "
     "deferred, maybe later.", [("car", "go_straight", "ego"), ("truck", "change_lane_to_left", "right")]),
    ("A child runs out in front of the ego. The team decided to leave out the parked cars for v1.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("The ego waits at the red light. We agreed to drop the bus and keep one car ahead, which also waits.",
     [("car", "stop", "ego"), ("car", "stop", "front")]),
])
def test_what_minutes_say_was_proposed_and_turned_down_or_left_out_is_no_agent(prompt, expected):
    assert agents(prompt) == sorted(expected)


@pytest.mark.parametrize("prompt, expected", [
    ("A bus stops to drop off two kids in front of the ego.", ("pedestrian", "cross_the_road", "front")),
    ("Jo asked for a parked van ahead of the ego too, agreed.", ("car", "stop", "front")),
])
def test_a_proposal_the_minutes_keep_stays_in_the_scene(prompt, expected):
    assert expected in agents(prompt)


def test_the_teams_own_schedule_starts_no_stage():
    scene = lower("The ego drives straight on and a jogger crosses in front of it.\nAction: PK to build it, "
                  "target next sprint, review next week.").scenario
    assert len(scene.stages) == 1 and len(list(scene.agents())) == 2


@pytest.mark.parametrize("prompt, required, without", [
    ("A T-junction without stop or give-way signs; the ego turns right.", (), ("stop", "yield")),
    ("At a crossroads with stop and yield signs the ego goes straight.", ("stop", "yield"), ()),
    ("The test shall take place at a junction without traffic lights, stop or yield signs.", (),
     ("traffic_light", "stop", "yield")),
])
def test_a_sign_noun_said_once_for_two_signs_names_both(prompt, required, without):
    found = road(prompt)
    assert set(found.required_signals) == set(required) and set(found.without_signals) == set(without), found


@pytest.mark.parametrize("prompt", [
    "Yielding to an ambulance\nThe ego moves into the right lane so the ambulance behind can pass.",
    "Giving way to buses: the ego waits while a bus pulls out in front of it.",
])
def test_yielding_to_someone_is_the_act_not_a_sign(prompt):
    assert "yield" not in road(prompt).required_signals


@pytest.mark.parametrize("prompt, expected", [
    ("In my mirror a fire engine was closing fast.", ("firetruck", "go_straight", "back")),
    ("In the rear view mirror a motorbike weaves about.", ("motorcycle", "go_straight", "back")),
    ("On my tail a white van sat for miles.", ("car", "stop", "back")),
    ("He saw the cyclist in his mirror.", ("cyclist", "go_straight", "back")),
    ("A bus appeared in her rearview mirror.", ("bus", "go_straight", "back")),
])
def test_a_place_that_ends_in_its_own_noun_places_the_subject_after_it(prompt, expected):
    assert expected in agents(prompt)


def test_a_place_before_a_noun_still_takes_it_as_its_reference():
    found = agents("Behind the bus a cyclist waits. The ego drives on.")
    assert ("cyclist", "stop", "back") not in found and ("bus", "go_straight", "front") in found


@pytest.mark.parametrize("prompt, ego, other", [
    ("A police car is working its way through the queue behind me.", "go_straight", ("police", "go_straight", "back")),
    ("The queue reaches the retail park, and a lorry is edging its way along.", "go_straight",
     ("truck", "go_straight", "front")),
    ("I was stuck at the back of the queue behind a van.", "stop", ("car", "stop", "front")),
])
def test_a_queue_named_is_no_one_standing_unless_someone_is_in_it(prompt, ego, other):
    found = agents(prompt)
    assert ("car", ego, "ego") in found and other in found


@pytest.mark.parametrize("prompt", [
    "An ambulance, lights strobing, was right behind us.",
    "A police car with its lights spinning came up behind me and I pulled over.",
    "A fire engine, blue lights blinking, passes me.",
])
def test_an_emergency_vehicles_own_lamps_are_no_traffic_light(prompt):
    assert "traffic_light" not in road(prompt).required_signals


@pytest.mark.parametrize("prompt, expected", [
    ("Two vans parked on the left with a bus approaching from the other direction.",
     [("bus", "go_straight", "front_left"), ("car", "go_straight", "ego"), ("car", "stop", "front_left"),
      ("car", "stop", "front_left")]),
    ("A lorry stopped at the kerb with a cyclist coming up behind me.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "back"), ("truck", "stop", "front")]),
])
def test_a_participle_after_with_and_its_noun_is_that_nouns(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, ego_actions", [
    ("A bin lorry was stopped ahead. The candidate held back behind it and waited, then moved off and passed it.",
     ["stop", "go_straight"]),
    ("Two lorries were parked ahead. Candidate held back behind the parked lorries and waited, then moved off.",
     ["stop", "go_straight"]),
])
def test_the_candidate_of_a_driving_test_is_the_ego(prompt, ego_actions):
    scene = lower(prompt).scenario
    assert [a.action for stage in scene.stages for a in stage.agents if a.is_ego] == ego_actions


@pytest.mark.parametrize("prompt, expected", [
    ("A lorry cut me up on the bypass this morning.", None),
    ("Yesterday afternoon a cyclist ran the red in front of me.", None),
    ("Early this morning a cyclist ran the red in front of me.", ("clear", "dawn")),
    ("This morning at about 6 a cyclist ran the red in front of me.", ("clear", "dawn")),
    ("The rain was lashing down when a bus pulled out in front of me.", ("hard_rain", "noon")),
    ("Rain is pelting down and a van brakes ahead of me.", ("hard_rain", "noon")),
])
def test_the_day_an_event_happened_says_no_light_and_rain_said_by_what_it_does_is_heavy(prompt, expected):
    weather = lower(prompt).scenario.weather
    assert (None if weather is None else (weather.condition, weather.time)) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Three cyclists rode ahead of me, one of them a child.", [("car", "go_straight", "ego")] +
     [("cyclist", "go_straight", "front")] * 3),
    ("Two cars were parked on the left, one of them a taxi.", [("car", "go_straight", "ego")] +
     [("car", "stop", "front_left")] * 2),
])
def test_a_member_of_a_group_named_after_one_of_them_is_no_new_agent(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, limit", [
    ("On the A30, a 60 limit, a lorry pulls out in front of me.", "speed_97"),
    ("Outside the school, 20 limit, a child steps onto the zebra crossing.", "speed_32"),
    ("Northbound on I-5, speed limit 70, a pickup cuts in ahead of me.", "speed_113"),
    ("I was doing 30 miles an hour in a 40 limit when a van pulled out.", "speed_64"),
    ("Outside the school, 30 limit, a child steps onto the zebra; I'm doing 25 km/h.", "speed_30"),
    ("Speed limit 50, a cyclist crosses from the right.", "speed_50"),
])
def test_a_limit_said_by_its_number_on_a_british_or_us_road_is_in_mph(prompt, limit):
    assert [o for o in road(prompt).required_objects if o.startswith("speed_")] == [limit]


@pytest.mark.parametrize("prompt", [
    "I came up behind four riders cycling two abreast.",
    "Four horse riders, no, four cyclists were riding three abreast ahead of me.",
])
def test_riding_n_abreast_is_how_a_group_rides_not_a_part_of_it_beside_the_ego(prompt):
    found = agents(prompt)
    assert [a for a in found if a[0] == "cyclist"] == [("cyclist", "go_straight", "front")] * 4, found


@pytest.mark.parametrize("prompt, expected", [
    ("She came over the hill onto a tractor. She crept along behind it for a mile.",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "front")]),
    ("He pulled up at the lights behind a bus, and when they went green he turned left.",
     [("bus", "stop", "front"), ("car", "stop", "ego"), ("car", "turn_left", "ego")]),
])
def test_the_driver_a_story_is_told_of_without_a_name_is_the_ego(prompt, expected):
    assert agents(prompt) == expected


def test_the_driver_of_a_story_is_not_a_person_named_before_the_pronoun():
    assert ("pedestrian", "cross_the_road", "front") in agents(
        "A woman stepped off the kerb and she crept slowly across in front of a bus.")


def test_one_of_those_before_a_group_is_named_counts_nothing_of_it():
    found = agents("It was one of those dull, damp afternoons, and we came round a bend onto three cyclists.")
    assert [a[0] for a in found].count("cyclist") == 3, found


@pytest.mark.parametrize("prompt", ["I came over the hill onto a tractor.", "We went over the bridge behind a bus."])
def test_coming_over_a_hill_or_a_bridge_is_no_lane_change(prompt):
    assert ("car", "go_straight", "ego") in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A fire engine crosses the junction from the left with a police car right on its tail.",
     ("police", "go_straight", "road_of_left_turn")),
    ("An ambulance came at us from the opposite direction, a police van glued to its bumper, and I turned right.",
     ("police", "go_straight", "road_of_straight")),
])
def test_a_vehicle_on_anothers_tail_is_where_that_one_is(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("Driving in the UK: a cyclist came up on my inside at the lights.", ("cyclist", "go_straight", "left")),
    ("On the motorway a coach sat in the inside lane beside me.", ("bus", "go_straight", "left")),
    ("UK roundabout: I take the third exit and a taxi waits on the road to my left.", ("car", "turn_right", "ego")),
    ("At the roundabout I take the third exit.", ("car", "turn_left", "ego")),
])
def test_where_traffic_keeps_left_the_inside_is_left_and_the_third_exit_a_right_turn(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt", [
    "A van has broken down on the bypass and traffic is queuing back past the Tesco turn.",
    "A bus is stopped just before the Mill Road turn, so I wait behind it.",
    "I missed the turn and a cyclist passed me on the left.",
])
def test_a_turning_named_as_a_place_is_nobody_turning(prompt):
    assert not any(a[1].startswith("turn") for a in agents(prompt)), agents(prompt)


def test_taking_the_turn_still_turns():
    assert ("car", "turn_left", "ego") in agents("At the junction I took the turn to the left behind a bus.")


@pytest.mark.parametrize("prompt", [
    "Outside the school two little ones crossing, so I waited.",
    "An old man crossing, so we stopped and let him go.",
])
def test_crossing_after_a_person_named_in_several_words_is_the_person_crossing(prompt):
    assert not road(prompt).required_objects and any(a[1] == "cross_the_road" for a in agents(prompt))


@pytest.mark.parametrize("prompt", [
    "At the lights I turned left, and a cyclist was crossing Oak Avenue, the one I was turning into.",
    "I was turning right when two kids ran across the road I was turning into.",
])
def test_the_road_the_narrator_turns_into_is_the_destination_in_any_tense(prompt):
    assert any(a[2] == "at_the_destination" for a in agents(prompt)), agents(prompt)

@pytest.mark.parametrize("prompt, ego", [
    ("You are at the wheel of a fire engine, going straight through a junction.", "firetruck"),
    ("You're behind the wheel of a coach on a two-lane road.", "bus"),
    ("The player drives the getaway van down a back street.", "car"),
    ("The player pulls the bus in and waits at the stop.", "bus"),
    ("I was the front seat passenger in my brother's Skoda on the motorway.", "car"),
    ("I was sitting in the passenger seat of my friend's minibus when we stopped.", "bus"),
])
def test_a_vehicle_the_speaking_ego_drives_or_sits_in_is_the_egos_own(prompt, ego):
    found = [a.type for a in lower(prompt).scenario.agents()]
    assert found == [ego], found


@pytest.mark.parametrize("prompt", ["I was behind a bus at the lights.", "You pulled in behind the truck.",
                                    "I was in front of a lorry on the motorway."])
def test_a_vehicle_the_ego_is_placed_by_is_another_agent(prompt):
    assert len(agents(prompt)) == 2


@pytest.mark.parametrize("prompt", [
    "Delivery Van Frenzy - Round 4\nThe player waits at the red light behind a stopped bus.",
    'COACH PARTY - "CROSSFIRE"\nThe player waits at the red light behind a stopped bus.',
    "Taxi Rank Blues\n\nThe player waits at the red light behind a stopped bus.",
])
def test_a_marked_title_line_over_prose_names_no_agent(prompt):
    assert agents(prompt) == [("bus", "stop", "front"), ("car", "stop", "ego")]


@pytest.mark.parametrize("prompt, limit", [
    ("I was doing about 25 mph down the high street, it's a 30 limit.", "speed_48"),
    ("The lorry was doing 40 miles per hour in a 50 limit.", "speed_80"),
    ("On the motorway the roadworks had a 50 limit.", "speed_80"),  # keeps left: a British sign
    ("The truck was doing 60 km/h although it is a 40 limit.", "speed_40"),
    ("Speed limit 30 on this street, a child crosses.", "speed_30"),
])
def test_a_limit_said_by_its_number_alone_takes_the_texts_unit(prompt, limit):
    assert [w for w in road(prompt).required_objects if w.startswith("speed_")] == [limit]


@pytest.mark.parametrize("prompt, expected", [
    ("The roundabout is entered from the right by a lorry.", ("truck", "go_straight", "road_of_right_turn")),
    ("The crossroads is entered from the opposite side by a van while the ego waits.",
     ("car", "go_straight", "road_of_straight")),
])
def test_a_junction_entered_in_the_passive_is_entered_by_the_agent_after_by(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, action", [
    ("The ego is steered into the right lane.", "change_lane_to_right"),
    ("To let the bus out, I steered into the left lane.", "change_lane_to_left"),
])
def test_steering_into_a_named_lane_is_a_lane_change(prompt, action):
    assert ("car", action, "ego") in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A bus is waiting on the street the ego wants to turn into.", ("bus", "stop", "at_the_destination")),
    ("Two pedestrians are crossing the road that the ego is going to turn into.",
     ("pedestrian", "cross_the_road", "at_the_destination")),
    ("A taxi is stopped on the road that the ego is about to turn into.", ("car", "stop", "at_the_destination")),
])
def test_the_road_the_ego_is_about_to_turn_into_is_the_destination(prompt, expected):
    assert expected in agents(prompt) and ("car", "turn_left", "ego") in agents(prompt)


def test_that_road_said_again_after_the_destination_is_the_destination():
    found = agents("A taxi waits on the road the ego turns into. The ego turns left, and then two children cross "
                   "that road.")
    assert found.count(("pedestrian", "cross_the_road", "at_the_destination")) == 2


def test_a_sequence_word_after_a_place_that_starts_with_that_still_opens_a_stage():
    found = agents("The ego waits at a red light. A van is parked on the road that the ego is about to turn into. "
                   "Then the ego turns left.")
    assert ("car", "stop", "ego") in found and ("car", "turn_left", "ego") in found


@pytest.mark.parametrize("prompt, expected, absent", [
    ("You rolled past the give way line instead of stopping, and a van came from the right.",
     ("car", "go_straight", "ego"), ("car", "stop", "ego")),
    ("The lorry kept going rather than stopping at the red light.", ("truck", "go_straight", "ego"),
     ("truck", "stop", "ego")),
    ("Rather than braking, the van swerved into the left lane.", ("car", "change_lane_to_left", "front"),
     ("car", "stop", "front")),
])
def test_a_manoeuvre_passed_over_for_another_is_not_made(prompt, expected, absent):
    found = agents(prompt)
    assert expected in found and absent not in found


@pytest.mark.parametrize("prompt", [
    "You stopped dead when the fire engine came up behind. Better to pull over to the left.",
    "You stopped dead when the fire engine came up behind. It is best to pull over to the right.",
    "You stopped dead when the fire engine came up behind. A blue light behind you means pull over to the left.",
])
def test_advice_after_the_account_is_no_manoeuvre_of_the_scene(prompt):
    assert agents(prompt) == [("car", "stop", "ego"), ("firetruck", "go_straight", "back")]


def test_what_the_ego_did_instead_replaces_what_it_was_to_do():
    found = agents("There was a lorry parked on our side, so we had to wait. Instead you carried on.")
    assert ("car", "go_straight", "ego") in found and ("car", "stop", "ego") not in found


@pytest.mark.parametrize("prompt, expected", [
    ("On the approach to the junction the van in the right lane ahead of us moved into our lane.",
     ("car", "change_lane_to_left", "front_right")),
    ("On the approach to the roundabout the lorry in the right lane ahead of us came over into our lane.",
     ("truck", "change_lane_to_left", "front_right")),
])
def test_the_approach_to_a_place_is_a_place_not_the_egos_verb(prompt, expected):
    found = agents(prompt)
    assert expected in found and ("car", "go_straight", "ego") in found


@pytest.mark.parametrize("prompt", ["An oncoming pickup truck turns left in front of the ego.",
                                    "A pick-up truck is parked on the right ahead."])
def test_a_pickup_truck_is_a_car_as_the_conventions_type_it(prompt):
    assert [a.type for a in lower(prompt).scenario.agents() if not a.is_ego] == ["car"]


@pytest.mark.parametrize("prompt, expected", [
    ("A grey Audi came up the outside lane on my right and cut in front of me.",
     ("car", "change_lane_to_left", "back_right")),
    ("A lorry came up the left lane.", ("truck", "go_straight", "back_left")),
])
def test_coming_up_a_lane_beside_comes_from_behind(prompt, expected):
    assert expected in agents(prompt)


def test_coming_up_in_a_lane_says_no_more_than_the_lane():
    assert ("car", "change_lane_to_right", "back_left") not in agents(
        "A van came up fast in the left lane and cut in just in front of us.")


def test_a_place_said_after_a_cut_in_does_not_undo_where_it_started():
    found = agents("A white van came up the inside lane on my left, cut me up and braked hard. I had to stop to avoid "
                   "going into the back of it.")
    assert ("car", "block_the_ego", "back_left") in found


@pytest.mark.parametrize("prompt, limit", [("Empty dual carriageway, 100 km/h signs, the player cruises.", "speed_100"),
                                           ("There are 50 km/h signs along the road and a bus is parked ahead.",
                                            "speed_50")])
def test_signs_that_show_a_speed_are_its_limit(prompt, limit):
    assert limit in road(prompt).required_objects


@pytest.mark.parametrize("prompt", ["A cyclist rides ahead of the ego. Keep the focus on the cyclist.",
                                    "A cyclist rides ahead of the ego; the focus on the cyclist matters most."])
def test_the_focus_on_something_is_no_ford(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]


@pytest.mark.parametrize("prompt", [
    "The player waits at a red light. When the light flips to green the player has to turn left.",
    "The ego waits at the red light. When the lights switch to green the ego turns left.",
    "The ego waits at a red light. When it changes to green the ego turns left.",
])
def test_a_light_changing_colour_without_a_comma_opens_a_stage_for_the_clause_after(prompt):
    found = agents(prompt)
    assert ("car", "stop", "ego") in found and ("car", "turn_left", "ego") in found


@pytest.mark.parametrize("prompt, expected", [
    ("When you see a school bus with its stop arm out, stop. Today a van passes you on the left.",
     [("car", "go_straight", "back_left"), ("car", "go_straight", "ego")]),
    ("If you come across a tractor on a narrow lane, slow down. Here a cyclist is riding ahead of you.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]),
])
def test_whoever_a_rule_says_you_may_meet_is_nobody_in_the_scene(prompt, expected):
    assert agents(prompt) == expected


def test_someone_the_narrator_saw_is_still_in_the_scene():
    assert ("police", "stop", "front_right") in agents(
        "When I saw a police car on the shoulder, I moved over.")


@pytest.mark.parametrize("prompt, expected", [
    ("| id | type | role | lane | action |\n|----|------|------|------|--------|\n| EGO | hatchback | SUT | lane 1 | "
     "keep lane |\n| V2 | lorry | lead veh | ego lane, 30 m ahead | stops |",
     [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
    ("name,kind,position,manoeuvre,speed_mph\nego,car,approach,turn_right,10\nbike1,cyclist,oncoming,straight,12",
     [("car", "turn_right", "ego"), ("cyclist", "go_straight", "road_of_straight")]),
    ("agent   | start          | intent\nego     | south approach | straight\nnpc_x   | west (left)    | "
     "turn right", [("car", "go_straight", "ego"), ("car", "turn_right", "road_of_left_turn")]),
])
def test_a_table_of_actors_reads_one_actor_a_row(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_a_tables_speed_column_gives_its_unit_and_its_time_column_the_stages():
    scene = lower("| step | actor | what |\n|---|---|---|\n| 1 | ego | waits at the red light |\n"
                  "| 1 | pedestrian | on crosswalk, crossing |\n| 2 (after the pedestrian is clear) | ego | "
                  "goes straight |").scenario
    assert len(scene.stages) == 2 and scene.stages[1].agents[0].action == "go_straight"
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in agents(
        "| step | actor | what |\n|---|---|---|\n| 1 | ego | waits |\n| 1 | pedestrian | on crosswalk, crossing |")
    ego = lower("actor,type,speed_mph\nego,car,25\nnpc1,truck,30").scenario.ego
    assert ego.speed is not None and ego.speed.unit == "mph" and float(ego.speed.value) == 25


@pytest.mark.parametrize("prompt, expected", [
    ("Ego: straight. Van: oncoming, turn left.", ("car", "turn_left", "road_of_straight")),
    ("Ego: 30 km/h, keep lane. Bus: ahead, brake hard.", ("bus", "stop", "front")),
])
def test_a_bare_verb_later_in_a_keyed_line_is_the_keys(prompt, expected):
    found = agents(prompt)
    assert expected in found and ("car", "go_straight", "ego") in found, found


@pytest.mark.parametrize("prompt, expected", [
    ("Ego: turns right. Cyclist: on crosswalk at exit arm, crossing.",
     ("cyclist", "cross_the_road", "near_the_crosswalk")),
    ("Ego: turns left. Ped1: pedestrian, xwalk at exit leg, crossing.",
     ("pedestrian", "cross_the_road", "near_the_crosswalk")),
])
def test_crossing_as_a_piece_of_its_own_in_a_persons_note_is_what_they_do(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("The ego pulls out into the right lane to pass a bus.", ("car", "change_lane_to_right", "ego")),
    ("On the dual carriageway the ego pulls out into the left lane to pass a slow lorry.",
     ("car", "change_lane_to_left", "ego")),
    ("A van pulls out into the right lane ahead of the ego.", ("car", "change_lane_to_right", "front")),
])
def test_pulling_out_into_a_named_lane_goes_to_that_side(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("The vehicle under test shall be a bus. It shall turn left at the junction.", [("bus", "turn_left", "ego")]),
    ("The subject vehicle shall be a goods vehicle. A cyclist shall ride beside it on the left.",
     [("truck", "go_straight", "ego"), ("cyclist", "go_straight", "left")]),
])
def test_what_a_test_says_the_ego_shall_be_is_its_type(prompt, expected):
    assert agents(prompt) == sorted(expected)


@pytest.mark.parametrize("prompt, other", [
    ("The subject vehicle shall travel at 40 km/h behind a van. The subject vehicle driver shall not brake.",
     ("car", "go_straight", "front")),
    ("The VUT shall travel at 30 km/h. A pedestrian shall cross in front of it. The driver of the VUT shall not "
     "brake.", ("pedestrian", "cross_the_road", "front")),
])
def test_the_driver_of_the_ego_is_the_ego(prompt, other):
    assert agents(prompt) == sorted([("car", "go_straight", "ego"), other])


def test_a_tests_dry_conditions_are_clear_weather():
    assert lower("The ego turns right. The test shall be performed in dry conditions.").scenario.weather.condition \
        == "clear"


@pytest.mark.parametrize("prompt, expected", [
    ("We're merging left and there's a coach in the left lane just behind us, so we slot in behind it.",
     ("bus", "go_straight", "back_left")),
    ("A lorry sits in the right lane just behind me, so I pull in behind it.", ("truck", "go_straight", "back_right")),
])
def test_where_an_agent_is_said_to_be_first_is_where_it_starts(prompt, expected):
    assert expected in agents(prompt)


def test_an_agent_named_in_words_cut_off_and_named_again_is_one():
    talk = ("HOST A: So we're in the right lane and we need to get left.\n"
            "HOST B: And there's a coach\u2014\n"
            "HOST A: A coach!\n"
            "HOST B: Yes. There's a bus in the left lane just behind us, so we slot in behind it.")
    found = agents(talk)
    assert [a[0] for a in found].count("bus") == 1, found


def test_words_cut_off_that_name_no_agent_again_stay():
    talk = ("HOST A: It's dusk, we're going straight, and there's a cyclist on the right\u2014\n"
            "HOST B: Oh no.\n"
            "HOST A: And a van comes up behind us.")
    assert ("cyclist", "go_straight", "right") in agents(talk)


@pytest.mark.parametrize("prompt", [
    "a taxi pulled out right in front of me on Mill Road and stopped. #london @MetPolice",
    "@CyclingUK a taxi pulled out right in front of me on Mill Road and stopped. #cycling #roadsafety",
])
def test_a_posts_handles_and_hashtags_name_nobody_on_the_road(prompt):
    assert agents(prompt) == [("car", "block_the_ego", "front"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, weather", [
    ("Ego turns left at the junction #rain #night", ("mid_rain", "night")),
    ("a taxi pulled out in front of me and stopped #dashcam #fog", ("fog", "noon")),
    ("a taxi pulled out in front of me and stopped #roadrage #Tesla", None),
])
def test_a_posts_closing_tags_that_name_weather_or_light_say_it_of_the_scene(prompt, weather):
    said = lower(prompt).scenario.weather
    assert ((said.condition, said.time) if said else None) == weather


@pytest.mark.parametrize("prompt", [
    "a lorry broke down on the hard shoulder ahead of me and nobody moved over. come on people",
    "a lorry broke down on the hard shoulder ahead of me. drive safe out there folks",
])
def test_the_readers_called_on_at_the_end_are_nobody_on_the_road(prompt):
    assert not any(a[0] == "pedestrian" for a in agents(prompt)), agents(prompt)


def test_you_in_a_post_written_to_someone_on_the_road_is_them():
    post = ("To the van driver on Hill St this morning: I was going straight through the lights and you turned "
            "left right across me. I nearly hit you.")
    found = agents(post)
    assert ("car", "go_straight", "ego") in found and any(a[0] == "car" and a[1] == "turn_left" for a in found), found


def test_you_addressed_by_a_driving_instructor_stays_the_ego():
    assert ("car", "turn_left", "ego") in agents("Dear learner: at the lights you turn left after the bus passes.")


@pytest.mark.parametrize("prompt", [
    "a lorry sat about 2m off my bumper for miles on the A1",
    "some van sat right on my bumper all the way down the bypass",
])
def test_sitting_on_the_egos_bumper_is_tailgating_not_standing(prompt):
    found = agents(prompt)
    assert any(a[1] == "go_straight" and a[2] == "back" for a in found if a[2] != "ego"), found


@pytest.mark.parametrize("prompt, time", [
    ("This morning a bus pulled out in front of me on Mill Road.", None),
    ("Yesterday afternoon a bus pulled out in front of me on Mill Road.", None),
    ("Early this morning a bus pulled out in front of me on Mill Road.", "dawn"),
    ("This morning at about 6 a bus pulled out in front of me on Mill Road.", "dawn"),
    ("At 2 this afternoon a bus pulled out in front of me on Mill Road.", "noon"),
])
def test_this_morning_dates_the_event_unless_early_or_with_its_hour(prompt, time):
    weather = lower(prompt).scenario.weather
    assert (weather.time if weather else None) == time


@pytest.mark.parametrize("prompt, condition", [("It was getting dark and raining really hard.", "hard_rain"),
                                               ("Raining very lightly as the bus pulled out.", "soft_rain"),
                                               ("It was raining pretty heavily on the motorway.", "hard_rain")])
def test_how_hard_it_rains_said_after_an_intensifier_sets_the_rain(prompt, condition):
    assert lower(prompt).scenario.weather.condition == condition


@pytest.mark.parametrize("prompt, expected", [
    ("I overtook a tractor instead of waiting behind it.", [("car", "go_straight", "ego"), ("truck", "go_straight", "front")]),
    ("Instead of stopping, the bus ahead of me carried on.", [("bus", "go_straight", "front"), ("car", "go_straight", "ego")]),
])
def test_what_was_done_instead_of_is_not_done(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "Keep a safe distance to other road users while the bus ahead of you stops.",
    "Be considerate towards other road users; a bus stops ahead of you.",
])
def test_other_road_users_in_general_are_nobody_in_the_scene(prompt):
    assert [a[0] for a in agents(prompt)] == ["bus", "car"], agents(prompt)


def test_a_centre_line_said_with_its_colour_is_that_marking():
    assert "solid_single_white" in road("A van overtook me over the solid white centre line.").required_objects


@pytest.mark.parametrize("prompt", [
    "Autopilot (v11.4.9) did a weird thing: a semi in the left lane just ahead of me drifted into my lane.",
    "On software version 2.3 a semi in the left lane just ahead of me drifted into my lane.",
])
def test_a_software_version_is_no_vehicle(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("truck", "change_lane_to_right", "front_left")]


@pytest.mark.parametrize("prompt", [
    "A bus pulled in at a stop just ahead of me.",
    "A taxi pulled in to the kerb in front of me.",
    "Ahead of us a lorry pulled into a lay-by.",
])
def test_pulling_in_at_a_stopping_place_is_stopping_there(prompt):
    assert [a[1] for a in agents(prompt) if a[2] != "ego"] == ["stop"], agents(prompt)


@pytest.mark.parametrize("prompt", [
    "I turned right and a van was parked just round the corner.",
    "We turn left into Mill Lane; a bin lorry is stopped just around the corner.",
])
def test_just_round_the_corner_from_a_turn_is_the_destination(prompt):
    assert any(a[2] == "at_the_destination" and a[1] == "stop" for a in agents(prompt)), agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A box van squeezed over into the right lane ahead of me.", ("car", "change_lane_to_right", "front")),
    ("A coach is trying to muscle into the left lane just ahead of us.", ("bus", "change_lane_to_left", "front")),
])
def test_an_unknown_verb_of_motion_into_a_lane_beside_is_a_lane_change(prompt, expected):
    assert expected in agents(prompt)


def test_a_vehicle_in_a_lane_beside_is_still_placed_there():
    assert ("truck", "stop", "front_left") in agents("A truck parked in the left lane ahead of me.")


@pytest.mark.parametrize("prompt, expected", [
    ("A fire engine comes up behind us, so the ego ducks into the left lane.", ("car", "change_lane_to_left", "ego")),
    ("A bus pulls out ahead and the ego nips into the right lane.", ("car", "change_lane_to_right", "ego")),
    ("The ego tucks into the left lane behind a lorry.", ("car", "change_lane_to_left", "ego")),
])
def test_quick_short_moves_into_a_lane_change_lane(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A van in the left lane is boxing the ego in at the lights.", ("car", "block_the_ego", "left")),
    ("A lorry on my right boxed me in while I waited to merge.", ("truck", "block_the_ego", "right")),
])
def test_a_vehicle_boxing_the_ego_in_blocks_it(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, weather, expected", [
    ("A police car comes storming up from behind and overtakes the ego.", None, ("police", "go_straight", "back")),
    ("A lorry came storming down the outside lane past the ego.", None, None),
    ("It was storming and a truck came towards us.", ("hard_rain", "noon"), None),
    ("It was snowing in town and a truck came towards us.", ("snow", "noon"), None),
    ("The rain was pouring down the windscreen as the ego turned left.", ("hard_rain", "noon"), None),
])
def test_a_weather_verb_of_a_road_user_heading_somewhere_is_its_motion(prompt, weather, expected):
    scene = lower(prompt).scenario
    assert (scene.weather and (scene.weather.condition, scene.weather.time)) == (weather or None)
    assert expected is None or expected in agents(prompt)


def test_tonight_is_the_night():
    assert lower("Heavy rain tonight and a cyclist crosses in front of the ego.").scenario.weather.time == "night"


@pytest.mark.parametrize("prompt, ego", [
    ("I was at the junction, the light went green, and I turned left.", ("car", "turn_left", "ego")),
    ("The lights turned green and then the ego turns right while a van comes from the opposite direction.",
     ("car", "turn_right", "ego")),
])
def test_the_first_turn_of_an_ego_that_did_nothing_before_is_its_action(prompt, ego):
    found = agents(prompt)
    assert ego in found and sum(a[2] == "ego" for a in found) == 1, found


def test_a_turn_after_the_ego_waited_stays_in_its_later_stage():
    found = agents("The ego waits at the red light. When it turns green the ego turns left.")
    assert ("car", "stop", "ego") in found and ("car", "turn_left", "ego") in found


@pytest.mark.parametrize("prompt, expected", [
    ("Here comes a truck, cutting in from the left lane in front of the ego.",
     [("car", "go_straight", "ego"), ("truck", "change_lane_to_right", "front_left")]),
    ("And here comes the hatchback, cutting across from the left lane in front of the ego.",
     [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]),
    ("Oh and here comes a bus, pulling out from the stop in front of the ego.",
     [("bus", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]),
])
def test_here_comes_puts_its_subject_after_the_verb(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A jogger comes across the road from the right in front of the ego.",
     ("pedestrian", "cross_the_road", "front_right")),
    ("A kid on a bike came straight across the road in front of me.", ("cyclist", "cross_the_road", "front")),
])
def test_coming_across_the_road_is_crossing_it(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected, count", [
    ("A van broke down on the shoulder ahead, and the driver is out and walking across the road in front of the ego.",
     ("pedestrian", "cross_the_road", "front_right"), 3),
    ("The driver is out of his mind and overtakes the ego.", ("car", "go_straight", "back_left"), 2),
])
def test_a_driver_said_to_be_out_is_on_foot(prompt, expected, count):
    found = agents(prompt)
    assert expected in found and len(found) == count, found


@pytest.mark.parametrize("prompt, expected", [
    ("A lorry broke down in front of the ego.", ("truck", "stop", "front")),
    ("A pickup blew past us in the left lane.", ("car", "go_straight", "back_left")),
])
def test_irregular_past_tenses_of_driving_verbs(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("Ego is going straight and one two-wheeler which is in the right lane suddenly cuts in front of ego.",
     ("motorcycle", "change_lane_to_left", "right")),
    ("One aunty is standing on the footpath on left side.", ("pedestrian", "on_the_sidewalk", "left")),
    ("One police jeep is coming from behind with siren.", ("police", "go_straight", "back")),
])
def test_vehicle_and_people_words_of_indian_english(prompt, expected):
    assert expected in agents(prompt)


def test_kin_who_drives_is_no_pedestrian():
    assert agents("My uncle was driving and a bus stopped ahead.") == [("bus", "stop", "front"),
                                                                      ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected, crosswalk", [
    ("One cyclist is coming from the left side road and crossing.", ("cyclist", "cross_the_road", "road_of_left_turn"),
     False),
    ("A boy was running along the footpath and crossing in front of ego.", ("pedestrian", "cross_the_road", "front"),
     False),
    ("The ego is approaching a junction with a light and crossing.", ("car", "go_straight", "ego"), True),
])
def test_crossing_joined_to_a_verb_in_ing_is_a_verb(prompt, expected, crosswalk):
    assert expected in agents(prompt)
    assert ("crosswalk" in road(prompt).required_objects) == crosswalk


def test_coming_back_to_a_lane_changes_lane():
    found = agents("Ego shifts to the left lane. After the truck has passed, ego comes back to the right lane.")
    assert ("car", "change_lane_to_right", "ego") in found and ("car", "change_lane_to_left", "ego") in found


@pytest.mark.parametrize("prompt, limit", [
    ("A lorry sat on my bumper for 5 miles on the A1. i was doing 60 which is literally the limit.", "speed_97"),
    ("i was doing 80, which is the limit, and a car overtook me.", "speed_80"),
    ("i was doing 60 which is way over the limit and a truck passed me.", None),
])
def test_a_speed_said_to_be_the_limit_is_the_limit(prompt, limit):
    assert [o for o in road(prompt).required_objects if o.startswith("speed_")] == ([limit] if limit else [])


@pytest.mark.parametrize("prompt, expected", [
    ("HGV broken down on the hard shoulder of the M62, right ahead of me. moved out a lane like you're supposed to.",
     ("car", "change_lane_to_right", "ego")),
    ("A truck is stopped on the shoulder ahead on the right, so the ego moves over one lane.",
     ("car", "change_lane_to_left", "ego")),
])
def test_moving_out_a_lane_changes_lane_away_from_the_shoulder(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, later", [
    ("Ego is standing at the signal. When the signal becomes green, ego will go straight.", ("car", "go_straight", "ego")),
    ("Ego is waiting at red light. When light turns green, ego turns left.", ("car", "turn_left", "ego")),
    ("Ego is standing at the signal. When signal becomes green, ego will go straight.", ("car", "go_straight", "ego")),
])
def test_a_signal_that_becomes_green_starts_the_next_stage(prompt, later):
    found = agents(prompt)
    assert ("car", "stop", "ego") in found and later in found, found


@pytest.mark.parametrize("post, tags", [
    ("a taxi pulled out of a side road right in front of me and i had to stop.", " @MetPoliceUK #cabbies #schoolrun"),
    ("so grateful to the driver behind who waited while i went round a parked van", " #cycling @CyclingUK #BusLane"),
    ("an HGV sat on my bumper for miles on the motorway in thick fog", " #tailgating #M6 @PoliceAmbulanceFans"),
])
def test_a_posts_handles_and_closing_tags_are_no_road_users(post, tags):
    assert agents(post + tags) == agents(post)
    assert agents("@WestMidsPolice " + post) == agents(post)


def test_a_tag_inside_a_sentence_is_the_word_it_tags():
    assert ("motorcycle", "go_straight", "front") in agents("a #motorbike was weaving ahead of me #scary")


@pytest.mark.parametrize("prompt, count", [
    ("A cyclist ran the red in front of me and I braked hard. be safe out there ppl", 0),
    ("The van cut me off at the lights. slow down, folks!", 0),
    ("A bus stopped and two people crossed in front of it. come on people", 2),
    ("I was doing 30 and nearly hit people", 2),
])
def test_the_readers_a_post_speaks_to_are_nobody_in_the_scene(prompt, count):
    assert sum(a[0] == "pedestrian" for a in agents(prompt)) == count


@pytest.mark.parametrize("prompt, expected", [
    ("A lorry sat about 2m off my bumper for 5 miles in thick fog.", ("truck", "go_straight", "back")),
    ("A lorry sat right on my bumper for miles.", ("truck", "go_straight", "back")),
    ("A BMW stayed a foot off my back bumper all the way.", ("car", "go_straight", "back")),
])
def test_a_vehicle_sitting_on_the_egos_bumper_tailgates_it(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, count", [
    ("A lorry was broken down on the shoulder. half the cars behind me didnt bother.", 1),
    ("A lorry stopped. most of the cars behind me kept going.", 1),
    ("A lorry stopped. two of the cars behind me stopped.", 3),
])
def test_a_share_of_an_uncounted_group_is_no_agent(prompt, count):
    assert len(agents(prompt)) - 1 == count


@pytest.mark.parametrize("prompt, expected", [
    ("a white transit in the right lane blocked me.",
     [("car", "block_the_ego", "right"), ("car", "go_straight", "ego")]),
    ("a white Transit-type van was approaching from my left at the junction.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]),
    ("I take public transit but today I drove and a bus stopped ahead.",
     [("bus", "stop", "front"), ("car", "go_straight", "ego")]),
])
def test_a_transit_is_a_van(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "Ego goes straight on green at a crossroads.",
    "A car from the right runs its red light while the ego crosses the junction.",
    "The van jumped his light and the ego braked at the junction.",
])
def test_a_light_gone_through_or_a_colour_driven_on_is_a_signal(prompt):
    assert "traffic_light" in road(prompt).required_signals


def test_a_vehicles_own_lights_are_no_signal():
    assert "traffic_light" not in road("The bus stopped with its red lights flashing.").required_signals


@pytest.mark.parametrize("prompt", [
    "Broken-down HGV on the hard shoulder ahead on the right. Driver has got out and is walking across in front of us.",
    "Van stopped ahead on the right. Driver gets out and walks across in front of us.",
])
def test_a_bare_driver_after_a_bare_vehicle_in_notes_is_its_driver_on_foot(prompt):
    found = agents(prompt)
    assert ("pedestrian", "cross_the_road", "front_right") in found and ("car", "go_straight", "ego") in found, found


def test_a_bare_driver_of_the_ride_described_is_still_the_ego():
    found = agents("4 stars. Car was clean, driver was friendly. A bus pulled out ahead of us.")
    assert [t for t, _, _ in found] == ["bus", "car"], found


@pytest.mark.parametrize("prompt, limit", [
    ("25 mph residential street. Kid chases a ball out from between parked cars.", "speed_40"),
    ("On a 50 km/h urban road the ego follows a bus.", "speed_50"),
    ("The ego drives on a 70 mph two-lane road.", "speed_113"),
])
def test_a_speed_that_qualifies_a_road_is_its_limit_and_nobodys_speed(prompt, limit):
    scene = lower(prompt).scenario
    assert limit in scene.road.required_objects and all(a.speed is None for a in scene.agents()), scene


@pytest.mark.parametrize("prompt, start", [
    ("A stalled pickup on the hard shoulder up ahead on the right, and the driver is out and walking across the road "
     "in front of the ego!", "front_right"),
    ("A van is parked on the left ahead. The driver gets out and walks across in front of us.", "front_left"),
    ("A lorry stopped ahead of us in our lane. The driver got out and walked across the road.", "front"),
])
def test_a_driver_on_foot_starts_at_the_side_of_the_vehicle_left(prompt, start):
    assert ("pedestrian", "cross_the_road", start) in agents(prompt), agents(prompt)


@pytest.mark.parametrize("prompt, other", [
    ("The participant's vehicle follows a confederate vehicle on a two-lane road; the confederate vehicle brakes "
     "hard.", ("car", "stop", "front")),
    ("The participant turns left while a confederate pedestrian crosses the road ahead.",
     ("pedestrian", "cross_the_road", "front")),
])
def test_a_studys_participant_drives_the_ego_and_its_confederates_are_the_others(prompt, other):
    found = agents(prompt)
    assert other in found and len(found) == 2 and [p for _, _, p in found].count("ego") == 1, found


@pytest.mark.parametrize("prompt, ego", [
    ("A woman crosses the road in front of the ego, which stops to let her pass.", ("car", "stop", "ego")),
    ("A jogger runs out ahead of the ego vehicle, which brakes hard and stops.", ("car", "stop", "ego")),
    ("A truck pulls out in front of the AV, which slows down and stops.", ("car", "stop", "ego")),
    ("A car stops right ahead of me, which makes me brake.", ("car", "go_straight", "ego")),
])
def test_a_relative_set_off_by_a_comma_after_the_ego_is_about_the_ego(prompt, ego):
    assert ego in agents(prompt), agents(prompt)


def test_a_restrictive_or_plural_relative_after_the_ego_is_about_the_noun_before_it():
    for prompt in ("Three cars ahead of the player, which each swerve across in front of it.",
                   "Three cars ahead of the player that each swerve across in front of it."):
        found = agents(prompt)
        assert ("car", "go_straight", "ego") in found and found.count(("car", "change_lane_to_right", "front_left")) \
            == 3, found


@pytest.mark.parametrize("prompt, placed", [
    ("At the crossroads one car was waiting at the lights, on my left, and a van drove straight through.",
     ("car", "stop", "road_of_left_turn")),
    ("A lorry sat at the kerb, on our right, and a man walked out from behind it.", ("truck", "stop", "right")),
    ("A bus was waiting at the stop, in the right lane, but a cyclist went past.", ("bus", "stop", "right")),
])
def test_a_place_set_off_after_a_clause_places_that_clauses_subject(prompt, placed):
    assert placed in agents(prompt), agents(prompt)


@pytest.mark.parametrize("prompt, members", [
    ("The ego waits to turn left while two oncoming vehicles (a bus and a van) pass through.",
     [("bus", "go_straight", "road_of_straight"), ("car", "go_straight", "road_of_straight")]),
    ("At the junction two vehicles from the right, a lorry and a taxi, go straight across.",
     [("car", "go_straight", "road_of_right_turn"), ("truck", "go_straight", "road_of_right_turn")]),
])
def test_the_members_named_of_a_counted_group_are_what_the_group_was_said_to_be(prompt, members):
    found = agents(prompt)
    assert [a for a in found if a[2] != "ego"] == members, found


@pytest.mark.parametrize("prompt, plain", [
    ("A pedestrian, a child, crosses from the left.", "A pedestrian crosses from the left."),
    ("A car, a taxi, pulls out from the right in front of us.", "A car pulls out from the right in front of us."),
    ("A second cyclist, a courier, rides past on the left.", "A cyclist rides past on the left."),
    ("A pedestrian (an elderly man with a stick) crosses in front of the ego.",
     "A pedestrian crosses in front of the ego."),
    ("A cyclist, a courier in a yellow jacket, rides past on the left.", "A cyclist rides past on the left."),
])
def test_a_noun_of_the_same_kind_between_commas_before_the_verb_is_no_second_agent(prompt, plain):
    found = agents(prompt)
    assert found == agents(plain) and len(found) == 2, found


@pytest.mark.parametrize("prompt, plain", [
    ("Three pedestrians (two adults and a child) cross in front of the ego.",
     "Three pedestrians cross in front of the ego."),
    ("Two cars come from the left, a taxi and a van.", "Two cars come from the left."),
    ("The ego is followed by two cars (a taxi and a van).", "The ego is followed by two cars."),
    ("Two pedestrians wait at the kerb, a child and a woman.", "Two pedestrians wait at the kerb."),
])
def test_the_members_listed_after_a_counted_group_are_no_new_agents(prompt, plain):
    assert agents(prompt) == agents(plain), agents(prompt)


def test_a_list_that_does_not_close_after_a_counted_group_is_more_agents():
    assert len(agents("A car, a taxi with its light on, a van and a bus wait.")) == 5
    assert len(agents("Two cars, a taxi and a van wait at the lights.")) == 5
    assert len(agents("Two cars are parked on the left. A taxi and a van pull out.")) == 5


@pytest.mark.parametrize("prompt, plain", [
    ("My car, which is a hatchback, waits at the lights while a bus turns left.",
     "My car waits at the lights while a bus turns left."),
    ("The ego, which is a city bus, waits at the stop.", "The ego bus waits at the stop."),
    ("A vehicle, which was a white van, pulled out from the left.", "A white van pulled out from the left."),
    ("A motorbike, which I think was a Honda, overtook me on the right.", "A motorbike overtook me on the right."),
    ("A car, which I think was a taxi, stopped ahead of me.", "A car stopped ahead of me."),
])
def test_the_noun_after_the_copula_of_a_relative_is_what_its_noun_is(prompt, plain):
    assert agents(prompt) == agents(plain), agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("A police car was behind me. The officers pulled me over.", ["car", "police"]),
    ("A patrol car sat behind me for a mile. Officers then flagged me down.", ["car", "police"]),
    ("A bin lorry stopped ahead. The bin men walked behind it.", ["car", "truck"]),
    ("A garbage truck was stopped in my lane. The garbage men were running between the bins.", ["car", "truck"]),
    ("A motorbike passed me on the right. The biker then cut in front of me.", ["car", "motorcycle"]),
    ("An ambulance came up behind me. The paramedic waved at me.", ["ambulance", "car"]),
])
def test_the_people_of_a_vehicle_named_after_it_are_no_agents_of_their_own(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


@pytest.mark.parametrize("prompt, walkers", [
    ("A police car stopped ahead of me. Two officers got out and crossed the road.", 2),
    ("A police car stopped ahead of me. The officers got out and crossed the road.", 2),
    ("A bin lorry stopped ahead. Two bin men crossed in front of it.", 2),
])
def test_a_vehicles_people_counted_or_out_of_it_are_on_foot(prompt, walkers):
    assert [t for t, _, _ in agents(prompt)].count("pedestrian") == walkers, agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("A motorbike was ahead of me. The bike then swerved left.", ["car", "motorcycle"]),
    ("A pickup was ahead of me. The truck braked suddenly.", ["car", "car"]),
    ("A white van was ahead of me. The truck braked suddenly.", ["car", "car"]),
    ("An e-scooter rider came up on my right. The scooter then cut across me.", ["car", "cyclist"]),
])
def test_a_loose_name_of_another_type_names_the_one_vehicle_it_fits(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("A pickup was ahead of me. The truck behind me honked.", ["car", "car", "truck"]),
    ("A motorbike was ahead of me. A cyclist was on my left. The bike then swerved left.",
     ["car", "cyclist", "motorcycle"]),
    ("A bus was stopped ahead on our right. The vehicle braked to a stop.", ["bus", "car"]),
])
def test_a_loose_name_placed_elsewhere_or_of_its_own_type_is_not_the_other(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("Police pursuit at the crossroads. A motorbike came through from the left with a police car behind it.",
     ["car", "motorcycle", "police"]),
    ("There was a police checkpoint ahead. A van stopped in front of me.", ["car", "car"]),
    ("Near the taxi rank, a pedestrian stepped out in front of me.", ["car", "pedestrian"]),
    ("The truck traffic was heavy. A car cut in front of me.", ["car", "car"]),
    ("I waited by the bus shelter. A cyclist turned left in front of me.", ["car", "cyclist"]),
])
def test_a_vehicle_noun_that_only_describes_the_noun_after_it_is_no_agent(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("A school bus was stopped ahead picking kids up.", ["bus", "car"]),
    ("A bus was unloading schoolchildren on the right.", ["bus", "car"]),
    ("A minibus dropped off pupils at the school gate.", ["bus", "car"]),
    ("A taxi stopped ahead to pick up a passenger. A cyclist passed on my right.", ["car", "car", "cyclist"]),
    ("A bus was at the stop letting people off. A man then crossed in front of me.", ["bus", "car", "pedestrian"]),
    ("A woman carrying a child crossed in front of me.", ["car", "pedestrian"]),
])
def test_people_a_vehicle_takes_on_or_sets_down_are_its_passengers(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


@pytest.mark.parametrize("prompt, walkers", [
    ("The bus let two kids off and they ran across in front of me.", 2),
    ("A minibus dropped off three pupils at the school gate.", 3),
])
def test_people_set_down_who_then_cross_or_are_counted_are_on_foot(prompt, walkers):
    assert [t for t, _, _ in agents(prompt)].count("pedestrian") == walkers, agents(prompt)


@pytest.mark.parametrize("prompt, walkers", [
    ("A van stopped ahead of me. Some people behind us were mad.", 0),
    ("A cyclist turned left in front of me and people were furious.", 0),
    ("Some people were crossing the road ahead.", 2),
    ("Some people stood at the kerb.", 2),
])
def test_uncounted_people_who_do_nothing_on_foot_are_no_pedestrians(prompt, walkers):
    assert [t for t, _, _ in agents(prompt)].count("pedestrian") == walkers, agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("Jaywalker at night. Ped_1 crosses in front of the Ego from the right.", ["car", "pedestrian"]),
    ("Stalled car. Car_1 is stopped in the ego lane ahead.", ["car", "car"]),
    ("Truck ahead. Truck_2 is behind the ego.", ["car", "truck", "truck"]),
])
def test_a_heading_names_the_agent_its_description_names_by_label(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("Night variant of the lead-vehicle-following scenario. The ego follows a bus in the same lane.", ["bus", "car"]),
    ("The ego follows a lead vehicle. Car-following scenario at night.", ["car", "car"]),
    ("A cyclist-overtaking scenario: the ego passes a cyclist riding ahead in the same lane.", ["car", "cyclist"]),
    ("A cyclist scenario at dusk.", ["car", "cyclist"]),
])
def test_a_noun_in_the_name_of_the_case_is_the_agent_named_elsewhere(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("a school bus was stopped right in front of me and i barely stopped in time coach better appreciate me",
     ["bus", "car"]),
    ("Tesla said the car was on Autopilot when a truck pulled out from the right.", ["car", "truck"]),
    ("Taxi driver said he didn't see me when he pulled out from the left.", ["car", "car"]),
])
def test_a_bare_vehicle_word_that_speaks_is_a_person_or_a_firm(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("A second pedestrian, a child dummy, crosses from the left in front of the ego.", ["car", "pedestrian"]),
    ("A car, a red Ford, cut in front of me.", ["car", "car"]),
    ("A motorbike, a big Harley, overtook me on the right.", ["car", "motorcycle"]),
    ("A car, a van, and a taxi were waiting at the light.", ["car", "car", "car", "car"]),
    ("A car, a van, a taxi and a bus waited at the light.", ["bus", "car", "car", "car", "car"]),
])
def test_a_noun_set_between_commas_after_one_of_its_type_says_what_that_one_is(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("Three cars drive ahead of the ego. Car_1 brakes hard.", ["car", "car", "car", "car"]),
    ("Two vehicles wait at the junction. Car_A turns left and Truck_B goes straight.", ["car", "car", "truck"]),
])
def test_a_label_first_said_of_a_counted_group_names_one_of_it(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


# -- standing and moving ----------------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("A man walks across in front of the ego, who comes to a stop to let him over.",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("A cyclist rides out in front of the ego, who brakes to a halt.",
     [("car", "stop", "ego"), ("cyclist", "cross_the_road", "front")]),
])
def test_a_relative_clause_set_off_by_a_comma_after_the_ego_is_the_egos(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A group of pedestrians was standing at the crosswalk waiting to cross.",
     [("car", "go_straight", "ego"), ("pedestrian", "stop", "near_the_crosswalk"),
      ("pedestrian", "stop", "near_the_crosswalk")]),
    ("A man stands at the crossing waiting to cross.",
     [("car", "go_straight", "ego"), ("pedestrian", "stop", "near_the_crosswalk")]),
    ("A woman is waiting to cross at the zebra.",
     [("car", "go_straight", "ego"), ("pedestrian", "stop", "near_the_crosswalk")]),
    ("A car waits at the junction on the left to turn right.",
     [("car", "go_straight", "ego"), ("car", "stop", "road_of_left_turn")]),
    ("An old man on the left is waiting to cross the road.",
     [("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "front_left")]),
])
def test_what_a_waiting_agent_means_to_do_is_not_done_yet(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A motorcyclist was closing fast from behind and had to brake.",
     [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "back")]),
    ("A van came up behind me and had to wait.", [("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
    ("A cyclist riding beside me had to slam on his brakes.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "right")]),
    ("The car behind me had to stop.", [("car", "go_straight", "ego"), ("car", "stop", "back")]),
])
def test_a_stop_forced_on_an_agent_does_not_outrank_what_it_was_doing(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("I was waiting at the red light with a cyclist stopped in front of me. When it turned green we both set off.",
     [("car", "go_straight", "ego"), ("car", "stop", "ego"), ("cyclist", "stop", "front")]),
    ("I sat at the lights with a motorbike waiting in front of me. Once they changed, we both moved off.",
     [("car", "go_straight", "ego"), ("car", "stop", "ego"), ("motorcycle", "stop", "front")]),
])
def test_one_standing_in_the_stage_it_is_named_in_stands_there_though_it_moves_off_later(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Three cars including ours were cruising down the motorway in one lane, we were in the middle.",
     [("car", "go_straight", "back"), ("car", "go_straight", "ego"), ("car", "go_straight", "front")]),
    ("Five cars including ours sat at the red light, and we were the third one.",
     [("car", "stop", "back"), ("car", "stop", "back"), ("car", "stop", "ego"), ("car", "stop", "front"),
      ("car", "stop", "front")]),
])
def test_a_place_in_a_moving_column_is_no_place_in_a_queue(prompt, expected):
    assert agents(prompt) == expected


def test_both_of_us_are_the_ego_and_the_other_one():
    assert agents("A cyclist was ahead of me at the lights. Both of us turned right.") == [
        ("car", "turn_right", "ego"), ("cyclist", "turn_right", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("A taxi ahead had stopped but then moved off.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("The lorry in front waited for a moment but then drove on.",
     [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
])
def test_but_then_goes_on_with_the_same_subject(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Act 1: the Ego waits at the stop line. Act 2: the Ego turns left after a truck from the right has gone past.",
     [("car", "stop", "ego"), ("car", "turn_left", "ego"), ("truck", "go_straight", "road_of_right_turn")]),
    ("Act 1: Ego holds at the red light behind a bus. Act 2, on green: Ego drives straight on.",
     [("bus", "stop", "front"), ("car", "go_straight", "ego"), ("car", "stop", "ego")]),
])
def test_a_storyboards_later_act_is_a_later_stage(prompt, expected):
    assert agents(prompt) == expected


def test_holding_at_a_stopping_place_is_standing_and_holding_a_speed_is_not():
    assert agents("The ego holds at the stop line while a cyclist crosses from the left.")[0] == ("car", "stop", "ego")
    assert agents("The lead car holds at 50 km/h.") == [("car", "go_straight", "ego"), ("car", "go_straight", "front")]


# -- a safety driver's debrief, a study's staging ------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("We were on the ring road behind a bus. The vehicle eased off to about 40 and held back.",
     [("bus", "go_straight", "front"), ("car", "go_straight", "ego")]),
    ("A lorry was double-parked in our lane and the vehicle just waited behind it, so I took over.",
     [("car", "stop", "ego"), ("truck", "stop", "front")]),
    ("Our second lap. A cyclist came up on our left and the vehicle slowed right down.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "left")]),
])
def test_a_crews_vehicle_is_the_ego(prompt, expected):
    assert agents(prompt) == expected


def test_the_vehicle_of_a_crew_stays_another_when_the_crew_names_other_vehicles_as_vehicles():
    found = agents("We were parked when a vehicle came past us; the vehicle turned left at the corner.")
    assert ("car", "turn_left", "road_of_left_turn") in found or any(
        t == "car" and p != "ego" and a == "turn_left" for t, a, p in found), found


@pytest.mark.parametrize("prompt", [
    "A single confederate van is presented as oncoming traffic on the rural road.",
    "On a straight road a truck appears as opposing traffic.",
])
def test_a_vehicle_cast_as_oncoming_traffic_is_oncoming(prompt):
    assert [p for _, _, p in agents(prompt) if p != "ego"] == ["front_left"], agents(prompt)


@pytest.mark.parametrize("prompt", [
    "We held at the junction for an oncoming van. Once he'd cleared we completed the turn.",
    "We waited for an oncoming lorry at the lights. Once it had vanished we made the left turn.",
])
def test_a_past_condition_without_a_comma_ends_where_we_act(prompt):
    stages = lower(prompt).scenario.stages
    assert len(stages) == 2 and [a.action for a in stages[1].agents] == ["turn_left"], stages
    assert [a.action for a in stages[0].agents if not a.is_ego] == ["go_straight"], stages


@pytest.mark.parametrize("text, expected", [
    ("once he'd cleared", "had"), ("we'd already stopped", "had"), ("i'd need a gap", "would"),
    ("he'd stop there", "would"),
])
def test_d_after_a_pronoun_is_had_before_a_participle(text, expected):
    assert expected in [t.word for t in tokenize(text)]


@pytest.mark.parametrize("prompt, mover", [
    ("We were following two vans when a pickup from the lane to our right squeezed in between us and them.",
     ("car", "change_lane_to_left", "right")),
    ("I was behind a bus when a taxi from the lane to my left nipped in between me and the bus.",
     ("car", "change_lane_to_right", "left")),
])
def test_a_cut_in_between_the_ego_and_its_leaders_starts_beside_not_behind(prompt, mover):
    assert mover in agents(prompt), agents(prompt)


@pytest.mark.parametrize("prompt, people", [
    ("A school bus was stopped ahead on our right picking kids up; a cyclist passed us.", 0),
    ("A coach stood at the kerb on the left letting passengers off, and we waited behind a van.", 0),
    ("A bus picks up two children at the stop and they cross in front of the ego.", 2),
])
def test_the_people_a_vehicle_picks_up_or_sets_down_are_its_passengers(prompt, people):
    found = agents(prompt)
    assert sum(t == "pedestrian" for t, _, _ in found) == people and any(t == "bus" for t, _, _ in found), found


@pytest.mark.parametrize("prompt", ["The bus stopped to pick up two women.", "A bus will pick up the kids ahead."])
def test_pick_up_with_its_object_after_it_is_the_verb_and_no_pickup_truck(prompt):
    assert [t for t, _, _ in agents(prompt)].count("car") == 1, agents(prompt)  # the ego only


@pytest.mark.parametrize("prompt, required, without", [
    ("The ego waits at a crossroads without signals, stop or yield control.", (),
     ("traffic_light", "stop", "yield")),
    ("The ego waits at a junction with no signal, stop or give way control, then turns left.", (),
     ("traffic_light", "stop", "yield")),
    ("A T-junction under give-way control; the ego turns right onto the main road.", ("yield",), ()),
    ("Side road stop-controlled, main road uncontrolled. The ego turns left out of the side road.", ("stop",), ()),
    ("An uncontrolled junction; a van comes from the left.", (), ("traffic_light", "stop", "yield")),
])
def test_a_junctions_controls_as_a_traffic_engineer_lists_them(prompt, required, without):
    spec = road(prompt)
    assert set(spec.required_signals) == set(required) and set(spec.without_signals) == set(without), spec


@pytest.mark.parametrize("prompt, expected", [
    ("The ego waits to turn left while two oncoming vehicles (a lorry, followed by a taxi) pass through the junction.",
     [("car", "go_straight", "road_of_straight"), ("car", "turn_left", "ego"),
      ("truck", "go_straight", "road_of_straight")]),
    ("On a straight rural road the ego meets two oncoming vehicles (a van and a motorbike).",
     [("car", "go_straight", "ego"), ("car", "go_straight", "front_left"),
      ("motorcycle", "go_straight", "front_left")]),
])
def test_a_counted_groups_members_named_in_brackets_share_its_words(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Participants follow a van on a two-lane road; the van brakes hard.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("Study participants encounter a cyclist riding ahead of them in the same lane.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]),
])
def test_a_studys_participants_in_the_plural_drive_the_ego(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A pedestrian, an elderly man, crosses from the left in front of the ego.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left")]),
    ("A second pedestrian, a child dummy, steps out from the right in front of the ego.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right")]),
    ("A truck, a big fuel tanker, pulls out from the right lane in front of us.",
     [("car", "go_straight", "ego"), ("truck", "change_lane_to_left", "front_right")]),
])
def test_a_general_noun_then_one_of_its_kind_set_off_by_commas_is_one_agent(prompt, expected):
    assert agents(prompt) == expected


def test_a_list_of_one_kind_is_still_a_list():
    assert [t for t, _, p in agents("A car, a van, and a taxi wait ahead of the ego.") if p != "ego"] == ["car"] * 3


def test_a_testers_abbreviations_read_as_words():
    scene = lower("2 cars incl. ego wait at a red TL, ego second in line. When the TL turns green ego turns right.")
    assert "traffic_light" in scene.scenario.road.required_signals
    stages = scene.scenario.stages
    assert len(stages) == 2 and [a.action for a in stages[1].agents] == ["turn_right"], stages
    assert sorted((a.type, a.action) for a in stages[0].agents) == [("car", "stop"), ("car", "stop")], stages


@pytest.mark.parametrize("prompt", [
    "The ego waits at a red light. When the traffic light turns green, the ego goes straight.",
    "We sat at the red. Once the traffic signal changed to green we went straight on.",
])
def test_a_signal_named_in_full_starts_a_stage_as_the_light_does(prompt):
    stages = lower(prompt).scenario.stages
    assert [[a.action for a in s.agents] for s in stages] == [["stop"], ["go_straight"]], stages


@pytest.mark.parametrize("prompt, expected", [
    ("Can we show the car turning right at a junction while a cyclist waits on the corner?",
     [("car", "turn_right", "ego"), ("cyclist", "stop", "at_the_destination")]),
    ("Could we have our car stopping for a kid who runs out?",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "front")]),
])
def test_the_team_that_asks_can_we_show_is_not_the_ego(prompt, expected):
    found = agents(prompt)
    assert [a for a in found if a[2] == "ego"] == [e for e in expected if e[2] == "ego"], found


@pytest.mark.parametrize("prompt", [
    "The ego turns left at the junction. Two vans come the other way, so it has to wait.",
    "The ego car turns left; maybe a couple of buses coming the other way so it has to hold for a gap.",
])
def test_it_after_a_counted_group_is_not_the_group(prompt):
    found = agents(prompt)
    assert all(a != "stop" for t, a, p in found if p != "ego"), found


@pytest.mark.parametrize("prompt, noun", [
    ("A lorry that I had been following for miles turned left.", ("truck", "turn_left", "front")),
    ("A lorry that I had been following for miles then turned left.", ("truck", "turn_left", "front")),
    ("A taxi that we were stuck behind suddenly swerved to the left.", ("car", "change_lane_to_left", "front")),
    ("A van that I had passed earlier then overtook me.", ("car", "go_straight", "back_left")),
    ("A truck that the ego is following brakes suddenly.", ("truck", "stop", "front")),
])
def test_the_verb_after_a_relative_with_its_own_subject_is_its_nouns(prompt, noun):
    found = agents(prompt)
    assert noun in found and len(found) == 2, found


@pytest.mark.parametrize("prompt, plain", [
    ("A cyclist, defined here as anyone riding a bicycle or a scooter, rides past the ego on the left.",
     "A cyclist rides past the ego on the left."),
    ("We test an overtake, that is, a manoeuvre in which a car passes a slower truck, with a van behind the ego.",
     "We test an overtake with a van behind the ego."),
    ("The ego meets a blockage, which we define as a parked bus or lorry standing in the lane. A lorry is parked "
     "ahead of the ego.", "A lorry is parked ahead of the ego."),
])
def test_a_definition_speaks_of_a_kind_and_names_nobody_in_the_scene(prompt, plain):
    assert agents(prompt) == agents(plain), agents(prompt)


@pytest.mark.parametrize("prompt, plain", [
    ("A car, like the one that hit my neighbour's van last week, ran the red light from the left.",
     "A car ran the red light from the left."),
    ("A van pulled out in front of me, which reminded me of a crash I saw last year involving a bus.",
     "A van pulled out in front of me."),
    ("A taxi, similar to the one that clipped a cyclist outside my house, cut in from the right.",
     "A taxi cut in from the right."),
])
def test_what_the_scene_is_compared_with_names_nobody_in_it(prompt, plain):
    assert agents(prompt) == agents(plain), agents(prompt)


def test_the_one_after_a_noun_is_that_noun_and_not_the_subject_before_it():
    found = agents("The ego follows a bus, the one that was stopped at the kerb.")
    assert ("car", "go_straight", "ego") in found and ("bus", "stop", "front") in found, found


@pytest.mark.parametrize("prompt, noun", [
    ("A bus - the one that was stopped at the kerb - moves off.", ("bus", "go_straight", "front")),
    ("A taxi, which had stopped ahead of us, drives off.", ("car", "go_straight", "front")),
])
def test_a_relative_before_its_nouns_own_verb_says_what_it_was_not_what_it_does(prompt, noun):
    assert noun in agents(prompt), agents(prompt)


def test_a_participle_right_after_a_noun_inside_a_relative_stays_the_nouns():
    found = agents("Make a scene in which the ego waits at the lights with a lorry stopped beside it in the left lane.")
    assert ("truck", "stop", "left") in found and ("car", "stop", "ego") in found, found


@pytest.mark.parametrize("prompt, expected", [
    ("At the lights one truck is waiting on my left, one on my right and one behind me.",
     [("car", "go_straight", "ego"), ("truck", "stop", "back"), ("truck", "stop", "left"),
      ("truck", "stop", "right")]),
    ("One motorbike rides ahead of us, one in the left lane and one behind us.",
     [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "back"), ("motorcycle", "go_straight", "front"),
      ("motorcycle", "go_straight", "left")]),
    ("One cyclist waits on the left and one on the right of the ego.",
     [("car", "go_straight", "ego"), ("cyclist", "stop", "left"), ("cyclist", "stop", "right")]),
    ("The ego is boxed in by one car in front, one on the left and one on the right.",
     [("car", "block_the_ego", "front"), ("car", "block_the_ego", "left"), ("car", "block_the_ego", "right"),
      ("car", "go_straight", "ego")]),
])
def test_a_list_of_one_items_names_one_more_agent_each(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("The ego gets hemmed in on the motorway: one truck ahead, one on the left and one on the right.",
     [("car", "go_straight", "ego"), ("truck", "block_the_ego", "front"), ("truck", "block_the_ego", "left"),
      ("truck", "block_the_ego", "right")]),
    ("My car got boxed in on the high street, one bus ahead of me and one van on my right.",
     [("bus", "block_the_ego", "front"), ("car", "block_the_ego", "right"), ("car", "go_straight", "ego")]),
    ("The ego gets boxed in on a two-lane road: a bus in front and a van on its left.",
     [("bus", "block_the_ego", "front"), ("car", "block_the_ego", "left"), ("car", "go_straight", "ego")]),
])
def test_the_vehicles_named_around_an_ego_boxed_in_by_nobody_box_it_in(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "The ego gets blocked in the left lane, a car overtakes it on the right.",
    "The ego was cut off. Two cars overtook it on the right.",
    "The ego is blocked. A car passes on the left.",
])
def test_a_vehicle_passing_an_ego_boxed_in_does_not_box_it_in(prompt):
    assert all(action != "block_the_ego" for _, action, _ in agents(prompt)), agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("We were the second of three cars driving along the high street.",
     [("car", "go_straight", "back"), ("car", "go_straight", "ego"), ("car", "go_straight", "front")]),
    ("I was the third of four cars in the queue at the red light.",
     [("car", "stop", "back"), ("car", "stop", "ego"), ("car", "stop", "front"), ("car", "stop", "front")]),
    ("I was the last of three cars waiting at the stop sign.",
     [("car", "stop", "ego"), ("car", "stop", "front"), ("car", "stop", "front")]),
])
def test_the_ego_placed_as_the_nth_of_a_counted_group_is_one_of_it(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Two vans are parked behind us and one on the right.",
     [("car", "go_straight", "ego"), ("car", "stop", "back"), ("car", "stop", "back"), ("car", "stop", "right")]),
    ("three buses in front of me and one in the left lane, motorway, morning",
     [("bus", "go_straight", "front"), ("bus", "go_straight", "front"), ("bus", "go_straight", "front"),
      ("bus", "go_straight", "left"), ("car", "go_straight", "ego")]),
])
def test_one_placed_apart_from_a_group_placed_together_is_one_more(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Two cars are parked ahead, one on the left and one on the right.",
     [("car", "go_straight", "ego"), ("car", "stop", "front_left"), ("car", "stop", "front_right")]),
    ("Two cyclists ride ahead of the ego, one on the left and one on the right.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front_left"),
      ("cyclist", "go_straight", "front_right")]),
])
def test_a_group_shared_out_by_one_items_is_not_added_to(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Two cars ahead of the ego, one in the left lane and one in the right lane.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "front_left"), ("car", "go_straight", "front_right")]),
    ("Two trucks behind us, one on the left, one on the right.",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "back_left"), ("truck", "go_straight", "back_right")]),
    ("We got boxed in by two vans, one on our left and one in front of us.",
     [("car", "block_the_ego", "front"), ("car", "block_the_ego", "left"), ("car", "go_straight", "ego")]),
])
def test_each_member_of_a_group_placed_ahead_or_behind_is_there_in_its_own_lane(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("The lead car brakes, SpeedAction target 0, and the ego follows it.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("Ego drives at a target speed of 50 km/h behind a bus.", [("bus", "go_straight", "front"),
                                                               ("car", "go_straight", "ego")]),
])
def test_an_actions_target_value_is_no_target_vehicle(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Two trucks come the other way, so it has to wait.",
     [("car", "stop", "ego"), ("truck", "go_straight", "front_left"), ("truck", "go_straight", "front_left")]),
    ("The ego is at a junction. A couple of vans are coming the other way, so it has to wait for a gap.",
     [("car", "go_straight", "road_of_straight"), ("car", "go_straight", "road_of_straight"),
      ("car", "stop", "ego")]),
])
def test_it_after_a_counted_group_alone_is_the_ego(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Three cars, including a taxi, wait at the red light ahead of the ego.",
     [("car", "go_straight", "ego"), ("car", "stop", "front"), ("car", "stop", "front"), ("car", "stop", "front")]),
    ("Two trucks including a tanker drive ahead of the ego.",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "front"), ("truck", "go_straight", "front")]),
    ("Four pedestrians, including a child, cross in front of the ego.",
     [("car", "go_straight", "ego")] + [("pedestrian", "cross_the_road", "front")] * 4),
])
def test_one_named_as_included_in_a_counted_group_is_one_of_it(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, start", [
    ("Two vans were parked on my right, one behind the other. A girl ran out from between them into the road in "
     "front of me.", "front_right"),
    ("There were two cars parked on my left-hand side, one behind the other. A young boy ran out from between them "
     "into the road right in front of me.", "front_left"),
    ("Two cars shall be parked on the right, one behind the other. A child shall emerge from between the parked "
     "cars and cross in front of the ego.", "front_right"),
])
def test_a_crosser_from_between_a_group_named_before_comes_from_its_side(prompt, start):
    assert ("pedestrian", "cross_the_road", start) in agents(prompt), agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("A pedestrian, defined here as any road user travelling on foot, crosses the road from the right in front of "
     "the ego.", ["car", "pedestrian"]),
    ("The scenario is a blocking event, which we define as another road user occupying the path of the ego. A van "
     "parked on the shoulder ahead pulls out and blocks the ego.", ["car", "car"]),
    ("We consider a cut-in, that is, a situation in which a vehicle from an adjacent lane enters the ego lane. "
     "Specifically, a black sedan in the left lane changes lanes to the right in front of the ego.", ["car", "car"]),
    ("A car that is parked on the right pulls out in front of me.", ["car", "car"]),
])
def test_the_nouns_of_a_definition_are_nobody_in_the_scene(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("This scenario examines the response of the ego to an approaching emergency vehicle. A police car approaches "
     "at high speed from behind in the left lane.", ["car", "police"]),
    ("I want the emergency vehicle moment: a fire truck comes up behind us with the sirens going.",
     ["car", "firetruck"]),
    ("An emergency vehicle approaches from behind. A cyclist rides on my right.", ["ambulance", "car", "cyclist"]),
])
def test_a_kind_named_before_one_agent_of_it_is_that_agent(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A van pulled out. The courier then stopped in front of me.", ("car", "go_straight", "ego")),
    ("A tractor was ahead. The farmer then turned left.", ("truck", "turn_left", "front")),
])
def test_a_subject_named_by_a_noun_not_known_is_the_agent_named_before_not_the_ego(prompt, expected):
    found = agents(prompt)
    assert expected in found and len(found) == 2, found


@pytest.mark.parametrize("prompt, expected", [
    ("A learner was ahead of me. The L-plater stalled at the lights.", [("car", "go_straight", "ego"),
                                                                        ("car", "stop", "front")]),
    ("A Beemer cut in front of me.", [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]),
])
def test_nicknames_of_a_car_name_a_car(prompt, expected):
    assert agents(prompt) == expected


def test_a_noun_not_known_after_a_copula_is_no_subject():
    found = agents("Our car is sitting at a signalised intersection and it wants to turn left. And there's an oncoming "
                   "pickup coming straight through. That's the whole unprotected-left problem in one sentence.")
    assert ("car", "go_straight", "road_of_straight") in found, found


@pytest.mark.parametrize("prompt, kinds", [
    ("Pickup ahead of me. Truck braked suddenly.", ["car", "car"]),
    ("Motorbike ahead of me. Bike swerved left.", ["car", "motorcycle"]),
    ("Car ahead of me. Truck behind me honked.", ["car", "car", "truck"]),
])
def test_a_bare_loose_name_in_notes_names_the_vehicle_it_fits(prompt, kinds):
    assert sorted(t for t, _, _ in agents(prompt)) == kinds, agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("The ego is pulling away from the kerb when a cyclist comes up behind.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "back")]),
    ("Our bus pulls away from the bus stop as a car overtakes it on the left.",
     [("bus", "go_straight", "ego"), ("car", "go_straight", "back_left")]),
    ("The ego pulls away from the kerb into the right lane.", [("car", "change_lane_to_right", "ego")]),
])
def test_the_ego_pulling_away_from_where_it_stood_moves_off(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A lorry was parked in our lane and we just sat behind it and would not go round.",
     [("car", "stop", "ego"), ("truck", "stop", "front")]),
    ("The AV sat behind the stopped bus and would not pass it.", [("bus", "stop", "front"), ("car", "stop", "ego")]),
    ("I sat behind a slow tractor for miles.", [("car", "go_straight", "ego"), ("truck", "go_straight", "front")]),
])
def test_the_ego_sitting_behind_one_that_stands_stands_too(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "I was slowing for the lights when a van ran into the back of me.",
    "A van ran into the back of the ego.",
])
def test_one_that_runs_into_the_back_of_the_ego_came_from_behind(prompt):
    assert agents(prompt) == [("car", "go_straight", "back"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Lead vehicle ahead at 0 km/h.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("ego car 40 km/h, lead truck 40 km/h decelerating to 0", [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
    ("The lead car accelerates from a standstill.", [("car", "go_straight", "ego"), ("car", "go_straight", "front")]),
    ("Ego initial speed 0, accelerates to 30 km/h.", [("car", "go_straight", "ego")]),
])
def test_a_speed_of_nothing_stands_and_a_start_from_it_moves(prompt, expected):
    assert agents(prompt) == expected


# -- a student's report, a product manager's request ---------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("This study examines how the ego vehicle responds to an approaching emergency vehicle. A fire engine comes up "
     "behind the ego on a two-lane road.", [("car", "go_straight", "ego"), ("firetruck", "go_straight", "back")]),
])
def test_an_emergency_vehicle_named_in_general_then_by_its_kind_is_one(prompt, expected):
    assert agents(prompt) == expected


def test_two_emergency_vehicles_each_placed_stay_two():
    found = agents("An emergency vehicle comes up behind the ego; an ambulance waits at the junction ahead.")
    assert sum(t == "ambulance" for t, _, _ in found) == 2, found


@pytest.mark.parametrize("prompt, expected", [
    ("A cyclist, defined here as any road user riding a bicycle, crosses from the left in front of the ego vehicle.",
     [("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "front_left")]),
    ("The scene is a blocking event, which we define as another road user occupying the path of the ego. A lorry "
     "pulls out from the right and blocks the ego.",
     [("car", "go_straight", "ego"), ("truck", "block_the_ego", "front_right")]),
    ("We study a following scenario, that is, a situation in which a vehicle drives behind another vehicle. A van "
     "follows the ego vehicle.", [("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
])
def test_a_reports_definitions_of_its_terms_name_no_agents(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("For our project we consider a lane change. The ego vehicle changes into the left lane behind a truck.",
     ("car", "change_lane_to_left", "ego")),
    ("In this study we examine a left turn: the ego vehicle turns left while a bus comes the other way.",
     ("car", "turn_left", "ego")),
])
def test_a_reports_authors_saying_we_are_not_the_ego(prompt, expected):
    found = agents(prompt)
    assert expected in found and [p for _, _, p in found].count("ego") == 1, found


def test_what_a_report_expects_of_the_ego_is_its_check_not_the_scene():
    found = agents("A cyclist crosses ahead of the ego on a straight road. We expect the ego to brake to a stop.")
    assert ("car", "go_straight", "ego") in found, found


def test_a_time_of_day_said_after_a_sequence_word_is_no_stage():
    scene = lower("The test takes place at a four-way stop shortly after sunrise. A bus turns left in front of the ego.")
    assert len(scene.scenario.stages) == 1 and scene.scenario.weather.time == "dawn", scene.scenario


@pytest.mark.parametrize("prompt, objects, signals", [
    ("A cyclist starts to cross when the ego is 15 m from the stop line.", ("stop_line",), ()),
    ("Vehicle signal on red. The subject vehicle is held at the stop line.", ("stop_line",), ("traffic_light",)),
    ("The pedestrian signal shows green and a man crosses in front of the ego.", (), ("traffic_light",)),
])
def test_a_signal_named_by_whom_it_controls_and_a_line_held_at_or_measured_from_are_on_the_road(prompt, objects,
                                                                                                signals):
    spec = road(prompt)
    assert set(objects) <= set(spec.required_objects) and set(signals) <= set(spec.required_signals), spec
    assert [t for t, _, p in agents(prompt) if p != "ego" and t == "car"] == [], agents(prompt)


def test_a_distance_from_the_stop_line_is_no_stop_at_it():
    assert ("car", "go_straight", "ego") in agents("A cyclist starts to cross when the ego is 15 m from the stop line.")


@pytest.mark.parametrize("prompt, lanes", [
    ("The ego approaches the junction in the left-hand one of two through lanes and turns left.", 2),
    ("Arterial with three travel lanes per direction; a bus stops ahead of the ego.", 3),
])
def test_a_lane_count_with_a_traffic_engineers_kind_of_lane(prompt, lanes):
    assert road(prompt).lanes == lanes


@pytest.mark.parametrize("prompt, mover", [
    ("A truck a bit ahead of us on the right slowly merges into our lane.",
     ("truck", "change_lane_to_left", "front_right")),
    ("A van a little ahead of me on the left cuts in.", ("car", "change_lane_to_right", "front_left")),
])
def test_a_little_ahead_of_us_on_a_side_places_the_mover_on_that_side(prompt, mover):
    assert mover in agents(prompt), agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("Something with a bus? A city bus is stopped ahead of our car, and we go around it on the left.",
     [("bus", "stop", "front"), ("car", "change_lane_to_left", "ego")]),
    ("Maybe something with a cyclist. A cyclist rides ahead of the ego and turns right at the junction.",
     [("car", "go_straight", "ego"), ("cyclist", "turn_right", "front")]),
])
def test_a_requests_topic_named_again_in_its_scene_is_one_agent(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, people", [
    ("Pedestrian 1 crosses the road ahead of the ego. Pedestrian 2 stands on the sidewalk.", 2),
    ("Walker 1 crosses on the crosswalk. Walker 2 waits on the sidewalk next to the crosswalk.", 2),
    ("Walker A crosses from the left. Walker B stands on the pavement.", 2),
])
def test_numbered_or_lettered_walkers_are_each_an_agent(prompt, people):
    assert sum(t == "pedestrian" for t, _, _ in agents(prompt)) == people, agents(prompt)


@pytest.mark.parametrize("prompt, count", [
    ("Two trucks ahead of me and one in the lane on my right, on the highway.", 3),
    ("Three pedestrians on the left and one on the right cross the road.", 4),
    ("Two cars, one ahead and one behind.", 2),
])
def test_and_one_after_a_placed_group_is_one_more(prompt, count):
    assert len([a for a in agents(prompt) if a[2] != "ego"]) == count, agents(prompt)


@pytest.mark.parametrize("prompt, action", [
    ("The ego changes lanes, on its right, to let the ambulance pass.", "change_lane_to_right"),
    ("The ego changes lanes, to its right, and passes a slow truck.", "change_lane_to_right"),
])
def test_a_lane_changes_side_set_off_by_commas_is_its_direction(prompt, action):
    assert ("car", action, "ego") in agents(prompt), agents(prompt)


def test_a_move_between_numbered_lanes_is_a_lane_change():
    assert any(p == "ego" and a.startswith("change_lane") for _, a, p in agents("The ego moves from lane 1 to lane 2."))


@pytest.mark.parametrize("prompt, expected", [
    ("A bus turns left at a junction while a pedestrian crosses the road it turns into.",
     [("bus", "turn_left", "ego"), ("pedestrian", "cross_the_road", "at_the_destination")]),
    ("A truck changes lane to the left because a car is stopped ahead.",
     [("car", "stop", "front"), ("truck", "change_lane_to_left", "ego")]),
    ("A car drives down a residential street and a child runs out in front of it from the right.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right")]),
    ("A police car follows a red sedan, which suddenly stops.",
     [("car", "stop", "front"), ("police", "go_straight", "ego")]),
    ("Coach in the middle lane of a motorway, an ambulance comes up fast, and our driver moves over to the left.",
     [("ambulance", "go_straight", "front"), ("bus", "change_lane_to_left", "ego")]),
    ("Coach in the middle lane of a motorway, an ambulance comes up behind it, and our driver moves over to the left.",
     [("ambulance", "go_straight", "back"), ("bus", "change_lane_to_left", "ego")]),
    ("A coach is in the middle lane. An ambulance comes up behind the coach.",
     [("ambulance", "go_straight", "back"), ("bus", "go_straight", "ego")]),
    ("A bus drives along. A car follows it.", [("bus", "go_straight", "ego"), ("car", "go_straight", "back")]),
    ("A pedestrian crosses the road while a car approaches.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("Just the minibus doing an ordinary left turn at a junction with traffic lights, early morning, fog.",
     [("bus", "turn_left", "ego")]),
    ("The lorry turns right while two cars come the other way.",
     [("car", "go_straight", "road_of_straight"), ("car", "go_straight", "road_of_straight"),
      ("truck", "turn_right", "ego")]),
])
def test_a_text_that_names_no_ego_tells_its_scene_from_the_first_vehicle_it_names(prompt, expected):
    """A third-person scene ('a bus turns left ...') or one naming the ego only as 'our driver' is told from its
    first vehicle: it is the ego, not a vehicle ahead of an ego the reader made up."""
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("I watch this every morning: a car drives down the street and a little boy runs out in front of it.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("I think it should be a bus turning left while a cyclist goes straight on its inside.",
     [("bus", "turn_left", "ego"), ("cyclist", "go_straight", "front")]),
    ("I was driving when a car pulled out in front of me.",
     [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]),
    ("My dashcam caught a van turning left across a cyclist.",
     [("car", "go_straight", "ego"), ("car", "turn_left", "front"), ("cyclist", "go_straight", "front")]),
])
def test_a_speaker_who_only_watches_or_asks_leaves_the_scene_to_the_vehicle_it_is_about(prompt, expected):
    """'I watch', 'I think', 'I want' say nothing of the speaker on the road; 'I saw', 'I was driving', 'in front
    of me', 'my dashcam' put the speaker in a vehicle there, and that vehicle is the ego."""
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "bus pulling out of a stop on the right, rain",
    "Two-lane road, and this pickup's doing like forty. Don't try to pass him. Stay behind.",
    "A van is parked on the right; a child runs out from behind it.",
])
def test_a_vehicle_placed_relative_to_someone_or_an_order_to_the_driver_leaves_the_ego_unnamed(prompt):
    """A place ('on the right', 'ahead') is relative to an onlooker, and an order is given to the one at the
    wheel: then the ego is that onlooker, and the vehicle another."""
    assert sum(1 for a in lower(prompt).scenario.agents() if a.relative_to_ego is None) == 1
    assert ("car", "go_straight", "ego") in agents(prompt)


def test_with_no_ego_named_the_vehicle_others_are_placed_by_is_the_ego():
    """'A little boy runs out into the road in front of the car': the car is where the scene is told from."""
    assert agents("A little boy runs out into the road in front of the car.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]
    assert agents("A cyclist rides alongside the bus as it turns left.")[0] == ("bus", "turn_left", "ego")


@pytest.mark.parametrize("prompt", [
    "I was driving north along the east kerb when a cyclist heading west crossed in front of me.",
    "The ego is northbound, its right wheels by the east curb. A van parked against the east curb ahead; a boy runs "
    "out from behind it, east to west across the ego's path.",
    "Patrol car in lane 2 directly ahead of the ego; ego's in lane 2 behind it. Another car in lane 1 alongside the "
    "ego and one in lane 3 just ahead of it.",
])
def test_an_agent_given_two_headings_or_lanes_reads_the_same_in_every_run(prompt):
    import os
    import subprocess
    import sys
    root = Path(__file__).resolve().parents[1]
    code = ("import sys; from ttsgc.lowering.offline import lower; from ttsgc.language import format_scenario; "
            "print(format_scenario(lower(sys.argv[1]).scenario))")
    readings = {subprocess.run([sys.executable, "-c", code, prompt], capture_output=True, text=True, check=True,
                               cwd=root, env={**os.environ, "PYTHONPATH": str(root), "PYTHONHASHSEED": str(seed)}
                               ).stdout for seed in (0, 1, 2, 5)}
    assert len(readings) == 1, readings


@pytest.mark.parametrize("prompt, expected", [
    ("A 9-year-old child runs into the road in front of the ego.", 1),
    ("An 8 year old boy crosses in front of the ego car.", 1),
    ("The ego passes a seventy-year-old man walking on the sidewalk.", 1),
    ("Two 12-year-olds cross ahead of the ego.", 2),
    ("A 16 yo on a bike rides out from a driveway on the right.", 1),
    ("A 44-tonne artic waits at the lights ahead of the ego.", 1),
    ("The ego follows a 12-metre bus and a 3-axle truck.", 2),
])
def test_an_age_or_a_measure_is_no_count(prompt, expected):
    """'a 9-year-old child' is one child, not nine; 'a 44-tonne artic' one truck."""
    assert sum(1 for a in lower(prompt).scenario.agents() if not a.is_ego) == expected


# -- key=value tags ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("ego=truck, lead=van braking, weather=rain, lanes=2",
     [("car", "stop", "front"), ("truck", "go_straight", "ego")]),
    ("lanes=3, rain, lead=car braking", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("weather=snow, time_of_day=night, ego=bus, oncoming=motorbike",
     [("bus", "go_straight", "ego"), ("motorcycle", "go_straight", "front_left")]),
])
def test_a_key_value_tag_names_its_value_by_its_key(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, lanes", [("lanes=3, rain, lead=car braking", 3),
                                           ("ego: car | lanes: 2 | fog", 2),
                                           ("ego=bus, num_lanes=4, night", 4)])
def test_a_counting_key_counts_its_value(prompt, lanes):
    assert road(prompt).lanes == lanes


# -- the same scene said other ways: sequence words, names of the ego, vehicle nouns --------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("The ego waited at the give way line, after that pulled out to the right.",
     [("car", "stop", "ego"), ("car", "turn_right", "ego")]),
    ("Our bus stops at the red light and after that goes straight on.",
     [("bus", "go_straight", "ego"), ("bus", "stop", "ego")]),
    ("The test car waited behind the parked van, after that changed lanes to the left.",
     [("car", "change_lane_to_left", "ego"), ("car", "stop", "ego"), ("car", "stop", "front")]),
])
def test_after_that_before_a_verb_goes_on_with_the_same_subject(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Van 214 was turning left at a junction when an oncoming car went straight across. Van is the SUT.",
     [("car", "go_straight", "road_of_straight"), ("car", "turn_left", "ego")]),
    ("Cab 7 stopped for a woman on the zebra. Can we get this with the cab as the system under test?",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("The taxi was waiting at the red light when a cyclist passed it on the right. The taxi is the subject vehicle.",
     [("car", "stop", "ego"), ("cyclist", "go_straight", "back_right")]),
])
def test_a_vehicle_declared_the_ego_by_another_name_of_the_role_is_the_ego(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("The automated car was waiting at the lights while a cyclist crossed in front of it. Once the cyclist had "
     "gone, the saloon turned right.", [("car", "stop", "ego"), ("car", "turn_right", "ego"),
                                        ("cyclist", "cross_the_road", "front")]),
    ("Can we show the hatchback changing to the left lane behind a slow bus?",  # the bus is in the lane it moves to
     [("bus", "go_straight", "front_left"), ("car", "change_lane_to_left", "ego")]),
    ("The driverless lorry waits at the junction for a cyclist passing from the left. Afterwards, the HGV turns left.",
     [("cyclist", "go_straight", "road_of_left_turn"), ("truck", "stop", "ego"), ("truck", "turn_left", "ego")]),
])
def test_a_noun_of_the_egos_body_said_again_names_the_ego(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, others", [
    ("I was waiting at the lights. The sedan braked hard in front of me.", 1),  # a narrator's 'I' is no sedan
    ("We were driving along the high street when the saloon pulled out of a side road on the left.", 1),
    ("And here comes the blue car, cutting across from the left lane right in front of the ego car!", 1),
])
def test_a_body_noun_in_a_narrators_account_or_placed_by_the_ego_is_another_vehicle(prompt, others):
    assert len([a for a in agents(prompt) if a[2] != "ego"]) == others, agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("An oncoming car and the AV reach a junction at the same time; the AV agent must yield.",
     [("car", "go_straight", "road_of_straight"), ("car", "stop", "ego")]),
    ("Behind the SUT truck a small car follows.", [("car", "go_straight", "back"), ("truck", "go_straight", "ego")]),
    ("The AV truck turns right while a cyclist rides straight on its right.",
     [("cyclist", "go_straight", "right"), ("truck", "turn_right", "ego")]),
])
def test_a_vehicle_noun_after_another_name_of_the_ego_is_the_egos_own(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, mover", [
    ("We were heading north, two lanes our side and a white SUV in the right lane just ahead of us cut across into "
     "our lane.", ("car", "change_lane_to_left", "front_right")),
    ("We were heading west on the bypass, three lanes our side and a dark van in the left lane just ahead of us cut "
     "across into our lane.", ("car", "change_lane_to_right", "front_left")),
])
def test_and_before_a_new_subject_with_adjectives_and_its_verb_opens_a_clause(prompt, mover):
    assert agents(prompt) == sorted([mover, ("car", "go_straight", "ego")])


@pytest.mark.parametrize("prompt", [
    "A sedan pulled up on your left a second before you did and an SUV is stopped across from you waiting to turn "
    "left.",
    "A taxi pulled up on my right just before I did and a bus is waiting across from me to turn left.",
])
def test_a_clause_ended_by_its_auxiliary_alone_gives_its_verb_to_no_one_after_and(prompt):
    assert ("car", "turn_left", "ego") not in agents(prompt), agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("Two lorries, a coach are waiting at the red light ahead of us.",
     [("bus", "stop", "front"), ("truck", "stop", "front"), ("truck", "stop", "front")]),
    ("A cyclist, a jogger are crossing in front of the ego from the right.",
     [("cyclist", "cross_the_road", "front_right"), ("pedestrian", "cross_the_road", "front_right")]),
    ("A van, a small hatchback have stopped on the hard shoulder ahead on the left.",
     [("car", "stop", "front_left"), ("car", "stop", "front_left")]),
    ("A truck, a long articulated one, is parked ahead of the ego.", [("truck", "stop", "front")]),  # apposition
])
def test_noun_phrases_listed_with_a_comma_share_the_plural_verb_after_them(prompt, expected):
    assert [a for a in agents(prompt) if a[2] != "ego"] == expected


@pytest.mark.parametrize("prompt, expected", [
    ("For our project we consider a cut-in, where a black sedan travelling in the left lane, slightly ahead of the "
     "AV, changes lanes to the right directly in front of the AV.",
     [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]),
    ("In this paper we study a cut-in where a white van in the right lane, just ahead of the SUT, moves left in "
     "front of the SUT.", [("car", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]),
])
def test_authors_we_beside_an_ego_named_by_any_role_name_is_no_vehicle(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("later", ["afterwards", "subsequently", "then"])
def test_a_catalogue_summary_line_before_its_phases_keeps_only_its_start_whatever_word_says_later(later):
    prompt = ("Case: Overtaking a slow tractor\n"
              f"Ego: follows the tractor, {later} pulls out to overtake\n"
              "Actors: tractor ahead in the ego lane; oncoming van in the opposite lane\n"
              "Phase 1: ego follows the tractor while the van approaches\n"
              "Phase 2: after the van has passed, ego changes to the left lane and overtakes")
    assert [a for a in agents(prompt) if a[2] == "ego"] == [("car", "change_lane_to_left", "ego"),
                                                          ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", [
    "We waited for the cyclist to pass, and after that we made our turn.",
    "I stopped for the jogger at the junction, and after that I made my turn.",
    "We gave way to the bus at the junction, after that we took our turn.",
])
def test_someones_turn_after_a_word_of_sequence_is_a_turn_not_a_turning_named_as_a_place(prompt):
    assert any(p == "ego" and a.startswith("turn") for _, a, p in agents(prompt)), agents(prompt)


def test_a_turning_named_as_a_place_is_still_nobodys_turn():
    assert not any(a.startswith("turn") for _, a, _ in agents("They got stuck just past the Elm Street turn."))


@pytest.mark.parametrize("prompt, other", [
    ("Ego had to take a left turn at the crossroads, and one car was standing on the road where ego was going.",
     ("car", "stop", "at_the_destination")),
    ("The ego was turning right at the crossroads while a van was parked on the road where the ego was heading.",
     ("car", "stop", "at_the_destination")),
])
def test_the_road_the_ego_heads_for_is_its_destination_in_any_tense(prompt, other):
    assert other in agents(prompt), agents(prompt)


@pytest.mark.parametrize("prompt", [
    "One cyclist rides across the ladder crosswalk when the ego is fifteen metres away and one car waits behind the "
    "ego.",
    "A child runs out when the ego is 20 m away and two cars wait behind the ego.",
])
def test_and_before_a_counted_subject_and_its_verb_ends_a_condition_with_a_copula(prompt):
    assert ("car", "stop", "ego") not in agents(prompt), agents(prompt)
    assert ("car", "stop", "back") in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A cyclist rode in front of me before turning left.", [("car", "go_straight", "ego"),
                                                            ("cyclist", "turn_left", "front")]),
    ("A van overtook me before cutting in.", [("car", "change_lane_to_right", "back_left"),
                                              ("car", "go_straight", "ego")]),
    ("I followed a cyclist before turning left.", [("car", "turn_left", "ego"), ("cyclist", "go_straight", "front")]),
])
def test_a_participle_after_before_or_while_is_done_by_the_subject_of_its_clause(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("We were at the red light when an ambulance came through from the right. The kids were fascinated.",
     [("ambulance", "go_straight", "road_of_right_turn"), ("car", "stop", "ego")]),
    ("I was taking my mother to her appointment. My mother was shaken up but she is fine.",
     [("car", "go_straight", "ego")]),
    ("I stopped at the school. The children crossed in front of me.",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "front"), ("pedestrian", "cross_the_road", "front")]),
])
def test_the_speakers_family_named_with_the_and_doing_nothing_on_the_road_rides_with_the_speaker(prompt, expected):
    assert agents(prompt) == expected


def test_a_counted_group_including_the_speaker_at_a_red_light_waits_with_it():
    assert agents("We were sitting at the red light, three cars including mine, and I was at the back of the queue.") \
        == [("car", "stop", "ego"), ("car", "stop", "front"), ("car", "stop", "front")]
    assert agents("Three cars including the ego drive down the high street.") == [
        ("car", "go_straight", "ego"), ("car", "go_straight", "front"), ("car", "go_straight", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("Winter pick-up is in the dark now. A child ran out between the parked cars right in front of me.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("At pick-up time a pick-up truck stopped in front of me.", [("car", "go_straight", "ego"),
                                                               ("car", "stop", "front")]),
])
def test_the_school_pick_up_is_a_time_and_a_pick_up_truck_a_car(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", ["The number 3 bus pulls away ahead of me.", "The platform 4 bus pulls away ahead of me."])
def test_a_number_after_a_naming_noun_counts_nothing(prompt):
    assert agents(prompt) == [("bus", "go_straight", "front"), ("car", "go_straight", "ego")]


def test_just_me_and_the_bike_is_the_speakers_motorbike():
    assert agents("Just me and the bike, crawling along a country lane with no junctions for miles.") == [
        ("motorcycle", "go_straight", "ego")]


def test_a_clause_after_a_semicolon_with_no_subject_goes_on_with_the_subject_before_it():
    assert agents("Ego: passenger car, follows its lane.\nChallenger: passenger car in the adjacent left lane, ahead "
                  "of the ego; changes lane to the right into the ego lane.") == [
        ("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]
    assert agents("A truck is stopped ahead; overtake it on the left.") == [
        ("car", "change_lane_to_left", "ego"), ("truck", "stop", "front")]


def test_a_catalogues_functional_scenario_line_is_its_title():
    assert agents("Functional scenario: Stationary obstacle in ego lane.\nEgo: follows lane.\n"
                  "Obstacle: broken-down truck, stationary in the ego lane ahead.") == [
        ("car", "go_straight", "ego"), ("truck", "stop", "front")]


def test_a_crossing_cyclist_crosses_and_asks_for_no_crosswalk():
    scenario = lower("A crossing cyclist at an unsignalised T-junction. Ego turns right.").scenario
    assert "crosswalk" not in scenario.road.required_objects
    assert sorted((a.type, a.action) for a in scenario.agents()) == [("car", "turn_right"),
                                                                      ("cyclist", "cross_the_road")]
    assert "crosswalk" in road("The ego stops at the crossing. A pedestrian crosses.").required_objects


def test_bare_vehicle_in_an_operators_log_is_the_av_named_before():
    assert agents("AV turning right on green. Two pedestrians on the crosswalk on the far side; vehicle waited for "
                  "them to clear.") == [("car", "turn_right", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
                                        ("pedestrian", "cross_the_road", "near_the_crosswalk")]
    assert ("car", "go_straight", "road_of_left_turn") in agents(
        "AV going straight at the junction. Vehicle approaching from the left.")


def test_every_doer_and_joins_after_a_passives_by_does_what_the_first_does():
    assert agents("The ego is overtaken by a van and a bus.") == [
        ("bus", "go_straight", "back_left"), ("car", "go_straight", "back_left"), ("car", "go_straight", "ego")]
    assert agents("The ego is overtaken by a van and a bus waits ahead.") == [
        ("bus", "stop", "front"), ("car", "go_straight", "back_left"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Put the camera in the lorry so people can see what the driver sees. The lorry turns left.",
     [("truck", "turn_left", "ego")]),
    ("Drivers never look. A car turns left at the junction.", [("car", "turn_left", "ego")]),
    ("People watch from the pavement as a car turns left.",
     [("car", "turn_left", "ego"), ("pedestrian", "on_the_sidewalk", "right"),
      ("pedestrian", "on_the_sidewalk", "right")]),
])
def test_people_in_general_who_see_or_think_are_no_agents_unless_placed(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("after", ["We called an ambulance.", "An ambulance came later.",
                                   "The police arrived ten minutes later.", "A cop took our statements.",
                                   "Paramedics checked us over."])
def test_emergency_services_named_after_a_told_collision_came_to_help_and_are_no_agents(after):
    assert agents("A car ran the red light and hit me. " + after) == [("car", "go_straight", "ego"),
                                                                      ("car", "go_straight", "front")]


@pytest.mark.parametrize("prompt", [
    "A car hit me. Then an ambulance came up behind us with its siren on.",
    "A car nearly hit me. An ambulance came later.",
    "The ego must not hit anything. An ambulance approaches.",
])
def test_an_emergency_vehicle_placed_or_after_no_collision_stays_in_the_scene(prompt):
    assert any(a[0] == "ambulance" for a in agents(prompt))


@pytest.mark.parametrize("prompt, expected", [
    ("A box truck changed lanes into my lane from the right. The woman driving it stopped suddenly.",
     [("car", "go_straight", "ego"), ("truck", "change_lane_to_left", "front_right")]),
    ("A taxi was parked on my left. The guy was clearly speeding.",
     [("car", "go_straight", "ego"), ("car", "stop", "front_left")]),
    ("A van stopped ahead of me. The man driving the van waved me through.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("A taxi stopped ahead. The guy got out and walked across the road.",
     [("car", "go_straight", "ego"), ("car", "stop", "front"), ("pedestrian", "cross_the_road", "front")]),
    ("A car stopped. The man crossed the road in front of me.",
     [("car", "go_straight", "ego"), ("car", "stop", "front"), ("pedestrian", "cross_the_road", "front")]),
])
def test_a_person_named_again_by_what_drives_a_vehicle_named_before_is_that_vehicle(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("aside", ["Pedestrians in this town never use the crossing.", "Truck drivers have huge blind spots.",
                                   "Everyone on the bus was fine.", "The traffic warden saw nothing."])
def test_road_users_in_general_those_on_board_and_onlookers_who_only_saw_are_no_agents(aside):
    assert agents("I was driving through town. A van pulls out of a side road on my left. " + aside) == [
        ("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]


@pytest.mark.parametrize("prompt", ["The pedestrian saw me and stopped.", "The traffic warden waved me through.",
                                    "Two trucks have stopped ahead of me."])
def test_one_who_saw_and_then_did_something_or_a_counted_plural_stays(prompt):
    assert len(agents(prompt)) >= 2


@pytest.mark.parametrize("prompt, other", [
    ("I turn right into a side street and a woman is crossing it.", ("pedestrian", "cross_the_road")),
    ("Turning left into Elm Street, there's a jogger crossing the mouth of the road.", ("pedestrian", "cross_the_road")),
    ("I was turning right into the car park entrance when a man walked across it.", ("pedestrian", "cross_the_road")),
    ("Ego turns left into the side road; a van is parked just inside it.", ("car", "stop")),
])
def test_the_road_the_ego_turns_into_said_again_is_its_destination(prompt, other):
    assert other + ("at_the_destination",) in agents(prompt)


def test_traffic_along_the_road_turned_onto_keeps_the_side_it_comes_from():
    assert ("car", "go_straight", "road_of_right_turn") in agents(
        "Give-way sign, the ego turns left onto the main road. A car approaches from the right on the main road.")


@pytest.mark.parametrize("prompt, expected", [
    ("A van two cars ahead of me in my lane brakes.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("The lorry three cars in front of me stopped suddenly.", [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
    ("Two cars ahead of me brake.", [("car", "go_straight", "ego"), ("car", "stop", "front"), ("car", "stop", "front")]),
])
def test_cars_counted_right_after_another_vehicle_measure_how_far_it_is(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("The ego is stopped behind a truck. Then the ego turns left.",
     [("car", "stop", "ego"), ("car", "turn_left", "ego"), ("truck", "stop", "front")]),
    ("The ego waits behind a bus.", [("bus", "stop", "front"), ("car", "stop", "ego")]),
    ("The ego stops. A truck ahead turns left.", [("car", "stop", "ego"), ("truck", "turn_left", "front")]),
    ("Stuck behind a lorry on a B-road for what felt like forever.", [("car", "stop", "ego"),
                                                                     ("truck", "go_straight", "front")]),
])
def test_what_a_stopped_ego_stands_behind_doing_nothing_said_stands_too(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("verb, action", [("slows right down", "go_straight"), ("taps the brakes", "go_straight"),
                                          ("brakes gently", "go_straight"), ("brakes hard", "stop"),
                                          ("comes to a stop", "stop")])
def test_a_light_touch_of_the_brakes_drives_on_and_right_before_a_particle_is_no_side(verb, action):
    assert agents(f"A van ahead of me {verb}.") == [("car", "go_straight", "ego"), ("car", action, "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("SV1 is oncoming truck, SV2 oncoming car following SV1.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "front_left"), ("truck", "go_straight", "front_left")]),
    ("POV, heavy truck, enters from right.", [("car", "go_straight", "ego"), ("truck", "go_straight", "right")]),
    ("Vehicle behind me, white Ford Transit, failed to stop.", [("car", "go_straight", "back"),
                                                               ("car", "go_straight", "ego")]),
    ("Two pedestrians cross at crosswalk while third walks along sidewalk on right.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
      ("pedestrian", "cross_the_road", "near_the_crosswalk"), ("pedestrian", "on_the_sidewalk", "right")]),
    ("Two cars wait. Second turns left.", [("car", "go_straight", "ego"), ("car", "stop", "front"),
                                          ("car", "turn_left", "front")]),
    ("Bus pulled out right in front of me on bike and just sat there.",
     [("bus", "block_the_ego", "front"), ("motorcycle", "go_straight", "ego")]),
    ("so I'm turning right at junction and cyclist no jogger is crossing road I'm turning into",
     [("car", "turn_right", "ego"), ("pedestrian", "cross_the_road", "at_the_destination")]),
    ("A bus stops ahead, no cars around.", [("bus", "stop", "front"), ("car", "go_straight", "ego")]),
])
def test_notes_that_drop_their_articles_read_as_with_them(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Lead car changed lane left, revealing stopped car in our lane.",
     [("car", "change_lane_to_left", "front"), ("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("Cut-out: lead vehicle changes to right adjacent lane and reveals stationary vehicle further ahead in ego lane.",
     [("car", "change_lane_to_right", "front"), ("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("Coming up to T-junction on bike and Corsa pulls out of side road on my left.",
     [("car", "go_straight", "road_of_left_turn"), ("motorcycle", "go_straight", "ego")]),
    ("A lad on bike passed me.", [("car", "go_straight", "ego"), ("cyclist", "go_straight", "back_left")]),
])
def test_a_bare_noun_said_in_another_state_or_a_bare_bike_the_speaker_rides(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Two cyclists ride ahead of me. The pair turn left at the junction.",
     [("car", "go_straight", "ego"), ("cyclist", "turn_left", "front"), ("cyclist", "turn_left", "front")]),
    ("Two cyclists ride ahead of me. The two of them turn left at the junction.",
     [("car", "go_straight", "ego"), ("cyclist", "turn_left", "front"), ("cyclist", "turn_left", "front")]),
    ("A van and a truck wait at the lights. The former turns left.",
     [("car", "go_straight", "ego"), ("car", "turn_left", "front"), ("truck", "stop", "front")]),
    ("A van and a truck wait at the lights. The latter turns left.",
     [("car", "go_straight", "ego"), ("car", "stop", "front"), ("truck", "turn_left", "front")]),
    ("A van and a truck wait at the lights. Each turns left.",
     [("car", "go_straight", "ego"), ("car", "turn_left", "front"), ("truck", "turn_left", "front")]),
])
def test_the_pair_the_two_of_them_each_the_former_and_the_latter_name_those_just_named(prompt, expected):
    assert agents(prompt) == expected


def test_street_lamps_lit_say_it_is_night():
    assert lower("A cyclist crosses under the streetlights.").scenario.weather.time == "night"


@pytest.mark.parametrize("prompt, expected", [
    ("The scene has three agents: the ego, a cyclist and a bus.",
     [("bus", "go_straight", "front"), ("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]),
    ("Three vehicles take part: a truck, a bus and the ego.",
     [("bus", "go_straight", "front"), ("car", "go_straight", "ego"), ("truck", "go_straight", "front")]),
    ("Two vehicles wait. The ego turns left.",
     [("car", "stop", "front"), ("car", "stop", "front"), ("car", "turn_left", "ego")]),
    ("Other traffic: two cars, one ahead of the ego and one behind it.",
     [("car", "go_straight", "back"), ("car", "go_straight", "ego"), ("car", "go_straight", "front")]),
])
def test_the_ego_listed_in_a_counted_group_is_one_of_it_and_it_after_the_ego_is_the_ego(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Scenario: unprotected left. Oncoming: 1 sedan, 1 box truck. Pedestrians: 2 crossing the destination road.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_straight"),
      ("pedestrian", "cross_the_road", "at_the_destination"), ("pedestrian", "cross_the_road", "at_the_destination"),
      ("truck", "go_straight", "road_of_straight")]),
    ("T-junction, ego turning left out of a side road.\nTraffic from left: 1 HGV.\nFrom right: 2 cars.",
     [("car", "go_straight", "road_of_right_turn"), ("car", "go_straight", "road_of_right_turn"),
      ("car", "turn_left", "ego"), ("truck", "go_straight", "road_of_left_turn")]),
    ("Ego: going straight.\nCrossing traffic from the right: a van, a motorbike.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "right"), ("motorcycle", "go_straight", "right")]),
])
def test_a_key_that_says_only_where_places_every_agent_its_value_lists_even_run_on_in_one_line(prompt, expected):
    assert agents(prompt) == expected


def test_what_a_test_expects_run_on_in_one_line_stays_in_its_sentence():
    assert ("car", "change_lane_to_right", "ego") in agents(
        "An ambulance approaches the ADS vehicle from behind in the same lane. Expected response: the ADS vehicle "
        "changes lane to the right. ODD: urban arterial, 2 lanes per direction.")


@pytest.mark.parametrize("prompt, expected", [
    ("We approached the pelican crossing and a man started crossing from the right.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("While the ego waits to turn left, a pedestrian crosses the side road it wants to enter.",
     [("car", "turn_left", "ego"), ("pedestrian", "cross_the_road", "at_the_destination")]),
    ("The ego turns right; a cyclist crosses the street the ego is about to enter.",
     [("car", "turn_right", "ego"), ("cyclist", "cross_the_road", "at_the_destination")]),
    ("A van comes round a bend towards us, and we both stop.",
     [("car", "stop", "ego"), ("car", "stop", "front_left")]),
    ("Two lanes, heavy traffic. The car in front slams on its brakes and the guy behind me doesn't stop in time.",
     [("car", "go_straight", "back"), ("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("A line of cyclists ride ahead of me.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front"), ("cyclist", "go_straight", "front")]),
])
def test_crossings_begun_roads_to_be_entered_we_both_and_lines_of_riders(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("place, expected", [
    ("on the traffic island ahead", ("pedestrian", "cross_the_road", "front")),
    ("waiting at the bus stop ahead", ("pedestrian", "on_the_sidewalk", "front_right")),
    ("at the bus stop on the left", ("pedestrian", "on_the_sidewalk", "left")),
    ("on the shoulder ahead", ("pedestrian", "cross_the_road", "front_right")),
])
def test_a_woman_on_an_island_at_a_bus_stop_or_on_the_shoulder_is_on_foot(place, expected):
    assert agents(f"A woman {place}.") == [("car", "go_straight", "ego"), expected]


def test_an_ego_named_only_by_its_lane_is_still_the_ego():
    assert agents("An articulated lorry swings wide to turn left, crossing into the ego's lane.") == [
        ("car", "go_straight", "ego"), ("truck", "turn_left", "front")]
    assert agents("A bus turns left while a pedestrian crosses.") == [
        ("bus", "turn_left", "ego"), ("pedestrian", "cross_the_road", "front")]


@pytest.mark.parametrize("aside", ["Someone should fix that junction.", "The workers at the depot say it happens daily."])
def test_a_person_said_only_to_judge_or_report_is_nobody_on_the_road(aside):
    assert not any(a[0] == "pedestrian" for a in agents("A van pulls out on my left. " + aside))


def test_a_person_asked_for_with_should_and_a_road_verb_stays():
    assert agents("A pedestrian should cross in front of the ego.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("The ego turns right into the side road.", [("car", "turn_right", "ego")]),
    ("I turned left into a side street.", [("car", "turn_left", "ego")]),
    ("A van rolled right into the back of me.", [("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
])
def test_right_before_into_is_a_side_after_a_turn_and_a_word_of_degree_after_other_verbs(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Two cars from the right; second car turns left.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_right_turn"),
      ("car", "turn_left", "road_of_right_turn")]),
    ("A car waits. Second car arrives from the left.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "left"), ("car", "stop", "front")]),
])
def test_an_ordinal_with_no_article_names_a_member_of_the_group_named_before(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("side", ["left", "right"])
@pytest.mark.parametrize("verb", ["turns {} into", "turned {} onto", "is turning {} into", "makes a {} into",
                                  "hangs a {} into", "swings {} into", "bears {} into"])
@pytest.mark.parametrize("place", ["the side road", "the main road", "a car park", "the side street"])
def test_a_turn_into_a_road_keeps_its_side_however_it_is_said(side, verb, place):
    assert agents(f"The ego {verb.format(side)} {place}.") == [("car", f"turn_{side}", "ego")]


@pytest.mark.parametrize("side", ["left", "right"])
@pytest.mark.parametrize("verb", ["moves into the {} lane", "changes lanes to the {}", "pulls out to the {}",
                                  "shifts over a lane to the {}", "merges {}", "slides into the lane on its {}",
                                  "moves over to the {}", "drifts into the {} lane"])
def test_a_lane_change_keeps_its_side_however_it_is_said(side, verb):
    assert agents(f"The ego {verb.format(side)}.") == [("car", f"change_lane_to_{side}", "ego")]


def test_a_car_a_lane_over_is_placed_there_and_changes_nothing():
    assert agents("There is a car a lane to the left of me.") == [("car", "go_straight", "ego"),
                                                                 ("car", "go_straight", "left")]


@pytest.mark.parametrize("prompt, expected", [
    ("The ego drives on an empty road without any pedestrians.", [("car", "go_straight", "ego")]),
    ("No vehicles are parked on the street as the ego passes a school.", [("car", "go_straight", "ego")]),
    ("No cars are coming, so the ego turns left.", [("car", "turn_left", "ego")]),
    ("A man rides a bike ahead.", [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]),
    ("A woman was riding a scooter on my left.", [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "left")]),
])
def test_road_users_said_not_to_be_there_do_nothing_and_a_rider_is_the_ridden(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("If a truck had pulled out, the ego would have braked.", [("car", "go_straight", "ego")]),
    ("Had a truck pulled out, the ego would have braked.", [("car", "go_straight", "ego")]),
    ("The ego stops at the lights. Had a cyclist been there, it would have been hit.", [("car", "stop", "ego")]),
    ("Buses often pull out here. The ego turns left.", [("car", "turn_left", "ego")]),
])
def test_what_did_not_happen_or_happens_in_general_gives_its_verb_to_no_one(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A van pulls into my lane from the right.", [("car", "change_lane_to_left", "front_right"),
                                                  ("car", "go_straight", "ego")]),
    ("A truck is parked in my lane.", [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
])
def test_a_vehicle_said_to_come_into_the_egos_lane_by_any_verb_cuts_in(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A car pulled out from the kerb ahead of me.", [("car", "change_lane_to_left", "front_right"),
                                                     ("car", "go_straight", "ego")]),
    ("A parked car pulled out in front of me.", [("car", "change_lane_to_left", "front_right"),
                                                 ("car", "go_straight", "ego")]),
    ("A bus pulled out from the stop ahead of me on the motorway.", [("bus", "change_lane_to_right", "front_left"),
                                                                     ("car", "go_straight", "ego")]),
    ("A pickup pulled out to overtake me.", [("car", "change_lane_to_left", "back"), ("car", "go_straight", "ego")]),
    ("A van nosed out of a side road on my left.", [("car", "go_straight", "ego"),
                                                    ("car", "go_straight", "road_of_left_turn")]),
])
def test_pulling_out_from_the_kerb_is_from_the_kerb_side_and_pulling_out_to_overtake_is_from_behind(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A motorbike crept up on my nearside on the motorway.", [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "left")]),
    ("A motorbike was creeping up on my inside on the motorway.", [("car", "go_straight", "ego"),
                                                                   ("motorcycle", "go_straight", "left")]),
    ("A cyclist undertook me on the motorway.", [("car", "go_straight", "ego"), ("cyclist", "go_straight", "back_left")]),
    ("The car in front jammed on the anchors.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
])
def test_british_words_of_the_kerb_side_and_the_brakes(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("The car opposite me at the four way stop went first and turned left.",
     [("car", "go_straight", "ego"), ("car", "turn_left", "road_of_straight")]),
    ("The car facing me went first and turned left.", [("car", "go_straight", "ego"),
                                                      ("car", "turn_left", "road_of_straight")]),
    ("A taxi coming towards me at the junction turned right.", [("car", "go_straight", "ego"),
                                                                ("car", "turn_right", "road_of_straight")]),
    ("A car came towards me from the right at the crossroads.", [("car", "go_straight", "ego"),
                                                                 ("car", "go_straight", "road_of_right_turn")]),
])
def test_the_ego_named_in_an_oncoming_place_is_not_a_doer_of_the_verbs(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("There's a semi stopped on the shoulder up ahead on the left with its hazards going.",
     [("car", "go_straight", "ego"), ("truck", "stop", "front_left")]),
    ("A van was parked ahead with its engine running.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("A car was stopped ahead with a cyclist riding past it.",
     [("car", "go_straight", "ego"), ("car", "stop", "front"), ("cyclist", "go_straight", "front")]),
    ("A ute was sitting right next to me in the right lane so I can't move over.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "right")]),
    ("A BMW was sitting on my tail.", [("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
    ("The car ahead could not move.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("I cannot move over because of a van.", [("car", "go_straight", "ego"), ("car", "go_straight", "front")]),
])
def test_a_thing_doing_after_with_and_a_manoeuvre_that_could_not_be_made_are_nobodys_actions(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Bus has the green at the crossroads and a fire engine comes through the red from the right. Our driver brakes "
     "to a stop.", [("bus", "stop", "ego"), ("firetruck", "go_straight", "road_of_right_turn")]),
    ("The ego has the green and a cyclist comes from the left.", [("car", "go_straight", "ego"),
                                                                  ("cyclist", "go_straight", "road_of_left_turn")]),
    ("A car drove across the crosswalk in front of me.", [("car", "go_straight", "ego"), ("car", "go_straight", "front")]),
    ("A truck crossed the junction from the left.", [("car", "go_straight", "ego"),
                                                    ("truck", "go_straight", "road_of_left_turn")]),
    ("The car behind me pulled out around me.", [("car", "change_lane_to_left", "back"), ("car", "go_straight", "ego")]),
    ("The car behind me pulled out round me.", [("car", "change_lane_to_left", "back"), ("car", "go_straight", "ego")]),
])
def test_a_held_green_ends_a_clause_and_a_vehicle_over_a_crossing_or_out_round_the_ego_is_no_cross_traffic(
        prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("I pulled out to the right and went round the cyclist.", [("car", "change_lane_to_right", "ego"),
                                                               ("cyclist", "go_straight", "front")]),
    ("Three cars including the ego are queued at a red light, with the ego second in the queue. The car behind "
     "honks.", [("car", "stop", "back"), ("car", "stop", "ego"), ("car", "stop", "front")]),
])
def test_going_round_keeps_the_side_pulled_out_to_and_the_car_behind_a_queued_ego_is_the_one_behind(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("#cutin #highway truck from the right lane", [("car", "go_straight", "ego"),
                                                    ("truck", "change_lane_to_left", "right")]),
    ("Cut in test. A van in the left lane.", [("car", "change_lane_to_right", "left"), ("car", "go_straight", "ego")]),
    ("A truck in the right lane. I cut in front of it.", [("car", "change_lane_to_left", "ego"),
                                                          ("truck", "go_straight", "right")]),
])
def test_a_scene_named_for_a_cut_in_gives_it_to_its_one_vehicle_beside_the_ego(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "The ego is stopped at a red light with a motorcycle beside it on the left. The light turns green and they both go.",
    "Ego stopped at red. Motorcycle filters up on the left and stops beside us. Light goes green, both go.",
])
def test_both_after_the_ego_and_one_other_are_those_two_and_the_one_queued_beside_waits_first(prompt):
    assert stages(prompt) == [[("ego", "stop", None), ("motorcycle", "stop", "left")], [("ego", "go_straight", None)]]


def test_the_lane_said_to_be_the_egos_after_where_places_the_others_by_number():
    assert agents("On the motorway a lorry in lane 1 started to move out into lane 2 where I was, so I braked.") == [
        ("car", "go_straight", "ego"), ("truck", "change_lane_to_right", "left")]


@pytest.mark.parametrize("prompt, expected", [
    ("Two joggers run along the side of the road towards the ego.",
     [("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "right"),
      ("pedestrian", "on_the_sidewalk", "right")]),
    ("A man was running along the verge.", [("car", "go_straight", "ego"),
                                            ("pedestrian", "on_the_sidewalk", "front_right")]),
    ("A child runs across the road.", [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
])
def test_a_person_running_along_the_roadside_keeps_to_it(prompt, expected):
    assert agents(prompt) == expected


def test_a_passenger_of_the_other_driver_is_on_board_and_no_one_on_the_road():
    assert agents("The other driver's passenger got out and started shouting. The other driver had jumped the red "
                  "light from the right.") == [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_right_turn")]


@pytest.mark.parametrize("prompt, expected", [
    ("I waited for the kids to cross.", [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "front"),
                                         ("pedestrian", "cross_the_road", "front")]),
    ("I'm stopped at a four-way stop waiting for a cyclist to cross in front of me.",
     [("car", "stop", "ego"), ("cyclist", "cross_the_road", "front")]),
    ("The ego waits patiently for the bus to pull out.", [("bus", "change_lane_to_right", "front_left"),
                                                          ("car", "stop", "ego")]),
])
def test_the_one_waited_for_does_the_verb_after_to(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("The ego waits to turn right at the junction. Once the oncoming car has gone by, it turns right.",
     [[("ego", "stop", None), ("car", "go_straight", "road_of_straight")], [("ego", "turn_right", None)]]),
    ("A car is waiting to turn right at a crossroads. Once the oncoming car has gone by, it turns right.",
     [[("ego", "stop", None), ("car", "go_straight", "road_of_straight")], [("ego", "turn_right", None)]]),
    ("A driver is waiting to turn right at a crossroads. Once the oncoming car has gone by he turns right.",
     [[("ego", "stop", None), ("car", "go_straight", "road_of_straight")], [("ego", "turn_right", None)]]),
    ("The ego waits at the junction, looking out for cars.", [[("ego", "stop", None)]]),
])
def test_one_gone_by_in_a_condition_passes_while_the_waiting_one_waits_and_then_turns(prompt, expected):
    assert stages(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("V1 was stationary at a red signal. V2 (HGV) failed to stop and struck V1 from behind.",
     [("car", "stop", "ego"), ("truck", "go_straight", "back")]),
    ("At approx 0815 hrs V1 (Ford Focus) was stationary at a red signal. V2 (HGV) failed to stop and struck V1 from "
     "behind.", [("car", "stop", "ego"), ("truck", "go_straight", "back")]),
    ("P1 (pedestrian) stepped into the carriageway from the offside footway. V1 braked but struck P1.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right")]),  # keep left: offside right
    ("The ego entered the junction and collided with a car coming from the nearside.",  # a British word: the
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]),  # kerb side is the left
    ("In the CPNA test the VUT drives straight and a pedestrian target crosses from the nearside.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right")]),  # a protocol's: the right
    ("A pedestrian crosses the ego's path from the right.", [("car", "go_straight", "ego"),
                                                            ("pedestrian", "cross_the_road", "front_right")]),
])
def test_a_collision_reports_numbered_vehicles_times_and_kerb_sides(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Coming through the village in the tipper, an old boy steps off the kerb onto the zebra.",
     [("pedestrian", "cross_the_road", "near_the_crosswalk"), ("truck", "go_straight", "ego")]),
    ("Heads up westbound. Rolling up on it now in the Kenworth: jackknifed semi blocking both lanes. Back it down.",
     [("truck", "block_the_ego", "front"), ("truck", "go_straight", "ego")]),
    ("Right lads, one for the sim. Some muppet in a white van cut me up.",
     [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]),
    ("I'm in the artic on the motorway, sat at 56 on the limiter.", [("truck", "go_straight", "ego")]),
    ("On the motorway a motorbike came up my inside.", [("car", "go_straight", "ego"),
                                                        ("motorcycle", "go_straight", "left")]),
])
def test_a_drivers_own_cab_the_readers_spoken_to_and_trade_words(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("ego waits at the 4 way stop, then once its clear ego turns right",
     [[("ego", "stop", None)], [("ego", "turn_right", None)]]),
    ("The ego waits at the stop sign. Once it's clear the ego turns right.",
     [[("ego", "stop", None)], [("ego", "turn_right", None)]]),
    ("pls someone set up a zebra crossing w/ a kid crossing from the right, ego just comes up to it.",
     [[("ego", "go_straight", None), ("pedestrian", "cross_the_road", "near_the_crosswalk")]]),
    ("Someone ran out in front of me.", [[("ego", "go_straight", None), ("pedestrian", "cross_the_road", "front")]]),
    ("In the opposite direction come two cars that go straight.",
     [[("ego", "go_straight", None), ("car", "go_straight", "front_left"), ("car", "go_straight", "front_left")]]),
    ("A bus pulled out in front of me, so I stopped. You're supposed to give way to buses anyway.",
     [[("ego", "stop", None), ("bus", "change_lane_to_right", "front_left")]]),
])
def test_chat_requests_and_second_language_english(prompt, expected):
    assert stages(prompt) == expected


def test_a_numbered_name_after_an_open_group_out_of_reach_reads_without_failing():
    prompt = ("V1 was stationary at the pelican crossing outside St Mary's Primary School, traffic signals showing red "
              "for vehicles. Ped 1 and Ped 2 (both juveniles, approx. 10 years) were crossing from V1's nearside. V2 "
              "(silver BMW 3 Series) was travelling in the offside lane at excessive speed, passed V1 and went through "
              "the red signal, narrowly missing Ped 2. V2 failed to stop at the scene. Two lanes in this direction.")
    assert agents(prompt) == [("car", "go_straight", "back_right"), ("car", "stop", "ego"),
                              ("pedestrian", "cross_the_road", "near_the_crosswalk"),
                              ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_a_reports_compass_abbreviations_and_straight_ahead_said_as_a_manoeuvre():
    words = [t.word for t in tokenize("V1 was travelling N/B, V2 S/B, V3 E/B and V4 W/B.")]
    assert [w for w in words if w.endswith("bound")] == ["northbound", "southbound", "eastbound", "westbound"]
    assert agents("The ego turns left. A van proceeded straight ahead through the junction from the right.") == [
        ("car", "go_straight", "road_of_right_turn"), ("car", "turn_left", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Snow day, and the gritter hasn't touched Park Lane. I was crawling along at 10 mph when four schoolchildren "
     "crossed right in front of me.", [("car", "go_straight", "ego")] + [("pedestrian", "cross_the_road", "front")] * 4),
    ("For once I was driving (yes, campaigners own cars too) and a cyclist came up the inside.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]),
    ("I stopped. Road was icy.", [("car", "stop", "ego")]),
])
def test_street_names_owned_kinds_and_ones_that_never_came_are_nobody(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Just drove round and round the estate for an hour in the dark. Didn't see one other car!!",
     [("car", "go_straight", "ego")]),
    ("We didn't see a single cyclist all day.", [("car", "go_straight", "ego")]),
    ("I went round the parked van.", [("car", "change_lane_to_left", "ego"), ("car", "stop", "front")]),
])
def test_none_seen_and_round_and_round_name_no_one_and_no_lane_change(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("The ego approaches to a pass of pedestrians with semaphore. There are two persons waiting in the sidewalk and "
     "one old man that is crossing very slow. The ego stops.",
     [[("ego", "stop", None), ("pedestrian", "on_the_sidewalk", "near_the_crosswalk"),
       ("pedestrian", "on_the_sidewalk", "near_the_crosswalk"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]]),
    ("sam pls: 3 cars incl ego queued at a red light, ego is the middle one. then it goes green and ego goes straight",
     [[("ego", "stop", None), ("car", "stop", "front"), ("car", "stop", "back")], [("ego", "go_straight", None)]]),
    ("We did the big roundabout and I went round and came off to the right.", [[("ego", "turn_right", None)]]),
])
def test_spanish_calques_the_middle_one_and_coming_off_a_roundabout(prompt, expected):
    assert stages(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Turning left at the lights in the 44-tonner and a cyclist comes flying up the inside of me.",
     [("cyclist", "go_straight", "right"), ("truck", "turn_left", "ego")]),
    ("Two 44-tonners overtook me.", [("car", "go_straight", "ego"), ("truck", "go_straight", "back_left"),
                                     ("truck", "go_straight", "back_left")]),
])
def test_a_tonner_is_a_lorry_and_the_one_the_speaker_turns_in_is_the_ego(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("SC-07 Emergency vehicle approach from the rear. An ambulance approaches the ADS vehicle from behind in the same "
     "lane.", [("ambulance", "go_straight", "back"), ("car", "go_straight", "ego")]),
    ("RTC, 2 veh. V1 stationary in queue at traffic lights. V2 failed to stop and ran into rear of V1.",
     [("car", "go_straight", "back"), ("car", "stop", "ego")]),
    ("Two-vehicle collision. The ego is stopped at a red light and a van runs into the back of it.",
     [("car", "go_straight", "back"), ("car", "stop", "ego")]),
    ("We were sat in the middle lane with the cruise set at 60 mph when a coach loomed ahead.",
     [("bus", "go_straight", "front"), ("car", "go_straight", "ego")]),
    ("We were sat in the middle lane at the red light, a coach ahead.",
     [("bus", "stop", "front"), ("car", "stop", "ego")]),
])
def test_a_coded_title_a_crash_counted_by_its_vehicles_and_sitting_at_a_speed(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A truck passed me. EMS + PD dispatched 14:03.", [("car", "go_straight", "ego"), ("truck", "go_straight",
                                                                                        "back_left")]),
    ("A truck passed me. Medic 4, Engine 2 en route.", [("car", "go_straight", "ego"),
                                                        ("truck", "go_straight", "back_left")]),
    ("I'm at a four-way stop going straight. A silver SUV from my right nearly T-boned me. The cop who showed up "
     "later said it was 50/50.", [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_right_turn")]),
    ("A police car arrived and stopped in front of me.", [("car", "go_straight", "ego"), ("police", "stop", "front")]),
    ("A semi passed me. Truckers around here seem to think they own the road.",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "back_left")]),
    ("On Friday the bus I was on was waiting at the red light.", [("bus", "stop", "ego")]),
    ("A car cut in, that's why mate.", [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]),
])
def test_help_called_out_kinds_in_general_the_bus_the_speaker_was_on_and_a_word_of_address(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("REQ-AEB-112: When the subject vehicle approaches a signalised intersection at 50 km/h and a pedestrian steps "
     "onto the crosswalk in front of it, the AEB function shall bring the subject vehicle to a standstill.",
     [[("ego", "stop", None), ("pedestrian", "cross_the_road", "near_the_crosswalk")]]),
    ("I stopped in the left lane, and 3 cars piled up right ahead of me and a truck stopped in the right lane "
     "beside me.", [[("ego", "stop", None), ("car", "stop", "front"), ("car", "stop", "front"),
                     ("car", "stop", "front"), ("truck", "stop", "right")]]),
    ("A pedestrian ran across the road in front of me. Ped not struck.",
     [[("ego", "go_straight", None), ("pedestrian", "cross_the_road", "front")]]),
    ("I stopped at the line. The kid in the Civic behind me slammed right into me. He should've left more room.",
     [[("ego", "stop", None), ("car", "go_straight", "back")]]),
    ("A car on the left left me no room.", [[("ego", "go_straight", None), ("car", "go_straight", "left")]]),
    ("I was turning right. A cyclist on my right slammed into my door. The officer didn't ticket anybody.",
     [[("ego", "turn_right", None), ("cyclist", "go_straight", "right")]]),
])
def test_a_requirements_trigger_a_pile_up_a_clipped_name_room_left_and_an_officers_paperwork(prompt, expected):
    assert stages(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("The ego drives toward a zebra crossing. Two pedestrians step onto the crossing from the right kerb.",
     [[("ego", "go_straight", None), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
       ("pedestrian", "cross_the_road", "near_the_crosswalk")]]),
    ("I was waiting at the give-way sign when a van came round from my right, and the taxi waiting behind me "
     "sounded its horn at me.", [[("ego", "stop", None), ("car", "go_straight", "road_of_right_turn"),
                                  ("car", "stop", "back")]]),
    ("The ego turns left. One truck comes from the opposite side, and behind it two cars.",
     [[("ego", "turn_left", None), ("truck", "go_straight", "road_of_straight"),
       ("car", "go_straight", "road_of_straight"), ("car", "go_straight", "road_of_straight")]]),
    ("I was waiting at the give-way sign when a white van came round from my right, as though I ought to have "
     "pulled out.", [[("ego", "stop", None), ("car", "go_straight", "road_of_right_turn")]]),
    ("hey Siri note comma at the four way stop I was stopped comma a cyclist came through from the road on my right "
     "going straight full stop tell Karen about it later",
     [[("ego", "stop", None), ("cyclist", "go_straight", "road_of_right_turn")]]),
])
def test_a_crossing_from_a_kerb_two_bodies_of_car_behind_it_after_its_clause_ought_to_have_and_dictation(
        prompt, expected):
    assert stages(prompt) == expected


def test_a_dictated_notes_spoken_marks_are_marks_and_its_wake_words_no_part_of_it():
    from ttsgc.lowering.narration import read_narration
    assert read_narration("hey Siri note a truck cut me off comma it was on my right full stop three lanes").text == \
        "a truck cut me off, it was on my right. three lanes"
    assert read_narration("The comma was missing. A car came.").text == "The comma was missing. A car came."


@pytest.mark.parametrize("prompt, expected", [
    ("The lights were green when Marguerite reached them, and she eased the Volvo left.", [("car", "go_straight",
                                                                                            "ego")]),
    ("I turned the car left at the crossroads.", [("car", "turn_left", "ego")]),
    ("The ego turns left at a crossroads. Two cars come the other way, the second one behind the first.",
     [("car", "go_straight", "road_of_straight"), ("car", "go_straight", "road_of_straight"),
      ("car", "turn_left", "ego")]),
    ("You're driving along a rural road. Ahead of you, a car is slowing to turn right into a farm track.",
     [("car", "go_straight", "ego"), ("car", "turn_right", "front")]),
    ("The ego, a bus, is waiting at the stop.", [("bus", "stop", "ego")]),
])
def test_the_car_steered_is_the_egos_a_member_placed_as_its_group_and_a_noun_with_its_own_verb_after_the_ego(
        prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Two lanes each way, and a white hatchback in the lane to my left cuts straight in front of me.",
     ("car", "change_lane_to_right", "left")),
    ("This van pulls out of the left lane and cuts straight in front of me.",
     ("car", "change_lane_to_right", "left")),
    ("Doing 65 in the right lane and a car in the left lane dives in right in front of my bumper.",
     ("car", "change_lane_to_right", "left")),
])
def test_in_front_of_the_ego_after_a_cut_in_is_where_it_ends_and_out_of_a_lane_is_where_it_came_from(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("I'm driving along, and a squad car comes out of the side road on my left and stops dead across the front of "
     "me. Then two more pull up right behind me.",
     [[("ego", "go_straight", None), ("police", "stop", "road_of_left_turn")],
      [("police", "stop", "back"), ("police", "stop", "back")]]),
    ("I'm waiting at the red, and a fire engine comes through from the road on my left, and then two more come "
     "straight after it.",
     [[("ego", "stop", None), ("firetruck", "go_straight", "road_of_left_turn")],
      [("firetruck", "go_straight", "road_of_left_turn"), ("firetruck", "go_straight", "road_of_left_turn")]]),
    ("Two more seconds and I'd have hit it.", [[("ego", "go_straight", None)]]),
])
def test_a_count_and_more_with_no_noun_are_more_of_the_kind_just_named(prompt, expected):
    assert stages(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A car swings across in front of me, driving like a proper lunatic he was.",
     [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]),
    ("A car came out of a side road on my left and nearly hit me. The cop said it was 50/50.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]),
    ("two kids on the zebra, foggy morning", [("car", "go_straight", "ego"),
                                              ("pedestrian", "cross_the_road", "near_the_crosswalk"),
                                              ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
])
def test_someone_named_by_a_role_who_does_nothing_and_is_nowhere_is_no_one_on_foot(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Drove the fire engine to a car fire on the ring road. The car in front of me pulled over.",
     [("car", "change_lane_to_right", "front"), ("firetruck", "go_straight", "ego")]),
    ("First shout driving the fire engine: house fire on Elm Road. I went down a narrow street and a cyclist ahead of "
     "me kept pedalling.", [("cyclist", "go_straight", "front"), ("firetruck", "go_straight", "ego")]),
    ("A truck was driving the wrong way. I stopped.", [("car", "stop", "ego"), ("truck", "go_straight", "front")]),
])
def test_a_vehicle_driven_by_a_verb_with_no_subject_in_a_first_person_account_is_the_speakers(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Event: PCW | 2024-05-14 22:14:50 | Veh: Bus #77 | Light: dark. Driver comment: two lads stepped onto the "
     "crossing.", [("bus", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
                   ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("Event: Following Distance < 1.0 s (x3) | 13:40-13:44 | Veh: Car 5 | Spd 45 -> 30 km/h. Lead object: bus.",
     [("bus", "go_straight", "front"), ("car", "go_straight", "ego")]),
    ("A northbound car turns left into Elm Street on the green while a southbound cyclist goes straight through.",
     [("car", "turn_left", "ego"), ("cyclist", "go_straight", "road_of_straight")]),
])
def test_an_event_records_fields_and_a_scene_told_by_compass_headings(prompt, expected):
    assert agents(prompt) == expected
    assert not [w for w in road(prompt).required_objects if w.startswith("speed_")]  # a speed of its own, no limit


@pytest.mark.parametrize("prompt, expected", [
    ("A bus goes straight through the junction, and a car sits waiting at the red to the bus's left.",
     [("bus", "go_straight", "ego"), ("car", "stop", "road_of_left_turn")]),
    ("A southbound car turns left onto Route 30 while a police car approaches from the car's right.",
     [("car", "turn_left", "ego"), ("police", "go_straight", "road_of_right_turn")]),
    ("The subject is a bus travelling straight through on its green. A fire engine is speeding up behind it.",
     [("bus", "go_straight", "ego"), ("firetruck", "go_straight", "back")]),
    ("The bus priority signal is green. A bus goes straight.", [("bus", "go_straight", "ego")]),
    ("The bus signals right and pulls out.", [("bus", "change_lane_to_right", "front_left"),
                                              ("car", "go_straight", "ego")]),
])
def test_a_brief_about_one_vehicle_places_the_others_by_it_and_a_nouns_modifier_names_no_one(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Insured vehicle (IV), a 2018 Toyota Camry, was making a left turn at a signalized intersection. Claimant "
     "vehicle (CV), a Ford Escape traveling straight through from the opposite direction, struck IV's passenger side.",
     [("car", "go_straight", "road_of_straight"), ("car", "turn_left", "ego")]),
    ("IV was stopped at a red signal. CV struck IV from behind. Liability: IV 90% / CV 10%.",
     [("car", "go_straight", "back"), ("car", "stop", "ego")]),
])
def test_an_insurance_files_insured_vehicle_is_the_ego_and_a_share_of_liability_no_count(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("I was waiting at the bus stop on Harcourt Road. A red hatchback came down the hill and turned left at the "
     "junction. The bus I was waiting for still hadn't turned up, typical.", [("car", "turn_left", "ego")]),
    ("I was standing on the footway a short distance ahead of the vehicle concerned, when I saw a silver Ford "
     "Focus travelling towards me.", [("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "front_left")]),
])
def test_a_witness_on_foot_is_an_agent_only_when_placed_by_the_vehicles_and_a_bus_not_come_is_none(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("There is pedestrian crossing without traffic light. Two pedestrians are crossing the road on it, ego stops "
     "before the crossing.", [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
                              ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("A pedestrian crossing without looking steps out in front of me.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("The car in front of me stopped. I hit my brakes but slid right into the back of him.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("I wasn't moving and neither was the car behind me.", [("car", "stop", "back"), ("car", "stop", "ego")]),
    ("A fire engine came down the right lane past me.", [("car", "go_straight", "ego"),
                                                         ("firetruck", "go_straight", "back_right")]),
])
def test_a_crossing_without_lights_a_skid_into_the_back_neither_was_and_past_me_down_a_lane(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("I'd been stuck behind a cyclist in club colours for most of it.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]),
    ("I just got a ticket for not moving over. I was in the right lane and a trooper was stopped on the shoulder "
     "ahead on the right.", [("car", "go_straight", "ego"), ("police", "stop", "front_right")]),
    ("The car in front did not move.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
])
def test_stuck_behind_a_slow_rider_and_not_moving_over_are_no_stop_of_the_ego(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("I sat behind the 42 bus on Kingsway for about a mile.", [("bus", "go_straight", "front"),
                                                               ("car", "go_straight", "ego")]),
    ("The 3 cars ahead stopped.", [("car", "go_straight", "ego")] + [("car", "stop", "front")] * 3),
])
def test_the_number_of_a_route_is_no_count_and_a_count_of_a_plural_is(prompt, expected):
    assert agents(prompt) == expected


def test_a_team_that_wants_to_test_a_junction_is_not_on_the_road_the_first_vehicle_is_the_ego():
    assert agents("We want to test the unmarked crossroads at Hollow Lane: no signals, no stop or give-way signs. "
                  "Model a car going straight across at dawn in fog, and a motorcyclist coming the other way "
                  "turning right.") == [("car", "go_straight", "ego"), ("motorcycle", "turn_right", "road_of_straight")]


@pytest.mark.parametrize("prompt, expected", [
    ("The subject car approaches slowly. The head teacher's concern is drivers not slowing down enough.",
     [("car", "go_straight", "ego")]),
    ("Two drivers wait at the lights ahead of me.", [("car", "go_straight", "ego"), ("car", "stop", "front"),
                                                     ("car", "stop", "front")]),
])
def test_drivers_said_bare_are_drivers_in_general_and_counted_ones_are_agents(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("word", ["kiddies", "sprogs", "bairns"])
def test_words_for_children_in_british_and_scots_speech_name_pedestrians(word):
    assert agents(f"Two {word} walk across the zebra. You stop.") == [
        ("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
        ("pedestrian", "cross_the_road", "near_the_crosswalk")]


@pytest.mark.parametrize("prompt, lanes", [
    ("A school bus was stopped ahead on our right picking kids up. We drove on.", 1),
    ("The ego passes a bus that is stopped at a bus stop in the right lane ahead.", 2),
    ("Got cut up by a Tesla, it came across from the lane on my left and slammed on right in front of me.", 2),
])
def test_a_vehicle_stopped_ahead_to_one_side_stands_at_the_kerb_unless_a_lane_is_said(prompt, lanes):
    assert road(prompt).lanes == lanes


@pytest.mark.parametrize("prompt, has", [
    ("The ego turns to right in the crossroad with stop signal, and a bicycle comes from the left side.", ["stop"]),
    ("One car comes from the opposite in a crossroad with give way signal, while the ego waits to turn left.",
     ["yield"]),
    ("One big truck stop on right shoulder in front of ego, hazard light is on.", []),
    ("First blue-light drive: a broken-down HGV on the hard shoulder ahead.", []),
])
def test_a_sign_called_a_signal_is_the_sign_and_a_vehicles_own_lamps_are_no_traffic_light(prompt, has):
    assert list(road(prompt).required_signals) == has


@pytest.mark.parametrize("prompt, limit", [
    ("Imagine you are driving down a residential street with a 20 mph limit. A van is stopped ahead of you.",
     "speed_32"),
    ("Had to get past a cyclist on the 20 mph bit by the park.", "speed_32"),
])
def test_imagining_oneself_at_the_wheel_is_the_scene_and_a_speed_on_a_bit_of_road_is_its_limit(prompt, limit):
    assert road(prompt).required_objects == (limit,)


def test_imagining_oneself_in_a_role_is_still_the_request_to_the_chatbot():
    lowered = lower_prompt("Imagine you are a simulation expert. A car turns left.", "offline")
    assert any("read past the request's words" in n for n in lowered.notes)


@pytest.mark.parametrize("prompt", [
    "Semi on a two-lane county road, miles from any intersection. A pickup comes the other way.",
    "The ego drives along a lane a long way from any junction; a cyclist rides ahead.",
    "Nowhere near any roundabout, a van overtakes the ego.",
])
def test_a_road_said_to_be_far_from_any_junction_is_not_at_one(prompt):
    assert road(prompt).junction is False


def test_room_given_to_a_rider_is_no_word_misread():
    lowered = lower_prompt("The ego waits, then moves over to the left to give the cyclist ahead room.", "offline")
    assert "room" not in " ".join(lowered.unknown)


@pytest.mark.parametrize("prompt, expected", [
    ("IV was traveling straight on Lincoln Ave, followed by CV, a Jeep Wrangler. CV rear-ended IV.",
     [("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
    ("At the crossroads, CV, a Mack dump truck, came from IV's left.",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "road_of_left_turn")]),
    ("CV, a Jeep Wrangler, followed IV.", [("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
    ("The ego drives along, followed by a truck.", [("car", "go_straight", "ego"), ("truck", "go_straight", "back")]),
])
def test_what_a_claimants_vehicle_is_said_after_it_and_followed_by_said_after_the_ego(prompt, expected):
    assert agents(prompt) == expected


def test_a_verbless_ego_before_a_comma_is_not_the_subject_of_the_next_vehicles_verb():
    assert agents("SUT at 30 km/h, a parked van pulls out from the right kerb just ahead and stops across the lane, "
                  "blocking the SUT.") == [("car", "block_the_ego", "front_right"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("In town the autonomous emergency braking gets its test. A cyclist shoots out of a side street on the right "
     "across our bows, and the car stamps on the brakes all by itself, stopping short of him.",
     [("car", "stop", "ego"), ("cyclist", "cross_the_road", "road_of_right_turn")]),
    ("RP driving on Route 9. Says a pedestrian ran across the road in front of her, she swerved and stopped.",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "front")]),
])
def test_by_itself_names_no_one_and_she_who_swerves_is_at_a_wheel_not_on_foot(prompt, expected):
    assert agents(prompt) == expected


def test_a_car_the_text_opens_on_is_the_speakers_own_and_the_system_holding_the_car_holds_the_ego():
    assert stages("Watch as the car waits to turn right on a green at a busy downtown intersection. Two "
                  "pedestrians step onto the zebra crossing of the street we're turning into, so the system holds "
                  "the car in place. Once they're safely across, it completes the turn.") == [
        [("ego", "stop", None), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
         ("pedestrian", "cross_the_road", "near_the_crosswalk")], [("ego", "turn_right", None)]]


def test_right_where_it_is_is_no_side():
    assert road("The driver signals left, but a motorcycle is in the left lane just behind us, so the system "
                "keeps the car right where it is.").junction is None


@pytest.mark.parametrize("prompt, signals, expected", [
    ("The red car is driving down the street when a boy runs out into the road.", (),
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("The ego waits at the red light. A green bus waits beside it on the left.", ("traffic_light",),
     [("bus", "stop", "left"), ("car", "stop", "ego")]),
])
def test_a_colour_before_a_vehicle_is_its_paint_not_a_signal(prompt, signals, expected):
    assert (road(prompt).required_signals, agents(prompt)) == (signals, expected)


@pytest.mark.parametrize("prompt, expected", [
    ("Dude in a white pickup just swerved over from the lane on my right and cut in right in front of me.",
     [("car", "change_lane_to_left", "right"), ("car", "go_straight", "ego")]),
    ("First snow of the year and people already forgot how to drive. Going through on a green and a Jeep from the "
     "left slides right through his red in front of me. Swear my heart stopped.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]),
])
def test_where_a_swerve_came_from_people_in_general_and_the_speakers_heart(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("The ego is in the left lane; a truck in the middle lane is level with it.",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "right")]),
    ("The ego drives in the right lane. A van follows the ego in the right lane.",
     [("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
    ("I was driving in the left-hand lane when a cyclist passed me in the lane to my left.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "back_left")]),
])
def test_a_lane_named_by_its_place_on_the_road_is_placed_against_the_egos_named_lane(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Hi sim folks, I'm putting together the highway merge set. Our car drives in the left lane.",
     [("car", "go_straight", "ego")]),
    ("A car just ahead of me in the left lane keeps going.", [("car", "go_straight", "ego"),
                                                             ("car", "go_straight", "front_left")]),
    ("Our truck is in the right lane of a three-lane motorway, and a car just ahead of it in the middle lane "
     "changes into the right lane in front of the truck.",
     [("car", "change_lane_to_right", "front_left"), ("truck", "go_straight", "ego")]),
])
def test_a_named_set_of_tests_is_no_manoeuvre_and_a_lane_after_ahead_of_me_is_the_subjects(prompt, expected):
    assert agents(prompt) == expected


def test_a_bug_ticket_written_on_one_line_is_read_for_its_repro_only():
    assert agents("No spray from truck tyres on wet road. Repro: rural road with one lane each way, no junctions. "
                  "Ego follows a cyclist while a truck comes the other way. Expected: spray behind the truck's "
                  "wheels. Actual: no spray at all, and the truck's wheels don't turn.") == [
        ("car", "go_straight", "ego"), ("cyclist", "go_straight", "front"), ("truck", "go_straight", "front_left")]


@pytest.mark.parametrize("prompt, expected", [
    ("The ego follows a lorry. Students may choose the lorry's speed, and students who wish to may consider rain.",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "front")]),
    ("The ego waits at the crossing. Pedestrians should cross in front of the ego.",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
      ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("A driver clipped a cyclist on the lane. Dozens of cyclists use the lane every day.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]),
])
def test_people_told_what_they_may_do_and_dozens_said_of_every_day_are_no_agents(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("The farm track comes out onto the main road at a stop sign, so I've stopped there in the truck with a tractor "
     "on the back. Van waiting on the road to my left. Then I went straight across once it was clear.",
     [[("ego", "stop", None), ("car", "stop", "road_of_left_turn")], [("ego", "go_straight", None)]]),
])
def test_a_vehicle_on_the_back_is_a_load_and_the_truck_the_speaker_sits_in_is_the_ego(prompt, expected):
    assert stages(prompt) == expected
    assert lower_prompt(prompt, "offline").scenario.stages[0].agents[0].type == "truck"


def test_a_queue_said_with_the_egos_wait_the_man_in_the_van_and_asking_after_someone():
    assert stages("Dear Sylvia, you asked after my driving, so I shall be honest. I was waiting at the red light "
                  "with a taxi in front of me and a white van behind. Then the light went green and I went straight "
                  "on across the junction, and the young man in the van leaned on his horn.") == [
        [("ego", "stop", None), ("car", "stop", "front"), ("car", "stop", "back")], [("ego", "go_straight", None)]]


def test_a_report_forms_vehicle_field_names_the_ego():
    lowered = lower_prompt("Vehicle: Iveco 18 tonner. Location: A38 southbound. What happened: the car in front of "
                           "me stopped suddenly and I stopped behind it.", "offline")
    assert [(a.type, a.action, a.relative_to_ego) for a in lowered.scenario.agents()] == [
        ("truck", "stop", None), ("car", "stop", "front")]


def test_a_diagrams_highlighted_vehicle_is_the_ego_and_a_drivers_handbook_no_agent():
    lowered = lower_prompt("This diagram from the bus driver's handbook shows the highlighted coach on a dual "
                           "carriageway. The coach moves over to the left lane to pass a slow lorry ahead.", "offline")
    ego = lowered.scenario.stages[0].agents[0]
    assert (ego.type, ego.action) == ("bus", "change_lane_to_left")
    assert [a.type for a in lowered.scenario.agents()] == ["bus", "truck"]


def test_a_crash_databases_participant_is_the_one_its_bracket_names():
    assert agents("Vehicle 1 (passenger car) was travelling straight. Participant 3 (pedestrian, 9 years) ran across "
                  "the road in front of V1.") == [("car", "go_straight", "ego"),
                                                  ("pedestrian", "cross_the_road", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("Vehicle 1 (passenger car) was travelling straight through a crossroads. Vehicle 2 (pickup truck) approached "
     "from the road on the left. The front of V2 struck the left side of V1.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]),
    ("I was waiting to turn right into Church Street. Then, as I went round into Church Street, two ladies stepped "
     "off the kerb and started across it.", [("car", "stop", "ego"), ("car", "turn_right", "ego"),
                                             ("pedestrian", "cross_the_road", "at_the_destination"),
                                             ("pedestrian", "cross_the_road", "at_the_destination")]),
])
def test_the_front_of_a_vehicle_is_no_place_and_going_round_into_a_street_is_a_turn(prompt, expected):
    assert agents(prompt) == expected


def test_one_pulled_up_behind_a_vehicle_on_the_shoulder_is_on_it_too_and_needs_no_lane():
    lowered = lower_prompt("A broken-down lorry on the hard shoulder just ahead on my left with a cop car pulled up "
                           "behind it.", "offline").scenario
    assert lowered.road.lanes == 1
    assert [(a.type, a.road_type) for a in lowered.agents() if not a.is_ego] == [("truck", "shoulder"),
                                                                               ("police", "shoulder")]


@pytest.mark.parametrize("prompt, expected", [
    ("Lady rang in about a flat battery, so I'm turning left into Albert Street in the truck, and there's a "
     "delivery van stopped just round the corner in the street I'm turning into.",
     [("car", "stop", "at_the_destination"), ("truck", "turn_left", "ego")]),
    ("A Ford turned left across my path. My daughter was a rear-seat passenger and reports no injuries.",
     [("car", "go_straight", "ego"), ("car", "turn_left", "road_of_straight")]),
])
def test_a_caller_and_a_passenger_are_no_one_on_the_road(prompt, expected):
    assert agents(prompt) == expected


def test_a_text_opening_on_a_report_it_comes_from_still_opens_on_its_bus():
    assert stages("This one's off an incident report. Single-decker on a high street coming up to a zebra crossing. "
                  "A woman is at the kerb waiting to go, so the bus stops for her.") == [
        [("ego", "stop", None), ("pedestrian", "on_the_sidewalk", "near_the_crosswalk")]]


@pytest.mark.parametrize("prompt, expected", [
    ("Hi all, I'm trying to set up a cut-in in esmini. The ego drives in the right lane and a white SUV a bit ahead "
     "of it in the middle lane cuts in right in front of the ego. I tried a LaneChangeAction with a relative "
     "target lane but the SUV just drifts off the road.",
     [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]),
    ("Static obstacle. A truck stands in the ego lane 80 m ahead. Ego performs LaneChangeAction to the left lane.",
     [("car", "change_lane_to_left", "ego"), ("truck", "stop", "front")]),
    ("The ego stops at its stop sign and a car from the right turns left in front of it. How do I start the ego's "
     "second maneuver when the car has gone?", [("car", "stop", "ego"), ("car", "turn_left", "road_of_right_turn")]),
])
def test_a_scenario_formats_element_tried_and_a_scene_set_up_are_the_tool_talked_about(prompt, expected):
    assert agents(prompt) == expected


def test_a_phone_transcripts_speaker_labels_are_no_agents():
    assert agents("Agent: Okay, can you tell me what happened?\nCaller: Yeah, so, um, I was stopped at a red light, "
                  "and a city bus behind me just didn't stop and went right into the back of me.\nAgent: Was anyone "
                  "else involved?\nCaller: No, just me and the bus.") == [("bus", "go_straight", "back"),
                                                                            ("car", "stop", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Stop 1: Pupil turns left at the T-junction; a bus comes from the right.",
     [("bus", "go_straight", "road_of_right_turn"), ("car", "turn_left", "ego")]),
    ("Stop 7: puffin crossing, evening lesson. Pupil approaches on amber, then stops at the stop line while an "
     "elderly man crosses.", [("car", "go_straight", "ego"), ("car", "stop", "ego"),
                             ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("A pupil crosses the road in front of the ego.", [("car", "go_straight", "ego"),
                                                       ("pedestrian", "cross_the_road", "front")]),
])
def test_a_learner_who_drives_is_at_the_wheel_and_a_pupil_who_crosses_is_on_foot(prompt, expected):
    assert agents(prompt) == expected


def test_a_short_heading_names_its_case_and_crossing_outside_a_crosswalk_puts_none_there():
    lowered = lower_prompt("Pedestrian crossing outside a crosswalk. Our vehicle is driving along a street when a "
                           "pedestrian crosses the road ahead.", "offline").scenario
    assert [(a.type, a.action, a.relative_to_ego) for a in lowered.agents()] == [
        ("car", "go_straight", None), ("pedestrian", "cross_the_road", "front")]
    assert "crosswalk" not in lowered.road.required_objects


@pytest.mark.parametrize("prompt, expected", [
    ("UC-12 Unprotected left turn. Actor: the automated vehicle (AV); the safety driver monitors. Preconditions: "
     "the AV is waiting at the stop line on a green light. Main flow: 1. An oncoming car goes straight through the "
     "intersection. 2. Once it has cleared, the AV turns left.",
     [("car", "go_straight", "road_of_straight"), ("car", "stop", "ego"), ("car", "turn_left", "ego")]),
    ("Our vehicle is following a sport utility vehicle when the SUV suddenly brakes to a halt.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
])
def test_a_use_cases_actor_is_the_ego_and_a_body_spelt_out_is_its_abbreviation(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("At the roundabout I took the exit to the right in the patrol car. A motorbike on the road I was heading into "
     "was riding towards the roundabout.", [("motorcycle", "go_straight", "at_the_destination"),
                                           ("police", "turn_right", "ego")]),
    ("Stop 5: crossroads, traffic lights. Pupil turns right on the green. There's usually a jogger crossing the "
     "road she's turning into as well.", [("car", "turn_right", "ego"),
                                          ("pedestrian", "cross_the_road", "at_the_destination")]),
])
def test_the_road_the_one_at_the_wheel_heads_or_turns_into_is_the_destination(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, lanes", [
    ("Queens Road is a single carriageway. A van is parked on the nearside ahead; I pulled out to pass it and an "
     "Audi came towards me.", 1),
    ("It's pretty narrow, one lane each way. A box truck was parked on my right and I squeezed past it.", 1),
    ("A three-lane motorway: I pulled out to pass a parked van.", 3),
])
def test_a_road_said_to_have_one_lane_each_way_gets_no_second_lane_from_a_pass(prompt, lanes):
    assert road(prompt).lanes == lanes


def test_a_pub_named_by_a_colour_is_no_signal_and_no_signs_is_no_limit():
    lowered = lower_prompt("The crossroads by the Red Lion has no signs and no lights. A car turns left.", "offline")
    assert lowered.scenario.road.required_signals == ()
    assert not any("speed limit" in n for n in lowered.notes)


def test_a_red_light_violation_by_crossing_traffic_puts_no_crosswalk_there():
    assert road("Red-light violation by crossing traffic. Our vehicle proceeds straight through a signalized "
                "intersection on a green light.").required_objects == ()


@pytest.mark.parametrize("prompt, expected", [
    ("Quiet one today. One car all morning and it stopped for me and the two Patel girls at the crossing.",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
      ("pedestrian", "cross_the_road", "near_the_crosswalk"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("I was stationary at a red light at a crossroads. Then I turned right through the red. A bus coming from the "
     "road on my left had stopped for me.", [("bus", "stop", "road_of_left_turn"), ("car", "stop", "ego"),
                                            ("car", "turn_right", "ego")]),
])
def test_a_speaker_who_sees_people_over_a_crossing_is_on_foot_and_a_driver_stopped_for_is_not(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "Doing 65 in the right lane and some four-wheeler in the left lane dives in right in front of my bumper.",
    "I'm in lane one on the limiter at 52. A Merc in lane two just ahead of me cuts straight across my front.",
])
def test_a_speaker_who_talks_as_a_truck_driver_drives_a_truck(prompt):
    assert lower_prompt(prompt, "offline").scenario.stages[0].agents[0].type == "truck"


def test_a_car_driver_is_no_trucker_for_a_trailer_towed_by_another():
    assert lower_prompt("I was driving home when a car towing a trailer pulled out in front of me.",
                        "offline").scenario.stages[0].agents[0].type == "car"


def test_a_person_in_a_reported_question_is_no_one_on_the_road():
    assert agents("I was driving through town. My son asked why the man was so angry. A bus comes the other way.") \
        == [("bus", "go_straight", "front_left"), ("car", "go_straight", "ego")]


def test_a_subjectless_opening_says_where_the_speaker_sits_even_with_what_they_were_doing_after():
    lowered = lower_prompt("Sat at the crossroads in the lorry waiting to go, and an ambulance comes tearing "
                           "across from the left on blue lights. I stayed put till it was gone.", "offline")
    assert [(a.type, a.action, a.relative_to_ego) for a in lowered.scenario.stages[0].agents] == [
        ("truck", "stop", None), ("ambulance", "go_straight", "road_of_left_turn")]


def test_a_person_who_drives_their_own_vehicle_is_its_driver_not_on_foot():
    assert agents("A teenager was driving his Corsa too fast on the bypass when he hit a van coming the other way.") \
        == [("car", "go_straight", "ego"), ("car", "go_straight", "front_left")]


@pytest.mark.parametrize("prompt, expected", [
    ("A car ran the red light from my left and I stopped. I called an ambulance for the other driver.",
     [("car", "go_straight", "road_of_left_turn"), ("car", "stop", "ego")]),
    ("A car ran the red light from my left and I stopped. No EMS needed.",
     [("car", "go_straight", "road_of_left_turn"), ("car", "stop", "ego")]),
])
def test_help_only_called_for_is_no_agent(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A van cut in front of me, driving like a taxi driver.", [("car", "change_lane_to_right", "front_left"),
                                                               ("car", "go_straight", "ego")]),
    ("A car pulled out in front of me and stopped. It sounded like a truck hitting a wall.",
     [("car", "block_the_ego", "front"), ("car", "go_straight", "ego")]),
    ("I'd like a bus coming the other way while I turn left.", [("bus", "go_straight", "road_of_straight"),
                                                                ("car", "turn_left", "ego")]),
])
def test_a_vehicle_after_like_is_a_comparison_unless_it_is_wanted(prompt, expected):
    assert agents(prompt) == expected


def test_the_one_who_asks_for_a_parked_vehicle_does_not_park():
    assert agents("I would like a truck parked on the right.") == [("car", "go_straight", "ego"),
                                                                    ("truck", "stop", "front_right")]


def test_a_driver_who_tells_of_the_lollipop_lady_is_still_the_driver():
    lowered = lower_prompt("I was stopped at the red at the crossing outside St Mary's while the lollipop lady took "
                           "four little ones across. Then a moped came whizzing past me.", "offline")
    ego = lowered.scenario.stages[0].agents[0]
    assert (ego.type, ego.action) == ("car", "stop")


@pytest.mark.parametrize("prompt", [
    "Two lads dash onto the zebra crossing in front of me. The two lads run out onto the crossing.",
    "Two kids are on the pavement, one of them in red. The two kids cross the road in front of me.",
])
def test_a_counted_group_named_again_with_its_count_is_the_same_group(prompt):
    people = [a for a in agents(prompt) if a[0] == "pedestrian"]
    assert len(people) == 2 and all(a[1] == "cross_the_road" for a in people)


def test_one_of_them_described_leaves_the_group_its_count():
    assert len([a for a in agents("Two kids are on the sidewalk, one of them holding a ball.")
                if a[0] == "pedestrian"]) == 2


def test_a_make_named_again_bare_with_its_place_is_the_same_vehicle():
    assert agents("This guy in a white Silverado pickup cut me off. Silverado in the right lane swerves into my "
                  "lane.") == [("car", "block_the_ego", "right"), ("car", "go_straight", "ego")]


def test_a_chapter_line_in_the_third_person_goes_on_with_the_one_before():
    prompt = ("0:04 - Cruising in the right lane\n0:09 - Gray Tacoma pickup riding next to me in the left lane\n"
              "0:20 - He swerves in front of me and stops dead in my lane\n0:32 - Sits there honking\n")
    assert ("car", "go_straight", "ego") in agents(prompt)



def test_the_vehicle_a_complaint_opens_by_owning_is_the_ego_and_so_is_the_vehicle_after():
    lowered = lower_prompt("I OWN A 2022 GMC TERRAIN. I WAS APPROACHING A ROUNDABOUT WITH A BOX TRUCK FOLLOWING CLOSE "
                           "BEHIND ME. THEN THE VEHICLE BRAKED BY ITSELF TO A COMPLETE STOP.", "offline")
    first, second = lowered.scenario.stages
    assert [(a.type, a.action, a.relative_to_ego) for a in first.agents] == [
        ("car", "go_straight", None), ("truck", "go_straight", "back")]
    assert [(a.name, a.action) for a in second.agents] == [("ego", "stop")]


def test_the_one_a_text_opens_on_by_an_unknown_noun_is_the_ego_when_named_again():
    lowered = lower_prompt("THE CONTACT OWNS A 2020 NISSAN ROGUE. THE CONTACT STATED THAT WHILE DRIVING STRAIGHT, A "
                           "PEDESTRIAN WAS CROSSING IN THE CROSSWALK. THE CONTACT THEN BRAKED TO A STOP.", "offline")
    assert [(a.name, a.action) for a in lowered.scenario.stages[1].agents] == [("ego", "stop")]


def test_a_verb_form_of_a_word_for_a_driver_names_no_one():
    assert agents("The lane keeping assist jerked my vehicle toward the center line as an oncoming motorcycle was "
                  "passing.") == [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "front_left")]


def test_a_vehicle_not_seen_but_said_to_approach_is_there():
    assert ("car", "go_straight", "road_of_left_turn") in agents(
        "While turning left at the junction I did not see a van approaching from the left.")
    assert agents("I didn't see a single car all morning.") == [("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("I'm going straight through a green with a Tesla in front of me. Tesla just hooks a right across the cyclist.",
     ("car", "turn_right", "front")),
    ("A Jetta in the lane to my left dives right across in front of me.", ("car", "change_lane_to_right", "left")),
    ("Some Audi in the lane to my right decides to dive across in front of me.",
     ("car", "change_lane_to_left", "right")),
])
def test_slang_manoeuvres(prompt, expected):
    assert expected in agents(prompt)


def test_an_unknown_make_before_a_lane_or_a_manoeuvre_is_a_car():
    assert agents("I'm in the middle of three lanes. A Commodore in the left lane just ahead of me dives across into "
                  "my lane.") == [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]
    assert agents("The driver made an evasive lane change to the left.") == [("car", "change_lane_to_left", "ego")]


def test_a_bare_plural_said_before_one_of_its_kind_is_named_speaks_in_general():
    assert agents("Pedestrians step off the kerb here without looking. Yesterday an elderly man crossed in front of "
                  "me.") == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]


def test_a_driver_a_case_is_about_is_the_ego_and_what_it_may_not_see_acts():
    assert agents("An eastbound driver on Park Road may not see a fire engine coming out of the station on the right "
                  "and turning right across their path.") == [("car", "go_straight", "ego"),
                                                              ("firetruck", "turn_right", "road_of_right_turn")]


def test_a_numbered_lane_said_before_anyone_is_named_is_the_tellers():
    assert agents("Approaching in lane 2 in the TOV, saw a van stopped in lane 1 ahead.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front_left")]
    assert agents("Attended lane 1 obstruction. A van stopped in lane 1 ahead of us.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front")]


def test_a_teller_on_the_way_over_is_a_crossing_pedestrian_and_the_vehicle_met_is_the_ego():
    assert agents("I was halfway over the zebra crossing on Mill Road in my chair when a silver hatchback pulled up "
                  "and waited for me.") == [("car", "stop", "ego"),
                                            ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_a_list_of_kinds_with_no_verb_and_a_plural_after_one_of_its_kind_speak_in_general():
    assert agents("Watch as the car turns left, and the system picks out a cyclist crossing the road we're turning "
                  "into. Pedestrians, cyclists, everyone: seen.") == [
        ("car", "turn_left", "ego"), ("cyclist", "cross_the_road", "at_the_destination")]


def test_a_key_said_to_have_no_value_names_no_agent():
    assert agents("ego: straight. oncoming: 2 cars. pedestrians: none.") == [
        ("car", "go_straight", "ego"), ("car", "go_straight", "front_left"), ("car", "go_straight", "front_left")]


def test_family_said_to_be_in_the_car_ride_with_the_speaker():
    assert agents("A truck in the left lane cut in front of me, I was with my wife and kids in the car.") == [
        ("car", "go_straight", "ego"), ("truck", "change_lane_to_right", "left")]


@pytest.mark.parametrize("prompt, expected", [
    ("I was in the middle lane and a truck that was in the left lane entered in my front without put the arrow.",
     ("truck", "change_lane_to_right", "left")),
    ("At the four-way stop a Camry across from me was waiting its turn.", ("car", "stop", "road_of_straight")),
])
def test_calques_and_idioms_of_waiting_and_cutting_in(prompt, expected):
    assert expected in agents(prompt)


def test_a_speaker_who_puts_out_a_stop_arm_drives_a_bus_unless_the_arm_is_another_bus():
    assert agents("I was stopped at the Oakwood Dr stop, red lights flashing and stop arm out. A black pickup coming "
                  "the other way drove right past my arm.") == [("bus", "stop", "ego"),
                                                                ("car", "go_straight", "front_left")]
    assert ("car", "stop", "ego") in agents("I was stopped behind a school bus with its red lights flashing and the "
                                            "stop arm out.")


def test_a_posts_title_told_again_in_its_body_is_one_agent():
    assert agents("Jeep tried to merge INTO me at a red light. OP here, on my motorcycle. Sitting at a red in the left "
                  "lane, Jeep Wrangler in the right lane next to me just starts drifting over into my lane.") == [
        ("car", "change_lane_to_left", "right"), ("motorcycle", "stop", "ego")]


def test_someone_else_on_the_bike_is_not_the_speakers_bike():
    assert agents("I'm going straight. A cyclist is riding on the shoulder ahead on my right. The guy on the bike "
                  "deserves a medal.") == [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front_right")]


def test_a_lane_change_given_up_is_not_made():
    assert agents("I went to move into the right lane, but a pickup was in my blind spot, so I aborted and stayed in "
                  "my lane.")[-1] == ("car", "go_straight", "ego")


def test_both_after_two_named_in_the_clause_is_those_two():
    assert agents("The ego is in the middle lane. A car from the left lane and a motorcycle from the right lane both "
                  "cut into the ego's lane.") == [("car", "change_lane_to_right", "left"),
                                                  ("car", "go_straight", "ego"),
                                                  ("motorcycle", "change_lane_to_left", "right")]


def test_school_children_and_a_test_applicant():
    assert agents("The crossing guard walked out onto the crosswalk with three kindergartners and I stopped for "
                  "them.").count(("pedestrian", "cross_the_road", "near_the_crosswalk")) == 4
    assert ("car", "turn_right", "ego") in agents("Applicant turned right on red without first stopping.")


def test_a_log_entry_is_about_the_vehicle_it_opens_on_and_places_the_others_by():
    assert agents("Cam 9, 21:40: Dark grey Audi A4 parked at the curb outside the pizza place, hazards on. Patrol car "
                  "pulls up behind it and stops.") == [("car", "stop", "ego"), ("police", "stop", "back")]


def test_the_ego_said_first_in_line_is_no_second_car():
    assert agents("Ego car is waiting at red signal, as first car. Fire engine with siren comes from right side "
                  "road.") == [("car", "stop", "ego"), ("firetruck", "go_straight", "road_of_right_turn")]


def test_he_or_she_names_one_not_a_group():
    found = agents("At the four-way stop by the library he waited for two older ladies to cross on the crosswalk. "
                   "Then he went straight through.")
    assert found.count(("pedestrian", "cross_the_road", "near_the_crosswalk")) == 2


def test_a_manoeuvre_made_with_not_before_its_verb_is_not_made():
    assert agents("The ego goes straight, he not make U-turn there.") == [("car", "go_straight", "ego")]


def test_vehicles_said_with_no_count_doing_nothing_are_no_agents():
    assert agents("My driver turned right. Three teenagers were standing on the sidewalk to our right throwing "
                  "snowballs at cars.") == [("car", "turn_right", "ego")] + [
        ("pedestrian", "on_the_sidewalk", "right")] * 3


def test_the_driver_when_the_only_vehicle_is_the_egos_is_its_driver():
    assert agents("The red car is driving down the street when a small boy runs out into the road from the right. "
                  "The driver could not have seen the boy.") == [("car", "go_straight", "ego"),
                                                                 ("pedestrian", "cross_the_road", "front_right")]


def test_the_car_in_a_text_with_no_other_vehicle_is_the_ego():
    lowered = lower_prompt("A pedestrian starts across the ladder crosswalk ahead. Watch as NightVision picks her out. "
                           "Then it brings the car to a gentle stop.", "offline")
    assert [(a.type, a.action) for a in lowered.scenario.stages[0].agents if a.is_ego] == [("car", "go_straight")]
    assert not [a for stage in lowered.scenario.stages for a in stage.agents if a.type == "car" and not a.is_ego]


def test_a_turn_said_bare_after_waiting_to_turn_is_the_turn_waited_for():
    assert ("car", "turn_right", "road_of_straight") in agents(
        "I was going straight through the lights, and a car coming from the other direction was waiting to turn right "
        "across me, and he just turned, right in front of me.")


def test_lights_going_is_no_one_going_and_there_was_opens_its_own_clause():
    assert agents("I was in the right lane and there was a state trooper stopped on the shoulder up ahead on the "
                  "right with his lights going.") == [("car", "go_straight", "ego"),
                                                      ("police", "stop", "front_right")]


def test_the_moped_a_speaker_is_on_is_the_egos():
    assert agents("on the moped doing food runs tonight. some guy double parked right in front of me so I went round "
                  "him into the left lane.") == [("car", "stop", "front"), ("motorcycle", "change_lane_to_left", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Our car drives straight through a four-way stop while a cyclist rides straight across from the road on the right.",
     ("cyclist", "go_straight", "road_of_right_turn")),
    ("At the crossroads a cyclist rides across from the right in front of me.",
     ("cyclist", "cross_the_road", "road_of_right_turn")),
])
def test_a_cyclist_straight_across_from_a_side_road_goes_on_along_its_own_road(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt", [
    "stuck behind a plow truck doing 15, two kids walking on the sidewalk on my right",
    "I was stuck behind a car towing a caravan, crawling along.",
])
def test_stuck_behind_one_still_moving_is_no_stop(prompt):
    assert ("car", "go_straight", "ego") in agents(prompt)


@pytest.mark.parametrize("prompt", [
    "There was a tractor-trailer on the right shoulder of I-95.",
    "There is a disabled truck on the right shoulder, no flashers.",
])
def test_a_vehicle_on_the_shoulder_with_nothing_said_it_does_stands_there_ahead(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("truck", "stop", "front_right")]


def test_an_absolute_after_a_comma_is_the_things_and_the_side_ends_at_the_comma():
    assert ("police", "stop", "front_left") in agents(
        "There is a patrol car stopped on the hard shoulder up ahead on our left, light bar going.")
    assert agents("A car stopped ahead of me, hazards blinking.") == [("car", "go_straight", "ego"),
                                                                     ("car", "stop", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("In thick fog I drove home. Suddenly stood a car without lights still on the road in front of me.",
     ("car", "stop", "front")),
    ("I drove in the city. Then crosses a boy on his bike the road from the right, without looking.",
     ("cyclist", "cross_the_road", "front_right")),
])
def test_verb_second_order_with_no_place_first_has_its_subject_after_the_verb(prompt, expected):
    found = agents(prompt)
    assert expected in found and ("car", "go_straight", "ego") in found


def test_an_order_to_come_across_someone_is_still_the_egos():
    assert agents("Came across a cyclist on the bridge.") == [("car", "go_straight", "ego"),
                                                             ("cyclist", "go_straight", "front")]


def test_standing_still_in_a_lane_is_at_the_wheel_not_on_foot():
    assert agents("There was a traffic jam. I stood still in the right lane. Over the hard shoulder an ambulance came "
                  "from behind past us.") == [("ambulance", "go_straight", "back_right"), ("car", "stop", "ego")]


def test_a_videos_time_stamp_is_no_count():
    assert agents("0:42 the van just swings into my lane from the left lane.") == [
        ("car", "change_lane_to_right", "left"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, ego", [
    ("OP is the one driving the 40-tonne truck. A car cuts in front of him.", "truck"),
    ("0:42 a van swings into OP's lane from the left lane.", "car"),
])
def test_the_original_poster_is_the_ego(prompt, ego):
    found = agents(prompt)
    assert (ego, "go_straight", "ego") in found and len([a for a in found if a[2] == "ego"]) == 1


def test_the_co_op_is_a_shop():
    assert agents("Two pedestrians cross in front of me outside the Co-op.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front"),
        ("pedestrian", "cross_the_road", "front")]


def test_a_cab_cam_is_no_cab_and_under_ones_nose_is_ahead():
    assert agents("Watch my cab cam: a hatchback in the right lane cuts left right under my nose.") == [
        ("car", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]


def test_help_asked_for_by_a_caller_is_no_agent():
    assert agents("CALLER: I need police and an ambulance. / OPERATOR: Where are you? / CALLER: I'm stopped at the "
                  "red light in my car.") == [("car", "stop", "ego")]


def test_following_after_the_copula_is_a_verb():
    assert agents("Ego car is following city bus in right lane.") == [("bus", "go_straight", "front"),
                                                                     ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Three-lane motorway, I'm in the middle lane. HGV at my seven the whole time, holding its lane.",
     ("truck", "go_straight", "back_left")),
    ("Motorway, two lanes. Lorry at my twelve, steady.", ("truck", "go_straight", "front")),
    ("Motorway, two lanes. Car at my three, level with me, pulls across into my lane.",
     ("car", "change_lane_to_left", "right")),
    ("Side road, yield sign at the end, I want to turn right. Car at my nine o'clock coming along the main road.",
     ("car", "go_straight", "road_of_left_turn")),
])
def test_a_place_told_by_the_clock(prompt, expected):
    assert expected in agents(prompt)


def test_a_time_on_the_clock_is_no_place():
    assert agents("At eight o'clock a van pulled out in front of me.") == [
        ("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]


def test_scots_spellings_are_read_as_the_english_they_are():
    assert agents("Ah wis sat at a red light when a polis car came up behind me wi the blues oan. Then ah nudged ower "
                  "intae the left lane tae let it through.") == [
        ("car", "change_lane_to_left", "ego"), ("car", "stop", "ego"), ("police", "go_straight", "back")]


@pytest.mark.parametrize("prompt, expected", [
    ("Ootside the shop there's a zebra. The motor behind me had tae slam on.", ("car", "stop", "back")),
    ("At night a machine is stopped on the shoulder on the right in front of me.",
     ("car", "stop", "front_right")),
])
def test_a_motor_and_a_machine_are_cars(prompt, expected):
    assert expected in agents(prompt)


def test_the_machine_the_speaker_stops_is_the_egos():
    assert agents("At the light I stop the machine on the stop line.") == [("car", "stop", "ego")]


def test_going_in_my_lane_is_going_into_it():
    assert ("car", "change_lane_to_right", "left") in agents("A black Audi in the left lane enters in my lane.")
    assert agents("A bus is stopped in my lane.") == [("bus", "stop", "front"), ("car", "go_straight", "ego")]


def test_a_vehicle_that_emerges_in_the_oncoming_lane_is_oncoming_with_no_junction():
    lowered = lower("A van emerges from the mist in the oncoming lane and passes.")
    assert [(a.type, a.relative_to_ego) for a in lowered.scenario.agents() if not a.is_ego] == [("car", "front_left")]
    assert not lowered.scenario.road.junction


def test_a_bus_driver_moving_off_from_the_stop_is_at_the_wheel():
    assert agents("I am a bus driver. I was moving off from the bus stop and changing out to the right lane, but a BMW "
                  "came from behind on my right side.") == [("bus", "change_lane_to_right", "ego"),
                                                            ("car", "go_straight", "back_right")]


def test_a_captions_point_of_view_is_the_egos():
    assert agents("POV: ur turning left at the lights and the dude coming the other way in a lifted pickup floors it "
                  "thru the intersection") == [("car", "go_straight", "road_of_straight"), ("car", "turn_left", "ego")]
    assert ("car", "go_straight", "ego") not in agents("SV: a truck turning left. POV: a silver sedan traveling north.")


@pytest.mark.parametrize("later", ["An ambulance arrived ten minutes later.", "A police officer turned up later."])
def test_help_that_arrives_after_the_collision_is_no_agent(later):
    assert agents("A van pulled out in front of me and I hit it. " + later) == [
        ("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]


def test_turning_up_a_street_is_still_a_turn():
    assert ("car", "turn_left", "ego") in agents("A car turned up Elm Street.")


@pytest.mark.parametrize("habit", ["Cyclists use this road a lot too.",
                                   "There's usually a lollipop lady there in the mornings."])
def test_who_usually_is_there_is_no_agent_of_a_scene_told_in_the_past(habit):
    assert agents("A van pulled out in front of me. " + habit) == [
        ("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]


def test_who_usually_is_there_is_the_scene_of_a_lesson_plan():
    assert ("pedestrian", "cross_the_road", "at_the_destination") in agents(
        "Stop 5: crossroads, traffic lights. Pupil turns right on the green. There's usually a jogger crossing the "
        "road she's turning into as well.")


@pytest.mark.parametrize("prompt", ["A car coming the other way drifted onto my side of the road.",
                                    "An oncoming truck came over onto our side on the bend."])
def test_onto_my_side_of_the_road_is_into_the_egos_lane(prompt):
    assert [a[1:] for a in agents(prompt) if a[2] != "ego"] == [("change_lane_to_left", "front_left")]


@pytest.mark.parametrize("prompt, expected", [
    ("Pt 52M rider of motorcycle, approx 40mph on main road at dusk. Car coming the other way turned right across "
     "his path into a side road.", [("car", "turn_right", "road_of_straight"), ("motorcycle", "go_straight", "ego")]),
    ("Minor injuries: 28F driver, stationary at red lights, shunted from behind by a taxi. Declined conveyance.",
     [("car", "go_straight", "back"), ("car", "stop", "ego")]),
    ("8yo F, pedestrian, ran out from between parked cars on the left and was struck by a car travelling approx "
     "20mph. Pt GCS 14.", [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left")]),
])
def test_a_handover_tells_the_scene_from_the_patients_side(prompt, expected):
    assert agents(prompt) == expected


def test_an_age_is_no_count_and_a_distance_stays_a_distance():
    assert agents("Pt 34M, restrained driver of car travelling approx 30mph, struck by a van pulling out of a side "
                  "road on his left.") == [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]
    assert agents("A car is stopped 50 m ahead.") == [("car", "go_straight", "ego"), ("car", "stop", "front")]


@pytest.mark.parametrize("prompt", ["I was stationary at red lights and was rear-ended by a taxi.",
                                    "I was stationary at the lights when a taxi shunted me from behind."])
def test_who_rear_ends_the_ego_comes_from_behind(prompt):
    assert agents(prompt) == [("car", "go_straight", "back"), ("car", "stop", "ego")]


def test_a_police_logs_shorthand():
    assert agents("Dusk, wet road. RP in red Yaris at give way sign, waiting to turn R onto B4455. HGV approaching from "
                  "her R, P/C from her L. Once both had passed, RP turned R.") == [
        ("car", "stop", "ego"), ("car", "turn_right", "ego"), ("cyclist", "go_straight", "road_of_left_turn"),
        ("truck", "go_straight", "road_of_right_turn")]


def test_a_marked_car_is_a_police_car():
    assert agents("A marked car came up behind me with its lights on.") == [("car", "go_straight", "ego"),
                                                                          ("police", "go_straight", "back")]


@pytest.mark.parametrize("prompt, expected", [
    ("A car entered my lane from the left.", ("car", "change_lane_to_right", "front_left")),
    ("A bus is stopped ahead, so I enter the right lane.", ("car", "change_lane_to_right", "ego")),
    ("na so one danfo just swerve enter my lane from the lane by my left.", ("bus", "change_lane_to_right", "left")),
])
def test_entering_a_lane(prompt, expected):
    assert expected in agents(prompt)


def test_entering_the_same_lane_as_a_turning_ego_is_no_cut_in():
    assert not [a for a in agents("The ego vehicle is preparing to make a right turn while another vehicle from the "
                                  "left also attempts to enter the same lane.") if a[1].startswith("change_lane")]


@pytest.mark.parametrize("prompt, expected", [
    ("One keke was parked on the shoulder by my right, a small distance ahead of me.",
     ("motorcycle", "stop", "front_right")),
    ("The jeepney in front suddenly stopped to load passengers.", ("bus", "stop", "front")),
    ("Two okadas dey behind me for my lane.", ("motorcycle", "go_straight", "back")),
])
def test_west_african_and_philippine_vehicles(prompt, expected):
    assert expected in agents(prompt)


def test_holding_the_middle_lane_is_no_stop_and_an_aside_of_feeling_is_no_one():
    assert ("car", "go_straight", "ego") in agents("Three lanes each way, I held the middle, steady, slow; a coupe on "
                                                  "my right cut in ahead.")
    assert ("car", "go_straight", "ego") in agents("Two lanes my way, a red convertible, to my surprise, swerved from "
                                                  "the left lane and stopped dead in front of me.")
    assert agents("I was held at the lights.") == [("car", "stop", "ego")]


def test_the_vehicle_the_speaker_took_is_the_egos():
    assert agents("Early morning I took the pickup down to the bottom field. Round the corner there's a hatchback "
                  "stuck sideways, blocking the whole lane.") == [("car", "block_the_ego", "front"),
                                                                  ("car", "go_straight", "ego")]


@pytest.mark.parametrize("aside", ["Critical driving error, auto-fail.",
                                   "Our sensors see the pedestrian before a human driver would."])
def test_an_auto_fail_and_a_human_driver_are_no_cars(aside):
    assert agents("A pickup on the cross street to our left turned left. " + aside) == [
        ("car", "go_straight", "ego"), ("car", "turn_left", "road_of_left_turn")]


def test_vehicles_said_after_the_ones_named_are_those_again():
    assert agents("I was stopped at the sign when a car from my right and a van from the opposite side both went at "
                  "the same time and collided in the middle. Nobody hurt, vehicles blocking the intersection.") == [
        ("car", "go_straight", "road_of_right_turn"), ("car", "go_straight", "road_of_straight"), ("car", "stop", "ego")]


def test_not_making_someone_wait_is_no_stop():
    assert ("police", "go_straight", "back") in agents(
        "A police car with its siren came up behind me; I changed lanes to the right, didn't make it wait, and "
        "watched it pass me.")


@pytest.mark.parametrize("prompt, expected", [
    ("We're tracking a blue hatchback northbound on Main, that's our ego for this one. A white van runs its red.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "front")]),
    ("The black pickup southbound on Elm is our ego, and it's making a right onto 3rd.",
     [("car", "turn_right", "ego")]),
    ("Our ego, a green hatchback in the right lane, is coming up on a tow truck stopped on the right shoulder.",
     [("car", "go_straight", "ego"), ("truck", "stop", "front_right")]),
])
def test_a_vehicle_named_as_the_ego_is_the_ego(prompt, expected):
    assert [(t, a, p) for t, a, p in agents(prompt)] == sorted(expected)


def test_a_place_by_the_ego_does_not_name_it():
    assert ("car", "go_straight", "ego") in agents("A cyclist riding in front of the ego stops. Behind the ego, a "
                                                  "motorcycle keeps coming at the same speed.")


def test_a_thing_said_then_none_is_denied_and_denies_nothing_after():
    found = lower("STREET, CROSSWALK NONE, LIGHT GREEN. MAN CROSS FRONT-OF-ME. ME STOP.").scenario.road
    assert "crosswalk" in found.without_objects and "traffic_light" in found.required_signals
    assert lower("COUNTRY ROAD, NARROW, INTERSECTION NONE. CAR OPPOSITE-DIRECTION COME FAST.").scenario.road.junction \
        is False


def test_a_text_all_in_capitals_has_no_title():
    assert ("motorcycle", "go_straight", "ego") in agents(
        "ME RIDE MOTORCYCLE. INTERSECTION, LIGHT GREEN, ME GO STRAIGHT. CAR OPPOSITE-DIRECTION TURN LEFT "
        "ACROSS FRONT-OF-ME.")


@pytest.mark.parametrize("prompt", [
    "Nothing turns you into a worse driver than an ambulance. I'm in the left lane and one comes up behind me, so I "
    "move over into the right lane like a functioning adult.",
    "A guy on a motorcycle pulls up in the lane to my left at the red and revs it. Buddy, my car has a car seat in "
    "the back.",
])
def test_a_comparison_and_a_car_seat_name_no_one(prompt):
    assert not [a for a in agents(prompt) if a[0] in ("car", "pedestrian") and a[2] != "ego"]


@pytest.mark.parametrize("prompt", [
    "Hazard H-22: pedestrian emerging from behind parked vehicles. Triggering condition: a child steps out between "
    "two parked cars on the right-hand side ahead.",
    "Scenario of pedestrian rush-out. Host vehicle is driving on a narrow road. A child suddenly runs out from the "
    "right side and crosses in front of host vehicle.",
])
def test_a_road_user_in_a_cases_heading_names_the_case(prompt):
    assert [a for a in agents(prompt) if a[0] == "pedestrian"] == [("pedestrian", "cross_the_road", "front_right")]


def test_what_the_tellers_companion_does_is_not_the_egos():
    assert stages("You are driving a car. Your friend is sitting next to you. A bus is in front of you. The bus stops "
                  "at a bus stop. Then you stop behind the bus.") == [
        [("ego", "go_straight", None), ("bus", "stop", "front")], [("ego", "stop", None)]]
    assert ("car", "go_straight", "ego") in agents(
        "I was the front seat passenger in my husband's Honda, in the right-hand lane. A lorry in the left-hand lane "
        "started to come over into our lane.")


@pytest.mark.parametrize("prompt", [
    "I was stopped at a red light waiting to turn right. The guy in the pickup behind me started honking at me to go.",
    "A little old man was crossing really slowly at the crosswalk with the pedestrian light, and two cars behind us "
    "were honking. My driver didn't budge till he was across.",
])
def test_who_honks_behind_a_waiting_ego_waits_too(prompt):
    assert {a for a in agents(prompt) if a[2] == "back"} == {("car", "stop", "back")}


def test_where_after_the_road_turned_into_is_the_destination():
    assert ("car", "stop", "at_the_destination") in agents(
        "The ego turns left into a side road where a delivery van stands parked a short distance beyond the junction.")
    assert ("cyclist", "stop", "at_the_destination") not in agents(
        "I turned left at the junction where a cyclist was waiting.")


def test_the_rider_of_the_motorbike_speaking_rides_it():
    assert ("motorcycle", "go_straight", "ego") in agents("I was the rider of the motorbike. A car pulled out.")


@pytest.mark.parametrize("prompt, expected", [
    ("JOB CARD 20417 - 2016 VW Golf. Customer states vehicle was stationary at a red light when it was struck in the "
     "rear by a bus.", [("bus", "go_straight", "back"), ("car", "stop", "ego")]),
    ("Job card 8107 - 2013 Ford Focus. Customer states he was driving home at night when a man ran out from between "
     "parked cars on the left and he hit him.", [("car", "go_straight", "ego"),
                                                 ("pedestrian", "cross_the_road", "front_left")]),
])
def test_a_job_card_is_told_from_the_customers_vehicle(prompt, expected):
    assert agents(prompt) == expected


def test_a_big_number_before_one_vehicle_names_it():
    assert len(agents("JOB CARD #4471 | 2017 Toyota Camry. Customer states: a white pickup came from the road on "
                      "the left and hit the driver's door.")) == 2


@pytest.mark.parametrize("prompt, expected", [
    ("Manze, a matatu in front of me just stopped in the middle of the road to pick up passengers.",
     ("bus", "stop", "front")),
    ("Hapo Kangemi, a boda boda from the opposite side went straight.", ("motorcycle", "go_straight", "front_left")),
    ("Marshrutka number 7 stays on the bus stop on the right, little before me. When I come close, it suddenly goes "
     "out from the stop into my lane.", ("bus", "change_lane_to_left", "front_right")),
])
def test_minibuses_and_motorbike_taxis_of_other_countries(prompt, expected):
    assert expected in agents(prompt)


def test_changing_to_my_lane_is_into_it():
    assert ("car", "change_lane_to_left", "right") in agents("A car in the right lane changed to my lane.")


def test_going_round_on_a_narrow_road_with_oncoming_traffic_is_no_lane_change():
    assert ("car", "go_straight", "ego") in agents(
        "On Fore Street the candidate came up behind a bus pulled in at a stop and went round it without checking the "
        "road ahead was clear - an oncoming van had to slow down.")
    assert ("car", "change_lane_to_left", "ego") in agents(
        "A delivery lorry was stopped in my lane, so I went round it.")


def test_an_overtaker_on_a_road_with_oncoming_traffic_comes_from_behind_in_the_egos_lane():
    lowered = lower("Two motorbikes came past me way too fast on the approach to a blind bend, with a logging truck "
                    "coming the other way.")
    assert [a.relative_to_ego for a in lowered.scenario.agents() if a.type == "motorcycle"] == ["back", "back"]
    assert (lowered.scenario.road.lanes or 1) == 1


def test_a_place_said_after_a_comma_places_the_one_just_named():
    assert agents("She was driving down a residential street with two people walking along the pavement on her "
                  "right, a bit ahead.") == [("car", "go_straight", "ego"),
                                             ("pedestrian", "on_the_sidewalk", "front_right"),
                                             ("pedestrian", "on_the_sidewalk", "front_right")]


@pytest.mark.parametrize("after", ["An ambulance was on its way.",
                                   "The ambulance station is just round the corner, so sirens are normal here."])
def test_an_ambulance_on_its_way_or_its_station_is_no_agent(after):
    assert agents("A car pulled out in front of me and hit me. " + after) == [
        ("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]


def test_a_passer_by_who_called_the_police_is_no_agent():
    assert agents("A van pulled out in front of me. A passer-by called the police.") == [
        ("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("before", ["", "I was driving along. "])
def test_the_car_two_cars_ahead_is_another(before):
    assert agents(before + "The car two cars ahead of me slammed on its brakes.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front")]


def test_one_followed_by_another_both_do_what_the_sentence_says_after():
    assert agents("At a roundabout, our vehicle waits at the entry while a car, followed closely by a "
                  "motorcyclist, approaches from our left.") == [
        ("car", "go_straight", "road_of_left_turn"), ("car", "stop", "ego"),
        ("motorcycle", "go_straight", "road_of_left_turn")]


def test_labelled_vehicles_joined_by_and_share_the_verb():
    assert agents("Vehicle 1 (passenger car) waits at the junction. Vehicle 2 (fire engine) and Vehicle 3 (police "
                  "patrol car) approached from the road on the right.") == [
        ("car", "stop", "ego"), ("firetruck", "go_straight", "road_of_right_turn"),
        ("police", "go_straight", "road_of_right_turn")]


def test_stopped_meaning_to_go_straight_then_going_is_two_stages():
    assert stages("The ego had stopped at the stop line, intending to go straight. After the van had passed, the "
                  "ego proceeded straight across.")[0][0] == ("ego", "stop", None)


def test_a_case_numbers_title_line_names_no_agent():
    prompt = ("TC-052: Red-light runner from the left\nPreconditions: Signalised crossroads, midday.\nSteps:\n"
              "1. The SUT goes straight through the junction.\n2. A car coming from the road on the left runs its "
              "red light.")
    assert [a for a in agents(prompt) if a[0] == "pedestrian"] == []


@pytest.mark.parametrize("label", ["TV1", "V2"])
def test_a_label_in_brackets_after_a_vehicle_is_its_name(label):
    assert agents(f"Ego in the middle lane. A white SUV ({label}) drives in the right lane slightly ahead of Ego. "
                  f"{label} cuts into Ego's lane.") == [("car", "change_lane_to_left", "front_right"),
                                                        ("car", "go_straight", "ego")]


@pytest.mark.parametrize("heading", ["Event 7: motorcycle at a junction.", "Abrupt stop of a motorcycle."])
def test_a_road_user_in_a_numbered_or_nominal_heading_is_the_one_told_of_after(heading):
    kinds = [a for a in agents(f"{heading} The ego waits. A motorcycle approaches from the right.")
             if a[0] == "motorcycle"]
    assert len(kinds) == 1


@pytest.mark.parametrize("prevented", ["prevents a lane change to the right", "prevents an immediate lane change"])
def test_a_lane_change_prevented_is_made_by_no_one(prevented):
    assert agents(f"The ego drives in the left lane. A passenger car in the middle lane alongside the ego vehicle "
                  f"{prevented}.") == [("car", "go_straight", "ego"), ("car", "go_straight", "right")]


@pytest.mark.parametrize("prompt", [
    "The ego vehicle turns left from the main road into a side street. A delivery truck is parked in the side "
    "street just beyond the junction.",
    "The participant is stopped at a red light, intending to turn right. A delivery truck is parked in the road "
    "the participant is about to turn into."])
def test_the_road_turned_into_named_again_or_by_a_participant_is_the_destination(prompt):
    assert ("truck", "stop", "at_the_destination") in agents(prompt)


@pytest.mark.parametrize("correction, expected", [
    ("Actually change the van to a pickup.", ("car", "go_straight", "front_left")),
    ("Make the truck a bus.", ("bus", "go_straight", "front_left"))])
def test_a_request_corrected_in_the_same_message_names_one_agent(correction, expected):
    said = agents(f"Country road, no junctions. An oncoming {'van' if 'van' in correction else 'truck'}, and I keep "
                  f"going straight. {correction}")
    assert said == sorted([("car", "go_straight", "ego"), expected])


def test_the_driver_of_the_ego_vehicle_and_neither_road_user_are_no_agents():
    assert agents("The ego vehicle travels in the middle lane. The driver of the ego vehicle is distracted. A cyclist "
                  "rides on the shoulder ahead on the right. Neither road user interacts with the ego.") == [
        ("car", "go_straight", "ego"), ("cyclist", "go_straight", "front_right")]


def test_a_sequence_word_before_anyone_of_the_scene_is_named_opens_no_stage():
    assert len(stages("S5 was suggested by a member of my committee after a near miss she observed. The ego vehicle "
                      "travels in the right lane and changes to the left lane.")) == 1


def test_road_users_in_a_heading_are_the_ones_counted_after():
    said = agents("SignalizedJunctionLeftTurn with pedestrians. The ego vehicle turns left at a signalized "
                  "intersection where two pedestrians are crossing on a ladder crosswalk.")
    assert [a for a in said if a[0] == "pedestrian"] == [("pedestrian", "cross_the_road", "near_the_crosswalk")] * 2


def test_a_red_light_runner_in_a_heading_is_the_case_not_a_pedestrian():
    said = agents("Assignment 5: red-light runner. The ego goes straight through a signalised crossroads on a green "
                  "light. A motorcycle from the road on the left runs its red light at high speed.")
    assert [a for a in said if a[0] == "pedestrian"] == []


def test_road_users_asked_to_be_left_out_are_none():
    said = agents("The ego vehicle turns left at an intersection while two oncoming cars go straight through. This "
                  "is for our planner, so please leave pedestrians out.")
    assert [a for a in said if a[0] == "pedestrian"] == []


@pytest.mark.parametrize("denial", ["The person visible in the driver's seat is our safety operator, not an actor.",
                                    "A man stands on the pavement, but he is not part of the scene."])
def test_one_said_to_be_no_part_of_the_scene_is_no_agent(denial):
    assert agents(f"The ego drives on. {denial}") == [("car", "go_straight", "ego")]


@pytest.mark.parametrize("aside", ["The ambulance crew is not modelled.", "The bus's driver is not modelled.",
                                   "Note that the ambulance is not to be modelled as stopping."])
def test_what_is_not_modelled_of_an_agent_leaves_the_agent(aside):
    assert ("ambulance" if "ambulance" in aside else "bus") in [
        a[0] for a in agents(f"The ego drives on. An ambulance approaches from behind. A bus is stopped ahead. "
                             f"{aside}")]


def test_the_scene_proposed_is_told_from_the_vehicle_proposed():
    assert agents("We propose to test a car travelling along Mill Road as two cyclists cross in front of it from "
                  "the right.") == [("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "front_right"),
                                    ("cyclist", "cross_the_road", "front_right")]


def test_a_scene_asked_for_in_a_titles_question_is_the_one_told_after():
    said = agents("CARLA: make an NPC cut in and stop dead in front of the ego? Scene is a three-lane arterial. The "
                  "ego goes straight in the middle lane, and a black sedan just ahead of it in the left lane swerves "
                  "into its lane and stops, blocking it.")
    assert said == [("car", "block_the_ego", "front_left"), ("car", "go_straight", "ego")]


def test_a_release_number_ends_no_sentence_and_quoted_code_is_no_scene():
    said = agents("How do I get a fire engine to turn left across the ego's path (CARLA 0.9.14)? The ego drives "
                  "straight and a fire engine comes from the road on the right and turns left in front of it. I "
                  "set `ignore_stop_signs=False` and `vehicle.apply_control()` on the RoadRunner map.")
    assert said == [("car", "go_straight", "ego"), ("firetruck", "turn_left", "road_of_right_turn")]
    quoted = road("The ego drives straight. I set `ignore_stop_signs=False` on it.")
    assert quoted.required_signals == () and quoted.required_objects == ()


@pytest.mark.parametrize("prompt", [
    "# Fire engine runs the red. Ego is stopped at a red light; a fire engine from\n# the opposite direction turns "
    "left across ego's path.",
    '"""Fire engine runs the red.\n\nEgo is stopped at a red light; a fire engine from\nthe opposite direction turns '
    'left across ego\'s path.\n"""'])
def test_a_scene_in_a_code_comment_is_read_across_its_wrapped_lines(prompt):
    assert agents(prompt) == [("car", "stop", "ego"), ("firetruck", "turn_left", "road_of_straight")]


def test_the_egos_place_in_a_line_counts_it_among_the_line():
    assert agents("Ego is stopped, third in a line of three cars at a four-way stop.") == [
        ("car", "stop", "ego"), ("car", "stop", "front"), ("car", "stop", "front")]


def test_a_headings_road_user_told_by_its_participle_is_the_one_told_after():
    assert agents('"""Cyclist crossing from the right at an uncontrolled junction.\n\nEgo goes straight; a cyclist '
                  'comes out of the road on the right and crosses\nin front of ego.\n"""') == [
        ("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "road_of_right_turn")]


def test_people_crossing_short_of_the_zebra_crossing_are_not_on_it():
    said = agents("A group of pedestrians crosses the road from the left about 50 m before the zebra crossing; ego "
                  "goes straight.")
    assert [a[2] for a in said if a[0] == "pedestrian"] == ["front_left", "front_left"]


def test_it_after_actor_n_is_a_kind_is_the_one_before():
    assert ("truck", "go_straight", "road_of_straight") in agents(
        "The ego turns left at a crossroads. Actor 1 is a motorcycle coming from the opposite direction, and Actor 2 "
        "is a box truck right behind it.")


def test_an_annotators_instruction_names_no_agent():
    assert agents("Clip shows the ego going straight. A fire engine comes out of the road on the right and turns "
                  "left. Give Actor 2 the emergency attribute. Don't use the emergency-vehicle tag for the car.") == [
        ("car", "go_straight", "ego"), ("firetruck", "turn_left", "road_of_right_turn")]


def test_heading_away_from_the_junction_is_a_way_not_a_road_without_junction():
    prompt = ("The ego turns left at a junction with traffic lights. A cyclist is riding along the street the ego "
              "turns into, heading away from the junction.")
    assert road(prompt).junction is True
    assert ("cyclist", "go_straight", "at_the_destination") in agents(prompt)


def test_a_place_said_aside_ends_before_the_next_one_named():
    assert agents("The ego car drives straight along a three-lane road. A bus travels in the lane to its left, level "
                  "with it, and a hatchback follows the ego in the same lane.") == [
        ("bus", "go_straight", "left"), ("car", "go_straight", "back"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("whose", ["the", "your"])
def test_each_of_two_coordinated_road_users_keeps_its_own_side(whose):
    said = agents(f"I am turning right out of a T-junction. Two cars are coming from {whose} left and a motorcycle "
                  f"from {whose} right.")
    assert ("motorcycle", "go_straight", "road_of_right_turn") in said
    assert said.count(("car", "go_straight", "road_of_left_turn")) == 2


@pytest.mark.parametrize("prompt, expected", [
    ("Ego was going straight through on a green when an ambulance came across from the road on our left.",
     ("ambulance", "go_straight", "road_of_left_turn")),
    ("At the roundabout, ego stopped at the entry to yield to a car already circulating, coming from our left.",
     ("car", "go_straight", "road_of_left_turn"))])
def test_coming_across_or_along_from_our_side(prompt, expected):
    assert expected in agents(prompt)


def test_what_a_road_user_was_taken_for_and_the_only_actor_are_no_agents():
    assert agents("Ego turning left at a signalised intersection. A jogger was crossing the side street we were "
                  "turning onto. Perception classified the jogger as a cyclist. Please repro with the jogger as the "
                  "only actor.") == [("car", "turn_left", "ego"),
                                     ("pedestrian", "cross_the_road", "at_the_destination")]


def test_mine_as_the_verb_of_a_request_is_no_speaker():
    assert "mine" not in [t.word for t in tokenize("Please mine highway cut-ins from the right.")]
    assert "mine" in [t.word for t in tokenize("The car beside mine cuts in.")]


def test_a_patrol_car_on_the_shoulder_and_the_vehicle_it_pulled_over():
    assert agents("You're in the right lane of an interstate and there's a patrol car stopped on the shoulder ahead, "
                  "lights flashing, parked behind a pickup it has pulled over. You change into the left lane.") == [
        ("car", "change_lane_to_left", "ego"), ("car", "stop", "front_right"), ("police", "stop", "front_right")]


def test_a_snowplough_is_a_truck_and_sitting_in_the_fast_lane_is_driving():
    assert agents("You're driving slowly behind a snowplough.") == [("car", "go_straight", "ego"),
                                                                    ("truck", "go_straight", "front")]
    assert agents("You're on a motorway, sitting in the fast lane, with a van close behind you.") == [
        ("car", "go_straight", "back"), ("car", "go_straight", "ego")]


def test_passengers_waiting_at_the_stop_are_people_and_a_lane_change_planner_changes_no_lane():
    said = agents("A bus is stopped ahead of the host vehicle in its lane, and three waiting passengers stand on the "
                  "pavement on the host vehicle's right. S17 evaluates the lane-change planner.")
    assert said.count(("pedestrian", "on_the_sidewalk", "right")) == 3 and ("car", "go_straight", "ego") in said


def test_the_rightmost_lane_is_the_right_lane():
    assert ("car", "go_straight", "back_left") in agents(
        "The ego vehicle starts in the rightmost lane of a three-lane highway, while a sports car approaches from "
        "behind in the middle lane.")


def test_level_with_the_ego_then_into_its_lane_just_ahead_is_level():
    assert ("car", "block_the_ego", "left") in agents(
        "Ego drives in the right lane of a two-lane road. A sedan in the left lane, level with Ego, swerves into "
        "Ego's lane just ahead and stops dead, blocking Ego.")


def test_a_lane_said_after_one_placed_alongside_another_is_its_own():
    assert ("truck", "go_straight", "right") in agents(
        "The ego crawls along behind a bus in the centre lane, with a truck alongside it in the right lane.")


def test_people_who_tell_of_a_place_are_not_on_its_road():
    said = agents("Several residents told us that turning right out of Quay Street feels unsafe. The scenario is a car "
                  "turning right onto Harbour Road while a bus approaches from the left.")
    assert not any(a[0] == "pedestrian" for a in said)


def test_a_title_cased_heading_after_an_example_number_is_a_title():
    assert agents("Example 15: Right Turn With Oncoming Cyclist. The ego delivery van turns right at a signalised "
                  "junction. A cyclist coming from the opposite direction rides straight through.") == [
        ("car", "turn_right", "ego"), ("cyclist", "go_straight", "road_of_straight")]


def test_the_ego_named_in_brackets_is_named_again_by_its_noun():
    said = agents("A motorcyclist (the subject vehicle) rides along Station Parade and comes up to a delivery van "
                  "stopped in the lane ahead. The motorcyclist then stops behind the van.")
    assert [a for a in said if a[0] == "motorcycle"] == [("motorcycle", a[1], "ego") for a in said
                                                          if a[0] == "motorcycle"]


def test_a_triggering_conditions_road_users_are_the_ones_the_scene_names_again():
    said = agents("Triggering condition: radar returns from a motorcycle lost in clutter. On a two-lane expressway the "
                  "ego vehicle drives in the right lane. A motorcycle approaching fast from behind in the left lane "
                  "cuts sharply into the ego's lane just in front of it.")
    assert [a for a in said if a[0] == "motorcycle"] == [("motorcycle", "change_lane_to_right", "back_left")]


def test_cannot_just_swerve_is_no_lane_change():
    assert ("car", "go_straight", "ego") in agents(
        "Ego drives straight on a two-lane road and a truck is stopped in our lane ahead. Put a car in the left lane "
        "ahead of us too, so the ego can't just swerve round it.")


def test_one_let_pass_is_not_the_subject_that_goes_on():
    said = agents("Our vehicle approaches a police car stopped in our lane. A city bus is approaching from behind in "
                  "the right lane. Our vehicle slows, lets the bus pass, and then changes lanes to the right.")
    assert ("bus", "go_straight", "back_right") in said


def test_the_road_users_counted_after_those_named_are_the_same():
    said = agents("The ego enters a signalised intersection on a green light and turns left. Two oncoming cars "
                  "proceed straight. A pedestrian is crossing at the crosswalk. The feature shall yield to all three "
                  "road users before completing the turn.")
    assert len(said) == 4


def test_a_lane_change_said_not_to_be_required_is_not_made():
    assert ("car", "go_straight", "ego") in agents(
        "The subject vehicle cruises in the middle lane of a three-lane motorway. A car in the left lane cuts into "
        "the SV's lane. The ACC shall restore a safe gap; a lane change by the SV is not required.")


@pytest.mark.parametrize("prompt", [
    "The ego goes straight on green, and an ambulance from the road on the left runs the red at speed. Please "
    "build a red-runner case.",
    "The host vehicle approaches on a green light. A fire engine crosses from the road on the right. Expected "
    "HMI: an emergency-vehicle icon is shown to the driver."])
def test_a_red_runner_case_and_an_emergency_vehicle_icon_are_no_agents(prompt):
    said = agents(prompt)
    assert not any(a[0] == "pedestrian" for a in said) and len(said) == 2


def test_a_car_a_trooper_is_pulled_over_beside_stands_with_it():
    assert ("car", "stop", "front_right") in agents(
        "Dusk on a highway with two lanes each way, and a state trooper is stopped on the right shoulder behind a car "
        "he's pulled over, lights flashing, so I move over to the left lane.")


def test_him_placing_one_after_another_told_by_i_is_the_other_driver():
    assert ("car", "go_straight", "road_of_right_turn") in agents(
        "I'm stopped at the yield sign and a Prius coming from the road on my right just blows through. Then a van "
        "right behind him does the exact same thing.")
    assert ("ambulance", "go_straight", "back") in agents(
        "Customer states he was moving over into the right lane for an ambulance coming up behind him.")


@pytest.mark.parametrize("place", ["right after the corner", "just past the corner"])
def test_just_past_the_corner_the_ego_turns_round_is_where_it_heads(place):
    assert ("bus", "stop", "at_the_destination") in agents(
        f"When we turned right at the yield sign onto Pine Street, a bus was stopped at the bus stop {place}.")


def test_straight_across_the_junction_is_a_path_and_that_street_is_the_one_turned_into():
    assert ("car", "go_straight", "road_of_right_turn") in agents(
        "The ego waits at a stop sign to turn left while a car from the right goes straight across the junction.")
    assert ("car", "block_the_ego", "at_the_destination") in agents(
        "The ego turns left into a side street, and a delivery van is stopped in that street, blocking our way.")


def test_what_the_speaker_spotted_and_then_had_to_do_is_the_speakers():
    said = agents("Two lanes my side. There's a car broken down in my lane with no hazards on, I only spotted it at "
                  "about 30 metres and had to swing out into the right-hand lane to get round it.")
    assert ("car", "change_lane_to_right", "ego") in said and ("car", "stop", "front") in said


def test_a_task_set_on_the_scene_and_a_crossing_told_by_its_markings():
    prompt = ("The crossing is marked only with two parallel lines, without stripes, and has no traffic light. A "
              "jogger crosses the road on it while the ego approaches cautiously. Evaluate the distance at which your "
              "vehicle yields.")
    assert ("car", "go_straight", "ego") in agents(prompt)
    assert "parallel_open_crosswalk" in road(prompt).required_objects


@pytest.mark.parametrize("who", ["You are the driver of a car.", "I am the driver of a car."])
def test_the_driver_of_a_vehicle_said_of_the_speaker_is_the_speakers_own(who):
    said = agents(f"{who} A fire engine comes from the road on the right and goes straight across in front.")
    assert ("car", "go_straight", "ego") in said and not any(k[0] == "car" and k[2] != "ego" for k in said)


def test_one_of_our_vans_after_a_heading_that_names_its_manoeuvre_is_the_ego():
    said = agents("Lane-change reminder. On Tuesday one of our service vans changed lanes to the left and cut right "
                  "across the path of a silver hatchback that was coming up behind him in the left lane.")
    assert sorted(said) == [("car", "change_lane_to_left", "ego"), ("car", "go_straight", "back_left")]


def test_the_vehicle_the_speaker_sits_in_with_a_participle_after_it_is_the_speakers():
    assert ("car", "stop", "front") not in agents(
        "Foggy, and I was sat at the end of our yard in the Land Rover waiting to turn left. A lorry came from the "
        "right.")
    assert ("car", "stop", "front") in agents("I was stuck behind a guy in the pickup waiting to turn.")


def test_a_connected_vehicle_use_case_tells_the_host_vehicle_and_the_remote_ones():
    said = agents("The HV has stopped at the stop bar at the intersection and intends to go straight across. RV1 is "
                  "approaching from the HV's right. RV2, a motorcycle, is approaching from the HV's left.")
    assert ("car", "go_straight", "road_of_right_turn") in said
    assert ("motorcycle", "go_straight", "road_of_left_turn") in said


def test_a_place_said_not_to_be_and_the_same_lane_as_the_one_followed():
    said = agents("The HV is travelling in the right lane of a freeway with two lanes in each direction. RV1, ahead of "
                  "the HV in the left lane, brakes hard. Since RV1 is not in the HV's path, the HV continues.")
    assert ("car", "stop", "front_left") in said
    said = agents("The HV is travelling in the right lane of a road with two lanes in each direction. RV1, an "
                  "ambulance, approaches from behind in the left lane and broadcasts its status; a police car "
                  "escorting it follows RV1 in the same lane.")
    assert ("ambulance", "go_straight", "back_left") in said


def test_a_case_named_by_the_turn_another_makes_while_the_ego_goes_straight():
    said = agents("Left Turn Across Path, HV going straight. The HV drives straight through a signalized "
                  "intersection on green. RV1, approaching from the opposite direction, turns left across the HV's "
                  "path.")
    assert ("car", "go_straight", "ego") in said and ("car", "turn_left", "road_of_straight") in said


def test_an_operators_log_names_its_own_vehicle_bare():
    said = agents("10:42, light rain. A delivery van was double-parked in our lane with its hazards on. Shuttle braked "
                  "to a stop behind it. Once the left lane was clear it changed lanes to the left and went round the "
                  "van.")
    assert ("bus", "stop", "ego") in said and ("bus", "change_lane_to_left", "ego") in said
    assert ("truck", "go_straight", "ego") in agents(
        "I'm rolling up in the truck, and the two cars that had bumped were still sat in my lane in front of me. "
        "Ambulance had already been and gone.")
    assert ("car", "turn_right", "ego") in agents(  # a commentary's bare noun with its participle: another
        "Night, rain. Approaching junction, turning right into Market Street. Car waiting to come out of Market "
        "Street. Control asking for our ETA, leave it.")


def test_you_in_advice_after_the_scene_is_said_to_all():
    said = agents("Be seen, be safe. In the dark yesterday, a driver on the A38 had to stop when a man dressed all in "
                  "black walked out across the road in front of her car. If you're walking at night, please wear "
                  "something bright.")
    assert ("car", "stop", "ego") in said


def test_a_builders_how_question_and_code_identifiers_after_the_scene_are_no_scene():
    said = agents("For my thesis I need a scene where the ego vehicle drives straight on a 2-lane edge and a truck in "
                  "the left lane ahead of it changes into the ego's lane. How do I force that lane change at a given "
                  "position? I tried changeLane via TraCI but the truck ignores it.")
    assert ("car", "go_straight", "ego") in said and ("truck", "change_lane_to_right", "front_left") in said


@pytest.mark.parametrize("ego", ["The main vehicle", "The ADC"])
def test_a_driving_stacks_document_names_the_ego_the_main_vehicle(ego):
    said = agents(f"{ego} is on the minor road of a T junction with a stop sign. One obstacle vehicle approaches on "
                  f"the major road from the right side. {ego} must stop at the stop line first, then turn left after "
                  "it has passed.")
    assert ("car", "stop", "ego") in said and ("car", "turn_left", "ego") in said


def test_someone_feared_for_in_the_future_is_no_one_of_the_scene():
    said = agents("Yesterday I was driving out there with a guy on a bike riding on the shoulder just ahead of me on "
                  "the right. Somebody is going to get killed out there.")
    assert not any(k[0] == "pedestrian" for k in said)


@pytest.mark.parametrize("move", ["moves into your lane just in front of you", "enters suddenly in your lane in front "
                                  "of you"])
def test_in_front_after_the_lane_a_cut_in_ends_in_is_where_it_ends(move):
    said = agents(f"It is raining. You are driving a car on the motorway. The motorway has three lanes. A van is in "
                  f"the lane on your left. The van {move}.")
    assert ("car", "change_lane_to_right", "left") in said


def test_footage_sent_to_the_poster_is_told_from_the_driver_who_sent_it():
    said = agents("Dashcam footage sent to us by the driver of a silver Corolla on the M6 last night. She's in the "
                  "middle lane of the three-lane motorway when a white van in the lane to her left cuts dangerously "
                  "across in front of her without indicating.")
    assert sorted(said) == [("car", "change_lane_to_right", "left"), ("car", "go_straight", "ego")]


def test_an_ego_that_filters_or_rides_rides_a_motorbike():
    assert ("motorcycle", "go_straight", "ego") in agents(
        "You're filtering slowly between two lanes of stationary traffic. A car in the right-hand lane just ahead of "
        "you pulls across into the left lane.")
    assert ("car", "go_straight", "ego") in agents(
        "I ride the centre's van to my appointments, and on Tuesday a sports car in the left lane cut right across in "
        "front of us.")
    assert ("car", "go_straight", "ego") in agents(
        "Three lanes of queueing traffic, and a motorbike is filtering up between the lanes from behind me.")
    said = agents("Country lane, early morning. The rider comes round a left-hand bend and finds two cyclists riding "
                  "side by side in the lane ahead.")
    assert ("motorcycle", "go_straight", "ego") in said and ("cyclist", "go_straight", "front") in said
    assert ("car", "go_straight", "ego") in agents(
        "A cyclist came up on my left at the lights. The rider then went straight on.")


def test_a_crews_log_names_its_own_vehicle_as_one_known():
    said = agents("Run 3318, 02:40, dark. An ambulance came up quickly behind us in our lane with lights and siren, "
                  "and the truck changed to the right lane to let it by.")
    assert ("truck", "change_lane_to_right", "ego") in said
    said = agents("The truck was in the right lane of a three-lane section when a pickup in the center lane made a "
                  "sudden cut-in directly in front of us with barely a truck length to spare.")
    assert sorted(said) == [("car", "change_lane_to_right", "left"), ("truck", "go_straight", "ego")]


def test_a_commentarys_nearside_and_its_participle_after_the_others_are_through():
    assert ("car", "stop", "road_of_left_turn") in agents(
        "Approaching crossroads, give way lines my side. Van waiting to emerge from the nearside road, cyclist ahead "
        "of me, hanging back.")
    said = agents("Stopped at the stop line. A lorry comes from the right. Once it is through, turning left.")
    assert ("car", "stop", "ego") in said and ("car", "turn_left", "ego") in said
    assert ("truck", "go_straight", "road_of_right_turn") in said


@pytest.mark.parametrize("prompt", [
    "Scenario: ego turns left at a junction while a truck comes from the opposite direction.\nWeather: rain.",
    "TC-1 FAILED. Scene: ego turns left at a junction while a truck comes from the opposite direction. Log: x.mcap."])
def test_a_scene_key_whose_value_tells_the_scene_is_no_title(prompt):
    said = agents(prompt)
    assert ("car", "turn_left", "ego") in said and ("truck", "go_straight", "road_of_straight") in said


def test_pulling_out_in_front_of_a_road_user_is_the_subjects_doing():
    said = agents("The ego, turning left out of a T-junction, pulled out in front of a motorcycle coming from the "
                  "right.")
    assert ("motorcycle", "go_straight", "road_of_right_turn") in said


def test_a_querys_ego_type_is_what_the_ego_is():
    said = agents("FIND clips WHERE ego_type = truck AND ego changes lane right AND car approaching in right lane "
                  "behind ego")
    assert sorted(said) == [("car", "go_straight", "back_right"), ("truck", "change_lane_to_right", "ego")]


def test_an_eighteen_wheeler_and_a_stop_not_needed():
    said = agents("An 18 wheeler was broken down on the shoulder ahead of me on the right, and I braked but didn't "
                  "have to stop.")
    assert ("truck", "stop", "front_right") in said and ("car", "go_straight", "ego") in said


def test_a_scenario_languages_param_and_a_pushchair_without_its_article_are_no_one():
    said = agents("ego = Car on a rural road. oncoming1 = Car in the opposite lane driving toward ego. param weather = "
                  "snow, param timeOfDay = sunset.")
    assert not any(k[0] == "pedestrian" for k in said)
    said = agents("Female ped with pushchair crosses in front of the ego on the pedestrian crossing.")
    assert [k for k in said if k[0] == "pedestrian"] == [("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_markdown_bold_keys_and_a_description_key_are_read_as_the_scene():
    said = agents("**Scenario: Unprotected Left Turn at Dusk**\n\n- **Ego vehicle:** Sedan, turning left\n"
                  "- **Other actors:** Two oncoming cars going straight through the intersection")
    assert sorted(said) == [("car", "go_straight", "road_of_straight")] * 2 + [("car", "turn_left", "ego")]
    said = agents("**Scenario: Police Roadblock**\n\n**Description:** Late at night on a single-lane rural road, two "
                  "patrol cars are parked across the ego's lane ahead, blocking the road completely.")
    assert [k for k in said if k[0] == "police"] == [("police", "block_the_ego", "front")] * 2


def test_the_road_turned_into_named_again_is_where_the_ego_heads():
    said = agents("I turned right onto Walnut Street, and a school bus was parked on Walnut Street with its "
                  "flashers on.")
    assert ("bus", "stop", "at_the_destination") in said
    said = agents("The ego waits at the give way line to turn left into the main road. A car on the main road comes "
                  "from the right.")
    assert ("car", "go_straight", "road_of_right_turn") in said


@pytest.mark.parametrize("prompt", [
    "On Friday evening the driver of a blue hatchback turned right at the junction, straight across the path of an "
    "oncoming motorcyclist. Footage from the hatchback's own dashcam shows the rider had his headlight on.",
    "Dashcam from a grey Civic turning right at the crossroads yesterday afternoon, straight across the path of an "
    "oncoming motorcyclist. Both walked away."])
def test_a_clip_is_told_from_the_vehicle_whose_camera_filmed_it(prompt):
    said = agents(prompt)
    assert ("car", "turn_right", "ego") in said and ("motorcycle", "go_straight", "road_of_straight") in said


def test_what_someone_of_theirs_does_is_not_the_egos():
    said = agents("Create a scene at night where a man in dark clothes crosses in front of the ego from the right. The "
                  "ego goes straight. His friend waits on the far side of the road.")
    assert ("car", "go_straight", "ego") in said and len(said) == 2


def test_a_stop_arrived_at_gives_way_to_the_way_meant_unless_a_later_stage_goes_on():
    said = agents("You arrive at a four-way stop at the same time as a car on the road to your right. Both of you want "
                  "to go straight. Who has the right-of-way?")
    assert ("car", "go_straight", "ego") in said
    told = stages("Player pulls up to a stop sign at a T-junction and needs to go right. A pickup is coming along "
                  "from the left. Once it has cleared, the player makes the turn.")
    assert told[0][0] == ("ego", "stop", None) and told[1][0] == ("ego", "turn_right", None)


def test_a_fleet_records_unit_is_the_ego():
    said = agents("Event type: Harsh braking. 14:32:07. Unit 4417 (tractor-trailer) in right lane of 3-lane "
                  "interstate, 58 mph. Third-party sedan in the center lane, level with the cab, abruptly cut in "
                  "ahead of the unit, no signal. Driver braked, no contact.")
    assert ("truck", "go_straight", "ego") in said and [k for k in said if k[2] != "ego"] == [
        ("car", "change_lane_to_right", "left")]
    said = agents("Unit 12 at scene, 2 veh RTC at lights. V1 silver Astra stationary at red at the stop line, V2 white "
                  "Transit van failed to stop and went into rear of V1.")
    assert ("car", "stop", "ego") in said  # the reporting unit is not in the scene; V1 is


def test_advice_after_the_scene_is_not_the_scene():
    said = agents("Event type: Near collision. Unit 340 (tractor-trailer) turning left at an uncontrolled "
                  "intersection. Oncoming motorcycle proceeding straight. Coachable: right-of-way, judging speed of "
                  "oncoming two-wheelers.")
    assert sorted(said) == [("motorcycle", "go_straight", "road_of_straight"), ("truck", "turn_left", "ego")]


def test_a_learning_environments_agent_is_the_ego():
    said = agents("I need an env for emergency-vehicle yielding. Agent is in the left lane of a two-lane road; an "
                  "ambulance comes up fast behind it with sirens on, and the agent has to change to the right lane. "
                  "Reward shaped on how quickly it clears the lane.")
    assert ("car", "change_lane_to_right", "ego") in said and ("ambulance", "go_straight", "back") in said


def test_an_agent_noun_in_a_compound_and_a_need_for_none_name_no_one():
    said = agents("For the ped-safety task I want a straight road with a zebra crossing. One pedestrian walks across "
                  "on the zebra as the ego approaches. No need for NPC cyclists in this one.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_a_move_out_of_its_lane_into_the_one_on_its_right_is_a_lane_change_right():
    assert agents("The ego moves from its current lane into the adjacent lane on its right.") == [
        ("car", "change_lane_to_right", "ego")]


def test_a_definitions_agents_are_played_by_the_instance_told_after_it():
    said = agents("stopping_with_lead: the ego decelerates to a stop behind a lead vehicle that has itself come to a "
                  "halt. A typical log shows the ego stopping behind a box truck that is stopped in its lane.")
    assert sorted(said) == [("car", "stop", "ego"), ("truck", "stop", "front")]


def test_a_device_turned_on_is_no_turn_and_a_tool_step_keeps_the_scene_set_up_after_it():
    said = agents("Steps to reproduce: turn fog on in AWSIM, ego drives at 50 km/h, and npc_1 is stopped in ego's lane "
                  "about 100 m ahead with its hazards on. Expected behavior: ego stops behind npc_1.")
    assert ("car", "go_straight", "ego") in said and ("car", "stop", "front") in said
    said = agents("**Steps to reproduce**: launch `planning_simulator` with the sample map, put ego in front of the "
                  "signalised intersection and set a goal so the route turns left on green. Spawn `npc_1` on the "
                  "opposite approach, going straight through. **Expected behavior**: ego yields to `npc_1`.")
    assert sorted(said) == [("car", "go_straight", "road_of_straight"), ("car", "turn_left", "ego")]


def test_a_country_said_to_drive_on_the_left_is_no_turn_of_the_ego():
    said = agents("Ego turns right at an unsignalised intersection (we drive on the left here, so right is across "
                  "traffic). A car comes from the opposite direction going straight.")
    assert ("car", "turn_right", "ego") in said


@pytest.mark.parametrize("prompt, expected", [
    ("Highway, 5 lanes, numbered from the left. Ego in lane 3, all vehicles moving. Lane 2: 1 car slightly ahead. "
     "Lane 4: 2 trucks, one level with the ego, one behind it.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "front_left"), ("truck", "go_straight", "back_right"),
      ("truck", "go_straight", "right")]),
    ("3 lanes. Ego: right lane, moving. Middle lane behind: 1 ambulance, fast, sirens on.",
     [("ambulance", "go_straight", "back_left"), ("car", "go_straight", "ego")]),
    ("Roundabout entry, single lane, give-way sign. Ego stopped at the give-way line. Circulating from the left: 2 "
     "cars, passing.",
     [("car", "go_straight", "road_of_left_turn")] * 2 + [("car", "stop", "ego")])])
def test_a_layout_keyed_by_lane_places_what_follows_in_that_lane(prompt, expected):
    assert agents(prompt) == expected


def test_the_one_named_by_where_it_is_is_the_one_placed_there():
    said = agents("Motorway, 2 lanes. Ego in the right lane. Left lane: 1 car ahead, 1 car level with the ego, both "
                  "moving. The car level with the ego cuts in front of the ego.")
    assert ("car", "change_lane_to_right", "left") in said and ("car", "go_straight", "front_left") in said


def test_a_driver_assistance_system_is_the_car_it_drives_and_a_kind_it_should_detect_is_no_one():
    said = agents("Autopilot on a divided highway, two lanes each way, me in the right lane. Fire truck parked on the "
                  "shoulder up ahead and AP didn't move over. Isn't it supposed to detect emergency vehicles now??")
    assert not any(k[0] == "ambulance" for k in said)
    said = agents("FSD in the city: a UPS truck was double parked in my lane with its flashers on and FSD just sat "
                  "behind it for a full minute.")
    assert ("car", "stop", "ego") in said and ("truck", "stop", "front") in said


def test_let_in_ahead_of_me_is_where_it_goes_and_the_only_other_car_said_to_be_one_is_that_one():
    said = agents("Right lane. A semi in the lane to my left just started coming over into my lane. I braked and let "
                  "him in ahead of me.")
    assert ("truck", "change_lane_to_right", "left") in said
    said = agents("Two lanes my side, nobody in front of me. The only other car around was a Camry following behind "
                  "me.")
    assert [k for k in said if k[2] != "ego"] == [("car", "go_straight", "back")]


def test_a_benchmarks_adversary_said_with_the_is_new_and_a_role_it_plays_is_no_one():
    said = agents("The ego is stopped at a red light in the right lane, behind a stopped bus. The adversarial vehicle "
                  "in the left lane swerves into the ego's path and stops, blocking it.")
    assert ("bus", "stop", "front") in said and ("car", "block_the_ego", "left") in said
    said = agents("The ego drives straight. An adversarial child darts out from the right and crosses in front of "
                  "the ego. The child is the only adversarial agent in this scenario. A police car, added as a "
                  "distractor, is parked ahead on the right.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right"),
                            ("police", "stop", "front_right")]


def test_passing_in_a_lane_by_one_on_the_shoulder_and_holding_position_beside_keep_their_lanes():
    said = agents("A broken-down van stands on the hard shoulder ahead on the right while the subject vehicle passes "
                  "in the right-hand lane at 60 km/h.")
    assert ("car", "go_straight", "ego") in said
    said = agents("The lead vehicle is a coach in the subject vehicle's lane. A second target vehicle holds position "
                  "in the adjacent left lane right next to the subject vehicle.")
    assert ("car", "go_straight", "left") in said


@pytest.mark.parametrize("prompt, expected", [
    ("Conflict 25. Subject: a grey SUV going straight through on green when a fire engine on blue lights came "
     "through against the red from the subject's right.",
     [("car", "go_straight", "ego"), ("firetruck", "go_straight", "road_of_right_turn")]),
    ("Conflict 2 (signalised crossroads): left-turning car (the subject) on a permissive green against an opposing "
     "through motorcycle. PET 0.8 s.",
     [("car", "turn_left", "ego"), ("motorcycle", "go_straight", "road_of_straight")]),
    ("Conflict 11, two-way stop. Subject: a northbound pickup on the minor leg going straight across. Conflicting "
     "vehicle: an eastbound sedan on the major road, so approaching from the subject's left.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")])])
def test_an_observers_subject_is_the_ego(prompt, expected):
    assert agents(prompt) == expected


def test_a_second_bike_after_a_motorcycle_is_a_motorcycle():
    said = agents("I was turning left onto 22 and never saw the motorcycle coming from my left till he was right on "
                  "me, with a second bike right behind him.")
    assert [k[0] for k in said if k[2] != "ego"] == ["motorcycle", "motorcycle"]


def test_a_dashed_list_run_on_in_a_line_and_scenery_said_so():
    said = agents("Goal: end-of-queue braking. Constraints: - 3 lanes, ego in the middle lane at 110 km/h - 3 stopped "
                  "cars ahead in ego lane (tail of a jam) - truck in the right lane, level with ego")
    assert sorted(said) == [("car", "go_straight", "ego")] + [("car", "stop", "front")] * 3 + [
        ("truck", "go_straight", "right")]
    said = agents("Goal: bus pulling out. Constraints: - 2-lane urban road, ego in the right lane - city bus at a stop "
                  "ahead on the right, pulls out into ego's lane - passengers waiting at the stop: scenery only")
    assert ("car", "go_straight", "ego") in said and not any(k[0] == "pedestrian" for k in said)


def test_a_translated_specifications_main_car_lane_and_absent_participants():
    said = agents("2. Main car drive straight in the middle lane with speed 50km/h. 3. Target car in the left adjacent "
                  "lane, a little ahead of main car, suddenly change lane into main car lane. 4. No other traffic "
                  "participant.")
    assert sorted(said) == [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]


def test_the_ego_said_to_be_a_vehicle_with_its_heading_is_that_vehicle():
    assert agents("The ego is a westbound semi turning right onto Mill.") == [("truck", "turn_right", "ego")]


def test_the_ego_named_again_by_its_type_in_a_note_is_the_ego():
    said = agents("Conflict 19, mid-block. Subject: a city bus in the centre lane, going straight. A white hatchback "
                  "in the left lane just ahead of the bus changed abruptly right into the centre lane. Bus braked.")
    assert sorted(said) == [("bus", "go_straight", "ego"), ("car", "change_lane_to_right", "front_left")]


def test_a_newcomers_corrections_replace_what_they_correct():
    said = agents("I want something simple: a car parked ahead of me in my lane, and I have to go around it by "
                  "changing into the right lane. Hmm, maybe make the parked thing a delivery truck instead of a car.")
    assert sorted(said) == [("car", "change_lane_to_right", "ego"), ("truck", "stop", "front")]
    said = agents("My car goes straight through a junction on a green light, and a cyclist from the left road is "
                  "crossing... no wait, the cyclist should be waiting at the light.")
    assert ("cyclist", "stop", "road_of_left_turn") in said


def test_weather_that_sits_or_falls_is_no_ones_doing():
    said = agents("Early morning fog sitting over the bridge, visibility poor. Our ego is the white Tesla in the right "
                  "lane. A motorbike in the lane on its left cuts across in front of it.")
    assert ("car", "go_straight", "ego") in said


@pytest.mark.parametrize("prompt, ego", [
    ("I drive the 22 bus. A boy on a moped came flying up the outside of me.", "bus"),
    ("I pulled off to go straight across, and a pickup coming from my left ran its stop sign and missed the rear "
     "of the bus by a few feet.", "bus"),
    ("I was travelling along Albert Road at about 25 mph when a police car pulled out across in front of me, so I "
     "then stopped to let it go. Two passengers were standing at the time.", "bus"),
    ("At the signal the truck turned left on a green arrow while two oncoming cars sat at their red light. A woman "
     "stood on the sidewalk of the road we turned onto.", "truck")])
def test_the_speakers_vehicle_named_by_its_route_its_part_or_its_passengers(prompt, ego):
    assert {k[0] for k in agents(prompt) if k[2] == "ego"} == {ego}


def test_a_driver_who_signalled_changes_lane():
    said = agents("I was stationary at the Library stop with the doors open. Once loading was done I signalled and "
                  "moved out into the right lane.")
    assert ("bus", "change_lane_to_right", "ego") in said


def test_an_operators_note_on_its_numbered_vehicle():
    said = agents("Unit 218, 02:10. It stopped behind a delivery truck double-parked in its lane, hazards on, driver "
                  "nowhere around. Then, once I confirmed the left lane was clear, it changed into the left lane.")
    assert sorted(said) == [("car", "change_lane_to_left", "ego"), ("car", "stop", "ego"), ("truck", "stop", "front")]
    said = stages("Robotaxi 9 requested help on a right turn: a crowd was streaming across the crosswalk it needed, "
                  "and it waited about 4 minutes. Then it made the turn once they thinned out.")
    assert [[a for a in st if a[0] == "ego"] for st in said] == [[("ego", "stop", None)], [("ego", "turn_right", None)]]
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in said[0]
    said = agents("Car 31 stopped on a narrow street when a patrol car with its lights on came up right behind it.")
    assert sorted(said) == [("car", "stop", "ego"), ("police", "go_straight", "back")]


def test_after_a_manoeuvre_named_as_a_noun_is_no_later_stage():
    scene = lower_prompt("The ego turned left after a short wait, and a cyclist crossed in front of it.",
                         "offline").scenario
    assert len(scene.stages) == 1


def test_the_ego_named_with_its_place_in_an_apposition_and_again_by_that_name():
    said = agents("Our ego, a green hatchback in the right lane, is coming up on a tow truck stopped on the shoulder. "
                  "There's a motorcycle riding alongside the hatchback in the lane to its left.")
    assert ("motorcycle", "go_straight", "left") in said and [k for k in said if k[0] == "car"] == [
        ("car", "go_straight", "ego")]


def test_scenery_said_again_with_the_is_still_scenery():
    said = agents("A kid on a bike suddenly shoots out of a driveway on the right between parked cars and crosses in "
                  "front of us. Ego brakes to a halt. The parked cars hide everything but his helmet.")
    assert not any(k[0] == "car" and k[2] != "ego" for k in said)


def test_tram_tracks_are_no_tram():
    said = agents("Crossroad of equal roads, no signs and no lights, only tram tracks go across. I want turn left. "
                  "From right road comes cyclist and from left road comes taxi.")
    assert not any(k[0] == "bus" for k in said)


def test_a_configs_opening_scenario_key_is_its_name():
    said = agents("scenario: stopped vehicle on shoulder. road: 2-lane rural road. ego: straight, right lane. obj: "
                  "white van stopped on hard shoulder ahead right, hazards on.")
    assert len([k for k in said if k[2] != "ego"]) == 1


def test_someones_relation_on_the_pavement_is_a_pedestrian():
    said = agents("Old man is crossing at crosswalk in front. His wife is standing on sidewalk at right side, she is "
                  "not crossing.")
    assert ("pedestrian", "on_the_sidewalk", "right") in said
    said = agents("Two kids were waiting on the sidewalk ahead to the right, next to a zebra crossing. One of them "
                  "darted onto the crossing, and our car stopped while her friend stayed on the sidewalk.")
    assert len([k for k in said if k[0] == "pedestrian"]) == 2


def test_the_driver_placed_behind_the_speaker_is_no_driver_named_before():
    said = agents("At the yield sign, I came to a full stop and waited for a motorcyclist on the road to the left. The "
                  "driver waiting behind us honked twice.")
    assert ("car", "stop", "back") in said and ("motorcycle", "go_straight", "road_of_left_turn") in said


def test_one_sitting_behind_a_stopped_ego_stands_and_one_sitting_behind_a_moving_ego_follows():
    assert ("police", "stop", "back") in agents("The ego is stopped at the red light. A patrol car sat behind the ego.")
    assert ("police", "go_straight", "back") in agents("A patrol car sat behind me for miles.")


def test_a_subject_said_again_by_a_pronoun_right_after_it():
    said = agents("I drive the water truck and I have green arrow so I turn left, and the bus from the opposite side "
                  "he stop for me, and one man he cross the street where I am going into, on the zebra crossing.")
    assert ("bus", "stop", "road_of_straight") in said
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in said


def test_a_driver_who_stood_still_at_a_give_way_sign_is_at_the_wheel():
    said = agents("At the intersection there is a give-way sign for me. So I stood still. From the right came a car "
                  "straight on.")
    assert ("car", "stop", "ego") in said and ("car", "go_straight", "road_of_right_turn") in said


def test_a_photo_is_taken_from_the_ego():
    said = agents("Photo taken from a stopped car in light rain: a child in a yellow raincoat is crossing on a zebra "
                  "crossing just in front of the bonnet.")
    assert sorted(said) == [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_sitting_in_a_motorway_lane_is_cruising_there():
    said = agents("Suppose you're on a three-lane motorway on a clear day, sitting in the middle lane with the left "
                  "lane completely empty, and a van is sitting close behind you in your lane.")
    assert ("car", "go_straight", "ego") in said


def test_being_ready_to_stop_and_what_a_sign_means_are_no_stop():
    assert ("car", "go_straight", "ego") in agents("Elderly gent crossing, taking his time, so I'm ready to stop.")
    assert ("motorcycle", "go_straight", "ego") in agents("We ride at a speed where we can stop. A kid runs out in "
                                                          "front of the bike.")
    said = agents("One of our reps was entering the roundabout at the yield sign, heading straight across, when a car "
                  "already on the roundabout came from the left and clipped his front bumper. Yield means yield.")
    assert ("car", "go_straight", "ego") in said


def test_a_cut_in_the_speaker_asks_for_is_someone_elses():
    said = agents("Hi Lena, I need a highway cut-in for the ACC tests. Three lanes each way, ego in the middle lane at "
                  "110. A white van slightly ahead of us in the right lane cuts in aggressively.")
    assert ("car", "go_straight", "ego") in said and ("car", "change_lane_to_left", "front_right") in said


@pytest.mark.parametrize("prompt, expected", [
    ("Reporting a close pass on Mill Lane. I was riding in the middle of the lane because of the potholes when a "
     "silver hatchback came up behind me and overtook with maybe half a metre to spare.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]),
    ("Cycle commuter, reporting a white delivery van on Harbor Road, which has two lanes each way. I was riding in the "
     "right lane and the van was in the left lane, a little behind me. The driver swerved right into my lane.",
     [("car", "change_lane_to_right", "ego"), ("cyclist", "go_straight", "front_right")]),
    ("I was crossing Western Avenue at the toucan crossing on a green cycle signal when a black BMW ran the red light "
     "and shot through about a metre in front of me.",
     [("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "near_the_crosswalk")])])
def test_a_cyclists_report_is_told_from_the_vehicle_reported(prompt, expected):
    assert sorted(agents(prompt)) == sorted(expected)


def test_a_case_told_of_the_driver_places_others_by_the_drivers_side():
    said = agents("The most common pattern is a fire engine on blue lights coming from the driver's left through a red "
                  "signal, while the driver goes straight ahead on green.")
    assert ("firetruck", "go_straight", "road_of_left_turn") in said
    said = agents("A child runs into the road mid-block from between parked cars on the driver's right, and the "
                  "driver cannot stop in time.")
    assert [k for k in said if k[0] == "car"] == [("car", "go_straight", "ego")]


def test_a_cyclists_arm_out_is_no_bus_stop_arm():
    said = agents("I was turning left into Hill Street with my arm out when a car coming towards me sped up and went "
                  "through the lights on amber.")
    assert not any(k[0] == "bus" for k in said)


def test_a_ride_hailing_drivers_rider_is_their_passenger():
    said = agents("Re: the \"unsafe driving\" complaint from trip 4471-B. I was driving down Elm Street at about 25 "
                  "mph, in the middle of the block. A guy in a black hoodie stepped off the curb on my right and "
                  "walked straight out in front of me. Then I stopped. The rider hit his knee on the seat.")
    assert {k[0] for k in said if k[2] == "ego"} == {"car"}


def test_a_rule_of_the_road_before_the_scene_it_illustrates_is_no_part_of_it():
    said = agents("A YIELD sign means slow down and be ready to stop to let any vehicle, pedestrian, or bicyclist pass "
                  "before you proceed (DMV handbook). Scenario: the ego is turning right at a yield sign onto a busier "
                  "road. A bicyclist is already riding along the road the ego is turning onto, and a car is coming "
                  "from the left.")
    assert sorted(said) == [("car", "go_straight", "road_of_left_turn"), ("car", "turn_right", "ego"),
                            ("cyclist", "go_straight", "at_the_destination")]


def test_a_subject_with_a_predicate_of_its_own_does_not_share_the_next_ones_verb():
    said = agents("The ego is on a two-lane road and a motorbike in the right lane, slightly ahead of it, suddenly "
                  "cuts in front of the ego.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("motorcycle", "change_lane_to_left", "front_right")]


@pytest.mark.parametrize("prompt, expected", [
    ("When the subject vehicle turns right from a major road into a minor road while a pedestrian is crossing the "
     "minor road, the system shall brake.", ("pedestrian", "cross_the_road", "at_the_destination")),
    ("Made my full stop, then turned right onto Main. There was a kid on a bike already on Main, riding away from "
     "the junction.", ("cyclist", "go_straight", "at_the_destination"))])
def test_the_road_turned_into_said_again_by_its_name(prompt, expected):
    assert expected in agents(prompt)


def test_one_following_another_from_a_side_is_placed_by_its_own_side():
    said = agents("Our vehicle is stopped at the entry of a roundabout controlled by yield signs while a circulating "
                  "car, followed closely by a motorcyclist, approaches from our left.")
    assert ("motorcycle", "go_straight", "road_of_left_turn") in said


def test_an_age_with_no_noun_after_it_is_a_child():
    said = agents("The ego drives along a rural road. K, a seven-year-old, runs out from in front of a parked bus and "
                  "across the ego's path.")
    assert any(k[0] == "pedestrian" and k[1] == "cross_the_road" for k in said)


@pytest.mark.parametrize("prompt, expected", [
    ("D is driving her sedan north on Main Street at 40 mph. P, a pedestrian, steps off the curb into the crosswalk "
     "in front of D. D does not brake and hits P.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("Dave drives his sedan north on Main Street. A pedestrian steps into the crosswalk in front of him.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("Client was riding his motorcycle eastbound on Lakeshore Dr. Says a black SUV in the lane to his left suddenly "
     "cut into his lane without signaling.",
     [("car", "change_lane_to_right", "left"), ("motorcycle", "go_straight", "ego")])])
def test_a_party_at_the_wheel_told_of_by_name_letter_or_role_is_the_ego(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_of_two_parties_at_the_wheel_the_one_others_are_placed_by_is_the_ego():
    said = agents("E is driving her van in the lane to D's right. D is driving his sedan straight through the "
                  "intersection when a pickup runs the red light from D's left.")
    assert said == [("car", "go_straight", "ego"), ("car", "go_straight", "right"),
                    ("car", "go_straight", "road_of_left_turn")]


def test_a_place_said_by_the_egos_possessive_is_the_place_said_by_ours():
    assert agents("The ego goes straight through the intersection. A van is in the lane to the ego's right.") == \
        agents("The ego goes straight through the intersection. A van is in the lane to our right.")


@pytest.mark.parametrize("prompt", ["The ego is a white SUV. A bus directly behind the SUV stops.",
                                    "Ego: white SUV, right lane. A bus directly behind the SUV stops."])
def test_the_noun_the_ego_is_said_to_be_names_it_again(prompt):
    assert agents(prompt) == [("bus", "stop", "back"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Event 7781 - Cam 3, all-way stop, overcast.\n+0.0 s  Subject: box truck SB, comes to a stop at the stop "
     "line.\n+4.2 s  Sedan from the west approach (subject's right) turns right.",
     [("car", "turn_right", "road_of_right_turn"), ("truck", "stop", "ego")]),
    ("RSU 41 | T-junction, give way sign | dusk\nobj A motorcycle = subject, stationary at the give-way line\n"
     "obj B car approaching from A's left, going straight through",
     [("car", "go_straight", "road_of_left_turn"), ("motorcycle", "stop", "ego")]),
    ("Zebra crossing monitor (unsignalised) | snow, dark\n#1 subject: taxi approaching northbound\n#2 pedestrian "
     "on the zebra, crossing in front of #1\n#3 jogger on the pavement to #1's left",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
      ("pedestrian", "on_the_sidewalk", "left")])])
def test_a_logs_subject_is_the_ego_by_its_key_and_its_label(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_vehicles_of_a_kind_told_apart_by_numbers_are_as_many():
    said = agents("Hero car turns left on the green. Oncoming picture car 10 turns right into the same street. Picture "
                  "car 11, also oncoming, goes straight through behind car 10.")
    assert said == [("car", "go_straight", "road_of_straight"), ("car", "turn_left", "ego"),
                    ("car", "turn_right", "road_of_straight")]


def test_a_shot_lists_extras_are_people_on_foot():
    said = agents("Hero car drives straight through on the green. Two ND extras hold on the right-hand corner "
                  "sidewalk.")
    assert said == [("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "right"),
                    ("pedestrian", "on_the_sidewalk", "right")]


def test_a_court_report_is_told_from_the_seat_of_the_driver_named_in_full():
    said = agents("The court heard that Alan Briggs, 47, was riding his motorcycle along the A59 when an oncoming "
                  "Honda Jazz, driven by Margaret Ellis, turned right across him into Hall Lane. Mr Briggs was thrown "
                  "over the bonnet.")
    assert said == [("car", "turn_right", "road_of_straight"), ("motorcycle", "go_straight", "ego")]


def test_children_in_the_back_of_the_car_are_passengers():
    assert agents("The ego drives on. Two children were in the back of the car at the time.") == \
        [("car", "go_straight", "ego")]


def test_a_crossing_denied_with_an_adverb_is_denied_and_nobody_crosses_at_it():
    scenario = lower("A man stepped out into the road in front of me, and there isn't even a crossing on that "
                     "stretch.").scenario
    assert "crosswalk" in scenario.road.without_objects
    assert [(a.type, a.action, a.relative_to_ego) for a in scenario.agents() if not a.is_ego] == \
        [("pedestrian", "cross_the_road", "front")]


def test_a_car_stopped_behind_the_speaker_is_another_car():
    assert agents("I was stopped at the zebra crossing. The car stopped behind me beeped its horn.") == \
        [("car", "stop", "back"), ("car", "stop", "ego")]


def test_a_fright_said_as_a_turn_is_no_turn():
    assert agents("I was stopped at the red with an ambulance coming across from the road on the left. Gave me "
                  "such a turn!") == [("ambulance", "go_straight", "road_of_left_turn"), ("car", "stop", "ego")]


def test_the_listeners_kin_a_teller_drives_is_a_passenger():
    assert agents("I had to drive your grandfather to his eye appointment. A young fellow on a moped was weaving "
                  "about just in front of me.") == [("car", "go_straight", "ego"),
                                                    ("motorcycle", "go_straight", "front")]


def test_a_lane_change_goes_to_the_side_said_after_the_lanes_it_names():
    assert agents("V1 (insured) was westbound on the expressway, three lanes. V1 changed lanes from lane 1 to lane 2, "
                  "to its right.") == [("car", "change_lane_to_right", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Unit 1 (subject vehicle) was stopped at a red signal. Unit 2, Engine 14 of the county fire department, came "
     "from the cross street on Unit 1's left and turned right.", ("firetruck", "turn_right", "road_of_left_turn")),
    ("The ego waits at the junction while Medic 12 comes from the road on the left.",
     ("ambulance", "go_straight", "road_of_left_turn"))])
def test_a_fire_or_ambulance_unit_named_by_its_call_sign(prompt, expected):
    assert expected in agents(prompt)


def test_two_friends_crossing_are_two_people_on_foot():
    said = agents("D waits at the stop line of a four-way stop while two friends, P and Q, cross in the crosswalk in "
                  "front of her.")
    assert said.count(("pedestrian", "cross_the_road", "near_the_crosswalk")) == 2


def test_a_subject_said_again_by_he_after_and_is_that_subject_only():
    said = agents("The ego car he is stopping in the right lane because the signal is red, and one taxi waiting in "
                  "left lane beside him, then the signal become green and the ego he go straight.")
    assert ("car", "stop", "left") in said


def test_lamps_flashing_and_the_travel_lane_are_no_movement():
    said = agents("Scenario class: stationary emergency vehicle in the travel lane. Our vehicle approaches a police "
                  "car stopped in our lane with its emergency lights flashing. Our vehicle slows, and then changes "
                  "lanes to the right to proceed around the police car.")
    assert ("police", "stop", "front") in said


def test_the_last_thing_waited_for_is_not_the_subject_after_then():
    assert stages("Unprotected left, no light, just a yield sign. It waited for 2 oncoming cars and a motorcycle "
                  "then went.")[1] == [("ego", "turn_left", None)]


def test_an_emoji_between_words_ends_a_sentence():
    said = agents("FSD handled a cut-in like a champ on my commute \U0001F64C semi in the right lane merged in "
                  "front of my car, 3 lanes \U0001F327\ufe0f and it just backed off smooth.")
    assert ("car", "go_straight", "ego") in said and not any(k[0] == "truck" and k[2] == "ego" for k in said)


@pytest.mark.parametrize("prompt, expected", [
    ("a \U0001F6B6 steps onto the zebra crossing in front of me",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("stuck behind a slow \U0001F69B on a country road",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "front")]),
    ("\U0001F691 w/ sirens coming up behind me", [("ambulance", "go_straight", "back"), ("car", "go_straight", "ego")]),
])
def test_a_picture_where_a_noun_would_stand_is_that_noun(prompt, expected):
    assert agents(prompt) == expected


def test_a_picture_after_its_own_noun_or_where_no_noun_could_stand_names_no_one_more():
    said = agents("2 kids \U0001F6B6\U0001F6B6 walking on the sidewalk to my right")
    assert said.count(("pedestrian", "on_the_sidewalk", "right")) == 2 and len(said) == 3
    said = agents("stopped at the stop sign, a cyclist came blowing thru from the left no helmet no lights \U0001F6B2")
    assert [a for a in said if a[0] == "cyclist"] == [("cyclist", "go_straight", "road_of_left_turn")]


def test_pictures_of_the_weather_and_arrows_read_as_words():
    scene = lower("early morning \U0001F327\ufe0f a car ahead brakes \u2192 i stop").scenario
    assert scene.weather.condition == "mid_rain" and len(scene.stages) == 2
    assert stages("a bus stopped ahead of me n a ped walks out in front of it, crossing from the right")[0] == [
        ("ego", "go_straight", None), ("bus", "stop", "front"), ("pedestrian", "cross_the_road", "front_right")]


@pytest.mark.parametrize("prompt, expected", [
    ("There was a lorry pulled in on the hard shoulder just ahead on the left with the hazards going.",
     ("truck", "stop", "front_left")),
    ("A squad car pulled in on the verge ahead on the left.", ("police", "stop", "front_left")),
])
def test_pulled_in_on_the_place_it_stands_is_stopped_there(prompt, expected):
    assert agents(prompt) == [("car", "go_straight", "ego"), expected]


def test_pulling_out_and_going_right_is_the_turn():
    assert stages("At the yield sign I waited for a lorry from the right to pass and then pulled out and went "
                  "right.")[1] == [("ego", "turn_right", None)]


@pytest.mark.parametrize("prompt, expected", [
    ("A truck ahead. I pulled out to pass it. Then I pulled back in.", "change_lane_to_right"),
    ("A truck ahead. I pulled out to pass it. Once I got past the truck I pulled back in.", "change_lane_to_right"),
    ("Stuck behind a slow truck. I pull out to overtake and there's a bakkie coming at me from the other way, then I "
     "had to duck back in behind the truck.", "change_lane_to_left"),
])
def test_pulling_back_in_returns_to_the_side_pulled_out_from(prompt, expected):
    assert stages(prompt)[-1] == [("ego", expected, None)]


@pytest.mark.parametrize("prompt, expected", [
    ("Suddenly angkot in front of ego stop for take passenger.", ("bus", "stop", "front")),
    ("One ojek in left lane beside ego.", ("motorcycle", "go_straight", "left")),
    ("One ibu is walking on sidewalk on left side.", ("pedestrian", "on_the_sidewalk", "left")),
    ("A bakkie is parked ahead of me.", ("car", "stop", "front")),
])
def test_road_users_named_in_the_words_of_other_countries(prompt, expected):
    assert expected in agents(prompt)


def test_a_pedestrian_crossover_is_a_crosswalk():
    scene = road("I'm coming up to one of those pedestrian crossovers and two kids start across.")
    assert "crosswalk" in scene.required_objects


@pytest.mark.parametrize("prompt, expected", [
    ("Test car waiting to turn right into a side road, three of us coming the other way going straight on. It "
     "has to let the last rider past.",
     [("car", "turn_right", "ego")] + [("cyclist", "go_straight", "road_of_straight")] * 3),
    ("Mini roundabout on the club route. I'm taking the lane going straight over with the test car sat behind me.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]),
    ("Sunday club run, four of us riding two abreast, test car coming up behind. Back marker shouts \"car back!\" and "
     "we single out.", [("car", "go_straight", "ego")] + [("cyclist", "go_straight", "front")] * 4),
])
def test_riders_telling_of_the_vehicle_under_test_are_cyclists_placed_from_it(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("I was crossing the road when the test car turned left towards me.",
     [("car", "turn_left", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("I was standing at the kerb waiting to cross when the AV pulled up and stopped for me.",
     [("car", "stop", "ego"), ("pedestrian", "on_the_sidewalk", "front")]),
])
def test_a_walker_telling_of_the_vehicle_under_test_is_a_pedestrian_by_it(prompt, expected):
    assert agents(prompt) == expected


def test_a_motorcyclist_telling_of_the_ego_is_not_read_as_a_cyclist():
    said = agents("Saw this from behind on my motorbike: the ego is the car in front of me, sat at the give way.")
    assert not any(a[0] == "cyclist" for a in said)


def test_after_with_the_ego_placed_by_the_subject_places_the_subject():
    assert agents("A cyclist rides in the lane with the ego right behind it.") == [
        ("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]
    assert ("cyclist", "go_straight", "front") in agents("A van is parked ahead with a cyclist behind it.")


def test_a_word_problems_speeds_in_metres_per_second_and_its_questions():
    lowered = lower("Car A is travelling at 22 m/s in the right-hand lane, accelerating at 1.5 m/s\u00b2. An ambulance "
                    "comes up behind it in the same lane.\n(a) How far behind car A is the ambulance after 3 s?\n"
                    "(b) Find the speed of the two vehicles.")
    assert [(a.type, a.action, a.relative_to_ego) for a in lowered.scenario.stages[0].agents[1:]] == [
        ("ambulance", "go_straight", "back")]
    assert lowered.scenario.stages[0].agents[0].speed.value == 79 and len(lowered.scenario.stages) == 1


def test_the_vehicle_named_first_in_a_lane_of_its_own_is_the_one_the_others_are_placed_by():
    assert agents("A car is travelling in the right-hand lane of a two-lane road. A bus pulls out into the car's "
                  "lane.") == [("bus", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]
    assert ("truck", "go_straight", "right") in agents(
        "Car in the left lane was sitting level with a semi in the right lane.")


@pytest.mark.parametrize("prompt, expected", [
    ("I was sat upstairs at the front. We were in the left lane and a hatchback that was in the lane to our right "
     "swung in right in front of the bus. The people standing downstairs were thrown about.",
     [("bus", "go_straight", "ego"), ("car", "change_lane_to_left", "right")]),
    ("Travelling back on the overnight coach last night, three lanes and we were in the inside lane, and a lorry in "
     "the middle lane right beside us started drifting over into our lane.",
     [("bus", "go_straight", "ego"), ("truck", "change_lane_to_right", "left")]),
])
def test_a_passenger_tells_of_the_bus_they_ride_as_the_ego(prompt, expected):
    assert agents(prompt) == expected


def test_a_bus_driver_named_or_a_bus_stop_is_no_bus_ridden():
    said = agents("We were stopped behind a yellow school bus with its red lights flashing. The bus driver waved.")
    assert ("car", "stop", "ego") in said


@pytest.mark.parametrize("prompt, expected", [
    ("A bus comes from the left, so the ego waits. When the bus has passed, then drives the ego in and turns left.",
     [("ego", "turn_left", None)]),
    ("The ego is in the middle lane. After that changes the ego lane to the right.",
     [("ego", "change_lane_to_right", None)]),
])
def test_a_verb_put_before_the_ego_as_in_swedish_or_german_is_the_egos(prompt, expected):
    assert stages(prompt)[-1] == expected


def test_the_ego_after_a_verb_that_follows_a_comma_stays_its_object():
    assert ("car", "go_straight", "back") in agents("A car comes from behind, passes the ego and cuts in.")


def test_coming_against_us_is_coming_the_other_way():
    assert ("car", "go_straight", "front_left") in agents("A car comes against me on the narrow street.")


def test_an_order_to_stay_behind_then_move_over_is_the_egos():
    assert stages("A lorry is ahead. Stay behind it, then move into the right lane.") == [
        [("ego", "go_straight", None), ("truck", "go_straight", "front")], [("ego", "change_lane_to_right", None)]]
    assert agents("A car stays behind us.") == [("car", "go_straight", "back"), ("car", "go_straight", "ego")]


def test_a_driver_who_signals_is_indicating_and_lane_n_of_m_counts_the_lanes():
    scene = lower("The host vehicle signals and changes lanes to the right.").scenario
    assert "traffic_light" not in scene.road.required_signals
    assert road("Lane 2 of 3. An HGV in lane 1 swerves into your lane.").lanes == 3


def test_running_the_yellow_is_at_a_signal_and_a_yellow_line_is_none():
    assert "traffic_light" in road("An oncoming pickup decides to run the yellow while the ego turns left."
                                   ).required_signals
    assert "traffic_light" not in road("A yellow taxi is parked on the yellow line ahead.").required_signals


@pytest.mark.parametrize("prompt, expected", [
    ("Cases:\na) When the light turns red, the ego stops.\nb) When the light is green, the ego turns left in front of "
     "an oncoming car.", ("car", "go_straight", "road_of_straight")),
    ("The red lights on the bus were flashing, so I stopped, but the car behind me went around me and passed the bus.",
     ("car", "stop", "ego")),
    ("Vehicle B drives alongside the ego and then enters the ego lane.", ("car", "change_lane_to_right", "front_left")),
    ("The police officer signals the ego to stop.", ("car", "stop", "ego")),
    ("We were driving around Lake Garda when a scooter overtook us on the left.",
     ("motorcycle", "go_straight", "back_left")),
])
def test_what_the_newer_readings_leave_as_it_was(prompt, expected):
    """Lettered cases that are no questions, a bus the teller does not ride, 'the ego lane' after a verb, an order
    signalled to someone, 'Lake Garda': each read as before the readings of pictures, passengers and word order."""
    assert expected in agents(prompt)


def test_a_test_written_with_we_about_cyclists_has_no_cyclist_teller():
    said = agents("In this test we check that the ego vehicle overtakes two cyclists riding two abreast with enough "
                  "clearance.")
    assert [a for a in said if a[0] == "cyclist"] == [("cyclist", "go_straight", "front")] * 2


def test_an_acceleration_spelled_out_an_arrow_between_values_and_kin_in_pictures_are_no_speed_stage_or_agent():
    scene = lower("A car ahead accelerates from rest at 2 meters per second squared.").scenario
    assert all(a.speed is None for a in scene.agents())
    scene = lower("Speed drops 80 \u2192 30 km/h as the ego enters the work zone behind a truck.").scenario
    assert len(scene.stages) == 1
    assert not any(a[0] == "pedestrian" for a in agents(
        "Me and my \U0001F469 were driving home when a cyclist swerved into our lane."))


@pytest.mark.parametrize("prompt, expected", [
    ("A car on the left of the ego and one on the right.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "left"), ("car", "go_straight", "right")]),
    ("Ego in lane 2. Another car in lane 1 alongside the ego and one in lane 3 just ahead of it.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "front_right"), ("car", "go_straight", "left")]),
    ("Two cars: one on the left of the ego and one on the right.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "left"), ("car", "go_straight", "right")]),
])
def test_and_one_with_a_place_of_its_own_is_one_more_of_the_kind(prompt, expected):
    assert agents(prompt) == expected


def test_a_van_unloading_outside_a_shop_stands_and_the_shop_and_the_trolley_are_no_one():
    assert agents("I'm in the right lane, level with a van unloading outside a shop in the left lane. A bloke with a "
                  "sack trolley walks across in front of me.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "left"), ("pedestrian", "cross_the_road", "front")]


def test_the_guy_honking_behind_an_ego_at_the_light_stands():
    assert ("car", "stop", "back") in agents(
        "My car was first at the red light and stayed stopped. Better than the guy behind me honking.")


def test_ones_turn_in_an_order_is_no_manoeuvre():
    said = agents("The AV is going straight through a crossroads on a green light. A bus is waiting at the red light "
                  "on the road to the left. Blind pedestrians listen to know when it is their turn.")
    assert ("bus", "stop", "road_of_left_turn") in said


@pytest.mark.parametrize("prompt", [
    "FSD handled a cut-in like a champ. A semi in the right lane merged right in front of my car on I-5, 3 lanes, and "
    "my car just backed off smooth."])
def test_right_in_front_is_how_close_and_backing_off_is_no_place(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("truck", "change_lane_to_left", "right")]


def test_asking_who_someone_was_keeps_them_in_the_scene():
    said = agents("Who was the absolute idiot on the motorbike weaving in and out of traffic last night? I was sat at "
                  "the lights and he cut in right in front of me from the right-hand lane.")
    assert ("car", "stop", "ego") in said and any(k[0] == "motorcycle" and k[1] == "change_lane_to_left"
                                                    for k in said)


def test_a_car_ahead_is_not_the_one_beside():
    said = agents("The ego vehicle is traveling on a highway at night, with a pickup in the right lane beside it, when "
                  "the car ahead of the ego suddenly brakes hard and stops.")
    assert ("car", "go_straight", "right") in said and ("car", "stop", "front") in said


def test_a_plain_person_in_a_vehicle_is_that_vehicle():
    said = agents("I had stopped at the four-way stop when a young fellow in a pickup came from the road on my right "
                  "and turned left in front of me.")
    assert said == [("car", "stop", "ego"), ("car", "turn_left", "road_of_right_turn")]


def test_a_plain_person_who_crosses_is_kept_though_at_the_wheel_words_name_them():
    said = agents("I stopped to let an old gentleman with a stick cross, only for a young man on a motorbike to come "
                  "up behind me.")
    assert any(k[0] == "pedestrian" for k in said)  # (a guard: plain people at the wheel are not dropped as roles)


def test_the_drivers_of_a_town_are_a_kind():
    assert agents("You would not believe the drivers down here. I waited at the stop sign when a van came from the "
                  "right and turned left.") == [("car", "stop", "ego"), ("car", "turn_left", "road_of_right_turn")]


def test_a_records_unit_named_in_capitals_is_the_ego():
    said = agents("Event: Harsh Braking | 2024-05-14 14:32:07 | Veh: Unit 212 (Ford Transit) | Spd 62 -> 19 km/h | "
                  "Posted 60 km/h. Lead vehicle braked suddenly to a full stop in ego lane.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("car", "stop", "front")]


def test_a_car_in_front_after_a_lead_vehicle_is_that_vehicle():
    assert agents("Lead vehicle braked suddenly to a full stop in ego lane. Driver comment: car in front slammed on "
                  "for no reason.") == [("car", "go_straight", "ego"), ("car", "stop", "front")]


@pytest.mark.parametrize("prompt", [
    "Sitting at the green waiting to make my left with the plow, an SUV coming the other way slid through.",
    "I was stopped first with the truck and a pickup from the road on my right turned left in front of me.",
    "I had the truck stopped at the yield sign when the fire engine came along from my right.",
    "Small hatchback stopped on the right shoulder ahead of me. Slowed the truck down and gave them room."])
def test_the_vehicle_a_speaker_works_with_or_handles_is_the_egos(prompt):
    assert any(k[0] == "truck" and k[2] == "ego" for k in agents(prompt))


@pytest.mark.parametrize("prompt", ["I collided with the truck.", "The bus stopped. I stopped the car behind the bus."])
def test_a_vehicle_met_or_placed_is_not_the_speakers(prompt):
    said = agents(prompt)
    assert ("car", "stop" if "stopped" in prompt else "go_straight", "ego") in said and len(said) == 2


def test_the_speakers_own_vehicle_named_again_is_not_the_one_named_before():
    said = agents("Semi pulled over on the right shoulder up ahead. I moved the truck over a lane to give him room.")
    assert any(k[0::2] == ("truck", "ego") for k in said) and ("truck", "stop", "front_right") in said


def test_the_van_of_one_the_speaker_places_is_theirs():
    said = agents("I'm coming past the station and a girl steps out onto the zebra, so I had to stop dead. And the "
                  "eejit behind me in the white van was flying.")
    assert ("car", "go_straight", "back") in said


@pytest.mark.parametrize("prompt, expected", [
    ("A semi pulled over on the right shoulder up ahead.", ("truck", "stop", "front_right")),
    ("A car pulled over in front of me.", ("car", "change_lane_to_right", "front"))])
def test_pulled_over_on_a_place_stands_there(prompt, expected):
    assert expected in agents(prompt)


def test_the_listener_addressed_is_not_the_ego():
    said = agents("You won't believe this, a guy on a motorcycle in January. Passed me on the left doing 60 while I'm "
                  "salting the right lane in the truck.")
    assert sorted(said) == [("motorcycle", "go_straight", "back_left"), ("truck", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, ego", [
    ("Sitting at the bus stop on the corner waiting for the 43, I watched a woman in a little hatchback nearly get "
     "hit. She was driving along the main road and a motorbike came flying out of the side road on her right.",
     ("car", "go_straight", "ego")),
    ("In broad daylight, mind you. I was across the street outside the pharmacy and watched a car turning right at "
     "the corner nearly take out two kids on bicycles who were riding across in the crosswalk.",
     ("car", "turn_right", "ego")),
    ("From the bench outside the chemist's I watched a little red car come out of Church Street and turn left onto "
     "the main road.", ("car", "turn_left", "ego"))])
def test_a_teller_watching_from_the_roadside_is_no_agent(prompt, ego):
    said = agents(prompt)
    assert ego in said and not any(k[0] == "pedestrian" and k[1] != "cross_the_road" for k in said)


def test_a_teller_on_a_scooter_halfway_over_a_zebra_is_on_foot():
    said = agents("I was halfway over the zebra crossing outside the post office on my scooter when a silver car came "
                  "straight at me and never slowed down.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_what_followed_the_vehicle_a_teller_met_follows_the_ego():
    said = agents("I'd got a good way over the zebra on the Parade when a blue Nissan came straight through without "
                  "stopping, and a taxi right behind it did the very same. My daughter wants me to give the scooter "
                  "up but I won't.")
    assert sorted(said) == [("car", "go_straight", "back"), ("car", "go_straight", "ego"),
                            ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_a_place_named_for_people_names_none_and_a_teller_who_froze_stands():
    said = agents("I was on the zebra by the infants' school when a police car came tearing down the hill, and I just "
                  "froze in the middle.")
    assert sorted(said) == [("pedestrian", "stop", "near_the_crosswalk"), ("police", "go_straight", "ego")]


def test_a_teller_going_over_on_the_green_man_crosses_at_a_crossing():
    said = agents("At the lights I was going over on the green man when a car turning right out of the High Street "
                  "cut across right in front of me.")
    assert ("car", "turn_right", "ego") in said and ("pedestrian", "cross_the_road", "near_the_crosswalk") in said


def test_a_plurals_possessive_is_one_word():
    assert [(t.word, t.possessive) for t in tokenize("the infants' school")] == [
        ("the", False), ("infants", True), ("school", False)]


@pytest.mark.parametrize("prompt", [
    "Police are appealing for witnesses after a van ran the red light in front of me.",
    "Police say they are aware of the footage. A van ran the red light in front of me.",
    "A van ran the red light in front of me. Police are urging drivers to slow down."])
def test_police_who_speak_of_a_scene_are_not_in_it(prompt):
    assert not any(k[0] == "police" for k in agents(prompt))


def test_a_recovery_truck_on_its_way_is_not_in_the_scene():
    said = agents("A stalled SUV is sitting in my lane ahead. Tow truck is on the way.")
    assert not any(k[0] == "truck" for k in said) and ("car", "stop", "front") in said


def test_he_after_a_vehicle_placed_by_him_is_the_one_placed_by():
    said = agents("An ambulance came up behind him in the outside lane and he moved across into the left lane to let "
                  "it through.")
    assert ("car", "change_lane_to_left", "ego") in said and any(k[0] == "ambulance" for k in said)


def test_riding_the_scooter_with_no_subject_is_the_speakers():
    said = agents("riding the lime scooter home down the high street last night, and some taxi sat right on my back "
                  "wheel the whole way.")
    assert sorted(said) == [("car", "go_straight", "back"), ("motorcycle", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", [
    "3 lane hwy, im in the middle, box truck in the right lane ahead of me merges into my lane. then i hit the "
    "blinker and it moved me over to the left lane on its own",
    "delivery truck double parked in my lane and OP just sat behind it. then i nudged the blinker and OP took me "
    "around it into the left lane by itself"])
def test_a_system_moving_the_speaker_moves_the_ego(prompt):
    assert stages(prompt)[-1] == [("ego", "change_lane_to_left", None)]


@pytest.mark.parametrize("prompt", [
    "i was sitting at a stop sign waiting to turn left and 2 cars were coming from the opposite direction. once they "
    "passed i took over and made the left",
    "The ego waits at the stop line. Once the oncoming car passes the ego turns left."])
def test_a_condition_ends_where_the_ego_speaks_again(prompt):
    said = stages(prompt)
    assert said[0][0] == ("ego", "stop", None) and said[1] == [("ego", "turn_left", None)]


def test_a_list_heading_key_names_no_agent():
    said = agents("Functional scenario FS-HW-03, cut-in from the left. Road layer: motorway, three lanes per "
                  "direction. Traffic participants: the ego vehicle travels in the middle lane at constant speed; a "
                  "passenger car drives in the left adjacent lane slightly ahead of the ego and performs a lane "
                  "change into the ego lane.")
    assert sorted(said) == [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]


def test_a_named_street_joined_from_a_side_is_the_side_road():
    said = agents("I proceeded through the junction with Hall Lane on a green light. A car came out of Hall Lane on my "
                  "right and went straight through the red light at speed, directly in front of me.")
    assert ("car", "go_straight", "road_of_right_turn") in said


@pytest.mark.parametrize("prompt", ["Environment: light snowfall, dusk. A car stops ahead.",
                                    "There was light traffic and a car stopped ahead."])
def test_light_before_weather_or_traffic_is_how_much(prompt):
    assert "traffic_light" not in road(prompt).required_signals


def test_a_capitalised_name_is_never_read_as_a_slip_of_a_known_word():
    assert not any(k[0] == "truck" for k in agents("A white BMW cut in front of me on the M1 near Kegworth."))
    assert [t.word for t in tokenize("a pedestrain crossed near Kegworth")] == [
        "a", "pedestrian", "crossed", "near", "kegworth"]


def test_the_man_driving_a_truck_named_before_is_not_the_speaker():
    said = agents("I was driving to work on Tuesday morning. A box truck came the other way. The man driving the truck "
                  "braked hard.")
    assert ("car", "go_straight", "ego") in said and not any(k[0] == "truck" and k[2] == "ego" for k in said)


def test_a_vehicle_coming_out_of_the_street_turned_into_is_at_the_destination():
    said = agents("As I was turning right into Cedar Close from the main road, a white van came out of Cedar Close "
                  "at speed.")
    assert ("car", "turn_right", "ego") in said and any(k[0] == "car" and k[2] == "at_the_destination" for k in said)


def test_a_teller_holding_traffic_at_a_works_board_is_on_foot_and_no_agent():
    said = agents("Evening shift, sun low. The number 7 bus was stopped at my board at the front of the queue with two "
                  "cyclists waiting behind it. When I spun it to GO the bus pulled off and both cyclists followed it.")
    assert any(k[0] == "bus" and k[2] == "ego" for k in said) and not any(k[0] == "pedestrian" for k in said)


def test_and_before_a_pronoun_with_its_verb_opens_a_clause():
    said = agents("An ambulance came up behind him in the outside lane and he moved across into the left lane to let "
                  "it through.")
    assert sorted(said) == [("ambulance", "go_straight", "back_right"), ("car", "change_lane_to_left", "ego")]


def test_the_car_of_a_driver_read_as_the_ego_is_the_ego():
    said = agents("A driver had to stop when a man walked out across the road in front of her car.")
    assert sorted(said) == [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "front")]


def test_an_inverted_subject_after_a_whole_place_takes_its_verb_and_place():
    said = agents("The ego drives on a country road. At the same time comes in the opposite direction a bus.")
    assert sorted(said) == [("bus", "go_straight", "front_left"), ("car", "go_straight", "ego")]
    said = agents("The ego drives on the left lane. In front of the ego stand already two cars.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("car", "stop", "front"), ("car", "stop", "front")]
    said = agents("The ego drives. Then comes to a stop behind a truck.")  # 'behind' takes the truck: no inversion
    assert ("car", "stop", "ego") in said and any(k[0] == "truck" and k[2] == "front" for k in said)


def test_a_junctions_arms_named_as_approaches():
    said = agents("A pickup on the right approach turns left across the intersection; the ego waits at its stop line.")
    assert sorted(said) == [("car", "stop", "ego"), ("car", "turn_left", "road_of_right_turn")]


def test_coming_towards_the_ego_on_the_road_it_turned_into_is_at_the_destination():
    said = agents("The ego turns left. On the street where I turned in, two kids on bikes came towards me.")
    assert sorted(said) == [("car", "turn_left", "ego"), ("cyclist", "go_straight", "at_the_destination"),
                            ("cyclist", "go_straight", "at_the_destination")]


def test_an_unknown_word_after_a_paint_colour_that_drives_is_a_car():
    assert sorted(agents("A silver Zafira pulled out in front of me.")) == [
        ("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]
    assert sorted(agents("A red Kuga overtook me on the right.")) == [
        ("car", "go_straight", "back_right"), ("car", "go_straight", "ego")]
    said = agents("I was driving down Elm Street. A guy in a black hoodie stepped off the curb in front of me.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]  # his clothes


def test_a_passenger_who_gets_off_and_crosses_is_a_pedestrian():
    said = agents("The ego waits behind a bus at the stop, and a passenger who has just got off walks across the road "
                  "in front of the bus.")
    assert sorted(said) == [("bus", "stop", "front"), ("car", "stop", "ego"), ("pedestrian", "cross_the_road", "front")]
    said = agents("You're following a bus. It stops at a bus stop and one of the passengers getting off walks straight "
                  "out in front of it to cross the road.")
    assert ("pedestrian", "cross_the_road", "front") in said and ("bus", "stop", "front") in said
    assert not any(k[0] == "pedestrian" for k in agents("A bus full of passengers stopped ahead of the ego."))


def test_a_new_subject_that_is_no_agent_takes_no_verb_from_the_one_before():
    assert sorted(agents("A bus stops ahead and a dog runs out.")) == [("bus", "stop", "front"),
                                                                        ("car", "go_straight", "ego")]


def test_a_driver_standing_by_the_vehicle_is_on_foot():
    said = agents("A truck is stopped on the hard shoulder ahead on the right with its driver standing beside it "
                  "on the shoulder.")
    assert ("truck", "stop", "front_right") in said and any(k[0] == "pedestrian" for k in said)


def test_people_named_by_trade_or_as_a_figure_are_on_foot():
    assert agents("A vendor was walking on the sidewalk to my right.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "right")]
    assert ("pedestrian", "cross_the_road", "front") in agents(
        "A figure in dark clothes steps off the kerb and walks across in front of me.")
    assert ("pedestrian", "cross_the_road", "front") in agents("Elderly gent crossing, taking his time.")


def test_a_person_before_a_streets_suffix_names_the_street():
    said = agents("He drove straight across the crossroads at Northgate and Vicar Lane against a red signal.")
    assert not any(k[0] == "pedestrian" for k in said)


def test_an_agents_noun_naming_another_scenario_is_no_agent():
    said = agents("The ego drives straight; a truck cuts in from the right. This is similar to the bus scenario we did "
                  "last week.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("truck", "change_lane_to_left", "front_right")]


def test_after_a_relative_clause_a_verb_done_to_its_noun_is_the_main_subjects():
    assert stages("The ego slows down behind a truck that is stopped in its lane, then changes to the left lane to "
                  "pass it.") == [[("ego", "go_straight", None), ("truck", "stop", "front")],
                             [("ego", "change_lane_to_left", None)]]


def test_the_same_direction_as_the_ego_is_a_likeness_not_a_clause():
    said = agents("A cyclist traveling in the same direction as the ego, ahead on the right, swerves left to avoid a "
                  "pothole.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("cyclist", "change_lane_to_left", "front_right")]


def test_a_request_to_make_the_ego_a_kind_sets_its_kind():
    assert agents("Make the ego a bus that stops at a bus stop.") == [("bus", "stop", "ego")]
    assert agents("Let the ego be a truck. It turns left.") == [("truck", "turn_left", "ego")]


def test_a_turn_asked_for_with_an_article_is_the_egos():
    assert sorted(agents("Create an unprotected left turn with an oncoming truck.")) == [
        ("car", "turn_left", "ego"), ("truck", "go_straight", "road_of_straight")]
    assert agents("How do I model the turn in esmini?") == [("car", "go_straight", "ego")]  # the tool asked about


def test_an_on_ramp_joins_from_the_right():
    said = agents("A car on the on-ramp merges in front of the ego.")
    assert ("car", "go_straight", "ego") in said and any(k[0] == "car" and k[1] == "change_lane_to_left" and
                                                         k[2].endswith("right") for k in said)


def test_overtaking_one_already_in_the_other_lane_keeps_the_egos_lane():
    said = agents("My car drive on the road with 2 lanes in each direction. On the right lane, little bit in front of "
                  "me, is going slowly a truck and I am overtaking him on the left lane.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("truck", "go_straight", "front_right")]
    assert ("car", "change_lane_to_left", "ego") in agents("A van is parked on the right. I overtake it on the left.")
    assert ("bus", "stop", "front") in agents("There is a microbus stopped in front of the ego.")


def test_one_stepping_out_from_a_row_of_parked_cars_on_one_side_comes_from_that_side():
    said = agents("It's a 20 mph limit through town with a line of parked cars on your right. A kid runs out from "
                  "between them, right in front of me.")
    assert ("pedestrian", "cross_the_road", "front_right") in said
    said = agents("A child in a navy coat suddenly ran out between the parked cars right in front of me.")
    assert ("pedestrian", "cross_the_road", "front") in said  # 'right in front': how near, no side
    assert ("pedestrian", "cross_the_road", "front") in agents("Cars are parked on both sides. A child runs out from "
                                                               "between them.")


def test_a_vehicle_stood_on_the_shoulder_is_met_by_the_ego_and_stands():
    said = agents("There was a broken-down car on the hard shoulder and a police car behind it.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("car", "stop", "front_right"),
                            ("police", "stop", "front_right")]
    assert ("cyclist", "go_straight", "right") in agents("A cyclist is on the shoulder to the right of the ego.")


def test_the_infinitive_after_a_participle_is_the_participles_owners():
    assert sorted(agents("The ego comes to a stop behind a car waiting to turn left.")) == [
        ("car", "stop", "ego"), ("car", "stop", "front")]


def test_driving_past_a_queue_in_the_other_lane_keeps_the_egos_lane():
    said = agents("There is a queue of four cars in the left lane, and the ego drives past them in the right lane.")
    assert ("car", "go_straight", "ego") in said and said.count(("car", "stop", "left")) == 4


def test_a_count_with_a_word_before_its_noun_lists_the_members_after_a_colon():
    assert sorted(agents("2 NPC cars: one in front of the ego, one behind.")) == [
        ("car", "go_straight", "back"), ("car", "go_straight", "ego"), ("car", "go_straight", "front")]


def test_a_reports_opening_sentence_passed_on_someone_is_no_scene():
    said = agents("A pensioner who turned across the path of a motorcyclist has been banned from driving for a year. "
                  "The court heard that the motorcyclist was riding along the A59 when an oncoming car turned right "
                  "across him.")
    assert not any(k[0] == "pedestrian" for k in said)
    assert ("car", "turn_right", "road_of_straight") in said
    assert any(k[0] == "pedestrian" for k in agents("A pedestrian has been hurt. A car hit her as she crossed."))


def test_a_speaker_who_rides_after_and_rides_a_motorbike():
    assert agents("You ease off and ride slowly towards the crossing.")[0][:1] == ("motorcycle",)
    assert ("car", "go_straight", "ego") in agents("My uber driver was fast. I got in and ride was smooth, then a bus "
                                                   "pulled out.")


def test_the_lane_and_the_car_of_the_ego_said_with_of():
    said = agents("Suddenly one motorcycle is entering in the lane of the ego from the right.")
    assert said == [("car", "go_straight", "ego"), ("motorcycle", "change_lane_to_left", "front_right")]
    said = agents("The car of the ego is turning right and one cyclist is going straight in his right side.")
    assert sorted(said) == [("car", "turn_right", "ego"), ("cyclist", "go_straight", "right")]


def test_each_lane_said_to_have_someone_is_a_clause_of_its_own():
    said = agents("Ego is in the middle lane. Left lane has one bus, right lane has one truck.")
    assert sorted(said) == [("bus", "go_straight", "left"), ("car", "go_straight", "ego"),
                            ("truck", "go_straight", "right")]


def test_a_cyclist_heading_across_the_egos_heading_rides_the_road_on_that_side():
    said = agents("The ego heads east; a cyclist heading north goes straight across the junction.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("cyclist", "go_straight", "road_of_right_turn")]


def test_a_person_standing_on_the_shoulder_stands_on_the_road_not_a_pavement():
    said = agents("A truck is stopped on the hard shoulder ahead with its driver standing beside it on the shoulder.")
    assert ("pedestrian", "stop", "front_right") in said
    assert ("pedestrian", "on_the_sidewalk", "right") in agents("A man stands on the pavement on the right.")


def test_alongside_wins_over_the_blind_spot():
    said = agents("Ego turns right at a signalised intersection with a cyclist riding alongside on our right, in the "
                  "blind spot, going straight through.")
    assert ("cyclist", "go_straight", "right") in said
    assert ("motorcycle", "go_straight", "back_left") in agents("A motorbike is in the ego's blind spot on the left.")


def test_a_relative_after_a_place_phrase_ending_in_a_pronoun_is_about_the_one_placed():
    said = agents("An oncoming bus is waiting to turn left and hides a motorbike next to it, which turns left across "
                  "our path.")
    assert ("bus", "stop", "road_of_straight") in said and ("motorcycle", "turn_left", "road_of_straight") in said


def test_one_more_added_to_a_heading_line_is_not_the_headings_agent():
    said = agents("Pedestrian standing on the pavement right next to a crosswalk, not crossing, as the ego drives "
                  "past, plus a jogger on the right-hand sidewalk just ahead of us running the same way.")
    assert sorted(k for k in said if k[0] == "pedestrian") == [
        ("pedestrian", "on_the_sidewalk", "front_right"), ("pedestrian", "on_the_sidewalk", "near_the_crosswalk")]


def test_a_manoeuvre_someone_is_kept_from_is_not_made():
    assert agents("A truck in the left lane keeps the ego from changing lanes.") == [
        ("car", "go_straight", "ego"), ("truck", "go_straight", "left")]
    assert agents("A car alongside in the left lane stops the ego from moving over.") == [
        ("car", "go_straight", "ego"), ("car", "go_straight", "left")]
    assert ("car", "change_lane_to_left", "ego") in agents("The ego changes lanes to the left to pass a truck.")


def test_blocking_the_escape_path_is_driving_alongside():
    said = agents("Gap - SV following a lead vehicle that brakes to a stop, wet road at night, POV alongside in the "
                  "adjacent left lane blocking the escape path.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("car", "go_straight", "left"), ("car", "stop", "front")]


def test_the_lead_car_is_not_one_named_beside_the_ego():
    assert agents("A van drives on the left. The lead car brakes.") == [
        ("car", "go_straight", "ego"), ("car", "go_straight", "left"), ("car", "stop", "front")]
    assert agents("A car is ahead of the ego in the left lane. The lead car brakes.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front_left")]


def test_a_lane_count_with_a_plus_is_at_least_that_many():
    assert road("Truck cut-in from the right adjacent lane on a 3+ lane highway.").lanes == 3
    assert road("A 4+ lanes road with a car ahead.").lanes == 4


def test_the_exit_arm_is_where_the_ego_heads_and_mid_crossing_is_crossing():
    assert ("cyclist", "go_straight", "at_the_destination") in agents(
        "The ego turns right at the roundabout while a cyclist rides on the ego's exit arm.")
    said = agents("No coverage for: ego going straight over a ladder crosswalk with one ped standing on the pavement "
                  "and another already mid-crossing from the left.")
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in said and len(said) == 3


def test_what_perception_makes_of_road_users_is_no_one_on_the_road():
    said = agents("A bus has pulled in at a stop in the right-hand lane ahead, and three people walk out in front of "
                  "it and cross our lane from right to left. Check we keep three separate pedestrian tracks instead "
                  "of one merged blob.")
    assert said.count(("pedestrian", "cross_the_road", "front_right")) == 3 and len(said) == 5
    assert agents("Can we get an env where the ego drives down a street and there's a stopped delivery van in its "
                  "lane ahead?") == [("car", "go_straight", "ego"), ("car", "stop", "front")]


def test_a_tool_named_after_a_runner_is_no_one_on_foot():
    assert agents("Is this doable with the Python API alone, or do I need ScenarioRunner for the light timing? The "
                  "ego waits at a red light.") == [("car", "stop", "ego")]
    assert ("pedestrian", "cross_the_road", "front") in agents("A runner crosses in front of the ego.")


def test_the_ego_in_a_queue_of_counted_cars_waits_behind_them_standing():
    said = agents("Heavy traffic: the ego is in a queue of five cars at a red light.")
    assert said.count(("car", "stop", "front")) == 5 and ("car", "stop", "ego") in said


def test_the_street_the_ego_turns_into_said_with_its_direction_gives_the_egos_turn():
    assert agents("The oncoming truck turns right into the same street the ego is turning left into.") == [
        ("car", "turn_left", "ego"), ("truck", "turn_right", "road_of_straight")]
    assert agents("A pedestrian crosses the road I am turning right into.") == [
        ("car", "turn_right", "ego"), ("pedestrian", "cross_the_road", "at_the_destination")]


def test_what_one_is_made_to_do_and_where_is_theirs():
    assert agents("A delivery van double-parked on the right forces the ego to pass it in the oncoming lane.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front_right")]
    assert agents("A truck stopped ahead makes the ego change to the left lane.") == [
        ("car", "change_lane_to_left", "ego"), ("truck", "stop", "front")]
    assert ("motorcycle", "change_lane_to_right", "front_left") in agents(
        "can u make a scooter cutting in from the left lane right in front of ego, snowy night")


def test_after_a_reason_clause_the_one_who_acted_acts_again():
    assert agents("The ego slows down because a tractor is driving slowly ahead, then overtakes it when the "
                  "oncoming lane is clear.") == [("car", "go_straight", "ego"), ("truck", "go_straight", "front")]


def test_a_chat_message_that_says_the_whole_scene_again_is_read_from_there_with_its_weather():
    lowered = lower("and also add a scooter. the whole thing: ego car turns right into a side street with a yield "
                    "sign, a scooter coming from the road on the right, and a van parked in the side street we're "
                    "turning into. night, heavy rain")
    assert len(list(lowered.scenario.agents())) == 3
    lowered = lower("Same as our right turn at a stop sign, but swap the cyclist for a motorcycle and make it foggy at "
                    "dawn. So: the ego comes to a stop at the stop sign while a motorcycle comes straight through "
                    "from the road on the left, then the ego turns right.")
    assert (lowered.scenario.weather.condition, lowered.scenario.weather.time) == ("fog", "dawn")
    assert not any(a.type == "cyclist" for a in lowered.scenario.agents())


def test_the_extra_one_is_one_more():
    said = agents("so: ego turns right at the traffic lights, a car waiting on the street we turn into, and the extra "
                  "car following behind us")
    assert ("car", "go_straight", "back") in said and ("car", "stop", "at_the_destination") in said


def test_both_after_a_pair_just_counted_is_the_pair():
    assert agents("ego on a 3 lane highway, two cars ahead of us in our lane both braking to a stop") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front"), ("car", "stop", "front")]


def test_a_manoeuvre_naming_a_review_is_no_manoeuvre():
    said = agents("For the merge-safety review, please build a scene in which the ego car drives in the right lane "
                  "and a truck on the hard shoulder ahead pulls out into our lane.")
    assert ("car", "go_straight", "ego") in said


def test_the_lane_one_swerved_in_from_stays_its_lane_when_the_ego_stops_behind_it():
    said = agents("A sedan just ahead of the ego in the left lane swerves into our path and stops, and our vehicle "
                  "must come to a stop behind it.")
    assert ("car", "block_the_ego", "front_left") in said


def test_in_the_lane_to_its_right_places_the_one_named_beside_the_subject():
    said = agents("Ego turning right at a signalised intersection with a cyclist going straight in the lane to its "
                  "right.")
    assert ("cyclist", "go_straight", "right") in said
    said = agents("I worry for these delivery lads on mopeds weaving through the traffic on a three-lane city road. "
                  "One of them cuts in front of the car from the lane on its left.")
    assert not any(k[0] == "car" and k[2] == "left" for k in said)  # where the moped comes from, not the car's lane


def test_the_one_the_ego_moves_in_behind_is_in_the_lane_it_moves_into():
    assert agents("ego merges into the right lane behind a slow van") == [
        ("car", "change_lane_to_right", "ego"), ("car", "go_straight", "front_right")]
    assert ("truck", "go_straight", "front") in agents("You are following a lorry and intend to pull out into the "
                                                       "right-hand lane. Get as close as possible behind the lorry.")


def test_just_ahead_after_cutting_into_the_egos_lane_is_where_the_cut_in_ends():
    assert ("car", "change_lane_to_left", "right") in agents(
        "A van travelling in the lane to our right cut into the ego's lane just ahead of it.")


def test_a_bike_lane_runs_along_the_kerb():
    assert ("cyclist", "go_straight", "right") in agents("The ego yields to a cyclist on the bike lane before "
                                                         "turning right.")
    asked = road((CORPUS / "dev" / "municipal_311_request" / "11.txt").read_text(encoding="utf-8"))  # "... Please
    # model it and put in a bike lane."
    assert asked.lanes in (None, 1)  # a bike lane asked to be put in is where no one is yet


def test_flashing_its_lights_is_said_of_the_one_that_flashes_and_ends_no_clause_of_the_ego():
    assert agents("The car coming the other way flashes its lights and the ego turns left in front of it.") == [
        ("car", "go_straight", "road_of_straight"), ("car", "turn_left", "ego")]


def test_a_state_said_before_the_ego_is_the_egos():
    assert agents("A cyclist overtakes the stationary ego on the right and then turns right at the junction.") == [
        ("car", "stop", "ego"), ("cyclist", "turn_right", "back_right")]  # (the turn its sentence goes on to)
    assert ("truck", "go_straight", "back_right") in agents("A truck passed ego on the right.")


def test_walking_a_dog_across_the_road_is_crossing_it():
    assert ("pedestrian", "cross_the_road", "front") in agents("A man walks his dog across the road in front of "
                                                               "the ego.")


def test_a_skateboarder_rolling_into_the_road_rides_across_it():
    assert ("cyclist", "cross_the_road", "front_left") in agents("A teenager on a skateboard rolls into the road from "
                                                                 "the left.")


def test_with_one_on_its_left_places_that_one_beside_the_subject():
    said = agents("Heavy traffic on a three-lane highway: the ego is in the center lane with a truck on its left and "
                  "a car on its right.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("car", "go_straight", "right"),
                            ("truck", "go_straight", "left")]
    assert ("truck", "go_straight", "front") in agents("The ego passes the slow truck on its left.")


def test_dodge_is_a_verb_unless_a_determiner_makes_it_the_make():
    assert agents("The ego drives on. A cyclist dodging a pothole swerves into its lane.") == [
        ("car", "go_straight", "ego"), ("cyclist", "change_lane_to_left", "front_right")]
    assert agents("The ego drives straight. A pedestrian darts out and the ego has to dodge him.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]
    assert ("car", "change_lane_to_left", "front_right") in agents("The ego drives straight; a red Dodge pulls out "
                                                                   "from the right.")


def test_the_noun_after_a_lane_and_behind_places_the_subject_and_takes_no_verb():
    assert agents("Ego in the middle lane. A motorcycle in the left lane behind ego cuts into our lane.") == [
        ("car", "go_straight", "ego"), ("motorcycle", "change_lane_to_right", "back_left")]


def test_lead_alone_before_a_finite_verb_is_the_lead_vehicle_said_again():
    assert agents("Ego following a lead vehicle at 40 mph, lead slams on its brakes and comes to a full stop.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front")]
    assert agents("Ego follows a truck; this could lead to a crash.") == [
        ("car", "go_straight", "ego"), ("truck", "go_straight", "front")]


def test_a_test_tracks_soft_targets_are_cars():
    assert agents("CCRb, 12 m headway. GST brakes hard, down to a standstill.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front")]


def test_two_compound_names_of_one_last_word_name_two_agents():
    said = agents("VUT approaching the zebra. Kid dummy waiting at the kerb by the crossing, steps out and crosses. "
                  "Adult dummy on the footway to the right further up, just walking along, not crossing.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
                            ("pedestrian", "on_the_sidewalk", "front_right")]
    assert ("pedestrian", "on_the_sidewalk", "right") in agents(
        "The VUT drives. Child dummy crosses at the zebra. Adult dummy on the footway to the right, just walking "
        "along.")


def test_losing_the_light_is_dusk_and_no_traffic_light():
    scene = lower("Bike target in the VUT's lane riding away. Light rain, running it before we lose the light.")
    assert scene.scenario.weather.time == "sunset"
    assert "traffic_light" not in scene.scenario.road.required_signals


def test_like_someone_after_an_agent_asked_for_describes_that_agent():
    assert agents("One more with a pedestrian, like someone jaywalking across the road from the left.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left")]


def test_that_same_street_is_the_street_the_ego_turns_into():
    assert ("car", "stop", "at_the_destination") in agents("The ego turns left into a side street. A van is parked "
                                                           "on that street.")
    assert ("ambulance", "go_straight", "road_of_left_turn") in agents(
        "The ego waits to turn right onto a boulevard when an ambulance races along that boulevard from the left.")


def test_a_place_set_off_after_a_pronoun_object_places_the_subject():
    said = agents("Four-way stop. The ego stops. A hatchback pulls up on the road to its right, and a pickup across "
                  "from it, on the opposite road, is turning left.")
    assert ("car", "stop", "road_of_right_turn") in said and ("car", "turn_left", "road_of_straight") in said


def test_a_state_after_the_object_of_finding_is_the_objects():
    assert agents("The ego finds a van double-parked ahead.") == [("car", "go_straight", "ego"),
                                                                  ("car", "stop", "front")]


def test_choices_weighed_are_none_made():
    assert agents("The ego approaches a bus stopped ahead. The ego has to decide whether to pull around the bus "
                  "or wait.") == [("bus", "stop", "front"), ("car", "go_straight", "ego")]


def test_nowhere_near_the_crosswalk_has_one_that_no_one_is_at():
    prompt = "The ego is turning right at a traffic light when a man crosses the street, nowhere near the crosswalk."
    assert "crosswalk" in road(prompt).required_objects
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") not in agents(prompt)
    assert "crosswalk" in road("A man crosses mid-block, nowhere near a crosswalk.").without_objects


def test_people_on_the_sidewalk_by_a_vehicle_ahead_are_ahead_on_the_kerb_side():
    assert ("pedestrian", "on_the_sidewalk", "front_right") in agents(
        "City bus stopped at a bus stop in ego's lane, two people standing on the sidewalk next to it.")


def test_a_sentence_taking_back_the_one_before_leaves_out_whom_it_added():
    said = agents("Could I get one where the test vehicle is driving and a person crosses at the zebra crossing in "
                  "front of it. Oh and maybe a second person waiting on the pavement? Actually no, just the one "
                  "crossing, sorry.")
    assert said == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]
    assert ("pedestrian", "on_the_sidewalk", "right") in agents("The ego drives. A pedestrian waits on the pavement. "
                                                                "Actually no cars are parked.")


def test_weather_denied_past_an_article_is_not_the_weather():
    assert lower("The ego drives in the rain, normal rain not a storm.").scenario.weather.condition == "mid_rain"
    assert lower("Carriageway still wet from the earlier rain, after dark.").scenario.weather.condition == "wet"


def test_where_traffic_keeps_left_pulling_over_and_the_nearside_lane_are_left():
    said = agents("Urban dual carriageway. The test car is running in the offside lane when an ambulance comes up "
                  "behind it. The car pulls over into the nearside lane to let it through.")
    assert sorted(said) == [("ambulance", "go_straight", "back"), ("car", "change_lane_to_left", "ego")]


def test_the_turn_said_first_is_made_when_the_ego_pulls_out_after_waiting():
    assert stages("T-intxn, ego on minor rd at give way sign, turning L onto main rd. veh from R going straight. "
                  "ego waits for it, then pulls out.")[-1] == [("ego", "turn_left", None)]


def test_sitting_in_a_blind_spot_keeps_pace():
    assert ("car", "go_straight", "back_right") in agents("The ego drives. A car is sitting in its right rear blind "
                                                          "spot.")


def test_a_lane_change_wanted_is_made_when_said_again_later():
    said = stages("The ego car wants to move into the right lane, but another vehicle is sitting in its right rear "
                  "blind spot. The ego should hold its lane until that vehicle passes, and then make the lane "
                  "change.")
    assert [s[0] for s in said] == [("ego", "go_straight", None), ("ego", "change_lane_to_right", None)]


def test_a_counted_group_said_again_by_its_last_word_and_count_is_that_group():
    assert agents("Two delivery vans parked on the right. A child comes out from between the two vans.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front_right"), ("car", "stop", "front_right"),
        ("pedestrian", "cross_the_road", "front_right")]


def test_going_by_on_a_side_after_the_ego_moved_over_is_in_its_own_lane():
    said = stages("ego on 2-lane arterial, L lane. ambulance coming up behind in ego lane. ego moves over to R lane, "
                  "amb goes by on L. after that ego merges back L.")
    assert ("ambulance", "go_straight", "back") in said[0] and said[1] == [("ego", "change_lane_to_left", None)]


def test_a_word_wondered_about_with_a_question_mark_does_not_end_the_sentence():
    assert ("firetruck", "stop", "front_right") in agents(
        "so the ego is on a motorway, and theres a fire engine, sorry, fire truck? whatever its called, stopped on "
        "the hard shoulder a bit ahead on the right.")


def test_a_lane_named_after_the_ego_moved_is_placed_against_its_new_lane():
    said = stages("Three-lane road. The ego, in the right lane, has to move over into the middle lane. A truck is in "
                  "the middle lane ahead of it. Then a white van from the right lane forces its way in ahead of it.")
    assert ("truck", "go_straight", "front_left") in said[0]
    assert said[1] == [("car", "change_lane_to_left", "front_right")]


def test_a_vehicle_named_as_if_known_that_is_nowhere_and_does_nothing_is_no_agent():
    assert ("police", "go_straight", "front") not in agents(
        "The ego follows a slow truck in lane 1. A 4x4 overtook both of us in lane 2, far too quick; reg noted for "
        "the police.")
    assert agents("A cyclist crosses in front of the ego from the left. The van was nowhere to be seen.") == [
        ("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "front_left")]
    assert ("truck", "go_straight", "front") in agents("The ego follows the truck through the village.")


def test_arriving_at_a_red_light_or_a_stop_said_before_is_stopping():
    assert agents("The ego arrives at a red light.") == [("car", "stop", "ego")]
    assert stages("At a four-way stop, the ego arrives at the same time as a car on its left; the other car goes "
                  "first, then the ego turns right.") == [[("ego", "stop", None), ("car", "go_straight",
                                                                                    "road_of_left_turn")],
                                                          [("ego", "turn_right", None)]]


def test_a_clause_of_only_a_new_agent_after_one_placed_and_doing_says_the_same_of_it():
    assert ("cyclist", "go_straight", "road_of_straight") in agents(
        "The ego waits to turn left. Two oncoming cars pass, then a cyclist.")
    assert ("car", "stop", "front_right") in agents("A truck is parked on the right, and a van.")
    assert ("car", "change_lane_to_right", "front_left") in agents(
        "First a motorcycle came up from behind me on my left. Then a Prius that was just ahead of me in the left "
        "lane swung over into my lane.")


def test_a_lane_change_is_given_up_only_by_the_one_that_makes_it():
    assert ("car", "change_lane_to_right", "left") in agents(
        "The ego is in the middle lane. A car on the left changes into the middle lane in front of the ego, and a "
        "truck on the right stays in its lane.")
    assert ("car", "change_lane_to_right", "ego") not in agents(
        "I went to move into the right lane but a car was there so I aborted and stayed in my lane.")


def test_a_school_buss_own_stop_arm_is_no_sign_of_the_road():
    prompt = "On a rainy evening, the ego stops behind a school bus with its stop sign extended while children cross."
    assert "stop" not in road(prompt).required_signals
    assert "stop" in road("A pickup drove across from my left without stopping at its stop sign.").required_signals


def test_the_target_road_is_the_road_the_ego_turns_into():
    assert ("pedestrian", "cross_the_road", "at_the_destination") in agents(
        "Ego performs an unprotected left turn; oncoming NPC goes straight; pedestrian crosses the target road.")


def test_a_parked_vehicle_placed_by_a_crosser_stands_at_the_kerb_and_asks_for_no_lane():
    prompt = "A pedestrian crosses from the left in front of the ego, occluded by a parked van."
    assert ("car", "stop", "front_left") in agents(prompt)
    assert road(prompt).lanes in (None, 1)


def test_pulling_out_to_overtake_on_a_side_is_a_lane_change_to_that_side():
    assert ("car", "change_lane_to_left", "back") in agents("A car behind the ego pulls out to overtake on the left.")
    assert ("car", "go_straight", "back_left") in agents("A car behind the ego overtakes on the left.")


def test_neither_vehicle_names_the_two_said_before_and_denies_the_verb():
    said = agents("The ego approaches an uncontrolled intersection. A pickup approaches from the right at the same "
                  "time, and neither vehicle slows down.")
    assert said == [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_right_turn")]
    assert ("bus", "go_straight", "road_of_left_turn") in agents(
        "The ego waits at the junction. A van and a bus come from the left; neither of them stops.")


@pytest.mark.parametrize("prompt, expected", [
    ("Ego goes straight at the crossroads; a cyclist comes from the right and runs the red, like every cyclist in "
     "town.", [("car", "go_straight", "ego"), ("cyclist", "go_straight", "road_of_right_turn")]),
    ("The ego follows a lead car that brakes hard. Never trust a cab.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("A car ahead brakes hard. My dad drives a bus for a living.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("A car ahead brakes hard; it handles like a bus.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
])
def test_a_vehicle_of_which_nothing_is_said_among_others_told_is_a_passing_mention(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, kept", [
    ("A car ahead brakes hard. There is also a truck.", ("truck", "go_straight", "front")),
    ("A car overtakes the ego on the left and a truck appears.", ("truck", "go_straight", "front")),
    ("Ego vehicle at a junction, a car from the right, a motorcycle and a bus.", ("bus", "go_straight", "front")),
    ("A cyclist rides on the right. Include one more car.", ("car", "go_straight", "front")),
    ("The ego is stuck behind a slow truck when a car overtakes both on the left.", ("truck", "go_straight", "front")),
    ("A car and a truck.", ("truck", "go_straight", "front")),
    ("A lead vehicle brakes hard. A motorcycle splits the lane.", ("motorcycle", "go_straight", "front")),
    ("A lead vehicle brakes hard. The ego yields to a bus.", ("bus", "go_straight", "front")),
    ("A lead vehicle brakes hard. A police car, sirens on.", ("police", "go_straight", "front")),
    ("A car turns left across the ego's path. A truck, then a bus.", ("truck", "go_straight", "front")),
    ("A car turns left across the ego's path; in the distance a truck.", ("truck", "go_straight", "front")),
])
def test_a_vehicle_put_in_the_scene_listed_or_met_stays_with_nothing_said_of_it(prompt, kept):
    assert kept in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A boy on a bike rolled across the street in front of us.", ("cyclist", "cross_the_road", "front")),
    ("A woman trailed across the street in front of the ego car.", ("pedestrian", "cross_the_road", "front")),
])
def test_rolling_or_trailing_across_the_road_is_crossing_it(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("The driver behind me was an idiot.", [("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
    ("The vehicle behind me was a bus.", [("bus", "go_straight", "back"), ("car", "go_straight", "ego")]),
])
def test_what_a_placed_one_is_said_to_be_is_no_second_agent(prompt, expected):
    assert agents(prompt) == expected


def test_a_definite_noun_told_apart_by_what_it_did_is_not_the_ego():
    assert agents("The ego brakes. The car that cut in was a white van.") == [
        ("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]
    assert agents("The car that I was driving turned left.") == [("car", "turn_left", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("A bus pulled in at a stop ahead on the right, and two people are waiting on the pavement by the stop.",
     ("pedestrian", "on_the_sidewalk", "front_right")),
    ("A bus is stopped at the stop ahead of the ego in its lane. Three extras wait at the bus stop on the sidewalk.",
     ("pedestrian", "on_the_sidewalk", "front_right")),
    ("The ego is behind a bus stopped at a bus stop, and a woman stands on the sidewalk to the right, level with "
     "the bus.", ("pedestrian", "on_the_sidewalk", "front_right")),
    ("The ego turns left at the lights. A lady was walking along the sidewalk on the far right corner.",
     ("pedestrian", "on_the_sidewalk", "front_right")),
])
def test_one_on_the_pavement_at_the_stop_level_with_a_vehicle_or_on_the_far_corner_is_ahead(prompt, expected):
    assert expected in agents(prompt)


def test_what_traffic_does_in_general_is_not_the_egos_doing():
    assert agents("Merging traffic is the hard part. A car on the ramp to my right merged into my lane.") == [
        ("car", "change_lane_to_left", "right"), ("car", "go_straight", "ego")]
    assert agents("Turning left across oncoming traffic at a crossroads.") == [("car", "turn_left", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("A truck moves left into the ego's lane.", ("truck", "change_lane_to_left", "front_right")),
    ("A truck moves right into the ego's lane.", ("truck", "change_lane_to_right", "front_left")),
    ("A car behind the ego moves left into the ego's lane.", ("car", "change_lane_to_left", "back_right")),
])
def test_moving_to_a_side_into_the_egos_lane_starts_in_the_lane_on_the_other_side(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt", [
    "A man was on the crosswalk I was turning across.",
    "Turning right on red, there was a man on the crosswalk I was turning across.",
])
def test_a_relative_with_no_that_keeps_the_speakers_verb_to_the_speaker(prompt):
    said = agents(prompt)
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in said and len(said) == 2


def test_people_let_across_are_on_foot_in_the_scene():
    assert agents("I was stopped at the crosswalk, letting people across.") == [
        ("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
        ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_a_makers_name_after_on_or_onto_with_no_article_is_a_street():
    assert agents("I was stopped at the red. An ambulance came across from the left, probably going to the hospital "
                  "on Lincoln.") == [("ambulance", "go_straight", "road_of_left_turn"), ("car", "stop", "ego")]
    assert ("motorcycle", "go_straight", "back_left") in agents("A guy on a Harley overtook me.")


def test_a_condition_ends_before_the_speaker_after_its_verb_and_particle():
    assert stages("I was waiting to turn left at the lights. An ambulance came towards me from the other "
                  "direction, so I just sat there and waited. Then once it had gone by I made my turn.") == [
        [("ego", "stop", None), ("ambulance", "go_straight", "road_of_straight")], [("ego", "turn_left", None)]]


def test_an_obligation_with_no_subject_in_a_speakers_account_is_the_speakers():
    assert stages("A bus pulled out from a stop on my right, right in front of me. Had to take over, then braked "
                  "all the way to a stop behind the bus.") == [
        [("ego", "go_straight", None), ("bus", "change_lane_to_left", "front_right")], [("ego", "stop", None)]]


def test_shortly_after_said_at_the_end_of_a_clause_is_when_it_happens_not_a_new_stage():
    assert stages("At a four-way stop, a car arrives from the left shortly after and waits.") == [
        [("ego", "go_straight", None), ("car", "stop", "road_of_left_turn")]]
    assert len(stages("The ego stops. Shortly after, a car comes from the left.")) == 2


@pytest.mark.parametrize("prompt", [
    "A van double-parked ahead forces the ego to wait for oncoming traffic before passing it.",
    "A van parked ahead means the ego must wait before passing it.",
])
def test_passing_it_after_the_ego_is_made_to_wait_is_the_egos_doing(prompt):
    assert ("car", "stop", "front") in agents(prompt)


def test_a_driver_who_is_standing_beside_the_vehicle_is_on_foot():
    assert ("pedestrian", "stop", "front_right") in agents(
        "A truck is parked on the hard shoulder and its driver is standing next to it.")


@pytest.mark.parametrize("prompt, expected", [
    ("A car is parked on each side of the street.", [("car", "go_straight", "ego"), ("car", "stop", "front_left"),
                                                      ("car", "stop", "front_right")]),
    ("The ego is boxed in with a truck on either side of it.", [("car", "go_straight", "ego"),
                                                                ("truck", "go_straight", "left"),
                                                                ("truck", "go_straight", "right")]),
])
def test_one_on_each_side_is_two(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A tractor is pulling out of a field on the left.", ("truck", "change_lane_to_right", "front_left")),
    ("A van pulls out of a petrol station on the left.", ("car", "change_lane_to_right", "front_left")),
])
def test_out_of_a_field_or_a_petrol_station_joins_the_road_ahead(prompt, expected):
    assert expected in agents(prompt)


def test_holding_at_the_lights_is_waiting_there():
    assert stages("The ego is holding at the traffic lights while an ambulance crosses from the right. Once the "
                  "ambulance clears, the ego goes straight through.") == [
        [("ego", "stop", None), ("ambulance", "go_straight", "road_of_right_turn")], [("ego", "go_straight", None)]]
    assert road("The ego is holding at the traffic lights.").required_signals


@pytest.mark.parametrize("prompt", [
    "A car passes the ego on the left, then cuts in.",
    "A car overtakes the ego and then cuts in front of it.",
])
def test_a_pass_that_goes_on_into_a_cut_in_is_the_cut_in(prompt):
    assert agents(prompt) == [("car", "change_lane_to_right", "back_left"), ("car", "go_straight", "ego")]


def test_what_the_ego_is_told_after_another_passes_stays_the_egos():
    assert ("motorcycle", "go_straight", "back_right") in agents(
        "The ego is in the middle lane and a motorcycle comes speeding behind on the right. Once it has passed, "
        "changes the ego lane to the right.")


def test_one_in_the_blind_spot_is_behind_in_the_lane_the_ego_moves_into():
    assert agents("The ego changes lanes to the right while a motorcycle is in its blind spot.") == [
        ("car", "change_lane_to_right", "ego"), ("motorcycle", "go_straight", "back_right")]
    assert ("car", "go_straight", "back") in agents("A car sits in the ego's blind spot.")


def test_oncoming_said_of_traffic_places_no_one_named():
    assert agents("The ego overtakes a slow truck despite oncoming traffic.") == [
        ("car", "go_straight", "ego"), ("truck", "go_straight", "front")]


def test_a_learner_on_the_pedals_is_at_the_wheel():
    assert agents("Stop 15: estate roads by the park. Pupil covers the brake and creeps past an ice cream van "
                  "parked ahead.") == [("car", "go_straight", "ego"), ("car", "stop", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("Event 7: a motorcycle turns left in front of the ego. Weather: rain.",
     [("car", "go_straight", "ego"), ("motorcycle", "turn_left", "front")]),
    ("Exercise 10: the occluded pedestrian. The ego drives straight along a street. A child steps out from between "
     "two parked cars on the right.", [("car", "go_straight", "ego"), ("car", "stop", "front_right"),
                                      ("car", "stop", "front_right"), ("pedestrian", "cross_the_road", "front_right")]),
    ("Hazard H-22: pedestrian emerging from behind parked vehicles. Triggering condition: a child steps out between "
     "two parked cars on the right-hand side ahead. ODD: residential street.",
     [("car", "go_straight", "ego"), ("car", "stop", "front_right"), ("car", "stop", "front_right"),
      ("pedestrian", "cross_the_road", "front_right")]),
])
def test_a_numbered_cases_key_and_title_are_no_scene_words(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, kind", [
    ("Two trucks, one in each adjacent lane, travel alongside the ego.", "truck"),
    ("A car drives in each adjacent lane.", "car"),
])
def test_one_in_each_adjacent_lane_is_one_on_each_side(prompt, kind):
    assert sorted(a for a in agents(prompt) if a[2] != "ego") == [(kind, "go_straight", "left"),
                                                                 (kind, "go_straight", "right")]


def test_the_doers_of_a_passive_said_as_a_bare_plural_are_in_the_scene():
    assert agents("The ego is overtaken by trucks.") == [
        ("car", "go_straight", "ego"), ("truck", "go_straight", "back_left"), ("truck", "go_straight", "back_left")]
    assert not [a for a in agents("A car from the left, which was hidden by vehicles parked near the junction, "
                                  "pulls out.") if a[1] == "stop"]


@pytest.mark.parametrize("prompt", [
    "A car on the side road to the right pulls out in front of the ego.",
    "The ego goes straight while a car waiting on the side street to our right pulls out in front of it.",
])
def test_a_side_road_to_one_side_is_the_road_on_that_side(prompt):
    assert [a for a in agents(prompt) if a[2] != "ego"] == [("car", "go_straight", "road_of_right_turn")]


def test_a_manoeuvre_said_bare_is_no_lane_change():
    assert agents("A pedestrian crosses the road in front of the ego. The ego must perform an emergency brake or an "
                  "avoidance maneuver.") == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]
    assert road("The ego must perform an avoidance maneuver.").lanes < 2


def test_one_that_prevents_an_evasive_manoeuvre_drives_where_it_is():
    assert ("car", "go_straight", "front_left") in agents(
        "If the truck ahead brakes to a halt while an oncoming car prevents an evasive manoeuvre, the AEB function "
        "shall bring the subject vehicle to a stop behind the truck.")


def test_a_scenario_class_named_for_what_crosses_puts_no_crossing_on_the_road():
    assert not road("DynamicObjectCrossing. The ego vehicle drives straight along an urban road when a pedestrian "
                    "emerges from behind a parked van and crosses the road.").required_objects


def test_a_participle_after_the_object_of_a_denied_verb_is_the_objects():
    assert agents("The ego turning right did not wait for a crowd leaving the stadium that was still on the "
                  "crosswalk.") == [("car", "turn_right", "ego"),
                                    ("pedestrian", "cross_the_road", "near_the_crosswalk")]


@pytest.mark.parametrize("prompt, expected", [
    ("The ego overtakes a bus stopped at a bus stop.", [("bus", "stop", "front"), ("car", "go_straight", "ego")]),
    ("The ego passes a truck parked on the right.", [("car", "go_straight", "ego"), ("truck", "stop", "front_right")]),
    ("Hero overtakes a cyclist riding on the right shoulder ahead, staying in its lane.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front_right")]),
])
def test_where_the_one_passed_stands_is_its_own_place(prompt, expected):
    assert agents(prompt) == expected


def test_the_side_said_after_the_one_passed_is_the_side_of_the_pass():
    assert ("car", "change_lane_to_left", "ego") in agents("The ego overtakes the standing bus over the left lane.")


def test_the_egos_lane_said_with_lane_after_its_side_places_the_others_by_it():
    assert agents("Ego on rightmost lane of 3 lanes highway. One car in middle lane behind of ego.") == [
        ("car", "go_straight", "back_left"), ("car", "go_straight", "ego")]


def test_a_lane_said_before_behind_and_whom_is_the_subjects_lane():
    assert agents("The ego vehicle starts in the rightmost lane behind a slow-moving truck, while a sports car "
                  "approaches at high speed from behind in the middle lane and overtakes it.") == [
        ("car", "go_straight", "back_left"), ("car", "go_straight", "ego"), ("truck", "go_straight", "front")]
    assert ("car", "go_straight", "back_right") in agents("A car in the right lane behind the ego speeds up.")


def test_pulling_in_to_a_stop_is_stopping_there():
    assert agents("The bus in front pulls in to the bus stop.") == [("bus", "stop", "front"),
                                                                   ("car", "go_straight", "ego")]


def test_one_on_a_horse_rides_along_the_road():
    assert agents("A horse rider is on the road ahead.") == [("car", "go_straight", "ego"),
                                                           ("cyclist", "go_straight", "front")]


def test_what_one_named_by_an_unknown_noun_does_is_not_the_egos():
    assert agents("A pony trap pulls out in front of the ego.") == [("car", "go_straight", "ego")]
    assert agents("A milk float pulls out in front of the ego.") == [("car", "change_lane_to_right", "front_left"),
                                                                   ("car", "go_straight", "ego")]


def test_the_driver_placed_behind_one_named_before_is_another():
    assert agents("An oncoming car goes through the lights. The driver behind it stops.") == [
        ("car", "go_straight", "ego"), ("car", "go_straight", "road_of_straight"), ("car", "stop", "road_of_straight")]
    assert agents("I was turning left into Hill Street when a car coming towards me sped up and went through the "
                  "lights on amber. The learner driver behind him stopped properly.") == [
        ("car", "go_straight", "road_of_straight"), ("car", "stop", "road_of_straight"), ("car", "turn_left", "ego")]


@pytest.mark.parametrize("prompt", [
    "I was on my scooter on the pavement when a van came straight at me.",
    "I was on the pavement on my mobility scooter when a car turned left across me into a side road.",
    "I was standing on the pavement when a van mounted the kerb in front of me.",
])
def test_a_witness_on_foot_met_by_the_vehicle_is_on_the_pavement(prompt):
    found = agents(prompt)
    assert found[0][1:] in {("go_straight", "ego"), ("turn_left", "ego")}
    assert ("pedestrian", "on_the_sidewalk", "left") in found and len(found) == 2


@pytest.mark.parametrize("prompt", [
    "Riding along a street with cars parked on the left, a taxi ahead of me stopped suddenly, so I went round it.",
    "A car in the lane to my right changed lane to the left right in front of me, and I had to grab a handful of "
    "front brake.",
])
def test_a_teller_who_rides_or_grabs_the_front_brake_is_on_a_motorbike(prompt):
    assert any(kind == "motorcycle" and where == "ego" for kind, _, where in agents(prompt))


@pytest.mark.parametrize("prompt", [
    "Actors: ego, truck\nPositions: truck ahead of ego\nManeuvers: truck stops\n",
    "Actors: the ego, a truck\nPositions: truck ahead of ego\nManeuvers: truck stops\n",
    "A truck. Truck ahead of ego. Truck stops.",
])
def test_an_agent_listed_then_placed_in_note_style_is_one(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("truck", "stop", "front")]


def test_a_second_apposition_after_the_egos_names_another():
    assert agents("Our ego, a bus, stops behind a truck.") == [("bus", "stop", "ego"), ("truck", "stop", "front")]


def test_one_stepping_out_from_behind_it_comes_from_behind_what_stands():
    assert agents("A truck is parked in the lane to the right of the ego and a pedestrian steps out from behind "
                  "it.") == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right"),
                             ("truck", "stop", "front_right")]


def test_a_teller_crossing_whose_wheelchair_is_named_later_is_on_foot():
    assert agents("I was halfway across the road at the junction when a car coming from the road on my right turned "
                  "left towards me, and the driver only saw my wheelchair at the last second and stopped.") == [
        ("car", "turn_left", "ego"), ("pedestrian", "cross_the_road", "front")]
    assert agents("As I crossed the road at the junction, a van turned left into the street and nearly hit me.") == [
        ("car", "turn_left", "ego"), ("pedestrian", "cross_the_road", "front")]


@pytest.mark.parametrize("prompt", [
    "OPERATOR: Police, fire or ambulance? / CALLER: Police. A car has just run the red light in front of me.",
    "Caller: Police, please, there's a car driving the wrong way, it's coming straight at us.",
])
def test_the_service_a_call_asks_for_sends_no_one_into_the_scene(prompt):
    assert [kind for kind, _, _ in agents(prompt)] == ["car", "car"]


def test_a_teller_stepping_out_onto_the_crossing_is_on_foot():
    assert agents("The silver car came up behind a black taxi that had stopped at the zebra crossing for me, pulled "
                  "out to the right around it, and carried on straight through while I was stepping out from the "
                  "left.") == [("car", "change_lane_to_right", "ego"), ("car", "stop", "front"),
                               ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_a_caller_who_says_they_are_a_cyclist_reports_the_driver():
    assert agents("Caller: I'm a cyclist, I was riding along Park Road and a white van has just overtaken me and "
                  "turned left across me into a driveway. Dispatcher: Are you injured? Caller: My arm, I think.") == [
        ("car", "turn_left", "ego"), ("cyclist", "go_straight", "front")]


@pytest.mark.parametrize("prompt, kind", [
    ("At the crossroads a car coming from the right pulls out in front of the ego.", "car"),
    ("At the crossroads a motorcyclist coming from the right ignored the stop sign and shot across in front of me "
     "as I drove straight over.", "motorcycle"),
])
def test_one_that_came_along_a_side_road_and_shoots_across_crosses_the_junction(prompt, kind):
    assert agents(prompt) == sorted([("car", "go_straight", "ego"), (kind, "go_straight", "road_of_right_turn")])
    assert road(prompt).lanes < 2


def test_one_cutting_in_from_a_side_at_a_junction_without_coming_along_it_changes_lane():
    assert ("car", "change_lane_to_right", "front_left") in agents(
        "At the signal an auto suddenly cut in from the left in front of the ego.")


def test_a_cyclist_out_of_a_side_road_crosses_from_that_road():
    prompt = "A cyclist emerged from a side road on our right and went straight across in front of us."
    assert agents(prompt) == [("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "road_of_right_turn")]
    assert road(prompt).junction


def test_the_bus_driver_named_by_passengers_drives_their_bus():
    assert agents("A lorry coming towards us turned right across our front, and the bus driver slammed on so hard "
                  "my shopping went everywhere.") == [("bus", "stop", "ego"),
                                                      ("truck", "turn_right", "road_of_straight")]
    assert ("bus", "go_straight", "front") in agents(
        "We were stuck in traffic and the bus driver ahead of us got out.")


@pytest.mark.parametrize("prompt", [
    "A lorry coming towards us swung right across our front.",
    "An oncoming car swings right across the ego's path into a side road.",
])
def test_swinging_to_a_side_across_the_egos_front_is_a_turn(prompt):
    assert agents(prompt)[1][1:] == ("turn_right", "road_of_straight")


@pytest.mark.parametrize("prompt, expected", [
    ("A m/c overtook us on the offside.", ("motorcycle", "go_straight", "back_right")),
    ("m/cycle came from the rd to our left and turned right across our bonnet.",
     ("motorcycle", "turn_right", "road_of_left_turn")),
])
def test_a_police_logs_short_name_for_a_motorcycle(prompt, expected):
    assert expected in agents(prompt)


def test_neither_one_nor_the_other_is_one_each_and_denies_the_verb():
    assert agents("Neither the cyclist in the right lane nor the car behind the ego changes lane.") == [
        ("car", "go_straight", "back"), ("car", "go_straight", "ego"), ("cyclist", "go_straight", "right")]
    assert ("truck", "go_straight", "left") in agents("Neither the ego nor the truck beside it can change lanes.")


def test_the_verb_after_one_let_and_placed_is_the_let_ones():
    assert agents("Waiting at the junction, the test vehicle lets a car from the road on the left turn right in front "
                  "of it.") == [("car", "stop", "ego"), ("car", "turn_right", "road_of_left_turn")]


@pytest.mark.parametrize("prompt", [
    "The ego approaches the junction, and as soon as it reaches the junction it turns right.",
    "The ego drives on. Then it turns right.",
])
def test_driving_up_to_a_turn_is_the_way_into_it(prompt):
    assert agents(prompt) == [("car", "turn_right", "ego")]


def test_going_straight_before_a_later_turn_stays_its_own_manoeuvre():
    assert agents("The ego goes straight. Then it turns right.") == [("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", [
    "The car ahead stops. The van in the left lane goes straight.",
    "The car ahead of the SUT stops, whereas the van in the left lane ahead goes straight.",
])
def test_a_van_is_not_the_car_named_before(prompt):
    assert ("car", "stop", "front") in agents(prompt)
    assert len(agents(prompt)) == 3


def test_a_vehicle_placed_ahead_is_not_the_one_that_came_from_behind():
    assert agents("An ambulance approaches the AV from behind and goes straight. The van in the right lane ahead "
                  "stops to let it pass.") == [("ambulance", "go_straight", "back"), ("car", "go_straight", "ego"),
                                               ("car", "stop", "front_right")]


def test_the_car_behind_is_not_the_one_that_cut_in():
    assert agents("A van cuts in from the left lane. The car behind the ego goes straight.") == [
        ("car", "change_lane_to_right", "left"), ("car", "go_straight", "back"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", [
    "The motorcycle that is between the ego and the police car changes lane right, and the police car stops.",
    "The motorcycle between the ego and the police car changes lane right while the police car stops.",
])
def test_the_two_it_is_between_place_it_and_are_not_its_subjects(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("motorcycle", "change_lane_to_right", "front"),
                              ("police", "stop", "front")]


def test_the_car_between_the_ego_and_a_bus_is_the_one_that_stops():
    assert agents("The car between the ego and the bus brakes hard and stops, while the bus goes straight.") == [
        ("bus", "go_straight", "front"), ("car", "go_straight", "ego"), ("car", "stop", "front")]


@pytest.mark.parametrize("prompt", ["The oncoming car goes straight.", "The parked car stops."])
def test_a_car_placed_or_parked_named_first_with_the_is_not_the_ego(prompt):
    assert len(agents(prompt)) == 2


def test_going_straight_across_the_junction_is_at_a_junction():
    prompt = "A truck coming from the left side road goes straight across the junction."
    assert road(prompt).junction
    assert ("truck", "go_straight", "road_of_left_turn") in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("Coming from a side road on the right, a truck turns left across the ego's path.",
     ("truck", "turn_left", "road_of_right_turn")),
    ("Parked in the right lane ahead, a truck blocks the lane.", ("truck", "block_the_ego", "front_right")),
    ("Following the ego closely, a motorcycle changes lane left.", ("motorcycle", "change_lane_to_left", "back")),
])
def test_an_opening_participle_is_said_of_the_main_clauses_subject(prompt, expected):
    assert expected in agents(prompt)
    assert ("car", "go_straight", "ego") in agents(prompt)


def test_a_tellers_opening_participle_stays_the_tellers():
    assert ("motorcycle", "stop", "ego") in agents(
        "OP here, on my motorcycle. Sitting at a red in the left lane, a Jeep in the right lane next to me just "
        "starts drifting over into my lane.")


def test_the_verb_after_letting_the_ego_is_the_egos():
    assert agents("A car from the left and a bus from the right both stop at the junction, letting the ego go "
                  "straight.") == [("bus", "stop", "road_of_right_turn"), ("car", "go_straight", "ego"),
                                   ("car", "stop", "road_of_left_turn")]


@pytest.mark.parametrize("prompt", ["Around ten a school bus came up behind us and stopped.",
                                    "At about ten a bus stopped behind us."])
def test_a_number_before_an_article_is_a_time_and_counts_nothing(prompt):
    assert agents(prompt) == [("bus", "stop", "back"), ("car", "go_straight", "ego")]


def test_a_job_cards_cust_is_the_customer():
    assert agents("Cust was turning left out of a side road.") == [("car", "turn_left", "ego")]


def test_the_car_is_not_the_van_named_before():
    assert agents("A van was blocking the left lane, so the car ahead of me swung out into my lane.") == [
        ("car", "block_the_ego", "left"), ("car", "change_lane_to_left", "front"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", ["A truck is parked ahead. Does the ego stop?",
                                    "A car is travelling along a street. Will the car stop in time?"])
def test_a_question_whether_one_named_does_a_thing_tells_nothing(prompt):
    assert ("car", "go_straight", "ego") in agents(prompt)


def test_a_question_asking_for_one_still_asks_for_it():
    assert ("car", "change_lane_to_right", "front_left") in agents("Can a car cut in front of the ego?")


@pytest.mark.parametrize("prompt, expected", [
    ("The ego waits behind a truck at the red light. When the light turns green, the truck turns right.",
     ("truck", "turn_right", "front")),
    ("We wait at a red light behind a car. Once the light turns green, it turns left.", ("car", "turn_left", "front")),
])
def test_the_turn_one_waited_to_make_is_what_it_does(prompt, expected):
    assert expected in agents(prompt)
    assert road(prompt).junction


@pytest.mark.parametrize("prompt", [
    "A pedestrian stands on the sidewalk to the right. Neither of them enters the ego's lane.",
    "A pedestrian stands on the sidewalk to the right. The pedestrian does not enter the ego's lane.",
])
def test_no_one_goes_where_a_denied_verb_goes(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "right")]


@pytest.mark.parametrize("prompt, expected", [
    ("What should the AV do when an oncoming motorcycle turns left across its path at 30 km/h?",
     ("motorcycle", "turn_left", "road_of_straight")),
    ("If a car cuts in, what should the ego do?", ("car", "change_lane_to_right", "front_left")),
])
def test_the_case_a_question_asks_about_is_the_scene(prompt, expected):
    assert agents(prompt) == sorted([("car", "go_straight", "ego"), expected])


def test_a_question_of_building_tells_no_case():
    assert ("motorcycle", "go_straight", "back") in agents(
        "At an unsignalised crossroads the ego goes straight while a motorcycle follows the ego in its lane. How do I "
        "stop the cyclist from teleporting when it waits too long?")


def test_the_former_and_the_latter_in_the_order_named():
    assert agents("An ambulance and a car approach from behind the ego; the former changes lane left, the latter "
                  "stops on the shoulder.") == [("ambulance", "change_lane_to_left", "back"),
                                                ("car", "go_straight", "ego"), ("car", "stop", "back_right")]


def test_the_role_set_off_after_a_noun_is_the_role_it_plays():
    assert agents("A truck, the lead vehicle, brakes hard.") == [("car", "go_straight", "ego"),
                                                                 ("truck", "stop", "front")]


def test_what_one_asked_about_does_in_a_question_for_a_scene_stays():
    assert ("bus", "turn_right", "road_of_straight") in agents(
        "Can the ego handle a bus that turns right across its path?")


@pytest.mark.parametrize("prompt, expected", [
    ("A truck that comes in front in sense contrary turns to the left.", ("truck", "turn_left", "road_of_straight")),
    ("When it changes to green, a motorbike from the side street of the left passes.",
     ("motorcycle", "go_straight", "road_of_left_turn")),
    ("The ego goes by the highway and a car of the right lane puts itself in front very close.",
     ("car", "change_lane_to_left", "right")),
])
def test_phrases_written_word_for_word_from_spanish_or_french(prompt, expected):
    assert expected in agents(prompt)


def test_fires_at_a_crossroad_are_its_signals():
    assert "traffic_light" in road("The ego arrives at a crossroad with fires which are green.").required_signals


@pytest.mark.parametrize("prompt", [
    "The ego car wants to turn left at a crossing without traffic lights. An oncoming car goes straight.",
    "The ego car comes at a crossing without traffic lights. A car comes from the right side street.",
])
def test_a_crossing_with_no_one_on_foot_to_cross_it_is_a_junction(prompt):
    assert road(prompt).junction
    assert "crosswalk" not in road(prompt).required_objects


def test_a_crossing_a_pedestrian_crosses_stays_a_crosswalk():
    assert "crosswalk" in road("A pedestrian crosses at the crossing without traffic lights.").required_objects


def test_a_correction_that_says_the_place_again_names_one():
    assert agents("The ego drives behind a tractor, no sorry, behind a truck who drives very slow.") == [
        ("car", "go_straight", "ego"), ("truck", "go_straight", "front")]


@pytest.mark.parametrize("prompt, kind", [("Ahead a car stands.", "car"), ("In front a bus stops.", "bus")])
def test_a_clause_opened_by_ahead_places_its_subject(prompt, kind):
    assert agents(prompt) == sorted([("car", "go_straight", "ego"), (kind, "stop", "front")])


def test_the_lane_change_one_waited_to_make_from_a_side_lane_is_what_it_does():
    assert ("motorcycle", "change_lane_to_right", "left") in agents(
        "The ego waits at a red light in the right lane, and a motorcycle waits in the left lane next to it. When "
        "the light turns green, the motorcycle changes lane right in front of the ego.")


def test_the_driver_is_no_cyclists():
    assert ("car", "stop", "back") in agents(
        "A car is following the ego closely. The ego stops for the cyclist, and the driver behind also stops.")


@pytest.mark.parametrize("prompt, expected", [
    ("Ego: car, turn right | Actor 1: ped at crosswalk, cross road",
     [("car", "turn_right", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("Ego: car, go straight | Actor 1: truck ahead, stop", [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
    ("Ego: car, lane change left | Actor 1: motorcycle left lane behind, go straight",
     [("car", "change_lane_to_left", "ego"), ("motorcycle", "go_straight", "back_left")]),
])
def test_a_rows_cells_keyed_by_an_agent_are_that_agents(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", ["POV truck ahead. POV brakes.",
                                    "Setup: ego on 3-lane hwy, LV truck ahead 40 m; Trigger: LV hard brake to stop"])
def test_a_role_named_before_a_vehicle_names_it_again(prompt):
    assert [a for a in agents(prompt) if a[0] != "car"] == [("truck", "stop", "front")]
    assert len(agents(prompt)) == 2


@pytest.mark.parametrize("prompt, expected", [
    ("The ego goes straight. A car and a bus ahead turn left and right respectively.",
     [("bus", "turn_right", "front"), ("car", "go_straight", "ego"), ("car", "turn_left", "front")]),
    ("The ego goes straight. A van and a truck behind it change lane left and right respectively.",
     [("car", "change_lane_to_left", "back"), ("car", "go_straight", "ego"),
      ("truck", "change_lane_to_right", "back")]),
    ("The ego goes straight while two cars coming from the opposite direction turn right and left respectively.",
     [("car", "go_straight", "ego"), ("car", "turn_left", "road_of_straight"),
      ("car", "turn_right", "road_of_straight")]),
])
def test_respectively_pairs_each_road_user_with_its_item(prompt, expected):
    assert agents(prompt) == expected


def test_respectively_with_its_items_after_it():
    from ttsgc.lowering.lexicon import _respectively
    assert _respectively("a car and a bus, respectively ahead and behind, stop.") == \
        "a car, ahead, stop, and a bus, behind, stop."
    assert _respectively("speeds are 30 and 50 respectively.") == "speeds are 30 and 50 respectively."


def test_a_pronoun_before_then_is_the_later_stages_subject():
    assert agents("A van waits ahead of the ego. It then changes lane to the left.") == [
        ("car", "change_lane_to_left", "front"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", ["The ego goes straight. A van and a car ahead change lane left. Neither of them "
                                    "signals.",
                                    "A cyclist rides ahead of the ego. The rider signals and turns left."])
def test_one_who_signals_is_indicating_not_a_traffic_light(prompt):
    assert "traffic_light" not in road(prompt).required_signals


def test_a_turn_the_same_sentence_goes_on_to_is_what_it_does():
    assert ("truck", "turn_right", "back_left") in agents("A truck overtakes the ego and then turns right.")


@pytest.mark.parametrize("prompt, expected", [
    ("Pedestrians stand at the crosswalk but nobody crosses. The ego goes straight.", "stop"),
    ("Rather than stopping at the bus stop, the bus changes lane to the left in front of the ego.",
     "change_lane_to_left"),
    ("The ego follows a hatchback which indicates right but does not actually turn.", "go_straight"),
])
def test_a_denied_verb_is_not_done(prompt, expected):
    found = agents(prompt)
    assert ("car", "go_straight", "ego") in found
    assert all(a[1] == expected for a in found if a[2] != "ego")


def test_vehicles_ahead_counted_are_the_members_listed_after():
    assert agents("Three vehicles ahead of the ego: a bus, a car and a motorcycle.") == [
        ("bus", "go_straight", "front"), ("car", "go_straight", "ego"), ("car", "go_straight", "front"),
        ("motorcycle", "go_straight", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("A car, a van and a truck wait ahead of the ego. The first turns right.",
     [("car", "go_straight", "ego"), ("car", "stop", "front"), ("car", "turn_right", "front"),
      ("truck", "stop", "front")]),
    ("A car and a truck wait ahead of the ego. The first turns right, the second goes straight.",
     [("car", "go_straight", "ego"), ("car", "turn_right", "front"), ("truck", "go_straight", "front")]),
])
def test_an_ordinal_names_one_of_those_listed_one_by_one(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A white car and a black car wait at the lights ahead of the ego. The white one turns left.",
     [("car", "go_straight", "ego"), ("car", "stop", "front"), ("car", "turn_left", "front")]),
    ("A red car and a blue car are ahead of the ego. The blue one changes lane to the left.",
     [("car", "change_lane_to_left", "front"), ("car", "go_straight", "ego"), ("car", "go_straight", "front")]),
])
def test_the_one_with_a_paint_said_before_is_that_vehicle(prompt, expected):
    assert agents(prompt) == expected


def test_the_red_one_is_no_red_light():
    prompt = "A red car drives ahead of the ego. The red one then stops."
    assert "traffic_light" not in road(prompt).required_signals
    assert len(agents(prompt)) == 2


def test_a_make_said_before_another_noun_names_that_one_again():
    assert agents("A white Volvo truck is parked on the right shoulder ahead of the test vehicle. The Volvo pulls out "
                  "and changes lane left.") == [("car", "go_straight", "ego"), ("truck", "change_lane_to_left",
                                                                                 "front_right")]


@pytest.mark.parametrize("prompt", [
    "A pedestrian waits at the crosswalk ahead of the ego. He then steps out and crosses the road.",
    "A teenager on a bike waits at the side road on the left. He then pulls out and crosses the road in front of "
    "the ego.",
    "A jogger runs along the sidewalk on the right of the ego. She then crosses the road in front of the ego car.",
])
def test_one_on_foot_or_on_a_bike_who_waited_or_walked_then_crossed_crosses(prompt):
    assert [a[1] for a in agents(prompt) if a[2] != "ego"] == ["cross_the_road"]


@pytest.mark.parametrize("prompt", [
    "The ego travels northbound. A truck in the adjacent lane to the east changes lane into its lane.",
    "The ego is travelling southbound when a truck in the adjacent lane to the west changes lane into its lane.",
])
def test_the_lane_to_a_compass_point_is_a_side_lane(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("truck", "change_lane_to_left", "right")]
    assert not road(prompt).junction


@pytest.mark.parametrize("prompt, expected", [
    ("ego left turn unprotected, oncoming mc fast, dusk",
     [("car", "turn_left", "ego"), ("motorcycle", "go_straight", "road_of_straight")]),
    ("mc brakes hard in front of ego on wet road, heavy traffic",
     [("car", "go_straight", "ego"), ("motorcycle", "stop", "front")]),
])
def test_shorthand_typed_in_a_hurry(prompt, expected):
    assert agents(prompt) == expected


def test_ln_is_a_lane():
    assert road("ego overtakes truck on 2 ln rural road, oncoming bus appears").lanes == 2


@pytest.mark.parametrize("prompt", ["night, no street lights, ped walking on road edge, ego straight",
                                    "Night time, no street light, my car going straight on country road."])
def test_no_street_lights_is_dark_and_no_traffic_light(prompt):
    assert "traffic_light" not in road(prompt).required_signals
    assert not road(prompt).junction
    assert lower(prompt).scenario.weather.time == "night"


def test_an_arrow_typed_as_two_marks_is_then():
    assert agents("ego straight -> truck cuts in -> ego brakes") == [
        ("car", "go_straight", "ego"), ("truck", "change_lane_to_right", "front_left")]


@pytest.mark.parametrize("prompt", ["bus stops at bus stop, ego overtakes it, oncoming bike",
                                    "rural road, bus stops suddenly, ego overtakes it"])
def test_bus_stops_said_of_a_bus_is_its_stopping(prompt):
    assert ("bus", "stop", "front") in agents(prompt)


@pytest.mark.parametrize("prompt", ["Three cars wait ahead of the ego. All three turn right.",
                                    "Three cars wait ahead of the ego. All of them turn right."])
def test_all_of_a_group_named_before_do_what_is_said(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego")] + [("car", "turn_right", "front")] * 3


@pytest.mark.parametrize("rest", ["the others", "the rest", "the remaining two"])
def test_the_rest_of_a_group_some_were_told_apart_from(rest):
    assert agents(f"Four cyclists ride ahead of the ego. Two of them turn left and {rest} stop.") == [
        ("car", "go_straight", "ego")] + [("cyclist", "stop", "front")] * 2 + [("cyclist", "turn_left", "front")] * 2


def test_neither_denies_past_a_count_and_a_place():
    assert agents("Neither of the two oncoming trucks turns, and the ego turns left.") == [
        ("car", "turn_left", "ego")] + [("truck", "go_straight", "road_of_straight")] * 2


@pytest.mark.parametrize("prompt, expected", [
    ("The ego goes straight. Two cars, one on each side, brake.",
     [("car", "go_straight", "ego"), ("car", "stop", "left"), ("car", "stop", "right")]),
    ("The ego is in the middle lane. Two cars, one in each adjacent lane, change lane into the ego's lane.",
     [("car", "change_lane_to_left", "front_right"), ("car", "change_lane_to_right", "front_left"),
      ("car", "go_straight", "ego")]),
])
def test_a_verb_after_an_apposition_is_its_subjects(prompt, expected):
    assert agents(prompt) == expected


def test_signalled_by_someone_is_no_traffic_light():
    waved_in = road("Was signalled by a police car to pull into a lay-by for a routine check.")
    assert "traffic_light" not in waved_in.required_signals
    assert "traffic_light" in road("The junction is signalled by lights.").required_signals


@pytest.mark.parametrize("prompt, teller", [
    ("I want to file a complaint. I was riding through the junction when a pickup coming from my left rolled "
     "through his stop sign.", ("cyclist", "go_straight", "road_of_right_turn")),
    ("I was turning left with my arm out when a car coming towards me went through the lights on amber.",
     ("cyclist", "turn_left", "front")),
])
def test_a_rider_reporting_a_driver_with_no_word_of_pedals(prompt, teller):
    assert agents(prompt) == [("car", "go_straight", "ego"), teller]


@pytest.mark.parametrize("prompt, expected", [
    ("Car 1 is the ego, waiting to turn left at a junction. Car 2 is oncoming and goes straight, and car 3 is "
     "oncoming and turns right.", [("car", "go_straight", "road_of_straight"), ("car", "turn_left", "ego"),
                                   ("car", "turn_right", "road_of_straight")]),
    ("Truck 1 is the ego and goes straight. Truck 2 comes from the left and turns right.",
     [("truck", "go_straight", "ego"), ("truck", "turn_right", "road_of_left_turn")]),
    ("Our tram 1 is the ego. Tram 2 comes the other way.", [("bus", "go_straight", "ego"),
                                                             ("bus", "go_straight", "front_left")]),
])
def test_one_numbered_vehicle_declared_the_ego_leaves_the_others_numbered_alike(prompt, expected):
    assert agents(prompt) == expected


def test_a_fleet_number_declared_the_ego_still_names_it_by_its_noun():
    assert agents("Van 203 is the ego. The van turns left while a car comes from the left.") == [
        ("car", "go_straight", "road_of_left_turn"), ("car", "turn_left", "ego")]


@pytest.mark.parametrize("prompt", ["ego turns right at junction; ped crossing side road crosswalk from the left",
                                    "Ego turns right; ped crossing crosswalk on ego left side",
                                    "ego turns right; ped crossing far-side crosswalk left to right"])
def test_a_ped_crossing_what_a_note_names_without_its_article_is_a_person(prompt):
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in agents(prompt)


@pytest.mark.parametrize("prompt", ["Ego goes straight through the pedestrian crossing near the school.",
                                    "The ego approaches a pedestrian crossing side by side with a bus."])
def test_a_pedestrian_crossing_with_its_article_is_still_a_crosswalk(prompt):
    assert not any(kind == "pedestrian" for kind, _, _ in agents(prompt))
    assert "crosswalk" in road(prompt).required_objects


@pytest.mark.parametrize("prompt, expected", [
    ("Ego: straight through 4-way signalised junction on green; Actor 1: oncoming car turns left across path; "
     "Road: 2 lanes per direction, TL controlled; Env: dry, daylight",
     [("car", "go_straight", "ego"), ("car", "turn_left", "road_of_straight")]),
    ("Ego: right turn at unsignalised 4-way all-way stop; Actor 1: car from side road left goes straight; Actor 2: "
     "oncoming car turns left; Road: 1 lane per approach, stop signs",
     [("car", "go_straight", "road_of_left_turn"), ("car", "turn_left", "road_of_straight"),
      ("car", "turn_right", "ego")]),
])
def test_numbered_actor_keys_run_on_in_one_line_each_key_one_road_user(prompt, expected):
    assert agents(prompt) == expected


def test_a_note_says_the_side_road_and_then_its_side():
    assert agents("The ego goes straight; truck from side road right turns right into ego lane ahead") == [
        ("car", "go_straight", "ego"), ("truck", "turn_right", "road_of_right_turn")]


@pytest.mark.parametrize("prompt, expected", [
    ("ego test veh EB straight, motorcycle overtaking from behind cut in front.",
     [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "back")]),
    ("t=0.0 ego lane 2 of 3 v=12 straight; t=0.8 object#4 (truck) ahead lane 2 dist=35 braking",
     [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
])
def test_a_logs_short_words_name_no_other_vehicle(prompt, expected):
    assert agents(prompt) == expected


def test_a_logged_v_is_a_speed_in_metres_per_second():
    ego = next(a for a in lower("t=0.0 ego lane 1 of 2 v=15 straight").scenario.agents() if a.is_ego)
    assert ego.speed is not None and round(ego.speed.value) == 54


def test_the_bare_noun_a_label_is_said_to_be_is_one_more_road_user():
    assert agents("The ego turns right. Actor 1 is car from the left road, goes straight. Actor 2 is oncoming car, "
                  "turns left.") == [("car", "go_straight", "road_of_left_turn"),
                                     ("car", "turn_left", "road_of_straight"), ("car", "turn_right", "ego")]


def test_a_place_name_after_next_says_which_and_opens_no_stage():
    assert agents("Rainy day, ego car in right lane, one van from next lane overtake ego and cut in front of ego") \
        == [("car", "change_lane_to_right", "back_left"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", ["The ego goes straight on the crossroad with lights, and a bus from the opposite "
                                    "side is turning on the left in front of it",
                                    "The ego goes straight, and an oncoming bus turns on the left."])
def test_a_turn_said_on_a_side_is_a_turn_to_it(prompt):
    assert ("bus", "turn_left", "road_of_straight") in agents(prompt)


def test_a_verb_said_before_then_and_its_object_after():
    assert agents("The ego is in the right lane; a motorbike overtakes it from behind and makes then a lane change in "
                  "front of it") == [("car", "go_straight", "ego"), ("motorcycle", "change_lane_to_left", "back")]


def test_a_pedestrian_lane_is_a_crosswalk():
    prompt = "The ego is stopping at the pedestrian lane, there is a student crossing from the right."
    assert agents(prompt) == [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]
    assert "crosswalk" in road(prompt).required_objects


@pytest.mark.parametrize("prompt, expected", [
    ("The ego goes straight. A car comes from the left side road, and a cyclist comes from the same road.",
     ("cyclist", "go_straight", "road_of_left_turn")),
    ("The ego turns left. A truck is oncoming and a car comes out of the same road.",
     ("car", "go_straight", "road_of_straight")),
])
def test_from_the_same_road_as_the_one_named_before(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, kinds", [
    ("Ego straight; bus stopped ahead pulls out; ped crosses in front of bus from the right", ["bus", "pedestrian"]),
    ("VUT straight; school bus ahead stopped in same lane; child peds crossing in front of bus from right to left",
     ["bus", "pedestrian", "pedestrian"]),
])
def test_a_bare_noun_after_in_front_of_is_the_one_named_before(prompt, kinds):
    assert sorted(kind for kind, _, position in agents(prompt) if position != "ego") == kinds


@pytest.mark.parametrize("prompt, expected", [
    ("Signal pe ruka hua tha, peeche se ek truck aaya aur mere right side se nikal gaya.",
     [("car", "stop", "ego"), ("truck", "go_straight", "back_right")]),
    ("Main left lane mein tha, ek bus right wali lane se mere aage ghus gayi.",
     [("bus", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]),
    ("Chaurahe pe maine right turn liya, saamne se ek car seedhi aa rahi thi.",
     [("car", "go_straight", "road_of_straight"), ("car", "turn_right", "ego")]),
    ("Zebra crossing pe ek aunty road cross kar rahi thi, maine gaadi rok di.",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("Raat ko baarish ho rahi thi, aage wali car ne achanak brake maara.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("Ek bike wala left side se aaya aur meri lane mein cut kiya.",
     [("car", "go_straight", "ego"), ("motorcycle", "change_lane_to_right", "front_left")]),
    ("Signal pe ruk gaya tha, ek auto left se aaya aur mere aage ruk gaya.",
     [("car", "stop", "ego"), ("car", "stop", "front_left")]),
])
def test_hinglish_is_read_as_the_english_meant(prompt, expected):
    assert agents(prompt) == expected


def test_hinglish_weather_and_time_of_day():
    weather = lower("Raat ko baarish ho rahi thi, aage wali car ne achanak brake maara.").scenario.weather
    assert (weather.condition, weather.time) == ("mid_rain", "night")


@pytest.mark.parametrize("prompt", ["The main road has two lanes and a car comes from the side road on the left.",
                                    "Do not let the truck ahead of the ego turn; ek means nothing here."])
def test_a_few_words_that_are_also_hindi_leave_english_as_it_is(prompt):
    from ttsgc.lowering.lexicon import _hinglish
    assert _hinglish(prompt.lower()) == prompt.lower()


def test_a_clause_with_its_copula_before_a_comma_is_no_list_sharing_a_verb():
    assert agents("I was in the left lane, a bus from the right lane cut in ahead of me.") == [
        ("bus", "change_lane_to_left", "right"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Night works on the motorway, right lane closed. A car in the left lane was sitting level with a lorry in the "
     "right lane. At the taper the lorry went to merge left and the car would not let him in.",
     [("car", "go_straight", "ego"), ("truck", "change_lane_to_left", "right")]),
    ("Temp lights on red at the roadworks. A hatchback pulled up at the stop line, then a cyclist came round it from "
     "behind and went straight through the red.", [("car", "stop", "ego"), ("cyclist", "go_straight", "back")]),
])
def test_a_report_from_road_works_is_told_about_the_first_vehicle_it_names(prompt, expected):
    assert agents(prompt) == expected


def test_a_works_lorry_parked_on_the_shoulder_is_the_scene_the_ego_passes():
    assert ("truck", "stop", "front_right") in agents("roadworks: lorry parked on the hard shoulder, worker walking "
                                                       "across")


def test_a_flaggers_stop_board_is_no_one_stopping():
    assert agents("Flagging at the roadworks today, I had a van go straight through my stop board while a tipper "
                  "came towards it.") == [("car", "go_straight", "ego"), ("truck", "go_straight", "front_left")]


@pytest.mark.parametrize("prompt", [
    "I was riding my bicycle northbound in the bike lane when an oncoming SUV turned left across my path.",
    "Shoutout to the Tesla that passed me from behind and then turned right straight across my bike lane.",
])
def test_a_cyclists_own_bicycle_and_bike_lane_tell_of_a_rider_reporting_a_driver(prompt):
    said = agents(prompt)
    assert said[0][2] == "ego" and said[0][1].startswith("turn") and ("cyclist", "go_straight") in [
        (kind, action) for kind, action, _ in said]
    assert len(said) == 2


@pytest.mark.parametrize("prompt", [
    "From the bus I saw a lorry ahead of us turn left at the junction while a cyclist on its inside went straight.",
    "The school bus I ride was turning right at the lights while a kid on a bike came straight on the other way.",
])
def test_a_passenger_tells_of_the_bus_they_ride_by_more_names(prompt):
    assert next(a for a in agents(prompt) if a[2] == "ego")[0] == "bus"


def test_waiting_for_a_bus_is_not_riding_it():
    assert next(a for a in agents("The bus I was waiting for was late. A red hatchback turned left at the junction "
                                  "and a cyclist came the other way.") if a[2] == "ego")[0] == "car"


@pytest.mark.parametrize("prompt", ["The ego goes straight. A red Ford Transit Custom van overtakes it.",
                                    "The ego goes straight. A Toyota Hilux Invincible pickup overtakes it."])
def test_a_model_its_trim_and_its_noun_are_one_vehicle(prompt):
    assert len(agents(prompt)) == 2


@pytest.mark.parametrize("prompt, ego", [
    ("A lorry travelling at 15 m/s comes up behind a cyclist riding at 6 m/s. The lorry driver passes the cyclist at "
     "a constant 15 m/s.", "truck"),
    ("A fire engine goes through a red light at a crossroads at 18 m/s, coming from the road on the left. A car is "
     "approaching the crossroads on green at 14 m/s when its driver hears the siren and brakes.", "car"),
])
def test_a_text_naming_no_ego_is_told_from_the_one_driver_at_the_controls(prompt, ego):
    said = agents(prompt)
    assert sum(1 for a in said if a[2] == "ego") == 1 and next(a for a in said if a[2] == "ego")[0] == ego
    assert len(said) == 2


def test_a_driver_who_only_claims_is_not_at_the_controls():
    said = agents("Client was in the left lane. A Jeep in the right lane just ahead of client cut into client's lane "
                  "right in front of her. Jeep driver claims client was tailgating.")
    assert ("car", "change_lane_to_left", "front_right") in said


@pytest.mark.parametrize("prompt", [
    "I was riding my e-scooter straight in the bike lane when a sedan pulled out in front of me.",
    "On my e-scooter in the cycle lane going straight when a white van came past me.",
])
def test_the_tellers_own_e_scooter_is_ridden_as_a_scooter(prompt):
    assert next(a for a in agents(prompt) if a[2] == "ego")[0] == "motorcycle"


@pytest.mark.parametrize("prompt", [
    "My car in the left lane, the truck in the middle lane he change to the left lane in front of my car.",
    "Test vehicle in left lane, the tricycle in right lane suddenly change lane in front of ego.",
])
def test_a_placed_road_user_before_a_comma_shares_no_verb_with_the_next(prompt):
    assert [a for a in agents(prompt) if a[2] == "ego"] == [("car", "go_straight", "ego")]


def test_pedestrian_lights_are_a_signal_not_a_pedestrian():
    prompt = "The ego stops at a crosswalk with pedestrian lights. Two pedestrians cross from the left."
    assert sum(1 for kind, _, _ in agents(prompt) if kind == "pedestrian") == 2
    assert "traffic_light" in road(prompt).required_signals


@pytest.mark.parametrize("prompt", ["Only after the cyclist had cleared the junction did the ego turn right.",
                                    "The ego waited at the lights while a cyclist went straight. Only then did it "
                                    "turn right."])
def test_only_after_did_is_said_of_the_one_after_did(prompt):
    said = agents(prompt)
    assert ("cyclist", "go_straight") in [(kind, action) for kind, action, _ in said]
    assert ("car", "turn_right", "ego") in said


def test_a_conversion_to_a_side_is_a_turn():
    assert ("car", "turn_left", "road_of_straight") in agents(
        "The ego goes straight, but a taxi from the opposite direction makes the conversion to the left in front of "
        "it.")


@pytest.mark.parametrize("prompt, expected", [
    ("In front of the ego is a stopped van.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("The ego goes straight. Behind the ego is a truck.", [("car", "go_straight", "ego"), ("truck", "go_straight",
                                                                                         "back")]),
    ("My car is on the right lane, behind me is a bus.",
     [("bus", "go_straight", "back"), ("car", "go_straight", "ego")]),
])
def test_a_place_said_before_its_subject_and_a_copula(prompt, expected):
    assert agents(prompt) == expected


def test_one_behind_the_ego_overtaking_from_a_side_at_a_junction_passes_on_that_side():
    assert agents("At the junction the ego turns left. A motorcycle behind the ego overtakes it from the left side.") \
        == [("car", "turn_left", "ego"), ("motorcycle", "go_straight", "back_left")]


@pytest.mark.parametrize("prompt", [
    "A van on my right cuts across the front of my car.",
    "A van on my right cuts across my front.",
    "I'm in the artic. A white van comes up my offside and cuts straight across the front of the cab.",
])
def test_a_cut_across_the_egos_front_ends_there_and_starts_beside(prompt):
    assert [a for a in agents(prompt) if a[2] != "ego"] == [("car", "change_lane_to_left", "right")]


def test_a_vehicles_cab_is_part_of_it_not_a_taxi():
    assert agents("At the lights a lorry next to you on the left is turning left. Don't sit beside its cab in the "
                  "blind spot.") == [
        ("car", "go_straight", "ego"), ("truck", "turn_left", "left")]


@pytest.mark.parametrize("prompt, expected", [
    ("Job card 3320 - 2020 Hyundai Tucson. Customer states he was turning left at the intersection when an oncoming "
     "SUV came through.", [("car", "go_straight", "road_of_straight"), ("car", "turn_left", "ego")]),
    ("Job card 1178 - 2012 Nissan Leaf. Customer states she stopped at the four-way stop, then pulled out to go "
     "straight across.", [("car", "go_straight", "ego"), ("car", "stop", "ego")]),
])
def test_a_job_cards_heading_names_the_customers_vehicle(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, ego", [
    ("Tanker driver. Taking a left at the crossroads, I swung wide and a cyclist tried to go up my inside.", "truck"),
    ("HGV driver here. On the motorway in lane one, a car cut in front of me.", "truck"),
    ("Bus driver here, twenty years. A car cut in front of me.", "bus"),
    ("Lorry driver. Turning right at the lights, there was a bus waiting opposite.", "truck"),
])
def test_a_first_line_saying_what_the_speaker_drives_names_the_ego(prompt, ego):
    said = agents(prompt)
    assert [a[0] for a in said if a[2] == "ego"] == [ego]
    assert sum(1 for a in said if a[0] == ego) == 1 + (ego == "bus" and "bus waiting" in prompt)


@pytest.mark.parametrize("prompt", ["Empty trailer, fog on the motorway at dawn. Kept her at 40.",
                                    "Trucking on the interstate at night in the snow, nothing else about."])
def test_a_truckers_words_tell_of_a_truck_with_no_speaker_named(prompt):
    assert agents(prompt) == [("truck", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", [
    "A pickup ahead of me spun across into my lane and stopped there broadside.",
    "A red hatchback ahead of me aquaplaned, spun and came to rest in front of me.",
])
def test_one_come_to_rest_athwart_the_egos_lane_blocks_it(prompt):
    assert ("car", "block_the_ego", "front") in agents(prompt)


@pytest.mark.parametrize("prompt, action", [
    ("Control from Tango 4-2, we're northbound approaching junction 28, a silver Audi ahead of us is weaving.",
     "go_straight"),
    ("22:10 Bravo 1-1 stationary at red signal Queen St. A moped alongside on our left went through on red.", "stop"),
    ("1318 Echo 4 turning right out of Abbey Rd, white van approaching from our right at speed.", "turn_right"),
])
def test_a_patrols_call_sign_tells_of_a_police_car(prompt, action):
    assert ("police", action, "ego") in agents(prompt)


def test_a_make_said_as_a_model_is_no_call_sign():
    assert agents("My Golf 4 turned left at the junction.") == [("car", "turn_left", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Veh 1 white Transit tailgating a bus directly in front.", [("bus", "go_straight", "front"),
                                                                 ("car", "go_straight", "ego")]),
    ("V1 blue Ford Focus turning R into Forge Ln collided with V2 white Transit travelling SB.",
     [("car", "go_straight", "front"), ("car", "turn_right", "ego")]),
    ("V1 turns left. V2 white HGV goes straight.", [("car", "turn_left", "ego"), ("truck", "go_straight", "front")]),
])
def test_a_label_then_paint_and_a_noun_is_one_vehicle(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Riding west into the low sun on Clifton Road when a Corsa coming the other way turned right across me.",
     [("car", "turn_right", "ego"), ("cyclist", "go_straight", "road_of_straight")]),
    ("Yet again a delivery van parked right across the cycle lane, which forced me out into the traffic to get round "
     "it.", [("car", "stop", "ego"), ("cyclist", "go_straight", "back")]),
])
def test_a_rider_with_no_bicycle_named_reports_a_driver(prompt, expected):
    assert agents(prompt) == expected


def test_a_motorbike_reported_by_a_cyclist_is_the_ego():
    said = agents("A moped rider came up behind me in the cycle lane and squeezed past at speed.")
    assert [a[0] for a in said] == ["cyclist", "motorcycle"] and said[1][2] == "ego"


@pytest.mark.parametrize("prompt", [
    "I was riding my e-scooter along the high street when a moped came up behind me.",
    "Riding the lime scooter home when a taxi sat right on my back wheel.",
])
def test_a_rider_on_a_scooter_of_their_own_stays_the_ego(prompt):
    assert next(a for a in agents(prompt) if a[2] == "ego")[0] == "motorcycle"


@pytest.mark.parametrize("prompt, expected", [
    ("I use a mobility scooter and was halfway over the zebra when a silver hatchback came straight through.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("I was already on the crossing in my wheelchair when a white van swung left across it.",
     [("car", "turn_left", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
])
def test_a_teller_in_a_wheelchair_on_the_crossing_is_met_there(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, ego", [
    ("Was on the 16 coming back from the hospital. A car from the left shot across in front of us, the driver did "
     "well to stop.", "bus"),
    ("Honestly the 42 driver is a menace. Swung into the left lane and a cyclist alongside us had to swerve.", "bus"),
    ("We were on the 101 and the driver in front braked hard.", "car"),
    ("I was on the 405 when the car in front of me braked hard.", "car"),
])
def test_a_bus_ridden_by_its_route_number(prompt, ego):
    assert [a[0] for a in agents(prompt) if a[2] == "ego"][:1] == [ego]


def test_a_word_before_the_next_sentences_verb_is_no_make():
    assert agents("The ego bus is a menace. Swung into the left lane.") == [("bus", "change_lane_to_left", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("I drove onto the roundabout, then came from the right a scooter that did not give way, and behind me drove a "
     "police car.", [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "road_of_right_turn"),
                     ("police", "go_straight", "back")]),
    ("The ego waits at the lights. In front of it stood a lorry with its hazards on.",
     [("car", "stop", "ego"), ("truck", "stop", "front")]),
])
def test_a_place_and_a_verb_said_before_the_one_who_moves(prompt, expected):
    assert agents(prompt) == expected


def test_as_a_driver_of_a_kind_the_speaker_drives_one():
    assert agents("As a bus driver on Victoria Road, I am routinely cut up by a car in the lane to my left that "
                  "swerves in front of me.")[0] == ("bus", "go_straight", "ego")


@pytest.mark.parametrize("prompt", [
    "While I was on the crossing, a white SUV turning right came straight at me.",
    "I was on the crossing when a white SUV turned right and came straight at me.",
])
def test_a_turn_said_as_a_participle_is_how_a_vehicle_came(prompt):
    assert agents(prompt) == [("car", "turn_right", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]


@pytest.mark.parametrize("prompt, expected", [
    ("A car is 20 m behind a cyclist. The car continues straight on.",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]),
    ("A car moving at 10 m/s is 20 m behind a cyclist when the cyclist turns right into a side street.",
     [("car", "go_straight", "ego"), ("cyclist", "turn_right", "front")]),
])
def test_a_vehicle_placed_by_a_rider_is_the_one_the_scene_is_told_from(prompt, expected):
    assert agents(prompt) == expected


def test_going_by_motorbike_rides_one():
    assert agents("I was going by motorbike in the left lane and in front of me a car suddenly braked.") == [
        ("car", "stop", "front"), ("motorcycle", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, where", [
    ("I was in the left lane and in front of me a car suddenly braked.", "front"),
    ("I was in the left lane and behind me a white van was tailgating.", "back"),
])
def test_a_place_by_the_speaker_said_before_the_next_subject_is_that_ones(prompt, where):
    assert [a[2] for a in agents(prompt) if a[2] != "ego"] == [where]


def test_a_lettered_labels_possessive_names_the_same_one():
    assert agents("Car A travels east. A pedestrian crosses ahead of it. Will the pedestrian be clear of car A's "
                  "lane?") == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("Guy overtakes a whole line of traffic on a blind bend and almost hits me head on.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "front_left")]),
    ("The guy in the right lane sped up so I couldn't get in.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "right")]),
    ("The guy next to me on the left runs the red light.", [("car", "go_straight", "ego"),
                                                            ("car", "go_straight", "left")]),
])
def test_a_vague_person_in_a_lane_or_passing_drives(prompt, expected):
    assert agents(prompt) == expected


def test_someone_opening_a_parked_cars_door_is_inside_it():
    assert agents("Somebody flung open the door of a parked taxi just ahead on my left.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "front_left")]


def test_an_obligation_with_no_subject_by_the_speakers_brakes_is_the_speakers():
    assert agents("A bus came on from the right without slowing down, had to stand on my brakes.") == [
        ("bus", "go_straight", "right"), ("car", "stop", "ego")]


def test_the_vehicle_a_text_opens_on_placed_by_one_named_after_is_the_ego():
    assert agents("A lorry moving at 18 m/s is 40 m behind car B, which is doing 12 m/s in the same lane.") == [
        ("car", "go_straight", "front"), ("truck", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", [
    "Car X turns right at a crossroads. A motorcycle comes from the road on car X's left.",
    "A car turns right at a crossroads. A motorcycle comes from the road on the car's left.",
])
def test_the_road_on_a_named_vehicles_side_is_a_side_road(prompt):
    assert agents(prompt) == [("car", "turn_right", "ego"), ("motorcycle", "go_straight", "road_of_left_turn")]


def test_a_numbered_labels_possessive_names_the_same_one():
    assert agents("V1 was travelling north. V2, in the lane to V1's right, swerved into V1's lane.") == [
        ("car", "change_lane_to_left", "right"), ("car", "go_straight", "ego")]


def test_a_vehicle_said_only_to_head_somewhere_is_on_its_way():
    assert agents("Vehicle A was heading north on Main Street. Vehicle B was heading east on Oak Avenue and entered "
                  "the intersection.") == [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]


@pytest.mark.parametrize("prompt, expected", [
    ("Car A travels at 20 m/s towards a stationary van 60 m ahead. What deceleration does car A need to stop just "
     "short of the van?", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("A car travels at 13 m/s and a child runs out 18 m ahead. How far short of the child does it stop, if at all?",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
])
def test_what_a_wh_question_asks_is_not_told(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "Complaint about the 301: the bus just sat there at a green light, and the lorry behind us leaned on its horn.",
    "Dear First Bus, your driver on the 24 ran the red at Carlton Cross and a car coming from the right had to stop.",
])
def test_a_bus_named_by_its_route_in_a_complaint_is_the_ego(prompt):
    assert [a[0] for a in agents(prompt) if a[2] == "ego"] == ["bus"]


@pytest.mark.parametrize("prompt", [
    "A car is travelling at 13 m/s along a street. The driver reacts in 0.7 s and brakes with a deceleration of "
    "7 m/s².",
    "A car is travelling at 16 m/s. A bus pulls out in front of it, and the car driver brakes at 6 m/s^2.",
])
def test_a_rate_of_braking_in_a_word_problem_is_no_halt(prompt):
    assert ("car", "go_straight", "ego") in agents(prompt)


def test_a_counted_group_crossing_is_not_what_the_next_one_does():
    assert agents("Ego approaching the crossing. Three schoolkids crossing on their green man and a mum with a buggy "
                  "standing on the pavement.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
        ("pedestrian", "cross_the_road", "near_the_crosswalk"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
        ("pedestrian", "on_the_sidewalk", "near_the_crosswalk")]


@pytest.mark.parametrize("prompt", [
    "A car overtakes a lorry. The lorry is 16 m long.",
    "A car passes a cyclist. The cyclist is 2 m wide.",
])
def test_a_size_in_metres_is_no_gap(prompt):
    assert all(a.gap_m is None for a in lower(prompt).scenario.agents())


@pytest.mark.parametrize("prompt", [
    "A car approaches a crossroads.",
    "A car is approaching a junction.",
])
def test_the_vehicle_a_text_opens_on_approaching_a_junction_is_the_ego(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", [
    "A motorist sees a cyclist.",
    "A motorist at 30 mph spots a cyclist.",
])
def test_one_who_opens_the_text_by_seeing_another_is_the_ego(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("Our crash cushion truck was parked at the start of the lane 1 closure, beacons going, and a supermarket delivery "
     "lorry in lane 1 went right into the back of it in the rain.",
     [("truck", "go_straight", "ego"), ("truck", "stop", "front")]),
    ("We had the left lane coned off on the interstate, our arrow board truck parked at the head of the taper; a semi "
     "in the right lane started merging left into the taper before he saw it.",
     [("truck", "change_lane_to_left", "ego"), ("truck", "stop", "front")]),
])
def test_a_works_crews_own_standing_lorry_is_what_the_driver_meets(prompt, expected):
    assert agents(prompt) == expected


def test_a_patrols_own_car_in_a_closure_stays_the_ego():
    assert agents("Our patrol car was parked in the closure with the cones out, and a van in lane 1 went past it.")[
        -1] != ("police", "stop", "front")


def test_the_end_of_a_shuttle_is_road_works_not_a_bus():
    assert not any(a[0] == "bus" for a in agents(
        "I had the stop board up at the south end of the shuttle when a white Transit carried on past the board."))


@pytest.mark.parametrize("prompt", [
    "I turned right at the crossroads on the GS and had to ease off for a woman pushing a pram.",
    "I was on my Bonneville when a car pulled out of a side road on my left.",
])
def test_a_motorbike_named_by_its_model_is_the_riders_own(prompt):
    assert [a[0] for a in agents(prompt) if a[2] == "ego"] == ["motorcycle"]


def test_road_users_named_only_by_their_kind_in_a_habit_are_the_scene():
    assert agents("Drivers turning left regularly cut across cyclists going straight on.") == [
        ("car", "change_lane_to_left", "ego"), ("cyclist", "go_straight", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("A police car leaving the station had to pull up sharply because a pedestrian stepped off the kerb directly in "
     "front of it.", [("pedestrian", "cross_the_road", "front"), ("police", "stop", "ego")]),
    ("An ambulance on a blue-light run had to wait behind a taxi that had stopped in front of it.",
     [("ambulance", "stop", "ego"), ("car", "stop", "front")]),
])
def test_what_the_one_the_scene_is_told_from_is_made_to_do_it_does(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A BMW in the left lane swung right into my lane.", ("car", "change_lane_to_right", "left")),
    ("I was cruising in lane two when a white BMW just ahead of me in lane one swung right into my lane.",
     ("car", "change_lane_to_right", "front_left")),
])
def test_a_turn_into_a_lane_of_the_same_road_is_a_lane_change(prompt, expected):
    assert expected in agents(prompt)
    assert road(prompt).junction is not True


def test_a_truckers_wagons_are_lorries():
    assert agents("Three of us in convoy this morning, me leading in the DAF nice and slow and two more wagons off the "
                  "same yard tucked in behind.") == [
        ("truck", "go_straight", "back"), ("truck", "go_straight", "back"), ("truck", "go_straight", "ego")]


def test_a_marked_unit_is_a_police_car():
    assert [a[0] for a in agents("Unit 31, marked unit, I-5 SB, 3 lanes. Unit in #2 lane. Black Charger in the #1 "
                                 "lane to the left of unit cut across in front of unit into the #3 lane.")
            if a[2] == "ego"] == ["police"]


@pytest.mark.parametrize("prompt, expected", [
    ("Entering the junction from the south, my car goes straight; a police car comes from the west, and a fire engine "
     "comes from the north.", [("car", "go_straight", "ego"), ("firetruck", "go_straight", "road_of_straight"),
                                ("police", "go_straight", "road_of_left_turn")]),
    ("Northbound ego car turning right at an intersection; a southbound motorcycle proceeds straight.",
     [("car", "turn_right", "ego"), ("motorcycle", "go_straight", "road_of_straight")]),
])
def test_the_egos_compass_heading_places_the_others(prompt, expected):
    assert agents(prompt) == expected


def test_a_side_said_beats_a_compass_word_in_brackets():
    assert ("car", "stop", "road_of_left_turn") in agents(
        "The ego vehicle comes from south and drives straight over the crossroads. On the street from the left (west) "
        "a car stands at the red light.")


def test_cutting_in_right_in_front_of_the_ego_ends_there():
    assert agents("A car in the left lane cuts in right in front of the ego vehicle.") == [
        ("car", "change_lane_to_right", "left"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Two cars are waiting at a red light with the ego SUV stopped behind them.",
     [("car", "stop", "ego"), ("car", "stop", "front"), ("car", "stop", "front")]),
    ("A bus turns left with the ego waiting behind it.", [("bus", "turn_left", "front"), ("car", "stop", "ego")]),
])
def test_with_the_ego_and_its_own_state_and_place(prompt, expected):
    assert agents(prompt) == expected


def test_waiting_at_a_pedestrian_crossing_names_no_pedestrian():
    assert agents("The ego waits at a pedestrian crossing while three schoolchildren walk across.") == [
        ("car", "stop", "ego")] + [("pedestrian", "cross_the_road", "near_the_crosswalk")] * 3


def test_it_after_the_narrator_reports_a_vehicle_is_that_vehicle():
    assert agents("I'm reporting a white van. It overtook me while I was riding.") == [
        ("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("As I go through the intersection a bus comes in from the left and turns right.",
     [("bus", "turn_right", "road_of_left_turn"), ("car", "go_straight", "ego")]),
    ("When I reached the junction a bus pulled out and turned left.",
     [("bus", "turn_left", "front"), ("car", "go_straight", "ego")]),
])
def test_a_subordinate_clause_with_no_comma_ends_where_a_new_subject_and_verb_start(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("I had the stop board up when a white Transit carried on past the board and came straight at me.",
     [("car", "go_straight", "ego"), ("pedestrian", "stop", "front")]),
    ("I was holding the paddle on STOP and a pickup rolled right up to me and stopped two feet from my boots.",
     [("car", "stop", "ego"), ("pedestrian", "stop", "front")]),
    ("Stop/go on the single-lane section. Once the cement mixer was past me I spun the board to GO.",
     [("truck", "go_straight", "ego")]),
])
def test_one_working_the_traffic_on_foot_is_placed_only_when_the_driver_comes_at_them(prompt, expected):
    assert agents(prompt) == expected


def test_riders_who_say_we_ride_their_own_bike():
    assert agents("We were two-up on the Africa Twin, sat at a red light behind a Honda Civic, when a kid on a "
                  "pushbike shot across the junction from the left.") == [
        ("car", "stop", "front"), ("cyclist", "cross_the_road", "road_of_left_turn"), ("motorcycle", "stop", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Sat at the red on the A38 in the wagon when a cop car came up behind me on blues.",
     [("police", "go_straight", "back"), ("truck", "stop", "ego")]),
    ("Bobtailing back to the yard, I was stopped at a four way stop and a pickup from my right rolled through.",
     [("car", "go_straight", "road_of_right_turn"), ("truck", "stop", "ego")]),
])
def test_a_truckers_own_words_for_the_truck_make_the_ego_a_truck(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("EGO: bus / turn right || NPC1: cyclist / from left road / straight || NPC2: car / oncoming / stopped || "
     "Junction: signalised crossroads",
     [("bus", "turn_right", "ego"), ("car", "stop", "road_of_straight"),
      ("cyclist", "go_straight", "road_of_left_turn")]),
    ("{ego: bus, straight} {npc: car, right lane just ahead, cuts in to the left} {weather: heavy rain, night}",
     [("bus", "go_straight", "ego"), ("car", "change_lane_to_left", "front_right")]),
    ("ego=car:turn_right; a1=car:from opposite road:straight; junction=crossroads, no traffic lights",
     [("car", "go_straight", "road_of_straight"), ("car", "turn_right", "ego")]),
    ("ego_type=truck ego_manoeuvre=straight npc_1=police,behind,straight npc_2=car,same lane ahead,braking to a stop",
     [("car", "stop", "front"), ("police", "go_straight", "back"), ("truck", "go_straight", "ego")]),
])
def test_a_record_of_keyed_fields_on_one_line_reads_a_field_a_line(prompt, expected):
    assert agents(prompt) == expected


def test_a_list_of_tags_on_one_line_stays_a_list_of_tags():
    assert one_line_records("ego: car | weather: fog | lanes: 3") == "ego: car | weather: fog | lanes: 3"


@pytest.mark.parametrize("prompt, expected", [
    ("A bloke in a black BMW swung left into Mill Lane while I was crossing the end of it in my powerchair.",
     [("car", "turn_left", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("A lorry driver stopped well short of the zebra and waved me and my guide dog across.",
     [("pedestrian", "cross_the_road", "near_the_crosswalk"), ("truck", "stop", "ego")]),
    ("I was waiting at the zebra on my mobility scooter when a van parked right across it.",
     [("car", "stop", "ego"), ("pedestrian", "stop", "near_the_crosswalk")]),
])
def test_a_teller_with_a_mobility_aid_is_on_foot_and_met_by_the_vehicle(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", [
    "I was crossing the zebra with my son when a van drove straight over it.",
    "My daughter and I were halfway over the zebra when a taxi sailed through.",
])
def test_kin_crossing_with_the_teller_cross_too(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego")] + [
        ("pedestrian", "cross_the_road", "near_the_crosswalk")] * 2


@pytest.mark.parametrize("prompt, expected", [
    ("Dispatch, 4-Adam-3, we're sat in traffic on the Westway, boxed in by a bus in front.",
     [("bus", "block_the_ego", "front"), ("police", "stop", "ego")]),
    ("0845. On patrol in marked IRV, Church St. A male on a pedal cycle rode off the footway and crossed the road in "
     "front of us.", [("cyclist", "cross_the_road", "front"), ("police", "go_straight", "ego")]),
])
def test_a_patrols_own_run_or_call_sign_makes_the_ego_a_police_car(prompt, expected):
    assert agents(prompt) == expected


def test_an_opening_participle_on_foot_makes_the_teller_a_witness():
    assert agents("Whilst on foot at the taxi rank, I saw a black cab turn right across the path of an oncoming "
                  "moped.") == [("car", "turn_right", "ego"), ("motorcycle", "go_straight", "road_of_straight")]


@pytest.mark.parametrize("prompt, expected", [
    ("Amazon van, doing drops on Elm Street. I was parked on the right with my hazards on and a school bus went past "
     "me.", [("bus", "go_straight", "back_left"), ("car", "stop", "ego")]),
    ("Taxi stopped at the stop sign on Oak. A jogger went across in front of me.",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("Car stopped at the lights. I went round it.", [("car", "change_lane_to_left", "ego"), ("car", "stop", "front")]),
    ("Van on the hard shoulder. I moved over to the middle lane.",
     [("car", "change_lane_to_left", "ego"), ("car", "stop", "front_right")]),
])
def test_a_text_opening_on_a_bare_standing_vehicle_opens_on_the_speakers_own(prompt, expected):
    assert agents(prompt) == expected


def test_vehicle_words_kept_from_another_language():
    assert agents("On highway I drive behind big tir, he go very slow, so I go to left lane for overtake him.") == [
        ("car", "change_lane_to_left", "ego"), ("truck", "go_straight", "front")]
    assert agents("Make scenario please: two otobüs waiting on red light in front of ego car, ego also stop.") == [
        ("bus", "stop", "front"), ("bus", "stop", "front"), ("car", "stop", "ego")]


@pytest.mark.parametrize("prompt", [
    "Riding along the cycle lane this morning and a tipper lorry comes alongside me then swings left into Tollington "
    "Way.",
    "Road: A6 northbound. Summary: The HGV overtook me at around 50mph and the draught nearly pulled me off the bike.",
])
def test_a_rider_said_of_no_noun_is_a_cyclist_met_by_the_vehicle_reported(prompt):
    found = agents(prompt)
    assert ("cyclist", "go_straight", "front") in found and found[-1][0] == "truck" and found[-1][2] == "ego"


def test_a_summary_told_by_the_one_it_happened_to_is_the_scene_and_a_short_one_a_title():
    assert agents("Summary: Unprotected left turn with oncoming traffic.") == [("car", "turn_left", "ego")]
    assert len(agents("Road: A6. Summary: The van overtook me and cut in sharply right in front of my car.")) == 2


def test_a_witness_on_the_pavement_a_vehicle_comes_towards_is_ahead_of_it_in_its_path():
    assert agents("I was on the pavement outside the bakery when a white Transit mounted the kerb and came towards "
                  "me.") == [("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "front")]


@pytest.mark.parametrize("prompt, riders", [
    ("We were riding two abreast when a pickup came flying past us.", 2),
    ("Three of us were riding single file when a Range Rover overtook us on a blind bend.", 3),
    ("Our group of four was riding single file when a red Jeep passed us on a double yellow.", 4),
])
def test_a_party_of_riders_reporting_a_driver_is_that_many_cyclists_ahead_of_it(prompt, riders):
    assert agents(prompt) == [("car", "go_straight", "ego")] + [("cyclist", "go_straight", "front")] * riders


def test_a_rider_hooked_from_beside_the_turner_is_on_that_side():
    assert agents("Left hook at King St. I was in the cycle lane level with the cab of a DPD van when he turned left "
                  "straight across me.") == [("car", "turn_left", "ego"), ("cyclist", "go_straight", "left")]


@pytest.mark.parametrize("prompt, expected", [
    ("Paramedic, night shift. We were stopped at the lights with the patient on board, a taxi waiting behind us.",
     [("ambulance", "stop", "ego"), ("car", "stop", "back")]),
    ("We were on our way to a house fire when a car ahead of us stopped dead in the lane.",
     [("car", "stop", "front"), ("firetruck", "go_straight", "ego")]),
])
def test_a_crew_that_says_we_of_its_own_vehicle_drives_an_ambulance_or_a_fire_engine(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, people", [
    ("We were halfway over the zebra when a taxi sailed through.", 2),
    ("Walking my two to school, we were on the zebra outside St Mary's when a silver Audi drove straight through.", 3),
])
def test_a_tellers_party_on_the_way_over_is_that_many_people_crossing(prompt, people):
    assert agents(prompt) == [("car", "go_straight", "ego")] + [
        ("pedestrian", "cross_the_road", "near_the_crosswalk")] * people


@pytest.mark.parametrize("prompt, expected", [
    ("Describe what happened: a group of schoolkids suddenly ran across the road in front of me outside the school.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front"),
      ("pedestrian", "cross_the_road", "front")]),
    ("Describe what happened: I was stationary at a red light when the vehicle behind failed to stop and struck the "
     "rear of my car. Your vehicle: Ford Focus. Third party vehicle: Vauxhall Astra.",
     [("car", "go_straight", "back"), ("car", "stop", "ego")]),
    ("Your vehicle: 44t artic (HGV). Third party vehicle: silver Nissan Micra. Describe what happened: I was turning "
     "left out of the depot when the Micra, travelling from my right, drove into the side of my trailer.",
     [("car", "go_straight", "road_of_right_turn"), ("truck", "turn_left", "ego")]),
])
def test_a_claim_forms_fields_name_the_claimants_vehicle_and_its_account_is_the_scene(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Sir, I watched as a double-decker bus swung right into Wharf Lane while a young woman was crossing that very "
     "road with a pushchair.", [("bus", "turn_right", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("I watched the car in front of me brake hard.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
])
def test_a_teller_who_only_looks_on_is_no_one_and_one_by_whom_others_are_placed_drives(prompt, expected):
    assert agents(prompt) == expected


def test_police_who_report_are_no_one_and_police_who_drive_are():
    assert agents("Police have released CCTV of a near miss in which a red hatchback went past a bus stationary at "
                  "a stop.") == [("bus", "stop", "front"), ("car", "go_straight", "ego")]
    assert ("police", "go_straight", "ego") in agents("Police were chasing a stolen car when it crashed.")


def test_a_vehicle_turning_into_the_road_is_going_its_own_way_not_standing_in_it():
    assert agents("A cement lorry swings right off the high street into the road while two kids are still on the "
                  "zebra.") == [("pedestrian", "cross_the_road", "near_the_crosswalk")] * 2 + [
        ("truck", "turn_right", "ego")]


def test_a_vehicle_pulling_out_of_a_side_road_to_turn_goes_its_own_way():
    assert agents("A hatchback pulled out of Orchard Close and turned right, and a cyclist approaching from the right "
                  "had to brake.") == [("car", "turn_right", "ego"), ("cyclist", "go_straight", "road_of_right_turn")]


@pytest.mark.parametrize("prompt", [
    "A traffic car pulled me over on the M6.",
    "We were hit from behind at the lights and paramedics checked us over.",
    "We were at the pump when a van reversed into us.",
])
def test_a_patrols_or_a_crews_words_said_of_others_leave_the_speaker_in_a_car(prompt):
    assert [kind for kind, _, where in agents(prompt) if where == "ego"] == ["car"]


@pytest.mark.parametrize("prompt, expected", [
    ("A white Transit turned left out of the industrial estate into the path of a motorbike coming along the main "
     "road from the right.", [("car", "turn_left", "ego"), ("motorcycle", "go_straight", "road_of_right_turn")]),
    ("A lorry turned left out of a side road across the path of a car coming from the right.",
     [("car", "go_straight", "road_of_right_turn"), ("truck", "turn_left", "ego")]),
])
def test_the_path_of_another_is_that_ones_not_the_egos(prompt, expected):
    assert agents(prompt) == expected


def test_the_path_of_the_ego_is_the_egos():
    assert agents("A child runs out from between parked cars into the path of the ego vehicle.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]


def test_a_teller_on_foot_drives_no_car_so_the_car_is_another():
    assert agents("I was walking on the zebra when the car turned left.") == [
        ("car", "turn_left", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_a_party_of_riders_is_counted_past_six():
    assert agents("There were eight of us riding two abreast on Coldharbour Lane when a grey Volvo overtook the whole "
                  "group.") == [("car", "go_straight", "ego")] + [("cyclist", "go_straight", "front")] * 8


@pytest.mark.parametrize("prompt, expected", [
    ("When I stopped a van hit me from behind.", [("car", "go_straight", "back"), ("car", "stop", "ego")]),
    ("As I went forward a car came out of the junction on my right and struck my car.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_right_turn")]),
])
def test_a_subordinate_clause_ends_where_its_left_out_comma_would(prompt, expected):
    assert agents(prompt) == expected


def test_a_car_passed_and_parked_is_the_object_of_the_subordinate_clause():
    assert ("car", "stop", "front_left") in agents("As I passed a car parked on the left, a cyclist came towards me.")


def test_the_subject_of_a_passive_is_met_not_left_out():
    assert agents("The cyclist was clipped by a van turning left.") == [
        ("car", "turn_left", "ego"), ("cyclist", "go_straight", "front")]


def test_when_i_got_to_the_junction_ends_where_its_comma_would():
    assert agents("When I got to the junction a lorry turned left in front of me.") == [
        ("car", "go_straight", "ego"), ("truck", "turn_left", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("The car I was following braked hard.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("The lorry I was behind turned left.", [("car", "go_straight", "ego"), ("truck", "turn_left", "front")]),
    ("The lorry that I was behind turned left.", [("car", "go_straight", "ego"), ("truck", "turn_left", "front")]),
    ("A van came out of the road on the left, and the car I was following had to stop dead.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn"), ("car", "stop", "front")]),
])
def test_a_relative_whose_subject_is_the_speaker_places_its_noun_ahead(prompt, expected):
    assert agents(prompt) == expected


def test_the_vehicle_the_speaker_drives_is_the_ego():
    assert agents("The taxi I was driving stopped at the lights.") == [("car", "stop", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Bus stops dead as schoolboy darts into road mid-block",
     [("bus", "stop", "ego"), ("pedestrian", "cross_the_road", "front_left")]),
    ("A bus stopped for a woman on the zebra.",
     [("bus", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
])
def test_one_that_stops_for_someone_is_the_one_the_scene_is_told_from(prompt, expected):
    assert agents(prompt) == expected


def test_a_bus_stopped_for_its_passengers_is_met_standing():
    assert agents("A bus stopped for passengers at the stop.") == [
        ("bus", "stop", "front"), ("car", "go_straight", "ego")]


def test_a_riders_elbow_is_a_part_not_a_side():
    assert agents("A white transit came past so close his mirror clipped my right elbow. I was riding in primary.") == [
        ("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]


def test_a_rider_said_only_by_the_bike_is_met_by_the_one_vehicle_named():
    assert agents("For about a mile along Station Lane a pickup sat a few feet off my back wheel revving, then flew "
                  "past with inches to spare.") == [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]


@pytest.mark.parametrize("prompt, riders", [
    ("Reporting on behalf of Wheelers CC. I was leading six riders (me included) along the B4009 when a tipper truck "
     "passed the group within a foot of the back marker's shoulder.", 6),
    ("Club ride of nine. A coach came past the whole group on the approach to Fleet services and then swung left into "
     "the slip road right across our lead rider.", 9),
    ("As ride captain I'm logging a near miss at the Hook roundabout: seven of us were already on the roundabout when "
     "an Audi came on from the next entry, from our left, and drove into the middle of the group.", 7),
])
def test_a_party_of_riders_is_as_many_as_its_leader_counts(prompt, riders):
    assert sum(kind == "cyclist" for kind, _, _ in agents(prompt)) == riders


def test_a_rider_met_by_one_out_of_a_named_street_on_a_side_is_on_the_road_across():
    assert agents("I was cycling north along Mill Road when a grey Vauxhall Astra emerged from Catharine Street on my "
                  "left and turned right across my path.") == [
        ("car", "turn_right", "ego"), ("cyclist", "go_straight", "road_of_right_turn")]


@pytest.mark.parametrize("prompt", [
    "There I was on my scooter, about halfway across the zebra by the bank, and a grey car came right at me and "
    "didn't slow down one little bit.",
    "Going over the pelican crossing by the town hall on my scooter, the green man was on, and a white van went "
    "straight through the red light just in front of me.",
])
def test_a_scooter_on_a_crossing_is_a_mobility_scooter_its_rider_on_foot(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_a_scooter_in_traffic_is_still_a_motorbike():
    assert ("motorcycle", "go_straight", "ego") in agents("I was on my scooter at the lights when a van cut in front "
                                                          "of me.")


def test_right_at_me_is_straight_at_me_and_right_at_the_lights_a_turn():
    assert agents("A car came right at me.") == [("car", "go_straight", "ego"), ("car", "go_straight", "front")]
    assert agents("I turned right at the lights.") == [("car", "turn_right", "ego")]


@pytest.mark.parametrize("prompt", [
    "Put this one in the simulator. 2am, M6 northbound, me in the 40-tonner at 56 in the centre lane of three.",
    "Running empty over the Pennines in thick fog about 5 this morning. Road to myself.",
    "Swinging left out of the distribution park, fully loaded wagon, and a cyclist nips up my inside.",
])
def test_a_truckers_own_words_put_the_ego_in_a_truck(prompt):
    assert [kind for kind, _, where in agents(prompt) if where == "ego"] == ["truck"]


@pytest.mark.parametrize("prompt, expected", [
    ("Unit 7 on scene. V1 blue Ford Focus held at red light, stopped on the stop line. V2 grey Sprinter van behind "
     "failed to stop and shunted into back of V1.", [("car", "go_straight", "back"), ("car", "stop", "ego")]),
    ("Unit 9 (marked) responding to Grade 1, lights and sirens. Blue Golf slightly in front of unit in the n/s lane "
     "moved across into our lane, no indication.",
     [("car", "change_lane_to_right", "front_left"), ("police", "go_straight", "ego")]),
])
def test_a_patrols_unit_by_its_call_sign_is_no_crash_reports_vehicle(prompt, expected):
    assert agents(prompt) == expected


def test_a_riders_own_e_scooter_makes_a_motorbike_ego_and_anothers_a_cyclist():
    assert agents("So I'm waiting at the stop sign at the end of Park Ave on the e-scooter and this lycra guy on a "
                  "racing bike comes flying out of the road to my left and straight over.") == [
        ("cyclist", "go_straight", "road_of_left_turn"), ("motorcycle", "stop", "ego")]
    assert ("cyclist", "go_straight", "road_of_left_turn") in agents("A guy on an e-scooter came out of the road on "
                                                                     "my left.")


def test_glued_to_my_rear_wheel_is_behind():
    assert ("car", "go_straight", "back") in agents("On the voi scooter heading home along Mill Road last night, and "
                                                    "this cab was glued to my rear wheel the entire way.")



def test_what_an_instructor_says_of_the_throttle_puts_the_learner_on_a_motorbike():
    assert ("motorcycle", "go_straight", "ego") in agents(
        "Evening, fog coming down, town road and a zebra ahead. There's a mum with a buggy waiting on the pavement "
        "next to it. You back off the throttle and take it slow on the approach.")
    assert ("car", "go_straight", "ego") in agents("You are driving a car. A bike rider is in front of you. You stay "
                                                   "behind the bike rider.")


def test_passengers_on_the_top_deck_ride_in_the_bus_the_scene_is_told_from():
    assert agents("I want to report something that happened on the 62 yesterday. I was on the top deck right at the "
                  "front. We were in the inside lane of the dual carriageway and a white Golf in the lane next to us "
                  "on the right just cut across in front of the bus without signalling.") == [
        ("bus", "go_straight", "ego"), ("car", "change_lane_to_left", "right")]


def test_what_the_teller_could_not_tell_had_happened_is_not_done():
    assert agents("Car 31 stopped on a narrow street when a patrol car came up right behind it; it couldn't tell if it "
                  "was being pulled over. The patrol car just passed it and kept going.") == [
        ("car", "stop", "ego"), ("police", "go_straight", "back")]
    assert agents("A patrol car came up right behind me; I wasn't sure if I was being pulled over. It passed me and "
                  "kept going.") == [("car", "go_straight", "ego"), ("police", "go_straight", "back")]
    assert ("car", "stop", "ego") in agents("A patrol car came up right behind me and I was sure it would pass. I "
                                            "pulled over and stopped.")


def test_passengers_of_a_driver_on_a_numbered_service_or_in_the_bus_lane_ride_a_bus():
    said = ("At noon the 14 stopped at the zebra for an old man to cross, and the car behind us sat on its horn. Our "
            "driver stayed calm and waited until he was over.")
    assert ("bus", "stop", "ego") in agents(said)
    assert ("bus", "change_lane_to_right", "ego") in agents(
        "A van was parked in the bus lane again. Our driver had to pull out into the lane on the right.")
    assert ("car", "change_lane_to_right", "ego") in agents(  # a ride with no service or bus lane: a car
        "A van was parked on the shoulder again. Our driver had to pull out into the lane on the right.")
    assert all(a[0] != "bus" for a in agents("Our driver took us along Route 9 and stopped at the red light."))


@pytest.mark.parametrize("prompt, expected", [
    ("A two-axle truck stopped ahead.", [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
    ("An 8-wheel tipper came the opposite way.",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "front_left")]),
])
def test_what_a_vehicle_is_built_with_counts_no_vehicles(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("A van veered left into Mill Road.", [("car", "turn_left", "ego")]),
    ("A van cut left into the petrol station.", [("car", "turn_left", "ego")]),
    ("A van moved left into the left lane.", [("car", "change_lane_to_left", "left"), ("car", "go_straight", "ego")]),
    ("Highway, 3 lanes.\nHero in the middle lane, going straight.\nNPC in the right lane, level with the hero, does a "
     "lane change left into the hero lane.\nSecond NPC right behind the hero, same lane.",
     [("car", "change_lane_to_left", "right"), ("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
])
def test_a_move_to_a_side_that_ends_in_a_road_is_a_turn_and_one_into_a_lane_a_lane_change(prompt, expected):
    assert agents(prompt) == expected


def test_a_person_opening_a_sentence_with_its_article_left_out_drives_the_vehicle_named_before():
    assert agents("A box truck just ahead of me in the right lane cut across into my lane. Guy kept right on "
                  "going.") == [("car", "go_straight", "ego"), ("truck", "change_lane_to_left", "front_right")]


@pytest.mark.parametrize("prompt, expected", [
    ("Site 4. A motorcyclist, as the subject vehicle, rides along Park Road and comes up behind a van stopped in its "
     "lane. Afterwards the motorcyclist waits behind the van.",
     [("car", "stop", "front"), ("motorcycle", "go_straight", "ego"), ("motorcycle", "stop", "ego")]),
    ("Cam 3, T-junction, give-way. Subject motorbike waiting at the give-way line. Car approaching from subject's "
     "right carries straight on. After the car passes, subject turns left.",
     [("car", "go_straight", "road_of_right_turn"), ("motorcycle", "stop", "ego"), ("motorcycle", "turn_left", "ego")]),
    ("Subject vehicle: turns right at the lights.", [("car", "turn_right", "ego")]),
])
def test_the_subject_said_in_passing_or_before_its_noun_is_the_ego(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Motorcyclist, 41M. Riding at about 30 when a van pulled out of a side road on his left and stopped in front "
     "of him. GCS 15.", [("car", "block_the_ego", "front"), ("motorcycle", "go_straight", "ego")]),
    ("Pt 27M moped rider, approx 20mph, moved into the left lane so an ambulance could pass from behind. Helmeted, "
     "no LOC.", [("ambulance", "go_straight", "back"), ("motorcycle", "change_lane_to_left", "ego")]),
])
def test_a_handover_that_opens_on_a_rider_is_told_from_the_patients_motorbike(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("I'm going straight on at the lights on a Lime scooter and a car turns left across me.",
     [("car", "turn_left", "road_of_straight"), ("motorcycle", "go_straight", "ego")]),
    ("Scooting down Park Lane after work when a minicab pulled out of a side road on my left.",
     [("car", "go_straight", "road_of_left_turn"), ("motorcycle", "go_straight", "ego")]),
    ("Stopped in traffic, a car next to me on my right and a man on a bike on my left.",
     [("car", "go_straight", "right"), ("car", "stop", "ego"), ("cyclist", "go_straight", "left")]),
])
def test_the_speaker_on_a_scooter_rides_a_motorbike(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, ego", [
    ("Had the truck in the left lane of the interstate when a sedan alongside me in the right lane swerved in ahead "
     "of the blade.", "truck"),
    ("Had the plow sitting on a green at 3rd and Oak waiting to turn left while a pickup came through from the other "
     "direction. After it had cleared I made my left.", "truck"),
    ("A truck pulled out. I had the truck in front of me for miles.", "car"),
])
def test_a_vehicle_the_speaker_had_somewhere_or_doing_something_is_the_speakers(prompt, ego):
    assert {a[0] for a in agents(prompt) if a[2] == "ego"} == {ego}


def test_a_bus_named_bare_by_its_driver_at_the_stop_is_the_ego():
    assert agents("Market Square stop. Bus was standing at the stop with the doors open. I pulled out into the right "
                  "lane and a car came up behind me.") == [("bus", "change_lane_to_right", "ego"),
                                                           ("car", "go_straight", "back")]


@pytest.mark.parametrize("prompt, expected", [
    ("Cam 4, 08:10: Route 12 bus NB on the high street, left lane. Taxi in the right lane alongside the bus cuts "
     "sharply left across its front. Bus brakes hard, no contact.",
     [("bus", "go_straight", "ego"), ("car", "change_lane_to_left", "right")]),
    ("A taxi cuts in ahead of me. I brake hard.", [("car", "change_lane_to_right", "front_left"),
                                                    ("car", "go_straight", "ego")]),
    ("The car ahead of me brakes hard and stops.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
])
def test_braking_is_no_stop_of_the_ego_even_when_it_is_found_to_be_the_ego_later(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("I was doing 30 and a black Astra sat right up my backside flashing at me.",
     [("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
    ("A cyclist was heading my way.", [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front_left")]),
])
def test_up_my_backside_is_behind_and_heading_my_way_is_oncoming(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("The car stops at the stop line. A cane user is crossing ahead of it on the crossing.",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("As a cyclist myself, I care about this one. An automated car is driving down a street.",
     [("car", "go_straight", "ego")]),
    ("A fire engine came up behind us. Then an ambulance did the same.",
     [("ambulance", "go_straight", "back"), ("car", "go_straight", "ego"), ("firetruck", "go_straight", "back")]),
])
def test_a_cane_user_walks_the_writer_as_one_is_no_one_and_the_same_is_done_from_the_same_place(prompt, expected):
    assert agents(prompt) == expected


def test_the_one_let_do_something_is_not_the_one_who_lets_it():
    assert agents("Eastbound on High St, a bus pulled out ahead of us on the right. Shuttle eased off and let it "
                  "merge.") == [("bus", "change_lane_to_left", "front_right"), ("bus", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("I hung a right at the lights.", [("car", "turn_right", "ego")]),
    ("I was pulling left out of the trading estate at the lights and a cyclist came down my nearside.",
     [("car", "turn_left", "ego"), ("cyclist", "go_straight", "left")]),
    ("A van pulled right out of a side road on my left.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]),
])
def test_hung_a_right_and_pulling_left_out_of_a_place_are_turns(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("V1 stopped at the zebra crossing. V2 (Suzuki m/cycle) following V1, rider unable to stop, struck rear of V1.",
     [("car", "stop", "ego"), ("motorcycle", "go_straight", "back")]),
    ("The ego stops at the crossing. A truck, a white Scania, behind the ego.",
     [("car", "stop", "ego"), ("truck", "go_straight", "back")]),
    ("We stopped at the lights. A van, a white Transit, behind us, failed to stop.",
     [("car", "go_straight", "back"), ("car", "stop", "ego")]),
    ("A car, a bus, and a van.", [("bus", "go_straight", "front"), ("car", "go_straight", "ego"),
                                  ("car", "go_straight", "front"), ("car", "go_straight", "front")]),
])
def test_a_noun_set_off_after_another_of_its_kind_then_placed_by_the_ego_is_that_one(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Client stopped for pedestrian at a crosswalk. Client stopped to let an elderly gentleman cross; following "
     "vehicle did not stop and hit her from behind.",
     [("car", "go_straight", "back"), ("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("There was a pedestrian in the crosswalk. I failed to yield to a pedestrian in the crosswalk.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("A pedestrian crosses from the left. A pedestrian crosses from the right.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left"),
      ("pedestrian", "cross_the_road", "front_right")]),
    ("A man crosses in front of the ego. A woman crosses in front of the ego.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front"),
      ("pedestrian", "cross_the_road", "front")]),
    ("A car stops in front of the ego. Then another car stops in front of the ego.",
     [("car", "go_straight", "ego"), ("car", "stop", "front"), ("car", "stop", "front")]),
])
def test_one_named_again_with_a_and_nothing_new_said_of_it_is_the_one_named_before(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Stopped at red signal. Rear-ended by Dodge Ram pickup. 10-y-o son in back seat, no injuries.",
     [("car", "go_straight", "back"), ("car", "stop", "ego")]),
    ("The driver had to brake hard and the people standing on the lower deck were thrown about.",
     [("car", "go_straight", "ego")]),
])
def test_people_in_the_back_seat_or_on_a_deck_ride_on_board(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Parked cars down your right. A kid chases a ball out between them right in front of you. Ride so you can "
     "stop.", [("motorcycle", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right")]),
    ("A kid runs out in front of you. Keep your speed low so you are able to stop.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("A kid ran out in front of me. I was able to stop.", [("car", "stop", "ego"), ("pedestrian", "cross_the_road",
                                                                                  "front")]),
    ("A kid ran out. The car behind also can stop.",
     [("car", "go_straight", "ego"), ("car", "stop", "back"), ("pedestrian", "cross_the_road", "front")]),
    ("Minibus travelling 30mph ran into the back of a queue, 2 cars stopped in it. Pt is the minibus driver, 63M.",
     [("bus", "go_straight", "ego"), ("car", "stop", "front"), ("car", "stop", "front")]),
])
def test_a_stop_one_could_make_and_a_queue_run_into_are_no_stop_of_its_own(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Portable lights showing red, Honda Jazz waiting at the stop line. After that a cyclist squeezed past her from "
     "the back and rode through on red.", [("car", "stop", "ego"), ("cyclist", "go_straight", "back")]),
    ("Temporary signals at red, and a little Fiesta pulled up right on the white stop line. Then a bloke on a bike "
     "came up behind her and through the red.", [("car", "stop", "ego"), ("cyclist", "go_straight", "back")]),
    ("Police are appealing for witnesses after a woman driving home was boxed in by two cars. She says one of them "
     "stopped dead in front of her.", [("car", "block_the_ego", "front"), ("car", "go_straight", "ego"),
                                       ("car", "stop", "front"), ("car", "stop", "front")]),
])
def test_a_vehicle_the_others_are_placed_by_as_her_or_him_is_the_one_told_from(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("I honked at a cyclist. There was a cyclist riding on the shoulder on my right, a bit ahead of me, and I gave "
     "him room.", [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front_right")]),
    ("I saw a van. A van pulled out of the side road on my left.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]),
])
def test_one_first_named_with_nothing_said_of_it_is_the_one_named_again_where_it_is_told_of(prompt, expected):
    assert agents(prompt) == expected



@pytest.mark.parametrize("prompt, expected", [
    ("The VUT approaches a stationary target vehicle in its own lane. Single target, nothing else in the scene.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("Restrained driver of car travelling approx 30mph, struck on passenger side by a van pulling out of a side road "
     "on his left, van going straight across.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]),
    ("MOI: pt front seat passenger in car that pulled out of a give way junction, turning right, and was T-boned "
     "by a car coming along the main road from the left. Speed of other vehicle est 40mph.",
     [("car", "turn_right", "ego"), ("car", "go_straight", "road_of_left_turn")]),
    ("Pt rider of motorcycle on main road. Car coming the other way turned right across his path into a side road. "
     "Car driver walking wounded, seen by 2nd crew.",
     [("motorcycle", "go_straight", "ego"), ("car", "turn_right", "road_of_straight")]),
])
def test_one_named_again_bare_or_by_a_shorter_name_is_the_one_told_of(prompt, expected):
    assert sorted(agents(prompt)) == sorted(expected)


@pytest.mark.parametrize("prompt, expected", [
    ("Vehicle B (insured) was traveling in the left lane. Vehicle A, a bus, was stopped in the right lane ahead of "
     "Vehicle B.", [("car", "go_straight", "ego"), ("bus", "stop", "front_right")]),
    ("V1 (our insured, a 2019 Camry) turned left at the lights. V2 came the other way. Driver of the Camry states "
     "the sun was in her eyes.", [("car", "turn_left", "ego"), ("car", "go_straight", "road_of_straight")]),
    ("See sketch. V1, the insured's Honda, turned left at the lights. V2 came the other way.",
     [("car", "turn_left", "ego"), ("car", "go_straight", "road_of_straight")]),
])
def test_the_insured_vehicle_of_a_claim_is_the_ego(prompt, expected):
    assert sorted(agents(prompt)) == sorted(expected)


@pytest.mark.parametrize("prompt, expected", [
    ("Missing: bus pulling out from a stop into ego lane, front right of SV.",
     [("bus", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]),
    ("LVB: the SV ahead in the ego lane decelerates to a standstill.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
])
def test_the_subject_vehicle_beside_an_ego_lane_is_the_ego_unless_it_is_placed(prompt, expected):
    assert sorted(agents(prompt)) == sorted(expected)


def test_pulling_off_the_shoulder_into_the_lane_cuts_in():
    assert sorted(agents("V1 was traveling in the right lane of a two-lane highway. V2, a pickup that had been "
                         "disabled on the right shoulder ahead of V1, pulled suddenly off the shoulder into V1's "
                         "lane.")) == [("car", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]


def test_the_reporting_person_driving_a_car_named_bare_drives_it():
    assert sorted(agents("RP driving grey Qashqai in middle lane, ambulance on blues came up behind her.")) == [
        ("ambulance", "go_straight", "back"), ("car", "go_straight", "ego")]


def test_the_turning_vehicle_is_the_one_told_to_turn():
    assert sorted(agents("The vehicle under test shall be a goods vehicle. It shall make a right turn at the "
                         "junction. A bicycle shall travel straight ahead alongside it on its right-hand side, so "
                         "that it would be struck by the turning vehicle.")) == [
        ("cyclist", "go_straight", "right"), ("truck", "turn_right", "ego")]


def test_there_is_after_a_comma_opens_a_clause_of_its_own():
    assert sorted(agents("I'm on I-75 southbound, there's a semi stopped on the right shoulder. I'm just driving, "
                         "going past it in the right lane.")) == [("car", "go_straight", "ego"),
                                                                  ("truck", "stop", "front_right")]


def test_holding_ones_ground_is_going_on():
    assert sorted(agents("You were in the middle lane, and that lorry just ahead of you in the left lane started "
                         "coming over into your lane, and you hooted and held your ground.")) == [
        ("car", "go_straight", "ego"), ("truck", "change_lane_to_right", "front_left")]


def test_a_stop_anyone_could_make_in_time_is_none():
    assert sorted(agents("Suppose you're driving down a street at 25 mph and a child suddenly dashes out from the "
                         "right. At 25 you can stop in time.")) == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right")]


def test_a_scene_key_told_with_its_verbs_is_the_scene_not_a_title():
    assert sorted(agents("Triggering condition TC-07: low sun at dusk. Scene: the subject vehicle travels straight "
                         "on a rural road, and a pedestrian crosses in front of it from the right. Hazardous "
                         "behaviour: no braking is triggered.")) == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right")]


@pytest.mark.parametrize("prompt", [
    "The ego drives on. A young man walks across the pedestrian crossing just in front of us.",
    "The ego drives on. Two kids wait on the sidewalk ahead to the right, next to a zebra crossing. One of them "
    "darts onto the crossing.",
])
def test_one_crossing_on_the_crossing_said_of_it_is_at_the_crosswalk(prompt):
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("Carter drove his Audi straight across the crossroads against a red signal. A Corsa coming from his right had "
     "a green light and was struck. Its driver, a 61-year-old grandmother, suffered a broken wrist.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_right_turn")]),
    ("Last week dad drove us to the cinema. At the crossroads we went straight on. A fire engine came from the road "
     "on the left and turned left.",
     [("car", "go_straight", "ego"), ("firetruck", "turn_left", "road_of_left_turn")]),
])
def test_a_person_who_says_who_someone_is_or_drives_the_teller_is_no_one_on_foot(prompt, expected):
    assert sorted(agents(prompt)) == sorted(expected)


def test_a_person_set_off_who_does_something_stays():
    said = agents("The ego stops at the zebra. A woman, a mother of two, crosses in front of it.")
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in said


def test_a_pedestrian_crossing_after_the_sentence_before_ends_is_a_person_crossing():
    said = agents("Ego turns left at a 4-way intersection. One NPC car from the opposite lane going straight "
                  "through; pedestrian crossing ahead on the crosswalk.")
    assert ("pedestrian", "cross_the_road", "near_the_crosswalk") in said


def test_i_and_you_said_only_inside_quotes_are_no_teller():
    said = agents('The classic "sorry mate, I didn\'t see you". A driver is waiting to turn right at a crossroads '
                  'with no lights. Once the oncoming car has gone by he turns.')
    assert ("car", "turn_right", "ego") in said and ("car", "go_straight", "road_of_straight") in said
    assert len(said) == 2


def test_the_vehicle_an_account_opens_with_someone_riding_is_the_ego():
    assert sorted(agents("Client was on his motorcycle heading west on Grand Ave. A white SUV in the adjacent left "
                         "lane merged into his lane.")) == [("car", "change_lane_to_right", "left"),
                                                             ("motorcycle", "go_straight", "ego")]


def test_a_crews_log_names_its_own_vehicle_as_known():
    assert sorted(agents("22:50, final loop. A runner darted out from between parked cars on our left and crossed "
                         "directly in front of the shuttle. Hard stop.")) == [
        ("bus", "stop", "ego"), ("pedestrian", "cross_the_road", "front_left")]


def test_someone_on_board_is_no_one_on_the_road():
    assert sorted(agents("We're in the left lane. An ambulance came up behind us with its sirens going. We moved "
                         "over to the right lane. Someone on board filmed it.")) == [
        ("ambulance", "go_straight", "back"), ("car", "change_lane_to_right", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("I'm creeping down the road, and the guy in front of me in a Subaru just stops dead.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("The guy just behind us in a pickup honked.", [("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
])
def test_a_driver_placed_then_in_his_vehicle_is_that_vehicle(prompt, expected):
    assert sorted(agents(prompt)) == sorted(expected)


@pytest.mark.parametrize("prompt", [
    "A silver SUV waiting across the intersection is waving somebody through, nobody knows who.",
    "A motorcycle sped past me. Half the claims started with someone misjudging the motorcycle's speed.",
])
def test_someone_nowhere_who_does_nothing_is_no_one_in_the_scene(prompt):
    assert not [a for a in agents(prompt) if a[0] == "pedestrian"]


def test_someone_placed_or_acting_stays():
    assert ("pedestrian", "cross_the_road", "front") in agents("Someone is crossing in front of me.")


@pytest.mark.parametrize("prompt, ego", [
    ("I'd had the semi eleven years. That morning a minivan was puttering along ahead of me, so I moved over to "
     "the left lane to get round it.", ("truck", "change_lane_to_left", "ego")),
    ("I've driven the bus for a good few years. A car pulled out in front of me.", ("bus", "go_straight", "ego")),
])
def test_the_vehicle_the_teller_has_had_for_years_is_the_ego(prompt, ego):
    said = agents(prompt)
    assert ego in said and len([a for a in said if a[2] == "ego"]) == 1


def test_a_vehicle_had_in_front_for_years_is_not_the_tellers():
    assert ("bus", "go_straight", "front") in agents("I had the bus in front of me for years.")


@pytest.mark.parametrize("prompt, turn", [
    ("Got to the big roundabout wanting to take the first exit, left. Cyclist already coming round from my right "
     "so I waited for her. Then I went.", "turn_left"),
    ("At the roundabout I took the third exit, right.", "turn_right"),
])
def test_a_roundabout_exit_said_by_side_turns_to_that_side(prompt, turn):
    assert ("car", turn, "ego") in agents(prompt)


def test_tucked_in_behind_is_following_not_cutting_in():
    said = agents("A pickup leads through the closure slowly, ego tucked in right behind it.")
    assert ("car", "go_straight", "ego") in said and ("car", "go_straight", "front") in said


@pytest.mark.parametrize("prompt, expected", [
    ("A pickup following us also braked, no contact.", ("car", "go_straight", "back")),
    ("At the crossroads a sedan coming from the left braked, TA 1.4 s.", ("car", "go_straight", "road_of_left_turn")),
    ("The car in front braked hard.", ("car", "stop", "front")),
    ("The car in front braked hard and stopped.", ("car", "stop", "front")),
    ("The front car brake suddenly until stop.", ("car", "stop", "front")),
    ("The car in front slammed on its brakes.", ("car", "stop", "front")),
    ("The lead car brakes hard, down to a standstill.", ("car", "stop", "front")),
])
def test_braking_behind_or_across_slows_and_ahead_or_to_a_halt_stops(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("A pickup was coming from the road on our right. The pickup had to stop for us.",
     ("car", "stop", "road_of_right_turn")),
    ("A van came up behind me and had to stop.", ("car", "stop", "back")),
    ("A van came up behind me and had to brake.", ("car", "go_straight", "back")),
])
def test_one_made_to_stop_stops_and_one_made_to_brake_drives_on(prompt, expected):
    assert expected in agents(prompt)


def test_a_bare_verb_after_until_is_the_main_subjects():
    said = lower("The ego follows the front car. The front car brakes suddenly until stop. Then the ego stops "
                 "behind it.").scenario
    assert [(a.name, a.action) for a in said.stages[0].agents] == [("ego", "go_straight"), ("c1", "stop")]
    assert [(a.name, a.action) for a in said.stages[1].agents] == [("ego", "stop")]


@pytest.mark.parametrize("prompt, expected", [
    ("A postman stands on the footway to my right.", ("pedestrian", "on_the_sidewalk", "right")),
    ("A postman pulled out in front of me.", ("car", "change_lane_to_right", "front_left")),
])
def test_people_named_by_their_round_are_on_foot_unless_at_a_wheel(prompt, expected):
    assert expected in agents(prompt)


def test_the_system_is_the_egos_own_driving():
    said = agents("A pickup in the center lane made a sudden cut-in directly in front of us. The system braked "
                  "firmly and held its lane.")
    assert ("car", "go_straight", "ego") in said and [a[1] for a in said if a[2] != "ego"] == ["change_lane_to_right"]


def test_mines_before_a_street_suffix_is_a_street_not_the_teller():
    said = agents("At the signalized intersection of the frontage road and Mines Rd the truck had a green light to "
                  "turn right, but two pedestrians were walking across the crosswalk on Mines Rd, the street we were "
                  "turning onto. The truck stopped at the corner, then made its right turn.")
    assert [a for a in said if a[2] == "ego"] == [("truck", "stop", "ego"), ("truck", "turn_right", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Ambulance on blues came up behind me in my lane, moved over to the right lane to let them by.",
     [("ambulance", "go_straight", "back"), ("car", "change_lane_to_right", "ego")]),
    ("A van came up behind me in my lane, cut me up and braked.", [("car", "block_the_ego", "front"),
                                                                    ("car", "go_straight", "ego")]),
])
def test_a_move_after_a_comma_to_let_them_by_is_the_egos(prompt, expected):
    assert sorted(agents(prompt)) == sorted(expected)


@pytest.mark.parametrize("prompt, kept", [
    ("An ambulance comes up fast behind the ego, and the ego changes to the right lane. Maybe add a police car later "
     "but not for v1.", False),
    ("We could add a cyclist in a follow-up. The ego turns left.", False),
    ("An ambulance comes up fast behind the ego. Add a police car behind the ambulance.", True),
])
def test_one_added_in_a_later_version_is_not_in_this_scene(prompt, kept):
    said = agents(prompt)
    assert any(a[0] in ("police", "cyclist") for a in said) == kept


def test_police_closing_a_street_before_a_side_is_said_are_no_car():
    said = agents("Police have closed Bank Street, and drivers are being sent left onto Mill Road instead. A reader "
                  "says she turned left into Mill Road and then had to stop at the zebra crossing.")
    assert not [a for a in said if a[0] == "police"]


@pytest.mark.parametrize("prompt, counts", [
    ("Five vehicles including a truck come towards the ego.", {"car": 5, "truck": 1}),
    ("Five cars including a taxi come towards the ego.", {"car": 6}),
    ("Three vehicles including the ego wait at the light.", {"car": 3}),
])
def test_a_member_named_in_a_counted_group_is_taken_from_it_once(prompt, counts):
    said = agents(prompt)
    assert {t: sum(a[0] == t for a in said) for t in counts} == counts


def test_a_member_at_the_back_of_its_group_is_among_them_not_behind_the_ego():
    said = agents("A convoy of five vehicles including a concrete mixer at the back comes towards the ego.")
    assert sum(a[0] == "car" for a in said) == 5 and ("truck", "go_straight", "back") not in said


@pytest.mark.parametrize("noun", ["cattle hauler", "concrete mixer", "horsebox"])
def test_heavy_vehicles_named_by_their_load_are_trucks(noun):
    assert ("truck", "go_straight", "road_of_right_turn") in agents(
        f"At the crossroads a {noun} was coming from the road on my right.")


@pytest.mark.parametrize("prompt, expected", [
    ("I'm driving past this guy in a three-piece suit standing on the sidewalk on my right.",
     ("pedestrian", "on_the_sidewalk", "right")),
    ("I drive past a man in a red coat standing on the sidewalk.", ("pedestrian", "on_the_sidewalk", "right")),
    ("A car was driving along when this chap in a hoodie suddenly darted out in front of it.",
     ("pedestrian", "cross_the_road", "front")),
])
def test_what_a_person_wears_stands_between_them_and_their_participle(prompt, expected):
    assert expected in agents(prompt)


def test_a_teacher_is_on_foot_and_one_only_named_is_no_one_in_the_scene():
    assert ("pedestrian", "on_the_sidewalk", "left") in agents("A teacher is standing on the pavement to my left.")
    assert not [a for a in agents("A cyclist was pedalling along in front of me. I hung back behind him, no way am I "
                                  "honking at Freddie's teacher!") if a[0] == "pedestrian"]


def test_one_of_them_after_a_verbless_group_opens_a_clause_of_its_own():
    said = agents("Two little kids on the footpath by the zebra crossing and one of them suddenly darts out across it.")
    assert ("pedestrian", "on_the_sidewalk", "near_the_crosswalk") in said
    assert [a[1] for a in said if a[0] == "pedestrian"].count("cross_the_road") == 1
    assert ("bus", "stop", "front") in agents("A bus and one of the cars stop.")


@pytest.mark.parametrize("prompt, expected", [
    ("The ego moves from the left lane into the right lane.", ("car", "change_lane_to_right", "ego")),
    ("The ego truck pulls from the right lane into the left lane to get round a stopped car.",
     ("truck", "change_lane_to_left", "ego")),
    ("The subject car moves from the right lane into the middle lane.", ("car", "change_lane_to_left", "ego")),
])
def test_a_move_from_one_lane_into_another_changes_lane_towards_the_second(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("The ego turns right into the main road. On the main road (the ego's destination road) a car drives through.",
     ("car", "go_straight", "at_the_destination")),
    ("I stop first, then I turn right. As I dey turn, one keke park for the road wey I dey enter.",
     ("motorcycle", "stop", "at_the_destination")),
])
def test_the_destination_road_named_as_such_is_where_the_ego_heads(prompt, expected):
    assert expected in agents(prompt)


def test_a_threads_post_numbers_count_no_one():
    said = agents("1/ Ego follows a bus on an urban road, two lanes in our direction. 2/ The bus halts at a bus stop. "
                  "3/ The ego changes to the left lane to get around the bus.")
    assert sorted(said) == [("bus", "stop", "front"), ("car", "change_lane_to_left", "ego")]


def test_the_ego_wanted_to_be_a_bus_is_a_bus_not_a_second_one():
    said = agents("We want the ego to be a bus for this batch: the ego bus turns right at a signalised junction.")
    assert said == [("bus", "turn_right", "ego")]


@pytest.mark.parametrize("prompt", [
    "So I'm sitting at a four-way stop, it's a hostage negotiation with turn signals, and then I turn right.",
    "A van cut in front of me and didn't use his signal.",
    "A van pulled out with its right signal on.",
])
def test_a_turn_signal_is_an_indicator_no_turn_and_no_traffic_light(prompt):
    scene = lower(prompt).scenario
    assert "traffic_light" not in scene.road.required_signals
    assert scene.ego.action != "turn_left"


def test_our_signal_turning_green_is_the_light_facing_us():
    road = lower("Our signal was green, so we turned right at the junction.").scenario.road
    assert "traffic_light" in road.required_signals


@pytest.mark.parametrize("prompt, expected", [
    ("Please add a sedan behind the ego that brakes hard; the ego should drive straight.", ("car", "stop", "back")),
    ("My van slows down, with a taxi behind that brakes hard.", ("car", "stop", "back")),
])
def test_braking_asked_for_is_played_as_a_stop(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt", [
    "A cyclist rides in the right lane slightly ahead of the ego. FAIL: lateral clearance to cyclist 0.6 m < 1.5 m.",
    "A car drives ahead of the ego. Gap to car 2.5 m at the end.",
])
def test_a_decimal_after_a_noun_is_a_measure_not_a_name(prompt):
    assert len(agents(prompt)) == 2


def test_a_name_said_before_a_road_users_noun_names_it():
    said = agents("At the roundabout, npc1 car from left; npc2 bus directly behind npc1.")
    assert sorted(said) == [("bus", "go_straight", "road_of_left_turn"), ("car", "go_straight", "ego"),
                            ("car", "go_straight", "road_of_left_turn")]


def test_a_partys_role_names_the_ego_in_any_case():
    said = agents("Client was stopped behind a school bus on a county road. A pickup following client failed to stop "
                  "and shoved client's car into the back of the bus.")
    assert sorted(said) == [("bus", "stop", "front"), ("car", "go_straight", "back"), ("car", "stop", "ego")]


@pytest.mark.parametrize("prompt", [
    "I was doing 30, a van came out of a side road on my left across the junction and hit my nearside.",
    "I was going along the main road. A van shot straight across from a side road on my left.",
])
def test_across_after_a_side_road_is_the_way_it_goes_not_where_it_comes_from(prompt):
    assert ("car", "go_straight", "road_of_left_turn") in agents(prompt)


@pytest.mark.parametrize("ending", ["Out of car unaided before we arrived.", "Walked from vehicle."])
def test_a_handovers_bare_vehicle_left_is_the_patients_own(ending):
    said = agents(f"Driver going along the main road at 30. A van shot out from a side road on his left. {ending}")
    assert sorted(said) == [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]


def test_someone_climbing_out_of_a_car_leaves_another_car():
    assert ("car", "go_straight", "front") in agents("I stopped. A woman climbed out of car and ran.")


def test_you_could_hardly_see_is_anyone_not_the_ego():
    said = agents("Foggy, you could hardly see across the road. I was sat on the bench outside the butcher's and saw a "
                  "small blue car pull out of Mill Lane, turning left onto the high road.")
    assert ("car", "turn_left", "ego") in said


def test_the_bus_a_passenger_never_got_is_not_the_egos():
    said = agents("I was at the junction. A silver Micra came up to it and turned left. Never did get my bus, ended "
                  "up walking home.")
    assert all(kind != "bus" for kind, _, _ in said)


def test_a_witness_waiting_in_the_shelter_is_on_foot_and_not_at_a_crossing():
    prompt = ("I was waiting in the shelter on Kings Road. White Toyota coming along and a fella in a black jacket "
              "suddenly walks out between the parked cars right in front of it, not at a crossing or anything.")
    assert agents(prompt) == [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]
    assert "crosswalk" not in road(prompt).required_objects + road(prompt).required_signals


def test_a_vehicle_held_at_a_junction_that_then_turns_is_the_one_told_from():
    said = agents("At a T-junction controlled by a stop sign, a car is initially stationary. Its driver then pulls "
                  "away, turning right. In the road the car is joining, a pedestrian is walking across.")
    assert ("car", "turn_right", "ego") in said and not any(pos == "front" and kind == "car" for kind, _, pos in said)


def test_other_bikes_riding_with_a_motorcycle_ego_are_motorbikes():
    said = agents("You're leading a group ride on your motorbike with three other bikes following you in a line.")
    assert said.count(("motorcycle", "go_straight", "back")) == 3


def test_a_callers_vehicle_is_the_ego_when_the_caller_drives():
    said = agents("Caller (F, driver) reports she is stopped at the red light. States a pickup came up in the lane "
                  "next to her on the left and ran the red. Caller's veh not involved.")
    assert sorted(said) == [("car", "go_straight", "left"), ("car", "stop", "ego")]


@pytest.mark.parametrize("then, expected", [("A pickup in the lane to my left ran the red.",
                                              [("car", "go_straight", "left"), ("car", "stop", "ego")]),
                                             ("EMS + PD dispatched 14:03.", [("car", "stop", "ego")])])
def test_first_in_line_puts_no_one_ahead(then, expected):
    assert sorted(agents(f"I am stopped at the red light, first in line. {then}")) == expected


def test_coach_before_a_name_is_a_title_not_a_bus():
    said = agents("Hey Ethan, it's Coach Dana. When you did the right on red tonight, you came to a full stop first, "
                  "and there was a motorcycle coming from your left.")
    assert all(kind != "bus" for kind, _, _ in said)


@pytest.mark.parametrize("prompt, expected", [
    ("I'm trying to get over into the left lane and the car beside me lets me in.", "change_lane_to_left"),
    ("We got across into the right lane behind a lorry.", "change_lane_to_right"),
])
def test_getting_over_into_a_lane_changes_lane(prompt, expected):
    assert ("car", expected, "ego") in agents(prompt)


def test_hoping_for_a_scene_asks_for_it_and_hoping_for_others_is_no_ones_act():
    said = agents("Hi! I hope you can make a scene where the ego turns left at a junction and a cyclist crosses.")
    assert sorted(said) == [("car", "turn_left", "ego"), ("cyclist", "cross_the_road", "front")]
    said = agents("We were on the dual carriageway when an ambulance came up behind us. We moved across into the "
                  "left-hand lane to let it by. I do hope whoever was waiting for it came to no harm.")
    assert ("car", "change_lane_to_left", "ego") in said


def test_the_tellers_family_at_the_wheel_is_the_ego():
    said = agents("My husband and I were returning along the A38 dual carriageway when an ambulance came up behind "
                  "us. My husband moved across into the left-hand lane to let it by.")
    assert sorted(said) == [("ambulance", "go_straight", "back"), ("car", "change_lane_to_left", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("I go round a left bend and a car comes the other way.", [("car", "go_straight", "ego"),
                                                              ("car", "go_straight", "front_left")]),
    ("A cyclist goes round a left-hand bend ahead of me.", [("car", "go_straight", "ego"),
                                                            ("cyclist", "go_straight", "front")]),
])
def test_a_bend_named_by_its_side_is_the_roads_shape(prompt, expected):
    assert agents(prompt) == expected


def test_a_moped_guy_rides_a_moped():
    assert ("motorcycle", "stop", "back") in agents("Stopped at the zebra for a woman going across. Moped guy behind "
                                                    "me also had to stop and leaned on his horn.")


@pytest.mark.parametrize("prompt", [
    "Reporting a dark grey Range Rover. I was riding straight across at the crossroads when the driver, heading "
    "towards me from the far side, swung left directly in front of my bike. His wing mirror came within about 30 cm "
    "of my bars.",
    "Bike commuter here. Reporting a white Transit. I was cycling in the right-hand lane, the Transit was in the "
    "left-hand lane slightly behind me, and a refuse truck had stopped in front of it. The driver pulled sharply "
    "across into my lane.",
])
def test_a_cyclists_report_is_told_from_the_vehicle_reported(prompt):
    said = agents(prompt)
    assert any(kind == "car" and pos == "ego" for kind, _, pos in said)
    assert any(kind == "cyclist" for kind, _, _ in said)


@pytest.mark.parametrize("prompt", [
    "Zebra in the 20 limit: our lot, four riders, all stopped while a grandma and a toddler cross, and the test car "
    "arrives behind and stops with us.",
    "Dusk. Test car approaching the signals at a toucan and two of our youth riders are pedalling across it, so it "
    "has to stop.",
])
def test_a_clubs_riders_beside_the_test_car_are_cyclists(prompt):
    said = agents(prompt)
    assert ("car", "stop", "ego") in said and any(kind == "cyclist" for kind, _, _ in said)


@pytest.mark.parametrize("prompt, expected", [
    ("Shuttle lights on the A61 today. Grey Mercedes came up to my red and just kept on going, straight into the "
     "coned-off single lane while our tipper lorry was heading towards him from the other end. Lorry had to pull "
     "up sharp and stop.", [("car", "go_straight", "ego"), ("truck", "stop", "front_left")]),
    ("Temp lights on red my side, traffic backing up. Some lad on a motorbike came up the outside of the line and "
     "carried on through the red into the works section.", [("motorcycle", "go_straight", "ego")]),
])
def test_works_staff_tell_of_the_driver_at_their_signals(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt, ego, speed", [
    ("A lorry moving at 15 m/s catches up with a cyclist travelling at 6 m/s. The lorry overtakes without leaving "
     "its lane.", "truck", 54),
    ("Car A travels at 28 m/s in the left-hand lane of a two-lane motorway and is gaining on a lorry ahead of it in "
     "that lane. The driver of car A moves out into the right-hand lane to overtake.", "car", 101),
])
def test_a_word_problems_overtaker_is_the_one_told_from_at_its_own_speed(prompt, ego, speed):
    scene = lower(prompt).scenario
    assert scene.ego.type == ego and round(scene.ego.speed.value) == speed


@pytest.mark.parametrize("prompt, ego", [
    ("Green man at the pedestrian lights by the bank. I'm going over and a car turns right out of Station Road, "
     "across right in front of me. The bus coming the other way stopped, good lad, but she didn't even look.",
     ("car", "turn_right", "ego")),
    ("Zebra crossing on the front, I'm more than halfway over, and a little silver Toyota drives straight through, "
     "with a taxi right on its tail doing the same. Our Sandra says I shouldn't be out on the scooter.",
     ("car", "go_straight", "ego")),
])
def test_a_teller_going_over_a_crossing_is_on_foot_and_the_vehicle_met_is_the_ego(prompt, ego):
    said = agents(prompt)
    assert ("pedestrian", "cross_the_road", "front") in said or \
        ("pedestrian", "cross_the_road", "near_the_crosswalk") in said
    assert [a for a in said if a[2] == "ego"] == [ego]
    assert [kind for kind, _, _ in said].count("pedestrian") == 1


@pytest.mark.parametrize("prompt, expected", [
    ("Running empty over the Pennines in thick fog. Road to myself. Held 40 all the way over.",
     [("truck", "go_straight", "ego")]),
    ("In the artic pulling left out of the trading estate at the traffic lights, and a bloke on a pushbike shoots "
     "down my nearside.", [("cyclist", "go_straight", "left"), ("truck", "turn_left", "ego")]),
    ("This is why you keep your following distance, folks. I'm in the right lane at 65, and a four-wheeler in the "
     "left lane guns it and cuts in right in front of my bumper.",
     [("car", "change_lane_to_right", "left"), ("truck", "go_straight", "ego")]),
])
def test_a_truckers_own_words_put_the_speaker_in_the_truck(prompt, expected):
    assert agents(prompt) == expected


def test_a_proposals_we_are_its_authors_not_a_vehicle():
    said = agents("At the May consultation event residents said they feel unsafe turning right out of Ferry Lane. We "
                  "propose to simulate a car in Ferry Lane making a right turn onto Harbour Road at the Give Way "
                  "sign, with a bus approaching along Harbour Road from the left.")
    assert sorted(said) == [("bus", "go_straight", "road_of_left_turn"), ("car", "turn_right", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("Road three lanes is, ego car middle lane in going. Behind of ego car, one truck also coming.",
     ("truck", "go_straight", "back")),
    ("I in middle lane driving. My behind a big truck is coming.", ("truck", "go_straight", "back")),
    ("I at four-way stop stopped. Left side road from one pickup came, straight went. It passed, then I to right "
     "turned.", ("car", "turn_right", "ego")),
    ("Intersection at, I left turn want. Opposite side from two cars coming.", ("car", "go_straight",
                                                                                 "road_of_straight")),
])
def test_places_said_after_their_noun_as_turkish_says_them(prompt, expected):
    assert expected in agents(prompt)


def test_that_before_a_noun_after_a_place_names_the_one_said_before():
    said = agents("The ego passes a car that is stopped on the right shoulder. A police car is stopped behind that "
                  "car, on the shoulder too.")
    assert ("police", "stop", "front_right") in said


@pytest.mark.parametrize("prompt, expected", [
    ("RP driving black Focus in the middle lane, ambulance on blues approached from behind.",
     [("ambulance", "go_straight", "back"), ("car", "go_straight", "ego")]),
    ("V1 advises he stopped at the stop sign, then continued straight through. V2, approaching from V1's right, "
     "blew its stop.", [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_right_turn"),
                        ("car", "stop", "ego")]),
])
def test_a_logs_note_style_names_the_reporting_car_and_a_stop_blown(prompt, expected):
    assert sorted(agents(prompt)) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("See me, ah'm headin intae the roondaboot at the Kingsway an this huge lorry comes tearin oot fae the road on "
     "ma right, nae lookin at aw.", [("car", "go_straight", "ego"), ("truck", "go_straight", "road_of_right_turn")]),
    ("Middle o' the night an a guy in a black hoodie steps oot in front o' me fae between parked motors.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("Ah'm at the give way sign, indicatin left, an a wifie pushin a pram's crossin ower the road ah'm goin intae. "
     "Ah waited, then ah turned left.", [("car", "stop", "ego"), ("car", "turn_left", "ego"),
                                        ("pedestrian", "cross_the_road", "front")]),
])
def test_scots_an_ah_and_dropped_gs_read_as_meant(prompt, expected):
    assert sorted(agents(prompt)) == expected


def test_family_said_to_be_driving_in_a_relative_clause_is_the_ego():
    said = agents("An ambulance came up behind us with blue lights on and my son, who was driving, moved over into the "
                  "left lane to let it through.")
    assert ("car", "change_lane_to_left", "ego") in said and ("ambulance", "go_straight", "back") in said


def test_a_dustcart_is_a_truck():
    assert ("truck", "stop", "front") in agents("I was stationary behind the dustcart while the binmen did their round.")


def test_the_bus_one_waits_for_at_a_stop_is_not_the_egos():
    said = agents("I was stood at the bus stop on Mill Lane. A blue Fiesta came along to the crossroads and went left "
                  "down Chapel Road. Still no sign of my bus, of course.")
    assert said == [("car", "turn_left", "ego")]



@pytest.mark.parametrize("prompt, expected", [
    ("The test car follows the van through the works, and a cyclist is riding towards them.",
     ("cyclist", "go_straight", "front_left")),
    ("Three of us strung out single file, test car behind the back rider. A tanker is climbing towards us.",
     ("truck", "go_straight", "front_left")),
])
def test_one_coming_towards_those_ahead_of_the_ego_is_oncoming(prompt, expected):
    assert expected in agents(prompt)


def test_a_riders_line_strung_out_ahead_of_the_test_car_stays_in_the_scene():
    said = agents("Three of us strung out single file, test car behind the back rider. A van comes up the hill.")
    assert said.count(("cyclist", "go_straight", "front")) == 3


@pytest.mark.parametrize("prompt", [
    "You're filtering up the outside of a long queue. An oncoming car turns right through a gap, across you.",
    "I was filtering up the outside of a long queue when a pedestrian stepped out between the cars.",
])
def test_a_queue_filtered_past_is_no_stop(prompt):
    said = agents(prompt)
    assert ("motorcycle", "go_straight", "ego") in said and ("motorcycle", "stop", "ego") not in said


def test_a_make_after_off_names_a_street():
    said = agents("I was halfway across the zebra when a pickup swung left off Lincoln towards me.")
    assert [a for a in said if a[2] != "ego" and a[0] == "car"] == []


@pytest.mark.parametrize("prompt, expected", [
    ("Route 5 inbound: a van parked in our lane, hazards on. Shuttle halted behind it, then moved over left and went "
     "round.", [("bus", "change_lane_to_left", "ego"), ("bus", "stop", "ego"), ("car", "stop", "front")]),
    ("Three lanes our way, shuttle in the middle lane. A fire engine came up behind us. Shuttle indicated and moved "
     "over into the left lane.", [("bus", "change_lane_to_left", "ego"), ("firetruck", "go_straight", "back")]),
])
def test_a_crews_log_names_its_shuttle_halting_behind_or_moving_to_a_lane(prompt, expected):
    assert sorted(agents(prompt)) == expected


def test_a_vehicle_left_in_the_lane_stands_there():
    assert ("truck", "stop", "front") in agents("A delivery lorry left in our lane with nobody in it, so we stopped "
                                                "behind it.")


@pytest.mark.parametrize("prompt", [
    "Pulled up at the Market Street stop loading passengers. A cyclist came past on the right.",
    "Came to a full stop at the four-way stop. As I moved off to go straight through, a van from my left ran its stop "
    "sign. Missed the back of the bus by about 3 feet.",
    "Number 9, dual carriageway, bus in the right lane. A van alongside us on the left drifted into our lane and "
    "standing passengers fell over.",
])
def test_a_bus_driver_or_its_passengers_speak_from_the_bus(prompt):
    assert [a[0] for a in agents(prompt) if a[2] == "ego"][:1] == ["bus"]


@pytest.mark.parametrize("prompt, ego", [
    ("Four-way stop outside Tulsa on a rented Harley. A pickup on my left went first, then I turned right.",
     "motorcycle"),
    ("Stuck at the lights on red, scooter, a little Toyota waiting next to me on my right.", "motorcycle"),
    ("I was stopped at the lights when a guy on a moped pulled up beside me.", "car"),
])
def test_the_motorbike_a_teller_is_on_is_the_egos(prompt, ego):
    assert {a[0] for a in agents(prompt) if a[2] == "ego"} == {ego}


def test_someone_coming_the_other_way_who_floors_it_drives():
    said = agents("Green arrow for me, I'm halfway into my left, and this guy coming the other way just floors it "
                  "straight through his red light.")
    assert ("car", "go_straight", "road_of_straight") in said and not any(a[0] == "pedestrian" for a in said)


def test_family_said_to_sit_in_the_rear_are_passengers():
    said = agents("Owner says he was going straight over a crossroads and a pickup from the left hit him on the "
                  "driver's side. Daughter in rear, fine.")
    assert not any(a[0] == "pedestrian" for a in said)


def test_a_job_cards_customer_car_said_bare_is_the_ego():
    said = agents("JOB CARD 4410 - 2015 Vauxhall Corsa, reg AB15 XYZ.\nCust. reports car was stopped at red traffic "
                  "lights and a lorry ran into the back of it.\nDamage: rear bumper, tailgate.")
    assert sorted(said) == [("car", "stop", "ego"), ("truck", "go_straight", "back")]


@pytest.mark.parametrize("prompt, expected", [
    ("Q is driving west on Elm at 45 in a 30 zone. R, on foot, steps off the curb into the crosswalk ahead of Q. Q "
     "does not brake.", [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("M waits at a red light on Oak, planning to turn right onto Main. N is walking on the sidewalk to M's right. M "
     "then turns right on red.", [("car", "stop", "ego"), ("car", "turn_right", "ego"),
                                  ("pedestrian", "on_the_sidewalk", "right")]),
    ("J drives her pickup along a rural road. Ahead on the right a school bus is stopped on the shoulder. K, age six, "
     "darts out from in front of the bus into J's path.", [("bus", "stop", "front_right"), ("car", "go_straight", "ego"),
                                                           ("pedestrian", "cross_the_road", "front_right")]),
])
def test_a_cases_lettered_parties_are_read_by_what_is_said_of_them(prompt, expected):
    assert sorted(agents(prompt)) == expected


def test_lettered_parties_named_together_or_off_the_road_add_no_one():
    said = agents("D is stopped at the stop line as B and C, two friends, walk across the crosswalk in front of her. "
                  "D then goes straight ahead. R, the van's owner, had left the keys in it.")
    assert sorted(said) == [("car", "go_straight", "ego"), ("car", "stop", "ego"),
                            ("pedestrian", "cross_the_road", "near_the_crosswalk"),
                            ("pedestrian", "cross_the_road", "near_the_crosswalk")]


@pytest.mark.parametrize("prompt, expected", [
    ("Highway pe teen lane hai, main beech wali lane mein tha. Aage right lane mein ek truck tha, usne achanak meri "
     "lane mein cut maara.", [("car", "go_straight", "ego"), ("truck", "change_lane_to_left", "front_right")]),
    ("Expressway pe baarish ho rahi thi. Right lane wala ek Creta bina signal ke meri lane mein aa ghusa. Maine "
     "turant left lane le li.", [("car", "change_lane_to_left", "ego"), ("car", "change_lane_to_left", "right")]),
    ("Market ki gali mein left turn liya, corner ke turant baad ek chhota truck khada tha, maal utar raha tha.",
     [("car", "turn_left", "ego"), ("truck", "stop", "at_the_destination")]),
    ("Signal pe ruka tha. Peeche ek bus bhi ruki thi aur lagaatar horn maar rahi thi.",
     [("bus", "stop", "back"), ("car", "stop", "ego")]),
])
def test_hinglish_places_said_alone_and_lanes_taken(prompt, expected):
    assert sorted(agents(prompt)) == expected


@pytest.mark.parametrize("prompt, expected", [
    ("Wet today, so it was walk, don't run, on the crossing for all of them. The number 9 bus turned right out of "
     "Station Road and then stopped for us well back.", [("bus", "stop", "ego"), ("bus", "turn_right", "ego"),
                                                        ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
    ("Quiet morning. Only one van came by and it pulled up for me and the Patel twins on the crossing.",
     [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
])
def test_a_patrol_that_walks_its_crossing_tells_of_the_vehicle_that_stops_for_it(prompt, expected):
    assert sorted(agents(prompt)) == expected


def test_a_route_number_that_drives_is_a_bus():
    assert {a[0] for a in agents("The 47 sailed through the red while the kids were still on the zebra.")
            if a[2] == "ego"} == {"bus"}


@pytest.mark.parametrize("prompt", [
    "I'm in the left lane. A van level with me in the right lane cuts sharply left across my front.",
    "Two lanes. A grey Astra in the right-hand lane alongside me swerved suddenly into my lane in front of me.",
])
def test_one_level_with_the_ego_that_cuts_across_its_front_starts_beside_it(prompt):
    assert ("car", "change_lane_to_left", "right") in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("We all turn left at the crossroads. Just round the corner in the road you're going into there's a parked van.",
     ("car", "stop", "at_the_destination")),
    ("The car pulls away from the stop sign, turning right. In the road the car is joining, a woman is walking "
     "across.", ("pedestrian", "cross_the_road", "at_the_destination")),
])
def test_the_road_the_ego_goes_into_said_by_a_relative_clause(prompt, expected):
    assert expected in agents(prompt)


def test_not_once_is_never_and_no_link_of_stages():
    assert agents("A woman walked onto a zebra crossing, not once looking our way. The robotaxi stopped.") == [
        ("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_a_polis_motor_is_a_police_car():
    assert ("police", "go_straight", "back") in agents("At the lights, an a polis motor comes up ahint me.")


def test_what_one_wears_names_no_vehicle():
    assert agents("Then this guy in a Leafs jersey comes running across.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]


def test_a_tellers_this_brings_in_one_not_named_before():
    assert [a for a in agents("A pair of kids head across, so I stop. Then this guy comes running across.")
            if a[0] == "pedestrian"] == [("pedestrian", "cross_the_road", "front")] * 3


def test_a_logs_time_stamp_counts_no_one():
    assert agents("t=0 ego stopped at the line. t=3 car from the left turns right.") == [
        ("car", "stop", "ego"), ("car", "turn_right", "road_of_left_turn")]


def test_a_logs_bound_is_a_heading_and_its_subject_after_another_key_is_the_ego():
    assert agents("Ego: box truck, WB, full stop at stop line.") == [("truck", "stop", "ego")]
    assert {a for a in agents("Event 1123: subject = delivery box truck, full stop at stop line (t=0).")
            if a[2] == "ego"} == {("truck", "stop", "ego")}


def test_the_one_of_its_kind_named_again_by_its_kind_in_note_style():
    assert agents("A motorcyclist cut in ahead of me. M/C continued northbound at high speed, footage held on "
                  "dashcam.") == [("car", "go_straight", "ego"), ("motorcycle", "change_lane_to_right", "front_left")]


def test_the_cab_of_a_lorry_driver_is_his_lorry_no_taxi():
    assert agents("HGV driver on phone, driving lane 2. Reports motorcyclist level with his n/s in lane 1 darted "
                  "into lane 2 directly ahead of his cab.") == [("motorcycle", "change_lane_to_right", "left"),
                                                                ("truck", "go_straight", "ego")]


@pytest.mark.parametrize("prompt", ["A woman was riding towards us on a bicycle.", "A man came towards me on a bike."])
def test_one_who_rides_towards_the_ego_on_a_bicycle_is_a_cyclist(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front_left")]


def test_a_sentence_opened_by_opposite_direction_from_tells_an_oncoming_one():
    assert agents("Road narrow. In front right shoulder on one bicycle man slowly going. Opposite direction from one "
                  "lorry coming.") == [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front_right"),
                                       ("truck", "go_straight", "front_left")]


@pytest.mark.parametrize("prompt", [
    "A cyclist rode through on red. Got a few shouts from the lads.",
    "A cyclist rode through on red. Please fix this before a child gets hurt.",
])
def test_ones_feared_or_only_heard_are_no_agents(prompt):
    assert agents(prompt) == [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]


def test_the_siren_after_the_ego_named_again_is_the_emergency_vehicles():
    assert agents("The automated car is waiting while a man crosses. An ambulance comes up behind the car with its "
                  "siren blaring.") == [("ambulance", "go_straight", "back"), ("car", "stop", "ego"),
                                        ("pedestrian", "cross_the_road", "front")]


def test_one_named_in_the_egos_own_named_lane_with_nothing_more_is_ahead():
    assert agents("Three cars stopped in the left lane. The ego is in the left lane.") == [
        ("car", "go_straight", "ego")] + [("car", "stop", "front")] * 3


def test_passengers_who_leg_it_across_the_road_cross_it():
    assert agents("Three passengers hopped off and legged it across the road.") == [
        ("car", "go_straight", "ego")] + [("pedestrian", "cross_the_road", "front")] * 3


def test_a_hired_scooter_by_its_operators_name_and_one_waiting_on_the_other_side_of_a_junction():
    assert agents("4 way stop, me on a Bird turning left. A patrol car sitting at the stop sign on the other side "
                  "waved me through.") == [("motorcycle", "turn_left", "ego"), ("police", "stop", "road_of_straight")]


def test_a_units_own_line_after_the_time_and_the_light_is_the_patrol():
    assert agents("0040 hrs, dark, very heavy rain. Unit 6 (marked) NB Station Rd. Ped came out between parked "
                  "vehicles and walked across in front of unit. Unit then stopped.") == [
        ("pedestrian", "cross_the_road", "front"), ("police", "go_straight", "ego"), ("police", "stop", "ego")]


def test_a_log_of_offsets_with_a_route_bus_as_its_subject_named_bare_again():
    assert agents("+0.0 subject = route 7 bus, waiting at the stop line on red (SB)\n+2.1 car stationary behind "
                  "subject, queued\n+8.7 SB still red, bus still held") == [("bus", "stop", "ego"),
                                                                             ("car", "stop", "back")]


@pytest.mark.parametrize("prompt", ["A delivery van was double parked so I went around it into the oncoming lane.",
                                    "A van was stopped so I went into the oncoming lane to get round it."])
def test_going_round_one_stopped_by_the_oncoming_lane_is_a_move_left(prompt):
    assert agents(prompt) == [("car", "change_lane_to_left", "ego"), ("car", "stop", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("The car ahead indicated right then suddenly turned left without warning.",
     [("car", "go_straight", "ego"), ("car", "turn_left", "front")]),
    ("TOV then moved left into lane 1.", [("car", "change_lane_to_left", "ego")]),
])
def test_a_past_verb_after_then_goes_on_telling_of_the_one_before_it(prompt, expected):
    assert agents(prompt) == expected


@pytest.mark.parametrize("prompt", ["A pedestrian crossing against the lights was hit by a van.",
                                    "A pedestrian crossing on red was hit by a van."])
def test_a_pedestrian_crossing_against_the_light_is_a_person(prompt):
    assert ("pedestrian", "cross_the_road", "front") in agents(prompt)


def test_the_crosswalk_named_pedestrian_crossing_stays_a_place():
    assert agents("I stopped at the pedestrian crossing on red.") == [("car", "stop", "ego")]


def test_one_reversing_towards_the_ego_stays_where_it_is():
    assert agents("The lorry in front of me was reversing towards me so I beeped.") == [
        ("car", "go_straight", "ego"), ("truck", "go_straight", "front")]


@pytest.mark.parametrize("prompt, expected", [
    ("A pedestrian steps out; the ego brakes and stops; the pedestrian finishes crossing; the ego drives on.",
     [("car", "go_straight", "ego"), ("car", "stop", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("Event 1123: subject = delivery box truck, WB, full stop at stop line (t=0). t=3.5 car from subject's right "
     "turns right onto Lake. t=8.4 subject proceeds straight.",
     [("car", "turn_right", "road_of_right_turn"), ("truck", "go_straight", "ego"), ("truck", "stop", "ego")]),
])
def test_the_ego_going_on_after_a_halt_in_a_sentence_of_its_own_is_the_next_stage(prompt, expected):
    assert agents(prompt) == expected


def test_the_ego_going_on_with_no_halt_before_is_one_stage():
    assert agents("The ego drives along a street. A cyclist rides ahead. The ego continues.") == [
        ("car", "go_straight", "ego"), ("cyclist", "go_straight", "front")]


def test_a_key_of_where_they_come_from_said_with_its_participle_and_a_lists_after_them():
    assert agents("Ego turns left. Coming from opposite: two car, after them one motorcycle also.") == [
        ("car", "go_straight", "road_of_straight"), ("car", "go_straight", "road_of_straight"),
        ("car", "turn_left", "ego"), ("motorcycle", "go_straight", "road_of_straight")]


@pytest.mark.parametrize("prompt, junction, without", [
    ("I on straight road slow going, junction not have.", False, ()),
    ("Ego is at a junction. Traffic light there is not.", True, ("traffic_light",)),
])
def test_an_absence_said_in_another_languages_order(prompt, junction, without):
    road = lower(prompt).scenario.road
    assert (road.junction, road.without_signals) == (junction, without)


def test_a_vehicles_signal_none_is_no_absence_of_a_road_signal():
    assert agents("Three lanes, I was in the centre one; a sedan on my left, its signal none, swerved right in front "
                  "of me.") == [("car", "change_lane_to_right", "left"), ("car", "go_straight", "ego")]


@pytest.mark.parametrize("prompt, expected", [
    ("I let the car merge in front of me.", [("car", "change_lane_to_right", "front_left"),
                                              ("car", "go_straight", "ego")]),
    ("I let the car on my right merge in front of me.", [("car", "change_lane_to_left", "right"),
                                                          ("car", "go_straight", "ego")]),
])
def test_the_one_the_speaker_lets_merge_is_another_placed_before_its_verb(prompt, expected):
    assert agents(prompt) == expected


def test_the_next_right_taken_is_a_turn():
    assert ("car", "turn_right", "ego") in agents("Take the next right at the crossroads.")


def test_an_officer_who_reports_what_was_seen_is_no_one_on_the_road():
    assert agents("Officer observed a motorcycle in the right lane, slightly behind the ego vehicle, overtaking it at "
                  "high speed.") == [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "back_right")]


def test_the_ego_named_last_in_brackets_with_its_description():
    assert agents("Vehicle 1 (silver hatchback, ego) was travelling northbound when Vehicle 2, a black pickup "
                  "approaching from the opposite direction, turned left across its path at the intersection.") == [
        ("car", "go_straight", "ego"), ("car", "turn_left", "road_of_straight")]


def test_a_motorist_a_report_opens_on_is_the_one_it_is_told_from():
    assert agents("A motorist had a lucky escape when an articulated lorry, just ahead of her in the right-hand "
                  "lane, drifted into her lane.") == [("car", "go_straight", "ego"),
                                                      ("truck", "change_lane_to_left", "front_right")]


def test_a_progressive_goes_on_after_and_in_a_reason_and_passengers_of_a_service_by_its_number():
    assert agents("Sat at the front of the 47 and our driver had to stop because a fire engine was coming out of "
                  "the road on the right and turning left in front of us.") == [
        ("bus", "stop", "ego"), ("firetruck", "turn_left", "road_of_right_turn")]


def test_an_onlookers_account_of_the_one_that_stops_to_let_someone_cross():
    assert agents("From the pavement I saw a silver car stop to let a jogger cross in front of it.") == [
        ("car", "stop", "ego"), ("pedestrian", "cross_the_road", "front")]


def test_kin_who_had_to_go_round_one_drives_the_teller():
    assert agents("the scooter in front of us just stopped randomly n my mum had to go round it into the left "
                  "lane") == [("car", "change_lane_to_left", "ego"), ("motorcycle", "stop", "front")]


def test_the_one_who_waited_while_others_went_then_acts():
    assert ("car", "turn_left", "ego") in agents("Today she waited patiently while two elderly ladies crossed at the "
                                                 "zebra, then turned left.")


def test_a_weight_in_tonnes_after_a_space_counts_no_trucks():
    assert agents("Ego truck (40 t HGV), right lane of a three-lane motorway. A car in the middle lane, just ahead "
                  "of the truck, cuts in to the right in front of it.") == [
        ("car", "change_lane_to_right", "front_left"), ("truck", "go_straight", "ego")]


def test_those_waiting_in_the_queue_behind_the_ego_are_behind_it():
    assert agents("Ego stopped at a red light with two cars waiting in the queue behind it.") == [
        ("car", "stop", "back"), ("car", "stop", "back"), ("car", "stop", "ego")]


def test_both_after_two_placed_names_them_not_a_place_ahead_of_one():
    assert agents("Double cut-in at 90 km/h: POV1 from the left lane ahead and POV2 from the right lane ahead both "
                  "merge into the ego lane in front of the ego.") == [
        ("car", "change_lane_to_left", "front_right"), ("car", "change_lane_to_right", "front_left"),
        ("car", "go_straight", "ego")]


def test_the_lane_the_test_vehicle_turns_into_is_its_destination():
    assert ("car", "stop", "at_the_destination") in agents(
        "T-junction: VUT turns right into the main road. A van is stopped on the main road just past the junction, "
        "in the lane the VUT turns into, and a car on the main road coming from the left drives straight on.")


def test_a_bracketed_make_after_with_keeps_the_state_its_own():
    assert agents("V1 (Toyota Prius, private hire) was stationary in a queue at the traffic lights, with V2 "
                  "(Vauxhall Astra) stationary directly in front of it.") == [
        ("car", "stop", "ego"), ("car", "stop", "front")]


def test_a_side_of_another_after_a_participle_places_the_participles_subject():
    assert agents("The appellant's taxi was stopped at the give-way line of a T-junction when a scooter, travelling "
                  "along the main road from the taxi's right, collided with a lorry coming from the taxi's "
                  "left.") == [("car", "stop", "ego"), ("motorcycle", "go_straight", "road_of_right_turn"),
                               ("truck", "go_straight", "road_of_left_turn")]


def test_an_adjacent_lane_keyed_on_a_line_is_no_lane_of_the_ego():
    assert agents("SV: 100 km/h\nAdjacent left lane: empty\nAdjacent right lane: car 20 m behind the SV, "
                  "100 km/h") == [("car", "go_straight", "back_right"), ("car", "go_straight", "ego")]


def test_a_driver_standing_at_a_stop_sign_is_held_there_not_on_foot():
    assert agents("Today I am standing at a stop sign and from the left street comes a car and turns right directly "
                  "in front of my nose, without looking.") == [("car", "stop", "ego"),
                                                               ("car", "turn_right", "road_of_left_turn")]


def test_a_simile_of_standing_still_is_no_halt_and_a_learners_status_no_car():
    assert agents("My son (learner) was driving us home and we were doing about 40 in the left lane of the dual "
                  "carriageway when a Porsche came flying up the right lane from behind and went past like we "
                  "were standing still.") == [("car", "go_straight", "back_right"), ("car", "go_straight", "ego")]


def test_whose_turn_it_was_is_no_manoeuvre():
    assert agents("At the 4-way stop by my house I was stopped and it was clearly my turn, then the guy across "
                  "from me just went straight through anyway.") == [("car", "go_straight", "road_of_straight"),
                                                                     ("car", "stop", "ego")]


def test_the_route_a_teller_drives_is_a_bus_where_a_bus_is_spoken_of():
    assert agents("Driving the 42 down Queen St this morning and a moped in front of me suddenly braked to a halt "
                  "in the middle of the road. Nearly had him under the bus.") == [
        ("bus", "go_straight", "ego"), ("motorcycle", "stop", "front")]
    assert ("car", "go_straight", "ego") in agents("Driving the 405 south this morning and a moped in front of me "
                                                   "braked to a halt.")


def test_a_box_truck_the_teller_works_in_is_the_ego():
    assert ("truck", "turn_right", "ego") in agents("Doing my last drop in the box truck, turning right onto Oak, "
                                                    "and there's two guys crossing Oak in the crosswalk.")


def test_one_named_by_the_vehicle_they_ride_is_that_vehicle():
    assert agents("On the flyover one motorbike fellow came from the lane on my left side and suddenly cut in "
                  "front of my cab.") == [("car", "go_straight", "ego"), ("motorcycle", "change_lane_to_right", "left")]


def test_a_bus_stop_of_the_bus_waited_behind_puts_no_teller_on_foot():
    assert agents("I was waiting behind a bus which was stopped at the bus stop, and I could not pass it because "
                  "a truck was coming in the other sense.") == [("bus", "stop", "front"), ("car", "stop", "ego"),
                                                                ("truck", "go_straight", "front_left")]


def test_right_across_the_road_is_how_far_not_a_side():
    assert agents("Came round the bend and there was a fire engine right across the road in front of me, blocking "
                  "my way completely.") == [("car", "go_straight", "ego"), ("firetruck", "block_the_ego", "front")]


def test_an_apposition_with_who_drove_it_and_a_kind_of_place_named_by_a_plural():
    assert agents("The subject vehicle, an HGV driven by the defendant, turned left into the entrance of a "
                  "builders' merchant on Station Road. The deceased was cycling alongside the HGV on its left at the "
                  "time.") == [("cyclist", "go_straight", "left"), ("truck", "turn_left", "ego")]


def test_a_fleet_logs_one_numbered_unit_is_the_ego():
    assert agents("LDW + FCW event. Vehicle 22 (HGV) drifted out of its lane into the left-hand lane at 88 km/h "
                  "without indicating. A broken-down car was stopped in the left-hand lane 40 m ahead of the HGV at "
                  "the time.") == [("car", "stop", "front_left"), ("truck", "change_lane_to_left", "ego")]
    assert ("bus", "go_straight", "ego") in agents("Near-miss logged - Bus 88, Route 12. A pedestrian stepped off "
                                                   "the kerb from the left into the path of the bus mid-block.")


def test_the_vehicle_is_the_only_one_there_whatever_its_kind():
    assert agents("The ego bus drives on. A pedestrian walks across 4 m in front of the vehicle.") == [
        ("bus", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]


def test_a_lane_keyed_bullet_list_places_each_by_the_egos_numbered_lane():
    assert agents("Dense highway, 4 lanes numbered from the left; ego in lane 2.\n"
                  "- Lane 1: car cruising level with the ego\n- Lane 2: truck cruising ahead of the ego\n"
                  "- Lane 3: bus cruising behind the ego\n- Lane 3: car ahead of the ego, changes into lane 2") == [
        ("bus", "go_straight", "back_right"), ("car", "change_lane_to_left", "front_right"),
        ("car", "go_straight", "ego"), ("car", "go_straight", "left"), ("truck", "go_straight", "front")]


def test_a_road_feature_said_only_in_a_title_gives_way_to_the_body():
    r = road("scenario: ped_crossing_night\nego: VUT, 30 km/h, straight\nvru: 1x child pedestrian, crossing from "
             "the left between parked cars\nroad: 1 lane, no crosswalk\nweather: clear, night")
    assert "crosswalk" in r.without_objects and "crosswalk" not in r.required_objects


def test_the_two_vehicles_are_those_told_of_when_just_two_are():
    assert agents("Our policyholder was moving into the right-hand lane when the other party's pickup, travelling "
                  "level with her in that lane, accelerated instead of letting her in, and the two vehicles "
                  "touched.") == [("car", "change_lane_to_right", "ego"), ("car", "go_straight", "right")]
    assert len(agents("A bus pulls out of the stop ahead of me. The two cars behind me stop.")) == 4


def test_a_test_code_with_vru_in_it_names_no_road_user_and_an_age_then_is_no_stage():
    assert agents("RT-VRU: SV turns right at a signalised intersection; an adult pedestrian crosses, on the "
                  "crosswalk, the road the SV turns into.") == [("car", "turn_right", "ego"),
                                                                ("pedestrian", "cross_the_road", "near_the_crosswalk")]
    assert sum(a[0] == "pedestrian" for a in agents("RT-VRU: SV turns right at a signalised intersection; an adult "
                                                    "pedestrian crosses the road the SV turns into.")) == 1
    assert ("pedestrian", "cross_the_road", "front_left") in agents(
        "The appellant was driving his Range Rover along Church Lane when the respondent, then aged 12, stepped off "
        "the pavement on the appellant's left and into his path.")


def test_how_many_crew_a_vehicle_is_no_word_between_the_teller_and_it():
    assert ("police", "go_straight", "ego") in agents(
        "I was single-crewed in a marked police vehicle in the middle lane when a man on foot crossed the "
        "carriageway ahead of me.")


def test_a_logs_subject_named_by_its_body_after_a_time_stamp_is_the_ego():
    assert agents("Evt 9042 | cam 6 | Birch Ave x Pine St, 4-way stop | overcast\n+0.0s subject box truck NB, halts "
                  "at stop line\n+3.8s sedan on east approach (subject's right) makes right turn onto Pine St\n"
                  "+7.1s subject then continues straight through") == [
        ("car", "turn_right", "road_of_right_turn"), ("truck", "go_straight", "ego"), ("truck", "stop", "ego")]


def test_far_from_a_crossing_in_any_words_is_no_crossing():
    prompt = "Three girls walk straight out across the road in front of me, miles from the crossing."
    assert "crosswalk" in road(prompt).without_objects
    assert ("pedestrian", "cross_the_road", "front") in agents(prompt)


def test_a_drivers_standing_passengers_make_the_ego_a_bus_not_the_teller_one_on_foot():
    assert agents("Doing approx 25 mph along Kings Road when a marked police car, lights and sirens, came out of "
                  "Oak Avenue to my right and turned right in front of me. I then pulled up and let it go. It did "
                  "not stop. I had 2 passengers standing, both holding on, no injuries.") == [
        ("bus", "go_straight", "ego"), ("bus", "stop", "ego"), ("police", "turn_right", "road_of_right_turn")]



def test_a_first_impression_of_what_someone_was_is_no_denial_of_them():
    assert ("pedestrian", "cross_the_road", "front") in agents(
        "Middle o' the night, dark as a coal hole, an a guy in a black hoodie — thought it wis a deer at first — "
        "steps oot in front o' me fae between parked motors.")


def test_riders_named_bare_by_what_they_ride_are_a_vague_group():
    assert agents("I stop for the stop line because traffic light don red. Small time, ambulance wey dey blow siren "
                  "comot from the left road, turn right cross for front of my car. Nobody move, even okada men "
                  "respect am that day.") == [("ambulance", "turn_right", "road_of_left_turn"), ("car", "stop", "ego")]


def test_an_adult_male_riding_a_bike_is_its_rider():
    assert agents("An adult male riding a mountain bike on the hard shoulder a short way ahead.") == [
        ("car", "go_straight", "ego"), ("cyclist", "go_straight", "front_right")]


def test_a_street_named_by_a_colour_is_no_signal_and_a_left_hander_no_turn():
    assert road("The ego drives on Green Lane.").required_signals == ()
    assert "traffic_light" in road("The ego goes straight on green.").required_signals
    assert ("car", "turn_left", "ego") not in agents(
        "Round a left-hander you come up on two cyclists riding ahead of you, and there's a car coming towards you.")


def test_a_drivers_comment_key_keeps_the_first_person_and_the_side_before_through():
    assert agents("Event: Harsh Braking | 10:22:36 | Veh: Unit 40 | Signal: green | Spd 50 -> 0 km/h. Driver comment: "
                  "I had a green, two fire engines on blue lights came out of the road on my right through their "
                  "red. Braked hard and waited stopped till both were past.") == [
        ("car", "stop", "ego"), ("firetruck", "go_straight", "road_of_right_turn"),
        ("firetruck", "go_straight", "road_of_right_turn")]


def test_a_vehicle_only_towed_after_the_collision_is_no_one_new():
    assert not any(a[1:] == ("go_straight", "front") for a in agents(
        "Client was waiting at a red light behind a city bus. A patrol car entered the intersection from client's "
        "left on a red and hit the front of client's car. Vehicle was towed from the scene. We have requested the "
        "police report."))


def test_the_driver_of_a_route_number_drives_the_bus_its_passengers_ride():
    assert ("bus", "stop", "ego") in agents(
        "driver of the 9 came into the stop far too fast today, the front went up over the kerb on the right where a "
        "guy was standing just in front of us. i was in the front seat and i actually screamed out loud")


def test_a_clause_opening_on_up_ahead_then_names_its_subject():
    assert agents("I'm cruising in the middle lane, and up ahead a FedEx semi is stopped dead in my lane with its "
                  "hazards on.") == [("car", "go_straight", "ego"), ("truck", "stop", "front")]


def test_a_vehicle_kept_in_a_yard_or_a_shop_is_no_part_of_the_scene():
    assert agents("Rain hammered the windscreen as Mara eased the old Volvo towards the crossroads and let it roll "
                  "to a stop at the line. A dark hatchback slid through from the road on her right, its wipers "
                  "flailing, and was gone. Somewhere behind the houses a dog howled, and she thought of the two cars "
                  "rusting in her father's yard. Then, with the road finally clear, she turned left.") == [
        ("car", "go_straight", "road_of_right_turn"), ("car", "stop", "ego"), ("car", "turn_left", "ego")]
    assert ("car", "stop", "front_left") in agents("A van was parked at the shop on my left.")


def test_she_who_placed_another_in_the_sentence_before_is_named_again():
    assert agents("Clip review #14 for the driving school channel. Our learner is in a red Corsa, approaching a "
                  "signalised crossroads in the right-hand lane of two. A cyclist is riding straight on in the lane "
                  "to her left, level with her. Watch - she turns right on the green arrow, perfectly.") == [
        ("car", "turn_right", "ego"), ("cyclist", "go_straight", "left")]


def test_who_a_vehicle_was_driven_by_is_no_one_on_the_road():
    assert not any(a[0] == "pedestrian" for a in agents(
        "The ego vehicle was changing from the right lane into the left lane. It was struck by a Mazda travelling "
        "in the left lane behind it. The former was driven by an off-duty nurse."))


def test_records_pasted_on_one_line_with_slashes_are_read_as_lines():
    assert agents("LEAD_BRAKE_01 / SUT: sedan, centre lane, lane keep, v=60 km/h / POV: lorry, in SUT lane, gap 40 m, "
                  "brakes to standstill / road: highway 3 lanes") == [("car", "go_straight", "ego"),
                                                                       ("truck", "stop", "front")]


def test_people_counted_in_one_vehicle_are_that_vehicle():
    assert agents("Two lads in a Golf come up on my right from behind and fly past me.") == [
        ("car", "go_straight", "back_right"), ("car", "go_straight", "ego")]


def test_the_van_a_teller_took_with_no_subject_is_the_ego():
    assert agents("Tuesday. Took the van to the depot as usual. On the ring road a lorry in the lane to my left "
                  "indicated and pulled across into my lane.") == [("car", "go_straight", "ego"),
                                                                   ("truck", "change_lane_to_right", "left")]


def test_a_red_light_runner_is_a_vehicle_and_a_headings_one_names_the_case():
    assert agents("Signalized junction right turn with a red-light runner. The hero vehicle turns right at a "
                  "signalized intersection at night on a wet road. An adversary vehicle approaches from the left "
                  "road and runs the red light, crossing the junction straight ahead.") == [
        ("car", "go_straight", "road_of_left_turn"), ("car", "turn_right", "ego")]


def test_two_that_there_were_share_what_follows_them():
    assert agents("There was a mum and a toddler walking on the pavement just ahead on my left the whole time.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "front_left"),
        ("pedestrian", "on_the_sidewalk", "front_left")]


def test_the_one_we_call_the_subject_vehicle_is_the_ego_and_a_dark_body_no_night():
    assert ("car", "turn_right", "ego") in agents(
        "Camera 3, 02:13. A dark sedan - we'll call it the subject vehicle - enters frame and stops at the crossing. "
        "A person in a hoodie crosses the road in front of it on the crossing. The sedan then turns right and leaves "
        "frame.")
    assert lower("A dark sedan pulls out in front of me.").scenario.weather is None


def test_l_plates_are_a_learners_not_a_side():
    said = agents("A man was on the crossing when a car with L plates came along, and the learner pulled up well "
                  "back from him.")
    assert not any(a[2] in ("left", "front_left", "back_left") for a in said) and len(said) == 3


def test_people_who_follow_another_across_cross_too():
    assert agents("A woman crosses in front of me and her two kids follow her across.") == [
        ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front"),
        ("pedestrian", "cross_the_road", "front"), ("pedestrian", "cross_the_road", "front")]


def test_the_tellers_own_vehicle_moved_by_them_is_the_ego_moving():
    assert agents("Semi pulled over on the right shoulder up ahead. I moved the truck over a lane to the left to give "
                  "him room.") == [("truck", "change_lane_to_left", "ego"), ("truck", "stop", "front_right")]
    assert agents("I eased the van over into the right lane.") == [("car", "change_lane_to_right", "ego")]


def test_the_road_where_one_turns_is_the_road_turned_into():
    assert agents("At the junction I turn to the right, and in the street where I enter there is one car "
                  "stopped.") == [("car", "stop", "at_the_destination"), ("car", "turn_right", "ego")]


def test_a_side_or_direction_said_after_its_noun_as_other_languages_do():
    assert agents("I entered the roundabout and a bus was coming in the road of the right side.") == [
        ("bus", "go_straight", "road_of_right_turn"), ("car", "go_straight", "ego")]
    assert ("ambulance", "go_straight", "front_left") in agents(
        "An ambulance is coming in contrary direction, I am going straight.")


def test_green_that_comes_is_the_signal_turning_green():
    assert agents("I am waiting in red light, there is a cyclist waiting beside me on right. Then I turn left when "
                  "green come.") == [("car", "stop", "ego"), ("car", "turn_left", "ego"), ("cyclist", "stop", "right")]


def test_a_gapped_clause_with_a_place_of_its_own_does_what_the_one_before_did():
    assert agents("I stand at the red traffic light as first car. Behind me stands a bus and behind the bus a "
                  "taxi.") == [("bus", "stop", "back"), ("car", "stop", "back"), ("car", "stop", "ego")]


def test_one_named_at_the_wheel_and_told_of_as_he_or_she_is_the_ego():
    assert agents("Our daughter Zoe borrowed the work van. At the end of our road a cyclist was coming from the left, "
                  "so she waited for him to pass, then turned right.") == [
        ("car", "stop", "ego"), ("car", "turn_right", "ego"), ("cyclist", "go_straight", "road_of_left_turn")]
    assert agents("Bus driver Janet Lowe stopped at the zebra while two children crossed in front of her.") == [
        ("bus", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
        ("pedestrian", "cross_the_road", "near_the_crosswalk")]
    assert ("car", "change_lane_to_left", "ego") in agents(
        "On the interstate, Hannah in the right lane. Ahead on the right shoulder a trooper was stopped behind a car "
        "he had pulled over, so she moved over into the left lane.")  # ('he' there is the trooper)


def test_a_capitalised_verb_or_a_titled_name_is_no_driver_named():
    assert ("car", "go_straight", "front") in agents("Ambulance behind. Prius? Stays in the left lane at 45.")
    assert agents("Mrs. Feeney was in that crosswalk when the bus turned left.")[0][2] == "ego"


def test_one_watching_from_off_the_road_tells_of_the_first_vehicle_it_names():
    assert agents("From my shop window I saw a red pickup stop on the double yellows right outside my door, and the "
                  "bus behind it had to wait.") == [("bus", "stop", "back"), ("car", "stop", "ego")]
    assert agents("I'm the flagger on the resurfacing job. I turned the board to STOP and the tipper lorry at the "
                  "head of the queue pulled up at the line, with a motorbike stopping right behind it.") == [
        ("motorcycle", "stop", "back"), ("truck", "stop", "ego")]


def test_a_skip_lorry_is_a_lorry_and_the_time_of_a_bus_no_count():
    assert agents("Camera 6 picks up a skip lorry turning right into the industrial estate; a cyclist coming the "
                  "other way goes straight on.") == [
        ("cyclist", "go_straight", "road_of_straight"), ("truck", "turn_right", "ego")]
    assert agents("The 8.15 school bus turned left as the twins crossed the road it turned into.") == [
        ("bus", "turn_left", "ego"), ("pedestrian", "cross_the_road", "at_the_destination"),
        ("pedestrian", "cross_the_road", "at_the_destination")]


def test_leaving_at_an_exit_said_by_side_turns_to_that_side():
    assert agents("The car enters a roundabout and leaves at the first exit to the right.") == [
        ("car", "turn_right", "ego")]


def test_phrases_from_other_languages_own_car_no_there_is_and_waiting_the_bus():
    assert agents("Me and my family was going in car, suddenly one truck came in front and blocked our way.") == [
        ("car", "go_straight", "ego"), ("truck", "block_the_ego", "front")]
    assert lower("An ambulance is coming the other way, I am going straight. No there is any intersection "
                 "here.").scenario.road.junction is False
    assert ("bus", "go_straight", "front") not in agents(
        "I was on the sidewalk waiting the bus, and a red car turned right at the corner.")


def test_a_verb_of_the_third_person_after_an_adverb_goes_on_with_the_one_before():
    assert agents("A taxi in front of me just turns right. No signal. Just turns. And I nearly went into the back of "
                  "him.") == [("car", "go_straight", "ego"), ("car", "turn_right", "front")]


def test_a_courtesy_car_and_a_wheel_count_name_no_one_and_a_keyed_unit_said_again_is_the_ego():
    assert agents("Your vehicle: Yamaha motorcycle\nWhat happened: I was riding straight on along Station Road when "
                  "a silver SUV came out of the side road on my left.\nCourtesy vehicle: not required.") == [
        ("car", "go_straight", "road_of_left_turn"), ("motorcycle", "go_straight", "ego")]
    assert agents("Vehicle involved: 8-wheel tipper lorry\nThe tipper was turning right out of the site gate when a "
                  "worker walked across in front of it.") == [
        ("pedestrian", "cross_the_road", "front"), ("truck", "turn_right", "ego")]
    assert agents("Unit: Van 31 | Event: harsh braking | Notes: dashcam shows Van 31 going straight through a "
                  "crossroads when a cyclist crossed from the right.") == [
        ("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "road_of_right_turn")]


def test_a_party_named_by_role_at_the_wheel_is_the_teller_however_the_role_is_written():
    assert agents("Client riding northbound on Halsted, 2 lanes each way. Dark SUV in the lane to his left swerved "
                  "into his lane and clipped him. Witness: client's buddy, also on a motorcycle, who was ahead of him "
                  "in the same lane.") == [
        ("car", "change_lane_to_right", "left"), ("motorcycle", "go_straight", "ego"),
        ("motorcycle", "go_straight", "front")]


def test_a_rider_named_with_their_role_is_the_teller_on_that_vehicle():
    assert agents("Witnesses said motorcyclist Carla Reyes was riding in the right lane when a semi in the left lane, "
                  "just ahead of her, drifted into her lane. Reyes eased off.") == [
        ("motorcycle", "go_straight", "ego"), ("truck", "change_lane_to_right", "front_left")]


def test_a_verb_with_no_subject_that_comes_from_the_tellers_side_is_the_one_named_before():
    assert agents("Nearly got taken out by a scooter. Came from my right, from the side road, and turned left onto "
                  "my road.") == [("car", "go_straight", "ego"), ("motorcycle", "turn_left", "road_of_right_turn")]


def test_one_said_to_be_in_a_vehicle_between_commas_is_that_vehicle():
    assert agents("I'm going straight across the four-way stop, and the guy from the left, in a pickup, he just goes. "
                  "Doesn't stop.") == [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn")]


def test_a_records_one_vehicle_key_names_its_own_vehicle():
    assert agents("Bus: yellow school bus, route 3\nThe bus was stopped with the stop arm out. A pupil was crossing "
                  "in front of the bus. A pickup truck coming the opposite way did not stop.") == [
        ("bus", "stop", "ego"), ("car", "go_straight", "front_left"), ("pedestrian", "cross_the_road", "front")]


def test_a_fleet_number_keyed_and_a_vehicle_followed_from_the_air_keep_their_readings():
    assert agents("ALERT - Harsh braking event.\nVehicle: HGV-0412. Time: 14:03.\nDashcam review: a car travelling in "
                  "the adjacent right-hand lane, level with the truck, cut in sharply into the truck's lane.") == [
        ("car", "change_lane_to_left", "right"), ("truck", "go_straight", "ego")]
    assert ("truck", "go_straight", "ego") not in agents(
        "Live from the chopper: we're following the getaway car, a silver Camry, heading west in the left lane. "
        "Ahead of it in the center lane, a tanker truck is just rolling along. Then the Camry swerves right.")


def test_one_of_our_fleet_is_the_vehicle_the_teller_is_in():
    assert agents("I was heading north on the A14 in one of our HGVs when a red hatchback in the lane to my left "
                  "suddenly swung in front of me.") == [
        ("car", "change_lane_to_right", "left"), ("truck", "go_straight", "ego")]


def test_one_walking_home_who_saw_it_tells_of_the_first_vehicle_named():
    assert agents("Walking home along the lane in the dark, I saw a hatchback overtake a cyclist just as a lorry came "
                  "the other way.") == [("car", "go_straight", "ego"), ("cyclist", "go_straight", "front"),
                                        ("truck", "go_straight", "front_left")]


def test_one_parked_that_pulls_into_my_lane_cuts_in():
    assert agents("A van that had been parked on the right shoulder just ahead of me suddenly pulled into my "
                  "lane.") == [("car", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]


def test_the_vehicle_the_speaker_drives_is_the_ego():
    assert agents("Driving the 46A bus into town, absolutely lashing. Some eejit in a Yaris pulls out right in front "
                  "of me and stops in the middle of the lane.") == [
        ("bus", "go_straight", "ego"), ("car", "block_the_ego", "front")]
    assert agents("Running a reefer outta Salinas about 3am. Sitting at the red at Main and Alisal waiting to hang a "
                  "left, and an oncoming pickup runs the red straight through the intersection.") == [
        ("car", "go_straight", "road_of_straight"), ("truck", "turn_left", "ego")]
    assert agents("So I'm in the Freightliner hauling up I-5 in the right lane behind a Prius doing 50.") == [
        ("car", "go_straight", "front"), ("truck", "go_straight", "ego")]
    assert ("bus", "stop", "front") in agents("I was driving behind the bus when it stopped.")


def test_a_vehicle_named_first_as_a_label_is_the_speakers_own():
    assert agents("Coach full of Year 6s on the way back from the zoo. Waited on red at the lights on the A38 behind "
                  "a cement mixer, then turned left into Bristol Road.") == [
        ("bus", "stop", "ego"), ("bus", "turn_left", "ego"), ("truck", "stop", "front")]
    assert agents("Bin lorry, Tuesday round on Elm Close. We're stopped for the bins and some bloke in an Audi sat "
                  "right behind me leaning on his horn.") == [("car", "stop", "back"), ("truck", "stop", "ego")]
    assert ("truck", "go_straight", "ego") in agents(
        "18-wheeler, I-95 northbound outside Richmond, three lanes. I'm in the middle, there's a Greyhound in the "
        "right lane a little ahead of me.")


def test_a_logs_call_sign_with_what_it_is_names_the_ego():
    assert agents("C3 (marked car) NB Mill Rd. 1610: pedal cyclist crossed the c/w in front of C3 without looking, "
                  "C3 braked to a stop.") == [("cyclist", "cross_the_road", "front"), ("police", "stop", "ego")]
    assert agents("J5 (patrol car) at give-way, T-jct Mill Ln / B4012, waiting to turn L. Then turned L once clear. "
                  "Before that: motorbike from our R on the B4012 straight past at speed.") == [
        ("motorcycle", "go_straight", "road_of_right_turn"), ("police", "stop", "ego"), ("police", "turn_left", "ego")]
    assert agents("0344 RPU2 (traffic car) M1 NB. Coach stationary on the hard shoulder, hazards on. RPU2 pulled up "
                  "on the hard shoulder behind it.")[-1] == ("police", "stop", "ego")


def test_a_logs_times_to_the_second_and_sensor_names_count_no_one():
    assert agents("INC 0457 / E21 (fire engine) mobile on blues EB Harbour Rd\n0457:30 car directly ahead of E21 in "
                  "same lane stopped dead and would not move\n0458:10 E21 forced to stop behind it\n0458:15 ambulance "
                  "A7 also following directly behind E21") == [
        ("ambulance", "go_straight", "back"), ("car", "stop", "front"), ("firetruck", "stop", "ego")]
    assert agents("14:04:00 XING_07 VEH id=ego class=HGV STOPPED at stop line\n14:04:02 XING_07 PED count=2 "
                  "ON_CROSSING").count(("pedestrian", "cross_the_road", "near_the_crosswalk")) == 1


def test_a_riders_test_names_the_ego_a_motorbike():
    assert agents("Did the road ride part of my CBT today. At the first roundabout I stopped to let a lorry coming from "
                  "the right go round, then went left.") == [
        ("motorcycle", "stop", "ego"), ("motorcycle", "turn_left", "ego"),
        ("truck", "go_straight", "road_of_right_turn")]


def test_a_runner_or_one_in_a_shelter_watches_from_off_the_road():
    assert agents("Sat in the shelter outside the General this afternoon and watched a Deliveroo moped go straight "
                  "through the junction while an ambulance with its lights on was crossing from the left.") == [
        ("ambulance", "go_straight", "road_of_left_turn"), ("motorcycle", "go_straight", "ego")]
    assert agents("Out for my morning run along Ridgeway Road and a grey Audi overtook a cyclist right on the blind "
                  "bend.")[0] == ("car", "go_straight", "ego")


def test_a_calques_place_is_not_read_before_a_parts_name():
    assert agents("The car entered in my front and braked.") == [
        ("car", "block_the_ego", "front"), ("car", "go_straight", "ego")]
    assert agents("Van man pulled out of a side road on my left, straight across my front wheel.") == [
        ("car", "go_straight", "ego"), ("cyclist", "go_straight", "road_of_right_turn")]  # a rider's own wheel


def test_right_into_me_said_alone_is_no_turn():
    assert agents("I'm sitting at the red light, first in line, totally stopped, and this minivan behind me just "
                  "doesn't stop. Bam. Right into my rear bumper.") == [
        ("car", "go_straight", "back"), ("car", "stop", "ego")]
    assert agents("At the junction I turned. Right into the high street.") == [("car", "turn_right", "ego")]


def test_a_tables_lane_and_relative_cells_place_each_row():
    assert agents("actor,vehicle,lane,rel_pos,action\nEGO,car,middle,-,straight\nnpc_1,lorry,left,ahead,straight\n"
                  "npc_2,car,right,level,straight\nnpc_3,car,left,behind ego,straight") == [
        ("car", "go_straight", "back_left"), ("car", "go_straight", "ego"), ("car", "go_straight", "right"),
        ("truck", "go_straight", "front_left")]


def test_nested_keys_are_one_road_user_each():
    assert agents("test_case: TC-114\ntitle: cut-in from right\nego:\n  type: car\n  action: keep lane, straight\n"
                  "actors:\n  - id: npc1\n    type: SUV\n    start: right lane, level with ego\n"
                  "    action: cuts in to ego lane (lane change left)") == [
        ("car", "change_lane_to_left", "right"), ("car", "go_straight", "ego")]
    assert agents('scenario: T-junction, ego on the minor arm\nego: {type: car, action: "stop at give-way line, then '
                  'turn left"}\nnpc:\n  - {type: truck, from: main road on ego\'s right, action: straight across '
                  'ego\'s path}') == [
        ("car", "stop", "ego"), ("car", "turn_left", "ego"), ("truck", "go_straight", "road_of_right_turn")]


def test_a_close_pass_is_told_by_a_rider_of_the_vehicle_that_passed():
    assert agents("Non-emergency ambulance (no lights, no siren) overtook me on a single-track lane near Hawes with "
                  "about a foot to spare.") == [("ambulance", "go_straight", "ego"), ("cyclist", "go_straight", "front")]
    assert agents("I had pulled over onto the shoulder and come to a stop so an ambulance running its siren could "
                  "get by. A red Toyota was right behind the ambulance and didn't ease off at all, just tore past me "
                  "with less than a foot to spare.")[1] == ("car", "go_straight", "ego")


def test_the_bike_the_teller_rides_with_no_word_of_pedals_is_a_motorbike():
    assert agents("Jogger with headphones in ran out from between parked vans on my left, right in front of the bike. "
                  "Locked the back up and stopped with about a foot to spare.") == [
        ("motorcycle", "stop", "ego"), ("pedestrian", "cross_the_road", "front_left")]
    assert ("motorcycle", "go_straight", "back_right") in agents(
        "Tonight on the dual carriageway, the motorbike that came up behind you in the right-hand lane and went past, "
        "you didn't spot it in your mirror at all, did you?")


def test_the_one_named_first_behind_one_named_after_it_is_the_ego():
    assert agents("A car travels in the left lane behind a lorry.") == [
        ("car", "go_straight", "ego"), ("truck", "go_straight", "front")]
    assert agents("In the picture, a fire engine with its blue lights on is coming up fast behind the red car on a "
                  "dual carriageway. The red car moves into the left lane to let it through.") == [
        ("car", "change_lane_to_left", "ego"), ("firetruck", "go_straight", "back")]


def test_a_problems_reaction_time_keeps_the_subject_of_the_next_verb():
    assert agents("Car A is travelling at 22 m/s in the right-hand lane of a two-lane dual carriageway. An ambulance "
                  "comes up behind it in the same lane at 34 m/s. When the ambulance is 150 m behind, the driver of car "
                  "A notices it and, after a reaction time of 1.2 s, moves over into the left-hand lane.") == [
        ("ambulance", "go_straight", "back"), ("car", "change_lane_to_left", "ego")]


def test_a_patrols_unit_said_with_its_car_in_brackets_is_the_ego():
    assert agents("Unit 4 (marked car) en route NB A38. Red Audi A3 just ahead of us in the n/s lane pulled out "
                  "into our lane.") == [("car", "change_lane_to_right", "front_left"), ("police", "go_straight", "ego")]
    assert agents("0040 hrs, dark, very heavy rain. Unit 6 (marked) NB Station Rd, 30 mph limit. Ped, IC3 female, "
                  "dark coat, came out between parked vehicles and walked across in front of unit. Unit then stopped, "
                  "no contact.") == [
        ("pedestrian", "cross_the_road", "front"), ("police", "go_straight", "ego"), ("police", "stop", "ego")]
    assert ("truck", "go_straight", "front") in agents(
        "Unit 22 (marked ARV) on blues to Grade 1, A14 WB, 2 lanes, unit in lane 1. Slow skip lorry ahead in lane 1, "
        "unit pulled out into lane 2 to pass.")


def test_a_route_ridden_with_its_driver_said_bare_is_the_ego_bus():
    assert agents("Riding the 22 down Mission this afternoon and a kid on a bike came flying out of a driveway on the "
                  "right and straight across the street in front of us. Driver hit the brakes and we stopped maybe "
                  "two feet from him.") == [("bus", "stop", "ego"), ("cyclist", "go_straight", "front_right")]


def test_a_flagger_at_the_board_watches_from_off_the_road():
    assert agents("Lakeshore between 5th and 6th, parking lane's coned off for the vault work so traffic's running "
                  "right along the curb. Box truck rolled through and his mirror came within a foot of a jogger on "
                  "the sidewalk right next to him on his right. Told the foreman we need to move the barrels "
                  "out.")[-1] == ("truck", "go_straight", "ego")


def test_brought_to_rest_is_a_stop():
    assert agents("A car is travelling at 15 m/s along a straight country road when its driver hears the siren of a "
                  "fire engine coming towards it at 22 m/s. The two vehicles are 180 m apart at this moment. After a "
                  "reaction time of 0.9 s the driver brakes uniformly and brings the car to rest in 30 m.") == [
        ("car", "stop", "ego"), ("firetruck", "go_straight", "front_left")]


def test_one_filtering_in_a_cycle_lane_rides_a_bicycle():
    assert agents("Left hook on Park Row this morning, 8:20ish. Traffic was crawling and I was filtering up the inside "
                  "in the cycle lane. I was level with the passenger door of a silver Skoda when it turned left into "
                  "the Co-op car park across me.") == [("car", "turn_left", "ego"), ("cyclist", "go_straight", "left")]
    assert agents("Bloke stepped out from between the stationary traffic on Euston Road right in front of me while I "
                  "was filtering at walking pace. Inches from my front wheel.") == [
        ("motorcycle", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]


def test_dialect_and_word_order_calques_say_the_lane_and_side():
    assert ("bus", "go_straight", "front_left") in agents(
        "I'm on the quays, yeah, and there's a bus in the bus lane on me left, just ahead of me.")
    assert ("car", "change_lane_to_left", "ego") in agents(
        "Road two lanes, very full. In front of me one bus slowly going, uphill. Then I to left lane changed, the bus "
        "to overtake.")
    assert agents("Light green for me but I stopped, because from right road fire brigade truck siren with is coming, "
                  "red light passing.") == [("car", "stop", "ego"), ("firetruck", "go_straight", "road_of_right_turn")]
    assert ("car", "stop", "ego") in agents("I'm first at the lights on Old Street, yeah, and a moped pulls up right "
                                            "next to me.")


def test_the_ego_pulling_out_at_a_junction_turns():
    assert agents("At the T-junction I waited for a bus from the right, then pulled out left.") == [
        ("bus", "go_straight", "road_of_right_turn"), ("car", "stop", "ego"), ("car", "turn_left", "ego")]
    assert agents("At the lights I pulled out right to get round the bus.")[-1] == ("car", "change_lane_to_right", "ego")


def test_a_named_street_the_ego_turns_into_is_the_destination_when_crossed_or_left():
    assert agents("The ego turns left into Victoria Rd. 2 peds are walking across Victoria Rd.") == [
        ("car", "turn_left", "ego"), ("pedestrian", "cross_the_road", "at_the_destination"),
        ("pedestrian", "cross_the_road", "at_the_destination")]
    assert ("cyclist", "go_straight", "at_the_destination") in agents(
        "Test car turns left into Queen Street. A cyclist is exiting Queen Street towards the junction.")
    assert ("pedestrian", "cross_the_road", "at_the_destination") in agents(
        "I turned right onto Elm Street while a jogger was crossing Elm Street.")


def test_one_waiting_behind_the_ego_is_not_there_where_the_ego_turns():
    assert ("car", "stop", "back") in agents(
        "I was waiting at the red to turn right onto Main while an old man crossed Main in the crosswalk in front of "
        "me, and the pickup behind me sat there laying on the horn.")
    assert ("car", "stop", "back") in agents(
        "I'm at the light waiting to turn right, there's a bus stopped on the street I'm turning onto, and the van "
        "behind me just sits there honking.")


def test_a_timelines_stamps_and_the_unit_under_test():
    assert agents("T+0: UUT cruising at 30 km/h toward a zebra crossing. T+2: two pedestrians step onto the crossing. "
                  "T+4: UUT at standstill before the crossing. T+9: once both pedestrians have reached the far side, "
                  "the UUT pulls away.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
        ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_the_ego_first_named_the_car_is_the_car_again_after_another_car():
    assert agents("At an all-way stop, the car comes to a full stop. A minivan arrives from the right-hand road. "
                  "Then the car proceeds straight through the intersection.") == [
        ("car", "go_straight", "ego"), ("car", "go_straight", "road_of_right_turn"), ("car", "stop", "ego")]


def test_a_manoeuvre_named_with_its_adjectives_is_nobodys_act():
    assert agents("Unit 61 (refuse truck) stopped at a 4-way stop. A fire engine came from the right and turned left. "
                  "Driver remained stopped until it cleared, then proceeded straight. Flagged on the initial stop; no "
                  "issue.")[-2:] == [("truck", "go_straight", "ego"), ("truck", "stop", "ego")]


def test_a_bus_passengers_driver_said_again_and_pulling_away_from_the_stop():
    assert agents("Just want to say the driver on the first 12 out of Hillside was brilliant. We were sitting at the "
                  "stop on Park Road and a black BMW came up behind us in the right hand lane and shot past. Once it "
                  "had gone the driver pulled out and carried on.") == [
        ("bus", "go_straight", "ego"), ("bus", "stop", "ego"), ("car", "go_straight", "back_right")]


def test_those_a_memo_is_addressed_to_are_no_agents():
    assert agents("SAFETY MEMO - all drivers. Last Tuesday one of our delivery vans was turning left on a green light "
                  "at the Fifth and Main intersection when a speeding motorcycle coming the other way went straight "
                  "through.") == [("car", "turn_left", "ego"), ("motorcycle", "go_straight", "road_of_straight")]


def test_a_scooter_ridden_as_a_verb_and_the_guy_on_a_moped_is_no_one_on_foot():
    assert agents("Scootering down Castle St in the drizzle and I stopped at the zebra for two schoolkids and their "
                  "mum crossing. But the guy on the moped behind me, who had to stop too, beeped at me.") == [
        ("motorcycle", "stop", "back"), ("motorcycle", "stop", "ego")] + [
        ("pedestrian", "cross_the_road", "near_the_crosswalk")] * 3


def test_another_bike_beside_a_motorbike_ego_and_a_motor_courier_are_motorbikes():
    assert agents("I was riding my motorcycle on the A1. My friend was riding ahead of me in the same lane on another "
                  "bike.") == [("motorcycle", "go_straight", "ego"), ("motorcycle", "go_straight", "front")]
    assert ("motorcycle", "go_straight", "back_right") in agents(
        "Traffic jam, road two lanes. In front of me a Doblo van stopped. A motor courier from behind fast came, "
        "between lanes my right side from passed.")


def test_a_condition_without_its_comma_ends_where_the_teller_speaks_again():
    assert agents("I was waiting to turn left. An oncoming SUV went past. Once he was clear I made the turn.") == [
        ("car", "go_straight", "road_of_straight"), ("car", "stop", "ego"), ("car", "turn_left", "ego")]
    assert agents("Waiting at the light to make the right onto Broadway, two kids were crossing Broadway in the "
                  "crosswalk. Once they got across I made my turn.")[:2] == [("car", "stop", "ego"),
                                                                              ("car", "turn_right", "ego")]


def test_a_stop_or_turn_named_as_a_noun_after_for_is_nobodys_act():
    assert agents("All-way stop at Pine & 3rd. Shuttle stopped at the sign; a pickup coming from our right had got "
                  "there first, so we let it turn left in front of us. Then the shuttle carried straight on "
                  "through. 2 pax, both for the hospital stop.") == [
        ("bus", "go_straight", "ego"), ("bus", "stop", "ego"), ("car", "turn_left", "road_of_right_turn")]
    assert ("car", "stop", "road_of_straight") in agents(
        "At a signalised intersection the ego turns left. An oncoming car waits in the opposite approach for its own "
        "turn.")


def test_pulling_off_after_a_stop_moves_on():
    assert agents("I stopped at the lights. When the lights changed I pulled off.") == [
        ("car", "go_straight", "ego"), ("car", "stop", "ego")]


def test_you_all_and_we_all_take_the_egos_company_along():
    assert agents("You're leading a group ride with three other bikes following you in a line, and you all turn left "
                  "at an uncontrolled crossroads.") == [("motorcycle", "turn_left", "back")] * 3 + [
        ("motorcycle", "turn_left", "ego")]


def test_too_fast_to_stop_is_no_stop():
    assert agents("Filtering past a long queue on a wet evening. A car coming the other way turns right through a gap "
                  "in the queue, across your path. Don't be going too fast to stop.") == [
        ("car", "turn_right", "road_of_straight"), ("motorcycle", "go_straight", "ego")]


def test_with_one_placed_in_a_lane_its_participle_is_its_own():
    assert agents("Portaflows on red at my end and a queue building. A motorbike came right up the outside of the "
                  "queue and went straight through on red, with a cyclist already in the shuttle lane coming towards "
                  "him.") == [("cyclist", "go_straight", "front_left"), ("motorcycle", "go_straight", "ego")]


def test_diving_left_into_a_lane_changes_lane():
    assert ("car", "change_lane_to_left", "ego") in agents(
        "The ego is in lane three. Then at the last second it dived left into lane two, right behind a coach.")


def test_one_that_followed_it_round_goes_the_same_way_behind_it():
    assert agents("The ego turned right across the junction. A police car followed it round.") == [
        ("car", "turn_right", "ego"), ("police", "turn_right", "back")]
    assert agents("I was at the kerb outside the bank, waiting to cross Station Road, when a black cab jumped the red "
                  "and turned right across the junction. A police car followed it round.") == [
        ("car", "turn_right", "ego"), ("police", "turn_right", "back")]


def test_one_coming_the_other_way_that_had_to_wait_for_a_turner_stops():
    assert agents("The bus turned right at the lights. A car coming the other way had to wait for it.") == [
        ("bus", "turn_right", "ego"), ("car", "stop", "road_of_straight")]


def test_the_ego_moving_into_a_numbered_lane_changes_towards_it():
    assert ("car", "change_lane_to_right", "ego") in agents(
        "Patrolling M4 eastbound, lane 1, in the TOV. A white Transit came straight into lane 1 just ahead of us, so "
        "we moved out into lane 2 to avoid it.")
    assert agents("Inc 1553, M18 northbound, two lanes. Running in lane 2 in the TOV when an ambulance on blues and "
                  "twos came up behind us in lane 2. Moved over into lane 1 behind a Corsa to let the ambulance "
                  "through, then followed the ambo to the RTC.") == [
        ("ambulance", "go_straight", "back"), ("car", "change_lane_to_left", "ego"), ("car", "go_straight", "ego"),
        ("car", "go_straight", "front_left")]


def test_a_ploughs_blade_and_spinner_are_its_drivers_truck():
    assert agents("Three lanes on the turnpike, I'm doing the center lane with the spinner going and a box truck just "
                  "ahead of me in the right lane cuts over into my lane right in front of the blade.") == [
        ("truck", "change_lane_to_left", "front_right"), ("truck", "go_straight", "ego")]


def test_a_caller_who_drives_a_vehicle_tells_from_it():
    assert ("bus", "go_straight", "ego") in agents(
        "Caller is driver of city bus, route 42. Says he was pulling away from the stop on Grand Ave when a cyclist "
        "came up on his left side and swerved in front of the bus.")
    assert agents("Caller is taxi driver w/ fare on board, at the 4-way stop Cedar/Hill. Says he was stopped at the "
                  "sign waiting his turn when a car from his right and a van from the opposite side both went at the "
                  "same time.") == [
        ("car", "go_straight", "road_of_right_turn"), ("car", "go_straight", "road_of_straight"),
        ("car", "stop", "ego")]


def test_someone_said_again_of_the_same_place_is_the_one_named_before():
    assert agents("On Friday one of our vans stopped at a red light and then turned right on red while a woman was "
                  "crossing, in the crosswalk, the street it was turning into. A right on red is never worth it with "
                  "someone in the crosswalk.") == [
        ("car", "stop", "ego"), ("car", "turn_right", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_one_behind_the_stopped_ego_that_only_honks_stands_behind_it():
    assert agents("I'm stopped at a zebra crossing for a couple crossing, and the Audi behind me is sat right on my "
                  "bumper leaning on his horn.") == [
        ("car", "stop", "back"), ("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk"),
        ("pedestrian", "cross_the_road", "near_the_crosswalk")]


def test_a_subject_that_is_no_agent_goes_on_in_its_next_verb():
    assert agents("I was stopped on the shoulder at the box when the fire truck came flying up behind me, lights and "
                  "siren, and went on by. A deer stood in the ditch the whole time and never moved.") == [
        ("car", "stop", "ego"), ("firetruck", "go_straight", "back")]


def test_services_called_and_records_kept_are_no_agents():
    assert agents("CALLER: I need police and an ambulance, there's been a crash right in front of me. I'm stopped at "
                  "the red in my car. A pickup ran the red from the road on my left.") == [
        ("car", "go_straight", "road_of_left_turn"), ("car", "stop", "ego")]
    assert agents("I was stopped at a red light in the HGV. A fire engine came through the junction from my left. The "
                  "supervisor asks us to log all emergency vehicle incidents.") == [
        ("firetruck", "go_straight", "road_of_left_turn"), ("truck", "stop", "ego")]


def test_one_from_the_same_direction_comes_from_where_the_one_before_came():
    assert agents("The ego is stopped at a red light. A fire engine crosses the intersection from the right. Then an "
                  "ambulance follows from the same direction.") == [
        ("ambulance", "go_straight", "road_of_right_turn"), ("car", "stop", "ego"),
        ("firetruck", "go_straight", "road_of_right_turn")]


def test_into_the_other_lane_changes_lane_and_holding_at_the_green_waits():
    assert agents("There was a big lorry in front of us and it was going realy slow. Then dad went in to the other "
                  "lane on the right and went past it.") == [
        ("car", "change_lane_to_right", "ego"), ("car", "go_straight", "ego"), ("truck", "go_straight", "front")]
    assert ("car", "stop", "ego") in agents("Our ego is holding at the green, because an ambulance is barreling "
                                             "across. Once the ambulance clears, the sedan goes straight through.")


def test_just_beyond_one_ahead_is_ahead():
    assert ("pedestrian", "on_the_sidewalk", "front_left") in agents(
        "On a clear evening a westbound driver is looking straight into the setting sun and may not see a car "
        "queuing ahead of them for the garden centre, or a pedestrian walking along the footway on their left just "
        "beyond it.")


def test_when_in_the_past_perfect_opens_a_later_stage():
    assert agents("I was waiting to turn right while a Land Rover came towards me. When it had passed, I turned.") == [
        ("car", "go_straight", "road_of_straight"), ("car", "stop", "ego"), ("car", "turn_right", "ego")]
