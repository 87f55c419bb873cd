"""Road synthesis: a map built for a scene has exactly what its road block asks and what its agents need,
converts cleanly, passes the ASAM checker, and hosts the scene in SUMO."""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from conftest import EXAMPLES, ROOT, asam_errors
from ttsgc import vocabulary as V
from ttsgc.cli import main
from ttsgc.language import parse, parse_file
from ttsgc.pipeline import compile_and_prove
from ttsgc.roads import load_index, retrieve
from ttsgc.roads.synth import SynthesisError, design, needs_of, synthesize
from ttsgc.scenario import Agent, RoadSpec, Scenario, Stage

LINES = ("dashed_single_white", "solid_single_white")
MARKINGS = ("crosswalk", "ladder_crosswalk", "continental_crosswalk", "parallel_open_crosswalk", "stop_line",
            "stop_sign_on_road") + LINES


def _choose(draw, words) -> tuple[list[str], list[str]]:
    """Each word required, forbidden or not mentioned."""
    required, forbidden = [], []
    for word in words:
        fate = draw(st.sampled_from(["has", "without", "-", "-"]))
        (required if fate == "has" else forbidden if fate == "without" else []).append(word)
    return required, forbidden


# Agents whose actions a road can show (the simulator proves them); the position and road type each needs.
DRIVERS = [("car", "go_straight", "front"), ("car", "stop", "front_left"), ("truck", "go_straight", "back"),
           ("car", "change_lane_to_right", "left"), ("motorcycle", "go_straight", "back_right"),
           ("truck", "stop", "front_right", "shoulder")]
AT_JUNCTION = [("car", "go_straight", "road_of_straight"), ("car", "turn_left", "road_of_straight"),
               ("bus", "turn_right", "road_of_left_turn"), ("car", "go_straight", "road_of_right_turn"),
               ("car", "go_straight", "at_the_destination")]
PEOPLE = [("pedestrian", "cross_the_road", "near_the_crosswalk"), ("pedestrian", "on_the_sidewalk", "right"),
          ("pedestrian", "stop", "front_right", "shoulder")]


@st.composite
def scenes(draw) -> Scenario:
    junction = draw(st.sampled_from([None, True, False]))
    signals, no_signals = _choose(draw, list(V.SIGNALS))
    objects, no_objects = _choose(draw, MARKINGS)
    speeds = draw(st.lists(st.integers(*V.SPEED_SIGN_LIMITS), max_size=2, unique=True))
    objects += [f"speed_{n}" for n in speeds]
    no_objects += [f"speed_{n}" for n in draw(st.lists(st.integers(*V.SPEED_SIGN_LIMITS), max_size=1))
                   if n not in speeds]
    ego_actions = ["go_straight", "stop", "change_lane_to_left", "change_lane_to_right"]
    if junction is not False:
        ego_actions += ["turn_left", "turn_right"]
    kinds = DRIVERS + PEOPLE + (AT_JUNCTION if junction is not False else [])
    if any(w in objects for w in V.CROSSWALK_OBJECTS) and "crosswalk" in no_objects:
        no_objects.remove("crosswalk")  # a contradiction (test_contradictions)
    if "crosswalk" in no_objects:
        kinds = [k for k in kinds if k[2] != "near_the_crosswalk"]
    agents = [Agent(name="ego", type=draw(st.sampled_from(["car", "car", "truck", "bus"])), is_ego=True,
                    action=draw(st.sampled_from(ego_actions)))]
    for k, kind in enumerate(draw(st.lists(st.sampled_from(kinds), max_size=3, unique=True))):
        agents.append(Agent(name=f"a{k}", type=kind[0], action=kind[1], relative_to_ego=kind[2],
                            road_type=kind[3] if len(kind) > 3 else V.default_road_type(kind[0])))
    road = RoadSpec(lanes=draw(st.integers(*V.LANES_RANGE)), junction=junction,
                    required_signals=tuple(signals), without_signals=tuple(no_signals),
                    required_objects=tuple(objects), without_objects=tuple(no_objects))
    return Scenario(name="drawn", road=road, stages=(Stage(name="one", agents=tuple(agents)),))


def words_of(approach) -> set[str]:
    return set(approach.signals) | set(approach.objects)


def check_synthesised(scenario: Scenario, seed: int, folder: Path) -> None:
    """The map has what was asked (on the scene's approach) and nothing forbidden (anywhere), converts without
    a warning, passes the ASAM checker, and the scene binds with every requirement met and proves in SUMO."""
    from ttsgc.simulate.network import convert

    d, data = synthesize(scenario, seed)
    path = folder / f"{d.name}.xodr"
    path.write_bytes(data)
    index = load_index(path)
    road, needs = scenario.road, needs_of(scenario)
    ego = index.by_id[d.ego_approach]
    asked = set(road.required_signals) | set(road.required_objects)
    assert asked <= words_of(ego), asked - words_of(ego)
    forbidden = set(road.without_signals) | set(road.without_objects)
    for approach in index.approaches:
        assert not forbidden & words_of(approach), (approach.id, forbidden & words_of(approach))
    assert ego.lanes == max(needs.lanes, 1 + sum(w in asked for w in LINES)) >= road.lanes
    if road.junction is not None:
        assert (ego.junction is not None) == road.junction
    if needs.movement:
        assert ego.turns_to(needs.movement)
    speeds = sorted(int(w[6:]) for w in asked if w.startswith("speed_"))
    if len(speeds) == 1:
        assert ego.speed_limit_kmh == speeds[0]
    assert ego in retrieve([index], road)
    assert convert(path, folder / "net.xml") == []
    assert asam_errors("qc_opendrive", "xodrBundle", path, folder) == []
    compiled, report = compile_and_prove(scenario, folder / "scene.xosc", maps=[path], seed=seed, log=lambda m: None)
    assert compiled.scene.unmet == (), compiled.scene.explanation
    assert report.ok, report.table()


# Derandomised: the same examples on every run. No shrinking: each example runs SUMO, and a failure prints
# its scene whole.
COMMON = dict(deadline=None, derandomize=True, phases=[Phase.explicit, Phase.generate],
              suppress_health_check=[HealthCheck.too_slow])


@settings(max_examples=10, **COMMON)
@given(scene=scenes(), seed=st.integers(0, 2**32 - 1))
def test_synthesised_maps_have_what_was_asked_and_host_the_scene(scene, seed):
    with tempfile.TemporaryDirectory() as folder:
        check_synthesised(scene, seed, Path(folder))


@pytest.mark.slow
@settings(max_examples=150, **COMMON)
@given(scene=scenes(), seed=st.integers(0, 2**32 - 1))
def test_synthesised_maps_many(scene, seed):
    with tempfile.TemporaryDirectory() as folder:
        check_synthesised(scene, seed, Path(folder))
