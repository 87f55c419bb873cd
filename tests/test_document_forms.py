"""Scenes written inside other documents' forms (narration.py): acceptance criteria in Given/When/Then steps, bug
reports, prompts written for a chatbot; and the reader's rules these forms brought to light. Each rule is held by
sentences written for it, not taken from the corpus."""

from __future__ import annotations

import pytest

from ttsgc.lowering.offline import lower


def agents(prompt: str) -> list[tuple[str, str, str]]:
    return sorted((a.type, a.action, a.relative_to_ego or "ego") for a in lower(prompt).scenario.agents())


def stages(prompt: str) -> list[list[tuple[str, str, str]]]:
    return [[(a.type, a.action, a.relative_to_ego or "ego") for a in s.agents] for s in lower(prompt).scenario.stages]


# -- acceptance criteria in steps ---------------------------------------------------------------------------

def test_a_then_step_is_the_egos_reaction_to_its_when_step_not_a_later_stage():
    found = stages("Scenario: cyclist out of a driveway\n"
                   "  Given the ego car drives along a two-lane street\n"
                   "  When a cyclist rides out from a driveway on the right\n"
                   "  Then the ego car should stop\n")
    assert len(found) == 1 and ("car", "stop", "ego") in found[0], found


def test_a_then_step_with_no_when_before_it_is_no_stage_either():
    found = stages("Feature: lane keeping\n"
                   "  Background:\n"
                   "    Given it is a foggy night\n"
                   "  Scenario: empty motorway\n"
                   "    Given the ego is driving on a motorway\n"
                   "    Then the ego should keep its lane\n")
    assert found == [[("car", "go_straight", "ego")]], found
    assert lower("Given it is a foggy night\nAnd the ego is driving on a motorway\n"
                 "Then the ego should keep its lane").scenario.weather.condition == "fog"


def test_a_when_step_that_changes_the_scene_still_starts_a_stage():
    found = stages("Given the ego truck is waiting at a red light\n"
                   "And a bus is waiting in the lane to its left\n"
                   "When the light turns green\n"
                   "Then the ego truck should turn right\n")
    assert len(found) == 2 and ("truck", "turn_right", "ego") in found[1], found
    assert ("bus", "stop", "left") in found[0], found


def test_a_then_steps_modal_is_what_the_ego_is_to_do():
    found = stages("Given the ego is stopped at a stop sign\n"
                   "And a van is crossing from the left\n"
                   "When the van has passed\n"
                   "Then the ego may turn left\n")
    assert len(found) == 2 and ("car", "turn_left", "ego") in found[1], found


def test_a_sentence_that_starts_with_given_is_no_step():
    found = agents("Given the rain, the ego drives slowly. Then a bus pulls out in front of the ego.")
    assert len(lower("Given the rain, the ego drives slowly. Then a bus pulls out in front of the ego.")
               .scenario.stages) == 2, found


# -- bug reports -----------------------------------------------------------------------------------------------

def test_what_a_bug_report_got_under_actual_is_no_part_of_the_scene():
    report = ("Motorbike overtakes on the wrong side\n\n"
              "## To Reproduce\n"
              "- prompt: a motorcycle comes up behind the ego and overtakes it on the left\n"
              "- `ttsgc compile prompt.txt --map town04`\n\n"
              "## Expected behavior\nThe motorcycle passes on the left.\n\n"
              "## Current behavior\nThe motorcycle passes on the right and a second bus appears behind the ego.\n")
    assert agents(report) == [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "back_left")]


def test_a_bug_reports_versions_and_tool_steps_name_no_agents():
    report = ("Title: cyclist disappears at roundabout\n"
              "Environment: ttsgc 1.4.0 / esmini 2.40, Ubuntu 22.04\n"
              "Steps to reproduce:\n"
              "1. Ask for \"the ego waits at a junction while a cyclist rides past from the left\"\n"
              "2. Run validate and watch the ego\n"
              "Expected: cyclist keeps going, ego gives way.\n"
              "Actual result: the cyclist is removed and a truck is stopped in the ego's lane.\n")
    assert agents(report) == [("car", "stop", "ego"), ("cyclist", "go_straight", "road_of_left_turn")]


def test_a_bug_report_that_tells_its_scene_only_as_expected_is_read_from_that():
    report = ("Steps to reproduce: lower the attached prompt with seed 1.\n"
              "Expected result: a van stopped ahead in the ego's lane, and the ego changes lane to the left.\n"
              "What happened instead: the ego stops behind the van forever and a police car shows up.\n")
    assert agents(report) == [("car", "change_lane_to_left", "ego"), ("car", "stop", "front")]


def test_the_prompt_quoted_in_a_tool_step_is_the_scene():
    report = ("Steps to reproduce: lower \"a van is double-parked ahead in the ego's lane\" with seed 1.\n"
              "Expected result: the ego waits.\nActual: a police car shows up.\n")
    assert agents(report) == [("car", "go_straight", "ego"), ("car", "stop", "front")]


def test_a_bug_reports_title_names_no_agents():
    report = ("Bug: the lead truck never stops in cut-in scenes\n"
              "Steps to reproduce\n1. A car in the left lane cuts in front of the ego.\n"
              "Expected\nThe car changes lane to the right.\nActual\nIt stays in its lane.\n")
    assert agents(report) == [("car", "change_lane_to_right", "left"), ("car", "go_straight", "ego")]


# -- prompts written for a chatbot -------------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, count", [
    ("Act as a traffic simulation assistant. Build a scene where the ego follows a bus on a two-lane road and a "
     "motorcycle overtakes the ego on the left. Return a list of all actors with their start positions and "
     "manoeuvres.", 3),
    ("You are a scenario generator. A pedestrian crosses in front of the ego at night. Respond in JSON, one object "
     "per agent.", 2),
    ("Generate a scene: the ego stops at a red light. Output format: every vehicle with its lane and action.", 1),
])
def test_a_chatbots_role_and_the_form_of_its_answer_name_no_agents(prompt, count):
    assert len(agents(prompt)) == count, agents(prompt)


def test_an_order_to_the_chatbot_that_names_a_road_user_or_the_weather_is_read():
    found = lower("Generate a scene: the ego stops at a red light. Make sure that a truck is parked on the "
                  "shoulder. Keep it rainy. Keep the output short.").scenario
    assert ("truck", "stop", "front_right") in [(a.type, a.action, a.relative_to_ego) for a in found.agents()]
    assert found.weather is not None and "rain" in found.weather.condition


# -- the reader's rules the forms brought to light -----------------------------------------------------------------

@pytest.mark.parametrize("prompt, later", [
    ("The ego waits at the junction. A lorry comes from the right. When the lorry has gone through, the ego turns "
     "left.", ("car", "turn_left", "ego")),
    ("The ego waits behind a parked van. A cyclist comes towards it. when the cyclist has passed the ego pulls "
     "out to the left.", ("car", "change_lane_to_left", "ego")),
])
def test_a_when_clause_in_the_present_perfect_starts_a_later_stage(prompt, later):
    found = stages(prompt)
    assert len(found) == 2 and later in found[1], found


def test_the_van_named_again_is_the_van_not_a_car_named_after_it():
    assert agents("The ego is behind a delivery van. A car follows the ego. The van stops.") == [
        ("car", "go_straight", "back"), ("car", "go_straight", "ego"), ("car", "stop", "front")]


def test_straight_across_the_junction_is_the_way_a_vehicle_goes_not_where_it_comes_from():
    assert ("truck", "go_straight", "road_of_right_turn") in agents(
        "A lorry comes from the road on the right and goes straight across the intersection.")


def test_a_vehicle_that_is_stopped_dead_stands_it_made_no_abrupt_stop():
    stood = lower("A bus is stopped dead in the middle lane ahead.").scenario
    assert [a.behavior for a in stood.agents() if not a.is_ego] != ["aggressive"]
    braked = lower("The bus ahead stops dead.").scenario
    assert [a.behavior for a in braked.agents() if not a.is_ego] == ["aggressive"]


def test_a_painted_stop_line_is_a_stop_line():
    road = lower("The ego waits at a painted stop line.").scenario.road
    assert "stop_line" in road.required_objects + road.required_signals
    assert "stop_sign_on_road" not in road.required_objects + road.required_signals


@pytest.mark.parametrize("prompt, expected", [
    ("The ego waits at the junction. A lorry is waiting at the give-way line on the right. When the lorry drives "
     "straight across, the ego stops.", ("truck", "go_straight", "road_of_right_turn")),
    ("A motorbike waits on the ego's left at the lights. Once the lights change, the motorbike goes straight on and "
     "the ego turns left.", ("motorcycle", "go_straight", "left")),
])
def test_one_that_waits_then_goes_straight_through_goes_straight(prompt, expected):
    assert expected in agents(prompt), agents(prompt)


def test_one_that_waits_then_only_moves_off_stood():
    assert ("cyclist", "stop", "front") in agents(
        "A cyclist waits in front of me at the red light. Once it goes green we both move off.")


@pytest.mark.parametrize("prompt, expected", [
    ("Two other cars are at the junction. One is stopped on the road to the right, and the other comes from the "
     "left and turns right.", [("car", "stop", "road_of_right_turn"), ("car", "turn_right", "road_of_left_turn")]),
    ("Two cyclists ride ahead of the ego. One keeps going straight and the other turns left.",
     [("cyclist", "go_straight", "front"), ("cyclist", "turn_left", "front")]),
    ("There are three cars including the ego. One car is stopped on the road to the right, and the other comes "
     "from the left.", [("car", "go_straight", "road_of_left_turn"), ("car", "stop", "road_of_right_turn")]),
])
def test_the_other_after_one_is_the_groups_other_member(prompt, expected):
    assert [a for a in agents(prompt) if a[2] != "ego"] == expected, agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("The ego comes up behind a lorry that has broken down in the right lane.", ("truck", "stop", "front")),
    ("The ego pulls up behind a bus stopped in the left lane.", ("bus", "stop", "front")),
])
def test_the_lane_named_for_one_the_ego_comes_up_behind_is_the_egos_lane(prompt, expected):
    assert expected in agents(prompt), agents(prompt)


def test_one_in_a_lane_the_ego_is_not_said_to_follow_in_keeps_its_side():
    assert ("bus", "go_straight", "front_left") in agents("A bus is in the left lane ahead. The ego stays in the "
                                                          "right lane.")
    assert ("car", "go_straight", "back_left") in agents("A van rides behind the ego in the left lane.")


def test_an_obliged_verb_placed_by_it_after_a_relative_clause_is_the_main_subjects():
    assert ("car", "stop", "ego") in agents("The ego comes up behind a lorry that has broken down and has to wait "
                                            "behind it.")


@pytest.mark.parametrize("prompt, expected", [
    ("the ego is waiting at a red light, with a taxi waiting beside it in the lane to its right.",
     ("car", "stop", "right")),
    ("The ego waits at the lights, with a van waiting next to it in the lane on its right.", ("car", "stop", "right")),
])
def test_its_after_it_said_of_the_ego_is_the_egos(prompt, expected):
    assert expected in agents(prompt), agents(prompt)


def test_its_said_of_the_one_passed_is_still_its_own_side():
    assert ("truck", "go_straight", "front") in [(t, a, p) for t, a, p in agents("The ego overtakes a slow truck "
                                                                                  "on its left.")]


@pytest.mark.parametrize("prompt, action", [
    ("The ego is travelling in the right-hand lane of a three-lane motorway. The ego moves into the middle lane.",
     "change_lane_to_left"),
    ("The ego is in the left lane of a three-lane motorway. A lorry merges ahead, and the ego moves over to the "
     "centre lane.", "change_lane_to_right"),
])
def test_a_move_into_the_middle_lane_is_away_from_the_side_lane_the_ego_is_in(prompt, action):
    assert ("car", action, "ego") in agents(prompt), agents(prompt)


def test_an_outlines_first_example_row_is_the_scene_and_its_table_no_agents():
    outline = ("Scenario Outline: pedestrian crossing at different speeds\n"
               "  Given the ego car drives at <speed> towards a zebra crossing in <weather>\n"
               "  When a <actor> steps onto the crossing\n"
               "  Then the ego car should stop\n\n"
               "  Examples:\n"
               "    | speed   | weather | actor      |\n"
               "    | 30 km/h | rain    | child      |\n"
               "    | 50 km/h | fog     | pedestrian |\n")
    scene = lower(outline).scenario
    assert agents(outline) == [("car", "stop", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]
    assert scene.weather is not None and scene.weather.condition == "mid_rain"


def test_an_order_to_leave_road_users_out_says_there_are_none():
    assert agents("Create a scenario where the ego turns left at an intersection and a pedestrian crosses from the "
                  "left. Don't include any other vehicles.") == [("car", "turn_left", "ego"),
                                                                 ("pedestrian", "cross_the_road", "front_left")]
    assert len(agents("I want you to act as a scenario designer. A bus overtakes the ego. Do not add any "
                      "pedestrians.")) == 2


def test_a_story_told_a_line_at_a_time_is_no_set_of_steps():
    story = "I was driving along.\nWhen a bus pulled out, I braked.\nThen a cyclist overtook me."
    assert len(lower(story).scenario.stages) == 2
