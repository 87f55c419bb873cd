"""Road choice spreads over every fitting road of every map for different seeds, even when each seed's scene
(what the prompt leaves open is sampled per seed) ties on a different set of roads."""

from __future__ import annotations

from itertools import permutations
from pathlib import Path
from types import SimpleNamespace

import pytest

from conftest import EXAMPLES
from ttsgc.binding import bind
from ttsgc.binding.rank import rank, spread
from ttsgc.evaluate import road_of
from ttsgc.lowering import lower_prompt
from ttsgc.roads.retrieve import load_library, retrieve

SEEDS = range(5)


def _roads(maps: int, per_map: int) -> list:
    """Stand-ins for ranked candidates: one approach per road, `per_map` roads on each of `maps` maps."""
    return [SimpleNamespace(index=SimpleNamespace(name=f"map{m}"),
                            approach=SimpleNamespace(id=f"{r}:fwd", road=str(r)))
            for m in range(maps) for r in range(per_map)]


def _first(tied, seed: int) -> tuple[str, str]:
    chosen = spread(tied, seed, "scene")[0]
    return chosen.index.name, chosen.approach.road


@pytest.mark.parametrize("maps, per_map", [(4, 12), (6, 5), (3, 30)])
def test_a_seed_whose_scene_rules_out_one_map_takes_another_road_than_every_other_seed(maps, per_map):
    """One seed's scene fits every road, another's every road but those of one map (a sampled agent needs what
    that map lacks): the five seeds still start on five roads. Dealing seed s the s-th road of its own deal,
    the smaller deal's road 1 was the larger deal's road 2 when the map left out was dealt second."""
    every = _roads(maps, per_map)
    for left_out in {r.index.name for r in every}:
        fewer = [r for r in every if r.index.name != left_out]
        for s, t in permutations(SEEDS, 2):
            assert _first(every, s) != _first(fewer, t), (left_out, s, t)


@pytest.mark.parametrize("n", range(1, 9))
def test_one_set_of_roads_gives_as_many_roads_as_it_has_to_five_seeds(n):
    tied = _roads(maps=1, per_map=n)
    assert len({_first(tied, seed) for seed in SEEDS}) == min(n, 5)


def test_a_seed_whose_road_fails_tries_roads_no_other_seed_starts_on():
    """When the scene cannot be proven on a seed's road, the next roads it tries are not the roads the other
    seeds start on (with the deal's step as the next road, seed s fell back onto seed s + 1's road)."""
    tied = _roads(maps=5, per_map=8)
    starts = {_first(tied, seed) for seed in SEEDS}
    for seed in SEEDS:
        order = [(r.index.name, r.approach.road) for r in spread(tied, seed, "scene")]
        assert not set(order[1:3]) & starts, seed


def _bound_roads(prompt: Path, library) -> set[str]:
    roads = set()
    for seed in SEEDS:
        scene = bind(lower_prompt(prompt.read_text(), "offline", seed=seed).scenario, library, seed=seed)
        roads.add(road_of(f"{scene.map_name} {scene.approach}"))
    return roads


def _fitting_roads(prompt: Path, library) -> int:
    """The fewest best-ranked roads any seed's scene has (the most different roads five seeds can take)."""
    fewest = None
    for seed in SEEDS:
        scenario = lower_prompt(prompt.read_text(), "offline", seed=seed).scenario
        retrieved = {id(a) for a in retrieve(library, scenario.road)}
        pool = [(a, m) for m in library for a in m.approaches if id(a) in retrieved]
        _, ranked = rank(scenario, pool, seed)
        best = {(r.index.name, r.approach.road) for r in ranked if r.score == ranked[0].score}
        fewest = len(best) if fewest is None else min(fewest, len(best))
    return fewest


def test_every_example_prompt_binds_its_five_seeds_to_as_many_roads_as_fit():
    """Bound without playing: each prompt's five seeds take five roads, or every road that fits when fewer do
    (on the built-in library school_zone fits four roads, yield_sudden_stop two)."""
    library = load_library()
    for prompt in sorted(EXAMPLES.glob("*.txt")):
        assert len(_bound_roads(prompt, library)) == min(5, _fitting_roads(prompt, library)), prompt.stem


def test_with_the_carla_towns_every_example_prompt_binds_five_seeds_to_five_roads(shared):
    library = load_library(["builtin", shared / "maps" / "carla"])
    for prompt in sorted(EXAMPLES.glob("*.txt")):
        assert len(_bound_roads(prompt, library)) == 5, prompt.stem
