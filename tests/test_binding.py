"""Binding: a road is given to a scene only where every agent can do what it is asked to."""

from __future__ import annotations

import itertools

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


def test_a_walker_on_the_sidewalk_by_a_crosswalk_walks_away_from_the_junction_when_that_way_is_short():
    """The crosswalk lies at the junction end: along the driving direction there were 1 to 6 m of sidewalk
    left, a step the judge rightly failed as no walk; it takes the way with room."""
    scene = parse('scenario "w"\nroad {\n    has crosswalk\n}\nstage main {\n    ego car go_straight\n'
                  '    pedestrian p1 at near_the_crosswalk on_the_sidewalk\n}\n')
    walks = [next(a for a in bound.agents if a.name == "p1") for bound in
             itertools.islice(candidates(scene, load_library(["builtin"])), 8)]
    assert len(walks) == 8 and all(abs(p.walk_to.s - p.start.s) >= 15 for p in walks)


def test_people_waiting_to_cross_stand_at_the_kerb_and_a_walker_passes_them_on_the_outer_half():
    """A walker along the pavement walked through the people waiting on it to cross (a collision of two
    pedestrians in both players); people keep to one side of a pavement, so the two halves never meet."""
    from ttsgc.vocabulary import BODIES

    scene = parse('scenario "w"\nstage main {\n    ego car go_straight\n    pedestrian p1 at front cross_the_road\n'
                  '    pedestrian p2 at front_right on_the_sidewalk\n}\n')
    bound = next(iter(candidates(scene, load_library(["builtin"]))))
    crosser, walker = bound.agent("p1"), bound.agent("p2")
    assert (crosser.start.road, crosser.start.lane) == (walker.start.road, walker.start.lane)  # the same pavement
    outward = -1 if walker.start.lane < 0 else 1  # t grows to the left of the reference line
    assert walker.start.offset * outward > 0 > crosser.start.offset * outward
    assert walker.walk_to.offset == walker.start.offset  # the whole walk, not its first step
    assert abs(walker.start.offset - crosser.start.offset) >= BODIES["pedestrian"][1]


def test_two_people_walking_one_behind_the_other_end_their_walk_apart():
    """Where the sidewalk ends before a whole walk, both walks used to stop at its end, and the one behind
    walked into the one ahead (a collision in both players): the ends keep the gap the starts had."""
    scene = parse('scenario "w"\nroad {\n    at junction\n    has stop\n}\nstage main {\n    ego car go_straight\n'
                  '    pedestrian p1 at right on_the_sidewalk\n    pedestrian p2 at right on_the_sidewalk behind p1\n}\n')
    checked = 0
    for bound in itertools.islice(candidates(scene, load_library(["builtin"])), 6):
        p1, p2 = bound.agent("p1"), bound.agent("p2")
        if (p1.start.road, p1.start.lane) != (p2.start.road, p2.start.lane):
            continue
        forward = 1 if p1.walk_to.s >= p1.start.s else -1
        assert forward * (p1.start.s - p2.start.s) > 0  # p2 starts behind
        assert forward * (p1.walk_to.s - p2.walk_to.s) >= min(forward * (p1.start.s - p2.start.s), 2.0) - 1e-6
        assert p2.speed_mps <= p1.speed_mps
        checked += 1
    assert checked
