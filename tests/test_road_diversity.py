"""Road diversity: equally ranked roads spread over the library by the seed; 'not at junction' as well before
any junction; the paper's count (two directions of one road are one road)."""

from __future__ import annotations

from ttsgc.binding import bind
from ttsgc.binding.place import _Frame
from ttsgc.evaluate import Case, Run, generation_seed, summarize
from ttsgc.language import parse
from ttsgc.roads.opendrive import load_opendrive
from ttsgc.roads.retrieve import JUNCTION_CLEARANCE_M, load_library, retrieve

PLAIN = 'scenario "plain"\nstage s {\n    ego car go_straight\n    car c1 at front go_straight\n}\n'
AWAY = ('scenario "away"\nroad {\n    not at junction\n}\nstage s {\n    ego car go_straight\n'
        '    car c1 at front block_the_ego when ego within 25m\n}\n')


def test_consecutive_seeds_bind_to_different_roads_of_different_maps():
    library = load_library()
    scenes = [bind(parse(PLAIN), library, seed=seed) for seed in range(8)]
    roads = {(s.map_name, s.approach.split(":")[0]) for s in scenes}
    assert len(roads) == 8
    assert len({s.map_name for s in scenes[:4]}) == 4  # dealt one map at a time
    assert bind(parse(PLAIN), library, seed=5).approach == scenes[5].approach  # the same seed, the same road


def test_not_at_junction_admits_a_long_road_ending_at_a_junction_and_keeps_the_scene_well_before_it():
    library = load_library()
    candidates = retrieve(library, parse(AWAY).road)
    assert any(a.junction is not None for a in candidates)
    checked = 0
    for seed in range(6):
        scene = bind(parse(AWAY), library, seed=seed)
        index = next(m for m in library if m.name == scene.map_name)
        approach = index.by_id[scene.approach]
        if approach.junction is None:
            continue
        frame = _Frame.build(approach, load_opendrive(index.path))
        ego, blocker = scene.agent("ego"), scene.agent("c1")
        assert ego.start.road == approach.road == blocker.start.road
        s_to_end = ego.start.s if approach.direction == "backward" else frame.road.length - ego.start.s
        assert s_to_end >= JUNCTION_CLEARANCE_M
        checked += 1
    assert checked


def test_road_diversity_counts_both_directions_of_a_road_once():
    runs = [Run("a", "normal", k, "a", ok=True, road=road) for k, road in
            enumerate(["m 1:fwd", "m 1:bwd", "m 2:fwd", "n 1:fwd"])]
    assert summarize(runs)["RD"] == 0.75


def test_the_plans_of_one_kind_take_consecutive_seeds():
    plans = [Case(f"k/{n}", "normal", group="k", plan=__file__, generation=n) for n in range(5)]
    assert [generation_seed(c, 0) for c in plans] == [0, 1, 2, 3, 4]
    assert generation_seed(Case("p", "normal", prompt=__file__), 3) == 3


def test_no_vehicle_starts_on_a_lane_still_opening(shared):
    """Town06 road 15: lane -3 widens from nothing; 12 m in it is 1.4 m wide (SUMO admits no car there)."""
    odr = load_opendrive(shared / "maps" / "carla" / "Town06.xodr")
    index = next(m for m in load_library([shared / "maps" / "carla" / "Town06.xodr"]))
    frame = _Frame.build(index.by_id["15:fwd"], odr)
    u = frame.u_on_approach(12.25)
    assert -3 not in frame.lanes_at(u) and -4 in frame.lanes_at(u)
    assert -3 in frame.lanes_at(frame.u_on_approach(80.0))


def test_a_crossing_away_from_a_junction_is_mid_block():
    """'not at junction' with a pedestrian by the crossing: a mid-block crossing, never one at a junction's mouth."""
    from ttsgc.binding.rank import mid_block

    library = load_library()
    scene_text = ('scenario "mid-block"\nroad {\n    not at junction\n}\nstage s {\n    ego car go_straight\n'
                  '    pedestrian p1 at near_the_crosswalk cross_the_road when ego within 20m\n}\n')
    for seed in range(4):
        scene = bind(parse(scene_text), library, seed=seed)
        approach = next(m for m in library if m.name == scene.map_name).by_id[scene.approach]
        assert any(mid_block(approach, u) for u in approach.crosswalks), (scene.map_name, scene.approach)
