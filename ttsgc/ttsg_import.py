"""The TTSG reference code's plans (agent_output.json, road_info.json) -> the scenario language.

A plan has three parts: analysis, retrieval (road conditions) and planning (weather preset, at_junction, one
entry per agent with type, is_ego, action, behavior, pos_id, road_type, relative_to_ego). Plans written by an
LLM are not always consistent (two egos, a pedestrian that blocks the ego, a pedestrian on a driving lane):
what is particular to the plan format is repaired here, everything else by the one plan inference
(ttsgc/lowering/infer.py) that the English lowerings use too; each repair and inference is recorded as a
note, never made silently.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

from ttsgc import vocabulary as V
from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.lowering.infer import infer_plan
from ttsgc.lowering.offline import NAME_PREFIX
from ttsgc.scenario import Agent, Comment, RoadSpec, Scenario, Stage, Weather, find_problems

CONDITIONS = {"Clear": "clear", "Cloudy": "cloudy", "Wet": "wet", "WetCloudy": "wet_cloudy", "SoftRain": "soft_rain",
              "MidRain": "mid_rain", "MidRainy": "mid_rain", "HardRain": "hard_rain", "SoftRainy": "soft_rain",
              "HardRainy": "hard_rain"}
TIMES = {"Noon": "noon", "Sunset": "sunset", "Night": "night"}


class PlanError(TtsgcError):
    exit_code = ExitCode.INVALID_SCENARIO


@dataclass(frozen=True)
class PaperRoad:
    town: str
    road: str
    direction: str  # forward | backward

    @property
    def approach(self) -> str:
        return f"{self.road}:{'fwd' if self.direction == 'forward' else 'bwd'}"


@dataclass
class Imported:
    scenario: Scenario
    notes: list[str] = field(default_factory=list)
    paper_road: PaperRoad | None = None


def weather_of(preset: str) -> tuple[Weather, str | None]:
    """'MidRainSunset' -> mid_rain sunset; an unknown preset gives clear noon and a note."""
    for time_word, time in TIMES.items():
        if preset.endswith(time_word) and preset[: -len(time_word)] in CONDITIONS:
            return Weather(condition=CONDITIONS[preset[: -len(time_word)]], time=time), None
    return Weather(), f"unknown weather preset '{preset}', used clear noon"


def _load(path: Path) -> dict:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise PlanError(f"{path}: cannot read the plan: {exc}") from None


def import_plan(agent_output: str | Path, road_info: str | Path | None = None) -> Imported:
    path = Path(agent_output)
    plan = _load(path)
    try:
        planning, retrieval = plan["planning"], plan.get("retreival") or plan.get("retrieval") or {}
        env, agents_in = planning["env"], planning["agents"]
    except (KeyError, TypeError) as exc:
        raise PlanError(f"{path}: not a TTSG plan (missing {exc})") from None
    notes: list[str] = []
    weather, note = weather_of(str(env.get("weather", "ClearNoon")))
    notes += [note] if note else []
    road = _road(retrieval, env, notes)
    agents = _agents(agents_in, road, notes)
    name = f"ttsg {path.parent.parent.name} {path.parent.name}".strip()
    draft = Scenario.model_construct(name=name, seed=None, weather=weather, road=road,
                                     stages=(Stage(name="main", agents=tuple(agents)),), comments={})
    inferred = infer_plan(draft)
    notes += inferred.notes
    comments = {"scenario": Comment(leading=tuple([f"Imported from the TTSG plan {path}"] +
                                                  [f"import: {n}" for n in notes]))}
    scenario = inferred.scenario.model_copy(update={"comments": comments})
    problems = find_problems(scenario)
    if problems:
        raise PlanError(f"{path}: the plan does not make a valid scene: " + "; ".join(p.message for p in problems))
    paper = _paper_road(Path(road_info)) if road_info else None
    return Imported(Scenario.model_validate(scenario.model_dump() | {"comments": comments}), notes, paper)


def _road(retrieval: dict, env: dict, notes: list[str]) -> RoadSpec:
    def words(key: str) -> tuple[str, ...]:
        out = []
        for w in retrieval.get(key) or []:
            w = str(w).lower().replace(" ", "_")
            if w in V.SIGNALS or V.is_object(w):
                out.append(w)
            else:
                notes.append(f"dropped the unknown road word '{w}' from {key}")
        return tuple(dict.fromkeys(out))
    required = words("required_signals") + words("required_objects")
    forbidden = words("without_signals") + words("without_objects")
    lanes = int(retrieval.get("number_of_lanes") or 1)
    if not 1 <= lanes <= 6:
        notes.append(f"number_of_lanes {lanes} is out of 1..6, used {min(max(lanes, 1), 6)}")
        lanes = min(max(lanes, 1), 6)
    junction = env.get("at_junction")
    return RoadSpec(lanes=lanes, junction=bool(junction) if junction is not None else None,
                    required_signals=tuple(w for w in required if w in V.SIGNALS),
                    required_objects=tuple(w for w in required if w not in V.SIGNALS),
                    without_signals=tuple(w for w in forbidden if w in V.SIGNALS and w not in required),
                    without_objects=tuple(w for w in forbidden if w not in V.SIGNALS and w not in required))


def _agents(entries: list[dict], road: RoadSpec, notes: list[str]) -> list[Agent]:
    counts: dict[str, int] = {}
    ego_seen = False
    agents: list[Agent] = []
    ordered = sorted(enumerate(entries), key=lambda e: (not e[1].get("is_ego"), e[0]))
    for index, entry in ordered:
        kind = str(entry.get("type", "car")).lower()
        if kind not in V.AGENT_TYPES:
            notes.append(f"agent {index + 1}: unknown type '{kind}', used car")
            kind = "car"
        is_ego = bool(entry.get("is_ego")) and not ego_seen and kind in V.EGO_TYPES
        if entry.get("is_ego") and not is_ego:
            notes.append(f"agent {index + 1} ({kind}) was also marked as the ego; kept as an agent")
        ego_seen |= is_ego
        action = str(entry.get("action", "go_straight"))
        if action not in V.ACTIONS:
            notes.append(f"agent {index + 1} ({kind}): unknown action '{action}', used go_straight")
            action = "go_straight"  # a known action a type cannot do is repaired by the plan inference
        position = None if is_ego else str(entry.get("relative_to_ego", "front"))
        if position is not None and position not in V.POSITIONS:
            notes.append(f"agent {index + 1}: position '{position}' is not one of the vocabulary's, used front")
            position = "front"
        road_type = str(entry.get("road_type", V.default_road_type(kind)))
        if road_type not in V.ROAD_TYPES:
            notes.append(f"agent {index + 1} ({kind}): unknown road type '{road_type}', used the default")
            road_type = V.default_road_type(kind)
        behavior = str(entry.get("behavior", "normal"))
        behavior = behavior if behavior in V.BEHAVIORS else "normal"
        order = entry.get("pos_id")
        order = int(order) if isinstance(order, int) and V.ORDER_RANGE[0] <= order <= V.ORDER_RANGE[1] and not is_ego \
            else None
        if is_ego:
            name = "ego"
        else:
            prefix = NAME_PREFIX[kind]
            counts[prefix] = counts.get(prefix, 0) + 1
            name = f"{prefix}{counts[prefix]}"
        agents.append(Agent(name=name, type=kind, is_ego=is_ego, action=action, behavior=behavior,
                            relative_to_ego=position, road_type=road_type, order=order))
    if not ego_seen:
        notes.append("the plan has no usable ego; added a car going straight")
        agents.insert(0, Agent(name="ego", type="car", is_ego=True, action="go_straight"))
    return agents


def _paper_road(path: Path) -> PaperRoad | None:
    info = _load(path)
    roads = info.get("road_id") or []
    if not info.get("town") or not roads:
        return None
    # The plans' direction names the lane side: left lanes drive against s, right lanes along it.
    direction = "backward" if str(info.get("direction", "right")).lower() == "left" else "forward"
    return PaperRoad(str(info["town"]), str(roads[0]), direction)
