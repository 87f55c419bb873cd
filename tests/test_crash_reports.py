"""Reading crash reconstructions and pre-crash typology notes: vehicles named V1, Unit 2, Ped 1, one of them said to
be the ego; makes, models and model numbers; compass headings against the ego's; crash-typology names."""

from __future__ import annotations

import pytest

from ttsgc.lowering.narration import read_narration
from ttsgc.lowering.offline import lower


def agents(prompt: str) -> list[tuple[str, str, str]]:
    """(type, action, position) of every agent, the ego as position 'ego'."""
    return sorted((a.type, a.action, a.relative_to_ego or "ego") for a in lower(prompt).scenario.agents())


# -- the designated ego ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("Unit 1 (ego), a 2011 Mazda 3 hatchback, is southbound on Pine Rd. Unit 1 stops behind a parked van.",
     [("car", "stop", "ego"), ("car", "stop", "front")]),
    ("V1 (ego, 2020 Honda Civic) travels in the right lane. A motorcycle passes V1 on the left.",
     [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "back_left")]),
    ("Vehicle 1 (subject vehicle) turns right at the junction while V1's driver watches a cyclist crossing.",
     [("car", "turn_right", "ego"), ("cyclist", "cross_the_road", "front")]),
    ("V1, the ego vehicle, is eastbound at 30 mph. V2, a red sedan, is westbound and turns left in front of V1.",
     [("car", "go_straight", "ego"), ("car", "turn_left", "road_of_straight")]),
    ("Vehicle 2 (V2), a grey Nissan van, stopped ahead of Vehicle 1 (V1, ego). V1 stopped behind V2.",
     [("car", "stop", "ego"), ("car", "stop", "front")]),
    ("Ego = V1, northbound, 35 mph. V2, a bus, is stopped ahead of V1.",
     [("bus", "stop", "front"), ("car", "go_straight", "ego")]),
])
def test_a_designation_said_to_be_the_ego_is_the_ego_wherever_it_is_named(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_the_designated_egos_bracket_describes_it_and_its_name_is_replaced_everywhere():
    told = read_narration("V1 (ego, 2019 Ford Escape) brakes. V2 hits V1's rear.").text
    assert told == "The ego, a 2019 Ford Escape, brakes. V2 hits the ego's rear."
    assert read_narration("V12 turns left. V1 waits.").text == "V12 turns left. V1 waits."  # no ego said: as written
    assert read_narration("V1 (ego, eastbound) enters.").text == "The ego, eastbound, enters."  # no second agent


# -- makes, models and their numbers ------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("A Dodge Ram 2500 pickup turns right in front of me.", [("car", "go_straight", "ego"),
                                                             ("car", "turn_right", "front")]),
    ("An 8-year-old boy runs across the road.", [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road",
                                                                                 "front")]),
    ("The ego, a Toyota Highlander, follows a Nissan Sentra.", [("car", "go_straight", "ego"),
                                                                ("car", "go_straight", "front")]),
    ("V3, a Chevrolet Malibu, is stopped ahead.", [("car", "go_straight", "ego"), ("car", "stop", "front")]),
])
def test_a_make_a_model_and_a_model_number_name_one_vehicle(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_a_counted_number_still_counts():
    assert len(agents("3 cars wait at the light.")) == 4
    assert len(agents("A group of 3 cyclists waits.")) == 4


# -- compass headings against the ego's ----------------------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("The ego is eastbound on Main St. A box truck is northbound on 3rd Ave and drives through the intersection.",
     ("truck", "go_straight", "road_of_right_turn")),  # north is an eastbound ego's left: the truck heads there
    ("The ego travels south on Route 4. A sedan heading east runs the stop sign at the junction.",
     ("car", "go_straight", "road_of_right_turn")),
    ("The ego, westbound, reaches the crossroads. A bus coming from the north goes straight across.",
     ("bus", "go_straight", "road_of_right_turn")),
    ("The ego drives northbound through the junction and turns right onto eastbound Elm. A van is southbound on the "
     "same street.", ("car", "go_straight", "road_of_straight")),
])
def test_compass_headings_place_crossing_and_oncoming_traffic(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("Unit 1 (ego) is southbound on Lake Rd. A pickup is parked against the west curb ahead. A boy runs out from "
     "behind it, west to east.", [("car", "go_straight", "ego"), ("car", "stop", "front_right"),
                                  ("pedestrian", "cross_the_road", "front_right")]),
    ("The ego heads east. A jogger crosses from the north side of the street.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left")]),
    ("The ego is westbound. A woman is walking southbound across the road ahead.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_right")]),
    ("Ped 1 stepped off the west curb, walking east, into the path of V1 (ego), which was northbound.",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left")]),
    ("The ego heads north. A man walks north on the east sidewalk.",
     [("car", "go_straight", "ego"), ("pedestrian", "on_the_sidewalk", "right")]),
])
def test_compass_sides_and_origins_place_what_stands_and_who_crosses(prompt, expected):
    assert agents(prompt) == sorted(expected)


@pytest.mark.parametrize("prompt, expected", [
    ("The ego is northbound on Park Ave at 30 mph.", [("car", "go_straight", "ego")]),
    ("A cyclist rides along Stop Rd behind the ego.", [("car", "go_straight", "ego"),
                                                       ("cyclist", "go_straight", "back")]),
    ("The ego drives west on Park Blvd and a van is parked ahead.", [("car", "go_straight", "ego"),
                                                                     ("car", "stop", "front")]),
    ("The ego waits at the light on Turner Road; a bus is stopped on Stop Street ahead.",
     [("bus", "stop", "front"), ("car", "stop", "ego")]),
])
def test_a_verbs_word_naming_a_street_names_nothing_of_the_scene(prompt, expected):
    assert agents(prompt) == sorted(expected)
    assert "stop" not in lower(prompt).scenario.road.required_signals


@pytest.mark.parametrize("prompt, expected", [
    ("V1 (ego) keeps its lane. V2, a truck in the right lane ahead, merges left; end the run before V2's left rear trailer "
     "corner touches V1.",
     [("car", "go_straight", "ego"), ("truck", "change_lane_to_left", "front_right")]),
    ("The car behind me clipped my right rear bumper.", [("car", "go_straight", "back"), ("car", "go_straight", "ego")]),
    ("A pickup behind the ego taps the ego's left rear bumper.", [("car", "go_straight", "back"),
                                                                  ("car", "go_straight", "ego")]),
])
def test_a_side_that_names_a_vehicles_part_places_no_one(prompt, expected):
    assert agents(prompt) == sorted(expected)


# -- the road a report describes ----------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, lanes", [
    ("Divided highway, two northbound lanes, posted 55 mph. The ego is in the left lane.", 2),
    ("Four westbound lanes at the approach; the ego is in lane 3.", 4),
    ("An arterial with three eastbound lanes and a bus stopped in the curb lane.", 3),
])
def test_lanes_counted_by_their_heading_are_the_lanes_of_one_direction(prompt, lanes):
    assert lower(prompt).scenario.road.lanes == lanes


@pytest.mark.parametrize("prompt", [
    "Two-way stop: CR 12 approaches are stop-sign controlled and the ego is on the through road.",
    "SH 6 is signed as the priority road, FM 1960 approaches are yield controlled.",
])
def test_a_county_or_state_roads_number_limits_no_speed(prompt):
    objects = lower(prompt).scenario.road.required_objects
    assert not [o for o in objects if o in ("speed_12", "speed_6", "speed_1960")]


# -- a heading that names the case ---------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("Cyclist conflict, urban junction. The ego turns right while a courier on a bike goes straight on its right.",
     [("car", "turn_right", "ego"), ("cyclist", "go_straight", "right")]),
    ("Rear-end scenario, truck braking. The ego follows a delivery truck that brakes hard.",
     [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
    ("Pre-crash reconstruction, emergency vehicle approach. V2, a fire engine, comes up behind V1 (ego).",
     [("car", "go_straight", "ego"), ("firetruck", "go_straight", "back")]),
    ("Rear-end, lead vehicle decelerating. Ego following a city bus at 40 km/h; bus brakes for a stop. Clear.",
     [("bus", "stop", "front"), ("car", "go_straight", "ego")]),
    ("Lead vehicle stopped, rural road. Ego approaches a broken-down tractor at 50 km/h.",
     [("car", "go_straight", "ego"), ("truck", "stop", "front")]),
    ("Vehicle(s) not making a maneuver, opposite direction. Ego straight; oncoming truck drifts over the center "
     "line.", [("car", "go_straight", "ego"), ("truck", "go_straight", "front_left")]),
    ("Bus(es) Stopped Ahead. The ego waits behind a school bus.", [("bus", "stop", "front"),
                                                                  ("car", "stop", "ego")]),
])
def test_a_heading_that_names_the_case_by_its_agent_adds_no_agent(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_agents_named_after_a_heading_keep_their_own_places():
    # the heading's agent gives way to the police car; the pedestrian after it is another agent with its own place
    found = agents("Case summary, emergency vehicle passing. V1 (ego) waits in the right lane. V2, a police car, "
                   "approaches from behind V1 in the left lane. Ped 1 stands on the sidewalk to V1's right.")
    assert found == sorted([("car", "stop", "ego"), ("police", "go_straight", "back_left"),
                            ("pedestrian", "on_the_sidewalk", "right")])


@pytest.mark.parametrize("prompt, expected", [
    ("Cut-in risk: a van travels in the ego's blind spot on the right while the ego merges right.",
     ("car", "go_straight", "back_right")),
    ("Motorcycle in the ego's blind spot (right rear); ego changes lanes to the right.",
     ("motorcycle", "go_straight", "back_right")),
    ("A scooter lurks in my blind spot, left side, as I change lanes to the left.",
     ("motorcycle", "go_straight", "back_left")),
])
def test_the_egos_blind_spot_is_behind_it_in_the_lane_beside(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, line", [
    ("At the four-way stop the ego waits at the line while a pickup crosses from the left.", True),
    ("Ego stopped at the white line as two children crossed.", True),
    ("The ego is at the line when the light turns green.", True),
    ("The ego waits at the line of parked cars for a gap.", False),
    ("Three cars wait in line at the junction.", False),
])
def test_stopping_at_the_line_is_at_the_stop_line(prompt, line):
    assert ("stop_line" in lower(prompt).scenario.road.required_objects) == line


@pytest.mark.parametrize("prompt, expected", [
    ("Unit 1 (ego) waits at the light. Unit 2 and Unit 3, two cyclists, cross from the right; Unit 3 stops in the "
     "middle.", [("car", "stop", "ego"), ("cyclist", "cross_the_road", "road_of_right_turn"),
                 ("cyclist", "cross_the_road", "road_of_right_turn")]),
    ("V1 (ego) follows V2, V3 and V4, three school buses in a line, at 30 mph.",
     [("bus", "go_straight", "front")] * 3 + [("car", "go_straight", "ego")]),
    ("The ego in the left lane passes V2 and V3, two tankers in the right lane ahead, 20 m apart. V3 brakes.",
     [("car", "go_straight", "ego"), ("truck", "go_straight", "front_right"), ("truck", "stop", "front_right")]),
])
def test_designations_listed_before_a_counted_noun_are_its_members(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_in_tandem_is_how_they_travel_not_a_tandem_bicycle():
    assert agents("Two motorcycles ride in tandem behind the ego.") == sorted(
        [("car", "go_straight", "ego"), ("motorcycle", "go_straight", "back"), ("motorcycle", "go_straight", "back")])


@pytest.mark.parametrize("prompt, expected", [
    ("Cut-in from left at 60 mph. Sedan in left lane moves into ego lane just ahead.",
     [("car", "change_lane_to_right", "front_left"), ("car", "go_straight", "ego")]),
    ("Cut-in from right lane. A white van swerves in front of the ego.",
     [("car", "change_lane_to_left", "right"), ("car", "go_straight", "ego")]),
    ("Aggressive cut-in from the right lane ahead.", [("car", "change_lane_to_left", "front_right"),
                                                      ("car", "go_straight", "ego")]),
])
def test_a_heading_that_says_only_what_was_done_is_done_by_the_vehicle_named_next(prompt, expected):
    assert agents(prompt) == sorted(expected)


# -- crash-typology names -------------------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("LTAP/OD, urban signal. Ego turns left on a green ball while a minivan proceeds straight.",
     ("car", "go_straight", "road_of_straight")),
    ("SCP at a two-way stop: ego straight through, pickup straight through.", ("car", "go_straight",
                                                                               "road_of_left_turn")),
    ("Lead vehicle stopped scenario. The ego approaches a delivery truck in its lane at 35 mph.",
     ("truck", "stop", "front")),
    ("LVS on a rural road: ego approaching at 45 mph, a pickup in its lane.", ("car", "stop", "front")),
])
def test_a_crash_type_places_the_one_other_vehicle_the_text_leaves_unplaced(prompt, expected):
    assert expected in agents(prompt)


def test_a_crash_type_leaves_a_vehicle_the_text_places_where_it_is():
    found = agents("LTAP/OD at signal. Ego turns left; a bus waits on the road to the right.")
    assert ("bus", "stop", "road_of_right_turn") in found


@pytest.mark.parametrize("prompt, expected", [
    ("VRU: e-scooter rider crossing from the left at crosswalk, ego turning left. Rain.",
     [("car", "turn_left", "ego"), ("cyclist", "go_straight", "road_of_left_turn")]),
    ("Ego turns right; VRU (cyclist) going straight on the right.",
     [("car", "turn_right", "ego"), ("cyclist", "go_straight", "right")]),
    ("VRU crossing at the crosswalk. Ego turning right. Drizzle.",
     [("car", "turn_right", "ego"), ("pedestrian", "cross_the_road", "near_the_crosswalk")]),
])
def test_a_vru_is_the_walker_or_rider_the_text_says_it_is(prompt, expected):
    assert agents(prompt) == sorted(expected)


@pytest.mark.parametrize("prompt", [
    "Animal crossing, rural. Deer from the right, ego straight at 50 mph, night.",
    "A deer crossing sign is on the right; the ego drives past at night.",
])
def test_an_animal_crossing_is_no_pedestrian_crossing(prompt):
    assert "crosswalk" not in lower(prompt).scenario.road.required_objects


@pytest.mark.parametrize("prompt, expected", [
    ("V1 (ego) is southbound. V2 is eastbound on Oak St and V3 is westbound on Oak St; both enter the intersection.",
     [("car", "go_straight", "ego"), ("car", "go_straight", "road_of_left_turn"),
      ("car", "go_straight", "road_of_right_turn")]),
    ("Unit 1 (ego) heads north. Unit 2 is parked ahead and Unit 3 is stopped behind Unit 1.",
     [("car", "go_straight", "ego"), ("car", "stop", "back"), ("car", "stop", "front")]),
])
def test_a_named_vehicle_after_and_starts_its_own_clause(prompt, expected):
    assert agents(prompt) == sorted(expected)


@pytest.mark.parametrize("prompt, count", [
    ("Ped crossing at midblock, no crosswalk, 2 peds from the right. Ego 25 mph. Dusk.", 3),
    ("Jaywalker at mid-block, night, a teenager from the left, ego at 30 mph.", 2),
    ("Ped crossing at the zebra, another ped waiting on the kerb.", 3),  # another: a second one
    ("Car stops ahead, a car passes on the left.", 3),  # a sentence, no heading
])
def test_a_one_line_notes_first_item_heads_it(prompt, count):
    assert len(agents(prompt)) == count


@pytest.mark.parametrize("prompt, expected", [
    ("V1 (ego), 2017 Kia Soul, is westbound. V2, Dodge Ram 2500 pickup, is stopped ahead of V1.",
     [("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("Ped 1, 8-year-old boy, runs across in front of Unit 1 (ego).",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front")]),
    ("Unit 2, city bus, pulls out from stop on right ahead of Unit 1 (ego), eastbound.",
     [("bus", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]),
])
def test_a_designations_apposition_without_its_article_says_what_it_is(prompt, expected):
    assert agents(prompt) == sorted(expected)


@pytest.mark.parametrize("prompt, expected", [
    ("The ego is in lane 2 (center). V2, a truck in lane 3 (left lane) just ahead, makes a lane change to the right "
     "into lane 2.", ("truck", "change_lane_to_right", "front_left")),
    ("Lanes are numbered from the median. A van in lane 1 moves over to the left into lane 2 ahead of the ego.",
     ("car", "change_lane_to_left", "front")),
])
def test_a_lane_change_said_with_its_side_keeps_it_whatever_the_lane_numbers(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("Veh. 1 (ego) was eastbound. Veh. 2, a pickup, was westbound and turned left across Veh. 1's path.",
     [("car", "go_straight", "ego"), ("car", "turn_left", "road_of_straight")]),
    ("V-1 (ego) stopped at the light. V-2, a cyclist, passed V-1 on the right.",
     [("car", "stop", "ego"), ("cyclist", "go_straight", "back_right")]),
])
def test_a_reports_designations_are_one_name_however_spelt(prompt, expected):
    assert agents(prompt) == sorted(expected)


@pytest.mark.parametrize("prompt, expected", [
    ("A tanker is in the curb lane beside me.", ("truck", "go_straight", "right")),
    ("V1 (ego) is in the curb lane. V2, a sedan, is in the median lane beside V1.", ("car", "go_straight", "left")),
    ("On the motorway a lorry is in the kerb lane beside us.", ("truck", "go_straight", "left")),  # keeps left
    ("V1 (ego) is northbound. V2 was making a left turn from the opposing left-turn lane.",
     ("car", "turn_left", "road_of_straight")),
])
def test_lanes_named_by_their_edge_or_direction_place_who_is_in_them(prompt, expected):
    assert expected in agents(prompt)


@pytest.mark.parametrize("prompt, expected", [
    ("V1 (ego) is westbound approaching the intersection. Ped 1 is standing on the northeast corner.",
     ("pedestrian", "on_the_sidewalk", "front_right")),
    ("The ego is eastbound at the crossroads; a woman waits on the north-west corner.",
     ("pedestrian", "on_the_sidewalk", "front_left")),
])
def test_a_junctions_corner_by_the_compass_is_on_the_egos_side_of_it(prompt, expected):
    assert expected in agents(prompt)
