"""Reading a scene typed as a terse list ('ego bus, lead car braking, two pedestrians crossing') or as notes, one
agent a line ('Van: stopped, front'): each item after the ego is an agent of its own, never a second name for the
ego nor the same agent said again."""

from __future__ import annotations

import random
from collections import Counter

import pytest

from ttsgc.lowering.offline import lower


def agents(prompt: str) -> list[tuple[str, str, str]]:
    """(type, action, position) of every agent, the ego as position 'ego'."""
    return sorted((a.type, a.action, a.relative_to_ego or "ego") for a in lower(prompt).scenario.agents())


@pytest.mark.parametrize("prompt, expected", [
    ("Ego bus, lead car braking.", [("bus", "go_straight", "ego"), ("car", "stop", "front")]),
    ("Ego van, oncoming truck turning left.", [("car", "go_straight", "ego"), ("truck", "turn_left", "road_of_straight")]),
    ("ego car, a cyclist on the right, a truck ahead braking",
     [("car", "go_straight", "ego"), ("cyclist", "go_straight", "right"), ("truck", "stop", "front")]),
    ("the ego vehicle, a pedestrian, and a truck",
     [("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front"), ("truck", "go_straight", "front")]),
    ("ego, a bus behind, child running out from the left",
     [("bus", "go_straight", "back"), ("car", "go_straight", "ego"), ("pedestrian", "cross_the_road", "front_left")]),
    ("ego bus, ambulance approaching from behind", [("ambulance", "go_straight", "back"), ("bus", "go_straight", "ego")]),
    ("Ego: a sedan. A van pulls out from the right.",
     [("car", "change_lane_to_left", "front_right"), ("car", "go_straight", "ego")]),
])
def test_a_noun_after_the_egos_comma_that_is_placed_or_does_something_is_another_agent(prompt, expected):
    assert agents(prompt) == sorted(expected)


@pytest.mark.parametrize("prompt, ego_type", [
    ("the ego, a city bus, turns left", "bus"),
    ("Ego (car), pedestrian crossing from the right", "car"),
    ("my vehicle, a grey Vauxhall Astra, was stopped at the lights", "car"),
    ("The ego, sedan, turns left.", "car"),
])
def test_a_noun_set_off_after_the_ego_with_nothing_of_its_own_still_says_what_the_ego_is(prompt, ego_type):
    found = agents(prompt)
    assert [t for t, _, where in found if where == "ego"] == [ego_type]
    assert all(t in ("pedestrian",) for t, _, where in found if where != "ego")


@pytest.mark.parametrize("prompt, expected", [
    ("ego stopped at the lights, oncoming car turning left, lead car braking",
     [("car", "stop", "ego"), ("car", "stop", "front"), ("car", "turn_left", "road_of_straight")]),
    ("ego going straight. lead car braking. car cutting in from the left lane",
     [("car", "change_lane_to_right", "left"), ("car", "go_straight", "ego"), ("car", "stop", "front")]),
    ("my car changing lanes to the left; car cutting in from the left lane",
     [("car", "change_lane_to_left", "ego"), ("car", "change_lane_to_right", "left")]),
])
def test_a_bare_noun_with_its_own_place_or_another_verb_is_not_the_one_named_before(prompt, expected):
    assert agents(prompt) == sorted(expected)


@pytest.mark.parametrize("prompt, expected", [
    ("ego behind cyclist, cyclist swerves left", 1),  # the cyclist, placed, then what it does
    ("Ego vehicle approaching junction. Vehicle braking.", 0),  # the ego again
])
def test_a_bare_noun_said_again_without_anything_new_is_the_same_one(prompt, expected):
    assert sum(where != "ego" for _, _, where in agents(prompt)) == expected


@pytest.mark.parametrize("prompt, pedestrians", [
    ("ego car going straight; two pedestrians crossing", 2),
    ("3 peds crossing from the left", 3),
    ("ego stops at the pedestrian crossing", 0),
    ("there is no pedestrian crossing, ego goes straight", 0),
])
def test_counted_pedestrians_crossing_are_people_and_a_pedestrian_crossing_is_a_crosswalk(prompt, pedestrians):
    assert sum(t == "pedestrian" for t, _, _ in agents(prompt)) == pedestrians


EGOS = [("ego", "car"), ("ego car", "car"), ("Ego vehicle", "car"), ("the ego", "car"), ("ego bus", "bus"),
        ("ego truck", "truck"), ("Ego (car)", "car"), ("ego: sedan", "car"), ("the ego vehicle", "car"),
        ("my car", "car")]
EGO_DOINGS = ["", " turning left", " going straight", " turns right", " stopped at the lights",
              " changing lanes to the left"]
ITEMS = [("a pedestrian crossing from the right", "pedestrian"), ("cyclist on the right", "cyclist"),
         ("truck ahead braking", "truck"), ("oncoming car turning left", "car"), ("lead car braking", "car"),
         ("a bus behind", "bus"), ("motorcycle overtaking on the left", "motorcycle"), ("parked van on the right", "car"),
         ("ambulance approaching from behind", "ambulance"), ("child running out from the left", "pedestrian"),
         ("car cutting in from the left lane", "car"), ("SUV in front stopping", "car"),
         ("pedestrian waiting on the sidewalk", "pedestrian"), ("a police car coming the other way", "police"),
         ("slow tractor ahead", "truck"), ("bicycle on the right", "cyclist"), ("two pedestrians crossing", "pedestrian"),
         ("a van pulling out from the right", "car")]


def test_every_item_of_a_generated_terse_list_is_one_agent_of_its_type():
    """Lists drawn at random (a fixed seed) from the forms engineers type: the ego with or without its type and
    verb, then one to three items, split by commas, semicolons or full stops."""
    draw = random.Random(7)
    wrong = []
    for _ in range(120):
        ego, ego_type = draw.choice(EGOS)
        items = draw.sample(ITEMS, draw.randint(1, 3))
        sep = draw.choice([", ", "; ", ". "])
        prompt = ego + draw.choice(EGO_DOINGS) + sep + sep.join(text for text, _ in items)
        want = Counter()
        for text, kind in items:
            want[kind] += 2 if text.startswith("two ") else 1
        found = agents(prompt)
        got = Counter(t for t, _, where in found if where != "ego")
        if got != want or [t for t, _, where in found if where == "ego"] != [ego_type]:
            wrong.append((prompt, found))
    assert wrong == []


# -- notes: one agent a line, by key ------------------------------------------------------------------------

@pytest.mark.parametrize("prompt, expected", [
    ("Ego (truck): stopped. Truck: front, stopped.", [("truck", "stop", "ego"), ("truck", "stop", "front")]),
    ("Ego car: braking to a stop. Car: front, stationary.", [("car", "stop", "ego"), ("car", "stop", "front")]),
    ("- Ego: drives straight\n- Police car: left lane, ahead, braking hard\n- Car: ahead, stationary",
     [("car", "go_straight", "ego"), ("car", "stop", "front"), ("police", "stop", "front_left")]),
    ("Ego car: stopped. SUV: braking hard, behind. Truck: in front of ego, braking hard.",
     [("car", "stop", "back"), ("car", "stop", "ego"), ("truck", "stop", "front")]),
    ("Ego (truck): stopped\nAmbulance: going straight, behind ego\nVan: going straight, front",
     [("ambulance", "go_straight", "back"), ("car", "go_straight", "front"), ("truck", "stop", "ego")]),
    ("- Ego car: braking to a stop\n- SUV: braking hard, left lane, ahead\n- Truck: behind ego, going straight",
     [("car", "stop", "ego"), ("car", "stop", "front_left"), ("truck", "go_straight", "back")]),
    ("1. Ego car - braking to a stop\n2. Car - front, stationary\n3. HGV - behind ego, stationary",
     [("car", "stop", "ego"), ("car", "stop", "front"), ("truck", "stop", "back")]),
    ("EGO: drives straight. Cyclist: crossing from the right.",
     [("car", "go_straight", "ego"), ("cyclist", "cross_the_road", "front_right")]),
])
def test_each_key_of_a_note_that_names_an_agent_is_one_agent_where_its_line_puts_it(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_a_key_naming_a_vehicle_said_before_in_the_text_is_that_vehicle():
    found = agents("Desc: double-parked delivery van blocking the ego lane\nEV: approaches and stops behind the van\n"
                   "Van: stationary in EV lane, hazards on, never moves off")
    assert [a for a in found if a[2] != "ego"] == [("car", "block_the_ego", "front")]
