"""Every closed word list of the scenario language, once.

The grammar, the model, the lowering prompts, the emitter and the docs all read these tables, so a word
added here is a word the whole tool knows. Words are spelled as the TTSG paper and its code spell them.
Each table maps a word to a one-line meaning, which the language reference and the LLM prompt show.
"""

from __future__ import annotations

import difflib
import re

AGENT_TYPES: dict[str, str] = {
    "car": "a passenger car",
    "truck": "a heavy goods vehicle",
    "bus": "a city bus",
    "motorcycle": "a motorcycle",
    "cyclist": "a person on a bicycle",
    "pedestrian": "a person on foot",
    "ambulance": "an ambulance (emergency vehicle)",
    "police": "a police car (emergency vehicle)",
    "firetruck": "a fire engine (emergency vehicle)",
}
EMERGENCY_TYPES = frozenset({"ambulance", "police", "firetruck"})
TWO_WHEELER_TYPES = frozenset({"motorcycle", "cyclist"})
VULNERABLE_TYPES = frozenset({"pedestrian", "cyclist"})
EGO_TYPES = frozenset(AGENT_TYPES) - VULNERABLE_TYPES

ACTIONS: dict[str, str] = {
    "go_straight": "follow its lane, straight through any junction",
    "turn_left": "turn left at the junction ahead",
    "turn_right": "turn right at the junction ahead",
    "change_lane_to_left": "change into the adjacent lane on its left",
    "change_lane_to_right": "change into the adjacent lane on its right",
    "stop": "come to a standstill and stay",
    "block_the_ego": "pull into the ego's path and stop there",
    "cross_the_road": "cross the road to the far side",
    "on_the_sidewalk": "walk along the sidewalk",
}
VEHICLE_ACTIONS = frozenset(
    {"go_straight", "turn_left", "turn_right", "change_lane_to_left", "change_lane_to_right", "stop",
     "block_the_ego"})
TURN_ACTIONS = frozenset({"turn_left", "turn_right"})
ACTIONS_BY_TYPE: dict[str, frozenset[str]] = {
    **{t: VEHICLE_ACTIONS for t in AGENT_TYPES},
    "cyclist": VEHICLE_ACTIONS | {"cross_the_road"},
    "pedestrian": frozenset({"cross_the_road", "on_the_sidewalk", "stop"}),
}
EGO_ACTIONS = VEHICLE_ACTIONS - {"block_the_ego"}

BEHAVIORS: dict[str, str] = {
    "cautious": "slower than the limit, keeps a long gap",
    "normal": "drives at the limit, keeps a normal gap",
    "aggressive": "faster than the limit, keeps a short gap",
}
DEFAULT_BEHAVIOR = "normal"
BRAKE_RATE = {"cautious": 3.0, "normal": 5.0, "aggressive": 8.0}  # m/s² of a stop, by behaviour

POSITIONS: dict[str, str] = {
    "front": "ahead of the ego in its lane",
    "back": "behind the ego in its lane",
    "left": "beside the ego in the lane to its left",
    "right": "beside the ego in the lane to its right",
    "front_left": "ahead of the ego in the lane to its left",
    "front_right": "ahead of the ego in the lane to its right",
    "back_left": "behind the ego in the lane to its left",
    "back_right": "behind the ego in the lane to its right",
    "road_of_left_turn": "on the road the ego's left turn leads to, driving towards the junction",
    "road_of_right_turn": "on the road the ego's right turn leads to, driving towards the junction",
    "road_of_straight": "on the road straight across the junction, driving towards the ego (oncoming)",
    "at_the_destination": "on the road the ego is heading to, past the junction",
    "near_the_crosswalk": "next to the crosswalk on the ego's road",
}
JUNCTION_POSITIONS = frozenset({"road_of_left_turn", "road_of_right_turn", "road_of_straight"})

ROAD_TYPES: dict[str, str] = {
    "driving": "a driving lane",
    "sidewalk": "the sidewalk at the road's right edge",
    "shoulder": "the shoulder at the road's right edge",
}
ROAD_TYPES_BY_TYPE: dict[str, frozenset[str]] = {
    **{t: frozenset({"driving", "shoulder"}) for t in AGENT_TYPES},
    "cyclist": frozenset({"driving", "shoulder", "sidewalk"}),
    "pedestrian": frozenset({"sidewalk", "shoulder"}),
}


def default_road_type(agent_type: str) -> str:
    """Where an agent of this type stands when the scene does not say: people on foot on the sidewalk."""
    return "sidewalk" if agent_type == "pedestrian" else "driving"


SIGNALS: dict[str, str] = {
    "traffic_light": "a traffic light controls the approach",
    "stop": "a stop sign",
    "yield": "a yield (give way) sign",
}

OBJECTS: dict[str, str] = {
    "crosswalk": "any pedestrian crossing",
    "parallel_open_crosswalk": "a crossing marked by two parallel lines",
    "ladder_crosswalk": "a crossing marked like a ladder",
    "continental_crosswalk": "a zebra crossing of wide bars",
    "dashed_single_white": "a dashed single white lane line",
    "solid_single_white": "a solid single white lane line",
    "stop_line": "a stop line across the lane",
    "stop_sign_on_road": "STOP painted on the road",
    "speed_N": "a speed limit sign of N km/h, e.g. speed_30",
}
CROSSWALK_OBJECTS = frozenset(
    {"crosswalk", "parallel_open_crosswalk", "ladder_crosswalk", "continental_crosswalk"})
SPEED_SIGN_PATTERN = re.compile(r"speed_([1-9][0-9]{0,2})")
SPEED_SIGN_LIMITS = (5, 200)
COMMON_SPEED_SIGNS = ("speed_30", "speed_40", "speed_60", "speed_90")

WEATHER_CONDITIONS: dict[str, str] = {
    "clear": "clear sky, dry road",
    "cloudy": "overcast, dry road",
    "wet": "clear sky, wet road",
    "wet_cloudy": "overcast, wet road",
    "soft_rain": "light rain",
    "mid_rain": "moderate rain",
    "hard_rain": "heavy rain",
    "fog": "dense fog, short visual range",
    "snow": "falling snow, slippery road",
}
TIMES_OF_DAY: dict[str, str] = {
    "dawn": "just after sunrise, low sun",
    "noon": "midday, high sun",
    "sunset": "late evening, low sun",
    "night": "dark",
}
DEFAULT_CONDITION, DEFAULT_TIME = "clear", "noon"

# Bounds the model enforces (why: beyond them no map of the library or simulator step makes sense).
LANES_RANGE = (1, 6)
GAP_RANGE_M = (0.5, 200.0)
SPEED_RANGE_MPS = (0.0, 70.0)
MAX_AGENTS = 500  # a scene's agents, the ego included: beyond this no player plays it in reasonable time
TRIGGER_TIME_RANGE_S = (0.0, 600.0)
TRIGGER_DISTANCE_RANGE_M = (1.0, 500.0)
ORDER_RANGE = (1, 99)

SPEED_UNITS: dict[str, float] = {"km/h": 1 / 3.6, "m/s": 1.0, "mph": 0.44704}


def is_object(word: str) -> bool:
    """True for a road object word, including any speed sign speed_N within the limits."""
    if word in OBJECTS and word != "speed_N":
        return True
    match = SPEED_SIGN_PATTERN.fullmatch(word)
    return bool(match) and SPEED_SIGN_LIMITS[0] <= int(match.group(1)) <= SPEED_SIGN_LIMITS[1]


def object_words() -> list[str]:
    """The object words a person can write, with the speed signs spelled out."""
    return [w for w in OBJECTS if w != "speed_N"] + list(COMMON_SPEED_SIGNS)


def either(words: list[str]) -> str:
    """'a', 'a or b', 'a, b or c'."""
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " or " + words[-1]


def nearest(word: str, candidates, n: int = 2) -> list[str]:
    """The valid words closest to a misspelt one, best first (for 'did you mean ...?')."""
    pool = list(dict.fromkeys(candidates))
    lowered = word.lower()
    if lowered in pool and lowered != word:
        return [lowered]
    return difflib.get_close_matches(lowered, pool, n=n, cutoff=0.6)

# The keywords of grammar/scenario.lark, which cannot name an agent or a stage, and the unit words that
# follow a number (free as names: they are keywords only right after a number). A test keeps both in step.
RESERVED_WORDS = frozenset({
    "scenario", "weather", "seed", "road", "lanes", "at", "junction", "not", "has", "without", "stage", "ego",
    "on", "behind", "order", "gap", "speed", "after", "when", "within"})
UNIT_WORDS = frozenset({"m", "s"})

# Body of each agent type, metres: length, width, height (what placement keeps apart and the emitter declares).
BODIES: dict[str, tuple[float, float, float]] = {
    "car": (4.5, 1.8, 1.5), "truck": (8.0, 2.5, 3.2), "bus": (12.0, 2.55, 3.2), "motorcycle": (2.2, 0.8, 1.4),
    "cyclist": (1.8, 0.6, 1.7), "pedestrian": (0.5, 0.6, 1.8), "ambulance": (6.0, 2.2, 2.6),
    "police": (4.8, 1.9, 1.5), "firetruck": (9.0, 2.5, 3.3),
}
