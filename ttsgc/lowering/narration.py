"""The scene's narration inside the document that carries it, and who the narration's ego is.

People write scenes inside other documents: an email with a greeting and a signature, a deposition whose
counsel object between answers, an app review headed by its rating. The frame around the account names people
and vehicles that are no part of the scene ("Cheers, Dana, Fleet Operations"), so it is taken off before the
parser reads the text.

The ego is often not "I": a fleet manager writes about "van 214 (driver Marek Nowak)" and says "our van is the
ego"; a passenger writes "my driver eased off". Mentions of the ego's vehicle and of its driver (by role, by
name, and the driver's pronoun) are read as the ego, spelled out as "the ego" for the parser.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache

from ttsgc import vocabulary as V
from ttsgc.lowering.lexicon import AT_THE_WHEEL_NAME, SLUGLINE, driver_named, known_word, lexicon, matches, tokenize

SALUTATION = re.compile(r"^\s*(?:(?:hi|hello|hey|hiya|dear|greetings|hallo|good\s+(?:morning|afternoon|evening|day)|"
                        r"morning|afternoon|evening)\b[^.!?,\n]{0,40}[,!]?|(?:hi|hello|hey|hiya|dear|greetings|hallo|"
                        r"good\s+(?:morning|afternoon|evening|day))\b"
                        r"[^.!?,\n]{0,40}[,!/][^.!?\n]{0,30}[,!]|to whom it may concern[,:]?)\s*$", re.I)
# "Hi team,", "Dear simulation team,", "Hallo zusammen / hi all,", "Morning,", "Good morning, team,": never
# "Morning rush hour on the M4"
CLOSING = re.compile(r"^\s*(?:cheers|thanks|thank you|many thanks|thanks a lot|thanks in advance|thx|ta|best|"
                     r"all the best|best wishes|best regards|kind regards|warm regards|warmest regards|regards|"
                     r"sincerely|yours(?: sincerely| faithfully| truly)?|take care|speak soon|talk soon|br|"
                     r"with thanks|respectfully|mit freundlichen gr(?:\u00fc|ue)(?:\u00df|ss)en|"
                     r"(?:viele|liebe|beste) gr(?:\u00fc|ue)(?:\u00df|ss)e)\b[\s,.!]*(?:\S+)?[\s,.!]*$", re.I)
RATING = re.compile(r"^\s*(?:(?:[0-5](?:\.5)?|one|two|three|four|five)\s*(?:/\s*5\s*)?stars?|[0-5]\s*/\s*5|"
                    r"[\u2605\u2606\u2B50]+)\s*[!.,:;\-]*\s*", re.I)
SPEAKER = re.compile(r"^\s*((?:[A-Z][A-Z.'\-]*\s?){1,4}):\s*", re.M)  # "MR. PRICE:", "THE COURT:"
QA_LABEL = re.compile(r"^\s*(Q|A|QUESTION|ANSWER|THE WITNESS|AGENT|CALLER|CUSTOMER|OPERATOR|INTERVIEWER|"
                      r"HANDLER|CLAIMANT|INSURED|REP)\s*(?::|\.(?=\s))\s*", re.I)
ASKERS = {"Q", "QUESTION", "AGENT", "OPERATOR", "INTERVIEWER", "HANDLER", "REP"}  # who asks, in a transcript
NEGATIVE_ANSWER = re.compile(r"^\s*(?:no(?:\s+[a-z]+){0,2}|none|nobody|no one|nothing|not yet|not then|"
                             r"not that i (?:saw|could see|know of)|i (?:could not|couldn't|can't|cannot) (?:tell|say)|"
                             r"i (?:don't|do not) (?:know|remember|recall)|not sure|i'm not sure|i am not sure|"
                             r"there (?:was|were) none)\b(?:,?\s*(?:sir|ma'am))?\s*(?:[.!]|$)", re.I)
TELL_US = re.compile(r"^\s*(?:(?:please|now|okay|ok|so|and),?\s+)*(?:tell|show) (?:us|me|the jury|the court)\s+"
                     r"(?:what|how|where)\s+", re.I)
HOW_MANY = re.compile(r"\bhow many ([a-z]+)\b", re.I)  # "How many lanes ...?"
NUMBER_ANSWER = re.compile(r"^\s*(\d{1,2}|one|two|three|four|five|six|seven|eight|nine|ten)\b[\s.,!]*", re.I)
ASKS_FOR_OTHERS = re.compile(r"\b(?:any|other|anyone|anybody|anything)\b|\b(?:was|were|is|are) there\b|"
                             r"\bdid you (?:see|notice|spot|observe)\b", re.I)
# "Were there other cars?", "Was there a bus behind you?", "Did you see his car?": a question of what was there
EXISTENTIAL = re.compile(r"\b(?:any|anyone|anybody)\b|\b(?:was|were|is|are) there\b", re.I)

VEHICLE_NOUNS = {"van": "car", "cab": "car", "taxi": "car", "car": "car", "vehicle": "car", "minibus": "bus",
                 "pickup": "car", "suv": "car", "truck": "truck", "lorry": "truck", "hgv": "truck", "bus": "bus",
                 "coach": "bus", "motorcycle": "motorcycle", "motorbike": "motorcycle", "scooter": "motorcycle",
                 "moped": "motorcycle"}
EGO_NOUN = {"car": "the ego", "truck": "the ego truck", "bus": "the ego bus", "motorcycle": "the ego motorcycle"}
_NOUN = r"(van|cab|taxi|car|vehicle|minibus|pickup|suv|truck|lorry|hgv|bus|coach|motorcycle|motorbike|scooter|moped)"
DECLARATION_PATTERN = (
    r"(?:,\s*|\b(?:with|using|having)\s+)?\b(?:(?:our|the|my|this|that)\s+)?(?:(?P<adjective>[a-z]+)\s+)?" + _NOUN +
    r"(?:\s+(?:no\.?\s*|#)?(?P<number>\d+))?\s+(?:as|is|=|being|should be|will be|as the|to be)\s+"
    r"(?:the\s+|our\s+)?(?:EGO_ROLE)\b"
    r"(?:\s+(?:vehicle|car))?(?:\s+for this)?(?:\s+please)?")
ROLE_BODIES = {"bus", "truck", "lorry", "van", "motorcycle", "motorbike", "taxi", "cab", "shuttle", "coach"}


@lru_cache(maxsize=1)
def _ego_roles() -> str:
    """The lexicon's names of the ego's role ('ego', 'SUT', 'AV', 'vehicle under test') as a pattern: no pronoun,
    no owner, no body of its own ('the ego truck' says more)."""
    roles = {" ".join(words) for words, (category, meaning) in lexicon().phrases.items()
             if category == "agents" and meaning == "ego" and len(" ".join(words)) > 1
             and words[0] not in ("my", "our", "your", "the", "i", "me", "we", "us", "you", "mine", "ours", "yours")
             and not ROLE_BODIES & set(words) and "'" not in " ".join(words) and not words[-1].startswith("participant")}
    return "|".join(r"\s+".join(map(re.escape, name.split())) for name in sorted(roles, key=len, reverse=True))


@lru_cache(maxsize=1)
def _declarations() -> tuple[re.Pattern, re.Pattern]:
    """'Our van is the ego', '... as the SUT', '... is the vehicle under test': a vehicle declared the ego by any
    name of the ego's role."""
    pattern = DECLARATION_PATTERN.replace("EGO_ROLE", _ego_roles())
    return re.compile(pattern, re.I), re.compile(pattern.replace(_NOUN, r"([a-z]+)"), re.I)
FLEET_ADJECTIVES = {"delivery", "box", "transit", "panel", "courier", "company", "work", "hire", "rental", "fleet",
                    "own", "passenger", "cargo", "parcel", "school", "city", "service"}
FLEET_NOUNS = r"van|cab|taxi|minibus|car|vehicle|unit|truck|lorry|bus|coach|motorcycle|motorbike|scooter"
FLEET_ONLY = {"van", "cab", "taxi", "minibus"}  # never a scenario's label ("car 1", "unit 2" are)
NOT_A_QUANTITY = r"(?!\s*(?:mph|km|kmh|kph|m\b|metres|meters|feet|ft|seconds|s\b|minutes|lanes?|%|percent|miles?))"
NAME = r"(?:[A-Z]'[A-Z][a-z]+|[A-Z][a-z]+(?:['\-][A-Z]?[a-z]+)?)"  # "Kelly", "O'Brien", "Smith-Jones"
FULL_NAME = rf"{NAME}(?:\s+{NAME}){{0,2}}"
DRIVER_NAMED = (re.compile(rf"\b(?i:driver|driven by)\s*:?\s+({FULL_NAME})"),  # "driver: Aisha Rahman", "driven by Sven"
                re.compile(rf"\(\s*({FULL_NAME})\s+(?:driving|at the wheel|behind the wheel)\s*\)"),  # "(Tom driving)"
                re.compile(rf"(?:^|[.!?,\n]\s*)({FULL_NAME})\s+(?:in|driving|at the wheel of)\s+the ego\b"))
LOWER_CASE_DRIVER = re.compile(r"\(\s*driver\s*:?\s+([a-z][a-z'\-]+(?:\s+[a-z][a-z'\-]+){0,2})\s*[),]|"
                               r"\(\s*([a-z][a-z'\-]+(?:\s+[a-z][a-z'\-]+)?)\s+driving\s*\)")
NOT_NAMES = {"The", "A", "An", "Our", "My", "His", "Her", "Their", "Van", "Cab", "Taxi", "He", "She", "It", "We",
             "I", "They", "This", "That", "Then", "On", "In", "At", "Yesterday", "Today", "Monday", "Tuesday",
             "Wednesday", "Thursday", "Friday", "Saturday", "Sunday", "Last", "No", "Driver"}
OTHER_PEOPLE = {"he": r"guy|man|boy|dude|bloke|lad|gentleman|fella|fellow|chap|husband|father|dad|son|brother|"
                      r"policeman|officer",
                "she": r"woman|lady|girl|mother|mom|mum|wife|daughter|sister|policewoman"}
AFTER_AN_OBJECT = r"and|or|but|nor|on|in|at|to|from|with|off|as|so|then|up|down|out|over|past|by|into|onto|again|too|" \
    r"just|before|after|while|when|until|till|through|across|around|round|behind|ahead|alone|now|there|here|" \
    r"because|since|for|the|a|an|go|pass|through|is|was|slowly|suddenly|completely"  # words that follow 'her' as an
# object ("overtakes her on the left"), not as an owner ("her son")
POSSESSED = r"(?:lane|left|right|way|path|front|side|mirror|wing|bumper|brakes?|direction|approach|exit|turn|rear|" \
            r"back|nose|bonnet|hood|door|windows?|wheel|speed|van|car|cab|taxi|truck|lorry|bus|vehicle|route|" \
            r"nearside|offside|view|line|mirrors|lights|horn|own|indicator|signal)"


@dataclass
class Narration:
    text: str
    notes: list[str] = field(default_factory=list)


SPOKEN_MARKS = (("full stop", "."), ("period", "."), ("comma", ","), ("colon", ":"), ("semicolon", ";"),
                ("question mark", "?"), ("exclamation mark", "!"), ("exclamation point", "!"),
                ("new paragraph", "."), ("new line", "."))
WAKE_WORDS = re.compile(r"^\s*(?:(?:hey|ok|okay)\s+(?:siri|google|alexa|car|assistant)|siri|alexa)\b[\s,]*"
                        r"(?:(?:take\s+a\s+)?note(?:\s+(?:that|this))?\b[\s,:]*)?|^\s*(?:take\s+a\s+)?note\b[\s,:]*"
                        r"(?=.*\b(?:comma|full stop)\b)", re.I)


def _dictated(text: str, notes: list[str]) -> str:
    """'hey Siri note a truck cut me off comma it was in the lane on my right full stop': speech to text says its
    punctuation in words; two or more such words are marks, and the wake words and 'note' before them are no
    part of the scene."""
    spoken = re.findall(r"\b(?:full stop|comma|period|colon|question mark|new line)\b", text, re.I)
    if len(spoken) < 2:
        return text
    text = WAKE_WORDS.sub("", text)
    for words, mark in SPOKEN_MARKS:
        text = re.sub(rf"\s*\b{words}\b", mark, text, flags=re.I)
    text = re.sub(r"^[\s.,:;]+", "", text)
    notes.append("read the spoken punctuation of a dictated note as marks")
    return text


RECORD_VEHICLE_KEY = re.compile(r"(?<![\w-])(?:veh|vehicle|unit|asset|subject)\s*:\s*(?=[^\s|])", re.I)


STATION = re.compile(r"\b([A-Z]{2,})_\d+\b")


def _event_record(text: str, notes: list[str]) -> str:
    """'Event: Harsh Braking | 2024-05-14 14:32:07 | Veh: Bus #77 | Spd 62 -> 19 km/h (x3)': a fleet system's
    record dates itself and counts its alerts (no agents), and its vehicle field names the vehicle the record is
    about, the ego; so do a report form's 'Vehicle:' field and a use case's 'Actor:'."""
    text = re.sub(r"\b(\d{1,2}:\d{2}):\d{2}(?:\.\d+)?\b", r"\1", text)  # seconds of a time stamp
    text = re.sub(r"\b([01]\d|2[0-3])([0-5]\d):[0-5]\d\b", r"\1\2 hrs", text)  # "0457:30": a log's time to the second
    text = STATION.sub(lambda m: m.group(0) if lexicon().phrases.get((m.group(1).lower(),), ("",))[0] == "agents"
                       else m.group(1), text)  # "XING_07 PED count=2": a sensor's name, no count (not "NPC_1")
    text = re.sub(r"\b(\d{1,2}:\d{2})\s*[-\u2013]\s*\d{1,2}:\d{2}\b", r"\1", text)  # a span of time
    text = re.sub(r"\b(?:\d{4}-\d{2}-\d{2}|\d{1,2}/\d{1,2}/\d{2,4})\b", " ", text)  # a date
    text = re.sub(r"\(\s*x\s?\d+\s*\)", " ", text)  # "(x3)": an alert's repeats
    if text.count("|") >= 2 and RECORD_VEHICLE_KEY.search(text):
        text = re.sub(r"\s*(?:->|\u2192|=>)\s*", " to ", text)  # "Spd 62 -> 19 km/h": from one speed to another
        key = RECORD_VEHICLE_KEY.search(text).group(0)
        text = RECORD_VEHICLE_KEY.sub("Ego: ", text, count=1)
        if key.lower().startswith("subject"):
            text = THE_SUBJECT.sub("the ego", text)  # "(subject's right)", "ahead of the subject"
        text = re.sub(r"\bEgo: (?:(?:unit|veh|vehicle|no)\b\.?|#)\s*#?\d*\s*(?:\(([^()]*)\))?",
                      lambda m: f"Ego: {m.group(1) or ''}", text, count=1, flags=re.I)
        # "Unit 212 (Ford Transit)": the van
        text = re.sub(r"\bspd\.?\s*:?\s*(\d+)(?:\s*to\s*\d+)?", r"doing \1", text, flags=re.I)  # its own speed
        text = re.sub(r"\s*\|\s*", ". ", text)  # each field said apart
        notes.append("read the record's vehicle field as the ego")
    elif re.search(r"(?:^|(?<=[.\n]))\s*(?:primary\s+)?actor\s*:", text, re.I) and \
            re.search(r"\b(?:preconditions?|main flow|trigger|postconditions?)\s*:", text, re.I):
        text = re.sub(r"((?:^|(?<=[.\n]))\s*)(?:primary\s+)?actor\s*:\s*", r"\1Ego: ", text, count=1, flags=re.I)
        notes.append("read the use case's actor as the ego")  # "UC-12 ... Actor: the automated vehicle (AV)."
    elif len(FORM_FIELD.findall(text)) >= 2 and RECORD_VEHICLE_KEY.search(text):
        text = RECORD_VEHICLE_KEY.sub("Ego: ", text, count=1)  # "Vehicle: Ford Focus pool car. Location: ..."
        notes.append("read the form's vehicle field as the ego")
    return text


FORM_FIELD = re.compile(r"(?:^|(?<=[.\n]))\s*(?:location|what happened|time|weather|conditions|date|route|driver|"
                        r"description|road|speed)\s*:", re.I)  # a report form's fields, each a label and its value


def read_narration(prompt: str) -> Narration:
    """The account a prompt gives, out of its document, with its ego's other names spelled as the ego."""
    notes: list[str] = []
    text = _event_record(_dictated(prompt, notes), notes)
    text = _gherkin(text, notes)
    text = _bug_report(text, notes)
    text = _chatbot_request(_tool_elements(text), notes)
    text = _without_letter_frame(text, notes)
    text = _testimony(text, notes)
    text = RATING.sub("", text, count=1) if RATING.match(text) else text
    text = _texting(text)
    text = _addressee(text, notes)
    text = _restarts(text, notes)
    text = _asides(_coach_as_a_title(text))
    text = _modelling_authors(_authors(text, notes), notes)
    text = _expectations(text, notes)
    text = _topic(text, notes)
    text = _passengers_bus(_awaited_bus(text), notes)
    text = _street_corners(_route_numbers(text))
    text = _ages(text)
    text = _side_street_named(_street_names(text))
    text = _named_at_the_wheel(text, notes)
    text = _designated_ego(_designations_spelt_alike(text), notes)
    text = _designated_groups(text, notes)
    text = _bare_appositions(text)
    text = _declared_ego(_ego_made_a_kind(_caller_at_the_wheel(text, notes)), notes)
    text = _observed_subject(text, notes)
    text = _learning_agent(text, notes)
    text = _call_sign_unit(_fleet_unit(text, notes), notes)
    text = _numbered_protagonist(text, notes)
    text = _vehicle_numbers(_abbreviated_bodies(text))
    text = _passengers_driver(_kin_at_the_wheel(text, notes), notes)
    text = _crews_vehicle(text, notes)
    text = _screenplay_driver(text, notes)
    text = _protagonist(text, notes)
    text = _party_at_the_wheel(text, notes)
    text = _storys_driver(text, notes)
    text = _tellers_beside_the_ego(text, notes)
    text = _moved_by_the_system(text)
    return Narration(text, notes)


NOT_ITS_BODY = r"(?!\s+(?:stop|stops|lane|lanes|bay|station|shelter|route|company)\b)"
ROUTES_DRIVER = r"(?:your|the)\s+driver\s+(?:on|of)\s+the\s+(?:first\s+|last\s+)?\d{1,3}\b"  # "your driver on the 24"
ON_A_BUS = re.compile(r"\b(?:(?:sat|sitting|seated)\s+(?:up|down)stairs|(?:up|down)stairs\s+at\s+the|top\s+deck|"
                      r"(?:i|we)(?:'m|'re|\s+am|\s+are|\s+was|\s+were)\s+(?:sat\s+|sitting\s+|riding\s+|"
                      r"travelling\s+|traveling\s+)?(?:on|aboard)\s+(?:the|our|this|a)\s+(?:bus|coach)\b" +
                      NOT_ITS_BODY +
                      r"|(?:i|we)\s+(?:rode|took|caught|got\s+on)\s+(?:the|our|a)\s+(?:bus|coach)\b" + NOT_ITS_BODY +
                      r"|(?:our|your)\s+(?:bus|coach)\b" + NOT_ITS_BODY + r"|overnight\s+coach|"
                      + ROUTES_DRIVER + r"|"
                      r"(?:from|out\s+of)\s+the\s+(?:bus|coach)\s+window\b|"
                      r"from\s+the\s+(?:bus|coach),?\s+(?:i|we)\s+(?:saw|watched|could\s+see|noticed)\b|"
                      r"from\s+the\s+top\s+deck\b|the\s+(?:school\s+)?(?:bus|coach)\s+(?:i|we)\s+"
                      r"(?:(?:was|were|am|are)\s+(?:on|in|riding|sitting|sat)|ride|rode|took|caught)\b|"
                      r"on\s+which\s+(?:i|we)\s+(?:was|were)\s+(?:a\s+)?passengers?\b)", re.I)
# ("from the bus window I watched", "the bus I was on", "the route 47 bus, on which I was a passenger")
ROUTE_RIDDEN = re.compile(r"\b(on|aboard|about|regarding|riding|rode|caught|boarded)\s+the\s+(?:number\s+)?"
                          r"\d{1,3}[a-z]?\b(?![\s-]*(?:mph|km|kph|miles?|m|metres?|meters?|feet|ft|yards?|%|am|pm|"
                          r"tonnes?|tons?|foot|lanes?|limit|zone|[:.]\d))", re.I)
ROUTE_DRIVER = re.compile(r"\bthe\s+(?:number\s+)?\d{1,3}[a-z]?\s+driver\b|"
                          r"\bdriver\s+of\s+the\s+(?:number\s+)?\d{1,3}[a-z]?\b" + NOT_A_QUANTITY, re.I)
# ("the 22 driver", "driver of the 9 came into the stop")
NOT_ANOTHERS_DRIVER = r"(?!\s+(?:of|in|ahead|behind|next|beside|to|here)\b)"  # (not "the driver of the van",
# "the driver in front")
ROUTE_TOLD = re.compile(r"\b(?:upstairs|downstairs|top\s+deck|up\s+top|(?:our|your)\s+driver|the\s+driver(?!\s+(?:in|"
                        r"ahead|behind|of|next|beside|to)\b)|passenger\s+on|"
                        r"(?:^|(?<=[.!?]\s))driver" + NOT_ANOTHERS_DRIVER + r")\b",
                        re.I)  # ("Driver hit the brakes": a sentence that opens on the driver, unnamed)
# a number ridden is a bus route when its driver is another ("the driver had to brake"; not "the driver in front")
OTHER_BUS = re.compile(r"(?<!on )\b(?:an?|another|other|second)\s+(?:[\w-]+\s+)?(?:bus|coach|buses|coaches)\b", re.I)
OUR_BUS = re.compile(r"\b(?:the|our|this)\s+(?:overnight\s+|night\s+|school\s+|city\s+|double[\s-]decker\s+)?"
                     r"(?:bus|coach|greyhound)\b" + NOT_ITS_BODY + r"|"
                     r"\b(?:the\s+)?number\s+\d{1,3}[a-z]?(?:\s+bus)?\b|\broute\s+\d{1,3}\b(?:\s+bus)?|"
                     r"\bthe\s+(?:first\s+|last\s+)?\d{1,3}[a-z]?\b(?=\s+(?:on|out|from|today|this|stopped|pulled|was|"
                     r"had|at|into))", re.I)
BUS_DRIVER = re.compile(r"\b(?:(?:our|your|my)\s+(?:bus\s+|coach\s+)?driver|the\s+(?:bus|coach)\s+driver|"
                        r"(?:^|(?<=[.!?]\s))driver)\b" + NOT_ANOTHERS_DRIVER, re.I)
# ("Driver hit the brakes": the passengers' driver, said bare at a sentence's opening)


ROUTE_NUMBER = re.compile(r"\b([Tt])he (\d{2,3}[a-z]?) (?=(?:turned|pulled|stopped|came|went|braked|drove|moved|"
                          r"set off|swung|cut|overtook|ran|sailed|flew|sped)\b)")


ROUTE_DRIVEN = re.compile(r"\b(driving|drove|drive|drives|driven)\s+the\s+(\d{1,3}[a-z]?)\b(?![\s-]*(?:mph|km|kph|"
                          r"miles?|m\b|metres?|meters?|feet|ft|yards?|%|am\b|pm\b|tonnes?|tons?|lanes?|[:.]\d))", re.I)


def _route_numbers(text: str) -> str:
    """'The 23 turned left out of Park Road and pulled up for us': a service named by its number, doing what
    vehicles do, is a bus (one its passengers tell of, 'our driver', is read with them); so is the one a teller
    drives in a text that speaks of a bus ('Driving the 42 down Queen St ... under the bus'; 'driving the 405' with
    no bus is a freeway)."""
    if ROUTE_TOLD.search(text):
        return text
    if re.search(r"\b(?:bus|buses|passengers?)\b", text, re.I):
        text = ROUTE_DRIVEN.sub(r"\1 the number \2 bus", text)
    return ROUTE_NUMBER.sub(lambda m: f"{m.group(1)}he number {m.group(2)} bus ", text)


COACH_TITLE = re.compile(r"\bCoach\s+([A-Z][a-z]+)\b")


def _coach_as_a_title(text: str) -> str:
    """'it's Coach Dana': a title before a name, no coach on the road ('Coach Station' stays a place)."""
    return COACH_TITLE.sub(lambda m: m.group(0) if known_word(m.group(1)) else m.group(1), text)


AT_A_STOP = re.compile(r"\b(?:i|we)(?:'d|'m|\s+was|\s+were|\s+had|\s+am)?(?:\s+been)?(?:\s+(?:stood|standing|waiting|"
                       r"sat|sitting))?\s+(?:at|in|by)\s+(?:the|my|our)\s+(?:bus\s+)?(?:stop|shelter)\b", re.I)


def _awaited_bus(text: str) -> str:
    """'I was stood at the bus stop ... still no sign of my bus', 'My bus was stood at the stop': the bus one
    waiting at a stop calls theirs is one they wait for, not one they drive."""
    return re.sub(r"\b([Mm])y bus\b", lambda m: "The bus" if m.group(1) == "M" else "the bus", text) \
        if AT_A_STOP.search(text) else text


def _passengers_bus(text: str, notes: list[str]) -> str:
    """'I was sat upstairs at the front ... a hatchback swung in right in front of the bus. The driver slammed on':
    a passenger's account of the bus or coach they ride; the bus (by any name: 'the number 38', 'the 7', 'our
    coach') and its driver are the ego, which is a bus, and 'we' are on it."""
    by_route = bool(ROUTE_TOLD.search(text)) and bool(ROUTE_RIDDEN.search(text)) or bool(ROUTE_DRIVER.search(text))
    routes_driver = re.search(r"\b" + ROUTES_DRIVER, text, re.I)  # "Dear First Bus, your driver on the 24 ran the
    # red": the bus, whoever tells
    if not (ON_A_BUS.search(text) or by_route) or DRIVING_MYSELF.search(text) or OTHER_BUS.search(text) or \
            re.search(r"\bego\b", text, re.I) or not (re.search(r"\b(?:i|me|my|we|us|our)\b", text, re.I) or
                                                       routes_driver):
        return text
    text, ridden = ROUTE_RIDDEN.subn(r"\1 the ego bus", text)  # "On the 55 this morning", "Was on the 16"
    text, driven = ROUTE_DRIVER.subn("the ego bus", text)  # "the 42 driver is a menace"
    text, named = OUR_BUS.subn("the ego bus", text)
    named += ridden + driven
    text = re.sub(r"\bthe\s+driver\s+(?:of|on)\s+the\s+ego\s+bus\b", "the ego bus", text, flags=re.I)
    text = BUS_DRIVER.sub("the ego", text)
    if routes_driver:  # "the driver on the first 12 was brilliant ... once it had gone the driver pulled out": theirs
        text = re.sub(r"\bthe\s+driver\b" + NOT_ANOTHERS_DRIVER, "the ego", text, flags=re.I)
    text = re.sub(r"\b(i|we)\s+(?:was|were|am|are|'m|'re)\s+(?:sat|sitting|seated|standing)\s+(?:right\s+)?"
                  r"(?:up|down)stairs\b(?:\s+(?:at|by|near)\s+the\s+(?:front|back|window))?", r"\1 was on board", text,
                  flags=re.I)  # "I was sat upstairs at the front": where on the bus, not the bus standing
    text = re.sub(r"\b(?:the\s+)?(?:people|passengers|ones|folk)\s+(?:standing|sitting|sat|seated)\s+"
                  r"(?:up|down)stairs\b", "the passengers", text, flags=re.I)  # "the people standing downstairs went
    # flying": on board
    notes.append("read the bus the teller rides as the ego")
    return text if named and not (ridden or driven) else "The ego is a bus. " + text  # (said first, when a route
    # number is all that names it: "Complaint about the 301: the driver just sat there")


RIDING = re.compile(r"\b(?:(?:i|we)(?:'m|'re|\s+am|\s+are|\s+was|\s+were)?\s+(?:riding|cycling|rode|cycled)|"
                    r"of\s+us\s+(?:riding|cycling|single|two\s+abreast|in\s+single)|"
                    r"(?:my|our)\s+(?:bicycles?|club|club\s+run|group\s+ride|riders|lads|juniors|back\s+wheel)|"
                    r"of\s+our\s+\w+\s+(?:is|are|was|were)\s+(?:riding|cycling)|on\s+(?:my|our)\s+bicycles?|"
                    r"(?:the\s+last|the\s+front)\s+rider|back\s+marker|ride\s+leader|club\s+(?:run|route)|"
                    r"(?:two|three|four|five|six|seven|eight|\d)\s+of\s+us|our\s+tail[\s-]end(?:er|\s+charlie)|"
                    r"our\s+lot|of\s+ours|primary\s+position|"
                    r"(?:take|takes|taken|taking|took)\s+the\s+lane|(?:saturday|sunday)\s+social|on\s+my\s+wheel|"
                    r"youth\s+riders)\b",
                    re.I)  # the teller said to ride, or one of the teller's group
DRIVING_MYSELF = re.compile(r"\b(?:i|we)(?:'m|\s+am|\s+was|\s+were|'re|\s+are)?\s+(?:driving|drove|drive)\b|"
                            r"\b(?:my|our)\s+(?:car|van|truck|lorry|test\s+car|test\s+vehicle)\b|"
                            r"\b(?:safety|test)\s+driver\b|"
                            r"\b(?:i|we)(?:'m|\s+am|\s+was|\s+were|'re|\s+are)\s+in\s+the\s+(?:test\s+)?"
                            r"(?:car|vehicle|av)\b", re.I)
UNDER_TEST = re.compile(r"\b(?:test\s+(?:car|vehicle)|(?:the|our|an)\s+av|autonomous\s+(?:car|vehicle)|"
                        r"self[\s-]driving\s+(?:car|vehicle)|driverless\s+(?:car|vehicle)|automated\s+(?:car|vehicle)|"
                        r"robotaxi|vehicle\s+under\s+test|ego(?:\s+car|\s+vehicle)?|vut|sut)\b", re.I)
CALL_OUT = re.compile(r"[\"\u201c](?:car|cars|truck|lorry|van|bus|bike|rider|horse|runner)\s+"
                      r"(?:back|up|down|left|right|ahead|behind|coming|front)!*[\"\u201d]", re.I)
MOTORBIKE = re.compile(r"\b(?:motorbikes?|motorcycles?|mopeds?|scooters?|bikers?|motorcyclists?|throttle)\b", re.I)
NUMBER = r"(two|three|four|five|six|seven|eight|nine|ten|\d{1,2})"
OUR_PEOPLE = r"(?:us|our\s+(?:lads|riders|girls|juniors|mates|group|club|members))"
GROUPS_OF_US = (  # a group's count, said of the riders (or walkers) in the third person
    (re.compile(rf"\b(?:the\s+)?{NUMBER}\s+of\s+{OUR_PEOPLE}", re.I), r"\1 cyclists"),
    (re.compile(rf"\bone\s+of\s+{OUR_PEOPLE}", re.I), "a cyclist"),
    (re.compile(rf"\bour\s+group\s+of\s+{NUMBER}\b", re.I), r"a group of \1 cyclists"),
    (re.compile(r"\b(?:the\s+lot|all|both)\s+of\s+us\b", re.I), "the cyclists"),
    (re.compile(rf"\bour\s+lot,?\s+{NUMBER}\s+riders\b", re.I), r"\1 cyclists"),  # "our lot, four riders"
    (re.compile(r"\bour\s+lot\b", re.I), "the cyclists"),
    (re.compile(r"\bone\s+of\s+ours\b", re.I), "a cyclist"),
    (re.compile(rf"\b{NUMBER}\s+(?:of\s+our\s+)?(?:youth\s+|junior\s+|club\s+)?(?:riders|juniors)\b", re.I),
     r"\1 cyclists"),  # "three riders in a line", "two of our youth riders", "two juniors": the club's own
)
AS_ONE = {"i'm": "{} is", "i am": "{} is", "i was": "{} was", "i've": "{} has", "i'd": "{} had", "i": "{}",
          "me": "{}", "my": "{}'s", "myself": "{}"}
AS_MANY = {"i'm": "the {}s are", "i am": "the {}s are", "i was": "the {}s were", "i've": "the {}s have",
           "i'd": "the {}s had", "i": "the {}s", "me": "the {}s", "my": "the {}s'", "myself": "the {}s",
           "we're": "the {}s are", "we are": "the {}s are", "we": "the {}s", "us": "the {}s", "our": "the {}s'",
           "ourselves": "the {}s"}
WALKING = re.compile(r"\b(?:(?:i|we)(?:'m|'re|\s+am|\s+are|\s+was|\s+were)?\s+(?:crossing|walking|stepping|"
                     r"stepped\s+(?:out|onto|off)|standing\s+(?:at|on)\s+the\s+(?:kerb|curb|crossing|corner|zebra)|"
                     r"waiting\s+to\s+cross)|(?:my|our)\s+(?:guide\s+dog|white\s+cane|pram|buggy|stroller|"
                     r"pushchair))\b", re.I)  # the teller said to be on foot
FIRST_PERSON_WORDS = re.compile(r"\b(" + "|".join(w.replace(" ", r"\s+") for w in sorted(AS_MANY, key=len,
                                                                                         reverse=True)) + r")\b", re.I)


def _tellers_beside_the_ego(text: str, notes: list[str]) -> str:
    """'I'm riding a door's width out with the test car sat behind me', 'four of us riding two abreast, test car
    coming up behind', 'I was crossing the road when the test car turned left towards me': a rider or a walker
    telling of a vehicle named as the one under test is a cyclist or a pedestrian by it, not its driver; the
    teller's words are said of them (of the group, when the teller rides in one), in the third person, so that
    each is placed from the ego."""
    riding, walking = RIDING.search(text), WALKING.search(text)
    if not (riding or walking) or DRIVING_MYSELF.search(text) or MOTORBIKE.search(text) or \
            not UNDER_TEST.search(text):
        return text
    noun = "cyclist" if riding else "pedestrian"
    text = CALL_OUT.sub('""', text)  # 'shouts "car back!"': a warning called out, the test car named again
    for pattern, said in GROUPS_OF_US:
        text = pattern.sub(said.replace("cyclist", noun), text)
    many = bool(re.search(rf"\b{noun}s\b|\b(?:we|us)\b", text, re.I))
    named: list[str] = []

    def said_of_them(m: re.Match) -> str:
        word = re.sub(r"\s+", " ", m.group(1).lower())
        if many or word not in AS_ONE:
            return AS_MANY[word].format(noun)
        named.append(word)
        return AS_ONE[word].format(f"a {noun}" if len(named) == 1 else f"the {noun}")

    notes.append(f"read the teller as a {noun} beside the vehicle under test")
    return FIRST_PERSON_WORDS.sub(said_of_them, text)


SYSTEM_MOVES_ME = re.compile(
    r"\b(it|op|openpilot|autopilot|fsd|the car|my car|the system|bluecruise|super ?cruise|pilot assist)\s+"
    r"(moved|moves|took|takes|steered|steers|put|puts|nudged|nudges|swung|swings|eased|eases)\s+(?:me|us)\s+"
    r"(?=(?:over|around|round|across|into|back|out|to the|onto)\b)", re.I)
ON_ITS_OWN = {"moved": "moved", "moves": "moves", "took": "went", "takes": "goes", "steered": "steered",
              "steers": "steers", "put": "moved", "puts": "moves", "nudged": "moved", "nudges": "moves",
              "swung": "swung", "swings": "swings", "eased": "eased", "eases": "eases"}


def _moved_by_the_system(text: str) -> str:
    """'I hit the blinker and it moved me over to the left lane', 'OP took me around it into the left lane': a
    driver-assist system moving the speaker moves the speaker's own car, the ego ('it' is the car, not the truck
    named before)."""
    return SYSTEM_MOVES_ME.sub(lambda m: f"{'my car' if m.group(1).lower() == 'it' else m.group(1)} "
                                         f"{ON_ITS_OWN[m.group(2).lower()]} ", text)


GHERKIN_STEP = re.compile(r"^[ \t]*(Given|When|Then|And|But|\*)[ \t]+(\S.*?)[ \t]*$")  # the keywords as written
GHERKIN_HEADER = re.compile(r"^[ \t]*(Feature|Rule|Background|Scenario Outline|Scenario Template|Scenario|Example|"
                            r"Examples|Scenarios)[ \t]*:[ \t]*(.*?)[ \t]*$", re.I)
THEN_MODAL = re.compile(r"\b(?:may|can|could|might|will|shall|must|(?:is|are) (?:allowed|permitted|expected|"
                        r"required|supposed|able) to)\b(?!\s+have\b)", re.I)
GHERKIN_ASIDE = re.compile(r"^[ \t]*(?:@\S+(?:[ \t]+@\S+)*|#.*|\"\"\"|```)[ \t]*$")  # tags, comments, doc strings


def _gherkin(text: str, notes: list[str]) -> str:
    """'Given the ego is driving ... When a pedestrian steps out ... Then the ego should stop': acceptance criteria
    in steps. The keywords are no words of the scene: a Then step is what the ego does in reaction to the When
    step before it, so the two read as one sentence ('When a pedestrian steps out, the ego should stop'), not
    as a 'then' that starts a stage; an And or But step goes on with the step before it. Whether the When starts
    a stage ('When the light turns green') is the reader's to say, as in prose."""
    lines = text.split("\n")
    steps = [m.group(1) for m in map(GHERKIN_STEP.match, lines) if m]
    headed = any(GHERKIN_HEADER.match(x) for x in lines)
    if len(steps) < 2 or not ("Given" in steps and {"When", "Then"} & set(steps) or
                               headed and {"When", "Then"} <= set(steps)):
        return text  # (a story told a line at a time may start lines with 'When ...' and 'Then ...')
    lines = _outline_example(lines)
    out: list[str] = []
    condition: list[str] = []  # the When step (and its And steps) waiting for its Then
    last = ""
    for line in lines:
        step, header = GHERKIN_STEP.match(line), GHERKIN_HEADER.match(line)
        if header is not None:
            out += [f"When {' and '.join(condition)}."] if condition else []
            condition, last = [], ""
            if header.group(2) and header.group(1).lower() in ("feature", "rule", "scenario", "example",
                                                                 "scenario outline", "scenario template"):
                out.append(f"Scenario: {header.group(2)}")  # the case's name, read for the road and weather
            continue
        if step is None:
            if not GHERKIN_ASIDE.match(line):
                out.append(line)
            continue
        keyword, body = step.group(1), step.group(2).rstrip(" .;")
        keyword = last if keyword in ("And", "But", "*") and last else keyword
        if keyword == "Then":  # "Then the ego may continue", "is expected to stop": what the ego is to do
            body = THEN_MODAL.sub("should", body)
        if keyword == "When":
            if last != "When" and condition:
                out.append(f"When {' and '.join(condition)}.")
                condition = []
            condition.append(body)
        elif keyword == "Then" and condition:
            out.append(f"When {' and '.join(condition)}, {body}.")
            condition = []
        else:
            out.append(body + ".")
        last = keyword
    out += [f"When {' and '.join(condition)}."] if condition else []
    notes.append("read the acceptance criteria's steps: each Then as the reaction to its When")
    return "\n".join(out)


SENTENCE = re.compile(r"[^.!?\n]*(?:[.!?]+|\n|$)")
ROLE_NOUNS = r"(?:expert|engineer|assistant|specialist|tester|designer|generator|simulator|model|ai|chatbot|" \
    r"consultant|analyst|author|writer|planner|developer|programmer|researcher|instructor|professional|bot)"
ROLE_PLAY = re.compile(r"^\s*(?:please\s+)?(?:(?:i want|i'd like|i would like|i need) you to )?"
                       r"(?:(?:act|acting|behave) as|pretend (?:to be|you are)|"
                       r"(?:assume|take|play) the role of|(?:imagine )?(?:you are|you're) (?:an?|the|my|our) (?:[a-z-]+\s+){0,3}?"
                       + ROLE_NOUNS + r"\b|as an? (?:[a-z-]+\s+){0,3}?" + ROLE_NOUNS + r"\s*,)", re.I)
# "Act as a simulation expert.", "You are a scenario generator."; not "You are approaching a zebra crossing.", "Imagine
# you are driving down a 20 mph street."
OUTPUT_ORDER = re.compile(r"^\s*(?:(?:please|also|then|finally|and|now|just|kindly)\s+)*(?:output|return|format|"
                          r"respond|reply|answer|list|print|present|express|structure|emit|export|make sure|"
                          r"keep (?:it|the (?:output|answer|response|scene|scenario|description|speeds?)|things|"
                          r"everything|speeds?)|"
                          r"ensure|be sure|avoid|the output|your output|your answer|your response|the answer|"
                          r"the response|output format|response format|answer format)\b", re.I)
LEAVE_OUT = re.compile(r"^\s*(?:please\s+)?(?:don't|do not|never|avoid)\s+(?:include|add|put|place|spawn|have|use|"
                       r"including|adding|putting|placing|spawning|having|using)\s+(?:in\s+)?(?:any\s+)?", re.I)
META_AGENTS = re.compile(r"\b(?:(?:all|every|each|any|the|their|its|other|of)\s+)*(?:agents?|actors?|vehicles?|"
                         r"road users?|participants?|entities|entity|objects?|npcs?|traffic participants?)\b", re.I)


TOOL_ELEMENT = re.compile(r"\b[A-Z][a-z]+(?:[A-Z][a-z]*)+(?:Action|Condition|Trigger|Controller|Position|Event|"
                          r"Element|Group|Storyboard|Maneuver|Act|Story|Entity|Entities)s?\b")


def _tool_elements(text: str) -> str:
    """'I tried a LaneChangeAction', 'StoryboardElementStateCondition isn't firing': a scenario format's element
    named by the one who writes with it, or said not to work, is the tool talked about, not an agent's manoeuvre
    ('Ego performs LaneChangeAction to the left lane' is the scene's)."""
    def tool(m: re.Match) -> str:
        before = re.findall(r"[a-z']+", text[max(0, m.start() - 40):m.start()].lower())[-4:]
        after = text[m.end():m.end() + 24].lower()
        mine = bool({"i", "i'm", "i've", "my", "we", "our", "we've", "tried", "using", "added"} & set(before))
        failing = re.match(r"\s*(?:isn't|is not|doesn't|does not|never|won't|keeps|just)\b", after) is not None
        return "element" if mine or failing else m.group(0)
    return TOOL_ELEMENT.sub(tool, text)


def _chatbot_request(text: str, notes: list[str]) -> str:
    """'Act as a simulation expert. Create a cut-in scenario: ... Output the scene with all agents, their positions
    and actions.': a prompt written for a chatbot casts it in a role and says how to answer; neither is the
    scene. A sentence that gives the role, or an order about the answer ('Output ...', 'Keep it realistic',
    'Make sure the speeds are plausible') that names no road user but the generic ones ('every agent'), is
    left out."""
    kept, dropped = [], []
    for m in SENTENCE.finditer(text):
        sentence = m.group(0)
        body = re.sub(r"^\s*(?:[-*\u2022]\s*|\d{1,2}[.)]\s*)", "", sentence)
        if LEAVE_OUT.match(body):  # "Don't include any other vehicles.": there are none
            kept.append(sentence[:len(sentence) - len(body)] + LEAVE_OUT.sub("No ", body, count=1))
            dropped.append(sentence.strip())
            continue
        if ROLE_PLAY.match(body) or OUTPUT_ORDER.match(body) and _orders_only_the_answer(body):
            dropped.append(sentence.strip())
            kept.append("\n" if sentence.endswith("\n") else " ")
            continue
        kept.append(sentence)
    if not dropped:
        return text
    notes.append(f"read past the request's words to the chatbot ('{dropped[0][:40]}')")
    return "".join(kept)


def _orders_only_the_answer(sentence: str) -> bool:
    """An order about the answer names no road user but the generic ones, no weather and no road: 'Output the
    scene with all agents' does; 'Make sure the truck is in the left lane' and 'Keep it rainy' do not."""
    said = {m.category for m in matches(tokenize(META_AGENTS.sub(" ", sentence)))
            if m.category != "agents" or m.meaning not in ("ego", "none")}  # "relative to the ego": whom to place by
    return not said & {"agents", "weather", "road"} and not re.search(r"\d", sentence)  # "a 55 along there"


MARKUP = re.compile(r"\*\*|__|`+|^[ \t]*(?:#{1,6}|>)[ \t]+", re.M)  # "**Version**", "## Steps", "`run`", "> quote"
REPORT_SECTION = re.compile(
    r"^[ \t]*(?:[-*\u2022][ \t]*|\d{1,2}[.)][ \t]*)?(?P<key>steps to reproduce|steps to repro|"
    r"repro(?:duction)? steps|"
    r"how to reproduce|to reproduce|reproduction|repro|expected(?: behaviou?r| results?| outcome| output)?|"
    r"desired(?: behaviou?r| result| outcome| output)?|what i expected|what should happen|"
    r"actual(?: behaviou?r| results?| outcome| output)?|observed(?: behaviou?r| results?| output)?|"
    r"current(?: behaviou?r| results?| output)|what i got|what happens instead|what happened instead|"
    r"what actually happens|what actually happened|versions?|env|environment|os|platform|build|commit|"
    r"system(?: info)?|logs?|attachments?|screenshots?|workaround|severity|priority|frequency|reproducibility|"
    r"scene|scenario|prompt|input|ask for|asked for|description|context|details|"
    r"scenario \(what i wanted\)|what i wanted|what i asked for|title|bug|issue|summary|describe the bug|"
    r"bug description)[ \t]*(?::|$)[ \t]*(?P<rest>.*)$", re.I)
REPORT_KINDS = {"actual": ("actual", "observed", "current", "what i got", "what actually", "what happen"),
                "expected": ("expected", "desired", "what i expected", "what should"),
                "steps": ("steps", "how to", "to reproduce", "repro")}
REPORT_ENVIRONMENT = ("version", "env", "os", "platform", "build", "commit", "system", "log", "attachment",
                      "screenshot", "workaround", "severity", "priority", "frequency", "reproducibility")
REPORT_TITLES = ("title", "bug", "issue", "summary", "describe the bug", "bug description")
TOOL_STEP = re.compile(r"^(?:\$|(?:(?:then|and|now|just|simply|please)[ \t]+)?(?:generate|run|re-?run|open|watch|"
                       r"load|compile|click|execute|launch|build|export|import|save|render|play|replay|observe|look|"
                       r"check|inspect|view|install|invoke|press|paste|submit|start|call|use|lower|python|ttsgc|"
                       r"pip)\b)", re.I)
QUOTED = re.compile(r"[\"\u201c]([^\"\u201c\u201d]+)[\"\u201d]")
TITLE_STOPS = re.compile(r"[.:;!?]+(?=\s)")


INLINE_SECTION = re.compile(r"(?<=[.;)!?])[ \t]+(?=(?:steps to reproduce|steps|repro|expected(?: result| behaviou?r)?|"
                            r"actual(?: result| behaviou?r)?|observed)[ \t]*:)", re.I)


def _inline_report_sections(text: str) -> str:
    """'SIM-482 Pedestrian spawns inside the curb. Steps: 1. ... Expected: ... Actual: ...': a ticket written on
    one line, its sections each put on a line of their own (its opening sentence, the title, without its stop)."""
    if len({m.group(0).split()[0].lower()[:6] for m in re.finditer(
            r"\b(?:steps|repro|expected|actual|observed)\b(?=[^:\n]{0,20}:)", text, re.I)}) < 2:
        return text
    out = []
    for line in text.split("\n"):
        parts = INLINE_SECTION.split(line)
        if len(parts) > 1 and not REPORT_SECTION.match(parts[0]):
            parts[0] = parts[0].rstrip().rstrip(".")  # the title before the first section
        out += parts
    return "\n".join(out)


def _bug_report(text: str, notes: list[str]) -> str:
    """A bug report ('Steps to reproduce', 'Expected behaviour', 'Actual'): the scene is the one asked for in its
    steps (or, told nowhere else, the one it expected); what went wrong under 'Actual' is no scene, nor are the
    versions it ran, the steps that only work the tool ('Generate and open the .xosc'), or its markup. Its title
    names the bug: read for the road and the weather only."""
    lines = _inline_report_sections(MARKUP.sub("", text)).split("\n")
    found = [m for m in map(REPORT_SECTION.match, lines) if m]
    kinds = {kind for m in found for kind, starts in REPORT_KINDS.items()
             if m.group("key").lower().startswith(starts)}
    if len(kinds) < 2:
        return text
    first = next((k for k, x in enumerate(lines) if x.strip()), 0)
    sections: list[tuple[str, list[str]]] = [("scene", [])]
    field = False  # the last heading had its value on its own line ('Actual: ...'): a blank line ends it
    for k, line in enumerate(lines):
        m = REPORT_SECTION.match(line)
        if m is None and k == first and len(line.split()) <= 15 and not line.rstrip().endswith("."):
            sections += [("title", [line.strip()]), ("scene", [])]  # "cut-in from right lane goes the wrong way"
            continue
        if m is None:
            if field and not line.strip():
                sections.append(("scene", []))
                field = False
            sections[-1][1].append(line)
            continue
        key, rest = m.group("key").lower(), m.group("rest").strip()
        kind = next((kind for kind, starts in REPORT_KINDS.items() if key.startswith(starts)), "scene")
        kind = "environment" if key.startswith(REPORT_ENVIRONMENT) else "title" if key in REPORT_TITLES else kind
        sections.append((kind, [rest] if rest else []))
        field = bool(rest)
        if kind in ("title", "environment") and rest:
            sections.append(("scene", []))  # "Version: 0.7.0": a field of one line
    scene = [_scene_step(x) for kind, said in sections if kind in ("scene", "steps") for x in said]
    if not any(_agent_kinds(x) - {"ego"} for x in scene):  # the scene said only as what was expected
        scene += [_scene_step(x) for kind, said in sections if kind == "expected" for x in said]
    titles = ["Title: " + TITLE_STOPS.sub(",", x) for kind, said in sections if kind == "title"
              for x in said if x.strip()]  # one title, whatever marks it holds
    notes.append("read the bug report's scene, not what it got ('Actual') nor how it was run")
    return "\n".join(titles[:1] + [x for x in scene if x.strip()])


def _scene_step(line: str) -> str:
    """One line of a report's steps as the scene it asks for: 'Generate and open the .xosc' works the tool, no
    scene; '2. A silver sedan ... cuts in' is the scene, its number gone."""
    line = re.sub(r"^[ \t]*(?:[-*\u2022][ \t]*|\d{1,2}[.)][ \t]*)", "", line)
    line = re.sub(r"^(?:scene|scenario|prompt|input|ask(?:ed)? for|what i wanted)[ \t]*(?:\([^)]*\))?[ \t]*:[ \t]*",
                  "", line, flags=re.I)
    if TOOL_STEP.match(line) and QUOTED.search(line):  # 'lower "a van is double-parked ahead ..." with seed 1': the
        return ". ".join(x.strip().rstrip(".") for x in QUOTED.findall(line) if len(x.split()) >= 3)  # prompt given
    return " ".join(_without_tool_work(x) for x in re.split(r"(?<=[.!?])\s+", line))


def _without_tool_work(sentence: str) -> str:
    """'launch planning_simulator with the sample map, put ego in front of the intersection': the clause that works
    the tool goes, the scene set up after it stays (a sentence that only works the tool goes whole)."""
    if not TOOL_STEP.match(sentence):
        return sentence
    rest = sentence.split(", ", 1)[1] if ", " in sentence else ""
    return rest if len(rest.split()) >= 4 else ""


def _outline_example(lines: list[str]) -> list[str]:
    """'Scenario Outline: ... the ego drives at <speed> ... Examples: | speed | 30 km/h |': an outline is one scene
    per row of its table; the first row is the scene told (one scene, not all of them at once), and the table is
    no scene of its own."""
    start = next((k for k, x in enumerate(lines) if re.match(r"^[ \t]*(?:Examples|Scenarios)[ \t]*:", x, re.I)), None)
    if start is None:
        return lines
    rows = [[c.strip() for c in x.strip().strip("|").split("|")] for x in lines[start + 1:] if x.strip().startswith("|")]
    end = start + 1
    while end < len(lines) and (lines[end].strip().startswith("|") or not lines[end].strip()):
        end += 1
    kept = lines[:start] + lines[end:]
    if len(rows) < 2 or len(rows[1]) != len(rows[0]):
        return kept
    values = dict(zip(rows[0], rows[1]))
    return [re.sub(r"<([^<>]+)>", lambda m: values.get(m.group(1).strip(), m.group(0)), x) for x in kept]


AUTHORS = re.compile(r"\b(?:(?:for|in) (?:our|this) (?:project|study|work|report|thesis|paper|assignment|"
                     r"coursework),?\s*)?\bwe (?:consider|examine|study|investigate|model|simulate|present|describe|analyse|analyze|"
                     r"look at|focus on|propose|choose|chose|selected|select)\s+", re.I)


MODELLING = re.compile(r"\b(?:we|i)\s+(?:(?:would\s+)?(?:propose|intend|plan|want|would like|wish|aim)\s+(?:to\s+)?|"
                       r"will\s+|shall\s+|would\s+)?(?:simulate|simulating|model|modelling|modeling|represent|"
                       r"recreate|reconstruct)\b|\bwe\s+ask\s+that\s+the\s+(?:model|simulation)\b", re.I)
AUTHORS_WORDS = {"we": "the authors", "us": "the authors", "our": "the authors'", "ours": "the authors'"}


def _modelling_authors(text: str, notes: list[str]) -> str:
    """'We propose to simulate a car in Ferry Lane making a right turn', 'We will model a westbound car ...': the
    authors of a proposal say 'we' of their work and their office, never of a vehicle on the road."""
    if not MODELLING.search(text) or DRIVING_MYSELF.search(text) or \
            re.search(r"\b(?:we|i)(?:'re|'m|\s+were|\s+was|\s+are|\s+am)?\s+(?:riding|cycling|walking|crossing)\b",
                      text, re.I):
        return text
    notes.append("read the proposal's 'we' as its authors")
    return re.sub(r"\b(we|us|our|ours)\b", lambda m: AUTHORS_WORDS[m.group(1).lower()], text, flags=re.I)


def _authors(text: str, notes: list[str]) -> str:
    """'For our project we consider a cut-in manoeuvre ... the ego' (or 'the AV', 'the SUT'): the authors of a report
    that names its ego say 'we' of their work, not of a vehicle."""
    if not re.search(rf"\bthe\s+(?:{_ego_roles()})\b|\bego vehicle\b", text, re.I) or not AUTHORS.search(text):
        return text
    notes.append("read the report's 'we' as its authors")
    return AUTHORS.sub(lambda m: "", text)


EXPECTATION = re.compile(r"(?:^|(?<=[.!?]\s))(?:(?:we|i) (?:would )?(?:expect|anticipate|hope)(?!\s+(?:that\s+)?"
                         r"(?:you|u|someone|somebody|anyone|this tool|the tool)\b)|(?:we|i) want to "
                         r"(?:see|verify|check|confirm) (?:whether|if|that)|the expected (?:behaviou?r|response|outcome) "
                         r"is)\b[^.!?]*[.!?]?\s*", re.I)


TOPIC = re.compile(r"^\s*(?:(?:so|ok|okay|maybe|perhaps|how about|what about|could we do|can we do|we need|i want)"
                   r",?\s+)*(?:something|a scene|a scenario|one)\s+(?:with|involving|featuring|about)\s+(?:an?|some)\s+"
                   r"([a-z -]{2,30}?)\s*[?.!:]\s*", re.I)


def _topic(text: str, notes: list[str]) -> str:
    """'Something with a bus? A city bus is stopped ahead of our car ...': a request that first names its topic,
    then the scene; the agent of the topic is the one the scene names after it, not one more."""
    m = TOPIC.match(text)
    if m is None:
        return text
    kinds = _agent_kinds(m.group(1)) - {"ego", "none"}
    if not kinds or not kinds <= _agent_kinds(text[m.end():]):
        return text
    notes.append(f"read '{m.group(0).strip()}' as the request's topic, named again in the scene")
    return text[m.end():]


def _expectations(text: str, notes: list[str]) -> str:
    """'We expect the ego to yield to the jogger before proceeding.': what a report expects of the system under
    test is what it checks, not what the scene scripts (as an 'Expected:' line is)."""
    text, n = EXPECTATION.subn("", text)
    if n:
        notes.append("read what the report expects of the ego as its check, not the scene")
    return text


PROTAGONIST = re.compile(r"\b(?:our|the) (?:hero|heroine|protagonist)\b", re.I)


def _protagonist(text: str, notes: list[str]) -> str:
    """'just ahead of our HERO. He checks over his shoulder': the story's hero is the ego, and so is the pronoun
    the story gives them after."""
    if not PROTAGONIST.search(text) or "the ego" in text:
        return text
    notes.append("read the story's hero as the ego")
    return _drivers_pronoun(PROTAGONIST.sub("the ego", text), notes)


EGO_OWNER = re.compile(r"\b[Tt]he ego(?: car| vehicle)?\s*(?:,|--|\u2014|\u2013)\s*([A-Z][A-Za-z]+)'s\b")  # "The ego car,
# PRIYA's electric hatch, hums along": whose it is


def _screenplay_driver(text: str, notes: list[str]) -> str:
    """'Tom waits. Once the bus clears, he turns right.': in a screenplay's action lines the character at the wheel
    (lexicon.driver_named), or whose the ego car is ('the ego car, PRIYA's hatch'), is the ego, and so is the pronoun
    the page gives them after."""
    if not SLUGLINE.search(text):
        return text
    lines = text.split("\n")
    names = set()
    for k, line in enumerate(lines):
        if SLUGLINE.match(line) or re.match(r"^(?: {4,}|\t)\S", line):
            continue  # a scene heading, or a character's name and what they say
        names |= {m.group(1) for m in AT_THE_WHEEL_NAME.finditer(line) if driver_named(m) == "the ego"}
        names |= {m.group(1) for m in EGO_OWNER.finditer(line) if not known_word(m.group(1))}
    if not names:
        return text
    for k, line in enumerate(lines):
        if not (SLUGLINE.match(line) or re.match(r"^(?: {4,}|\t)\S", line)):
            for name in names:  # "MAYA's hatchback idles ... Maya waits": the character by any case of the name
                lines[k] = re.sub(rf"\b{re.escape(name)}\b", "the ego", line, flags=re.I)
                line = lines[k]
    named = "\n".join(lines)
    notes.append("read the screenplay's character at the wheel as the ego")
    return _drivers_pronoun(named, notes)


ADDRESSEE = re.compile(r"^\s*(?:psa|shout\s*out|a message|message|note|an open letter|open letter)?\s*(?:to|dear)\s+"
                       r"(?:the|that|this)\s+((?:[a-z]+\s+){0,3}?(?:" + _NOUN[1:-1] +
                       r"|cyclist|biker|rider|motorcyclist|pedestrian|jogger|driver))\b", re.I)


def _addressee(text: str, notes: list[str]) -> str:
    """'PSA to the cyclist who ran the red ...: I had the green ..., you came flying straight through': a post
    written to someone on the road by a narrator who drove; 'you' is the one written to, not the ego."""
    m = ADDRESSEE.match(text)
    rest = text[m.end():] if m else ""
    if m is None or not re.search(r"\b(?:i|i'm|me|my)\b", rest, re.I) or not re.search(r"\b(?:you|u)\b", rest, re.I):
        return text
    noun = m.group(1).split()[-1]
    notes.append(f"read 'you' as the {noun} the text is written to")
    rest = re.sub(r"\b(?:you|u)(?='re\b)", f"the {noun}", rest, flags=re.I)
    rest = re.sub(r"\byour\b", f"the {noun}'s", rest, flags=re.I)
    return text[:m.end()] + re.sub(r"\b(?:you|u)\b", f"the {noun}", rest, flags=re.I)


BROKEN_OFF = re.compile(r"([^.!?:,;\n]*?)\s*(?:\u2014|\u2013|--)\s*$")  # "And there's a lorry\u2014": cut off


def _restarts(text: str, notes: list[str]) -> str:
    """'B: And there's a lorry\u2014 / A: Lorry! Listen to him. / B: There's a truck in the left lane ...': a speaker
    cut off before saying what the agent does starts again; the agent named in the broken-off words and echoed by
    the other speaker is the one named again later, not one more."""
    lines = text.split("\n")
    for k, line in enumerate(lines):
        if not line.rstrip().endswith(("\u2014", "\u2013", "--")):
            continue  # (searched only then: the pattern tried at every start of a long line is quadratic)
        m = BROKEN_OFF.search(line)
        if m is None or not m.group(1).strip():
            continue
        kinds = _agent_kinds(m.group(1)) - {"ego"}
        later = "\n".join(lines[k + 1:])
        if not kinds or not kinds & _agent_kinds(later):
            continue
        named = [w for w in re.findall(r"[A-Za-z]+", m.group(1)) if _agent_kinds(w) & kinds]
        lines[k] = line[:m.start(1)]
        notes.append(f"read '{m.group(1).strip()[:40]}' (cut off) as said again later")
        if k + 1 < len(lines) and named:  # "Lorry!": the other speaker echoing the word, no agent of its own
            echo = rf"^(\s*(?:[A-Z][A-Za-z.' -]{{0,30}}:)?\s*)(?:an? |the )?{re.escape(named[-1])}\s*[!?.]"
            lines[k + 1] = re.sub(echo, r"\1", lines[k + 1], flags=re.I)
    return "\n".join(lines)


def _without_letter_frame(text: str, notes: list[str]) -> str:
    """'Hi team,' ... 'Cheers, / Dana / Fleet Operations': the greeting and the signature are no scene."""
    lines = text.split("\n")
    if len([x for x in lines if x.strip()]) < 2:
        return _without_greeting_word(text)
    first = next(k for k, x in enumerate(lines) if x.strip())
    greeting = lines[first].strip()
    if SALUTATION.match(greeting) and (greeting[-1] in ",!" or len(greeting.split()) <= 3 and
                                       greeting.split()[0].lower() in ("hi", "hello", "hey", "hiya", "dear")):
        lines[first] = ""
        notes.append("read past the letter's greeting")
    for k in range(len(lines) - 1, first, -1):
        if CLOSING.match(lines[k]) and len(lines[k].split()) <= 4 and any(x.strip() for x in lines[:k]):
            notes.append("read up to the letter's closing")
            lines = lines[:k]
            break
    return _without_greeting_word("\n".join(lines))


def _without_greeting_word(text: str) -> str:
    """'Good morning! A van ...', 'Evening, ...': a greeting that opens the text, not the time of day."""
    return re.sub(r"^\s*(?:good\s+)?(?:morning|afternoon|evening)\s*[!,.]+", " ", text, flags=re.I)


def _testimony(text: str, notes: list[str]) -> str:
    """A transcript of questions and answers: counsel's interjections ('MR. PRICE: Objection.') are no account,
    the labels go, a question answered 'No.' / 'None.' / 'I couldn't tell.' names nothing that was there, and a
    number answers 'how many' with its noun."""
    lines = text.split("\n")
    if sum(bool(QA_LABEL.match(x)) for x in lines) < 2:
        return text
    kept: list[str] = []
    named: set[str] = set()  # the kinds of agent named so far
    asked: int | None = None  # the index in kept of the question last asked
    for line in lines:
        label = QA_LABEL.match(line)
        if label is None and SPEAKER.match(line):
            notes.append(f"read past '{line.strip()[:40]}' (not the witness's account)")
            continue
        body = line[label.end():] if label else line
        kind = ("Q" if label.group(1).upper() in ASKERS else "A") if label else ""  # "THE WITNESS:" answers
        if kind == "Q":
            body = TELL_US.sub("", body)  # "Tell us what the white SUV did.": the SUV is what the answer is about
        if kind == "Q" and "?" in body:  # "Q: You can answer." asks nothing
            asked = len(kept)
        elif kind == "A" and asked is not None and HOW_MANY.search(kept[asked]) and NUMBER_ANSWER.match(body):
            n = NUMBER_ANSWER.match(body).group(1)  # "How many lanes ...? Four.": four lanes
            body = f"{n} {HOW_MANY.search(kept[asked]).group(1)}. " + body[NUMBER_ANSWER.match(body).end():]
        elif kind == "A" and asked is not None and NEGATIVE_ANSWER.match(body) and \
                ASKS_FOR_OTHERS.search(kept[asked]):
            notes.append(f"read '{kept[asked].strip()[:40]}' as answered no")
            kept[asked] = _denied(kept[asked])
            asked = None  # "Were there other cars? No.": there were no other cars
        elif kind == "A" and asked is not None and EXISTENTIAL.search(kept[asked]) and _names_agents(body):
            kept[asked] = _denied(kept[asked])  # "Were there other cars? There was one car stopped ...": the
            asked = None  # answer says what there was
        if kind == "A":
            body = _without_re_descriptions(body, named)
        named |= _agent_kinds(body)
        kept.append(body if not body.strip() or body.rstrip()[-1] in ".?!" else body.rstrip() + ".")
    return "\n".join(kept)


def _without_re_descriptions(answer: str, named_before: set[str]) -> str:
    """'Q: The other vehicle was a minivan? A: A gray minivan, yes.', 'Q: How old? A: Teenager.': an answer that
    only names again what was already named describes it; it adds no second agent."""
    named = set(named_before)
    kept = []
    for sentence in re.split(r"(?<=[.!?])\s+", answer):
        found = matches(tokenize(sentence))
        agents = [m.meaning for m in found if m.category == "agents" and m.meaning not in ("ego", "none")]
        verbless = not any(m.category == "actions" for m in found) and not re.search(
            r"\b(?:is|was|were|are|had|has|have|there|it|he|she|they)\b", sentence, re.I)
        if not (agents and verbless and set(agents) <= named):
            kept.append(sentence)
            named |= _agent_kinds(sentence)
    return " ".join(kept)


def _agent_kinds(text: str) -> set[str]:
    """The kinds of agent a text names, the ego's by its vehicle noun ('my motorcycle')."""
    named = set()
    for m in matches(tokenize(text)):
        if m.category == "agents":
            named |= {m.meaning} if m.meaning != "ego" else {VEHICLE_NOUNS[w] for w in m.phrase.split()
                                                               if w in VEHICLE_NOUNS}
    return named


TEXTING = ((r"\b(does|did|do|could|would|should|was|were|is|are|has|have|had|must|need)nt\b", r"\1n't"),
           (r"\bcant\b", "can't"), (r"\bwont\b", "won't"), (r"\bim\b", "i'm"), (r"\bive\b", "i've"),
           (r"\btheres\b", "there's"),  # no word of its own, whatever follows ("theres car coming")
           (r"\b(there|that|it|what|he|she)s\b(?=\s+(?:a|an|the|this|like|no|some|two|three|so|just|gonna|going|"
            r"literally|always|never|not|been|still|on|in|at)\b)", r"\1's"),
           (r"\byoure\b", "you're"), (r"\btheyre\b", "they're"), (r"\bu\b(?=\s+(?:know|see|were|are|can|could|"
                                                                               r"have|had|was))", "you"),
           (r"\bur\b", "your"), (r"\blil\b", "little"), (r"\bgonna\b", "going to"))


def _texting(text: str) -> str:
    """'doesnt go', 'theres a bus', 'im at the light': a text message's spelling, read as the words it stands for
    (only where the letters can mean nothing else: 'its', 'ill' and 'well' stay)."""
    for pattern, replacement in TEXTING:
        text = re.sub(pattern, replacement, text, flags=re.I)
    return text


SIMILE = re.compile(r"\b(" + _NOUN[1:-1] + r"|truck|semi|ambulance|engine|lorry)(e?s?),?\s+like an?\s+"
                    r"(?:[a-z]+\s+){0,2}?(?:"
                    + _NOUN[1:-1] + r"|truck|ambulance|fire engine|police car|racing car|race car)\b", re.I)


BELIEF = re.compile(r"\b(?:i|we) (?:thought|figured|assumed|feared|was sure|were sure|was convinced)\s+(?:that\s+)?"
                    r"(?:i|we|he|she|it|they)\s+(?:was|were|would|might|had|am|are)\b[^.,;!?]*?"
                    r"(?=\s+(?:lmao|lol|haha|and then|but|turns out|turned out|then)\b|[.,;!?]|$)", re.I)


AS_ONE_MYSELF = re.compile(r"\b(?:speaking\s+)?as\s+an?\s+(?:[a-z-]+\s+){0,3}?[a-z-]+\s+(?:myself|ourselves)\b\s*,?",
                           re.I)


def _asides(text: str) -> str:
    """'a big box truck, like a moving truck': a likeness is no second vehicle; 'a 2019 Harley': a model year
    counts nothing; 'I thought I was getting pulled over': what the narrator feared did not happen; 'as a cyclist
    myself': who the writer is, no one in the scene."""
    text = SIMILE.sub(lambda m: m.group(1) + m.group(2), text)
    text = BELIEF.sub("", text)
    text = re.sub(r"\b(?:it\s+)?turn(?:s|ed)\s+out\s+(?=(?:that|he|she|it|they|i|we|the|to)\b)", "", text,
                  flags=re.I)  # "turns out he was ...": what was learnt, no turn
    text = AS_ONE_MYSELF.sub("", text)  # "As a guide dog user myself, I care about this one": who the writer is
    return re.sub(r"\b(a|an|the|my|his|her|their|our|your)\s+(?:19[5-9]\d|20[0-4]\d)\s+(?=[A-Za-z])", r"\1 ", text,
                  flags=re.I)


def _denied(question: str) -> str:
    return re.sub(r"\b(?:any other|any|some|other|an?)\b|(?:(?<=see )|(?<=notice )|(?<=spot )|(?<=observe ))the\b",
                  "no", question, flags=re.I)


def _names_agents(text: str) -> bool:
    return any(m.category == "agents" and m.meaning not in ("ego", "none") for m in matches(tokenize(text)))


STREET = r"(?:[A-Z][a-z]+|\d{1,3}(?:st|nd|rd|th))(?:\s+(?:Street|St\.?|Avenue|Ave\.?|Road|Rd\.?|Boulevard|Blvd\.?|" \
         r"Lane|Ln\.?|Drive|Way|Close|Grove|Crescent|Place|Terrace|Parade|Square))?"
CORNER = re.compile(rf"\b((?i:at|on|near|by))\s+({STREET})\s+(?:and|&)\s+({STREET})\b(?!\s+(?:intersection|junction|"
                    r"crossroads?|corner))")


AGE_NUMBER = (r"(?:\d{1,3}|(?:twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety)(?:[\s-]+(?:one|two|three|four|"
              r"five|six|seven|eight|nine))?|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|"
              r"thirteen|fourteen|fifteen|sixteen|seventeen|eighteen|nineteen)")
AGE = re.compile(rf"\b{AGE_NUMBER}(?:[\s-]+(?:years?|yrs?)[\s-]+old(?P<noun>s)?|[\s-]*(?:yo|y/o))\b", re.I)


MEASURE = re.compile(r"\b\d+(?:\.\d+)?-(?:tonnes?|tons?|tonner|t|foot|feet|ft|metres?|meters?|m|seaters?|axles?|"
                     r"doors?|wheeled|passengers?|cylinders?|litres?|liters?)\b(?=\s+[a-z])|"
                     r"\b\d+(?:\.\d+)?\s+(?:tonnes?|tons?|tonner|t|seaters?|axles?)\b(?=\s+[a-z])|"
                     r"\b\d+\s+wheelers?\b(?=\s+(?:trucks?|lorry|lorries|rigs?|semis?|trailers?)\b)", re.I)
# ('a 7.5 tonne lorry': a weight said apart from its number is no distance, as '10 metres ahead' is; 'an 18
# wheeler was broken down' names the truck itself)


TONNER = re.compile(r"\b\d+(?:\.\d+)?[\s-]tonner(s?)\b(?!\s+(?:lorry|lorries|truck|trucks|hgv|wagon|van))", re.I)


def _ages(text: str) -> str:
    """'a 9-year-old child', 'an 8 year old boy', 'two 12-year-olds': an age, no count ('young'; the plural
    noun 'children'); so is a measure said as an adjective ('our 44-tonne artics', 'a 12-metre bus')."""
    text = AGE.sub(lambda m: "children" if m.group("noun") else "child" if _no_noun_after(text, m.end()) else "young",
                   text)  # "K, a seven-year-old, runs out": the age names the child
    text = TONNER.sub(lambda m: "truck" + (m.group(1) or ""), text)  # "in the 44-tonner": the lorry itself
    text = MEASURE.sub("big", text)
    return re.sub(r"\ban (young|big)\b", r"a \1", text, flags=re.I)


def _no_noun_after(text: str, end: int) -> bool:
    """'a seven-year-old, runs out', 'the 8-year-old ran': nothing after an age for it to describe."""
    m = re.match(r"\s*(?:[,.;:!?)]|$|(?:is|was|ran|runs|steps|stepped|darts|darted|who|had|has)\b)", text[end:])
    return m is not None


def _street_corners(text: str) -> str:
    """'at Ninth and Walnut', 'the light at Grand and Fourth': two streets named together are their
    intersection."""
    return CORNER.sub(lambda m: f"{m.group(1)} the {m.group(2)} and {m.group(3)} intersection", text)


STREET_ABBREVIATION = re.compile(r"\b([A-Za-z]+) (?=(?:St|Ave|Rd|Blvd|Pkwy|Hwy)\b)", re.I)
STREET_NAMED = re.compile(r"(?<=[a-z,] )([A-Z][a-z]+) (?=(?:Street|Avenue|Road|Boulevard|Parkway|Highway)\b)")
STREET_SUFFIX_VERB = re.compile(r"(?<=[a-z,] )([A-Z][a-z]+) (?:Close|Drive)\b")


SIDE_STREET_NAMED = re.compile(r"\b(out of|from) (?:[A-Z][a-z]+ ){1,3}(?:Lane|Road|Street|Avenue|Close|Drive|Way|Rd|St|"
                               r"Ave|Crescent|Place|Grove|Terrace|Row|Gardens)\b(?= (?:on|to) (?:my|our|the ego's) "
                               r"(?:right|left)\b)")


def _side_street_named(text: str) -> str:
    """'A Ford came out of Hall Lane on my right': a street named by the side it joins from is the side road on
    that side, wherever else the vehicle is said to go ('directly in front of me')."""
    return SIDE_STREET_NAMED.sub(r"\1 the side road", text)


def _street_names(text: str) -> str:
    """'on Park Ave', 'onto Stop Rd', 'along Cross Street': a word the reader knows as a verb, a place or a sign,
    naming a street, names nothing of the scene (no parked car, no stop sign); makes ('Ford Road') and words the
    reader does not know stay, they are read as names already."""
    def name(m: re.Match) -> str:
        entry = lexicon().phrases.get((m.group(1).lower(),))
        return "" if entry is not None and entry[0] in ("actions", "positions", "road", "behaviours", "weather") \
            else m.group(0)
    text = STREET_SUFFIX_VERB.sub(r"\1 Road", text)  # "Cedar Close", "Ocean Drive": a street, not closing in
    return STREET_NAMED.sub(name, STREET_ABBREVIATION.sub(name, text))


def _abbreviated_bodies(text: str) -> str:
    """'a sport utility vehicle ... the SUV': a body spelt out is the same as its abbreviation, said again."""
    return re.sub(r"\bsport[- ]utility vehicle(s?)\b", r"SUV\1", text, flags=re.I)


NUMBERED_VEHICLE = re.compile(r"(?:^|(?<=[.:;!?\n])\s*|(?<=\s[-–—])\s*)(car|vehicle|av|robotaxi|shuttle|van|bus|"
                              r"truck|unit)\s+#?(\d{1,5})\b" + NOT_A_QUANTITY + r"(?=\s+[a-z]|\s*\(|,)", re.I)
# ("Vehicle 22 (HGV) drifted", "Near-miss logged - Bus 88, Route 12.")
ANY_NUMBERED = re.compile(r"\b(?:" + FLEET_NOUNS + r"|av|robotaxi|shuttle|v|veh)\s*#?\s*(\d{1,5})\b" + NOT_A_QUANTITY,
                          re.I)


def _numbered_protagonist(text: str, notes: list[str]) -> str:
    """'Car 12 called in at an all-way stop ... it went straight through', 'Robotaxi 9 requested help': an
    operator's note opens a sentence on the one vehicle it numbers, the one it is about: the ego. Not where the
    text names the ego, or numbers more than one vehicle (a crash report's Car 1 and Car 2). A numbered vehicle
    keyed as the ego ('Ego: Van 31 (Mercedes Sprinter)') is the ego wherever it is named again."""
    keyed = re.search(r"\bego\s*:\s*(" + FLEET_NOUNS + r")\s+#?(\d{1,5})\b", text, re.I)
    if keyed is not None:
        return text[:keyed.end()] + _said_again_as_the_ego(text[keyed.end():], keyed.group(1), keyed.group(2))
    found = NUMBERED_VEHICLE.search(text)
    if found is None or re.search(r"\bego\b", text, re.I) or \
            {m.group(1) for m in ANY_NUMBERED.finditer(text)} != {found.group(2)}:
        return text
    notes.append(f"read {found.group(1)} {found.group(2)} as the ego")
    body = found.group(1).lower()
    ego = "the ego " + body if body in ("bus", "truck", "shuttle") else "the ego"
    text = text[:found.start(1)] + ego + text[found.end(2):]
    return _said_again_as_the_ego(text, found.group(1), found.group(2))


def _said_again_as_the_ego(text: str, noun: str, number: str) -> str:
    """'Unit: Van 31 ... dashcam shows Van 31 going straight': the numbered vehicle named again is the ego."""
    return re.sub(rf"\b{re.escape(noun)}\s+#?{number}\b", "the ego", text, flags=re.I)


def _vehicle_numbers(text: str) -> str:
    """'van 214', 'Cab 17', 'the number 14 bus', 'unit 214', 'Junction 9', 'Route 12': a number that names a
    vehicle or a place counts nothing and limits no speed."""
    text = re.sub(r"\b(?:the\s+)?(?:number|no\.|#)\s*\d+\s+" + _NOUN + r"\b", lambda m: "the " + m.group(1), text,
                  flags=re.I)
    text = re.sub(r"\bthe\s+number\s+\d{1,3}[a-z]?(?=\s+(?:[a-z]+ed|came|went|ran|overtook|swung|cut|shot|drove|sped|"
                  r"flew|hit|nipped|pulled|knelt)\b)", "the bus", text, flags=re.I)  # "the number 36 squeezed past
    # me": a bus by its route, doing something (not "driving the number 37 service")
    text = re.sub(r"\b(?:Engine|Ladder|Quint)\s+\d{1,3}\b", "fire engine", text)  # a fire service's units by call sign
    text = re.sub(r"\bMedic\s+\d{1,3}\b", "ambulance", text)
    text = _numbered_alike(text)
    text = re.sub(r"\b(" + FLEET_NOUNS + r")\s+(?:no\.?\s*|#)?(\d{1,4})\b" + NOT_A_QUANTITY,
                  lambda m: m.group(1) if len(m.group(2)) > 1 or m.group(1).lower() in FLEET_ONLY else m.group(0), text,
                  flags=re.I)  # "car 1" and "unit 2" stay the labels a police report gives
    text = re.sub(r"\b(junction|exit|gate|platform|stand|bay|pier|route|highway|interstate|county road)\s+"
                  r"(?:no\.?\s*|#)?\d{1,4}[a-z]?\b" + NOT_A_QUANTITY, lambda m: m.group(1), text,
                  flags=re.I)  # "at Junction 9", "Route 12"
    return re.sub(r"\(\s*(?:unit|no\.?|fleet no\.?)\s*\d+\s*,\s*", "(", text, flags=re.I)


NUMBERED = re.compile(r"\b(car|truck|bus|van|vehicle)\s+(\d{1,4})\b" + NOT_A_QUANTITY, re.I)


def _numbered_alike(text: str) -> str:
    """'picture car 10 turns right; picture car 11 goes straight behind car 10': vehicles of one kind told apart
    by numbers are as many vehicles, named as a report names them ('car 1', 'car 2'), not one fleet number."""
    said: dict[str, list[str]] = {}
    for m in NUMBERED.finditer(text):
        numbers = said.setdefault(m.group(1).lower(), [])
        if m.group(2) not in numbers:
            numbers.append(m.group(2))
    renamed = {noun: {n: k + 1 for k, n in enumerate(numbers)} for noun, numbers in said.items()
               if 2 <= len(numbers) <= 9 and any(len(n) > 1 for n in numbers)}
    if not renamed:
        return text
    return NUMBERED.sub(lambda m: f"{m.group(1)} {renamed[m.group(1).lower()][m.group(2)]}"
                        if m.group(1).lower() in renamed else m.group(0), text)


DESIGNATION = r"(?:V|Veh|Vehicle|Unit|U)\s?[#-]?\s?(\d{1,2})"  # a crash report's names of its vehicles
EGO_ROLE = r"(?:the\s+)?(?:ego|subject|sv|host)(?:\s+(?:vehicle|car|unit))?"
DESIGNATED_EGO = (
    re.compile(rf"\b{DESIGNATION}\s*\(\s*{EGO_ROLE}\s*(?:[,;:]\s*(?P<what>[^()]*?))?\s*\)", re.I),  # "V1 (ego)"
    re.compile(rf"\b{EGO_ROLE}\s*\(\s*{DESIGNATION}\s*\)", re.I),  # "the subject vehicle (V1)"
    re.compile(rf"\b{EGO_ROLE}\s*(?:=|:|\bis\b)\s*{DESIGNATION}\b", re.I),  # "Ego = V1"
    re.compile(rf"\b{DESIGNATION}\s+(?:is|=)\s+{EGO_ROLE}\b", re.I),  # "V1 is the ego vehicle"
    re.compile(rf"\b{DESIGNATION}\s*(?:,|--|\u2013|\u2014)\s*{EGO_ROLE}\s*(?:,|--|\u2013|\u2014)", re.I))
# "V1, the ego vehicle, is eastbound"


SAME_DESIGNATION = re.compile(rf"\b({DESIGNATION})\s*\(\s*(?:V|Veh|Vehicle|Unit|U)\s?[#-]?\s?(\d{{1,2}})\s*(,\s*|(?=\)))",
                              re.I)


SPELT_DESIGNATION = re.compile(r"\b(?:V|Veh|Vehicle|Unit)(?:\.\s?|\s?[#-]\s?|\s)(\d)\b"
                               r"(?!\s*(?:mph|km|kmh|kph|m\b|metres|meters|ft|feet|lanes?|%|s\b|seconds|minutes))")


def _designations_spelt_alike(text: str) -> str:
    """'Veh. 2', 'V-2', 'Vehicle 2', 'Unit 2' are one report's way of naming V2 (and 'Veh.' ends no sentence); a
    crash database's 'Participant 3' is its P3."""
    text = re.sub(r"\bparticipant\s?[#-]?\s?(\d{1,2})\b", r"P\1", text, flags=re.I)
    patrols = set(re.findall(r"\bUnit\s+(\d{1,3})\b(?=\s*(?:at scene|on scene|attending|in attendance|arrived|"
                             r"\((?:marked|traffic|area|response|patrol|police|arv|irv|rpu)\b[^()]*\)|,\s*marked\s*,))",
                             text, flags=re.I))  # ("Unit 9 (marked car)", "Unit 22 (traffic car)")
    for number in patrols:  # a patrol's own unit by its call sign ("Unit 7 on scene", "Unit 9 (marked) responding
        text = re.sub(rf"\b(Unit)\s+{number}\b", r"\1", text, flags=re.I)  # ... Unit 9 continued"): no crash
        # report's V7
    return SPELT_DESIGNATION.sub(r"V\1", text)


def _designated_ego(text: str, notes: list[str]) -> str:
    """'V1 (ego), a 2016 Honda Accord, is northbound ... V1 initiates its turn': a reconstruction names its vehicles
    V1, V2 (or Unit 1, Unit 2) and says which one the ego is; every mention of that name is the ego, and what the
    bracket says besides ('ego, 2019 Chevrolet Tahoe') describes it."""
    text = SAME_DESIGNATION.sub(lambda m: m.group(1) + " (" if m.group(2) == m.group(3) else m.group(0), text)
    text = re.sub(r"\s*\(\s*\)", "", text)  # "Vehicle 2 (V2)", "Vehicle 1 (V1, ego)": one name said twice
    for pattern in DESIGNATED_EGO:
        m = pattern.search(text)
        if m is not None:
            break
    else:
        return text
    number = next(g for g in m.groups() if g is not None and g.isdigit())
    what = (m.groupdict().get("what") or "").strip()
    if what and not re.match(r"(?i)(?:an?|the)\b", what) and _names_agents(what):
        what = "a " + what  # "(ego, 2019 Chevrolet Tahoe)": one; "(ego, eastbound)" says how it goes
    said = "the ego" + (f", {what}," if what else "")
    text = text[:m.start()] + said + text[m.end():]
    text = re.sub(rf"\b(?:V|Veh|Vehicle|Unit|U)\s?[#-]?\s?{number}\b(?!\s*(?:mph|km|m\b|ft|feet|lanes?))",
                  "the ego", text, flags=re.I)
    text = re.sub(r"((?:^|[.!?]\s+|\n\s*))the ego\b", r"\1The ego", text)
    text = re.sub(r"\bthe ego,\s*,", "the ego,", text)
    notes.append(f"read V{number} as the ego (said so)")
    return text


LISTED_DESIGNATIONS = re.compile(
    rf"\b((?:V|Veh|Vehicle|Unit|U)\s?[#-]?\s?\d{{1,2}}(?:\s*,\s*(?:V|Veh|Vehicle|Unit|U)\s?[#-]?\s?\d{{1,2}})*,?\s+"
    rf"(?:and|&)\s+(?:V|Veh|Vehicle|Unit|U)\s?[#-]?\s?\d{{1,2}})\s*,\s*(?=(?:two|three|four|2|3|4)\s)", re.I)
ORDINAL_NAMES = ("first", "second", "third", "fourth")


def _designated_groups(text: str, notes: list[str]) -> str:
    """'overtaking V2 and V3, two loaded logging trucks travelling in tandem': the names are the counted group's,
    said once; where one of them is named alone later it is the first or the second of the group."""
    for m in list(LISTED_DESIGNATIONS.finditer(text))[:1]:
        names = re.findall(r"(?:V|Veh|Vehicle|Unit|U)\s?[#-]?\s?(\d{1,2})", m.group(1), flags=re.I)
        rest = text[m.end():]
        head = next((w for w in re.findall(r"[a-z]+", rest.split(",")[0].lower())
                     if w.endswith("s") and _vehicle_kind_of_plural(w)), None)
        if head is None or len(names) > len(ORDINAL_NAMES):
            return text
        if re.search(r"(?:^|[.!?;]\s*|\n\s*)$", text[:m.start()]):
            rest = re.sub(r"^([^,.;]*),\s*", r"\1 ", rest, count=1)  # "V2 and V3, two cyclists, cross": the
            # subject, whose apposition closes before its verb
        text = text[:m.start()] + rest
        for k, number in enumerate(names):
            text = re.sub(rf"\b(?:V|Veh|Vehicle|Unit|U)\s?[#-]?\s?{number}\b(?!\s*(?:mph|km|m\b|ft|feet|lanes?))",
                          f"the {ORDINAL_NAMES[k]} {_vehicle_kind_of_plural(head)}", text, flags=re.I)
        text = re.sub(r"((?:^|[.!?]\s+|\n\s*))the (first|second|third|fourth)\b", r"\1The \2", text)
        notes.append(f"read {', '.join('V' + n for n in names)} as the {head} named with them")
    return text


def _vehicle_kind_of_plural(word: str) -> str | None:
    """'trucks' -> 'truck', 'buses' -> 'bus': the singular of an agent noun, or None."""
    for singular in (word[:-1], word[:-2]):
        entry = lexicon().phrases.get((singular,))
        if entry is not None and entry[0] == "agents" and entry[1] not in ("ego", "none"):
            return singular
    return None


BARE_APPOSITION = re.compile(r"\b((?:the ego|(?:V|Veh|Vehicle|Unit|U|Ped|P|Cyc|Cyclist|Pedestrian)\s?[#-]?\s?\d{1,2}))"
                             r"(\s*(?:\([^()]*\)\s*)?,\s*)(?=\S)(?!(?:an?|the|which|who|whose|that|and|but|then|its|his|her)\b)"
                             r"(?=([^,.;()]{2,60}?)\s*,)", re.I)


def _bare_appositions(text: str) -> str:
    """'V2, Ford F-150 pickup, is southbound', 'Ped 1, adult male, is crossing': a note that drops its articles
    still says what a named one is; read with its article, as one ('a Ford F-150 pickup')."""
    return BARE_APPOSITION.sub(lambda m: m.group(1) + m.group(2) + ("a " if _names_agents(m.group(3)) else ""), text)


EGO_MADE = re.compile(r"\b(?:make|let|have|set)\s+(?:the\s+)?ego(?:\s+(?:vehicle|car))?\s+(?:to\s+)?(?:be\s+)?"
                      r"(?=(?:a|an)\s)", re.I)


EGOS_OWN_WITH_OF = re.compile(r"\b(?:the\s+)?(car|vehicle|truck|bus|van|motorcycle|motorbike)\s+of\s+(?:the\s+)?ego\b",
                              re.I)


def _ego_made_a_kind(text: str) -> str:
    """'Make the ego a bus that stops at a bus stop', 'let the ego be a truck': a request for the ego's kind,
    said as what the ego is; 'the car of the ego', as Romance languages say it, is the ego."""
    text = EGOS_OWN_WITH_OF.sub(lambda m: f"the ego {m.group(1).lower()}", text)
    return EGO_MADE.sub("the ego is ", text)


@lru_cache(maxsize=1)
def _apposed_role() -> re.Pattern:
    return re.compile(r"\b(?:a|an|the)\s+(?:[a-z]+\s+){0,2}?([a-z]+)\s*,\s*as\s+(?:the|our)\s+(?:" + _ego_roles() +
                      r")\b(?:\s+(?:vehicle|car))?\s*(?=,)", re.I)


def _role_in_apposition(text: str) -> str:
    """'a motorcyclist, as the subject vehicle, riding along Queen Street': the role said in passing is declared
    as 'the motorcyclist is the subject vehicle' would declare it."""
    m = _apposed_role().search(text)
    if m is None or _vehicle_kind(m.group(1).lower()) is None:
        return text
    return text[:m.start(1) + len(m.group(1))] + text[m.end():] + f" The {m.group(1).lower()} is the ego."


def _declared_ego(text: str, notes: list[str]) -> str:
    """'Our van is the ego', 'with the taxi as the ego', 'Van = ego': that vehicle, and its driver, are the ego
    wherever the text names them by role, by fleet name or by name."""
    declaration, any_declaration = _declarations()
    text = _role_in_apposition(text)
    said = text  # ("Car 1 is the ego, waiting" keeps the ego where the text names it)
    m = declaration.search(text)
    if m is not None:
        noun, kind = m.group(2).lower(), VEHICLE_NOUNS[m.group(2).lower()]  # the noun after the adjective
        text = declaration.sub("", text)
    else:  # "our tram is the ego", "with the ambulance as the ego": a vehicle the reader knows by another noun
        m = next((d for d in any_declaration.finditer(text) if _vehicle_kind(d.group(2).lower())), None)
        if m is None:
            return text
        noun, kind = m.group(2).lower(), _vehicle_kind(m.group(2).lower())
        text = text[:m.start()] + text[m.end():]
    ego = EGO_NOUN.get(kind, f"the ego {noun}")  # "the ego ambulance"
    notes.append(f"read the {noun} as the ego (said so)")
    numbered = rf"\b{noun}\s+(?:no\.?\s*|#)?0*(\d+)\b" + NOT_A_QUANTITY
    number = int(m.group("number")) if m.group("number") is not None else None
    if number is not None and any(int(n) != number for n in re.findall(numbered, said, re.I)):
        declared = m.group(0).lstrip(", ")  # "Car 1 is the ego ... car 2 is oncoming": the others are numbered alike,
        if not re.match(r"(?i)(?:with|using|having)\b", declared):  # and only car 1 is the ego
            said = said[:m.start()] + m.group(0)[:len(m.group(0)) - len(declared)] + ego + said[m.end():]
        else:
            said = text  # ("with car 1 as the ego, ..." says no more)
        return _named_driver(re.sub(numbered, lambda n: ego if int(n.group(1)) == number else n.group(0), said,
                                    flags=re.I), notes)
    met = re.findall(rf"\b(?:a|an)\s+(?:[a-z]+\s+){{0,2}}?{noun}\b", text, flags=re.I)
    if len(met) == 1 and re.match(r"(?:,\s*)?(?:(?:with|using|having)\s+)?the\b", m.group(0), re.I):
        text = text.replace(met[0], ego, 1)  # "... just as a taxi in that lane draws alongside; the taxi is the
        # subject vehicle": the one met is the one declared (not "with our van as ego": ours, not "an oncoming van")
    plural = noun + ("es" if noun.endswith("s") else "s")
    text = re.sub(rf"\bone of (?:our|my|the) (?:[a-z]+ )?{plural}\b", ego, text, flags=re.I)
    text = re.sub(rf"\b(?:{FLEET_NOUNS})\s+(?:no\.?\s*|#)?\d{{2,4}}\b" + NOT_A_QUANTITY +
                  r"(?:\s*\(\s*(?:[A-Za-z]+\s+)?"
                  rf"{noun}\s*,)?", ego, text, flags=re.I)  # "vehicle 311 (Transit van, ...)": the fleet's vehicle
    text = re.sub(rf"\b{noun}\s+(?:no\.?\s*|#)?\d{{1,4}}\b(?!\s*(?:mph|km|kmh|kph|m\b|metres|meters|feet|ft|seconds|"
                  rf"s\b|minutes|lanes?|%|percent))", ego, text, flags=re.I)  # "Van 203 (driver ...)": a fleet name
    own = {(m.group("adjective") or "").lower()} - {"our", "the", "my", "this", "that", "with", "using", ""}
    adjectives = "|".join(sorted(FLEET_ADJECTIVES | own))  # "the red car is the ego": "the blue car" is another
    text = re.sub(rf"\b(?:our|my|the|this|that)\s+(?:(?:{adjectives})\s+)?{noun}\b", ego, text, flags=re.I)
    text = re.sub(rf"\b(?:our|my)\s+(?!(?:other|another|second|spare|old|new)\b)(?:[a-z]+\s+){{1,2}}?{noun}\b", ego,
                  text, flags=re.I)  # "our white delivery van": whatever else it is called, ours is the ego
    text = re.sub(rf"(?:^|(?<=[.!?,(]\s)|(?<=\n))\b{noun}\b(?=\s*(?:\(|,|is\b|was\b|had\b))", ego, text,
                  flags=re.I)  # "Cab is the ego", "Taxi, driver ...": bare at a sentence's start
    text = re.sub(r"\b(?:our|my|the|this|that)\s+(?:[a-z]+\s+)?the ego\b", "the ego", text, flags=re.I)
    return _named_driver(text, notes)


def _vehicle_kind(noun: str) -> str | None:
    """The ego kind a vehicle noun names: 'van' a car, 'tram' a bus, 'ambulance' an ambulance; None for what is
    no vehicle the ego can be."""
    if noun in VEHICLE_NOUNS:
        return VEHICLE_NOUNS[noun]
    meaning = lexicon().phrases.get((noun,))
    return meaning[1] if meaning and meaning[0] == "agents" and meaning[1] in V.EGO_TYPES else None


def _named_driver(text: str, notes: list[str]) -> str:
    """'(driver: Aisha Rahman)', 'Tom Akers driving', 'Jamie Cole in van 140': the ego's driver is the ego, by
    name and by the pronoun the text gives them."""
    names: list[str] = []
    for pattern in DRIVER_NAMED:
        for m in pattern.finditer(text):
            words = [w for w in m.group(1).split() if w not in NOT_NAMES]
            if words:
                names.append(" ".join(words))
    for m in LOWER_CASE_DRIVER.finditer(text):  # "(driver marek nowak)": a name written in lower case
        words = [w for w in (m.group(1) or m.group(2)).split() if w.capitalize() not in NOT_NAMES]
        if words and not any(known_word(w) for w in words):
            names.append(" ".join(words))
    text = re.sub(r"\(\s*(?:driver\s*:?\s*)?" + FULL_NAME + r"(?:\s+driving)?\s*\)", "", text)
    text = re.sub(r",?\s*\b(?i:driver)\s*:?\s+" + FULL_NAME + r"\s*(?=[,)])", "", text)
    for name in sorted(set(names), key=len, reverse=True):
        parts = [name] + ([name.split()[0]] if " " in name else [])
        for part in parts:  # "ray braked hard" after "(driver Ray)"; a name that is also a word ("Will") as written
            flags = 0 if known_word(part) else re.I
            text = re.sub(rf"\b{re.escape(part)}'s\b", "the ego's", text, flags=flags)
            text = re.sub(rf"\b{re.escape(part)}\b", "the ego", text, flags=flags)
        notes.append(f"read {name} as the ego's driver")
    text = re.sub(r"\b(?:driver|driven by)\s*:?\s*the ego\b", "the ego", text, flags=re.I)
    text = re.sub(r"\bthe ego(?:\s*,)?\s+(?:\(\s*)?the ego\b\s*\)?", "the ego", text)
    return _drivers_pronoun(text, notes) if names or "the ego" in text else text


NARRATORS_DRIVER = "read the narrator's driver as the ego"  # the note that says a passenger tells the scene
NOT_A_CAR_PART = r"(?![\s-]+(?:side|seat|door|window|mirror)\b)"  # "my driver side mirror": the car's, no person


DRIVERS_WORDS_KEY = r"(?!\s*(?:comments?|statement|remarks?|notes?|account|report|says?)\s*:\s*(?:i|we|my|our)\b)"
# ("Driver comment: I had a green": the key of what the driver said, in the first person; "Driver comment: followed
# a bus", "Driver: going through on green" are the ego's own lines)


def _passengers_driver(text: str, notes: list[str]) -> str:
    """'my driver eased off', 'Driver slowed way down': a passenger's account; whoever drives the narrator is the
    ego, named by role ('my driver', 'the driver' when no other vehicle is named before) or by name."""
    said = re.search(r"\b(?i:my|our)\s+(?:uber\s+|lyft\s+|cab\s+|taxi\s+)?driver\b" + NOT_A_CAR_PART +
                     r"(?:\s*,?\s*(" + FULL_NAME + r"))?", text)
    bare = re.search(r"(?:^|[.!?,]\s+)(?:the\s+)?[Dd]river\b(?!\s+of\b)" + DRIVERS_WORDS_KEY, text)
    if said is None and bare is None:
        return text
    before = text[:(said or bare).start()]
    if said is None and (re.search(r"\b(?:an?|the|some|this|that)\s+(?:[a-z]+\s+){0,2}?(?:" + _NOUN[1:-1] +
                                   r"|cyclist|rider)s?\b", before, re.I) or re.search(
            r"(?:^|[.!?]\s+)(?:[\w-]+\s+)?" + _NOUN + r"\b(?!\s+(?:was|is|were)\b)", before, re.I)):
        return text  # "a truck pulled out. The driver ...", "Broken-down HGV ahead. Driver got out": its driver
        # ("Car was clean, driver was friendly": the ride's own)
    names = [w for w in (said.group(1).split() if said and said.group(1) else []) if w not in NOT_NAMES]
    text = re.sub(r"\b(?i:my|our)\s+(?:uber\s+|lyft\s+|cab\s+|taxi\s+)?driver\b" + NOT_A_CAR_PART +
                  r"(?:\s*,?\s*" + FULL_NAME + r")?", "the ego", text) if said else text
    text = re.sub(r"(^|[.!?,]\s+)(?:[Tt]he\s+)?[Dd]river\b(?!\s+of\b)" + DRIVERS_WORDS_KEY, r"\1the ego", text)
    text = re.sub(r"(^|[.!?,]\s+)(?:[Tt]he\s+)?[Cc]ar\s+(?=(?:was|is|smelled|smelt|smells|looked|looks|felt|feels)\s+"
                  r"(?!in\b|on\b|at\b|ahead\b|behind\b|next\b|beside\b|stopped\b|parked\b|coming\b|going\b|"
                  r"driving\b|turning\b|waiting\b|pulling\b))", r"\1the ego ", text)  # "Car was clean": the ride
    role = re.search(r"\b([A-Z][a-z]+)\s*\([^()]*\bthe ego\s*\)", text)  # "Caller (F, driver) ... Caller's veh"
    if role is not None and role.group(1) not in NOT_NAMES:
        names.append(role.group(1))
    for name in names:
        text = re.sub(rf"\b{re.escape(name)}'s\b", "the ego's", text)
        text = re.sub(rf"\b{re.escape(name)}\b", "the ego", text)
    notes.append(NARRATORS_DRIVER)
    return _drivers_pronoun(text, notes)


KIN_AT_THE_WHEEL = r"husband|wife|partner|boyfriend|girlfriend|dad|father|mum|mom|mother|son|daughter|brother|sister"


NAME = (r"(?:[A-Z]\. )?[A-Z\u00c0-\u00de][a-z\u00df-\u00ff]+(?:[-'][A-Z][a-z]+)?"
        r"(?: [A-Z][a-z\u00df-\u00ff]+(?:-[A-Z][a-z]+)?)?")  # "Tyler", "M. Kowalski", "Tomás Ruiz", "O'Neil"
DRIVER_ROLES = "driver|trainee|student|pupil|learner|motorist|motorcyclist|biker|rider|cyclist|trucker|cabbie|chauffeur"
VEHICLE_ROLES = {"bus", "coach", "taxi", "cab", "cabbie", "lorry", "truck", "trucker", "haulage", "hgv", "van",
                 "delivery", "motorcyclist", "motorcycle", "motorbike", "biker", "rider", "cyclist", "scooter",
                 "minibus"}  # a role that says what is driven ("Bus driver Janet Lowe")
AT_THE_WHEEL = (
    "drove|drives|drive|driving|rode|rides|riding|pulled|turned|stopped|moved|changed|braked|waited|eased|signall?ed|"
    "indicated|merged|overtook|slowed|stayed|kept|carried|went|took|borrowed|heading|travell?ing|approaching|"
    "approached|taking|following|going|coming|sitting|waiting|queuing|queueing|behind the wheel|at the wheel|"
    "stopping|turning|pulling|reversing|overtaking|crept|edged|nosed|inched|steered|swerved|reversed|entered|joined|"
    "came|headed|had to|has to|offered to drive|agreed to drive|set off|moved off|creeping|cruising|crawling|rolling|"
    "(?<=was )(?:in|on) (?!(?:that|the|a) (?:crosswalk|crossing|zebra|road|street|pavement|sidewalk)\b)|"
    "(?<!, )in the (?:left|right|middle|inside|outside|fast|slow)(?:-hand)? lane")  # ("Hannah in the right lane")
NAMED_DRIVER = re.compile(
    rf"(?P<role>(?:(?:[Mm]y|[Oo]ur) (?:[A-Za-z-]+ ){{0,2}}?[a-z-]+,? |(?:(?i:{'|'.join(sorted(VEHICLE_ROLES))}|"
    rf"learner) )?(?i:{DRIVER_ROLES}) ))?(?<![\w'\u00c0-\u00ff])(?P<name>{NAME})"
    rf"(?P<aside>(?:, (?:[^,.;]{{1,40}}),)?)(?:,? |(?='s first (?:time|drive|lesson)))"
    rf"(?P<verb>'s first|(?:who (?:still |now )?|has |had |was |is |then |just |carefully |slowly )*"
    rf"(?:{AT_THE_WHEEL})\b)")  # the role before the name ("our daughter Zoe"), an aside after it (", 58,")
SHE_ROLES = {"wife", "daughter", "girlfriend", "mum", "mom", "mother", "sister", "gran", "grandma", "nan", "aunt",
             "niece", "fiancee"}
HE_ROLES = {"husband", "son", "boyfriend", "dad", "father", "brother", "grandad", "grandpa", "uncle", "nephew",
            "fiance"}
AS_THE_TELLER = {"he": {"he": "I", "him": "me", "his": "my", "himself": "myself"},
                 "she": {"she": "I", "her": None, "hers": "mine", "herself": "myself"}}


def _named_at_the_wheel(text: str, notes: list[str]) -> str:
    """'Tyler was in the left lane when he signalled and moved over', 'Bus driver Janet Lowe pulled out': one named
    at the wheel, told of in the third person, is read as a teller telling their own drive ('I was in the left
    lane when I signalled ...'): the reading of a teller's drive places everyone by them. Only the first one named
    at the wheel, and only in a text with no ego named otherwise."""
    if re.search(r"(?i)\bego\b|\b(?:i|we) (?:was |were |am |are )?(?:driving|drove|drive)\b", text):
        return text
    m = next((m for m in NAMED_DRIVER.finditer(text) if _a_persons_name(m, text)), None)
    if m is None:
        return text
    role = (m.group("role") or "").strip(" ,")
    role_words = set(role.lower().split())
    teller = f"I, a {role.lower().split(' ', 1)[1] if role_words & {'my', 'our'} else role.lower()}," \
        if role_words & VEHICLE_ROLES else "I"
    parts = m.group("name").split()
    names = {m.group("name")} | {p for p in parts if len(p) > 2}
    said = re.compile(r"\b(" + "|".join(re.escape(n) for n in sorted(names, key=len, reverse=True)) + r")('s)?\b",
                      re.I if re.fullmatch(PARTY_ROLES, m.group("name")) else 0)  # ("Client ... client's left")
    rest = text[m.end("name"):]
    opening_a_clause = re.search(r"(?i)(?:^|[.,;:!?]|\b(?:and|so|but|then|when|while|once|until|before|after|as|"
                                 r"because|that|where))\s+(he|she)\b", rest)  # ("a car he'd stopped": another's)
    said_of = opening_a_clause or re.search(r"(?i)\b(he|she|him|his|her|himself|herself)\b", rest)
    gender = "she" if role_words & SHE_ROLES else "he" if role_words & HE_ROLES else None if said_of is None else \
        "she" if said_of.group(1).lower() in ("she", "her", "herself") else "he"
    rest = said.sub(lambda n: "my" if n.group(2) else "I", rest)
    if gender is not None:
        table = AS_THE_TELLER[gender]
        rest = re.sub(r"\b(" + "|".join(table) + r")\b(?=(\W+\w+)?)", lambda p: _as_the_teller(p, table), rest,
                      flags=re.I)
    if rest.startswith("'s"):  # "Mia's first time on the beltway"
        teller, rest = "my", rest[2:]
    opening = re.sub(r"\b(?:[Mm]y|[Oo]ur|[Hh]is|[Hh]er|[Tt]heir) $", "", text[:m.start()])  # ("our Kayla turned")
    notes.append(f"read {m.group('name')}, at the wheel, as the teller")
    return opening + (teller.rstrip(",") if rest[:1] == "," else teller) + rest


def _a_persons_name(m: re.Match, text: str) -> bool:
    """A name said as a person's: not a street ('Canal Street'), a make ('a black BMW'), a known word, or one that
    opens a sentence and is a word the reader knows ('Then', 'Will')."""
    name = m.group("name")
    if name.split()[0] in NOT_NAMES:
        return False
    before = text[:m.start("name")].rstrip()
    if re.search(r"(?i)\b(?:a|an|the|on|in|at|into|onto|from|to|along|via|near|past|towards|of|off|behind|by|"
                 r"mrs?\.?|ms\.?|miss|dr\.?|officer|pc|sergeant|constable)(?: \d+-year-old)?$",
                 before) or before.endswith("'s") or name.isupper() or text[:m.start()].rstrip().endswith(" of"):
        return False
    word_before = re.search(r"([A-Za-z]+)\W*$", before)
    if not m.group("role") and word_before and before[-1:].isalpha() and \
            word_before.group(1).lower() not in BEFORE_A_NAME_AT_THE_WHEEL:
        return False  # "a silver Zafira pulled out": a make said after its colour
    return bool(m.group("role")) or not any(known_word(p) or lexicon().base(p.lower())[0] in lexicon().vocabulary
                                            for p in name.split())


BEFORE_A_NAME_AT_THE_WHEEL = {"and", "but", "so", "then", "when", "while", "as", "after", "before", "until",
                              "because", "once", "night", "today", "yesterday", "morning", "afternoon", "evening",
                              "let", "with", "support", "says", "said", "that", "where", "if", "though", "although",
                              "old"}  # ("34-year-old Daniel Okafor was on Harbour Road")


def _as_the_teller(p: re.Match, table: dict[str, str | None]) -> str:
    """The pronoun of the one named at the wheel, as the teller says it of themself."""
    word, after = p.group(1), p.group(2) or ""
    said = table[word.lower()]
    if said is None:  # 'her': 'my' before what she owns ('her lane'), else 'me' ('behind her')
        nxt = after.strip(" \t").lower()
        said = "me" if not nxt or not nxt[0].isalpha() or re.fullmatch(AFTER_AN_OBJECT, nxt) else "my"  # (as
        # _drivers_pronoun tells 'her' the owner from 'her' the one done to)
    return said


def _kin_at_the_wheel(text: str, notes: list[str]) -> str:
    """'My husband and I were returning along the A38 ... My husband moved across into the left-hand lane': the
    one of the teller's family who drives them is the ego, the 'we' of the teller's party."""
    m = re.search(rf"\b[Mm]y ({KIN_AT_THE_WHEEL})(?:,\s*who\s+was\s+(?:driving|at\s+the\s+wheel),)?\s+"
                  rf"(?:[a-z]+ly\s+)?(?:{STORY_DRIVING}|moved|swerved|stopped|slammed|was at the wheel|"
                  rf"was behind the wheel|went round|went around|had to (?:go|stop|brake|swerve|pull|slam|turn))\b",
                  text)  # ("my son, who was driving, moved over", "my mum had to go round it")
    if m is None or not CREW.search(text) or WALKING.search(text) or RIDING.search(text):
        return text  # (not a party on foot or on bikes: "my son and I were crossing ... my son turned back")
    kin = m.group(1)
    text = re.sub(rf"\b(?:[Mm]y {kin} and I|[Mm]e and my {kin})\b", "we", text)
    text = re.sub(rf"\b[Mm]y {kin}'s\b", "our", text)
    text = re.sub(rf"\b[Mm]y {kin}(?:,\s*who\s+was\s+(?:driving|at\s+the\s+wheel),)?", "we", text)  # (the ego
    # as the teller's party says it)
    notes.append(f"read the teller's {kin}, at the wheel, as the ego")
    return text


CREW = re.compile(r"\b(?:we|us|our)\b", re.I)
ANY_VEHICLE = re.compile(r"\b(?:(the)\s+)?(?:[a-z-]+\s+)?vehicles?\b", re.I)
THE_VEHICLE_ACTS = re.compile(r"\b[Tt]he vehicle\b(?!'s\b|\s+(?:ahead|in|on|to|behind|beside|next|alongside|from|"
                              r"that|which|who|of|at|with|coming|going|approaching|travelling|traveling|driving|"
                              r"parked|stopped)\b)")


SUBJECT_BEFORE_ITS_NOUN = r"subject\s+(?!vehicle\b|to\b)(?=(?:[a-z]+\s+)?(?:" + _NOUN[1:-1] + \
    r"|motorcyclist|cyclist|rider)\b)"
# ("Subject motorbike waiting at the give-way line": a log's subject named by what it is)
SUBJECT_ROLE = re.compile(r"\(the subject\)|(?:^|(?<=[.;:!?(]\s)|(?<=[.;:!?(]))\s*subject\s*[:,]|"
                          r"(?<![\w'-])subject\s*[:=]|=\s*subject\b|(?:^|(?<=[.;:!?|]\s)|(?<=[.;:!?|]))\s*"
                          r"(?:\+?\d+(?:\.\d+)?\s*s?\s+)?" + SUBJECT_BEFORE_ITS_NOUN, re.I | re.M)  # ("+0.0s subject
# box truck NB": after a log's time stamp)
SUBJECT_LABELLED = re.compile(r"(?:\bobj(?:ect)?\s+([A-Z])\s+|(#\d{1,3})\s+)?([a-z]+)\s*=\s*subject\b|"
                              r"(#\d{1,3})\s+subject\s*:", re.I)  # "obj A motorcycle = subject", "#1 subject: taxi":
# the label it is called by
THE_SUBJECT = re.compile(r"\b(?:the\s+)?subject\b(?!\s+(?:to|vehicle|car|veh|of|matter|area)\b)", re.I)


def _observed_subject(text: str, notes: list[str]) -> str:
    """'left-turning car (the subject) against an opposing through motorcycle', 'Subject: a grey SUV going
    straight ... from the subject's right': an observer's write-up names the road user it watched the subject, and
    the scene is told from it (a road 'subject to a 30 mph limit' says nothing of anyone)."""
    if not SUBJECT_ROLE.search(text) or re.search(r"\bego\b", text, re.I):
        return text
    notes.append("read the observed subject as the ego")
    m = SUBJECT_LABELLED.search(text)
    label = m and (m.group(1) or m.group(2) or m.group(4))
    if m and m.group(3):
        text = text[:m.start()] + f"the ego {m.group(3)}" + text[m.end():]
    if label:  # "approaching from A's left", "to #1's left", "in front of #1"
        text = re.sub(rf"(?<![\w#]){re.escape(label)}(?='s\b)", "the ego", text)
        if label[0] == "#":  # a log's numbered lines: the numbers are names, never counts
            text = re.sub(rf"(?<![\w#]){re.escape(label)}\b(?!\s*subject)", "the ego", text)
            text = re.sub(r"(?m)^([ \t]*)#\d{1,3}[ \t]+(?=\w)", r"\1", text)
    text = re.sub(r"\b(\w+)\s*\(the subject\)", r"ego \1", text, flags=re.I)  # "left-turning ego car"
    text = re.sub(r"((?:^|[.;:!?(])\s*)subject\s*:\s*(?=(?:a|an)\b)", r"\1The ego is ", text, flags=re.I | re.M)
    text = re.sub(r"((?:^|[.;:!?(])\s*)subject\s*:\s*", r"\1Ego: ", text, flags=re.I | re.M)
    text = re.sub(r"((?:^|[.;:!?(])\s*)subject\s*,\s*(?=(?:a|an|the)\b)", r"\1the ego, ", text, flags=re.I | re.M)
    text = re.sub(r"((?::|^\s*\+?\d+(?:\.\d+)?\s*s?)\s+)subject\s*=\s*(?!(?:a|an|the)\b)", r"\1the ego is a ", text,
                  flags=re.I | re.M)  # "Event 1123: subject = delivery box truck", "+0.0 subject = route 7 bus":
    # after another key or a time stamp on its line, said as a sentence
    text = re.sub(r"(?<![\w'-])subject\s*=\s*", "Ego: ", text, flags=re.I)  # "subject = white SUV (trk 77)"
    text = re.sub(r"((?:^|[.;:!?|])\s*(?:\+?\d+(?:\.\d+)?\s*s?\s+)?)" + SUBJECT_BEFORE_ITS_NOUN, r"\1the ego ", text,
                  flags=re.I | re.M)  # "Subject motorbike"
    text = re.sub(r"(?<=\s)subject\s*:\s*", "\nEgo: ", text, flags=re.I)  # "+0.0 s  Subject: box truck SB": a key,
    # on a line of its own
    return THE_SUBJECT.sub("the ego", text)


LEARNING = re.compile(r"\b(?:rewards?|rewarded|episodes?|env|envs|policy|curriculum|obs|observations?|rl|"
                      r"reinforcement|training|trained|gym)\b", re.I)
THE_AGENT = re.compile(r"\b(?:(?:the|our|my)\s+(?:rl\s+|learning\s+)?agent|(?:^|(?<=[.;:!?]\s))agent)\b(?!s\b|\s*_?\d)",
                       re.I | re.M)


def _learning_agent(text: str, notes: list[str]) -> str:
    """'I need an env where the agent has to merge', 'Agent gets rewarded for ...': in a request for a learning
    environment the agent is the vehicle the policy drives, the ego (the NPCs around it are not agents of it)."""
    if not LEARNING.search(text) or not THE_AGENT.search(text):
        return text
    notes.append("read the learning environment's agent as the ego")
    return THE_AGENT.sub("the ego", text)


FLEET_UNIT = re.compile(r"\bunit\s*(?:(?:no\.?\s*|#\s*)?(\d{1,5})\b|(?=\())(?:\s*\(([^()]{1,40})\))?", re.I)
# ("Unit 4417 (tractor-trailer)"; "Unit (marked car)": a patrol's call sign, its number taken off before)
THE_UNIT = re.compile(r"(?<![\w-])(?:(the|of|behind|beside|past|around|passed|struck|hit|towards|toward|to|with|at|"
                      r"alongside)\s+)?unit\b(?!\s*(?:no\.?\s*|#\s*)?\d)", re.I)


def _fleet_unit(text: str, notes: list[str]) -> str:
    """'Unit 4417 (tractor-trailer) in right lane ... cut in ahead of the unit. Driver braked': a fleet's record
    names its own vehicle by a unit number, and that vehicle is the ego; only where the text names no ego, no
    numbered vehicle and one unit alone (a crash report's Unit 1 and Unit 2 are its vehicles' labels)."""
    units = {m.group(1) for m in FLEET_UNIT.finditer(text) if m.group(1) or SIGNS_VEHICLE.search(m.group(2) or "")}
    if len(units) != 1 or re.search(r"\bego\b|\b(?:v|veh|vehicle)\s?#?\d\b|\bsubject\s+veh", text, re.I) or \
            re.search(FLEET_UNIT.pattern + r"\s*(?:reports|reporting|at scene|on scene|attend)", text, re.I):
        return text  # ("Unit 12 at scene ... V1 stationary at red": the unit reports a crash of vehicles it numbers)
    notes.append("read the record's unit as the ego")
    body = FLEET_UNIT.search(text).group(2) or ""
    text = FLEET_UNIT.sub(lambda m: "the ego" if not m.group(2) else f"the ego {m.group(2)}" if m.group(1) else
                          f"the ego, a {m.group(2)},", text, count=1)  # ("Unit (marked car)": a patrol's own car)
    text = re.sub(r"(?:^|(?<=[.;!?]\s))[Dd]river\b" + DRIVERS_WORDS_KEY, "the ego", text, flags=re.M)  # "Driver
    # braked", said bare (not "Driver comment: I had a green", the key of what the driver told)
    if re.search(r"truck|trailer|lorry|semi|hgv|rig\b", body, re.I):
        text = re.sub(r"\bthe (?:cab|trailer|tractor)\b", "the ego", text, flags=re.I)  # "level with the cab": its own

    def own(m: re.Match) -> str:  # "the unit", "in front of unit", "Unit then braked"; not "a tractor unit"
        opening = not text[:m.start()].rstrip() or text[:m.start()].rstrip()[-1] in ".;:!?,"  # (", unit pulled out")
        if m.group(1) is None and not opening:
            return m.group(0)
        return "the ego" if m.group(1) is None or m.group(1).lower() == "the" else f"{m.group(1)} the ego"
    return THE_UNIT.sub(own, text)


CALL_SIGN = re.compile(r"(?<![\w/-])((?:[A-Z]{1,5}-?\d{1,3}[A-Z]?|[A-Z][a-z]+-\d{1,3})(?:-\d{1,2})?)"
                       r"\s*\(([^()]{1,40})\)")  # "MP21 (marked patrol car)", "E21 (fire engine)", "Tango-6 (...)"
SIGNS_VEHICLE = re.compile(r"\b(?:car|van|ambulance|engine|appliance|pump|tender|bus|coach|lorry|truck|hgv|tanker|"
                           r"artic|tipper|minibus|cruiser|suv|irv|arv|rpu|patrol|traffic|vehicle|unit|motorcycle|"
                           r"bike)s?\b", re.I)  # what a call sign's brackets say it is


def _call_sign_unit(text: str, notes: list[str]) -> str:
    """'2214 MP21 (marked patrol car) WB Station Rd ... passed us', 'INC 0457 / E21 (fire engine) mobile on blues ...
    car directly ahead of E21': a radio or dispatch log names the unit it follows by a call sign, with what it is in
    brackets, and says the sign again for it: that unit is the ego. Only one sign so described, in a text with no
    ego, numbered vehicle or fleet unit of its own (a crash report's 'V2 (Royal Mail van)' labels a vehicle)."""
    signs = {m.group(1) for m in CALL_SIGN.finditer(text) if SIGNS_VEHICLE.search(m.group(2))}
    if len(signs) != 1 or re.search(r"\bego\b|\b(?:v|veh|vehicle)\s?#?\d\b|\bsubject\s+veh|\bunit\b", text, re.I):
        return text
    sign = signs.pop()
    notes.append(f"read the log's unit {sign} as the ego")
    first = next(m for m in CALL_SIGN.finditer(text) if m.group(1) == sign)
    text = text[:first.start()] + f"the ego, a {first.group(2)}," + text[first.end():]
    return re.sub(rf"(?<![\w/-])(?:the\s+)?{re.escape(sign)}(?![\w-])", "the ego", text)


def _crews_vehicle(text: str, notes: list[str]) -> str:
    """'We stayed in lane two and the vehicle eased off', 'a van was double-parked in our lane and the vehicle just
    sat behind it, so I disengaged': a crew riding an automated vehicle ('we', a safety driver) speaks of it as 'the
    vehicle' and of itself as 'we'; both are the ego. Only when no other vehicle is called a vehicle ('a vehicle',
    'the other vehicle', 'vehicles') and 'the vehicle' is not placed ('the vehicle ahead')."""
    if not CREW.search(text) or "the ego" in text:
        return text
    mentions = list(ANY_VEHICLE.finditer(text))
    if not mentions or any(m.group(1) is None or m.group(0).lower() != "the vehicle" for m in mentions):
        return text
    if not THE_VEHICLE_ACTS.search(text):
        return text
    notes.append("read 'the vehicle' of a crew that says 'we' as the ego")
    return THE_VEHICLE_ACTS.sub("the ego", text)


STORY_DRIVING = (r"came|drove|pulled|turned|braked|slowed|crept|eased|steered|indicated|swung|rolled|edged|nosed|"
                 r"inched|merged|reversed|overtook|followed|accelerated|headed|was driving|had been driving|"
                 r"was heading|was following|was cruising|was doing|kept|held|hung|sat|drives|pulls|turns|brakes|"
                 r"slows|creeps|eases|steers|indicates|swings|edges|merges|follows|accelerates|heads|is driving")
STORY_DRIVER = re.compile(rf"\b(she|he)\s+(?:[a-z]+ly\s+)?(?:{STORY_DRIVING})\b", re.I)
FIRST_PERSON = re.compile(r"\b(?:i|me|my|we|us|our|ego)\b", re.I)


CALLER_AT_THE_WHEEL = re.compile(r"\b(?:the\s+)?(?:caller|client|claimant|complainant|customer|informant|insured|rp)"
                                 r"\s+(?:is|was)\s+(?:(?:the\s+)?driver\s+of\s+(?:an?\s+|the\s+)?"
                                 r"(?P<of>(?:[a-z-]+\s+){0,2}?" + _NOUN + r")|"
                                 r"(?:an?\s+)?(?P<by>(?:[a-z-]+\s+){0,2}?" + _NOUN + r")\s+driver)\b", re.I)
# ("Caller is driver of city bus", "Caller is taxi driver w/ fare on board")


def _caller_at_the_wheel(text: str, notes: list[str]) -> str:
    """'Caller is driver of city bus, route 42. Says he was pulling away from the stop': the one who tells, said to
    be the driver of a vehicle, tells from that vehicle: it is the ego."""
    m = CALLER_AT_THE_WHEEL.search(text)
    if m is None:
        return text
    vehicle = m["of"] or m["by"]
    notes.append(f"read the {vehicle.lower()} the teller drives as the ego")
    return text[:m.start()] + f"The ego is a {vehicle}" + text[m.end():]


PARTY_ROLES = r"(?:[Tt]he |[Mm]y |[Oo]ur )?(?:[Cc]lient|[Cc]laimant|[Ii]nsured|[Pp]olicyholder|[Dd]efendant|" \
              r"[Pp]laintiff|[Cc]omplainant)"
PARTY_LETTER = r"\b(?:[B-HJ-Z]|[A-Z]{2,3})\b(?!\.)"  # "D", "P", "IV" ("A" and "I" are words; "J. Smith" an initial)
AFTER_A_LINK = "|".join(rf"(?<=\b{w}\s)" for w in ("when", "as", "while", "then", "and", "but", "that", "Suppose",
                                                    "suppose", "Assume", "assume", "Imagine", "imagine"))
TITLE = r"(?:(?:Mr|Mrs|Ms|Miss|Dr)\.?\s+)"
PARTY_DRIVING = re.compile(
    rf"(?:^|(?<=[.!?;:,]\s)|{AFTER_A_LINK})({PARTY_LETTER}|{TITLE}?{FULL_NAME}|{PARTY_ROLES})"
    rf"(?:,[^,.]{{1,60}},|\s*\([^()]{{1,60}}\))?\s+(?:[a-z]+ly\s+)?(?:{STORY_DRIVING}|wants to turn|waits|"
    rf"was waiting|is waiting|was stopped|is stopped|stops|stopped|was changing lanes|changes lanes|travels|"
    rf"proceeds|intends to (?:turn|make)|begins a (?:left|right) turn|has the green|has a green light|is doing|"
    rf"(?:is|was) (?:riding|driving|approaching|travelling|traveling|going|proceeding|heading|speeding)|"
    rf"rides (?:his|her|their)|rode (?:his|her|their)|"
    rf"(?P<told>(?:states|says|reports|told us|stated|said) (?:that )?(?:she|he) (?:was|is|had)))\b")
PARTY_MARK = re.compile(r"\b(?:my|our) (?=client|insured)", re.I)  # a lawyer's "my client" tells of the client, not
# of the lawyer at the wheel


def _party_at_the_wheel(text: str, notes: list[str]) -> str:
    """'D is driving her sedan north ... P steps into the crosswalk in front of D', 'Client was riding his motorcycle
    ... a black SUV in the lane to his left': a case told of a party at the wheel, by a letter, a name or a role,
    with no narrator and no ego named, is told from that party's seat. Of several parties at the wheel the one
    the others are placed by ('from D's left', 'in front of D') is the ego, else the first. A name of no role
    that only tells ('Customer states she was driving') is left to the story's 'she'."""
    if FIRST_PERSON.search(PARTY_MARK.sub("", text)):
        return text
    drivers = []
    for m in PARTY_DRIVING.finditer(text):
        party = re.sub(rf"^{TITLE}", "", m.group(1))
        a_name = not re.fullmatch(PARTY_LETTER, party) and not re.fullmatch(PARTY_ROLES, party)
        if party in NOT_NAMES or (a_name or len(party) > 1) and known_word(party.split()[-1]) or \
                a_name and m.group("told") or party in drivers:
            continue
        drivers.append(party)
    if not drivers:
        return text

    def said(party: str) -> str:  # "Sarah Jennings", then "Mrs Jennings", "Jennings" or "Sarah"; a role in any
        # case ("Client stopped ... a pickup following client")
        if re.fullmatch(PARTY_ROLES, party):
            return rf"(?i:(?:the\s+|my\s+|our\s+)?{re.escape(party.split()[-1])})"
        return rf"(?:{TITLE}?{re.escape(party)}|{TITLE}?(?:{'|'.join(map(re.escape, party.split()))}))" \
            if " " in party else re.escape(party)

    def placed_by(party: str) -> int:
        return len(re.findall(rf"\b{said(party)}'s\s+{POSSESSED}\b|"
                              rf"\b(?:of|to|toward|towards|behind|past|beside)\s+{said(party)}\b", text))
    ego = max(drivers, key=lambda d: (placed_by(d), -drivers.index(d)))
    text = re.sub(rf"\b{said(ego)}'(?!s\b)", "the ego's", text)  # "Mrs Jennings' two children"
    text = re.sub(rf"\b{said(ego)}\b", "the ego", text)  # ("D's left": the ego's left)
    notes.append(f"read {ego} as the ego's driver")
    if re.fullmatch(PARTY_LETTER, ego) and len(ego) == 1:
        text = _lettered_parties(text, notes)
    return _drivers_pronoun(text, notes) if len(drivers) == 1 else text  # (of several, whose 'her' is unsaid)


LETTERED = re.compile(r"(?<![\w.'-])([B-HJ-Z])(?![\w.'-])('s)?")  # a party named by one capital letter ("P", "X's")
PARTY_KINDS = (  # what a lettered party is, by the words said with it first (the nearest wins; None: no one on the
    # road, "R, the sedan's owner, had left the keys in it", "X's passenger")
    (r"owner|passenger|witness\w*|employer|insurer|sues|sued", None),
    (r"on foot|walk(?:s|ing|ed)?|steps?|stepped|darts?|darted|dashe[sd]|dash|cross(?:es|ing|ed)?|stroll\w*|"
     r"pedestrian|jogg\w*|age \w+|(?:\w+-)?years?-old|child|boy|girl", "pedestrian"),
    (r"motorcycle|motorbike|moped|scooter|vespa|harley", "motorcyclist"),
    (r"bicycle|bike|cycling|cyclist", "cyclist"),
    (r"cruiser|squad car|patrol car|police car|officer|deputy|trooper", "police car"),
    (r"ambulance", "ambulance"), (r"fire (?:engine|truck)", "fire engine"),
    (r"bus", "bus"), (r"semi|eighteen-wheeler|18-wheeler|truck|lorry|rig|tractor-trailer", "truck"),
    (r"car|sedan|coupe|hatchback|suv|pickup|van|jeep|vehicle|driving|drives|driver", "car"),
)
NAMED_KIND = re.compile(r"\b(?:[Pp]edestrian|[Oo]fficer|[Dd]eputy|[Tt]rooper|[Dd]river|[Mm]otorist|[Cc]yclist|"
                        r"[Mm]otorcyclist|[Rr]ider|[Pp]assenger|[Ww]itness|[Pp]laintiff|[Dd]efendant),?\s+$")


def _lettered_parties(text: str, notes: list[str]) -> str:
    """'P, on foot, steps into the crosswalk ahead of D', 'T's eighteen-wheeler is coming from D's left', 'W is
    walking on the sidewalk to V's right': a case that names its parties by letters names each other party by
    what the words said with it first make it (on foot, on a motorcycle, in a sedan); its vehicle said as the
    party's ('T's eighteen-wheeler', 'E's vehicle') is the party itself. A party said only to witness or to sue
    is no one on the road."""
    firsts: dict[str, re.Match] = {}
    for m in LETTERED.finditer(text):
        firsts.setdefault(m.group(1), m)
    for letter, first in sorted(firsts.items(), key=lambda x: -x[1].start()):
        if NAMED_KIND.search(text[max(0, first.start() - 14):first.start()]) or \
                re.search(r"\b(?:driven|ridden|operated)\s+by\s+$", text[max(0, first.start() - 14):first.start()]):
            continue  # "Pedestrian P", "Officer P", "a tractor-trailer driven by T": named with its kind
        end = re.search(r"[.;!?]", text[first.end():])
        said = text[first.end():first.end() + (end.start() if end else len(text))]
        if first.group(2):
            said = " ".join(said.split()[:3])  # "T's eighteen-wheeler": what it owns, right after it (not "D's
            # left, O's cruiser close behind")
        hits = [(m.start(), kind) for pattern, kind in PARTY_KINDS for m in re.finditer(rf"\b(?:{pattern})\b", said,
                                                                                       re.I)]
        if not hits:
            continue
        at, kind = min(hits, key=lambda h: (h[1] is not None or h[0] > 30, h[0]))  # ("R, the sedan's owner,")
        if kind is None or re.search(rf"\b[B-HJ-Z]\s+and\s+$", text[max(0, first.start() - 6):first.start()]) or \
                re.match(r"\s+and\s+[B-HJ-Z]\b", text[first.end():]):
            continue  # ("P and Q, two friends, walk across": named together by what follows)
        if re.search(r"\b(?:an?|his|her|their)\s+(?:[\w-]+\s+){0,2}$", said[:at]) and kind != "pedestrian":
            continue  # "P is riding a motorcycle toward D", "D, in his pickup": the vehicle is named, the party at it
        owned = re.compile(rf"(?<![\w.'-]){letter}'s\s+(?:[\w-]+\s+){{0,2}}?(?:car|sedan|coupe|hatchback|suv|pickup|"
                           rf"van|vehicle|truck|semi|rig|eighteen-wheeler|cruiser|squad car|motorcycle|motorbike|"
                           rf"moped|bike|bicycle|bus)\b")
        if kind not in ("pedestrian", "cyclist", "motorcyclist"):
            text = owned.sub(letter, text)  # "E's vehicle", "O's squad car": the party, at its wheel
            text = text[:first.end()] + re.sub(r"^((?:\s+\w+){1,3}?)\s+(?:his|her|their)\s+(?:car|sedan|van|truck|"
                                               r"pickup|vehicle)\b", r"\1", text[first.end():])  # "X has stopped his car"
        m = next(LETTERED.finditer(text, first.start() - 1 if first.start() else 0), None)
        if m is None or m.group(1) != letter:
            continue
        text = text[:m.start()] + f"{'an' if kind[0] in 'aeiou' else 'a'} {kind} {letter}" + text[m.start() + 1:]
        notes.append(f"read {letter} as a {kind}")
    return text


def _storys_driver(text: str, notes: list[str]) -> str:
    """'she came round a bend onto three cyclists. She crept along behind them': a story told of an unnamed
    driver, with no narrator and no ego named, is told from that driver's seat: its 'she' (or 'he') is the ego."""
    if FIRST_PERSON.search(text):
        return text
    m = STORY_DRIVER.search(text)
    if m is None or re.search(rf"\b(?:{OTHER_PEOPLE[m.group(1).lower()]})s?\b", text[:m.start()], re.I):
        return text  # "a woman stepped out and she stopped": the woman
    text = text[:m.start()] + "the ego" + text[m.start() + len(m.group(1)):]
    driver = re.search(r"\b(?:[Aa]|[Tt]he|[Oo]ne)\s+driver\b(?!\s+of\b|')", text[:m.start()])
    if driver is not None:  # "a driver is waiting to turn right ... he turns": that driver
        text = text[:driver.start()] + "the ego" + text[driver.end():]
    return _drivers_pronoun(text, notes)


def _drivers_pronoun(text: str, notes: list[str]) -> str:
    """The ego's driver's pronoun: the first 'he' or 'she' (him, his, her) after the driver is named, unless a man
    (a woman) was named before it; from there each 'he/him/his' (or 'she/her') is the ego."""
    first = text.find("the ego")
    if first < 0:
        return text
    m = re.search(r"\b(he|she|him|his|her)\b", text[first:], re.I)
    if m is None:
        return text
    pronoun = "she" if m.group(1).lower() in ("she", "her") else "he"
    if re.search(rf"\b(?:{OTHER_PEOPLE[pronoun]})s?\b", text[:first + m.start()], re.I):
        return text  # "a man crossed in front of the taxi and he stopped": the man
    start = first + m.start()
    head, tail = text[:start], text[start:]
    if pronoun == "he":  # the possessive as "our": "on our left" is a side, "the ego's left" reads as a turn
        tail = re.sub(r"\bhis\b", "our", tail, flags=re.I)
        tail = re.sub(r"\b(?:he|him|himself)\b", "the ego", tail, flags=re.I)
    else:
        tail = re.sub(rf"\bher\b(?=\s+{POSSESSED}\b)", "our", tail, flags=re.I)
        tail = re.sub(rf"\bher\b(?=\s+(?!(?:{AFTER_AN_OBJECT})\b)[a-z])", "our", tail, flags=re.I)  # "her sullen
        # teenage son": hers, as "his" is; "level with her and", "ahead of her": her
        tail = re.sub(r"\b(?:she|her|herself)\b", "the ego", tail, flags=re.I)
    notes.append(f"read '{pronoun}' as the ego's driver")
    return head + tail
