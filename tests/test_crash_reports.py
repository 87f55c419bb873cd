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
])
def test_a_designation_said_to_be_the_ego_is_the_ego_wherever_it_is_named(prompt, expected):
    assert agents(prompt) == sorted(expected)


def test_the_designated_egos_bracket_describes_it_and_its_name_is_replaced_everywhere():
    told = read_narration("V1 (ego, 2019 Ford Escape) brakes. V2 hits V1's rear.").text
    assert told == "The ego, a 2019 Ford Escape, brakes. V2 hits the ego's rear."
    assert read_narration("V12 turns left. V1 waits.").text == "V12 turns left. V1 waits."  # no ego said: as written


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
