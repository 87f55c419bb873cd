"""Seeded choices for what a sentence leaves open: a scene kind's agents, their types, actions, positions,
behaviours and trigger distances, drawn from per-kind distributions kept as data (templates/kinds/KIND.toml).

Why stratified rather than independent draws: the paper measures diversity over the seeds of one prompt, and
independent draws repeat themselves (five draws from five options repeat one with probability 0.96). So each
list is cycled in an order fixed by a seeded shuffle: any run of consecutive seeds chooses differently, and the
same seed always chooses the same. Seed 0 takes the first entry of every list, the kind's typical scene.

Nothing the sentence says is changed: the kind only fills a scene whose prompt names no agents of its own, and
the lowering keeps the prompt's own ego when it said what the ego does. Every choice is written beside its
agent line as a comment, so the user sees it and can pin it by editing the .tsg.
"""

from __future__ import annotations

import random
import tomllib
import zlib
from collections.abc import Mapping
from contextvars import ContextVar
from dataclasses import dataclass, field

from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.resources import resource_dir
from ttsgc.scenario import Comment, Scenario

NAME_PREFIX = {"car": "c", "truck": "t", "bus": "b", "motorcycle": "m", "cyclist": "k", "pedestrian": "p",
               "ambulance": "a", "police": "po", "firetruck": "f"}


class SamplingError(TtsgcError):
    exit_code = ExitCode.LOWERING_FAILED


@dataclass
class Sampled:
    scenario: Scenario  # the kind's scene for this seed, each agent's choices in its trailing comment
    notes: list[str] = field(default_factory=list)


def kind_file(kind: str):
    return resource_dir("templates") / "kinds" / f"{kind}.toml"


def has_distribution(kind: str) -> bool:
    return kind_file(kind).is_file()


class _Draw:
    """One seed's choices: entry `seed` of each list in its fixed seeded order, entry 0 for seed 0."""

    def __init__(self, kind: str, seed: int):
        self.kind, self.seed = kind, seed

    def order(self, slot: str, n: int) -> list[int]:
        rest = list(range(1, n))
        random.Random(zlib.crc32(f"{self.kind}/{slot}".encode())).shuffle(rest)
        return [0] + rest

    def pick(self, slot: str, options: list):
        if not options:
            raise SamplingError(f"templates/kinds/{self.kind}.toml: '{slot}' has no entries")
        k = self.order(slot, len(options))[self.seed % len(options)]
        return options[k]

    def window(self, slot: str, options: list, count: int) -> list:
        """`count` entries, consecutive seeds taking consecutive, non-overlapping windows of the order."""
        if count <= 0 or not options:
            return []
        order = self.order(slot, len(options))
        start = (self.seed - 1) * count
        return [options[order[(start + j) % len(options)]] for j in range(min(count, len(options)))]

    def number(self, slot: str, low: float, high: float) -> float:
        """Within [low, high]: seeds 1, 2, ... spread over the range in a shuffled order of ten steps."""
        step = self.order(slot, 11)[self.seed % 11]
        return round(low + (high - low) * step / 10.0)

    def rng(self, slot: str) -> random.Random:
        return random.Random(zlib.crc32(f"{self.kind}/{slot}/{self.seed}".encode()))


def sample_kind(kind: str, seed: int) -> Sampled:
    """The scene of a scene kind for one seed, built as .tsg text and parsed, so the language's rules judge it."""
    from ttsgc.language import ScenarioError, parse

    path = kind_file(kind)
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    draw = _Draw(kind, seed)
    behaviours = data.get("behaviours", ["normal"])
    names: dict[str, int] = {}
    lines = [f'scenario "{data.get("name", kind.replace("_", " "))}"']
    weather = data.get("weather")
    if weather:
        lines.append(f"weather {draw.pick('weather', weather)}")
    road = data.get("road", [])
    if road:
        lines += ["road {"] + [f"    {r}" for r in road] + ["}"]
    lines.append("stage main {")
    ego = draw.pick("ego", data["ego"])
    lines.append(f"    ego {ego}")
    chosen: list[tuple[str, str]] = [("ego", f"ego: {ego}" + _of(data["ego"]))]
    roles = list(data.get("agent", []))
    traffic = data.get("traffic")
    if traffic and seed > 0:
        low, high = traffic.get("count", [0, 0])
        count = draw.rng("traffic count").randint(low, high)
        for option in draw.window("traffic", traffic["choose"], count):
            roles.append({"what": traffic.get("what", "other traffic"), "choose": [option]})
    for k, role in enumerate(roles):
        option = draw.pick(f"agent {k}", role["choose"])
        words = option.split()
        agent_type = words[0]
        names[agent_type] = names.get(agent_type, 0) + 1
        name = f"{NAME_PREFIX[agent_type]}{names[agent_type]}"
        said = [f"{role.get('what', 'agent')}: {option}" + _of(role["choose"])]
        extra = []
        if "behaviour" not in role and not set(words) & {"cautious", "normal", "aggressive"} and seed > 0:
            behaviour = draw.pick(f"agent {k} behaviour", behaviours)
            if behaviour != "normal":
                extra.append(behaviour)
            said.append(f"behaviour {behaviour}" + _of(behaviours))
        trigger = role.get("trigger_m")
        if trigger:
            metres = trigger[0] if seed == 0 else draw.number(f"agent {k} trigger", trigger[1], trigger[2])
            extra += ["when", "ego", "within", f"{metres:g}m"]
            said.append(f"trigger {metres:g} m (of {trigger[1]:g}..{trigger[2]:g} m)")
        lines.append("    " + " ".join([agent_type, name] + words[1:] + extra))
        chosen.append((name, "; ".join(said)))
    lines.append("}")
    text = "\n".join(lines) + "\n"
    try:
        scenario = parse(text, str(path))
    except ScenarioError as exc:
        raise SamplingError(f"{path}: the scene drawn for seed {seed} is invalid: {exc}") from exc
    comments = {f"agent.{name}": Comment(trailing=f"sampled {what}") for name, what in chosen}
    notes = [f"the scene kind '{kind}' was asked for: seed {seed} drew its agents from templates/kinds/{kind}.toml"
             " (each choice beside its agent; edit a line to pin it)"]
    return Sampled(scenario.model_copy(update={"comments": comments}), notes)


def _of(options: list) -> str:
    return f" (of {len(options)})" if len(options) > 1 else ""


# -- what a sentence leaves open, in the lowering's own table ---------------------------------------------

_OPEN_SEED: ContextVar[int] = ContextVar("ttsgc_open_seed", default=0)
_OPEN_CHOSEN: ContextVar[list | None] = ContextVar("ttsgc_open_chosen", default=None)


class OpenChoices(Mapping):
    """The lowering's table of what a sentence leaves open (which side a crossing road is on when the text
    does not say, which way "turns" goes...). Seed 0 reads the conventions' values, the table's own; other
    seeds draw from templates/unspecified.toml, each key cycled in a seeded order like a kind's lists. The
    lowering reads it as a plain mapping; `draw_for(seed)` starts one lowering (a context variable, so
    concurrent lowerings do not share a seed) and `chosen()` lists what was drawn, for the scene's comments."""

    def __init__(self, conventions: dict[str, str]):
        self.conventions = dict(conventions)

    def __getitem__(self, key: str) -> str:
        default, seed = self.conventions[key], _OPEN_SEED.get()
        options = [default] + [o for o in _open_options().get(key, []) if o != default]
        value = default if seed == 0 else _Draw("unspecified", seed).pick(key, options)
        chosen = _OPEN_CHOSEN.get()
        if chosen is not None and len(options) > 1 and seed != 0:
            note = f"sampled (seed {seed}): {key.replace('_', ' ')} {value} (of {', '.join(options)})"
            if note not in chosen:
                chosen.append(note)
        return value

    def __iter__(self):
        return iter(self.conventions)

    def __len__(self) -> int:
        return len(self.conventions)

    def agent_type(self, reading: str, mention: int) -> str:
        """The type of an agent named by a general noun ("a vehicle"): the reading for seed 0, else drawn."""
        return self._draw(f"vehicle type {mention}", "type of a vehicle", reading,
                          _open_options().get("type_of_a_vehicle", []))

    def vague_count(self, reading: int, mention: int) -> int:
        """A count said vaguely ("a few cars", "more than ten"): the reading for seed 0, else up to
        `vague_count_spread` more."""
        spread = int(_open_options().get("vague_count_spread", 0))
        return int(self._draw(f"vague count {mention}", "vague count", str(reading),
                              [str(reading + k) for k in range(spread + 1)]))

    def _draw(self, slot: str, what: str, reading: str, options: list[str]) -> str:
        options = [reading] + [o for o in options if o != reading]
        seed = _OPEN_SEED.get()
        value = reading if seed == 0 else _Draw("unspecified", seed).pick(slot, options)
        chosen = _OPEN_CHOSEN.get()
        if chosen is not None and len(options) > 1 and seed != 0:
            chosen.append(f"sampled (seed {seed}): {what} {value} (of {', '.join(options)})")
        return value

    def draw_for(self, seed: int) -> None:
        _OPEN_SEED.set(seed)
        _OPEN_CHOSEN.set([])

    def chosen(self) -> list[str]:
        return list(_OPEN_CHOSEN.get() or [])


def _open_options() -> dict[str, list[str]]:
    path = resource_dir("templates") / "unspecified.toml"
    return tomllib.loads(path.read_text(encoding="utf-8")) if path.is_file() else {}
