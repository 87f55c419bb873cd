"""Meaning-preserving rewrites of a prompt, the kind a real writer makes: the gold stays the gold.

Each rewrite changes only wordings it can change safely (a noun after an article, a verb after its subject, a
whole sentence's opening) and leaves a prompt it has nothing safe to change as it is; bench/lowering_eval.py
counts, per rewrite, the dev prompts that read worse rewritten than as written.
"""

from __future__ import annotations

import re

_NUMBERS = ("zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")
# Nouns a vehicle or person noun in front of only describes: 'a car park', 'a pedestrian crossing'.
_COMPOUND_HEADS = (r"park|parks|length|lengths|width|door|doors|wash|seat|window|horn|alarm|crossing|crossings"
                   r"|light|lights|signal|signals|island|zone|refuge|bridge|dummy|dummies|target|targets|path|area"
                   r"|button|phase|walkway|subway|underpass|barrier|lane|lanes|route|stop|stops|driver|drivers"
                   r"|rank|ahead|mirror|stand|rack|carrier|shelter|bay|box|traffic|flow|volume|accident|crash"
                   r"|collision|fatalities|safety|speed|movement|movements|detection|facilities|facility|phase")
_ARTICLE = r"\b(a|an|the|another|one|A|An|The|Another|One)"


def _article(article: str, noun: str) -> str:
    """The indefinite article the new noun takes ('a car' -> 'an HGV'); others unchanged."""
    if article.lower() not in ("a", "an"):
        return article
    vowel = re.match(r"[aeiou]|hgv|suv|mpv", noun, re.I) is not None
    word = "an" if vowel else "a"
    return word.capitalize() if article[0].isupper() else word


def swap_noun(old: str, new: str, plural_old: str | None = None, plural_new: str | None = None):
    """'a car' -> 'a sedan' (and 'the car', 'two cars' -> 'two sedans'), never a compound ('car park')."""
    tail = rf"(?![\w-])(?!'s? (?:{_COMPOUND_HEADS})\b)(?! (?:{_COMPOUND_HEADS})\b)"

    def rewrite(text: str) -> str:
        text = re.sub(rf"{_ARTICLE} {old}{tail}", lambda m: f"{_article(m.group(1), new)} {new}", text)
        if plural_old:
            counts = "|".join(_NUMBERS[2:]) + r"|\d+|two or three|several|some|both|the|other|more"
            text = re.sub(rf"\b({counts}) {plural_old}{tail}", rf"\1 {plural_new}", text, flags=re.I)
        return text
    return rewrite


_EGO_BODY = r"(?: (?:vehicle|car))?(?! (?:truck|lorry|bus|van|motorcycle|motorbike|coach|taxi|lkw|LKW|pkw|PKW))\b"


def ego_named(name: str):
    """'the ego' (or 'the ego vehicle', 'the ego car') named otherwise; an ego of another body keeps its name, and
    so does the role a vehicle is declared or set beside ('our van is the ego': 'our van is our vehicle' declares
    nothing)."""
    def rewrite(text: str) -> str:
        def named(m: re.Match) -> str:
            if re.match(r"(?:my|our)\b", name, re.I) and (
                    re.search(r"(?:\b(?:is|as|be|being)|=|[(,\u2014-])\s*$", text[:m.start()]) or
                    re.match(r"\s*(?:,\s+[A-Z]+'s|lane\b)", text[m.end():])):
                return m.group(0)  # a declaration or an apposition ("her SUV (the ego)", "the ego, PRIYA's hatch"),
                # or a compound ("the ego lane"): an owner's name says no such thing
            if m.group(1) == "T" and not name[0].isupper():
                return name[0].upper() + name[1:]
            return name
        return re.sub(rf"\b([Tt])he ego{_EGO_BODY}", named, text)
    return rewrite


def ego_vehicle(text: str) -> str:
    return re.sub(r"\b([Tt])he ego\b(?![ -]\w)", r"\1he ego vehicle", text)


def words_to_digits(text: str) -> str:
    """'two cars' -> '2 cars'; never 'one' (the one, no one), never inside a hyphened word of its own."""
    def digit(m: re.Match) -> str:
        return str(_NUMBERS.index(m.group(1).lower()))
    return re.sub(r"\b(two|three|four|five|six|seven|eight|nine|ten)\b(?= [a-z])", digit, text, flags=re.I)


def digits_to_words(text: str) -> str:
    """'3 lanes' -> 'three lanes'; never a measure ('30 km/h'), an ordinal, a time, a code or a section number."""
    units = (r"km|kph|kmh|mph|m|ft|feet|s|sec|secs|second|seconds|min|mins|minute|minutes|h|hr|hrs|hour|hours"
             r"|am|pm|a\.m|p\.m|metres|meters|metre|meter|percent|yards|miles|mile|kilometres|kilometers|st|nd|rd"
             r"|th|o'clock|%")
    return re.sub(rf"(?<![\w.#/:-])(?<!Route )(?<!route )(?<!Exit )(?<!exit )(?<!No\. )(?<!number )([1-9])(?![\w.,:/%-])(?!\s*(?:{units})\b)(?!\s*[-/:%])",
                  lambda m: _NUMBERS[int(m.group(1))], text)


def _one_plain_paragraph(text: str) -> bool:
    stripped = text.strip()
    return ("\n" not in stripped and "?" not in stripped and ":" not in stripped
            and re.match(r"(A|An|The|Ego|Two|Three|One) ", stripped) is not None)


def request_prefix(text: str) -> str:
    """'A car turns left.' -> 'Please create a scenario where a car turns left.'"""
    if not _one_plain_paragraph(text):
        return text
    stripped = text.strip()
    return "Please create a scenario where " + stripped[0].lower() + stripped[1:] + "\n"


def scenario_prefix(text: str) -> str:
    if not _one_plain_paragraph(text):
        return text
    return "Scenario: " + text.strip() + "\n"


_SPELLINGS = (("signalized", "signalised"), ("unsignalized", "unsignalised"), ("signaling", "signalling"),
              ("signaled", "signalled"), ("maneuvers", "manoeuvres"), ("maneuvering", "manoeuvring"),
              ("maneuvered", "manoeuvred"), ("maneuver", "manoeuvre"), ("curb", "kerb"), ("curbs", "kerbs"),
              ("color", "colour"), ("colored", "coloured"), ("center", "centre"), ("meters", "metres"),
              ("meter", "metre"), ("neighboring", "neighbouring"), ("behavior", "behaviour"),
              ("tires", "tyres"), ("traveling", "travelling"), ("traveled", "travelled"), ("canceled", "cancelled"),
              ("gray", "grey"), ("program", "programme"), ("organized", "organised"), ("realized", "realised"),
              ("recognized", "recognised"), ("prioritized", "prioritised"), ("analyze", "analyse"),
              ("labeled", "labelled"), ("favor", "favour"),
              ("defense", "defence"), ("theater", "theatre"), ("liters", "litres"), ("aluminum", "aluminium"),
              ("pajamas", "pyjamas"), ("plow", "plough"))
_SPELLING_PAIRS = tuple((a, b) for a, b in _SPELLINGS if a != "program")  # a computer's program is no programme


def _respell(pairs):
    table = {a: b for a, b in pairs}

    def rewrite(text: str) -> str:
        def one(m: re.Match) -> str:
            word = m.group(0)
            new = table[word.lower()]
            return new.capitalize() if word[0].isupper() else new
        return re.sub(r"\b(" + "|".join(table) + r")\b", one, text, flags=re.I)
    return rewrite


def _ize_to_ise(text: str) -> str:
    return re.sub(r"\b(\w{3,})iz(e|ed|es|ing|ation)\b",
                  lambda m: m.group(1) + "is" + m.group(2) if m.group(1).lower() not in ("capsize", "pr", "se") else
                  m.group(0), text)


def british_spelling(text: str) -> str:
    return _ize_to_ise(_respell(_SPELLING_PAIRS)(text))


def american_spelling(text: str) -> str:
    text = _respell(tuple((b, a) for a, b in _SPELLING_PAIRS))(text)
    return re.sub(r"\b(\w{3,})is(e|ed|es|ing|ation)\b",
                  lambda m: m.group(1) + "iz" + m.group(2)
                  if re.search(r"(al|gn|ic|ior|or|gan|ar|ym|ath|ur|pr|ys|at|iz)$", m.group(1).lower())
                  and m.group(1).lower() not in ("pr", "wise", "prom", "compr", "surpr", "advert", "superv",
                                                 "rev", "adv", "dev", "exerc", "franch", "desp", "improv")
                  else m.group(0), text)


_CONTRACTIONS = (("is not", "isn't"), ("are not", "aren't"), ("was not", "wasn't"), ("were not", "weren't"),
                 ("does not", "doesn't"), ("do not", "don't"), ("did not", "didn't"), ("has not", "hasn't"),
                 ("have not", "haven't"), ("had not", "hadn't"), ("cannot", "can't"), ("can not", "can't"),
                 ("will not", "won't"), ("would not", "wouldn't"), ("could not", "couldn't"),
                 ("should not", "shouldn't"), ("I am", "I'm"), ("you are", "you're"), ("we are", "we're"),
                 ("they are", "they're"), ("it is", "it's"), ("there is", "there's"), ("that is", "that's"),
                 ("let us", "let's"), ("I will", "I'll"), ("we will", "we'll"), ("I have been", "I've been"),
                 ("we have been", "we've been"), ("he is", "he's"), ("she is", "she's"))


def _case_keeping(pairs):
    def rewrite(text: str) -> str:
        for old, new in pairs:
            text = re.sub(rf"\b{old}\b", new, text)
            if old[0].islower():
                text = re.sub(rf"\b{old[0].upper() + old[1:]}\b", new[0].upper() + new[1:], text)
        return text
    return rewrite


def contracted(text: str) -> str:
    return _case_keeping(_CONTRACTIONS)(text)


def expanded(text: str) -> str:
    text = text.replace("\u2019", "'")
    safe = tuple((new, old) for old, new in _CONTRACTIONS if not new.endswith("'s") and old != "can not")
    text = _case_keeping(safe)(text)
    # "'s" is 'is' only before a participle or a place; "it's been" is 'it has been' and stays
    return re.sub(r"\b(it|there|that|he|she)'s (?!been|got|gone|had)", r"\1 is ", text, flags=re.I)


# Main verbs told in the present and in the past, after a subject: 'the car turns' <-> 'the car turned'.
_TENSES = (("turns", "turned"), ("goes", "went"), ("stops", "stopped"), ("crosses", "crossed"),
           ("drives", "drove"), ("comes", "came"), ("approaches", "approached"), ("changes", "changed"),
           ("overtakes", "overtook"), ("brakes", "braked"), ("pulls", "pulled"), ("cuts", "cut"),
           ("merges", "merged"), ("walks", "walked"), ("runs", "ran"), ("waits", "waited"), ("stands", "stood"),
           ("enters", "entered"), ("passes", "passed"), ("follows", "followed"), ("travels", "travelled"),
           ("moves", "moved"), ("continues", "continued"), ("swerves", "swerved"), ("reverses", "reversed"),
           ("accelerates", "accelerated"), ("slows", "slowed"), ("yields", "yielded"), ("blocks", "blocked"),
           ("parks", "parked"), ("is", "was"), ("are", "were"), ("speeds", "sped"), ("steps", "stepped"),
           ("makes", "made"), ("takes", "took"), ("appears", "appeared"), ("emerges", "emerged"),
           ("starts", "started"), ("begins", "began"), ("tries", "tried"), ("wants", "wanted"),
           ("needs", "needed"), ("sits", "sat"), ("has", "had"), ("rides", "rode"))
_SUBJECT = (r"\b((?:[Tt]he|[Aa]n?|[Mm]y|[Oo]ur|[Aa]nother|[Tt]hat|[Tt]his) (?:(?!its |his |her |their )[\w-]+ )?[\w-]+"
            r"|[Ii]t|[Hh]e|[Ss]he"
            r"|[Ee]go|[Tt]hey|[Ww]e|I|[Yy]ou)")
# A noun that is no subject although a verb-like word follows it: 'at the bus stops', 'the left turns'.
_NOT_A_SUBJECT_BEFORE = (r"(?<!\bat )(?<!\bto )(?<!\bof )(?<!\bin )(?<!\bon )(?<!\bfor )(?<!\bby )(?<!\bwith )(?<!\bw/ )"
                         r"(?<!there's )(?<!there is )(?<!there was )(?<!there were )(?<!\bsee )(?<!\bsaw )")
# ('a scene with a fire engine parked', "there's a car parked": a participle after its noun, no verb of a subject)
_HYPOTHETICAL = re.compile(r"\b(if|unless|should|would|could|will|shall|must|may|might|can|wants?|let|suppose"
                           r"|imagine|expected|expect|when(ever)?|once|until|before|after|as soon as|every|each"
                           r"|always|usually|often|never|please|generate|create|make|simulate|test|need|needs)\b|\?",
                           re.I)


def present_to_past(text: str) -> str:
    """A present-tense telling told in the past; a prompt with conditions, modals or requests keeps its tense (a
    past tense there would read as a hypothetical or a habit)."""
    if _HYPOTHETICAL.search(text) or _tense_count(text, [past for _, past in _TENSES if past != "cut"]):
        return text
    table = dict(_TENSES)

    def verb(m: re.Match) -> str:
        return f"{m.group(1)} {table[m.group(2)]}"
    return re.sub(_NOT_A_SUBJECT_BEFORE + _SUBJECT + r" (" + "|".join(table) + r")\b", verb, text)


def _base_form(verb: str) -> str:
    """'crosses' -> 'cross', 'tries' -> 'try', 'turns' -> 'turn'."""
    if re.search(r"[^aeiou]ies$", verb):
        return verb[:-3] + "y"
    if re.search(r"(ss|ch|sh|x|o)es$", verb):
        return verb[:-2]
    return verb[:-1] if verb.endswith("s") else verb


def _tense_count(text: str, forms) -> int:
    return len(re.findall(r"\b(" + "|".join(forms) + r")\b", text))


def past_to_present(text: str) -> str:
    """A past-tense report told in the present, the verb agreeing with its subject ('I stopped' -> 'I stop')."""
    if _HYPOTHETICAL.search(text) or re.search(r"\b(had|been|yesterday|ago|last)\b", text, re.I) \
            or _tense_count(text, [present for present, _ in _TENSES]):
        return text
    table = {past: present for present, past in _TENSES if past not in ("cut",)}

    def verb(m: re.Match) -> str:
        subject, past = m.group(1), m.group(2)
        present = table[past]
        if subject.lower() in ("i", "we", "they", "you") or re.search(r"s$", subject) and " " in subject \
                and not re.search(r"(ss|us|is)$", subject):
            if present == "is":
                present = {"i": "am"}.get(subject.lower(), "are")
            elif present == "was":
                present = "were"
            else:
                present = {"has": "have", "goes": "go", "does": "do"}.get(present) or _base_form(present)
        return f"{subject} {present}"
    table.update({"was": "is", "were": "are"})
    text = re.sub(_NOT_A_SUBJECT_BEFORE + _SUBJECT + r" (" + "|".join(table) + r")\b", verb, text)
    return text


def _sequence_word(word: str, sentence_initial_only: bool = False):
    def rewrite(text: str) -> str:
        cap = word[0].upper() + word[1:]
        text = re.sub(r"(^|[.!]\s+)Then,? ", lambda m: f"{m.group(1)}{cap}, ", text, flags=re.M)
        if not sentence_initial_only:
            text = re.sub(r"(,|\band) then\b(?!,)", rf"\1 {word}", text)
        return text
    return rewrite


def oxford_comma_dropped(text: str) -> str:
    return re.sub(r", and\b", " and", text)


_CLAUSE_VERB = r"(?:turns|stops|crosses|goes|drives|waits|comes|brakes|is|was|are|were|pulls|cuts|changes|stands)"


def and_for_comma(text: str) -> str:
    """Two clauses joined by a comma joined by 'and' ('a car turns left, a bus stops' -> '... and a bus stops')."""
    def join(m: re.Match) -> str:
        sentence = re.split(r"[.!?;:\n]", text[:m.start(2)])[-1]
        subordinate = re.search(r"\b(once|when|whenever|as|after|before|if|while|until|till|since|because|though"
                                r"|although|unless|by the time)\b", sentence, re.I)
        return m.group(0) if subordinate else f"{m.group(1)} and {m.group(2)} "
    return re.sub(rf"(\b{_CLAUSE_VERB}\b[^,.;:\n]*?), (an?|the) (?=[a-z]+ {_CLAUSE_VERB}\b)", join, text)


def comma_for_and(text: str) -> str:
    """Noun phrases or clauses joined by 'and' joined by a comma ('a car and a truck' -> 'a car, a truck')."""
    def join(m: re.Match) -> str:
        before = text[max(0, m.start() - 30):m.start()]
        return m.group(0) if re.search(r"\bbetween\b[^,.]*$", before) else ", "
    return re.sub(r"(?<![,;.]) and (?=(?:an?|the|two|three) \w+)", join, text)


_ACTOR = (r"(?:car|truck|lorry|bus|van|cyclist|pedestrian|motorcycle|motorbike|motorcyclist|taxi|SUV|sedan"
          r"|ambulance|police car|fire truck|fire engine|child|kid|man|woman|jogger|person|bike|scooter|cab)")


_SUDDEN_VERB = (r"(?:pulls|pulled|cuts|cut|steps|stepped|turns|turned|brakes|braked|swerves|swerved|changes|changed"
                r"|crosses|crossed|runs|ran|comes|came|emerges|emerged|appears|appeared|darts|darted|stops|stopped"
                r"|merges|merged|overtakes|overtook|moves|moved|walks|walked|reverses|reversed|jumps|jumped)")


def suddenly(text: str) -> str:
    """'A car cuts in.' -> 'Suddenly, a car cuts in.' for the first later sentence an agent opens with a move."""
    return re.sub(rf"(?<=[.!] )(A|An|The) (?=(?:\w+ )?{_ACTOR} (?:\w+ )?{_SUDDEN_VERB}\b)",
                  lambda m: "Suddenly, " + m.group(1).lower() + " ", text, count=1)


def split_at_and_then(text: str) -> str:
    """'X, and then the ego turns' -> 'X. Then the ego turns' when a subject follows (no subjectless sentence)."""
    return re.sub(r",? and then (?=(?:the|a|an|I|we|it|he|she|they|ego|my|our|two|three)\b)",
                  ". Then ", text)


REPHRASINGS = {
    "car named a sedan": swap_noun("car", "sedan", "cars", "sedans"),
    "car named a vehicle": swap_noun("car", "vehicle"),
    "car named a hatchback": swap_noun("car", "hatchback", "cars", "hatchbacks"),
    "truck named a lorry": swap_noun("truck", "lorry", "trucks", "lorries"),
    "truck named an HGV": swap_noun("truck", "HGV", "trucks", "HGVs"),
    "lorry named a truck": swap_noun("lorry", "truck", "lorries", "trucks"),
    "pedestrian on foot": swap_noun("pedestrian", "person on foot", "pedestrians", "people on foot"),
    "cyclist a bike rider": swap_noun("cyclist", "bike rider", "cyclists", "bike riders"),
    "the ego vehicle": ego_vehicle,
    "the ego named the SUT": ego_named("the SUT"),
    "the ego named our vehicle": ego_named("our vehicle"),
    "numbers as digits": words_to_digits,
    "digits as words": digits_to_words,
    "please create a scenario": request_prefix,
    "Scenario: prefix": scenario_prefix,
    "British spelling": british_spelling,
    "American spelling": american_spelling,
    "contracted": contracted,
    "contractions expanded": expanded,
    "present told as past": present_to_past,
    "past told as present": past_to_present,
    "then as after that": _sequence_word("after that"),
    "then as afterwards": _sequence_word("afterwards"),
    "then as next": _sequence_word("next", sentence_initial_only=True),
    "Oxford comma dropped": oxford_comma_dropped,
    "commas as and": and_for_comma,
    "and as commas": comma_for_and,
    "suddenly, ...": suddenly,
    "and then split": split_at_and_then,
}
