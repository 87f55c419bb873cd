"""Property tests: parse(format(s)) == s for generated scenarios; no input makes the parser raise anything
but the language's own error."""

from __future__ import annotations

from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from ttsgc import vocabulary as V
from ttsgc.language import ScenarioError, format_scenario, parse, parse_file
from ttsgc.scenario import Agent, Comment, RoadSpec, Scenario, Speed, Stage, Trigger, Weather, find_problems

names = st.from_regex(r"[a-z][a-z0-9_]{0,7}", fullmatch=True).filter(
    lambda n: n not in V.RESERVED_WORDS and n != "ego")
comment_text = st.text(st.characters(blacklist_categories=("Cc", "Cs", "Zl", "Zp")), max_size=20).map(str.strip)
numbers = lambda lo, hi: st.floats(lo, hi, allow_nan=False, allow_infinity=False)  # noqa: E731


@st.composite
def agents(draw, name: str, is_ego: bool, previous: list[Agent], junction: bool | None,
           later_ego_of: str | None = None) -> Agent:
    agent_type = draw(st.sampled_from(sorted(V.EGO_TYPES if is_ego else V.AGENT_TYPES)))
    actions = V.EGO_ACTIONS if is_ego else V.ACTIONS_BY_TYPE[agent_type]
    if junction is False:
        actions = actions - V.TURN_ACTIONS
    action = draw(st.sampled_from(sorted(actions)))
    road_types = {"driving"} if is_ego else V.ROAD_TYPES_BY_TYPE[agent_type]
    road_type = "sidewalk" if action == "on_the_sidewalk" else draw(st.sampled_from(sorted(road_types)))
    fields: dict = {"name": name, "type": agent_type, "is_ego": is_ego, "action": action, "road_type": road_type,
                    "behavior": draw(st.sampled_from(sorted(V.BEHAVIORS)))}
    if not is_ego:
        positions = V.POSITIONS.keys() - (V.JUNCTION_POSITIONS if junction is False else set())
        fields["relative_to_ego"] = draw(st.sampled_from(sorted(positions)))
        others = [a for a in previous if not a.is_ego]
        if others and draw(st.booleans()):
            fields["behind"] = others[-1].name
            fields["relative_to_ego"] = others[-1].relative_to_ego
        elif draw(st.booleans()):
            fields["order"] = draw(st.integers(*V.ORDER_RANGE))
    if later_ego_of is not None:  # the ego's action in a later stage: same type, no start of its own
        fields["type"] = later_ego_of
    elif draw(st.booleans()):
        fields["gap_m"] = draw(numbers(*V.GAP_RANGE_M))
    if draw(st.booleans()):
        unit = draw(st.sampled_from(sorted(V.SPEED_UNITS)))
        fields["speed"] = Speed(value=draw(numbers(0, V.SPEED_RANGE_MPS[1] / V.SPEED_UNITS[unit])), unit=unit)
    if draw(st.booleans()):
        fields["trigger"] = Trigger(
            after_s=draw(st.none() | numbers(*V.TRIGGER_TIME_RANGE_S)),
            within_m=draw(numbers(*V.TRIGGER_DISTANCE_RANGE_M)),
            of="ego" if is_ego or not previous else draw(st.sampled_from(["ego"] + [a.name for a in previous])))
        if is_ego:
            fields["trigger"] = Trigger(after_s=draw(numbers(*V.TRIGGER_TIME_RANGE_S)))
    return Agent(**fields)


@st.composite
def scenarios(draw) -> Scenario:
    junction = draw(st.sampled_from([None, True, False]))
    signals, objects = sorted(V.SIGNALS), V.object_words() + ["speed_50", "speed_120"]
    req_sig = draw(st.lists(st.sampled_from(signals), unique=True, max_size=2))
    req_obj = draw(st.lists(st.sampled_from(objects), unique=True, max_size=3))
    road = RoadSpec(lanes=draw(st.integers(*V.LANES_RANGE)), junction=junction, required_signals=tuple(req_sig),
                    without_signals=tuple(w for w in draw(st.lists(st.sampled_from(signals), unique=True))
                                          if w not in req_sig),
                    required_objects=tuple(req_obj),
                    without_objects=tuple(w for w in draw(st.lists(st.sampled_from(objects), unique=True,
                                                                   max_size=3)) if w not in req_obj))
    all_names = draw(st.lists(names, min_size=12, max_size=12, unique=True))
    stage_count = draw(st.integers(1, 3))
    stages, placed = [], []
    for i in range(stage_count):
        ego_acts = i == 0 or draw(st.booleans())  # a later stage may hold the ego's action there
        count = draw(st.integers(0 if ego_acts else 1, 3))
        members = []
        for k in range(count + (1 if ego_acts else 0)):
            is_ego = ego_acts and k == 0
            later_ego_of = placed[0].type if is_ego and i > 0 else None
            agent = draw(agents("ego" if is_ego else all_names.pop(), is_ego, members, junction, later_ego_of))
            members.append(agent)
        placed += members
        stages.append(Stage(name=all_names.pop(), agents=tuple(members)))
    weather = draw(st.none() | st.builds(Weather, condition=st.sampled_from(sorted(V.WEATHER_CONDITIONS)),
                                         time=st.sampled_from(sorted(V.TIMES_OF_DAY))))
    seed = draw(st.none() | st.integers(0, 2**32 - 1))
    anchors = ["scenario", "road", "road.lanes", "road.end"] + [f"stage.{s.name}" for s in stages]
    anchors += [f"stage.{s.name}.end" for s in stages] + [f"agent.{a.name}" for a in placed]
    anchors += [f"stage.{s.name}.ego" for s in stages[1:] if any(a.is_ego for a in s.agents)]
    anchors += (["weather"] if weather else []) + (["seed"] if seed is not None else [])
    anchors += (["road.junction"] if junction is not None else []) + (["road.has"] if req_sig or req_obj else [])
    anchors += ["road.without"] if road.without_signals or road.without_objects else []
    comments = {}
    for anchor in draw(st.lists(st.sampled_from(anchors), unique=True, max_size=4)):
        comments[anchor] = Comment(leading=tuple(draw(st.lists(comment_text, max_size=2))),
                                   trailing=draw(st.none() | comment_text))
    if draw(st.booleans()):
        comments["end"] = Comment(leading=tuple(draw(st.lists(comment_text, min_size=1, max_size=2))))
    candidate = Scenario.model_construct(name=draw(st.from_regex(r"[A-Za-z0-9 ,.'-]{0,15}[A-Za-z]", fullmatch=True)),
                                         seed=seed, weather=weather, road=road, stages=tuple(stages),
                                         comments=comments)
    assume(not find_problems(candidate))
    return Scenario.model_validate(candidate.model_dump() | {"comments": comments})


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(scenarios())
def test_parse_of_format_is_identity(scenario):
    text = format_scenario(scenario)
    assert parse(text) == scenario
    assert format_scenario(parse(text)) == text


@settings(max_examples=300, deadline=None)
@given(st.binary(max_size=400))
def test_random_bytes_raise_only_the_language_error(tmp_path_factory, data):
    path = tmp_path_factory.mktemp("fuzz") / "f.tsg"
    path.write_bytes(data)
    try:
        parse_file(path)
    except ScenarioError as exc:
        assert exc.diagnostics and exc.render()


TOKENS = ["scenario", '"x"', "weather", "seed", "7", "road", "stage", "{", "}", "\n", "ego", "car", "pedestrian",
          "at", "on", "front", "go_straight", "turn_left", "behind", "order", "gap", "8m", "speed", "30", "km/h",
          "after", "2s", "when", "within", "lanes", ">=", "has", "without", "not", "junction", "#", ",", "s", "m",
          "traffic_light", "crosswalk", "sidewalk", "trun_left", "1.5", "-", "\t"]


@settings(max_examples=500, deadline=None)
@given(st.lists(st.sampled_from(TOKENS), max_size=60), st.booleans())
def test_token_soup_raises_only_the_language_error(tokens, valid_prefix):
    text = ('scenario "x"\nstage s {\n    ego car go_straight\n' if valid_prefix else "") + " ".join(tokens)
    try:
        parse(text)
    except ScenarioError as exc:
        assert exc.diagnostics and exc.render()
