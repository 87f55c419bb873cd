"""The ttsgc:* entity Properties: what each agent was asked to do, written into the .xosc by emit and read back
by simulate, so that a scene can be judged from the file alone. This module is the one contract between them.
"""

from __future__ import annotations

PREFIX = "ttsgc:"

ACTION = "action"  # the scene language's action word (turn_left, cross_the_road, ...)
POSITION = "position"  # where it stands relative to the ego ("ego" for the ego)
ROAD_TYPE = "road_type"  # driving | sidewalk | shoulder
BEHAVIOR = "behavior"  # cautious | normal | aggressive
TYPE = "type"  # agent type (car, pedestrian, ...)
STAGE = "stage"  # 0-based stage index
IS_EGO = "is_ego"  # "true" | "false"
MOVEMENT = "movement"  # left | right | straight through a junction, "" when it meets none
TARGET_ROAD = "target_road"  # the road its movement leads to
MAP = "map"
APPROACH = "approach"
# The ego's actions in later stages, "STAGE:ACTION" comma-separated (0-based stages, e.g. "1:change_lane_to_left");
# each is the ego event of that stage's act named by later_event_name.
STAGE_ACTIONS = "stage_actions"

KEYS = (ACTION, POSITION, ROAD_TYPE, BEHAVIOR, TYPE, STAGE, IS_EGO, MOVEMENT, TARGET_ROAD, MAP, APPROACH,
        STAGE_ACTIONS)

# The movement through a junction each action implies; a file whose movement says otherwise contradicts itself.
MOVEMENT_OF_ACTION = {"turn_left": "left", "turn_right": "right", "go_straight": "straight"}
# Actions that aim at the ego's path: a collision with the ego is what the scene asks for.
DANGEROUS_ACTIONS = frozenset({"block_the_ego"})


def property_name(key: str) -> str:
    return PREFIX + key


def properties(values: dict[str, str]) -> list[tuple[str, str]]:
    """(property name, value) in the contract's order; unknown keys are a fault in the caller."""
    unknown = set(values) - set(KEYS)
    if unknown:
        raise KeyError(f"not ttsgc intent keys: {', '.join(sorted(unknown))}")
    return [(property_name(k), values[k]) for k in KEYS if k in values]


def read(named: dict[str, str]) -> dict[str, str]:
    """The intent from a ScenarioObject's properties (name -> value); properties of other tools are ignored."""
    return {name[len(PREFIX):]: value for name, value in named.items() if name.startswith(PREFIX)}


def contradictions(intent: dict[str, str]) -> list[str]:
    """Properties of one entity that say different things, in words; empty when they agree."""
    problems = []
    action, movement = intent.get(ACTION, ""), intent.get(MOVEMENT, "")
    implied = MOVEMENT_OF_ACTION.get(action)
    if implied and movement and movement != implied:
        problems.append(f"{property_name(ACTION)} is {action} but {property_name(MOVEMENT)} is {movement}")
    return problems


def format_stage_actions(actions: list[tuple[int, str]]) -> str:
    return ",".join(f"{stage}:{action}" for stage, action in actions)


def parse_stage_actions(value: str) -> list[tuple[int, str]]:
    """The (stage, action) pairs of a STAGE_ACTIONS property; a malformed item is left out."""
    out = []
    for item in value.split(","):
        stage, _, action = item.strip().partition(":")
        if stage.isdigit() and action:
            out.append((int(stage), action))
    return out


def later_event_name(entity: str, stage: int, action: str) -> str:
    """The event that carries the ego's action in a later stage: the judge times the action from its start."""
    return f"{entity}_{action}_in_stage_{stage}"
