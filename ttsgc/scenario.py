"""The Scenario model: what a .tsg file means, as plain pydantic data.

Every semantic rule of the language lives in `find_problems`, which reports each problem with the path of
the field it concerns (pydantic-style: ("stages", 0, "agents", 2, "action")). The parser maps those paths
back to file:line:col; a Scenario built in code is checked by the same rules through its validator, so an
invalid Scenario cannot exist either way.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Any, Iterator

from pydantic import AfterValidator, BaseModel, ConfigDict, Field, field_validator, model_validator

from ttsgc import vocabulary as V

Path = tuple[Any, ...]

# Lengths, times and speeds are kept to three decimals (millimetres, milliseconds): the language writes
# plain decimals, so every value a Scenario can hold has an exact spelling in a .tsg.
Decimal3 = Annotated[float, AfterValidator(lambda x: round(float(x), 3) + 0.0)]


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class Weather(_Model):
    condition: str = V.DEFAULT_CONDITION
    time: str = V.DEFAULT_TIME


class RoadSpec(_Model):
    """What the road must offer; the retrieval conditions of the paper."""

    lanes: int = 1
    junction: bool | None = None  # None: the scene does not say
    required_signals: tuple[str, ...] = ()
    without_signals: tuple[str, ...] = ()
    required_objects: tuple[str, ...] = ()
    without_objects: tuple[str, ...] = ()


class Speed(_Model):
    value: Decimal3
    unit: str = "km/h"

    @property
    def mps(self) -> float:
        return self.value * V.SPEED_UNITS.get(self.unit, 1.0)


class Trigger(_Model):
    """When the agent's action starts: after a delay, when an entity comes within a distance, or both."""

    after_s: Decimal3 | None = None
    within_m: Decimal3 | None = None
    of: str = "ego"


class Agent(_Model):
    name: str
    type: str
    is_ego: bool = False
    action: str
    behavior: str = V.DEFAULT_BEHAVIOR
    relative_to_ego: str | None = None
    road_type: str = "driving"
    behind: str | None = None
    order: int | None = None  # the paper's pos_id among agents at one position
    gap_m: Decimal3 | None = None
    speed: Speed | None = None
    trigger: Trigger | None = None


class Stage(_Model):
    name: str
    agents: tuple[Agent, ...]


class Comment(_Model):
    """Comments anchored to one statement: whole lines above it, and one at the end of its line."""

    leading: tuple[str, ...] = ()
    trailing: str | None = None


class Scenario(_Model):
    name: str
    seed: int | None = None
    weather: Weather | None = None
    road: RoadSpec = RoadSpec()
    stages: tuple[Stage, ...]
    # Anchors: "scenario", "weather", "seed", "road", "road.lanes", "road.junction", "road.has",
    # "road.without", "road.end", "stage.NAME", "stage.NAME.end", "agent.NAME", "end"; the ego's line in a
    # later stage: "stage.NAME.ego".
    comments: dict[str, Comment] = Field(default_factory=dict, exclude=True)

    @field_validator("comments")
    @classmethod
    def _drop_empty_comments(cls, comments: dict[str, Comment]) -> dict[str, Comment]:
        return {k: c for k, c in sorted(comments.items()) if c.leading or c.trailing is not None}

    @model_validator(mode="after")
    def _check(self) -> "Scenario":
        problems = find_problems(self)
        if problems:
            raise ValueError("; ".join(p.message for p in problems))
        return self

    def agents(self) -> Iterator[Agent]:
        for stage in self.stages:
            yield from stage.agents

    @property
    def ego(self) -> Agent:
        return next(a for a in self.agents() if a.is_ego)

    def to_json(self) -> dict[str, Any]:
        """The documented JSON shape (`ttsgc check --json`), words spelled as in the vocabulary."""
        data = self.model_dump(mode="json")
        for stage, model in zip(data["stages"], self.stages):
            for agent, source in zip(stage["agents"], model.agents):
                if source.speed is not None:
                    agent["speed"]["mps"] = round(source.speed.mps, 6)
        return data


@dataclass(frozen=True)
class Problem:
    path: Path
    message: str


def _choices(words) -> str:
    return ", ".join(sorted(words))


def _unknown(kind: str, word: str, valid) -> str:
    suggestions = V.nearest(word, valid)
    hint = f"; did you mean {V.either(suggestions)}?" if suggestions else f" (one of: {_choices(valid)})"
    return f"unknown {kind} '{word}'{hint}"


def _in_range(value: float, bounds: tuple[float, float]) -> bool:
    return bounds[0] <= value <= bounds[1]


def find_problems(s: Scenario) -> list[Problem]:
    """All semantic problems of a scenario, in source order (as far as the model knows it)."""
    out: list[Problem] = []
    add = lambda path, message: out.append(Problem(tuple(path), message))  # noqa: E731

    if not s.name.strip() or '"' in s.name or "\n" in s.name:
        add(("name",), "the scenario name must be non-empty text on one line without '\"'")
    if s.seed is not None and not 0 <= s.seed < 2**32:
        add(("seed",), f"seed {s.seed} is out of range 0..{2**32 - 1}")
    if s.weather is not None:
        if s.weather.condition not in V.WEATHER_CONDITIONS:
            add(("weather", "condition"), _unknown("weather condition", s.weather.condition, V.WEATHER_CONDITIONS))
        if s.weather.time not in V.TIMES_OF_DAY:
            add(("weather", "time"), _unknown("time of day", s.weather.time, V.TIMES_OF_DAY))
    _road_problems(s.road, add)

    if not s.stages:
        add(("stages",), "a scenario needs at least one stage")
    seen_stages: set[str] = set()
    for i, stage in enumerate(s.stages):
        if stage.name in seen_stages:
            add(("stages", i, "name"), f"stage '{stage.name}' is defined twice")
        seen_stages.add(stage.name)
        if stage.name in V.RESERVED_WORDS:
            add(("stages", i, "name"), f"'{stage.name}' is a keyword and cannot name a stage")
        if not stage.agents:
            add(("stages", i, "name"), f"stage '{stage.name}' has no agents")

    _agent_problems(s, add)
    return out


def _road_problems(road: RoadSpec, add) -> None:
    if not _in_range(road.lanes, V.LANES_RANGE):
        add(("road", "lanes"), f"lanes >= {road.lanes} is out of range {V.LANES_RANGE[0]}..{V.LANES_RANGE[1]}")
    for field, valid, kind in (("required_signals", V.SIGNALS, "signal"), ("without_signals", V.SIGNALS, "signal")):
        for k, word in enumerate(getattr(road, field)):
            if word not in valid:
                add(("road", field, k), _unknown(kind, word, valid))
    for field in ("required_objects", "without_objects"):
        for k, word in enumerate(getattr(road, field)):
            if not V.is_object(word):
                add(("road", field, k), _unknown("road object", word, V.object_words()))
    for kind in ("signals", "objects"):
        forbidden = getattr(road, f"without_{kind}")
        for k, word in enumerate(forbidden):
            if word in getattr(road, f"required_{kind}"):
                add(("road", f"without_{kind}", k), f"'{word}' is both required (has) and forbidden (without)")


def _agent_problems(s: Scenario, add) -> None:
    located = [(i, j, a) for i, st in enumerate(s.stages) for j, a in enumerate(st.agents)]
    by_name: dict[str, Agent] = {}
    egos = [(i, j) for i, j, a in located if a.is_ego]
    if not egos and s.stages:
        add(("stages", 0, "name"), "the scenario has no ego; start an agent line with 'ego', e.g. 'ego car go_straight'")
    if egos and egos[0][0] != 0:
        i, j = egos[0]
        add(("stages", i, "agents", j, "name"), "the ego must be in the first stage: later agents are placed relative to it")
    elif egos:
        _later_ego_problems(s, egos, add)
    if len(located) > V.MAX_AGENTS:
        i, j, _ = located[V.MAX_AGENTS]
        add(("stages", i, "agents", j), f"a scene holds at most {V.MAX_AGENTS} agents, the ego included; this one has "
            f"{len(located)}")
        return
    stage_of = {a.name: i for i, _, a in located}

    for i, j, a in located:
        at = ("stages", i, "agents", j)
        if a.name in by_name and not (a.is_ego and by_name[a.name].is_ego):  # a second ego is reported above
            add(at + ("name",), f"the name '{a.name}' is used twice")
        by_name.setdefault(a.name, a)
        if a.name in V.RESERVED_WORDS and not a.is_ego:
            add(at + ("name",), f"'{a.name}' is a keyword and cannot name an agent")
        if a.type not in V.AGENT_TYPES:
            add(at + ("type",), _unknown("agent type", a.type, V.AGENT_TYPES))
            continue
        if a.is_ego:
            if a.type not in V.EGO_TYPES:
                add(at + ("type",), f"the ego cannot be a {a.type}; it must be one of: {_choices(V.EGO_TYPES)}")
                continue
            if a.relative_to_ego is not None:
                add(at + ("relative_to_ego",), "the ego has no position relative to itself"
                    + ("; its later action keeps its one start" if i > 0 else ""))
        elif a.relative_to_ego is None:
            add(at + ("name",), f"agent '{a.name}' has no position; add e.g. 'at front' (one of: {_choices(V.POSITIONS)})")
        elif a.relative_to_ego not in V.POSITIONS:
            add(at + ("relative_to_ego",), _unknown("position", a.relative_to_ego, V.POSITIONS))
        action_ok = False
        if a.action not in V.ACTIONS:
            add(at + ("action",), _unknown("action", a.action, V.ACTIONS))
        elif a.action not in V.ACTIONS_BY_TYPE[a.type]:
            able = [t for t in V.AGENT_TYPES if a.action in V.ACTIONS_BY_TYPE[t]]
            only = f"only a {' or '.join(able)} can {a.action}; " if len(able) <= 2 else ""
            add(at + ("action",), f"a {a.type} cannot {a.action}; {only}a {a.type} can: "
                                  f"{_choices(V.ACTIONS_BY_TYPE[a.type])}")
        elif a.is_ego and a.action not in V.EGO_ACTIONS:
            add(at + ("action",), f"the ego cannot {a.action}")
        else:
            action_ok = True
        if a.behavior not in V.BEHAVIORS:
            add(at + ("behavior",), _unknown("behaviour", a.behavior, V.BEHAVIORS))
        if a.road_type not in V.ROAD_TYPES:
            add(at + ("road_type",), _unknown("road type", a.road_type, V.ROAD_TYPES))
        elif a.road_type not in V.ROAD_TYPES_BY_TYPE[a.type] or (a.is_ego and a.road_type != "driving"):
            allowed = {"driving"} if a.is_ego else V.ROAD_TYPES_BY_TYPE[a.type]
            add(at + ("road_type",), f"a {'ego' if a.is_ego else a.type} cannot stand on the {a.road_type}; "
                                     f"it can stand on: {_choices(allowed)}")
        elif action_ok and a.action == "on_the_sidewalk" and a.road_type != "sidewalk":
            add(at + ("road_type",), "on_the_sidewalk needs the agent on the sidewalk ('on sidewalk')")
        if s.road.junction is False and (a.action in V.TURN_ACTIONS or a.relative_to_ego in V.JUNCTION_POSITIONS):
            word = a.action if a.action in V.TURN_ACTIONS else a.relative_to_ego
            add(at + ("action" if word == a.action else "relative_to_ego",),
                f"'{word}' needs a junction, but the road block says 'not at junction'")
        if a.behind is not None and a.order is not None:
            add(at + ("order",), "use either 'behind' or 'order', not both")
        if a.order is not None and not _in_range(a.order, V.ORDER_RANGE):
            add(at + ("order",), f"order {a.order} is out of range {V.ORDER_RANGE[0]}..{V.ORDER_RANGE[1]}")
        if a.gap_m is not None and not _in_range(a.gap_m, V.GAP_RANGE_M):
            add(at + ("gap_m",), f"gap {format_number(a.gap_m)}m is out of range {format_number(V.GAP_RANGE_M[0])}..{format_number(V.GAP_RANGE_M[1])} m")
        if a.speed is not None:
            if a.speed.unit not in V.SPEED_UNITS:
                add(at + ("speed",), _unknown("speed unit", a.speed.unit, V.SPEED_UNITS))
            elif not _in_range(a.speed.mps, V.SPEED_RANGE_MPS):
                add(at + ("speed",), f"speed {format_number(a.speed.value)} {a.speed.unit} is out of range "
                                     f"0..{format_number(round(V.SPEED_RANGE_MPS[1] * 3.6))} km/h")
        if a.trigger is not None:
            _trigger_problems(a, at, by_name_all={x.name for _, _, x in located}, add=add)

    for i, j, a in located:
        if a.behind is None:
            continue
        at = ("stages", i, "agents", j, "behind")
        target = by_name.get(a.behind)
        if a.behind == a.name:
            add(at, f"agent '{a.name}' cannot be behind itself")
        elif target is None:
            suggestions = V.nearest(a.behind, by_name)
            hint = f"; did you mean {V.either(suggestions)}?" if suggestions else ""
            add(at, f"'behind {a.behind}' names no agent{hint}")
        elif target.is_ego:
            add(at, "to follow the ego, use 'at back'")
        elif stage_of[a.behind] != i or target.relative_to_ego != a.relative_to_ego:
            add(at, f"'{a.name}' can only be behind an agent of the same stage at the same position "
                    f"('{a.behind}' is at {target.relative_to_ego} in stage '{s.stages[stage_of[a.behind]].name}')")

    follows = {a.name: a.behind for _, _, a in located if a.behind and a.behind in by_name}
    for cycle in behind_cycles(follows):
        if len(cycle) > 1:
            i, j, _ = next(x for x in located if x[2].name == min(cycle))
            add(("stages", i, "agents", j, "behind"), "'behind' forms a cycle: " + " -> ".join(sorted(cycle)))


def _later_ego_problems(s: Scenario, egos: list[tuple[int, int]], add) -> None:
    """A later stage may hold one `ego TYPE ACTION` line: the ego's action in that stage. The ego keeps its
    one start, so the line has no position, queue or road type of its own."""
    first = s.stages[egos[0][0]].agents[egos[0][1]]
    seen: set[int] = set()
    for i, j in egos[1:]:
        a, at = s.stages[i].agents[j], ("stages", i, "agents", j)
        if i == 0 or i in seen:
            add(at + ("name",), "a second ego line in one stage; the ego acts once per stage "
                                "(put a later action in a new stage)")
            continue
        seen.add(i)
        if a.type != first.type:
            add(at + ("type",), f"the ego is a {first.type} (stage '{s.stages[0].name}'); its later action must "
                                f"say 'ego {first.type}'")
        for field, word in (("behind", "behind"), ("order", "order"), ("gap_m", "gap")):
            if getattr(a, field) is not None:
                add(at + (field,), f"the ego's later action has no '{word}': the ego keeps its one start")


def behind_cycles(follows: dict[str, str]) -> list[list[str]]:
    """The cycles of 'behind' links (agent -> the agent it stands behind), each once. An agent stands behind
    at most one other, so walking the links from every agent finds them all in linear time."""
    cycles, walked = [], set()
    for start in follows:
        path, at = [], {}
        name = start
        while name in follows and name not in walked and name not in at:
            at[name] = len(path)
            path.append(name)
            name = follows[name]
        if name in at:
            cycles.append(path[at[name]:])
        walked.update(path)
    return cycles


def _trigger_problems(a: Agent, at: Path, by_name_all: set[str], add) -> None:
    t = a.trigger
    assert t is not None
    if t.after_s is None and t.within_m is None:
        add(at + ("trigger",), "a trigger needs 'after N s' or 'when X within N m'")
    if t.after_s is not None and not _in_range(t.after_s, V.TRIGGER_TIME_RANGE_S):
        add(at + ("trigger", "after_s"), f"after {format_number(t.after_s)}s is out of range "
                                         f"{format_number(V.TRIGGER_TIME_RANGE_S[0])}..{format_number(V.TRIGGER_TIME_RANGE_S[1])} s")
    if t.within_m is not None:
        if not _in_range(t.within_m, V.TRIGGER_DISTANCE_RANGE_M):
            add(at + ("trigger", "within_m"), f"within {format_number(t.within_m)}m is out of range "
                                              f"{format_number(V.TRIGGER_DISTANCE_RANGE_M[0])}..{format_number(V.TRIGGER_DISTANCE_RANGE_M[1])} m")
        if t.of != "ego" and t.of not in by_name_all:
            add(at + ("trigger", "of"), f"'when {t.of} within' names no agent")
        elif t.of == a.name or (t.of == "ego" and a.is_ego):
            add(at + ("trigger", "of"), "an agent cannot wait to come within reach of itself")


def format_number(x: float) -> str:
    """A number as the language writes it: 8 rather than 8.0, at most three decimals, never an exponent."""
    return f"{x:.3f}".rstrip("0").rstrip(".")
