"""One plan inference for every front end: the offline rules, the LLM's answer, and imported TTSG plans.

A plan read from English (by rules or by a model) or from another tool is often incomplete or inconsistent:
an agent beside the ego needs a second lane, a turn needs a junction, a pedestrian cannot "block" the ego
(it steps into its path instead). Every front end hands its draft scene here, so the same sentence gives the
same road whoever read it, nothing contradictory is ever written, and every inference and repair is a note
that the caller prints and writes into the .tsg as a comment.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

from ttsgc import vocabulary as V
from ttsgc.scenario import Agent, Comment, RoadSpec, Scenario, Stage, find_problems

SIDE_POSITIONS = frozenset({"left", "right", "front_left", "front_right", "back_left", "back_right"})
LANE_CHANGES = frozenset({"change_lane_to_left", "change_lane_to_right"})
BLOCKER_CANNOT_START = V.JUNCTION_POSITIONS | {"back"}  # behind the ego or on another road of the junction
PEDESTRIAN_FOR_VEHICLE_ACTION = {"block_the_ego": "cross_the_road", "go_straight": "on_the_sidewalk",
                                 "turn_left": "cross_the_road", "turn_right": "cross_the_road",
                                 "change_lane_to_left": "cross_the_road", "change_lane_to_right": "cross_the_road"}


@dataclass
class Inferred:
    scenario: Scenario  # built with model_construct: the caller validates (find_problems) and reports
    notes: list[str] = field(default_factory=list)


@lru_cache(maxsize=1)
def language_allows_later_ego() -> bool:
    """Whether the language accepts `ego TYPE ACTION` in a later stage (the ego acting again)."""
    probe = Scenario.model_construct(
        name="probe", seed=None, weather=None, road=RoadSpec(),
        stages=(Stage(name="a", agents=(Agent(name="ego", type="car", is_ego=True, action="go_straight"),)),
                Stage(name="b", agents=(Agent(name="ego", type="car", is_ego=True, action="turn_left"),))),
        comments={})
    return not find_problems(probe)


def infer_plan(draft: Scenario, oncoming: frozenset[str] = frozenset()) -> Inferred:
    """Repair what cannot be, then add what the agents imply about the road; `oncoming` names agents at a
    side position because they drive the other way or stand parked at the kerb (they need no second lane in the
    ego's direction)."""
    notes: list[str] = []
    road = _repair_road(draft.road, notes)
    junction_said = _implied_road(road, draft.stages, frozenset(), []).junction  # before blockers are moved
    stages = _repair_agents(draft.stages, road, notes)
    road = _implied_road(road, stages, oncoming, notes)
    if junction_said is True and road.junction is None:
        road = road.model_copy(update={"junction": True})
        notes.append("inferred: at junction (the blocker came out of a road of the junction)")
    comments = dict(draft.comments)
    if notes:
        old = comments.get("scenario", Comment())
        comments["scenario"] = Comment(leading=old.leading + tuple(notes), trailing=old.trailing)
    scenario = Scenario.model_construct(name=draft.name, seed=draft.seed, weather=draft.weather, road=road,
                                        stages=stages, comments=comments)
    return Inferred(scenario, notes)


def _repair_road(road: RoadSpec, notes: list[str]) -> RoadSpec:
    update: dict = {}
    low, high = V.LANES_RANGE
    if not low <= road.lanes <= high:
        update["lanes"] = min(max(road.lanes, low), high)
        notes.append(f"repaired: lanes >= {road.lanes} is out of {low}..{high}; used lanes >= {update['lanes']}")
    for kind in ("signals", "objects"):
        required, forbidden = getattr(road, f"required_{kind}"), getattr(road, f"without_{kind}")
        both = [w for w in forbidden if w in required]
        if both:
            update[f"without_{kind}"] = tuple(w for w in forbidden if w not in required)
            notes.append(f"repaired: {', '.join(both)} both required and forbidden; kept as required")
    return road.model_copy(update=update) if update else road


def _repair_agents(stages, road: RoadSpec, notes: list[str]) -> tuple[Stage, ...]:
    out = []
    ego_type = None
    later_ego_ok = language_allows_later_ego()
    turned = False
    for k, stage in enumerate(stages):
        agents = []
        for agent in stage.agents:
            if agent.is_ego and ego_type is not None:
                if k == 0 or not later_ego_ok or any(a.is_ego for a in agents):
                    notes.append(f"left out: the ego's later action ({agent.action} in stage '{stage.name}'), "
                                 "which the language cannot say here")
                    continue
                first = next((a.action for a in out[0].agents if a.is_ego), "") if out else ""
                if agent.action in V.TURN_ACTIONS and (first != "stop" or turned):  # binding lays the ego's one
                    # route from its start: a later turn only after it stopped before the junction, and once
                    notes.append(f"left out: the ego's later {agent.action} (stage '{stage.name}'): ttsgc binds "
                                 "a later turn of the ego only after a first-stage stop, and once")
                    continue
                turned |= agent.action in V.TURN_ACTIONS
                agent = agent.model_copy(update={"type": ego_type})
            agent = _repair_agent(agent, road, notes)
            if agent.is_ego and ego_type is None:
                ego_type = agent.type
            agents.append(agent)
        out.append(Stage(name=stage.name, agents=tuple(agents)))
    names = {}
    for k, stage in enumerate(out):
        for agent in stage.agents:
            names[agent.name] = (k, agent.relative_to_ego)
    fixed = []
    for k, stage in enumerate(out):
        agents = []
        for agent in stage.agents:
            if agent.behind is not None and names.get(agent.behind) != (k, agent.relative_to_ego):
                agent = agent.model_copy(update={"behind": None})
            agents.append(agent)
        if agents:
            fixed.append(Stage(name=stage.name, agents=tuple(agents)))
    return tuple(fixed)


def _repair_agent(agent: Agent, road: RoadSpec, notes: list[str]) -> Agent:
    who = "the ego" if agent.is_ego else f"{agent.type} {agent.name}"
    update: dict = {}
    kind = agent.type
    if agent.is_ego and kind not in V.EGO_TYPES:
        notes.append(f"repaired: the ego cannot be a {kind}; it is a car")
        kind = update["type"] = "car"
    action = agent.action
    allowed = V.EGO_ACTIONS if agent.is_ego else V.ACTIONS_BY_TYPE.get(kind, V.VEHICLE_ACTIONS)
    if action not in allowed:
        if kind == "pedestrian":
            fixed = PEDESTRIAN_FOR_VEHICLE_ACTION.get(action, "cross_the_road")
            why = " (it steps into the ego's path)" if action == "block_the_ego" else ""
        else:
            fixed, why = "go_straight", ""
        notes.append(f"repaired: a {'ego' if agent.is_ego else kind} cannot {action}; {who} will {fixed}{why}")
        action = update["action"] = fixed
    road_type = agent.road_type
    if agent.is_ego:
        if road_type != "driving":
            road_type = update["road_type"] = "driving"
        if agent.relative_to_ego is not None:
            update["relative_to_ego"] = None
    elif road_type not in V.ROAD_TYPES_BY_TYPE.get(kind, ()):
        fixed = V.default_road_type(kind)
        notes.append(f"repaired: a {kind} cannot stand on the {road_type}; {who} is on the {fixed}")
        road_type = update["road_type"] = fixed
    if action == "on_the_sidewalk" and road_type != "sidewalk":
        update["road_type"] = "sidewalk"
    position = agent.relative_to_ego
    if not agent.is_ego and position is None:
        update["relative_to_ego"] = position = "front"
        notes.append(f"inferred: {who} has no position; placed at front")
    if action == "block_the_ego" and position in BLOCKER_CANNOT_START:
        notes.append(f"repaired: {who} blocks the ego but starts at {position}, out of the ego's path; "
                     "it blocks from the front")  # a blocker stops in the ego's path: ahead of it or beside it
        position = update["relative_to_ego"] = "front"
    if road.junction is False:
        if action in V.TURN_ACTIONS:
            notes.append(f"repaired: {who} cannot {action} on a road that is not at a junction; it goes straight")
            update["action"] = "go_straight"
        if position in V.JUNCTION_POSITIONS or position == "at_the_destination":
            notes.append(f"repaired: {position} needs a junction, but the road is not at one; {who} is at front")
            update["relative_to_ego"] = "front"
    return agent.model_copy(update=update) if update else agent


def _implied_road(road: RoadSpec, stages, oncoming: frozenset[str], notes: list[str]) -> RoadSpec:
    agents = [a for s in stages for a in s.agents]
    update: dict = {}
    beside = next((a for a in agents if a.relative_to_ego in SIDE_POSITIONS and a.name not in oncoming
                   and a.road_type == "driving" and a.action != "cross_the_road"), None)
    # on a shoulder or a sidewalk, or crossing the road, it needs no lane of its own
    changer = next((a for a in agents if a.action in LANE_CHANGES and a.name not in oncoming), None)
    # (an oncoming vehicle over the centre line changes into the opposite direction's lane: no second lane ours)
    if road.lanes < 2 and (beside or changer):
        update["lanes"] = 2
        why = (f"{beside.name} is at {beside.relative_to_ego}" if beside else
               f"{'the ego' if changer.is_ego else changer.name} changes lane")
        notes.append(f"inferred: lanes >= 2 ({why})")
    if road.junction is None:
        turner = next((a for a in agents if a.action in V.TURN_ACTIONS), None)
        placed = next((a for a in agents if a.relative_to_ego in V.JUNCTION_POSITIONS
                       or a.relative_to_ego == "at_the_destination"), None)
        if turner or placed:
            update["junction"] = True
            why = (f"{'the ego' if turner.is_ego else turner.name} turns" if turner else
                   f"{placed.name} is at {placed.relative_to_ego}")
            notes.append(f"inferred: at junction ({why})")
    return road.model_copy(update=update) if update else road
