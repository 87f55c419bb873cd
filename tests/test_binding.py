"""Binding: a road is given to a scene only where every agent can do what it is asked to."""

from __future__ import annotations

from ttsgc.binding.scene import candidates
from ttsgc.language import parse
from ttsgc.roads import load_library

TURNING_FROM_THE_LEFT_ROAD = """scenario "police turns from the left road"
road {
    at junction
}
stage main {
    ego car turn_left
    police po1 at road_of_left_turn turn_left
}
"""


def test_an_agent_that_turns_is_never_placed_on_a_road_without_that_turn():
    """Where the best road fails in simulation the next-ranked roads are tried; one whose left road offers no
    left turn (the stem of a T-junction) must not be among them: the police car there could only drive on."""
    scenario = parse(TURNING_FROM_THE_LEFT_ROAD, "turn.tsg")
    scenes = list(candidates(scenario, load_library(None), seed=0))
    assert scenes
    for scene in scenes:
        assert scene.agent("po1").movement == "left", (scene.map_name, scene.approach, scene.unmet)

TURNING_AHEAD_OF_THE_EGO = """scenario "a car ahead turns left"
road {
    lanes >= 2
}
stage main {
    ego car go_straight
    car c1 at front_left turn_left
}
"""


def test_an_agent_on_the_egos_road_that_turns_gets_a_road_with_that_turn():
    """A turn on the ego's road needs the ego's approach to offer it: ranked for, and never placed without."""
    scenario = parse(TURNING_AHEAD_OF_THE_EGO, "ahead.tsg")
    scenes = list(candidates(scenario, load_library(None), seed=0))
    assert scenes and not scenes[0].unmet
    for scene in scenes:
        assert scene.agent("c1").movement == "left", (scene.map_name, scene.approach, scene.unmet)
