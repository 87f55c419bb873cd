"""English -> Scenario by deterministic rules over the one vocabulary (the default lowering, no API key).

A small semantic parser: the prompt is split into stages at sequence words ("then", "after that"); road
conditions (with negation: "no traffic light and stop sign"), weather and time are read from the whole text;
each agent mention ("two cars", "an ambulance", "the ego") owns the words up to the next mention, from which
its action, position, behaviour and road type are read through synonym tables. A scene kind the prompt names
without describing its agents ("daily traffic", "emergency vehicles") is filled from templates/kinds/*.tsg.
Words no rule can place are returned as `unknown`, never dropped silently.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ttsgc import vocabulary as V
from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.numbers import clamped_int
from ttsgc.language import parse
from ttsgc.resources import resource_dir
from ttsgc.scenario import Agent, RoadSpec, Scenario, Speed, Stage, Trigger, Weather, find_problems


class LoweringError(TtsgcError):
    exit_code = ExitCode.LOWERING_FAILED


def _phrases(table: dict[str, str]) -> list[tuple[tuple[frozenset[str], ...], str]]:
    """'turn|turns left' -> ((turn, turns), (left,)); longest phrases first so they win."""
    out = []
    for pattern, meaning in table.items():
        for variant in pattern.split(";"):
            out.append((tuple(frozenset(w.split("|")) for w in variant.split()), meaning))
    return sorted(out, key=lambda p: -len(p[0]))


AGENT_WORDS = _phrases({
    "fire truck|trucks|engine|engines;firetruck|firetrucks;fire brigade": "firetruck",
    "police car|cars|vehicle;police;cop car|cars": "police",
    "ambulance|ambulances": "ambulance",
    "car|cars|vehicle|vehicles|sedan|sedans|suv|suvs|van|vans|taxi|taxis|traffic": "car",
    "truck|trucks|lorry|lorries": "truck",
    "bus|buses|coach|coaches": "bus",
    "motorcycle|motorcycles|motorbike|motorbikes|scooter|scooters|moped|mopeds|motorcyclist|motorcyclists": "motorcycle",
    "cyclist|cyclists|bicycle|bicycles|bike|bikes|biker|bikers": "cyclist",
    "pedestrian|pedestrians|person|people|walker|walkers|child|children|kid|kids|man|men|woman|women|boy|girl|"
    "jogger|joggers": "pedestrian",
})
EGO_WORDS = _phrases({"ego|egos;autonomous car|vehicle;self driving car|vehicle;our car|vehicle": "ego"})
EGO_NOUNS = {"car": "car", "vehicle": "car", "agent": "car", "truck": "truck", "bus": "bus", "motorcycle": "motorcycle"}
COUNTS = {"a": 1, "an": 1, "one": 1, "another": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6,
          "seven": 7, "eight": 8, "nine": 9, "ten": 10, "several": 3, "some": 2, "few": 2, "couple": 2, "many": 6,
          "both": 2}
MAX_AGENTS_PER_MENTION = 12
MAX_READ_NUMBER = 10**6  # a number in prose above this is read as this; the scene's range rules judge it

ACTIONS = _phrases({
    "cross|crosses|crossing|crossed;runs|run|walks|walk|dashes across;jaywalks|jaywalking": "cross_the_road",
    "walks|walk|walking|strolls along the sidewalk|pavement;walks|walk|walking|strolls along;"
    "on the sidewalk|pavement": "on_the_sidewalk",
    "block|blocks|blocking|blocked": "block_the_ego",
    "swerve|swerves|swerving into its|the path|lane;cut|cuts|cutting in|into|off|across;"
    "swerve|swerves|swerving into;merges|merge in front": "cut_in",
    "change|changes|changing lane|lanes to the left;moves|move into the left lane;merges|merge left;"
    "changes|change to the left lane": "change_lane_to_left",
    "change|changes|changing lane|lanes to the right;moves|move into the right lane;merges|merge right;"
    "changes|change to the right lane": "change_lane_to_right",
    "turn|turns|turning|turned left;left turn;turns|turn onto|into the left": "turn_left",
    "turn|turns|turning|turned right;right turn": "turn_right",
    "stop|stops|stopped|stopping;brake|brakes|braking;halt|halts;wait|waits|waiting;parked;stationary;"
    "does|do not move;standing still": "stop",
    "go|goes|going|drive|drives|driving|ride|rides|riding straight through|ahead;"
    "go|goes|going|drive|drives|driving straight|through|ahead;pass|passes through;continue|continues;"
    "ride|rides|riding;"
    "follow|follows|following;overtake|overtakes|overtaking;come|comes|coming|approach|approaches|approaching;"
    "drive|drives|driving": "go_straight",
})
POSITIONS = _phrases({
    "front right;ahead on|to the right;in front on the right;right front": "front_right",
    "front left;ahead on|to the left;in front on the left;left front": "front_left",
    "back right;behind on the right;rear right": "back_right",
    "back left;behind on the left;rear left;overtakes|overtaking on the left": "back_left",
    "from|in the opposite direction;oncoming;towards|toward the ego;head on": "road_of_straight",
    "from the left;from the road on the left;on the road to the left;from the left road": "from_left",
    "from the right;from the road on the right;on the road to the right;from the right road": "from_right",
    "at the destination;where the ego is heading|going": "at_the_destination",
    "near|at|by the crosswalk|crossing": "near_the_crosswalk",
    "in front;ahead;leading;in front of the ego": "front",
    "behind;from behind;following;at the back;behind the ego": "back",
    "on|to the left;in the left lane;in the lane to the left": "left",
    "on|to the right;in the right lane;in the lane to the right": "right",
})
ROAD_TYPES = _phrases({"on the shoulder;hard shoulder;roadside;side of the road": "shoulder",
                       "on the sidewalk|pavement": "sidewalk"})
BEHAVIORS = _phrases({
    "aggressive|aggressively|dangerous|dangerously|reckless|recklessly|speeding|fast|quickly|suddenly|sudden|"
    "rushing|rushes|runs|running|dashes|overtake|overtakes|overtaking": "aggressive",
    "careful|carefully|cautious|cautiously|slow|slowly|gently": "cautious",
})
FEATURES = _phrases({
    "traffic light|lights|signal|signals;signalised|signalized;signal controlled": "traffic_light",
    "unsignalised|unsignalized|uncontrolled": "!traffic_light",
    "stop sign|signs;all way stop": "stop",
    "yield sign|signs;give way sign|signs;yield;give way": "yield",
    "crosswalk|crosswalks;zebra crossing|crossings;pedestrian crossing|crossings": "crosswalk",
    "ladder crosswalk": "ladder_crosswalk",
    "continental crosswalk;zebra": "continental_crosswalk",
    "stop line|lines": "stop_line",
})
JUNCTION = _phrases({"junction|junctions|intersection|intersections|crossroads|crossroad;t junction": "junction"})
NEGATIONS = {"no", "not", "without", "none", "never"}
CONDITIONS = _phrases({
    "heavy|hard|pouring rain;downpour;storm|stormy": "hard_rain",
    "light|soft rain;drizzle|drizzling": "soft_rain",
    "rain|rainy|raining": "mid_rain",
    "puddles|puddle;wet road|roads;wet": "wet",
    "cloudy|overcast|clouds": "cloudy",
    "fog|foggy|mist|misty|haze": "fog",
    "snow|snowy|snowing": "snow",
    "clear|sunny": "clear",
})
TIMES = _phrases({"night|dark|darkness|midnight": "night", "dusk|sunset|evening|twilight": "sunset",
                  "dawn|sunrise|morning": "dawn", "noon|midday|daytime|afternoon": "noon"})
STAGE_BREAKS = _phrases({"then;after that;afterwards;after this;next;later;finally;subsequently": "then"})
KINDS = _phrases({
    "block|blocks|blocking|blocked": "blocking",
    "pedestrian crush|crushing;crush|crushing;hit a pedestrian": "crushing",
    "cut off;cut in;cutoff;cutting in": "cut_off",
    "daily|everyday|normal|regular|ordinary traffic": "daily_traffic",
    "emergency vehicles|vehicle;emergency": "emergency",
    "intersection;junction": "intersection",
    "two wheel|wheeled|wheelers|wheeler vehicles;two wheelers;only two wheelers": "two_wheels",
    "rain|rainy|snow|snowy|fog|foggy|bad|wet weather;rain|rainy|snow|snowy|fog|foggy|weather": "weather",
})
STOPWORDS = set("""
a an the of to in on at is are was were be and or while with from for its it that which who as by into onto
this there where when scene scenario please create make generate build give me show some road roads lane lanes
street streets way one ego's egos side same other also just then it's their them they he she his her having has
have
""".split())
NAME_PREFIX = {"car": "c", "truck": "t", "bus": "b", "motorcycle": "m", "cyclist": "k", "pedestrian": "p",
               "ambulance": "a", "police": "po", "firetruck": "f"}
COORDINATION = {"and", "or", "a", "an", "the", "as", "well", "plus", "both"}
NUMBER_WORDS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "single": 1, "double": 2,
                "multi": 2, "multiple": 2}


@dataclass
class Lowered:
    scenario: Scenario
    unknown: list[str]  # words no rule placed
    kind: str | None = None  # the scene kind a template filled in


@dataclass
class _Mention:
    start: int
    end: int
    type: str
    count: int
    is_ego: bool
    adjectives: int = 0  # where the words qualifying the noun begin ("an aggressive car", "an oncoming bus")


@dataclass
class _Text:
    tokens: list[str]
    used: set[int] = field(default_factory=set)

    def find(self, table, start: int = 0, stop: int | None = None, mark: bool = True):
        """Matches of a phrase table in tokens[start:stop]: (index, length, meaning), in text order."""
        stop = len(self.tokens) if stop is None else stop
        found, taken = [], set()
        for words, meaning in table:
            n = len(words)
            for i in range(start, stop - n + 1):
                if any(j in taken for j in range(i, i + n)):
                    continue
                if all(self.tokens[i + k] in words[k] for k in range(n)):
                    found.append((i, n, meaning))
                    taken.update(range(i, i + n))
        found.sort()
        if mark:
            for i, n, _ in found:
                self.used.update(range(i, i + n))
        return found


def tokenize(text: str) -> list[str]:
    text = text.lower().replace("km/h", " kmh ").replace("'s", " ")
    return re.findall(r"[a-z]+|\d+(?:\.\d+)?", text)


def lower(prompt: str, seed: int = 0) -> Lowered:
    """Lower an English prompt into a Scenario; LoweringError when nothing usable can be read from it."""
    text = _Text(tokenize(prompt))
    if not text.tokens:
        raise LoweringError("the prompt is empty")
    kinds = text.find(KINDS, mark=False)
    road = _road(text)
    weather = _weather(text)
    segments = _segments(text)
    kind_tokens = {j for i, n, _ in kinds for j in range(i, i + n)}
    mentions_by_segment = [_mentions(text, a, b, skip=set(text.used) | kind_tokens) for a, b in segments]
    others = [m for ms in mentions_by_segment for m in ms if not m.is_ego]
    kind = None
    if not others and kinds:
        i, n, kind = kinds[0]
        text.used.update(range(max(0, i - 1), i + n))  # the kind and the word that qualifies it
    junction_context = road.junction is True or bool(text.find(JUNCTION, mark=False))
    stages, names = [], _Namer()
    ego: Agent | None = None
    for (_, b), mentions in zip(segments, mentions_by_segment):
        agents: list[Agent] = []
        for i, m in enumerate(mentions):
            clause_end = mentions[i + 1].start if i + 1 < len(mentions) else b
            clause = (m.end, clause_end)
            k = i
            while all(t in COORDINATION for t in text.tokens[clause[0]:clause[1]]) and k + 1 < len(mentions) \
                    and not mentions[k + 1].is_ego:  # "an ambulance and a police car drive behind": shared
                k += 1
                clause = (mentions[k].end, mentions[k + 1].start if k + 1 < len(mentions) else b)
            if m.is_ego:
                if ego is None:
                    ego = _ego(text, m, clause)
                continue
            agents += _agents(text, m, clause, names, junction_context, road)
        for j, agent in enumerate(agents):  # "in front of a truck": at the truck's position
            if agent.relative_to_ego == "same_as_next":
                nxt = next((x.relative_to_ego for x in agents[j + 1:] if x.relative_to_ego != "same_as_next"),
                           "front")
                agents[j] = agent.model_copy(update={"relative_to_ego": nxt})
        stages.append(agents)
    if kind is not None:
        template = _template(kind, seed)
        road = _merge_road(template.road, road)
        ego = ego or template.ego
        stages[0] = [a for a in template.stages[0].agents if not a.is_ego] + stages[0]
    if ego is None:
        ego = Agent(name="ego", type="car", is_ego=True, action="go_straight")
    ego = _ego_default_for_obstacles(ego, stages[0])
    stages[0] = [ego] + stages[0]
    if not any(stages[1:]) and len(stages) > 1:
        stages = [stages[0]]
    stage_models = tuple(Stage(name=_stage_name(k, len(stages)), agents=tuple(agents))
                         for k, agents in enumerate(stages) if agents)
    if road.junction is None and any(a.action in V.TURN_ACTIONS or a.relative_to_ego in V.JUNCTION_POSITIONS
                                     for s in stage_models for a in s.agents):
        road = road.model_copy(update={"junction": True})
    name = _name(prompt)
    candidate = Scenario.model_construct(name=name, seed=None, weather=weather, road=road, stages=stage_models)
    problems = find_problems(candidate)
    if problems:
        raise LoweringError("the prompt lowers to an invalid scene: " + "; ".join(p.message for p in problems))
    scenario = Scenario.model_validate(candidate.model_dump())
    unknown = [t for i, t in enumerate(text.tokens) if i not in text.used and t not in STOPWORDS
               and t not in COUNTS and not t.isdigit()]
    unknown = list(dict.fromkeys(unknown))
    said_nothing = (kind is None and len(list(scenario.agents())) == 1 and scenario.road == RoadSpec()
                    and scenario.weather is None and scenario.ego.action == "go_straight"
                    and scenario.ego.behavior == V.DEFAULT_BEHAVIOR)
    if said_nothing:
        raise LoweringError("nothing in the prompt could be read as a scene"
                            + (f"; unknown words: {', '.join(unknown)}" if unknown else "")
                            + ". Name agents (car, pedestrian, bus...), what they do (turns left, crosses, stops...) "
                              "and where (in front, from the opposite direction...), or write the scene in the "
                              "scenario language (.tsg)")
    return Lowered(scenario, unknown, kind)


class _Namer:
    def __init__(self):
        self.counts: dict[str, int] = {}

    def __call__(self, agent_type: str) -> str:
        prefix = NAME_PREFIX[agent_type]
        self.counts[prefix] = self.counts.get(prefix, 0) + 1
        return f"{prefix}{self.counts[prefix]}"


def _stage_name(k: int, total: int) -> str:
    return "main" if total == 1 else ("first", "second", "third", "fourth", "fifth", "sixth")[min(k, 5)]


def _name(prompt: str) -> str:
    words = re.findall(r"[A-Za-z0-9][A-Za-z0-9'-]*", prompt)
    return (" ".join(words[:10]) or "scene").lower()


def _segments(text: _Text) -> list[tuple[int, int]]:
    breaks = [i for i, n, _ in text.find(STAGE_BREAKS)] + [len(text.tokens)]
    out, start = [], 0
    for b in breaks:
        if b > start:
            out.append((start, b))
        start = b + 1
    return out or [(0, len(text.tokens))]


def _road(text: _Text) -> RoadSpec:
    fields: dict = {"required_signals": [], "without_signals": [], "required_objects": [], "without_objects": []}
    tokens = text.tokens
    negated = False
    features = {i: (n, meaning) for i, n, meaning in text.find(FEATURES)}
    i = 0
    while i < len(tokens):
        if tokens[i] in NEGATIONS:
            negated = True
            text.used.add(i)
        elif i in features:
            n, meaning = features[i]
            word = meaning.lstrip("!")
            group = "signals" if word in V.SIGNALS else "objects"
            forbidden = negated != meaning.startswith("!")
            target = fields[f"{'without' if forbidden else 'required'}_{group}"]
            if word not in target:
                target.append(word)
            i += n
            continue
        elif tokens[i] not in ("and", "or", "a", "an", "any", "nor", "sign", "signs"):
            negated = False
        i += 1
    for limit in _speed_limits(text):
        word = f"speed_{limit}"
        if V.is_object(word) and word not in fields["required_objects"]:
            fields["required_objects"].append(word)
    lanes = _lanes(text)
    if lanes is not None:
        fields["lanes"] = lanes
    junction = _junction(text)
    if junction is not None:
        fields["junction"] = junction
    return RoadSpec(**{k: tuple(v) if isinstance(v, list) else v for k, v in fields.items()})


def _speed_limits(text: _Text):
    tokens, out = text.tokens, []
    for i, t in enumerate(tokens):
        if not t.isdigit():
            continue
        window = tokens[i + 1: i + 5]
        before = tokens[max(0, i - 3): i]
        if ("limit" in before or "speed" in before or ("kmh" in window[:1] and {"limit", "sign", "zone"} & set(window))
                or (window[:1] == ["zone"])):
            text.used.update(j for j in range(max(0, i - 3), min(len(tokens), i + 5))
                             if tokens[j] in ("speed", "limit", "sign", "kmh", "zone", "of") or j == i)
            out.append(clamped_int(t, MAX_READ_NUMBER))
    return out


def _lanes(text: _Text) -> int | None:
    tokens = text.tokens
    for i, t in enumerate(tokens):
        if t in ("lane", "lanes") and i > 0:
            n = NUMBER_WORDS.get(tokens[i - 1]) or (clamped_int(tokens[i - 1], MAX_READ_NUMBER) if tokens[i - 1].isdigit() else None)
            if n is not None and 1 <= n <= 6:
                text.used.update((i - 1, i))
                return n
        if t in ("highway", "motorway", "freeway", "expressway"):
            text.used.add(i)
            return 2
    return None


def _junction(text: _Text) -> bool | None:
    tokens = text.tokens
    straight = [i for i, t in enumerate(tokens[:-1]) if t == "straight" and tokens[i + 1] in ("road", "street")]
    text.used.update(j for i in straight for j in (i, i + 1))
    for i, _, _ in text.find(JUNCTION):
        if any(t in NEGATIONS for t in tokens[max(0, i - 2): i]):
            return False
        return True
    for i, t in enumerate(tokens):
        if t in ("highway", "motorway", "freeway", "expressway"):
            return False
        if i in straight:
            return False
    return None


def _weather(text: _Text) -> Weather | None:
    conditions = [c for _, _, c in text.find(CONDITIONS)]
    times = [t for _, _, t in text.find(TIMES)]
    if not conditions and not times:
        return None
    return Weather(condition=conditions[0] if conditions else V.DEFAULT_CONDITION,
                   time=times[0] if times else V.DEFAULT_TIME)


def _mentions(text: _Text, start: int, stop: int, skip: set[int]) -> list[_Mention]:
    tokens = text.tokens
    out = []
    egos = text.find(EGO_WORDS, start, stop)
    ego_spans = set(skip)
    for i, n, _ in egos:
        span_end = i + n
        ego_type = "car"
        if span_end < stop and tokens[span_end] in EGO_NOUNS:
            ego_type = EGO_NOUNS[tokens[span_end]]
            span_end += 1
            text.used.add(span_end - 1)
        ego_spans.update(range(i, span_end))
        referenced = i > 0 and tokens[i - 1] in ("the",) and i > 1 and tokens[i - 2] in (
            "of", "behind", "block", "blocks", "blocking", "towards", "toward", "beside", "than", "before", "past",
            "overtake", "overtakes", "to", "for")
        out.append(_Mention(i, span_end, ego_type, 1, True) if not referenced else None)
    out = [m for m in out if m is not None]
    for i, n, agent_type in _find_skipping(text, AGENT_WORDS, start, stop, ego_spans):
        adjectives = i  # up to two qualifying words before the noun: "an aggressive car", "oncoming traffic"
        while adjectives > start and i - adjectives < 2 and tokens[adjectives - 1] not in STOPWORDS and \
                tokens[adjectives - 1] not in COUNTS and not tokens[adjectives - 1].isdigit() and \
                adjectives - 1 not in skip:
            adjectives -= 1
        j = adjectives - 1
        while j >= start and tokens[j] in ("of", "the"):
            j -= 1
        count = 1
        counted = j >= start and (tokens[j] in COUNTS or tokens[j].isdigit())
        if counted:
            count = COUNTS.get(tokens[j]) or clamped_int(tokens[j], MAX_READ_NUMBER)
            if j > start and tokens[j - 1] == "than":  # more than ten
                count += 1
                text.used.update(k for k in (j - 2, j - 1) if k >= start and tokens[k] in ("more", "than"))
            text.used.add(j)
        if tokens[i + n - 1].endswith("s") and not counted and tokens[i + n - 1] not in ("bus", "police"):
            count = 2  # a bare plural: some
        if tokens[i + n: i + n + 3] == ["including", "the", "ego"]:
            count -= 1
            text.used.update(range(i + n, i + n + 3))
        out.append(_Mention(i, i + n, agent_type, max(0, min(count, MAX_AGENTS_PER_MENTION)), False,
                            adjectives=adjectives))
    return sorted(out, key=lambda m: m.start)


def _find_skipping(text: _Text, table, start: int, stop: int, skip: set[int]):
    return [(i, n, m) for i, n, m in text.find(table, start, stop) if i not in skip]


def _first(text: _Text, table, a: int, b: int):
    found = text.find(table, a, b)
    return found[0][2] if found else None


def _ego(text: _Text, m: _Mention, clause: tuple[int, int]) -> Agent:
    a, b = clause
    action = _first(text, ACTIONS, a, b)
    if action in (None, "cut_in", "cross_the_road", "on_the_sidewalk", "block_the_ego"):
        action = "go_straight"
    behavior = _first(text, BEHAVIORS, a, b) or V.DEFAULT_BEHAVIOR
    return Agent(name="ego", type=m.type if m.type in V.EGO_TYPES else "car", is_ego=True, action=action,
                 behavior=behavior)


def _agents(text: _Text, m: _Mention, clause: tuple[int, int], names: _Namer, junction_context: bool,
            road: RoadSpec) -> list[Agent]:
    a, b = clause
    tokens = text.tokens
    action = _first(text, ACTIONS, a, b)
    position = _first(text, POSITIONS, m.adjectives, m.start) or _first(text, POSITIONS, a, b)
    road_type = _first(text, ROAD_TYPES, a, b)
    behavior = _first(text, BEHAVIORS, m.adjectives, m.start) or _first(text, BEHAVIORS, a, b) or \
        V.DEFAULT_BEHAVIOR
    if m.type == "pedestrian" and action in (None, "go_straight"):
        action = "on_the_sidewalk" if road_type == "sidewalk" or "sidewalk" in tokens[a:b] else "cross_the_road"
    if action is None:
        action = "go_straight"
    if action in ("on_the_sidewalk", "cross_the_road") and m.type != "pedestrian":
        action = "go_straight" if m.type != "cyclist" or action == "on_the_sidewalk" else action
    if position in ("from_left", "from_right"):
        side = position[5:]
        position = f"road_of_{side}_turn" if junction_context else side
    if action == "cut_in":
        position = position if position in ("left", "right", "front_left", "front_right") else "front_left"
        action = "change_lane_to_right" if "left" in position else "change_lane_to_left"
    if action == "cross_the_road" and m.type == "pedestrian" and (
            "crosswalk" in road.required_objects or position is None) and position not in ("left", "right"):
        if "crosswalk" in road.required_objects or any(t in ("crosswalk", "crossing") for t in tokens):
            position = "near_the_crosswalk"
    if position is None:
        position = "front_right" if m.type == "pedestrian" else "front"
    if tuple(tokens[max(a, b - 4):b]) in (("in", "front", "of", "a"), ("in", "front", "of", "the")) or \
            tuple(tokens[max(a, b - 2):b]) in (("behind", "a"), ("behind", "the"), ("beside", "a"), ("beside", "the")):
        position = "same_as_next"  # "crosses in front of a truck": where that truck is
    if road_type is None:
        road_type = V.default_road_type(m.type)
    if road_type not in V.ROAD_TYPES_BY_TYPE[m.type]:
        road_type = V.default_road_type(m.type)
    trigger = _trigger(text, a, b)
    speed = _speed(text, a, b)
    out: list[Agent] = []
    for _ in range(m.count):
        out.append(Agent(name=names(m.type), type=m.type, action=action, behavior=behavior,
                         relative_to_ego=position, road_type=road_type,
                         behind=out[-1].name if out else None, trigger=trigger, speed=speed))
    return out


def _trigger(text: _Text, a: int, b: int) -> Trigger | None:
    tokens, within, after = text.tokens, None, None
    for i in range(a, b):
        if tokens[i] == "within" and i + 1 < b and tokens[i + 1].isdigit():
            within = float(clamped_int(tokens[i + 1], MAX_READ_NUMBER))
            text.used.update((i, i + 1))
        if tokens[i] == "after" and i + 1 < b and tokens[i + 1].isdigit():
            after = float(clamped_int(tokens[i + 1], MAX_READ_NUMBER))
            text.used.update((i, i + 1))
    return Trigger(after_s=after, within_m=within) if within or after else None


def _speed(text: _Text, a: int, b: int) -> Speed | None:
    tokens = text.tokens
    for i in range(a, b - 1):
        if tokens[i].isdigit() and tokens[i + 1] in ("kmh", "mph"):
            text.used.update((i, i + 1))
            return Speed(value=float(clamped_int(tokens[i], MAX_READ_NUMBER)), unit="km/h" if tokens[i + 1] == "kmh" else "mph")
    return None


def _ego_default_for_obstacles(ego: Agent, first_stage: list[Agent]) -> Agent:
    """The ego cannot drive through a car that stops in its lane ahead: then it stops behind it."""
    stopper = next((a for a in first_stage if a.relative_to_ego == "front" and a.action == "stop"), None)
    if stopper is not None and ego.action == "go_straight":
        return ego.model_copy(update={"action": "stop", "trigger": Trigger(within_m=15.0, of=stopper.name)})
    return ego


def _template(kind: str, seed: int) -> Scenario:
    folder = resource_dir("templates") / "kinds"
    variants = sorted(folder.glob(f"{kind}.tsg")) + sorted(folder.glob(f"{kind}.*.tsg"))
    if not variants:
        raise LoweringError(f"no template for the scene kind '{kind}'")
    path = variants[seed % len(variants)]
    return parse(path.read_text(encoding="utf-8"), str(path))


def _merge_road(template: RoadSpec, said: RoadSpec) -> RoadSpec:
    """What the prompt says about the road wins over the kind's defaults."""
    default = RoadSpec()
    merged = template.model_dump()
    for key, value in said.model_dump().items():
        if value != getattr(default, key):
            merged[key] = value
    return RoadSpec(**merged)
