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
from ttsgc.roads.synth import design, needs_of, synthesize
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
# A scene is vehicles, or people (with a vehicle parked on the shoulder): SUMO's drivers do not see people.
DRIVERS = [("car", "go_straight", "front"), ("car", "stop", "front_left"), ("truck", "go_straight", "back"),
           ("car", "change_lane_to_right", "back_left"), ("motorcycle", "go_straight", "back_right")]
AT_JUNCTION = [("car", "go_straight", "road_of_straight"), ("car", "turn_left", "road_of_straight"),
               ("bus", "turn_right", "road_of_left_turn"), ("car", "go_straight", "road_of_right_turn"),
               ("car", "go_straight", "at_the_destination")]
PEOPLE = [("pedestrian", "cross_the_road", "near_the_crosswalk"), ("pedestrian", "on_the_sidewalk", "right"),
          ("pedestrian", "stop", "front_right", "shoulder"), ("truck", "stop", "front_right", "shoulder")]
CROSS_TRAFFIC_KMH = 80  # above it, traffic crossing the junction cannot yield in time: no agents there


@st.composite
def scenes(draw) -> Scenario:
    junction = draw(st.sampled_from([None, True, False]))
    signals, no_signals = _choose(draw, list(V.SIGNALS))
    objects, no_objects = _choose(draw, MARKINGS)
    speeds = draw(st.lists(st.integers(*V.SPEED_SIGN_LIMITS), max_size=2, unique=True))
    objects += [f"speed_{n}" for n in speeds]
    no_objects += [f"speed_{n}" for n in draw(st.lists(st.integers(*V.SPEED_SIGN_LIMITS), max_size=1))
                   if n not in speeds]
    if any(w in objects for w in V.CROSSWALK_OBJECTS) and "crosswalk" in no_objects:
        no_objects.remove("crosswalk")  # a contradiction (test_a_contradictory_road_block_is_a_clear_error)
    ego_actions = ["go_straight", "stop", "change_lane_to_left", "change_lane_to_right"]
    if junction is not False:
        ego_actions += ["turn_left", "turn_right"]
    if draw(st.booleans()):
        kinds = DRIVERS + (AT_JUNCTION if junction is not False and max(speeds, default=0) <= CROSS_TRAFFIC_KMH
                           else [])
    else:
        kinds = [k for k in PEOPLE if "crosswalk" not in no_objects or k[2] != "near_the_crosswalk"]
    ego = Agent(name="ego", type=draw(st.sampled_from(["car", "car", "truck", "bus"])), is_ego=True,
                action=draw(st.sampled_from(ego_actions)))
    if ego.action not in ("go_straight", "turn_left", "turn_right"):  # its destination is no junction road
        kinds = [k for k in kinds if k[2] != "at_the_destination"]
    if ego.action == "stop":  # followers at up to 200 km/h would run into it
        kinds = [k for k in kinds if not k[2].startswith("back")]
    agents = [ego]
    drawn = draw(st.lists(st.sampled_from(kinds), max_size=3, unique=True))
    if any(kind[1].startswith("change_lane") for kind in drawn):  # it changes into the ego's lane: keep that free
        drawn = [kind for kind in drawn if kind[2] not in ("front", "back")]
    for k, kind in enumerate(drawn):
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
    from ttsgc.simulate.players.sumo.network import convert

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


# -- the commands ---------------------------------------------------------------------------------------

def readme_example(folder: Path) -> Path:
    """The scene of the README's section on the scenario language, as a file."""
    import re

    text = (ROOT / "README.md").read_text(encoding="utf-8")
    scene = re.search(r"```\n(# Unprotected left turn.*?)```", text, re.S).group(1)
    path = folder / "readme.tsg"
    path.write_text(scene, encoding="utf-8")
    return path


def test_the_readme_example_compiles_on_a_synthesised_road(tmp_path, capsys):
    src = readme_example(tmp_path)
    assert main(["compile", str(src), "-o", str(tmp_path / "never.xosc"), "--synthesize", "never"]) == 4
    assert "none meets 'without stop'" in capsys.readouterr().err
    out = tmp_path / "out" / "readme.xosc"
    assert main(["compile", str(src), "-o", str(out)]) == 0
    err = capsys.readouterr().err
    assert "none meets 'without stop'" in err and "synthesised synth_unprotected_left_turn_7.xodr" in err
    copy = out.parent / "synth_unprotected_left_turn_7.xodr"
    assert sorted(p.name for p in out.parent.iterdir()) == sorted([copy.name, out.name])
    ego = next(a for a in load_index(copy).approaches if a.junction is not None)
    assert "stop_line" in ego.objects and not {"stop", "traffic_light"} & set(ego.signals)


def test_auto_keeps_the_library_when_a_road_fits_and_always_skips_it(tmp_path, capsys):
    scene = EXAMPLES / "stop_sign_right_turn.tsg"
    assert main(["compile", str(scene), "-o", str(tmp_path / "a" / "x.xosc"), "--no-simulate"]) == 0
    assert "synthesised" not in capsys.readouterr().err
    assert not [p for p in (tmp_path / "a").iterdir() if p.name.startswith("synth_")]
    assert main(["compile", str(scene), "-o", str(tmp_path / "b" / "x.xosc"), "--no-simulate",
                 "--synthesize", "always"]) == 0
    assert "--synthesize always; synthesised synth_" in capsys.readouterr().err
    assert [p for p in (tmp_path / "b").iterdir() if p.name.startswith("synth_")]


@pytest.mark.parametrize("road, agent, message", [
    ("has ladder_crosswalk\n    without crosswalk", "", "forbids any crosswalk, but the scene needs ladder_crosswalk"),
    ("without crosswalk", "pedestrian p at near_the_crosswalk cross_the_road",
     "forbids any crosswalk, but the scene needs a crossing near the ego"),
])
def test_a_contradictory_road_block_is_a_clear_error(tmp_path, capsys, road, agent, message):
    src = tmp_path / "x.tsg"
    src.write_text(f'scenario "x"\nroad {{\n    {road}\n}}\nstage s {{\n    ego car go_straight\n    {agent}\n}}\n')
    assert main(["maps", "synth", str(src), "-o", str(tmp_path / "x.xodr")]) == 4
    assert message in capsys.readouterr().err
    assert main(["compile", str(src), "-o", str(tmp_path / "x.xosc")]) == 4
    assert message in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.tsg"]


def test_a_junction_that_is_not_at_a_junction_is_still_an_invalid_scene(tmp_path, capsys):
    src = tmp_path / "x.tsg"
    src.write_text('scenario "x"\nroad {\n    not at junction\n}\nstage s {\n    ego car turn_left\n}\n')
    assert main(["compile", str(src), "-o", str(tmp_path / "x.xosc"), "--synthesize", "always"]) == 2
    assert "'turn_left' needs a junction, but the road block says 'not at junction'" in capsys.readouterr().err


def test_maps_synth_writes_the_map_and_prints_its_approaches(tmp_path, capsys):
    src = readme_example(tmp_path)
    out = tmp_path / "road.xodr"
    assert main(["maps", "synth", str(src), "-o", str(out), "--seed", "3"]) == 0
    printed = capsys.readouterr().out
    assert "synth_unprotected_left_turn_3" in printed and "the scene's approach is 1:bwd" in printed
    assert out.read_bytes() == synthesize(parse_file(src), 3)[1]
    assert main(["maps", "synth", str(src), "-o", str(src)]) == 2
    assert "would overwrite the scene" in capsys.readouterr().err


# -- the design -----------------------------------------------------------------------------------------

def test_synthesis_is_deterministic_and_varies_with_the_seed(tmp_path):
    scene = parse_file(readme_example(tmp_path))
    assert synthesize(scene, 5)[1] == synthesize(scene, 5)[1]
    designs = [design(scene, seed) for seed in range(12)]
    assert len({d.layout for d in designs}) == 2  # the scene fits a 4-way junction and a T
    assert len({round(d.arms[1].angle - d.arms[0].angle, 3) for d in designs}) == 12
    assert len({d.arms[0].length for d in designs}) == 12
    assert len({d.arms[0].bend for d in designs}) == 12
    assert len({d.side.lane_width for d in designs}) > 1


def test_the_layout_offers_every_turn_and_road_the_agents_need():
    scene = parse('scenario "x"\nstage s {\n    ego car turn_left\n    car c at road_of_right_turn turn_left\n'
                  '    car d at road_of_straight go_straight\n}\n')
    for seed in range(8):
        d = design(scene, seed)
        assert d.layout == "fourway"  # a T has no road both to the left and straight ahead
    t_scene = parse('scenario "x"\nstage s {\n    ego car turn_right\n    car c at road_of_left_turn go_straight\n}\n')
    assert {design(t_scene, seed).layout for seed in range(8)} == {"fourway", "tee"}


def test_queues_fit_on_the_synthesised_roads(tmp_path):
    from ttsgc.binding import bind

    cars = "\n    ".join([f"car f{k} at front go_straight gap 30m" for k in range(5)]
                          + [f"truck b{k} at back go_straight gap 20m" for k in range(5)]
                          + [f"bus s{k} at road_of_straight go_straight gap 25m" for k in range(4)])
    scene = parse(f'scenario "queues"\nstage s {{\n    ego car turn_left\n    {cars}\n}}\n')
    d, data = synthesize(scene, 0)
    path = tmp_path / "q.xodr"
    path.write_bytes(data)
    bound = bind(scene, [load_index(path)], seed=0)
    assert bound.unmet == ()


def test_lanes_from_one_to_six_and_lane_lines(tmp_path):
    for lanes in range(1, 7):
        scene = parse(f'scenario "x"\nroad {{\n    lanes >= {lanes}\n    without dashed_single_white\n}}\n'
                      f'stage s {{\n    ego car go_straight\n}}\n')
        d, data = synthesize(scene, lanes)
        path = tmp_path / f"l{lanes}.xodr"
        path.write_bytes(data)
        ego = load_index(path).by_id[d.ego_approach]
        assert ego.lanes == lanes and "dashed_single_white" not in ego.objects
        assert ("solid_single_white" in ego.objects) == (lanes > 1)
