"""English -> Scenario by a small semantic parser over a data lexicon (the default lowering, no API key).

The text is read the way a person reads it, not by spotting keywords:
- words become lexicon units (ttsgc/lowering/lexicon/*.txt: multiword phrases, base forms, British spellings);
- the text splits into stages at sequence words and conditions ("then", "once the light turns green", "when the
  ego reaches the junction"), stages into clauses ("while", "and" after a predicate, relative "which/who");
- each clause has a subject, predicates and objects: passive voice ("is approached by an ambulance"), reduced
  relatives ("a cyclist riding alongside swerves..."), coordination ("a bus and a truck stop"), possessives
  ("into the ego's lane");
- noun phrases are tracked as entities: re-mentions ("the truck", "it", "both", "the other car"), counted groups
  as constraints ("three cars including the ego" is the ego and two cars, whom "the car in front" and "the car
  behind" then name);
- positions are composed once the whole text is read (side x ahead/behind x which road), against the junction
  context and the ego's manoeuvre;
- the draft goes through the one plan inference (infer.py), which adds what the agents imply about the road
  and repairs what cannot be, with a note for each.
Scene-kind templates (templates/kinds/) fill a scene only when a kind is asked for as the scene ("create a
scene for daily traffic"). Content words no rule places are reported with the nearest known word.
"""

from __future__ import annotations

import itertools
import re
from bisect import bisect_left, bisect_right
from contextvars import ContextVar
from dataclasses import dataclass, field, replace
from functools import lru_cache

from ttsgc import vocabulary as V
from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.lowering.infer import infer_plan, language_allows_later_ego
from ttsgc.lowering.narration import NARRATORS_DRIVER, OTHER_PEOPLE, read_narration
from ttsgc.lowering.lexicon import (SIGNAL_COLOURS, TOO_LARGE, Match, Token, _lookup, _names_agent, _verbs, bodies,
                                    categories, compound_heads, crews, lexicon, loose_names, matches, one_line_records,
                                    read_number, rule_before_its_scene, tokenize, typologies)
from ttsgc.lowering.sampling import OpenChoices
from ttsgc.scenario import Agent, Comment, RoadSpec, Scenario, Speed, Stage, Trigger, Weather, find_problems


class LoweringError(TtsgcError):
    exit_code = ExitCode.LOWERING_FAILED


NAME_PREFIX = {"car": "c", "truck": "t", "bus": "b", "motorcycle": "m", "cyclist": "k", "pedestrian": "p",
               "ambulance": "a", "police": "po", "firetruck": "f"}
MAX_AGENTS_PER_MENTION = 12
BARE_PLURAL_COUNT = 2  # "cars pass", "a crowd of children": the gold conventions' count for an unstated size
# What a sentence leaves open, chosen in one place (the corpus conventions' readings; a seeded sampler of the
# unspecified can vary these and nothing else).
UNSPECIFIED = OpenChoices({  # other seeds draw from templates/unspecified.toml (sampling.py)
    "side_of_a_crossing_road": "left",  # "a vehicle from a perpendicular direction"
    "side_of_an_overtaker": "left",
    "side_of_a_cut_in": "left", "side_of_a_cyclist_cut_in": "right",
    "side_beside_a_vehicle": "left", "side_beside_a_person": "right",
    "side_of_a_sidewalk_walker": "right",
    "turn_direction": "left",  # "turns" with no side
    "ego_lane_change_direction": "left",  # "the ego pulls out to pass"
})

VAGUE_COUNTS = {"some", "few", "several", "multiple", "various", "a"}
PLAIN_PEOPLE = {"person", "someone", "somebody", "man", "woman", "lady", "kid", "lad", "teen", "teenager", "young man",
                "young woman", "old man", "old woman", "old lady", "old guy", "old timer", "old gentleman", "fellow",
                "gentleman", "elderly man", "elderly woman", "elderly lady", "youngster", "gent", "old gent",
                "elderly gent", "lass"}
# people named by who they are, not by a role: on foot unless the text puts them at the wheel
DRIVERS = PLAIN_PEOPLE | {"driver", "learner", "learner driver", "motorist", "guy", "dude", "bloke", "chap", "mate",
                          "fella", "idiot", "jerk", "moron", "lunatic", "nutter", "maniac", "muppet", "numpty",
                          "plonker", "pillock", "wally", "clown", "prat", "twit", "nutcase", "boy racer"}
SCENERY_PREPOSITIONS = {"between", "past", "among", "amongst", "through", "around", "beside", "by", "of", "in",
                        "with"}
DEFINITE = {"the", "this", "that", "these", "those", "said"}
INDEFINITE = {"a", "an", "another", "some", "any", "one"}
PRONOUNS = {"it", "they", "them", "he", "she", "him", "her", "itself", "both", "former", "latter"}
NEGATIONS = {"no", "not", "without", "never", "none", "neither", "nor", "lacking", "absent", "unmarked", "non"}
REMOVED = {"removed", "scrapped", "dismantled", "missing"}  # "the council removed the stop sign": none there now
AUXILIARIES = {"is", "are", "was", "were", "be", "been", "being", "am", "will", "would", "can", "could", "does",
               "do", "did", "has", "have", "had", "should", "must", "may", "might", "shall", "keeps", "keep",
               "then", "also", "to", "and"}
CLAUSE_WORDS = {"while", "whilst", "as", "when", "whereas", "but", "although", "though", "because", "so", "where",
                "and", "or", "which", "who", "that", "whose", "whom", "until", "before", "if"}
LIGHT_PARTICIPLES = {"made", "taken", "performed", "executed", "done", "initiated", "attempted", "carried", "out",
                     "being", "been"}
SUBORDINATE = {"if", "when", "as", "while", "whilst", "because", "although", "though", "until", "before"}
RELATIVES = {"which", "who", "that", "whose", "whom"}
# Relational verbs: (subject's place relative to the object) when one of them is the ego.
FOLLOWING = {"follow", "tailgate", "trail", "chase", "pursue", "rear end", "rear", "tail"}
HIDING = {"hide", "conceal", "occlude", "mask", "obscure"}
LEADING = {"lead", "precede"}
OVERTAKING = {"overtake", "pass", "past", "squeeze", "filter", "undertake", "around", "split", "splitting"}
ACTION_RANK = {  # the more specific predicate wins among equally strong ones
    "sideways_left": 6, "sideways_right": 6, "block": 9, "cut_in": 7, "lane_left": 6, "lane_right": 6,
    "lane_change": 6, "turn_left": 8, "turn_right": 8, "turn": 5, "u_turn": 5, "cross": 4, "stop": 3, "walk": 2,
    "go_straight": 1, "move": 1,
}
SIDES = ("left", "right")
OTHER_SIDE = {"left": "right", "right": "left"}
COMPASS_OPPOSITE = {"compass_north": "compass_south", "compass_south": "compass_north",
                    "compass_east": "compass_west", "compass_west": "compass_east"}
COMPASS_LEFT = {"compass_north": "compass_west", "compass_east": "compass_north", "compass_south": "compass_east",
                "compass_west": "compass_south"}  # the side on the left of a heading
TALKED_ABOUT = {"learn", "how to", "avoid", "determine", "negotiate", "learn how to", "must learn", "let", "to let"}
SIDE_MEANINGS = {"side_left", "side_right", "front_left", "front_right", "back_left", "back_right"}
LANE_WORDS = {"lane", "lanes", "adjacent", "outside", "inside", "fast", "slow", "overtaking", "far", "farside",
              "near", "nearside", "side"}
INVERSE = {"behind": "ahead", "ahead": "behind", "side_left": "side_right", "side_right": "side_left",
           "level": "level"}
LANE_STEERING = {"move", "steer", "veer", "swerve", "pull", "ease", "inch", "creep", "slide", "skid", "swing", "duck",
                 "tuck", "slip", "hop", "nip", "dive"}  # "... into the left lane": a lane change
STEERING = {"move", "steer", "ease", "inch", "creep", "slide", "skid", "veer", "swerve", "pull", "merge", "shift", "go",
            "head", "drift", "swing"}
RUSHING = {"run", "dash", "dart", "rush", "sprint", "race", "speed", "zoom", "barge", "jump", "barrel", "hurtle",
           "tear"}


@dataclass
class Lowered:
    scenario: Scenario
    unknown: list[str]  # words no rule placed, each with the nearest known word when there is one
    kind: str | None = None  # the scene kind a template filled in
    notes: list[str] = field(default_factory=list)  # every inference and repair, also in the scene's comments


@dataclass
class Unit:
    """A lexicon phrase or a single token, in text order."""

    start: int
    end: int
    category: str  # a lexicon category, or "word", "number", "comma"
    meaning: str
    tokens: tuple[Token, ...]

    @property
    def word(self) -> str:
        return self.tokens[0].word

    @property
    def base(self) -> str:
        return " ".join(t.base for t in self.tokens)


@dataclass(eq=False)  # one entity is itself only (keys are never shared); comparing every field made each
class Entity:  # `e in r.entities` cost more with every field added
    key: int
    type: str
    is_ego: bool
    stage: int
    count: int = 1
    head: str = ""
    generic: bool = False  # "vehicles", "road users": a group others may be members of
    group_open: int = 0  # members of a counted group not yet named by a re-mention
    features: set = field(default_factory=set)  # position features, see positions.txt
    relative_to: "Entity | None" = None  # "in front of a truck": at the truck's place
    uncounted: bool = False  # a plural said with no count ("parked cars", "cars parked both sides")
    relative_how: str = ""  # where it is from that one: "ahead", "behind", "level" ("behind the coach"), or how
    # it drives by it: "follows", "leads"
    actions: list = field(default_factory=list)  # (stage, strength, rank, order, class, direction)
    behavior: str | None = None
    road_type: str | None = None
    trigger: Trigger | None = None
    speed: Speed | None = None
    gap_m: float | None = None
    parent: "Entity | None" = None  # the counted group it was taken from
    label: str = ""  # the name the text gives it ("SV1")
    includes_ego: bool = False  # "three cars including the ego": the ego shares what the group does
    aliases: set = field(default_factory=set)  # short names given in brackets ("(GVT)")
    headline: bool = False  # named bare in the text's first sentence, as a heading names it ("Jaywalker mid-block.")
    definite: bool = False  # first named with 'the', as someone known to the speaker ("the kids were fascinated")
    implied: bool = False  # never named, only done ("cut-in from the right lane ahead"): someone did it
    said_at: int = -1  # the token it was first named at
    named_of: "Entity | None" = None  # the counted group it is named as included in ("three cars, including a
    # taxi"): where the group is and what it does, unless said of this one
    listed_after: "Entity | None" = None  # the 'one ...' list item before it: does what that one does, unless
    # said to do otherwise ("one cyclist waits on the left and one on the right")
    waits_to_turn: tuple = ()  # "a car is waiting to turn right": (stage, action, direction) of the turn to come,
    # on its own way
    goes_on: set = field(default_factory=set)  # later stages its own sentence goes on into ("passes the ego, then
    # cuts in")
    came_along: bool = False  # "coming from the right": said to come along from a side (not "cut in from the left")


@dataclass
class _Reader:
    tokens: list[Token]
    units: list[Unit]
    notes: list[str] = field(default_factory=list)
    used: set = field(default_factory=set)  # token indexes some rule placed
    entities: list[Entity] = field(default_factory=list)
    order: int = 0
    keys: int = 0  # entity keys handed out
    clause_mentions: list = field(default_factory=list)  # entities named so far in the clause being read
    scenery: set = field(default_factory=set)  # nouns said as scenery ("between parked cars"), said so again later
    last_mentions: list = field(default_factory=list)  # those named in the clause read before
    after_verbless: bool = False  # the clause before named agents without a verb ("ambulance behind, ...")
    unnamed_subject: bool = False  # the clause before had a subject that is no agent ("a deer stood in the ditch")
    surface: list = field(default_factory=list)  # the last clause's grammatical subject (the ego, in "the ego is
    # overtaken by a motorcycle before it turns": "it" is the ego)
    listed_one: tuple | None = None  # (agent, sentence) last named as a 'one ...' list item: the list may go on
    passive: object = None  # the last clause with a passive's doer ('overtaken by a van'): 'and a bus' may follow
    # past a clause break ("one car in front, one on the left and one on the right")
    owned: bool = False  # the text opened on the vehicle its teller owns: "the vehicle" is that one
    typical: bool = False  # the text names road users only by their kinds, in what they habitually do
    staged: bool = False  # the text goes on to a later stage ("then", "once ...")
    plain_brakes: set = field(default_factory=set)  # the tick of each stop said only as braking, with no halt
    braked: set = field(default_factory=set)  # the order of each stop said only as braking ("the bus brakes hard"):
    # no stop if that one turns out to be the ego

    def mark(self, unit: Unit) -> None:
        self.used.update(range(unit.start, unit.end))

    def tick(self) -> int:
        self.order += 1
        return self.order

    def new_key(self) -> int:
        """A key no other entity has had: entities are removed as they are found to be one (appositions,
        headings), so the count of those left could name two."""
        self.keys += 1
        return self.keys - 1


# -- units --------------------------------------------------------------------------------------------------

def _subject_vehicle_is_ego(tokens: list[Token]) -> bool:
    """Crash-typology papers call the vehicle under study the subject vehicle (SV) and the others principal other
    vehicles (POV); scenario specs that also name an ego use SV1, SV2 for surrounding vehicles. 'Into the ego
    lane, front right of SV' names a lane, not an ego; 'the SV ahead in the ego lane' places a surrounding one."""
    placed = any(t.word == "sv" and k + 1 < len(tokens) and tokens[k + 1].word in (
        "ahead", "behind", "in", "on", "beside", "alongside", "next", "travelling", "traveling", "drives", "driving")
                 for k, t in enumerate(tokens))
    return any(t.word == "sv" and not t.label for t in tokens) and not any(
        t.word == "ego" and (placed or k + 1 == len(tokens) or tokens[k + 1].word not in ("lane", "lanes", "path"))
        or (t.word == "sv" and t.label) for k, t in enumerate(tokens))


def _first_numbered_vehicle(tokens: list[Token]) -> str:
    """Collision reports number the vehicles (V1, Vehicle 2, Unit 1) and tell the scene of V1: with no ego and no
    speaker named, V1 is the ego ('' when the text names one, or numbers no vehicle 1). An adjuster's 'Vehicle B
    (insured)', 'V1 (our insured, a Camry)' names the one the claim is told from: that one is the ego, and 'our'
    before the insured is no speaker on the road."""
    insured = next((t.label for k, t in enumerate(tokens) if t.label and k + 2 < len(tokens) and
                    tokens[k + 1].word == "," and "insured" in {x.word for x in tokens[k + 2:k + 4]}), "")
    if any(t.word in ("ego", "sv", "vut", "sut", "av") or t.word in SPEAKERS and not (
            insured and t.word == "our" and tokens[k + 1].word == "insured") for k, t in enumerate(tokens)):
        return ""
    return insured or ("v1" if any(t.label == "v1" for t in tokens) else "")


def _without_the_insured_aside(tokens: list[Token]) -> list[Token]:
    """'V1 (our insured, a Camry) was northbound': once V1 is read as the ego, the aside that made it so is said;
    left in, it stands between the ego and what it is ('V1, a Camry, was')."""
    for k, t in enumerate(tokens[:-3]):
        if t.word == "ego" and tokens[k + 1].word == ",":
            end = k + 2 + (tokens[k + 2].word in ("our", "the"))
            if tokens[end].word == "insured" and not tokens[end].possessive:  # (not "V1, the insured's Honda,")
                comma = end + 1 < len(tokens) and tokens[end + 1].word == ","
                goes_on = comma and end + 2 < len(tokens) and tokens[end + 2].word in ("a", "an")  # "..., a Camry,"
                kept = tokens[:k + 1 + goes_on] + tokens[end + 1 + comma:]
                return [replace(x, index=i) for i, x in enumerate(kept)]
    return tokens


EMERGENCY_SIGNS = {"siren", "sirens", "blue", "blues", "emergency", "ambulance", "paramedic", "paramedics", "fire",
                   "police", "beacon", "beacons", "responding"}


def _ev_as_ego(tokens: list[Token]) -> list[Token]:
    """EV read as the ego's own word where it names the ego ('the lane the EV merges into' is the ego's target
    lane)."""
    if not _ego_vehicle_abbreviated(tokens, matches(tokens)):
        return tokens
    return [replace(t, word="ego", base="ego") if t.word == "ev" and not t.label else t for t in tokens]


def _ego_vehicle_abbreviated(tokens: list[Token], found) -> bool:
    """Scenario catalogues write EV for the ego vehicle ('EV: turns right', 'in the EV lane'); elsewhere EV is an
    emergency vehicle, which comes with its sirens or blue lights. EV is the ego where nothing speaks of an
    emergency, and either nothing else names the ego or a line starts with it ('EV: turns right out of ...')."""
    evs = [t for t in tokens if t.word == "ev" and not t.label]
    keyed = any(t.index == 0 or tokens[t.index - 1].sentence != t.sentence for t in evs)
    return bool(evs) and (keyed or not any(m.category == "agents" and m.meaning == "ego" for m in found)) and \
        not any(t.word in EMERGENCY_SIGNS for t in tokens)


LEFT_HAND_TRAFFIC = {"motorway", "carriageway", "hgv", "constable", "footway", "pavement", "indicate", "indicated",
                     "indicating", "indicator", "indicators", "uk", "britain", "england", "scotland", "wales", "artic",
                     "pelican", "puffin", "toucan", "footpath", "ute", "lollipop", "nearside", "offside", "bakkie",
                     "bakkies", "gardai", "boreen", "angkot", "ojek", "matatu"}
# "without indicating", a pelican crossing, a ute, a lollipop lady, the nearside and the offside, a bakkie, the
# gardai, an angkot: keep-left countries' words (a test protocol's nearside is excluded by its own words)
_KEEPS_LEFT: ContextVar[bool] = ContextVar("keeps_left", default=False)
_EGO_SPEAKS: ContextVar[bool] = ContextVar("ego_speaks", default=False)  # the ego is only ever "I" or "we"


def _overtaking_side(key: str) -> str:
    """The side an unsaid overtaking takes: the conventions' (right-hand traffic) unless the text keeps left."""
    side = UNSPECIFIED[key]
    return OTHER_SIDE[side] if _KEEPS_LEFT.get() else side
TEST_PROTOCOL = {"vut", "target", "ncap", "kmh", "km", "kph", "epta", "ebta", "cpnc", "cpfa", "cpla", "gvt", "sut"}


def _drives_on_the_left(tokens: list[Token]) -> bool:
    """The nearside is the kerb side: the left where traffic keeps left (British statements speak of motorways,
    lorries and mph), the right in test protocols written for right-hand traffic (VUT, targets, km/h)."""
    words = {t.word for t in tokens}
    road_numbers = any(t.word in ("a", "m", "b") and (t.label or k + 1 < len(tokens) and
                                                      tokens[k + 1].word.isdigit() and t.word != "a")
                       for k, t in enumerate(tokens))
    said = any([t.base for t in tokens[k:k + 4]] == ["drive", "on", "the", "left"] for k in range(len(tokens)))
    # "we drive on the left here"
    return bool(words & LEFT_HAND_TRAFFIC or road_numbers or said) and not words & TEST_PROTOCOL


EXIT_TURNS = {"turn_left": "turn_right", "turn_right": "turn_left"}


def _kerb_sides(tokens: list[Token], units: list[Unit]) -> list[Unit]:
    """Where traffic keeps left the kerb is on the left: the nearside and the inside are left, the offside right,
    and a roundabout's first exit is a left turn, its third a right one (the lexicon says them for keeping right)."""
    if not _drives_on_the_left(tokens):
        return units
    swap = {"side_right": "side_left", "side_left": "side_right", "from_right": "from_left",
            "from_left": "from_right"}
    out = []
    for u in units:
        words = [t.word for t in u.tokens]
        kerb = "nearside" in words or "near" in words and "side" in words or "inside" in words or \
            bool({"kerb", "curb", "kerbside", "curbside"} & set(words)) or \
            "lane" in words and bool({"bike", "cycle", "bicycle"} & set(words))
        far = "offside" in words or "off" in words and "side" in words or "median" in words
        if u.category == "positions" and u.meaning in swap and (kerb and u.meaning in ("side_right", "from_right")
                                                               or far and u.meaning in ("side_left", "from_left")):
            u = Unit(u.start, u.end, u.category, swap[u.meaning], u.tokens)
        if u.category == "actions" and u.meaning == "lane_right" and [t.base for t in u.tokens][:2] in (
                ["pull", "over"], ["pull", "in"]) and not {"left", "right"} & set(words):
            u = Unit(u.start, u.end, u.category, "lane_left", u.tokens)  # "pulls over to let it through": to the kerb
        if u.category == "actions" and u.meaning in EXIT_TURNS and "exit" in words and \
                not {"left", "right"} & set(words):
            u = Unit(u.start, u.end, u.category, EXIT_TURNS[u.meaning], u.tokens)  # "take the third exit"
        out.append(u)
    return out


def _exit_named_by_side(units: list[Unit]) -> list[Unit]:
    """'take the first exit, left': a roundabout exit said by number, then by side; the side the text names is the
    turn, whichever side the traffic keeps to."""
    out = list(units)
    for k, u in enumerate(units):
        if u.category != "actions" or u.meaning not in EXIT_TURNS or "exit" not in [t.word for t in u.tokens] or \
                {"left", "right"} & {t.word for t in u.tokens}:
            continue
        j = k + 1 + (k + 1 < len(units) and units[k + 1].category == "comma")
        side = units[j] if j < len(units) else None
        if side is not None and len(side.tokens) == 1 and side.tokens[0].word in ("left", "right"):
            out[k] = Unit(u.start, u.end, u.category, f"turn_{side.word}", u.tokens)
            out[j] = Unit(side.start, side.end, "word", side.word, side.tokens)  # said of the exit, no one's place
    return out


LANE_MOVING = {"move", "pull", "go", "swing", "steer", "drift", "weave", "switch", "shift", "slide", "ease", "nudge",
               "cut", "merge", "change"}


def _from_one_lane_into_another(units: list[Unit]) -> list[Unit]:
    """'moves from the left lane into the right lane', 'pulls from the right lane into the middle lane': a move said
    with the lane it leaves and the one it enters is a lane change towards the second (the middle one lies away
    from the side it leaves)."""
    out = list(units)
    for k, u in enumerate(units[:-2]):
        source = units[k + 1]
        moving = u.category == "actions" and u.meaning in ("move", "cut_in", "lane_change") or \
            u.category == "word" and u.base in LANE_MOVING
        if not moving or source.category != "positions" or source.tokens[0].word != "from" or \
                source.tokens[-1].word != "lane":
            continue
        target: list[str] = []
        for x in units[k + 2:k + 6]:
            target += [t.word for t in x.tokens]
            if "lane" in target:
                break
        if not target or target[0] not in ("into", "to", "onto") or "lane" not in target:
            continue
        leaves = {t.word for t in source.tokens} & {"left", "right"}
        side = next((w for w in ("left", "right") if w in target), None)
        if side is None and set(target) & {"middle", "centre", "center"} and len(leaves) == 1:
            side = "right" if leaves == {"left"} else "left"
        if side is not None:
            out[k] = Unit(u.start, u.end, "actions", f"lane_{side}", u.tokens)
    return out


GROUP_ENDS = (["at", "the", "back"], ["at", "the", "rear"], ["at", "the", "end"], ["at", "the", "tail"],
              ["at", "the", "front"], ["at", "the", "head"])


def _at_an_end_of_the_group(units: list[Unit]) -> list[Unit]:
    """'five vehicles including a concrete mixer at the back': the back of the five, where the member goes among
    them, not behind the ego."""
    out = list(units)
    for k, u in enumerate(units[2:], 2):
        if u.category == "positions" and [t.word for t in u.tokens] in GROUP_ENDS and \
                units[k - 1].category == "agents" and \
                any(x.word in ("including", "incl") for x in units[max(0, k - 4):k - 1]):
            out[k] = Unit(u.start, u.end, "word", u.word, u.tokens)
    return out


def _indicators_are_no_lights(units: list[Unit]) -> list[Unit]:
    """'didn't use his signal', 'with its right signal on': a driver's own signal is the indicator, no traffic
    light at the junction (but 'our signal was green' is the light facing us)."""
    out = list(units)
    for k, u in enumerate(units):
        if u.category != "road" or u.meaning != "traffic_light" or [t.word for t in u.tokens] not in (
                ["signal"], ["signals"]) or k == 0:
            continue
        before = [x.word for x in units[max(0, k - 2):k]]
        if any(t.word in ("green", "red", "amber", "yellow") for x in units[k + 1:k + 4] for t in x.tokens):
            continue  # "our signal was green": the light facing us
        owned = OWNERS | POSSESSIVES  # "his signal", "its right signal": an indicator
        if before[-1:] and before[-1] in owned or before[-2:-1] and before[-2] in owned and \
                before[-1] in ("left", "right", "indicator"):
            out[k] = Unit(u.start, u.end, "word", u.word, u.tokens)
    return out


def _signalled_by_a_driver(units: list[Unit]) -> list[Unit]:
    """'I signalled and moved out into the right lane', 'the host vehicle signals and changes lanes': 'signalled'
    right after the one who did it is their indicating, not a signalled junction."""
    return [Unit(u.start, u.end, "actions", "try", u.tokens)
            if k > 0 and u.category == "road" and len(u.tokens) == 1 and u.tokens[0].word in (
                "signaled", "signalled", "signals", "signaling", "signalling")
            and _a_signaller_before(units, k) and not _signalled_to(units, k)
            else u for k, u in enumerate(units)]


def _a_signaller_before(units: list[Unit], k: int) -> bool:
    """Who signals: one named ('the van signals'), a pronoun ('neither of them signals'), or a noun read later
    whose signal leads into its next move ('the rider signals and turns left')."""
    before = units[k - 1]
    return before.category == "agents" and before.meaning != "none" or \
        before.word in ("it", "he", "she", "they", "them", "who") or \
        before.category == "word" and k >= 2 and units[k - 2].word == "the" and k + 2 < len(units) and \
        units[k + 1].category == "word" and units[k + 1].word == "and" and units[k + 2].category == "actions"


def _signalled_to(units: list[Unit], k: int) -> bool:
    """'the officer signals the ego to stop', 'signals to us': an order given to someone, not indicating."""
    j = k + 1
    while j < len(units) and units[j].word in ("the", "a", "an", "us", "me", "him", "her", "them"):
        if units[j].word in ("us", "me", "him", "her", "them"):
            return True
        j += 1
    return j < len(units) and (units[j].category == "agents" or units[j].word == "to")


RELATIONS = {"wife", "husband", "friend", "brother", "sister", "buddy", "pal", "teacher", "neighbour", "neighbor",
             "girlfriend", "boyfriend", "colleague", "coworker", "partner"}


def _relations_on_the_pavement(units: list[Unit]) -> list[Unit]:
    """'His wife is standing on sidewalk at right side', 'their teacher is waiting on the sidewalk': someone's
    relation placed on the pavement in the same clause is a pedestrian there (said elsewhere, 'my wife was in the
    car', 'I told my friend', no one on the road)."""
    out = list(units)
    for k, u in enumerate(units[1:], 1):
        if u.category != "word" or u.word not in RELATIONS or units[k - 1].word not in ("his", "her", "their") or any(
                a.category in ("numbers", "number") and b.category == "agents" and b.meaning == "pedestrian"
                for a, b in zip(units[:k], units[1:k])):
            continue  # ("two kids waiting ... one of them darted out ... her friend stayed": the other one)
        for x in units[k + 1:k + 8]:
            if x.tokens[0].sentence != u.tokens[0].sentence or x.category in ("agents", "comma", "sequence"):
                break
            if x.category == "positions" and x.meaning == "sidewalk" or \
                    x.category == "actions" and any(t.word in SIDEWALK_WORDS for t in x.tokens):
                out[k] = Unit(u.start, u.end, "agents", "pedestrian", u.tokens)  # ("is standing on sidewalk")
                break
    return out


MET_VERBS = {"handled", "handles", "handle", "handling", "survived", "avoided", "witnessed", "managed", "spotted",
             "caught", "nailed", "saw"}  # what one does to a manoeuvre someone else makes


def _cut_in_named_as_a_case(units: list[Unit]) -> list[Unit]:
    """'I need a highway cut-in for the ACC tests', 'I'm trying to reproduce a cut-in at night': a cut-in named with
    an article as what the speaker asks for is the case's name; the cut-in is someone else's, said after."""
    out = list(units)
    for k, u in enumerate(units):
        if u.category != "actions" or u.meaning != "cut_in" or k == 0:
            continue
        j = k - 1
        while j > 0 and units[j].category in ("road", "behaviours", "word") and units[j].word not in (
                "a", "an", "the", ",", "and") and k - j < 3:
            j -= 1
        met = j > 0 and units[j - 1].tokens[-1].word in MET_VERBS  # "FSD handled a cut-in like a champ"
        if units[j].category != "word" or units[j].word not in ("a", "an", "the") or not any(
                x.category == "agents" and x.meaning == "ego" and (x.tokens[0].word in ("i", "we") or met)
                and x.tokens[0].sentence == u.tokens[0].sentence for x in units[:j]):
            continue
        out[k] = Unit(u.start, u.end, "word", "cut in", u.tokens)
    return out


QUEUE_PASSED = {"of", "past", "along", "alongside", "beside", "by", "through", "passing", "overtaking", "round",
                "around"}  # a queue after these is a noun: the place one passes, not a verb of one's own


def _a_queue_run_into(units: list[Unit]) -> list[Unit]:
    """'ran into the back of a queue', 'ploughed into the rear of the queue', 'filtering up the outside of a long
    queue', 'past the queue': the queue that was hit or passed, a noun; those in it wait, and the one that hit or
    passed it did not stop to join it."""
    out = list(units)
    for k, u in enumerate(units):
        if k < 2 or u.category != "actions" or u.tokens[0].word not in ("queue", "queues"):
            continue
        j = k - 1
        while j > 0 and units[j].category == "word" and units[j].word not in ("a", "the") and \
                units[j].word.isalpha() and j > k - 3:
            j -= 1  # "a long queue", "the stationary queue": its adjectives
        if units[j].word not in ("a", "the", "this", "that"):
            continue
        before = [t.word for t in units[j - 1].tokens]
        if before[-2:] in (["back", "of"], ["rear", "of"], ["tail", "of"], ["end", "of"]) and \
                units[j - 1].category == "actions" or before[-1] in QUEUE_PASSED:
            out[k] = Unit(u.start, u.end, "word", u.tokens[0].word, u.tokens)
    return out


def _units(tokens: list[Token]) -> list[Unit]:
    units = _exit_named_by_side(_kerb_sides(tokens, _wanted_of_the_ego(_entering_in(_ages(_time_stamps(
        _read_units(tokens)))))))
    units = _unknown_makes(tokens, _street_names(tokens, _with_absolutes(units)))
    for reread in (_passengers_on_foot, _other_scenarios_named, _aborted_lane_changes, _signalled_by_a_driver,
                   _at_an_end_of_the_group, _from_one_lane_into_another, _indicators_are_no_lights,
                   _relations_on_the_pavement, _cut_in_named_as_a_case, _lane_change_to_a_side_said_after,
                   _the_path_of_another, _swerved_into_a_road, _pulled_in_or_out, _one_more_of_the_kind,
                   _a_lane_then_whom_it_is_behind, _paint_of_one, _a_label_then_what_it_is, _a_queue_run_into,
                   _one_named_by_what_they_ride, _words_said_of_a_noun):
        units = reread(units)  # a unit read again by its neighbours, in this order
    return units


ACROSS_WAYS = {"across", "over", "through", "outside", "beside", "alongside"}


def _words_said_of_a_noun(units: list[Unit]) -> list[Unit]:
    """'a fire engine right across the road', 'parked right outside': 'right' before a preposition after the one
    placed is how far, no side ('turned right across the road' keeps its turn); 'driven by' after a noun says
    who drove it, no verb; a plural's possessive after 'a' names a kind of place; 'a dark sedan' is its colour;
    people who 'follow ... across' cross."""
    for k, u in enumerate(units[1:-1], 1):
        said = [t.word for t in u.tokens]
        after = k + 1 + (said in (["driven"], ["ridden"]))  # the first unit after "driven by"
        by = said in (["driven", "by"], ["ridden", "by"]) or \
            said in (["driven"], ["ridden"]) and units[k + 1].word == "by"
        if u.category == "actions" and by and after < len(units) and \
                (units[k - 1].category == "agents" or units[k - 1].word in ("was", "is", "were", "are")) and \
                units[after].word not in ("me", "us", "i", "we", "myself"):
            units[k] = Unit(u.start, u.end, "word", "driven", u.tokens)  # "an HGV driven by the defendant", "the
            # former was driven by a nurse": who was at its wheel, said of the noun, no verb of the clause, and no
            # one of the scene ("a sedan driven by U": not 'you')
            j = after
            while j < len(units) and j < after + 4 and units[j].category == "word":
                j += 1  # "by an off-duty nurse": over its article and adjectives
            if j < len(units) and units[j].category == "agents" and units[j].meaning in ("ego", "pedestrian", "none"):
                units[j] = Unit(units[j].start, units[j].end, "word", "driver", units[j].tokens)
        if u.category == "actions" and u.tokens[0].base == "follow" and any(
                x.word in ("across", "over") and x.tokens[0].sentence == u.tokens[0].sentence
                for x in units[k + 1:k + 4]) and any(
                x.category == "agents" and x.meaning in ("pedestrian", "cyclist") for x in units[max(0, k - 3):k]):
            units[k] = Unit(u.start, u.end, "actions", "cross", u.tokens)  # "two cyclists follow the person
            # across": they cross too
        if u.category == "weather" and [t.word for t in u.tokens] in (["dark"], ["light"]) and \
                units[k + 1].category == "agents" and units[k - 1].word in DEFINITE | INDEFINITE:
            units[k] = Unit(u.start, u.end, "word", u.word, u.tokens)  # "a dark sedan": its colour, no night
        if u.category == "agents" and u.tokens[-1].plural and u.tokens[-1].possessive and \
                units[k - 1].word in ("a", "an") and units[k + 1].category == "word":
            units[k] = Unit(u.start, u.end, "word", u.word, u.tokens)  # "a builders' merchant", "a children's
            # playground": the kind of place, nobody in it
        if u.category == "positions" and [t.word for t in u.tokens] == ["right"] and \
                units[k + 1].word in ACROSS_WAYS and (units[k - 1].category == "agents" or units[k - 1].word in (
                    "was", "were", "is", "are", "stood", "sat", "parked", "stopped", "stationary")):
            units[k] = Unit(u.start, u.end, "word", "just", u.tokens)  # "a fire engine right across the road"
    return units


RIDERS_NAMES = {"guy", "fellow", "fella", "man", "lad", "dude", "bloke", "chap", "wala", "walla", "wallah", "uncle",
                "bhaiya", "woman", "lady", "boy", "kid"}
RIDDEN_TYPES = {"car", "truck", "bus", "motorcycle", "cyclist"}


def _one_named_by_what_they_ride(units: list[Unit]) -> list[Unit]:
    """'one motorbike fellow', 'a scooter guy', 'the auto wala': one named by the vehicle before them is that
    vehicle's rider or driver, the vehicle on the road (not 'a police man', on foot)."""
    out: list[Unit] = []
    for u in units:
        last = out[-1] if len(out) > 1 else None
        counted = last is not None and (out[-2].word in DEFINITE | INDEFINITE or out[-2].category == "numbers" or
                                        u.tokens[-1].plural)  # ("even okada men respect am": riders, said bare)
        if counted and u.category == "agents" and u.base in RIDERS_NAMES and last.category == "agents" and \
                last.meaning in RIDDEN_TYPES and not last.tokens[-1].plural and not last.tokens[-1].possessive and \
                u.start == last.end and u.tokens[0].sentence == last.tokens[-1].sentence:  # (not "on the bike.
            # Woman with her lads": bare, and a sentence apart)
            out[-1] = Unit(last.start, u.end, "agents", last.meaning, last.tokens + u.tokens)
            continue
        out.append(u)
    return out


TURNED_INTO = {("petrol", "station"), ("gas", "station"), ("car", "park"), ("parking", "lot"), ("driveway",),
               ("side", "road"), ("side", "street"), ("estate",), ("industrial", "estate"), ("retail", "park"),
               ("yard",), ("entrance",), ("forecourt",), ("garage",), ("alley",), ("junction",)}
ORDINAL_STREETS = {"first", "second", "third", "fourth", "fifth", "sixth", "seventh", "eighth", "ninth", "tenth"}


def _into_a_road(units: list[Unit], k: int) -> bool:
    """'into Mill Road', 'onto 2nd', 'into the petrol station': a road or a place off it, not a lane."""
    if k >= len(units) or units[k].category != "word" or units[k].word not in ("into", "onto"):
        return False
    rest = [x for x in units[k + 1:k + 4] if x.tokens[0].sentence == units[k].tokens[0].sentence]
    words = [x.word for x in rest]
    if words[:1] and words[0] in ORDINAL_STREETS or len(rest) >= 2 and rest[0].category == "word" and \
            words[0] not in lexicon().function_words and words[1] in STREET_SUFFIXES - {"lane", "way"}:
        return True  # "onto 2nd", "into Mill Road" (a lane may be one of the road's: "into outside lane")
    if words[:1] in (["the"], ["a"]):
        words = words[1:]
    return any(tuple(words[:len(place)]) == place for place in TURNED_INTO)


def _swerved_into_a_road(units: list[Unit]) -> list[Unit]:
    """'veered left into Mill Road', 'cut left onto 2nd', 'swerved left into the petrol station': a move to a side
    that ends in a road or a place off it is a turn that way, not a lane change."""
    out = list(units)
    for k, u in enumerate(units):
        if u.category != "actions":
            continue
        side = {"lane_left": "left", "lane_right": "right"}.get(u.meaning) if \
            u.tokens[-1].word in ("left", "right") else None
        after = k + 1
        if side is None and u.meaning in ("cut_in", "lane_change", "move") and k + 1 < len(units) and \
                units[k + 1].category == "positions" and [t.word for t in units[k + 1].tokens] in (["left"], ["right"]):
            side, after = units[k + 1].tokens[0].word, k + 2
        if side is not None and _into_a_road(units, after):
            out[k] = Unit(u.start, u.end, "actions", f"turn_{side}", u.tokens)
            if after == k + 2:
                out[k + 1] = Unit(units[k + 1].start, units[k + 1].end, "word", side, units[k + 1].tokens)
    return out


def _noun_after_paint(units: list[Unit], k: int) -> int | None:
    """Where a vehicle noun stands after one or more paint words right after unit k ('V2 white Transit', 'V1 blue
    Ford Focus'), or None."""
    j = k + 1
    while j < len(units) and units[j].category == "word" and units[j].word in PAINT | {"light"}:
        j += 1
    if j == k + 1 or j >= len(units) or units[j].category != "agents" or units[j].meaning not in V.EGO_TYPES or \
            units[j].tokens[-1].plural or units[j].tokens[-1].label:
        return None
    return j


def _a_label_then_what_it_is(units: list[Unit]) -> list[Unit]:
    """'collided with V2 white Transit travelling SB', 'veh 2 grey Astra coming from its R': a label, then paint
    and a vehicle noun with no article, is one vehicle of that noun's kind, not two."""
    out: list[Unit] = []
    k = 0
    while k < len(units):
        u = units[k]
        out.append(u)
        k += 1
        if u.category != "agents" or not u.tokens[-1].label or u.meaning not in ("car", "generic"):
            continue
        j = _noun_after_paint(units, k - 1)
        if j is None:
            continue
        out[-1] = Unit(u.start, u.end, "agents", units[j].meaning, u.tokens)
        while j < len(units) and units[j].category == "agents" and units[j].meaning in V.EGO_TYPES:
            j += 1  # ("V1 blue Ford Focus": the make and the model both)
        k = j  # the paint and the noun say what the labelled one is, and are read no further
    return out


def _paint_of_one(units: list[Unit]) -> list[Unit]:
    """'the red one turns right': a colour before 'one' is a vehicle's paint, not a traffic light's aspect."""
    out = []
    for k, u in enumerate(units):
        if u.category == "road" and [t.word for t in u.tokens][:1] == ["the"] and len(u.tokens) == 2 and \
                u.tokens[1].word in PAINT and k + 1 < len(units) and units[k + 1].word in ("one", "ones"):
            out += [Unit(t.index, t.index + 1, "word", t.word, (t,)) for t in u.tokens]
        else:
            out.append(u)
    return out


def _a_lane_then_whom_it_is_behind(units: list[Unit]) -> list[Unit]:
    """'starts in the rightmost lane behind a slow-moving truck': a lane said before 'behind' and the one it is
    behind is the subject's lane, and 'behind' says whom it follows (not 'a car in the right lane behind',
    a place of its own)."""
    out = []
    for k, u in enumerate(units):
        words = [t.word for t in u.tokens]
        after = units[k + 1:k + 4]
        if u.category == "positions" and u.meaning in ("back_left", "back_right") and words[-1] == "behind" and \
                "lane" in words and after and after[0].word in ("a", "an", "the") and any(
                    x.category == "agents" and x.meaning not in ("ego", "none") for x in after[1:]):
            side = Unit(u.start, u.end - 1, "positions", "side_" + u.meaning[5:], u.tokens[:-1])
            out += [side, Unit(u.end - 1, u.end, "positions", "behind", u.tokens[-1:])]
        else:
            out.append(u)
    return out


def _one_more_of_the_kind(units: list[Unit]) -> list[Unit]:
    """'a car on the left of the ego and one on the right', 'a car in lane 1 and one in lane 3': 'one' with a place
    of its own, after a single road user named with 'a' in the same sentence and no count, is one more of its
    kind (not 'two cars: one on the left and one on the right', the members of a count)."""
    out = list(units)
    for k, u in enumerate(units[2:-1], 2):
        if u.category != "numbers" or u.word != "one" or units[k - 1].word not in ("and", ",") or \
                units[k + 1].category != "positions":
            continue
        sentence = [x for x in units[:k] if x.tokens[0].sentence == u.tokens[0].sentence]
        named = [j for j, x in enumerate(sentence) if x.category == "agents" and x.meaning not in ("ego", "none")]
        counted = any(x.category == "numbers" for x in sentence)
        if named and not counted and sentence[named[-1] - 1].word in ("a", "an", "another") and \
                not sentence[named[-1]].tokens[-1].plural:
            out[k] = Unit(u.start, u.end, "agents", sentence[named[-1]].meaning, u.tokens)
    return out


def _the_path_of_another(units: list[Unit]) -> list[Unit]:
    """'turned left out of the estate into the path of a motorbike': the path is the motorbike's, not the ego's;
    the one moving into it is placed by nothing here (but 'into the path of the ADS vehicle' is the ego's)."""
    out = list(units)
    for k, u in enumerate(units):
        if u.category != "positions" or u.tokens[-1].word != "path" or k + 2 >= len(units) or units[k + 1].word != "of":
            continue
        j = k + 2
        while j < min(len(units), k + 6) and (units[j].category == "word" or units[j].category == "positions" and
                                             len(units[j].tokens) == 1):
            j += 1  # "of an oncoming silver car"
        if j < len(units) and units[j].category == "agents" and units[j].meaning not in ("ego", "none") and \
                not units[j].tokens[-1].label:  # ("across the path of Unit 1, the AV": a label, named the ego after)
            out[k] = Unit(u.start, u.end, "word", u.word, u.tokens)
    return out


def _pulled_in_or_out(units: list[Unit]) -> list[Unit]:
    """'a lorry pulled in on the hard shoulder', 'a squad car pulled in on the verge ahead': pulled in, over or up
    on the place it stands is stopped there (pulling onto it, or into a lane, is a move). And 'pulled out and went
    right': the pulling out is how the way said next begins, not a move of its own."""
    out = list(units)
    for k, u in enumerate(units[:-1]):
        place = units[k + 1]
        pulled = u.category == "actions" and [t.base for t in u.tokens][:1] == ["pull"] and len(u.tokens) == 2
        if pulled and u.tokens[1].word in ("in", "over", "up") and place.category == "positions" and \
                place.meaning == "shoulder" and place.tokens[0].word == "on":
            out[k] = Unit(u.start, u.end, "actions", "stop", u.tokens)
        if pulled and u.tokens[1].word in ("in", "up") and place.word in ("to", "at") and any(
                x.category == "agents" and x.meaning == "none" and x.tokens[-1].word == "stop" and
                x.tokens[0].sentence == u.tokens[0].sentence for x in units[k + 1:k + 4]):
            out[k] = Unit(u.start, u.end, "actions", "stop", u.tokens)  # "pulls in to the bus stop": it stops there
        if u.category == "actions" and u.meaning == "cut_in" and [t.base for t in u.tokens] in (
                ["tuck", "in"], ["slot", "in"]) and place.category == "positions" and place.meaning == "behind":
            out[k] = Unit(u.start, u.end, "actions", "move", u.tokens)  # "tucked in right behind it": following
        if pulled and u.tokens[1].word == "out" and place.word == "and" and k + 2 < len(units) and \
                units[k + 2].category == "actions" and units[k + 2].meaning in ("sideways_left", "sideways_right"):
            out[k] = Unit(u.start, u.end, "word", "pulled out", u.tokens)
    return out


OTHER_SCENARIO_NOUNS = {"scenario", "scenarios", "scene", "scenes", "test", "tests", "case", "cases"}


def _other_scenarios_named(units: list[Unit]) -> list[Unit]:
    """'similar to the bus scenario we did last week', 'like the truck test from yesterday': an agent's noun naming
    another scenario, with 'the', is no agent of this one."""
    out = list(units)
    for k, u in enumerate(units[1:-1], 1):
        if u.category == "agents" and u.meaning not in ("ego", "none") and len(u.tokens) == 1 and \
                units[k - 1].word == "the" and units[k + 1].word in OTHER_SCENARIO_NOUNS and \
                units[k + 1].tokens[0].sentence == u.tokens[0].sentence:
            out[k] = Unit(u.start, u.end, "word", u.tokens[0].word, u.tokens)
    return out


def _passengers_on_foot(units: list[Unit]) -> list[Unit]:
    """'one passenger gets off and crosses the road', 'a passenger who has just got off walks across': one who
    rides is no agent, until the sentence has them walk or cross before anyone else is named."""
    out = list(units)
    for k, u in enumerate(units):
        if u.category != "agents" or u.meaning != "none" or u.tokens[-1].base not in ("passenger", "passengers"):
            continue
        for x in units[k + 1:k + 9]:
            if x.tokens[0].sentence != u.tokens[-1].sentence or x.category == "agents" and x.meaning != "none":
                break
            if x.category == "actions" and x.meaning in ("cross", "walk"):
                out[k] = Unit(u.start, u.end, "agents", "pedestrian", u.tokens)
                break
    return out


def _lane_change_to_a_side_said_after(units: list[Unit]) -> list[Unit]:
    """'V1 changed lanes from lane 1 to lane 2, to its right': the side said after a lane change, past the lanes it
    names, is where it goes (not the lane it was in)."""
    out = list(units)
    for k, u in enumerate(units):
        if u.category != "actions" or u.meaning != "lane_change":
            continue
        for j in range(k + 1, min(k + 13, len(units))):
            x = units[j]
            if x.tokens[0].sentence != u.tokens[0].sentence or x.category in ("agents", "actions"):
                break
            if x.category == "positions" and x.meaning in ("side_left", "side_right"):
                said = [t.word for y in units[max(k + 1, j - 2):j] for t in y.tokens] + [t.word for t in x.tokens]
                if x.tokens[-1].word in ("left", "right") and (x.tokens[0].word == "to" or said[-3:-1] in (
                        ["to", "its"], ["to", "the"], ["to", "his"], ["to", "her"], ["to", "their"])):
                    out[k] = Unit(u.start, u.end, "actions", "lane_" + x.meaning[5:], u.tokens)
                    out[j] = Unit(x.start, x.end, "word", x.word, x.tokens)
                break
    return out


FROM_BEHIND_VERBS = {"rear end", "rear ended", "shunt", "run into the back of"}
GOING_INTO = {"enter", "come", "move", "get", "swerve", "merge", "slide", "push", "squeeze", "put"}


WANTING_OF_THE_EGO = {"at", "honking", "hooting", "beeping", "flashing", "waving", "signalling", "signaling"}


def _wanted_of_the_ego(units: list[Unit]) -> list[Unit]:
    """'started honking at me to go', 'flashing us to pull out': what someone wants the ego to do is no doing of
    theirs, nor yet of the ego's."""
    return [Unit(u.start, u.end, "word", u.tokens[0].word, u.tokens)
            if u.category == "actions" and k > 1 and units[k - 1].word == "to" and units[k - 2].category == "agents"
            and units[k - 2].meaning == "ego" and units[k - 2].word in ("me", "us") and k > 2 and
            units[k - 3].word in WANTING_OF_THE_EGO
            else u for k, u in enumerate(units)]


def _entering_in(units: list[Unit]) -> list[Unit]:
    """'a car entered my lane': into it; 'I entered the left lane': a change to it."""
    out = list(units)
    for k, u in enumerate(units):
        j = k - 1 - (k > 1 and units[k - 1].word == "the")
        entered = j >= 0 and units[j].category == "actions" and [t.base for t in units[j].tokens] == ["enter"]
        if entered and u.category == "positions" and u.meaning == "ego_lane" and \
                {t.word for t in u.tokens} & {"my", "our", "your", "ego"}:
            out[k] = Unit(u.start, u.end, "positions", "into_ego_lane", u.tokens)  # "a car entered my lane" (not
            # "attempts to enter the same lane": the one the ego turns into)
            continue
        if entered and u.category == "positions" and u.meaning in ("side_left", "side_right") and \
                u.tokens[-1].word == "lane" and u.tokens[0].word in ("the", "left", "right"):
            v = units[j]  # "I entered the left lane": a lane change to it
            out[j] = Unit(v.start, v.end, "actions", "lane_" + u.meaning[5:], v.tokens)
    return out


def _going_in(units: list[Unit], i: int) -> bool:
    """'is coming in ego lane', 'enters suddenly in my lane' (Italian, Spanish, Portuguese: 'entra nella mia
    corsia', 'is entering in the lane of the ego'): 'in' the ego's lane right after a verb of going, past a
    manner adverb, is into it."""
    if units[i].tokens[0].word == "in":
        j = i - 1
    elif i > 0 and units[i - 1].word == "in":
        j = i - 2  # "in" read apart from "the lane of the ego"
    else:
        return False
    verb_next = j
    while j >= 0 and (units[j].category == "behaviours" or units[j].word.endswith("ly") and
                      units[j].category == "word"):
        j -= 1
    return j >= 0 and units[j].category == "actions" and (
        j == verb_next and units[j].tokens[0].base in STEERING | {"come", "get"} or
        units[j].tokens[-1].base in GOING_INTO and all(t.word in AUXILIARIES for t in units[j].tokens[:-1]))


AGE_MARKS = {"f", "yo", "yrs", "yr", "y"}


def _ages(units: list[Unit]) -> list[Unit]:
    """'Pt 52M rider of motorcycle', '28F driver', '8yo F': a patient's age and sex, no count (but '50 m ahead' and
    'within 9000 m' are distances)."""
    out = list(units)
    for k in range(len(units) - 1):
        a, b = units[k], units[k + 1]
        if a.category not in ("number", "numbers") or not a.word.isdigit() or len(b.tokens) != 1 or \
                b.tokens[0].index != a.tokens[-1].index + 1:
            continue
        after = units[k + 2].word if k + 2 < len(units) else ""
        before = units[k - 1].word if k > 0 else ""
        male = b.word == "m" and (after in AGED or before in PATIENT_WORDS) and int(a.word) <= 110
        if b.word in AGE_MARKS and int(a.word) <= 110 or male:
            out[k] = Unit(a.start, a.end, "word", a.word, a.tokens)
    return out


AGED = {"driver", "rider", "pedestrian", "cyclist", "passenger", "motorcyclist", "pt", "patient", ","}


def _time_stamps(units: list[Unit]) -> list[Unit]:
    """'0:42 the van swings in', '14:02 Caller reports': a clock's or a video's time (two numbers with nothing
    between, the second of two digits) is no count and no speed."""
    out = list(units)
    for k in range(len(units) - 1):
        a, b = units[k], units[k + 1]
        if a.category in ("number", "numbers") and b.category in ("number", "numbers") and _clock_stamp(a, b):
            out[k] = Unit(a.start, a.end, "word", a.word, a.tokens)
            out[k + 1] = Unit(b.start, b.end, "word", b.word, b.tokens)
    return out


ABORTED = {"aborted", "abort", "aborts", "aborting", "abandoned", "abandons", "cancelled", "canceled", "cancels",
           "refuses", "refused", "refuse"}
STAYED_IN_LANE = (("stayed", "in", "my", "lane"), ("stayed", "in", "lane"), ("stays", "in", "its", "lane"),
                  ("stayed", "in", "its", "lane"), ("kept", "my", "lane"), ("held", "my", "lane"),
                  ("holds", "its", "lane"), ("stay", "in", "my", "lane"), ("stays", "in", "lane"))


def _aborted_lane_changes(units: list[Unit]) -> list[Unit]:
    """'went to move into the right lane ... so I aborted and stayed in my lane', 'the car flatly refuses the lane
    change': a lane change given up in its own sentence is only tried."""
    words: dict[int, list[str]] = {}
    for u in units:
        words.setdefault(u.tokens[0].sentence, []).extend(t.word for t in u.tokens)
    given_up = {k for k, said in words.items() if set(said) & ABORTED or _says_any(said, STAYED_IN_LANE)}

    def by_another(k: int) -> bool:  # "a car changes into the middle lane, and a truck stays in its lane": the
        # one who stays is someone named after the lane change, and the change is made
        later = [x for x in units[k + 1:] if x.tokens[0].sentence == units[k].tokens[0].sentence]
        said = [t.word for x in later for t in x.tokens]
        ends = list(itertools.accumulate(len(x.tokens) for x in later))
        at = next((n for n in range(len(said)) if said[n] in ABORTED or
                   any(tuple(said[n:n + len(p)]) == p for p in STAYED_IN_LANE)), None)
        if at is None:
            return False
        before = [j for j, x in enumerate(later) if ends[j] <= at and x.category == "agents"]
        return bool(before) and later[before[-1]].meaning not in ("ego", "none") and before[-1] > 0 and \
            later[before[-1] - 1].word in ("a", "an", "another")
    return [Unit(u.start, u.end, "actions", "try", u.tokens)
            if u.tokens[0].sentence in given_up and u.category == "actions" and
            u.meaning in ("lane_left", "lane_right", "lane_change") and not by_another(k) else u
            for k, u in enumerate(units)]


LANE_PLACES = {"side_left", "side_right", "lane_said", "ego_lane", "into_ego_lane", "ahead", "behind"}


def _unknown_makes(tokens: list[Token], units: list[Unit]) -> list[Unit]:
    """'A Commodore in the left lane dives across', 'the Hilux cut in': a word the lexicon does not know, after an
    article and right before a lane or a driver's manoeuvre, is a vehicle's make or model: a car. After a paint
    colour ('a silver Zafira pulled out', 'Black Fortuner from left lane cut in') any doing or place will do."""
    lex = lexicon()
    out = list(units)
    for k in range(1, len(units) - 1):
        u, before, nxt = units[k], units[k - 1], units[k + 1]
        t = u.tokens[0]
        if u.category != "word" or len(u.tokens) != 1 or not t.word.isalpha() or len(t.word) < 4 or t.misspelt or \
                t.label or t.word in lex.vocabulary or t.base in lex.vocabulary or t.word in ORDINAL_MEMBERS or \
                t.word in ORDINAL_NUMBERS or before.tokens[-1].sentence != t.sentence or \
                nxt.tokens[0].sentence != t.sentence:
            continue  # (not "is a menace. Swung into the left lane": the next sentence's verb)
        painted = before.word in PAINT and (k == 1 or units[k - 2].word in ("a", "an", "the", "this", "his", "her",
                                                                            "their", "one", "some") and not (
            k > 2 and units[k - 3].word in ("in", "wearing", "with")) or units[k - 2].tokens[-1].sentence != t.sentence)
        # (not "a guy in a black hoodie": what he wears)
        if before.word not in ("a", "an", "the", "this") and not painted:
            continue
        verb = nxt.tokens[0]
        if nxt.category == "positions" and nxt.meaning in LANE_PLACES and verb.word == "in" or \
                nxt.category == "actions" and nxt.meaning in VEHICLE_ONLY_ACTIONS and (
                    verb.word != verb.base or verb.word.endswith(("s", "ed", "ing"))) or \
                painted and (nxt.category == "actions" and nxt.meaning in VEHICLE_ONLY_ACTIONS | {"move", "stop"} and
                             verb.word != verb.base or
                             nxt.category == "positions" and nxt.meaning in LANE_PLACES | {"side_left", "side_right"}):
            out[k] = Unit(u.start, u.end, "agents", "car", u.tokens)  # (not "an evasive lane change")
    return out


STREET_SUFFIXES = {"road", "street", "avenue", "drive", "way", "close", "crescent", "terrace", "place", "gardens",
                   "hill", "row", "square", "parade", "lane", "rd", "st", "ave", "boulevard", "blvd"}


def _street_names(tokens: list[Token], units: list[Unit]) -> list[Unit]:
    """'the gritter hasn't touched Park Lane', 'turned into Cross Street', 'at Northgate and Vicar Lane', 'Mines Rd':
    a one-word verb or person (or 'mines') before a street's suffix, with no article before it, is the street's
    name."""
    out = list(units)
    for k, u in enumerate(units):
        if not (u.category == "actions" or u.category == "agents" and u.meaning == "pedestrian" or
                u.category == "agents" and u.meaning == "ego" and u.tokens[0].word == "mines") or \
                len(u.tokens) != 1 or k + 1 >= len(units) or \
                units[k + 1].tokens[0].word not in STREET_SUFFIXES or len(units[k + 1].tokens) != 1 or \
                units[k + 1].tokens[0].sentence != u.tokens[0].sentence:
            continue
        before = tokens[u.start - 1].word if u.start > 0 else ""
        if before in DETERMINERS or before in ("to", "will", "would", "can", "could", "must", "should", "not"):
            continue  # "the park lane", "to stop, road clear"
        out[k] = Unit(u.start, u.end, "word", u.tokens[0].word, u.tokens)
    return out


UNABLE = {"ca", "can", "could", "cannot", "couldn", "unable", "able"}  # "can't move" (tokens "ca", "not move")
GERUND_MODIFIERS = {"own", "hard", "heavy", "sudden", "harsh", "light", "gentle", "late", "full", "emergency", "some",
                    "no", "little", "much", "more", "less", "quick", "slow", "fast", "careful", "constant",
                    "aggressive", "cautious", "normal", "steady", "smooth", "abrupt", "erratic", "reckless",
                    "dangerous"}


def _with_absolutes(units: list[Unit]) -> list[Unit]:
    """'a semi stopped on the shoulder with its hazards going', 'with the engine running', ', light bar going': the
    -ing verb after 'with' (or a comma) and a thing that is no road user is that thing's, not a doing of the
    clause's subject."""
    out = list(units)
    for k, u in enumerate(units):
        if u.category == "comma" and k + 2 < len(units) and units[k + 1].category == "agents" and \
                units[k + 1].meaning == "none":  # ", light bar going", ", hazards blinking": the same, with no 'with'
            j = k + 2 if units[k + 2].category == "actions" else k + 3
            if j < len(units) and units[j].category == "actions" and len(units[j].tokens) == 1 and \
                    units[j].tokens[0].word.endswith("ing") and (j == k + 2 or units[k + 2].word.isalpha() and
                                                                 units[k + 2].category == "word"):
                out[j] = Unit(units[j].start, units[j].end, "word", units[j].tokens[0].word, units[j].tokens)
            continue
        if u.word != "with" or u.category != "word":
            continue
        j = k + 1
        while j < len(units) and units[j].category == "word" and units[j].word in POSSESSIVES | {"the", "all", "a"}:
            j += 1
        if _placed_by_the_subject(units, j):  # "riding in the lane with the test car sat behind the cyclist": the
            out[k] = Unit(u.start, u.end, "comma", ",", (replace(u.tokens[0], word=",", base=","),))  # ego's place
            continue
        thing = j < len(units) and (units[j].category == "agents" and units[j].meaning == "none" or
                                    units[j].category == "word" and units[j].word.isalpha() and
                                    units[j].word not in AUXILIARIES | GERUND_MODIFIERS and
                                    not units[j].word.endswith("ly"))  # "with their own braking": a doing
        while thing and j + 1 < len(units) and units[j + 1].category == "word" and units[j + 1].word.isalpha() and \
                j - k < 3 and units[j + 1].word not in AUXILIARIES | {"and", "or"}:
            j += 1  # "with its hazard lights going"
        if thing and j + 1 < len(units) and units[j + 1].category == "actions" and \
                units[j + 1].tokens[0].word.endswith("ing") and len(units[j + 1].tokens) == 1:
            v = units[j + 1]
            out[j + 1] = Unit(v.start, v.end, "word", v.tokens[0].word, v.tokens)
    return out


RELATIONS_TO_ONE = {"behind", "ahead", "level"}


def _placed_by_the_subject(units: list[Unit], j: int) -> bool:
    """'with the test car (sat) behind the cyclist', 'with the ego right behind it': after 'with', the ego placed
    by one named again, said of the ego as a clause of its own (not 'with a cyclist behind it', where the one
    after 'with' is placed)."""
    if j >= len(units) or units[j].category != "agents" or units[j].meaning != "ego":
        return False
    k = j + 1
    while k < len(units) and units[k].category == "word" and units[k].word in ("sat", "sitting", "right", "just"):
        k += 1
    pronouns = ("it", "him", "her", "them")
    return k < len(units) and units[k].category == "positions" and units[k].meaning in RELATIONS_TO_ONE and (
        units[k].tokens[-1].word in pronouns or k + 1 < len(units) and (
            units[k + 1].word in pronouns + ("the",) or units[k + 1].category == "agents"))


def _manner_adverb(t: Token) -> bool:
    """'sharply', 'slowly', 'violently': an -ly adverb of manner, which may stand inside a verb phrase."""
    if not (t.word.endswith("ly") and len(t.word) >= 5):
        return False
    entry = lexicon().phrases.get((t.word,))
    return entry is None and t.word not in lexicon().function_words or entry is not None and entry[0] == "behaviours"


def _inside_a_verb(tokens: list[Token], i: int) -> bool:
    """A word that may stand between a verb and its particle: a manner adverb ('pulled sharply across'), or 'right'
    before the particle ('dives right across in front of me': how far, no side)."""
    return _manner_adverb(tokens[i]) or tokens[i].word == "right" and i + 1 < len(tokens) and \
        tokens[i + 1].word in ("across", "over", "through", "out") and not _a_side_owned(tokens, i)


def _a_side_owned(tokens: list[Token], i: int) -> bool:
    """'on my right through their red', 'to the right over the line': 'right' said with whose side it is is that
    side, never 'right' meaning how far."""
    return i > 0 and tokens[i - 1].word in OWNERS | {"its", "the"}


def _units_of_one_word(tokens: list[Token], i: int) -> list[Unit]:
    """A token read alone: its own lexicon entry when it has one, else a word, a number or a comma."""
    t = tokens[i]
    entry = _lookup(lexicon(), [t])
    if entry is not None:
        return _disambiguate(tokens, Match(i, i + 1, entry[0], entry[1], t.word))
    category = "comma" if t.word == "," else "number" if read_number(t.word) is not None else "word"
    return [Unit(i, i + 1, category, t.word, (t,))]


def _verbs_around_an_adverb(tokens: list[Token], found: dict[int, Match]) -> tuple[dict[int, Match], set[int]]:
    """'pulled sharply across in front of us', 'swung wildly out': a manner adverb between a verb and its
    particle; the verb phrase is read without it, and the adverb on its own after it."""
    lex, split = lexicon(), set()
    for i, t in enumerate(tokens[1:-1], start=1):
        if not _inside_a_verb(tokens, i) or tokens[i - 1].sentence != t.sentence:
            continue
        before = next((f for f in found.values() if f.end == i), None)
        start = before.start if before is not None else i - 1
        if before is not None and before.category != "actions" or start in split:
            continue
        for n in range(min(lex.longest, len(tokens) - i - 1), 0, -1):
            span = tokens[start:i] + tokens[i + 1:i + 1 + n]
            if any(x.word == "," or x.sentence != t.sentence for x in span):
                continue
            entry = _lookup(lex, span)
            if entry == ("actions", "turn") and t.word in ("left", "right"):
                entry = ("actions", f"turn_{t.word}")  # "swung right across our front": a turn to that side
            if entry is not None and entry[0] == "actions":
                for k in [k for k in found if start <= k < i + 1 + n]:
                    del found[k]
                found[start] = Match(start, i + 1 + n, entry[0], entry[1], " ".join(x.word for x in span))
                split.add(start)
                break
    return found, split


def _read_units(tokens: list[Token]) -> list[Unit]:
    found = {m.start: m for m in matches(tokens)}
    found, around_an_adverb = _verbs_around_an_adverb(tokens, found)
    if _subject_vehicle_is_ego(tokens):
        found = {k: Match(m.start, m.end, "agents", "ego", m.phrase)
                 if m.category == "agents" and [t.word for t in tokens[m.start:m.end]] == ["sv"] else m
                 for k, m in found.items()}
    out, i = [], 0
    while i < len(tokens):
        m = found.get(i)
        if m is not None and m.category == "agents" and m.meaning == "ego" and (
                tokens[m.end - 1].possessive or tokens[m.end - 1].word not in ("i", "we", "you", "me", "us")) and \
                m.end < len(tokens) and tokens[m.end].word in ("lane", "path", "way", "side", "front", "right",
                                                               "left", "rear", "back", "blind") and \
                tokens[m.end].sentence == tokens[m.end - 1].sentence and (tokens[m.end - 1].possessive or
                                                                           tokens[m.end].word in ("lane", "path")) \
                and _part_after(tokens, m.end + 1) is None and (  # "the ego's right rear door": a part of it
                    tokens[m.end].word != "blind" or [t.word for t in tokens[m.end + 1:m.end + 2]] == ["spot"]):
            blind = tokens[m.end].word == "blind" and m.end + 1 < len(tokens) and tokens[m.end + 1].word == "spot"
            span = tuple(tokens[m.start:m.end + 1 + blind])  # "the AV's lane", "the test vehicle's path"
            meaning = {"front": "ahead", "right": "side_right", "left": "side_left", "rear": "behind",
                       "back": "behind", "spot": "behind"}.get(span[-1].word, "ego_lane")  # "on the ego's right",
            # "in the ego's blind spot": behind it, in the lane beside
            before = m.start - 1 if m.start > 0 and tokens[m.start - 1].word != "the" else m.start - 2
            if before >= 0 and tokens[before].word in ("into", "onto", "across"):  # "into the VUT's path"
                meaning = "into_ego_lane" if meaning == "ego_lane" else meaning
            if before >= 0 and tokens[before].word == "from" and meaning in ("side_left", "side_right"):
                meaning = "from_" + meaning[5:]  # "approaching from the HV's left": as "from our left"
            out.append(Unit(m.start, m.end + 1 + blind, "positions", meaning, span))
            i = m.end + 1 + blind
            if any(f.start < i < f.end for f in found.values()):  # "from the SV's left turns left": read on
                found |= {f.start: f for f in matches(tokens, i)}
            continue
        numbered = _numbered_lane(tokens, i + 1) if tokens[i].word == "in" and i + 1 < len(tokens) else None
        if numbered is not None or (tokens[i].word == "in" and i + 2 < len(tokens) and tokens[i + 1].word == "lane"
                                    and _word_number(tokens[i + 2]) == 1):
            end = i + 3 + (i + 4 < len(tokens) and tokens[i + 3].word == "of")
            end += end > i + 3
            out.append(Unit(i, end, "positions", f"lane_{int(_word_number(tokens[i + 2]))}", tuple(tokens[i:end])))
            i = end  # "in lane two (of three)": which lane, counted from the kerb
            continue
        if m is not None and i in around_an_adverb:
            adverb = next(k for k in range(m.start + 1, m.end) if _inside_a_verb(tokens, k))
            out.append(Unit(m.start, m.end, m.category, m.meaning,
                            tuple(x for x in tokens[m.start:m.end] if x.index != adverb)))
            out.extend(_units_of_one_word(tokens, adverb) if tokens[adverb].word != "right" else
                       [Unit(adverb, adverb + 1, "word", "right", (tokens[adverb],))])
            i = m.end
            continue
        if m is not None:
            out.extend(_disambiguate(tokens, m))
            i = m.end
            continue
        out.extend(_units_of_one_word(tokens, i))
        i += 1
    return _driver_of(_names_no_agent(_ego_and_its_noun(_short_names(_again_the_road_turned_into(_turned_into(out))))))


STREET_WORDS = {"street", "st", "road", "rd", "avenue", "ave", "drive", "dr", "boulevard", "blvd", "lane", "ln",
                "way", "highway", "hwy", "pike", "parkway", "pkwy", "place", "pl", "terrace", "crescent", "close",
                "court", "ct", "square", "row", "hill", "bridge", "circle"}
ORGANISATION_WORDS = {"company", "companies", "firm", "insurance", "insurer", "insurers", "depot", "dealership",
                      "dealer", "agency", "office", "garage", "rental", "hire", "owner", "owners", "fleet",
                      "operator", "service", "services", "industry", "union", "association"}


AT_THE_CONTROLS = {"driver", "rider", "motorist", "operator", "cyclist"}
SPEAKING = {"say", "says", "said", "tell", "tells", "told", "better", "reckons", "claims", "claimed", "insists",
            "insisted", "confirmed", "confirms", "stated", "states", "announced", "announces", "replied", "responded",
            "thinks", "thought", "yelled", "shouted", "texted", "emailed"}  # a bare noun before them is who speaks


def _driver_of(units: list[Unit]) -> list[Unit]:
    """'the minivan driver', 'the scooter rider': the vehicle, named by who drives it; one agent."""
    out: list[Unit] = []
    for u in units:
        prev = out[-1] if out else None
        vehicle = lexicon().phrases.get(tuple(t.base for t in u.tokens[:-1])) if len(u.tokens) > 1 else None
        if u.category == "agents" and vehicle is not None and vehicle[0] == "agents" and vehicle[1] == u.meaning \
                and u.tokens[-1].base in AT_THE_CONTROLS and not u.tokens[-1].plural:
            out.append(Unit(u.start, u.end, "agents", u.meaning, u.tokens[:-1]))  # "the van driver": the van
            continue
        if prev is not None and u.category == "agents" and u.tokens[-1].base in AT_THE_CONTROLS and \
                len(u.tokens) == 1 and prev.category == "agents" and prev.meaning not in ("none", "pedestrian") \
                and not prev.tokens[-1].possessive and not prev.tokens[-1].plural and \
                prev.tokens[-1].sentence == u.tokens[0].sentence and (prev.meaning != "ego" or (
                    prev.end == u.start and prev.tokens[-1].word not in FIRST_PERSON | {"we", "you"})):
            out[-1] = Unit(prev.start, u.end, "agents", prev.meaning, prev.tokens)  # read as the vehicle's noun
            continue  # "the VUT driver": the ego, named by who drives it
        if u.category == "agents" and u.meaning == "ego" and u.tokens[0].word not in FIRST_PERSON | {"we", "you"}:
            j = len(out) - 1
            while j >= 0 and out[j].word in ("the", "our", "this"):
                j -= 1
            if j >= 1 and out[j].word == "of" and out[j - 1].category == "agents" and \
                    len(out[j - 1].tokens) == 1 and out[j - 1].tokens[0].base in AT_THE_CONTROLS and \
                    out[j - 1].tokens[0].sentence == u.tokens[0].sentence:
                del out[j - 1:]  # "the driver of the VUT": the ego
        out.append(u)
    return out


CORNER_WORDS = {"intersection", "junction", "corner", "crossroads"}


def _corner_with_a_numbered_street(units: list[Unit], k: int) -> bool:
    """'Lincoln & 3rd', 'at 5th and Lincoln': a make joined to a numbered street names the other street of a
    corner, not a car."""
    def ends_the_name(j: int) -> bool:
        return j >= len(units) or units[j].category == "comma" or units[j].word in STREET_WORDS | CORNER_WORDS or \
            units[j].tokens[0].sentence != units[k].tokens[0].sentence
    determiner = k > 0 and units[k - 1].word in ("a", "an", "the", "this", "that", "another")
    after = k + 2 < len(units) and units[k + 1].word == "and" and units[k + 2].word in ORDINALS and \
        len(units[k + 2].tokens) == 1 and ends_the_name(k + 3)
    before = k >= 2 and units[k - 1].word == "and" and units[k - 2].word in ORDINALS and \
        len(units[k - 2].tokens) == 1 and ends_the_name(k + 1)
    return not determiner and (after or before)


def _names_no_agent(units: list[Unit]) -> list[Unit]:
    """'on Lincoln St', 'Ford Road': a make before a street word names a street; 'the cab company', 'his
    insurance': an agent noun before an organisation names who owns or insures, not an agent on the road."""
    out = list(units)
    for k, u in enumerate(units[:-1]):
        nxt = units[k + 1]
        if u.category == "agents" and u.meaning not in ("ego", "none") and not u.tokens[-1].plural and \
                _corner_with_a_numbered_street(units, k):
            out[k] = Unit(u.start, u.end, "word", u.base, u.tokens)
            continue
        if nxt.word == "s" and k + 2 < len(units) and u.tokens[-1].plural:
            nxt = units[k + 2]  # "the residents' association": the plural's possessive, then what it owns
        if u.category != "agents" or u.meaning in ("ego", "none") or nxt.category != "word" or \
                nxt.tokens[0].sentence != u.tokens[-1].sentence:
            continue
        street = nxt.word in STREET_WORDS and not (k > 0 and units[k - 1].word in ("a", "an", "the", "this", "that"))
        if street and not u.tokens[-1].plural or nxt.word in ORGANISATION_WORDS:
            out[k] = Unit(u.start, u.end, "word", u.base, u.tokens)
    for k, u in enumerate(units[:-1]):  # "coach better appreciate me", "Tesla said": a person or a firm speaks
        nxt = units[k + 1]
        if u.category == "agents" and u.meaning in V.EGO_TYPES and not u.tokens[-1].plural and \
                not u.tokens[-1].possessive and nxt.word in SPEAKING and \
                nxt.tokens[0].sentence == u.tokens[-1].sentence and u.tokens[-1].base not in AT_THE_CONTROLS | {
                    "trucker", "cabbie"} and (k == 0 or units[k - 1].word not in DEFINITE | INDEFINITE | OWNERS
                                              and units[k - 1].category not in ("numbers", "number")):
            out[k] = Unit(u.start, u.end, "word", u.base, u.tokens)  # (bare: "the coach said" may be the bus's)
    for k, u in enumerate(units[:-1]):  # "a police pursuit", "the taxi rank", "truck traffic": said of a thing
        nxt = units[k + 1]
        if u.category == "agents" and u.meaning not in ("ego", "none") and not u.tokens[-1].plural and \
                not u.tokens[-1].possessive and len(nxt.tokens) == 1 and nxt.word in compound_heads() \
                and nxt.tokens[0].sentence == u.tokens[-1].sentence:
            out[k] = Unit(u.start, u.end, "word", u.base, u.tokens)
    return out


def _ego_and_its_noun(units: list[Unit]) -> list[Unit]:
    """'Ego PKW turns right', 'behind the ego LKW', 'our hero's taxi', 'the AV truck', 'the SUT agent': a vehicle
    (or agent) noun right after the word ego, another name of the ego's role, or the ego's possessive is the ego's
    own noun, as in 'the ego truck', not another agent."""
    out: list[Unit] = []
    noun = 0
    for k, u in enumerate(units):
        prev = out[-1] if out else None
        if k < noun:
            continue  # (paint, taken into the ego's name)
        if prev is not None and prev.category == "agents" and prev.meaning == "ego" and \
                prev.tokens[-1].word == "ego" and u.category == "word":
            noun = _noun_after_paint(units, k - 1) or 0
            if noun:  # "V1 blue Ford Focus turning R": the ego's paint, then its noun
                prev = out[-1] = Unit(prev.start, units[noun - 1].end, "agents", "ego",
                                      prev.tokens + tuple(t for x in units[k:noun] for t in x.tokens))
                continue
        role = prev is not None and prev.category == "agents" and prev.meaning == "ego" and \
            prev.tokens[-1].word not in SELF_NAMES and not prev.tokens[-1].plural  # "the AV", not "we"
        if prev is not None and u.category == "agents" and (u.meaning in V.EGO_TYPES or role and u.meaning == "generic"
                                                            and u.base in ("agent", "actor", "participant")) and \
                (prev.tokens[-1].word == "ego" or role or prev.tokens[-1].possessive and prev.category == "agents"
                 and prev.meaning == "ego") and \
                prev.tokens[-1].sentence == u.tokens[0].sentence and not u.tokens[-1].plural:
            if prev.category == "agents" and prev.meaning == "ego":
                out[-1] = Unit(prev.start, u.end, "agents", "ego", prev.tokens + u.tokens)
                continue
            if prev.category == "positions":
                out.append(Unit(u.start, u.end, "word", u.base, u.tokens))
                continue
        out.append(u)
    return out


CORRECTIONS = (("no", "wait"), ("wait", "no"), ("no", "sorry"), ("i", "mean"), ("or", "rather"),
               ("scratch", "that"), ("make", "that"), ("no",), ("sorry",), ("wait",), ("actually",), ("rather",))
NOUN_PHRASE_WORDS = {"a", "an", "the", "one", "some", "another", "this", "big", "small", "little", "white", "black",
                     "red", "blue", "silver", "grey", "gray", "green", "yellow", "dark", "parked", "stopped"}


def _marker_end(units: list[Unit], j: int, markers=CORRECTIONS) -> int | None:
    """The unit after a correction marker starting at unit j (the lexicon may hold the marker as one phrase)."""
    for marker in markers:
        words, n = [], j
        while n < len(units) and len(words) < len(marker):
            words += [t.word for t in units[n].tokens]
            n += 1
        if words == list(marker):
            return n
    return None


def _retract_corrections(r: "_Reader") -> list[Unit]:
    """'a car, no wait, a truck', 'a cyclist, I mean a jogger': speech corrects itself; only the last word stands."""
    units, out, k = r.units, [], 0
    while k < len(units):
        u = units[k]
        out.append(u)
        k += 1
        if not (u.category == "agents" and u.meaning not in ("ego", "none")):
            continue
        j = k + (k < len(units) and units[k].category == "comma")
        if j < len(units) and units[j].word == "not" and len(units[j].tokens) == 1:  # "a van, not a truck,"
            n = j + 1
            while n < len(units) and n - j < 4 and units[n].word in NOUN_PHRASE_WORDS:
                n += 1
            if n < len(units) and units[n].category == "agents" and units[n].meaning not in ("ego", "none"):
                r.notes.append(f"read '{' '.join(t.word for x in units[j:n + 1] for t in x.tokens)}' as denied")
                for x in units[k:n + 1]:
                    r.mark(x)
                k = n + 1
                continue
        end = _marker_end(units, j)
        if end is None:
            continue
        j = end
        j += j < len(units) and units[j].category == "comma"
        placed = k - 2
        while placed >= 0 and units[placed].category == "word" and units[placed].word in NOUN_PHRASE_WORDS:
            placed -= 1
        if j < len(units) and units[j].category == "positions" and placed >= 0 and \
                units[placed].category == "positions":
            j += 1  # "behind a tractor, no sorry, behind a truck": the place said again with the noun
        n = j
        while n < len(units) and n - j < 4 and units[n].category in ("word", "number", "numbers") and \
                (units[n].word in NOUN_PHRASE_WORDS or units[n].category != "word"):
            n += 1
        if not (j <= n < len(units) and units[n].category == "agents" and units[n].meaning not in ("ego", "none")) \
                or n == j and units[n].tokens[-1].plural:  # ("a bus, no cars around": none, no correction)
            continue  # "a car, no wait, a truck", "car no wait truck" (articles dropped)
        first = len(out) - 1
        while first > 0 and out[first - 1].category in ("word", "number", "numbers") and \
                out[first - 1].word in NOUN_PHRASE_WORDS | {"two", "three"}:
            first -= 1
        r.notes.append(f"read '{' '.join(t.word for x in out[first:] for t in x.tokens)}' as corrected by "
                       f"'{' '.join(t.word for x in units[j:n + 1] for t in x.tokens)}'")
        for x in out[first:] + units[k:j]:
            r.mark(x)
        del out[first:]
        k = j
    return out  # a later 'make it a X' is read by _later_corrections


LATER_CORRECTIONS = (("make", "it"), ("make", "that"), ("make", "them"), ("change", "it", "to"),
                     ("change", "that", "to"), ("change", "them", "to"))
CORRECTION_LEADS = {"wait", "actually", "no", "oh", "sorry", "hmm", "ok", "okay", "and", "but"}
SAID_COUNT = {"a", "an", "of", "some"}


def _opens_a_correction(units: list[Unit]) -> bool:
    """'no wait, the cyclist should be waiting', 'actually, the van is parked': a clause that takes back what was
    just said of one named before."""
    words = [t.word for u in units[:3] for t in u.tokens]
    return words[:2] in (["no", "wait"], ["wait", "no"], ["i", "mean"]) or words[:1] in (["actually"], ["sorry"])


def _made_the_thing(units: list[Unit], k: int) -> int | None:
    """'maybe make the parked thing a delivery truck': 'make the' and a few words naming no agent, then 'a': the
    unit of that 'a', as after 'make it'."""
    if units[k].word != "make" or k + 2 >= len(units) or units[k + 1].word != "the":
        return None
    n = k + 2
    while n < len(units) and n - k <= 4 and units[n].category in ("word", "actions") and \
            units[n].word not in ("a", "an"):
        n += 1
    return n if n > k + 2 and n < len(units) and units[n].word in ("a", "an") else None


def _later_corrections(r: "_Reader") -> list[Unit]:
    """'a bunch of kids crossing ... wait make it 3 kids', 'a car cuts in. actually make it a truck': a chat
    corrects itself later on; the count or type said last replaces the earlier one, where it was said."""
    units, k = list(r.units), 1
    while k < len(units):
        end = _marker_end(units, k, LATER_CORRECTIONS) or _made_the_thing(units, k)
        if end is None:
            k += 1
            continue
        j = end + (end < len(units) and units[end].category == "comma")
        n = j
        while n < len(units) and n - j < 3 and (units[n].category in ("numbers", "number") or
                                                units[n].word in SAID_COUNT):
            n += 1
        said = units[n] if n < len(units) else None
        counted = n > j and units[n - 1].category in ("numbers", "number")
        if said is None or said.category != "agents" or said.meaning in ("ego", "none"):
            if not counted:  # "make it turn left": no correction
                k += 1
                continue
            said, n = None, n - 1  # "two cyclists pass us. wait, make it three": the count alone
        others = [i for i in range(k) if units[i].category == "agents" and units[i].meaning not in ("ego", "none")]
        same = [i for i in others if said is not None and units[i].meaning == said.meaning]
        if not (same or others):
            k += 1
            continue
        i = (same or others)[-1]
        first = i
        while first > 0 and (units[first - 1].category in ("numbers", "number") or units[first - 1].word in SAID_COUNT):
            first -= 1
        lead = k
        while lead > i + 1 and (units[lead - 1].word in CORRECTION_LEADS or units[lead - 1].category == "comma"
                                or [t.word for t in units[lead - 1].tokens] == ["wait"]):
            lead -= 1
        stop = n + 1
        if stop < len(units) and units[stop].word in ("not", "instead", "rather"):
            stop += 1  # "make it 3 kids not a bunch": what it replaces, said again
            while stop < len(units) and stop - n < 5 and units[stop].category not in ("comma", "agents", "actions") \
                    and units[stop].tokens[0].sentence == units[n].tokens[0].sentence:
                stop += 1
            if stop < len(units) and units[stop].category == "agents" and units[stop - 1].word in ("a", "an") and \
                    units[stop].tokens[0].sentence == units[n].tokens[0].sentence:
                stop += 1  # "a delivery truck instead of a car": the car replaced, said again
        sentence = units[i].tokens[0].sentence
        moved = [Unit(u.start, u.end, u.category, u.meaning, tuple(replace(t, sentence=sentence) for t in u.tokens))
                 for u in units[j:n + 1]] + ([units[i]] if said is None else [])
        r.notes.append(f"read '{' '.join(t.word for x in units[first:i + 1] for t in x.tokens)}' as corrected by "
                       f"'{' '.join(t.word for x in units[lead:stop] for t in x.tokens)}'")
        for x in units[first:i + 1] + units[lead:stop]:
            r.mark(x)
        units = units[:first] + moved + units[i + 1:lead] + units[stop:]
        k = lead - (i + 1 - first) + len(moved)
    return units


TO_COME = AUXILIARIES | {"am", "about", "going", "due", "want", "wants", "wanted", "need", "needs", "needed", "plan",
                         "plans", "planned", "intend", "intends", "intended", "has", "have", "had", "set"}


ENTERING = {"enter", "entering", "enters", "entered"}


def _to_come(u: Unit) -> bool:
    """'is about', 'wants', 'to': the words between who and the verb of what it is yet to do."""
    return u.category == "word" and u.word in TO_COME | {"to"} or u.category == "actions" and u.meaning == "try" and \
        all(t.word in TO_COME | {"to"} for t in u.tokens)


def _entered(units: list[Unit], j: int) -> bool:
    """'(the road) it wants to enter', 'it is turning into': after 'it', the verb of heading into a road."""
    while j < len(units) and _to_come(units[j]):
        j += 1
    return j < len(units) and (units[j].tokens[0].base in ENTERING or units[j].category == "actions" and
                               units[j].meaning.startswith("turn"))


def _turned_into(units: list[Unit]) -> list[Unit]:
    """'crossing the road I was turning into': a relative clause on a road noun naming where the ego turns."""
    out, k = [], 0
    named = False
    while k < len(units):
        u = units[k]
        if named and u.tokens[-1].word in ("road", "street", "avenue") and out and out[-1].word in ("that", "this") \
                and (k + 1 >= len(units) or units[k + 1].word not in ("that", "which")):
            out[-1] = Unit(out[-1].start, u.end, "positions", "destination", out[-1].tokens + u.tokens)
            k += 1  # "... the road the ego turns into. Then that road is crossed by two people": that road again
            continue
        out.append(u)
        k += 1
        named = named or u.category == "positions" and u.meaning == "destination"
        if u.tokens[-1].word not in ("road", "street", "avenue") or k >= len(units):
            continue
        j = k + (k + 1 < len(units) and units[k].word in ("in", "into", "onto") and units[k + 1].word == "which")
        j += j < len(units) and units[j].word in ("that", "which")  # "the road (in which) the AV is turning"
        j += j < len(units) and units[j].word == "the" and units[j].category == "word"
        if not (j < len(units) and (units[j].category == "agents" and units[j].meaning == "ego" or
                                    units[j].word == "it" and _entered(units, j + 1))):
            continue  # "the road the ego turns into", "the side road it wants to enter"
        j += 1
        while j < len(units) and _to_come(units[j]):
            j += 1  # "the road the ego is about to turn into", "the street we want to turn into"
        into = j + 1 < len(units) and units[j + 1].word in ("into", "onto")
        if j < len(units) and units[j].tokens[0].base in ENTERING:  # "the side road the ego wants to enter"
            end = j + 1
            tokens = tuple(t for x in units[k:end] for t in x.tokens)
            out.append(Unit(units[k].start, units[end - 1].end, "positions", "destination", tokens))
            k = end
            named = True
            continue
        if j < len(units) and units[j].category == "actions" and units[j].meaning.startswith("turn") and (
                into or units[k].word in ("in", "into", "onto")):
            end = j + 1 + into
            tokens = tuple(t for x in units[k:end] for t in x.tokens)
            out.append(Unit(units[k].start, units[end - 1].end, "positions", "destination", tokens))
            k = end
            named = True
    return out


ROAD_NOUNS = {"road", "street", "avenue", "lane", "drive", "close", "boulevard", "crescent", "entrance", "driveway",
              "way", "terrace", "place", "row", "parade", "rd", "st", "ave", "blvd"}
INTO_THE_ROAD = {"across", "inside", "in", "into", "over"}  # "walked across it", "parked inside it" (not "along it")


SIDED_PLACES = {"from_left", "from_right", "road_left", "road_right", "road_straight", "toward", "oncoming",
                "side_left", "side_right"}


def _again_the_road_turned_into(units: list[Unit]) -> list[Unit]:
    """'I turn right into a side street and a woman is crossing it', 'turning left into Elm Street, a jogger crosses
    the mouth of the road': once the ego is said to turn into a road, that road said again ('it', 'the road',
    'there') in the same or the next sentence is where the ego is heading."""
    out: list[Unit] = []
    until = -1  # the last sentence in which the road turned into may be said again
    name: list[str] = []  # its words, when they name it ("Walnut Street", "the main road"): said again anywhere
    k = 0
    while k < len(units):
        u = units[k]
        sentence = u.tokens[0].sentence
        into = k + 1 if u.tokens[-1].word in ("into", "onto") else next(
            (j + 1 for j in range(k + 1, min(k + 7, len(units))) if units[j].word in ("into", "onto")), None)
        # "turns left into a side street", "turns right from a major road into a minor road"
        turned_by_the_ego = u.category == "actions" and u.meaning in ("turn_left", "turn_right", "turn") and \
            into is not None and _said_by_the_ego(units, k)
        if turned_by_the_ego and _street_named_alone(units, into):
            out.extend(units[k:into + 1])  # "turned right onto Main. ... a kid on a bike already on Main"
            name = [units[into].word]
            k = into + 1
            until = sentence + 1
            continue
        if turned_by_the_ego and any(x.tokens[-1].word in ROAD_NOUNS and x.category != "agents"
                                     for x in units[into:into + 4]):
            out.extend(units[k:into])
            k = into
            end = next(j for j in range(k, min(k + 4, len(units))) if units[j].tokens[-1].word in ROAD_NOUNS and
                       units[j].category != "agents")
            out.extend(units[k:end + 1])
            said = [t.word for x in units[k:end + 1] for t in x.tokens if t.word not in ("a", "an", "the")]
            name = said if len(said) >= 2 and all(x.category == "word" for x in units[k:end]) else []
            k = end + 1
            until = sentence + 1
            continue
        if name and (u.category == "word" and (u.word in ("on", "in", "along", "down", "up", "from", "across") or
                                               u.word == "of" and k and units[k - 1].tokens[-1].word == "out") or
                     u.category == "actions" and (u.meaning == "cross" or u.tokens[0].base in ("exit", "leave"))) \
                and k + 1 < len(units):
            # ("turning right into Cedar Close ... a van came out of Cedar Close": from where the ego heads;
            # "... into Victoria St ... a man crossing Victoria St", "a cyclist exiting Victoria St")
            first = k + 1 + (units[k + 1].word == "the")
            span = list(itertools.takewhile(lambda x: x.tokens[0].sentence == sentence, units[first:first + 4]))
            words = [t.word for x in span for t in x.tokens]
            counts = list(itertools.accumulate(len(x.tokens) for x in span))  # tokens said up to each unit
            last = next((j for j, n in enumerate(counts) if n >= len(name)), None)
            if words[:len(name)] == name and counts[last] == len(name) and \
                    all(x.category in ("word", "road", "positions") for x in span[:last + 1]) and not any(
                    x.category == "positions" and x.meaning in SIDED_PLACES for x in units
                    if x.tokens[0].sentence == sentence):  # "... onto Walnut Street; a school bus parked right
                # there on Walnut Street": where the ego is heading (not "a car on the main road comes from the
                # right": the road it comes along, from its side)
                out.append(u)
                tokens = tuple(t for x in span[:last + 1] for t in x.tokens)
                out.append(Unit(span[0].start, span[last].end, "positions", "destination", tokens))
                k = first + last + 1
                continue
        if u.category == "positions" and u.meaning == "destination" and k and units[k - 1].tokens[-1].word in \
                ROAD_NOUNS:
            until = sentence + 1  # "the street it's turning into": said again as "that same street"
        before = out[-1] if out else None
        done_to = before is not None and (before.category == "actions" and before.meaning == "cross" or
                                          before.word in INTO_THE_ROAD or before.word in ALONG_A_ROAD and
                                          (u.word == "that" or k + 1 < len(units) and units[k + 1].word == "same")
                                          and not any(x.meaning in ("from_left", "from_right")
                                                      for x in units[k + 1:k + 6] if x.category == "positions"))
        # (not "raced along that boulevard from the left": from its side)
        if sentence <= until and done_to and u.word in ("it", "there") and u.category == "word":
            out.append(Unit(u.start, u.end, "positions", "destination", u.tokens))
            k += 1
            continue
        if sentence <= until and done_to and u.word in ("the", "that"):  # "a van is stopped in that street"
            end = next((j for j in range(k + 1, min(k + 6, len(units)))
                        if units[j].tokens[-1].word in ROAD_NOUNS and units[j].category != "agents"), None)
            if end is not None and all(x.category == "word" for x in units[k:end]):
                tokens = tuple(t for x in units[k:end + 1] for t in x.tokens)
                out.append(Unit(u.start, units[end].end, "positions", "destination", tokens))
                k = end + 1
                continue
        out.append(u)
        k += 1
    return out


ALONG_A_ROAD = {"down", "along", "up", "on", "in"}  # "riding the wrong way down that same street"
NOT_STREETS = {"traffic", "view", "place", "position", "line", "gear", "reverse", "park", "it", "them", "him", "her"}


def _street_named_alone(units: list[Unit], k: int) -> bool:
    """'onto Walnut,', 'onto Main while ...': a street named by its name alone, a word the lexicon does not know
    right after the turn's 'onto', with nothing after it in its phrase."""
    if k >= len(units) or units[k].category != "word" or len(units[k].tokens) != 1:
        return False
    word = units[k].word
    after = units[k + 1] if k + 1 < len(units) else None
    return word.isalpha() and word not in lexicon().function_words and word not in NOT_STREETS and (
        after is None or after.category == "comma" or after.tokens[0].sentence != units[k].tokens[0].sentence or
        after.category == "word" and after.word in lexicon().function_words)


def _said_by_the_ego(units: list[Unit], k: int) -> bool:
    """The turn at units[k] is the ego's: the agent before it in its sentence is the ego, or there is none."""
    sentence = units[k].tokens[0].sentence
    doer = next((x for x in reversed(units[:k]) if x.category == "agents" and x.tokens[0].sentence == sentence
                 and x.meaning != "none"), None)
    return doer is None or doer.meaning == "ego"


def _short_names(units: list[Unit]) -> list[Unit]:
    """'a Soft Car Target (SCT) ... the SCT brakes': a word the lexicon lacks, given in brackets after an agent
    noun, names that agent wherever it is used."""
    names: dict[str, str] = {}
    for k in range(1, len(units) - 2):
        u, name, close = units[k], units[k + 1], units[k + 2]
        if u.category == "comma" and units[k - 1].category == "agents" and units[k - 1].meaning not in (
                "none", "ego") and name.category == "word" and close.category == "comma" and \
                name.word not in lexicon().function_words and name.word.isalpha() and 2 <= len(name.word) <= 6:
            names[name.word] = units[k - 1].meaning
    if not names:
        return units
    return [Unit(u.start, u.end, "agents", names[u.word], u.tokens) if u.category == "word" and u.word in names
            else u for u in units]


STILL_MOVING = {"going", "driving", "doing", "crawling", "travelling", "traveling", "moving", "trundling", "slow",
                "dawdling", "plodding", "creeping", "rolling", "cruising", "towing", "pulling", "hauling"}
EGO_WORDS = {"you", "i", "we", "player", "ego", "av", "sv"}


def _phrase_words(tokens: list[Token], i: int, n: int) -> list[str]:
    """Up to n words from i, to the end of the phrase ("stuck behind a plow truck doing 15, two kids ...")."""
    words = []
    for t in tokens[i:i + n]:
        if t.word in (",", ".", ";", ":", "and", "but"):
            break
        words.append(t.word)
    return words


def _rides_slowly(tokens: list[Token], i: int) -> bool:
    """'stuck behind a cyclist', 'stuck behind a tractor for miles': one that moves slowly holds the ego up; it is
    not stopped."""
    nouns = [t.base for t in tokens[i:i + 3] if t.word not in ("a", "an", "the", "this", "some", "slow")]
    return bool(nouns) and nouns[0] in ("cyclist", "bike", "bicycle", "tractor", "learner", "horse", "rider",
                                        "caravan")


SKIDS = {"slide", "slid", "skid", "skidded", "slip", "slipped", "plough", "plow", "smash", "slam", "crash", "roll"}
UNCONTROLLED_BY = {"traffic", "light", "lights", "signal", "signals", "sign", "signs", "markings", "stripes",
                   "controls", "any", "zebra", "lollipop", "island", "refuge", "belisha"}
VERB_AFTER_CROSSING = {"the", "a", "an", "road", "street", "in", "from", "over", "into", "to", "toward", "towards",
                       "slowly", "quickly", "suddenly", "carelessly", "directly", "between", "across", "at", "when",
                       "while", "as", "diagonally", "illegally", "right", "left", "just", "without", "outside",
                       "mid", "lanes", "it", "its", "his", "her", "their", "before", "behind", "ahead",
                       "very", "infront", "one", "front", "against", "despite", "during"}  # "a pedestrian crossing
# against the red light": a person crossing
CROSSED_WITHOUT_ARTICLE = {"side", "far", "both", "target", "crosswalk", "crosswalks", "zebra", "roadway",
                           "carriageway"}  # "ped crossing side road crosswalk", "ped crossing far-side crosswalk":
# a note's person crossing, the article before what is crossed left out


LANE_EDGES = {"kerb", "curb", "verge", "gutter", "centre", "center", "edge", "line", "lines", "kerbside", "curbside"}
COLOURS = {"blue", "green", "grey", "gray", "red", "brown", "purple", "coloured", "colored", "metallic", "silver",
           "orange", "yellow", "pink"}
PAINT = COLOURS | {"black", "white", "dark", "maroon", "beige", "gold", "navy", "bronze", "burgundy", "cream"}  # a
# vehicle's paint ("a silver Zafira")
SCENE_NOUNS = {"scene", "scenario", "situation", "case", "simulation", "setup", "test", "one", "example", "sim",
               "level", "map", "run"}


def _read_inside(tokens: list[Token], start: int, end: int) -> list[Unit]:
    """The units of tokens[start:end] read on their own."""
    found = {f.start: f for f in matches(tokens, start, end)}
    out, i = [], start
    while i < end:
        if i in found:
            f = found[i]
            out.append(Unit(f.start, f.end, f.category, f.meaning, tuple(tokens[f.start:f.end])))
            i = f.end
            continue
        t = tokens[i]
        out.append(Unit(i, i + 1, "comma" if t.word == "," else "number" if read_number(t.word) is not None
                        else "word", t.word, (t,)))
        i += 1
    return out


INTERJECTIONS = {"ok", "okay", "so", "well", "alright", "um", "uh", "erm", "er", "hmm", "oh", "and", "now"}
AFTER_A_SPOKEN_RIGHT = INTERJECTIONS | {",", "then", "there", "here", "i", "we", "you", "listen", "let", "let's",
                                        "guys", "folks", "this", "that", "next"}


def _opens_talk(tokens: list[Token], m: Match) -> bool:
    """'Right, so...', 'okay right there's...': a spoken 'right' that opens a sentence is a discourse marker."""
    sentence = tokens[m.start].sentence
    before = [t.word for t in tokens[:m.start] if t.sentence == sentence]
    nxt = tokens[m.end].word if m.end < len(tokens) and tokens[m.end].sentence == sentence else ""
    return all(w in INTERJECTIONS or w == "," for w in before) and nxt in AFTER_A_SPOKEN_RIGHT


OWNERS = {"my", "your", "his", "her", "their", "our"}
BODY_PARTS = {"shoulder", "shoulders"}


CORNERS = {"front_left", "front_right", "back_left", "back_right"}
CLOCK_HOURS = {"one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve",
               *(str(n) for n in range(1, 13))}


def _a_clock_hour(span: list[Token]) -> bool:
    """'at my two o'clock', 'at my seven': a place told by the clock (positions.txt)."""
    return any(t.word in CLOCK_HOURS for t in span) and any(t.word in ("my", "your", "our") for t in span)


def _body_part(tokens: list[Token], m: Match) -> bool:
    """'over your right shoulder', 'a shoulder check': the driver's shoulder, not the road's, nor a side."""
    words = [t.word for t in tokens]
    j = m.end - 1
    if m.end - m.start == 1 and words[j] in ("left", "right") and m.end < len(words) and words[m.end] in BODY_PARTS:
        j = m.end  # the side of the shoulder
    elif words[m.end - 1] not in BODY_PARTS:
        return False
    before = words[j - 1] if j > 0 else ""
    if before in ("left", "right"):
        before = words[j - 2] if j > 1 else ""
    after = words[j + 1] if j + 1 < len(words) else ""
    return before in OWNERS or after in ("check", "checks", "checked", "checking") or \
        before == "the" and j > 1 and words[j - 2] == "over" or before == "over"


VEHICLE_PARTS = {"corner", "bumper", "fender", "wing", "door", "wheel", "tyre", "tire", "panel", "quarter", "mirror",
                 "headlight", "headlamp", "taillight", "lamp", "light", "lights", "indicator", "bodywork", "trailer"}

RIDERS_PARTS = {"elbow", "knee", "leg", "hip", "foot", "ankle", "ear", "handlebar", "handlebars", "pedal", "pannier",
                "panniers"}  # "his mirror clipped my right elbow" (not "shoulder", "arm": of a road too)


def _a_vehicles_part(tokens: list[Token], m: Match) -> bool:
    """'V2's left rear trailer corner', 'my right front fender', 'the left rear tyre': the side names a part of a
    vehicle (where it was struck), not where anyone is."""
    if m.start == 0 or m.end >= len(tokens) or not all(t.word in set(SIDES) | TAIL_ENDS | {"front", "side", "hand"}
                                                       for t in tokens[m.start:m.end]):
        return False
    before = tokens[m.start - 1]
    owned = before.possessive or before.word in OWNERS | POSSESSIVES or before.word == "s"  # "V2's"
    part = _part_after(tokens, m.end)
    return part is not None and (owned or before.word == "the" and part == m.end) and \
        all(t.sentence == before.sentence for t in tokens[m.start - 1:part + 1])


def _part_after(tokens: list[Token], k: int) -> int | None:
    """Where a vehicle's part is named in the next two words ('rear trailer corner', 'front fender')."""
    for j in range(k, min(k + 2, len(tokens))):
        if tokens[j].word == ",":
            return None  # "on our left, light bar going": the side ends at the comma
        if tokens[j].word in VEHICLE_PARTS | RIDERS_PARTS and not tokens[j].plural:
            return j
    return None


PACE_PLACES = {"behind", "ahead", "alongside", "beside", "level", "next", "abreast"}
TAIL_ENDS = {"bumper", "tail", "back", "rear", "boot", "trunk", "tailgate"}


SPEED_UNIT_WORDS = {"mph", "kmh", "kph", "kmph", "mps"}
STILL_AT = {"traffic", "queue", "jam", "red", "lights", "light", "junction", "line"}


MOTORWAYS = {"motorway", "motorways", "highway", "freeway", "expressway", "interstate", "autobahn", "carriageway"}


def _sits_in_moving_traffic(tokens: list[Token], i: int) -> bool:
    """'sitting in the outside lane just behind you': 'sit' with a lane and a place beside or behind the ego
    says where something keeps pace, as drivers say it; 'sitting in the lane, broken down' is still a stop."""
    words = [t.word for t in tokens[i:i + 8] if t.sentence == tokens[i].sentence]
    if any(a in ("on", "off") and b in OWNERS | {"the", "its"} and c in TAIL_ENDS
           for a, b, c in zip(words, words[1:], words[2:])):
        return True  # "sat about 2m off my bumper for miles", "sitting right on our tail": tailgating
    near = words[:12]
    if any(w in ("cruise", "limiter") or w in SPEED_UNIT_WORDS and k > 0 and read_number(near[k - 1]) is not None
           for k, w in enumerate(near)) and not set(near) & STILL_AT:
        return True  # "we were sat in the middle one with the cruise set at 60 mph": sitting at a speed drives on
    if words[1:2] == ["the"]:
        del words[1]  # "sitting in (the) right-hand lane"
    if words[:1] != ["in"] or "lane" not in words[1:5]:
        return False
    sentence = {t.word for t in tokens if t.sentence == tokens[i].sentence}
    speaker = {"you", "you're", "i", "i'm", "we", "we're"} & {t.word for t in tokens[:i]
                                                             if t.sentence == tokens[i].sentence}
    if speaker and {t.word for t in tokens} & MOTORWAYS and \
            not sentence & (STILL_AT | {"stopped", "stationary", "broken", "parked"}):
        return True  # "you're on a three-lane motorway ..., sitting in the middle lane": cruising there ("a van
        # sits in the far side lane" stands)
    after = words[words.index("lane", 1) + 1:]
    after = after[1:] if after[:1] in (["just"], ["right"], ["slightly"], ["directly"]) else after
    return bool(after) and after[0] in PACE_PLACES


HEDGE_VERBS = {"think", "guess", "reckon", "believe", "suppose", "mean"}
HOPING = {"hope", "pray", "trust"}  # "I do hope whoever was waiting for it came to no harm": of them, not of me
TOLD_TO_THE_LISTENER = (("wo", "not", "believe"), ("would", "not", "believe"), ("will", "not", "believe"),
                        ("will", "never", "believe"), ("would", "never", "believe"), ("will", "never", "guess"),
                        ("know", "what"), ("guessed", "it"), ("can", "imagine"), ("could", "imagine"))


SEEING_MODALS = {"could", "can", "couldn't", "can't", "cannot", "would", "wouldn't"}


def _sees_in_general(tokens: list[Token], end: int) -> bool:
    """'you could hardly see across the road', 'you couldn't see a thing': said of anyone, in a text told by an
    'I' or a 'we'."""
    after = [t.word for t in tokens[end:end + 4]]
    return bool(after) and after[0] in SEEING_MODALS and any(w in ("see", "hear") for w in after[1:]) and \
        any(t.word in ("i", "we", "i'm", "we're") for t in tokens)


LEFT_AS_A_VERB_AFTER = {"never", "not", "had", "has", "have", "just", "finally", "eventually", "already", "then",
                        "he", "she", "it", "they", "who", "which", "that", "i", "we", "you"}


LEFT_THERE = {"on", "in", "at", "by", "there", "outside", "across", "behind", "parked", "standing", "stranded",
              "unattended", "abandoned"}


ROOM_WORDS = {"room", "space", "gap", "distance", "time", "margin"}


def _left_room(tokens: list[Token], i: int) -> bool:
    """'should have left more room', 'left a bigger gap', 'left me no space': the room someone leaves, no side."""
    after = [t.word for t in tokens[i + 1:i + 5] if t.sentence == tokens[i].sentence]
    return any(w in ROOM_WORDS for w in after[:4]) and after[0] in ROOM_MEASURES and i > 0 and \
        tokens[i - 1].word in LEFT_AS_A_VERB_AFTER | {"should", "would", "could", "must", "always"}


ROOM_MEASURES = {"more", "enough", "a", "no", "plenty", "some", "me", "him", "her", "them", "us", "any", "little",
                 "too", "loads", "lots", "the", "room", "space"}


def _left_as_a_verb(tokens: list[Token], i: int) -> str | None:
    """'never left the sidewalk', 'he left the scene', 'the van left the junction': the past of 'leave', with
    its object after it, not a side ('move'). 'A lorry had been left on the hard shoulder', 'I was left sitting
    behind it': left standing there ('stop')."""
    before = tokens[i - 1] if i > 0 and tokens[i - 1].sentence == tokens[i].sentence else None
    after = tokens[i + 1] if i + 1 < len(tokens) and tokens[i + 1].sentence == tokens[i].sentence else None
    if before is None or after is None:
        return None
    if before.word in ("been", "was", "were", "is", "are", "be", "being", "got", "get") and (
            after.word in LEFT_THERE or after.word.endswith("ing")):
        return "stop"
    if after.word not in ("the", "a", "an", "his", "her", "its", "their", "my", "our"):
        return None
    entry = _lookup(lexicon(), [before])
    return "move" if before.word in LEFT_AS_A_VERB_AFTER or entry is not None and entry[0] == "agents" else None


SIGHT_WORDS = {"view", "sight", "vision", "visibility"}
LANE_MARKINGS = {"line", "lines", "marking", "markings", "median", "lane line", "lane lines"}


def _over_a_lane_marking(tokens: list[Token], end: int) -> bool:
    """'crossed the solid white line', 'crossed over the double yellows': what is crossed is a line painted
    along the road, so the crosser drifts out of its lane; it does not cross the road."""
    for t in tokens[end:end + 6]:
        if t.sentence != tokens[end - 1].sentence or t.word in (",", "and", "into", "onto", "in", "to", "at"):
            return False
        if t.word in LANE_MARKINGS or t.word in ("yellows", "whites"):
            return True
    return False


QUEUE_NOUNS = {"queue", "jam", "tailback", "backup", "gridlock"}
QUEUE_PLACES = {"in", "of", "into", "join", "joins", "joined", "joining", "at"}


PLACE_OF_A_TURNING = {"to", "past", "after", "before", "beyond", "near", "by", "from", "until", "till", "miss",
                      "missed", "misses", "missing"}


def _turning_named_as_a_place(tokens: list[Token], i: int) -> bool:
    """'back to the Sainsbury's turn', 'just past the Elm Street turn', 'missed the turn': a turning named as a
    place on the road, nobody turning ('took the turn', 'slowed for the turn' still turn)."""
    k = i - 1
    while k >= 0 and tokens[k].sentence == tokens[i].sentence and (
            tokens[k].possessive or tokens[k].word not in DEFINITE | INDEFINITE) and i - k <= 4 and \
            tokens[k].word not in PLACE_OF_A_TURNING:
        if tokens[k].word in SUBJECT_PRONOUNS | {"our", "my", "your", "his", "her", "its", "their"}:
            return False  # "after that we made our turn": someone's turn, a clause of its own, no place
        k -= 1  # back over the turning's name: "the Sainsbury's", "the Elm Street"
    return k > 0 and tokens[k].word in DEFINITE | INDEFINITE and tokens[k - 1].word in PLACE_OF_A_TURNING or \
        k >= 0 and tokens[k].base in ("miss",)


def _unknown_verb_before(tokens: list[Token], i: int) -> bool:
    """A verb the lexicon does not know right before a place ('squeezed over into', 'barged into')."""
    k = i - 1
    if k >= 0 and tokens[k].word in ("over", "across", "back", "straight", "right", "suddenly", "sharply"):
        k -= 1
    if k < 0 or tokens[k].sentence != tokens[i].sentence:
        return False
    t = tokens[k]
    lex = lexicon()
    verb_form = t.word.endswith(("ed", "ing", "es")) or k > 0 and tokens[k - 1].word == "to"  # "trying to squeeze"
    return verb_form and _lookup(lex, [t]) is None and \
        t.word not in lex.function_words and t.base not in ("be", "have", "get")


HEADINGS = {"up", "past", "through", "in", "into", "out", "off", "along", "across", "towards", "toward", "by",
            "around", "round", "away", "onto", "over", "ahead", "behind", "alongside", "after"}


def _heads_somewhere(tokens: list[Token], i: int) -> bool:
    """A weather verb followed by where to ('storming up the outside lane', 'thundering past'): a vehicle rushing
    there; 'storming', 'pouring down' alone are the weather. 'down' heads somewhere only before its road."""
    if i >= len(tokens) or tokens[i].sentence != tokens[i - 1].sentence:
        return False
    subject = next((t for t in reversed(tokens[max(0, i - 7):i - 1]) if t.sentence == tokens[i].sentence and (
        t.word in ("it", ",") or (lexicon().phrases.get((t.base,)) or ("", ""))[0] == "agents")), None)
    if subject is None or subject.word in ("it", ",") or lexicon().phrases[(subject.base,)][1] == "none":
        return False  # "it was snowing in town": the weather; "a van storming past": a road user rushing
    word = tokens[i].word
    return word in HEADINGS or word == "down" and i + 1 < len(tokens) and tokens[i + 1].word in (
        "the", "a", "our", "my", "its", "this", "that")


def _into_a_lane(tokens: list[Token], end: int) -> bool:
    """'into my lane', 'into the outside lane', 'into lane two', 'across into the ego's lane': what follows a verb
    ends in a lane of the road it is on."""
    after = [t.word for t in tokens[end:end + 6] if t.sentence == tokens[end - 1].sentence]
    if after[:1] == ["across"]:
        after = after[1:]
    if after[:1] != ["into"]:
        return False
    rest = after[1:]
    return rest[:1] == ["lane"] or bool(rest) and (rest[0] in OWNERS | POSSESSIVES | {"the"} or
                                                   rest[0].endswith("'s")) and "lane" in rest[1:4] and \
        not {"turn", "turning", "bus", "cycle", "bike"} & set(rest[1:4])


def _coordinated_participle(tokens: list[Token], m: Match) -> bool:
    """'a cyclist is coming from the side road and crossing': 'crossing' after 'and' that joins it to a verb in
    -ing of the same clause is that road user's second verb, not a crosswalk ('a light and crossing')."""
    if m.end - m.start != 1 or m.start < 2 or tokens[m.start - 1].word not in ("and", "then"):
        return False
    if (lexicon().phrases.get((tokens[m.start - 2].base,)) or ("", ""))[0] == "road" or \
            tokens[m.start - 2].word in CORNER_WORDS | {"light", "lights", "signal", "signals"}:
        return False  # "a junction with a light and crossing": the things the road has
    before = [t for t in tokens[max(0, m.start - 9):m.start - 1] if t.sentence == tokens[m.start].sentence]
    return any(t.word.endswith("ing") and (lexicon().phrases.get((t.base,)) or ("", ""))[0] == "actions"
               for t in before)


def _runs_a_light(units: list[Unit], k: int) -> bool:
    """'runs its red light', 'jumped his light': a signal the driver goes through, not the vehicle's own lamp."""
    return [t.word for t in units[k].tokens][-1] == "light" and k > 1 and \
        units[k - 2].tokens[0].base in ("run", "jump", "blow", "go", "shoot", "sail", "barrel", "race")


PASSIVE_ADVERBS = {"then", "also", "later", "soon", "suddenly", "eventually", "finally", "quickly", "slowly", "just",
                   "now", "again", "immediately", "carefully"}
PLANNING_WORDS = {"next", "date", "sprint", "release", "deadline", "week", "month", "end", "completion", "eod", "eow",
                  "friday", "monday", "q1", "q2", "q3", "q4"}


INTENSIFIED = {"down", "up", "out", "off", "back", "away", "along", "round", "around", "through",
               "across", "past"}  # 'right' before them


ASPECT_VERBS = ("started", "starts", "start", "began", "begins", "begin", "kept", "keeps", "continued", "continues",
                "tried", "tries")  # "started crossing": the crossing is done


def _an_unknown_noun_ends_the_phrase(tokens: list[Token], k: int) -> bool:
    """'one merged blob': the word at k is none the lexicon knows, and a function word or the sentence's end
    follows it ('a stopped delivery van' goes on to its noun)."""
    known = lexicon()
    if tokens[k].base in known.function_words or known.phrases.get((tokens[k].base,)) is not None:
        return False
    return k + 1 == len(tokens) or tokens[k + 1].sentence != tokens[k].sentence or \
        tokens[k + 1].base in known.function_words


RETURNING = {"move", "merge", "pull", "swing", "cut", "go", "get", "come", "pop", "drift", "steer", "tuck", "slot",
             "change", "head", "return", "ease", "nip", "dive", "switch"}  # "... back left": back to that lane
KEEPERS = {"keep", "prevent", "stop", "bar", "hinder", "deter", "discourage"}


def _kept_from(tokens: list[Token], m: Match) -> bool:
    """'keeps the ego from changing lanes', 'prevents us from overtaking': the keeping verb and the manoeuvre kept
    from (a gerund after 'from', a keeper a few words before it in the sentence)."""
    sentence = tokens[m.start].sentence
    if m.start > 1 and tokens[m.start - 1].word == "from" and tokens[m.start].word.endswith("ing"):
        return any(t.base in KEEPERS and t.sentence == sentence for t in tokens[max(0, m.start - 6):m.start - 2])
    if m.end - m.start != 1 or tokens[m.start].base not in KEEPERS:
        return False
    later = tokens[m.end + 1:m.end + 6]
    return any(t.word == "from" and k + 1 < len(later) and later[k + 1].word.endswith("ing") and
               t.sentence == sentence for k, t in enumerate(later))


def _disambiguate(tokens: list[Token], m: Match) -> list[Unit]:
    """'a pedestrian crossing the road' is a person crossing, 'a pedestrian crossing' is a crosswalk;
    'parked right at the corner' says where exactly, not which side."""
    span = tuple(tokens[m.start:m.end])
    nxt = tokens[m.end].word if m.end < len(tokens) and tokens[m.end].sentence == span[-1].sentence else ""
    if m.category == "positions" and len(span) == 1 and span[0].word == "right" and m.start > 0 and (
            tokens[m.start - 1].word.endswith("ed") or m.start > 1 and tokens[m.start - 2].word.endswith("ed") and
            tokens[m.start - 1].word in ("up", "in", "over", "down")) and \
            nxt in ("at", "in", "by", "on", "next", "outside", "beside"):
        return [Unit(m.start, m.end, "word", "right", span)]  # ("pulled up right on the line": exactly there)
    after = [t.word for t in tokens[m.end:m.end + 3]]
    if m.category == "actions" and m.end - m.start == 1 and span[0].word.endswith("ed") and \
            span[0].word != span[0].base and m.start > 0 and tokens[m.start - 1].word in ("a", "an", "one", "the") \
            and nxt and _an_unknown_noun_ends_the_phrase(tokens, m.end):
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "one merged blob": a participle before a noun
        # the lexicon does not know says what the thing is, no one's act
    if m.category == "actions" and _kept_from(tokens, m):
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "an oncoming car keeping the ego from moving
        # over": neither keeps to a manoeuvre, and the one kept does not make it
    if m.category == "actions" and m.meaning == "cut_in" and span[-1].word == "into" and span[0].base in SKIDS and (
            after[:2] in (["the", "back"], ["the", "rear"], ["the", "side"]) or after[:1] in (
                ["him"], ["her"], ["me"], ["us"], ["it"], ["them"])):
        return [Unit(m.start, m.end, "actions", "move", span)]  # "slid into the back of him": a skid into it,
        # no move into a lane
    if m.category == "positions" and [t.word for t in span] == ["left"] and _left_room(tokens, m.start):
        return [Unit(m.start, m.end, "word", "left", span)]  # "he should have left more room": no side, no act
    if m.category == "positions" and [t.word for t in span] == ["left"] and _left_as_a_verb(tokens, m.start):
        return [Unit(m.start, m.end, "actions", _left_as_a_verb(tokens, m.start), span)]
        # "the jogger never left the sidewalk": leave; "a lorry had been left on the hard shoulder": it stands
    if m.category == "road" and [t.word for t in span] == ["light"] and nxt and (
            (lexicon().phrases.get((nxt,)) or ("",))[0] == "weather" or nxt in ("traffic", "snowfall", "showers")):
        return [Unit(m.start, m.end, "word", "light", span)]  # "light snowfall, dusk", "light traffic": how much
    if m.category == "actions" and m.meaning == "lane_right" and [t.base for t in span] == ["pull", "over"] and \
            nxt in ("on", "at", "in") and after[1:2] != ["front"]:
        return [Unit(m.start, m.end, "actions", "stop", span)]  # "a semi pulled over on the right shoulder": where
        # it stands ("pulled over into the right lane", "pulled over onto the shoulder": a move)
    if m.category == "agents" and len(span) == 1 and span[0].base in ("plow", "plough") and not (
            span[0].word in ("plow", "plough", "plows", "ploughs") and m.start > 0 and
            tokens[m.start - 1].word in OWNERS | DEFINITE | {"a", "another", "other"}):
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "with the plow": a snowplow; "ploughed into
        # the back of me", "we plow the ramps first": a verb
    if m.category == "positions" and m.meaning in ("back_left", "back_right") and len(span) == 2 and \
            m.start > 0 and tokens[m.start - 1].base in RETURNING:
        return [Unit(m.start, m.start + 1, "word", "back", span[:1]),
                Unit(m.start + 1, m.end, "positions", "side_" + span[1].word, span[1:])]  # "merges back left":
        # back to the lane on the left, no place behind
    if m.category == "actions" and m.meaning == "stop" and [t.base for t in span] == ["sit"] and \
            after[:1] in (["in"], ["right"], ["just"]) and "blind" in [t.word for t in tokens[m.end:m.end + 6]]:
        return [Unit(m.start, m.end, "actions", "move", span)]  # "a car sitting in its blind spot": keeping pace
    if m.category == "agents" and [t.word for t in span] == ["lead"] and not span[0].label and not (
            nxt and tokens[m.end].base in _verbs() and tokens[m.end].base not in lexicon().function_words and
            tokens[m.end].word != tokens[m.end].base and not tokens[m.end].word.endswith("ing") and
            (m.start == 0 or tokens[m.start - 1].word not in MODALS | {"to", "take", "takes", "took", "taking"})):
        return [Unit(m.start, m.end, "word", "lead", span)]  # "lead slams on its brakes": the lead vehicle; "could
        # lead to a crash", "takes the lead": no one
    if m.category == "agents" and len(span) == 1 and span[0].base == "dodge" and (
            span[0].word != "dodge" or m.start == 0 or not (tokens[m.start - 1].word in DETERMINERS | OWNERS |
                                                            POSSESSIVES | COLOURS or tokens[m.start - 1].possessive)):
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "swerved to dodge a pothole", "a cyclist dodging
        # the door": the verb; "a red Dodge", "the dodge": the make
    if m.category == "agents" and [t.word for t in span] == ["focus"] and nxt == "on" and not {
            t.word for t in tokens[m.end + 1:m.end + 4]} & {"left", "right", "side", "lane", "tail", "bumper"}:
        return [Unit(m.start, m.end, "word", "focus", span)]  # "the focus on the oncoming pair": no Ford
    if m.category == "agents" and [t.word for t in span] == ["target"] and nxt in PLANNING_WORDS:
        return [Unit(m.start, m.end, "word", "target", span)]  # "target next sprint": a date, no test target
    if m.category == "actions" and [t.base for t in span] == ["approach"] and m.start > 0 and \
            tokens[m.start - 1].word in OWNERS | POSSESSIVES | {"the", "an", "on"} and nxt in ("to", "of", "", ",", "into"):
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "on the approach to the roundabout": a place
    if m.category == "actions" and m.meaning == "block" and {t.word for t in tokens[m.end:m.end + 3]
                                                             if t.sentence == span[-1].sentence} & SIGHT_WORDS:
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "the pillar blocks your view": of sight
    if m.category == "actions" and m.meaning == "cross" and _over_a_lane_marking(tokens, m.end):
        return [Unit(m.start, m.end, "actions", "move", span)]  # "crossed the centre line": a drift, no crossing
    if m.category == "actions" and m.meaning in ("turn_left", "turn_right") and _into_a_lane(tokens, m.end):
        return [Unit(m.start, m.end, "actions", "lane_" + m.meaning[5:], span)]  # "swung right into my lane",
        # "swung left into lane one": into a lane of the same road, no junction
    if m.category == "actions" and m.meaning in ("turn_left", "turn_right") and m.end - m.start == 2 and \
            span[0].word in SIDES and span[1].word.startswith("turn") and m.start > 1 and \
            tokens[m.start - 1].word in OWNERS | POSSESSIVES | {"the"} and tokens[m.start - 2].word in ("on", "to", "from"):
        return [Unit(m.start, m.start + 1, "positions", f"side_{span[0].word}", span[:1])] + \
            _read_inside(tokens, m.start + 1, m.end)  # "a van on my left turning left": its side, then its turn
    if m.category == "positions" and len(span) > 1 and span[0].word in SIDES and m.start > 0 and \
            tokens[m.start - 1].base in ("turn", "bear"):
        return [Unit(m.start, m.start + 1, "positions", f"side_{span[0].word}", span[:1])] + \
            _read_inside(tokens, m.start + 1, m.end)  # "turns right in front of me": its turn, then where
    if m.category == "positions" and m.meaning == "into_ego_lane" and span[-1].word == "lane" and \
            m.end < len(tokens) and tokens[m.end].sentence == span[-1].sentence and \
            _word_number(tokens[m.end]) in (1, 2, 3, 4, 5):  # "pull out into lane two": a numbered lane, not ours
        return [Unit(m.start, m.end + 1, "positions", f"into_lane_{int(_word_number(tokens[m.end]))}",
                     tuple(tokens[m.start:m.end + 1]))]
    if m.category == "positions" and m.meaning in CORNERS and _a_clock_hour(span):
        ahead, side = m.meaning.split("_")  # "a van at my two o'clock": ahead and to the right, each as said apart,
        return [Unit(m.start, m.end - 1, "positions", "ahead" if ahead == "front" else "behind", span[:-1]),
                Unit(m.end - 1, m.end, "positions", "side_" + side, span[-1:])]  # so a crossing or a road wins
    if m.category == "actions" and m.meaning == "turn" and [t.base for t in span] == ["turn"] and nxt == "up" and (
            m.end + 1 >= len(tokens) or tokens[m.end + 1].sentence != span[0].sentence or
            tokens[m.end + 1].word in ("later", "soon", "eventually", "after", "at", "and", ",", "then", "too", "as")):
        return [Unit(m.start, m.end, "actions", "reach", span)]  # "a police officer turned up later": arrived
    if m.category == "agents" and [t.word for t in span] == ["pov"] and m.start == 0 and m.end < len(tokens) and \
            tokens[m.end].word == "is" and not {t.word for t in tokens} & {"sv", "ego", "sv1", "v1"}:
        return [Unit(m.start, m.end, "word", "pov", span)]  # "POV: ur turning left ...": a caption's point of view
        # (the ego's), not a crash report's principal other vehicle
    if m.category == "positions" and m.meaning == "ego_lane" and [t.word for t in span][-1:] == ["way"] and \
            m.start > 0 and tokens[m.start - 1].word == "on":
        return [Unit(m.start, m.end, "word", "way", span)]  # "an ambulance was on its way": coming, no place
    if m.category == "agents" and m.meaning == "none" and span[0].word in OWNERS and span[-1].possessive:
        return [Unit(m.start, m.end, "word", span[-1].word, span)]  # "in my husband's Honda": whose it is, as said
    if m.category == "agents" and m.meaning == "ego" and [t.base for t in span] == ["iv"] and span[0].plural:
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "2 large bore IVs": drips, no insured vehicle
    if m.category == "agents" and [t.word for t in span] == ["op"] and m.start > 0 and tokens[m.start - 1].word == "co":
        return [Unit(m.start, m.end, "word", "op", span)]  # "outside the Co-op": a shop, not the original poster
    if m.category == "positions" and [t.word for t in span] == ["right"] and m.start > 0 and nxt in INTENSIFIED and \
            "actions" in ((lexicon().phrases.get((tokens[m.start - 1].base,)) or ("", ""))[0],
                          (lexicon().phrases.get((tokens[m.start - 1].base, nxt)) or ("", ""))[0]):
        return [Unit(m.start, m.end, "word", "right", span)]  # "slows right down", "pulled right out": how far
    if m.category == "positions" and [t.word for t in span] == ["right"] and nxt == "at" and \
            [t.word for t in tokens[m.end + 1:m.end + 2]] in (["me"], ["us"], ["him"], ["her"], ["them"], ["you"]):
        return [Unit(m.start, m.end, "word", "right", span)]  # "came right at me": straight at, no side
    if m.category == "actions" and m.meaning == "stop" and [t.word for t in span] == ["stop"] and m.start > 0 and \
            tokens[m.start - 1].word in ("says", "said", "reads", "read", "saying", "reading"):
        return [Unit(m.start, m.end, "road", "stop", span)]  # "the sign says stop": a stop sign, nobody stopping
    if m.category == "agents" and m.meaning == "ego" and [t.word for t in span] in (["us"], ["i"]) and \
            _road_number(tokens, m.end):
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "US-101", "I-70": a highway, not the narrators
    if m.category == "agents" and m.meaning == "ego" and [t.word for t in span] == ["i"] and \
            m.end < len(tokens) and (tokens[m.end].word in HEDGE_VERBS or tokens[m.end].word in HOPING or
                                     tokens[m.end].word in ("do", "really", "just") and
                                     m.end + 1 < len(tokens) and tokens[m.end + 1].word in HOPING):
        return [Unit(m.start, m.end, "word", "i", span)]  # "a truck, I think, pulls out": a hedge, not the ego acting
    if m.category == "agents" and m.meaning == "ego" and [t.word for t in span] == ["you"] and \
            (_says_any([t.word for t in tokens[m.end:m.end + 3]], TOLD_TO_THE_LISTENER) or
             m.start > 0 and tokens[m.start - 1].word == "mind" and (
                 m.end == len(tokens) or tokens[m.end].sentence != span[0].sentence or tokens[m.end].word == ",")):
        return [Unit(m.start, m.end, "word", "you", span)]  # "You won't believe this, a guy on a motorcycle", "in
        # broad daylight, mind you": the listener, addressed, not the one driving
    if m.category == "agents" and m.meaning == "ego" and [t.word for t in span] == ["you"] and \
            _sees_in_general(tokens, m.end):
        return [Unit(m.start, m.end, "word", "you", span)]  # "Foggy, you could hardly see across the road. I was
        # sat on the bench": anyone there, not one at a wheel
    if m.category == "positions" and len(span) == 1 and span[0].word in ("backed", "backs", "backing") and \
            m.end < len(tokens) and tokens[m.end].word in ("off", "away"):
        return [Unit(m.start, m.end, "actions", "move", span)]  # "it just backed off smooth": it eased off, no place
    if m.category == "actions" and len(span) == 2 and span[-1].word in ("right", "left") and \
            m.meaning.startswith("lane_") and [t.word for t in tokens[m.end:m.end + 2]] in (
                ["in", "front"], ["ahead", "of"], ["behind", "me"], ["behind", "us"], ["next", "to"], ["beside", "me"],
                ["beside", "us"]):
        verb = matches(list(span[:1]))
        return [Unit(m.start, m.start + 1, verb[0].category, verb[0].meaning, span[:1]) if verb else
                Unit(m.start, m.start + 1, "word", span[0].word, span[:1]),
                Unit(m.start + 1, m.end, "word", span[-1].word, span[1:])]  # "merged right in front of my car": how
        # close, not which way
    if m.category == "actions" and [t.word for t in span] == ["turn"] and m.start > 1 and \
            tokens[m.start - 1].word in OWNERS and tokens[m.start - 2].word in ("is", "was", "be", "s"):
        return [Unit(m.start, m.end, "word", "turn", span)]  # "to know when it is their turn": one's turn in an
        # order, no manoeuvre
    if m.category == "actions" and [t.word for t in span] == ["travel"] and m.end < len(tokens) and \
            tokens[m.end].word in ("lane", "lanes"):
        return [Unit(m.start, m.end, "word", "travel", span)]  # "stopped in the travel lane": a lane's kind
    if m.category == "actions" and len(span) == 1 and span[0].word in LAMP_STATES and m.start > 0 and \
            tokens[m.start - 1].word in LAMPS:
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "a police car stopped with its lights flashing":
        # its lamps, no movement
    if m.category == "positions" and m.meaning == "level" and after[:1] in (["a"], ["the"]) and \
            after[1:2] in (["crosswalk"], ["crossing"], ["zebra"]):
        return [Unit(m.start, m.end, "positions", "crosswalk", span)]  # "standing right next to a crosswalk": by it
    if m.category == "positions" and m.meaning == "behind" and ([t.word for t in span] == ["in", "the", "back"] or [
            t.word for t in span] in (["in", "back"], ["in", "the", "rear"], ["in", "rear"]) and m.start > 0 and
            tokens[m.start - 1].base in KIN) and \
            (m.end >= len(tokens) or tokens[m.end].word != "of" or [t.word for t in tokens[m.end + 2:m.end + 3]] in (
                ["car"], ["vehicle"], ["van"], ["cab"], ["taxi"], ["suv"])):
        return [Unit(m.start, m.end, "positions", "on_board", span)]  # "kids arguing in the back", "two children
        # were in the back of the car", "Daughter in rear, fine": my passengers
    if m.category == "positions" and m.meaning == "behind" and [t.word for t in span][:1] == ["in"] and \
            span[-1].word in ("back", "rear") and after[:1] in (["seat"], ["seats"]):
        return [Unit(m.start, m.end, "positions", "on_board", span)]  # "son in back seat", "kids in the rear seat"
    if m.category == "actions" and m.start > 1 and tokens[m.start - 1].word in ("parallel", "bay", "reverse") and \
            tokens[m.start - 2].word in OWNERS | POSSESSIVES | {"the", "a"}:
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "your parallel park was fine": a manoeuvre named
    if m.category == "positions" and _a_vehicles_part(tokens, m):
        return [Unit(m.start, m.end, "word", span[-1].word, span)]  # "V2's left rear trailer corner": no place
    if m.category == "positions" and _body_part(tokens, m):
        return [Unit(m.start, m.end, "word", span[-1].word, span)]  # "a look over your right shoulder": no verge
    if m.category == "positions" and len(span) == 1 and span[0].word == "right" and _opens_talk(tokens, m):
        return [Unit(m.start, m.end, "word", "right", span)]  # "Right, so there's an ambulance": no side
    if m.category == "positions" and len(span) == 1 and span[0].word == "right" and m.start > 0 and (
            after[:1] and after[0] in ("behind", "ahead", "beside", "alongside", "next", "up")
            or after[:2] == ["in", "front"] and tokens[m.start - 1].base not in ("turn", "bear") or after[:1] == ["on"] and after[2:3] and after[2] in ("tail", "bumper")):
        return [Unit(m.start, m.end, "word", "right", span)]  # "sits right on our tail": how close, not a side
    if m.category == "positions" and len(span) == 1 and span[0].word == "right" and m.start > 0 and (
            after[:1] in (["there"], ["through"]) or after[:3] in (["in", "the", "middle"], ["in", "the", "centre"],
                                                                  ["in", "the", "center"])) and \
            tokens[m.start - 1].base not in STEERING - {"slide", "skid"} | {"turn", "bear", "indicate", "signal", "cut",
                                                                           "merge"} and \
            not _a_side_owned(tokens, m.start):  # "slid right through": straight (not "on my right through")
        return [Unit(m.start, m.end, "word", "right", span)]  # "riding right in the middle of the lane": exactly
    if m.category == "actions" and m.meaning == "stop" and len(span) == 1 and span[0].base == "sit" and \
            [t.word for t in tokens[m.end:m.end + 2]] == ["in", "the"] and m.end + 3 < len(tokens) and \
            tokens[m.end + 3].word == "lane" and \
            any(t.word in EGO_WORDS for t in tokens[max(0, m.start - 3):m.start]):
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "you sat in the left lane": where, not a stop
    if m.category == "actions" and m.meaning == "stop" and [t.base for t in span] == ["hold"] and (
            [t.word for t in tokens[m.end:m.end + 2]] in (["my", "lane"], ["my", "line"], ["our", "lane"],
                                                          ["our", "line"]) or
            nxt == "the" and m.end + 1 < len(tokens) and tokens[m.end + 1].word in LANE_NAMES):
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "I held the middle, steady": kept to a lane
    if m.category == "actions" and m.meaning == "stop" and [t.base for t in span] == ["hold"] and (
            nxt is not None and read_number(nxt) is not None or nxt in ("a", "steady", "speed", "my", "our", "her",
                                                                     "his", "its") and
            any(t.word in ("speed", "steady", "mph", "kmh", "pace") or read_number(t.word) is not None
                for t in tokens[m.end:m.end + 4])):
        return [Unit(m.start, m.end, "actions", "go_straight", span)]  # "Held 40 all the way over", "holding a
        # steady 15 m/s": a speed kept, no stop
    if m.category == "actions" and m.meaning == "stop" and len(span) == 1 and span[0].base == "sit" and \
            nxt == "back":
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "I sat back behind the bike": hung back, moving
    if m.category == "actions" and m.meaning == "stop" and len(span) == 1 and span[0].base == "sit" and \
            _sits_in_moving_traffic(tokens, m.end):
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "a motorbike sitting in the right lane just
        # behind you": where it keeps pace, not a stop
    if m.category == "actions" and m.meaning == "stop" and [t.base for t in span][-1:] == ["move"] and \
            span[0].word == "not" and nxt in ("over", "across", "aside"):
        return [Unit(m.start, m.end, "word", "not", span)]  # "a ticket for not moving over": no lane change, no stop
    if m.category == "actions" and m.meaning == "stop" and [t.word for t in span] == ["stuck"] and (
            nxt in STILL_MOVING or nxt == "behind" and (set(_phrase_words(tokens, m.end + 1, 5)) & STILL_MOVING
                                                       or _rides_slowly(tokens, m.end + 1))):
        return [Unit(m.start, m.end, "word", "stuck", span)]  # "stuck behind a crawling van": slow, not stopped
    if m.category == "actions" and [t.word for t in span] == ["slow"] and m.start > 0 and \
            tokens[m.start - 1].word in ("a", "an", "the", "this", "that", "very", "really"):
        return [Unit(m.start, m.end, "behaviours", "cautious", span)]  # "a slow bus": how it drives, no verb
    if m.category == "positions" and m.meaning in ("side_left", "side_right") and span[0].word == "into" and \
            span[-1].word == "lane" and _unknown_verb_before(tokens, m.start):
        return [Unit(m.start, m.end, "actions", "lane_" + m.meaning[5:], span)]  # "squeezed over into the left
        # lane", "muscled into the right lane": any verb of motion into a lane beside is a lane change
    if m.category == "positions" and [t.word for t in span] == ["abreast"] and m.start > 0 and \
            _word_number(tokens[m.start - 1]) is not None:
        return [Unit(m.start, m.end, "word", "abreast", span)]  # "riding two abreast": how they ride, side by side
        # in the lane, not where they are (nor two of them apart)
    if m.category == "actions" and m.meaning == "turn" and [t.base for t in span] == ["turn"] and \
            _turning_named_as_a_place(tokens, m.start):
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "queue's back to the Sainsbury's turn"
    if m.category == "actions" and m.meaning == "stop" and len(span) == 1 and span[0].base in QUEUE_NOUNS and (
            span[0].possessive or m.start > 0 and tokens[m.start - 1].word in DEFINITE | INDEFINITE | OWNERS and
            (m.start < 2 or tokens[m.start - 2].word not in QUEUE_PLACES)):
        return [Unit(m.start, m.end, "word", span[0].word, span)]  # "through the queue", "the queue's back to": the
        # queue named, nobody said to stand in it ("in the queue", "at the back of the queue": standing)
    if m.category == "actions" and [t.word for t in span] == ["park"] and m.start > 0 and \
            tokens[m.start - 1].word in ("the", "a", "city", "car", "national", "retail", "business", "theme"):
        return [Unit(m.start, m.end, "word", "park", span)]  # "the intersection by the park": a place, no stop
    if m.category == "agents" and [t.word for t in span] == ["target"] and m.start > 0 and \
            tokens[m.start - 1].word in ("by", "at", "near", "outside", "from", "to", "behind") and \
            tokens[m.start].sentence == tokens[m.start - 1].sentence:
        return [Unit(m.start, m.end, "word", "target", span)]  # "the crosswalk by target": the shop; a test
        # target is "the target" or "a target"
    if m.category == "agents" and [t.word for t in span] == ["pick", "up"] and _picks_someone_up(tokens, m.start, nxt):
        return _units_of_one_word(tokens, m.start) + _units_of_one_word(tokens, m.start + 1)
        # "stopped to pick up two women": the verb, no pickup truck
    if m.category == "agents" and [t.word for t in span] == ["pickup"] and _picking_up(tokens, m.start, nxt):
        return [Unit(m.start, m.end, "word", "pickup", span)]  # "a late night pickup downtown": a fare, no truck
    if m.category == "weather" and len(span) == 1 and span[0].word != span[0].base and not \
            m.meaning.startswith("time:") and span[0].word.endswith(("ing", "ed", "s")) and \
            (lexicon().phrases.get((span[0].base,)) or ("", ""))[0] == "weather" and _heads_somewhere(tokens, m.end):
        return [Unit(m.start, m.end, "actions", "move", span)]  # "an ambulance storming up from behind": it rushes
    if m.category == "weather" and [t.word for t in span] == ["dark"] and nxt in COLOURS:
        return [Unit(m.start, m.end, "word", "dark", span)]  # "a dark blue saloon": a shade, not the night
    prev = tokens[m.start - 1] if m.start > 0 else None
    if m.category == "positions" and m.meaning == "destination" and span[0].word == "where" and (
            prev is None or prev.word in SCENE_NOUNS):
        return [Unit(m.start, m.start + 1, "word", "where", span[:1])] + _read_inside(tokens, m.start + 1, m.end)
        # "a scene where the ego turns left": what happens in the scene, not the road the ego turns into
    if prev is not None and prev.word == "," and m.start > 1 and m.category == "road":
        prev = tokens[m.start - 2]  # "pedestrians (crossing, from left)": the noun before the bracket
    if m.category == "agents" and m.meaning == "none" and [t.word for t in span] == ["bus", "stops"] and \
            prev is not None and prev.word in ("a", "the", "this", "that", "city", "school"):
        return [Unit(m.start, m.start + 1, "agents", "bus", span[:1]),  # "a bus stops": no bus stops
                Unit(m.start + 1, m.end, "actions", "stop", span[1:])]
    if m.category == "agents" and m.meaning == "none" and [t.word for t in span] == ["car", "parks"] and \
            prev is not None and prev.word in ("a", "an", "one", "another", "this", "that", "each"):
        return [Unit(m.start, m.start + 1, "agents", "car", span[:1]),  # "a car parks on the left": no car parks
                Unit(m.start + 1, m.end, "actions", "stop", span[1:])]
    auxiliary = prev
    if prev is not None and prev.word in PASSIVE_ADVERBS and m.start > 1:
        auxiliary = tokens[m.start - 2]  # "the van is then passed by the ego"
    if m.category == "actions" and len(span) > 1 and span[-1].word == "by" and auxiliary is not None and \
            auxiliary.word in ("is", "are", "was", "were", "be", "been", "being", "gets", "got", "get"):
        return [Unit(m.start, m.end - 1, "actions", m.meaning, span[:-1]),  # "is passed by the ego": a passive
                Unit(m.end - 1, m.end, "word", "by", span[-1:])]
    after_person = prev is not None and prev.base in ("pedestrian", "child", "kid", "ped", "cyclist", "person",
                                                      "people", "jogger", "man", "woman", "boy", "girl", "student",
                                                      "vru", "children", "kids", "peds", "pedestrians", "walker",
                                                      "toddler", "pensioner", "cyclists", "bicyclist",
                                                      "target", "dummy") or \
        any((_lookup(lexicon(), list(tokens[m.start - n:m.start])) or ("", ""))[1] == "pedestrian"
            for n in (1, 2, 3) if m.start >= n)  # "schoolkids crossing", "three little ones crossing"
    after_verb = prev is not None and prev.word in ("keep", "keeps", "kept", "is", "are", "was", "were", "be", "not",
                                                    "been", "start", "starts", "begin", "begins", "stop", "stops",
                                                    "finish", "finishes", "while", "when", "still", "already")
    person_before = after_person or prev is not None and prev.word == "," and m.start > 1 and \
        tokens[m.start - 2].base in ("target", "dummy", "pedestrian", "cyclist", "child", "person") or \
        prev is not None and (lexicon().phrases.get((prev.base,)) or ("", ""))[1] in V.VULNERABLE_TYPES or \
        prev is not None and prev.word in ("is", "are", "was", "were") + ASPECT_VERBS and m.start > 1 and \
        ((lexicon().phrases.get((tokens[m.start - 2].base,)) or ("", ""))[1] in V.VULNERABLE_TYPES or
         prev.word in ASPECT_VERBS and tokens[m.start - 2].word in ("he", "she", "they"))
    # "EBT crossing from the right": a word that names a person or a rider; "a cyclist is crossing from the left",
    # "a man started crossing from the right"
    if m.category == "positions" and m.meaning in ("road_left", "road_right") and span[0].word == "crossing" and \
            person_before:  # "a cyclist crossing from the right": a person crossing the road, from that side
        side = m.meaning[5:]
        return [Unit(m.start, m.start + 1, "actions", "cross", span[:1]),
                Unit(m.start + 1, m.end, "positions", f"from_{side}", span[1:])]
    nxt2 = tokens[m.end + 1].word if m.end + 1 < len(tokens) else ""
    place_then_verb = nxt in ("ahead", "behind") and nxt2 in ("is", "was", "are", "were", "has", "had")
    on_a_crossing = nxt in ("on", "along") and bool({t.word for t in tokens[m.end + 1:m.end + 4]} & {
        "crosswalk", "crosswalks", "zebra", "crossing"}) or nxt == "on" and nxt2 == "red"  # "ped crossing on the
    # crosswalk": a person crossing at it; "a pedestrian crossing on red": crossing while the light is red
    lone_piece = len(span) == 1 and m.start > 0 and tokens[m.start - 1].word == "," and (
        m.end >= len(tokens) or tokens[m.end].sentence != span[0].sentence or tokens[m.end].word == ",") and any(
            (lexicon().phrases.get((t.base,)) or ("", ""))[1] in V.VULNERABLE_TYPES
            for t in tokens[:m.start] if t.sentence == span[0].sentence)
    # "cyclist: on crosswalk at exit arm, crossing": a note's piece of its own about a person, what they do
    at_the_crossing = len(span) > 1 and m.start >= 2 and tokens[m.start - 1].word in ("a", "the") and \
        tokens[m.start - 2].word in ("at", "near", "by", "approaching", "approaches", "reaches", "reaching") and \
        nxt in ("while", "when", "as", "before", "after", ",", "and", "")  # "waits at a pedestrian crossing while
    # three children walk across": the crosswalk, no person crossing
    at_the_crossing = at_the_crossing or len(span) > 1 and m.start >= 2 and nxt not in ("the", "a", "an", "from") and \
        tokens[m.start - 2].sentence == span[0].sentence and (
            tokens[m.start - 1].word == "the" and tokens[m.start - 2].word in (
                "across", "over", "through", "onto", "into", "on", "along", "towards", "toward", "reaches",
                "reaching", "approaching", "approaches") or tokens[m.start - 1].word in ("across", "over", "through",
                                                                                         "onto"))
    # "walks across the pedestrian crossing just in front of us", "goes through pedestrian crossing on red"
    counted = len(span) > 1 and span[-1].word == "crossing" and (span[0].word in ("pedestrians", "peds") or (
        m.start > 0 and (_word_number(tokens[m.start - 1]) or 0) >= 1))  # "two pedestrians crossing": people
    if m.category == "road" and [t.word for t in span] == ["crossing"] and prev is not None and \
            prev.word in ("a", "the") and not any((lexicon().phrases.get((t.base,)) or ("", ""))[1] in
                                                  V.VULNERABLE_TYPES for t in tokens):
        return [Unit(m.start, m.end, "road", "junction", span)]  # "turns left at a crossing without traffic
        # lights" ("Kreuzung", "cruce"), no one on foot or on a bicycle to cross: where roads cross
    if m.category == "road" and [t.word for t in span] == ["crossing"] and nxt and \
            (lexicon().phrases.get((tokens[m.end].base,)) or ("", ""))[1] in V.VULNERABLE_TYPES:
        return [Unit(m.start, m.end, "actions", "cross", span)]  # "a crossing cyclist": one who crosses, no crosswalk
    if m.category == "road" and span[-1].word in ("crossing", "xing") and (
            len(span) == 1 or span[0].base in ("pedestrian", "ped")) and (
            nxt in VERB_AFTER_CROSSING or on_a_crossing or nxt in CROSSED_WITHOUT_ARTICLE and nxt2 not in (
                "by", "from", "of") and not (prev is not None and prev.word in ("a", "an", "the")) or lone_piece or
            counted or (len(span) == 1 and (after_person or after_verb or _coordinated_participle(tokens, m)))) and \
            not place_then_verb and not at_the_crossing and \
            not (prev is not None and prev.word in ("no", "without", "any", "a", "the") and len(span) == 1) and not (
                nxt in ("without", "with") and nxt2 in UNCONTROLLED_BY):  # "pedestrian crossing without traffic
        # light": the crossing and what it lacks ("crossing without looking": a person crossing)
        # the verb: "a pedestrian crossing the road"; the noun stays: "no crossing", "the pedestrian crossing ahead is"
        out = []
        if len(span) > 1 and span[0].word in ("pedestrian", "pedestrians", "ped", "peds"):
            out.append(Unit(m.start, m.start + 1, "agents", "pedestrian", span[:1]))
        out.append(Unit(m.end - 1, m.end, "actions", "cross", span[-1:]))
        return out
    return [Unit(m.start, m.end, m.category, m.meaning, span)]


# -- road, weather, kinds -----------------------------------------------------------------------------------

PICKUP_TIMES = {"night", "morning", "evening", "afternoon", "midnight", "airport", "station", "school", "late", "early",
                "passenger", "rider", "ride", "uber", "lyft", "taxi", "cab", "curbside", "kerbside"}
PICKUP_PLACES = {"downtown", "location", "point", "spot", "time", "address", "zone", "area"}


def _picking_up(tokens: list[Token], start: int, nxt: str) -> bool:
    """'late night pickup downtown', 'an airport pickup', 'the pickup point': a passenger collected, no vehicle."""
    prev = tokens[start - 1].word if start > 0 and tokens[start - 1].sentence == tokens[start].sentence else ""
    return prev in PICKUP_TIMES or nxt in PICKUP_PLACES


OBJECT_STARTS_OF_PEOPLE = {"him", "her", "them", "me", "us", "someone", "somebody", "people", "passengers", "kids",
                           "children", "pupils", "everyone"}


def _picks_someone_up(tokens: list[Token], start: int, nxt: str) -> bool:
    """'to pick up two women', 'stopped and pick up the kids': the verb with its object after it; a truck is 'a
    pick up', 'his old pick up'."""
    prev = tokens[start - 1].word if start > 0 and tokens[start - 1].sentence == tokens[start].sentence else ""
    return prev in ("to", "and", "or", "then", "will", "would", "can", "could", "must", "should", "i", "we", "they",
                    "he", "she", "you", "please") or nxt in DEFINITE | INDEFINITE | OWNERS | OBJECT_STARTS_OF_PEOPLE \
        or read_number(nxt) is not None or (lexicon().phrases.get((nxt,)) or ("", ""))[0] == "numbers"


CARRYING = {("pick", "up"), ("drop", "off"), ("let", "off"), ("let", "out"), ("let", "on"), ("set", "down"),
            ("load", ""), ("unload", ""), ("collect", ""), ("ferry", ""), ("transport", ""), ("carry", "")}
CARRYING_VERBS = {verb for verb, _ in CARRYING}


def _carried(tokens: list[Token], start: int, end: int) -> str:
    """'picking kids up', 'to drop off some pupils', 'letting people off', 'unloading schoolchildren': the people a
    vehicle takes on or sets down are its passengers, no agents of their own ('taken'); a person carried in
    someone's arms is 'held'; '' when neither."""
    def base(i: int) -> str:
        if not (0 <= i < len(tokens) and tokens[i].sentence == tokens[start].sentence):
            return ""
        word = tokens[i].word
        for suffix, stem in (("ying", "y"), ("ies", "y"), ("ied", "y"), ("ting", ""), ("ping", ""), ("ing", ""),
                             ("ped", ""), ("ed", ""), ("s", "")):  # "picking", "dropped", "ferries", "letting"
            if word.endswith(suffix) and (word[:-len(suffix)] + stem) in CARRYING_VERBS:
                return word[:-len(suffix)] + stem
        return word
    after = tokens[end].word if end < len(tokens) and tokens[end].sentence == tokens[start].sentence else ""
    if base(start - 1) == "carry":
        return "held"
    taken = (base(start - 2), base(start - 1)) in CARRYING or (base(start - 1), after) in CARRYING or \
        (base(start - 1), "") in CARRYING
    return "taken" if taken else ""


POSSESSIVES = {"its", "his", "her", "their"}
PUSHED_ALONG = {"push", "wheel", "walk", "drag", "carry", "lift", "lead", "pushing", "wheeling", "walking"}
HAND_HELD = {"holding", "holds", "held", "carrying", "carries", "waving", "waves", "raising", "raises"}


LAMPS = {"lights", "light", "lamps", "hazards", "hazard", "beacons", "beacon", "blues", "strobes", "flashers",
         "indicators", "indicator", "blinkers", "blinker", "headlights", "headlamps"}
LAMP_STATES = {"flashing", "flash", "flashed", "going", "blazing", "strobing", "strobe", "blinking", "spinning",
               "pulsing", "whirling", "ablaze"}  # "lights strobing": a vehicle's own lamps, no signal


DENIED_KINDS = {"marked", "painted", "designated", "proper", "formal", "official", "dedicated", "real", "actual",
                "signalised", "signalized", "controlled", "pedestrian", "visible", "working"}


def _road(r: _Reader) -> RoadSpec:
    fields: dict = {"required_signals": [], "without_signals": [], "required_objects": [], "without_objects": []}
    junction: bool | None = None
    lanes: int | None = None
    negated = False
    units = r.units

    titled: set[str] = set()  # said only in a title ("scenario: ped_crossing_night"): the body's word wins
    in_title = False

    def put(word: str, forbidden: bool) -> None:
        group = "signals" if word in V.SIGNALS else "objects"
        target = fields[f"{'without' if forbidden else 'required'}_{group}"]
        other = fields[f"{'required' if forbidden else 'without'}_{group}"]
        if word in other and word in titled and not in_title:
            other.remove(word)  # "scenario: ped_crossing_night ... road: 1 lane, no crosswalk": none there
            titled.discard(word)
        if word not in target and word not in other:
            target.append(word)
            if in_title:
                titled.add(word)

    negated_in, removing = -1, False
    uncontrolled: list[list[str]] = []
    for k, u in enumerate(units):
        in_title = u.tokens[0].title
        if negated and u.tokens[0].sentence != negated_in:
            negated = False  # "no crossing. Road: mid-block": a denial ends with its sentence
        if u.category == "actions" and len(u.tokens) > 2:
            for m in matches(list(u.tokens), 1):  # "held at the stop line": where it holds is on the road
                if m.category == "road" and (m.meaning in V.OBJECTS or m.meaning in ("stop", "yield") and
                                             m.end - m.start > 1):  # (not "flashing his lights": its own lamps)
                    put(m.meaning, False)
        if u.word == "none" and k > 0 and _none_after(units, k - 1):
            r.mark(u)
            continue  # "CROSSWALK NONE, LIGHT GREEN": the none closes what it follows, denying nothing after
        if u.category == "word" and u.word in NEGATIONS | REMOVED or (u.category == "word" and u.word.endswith("n't")) \
                or (u.category == "numbers" and u.meaning == "0"):
            negated, negated_in = True, u.tokens[0].sentence
            removing = u.category == "word" and u.word in REMOVED
            r.mark(u)
            owner = k - 1 - (k > 1 and units[k - 1].word == "with")
            if k > 0 and units[owner].category == "agents" and units[owner].meaning not in ("none", "ego") and \
                    k + 1 < len(units) and units[k + 1].category == "road" and units[k + 1].meaning == "traffic_light":
                units[k + 1].category = "word"  # "a cyclist without lights", "with no lights": its own lamps
                negated = False
            continue
        if u.category in ("road", "positions") and _then_doubted(units, k):
            said = u.meaning if u.category == "road" else (
                "continental_crosswalk" if "zebra" in {t.word for t in u.tokens} else "crosswalk"
            ) if u.meaning == "crosswalk" else None
            if said in V.SIGNALS or said in V.OBJECTS:
                put(said, True)  # "at a crosswalk? probably not": said, then taken back
            r.mark(u)
            continue
        if u.category == "actions" and u.base == "stop" and _sign_said_once_for_two(units, k):
            put("stop", negated)  # "without stop or give-way signs": the stop sign, its noun said once
            r.mark(u)
            u.category, u.meaning = "road", "stop"
            continue
        yielding_to = k + 1 < len(units) and units[k + 1].word == "to"  # "yielding to emergency vehicles": the act
        if u.category == "actions" and u.base in ("yield", "give way") and not yielding_to and (
                k == 0 or units[k - 1].category in ("comma", "word")
                and units[k - 1].word in (",", "a", "at", "with", "the")
                or (k + 1 < len(units) and units[k + 1].word in ("sign", "signs", "junction", "line", "markings"))):
            put("yield", negated)  # "a give way junction", "roundabout entry, give way": the sign
            r.mark(u)
            u.category, u.meaning = "road", "yield"
            continue
        if u.category == "actions" and u.meaning == "stop" and _held_at_the_line(units, k):
            put("stop_line", False)  # "waits at the line", "stopped at the white line": the stop line
        if u.category == "sequence" and {"light", "lights", "signal", "green"} & {t.word for t in u.tokens}:
            put("traffic_light", False)  # "when the light goes green": a signal there
        if u.category == "actions" and {"stop", "sign"} <= {t.word for t in u.tokens}:
            put("stop", False)  # "runs the stop sign"
        elif u.category == "actions" and {"red", "light", "lights"} & {t.word for t in u.tokens} and not \
                {t.word for t in u.tokens} & (POSSESSIVES | {"flash", "flashing", "flashed", "flashes", "headlights"}):
            put("traffic_light", False)  # "runs a red light"; not "flashing his lights", its own lamps
        if u.category == "road" and u.meaning == "traffic_light" and u.tokens[0].word in ("signals", "signal",
                                                                                          "signaled") \
                and any(x.category == "agents" for x in units[max(0, k - 3):k]) and not (
                    k > 0 and units[k - 1].word in ("a", "the", "at", "with", "no", "traffic")):
            continue  # "a cyclist signals and turns left": a hand signal, not a traffic light
        if u.category == "road" and u.meaning == "traffic_light" and len(u.tokens) == 1 and \
                u.tokens[0].word in ("signaled", "signalled") and k + 2 < len(units) and units[k + 1].word == "by" \
                and units[k + 2].category in ("agents", "word"):
            continue  # "was signalled by a police car to pull in": waved in by someone, not a traffic light
        if u.category == "road" and u.meaning == "traffic_light" and u.tokens[0].word in ("signal", "signals") and \
                {x.word for x in units[max(0, k - 3):k + 4] if x.tokens[0].sentence == u.tokens[0].sentence} & {
                    "mirror", "mirrors", "maneuver", "manoeuvre", "position"}:
            continue  # "mirror, signal, manoeuvre": the driver's routine, the indicator, not a traffic light
        if u.category == "road" and u.meaning == "traffic_light" and [t.word for t in u.tokens] == ["signal"] and \
                any(x.word in ("without", "no", "never") for x in units[max(0, k - 3):k]) and (any(
                    x.category == "actions" and x.tokens[0].sentence == u.tokens[0].sentence
                    for x in units[max(0, k - 6):k]) or _beside_a_lane_move(units, k)) and \
                not _controls_listed_after(units, k):
            r.mark(u)
            negated = False
            continue  # "turned left without any signal", "lurches into my lane -- no signal, nothing": no
            # indicator, not a junction without traffic lights
        if u.category == "road" and u.meaning in ("stop", "yield") and k > 1 and \
                {units[k - 1].word, units[k - 2].word} & HAND_HELD:
            r.mark(u)
            continue  # "a crossing guard holding a stop sign": a hand-held sign, not the road's
        if u.category == "word" and u.word in SIGNAL_COLOURS and k > 0 and \
                units[k - 1].tokens[-1].word in ("on", "through", "against") and not (
                    k + 1 < len(units) and units[k + 1].word in STREET_SUFFIXES and
                    units[k + 1].tokens[0].sentence == u.tokens[0].sentence):  # (not "on Green Lane": a street)
            put("traffic_light", False)  # "goes straight on green": the phrase took the "on", the colour is a signal's
        if u.category == "road" and u.meaning == "traffic_light" and u.tokens[-1].word in ("light", "lights") and (
                any(x.word in POSSESSIVES for x in units[max(0, k - 2):k]) and not _runs_a_light(units, k) or
                u.tokens[-1].word == "lights" and any(x.word in LAMP_STATES for x in units[max(0, k - 1):k + 2])):  # "a flashing red light": a signal
            r.mark(u)
            continue  # "the bus has stopped with its red lights flashing": its own lamps, not a signal
        if u.category == "road" and u.meaning == "traffic_light" and {t.word for t in u.tokens} <= {"light", "lights"} \
                and any(x.word in ("had", "has", "have", "having") for x in units[max(0, k - 4):k]) and any(
                    x.word in ("he", "she", "they", "it") or x.category == "agents" for x in units[max(0, k - 6):k]):
            r.mark(u)
            negated = False
            continue  # "he had no lights at all": the rider's own lamps
        if u.category == "actions" and u.tokens[-1].word in ("junction", "intersection", "crossroads") and \
                junction is None:
            junction = True  # "goes straight across the junction": the path names the junction it crosses
        if u.category == "road":
            r.mark(u)
            meaning = u.meaning
            said_not = negated or _none_after(units, k)  # ("LIGHT NONE": this one only)
            if meaning == "none":
                pass
            elif meaning == "junction":
                denied = _denied(units, k)
                if junction is None or denied:
                    junction = not denied
            elif meaning == "no_junction":
                junction = False if not said_not else junction
            elif meaning == "highway":
                lanes = max(lanes or 0, 2)
                junction = False if junction is None else junction
            elif meaning == "sign":
                if said_not:
                    put("stop", True)
                    put("yield", True)
            elif meaning.startswith("!") and "+" in meaning:
                uncontrolled.append(meaning[1:].split("+"))  # decided once every control said is known
            elif meaning.startswith("!"):
                for word in meaning[1:].split("+"):
                    put(word, True)
            elif meaning == "stop+junction":  # "a four-way stop": a stop sign at a junction
                put("stop", said_not)
                junction = True if junction is None else junction
            else:
                if meaning == "traffic_light" and u.tokens[0].word in ("light", "lights") and not said_not and \
                        k > 0 and units[k - 1].category == "weather":
                    continue  # "light rain" is read as weather first; a stray "light" after weather is not a signal
                put(meaning, said_not)
            continue
        if u.category == "positions" and u.meaning in ("crosswalk", "off_crosswalk") and _none_after(units, k):
            put("continental_crosswalk" if "zebra" in {t.word for t in u.tokens} else "crosswalk", True)
            continue  # "STREET, CROSSWALK NONE"
        if u.category == "positions" and u.meaning in ("crosswalk", "off_crosswalk"):  # "near the crosswalk": there is one
            said = {t.word for t in u.tokens}
            word = "continental_crosswalk" if "zebra" in said else "crosswalk"
            if not any(w in V.CROSSWALK_OBJECTS for w in fields["required_objects"] + fields["without_objects"]) \
                    and "any" not in said and not (u.meaning == "off_crosswalk" and said & {"a", "an"}):
                # "outside any crosswalk", "crossing outside a crosswalk": there may be none
                put(word, False)
        if u.category == "comma" or (u.category == "word" and u.word in
                                     {"and", "or", "nor", "a", "an", "any", "either", "sign", "signs", "traffic",
                                      "even", "really", "actually", "ever", "single"} | DENIED_KINDS):
            continue  # "no marked crosswalk", "no proper give-way sign", "isn't even a crossing": the denial
            # reaches past its kind and its adverb
        if removing and u.category == "word" and u.word in ("the", "its", "their", "both"):
            continue  # "removed the stop sign and the stop line": each thing removed
        if u.category == "agents" and u.meaning == "none" and u.word == "traffic":
            continue
        negated = False
    for controls in uncontrolled:
        if not set(controls) & set(fields["required_signals"]):  # "minor arm under give-way control, major road
            for word in controls:  # uncontrolled": the major road has priority; the junction has its give-way
                put(word, True)
    kinds = [w for w in fields["required_objects"] if w in V.CROSSWALK_OBJECTS and w != "crosswalk"]
    if kinds and "crosswalk" in fields["required_objects"]:
        fields["required_objects"].remove("crosswalk")  # "a zebra crossing ... stops before the crossing": one
    speed_limits = _speed_limits(r)
    for word in speed_limits:
        put(word, False)
    lanes = _lanes(r, lanes)
    spec: dict = {k: tuple(v) for k, v in fields.items()}
    if lanes is not None:
        spec["lanes"] = lanes
    if junction is not None:
        spec["junction"] = junction
    return RoadSpec.model_construct(**(RoadSpec().model_dump() | spec))


def _held_at_the_line(units: list[Unit], k: int) -> bool:
    """'waits at the line', 'stopped at the white line': where one stops at 'the line' it is the stop line (not
    'the line of cars', not 'in line')."""
    words = [u.word for u in units[k + 1:k + 5] if u.tokens[0].sentence == units[k].tokens[0].sentence]
    if units[k].tokens[-1].word in ("at", "to"):
        words = ["at"] + words
    return words[:3] in (["at", "the", "line"], ["to", "the", "line"]) and words[3:4] != ["of"] or \
        words[:4] in (["at", "the", "white", "line"], ["to", "the", "white", "line"]) and words[4:5] != ["of"]


def _controls_listed_after(units: list[Unit], k: int) -> bool:
    """'with no signal, stop or yield control': the signal heads a list of a junction's controls, no indicator."""
    return k + 2 < len(units) and units[k + 1].word in ("or", "and", "nor", ",") and (
        units[k + 2].category == "road" and units[k + 2].meaning in ("stop", "yield") or
        units[k + 2].category == "actions" and units[k + 2].base == "stop" and _sign_said_once_for_two(units, k + 2))


def _sign_said_once_for_two(units: list[Unit], k: int) -> bool:
    """'stop or give way signs', 'stop and yield signs', 'signals, stop or yield control': a first sign named by its
    word alone, its noun said with the second."""
    if k + 2 >= len(units) or units[k + 1].word not in ("or", "and", "nor", ","):
        return False
    nxt = units[k + 2]
    return nxt.category == "road" and nxt.meaning in ("yield", "stop") and \
        nxt.tokens[-1].word in ("sign", "signs", "control", "controlled")


LANE_MOVES = {"cut_in", "lane_change", "lane_left", "lane_right"}


def _beside_a_lane_move(units: list[Unit], k: int) -> bool:
    """'No signal, nothing.' said of a vehicle moving into the ego's lane, in its sentence or the two before: the
    vehicle's indicator. Where those sentences name a junction, the signal is the junction's."""
    sentence = units[k].tokens[0].sentence
    near = [x for x in units if sentence - 2 <= x.tokens[0].sentence <= sentence]
    return not any(x.category == "road" and x.meaning in ("junction", "stop+junction") for x in near) and any(
        x.category == "actions" and x.meaning in LANE_MOVES or
        x.category == "positions" and x.meaning in ("ego_lane", "into_ego_lane") for x in near)


def _then_doubted(units: list[Unit], k: int) -> bool:
    """'not sure if at a crosswalk, probably not': a road feature wondered about and then taken back."""
    sentence = units[k].tokens[0].sentence
    after = [u.word for u in units[k + 1:k + 5] if u.tokens[0].sentence in (sentence, sentence + 1)]
    return any(a in ("probably", "prob", "maybe", "likely") and b == "not" for a, b in zip(after, after[1:]))


def _none_after(units: list[Unit], k: int) -> bool:
    """'CROSSWALK NONE', 'LIGHT NONE, SIGN NONE' (a sign-language gloss): the thing said, then denied."""
    return k + 1 < len(units) and units[k + 1].word == "none" and units[k + 1].tokens[0].sentence == \
        units[k].tokens[-1].sentence


def _denied(units: list[Unit], k: int) -> bool:
    """'no junction', 'not at a junction', 'without any junctions', 'away from junctions', 'intersection none'."""
    if _none_after(units, k):
        return True
    for j in range(k - 1, max(0, k - 3) - 1, -1):
        u = units[j]
        if u.category == "word" and u.word == "away" and j > 0 and (units[j - 1].category == "actions" or
                                                                  units[j - 1].word.endswith("ing")):
            return False  # "a cyclist riding along the street, heading away from the junction": its way
        if u.category == "word" and (u.word in NEGATIONS or u.word == "away") or \
                u.category == "numbers" and u.meaning == "0":
            return True
        if not (u.category == "word" and u.word in {"at", "a", "an", "any", "from", "near", "the"} | DENIED_KINDS):
            return False  # ("no marked crosswalk": the denial reaches past its kind)
    return False


LIMIT_WORDS = {"limit", "zone", "sign", "signs", "signed", "signposted", "limited", "posted", "restricted", "maximum",
               "max", "limits"}


LIMITED_PLACES = {"road", "street", "highway", "motorway", "freeway", "zone", "area", "stretch", "section", "lane",
                  "avenue", "roadway", "carriageway", "route", "limit", "arterial", "boulevard", "expressway",
                  "dual", "bypass", "parkway", "thoroughfare", "collector", "residential", "interstate", "autobahn",
                  "bit", "part", "stretches"}  # "the 20 mph bit by the park"


MILES_WORDS = {"mph", "miles", "mile", "feet", "ft", "yards", "yd", "yds", "interstate", "freeway", "northbound",
               "southbound", "eastbound", "westbound"}  # a text that measures in miles, or a US highway's words
BRITISH_ROAD_WORDS = {"lorry", "zebra", "pushchair", "pelican", "puffin", "toucan"}  # signed in miles an hour
ROAD_NUMBER_PREFIXES = {"i", "us", "sr", "cr", "sh", "fm", "route", "rte", "hwy", "highway", "interstate", "exit", "m"}
NUMBERED_NAMES = ROAD_NUMBER_PREFIXES | {"year", "class", "grade", "platform", "gate", "bay", "terminal", "pier",
                                         "room", "floor", "zone", "number"}  # "Mr Patel from Year 4 cycles in"


SPEED_UNITS = (["mph"], ["km", "h"], ["kmh"], ["kph"], ["miles", "per", "hour"])
BEFORE_A_ROADS_SPEED = {"a", "an", "the", "on", "in", "into", "onto", "along", "down", "up", ","}


def _speed_of_a_road(tokens: list[Token], first: int, last: int) -> bool:
    """'a 40 mph road', '25 mph residential street', 'on a 50 km/h urban road': a speed that qualifies a road
    (up to two words between, 'urban', 'two-lane') is its limit, nobody's speed."""
    sentence = tokens[last].sentence
    if first > 0 and tokens[first - 1].sentence == sentence and tokens[first - 1].word not in BEFORE_A_ROADS_SPEED:
        return False
    after = [t.word for t in tokens[last + 1:last + 7] if t.sentence == sentence]
    unit = next((len(u) for u in SPEED_UNITS if after[:len(u)] == u), 0)
    if not unit:
        return False
    between = after[unit:unit + 3]
    place = next((k for k, w in enumerate(between) if w in LIMITED_PLACES), None)
    return place is not None and all(w.isalpha() and w not in ("in", "on", "at", "and", "to", "when", "while",
                                                                 "through", "past", "towards", "the", "a")
                                     for w in between[:place])


def _road_number(tokens: list[Token], i: int) -> bool:
    """'I-95', 'US-101', 'Route 30', 'the M25': a number that names a road, not a speed."""
    return 0 < i < len(tokens) and tokens[i - 1].word in ROAD_NUMBER_PREFIXES and \
        tokens[i - 1].sentence == tokens[i].sentence \
        and tokens[i].word.isdigit()


def _measured_in_miles(tokens: list[Token]) -> bool:
    """A text that gives speeds or distances in miles, drives on a US interstate or on British roads (it keeps
    left, or speaks of lorries and zebra crossings): a limit it says with no unit is in miles an hour ('three
    lanes my direction, speed limit 70' on I-95, 'Church Road, 30 limit'); never a text that says km/h."""
    if any(t.word in ("kmh", "km", "kph", "kilometers", "kilometer") for t in tokens):
        return False
    return _drives_on_the_left(tokens) or any(
        t.word in MILES_WORDS | BRITISH_ROAD_WORDS or _road_number(tokens, k) and tokens[k - 1].word in (
            "i", "us", "interstate") for k, t in enumerate(tokens))


ONE_LANE_EACH_WAY = (("single", "carriageway"), ("one", "lane", "each", "way"), ("one", "lane", "in", "each"),
                     ("a", "lane", "each", "way"), ("single", "track"), ("single", "lane", "road"))


def _says_any(words: list[str], phrases) -> bool:
    """Whether one of the phrases (tuples of words) is said, word for word, in the words."""
    return any(tuple(words[k:k + len(p)]) == p for p in phrases for k in range(len(words)))


def _one_lane_each_way(tokens: list[Token]) -> bool:
    """'a single carriageway', 'one lane each way': a road with no second lane in a direction."""
    return _says_any([t.word for t in tokens], ONE_LANE_EACH_WAY)


def _speed_limits(r: _Reader) -> list[str]:
    """'a 30 km/h speed limit', 'a speed limit of ninety', 'a limit of forty', 'twenty miles per hour'."""
    tokens, out = r.tokens, []
    in_miles = _measured_in_miles(tokens)
    for i, t in enumerate(tokens):
        value = _word_number(t)
        if value is None or (i + 1 < len(tokens) and _word_number(tokens[i + 1]) is not None
                             and read_number(t.word) is None) or _road_number(tokens, i) or \
                value == 0 and not t.word.isdigit():
            continue  # the tens of "thirty five": read at the units; "I-95" names a road; "no signs" counts none
        value, first = _number_before(tokens, i)
        alone = all(first <= x.index <= i for x in _sentence(tokens, t.sentence))
        around = {x.word for x in tokens[max(0, first - 4): i + 5] if x.sentence == t.sentence or alone and
                  x.sentence == t.sentence - 1}  # not "70 mph limit. 00:05 Ambulance ...": a limit is said in
        # its own sentence, or answered alone after it ("What was the limit there? Fifty-five.")
        after_unit = [x.word for x in tokens[i + 1: i + 5]]
        unit_then_road = _speed_of_a_road(tokens, first, i)
        speed_of_someone = first > 0 and tokens[first - 1].word in (
            "doing", "going", "travelling", "traveling", "driving", "at", "about", "around", "approximately",
            "roughly", "nearly", "almost") and not {x.word for x in tokens[i + 1:i + 4] if x.sentence == t.sentence} \
            & (LIMIT_WORDS | LIMITED_PLACES) \
            and not (first > 1 and tokens[first - 2].word in LIMIT_WORDS | {"signed", "signposted"})  # "posted at 25"
        said_limit = _said_to_be_the_limit(tokens, i)
        if speed_of_someone and not said_limit:
            continue  # "a learner doing 20 in a 40 zone": 20 is the learner's speed, 40 the limit
        road_then_unit = first > 1 and {x.word for x in tokens[max(0, first - 3):first] if x.sentence == t.sentence
                                        and not (x.word == "lane" and _word_number(tokens[x.index - 1]) is None)
                                        } & LIMITED_PLACES and \
            not _speed_in_a_lane(tokens, first) and \
            after_unit[:1] and after_unit[0] in ("mph", "kmh", "kph", "km")  # "divided highway, 65 mph"
        if not (around & LIMIT_WORDS or said_limit or unit_then_road or road_then_unit or _a_bare_limit(tokens, first, i)) or {x.word for x in tokens[i + 1: i + 2]} & {"lane", "lanes", "m", "meters",
                                                                                 "seconds", "s", "cars"}:
            continue
        rest = [x.word for x in tokens[i + 1: i + 4]]
        mph = rest[:1] == ["mph"] or rest[:3] == ["miles", "per", "hour"] or rest[:2] == ["miles", "an"]
        unitless = not rest or rest[0] not in ("kmh", "km", "kilometers", "kilometer")
        if unitless and not mph and value % 10 == 5 and 15 <= value <= 85:
            mph = True  # "25 limit", "Limit's 65": US signs in miles an hour step by five
            r.notes.append(f"inferred: a limit of {value:g} with no unit is read as mph (a US sign)")
        elif unitless and not mph and (in_miles or _KEEPS_LEFT.get()) and value % 5 == 0 and 10 <= value <= 85:
            mph = True  # "doing 35 mph in a 40 zone", "I-95, speed limit 70": the text's own unit; "a 50 limit on
            # the motorway": a British sign
            r.notes.append(f"inferred: a limit of {value:g} with no unit is read as mph (the text measures in miles)")
        unit = "mph" if mph else "km/h"
        kmh = value * 1.609344 if mph else value
        r.used.update(j for j in range(max(0, first - 4), min(len(tokens), i + 5))
                      if tokens[j].word in LIMIT_WORDS | {"speed", "kmh", "mph", "of", "km", "miles", "kilometers",
                                                          "per", "hour", "an"} or first <= j <= i)
        limit = round(kmh)
        low, high = V.SPEED_SIGN_LIMITS
        if not low <= limit <= high:
            shown = "a number too large to read" if value >= TOO_LARGE else f"{value:g} {unit}"
            r.notes.append(f"left out: a speed limit of {shown} is outside {low}..{high} km/h")
            continue
        if mph:
            r.notes.append(f"inferred: {value:g} mph is speed_{limit} (km/h)")
        if f"speed_{limit}" not in out:
            out.append(f"speed_{limit}")
    return out


LIMIT_HEDGES = {"is", "was", "the", "speed", "literally", "exactly", "just", "actually", "basically", "also", "bang",
                "on", "right", "precisely", "legal", "posted"}  # "which is literally the limit"; not "way over the limit"


def _said_to_be_the_limit(tokens: list[Token], i: int) -> bool:
    """'I was doing 60, which is literally the limit', 'doing 30, that's the limit there': a speed the text
    says is the limit names the limit too."""
    after = [t.word for t in tokens[i + 1:i + 9] if t.sentence == tokens[i].sentence]
    if after[:1] == [","]:
        after = after[1:]
    if not after or after[0] not in ("which", "that", "ie", "i.e", "exactly", "bang", "right"):
        return False
    if "limit" not in after:
        return False
    between = after[1:after.index("limit")]
    return bool({"is", "was"} & set(between)) and "the" in between and set(between) <= LIMIT_HEDGES


def _speed_in_a_lane(tokens: list[Token], first: int) -> bool:
    """'AV traveling in right lane ~30 mph', 'in lane 3, 10 mph': the speed of whoever drives in the lane, not a
    sign's ('down to one lane and 45 mph' is still a limit)."""
    for j in range(first - 1, max(-1, first - 4), -1):
        if tokens[j].word in ("lane", "lanes"):
            return any(x.word in ("in", "on") for x in tokens[max(0, j - 3):j])
    return False


AFTER_A_BARE_LIMIT = {",", "through", "there", "here", "around", "along", "on", "so", "and", "but", "zone", "now"}


def _a_bare_limit(tokens: list[Token], first: int, i: int) -> bool:
    """'it's a 65 through there', 'doing 80 in a 65': a limit named by its number alone, as US drivers say it."""
    value = _word_number(tokens[i])
    nxt = tokens[i + 1] if i + 1 < len(tokens) and tokens[i + 1].sentence == tokens[i].sentence else None
    return first > 0 and tokens[first - 1].word == "a" and value is not None and value % 5 == 0 and \
        15 <= value <= 85 and value % 10 == 5 and (nxt is None or nxt.word in AFTER_A_BARE_LIMIT)


PER_DIRECTION = {"per", "each", "every", "in", "a", "one"}


BOUND_WORDS = {"northbound", "southbound", "eastbound", "westbound", "inbound", "outbound"}
COUNTED_LANE_KINDS = {"through", "travel", "traffic", "running", "driving", "general", "approach", "thru", "moving"}


DIVIDED_ROADS = {("dual", "carriageway"), ("dual", "carriageways"), ("divided", "highway")}


def _lanes(r: _Reader, lanes: int | None) -> int | None:
    """'a two-lane road', 'three lanes in each direction' (which wins over a total: 'a four-lane avenue, two
    lanes each way'), 'multi-lane'."""
    tokens = r.tokens
    found: list[tuple[bool, int]] = []
    for i, t in enumerate(tokens):
        if t.word not in ("lane", "lanes") or i == 0:
            continue
        prev = tokens[i - 1]
        one_way = prev.word in BOUND_WORDS  # "three southbound lanes": the lanes of one direction
        if prev.word in COUNTED_LANE_KINDS | BOUND_WORDS and i >= 2 and _word_number(tokens[i - 2]) is not None:
            prev = tokens[i - 2]  # "two through lanes", "three travel lanes": a traffic engineer's kind of lane
        numbered = _numbered_lane(tokens, i) or _named_lane_of(tokens, i)
        if numbered is not None:  # "in lane two of three": lanes are numbered on one carriageway
            found.append(numbered)
            continue
        n = _word_number(prev)
        if n is None:
            if prev.word in ("multi", "multiple", "several", "many"):
                n = 2.0
            elif prev.word == "single":
                n = 1.0
        if n is None or n == 0:
            continue
        nxt = tokens[i + 1].word if i + 1 < len(tokens) else ""
        if not (t.word == "lanes" or t.word == "lane" and nxt not in ("change", "changes", "changing")):
            continue
        after = {x.word for x in tokens[i + 1: i + 4]}
        per_direction = one_way or bool(after & {"direction", "way", "each", "per"}) and bool(
            after & PER_DIRECTION | after & {"direction", "way"})
        r.used.update((i - 1, i))
        if n >= TOO_LARGE:
            r.notes.append("repaired: a lane count too large to read; used lanes >= 6")
            n = 6
        found.append((per_direction, int(n)))
    if found:
        for i, t in enumerate(tokens[:-2]):  # "a four-lane road, two in each direction"
            n = _word_number(t)
            after = [x.word for x in tokens[i + 1:i + 4]]
            if n and 0 < n < TOO_LARGE and after[:1] in (["in"], ["each"], ["per"], ["a"]) and (
                    "direction" in after or "way" in after):
                found.append((True, int(n)))
                r.used.add(i)
    if not found:
        divided = any((t.word, nxt.word) in DIVIDED_ROADS for t, nxt in zip(tokens, tokens[1:]))
        if divided and (lanes or 1) < 2:
            r.notes.append("inferred: lanes >= 2 (a dual carriageway has two lanes each way)")
            return 2
        return lanes
    per = [n for p, n in found if p]
    return max(per) if per else max([n for _, n in found] + [lanes or 0])


def _numbered_lane(tokens: list[Token], i: int) -> tuple[bool, int] | None:
    """'lane two of three' says three lanes each way; 'in lane 3' at least three."""
    if tokens[i].word != "lane" or i + 1 >= len(tokens) or tokens[i + 1].sentence != tokens[i].sentence:
        return None
    n = _word_number(tokens[i + 1])
    if n is None or not 1 <= n < 10 or n != int(n):
        return None
    if i + 3 < len(tokens) and tokens[i + 2].word == "of":
        of = _word_number(tokens[i + 3])
        if of is not None and n <= of < 10:
            return True, int(of)
    return (False, int(n)) if n >= 2 else None


LANE_NAMES = {"left", "right", "middle", "centre", "center", "inside", "outside", "nearside", "offside", "fast", "slow",
              "overtaking", "first", "second", "third", "inner", "outer"}


def _named_lane_of(tokens: list[Token], i: int) -> tuple[bool, int] | None:
    """'the middle lane of three', 'the left lane of two': how many lanes the ego's carriageway has."""
    if tokens[i].word != "lane" or tokens[i - 1].word not in LANE_NAMES or i + 2 >= len(tokens) or \
            tokens[i + 1].word != "of" or tokens[i + 2].sentence != tokens[i].sentence:
        return None
    n = _word_number(tokens[i + 2])
    return (True, int(n)) if n is not None and 2 <= n < 10 and n == int(n) else None


def _word_number(t: Token) -> float | None:
    """A number written in digits or as one number word ('three', 'forty')."""
    value = read_number(t.word)
    if value is not None:
        return value
    entry = lexicon().phrases.get((t.word,))
    if entry and entry[0] == "numbers" and t.word not in ("some", "few", "crowd", "group", "multiple", "various",
                                                          "bunch", "handful", "several", "couple", "pair"):
        return float(entry[1])
    return None


def _number_before(tokens: list[Token], i: int) -> tuple[float | None, int]:
    """The number ending at token i: '50', 'fifty', 'thirty five'; (value, first token)."""
    value = _word_number(tokens[i]) if 0 <= i < len(tokens) else None
    if value is None:
        return None, i
    if value < 10 and i > 0:
        tens = _word_number(tokens[i - 1])
        if tens is not None and tens >= 20 and tens % 10 == 0 and not read_number(tokens[i - 1].word):
            return tens + value, i - 1
    return value, i


INTENSIFIERS = {"quite", "really", "very", "pretty", "so", "fairly", "rather", "extremely", "incredibly", "that"}
RAIN_DEGREES = {"hard": "hard_rain", "heavily": "hard_rain", "heavy": "hard_rain", "lightly": "soft_rain",
                "light": "soft_rain", "softly": "soft_rain", "gently": "soft_rain"}


def _weather(r: _Reader) -> Weather | None:
    conditions, times = [], []
    for k, u in enumerate(r.units):
        if u.category != "weather":
            continue
        j = k - 1
        while j > 0 and r.units[j].word in ("a", "an", "any") and len(r.units[j].tokens) == 1:
            j -= 1  # "normal rain, not a storm"
        before = r.units[j] if j >= 0 else None
        if before is not None and before.category in ("word", "numbers") and before.word in ("no", "without", "not"):
            r.mark(u)
            continue
        r.mark(u)
        if u.meaning.startswith("time:") and _time_of_a_cause(r.units, k):
            r.notes.append(f"left out: '{' '.join(t.word for t in u.tokens)}' (when something before the scene "
                           "happened, not the scene's time)")
            continue
        if u.meaning.startswith("time:") and _part_of_a_date(r.units, k):
            hour = _hour_of_the_part(r.units, k)
            if hour is not None:  # "this morning at about 7": seven in the morning
                times.append(hour)
                continue
            r.notes.append(f"left out: '{' '.join(t.word for t in u.tokens)}' (it dates the event, as a day's "
                           "morning or afternoon, and says nothing of the light)")
            continue
        meaning = u.meaning
        degree = [x for x in r.units[k + 1:k + 3] if x.tokens[0].sentence == u.tokens[0].sentence]
        while degree and degree[0].word in INTENSIFIERS:
            degree = degree[1:]
        if meaning == "mid_rain" and degree and degree[0].word in RAIN_DEGREES:
            meaning = RAIN_DEGREES[degree[0].word]  # "raining quite hard", "raining very lightly"
            r.mark(degree[0])
            degree[0].category = "word"  # how hard it rained, said of no one
        (times if meaning.startswith("time:") else conditions).append(
            (meaning.removeprefix("time:"), " ".join(t.word for t in u.tokens)))
    clock = _clock_time(r)
    if clock and not times:
        times.append(clock)
    if not conditions and not times:
        return None
    condition = _one_condition(conditions, r.notes)
    time = times[0][0] if times else V.DEFAULT_TIME
    for other, said in times[1:]:
        if other != time:
            r.notes.append(f"left out: '{said}' (the scene has one time of day: {time})")
    return Weather(condition=condition, time=time)


WEEKDAYS = {"monday", "tuesday", "wednesday", "thursday", "friday", "saturday", "sunday"}
MONTHS = {"january", "february", "march", "april", "may", "june", "july", "august", "september", "october",
          "november", "december", "jan", "feb", "mar", "apr", "jun", "jul", "aug", "sep", "sept", "oct", "nov", "dec"}
DAYS_FROM_TODAY = {"this", "yesterday", "tomorrow"}  # "that morning" in a story still says its light
CLOCK_PARTS_OF_DAY = {"morning", "afternoon"}  # hours on a clock; "night", "dusk" say how light it is


def _part_of_a_date(units: list[Unit], k: int) -> bool:
    """'On Friday morning', 'this morning', 'the afternoon of 9th October': the morning or afternoon of a named day
    says when it happened, like a date; 'a foggy morning' or 'early (this) morning' still says the light."""
    u = units[k]
    if u.word not in CLOCK_PARTS_OF_DAY:
        return False
    hour_said = any(read_number(v.word) is not None for v in units[k + 1:k + 5] if v.category in ("word", "number"))
    if k > 0 and (units[k - 1].word in WEEKDAYS or units[k - 1].word in DAYS_FROM_TODAY and not hour_said) and \
            not any(v.word == "early" for v in units[max(0, k - 4):k]):
        return True  # "on the commute this morning": the day it happened, as a date ("early this morning", "this
        # morning at about 7": the light of that hour)
    after = [v.word for v in units[k + 1:k + 5]]
    if after[:1] == ["of"]:
        rest = after[1:] if after[1:2] != ["the"] else after[2:]
        return bool(rest) and (rest[0] in WEEKDAYS | MONTHS or rest[0] in ORDINALS or
                               read_number(rest[0]) is not None or rest[0].rstrip("stndrh").isdigit())
    return False


def _hour_of_the_part(units: list[Unit], k: int) -> tuple[str, str] | None:
    """'this morning at about 7', 'at 5 this afternoon': an hour said with the part of the day it falls in."""
    near = units[max(0, k - 4):k] + units[k + 1:k + 5]
    for j, v in enumerate(near):
        value = _word_number(v.tokens[0]) if v.category in ("number", "numbers") else None
        if value is not None and 1 <= value <= 12 and value == int(value) and j > 0 and \
                near[j - 1].word in TIME_INTRODUCERS:
            hour = int(value) % 12 + (12 if units[k].word == "afternoon" else 0)
            return _hour_time(hour, f"{v.word} in the {units[k].word}")
    return None


SINCE = {"from", "since"}
CAUSE_FILLER = {"this", "the", "last", "earlier", "yesterday", "rain", "rainfall", "shower", "showers", "storm",
                "downpour", "frost", "snow", "snowfall", "'s", "of"}


def _time_of_a_cause(units: list[Unit], k: int) -> bool:
    """'wet from this morning', 'icy since last night': when the road got so, not the scene's time of day."""
    sentence = units[k].tokens[0].sentence
    for j in range(k - 1, max(-1, k - 5), -1):
        u = units[j]
        if u.tokens[0].sentence != sentence:
            return False
        if u.word in SINCE:  # after a state of the road: "wet from", "icy since"
            return j > 0 and units[j - 1].category == "weather" and not units[j - 1].meaning.startswith("time:")
        if u.word not in CAUSE_FILLER and u.category not in ("weather",):
            return False
    return False


def _clock_time(r: _Reader) -> tuple[str, str] | None:
    """'At 23:10' is night, '12:05' and '3 pm' noon (the afternoon is daytime), '17:40' sunset, '06:30' dawn;
    other hours say no time of day."""
    for i, t in enumerate(r.tokens[:-1]):
        nxt = r.tokens[i + 1]
        if t.word.isdigit() and nxt.word in ("am", "pm") and 1 <= int(t.word) <= 12:  # "at 9 pm", "6am"
            hour = int(t.word) % 12 + (12 if nxt.word == "pm" else 0)
            r.used.update((t.index, nxt.index))
            return _hour_time(hour, f"{t.word} {nxt.word}")
        if t.word.isdigit() and len(t.word) == 4 and nxt.word in ("hours", "hrs", "hr", "h") and \
                int(t.word[:2]) < 24 and int(t.word[2:]) < 60:  # "at 2215 hours": a statement's 24-hour clock
            r.used.update((t.index, nxt.index))
            return _hour_time(int(t.word[:2]), f"{t.word} {nxt.word}")
        if read_number(t.word) is None or read_number(nxt.word) is None or nxt.index != t.index + 1:
            continue
        if not (len(nxt.word) == 2 and t.word.isdigit() and int(t.word) < 24 and nxt.word.isdigit()):
            continue
        r.used.update((t.index, nxt.index))
        after = r.tokens[i + 2].word if i + 2 < len(r.tokens) else ""
        if after in ("am", "pm") and 1 <= int(t.word) <= 12:  # "7:45 PM"
            r.used.add(r.tokens[i + 2].index)
            return _hour_time(int(t.word) % 12 + (12 if after == "pm" else 0), f"{t.word}:{nxt.word} {after}")
        if not _said_as_the_time(r.tokens, i):
            r.notes.append(f"left out: '{t.word}:{nxt.word}' (a record's time stamp, not the scene's time of day)")
            continue
        return _hour_time(int(t.word), f"{t.word}:{nxt.word}")
    return None


TIME_INTRODUCERS = {"at", "around", "about", "after", "before", "by", "until", "till", "since", "was", "is",
                    "timeofday", "time", "clock", "day", "approximately", "nearly", "almost", "past"}
TIME_HEDGES = {"approx", "approximately", "roughly", "exactly", "just", "shortly", "circa", "ca", "~"}


def _said_as_the_time(tokens: list[Token], i: int) -> bool:
    """'At 14:20 the AV...', 'TimeOfDay 23:00' say when the scene happens; a log entry's stamp ('Takeover #3 —
    14:02, Elm & 5th', '14:30 run 9:') dates the record and says nothing of the light."""
    j = i - 1
    while j >= 0 and tokens[j].word in TIME_HEDGES - {"approximately"}:
        j -= 1
    return j >= 0 and tokens[j].word in TIME_INTRODUCERS


def _hour_time(hour: int, said: str) -> tuple[str, str] | None:
    for time, hours in (("night", range(21, 29)), ("dawn", range(5, 8)), ("noon", range(11, 17)),
                        ("sunset", range(17, 21))):
        if hour in hours or hour + 24 in hours:
            return time, said
    return None


FALLING = ("hard_rain", "mid_rain", "soft_rain", "snow", "fog")


def _one_condition(conditions: list[tuple[str, str]], notes: list[str]) -> str:
    """One condition from many words: rain, snow or fog over wet or cloudy; wet and cloudy make wet_cloudy."""
    words = [c for c, _ in conditions]
    if not words:
        return V.DEFAULT_CONDITION
    falling = [(c, said) for c, said in conditions if c in FALLING]
    if falling:
        rain = [c for c, _ in falling if c.endswith("rain")]
        first = falling[0][0]
        if first.endswith("rain") and len(set(rain)) > 1:
            first = next(c for c in ("hard_rain", "soft_rain", "mid_rain") if c in rain)
        for c, said in falling:
            if c != first and not (c.endswith("rain") and first.endswith("rain")):
                notes.append(f"left out: '{said}' (the scene has one weather condition: {first})")
        return first
    if "wet_cloudy" in words or ("wet" in words and "cloudy" in words):
        return "wet_cloudy"
    for c in ("wet", "cloudy", "clear"):
        if c in words:
            return c
    return words[0]


ASKING = {"scene", "scenario", "situation", "simulation", "case", "test"}
ASKING_LINKS = {"for", "of", "with", "about", "involving", "showing", "featuring", "depicting", "having", "on",
                "where", "containing", "that", "has", "is", "a", "an", "the", "some", "shows", "covering"}


def _asked_kind(tokens: list[Token]) -> tuple[str, range] | None:
    """The scene kind when the prompt asks for one as the whole scene: 'create a scene for daily traffic',
    'a daily traffic scene', 'daily traffic'. A passing word ('at an intersection', 'in fog') is not asked."""
    kinds = lexicon().kinds
    words = [t.base for t in tokens]
    content = [i for i, t in enumerate(tokens) if t.word != "," and (t.word not in lexicon().function_words
                                                                    or t.word in ASKING)]

    def kind_at(i: int):
        for n in range(6, 0, -1):
            key = tuple(words[i:i + n])
            raw = tuple(t.word for t in tokens[i:i + n])
            if len(key) == n and (key in kinds or raw in kinds):
                return kinds.get(raw) or kinds[key], n
        return None

    def nothing_after(end: int) -> bool:  # "... daily traffic at dusk": only weather or road words may follow
        for t in tokens[end:]:
            if t.sentence != tokens[end - 1].sentence:
                break
            entry = lexicon().phrases.get((t.base,)) or lexicon().phrases.get((t.word,))
            if entry and entry[0] in ("agents", "actions") and entry[1] != "none":
                return False
        return True

    for i, t in enumerate(tokens):
        if t.word in ASKING:
            j = i + 1
            while j < len(tokens) and tokens[j].word in ASKING_LINKS:
                j += 1
            if j > i + 1 and (found := kind_at(j)) and nothing_after(j + found[1]):
                return found[0], range(i, j + found[1])
            if i > 0:
                for k in range(max(0, i - 4), i):
                    found = kind_at(k)
                    if found and k + found[1] == i and nothing_after(i + 1):
                        return found[0], range(k, i + 1)
    if content:
        first = content[0]
        found = kind_at(first)
        if found and first + found[1] > content[-1]:
            return found[0], range(first, first + found[1])
    return None


# -- stages and clauses -------------------------------------------------------------------------------------

@dataclass
class Clause:
    units: list[Unit]
    stage: int
    condition: bool = False  # "once the light turns green": sets no action of its own
    antecedent: Entity | None = None  # a relative clause's noun
    link: str = ""  # the word that opened it (and, while, which...)
    after_subordinate: bool = False  # follows an 'if' / 'when' clause: its subject is its own
    background: bool = False  # a relative on a noun whose own verb follows it: what the noun was, not what it does


def _main_clause_before_its_opening_participle(clauses: list[Clause]) -> list[Clause]:
    """'Coming from a side road on the right, a truck turns left', 'Having overtaken the ego, a van cuts in': a
    sentence's opening participle is said of the subject of the clause after its comma, so that clause is read first
    and the participle after it, joined by the comma, as said of the same subject."""
    out = list(clauses)
    for k in range(len(out) - 1):
        opening, main = out[k], out[k + 1]
        if opening.link or opening.condition or main.link != "," or main.condition or opening.stage != main.stage \
                or not opening.units or not main.units:
            continue
        sentence = opening.units[0].tokens[0].sentence
        if k > 0 and out[k - 1].units and out[k - 1].units[-1].tokens[0].sentence == sentence or \
                main.units[0].tokens[0].sentence != sentence:
            continue  # the sentence's first clause only
        verb = 1 if opening.units[0].word == "having" else 0
        participle = opening.units[verb] if verb < len(opening.units) else None
        placing = participle is not None and participle.category == "positions" and \
            participle.word in TRANSITIVE_POSITIONS  # "Following the ego closely, a motorcycle changes lane"
        if not placing and (participle is None or participle.category != "actions" or not (
                participle.tokens[0].word.endswith("ing") or verb or participle.meaning == "stop" or
                verb + 1 < len(opening.units) and opening.units[verb + 1].word == "by")):
            continue  # "Parked in the right lane", "Overtaken by a van": a participle ("Moved out into the right
            # lane", a note's verb with its subject left out, is none)
        subject = next((i for i, u in enumerate(main.units) if u.category == "agents"), None)
        main_verb = next((i for i, u in enumerate(main.units) if u.category == "actions" and subject is not None
                          and i > subject), None)
        if subject is None or subject > 2 or main.units[subject].meaning == "none" or main_verb is None or \
                any(u.category != "word" or u.word not in DETERMINERS for u in main.units[:subject]) or \
                any(u.word in COPULAS for u in main.units[subject + 1:main_verb]) or \
                participle.meaning == "stop" and _told_in_the_past(main.units[main_verb]):
            continue  # ("Going straight over the lights, a lorry is parked on the far side": a state the one
            # driving sees, said as the scene before it; "stopped at the stop sign, a cyclist came blowing thru":
            # an account in the past, whose stop is its teller's as often as not)
        main.link, opening.link = "", ","
        out[k], out[k + 1] = main, opening
    return out


def _told_in_the_past(verb: Unit) -> bool:
    t = verb.tokens[0]
    return t.word != t.base and not t.word.endswith(("s", "ing"))  # "came", "turned" (not "turns", "turning")


def _listed_before_then(current: list[Unit], units: list[Unit], k: int) -> bool:
    """'it waited for 2 oncoming cars and a motorcycle then went': the last of the things waited for, not the
    subject of what follows 'then' (which is the waiter's)."""
    if not current or current[-1].category != "agents" or not any(
            x.category == "actions" and x.meaning == "stop" for x in current):
        return False
    j = k + 1
    while j < len(units) and (units[j].word in ("a", "an", "the", "another") or units[j].category in (
            "numbers", "number", "positions", "behaviours")):
        j += 1
    return j + 1 < len(units) and units[j].category == "agents" and units[j + 1].word == "then" and \
        units[j + 1].tokens[0].sentence == units[k].tokens[0].sentence


def _another_lane_has(current: list[Unit], units: list[Unit], k: int) -> bool:
    """'Left lane has one bus, right lane has one truck': a lane said to have someone opens a clause of its own
    after one that said the same of another lane."""
    j = k + 1 + (k + 1 < len(units) and units[k + 1].word == "the")
    return j + 1 < len(units) and units[j].category == "positions" and units[j].meaning in ("side_left", "side_right") \
        and units[j + 1].word in ("has", "have", "had") and any(x.word in ("has", "have", "had") for x in current)


def _clauses(r: _Reader, skip: set[int]) -> list[Clause]:
    in_case_name: set[int] = set()  # "car-to-pedestrian farside adult": a test case's name, up to the next comma
    naming = False
    for k, u in enumerate(r.units):
        if u.category == "agents" and u.meaning == "none" and u.tokens[0].word in ("car", "vehicle") and \
                len(u.tokens) > 2 and u.tokens[1].word == "to":
            naming = True
        elif naming and (u.category == "comma" or u.tokens[0].sentence != r.units[k - 1].tokens[0].sentence):
            naming = False
        if naming:
            in_case_name.add(k)
    units = [_as_nobody(u) if _hypothetical(r.tokens, u) else u for k, u in enumerate(r.units)
             if u.start not in skip and (not _hypothetical(r.tokens, u) or _nobody_doing(r.tokens, u))
             and not u.tokens[0].title and k not in in_case_name]
    if in_case_name and not any(u.category == "agents" and u.meaning != "none" for u in units):
        units = [u for u in r.units if u.start not in skip and not _hypothetical(r.tokens, u)
                 and not u.tokens[0].title]  # the case's name is all the prompt says of its agents: read it
    if not any(u.category == "agents" and u.meaning != "none" for u in units) and any(
            u.category == "agents" and _in_general(r.tokens, u) for u in r.units):
        units = [u for k, u in enumerate(r.units) if u.start not in skip and (
            not _hypothetical(r.tokens, u) or u.category == "agents" and _in_general(r.tokens, u)) and
                 not u.tokens[0].title and k not in in_case_name]
        r.typical = True  # "Drivers turning left regularly cut across cyclists going straight on": a kind of road
        # user is all the text names; what it does habitually is the scene, one of each kind
    out: list[Clause] = []
    stage, current, condition, link = 0, [], False, ""
    sentence = units[0].tokens[0].sentence if units else 0

    def close(next_link: str = "", next_condition: bool = False):
        nonlocal current, condition, link
        if current:
            this = current[0].tokens[0].sentence
            opened = [c for c in out if c.units[0].tokens[0].sentence == this]  # "If ... and a car ..., brake"
            subordinate = bool(opened) and opened[0].link in SUBORDINATE and link == "," and \
                not any(c.link == "," for c in opened[1:])
            out.append(Clause(current, stage, condition, link=link, after_subordinate=subordinate))
        current, condition, link = [], next_condition, next_link

    skip_next = False
    for k, u in enumerate(units):
        if skip_next:
            skip_next = False
            r.mark(u)
            continue
        nxt = units[k + 1] if k + 1 < len(units) else None
        new_sentence = u.tokens[0].sentence != sentence
        sentence = u.tokens[0].sentence
        if new_sentence:
            close()
        prev_word = units[k - 1].tokens[-1].word if k and not new_sentence else ""
        # (the word right before, in this sentence: "stopped at the crossing. Once ..." is no "at once")
        verb_ended = current and (current[-1].category == "actions" or len(current) >= 2 and current[-1].word in (
            "by", "past", "through", "clear", "away", "off") and current[-2].category == "actions")
        state_ended = len(current) >= 2 and current[-1].word in ("clear", "past", "across", "over", "through") and \
            current[-2].word in COPULAS | {"got", "get", "gets"} and u.tokens[0].word in ("i", "we")
        # ("once he was clear I made the turn", "once they got across I went"; not "once it is past the ego")
        if condition and (verb_ended or state_ended) and u.category == "agents" and \
                u.meaning == "ego" and (u.tokens[0].word in ("i", "we") or [t.word for t in u.tokens][-1:] == ["ego"]):
            close()  # "once they passed i took over and made the left", "once it had gone by I made my turn": the
            # condition ends where its comma would
        if _a_relative_with_its_pronoun_left_out(current, units, k):
            close(next_link="that")  # "the car I was following braked": "the car (that) I was following"
            current.append(u)
            continue
        if link in SUBORDINATE_LINKS and _its_comma_left_out(current, units, k):
            close()  # "As I went forward a car came out of the junction", "When I stopped a van hit me": the
            # subordinate clause ends where its comma would
        if u.category == "sequence" and (prev_word == "even" or _next_names_which(u, prev_word, nxt) or
                                         u.word == "later" and prev_word in ("bit", "little", "or", "maybe")):
            r.mark(u)
            continue  # "stop, even when it's clear": a concession; "the next bit was ...": which bit; "around 6pm,
            # maybe a bit later": when, roughly; no stage
        if u.category == "sequence" and nxt is not None and nxt.category == "weather" and \
                nxt.meaning.startswith("time:") and u.tokens[-1].word in ("after", "before"):
            r.mark(u)
            continue  # "shortly after sunrise", "just before dusk": the time of day, no later stage
        if u.category == "sequence" and u.word == "after" and prev_word in AFTER_OF_A_VERB:
            r.mark(u)
            continue  # "you asked after my driving", "she looks after the kids": no time, a verb's own word
        if u.category == "sequence" and prev_word in RELATIVES and units[k - 1].category == "word":
            r.mark(u)
            continue  # "a motorcyclist who then overtakes it": the same clause, in order
        if u.category == "sequence" and [t.word for t in u.tokens][-1:] == ["after"] and _has_verb(current) and \
                ([t.word for t in u.tokens][:-1] or [prev_word])[0] in ("shortly", "soon", "just", "right") and \
                (nxt is None or nxt.word == "and" or nxt.category == "comma" or
                 nxt.tokens[0].sentence != u.tokens[0].sentence):
            r.mark(u)
            continue  # "a car arrives from the left shortly after and waits": when it comes, said of its clause
        if u.category == "sequence" and u.word == "after" and prev_word in ("one", "each") and nxt is not None and \
                nxt.word in ("another", "the", "other"):
            r.mark(u)
            continue  # "three cars swerve in, one after another": their order, not a later stage
        if u.category == "sequence" and u.base in ("after", "before") and nxt is not None and (
                nxt.tokens[0].word.endswith("ing") or nxt.category == "actions"):  # the preposition alone: "after
            # that turns right" is a later stage
            if nxt.category == "actions" and not nxt.tokens[0].word.endswith("ing"):
                skip_next = True  # "after overtake it comes in": when, and no predicate of its own
            continue  # "after braking for a fox": when, not a stage
        if u.category == "sequence" and u.word == "after" and _has_verb(current) and \
                not (nxt is not None and nxt.category == "number") and (
                    _no_verb_to_the_sentence_end(units, k + 1) or _a_manoeuvre_named_after(units, k)):
            r.mark(u)
            continue  # "two cars stopped ahead after a minor collision", "parked just after the junction": when
            # or where that was, said after it; what comes next is no later stage
        if u.category == "sequence" and u.meaning == "then" and u.word == "then" and (
                _has_agent(current) or _only_a_pronoun(current)) and \
                not any(x.category == "actions" and not x.tokens[0].word.endswith("ing") for x in current) and \
                not any(x.category == "comma" for x in current) and \
                nxt is not None and nxt.category == "actions" and \
                not (link in RELATIVES and _main_verb_after_a_relative(current, units, k + 1)):
            r.mark(u)
            stage += 1  # "the taxi then sped past": its subject opens the later stage's clause; so does "a
            # motorcyclist coming along the main road from our right then turned left": a subject and its participle
            continue
        if u.category == "sequence" and u.word == "then" and _then_of_a_verdict(units, k):
            r.mark(u)
            continue  # "then honestly that's fine, the car just holds its line": in that case, not later
        if u.category == "sequence" and not (u.base == "after" and nxt is not None and
                                             nxt.category in ("number", "numbers") and
                                             not _a_wait_of_minutes(units, k)) and not (
                u.base == "after" and nxt is not None and nxt.base in ("the start", "start", "the beginning")) \
                and prev_word not in ("for", "at", "all") and not _next_names_which(u, prev_word, nxt):
            # ("for once", "at once")
            r.mark(u)
            had_verb = _has_verb(current)
            noun_acts = link in RELATIVES and nxt is not None and _main_verb_after_a_relative(current, units, k + 1)
            # "a van that I had passed then overtook me": the van overtook, not the one who had passed it
            if out or current:
                close()
                stage += 1
            changed = u.meaning == "once" and u.tokens[-1].base in ("change", "turn", "flip", "switch") and \
                len(u.tokens) > 2 and not (nxt is not None and nxt.tokens[0].sentence == u.tokens[0].sentence and (
                    nxt.word in SIGNAL_COLOURS | {"to", "into"} or nxt.category == "road"))
            whole = u.tokens[-1].word in SIGNAL_COLOURS | {"clear", "safe", "so", "gap", "appears"} or changed
            # "when the light goes green", "when it is safe", "when the lights changed I moved off": said in full
            joined_on = (prev_word in ("and", ",", "but") or u.tokens[0].word == "and" or u.word == "then" and
                         nxt is not None and nxt.category == "actions" and had_verb and not noun_acts) and \
                not new_sentence and not _starts_subject(units, k + 1)  # "indicates right and then turns"; "a
            # van parked on the left then pulled out": the same subject goes on
            state = u.meaning == "once" and nxt is not None and nxt.category == "word" and \
                nxt.word in CONDITION_STATES  # "once clear it makes the turn": the condition is that one word
            if state:
                skip_next = True
            close(next_link="and" if joined_on else "", next_condition=u.meaning == "once" and not whole
                  and not state and not (u.word == "after" and _a_wait_of_minutes(units, k)))
            continue
        if u.category == "word" and u.word == "when" and nxt is not None and (_reaching(units, k + 1) or
                                                                             _completed(units, k + 1)):
            r.mark(u)
            close()
            stage += 1
            condition = True
            continue
        if u.category == "comma" and _placed_by_the_ego_next(current, units, k):
            current.append(u)  # "V2 (Suzuki m/cycle), following V1,": where the one just named is, no new subject
            continue
        if u.category == "comma" and _a_place_said_after(out, current, link):
            out[-1].units.extend(current)  # "one car stopped at the light, on my left, and the ambulance went
            current, link = [], ","  # round it": where the car was, not where the ambulance went
            continue
        if u.category == "comma":
            only_ego = all(x.category == "agents" and (x.meaning == "ego" or x.tokens[-1].label)
                           or x.category == "word" and x.word == "the" for x in current) or \
                _ego_then_what_it_is(current, units, k)  # appositions follow
            labelled = bool(current) and current[-1].category == "agents" and (
                bool(current[-1].tokens[-1].label) or current[-1].base.split()[-1] in APPOSED_HEADS) and \
                not _has_verb(current)  # "... that vehicle 1, the AV, was stopped", "VRU, a cyclist,": apposition
            tail = list(current)  # "the vehicle ahead of me, a red pickup, braked": what the vehicle is
            while tail and (tail[-1].category == "agents" and tail[-1].meaning == "ego" or tail[-1].word in (
                    "of", "the")):
                tail.pop()
            closed = next((x.category == "comma" for x in units[k + 1:k + 8] if x.category in ("comma", "actions")
                           or x.word in ("and", "or")), False)
            while len(tail) >= 3 and tail[-1].category == "positions" and tail[-2].word in (
                    "my", "our", "your", "the") and tail[-3].word in ("on", "in", "to"):
                del tail[-3:-1]  # "the vehicle on my left, a red minivan,": placed as "the vehicle left"
            labelled = labelled or len(tail) >= 2 and tail[-1].category == "positions" and \
                tail[-2].category == "agents" and tail[-2].base.split()[-1] in APPOSED_HEADS | {"car"} and \
                not _has_verb(current) and nxt is not None and nxt.word in ("a", "an") and closed
            ego_make = bool(current) and current[-1].category == "agents" and current[-1].meaning == "ego" and \
                len(current[-1].tokens) > 1 and nxt is not None and (
                    nxt.word in ("a", "an") or nxt.word in COLOURS | {"white", "black", "dark"}) and closed
            # "I was driving my vehicle, a grey Astra, west": what the ego is, not another car
            new_noun = _has_agent(current) and not only_ego and not labelled and _starts_noun(units, k + 1)
            new_noun = new_noun or _has_agent(current) and nxt is not None and nxt.word in (
                "he", "she", "they", "there") and k + 2 < len(units) and units[k + 2].word in COPULAS | {"be"}
            # "I'm in lane 1, he's in lane 2 and starts drifting": a new subject
            joined = nxt is not None and nxt.category == "word" and _has_agent(current) and nxt.word in (
                "and", "but", "while", "whilst", "so", "where", "which", "who")
            order = nxt is not None and _bare_verb(nxt) and _has_agent(current) and not any(
                x.word in ("a", "an", "the", "this", "that") or x.category == "comma" for x in current) and \
                nxt.tokens[0].word not in SAME_IN_THE_PAST  # "bus ahead, overtake it"; not "a guy ..., cut in", nor
            # "two cars, one on each side, brake": the verb of a subject set off by an apposition
            short_name = bool(current) and current[-1].category == "agents" and nxt is not None and \
                nxt.category == "agents" and len(nxt.tokens) == 1 and k + 2 < len(units) and \
                units[k + 2].category == "comma" and not nxt.tokens[0].plural  # "a target (GVT), ..."
            ego_named = bool(current) and current[-1].category == "agents" and current[-1].meaning != "ego" and \
                any(x.category == "agents" and x.meaning == "ego" for x in units[k + 1:k + 3]) and \
                all(x.category == "agents" or x.word in ("the", "a", "an") for x in units[k + 1:k + 3]) and \
                (k + 3 >= len(units) or units[k + 2].category == "comma" or units[k + 3].category == "comma")
            # "across the path of Unit 1, the AV, which ...": the unit is named the ego
            role_named = bool(current) and current[-1].category == "agents" and \
                current[-1].meaning not in ("ego", "none") and k + 3 < len(units) and units[k + 1].word == "the" and \
                units[k + 2].category == "agents" and units[k + 2].base in ROLE_NAMES and \
                units[k + 3].category == "comma"  # "a truck, the lead vehicle, brakes": the role it plays
            bracketed = len(current) >= 3 and current[-1].category == "agents" and len(current[-1].tokens) == 1 \
                and current[-1].base in ROLE_NAMES and current[-2].category == "comma" and \
                current[-3].category == "agents" and not joined  # "a principal other vehicle (POV) stationary"
            relative_ends = link in RELATIVES and nxt is not None and nxt.category == "actions" and \
                _has_agent(current)  # "a man, whom I know to be its driver, walked out": the man's verb
            the_one = _the_one_after(current, units, k + 1)  # "a bus, the one that was stopped, moves off"
            if _a_list_sharing_a_plural_verb(current, units, k):
                current.append(u)  # "two cars, a motorbike are coming": one subject, listed with a comma
                continue
            placed_aside = any(x.category == "positions" for x in current) and nxt is not None and \
                nxt.word == "and" and k + 3 < len(units) and units[k + 2].word in ("a", "an") and \
                units[k + 3].category == "agents"  # "..., level with it, and a hatchback follows"
            if (_has_verb(current) or condition or new_noun or joined or order or relative_ends or the_one or
                    placed_aside or _another_lane_has(current, units, k)) \
                    and not short_name \
                    and not ego_named and not role_named \
                    and not bracketed and not ego_make and not _closed_apposition(current, units, k) \
                    and not _what_a_label_is(current, units, k):  # "followed by CV, a Jeep Wrangler."
                close(",")
            else:
                current.append(u)  # "the ego, a city bus, is driven": the commas of an apposition
            continue
        if condition and _main_clause_after_condition(current, units, k):
            close()  # "once you were past the lorry you moved back": the condition ends where its main clause starts
        elif (condition or link in SUBORDINATE_LINKS) and u.category == "word" and u.word in ("a", "an") and \
                _has_agent(current) and _has_verb(current) and current[-1].category in ("road", "positions", "agents") \
                and current[-1].tokens[-1].word not in OBJECT_AWAITED and _subject_and_verb_follow(units, k):
            close()  # "as I go through the intersection a bus comes in from the north and turns right": the
            # subordinate clause said in full, then the main one's new subject and its verb
        if current and current[0].category == "actions" and current[0].tokens[0].word.endswith("ing") and \
                not _has_agent(current) and _subject_and_verb_follow(units, k):
            close(",")  # "coming home last night a cop car pulled out": the narrator's opening participle with no
            # comma after it, then a clause with its own subject
        if u.category == "word" and u.word == "but" and prev_word in ("option", "choice", "alternative"):
            current.append(u)  # "no option but to stop": one idiom, the verb is the one left without a choice's
            continue
        if u.category == "word" and u.word in CLAUSE_WORDS:
            pronoun_acts = nxt is not None and nxt.word in ("he", "she", "they", "i", "we") and \
                k + 2 < len(units) and units[k + 2].category == "actions"  # "an ambulance came up behind him and he
            # moved across": a new subject with its verb, though the place before swallowed the first verb
            member_acts = nxt is not None and nxt.word in ("one", "both", "each") and k + 3 < len(units) and \
                units[k + 2].word == "of" and units[k + 3].word in ("them", "those", "these") and \
                any(x.category == "agents" and x.tokens[-1].plural for x in current)
            # "two kids on the footpath and one of them darts out": one of the group just named, with its own verb
            joined = not _has_verb(current) and not _new_subject_after_copula(current, units, k) and \
                not _holds_the_green(current) and not pronoun_acts and not _another_lane_has(current, units, k) and \
                not member_acts
            if u.word in ("and", "or") and (joined or _listed_before_then(current, units, k)) or \
                    u.word == "and" and _between_one_and(current):
                current.append(u)
                continue
            if u.word == "that" and not (current and current[-1].category in ("agents", "positions", "behaviours")) \
                    or u.word == "that" and current and current[-1].category == "positions" and nxt is not None and \
                    nxt.category == "agents" and nxt.meaning != "ego":  # "stopped behind that car": which car
                current.append(u)
                continue
            if u.word == "as" and (nxt is not None and nxt.category == "word" and nxt.word in ("well", "soon", "if")
                                   or prev_word in ("employed", "work", "works", "working")  # "employed as a"
                                   or _in_the_role_of(units, k)
                                   or any(x.word == "same" for x in current[-3:])):  # "in the same direction as"
                # the ego": a likeness, no clause
                current.append(u)
                continue
            close(u.word)
            continue
        if link in RELATIVES and _main_verb_after_a_relative(current, units, k):
            close(",")  # "a lorry that I had been following for miles turned left": the lorry turned
        elif _a_contact_relative(current, units, k):
            close()  # "a man was on the crosswalk I was turning across": what the speaker did, of its own
        current.append(u)
        if condition and _ends_its_condition(units, k):
            close()  # "after the cyclist has passed ego turns right"
            continue
        if condition and u.category == "word" and u.word in SIGNAL_COLOURS and len(current) >= 2 and \
                current[-2].category == "actions" and _signal_change(current, len(current) - 2):
            close()  # "once it turns green we turn left": the condition ends at its colour
    close()
    told = min((c.stage for c in out if _has_agent(c.units) or any(
        u.category == "actions" and u.meaning not in ("try", "relate", "reach") for u in c.units)), default=0)
    for c in out:  # "S5 was suggested ... after a near miss she observed. The ego vehicle travels ...": a later
        c.stage = max(0, c.stage - told)  # stage opened before anyone of the scene is named opens nothing
    return out


def _between_one_and(current: list[Unit]) -> bool:
    """'the motorcycle that is between the ego and the police car changes lane': the 'and' of 'between' joins the
    two it is between, and opens no clause."""
    at = len(current) - 1
    if at < 0 or current[at].category != "agents":
        return False
    at -= 1
    while at >= 0 and current[at].category == "word" and current[at].word in DETERMINERS:
        at -= 1
    return at >= 0 and current[at].word == "between"


AFTER_OF_A_VERB = {"ask", "asks", "asked", "asking", "look", "looks", "looked", "looking", "named", "take", "takes",
                   "took", "taking", "inquire", "inquired", "enquire", "enquired"}


def _the_one_after(current: list[Unit], units: list[Unit], k: int) -> bool:
    """', the one that was stopped at the kerb,' after a noun: that noun again, said which one it is."""
    return bool(current) and current[-1].category == "agents" and current[-1].meaning not in ("ego", "none") and \
        k + 2 < len(units) and units[k].word == "the" and units[k + 1].word == "one" and \
        units[k + 2].word in RELATIVES | {"with", "on", "in", "at", "parked", "stopped", "waiting"}


RELATIVE_SUBJECTS = {"i", "we", "you", "he", "she", "they"}


def _a_contact_relative(current: list[Unit], units: list[Unit], k: int) -> bool:
    """'A man was on the crosswalk I was turning across': after a clause with its subject and verb, a place
    followed by the speaker and a verb opens a relative with no 'that', whose verb is the speaker's alone ('behind
    the bus I saw a cyclist': a place said first, no verb before it)."""
    u = units[k]
    if not (u.category == "agents" and u.meaning == "ego" and [t.word for t in u.tokens] in (["i"], ["we"])) or \
            not current or current[-1].category != "positions" or \
            current[-1].tokens[-1].sentence != u.tokens[0].sentence or not _has_agent(current[:-1]) or \
            not any(x.category == "actions" or x.word in COPULAS for x in current[:-1]):
        return False
    verb = k + 1
    while verb < len(units) and units[verb].category == "word" and units[verb].word in AUXILIARIES | {"just"}:
        verb += 1
    return verb < len(units) and units[verb].category == "actions"


def _main_verb_after_a_relative(current: list[Unit], units: list[Unit], k: int) -> bool:
    """'that I was following', 'which we had passed': a relative with its own subject and verb ends where a second
    finite verb comes, which is its noun's ('a lorry that I had been following turned left')."""
    u = units[k]
    first = 1 if current and current[0].word == "the" else 0  # "a truck that the ego is following brakes"
    if u.word in ("had", "has") and [x.word for x in units[k + 1:k + 2]] == ["to"] and k + 2 < len(units) and \
            units[k + 2].category == "actions" and len(current) >= first + 2 and \
            current[-1].category in ("actions", "positions") and current[first].category == "agents" and (
                current[first].tokens[0].word in RELATIVE_SUBJECTS or current[first].meaning == "ego"):
        return True  # "the car I was following had to stop dead": the noun's own verb, said with "had to"
    if u.category != "actions" or len(current) < first + 2 or current[first].category != "agents" or not (
            current[first].tokens[0].word in RELATIVE_SUBJECTS or current[first].meaning == "ego"):
        return False
    t = u.tokens[0]
    if t.word == t.base or t.word.endswith("ing") or current[-1].word in AUXILIARIES | {"to", "had", "have", "has"} \
            or current[-1].category == "agents":
        return False  # "that I saw pull out", "that I was following": still the relative's; "in which the ego
        # waits with a van stopped beside it": the van's participle
    return any(x.category in ("actions", "positions") or x.word in AUXILIARIES | {"had", "have", "has"}
               for x in current[first + 1:])


def _what_a_label_is(current: list[Unit], units: list[Unit], k: int) -> bool:
    """', a Jeep Wrangler.' after a label ('CV', 'SV1', 'the target'): one noun with its article and no verb, up to
    the sentence's end or the next comma, says what the labelled one is, whatever came before the label."""
    last = current[-1] if current else None
    if last is None or last.category != "agents" or last.meaning in ("ego", "none") or not (
            last.tokens[-1].label or last.base.split()[-1] in APPOSED_HEADS) or k + 2 >= len(units) or \
            units[k + 1].word not in ("a", "an"):
        return False
    sentence = units[k].tokens[0].sentence
    rest = list(itertools.takewhile(lambda x: x.category != "comma" and x.tokens[0].sentence == sentence,
                                    units[k + 2:]))
    named = [j for j, x in enumerate(rest) if x.category == "agents"]  # "a Jeep Wrangler": a make and its model
    return bool(named) and named == list(range(named[0], len(rest))) and \
        not any(x.category in ("actions", "sequence", "positions") for x in rest)


def _closed_apposition(current: list[Unit], units: list[Unit], k: int) -> bool:
    """'A pedestrian, a child, crosses', 'three pedestrians (two adults and a child) cross': nouns of the first
    one's kind between two commas, as many as it counts, and then the verb or a place ('a van, a white Transit,
    behind us'), say what it is or who its members are; a list goes on with 'and' or another noun ('a car, a bus
    and a van')."""
    if not current or _has_verb(current) or current[-1].category != "agents" or current[-1].meaning in ("ego", "none"):
        return False
    group = current[-1]
    wanted = 1
    if group.tokens[-1].plural:
        number = next((x for x in reversed(current[:-1]) if x.category != "word" or x.word in lexicon().function_words),
                      None)
        wanted = _word_number(number.tokens[0]) if number is not None and number.category in ("numbers", "number") \
            else None
        if not wanted or wanted < 2:
            return False
    named, count, j = 0, None, k + 1
    while j < len(units):
        x = units[j]
        if named == wanted == 1 and x.category not in ("comma", "agents"):
            if x.category in ("actions", "sequence"):
                return False  # "a pedestrian (an elderly man with a stick) crosses": what he has, said on the way
        elif x.category == "agents":
            if x.meaning != group.meaning or count is None:
                return False
            named += count if x.tokens[-1].plural else 1
            count = None
        elif x.category in ("numbers", "number") or x.word in ("a", "an"):
            count = _word_number(x.tokens[0]) if x.word not in ("a", "an") else 1
        elif x.category == "comma" and count is None:
            return named == wanted and j + 1 < len(units) and _goes_on_with_its_verb_or_place(units[j + 1])
        elif not (x.word == "and" and count is None or x.category in ("word", "behaviours") and count is not None
                  and x.word not in lexicon().function_words):
            return False
        j += 1
    return False


def _closed_after(units: list[Unit], i: int) -> bool:
    """From the noun at i, a tail with no verb or other agent up to a comma, and the verb (or a place) right after
    it."""
    j = i + 1
    while j < len(units) and units[j].category not in ("comma", "actions", "agents", "sequence"):
        j += 1
    return j + 1 < len(units) and units[j].category == "comma" and _goes_on_with_its_verb_or_place(units[j + 1])


def _goes_on_with_its_verb_or_place(u: Unit) -> bool:
    """After an apposition's closing comma, what the noun does ('brakes', 'failed to stop') or where it is ('behind
    us'): the sentence goes on about the one named, no list goes on."""
    return u.category in ("actions", "positions") or u.category == "word" and u.word.endswith("ed")


def _placed_by_the_ego_next(current: list[Unit], units: list[Unit], k: int) -> bool:
    """'a van, a white Transit, behind us,', 'V2 (motorcycle), following V1.': after a noun phrase with no verb, a
    place said by the ego alone between commas (or up to the sentence's end) places that noun; the ego is only
    where it is from."""
    if not current or _has_verb(current) or current[-1].category != "agents" or current[-1].meaning == "ego" or \
            k + 1 >= len(units) or units[k + 1].category != "positions":
        return False
    sentence = units[k].tokens[0].sentence
    j = k + 1
    if not (EGO_WORDS | SPEAKERS) & {t.word for t in units[j].tokens[1:]}:  # "behind us" is one unit
        j += 1  # ("following V1" two)
        while j < len(units) and units[j].category == "word" and units[j].word in ("the", "my", "our", "of"):
            j += 1
        if j >= len(units) or units[j].category != "agents" or units[j].meaning != "ego":
            return False
    return j + 1 == len(units) or units[j + 1].category == "comma" or units[j + 1].tokens[0].sentence != sentence


def _a_place_said_after(out: list[Clause], current: list[Unit], link: str) -> bool:
    """', on my left,' between two commas after a clause with its subject and verb: an afterthought that places
    that clause's subject; it has no subject or verb of its own to lend to what follows."""
    if link != "," or not out or not current or current[0].word not in ("on", "in", "to", "at", "from"):
        return False
    if any(x.category in ("agents", "actions", "sequence") for x in current) or \
            not any(x.category == "positions" for x in current):
        return False
    before = out[-1]
    return before.units[-1].tokens[0].sentence == current[0].tokens[0].sentence and _has_agent(before.units) and \
        _has_verb(before.units)


VERDICT_SUBJECTS = {"that", "it", "this"}
VERDICT_COPULAS = {"is", "was", "would", "should", "will", "seems"}


LONG_WAITS = {"min", "mins", "minute", "minutes", "hour", "hours", "hr", "hrs"}


def _no_verb_to_the_sentence_end(units: list[Unit], k: int) -> bool:
    """Only a noun phrase from here to the end of the sentence ('after a minor collision between them.')."""
    sentence = units[k - 1].tokens[0].sentence
    rest = [u for u in units[k:] if u.tokens[0].sentence == sentence]
    return bool(rest) and not any(u.category in ("actions", "sequence") or u.word.endswith(("ed", "ing"))
                                  for u in rest)


def _a_manoeuvre_named_after(units: list[Unit], k: int) -> bool:
    """'asked for help after a hard brake on a boulevard, ...': 'after' and a manoeuvre named as a noun (an article,
    its adjectives, the noun) with no verb to the clause's end says when, not a later stage."""
    j = k + 1
    if j >= len(units) or units[j].word not in ("a", "an", "the", "its", "his", "her", "their", "my", "our"):
        return False
    j += 1
    while j < len(units) and units[j].category in ("behaviours", "word") and units[j].word not in (",", "and"):
        j += 1
    if j >= len(units) or units[j].category != "actions" or units[j].tokens[0].word.endswith(("ing", "ed", "s")):
        return False
    sentence = units[k].tokens[0].sentence
    for u in units[j + 1:]:
        if u.tokens[0].sentence != sentence or u.category == "comma" or u.word in ("and", "but"):
            return True
        if u.category in ("actions", "sequence") or u.category == "agents" and u.meaning != "none":
            return False
    return True


def _a_wait_of_minutes(units: list[Unit], k: int) -> bool:
    """'After ~2 min the operator changed lanes': a scene plays for seconds, so a wait of minutes is no trigger
    ('after 2s') but a later stage."""
    return units[k].word == "after" and any(t.word in LONG_WAITS for x in units[k + 1:k + 4] for t in x.tokens)


def _then_of_a_verdict(units: list[Unit], k: int) -> bool:
    """'Then that's fine', 'then honestly it is okay': 'then' as 'in that case', a verdict on what was said."""
    j = k + 1
    while j < len(units) and _sentence_adverb(units[j]):
        j += 1
    return j + 1 < len(units) and units[j].word in VERDICT_SUBJECTS and units[j + 1].word in VERDICT_COPULAS


CONDITION_STATES = {"clear", "safe", "free", "possible", "ready", "past", "through", "gone", "done"}
COPULAS = {"is", "are", "was", "were", "am"}
SUBJECT_PRONOUNS = {"we", "i", "it", "they", "he", "she", "you"}
PRO_VERBS = {"did", "does", "do", "had", "has", "have", "could", "would", "can", "will", "should"}


def _new_subject_after_copula(current: list[Unit], units: list[Unit], k: int) -> bool:
    """'a police car is behind us and we pull over': a complete 'X is PLACE', then a new subject and its verb."""
    rest = units[k + 1:k + 5]
    if not rest:
        return False
    agent_at = next((j for j, u in enumerate(current) if u.category == "agents" and u.meaning not in ("none", "ego")),
                    None)
    placed = agent_at is not None and any(u.category == "positions" for u in current[agent_at + 1:])
    if placed and rest[0].word in ("i", "we") and not any(u.word == "both" for u in rest) and any(
            x.category == "actions" for x in rest[1:3]):
        return True  # "an ambulance comes up behind me and I pull over"
    pro_verb = bool(current) and current[-1].category == "word" and current[-1].word in PRO_VERBS  # "a second
    # before you did and an SUV is stopped": the clause's verb said again by its auxiliary alone
    if not (_has_agent(current) and (pro_verb or any(u.category == "word" and u.word in COPULAS for u in current))):
        return False
    if rest[0].word == "there" and len(rest) > 1 and rest[1].word in COPULAS:
        return True  # "I was in the right lane and there was a police car stopped on the shoulder": its own clause
    if len(current) > 1 and current[0].word == "there" and current[1].word in COPULAS and all(
            x.category in ("agents", "numbers", "number", "behaviours") or x.category == "word" and
            x.word in DETERMINERS | INDEFINITE for x in current[2:]):
        return False  # "There was a mum and a toddler walking on the pavement": the two that there were
    starts = rest[0].category == "agents" and (rest[0].meaning == "ego" or bool(rest[0].tokens[-1].label)) or \
        rest[0].word in SUBJECT_PRONOUNS or (  # "V2 is eastbound and V3 is westbound": a named one's own clause
        (rest[0].word in ("the", "a", "an", "this", "that", "some", "another") or rest[0].category in (
            "number", "numbers")) and len(rest) > 1 and _starts_noun(units, k + 2)) or (
        rest[0].word == "another" and _stands_alone(units, k + 1))  # "... and another is behind",
    # "... and this guy swerves",
    # "... and a white SUV ... cut across", "when the ego is 15 m away and one car waits behind it"
    if not starts:
        return False
    for x in units[k + 2:k + 10]:
        if x.category == "actions" or x.word in COPULAS or x.word in AUXILIARIES - {"to", "and", "then", "also"}:
            return True  # "... is behind us and we pull over", "... and a car in the lane to our left merges",
            # "... was next to us and he couldn't get over"
        if x.category == "comma" or x.word in CLAUSE_WORDS:
            return False
    return False


def _main_clause_after_condition(current: list[Unit], units: list[Unit], k: int) -> bool:
    """A condition written without a comma ('once you were past it you pulled in'): a complete condition (a
    subject and its verb), then a subject pronoun and a verb start the clause the condition is for."""
    u = units[k]
    if current and all(x.word in SIGNAL_COLOURS | {"to"} for x in current) and \
            current[-1].word in SIGNAL_COLOURS and _subject_then_its_verb(units, k):
        return True  # "when the light flips to green the player turns left": the change said, then who acts
    ego = u.category == "agents" and u.meaning == "ego" or u.category == "word" and u.word == "the" and \
        k + 1 < len(units) and units[k + 1].category == "agents" and units[k + 1].meaning == "ego"
    if ego and len(current) >= 3 and current[-1].category in ("road", "agents", "positions") and \
            (_has_verb(current) or any(x.word in ("has", "have", "had") for x in current)) and \
            _subject_then_its_verb(units, k):
        return True  # "when the bus has cleared the junction the ego turns right": the condition said in full
        # (up to its object), then the ego and its verb
    pronoun = u.category == "agents" and u.meaning == "ego" and u.word in ("i", "we", "you") or \
        u.category == "word" and u.word in SUBJECT_PRONOUNS
    if not pronoun or len(current) < 2 or not (_has_verb(current) or any(
            x.word in COPULAS | {"got", "get", "gets"} or _past_tense_verb(x) for x in current)):
        return False  # ("once he had cleared we went", "once I got past the lorry I pulled in": a verb the lexicon
        # does not know is still the verb)
    if current[-1].category == "word" and current[-1].word in COPULAS | AUXILIARIES:
        return False  # "once it is you ...": the pronoun belongs to the condition
    return any(x.category == "actions" for x in units[k + 1:k + 3]) or \
        k + 1 < len(units) and _past_tense_verb(units[k + 1]) and \
        any(x.category == "actions" for x in units[k + 2:k + 4])  # "once he'd cleared we completed the turn"


OBLIGED = {"has", "have", "had", "needs", "need", "must", "to", "got", "gets", "then", "just", "will", "should"}


def _subject_then_its_verb(units: list[Unit], k: int) -> bool:
    """'the player turns left', 'the player has to swing left': a noun phrase, then its verb (after words of
    obligation or time at most)."""
    for j, u in enumerate(units[k:k + 4], start=k):
        if u.category == "agents":
            if u.meaning == "none":
                return False
            for x in units[j + 1:j + 4]:
                if x.category == "actions":
                    return x.tokens[0].sentence == u.tokens[0].sentence
                if not (x.category == "word" and x.word in OBLIGED):
                    return False
            return False
        if not (u.category == "word" and (u.word in DETERMINERS or u.word in SUBJECT_PRONOUNS)):
            return False
    return False


def _starts_subject(units: list[Unit], k: int) -> bool:
    """A clause starting here names its own subject ('then the truck turns', 'then we stop')."""
    for u in units[k:k + 4]:
        if u.category == "agents":
            return True
        if not (u.category in ("numbers", "number", "behaviours") or u.category == "word" and (
                u.word in DETERMINERS or u.word in SUBJECT_PRONOUNS)):
            return False
        if u.word in SUBJECT_PRONOUNS:
            return True
    return False


SUBORDINATE_LINKS = {"as", "while", "when", "whilst"}
OBJECT_AWAITED = {"of", "behind", "from", "past", "to", "into", "onto", "at", "in", "on", "by", "with", "towards",
                  "toward", "across", "around", "round", "between", "beside", "alongside", "near", "passing", "passed"}
# a place phrase that ends in one of these names its object next ("emerges from behind a van parked ...")


SPEAKERS_OWN = {"driving", "drove", "riding", "rode", "in", "on", "sat", "sitting", "own", "owned", "hired",
                "borrowed"}  # "the taxi (that) I was driving": the speaker's own, no other


def _a_relative_with_its_pronoun_left_out(current: list[Unit], units: list[Unit], k: int) -> bool:
    """'The car I was following braked hard', 'the lorry we were stuck behind': a noun said with 'the' and no verb
    yet, then 'I' or 'we' with a verb of their own, then the noun's own verb."""
    u = units[k]
    if u.category != "agents" or u.meaning != "ego" or u.word not in ("i", "we") or len(current) < 2 or \
            current[-1].category != "agents" or current[-1].meaning in ("ego", "none") or _has_verb(current) or \
            current[-2].word != "the":
        return False
    rest = [x for x in units[k + 1:k + 8] if x.tokens[0].sentence == u.tokens[0].sentence]
    verbs = [j for j, x in enumerate(rest) if x.category == "actions" or x.category == "positions" and
             x.meaning in ("behind", "ahead")]
    return len(verbs) >= 2 and (rest[0].word in ("was", "were", "had", "am", "'d") or rest[0].category == "actions") \
        and not any(t.word in SPEAKERS_OWN for x in rest[:verbs[0] + 1] for t in x.tokens)  # ("the taxi I was
    # driving": mine)


PARKED_STATES = {"park", "stop", "stall", "leave", "abandon", "break"}  # "passed a car parked ...": its state


def _its_comma_left_out(current: list[Unit], units: list[Unit], k: int) -> bool:
    """'[As] I went forward | a car came out': a clause with its subject and verb said, then a new indefinite
    subject with a finite verb of its own (not 'I saw a car pull out', 'as I passed a car parked on the left')."""
    arrived = any(x.word in ("got", "get", "gets", "arrived", "arrive") for x in current)  # "When I got to the
    # junction a lorry turned left": a verb the lexicon reads as no action
    if units[k].word not in ("a", "an") or not _has_agent(current) or not (_has_verb(current) or arrived) or \
            current[-1].word in OBJECT_AWAITED or not _subject_and_verb_follow(units, k):
        return False
    verbs = [x for x in current if x.category == "actions"]
    if any(t.base in PERCEIVING or t.base in ("let", "make", "help", "watch") for x in verbs for t in x.tokens):
        return False
    verb = next(x for x in units[k + 1:] if x.category == "actions").tokens[0]
    transitive_before = current[-1].category == "actions"  # "as I passed a car ...": its object, unless it acts
    return not verb.word.endswith("ing") and not (transitive_before and verb.base in PARKED_STATES)


def _subject_and_verb_follow(units: list[Unit], k: int) -> bool:
    """A new clause with no word to open it: 'ego turns right', 'the truck stops' (not 'the ego, it turns')."""
    for j, u in enumerate(units[k:k + 4], start=k):
        if u.category == "agents":
            return u.meaning != "none" and j + 1 < len(units) and units[j + 1].category == "actions" and \
                units[j + 1].tokens[0].sentence == u.tokens[0].sentence
        if not (u.category == "word" and u.word in DETERMINERS):
            return False
    return False


PLURAL_VERBS = {"are", "were", "have"}


def _a_list_sharing_a_plural_verb(current: list[Unit], units: list[Unit], k: int) -> bool:
    """'two cars, a motorbike are coming', 'the ego, a motorcycle on its left wait': a noun phrase, a comma and
    a singular noun phrase whose verb agrees only with both: a list without its 'and', no apposition, no clause."""
    if not _has_agent(current) or _has_verb(current) or any(x.category == "comma" for x in current) or \
            not _starts_noun(units, k + 1) or any(x.word in COPULAS for x in current) or \
            any(x.category == "positions" for x in current) and units[k + 1].word in ("the", "a", "an"):
        return False  # ("I was in the left lane, a bus cut in", "my car in the left lane, the truck he change lane":
        # a clause of its own before the comma, verbless or not; "vehicle behind me, white Ford Transit, failed to
        # stop" names one)
    head = next(j for j in range(k + 1, len(units)) if units[j].category == "agents")
    if units[head].tokens[-1].plural or units[head].meaning == "ego":
        return False
    for x in units[head + 1:head + 12]:
        if x.tokens[0].sentence != units[head].tokens[0].sentence or x.category == "agents" and \
                x.meaning not in ("none", "ego") or x.word in CLAUSE_WORDS:
            return False
        if x.category == "word" and x.word in COPULAS | AUXILIARIES - {"to", "and", "then", "also", "keeps"}:
            return x.word in PLURAL_VERBS
        if x.category == "actions":
            verb = x.tokens[0]
            return not x.tokens[0].word.endswith("ing") and verb.word == verb.base and not verb.word.endswith("s")
    return False


def _starts_noun(units: list[Unit], k: int) -> bool:
    """A noun phrase begins here: determiners, numbers and adjectives, then an agent noun."""
    for j, u in enumerate(units[k:k + 4]):
        if u.category == "agents":
            return u.meaning != "none"
        state = j > 0 and u.category == "actions" and len(u.tokens) == 1 and (
            u.tokens[0].word.endswith("ed") or u.tokens[0].word == "stationary") and \
            units[k + j - 1].word in DETERMINERS | {"a", "an", "one", "two", "three"}  # "a parked van": its state
        if not (state or u.category in ("numbers", "number", "behaviours") or u.word in COLOURS | {"dark", "light", "white",
                                                                                       "black"} or
                (u.category == "word" and u.word in DETERMINERS | {"and"}) or
                (u.category == "word" and u.word not in lexicon().function_words and u.word not in CLAUSE_WORDS)
                or (u.category == "positions" and u.word in ADJECTIVE_POSITIONS and len(u.tokens) == 1)):
            return False  # "..., delivery lorry stopped": an unknown word before a noun is its adjective
    return False


def _has_agent(units: list[Unit]) -> bool:
    return any(u.category == "agents" and u.meaning != "none" for u in units)


def _only_a_pronoun(units: list[Unit]) -> bool:
    """'it then changes lane', 'and he then cuts in', 'the red one then turns': a pronoun, or 'one' with its
    paint, as all the subject said before 'then'."""
    words = [u.word for u in units if u.word not in ("and", "but")]
    return len(words) == 1 and words[0] in ("it", "he", "she", "they") or \
        len(words) == 3 and words[0] == "the" and words[1] in PAINT and words[2] == "one"


QUESTION_WORDS = {"what", "how", "why", "where", "which", "who"}


COUNTED_BY = {"the", "these", "those", "a", "few", "several", "some", "many", "of", "two", "three", "four", "five"}
ANYONE = {"someone", "somebody", "anyone", "anybody", "people", "everyone", "everybody", "whoever", "folk", "folks"}


ASKING_MODALS = {"should", "do", "does", "would", "could", "am", "was", "did", "have", "must", "can", "shall",
                 "is", "are"}
DEONTIC = {"should", "must", "ought"}
ASKING_FOR_A_SCENE = {"scene", "scenario", "simulation", "simulate", "create", "generate", "make", "build", "set",
                      "spawn", "test", "case", "have", "get"}


def _asks_what_to_do(tokens: list[Token], sentence: int) -> bool:
    """'Should I have been able to stop?', 'Who should give way?', 'Do I have to wait?': a question about what
    ought to happen is no account of what did (a request for a scene is no such question)."""
    words = [t.word for t in _sentence(tokens, sentence)]
    if words[:1] == ["how"] and words[2:3] in (["i"], ["we"]) and any(
            t.word == "ego" and t.sentence < sentence for t in tokens):
        return True  # "... and a truck cuts into the ego's lane. How do I force that lane change?": how to build the
        # scene told before, by one who builds it
    if len(words) < 2 or set(words) & ASKING_FOR_A_SCENE - {"have"}:
        return False
    if (words[0] in QUESTION_WORDS or words[:2] == ["in", "which"]) and set(words) & DEONTIC:
        return True  # "Where should you stop?", "In which order should the cars proceed?": an exam's question
    if "you" in words[:3]:
        return False
    if any(w == "one" and nxt in ("where", "with", "in", "that", "when") for w, nxt in zip(words, words[1:])):
        return False  # "could we do one where the ego turns left?": a scene asked for
    return words[0] in ("who", "whose", "whom") or (words[0] in ASKING_MODALS and words[1] in ("i", "we")
                                                    and not (words[0] in ("can", "could", "may")
                                                             and {"get", "have"} & set(words[2:3])))


CASE_OPENERS = {"when", "if", "while", "whilst", "once", "as"}


def _in_the_questions_case(tokens: list[Token], t: Token) -> bool:
    """'What should the AV do when an oncoming motorcycle turns left?', 'If a car cuts in, what should the ego do?':
    the case the question is asked of is told as the scene; only the question itself is not."""
    asked = _sentence(tokens, t.sentence)
    if {x.word for x in asked[:3]} & {"i", "we", "you"}:
        return False  # "How do I stop the cyclist from teleporting when it waits too long?": a question of building
    opener = next((x for x in reversed(asked) if x.index < t.index and (x.word in CASE_OPENERS or x.word == ",")),
                  None)
    return opener is not None and opener.word in CASE_OPENERS


def _rule_of_the_road(tokens: list[Token], sentence: int) -> bool:
    """'Once someone's on a zebra, you stop and you wait': advice for anyone at any time, no event of the scene."""
    words = [x.word for x in _sentence(tokens, sentence)]
    if "you" in words and any(f.category == "agents" and _met_in_a_rule(
            _sentence(tokens, sentence), [x for x in tokens[:f.start] if x.sentence == sentence],
            [x for x in tokens[f.end:] if x.sentence == sentence]) for f in _matches_of(tokens, sentence)):
        return True  # "when you see a police car on the shoulder, change lanes": what anyone does then
    return any(w in ("once", "when", "whenever", "if") and words[k + 1] in ANYONE for k, w in enumerate(words[:-1])) \
        and "you" in words and not set(words) & _agent_nouns() - ANYONE - EGO_WORDS


def _matches_of(tokens: list[Token], sentence: int) -> list:
    inside = [x.index for x in _sentence(tokens, sentence)]
    return matches(tokens, inside[0], inside[-1] + 1) if inside else []


SIGN_WORDS = {"sign", "signs", "light", "lights", "line", "lines", "marking", "markings", "arrow", "signal", "red",
              "amber", "green", "yellow", "crossing"}  # "a solid white line means ...": what a sign tells everyone


def _standing_advice(tokens: list[Token], sentence: int) -> bool:
    """'Always look right and give way.', 'Never overtake there.', 'Next time wait.': advice for every drive, no
    event of this one."""
    words = [x.word for x in _sentence(tokens, sentence)]
    if words[:2] == ["next", "time"]:
        words = words[1:]  # "Next time wait."
    if words[:2] in (["it", "is"], ["it", "would"], ["it", "will"]) and words[2:4] != ["to", "be"]:
        words = words[2:] if words[2:3] != ["be"] else words[3:]  # "It's better to pull over"
    if words[:1] in (["better"], ["best"], ["safer"], ["wiser"]) and words[1:2] == ["to"] or any(
            w in ("means", "mean") and set(words[:k]) & SIGN_WORDS for k, w in enumerate(words[:8])):
        return True  # "Better to pull over to the left.", "A stop sign means wheels stopped, every time."
    return len(words) > 1 and words[0] in ("always", "never", "time") and words[1] not in ("the", "a", "an", "there") and \
        not set(words) & _agent_nouns() - ANYONE - EGO_WORDS


COUNTERFACTUAL_MODALS = {"would", "could", "should", "might", "must"}


POSSIBILITY_MODALS = {"might", "may"}


def _only_possible(units: list[Unit], i: int) -> bool:
    """'Kids walking on the pavement ... they might step out': what may happen is weaker than anything the agent is
    said to do, and counts only where nothing else is said of it ('a van that may be turning left')."""
    k = i - 1
    while k >= 0 and (units[k].word in (ADVERBS | AUXILIARIES | {"well"}) - POSSIBILITY_MODALS or
                      units[k].category == "behaviours"):  # "may well suddenly swerve"
        k -= 1
    return k >= 0 and units[k].category == "word" and units[k].word in POSSIBILITY_MODALS


def _counterfactual(tokens: list[Token], t: Token) -> bool:
    """'You'd have had to stop again if I hadn't': what would have happened, not what did."""
    for j in range(t.index - 1, max(-1, t.index - 6), -1):
        x = tokens[j]
        if x.sentence != t.sentence or x.word in (",", "and", "but", "so", "then"):
            return False
        if x.word == "have" and j > 0 and tokens[j - 1].word in COUNTERFACTUAL_MODALS and not tokens[j - 1].question:
            return True
        if x.word == "have" and j > 1 and [tokens[j - 2].word, tokens[j - 1].word] == ["ought", "to"]:
            return True  # "as though I ought to have pulled out"
    return False


HABITUAL = frozenset({"often", "usually", "always", "sometimes", "regularly", "normally", "generally", "typically",
                      "constantly", "frequently", "routinely", "never", "rarely", "seldom", "nowadays"})
HABITUAL_PHRASES = (("all", "the", "time"), ("every", "day"), ("every", "morning"), ("every", "evening"),
                    ("every", "time"), ("most", "days"), ("tend", "to"), ("around", "here"), ("round", "here"),
                    ("seem", "to"), ("these", "days"), ("in", "general"))  # "truckers around here seem to think"
LOCALITIES = (("down", "here"), ("up", "here"), ("out", "here"), ("in", "this", "town"), ("in", "this", "city"),
              ("in", "this", "country"), ("nowadays",))


def _bare_plural(tokens: list[Token], u: Unit) -> bool:
    """A plural noun with no determiner, owner or count before it ('buses', 'kids'): a kind, not some of it."""
    t = u.tokens[0]
    if not u.tokens[-1].plural:
        return False
    before = tokens[t.index - 1] if t.index > 0 and tokens[t.index - 1].sentence == t.sentence else None
    if before is not None and before.word == "of" and t.index > 1 and tokens[t.index - 2].word in VAGUE_MANY:
        return True  # "dozens of cyclists use the lane every day": as many as one likes, a kind
    return before is None or before.word not in SAID_OF_SOME and read_number(before.word) is None


VAGUE_MANY = {"dozens", "hundreds", "thousands", "scores", "lots", "loads", "plenty", "tons", "masses"}


def _in_general(tokens: list[Token], u: Unit) -> bool:
    """'Buses often use this road', 'Taxis do that all the time': a bare plural in a sentence of what happens
    habitually speaks of a kind, not of anyone in the scene."""
    t = u.tokens[0]
    if u.meaning == "ego":
        return False
    if u.tokens[-1].word in ("drivers", "motorists") and t.index and tokens[t.index - 1].word in ("the", "these") \
            and _says_any([x.word for x in tokens[t.index + 1:t.index + 4]], HABITUAL_PHRASES + LOCALITIES):
        return True  # "you would not believe the drivers down here": the town's drivers, a kind
    if not _bare_plural(tokens, u):
        return False
    if u.tokens[-1].word in ("drivers", "motorists"):
        return True  # "the head teacher's concern is drivers not slowing down": drivers in general
    after = [x for x in tokens[u.tokens[-1].index + 1:u.tokens[-1].index + 6] if x.sentence == t.sentence]
    told = after[:1] and after[0].word in ("should", "must", "may", "need", "ought", "might", "shall") or \
        [x.word for x in after[:1]] == ["who"] and after[1:] and after[1].word in ("wish", "want", "prefer")
    verb = next((x for x in after[1:] if x.word not in ("not", "also", "additionally", "carefully", "first", "be",
                                                         "to", "wish", "want", "prefer", "may", "should")), None)
    if told and verb is not None and (lexicon().phrases.get((verb.base,)) or ("",))[0] != "actions":
        return True  # "Students may choose ...", "students who wish to may consider": those told what they may
        # do, off the road (not "pedestrians should cross in front of the ego")
    words = [x.word for x in _sentence(tokens, t.sentence)]
    return bool(HABITUAL & set(words)) or _says_any(words, HABITUAL_PHRASES)


def _nobody_doing(tokens: list[Token], u: Unit) -> bool:
    """An agent said only in what did not happen or of a kind in general ('had a truck pulled out', 'buses often
    pull out here') is kept as a noun that names no agent: its verb is then nobody's, not the ego's."""
    return u.category == "agents" and u.meaning not in ("ego", "none") and (_what_if(tokens, u) or
                                                                           _in_general(tokens, u))


def _as_nobody(u: Unit) -> Unit:
    return Unit(u.start, u.end, "agents", "none", u.tokens)


def _what_if(tokens: list[Token], u: Unit) -> bool:
    """'If a cyclist had been there, I would have hit him', 'had a cyclist been there, ...': someone said to be
    there in what did not happen.
    A present 'if a pedestrian steps out, the ego brakes' is a test's condition and stays; 'if the cyclist had
    not braked' speaks of one who was there."""
    t = u.tokens[0]
    if t.index == 0 or tokens[t.index - 1].word not in ("a", "an", "another", "any"):
        return False
    sentence = _sentence(tokens, t.sentence)
    words = [x.word for x in sentence]
    would_have = any(w in COUNTERFACTUAL_MODALS and "have" in words[k + 1:k + 3] for k, w in enumerate(words))
    if sentence[0].word in ("had", "were") and t.index - 1 == sentence[1].index and would_have:
        return True  # "Had a cyclist been there, it would have been hit": the 'if' said by the order of words
    opened = next((x for x in reversed(sentence) if x.index < t.index and x.word in ("if", ",")), None)
    if opened is None or opened.word != "if":
        return False
    clause = [x.word for x in sentence if x.index > t.index and x.word != ","][:4]
    return would_have and bool({"had", "were"} & set(clause))


YES_NO_OPENINGS = {"does", "do", "did", "will", "would", "can", "could", "should", "is", "was", "are", "were"}


def _asks_whether(tokens: list[Token], t: Token) -> bool:
    """'Does the car stop in time?', 'Will he hit the boy?': a question of whether one named before does something
    asks the outcome; the scene does not tell it ('Can a car cut in here?' asks for one, and stays; so does what a
    new one does in it: 'Can the ego handle a bus that turns right?')."""
    words = [x.word for x in _sentence(tokens, t.sentence) if x.index < t.index]
    asked_how = len(words) > 3 and words[0] in ("what", "how") and any(  # "What deceleration does car A need to
        w in YES_NO_OPENINGS and words[k + 1:k + 2] and words[k + 1] not in ("you", "i", "we")  # stop", "How far
        for k, w in enumerate(words[1:], 1))  # short of the child does it stop?" (not "how do I stop")
    return len(words) > 2 and (words[0] in YES_NO_OPENINGS and words[1] in ("the", "he", "she", "they") or
                               asked_how) and not set(words) & (CASE_OPENERS | RELATIVES)


BELIEVING = {"thought", "believed", "assumed", "figured", "guessed", "presumed", "reckoned", "imagined", "expected"}


def _opened_in_its_clause(tokens: list[Token], t: Token, opens) -> bool:
    """opens(k) holds at one of the eight words before t in t's clause (no comma or conjunction between)."""
    k = t.index - 1
    while k > 0 and tokens[k].sentence == t.sentence and t.index - k <= 8:
        if tokens[k].word in (",", "but", "so", "and", "then", "because", "until", "when"):
            return False
        if opens(k):
            return True
        k -= 1
    return False


def _believed(tokens: list[Token], t: Token) -> bool:
    """A verb after 'I thought (that)' in the same clause: a belief of the narrator, not what happened."""
    return _opened_in_its_clause(tokens, t, lambda k: tokens[k].word in BELIEVING and tokens[k - 1].word in ("i", "we"))


DOUBTING = {"wondered", "wondering", "wonder", "unsure", "uncertain"}  # before 'if' or 'whether'
DOUBTED_AFTER_NOT = {"tell", "know", "sure", "certain", "clear", "see"}  # 'could not tell if', 'was not sure whether'


def _doubted(tokens: list[Token], t: Token) -> bool:
    """A verb after 'could not tell if', 'was not sure whether', 'wondered if' in the same clause: what the teller
    could not tell had happened, not what happened ('it couldn't tell if it was being pulled over')."""
    return _opened_in_its_clause(tokens, t, lambda k: k > 1 and tokens[k].word in ("if", "whether") and (
        tokens[k - 1].word in DOUBTING or tokens[k - 1].word in DOUBTED_AFTER_NOT and tokens[k - 2].word == "not"))


def _hypothetical(tokens: list[Token], u: Unit) -> bool:
    """A question such as 'What happens if a truck runs a red light?' names no agent of the scene; the
    sentences after it describe the scene. 'Can someone explain this?', 'Why are people like this': the
    readers of a forum post or people in general are nobody in the scene. Nor are kinds spoken of in general
    or someone in what did not happen (_in_general, _what_if)."""
    t = u.tokens[0]
    asked = _sentence(tokens, t.sentence)
    if t.question and len(asked) > 2 and asked[0].word == "who" and asked[1].word in ("was", "is", "were") and \
            asked[2].word == "the":
        return False  # "Who was the idiot on the motorbike weaving in and out of traffic last night?": asks who
        # someone in the scene was
    if u.category != "comma" and _set_aside(tokens, u):
        return True
    if _in_an_aside(tokens, u):
        return True
    if u.category == "agents" and (_in_general(tokens, u) or _what_if(tokens, u) or
                                   _only_talked_about(tokens, u)):
        return True
    first = _sentence(tokens, t.sentence)[0]
    before = tokens[t.index - 1] if t.index > 0 and tokens[t.index - 1].sentence == t.sentence else None
    counted = before is not None and (read_number(before.word) is not None or before.word in COUNTED_BY)
    if u.category == "agents" and len(u.tokens) == 1 and t.word in ANYONE and not counted and (
            t.question or first.word in QUESTION_WORDS):
        return True
    if t.question and _asks_what_to_do(tokens, t.sentence) and not _in_the_questions_case(tokens, t):
        return True
    after = [x.word for x in tokens[u.end:u.end + 3] if x.sentence == t.sentence]
    if u.category == "agents" and t.word in ANYONE and not counted and (
            after[:3] == ["is", "going", "to"] or after[:1] in (["will"], ["gonna"])):
        return True  # "somebody is going to get killed out there": a fear for the future, no one of the scene
    if u.category == "agents" and t.word in ANYONE and before is not None and \
            before.word in ("once", "when", "whenever", "if") and any(
                x.word == "you" for x in tokens[t.index + 1:] if x.sentence == t.sentence):
        return True  # "once someone's on a zebra, you stop": a rule of the road, anyone at any time
    if u.category == "actions" and (_believed(tokens, t) or _doubted(tokens, t)):
        return True  # "I thought the second one was turning": what the narrator wrongly expected; "wasn't sure
        # if it was turning": what could not be told
    if u.category in ("actions", "sequence") and (_rule_of_the_road(tokens, t.sentence) or _counterfactual(tokens, t)
                                                  or _standing_advice(tokens, t.sentence)):
        return True  # "once someone's on a zebra, you stop and you wait"; "you'd have had to stop"
    if u.category == "agents" and u.meaning not in ("ego", "none") and u.tokens[-1].plural and not counted and \
            (before is None or before.word not in ("my", "our", "his", "her", "their", "its")) and t.question \
            and first.word in QUESTION_WORDS:
        return True  # "How are you meant to merge when trucks do this?": trucks in general
    if u.category == "actions" and t.question and _asks_whether(tokens, t):
        return True  # "Does the car stop in time?": whether it does is asked, not told
    if not t.question:
        return False
    if first.word not in QUESTION_WORDS and not (t.sentence == 1 and first.opened_by == ":" and first.word in (
            "make", "get", "have", "spawn", "create", "simulate", "force", "trigger")):
        return False  # ("CARLA: make an NPC cut in and stop in front of the ego? Scene is ...": the title's question)
    later = [x.base for x in tokens if x.sentence > t.sentence]
    phrases = lexicon().phrases
    return bool(set(later) & _agent_nouns()) or any(
        phrases.get(pair, ("", ""))[0] == "agents" and phrases[pair][1] not in ("none", "ego")
        for pair in zip(later, later[1:]))  # ("... a fire engine comes from the right")


INSTITUTIONS = {"police", "fire brigade", "fire service", "fire and rescue", "ambulance service", "paramedics"}
INSTITUTIONS_SPEAKING = {"want", "wants", "said", "say", "says", "appealed", "appeal", "appeals", "believe",
                         "believes", "released", "urged", "urge", "confirmed", "condemned", "arrested", "charged",
                         "appealing", "investigating", "looking", "asking", "urging", "seeking", "issued", "launched"}
ADDRESSED = {"to", "blame", "blamed", "call", "called", "ring", "rang", "phone", "phoned", "contact", "contacted",
             "inform", "informed", "tell", "told", "thank", "thanked", "praise", "dial", "dialled", "dialed",
             "notify", "notified", "alert", "alerted", "involve", "involved", "fault", "criticise", "criticize"}
GENERAL_TRUTH_VERBS = {"think", "thinks", "say", "says", "know", "knows", "believe", "assume", "expect", "realise",
                       "realize", "forget", "underestimate", "do", "tend", "love", "hate"}
AFTER_A_SCENE_COPULA = {"on", "in", "at", "by", "near", "next", "behind", "ahead", "there", "here", "all", "both",
                        "still", "already", "everywhere", "coming", "going", "parked", "stopped", "queued", "lined"}
HISTORY_LINKS = {"in", "since", "until", "till"}
ADDRESSEES = ANYONE | {"guys", "y'all", "yall", "ya", "all"}
ADDRESS_CLOSERS = {",", "there", "here", "on", "cmon", "out", "up", "down", "safe", "careful", "please", "pls", "plz",
                   "again", "now", "seriously", "honestly", "lol", "smh", "tbh", "ffs", "ok", "okay", "it", "already",
                   "together", "slow", "thanks", "thank", "you", "though", "too", "guys", "folks", "c'mon"}


SHARES = {"half", "most", "many", "none", "majority", "lots", "loads", "plenty", "rest", "quarter", "third"}


def _a_share_of(before: list[Token]) -> bool:
    """'half the cars behind me didn't bother', 'most of the drivers': a share of a group nobody counted,
    traffic in general, no agents of the scene."""
    words = [t.word for t in before[-4:]]
    if words[-1:] not in (["the"], ["those"], ["these"]):
        return False
    words = words[:-1]
    if words[-1:] == ["of"]:
        words = words[:-1]
    return bool(words) and words[-1] in SHARES


def _addressed_readers(before: list[Token], after: list[Token], u: Unit) -> bool:
    """'be safe out there ppl', 'cmon people', 'slow down, folks': the readers a post or a broadcast ends a
    sentence by speaking to, nobody in the scene. Counted people ('two people') or the object of a verb or a
    preposition ('nearly hit people', 'stopped for people') stay agents."""
    return len(u.tokens) == 1 and u.tokens[0].word in ADDRESSEES and not after and \
        (not before or before[-1].word in ADDRESS_CLOSERS)


BUILDING = {"set", "make", "do", "build", "create", "write", "add", "knock", "whip", "simulate", "model", "code", "mock",
            "script", "spin"}
ASKING_FOR_HELP = {"pls", "please", "plz", "can", "could", "would", "will", "hey", "can't", "cant", "anyone", ",", "@"}
VOCATIVES = ADDRESSEES | {"lads", "gents", "boys", "fellas", "chaps", "team", "mates", "mate", "ladies", "drivers",
                          "everyone", "peeps", "troops"}
GREETINGS = {"right", "ok", "okay", "alright", "hey", "hi", "hello", "morning", "evening", "afternoon", "listen", "so",
             "well", "oi", "cheers", "thanks"}


def _opening_vocative(before: list[Token], after: list[Token], u: Unit) -> bool:
    """'Right lads, one for the sim', 'Morning all, ...', 'Back it down, drivers.': those spoken to at the start or
    the end of a sentence, set off by a comma, are the readers, nobody in the scene."""
    if len(u.tokens) != 1 or u.tokens[0].word not in VOCATIVES:
        return False
    opening = all(t.word in GREETINGS for t in before) and after[:1] and after[0].word == ","
    closing = before[-1:] and before[-1].word in {","} | GREETINGS | SPOKEN_TAGS and not after
    return bool(opening or closing)


NAMED_BY_ROLE = (DRIVERS - PLAIN_PEOPLE) | {"officer", "cop", "policeman", "policewoman", "warden", "marshal", "copper",
                                           "trooper", "deputy", "constable", "teacher"}
# a driver, an officer, a mate: someone by role or a word for a driver, who does nothing and is nowhere in the
# scene, is no one on foot in it ("that's why mate", "the officer didn't ticket anybody")
SPOKEN_TAGS = {"why", "honest", "innit", "yeah", "though", "eh", "ta", "seriously", "mind", "swear", "promise"}
# "that's why mate", "cheers mate", "honest mate": a bare word of address ending what is said


DAMAGED = {"totaled", "totalled", "damaged", "dented", "wrecked", "smashed", "scratched", "crushed", "destroyed",
           "undriveable", "undrivable", "fine", "ok", "okay", "undamaged", "repaired", "gone"}
DEGREE = {"badly", "completely", "totally", "slightly", "a", "now", "basically", "pretty", "all", "still"}
HAVING_OF_A_KIND = {"own", "owns", "buy", "buys", "sell", "sells", "hate", "hates", "love", "loves", "rent", "rents",
                    "insure", "insures", "ban", "bans", "banning", "allow", "allows"}
NEVER_CAME = {"come", "came", "comes", "arrive", "arrived", "arrives", "appear", "appeared", "appears"}
AWAITED_BY = {"i", "we", "you", "was", "were", "am", "are", "waiting", "for", "still", "yet", "that",
              "which", "even", "they"}  # "the bus (I was waiting for) (still) hadn't come": who waits for it
# "never comes", "never arrived": one that is not there ("never came to a stop" is there, and did not stop)


MEETING = {"see", "spot", "notice", "encounter", "meet", "approach", "come", "find", "pass", "hear"}


def _met_in_a_rule(sentence: list[Token], before: list[Token], after: list[Token]) -> bool:
    """'When you see a school bus with its stop arm out, stop.', 'If you meet a horse rider, slow down': a rule
    for anyone who meets such a one (an order follows the condition), not an agent of the scene."""
    lead = [x for x in before if x.word not in ("a", "an", "any", "another")]
    if len(lead) < 3 or lead[-1].base not in MEETING and [x.word for x in lead[-2:]] not in (["come", "across"],
                                                                                           ["come", "upon"]):
        return False
    k = len(lead) - (1 if lead[-1].base in MEETING else 2)
    if not (lead[k - 1].word in ("you", "drivers", "motorists", "one") and k >= 2 and
            lead[k - 2].word in ("when", "whenever", "if", "once")):
        return False
    comma = next((j for j, x in enumerate(after) if x.word == ","), None)
    if comma is None or comma + 1 >= len(after):
        return False
    order = after[comma + 1]
    return order.word not in SUBJECT_PRONOUNS and order.word == order.base and \
        lexicon().phrases.get((order.base,), ("",))[0] in ("actions",) or \
        order.word in ("change", "slow", "move", "give", "pull", "keep", "stay", "wait", "yield", "stop")


def _only_talked_about(tokens: list[Token], u: Unit) -> bool:
    """Agent nouns the text talks about, that are nobody in the scene: an institution written to or blamed ('I
    reported it to the police', 'I do not blame the fire brigade'); people or vehicles in general ('kids are
    unpredictable', 'harder than people think'); a topic said alone ('Motorcycles.'); a clause of history dated
    by its year ('the crossing patrol lady was withdrawn in 2020')."""
    t, last = u.tokens[0], u.tokens[-1]
    sentence = _sentence(tokens, t.sentence)
    before = [x for x in sentence if x.index < t.index]
    after = [x for x in sentence if x.index > last.index]
    said = " ".join(x.word for x in u.tokens)
    lead = [x.word for x in before[-2:]]
    if _addressed_readers(before, after, u) or last.plural and _a_share_of(before) or \
            _opening_vocative(before, after, u):
        return True
    if said in ("someone", "somebody", "anyone", "anybody") and after and after[0].base in BUILDING and \
            before and before[-1].word in ASKING_FOR_HELP:
        return True  # "pls someone set up a zebra crossing", "can anyone make this": whoever is asked to build it
    if said in INSTITUTIONS and lead and (lead[-1] in ADDRESSED or lead[-1] == "the" and len(lead) == 2
                                         and lead[0] in ADDRESSED):
        return True
    if said in INSTITUTIONS and not before and after[:1] and (after[0].word in INSTITUTIONS_SPEAKING or after[
            0].word in ("are", "were", "have", "has", "is") and after[1:2] and after[1].word in INSTITUTIONS_SPEAKING):
        return True  # "Police are appealing for witnesses after ...", "Police have released CCTV": who reports it
        # (not "Police were chasing a stolen car")
    bare = _bare_plural(tokens, u) or last.plural and before[-1].word == "than" and \
        not (len(before) > 1 and before[-2].word in ("more", "fewer"))  # "harder than people think"
    if bare and u.meaning not in ("ego", "none"):
        if before[-1:] and before[-1].word in HAVING_OF_A_KIND:
            return True  # "campaigners own cars too": cars in general
        if before[-1:] and before[-1].word == "than" or after[:1] and after[0].word in GENERAL_TRUTH_VERBS:
            return True  # "harder than people think", "people underestimate it"
        if {"supposed", "always", "ought", "meant"} & {x.word for x in before} and \
                any(x.word in ("you", "you're", "youre", "one", "drivers") for x in before):
            return True  # "you're supposed to give way to buses anyway": what one does for buses, in general
        if len(after) >= 2 and after[0].word in ("are", "were") and not after[1].word.endswith("ing") and \
                after[1].word not in AFTER_A_SCENE_COPULA and \
                lexicon().phrases.get((after[1].word,), ("word",))[0] not in ("actions", "positions", "agents"):
            return True  # "kids are unpredictable", "trucks are a menace": what they are like, in general
        if not after and all(x.word in INTERJECTIONS | {","} for x in before) and u.meaning != "generic" and \
                last.base != "vehicle" and any(m.category == "agents" and m.meaning == u.meaning
                                               for m in matches(tokens, last.index + 1)):
            return True  # "HOST B: Motorcycles." the topic, before the scene tells of one ("Actors:" heads a list)
    if u.meaning not in ("ego", "none") and _met_in_a_rule(sentence, before, after):
        return True  # "when you see a police car stopped on the shoulder, change lanes": whoever one meets
    said_other = before[-2:-1] if before[-1:] and before[-1].word == "other" else before[-1:] if t.word == "other" \
        else []
    if last.plural and u.meaning == "generic" and said_other and \
            said_other[0].word in GENERIC_AFTER | {"to", "towards", "toward", "around"}:
        return True  # "clearance to other road users", "care for other vehicles": anyone else, in general
    words = [x.word for x in after[:5]]
    lead = next((k for k, w in enumerate(x.word for x in after[:9]) if w not in AWAITED_BY), 0)
    if lead and [x.word for x in after[lead:lead + 1]] in (["has"], ["had"], ["did"], ["have"]):
        words = [x.word for x in after[lead:lead + 5]]  # "the bus I was waiting for still hadn't turned up"
    if u.meaning not in ("ego", "none") and not before and len(words) >= 2 and words[0] in COPULAS and \
            (words[1] in DAMAGED or words[1] in DEGREE and words[2:3] and words[2] in DAMAGED):
        return True  # "Car is totaled.": the state of the writer's car after it all, no one on the road
    if u.meaning not in ("ego", "none") and words[:2] in (["has", "not"], ["had", "not"], ["did", "not"],
                                                          ["have", "not"]) and len(words) > 2 and \
            words[2] in NEVER_CAME | {"touched", "touch", "been", "shown", "turned", "done"} and \
            not (len(words) > 3 and words[3] in ("to", "a", "the", "into", "in", "at")):
        return True  # "the gritter hasn't touched Park Lane", "the bus hadn't come": one that is not there
    if u.meaning not in ("ego", "none") and "never" in words[:3]:
        k = words.index("never")
        verb = after[k + 1] if k + 1 < len(after) else None
        if verb is not None and (verb.word in NEVER_CAME or verb.base in ("show", "turn") and k + 2 < len(after)
                                 and after[k + 2].word == "up") and not (k + 2 < len(after) and after[k + 2].word
                                                                         == "to"):
            return True  # "the gritting lorry never comes up our road": one that is not there
    for x, nxt in zip(sentence, sentence[1:]):
        if x.word in HISTORY_LINKS and nxt.word.isdigit() and len(nxt.word) == 4 and 1900 <= int(nxt.word) <= 2099:
            lo, hi = sorted((t.index, nxt.index))
            if not any(y.word == "," for y in tokens[lo:hi]):
                return True  # "was withdrawn in 2020": before the scene, in the same clause
    return False


PROPOSING = {"ask", "asked", "want", "wanted", "suggest", "suggested", "propose", "proposed", "raise", "raised",
             "mention", "mentioned", "float", "floated", "request", "requested", "pitch", "pitched", "prefer"}
TURNED_DOWN = (("not",), ("no",), ("parked",), ("park",), ("deferred",), ("defer",), ("dropped",), ("drop",),
               ("rejected",), ("postponed",), ("shelved",), ("vetoed",), ("out", "of", "scope"), ("for", "later"),
               ("maybe", "later"), ("later",), ("not", "now"))
LEAVING_OUT = (("leave", "out"), ("leaving", "out"), ("drop",), ("dropped",), ("exclude",),
               ("excluded",), ("omit",), ("omitted",), ("remove",), ("removed",), ("skip",), ("skipped",))


def _sentence(tokens: list[Token], sentence: int) -> list[Token]:
    """The tokens of one sentence, found by bisection: tokens come in sentence order, and a scan of the whole
    text for each word read would make reading quadratic in its length."""
    return tokens[bisect_left(tokens, sentence, key=_sentence_number):
                  bisect_right(tokens, sentence, key=_sentence_number)]


def _sentence_number(t: Token) -> int:
    return t.sentence


def _unit_start(u: Unit) -> int:
    return u.start


def _starts_with(words: list[str], phrases) -> bool:
    return any(tuple(words[:len(p)]) == p for p in phrases)


def _set_aside(tokens: list[Token], u: Unit) -> bool:
    """Minutes of a meeting tell what was proposed as well as what was agreed: what someone asked about or
    wanted that the same sentence turns down ('Sofia asked about a bus too - not for this one', 'Dan wanted a
    motorbike as well: parked for now'), or what the team leaves out ('agreed to leave out oncoming traffic',
    'drop the parked cars'), is no part of the scene: the clause from that verb on, with its agents and what
    they do."""
    t = u.tokens[0]
    if u.meaning == "ego":
        return False
    sentence = _sentence(tokens, t.sentence)
    words = [x.word for x in sentence]
    bases = [x.base for x in sentence]
    ends = [k for k, w in enumerate(words) if w in (",", "but") or w == "and" and k + 1 < len(words) and
            words[k + 1] not in DETERMINERS and _word_number(sentence[k + 1]) is None] + [len(words)]
    following = _sentence(tokens, t.sentence + 1)
    at = next((k for k, x in enumerate(sentence) if x.index == t.index), None)
    if at is None or not set(words[:at + 1]) & (PROPOSING | {p[0] for p in LEAVING_OUT}):
        return False
    for k in range(at + 1):
        said = next((p for p in LEAVING_OUT if tuple(words[k:k + len(p)]) == p), None)
        nxt = sentence[k + len(said)] if said and k + len(said) < len(words) else None
        leaving = said is not None and nxt is not None and nxt.word != "off" and nxt.word not in INDEFINITE \
            and _word_number(nxt) is None and (lexicon().phrases.get((nxt.base,)) or ("",))[0] != "agents"
        # ("a skip lorry": a lorry of its kind, nothing left out)
        # "drop off the kids" is no leaving out, nor is "drop two vans ahead of the player" (a game's spawn)
        if not leaving and words[k] not in PROPOSING:
            continue
        end = next(e for e in ends if e > k)
        if at >= end or not set(bases[k:end]) & _agent_nouns():
            continue
        if leaving:
            return True
        pieces = [sentence[e + 1:] for e in ends if e > k and e < len(words)] + [following]
        if any(_starts_with([x.word for x in piece], TURNED_DOWN) and not {x.base for x in piece} & _agent_nouns()
               for piece in pieces):
            return True
    return False


DEFINING = (("defined", "as"), ("defined", "here", "as"), ("define", "as"), ("defines", "as"), ("that", "is", ","),
            ("i", "e"), ("in", "other", "words"), ("by", "which", "we", "mean"), ("by", "which", "i", "mean"))
COMPARING = (("like", "the", "one"), ("like", "the", "ones"), ("similar", "to", "the", "one"), ("just", "like", "the"),
             ("reminded", "me", "of"), ("reminds", "me", "of"), ("the", "same", "as", "the", "one"))


def _in_an_aside(tokens: list[Token], u: Unit) -> bool:
    """'a pedestrian, defined here as any road user travelling on foot, crosses', 'a cut-in, that is, a situation
    in which a vehicle enters the ego's lane': what a word means; 'a car, like the one that hit my van last week,',
    'which reminded me of a crash involving a bus': what the scene is compared with. From those words to the next
    comma or the sentence's end it speaks of a kind or of another time, of nobody in the scene."""
    t = u.tokens[0]
    sentence = _sentence(tokens, t.sentence)
    at = t.index - sentence[0].index
    if at >= len(sentence):
        return False  # a unit placed past its sentence's tokens opens no aside (as the slices before read it)
    comma = next((k for k in range(at, -1, -1) if sentence[k].word == ","), -1)  # an aside that began before the
    # last comma ended there: only the words since, and a pattern's length before, can open one that holds `at`
    for k in range(max(0, comma - ASIDE_LONGEST), at + 1):
        if sentence[k].word not in ASIDE_OPENERS:
            continue
        said = next((p for p in DEFINING + COMPARING if tuple(x.word for x in sentence[k:k + len(p)]) == p), None)
        if said is None:
            continue
        start = k + len(said)
        end = next((e for e in range(start, len(sentence)) if sentence[e].word == ","), len(sentence))
        if k <= at < end:
            return True
    return False


ASIDE_OPENERS = {p[0] for p in DEFINING + COMPARING}
ASIDE_LONGEST = max(len(p) for p in DEFINING + COMPARING)


@lru_cache(maxsize=1)
def _agent_nouns() -> frozenset[str]:
    return frozenset(w for words, (category, meaning) in lexicon().phrases.items() if category == "agents"
                     and meaning not in ("none", "ego") and len(words) == 1 for w in words)


LOOKING = {"look", "looking", "looked", "watch", "watching", "watched", "check", "checking", "checked", "scan",
           "scanning", "scanned", "eye", "search", "searching"}


def _looked_out_for(units: list[Unit], first: int) -> bool:
    """'looking out for cars', 'checks for pedestrians': what one looks for, in general; nobody in the scene."""
    said = [t.word for u in units[max(0, first - 3):first] for t in u.tokens]
    return said[-1:] == ["for"] and bool(set(said[:-1]) & LOOKING)


VERB_PARTICLES = {"by", "past", "through", "off", "away", "out", "over", "across"}


def _ends_its_condition(units: list[Unit], k: int) -> bool:
    """A condition with no comma ends at its verb ('after the cyclist has passed ego turns right'), at the particle
    after it ('once the oncoming car has gone by he turns') or at its state ('once it's clear the ego turns
    right'), when a subject and its verb follow."""
    u = units[k]
    said = u.category == "actions" or k > 0 and u.category == "word" and (
        u.word in VERB_PARTICLES and units[k - 1].category == "actions" or
        u.word in CONDITION_STATES and units[k - 1].word in COPULAS | {"be"})
    return said and _subject_and_verb_follow(units, k + 1)


def _ego_then_what_it_is(current: list[Unit], units: list[Unit], k: int) -> bool:
    """'at 8am the ego (a Ford Focus) was stationary', 'at 0815 hrs V1 (Ford Focus)': the ego ends an opening with
    no verb and no other noun, and the comma at k sets off what it is (an article, or a make closed by a comma)."""
    nxt = units[k + 1] if k + 1 < len(units) else None
    if not current or current[-1].category != "agents" or current[-1].meaning != "ego" or _has_verb(current) or \
            sum(x.category == "agents" for x in current) != 1 or nxt is None:
        return False
    closed = next((x.category == "comma" for x in units[k + 2:k + 5] if x.category in ("comma", "actions")), False)
    return nxt.word in ("a", "an") or nxt.category == "agents" and closed


def _gone_by(units: list[Unit]) -> bool:
    """'once the oncoming car has gone by', 'when the bus has passed', 'after it clears the junction': whoever the
    condition is about has left."""
    for k, u in enumerate(units):
        words = set(u.base.split())
        if u.category == "actions" and (words & {"pass", "clear", "past", "by"} or u.meaning == "move" and
                                        k + 1 < len(units) and units[k + 1].word in ("by", "past", "through")):
            return True
        if u.word in COPULAS and k + 1 < len(units) and units[k + 1].word in ("through", "past", "clear", "gone"):
            return True  # "once both are through", "he's clear"
    return False


def _has_verb(units: list[Unit]) -> bool:
    return any(u.category == "actions" and u.meaning not in ("try",) for u in units)


def _holds_the_green(units: list[Unit]) -> bool:
    """'the bus has the green, and a fire engine comes through the red': a predicate the road lexicon holds whole,
    so what follows 'and' is another clause, not a second subject of the next verb."""
    return any(u.category == "road" and len(u.tokens) > 1 and u.tokens[0].base in ("have", "get") and
               any(x.category == "agents" for x in units[:units.index(u)]) for u in units)


def _reaching(units: list[Unit], k: int) -> bool:
    """'when the ego reaches / approaches / enters the junction': the start of a later stage."""
    window = units[k:k + 5]
    ego = any(u.category == "agents" and u.meaning == "ego" for u in window[:3])
    verb = next((u for u in window if u.category == "actions"), None)
    if not ego or verb is None or any(u.word == "shall" for u in units if u.tokens[0].sentence ==
                                      units[k].tokens[0].sentence):
        return False  # "When the subject vehicle approaches the junction ..., the AEB shall stop it": a
        # requirement's trigger, what the scene is, not a stage before it
    if verb.meaning == "reach":
        return True
    rest = units[units.index(verb) + 1: units.index(verb) + 4]
    return verb.base in ("approach", "enter") and any(u.category == "road" and u.meaning == "junction" for u in rest)


def _completed(units: list[Unit], k: int) -> bool:
    """'when the bus has cleared the junction', 'when they have gone by': a condition told in the present perfect
    holds once a deed is done, the start of a later stage (as 'once' is); so does one in the past perfect told in
    the past; a subject, then has / have / had and a participle."""
    window = units[k:k + 6]
    for j, u in enumerate(window):
        if u.category == "comma" or u.tokens[0].sentence != units[k].tokens[0].sentence or u.category == "actions":
            return False
        if u.category == "word" and u.word in ("has", "have", "had"):  # ("when it had passed, I began my turn")
            said = [x for x in window[j + 1:j + 3] if x.word not in ADVERBS | {"fully", "completely", "safely"}]
            subject = any(x.category == "agents" or x.word in PRONOUNS for x in window[:j])
            return subject and bool(said) and (said[0].category == "actions" or said[0].category == "word" and
                                               re.fullmatch(r"[a-z]{3,}(?:ed|en)", said[0].word) is not None)
    return False


# -- noun phrases and entities ------------------------------------------------------------------------------

@dataclass
class NounPhrase:
    entity: Entity | None  # None: names no agent
    index: int  # where in the clause's units its head is
    first: int  # its first unit (determiner)
    introduced: bool = False  # a new entity (indefinite)
    plural: bool = False
    group: list = field(default_factory=list)  # several entities ("both", "they")


def _agent_type(u: Unit) -> tuple[str, bool]:
    """(type, is_ego) of an agent unit; the ego's type from its noun ('the ego truck')."""
    if u.meaning == "ego":
        words = [t.base for t in u.tokens]
        for kind, nouns in (("truck", ("truck", "lorry", "hgv", "robotruck")),
                            ("bus", ("bus", "coach", "shuttle", "robobus")),
                            ("motorcycle", ("motorcycle", "motorbike"))):
            if set(nouns) & set(words):
                return kind, True
        for k in range(1, len(words)) if words[:1] == ["ego"] else ():
            own = lexicon().phrases.get(tuple(words[k:]))
            if own is not None and own[0] == "agents" and own[1] in V.EGO_TYPES:
                return own[1], True  # "the ego LKW", "V1 white Scania"
        return "car", True
    if u.meaning == "generic":
        return "car", False
    return u.meaning, False


ADJECTIVE_POSITIONS = {"oncoming", "opposing", "leading", "lead", "following", "trailing", "adjacent", "preceding",
                       "opposite", "front", "rear", "back", "tailgating", "northbound", "southbound", "eastbound",
                       "westbound"}
TRANSITIVE_POSITIONS = {"following", "trailing", "tailgating", "leading", "preceding"}


def _placed_on_the_way_in(between: list[Unit]) -> bool:
    """'(the dude) coming the other way in (a pickup)': a verb in -ing and where it goes, then 'in' its vehicle."""
    return len(between) >= 2 and between[-1].word == "in" and between[0].tokens[0].word.endswith("ing") and \
        between[0].category in ("actions", "positions") and all(
            u.category == "positions" or u.category == "word" and u.word in ("the", "other", "way", "from", "up",
                                                                            "down", "along")
            for u in between[1:-1])


def _a_verb_after_the_copula(units: list[Unit], u: Unit) -> bool:
    """'Ego car is following city bus': the -ing word right after 'is' is its verb (the bus is followed), not a
    word for which one it is ('SV1 is oncoming truck')."""
    k = units.index(u)
    return u.word in TRANSITIVE_POSITIONS and k > 0 and units[k - 1].word in ("is", "are", "was", "were")


DETERMINERS = DEFINITE | INDEFINITE | {
    "his", "her", "my", "other", "both", "all", "each", "every", "more", "than", "over", "of", "second", "third",
    "first", "same", "further", "additional", "extra", "its", "their", "neither", "either",
}
SAID_OF_SOME = DETERMINERS | OWNERS | COUNTED_BY | {"no"}  # before a plural: some of the kind, not the kind


CLOCK_WORDS = {"hrs", "hours", "hr", "h", "am", "pm", "oclock", "o'clock", "gmt", "bst", "utc"}


def _clock_stamp(hours: Unit, minutes: Unit) -> bool:
    """'14:02', '00:05', '12:45' (a video's minutes): the two numbers of a time, read as the tokens they are."""
    return hours.word.isdigit() and int(hours.word) < 60 and len(minutes.word) == 2 and minutes.word.isdigit() \
        and minutes.tokens[0].index == hours.tokens[-1].index + 1


MADE_WITH = {"wheel", "wheels", "wheeled", "wheeler", "axle", "axles", "axled", "seater", "seat", "door", "doors",
             "berth", "cylinder", "litre", "liter", "speed", "deck", "decker", "storey", "tonne", "ton", "tonner"}


def _count_before(units: list[Unit], head: int, lo: int) -> tuple[int | None, int, set[str], list[Unit]]:
    """The count, determiner words and premodifiers in front of a noun: 'the two dangerous oncoming cars'.
    Modifiers stand between the determiner and the noun; the determiner ends the phrase on the left."""
    count, first, words, modifiers = None, head, set(), []
    if units[head].word in ("i", "me", "we", "us", "you"):
        return count, first, words, modifiers  # a pronoun takes no premodifier: 'just drove past us'
    k = head - 1
    in_determiner = False
    while k >= lo:
        u = units[k]
        if k > lo and _clock_stamp(units[k - 1], u):
            break  # "00:05 Ambulance closes up behind": a log's time, no count
        if u.category == "numbers" and words & {"a", "an"}:
            break  # "around ten a school bus came up": a time before the article, no count
        if u.category in ("numbers", "number") and k + 1 < head and units[k + 1].word in MADE_WITH:
            modifiers.append(u)  # "our 8-wheel tipper", "a two-axle truck": what it is built with, no count
        elif u.category == "numbers":
            count = int(u.meaning) if count is None else count
            if u.word in VAGUE_COUNTS:
                words.add("some")
            in_determiner = True
        elif u.category == "number" and _model_year(u.word) and k + 1 == head - len(modifiers):
            modifiers.append(u)  # "a 2017 Camry": the year it was built, not how many
        elif u.category == "number" and count is None and _named_after_a(units, k, lo):
            modifiers.append(u)  # "a Ram 3500 pickup", "a 9 year old child": a model's or an age's number
        elif u.category == "agents" and u.meaning not in ("ego", "none") and k + 1 == head - len(modifiers) and \
                not words and count is None:
            modifiers.append(u)  # "a Chevrolet Tahoe", "a Ford F-150 pickup": the maker's name before the model
        elif u.category == "number" and (words & {"a", "an"} or k > 0 and units[k - 1].word in NUMBERED_NAMES or
                                         k > 0 and units[k - 1].word == "the" and u.word.isdigit() and
                                         not units[head].tokens[-1].plural):
            break  # "on SR-99 a bus stops", "Year 4 cycles in", "the 42 bus": a road's, a name's or a route's
            # number, no count
        elif u.category == "number":
            value = read_number(u.word) or 0
            count = int(min(value, TOO_LARGE)) if count is None else count
            in_determiner = True
        elif u.category == "word" and u.word in DETERMINERS:
            words.add(u.word)
            in_determiner = True
        elif in_determiner:
            break
        elif units[head].meaning == "ego" and u.category == "actions" and not (
                k > lo and units[k - 1].word in DETERMINERS and k + 1 == head):
            break  # "passed ego on right": the verb before the ego is no premodifier of it ("the stationary ego" is)
        elif u.category == "word" and u.word in DISTANCE_UNITS | {"foot", "inch", "inches", "percent"} | CLOCK_WORDS:
            break  # "missed me by like a foot mom said": a measure ends the phrase before it (texts lack commas);
            # so does a time ("at 0815 hrs V1 ...")
        elif u.category == "behaviours" or (u.category == "actions" and k + 1 == head - len(modifiers)
                                            and not any(m.category == "actions" for m in modifiers)) or \
                (u.category == "positions" and len(u.tokens) == 1 and u.word in ADJECTIVE_POSITIONS) or \
                (u.category == "word" and u.word not in lexicon().function_words and u.word not in CLAUSE_WORDS):
            modifiers.append(u)
        else:
            break
        first = k
        k -= 1
    # a premodifier run without a determiner in front of it belongs to what came before ("ego following truck")
    if not words and count is None and modifiers and first > 0 and (
            units[first - 1].category == "agents" or units[first - 1].category == "actions"
            and modifiers[-1].category != "actions" or units[first - 1].word in AUXILIARIES
            and modifiers[-1].category == "positions"):
        first = head  # "ego following truck", "the ego is following slow-moving bus": the predicate's, not a noun's
        modifiers = []
    return count, first, words, modifiers


def _clipped(short: str, name: str) -> bool:
    """'ped' for 'pedestrian', 'veh' for 'vehicle', 'moto' for 'motorcycle': a name cut short, as notes write it."""
    return 3 <= len(short) < len(name) and " " not in short and name.split()[-1].startswith(short)


def _it_was_a(r: _Reader, units: list[Unit], first: int, recent: list[Entity]) -> Entity | None:
    """'a truck on the left, I think it was a truck,': the noun after 'it was' corrects or repeats the one before."""
    if first < 2 or units[first].word not in ("a", "an") or units[first - 1].word not in ("was", "is") or \
            units[first - 2].word != "it":
        return None
    return next((e for e in reversed(recent + r.clause_mentions) if not e.is_ego), None)


CASE_NOUNS = {"scenario", "scene", "test", "case", "situation"}
RIDING_PEOPLE = {"guy", "man", "woman", "lady", "dude", "kid", "lad", "bloke", "boy", "girl", "person", "fella"}


def _names_the_case(r: _Reader, units: list[Unit], head: int, kind: str) -> bool:
    """'stopped veh scenario', 'cut-in car test', 'the lead-vehicle-following scenario': a noun naming the kind of
    case, when an agent of its kind is introduced before or later on; with no other ('a cyclist scenario') it is the
    agent asked for."""
    case = head + 1 + (head + 2 < len(units) and units[head + 1].category in ("actions", "positions") and
                       units[head + 1].tokens[-1].word.endswith(("ing", "ed")))  # "the lead-vehicle-following
    # scenario", "a lead vehicle stopped scenario"
    if case >= len(units) or units[case].word not in CASE_NOUNS or units[head].tokens[-1].plural:
        return False
    end = units[case].tokens[-1].index + 1
    vehicles = V.EGO_TYPES if units[head].meaning == "generic" or units[head].base.split()[-1] == "vehicle" else {kind}
    return any(m.category == "agents" and m.meaning in vehicles for m in matches(r.tokens, end)) or \
        any(not e.is_ego and e.type in vehicles for e in r.entities)  # "... a lead vehicle. Car-following scenario"


def _vague_part_of_the(units: list[Unit], first: int, head: int) -> bool:
    """'a group of the children', 'some of the pupils': an uncounted part of a group named before."""
    span = units[first:head]
    vague = any(u.category == "numbers" and u.tokens[0].word in VAGUE_COUNTS | {"group", "crowd", "bunch"}
                for u in span)
    of_the = any(u.word in ("the", "those", "these") and k > 0 and (span[k - 1].word == "of" or (
        span[k - 1].category == "numbers" and span[k - 1].tokens[-1].word == "of")) for k, u in enumerate(span))
    return vague and of_the


GENERIC_AFTER = {"for", "about", "like", "of"}  # "for people entering": people in general


def _gets_out(units: list[Unit], head: int, walking: bool = True) -> bool:
    """'the driver gets out', 'the rider climbs off', 'the driver is out and walking': out of the vehicle, on
    foot. A driver who walks is out of the vehicle too ('walking' False: a vehicle's crew walks beside it)."""
    words = [t.word for u in units[head + 1:head + 5] for t in u.tokens]
    verbs = {"get", "gets", "got", "climb", "climbs", "climbed", "step", "steps", "stepped", "jump", "jumps", "jumped",
             "hop", "hops", "hopped", "is", "was", "are", "were", "now", "getting", "climbing", "stepping", "jumping",
             "hopping"}
    if walking and units[head + 1:head + 2] and units[head + 1].category == "actions" and \
            units[head + 1].tokens[0].base in ("walk", "stroll", "wander", "stride", "stagger"):
        return True  # "the driver walked out from in front of it": on foot
    if walking and (words[1:2] if words[:1] in (["is"], ["was"]) else words[:1]) in (["standing"], ["stood"],
                                                                                     ["stands"]):
        return True  # "its driver (is) standing beside it on the shoulder": out of it, on foot
    words += [""]
    return any(w in verbs and nxt in ("out", "off", "down") and not (
        w in AUXILIARIES and (after == "of" or nxt == "down")) for w, nxt, after in zip(words, words[1:], words[2:]))
    # ("climbed down from the cab"; not "is out of his mind", "was down the road")


KIN = {"mother", "mom", "mum", "father", "dad", "wife", "husband", "son", "daughter", "kid", "child", "passenger",
       "friend", "sister", "brother", "grandma", "grandpa", "granny", "grandmother", "grandfather", "baby",
       "girlfriend", "boyfriend", "partner", "family", "toddler", "teen", "teenager", "parent", "boy", "girl",
       "uncle", "aunt", "aunty", "auntie", "cousin"}


KIN_NAMES = {"mom", "mum", "mommy", "mummy", "mama", "dad", "daddy", "papa", "grandma", "grandpa", "granny", "gran",
             "nan", "nana", "grandad", "granddad"}  # kin called by name, with no article ("mom said")


def _on_foot_in_the_scene(units: list[Unit], head: int) -> bool:
    """Whether the clause puts a person on the road, the pavement or a crossing ('my son was crossing', 'letting
    people across')."""
    let_across = head + 1 < len(units) and units[head + 1].word in ("across", "over", "through") and any(
        x.tokens[0].base in ("let", "wave") for x in units[max(0, head - 3):head])
    return let_across or any(
        u.category == "actions" and u.meaning in ("cross", "walk") or u.category == "positions" and u.meaning in (
            "sidewalk", "crosswalk", "in_road", "shoulder") or u.category == "road" and u.meaning in
        V.CROSSWALK_OBJECTS for u in units[head + 1:])


def _on_a_machine(units: list[Unit], head: int) -> bool:
    """'the guy on the moped', 'the woman in the van': a person named by the vehicle they ride or drive."""
    j = head + 2 + (head + 2 < len(units) and units[head + 2].word in ("a", "an", "the", "his", "her", "that"))
    return head + 1 < len(units) and units[head + 1].word in ("on", "in") and j < len(units) and \
        units[j].category == "agents" and units[j].meaning in V.EGO_TYPES | V.TWO_WHEELER_TYPES


def _on_foot_with_someone(units: list[Unit], first: int) -> bool:
    """'I was crossing the zebra with my son': kin who go with one crossing or walking go on foot too."""
    return first > 0 and units[first - 1].word == "with" and any(
        u.category == "actions" and u.meaning in ("cross", "walk") for u in units[max(0, first - 8):first - 1])


def _of_a_group(units: list[Unit], first: int) -> bool:
    """'a whole crowd of people': the people are the crowd, counted as one; 'a bus full of people' are not."""
    k = first - 1 if units[first].word == "of" else first - 2
    return k >= 0 and (units[k].category in ("agents", "numbers") or units[k].word in GROUP_NOUNS)


def _named_after_a(units: list[Unit], k: int, lo: int) -> bool:
    """A number in a noun phrase that 'a' opens ('a Ram 3500 pickup', 'a 9-year-old child', 'an F 150') counts
    nothing: one is said, the number is part of a model's name or an age."""
    if not units[k].word.isdigit():
        return False
    j = k - 1
    while j >= lo and units[j].category in ("word", "agents") and units[j].word not in ("a", "an") and \
            units[j].word not in lexicon().function_words and units[j].word not in DETERMINERS:
        j -= 1
    return j >= lo and units[j].category == "word" and units[j].word in ("a", "an")


def _model_named_before(units: list[Unit], i: int) -> bool:
    """'a Mazda 3 hatchback': the maker and the model's number name the hatchback, no vehicle of their own."""
    return 0 < i and i + 2 < len(units) and units[i - 1].word in ("a", "an") and units[i].meaning not in (
        "ego", "none") and units[i + 1].category == "number" and units[i + 1].word.isdigit() and \
        units[i + 2].category == "agents" and units[i + 2].meaning not in ("ego", "none")


def _model_year(word: str) -> bool:
    return len(word) == 4 and word.isdigit() and 1950 <= int(word) <= 2099


HEADLINE_PLACES = {"ahead", "behind", "level", "side_left", "side_right", "from_left", "from_right", "road_left",
                   "road_right", "road_straight", "destination"}  # "Truck ahead.": a note that places one, no heading
DRIVER_CONTROLS = {"kept", "keep", "keeps", "held", "hold", "holds", "brought", "bring", "brings", "steered",
                   "steer", "steers", "stopped", "pulled", "moved", "put", "took", "drove", "parked"}


IMPACTS = {"hit", "hits", "crashed", "collided", "smashed", "struck", "rammed", "rear", "t", "clipped", "crash",
           "collision", "impact", "bumped", "slammed", "ploughed", "plowed", "totalled", "totaled", "wrecked"}
RESPONDERS = {"ambulance", "police", "firetruck"}
RECOVERY_VEHICLES = {"tow truck", "recovery truck", "recovery vehicle", "breakdown truck", "wrecker", "tow"}
RESPONDING_PEOPLE = {"officer", "police officer", "policeman", "policewoman", "cop", "constable", "paramedic",
                     "firefighter", "fireman", "medic", "trooper", "deputy", "sheriff"}  # on foot, come to help
UNREAL_IMPACT = {"not", "never", "avoid", "avoided", "without", "almost", "nearly", "could", "would", "might", "to",
                 "no", "near", "avoiding", "before", "if", "may", "must", "shall", "should", "will", "can"}


def _help_placed_nowhere(e: Entity, ignoring: frozenset[str] = frozenset()) -> bool:
    """An emergency service or a recovery truck said to do nothing but come, and placed nowhere (but for the
    features `ignoring` names): help that may have come to the scene rather than be in it ('Tow truck is on the
    way')."""
    return (e.type in RESPONDERS or e.type == "pedestrian" and e.head in RESPONDING_PEOPLE or
            e.head in RECOVERY_VEHICLES) and not e.is_ego and \
        not e.label and e.said_at >= 0 and not e.features - ignoring and all(a[4] in ("move", "reach")
                                                                           for a in e.actions)


ABOARD_WORDS = (("in", "the", "car"), ("in", "my", "car"), ("in", "our", "car"), ("in", "the", "back"),
                ("on", "board"), ("with", "me"), ("with", "us"))


def _said_aboard(r: _Reader, e: Entity) -> bool:
    """'I was with my wife and kids in the car': people said to be in the speaker's vehicle, a few words on."""
    if e.said_at < 0:
        return False
    after = [t.word for t in r.tokens[e.said_at:e.said_at + 7] if t.sentence == r.tokens[e.said_at].sentence]
    return _says_any(after, ABOARD_WORDS)


def _said_in_general(r: _Reader, e: Entity) -> bool:
    """'Left-hook risk to cyclists ... may not see a cyclist riding alongside', 'Pedestrians step off the kerb ...
    we watched a taxi turn while an elderly man was halfway across': a bare plural, counted by no one, said before
    one of its kind is named on its own in a later sentence, speaks of such agents in general; so does one that
    does nothing and is placed nowhere, when one of its kind is named on its own anywhere, when its sentence says
    no one does anything ('Pedestrians, cyclists, everyone: seen.'), or when it is vehicles ('throwing snowballs
    at cars')."""
    if not e.uncounted or e.definite or e.is_ego or e.parent is not None or e.said_at < 0 or e.label:
        return False
    sentence = r.tokens[e.said_at].sentence
    after = r.tokens[e.said_at + 1] if e.said_at + 1 < len(r.tokens) else None
    keyed = after is not None and (after.sentence != sentence and after.opened_by == ":" or
                                   after.word in ("is", "are", "was", "were"))  # "Pedestrians: a group crossing"
    idle = not e.actions and not e.features and not keyed  # "Pedestrians, cyclists, everyone: seen.", "... with old
    # people"
    if idle and (e.type not in V.VULNERABLE_TYPES or not any(u.category == "actions" for u in r.units
                                                             if u.tokens[0].sentence == sentence)):
        return True  # ("throwing snowballs at cars": vehicles said with no count, doing nothing, are no agents)
    return any(f is not e and not f.is_ego and f.type == e.type and f.count >= 1 and not f.uncounted and
               f.parent is not e and f.said_at >= 0 and (r.tokens[f.said_at].sentence > sentence or idle)
               for f in r.entities)


ROLE_GROUPS = {"road user", "road users", "agent", "agents", "actor", "actors", "participant", "participants"}


def _the_vehicles_named_before(r: _Reader, e: Entity) -> bool:
    """'vehicles blocking the intersection', 'both vehicles', said with no count after two or more vehicles were
    named, and 'all three road users' after as many were named: those again, no new ones."""
    if e.is_ego or e.said_at < 0:
        return False
    before = [f for f in r.entities if f is not e and not f.is_ego and f.count >= 1 and 0 <= f.said_at < e.said_at]
    if e.head in ROLE_GROUPS and not e.actions and not e.features and e.said_at > 0 and \
            r.tokens[e.said_at - 1].word in ("all", "both", "the", "these", "those", "two", "three", "four", "five"):
        return sum(f.count for f in before) >= max(2, e.count)  # "yield to all three road users": those named
    return e.uncounted and e.head in ("vehicle", "vehicles") and sum(
        1 for f in before if f.type not in V.VULNERABLE_TYPES) >= 2


CASE_HEADINGS = CASE_NOUNS | {"hazard", "class", "title", "type", "category", "rush"}


def _names_the_case_in_a_heading(r: _Reader, e: Entity) -> bool:
    """'Hazard H-22: pedestrian emerging from behind parked vehicles.', 'Scenario class: pedestrian at an
    unsignalized crosswalk.', 'Scenario of pedestrian rush-out.', 'a pedestrian-at-night case': a road user said
    bare in a case's heading names the case, when one of its kind is told of in a later sentence."""
    if e.is_ego or e.count != 1 or e.said_at < 0 or e.label or e.parent is not None:
        return False
    t = r.tokens[e.said_at]
    words = [x.word for x in r.tokens if x.sentence == t.sentence]
    heading = {x.word for x in r.tokens if x.sentence == t.sentence - 1} if t.opened_by == ":" and t.sentence > 0 \
        else set()
    keyed = bool(heading & CASE_HEADINGS)  # "Scenario class: pedestrian"
    triggered = {"triggering", "condition"} <= heading or {"trigger", "condition"} <= heading  # "Triggering condition:
    # a motorcycle masked by a larger oncoming vehicle. ... a motorcycle follows close behind it": the case's kind
    before = r.tokens[e.said_at - 1].word if e.said_at > 0 and r.tokens[e.said_at - 1].sentence == t.sentence else ""
    after = [x.word for x in r.tokens[e.said_at + 1:e.said_at + 5] if x.sentence == t.sentence]
    named = before in ("", "of") and bool(set(words) & CASE_HEADINGS) or before in ("a", "an") and bool(
        set(after) & CASE_NOUNS)  # "Scenario of pedestrian rush-out", "a pedestrian-at-night case"
    named = named or t.sentence == 0 and before in ("a", "an") and e.said_at > 1 and \
        r.tokens[e.said_at - 2].word in ("of", "with") and len(words) <= 10  # "Abrupt stop of a taxi. ... A taxi
    # ahead stops", "Signalized junction right turn with a red-light runner. ... An adversary vehicle ... runs the red"
    return (keyed and before == "" or triggered and before in ("a", "an") or named) and any(
        f is not e and not f.is_ego and f.type == e.type and f.said_at >= 0 and
        r.tokens[f.said_at].sentence > t.sentence for f in r.entities)


NO_PART = {"part", "actor", "actors", "agent", "agents", "modelled", "modeled", "simulated", "included"}


def _says_no_part(units: list[Unit], tokens: list[Token]) -> bool:
    """'he is not part of the scene', 'our safety operator, not an actor', 'the person at the wheel is our safety
    operator': who the clause is about is in no way in the scene."""
    said_tokens = [t for u in units for t in u.tokens]
    words = [t.word for t in said_tokens] + [tokens[said_tokens[-1].index + 1].word if said_tokens and
                                             said_tokens[-1].index + 1 < len(tokens) else ""]
    said = next((k for k, u in enumerate(units) if "not" in [t.word for t in u.tokens]), None)
    before = units[:said] if said is not None else []
    while before and before[-1].category == "word" and before[-1].word in COPULAS | AUXILIARIES | {"need", "needs"}:
        before = before[:-1]  # "he is not", "its driver need not be": who the denial is said of comes right before
    if before and not (before[-1].category == "agents" or before[-1].word in ("he", "she", "they", "it")):
        before = []  # "the ambulance crew is not modelled", "the crew on board are ..., not separate actors"
    denied = any(w == "not" and any(words[j] in NO_PART and words[j + 1:j + 2] != ["as"] for j in range(
        k + 1, min(k + 4, len(words) - 1))) for k, w in enumerate(words)) and \
        any(u.category == "agents" and u.meaning != "none" or u.word in ("he", "she", "they", "it") for u in before) \
        and not any(u.category == "agents" and u.meaning == "none" or any(
            t.possessive or t.word == "its" for t in u.tokens) for u in before)
    # (not "the lorry's driver is not modelled", "the child's parents, who are not modelled": they are not)
    copula = next((k for k, u in enumerate(units) if u.word in COPULAS and u.category == "word"), None)
    named = copula + 1 if copula is not None else len(units)
    named += named < len(units) and units[named].word in ("a", "an", "the", "our", "my", "their", "your")
    nobody = named < len(units) and units[named].category == "agents" and units[named].meaning == "none" and any(
        u.category == "agents" and u.meaning != "none" for u in units[:copula]) and not any(
        u.word in BELIEVING for u in units[:copula])  # ("a guy in a black hoodie, thought it was a deer at first,":
    # a first impression, no denial)
    return denied or nobody


HABIT = (("usually",), ("normally",), ("generally",), ("typically",), ("often",), ("a", "lot"), ("all", "the", "time"),
         ("every", "day"), ("every", "morning"), ("most", "days"), ("most", "mornings"), ("round", "here"),
         ("around", "here"), ("tend", "to"), ("tends", "to"))


def _said_of_a_habit(r: _Reader, e: Entity) -> bool:
    """'Cyclists use this road a lot too', 'There's usually a lollipop lady there in the mornings': a road user in a
    sentence of what usually happens is no agent of the scene told, when the text tells that scene in the past in
    another sentence (a lesson plan's 'there's usually a jogger crossing' is its scene)."""
    if e.said_at < 0:
        return False
    sentence = r.tokens[e.said_at].sentence
    if not _says_any([t.word for t in _sentence(r.tokens, sentence)], HABIT):
        return False
    told_in_the_past = any(t.sentence != sentence and (t.word in PAST_FORMS or t.word.endswith("ed") and
                                                      t.base != t.word) for t in r.tokens)
    return told_in_the_past and any(
        f is not e and (f.is_ego or f.count > 0) and f.said_at >= 0 and r.tokens[f.said_at].sentence != sentence
        for f in r.entities)


PAST_FORMS = {"was", "were", "came", "went", "drove", "saw", "ran", "had", "got", "stood", "sat", "rode", "swung",
              "shot", "flew", "spun", "slid"}  # irregular; a regular past ends in -ed


OFF_THE_ROAD_PLACES = {"yard", "garage", "shop", "driveway", "home", "depot", "workshop", "showroom", "garden"}


def _kept_off_the_road(r: _Reader, e: Entity) -> bool:
    """'my sister's jeep is still in the shop', 'the two cars rusting in her father's yard', 'my oke at home has
    two more bakkies': a vehicle placed by no side, said to be kept at home, in a yard or a shop, is no part of the
    scene ('a van parked at the shop on my left' is: at it, and placed)."""
    if e.is_ego or e.features - {"ahead", "behind"} or e.said_at < 0 or e.type in V.VULNERABLE_TYPES or \
            any(a[4] not in ("move", "stop") for a in e.actions):
        return False
    sentence = r.tokens[e.said_at].sentence
    words = [t.word for t in r.tokens[max(0, e.said_at - 6):e.said_at + 8] if t.sentence == sentence]
    for k, w in enumerate(words):
        opener = next((words[j] for j in range(k - 1, max(-1, k - 4), -1) if words[j] in ("in", "at")), None)
        if w in OFF_THE_ROAD_PLACES and (opener == "in" or opener == "at" and w in ("home", "yard")):
            return True  # ("parked at the shop": at it, on the road)
    return False


TOWED = {"towed", "impounded", "recovered", "tow", "towing"}


def _towed_away(r: _Reader, e: Entity) -> bool:
    """'Vehicle was towed from the scene', 'V2 not drivable, recovered': a vehicle first named, placed nowhere and
    doing nothing, in a sentence after the collision that says it was towed, is one of those that crashed, or none."""
    if e.is_ego or e.label or e.said_at < 0 or e.features or e.type in V.VULNERABLE_TYPES or \
            any(a[4] not in ("move", "stop") for a in e.actions):
        return False
    sentence = r.tokens[e.said_at].sentence
    if not any(t.word in TOWED for t in r.tokens[e.said_at:] if t.sentence == sentence):
        return False
    return any(t.word in IMPACTS for t in r.tokens[:e.said_at] if t.sentence < sentence)


def _came_after_the_crash(r: _Reader, e: Entity) -> bool:
    """'... and hit me. An ambulance came later', 'Paramedics checked us over': an emergency service first named in
    a sentence after the one that tells of the collision, and placed nowhere, came to help: no agent of the scene."""
    if not _help_placed_nowhere(e):
        return False
    crash = next((t.sentence for t in r.tokens if t.word in IMPACTS and t.index < e.said_at and not any(
        w.word in UNREAL_IMPACT for w in r.tokens[max(0, t.index - 3):t.index] if w.sentence == t.sentence)), None)
    return crash is not None and r.tokens[e.said_at].sentence > crash


CALLED_OUT = {"dispatched", "requested", "enroute", "attended", "responded", "summoned", "notified", "called",
              ("en", "route"), ("showed", "up"), ("turned", "up"), ("on", "scene"), ("came", "out"),
              ("on", "the", "way"), "needed", "required"}  # (not "came later": with no collision told, a later
# arrival is in the scene)
CALLED_FOR = {"call", "called", "calling", "phone", "phoned", "phoning", "ring", "rang", "ringing", "request",
              "requested", "requesting", "summon", "summoned", "dial", "dialled", "dialed", "need", "send"}
# "I called an ambulance", "I need police and an ambulance" (a caller asking for help)


def _called_out(r: _Reader, e: Entity) -> bool:
    """'EMS + PD dispatched 14:03', 'Trooper dispatched', 'Medic 4, Engine 2 en route', 'the cop who showed up later
    said', 'I called an ambulance': an emergency service placed nowhere and only called to the scene, or come after
    it, is no agent of it."""
    if not _help_placed_nowhere(e):
        return False
    sentence = r.tokens[e.said_at].sentence
    after = [t.word for t in r.tokens[e.said_at + 1:e.said_at + 10] if t.sentence == sentence]
    said = set(after) | set(zip(after, after[1:])) | set(zip(after, after[1:], after[2:]))
    before = {t.word for t in r.tokens[max(0, e.said_at - 5):e.said_at] if t.sentence == sentence}
    return bool(said & CALLED_OUT or before & CALLED_FOR)


def _said_parked(units: list[Unit], first: int, head: int) -> bool:
    """'parked' said of the noun, before it ('a row of parked cars') or right after it ('a line of cars parked')."""
    return any(u.tokens[0].word == "parked" for u in units[first:head + 2])


# After a person, words of what one says, knows, may do or was done to off the road ("the officer didn't ticket
# anybody", "the officer who took the report agreed", "people already forgot how to drive", "lady rang in").
OFF_THE_ROAD = {"should", "would", "could", "must", "might", "say", "says", "said", "had", "reckon", "reckons",
                "think", "thinks", "thought", "told", "tell", "tells", "ticket", "ticketed", "tickets", "cite",
                "cited", "fine", "fined", "arrest", "arrested", "charge", "charged", "book", "booked", "interviewed",
                "questioned", "wrote", "write", "blamed", "blame", "report", "statement", "statements", "agreed",
                "agree", "agrees", "forgot", "forget", "forgets", "forgotten", "know", "knows", "knew", "seem",
                "seems", "seemed", "learn", "learned", "learnt", "may", "need", "needs", "wish", "wishes", "can",
                "will", "shall", "ought", "choose", "consider", "nowhere", "rang", "rung", "phoned", "rings",
                "passenger", "called", "dialled", "dialed"}  # ("a passer-by called the police")


LOADED = (("on", "the", "back"), ("on", "the", "trailer"), ("on", "the", "flatbed"), ("on", "the", "bed"),
           ("on", "tow"), ("in", "tow"), ("on", "the", "low", "loader"), ("on", "the", "hook"))


def _a_load(r: _Reader, e: Entity) -> bool:
    """'with a tractor on the back', 'a Fiesta back to the garage on the back of the truck': a vehicle said a few
    words before it is placed on another's back or in tow is a load, no agent of the scene."""
    if e.said_at < 0:
        return False
    sentence = r.tokens[e.said_at].sentence
    after = [t for t in r.tokens[e.said_at + 1:e.said_at + 12] if t.sentence == sentence]
    words = [t.word for t in after]
    at = next((k for k in range(len(words)) for p in LOADED if tuple(words[k:k + len(p)]) == p), None)
    return at is not None and not any((lexicon().phrases.get((t.base,)) or ("",))[0] == "agents"
                                      for t in after[:at])  # (not "in the truck with a tractor on the back")


TELLING = {"told", "tell", "tells", "said", "say", "says", "asked", "ask", "asks", "complained", "complain",
           "complains", "wrote", "write", "writes", "reported", "report", "reports", "objected", "object", "objects",
           "reckons", "reckoned", "thinks", "thought"}


def _tells(r: _Reader, e: Entity) -> bool:
    """People whose own verb is one of telling ('residents told us that ...', 'parents have asked the council'):
    they speak of the place; what they tell of is not theirs to do."""
    after = [t.word for t in r.tokens[e.said_at + 1:e.said_at + 3] if t.sentence == r.tokens[e.said_at].sentence] \
        if e.said_at >= 0 else []
    return bool(after) and (after[0] in TELLING or after[0] in ("have", "has", "had") and after[1:2] and
                            after[1] in TELLING)


APPEALING = TELLING | {"appeal", "appealing", "appealed", "urge", "urging", "urged", "want", "wants", "warn",
                       "warning", "warned", "advise", "advising", "advised", "investigating", "investigate", "closed",
                       "close", "closing", "aware", "asking", "believe", "believes"}
AS_A_FORCE = {"police", "officers", "detectives", "the police"}  # the force, not a car of it


LATER_VERSIONS = {"later", "v2", "followup", "follow", "future", "eventually"}


def _left_for_later(r: _Reader, e: Entity) -> bool:
    """'Maybe add a police car later but not for v1', 'we could add a cyclist in a follow-up': one the request adds
    to a later version, placed nowhere and doing nothing, is not in this scene."""
    if e.said_at < 0 or e.features or any(a[4] != "move" for a in e.actions):
        return False
    sentence = r.tokens[e.said_at].sentence
    before = [t.word for t in r.tokens[max(0, e.said_at - 4):e.said_at] if t.sentence == sentence]
    after = {t.word for t in r.tokens[e.said_at + 1:] if t.sentence == sentence}
    return bool({"add", "adding"} & set(before)) and bool(after & LATER_VERSIONS)


def _police_as_a_source(r: _Reader, e: Entity) -> bool:
    """'Police are appealing for witnesses', 'Leicestershire Police say they are aware', 'Police have closed Bank
    Street': a news item's police, placed nowhere and doing nothing on the road, speak of the scene or act off it."""
    if e.type != "police" or e.head not in AS_A_FORCE or not _help_placed_nowhere(
            e, ignoring=frozenset({"bare_left", "bare_right", "side_left", "side_right"})):
        return False  # (a side the sentence gives later, "drivers are being sent left", places no police)
    after = [t.word for t in r.tokens[e.said_at + 1:e.said_at + 3] if t.sentence == r.tokens[e.said_at].sentence]
    after = after[1:] if after[:1] and after[0] in ("are", "is", "have", "has", "had", "were", "was") else after
    return bool(after) and after[0] in APPEALING


def _said_to_do_no_road_thing(r: _Reader, e: Entity) -> bool:
    """A person whose sentence, after them and before any comma, goes on with a modal, a report or a past
    perfect ('someone should fix that junction', 'the workers at the depot say') and gives them nothing to do
    on the road: no one of the scene."""
    if e.said_at < 0:
        return False
    sentence = r.tokens[e.said_at].sentence
    after = []
    for t in r.tokens[e.said_at + 1:]:
        if t.sentence != sentence or t.word == ",":
            break
        after.append(t.word)
    before = {t.word for t in r.tokens[max(0, e.said_at - 4):e.said_at] if t.sentence == sentence}
    return bool(set(after[:5]) & OFF_THE_ROAD) or bool(before & {"why", "whether", "wondered", "asked"})
    # ("my son asked why the man was so angry": a man in a question reported, no one on the road)


def _waits_where_people_wait(r: _Reader, e: Entity) -> bool:
    """A person said at a bus or tram stop, a shelter or the kerb in the sentence that names them: on foot."""
    if e.said_at < 0:
        return False
    words = [t.word for t in r.tokens if t.sentence == r.tokens[e.said_at].sentence]
    pairs = set(zip(words, words[1:]))
    return bool(pairs & {("bus", "stop"), ("tram", "stop"), ("bus", "shelter")}) or \
        bool(set(words) & {"kerb", "curb", "pavement", "sidewalk", "footpath"})


def _the_riders_own(units: list[Unit], head: int, first: int, lo: int, words: set[str]) -> bool:
    """'my bike', 'on the bike', 'just me and (the) bike', 'in front of me on bike', 'I'm turning left on a
    scooter': the speaker's own, not a bike somewhere ahead."""
    after_me = first >= 2 and units[first - 2].tokens[-1].word in ("me", "i")  # "in front of me on bike"
    someone_before = first >= 2 and units[first - 2].category == "agents" and units[first - 2].meaning != "ego"
    speaker = max((k for k in range(first - 1) if units[k].tokens[-1].word in ("i", "i'm")), default=None)
    return "my" in words or first > lo and units[first - 1].word == "on" and not someone_before and (
        "the" in words or not words or words <= {"a", "an"} and speaker is not None and not any(
            x.category in ("agents", "comma", "positions") for x in units[speaker + 1:first - 1]) and (
            head + 1 == len(units) or units[head + 1].category != "positions")) or \
        words <= {"the"} and first >= 2 and units[first - 1].word == "and" and after_me and \
        (head + 1 == len(units) or units[head + 1].category != "positions")


NONE_VALUES = {"none", "no", "0", "zero", "nil", "n/a", "na", "nobody", "nothing"}
STREET_BEFORE = {"on", "onto", "along", "down", "up", "into", "off"}  # a street's name follows with no article


def _resolve(r: _Reader, units: list[Unit], head: int, lo: int, stage: int, recent: list[Entity]) -> NounPhrase:
    u = units[head]
    r.mark(u)
    kind, is_ego = _agent_type(u)
    if u.base == "wagon" and any(e.is_ego and e.type == "truck" for e in r.entities):
        kind = "truck"  # "me leading in the DAF and two more wagons off the same yard": a trucker's lorries
    count, first, words, modifiers = _count_before(units, head, lo)
    if first > lo and units[first - 1].word == "not" and (words & {"a", "an", "single", "another"} or count == 1) and \
            not is_ego:
        count = 0  # "there isn't a car around", "not one car in sight", "not a single pedestrian"
    if first > lo and units[first - 1].word == "without" and not words - {"any", "a", "an", "other", "single"} and \
            not is_ego and count in (None, 1):
        count = 0  # "an empty road without any pedestrians", "without other traffic"
    if first > lo + 2 and [x.word for x in units[first - 3:first]] in (["no", "need", "for"], ["not", "need", "any"]) \
            and not is_ego:
        count = 0  # "no need for NPC pedestrians in this one", "we don't need any cyclists"
    if not is_ego and first == head and head > lo and units[head - 1].word in STREET_BEFORE and \
            len(u.tokens) == 1 and u.base not in KIND_NOUNS and u.base not in bodies() and \
            kind not in V.VULNERABLE_TYPES:
        return NounPhrase(None, head, first)  # "going to the hospital on Lincoln", "turned onto Ford": a street
        # named for a maker, no vehicle ("a guy on a Harley" has its article)
    value = u.tokens[-1].index + 1
    if not is_ego and value < len(r.tokens) and r.tokens[value].opened_by == ":" and \
            r.tokens[value].sentence != u.tokens[-1].sentence and r.tokens[value].word in NONE_VALUES:
        count = 0  # "pedestrians: none", "cyclists: 0": a key said to have no value
    if first > lo + 1 and units[first - 1].base in ("see", "spot", "meet", "pass", "notice") and \
            units[first - 2].word in ("not", "never") and not is_ego and count in (None, 1) and \
            not words - {"any", "a", "an", "other", "single", "one", "another", "some"} and not (
                not words & {"any", "other", "single", "one", "another", "some"} and head + 1 < len(units) and
                units[head + 1].category in ("actions", "positions")):
        count = 0  # "didn't see one other car", "never met a single cyclist" (not "did not see a van approaching
        # from the left": one there, unseen)
    for k in range(first, head):
        if units[k].category in ("word", "numbers", "number"):
            r.mark(units[k])
    plural = u.tokens[-1].plural and not is_ego
    if r.typical and plural and count is None and not words:
        plural = False  # "drivers turning left cut across cyclists": one of each kind, as the scene to test
    if words & {"neither", "either"} and not plural and not words & {"the", "a", "an"}:  # (not "neither the cyclist
        # nor the car": one each)
        words, plural = (words - {"neither", "either"}) | {"both"}, True  # "neither vehicle slows": the two named
    owner = first - 1  # "our little Fiat", "the ego's electric hatch": over the adjectives to whose it is
    while not words and owner > first - 3 and owner > 0 and units[owner].category == "word" and \
            units[owner].word not in OWNERS | DETERMINERS | AUXILIARIES | {"there", "here"}:
        owner -= 1
    owners = words & OWNERS or ({units[owner].word} & OWNERS if not words and owner >= 0 and
                                units[owner].category == "word" else set())
    speakers = owners & {"my", "our"} or not words and owner >= 0 and (
        units[owner].category == "agents" and units[owner].meaning == "ego" and units[owner].tokens[-1].possessive)
    fleet = first
    while fleet > lo and units[fleet - 1].category == "word" and units[fleet - 1].word not in OWNERS | DETERMINERS:
        fleet -= 1  # "one of our (big) artics"
    at_its_wheel = fleet >= 5 and units[fleet - 4].word in ("in", "driving", "of") and \
        units[fleet - 5].category == "agents" and units[fleet - 5].meaning == "ego"
    fleets_one = plural and kind in V.EGO_TYPES and fleet >= 3 and [x.word for x in units[fleet - 3:fleet]] in (
        ["one", "of", "our"], ["one", "of", "my"]) and (at_its_wheel or not any(
            e.is_ego and not _supplied(r, e) for e in r.entities))
    # "(the driver in) one of our artics": the fleet's vehicle the scene is told from; an ego supplied before for a
    # heading's verb with no subject ("Lane-change reminder.") is that vehicle
    if fleets_one:
        is_ego, plural = True, False
    ridden = u.base in ("bike", "motorbike", "moped", "scooter", "motorcycle", "e scooter", "electric scooter") or \
        kind == "motorcycle" and not u.base.endswith(("ist", "er", "rider", "courier", "cop"))  # "on the GS", "my
    # Bonneville": a machine (and "on the e-scooter": the rider's own)
    on_the_bike = ridden and not plural and count is None and \
        _the_riders_own(units, head, first, lo, words) and any(t.word in ("i", "me", "my", "i'm", "we", "us", "our")
                                                               for t in r.tokens) and \
        not any(e.is_ego and e.type not in ("car", "motorcycle") for e in r.entities)
    if on_the_bike:  # "coming up to the junction on the bike", "just me and the bike": the rider's own; one who speaks
        is_ego, kind = True, "motorcycle"  # cannot be a cyclist ego, so the bike is a motorbike
    if not is_ego and not plural and speakers and kind in V.EGO_TYPES and count is None and \
            u.meaning != "none" and not any(t.possessive for k in range(first, head) for t in units[k].tokens):
        is_ego = True  # "my little Fiat", "our battered old van": the speaker's own vehicle, however described
    if not is_ego and not plural and count is None and kind == "bus" and words == {"the"} and \
            "driver" in [t.word for t in r.tokens[u.tokens[-1].index:u.tokens[-1].index + 2]] and \
            any(t.word in ("us", "we", "our") for t in r.tokens) and \
            not any(e.type == "bus" for e in r.entities) and \
            not (head + 1 < len(units) and units[head + 1].category == "positions") and \
            all(e.head in SPEAKERS | FIRST_PERSON or _supplied(r, e) for e in r.entities if e.is_ego):
        is_ego = True  # "a lorry swung across our front, and the bus driver slammed on": the bus we were on
    if plural and count == 1 and "of" in words and words & DEFINITE and head > first and \
            units[first].category == "numbers" and units[first].word == "one":
        plural, count = False, None  # "one of the other cars": a member of the group named before
        words = words - {"of"}
    if is_ego:
        ego = next((e for e in r.entities if e.is_ego), None)
        if ego is None:
            ego = Entity(r.new_key(), kind, True, stage, head=u.base)
            r.entities.append(ego)
        elif kind != "car" and ego.type == "car":
            ego.type = kind
        ego.aliases.add(u.base)  # every name the ego is given ("an automated shuttle bus ... the shuttle")
        _ego_listed_in_a_group(r, ego, units, first)
        for m in modifiers:
            if m.category == "actions" or m.category == "positions" and m.meaning.startswith("compass_"):
                _modify(r, ego, m, stage, strength=1)  # "a cyclist overtakes the stationary ego": it stands;
                # "the northbound ego": its heading
        return NounPhrase(ego, head, first)
    if not is_ego and _scenery_only(units, head):
        return NounPhrase(None, head, first)  # "passengers waiting at the stop: scenery only"
    if u.meaning == "none":  # "stopped with flashing lights": no agent, and no claim on the verb before it
        return NounPhrase(None, head, head if units[first].category == "actions" else first)
    if count == 0:  # "no other vehicles"
        return NounPhrase(None, head, first)
    if count is not None and plural and u.base in ("car", "vehicle") and first > 0 and \
            units[first - 1].category == "agents" and units[first - 1].meaning not in ("ego", "none") and \
            head + 1 < len(units) and units[head + 1].category == "positions" and \
            units[head + 1].meaning in ("ahead", "behind"):
        return NounPhrase(None, head, first)  # "a van two cars ahead of me": how far ahead it is, no cars named
    told_to = "your" in owners and any(t.word == "i" for t in r.tokens)  # "I had to drive your grandfather": the
    # listener's kin, as a teller speaks to them
    if ((owners - {"your"} or told_to) and u.tokens[-1].base in KIN or not words and first == head and
            u.tokens[-1].word in KIN_NAMES) and not _on_foot_in_the_scene(units, head) and \
            not _on_foot_with_someone(units, first):
        return NounPhrase(None, head, first)  # "taking my mother to her appointment": a passenger, no agent;
        # "mom said no more driving": kin named as a name, by a text's writer
    carried = kind == "pedestrian" and count is None and next(
        (how for k in range(first, head + 1) if (how := _carried(r.tokens, units[k].start, u.end))), "")
    if carried == "held" or carried and not _on_foot_in_the_scene(units, head):
        return NounPhrase(None, head, first)  # "a school bus stopped ahead, picking kids up": its passengers;
        # "a woman carrying a child crossed": the child is held, on foot only through her ("drops off two kids in
        # front of the ego": counted, they are put in the scene)
    if plural and u.tokens[-1].possessive and count is None and head + 1 < len(units) and \
            units[head + 1].word in PEOPLES_PLACES:
        return NounPhrase(None, head, first)  # "on the zebra by the infants' school": a place named for them
    if u.tokens[-1].word in ("people", "folks") and (count is None or "some" in words) and \
            not words - {"some", "the", "other"} and \
            not any(m.category == "actions" for m in units) and not _on_foot_in_the_scene(units, head):
        return NounPhrase(None, head, first)  # "some people behind us were mad": uncounted, doing nothing on foot
        # and nothing done to them ("nearly hit people": they were on the road)
    if u.tokens[-1].word in ("people", "folks", "drivers", "motorists") and count is None and not words and \
            _minds_a_thing(units, head):
        return NounPhrase(None, head, first)  # "so people can see what the driver sees", "drivers never look"
    if plural and count is None and not words and not is_ego and any(
            units[k].base in SYSTEM_SKILLS for k in (first - 1, first) if 0 <= k < head):
        return NounPhrase(None, head, first)  # "isn't it supposed to detect emergency vehicles now?": any such
    if not is_ego and count is None and head + 1 < len(units) and units[head + 1].word in TALLIED:
        return NounPhrase(None, head, first)  # "log all emergency vehicle incidents": a kind of record, no agent
    if not is_ego and kind in V.EMERGENCY_TYPES and count is None and _services_called(units, first):
        return NounPhrase(None, head, first)  # "I need police and an ambulance": a service called, not on the road
    if plural and count is None and words == {"all"} and not is_ego and \
            u.tokens[-1].word in ("drivers", "riders", "motorists", "staff", "operators", "crews"):
        return NounPhrase(None, head, first)  # "SAFETY MEMO - all drivers": those it is addressed to
    if plural and count is None and not words and not is_ego and _owned_by_all(units, head):
        return NounPhrase(None, head, first)  # "truck drivers have huge blind spots": road users in general
    if not plural and count is None and words & {"the", "this", "that"} and kind == "pedestrian" and \
            u.base not in NAMED_ON_FOOT and not any(e.type == "pedestrian" for e in r.entities) and \
            _minds_a_thing(units, head) and not any(m.category == "actions" and m.meaning != "try"
                                                     for m in units[head + 2:]):
        return NounPhrase(None, head, first)  # "the traffic warden saw nothing": one who saw or said, no agent
    if not plural and count is None and words <= {"the", "reporting", "attending"} and first == lo and \
            u.base in WATCHERS and head + 2 < len(units) and units[head + 1].tokens[0].base in PERCEIVING and \
            (units[head + 2].word in INDEFINITE | {"two", "three", "four"} or units[head + 2].category == "agents"):
        return NounPhrase(None, head, first)  # "Officer observed a motorcycle in the right lane ... overtaking": the
        # one who reports what was seen, no one on the road
    if u.tokens[-1].word in ("people", "folks", "drivers", "motorists") and count is None and \
            not words - {"of"} and first > 0 and (units[first - 1].word in GENERIC_AFTER or units[first].word == "of") \
            and not _of_a_group(units, first):
        return NounPhrase(None, head, first)  # "a yield sign for people entering", "you hear about people doing that"
    if u.base in RIDDEN and first > lo and units[first].word in POSSESSIVES and \
            units[first - 1].base in PUSHED_ALONG:
        return NounPhrase(None, head, first)  # "a lad pushing his bike across": a pedestrian, the bike his
    loosely = next((e for e in reversed(r.entities) if not e.is_ego and e.type != kind and
                    e.head in loose_names().get(u.base, frozenset())), None) \
        if words & {"second", "another", "other"} and not plural else None
    if loosely is not None and not any(e.type == kind and not e.is_ego for e in r.entities):
        kind = loosely.type  # "the motorcycle coming from my left ... with a second bike right behind him"
    said_again = _it_was_a(r, units, first, recent)
    if said_again is not None:
        said_again.type, said_again.head = kind, u.base
        return NounPhrase(said_again, head, first)  # "a car, well actually it was a van,": the van said again
    if _names_the_case(r, units, head, kind):
        return NounPhrase(None, head, first)  # "stopped veh scenario. Soft target (sedan) parked...": the case's name
    if u.base in RIDDEN and units[first].word in POSSESSIVES:
        rider = next((e for e in reversed(recent) if not e.is_ego and e.type == kind), None)
        if rider is not None:
            return NounPhrase(rider, head, first)  # "a cyclist ... no lights on his bike": the cyclist's own
    label = u.tokens[-1].label
    if label:
        named = next((e for e in r.entities if e.label == label), None) or next(
            (e for e in r.entities if e.headline and not e.label and not e.features & HEADLINE_PLACES
             and e.type == kind and not plural and not words and count is None), None)
        if named is not None:  # "Jaywalker mid-block. Ped_1 crosses ...": the one the heading named, now by name
            named.label = named.label or label
            return NounPhrase(named, head, first)
        if first == 0 and not plural and count is None and any(
                not e.is_ego and e.group_open > 0 and (e.type == kind or e.generic) for e in r.entities):
            found = _existing(r, kind, u.meaning == "generic", False, False, False, recent)
            if found:  # (none when the open group is out of reach of 'recent')
                found[0].label = label  # "Three cars drive ahead. Car_1 brakes hard": one of the three, by its name
                return NounPhrase(found[0], head, first)
    if count is not None and plural and _vague_part_of_the(units, first, head):
        count, words = None, words - {"some"}  # "a group of the children", "some of the kids": those said before
    if count is not None and count > 1 and not plural and words & {"some", "any"}:
        count = 1  # "some car suddenly cuts in"
    definite = bool(words & (DEFINITE | {"both", "other", "its", "their"})) and not words & {"another", "a", "an"}
    if "more" in words and "than" in words and count is not None:
        count += 1
    if count is not None and 1 < count < TOO_LARGE and words & {"some", "more"}:  # "a few", "more than ten"
        count = UNSPECIFIED.vague_count(count, len(r.entities))
    bare = not words and count is None and not plural and not label and not (
        head + 1 < len(units) and units[head + 1].category == "positions" and not (
            first > 0 and units[first - 1].tokens[-1].word == "of")) \
        and not _what_a_label_names(units, first)
    # ("car opposite waiting": another; "ped crosses in front of bus from the right": the bus named before)
    placed_by = _place_in_the_name(units, head, first)
    doing = units[head + 1].meaning if first == lo and head + 1 < len(units) and \
        units[head + 1].category == "actions" and units[head + 1].tokens[0].word.endswith("ing") else None
    listed = doing is not None and any(x.category == "positions" for x in units[head:])
    # "car cutting in from the left lane": a terse list's item, an agent with its own verb and place
    placed_here = _placed_in_its_sentence(r, u) if first == lo else set()
    if words and words <= ORDINAL_MEMBERS and count is None and not plural and \
            any(not e.is_ego and (e.parent is not None or e.count > 1) and e.type == kind for e in r.entities):
        definite = True  # "two cars from the right ... went after 2nd car": the second of them, articles dropped
    described = next((m.meaning for m in modifiers if m.category == "actions"), None)  # "revealing stopped car":
    # a state said before the noun sets it apart from one named before doing otherwise
    # "Ego car: stopped. Car: front, stationary", "Ambulance: behind. Van: stopped, ahead": a note's item, placed
    if bare and any((e.head.split()[-1] == u.base.split()[-1] and e.type == kind and not (
                        " " in u.base and " " in e.head and u.base != e.head) or u.base in e.aliases or
                     (_clipped(u.base, e.head) or e.head.split()[0] == u.base) and e.type == kind) and not e.is_ego
                    and e.count == 1 and (placed_by is None or placed_by in e.features)
                    and not (doing and e.actions and doing not in {a[4] for a in e.actions})
                    and not (described and described not in {a[4] for a in e.actions})
                    and not _placed_apart(placed_here, e) for e in r.entities):
        definite = True  # "ego behind cyclist, cyclist swerves left", "a white van ... behind van", "a lead vehicle
        # ... lead slams on": the same one; not "kid dummy ... adult dummy";
        # not "oncoming car turning left, lead car braking": a place in the name sets another apart; not "lead
        # car braking, car cutting in", "a pedestrian crossing; pedestrian waiting": an item that does another thing
    if not words and count is None and plural and not label and any(
            not e.is_ego and e.count > 1 and e.head.split()[-1] == u.base.split()[-1] and
            not _placed_apart(placed_here, e) for e in r.entities):
        definite = True  # "three kids crossing in front of it ... even if kids look clear": the kids said before
    loose = loose_names().get(u.base, frozenset())
    if bare and loose and not any(e.type == kind and not e.is_ego for e in r.entities) and any(
            not e.is_ego and e.count == 1 and (e.head in loose or e.head.split()[-1] in loose) and
            not _placed_apart(placed_here, e) for e in r.entities):
        definite = True  # "Pickup ahead of me. Truck braked": the pickup, in note style
    of_its_kind = [e for e in r.entities if e.type == kind and not e.is_ego]
    if bare and u.base == kind and kind in ("motorcycle", "cyclist", "truck", "bus") and len(of_its_kind) == 1 and \
            of_its_kind[0].count == 1 and not _placed_apart(placed_here, of_its_kind[0]):
        definite = True  # "reports motorcyclist ... darted into lane 2 ... M/C continued NB": the one of its kind,
        # named again by its kind in note style
    speaker_ego = next((e for e in r.entities if e.is_ego and (e.head in SPEAKERS | {"i'm"} or e.aliases & SPEAKERS)),
                       None)  # ("FSD did something sketchy ... I'm in the middle lane": named first by its system)
    named_ego = next((e for e in r.entities if e.is_ego and e.type == "car"), None)
    if bare and first == lo and (u.base in ("car", "vehicle") and speaker_ego is not None or
                                 u.base == "vehicle" and named_ego is not None) and not placed_here and \
            not listed and not any(not e.is_ego and e.type == "car" for e in r.entities):
        definite = True  # "I'm in the middle lane ... Car braked and moved over": the speaker's car, note style;
        # "AV turning right ... vehicle waited for them": the AV, as an operator's log names it again
    ego_of_kind = next((e for e in r.entities if e.is_ego and e.type == kind), None)
    if bare and ego_of_kind is not None and kind in ("bus", "truck") and not placed_here and \
            not listed and _names_the_ego_again(r, ego_of_kind, u.base) and \
            not any(not e.is_ego and e.type == kind for e in r.entities):
        definite = True  # "subject = route 7 bus ... SB still red, bus still held": the ego, in a log's note style
    if bare and u.base in RIDING_PEOPLE and any(e.type in V.TWO_WHEELER_TYPES for e in r.entities):
        definite = True  # "cut off a cyclist. Guy was riding straight": the rider, named as a texter names him
    if bare and u.base in ("driver", "rider") and any(not e.is_ego and e.type not in V.VULNERABLE_TYPES
                                                      for e in r.entities):
        definite = True  # "Broken-down HGV on the shoulder. Driver has got out": its driver, in note style
    if not words and count is None and not plural and not label and head + 1 < len(units) and \
            units[head + 1].category == "positions" and any(
                (e.head.split()[-1] == u.base.split()[-1] or e.type == kind and
                 {e.head.split()[-1], u.base} <= {"car", "vehicle"}) and not e.is_ego and e.count == 1 and
                (units[head + 1].meaning in e.features or e.head.split()[-1] == u.base.split()[-1] and
                 not e.features & PLACE_FEATURES and not e.actions) and
                not (described and described not in {a[4] for a in e.actions})
                for e in r.entities):
        definite = True  # "Ego: follows HGV. Actors: HGV ahead in the ego lane": the HGV already placed there;
        # "Lead vehicle braked ... car in front slammed on": a car and a vehicle, one in that place; "Actors: ego,
        # truck. Positions: truck ahead of ego": the truck only listed before, placed now
    if not words and count is None and not plural and not label and head + 1 < len(units) and \
            units[head + 1].category == "positions" and u.base not in GENERAL_BODIES and any(
                u.base in e.aliases and not e.is_ego and e.count == 1 and not e.features & PLACE_FEATURES
                for e in r.entities):
        definite = True  # "a white Silverado pickup cut me off ... 0:22 Silverado in the right lane swerves": its
        # make, named again where it was not yet placed
    ego_now = next((e for e in r.entities if e.is_ego), None)
    existential = first >= 2 and units[first - 2].word == "there" and units[first - 1].word in (
        "is", "was", "be", "comes", "came")  # "there's car coming the other way": introduced, never the ego
    if bare and placed_by is None and ego_now is not None and u.base in ("vehicle", "car") and (
            u.base in ego_now.head.split() and len(ego_now.head.split()) > 1) and not existential and \
            not any(not e.is_ego and e.type == "car" for e in r.entities) and not listed and not placed_here:
        return NounPhrase(ego_now, head, first)  # "in front of vehicle", "vehicle's front left corner": the ego;
        # "my car turns right, car cutting in from the left": a list's item, another car
    if words <= {"of", "from", "in"} and count is None and not plural and not label and ego_now is not None and \
            u.base in ("vehicle", "car") and head - 2 == lo and \
            [x.word for x in units[head - 2:head]] in (["out", "of"], ["walked", "from"], ["trapped", "in"]) and \
            not any(not e.is_ego and e.head.split()[-1] in ("car", "vehicle") for e in r.entities):
        return NounPhrase(ego_now, head, first)  # a handover's "Out of car unaided", "Walked from vehicle": the
        # patient's own, the ego, with its subject and article dropped
    if (bare and first == head or definite and words <= {"the"} and first == head - 1) and first == lo and \
            ego_now is not None and kind != "car" and ego_now.type == kind and count is None and not plural and \
            not existential and not listed and not placed_here and \
            not any(not e.is_ego and e.type == kind for e in r.entities):
        return NounPhrase(ego_now, head, first)  # "Subject: a city bus in the centre lane ... Bus braked": the ego,
        # named again by its type, as a note does
    if definite and words <= {"the"} and u.base == "vehicle" and ego_now is not None and ego_now.type != "car" and \
            count is None and not plural and not existential and not any(
                not e.is_ego and e.type in V.EGO_TYPES for e in r.entities):
        return NounPhrase(ego_now, head, first)  # "the ego minibus ... a pedestrian walked across in front of the
        # vehicle": the only vehicle there is, whatever its kind
    if ego_now is not None and u.base == "vehicle" and head > 0 and units[head - 1].word in DRIVER_CONTROLS and \
            count is None and not plural and not label and not any(not e.is_ego and e.type == "car" for e in r.entities):
        return NounPhrase(ego_now, head, head)  # "operator kept vehicle stopped": the one at the controls drives it
    if words <= {"the", "my", "our"} and words and count is None and not plural and kind in V.EGO_TYPES and \
            _handled_by_the_speaker(r, units, first) and \
            not (head + 1 < len(units) and units[head + 1].category in ("positions", "agents")):
        ego = _ego_entity(r, stage)  # "Semi pulled over on the shoulder. I moved the truck over a lane": the
        ego.type = kind if kind != "car" else ego.type  # speaker's own, though a truck was named before
        return NounPhrase(ego, head, first)
    vehicle_left = None  # the vehicle a driver is said to get out of
    predicate = first > 0 and units[first - 1].word in COPULAS | {"be", "being", "been"}  # "whom I know to be the
    # driver of the HGV": says who the man is; he is not the HGV
    if predicate and u.base in ("driver", "rider", "motorist") and not plural:
        return NounPhrase(None, head, first)
    if first >= 3 and units[first - 3].word in COPULAS and [x.word for x in units[first - 2:first]] == ["the", "only"] \
            and not plural:
        return NounPhrase(None, head, first)  # "the child is the only adversarial agent in this scenario": a role
    if definite and count is None and u.base in ("driver", "rider", "motorist") and not plural and \
            _gets_out(units, head):  # "the driver gets out and walks across": a person on foot now
        kind, definite = "pedestrian", False
        vehicle_left = _last_named(r, recent, lambda e: not e.is_ego and e.type not in V.VULNERABLE_TYPES)
    if definite and count is None and u.base in ("driver", "rider", "motorist") and not plural:
        driven = _last_named(r, recent, lambda e: not e.is_ego and e.type != "pedestrian" and not (
            e.type == "cyclist" and u.base != "rider"))  # ("the driver behind": no cyclist's)
        place = next((x for x in units[head + 1:head + 3] if x.category == "positions"), None)
        if driven is not None and place is not None and place.meaning in ("behind", "ahead") and \
                (place.tokens[-1].word in SPEAKERS and place.meaning not in driven.features or
                 _placed_by_one_named_before(units, head + 1, ("it", "them", "him", "her"))):
            driven = None  # "waited for a motorcyclist on the road to the left. The driver waiting behind us
            # honked": another, placed by the speaker where the one named before is not; "the learner driver behind
            # him stopped": another, placed by the one named before
        if driven is not None:  # "a coach came from the right ... The driver didn't indicate": the coach's driver
            return NounPhrase(driven, head, first)
        own = next((e for e in r.entities if e.is_ego and e.type not in V.VULNERABLE_TYPES), None)
        if own is not None and not any(not e.is_ego and e.type != "pedestrian" for e in r.entities) and \
                u.base == "driver" and (own.aliases - {own.head} or own.head not in SPEAKERS | FIRST_PERSON):
            return NounPhrase(own, head, first)  # "put the camera in the lorry ... what the driver sees": its driver
        if own is None and u.base == "driver" and not any(e.type != "pedestrian" for e in r.entities) and \
                "other" not in words and not any(t.word == "ego" for t in r.tokens) and \
                (head + 1 >= len(units) or units[head + 1].word != "of" and units[head + 1].category != "positions"):
            return NounPhrase(_ego_entity(r, stage), head, first)  # "a child runs out from between parked cars on
            # the driver's right, and the driver cannot stop in time": the one the case is told from
    at_the_wheel = _driven_by(r, units, head, recent) if count is None and not plural else None
    if at_the_wheel is not None:  # "a box truck ... the woman driving it stopped": the truck, by its driver
        return NounPhrase(at_the_wheel, head, first)
    if (definite or _article_dropped(r, units, first, words)) and count is None and not plural and \
            u.base in DRIVING_PEOPLE and not _gets_out(units, head) and not _on_foot_in_the_scene(units, head) and \
            not any(e.type in V.VULNERABLE_TYPES for e in r.entities) and \
            (head + 1 == len(units) or units[head + 1].category != "positions"):
        driven = _last_named(r, recent, lambda e: not e.is_ego and e.type not in V.VULNERABLE_TYPES)
        if driven is not None:  # "a taxi pulled out ... the guy never looked": nobody on foot named, its driver
            return NounPhrase(driven, head, first)
    crewed = _crewed_vehicle(r, units, head, first, recent, definite or not words) if count is None else None
    if crewed is not None:  # "a police car ... the officers pulled me over", "a motorbike ... the biker": its own
        return NounPhrase(crewed, head, first)
    if definite and count is None and u.base in RIDING_PEOPLE and not plural and \
            not any(e.type == "pedestrian" for e in r.entities):
        rider = _last_named(r, recent, lambda e: e.type in V.TWO_WHEELER_TYPES)
        if rider is not None:  # "a cyclist swerving in the bike lane ... until the guy turned right": the rider
            return NounPhrase(rider, head, first)
    counted = _counted_again(r, kind, u.base, count) if definite and count is not None and count > 1 else None
    if counted:  # "Two lads dash onto the crossing ... the two lads run out": the same two
        return NounPhrase(counted[0], head, first, plural=True, group=counted if len(counted) > 1 else [])
    pair = _the_two_told_of(r, units, first, u.base) if definite and count == 2 else []
    if pair:
        return NounPhrase(pair[0], head, first, plural=True, group=pair if len(pair) > 1 else [])
    if definite and count is None and r.owned and u.base == "vehicle" and not plural and ego_now is not None and \
            (head + 1 == len(units) or units[head + 1].category != "positions"):
        return NounPhrase(ego_now, head, first)  # "I own a GMC Terrain ... then the vehicle braked by itself"
    adversarial = any(t.word == "adversarial" for k in range(first, head + 1) for t in units[k].tokens)
    if definite and adversarial and not any("adversarial" in e.aliases for e in r.entities):
        definite = False  # "behind a stopped bus ... the adversarial vehicle in the left lane swerves": the benchmark
        # names its adversary with 'the' the first time
    said_after = units[first].tokens[0].index
    if words == {"this"} and count is None and not plural and said_after > 0 and r.tokens[said_after - 1].word in (
            "then", "suddenly", "and", "when", "until", "till", "but", "next") and not any(
            u.base == e.head or u.base in e.aliases or e.head.split()[-1] == u.base for e in r.entities):
        definite = False  # "a pair of kids head across ... then this guy comes running": a teller's 'this'
        # brings in one not named before
    if definite and count is None and kind == "pedestrian" and not plural and _on_a_machine(units, head):
        definite = False  # "two kids and their mum crossing ... the guy on the moped behind me": its rider, no one
        # on foot named before
    if definite and count is None:
        found = _existing(r, kind, u.meaning == "generic" or u.base == "vehicle", plural, "other" in words,
                          "both" in words, recent, u.base) or _named_by_its_make(r, u)
        first_named = next((e for e in r.entities if e.is_ego and f"the {u.base}" in e.aliases), None)
        if first_named is not None and words == {"the"} and not plural and not modifiers and not any(
                not e.is_ego and (e.head.split()[-1] == u.base or u.base in e.aliases) for e in r.entities):
            found = [first_named]  # "the car comes to a stop ... a minivan arrives ... then the car proceeds": the
            # ego, by the very name it was first given (not the minivan named last)
        placed_after = units[head + 1].meaning if head + 1 < len(units) and units[head + 1].category == "positions" \
            else None
        there = [e for e in r.entities
                 if not e.is_ego and e.type == kind and e.count == 1 and placed_after in e.features]
        if len(found) == 1 and placed_after not in found[0].features and len(there) == 1:
            found = there  # "1 car ahead, 1 car level with the ego ... the car level with the ego cuts in": that one
        if len(found) == 1 and not found[0].parent and (_placed_elsewhere(found[0], units, head) or (
                found[0] in r.clause_mentions and head + 1 < len(units) and units[head + 1].category == "positions")):
            found = []  # "a car ahead ... the car behind us", "the car from the left and the car from the right"
        said_places = {m.meaning for m in modifiers if m.category == "positions"} & {"road_straight", "toward",
                                                                                     "road_left", "road_right"}
        if len(found) == 1 and said_places and not said_places & found[0].features and not found[0].is_ego:
            found = []  # "a car is waiting to turn ... once the oncoming car has gone by": another car
        if len(found) == 1 and u.base.split()[0] in ("lead", "leading") and "ahead" not in found[0].features and \
                found[0].features & {"level", "behind", "side_left", "side_right", "road_straight"}:
            found = [e for e in r.entities if not e.is_ego and e.count == 1 and e.head.split()[0] in (
                "lead", "leading")][-1:]  # "a van alongside on the left, while the lead car brakes": the one
            # ahead is another, the lead named before if there is one
        if found:
            if len(found) == 1:
                found[0].aliases.add(u.base)  # "a woman ... the pedestrian": every name it is given
                return NounPhrase(found[0], head, first, plural=plural)
            return NounPhrase(found[0], head, first, plural=True, group=found)
        ego = next((e for e in r.entities if e.is_ego), None)
        after = head + 1
        while after < len(units) and _sentence_adverb(units[after]):
            after += 1  # "the car still has to deal with him", "the car just holds its line"
        nxt = units[after] if after < len(units) else None
        if ego is not None and not plural and kind == ego.type and "other" not in words and \
                not _picked_out_by_what_it_did(r, u) and not _the_teller_afoot(ego) and \
                not (first > 0 and units[first - 1].word in LETTING and ego.head in SPEAKERS) and \
                not any(m.category == "positions" for m in modifiers) and (  # ("the oncoming car": another)
                u.base in GENERAL_BODIES or u.base in bodies() and _named_by_a_vehicle_noun(ego) or
                _names_the_ego_again(r, ego, u.base)) and not _measured_by_others(units, after) and (
                nxt is None or nxt.category not in ("positions", "word") or nxt.word in AUXILIARIES
                or _anothers_siren(r, units, after) or u.tokens[-1].possessive or _past_tense_verb(nxt)
                or _verb_before_its_object(units, after)
                or first > 0 and units[first - 1].tokens[0].base in CONTROLLING or
                first > 0 and units[first - 1].category == "positions" and u.base not in GENERAL_BODIES and
                _names_the_ego_again(r, ego, u.base)):  # "our ego, a green hatchback, ... a motorcycle riding
            # alongside the hatchback in the lane to its left": the place is the motorcycle's
            return NounPhrase(ego, head, first)  # "The test car turns right ... The car had to stop", "the
            # system holds the car in place"
        if ego is None and not plural and bodies().get(u.base) == "car" and "other" not in words and \
                not _measured_by_others(units, after) and not any(
                    m.category == "positions" or m.word == "parked" for m in modifiers) and \
                not any(not e.is_ego and e.type not in V.VULNERABLE_TYPES for e in r.entities) and \
                (nxt is None or nxt.category != "positions") and \
                not _ego_object_follows(units, head) and not _placed_by_the_ego_in_its_relative(r, u) and \
                not _ego_named_later_in_the_sentence(r, u):
            # ("the car overtakes us": the ego is named after it, so the car is another; "a pedestrian starts across
            # ... it brings the car to a stop": no other vehicle, the car is the ego; "the oncoming car", "the parked
            # car": placed against the one the scene is told from, another)
            ego = _ego_entity(r, stage)  # "The vehicle had been travelling at 30 km/h when ...": the protagonist
            ego.aliases.add(f"the {u.base}")
            r.notes.append(f"inferred: 'the {u.base}', named before anyone else, is the ego")
            return NounPhrase(ego, head, first)
    before = first - 1
    while before > lo and units[before].category in ("actions", "behaviours"):
        before -= 1  # "between parked cars"
    scenery = before >= lo and units[before].category == "word" and units[before].word in SCENERY_PREPOSITIONS or \
        any(m.category == "word" and m.word in SCENERY_PREPOSITIONS for m in modifiers)  # "from between parked cars"
    if before > lo and units[before].word == "by" and units[before - 1].category == "actions" and first == head and \
            units[before - 1].meaning != "relate" and not (head + 1 < len(units) and units[head + 1].meaning == "stop"):
        scenery = False  # "the ego is overtaken by trucks": the passive's doers ("hidden by vehicles parked near the
        # junction" is the scenery that hides)
    doing = head + 1 < len(units) and units[head + 1].category in ("actions", "positions") and \
        units[head + 1].tokens[0].word.endswith("ing")  # "a junction with cars coming from the right": agents
    again = plural and count is None and words == {"the"} and u.base in r.scenery and \
        not any(e.type == kind and not e.is_ego for e in r.entities)  # "... between parked cars. The parked cars hide
    # everything": the scenery said again
    if again or scenery and not doing and plural and count is None and kind not in V.VULNERABLE_TYPES and \
            words <= {"the"} and (not words or not any(e.type == kind and not e.is_ego for e in r.entities)) or (
            count is None and plural and before >= lo and "of" in words and kind not in V.VULNERABLE_TYPES
            and units[before].word in ("row", "line", "lot", "rows") and _said_parked(units, first, head)):
        # "a row of parked cars": scenery ("a line of cyclists", "a line of cars waiting at the lights": agents)
        for k in range(before + 1, head):
            r.mark(units[k])
            units[k].category = "word"
        if head + 1 < len(units) and units[head + 1].category == "actions" and \
                units[head + 1].tokens[0].word.endswith("ed"):
            r.mark(units[head + 1])
            units[head + 1].category = "word"  # "a street with cars parked both sides": said of the scenery
        r.scenery.add(u.base)
        return NounPhrase(None, head, first)  # "a kid runs out between parked cars": scenery, no agents
    if plural and count is None and not words and not doing and _looked_out_for(units, first):
        return NounPhrase(None, head, first)  # "looking out for cars and nothing else": cars in general
    headline = not words and count is None and not plural and u.tokens[0].sentence == 0
    uncounted = count is None and plural and not words & {"a", "an", "one", "another"}
    if count is None:
        count = BARE_PLURAL_COUNT if plural and not words & {"a", "an", "one", "another"} else 1
    if count is not None and count > 1 and not plural and u.base in ("group", "crowd", "family"):
        count = BARE_PLURAL_COUNT
    if count >= 100 and not plural:
        r.notes.append(f"read the number before '{u.base}' as naming it, not counting")
        count = 1  # "JOB CARD #4471 | 2017 Toyota Camry": a job's number before one car
    if count >= TOO_LARGE:
        r.notes.append(f"repaired: a count too large to read for {u.base}; used {MAX_AGENTS_PER_MENTION}")
        count = MAX_AGENTS_PER_MENTION
    elif count > MAX_AGENTS_PER_MENTION:
        r.notes.append(f"repaired: {count} {u.base}s is more than {MAX_AGENTS_PER_MENTION} in one mention; "
                       f"used {MAX_AGENTS_PER_MENTION}")
        count = MAX_AGENTS_PER_MENTION
    open_kind = u.meaning == "generic" or u.base in ("vehicle", "vehicle ahead")  # "three vehicles ahead: ..."
    if open_kind:  # "a vehicle": its type is left open
        kind = UNSPECIFIED.agent_type(kind, len(r.entities))
    entity = Entity(r.new_key(), kind, False, stage, count=count, head=u.base,
                    generic=open_kind and (count > 1 or plural), label=label,
                    headline=headline and not label, said_at=u.tokens[0].index)
    entity.uncounted = uncounted
    entity.definite = "the" in words
    entity.aliases |= {m.base for m in modifiers if m.category == "agents" and m.base in ROLE_NAMES}  # "LV truck
    # ahead ... LV hard brake": the role it is named by again
    if u.base.split()[0] in ("lead", "leading") or "lead vehicle" in entity.aliases:
        entity.features.add("ahead")
    if first >= 1 and "of" in words and units[first - 1].tokens[-1].word in ("queue", "line", "row", "jam"):
        entity.actions.append((stage, 1, ACTION_RANK["stop"], r.tick(), "stop", None))  # "a queue of four cars"
    elif u.base == "tailgater":
        entity.features.add("behind")
    if _including_ego(units, head, r.units):
        entity.count = max(0, count - 1)
        entity.includes_ego = True
    if entity.count > 1 or entity.generic or entity.includes_ego:
        entity.group_open = entity.count
    entity.aliases |= {m.base for m in units[max(lo, first - 1):head] if m.category == "agents" and m.meaning == kind}
    # "a silver Ford Focus ... the Ford": the make names it too
    if adversarial:
        entity.aliases.add("adversarial")
    if scenery and before >= lo and units[before].word == "between":
        entity.features.add("screening")  # "out from between two parked cars": the cars a crosser emerges from
    entity.relative_to = vehicle_left  # at the vehicle it got out of
    heading = _named_in_the_heading(r, entity, u.tokens[0], words) if not words & {
        "another", "other", "second", "more"} else None
    if heading is not None:  # "Pre-crash scene, emergency vehicle yield. ... V2, an ambulance, approaches": it
        r.notes.append(f"read the heading's '{heading.head}' as the case's name; the {entity.head} is the agent")
        entity.headline = False
        if heading.implied:  # "Cut-in from right lane. A white van swerves in front": what it did, and from where
            entity.features |= heading.features
            entity.actions += heading.actions
            entity.behavior = heading.behavior
        r.entities[r.entities.index(heading)] = entity  # what a listing heading said of it is the case's name
    named_as_a_kind = None if heading is not None else _named_as_a_kind(r, entity)
    if named_as_a_kind is not None:  # "an approaching emergency vehicle ... A police car approaches": that one
        named_as_a_kind.type, named_as_a_kind.head = entity.type, entity.head
        named_as_a_kind.aliases |= entity.aliases
        entity = named_as_a_kind
    elif heading is None:
        _take_from_the_group_it_is_included_in(r, units, first, entity)
        if not _absorbed(r, entity):
            r.entities.append(entity)
    for m in modifiers:
        _modify(r, entity, m, stage, strength=1)
    back = first - 1 - (first >= 2 and units[first - 1].category == "comma")  # "oncoming traffic, 2 cars"
    if back >= 1 and units[back].category == "agents" and units[back].word == "traffic" and \
            units[back - 1].category == "positions":
        _modify(r, entity, units[back - 1], stage, strength=1)
    elif first >= 2 and units[first - 1].category == "agents" and units[first - 1].word == "traffic" and \
            units[first - 2].category == "positions":
        _modify(r, entity, units[first - 2], stage, strength=1)  # "oncoming traffic two cars": the cars are oncoming
    return NounPhrase(entity, head, first, introduced=True, plural=count > 1)


def _the_two_told_of(r: _Reader, units: list[Unit], first: int, base: str) -> list[Entity]:
    """'... the two cars keep their lanes' after two cars were placed one by one; '... and the two vehicles
    touched' after one other vehicle: those already told of (the ego the second of 'the two vehicles'). Any other
    count of them makes 'the two cars' two more."""
    if units[first].word != "the" or first + 1 >= len(units) or units[first + 1].category not in ("numbers", "number"):
        return []  # (not "two of the cars behind me")
    named = [e for e in r.entities if not e.is_ego and e.count == 1 and e.type in V.EGO_TYPES and
             (base == "vehicle" or e.type == "car")]
    if len(named) == 2 or len(named) == 1 and base == "vehicle":
        return named
    return []


def _counted_again(r: _Reader, kind: str, base: str, count: int) -> list[Entity]:
    """'the two lads' after 'two lads': a counted group named again with 'the' and its count is the group, with
    the members already taken from it."""
    for group in reversed(r.entities):
        if group.is_ego or group.parent is not None or group.type != kind or \
                base not in (group.head, group.head.split()[-1]) and base not in group.aliases:
            continue  # ("two balloon cars ... the two cars")
        members = [e for e in r.entities if e.parent is group]
        if group.count + len(members) == count:
            return ([group] if group.count else []) + members
    return []


def _crewed_vehicle(r: _Reader, units: list[Unit], head: int, first: int, recent: list[Entity],
                    definite: bool) -> Entity | None:
    """The vehicle whose own people a definite (or bare) person noun names: 'a police car ... the officers',
    'a bin lorry ... the bin men', 'a motorbike ... the biker'. They ride in it or work it, so they are no agents
    of their own; one of the same noun named before ('an officer directing traffic ... the officer') is that
    one, and people who get out are on foot."""
    u = units[head]
    if not definite or _gets_out(units, head, walking=False):
        return None
    phrase = tuple(u.base.split())
    types = crews().get(phrase)
    if first < head and units[head - 1].category == "word":  # "the bin men": the vehicle's word before them
        types = crews().get((units[head - 1].word,) + phrase, types)
    if not types or any(not e.is_ego and (e.head == u.base or e.type == u.meaning != "pedestrian")
                        for e in r.entities):
        return None
    return _last_named(r, recent, lambda e: not e.is_ego and e.type in types)


def _article_dropped(r: _Reader, units: list[Unit], first: int, words: set) -> bool:
    """'Guy ate a load of salt', 'Bloke never looked': a log's or a note's noun opening a sentence with its article
    left out, as 'the' is."""
    return not words and _opens_its_sentence(r.tokens, units[first].tokens[0])


DRIVING_PEOPLE = {"guy", "dude", "man", "woman", "lady", "bloke", "chap", "fella", "fellow", "gentleman", "idiot",
                  "jerk", "moron", "lunatic", "nutter", "maniac", "numpty", "muppet", "culprit", "offender"}


def _driven_by(r: _Reader, units: list[Unit], head: int, recent: list[Entity]) -> Entity | None:
    """'the woman driving it', 'the man driving the van': the vehicle named before, by whoever drives it."""
    if head + 2 >= len(units) or units[head + 1].tokens[0].word != "driving":
        return None
    after = units[head + 2]
    if after.word in ("it", "that", "this"):
        return _last_named(r, recent, lambda e: not e.is_ego and e.type not in V.VULNERABLE_TYPES)
    if after.word in DEFINITE and head + 3 < len(units) and units[head + 3].category == "agents":
        noun = units[head + 3]
        return _last_named(r, recent, lambda e: not e.is_ego and e.type not in V.VULNERABLE_TYPES and (
            e.head == noun.base or noun.base in e.aliases or e.type == noun.meaning))
    return None


def _last_named(r: _Reader, recent: list[Entity], fits) -> Entity | None:
    """The last one that fits among those named lately, else among all named: whom 'the driver', 'the rider',
    'the officers' belong to."""
    return next((e for e in reversed(recent) if fits(e)), None) or \
        next((e for e in reversed(r.entities) if fits(e)), None)


def _names_the_ego_again(r: _Reader, ego: Entity, noun: str) -> bool:
    """'A driverless taxi ... the taxi': the ego's own noun, said again, is the ego, unless another agent
    was named by it too."""
    return any(noun in name.split() for name in ego.aliases | {ego.head}) and not any(
        not e.is_ego and (e.head.split()[-1] == noun or noun in e.aliases) for e in r.entities)


def _measured_by_others(units: list[Unit], k: int) -> bool:
    """'the car two cars ahead of me': a count of vehicles and a place right after the noun say where it is;
    'the car stopped behind me': a participle and a place by the speaker."""
    if k + 1 < len(units) and units[k].category == "actions" and len(units[k].tokens) == 1 and \
            units[k].word.endswith(("ed", "ing")) and units[k + 1].category == "positions" and \
            any(t.word in SPEAKING_SELF | {"ego"} for t in units[k + 1].tokens):
        return True
    return k + 2 < len(units) and units[k].category in ("numbers", "number") and units[k + 1].category == "agents" \
        and units[k + 2].category == "positions"


def _the_teller_afoot(ego: Entity) -> bool:
    """'I was walking on the zebra when the car turned left': a teller on foot drives no car, so 'the car' is
    another."""
    return ego.head in SPEAKERS | FIRST_PERSON and any(a[4] in ("walk", "cross") for a in ego.actions)


GENERAL_BODIES = {"car", "vehicle", "truck", "bus", "machine", "motor"}  # (machine: an Italian or Russian "car")
CONTROLLING = {"hold", "bring", "keep", "steer", "guide", "ease", "brake", "move", "stop", "park", "put", "drive",
               "pull"}  # what a system (or its driver) does to the car it drives
SELF_NAMES = {"i", "me", "we", "us", "you", "mine", "ours", "yours", "my own"}


def _named_by_a_vehicle_noun(ego: Entity) -> bool:
    """'The test car ... the sedan': an ego told of by a vehicle noun may be named again by another noun of its
    body; a narrator's 'I' or 'we' is not, and 'the sedan' in their account is someone else's."""
    return any(name.split()[-1] not in SELF_NAMES for name in ego.aliases | {ego.head} if name)


PAST_WITHOUT_ED = {"went", "cut", "came", "ran", "swung", "hit", "drove", "rode", "took", "made", "pulled", "shot",
                   "sped", "stuck", "began", "kept", "left", "got", "slid", "spun", "flew", "stole", "threw"}


PREDICATE_ENDS = {"left", "right", "straight", "ahead", "first", "lane", "lanes", "off", "out", "in", "over", "up", "down",
                  "hard", "again", "away", "back", "forward", "on", "signal", "indicator", "lights", "horn", "brakes"}


def _ends_a_predicate(word: str) -> bool:
    """'indicated right', 'slowed down', 'braked', 'suddenly': a word a predicate ends on, not a subject ('TOV then
    moved', 'she then made')."""
    return word in PREDICATE_ENDS or word.endswith(("ed", "ly")) and len(word) > 3


def _after_then(tokens: list[Token], clause: Clause) -> bool:
    """The clause opens right after ', then' ('waited while two ladies crossed, then turned left')."""
    at = clause.units[0].start if clause.units else 0
    return at >= 2 and tokens[at - 1].word == "then" and tokens[at - 2].word == ","


def _progressive_goes_on(before: Clause, clause: Clause) -> bool:
    """'... because a fire engine was coming out of the road on the right and turning left': an '-ing' after 'and'
    goes on with the progressive before it, of the same subject."""
    words = [u.tokens[0].word for u in before.units]
    return clause.link == "and" and clause.units[0].tokens[0].word.endswith("ing") and any(
        w in ("was", "were", "is", "are") and nxt.endswith("ing") for w, nxt in zip(words, words[1:]))


def _goes_on_in_the_past(r: _Reader, units: list[Unit], verbs: list[int], previous_subject: list) -> bool:
    """'The car ahead indicated right then suddenly turned left': after 'then' in the same sentence, a past verb with
    no subject goes on telling of the one before it (not the ego's, as an order or a note's next line would be)."""
    at = units[0].start if units else 0
    if not verbs or any(e.is_ego for e in previous_subject) or at < 2 or r.tokens[at - 1].word != "then" or \
            not _ends_a_predicate(r.tokens[at - 2].word) or r.tokens[at - 1].sentence != r.tokens[at].sentence or \
            r.tokens[at - 2].sentence != r.tokens[at].sentence:
        return False
    if any(u.category not in ("behaviours",) and u.word not in ADVERBS for u in units[:verbs[0]]):
        return False
    word = units[verbs[0]].tokens[0].word
    return word.endswith("ed") or word in PAST_WITHOUT_ED


def _past_tense_verb(u: Unit) -> bool:
    """A word the lexicon does not know, in the past tense ('the car behaved'): the verb after a subject."""
    return u.category == "word" and u.word.endswith("ed") and len(u.word) > 4 and \
        u.word not in lexicon().function_words


ADVERBS = {"still", "just", "really", "actually", "also", "even", "simply", "now", "only", "always", "basically",
           "already", "then", "obviously", "clearly", "probably", "definitely", "literally", "kind", "sort", "of"}


OBJECT_STARTS = {"its", "the", "a", "an", "that", "it", "his", "her", "their", "what", "this", "whether", "if"}


def _verb_before_its_object(units: list[Unit], k: int) -> bool:
    """'the car holds its line', 'does the car read that...': a word the lexicon does not know, followed by
    what starts an object, is the noun phrase's verb ('the car park' is no verb)."""
    return units[k].category == "word" and units[k].word not in lexicon().function_words and \
        k + 1 < len(units) and units[k + 1].word in OBJECT_STARTS


def _sentence_adverb(u: Unit) -> bool:
    return u.category == "word" and (u.word in ADVERBS or u.word.endswith("ly") and len(u.word) > 4)


OPPOSITE_PLACES = {"ahead": {"behind", "level", "back_left", "back_right"},
                   "behind": {"ahead", "overtaking", "level", "front_left", "front_right"},
                   "front_left": {"behind", "back_left", "back_right"},
                   "front_right": {"behind", "back_left", "back_right"},
                   "back_left": {"ahead", "front_left", "front_right"},
                   "back_right": {"ahead", "front_left", "front_right"},
                   "side_left": {"side_right"},
                   "side_right": {"side_left"}, "from_left": {"from_right", "road_right"},
                   "from_right": {"from_left", "road_left"}, "road_left": {"road_right", "from_right"},
                   "road_right": {"road_left", "from_left"}}


def _ego_object_follows(units: list[Unit], head: int) -> bool:
    """'the car overtakes us', 'the car swerves into our lane': the ego is named in the car's own predicate
    (before any other agent), so the car is another road user."""
    for j, x in enumerate(units[head + 1:], head + 1):
        if x.category == "agents" and x.meaning == "ego" or x.category == "positions" and {
                t.word for t in x.tokens} & {"us", "our", "me", "my", "ego", "you", "your"}:
            return True
        if x.category == "word" and x.word in ("my", "our", "your") and j + 1 < len(units) and \
                units[j + 1].category == "positions":
            return True  # "the car on my left": placed by the ego, so another
        if x.category == "agents" and x.meaning != "none":
            return False
    return False


def _placed_by_the_ego_in_its_relative(r: _Reader, noun: Unit) -> bool:
    """'the car which is in front of me brakes', 'the bus that drives ahead of the ego vehicle': a relative clause
    that places the noun by the ego, read as a clause of its own, still names the noun as another road user."""
    at = next((i for i, x in enumerate(r.units) if x is noun), None)
    if at is None or at + 2 >= len(r.units) or r.units[at + 1].word not in RELATIVES or \
            r.units[at + 2].category == "agents":  # "the car which I drive": the relative's subject is another
        return False
    sentence, verbs = noun.tokens[0].sentence, 0
    for x in r.units[at + 2:]:
        verbs += x.category == "actions" or x.category == "word" and x.word in AUXILIARIES
        if x.tokens[0].sentence != sentence or x.word == "," or x.category == "agents" and x.meaning != "ego" or \
                verbs > 1:  # a second verb is the main clause's ("the car which turns left is the ego")
            return False
        if x.category == "agents" and x.meaning == "ego" or x.category == "positions" and {
                t.word for t in x.tokens} & {"us", "our", "me", "my", "ego", "you", "your"}:
            return True
    return False


PLACING_WORDS = {"of", "to", "past", "behind", "beside", "alongside", "into", "at", "towards", "toward", "near"}


def _picked_out_by_what_it_did(r: _Reader, u: Unit) -> bool:
    """'The ego brakes. The car that cut in was a white van': a definite noun told apart by a relative whose
    subject it is names the one that did it, not the ego ('the car that I drive', 'the car which the ego follows':
    the relative has a subject of its own)."""
    at = u.end
    if at + 1 >= len(r.tokens) or r.tokens[at].word not in ("that", "which") or \
            r.tokens[at].sentence != u.tokens[-1].sentence:
        return False
    nxt = r.tokens[at + 1].word
    return nxt not in SPEAKERS and nxt not in PRONOUNS and nxt not in ("the", "a", "an", "ego")


def _ego_named_later_in_the_sentence(r: _Reader, u: Unit) -> bool:
    """'here comes the hatchback, cutting across right in front of the ego car': a sentence that places a vehicle
    by the ego named after it, past the vehicle's clause, tells of another vehicle ('the car pulls up ..., and
    our car goes': the ego named again as a subject is no such place)."""
    sentence = u.tokens[-1].sentence
    for k, x in enumerate(r.units):
        if x.start < u.end or x.tokens[0].sentence != sentence:
            continue
        if x.category == "agents" and x.meaning not in ("ego", "none"):
            return False  # "the car cope with a motorbike coming up behind us": the motorbike's place
        if x.category == "positions" and {t.word for t in x.tokens} & {"us", "me", "ego", "you"}:
            return True  # "... then slams on its brakes in front of me"
        if x.category == "agents" and x.meaning == "ego" and x.word in ("i", "we") and (
                r.units[k - 1].start == u.start or r.units[k - 1].word in ("that", "which") and
                r.units[k - 2].start == u.start) and not any(
                t.word in SPEAKERS_OWN for y in r.units[k + 1:k + 4] for t in y.tokens):
            return True  # "the car (that) I was following": the one the speaker follows, another (not "the car
            # that I was driving")
        if x.category == "agents" and x.meaning == "ego":
            before = k - 1
            while before >= 0 and r.units[before].word in ("the", "our", "my"):
                before -= 1
            if before >= 0 and (r.units[before].category == "positions" or r.units[before].word in PLACING_WORDS):
                return True
    return False


def _placed_in_its_sentence(r: _Reader, u: Unit) -> set[str]:
    """The places said after a noun in its sentence, up to the next agent named: 'Van: stopped, left lane, ahead'."""
    at = bisect_left(r.units, u.start, key=_unit_start)
    places = set()
    for x in r.units[at + 1:]:
        if x.category == "agents" or x.tokens[0].sentence != u.tokens[0].sentence:
            break
        if x.category == "positions":
            places.add(x.meaning)
    return places


def _placed_apart(places: set[str], e: Entity) -> bool:
    """'SUV: behind. Truck: in front of ego': a place that contradicts where the one named before is."""
    return any(OPPOSITE_PLACES.get(p, set()) & e.features for p in places)


def _place_in_the_name(units: list[Unit], head: int, first: int) -> str | None:
    """The place a noun phrase carries in its own words: 'lead car' (ahead), 'oncoming car' (road_straight)."""
    if units[head].base.split()[0] in ("lead", "leading"):
        return "ahead"
    return next((units[k].meaning for k in range(first, head) if units[k].category == "positions"), None)


def _placed_by_one_named_before(units: list[Unit], k: int, pronouns: tuple[str, ...] = ("it", "them")) -> bool:
    """'behind it', 'in front of them': a place taken from one named before by a pronoun."""
    last = units[k + 1].word if units[k].tokens[-1].word in ("behind", "ahead") and k + 1 < len(units) else \
        units[k].tokens[-1].word
    return last in pronouns


def _placed_elsewhere(e: Entity, units: list[Unit], head: int) -> bool:
    """'the car behind us' names another car than one already placed ahead."""
    after = head + 1 + (head + 1 < len(units) and units[head + 1].word in ("driver", "rider"))
    driver = after > head + 1 or units[head].tokens[-1].word in ("driver", "rider", "learner")  # "the learner
    # (driver) behind him": a person
    nxt = units[after] if after < len(units) else None
    if nxt is None or nxt.category != "positions":
        return False
    if _placed_by_one_named_before(units, after, ("it", "them") + ("him", "her") * driver) and \
            nxt.meaning in ("ahead", "behind", "level"):
        return True  # "a taxi stops ... the car behind it": another car, placed by the taxi; "the learner driver
        # behind him": another, placed by the one named before
    if nxt.meaning == "behind" and any(a[4] == "cut_in" for a in e.actions):
        return True  # "a van cuts in from the left lane. The car behind the ego goes on": one cutting in is ahead
    return bool(OPPOSITE_PLACES.get(nxt.meaning, set()) & e.features)


PLACES_IN_A_GROUP = {"first", "second", "third", "fourth", "fifth", "sixth", "2nd", "3rd", "4th", "5th", "6th", "last",
                     "middle"}


CRASH_NAMES = {"collision", "crash", "accident", "rtc", "rta", "incident", "pile", "smash", "shunt", "prang"}
TALLIED = {"incidents", "collisions", "crashes", "accidents", "calls", "callouts", "jobs", "cases", "events"}
# ("all emergency vehicle incidents", "bus crashes are rare": what is counted, of that kind)
CALLING = {"need", "needs", "needed", "call", "calls", "called", "calling", "send", "sent", "request", "requested"}


def _services_called(units: list[Unit], first: int) -> bool:
    """'I need police and an ambulance', 'called an ambulance': a service asked for, after a verb of calling, with
    no doing of its own in the clause."""
    k = first - 1
    while k >= 0 and (units[k].word in ("and", "an", "a", "the", "some") or units[k].category == "agents" and
                      units[k].meaning in V.EMERGENCY_TYPES):
        k -= 1
    return k >= 0 and units[k].tokens[-1].word in CALLING and \
        not any(u.category == "actions" for u in units[first:])


def _counts_the_crash(units: list[Unit], head: int) -> bool:
    """'a two-vehicle collision', 'RTC, 2 veh.', 'a collision involving two cars': the vehicles a crash is
    counted by are all of its vehicles, the one the scene is told from among them."""
    after = units[head + 1] if head + 1 < len(units) else None
    if after is not None and after.word in CRASH_NAMES and not units[head].tokens[-1].plural:
        return True  # "two-vehicle collision", "a three-car pile-up"
    before = [u for u in units[max(0, head - 4):head] if u.category not in ("numbers", "number")]
    return bool(before) and (before[-1].word in ("involving", "involved") or before[-1].category == "comma" and
                             len(before) >= 2 and before[-2].word in CRASH_NAMES)


def _including_ego(units: list[Unit], head: int, whole: list[Unit] | None = None) -> bool:
    at = bisect_left(whole, units[head].start, key=_unit_start) if whole is not None else None
    if at is not None and (at >= len(whole) or whole[at] is not units[head]):
        at = None
    if _ego_placed_among(units, head) or at is not None and _ego_placed_among(whole, at) or \
            _counts_the_crash(units, head):  # ("Ego is stopped, third in a line of three cars": past the comma)
        return True
    window = [u for u in units[head + 1: head + 5] if u.category != "comma"]
    if (bool(window) and window[0].category == "word" and window[0].word in ("including", "incl", "counting",
                                                                             "inc", "with")
            and any(u.category == "agents" and u.meaning == "ego" for u in window[1:3])):
        return True
    if at is not None:  # read on past the clause: "three cars wait, including yours"
        units, head = whole, at
    for k in range(head + 1, min(len(units) - 1, head + 9)):  # "three cars at a crossroads, including yours"
        if units[k].category == "agents" and units[k].meaning == "ego" and units[k + 1].word == "included" and \
                units[k - 1].category == "comma":
            return True  # "a queue of three cars, mine included"
        if units[k].category == "agents" or units[k].tokens[0].sentence != units[head].tokens[0].sentence:
            return False
        after = units[k + 1 + (units[k + 1].word == "the" and k + 2 < len(units))]
        if units[k].word in ("including", "incl", "counting") and after.category == "agents" and \
                after.meaning == "ego":
            return True
    return False


def _ego_placed_among(units: list[Unit], head: int) -> bool:
    """'we were the second of three cars', 'I was the last of four cars in the queue': the ego is one of them."""
    of = next((k for k in range(head - 1, max(0, head - 4), -1) if units[k].word == "of"), None)
    line = next((j for j in range(of - 1, max(0, of - 4) - 1, -1) if units[j].tokens[0].word == "in"), None) \
        if of is not None else None
    if line is not None and [t.word for u in units[line:of] for t in u.tokens] in (
            ["in", a, noun] for a in ("a", "the") for noun in ("line", "queue", "row", "convoy", "column")):
        of = line  # "third in a line of three cars": the ego's place in it
    if of is None or of < 2 or units[of - 1].word not in PLACES_IN_A_GROUP:
        return False
    return any(u.category == "agents" and u.meaning == "ego" for u in units[max(0, of - 5):of - 1])


KIND_NOUNS = {"car", "vehicle", "truck", "lorry", "van", "bus", "coach", "suv", "sedan", "hatchback", "pickup", "taxi",
              "cab", "motorcycle", "motorbike", "bike", "scooter", "moped", "tram", "minivan", "jeep", "ambulance",
              "police", "firetruck", "engine", "hgv", "semi", "tractor"}  # no make
GENERAL_NOUNS = {"car", "vehicle", "truck", "bus", "motorcycle", "bike", "cyclist", "pedestrian", "person",
                 "ambulance", "police", "police car", "firetruck", "fire truck", "sv", "pov", "target", "agent",
                 "people", "child", "kid", "man", "woman", "guy"}


FOOTWAYS = {"pavement", "footway", "sidewalk", "footpath"}
SIDEWALK_WORDS = FOOTWAYS | {"kerb", "curb"}
WANTING = {"want", "need", "like", "expect", "wish", "prefer", "propose"}  # "I want a car to cut in": the car cuts in
WATCHERS = {"officer", "constable", "pc", "trooper", "deputy", "witness", "observer", "examiner", "instructor",
            "inspector", "marshal", "steward", "warden", "investigator", "analyst", "reviewer"}  # who report seeing
PERCEIVING = {"see", "saw", "seen", "observe", "notice", "watch", "spot", "witness", "hear", "heard", "noticed",
              "observed", "spotted", "watched", "witnessed"}
RIDDEN = {"bike", "bicycle", "pushbike", "push bike", "pedal cycle", "motorbike", "motorcycle", "moped", "scooter"}


MINDING = PERCEIVING | {"know", "understand", "realize", "realise", "learn", "think", "care", "remember", "forget",
                        "look", "believe", "expect", "assume", "feel", "worry", "complain", "need", "want", "say",
                        "said", "ask", "agree", "tell", "told", "admit", "explain", "confirm", "claim", "report"}


def _owned_by_all(units: list[Unit], head: int) -> bool:
    """'Truck drivers have huge blind spots': a bare plural said to have something, placed nowhere: road users in
    general ('what they do as a habit' is read in _in_general)."""
    rest = units[head + 1:]
    return len(rest) >= 2 and rest[0].word in ("have", "has") and rest[1].category == "word" and \
        rest[1].word != "to" and not any(m.category == "positions" and m.meaning != "behind" or
                                         m.category == "actions" for m in rest[2:])


MODALS = {"can", "could", "should", "would", "will", "must", "might", "may", "never", "always", "just", "do", "don't",
          "dont", "really", "all", "to", "shall", "need", "have"}


def _minds_a_thing(units: list[Unit], head: int) -> bool:
    """'(so) people can see', 'drivers never look', 'I want drivers to understand': people in general, who see,
    think or know, and do nothing on the road."""
    k = head + 1
    while k < len(units) and units[k].category == "word" and units[k].word in MODALS:
        k += 1
    return k < len(units) and units[k].tokens[0].base in MINDING and \
        not any(m.category == "positions" for m in units[k + 1:])  # ("people watch from the pavement": there)


CAR_BODIES = {"taxi": "taxi", "cab": "taxi", "minicab": "taxi", "van": "van", "minivan": "minivan",
              "suv": "suv", "pickup": "pickup", "ute": "pickup", "hatchback": "hatchback", "hatch": "hatchback",
              "sedan": "sedan", "saloon": "sedan", "estate": "estate", "wagon": "estate", "coupe": "coupe",
              "convertible": "convertible", "jeep": "jeep", "limo": "limo", "limousine": "limo", "camper": "camper",
              "campervan": "camper", "motorhome": "camper"}


NOT_CALLED_CARS = {"van", "pickup", "camper"}  # bodies of the car type that nobody calls a car


def _other_body(head: str, named: str) -> bool:
    """'a white van came round ... the taxi waiting behind me': two bodies of car, each said by its own name, are
    two cars, not one named again; 'the car ahead stops, and the van in the left lane goes on': a van is not what
    anyone calls a car, so the van is not the car."""
    said, before = CAR_BODIES.get(head.split()[-1] if head else ""), CAR_BODIES.get(named.split()[-1] if named else "")
    if said in NOT_CALLED_CARS and named.split()[-1:] == ["car"] or before in NOT_CALLED_CARS and \
            head.split()[-1:] == ["car"]:
        return True  # (either way round: "a van ... the car", "a car ... the van")
    return said is not None and before is not None and said != before


def _existing(r: _Reader, kind: str, generic: bool, plural: bool, other: bool, both: bool,
              recent: list[Entity], head: str = "") -> list[Entity]:
    """The entities a definite noun phrase names: a counted group's next member, the other one, the last one."""
    drivers = head in ("driver", "drivers") and (both or plural)  # "both drivers": of the vehicles named
    pool = [e for e in r.entities if not e.is_ego and (e.type == kind or (generic and e.type in V.EGO_TYPES)
                                                        or (e.generic and kind in V.EGO_TYPES)
                                                        or drivers and e.type not in V.VULNERABLE_TYPES
                                                        or head in ROLE_NAMES and head in e.aliases)]
    # ("LV truck ahead ... LV brakes": the truck, by the role it was named by)
    if len(head.split()) > 1 and head.split()[-1] in ("driver", "rider", "drivers", "riders"):
        head = " ".join(head.split()[:-1])  # "the van's driver", "the bus driver": the van, the bus
    if head and head not in GENERAL_NOUNS and not both and not plural:
        same = [e for e in pool if e.head.split()[-1] == head.split()[-1] or head in e.aliases
                or len(e.head.split()) > 1 and e.head.split()[0] == head  # "a pickup truck ... the pickup"
                or e.head in GENERAL_NOUNS and e.head != "vehicle" and not _other_body(head, e.head)
                or e.type in V.TWO_WHEELER_TYPES and head in RIDDEN  # "a cyclist ... the bicycle": the same
                or head.split()[-1] in GROUP_NOUNS and e.count > 1]  # "a crowd of fans ... the crowd": them
        named = [e for e in same if e.head.split()[-1] == head.split()[-1] or head in e.aliases or
                 len(e.head.split()) > 1 and e.head.split()[0] == head]
        same = named or same  # "a delivery van ... a car behind ... the van": the van, not the car named last
        before = [e for e in pool if e.parent is None and e.count == 1 and e not in r.clause_mentions]
        if not same and not other and len(pool) == 1 and before == pool and not _other_body(head, pool[0].head):
            same = pool  # "a lorry ... the HGV", "a jogger ... the runner": the one of its kind named before
        pool = same  # "the oncoming SUV and the pickup behind it": a pickup is not the SUV
    elif head.split()[-1:] == ["car"] and not both and not plural:
        pool = [e for e in pool if not _other_body(head, e.head)]  # "a van was blocking the left lane, so the car
        # ahead of me swung out": nobody calls a van a car
    if not pool and not any(e.type == kind for e in r.entities if not e.is_ego) and not both and not plural:
        loose = loose_names().get(head, frozenset())  # "a pickup ... the truck", "a motorbike ... the bike"
        pool = [e for e in r.entities if not e.is_ego and e.parent is None and (e.head in loose or e.head.split()[-1] in loose
                                                                 or e.aliases & loose)]
    if not pool:
        return []
    if both or plural:
        groups = [e for e in pool if e.count > 1]
        return [groups[-1]] if groups else pool[-2:]
    groups = [e for e in pool if e.group_open > 0]
    if groups:
        group = groups[-1]
        member = Entity(r.new_key(), group.type if not group.generic else kind, False, group.stage,
                        head=group.head, parent=group, features=set(group.features),
                        actions=list(group.actions), behavior=group.behavior)
        group.group_open -= 1
        group.count -= 1
        r.entities.append(member)
        return [member]
    singles = [e for e in pool if e.parent is None or e.count == 1]
    if other:
        last = recent[-1] if recent and recent[-1] in singles else (singles[-1] if singles else None)
        others = [e for e in singles if e is not last]
        return [others[-1]] if others else ([last] if last else [])  # "the other vehicle": the one not the ego
    mentioned = [e for e in recent if e in singles]
    return [mentioned[-1]] if mentioned else [singles[-1]]


def _take_from_the_group_it_is_included_in(r: _Reader, units: list[Unit], first: int, entity: Entity) -> None:
    """'three cars, including a taxi, wait': the taxi is one of the three, not a fourth. It stays an agent of
    its own; the group it is taken from counts one less."""
    if not (first >= 1 and units[first - 1].word == "including") or entity.count != 1:
        return
    group = next((e for e in reversed(r.entities) if not e.is_ego), None)
    if group is None or group.count < 2 or not (group.type == entity.type or group.generic):
        return
    group.count -= 1
    group.group_open = max(0, group.group_open - 1)
    entity.named_of = group


def _named_as_a_kind(r: _Reader, entity: Entity) -> Entity | None:
    """The one agent named before only by the kind the new one is of ('the emergency vehicle moment ... a fire truck
    comes up behind us'); none when two of that kind were named, or the new one is counted."""
    if entity.count != 1 or entity.label:
        return None
    kinds = [e for e in r.entities if not e.is_ego and e.count == 1 and e.parent is None and not e.label and
             entity.type in categories().get(e.head, frozenset()) and e.type != entity.type
             and e not in r.clause_mentions]  # (in one clause, "VRU (cyclist, ...)" is an apposition's)
    return kinds[0] if len(kinds) == 1 else None


HEADING_WORDS = {"scene", "scenario", "case", "reconstruction", "crash", "collision", "conflict", "brief", "typology",
                 "type", "category", "report", "phase", "summary"}


def _named_in_the_heading(r: _Reader, entity: Entity, said: Token, words: set[str]) -> Entity | None:
    """'Pedestrian crossing at intersection, all-way stop, ladder crosswalk. Ego stopped while a kid and a parent
    cross': a first line that lists what the case is (commas, or a word like scene or reconstruction, and no ego)
    names the case by its agent; the one later introduced of that kind is the agent, not a second one. A note
    of one line lists its heading first: 'Ped crossing at midblock, no crosswalk, 2 peds from the right'."""
    if entity.is_ego:
        return None
    first = [t for t in r.tokens if t.sentence == 0]
    heading_end = len(r.tokens)
    if said.sentence == 0:  # the heading is the note's first item, the agent named in a later one
        heading_end = next((t.index for t in first if t.word == ","), said.index)
        first = [t for t in first if t.index < heading_end]
        if said.index <= heading_end or not (words or entity.count > 1) or any(
                t.word != t.base and t.word.endswith(("s", "ed")) and
                lexicon().phrases.get((t.base,), ("",))[0] == "actions" for t in first):
            return None  # "Pedestrian crossing, pedestrian waiting": two, said bare; "Car stops, a car passes"
        at = said.index - 1
        while at > heading_end and r.tokens[at].word in ("a", "an", "one", "the", "another"):
            at -= 1
        if r.tokens[at].word in ("plus", "and", "also"):
            return None  # "Pedestrian standing by a crosswalk, not crossing, plus a jogger on the sidewalk": one more
    if any(t.word == "ego" for t in first) or _a_job_card(r) and entity.head not in ("vehicle", "car"):
        return None  # ("JOB CARD 3320 - 2020 Hyundai Tucson. Customer states ... an oncoming SUV": the heading's is
        # the customer's, and the SUV another; "Customer states vehicle was stationary": the heading's)
    listed = any(t.word in HEADING_WORDS for t in first) or any(t.word == "," for t in first) or \
        said.sentence == 0 or len(first) <= 8 and not any(
            t.word != t.base and not t.word.endswith("ing") and not t.plural and
            (lexicon().phrases.get((t.base,)) or ("",))[0] == "actions" for t in first)  # "Pedestrian crossing
    # outside a crosswalk.": a short line with no finite verb is a heading
    titled = said.sentence > 0 and r.tokens[-1].sentence >= 2 and any(
        e.headline and 0 <= e.said_at <= 2 and not e.is_ego for e in r.entities)  # "Jeep tried to merge INTO me
    # at a red light. OP here ... Jeep Wrangler in the right lane": a post's title, told again in its body
    listed = listed or titled
    coded = said.sentence > 0 and first and first[0].word == "case"  # "SC-07 Emergency vehicle approach from the
    # rear.": a line opened by a document's identifier is the case's title, whatever places it says
    named = [e for e in r.entities if e.headline and not e.label and not e.is_ego and e.count == 1 and
             e.said_at < heading_end and
             e.parent is None and e.stage == entity.stage and (
                 e.implied and entity.type not in V.VULNERABLE_TYPES  # "Cut-in from left. Sedan in left lane ..."
                 or listed and (coded or _a_case_told(r, e) or
                                not e.features & HEADLINE_PLACES - _places_named(e, said.sentence)) and (
                     e.type == entity.type or entity.type in categories().get(e.head, frozenset()) or
                     e.head.split()[-1] == "vehicle" and entity.type not in V.VULNERABLE_TYPES))]
    if len(named) != 1 or said.sentence == 0 and named[0].said_at + 1 == heading_end and \
            r.tokens[heading_end + 1].word in ("a", "an"):
        return None  # "CV, a Jeep Wrangler, followed IV": the noun and what it is, no heading
    return named[0]


def _a_case_told(r: _Reader, e: Entity) -> bool:
    """'Cyclist crossing from the right at an uncontrolled junction.' over the text: a heading noun and the
    participle that tells its case, wherever that places it."""
    after = r.tokens[e.said_at + 1] if 0 <= e.said_at < len(r.tokens) - 1 else None
    return after is not None and after.sentence == 0 and r.tokens[e.said_at].sentence == 0 and \
        after.word.endswith("ing") and e.said_at <= 2


def _places_named(e: Entity, sentence: int) -> set[str]:
    """The place a heading's noun says by itself: a lead vehicle is ahead; 'Vehicle(s) not making a maneuver,
    opposite direction.' names where the case's vehicle comes from, said again where the text names it."""
    if e.head.split()[-1] == "vehicle" and sentence > 0:  # ("Emergency vehicle approaching from behind.")
        return HEADLINE_PLACES
    return {"ahead"} if e.head.split()[0] in ("lead", "leading") else set()


def _ego_listed_in_a_group(r: _Reader, ego: Entity, units: list[Unit], first: int) -> None:
    """'three agents: the ego, a cyclist and a bus': the ego named in the list of a counted kind is one of it."""
    listed = units[first - 1].word in (",", "and") if first > 0 else units[first].tokens[0].opened_by == ":"
    group = next((e for e in reversed(r.entities) if not e.is_ego and e.parent is None and e.named_of is None), None)
    if listed and group is not None and group.generic and group.group_open > 0 and group.count > 0:
        group.group_open -= 1
        group.count -= 1


def _absorbed(r: _Reader, entity: Entity) -> bool:
    """A new agent of a counted group already introduced ('four vehicles: a car, a bus...') is one of it, and is
    what the group was said to be ('two oncoming vehicles (a bus and a van)': both oncoming)."""
    for group in reversed(r.entities):
        if group.is_ego or group is entity or group.group_open <= 0 and group is not entity.named_of:
            continue
        if group is entity.named_of or group.generic or (group.includes_ego and group.type == entity.type):
            if group is not entity.named_of:  # ("five vehicles including a truck": taken from the five already)
                taken = min(entity.count, group.group_open)
                group.group_open -= taken
                group.count -= taken
            entity.named_of = group  # "three cars including the ego. One car is stopped ...": one of them
            entity.features |= group.features
            entity.behavior = entity.behavior or group.behavior
            entity.actions = entity.actions or list(group.actions)
            return False
    return False


# -- clause reading -----------------------------------------------------------------------------------------

CAME_ALONG = {"coming", "came", "comes", "come", "approaching", "emerging", "travelling", "traveling", "driving",
              "arriving", "heading", "riding"}  # said before 'from the right' of one that came along that road


def _modify(r: _Reader, e: Entity, u: Unit, stage: int, strength: int, clause_units: list[Unit] | None = None,
            k: int | None = None) -> None:
    """Give a modifier or a predicate to the entity it belongs to."""
    r.mark(u)
    if u.category == "behaviours":
        e.behavior = e.behavior or u.meaning
    elif u.category == "positions":
        if u.meaning in ("side_left", "side_right") and not {t.word for t in u.tokens} & LANE_WORDS:
            e.features.add("bare_" + u.meaning[5:])
        elif u.meaning in SIDE_MEANINGS and {t.word for t in u.tokens} & {"lane", "lanes"}:
            e.features.add("lane_said")  # "a bus stopped in the right lane ahead": in a lane, not at the kerb
            words = [t.word for t in u.tokens]
            named = next((w for w, nxt in zip(words, words[1:]) if w in SIDES and nxt in ("lane", "hand")), None)
            if named and not set(words) & {"my", "our", "your", "its", "his", "her", "their", "of", "ego"}:
                e.features.add("named_lane_" + named)  # "in the left lane": a lane of the road, not one beside me
        before = [t.word for t in r.tokens[max(0, u.start - 3):u.start]]
        if u.meaning in ("side_left", "side_right") and (u.tokens[0].word == "from" or before[-2:] == ["out", "of"]
                                                         or before == ["out", "of", "the"]):
            e.features.add("from_lane")  # "pulls out of the left lane": where it came from, as "from" says
        if u.meaning == "side_left" and {t.word for t in u.tokens} & {"far", "farside"} and \
                "lane" not in {t.word for t in u.tokens}:
            e.features.add("far_side")  # the far lane of a road, or across a junction: decided in _position
        if u.meaning == "behind" and "blind" in {t.word for t in u.tokens}:
            e.features.add("blind_spot")  # behind, in the lane beside: the one the ego moves into, if it does
        where = [t.word for t in r.tokens[u.end:u.end + 2]]
        if u.meaning in ("ahead", "behind") and where[:1] == ["where"] and where[1:] and where[1] in PRONOUNS:
            e.relative_to = e.relative_to or next(
                (x for x in reversed(r.entities) if not x.is_ego and x is not e and x.key < e.key), None)
            return  # "a stopped car behind where it was": at the place of the one that moved away
        if u.meaning in ("ahead", "behind") and INVERSE[u.meaning] in e.features and e.actions:
            return  # "a Toyota behind me ... cut in directly in front of me": the first place said is its start
        if u.meaning == "sidewalk" and e.type != "pedestrian" and "corner" in {t.word for t in u.tokens}:
            return  # "the cyclist turned right at the next corner": at the junction, not on the pavement
        if u.meaning == "road_straight" and {t.word for t in u.tokens} & {"lane", "lanes"}:
            e.features.add("oncoming_lane")  # "in the oncoming lane": a lane of this road, no junction's arm
        if u.meaning in ("shoulder", "sidewalk"):
            e.road_type = e.road_type or u.meaning
            if u.meaning == "sidewalk":
                e.features.add("on_sidewalk")
                if {t.word for t in u.tokens} & {"corner", "corners"} and "far" in {
                        t.word for t in r.tokens[max(0, u.start - 3):u.end]}:
                    e.features.add("on_the_far_corner")  # "on the far right corner": across the junction ahead
            if u.meaning == "shoulder" and {t.word for t in u.tokens} & {"verge", "verges", "grass", "grassy"}:
                e.features.add("on_verge")  # the grass beside the road, where people walk
        elif u.meaning.startswith("compass_"):
            _add_compass(r, e, u)
        else:
            e.features.add(u.meaning)
            if u.meaning in ("from_left", "from_right") and any(
                    t.word in CAME_ALONG and t.sentence == u.tokens[0].sentence
                    for t in [*r.tokens[max(0, u.start - 4):u.start], u.tokens[0]]):
                e.came_along = True  # "a car coming from the right", "came off Quarry from my left": along the road
                # on that side
            if u.meaning == "both_sides" and e.count == 1 and not e.is_ego and e.parent is None and \
                    {t.word for t in u.tokens} & {"each", "either"}:
                e.count = 2  # "a car parked on each side of the street": one on each side, two
    elif u.category == "actions" and u.meaning == "same":
        acted = [x for x in r.entities if x is not e and x.actions and x.parent is not e and e.parent is not x]
        model = max(acted, key=lambda x: max(a[3] for a in x.actions), default=None) or max(
            (x for x in r.entities if x is not e and not x.is_ego and x.features and x.parent is not e and
             e.parent is not x), key=lambda x: x.said_at, default=None)  # the last one who acted, or was placed
        # ("a fire engine came up behind us. Then an ambulance did the same")
        if model is not None:  # "then a second taxi did exactly the same thing": its manoeuvre, from its place
            e.actions += [(stage, strength) + a[2:3] + (r.tick(),) + a[4:] for a in model.actions]
            if not model.is_ego and e.relative_to is not model:  # "the ego waits; two cars behind it do the same":
                # they wait, where they are (one that "followed it round" is behind it, not where it is)
                e.features |= model.features
                e.relative_to = e.relative_to or model.relative_to
            r.notes.append(f"inferred: '{e.head}' does what '{model.head}' did")
    elif u.category == "actions":
        direction = None
        if not e.is_ego and u.base in ("come up", "creep up", "speed up", "race up", "fly up") and \
                clause_units is not None and k is not None and any(
                x.category == "positions" and x.meaning in ("side_left", "side_right") and
                x.tokens[-1].word == "lane" and x.tokens[0].word not in ("in", "on", "from", "into")
                for x in clause_units[k + 1:k + 3]) and \
                "ahead" not in e.features:
            e.features.add("behind")  # "came up the inside lane": along the lane beside, from behind
        if clause_units is not None and k is not None and (u.meaning in ("turn", "lane_change", "cut_in") or (
                u.meaning == "move" and u.tokens[0].base in STEERING | LANE_STEERING)):
            direction = _direction_after(r, clause_units, k)
        action = u.meaning
        if action == "walk" and clause_units is not None and k is not None and any(
                x.category == "word" and x.word in ("across", "over") for x in clause_units[k + 1:k + 3]):
            action = "cross"  # "a granny shuffles slowly across": over the road
        if e.type == "pedestrian" and action in ("move", "cross") and clause_units is not None and k is not None and (
                u.tokens[-1].word == "along" or k + 1 < len(clause_units) and clause_units[k + 1].word == "along") and \
                not any(x.meaning in ("crosswalk", *V.CROSSWALK_OBJECTS) for x in clause_units[k + 1:k + 4]):
            action = "walk"  # "two joggers run along the side of the road": along it, not across (but "crossing
            # along the crosswalk" is over it)
        if action == "cross" and e.type not in V.VULNERABLE_TYPES and clause_units is not None and k is not None and \
                any(x.category in ("road", "positions") and (x.meaning in V.CROSSWALK_OBJECTS | {"crosswalk", "stop_line"})
                    for x in clause_units[k + 1:k + 4]):
            action = "move"  # "the Fiesta went across the zebra": through the crossing, on its own road
        if not e.is_ego and u.base in FROM_BEHIND_VERBS and clause_units is not None and k is not None and any(
                x.category == "agents" and x.meaning == "ego" or x.word == "by" for x in clause_units[k + 1:k + 3]):
            e.features.add("behind")  # "rear-ended by a taxi", "a taxi shunted me": it came from behind (not "two
            # cars had shunted": into each other)
        if action == "cross" and e.type not in V.VULNERABLE_TYPES and u.base == "emerge" and \
                clause_units is not None and k is not None and any(
                x.category == "positions" and x.meaning in ("road_straight", "toward")
                for x in clause_units[k + 1:k + 6]):
            action = "move"  # "a van emerges from the mist in the oncoming lane": it comes on, along its own lane
        if action == "cross" and e.type == "cyclist" and "straight" in {t.word for t in u.tokens}:
            e.features.add("straight_across")  # "rides straight across from the road on the left": through the
            # junction on its own road, when it comes from a side road (mid-block, over the ego's road)
        pace_window = 3 if u.base == "sit" else 6 if u.base in ("hold position", "held position") else 0
        if action == "stop" and not e.is_ego and pace_window and clause_units is not None and k is not None and any(
                x.category == "positions" and x.meaning in ("level", "behind")
                for x in clause_units[k + 1:k + pace_window]):
            action = "move"  # "a ute sitting right next to me", "sitting on my tail", "holds position in the adjacent
            # lane right next to the subject vehicle": keeping pace with the ego
        if action == "stop" and u.base == "sit" and clause_units is not None and k is not None and \
                [x.word for x in clause_units[k + 1:k + 2]] == ["at"] and k + 2 < len(clause_units) and \
                clause_units[k + 2].category in ("number", "numbers"):
            action = "move"  # "sat at 56 on the limiter": a speed held, not a stop
        if action == "stop" and len(u.tokens) > 1 and clause_units is not None and k is not None and (
                u.tokens[0].word == "cannot" or u.tokens[0].word == "not" and k > 0 and
                clause_units[k - 1].word in UNABLE) and k + 1 < len(clause_units) and \
                clause_units[k + 1].word in ("over", "across", "out", "into", "left", "right", "past", "around", "round"):
            return  # "so I can't move over": a lane change it could not make, not a stop ("couldn't move": stuck)
        if action == "stop" and clause_units is not None and k is not None and u.tokens[0].word == "stop" and (
                [x.word for x in clause_units[max(0, k - 1):k]] == ["can"] and (
                    {"so", "what", "that"} & {t.word for t in r.tokens[max(0, u.start - 4):u.start - 1]} or
                    [x.word for x in clause_units[k + 1:k + 3]] == ["in", "time"] and
                    [t.word for t in r.tokens[max(0, u.start - 2):u.start - 1]] == ["you"]) or
                [x.word for x in clause_units[max(0, k - 2):k]] == ["able", "to"] and k > 2 and
                clause_units[k - 3].word in ("be", "are", "is", "am", "re")):
            return  # "ride so you can stop", "slow enough to be able to stop", "at 25 you can stop in time": a stop
            # one could make, none made (not "car behind also can stop", where 'can' tells it did)
        if e.is_ego and action in ("cut_in", "move", "lane_change") and clause_units is not None and k is not None \
                and _towards_an_edge(clause_units[k + 1:k + 5]):
            action, direction = "move", None  # "you kept drifting over towards the kerb": within the lane
        if action in ("cut_in", "move", "lane_change", "lane_left", "lane_right") and clause_units is not None and \
                k is not None and _onto_the_roadside(clause_units[k + 1:k + 5]):
            action, direction = "move", None  # "steered right onto the gravel and stopped": off the road, no lane
        if e.is_ego and action == "cut_in" and not direction and [t.base for t in u.tokens[:2]] == ["pull", "away"]:
            action = "move"  # "the ego is a bus pulling away from a bus stop": it moves off; no lane is named
        if e.is_ego and action == "cut_in" and not direction and "back" in {t.word for t in u.tokens}:
            e.features.add(f"returns_{stage}")  # "then pulled back in": to the lane it pulled out of
        if e.is_ego and action == "cut_in" and not direction and u.tokens[0].base in ("swerve", "jerk", "veer"):
            action = "move"  # "I slammed on the brakes and swerved": a jerk of the wheel, no lane named
        if action == "move" and u.base in LANE_STEERING and direction:
            action = "lane_" + direction
        if action == "move" and not e.is_ego and u.tokens[0].base in STEERING and clause_units is not None and \
                k is not None and any(x.category == "positions" and x.meaning == "toward"
                                      for x in clause_units[k + 1:k + 3]):
            action = "cut_in"  # "a lorry on our left began to drift towards us": over into the ego's lane
        waiting_to = clause_units is not None and k is not None and _waiting_to(clause_units, k)
        if action == "cross" and waiting_to:
            e.features.add("waits_to_cross")  # "standing at the crossing, waiting to cross": the crossing is to come;
            return  # it stands there (on the pavement, if said) until a later stage says it goes
        if waiting_to and set(u.base.split()) & OVERTAKING:
            e.actions = [a for a in e.actions if not (a[0] == stage and a[4] == "stop")]
            return  # "behind a cyclist, waiting to pass": following it, for a chance to pass
        if waiting_to and (action in ("cut_in", "move", "lane_change", "lane_left", "lane_right") or
                           action in ("turn", "turn_left", "turn_right", "u_turn") and not e.is_ego):
            if action in ("turn", "turn_left", "turn_right", "u_turn"):
                e.waits_to_turn = (stage, action, direction)
            return  # "a bus is waiting to pull out of the side road", "cars waiting to turn": it waits; pulling out
            # or turning is to come (the ego's turn is its plan, read in its own stage)
        if action == "turn" and not direction and e.waits_to_turn and \
                e.waits_to_turn[1] in ("turn_left", "turn_right"):
            action = e.waits_to_turn[1]  # "waiting to turn right across me, and he just turned": the turn it waited
            # to make
        if action == "walk" and e.type == "pedestrian" and {t.word for t in u.tokens} & SIDEWALK_WORDS:
            e.features.add("on_sidewalk")  # "standing on the pavement near the crossing": on the pavement, by it
        if action == "lane_change" and u.base == "change" and not direction and clause_units is not None and not \
                any("lane" in x.base for x in clause_units[k + 1:k + 5]):
            return  # "waiting for the light to change"
        if action == "move" and e.is_ego and clause_units is not None and k is not None and (
                set(u.base.split()) & OVERTAKING or k + 1 < len(clause_units)
                and clause_units[k + 1].word in ("around", "round", "past")) and \
                not _round_a_bend(clause_units, k):  # "go around it on the left"
            ahead = clause_units[k + 1:k + 8]
            ahead = ahead[:next((j for j, x in enumerate(ahead) if x.category == "actions" and j > 0 and
                                 ahead[j - 1].category == "agents"), len(ahead))]
            side = direction or _direction_after(r, clause_units, k) or next(  # "went around on the right": read once
                (x.meaning[5:] for x in ahead if x.category == "positions"  # (not "passes a truck parked on
                 and x.meaning in ("side_left", "side_right")), None)  # the right": where the truck is)
            circulating = any(t.word in ("roundabout", "rotary", "circle") for x in clause_units for t in x.tokens) \
                and not (k + 2 < len(clause_units) and (clause_units[k + 2].category == "agents" or
                                                       clause_units[k + 2].word in ("it", "him", "her", "them"))) \
                or k + 2 < len(clause_units) and clause_units[k + 2].word in ("into", "onto")  # "went round into
            # Church Street": a turn into it, no way round someone
            if not side:  # "changed lanes to the right to go around", "pulled out to the right and went round her"
                side = next((a[4][5:] for a in reversed(e.actions) if a[0] == stage
                             and a[4] in ("lane_left", "lane_right")), None)  # the purpose of the change said
            at = clause_units[k + 1].tokens[0].index if k + 1 < len(clause_units) else -1
            again = at >= 0 and ([t.word for t in r.tokens[at + 1:at + 3]] in (["and", "round"], ["and", "around"]) or
                                 [t.word for t in r.tokens[max(0, at - 2):at]] in (["round", "and"], ["around", "and"]))
            if not side and k + 1 < len(clause_units) and clause_units[k + 1].word in ("around", "round") and \
                    not circulating and not again and not (
                        _one_lane_with_oncoming(r.tokens) and not {"left", "right"} & {
                            t.word for t in r.tokens if t.sentence == u.tokens[0].sentence}):
                # ("in the roundabout going around": round it, not round someone; "drove round and round the
                # estate": about it; on a narrow road with traffic coming the other way, round it in the one lane)
                side = _overtaking_side("ego_lane_change_direction")  # "I have to go around it": the next lane
            if side and _passing_one_off_the_lanes(r, clause_units, k, side):
                side = None  # "a semi stopped on the shoulder ... I'm going past it in the right lane": no change
            if side:
                action, direction = "lane_" + side, side  # "we overtake it on the left": out into that lane
                for x in clause_units[k + 1:k + 6]:
                    if x.category == "positions" and x.meaning == "side_" + side:
                        x.meaning = "used"  # the side of the ego's manoeuvre, not of what it passes
                        break
        overtaken = next((x for x in (clause_units or [])[k + 1:k + 4] if x.category == "agents"), None) \
            if k is not None else None
        went_by = strength == 1 and set(u.base.split()) & OVERTAKING <= {"pass", "past"} and \
            clause_units is not None and k is not None and k + 1 == len(clause_units)  # "after he passed", "until
        # it has gone past": a condition that it went by, not that it overtook us ("a motorbike passes" still does)
        if action == "move" and not e.is_ego and set(u.base.split()) & OVERTAKING and not went_by and not (
                overtaken is not None and overtaken.meaning not in ("ego", "none")):  # not "to overtake a cyclist"
            e.features.add("overtaking")
            if "undertake" in u.base.split():
                e.features.add("undertaking")  # passing on the kerb side
        if [t.base for t in u.tokens] == ["pull", "over"] and clause_units is not None and k is not None and \
                k + 1 < len(clause_units) and (clause_units[k + 1].category == "agents" and clause_units[k + 1].meaning
                                               != "ego" or clause_units[k + 1].word in ("a", "an", "the", "another")):
            action, direction = "stop", None  # "the cop car has pulled over a pickup": it stopped the pickup, and
            # stands behind it
        if action == "block":  # "cut me off" may be told as the lane change it was; "blocks", "boxes in" may not
            e.features.add("cuts_off" if "cut" in {t.word for t in u.tokens} else "blocks")
        if action == "stop" and _to_settle_up(r.tokens, u):
            return  # "the other driver did stop and gave me her info": after the collision, not in the scene
        if action == "stop" and not e.is_ego and clause_units is not None and k is not None and \
                _stands_across(clause_units[k + 1:k + 5]):
            action = "block"  # "a patrol car parked across the lane": nobody gets by
        sentence = u.tokens[-1].sentence
        reply = [x for x in r.units if x.tokens[0].sentence == sentence + 1]  # "... just not moving." "Forever."
        if action == "stop" and not e.is_ego and (_for_long([x for x in r.units if x.start > u.start and
                                                             x.tokens[0].sentence == sentence]) or
                                                  len(reply) <= 2 and _for_long(reply)):
            e.features.add("stays_long")  # "stayed there for a quarter of an hour": long enough to hold others up
        if action == "stop" and ({t.base for t in u.tokens} & {"park", "parked", "stationary", "break", "broken",
                                                                  "stall", "stalled", "double", "abandon"}
                                 or {"bus", "stop"} <= {t.word for t in u.tokens}):  # "at a bus stop": at the kerb
            e.features.add("parked")
        braking = action == "stop" and {t.base for t in u.tokens} & {"brake", "brakes"} and not (
                {t.word for t in u.tokens} & {"halt", "stop", "standstill"}) and not (
                clause_units is not None and k is not None and (any(
                    x.meaning == "stop" or x.word in ("halt", "stop", "standstill") for x in clause_units[k + 1:k + 5])
                    or _in_time(clause_units[k + 1:k + 5])))
        if braking and e.is_ego:
            return  # "the AV braked to avoid a collision": a reaction, not where the ego ends; "to a halt" is a stop
        plain_brake = braking and {t.base for t in u.tokens} <= {"brake", "brakes", "hard", "harshly", "firmly"} and \
            not any(x.meaning == "stop" or x.word in ("halt", "stop", "standstill", "stopped", "stationary")
                    for x in [x for x in r.units if x.start > u.start and x.tokens[0].sentence == sentence][:12])
        out_after = clause_units is not None and k is not None and k + 1 < len(clause_units) and \
            clause_units[k + 1].word == "out"
        if action == "cut_in" and not e.is_ego and ([t.word for t in u.tokens][-1:] == ["out"] or out_after or
                                                    [t.word for t in u.tokens][-2:-1] == ["out"]):
            e.features.add("moves_out")  # "the car in front pulls out", "swerves out": out of the lane it is in
        if action == "cut_in" and {"kerb", "curb", "kerbside", "curbside", "stop", "stand", "bay"} & \
                {t.word for t in u.tokens} or action == "cut_in" and "parked" in e.features and (
                    "moves_out" in e.features or "out" in {t.word for t in u.tokens}):
            e.features |= {"from_lane", "from_kerb"}  # "pulls away from the kerb", "pulling out of a stop on the
            # right", "a parked car pulled out": from where it stood, ahead; at the kerb unless a side is said
        if e.is_ego and action == "cut_in" and direction is None and any(
                a[0] == stage and a[4] in ("lane_left", "lane_right") for a in e.actions):
            return  # "merges left ... and has to slot in between them": the same lane change, its side said before
        noun = clause_units is not None and k is not None and k > 0 and clause_units[k - 1].word in (
            "same", "the", "a", "full", "high", "top", "its", "his", "her", "their", "at")  # "doing the same speed"
        jogging = e.type == "pedestrian" and action in ("move", "walk")  # "joggers running on the pavement"
        if u.tokens[0].base in RUSHING and not e.is_ego and not noun and not jogging:
            e.behavior = e.behavior or "aggressive"
        if action in ("lane_left", "lane_right") and [t.base for t in u.tokens[:2]] == ["pull", "out"]:
            e.features.add("pulls_out")  # "pulls out to the left": a turn when it pulls out of a junction
        stative = clause_units is not None and k is not None and k > 0 and \
            clause_units[k - 1].word in COPULAS | {"be", "been", "being"}  # "a truck is stopped dead ahead": it stands
        if action == "stop" and not e.is_ego and {t.word for t in u.tokens} & ABRUPT_STOP_WORDS and not stative:
            e.features.add("stops_abruptly")  # "stops dead", "slams on the brakes": a sudden stop, not a halt
            e.behavior = e.behavior or "aggressive"
        if action == "turn" and e.is_ego and not direction and clause_units is not None and k is not None and \
                k > 0 and clause_units[k - 1].word == "to":
            e.features.add("turn_intended")  # "waiting to turn out": a turn meant, not made
        if action == "reach" and e.is_ego and clause_units is not None and k is not None and \
                {t.base for t in u.tokens} & {"arrive", "pull"} and _a_stop_control(
                    clause_units[k + 1:k + 5] + clause_units[max(0, k - 6):k]):  # ("at a four-way stop, it arrives")
            e.actions.append((stage, strength if r.staged else 1, ACTION_RANK["stop"], r.tick(), "stop", None))
            # "I arrived at the all-way stop", "pulls up to a stop sign": it stops there; a way it means to go, said
            # with it, wins ("both of you want to go straight"), unless the story goes on to a later stage
        earlier = clause_units is not None and k is not None and any(
            x.word == "had" and y.word != "to" for x, y in zip(clause_units[max(0, k - 3):k],
                                                               clause_units[max(0, k - 3) + 1:k + 1])) and \
            action == "stop"  # ("I had to stop dead" is no state before the story)
        # "a BMW that had been sitting in the outside lane cut us up": a state before the story, not its end
        if plain_brake and not e.is_ego and clause_units is not None and k is not None and \
                _forced_reaction(clause_units, k):
            action = "move"  # "the guy behind had to brake hard too": slowed, and drove on
        if action == "stop" and not e.is_ego and not earlier and clause_units is not None and k is not None and \
                _forced_reaction(clause_units, k) and not {t.base for t in u.tokens} & {"stop", "halt"}:
            e.actions.append((stage, 1, ACTION_RANK["go_straight"], 0, action, direction))
            if _moving_in_a_place(clause_units[:k]) and not any(
                    x.category == "positions" and x.meaning in JUNCTION_PLACES for x in clause_units[:k]):
                # "came up behind me and had to wait": coming, said in its place (one "coming the other way" that
                # "had to wait for it" yields at the junction: it stops)
                e.actions.append((stage, strength, ACTION_RANK["move"], r.tick(), "move", None))
            return  # "was closing fast and had to brake", "came up behind and had to wait": a reaction to another;
            # what it was doing is its action; made to stop, it stops ("the pickup had to stop for us")
        e.actions.append((stage, strength, ACTION_RANK["go_straight"] if earlier else ACTION_RANK.get(action, 0),
                          0 if earlier else r.tick(), action, direction))
        if braking and not earlier:
            r.braked.add(r.order)
        if plain_brake and u.tokens[0].word == "braked" and not earlier and e.actions[-1][4] == "stop":
            r.plain_brakes.add(e.actions[-1][3])  # told as it happened ("the pickup behind also braked"); a scene
            # asked for ("a taxi behind that brakes hard") wants the braking played, its stop
        if action in ("lane_left", "lane_right") and not {"left", "right"} & {t.word for t in u.tokens}:
            e.features.add("to_the_kerb")  # "pulled over", "pulled to the side": towards the kerb, no lane named
        if action == "lane_change" and {"middle", "center"} & {t.word for t in u.tokens}:
            e.features.add("to_the_middle")  # "moves into the middle lane": away from the side lane it is in
        if action == "go_straight" and "straight" in {t.word for t in u.tokens}:
            e.features.add("straight_on")  # "goes straight through", said; not "moves off"
        # ("had stopped first and was proceeding straight across": what it does now outranks what it had done)
    elif u.category == "word" and u.word not in lexicon().function_words:
        pass


COMPASS_SIDES = {"side", "curb", "kerb", "sidewalk", "pavement", "shoulder", "edge", "verge", "footway", "footpath",
                 "corner", "curbside", "kerbside", "gutter", "crosswalk", "crossing", "leg", "approach", "sidewalks"}
COMPASS_WORDS = {"north", "south", "east", "west"}
CORNER_POINTS = {"northeast", "northwest", "southeast", "southwest"}
DESTINATION_WORDS = {"onto", "into", "toward", "towards"}


def _add_compass(r: _Reader, e: Entity, u: Unit) -> None:
    """A compass word is where one heads ('northbound', 'heading west'), where it comes from ('from the north',
    'east to west') or where it is ('on the east curb', 'the north side'). The first heading said is the heading:
    'northbound ... turns left onto westbound 5th Ave' heads north, westbound is the road it turns onto."""
    point = u.meaning[len("compass_"):]
    at = lambda k: r.tokens[k].word if 0 <= k < len(r.tokens) else ""  # noqa: E731
    bare = all(t.word in COMPASS_WORDS | CORNER_POINTS for t in u.tokens) and len(u.tokens) <= 2
    if point in CORNER_POINTS:  # "on the northeast corner": a corner is a place, never a heading
        if at(u.end) in COMPASS_SIDES and not any(f.startswith("compassat_") for f in e.features):
            e.features.add("compassat_" + point)
        return
    if bare and at(u.start - 1) == "to" and at(u.start - 2) in COMPASS_WORDS:
        return  # "east to west": where it goes, said after where it comes from
    if bare and (at(u.start - 1) == "from" or at(u.start - 1) == "the" and at(u.start - 2) == "from" or
                 at(u.end) == "to" and at(u.end + 1) in COMPASS_WORDS):
        if not any(f.startswith("compassfrom_") for f in e.features):
            e.features.add("compassfrom_" + point)
        return
    if bare and (at(u.end) in COMPASS_SIDES or at(u.start - 3) in ("lane", "lanes") and
                 (at(u.start - 2), at(u.start - 1)) == ("to", "the")):  # "in the adjacent lane to the east"
        if not any(f.startswith("compassat_") for f in e.features):
            e.features.add("compassat_" + point)
        return
    if at(u.start - 1) in DESTINATION_WORDS or any(f.startswith("compass_") for f in e.features):
        return
    e.features.add(u.meaning)


def _compass_places(others: list[Entity], ego: Entity | None) -> None:
    """Compass words against the ego's heading: one heading the other way is oncoming, one heading to the ego's
    left crosses from its right; one from the north or on the north side, where the ego heads east, is on its
    left."""
    heading = _heading(ego) if ego else None
    came_from = [f[12:] for f in sorted(ego.features) if f.startswith("compassfrom_")] if ego else []
    if heading is None and len(came_from) == 1 and came_from[0] in ("north", "south", "east", "west"):
        heading = COMPASS_OPPOSITE["compass_" + came_from[0]]  # "entering the junction from the south": heading north
    if heading is None:
        return
    left, ahead = COMPASS_LEFT[heading][8:], heading[8:]
    right, back = COMPASS_OPPOSITE["compass_" + left][8:], COMPASS_OPPOSITE[heading][8:]
    for e in others:
        own = (_heading(e) or "")[8:] or None
        came = next((f[12:] for f in sorted(e.features) if f.startswith("compassfrom_")), None)
        at = next((f[10:] for f in sorted(e.features) if f.startswith("compassat_")), None)
        person = e.type == "pedestrian"  # (a northbound cyclist across an eastbound ego rides the road on its right)
        if person and own in (left, right):
            e.features.add("in_road")  # "walking east" across a northbound ego's road: across it
        if person and came is None and own in (left, right) and at is None:
            came = right if own == left else left  # "walking westbound" across a northbound ego: from its right
        side = next((s for point, s in ((left, "left"), (right, "right")) if point in (came or at or "")), None)
        # ("the northeast corner" of a westbound ego's junction is on its right: north is)
        if side and not _side(e) and (person or at is not None and came is None):
            e.features.add(f"side_{side}")  # "parked against the east curb", "runs east to west"
            if at in CORNER_POINTS and not e.features & {"ahead", "behind", "level"}:
                e.features.add("ahead")  # a corner of the junction the ego approaches
        elif e.type == "pedestrian":
            continue  # (a cyclist heading the other way comes towards the ego, as a car does)
        elif came is not None and came in (left, right):
            e.features.add(f"road_{side}")  # "a van coming from the east"
        elif came == ahead:
            e.features.add("road_straight")
        elif own == back:
            e.features.add("road_straight")  # "V3 is northbound in the opposing lane" of a southbound ego
        elif own in (left, right) and not e.features & {"road_left", "road_right", "from_left", "from_right"}:
            e.features.add("road_right" if own == left else "road_left")  # westbound across a northbound ego:
            # it comes from the ego's right


PLACED_HOW = {"parked", "in_road", "ego_lane", "in_a_side_lane", "on_board", "oncoming", "bare_left", "bare_right",
              "in_junction", "first_in_line", "ego_behind", "followed", "screening", "into_ego_lane", "from_lane",
              "from_kerb", "moves_out", "target_lane", "undertaking", "off_road", "blocks", "cuts_off"}
# features that place a vehicle by the ego or say it is met by one ('parked', 'in the ego's lane'): whoever has
# one is not the one the scene is told from
PLACE_FEATURES = HEADLINE_PLACES | {"front_left", "front_right", "back_left", "back_right", "cross_road", "crosswalk",
                                    "toward", "across_path", "overtaking", "far_side"}


def _typology_places(r: _Reader, others: list[Entity]) -> None:
    """'LTAP/OD @ signal. Ego turns left, a sedan goes straight': the crash type a text is filed under says where the
    one other vehicle is (oncoming; from a side road; the stopped lead vehicle), when the text does not."""
    words = [t.word for t in r.tokens]
    shape = next((features for k in range(len(words)) for name, features in typologies().items()
                  if tuple(words[k:k + len(name)]) == name), None)
    vehicles = [e for e in others if e.type not in V.VULNERABLE_TYPES]
    if shape is None or len(vehicles) != 1:
        return
    e = vehicles[0]
    if not e.features & PLACE_FEATURES:
        e.features |= shape - {"stop"}
        r.notes.append(f"inferred: '{e.head}' is placed as the crash type said names ({', '.join(sorted(shape))})")
    if "stop" in shape and not e.actions:
        e.actions.append((e.stage, 1, ACTION_RANK["stop"], r.tick(), "stop", None))


def _forced_reaction(units: list[Unit], k: int) -> bool:
    """'had to brake', 'was forced to stop', 'must wait': made to by someone else, not what it set out to do."""
    if k >= 1 and units[k - 1].word == "must":
        return True
    return k >= 2 and units[k - 1].word == "to" and units[k - 2].category == "word" and \
        units[k - 2].base in ("have", "force", "make", "oblige", "compel")


def _moving_in_a_place(units: list[Unit]) -> bool:
    """'coming up behind', 'approaching from the right': a place phrase that says its agent is on the move."""
    phrases = lexicon().phrases
    return any(phrases.get((t.base,)) == ("actions", "move") or phrases.get((t.word,)) == ("actions", "move")
               for u in units if u.category == "positions" for t in u.tokens)


def _waiting_to(units: list[Unit], k: int) -> bool:
    """'waiting to cross', 'waits at the kerb to cross', 'sat at the junction to turn right': the verb after 'to' is
    what a waiting agent means to do, not yet done ('waits for the van to pass': the van's, not the waiter's)."""
    if k < 2 or units[k - 1].word != "to":
        return False
    for u in reversed(units[max(0, k - 7):k - 1]):
        if u.category == "actions":
            return u.meaning == "stop"
        if u.category == "agents" or u.word in ("for", "until", "till", "and", "but", "then", "while") or \
                u.word in PRONOUNS | {"me", "us", "you"}:
            return False
    return False


LONG_STAY = re.compile(r"(?:there |put |where it was |where they were )?(?:for (?:a (?:full |good |whole )?"
                       r"(?:quarter of an hour|half an hour|half hour|hour|few minutes|couple of minutes)|"
                       r"an (?:entire |whole )?hour|(?:a good |a full |the best part of )?(?:\S+ )?minutes|hours)|"
                       r"(?:basically |just |pretty much )?(?:forever|for ever|indefinitely))\b")


def _for_long(units: list[Unit]) -> bool:
    """'there for a full quarter of an hour', '... and stayed there for ten minutes', 'not moving. Forever.': a
    stay of minutes or without end, not seconds ('for ages' is a figure of speech)."""
    said = " ".join(t.word for u in units for t in u.tokens).lstrip(", ")
    return bool(LONG_STAY.match(said) or re.search(r"\b(?:stay|stays|stayed|sat|sit|sits|remain|remains|remained|"
                                                   r"wait|waits|waited|stood|stand|stands) " + LONG_STAY.pattern, said))


def _stands_across(units: list[Unit]) -> bool:
    """'parked across the lane', 'stopped across my lane', 'sat across the road': standing athwart the way."""
    if not units or units[0].word != "across":
        return False
    rest = units[1:3]
    return any(u.category == "positions" and u.meaning in ("ego_lane", "into_ego_lane") or
               u.word in ("lane", "road", "street", "carriageway", "way", "junction") for u in rest)


def _a_stop_control(units: list[Unit]) -> bool:
    """'the all-way stop', 'a stop sign', 'the give way line', 'a red light': a place where drivers stop."""
    return any(u.category == "road" and u.meaning in ("stop", "stop+junction", "yield", "stop_line") or
               any(t.word == "red" for t in u.tokens) for u in units)


SHORT_OF = {"from", "short", "away", "off"}


def _in_time(units: list[Unit]) -> bool:
    """'I braked in time', 'stopped just in time', 'slammed the brakes like 2 feet from him': the brake ended in a
    stop short of what was ahead."""
    words = [t.word for u in units for t in u.tokens]
    short = any(w in DISTANCE_UNITS | {"foot", "inch", "inches"} and words[i + 1:i + 2] and words[i + 1] in SHORT_OF
                for i, w in enumerate(words[:5]))
    return short or any(words[i:i + 2] == ["in", "time"] for i in range(min(3, len(words))))


def _towards_an_edge(units: list[Unit]) -> bool:
    """'towards the kerb', 'over toward the centre line': the ego drifts within its lane, to one of its edges."""
    words = [t.word for u in units for t in u.tokens]
    return bool(words) and words[0] in ("towards", "toward") and bool(set(words[1:4]) & LANE_EDGES)


def _onto_the_roadside(units: list[Unit]) -> bool:
    """'(swerved right) onto the hard shoulder', 'onto the verge': a move off the carriageway to its edge, to pull
    over or get out of the way, no lane change."""
    for j, u in enumerate(units[:4]):
        if u.category == "positions" and u.meaning == "shoulder":
            return any(t.word in ("onto", "into") for x in units[:j + 1] for t in x.tokens)
        if u.category in ("agents", "actions", "comma"):
            return False
    return False


ALONG = {"up", "along", "forward", "forwards", "ahead"}


def _direction_after(r: _Reader, units: list[Unit], k: int) -> str | None:
    """'turns onto the road to the left', 'changes lanes to the right': the side right after a verb."""
    turning = units[k].meaning in ("turn", "u_turn")
    owned = next((j for j in range(k + 1, min(len(units), k + 4)) if units[j].category == "agents" and (
        units[j].meaning == "ego" and units[j].tokens[0].word in OWNERS or
        any(x.word in OWNERS for x in units[k + 1:j]))), None)  # "swings his little Fiat out into ...", "steer our van"
    into_a_lane = k + 1 < len(units) and units[k + 1].word in ("into", "to") and any(
        x.word == "lane" for x in units[k + 2:k + 5])  # "into the adjacent lane on its right": further on
    reach = (6 if turning else 4) + (owned - k if owned is not None else 0) + 2 * into_a_lane
    for j, u in enumerate(units[k + 1: k + reach], start=k + 1):
        if u.category == "positions" and u.meaning in ("side_left", "side_right", "road_left", "road_right",
                                                        "from_left", "from_right"):
            if u.tokens[0].word in ("from", "coming") or units[j - 1].word in ("from", "of") or \
                    [t.word for t in u.tokens[1:2]] == ["from"] or (  # "swerved over from the lane on my right"
                    u.meaning.startswith("road") and not turning) or (
                    not turning and any(x.word == "from" for x in units[k + 1:j])) or (
                    not turning and {"out", "from"} & set(units[k].base.split()) and not (
                        j == k + 1 and len(u.tokens) == 1) and u.tokens[0].word not in ("into", "onto") and
                    units[k + 1].word not in ("into", "onto")):
                # "pulling out of a stop on the right"; but "pulls out into the right lane": where it goes
                return None  # where it comes from, not where it goes ("pulls out right": where it goes)
            if not turning and (u.tokens[0].word in ("on", "at", "beside", "alongside") or units[j - 1].word == "on") and \
                    {units[k].tokens[-1].word, *(x.word for x in units[k + 1:j])} & ALONG:
                return None  # "creeping up on my inside": where it is as it moves, not where it steers to
            if not turning and u.tokens[0].word == "on" and units[k + 1].word in ("by", "past") and any(
                    e.is_ego and any(a[4] in ("lane_left", "lane_right") for a in e.actions) for e in r.entities):
                return None  # "ego moves over to the R lane, amb goes by on L": past, in the lane the ego left
            r.mark(u)
            side, u.meaning = u.meaning.rsplit("_", 1)[-1], "used"
            return side  # (by its meaning: "the nearside lane" is the left where traffic keeps left)
        if j == owned:
            continue  # "swings his little Fiat out into the left lane": the vehicle steered, then where it goes
        if u.category in ("actions",) or (u.category == "agents" and u.meaning != "none"):
            return None
    return None


def _the_ego_acts_last(before: Clause, clause: Clause) -> bool:
    """'before passing it' after 'a van ... forces the ego to wait': an -ing clause with no subject after a time
    word, done to 'it' (the other), is done by the ego named after the other's verb, whose own verb came last
    ('a truck lets the ego go before turning left' is the truck's turn)."""
    units, prev = clause.units, before.units
    if clause.link not in ("before", "after", "while", "without") or not units or units[0].category != "actions" \
            or not units[0].tokens[0].word.endswith("ing") or not any(u.word in ("it", "them") for u in units[1:3]):
        return False
    ego_at = next((i for i, u in enumerate(prev) if u.category == "agents" and u.meaning == "ego"), None)
    return ego_at is not None and any(u.category == "actions" for u in prev[ego_at + 1:]) and any(
        u.category == "agents" and u.meaning not in ("ego", "none") for u in prev[:ego_at])


MADE_WAY = {"by", "past", "through", "pass", "go", "overtake"}


def _makes_way_for_the_subject(units: list[Unit], i: int) -> bool:
    """'(an ambulance came up behind me in my lane,) moved over to the right lane to let them by': a verb after a
    comma, made to let 'it' or 'them' by, is made for the clause's subject by another (the ego), not by it."""
    if i < 1 or units[i - 1].category != "comma":
        return False
    return any(u.tokens[-1].word in ("let", "letting", "allow", "allowing") and
               units[k + 1].word in ("it", "them", "him", "her") and units[k + 2].word in MADE_WAY
               for k, u in enumerate(units[i + 1:i + 4], i + 1) if k + 2 < len(units))


def _the_speakers_obligation(r: _Reader, clause: Clause) -> bool:
    """'Had to take over,', 'Needed to brake': a sentence opened by an obligation with no subject and no one named,
    in a text a speaker tells, is the speaker's."""
    units = clause.units
    return len(units) >= 2 and [u.word for u in units[:2]] in (["had", "to"], ["have", "to"], ["needed", "to"],
                                                                ["got", "to"]) and \
        (units[0].start == 0 or r.tokens[units[0].start - 1].sentence != units[0].tokens[0].sentence) and \
        not any(u.category == "agents" for u in units) and any(t.word in SPEAKERS for t in r.tokens)


def _read_clause(r: _Reader, clause: Clause, previous_subject: list[Entity], recent: list[Entity],
                 pending: list[Entity] | None = None) -> list[Entity]:
    units = clause.units
    stage = clause.stage
    _side_roads(units)
    phrases: list[NounPhrase] = []
    roles = [i + 1 for i, u in enumerate(units[:-1]) if u.category == "agents" and u.meaning not in (
        "ego", "none", "generic") and units[i + 1].category == "agents" and units[i + 1].base in ROLE_NOUNS]
    for i in roles:  # "a pedestrian target", "police NPC": the role noun says no type, and is left out
        r.mark(units[i])
    if roles:
        units = clause.units = [u for i, u in enumerate(units) if i not in roles]
    r.last_mentions, r.clause_mentions = r.clause_mentions, []
    heads = [i for i, u in enumerate(units) if u.category == "agents" and not (  # "an adult pedestrian"
        u.meaning not in ("ego", "none") and i + 1 < len(units) and units[i + 1].category == "agents"
        and units[i + 1].meaning not in ("ego", "none")) and not _model_named_before(units, i) and \
        not _a_model_then_its_noun(units, i) and not (
        u.tokens[-1].possessive and u.meaning in ("car", "pedestrian") and u.tokens[-1].base in DRIVING_PEOPLE | {"driver"} and
        i + 1 < len(units) and units[i + 1].category == "agents" and units[i + 1].meaning == "none")]
    # ("the other driver's passenger got out": the passenger, on board that car, no one on the road)
    lo = 0
    for i in heads:
        np = _resolve(r, units, i, lo, stage, recent)
        phrases.append(np)
        if np.entity is not None:
            r.clause_mentions.append(np.entity)
            if not np.entity.is_ego and units[np.first].word == "one" and np.entity.count == 1:
                r.listed_one = (np.entity, units[np.first].tokens[0].sentence)
            if not np.introduced and np.first > 0 and units[np.first - 1].word == "between" and \
                    np.entity.count > 1 and not np.entity.is_ego and np.entity.type not in V.VULNERABLE_TYPES:
                np.entity.features.add("screening")  # "... from between the parked cars": those said before
        lo = i + 1
    for np in phrases:  # "a family of four", "a group of six cyclists" ends in its noun; "a convoy of 3"
        e, i = np.entity, np.index
        if e is None or not np.introduced or e.is_ego or units[i].base.split()[-1] not in GROUP_NOUNS or \
                i + 2 >= len(units) or units[i + 1].word != "of" or units[i + 2].category not in ("numbers", "number") \
                or (i + 3 < len(units) and units[i + 3].category == "agents"):
            continue
        value = _word_number(units[i + 2].tokens[0])
        if value is not None and 1 <= value <= MAX_AGENTS_PER_MENTION:
            e.count = e.group_open = int(value)
            np.plural = value > 1
            r.mark(units[i + 1]), r.mark(units[i + 2])
            units[i + 2] = Unit(units[i + 2].start, units[i + 2].end, "word", "of", units[i + 2].tokens)
    for i, u in enumerate(units):  # "kids are crossing, three of them": the count of the group just named
        if u.category in ("numbers", "number") and i + 2 < len(units) and units[i + 1].word == "of" and \
                units[i + 2].word in ("them", "those", "these"):
            group = next((np.entity for np in reversed(phrases) if np.entity is not None and np.plural
                          and np.index < i), None)  # named before: "one of those evenings, ... three cyclists"
            group = group or next((e for e in reversed(recent) if e.count > 1), None)
            if group is not None:
                value = _word_number(u.tokens[0])
                r.mark(u), r.mark(units[i + 1]), r.mark(units[i + 2])
                if value is not None and 0 < value < group.count and group.stage == stage and \
                        group not in [np.entity for np in phrases]:  # "three wait; one of them crosses": a member
                    members = [_member(r, [group]) for _ in range(int(value))]
                    for member in [m for m in members if m is not None]:
                        phrases.append(NounPhrase(member, i + 2, i))
                    units[i] = Unit(u.start, u.end, "word", "of", u.tokens)
                elif value is not None and 1 < value <= MAX_AGENTS_PER_MENTION:
                    group.count = int(value)  # "kids are crossing, three of them": the group's count ("two kids
                    # on the pavement, one of them in red": still two)
                units[i + 2] = Unit(units[i + 2].start, units[i + 2].end, "word", "of", units[i + 2].tokens)
    pronouns, together = [], set()
    for i, u in enumerate(units):
        other = u.word == "other" and u.category == "word" and i + 1 < len(units) and (
            units[i + 1].category == "actions" or units[i + 1].word in AUXILIARIES)  # "one is stopped on the right,
        # and the other comes from the left": the group's other member, as its subject
        one_after = i + 1 < len(units) and units[i + 1].word == "one" and units[i + 1].category in ("numbers", "word")
        acts = lambda k: k < len(units) and units[k].category in ("actions", "behaviours")  # noqa: E731
        said_first = u.category == "positions" and [t.word for t in u.tokens] in (
            ["the", "first", "one"], ["first", "one"]) and acts(i + 1)  # "the first one brakes"
        article = i > 0 and units[i - 1].word == "the"
        lead = i - article  # where the noun phrase starts; terse writing drops the article ("first one brakes")
        if (said_first or (u.word in ORDINAL_MEMBERS - {"former", "latter"} or other) and article and (one_after or not (
                i + 1 < len(units) and units[i + 1].category in ("agents", "numbers", "number"))) or
                u.word in ORDINAL_MEMBERS and one_after and acts(i + 2) or
                u.category == "word" and u.word in ORDINAL_NUMBERS and acts(i + 1) and (
                    i == 0 or units[i - 1].word in ("and", ",", "but", "then")) and
                0 < ORDINAL_NUMBERS[u.word] <= _last_count(r)) and not any(  # "two cars wait, second turns left"
                np.first <= i <= np.index for np in phrases) and not (lead > 0 and units[lead - 1].category ==
                                                                      "positions") \
                and not _the_ego_is(units, lead - 1):
            # ("mine was the second one", "the ego is the last one": the ego's place among them, no member of its own)
            member = _member(r, recent) or _listed_single(r, u.word)  # "two motorbikes, the first on the left and
            # the second on the right"; "a car and a truck wait; the first turns right"
            if member is not None:  # "three cars in a line; the first one brakes, the second one stops behind it"
                r.mark(u)
                if one_after:
                    r.mark(units[i + 1])
                phrases.append(NounPhrase(member, i + one_after, i if said_first else lead))
            continue
        value = _word_number(u.tokens[0]) if u.category in ("numbers", "number") and len(u.tokens) == 1 else None
        if value is not None and 2 <= value <= MAX_AGENTS_PER_MENTION and not any(
                np.first <= i <= np.index for np in phrases) and i + 1 < len(units) and \
                units[i + 1].category == "positions":  # "nine pedestrians: four on the left, five on the right"
            part = _part_of_group(r, int(value))
            if part is not None:
                r.mark(u)
                phrases.append(NounPhrase(part, i, i, plural=True))
            continue
        if value is not None and 1 <= value <= MAX_AGENTS_PER_MENTION and _more_said_alone(units, i) and \
                not any(np.first <= i <= np.index for np in phrases):
            kin = next((np.entity for np in phrases if np.index < i and np.entity is not None and
                        not np.entity.is_ego), None) or next((e for e in reversed(recent) if not e.is_ego), None)
            if kin is not None:  # "a squad car stops across the front of me. Then two more pull up behind me"
                more = _one_more_like(r, kin, clause.stage, f"'{u.word} more' are more of the {kin.head}")
                more.count = more.group_open = int(value)
                more.named_of = kin  # where it is, unless said of them ("two more come straight after it")
                r.mark(u)
                r.mark(units[i + 1])
                phrases.append(NounPhrase(more, i + 1, i, introduced=True, plural=value > 1))
                continue
        one_more = u.word == "another" or u.word in ("second", "third", "fourth", "fifth") and i + 1 < len(units) and (
            i > 0 and units[i - 1].word in ("a", "an") and units[i + 1].category in ("positions", "actions") or
            (units[i - 1].word if i > 0 else clause.link) in ("while", "whilst", "and", "with", ",") and
            units[i + 1].category == "actions" and _past_the_count(r, u.word))  # "while a third walks along the
        # sidewalk", "two pedestrians cross while third walks": one
        # more ("a second before you did", "a second to react": a moment)
        if one_more and u.category == "word" and not any(np.first <= i <= np.index for np in phrases) \
                and _stands_alone(units, i):
            kin = next((np.entity for np in phrases if np.index < i and np.entity is not None and
                        not np.entity.is_ego), None) or next((e for e in previous_subject if not e.is_ego), None) or \
                next((e for e in reversed(recent) if not e.is_ego), None)  # the subject before: "one of them cuts
            # in front of the car, and another is undertaking": another of them
            # "two mopeds; one cuts in, another undertakes": the group's next member; "a car ahead and another
            # behind": one more of the kind named last, placed apart
            member = None if kin is None else _member(r, recent) if kin.parent is not None else \
                _one_more_like(r, kin, clause.stage, f"'{u.word}' is another {kin.head}", listed_after=kin)
            if member is not None:
                r.mark(u)
                if i + 1 < len(units) and units[i + 1].word == "one":
                    r.mark(units[i + 1])
                phrases.append(NounPhrase(member, i, i, introduced=True))
                continue
        if u.word == "one" and u.category in ("word", "numbers") and not any(np.first <= i <= np.index
                                                                              for np in phrases) \
                and not (i + 1 < len(units) and units[i + 1].category in ("agents",)) \
                and not (i + 1 < len(units) and units[i + 1].word in NOT_A_MEMBER_AFTER_ONE):
            j = i - 1
            while j >= 0 and units[j].category == "word" and units[j].word not in ("a", "an", "another") and \
                    units[j].word not in lexicon().function_words:
                j -= 1  # "a blue one", "another red one"
            kin = next((e for e in reversed(recent) if not e.is_ego), None)
            if j >= 0 and j < i - 1 and units[j].word in ("a", "an", "another") and kin is not None:
                member = _one_more_like(r, kin, clause.stage, f"'a ... one' is another {kin.head}")
                r.mark(u)  # "a red car in front, and a blue one behind it": another car
                phrases.append(NounPhrase(member, i, i, introduced=True))
                continue
            if _the_ego_is(units, i - 3) or _the_ego_is(units, i - 2):
                continue  # "mine was the second one", "ego is last one": the ego's place among them, no member
            placed_one = _the_one_placed(r, units, i) or _the_one_by_its_paint(r, units, i)  # "the one in front
            # slammed on his brakes": that member; "a red car and a blue car ... the red one": that car
            extra = _one_more_of_a_placed_group(r, units, i, phrases) if placed_one is None else None
            member = placed_one or (None if extra else _member(r, recent))  # "two cars, one in front and one behind"
            if extra is not None:
                r.notes.append(f"inferred: 'one' placed apart from the {extra.head}s placed before is one more")
            listed = extra or (_enumerated_one(r, units, i, phrases) if member is None else None)
            if listed is not None:
                member = _one_more_like(r, listed, clause.stage, f"'one ...' in a list after 'one {listed.head}' is "
                                        f"another {listed.head}", listed_after=listed)
                r.listed_one = (member, u.tokens[0].sentence)  # "one car in front, one on the left": single agents
                r.mark(u)
                phrases.append(NounPhrase(member, i, i, introduced=True))
                continue
            if member is not None:
                r.mark(u)
                phrases.append(NounPhrase(member, i, i))
            continue
        if u.word in ("others", "rest", "remaining") and i > 0 and units[i - 1].word == "the" and \
                not any(np.first <= i <= np.index for np in phrases) and (rest := _rest_of_a_group(r)) is not None:
            head = i + (i + 1 < len(units) and (units[i + 1].category in ("numbers", "number") or
                                                units[i + 1].word == "ones"))  # "the remaining two"
            for said in units[i:head + 1]:
                r.mark(said)
            phrases.append(NounPhrase(rest, head, i - 1, plural=True))  # "two of them cross and the others wait"
            continue
        if _names_them_together(units, i) and not any(np.first <= i <= np.index for np in phrases):
            together.add(i)  # "the pair turn left", "the two of them", "each turns left": they
            pronouns.append(i)
            continue
        if u.category == "word" and u.word == "all" and i > 0 and units[i - 1].category == "agents" and \
                units[i - 1].word in ("we", "you") and not any(np.first <= i <= np.index for np in phrases):
            pronouns.append(i)  # "three other bikes following you ... you all turn left": the ego and its company
            continue
        if u.category == "word" and u.word in PRONOUNS and not any(np.first <= i <= np.index for np in phrases):
            if u.word == "both" and i + 1 < len(units) and units[i + 1].category in ("agents", "word") and \
                    (units[i + 1].category == "agents" or units[i + 1].word in DEFINITE):
                continue  # "both the truck and the pedestrian": coordination, not a pronoun
            if u.word == "itself" and i > 0 and units[i - 1].word == "by":
                r.mark(u)
                continue  # "the car brakes all by itself": on its own, no one else named
            pronouns.append(i)
    for i in pronouns:
        u = units[i]
        r.mark(u)
        if u.word in ("both", "they", "them") or i in together:
            group = [e for e in recent if not e.is_ego][-2:] or list(previous_subject)
            named_here = [np.entity for np in phrases
                          if np.index < i and np.entity is not None and not np.entity.is_ego]
            if u.word == "both" and len(named_here) >= 2:  # "a car from the left lane and a motorcycle from the right
                phrases.append(NounPhrase(named_here[-2], i, i, plural=True, group=named_here[-2:]))  # lane both
                continue  # cut in": the two just named
            if u.word == "both" and named_here and named_here[-1].count == 2:
                phrases.append(NounPhrase(named_here[-1], i, i, plural=True, group=[named_here[-1]]))
                continue  # "two cars ahead of us in our lane both braking to a stop": the pair just named
            if u.word == "both" and [x.word for x in units[i + 1:i + 2]] == ["of"] and i + 2 < len(units) and \
                    units[i + 2].category == "agents" and units[i + 2].meaning == "ego":
                group = [e for e in recent if not e.is_ego][-1:] + [_ego_entity(r, stage)]  # "both of us": the
                # ego and the other one
            if u.word == "both" and i > 0 and units[i - 1].word in ("we", "us") and units[i - 1].category == "agents":
                group = [e for e in recent if not e.is_ego][-1:]  # "we both have to stop": the ego (said by 'we')
                # and the other one
            elif (u.word == "both" or i in together and u.word in ("pair", "two", "duo") or
                  [x.word for x in units[i + 1:i + 2]] == ["both"]) and \
                    len([e for e in recent if not e.is_ego and e.count == 1]) == 1 == len(
                        [e for e in recent if not e.is_ego]) and any(e.is_ego for e in recent):
                group = group + [_ego_entity(r, stage)]  # "a motorcycle stops beside the ego ... both go": the two
            if group:
                phrases.append(NounPhrase(group[0], i, i, plural=True, group=group))
                if u.word == "them" and i > 0 and units[i - 1].word == "between" and group[0].count > 1 and \
                        group[0].type not in V.VULNERABLE_TYPES:
                    group[0].features.add("screening")  # "two vans parked on my right ... ran out from between
                    # them": the vans a crosser emerges from
        elif u.word == "all":
            company = [e for e in recent if not e.is_ego and e.type != "pedestrian"]
            if company:
                phrases.append(NounPhrase(company[0], i, i, plural=True, group=company))
        elif u.word == "former" or u.word == "latter":
            pool = sorted([e for e in recent if not e.is_ego][-2:], key=lambda e: e.said_at)  # in the order named,
            # not as last mentioned ("the former changes lane, the latter stops": the first named is the former)
            if pool:
                phrases.append(NounPhrase(pool[0] if u.word == "former" else pool[-1], i, i))
        else:
            target = _ego_entity(r, stage) if _placed_by_the_same_pronoun(r, u) else \
                _pronoun(units, i, phrases, r.surface or previous_subject, recent)
            if target is None and u.word == "it" and _a_group(r.surface or previous_subject):
                target = _ego_entity(r, stage)  # "two trucks come the other way, so it has to wait": the ego
            if target is None and _a_drivers_verb_after(units, i) and any(e.type == "pedestrian" for e in recent):
                target = _ego_entity(r, stage)  # "a pedestrian ran across in front of her, she swerved": the one
                # at the wheel, told of in the third person
            if target is None and u.word in ("she", "he") and _on_foot_in_the_scene(units, i) and \
                    not any(e.type == "pedestrian" for e in r.entities):
                target = Entity(r.new_key(), "pedestrian", False, stage, head=u.word)
                r.entities.append(target)  # "Mrs. Feeney was in that crosswalk? ... She was crossing from my
                r.notes.append(f"inferred: '{u.word}' on foot is a person in the scene")  # left": named before
                phrases.append(NounPhrase(target, i, i, introduced=True))  # only by her name
            elif target is not None:
                phrases.append(NounPhrase(target, i, i))
    phrases.sort(key=lambda p: p.index)
    phrases = _appositions(r, units, phrases)
    phrases = _members_listed(r, clause, phrases, recent)
    phrases = _relative_says_what_it_is(r, clause, phrases)
    _shared_premodifier(units, phrases)
    denied = {i for i, u in enumerate(units) if u.category == "actions" and _denied_verb(units, i)}
    verbs = [i for i, u in enumerate(units) if u.category == "actions" and u.meaning not in ("try",)
             and not any(np.first <= i < np.index for np in phrases) and i not in denied
             and not _named_manoeuvre(units, i) and not _requested(units, i) and not _planned(units, i)
             and not _weighed(units, i)]
    if verbs and not any(np.index < verbs[0] and np.entity is not None for np in phrases) and any(
            u.category == "road" and u.meaning != "junction" for u in units[max(0, verbs[0] - 2):verbs[0]]):
        verbs = []  # "the light turns red": the subject is a signal, no agent acts ("the junction is entered by
        # two cars": a place is the subject of a passive, its agent acts)
    verbs = [i for i in verbs if not _signal_change(units, i)]
    for i in sorted(denied):  # "neither of them enters the ego's lane": no one goes where a denied verb goes
        for place in units[i + 1:]:
            if place.category in ("comma", "actions", "agents", "sequence"):
                break
            if place.category == "positions" and place.meaning in WAYS_IN:
                place.meaning = "used"
    for i in sorted(denied):  # "instead of waiting behind him": no one waits there, nor is placed by it
        if _instead_of(units, i):  # (a verb passed over is a denied one)
            for place in units[i + 1:]:
                if place.category in ("comma", "actions", "agents", "sequence"):
                    break
                if place.category == "positions":
                    place.meaning = "used"
    for i, u in enumerate(units):
        if u.category == "actions" and u.meaning == "try":
            r.mark(u)

    # the passive: "the ego is approached from behind by an ambulance"
    by = next((i for i, u in enumerate(units) if u.category == "word" and u.word == "by" and i > 0
               and (verbs and i > verbs[0] or units[i - 1].word.endswith(("ed", "en")))
               and any(np.index > i for np in phrases)), None)
    if by is not None and verbs and units[verbs[0]].tokens[-1].word in ("turn", "change", "stop", "maneuver") and \
            verbs[0] < by - 1 and \
            units[by - 1].word not in LIGHT_PARTICIPLES and units[by - 1].category != "actions":
        by = None  # "a right turn is prevented by a pedestrian": the pedestrian does not turn
    made_to = by is not None and any(
        u.category == "word" and u.word in ("kept", "held", "forced", "made", "left") and k + 1 < by
        and (units[k + 1].category == "actions" or units[k + 1].word == "to") for k, u in enumerate(units[:by]))
    waiting = by is not None and verbs and units[verbs[0]].base in (
        "keep waiting", "be kept waiting", "kept waiting", "held up", "stuck", "held")
    if made_to or waiting:
        by = None  # "the ego is kept waiting by two cars": the ego waits
    if by is not None and verbs and units[verbs[0]].meaning == "stop" and verbs[0] == by - 1:
        by = None  # "the ego is stopped by a police officer": the ego stops
    if by is None:
        by = _actor_of_a_named_action(units, verbs, phrases)
    subject: list[Entity] = []
    objects: list[NounPhrase] = []
    first_verb = verbs[0] if verbs else len(units)
    if by is not None:
        actor = next(np for np in phrases if np.index > by)
        subject = actor.group or [actor.entity]
        if any(u.category == "positions" and u.meaning == "ego_lane" for u in units[:by]) and actor.entity:
            actor.entity.features.add("into_ego_lane")  # "the ego's lane is entered by a motorbike"
        objects = [np for np in phrases if np is not actor]
        if not objects and clause.link == "," and verbs and verbs[0] == 0 and previous_subject:
            objects = [NounPhrase(previous_subject[0], -1, -1, group=list(previous_subject))]  # "the ego drives
            # along, followed by a truck": the participle is said of the clause before's subject
        r.mark(units[by])
        r.passive = clause
    else:
        before = [np for np in phrases if np.index < first_verb and np.entity is not None
                  and not _is_reference(units, np) and not (np.first == 1 and units[0].word in LETTING and
                                                             not np.entity.is_ego)]
        # ("our vehicle slows, lets the bus pass, and then changes lanes": the bus is let; the vehicle goes on)
        seer = next((j for j in range(len(before) - 2, -1, -1) if before[j].entity is not None
                     and (before[j].entity.is_ego or before[j].entity.head in DRIVERS) and any(
                         u.tokens[0].base in PERCEIVING for u in units[before[j].index + 1:before[j + 1].first])),
                    None)  # "I admit I was looking at that and did not notice the car in front had stopped"
        seen = seer is not None and not any(u.word == "and" for u in units[before[seer + 1].index + 1:first_verb])
        # ("I only spotted it at about 30 metres and had to swing out": the speaker swings out, not what was seen)
        if seen:
            before = before[seer:]
        wanted = len(before) >= 2 and before[0].entity.is_ego and 0 < first_verb < len(units) and (
            units[first_verb - 1].word == "to" or first_verb == before[1].index + 1 and
            units[first_verb].tokens[0].word.endswith(("ed", "ing"))) and any(
            u.tokens[0].base in WANTING for u in units[before[0].index + 1:before[1].first])
        # "I want a car to cut in", "I'd like a truck parked on the right": the one wanted acts
        if seen or wanted:
            before = before[1:2]  # "I saw a van pull out", "I want a car to cut in": the one seen or wanted acts
        elif len(before) >= 2 and verbs and not any(
                u.category == "comma" or u.word in ("and", "or", "with", "plus", "both", "&")
                for u in units[before[0].index + 1:before[1].first]) and any(
                u.category == "actions" for u in units[before[0].index + 1:before[1].first]):
            before = before[:1]  # "the AV handle(s) a cyclist swerving...": the first is the subject, then its object
        elif len(before) >= 2 and before[0].entity.is_ego and verbs and \
                units[first_verb].tokens[0].word.endswith("ing") and all(
                u.category == "comma" for a, b in zip(before, before[1:]) for u in units[a.index + 1:b.first]) and all(
                u.category != "word" or u.word not in ("and", "or", "with", "plus", "both", "all", "&", "each")
                for u in units[before[0].index + 1:first_verb]):
            before = before[1:]  # "Ego van, oncoming truck turning left": a terse list; the ego is an item of its own
        if len(before) >= 2 and verbs and any(u.category == "word" and u.word in COPULAS for u in
                                              units[before[0].index + 1:before[1].first]) and \
                units[before[1].first - 1].word == "and":
            before = before[1:]  # "the ego is on a two-lane road and a motorbike in the right lane, slightly ahead,
            # cuts in": the first has a predicate of its own
        inverted = _inverted_subject(units, phrases, first_verb) if not before and verbs else None
        if inverted is not None:  # "from the right comes a bus": the place first, then the verb, then who
            before = [inverted]
        for np in before:
            subject += np.group or [np.entity]
        joined = any(u.category == "word" and u.word in ("and", "or") for u in units[:first_verb])
        labelled = before and units[0].word in ("and", "or") and before[0].entity.label and \
            all(e.label for e in pending)
        if pending and (len(before) >= 2 or labelled) and joined and verbs and clause.link in ("", ","):
            # "an ambulance, a police car and a van approach" (not "... a slow semi, so I signaled and I moved");
            # "Vehicle 2 (fire engine) and Vehicle 3 (police car) approached"
            subject = list(pending) + subject
        objects = [np for np in phrases if (np.index > first_verb or _is_reference(units, np)) and np is not inverted]
    subject = [e for e in subject if e is not None]
    subject = [e for e in subject if not any(x.parent is e for x in subject)]  # "of the two buses, the first": it
    if not subject and verbs and any(u.category == "agents" and u.base in ("everyone", "everybody")
                                     for u in units[:verbs[0]]):
        subject = [_ego_entity(r, stage)]  # "everyone pulling over": the ego among them
    afterthought = not subject and not verbs and clause.link == "," and bool(units) and all(
        u.category in ("positions", "word") for u in units) and any(u.category == "positions" for u in units) and \
        previous_subject and all(e.is_ego for e in previous_subject)
    placed_last = next((e for e in reversed(r.last_mentions) if not e.is_ego), None) if afterthought else None
    if placed_last is not None:
        subject = [placed_last]  # "driving with two people walking on the pavement on her right, a bit ahead": theirs
    unnamed = False
    if not subject:
        if clause.antecedent is not None:
            subject = [clause.antecedent]
        elif clause.condition:
            subject = []
        elif verbs and any(np.entity is None and units[np.index].meaning == "none" and
                           units[np.first].word in INDEFINITE | DEFINITE and np.first == 0 and
                           first_verb - 3 <= np.index < first_verb for np in phrases):
            verbs = []  # "a bus stops and a dog runs out": a new subject that names no agent; the bus did not run
            # (but "sirens going, and turned left": the same one goes on)
            unnamed = True
        elif verbs and r.unnamed_subject and clause.link in ("and", ",", "but") and verbs[0] == 0:
            verbs = []  # "a deer stood in the ditch and never moved": the deer goes on
            unnamed = True
        elif previous_subject and (clause.link in ("and", "or", ",", "but", "so") or clause.link in ("then", "") and
                _goes_on_in_the_past(r, units, verbs, previous_subject)) and not clause.after_subordinate \
                and not _imperative_on(units, verbs, phrases, previous_subject) \
                and not (r.after_verbless and verbs and verbs[0] == 0 and _bare_verb(units[0])):
            # "ambulance behind with siren, pull over to the right": an order after a verbless description
            subject = list(previous_subject)
        elif previous_subject and clause.link in PARTICIPLE_LINKS and verbs and verbs[0] == 0 and \
                units[0].tokens[0].word.endswith("ing"):
            subject = list(previous_subject)  # "a cyclist rode ahead of me before turning left": the cyclist turns
        elif previous_subject and clause.link in ("until", "till") and verbs and verbs[0] == 0 and \
                len(units) <= 2 and not units[0].tokens[0].word.endswith("ing"):
            subject = list(previous_subject)  # "the front car brake suddenly until stop": until it stops
        elif previous_subject and clause.link == "" and verbs and verbs[0] == 0 and units[0].tokens[0].opened_by == ";" \
                and not _bare_verb(units[0]):  # ("a truck stopped ahead; overtake it": an order to the ego)
            subject = list(previous_subject)  # "a car in the left lane; changes lane to the right": the same car
        elif previous_subject and clause.link == "" and verbs and \
                _said_of_another(r, units[verbs[0]].tokens[0], previous_subject):
            subject = list(previous_subject)  # "He swerves in front of me and stops dead. Sits there honking": him
        elif verbs and verbs[0] == 0 and clause.link == "" and _from_the_tellers_side(units) and \
                any(not e.is_ego and e.type not in V.VULNERABLE_TYPES for e in r.last_mentions):
            subject = [next(e for e in reversed(r.last_mentions) if not e.is_ego and e.type not in
                            V.VULNERABLE_TYPES)]  # "Nearly got taken out by a scooter. Came from my right": no
            # teller comes from their own side; the one named last did
        elif verbs and any(np.entity is None and (units[np.index].meaning == "none" or _said_not_there(units, np)) and
                           first_verb - 3 <= np.index < first_verb and
                           not any(x.category == "comma" for x in units[np.index:first_verb]) for np in phrases):
            verbs = []  # "a deer ran out": its subject names no agent; nobody of the scene ran; nor did "no
            # vehicles are parked on the street"
            unnamed = True
        elif verbs:
            inside = frozenset(k for np in phrases for k in range(np.first, np.index + 1))
            subject = [e for e in [_implied(r, units, stage, verbs, inside)] if e is not None]
    r.unnamed_subject = unnamed or not subject and r.unnamed_subject and not verbs and not any(
        np.entity is not None for np in phrases)
    if any(e.includes_ego for e in subject):  # "three cars including the ego wait": the ego waits too
        subject = subject + [_ego_entity(r, stage)]
    if clause.condition or clause.background:
        strength = 1
    else:
        strength = 2

    main_verbs = []
    participles: dict[int, list[Entity]] = {}
    for i in verbs:
        if i > 1 and units[i - 1].word == "to" and i - 2 in participles:
            participles[i] = participles[i - 2]  # "behind a car waiting to turn left": the car's turn to come
            for e in participles[i]:
                _modify(r, e, units[i], stage, 1, units, i)
            continue
        if i - 1 in participles and units[i].tokens[0].word in ("at", "in", "on"):
            participles[i] = participles[i - 1]  # "overtakes a bus stopped at a bus stop": where the bus stands
            for e in participles[i]:
                _modify(r, e, units[i], stage, 1, units, i)
            continue
        owner = _participle_owner(units, i, phrases, subject, verbs)
        if owner is not None and not main_verbs and participles and not any(v > i for v in verbs) and \
                all(e in subject for owners in participles.values() for e in owners) and owner.entity not in subject \
                and not (owner.first > 0 and units[owner.first - 1].word in ("with", "while")) and \
                (not units[i].tokens[0].word.endswith("ing") or units[i - 1].word in AUXILIARIES):
            owner = None  # "a cyclist riding ahead of it swerved left": the subject's participle, then its finite verb
            # ("two cars parked, with a bus approaching": 'with' gives the bus its own participle; "the ego turning
            # right did not wait for a crowd crossing": the crowd's, where the finite verb was denied)
        if owner is not None:
            participles[i] = [e for e in owner.group or [owner.entity] if e is not None]
            for e in owner.group or [owner.entity]:
                if e is not None:
                    _modify(r, e, units[i], stage, 1, units, i)
        else:
            main_verbs.append(i)
    if not main_verbs and not any(np.index < 2 for np in phrases) and len(units) > 1 and \
            units[0].category == "positions" and \
            units[0].meaning in ("side_left", "side_right") and len(units[0].tokens) == 1 and \
            units[1].category == "word" and units[1].word in ("at", "into", "onto", "on"):
        ego = _ego_entity(r, stage)  # terse: "right at the stop sign"
        r.mark(units[0])
        ego.actions.append((stage, strength, ACTION_RANK["turn_left"], r.tick(), "turn_" + units[0].word, None))
        units[0].meaning = "used"
    ego_at = next((np.index for np in phrases if np.entity is not None and np.entity.is_ego), None)
    if not main_verbs and len(subject) == 1 and subject[0].is_ego and ego_at is not None and any(
            u.word in COPULAS for u in units[ego_at + 1:ego_at + 3]) and any(
            u.category == "road" and not _denied(units, k) and u.tokens[0].word not in ("from", "of") and (
                u.meaning in ("stop", "stop_line") or u.meaning == "traffic_light" and
                any(t.word == "red" for t in u.tokens)) for k, u in enumerate(units) if k > ego_at):
        subject[0].actions.append((stage, strength, ACTION_RANK["stop"], r.tick(), "stop", None))  # "we're at a red"
        # (not "is 20 m from the stop line": a distance to it)
    if not main_verbs and len(subject) == 1 and subject[0].is_ego:  # terse: "ego right at lights", "ego left"
        ego_np = next((p for p in phrases if p.entity is subject[0]), None)
        after = units[ego_np.index + 1] if ego_np is not None and ego_np.index + 1 < len(units) else None
        if after is not None and after.category == "positions" and after.meaning in ("side_left", "side_right") \
                and len(after.tokens) == 1:
            r.mark(after)
            after.meaning = "used"
            subject[0].actions.append((stage, strength, ACTION_RANK["turn_left"], r.tick(),
                                       "turn_" + after.tokens[-1].word, None))
    _ego_turn_in_a_place(r, units, stage)
    for u in units:
        words = {t.word for t in u.tokens}
        if u.category == "actions" and u.meaning == "try" and {t.base for t in u.tokens} & {"signal", "indicate"} \
                and words & set(SIDES):
            for e in subject:  # "signalled right and moved out to turn": the side of the turn it then makes
                e.features.add("signals_" + ("left" if "left" in words else "right"))
    if main_verbs and units[0].word == "instead" and len(units[0].tokens) == 1:
        for e in subject:  # "we needed to give way. Instead you carried on": what was done in place of the other
            e.actions = [a for a in e.actions if a[0] != stage]
    for i in main_verbs:
        made = _made_to(units, i, phrases)
        if not made and i > 0 and units[i - 1].category == "actions" and units[i - 1].tokens[0].base == "let" and \
                units[i - 1].tokens[-1].word == "ego":
            made = [_ego_entity(r, stage)]  # "stops, letting the ego go straight": the ego goes, the one letting stops
        if not made and subject and not any(e.is_ego for e in subject) and _makes_way_for_the_subject(units, i):
            made = [_ego_entity(r, stage)]  # "came up behind me, moved over to let them by": the ego moved over
        for e in made or subject:
            _modify(r, e, units[i], stage, 0 if _only_possible(units, i) else strength, units, i)
            if e.is_ego and by is not None and units[i].meaning == "move" and units[i].base in STEERING:
                side = next((u.meaning[5:] for k, u in enumerate(units[:i]) if u.category == "positions"
                             and u.meaning in ("side_left", "side_right")
                             and any(x.word == "lane" for x in units[max(0, k - 3):k])), None)
                if side:  # "the lane to its right is moved into by the ego"
                    e.actions.append((stage, strength, ACTION_RANK["lane_left"], r.tick(), "lane_" + side, side))
        _relational(units[i], units, i, subject, objects if by is not None else
                    [p for p in phrases if p.index > i and p.entity not in subject])
        pulled = next((p.entity for p in phrases if p.first == i + 1 and p.entity is not None), None) \
            if [t.base for t in units[i].tokens] == ["pull", "over"] else None
        if pulled is not None and not pulled.is_ego and pulled not in subject:
            pulled.actions.append((stage, 1, ACTION_RANK["stop"], r.tick(), "stop", None))  # "pulled over a van":
            # the van stands where it was pulled over, by the one that pulled it over
            if not pulled.features and subject and not subject[0].is_ego:
                pulled.relative_to = pulled.relative_to or subject[0]
                pulled.road_type = pulled.road_type or subject[0].road_type
        if units[i].meaning == "stop" and any(e.is_ego for e in made) and \
                {t.base for t in units[i].tokens} & {"stop", "halt", "standstill"}:  # to stop, not just to brake
            causers = subject if units[0].word not in CAUSATIVES else previous_subject
            for e in causers:  # "a patrol car swerved in front of the taxi, forcing it to stop": it blocks
                if not e.is_ego and any(a[0] == stage and a[4] == "cut_in" for a in e.actions):
                    e.actions.append((stage, strength, ACTION_RANK["block"], r.tick(), "block", None))
    if by is not None and not verbs:  # "the road it turns into is occupied by a parked truck"
        pass
    _queue_ahead(r, units, phrases, subject, stage)
    crosswalk = any(u.category == "road" and u.meaning in V.CROSSWALK_OBJECTS and not _denied(units, k)
                    for k, u in enumerate(units))
    for e in subject:
        if crosswalk and any(a[4] == "cross" and a[0] == stage for a in e.actions):
            e.features.add("crosswalk")  # "crosses at the zebra crossing", "the crosswalk is crossed by"
        elif crosswalk and e.type == "pedestrian" and "on_sidewalk" not in e.features and any(
                a[4] == "stop" and a[0] == stage for a in e.actions) and any(
                u.category == "actions" and u.meaning == "stop" and any(
                    x.category == "road" and x.meaning in V.CROSSWALK_OBJECTS for x in units[k + 1:k + 4])
                for k, u in enumerate(units)):
            e.features.add("crosswalk")  # "a woman is waiting at the zebra crossing": at it
        elif crosswalk and "waits_to_cross" in e.features and "on_sidewalk" not in e.features:
            e.features.add("crosswalk")  # "a woman is waiting to cross at the zebra": at it
        if any(u.category == "road" and u.meaning == "junction" for u in units) and not e.is_ego and \
                any(units[i].base in ("approach", "enter", "reach") for i in main_verbs):
            e.features.add("junction_approach")  # "a vehicle approaches the intersection"

    for i in main_verbs:  # "turns into a driveway on the left": where it turns, not where it is
        if units[i].meaning in ("turn_left", "turn_right"):
            for u in units[i + 1:i + 5]:
                if u.category == "positions" and u.meaning == "side_" + units[i].meaning[5:]:
                    r.mark(u)
                    u.meaning = "used"
    # positions, behaviours and road types: to the noun they follow, else the subject
    ego_as_it = False  # "beside it" said of the ego: the 'its' after it is the ego's too
    for i, u in enumerate(units):
        if u.category not in ("positions", "behaviours") or u.meaning == "used":
            continue
        after = [x.word for x in units[i + 1:i + 3]]
        if u.meaning in ("ahead", "behind") and after[:1] == ["the"] and after[1:] and after[1] in (
                "other", "first", "second", "former", "latter", "lead", "last"):
            r.mark(u)  # "two trucks, one behind the other": their order, not their place
            continue
        lead = i - 1
        while lead > i - 3 and lead > 0 and units[lead].word in ("in", "on", "at", "the", "a"):
            lead -= 1
        if u.category == "positions" and lead > 0 and units[lead].word in ("not", "never") and \
                units[lead - 1].word in COPULAS:
            r.mark(u)  # "since RV1 is not in the HV's path": a place it is said not to have
            continue
        if any(np.first <= i < np.index for np in phrases):
            continue  # a premodifier, already given
        if u.category == "positions" and len(u.tokens) == 1 and u.word in ADJECTIVE_POSITIONS and \
                i + 1 < len(units) and units[i + 1].category == "agents" and units[i + 1].meaning == "none":
            r.mark(u)  # "overtakes a slow truck despite oncoming traffic": the traffic's, which is no one named
            continue
        if u.meaning in ("ahead", "behind") and [t.word for t in u.tokens] in (["front"], ["rear"], ["back"]) and \
                u.start > 0 and r.tokens[u.start - 1].word == "the" and i + 1 < len(units) and \
                units[i + 1].word == "of" and not any(x.category in ("agents", "actions") for x in units[:i]):
            r.mark(u)
            continue  # "The front of V2 struck the left side of V1": a part of V2, no place
        if u.meaning == "ego_lane" and i > 0 and (units[i - 1].word in ("into", "onto", "across") or (
                units[i - 1].word == "to" and i > 1 and units[i - 2].category == "actions") or (
                units[i - 1].category == "actions" and units[i - 1].tokens[-1].word in ("into", "onto")) or
                _going_in(units, i)):
            u.meaning = "into_ego_lane"  # "moves ... into the ego's lane", "is coming in ego lane"
        if u.meaning == "ahead" and _swerves_in_front(units, i):
            u.meaning = "into_ego_lane"  # "swerves right in front of me": where the cut-in ends, not where it began
        if u.meaning == "ahead" and i > 0 and units[i - 1].meaning == "into_ego_lane":
            u.meaning = "into_ego_lane"  # "cut into the ego's lane just ahead of it": where the cut-in ends
        if u.meaning == "ahead" and _turns_in_front(units, i):
            u.meaning = "turned_in_front"  # "turns right in front of me": ahead, or across from its side road
        possessor = next((np for np in phrases if np.index == i - 1 and np.entity is not None and
                          not np.entity.is_ego), None) if u.category == "positions" and u.meaning in (
            "side_left", "side_right", "ahead", "behind") and i > 0 and units[i - 1].tokens[-1].possessive else None
        last_verb = max([v for v in main_verbs if v < i] + [v for v in participles if v < i], default=None)
        placed = participles[last_verb] if possessor is not None and last_verb in participles and not any(
            e in subject for e in participles[last_verb]) else subject  # ("collided with a lorry coming from the
        # taxi's left": the lorry's side, not the subject's)
        if possessor is not None and placed and possessor.entity not in placed:
            came = possessor.first > 0 and units[possessor.first - 1].word == "from" and \
                u.meaning in ("side_left", "side_right")  # "approaches from the car's right": from that side
            side_road = possessor.first > 2 and u.meaning in ("side_left", "side_right") and \
                [x.word for x in units[possessor.first - 3:possessor.first]] in (
                    ["road", "on", "the"], ["street", "on", "the"], ["road", "to", "the"]) or possessor.first > 1 and \
                [x.word for x in units[possessor.first - 2:possessor.first]] in (["road", "on"], ["street", "on"],
                                                                                 ["road", "to"])
            for e in placed:  # "children walk on the car's left": the car is where they are placed from
                if e.relative_to is None and not e.is_ego:
                    e.relative_to = possessor.entity  # ("comes from the road on car X's left": out of that road)
                    e.relative_how = "road_" + u.meaning[5:] if side_road else \
                        "from_" + u.meaning[5:] if came else u.meaning
            r.mark(u)
            continue
        owner = _let_in_place(units, i, phrases, recent) or \
            _modifier_owner(units, i, phrases, subject, main_verbs, participles)
        if u.meaning == "ego_lane" and any(t.word == "same" for t in u.tokens) and owner and subject and \
                not subject[0].is_ego and not any(e is subject[0] or e.is_ego for e in owner):
            r.mark(u)  # "a police car follows RV1 in the same lane": the lane of the one followed, not the ego's
            continue
        in_its_place = u.category == "positions" and u.meaning in ("ahead", "behind", "level") and (
            _placed_by_one_named_before(units, i) or any(t.word in ("its", "their") for t in u.tokens))
        # ("a biker behind it", "steps out from behind it")
        if u.category == "positions" and any(t.word == "its" for t in u.tokens) and owner and \
                not any(e in subject for e in owner) and not in_its_place and not ego_as_it and \
                not ([t.word for t in u.tokens[:2]] == ["in", "the"] and "lane" in {t.word for t in u.tokens}) and \
                not any(np.entity is owner[0] and np.first > 0 and units[np.first - 1].word in ("with", "as")
                        for np in phrases):  # ("the ego, with a truck on its left": the truck's own place; "at
            # the same time as a car on its left")
            r.mark(u)
            continue  # "pass the slow truck on its left": a side of the truck, not the truck's place ("with a
            # cyclist in the lane to its right": the lane beside the subject, where the cyclist is)
        if u.meaning in ("side_left", "side_right") and _side_of_passing_the_ego(units, i) and owner and \
                all(not e.is_ego and {"behind", "moves_out"} <= e.features for e in owner):
            for e in owner:  # "the van behind me pulled out to overtake me on the right": out of the ego's lane,
                e.features.add("passes_" + u.meaning[5:])  # on that side; it starts behind, in the lane
            r.mark(u)
            continue
        reference = _reference_after(units, i, phrases)
        targets = owner if owner else []
        if in_its_place and any(reference is t for t in targets):
            reference = None  # "and behind it two cars": 'it' is said before them, the cars are not their own place
        if in_its_place and (reference is None or reference.is_ego and u.tokens[0].word == "from"):
            reference = _pronoun_in_place(units, i, phrases, recent, targets)  # "a biker behind it", "a cop car
            # right on its tail", "steps out from behind it" (what stands, not the ego)
        ego_as_it = ego_as_it or reference is not None and reference.is_ego and (
            u.tokens[-1].word == "it" or i + 1 < len(units) and units[i + 1].word == "it")
        if targets and all(e.is_ego for e in targets) and u.category == "positions" and \
                u.meaning in ("ahead", "behind") and u.tokens[-1].word in ("me", "us") and i + 2 < len(units) and \
                units[i + 1].word in ("a", "an", "the", "one", "two", "three") and units[i + 2].category in (
                    "agents", "word"):
            targets = []  # "I was in the left lane and in front of me a car braked": the car's place, said first

        for e in targets:
            if e.is_ego and u.category == "positions":
                if u.meaning.startswith("compass_"):
                    _add_compass(r, e, u)
                if u.meaning == "road_straight" and {t.word for t in u.tokens} & JUNCTION_NOUNS:
                    e.features.add("in_junction")  # "my car slid out across the junction": the ego is at one
                if u.meaning == "first_in_line":
                    e.features.add("first_in_line")
                if u.meaning == "middle_lane" and not any(f.startswith("in_lane_") for f in e.features):
                    e.features.add("in_lane_middle")  # "VUT in the middle lane": the lane others are placed by
                if u.meaning == "behind" and u.tokens[0].base in ("sit", "wait", "stand", "idle") and \
                        reference is not None and any(a[4] in ("stop", "block") for a in reference.actions):
                    e.actions.append((stage, strength, ACTION_RANK["stop"], r.tick(), "stop", None))  # "a van was
                    # double-parked and we sat behind it": behind one that stands, it stands too
                edge_after = i + 1 < len(units) and (units[i + 1].category == "positions" and units[i + 1].meaning in (
                    "shoulder", "sidewalk") or units[i + 1].word in LANE_EDGES)  # "against the nearside verge"
                body_side = u.tokens[-1].word == "side" and (  # "struck the left side of V1": a part of it
                    u.start > 0 and r.tokens[u.start - 1].word in ("the", "its", "my", "our", "his", "her") and
                    u.end < len(r.tokens) and r.tokens[u.end].word == "of" or
                    u.start > 0 and r.tokens[u.start - 1].word in ("my", "our", "its"))
                lane_after = i + 1 < len(units) and units[i + 1].category == "word" and \
                    units[i + 1].word in ("lane", "lanes")  # "on rightmost lane": the word after its side
                beside_it = {t.word for t in u.tokens} & {"adjacent", "next", "neighbouring", "neighboring"}
                if u.meaning in ("side_left", "side_right") and ({t.word for t in u.tokens} & LANE_WORDS or
                                                                 lane_after) and not edge_after and not body_side \
                        and not beside_it:  # ("Adjacent right lane: car 20 m behind the SV": the lane beside it)
                    e.features.add("in_a_side_lane")  # "I'm in the slow lane": the road has lanes beside it
                    e.features.add("in_lane_" + u.meaning[5:])  # which side: a move to the middle is away from it
                later = reference is not None and bool(reference.features & {"ahead", "behind", "level"}) and (
                    stage > reference.stage or "level" in reference.features)  # "then returns ahead of the bus": it
                # was; "a truck right next to it, so the ego slots in behind it": beside, as said first
                started = reference is not None and u.meaning in ("ahead", "behind") and \
                    u.meaning in reference.features and bool(reference.actions)  # "a BMW came up the inside lane,
                # cut me up ... into the back of it": the first place said is where it started
                said_first = reference is not None and u.meaning in INVERSE and \
                    bool(reference.features & OPPOSITE_PLACES.get(INVERSE[u.meaning], set()))  # "a truck just behind
                # us ... we slot in behind it": where it was said to be first is where it starts
                if reference is not None and not reference.is_ego and u.meaning in INVERSE and not later and \
                        not started and not said_first:
                    reference.features.add(INVERSE[u.meaning])  # "the ego follows behind a truck": it is ahead
                    moving = any(a[0] == stage and a[4] in LANE_MOVES | {"lane_left", "lane_right"} for a in e.actions)
                    if u.meaning == "behind" and reference.stage == stage and not moving:
                        reference.features.add("ego_behind")  # in the ego's own lane, whichever lane that is
                        # (not "merged right into lane one behind the coach": the lane it moves into)
                    elif u.meaning == "behind" and reference.stage == stage and e.is_ego and any(
                            x.category == "actions" and x.meaning in LANE_MOVES | {"lane_left", "lane_right"}
                            for x in units[:i]):
                        reference.features.add("target_lane")  # "merges into the right lane behind a slow van"
                r.mark(u)
                continue
            if reference is not None and not reference.is_ego and u.category == "positions" and \
                    u.meaning in ("ahead", "behind", "level") and reference is not e:
                if e.relative_to is None:
                    e.relative_to, e.relative_how = reference, u.meaning
                r.mark(u)
                continue
            if u.meaning == "road_straight" and u.tokens[0].word == "across" and u.tokens[-1].word != "from" and \
                    e.features & {"road_left", "road_right", "cross_road"}:
                r.mark(u)  # "comes from the road on the left and goes straight across the junction": the way it
                continue  # goes, not where it comes from
            _modify(r, e, u, stage, 1)
        if not targets:
            r.mark(u)
    for e in subject:
        if e.type == "pedestrian" and not e.is_ego and e.relative_to is None:
            e.relative_to = _vehicle_got_out_of(units, phrases, recent, e) or _the_one_at_the_stop(units, recent)
            # at the vehicle it climbed out of; "waiting on the pavement by the stop": at the bus stopped there
    _numbers(r, units, subject)
    _there(units, subject, previous_subject)
    surface = [np.entity for np in phrases if np.entity is not None and np.index < first_verb]
    r.surface = surface[:1] if by is not None and surface else []
    mentioned = [np.entity for np in phrases if np.entity is not None]
    for e in mentioned:  # by identity: entities compare by value, and an equality test of each is costly
        recent[:] = [x for x in recent if x is not e] + [e]
    return subject


JUNCTION_PLACES = {"destination", "road_left", "road_right", "road_straight", "cross_road"}


def _there(units: list[Unit], subject: list[Entity], previous: list[Entity]) -> None:
    """'a bus stopped on the street I'm turning onto, and two girls standing on the sidewalk there': 'there' is the
    place of the one named before, on the junction's road it was put on ('there is a bus' says nothing of a place)."""
    said = any(u.word == "there" and not (k + 1 < len(units) and units[k + 1].word in COPULAS | {"be", "been"}) and
               not (k > 0 and units[k - 1].word in ("over", "out", "up", "down", "in", "from", "get", "got"))
               for k, u in enumerate(units))
    place = next((e.features & JUNCTION_PLACES for e in previous if not e.is_ego and e.features & JUNCTION_PLACES),
                 set())
    if said and place:
        for e in subject:
            if not e.is_ego and e not in previous and not e.features & (JUNCTION_PLACES | {"behind"}):
                e.features |= place  # (not "the pickup behind me sat there": behind the ego, where it waits)


INVERTING_VERBS = {"come", "follow", "stand", "sit", "wait", "drive", "go", "ride", "walk", "run", "stop", "park",
                   "appear", "emerge", "approach", "travel", "move", "roll", "hold", "halt", "cycle", "drive up"}
PLACE_PREPOSITIONS = {"from", "behind", "on", "in", "at", "into", "along", "across", "over", "next", "beside",
                      "ahead", "out", "down", "up", "opposite", "directly", "right", "just", "then", "now", "there", "here", "past", "round", "around"}


def _inverted_subject(units: list[Unit], phrases: list[NounPhrase], verb: int) -> NounPhrase | None:
    """Locative inversion, common in English written by Germans and in stage directions: 'From the opposite
    direction comes a PKW', 'Behind the ego follows a small car'. A clause that opens with a place, has no
    subject before its verb, and a verb of coming or standing in a finite form (not an order: 'follow a car')
    has as subject the new noun phrase right after the verb."""
    opening = next((j for j, u in enumerate(units[:verb]) if not (
        u.category == "word" and u.word in INTERJECTIONS | {"but", ","})), verb)  # "And here comes ..."
    v = units[verb]
    if all(u.category in ("behaviours", "comma") or u.word in INTERJECTIONS | TIME_ADVERBS
           for u in units[opening:verb]):
        return _inverted_at_the_start(units, phrases, verb)
    if not (units[opening].category == "positions" or units[opening].word in PLACE_PREPOSITIONS):
        return None
    if v.tokens[0].base not in INVERTING_VERBS:
        return None
    after = next((np for np in phrases if np.index > verb), None)
    if after is None or not after.introduced or after.entity is None or after.entity.is_ego:
        return None
    if v.tokens[0].word == v.tokens[0].base and not (after.plural or after.entity.count > 1):
        return None  # an order ("behind the truck, follow a car"); but "in the opposite direction come two cars"
    if any(not _a_whole_place(u) and (u.category not in ("behaviours", "word") or u.word not in
                                      lexicon().function_words | {"also", "already"} and u.category != "behaviours")
           for u in units[verb + 1:after.first]):
        return None
    return after


def _a_whole_place(u: Unit) -> bool:
    """'in the opposite direction', 'from the left' between an inverted verb and its subject ('comes in the opposite
    direction a bus'): a place complete in itself; not 'behind', 'in front of', which take the next noun as theirs
    ('comes to a stop behind a truck')."""
    return u.category == "positions" and u.tokens[-1].word not in PLACE_PREPOSITIONS | {"of", "to", "by", "with",
                                                                                          "near", "towards", "toward"}


TIME_ADVERBS = {"then", "suddenly", "also", "now", "there", "here", "again", "just", "next"}
COMING_AT_THE_START = {"come", "stand", "appear", "emerge", "run", "walk", "cross", "cycle"}  # none takes a road user
# as object ("came across a cyclist" has a word between)


def _inverted_at_the_start(units: list[Unit], phrases: list[NounPhrase], verb: int) -> NounPhrase | None:
    """Verb-second order with no place first, from writers of Dutch or German: 'Suddenly stood a car on the road',
    'Then crosses a boy on his bike the road'. A finite verb of coming, standing or crossing (not an order: 'cross
    the road') right before a new noun phrase has that phrase as subject."""
    v = units[verb]
    if v.category != "actions" or v.tokens[0].base not in COMING_AT_THE_START or v.tokens[0].word == v.tokens[0].base:
        return None
    after = next((np for np in phrases if np.index > verb), None)
    if after is None or not after.introduced or after.entity is None or after.entity.is_ego:
        return None
    if any(not (u.category in ("behaviours", "numbers", "number") or u.word in ARTICLES_AND_COUNTS or
                _a_whole_place(u)) for u in units[verb + 1:after.first]):
        return None
    return after


ARTICLES_AND_COUNTS = {"a", "an", "the", "one", "some", "another", "also", "two", "three"}


ACTION_NOUN_TAILS = {"action", "manoeuvre", "maneuver", "event", "move"}


def _actor_of_a_named_action(units: list[Unit], verbs: list[int], phrases: list[NounPhrase]) -> int | None:
    """'a lane change of the van into the ego lane', 'LaneChangeAction of TargetVehicle': an action named as a
    noun, its doer after 'of' or 'by', and no subject before it; the index of that 'of', read like the passive's
    'by'."""
    if not verbs or any(np.index < verbs[0] and np.entity is not None for np in phrases):
        return None
    if units[verbs[0]].tokens[-1].word in SHORT_OF | {"front"}:
        return None  # "stopping short of him", "pulled out in front of a motorcycle": where it went, not who did
    j = verbs[0] + 1
    while j < len(units) and units[j].word in ACTION_NOUN_TAILS:
        j += 1
    if j + 1 < len(units) and units[j].word in ("of", "by") and \
            any(np.first <= j + 2 and np.index > j and np.entity is not None and not np.entity.is_ego
                for np in phrases):
        return j
    return None


def _ego_turn_in_a_place(r: _Reader, units: list[Unit], stage: int) -> None:
    """'a woman crosses the road where the ego turns left': the place names the ego's turn, and its side."""
    for j, u in enumerate(units):
        words = {t.word for t in u.tokens}
        if u.category != "positions" or u.meaning != "destination" or not words & {"turn", "turns", "turning"} \
                or not words & EGO_WORDS | {"we", "us"}:
            continue
        ego = _ego_entity(r, stage)
        if any(a[4].startswith("turn") for a in ego.actions):
            continue
        after = units[j + 1] if j + 1 < len(units) else None
        side = None
        if after is not None and after.category == "positions" and after.meaning in ("side_left", "side_right") \
                and len(after.tokens) == 1:
            side = after.meaning[5:]
            r.mark(after)
            after.meaning = "used"
        ego.actions.append((stage, 2, ACTION_RANK["turn_left"], r.tick(), f"turn_{side}" if side else "turn", None))


def _signal_change(units: list[Unit], i: int) -> bool:
    """'the light has turned red', 'by the time it goes green': a signal changing colour, nobody's manoeuvre."""
    u = units[i]
    if u.tokens[0].base not in ("turn", "go", "change", "switch", "become", "flip") or len(u.tokens) > 1:
        return False
    after = [x.word for x in units[i + 1:i + 3]]
    return bool(after) and (after[0] in SIGNAL_COLOURS or after[:1] == ["to"] and after[1:2] and
                            after[1] in SIGNAL_COLOURS)


def _named_manoeuvre(units: list[Unit], i: int) -> bool:
    """'at the start of the manoeuvre', 'during the turn': a manoeuvre named as a noun after a preposition,
    nobody's predicate."""
    if i + 1 < len(units) and units[i + 1].word in ("test", "tests", "scenario", "scenarios", "case", "cases", "run",
                                                    "runs", "scene", "scenes", "event", "situation", "drill",
                                                    "exercise", "check", "set", "suite", "batch", "series",
                                                    "coverage", "backlog", "campaign", "library", "catalog"):
        return True  # "merge test", "cut-in scenario", "the highway merge set": the name of a test or a set
    if i >= 2 and units[i - 1].word in ("a", "an", "the", "this", "that") and \
            units[i - 2].tokens[-1].word in BUILDING_A_SCENE and not (
                units[i - 1].word in ("a", "an") and units[i].meaning in ("turn_left", "turn_right", "turn", "u_turn")):
        return True  # "trying to set up a cut-in in esmini", "how do I model the merge": the scene built, no act
        # (but "simulate a left turn with an oncoming truck": the turn the scene is, the ego's)
    if i >= 1 and units[i].tokens[0].word in ("maneuver", "manoeuvre", "maneuvers", "manoeuvres") and (
            units[i - 1].word in ("first", "second", "third", "next", "last", "final", "other") or
            units[i - 1].tokens[-1].possessive):
        return True  # "the ego's second maneuver", "its last manoeuvre": the manoeuvre talked about, not made here
    if i >= 2 and units[i - 1].word == "the" and units[i - 2].word in COPULAS and \
            units[i].meaning in ("cut_in", "lane_change", "block") and (
                i + 1 == len(units) or units[i + 1].category == "comma" or
                units[i + 1].tokens[0].sentence != units[i].tokens[-1].sentence):
        return True  # "the one that scares me is the cut-in.": the kind of scene talked about, nobody's act
    j = i - 1
    while j > 0 and i - j <= 2 and units[j].category == "word" and len(units[j].tokens) == 1 and \
            units[j].word not in lexicon().function_words and units[j - 1].category == "word":
        j -= 1  # "flagged on the initial stop", "2 pax, both for the hospital stop": the manoeuvre's adjectives
    if j < i - 1 and j >= 1 and units[j].word in ("the", "a", "an", "this", "that", "its", "their", "his", "her") \
            and units[j - 1].word in ("of", "during", "at", "before", "after", "throughout", "until", "since", "on",
                                      "for") \
            and units[i].word in ("stop", "turn", "brake", "merge", "overtake", "lane change", "manoeuvre", "maneuver"):
        return True
    return i >= 2 and units[i - 1].word in ("the", "a", "an", "this", "that", "its", "their") and \
        units[i - 2].word in ("of", "during", "at", "before", "after", "throughout", "until", "since") or \
        i >= 1 and units[i - 1].word in ("of", "during", "throughout") and units[i].tokens[0].word in (
            "maneuver", "manoeuvre", "turn", "lane", "overtake", "merge", "cut")  # "at start of manoeuvre"


BUILDING_A_SCENE = {"up", "build", "building", "built", "model", "modelling", "modeling", "modelled", "modeled",
                    "simulate", "simulating", "script", "scripting", "implement", "implementing", "reproduce",
                    "reproducing", "configure", "configuring", "create", "creating"}  # what one does to a scenario

PLANNING = {"queued", "queues", "planned", "plans", "planning", "scheduled", "proposed", "intended", "considered",
            "requested", "commanded", "queue", "plan"}  # a planner's or a driver's manoeuvre still to come


def _planned(units: list[Unit], i: int) -> bool:
    """'the AV planner queued a lane change to the left': the manoeuvre is planned, not made, and the planning
    verb ('queued') is no wait in a queue."""
    def planning(u: Unit) -> bool:
        return u.tokens[0].word in PLANNING
    return i + 2 < len(units) and planning(units[i]) and units[i + 1].word in ("a", "an", "the", "its", "another") \
        and units[i + 2].category == "actions" or \
        i >= 2 and units[i - 1].word in ("a", "an", "the", "its", "another") and planning(units[i - 2])


def _weighed(units: list[Unit], i: int) -> bool:
    """'has to decide whether to pull around the bus or wait': each choice weighed is none made."""
    return any(u.category == "word" and u.word == "whether" for u in units[max(0, i - 8):i])


REQUESTING = {"signal", "signals", "signaled", "signalled", "signaling", "signalling", "tell", "tells", "told",
              "ask", "asks", "asked", "order", "orders", "ordered", "instruct", "instructs", "instructed", "direct",
              "directs", "directed", "beckon", "beckons", "beckoned", "motion", "motions", "motioned", "motioning"}


def _requested(units: list[Unit], i: int) -> bool:
    """'a police car signals you to pull over', 'the officer tells us to stop': what one is asked to do is
    still to come, done by no one yet."""
    if i < 3 or units[i - 1].word != "to":
        return False
    j = i - 2
    while j > 0 and units[j].category == "word" and units[j].word in DETERMINERS:
        j -= 1
    return units[j].category == "agents" and units[j - 1].tokens[-1].word in REQUESTING


PASSED_OVER = (("instead", "of"), ("rather", "than"), ("as", "opposed", "to"), ("in", "place", "of"))


def _instead_of(units: list[Unit], i: int) -> bool:
    """A verb said after 'instead of' or 'rather than', or a verb phrase of the same clause after that one ('rather
    than stopping at the bus stop'): the manoeuvre that was not made."""
    for j in range(i, -1, -1):
        if j < i and (units[j].category == "comma" or units[j].word in ("and", "but", "so", "then")):
            return False
        said_before = [t.word for u in units[max(0, j - 3):j] for t in u.tokens]
        if units[j].category == "actions" and any(said_before[-len(lead):] == list(lead) for lead in PASSED_OVER):
            return True
    return False


WAYS_IN = {"into_ego_lane", "ego_lane", "target_lane", "in_road", "cross_road", "across_path"}  # where a move goes


def _denied_verb(units: list[Unit], i: int) -> bool:
    """'don't try to pass him', 'never overtakes', 'must learn how to yield': a verb said not to happen, or
    only talked about ('does not move' is a phrase of its own)."""
    if any(u.category == "actions" and u.meaning == "try" and u.base in TALKED_ABOUT
           for u in units[max(0, i - 3):i]):
        return True
    said_before = [u.word for u in units[:i]]
    if "neither" in said_before and "nor" in said_before[said_before.index("neither"):]:
        return True  # "neither the cyclist in the right lane nor the car behind the ego changes lane"
    for u in reversed(units[max(0, i - 6):i]):
        if u.word == "neither":
            return True  # "neither vehicle slows down", "neither of the two oncoming trucks turns"
        if u.category not in ("agents", "word", "numbers", "positions"):
            break
    after = [u.word for u in units[i + 1:i + 4]]
    if after[:1] and after[0] in ("impossible", "prohibited", "forbidden", "banned") or \
            after[:2] in (["not", "possible"], ["not", "allowed"], ["not", "permitted"], ["is", "impossible"]) or \
            after[:3] in (["is", "not", "possible"], ["is", "not", "allowed"], ["not", "an", "option"]):
        return True  # "overtaking not possible": the manoeuvre is ruled out
    if _instead_of(units, i):
        return True  # "rolled through instead of coming to a stop", "rather than stopping": the road not taken
    for k in range(i - 1, max(0, i - 7) - 1, -1):
        u = units[k]
        if u.word in ("it", "him", "her", "them") and k > 0 and units[k - 1].word in ("make", "made", "makes"):
            continue  # "didn't make it wait": the one made to, after the causative
        if u.category == "word" and u.word in ("not", "never", "cannot", "dont", "don", "failed", "fails", "fail",
                                               "failing", "refused", "refuses", "without", "unable", "nowhere",
                                               "nobody") or (
                u.category == "numbers" and u.meaning == "0"):
            return True
        if not (u.category == "word" and u.word in ("do", "does", "did", "to", "try", "will", "would", "should",
                                                     "is", "are", "be", "can", "could", "room", "space", "chance",
                                                     "able", "unable", "time", "even", "ever", "really", "properly",
                                                     "so", "much", "once", "a", "all", "the", "way", "completely",
                                                     "fully", "full", "quite", "whatever", "for", "any", "of",
                                                     "anyone", "anybody", "make", "makes", "made", "take",
                                                     "takes", "took", "perform", "performs", "performed", "just",
                                                     "simply", "easily", "safely", "then", "have", "has", "had",
                                                     "need", "needs", "needed", "actually", "yet")) \
                and u.category != "actions" and not (u.category == "agents" and u.meaning == "ego"):
            # ("nowhere whatever for any of us to pull over", "no room for me to move over", "didn't have to stop")
            return False
    return False


SIDE_ROAD_NOUNS = {"junction", "road", "street", "turning", "avenue"}  # a driveway is no junction road


def _side_roads(units: list[Unit]) -> None:
    """'emerged from a junction on its left', 'came out of a side street to our right': the road on that side,
    not the lane beside."""
    for k, u in enumerate(units):
        if k < 2 or u.category != "positions" or u.meaning not in ("side_left", "side_right"):
            continue
        j = k - 1
        while j > 1 and units[j].category == "word" and units[j].word in ("to", "on", "the", "our", "its", "your",
                                                                         "my", "his", "her", "their"):
            j -= 1  # "a side street to our right"
        noun = units[j]
        if not (noun.category == "road" and noun.meaning == "junction" or noun.word.split()[-1] in SIDE_ROAD_NOUNS):
            continue
        if any(x.word in ("from", "out", "of") for x in units[max(0, j - 4):j]):
            u.meaning = "road_" + u.meaning[5:]
    for k, u in enumerate(units):  # "reversing into a loading bay on the left": the bay's side, not the lorry's
        if k < 3 or u.category != "positions" or u.meaning not in ("side_left", "side_right") or \
                {t.word for t in u.tokens} & LANE_WORDS:
            continue
        noun = units[k - 1]
        if noun.category == "word" and noun.word not in lexicon().function_words and \
                noun.word.split()[-1] not in SIDE_ROAD_NOUNS and \
                any(x.word in ("into", "onto") for x in units[max(0, k - 4):k - 1]):
            u.meaning = "used"


QUEUE_WORDS = {"queue", "queued", "queueing", "queuing", "jam", "tailback", "traffic", "red", "lights"}  # "stuck in traffic", "at a red light"


def _queue_ahead(r: _Reader, units: list[Unit], phrases: list[NounPhrase], subject: list[Entity], stage: int):
    """'ego stopped in queue behind two lorries': those it queues behind stand too."""
    if not any(e.is_ego and any(a[4] == "stop" and a[0] == stage for a in e.actions) for e in subject):
        return
    if not any(t.word in QUEUE_WORDS for u in units for t in u.tokens):
        return
    for np in phrases:
        e = np.entity
        if e is None or e.is_ego or e in subject or e.actions or np.first == 0:
            continue
        if any(u.category == "positions" and u.meaning == "behind" for u in units[max(0, np.first - 2):np.first]):
            e.actions.append((stage, 2, ACTION_RANK["stop"], r.tick(), "stop", None))


ORDINALS = {"first": 1, "second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6, "2nd": 2, "3rd": 3, "4th": 4,
            "5th": 5, "6th": 6}
RED_OR_QUEUE = {"queue", "queued", "queueing", "queuing", "jam", "tailback", "red", "line"}


SITTING = {"sat", "sitting", "sits", "sit"}


def _sitting_behind_a_stopped_ego(r: _Reader) -> None:
    """'The ego is stopped at the red light. A patrol car sat behind her': one that sits behind an ego standing
    in that stage, doing nothing else, stands too ('sat behind me for miles' behind a moving ego follows)."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is None:
        return
    for e in r.entities:
        said = [t.word for t in r.tokens[e.said_at + 1:e.said_at + 4]] if e.said_at >= 0 else []
        ego_does = {a[4] for a in ego.actions if a[0] == e.stage}
        if e.is_ego or e.actions or "behind" not in e.features or not set(said) & SITTING or \
                "behind" not in said or ego_does != {"stop"}:
            continue
        e.actions.append((e.stage, 1, ACTION_RANK["stop"], r.tick(), "stop", None))


MET_BY_ANOTHER = {"behind", "let", "letting", "overtaking", "overtake", "overtook", "following", "follow",
                  "followed", "passing", "pass", "passed", "past", "around", "for", "with", "between", "than", "of",
                  "to", "at", "after", "hit", "hits", "hitting", "avoid", "avoids", "avoiding", "miss", "misses",
                  "missed", "notice", "notices", "noticed", "see", "sees", "saw", "seen", "spot", "spots", "spotted",
                  "block", "blocks", "clip", "clips", "clipped", "clipping", "startle", "startles", "startling",
                  "into", "across", "towards", "toward"}
PUT_IN_THE_SCENE = {"there", "there's", "also", "too", "add", "adds", "include", "includes", "including", "plus",
                    "nearby", "around", "present", "appear", "appears", "appeared", "scene", "additionally", "with",
                    "spawn", "place", "put", "distance", "just", "only"}
CLAUSE_OPENERS = {",", ";", ":", "-", "and", "then", "while", "when", "as", "but", "meanwhile", "until", "once"}
LIST_MARKS = {",", ";", "/", "-", "and", "or", "then"}
RENAMING = {"maybe", "well", "really", "ie", "probably", "possibly", "rather", "instead"}
OWNERS_AND_KINDS = {"his", "her", "my", "our", "their", "your", "every", "any", "each", "like", "trust", "own"}


def _anything_said_of(e: Entity) -> bool:
    return bool(e.features or e.actions or e.relative_to is not None or e.speed or e.gap_m or e.trigger or
                e.behavior or e.label or e.road_type or e.parent is not None)


DOOR_OPENING = {"open", "opens", "opened", "opening", "flung", "flings", "threw", "throws", "swung", "swings"}


def _a_door_opened_from_inside(r: _Reader) -> None:
    """'Somebody flung open the door of a parked taxi', 'someone opened a door on a parked car': one named by no
    more than a vague word who does nothing but open a vehicle's door sits in that vehicle; no one on foot."""
    for e in list(r.entities):
        if e.is_ego or e.type != "pedestrian" or e.head not in ("someone", "somebody") or e.features or \
                any(a[4] not in ("try",) for a in e.actions) or e.said_at < 0:
            continue
        after = [t.word for t in r.tokens[e.said_at + 1:e.said_at + 6]]
        if "door" in after and set(after[:3]) & DOOR_OPENING:
            r.entities.remove(e)
            r.notes.append(f"read '{e.head}' who opens a door as one inside the vehicle, no one on foot")


ANY_PERSON = {"pedestrian", "ped", "person", "someone", "somebody"}
ONE_MORE = {"another", "other", "second", "third", "more", "also", "too", "again", "different", "further", "extra"}


def _the_same_one_again(r: _Reader) -> None:
    """'Client stopped for a pedestrian ... let an elderly gentleman cross', 'Lead obj: car, sudden stop. Driver
    note: Car in front just stopped sharp': one named again with 'a', or bare at its clause's start, in a later
    sentence of the same stage, and said nothing new of (no place or doing the first was not said to have), is that
    one; so is one of which the first mention said nothing ('honked at a cyclist ... a cyclist riding on the
    shoulder'), told where it is said. Not when its sentence says it is one more ('another', 'a second', 'also'),
    or when it is named by another noun than the first ('a man' after 'a woman'; 'pedestrian', 'someone',
    'vehicle' name any)."""
    for e in list(r.entities):
        if e.is_ego or e.count != 1 or e.said_at < 1 or e.definite or e.parent is not None or e.label or \
                e.relative_to is not None or e not in r.entities:
            continue
        said = _sentence(r.tokens, r.tokens[e.said_at].sentence)
        lead = [t.word for t in said if e.said_at - 3 <= t.index < e.said_at]
        bare = said[0].index == e.said_at or r.tokens[e.said_at - 1].word in (",", ":") or \
            r.tokens[e.said_at].word == "other" and r.tokens[e.said_at - 1].word not in ("an", "one", "any", "no")
        if not ({"a", "an", "single"} & set(lead) or bare or r.tokens[e.said_at].word in ("someone", "somebody")) or \
                ONE_MORE & {t.word for t in said if t.index != e.said_at}:  # (its own 'other' is not the ego;
            # "someone" is as indefinite as "a person")
            continue
        done = {(a[4], a[5]) for a in e.actions}
        first = next((x for x in r.entities if x is not e and not x.is_ego and x.type == e.type and x.count == 1 and
                      0 <= x.said_at < said[0].index and x.stage == e.stage and x.parent is None and
                      (_one_name_in_the_other(x.head, e.head) or {x.head, e.head} & (ANY_PERSON | {"vehicle"})) and
                      (e.features <= x.features and done <= {(a[4], a[5]) for a in x.actions} or
                       not x.features and not x.actions and x.relative_to is None)), None)
        if first is None and bare:
            first = _named_bare_again(r, e)
            if first is not None:
                _fold(r, first, e)
                r.notes.append(f"read '{e.head}' as the {first.head} named before: named bare, as a note names "
                               f"the one it speaks of")
            continue
        if first is None:
            continue
        if e.features <= first.features and done <= {(a[4], a[5]) for a in first.actions}:
            first.aliases.add(e.head)
            _taken_over(r, e, first)
            r.notes.append(f"read '{e.head}' as the {first.head} named before: nothing new is said of it")
        else:  # "honked at a cyclist ... there was a cyclist riding on the shoulder": the first said nothing
            e.aliases |= first.aliases | {first.head}
            _taken_over(r, first, e)
            r.notes.append(f"read the {first.head} named before as '{e.head}': nothing was said of it there")


DOING_NAMES = {"turning": {"turn", "turn_left", "turn_right", "u_turn"},
               "merging": {"cut_in", "lane_change", "lane_left", "lane_right"}}


def _named_by_what_it_does(r: _Reader) -> None:
    """'It shall make a right turn ... it would be struck by the turning vehicle': 'the turning vehicle' is the
    one told to turn, where one alone is."""
    for e in list(r.entities):
        if e.is_ego or not e.definite or e.count != 1 or e.said_at < 2 or e.label or \
                r.tokens[e.said_at - 2].word != "the" or r.tokens[e.said_at - 1].word not in DOING_NAMES:
            continue
        doing = DOING_NAMES[r.tokens[e.said_at - 1].word]
        doers = [x for x in r.entities if x is not e and x.count == 1 and any(a[4] in doing for a in x.actions)]
        if len(doers) == 1 and (doers[0].type == e.type or e.head in GENERAL_BODIES):
            _taken_over(r, e, doers[0])
            r.notes.append(f"read 'the {r.tokens[e.said_at - 1].word} {e.head}' as the one said to do so")


def _named_bare_again(r: _Reader, e: Entity) -> Entity | None:
    """'a van pulling out of a side road on his left, van going straight across', 'Car coming the other way
    turned right ... Car driver walking wounded': a note names one it told of before bare, by the same noun, and
    goes on with what it does; only where that noun named one alone and the new words place it nowhere else."""
    other = e.head.split()[0] == "other"  # "Speed of other vehicle est 40mph": the one that is not the ego
    same = [x for x in r.entities if x is not e and not x.is_ego and (
        x.head == e.head or other and x.type == e.type and x.count == 1 and 0 <= x.said_at < e.said_at)]
    if len(same) != 1:
        return None
    first = same[0]
    ok = first.type == e.type and first.count == 1 and 0 <= first.said_at < e.said_at and \
        first.stage == e.stage and first.parent is None and not first.label and \
        e.features - {"straight_on", "moves_out"} <= first.features
    return first if ok else None


def _one_name_in_the_other(a: str, b: str) -> bool:
    """'target' and 'target vehicle', 'van' and 'delivery van': one name said again shorter or longer."""
    x, y = a.split(), b.split()
    return bool(x and y) and (set(x) <= set(y) or set(y) <= set(x))


def _passing_mentions(r: _Reader) -> None:
    """'his Audi', 'pickup drivers in the rain are idiots', 'never trust a cab': a vehicle of which nothing is
    said, in a text where others are told what they do, is a passing mention, not an agent. One that opens its
    clause ('a truck sheds its load', 'Meanwhile a motorcycle.'), is put in the scene ('there is also a truck',
    'a bus was at the stop'), listed beside another ('a car from the right, a motorcycle and a bus') or met by
    another ('behind a slow truck', 'yields to a bus') stays, unless it is someone's own or any of its kind
    ('my dad drives a bus', 'like every cyclist in town'); people stay, often in a scene with nothing said."""
    if not any(not e.is_ego and e.count > 0 and _anything_said_of(e) for e in r.entities):
        return
    for e in r.entities:
        if e.is_ego or e.count <= 0 or e.said_at < 0 or _anything_said_of(e) or e.type == "pedestrian":
            continue
        owned_or_any = set(_in_its_sentence(r, e, e.said_at - 3, e.said_at)) & OWNERS_AND_KINDS
        if not owned_or_any and (_opens_its_clause(r, e) or _put_in_the_scene(r, e) or _listed(r, e)):
            continue
        r.notes.append(f"read '{e.head}' as a passing mention: nothing is said of what it does or where it is")
        e.count = 0


DRIVING_WORDS = {"drove", "drives", "drive", "driving"}


def _the_crews_own(r: _Reader) -> None:
    """'A runner ... crossed directly in front of the shuttle. Hard stop.': where the text speaks as 'we' and the
    ego was supplied for a verb with no subject, a vehicle of another kind named with 'the' as one known, that
    someone crosses in front of and that does nothing itself, is the crew's own: the ego is of its kind."""
    ego = next((x for x in r.entities if x.is_ego), None)
    if ego is None or ego.said_at >= 0 or ego.head != "ego" or not any(t.word in ("we", "us", "our")
                                                                         for t in r.tokens):
        return
    for e in r.entities:
        if e.is_ego or not e.definite or e.count != 1 or e.type == ego.type or e.type not in V.EGO_TYPES or \
                e.features or e.actions or e.label or e.said_at < 3 or any(x.relative_to is e for x in r.entities) \
                or [t.word for t in r.tokens[e.said_at - 3:e.said_at]] != ["front", "of", "the"]:
            continue
        ego.type = e.type
        e.count = 0
        r.notes.append(f"read 'the {e.head}' as the ego's own: a crew's log names it as known")
        return


def _people_said_in_passing(r: _Reader) -> None:
    """'Its driver, a 61-year-old grandmother, suffered a broken wrist', 'Moss, a father of two, told
    magistrates': a person set off after someone already named, of whom nothing is said, says who that one is;
    'dad drove us to the cinema': one who drives the teller is at the ego's wheel. Neither is one on foot."""
    if not any(not e.is_ego and e.count > 0 and _anything_said_of(e) for e in r.entities):
        return
    for e in r.entities:
        if e.is_ego or e.type != "pedestrian" or e.count != 1 or e.said_at < 2 or e.features or \
                e.relative_to is not None or any(x.relative_to is e for x in r.entities):
            continue
        said = _sentence(r.tokens, r.tokens[e.said_at].sentence)
        before = [t.word for t in said if t.index < e.said_at]
        after = [t.word for t in said if t.index > e.said_at + len(e.head.split()) - 1]
        lead = next((k for k in range(len(before) - 1, -1, -1) if before[k] in ("a", "an")), None)
        set_off = not e.actions and lead is not None and lead >= 2 and before[lead - 1] == "," and \
            len(before) - lead <= 5 and (not after or after[0] in (",", "of"))
        at_the_wheel = after[:1] and after[0] in DRIVING_WORDS and after[1:2] and after[1] in (
            "us", "me", "my", "our") or after[:2] == ["was", "driving"] and after[2:3] and after[2] in ("us", "me")
        if set_off or at_the_wheel and all(a[4] == "move" for a in e.actions):
            e.count = 0
            r.notes.append(f"left out: '{e.head}' " + ("says who someone named is" if set_off else
                                                       "drives the teller's own vehicle"))


def _in_its_sentence(r: _Reader, e: Entity, start: int, end: int) -> list[str]:
    return [t.word for t in _sentence(r.tokens, r.tokens[e.said_at].sentence) if start <= t.index < end]


def _opens_its_clause(r: _Reader, e: Entity) -> bool:
    """The subject of a verb ('a truck sheds its load', 'a van catches fire') or a fragment of its own ('A police
    car.', 'Meanwhile a motorcycle.'): at most an article and two words between it and its clause's start."""
    before = _in_its_sentence(r, e, e.said_at - 4, e.said_at)
    opener = max((k for k, w in enumerate(before) if w in CLAUSE_OPENERS), default=-1)
    lead = before[opener + 1:]
    if not (opener >= 0 or len(before) < 4) or len(lead) > 3 or set(lead) & (OWNERS_AND_KINDS | MET_BY_ANOTHER):
        return False
    heads = set(e.head.split())
    after = [w for w in _in_its_sentence(r, e, e.said_at + 1, e.said_at + 4) if w not in heads] + [""]
    verb = after[0].isalpha() and (after[0].endswith(("s", "ed")) and not after[0].endswith(("ers", "ss")) or
                                   after[0] in AUXILIARIES - {"then", "also", "to", "and"})
    return verb or len(_in_its_sentence(r, e, 0, len(r.tokens))) <= 8


def _put_in_the_scene(r: _Reader, e: Entity) -> bool:
    after = _in_its_sentence(r, e, e.said_at + 1, e.said_at + 3) + ["", ""]
    return bool(set(_in_its_sentence(r, e, e.said_at - 4, e.said_at)) & MET_BY_ANOTHER or
                set(_in_its_sentence(r, e, 0, len(r.tokens))) & PUT_IN_THE_SCENE) or \
        after[0] in COPULAS and not after[1].endswith("ed")  # "a bus was at the stop", not "was transported"


def _listed(r: _Reader, e: Entity) -> bool:
    """'a car from the right, a motorcycle and a bus', 'a truck, the ego, and a van wait', 'a truck, then a bus':
    named in a list with another; not 'dark SUV, maybe a Tahoe', which names one twice."""
    sentence = r.tokens[e.said_at].sentence
    for o in r.entities:
        if o is e or o.said_at < 0 or r.tokens[o.said_at].sentence != sentence or \
                not 0 < abs(o.said_at - e.said_at) <= 12:
            continue
        between = [t.word for t in r.tokens[min(o.said_at, e.said_at) + 1:max(o.said_at, e.said_at)]]
        if set(between) & LIST_MARKS and not set(between) & RENAMING:
            return True
    return False


def _place_in_queue(r: _Reader) -> None:
    """'third in the queue at a red light': two vehicles wait ahead of the ego; and whoever is ahead of an ego
    waiting in a queue or at a red light, doing nothing said, waits too."""
    words = [t.word for t in r.tokens]
    ego = next((e for e in r.entities if e.is_ego), None)
    for i, w in enumerate(words):
        n = ORDINALS.get(w)
        rest = words[i + 1:i + 4]
        with_ego = next((e for e in r.entities if e.includes_ego and e.count > 0 and not e.is_ego), None)
        mine = rest[:1] == ["one"] and i > 1 and words[i - 1] == "the" and words[i - 2] in COPULAS and \
            with_ego is not None  # "we were three cars ..., mine was the second one"
        if rest[:1] == ["of"] and i > 1 and words[i - 1] == "the" and words[i - 2] in COPULAS and \
                with_ego is not None and (n or w == "last"):  # "I was the second of three cars": mine
            n, mine = n or with_ego.count + 1, True
        if w == "middle" and (words[max(0, i - 2):i] == ["in", "the"] or words[i - 1:i] == ["the"] and
                              rest[:1] == ["one"]) and with_ego is not None and \
                with_ego.count % 2 == 0 and rest[:1] != ["of"]:  # ("ego is the middle one")
            n, mine = with_ego.count // 2 + 1, True  # "three cars including ours, we were in the middle": second
        if not n or not mine and (rest[:1] not in (["in"], ["car"], ["vehicle"]) or not {"queue", "line"} & set(rest)):
            continue
        ego = ego or _ego_entity(r, 0)
        queueing = not mine or RED_OR_QUEUE & set(words) or any(a[4] == "stop" for a in with_ego.actions)
        if queueing and not any(a[4] == "stop" for a in ego.actions):  # ("three cars including the ego driving
            # in one lane, ego in the middle": a place in a moving platoon, no queue)
            ego.actions.append((0, 2, ACTION_RANK["stop"], r.tick(), "stop", None))
        members = [e for e in r.entities if with_ego is not None and e.parent is with_ego]  # "the first car"
        if with_ego is not None and n - 1 < with_ego.count + len(members) and "ahead" not in with_ego.features:
            still_ahead = n - 1 - len([m for m in members if "behind" not in m.features])  # "three cars including
            # us, we were second": one ahead, one behind ("the car behind" is the one behind)
            told = [x for x in r.entities if x.definite and "behind" in x.features and x.count == 1 and
                    not x.is_ego and x.parent is None and x is not with_ego and x.type not in V.VULNERABLE_TYPES]
            # "... we were second. The following vehicle fails to stop": the one behind, told of by itself
            if still_ahead <= 0:
                with_ego.features.add("behind")
                with_ego.count = max(0, with_ego.count - len(told))
            elif with_ego.count - still_ahead - len(told) <= 0:
                with_ego.count = still_ahead
            else:
                behind = Entity(r.new_key(), with_ego.type, False, with_ego.stage,
                                count=with_ego.count - still_ahead - len(told), head=with_ego.head,
                                features=set(with_ego.features) | {"behind"}, actions=list(with_ego.actions),
                                behavior=with_ego.behavior)
                with_ego.count = still_ahead
                r.entities.append(behind)
        queued = [e for e in r.entities if not e.is_ego and e.type not in V.VULNERABLE_TYPES and e.count > 0 and
                  not e.features & {"behind", "side_left", "side_right", "road_straight", "toward", "road_left",
                                    "road_right"}] if n > 1 else []  # (first in line: no one ahead)
        for e in queued:
            e.features.add("ahead")  # "fourth in line behind a bus": the bus is one of those ahead
        ahead = sum(e.count for e in queued)
        if n - 1 > ahead and n - 1 <= MAX_AGENTS_PER_MENTION:
            r.entities.append(Entity(r.new_key(), "car", False, 0, count=n - 1 - ahead, head="car",
                                     features={"ahead"}))
            r.notes.append(f"inferred: '{w} in the queue' puts {n - 1 - ahead} car(s) ahead of the ego")
        r.used.update(range(i, i + 4))
        break
    jammed = any(u.category == "agents" and u.meaning == "none" and u.base in STANDING_TRAFFIC and k > 0 and (
        r.units[k - 1].word == "in" or k > 1 and r.units[k - 1].word in ("a", "the") and r.units[k - 2].word == "in")
        for k, u in enumerate(r.units))  # "in stopped traffic"; not "the tail end of a traffic jam"
    if jammed:
        ego = ego or _ego_entity(r, 0)
    if jammed and not any(a[0] == 0 and a[2] > 0 for a in ego.actions):
        ego.actions.append((0, 1, ACTION_RANK["stop"], r.tick(), "stop", None))  # "in stopped traffic": it stands
        r.notes.append("inferred: the ego stands in the stopped traffic")
    if ego is None or not any(a[4] == "stop" and a[0] == 0 for a in ego.actions):
        return
    if not RED_OR_QUEUE & set(words) and "traffic_light" not in _said_signals(r) and not jammed:
        if any(w == "stuck" and words[k + 1:k + 2] == ["behind"] for k, w in enumerate(words)) or not any(
                u.category == "actions" and u.meaning == "stop" and k + 1 < len(r.units) and
                r.units[k + 1].category == "positions" and r.units[k + 1].meaning == "behind"
                for k, u in enumerate(r.units)):
            return  # "stuck behind a lorry on a B-road": it may crawl along, the ego with it; "travelling behind
            # the truck stopped": behind it while moving
        for e in r.entities:  # "the ego is stopped behind a truck": what it stands behind, doing nothing said, stands
            if not e.is_ego and not e.actions and e.type not in V.VULNERABLE_TYPES and e.stage == 0 and \
                    e.features <= {"ahead", "ego_behind"} and "ahead" in e.features and e.relative_to is None:
                e.actions.append((0, 1, ACTION_RANK["stop"], r.tick(), "stop", None))
        return
    for e in r.entities:  # ahead in the queue, level beside the ego at the line, or queued with it: standing too
        # (until a later stage says it goes: "the light turns green and both go")
        honks = any(a[0] == 0 for a in e.actions) and all(a[4] == "horn" for a in e.actions if a[0] == 0)
        if not e.is_ego and (honks or not any(a[0] == 0 for a in e.actions)) and \
                (e.type not in V.VULNERABLE_TYPES or honks and e.head in VAGUE_PEOPLE) and e.stage == 0 and (
                # ("the guy behind me honking": a driver, read as one at the wheel later)
                "ahead" in e.features and not e.features & {"side_left", "side_right", "road_straight", "toward"}
                or "level" in e.features and not e.features & {"ahead", "behind", "road_straight", "toward"}
                or (e.parent or e).includes_ego and not e.features  # "three cars including mine at the red"
                or "behind" in e.features and not e.features & {"side_left", "side_right", "overtaking"} and
                (honks or _queued_with_the_ego(r, e))):  # "waiting at the red light with a van behind"; "the guy
            # behind me started honking": held up behind the ego
            e.actions.append((0, 2, ACTION_RANK["stop"], r.tick(), "stop", None))


def _queued_with_the_ego(r: _Reader, e: Entity) -> bool:
    """'I was waiting at the red light with a taxi in front of me and a white van behind': one said after 'with'
    in the sentence of the ego's wait, no verb of its own between, waits in the queue too."""
    if e.said_at < 0:
        return False
    sentence = r.tokens[e.said_at].sentence
    before = [t for t in r.tokens[:e.said_at] if t.sentence == sentence]
    at = next((k for k in range(len(before) - 1, -1, -1) if before[k].word == "with"), None)
    return at is not None and not any((lexicon().phrases.get((t.base,)) or ("",))[0] == "actions"
                                      for t in before[at + 1:])


STANDING_TRAFFIC = {"stop traffic", "stopped traffic", "traffic jam", "queue of traffic", "stationary traffic",
                    "standstill traffic", "gridlock", "queued traffic", "queuing traffic", "queueing traffic",
                    "jammed traffic", "tailback"}


def _said_signals(r: _Reader) -> set[str]:
    return {u.meaning for u in r.units if u.category == "road"}


VAGUE_PEOPLE = {"someone", "somebody", "guy", "dude", "person", "man", "woman", "lady", "people", "lad", "bloke",
                "mate", "lunatic", "nutter", "maniac", "numpty", "muppet", "idiot", "jerk", "moron",
                "chap", "fella", "fellow", "gentleman", "young man", "young woman", "teen", "teenager", "postman"}
ON_FOOT_WITH = {"pushing", "wheeling", "walking", "carrying", "pulling", "holding", "leading", "with"}
NAMED_ON_FOOT = {"pedestrian", "ped", "walker", "jogger", "runner", "pedestrian target"}
VEHICLE_ONLY_ACTIONS = {"cut_in", "lane_change", "lane_left", "lane_right", "turn", "turn_left", "turn_right", "u_turn",
                        "block"}
DONE_AT_A_WHEEL = {"cut_in": "cuts in", "lane_change": "changes lane", "lane_left": "moves left",
                   "lane_right": "moves right", "turn": "turns", "turn_left": "turns left", "turn_right": "turns right",
                   "u_turn": "makes a U-turn", "block": "blocks", "horn": "sounds a horn"}  # for the note it leaves


LETTING = {"let", "lets", "letting"}
MAKING = {"make", "makes", "made", "making"}  # before a bare verb: "makes the ego stop"
CAUSATIVES = {"force", "forced", "forces", "forcing", "cause", "caused", "causes", "causing", "make", "made", "makes",
              "making", "compel", "compelled", "require", "required", "requires", "oblige", "obliged"}


LIGHT_VERBS = {"perform", "make", "do", "carry", "execute", "an", "a", "the", "out"}


def _left_no_option(units: list[Unit], i: int, phrases: list[NounPhrase]) -> list[Entity]:
    """'leaving me no option but to perform an emergency stop': the verb is the one left without a choice's."""
    j = i - 1
    while j >= 0 and units[j].category == "word" and units[j].word in LIGHT_VERBS:
        j -= 1
    if j < 3 or units[j].word != "to" or units[j - 1].word != "but" or \
            units[j - 2].word not in ("option", "choice", "alternative"):
        return []
    np = next((p for p in phrases if j - 6 <= p.index < j - 2 and p.entity is not None), None)
    return [np.entity] if np is not None else []


def _made_to(units: list[Unit], i: int, phrases: list[NounPhrase]) -> list[Entity]:
    """'a truck forced the AV to change lanes': the verb after 'to' is the object's doing; so is the bare verb
    after 'let' or 'make' ('I let the van merge': the van merges, not I; 'makes the ego change lanes')."""
    left = _left_no_option(units, i, phrases)
    if left:
        return left
    if i >= 2 and units[i - 1].word != "to":
        k = i - 1
        while k > 1 and (units[k].category == "positions" or units[k].word in (
                "on", "to", "in", "at", "the", "my", "our", "its", "his", "her", "their")):
            k -= 1  # "lets a car from the road on the left turn right", "let a van on my right merge": the one let,
            # placed before its verb
        np = next((p for p in phrases if p.index == k and p.entity is not None), None)
        if np is not None and np.first > 0 and (units[np.first - 1].word in LETTING or units[np.first - 1].word in
                                                 MAKING and units[i].tokens[0].word == units[i].tokens[0].base):
            return np.group or [np.entity]  # ("make a scooter cutting in": the scene asked for)
    if i < 3 or units[i - 1].word != "to":
        return []
    np = next((p for p in phrases if p.index == i - 2 and p.entity is not None), None)
    if np is None or np.first == 0 or units[np.first - 1].word not in CAUSATIVES and not _waited_for(units, np.first):
        return []
    return np.group or [np.entity]


def _waited_for(units: list[Unit], first: int) -> bool:
    """'I waited for the kids to cross', 'the ego stops for a cyclist to pass': the one waited for does the verb."""
    j = first - 1
    while j > 0 and (units[j].category == "behaviours" or units[j].word.endswith("ly")):
        j -= 1  # "waits patiently for the bus"
    before = units[j]
    if before.category == "actions" and before.meaning == "stop" and before.tokens[-1].word == "for":
        return True
    return before.word == "for" and any(u.category == "actions" and u.meaning == "stop"
                                        for u in units[max(0, first - 3):first - 1])


PLACE_ADVERBS = {"around", "nearby", "about"}  # "the only other car around was a Camry": where, before what it is
# "the SV is a patrol car", "I am employed as a bus driver": what the first noun is, said of it
APPOSITION_WORDS = {"is", "was", "be", "are", "being", "as", "am", "employed", "working", "work", "works"}
STATING_MODALS = {"shall", "will", "must", "should"}  # "the vehicle under test shall be a goods vehicle": it is one
ROLE_NOUNS = {"target", "npc", "adversary", "actor", "agent", "dummy", "target vehicle", "participant", "object"}
ROLE_NAMES = {"pov", "vru", "target", "npc", "adversary", "gvt", "tv", "vut", "lead vehicle", "principal other vehicle",
              "other vehicle", "bv", "obstacle"}
APPOSED_HEADS = {"vehicle", "agent", "actor", "user", "party", "vru", "target", "pov", "sv", "npc", "adversary",
                 "participant", "object", "hero", "cv", "tpv", "iv"}  # said what they are


DISTANCE_UNITS = {"m", "metres", "meters", "metre", "meter", "yards", "yard", "feet", "ft", "km", "miles", "mile"}


def _imperative_on(units: list[Unit], verbs: list[int], phrases: list[NounPhrase], previous: list[Entity]) -> bool:
    """'stopped bus ahead, overtake it on the left': a bare verb opening a clause, done to the agent just named,
    is the ego's (an instruction), not that agent's."""
    if not verbs or verbs[0] != 0 or units[0].tokens[0].word != units[0].tokens[0].base:
        return False
    return any(u.word in ("it", "them", "him", "her") for u in units[1:3]) or any(
        np.index > 0 and np.entity is not None and np.entity in previous for np in phrases)


NOT_VERBS = {"straight", "left", "right", "l", "r", "ahead", "through", "protected", "unprotected", "first", "second",
             "third", "uturn", "u", "lane", "right", "hazard", "double", "queue", "stationary", "standstill"}


SAME_IN_THE_PAST = {"cut", "hit", "put", "set", "let", "shut", "quit", "burst", "cast", "hurt", "split", "spread",
                    "thrust", "run", "come", "become"}


def _bare_verb(u: Unit) -> bool:
    """A verb in its base form ('pull over', 'slow down'), as an order is given; not 'pulls', 'pulling'."""
    t = u.tokens[0]
    return u.category == "actions" and t.word == t.base and not t.word.endswith(("ing", "ed")) and \
        t.word not in NOT_VERBS


def _supplied(r: _Reader, e: Entity) -> bool:
    """An ego the reader supplied for a verb with no subject: named 'ego' while the text never says 'ego'."""
    return e.is_ego and e.head == "ego" and not any(t.word == "ego" for t in r.tokens)


def _ego_entity(r: _Reader, stage: int) -> Entity:
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is None:
        ego = Entity(r.new_key(), "car", True, stage, head="ego")
        r.entities.append(ego)
    return ego


def _said_not_there(units: list[Unit], np: NounPhrase) -> bool:
    """A noun phrase said not to be there: 'no vehicles', 'not a single car', 'without any pedestrians', or only
    there as scenery ('passengers waiting at the stop: scenery only')."""
    return units[np.index].category == "agents" and (
        units[np.first].category == "numbers" and units[np.first].meaning == "0" or
        np.first > 0 and units[np.first - 1].word in ("not", "without") or units[np.first].word in ("no", "zero") or
        _scenery_only(units, np.index))


def _scenery_only(units: list[Unit], head: int) -> bool:
    """'passengers waiting at the stop: scenery only': road users said, right after, to be scenery."""
    return any(x.word == "scenery" for x in units[head + 1:head + 6])


def _from_the_tellers_side(units: list[Unit]) -> bool:
    """'came from my right': a place said from the teller's side, of someone else (the verb's, before anyone named:
    not 'stopped for a car coming from my left')."""
    for u in units:
        if u.category == "agents":
            return False
        if u.category == "positions" and u.tokens[0].word == "from" and any(t.word in ("my", "our") for t in u.tokens):
            return True
    return False


def _said_of_another(r: _Reader, verb: Token, previous_subject: list[Entity]) -> bool:
    """A sentence opened by a verb in the third person ('Sits there honking') in a first-person account is not the
    speaker's: it goes on with the one the sentence before was about."""
    first_person = any(t.word in FIRST_PERSON for t in r.tokens)
    done_to_me = verb.index + 1 < len(r.tokens) and r.tokens[verb.index + 1].word in ("me", "us") and \
        verb.word.endswith("ed")  # "a guy on a motorcycle. Passed me on the left": the speaker is its object
    return first_person and len(previous_subject) == 1 and not previous_subject[0].is_ego and (
        verb.word.endswith("s") and not verb.word.endswith("ss") and verb.base != verb.word or done_to_me) and \
        not any(t.word.isalpha() and t.word not in ADVERBS for t in r.tokens[:verb.index]
                if t.sentence == verb.sentence)
    # (after a time stamp, or an adverb: "Just turns.")


INSTANCE_OPENINGS = (["for", "example"], ["for", "instance"], ["e", "g"], ["one", "instance"],
                     ["in", "the", "instance"], ["concrete", "case"], ["concrete", "example"], ["a", "typical"],
                     ["a", "clean", "example"], ["example", ","], ["say", "on"], ["say", "at"], ["say", "in"])


def _object_of_a_deed(r: _Reader, e: Entity) -> bool:
    """'I collided with the truck', 'we hit the van': one a verb of the road is done to or with is met there."""
    k = e.said_at - 1
    while k > 0 and r.tokens[k].word in DETERMINERS | OWNERS | COLOURS:
        k -= 1
    if k > 0 and r.tokens[k].word in ("with", "into", "past", "behind"):
        k -= 1
    return k >= 0 and r.tokens[k].sentence == r.tokens[e.said_at].sentence and r.tokens[k].base in _verbs() and \
        r.tokens[k].base not in lexicon().function_words or _subject_of_a_passive(r, e)


def _subject_of_a_passive(r: _Reader, e: Entity) -> bool:
    """'The cyclist was clipped by a van turning left': the one a deed is done to, said first."""
    k = e.said_at + 1
    while k < len(r.tokens) and r.tokens[k].word in ("was", "were", "is", "are", "got", "gets", "had", "has", "been",
                                                     "being", "just", "nearly", "almost", "then"):
        k += 1
    if k == e.said_at + 1 or k >= len(r.tokens) or r.tokens[k].base not in _verbs() or \
            r.tokens[k].sentence != r.tokens[e.said_at].sentence:
        return False
    return any(t.word == "by" and t.sentence == r.tokens[k].sentence for t in r.tokens[k + 1:k + 4])


def _an_unknown_verb_after(r: _Reader, e: Entity) -> bool:
    """'until the bus had cleared': a verb the lexicon does not know, right after the noun, says it does
    something."""
    k = e.said_at + 1
    while k < len(r.tokens) and r.tokens[k].word in ("had", "has", "have", "just", "finally", "been"):
        k += 1
    return 0 < k < len(r.tokens) and r.tokens[k].sentence == r.tokens[e.said_at].sentence and \
        r.tokens[k].word.endswith("ed") and r.tokens[k].word not in lexicon().vocabulary


GAPPING_LINKS = {"then", "and", "too", "also", "well", "followed", "next", "finally"}
GAPPING_WORDS = {"then", "and", "too", "also", "as", "well", "after", "that", "by", "next", "finally", "a", "an",
                 "another", "one", "more", ",", "followed"}


def _gapped(r: _Reader, clause: "Clause", previous: list[Entity], new: list[Entity]) -> None:
    """'two oncoming cars pass, then a cyclist': a clause of only a new agent, after a clause that said where its
    subject was and what it did, says the same of the new one (the verb and the place are gapped). One with a
    place of its own ('a bus is stopped behind me, and behind the bus a taxi') does what the subject did, there."""
    placed_here = any(u.category == "positions" for u in clause.units)
    if len(new) != 1 or new[0].is_ego or new[0].actions or len(previous) != 1 or previous[0].is_ego or \
            previous[0].type in V.VULNERABLE_TYPES and new[0].type not in V.VULNERABLE_TYPES or \
            (not (new[0].features or new[0].relative_to) if placed_here else new[0].features):
        return
    units = [u for u in clause.units if u.category != "comma" and u.word != "and"]
    if placed_here and not (units[0].category == "positions" and units[-1].category == "agents" and
                            units[-1].start <= new[0].said_at < units[-1].end):
        return  # (the place first, the one placed last: "a cyclist coming up behind me" has a verb of its own)
    allowed = {"agents", "word", "comma", "sequence", "numbers"} | ({"positions"} if placed_here else set())
    if any(u.category not in allowed or u.category == "word" and u.word not in GAPPING_WORDS and
           not (placed_here and u.word == "the") for u in clause.units):
        return
    last = clause.units[-1]
    if not (clause.link in ("and", "then") or clause.stage > previous[0].stage or any(
            u.category == "sequence" or u.word in GAPPING_LINKS for u in clause.units)) or \
            last.end < len(r.tokens) and r.tokens[last.end].sentence == last.tokens[-1].sentence:
        return  # ("then a Prius that was just ahead of me ...": its own clause goes on)
    model = previous[0]
    places = {f for f in model.features if f in PLACE_FEATURES or f in ("ahead", "behind", "level", "toward")}
    said = [a for a in model.actions if a[1] == 2 and a[0] == model.stage]
    if not (places or placed_here) or not said:
        return
    if not placed_here:
        new[0].features |= model.features - {"no_part", "on_board", "followed", "headline"}
    new[0].actions += [(new[0].stage, 2, a[2], r.tick(), a[4], a[5]) for a in said]
    r.notes.append(f"read '{new[0].head}' as doing what '{model.head}' did" + ("" if placed_here else ", where it did"))


TAKING_BACK = (["actually", "no"], ["scratch", "that"], ["scrap", "that"], ["never", "mind"], ["forget", "that"],
               ["on", "second", "thought"], ["on", "second", "thoughts"])


def _taken_back(r: _Reader) -> None:
    """'maybe a second person waiting on the pavement? actually no, just the one crossing': a sentence that opens
    by taking back the one before, naming no one new and asking for nothing instead, leaves out whom that one
    added."""
    tokens = r.tokens
    words = [t.word for t in tokens]
    for t in tokens:
        if t.sentence == 0 or tokens[t.index - 1].sentence == t.sentence:
            continue
        said = next((o for o in TAKING_BACK if words[t.index:t.index + len(o)] == o), None)
        if said is None:
            continue
        end = t.index + len(said)
        unit = next((u for u in r.units if u.start == end), None)
        if end < len(tokens) and tokens[end].sentence == t.sentence and (unit is None or unit.category != "comma"):
            continue  # ("actually no cars are parked": a denial, not a taking back)
        sentence = [x.word for x in tokens if x.sentence == t.sentence]
        if any(e.said_at >= 0 and tokens[e.said_at].sentence == t.sentence for e in r.entities if not e.is_ego) or \
                {"make", "instead", "change", "replace", "swap"} & set(sentence):
            continue  # "actually no, make it a truck": a correction, read as such
        dropped = [e for e in r.entities if not e.is_ego and e.said_at >= 0 and
                   tokens[e.said_at].sentence == t.sentence - 1]
        for e in dropped:
            r.entities.remove(e)
        if dropped:
            r.notes.append(f"left out {', '.join(e.head for e in dropped)}: taken back by '{' '.join(said)}'")


def _an_instance_given(r: _Reader) -> None:
    """'stopping_with_lead: the ego decelerates behind a lead vehicle that has come to a halt. A typical log shows
    the ego stopping behind a box truck': a kind of scene defined, then an instance of it told; the instance names
    the agents, and those of the definition are the kind's roles, played by them, not more agents."""
    tokens = r.tokens
    words = [t.word for t in tokens]
    start = next((t.index for t in tokens if t.sentence > 0 and tokens[t.index - 1].sentence != t.sentence and (
        any(words[t.index:t.index + len(o)] == o for o in INSTANCE_OPENINGS) or t.word in ("example", "instance") and
        (t.index + 1 == len(tokens) or tokens[t.index + 1].sentence != t.sentence or words[t.index + 1] == "from"))),
        None)  # "Example:", "Example from the logs:"
    if start is None:
        return
    roles = [e for e in r.entities if not e.is_ego and 0 <= e.said_at < start]
    if not roles or not any(not e.is_ego and e.said_at >= start and e.count > 0 for e in r.entities) or \
            any(e.parent in roles for e in r.entities):
        return
    for e in roles:
        r.entities.remove(e)
    r.notes.append("read the agents of the definition as roles of the instance told after it")


def _in_the_role_of(units: list[Unit], k: int) -> bool:
    """'a police car, added as a distractor, is parked': 'as' before a noun phrase that names no agent and ends its
    stretch of words says in what role, and opens no clause ('as a car approaches' does)."""
    return k + 2 < len(units) and units[k + 1].word in ("a", "an") and units[k + 2].category == "word" and \
        (k + 3 == len(units) or units[k + 3].category == "comma")


def _implied(r: _Reader, units: list[Unit], stage: int, verbs: list[int], inside=frozenset()) -> Entity | None:
    """A predicate with no subject: the ego's ('left turn at crossroads'), unless it places someone else
    ('aggressive cut-in from right lane ahead' is a car's)."""
    placed = any(u.category == "positions" and u.meaning not in ("ego_lane", "into_ego_lane", "used", "target_lane",
                                                                 "first_in_line", "crosswalk", "destination")
                 and k not in inside for k, u in enumerate(units) if k > verbs[0])
    cutting = any(units[i].meaning in ("cut_in", "block") for i in verbs)
    named = any(units[i].base in ("cut in", "cut off", "cut across", "cut") for i in verbs)  # "a cut-in", a noun
    turning_elsewhere = placed and any(units[i].meaning in ("u_turn",) for i in verbs)
    if placed and ((cutting and named) or turning_elsewhere):
        entity = Entity(r.new_key(), "car", False, stage, head="car",
                        headline=units[verbs[0]].tokens[0].sentence == 0, implied=True,
                        said_at=units[verbs[0]].tokens[0].index)
        r.entities.append(entity)
        r.notes.append(f"inferred: '{units[verbs[0]].base}' with no one named is a car's")
        return entity
    if cutting and named:
        return None  # "Double cut-in on a motorway ...": the name of the case, not the ego's doing
    v = verbs[0]
    if units[v].tokens[-1].word.endswith("ing") and v + 2 < len(units) and units[v + 1].category == "agents" and \
            units[v + 1].meaning == "none" and (units[v + 2].word in COPULAS or units[v + 2].category == "actions"):
        return None  # "merging traffic is still its weakness": what the traffic does, said of no one in the scene
    named_otherwise = _named_by_an_unknown_noun(r, units, verbs[0])
    if named_otherwise is not None:
        return named_otherwise  # "A taxi pulled out. The cabbie then stopped": the taxi, by a word not known
    if _someone_of_theirs(r, units, verbs[0]) or _an_unknown_one(r, units, verbs[0]):
        return None
    if any(u.word in ("means", "meant") for u in units) and not any(u.category == "agents" for u in units):
        return None  # "Yield means yield.", "Stop means stop": what a sign means, said of no one
    if verbs[0] > 0 and units[verbs[0] - 1].category == "weather" and \
            not units[verbs[0] - 1].meaning.startswith("time:"):
        return None  # "fog sitting over the bridge", "rain coming down": the weather's doing ("night ride" is not)
    return _ego_entity(r, stage)


WHEN_AFTER = {"later", "earlier", "after", "ago", "on", "then", "again", "too", "also", "still", "further"}


def _no_entry_of_its_own(t: Token) -> bool:
    """A word the lexicon has no entry for as a word of its own (it may be part of a longer phrase)."""
    lex = lexicon()
    return (t.word,) not in lex.phrases and (t.base,) not in lex.phrases and t.word not in lex.function_words


def _an_unknown_one(r: _Reader, units: list[Unit], verb: int) -> bool:
    """'A pony trap pulls out in front of the ego': a subject that opens its clause with 'a' and nouns the lexicon
    has no entry for is no one it can place; what it does is not the ego's."""
    tokens = r.tokens
    k = units[verb].start - 1
    words = []
    while k >= 0 and tokens[k].sentence == tokens[units[verb].start].sentence and tokens[k].word.isalpha() and \
            tokens[k].word not in ("a", "an") and len(words) < 2:
        words.append(tokens[k])
        k -= 1
    if k < 0 or tokens[k].word not in ("a", "an") or not words or words[0].word in WHEN_AFTER:
        return False  # ("a second later brakes hard": when, not who)
    opens = k == 0 or tokens[k - 1].sentence != tokens[k].sentence or tokens[k - 1].word in (",", "and", "then")
    return opens and all(_no_entry_of_its_own(t) for t in words)


def _someone_of_theirs(r: _Reader, units: list[Unit], verb: int) -> bool:
    """'His friend waits on the far side', 'their dog barked': a subject said as someone's by a noun the lexicon
    does not know opens its clause; it is no agent, and what it does is not the ego's."""
    tokens = r.tokens
    k = units[verb].start - 1
    if k < 1 or tokens[k - 1].word not in ("his", "her", "their") or not tokens[k].word.isalpha() or \
            tokens[k].word in lexicon().function_words or (tokens[k].word,) in lexicon().phrases or \
            tokens[k].sentence != tokens[units[verb].start].sentence:
        return False
    return k < 2 or tokens[k - 2].sentence != tokens[k].sentence or tokens[k - 2].word in (",", "and", "but", "so")


def _named_by_an_unknown_noun(r: _Reader, units: list[Unit], verb: int) -> Entity | None:
    """'A van pulled out. The courier then stopped', 'A tractor was ahead. The farmer turned left': a subject said
    definitely by a noun the lexicon does not know as a word of its own, after another agent was named, names that
    agent (the last one named) again, and not the ego."""
    tokens = r.tokens
    k = units[verb].start - 1
    while k >= 0 and (tokens[k].word in ("then", "now", "also", "still", "suddenly", "just", "finally") or
                      tokens[k].word.endswith("ly") and len(tokens[k].word) > 4):
        k -= 1
    if k < 1 or tokens[k - 1].word != "the" or tokens[k].sentence != tokens[units[verb].start].sentence:
        return None
    if k >= 2 and tokens[k - 2].sentence == tokens[k].sentence and tokens[k - 2].word not in (
            ",", "and", "but", "so", "then", "when", "while", "as", "until", "before", "after"):
        return None  # the subject starts its clause ("that's the whole unprotected-left problem" is no subject)
    word = tokens[k]
    if not _no_entry_of_its_own(word) or word.misspelt or \
            word.word.endswith(("ly", "ing", "ed", "s")) or len(word.word) < 3 or not word.word.isalpha():
        return None
    opening = [t.word for t in tokens if t.word.isalpha()][:2]
    if opening == ["the", word.word] and tokens[k].index > 1:
        return next((e for e in r.entities if e.is_ego), None)  # "The contact owns a Rogue ... The contact then
        # braked": the one the text opens on, as a complaint names its teller
    others = [e for e in r.entities if not e.is_ego and e.count == 1]
    return others[-1] if others else None


# A system's skills, said of a whole kind ("detect emergency vehicles").
SYSTEM_SKILLS = {"detect", "recognize", "recognise", "classify", "identify", "track", "handle", "perceive"}
GROUP_NOUNS = {"family", "group", "crowd", "party", "gang", "bunch", "convoy", "column", "pack", "couple", "line",
               "queue", "peloton", "class", "team", "troop", "pedestrians", "people"}
NOT_A_MEMBER_AFTER_ONE = {"of", "lane", "lanes", "way", "direction", "side", "after", "another", "by", "more",
                          "time", "day", "moment", "point", "second", "stage", "step", "phase", "hand"}
def _the_ego_is(units: list[Unit], k: int) -> bool:
    """'mine was', 'I am', 'the ego is' at units[k - 1:k + 1]: what follows says the ego's own place."""
    return k > 0 and units[k].word in COPULAS and (
        units[k - 1].word in ("mine", "i", "we", "ours") or units[k - 1].category == "agents" and
        units[k - 1].meaning == "ego")


ORDINAL_MEMBERS = {"first", "second", "third", "fourth", "fifth", "last", "latter", "former"}
ORDINAL_NUMBERS = {"second": 2, "third": 3, "fourth": 4, "fifth": 5}


def _part_of_group(r: _Reader, n: int) -> Entity | None:
    """n members of the last counted group, described together ('four on the left')."""
    for group in reversed(r.entities):
        if group.is_ego or group.parent is not None or group.count < n:
            continue
        if group.count == n and any(m.parent is group for m in r.entities):
            return group  # the rest of it
        if group.count == n:
            return None
        part = Entity(r.new_key(), group.type, False, group.stage, count=n, head=group.head, parent=group,
                      features=set(group.features), actions=[(a[0], 1) + a[2:] for a in group.actions],
                      behavior=group.behavior)
        group.count -= n
        group.group_open = max(0, group.group_open - n)
        r.entities.append(part)
        return part
    return None


ONE_LANE_OR_ONCOMING = (("oncoming",), ("other", "way"), ("opposite", "direction"), ("towards", "me"), ("narrow",),
                        ("one", "lane"), ("single", "carriageway"), ("single", "track"))


def _one_lane_with_oncoming(tokens: list[Token]) -> bool:
    """'Narrow street with two cars parked on my side, and a van coming the other way ... went round them': a road
    of one lane each way, or traffic said to come the other way; going round is no change to another lane."""
    return _says_any([t.word for t in tokens], ONE_LANE_OR_ONCOMING)


def _passing_one_off_the_lanes(r: _Reader, units: list[Unit], k: int, side: str) -> bool:
    """'going past it in the right lane' when 'it' is the one stopped on the shoulder, 'a truck on the right lane
    ... I am overtaking him on the left lane': the one passed is off the ego's lane, on the other side, so the
    ego passes in its own lane."""
    said_again = any(u.word in ("it", "him", "her", "them") for u in units[k + 1:k + 3]) or \
        k + 1 < len(units) and units[k + 1].category == "positions" and units[k + 1].tokens[0].word in ("in", "on")
    # ("a van stands on the hard shoulder while the subject vehicle passes in the right-hand lane")
    last = next((e for e in reversed(r.entities) if not e.is_ego and e.count >= 1 and e.type != "pedestrian"), None)
    if not said_again or last is None:
        return False
    other = OTHER_SIDE[side]
    in_the_other_lane = f"side_{other}" in last.features and not last.features & {"parked", "ego_behind"} and (
        "lane_said" in last.features or not any(a[4] == "stop" for a in last.actions))
    # (a van parked on the right, or "behind a truck in the right lane", is passed by pulling out round it)
    return last.road_type == "shoulder" or in_the_other_lane


def _side_of_passing_the_ego(units: list[Unit], i: int) -> bool:
    """'(overtook) me on the right', 'passed us on the left': the side a vehicle passes the ego on."""
    j = i - 1
    if j >= 0 and units[j].category == "agents" and units[j].meaning == "ego":
        j -= 1
    return j >= 0 and units[j].category == "actions" and bool(set(units[j].base.split()) & OVERTAKING) and (
        j < i - 1 or units[i].tokens[0].word == "on")  # ("pulls out to overtake on the left": the ego unsaid)


def _the_one_placed(r: _Reader, units: list[Unit], i: int) -> Entity | None:
    """'the one in front', 'the one behind me': the one already placed there, among those named before."""
    if not (i > 0 and units[i - 1].word == "the" and i + 1 < len(units) and units[i + 1].category == "positions"
            and units[i + 1].meaning in ("ahead", "behind", "side_left", "side_right")):
        return None
    place = units[i + 1].meaning
    found = [e for e in r.entities if not e.is_ego and e.count > 0 and place in e.features]
    return found[-1] if len(found) == 1 or found and found[-1].parent is not None else None


def _named_with(r: _Reader, word: str, within: int) -> list[Entity]:
    """The single road users whose noun had `word` said up to `within` words before it ('a white Volvo truck')."""
    return [e for e in r.entities if not e.is_ego and e.count == 1 and e.said_at > 0 and
            word in {t.word for t in r.tokens[max(0, e.said_at - within):e.said_at]}]


def _a_model_then_its_noun(units: list[Unit], i: int) -> bool:
    """'a red Ford Transit Custom van', 'a Toyota Hilux Invincible pickup': a make or model, a word of its trim
    the lexicon does not know, then the vehicle's noun: one vehicle, named by the noun."""
    if i + 2 >= len(units):
        return False
    u, trim, noun = units[i], units[i + 1], units[i + 2]
    return u.category == noun.category == "agents" and u.meaning in V.EGO_TYPES and noun.meaning in V.EGO_TYPES \
        and trim.category == "word" and len(trim.tokens) == 1 and trim.word not in lexicon().vocabulary and \
        trim.word not in lexicon().function_words and trim.word not in PAINT and trim.word.isalpha() and \
        not u.tokens[-1].plural


def _named_by_its_make(r: _Reader, u: Unit) -> list[Entity]:
    """'a white Volvo truck ... the Volvo pulls out': a make said before another noun names that one again."""
    if len(u.tokens) != 1:
        return []
    found = [e for e in _named_with(r, u.tokens[0].word, 2) if e.head != u.base]
    return found if len(found) == 1 else []


def _the_one_by_its_paint(r: _Reader, units: list[Unit], i: int) -> Entity | None:
    """'the red one', 'the silver one': the one road user named before with that paint."""
    if not (i > 1 and units[i - 2].word == "the" and units[i - 1].word in PAINT):
        return None
    found = _named_with(r, units[i - 1].word, 3)
    return found[0] if len(found) == 1 else None


def _place_follows(units: list[Unit], i: int) -> bool:
    """'one on the left', 'one on my right': a place comes right after the word."""
    for u in units[i + 1:i + 4]:
        if u.category == "positions":
            return True
        if u.word in (",", "and", ";") or u.category == "actions" or (u.category == "agents" and u.meaning != "ego"):
            return False
    return False


GROUP_PLACES = {"ahead", "behind", "level", "side_left", "side_right", "road_straight", "road_left", "road_right",
                "from_left", "from_right", "shoulder", "sidewalk", "destination"}


def _one_more_of_a_placed_group(r: _Reader, units: list[Unit], i: int, phrases: list[NounPhrase]) -> Entity | None:
    """'two trucks ahead of me and one in the lane on my right': the two were placed together already, and one
    'one' cannot share out two, so it is one more truck; 'two cars, one in front and one behind' shares them out."""
    if not _place_follows(units, i) or i > 0 and units[i - 1].word not in (",", "and", ";", "plus"):
        return None  # "the second one close behind the first": a member
    group = next((e for e in reversed(r.entities) if not e.is_ego and e.parent is None and e.count >= 1), None)
    if group is None or group.count < 2 or group.generic or group.includes_ego or group.group_open != group.count \
            or any(m.parent is group for m in r.entities):
        return None
    said = next((np for np in phrases if np.entity is group and np.index < i), None)
    placed = bool(group.features & GROUP_PLACES) or said is not None and any(
        u.category == "positions" for u in units[said.index + 1:i])
    if not placed:
        return None
    sentence = units[i].tokens[0].sentence
    rest = [u for u in r.units if u.start >= units[i].start and u.tokens[0].sentence == sentence]
    ones = sum(u.word == "one" for u in rest)
    if ones >= group.count or any(u.word in ("other", "rest", "another", "second", "others") for u in rest):
        return None
    return group


def _more_said_alone(units: list[Unit], i: int) -> bool:
    """'two more pull up', 'then two more come straight after it', 'one more behind it': a count and 'more' with no
    noun after them, doing or placed, name more of the kind just named."""
    if i + 2 >= len(units) or units[i + 1].word != "more":
        return False
    nxt = units[i + 2]
    return nxt.category in ("actions", "positions") or nxt.category == "word" and nxt.word in (
        "come", "came", "comes", "pull", "pulled", "pulls", "follow", "followed", "follows", "are", "were", "arrive",
        "arrived", "turn", "turned", "appear", "appeared", "join", "joined")


def _one_more_like(r: _Reader, kin: Entity, stage: int, why: str, listed_after: Entity | None = None) -> Entity:
    """A new agent of the kind of one named before ('a blue one', 'another', 'one on the left'), noted; one listed
    after it does what it does unless said to do otherwise."""
    member = Entity(r.new_key(), kin.type, False, stage, head=kin.head, listed_after=listed_after)
    r.entities.append(member)
    r.notes.append(f"inferred: {why}")
    return member


def _names_them_together(units: list[Unit], i: int) -> bool:
    """'the pair', 'the two (of them)', 'the duo', 'each (of them)', 'all three', 'all of them' before a verb: those
    just named, together."""
    u = units[i]
    if u.category not in ("word", "numbers") or i + 1 >= len(units):
        return False
    after = i + 1 + 2 * ([x.word for x in units[i + 1:i + 3]] == ["of", "them"])
    acts = after < len(units) and (units[after].category == "actions" or units[after].word in AUXILIARIES)
    if u.word in ("each", "all"):  # "each turns left", "all of them turn right"
        return acts and (i == 0 or units[i - 1].word in ("and", ",", "then")) and (u.word == "each" or after > i + 1)
    return acts and (u.word in ("pair", "duo", "two", "three") and i > 0 and units[i - 1].word == "the" or
                     u.word in ("two", "three", "four", "five") and i > 0 and units[i - 1].word == "all")  # "all three"


def _rest_of_a_group(r: _Reader) -> Entity | None:
    """'the others', 'the rest', 'the remaining two': those of the last group some members were told apart from."""
    return next((e for e in reversed(r.entities) if not e.is_ego and e.parent is None and e.count >= 1 and
                 any(m.parent is e for m in r.entities)), None)


def _last_count(r: _Reader) -> int:
    """How many the last counted group named has (0: none named)."""
    group = next((e for e in reversed(r.entities) if not e.is_ego and e.parent is None and e.count > 1), None)
    return 0 if group is None else group.count + sum(1 for e in r.entities if e.parent is group)


def _past_the_count(r: _Reader, ordinal: str) -> bool:
    """'two pedestrians cross while third walks': an ordinal past the last group's count names one more."""
    return _last_count(r) > 0 and ORDINAL_NUMBERS.get(ordinal, 0) == _last_count(r) + 1


def _stands_alone(units: list[Unit], i: int) -> bool:
    """'another behind', 'and another one waits': 'another' with no noun of its own, up to a place, a verb,
    a comma or the end, past an adverb ('another already mid-crossing'; 'another red car' and 'another one of them'
    have theirs)."""
    j = i + 1
    if j < len(units) and units[j].word == "one":
        j += 1
    while j < len(units) and (_sentence_adverb(units[j]) or units[j].category == "behaviours"):
        j += 1
    return j >= len(units) or units[j].category in ("positions", "actions", "comma", "sequence") or \
        units[j].word in AUXILIARIES | {"and", "but", "then", "who", "which", "that", "coming", "going"}


def _enumerated_one(r: _Reader, units: list[Unit], i: int, phrases: list[NounPhrase]) -> Entity | None:
    """'one car in front, one on the left, one on the right': with no counted group before, a list item 'one' +
    place after an agent itself counted 'one' names one more of that kind, placed there; so does a clause of
    its own that opens on 'one' and its verb ('one car waits on the left and one turns right')."""
    opens = i == 0 or i == 1 and units[0].word in ("and", "but", "while", "whereas")
    acts = opens and i + 1 < len(units) and units[i + 1].category == "actions"
    if not (_place_follows(units, i) or acts):
        return None
    before = [np for np in phrases if np.index < i and np.entity is not None and not np.entity.is_ego]
    if i > 0 and units[i - 1].word in (",", "and", ";") and before:
        last = before[-1]
        return last.entity if units[last.first].word == "one" and last.entity.count == 1 else None
    if opens and r.listed_one is not None and r.listed_one[1] == units[i].tokens[0].sentence:
        return r.listed_one[0]  # the list goes on past a clause break
    return None


def _member(r: _Reader, recent: list[Entity]) -> Entity | None:
    """One member of the last counted group, which the text now describes on its own."""
    for group in reversed(r.entities):
        if group.is_ego or group.parent is not None:
            continue
        if group.count == 1 and any(m.parent is group or m.named_of is group for m in r.entities) and \
                not group.label:
            group.label = "#rest"  # "one from the left and one from the right": the second is what is left
            group.includes_ego = False  # "three cars including the ego ... the other one": not the ego again
            return group
        if group.count < 2:
            continue
        member = Entity(r.new_key(), group.type, False, group.stage, head=group.head, parent=group,
                        features=set(group.features), actions=[(a[0], 1) + a[2:] for a in group.actions],
                        behavior=group.behavior)  # what the group does, unless the member is said to do otherwise
        group.count -= 1
        group.group_open = max(0, group.group_open - 1)
        r.entities.append(member)
        return member
    return None


def _listed_single(r: _Reader, ordinal: str) -> Entity | None:
    """The nth of the road users last named one by one in a list ('a car, a van and a truck wait ahead; the first
    turns right'): the latest sentence that named two or more, in the order named."""
    named = sorted((e for e in r.entities if not e.is_ego and e.count == 1 and e.parent is None and e.said_at >= 0),
                   key=lambda e: e.said_at)
    by_sentence: dict[int, list[Entity]] = {}
    for e in named:
        by_sentence.setdefault(r.tokens[e.said_at].sentence, []).append(e)
    listed = next((row for _, row in sorted(by_sentence.items(), reverse=True) if len(row) >= 2), [])
    n = len(listed) if ordinal == "last" else 1 if ordinal == "first" else ORDINAL_NUMBERS.get(ordinal, 0)
    return listed[n - 1] if 0 < n <= len(listed) else None


RIDING_ON = (["on"], ["riding"], ["astride"], ["rides"], ["rode"], ["ride"], ["is", "riding"], ["was", "riding"],
             ["pedals"], ["pedalled"], ["pedaled"], ["pedaling"], ["pedalling"])  # "a man rides a bike": the cyclist


RODE = {"was", "is", "were", "are", "riding", "rode", "rides", "came", "comes", "coming", "cycling", "pedalling",
        "pedaling", "slowly", "quickly", "along", "down", "up", "the", "road", "street", "lane", "just", "then"}


def _rode_on(between: list[Unit]) -> bool:
    """'riding towards us on', 'came down the road on': words of riding and of where, then 'on' the two-wheeler."""
    return len(between) >= 2 and between[-1].word == "on" and any(
        u.word in ("riding", "rode", "rides", "cycling", "pedalling", "pedaling", "came", "comes", "coming")
        for u in between) and all(u.category in ("positions", "behaviours") or u.category == "agents" and
                                  u.meaning == "ego" or u.word in RODE for u in between[:-1])


def _anothers_siren(r: _Reader, units: list[Unit], after: int) -> bool:
    """'an ambulance comes up behind the car with its siren blaring': the siren is the emergency vehicle's, so
    'the car' is not set apart by it."""
    return units[after].word == "with" and any(e.type in V.EMERGENCY_TYPES for e in r.entities) and any(
        t.word in ("siren", "sirens", "blues", "beacons") for u in units[after + 1:after + 4] for t in u.tokens)


def _placed_driver(units: list[Unit], before: list[NounPhrase], np: NounPhrase) -> NounPhrase | None:
    """'the guy in front of me in a Subaru', 'some woman just behind us in a Prius': a driver placed, then 'in' the
    vehicle he drives; the words between are only where he is (the ego named in them is no driver)."""
    if not np.introduced or np.plural or np.entity is None or np.entity.type in V.VULNERABLE_TYPES:
        return None
    k = len(before) - 1
    while k >= 0 and before[k].entity is not None and before[k].entity.is_ego:
        k -= 1  # "in front of me": the ego in the place words
    if k < 0 or before[k].entity is None or before[k].entity.head not in DRIVERS or before[k].entity.count != 1 \
            or before[k].plural:
        return None
    between = units[before[k].index + 1: np.first]
    placed = len(between) >= 2 and between[-1].word == "in" and any(u.category == "positions" for u in between) \
        and all(u.category == "positions" or u.category == "agents" and u.meaning == "ego" or
                u.word in ("of", "the", "to", "on", "at", "my", "our", "your") for u in between[:-1])
    return before[k] if placed else None


def _appositions(r: _Reader, units: list[Unit], phrases: list[NounPhrase]) -> list[NounPhrase]:
    """'VUT is a bus', 'the ego, a city bus,', 'SV1 is an oncoming truck, SV2 an oncoming car': the second noun
    says what the first is; it is no new agent."""
    out: list[NounPhrase] = []
    folded_at: dict[int, int] = {}
    for np in phrases:
        if np.introduced and np.entity is not None and _a_likeness(units, np):
            if np.entity in r.entities:  # "driving like a taxi driver", "it sounded like a truck": a comparison
                r.entities.remove(np.entity)
            r.notes.append(f"left out: '{np.entity.head}' is only a comparison")
            continue
        if np.entity is not None and not np.entity.label and not np.entity.is_ego and not np.plural:
            name = next((u.tokens[0].label for u in units[np.first:np.index] if u.category == "agents" and
                         u.meaning == "generic" and len(u.tokens) == 1 and u.tokens[0].label), None)
            if name:
                np.entity.label = name  # "npc1 car from left ... behind npc1": the car is the one named npc1
        driver = _placed_driver(units, out, np)
        if driver is not None:  # "the guy in front of me in a Subaru": the Subaru, where the guy is
            _fold(r, driver.entity, np.entity)
            continue
        prev = out[-1] if out else None
        if prev is not None and prev.entity is not None and np.entity is not None and np.introduced and \
                not np.plural and prev.entity.parent is not None and units[prev.index].word in ("them", "those",
                                                                                              "these") and \
                np.first == prev.index + 1 and units[np.first].word in ("a", "an"):
            if np.entity in r.entities:  # "two pedestrians, one of them a mother with a buggy": the member named
                r.entities.remove(np.entity)
            continue
        if prev is not None and prev.entity is not None and np.entity is not None and \
                prev.entity.is_ego != np.entity.is_ego and _set_off(r.tokens, units, prev, np):
            ego, other = (prev.entity, np.entity) if prev.entity.is_ego else (np.entity, prev.entity)
            if not (np.introduced or prev.introduced) or other.count > 1:
                out.append(np)
                continue
            if other.type in V.EGO_TYPES and other.type != "car":
                ego.type = other.type  # "the ego, a city bus,", "Alex's delivery van -- the ego --"
            ego.aliases.add(other.head)  # "a motorcyclist (the subject vehicle) ... The motorcyclist then stops"
            if other in r.entities:
                r.entities.remove(other)
            if np.entity is ego:
                out[-1] = np
            continue
        if prev is not None and np.entity is not None and np.entity.is_ego and prev.entity is not None and \
                prev.entity.label and not prev.entity.is_ego and np.first > prev.index + 1 and \
                all(u.category == "comma" for u in units[prev.index + 1: np.first]):
            np.entity.label = prev.entity.label  # "V1 (the AV)": V1 is the ego
            if prev.entity in r.entities:
                r.entities.remove(prev.entity)
            out[-1] = np
            continue
        if prev is not None and np.entity is not None and prev.entity is not None and np.introduced and \
                np.entity.label and not prev.entity.label and not prev.entity.is_ego and prev.entity.count == 1 and \
                len(units[np.index].tokens) == 1 and units[np.index].tokens[0].label and np.index + 1 < len(units) and \
                units[np.index + 1].category == "comma" and \
                [u.category for u in units[prev.index + 1: np.first]] == ["comma"]:
            prev.entity.label = np.entity.label  # "a white SUV (TV1) ... TV1 cuts in": the name it goes by
            if np.entity in r.entities:
                r.entities.remove(np.entity)
            continue
        if prev is not None and np.introduced and prev.entity is not None and np.entity is not None \
                and prev.plural and np.plural and not prev.entity.is_ego and np.entity.type in V.TWO_WHEELER_TYPES \
                and (prev.entity.type == "pedestrian" or prev.entity.head.split()[-1] in ("riders", "rider")) \
                and [u.word for u in units[prev.index + 1: np.first]] in RIDING_ON:
            _fold(r, prev.entity, np.entity)  # "two kids on scooters": two riders, counted by the people
            continue
        if prev is not None and prev.introduced and not np.introduced and prev.entity is not None and \
                np.entity is not None and not prev.entity.is_ego and not np.entity.is_ego and \
                prev.entity.head in DRIVERS and prev.entity.count == 1 and \
                np.entity.type not in V.VULNERABLE_TYPES and [u.word for u in units[prev.index + 1:np.first]] == ["in"]:
            if prev.entity in r.entities:  # "the young man in the van leaned on his horn": the van's driver, the
                r.entities.remove(prev.entity)  # van named again
            out[-1] = np
            continue
        if np.introduced and _at_the_wheel_of(units, out, np):
            ego = next(p.entity for p in reversed(out) if p.entity is not None)
            ego.type = np.entity.type if np.entity.type != "car" else ego.type
            if np.entity in r.entities:  # "I was on patrol in a marked police vehicle": the ego's own vehicle
                r.entities.remove(np.entity)
            continue
        owned = np.introduced and (_owned_by_the_teller(r, units, np) or _kept_for_years(units, np))
        if np.introduced and (_the_speakers_seat(r, units, np) or _the_one_the_speaker_was_on(units, np) or
                              _driven_with_no_subject(r, units, np) or owned):
            ego = _ego_entity(r, np.entity.stage)
            ego.type = np.entity.type if np.entity.type != "car" else ego.type
            ego.aliases.add(np.entity.head)  # "... The lorry turns left": the ego, named again
            if np.entity in r.entities:  # "coming through the village in the tipper": the speaker's own vehicle
                r.entities.remove(np.entity)
            r.owned = r.owned or owned
            r.notes.append(f"read 'the {np.entity.head}' the speaker rides in as the ego's")
            out.append(NounPhrase(ego, np.index, np.first))
            continue
        if prev is not None and np.introduced and prev.plural and not np.plural and prev.entity is not None and \
                np.entity is not None and not prev.entity.is_ego and prev.entity.type == "pedestrian" and \
                prev.entity.head in DRIVERS and np.entity.type in V.EGO_TYPES and \
                [u.word for u in units[prev.index + 1:np.first]] == ["in"]:
            if prev.entity in r.entities:  # "two lads in a Golf come up on my right": one car, its people inside
                r.entities.remove(prev.entity)
            out[-1] = np
            continue
        if prev is not None and np.introduced and prev.entity is not None and np.entity is not None \
                and not prev.plural and not np.plural and not (prev.entity.label and np.entity.label):  # "ped_1, ped_2"
            between = units[prev.index + 1: np.first]
            copula = any(u.category == "word" and u.word in APPOSITION_WORDS for u in between)
            bracket = units[folded_at.get(id(prev), prev.index) + 1: np.first]  # after the noun last folded in
            abbreviation = bracket and all(u.category == "comma" or u.base in ROLE_NOUNS for u in bracket) and \
                np.first == np.index and \
                len(units[np.index].tokens) == 1 and not prev.entity.is_ego and (
                    np.entity.type == prev.entity.type) and units[np.index].base not in GENERAL_NOUNS
            role_name = between and all(u.category == "comma" for u in between) and np.first == np.index and \
                units[np.index].base in ROLE_NAMES and not prev.entity.is_ego and not np.entity.is_ego
            if abbreviation or role_name:  # "a stationary Global Vehicle Target (GVT)": its short name, no second
                # agent; "an oncoming pickup (POV)": its role in the study
                prev.entity.aliases.add(units[np.index].base)
                if np.entity in r.entities:
                    r.entities.remove(np.entity)
                continue
            seat = ["in"] if _placed_on_the_way_in(between) else [
                u.word for u in between if not (u.category in ("actions", "behaviours") and
                                                u.tokens[0].word.endswith("ing"))] \
                if len(between) == 2 else [u.word for u in between]
            # "some bloke speeding in a white hatchback", "the dude coming the other way in a lifted pickup"
            driver = (prev.entity.head in DRIVERS or prev.entity.head.split()[-1] == "rider" and
                      np.entity.type in V.TWO_WHEELER_TYPES) and (seat in (
                ["in"], ["driving"], ["on"], ["of"]) or not between and units[np.first].word == "of") or (
                # "the driver of a stopped bus": the bus
                prev.entity.type == "pedestrian" and ([u.word for u in between] in RIDING_ON or _rode_on(between))
                and np.entity.type in V.TWO_WHEELER_TYPES)  # "a lad on a bike": the cyclist; "a woman riding
            # towards us on a bicycle": one who rides it
            placed = not prev.entity.is_ego and prev.entity.head.split()[-1] in APPOSED_HEADS | {"car"} and \
                len(between) >= 2 and between[-1].category == "comma" and (
                    units[np.first].word in ("a", "an") or _undetermined(units, np)) and \
                np.index + 1 < len(units) and units[np.index + 1].category in ("comma", "word") and \
                units[np.index + 1].word not in ("and", "or") and \
                (between[0].category == "positions" or between[0].word in ("on", "in", "to") and any(
                    u.category == "positions" for u in between)) and all(
                    u.category in ("positions", "comma") or u.category == "agents" and u.meaning == "ego"
                    or u.word in ("the", "of", "on", "in", "to", "my", "our", "your") for u in between)
                # "the vehicle on my left, a red minivan,": the vehicle is the minivan
            said_to_be = not prev.entity.is_ego and units[prev.first].word == "the" and len(between) >= 2 and \
                between[-1].category == "word" and between[-1].word in COPULAS and \
                units[np.first].word in ("a", "an") and \
                (prev.entity.type == "pedestrian") == (np.entity.type == "pedestrian") and \
                between[0].category == "positions" and all(
                    u.category == "positions" or u.category == "agents" and u.meaning == "ego" or
                    u.word in ("the", "of", "on", "in", "to", "my", "our", "your") for u in between[:-1])
            # "the driver behind me was an idiot", "the car in the left lane was a taxi": what the one placed is
            if placed or said_to_be:  # "the vehicle behind me, a white Ford Transit, failed to stop": the Ford
                a, b = prev.entity, np.entity
                a.head = b.head
                a.aliases |= b.aliases | {b.head}
                _fold(r, a, b)
                continue
            mine = prev.entity.is_ego and np.entity.type in V.EGO_TYPES and len(units[prev.index].tokens) > 1 and \
                _named_make(units[prev.index + 1: np.index + 1], np.entity.type) and \
                not _placed_after(units, np.index) and not _does_after(units, np.index)
            # "my vehicle, a grey Vauxhall Astra,": its make and model; not "ego vehicle, a bus behind"
            if mine:
                prev.entity.type = np.entity.type if np.entity.type != "car" else prev.entity.type
                prev.entity.aliases.add(np.entity.head)
                if np.entity in r.entities:
                    r.entities.remove(np.entity)
                continue
            if driver:  # "a learner driver in a little hatchback": the hatchback
                _fold(r, prev.entity, np.entity)
                continue
            closed = between and all(u.category == "comma" for u in between) and not prev.entity.is_ego and \
                units[np.first].word in ("a", "an") and np.entity.type == prev.entity.type and \
                _closed_after(units, np.index)
            if closed:  # "a pedestrian, a child, crosses": the pedestrian is a child
                prev.entity.aliases.add(np.entity.head)
                if np.entity in r.entities:
                    r.entities.remove(np.entity)
                continue
            example = between and between[0].category == "comma" and all(
                u.category == "comma" or u.word in ("like", "say", "maybe", "probably") for u in between) and \
                not prev.entity.is_ego and not prev.entity.actions and np.entity.type == prev.entity.type and \
                prev.entity.count == 1 and np.index + 1 < len(units) and units[np.index + 1].category == "actions" \
                and units[np.index + 1].tokens[0].word.endswith("ing")
            if example:  # "one with a pedestrian, like someone jaywalking across": the one asked for, described
                prev.entity.aliases.add(np.entity.head)
                _fold(r, prev.entity, np.entity)
                out.append(replace(np, entity=prev.entity, introduced=False))
                continue
            bare = _undetermined(units, np)  # "SV1 is oncoming truck", "POV, heavy truck, enters": articles dropped
            to_be = [u.word for u in between[-2:]] == ["to", "be"]  # "we want the ego to be a bus"
            if all((u.category == "word" and u.word in APPOSITION_WORDS | STATING_MODALS | {"like"}) or
                   u.category == "word" and u.word == "to" and to_be or
                   u.category == "word" and u.word in PLACE_ADVERBS and copula or
                   # ("the only other car around was a Camry": where it was, then what it was)
                   u.category == "word" and u.word in ("a", "an") and copula and prev.entity.is_ego or
                   # ("the ego is a westbound semi turning right": the article before a heading said of the noun)
                   u.category == "comma" or bare and (copula or prev.entity.label) and u.category == "positions" and
                   len(u.tokens) == 1 and u.word in ADJECTIVE_POSITIONS and not _a_verb_after_the_copula(units, u)
                   for u in between) and (
                    copula or prev.entity.label or (between and prev.entity.is_ego and np.entity.type in V.EGO_TYPES and
                                                      not _placed_after(units, np.index) and (
                        units[np.first].word in ("a", "an") and not _does_after(units, np.index) or
                        np.first == np.index and (
                        _closed_after(units, np.index) or len(units[prev.index].tokens) == 1 and
                        units[np.index].end < len(r.tokens) and r.tokens[units[np.index].end].word == ",")))
                    # "the ego, sedan, turns", "Ego (car)"; not "ego, oncoming SUV", "ego bus, lead car braking",
                    # "the ego, a pedestrian and a truck", "ego, a bus behind,"
                    or (between and prev.entity.head.split()[-1] in APPOSED_HEADS and not prev.entity.is_ego
                        and (units[np.first].word in ("a", "an") or bare and _closed_after(units, np.index)))
                    or (between and not prev.entity.is_ego and np.entity.head in ROLE_NAMES and
                        units[np.first].word == "the" and _closed_after(units, np.index))
                    # "a truck, the lead vehicle, brakes hard": the role the truck plays
                    # "a third-party vehicle, a silver hatchback,", "POV, heavy truck, enters"
                    or (between and prev.entity.head in categories() and np.first == np.index and
                        np.entity.type in categories()[prev.entity.head])):  # "a VRU (cyclist)": which one it is
                a, b = prev.entity, np.entity
                if a.is_ego:
                    if b.type in V.EGO_TYPES:
                        a.type = b.type
                        a.aliases.add(b.head)  # "The ego is a white SUV. A bus behind the SUV": the ego again
                elif a.label or a.head == "car" or a.head.split()[-1] in APPOSED_HEADS:
                    _fold(r, a, b)
                    folded_at[id(prev)] = np.index  # "Target is a pedestrian dummy (EPTa)": the dummy's short name
                if b in r.entities:
                    r.entities.remove(b)
                continue
        out.append(np)
    return out


def _undetermined(units: list[Unit], np: NounPhrase) -> bool:
    """A noun phrase said with no article, determiner or count ('white Ford Transit'), as notes drop them."""
    return units[np.first].category not in ("numbers", "number") and \
        units[np.first].word not in DETERMINERS | {"a", "an", "one", "another"}


def _relative_says_what_it_is(r: _Reader, clause: Clause, phrases: list[NounPhrase]) -> list[NounPhrase]:
    """'my car, which is a hatchback, waits', 'a man, who was a courier, stepped out': the noun after the copula
    of a relative is what the relative's noun is, no new agent; the relative's noun stays its subject."""
    units, noun = clause.units, clause.antecedent
    hedge = 2 if len(units) > 2 and units[0].word in ("i", "we") and units[1].word in HEDGES else 0
    # "which I think was a Honda"
    if noun is None or len(units) < hedge + 2 or units[hedge].word not in COPULAS or not phrases or \
            phrases[-1].entity is None or not phrases[-1].introduced or phrases[-1].plural or \
            phrases[-1].first != hedge + 1 or units[phrases[-1].first].word not in ("a", "an") or \
            any(u.category == "actions" for u in units[:phrases[-1].first]):
        return phrases
    said = phrases[-1].entity
    make = said.type == "car" and said.head not in GENERAL_NOUNS and noun.type in V.EGO_TYPES
    if make and not noun.is_ego:  # "a motorbike, which I think was a Honda,": its maker's name
        if said in r.entities:
            r.entities.remove(said)
    elif noun.is_ego:
        if said.type in V.EGO_TYPES and said.type != "car":
            noun.type = said.type
        if said in r.entities:
            r.entities.remove(said)
    elif said.type == noun.type or noun.head.split()[-1] in APPOSED_HEADS | {"car"}:
        _fold(r, noun, said)  # "a vehicle, which was a white van, ..."
    else:
        return phrases
    noun.aliases.add(said.head)
    return [np for np in phrases if np.entity is not said and not (hedge and np.entity is not None and
                                                                   np.entity.is_ego)]


HEDGES = {"think", "thought", "believe", "believed", "guess", "reckon", "suppose"}


LIST_WORDS = {"a", "an", "and", "one", "two", "three", "four", "five", "six"}


def _members_listed(r: _Reader, clause: Clause, phrases: list[NounPhrase], recent: list[Entity]) -> list[NounPhrase]:
    """'three pedestrians (two adults and a child) cross', 'two cars come from the left, a taxi and a van': nouns
    of a counted group's kind set off after it, as many as it counts, name its members; they are no new agents."""
    units = clause.units

    def counted(nps: list[NounPhrase]) -> int:
        return sum(np.entity.count for np in nps)

    def kin(np: NounPhrase, group: Entity) -> bool:
        return np.entity is not None and np.introduced and not np.entity.is_ego and np.entity.type == group.type

    def drop(members: list[NounPhrase]) -> list[NounPhrase]:
        for m in members:
            if m.entity in r.entities:
                r.entities.remove(m.entity)
        r.notes.append(f"read: {', '.join(m.entity.head for m in members)} as the members of the group named "
                       "before them")
        return [np for np in phrases if np not in members]

    listing = [np for np in phrases if np.entity is not None]
    if clause.link == "," and listing and all(kin(np, listing[0].entity) for np in listing) and all(
            u.category in ("agents", "comma", "numbers", "number") or u.category == "word" and (
                u.word in LIST_WORDS or u.word not in lexicon().function_words) for u in units):
        group = next((e for e in reversed(recent) if not e.is_ego and e.count > 1 and e.stage == clause.stage and
                      e.type == listing[0].entity.type), None)  # "..., a taxi and a van": a list with no verb
        if group is not None and counted(listing) == group.count and group not in r.clause_mentions:
            return drop(listing)
    for k, np in enumerate(phrases):
        group = np.entity
        if group is None or not np.introduced or group.is_ego or group.generic or group.count < 2 or \
                np.index + 1 >= len(units) or units[np.index + 1].category != "comma":
            continue
        members, end = [], np.index
        for m in phrases[k + 1:]:
            between = units[end + 1:m.first]
            if not kin(m, group) or not all(u.category == "comma" or u.word == "and" for u in between):
                break
            members.append(m)
            end = m.index
            if counted(members) >= group.count:
                break
        closed = end + 1 == len(units) or units[end + 1].category == "comma"  # "(two adults and a child) cross"
        if members and counted(members) == group.count and closed:
            return drop(members)
    return phrases


def _at_the_wheel_of(units: list[Unit], before: list[NounPhrase], np: NounPhrase) -> bool:
    """'I was driving a bus', 'you're at the wheel of the ambulance', 'the player pulls the bus in', 'I was the
    front-seat passenger in my husband's Honda', 'OP is the one driving the truck': a vehicle the speaking ego
    drives, steers or sits in is the ego's own, no other agent."""
    k = len(before) - 1
    seat = None
    if k >= 1 and before[k].entity is None and (
            "passenger" in units[before[k].index].base.split() or units[before[k].index].base in AT_THE_CONTROLS):
        seat, k = before[k], k - 1  # "the front-seat passenger in ...", "you are the driver of a car": the speaker
    if k < 0 or before[k].entity is None or not before[k].entity.is_ego or \
            before[k].entity.head not in FIRST_PERSON | {"we", "you", "player", "ego", "op", "rp"} or \
            np.entity is None or np.entity.type not in V.EGO_TYPES or np.plural:
        return False
    between = units[before[k].index + 1: np.first]
    if np.first < np.index and units[np.first].word == "of":
        between.append(units[np.first])  # "at the wheel of the ambulance": 'of' was read into the noun phrase
    while len(between) > 1 and between[-1].category == "word" and between[-1].word in PAINT:
        between.pop()  # "RP driving grey Qashqai": a note's noun with no article keeps its colour outside it
    inside_seat = set(range(seat.first, seat.index + 1)) if seat is not None else set()
    wheel = any(u.word == "wheel" for u in between)
    return bool(between) and all(
        units.index(u) in inside_seat or wheel and u.category == "positions" and u.base == "behind" or
        u.category in ("word", "actions") and (u.tokens[-1].word in AT_THE_WHEEL_OF or u.base in AT_THE_WHEEL_OF)
        or u.word == "one" for u in between) and \
        (between[-1].tokens[-1].word in OPERATED_FROM or between[-1].base in OPERATED_FROM)


def _one_vehicle(np: NounPhrase) -> bool:
    """A single vehicle of a type the ego may be, newly named: what may turn out to be the ego's own."""
    e = np.entity
    return e is not None and not e.is_ego and e.type in V.EGO_TYPES and not np.plural and e.count == 1


MEETING_WITH = {"collide", "crash", "clash", "tangle", "meet", "level", "contact", "impact", "up", "along", "alongside",
                "pace", "race", "neck", "merge", "share", "deal", "cope", "struggle", "compete"}
# "collided with the truck", "drew level with the bus", "caught up with the van": another vehicle, met


def _the_speakers_seat(r: _Reader, units: list[Unit], np: NounPhrase) -> bool:
    """'I'm in the artic', 'coming through the village in the tipper', 'me leading in the DAF': in a first-person
    account, the vehicle the speaker is in ('in the', 'in my') is the ego's own, unless it is placed or acts; so is
    the one a speaker works with ('waiting to make my left with the plow'), unless met with ('collided with')."""
    if not _one_vehicle(np) or np.first < 1 or units[np.first].word not in ("the", "my", "our"):
        return False
    if np.first == 1:  # "In the artic pulling left out of the trading estate, and a bloke on a pushbike shoots
        # down my nearside": a sentence opened in the vehicle, doing what the speaker does
        return units[0].word == "in" and np.index + 1 < len(units) and units[np.index + 1].category == "actions" \
            and units[np.index + 1].tokens[0].word.endswith("ing") and any(t.word in FIRST_PERSON for t in r.tokens) \
            and not any(e.is_ego and e.head not in SPEAKING_SELF and not _supplied(r, e) for e in r.entities)
    if not (units[np.first - 1].word == "in" or units[np.first - 1].word == "with" and
            units[np.first - 2].category != "agents" and units[np.first - 2].tokens[-1].base not in MEETING_WITH):
        return False
    if units[np.first - 2].category == "positions" and units[np.first - 2].tokens[-1].word in ("me", "us"):
        return False  # "the eejit behind me in the white van": the van of one the speaker places
    sentence = units[np.first].tokens[0].sentence
    opening = [x for x in units[:np.first] if x.tokens[0].sentence == sentence]
    unsaid = bool(opening) and opening[0].category == "actions" and \
        not any(x.category == "agents" and x.meaning != "none" for x in opening)  # "Sat at the crossroads in the box
    # van waiting to go": a sentence opened by what the speaker was doing, with no subject, says where they sit
    told = unsaid or units[np.first - 2].category != "agents" and any(  # "I was stopped at it in the pickup
        x.category == "agents" and x.meaning == "ego" and x.tokens[0].word in FIRST_PERSON | {"we"} for x in opening)
    # wanting to go straight over": the speaker's own clause, not a noun's ("a guy in the pickup waiting")
    if np.index + 1 < len(units) and units[np.index + 1].category in ("positions", "actions", "agents") and not (
            told and units[np.index + 1].category == "actions" and units[np.index + 1].tokens[0].word.endswith("ing")):
        return False  # "in the van ahead", "in the car that pulled out": another
    if any(x.is_ego and x.head not in SPEAKING_SELF and not _supplied(r, x) for x in r.entities):
        return False
    egos = [u for u in r.units if u.category == "agents" and u.meaning == "ego"]
    if not egos:  # "Rolling up on it now in the Kenworth": no one named, a participle with no subject says where
        # the teller sits ("... up the inside of me": a speaker)
        return unsaid and opening[0].tokens[0].word.endswith("ing") or \
            any(t.word in SPEAKERS - {"you", "your"} for t in r.tokens)
    return any(u.tokens[0].word in SPEAKERS for u in egos)


OWNING = {"own", "owns", "owned", "owning"}


def _owned_by_the_teller(r: _Reader, units: list[Unit], np: NounPhrase) -> bool:
    """'I OWN A 2022 HYUNDAI SANTA FE', 'The contact owns a 2020 Nissan Rogue': the vehicle the teller of a complaint
    opens by owning is the one the complaint is about, the ego's own."""
    if not _one_vehicle(np) or np.first < 1 or units[np.first - 1].word not in OWNING:
        return False
    sentence = units[np.first].tokens[0].sentence
    return not any(e.is_ego and e.head not in FIRST_PERSON | {"ego"} or not e.is_ego and e is not np.entity and
                   e.type in V.EGO_TYPES for e in r.entities) and \
        all(t.sentence == sentence for t in r.tokens[:units[np.first].start] if t.word.isalpha())


def _kept_for_years(units: list[Unit], np: NounPhrase) -> bool:
    """'I'd had the semi eleven years', 'I've driven the bus for years': the vehicle the teller has long had or
    driven is the one they tell of driving, the ego's own."""
    if not _one_vehicle(np) or np.first < 2 or units[np.first].word not in ("the", "my", "our"):
        return False
    k = np.first - 1
    if units[k].base not in ("have", "own", "drive"):
        return False
    while k > 0 and units[k - 1].category == "word" and units[k - 1].word in ("would", "have", "has", "had", "been"):
        k -= 1
    teller = k > 0 and units[k - 1].category == "agents" and units[k - 1].word in ("i", "we")
    k = np.index + 1
    while k < len(units) and (units[k].category == "numbers" or units[k].word in (
            "for", "many", "a", "few", "some", "over", "nearly", "almost", "good")):
        k += 1  # "for years", "eleven years", "for a good few years"
    return teller and k < len(units) and units[k].word in ("years", "year", "months")


ABOARD = {"on", "in", "aboard", "riding", "travelling", "traveling", "sitting", "sat", "driving"}


HANDLING = {"move", "slow", "stop", "pull", "ease", "bring", "swing", "put", "park", "steer", "nose", "edge", "inch",
            "reverse", "back", "turn", "drive", "slide", "take"}  # what a driver does to the vehicle they drive


PEOPLES_PLACES = {"school", "hospital", "playground", "park", "centre", "center", "home", "ward", "nursery", "club",
                  "library", "clinic", "academy", "college", "entrance", "gate", "gates", "section", "zone", "area"}


def _handled_by_the_speaker(r: _Reader, units: list[Unit], first: int) -> bool:
    """'Slowed the truck down', 'I moved the truck over': a one-word verb of handling a vehicle (not driving it),
    opening its sentence or said by 'I' or 'we', in a first-person account."""
    if first < 1 or units[first - 1].tokens[-1].base not in HANDLING - {"drive"} or len(units[first - 1].tokens) != 1:
        return False
    said_by_me = first >= 2 and units[first - 2].category == "agents" and units[first - 2].meaning == "ego" and \
        units[first - 2].word in ("i", "we")
    return (_opens_its_sentence(r.tokens, units[first - 1].tokens[0]) or said_by_me) and \
        any(t.word in ("i", "we", "me", "my") for t in r.tokens)


def _opens_its_sentence(tokens: list[Token], t: Token) -> bool:
    """Whether the token is the first word of its sentence ('Slowed the truck down', 'Filtering past a queue'), with
    no subject before it."""
    return t.index == 0 or tokens[t.index - 1].sentence != t.sentence


def _driven_with_no_subject(r: _Reader, units: list[Unit], np: NounPhrase) -> bool:
    """'Drove the fire engine to a car fire on the ring road', 'First shout driving the fire engine: ...': in a
    first-person account, a vehicle driven by a verb with no subject of its own, or with the speaker as its subject
    ('I drive the 22 bus', 'I moved the truck over', 'I had the truck stopped'), is the speaker's."""
    first = np.first - 2 if np.first >= 2 and units[np.first - 1].category in ("numbers", "number") and \
        units[np.first - 2].word in ("the", "my", "our") else np.first  # "the 22 bus": its route number
    if not _one_vehicle(np) or first < 1 or units[first].word not in ("the", "my", "our", "a", "an"):
        return False
    verb = units[first - 1]
    handled = (verb.tokens[-1].base in HANDLING or verb.tokens[-1].base == "ride" and
               np.entity.type in V.TWO_WHEELER_TYPES) and units[first].word in ("the", "my", "our") and not (
        np.index + 1 < len(units) and units[np.index + 1].category in ("positions", "agents")) or \
        verb.tokens[-1].word in ("had", "have", "got") and units[first].word in ("the", "my", "our") and \
        np.index + 1 < len(units) and (
            units[np.index + 1].category == "actions" and units[np.index + 1].tokens[0].word.endswith(("ed", "ing"))
            or units[np.index + 1].category == "positions" and units[np.index + 1].tokens[0].word == "in" and
            units[np.index + 1].tokens[-1].word == "lane")  # (not "had the truck in front of me")
    # "I moved the truck over a lane", "slowed the truck down", "I had the truck stopped at the yield sign", "Had the
    # plow sitting on a green", "Had the truck in the right lane"
    if not handled and (verb.category != "actions" or verb.tokens[0].base != "drive") or len(verb.tokens) != 1:
        return False
    sentence = verb.tokens[0].sentence
    before = [u for u in units[:first - 1] if u.tokens[0].sentence == sentence]
    if before and before[-1].category == "agents" and before[-1].meaning == "ego" and \
            before[-1].tokens[0].word in ("i", "we") and not any(u.category == "agents" for u in before[:-1]):
        return True  # "I drive the 22 bus": the speaker's own, said with the speaker as the subject
    return not any(u.category == "agents" for u in before) and any(t.word in ("i", "me", "my", "we", "us", "our")
                                                                  for t in r.tokens)


def _the_one_the_speaker_was_on(units: list[Unit], np: NounPhrase) -> bool:
    """'the bus I was on was waiting at the red light', 'the taxi we were in': a vehicle the speaker says they rode
    in, in a relative clause right after it, is the ego's own."""
    if not _one_vehicle(np) or units[np.first].word not in ("the", "this", "that"):
        return False
    after = [u.tokens[0].word for u in units[np.index + 1:np.index + 4]]
    return len(after) == 3 and after[0] in ("i", "we") and after[1] in ("was", "were", "am", "are") and \
        after[2] in ABOARD


def _placed_after(units: list[Unit], i: int) -> bool:
    """'a bus behind', 'a van on the right': a place said right after the noun makes it one of the scene's
    agents, not a name for the one before it."""
    return i + 1 < len(units) and units[i + 1].category == "positions"


def _does_after(units: list[Unit], i: int) -> bool:
    """'ego, a van pulling out from the right', 'ahead of you, a car is slowing to turn': a noun with a verb of its
    own after it (its auxiliaries read past) is another agent."""
    k = i + 1
    while k < len(units) and units[k].category == "word" and units[k].word in ("is", "was", "are", "were", "has",
                                                                                "had", "been", "just", "then"):
        k += 1
    return k < len(units) and units[k].category == "actions"


def _named_make(after: list[Unit], kind: str) -> bool:
    """', a grey Vauxhall Astra' after the ego: a comma, an article, colours and the maker's name, nothing more.
    A bare kind after the comma is another agent of a terse list ('ego van, oncoming truck', 'ego bus, lead car')."""
    words = [u for u in after if u.category != "comma"]
    named = words[:-1] or words[-1:] and words[-1].tokens[-1].base not in KIND_NOUNS
    words = words[1:] if words and words[0].word in ("a", "an") else words  # "my car, (a) grey Vauxhall Astra,"
    return bool(after) and after[0].category == "comma" and bool(named) and all(
        u.word in COLOURS | {"dark", "light", "white", "black", "grey", "gray"} or
        u.category == "agents" and u.meaning == kind for u in words)


def _set_off(tokens: list[Token], units: list[Unit], prev: NounPhrase, np: NounPhrase) -> bool:
    """'the ego car, a beat-up Volvo, crawls', 'the hatchback -- our ego car -- waits': a noun phrase set off
    by commas (dashes and brackets read as commas) right after another says what the first is, unless a list
    goes on after it ('the ego, a van, and a bus')."""
    if prev.index + 2 > np.first or units[prev.index + 1].category != "comma" or \
            units[prev.index + 2].category != "word" and not (
                prev.entity.is_ego and np.first == prev.index + 2 and np.index > np.first and
                units[prev.index + 2].category == "agents"):
        return False  # "ego, oncoming SUV (going straight), pedestrian": a bare noun after a comma is another;
        # but "V1 (Ford Focus) was": a make and model in brackets after the ego is what it is
    if any(u.category not in ("word", "behaviours", "number", "numbers") or u.word in CLAUSE_WORDS | AUXILIARIES
           for u in units[prev.index + 2:np.first]):
        return False
    after = np.index + 1  # the closing comma, then the sentence ends or goes on with no further list item
    while prev.entity.is_ego and after < min(len(units), np.index + 7) and units[after].category not in (
            "comma", "agents", "actions", "sequence") and units[after].word not in CLAUSE_WORDS | AUXILIARIES:
        after += 1  # "our ego, a green hatchback in the right lane, is coming up": where the ego is, said with it
    if after >= len(units) or units[after].category != "comma":
        return False
    k = units[after].start + 1
    if k >= len(tokens) or tokens[k].sentence != tokens[k - 1].sentence:
        return True
    entry = lexicon().phrases.get((tokens[k].base,)) or lexicon().phrases.get((tokens[k].word,))
    return not (tokens[k].word in ("and", "or", "a", "an", "the") or entry is not None and entry[0] == "agents")


LIKENESS_VERBS = {"look", "looks", "looked", "looking", "seem", "seems", "seemed", "seeming", "would", "d", "i",
                  "we", "you", "they", "also", "really", "something", "anything", "vehicle", "vehicles", "one"}


def _a_likeness(units: list[Unit], np: NounPhrase) -> bool:
    """'driving like a taxi driver', 'it sounded like a truck hitting a wall', 'a worse driver than': a vehicle named
    after 'like' that follows what someone does, or before 'than', is a comparison, no agent ('it looked like a
    police car' and 'I'd like a truck parked on the right' name one)."""
    if np.index + 1 < len(units) and units[np.index + 1].word == "than" and units[np.first].word in ("a", "an"):
        return True  # "nothing turns you into a worse driver than an ambulance": a comparison
    if np.first < 2 or units[np.first - 1].word != "like" or units[np.first].word not in ("a", "an"):
        return False
    before = units[np.first - 2]
    return before.word not in LIKENESS_VERBS and before.tokens[-1].word not in LIKENESS_VERBS and (
        before.category in ("actions", "behaviours", "positions") or before.tokens[-1].word.endswith(("ed", "ing")))
    # ("moved over into the right lane like a functioning adult")


def _fold(r: _Reader, into: Entity, other: Entity) -> None:
    """Two noun phrases that name one agent ("a learner driver in a hatchback", "the vehicle behind me, a
    white Ford Transit,"): the first takes the second's type and what was said of it, and the second goes."""
    into.type = other.type
    into.aliases |= other.aliases | {other.head}  # "this guy in a white Silverado ... Silverado swerves": him
    into.features |= other.features
    into.actions += other.actions
    into.behavior = into.behavior or other.behavior
    if other in r.entities:
        r.entities.remove(other)


def _shared_premodifier(units: list[Unit], phrases: list[NounPhrase]) -> None:
    """'2 oncoming cars + 1 scooter': a counted list shares the first item's oncoming when the others say
    nothing of where they are."""
    for p, q in zip(phrases, phrases[1:]):
        if not (p.introduced and q.introduced and p.entity is not None and q.entity is not None) or \
                p.entity.is_ego or q.entity.is_ego:
            continue
        oncoming = any(u.category == "positions" and u.meaning == "road_straight" and len(u.tokens) == 1
                       for u in units[p.first:p.index])
        joined = all(u.category == "comma" or u.word == "and" for u in units[p.index + 1:q.first]) and \
            q.first > p.index + 1
        unplaced = not any(u.category == "positions" for u in units[q.first:q.index + 2]) and not q.entity.features
        if oncoming and joined and unplaced and units[q.first].category == "number":
            q.entity.features.add("road_straight")


PLACES_BEFORE_A_NOUN = {"behind", "ahead", "of", "to", "beside", "with", "alongside", "adjacent", "abreast", "abeam",
                        "parallel", "trailing", "tailgating", "preceding", "leading", "lead", "following", "past", "by"}


def _is_reference(units: list[Unit], np: NounPhrase) -> bool:
    """A noun after 'in front of', 'behind', 'by', 'including': it places another noun, it is not a subject."""
    k = np.first - 1
    if k < 0:
        return False
    u = units[k]
    if u.category == "positions" and units[np.first].word in ("it", "him", "her", "them"):
        return True  # "a motorbike in the right lane, slightly ahead of it, cuts in": whom the place is by
    if u.category == "positions" and u.meaning in ("ahead", "behind", "level", "side_left", "side_right",
                                                    "front_left", "front_right", "back_left", "back_right"):
        # "behind the ego a delivery van keeps its distance": the place is complete, the van is the subject
        if u.meaning in ("ahead", "behind") and len(u.tokens) == 1 and k > 0 and (
                units[k - 1].word in DISTANCE_UNITS or units[k - 1].word in ("up", "further", "way", "just")):
            return False  # "twenty-five metres ahead a lorry sits", "up ahead a bus": a place, then the subject
        opening = all(x.category == "comma" or x.word in ("and", "but", "so", "then") for x in units[:k])
        if opening and [t.word for t in u.tokens] in (["ahead"], ["in", "front"], ["up", "ahead"], ["just", "ahead"],
                                                      ["further", "ahead"], ["straight", "ahead"]):
            return False  # "Ahead a car stands broken", "..., and up ahead a semi is stopped": the place the clause
            # opens with, then its subject
        if u.meaning not in ("ahead", "behind", "level") and u.tokens[-1].word not in ("of", "to", "behind") and \
                units[np.first].word not in ("of", "to"):
            return False  # "on the left-hand side a woman waits": a place, then the subject ("left of a van" places)
        return u.tokens[-1].word in PLACES_BEFORE_A_NOUN or units[np.first].word in ("of", "to")
        # "in my mirror a police car": a place that ends in its own noun is complete, the noun after it the subject
    if u.word == "and" and _between_one_and(units[:k]):
        return True  # "the car between the ego and the bus brakes": the bus places the car too
    return u.category == "word" and u.word in ("of", "than", "including", "past", "beside", "behind", "to", "by",
                                               "towards", "toward", "for", "with", "besides", "from", "near",
                                               "between")


def _placed_by_the_same_pronoun(r: _Reader, u: Unit) -> bool:
    """'an ambulance came up behind him in the outside lane and he moved across': in an account told of 'he', the
    one a vehicle was just placed by ('behind him') is the one 'he' names again: the ego, not that vehicle."""
    objects = {"he": "him", "she": "her"}
    if u.word not in objects or any(t.word in FIRST_PERSON | {"we", "us", "ego"} for t in r.tokens):
        return False
    sentence = u.tokens[0].sentence
    return any(x.category == "positions" and (x.tokens[-1].word == objects[u.word] or y.word == objects[u.word]) and
               y.start < u.start and sentence - 1 <= x.tokens[0].sentence <= sentence
               for x, y in zip(r.units, r.units[1:]))  # (or in the sentence before: "A cyclist is in the lane to her
    # left, level with her. Watch - she turns right")


PLACES_NEXT = {"lane", "lanes", "junction", "intersection", "exit", "road", "street", "crossing", "crosswalk"}


def _next_names_which(u: Unit, prev_word: str, nxt: Unit | None) -> bool:
    """'into the next lane', 'one van from next lane': which lane, not what comes next."""
    return u.word == "next" and len(u.tokens) == 1 and (prev_word in ("the", "a", "this", "that", "its") or
                                                        nxt is not None and nxt.tokens[0].word in PLACES_NEXT)


def _what_a_label_names(units: list[Unit], first: int) -> bool:
    """'Actor 2: oncoming car turns left': the bare noun after a label and its colon says what the label is, one
    more road user, not the car named before."""
    k = first - 1
    while k >= 0 and units[k].category == "positions":
        k -= 1
    return k >= 1 and units[k].word in COPULAS and units[k - 1].category == "agents" and \
        bool(units[k - 1].tokens[-1].label)


def _pronoun(units, i, phrases, previous_subject, recent) -> Entity | None:
    """'it' as a subject is the last subject; as an object ('in front of it') the last thing named that is
    not the subject, usually the ego. 'she', 'him' name people."""
    opening = phrases[0] if phrases else None
    between = units[opening.index + 1:i] if opening is not None else []
    if units[i].word in ("he", "she", "they") and opening is not None and opening.entity is not None and \
            (opening.first == 0 or units[opening.first - 1].category == "comma" or
             units[opening.first - 1].word in ("and", "but", "so", "then")) and \
            all(u.category == "positions" or u.word in ("from", "the", "of", "on", "in", "at", "side", "opposite")
                for u in between) and i + 1 < len(units) and (units[i + 1].category == "actions" or (
                units[i + 1].word in AUXILIARIES and i + 2 < len(units) and units[i + 2].category == "actions")) and \
            all(p.entity is opening.entity for p in phrases if p.entity is not None):
        return opening.entity  # "the bus from the opposite side he stop for me", "the ego he go straight": the
        # subject said again, as some speakers do
    if units[i].word in ("she", "her", "he", "him"):
        drives = _a_drivers_verb_after(units, i)  # "a pedestrian ran out in front of her; she swerved"
        recent = [e for e in recent if e.count <= 1]  # "waited for two older ladies to cross ... then he went": one
        people = [e for e in recent if e.type in V.VULNERABLE_TYPES and not (drives and e.type == "pedestrian")]
        if drives and not people and any(e.type == "pedestrian" for e in recent):
            return next((e for e in reversed(recent) if e.type != "pedestrian"), None)
        told_in_person = any(e.is_ego for e in recent) and all(
            e.head in FIRST_PERSON | {"we", "us", "our", "you", "ego"} for e in recent if e.is_ego)
        drivers = [e for e in recent if not e.is_ego] if units[i].word in ("he", "she") or \
            units[i].word == "him" and i > 0 and units[i - 1].category == "positions" and told_in_person else []
        # "a coach started indicating ... so he could merge": the driver of the last vehicle; so is 'him' after a
        # place in a text told by 'I' ("a Prius blows through ... a van right behind him"), while in one told of
        # 'he' ("customer states he was ... a car just behind him") 'him' is the ego
        return people[-1] if people else drivers[-1] if drivers else None
    as_object = i > 0 and (units[i - 1].category in ("positions", "actions") or
                           (units[i - 1].category == "word" and units[i - 1].word in ("of", "to", "past", "behind"))
                           or units[i - 1].word in CAUSATIVES and i + 1 < len(units) and units[i + 1].word == "to"
                           or units[i - 1].word in LETTING and i + 1 < len(units) and
                           units[i + 1].category == "actions")
    # "forcing it to stop": whom it forced; "eased off and let it merge": whom it let
    named_here = [np.entity for np in phrases if np.index < i and np.entity is not None and not np.entity.is_ego
                  and np.entity.type not in V.VULNERABLE_TYPES]
    if units[i].word == "it" and not as_object and named_here and phrases[0].entity is named_here[0] and \
            named_here[0].count == 1:
        return named_here[0]  # "a van in the left lane decides it wants our lane": the clause's own subject
    naming = i + 2 < len(units) and units[i + 1].word in COPULAS and units[i + 2].word in ("a", "an", "the", "one")
    if units[i].word == "it" and not as_object and not naming and previous_subject and all(
            e.is_ego and e.head in SPEAKERS for e in previous_subject):  # ("it's a little intersection": a place)
        vehicles = [e for e in recent if not e.is_ego and e.type not in V.VULNERABLE_TYPES]
        if vehicles:  # "When I saw the lights. It was coming up behind me": the narrator is never 'it'
            return vehicles[-1]
    if units[i].word == "it" and not as_object and _a_group(previous_subject):  # "a couple of cars coming the other way so it has to
        # wait": 'it' is no group; the one thing named before them
        single = [e for e in recent if e not in previous_subject and e.type not in V.VULNERABLE_TYPES]
        return single[-1] if single else next((e for e in recent if e.is_ego), None)
    if units[i].word == "it" and not as_object:  # "a cyclist undertook the AV as it was turning": the AV
        things = [e for e in previous_subject if e.type not in V.VULNERABLE_TYPES and not (
            e.is_ego and e.head in SPEAKERS)]  # ("I'm reporting a white van. It overtook me": never the narrator)
        if things:
            return things[0]  # "a crowd streamed across the crosswalk it needed, and it waited": not the crowd
        if previous_subject:
            vehicles = [e for e in recent if e.type not in V.VULNERABLE_TYPES]
            return vehicles[-1] if vehicles else None  # ("a crowd streams across, and it waits": no one on foot is
            # 'it'; the ego, unnamed so far)
    if not as_object:
        if previous_subject:
            return previous_subject[0]
        return recent[-1] if recent else None
    owner = [np.entity for np in phrases if np.index < i and np.entity is not None]  # whom "behind it" places
    subject = owner[-1] if owner else (previous_subject or [None])[0]
    if not owner and any(np.index > i and np.introduced for np in phrases):
        subject = None  # "a PKW comes, and directly behind it a second PKW": the place first, then whom it places
    if len(previous_subject) == 1 and previous_subject[0].is_ego and previous_subject[0] is not subject and \
            not any(np.index < i and np.entity is not None and not np.entity.is_ego and np.entity is not subject
                    for np in phrases):
        return previous_subject[0]  # "the ego is tailgated by a truck, and the car in front of it stops"
    named_as = [np.entity for np in phrases if np.index < i and np.entity is not None and np.entity is not subject
                and np.index + 2 < len(units) and units[np.index + 1].word in COPULAS and units[np.index + 1].category
                == "word" and units[np.index + 2].word in ("a", "an")]  # "Actor 2 is a box truck right behind it":
    # the truck is Actor 2, 'it' another
    for e in reversed(recent + owner[:-1]):
        if e is not subject and not any(e is x for x in named_as):
            return e
    return None


SPEAKERS = {"i", "me", "we", "us", "you", "my", "our", "your"}
DRIVERS_VERBS = {"swerve", "brake", "steer", "skid", "accelerate", "indicate", "overtake", "stall", "slam", "stamp",
                 "reverse", "floor", "hit the brakes"}  # what only one at a wheel or on a saddle does


def _a_drivers_verb_after(units: list[Unit], i: int) -> bool:
    """'she swerved', 'he braked': the pronoun is someone at a wheel or on a saddle, no one on foot."""
    return units[i].word in ("she", "he") and i + 1 < len(units) and units[i + 1].category == "actions" and \
        units[i + 1].tokens[0].base in DRIVERS_VERBS


def _a_group(subject: list[Entity]) -> bool:
    """The subject is a group ('two trucks', 'a car and a car'), whom a later 'it' cannot name."""
    subjects = list({id(e): e for e in subject}.values())  # a subject may be listed twice
    return bool(subjects) and not any(e.is_ego for e in subjects) and sum(e.count or 1 for e in subjects) > 1 and \
        len({e.type for e in subjects}) == 1


def _pronoun_in_place(units, i, phrases, recent, owners) -> Entity | None:
    """'it' inside a place phrase ('a biker behind it'): the last agent named before, not the one placed; when
    that is the ego ('the ego waits; two cars behind it'), the place is the ego's, as every place is."""
    for k in range(i - 2, -1, -1):  # "two cars, one ahead of the ego and one behind it": the ego, said last
        if units[k].category == "agents" and units[k].meaning not in ("none", "ego"):
            break
        if units[k].category == "positions" and any(t.word == "ego" for t in units[k].tokens):
            return None
    before = [np.entity for np in phrases if np.index < i and np.entity is not None]
    for e in reversed(recent + before):
        if e in owners or e.is_ego and (_EGO_SPEAKS.get() or units[i].tokens[0].word == "from"):
            continue  # an ego the text calls "I" or "we" is never "it"; one steps out from behind what stands,
            # not from behind the ego ("a truck parked to the right of the ego, and a child steps out from behind
            # it")
        return None if e.is_ego else e
    return None


STANDING_WORDS = {"stopped", "stationary", "parked", "waiting", "queued", "queuing", "queueing", "idling", "held",
                  "stuck", "standing"}  # (not "sat", "sitting": "with the ego sitting in lane two" is where it is)


def _participle_owner(units, i, phrases, subject, verbs) -> NounPhrase | None:
    """A verb right after a noun, with a finite verb after it, modifies that noun: 'a cyclist riding alongside
    swerves', 'in front of a truck stopped on the shoulder'."""
    k = i - 1
    light = False  # "other cars performing lane changes": the noun's doing, not the sentence's
    while k >= 0 and (units[k].category in ("behaviours", "positions") or (
            units[k].category == "word" and units[k].word in ("that", "which", "who", "performing", "making",
                                                               "doing", "executing", "attempting", "already",
                                                               "still", "also", "currently", "slowly", "now"))):
        light = light or units[k].word in ("performing", "making", "doing", "executing", "attempting")
        k -= 1
    if k >= 3 and units[k].category == "comma" and units[k - 1].base in ROLE_NAMES and \
            units[k - 2].category == "comma":
        k -= 3  # "a principal other vehicle (POV) stationary in its lane": past the bracketed role
    elif k >= 3 and units[k].category == "comma" and units[k - 1].category == "agents":
        opening = next((j for j in range(k - 2, max(0, k - 5), -1) if units[j].category == "comma"), None)
        outer = next((p for p in phrases if opening is not None and p.index == opening - 1), None)
        if outer is not None and outer.entity is not None and outer.first > 0 and \
                units[outer.first - 1].word == "with":
            k = outer.index  # "with V2 (Vauxhall Astra) stationary in front of it": past the bracketed make
    worn = next((j for j in range(k - 1, max(0, k - 6), -1) if units[j].word == "in" and
                 units[j + 1].word in ("a", "an", "his", "her", "their", "dark", "black", "white") and
                 all(x.category in ("word", "numbers", "behaviours") for x in units[j + 1:k + 1])), None)
    where = next((j for j in range(k, max(0, k - 5), -1) if units[j].word in ("in", "on", "along") and
                  units[j].category == "word"), None)
    given = None if where is None else where - 1 - (units[where - 1].word in ("already", "still", "also"))
    if where is not None and where < k and units[i].tokens[0].word.endswith("ing") and all(
            x.category in ("word", "numbers") or x.meaning == "none" for x in units[where + 1:k + 1]) and any(
            p.index == given and p.entity is not None and p.first > 0 and units[p.first - 1].word == "with"
            for p in phrases):
        k = given  # "with a cyclist (already) in the single lane coming towards him": past where the one given it is
    if worn is not None and worn >= 1 and units[k].category == "word" and units[i].tokens[0].word.endswith("ing") and \
            any(p.index == worn - 1 and p.entity is not None and p.entity.type == "pedestrian" for p in phrases):
        k = worn - 1  # "this guy in a three-piece suit standing on the sidewalk": past what he wears
    if k < 0:
        return None
    np = next((p for p in phrases if p.index == k), None)
    if np is not None and np.entity is not None and np.entity.is_ego and np.first > 1 and \
            units[np.first - 1].category == "positions":
        placed = next((p for p in phrases if p.index == np.first - 2), None)
        if placed is not None and placed.entity is not None and not placed.entity.is_ego and \
                units[i].tokens[0].word.endswith("ing"):
            np = placed  # "with a taxi in front of the ego braking hard": the taxi brakes; the ego only places it
    if np is None or units[k].word in ("me", "us", "you", "him", "her", "them", "it", "i", "we", "he", "she", "they"):
        return None  # "a learner in front of me stalled": a pronoun takes no participle; the verb is finite
    aux = units[i - 1].category == "word" and units[i - 1].word in AUXILIARIES
    later = any(v > i and not (units[v - 1].category == "word" and units[v - 1].word == "to") for v in verbs)
    word = units[i].tokens[0].word  # a later finite verb makes this one a participle; 'to pass' is none
    participle = word.endswith("ing") or word.endswith("ed") or word in (
        "parked", "stopped", "stood", "stuck", "broken", "stationary", "idle", "motionless", "immobile") or light or \
        units[i].tokens[-1].word in ("parked", "stopped")  # "finds a van double-parked ahead"
    # "encounters a POV stationary in its lane": a state said of the object
    with_it = np.first > 0 and units[np.first - 1].word == "with" and i == k + 1 and word in STANDING_WORDS
    # "two cars wait at the light with the ego stopped behind them": the ego's own state
    if np.entity is not None and np.entity.is_ego and not light and not with_it and not (
            i == k + 1 and word.endswith("ing") and later and np is phrases[0] and np.first == 0):
        return None  # "the lead car ahead of the hero changed lane": the ego takes no participle, unless it opens
        # the clause with it ("a robotaxi travelling behind the truck stopped": the robotaxi stopped)
    if np.entity is not None and not aux and participle and (later or (np.entity not in subject)):
        return np
    return None


def _modifier_owner(units, i, phrases, subject, main_verbs, participles=None) -> list[Entity]:
    before = [p for p in phrases if p.index < i and p.entity is not None]
    while len(before) > 1 and not before[-1].introduced and \
            units[before[-1].index].word in ("it", "him", "her", "them") and \
            units[before[-1].index - 1].category == "positions" and before[-2].introduced and (
                "lane" in {t.word for t in units[i].tokens} or
                any(x.category == "comma" for x in units[before[-1].index + 1:i])):
        before.pop()  # "with a truck alongside it in the right lane": the truck's lane, not its; "a pickup across
        # from it, on the opposite road,": the pickup's road
    main_verbs = [v for v in main_verbs if not _queue_as_a_noun(units, v)]  # "two cars waiting in the queue
    # behind it": the place of those waiting, not of the one the clause began with
    last_verb = max([v for v in main_verbs if v < i] + [v for v in (participles or {}) if v < i], default=None)
    if last_verb is not None and participles and last_verb in participles:
        return participles[last_verb]  # "a van stopped beside it in the right lane": the van's
    verb_before = [v for v in main_verbs if v < i]
    if not verb_before:
        if before:
            last = before[-1]
            copula = any(u.category == "word" and u.word in ("is", "are", "was", "were", "be")
                         for u in units[last.index + 1:i])
            if last.entity in subject and copula:
                said = [e for e in subject if any(p.entity is e or any(e is g for g in p.group) for p in before)]
                return said or subject  # "both the truck and the pedestrian are in the front right" (not "two cars
                # are coming from the left and a motorcycle from the right": the motorcycle's is its own)
            placed_by = last.first - 1 - (last.first > 1 and units[last.first - 1].word == "of")
            if last.entity.is_ego and subject and last.entity not in subject and placed_by >= 0 and \
                    units[placed_by].category == "positions":
                return subject  # "a bicyclist is coming up behind you on your right", "a car just ahead of me in
                # the left lane": the bicyclist's side, the car's lane
            return last.group or [last.entity]
        return subject
    last_verb = verb_before[-1]
    objects_between = [p for p in before if p.index > last_verb]
    if objects_between:
        last = objects_between[-1]
        if last.introduced and not last.entity.is_ego:
            return [last.entity]
        if last.entity.is_ego and last.first > 0 and units[last.first - 1].word == "with" and \
                not any(x.category == "agents" for x in units[last.index + 1:i]):
            return [last.entity]  # "two cars wait at the light with the ego stopped behind them": the ego's place
    made = next((p for p in before if p.index == last_verb - 2), None)
    if made is not None and units[last_verb - 1].word == "to" and made.first > 0 and \
            units[made.first - 1].word in CAUSATIVES:
        return made.group or [made.entity]  # "a van double-parked on the right forces the ego to pass it in the
        # oncoming lane": the lane is where the one made to pass goes
    return subject


def _queue_as_a_noun(units, v) -> bool:
    """'in the queue', 'in a jam': a stop said by the place one stands in, no verb of its own."""
    return units[v].tokens[0].base in QUEUE_NOUNS and v > 0 and units[v - 1].word in DEFINITE | INDEFINITE


SWERVE_ADVERBS = {"right", "left", "across", "over", "out", "in", "sharply", "suddenly", "just", "straight"}


def _swerves_in_front(units, i) -> bool:
    """'swerves right in front of me', 'pulls across in front of us': 'in front of' the ego right after a
    sideways verb is the lane the mover ends in (as in 'cuts in front of'), not a place it started from."""
    u = units[i]
    if "front" not in {t.word for t in u.tokens}:
        return False
    j = i - 1
    while j >= 0 and (units[j].category == "word" and units[j].word in SWERVE_ADVERBS or
                      units[j].category == "behaviours" and len(units[j].tokens) == 1 or
                      [t.word for t in units[j].tokens] == ["straight"] or
                      units[j].category == "positions" and units[j].meaning in ("ego_lane", "into_ego_lane") or
                      units[j].category == "comma" and j + 1 < i and units[j + 1].word == "just" or
                      j == i - 1 and [t.word for t in u.tokens] == ["front"] and units[j].word in ("the", "my", "our")):
        j -= 1  # "pulled sharply across in front of us", "cuts straight in front of me": a manner adverb between
        # the verb and its path; "moves into your lane, just in front of you": the lane it ends in, said first;
        # "cuts across the front of my car", "across my front": the ego's front, where the cut ends
    verb = units[j] if j >= 0 else None
    if verb is None or verb.category != "actions" or not (
            verb.meaning in ("cut_in", "lane_change") or
            verb.tokens[0].base in STEERING | {"swing", "dart", "cut", "enter", "squeeze", "dive", "nip", "push"}
            or verb.meaning in ("move", "stop", "block") and _from_a_side_lane(units, j)):
        return False  # (any verb of one said in the lane beside: "from the left lane goes in front of us")
    if u.tokens[-1].word in ("me", "us", "you", "ego"):
        return True  # "in front of me"
    nxt = units[i + 1] if i + 1 < len(units) else None
    if nxt is not None and nxt.word == "of" and [t.word for t in u.tokens] == ["front"]:
        nxt = units[i + 2] if i + 2 < len(units) else None  # "the front of my car", "the front of the cab"
    if nxt is not None and nxt.word == "the" and i + 2 < len(units) and units[i + 2].category == "agents" and \
            units[i + 2].meaning == "ego":
        nxt = units[i + 2]  # "cuts in right in front of the ego vehicle"
    return nxt is None or nxt.category == "agents" and nxt.meaning == "ego" or nxt.category == "comma" or \
        nxt.word in ("my", "our")  # "dives in right in front of my bumper"


def _from_a_side_lane(units, j) -> bool:
    """Whether the clause before unit j names a lane beside the ego ('from the left lane', 'in the lane to my
    left') as where the mover is."""
    for u in reversed(units[:j]):
        if u.category in ("comma", "sequence") or u.category == "word" and u.word in CLAUSE_WORDS - {"and"}:
            return False
        if u.category == "positions" and u.meaning in ("side_left", "side_right") and \
                any(t.word in ("lane", "lanes") for t in u.tokens):
            return True
    return False


def _turns_in_front(units, i) -> bool:
    """'a pickup on my left turns right in front of me': 'in front of' the ego right after the turn of one on the
    ego's side is the path it turns across, coming out of the side road; not the lane ahead."""
    j = i - 1
    while j >= 0 and (units[j].category == "word" and units[j].word in SWERVE_ADVERBS or
                      units[j].category == "positions" and [t.word for t in units[j].tokens] in (["left"], ["right"])):
        j -= 1
    ego_after = i + 1 < len(units) and units[i + 1].category == "agents" and units[i + 1].meaning == "ego"
    return j >= 0 and units[j].category == "actions" and units[j].meaning in ("turn_left", "turn_right", "turn") \
        and (units[i].tokens[-1].word in ("me", "us", "you", "ego") or ego_after)


LET_PARTICLES = {"in", "through", "past", "by", "out", "go", "merge", "pass"}


def _let_in_place(units, i, phrases, recent) -> list[Entity]:
    """'we let it in ahead', 'let the van through in front': the place is where the let one ends up."""
    j = i - 1
    while j >= 0 and units[j].word in LET_PARTICLES:
        j -= 1
    if j == i - 1 or j < 1 or units[i].category != "positions" or units[i].meaning not in ("ahead", "behind"):
        return []
    if units[j].word in ("it", "them", "him", "her") and units[j - 1].word in LETTING:
        e = next((x for x in reversed(recent) if not x.is_ego), None)
        return [e] if e is not None else []
    np = next((p for p in phrases if p.index == j and p.entity is not None and not p.entity.is_ego), None)
    if np is not None and np.first > 0 and units[np.first - 1].word in LETTING:
        return np.group or [np.entity]
    return []


def _reference_after(units, i, phrases) -> Entity | None:
    np = next((p for p in phrases if p.first in (i + 1, i + 2) or p.index == i + 1), None)
    if np is None or units[np.first].word in ("both", "all", "each"):
        return None  # ("POV1 from the left lane ahead and POV2 from the right lane ahead both merge": those said)
    between = units[i + 1: np.first] + units[np.first:np.index]
    if all((u.category == "word" and (u.word in ("of", "the", "a", "an", "to", "that", "this")
                                      or u.word not in lexicon().function_words))
           or u.category in ("actions", "behaviours", "numbers") for u in between) and \
            not any(u.category == "actions" and u.meaning == "try" for u in units[i + 1:np.first]):
        return np.entity  # "from behind a parked bus" (not "into the nearside lane to let it through": the one let)
    return None


AFTERMATH_WORDS = {"info", "information", "details", "insurance", "witness", "statement", "exchange", "exchanged",
                   "apologise", "apologised", "apologize", "apologized", "apology"}


def _to_settle_up(tokens: list[Token], u: Unit) -> bool:
    """'did stop and gave me her info as a witness', 'pulled over to exchange details': a stop after the
    collision, to settle up, said in the same sentence; the scene ends before it."""
    sentence = u.tokens[-1].sentence
    after = [t.word for t in tokens[u.tokens[-1].index + 1:] if t.sentence == sentence][:10]
    return bool(AFTERMATH_WORDS & set(after))


GETTING_OUT = {"climb", "get", "step", "jump", "hop", "clamber"}


def _vehicle_got_out_of(units, phrases, recent, person) -> Entity | None:
    """'A man climbed down from the cab', 'the driver got out of the van': the person starts where that vehicle
    stands (the cab is the last vehicle named's)."""
    for k, u in enumerate(units):
        words = [t.word for t in u.tokens]
        if u.category == "agents" and u.meaning == "none" and "cab" in words and set(words) & {"from", "of"}:
            return next((e for e in reversed(recent) if not e.is_ego and e.type not in V.VULNERABLE_TYPES), None)
        if u.category == "word" and u.word in ("from", "of") and k > 0 and any(
                x.tokens[0].base in GETTING_OUT for x in units[max(0, k - 3):k]):
            np = next((p for p in phrases if p.first > k and p.first - k <= 2), None)
            if np is not None and np.entity is not None and np.entity is not person and not np.entity.is_ego and \
                    np.entity.type not in V.VULNERABLE_TYPES:
                return np.entity
    return None


def _the_one_at_the_stop(units: list[Unit], recent: list[Entity]) -> Entity | None:
    """'a bus pulled in at a stop ahead ... two people waiting by the stop': the stop named again is where the
    vehicle last seen standing stands."""
    for a, b in zip(units, units[1:]):
        if a.word in ("the", "that") and [t.word for t in b.tokens][-2:] in (["stop"], ["bus", "stop"]):
            return next((e for e in reversed(recent) if not e.is_ego and e.type not in V.VULNERABLE_TYPES and
                         any(x[4] == "stop" for x in e.actions)), None)
    return None


def _placed_by_the_egos_relative(clause: Clause, subject: list[Entity]) -> None:
    """'the lorry (that) I was stuck behind', 'the car we were following': a relative whose subject is the ego and
    whose place or verb has no object of its own places its noun (ahead of the ego, which follows it)."""
    noun = clause.antecedent
    if clause.link not in RELATIVES or noun is None or noun.is_ego or len(subject) != 1 or not subject[0].is_ego or \
            not clause.units:
        return
    last = clause.units[-1]
    if last.category == "positions" and [t.word for t in last.tokens] == ["behind"] or \
            last.category == "actions" and last.tokens[0].base in FOLLOWING and len(last.tokens) == 1:
        noun.features |= {"ahead", "followed"}
    elif last.category == "positions" and [t.word for t in last.tokens] in (["ahead", "of"], ["in", "front", "of"]):
        noun.features.add("behind")  # "the van I was in front of"


def _relational(verb: Unit, units, i, subject: list[Entity], phrases) -> None:
    """Places implied by verbs between an agent and the ego: following, leading, overtaking, hiding."""
    base = verb.tokens[0].base
    if verb.tokens[-1].word == "of" and {t.word for t in verb.tokens} & {"back", "rear"}:
        base = "rear end"  # "a van ran into the back of me": it came from behind
    if i + 1 < len(units) and units[i + 1].word in ("around", "round", "past") and base in STEERING | {"get"}:
        base = "around"  # "went around it", "got past the bus": what the mover passed is ahead of it
    obj = next((p for p in phrases if p.entity is not None and p.first - i <= 2), None)
    if base in HIDING and obj is not None:
        hidden_one = verb.tokens[0].word.endswith(("en", "ed"))  # "a child hidden behind a van": the child
        for t in obj.group or [obj.entity]:
            if not t.is_ego and subject and not subject[0].is_ego:
                if hidden_one:
                    subject[0].relative_to = subject[0].relative_to or t
                else:
                    t.relative_to = subject[0]  # "a parked van hides a pedestrian": the pedestrian is at the van
        return
    if obj is None or obj.entity is None:
        if base in OVERTAKING and base == "overtake":
            for e in subject:
                if not e.is_ego:
                    e.features.add("overtaking")
        return
    targets = obj.group or [obj.entity]
    for e in subject:
        for t in targets:
            if t.is_ego and not e.is_ego:
                if base in FOLLOWING:
                    e.features.add("behind")
                elif base in LEADING:
                    e.features.add("ahead")
                elif base in OVERTAKING and verb.meaning != "cut_in":  # "squeezed in between us and them":
                    e.features.add("overtaking")  # into the gap ahead of us, from beside; not past us from behind
            elif e.is_ego and not t.is_ego:
                if base in FOLLOWING or base in OVERTAKING:
                    t.features.add("ahead")
                if base in FOLLOWING:
                    t.features.add("followed")  # the ego follows it: in the ego's lane, whichever lane that is
                elif base in LEADING:
                    t.features.add("behind")
            elif not e.is_ego and not t.is_ego and e is not t and e.relative_to is None and \
                    (base in FOLLOWING or base in LEADING):  # "a bus drives along; a car follows it": where the
                e.relative_to, e.relative_how = t, "follows" if base in FOLLOWING else "leads"  # bus is, behind it


QUANTITY_UNITS = {"kmh": "speed", "mph": "speed", "m": "distance", "meters": "distance", "meter": "distance",
                  "metres": "distance", "s": "time", "seconds": "time", "second": "time", "sec": "time",
                  "secs": "time"}


SIZE_WORDS = {"long", "wide", "high", "tall", "across", "deep"}


def _numbers(r: _Reader, units: list[Unit], subject: list[Entity]) -> None:
    """Triggers, speeds and gaps said in numbers: 'within 15 m', 'after 2 seconds', 'at 50 km/h', '10 m ahead'. Of
    two speeds in one clause the subject's is the first ('a lorry moving at 15 m/s catches up with a cyclist
    travelling at 6 m/s')."""
    timed: list[Entity] = []
    for k, u in enumerate(units):
        if u.category != "number" or not subject:
            continue
        value = read_number(u.word)
        if value is None:
            continue
        prev = units[k - 1] if k else None
        nxt = units[k + 1] if k + 1 < len(units) else None
        unit_word = nxt.tokens[0].word if nxt is not None else ""
        if value >= TOO_LARGE:
            if unit_word in QUANTITY_UNITS:
                r.notes.append(f"left out: a {QUANTITY_UNITS[unit_word]} of a number too large to read")
                r.mark(u), r.mark(nxt)
            continue
        targets = [e for e in subject if not e.is_ego] or subject
        if prev is not None and prev.word == "within" and unit_word in ("m", "meters", "meter", "metres"):
            low, high = V.TRIGGER_DISTANCE_RANGE_M
            if low <= value <= high:
                for e in targets:
                    e.trigger = Trigger(within_m=value)
            else:
                r.notes.append(f"left out: a trigger distance of {value:g} m is outside {low:g}..{high:g} m")
            r.mark(u), r.mark(prev), r.mark(nxt)
        elif prev is not None and prev.word == "after" and unit_word in ("s", "seconds", "second", "sec", "secs"):
            if value <= V.TRIGGER_TIME_RANGE_S[1]:
                for e in targets:
                    e.trigger = Trigger(after_s=value)
            else:
                r.notes.append(f"left out: a trigger time of {value:g} s is above {V.TRIGGER_TIME_RANGE_S[1]:g} s")
            r.mark(u), r.mark(prev), r.mark(nxt)
        elif unit_word in ("kmh", "mph") and not any(t.word in LIMIT_WORDS for t in r.tokens[max(0, u.start - 4):
                                                                                            u.start + 5]) and \
                not _speed_of_a_road(r.tokens, u.start, u.end - 1):
            speed = Speed(value=value, unit="km/h" if unit_word == "kmh" else "mph")
            if speed.mps <= V.SPEED_RANGE_MPS[1]:
                for e in subject:
                    if not any(e is x for x in timed):
                        e.speed = speed
                        timed.append(e)
            else:
                r.notes.append(f"left out: a speed of {u.word} {unit_word} is above what the language allows")
            r.mark(u), r.mark(nxt)
        elif unit_word in ("m", "meters", "meter", "metres") and k + 2 < len(units) and \
                units[k + 2].tokens[0].word in SIZE_WORDS:
            r.mark(u), r.mark(nxt)  # "the lorry is 18 m long", "the road is 7 m wide": a size, no gap
        elif unit_word in ("m", "meters", "meter", "metres") and V.GAP_RANGE_M[0] <= value <= V.GAP_RANGE_M[1]:
            for e in targets:
                if not e.is_ego:
                    e.gap_m = value
            r.mark(u), r.mark(nxt)


# -- composing the scene ------------------------------------------------------------------------------------

ABRUPT_STOP_WORDS = frozenset({"dead", "short", "suddenly", "emergency", "slam", "slams", "slammed", "jam",
                               "jams", "jammed", "stamp", "stamps", "stamped", "anchors"})

def _action(e: Entity, stage: int | None = None) -> tuple[str | None, str | None]:
    """(action class, direction) of the strongest, most specific predicate (of one stage, if given)."""
    chosen = [a for a in e.actions if (stage is None or a[0] == stage) and a[2] > 0 and not (
        e.is_ego and a[4] in ("block", "cross", "walk"))]
    if not chosen:
        return None, None
    best = max(chosen, key=lambda a: (a[1], a[2], a[3]))
    if best[4] == "stop" and not e.is_ego and "straight_on" in e.features and any(
            a[4] == "go_straight" and a[1] == best[1] and a[3] > best[3] for a in chosen):
        return "go_straight", None  # "a pickup is stopped at the stop sign ... when the pickup proceeds straight
        # through": it stood, then went straight across; going is what it does
    turned = next((a for a in chosen if a[4] == "turn" and a[1] == best[1] and a[3] > best[3]), None)
    if best[4] == "cut_in" and turned is not None and e.features & {"road_left", "road_right", "from_left",
                                                                    "from_right"}:
        side = "left" if e.features & {"road_left", "from_left"} else "right"  # into the ego's way: towards it
        return "turn", turned[5] or side  # "pulled out of a side road on my left and turned into my lane": a turn
    if best[4] == "move" and e.parent is not None:  # "two motorbikes turn left ... the second one is coming too":
        inherited = [a for a in chosen if a[1] == 1 and a[2] >= ACTION_RANK["cross"]]  # coming is no other
        # manoeuvre (but "four wait ... one of them rides off" moves off)
        if inherited:
            best = max(inherited, key=lambda a: (a[2], a[3]))
    if best[4] == "move" and best[1] == 2:
        turning = [a for a in chosen if a[1] == 1 and a[4] in ("turn_left", "turn_right") and a[0] == best[0]]
        if turning:  # "a white SUV turning right came straight at me": the turn is how it came
            best = max(turning, key=lambda a: a[3])
    if best[4] == "cut_in" and any(a[4] == "stop" and a[1] == best[1] and a[3] > best[3] for a in chosen):
        return ("stop" if e.is_ego else "block"), None  # "swerves into its path and stops"; the ego pulls in and stops
    if best[4] == "cut_in" and {"ahead", "stops_abruptly"} <= e.features and any(
            a[4] == "stop" and a[1] == 2 and a[0] > best[0] for a in e.actions):
        return "block", None  # "cuts me up, then stops dead in front of me": a brake check blocks the ego
    moved_in = [a for a in chosen if a[4] in LANE_MOVES and a[5] is not None or a[4] in ("lane_left", "lane_right")]
    if best[4] == "block" and "cuts_off" in e.features and "blocks" not in e.features and moved_in and \
            not any(a[4] == "stop" for a in chosen):
        lane_move = max(moved_in, key=lambda a: a[3])  # "cut me off, he was in the lane to my left and swerved
        return lane_move[4], lane_move[5]  # right into my lane": the cut-off told as the lane change it was
    return best[4], best[5]


LATER_MANOEUVRES = {"turn", "turn_left", "turn_right", "lane_change", "lane_left", "lane_right", "cut_in"}


def _later_manoeuvre(e: Entity) -> tuple | None:
    """The last turn or lane change told of an agent in a stage after the one it was named in, to a side said or
    from a side lane ('it waited, then turned', with no side, tells of the one the text is told from as often as
    of the one waiting before it), or the crossing of one on foot or on a bike ('waits at the kerb, then
    crosses')."""
    return max((a for a in e.actions if a[0] > e.stage and a[1] == 2 and (a[4] in LATER_MANOEUVRES and (
        a[5] is not None or a[4] in ("turn_left", "turn_right", "lane_left", "lane_right") or
        a[4] in ("lane_change", "cut_in") and _side(e) is not None) or
        a[4] == "cross" and e.type in V.VULNERABLE_TYPES)), key=lambda a: (a[0], a[3]), default=None)


FACING_THE_EGO = {"front", "front_left", "front_right"}  # where a vehicle braking is the ego's hazard
INTO_A_LANE = {"cut_in", "lane_left", "lane_right", "lane_change", "block"}  # moves into another lane, or across it


def _only_braked(r: _Reader, e: Entity) -> bool:
    """Every stop said of it is a plain 'braked' ('braked hard', not 'braked to a halt' or 'slammed on'), and it
    did not cut in first (a brake check)."""
    stops = [a for a in e.actions if a[4] == "stop"]
    return bool(stops) and all(a[3] in r.plain_brakes for a in stops) and not any(
        a[4] in INTO_A_LANE for a in e.actions)


def _intro_action(e: Entity) -> tuple[str | None, str | None]:
    action = _action(e, e.stage)
    if action[0] in ("move", "go_straight") and not e.is_ego:
        later = _action(e)
        if later[0] in LATER_MANOEUVRES and any(a[0] > e.stage and a[4] == later[0] and a[0] in e.goes_on
                                                for a in e.actions):
            return later  # "a car passes the ego on the left, then cuts in", "overtakes the ego and then turns
            # right": the pass leads up to the manoeuvre its sentence goes on to
    if action[0] == "stop" and not e.is_ego and "straight_on" in e.features and any(
            a[4] == "go_straight" and a[1] == 2 and a[0] > e.stage for a in e.actions):
        return "go_straight", None  # "a cyclist waiting beside the ego ... when the light turns green, the ego lets
        # the cyclist go straight through first": the crossing it waited for is what it does ("we both moved off"
        # says no way, and it stood)
    if action[0] in ("stop", "walk") and not e.is_ego and (manoeuvre := _later_manoeuvre(e)) is not None and \
            (action[0] == "stop" or manoeuvre[4] == "cross"):  # "a jogger runs along the sidewalk; she then crosses"
        return manoeuvre[4], manoeuvre[5]  # "a truck waits at the red ahead of the ego; when the light turns green,
        # the truck turns right": the turn it waited to make is what it does
    if action[0] is None or not any(a[1] == 2 for a in e.actions if a[0] == e.stage):
        later = _action(e)
        if action[0] == "stop" and later[0] in ("move", "go_straight"):
            return action  # "with a cyclist waiting in front of me; once it went green we both moved off": it stood
            # in the stage it was named in; moving off is what the later stage does
        if later[0] is not None and (action[0] is None or any(a[1] == 2 for a in e.actions)):
            return later
    return action


def _side(e: Entity) -> str | None:
    return _side_of(e.features)


def _position(e: Entity, action: str | None, junction: bool, has_crosswalk: bool,
              target_side: str | None = None) -> tuple[str, bool]:
    """(position, oncoming) from the features, once the whole text is read: side x ahead/behind x which road,
    against the junction context and the lane the ego moves into (`target_side`)."""
    f = set(e.features)
    crossing = (action == "cross" or (action == "walk" and "in_road" in f) or "waits_to_cross" in f) and \
        e.type in V.VULNERABLE_TYPES  # one waiting to cross is placed where its crossing will start
    person = e.type == "pedestrian" or crossing
    walking = e.type == "pedestrian" and not crossing and (
        action == "walk" or ("on_sidewalk" in f and action in (None, "stop", "move")))
    if f & {"target_lane", "blind_spot"} and target_side and not _side(e):
        f.add(f"side_{target_side}")
    if {"level", "behind"} <= f and "overtaking" not in f:
        f.discard("behind")  # "riding alongside on our right, in the blind spot": level is said, and the blind
        # spot only says where the mirror cannot see it
    side = _side_of(f)
    if {"level", "ahead"} <= f and ("into_ego_lane" in f or side and action in (
            "cut_in", "lane_change", "lane_left" if side == "right" else "lane_right")):
        f.discard("ahead")  # "in the left lane, level with Ego, swerves into Ego's lane just ahead", "alongside the
        # bus, cuts left across its front": where it ends
    if crossing and e.type == "pedestrian" and has_crosswalk and "off_crosswalk" not in f:
        f.add("crosswalk")  # "Mrs. Feeney was in that crosswalk? ... She was crossing from my left": on the one
        # crosswalk the road has, said in another sentence
    if "waits_to_cross" in f and e.type in V.VULNERABLE_TYPES and has_crosswalk and "off_crosswalk" not in f:
        f.add("crosswalk")  # "standing beside it, waiting to cross": waiting at the one crosswalk the road has
    if e.road_type == "shoulder" and not _side_of(f):
        f.add("side_left" if _KEEPS_LEFT.get() else "side_right")  # the shoulder is at the kerb edge (the left
        # where traffic keeps left), ahead unless said otherwise
        if not f & {"behind", "level", "overtaking"}:
            f.add("ahead")
    if "ego_behind" in f and e.road_type != "shoulder" and not f & {"bare_left", "bare_right", "level", "behind",
                                                                      "into_ego_lane"}:
        f -= {"side_left", "side_right"}  # "the ego comes up behind a truck broken down in the right lane": the lane
        # named is the ego's too (not one it swerved in from: "swerves into our path and stops ... behind it")
    side = _side_of(f)
    lane_move = action in ("cut_in", "lane_change", "lane_left", "lane_right")
    if "screening" in f and side and action == "stop" and not f & {"behind", "level"}:
        return f"front_{side}", True  # parked at the kerb a crosser steps out from: no lane of the ego's direction
    if crossing and "crosswalk" in e.features and "off_crosswalk" not in f and not f & {"behind", "back_left",
                                                                                        "back_right"}:
        return "near_the_crosswalk", False  # "two kids wait ahead to the right ... one darts onto the crossing": on
        # the crossing said of it, wherever it waited
    for corner in ("front_left", "front_right", "back_left", "back_right"):
        if corner in f:
            return corner, False
    if "across_path" in f and (action or "").startswith("turn") and not f & {
            "road_left", "road_right", "from_left", "from_right", "side_left", "side_right", "cross_road"}:
        f.add("road_straight")  # "turned left across our path": the oncoming turner
    if "toward" in f and not lane_move and not (side and f"bare_{side}" not in f) and "destination" not in f:
        f.add("road_straight")  # "comes towards the ego": oncoming; "drifts towards the ego" from a lane: no; on
        # the road the ego turns into ("on the street where I turned in, two kids came towards me"): there
    if "far_side" in f and junction and not person and not lane_move:
        f -= {"side_left", "from_lane", "bare_left"}  # "from the far side" of a junction: across it
        f.add("destination" if (action == "stop" or action == "block" and "parked" in f) and "from_lane" not in
              e.features else "road_straight")  # "the exit is blocked by a bus sat stationary on the far side"
    if "road_straight" in f and not person:  # where it comes from wins over where it heads
        return ("road_of_straight", False) if junction else ("front_left", True)
    for s in SIDES:
        if f"road_{s}" in f:
            if person and crossing and not junction:  # "crossing from the left" with no junction: from that kerb
                return ("near_the_crosswalk" if "crosswalk" in f else f"front_{s}"), False  # ("onto the zebra
                # from the right kerb": at the crossing)
            return f"road_of_{s}_turn", False
    turner_from_a_side = (action or "").startswith("turn") and bool(f & {"from_left", "from_right"})
    if "destination" in f and not ("crosswalk" in f and crossing) and not turner_from_a_side:
        # "a motorbike from the left turning right into the street the player heads for": it comes from the left  # "on the crosswalk of the road it turns into"
        return "at_the_destination", False
    if "cross_road" in f and e.type != "pedestrian":  # (a cyclist "emerged from a side road on our right")
        return f"road_of_{side or UNSPECIFIED['side_of_a_crossing_road']}_turn", False
    if "crosswalk" in f and e.type in V.VULNERABLE_TYPES and not walking:
        return "near_the_crosswalk", False
    from_side = next((s for s in SIDES if f"from_{s}" in f), None)
    if from_side and e.type != "pedestrian" and junction and not {"behind", "overtaking"} <= f and (
            not lane_move or action == "cut_in" and not f & {
            "from_lane", "side_left", "side_right", "ego_lane", "into_ego_lane", "lane_said"} and e.came_along):
        return f"road_of_{from_side}_turn", False  # a cyclist crossing from the left; at a crossroads, one coming
        # from the right that shoots across in front, out of the road it came along (no lane named; not "cut in
        # from the left at the signal", nor one behind the ego overtaking it from the left)
    bare = next((s for s in SIDES if f"bare_{s}" in f), None)  # "a minivan on your right" at a four-way stop
    if bare and not person and junction and not lane_move and not f & {"ahead", "behind", "level", "overtaking"} \
            and e.type not in V.TWO_WHEELER_TYPES \
            and e.road_type != "shoulder" and "ego_lane" not in f:
        return f"road_of_{bare}_turn", False
    if "junction_approach" in f and junction and not person and side is None and not f & {"ahead", "behind"}:
        return f"road_of_{UNSPECIFIED['side_of_a_crossing_road']}_turn", False
    ahead, behind = ("ahead" in f or "off_road" in f and "behind" not in f) and "overtaking" not in f, \
        "behind" in f or "overtaking" in f and "level" not in f  # out of a driveway: it joins the road ahead
    if lane_move and {"level", "into_ego_lane"} <= f and not behind:
        ahead = False  # "alongside me ... moved into my lane, directly in front of me": level, ending ahead
    if ("ego_lane" in f or "followed" in f) and not lane_move and "into_ego_lane" not in f and "from_lane" not in f \
            and ("overtaking" not in f or "behind" in f) and not (crossing and f & {"from_left", "from_right"}):  # "overtook us on the right, pulled in ahead": the side it
        # passed on; but "approached from behind in the same lane ... passed on the left": it starts behind, in it
        side = None  # "stops in the ego lane"; but "from the right lane ... in the ego lane" keeps its origin
    if side is None and "overtaking" in f and not ("behind" in f and junction is False) and \
            "over_the_centre_line" not in f:  # (on a road of one lane each way it passes in the lane coming the
        # other way, behind the ego in its own: "two motorbikes came past me on the approach to a blind bend")
        side = _overtaking_side("side_of_an_overtaker")
        side = OTHER_SIDE[side] if "undertaking" in f else side  # passing on the kerb side
    if action == "block" and side and ("from_lane" in f or f"from_{side}" in f) and not behind:
        ahead = True  # "cuts off the ego from the right adjacent lane"
    if side is None and "from_kerb" in f and action == "cut_in" and not f & {"ego_lane", "behind"}:
        side = "left" if _KEEPS_LEFT.get() else "right"
    moving_out = "moves_out" in f and "ahead" in f and side is None and "ego_lane" not in f
    if (action == "cut_in" or action == "lane_change" and "from_lane" in f and "into_ego_lane" in f) and \
            not moving_out and not behind and "level" not in f and (side is None or "from_lane" in f or
                                                                    f"from_{side}" in f):
        from_a_lane_said = side is not None and "from_lane" in f and "lane_said" in f
        side = side or UNSPECIFIED["side_of_a_cyclist_cut_in" if e.type == "cyclist" else "side_of_a_cut_in"]
        ahead = ahead or not from_a_lane_said  # a cut-in from the lane beside starts ahead of the ego; from a lane
        # said ("a car from the left lane cuts in", as "in the left lane that cuts in"): level, unless placed ahead
    if action in ("lane_left", "lane_right") and "into_ego_lane" in f and side is None and \
            not f & {"ego_lane", "to_the_kerb"}:
        side = OTHER_SIDE[action[5:]]  # "a truck moves left into the ego's lane": from the lane on its right,
        ahead = ahead or not behind and "level" not in f  # met ahead as a cut-in is
    if side is None and "level" in f and not ahead and not behind:
        side = UNSPECIFIED["side_beside_a_person" if e.type in V.VULNERABLE_TYPES else "side_beside_a_vehicle"]
    if person and crossing and has_crosswalk and not behind and "off_crosswalk" not in f:
        return "near_the_crosswalk", False  # people crossing where there is a crosswalk cross at it
    if side and action == "stop" and "parked" in f and not person and \
            not f & {"ahead", "behind", "level", "overtaking"} and "target_lane" not in f:
        ahead = True  # "a bus parked on the right", "a lorry parked on the nearside": met ahead
    if "on_the_far_corner" in f and not behind and "level" not in f:
        ahead = True  # (the near corner is beside the ego, at its stop line)
    if walking:
        if has_crosswalk and (side is None or "crosswalk" in f) and not f & {"ahead", "behind"}:
            return "near_the_crosswalk", False  # standing by the crossing ("on your left near the crossing")
        side = side or (None if "met_head_on" in f else UNSPECIFIED["side_of_a_sidewalk_walker"])  # (one the ego
        # drives along the pavement towards is in its path)
    if side is not None:
        if person and crossing and not behind:
            return f"front_{side}", False
        if ahead:
            return f"front_{side}", False
        if behind:
            return f"back_{side}", False
        return side, False
    if behind:
        return "back", False
    return "front", False


def _side_of(f: set) -> str | None:
    for side in SIDES:
        if f"side_{side}" in f or f"front_{side}" in f or f"back_{side}" in f or f"from_{side}" in f:
            return side
    return None


def _final_action(e: Entity, action: str | None, direction: str | None, position: str) -> str:
    side_now = "left" if "left" in position else "right" if "right" in position else None
    if action is None:
        if e.type == "pedestrian":  # standing on the pavement or the verge, said no more: stays there
            return "on_the_sidewalk" if "on_sidewalk" in e.features or e.road_type in ("sidewalk", "shoulder") \
                and "crosswalk" not in e.features else "cross_the_road"
        if e.road_type == "shoulder" and e.type not in V.TWO_WHEELER_TYPES and not e.is_ego:
            return "stop"  # "a broken-down car on the hard shoulder and a police car behind it": stood there too
        return "go_straight"
    if action in ("turn_left", "turn_right"):
        return action
    if action in ("move", "cut_in") and {"into_ego_lane", "road_straight"} <= e.features and not e.is_ego:
        return "change_lane_to_right" if _KEEPS_LEFT.get() else "change_lane_to_left"  # oncoming, over the centre
        # line into the ego's lane: towards its own offside
    signalled = next((s for s in SIDES if f"signals_{s}" in e.features), None)
    if action in ("turn", "u_turn"):
        return f"turn_{direction or signalled or UNSPECIFIED['turn_direction']}"
    if action in ("lane_left", "lane_right"):
        return f"change_lane_to_{action[5:]}"
    if action == "lane_change":
        direction = direction or signalled
        if direction:
            return f"change_lane_to_{direction}"
        return "change_lane_to_right" if side_now == "left" else "change_lane_to_left"
    if action == "cut_in":
        if e.is_ego:
            return f"change_lane_to_{direction}" if direction else "go_straight"
        if position.startswith("road_of_"):
            return "go_straight"  # out of a side road, across in front: over the junction, no lane change
        if side_now is None and position == "front" and "moves_out" in e.features:
            return "change_lane_to_right" if _KEEPS_LEFT.get() else "change_lane_to_left"  # out, away from the kerb
        if side_now is None and position == "back" and "moves_out" in e.features:
            return f"change_lane_to_{_overtaking_side('side_of_an_overtaker')}"  # "the car behind pulled out round
            # me": out of the ego's lane to pass it
        if side_now is None:
            return "block_the_ego" if position == "front" and e.type != "pedestrian" else "go_straight"
        return "change_lane_to_right" if side_now == "left" else "change_lane_to_left"
    if action == "move" and direction and position == "back" and not e.is_ego:
        return f"change_lane_to_{direction}"  # "came up behind us and went around on the right": out of our lane
    if action == "block":
        if "parked" in e.features and position == "at_the_destination":
            return "stop"  # "a lorry parked in the road we turn into, obstructing it": it stands where we head
        return "block_the_ego"
    if action == "stop":
        if e.type != "pedestrian" and position == "front" and "stays_long" in e.features:
            return "block_the_ego"  # stopped in front of the ego for minutes: the ego cannot go on
        if e.type == "pedestrian" and e.road_type == "shoulder" and not e.features & {"on_sidewalk", "on_verge"}:
            return "stop"  # "the driver standing on the hard shoulder beside it": stood on the road's shoulder, not a
            # pavement
        if e.type == "pedestrian" and (e.features & {"on_sidewalk", "on_verge"} or e.road_type == "sidewalk"):
            return "on_the_sidewalk"  # standing on the pavement or the verge
        if e.type == "pedestrian" and "waits_to_cross" in e.features and position != "near_the_crosswalk":
            return "on_the_sidewalk"  # waiting to cross where there is no crossing: at the kerb, on the pavement
        if e.type == "pedestrian" and any(a[4] == "walk" for a in e.actions) and not e.features & {"crosswalk",
                                                                                                 "in_road"}:
            return "on_the_sidewalk"  # "standing on the pavement, waiting": where it waits is the pavement
        return "stop"
    if action == "cross":
        if "waits_to_cross" in e.features and e.type == "pedestrian" and (
                "on_sidewalk" in e.features or e.road_type == "sidewalk" or any(a[4] == "walk" for a in e.actions)):
            return "on_the_sidewalk"  # "standing on the pavement, waiting to cross": still on the pavement
        if "straight_across" in e.features and position in ("road_of_left_turn", "road_of_right_turn"):
            return "go_straight"
        return "cross_the_road" if e.type in V.VULNERABLE_TYPES else "go_straight"
    if action == "walk":
        if e.type != "pedestrian":
            return "go_straight"
        if "on_sidewalk" in e.features and "in_road" not in e.features:
            return "on_the_sidewalk"
        return "cross_the_road" if e.features & {"crosswalk", "in_road"} else "on_the_sidewalk"
    return "go_straight"


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
    words = [w[:20] for w in re.findall(r"[A-Za-z0-9][A-Za-z0-9'-]*", prompt)]
    return (" ".join(words[:10]) or "scene").lower().replace('"', "")[:80].strip()


QUOTED = re.compile(r'["\u201c]([^"\u201d\n]{1,80})["\u201d]')
FIRST_AND_SECOND_PERSON = re.compile(r"\b(?:i|me|we|us|you|my|our|your|i'm|i'd|i've|you're)\b", re.I)


def _without_quoted_speakers(prompt: str) -> str:
    """'The classic "sorry mate, I didn't see you". A driver is waiting to turn right ...': where 'I' and 'you'
    are only ever said inside quotes, they are someone's words quoted, no teller in the scene."""
    quotes = QUOTED.findall(prompt)
    if not any(FIRST_AND_SECOND_PERSON.search(q) for q in quotes) or \
            FIRST_AND_SECOND_PERSON.search(QUOTED.sub(" ", prompt)):
        return prompt
    return QUOTED.sub(lambda m: "" if FIRST_AND_SECOND_PERSON.search(m.group(1)) else m.group(0), prompt)


def lower(prompt: str, seed: int = 0) -> Lowered:
    """Lower an English prompt into a Scenario; LoweringError when nothing in it can be read as a scene."""
    narration = read_narration(rule_before_its_scene(_without_quoted_speakers(prompt)))
    prompt = one_line_records(narration.text)
    tokens = tokenize(prompt)
    if not tokens:
        raise LoweringError("the prompt is empty")
    tokens = _ev_as_ego(tokens)
    numbered = _first_numbered_vehicle(tokens)
    if numbered:
        tokens = [replace(t, word="ego", base="ego", label="") if t.label == numbered else t for t in tokens]
        tokens = _without_the_insured_aside(tokens)
    r = _Reader(tokens, _units(tokens), notes=list(narration.notes))
    if numbered:
        r.notes.append(f"read {numbered.upper()} as the ego: the report numbers its vehicles and names no ego")
    _KEEPS_LEFT.set(_drives_on_the_left(tokens))
    ego_words = [u.tokens for u in r.units if u.category == "agents" and u.meaning == "ego"]
    _EGO_SPEAKS.set(bool(ego_words) and all(len(ts) == 1 and ts[0].word in SPEAKERS for ts in ego_words))
    r.units = _retract_corrections(r)
    r.units = _later_corrections(r)
    UNSPECIFIED.draw_for(seed)
    road = _road(r)
    weather = _weather(r)
    asked = _asked_kind(tokens)
    skip: set[int] = set(_title(prompt, tokens)) | set(_sentence_passed(tokens))
    if asked is not None:
        skip |= set(asked[1])
        r.used.update(asked[1])
    clauses = _clauses(r, skip)
    if not any(t.word in SPEAKERS for t in tokens):  # ("Sitting at a red in the left lane, Jeep in the right lane
        # starts drifting": a teller's participle is often the teller's own)
        clauses = _main_clause_before_its_opening_participle(clauses)
    r.staged = any(c.stage for c in clauses)
    previous: list[Entity] = []
    main_subject: list[Entity] = []  # the subject of the last clause that is not a relative one
    outside_condition: list[Entity] = []  # the subject of the last clause that is not a condition
    recent: list[Entity] = []
    pending: list[Entity] = []
    header: list[Unit] = []
    boxed: dict = {}  # sentence -> the ego's block action told in the passive there, with no one said to do it
    subjects: list[list[Entity]] = []  # each clause's subject, in order
    for k, clause in enumerate(clauses):
        if clause.link == "," and k > 0 and recent and len(clause.units) > 2 and \
                _the_one_after(clauses[k - 1].units, clause.units, 0):
            clause.antecedent = next((e for e in reversed(recent) if not e.is_ego), None)
            r.mark(clause.units[0]), r.mark(clause.units[1])
            clause.units = clause.units[2 + (clause.units[2].word in RELATIVES):]  # the noun before, again
        if clause.link in RELATIVES and recent:
            clause.antecedent = recent[-1]
            other = recent[-2] if recent[-1].is_ego and len(recent) > 1 else recent[-1]
            if k > 0 and _ego_placed_last(clauses[k - 1].units):
                if _set_off_after_the_ego(tokens, clause, clauses[k - 1].units, other):
                    clause.antecedent = _ego_entity(r, clause.stage)  # "in front of the ego, who stops"
                elif recent[-1].is_ego and len(recent) > 1:
                    clause.antecedent = recent[-2]  # "three cars ahead of the player that each swerve": the cars
            elif k > 0 and len(recent) > 1 and not recent[-2].is_ego and _placed_by_a_pronoun(clauses[k - 1].units):
                clause.antecedent = recent[-2]  # "hides a motorbike next to it, which turns left": the one placed by
                # 'it', not the one 'it' names again
        if clause.antecedent is not None and not clause.antecedent.is_ego and k + 1 < len(clauses) and \
                clauses[k + 1].link == "," and clauses[k + 1].units and clauses[k + 1].units[0].category == "actions" \
                and clauses[k + 1].units[0].tokens[0].sentence == clause.units[-1].tokens[0].sentence and \
                not clauses[k + 1].units[0].tokens[0].word.endswith("ing"):
            clause.background = True  # "a bus, the one that was stopped at the kerb, moves off": it moves off
        if k > 0 and clauses[k - 1].antecedent is not None and previous == [clauses[k - 1].antecedent] and \
                main_subject and _returns_to_the_main_subject(clause.units):
            previous = main_subject  # "waits behind a bus that is stopped, then overtakes it": the ego overtakes
        if k > 1 and clauses[k - 1].link in ("while", "whilst") and _after_then(tokens, clause) and \
                clause.units[0].category == "actions" and subjects[k - 2]:
            previous = subjects[k - 2]  # "she waited while two ladies crossed, then turned left": the one who
            # waited goes on, not those she waited for
        elif k > 0 and clauses[k - 1].link in SIDE_LINKS and main_subject and clause.units and (
                clause.units[0].category == "actions" or clause.units[0].word in DOING_A_MANOEUVRE and
                any(u.category == "actions" for u in clause.units[1:3])) and \
                not _progressive_goes_on(clauses[k - 1], clause):  # ("..., and then make the lane change")
            previous = main_subject  # "held position until the pickup had passed, then completed the left": the
            # one who waited acts again, not the one waited for
        if k > 0 and clauses[k - 1].condition and not clause.condition and outside_condition and clause.units and \
                clause.units[0].word in ("it", "he", "she") and _gone_by(clauses[k - 1].units):
            previous = outside_condition  # "the ego waits to turn; once the oncoming car has gone by, it turns": the
            # one who waited, not the one gone
        if k > 0 and clauses[k - 1].condition and not clause.condition and clause.units and \
                clause.units[0].category == "actions" and clause.units[0].tokens[0].word.endswith("ing") and \
                _gone_by(clauses[k - 1].units):
            speaker = next((e for e in r.entities if e.is_ego), None)
            if speaker is not None:
                previous = [speaker]  # a commentary's "once both are through, turning left": the speaker's doing
        if k > 0 and _the_ego_acts_last(clauses[k - 1], clause) or _the_speakers_obligation(r, clause):
            ego_entity = next((e for e in r.entities if e.is_ego), None)
            previous = [ego_entity] if ego_entity is not None else previous  # "a van parked ahead forces the ego
            # to wait before passing it": the ego passes, not the van; "Had to take over, then braked": the
            # speaker, whose subject a diary drops, does what follows
        before = len(r.entities)
        ego_blocked = [e for e in r.entities if e.is_ego and any(a[4] == "block" for a in e.actions)]
        said_until = r.order
        subject = _read_clause(r, clause, previous, recent, pending)
        subjects.append(subject)
        _placed_by_the_egos_relative(clause, subject)
        if clause.stage > 0 and clause.units and clause.units[0].category == "actions" and subject == previous and \
                len(subject) == 1 and subject[0].said_at >= 0 and \
                tokens[subject[0].said_at].sentence == clause.units[0].tokens[0].sentence:
            subject[0].goes_on.add(clause.stage)  # "a car passes the ego, then cuts in": the sentence goes on
        _gapped(r, clause, previous, r.entities[before:])
        aside = clause.link == "," and subject and all(e in r.entities[:before] for e in subject) and \
            not _has_verb(clause.units) and k > 0
        # "It stopped behind a truck double-parked in its lane, driver nowhere around. ..., it changed lane": a
        # verbless aside on one named before leaves the subject where it was
        if _opens_a_correction(clause.units):
            for e in subject[:1] if subject and subject[0] in r.entities[:before] else []:
                if any(a[3] > said_until for a in e.actions):  # "a cyclist ... is crossing... no wait, the cyclist
                    e.actions = [a for a in e.actions if a[3] > said_until or a[0] != clause.stage]  # should be
                    # waiting": what it does is said again, and the new saying stands
        if _says_no_part(clause.units, tokens):
            for e in subject:  # "the person in the driver's seat is our safety operator, not an actor"
                if not e.is_ego:
                    e.features.add("no_part")
        if subject and not clause.condition and not aside:
            outside_condition = subject
        if clause.condition and clause.stage > 0 and _gone_by(clause.units):
            for e in r.entities[before:]:  # "once the oncoming car has gone by, it turns": the car goes by while the
                if not e.is_ego and e.stage == clause.stage:  # ego waits, in the stage before
                    e.stage -= 1
                    e.actions = [(a[0] - (a[0] == clause.stage),) + a[1:] for a in e.actions]
        _boxed_in_by_those_listed(r, clause, before, ego_blocked, boxed)
        if subject and clause.antecedent is None and clause.link not in SIDE_LINKS and not aside:
            main_subject = subject
        more_doers = clause.link == "and" and k > 0 and clauses[k - 1] is r.passive  # "by a van and a bus"
        if clause.units and (clause.units[0].word == "by" or more_doers) and not _has_verb(clause.units) and \
                previous and not any(e.is_ego for e in previous):
            for e in r.entities[before:]:  # "overtaken on the right by an ambulance and then by a fire engine"
                if not e.is_ego and not e.actions:
                    e.features |= set().union(*(p.features for p in previous))
                    e.actions += [(clause.stage,) + a[1:] for p in previous for a in p.actions]
                    r.notes.append(f"inferred: '{e.head}' after 'by' does what '{previous[0].head}' did")
        for e in r.entities[before:]:
            for u in header if not e.is_ego else []:
                _modify(r, e, u, clause.stage, 1)
        first = clause.units[0].tokens[0] if clause.units else None
        header = _header_of_place(clause.units) if first is not None and (
            first.index == 0 or tokens[first.index - 1].sentence != first.sentence) else []
        # a heading starts its line; "Ego: stationary in queue, left lane": the ego's lane, heading nobody
        lead = k - 1
        if clause.link == "which" and k > 1 and [u.word for u in clauses[k - 1].units] in (["in"], ["into"]):
            lead = k - 2  # "changes to the left lane, in which a car approaches"
        into_it = clause.link == "where" or lead == k - 2
        if into_it and k > 0 and any(u.category == "actions" and u.meaning.startswith("lane")
                                     for u in clauses[lead].units):
            for e in r.entities[before:]:  # "the ego changes into the left lane, where a van drives ahead"
                if not e.is_ego:
                    e.features.add("target_lane")
        elif clause.link == "where" and k > 0 and any(
                u.category == "actions" and u.meaning in ("turn", "turn_left", "turn_right")
                for u in clauses[k - 1].units) and any(t.word in ("into", "onto") for u in clauses[k - 1].units
                                                       for t in u.tokens):
            for e in r.entities[before:]:  # "turns left into a side road where a delivery van stands parked"
                if not e.is_ego and not e.features & {"road_left", "road_right", "road_straight", "from_left",
                                                       "from_right"}:
                    e.features.add("destination")
        followed = next((i for i, u in enumerate(clause.units[1:], 1) if u.word == "followed" and
                         clause.units[i - 1].category == "comma"), None)
        if followed is not None and clause is r.passive and subject and not any(e.is_ego for e in subject):
            led = [e for e in r.entities[before:] if not e.is_ego and e not in subject]
            subject = led[:1] + subject  # "a car, followed by a motorcyclist, approaches from our left": both do
        if subject and not aside:
            previous = subject
        if clause.antecedent is not None and not clause.antecedent.is_ego and clause.antecedent not in subject and \
                k + 1 < len(clauses) and clauses[k + 1].link in (",", "") and clauses[k + 1].units and (
                    clauses[k + 1].units[0].category == "actions" or
                    [x.word for x in clauses[k + 1].units[:2]] in (["had", "to"], ["has", "to"])) and \
                not clauses[k + 1].units[0].tokens[0].word.endswith("ing") and \
                clauses[k + 1].units[0].tokens[0].sentence == clause.units[-1].tokens[0].sentence:
            # "a man, whom I now know to be its driver, walked out": the man did; so "the bus I was stuck behind
            # finally pulled away", where the later stage opens on the bus's verb
            previous = [clause.antecedent]
            if clauses[k + 1].link == "":
                clauses[k + 1].link = "and"
        verbless = not _has_verb(clause.units)
        r.after_verbless = verbless and _has_agent(clause.units)
        pending = [e for e in r.entities[before:] if not e.is_ego] if verbless and clause.link in ("", ",") \
            else []
    _drivers_of_their_own(r)
    if not ego_words or NARRATORS_DRIVER in narration.notes:
        _protagonist_vehicle(r, driver_named=bool(ego_words))
    elif _EGO_SPEAKS.get() and not _speaker_on_the_road(r):
        _protagonist_vehicle(r, driver_named=False)  # "I watch drivers speed past the school ... a car speeding
        # past, and a boy running out in front of it": an onlooker speaks; the scene is told from the car
    _the_drivers_own_vehicle(r)
    _the_ego_said_again(r)
    _the_speakers_vehicle_by_a_part(r)
    _the_learner_at_the_wheel(r)
    _works_report(r)
    _the_crews_own_stands(r)
    _the_one_driver_spoken_of(r)
    _witness_on_foot(r)
    _rider_reporting_a_driver(r)
    _the_patients_vehicle(r)
    _named_as_the_ego(r)
    _the_customers_vehicle(r)
    _the_logs_own_vehicle(r)
    _the_named_turn_is_anothers(r)
    _a_riders_ego(r)
    _the_tellers_mount(r)
    _the_tellers_bike(r)
    _the_camera_car(r)
    _an_instance_given(r)
    _taken_back(r)
    _the_named_cut_in(r)
    _screens_on_the_crossers_side(r)
    _out_from_the_parked_row(r)
    _numbered_lane_sides(r)
    _from_the_same_place(r)
    _named_lane_sides(r)
    _included_and_listed_items_share(r)
    _members_keep_the_group_place(r)
    _place_in_queue(r)
    _sitting_behind_a_stopped_ego(r)
    _a_door_opened_from_inside(r)
    _the_same_one_again(r)
    _named_by_what_it_does(r)
    _passing_mentions(r)
    _people_said_in_passing(r)
    _the_crews_own(r)
    others = [e for e in r.entities if not e.is_ego and e.count > 0]
    kind = asked[0] if asked is not None and not others else None
    if asked is not None and others:
        r.notes.append(f"the scene kind '{asked[0]}' was asked for, but the prompt names its agents; "
                       "no template used")
    road = _ego_lane_road(r, road)
    _a_drivers_trade(r)
    _the_egos_brake_is_no_stop(r)
    _waiting_behind_the_stopped_ego(r)
    _from_the_same_direction(r)
    _other_bikes_like_the_egos(r)
    junction_words = road.junction is True or bool({"stop", "yield"} & set(road.required_signals)) or (
        road.junction is None and "traffic_light" in road.required_signals and (any(
            f"from_{side}" in e.features and "from_lane" not in e.features for e in r.entities for side in SIDES)
            or any("road_straight" in e.features and "oncoming_lane" not in e.features for e in r.entities)))
    # "a cyclist running the red light from the left", "an oncoming car at the lights": a signalised junction
    if junction_words or "stop_line" in road.required_objects:
        _pulling_out_of_a_junction_turns(r)
    _pulling_away_after_a_stop(r)
    turns = any((_intro_action(e)[0] or "").startswith("turn") for e in r.entities) or any(
        (_action(e, st)[0] or "").startswith("turn") for e in r.entities if e.is_ego
        for st in {a[0] for a in e.actions})  # "once it turns green we turn left": a later turn is at a junction
    for e in r.entities:  # "a truck crossing left to right": a vehicle crossing is cross traffic at a junction
        if not e.is_ego and e.type not in V.VULNERABLE_TYPES and any(a[4] == "cross" for a in e.actions):
            e.features.add("cross_road")
    junction_features = any(f in e.features for e in r.entities for f in ("road_left", "road_right",
                                                                           "destination", "cross_road")
                            if not (e.type == "pedestrian" and f.startswith("road_")))  # "crossing from the left"
    junction = road.junction is not False and (junction_words or turns or junction_features or
                                               any("road_straight" in e.features for e in r.entities) and turns)
    has_crosswalk = any(w in V.CROSSWALK_OBJECTS for w in road.required_objects)
    if any(w in V.CROSSWALK_OBJECTS for w in road.without_objects):
        for e in r.entities:
            e.features.discard("crosswalk")  # "a man stepped out ..., and there isn't even a crossing": at none
    stages, oncoming = _compose(r, junction, has_crosswalk)
    if road.lanes < 2 and _one_lane_each_way(r.tokens):
        oncoming = set(oncoming) | {a.name for st in stages for a in st}  # "one lane each way", "single carriageway":
        # one who pulls out round another, or passes, uses the other side's lane; no second lane is implied
    ego = stages[0][0]
    sampled_comments: dict[str, Comment] = {}
    if kind is not None:
        template, sampled_comments = _template(kind, seed, r.notes)
        road = _merge_road(template.road, road)
        if not any(a.action != "go_straight" for a in [ego]):
            ego = template.ego if ego.behavior == V.DEFAULT_BEHAVIOR else ego
        if ego is not template.ego:
            sampled_comments.pop("agent.ego", None)
        stages[0] = [ego] + [a for a in template.stages[0].agents if not a.is_ego] + stages[0][1:]
    stage_models = tuple(Stage(name=_stage_name(k, len(stages)), agents=tuple(agents))
                         for k, agents in enumerate(stages) if agents)
    draft = Scenario.model_construct(name=_name(prompt), seed=seed or None, weather=weather, road=road,
                                     stages=stage_models, comments={})
    inferred = infer_plan(draft, frozenset(oncoming))
    notes = r.notes + UNSPECIFIED.chosen() + inferred.notes
    candidate = inferred.scenario
    problems = find_problems(candidate)
    if problems:
        raise LoweringError("the prompt lowers to an invalid scene: " + "; ".join(p.message for p in problems))
    comments = sampled_comments | ({"scenario": Comment(leading=tuple(notes))} if notes else {})
    scenario = Scenario.model_validate(candidate.model_dump() | {"comments": comments})
    unknown = _unknown(r)
    said_nothing = (kind is None and not r.entities and scenario.road == RoadSpec() and scenario.weather is None)
    if said_nothing:
        raise LoweringError("nothing in the prompt could be read as a scene"
                            + (f"; unknown words: {', '.join(unknown)}" if unknown else "")
                            + ". Name agents (car, pedestrian, bus...), what they do (turns left, crosses, stops...) "
                              "and where (in front, from the opposite direction...), or write the scene in the "
                              "scenario language (.tsg)")
    return Lowered(scenario, unknown, kind, notes)


STEPPING_OVER = {"cross at", "crossed at", "cross the road", "cross the street", "crossed the road",
                 "crossed the street", "stepping out", "stepped out", "stepping off", "stepped off"}
# a teller on foot, on the way over
ON_FOOT = {"standing", "stood", "walking", "walked", "footway", "pavement", "sidewalk", "footpath", "on foot",
           "a pedestrian", "jogging", "bus stop", "wheelchair", "chair", "to cross", "dropped curb", "at the curb",
           "crossing the road", "crossing the street", "in the crosswalk", "rolling across", "wheeling across",
           "bench", "shelter", "was across the street", "was across the road", "on the porch", "on my porch",
           "in the garden", "in my garden", "at the window", "at my window", "over the zebra", "on the zebra", "across the zebra",
           "over the crossing", "across the crossing", "over the crosswalk", "green man", "walk signal",
           "on the crossing", "on the crosswalk", "halfway across", "halfway over", "wheeled across", "wheeled over",
           "rolled across", "crossed in front", "crossing in front", "crossing the zebra", "crossing the crosswalk",
           "pushing the pram", "pushing the buggy", "pushing the stroller", "pushing the pushchair"} | STEPPING_OVER
# (a wheelchair user, waiting to cross or on the way over; one watching from a bench, a porch or across the street;
# not "I stopped for kids on the crossing")
AT_THE_WHEEL = {"driving", "drove", "driven", "drive", "riding", "rode", "cycling", "cycled", "passenger", "passengers",
                "my car",
                "my vehicle", "my van", "my bike", "my lane", "in my", "was parked", "am parked", "were parked",
                "right lane", "left lane", "middle lane", "inside lane", "outside lane", "fast lane", "slow lane",
                "the lane", "moving off", "moved off", "pulling away", "pulled away", "pulling off", "pulled off",
                "stop sign", "stop line", "red light", "give way"}  # ("I am standing at a stop sign": a driver held)
# ("I stood still in the right lane": standing in traffic, at the wheel, not "Brook Lane"; "moving off from the
# bus stop")
FIRST_PERSON = {"i", "me", "my", "i'm"}
SPEAKING_SELF = FIRST_PERSON | {"we", "us", "our"}  # the names a teller gives itself, alone or in company
AT_THE_WHEEL_OF = {"was", "am", "were", "are", "is", "in", "driving", "drove", "operating", "operated", "on", "patrol",
                   "uniformed", "mobile", "sitting", "riding", "at", "the", "wheel", "of", "duty", "routine", "alone",
                   "stationary", "parked", "a", "an", "marked", "unmarked", "drive", "steer", "pilot", "pull",
                   "operate", "ride", "sit", "passenger", "ease", "nose", "swing", "guide", "edge", "inch", "turn",
                   "took", "take", "taking", "driver", "rider"}  # ("I was the rider of the motorbike")
OPERATED_FROM = {"in", "on", "of", "driving", "drove", "riding", "operating", "operated", "drive", "ride", "operate", "steer",
                 "pilot", "pull", "ease", "nose", "swing", "guide", "edge", "inch", "turn", "took", "take", "taking"}
# the word right before the ego's own vehicle ("she eased the Volvo left": the car she drives; "I took the pickup")
# "I was stationary in a marked police car", "you were operating the bus": the witness's own vehicle


JUNCTION_NOUNS = {"junction", "intersection", "crossroads"}
PARTICIPLE_LINKS = {"before", "while", "whilst", "when"}  # "... before turning left": said of the clause's subject
UNTIL_LINKS = {"until", "till", "before"}  # a clause of what is waited for: its subject is not the story's
DOING_A_MANOEUVRE = {"make", "makes", "made", "do", "does", "did", "perform", "performs", "performed", "complete",
                     "completes", "completed", "execute", "executes", "executed"}
SIDE_LINKS = UNTIL_LINKS | {"because", "since"}  # and of a reason: "slows because a tractor is ahead, then
# overtakes it": the one who slowed acts again


def _returns_to_the_main_subject(units: list[Unit]) -> bool:
    """A bare verb whose object is 'it', 'him', 'her' or 'them' after a relative clause: the pronoun names the
    relative's noun, and nothing does a thing to itself, so the verb is the main clause's subject's."""
    lead = 0
    while lead < len(units) - 1 and units[lead].category == "word" and units[lead].word in OBLIGED:
        lead += 1  # "and has to stop behind it": obliged, and still the verb's subject is to be found
    if len(units) < lead + 2 or units[lead].category != "actions":
        return False
    for u in units[lead + 1:lead + 5]:  # "... then overtakes it", "... and stops behind it", "... then changes to
        # the left lane to pass it"
        if u.category == "word" and u.word in ("it", "him", "her", "them") or \
                u.category == "positions" and u.tokens[-1].word in ("it", "him", "her", "them"):
            return True
        if u.category == "agents":
            return False
    return False


def _pulling_out_of_a_junction_turns(r: _Reader) -> None:
    """'Pulls out to the left from the give-way line', 'I waited for a bus, then pulled out left': out of a side road
    at a junction, a turn, not a lane change (on an open road the same words change lane)."""
    for e in r.entities:
        if "pulls_out" in e.features:
            e.actions = [(a[0], a[1], ACTION_RANK["turn_left"], a[3], "turn_" + a[4][5:], None)
                         if a[4] in ("lane_left", "lane_right") else a for a in e.actions]
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is not None and not {t.word for t in r.tokens} & (GOING_ROUND | {"lane", "lanes"}):
        ego.actions = [(a[0], a[1], ACTION_RANK["turn_left"], a[3], "turn_" + a[5], None)
                       if a[4] == "cut_in" and a[5] in SIDES else a for a in ego.actions]  # "waited for a bus from the
        # right, then pulled out left": the ego out of the junction's side road, turning (not "pulled out right to
        # get round the bus", "moved across into the left lane")


def _pulling_away_after_a_stop(r: _Reader) -> None:
    """'We were sitting at the stop ... the driver pulled out and carried on': the ego pulling out, with no side, lane
    or vehicle to get round said, after it stood, moves off on its way; it changes no lane."""
    ego = next((e for e in r.entities if e.is_ego), None)
    pulled = {t.sentence for k, t in enumerate(r.tokens[:-1]) if t.base == "pull" and r.tokens[k + 1].word == "out"}
    if ego is None or {t.word for t in r.tokens if t.sentence in pulled} & (GOING_ROUND | {"lane", "lanes"}):
        return
    stopped = [a[3] for a in ego.actions if a[4] == "stop"]
    ego.actions = [(a[0], a[1], ACTION_RANK["go_straight"], a[3], "move", None)
                   if a[4] == "cut_in" and a[5] not in SIDES and stopped and min(stopped) < a[3] else a
                   for a in ego.actions]


GOING_ROUND = {"overtake", "overtakes", "overtaking", "overtook", "pass", "passed", "passing", "past", "round",
               "around"}


STILL_PARTICIPLES = {"sitting", "sat", "standing", "stood", "waiting", "walking"}
OPENING_ON_FOOT = STILL_PARTICIPLES | {"from", "crossing", "pushing", "wheeling"}  # "Crossing the zebra pushing the
# pram, a Tesco lorry came towards us": the teller, first as an opening participle's subject


def _what_i_was(tokens: list[Token], k: int, start: int | None = None) -> set[str]:
    """The words of 'I was standing at the bus stop', up to the next clause (from `start`, for an opening
    'Sitting at the bus stop, I ...')."""
    out: list[str] = []
    start = k + 1 if start is None else start
    for t in tokens[start:start + 12]:
        if t.sentence != tokens[k].sentence or t.word in ("when", "while", "and", "as", "but", ",", "saw", "then",
                                                         "for", "which", "who") and not (  # ("I stopped for a lady
            # on the zebra": hers; "waiting behind a bus which was stopped at the bus stop": the bus's stop)
                t.word == "and" and t.index + 1 < len(tokens) and tokens[t.index + 1].word == "was"):
            break  # ("I use a mobility scooter and was halfway over the zebra": both said of me)
        out.append(t.word)
    pairs = {" ".join(out[i:i + n]) for n in (2, 3, 4) for i in range(len(out) - n + 1)}
    if {"chair", "wheelchair"} & set(out):
        pairs.discard("in my")  # "in my chair": on foot, not at a wheel
    if out[:2] == ["was", "crossing"] and out[2:3] in (["a"], ["the"]) and {"road", "street"} & set(out[3:6]):
        pairs.add("crossing the road")  # "I was crossing a quiet street", "I was crossing the main road"
    return set(out) | pairs


OWN_WAY = {"go_straight", "move", "turn", "turn_left", "turn_right", "lane_change", "lane_left", "lane_right", "u_turn",
           "reach"}  # the classes of actions a vehicle does on its own way, not to or for someone else


RELATIONS_TO_THE_EGO = {"follows": "behind", "leads": "ahead"}  # a relation by verb, as a place by the ego


def _may_drive_the_scene(e: Entity, own_lane: bool = False) -> bool:
    """(Not one stopped on the shoulder: 'a broken-down car on the hard shoulder and a police car behind it' are met
    by the ego.) With own_lane, a lane it is named in is its own ('Car A is travelling in the right-hand lane. An
    ambulance comes up behind it')."""
    lanes = {f for f in e.features if f.startswith("named_lane_")} if own_lane else set()
    features = e.features - lanes - {f"side_{f[len('named_lane_'):]}" for f in lanes} - (
        {"overtaking"} if own_lane else set())  # ("A lorry ... catches up with a cyclist. The
    # lorry overtakes": the text opens on the one overtaking, who is no one's overtaker but the scene's)
    if any(a[4] in ("turn", "turn_left", "turn_right") for a in e.actions):
        features -= {"in_road", "moves_out", "parked"}  # "swings right into the road", "pulled out of Orchard Close
        # and turned right": where it turns to and from, not where it stands or whom it meets; "a car is stationary
        # at the stop sign, then pulls away, turning right": held there, not parked
    return e.type in V.EGO_TYPES - {"motorcycle"} and e.count == 1 and not e.generic and \
        not features & (PLACE_FEATURES | PLACED_HOW) and e.road_type != "shoulder" and \
        (e.relative_to is None or e.relative_how in RELATIONS_TO_THE_EGO) and e.parent is None and e.named_of is None


def _the_speakers_vehicle_named_first(r: _Reader) -> bool:
    """A text that opens on one vehicle said with 'the' ('Watch as the car ...', 'At the stop, the car ...')
    before it ever says 'we' or 'us' tells of the speakers' own vehicle."""
    first = next((u for u in r.units if u.category == "agents" and u.meaning != "none"), None)
    if first is None or first.meaning not in V.EGO_TYPES or first.tokens[-1].plural or first.start == 0 or \
            r.tokens[first.start - 1].word != "the":
        return False
    speaker = next((t.index for t in r.tokens if t.word in SPEAKERS), None)
    return speaker is not None and speaker >= first.end and \
        not any(t.word in ("i", "me", "my", "you", "your") for t in r.tokens)


def _the_one_told_from(r: _Reader, driver_named: bool) -> Entity | None:
    if not driver_named and any(t.word in SPEAKERS for t in r.tokens) and _speaker_on_the_road(r) and \
            not _the_speakers_vehicle_named_first(r):
        return None  # "a semi hit my mirror": the one speaking is the ego (but "Watch as the car waits to turn
        # right ... the street we're turning into": the car the text opens on is the one the speakers ride in)
    if not driver_named and any(t.word == "ego" for t in r.tokens):
        return None  # "a lorry swings wide, crossing into the ego's lane": the ego is named, if only by its lane
    ordered = sorted(r.entities, key=lambda e: e.key)
    driver = next((e for e in ordered if not e.is_ego and e.head in ("driver", "motorist") and
                   _may_drive_the_scene(e) and (
        not e.definite or [t.word for t in r.tokens[e.said_at + 1:e.said_at + 3]] in (["of", "a"], ["of", "an"]))),
                  None)  # (so "the driver of a silver Corolla": named here for the first time)
    if driver is not None and not driver_named:
        return driver  # "an eastbound driver on Park Road may not see a fire engine coming out": the one the case
        # is told from, as an audit or a rule names the road user it is about
    ridden = next((e for e in ordered if not e.is_ego and e.type in V.EGO_TYPES and e.count == 1 and
                   e.said_at >= 2 and r.tokens[e.said_at - 1].word in ("his", "her", "their") and
                   r.tokens[e.said_at - 2].word in ("on", "in", "riding", "driving") and
                   r.tokens[e.said_at].sentence == r.tokens[0].sentence and
                   not any(a[4] in ("stop", "block") for a in e.actions)), None)
    if ridden is not None:
        return ridden  # "Client was on his motorcycle heading west ...": the one the account opens riding
    if not driver_named and _watched_from_off_the_road(r) and not _says_any(
            [t.word for t in r.tokens], (("we", "are", "following"), ("i", "am", "following"))):
        watched = next((e for e in ordered if not e.is_ego and e.type in V.EGO_TYPES and e.count == 1 and
                        not e.generic and e.parent is None), None)
        if watched is not None:
            return watched  # the first vehicle one watching from off the road tells of, whatever it does (one
            # "we are following" from the air is read as the speakers' own)
    named_first = next((e for e in ordered if not e.is_ego), None)
    if named_first is not None and named_first.type not in V.VULNERABLE_TYPES and \
            named_first.relative_to is not None and named_first.relative_how in ("ahead", "behind") and \
            named_first.relative_to.said_at > named_first.said_at and not named_first.relative_to.definite and \
            any(a[4] not in ("stop", "try") for a in named_first.actions) and \
            _may_drive_the_scene(replace(named_first, relative_to=None), own_lane=True):
        return named_first  # "Car A travels in the left lane of a motorway behind a lorry": the one the text opens
        # on, moving, placed by one named after it, is the one it follows (not the lorry, as an anchor; but "a fire
        # engine is coming up behind the red car": one said with 'the' is the one the scene knows)
    anchor = next((e for e in ordered if not e.is_ego and _may_drive_the_scene(e, own_lane=e is named_first) and (
        any(o.relative_to is e and o.relative_how not in RELATIONS_TO_THE_EGO for o in r.entities) or
        e.said_at >= 0 and any(t.possessive and t.word == e.head and r.tokens[t.index - 1].word == "the"
                               for t in r.tokens[e.said_at + 1:]))), None)  # "pulls out into the car's lane"
    # (not "a police car follows a red sedan": the follower is the one the scene is told from)
    if anchor is not None:
        return anchor
    first = next((e for e in ordered if not e.is_ego), None)  # a group named first ("four vehicles wait: a car,
    # a bus, ...") has count 0 once its members are named: no protagonist
    people_first = first is not None and first.type in V.VULNERABLE_TYPES
    if people_first:  # "a wheelchair user trying to get across, and the car turning left doesn't look": the
        first = next((e for e in ordered if not e.is_ego and e.type not in V.VULNERABLE_TYPES), None)  # vehicle
    if first is not None and not people_first and first.road_type != "shoulder" and _told_by_it(r, first):
        return first  # "Silver hatchback stopped at the red ... ped crosses in front of it ... hatchback proceeds":
        # a log of the vehicle it opens on, the others placed by 'it'
    if first is not None and not people_first and first.relative_to is not None and \
            first.relative_how in ("ahead", "behind") and first.relative_to.said_at > first.said_at and \
            _may_drive_the_scene(replace(first, relative_to=None)):
        return first  # "A car is 20 m behind a cyclist when the cyclist turns right", "A lorry moving at 18 m/s is
        # 40 m behind car B": the one the text opens on, placed by one named after it, is the one it follows
    if first is None or not _may_drive_the_scene(first, own_lane=True):
        return None
    earliest = min((a[0] for a in first.actions), default=0)
    opening = min((a for a in first.actions if a[0] == earliest), key=lambda a: a[3], default=None)
    heading = not first.actions and any(f.startswith("compass_") for f in first.features)  # "Car A is heading
    # east towards a crossroads": on its way
    if not driver_named and not first.waits_to_turn and not heading and not _sees_first(r, first) and \
            not _stops_for_someone(r, first) and (
            not any(a[4] in OWN_WAY for a in first.actions) or opening is not None and opening[4] in ("stop", "block")
            and not _the_one_vehicle_turning(r, first)):
        return None  # "the bus has stopped with its lights flashing", "a car cuts in", "the bus stopped, then
        # pulled away": met by someone, who is the ego
    named = next((u for u in r.units if u.category == "agents" and u.meaning != "none"), None)
    opens_on_it = named is not None and _opening_unit(r, named.tokens[0].sentence) is named
    if not people_first and not opens_on_it and not _the_speakers_vehicle_named_first(r):
        return None  # "the queue reaches the retail park, and a lorry is edging along": it opens on no vehicle
        # (but "At the signal the truck turned left ... the road we turned onto": the speakers' own, said first)
    opening = [u for u in r.units if u.start == 0 or r.tokens[u.start - 1].sentence != u.tokens[0].sentence]
    if any(_bare_verb(u) or u.tokens[0].word in ("don't", "dont", "do", "never") for u in opening):
        return None  # "this pickup's doing forty. Don't pass him. Stay behind.": said to the one at the wheel
    return first


BENDS = {"bend", "bends", "corner", "corners", "curve", "curves", "hairpin", "kink", "hander"}


def _round_a_bend(units: list[Unit], k: int) -> bool:
    """'go round a left bend', 'came round the corner': the road's shape the verb follows, no one gone round."""
    for x in units[k + 1:k + 6]:
        if x.category == "agents" or x.word in ("it", "him", "her", "them"):
            return False
        if {t.word for t in x.tokens} & BENDS:
            return True
    return False


def _the_one_vehicle_turning(r: _Reader, first: Entity) -> bool:
    """'A car is stationary at the stop sign, then pulls away, turning right; a pedestrian is crossing': the only
    vehicle named, held and then turning, makes a manoeuvre of its own (not 'a van and a truck wait at the
    lights; the former turns left': one of several met there)."""
    return any(a[4] in ("turn_left", "turn_right", "u_turn") for a in first.actions) and not any(
        e is not first and not e.is_ego and e.type not in V.VULNERABLE_TYPES for e in r.entities)


def _opening_unit(r: _Reader, sentence: int) -> Unit | None:
    """The first unit of a sentence that says something, past a place said first ('At a T-junction controlled by
    a stop sign, a car is stationary': the car)."""
    placed = False
    for u in r.units:
        if u.tokens[0].sentence != sentence or u.category == "word" or u.meaning.startswith("compass_"):
            continue
        if u.category in ("road", "weather") or u.category == "comma" and placed:
            placed = True
            continue
        return u
    return None


def _stops_to_let_by(r: _Reader, e: Entity) -> bool:
    """'a silver car stop to let a jogger cross', 'a van stopped for a woman with a pram': it gives way to someone."""
    if e.said_at < 0:
        return False
    words = [t.word for t in r.tokens[e.said_at + 1:e.said_at + 8] if t.sentence == r.tokens[e.said_at].sentence]
    return any(w in ("stop", "stops", "stopped", "stopping", "pulled", "waited", "waits") and
               words[k + 1:k + 3] in (["to", "let"], ["for", "a"], ["for", "the"], ["to", "allow"])
               for k, w in enumerate(words))


def _stops_for_someone(r: _Reader, first: Entity) -> bool:
    """'Bus stops dead as schoolboy darts into road', 'SUV stops for mum and pram on the zebra': one that stops for
    another, named right after its stop, is the one the scene is told from, not one met standing."""
    if first.said_at < 0:
        return False
    at = bisect_left(r.units, first.said_at, key=_unit_start)
    for k, u in enumerate(r.units[at + 1:at + 4], start=at + 1):
        if u.tokens[0].sentence != r.tokens[first.said_at].sentence or u.category == "agents":
            return False
        if u.category == "actions" and u.meaning == "stop":
            after = [x for x in r.units[k + 1:k + 6] if x.word not in ("dead", "sharply", "suddenly", "hard", "short")]
            return bool(after) and after[0].word in ("for", "as") and any(
                x.category == "agents" and x.meaning in V.VULNERABLE_TYPES for x in after[1:3])
    return False


def _sees_first(r: _Reader, first: Entity) -> bool:
    """'A motorist sees a cyclist 30 m ahead', 'a driver travelling at 13 m/s on a country road notices a child':
    one who opens the text by seeing another is the one it is told from."""
    if first.said_at < 0:
        return False
    others = {e.said_at for e in r.entities if e is not first}
    for t in r.tokens[first.said_at + 1:first.said_at + 16]:
        if t.sentence != r.tokens[first.said_at].sentence or t.index in others or \
                t.word in (",", "and", "but", "who", "which", "that", "when", "while", "as"):
            return False
        if t.base in PERCEIVING:
            return True
    return False


TOLD_BY_IT = (("in", "front", "of", "it"), ("ahead", "of", "it"), ("behind", "it"), ("on", "its", "right"),
              ("on", "its", "left"), ("from", "its", "right"), ("from", "its", "left"), ("to", "its", "right"),
              ("to", "its", "left"), ("its", "path"), ("across", "its", "front"), ("alongside", "it"))
TOLD_BY_ITS_DRIVER = tuple((*place, it) for it in ("her", "him") for place in (
    ("in", "front", "of"), ("ahead", "of"), ("behind",), ("past",), ("round",), ("around",), ("alongside",))) + tuple(
    (prep, its, side) for its in ("her", "his") for prep in ("on", "from", "to") for side in ("right", "left"))
# ("a Jazz waiting at the stop line; a cyclist squeezed past her": the vehicle, as its driver, when no one was
# named who 'her' could be)


def _told_by_it(r: _Reader, first: Entity) -> bool:
    """A text that opens on one vehicle, placed nowhere by the ego, and places the others by 'it' ('in front of it',
    'on its right'): the vehicle a log entry is about."""
    return first.type in V.EGO_TYPES and first.count == 1 and first.parent is None and not first.generic and \
        not first.features & (HEADLINE_PLACES | SIDE_PLACES) and first.relative_to is None and \
        (_says_any([t.word for t in r.tokens], TOLD_BY_IT) or _told_by_its_driver(r, first)) and \
        not any(e.is_ego and (e.aliases or e.type != "car") for e in r.entities) and \
        all(e is first or e.type in V.VULNERABLE_TYPES or e.key > first.key for e in r.entities if not e.is_ego)


def _told_by_its_driver(r: _Reader, first: Entity) -> bool:
    """'her' or 'him' placing another ('past her', 'on his left') names the vehicle by its driver where no person
    (but a rider) was named before it, nor 'she' or 'he' said."""
    words = [t.word for t in r.tokens]
    at = next((k for k in range(len(words)) for p in TOLD_BY_ITS_DRIVER if tuple(words[k:k + len(p)]) == p), None)
    return at is not None and first.said_at < at and not {"she", "he"} & set(words[:at]) and not any(
        e.type == "pedestrian" or e.head in DRIVERS and e.type not in V.TWO_WHEELER_TYPES
        for e in r.entities if 0 <= e.said_at < at)  # ("a bloke on a bike came up behind her": he rides)


SIDE_PLACES = {"side_left", "side_right", "front_left", "front_right", "back_left", "back_right", "from_left",
               "from_right", "road_straight", "road_left", "road_right", "oncoming", "level"}


def _drives(after: list[Token]) -> bool:
    """Whether the verb after a speaker ('I had been following', 'we pulled out') is one of the road."""
    for t in after:
        if t.word in AUXILIARIES | {"just", "then", "also", "still", "already"}:
            continue
        entry = lexicon().phrases.get((t.base,))
        if entry is not None and entry == ("actions", "try"):
            continue  # "we want to test ...": the verb wanted says what is done
        return entry is not None and entry[0] == "actions"
    return False


SEEN_FROM_A_SEAT = {"saw", "see", "noticed", "notice", "spotted", "spot", "heard", "looked", "glanced", "checked",
                    "clocked", "caught"}
SENT_TO = {"sent", "forwarded", "emailed", "posted", "submitted", "shared", "reported", "handed", "given", "shown",
           "uploaded", "passed", "mailed", "delivered", "supplied", "provided"}
OFF_ROAD_VANTAGES = (("helicopter",), ("chopper",), ("sky", "eye"), ("eye", "in", "the", "sky"), ("shop", "window"),
                     ("from", "my", "window"), ("from", "my", "shop"), ("from", "my", "office"),
                     ("from", "my", "flat"), ("from", "my", "house"), ("from", "my", "balcony"), ("from", "my", "porch"),
                     ("from", "my", "desk"),
                     ("from", "the", "footbridge"), ("from", "the", "overpass"), ("control", "room"),
                     ("traffic", "control"), ("the", "flagger"), ("a", "flagger"), ("stop", "go", "board"),
                     ("stop", "go"), ("stop", "slow"), ("my", "paddle"), ("stop", "paddle"), ("my", "board"),
                     ("my", "stop", "board"), ("stop", "bat"), ("my", "stop", "bat"), ("banksman",), ("the", "foreman"),
                     ("on", "the", "gate"), ("kerb", "gang"), ("paving", "crew"),
                     ("marshalling",), ("marshaling",), ("cctv",), ("waiting", "for", "my", "lift"),
                     ("walking", "home"), ("walking", "the", "dog"), ("we", "observed"), ("we", "recorded"),
                     ("we", "noted"), ("site", "visit"), ("during", "our", "visit"), ("sat", "in", "the", "shelter"),
                     ("from", "the", "shelter"), ("out", "for", "my", "morning", "run"), ("out", "for", "a", "run"),
                     ("out", "for", "my", "run"), ("on", "my", "morning", "run"), ("jogger", "here"),
                     ("i", "was", "out", "running"), ("i", "was", "jogging"), ("while", "jogging"))
SPEAKER_PLACES = {"of", "behind", "beside", "past", "passed", "to", "at", "into", "towards", "toward", "overtook",
                  "overtakes", "overtake", "hit", "cut", "followed", "follows", "by", "alongside", "round", "around",
                  "with", "near"}  # "in front of me", "cut us up", "came at me": someone is placed by the speaker


def _watched_from_off_the_road(r: _Reader) -> bool:
    """'From up here in the helicopter I can see a lorry ...', 'From my shop window I saw', 'I'm the flagger ... I
    turned the board to STOP', 'camera 6 picks up a skip lorry': the teller watches from off the road, and is in no
    vehicle of the scene; so do auditors ('we observed an articulated lorry ...')."""
    words = [t.word for t in r.tokens]
    return _says_any(words, OFF_ROAD_VANTAGES) or any(w == "camera" and r.tokens[k + 1].number is not None
                                                      for k, w in enumerate(words[:-1]))


def _speaker_on_the_road(r: _Reader) -> bool:
    """Whether the one who says 'I' or 'we' is in the scene: does something there, is someone's reference ('in
    front of me', 'my lane'), or is spoken to ('you'). 'I watch drivers do thirty past the school. Please recreate
    it: a car speeding past ...' is said by an onlooker; the scene is the car's."""
    if _watched_from_off_the_road(r):
        return False
    words = [t.word for t in r.tokens]
    speaker = next((e for e in r.entities if e.is_ego and e.head in SPEAKING_SELF), None)
    if speaker is not None and (speaker.actions or speaker.features):
        return True
    if _says_any(words, OWN_MOBILITY_AIDS) or any(
            _what_i_was(r.tokens, k) & CROSSING_ON_FOOT - {"across the road", "across the street"}
            for k, w in enumerate(words) if w == "i"):
        return True  # "I was already on the crossing in my wheelchair when a white van swung left across it": met
    told = max((u.tokens[0].sentence for u in r.units if u.category == "agents" and u.meaning not in ("ego", "none")),
               default=-1)  # the last sentence that names someone of the scene: 'you' after it is advice to all
    for k, w in enumerate(words):
        if w in ("you", "your", "yours") and r.tokens[k].sentence <= told or \
                w in ("i", "we") and k + 1 < len(words) and words[k + 1] in SEEN_FROM_A_SEAT:
            return True  # "I saw a van pull out": seen from the driver's seat; "I watch drivers do thirty": onlooking
        if w in ("i", "we") and _drives(r.tokens[k + 1:k + 5]):
            return True  # "a lorry that I had been following": the speaker drives
        if w in ("my", "our") and k + 1 < len(words) and words[k + 1] in ("dashcam", "dash", "camera", "footage",
                                                                          "video", "recording"):
            return True  # "my dashcam caught it": filmed from the speaker's car
        if w in ("me", "us") and k > 0 and words[k - 1] in SPEAKER_PLACES and not (
                k > 1 and words[k - 1] == "to" and words[k - 2] in SENT_TO):
            return True  # (not "footage sent to us by the driver of a Corolla": told to them, not met on the road)
        if w in ("my", "our") and k + 1 < len(words) and (lexicon().phrases.get((words[k + 1],)) or ("", ""))[0] in (
                "agents", "positions", "bodies") or w in ("my", "our") and k + 1 < len(words) and words[k + 1] in (
                "lane", "left", "right", "side", "mirror", "bumper", "bonnet", "windscreen", "way", "path", "inside",
                "outside", "nearside", "offside", "near", "off", "tail", "rear", "blind", "six", "front", "back", "wing",
                "door", "rearview", "hood", "windshield", "nose"):
            return True
    return False


def _placed_by_the_ego_now(r: _Reader, vehicle: Entity) -> None:
    """What was placed by a vehicle that turns out to be the ego is placed by the ego ("an ambulance comes up
    behind the coach": behind the ego)."""
    for e in r.entities:
        if e.relative_to is vehicle and e.relative_how:
            e.relative_to = None
            e.features.add(RELATIONS_TO_THE_EGO.get(e.relative_how, e.relative_how))
            if e.relative_how in ("side_left", "side_right"):
                e.features.add("bare_" + e.relative_how[5:])  # "to the bus's left": a side, no lane said


def _protagonist_vehicle(r: _Reader, driver_named: bool) -> None:
    """A text that names no ego, or names it only as the narrator's driver, tells its scene from one vehicle:
    the one the others are placed by ('a boy runs out in front of the car', 'on the car's left'), else the
    first it opens on, placed nowhere and on its own way ('A bus turns left while a pedestrian crosses',
    'Coach in the middle lane ..., our driver moves over'). That vehicle is the ego's; an ego the reader
    supplied for a verb with no subject is that vehicle too."""
    first = _the_one_told_from(r, driver_named)
    if first is None:
        return
    supplied = next((e for e in r.entities if e.is_ego), None)
    if first.relative_to is not None:  # "a police car follows a red sedan": the sedan drives ahead of the ego
        first.relative_to.features |= {"ahead", "followed"} if first.relative_how == "follows" else {
            SEEN_THE_OTHER_WAY.get(first.relative_how, "behind")}  # ("a car 20 m behind a cyclist": it is ahead)
        first.relative_to = None
    _placed_by_the_ego_now(r, first)
    if driver_named and supplied is not None:  # the driver is the ego, the vehicle theirs
        supplied.type = first.type
        supplied.actions += [a for a in first.actions if not any(b[0] == a[0] for b in supplied.actions)]
        _taken_over(r, first, supplied)
        r.notes.append(f"read the {first.head} as the ego's: the text names the ego only as its driver")
        return
    if supplied is not None and _watched_from_off_the_road(r):
        supplied.actions = []  # ("I'm the flagger ... I turned the board to STOP": the watcher's doings are not its)
    if supplied is not None:  # made for a verb with no subject, or a turn the text implies
        first.actions += [a for a in supplied.actions if not any(b[0] == a[0] for b in first.actions)]
        _taken_over(r, supplied, first)
    first.is_ego = True
    first.actions = [(a[0], 2, ACTION_RANK["stop"], a[3] or r.tick(), "stop", None) if a[4] == "stop" and
                     a[1] == 1 and a[2] == ACTION_RANK["go_straight"] and a[3] == 0 else a for a in first.actions]
    # "a bus heading into town has to stop whenever a lorry comes the other way": what the one the scene is told
    # from is made to do is what it does (a reaction of another's is kept weak: _modify)
    if first.waits_to_turn:  # "a car is waiting to turn right": the ego's turn, as if said of the ego
        stage, action, direction = first.waits_to_turn
        first.actions.append((stage, 2, ACTION_RANK[action], r.tick(), action, direction))
    r.notes.append(f"read the {first.head} as the ego: the text names no other and places it nowhere")


def _the_named_cut_in(r: _Reader) -> None:
    """'#cutin truck from the right lane', 'Cut-in scenario: a van in the left lane': a scene named for a cut-in,
    whose one vehicle in a lane beside the ego is said to do nothing, is that vehicle's cut-in."""
    words = [t.word for t in r.tokens]
    named = "cutin" in words or "cutins" in words or any(
        w == "cut" and words[k + 1:k + 2] == ["in"] and (r.tokens[k].title or r.tokens[k].label or k == 0 or
                                                       words[k + 2:k + 3] and words[k + 2] in SCENE_NAME_WORDS)
        for k, w in enumerate(words))
    if not named or any(a[4] in INTO_A_LANE for e in r.entities
                        for a in e.actions):
        return
    beside = [e for e in r.entities if not e.is_ego and e.type not in V.VULNERABLE_TYPES and e.count == 1 and
              not any(a[2] > 0 for a in e.actions) and e.features & {"side_left", "side_right"} and
              not e.features & {"road_left", "road_right", "road_straight", "toward", "behind"}]
    others = [e for e in r.entities if not e.is_ego and e not in beside and e.count > 0]
    if len(beside) == 1 and not any(not any(a[2] > 0 for a in e.actions) and e.type not in V.VULNERABLE_TYPES
                                    for e in others):
        beside[0].actions.append((beside[0].stage, 1, ACTION_RANK["cut_in"], r.tick(), "cut_in", None))
        r.notes.append(f"inferred: the cut-in the scene is named for is the {beside[0].head}'s")


SCENE_NAME_WORDS = {"scenario", "scene", "test", "case", "run", "event", ":", "-"}


def _drivers_of_their_own(r: _Reader) -> None:
    """'Liam Carter drove his Audi straight across', 'a man was driving her Kia': a person who drives, said with
    the vehicle he or she owns in the same sentence, is that vehicle's driver, no one on foot."""
    for e in list(r.entities):
        if e.is_ego or e.type != "pedestrian" or e.count != 1 or e.said_at < 0 or not e.actions or \
                any(a[4] in ("cross", "walk") for a in e.actions) or e.features & {"on_sidewalk", "crosswalk"}:
            continue
        sentence = r.tokens[e.said_at].sentence
        words = [t for t in r.tokens[e.said_at + 1:] if t.sentence == sentence]
        drives = next((k for k, t in enumerate(words) if t.base in ("drive", "driving", "drove", "driven")), None)
        if drives is None:
            continue
        owned = next((v for v in r.entities if not v.is_ego and v.type not in V.VULNERABLE_TYPES and
                      v.said_at > e.said_at and r.tokens[v.said_at].sentence == sentence and
                      any(t.word in ("his", "her", "their") for t in r.tokens[max(0, v.said_at - 3):v.said_at])),
                     None)
        if owned is None:
            continue
        owned.actions += e.actions
        owned.behavior = owned.behavior or e.behavior
        _taken_over(r, e, owned)
        r.notes.append(f"read the {e.head} who drives the {owned.head} as its driver")


def _the_drivers_own_vehicle(r: _Reader) -> None:
    """'a driver had to stop when a man walked out in front of her car': the ego read from a person at the wheel
    drives the vehicle that is 'hers' (his, theirs) wherever it is named after, unless someone else of that
    pronoun was named before it ('a man walked out in front of his car': the man's)."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is None or ego.head not in DRIVERS:
        return
    for v in list(r.entities):
        if v.is_ego or v.type in V.VULNERABLE_TYPES or v.count != 1 or v.actions or v.said_at < 1 or \
                v.relative_to is not None or v.features & {"ahead", "behind", "side_left", "side_right", "toward"}:
            continue
        owner = next((t.word for t in reversed(r.tokens[max(0, v.said_at - 2):v.said_at])
                      if t.word in ("his", "her", "their")), None)  # "her car", "her old car"
        if owner is None:
            continue
        others = re.compile(rf"\b(?:{OTHER_PEOPLE['he' if owner == 'his' else 'she']})s?\b") if owner != "their" \
            else None
        if others and any(others.fullmatch(e.head.split()[-1]) for e in r.entities
                          if not e.is_ego and e.said_at < v.said_at and e.type in V.VULNERABLE_TYPES):
            continue
        _taken_over(r, v, ego)
        r.notes.append(f"read the {v.head} as the {ego.head}'s own: the ego")


SIDE_WORDS = {"left": "left", "right": "right", "nearside": "right", "offside": "left"}  # where traffic keeps right


def _kerb_side(word: str) -> str:
    """The side a side word names: the nearside is the kerb's, on the left where traffic keeps left."""
    side = SIDE_WORDS[word]
    return OTHER_SIDE[side] if word in ("nearside", "offside") and _KEEPS_LEFT.get() else side


def _out_from_the_parked_row(r: _Reader) -> None:
    """'a line of parked cars on your right. A kid runs out from between them': one who steps out from between or
    behind parked vehicles named as scenery on one side of the road comes from that side."""
    words = [t.word for t in r.tokens]
    sides = set()
    for k, w in enumerate(words):
        if w == "parked":
            span = [j for j in range(max(1, k - 6), min(len(words), k + 7)) if r.tokens[j].sentence ==
                    r.tokens[k].sentence]
            said = {_kerb_side(words[j]) for j in span if words[j] in SIDE_WORDS and (
                words[j] in ("nearside", "offside") or words[j - 1] in OWNERS | {"the", "on", "to"})}
            # (not "right in front of me": how near)
            if "both" in (words[j] for j in span) or len(said) > 1:
                return  # "parked cars on both sides": from either
            sides |= said
    if len(sides) != 1 or any(not e.is_ego and "parked" in e.features and not e.uncounted for e in r.entities):
        return  # (a parked vehicle named as an agent screens the crosser in its own way; "parked cars", never
        # counted, are the row)
    side = sides.pop()
    for e in r.entities:
        if e.type != "pedestrian" or not any(a[4] == "cross" for a in e.actions) or \
                _side_of(e.features) or e.features & {"road_left", "road_right", "crosswalk"} or e.said_at < 0:
            continue
        sentence = [t.word for t in _sentence(r.tokens, r.tokens[e.said_at].sentence)]
        if any(w in ("between", "behind") and set(sentence[k + 1:k + 4]) & {"them", "parked", "cars", "vehicles"}
               for k, w in enumerate(sentence)):
            e.features.add(f"from_{side}")


def _taken_over(r: _Reader, gone: Entity, into: Entity) -> None:
    """One entity found to be another: whoever was placed by it is placed by the other, and it goes."""
    for x in r.entities:
        if x.relative_to is gone:
            x.relative_to = into
    r.entities.remove(gone)


def _waiting_behind_the_stopped_ego(r: _Reader) -> None:
    """'I'm stopped at a zebra ... the Audi behind me is sat right on my bumper leaning on his horn', 'a taxi sat
    behind us honking': one behind the ego that only sounds its horn, while the ego stands, stands behind it."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is None:
        return
    for e in r.entities:
        if e.is_ego or "behind" not in e.features or e.type in V.VULNERABLE_TYPES or \
                not any(a[4] == "horn" for a in e.actions) or any(a[4] not in ("horn", "try") for a in e.actions):
            continue
        stage = min(a[0] for a in e.actions)
        if any(a[4] == "stop" and a[0] == stage for a in ego.actions):
            e.actions.append((stage, 1, ACTION_RANK["stop"], r.tick(), "stop", None))


SAME_WAY = {"direction", "side", "way", "road"}
COME_FROM = {"from_left", "from_right", "road_left", "road_right", "road_straight", "toward", "oncoming"}


def _from_the_same_direction(r: _Reader) -> None:
    """'A fire engine crosses from the right. Then an ambulance follows from the same direction': it comes from
    where the one named before it came from."""
    for k, e in enumerate(r.entities):
        if e.is_ego or e.said_at < 0 or e.features & COME_FROM:
            continue
        said = [t.word for t in _sentence(r.tokens, r.tokens[e.said_at].sentence) if t.index > e.said_at]
        if not any(said[j:j + 3] == ["from", "the", "same"] and said[j + 3:j + 4] and said[j + 3] in SAME_WAY
                   for j in range(len(said))):
            continue
        model = next((x for x in reversed(r.entities[:k]) if not x.is_ego and x.features & COME_FROM), None)
        if model is not None:
            e.features |= model.features & COME_FROM


def _other_bikes_like_the_egos(r: _Reader) -> None:
    """'a group ride with three other bikes following you', 'on another bike': other bikes beside a motorcycle ego
    are motorbikes."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is None or ego.type != "motorcycle":
        return
    for e in r.entities:
        group = e.parent or e
        if not e.is_ego and e.type == "cyclist" and group.head == "bike" and group.said_at >= 1 and \
                {"other", "another"} & {t.word for t in r.tokens[max(0, group.said_at - 3):group.said_at]}:
            e.type = "motorcycle"  # ("my friend was riding ahead of me on another bike")


def _the_ego_said_again(r: _Reader) -> None:
    """'Watch as the car waits to turn ... the system holds the car in place': a vehicle named again with 'the',
    of the ego's own kind, that does nothing and is placed nowhere, while no other of that noun was named, is
    the ego, once the reading has settled who the ego is."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is None:
        return
    for e in list(r.entities):
        if e.is_ego or not e.definite or e.count != 1 or e.actions or e.features or e.relative_to is not None or \
                e.type != ego.type or e.head not in GENERAL_BODIES or e.label or any(
                    x is not e and not x.is_ego and x.head.split()[-1] == e.head for x in r.entities) or any(
                    x.relative_to is e for x in r.entities):
            continue
        r.entities.remove(e)
        r.notes.append(f"read 'the {e.head}' as the ego named again: it does nothing and is placed nowhere")


MET_PARTS = {"front", "rear", "back", "side", "nose", "tail", "bumper", "nearside", "offside", "roof", "cab",
             "door", "mirror", "wing", "corner", "bonnet", "hood", "boot", "trunk", "windscreen", "windshield"}


def _the_speakers_vehicle_by_a_part(r: _Reader) -> None:
    """'I pulled off to go straight across, and a pickup ... missed the rear of the bus': in a first-person account
    whose vehicle is named nowhere else, a vehicle first said with 'the' as the one whose part was met, and no
    other of its kind, is the speaker's own (not 'in front of the shuttle', a place)."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is None or ego.head not in SPEAKING_SELF or ego.aliases - SPEAKING_SELF or ego.type != "car":
        return
    for e in list(r.entities):
        k = e.said_at
        if e.is_ego or not e.definite or e.count != 1 or e.type not in V.EGO_TYPES or e.label or k < 3 or \
                [t.word for t in r.tokens[k - 2:k]] != ["of", "the"] or r.tokens[k - 3].word not in MET_PARTS or \
                r.tokens[k - 4].word == "in" or \
                any(x is not e and not x.is_ego and x.type == e.type for x in r.entities):
            continue
        ego.type = e.type
        ego.aliases.add(e.head)
        _taken_over(r, e, ego)
        r.notes.append(f"read 'the {e.head}' whose {r.tokens[k - 3].word} was met as the speaker's own")
        return


LEARNERS = {"pupil", "learner", "student", "trainee", "apprentice"}
DRIVING_LESSON = {"lesson", "lessons", "instructor", "mirrors", "handbrake", "manoeuvres", "maneuvers", "clutch",
                  "gears", "accelerator", "steering"}  # a lesson, or controls only the one at the wheel uses
VEHICLE_MANOEUVRES = {"turn", "turn_left", "turn_right", "u_turn", "lane_change", "lane_left", "lane_right", "cut_in"}


def _the_learner_at_the_wheel(r: _Reader) -> None:
    """'Stop 1: Pupil turns left at the T-junction', 'Pupil goes straight across': a learner who turns, changes lane
    or goes straight, or who does anything but walk in a driving lesson ('Pupil approaches on amber, then stops'),
    is at the wheel of the vehicle the scene is told from, the ego, not on foot."""
    lesson = bool({t.word for t in r.tokens} & DRIVING_LESSON) or any(
        a.word in ("the", "her", "his", "their") and b.word in ("brake", "brakes", "gas", "throttle")
        for a, b in zip(r.tokens, r.tokens[1:]))  # "Pupil covers the brake and creeps past": the pedals
    for e in list(r.entities):
        if e.is_ego or e.type != "pedestrian" or e.count != 1 or e.head not in LEARNERS or not (
                any(a[4] in VEHICLE_MANOEUVRES | {"go_straight"} for a in e.actions) or lesson and e.actions and
                not any(a[4] in ("cross", "walk") for a in e.actions) and
                not e.features & {"on_sidewalk", "crosswalk"}):
            continue
        ego = _ego_entity(r, e.stage)
        turned = {a[0] for a in e.actions if a[4] in ("turn_left", "turn_right") or a[4] == "turn" and a[5]}
        ego.actions = [a for a in ego.actions if not (a[4] == "turn" and not a[5] and a[0] in turned)] + e.actions
        # ("the road she's turning into": the turn the learner was said to make, with its side)
        ego.features |= e.features - {"on_sidewalk"}
        _taken_over(r, e, ego)
        r.notes.append(f"read the {e.head} who drives as the ego")


COMING_AT_ME = (("at", "me"), ("towards", "me"), ("toward", "me"), ("up", "to", "me"), ("my", "boots"),
                ("my", "feet"), ("hit", "me"), ("clipped", "me"), ("missed", "me"))
TRAFFIC_CONTROL = (("my", "board"), ("my", "paddle"), ("stop", "go", "board"), ("stop", "slow", "bat"),
                   ("my", "stop", "go"), ("flagging",), ("my", "end"), ("to", "my", "red"), ("at", "my", "red"),
                   ("spun", "the", "board"), ("spun", "it", "to"), ("waved", "through"), ("speed", "gun"),
                   ("stop", "board"), ("the", "paddle"), ("stop", "slow"), ("go", "board"), ("my", "stop", "end"),
                   ("through", "my", "red"), ("past", "my", "red"))
# a road-works operative's words for holding and releasing traffic: the teller is on foot at the roadside


COMING_TOWARDS_ME = (("towards", "me"), ("toward", "me"), ("straight", "at", "me"), ("right", "at", "me"),
                     ("towards", "us"), ("toward", "us"))
ONTO_THE_FOOTWAY = tuple((verb, "the", way) for verb in ("mounted", "up", "along", "onto")
                         for way in ("kerb", "curb", "pavement", "sidewalk", "footway", "footpath"))
OWN_MOBILITY_AIDS = (("my", "wheelchair"), ("my", "chair"), ("my", "power", "chair"), ("my", "mobility", "scooter"),
                     ("my", "walker"), ("my", "rollator"), ("my", "walking", "frame"), ("my", "white", "cane"),
                     ("use", "a", "wheelchair"), ("use", "a", "mobility", "scooter"), ("wheelchair", "user"),
                     ("i'm", "in", "a", "wheelchair"), ("i", "am", "in", "a", "wheelchair"),
                     ("on", "a", "mobility", "scooter"), ("on", "mobility", "scooters"),
                     ("drive", "a", "mobility", "scooter"), ("my", "powerchair"), ("my", "frame"),
                     ("my", "guide", "dog"), ("my", "pram"), ("my", "stroller"), ("my", "buggy"), ("my", "pushchair"),
                     ("my", "walking", "stick"), ("my", "cane"), ("my", "crutches"), ("my", "zimmer"),
                     ("me", "in", "the", "wheelchair"), ("me", "in", "my", "wheelchair"))
MET_BY = {"towards", "toward", "past", "beside", "at", "across", "round", "around", "into", "hit", "missed", "clipped",
          "struck"}  # "came straight at me", "turned left across me", "nearly hit me": a witness in the way


WORKS_WORDS = (("roadworks",), ("road", "works"), ("night", "works"), ("taper",), ("flagger",), ("flagging",),
               ("portaflow",), ("portaflows",), ("banksman",), ("temp", "lights"), ("temporary", "lights"),
               ("stop", "go"), ("stop", "slow"), ("shuttle", "working"), ("speed", "gun"), ("portable", "signals"),
               ("portable", "lights"), ("shuttle", "lights"), ("temp", "signals"), ("temporary", "signals"))


REACTING = {"reacts", "reacted", "notices", "noticed", "hears", "heard", "sees", "saw", "spots", "spotted", "brakes",
            "braked", "applies", "applied", "takes", "took", "decides", "decided", "passes", "passed", "swerves",
            "swerved", "steers", "steered", "accelerates", "accelerated", "slows", "slowed"}  # at the controls


def _names_no_ego(r: _Reader, words: list[str]) -> bool:
    """No word names the ego, and no one speaks as a participant ('I', 'we', 'you'): a text told in the third
    person of road users none of which is said to be the one under test."""
    ego = next((e for e in r.entities if e.is_ego), None)
    return (ego is None or ego.head == "ego" and ego.said_at < 0) and \
        not any(u.category == "agents" and u.meaning == "ego" for u in r.units) and \
        not (FIRST_PERSON | {"we", "us", "our", "you", "your"}) & set(words)


def _the_one_driver_spoken_of(r: _Reader) -> None:
    """'A lorry ... comes up behind a cyclist. The lorry driver passes the cyclist', 'A car is approaching the
    crossroads ... when its driver hears the siren': a text that names no ego (a word problem, a report told in
    the third person) is told from the seat of the one driver it speaks of; that driver's vehicle is the ego."""
    words = [t.word for t in r.tokens]
    if not _names_no_ego(r, words):
        return
    vehicles = [e for e in r.entities if not e.is_ego and e.type in V.EGO_TYPES and e.count == 1 and e.parent is None
                and e.said_at >= 0]
    owners = []
    for k, w in enumerate(words):
        if w != "driver" or k == 0 or not set(words[k + 1:k + 3]) & REACTING:
            continue  # ("the Jeep driver claims", "car driver walking wounded": no one at the controls)
        before = words[k - 1]
        if before in ("its", "her", "his"):
            owner = max((e for e in vehicles if e.said_at < k), key=lambda e: e.said_at, default=None)
        elif k + 2 < len(words) and words[k + 1] == "of" and before == "the":
            owner = next((e for e in vehicles if words[k + 2] == e.head or words[k + 2] in e.aliases or
                          k + 3 < len(words) and words[k + 3] in (e.head, *e.aliases)), None)
        else:
            owner = next((e for e in vehicles if before == e.head or before in e.aliases), None)
        if owner is not None:
            owners.append(owner)
    if owners and all(o is owners[0] for o in owners):
        _now_the_ego(r, owners[0], "the one driver the text speaks of drives it")


def _works_report(r: _Reader) -> None:
    """'Night works on the M1, right lane closed. Car in the left lane was sitting level with a semi ...', 'Temp
    lights on red and a Micra pulled up at the stop line': a report from road works, by staff who name no one
    at a wheel, is told about the first vehicle it names: the ego."""
    words = [t.word for t in r.tokens]
    if not _says_any(words, WORKS_WORDS) or {"driving", "drove"} & set(words) or \
            not (_names_no_ego(r, words) or _only_the_controls_are_mine(r, words)):
        return  # (a teller who says "I" or "my" is read as a witness: _witness_on_foot)
    first = min((e for e in r.entities if not e.is_ego and e.type in V.EGO_TYPES and e.count == 1 and
                 e.parent is None and e.said_at >= 0), key=lambda e: e.said_at, default=None)
    if first is not None and first.road_type != "shoulder" and "parked" not in first.features:  # (a works lorry
        # parked on the shoulder is the scene the ego passes)
        _now_the_ego(r, first, "a report from road works is told about the first vehicle it names")


def _only_the_controls_are_mine(r: _Reader, words: list[str]) -> bool:
    """'Temp lights on red my side', 'my end of the shuttle': staff who say 'my' only of the signals they work
    name no one at a wheel."""
    mine = [k for k, w in enumerate(words) if w in SPEAKING_SELF | {"you", "your"}]
    return bool(mine) and not any(e.is_ego for e in r.entities) and \
        all(words[k] == "my" and words[k + 1:k + 2] in (["side"], ["end"], ["red"], ["board"], ["lights"])
            for k in mine)


ONCOMING_IN_THE_WORKS = (("towards", "him"), ("towards", "her"), ("toward", "him"), ("toward", "her"),
                         ("the", "other", "end"), ("the", "opposite", "way"), ("his", "way"), ("her", "way"),
                         ("coming", "at", "him"), ("coming", "at", "her"))
CREW_WORDS = WORKS_WORDS + (("closure",), ("closures",), ("coned",), ("cones",), ("stop", "board"),
                           ("crash", "cushion"), ("ipv",), ("works",), ("operatives",), ("operative",))
STANDING_ACTIONS = {"stop", "block"}


def _the_crews_own_stands(r: _Reader) -> None:
    """'Our crash cushion truck was parked at the start of the closure and a lorry in lane 1 went into the back of
    it', 'our arrow board truck parked at the head of the taper; a semi in the right lane started merging left': a
    works crew's own lorry, standing where the crew work (or, when a driver is held at the crew's signals, coming
    through the works), is the scene the report is about a driver meeting; that driver's vehicle is the ego (a
    patrol's own car stays theirs)."""
    words = [t.word for t in r.tokens]
    ego = next((e for e in r.entities if e.is_ego), None)
    held = _says_any(words, TRAFFIC_CONTROL)  # "Grey Mercedes came up to my red ... while our tipper lorry was
    # heading towards him": the one held at the crew's signal is met by their lorry, moving or not
    if ego is None or not _says_any(words, CREW_WORDS) or {"driving", "drove", "drive", "drives"} & set(words) or \
            any(a[4] not in STANDING_ACTIONS for a in ego.actions) and not held or ego.type != "truck" or not any(
                t.base in {n.split()[-1] for n in ego.aliases | {ego.head}} and
                {"our", "my"} & set(words[max(0, t.index - 4):t.index])
                for t in r.tokens):
        return
    met = next((e for e in sorted(r.entities, key=lambda e: e.said_at) if not e.is_ego and e.count == 1 and
                e.parent is None and e.type in V.EGO_TYPES and "parked" not in e.features and
                any(a[4] in OWN_WAY or a[4] == "stop" for a in e.actions)), None)
    if met is None:
        return
    ego.is_ego = False
    ego.features = {"parked"} if not ego.actions else set()
    if _says_any(words, ONCOMING_IN_THE_WORKS):
        ego.features.add("road_straight")  # "heading towards him from the other end": through the works his way
    elif met.relative_to is ego and met.relative_how:
        ego.features.add(SEEN_THE_OTHER_WAY.get(met.relative_how, "ahead"))  # "a Polo had to stop behind it"
    else:
        ego.features.add("ahead")  # the crew's vehicle stands where the driver is going
    met.relative_to = None
    ego.stage = met.stage
    _the_ego_now(r, met)
    r.notes.append(f"read the {met.head} as the ego: a works crew's own vehicle is where the driver met it")


CROSSINGS = (("zebra",), ("crosswalk",), ("pelican",), ("puffin",), ("toucan",), ("the", "crossing"))
ON_THE_WAY_OVER = {"across", "crossing", "crossed", "cross", "over", "halfway"}


def _on_the_way_over(tokens: list[Token]) -> bool:
    """'waved me and my guide dog across', 'while I crossed', 'as we were halfway across the side road': the
    teller (or the teller's party) on the way over, said within a few words of naming them."""
    return any(t.word in SPEAKING_SELF and any(
        u.word in ON_THE_WAY_OVER and u.sentence == t.sentence for u in tokens[t.index + 1:t.index + 7])
        for t in tokens)


def _the_teller_on_foot(r: _Reader, teller: Entity, vehicle: Entity, features: set[str], action: str,
                        note: str) -> None:
    """The teller, read at first as the ego, is on foot where the vehicle met them; that vehicle is the ego."""
    teller.is_ego, teller.type, teller.road_type = False, "pedestrian", None
    teller.features = features
    teller.actions = [(0, 2, ACTION_RANK[action], r.tick(), action, None)]
    _the_ego_now(r, vehicle)
    r.notes.append(note)


def _only_looks_on(r: _Reader, ego: Entity, text: list[str]) -> bool:
    """'I watched as a double-decker bus swung right into Wharf Lane', 'I saw a white van run the red': a teller who
    does nothing but see, who is at no wheel and by whom no one is placed (not 'the car in front of me'), looks on."""
    pairs = {" ".join(text[k:k + n]) for n in (1, 2) for k in range(len(text))}
    return not ego.actions and not pairs & AT_THE_WHEEL and not {"me", "my", "us", "our", "we"} & set(text) and any(
        w == "i" and text[k + 1:k + 2] and text[k + 1] in PERCEIVING for k, w in enumerate(text))


def _witness_on_foot(r: _Reader) -> None:
    """'I was standing on the footway when I saw a van ...': a witness on foot is a pedestrian at the roadside,
    and the vehicle the statement is about (the first that moves) is the ego."""
    ego = next((e for e in r.entities if e.is_ego), None)
    text = [t.word for t in r.tokens]
    told_by_me = ego is not None and (ego.head in SPEAKING_SELF or ego.head == "ego" and "ego" not in text and any(
        w in SPEAKING_SELF for w in text))  # ("Sitting at the bus stop ..., I watched": the teller, first as a
    # participle's subject; "we were on the zebra": the teller and company)
    on_a_scooter = ego is not None and ego.type == "motorcycle" and _says_any(text, (("my", "scooter"),
                                                                                  ("on", "the", "scooter")))
    aboard_on_a_crossing = on_a_scooter and _says_any(text, CROSSINGS) and (
        _on_the_way_over(r.tokens) or _says_any(text, (("halfway",), ("green", "man"), ("going", "over"))))
    told_by_me = told_by_me or aboard_on_a_crossing  # "There I was on my scooter, about halfway across the zebra":
    # a mobility scooter, its rider on foot
    if not told_by_me or ego.type != "car" and not on_a_scooter:
        return  # ("I am a bus driver ... moving off from the bus stop": at the wheel of the bus)
    said = [_what_i_was(r.tokens, k) for k, t in enumerate(r.tokens) if t.word in ("i", "i'm", "we")] + \
        [_what_i_was(r.tokens, k, k) for k, t in enumerate(r.tokens) if (t.word in OPENING_ON_FOOT or t.word in (
            "on", "whilst", "while") and "foot" in [u.word for u in r.tokens[k + 1:k + 3]]) and
         _opens_its_sentence(r.tokens, t)]  # "Sitting at the bus stop ..., I watched a car",
    # "From the bench outside the chemist's I watched", "Whilst on foot at the taxi rank, I saw"
    words = set().union(*said) if said else set()
    if _says_any(text, OWN_MOBILITY_AIDS) or aboard_on_a_crossing:
        words.add("wheelchair")  # "the driver only saw my wheelchair at the last second": the teller is on foot
        words.discard("in my")  # ("while I was crossing the end of it in my powerchair": sat in it, on foot)
        if _on_the_way_over(r.tokens) or not words & (FOOTWAYS | {"bus stop"}) and _says_any(text, CROSSINGS):
            words.add("crossing")  # "waved me and my guide dog across", "a taxi sat right across the pelican
            # crossing ..., so I had to shuffle round its front bumper": on the way over
    if words & {"standing water", "standing traffic", "standing queue"}:
        words -= {"standing"}  # "I hit standing water": what stood, not the witness
    if words & {"stood still", "stand still", "standing still"}:
        words -= {"stood", "standing"}  # "a give-way sign for me, so I stood still": halted, on foot only if said
    patrol = _speaker_on_the_crossing(r.tokens, strong=any(a[4] not in ("walk", "cross") for a in ego.actions))
    # (one said only to walk or cross does nothing at a wheel)
    controlling = not words & {"driving", "drove", "my car", "my van", "my vehicle", "in my"} and \
        _says_any(text, TRAFFIC_CONTROL)
    if controlling:  # "The number 7 bus was stopped at my board ... When I spun it to GO the bus pulled off"
        words = (words - AT_THE_WHEEL) | {"standing"}
    if _only_looks_on(r, ego, text):
        words.add("a pedestrian")  # "I watched as a double-decker swung right into Wharf Lane": an onlooker
    if words & {"going over", "going across"} and _says_any(text, CROSSINGS + (("green", "man"),)):
        words |= {"crossing", "on the crossing"}  # "Green man at the pedestrian lights. I'm going over and a car
        # turns right"
    if not patrol and (not words & ON_FOOT or words & AT_THE_WHEEL) or \
            on_a_scooter and not words & (CROSSING_ON_FOOT | FOOTWAYS):
        return  # ("halfway over the zebra crossing on my scooter", "on my scooter on the pavement": a mobility
        # scooter, on the way over or on the footway)
    own = [t for t in r.tokens if t.word in ("i", "i'm", "me", "my", "us", "we")]
    far_side = words & {"was across the street", "was across the road"}  # on the other side, watching
    crossing = bool(words & CROSSING_ON_FOOT) and not patrol and not far_side  # "I was halfway over the zebra in my
    # chair"
    movers = [e for e in r.entities if not e.is_ego and e.type in V.EGO_TYPES and e.count == 1 and e.parent is None
              and any(a[4] not in ("stop", "try") or patrol or crossing or controlling for a in e.actions)]
    # (those held at a works board are the scene as much as those that go; "a van stops for
    if not movers and "a pedestrian" in words:  # us": the one met at the crossing)
        movers = [e for e in r.entities if not e.is_ego and e.type in V.EGO_TYPES and e.count == 1 and
                  e.parent is None and _stops_to_let_by(r, e)]  # "From the pavement I saw a silver car stop to let
        # a jogger cross": an onlooker's account of the one that gave way
    if not movers:
        return
    if crossing:
        subject = movers[0]  # "... when a silver hatchback pulled up and waited for me": the one met on the way over
        at_a_crossing = bool(words & {"crosswalk", "zebra", "pelican", "puffin", "toucan", "the crossing", "green man",
                                      "walk signal"})
        froze = any(a[4] == "stop" for a in ego.actions) and any(t.word in ("froze", "frozen") for t in r.tokens) \
            or bool(words & {"waiting", "waited"})  # "I was on the zebra ... and I just froze in the middle",
        # "I was stuck waiting there on my mobility scooter"
        _the_teller_on_foot(r, ego, subject, {"crosswalk"} if at_a_crossing else {"ahead"},
                            "stop" if froze else "cross",
                            f"inferred: the teller was crossing on foot; the '{subject.head}' that met them is the ego")
        if not any(e.type == "pedestrian" and e is not ego for e in r.entities):  # (company named on its own)
            _with_the_tellers_party(r, ego, _the_tellers_party(text))  # "we were on the zebra when a silver Audi
            # drove straight through": the teller's party, each on the way over
        return
    if patrol:
        subject = movers[0]
        waits = any(t.word in ("stood", "standing", "waiting", "waited") and r.tokens[k - 1].word in ("me", "i", "was")
                    for k, t in enumerate(r.tokens) if k)  # "with me stood on the kerb": waiting to cross
        _the_teller_on_foot(r, ego, subject, {"crosswalk"}, "stop" if waits else "cross",
                            f"inferred: the speaker sees people over a crossing, on foot; the '{subject.head}' that "
                            "meets them is the ego")
        return
    subject = movers[0]
    for e in [e for e in r.entities if not e.is_ego and e.head == "vehicle" and not e.actions and e is not subject]:
        r.entities.remove(e)  # "ahead of the vehicle concerned": the one the statement is about
    first_sentence = [t.word for t in r.tokens if t.sentence == next(t.sentence for t in own)]
    coming = _says_any(text, COMING_TOWARDS_ME) and _says_any(text, ONTO_THE_FOOTWAY)  # "a white Transit mounted
    # the kerb and came towards me": the teller is ahead of it on the footway it drives along, on no side unless one is
    # said (one the vehicle travels towards along the road stands beside its way)
    side = "side_right" if "right" in first_sentence else "side_left" if not coming or {
        "left", "nearside", "offside", "side"} & set(first_sentence) else None
    place = "ahead" if "ahead" in first_sentence or coming else "behind" if "behind" in first_sentence else None
    placed = not controlling and (place is not None or any(
        text[k + 1:k + 2] == ["me"] and w in MET_BY or
        text[k:k + 4] == ["in", "front", "of", "me"] for k, w in enumerate(text)))  # (one at a works board: no one,
    # unless the driver comes at them: "carried on past the board and came straight at me", "rolled right up to me")
    in_the_way = controlling and _says_any(text, COMING_AT_ME)
    if in_the_way:
        _the_teller_on_foot(r, ego, subject, {"ahead", "in_road"}, "stop",
                            f"inferred: the teller works the traffic on foot, in the way of the '{subject.head}', the "
                            "ego")
        return
    if placed:
        ego.is_ego, ego.type, ego.actions = False, "pedestrian", []
        ego.features = {"on_sidewalk"} | ({side} if side else {"met_head_on"}) | ({place} if place else set())
    else:  # "I was waiting at the bus stop ... a red hatchback turned left": an onlooker, in no one's way
        r.entities.remove(ego)
    _the_ego_now(r, subject)
    r.notes.append(f"inferred: the witness is on foot{'' if placed else ', placed by no one (no agent)'}; the "
                   f"'{subject.head}' the statement is about is the ego")


PEDAL_WORDS = {"bicycle", "pedalling", "pedaling", "pedalled", "pedaled", "handlebar", "handlebars", "pushbike",
               "toucan", "cycling", "cycled", "pannier", "panniers", "doored", "dooring", "chaingang", "cycleway",
               "peloton", "cleats"}  # (not "a brake pedal")
PEDAL_PHRASES = (("close", "pass"), ("helmet", "cam"), ("i", "was", "cycling"), ("i", "cycle"), ("cycle", "commuter"),
                 ("my", "bicycle"), ("in", "the", "cycle", "lane"), ("in", "the", "bike", "lane"),
                 ("i'm", "a", "cyclist"), ("i", "am", "a", "cyclist"), ("i'm", "a", "cycle"), ("my", "arm", "out"),
                 ("child", "seat", "on", "the", "back"), ("cycle", "lane"), ("bike", "lane"), ("cycle", "track"),
                 ("bike", "path"), ("advanced", "stop", "box"), ("my", "bell"), ("front", "and", "rear", "lights"),
                 ("my", "front", "wheel"), ("my", "back", "wheel"), ("in", "primary"), ("primary", "position"),
                 ("two", "abreast"), ("club", "run"), ("club", "ride"), ("group", "ride"), ("ride", "leader"),
                 ("back", "marker"), ("bar", "end"), ("my", "elbow"), ("my", "right", "elbow"), ("my", "left", "elbow"),
                 ("my", "pedal"), ("into", "the", "gutter"), ("knocked", "me", "off"), ("took", "me", "off"),
                 ("riding", "single", "file"), ("riding", "in", "single", "file"), ("ride", "captain"),
                 ("training", "ride"), ("social", "ride"), ("club", "training"), ("sunday", "social"),
                 ("saturday", "social"), ("my", "bars"), ("bike", "commuter"), ("taking", "the", "lane"),
                 ("take", "the", "lane"), ("took", "the", "lane"), ("hand", "out"), ("kid", "on", "the", "back"),
                 ("child", "seat"), ("lit", "up", "front", "and", "back"), ("lights", "on", "front", "and", "rear"),
                 ("front", "and", "back", "lights"), ("lights", "front", "and", "rear"),
                 ("pedalling", "across"), ("pedaling", "across"))
# (not "the cycle courier was banned"; "I was riding" and "my bike" are a motorcyclist's words too)
MOTOR_WORDS = {"motorbike", "motorcycle", "moped", "scooter", "motorcyclist", "biker"}
REPORTING_WORDS = {"reporting", "report", "complaint", "file"}
SEEN_THE_OTHER_WAY = {"ahead": "behind", "behind": "ahead", "side_left": "side_right", "side_right": "side_left",
                      "front_left": "back_right", "back_right": "front_left", "front_right": "back_left",
                      "back_left": "front_right", "from_left": "from_right", "from_right": "from_left",
                      "road_left": "road_right", "road_right": "road_left", "road_straight": "road_straight",
                      "oncoming": "oncoming", "level": "level"}


PASSING_ME = {"overtook", "overtakes", "overtaking", "passed", "passes", "passing", "buzzed", "squeezed", "cut",
              "cuts", "clipped", "hit", "missed", "doored", "alongside"}  # what a driver does to a rider it meets


CLEARANCES = (("inches",), ("inch",), ("a", "foot"), ("a", "hand's", "width"), ("cm",), ("half", "a", "metre"),
              ("half", "a", "meter"), ("to", "spare"), ("barely", "any", "room"), ("hardly", "any", "room"),
              ("barely", "any", "gap"), ("hardly", "any", "gap"), ("no", "room"), ("a", "whisker"),
              ("had", "me", "off"), ("into", "the", "verge"), ("into", "the", "gutter"), ("off", "my", "shoulder"),
              ("off", "my", "elbow"), ("of", "clearance"))
PASSED = {"overtook", "overtaking", "passed", "passing", "buzzed", "squeezed", "past"}


def _passed_too_close(r: _Reader) -> int | None:
    """'A grey BMW overtook me leaving about a hand's width', 'came past me with literally inches to spare', 'passed
    me ... close enough that the spray nearly had me off': a close pass, told by the one passed, who rides (a
    driver passed is not measured in inches); the sentence it is told in, or None."""
    words = [t.word for t in r.tokens]
    for k, w in enumerate(words):
        if w in PASSED and words[k + 1:k + 2] in (["me"], ["us"]):
            sentence = [t.word for t in r.tokens if t.sentence == r.tokens[k].sentence]
            if _says_any(sentence, CLEARANCES):
                return r.tokens[k].sentence
    return None


def _the_close_passer(r: _Reader, sentence: int | None) -> Entity | None:
    """'A red Toyota was right behind the ambulance and just tore past me with less than a foot to spare': the
    vehicle a close pass is told of (in `sentence`, from _passed_too_close) is the first named in its sentence,
    wherever it is placed."""
    return None if sentence is None else next(
        (e for e in sorted(r.entities, key=lambda e: e.said_at) if not e.is_ego and e.said_at >= 0 and
         e.type in V.EGO_TYPES - V.VULNERABLE_TYPES and e.count == 1 and e.parent is None and
         r.tokens[e.said_at].sentence == sentence and any(a[4] not in ("stop", "try") for a in e.actions)), None)


def _the_teller_rides(r: _Reader) -> bool:
    """'I was riding', 'we were riding', 'I had to ride into the gutter', 'Riding west into the sun when ...': the
    teller rides (not 'a pickup was riding my bumper', 'a boda boda was riding on the shoulder')."""
    words = [t.word for t in r.tokens]
    return any(w in RIDING and (
        words[k - 1:k] in (["i"], ["we"], ["i'm"], ["we're"]) or words[max(0, k - 2):k] in (
            ["i", "was"], ["we", "were"], ["i", "am"], ["we", "are"]) or words[max(0, k - 3):k] == ["i", "had", "to"]
        or w == "riding" and _opens_its_sentence(r.tokens, r.tokens[k]) and bool(set(words) & FIRST_PERSON))
        for k, w in enumerate(words))


def _rider_reporting_a_driver(r: _Reader) -> None:
    """'I was riding in the middle of the lane when a silver hatchback came up behind me and overtook with half a
    metre to spare': a cyclist's report of a driver is told from the vehicle reported, the ego; the teller is a
    cyclist (also as 'you' to whom a call's operator speaks), placed from there as the vehicle was placed from the
    teller (behind me: the cyclist ahead)."""
    ego = next((e for e in r.entities if e.is_ego), None)
    words = [t.word for t in r.tokens]
    own_bikes = [e for e in r.entities if e.type == "cyclist" and not e.is_ego and e.said_at > 1 and (
                 r.tokens[e.said_at - 1].word in ("my", "our") or [t.word for t in r.tokens[e.said_at - 2:e.said_at]]
                 in (["off", "the"], ["on", "the"])) and e.head in ("bicycle", "bike", "pushbike", "cycle", "push bike")]
    # ("the draught nearly pulled me off the bike": the teller's own)
    reported_riding = set(words) & {"riding", "rode"} and set(words) & REPORTING_WORDS  # "I'm reporting a police
    # patrol car ... it overtook me ... while I was riding past a line of parked cars": a rider's report of a driver
    met = any(w in MET_BY | PASSING_ME and words[k + 1:k + 2] in (["me"], ["us"], ["my"]) or
              words[k:k + 4] == ["in", "front", "of", "my"] for k, w in enumerate(words))
    # ("swung left directly in front of my bike", "turns left across my line")
    met = met or _says_any(words, PEDAL_PHRASES) and bool(set(words) & (PASSING_ME | {"past"}))  # "sat off my back
    # wheel, then flew past with inches to spare": passed, the rider said by the bike
    close_pass = _passed_too_close(r)
    plain = _says_any(words, PEDAL_PHRASES) or close_pass is not None or _the_teller_rides(r) and met
    # ("Riding west into the low sun when a Corsa ... turned right across me", "came up behind me in the cycle lane";
    # not "Riding along a street, a taxi ahead of me stopped, so I went round it": the teller's own ride, no one met)
    own_motor = any(w in MOTOR_WORDS and set(words[max(0, k - 3):k]) & {"my", "our", "e", "on", "riding"}
                    for k, w in enumerate(words))  # "on my e-scooter", "riding the lime scooter", "on a Bird scooter"
    # (also "the guy on the moped", which leaves the teller as before: at a wheel)
    pedalled = _pedalled(words)
    motor = (set(words) & MOTOR_WORDS or set(words) & FILTERING and not pedalled) and (own_motor or not (plain and any(
        e.type == "motorcycle" and not e.is_ego for e in r.entities)))  # (not "a moped rider squeezed past me")
    on_a_bike = (set(words) & PEDAL_WORDS or plain or reported_riding or own_bikes) and not motor and \
        not _says_any(words, (("my", "car"), ("i", "was", "driving"), ("i", "drove"), ("my", "van")) + RIDERS_CONTROLS)
    others_ride = any(e.type == "cyclist" and not e.is_ego and e not in own_bikes for e in r.entities)
    if ego is not None and ego.type in V.EGO_TYPES and ego.head not in FIRST_PERSON and not _supplied(r, ego) and \
            on_a_bike and met and not others_ride and not any(e.head in SPEAKING_SELF for e in r.entities):
        _the_teller_rides_by(r, ego, own_bikes)
        return
    reported = [e for e in r.entities if e.type in V.EGO_TYPES - V.VULNERABLE_TYPES and e.count == 1 and
                e.parent is None and not e.generic]
    if ego is None and on_a_bike and met and not others_ride and len(reported) == 1:
        _the_teller_rides_by(r, reported[0], own_bikes)  # "a pickup sat off my back wheel, then flew past": the
        _the_ego_now(r, reported[0])  # rider said only by the bike, met by the one vehicle named
        return
    if ego is None or ego.head not in SPEAKING_SELF and not _supplied(r, ego) or \
            ego.type not in ("car", "motorcycle") or ego.aliases - SPEAKING_SELF - {"you"} - BICYCLES or not on_a_bike or \
            others_ride:
        return
    for e in own_bikes:  # "I was riding my bicycle northbound", "I was on my bicycle on the roundabout, going
        r.entities.remove(e)  # straight over": the teller's own bicycle, no one else, and what it did the teller did
        ego.actions += e.actions
        ego.features |= e.features
    vehicles = [e for e in r.entities if not e.is_ego and e.type in V.EGO_TYPES - V.VULNERABLE_TYPES and
                e.count == 1 and e.parent is None and e.relative_to is None]
    movers = [e for e in vehicles if any(a[4] not in ("stop", "try") for a in e.actions)] or vehicles[:1] * (
        len(vehicles) == 1 and any(a[4] == "stop" for a in vehicles[0].actions))  # ("a delivery van parked right
    # across the cycle lane": the one vehicle, standing)
    if not movers:
        return
    subject = _the_one_reported(r, vehicles) or _the_close_passer(r, close_pass) or movers[0]
    own = ego.features & set(SEEN_THE_OTHER_WAY)
    if _says_any(words, (("i", "was", "crossing"), ("i", "crossed"), ("toucan",))):
        own = {"crosswalk"}  # "I was crossing at the toucan crossing when a BMW ran the red": on the crossing
        ego.actions = [(0, 2, ACTION_RANK["cross"], r.tick(), "cross", None)]
    ego.is_ego, ego.type = False, "cyclist"
    ego.actions = [a[:2] + (ACTION_RANK["move"], a[3], "move") + a[5:]
                   if a[4] in ("lane_change", "lane_left", "lane_right", "cut_in") else a for a in ego.actions]
    # ("I was passing along his right-hand side", "I had to swerve out round it": the rider keeps to its road)
    standing = not any(a[4] not in ("stop", "try") for a in subject.actions)
    seen = {f"road_{f[5:]}" if f.startswith("side_") and "cross_road" in subject.features else f
            for f in subject.features}  # "emerged from Catharine Street on my left": out of the road on my left
    ego.features = (ego.features - own) | (own or {SEEN_THE_OTHER_WAY[f] for f in seen
                                                   if f in SEEN_THE_OTHER_WAY}) or ego.features | {
        "behind" if standing else "ahead"}  # ("a delivery van parked right across the cycle lane": come up to)
    hook = next((a[4][5:] for a in subject.actions if a[4] in ("turn_left", "turn_right")), None)
    if hook and _says_any(words, LEVEL_WITH_THE_TURNER) and _says_any(words, ACROSS_THE_RIDER):
        ego.features = (ego.features - set(SEEN_THE_OTHER_WAY) - {"ahead", "behind"}) | {f"side_{hook}", "level"}
        ego.actions = [a for a in ego.actions if a[4] not in ("turn_left", "turn_right")] or [
            (ego.stage, 1, ACTION_RANK["move"], r.tick(), "move", None)]  # "turned left straight across me while I
        # was level with its cab": hooked from beside it, on that side, going on
    _the_ego_now(r, subject)  # ("a taxi waiting behind him": behind the ego now)
    riders = _the_tellers_party(words)
    _with_the_tellers_party(r, ego, riders)  # "we were riding two abreast", "three of us"
    r.notes.append(f"inferred: the teller rides a bicycle{f' (a party of {riders})' if riders > 1 else ''}; the "
                   f"'{subject.head}' reported is the ego")


REPORTED_BY = {"reporting", "report", "about", "complain", "complaining", "complaint"}


def _the_one_reported(r: _Reader, vehicles: list[Entity]) -> Entity | None:
    """'Reporting a white Transit ...', 'this report is about a police car': the vehicle the report names as its
    subject, whatever else moves in it."""
    for e in vehicles:
        before = [t.word for t in r.tokens[max(0, e.said_at - 5):e.said_at]
                  if t.sentence == r.tokens[e.said_at].sentence]
        if set(before) & REPORTED_BY:
            return e
    return None


BICYCLES = {"bike", "bicycle", "pushbike", "push bike", "cycle"}  # the teller's own, read first as a motorbike
LEVEL_WITH_THE_TURNER = (("alongside",), ("level", "with"), ("next", "to"), ("beside",), ("on", "his", "inside"),
                         ("on", "her", "inside"), ("on", "its", "inside"), ("up", "the", "inside"))
ACROSS_THE_RIDER = (("across", "me"), ("across", "my"), ("across", "the", "bike", "lane"), ("across", "the", "cycle"),
                    ("left", "hook"), ("right", "hook"), ("left", "hooked"), ("right", "hooked"))
PARTY_SIZES = range(2, 13)  # a party counted as a party (not "two of us out of forty")


def _party_count(word: str) -> int | None:
    """'eight', '8': the size a teller gives their party, or None."""
    said = lexicon().phrases.get((word,))
    n = read_number(word) if said is None or said[0] != "numbers" else float(said[1])
    return int(n) if n is not None and n in PARTY_SIZES else None
COMPANIONS = {"partner", "buddy", "mate", "friend", "wife", "husband", "son", "daughter", "girlfriend", "boyfriend",
              "brother", "sister", "dad", "mum", "mom", "pal"}


def _the_tellers_party(words: list[str]) -> int:
    """How many go with the teller, the teller counted: 'three of us', 'our group of four', 'two abreast', 'with my
    partner', 'both of us'; a 'we' with no count is two."""
    for k, w in enumerate(words):
        n = _party_count(w)
        if not n:
            continue
        after = words[k + 1:k + 6]
        said_in_total = after[:1] in (["riders"], ["cyclists"]) and _says_any(
            after, (("in", "total"), ("me", "included"), ("including", "me")))
        if after[:2] == ["of", "us"] or words[k - 2:k] in (["group", "of"], ["ride", "of"], ["run", "of"]) or \
                after[:1] == ["abreast"] or after[:2] == ["in", "total"] or said_in_total:
            return n  # "our group of seven", "club ride of nine", "5 riders in total", "six riders (me included)"
        if words[k - 1:k] == ["my"] and k >= 2 and words[k - 2] in ("walking", "taking", "with"):
            return n + 1  # "walking my two to school": the teller and two more
        if words[k - 1:k] in (["leading"], ["with"]) and {"riders", "cyclists"} & set(after[:3]):
            return n + 1  # "leading a ride with four new riders behind me": the leader and four more
    if _says_any(words, (("both", "of", "us"),)) or any(w in COMPANIONS and words[k - 1:k] == ["my"] and
                                                        "with" in words[max(0, k - 3):k] for k, w in enumerate(words)):
        return 2
    return 2 if {"we", "us", "our"} & set(words) and not {"i", "me", "my"} & set(words) else 1


def _with_the_tellers_party(r: _Reader, teller: Entity, party: int) -> None:
    """The others of a teller's party of `party`, each where the teller is, doing what the teller does."""
    for _ in range(party - 1):
        r.entities.append(replace(teller, key=r.new_key(), features=set(teller.features), actions=list(teller.actions)))


def _the_teller_rides_by(r: _Reader, ego: Entity, own_bikes: list[Entity]) -> None:
    """'Riding along the cycle lane ... a tipper lorry comes alongside me then swings left': the vehicle the rider
    reports was read as the ego with the rider said of no noun; the rider is a cyclist, where the vehicle was placed
    from it (ahead of one that comes up and past)."""
    for e in own_bikes:
        r.entities.remove(e)
    features = {SEEN_THE_OTHER_WAY[f] for f in ego.features if f in SEEN_THE_OTHER_WAY} or {"ahead"}
    r.entities.append(Entity(r.new_key(), "cyclist", False, ego.stage, head="i", features=features,
                             actions=[(ego.stage, 1, ACTION_RANK["move"], r.tick(), "move", None)]))
    r.notes.append(f"inferred: the teller rides a bicycle, met by the '{ego.head}' reported, the ego")


def _named_as_the_ego(r: _Reader) -> None:
    """'a blue hatchback northbound on Main, that's our ego', 'The black pickup on Elm is our ego', 'Our ego, a green
    hatchback, ...', 'Ego for this one is the white van': a vehicle the text names as the ego is the ego, and the
    ego said by that name is that vehicle."""
    words = [t.word for t in r.tokens]
    ego = next((e for e in r.entities if e.is_ego), None)
    for k, w in enumerate(words):
        if w != "ego" or ego is None:
            continue
        sentence = r.tokens[k].sentence
        lead = k - (k > 0 and words[k - 1] in ("our", "the"))
        opens = lead == 0 or r.tokens[lead - 1].sentence != sentence  # "Our ego, a ..." (not "Behind the ego, a ...")
        in_sentence = [e for e in r.entities if not e.is_ego and e.count == 1 and e.type in V.EGO_TYPES and
                       e.type not in V.VULNERABLE_TYPES - {"motorcycle"} and e.said_at >= 0 and
                       r.tokens[e.said_at].sentence == sentence]
        named = None
        if k > 1 and words[k - 1] in ("our", "the") and words[k - 2] == "is":
            named = next((e for e in reversed(in_sentence) if e.said_at < k), None)  # "..., that's our ego"
        elif opens and (words[k - 1:k + 3] in (["our", "ego", ",", "a"], ["our", "ego", ",", "an"]) or
                        words[k + 1:k + 5] == ["for", "this", "one", "is"]):  # (not "ego, a bus behind": a list)
            named = next((e for e in in_sentence if k < e.said_at <= k + 8 and "," not in words[k + 2:e.said_at]),
                         None)  # "Our ego, a green hatchback" (not "Our ego, a bus, stops behind a truck": the bus
            # was read as the ego's kind, and the truck is another)
        if named is not None:
            _now_the_ego(r, named, "the text names it so")
            return


def _now_the_ego(r: _Reader, vehicle: Entity, why: str) -> None:
    """A vehicle found to be the ego takes over the ego said so far: what it did, the lane it is in, whoever was
    placed by it."""
    ego = next((e for e in r.entities if e.is_ego), None)
    lane = next((side for side in SIDES if f"side_{side}" in vehicle.features and "lane_said" in vehicle.features),
                None)  # "a green hatchback in the right lane": the lane the ego is in
    kept = {"in_a_side_lane", f"in_lane_{lane}"} if lane else set()
    if ego is not None:
        vehicle.actions += [a for a in ego.actions if not any(b[0] == a[0] for b in vehicle.actions)]
        kept |= {f for f in ego.features if f.startswith("in_lane") or f == "in_a_side_lane"}
        _taken_over(r, ego, vehicle)
    _the_ego_now(r, vehicle)
    vehicle.features |= kept
    r.notes.append(f"read the {vehicle.head} as the ego: {why}")


CUSTOMER_WORDS = {"customer", "customers", "owner"}


def _a_job_card(r: _Reader) -> bool:
    """'Customer states ...': a garage's note of what its customer told."""
    words = [t.word for t in r.tokens]
    return any(w in CUSTOMER_WORDS and words[k + 1:k + 2] and words[k + 1] in ("states", "stated", "reports", "says")
               for k, w in enumerate(words))


def _the_customers_vehicle(r: _Reader) -> None:
    """'JOB CARD 20417 - 2016 VW Golf ... Customer states vehicle was stationary ...': a garage's job card opens on
    the customer's vehicle (or says 'vehicle' or 'car' of it), which the story is told from."""
    if not _a_job_card(r):
        return
    ego = next((e for e in r.entities if e.is_ego), None)
    first = min((e for e in r.entities if e.said_at >= 0), key=lambda e: e.said_at, default=None)
    if first is None or first.is_ego or first.type not in V.EGO_TYPES or first.count != 1 or \
            not (r.tokens[first.said_at].sentence == 0 or first.head == "vehicle" or
                 first.head == "car" and r.tokens[first.said_at - 1].word not in INDEFINITE) or \
            first.features - {"compass_north", "compass_south", "parked", "moves_out", "straight_on"} or \
            ego is not None and ego.head not in FIRST_PERSON | {"ego", "we", "us", "vehicle", "he", "she"}:
        return
    _now_the_ego(r, first, "a job card opens on the customer's vehicle")


def _its_own_lane(e: Entity, feature: str) -> bool:
    """'bus in the left lane', 'the shuttle in lane 2': a lane the vehicle is said to keep, which places it by no
    one else."""
    return feature in ("lane_said", "middle_lane") or feature.startswith("named_lane_") or \
        feature.startswith("side_") and f"named_lane_{feature[5:]}" in e.features


def _the_logs_own_vehicle(r: _Reader) -> None:
    """'Shuttle braked to a stop behind it', 'a taxi sat behind us ... Shuttle stopped at the stop line', 'when a
    pickup cut in front of us ... so the truck yielded': a crew's log names its own vehicle bare or as one known
    ('the truck'), opening a clause, while 'we' and 'us' are the ego; that one vehicle, placed by no one but in a
    lane of its own, is the ego's."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if not any(t.word in ("we", "us", "our") for t in r.tokens):
        return  # (a story's "Joe turned right ... The van behind him stopped": no crew telling of its vehicle)
    if ego is not None and (
            not (ego.head in ("we", "us", "i", "me", "op", "system") or _supplied(r, ego)) or ego.type != "car" or
            any(name.split()[-1] not in SELF_NAMES | {"ego", "op", "system"} for name in ego.aliases if name)):
        return  # the speakers, 'the system' driving, or an ego supplied for a verb with no subject, in no vehicle
        # of their own ("I'm rolling up in the truck" is)
    own = {"overtaking", "parked", "straight_on"}
    candidates = [
        e for e in r.entities if not e.is_ego and e.count == 1 and e.type in ("car", "bus", "truck") and
        (e.actions or any(f.startswith("named_lane_") for f in e.features)) and not e.label and
        not any(a[4] == "cut_in" and a[5] is None for a in e.actions) and not any(  # ("the car in the left lane
        # cuts in front of us"; not "moved over into the right lane", a lane named)
            x is not e and not x.is_ego and x.head == e.head for x in r.entities) and
        all(f in own or f.startswith("compass_") or _its_own_lane(e, f) for f in e.features) and
        (e.relative_to is None or e.relative_how == "behind" and not e.relative_to.is_ego) and any(
            t.word == e.head and (t.index == 0 or r.tokens[t.index - 1].sentence != t.sentence or
                                  e.definite and r.tokens[t.index - 1].word == "the" and (
                                      t.index == 1 or r.tokens[t.index - 2].sentence != t.sentence or
                                      r.tokens[t.index - 2].word in (",", "and", "so", "then", "but"))) and
            t.index + 1 < len(r.tokens) and r.tokens[t.index + 1].sentence == t.sentence and
            r.tokens[t.index + 1].word != "," and not r.tokens[t.index + 1].word.endswith("ing") and
            not any(x.word in ("behind", "beside", "alongside") for x in r.tokens[t.index + 1:t.index + 3]
                    if x.index == t.index + 1 or not r.tokens[t.index + 1].word.endswith("ed"))
            for t in r.tokens)]  # (not a commentary's "Car waiting to come out", a list's "Ego: SUV, turns right", a
    # story's "the learner driver behind him stopped": one told apart by its place; "Shuttle halted behind it" is
    # its own stop)
    if len(candidates) != 1:
        return
    vehicle = candidates[0]
    if vehicle.relative_to is not None:  # "Shuttle braked to a stop behind it": the one it stops behind is ahead
        vehicle.relative_to.features.add("ahead")
        vehicle.relative_to = None
    _now_the_ego(r, vehicle, "a crew's log names its own vehicle")


CAMERA_WORDS = {"dashcam", "dashcams", "camera", "footage", "video", "clip", "cam", "photo", "photograph", "picture"}


def _the_camera_car(r: _Reader) -> None:
    """'Footage from the hatchback's own dashcam shows ...', 'Dashcam from a grey Civic going straight across':
    a clip is told from the vehicle whose camera filmed it; with no ego named but the teller, that vehicle is the
    ego."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if any(t.word == "ego" for t in r.tokens) or ego is not None and (
            ego.head not in ("ego", "we", "us") or ego.features):
        return
    words = [t.word for t in r.tokens]
    cues = [k for k, t in enumerate(r.tokens) if t.possessive or t.word in CAMERA_WORDS]  # where a camera is named

    def filmed(e: Entity) -> bool:
        heads = {name.split()[-1] for name in e.aliases | {e.head} if name}
        if e.head == "driver" and e.said_at >= 0:  # "the driver of a blue hatchback": the hatchback's
            heads |= {x.word for x in r.tokens[e.said_at + 1:e.said_at + 6]
                      if x.sentence == r.tokens[e.said_at].sentence}
        for k in cues:
            t = r.tokens[k]
            if t.word in heads and t.possessive and (words[k + 1:k + 2] and words[k + 1] in CAMERA_WORDS or
                                                    words[k + 1:k + 3] and words[k + 1] == "own" and
                                                    words[k + 2:k + 3] and words[k + 2] in CAMERA_WORDS):
                return True  # "the hatchback's own dashcam"
            j = k + 1 if words[k + 1:k + 2] in (["taken"], ["shot"], ["filmed"]) else k  # "Photo taken from a car"
            if t.word in CAMERA_WORDS and words[j + 1:j + 2] in (["from"], ["of"]) and \
                    j + 2 <= e.said_at <= j + 5 and words[j + 2] in ("a", "an", "the"):
                return True  # "Dashcam from a grey Civic"
        return False
    filmers = [e for e in r.entities if not e.is_ego and e.count == 1 and e.type in V.EGO_TYPES and
               e.type not in V.VULNERABLE_TYPES and filmed(e)]
    if len(filmers) == 1:
        _now_the_ego(r, filmers[0], "the clip is filmed from its camera")


CYCLE_WAYS = (("cycle", "lane"), ("bike", "lane"), ("cycle", "track"), ("bike", "path"), ("bike", "box"),
              ("advanced", "stop", "box"))


def _pedalled(words: list[str]) -> bool:
    """'filtering up the inside in the cycle lane', 'pedalling past the queue': a rider who filters on a bicycle
    (not 'inches from my front wheel', said on a motorbike too)."""
    return bool(set(words) & PEDAL_WORDS) or _says_any(words, CYCLE_WAYS)


FILTERING = {"filter", "filters", "filtering", "filtered", "splitting"}  # ("Splitting on the 5 at maybe 30")
SCOOTING = {"scoot", "scoots", "scooted", "scooting"}  # ("scooted home down Station Rd": on an e-scooter)
RIDING = {"ride", "rides", "riding", "rode"} | SCOOTING


RIDERS_CONTROLS = (("front", "brake"), ("pillion",), ("cbt",), ("mod", "1"), ("mod", "2"), ("mod", "two"),
                   ("bike", "test"), ("moped", "test"), ("motorcycle", "test"), ("motorbike", "test"))
# what only one on two wheels handles ('I had to grab a handful of front brake') or sits a test on ('the road ride
# part of my CBT', 'PASSED MY MOD 2'), one on a bicycle read before (a car's driver speaks of a throttle, a visor,
# rear brakes too)


RIDERS_HANDLING = (("throttle",), ("roll", "off"), ("lead", "rider"), ("the", "bike", "goes"), ("your", "bike"),
                   ("bikes", "behind"), ("front", "brake"), ("pillion",), ("visor",), ("group", "ride"))

RIDE_HAILING = {"trip", "fare", "rating", "uber", "lyft", "rideshare", "passenger", "passengers"}


def _a_riders_ego(r: _Reader) -> None:
    """'You're filtering between two lanes of stationary traffic', 'you ease off and ride slowly towards it': an ego
    named by no vehicle that filters through traffic, or is said to ride (not in or on something), rides a
    motorbike; one on a bicycle is no ego this language has."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is not None and (ego.type != "car" or any(
            name.split()[-1] not in SELF_NAMES | {"ego", "rider"} for name in ego.aliases | {ego.head} if name)):
        return
    words = [t.word for t in r.tokens]
    said_of_the_ego = ("you", "i", "we", "you're", "i'm", "we're")
    hailed = bool(set(words) & RIDE_HAILING)  # "The rider hit his knee on the seat": the passenger of a ride hailed
    told_by_me = bool(set(words) & FIRST_PERSON)
    filters = set() if _pedalled(words) else FILTERING
    said = any(w in RIDING | filters and not (words[k + 1:k + 2] and words[k + 1] in (  # not "I ride the van"
        {"in", "on", "with", "as"} | DETERMINERS | OWNERS)) and (
        words[k - 1:k] and words[k - 1] in said_of_the_ego or words[max(0, k - 2):k] in (
            ["you", "are"], ["i", "am"], ["i", "was"], ["we", "are"], ["we", "were"], ["you", "were"]) or
        w in filters | SCOOTING | {"riding"} and _opens_its_sentence(r.tokens, r.tokens[k]) and (
            w in filters or told_by_me) or  # "Filtering past a queue", "Riding along
        # a street ..., a taxi ahead of me stopped"
        not hailed and words[k - 1:k] == ["and"] and not (words[k + 1:k + 2] and words[k + 1] in AUXILIARIES) and any(
            words[j] in said_of_the_ego and r.tokens[j].sentence == r.tokens[k].sentence
            for j in range(max(0, k - 5), k - 1)))  # "you ease off and ride slowly"
        for k, w in enumerate(words))
    if ego is None:
        if not said:
            return
        ego = _ego_entity(r, 0)  # "scooted down Park Lane after work and a minicab pulled out": the rider, said
        # by a verb the lexicon does not know
    the_rider = _supplied(r, ego) and not hailed and any(
        u.category == "word" and u.word == "rider" and k > 0 and r.units[k - 1].word == "the" and not any(
            e.type in ("cyclist", "motorcycle") and 0 <= e.said_at < u.start for e in r.entities)
        for k, u in enumerate(r.units))  # "The rider comes round a bend and finds two cyclists": the subject an ego
    # was supplied for, with no one on two wheels named before it
    geared = not hailed and told_by_me and _says_any(words, RIDERS_CONTROLS)
    instructed = not hailed and bool({"you", "you're", "your"} & set(words)) and _says_any(words, RIDERS_HANDLING)
    # "back off the throttle", "the bike goes round a left bend", "you're lead rider": said to one on a motorbike
    if said or the_rider or geared or instructed or ego.head == "rider":
        ego.type = "motorcycle"



def _at_no_named_wheel(r: _Reader, ego: Entity | None) -> bool:
    """An ego read as a car only because it is the teller ('I', 'we') or was supplied for a verb with no subject:
    what the teller rides may still be told."""
    return ego is not None and ego.type == "car" and (ego.head in SELF_NAMES or _supplied(r, ego)) and not any(
        name.split()[-1] not in SELF_NAMES | {"ego"} for name in ego.aliases if name)


TELLERS_BIKE = {"bike", "motorbike", "motorcycle", "moto"}


def _the_tellers_bike(r: _Reader) -> None:
    """'Jogger ran out right in front of the bike. Locked the back up and stopped', 'like an idiot I took the bike in',
    'keep the bike upright' (said to 'you'): a bike named with 'the' or 'my' by one who tells their own ride, with no
    one on two wheels named before it and no word of pedals, is the teller's motorbike: the ego (a bicycle rider's
    report of a driver is read before, by its pedals, cycle lanes, close passes)."""
    ego = next((e for e in r.entities if e.is_ego), None)
    words = [t.word for t in r.tokens]
    if not _at_no_named_wheel(r, ego) or not set(words) & (SPEAKING_SELF | {"you", "your", "you're"}) or \
            set(words) & PEDAL_WORDS or _says_any(words, PEDAL_PHRASES):
        return
    bikes = [e for e in r.entities if not e.is_ego and e.type in ("cyclist", "motorcycle") and e.head in TELLERS_BIKE
             and e.count == 1 and e.said_at > 0 and not r.tokens[e.said_at].plural and
             r.tokens[e.said_at - 1].word in ("the", "my", "our", "your") and not e.features and
             not any(a[4] not in ("move", "try") for a in e.actions)]  # (not "the motorbike that came up behind you")
    if len(bikes) != 1 or any(e.type in ("cyclist", "motorcycle") and e is not bikes[0] and
                              0 <= e.said_at < bikes[0].said_at for e in r.entities):
        return  # ("a cyclist ... the bike": one named before, said again)
    bike = bikes[0]
    for e in r.entities:
        if e.relative_to is bike:
            e.relative_to = ego  # "ran out right in front of the bike": in front of the teller
    ego.type = "motorcycle"
    ego.actions += [a for a in bike.actions if not any(b[0] == a[0] for b in ego.actions)]
    r.entities.remove(bike)
    r.notes.append(f"read the '{bike.head}' the teller rides as the ego's, a motorbike")


MOUNTED_BY = {"me", "i", "i'm", "im", "was", "we", "we're", "us", ","}  # the teller said just before 'on a ...'


def _the_tellers_mount(r: _Reader) -> None:
    """'Four way stop in New Mexico on a rental Harley', 'me on my moped turning left', 'at the lights on red,
    scooter, a Toyota next to me': a motorbike of which nothing else is said, which the teller is said to be on (or
    which is named bare between commas, as a label), is what the teller rides; the ego is a motorbike."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if not _at_no_named_wheel(r, ego) or not {t.word for t in r.tokens} & FIRST_PERSON:
        return
    words = [t.word for t in r.tokens]

    def mounted(e: Entity) -> bool:
        k = e.said_at
        sentence = r.tokens[k].sentence
        if k < 1 or r.tokens[k].plural:
            return False
        if words[k - 1] == "," and k + 1 < len(words) and words[k + 1] == ",":
            return True  # "stuck at the lights on red, scooter, little Toyota next to me": a label
        on = next((j for j in range(k - 1, max(0, k - 4) - 1, -1) if words[j] == "on"), None)
        if on is None or not all(words[j] in ("a", "an", "my", "the", "rental", "rented", "hired", "hire", "borrowed", "new", "old")
                                 for j in range(on + 1, k)):
            return False
        start = next(t.index for t in r.tokens if t.sentence == sentence)
        return words[on - 1] in MOUNTED_BY or not any(start <= x.said_at < on for x in r.entities if x is not e)
        # ("Four way stop in New Mexico on a rental Harley": no one else named before it in its sentence)
    mounts = [e for e in r.entities if not e.is_ego and e.type == "motorcycle" and e.count == 1 and
              e.said_at >= 0 and not e.generic and not _anything_said_of(e)]
    if len(mounts) == 1 and mounted(mounts[0]):
        ego.type = "motorcycle"
        ego.aliases.add(mounts[0].head)
        r.entities.remove(mounts[0])
        r.notes.append(f"read the '{mounts[0].head}' the teller is on as the ego's")

def _the_named_turn_is_anothers(r: _Reader) -> None:
    """'Left Turn Across Path, HV going straight. ... RV1 turns left across the HV's path', 'I go straight ... The
    truck in front of me it turn right': a turn read for an ego said to go straight in that stage, which another
    road user placed in the scene makes, is the other's (a case's name, a pronoun said again)."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is None or "straight_on" not in ego.features:
        return
    for a in list(ego.actions):
        if a[4] in ("turn_left", "turn_right") and any(
                b[0] == a[0] and b[4] == "go_straight" for b in ego.actions) and any(
                not e.is_ego and (e.features or e.relative_to is not None) and any(b[4] == a[4] for b in e.actions)
                for e in r.entities):  # (another placed somewhere: not one unplaced that may be the ego itself)
            ego.actions.remove(a)


PATIENT_WORDS = {"pt", "patient", "casualty", "moi", "atmist", "gcs", "injuries", "conveyance", "conveyed", "ems",
                 "loc", "handover", "spo2"}
STRUCK_BY = (("struck", "by"), ("hit", "by"), ("knocked", "down", "by"), ("run", "over", "by"),
             ("knocked", "over", "by"), ("clipped", "by"))


def _the_patients_vehicle(r: _Reader) -> None:
    """An ambulance crew's handover ('Pt 52M rider of motorcycle ...', 'MOI: restrained driver of car travelling
    approx 30mph, struck by a van'): the scene is told from the patient's vehicle, named after 'driver of' or
    'rider of'; a patient on foot or on a bike was met by the vehicle that struck them ('8yo F, pedestrian ...
    struck by car'), which is the ego."""
    words = [t.word for t in r.tokens]
    ego = next((e for e in r.entities if e.is_ego), None)
    if not PATIENT_WORDS & set(words) or ego is not None and ego.head not in ("ego", "i", "we", "us", "me", "driver"):
        return
    driven = next((e for e in r.entities if not e.is_ego and e.count == 1 and e.type in V.EGO_TYPES and
                   e.type not in V.VULNERABLE_TYPES - {"motorcycle"} and e.said_at >= 2 and
                   any(words[k] in ("driver", "rider", "passenger") and words[k + 1] in ("of", "in")
                       for k in range(max(0, e.said_at - 4), e.said_at - 1))), None)
    driven = driven or next((e for e in r.entities[:1] if not e.is_ego and e.count == 1 and (
        e.head == "driver" or e.type == "motorcycle" and r.tokens[e.said_at].sentence == 0)), None)
    # "28F driver, stationary at red lights": the patient drove ("Motorcyclist, 34F.", "Pt 19F moped rider, approx
    # 25mph": the patient rode)
    on_foot = any(e.type in V.VULNERABLE_TYPES and e.count == 1 for e in r.entities if not e.is_ego)
    striker = next((e for e in r.entities if not e.is_ego and e.count == 1 and e.type not in V.VULNERABLE_TYPES and
                    any(tuple(words[k:e.said_at]) in STRUCK_BY or tuple(words[k:e.said_at - 1]) in STRUCK_BY
                        for k in range(max(0, e.said_at - 4), e.said_at))), None)
    vehicle = driven or (striker if on_foot else None)
    if vehicle is None:
        return
    _now_the_ego(r, vehicle, "a handover tells the scene from the patient's side")


def _the_ego_now(r: _Reader, vehicle: Entity) -> None:
    """The vehicle an account on foot is about becomes the ego: first among the agents, placed by no one but its
    compass heading; what was placed by it is placed by the ego ("in front of the Ford": in front of the ego now)."""
    vehicle.relative_to = None
    _placed_by_the_ego_now(r, vehicle)
    for e in [e for e in r.entities if e.head in ("scooter", "mobility scooter") and not e.actions and
              not e.features and not e.is_ego and e.relative_to is None]:
        r.entities.remove(e)  # "my daughter wants me to give the scooter up": the teller's own, on foot
    vehicle.is_ego = True
    vehicle.features = {f for f in vehicle.features if f.startswith("compass_")}
    r.entities.remove(vehicle)
    r.entities.insert(0, vehicle)


CROSSING_ON_FOOT = {"halfway", "crossing", "crosswalk", "rolling across", "wheeling across", "in the crosswalk",
                    "wheeled across", "wheeled over", "rolled across", "crossed in front",
                    "across the road", "across the street", "over the zebra", "on the zebra", "across the zebra",
                    "green man", "walk signal"} | STEPPING_OVER
# what a teller on foot was doing: on the way over
PATROLLING = (("lollipop",), ("crossing", "with", "me"), ("over", "with", "me"), ("across", "with", "me"),
              ("my", "crossing"), ("my", "stick"))
STOPPED_FOR_ME = tuple((verb,) + up + ("for", who) for verb, up in (
    ("stopped", ()), ("stops", ()), ("stopping", ()), ("pulled", ("up",)), ("pulls", ("up",)), ("pulling", ("up",)),
    ("waited", ()), ("waits", ())) for who in ("me", "us"))  # ("it pulled up for me and the two girls")


def _speaker_on_the_crossing(tokens: list[Token], strong: bool) -> bool:
    """'I had four of the juniors crossing with me', 'I've got the lollipop out on the crossing', and, from a
    speaker who does nothing on the road, 'it stopped for me and the two girls at the crossing': the speaker sees
    people over a crossing, on foot, and the vehicles that meet them are the scene."""
    words = [t.word for t in tokens]
    patrol = tuple(w for w in PATROLLING if w != ("lollipop",) or not strong or not _says_any(
        words, tuple(("lollipop", who) for who in ("lady", "man", "woman"))))  # "I was stopped while the lollipop
    # lady took them across": a driver who tells of the patrol
    return bool({"crossing", "zebra", "crosswalk", "lights"} & set(words)) and \
        _says_any(words, patrol if strong else patrol + STOPPED_FOR_ME)


def _screens_on_the_crossers_side(r: _Reader) -> None:
    """The vehicles a person steps out from between stand at the kerb that person comes from, ahead of the ego."""
    for k, e in enumerate(r.entities):
        if "screening" not in e.features or e.is_ego:
            continue
        crosser = next((c for c in reversed(r.entities[:k]) if not c.is_ego), None)
        if crosser is None or crosser.type not in V.VULNERABLE_TYPES:  # named after them ('from between them')
            crosser = next((c for c in r.entities[k + 1:] if not c.is_ego and c.type in V.VULNERABLE_TYPES), None)
        if crosser is None:
            continue
        side = next((s for s in SIDES if f"from_{s}" in crosser.features or f"side_{s}" in crosser.features), None)
        if side and not _side_of(e.features):
            e.features.add(f"side_{side}")
        own = _side_of(e.features)
        if own and side is None:
            crosser.features.add(f"from_{own}")  # "out from between two lorries on my left": from the left
        if not any(a[4] == "stop" for a in e.actions):
            e.actions.append((e.stage, 1, ACTION_RANK["stop"], r.tick(), "stop", None))  # screens stand


def _boxed_in_by_those_listed(r: _Reader, clause: Clause, before: int, ego_blocked: list[Entity],
                              boxed: dict) -> None:
    """'The ego gets boxed in: one car in front, one on the left, one on the right': the ego cannot block itself;
    the vehicles the same sentence goes on to name, doing nothing more than driving, are the ones boxing it in."""
    if not clause.units:
        return
    sentence = clause.units[0].tokens[0].sentence
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is not None and ego not in ego_blocked and not any(not e.is_ego for e in r.entities[before:]):
        told = [a for a in ego.actions if a[4] == "block" and a[0] == clause.stage]
        if told:
            boxed[sentence] = told[-1]
        return
    named = [e for e in r.entities[before:] if not e.is_ego and e.type not in V.VULNERABLE_TYPES]
    listed = len(named) >= 2 or (r.listed_one is not None and r.listed_one[0] in named)
    if sentence not in boxed and not (sentence - 1 in boxed and listed):
        return  # "gets boxed in: one car in front, ...": a list after a colon (a sentence break here) names them
    told = boxed.get(sentence, boxed.get(sentence - 1))
    for e in named:
        if all(a[4] == "move" for a in e.actions) and "overtaking" not in e.features:
            e.actions.append((clause.stage,) + told[1:])
            e.features.add("blocks")
            r.notes.append(f"inferred: '{e.head}' is one of those boxing the ego in")


def _members_keep_the_group_place(r: _Reader) -> None:
    """'Two cars ahead of the ego, one in the left lane and one in the right lane': each is ahead, in its lane;
    a member taken before the group's own place was read gets that place too, unless said ahead or behind."""
    for e in r.entities:
        group = e.parent
        if group is not None and not e.features and e.relative_to is None and group.label != "#rest":
            e.features |= group.features  # "two cars come the other way, the second one behind the first": taken
            # from the group in the clause that places it, placed as the group is
            continue
        if group is None or e.features & {"ahead", "behind", "level"}:
            continue
        if not group.features & {"side_left", "side_right"}:
            continue  # "one on my left and one in front of me", "two on the left, four behind us": the place of
            # the ones left in the group, not one they all share
        e.features |= group.features & {"ahead", "behind"}


def _included_and_listed_items_share(r: _Reader) -> None:
    """An agent named only with another, said to do nothing itself, does what that one does and how: 'three cars,
    including a taxi, wait at the red light ahead' (the taxi is also where the three are, unless placed itself),
    'one cyclist waits on the left and one on the right' (both wait). One that acts on its own keeps its act and
    its manner ('... and one on the right turns right')."""
    for e in r.entities:
        source = e.named_of or e.listed_after
        if source is None:
            continue
        if e.named_of is not None and not e.features & HEADLINE_PLACES:
            e.features |= source.features  # (placed nowhere itself: "then two more come straight after it")
        if not e.actions:
            e.actions = list(source.actions)
            e.behavior = e.behavior or source.behavior


def _numbered_lane_sides(r: _Reader) -> None:
    """'I was in lane one, the van in lane two': lanes are counted from the kerb (lane 1 is the nearside lane in
    British and European usage), so a higher number is to the ego's right."""
    def number(e: Entity) -> int | None:
        return next((int(f[5:]) for f in sorted(e.features) if f.startswith("lane_") and f[5:].isdigit()), None)

    own = None
    for k, u in enumerate(r.units):  # "I'm in lane 1", "the player is in lane 2": the ego's own lane
        if u.category == "positions" and u.meaning.startswith("lane_") and any(
                x.category == "agents" and x.meaning == "ego" and all(
                    y.word in ("is", "was", "am", "are", "were", "be", "been", "still", "driving", "travelling",
                               "traveling", "sitting", "the", "on", "a", "dual", "carriageway", "motorway", "road",
                               "highway", "freeway") or y.category == "road"
                    for y in r.units[j + 1:k])  # "the ego is on a dual carriageway in lane one"
                for j, x in enumerate(r.units[max(0, k - 8):k], start=max(0, k - 8))):
            own = int(u.meaning[5:])
            break
        said_after = [x.word for x in r.units[k + 1:k + 4] if x.category != "number"]
        if u.category == "positions" and re.fullmatch(r"(into_)?lane_\d+", u.meaning) and \
                said_after[:1] == ["where"] and any(
                    x.category == "agents" and x.meaning == "ego" for x in r.units[k + 1:k + 5]):
            own = int(u.meaning.split("_")[-1])  # "moved out into lane 2, where I was": the ego's lane, said after
            break
    if own is None:
        own = _lane_said_of_no_one(r.units)
    if own is None:
        return
    _ego_into_a_numbered_lane(r, own)
    for e in r.entities:
        theirs = number(e) if not e.is_ego else None
        if theirs is None or theirs == own or e.features & {"side_left", "side_right", "from_left", "from_right",
                                                            "road_left", "road_right", "road_straight"}:
            continue
        side = "side_right" if theirs > own else "side_left"
        e.features.add(side)
        r.notes.append(f"inferred: '{e.head}' in lane {theirs} is to the {side[5:]} of the ego in lane {own}")


def _ego_into_a_numbered_lane(r: _Reader, own: int) -> None:
    """'Patrolling in lane 1 ... so we moved out into lane 2': the ego moving into another numbered lane changes lane
    towards it (lanes count from the kerb), unless a side was said."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is None or any(a[4] in ("lane_left", "lane_right") or a[4] in ("lane_change", "cut_in") and a[5]
                          for a in ego.actions):
        return
    moved = next((a for a in reversed(ego.actions) if a[4] in ("lane_change", "cut_in")), None) or next(
        (a for a in reversed(ego.actions) if a[4] == "move"), None)
    if moved is None:
        return
    for k, u in enumerate(r.units):
        into = re.fullmatch(r"into_lane_(\d+)", u.meaning) if u.category == "positions" else None
        if u.word == "lane" and k > 0 and k + 1 < len(r.units) and r.units[k + 1].category == "number" and \
                r.units[k - 1].category == "actions" and r.units[k - 1].tokens[-1].word in ("into", "to", "onto"):
            into = re.fullmatch(r"(\d+)", r.units[k + 1].word)  # "moved over into lane 1": the verb took its 'into'
        if not into or int(into[1]) == own:
            continue
        start = next((j for j in range(max(0, k - 4), k) if r.units[j].tokens[0].sentence == u.tokens[0].sentence), k)
        before = r.units[start:k]
        opened = start < k and r.units[start].category == "actions" and (
            start == 0 or r.units[start - 1].tokens[0].sentence != u.tokens[0].sentence)  # "Moved over into lane 1":
        # the teller's, said with no subject
        if (opened or any(
                x.category == "agents" and x.meaning == "ego" for x in before)) and any(
                x.category == "actions" and x.meaning in ("move", "lane_change", "cut_in") for x in before):
            ego.actions.append((moved[0], 2, ACTION_RANK["cut_in"] + 1, r.tick(),
                                "lane_right" if int(into[1]) > own else "lane_left", None))
            return


def _lane_said_of_no_one(units: list[Unit]) -> int | None:
    """'Approaching in lane 2 in the TOV, saw a van stopped in lane 1': a numbered lane a sentence places before it
    names anyone is the teller's own (not 'attended lane 1 obstruction': where the obstruction was)."""
    for k, u in enumerate(units):
        listed = u.category == "word" and u.word == "lane" and 0 < k < len(units) - 2 and \
            units[k - 1].category == "comma" and units[k + 1].category == "number" and units[k + 2].category == "comma"
        # ("Patrolling M4 eastbound, lane 1, in the TOV": a note's item)
        if not listed and (u.category != "positions" or not re.fullmatch(r"lane_\d+", u.meaning)):
            continue
        sentence = u.tokens[0].sentence
        before = [x for x in units[:k] if x.tokens[0].sentence == sentence]
        after = units[k + 1 + listed].word if k + 1 + listed < len(units) else ""
        if not any(x.category == "agents" and x.meaning not in ("none", "ego") for x in before) and \
                after not in ("obstruction", "closure", "closed", "blocked", "shut") and \
                not any(x.word in ("attended", "attend", "closed", "shut") for x in before[-2:]):
            return int(units[k + 1].word) if listed else int(u.meaning[5:])
    return None


NAMED_LANES = ("left", "middle", "right")  # across a road, left to right


def _named_lane_sides(r: _Reader) -> None:
    """'Our truck is in the right lane ..., a car just ahead of it in the middle lane', 'VUT in the middle lane; a
    car from the left lane': where the ego's own lane is named, another's named lane is placed against it (the
    same lane is the ego's; one named further left is to its left), not against the road's edge."""
    def lane(e: Entity, own: bool) -> str | None:
        if own:
            return next((s for s in NAMED_LANES if f"in_lane_{s}" in e.features), None)
        if "middle_lane" in e.features:
            return "middle"
        return next((s for s in SIDES if f"named_lane_{s}" in e.features), None)

    ego = next((e for e in r.entities if e.is_ego), None)
    start = lane(ego, True) if ego is not None else None
    if start is None:
        return
    moves = [a for a in ego.actions if a[1] == 2 and (a[4] in ("lane_left", "lane_right") or
                                                     a[4] in ("lane_change", "cut_in") and a[5] in SIDES)]
    moved_at = min((a[0] for a in moves), default=None)
    step = {"left": -1, "right": 1}.get(moves[0][4][5:] if moves and moves[0][4].startswith("lane_") else
                                        moves[0][5] if moves else "")
    after = "middle" if "to_the_middle" in ego.features and start != "middle" else \
        NAMED_LANES[NAMED_LANES.index(start) + step] if step and 0 <= NAMED_LANES.index(start) + step < 3 else None
    if "to_the_middle" in ego.features and moved_at is None:
        moved_at = min((a[0] for a in ego.actions if a[4] in ("lane_change", "cut_in")), default=None)
    for e in r.entities:
        theirs = lane(e, False) if not e.is_ego else None
        own = after if after and moved_at is not None and e.stage > moved_at else start
        # ("the ego moves over into the middle lane ... Then a van from the right lane forces its way in": the
        # lane the ego is in by then)
        if theirs is None or (theirs, own) == ("right", "left") or (theirs, own) == ("left", "right"):
            continue  # (left of the ego in the left lane, right of it in the right lane: as said)
        placed = {f"{p}{s}" for p in ("side_", "front_", "back_") for s in SIDES} & e.features
        ahead = bool(placed & {"front_left", "front_right"}) or "ahead" in e.features
        behind = bool(placed & {"back_left", "back_right"}) or "behind" in e.features
        e.features -= placed | {"middle_lane", "bare_left", "bare_right"}
        if theirs == own:
            e.features |= {"ahead"} if ahead else {"behind"} if behind else set()
            if not ahead and not behind and "level" not in e.features:
                e.features.add("ahead")  # "three cars stopped in the left lane ... the ego is in the left lane":
                # one lane holds no two level, and the one the ego meets in it is ahead
            r.notes.append(f"inferred: '{e.head}' in the {theirs} lane is in the ego's own lane")
            continue
        side = "left" if NAMED_LANES.index(theirs) < NAMED_LANES.index(own) else "right"
        e.features.add(f"side_{side}")
        e.features |= {"ahead"} if ahead else {"behind"} if behind else set()
        r.notes.append(f"inferred: '{e.head}' in the {theirs} lane is to the {side} of the ego in the {own} lane")


def _from_the_same_place(r: _Reader) -> None:
    """'A car approaches from the left side road, and a cyclist approaches from the same road': from where the
    last one named before it with a place came from."""
    for e in r.entities:
        if "same_place" not in e.features:
            continue
        e.features.discard("same_place")
        before = [x for x in r.entities if x is not e and not x.is_ego and 0 <= x.said_at < e.said_at and
                  x.features & PLACE_FEATURES]
        if before:
            model = max(before, key=lambda x: x.said_at)
            e.features |= model.features & PLACE_FEATURES
            r.notes.append(f"inferred: '{e.head}' comes from where '{model.head}' comes from")


def _ego_placed_last(units: list[Unit]) -> bool:
    """'... ahead of the player': the clause ends on the ego as the object of a place phrase (also one the
    lexicon knows whole, 'ahead of the ego vehicle')."""
    last = len(units) - 1 - (len(units) > 1 and units[-1].category == "word" and units[-1].word in EGO_HEADS)
    if last >= 0 and units[last].category == "positions" and units[last].tokens[-1].word == "ego":
        return True
    egos = [k for k, u in enumerate(units) if u.category == "agents" and u.meaning == "ego"]
    if not egos or egos[-1] != len(units) - 1:
        return False
    k = egos[-1] - 1
    while k >= 0 and units[k].category == "word" and units[k].word in ("the", "of", "a"):
        k -= 1
    return k >= 0 and units[k].category == "positions"


def _placed_by_a_pronoun(units: list[Unit]) -> bool:
    """'... a motorbike next to it': the clause ends on a pronoun that is the object of a place phrase."""
    return len(units) > 2 and units[-1].category == "word" and units[-1].word in ("it", "him", "her", "them") and \
        units[-2].category == "positions" and units[-3].category == "agents"


EGO_HEADS = {"vehicle", "car"}  # "the ego vehicle" after a place phrase that ends in "the ego"


def _set_off_after_the_ego(tokens: list[Token], clause: Clause, before: list[Unit], other: Entity) -> bool:
    """'... in front of the ego, who comes to a stop': a relative set off by a comma right after the ego named
    as a noun is about the ego, unless its verb agrees only with the plural named before it ('three cars ahead
    of the player, which each swerve'). 'that' restricts the noun it follows, and nobody writes it of the ego."""
    if clause.link not in ("who", "which") or not clause.units:
        return False
    at = clause.units[0].tokens[0].index - 1
    while at > 0 and tokens[at].word != clause.link:
        at -= 1
    if at < 1 or tokens[at - 1].word != ",":
        return False
    if before[-1].tokens[-1].word in SPEAKERS:  # "right in front of me, which made me brake": what happened
        return False
    verb = next((u for u in clause.units if u.category == "actions"), None)
    plural_verb = verb is not None and verb.tokens[0].word == verb.tokens[0].base and \
        not verb.tokens[0].word.endswith(("ed", "ing"))
    return not (plural_verb and other.count > 1)


TRUCKERS_WORDS = (("limiter",), ("four", "wheeler"), ("fourwheeler",), ("empty", "trailer"), ("my", "trailer"),
                  ("my", "rig"), ("the", "rig"), ("my", "load"), ("tachograph",), ("tacho",), ("trucking", "on"),
                  ("trucking", "along"), ("trucking", "down"), ("trucking", "through"), ("my", "unit"),
                  ("in", "the", "unit"), ("in", "the", "wagon"), ("my", "wagon"), ("in", "the", "artic"),
                  ("my", "artic"), ("the", "rigid"), ("my", "rigid"), ("in", "the", "tipper"), ("my", "tipper"),
                  ("the", "pete"), ("my", "pete"), ("my", "tractor", "trailer"), ("steer", "tire"), ("steer", "tyre"),
                  ("bobtailing",), ("night", "trunk"), ("trunking",), ("multidrop",), ("multi", "drop"),
                  ("the", "shipper"), ("the", "receiver"), ("my", "reefer"), ("in", "the", "truck"), ("tonner",),
                  ("running", "empty"), ("trailer", "empty"), ("loaded", "wagon"), ("in", "the", "lorry"),
                  ("my", "lorry"), ("in", "the", "hgv"), ("my", "hgv"), ("other", "wagons"), ("off", "our", "yard"),
                  ("kerb", "mirror"), ("close", "proximity", "mirror"), ("trailer", "wheels"),
                  ("in", "the", "box", "truck"), ("my", "box", "truck"), ("in", "the", "semi"), ("my", "semi"),
                  ("my", "blade"), ("the", "blade"), ("wing", "down"), ("the", "spinner"), ("plowing",),
                  ("ploughing",))
# (a unit, a wagon, a rigid, a Pete: a trucker's own truck; not "struck the unit" of a fleet's van; a plough's
# blade, wing and spinner: its driver's)


BUS_DRIVERS_WORDS = (("stop", "arm"), ("the", "arm", "out"), ("and", "arm", "out"), (",", "arm", "out"), ("my", "bus"),
                     ("standing", "passengers"), ("passengers", "were", "standing"), ("passengers", "standing"),
                     ("passengers", "on", "board"),
                     ("doors", "open"), ("the", "terminus"), ("my", "route"), ("loading", "passengers"),
                     ("picking", "up", "passengers"), ("letting", "passengers", "off"), ("open", "for", "boarding"),
                     ("back", "of", "the", "bus"), ("front", "of", "the", "bus"), ("side", "of", "the", "bus"))
# ("at the stop with the doors open", "missed the back of the bus by a foot": a bus no other is; not a cyclist's
# "with my arm out")


BUS_TAKEN = {"get", "got", "catch", "caught", "miss", "missed", "take", "took"}  # a passenger's bus, not a driver's
BUS_PASSENGERS_WORDS = (("top", "deck"), ("lower", "deck"), ("upper", "deck"), ("bus", "driver"),
                        ("coach", "driver"), ("night", "coach"), ("greyhound",), ("on", "the", "bus"),
                        ("on", "the", "coach"), ("standing", "passengers"), ("passengers", "fell"),
                        ("passengers", "were", "thrown"))


AMBULANCE_CREWS_WORDS = (("ambo", "crew"), ("ambulance", "crew"), ("patient", "on", "board"), ("the", "patient"),
                         ("cardiac", "arrest"), ("ems", "unit"), ("medic", "unit"), ("our", "ambulance"),
                         ("running", "hot"))
FIRE_CREWS_WORDS = (("structure", "fire"), ("driving", "the", "pump"), ("from", "a", "shout"), ("to", "a", "shout"),
                    ("on", "a", "shout"), ("fire", "appliance"), ("our", "engine"), ("our", "appliance"),
                    ("the", "appliance"), ("fire", "call"), ("ladder", "truck"), ("to", "a", "house", "fire"))
# ("Ambo crew, reds on ... the Honda in the left lane beside us", "Driving the pump back from a shout ... we stopped":
# a crew that says "we" of the vehicle it works from; not "paramedics checked us over", "we were at the pump")


def _a_drivers_introduction(r: _Reader) -> Entity | None:
    """'Tanker driver. Taking a left ...', 'HGV driver here. On the M6 ...': a first line that says only what the
    speaker drives, before a first-person account, names the ego's vehicle, not one more road user."""
    line = []
    for t in r.tokens:
        if t.sentence > 0 or t.word in (",", ":", "-"):
            break
        line.append(t)
    words = [t.word for t in line]
    if words[:1] == ["as"] and words[1:2] in (["a"], ["an"]) and "driver" in words[3:5]:
        line = line[2:words.index("driver", 3) + 1]  # "As a bus driver on Victoria Road, I am routinely cut up"
    vehicles = [e for e in r.entities if not e.is_ego and line and line[0].index <= e.said_at <= line[-1].index]
    if len(vehicles) != 1 or vehicles[0].count not in (0, 1) or vehicles[0].type not in V.EGO_TYPES or \
            vehicles[0].actions or not {"driver", "here"} & {t.word for t in line} or \
            not ({t.word for t in r.tokens[line[-1].index + 1:]} & SPEAKERS or not any(
                e.is_ego and not _supplied(r, e) for e in r.entities)):
        return None  # (the account in the first person, or with no subject: "Turning right at the lights, ...")
    named = set(vehicles[0].head.split()) | {"driver", "here", "a", "an", "i'm", "im", "professional"}
    return vehicles[0] if all(t.word in named or t.word in vehicles[0].aliases for t in line) else None


DRIVEN_BY = {"driving", "drivin", "drive", "drove", "running", "run", "ran", "had", "bobtailing", "piloting",
             "operating", "crewing"}  # "Driving the 46A bus", "Running a reefer", "Had the coach today"
TELLER_IN = {"i'm", "im", "we're", "i", "we", "was", "were", "am", "are", "sat", "sitting", "me", "us"}  # "I'm in the
# Freightliner", "we were sat in the ambulance"
NOT_OF_A_VEHICLE_NAMED = {",", ".", "behind", "past", "beside", "by", "after", "of", "to", "into", "from", "at", "for",
                          "round", "around", "over", "alongside", "than", "and", "with", "on", "off", "up", "down",
                          "out", "towards", "toward", "near", "next", "front", "lane", "me", "us", "him", "her",
                          "when", "as", "while", "whilst", "then", "but", "so", "because", "until", "till", "before",
                          "if", "that", "which", "who", "where", "once", "since", "like", "through", "along"}
# (what ends the words naming the vehicle: "driving behind the bus", "running into the back of a lorry", "I was
# driving when a car pulled out")


def _driven_by_the_speaker(r: _Reader) -> Entity | None:
    """'Driving the 46A bus into town ...', 'Running a reefer outta Salinas ...', 'Had the coach today', 'I'm in the
    Freightliner ...': one vehicle the speaker (said as 'I' or 'we', or by no subject at a sentence's opening) drives,
    runs or sits in is the speaker's own, the ego, whatever it is (not 'he was driving the truck', 'the man
    driving the van', 'behind the bus I was driving' placed by another)."""
    ego = next((e for e in r.entities if e.is_ego), None)
    words = [t.word for t in r.tokens]
    if "ego" in words or ego is not None and ego.head not in SPEAKING_SELF and not _supplied(r, ego) or \
            not set(words) & (SPEAKING_SELF | {"i'm", "we're"}) and ego is not None and not _supplied(r, ego):
        return None  # (an account of no one named may be the speaker's: "Running a reefer ... Sitting at the red")
    driven = []
    for e in r.entities:
        k = e.said_at
        if e.is_ego or e.count not in (0, 1) or e.generic or k < 1 or r.tokens[k].plural or \
                e.relative_to is not None or e.type not in V.EGO_TYPES - V.VULNERABLE_TYPES or \
                e.features & (PLACE_FEATURES | PLACED_HOW):
            continue
        j = k - 1
        while j > 0 and k - j < 6 and words[j] not in DRIVEN_BY | {"in"} | NOT_OF_A_VEHICLE_NAMED:
            j -= 1  # ("the 46A bus", "the marked police X5", "a 26-foot box truck")
        verb = words[j]
        before = words[max(0, j - 2):j]
        if r.tokens[j].sentence != r.tokens[k].sentence:
            continue
        by_the_speaker = before[-1:] and before[-1] in SPEAKING_SELF | {"i'm", "we're"} or \
            before in (["i", "was"], ["we", "were"], ["i", "am"], ["we", "are"]) or \
            _opens_its_sentence(r.tokens, r.tokens[j])
        if verb in DRIVEN_BY and by_the_speaker or verb == "in" and before[-1:] and before[-1] in TELLER_IN:
            driven.append(e)
    return driven[0] if len(driven) == 1 else None


OWN_VEHICLES_STATE = {"stop", "try", "relate"}  # "Taxi stopped at the stop sign on Oak.": where the speaker's own
# stands ("Bin lorry, Tuesday round on Elm Close": on its round, no move)


def _opens_on_the_speakers_vehicle(r: _Reader) -> Entity | None:
    """'Amazon van, doing drops on Elm Street. I was parked ...', 'Double-decker, Oxford Street westbound. Two taxis
    were parked in front of me', 'Taxi stopped at the stop sign on Oak. A jogger went across in front of me': a text
    that opens on a vehicle named bare (no article), said to do nothing but stand, placed by nothing, before a
    first-person account in a later sentence, opens on the speaker's own vehicle."""
    first = min((e for e in r.entities if not e.is_ego and e.said_at >= 0), key=lambda e: e.said_at, default=None)
    if first is None or first.type not in V.EGO_TYPES or first.count not in (0, 1) or \
            first.features & (PLACE_FEATURES | PLACED_HOW | {"parked"}) or first.relative_to is not None or \
            first.road_type is not None or \
            any(a[4] not in OWN_VEHICLES_STATE for a in first.actions):
        return None
    opening = [t for t in r.tokens if t.sentence == r.tokens[first.said_at].sentence]
    before = [t.word for t in opening if t.index < first.said_at]
    if opening[0].index != 0 or any(w in DETERMINERS | {"a", "an", "one", "another", "some"} for w in before) or \
            {t.word for t in opening if not (t.word == "i" and t.index + 1 < len(r.tokens) and
                                                r.tokens[t.index + 1].word.isdigit())} & SPEAKING_SELF \
            or r.tokens[first.said_at].plural:  # (not "I-95": a road's number)
        return None
    later = [t.word for t in r.tokens if t.sentence > opening[-1].sentence]
    ego = next((e for e in r.entities if e.is_ego), None)
    told_by_no_one = ego is not None and _supplied(r, ego)  # ("Coach full of Year 6s. Waited on red ...")
    if not (set(later) & FIRST_PERSON or told_by_no_one) or {"it", "its"} & set(later) or \
            any(e is not first and not e.is_ego and e.type == first.type and e.count == 1 for e in r.entities):
        return None  # ("Car stopped at the lights. I went round it": another's; "... a second taxi")
    return first


CALL_SIGN_WORDS = {"alpha", "bravo", "charlie", "echo", "foxtrot", "kilo", "lima", "mike", "oscar", "papa", "tango",
                   "uniform", "victor", "whiskey", "whisky", "yankee", "zulu"}  # (not golf, sierra, romeo: cars)


PATROL_CALL_WORDS = {"adam", "boy", "charles", "david", "edward", "frank", "george", "henry", "ida", "john", "king",
                     "lincoln", "mary", "nora", "ocean", "paul", "queen", "robert", "sam", "tom", "union", "william",
                     "young"}  # a US patrol's call sign ("2-David-14", "1-Lincoln-20")
PATROL_CARS = (("marked", "car"), ("marked", "vehicle"), ("marked", "irv"), ("marked", "unit"), ("irv",),
               ("area", "car"), ("traffic", "car"), ("response", "car"), ("police", "veh"), ("police", "vehicle"))
PATROLS_OWN_WORDS = tuple(lead + car for car in PATROL_CARS for lead in (("in",), ("in", "a"), ("in", "an"),
                                                                         ("in", "the"), ("our",), ("my",))) + (
    ("we're", "running", "code"), ("we", "were", "running", "code"), ("involving", "own", "vehicle"), ("pnb",),
    ("we're", "on", "blues"), ("we", "were", "on", "blues"), ("we", "are", "on", "blues"))
# ("in marked IRV", "our traffic car": the patrol's own; not "a traffic car pulled me over")
PATROLS_OPENINGS = (("blues", "and", "twos"), ("code", "3"), ("code", "three"), ("dispatch", ","), ("control", ","),
                    ("unit", ",", "marked", ",")) \
    + PATROL_CARS + tuple(("police",) + car for car in PATROL_CARS)
# ("Blues and twos WB Lord St to a fail to stop", "Code 3 to a 10-50", "Police traffic car, grade 1.", "Unit 9
# (marked) responding": a patrol's log opens on its own run or its own car)


def _a_patrols_call_sign(r: _Reader) -> bool:
    """'Control from Tango 4-2, we're NB ...', '22:10 Bravo 1-1 stationary at red signal', 'Dispatch, 4-Adam-3,
    we're sat in traffic', 'on patrol in marked IRV': a radio log whose speaker gives a call sign (a phonetic
    letter and a number) or speaks of the patrol's own car or run is told from a patrol car."""
    words = [t.word for t in r.tokens]
    return any(w in CALL_SIGN_WORDS and k + 1 < len(words) and words[k + 1].isdigit() and (
        k == 0 or words[k - 1] in ("from", "control", ",", ":", ".") or words[k - 1].isdigit()) or
        w in PATROL_CALL_WORDS and 0 < k < len(words) - 1 and words[k - 1].isdigit() and words[k + 1].isdigit()
        for k, w in enumerate(words)) or _says_any(words, PATROLS_OWN_WORDS) or \
        any(tuple(words[:len(p)]) == p for p in PATROLS_OPENINGS) or any(
            tuple(words[k:k + 4]) == ("unit", ",", "marked", ",") and (k == 0 or r.tokens[k - 1].sentence !=
                                                                       r.tokens[k].sentence) for k in range(len(words)))
    # ("0040 hrs, dark. Unit 6 (marked) NB Station Rd": the unit's own line, after the time and the light)


def _the_egos_brake_is_no_stop(r: _Reader) -> None:
    """'Taxi cuts across the bus's front. Bus brakes hard, no contact.': braking said of one found only later to be
    the ego is a reaction, not where the ego ends, as it is when said of the ego ('the AV braked')."""
    for e in r.entities:
        if e.is_ego:
            e.actions = [a for a in e.actions if not (a[4] == "stop" and a[3] in r.braked)]


def _said_with_a(r: _Reader, e: Entity) -> bool:
    """'a bus', 'a red double-decker bus': first named as one more, not as one known or bare."""
    said = [t for t in r.tokens[max(0, e.said_at - 4):e.said_at + 1] if t.sentence == r.tokens[e.said_at].sentence]
    return any(t.word in INDEFINITE for t in said)


SERVICE_NUMBERED = {"route", "number", "no", "service"}
SERVICE_BOARDED = {"of", "on", "off", "caught", "took", "missed", "boarded", "onto", "aboard"}  # "at the front of the
# 47", "caught the 9 home": a service its passengers ride
SERVICE_GOES = {"stopped", "pulled", "was", "came", "went", "braked", "left", "out", "from", "into", "on", "today"}


def _on_a_bus_route(words: list[str]) -> bool:
    """'the 7 stopped at the zebra', 'the number 38', 'in the bus lane': a service named by its number, or the bus
    lane it keeps to; with passengers who speak of their driver, what they ride is a bus, not a taxi."""
    return any(w in SERVICE_NUMBERED and words[k + 1].isdigit() or w == "the" and words[k + 1].isdigit() and
               k + 2 < len(words) and words[k + 2] in SERVICE_GOES or words[k:k + 2] == ["bus", "lane"] or
               w == "the" and words[k + 1].isdigit() and k > 0 and words[k - 1] in SERVICE_BOARDED and
               (k + 2 == len(words) or words[k + 2] in (",", "and", "when", "as", "because", "today", "yesterday",
                                                        "this", "last", "into", "from", "to", "home"))
               for k, w in enumerate(words[:-1]))


def _a_drivers_trade(r: _Reader) -> None:
    """'Empty trailer, fog down on the Pennines', 'some four-wheeler dives in front of my bumper', 'in lane one on
    the limiter': a speaker who talks as a truck driver drives a truck, told of by no other name; one who puts out
    a stop arm, or has passengers standing, drives a bus. 'HGV driver here.': one who says so."""
    introduced = _a_drivers_introduction(r) or _opens_on_the_speakers_vehicle(r) or _driven_by_the_speaker(r)
    if introduced is not None:
        if any(e.is_ego and e.actions for e in r.entities):
            introduced.actions = [a for a in introduced.actions if a[4] not in ("move", "relate")]  # ("Running a
            # reefer ... waiting to hang a left": the driving is the ego's, told by what it did)
        introduced.count = 1  # ("as a bus driver": a role, counted as no one until it is the speaker's)
        _now_the_ego(r, introduced, "the speaker says first what they drive")
        return
    words = [t.word for t in r.tokens]
    ego = next((e for e in r.entities if e.is_ego), None)
    if (ego is None or ego.type == "car" and (ego.head in SPEAKING_SELF or _supplied(r, ego))) and \
            _a_patrols_call_sign(r):
        ego = _ego_entity(r, 0)
        ego.type = "police"
        r.notes.append("inferred: the speaker gives a patrol's call sign; the ego is a police car")
        return
    told = [t.word for t in r.tokens if not t.question]  # (not "what's the rule when a school bus is stopped with
    # its stop arm out?")
    crew = {"we", "us", "our"} & set(words)  # (a crew speaks as one)
    driven = NARRATORS_DRIVER in r.notes and _on_a_bus_route(told)
    aboard_a_bus = bool(crew) and _says_any(told, BUS_PASSENGERS_WORDS) or driven
    # "we were in the inside lane ... I was on the top deck", "the coach driver hit the horn": the bus its
    # passengers ride in; "the 7 stopped at the zebra ... Our driver stayed calm": the bus its driver drives
    at_its_wheel = _says_any([w for k, w in enumerate(told) if not (
        w == "my" and k and told[k - 1] in BUS_TAKEN)], BUS_DRIVERS_WORDS)  # (not "never did get my bus")
    ours = [e for e in r.entities if e.type == "bus" and not e.is_ego and e.count == 1 and
            (e.definite or (at_its_wheel or aboard_a_bus) and not _said_with_a(r, e)) and
            not {f for f in e.features if not _its_own_lane(e, f)} & (PLACE_FEATURES | PLACED_HOW) and
            e.relative_to is None] \
        if (aboard_a_bus or at_its_wheel) and ego is not None and \
        (ego.head in FIRST_PERSON | {"we", "us", "our"} or _supplied(r, ego)) else []
    # ("cut across in front of the bus": the passengers' own, named by what it is; "Bus was standing at the stop
    # with the doors open": the driver's own)
    trade = "truck" if _says_any(words, TRUCKERS_WORDS) else "bus" if at_its_wheel or aboard_a_bus else \
        "ambulance" if crew and _says_any(words, AMBULANCE_CREWS_WORDS) else \
        "firetruck" if crew and _says_any(words, FIRE_CREWS_WORDS) else None
    if "ego" in words and not driven or trade is None or trade != "truck" and any(
            e.type == trade and not e.is_ego and not any(e is o for o in ours) for e in r.entities):
        return  # ("stopped behind a school bus with its stop arm out": that bus's arm)
    if ego is None and (set(words) & SPEAKERS or trade == "truck"):
        ego = _ego_entity(r, 0)  # "doing 65 ... in front of my bumper": the speaker, told of by no noun ("Empty
        # trailer, fog down on the Pennines": a trucker's words are the speaker's own)
    if ego is not None and ego.type == "car" and (ego.head in FIRST_PERSON | {"we", "us", "our", "ego"} or
                                                  ego.head == "you" and set(words) & FIRST_PERSON):
        ego.type = trade  # ("This is why you keep your distance. I'm in the right lane at 65 ...": the speaker)
        r.notes.append(f"inferred: the speaker talks as a {trade} driver; the ego is a {trade}")
        for e in ours if trade == "bus" else []:
            _fold(r, ego, e)


def _ego_lane_road(r: _Reader, road: RoadSpec) -> RoadSpec:
    """'I'm in the slow lane', 'the ego is in the left lane': a lane named by its side is one of several.
    'My car slid out across the junction': where the ego goes is at a junction."""
    ego = next((e for e in r.entities if e.is_ego), None)
    if ego is not None and "in_junction" in ego.features and road.junction is None:
        r.notes.append("inferred: at junction (the ego goes across it)")
        road = road.model_copy(update={"junction": True})
    if ego is None or "in_a_side_lane" not in ego.features or (road.lanes or 0) >= 2:
        return road
    r.notes.append("inferred: lanes >= 2 (the ego is in a lane named by its side)")
    return road.model_copy(update={"lanes": 2})


HEADER_OF_PLACE = (r"(oncoming|opposing|crossing|cross|following|leading|lead|adjacent|left|right|behind|ahead|in front"
                   r"|rear|from the left|from the right|from behind)( (lane|traffic|vehicles?|cars?|agents?|side))*")
HEADER_FILLER = {"traffic", "vehicles", "cars", "agents", "and", "lane", "side"}  # "car R lane behind" is an agent


def _header_of_place(units: list[Unit]) -> list[Unit]:
    """'oncoming: a bus and a van', 'Oncoming traffic: ...': a verbless heading of places for the agents listed next."""
    places = [u for u in units if u.category == "positions"]
    if not places or _has_verb(units):
        return []
    if all(u.category == "positions" or u.word in HEADER_FILLER or u.category == "comma"
           or (u.category == "agents" and u.meaning in ("none", "generic") and u.tokens[-1].plural) for u in units):
        return places
    return []


TITLE_SMALL_WORDS = {"a", "an", "the", "of", "in", "on", "at", "to", "with", "and", "vs", "for", "by", "from"}


SENTENCED = {"banned", "fined", "jailed", "sentenced", "convicted", "charged", "cleared", "acquitted", "disqualified",
             "imprisoned", "prosecuted", "ordered"}


def _sentence_passed(tokens: list[Token]) -> range:
    """'A pensioner who turned across the path of a motorcyclist has been banned from driving for a year. The court
    heard that ...': a report's first sentence gives the sentence passed on someone, and what they did in a word;
    the account after it tells the scene, with its people again."""
    first = [t for t in tokens if t.sentence == 0]
    words = [t.word for t in first]
    if len(first) == len(tokens) or not any(k + 1 < len(words) and (w == "been" and words[k + 1] in SENTENCED or
                                                                     w == "has" and words[k + 1] == "admitted")
                                            for k, w in enumerate(words)):  # ("has admitted dangerous driving")
        return range(0)
    return range(len(first))


def _headline(prompt: str, tokens: list[Token]) -> range:
    """'Scenario 1 (Lead Vehicle Stopped). The subject vehicle ...', 'Overtake Challenge. The player ...': a first
    sentence in title case, without a verb, names the case, not its agents."""
    m = re.match(r"\s*([^.!?\n]{1,60})[.!]\s+\S", prompt)
    letters = [c for c in prompt if c.isalpha()]
    if m is None or sum(c.isupper() for c in letters) > 0.8 * len(letters):
        return range(0)  # (a text all in capitals, as a sign-language gloss is written, has no title case to tell)
    words = re.findall(r"[A-Za-z][A-Za-z'-]*|\d+", re.sub(r"\((?:e?s)\)", "", m.group(1)))  # "Vehicle(s) Changing Lanes"
    if not words or len(words) > 8 or not all(w[0].isupper() or w[0].isdigit() or w.lower() in TITLE_SMALL_WORDS
                                             for w in words) or words[0].lower() in SUBJECT_PRONOUNS | {"i'm"}:
        return range(0)
    named = [w for w in words if not w.isdigit() and len(w) > 1]
    if len(named) == 1 and named[0].lower() not in DRIVERS and _names_agent(named[0]):
        return range(0)  # "Motorcyclist, 34F.", "Cyclist.": one road user (a handover's patient), no title
    n = _opening(tokens, m.group(1))
    if n >= len(tokens) or any(t.base in ("be", "have") for t in tokens[:n]):
        return range(0)
    return range(n)


def _opening(tokens: list[Token], title: str) -> int:
    """How many tokens the title is, if the text's tokens open with it, else 0 (the reading of lines may have
    taken it off already: "Event 7: a motorcycle turns left")."""
    words = [t.word for t in tokenize(title)]
    return len(words) if [t.word for t in tokens[:len(words)]] == words else 0


def _title(prompt: str, tokens: list[Token]) -> range:
    """'Cut-in: a target vehicle ...': a short title before a colon names the case, not its agents."""
    m = re.match(r"\s*([^.:;!?\n]{1,80}):\s*\S", prompt)
    if m is None and "\n" not in prompt.strip():
        return _headline(prompt, tokens)
    if m is None or "\n" in prompt.strip():  # notes written a line an item have their titles marked already
        return range(0)
    if _names_agent(m.group(1)) and m.group(1).strip().lower().split()[0] not in ("scenario", "case", "test"):
        return range(0)  # "ped: dashes across": the key is the subject (lexicon._keyed_agents)
    found = matches(tokenize(m.group(1)))
    said = {(f.category, f.meaning) for f in found}
    if any(category == "actions" for category, _ in said) and (("agents", "ego") in said and (
            m.group(1).strip().lower().split()[0] in ("the", "i", "we", "you", "player", "my", "our", "ego") or
            any(f.start == 0 and (f.category, f.meaning) == ("agents", "ego") for f in found))
            or {t.word for t in tokenize(m.group(1))} & {"i", "me", "we", "us"}):
        return range(0)  # "The player makes the left across oncoming traffic: ...", "A taxi cut me off: it ...",
        # "Robotaxi 9 requested help on a right turn: ...": a sentence (a title names no speaker), not a title
    counted = re.search(r"\b(\d+|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve)\s+(?:\w+\s+)?\w+s\b",
                        m.group(1).lower())  # "Nine pedestrians: four on the left ...", "2 NPC cars: one in
    # front, one behind": what is listed, no title
    if counted or re.match(r"there\b|.*\b(is|are|was|were)\b", m.group(1).strip().lower()):
        return range(0)  # "There are four cars: one in front ...": a sentence, not a title
    if re.match(r"(?:dash\s?cam|camera|footage|video|clip|photo|picture|image|still)\b.*\bfrom\s+(?:a|an|the|my|our)\b",
                m.group(1).strip().lower()):
        return range(0)  # "Photo taken from a stopped car in light rain: a child ...": the car it was taken from
    if re.fullmatch(HEADER_OF_PLACE, m.group(1).strip().lower()):
        return range(0)  # "Oncoming traffic: a car and a motorcycle": where the listed agents are, no title
    if _title_names_the_agent(m.group(1), prompt[m.end(1):]):
        return range(0)
    n = _opening(tokens, m.group(1))
    if n > 12 or n >= len(tokens):
        return range(0)
    return range(n)


def _title_names_the_agent(title: str, rest: str) -> bool:
    """'Overtaking the cyclist on the 30 road: you gave him room': a topic that names its agent with 'the' and
    that the rest only refers back to is where the agent is introduced, not a case's name."""
    title_tokens = tokenize(title)
    named = [f for f in matches(title_tokens) if f.category == "agents" and f.meaning not in ("ego", "none")]
    if not named:
        return False
    words = [t.word for t in title_tokens]
    referred = re.search(r"\b(him|her|he|she|them)\b", rest, re.I) is not None  # "you gave him room"
    definite = [f for f in named if f.start > 0 and words[f.start - 1] in DEFINITE or referred]
    if not definite:
        return False
    again = {f.meaning for f in matches(tokenize(rest)) if f.category == "agents"}
    return not any(f.meaning in again for f in definite)


def _compose(r: _Reader, junction: bool, has_crosswalk: bool) -> tuple[list[list[Agent]], set[str]]:
    names = _Namer()
    ego_entity = next((e for e in r.entities if e.is_ego), None)
    stage_count = 1 + max([e.stage for e in r.entities] + [a[0] for e in r.entities for a in e.actions] + [0])
    stages: list[list[Agent]] = [[] for _ in range(stage_count)]
    ego_action = _ego_class(ego_entity, 0, junction) if ego_entity else None
    first_act = 0  # "the light's gone green, and the ego is swinging left": nothing said of the ego before the
    # stage begins, so the turn it first makes is its action, on its line in the first stage (the ego's one route
    # binds a later turn only after a first-stage stop)
    if ego_entity is not None and ego_action in (None, "move"):  # "approaches the junction, and as soon as it
        # reaches it turns right": driving up to the junction is the way into the turn, not a manoeuvre of its own
        first_act = next((k for k in range(1, stage_count) if any(a[0] == k and a[1] == 2 and a[2] > 0
                                                                  for a in ego_entity.actions)), 0)
        if first_act and _ego_action(ego_entity, _ego_class(ego_entity, first_act, junction),
                                     first_act) in V.TURN_ACTIONS:
            ego_action = _ego_class(ego_entity, first_act, junction)
        else:
            first_act = 0
    ego_type = ego_entity.type if ego_entity else "car"
    ego = Agent(name="ego", type=ego_type if ego_type in V.EGO_TYPES else "car", is_ego=True,
                action=_ego_action(ego_entity, ego_action, first_act),
                behavior=(ego_entity.behavior if ego_entity and ego_entity.behavior else V.DEFAULT_BEHAVIOR),
                speed=ego_entity.speed if ego_entity else None)
    stages[0].append(ego)
    if ego_entity is not None:
        last = ego.action
        for k in range(first_act + 1, stage_count):
            if any(a[0] == k and a[1] == 2 and a[2] > 0 for a in ego_entity.actions):
                action = _ego_action(ego_entity, _ego_class(ego_entity, k, junction), k)
                if action == last and action in ("stop", "go_straight"):
                    continue  # "stopped at red ... kept the vehicle stopped until ...", "the van is then passed by
                    # the ego": still so, nothing new
                    # (a second lane change the same way is a manoeuvre of its own)
                last = action
                if language_allows_later_ego():
                    stages[k].append(Agent(name="ego", type=ego.type, is_ego=True, action=action))
                else:
                    r.notes.append(f"left out: the ego's later action ({action}): the language cannot yet say "
                                   "that the ego acts in a later stage")
    positions: dict[int, str] = {}
    oncoming: set[str] = set()
    resolved: dict[int, tuple[str, str]] = {}
    for e in r.entities:
        group = e.parent or e
        if group.uncounted and "parked" in group.features and e.type not in V.VULNERABLE_TYPES and e.count > 0 and \
                not e.is_ego and all(a[4] in ("stop", "move") for a in e.actions) and not e.label:
            e.count = 0  # "residential street, parked cars, dusk": the street's scenery, said with no count
            r.notes.append(f"left out: '{e.head}' parked, with no count, are the street's scenery")
        if e.count > 0 and _said_in_general(r, e):
            e.count = 0  # "pedestrians step off the kerb here ... we watched an elderly man cross": said in general
            r.notes.append(f"left out: '{e.head}', with no count, said of such road users in general")
        if e.count > 0 and _the_vehicles_named_before(r, e):
            e.count = 0  # "a car from his right and a van ... collided, vehicles blocking the intersection": those two
            r.notes.append(f"read '{e.head}s' as the vehicles named before")
        if e.count > 0 and _names_the_case_in_a_heading(r, e):
            e.count = 0  # "Hazard H-22: pedestrian emerging from behind parked vehicles. ... a child steps out"
            r.notes.append(f"read the heading's '{e.head}' as the case's name")
        if e.count > 0 and not e.is_ego and e.parent is None and not e.label and _said_of_a_habit(r, e):
            e.count = 0  # "Cyclists use this road a lot", "There's usually a lollipop lady there": what is usual
            r.notes.append(f"left out: '{e.head}' is said of what usually happens there, not of this scene")
        if e.count > 0 and not e.is_ego and _left_for_later(r, e):
            e.count = 0  # "Maybe add a police car later but not for v1": asked for another version, not this one
            r.notes.append(f"left out: '{e.head}' is asked for later, not in this scene")
        if e.count > 0 and "no_part" in e.features:
            e.count = 0
            r.notes.append(f"left out: '{e.head}' is said to be no part of the scene")
        if e.count > 0 and _came_after_the_crash(r, e):
            e.count = 0  # "a car ran the red and hit me. An ambulance came later": help after it, not the scene
            r.notes.append(f"left out: '{e.head}' came after the collision the text tells of")
        elif e.count > 0 and _kept_off_the_road(r, e):
            e.count = 0  # "my sister's jeep is still in the shop", "two cars rusting in her father's yard"
            r.notes.append(f"left out: '{e.head}' is kept off the road, at home or in a yard")
        elif e.count > 0 and _towed_away(r, e):
            e.count = 0  # "... hit the front of client's car. Vehicle was towed from the scene.": after it, no one new
            r.notes.append(f"left out: '{e.head}' is only towed away after the collision")
        elif e.count > 0 and _called_out(r, e):
            e.count = 0  # "EMS + PD dispatched 14:03": called to the scene, not in it
            r.notes.append(f"left out: '{e.head}' is only called out to the scene")
        elif e.count > 0 and _police_as_a_source(r, e):
            e.count = 0  # "Police are appealing for witnesses", "Leicestershire Police say": they speak of it
            r.notes.append(f"left out: '{e.head}' speak of the scene, and are not on the road")
        if e.type == "pedestrian" and e.count > 0 and not e.label and _tells(r, e):
            e.count = 0  # "Several residents told us that turning right out of Quay Street feels unsafe"
            r.notes.append(f"left out: '{e.head}' tell of the place, and are not on the road")
        if e.type == "pedestrian" and e.count > 0 and not e.actions and not e.features and not e.label and \
                _said_to_do_no_road_thing(r, e):
            e.count = 0  # "someone should fix that junction", "the workers at the depot say": nobody on the road
            r.notes.append(f"left out: '{e.head}' does nothing on the road")
        if e.type == "pedestrian" and e.head in ANY_PERSON | {"passenger", "passengers"} and e.count == 1 and \
                not e.actions and not e.features and not e.label and \
                ([t.word for t in r.tokens[e.said_at + 1:e.said_at + 3]] == ["on", "board"] or
                 [t.word for t in r.tokens[e.said_at + 1:e.said_at + 2]] == ["aboard"]):
            e.count = 0  # "Someone on board filmed it": a passenger, nobody on the road
            r.notes.append(f"left out: '{e.head}' is on board, not on the road")
        if e.type == "pedestrian" and (e.definite or _said_aboard(r, e)) and e.head in KIN and e.count > 0 and \
                not e.actions and not e.features and not e.label and any(t.word in SPEAKERS for t in r.tokens):
            e.count = 0  # "we sat at the red light ... the kids were fascinated": the speaker's own, on board
            r.notes.append(f"left out: 'the {e.head}', doing nothing on the road, ride with the speaker")
        if e.type in ("pedestrian", "police") and e.count > 0 and not e.actions and not e.features and \
                not e.label and e.relative_to is None and e.parent is None and (
                    e.named_of is None and e.head in NAMED_BY_ROLE or e.type == "pedestrian" and e.head in ANYONE and
                    e.count == 1 and not any(x.relative_to is e for x in r.entities)):
            e.count = 0  # "driving like a proper lunatic he was", "the cop said it was 50/50": no one on foot;
            # "waving somebody through", "started with someone misjudging the speed": no one in particular
            r.notes.append(f"left out: '{e.head}' does nothing and is nowhere in the scene")
        if e.definite and e.count == 1 and e.type != "pedestrian" and not e.features and \
                not [a for a in e.actions if a[2] > 0] and not e.label and e.relative_to is None and \
                e.parent is None and e.named_of is None and not any(x.relative_to is e for x in r.entities) and \
                not _an_unknown_verb_after(r, e) and not _object_of_a_deed(r, e):
            # "reg noted for the police", "the van was nowhere to be seen": a vehicle named with 'the' as one known,
            # said of nothing before, with no place and no doing, is none of the scene's
            e.count = 0
            r.notes.append(f"left out: 'the {e.head}', named as if known, is nowhere and does nothing in the scene")
        if e.type == "pedestrian" and "on_board" in e.features and e.count > 0:
            e.count = 0  # "the kids arguing in the back": passengers of the ego, nobody on the road
            r.notes.append(f"left out: '{e.head}' rides in the ego's car (a passenger, no agent)")
        if e.type not in V.VULNERABLE_TYPES and e.count > 0 and not e.actions and not _placed(e) and \
                _a_load(r, e):
            e.count = 0  # "in the truck with a tractor on the back", "a Fiesta ... on the back of the truck"
            r.notes.append(f"left out: '{e.head}' is carried, not driven")
    others = [e for e in r.entities if not e.is_ego and e.count > 0]
    target_side = ego.action.rsplit("_", 1)[-1] if ego.action.startswith("change_lane") else None
    for e in others:  # "the HGV in lane one had to pull out into lane two": lanes count from the kerb
        into = next((int(f[10:]) for f in sorted(e.features) if f.startswith("into_lane_")), None)
        own = next((int(f[5:]) for f in sorted(e.features) if f.startswith("lane_") and f[5:].isdigit()), None)
        said = any(a[4] in ("lane_left", "lane_right") or a[4] in ("lane_change", "cut_in") and a[5] for a in e.actions)
        if into is not None and own is not None and into != own and not said:  # "to the right into lane 2": said
            e.actions.append((e.stage, 2, ACTION_RANK["cut_in"] + 1, r.tick(), "lane_right" if into > own else
                              "lane_left", None))
    if target_side and _joins_from_a_ramp(r.tokens):
        for e in others:  # "merges left onto the highway; trucks in the highway's right lane": on the ego's left
            if e.type not in V.VULNERABLE_TYPES and not e.features & {
                    "bare_left", "bare_right", "road_left", "road_right", "road_straight", "cross_road"}:
                e.features -= {"side_left", "side_right"} | {f for f in e.features if f.startswith("lane_")}
                e.features.add(f"side_{target_side}")
    _compass_places(others, ego_entity)  # "the AV was travelling north ... a van heading south": oncoming
    _typology_places(r, others)
    if ego_entity is not None and "first_in_line" in ego_entity.features:
        for e in others:  # "three cars including the ego wait, the ego is first": the others queue behind it
            group = e.parent or e
            if group.includes_ego and not e.features & {"ahead", "behind"}:
                e.features.add("behind")
    for e in others:
        action, direction = _intro_action(e)
        on_foot = bool(e.aliases & NAMED_ON_FOOT) or any(  # "a woman ... the pedestrian stopped": named as one on
            t.word in ON_FOOT_WITH for t in r.tokens[e.said_at + 1:e.said_at + 3]) or \
            _waits_where_people_wait(r, e) or bool(e.features & {"crosswalk", "on_sidewalk"})
        # foot; "a man pushing a pram"; "a woman waiting at the bus stop"; "a man on the crosswalk"
        if e.type == "pedestrian" and e.head in VAGUE_PEOPLE and not on_foot and (action in VEHICLE_ONLY_ACTIONS or any(
                a[4] == "horn" for a in e.actions)):
            e.type = "car"  # "someone's pulling out of a parking spot", "the guy behind me honked": someone driving
            r.notes.append(f"inferred: '{e.head}' who {DONE_AT_A_WHEEL.get(action or 'horn', 'drives')} drives a car")
        elif e.type == "pedestrian" and e.head in VAGUE_PEOPLE and not on_foot and (action in (
                "move", "stop", "go_straight") or action is None and "behind" in e.features) and \
                e.features & {"ahead", "behind"} and not e.features & {"on_sidewalk", "crosswalk", "in_road",
                                                                       "shoulder", "sidewalk"} \
                and e.road_type not in ("sidewalk", "shoulder"):
            e.type = "car"  # "the guy behind me went into the back of me": a driver in the traffic queue
            r.notes.append(f"inferred: '{e.head}' behind or ahead in the lane drives a car")
        elif e.type == "pedestrian" and e.head in VAGUE_PEOPLE and not on_foot and e.road_type is None and (
                e.features & {"overtaking", "lane_said"} or
                e.features & {"level", "road_straight"} and action in ("move", "go_straight")):
            e.type = "car"  # "the guy in the right lane sped up", "guy overtakes a whole line of traffic", "the guy
            # next to me on the left just runs the light", "this guy coming the other way just floors it": in a lane,
            # passing, level in traffic or coming the other way, at a wheel
            r.notes.append(f"inferred: '{e.head}' in a lane of traffic drives a car")
        if e.type == "pedestrian" and action == "stop" and not e.features & {"crosswalk", "in_road", "waits_to_cross"} \
                and _waits_where_people_wait(r, e):
            e.features.add("on_sidewalk")  # "a woman waiting at the bus stop": standing on the pavement
        action = _sideways(action, junction)
        if e.type == "cyclist" and junction and action in (None, "move") and "ahead" in e.features and \
                e.features & {"from_left", "from_right", "road_left", "road_right"}:
            action = "cross"  # "a cyclist from the left ran the red right in front of me": across the ego's path
        action = _sideways(action, junction)
        if "into_ego_lane" in e.features and e.type == "pedestrian":
            action = "cross"  # "a child runs into the ego's path"
        if e.type == "pedestrian" and action in (None, "move") and "on_sidewalk" not in e.features:
            action = "cross"  # people on foot in the road cross it
        if "into_ego_lane" in e.features and (action in ("move", "lane_change") or
                                               action is None and e.type not in V.VULNERABLE_TYPES):
            action = "cut_in"  # "moves from the left lane into the ego's lane"
        bare = next((side for side in SIDES if f"bare_{side}" in e.features), None)
        if "turned_in_front" in e.features:  # said of one on the ego's side: it came out of that side's road
            e.features.add("across_path" if bare and junction else "ahead")
        turn_side = action[5:] if action in ("turn_left", "turn_right") else direction if action == "turn" else None
        if junction and bare and turn_side == bare and not e.features & {
                "ahead", "behind", "across_path", "from_left", "from_right", "road_left", "road_right", "from_lane"} \
                and not any(a[4] == "move" for a in e.actions):  # "a bus approaching from my right turns right"
            e.features.add("level")  # "a van on my left turning left": beside the ego, turning off its own side
        if junction and action == "cut_in" and bare and not e.features & {"ahead", "behind", "level", "from_lane",
                                                                          "into_ego_lane", "overtaking"}:
            e.features.add(f"road_{bare}")  # at a crossroads, "a taxi on our right waiting to pull out": its road
        if action in ("cut_in", "lane_change") and (_placed(e) and e.features & {"road_left", "road_right",
                                                                                 "road_straight", "cross_road"}):
            action = "move"  # "pulled out of a side road on the left": a junction road, no lane change
        if action == "cut_in" and direction and "into_ego_lane" not in e.features:
            action = "lane_" + direction  # "swings into the right lane"
        passes = next((side for side in SIDES if f"passes_{side}" in e.features), None)
        if passes is None and action == "cut_in" and not e.is_ego and {"moves_out", "overtaking"} <= e.features \
                and _side_of(e.features) is None and "ahead" not in e.features:
            passes = _overtaking_side("side_of_an_overtaker")  # "a pickup pulled out to overtake me": out of the
            e.features.add("behind")  # ego's lane behind it, to the overtaking side
        if passes and action == "cut_in" and "moves_out" in e.features:
            action, direction = "lane_" + passes, passes  # "pulled out to overtake me on the right"
        if e.road_type == "shoulder" and action is None and e.type not in V.VULNERABLE_TYPES:
            action = "stop"  # "a tractor-trailer on the right shoulder, no flashers": standing there
        if e.road_type == "shoulder" and action == "stop" and e.type not in V.VULNERABLE_TYPES and \
                not e.features & {"ahead", "behind", "level", "overtaking"}:
            e.features.add("ahead")  # "a tractor-trailer on the right shoulder, hazards on": one the ego comes up to
        if "overtaking" in e.features and not e.is_ego and _one_lane_with_oncoming(r.tokens) and \
                _side_of(e.features) is None and "lane_said" not in e.features and not {
                    "lanes", "dual", "motorway", "highway", "freeway", "expressway"} & {t.word for t in r.tokens}:
            e.features.add("over_the_centre_line")
        position, is_oncoming = _position(e, action, junction, has_crosswalk, target_side)
        resolved[e.key] = (action, direction)
        positions[e.key] = position
        parked_beside = position in ("front_left", "front_right") and e.type not in V.VULNERABLE_TYPES and (
            action == "stop" and "parked" in e.features and "lane_said" not in e.features
            or action == "stop" and "ahead" in e.features and not e.features & {"lane_said", "from_lane"})
        # "a parked bus on the right", "a school bus stopped ahead on our right": at the kerb, no lane of its own
        # (but "a bus stopped at a bus stop in the right lane ahead" is in a lane)
        if is_oncoming or parked_beside:
            oncoming.add(e.key)
    for e in others:  # "in front of a truck", "the driver got out of the van on the left": at the truck's
        # (the van's) place, unless the text placed it itself
        t = e.relative_to
        if t is None or t.key not in positions:
            continue
        if e.road_type == "shoulder" and t.road_type is None and not _placed(t) and \
                t.type not in V.VULNERABLE_TYPES and resolved[t.key][0] in ("stop", None):
            positions[t.key] = positions[e.key]  # "a patrol car stopped on the shoulder ahead, parked behind a
            t.road_type = "shoulder"  # pickup it has pulled over": the pickup stands on the shoulder too
            continue
        if _placed(e) and positions[e.key] in SIDES and e.type == "pedestrian" and e.relative_how == "level" and \
                positions[t.key].startswith(("front", "back")) and not e.features & {"ahead", "behind", "level"}:
            positions[e.key] = positions[t.key].split("_")[0] + "_" + positions[e.key]  # "on the sidewalk to the
            continue  # right, level with the bus" (a bus ahead): on that side, where the bus is
        if not _placed(e):
            positions[e.key] = positions[t.key]
            if "on_sidewalk" in e.features and positions[t.key] in ("front", "back"):
                positions[e.key] += "_" + UNSPECIFIED["side_of_a_sidewalk_walker"]  # "two people on the sidewalk
                # next to it" (a bus stopped ahead): on the pavement beside it, off the ego's lane
            if t.road_type == "shoulder" and e.road_type is None and e.type not in V.VULNERABLE_TYPES and \
                    resolved[e.key][0] in ("stop", None):
                e.road_type = "shoulder"  # "a cop car pulled up behind it" (a lorry on the hard shoulder): there too
            if t.key in oncoming or positions[e.key] in ("front_left", "front_right") and \
                    e.type not in V.VULNERABLE_TYPES and "parked" in e.features and "lane_said" not in e.features:
                oncoming.add(e.key)  # (no lane of its own where the other needs none; "occluded by a parked van": at
                # the kerb the crosser comes from)
        elif not _placed(t) and not (t.type not in V.VULNERABLE_TYPES and t.features & {"ahead", "behind"}):
            positions[t.key] = positions[e.key]  # ... and the truck, placed nowhere itself, is where the text put
            # the other (but "a boy darted onto the crossing from behind a bus which had stopped just ahead of me",
            # "a kid ran out from in front of the bus we went around": the bus stands in the ego's lane, as said)
    oncoming_names: set[str] = set()
    for e in others:
        action, direction = resolved[e.key]
        position = positions[e.key]
        final = _final_action(e, action, direction, position)
        if final == "stop" and position not in FACING_THE_EGO and _only_braked(r, e):
            final = "go_straight"  # "the pickup following us also braked", "the sedan from the left braked, TA 1.4 s":
            # a reaction; it slows and drives on (one ahead braking is the hazard, its stop)
        road_type = e.road_type or V.default_road_type(e.type)
        if road_type not in V.ROAD_TYPES_BY_TYPE[e.type]:
            road_type = V.default_road_type(e.type)
        if final == "on_the_sidewalk":
            road_type = "sidewalk"
        behavior = e.behavior or V.DEFAULT_BEHAVIOR
        first_name = None
        for n in range(e.count):
            if "both_sides" in e.features and "ego_lane" not in e.features:  # "cars cutting in from different
                # directions": one on each side; "a bus ahead in our lane" is in neither
                side = SIDES[n % 2]
                moving_in = action in ("cut_in", "lane_change", "block")  # "cars on both sides" alone: level
                placed = {f"from_{side}"} if junction else {f"side_{side}"} | ({"from_lane"} if moving_in else set()) | (
                    {"ahead"} if moving_in and not e.features & {"behind", "level", "overtaking"} or
                    "ahead" in e.features else set())
                member = Entity(e.key, e.type, False, e.stage, features=(e.features - {"both_sides"}) | placed,
                                road_type=e.road_type)
                position, _ = _position(member, action, junction, has_crosswalk, target_side)
                final = _final_action(member, action, direction, position)
                first_name = None
            name = names(e.type)
            stages[e.stage].append(Agent(name=name, type=e.type, action=final, behavior=behavior,
                                         relative_to_ego=position, road_type=road_type, behind=first_name and
                                         previous_name, trigger=e.trigger, speed=e.speed,
                                         gap_m=e.gap_m if n == 0 else None))
            first_name = first_name or name
            previous_name = name
            if e.key in oncoming:
                oncoming_names.add(name)
    return [s for k, s in enumerate(stages) if s or k == 0], oncoming_names


def _joins_from_a_ramp(tokens: list[Token]) -> bool:
    """'comes down the on-ramp', 'joined from the slip road': the ego merges onto a road whose lanes lie all on the
    side it merges to; a lane the text names by that road's own sides ('its right lane') is still on that side."""
    words = [t.word for t in tokens]
    return "ramp" in words or any(a == "slip" and b in ("road", "lane") for a, b in zip(words, words[1:]))


def _ego_class(e: Entity, stage: int, junction: bool) -> str | None:
    """The ego's action class in a stage, read against the junction context. 'Turning left out of the side
    road, the ego waited, then went': it waits in the first stage and makes its turn in the later one."""
    action, direction = _action(e, stage)
    later = [a for a in e.actions if a[0] > stage and a[1] == 2 and a[2] > 0]
    waits = [a for a in e.actions if a[0] == stage and a[1] == 2 and a[4] == "stop"]
    if later and waits and action in ("turn", "turn_left", "turn_right", "u_turn", "lane_left", "lane_right",
                                      "sideways_left", "sideways_right"):  # "pulls up ... and needs to go right"
        return "stop"
    held = [a for a in e.actions if a[0] == stage and a[1] == 2 and a[4] in ("move", "go_straight", "stop")]
    if action in ("lane_left", "lane_right") and held and any(a[4] in ("lane_change", "cut_in") and a[5] is None
                                                              for a in later):
        return max(held, key=lambda a: (a[2], a[3]))[4]  # "wants to move into the right lane ... holds its lane
        # until it passes, and then makes the lane change": the change is made in the later stage
    if later and waits and action in ("move", "go_straight") and later[0][4] in ("move", "go_straight"):
        return "stop"  # "had stopped at the line, intending to go straight. After V2 had passed, V1 proceeded"
    if stage > 0 and (action in ("move", "go_straight", None) or action == "cut_in" and direction is None and junction):
        # ("waits for both, then pulls out": into the junction)
        before = [a for a in e.actions if a[0] < stage and a[1] == 2 and a[4] in ("turn_left", "turn_right")]
        if before and any(a[0] == stage for a in e.actions) and any(
                a[0] == stage - 1 and a[4] == "stop" and a[1] == 2 for a in e.actions):
            return before[-1][4]  # "... then went": the turn it waited to make
    if action in ("turn", "u_turn") and direction is None and waits and "turn_intended" in e.features:
        return "stop"  # "stationary at the line, waiting to turn out": it stands; which way it would turn is unsaid
    action = _sideways(action, junction)
    if action == "cut_in" and direction is None and junction:
        return "move"  # "pull out at the stop sign to go straight": into the junction, no lane change
    return action


def _heading(e: Entity) -> str | None:
    """The one compass heading an agent is given; none when given several ('northbound ... the east curb ... east
    to west'): which is its own is not known, and taking any one of a set would read the text differently from
    one run to the next."""
    headings = [f for f in sorted(e.features) if f.startswith("compass_")]
    return headings[0] if len(headings) == 1 else None


def _placed(e: Entity) -> bool:
    return bool(e.features & {"side_left", "side_right", "front_left", "front_right", "back_left", "back_right",
                              "road_straight", "road_left", "road_right", "destination", "crosswalk",
                              "from_left", "from_right"})


def _sideways(action: str | None, junction: bool) -> str | None:
    """'goes right': a turn at a junction, a lane change elsewhere."""
    if action and action.startswith("sideways_"):
        side = action.rsplit("_", 1)[-1]
        return f"turn_{side}" if junction else f"lane_{side}"
    return action


def _ego_action(e: Entity | None, action: str | None, stage: int) -> str:
    if e is None or action is None:
        return "go_straight"
    direction = next((a[5] for a in sorted(e.actions, key=lambda a: -a[1]) if a[0] == stage and a[4] == action),
                     None)
    if action in ("turn_left", "turn_right", "stop"):
        return action
    signalled = next((s for s in SIDES if f"signals_{s}" in e.features), None)
    if action in ("turn", "u_turn"):
        meant = next((a[4].rsplit("_", 1)[-1] for a in e.actions if a[0] < stage and a[4] in (
            "turn_left", "turn_right", "sideways_left", "sideways_right")), None)  # "... then makes the turn"
        return f"turn_{direction or signalled or meant or UNSPECIFIED['turn_direction']}"
    if action in ("lane_left", "lane_right"):
        return f"change_lane_to_{action[5:]}"
    if action in ("lane_change", "cut_in"):
        direction = direction or signalled
        said = next((a[4].rsplit("_", 1)[-1] for a in sorted(e.actions, key=lambda a: a[0] != stage)
                     if a[0] <= stage and a[4] in ("lane_left", "lane_right", "sideways_left", "sideways_right")),
                    None)  # "merging ... move right"; "wants to move into the right lane ... then makes the change"
        inward = next((x for x in SIDES if f"in_lane_{SIDES[1 - SIDES.index(x)]}" in e.features), None) \
            if "to_the_middle" in e.features else None  # "in the right-hand lane ... moves into the middle lane": left
        moves = ("lane_change", "cut_in", "lane_left", "lane_right")
        out = max((a for a in e.actions if a[0] < stage and a[4] in moves), key=lambda a: a[0], default=None) \
            if f"returns_{stage}" in e.features and not direction else None
        if out is not None:  # "pulled out to pass it ... then pulled back in": back to the side it left
            return f"change_lane_to_{OTHER_SIDE[_ego_action(e, out[4], out[0]).rsplit('_', 1)[-1]]}"
        return f"change_lane_to_{direction or said or inward or _overtaking_side('ego_lane_change_direction')}"
        # ("pulling out": the side one overtakes on)
    return "go_straight"


def _unknown(r: _Reader) -> list[str]:
    lex = lexicon()
    out = []
    for t in r.tokens:
        if t.misspelt:
            out.append(f"{t.misspelt} (read as {t.word})")
            continue
        if t.index in r.used or t.word == "," or read_number(t.word) is not None:
            continue
        if t.word in lex.function_words or t.base in lex.vocabulary or t.word in lex.vocabulary:
            continue
        near = lex.nearest(t.word)
        out.append(f"{t.word} (did you mean {near}?)" if near else t.word)
    return list(dict.fromkeys(out))


def _template(kind: str, seed: int, notes: list[str]) -> tuple[Scenario, dict[str, Comment]]:
    """The kind's scene for this seed, drawn from its distribution (sampling.py), with a comment per choice."""
    from ttsgc.lowering.sampling import has_distribution, sample_kind

    if not has_distribution(kind):
        raise LoweringError(f"no distribution for the scene kind '{kind}' (templates/kinds/{kind}.toml)")
    sampled = sample_kind(kind, seed)
    notes += sampled.notes
    return sampled.scenario, dict(sampled.scenario.comments)


def _merge_road(template: RoadSpec, said: RoadSpec) -> RoadSpec:
    """What the prompt says about the road wins over the kind's defaults."""
    default = RoadSpec()
    merged = template.model_dump()
    for key, value in said.model_dump().items():
        if value != getattr(default, key):
            merged[key] = value
    return RoadSpec.model_construct(**merged)
