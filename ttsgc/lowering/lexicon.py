"""The offline lowering's words, read from data files (ttsgc/lowering/lexicon/*.txt), and the tokenizer.

Why data: the words engineers use grow faster than rules, and a word added to a file is a word the parser
knows, with no code change. The reader turns text into tokens carrying their base form ("turning" ->
"turn", "lorries" -> "lorry", "signalised" -> "signalized"), and finds the longest lexicon phrase at each
place. Numbers are read through a bounded reader: a count of any length is a number or "too large", never an
overflow.
"""

from __future__ import annotations

import difflib
import re
import unicodedata
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

FOLDER = Path(__file__).resolve().parent / "lexicon"
ORDINAL_WORDS = {"1": "first", "2": "second", "3": "third", "4": "fourth", "5": "fifth", "6": "sixth"}
BASE_VARIANT_CATEGORIES = ("sequence",)  # conditions written in any tense; other phrases keep their own forms
CATEGORIES = ("agents", "actions", "positions", "road", "weather", "behaviours", "numbers", "sequence")
MAX_DIGITS = 6  # a number with more digits than this is read as "too large"
TOO_LARGE = 10 ** MAX_DIGITS


@dataclass(frozen=True)
class Token:
    word: str  # as written, lower case, British spelling made American
    base: str  # the base form the lexicon knows, else the word
    index: int  # position in the whole text
    sentence: int
    plural: bool = False  # a noun in its plural form ("cars", "children")
    possessive: bool = False  # followed by 's ("the ego's lane")
    label: str = ""  # a name the text gives an agent ("SV1", "POV2")
    question: bool = False  # in a sentence that asks ("What happens if a truck runs a red light?")
    title: bool = False  # in a title line ("Case: child after ball"): read for the road and weather only
    misspelt: str = ""  # the word as written, when it was read as the nearest known word ("pedestrain")
    opened_by: str = ""  # the mark that ended the sentence before its own (";" in "ahead of the ego; changes lane")

    @property
    def number(self) -> float | None:
        return read_number(self.word)


@dataclass(frozen=True)
class Match:
    start: int  # token indexes [start, end)
    end: int
    category: str
    meaning: str
    phrase: str


def read_number(text: str) -> float | None:
    """A decimal as written, bounded: more than MAX_DIGITS integer digits reads as TOO_LARGE."""
    if not re.fullmatch(r"\d+(?:\.\d+)?", text):
        return None
    whole = text.split(".")[0].lstrip("0")
    if len(whole) > MAX_DIGITS:
        return float(TOO_LARGE)
    return float(text[: MAX_DIGITS + 4])


def _entries(name: str):
    for line in (FOLDER / f"{name}.txt").read_text(encoding="utf-8").splitlines():
        line = line.split("#", 1)[0].strip()
        if not line or ":" not in line:
            continue
        meaning, phrases = line.rsplit(":", 1)
        for phrase in phrases.split(","):
            words = tuple(_normalize(phrase).split())
            if words:
                yield meaning.strip(), words


def _normalize(text: str) -> str:
    return re.sub(r"[-_/]", " ", fold_letters(text.lower())).strip()


LIGATURES = {"\u00df": "ss", "\u00e6": "ae", "\u0153": "oe", "\u00f8": "o", "\u0142": "l"}


def fold_letters(text: str) -> str:
    """Letters with marks read as their plain letters ("Fußgänger" is "fussganger", "coupé" is "coupe"):
    words borrowed from other languages stay whole, not pieces split at each mark."""
    if text.isascii():
        return text
    return "".join(_plain_letter(c) if c.isalpha() and not c.isascii() else c for c in text)


def _plain_letter(c: str) -> str:
    if c in LIGATURES:
        return LIGATURES[c]
    return "".join(x for x in unicodedata.normalize("NFKD", c) if not unicodedata.combining(x))


@dataclass(frozen=True, eq=False)
class Lexicon:
    phrases: dict  # words tuple -> (category, meaning)
    longest: int
    vocabulary: frozenset  # every word of every phrase, and the function words
    content_words: tuple  # the words an unknown word is compared with
    irregular: dict  # inflected -> base
    spelling: dict  # british -> american
    function_words: frozenset
    kinds: dict  # words tuple -> scene kind (read only where a scene is asked for)
    starts: dict  # first word -> the length of the longest phrase it starts

    def base(self, word: str) -> tuple[str, bool]:
        """The base form of a word the lexicon knows, and whether it was a plural or an inflected form."""
        if word in self.irregular:
            return self.irregular[word], True
        if word in self.function_words:
            return word, False
        for suffix, replacement in (("ies", "y"), ("ied", "y"), ("es", ""), ("s", ""), ("ed", ""), ("ed", "e"),
                                    ("d", ""), ("ing", ""), ("ing", "e"), ("'s", "")):
            if word.endswith(suffix) and len(word) > len(suffix) + 1 and (suffix != "d" or word.endswith("ed")):
                # ("Ford" is no past tense of "for")
                stem = word[: -len(suffix)] + replacement
                if stem in self.vocabulary and (len(stem) > 2 or stem not in self.function_words):  # "red" != "re"+d
                    return stem, True
                if suffix in ("ed", "ing") and len(stem) > 2 and stem[-1] == stem[-2]:  # stopped, running
                    if stem[:-1] in self.vocabulary:
                        return stem[:-1], True
        return word, False  # a base form itself, or a word the lexicon does not know

    def nearest(self, word: str) -> str | None:
        return _nearest(self, word)


@lru_cache(maxsize=4096)
def _nearest(lex: "Lexicon", word: str) -> str | None:
    """The closest known content word; only words of about the same length can be close enough."""
    pool = [w for w in lex.content_words if abs(len(w) - len(word)) <= 2 and (w[0] == word[0] or w[1:2] == word[1:2])]
    found = difflib.get_close_matches(word, pool, n=1, cutoff=0.75)
    return found[0] if found else None


@lru_cache(maxsize=4096)
def _corrected(lex: "Lexicon", word: str) -> str | None:
    """A typing slip read as the one known word it was meant to be ("pedestrain", "turnign", "lfet", "adn"), never
    a word of English read as another ("tuning" stays, "form" is no "from"): a slip is one letter dropped, added,
    doubled, changed, or two neighbours swapped (a long word may have two); short words only swap or miss one."""
    if len(word) < 3 or not word.isalpha() or _english(word):
        return None
    forms = _known_forms(lex)
    for kind in _slips(word):  # the likeliest slip first: a swap, a letter missed, one too many, one changed
        found = {forms[w] for w in kind if w in forms and not word.startswith(w) and (len(word) > 4 or _english(w))}
        # a letter more at the end makes another word ("speedo"), not a slip; one less is a slip ("brak"); a short
        # word is read only as a word, never as an abbreviation ("hrs" is no "rhs")
        if len(found) == 1:
            return found.pop()
        if found:
            return None
    if len(word) < 8:
        return None  # two slips only in a long word
    pool = [w for w in forms if abs(len(w) - len(word)) <= 2 and w[0] == word[0]]
    close = [w for w in difflib.get_close_matches(word, pool, n=2, cutoff=0.86)
             if not (w.startswith(word) or word.startswith(w))]  # "commute" is no misspelt "commuter"
    if len(close) == 1 or (len(close) == 2 and difflib.SequenceMatcher(None, word, close[0]).ratio() >
                           difflib.SequenceMatcher(None, word, close[1]).ratio()):
        return forms[close[0]]
    return None


@lru_cache(maxsize=4096)
def _run_together(lex: "Lexicon", word: str) -> str | None:
    """Two words typed without the space between them ("stopsign", "turnsleft", "straightahead"), read apart when
    they begin a phrase of the lexicon other than an agent's name; a word of English stays whole."""
    if len(word) < 5 or not word.isalpha() or _english(word) or \
            word.endswith("in") and word + "g" in _known_forms(lex):
        return None  # ("pushin", "crossin": a g dropped, one word)
    for k in range(2, len(word) - 1):
        first, second = word[:k], word[k:]
        if any((a, b) in _phrase_openings(lex) for a in {first, lex.base(first)[0]}
               for b in {second, lex.base(second)[0]}):
            return f"{first} {second}"
    return None


@lru_cache(maxsize=1)
def _phrase_openings(lex: "Lexicon") -> frozenset:
    """How phrases open, save agents' names: "targetvehicle", "leadvehicle" are a specification's identifiers,
    whole names, not two words run together."""
    return frozenset(phrase[:2] for phrase, entry in lex.phrases.items() if len(phrase) > 1 and entry[0] != "agents")


def _slips(word: str) -> tuple[set[str], ...]:
    """The words a slip of one key could have been made from, by kind: a 3-letter word only by a swap, a 4-letter
    one by a swap or a letter missed; the first letter is taken as typed, save in a swap."""
    letters = "abcdefghijklmnopqrstuvwxyz"
    swapped = {word[:i] + word[i + 1] + word[i] + word[i + 2:] for i in range(len(word) - 1)}
    if len(word) < 4:
        return (swapped,)
    missed = {word[:i] + c + word[i:] for i in range(1, len(word) + 1) for c in letters}
    if len(word) < 5:
        return swapped, missed
    extra = {word[:i] + word[i + 1:] for i in range(1, len(word))}
    changed = {word[:i] + c + word[i + 1:] for i in range(1, len(word)) for c in letters}
    return swapped, missed, extra, changed


@lru_cache(maxsize=1)
def _known_forms(lex: "Lexicon") -> dict[str, str]:
    """Every form a known word is written in ("turn", "turns", "turned", "turning"), the form as its own key."""
    forms: dict[str, str] = {}
    for word in sorted(lex.vocabulary):
        if len(word) < 3 or not word.isalpha():
            continue
        forms[word] = word
        if word in lex.function_words or lex.base(word)[1] or word.endswith(("ing", "ed")) or \
                word.endswith("s") and not word.endswith("ss"):
            continue  # no suffix on a word that has one ("stops", "strobes" give no "stopsed", "strobesing")
        for suffix in ("ed", "ing", "s"):  # "stop": "stopped", "stopping", "stops"; "come": "coming"
            form = inflected(word, suffix)
            forms.setdefault(form, form)
    for form in lex.irregular:
        forms.setdefault(form, form)
    return forms


def inflected(word: str, suffix: str) -> str:
    """A word with a regular ending: 'ed', 'ing' or 's' ("stop" -> "stopped", "come" -> "coming", "pass" ->
    "passes")."""
    if suffix == "s":
        return word + ("es" if word.endswith(("s", "sh", "ch", "x")) else "s")
    if word.endswith("e"):
        return word + "d" if suffix == "ed" else word[:-1] + suffix
    if re.fullmatch(r"[a-z]?[^aeiouy][aeiou][bdgklmnprt]", word):
        return word + word[-1] + suffix  # one syllable ending vowel-consonant doubles it
    return word + suffix


NOT_A_PARTS_NAME = r"(?![\s-]+(?:wheels?|tyres?|tires?|bumpers?|doors?|wings?|end|brakes?|lights?|seats?|windows?|" \
                   r"windscreen|windshield|fork|forks|mudguard|panniers?|basket|garden|yard|porch|gate)\b)"
# ("my front wheel", "my behind seat": a part named, not the place a calque says)


@lru_cache(maxsize=1)
def _calques() -> tuple[tuple[re.Pattern, str, dict], ...]:
    """Phrases a speaker of another language writes word for word ("doubles the car", "in the opposite sense"),
    with the English meant, from calques.txt: the first word in any form, a regular ending carried over."""
    found = []
    written = list(_entries("calques")) + _slipped_phrases()
    for meant, words in list(written):  # terse writing drops articles: "goes back on right lane"
        if "the" in words[1:] and len(words) > 2:
            written.append((meant, tuple(w for w in words if w != "the")))
    for meant, words in dict.fromkeys(written):
        forms = {inflected(words[0], suffix): suffix for suffix in ("s", "ed", "ing")} | {words[0]: ""} | {
            form: "" for form, base in lexicon().irregular.items() if base == words[0]}  # "goes", "went": the base
        pattern = re.compile(r"\b(?P<first>" + "|".join(re.escape(f) for f in sorted(forms, key=len, reverse=True))
                             + ")" + "".join(r"[\s/-]+" + re.escape(w) for w in words[1:]) + r"\b" + NOT_A_PARTS_NAME)
        found.append((-len(words), pattern.pattern, pattern, meant, forms))
    return tuple((pattern, meant, forms) for *_, pattern, meant, forms in sorted(found, key=lambda x: x[:2]))
    # the longest phrase first


def _slipped_phrases() -> list[tuple[str, tuple[str, ...]]]:
    """Slips that spell another word, read as meant only among the words they are slipped in ("comes form the
    left"): spelling.txt's lines whose written side has several words."""
    found = []
    for line in (FOLDER / "spelling.txt").read_text(encoding="utf-8").splitlines():
        line = line.split("#", 1)[0].strip()
        written, _, meant = line.partition(":")
        if " " in written.strip() and meant.strip():
            found.append((meant.strip(), tuple(_normalize(written).split())))
    return found


def _without_calques(text: str) -> str:
    for pattern, meant, forms in _calques():
        head, _, tail = meant.partition(" ")
        text = pattern.sub(lambda m: " ".join(filter(None, (
            inflected(head, forms[m.group("first")]) if forms[m.group("first")] else head, tail))), text)
    return text


HINDI_MARKERS = {"hai", "tha", "thi", "se", "pe", "mein", "ek", "aur", "wala", "wali", "raha", "rahi", "gaya", "gayi",
                 "ko", "bhi", "maine", "mere", "meri", "peeche", "aage", "saamne", "nahi", "ruk", "kiya", "karke",
                 "liya", "wahan", "phir", "baarish", "raat", "gaadi", "hua", "diya"}
PLACES_AFTER = {"peeche": "behind", "aage": "ahead of", "saamne": "in front of", "bagal mein": "beside",
                "paas": "near", "left side mein": "on the left of", "right side mein": "on the right of",
                "left side pe": "on the left of", "right side pe": "on the right of"}
PLACED_ONES = {"peeche": "behind", "aage": "ahead", "saamne": "oncoming"}
HINDI_AFTER = {"mein": "in", "pe": "at", "se": "from"}  # a postposition said before its noun
HINDI_VERBS_MEANT = ("stopped", "stood", "came", "went past", "went", "drove", "turned left", "turned right",
                     "changed lane", "cut in", "overtook", "crossed", "braked", "waited", "parked")
HELD_BY_PHRASES = {"lane", "side", "left", "right", "beech", "bagal", "gali", "road", "ke", "ki", "ka", "wali", "wala",
                   "wale", "taraf", "usme", "isme", "jaldi", "tezi", "ekdum", "peeche", "aage", "saamne", "samne"}


@lru_cache(maxsize=1)
def _hindi_words() -> tuple[re.Pattern, dict[str, str]]:
    """hinglish.txt as one pattern, its longest phrases first, and what each means."""
    meant = {" ".join(words): meaning.lower() for meaning, words in _entries("hinglish")}
    pattern = re.compile(r"\b(?:" + "|".join(re.escape(w).replace(r"\ ", r"[\s-]+")
                                             for w in sorted(meant, key=len, reverse=True)) + r")\b")
    return pattern, meant


def _hinglish(text: str) -> str:
    """Hindi in Latin letters among English words ('ek truck right wali lane mein mere aage chal raha tha'): read
    as the English meant, in one pass, with a place said after its noun put before it ('bus ke peeche': behind
    the bus; 'peeche wala truck': the truck behind). Only in a text with enough Hindi words to be Hinglish."""
    if len(HINDI_MARKERS & set(re.findall(r"[a-z]+", text))) < 3:
        return text
    text = re.sub(r"\b(\w+) (?:ke|ki|ka) (just |theek |bilkul )?(peeche|aage|saamne|bagal mein|paas|"
                  r"(?:left|right) side (?:mein|pe))\b",
                  lambda m: f"{PLACES_AFTER[m.group(3)]} the {m.group(1)}", text)
    text = re.sub(r"\b(?:(mere|hamare) )?(peeche|aage|saamne) wal[aei] (\w+)",
                  lambda m: f"the {m.group(3)} {PLACED_ONES[m.group(2)]}" + (
                      f" of {'me' if m.group(1) == 'mere' else 'us'}" if m.group(1) and m.group(2) != "saamne"
                      else ""), text)
    text = re.sub(r"\b(peeche|saamne|samne) se ((?:[a-z0-9-]+ ){1,8}?)(aa raha|aa rahi|aa rahe|aa gaya|aa gayi|aa gaye|"
                  r"aaya|aayi|aaye|aata|aati)\b", lambda m: f"{m.group(2)}{m.group(3)} {m.group(1)} se", text)
    # "peeche se ek truck aaya": a truck came from behind (not "from behind a truck")
    text = re.sub(r"\b(?:main )?(?:[a-z]+ )?(bus|truck|taxi|auto|car|gaadi|tempo) chala(?:ta|ti) (?:hoon|hu|hun)\b",
                  r"i drive a \1", text)  # "main DTC bus chalata hoon": the teller's own vehicle
    pattern, meant = _hindi_words()
    text = re.sub(r"\b([a-z][a-z-]*) (mein|pe|se)\b", lambda m: m.group(0) if m.group(1) in HELD_BY_PHRASES or
                  m.group(0) in meant else f"{HINDI_AFTER[m.group(2)]} {m.group(1)}", text)
    # ("andheri mein": in andheri)
    text = pattern.sub(lambda m: meant[" ".join(re.split(r"[\s-]+", m.group(0)))], text)
    text = re.sub(r"\b((?:at|on|in|from) the [a-z]+(?: [a-z]+)?) (" + "|".join(HINDI_VERBS_MEANT) + r")\b",
                  r"\2 \1", text)  # "signal pe ruk gaya": stopped at the signal, the verb before its place
    return re.sub(r"  +", " ", text)


RESPECTIVE_NOUNS = {"lanes": "lane", "sides": "side", "roads": "road", "side roads": "side road",
                    "directions": "direction", "arms": "arm", "exits": "exit"}
LIST_ARTICLES = {"a", "an", "the", "one", "another"}
WORD_OR_COMMA = re.compile(r"[a-z0-9][a-z0-9'-]*|,")


def _respectively(text: str) -> str:
    """'A car and a bus turn left and right respectively' -> 'a car turn left, and a bus turn right': each of a
    list of road users paired with its item of a list said as long, one sentence per pair joined by 'and'."""
    if "respectively" not in text:
        return text
    return re.sub(r"[^.;!?\n]*\brespectively\b[^.;!?\n]*", lambda m: _paired(m.group(0)) or m.group(0), text)


def _paired(sentence: str) -> str | None:
    """One sentence with 'respectively' said as its pairs, or None where its lists are not found."""
    words = [(m.group(), m.start(), m.end()) for m in WORD_OR_COMMA.finditer(sentence)]
    said = [w for w, _, _ in words]
    at = said.index("respectively")
    found = _items_before(said, at) or _items_after(said, at)
    if found is None:
        return None
    items, first, last, noun = found
    after = first > at  # "a car and a bus, respectively ahead and behind, brake"
    subjects = _subjects_before(said, at if after else first, len(items))
    if subjects is None:
        return None
    (start, end), members = subjects
    mid = sentence[words[end][2]:words[at if after else first][1]]
    tail = sentence[words[last][2] if after else words[at][2]:]
    shared = ""
    if not mid.lstrip().startswith(","):  # "turn left and right respectively, then stop": the rest said once
        comma = tail.find(",")
        if comma >= 0:
            tail, shared = tail[:comma], tail[comma:]
    said_items = [" ".join(said[i] for i in item) + (" " + noun if noun else "") for item in items]
    pairs = [re.sub(r"\s+", " ", f"{member}{mid}{' ' if after else ''}{item}{tail}").rstrip()
             for member, item in zip(members, said_items)]
    return sentence[:words[start][1]] + ", and ".join(pairs) + shared


def _items_before(said: list[str], at: int):
    """'left and right respectively', 'in the left and right lanes respectively', 'turn left and go straight
    respectively': the items end where 'respectively' begins, each as many words long."""
    j, noun = at - 1, ""
    if j >= 1 and " ".join(said[j - 1:j + 1]) in RESPECTIVE_NOUNS:
        noun, j = RESPECTIVE_NOUNS[" ".join(said[j - 1:j + 1])], j - 2
    elif j >= 0 and said[j] in RESPECTIVE_NOUNS:
        noun, j = RESPECTIVE_NOUNS[said[j]], j - 1
    for n in (1, 2, 3):
        items = _parallel(said, j, n)
        if items:
            return items, items[0][0], j, noun
    return None


def _parallel(said: list[str], j: int, n: int) -> list[list[int]] | None:
    """Items of n words each, the list ending at j: 'x and y', 'x, y and z', 'x, y, and z'."""
    last = list(range(j - n + 1, j + 1))
    k = j - n
    if k < n or said[k] != "and" or any(said[i] in ("and", ",") for i in last):
        return None
    k -= said[k - 1] == ","
    items = [last]
    while True:
        item = list(range(k - n, k))
        if item[0] < 0 or any(said[i] in ("and", ",", "respectively") for i in item):
            return None
        items.insert(0, item)
        if item[0] >= 1 and said[item[0] - 1] == "," and len(items) < 4:
            k = item[0] - 1
            continue
        return items


def _items_after(said: list[str], at: int):
    """'..., respectively ahead and behind, ...': the items right after it, up to a comma or the end."""
    for n in (1, 2):
        end = at + 2 * n + 2
        if end <= len(said) and said[at + n + 1] == "and" and (end == len(said) or said[end] == ",") and \
                not any(w in ("and", ",") for w in said[at + 1:at + n + 1] + said[at + n + 2:end]):
            return [list(range(at + 1, at + n + 1)), list(range(at + n + 2, end))], at + 1, end - 1, ""
    return None


def _subjects_before(said: list[str], before: int, count: int):
    """The list of road users the items pair with, its first and last word and its members: 'a car and a bus',
    'the van, the truck and the bus', or a count said with its noun ('two cars'), each then one of them; the
    nearest such list before the items ('two cars behind the ego ...': the cars)."""
    for k in range(before - 1, -1, -1):
        found = _listed_at(said, k, count)
        if found is not None:
            return found
    return None


def _listed_at(said: list[str], k: int, count: int):
    """The list of `count` road users whose last noun is said[k], or None."""
    lex = lexicon()

    def agent(word: str) -> bool:
        return lex.phrases.get((lex.base(word)[0],), ("",))[0] == "agents"

    if not agent(said[k]):
        return None
    base, plural = lex.base(said[k])
    if plural:  # "two cars ... left and right respectively"
        counted = k >= 1 and (said[k - 1] == str(count) or lex.phrases.get((said[k - 1],)) == ("numbers", str(count)))
        return ((k - 1, k), [f"a {base}"] * count) if counted else None
    members, i, start = [], k, k
    while True:
        first = next((j for j in range(i, max(-1, i - 4), -1) if said[j] in LIST_ARTICLES), None)
        if first is None:
            return None
        members.insert(0, " ".join(said[first:i + 1]))
        start = first
        link = first - 1
        if link < 1 or said[link] not in ("and", ","):
            break
        i = link - 1 - (said[link] == "and" and said[link - 1] == ",")
        if i < 0 or not agent(said[i]) or lex.base(said[i])[1]:
            break
    return ((start, k), members) if len(members) == count else None


@lru_cache(maxsize=8192)
def _english(word: str) -> bool:
    """A word an English dictionary has: written as meant, whatever the lexicon knows of it."""
    return word in _dictionary()


@lru_cache(maxsize=1)
def _dictionary():
    from spellchecker import SpellChecker  # a word-frequency list of English, read once and only for unknown words
    return SpellChecker(language="en", distance=1)


@lru_cache(maxsize=1)
def lexicon() -> Lexicon:
    phrases: dict = {}
    for category in CATEGORIES:
        for meaning, words in _entries(category):
            phrases.setdefault(words, (category, meaning))  # the first file that names a phrase owns it
    for words, entry in list(phrases.items()):  # terse writing drops articles: "change to left lane"
        if "the" in words[1:] and len(words) > 2:
            phrases.setdefault(tuple(w for w in words if w != "the"), entry)
    for words, entry in list(phrases.items()):  # "the lane to our right" is "the lane to the ego's right"
        if entry[0] == "positions" and "our" in words[1:]:
            k = words.index("our")
            phrases.setdefault(words[:k] + ("the", "ego's") + words[k + 1:], entry)
    irregular, spelling = {}, {}
    for base, words in _entries("inflections"):
        for word in " ".join(words).split():
            irregular[word] = base
    for line in (FOLDER / "spelling.txt").read_text(encoding="utf-8").splitlines():
        line = line.split("#", 1)[0].strip()
        if ":" in line and " " not in line.split(":", 1)[0].strip():  # a phrase is read among its words
            british, american = (x.strip() for x in line.split(":", 1))
            spelling[british] = american
    function = frozenset((FOLDER / "function.txt").read_text(encoding="utf-8").split("\n", 1)[1].split())
    words = {w for phrase in phrases for w in phrase}
    content = tuple(sorted(w for w in words if len(w) > 3 and w not in function))
    kinds = {words: meaning for meaning, words in _entries("kinds")}
    starts: dict = {}
    lex = Lexicon(phrases, 0, frozenset(words | function | set(irregular.values())), content, irregular, spelling,
                  function, kinds, starts)
    for phrase, entry in list(phrases.items()):  # "when the light goes green" also read as "when it went green"
        if len(phrase) > 1 and entry[0] in BASE_VARIANT_CATEGORIES:
            based = tuple(lex.base(w)[0] for w in phrase)
            if based != phrase:
                phrases.setdefault(based, entry)
    for phrase in phrases:
        starts[phrase[0]] = max(starts.get(phrase[0], 0), len(phrase))
    return Lexicon(phrases, max(len(p) for p in phrases), lex.vocabulary, content, irregular, spelling, function,
                   kinds, starts)


def _grouped(name: str) -> dict[tuple[str, ...], frozenset[str]]:
    found: dict = {}
    for meaning, words in _entries(name):
        found.setdefault(words, set()).add(meaning)
    return {words: frozenset(meanings) for words, meanings in found.items()}


@lru_cache(maxsize=1)
def crews() -> dict[tuple[str, ...], frozenset[str]]:
    """crews.txt: a person phrase -> the vehicle types whose own people it names ('the officers' of a police
    car, 'the biker' of a motorbike)."""
    return _grouped("crews")


@lru_cache(maxsize=1)
def compound_heads() -> frozenset[str]:
    """compounds.txt: nouns a vehicle noun in front of only describes ('the taxi rank', 'a police pursuit')."""
    return frozenset(" ".join(words) for _, words in _entries("compounds"))


@lru_cache(maxsize=1)
def _later_words() -> str:
    """sequence.txt's words for 'later' said as an adverb ('then', 'after that', 'afterwards'), as a pattern; no
    numbered stage, no signal turning green."""
    named = {" ".join(words) for meaning, words in _entries("sequence") if meaning == "then" and len(words) <= 2
             and not set(words) & {"stage", "phase", "step", "act", "light", "lights", "signal", "and", "in"}
             and not any(w.isdigit() for w in words)}
    return "|".join(r"\s+".join(name.split()) for name in sorted(named, key=len, reverse=True))


@lru_cache(maxsize=1)
def bodies() -> dict[str, str]:
    """bodies.txt: a noun that names only a vehicle's body -> its type ('sedan': car, 'lorry': truck)."""
    return {" ".join(words): kind for kind, words in _entries("bodies")}


@lru_cache(maxsize=1)
def categories() -> dict[str, frozenset[str]]:
    """categories.txt: a noun naming a kind of agent -> the agent types it covers ('emergency vehicle': police...)."""
    found: dict = {}
    for category, words in _entries("categories"):
        found.setdefault(category, set()).update(words)
    return {category: frozenset(types) for category, types in found.items()}


@lru_cache(maxsize=1)
def typologies() -> dict[tuple[str, ...], frozenset[str]]:
    """typologies.txt: a crash-typology name ('LTAP/OD', 'lead vehicle stopped') -> the features it gives the one
    other vehicle a text leaves unplaced."""
    return {words: frozenset(meaning.split("+")) for meaning, words in _entries("typologies")}


@lru_cache(maxsize=1)
def loose_names() -> dict[str, frozenset[str]]:
    """loose_names.txt: a noun of one type -> the first names of agents of another type it names again ('a
    pickup ... the truck', 'a motorbike ... the bike')."""
    found: dict = {}
    for noun, first_name in _entries("loose_names"):
        found.setdefault(noun, set()).add(" ".join(first_name))
    return {noun: frozenset(names) for noun, names in found.items()}


TURNING_WORDS = {"turn", "turns", "turned", "turning", "swing", "swings", "swung", "swinging", "bear", "bears", "bore",
                 "bearing", "veer", "veers", "veered", "veering", "hang", "hangs", "hung", "head", "heads", "headed"}
TOKEN = re.compile(r"\d+(?:\.\d+)?|[a-z]+#[a-z0-9]+(?:'s)?|[a-z]+(?:'s)?|[,.;:!?()\u00a7]")
# (a label's possessive, "car A's lane", "V1's path", is one word)
LETTER_LABEL = re.compile(r"\b((?i:car|vehicle|actor|agent|target|truck|lorry|bus|cyclist|bike|motorcycle|van|pedestrian|walker"
                          r"|ped|pov|tv|npc|object))[ _]([A-HJ-Z])\b(?![.-]?[A-Za-z]|['\u2019](?![sS]\b)[A-Za-z])")
# (and its possessive: "car A's lane")
SENTENCE_ENDS = {".", ";", "!", "?", ":"}


KEY_NAME = r"([A-Za-z][A-Za-z0-9 '/_-]{0,30}?(?:\s*\([A-Za-z0-9 ,/_-]{1,24}\))?)"  # "Ego (truck)": its type aside
KEY_LINE = re.compile(r"^\s*(?:[-*\u2022]\s*)?(?:\(?[a-z0-9]\)\s*)?" + KEY_NAME + r"\s*[:|]\s*(.*)$")
DASHED_KEY = re.compile(r"^\s*(?:[-*\u2022]\s*)?" + KEY_NAME + r"\s+[-\u2013\u2014]\s+(.*)$")  # "Van - stopped, front"


def _dashed_agent_key(line: str) -> re.Match | None:
    """A line keyed by an agent set off by a dash ('2. Van - stopped, front'); a dash after other words is prose."""
    m = DASHED_KEY.match(line)
    return m if m is not None and _names_agent(m.group(1)) else None
TITLE_KEYS = {"case", "name", "id", "scenario", "objective", "title", "summary", "sequence", "scene", "test",
              "description", "goal", "purpose", "report", "note", "story", "epic", "feature",
              "functional", "logical", "concrete"}  # "Functional scenario: Stationary obstacle in ego lane."
CASE_WORDS = {"event", "scenario", "case", "exercise", "example", "test", "clip", "site", "problem", "question",
              "assignment", "lab", "scene", "hazard", "item", "section", "task", "variant", "figure", "slide"}
TITLE_CASED = re.compile(r"\s*((?:[A-Za-z][\w'-]*\s+){1,9}[A-Za-z][\w'-]*)[.!?]\s+\S")
TITLE_SMALL_WORDS = {"a", "an", "the", "with", "of", "at", "in", "on", "and", "to", "for", "from", "by", "or", "vs"}
NUMBERED_KEY = re.compile(r"\s*([A-Z][a-z]+ \d{1,3}[a-z]?|[A-Za-z]{1,8}[-_]\d{2,}(?:[-_.]\d+)*)\s*:\s+")
CASE_NUMBER = re.compile(r"[A-Za-z]{1,8}[-_]\d{2,}(?:[-_.]\d+)*")  # 'TC-052', 'HZ-014': a case's number keys its title
NUMBERED_CASE = re.compile(r"[a-z]+\s+#?(?:\d{1,4}[a-z]?|[a-z]{1,8}[-_]?\d+(?:[-_.]\d+)*)")  # 'hazard h-22', 'event 7'
TRIGGER_KEYS = {"triggering condition", "trigger condition", "trigger", "triggering event", "trigger event"}
OWN_VEHICLE_KEYS = {"your vehicle", "my vehicle", "own vehicle", "insured vehicle", "policyholder vehicle",
                    "your car", "my car", "vehicle driven", "vehicle you were driving", "vehicle involved",
                    "claimant vehicle", "claimant's vehicle", "insured's vehicle", "our vehicle", "reporting vehicle",
                    "vehicle in question"}
LONE_VEHICLE_KEYS = {"vehicle", "asset", "bus", "coach", "truck", "lorry", "van", "bike", "motorcycle", "taxi"}
# a record's one vehicle key ("Vehicle: coach RR-07", "Asset: TRK-0088 (Volvo FH)"): its own vehicle, when alone
THIRD_PARTY_KEYS = {"third party vehicle", "third party", "other party vehicle", "other party", "tp vehicle",
                    "third party's vehicle"}
# a claim form's fields for the claimant's own vehicle and the other party's, the latter told of in the account
FORM_ACCOUNT_KEYS = {"describe what happened", "what happened", "description of incident", "description of accident",
                     "details of incident", "details of accident", "how did it happen", "incident description",
                     "accident description", "circumstances", "account", "statement", "your account",
                     "driver comment", "driver comments", "driver statement", "driver's comment", "driver's statement",
                     "driver remarks", "driver notes", "driver note", "driver report", "driver account", "comment",
                     "comments", "remarks"}  # ("Driver comment: I had a green": what the ego's driver told)
ACCOUNT_KEYS = {"summary", "report"}  # a form's field that tells what happened ("Summary: The HGV overtook me
# ..."): the scene, not its title, when told by the one it happened to (not an auditor's "we")
PLAIN_KEYS = {"light", "lighting", "time", "time of day", "conditions", "condition", "environment", "weather",
              "env", "visibility", "daylight", "when"}
NOTHING = {"none", "n/a", "no", "-", "nil", "nothing", "0"}
PLAIN_KEYS |= FORM_ACCOUNT_KEYS
PLAIN_KEYS |= {"setup", "set up", "actors", "agents", "participants", "npcs", "road", "roads", "map", "route",
               "location", "description", "details", "steps", "notes", "trigger", "initial conditions",
               "initial state", "layout", "geometry", "infrastructure", "traffic", "other traffic", "situation",
               "context", "given", "when", "then", "and", "scene description", "scenario description",
               "positions", "initial positions", "start positions", "starting positions", "placement", "maneuvers",
               "manoeuvres", "actions", "behaviours", "behaviors", "dynamics", "events", "sequence"}
# ("Positions: truck ahead of ego", "Maneuvers: ego goes straight, truck stops": a field over what the agents
# listed before do, each named again)
ORACLE_KEYS = {"expected", "expected result", "expected behaviour", "expected behavior", "expected outcome", "ac",
               "acceptance", "acceptance criteria", "acceptance criterion", "pass criterion", "pass criteria",
               "success criteria", "success criterion", "kpi", "kpis", "metrics", "metric", "result", "outcome",
               "assert", "assertion", "assertions", "check", "checks", "verify", "pass", "fail", "fail criterion",
               "pass fail", "evaluation", "measure", "measured", "log", "logging", "priority", "status", "owner",
               "assignee", "labels", "label", "ticket", "jira", "reporter", "component", "sprint", "tags", "tag",
               "links", "attachments", "version", "build", "seed"}  # what the test checks, not the scene


SLUGLINE = re.compile(r"^[ \t]*(INT\.?[ \t]*/[ \t]*EXT|EXT\.?[ \t]*/[ \t]*INT|I/E|INT|EXT)\.[ \t]+(\S.*?)[ \t]*$", re.M)
SCENE_TIMES = {"day": "daytime", "night": "night", "dawn": "dawn", "dusk": "dusk", "morning": "morning",
               "evening": "evening", "sunrise": "sunrise", "sunset": "sunset", "afternoon": "afternoon",
               "midday": "midday", "noon": "noon", "twilight": "twilight", "first light": "first light",
               "magic hour": "golden hour", "golden hour": "golden hour", "late night": "late night"}
SCENE_CONTINUITY = {"continuous", "later", "moments later", "a moment later", "same", "same time", "flashback",
                    "present", "present day", "back to scene", "intercut"}
SCREEN_DIRECTIONS = re.compile(r"^[ \t]*(?:(?:CUT|DISSOLVE|SMASH CUT|MATCH CUT) TO:|FADE (?:IN|OUT)[:.]?|FADE TO BLACK\.?"
                               r"|THE END)[ \t]*$", re.M)


SERVICE = r"(?:police|fire(?: and rescue| brigade| service| department)?|ambulance(?: service)?|paramedics|coastguard)"
SERVICES_ASKED = re.compile(rf"(?i)(\b(?:caller|operator|dispatcher|dispatch|call handler|call taker)\s*:\s*)"
                            rf"(?:{SERVICE}(?:\s*(?:,|or|and|&)\s*(?:an?\s+)?{SERVICE})*(?:,?\s*(?:please|service))?"
                            rf"\s*[,.?!]\s*)+(?=\S)")


def _without_services_asked(text: str) -> str:
    """'OPERATOR: Police, fire or ambulance? / CALLER: Police. A car has just run the red': an emergency call
    opens on the service asked for, which sends no one into the scene."""
    return SERVICES_ASKED.sub(r"\1", text)


def _screenplay(text: str) -> str:
    """A screenplay's page: a scene heading ('EXT. HIGH STREET - NIGHT') says where and when, read like a title
    for the road and the weather ('DAY' is daytime; 'CONTINUOUS' and an interior place say nothing); lines
    indented far from the margin are a character's name and what they say, no description; transitions
    ('CUT TO:') are no scene."""
    if not SLUGLINE.search(text):
        return text
    out = []
    for line in text.splitlines():
        m = SLUGLINE.match(line)
        if m is not None:
            parts = [p.strip() for p in re.split(r"\s+[-\u2013\u2014]+\s+", m.group(2)) if p.strip()]
            interior = m.group(1).startswith("INT") and "EXT" not in m.group(1)
            said = [] if interior else parts[:1]
            for part in parts[1:]:  # "NIGHT", "DAY - RAIN", "CONTINUOUS"
                if part.lower() in SCENE_TIMES:
                    said.append(f"in the {SCENE_TIMES[part.lower()]}")
                elif part.lower() not in SCENE_CONTINUITY:
                    said.append(part)
            out.append("\u00a7 " + " , ".join(said) + "." if said else "")
        elif SCREEN_DIRECTIONS.match(line) or re.match(r"^(?: {4,}|\t)\S", line):
            out.append("")
        else:
            out.append(AT_THE_WHEEL_NAME.sub(driver_named, line))
    return "\n".join(out)


DRIVING_VERBS = ("waits|turns|pulls|eases|slides|swings|brakes|stops|accelerates|drives|indicates|edges|creeps|noses"
                 "|steers|merges|changes|moves|rolls|speeds|slows|reverses|overtakes|follows|halts|idles|signals")
AT_THE_WHEEL_NAME = re.compile(rf"(?:(?<=^)|(?<=[.!?,] )|(?<=then )|(?<=and ))([A-Z][a-z]+|[A-Z]{{2,}})(?= (?:{DRIVING_VERBS})\b)")


def known_word(name: str) -> bool:
    """A name that is also a word the reader knows ('Will', 'Mark', 'Then'; 'Grace' is not)."""
    lex = lexicon()
    return name.lower() in lex.vocabulary or name.lower() in lex.function_words


def driver_named(m: re.Match) -> str:
    """In a screenplay's action lines a character who drives ('Tom waits', 'Riley pulls straight ahead') is at
    the wheel of the ego; a word the lexicon knows ('A BUS', 'Then', 'Buses') is no name."""
    word = m.group(1)
    return word if known_word(word) or lexicon().base(word.lower())[0] in lexicon().vocabulary else "the ego"
CHOICE_BOX = re.compile(r"\s*(?:\[\s*[xX\u2713]?\s*\]|[\u2610\u2611\u2612])")  # "[ ] Wave them across"
CHOICE_MARK = re.compile(r"\s*\(?([A-Fa-f]|[1-6])(?:[.)]\s*|\s{2,}|\s+(?=[A-Z]))")  # "A. You do", "(b) Stop", "1) A, B"
CHOICE_INSTRUCTION = re.compile(r"\s*(?:mark|select|choose|tick|pick|circle)\s+(?:one|two|three|all|the|an?)\b"
                                r"[^.?!]*\banswers?\b", re.I)  # "Mark one answer"


ROAD_KEYS = {"road", "roads", "layout", "geometry", "location", "infrastructure", "street", "carriageway"}
BARE_SPEED = re.compile(r"(\b\d{2,3}\s*(?:km/h|kmh|kph|mph)(?![a-z]))", re.I)
LABEL_COLUMN = re.compile(r"^(\s*(?=[A-Z0-9]{2})[A-Z]{1,6}[0-9]{0,2})\s{2,}(?=\S)")
PHASE_KEY = re.compile(r"(stage|step|phase) (\d+|[a-z]|one|two|three|four)")
FIRST_PHASES = {"1", "a", "one"}
CHECKING = {"check", "checks", "verify", "verifies", "ensure", "ensures", "confirm", "confirms", "assert", "asserts"}


EXERCISE_ITEM = re.compile(r"\s*(?:\(?[a-h]\)|\(?(?:i|ii|iii|iv|v|vi)\)|[a-h]\.)\s+(?:(?:how|what|find|calculate|"
                           r"determine|work out|estimate|explain|convert|at what|by how|hence|deduce|compare|"
                           r"show that|prove)\b.*|.*\?\s*)$", re.I)
# "(a) How long does it take the car to catch up?", "(b) Find the stopping distance.": a word problem's questions,
# asked of the scene, are none of it (not "a) When the light turns red, the ego stops": a case of its own)


def _without_answer_choices(lines: list[str]) -> list[str]:
    """A multiple-choice question's answers ('A  Move off quickly', '(b) On the left', '[ ] Sound your horn')
    are what a reader might do, not the scene: after a line that asks, lines marked A, B, C... (or 1, 2, 3, or
    boxes) in order are left out, with the 'Mark one answer' line."""
    out, asked, expected = [], False, 0
    for line in lines:
        if asked and line.strip():
            if CHOICE_INSTRUCTION.match(line) or CHOICE_BOX.match(line):
                continue
            m = CHOICE_MARK.match(line)
            if m and "abcdef123456".index(m.group(1).lower()) % 6 == expected:
                expected += 1
                continue
        out.append(line)
        if line.rstrip().endswith("?"):
            asked, expected = True, 0
    return out


def _linking(value: str) -> str:
    """What joins a key to its value: 'Van: stopped, front-right' is 'Van is stopped, front-right', but
    'EV: turns right' is 'EV turns right' (a value that starts with a verb of its own)."""
    first = value.split()[0].lower() if value.split() else ""
    if first in ("is", "are", "has", "does", "keeps") or first.endswith("s") and not first.endswith("ss") and \
            lexicon().base(first)[1] and lexicon().base(first)[0] in _verbs():
        return " "
    return " is "


PLACE_WORDS = {"left", "right", "rear", "back", "front", "ahead", "behind", "level", "opposite", "oncoming", "near",
               "far", "middle", "centre", "center", "inside", "outside"}


def _keyed(key: str, value: str) -> str:
    """A key's line as a sentence with the key its subject: 'Van: oncoming, turn left' is 'Van is oncoming, and
    turn left' (a later piece that starts with a bare verb is the key's too, no order to the ego)."""
    pieces = value.split(", ")
    for k in range(1, len(pieces)):
        first = pieces[k].split()[0].lower() if pieces[k].split() else ""
        if first in _verbs() and lexicon().base(first) == (first, False) and first not in PLACE_WORDS:
            pieces[k] = "and " + pieces[k]  # not "left lane, ahead", "rear": where it is
    return f"{key}{_linking(value)}{', '.join(pieces)}"


@lru_cache(maxsize=1)
def _verbs() -> frozenset:
    return frozenset(words[0] for words, (category, _) in lexicon().phrases.items() if category == "actions")


OUTLINE_NUMBER = re.compile(r"^(\s*)(?:\u00a7\s*)?(?:\d{1,3}(?:\.\d{1,3})+\.?|\d{1,3}\.)[ \t]+(?=\S)")


def _without_outline_numbers(lines: list[str]) -> list[str]:
    """A formal document numbers its clauses ('6.3.1 The vehicle under test shall ...', '11.2 Pedestrian on a
    marked crossing'): the number is where the clause sits, no count or speed. A numbered line that is no
    sentence (no verb-bearing ending, a few words) is the heading of a section, read like a title."""
    out = []
    for line in lines:
        m = OUTLINE_NUMBER.match(line)
        if m is None:
            out.append(line)
            continue
        rest = line[m.end():].rstrip()
        heading = "." in m.group(0).strip().rstrip(".") and not rest.endswith((".", "!", "?", ":", ";")) \
            and len(rest.split()) <= 10
        out.append("\u00a7 " + rest + "." if heading else m.group(1) + rest)
    return out


TITLE_MARK = re.compile(r"\s[-\u2013\u2014]\s|[\"\u201c\u201d\[]")  # "Bus Career - Route 12", 'LEVEL 3 "GO"'


def _heading_line(lines: list[str]) -> bool:
    """A first line with no full stop that names the piece ('Ambulance Sim - Shift 2, Call 4', 'LEVEL 3 -
    "GREEN MEANS GO"') over a blank line, or marked as a title (a spaced dash, quotes, a tag in square
    brackets) over prose, or a case's identifier ('LEAD_BRAKE_01'): the piece's title, read for the road and the
    weather only."""
    first = lines[0]
    if first.rstrip().endswith((".", "!", "?")) or len(first.split()) > 12 or len(lines) < 2:
        return False
    if len(lines) > 2 and not lines[1].strip():
        return True
    if re.fullmatch(r"\s*[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+)+\s*", first):
        return True  # "LEAD_BRAKE_01", "unprot_left_02": a case's identifier over its lines
    return TITLE_MARK.search(first) is not None and lines[1].rstrip().endswith((".", "!", "?"))
COLUMNS = {  # a table's header words, by what the cells under them say
    "actor": {"actor", "agent", "id", "name", "vehicle", "object", "entity", "participant", "who", "label", "obj"},
    "type": {"type", "kind", "class", "category", "vehicle type", "actor type", "model", "vehicle class"},
    "time": {"t", "time", "step", "phase", "stage", "timestep", "time step", "tick", "seq", "sequence"},
    "role": {"role", "purpose", "function"},
    "speed": {"speed", "velocity", "v", "speed kph", "speed kmh", "speed mph", "speed km h", "init speed",
              "initial speed", "target speed", "v0"},
    "lane": {"lane", "start lane", "lane id", "current lane", "initial lane"},
    "relative": {"rel", "rel pos", "rel position", "relative position", "relative pos", "position rel ego",
                 "rel to ego", "relative to ego", "position relative to ego", "rel ego"},
    "other": {"start", "start pos", "start position", "position", "pos", "location", "manoeuvre",
              "maneuver", "action", "actions", "intent", "behaviour", "behavior", "what", "notes", "note",
              "trigger", "init", "initial", "initial state", "end", "goal", "route", "path", "description", "does",
              "event", "events", "state", "where", "heading", "direction", "origin", "from", "to"},
}
LANE_CELLS = {"left", "right", "middle", "centre", "center", "inside", "outside", "fast", "slow", "nearside",
              "offside", "overtaking", "passing", "leftmost", "rightmost"}
OWN_LANE_CELLS = {"same", "ego", "ego lane", "same as ego", "same lane", "ego's", "ego's lane", "own"}
RELATIVE_CELLS = {"ahead": "ahead of the ego", "behind": "behind the ego", "level": "level with the ego",
                  "alongside": "level with the ego", "beside": "level with the ego", "abreast": "level with the ego"}


def _cell_said(kind: str | None, value: str) -> str:
    """A lane or a place relative to the ego said bare in its column ('right' under 'lane', 'level' under
    'rel_pos'), said as a sentence would say it."""
    bare = value.strip().lower()
    if kind == "lane":
        if bare in LANE_CELLS:
            return f"in the {bare} lane"
        if bare in OWN_LANE_CELLS:
            return "in the ego's lane"
        if bare.isdigit():
            return f"in lane {bare}"
    if kind == "relative" and bare in RELATIVE_CELLS:
        return RELATIVE_CELLS[bare]
    return value


SEPARATOR_ROW = re.compile(r"^[\s|:+=-]*-[\s|:+=-]*$")


def _column(name: str) -> str | None:
    """What a header cell names ('start_pos', 'speed (km/h)', 'Speed_kph'), or None for a word of no table."""
    said = re.sub(r"[^a-z0-9]+", " ", name.lower()).strip()
    for kind, names in COLUMNS.items():
        if said in names or said.split()[:1] and said.split()[0] in names and kind == "speed":
            return kind
    return None


def _cells(line: str, delimiter: str) -> list[str]:
    return [c.strip() for c in line.strip().strip("|" if delimiter == "|" else "").split(delimiter)]


def _tables(lines: list[str]) -> list[str]:
    """A table of actors ('| actor | type | start | manoeuvre |', or comma-separated under a header row): each
    row is one actor, told as a line of its own ('TV1: HGV, ego lane, +40 m, brakes to stop'); the header and
    the rule under it are no scene. A role column beside a type column says what the test uses the actor for,
    no agent of its own ('lead veh'); a bare speed takes the header's unit; a time column ('t0', 't1 (after the
    cyclist clears)') orders the rows into stages."""
    out: list[str] = []
    k = 0
    while k < len(lines):
        delimiter = "|" if lines[k].count("|") >= 2 else "," if lines[k].count(",") >= 2 else None
        header = _cells(lines[k], delimiter) if delimiter else []
        kinds = [_column(c) for c in header]
        if not delimiter or sum(kind is not None for kind in kinds) < 2 or not all(
                kind is not None or not c for kind, c in zip(kinds, header)):
            out.append(lines[k])
            k += 1
            continue
        k += 1
        rows = []
        while k < len(lines) and (SEPARATOR_ROW.match(lines[k]) and delimiter == "|" or
                                  len(_cells(lines[k], delimiter)) == len(header) and lines[k].strip()):
            if not SEPARATOR_ROW.match(lines[k]):
                rows.append(_cells(lines[k], delimiter))
            k += 1
        times: list[str] = []
        for row in rows:
            cell = {kind: value for kind, value in zip(kinds, row) if kind in ("actor", "type", "time")}
            said = []
            for kind, name, value in zip(kinds, header, row):
                if kind in ("actor", "time") or kind == "role" and "type" in kinds or not value or value == "-":
                    continue
                if kind == "speed" and re.fullmatch(r"\d+(?:\.\d+)?", value):
                    unit = re.search(r"mph|kph|kmh|km ?/ ?h|m ?/ ?s", name.lower())
                    value = f"{value} {unit.group(0) if unit else 'km/h'}"
                said.append(_cell_said(kind, value))
            subject = cell.get("actor") or ""
            if not subject and said:
                subject = said.pop(0)
            value = ", ".join(said)
            line = f"{subject}: {value}" if subject and value else subject or value
            time = re.sub(r"\s*\(.*", "", cell.get("time", "")).strip()
            if time and times and time != times[-1]:
                condition = re.search(r"\((.*)\)", cell.get("time", ""))
                line = f"{condition.group(1) if condition else 'then'}, {_keyed(subject, value)}"
            if time and (not times or time != times[-1]):
                times.append(time)
            out.append(line)
    return out


OPENING_TITLE_KEY = re.compile(r"\s*([A-Za-z]+)[ \t]*:[ \t]*([^.:\n]{1,80})\.[ \t]+[A-Za-z]+[ \t]*:")
INLINE_KEY = re.compile(r"(?<=[.;])[ \t]+(?=((?!(?:In )?Lanes?\b)[A-Z][A-Za-z0-9/-]*(?: [A-Za-z0-9/-]+){0,2}):[ \t])")
# ("Actor 1:" keys its line; "Lane 2:" is read with the lanes)


def _inline_key_break(m: re.Match) -> str:
    """A line break before a key run on after a full stop; what a test expects stays in its sentence (the text
    told it as part of the scene)."""
    key = m.group(1).lower()
    return m.group(0) if key in ORACLE_KEYS or key.split()[0] in ("expected", "acceptance", "pass", "success") \
        else "\n"


ADVICE_KEY = re.compile(r"(?:^|(?<=[.;!?]))[ \t]*(?:coach|coachable|coaching|recommendations?|tips?|takeaways?|"
                        r"lessons?(?: learned)?|corrective actions?|action taken)[ \t]*:", re.I | re.M)
NEXT_KEY = re.compile(r"(?<=[.;])[ \t]+(?=(?!(?:In )?Lanes?\b)[A-Z][A-Za-z0-9/-]*(?: [A-Za-z0-9/-]+){0,2}:[ \t])|\n")


LANE_KEY = re.compile(r"(?:^|(?<=[.;]\s))[ \t]*(?:[-*•][ \t]+)?(?:the\s+)?(lanes?\s+\d(?:\s+and\s+\d)?|"
                      r"(?:(?:left|right|middle|centre|"
                      r"center|inside|outside|fast|slow|overtaking|ego's|ego|same|nearside|offside)\s+lane)|"
                      r"(?:(?:left|right|hard)\s+)?shoulder)((?:\s+(?:ahead|behind))?)[ \t]*:", re.I | re.M)
MOVING_FROM_KEY = re.compile(r"(?:^|(?<=[.;]\s))[ \t]*([A-Z][a-z]+ing)\s+(from the (?:left|right))[ \t]*:"
                             r"[ \t]*([^.;\n]+)", re.M)


def _lane_keys(text: str) -> str:
    """'Lane 4: 2 trucks, one level with the ego', 'Middle lane behind: 1 ambulance', 'Hard shoulder: 1 truck',
    'Circulating from the left: 2 cars': a layout keyed by lane or way says where what follows is, as 'in lane 4:'
    would."""
    def place(m: re.Match) -> str:
        key, lead = m.group(1) + m.group(2), m.group(0)[:m.start(1) - m.start()]
        if key.lower().startswith("lane"):
            return lead + f"In {key}:"
        return lead + ("On the " if "shoulder" in key.lower() else "In the ") + key + ":"
    text = MOVING_FROM_KEY.sub(lambda m: f"{m.group(2).capitalize()}: {m.group(3)}, {m.group(1).lower()}", text)
    # "Circulating from the left: 2 cars, passing": from the left come 2 cars, circulating
    return LANE_KEY.sub(place, text)


def _without_advice(text: str) -> str:
    """'Coachable: right-of-way, judging speed of oncoming two-wheelers', 'Recommendation: provide a right-turn
    lane': what someone should do about the scene after it is told, to the next key or the end of its line."""
    while (m := ADVICE_KEY.search(text)) is not None:
        end = NEXT_KEY.search(text, m.end())
        text = text[:m.start()] + (text[end.start():] if end else "")
    return text


def _verbless(phrase: str) -> bool:
    """No verb but a participle before its noun ('the occluded pedestrian'): a name, not a sentence."""
    found = matches(tokenize(phrase))
    return not any(f.category == "actions" and not any(g.start == f.end and g.category == "agents" for g in found)
                   for f in found)


TEST_CODE_KEY = re.compile(r"(?m)^[ \t]*(?:[A-Z]{1,6}-)+VRU(?:-[A-Z0-9]{1,6})*[ \t]*:")  # "RT-VRU: SV turns right":
# a test's code, no road user of its own


def _says_an_agent(value: str) -> bool:
    """'yellow school bus, route 3': a value that names a road user other than the ego."""
    return any(f.category == "agents" and f.meaning not in ("ego", "none") for f in matches(tokenize(value)))


def _one_vehicle_keyed(lines: list[str]) -> bool:
    """A record with one vehicle key and no numbered parties (a police report's 'Vehicle 1:', 'V2:')."""
    keys = [m.group(1).strip().lower() for m in map(KEY_LINE.match, lines) if m]
    return sum(k in LONE_VEHICLE_KEYS | OWN_VEHICLE_KEYS for k in keys) == 1 and \
        not re.search(r"(?i)\b(?:v|veh|vehicle|unit)\s?#?\d\b", "\n".join(lines))


NESTED_LINE = re.compile(r"^([ \t]*)(-[ \t]+)?([A-Za-z_][\w -]{0,30}?)[ \t]*:[ \t]*(.*?)[ \t]*$")
FLOW_ITEM = re.compile(r"\s*-\s*\{(.*)\}\s*")  # "  - {type: truck, from: ...}": a list's item, written in one line
FLOW_PAIR = re.compile(r"\s*([A-Za-z_][\w ]{0,30}?)\s*:\s*(\"[^\"]*\"|'[^']*'|[^,]*)\s*(?:,|$)")
KEPT_KEY_WORDS = {"from", "to", "towards", "toward", "into", "behind", "ahead"}  # "from: main road on ego's right"


def _pairs_said(subject: str, pairs: list[tuple[str, str]]) -> str:
    """A record's keys and values as one line: 'npc1: SUV, in the right lane, level with ego, cuts in'; its id or
    name is the subject (else the key it hangs under, else its type), its type said first."""
    kinds = [(_column(key), key, value.strip().strip("\"'")) for key, value in pairs]
    named = next((v for kind, _, v in kinds if kind == "actor" and v), "") or subject
    types = [v for kind, _, v in kinds if kind == "type" and v]
    rest = [f"{key} {v}" if key.lower() in KEPT_KEY_WORDS else _cell_said(kind, v) for kind, key, v in kinds
            if kind not in ("actor", "type") and v]
    if not named:
        named, types = (types[0], types[1:]) if types else ("", types)
    said = ", ".join(types + rest)
    return f"{named}: {said}" if named and said else named or said


def _nested_keys(text: str) -> str:
    """A record written as nested keys ('ego:' over '  type: car' and '  action: straight'; 'actors:' over '  - id:
    npc1' and its keys; '{type: truck, from: main road on ego's right}') read as one line a road user, as a
    table's rows are."""
    lines = text.splitlines()
    out: list[str] = []
    k = 0
    while k < len(lines):
        m = NESTED_LINE.match(lines[k])
        flow = m and re.fullmatch(r"\{(.*)\}", m.group(4)) if m else FLOW_ITEM.fullmatch(lines[k])
        if flow:
            pairs = FLOW_PAIR.findall(flow.group(1))
            out.append(_pairs_said(m.group(3) if m and not m.group(2) else "", pairs))  # "ego: {type: car, ...}"
            k += 1
            continue
        if m is None or m.group(4) or m.group(2):
            out.append(lines[k])
            k += 1
            continue
        indent = len(m.group(1).expandtabs())
        children = []
        j = k + 1
        while j < len(lines) and (not lines[j].strip() or len(lines[j]) - len(lines[j].lstrip()) > indent):
            children.append(lines[j])
            j += 1
        children = [c for c in children if c.strip()]
        if not children or not all(NESTED_LINE.match(c) or FLOW_ITEM.fullmatch(c) for c in children):
            out.append(lines[k])
            k += 1
            continue
        if any(c.lstrip().startswith("-") for c in children):  # "actors:" over items: each item a line of its own
            item: list[tuple[str, str]] = []
            for c in children:
                cm = NESTED_LINE.match(c)
                if cm is None:
                    out.extend([_pairs_said("", item)] if item else [])
                    item = []
                    out.append(_nested_keys(c))
                    continue
                if cm.group(2) and item:
                    out.append(_pairs_said("", item))
                    item = []
                item.append((cm.group(3), cm.group(4)))
            out.extend([_pairs_said("", item)] if item else [])
        else:  # "ego:" over its keys
            out.append(_pairs_said(m.group(3), [(cm.group(3), cm.group(4))
                                                for cm in map(NESTED_LINE.match, children)]))
        k = j
    return "\n".join(out)


def _lines(text: str) -> str:
    """Notes written one item a line ('Ego: straight', 'Child| runs into road', '- fire engine: behind ego')
    read as sentences: the key is the subject of its line ('Ego is straight'); 'Stage 2:' starts a stage;
    'Other actors: none' says there are none; a title line ('Case: child after ball') is dropped."""
    text = re.sub(r"\b[vV]\s?=\s?(\d{1,3}(?:\.\d+)?)\s?(km/h|kph|kmh|mph|m/s)", r"at \1 \2", text)  # "lane keep,
    # v=60 km/h": a speed, no vehicle called v
    text = _lane_keys(TEST_CODE_KEY.sub("", _nested_keys(text) if "\n" in text else text))
    if re.search(r":[ \t]+-[ \t]+\S", text):  # "Constraints: - 3 lanes, ego in the middle - 3 stopped cars ahead":
        text = re.sub(r"[ \t]+-[ \t]+(?=[A-Za-z0-9])", "\n- ", text)  # a dashed list run on in one line, an item a line
    if "\n" not in text.strip() and len(INLINE_KEY.findall(text)) >= 2:
        text = INLINE_KEY.sub(_inline_key_break, text)  # "Scenario: unprotected left. Oncoming: 1 sedan, 1 box
        # truck.": notes run on in one line, a key after each full stop
    text = _without_advice(text)
    if "\n" not in text.strip():
        title = OPENING_TITLE_KEY.match(text)
        if title and title.group(1).lower() in TITLE_KEYS and any(
                f.category == "agents" and f.meaning not in ("ego", "none") for f in matches(tokenize(title.group(2)))):
            text = "\u00a7 " + text[title.start(2):]  # "scenario: stopped vehicle on shoulder. road: ...": its name,
            # whose vehicle the keys name again ("Scenario: unprotected left turn." is the ego's turn, read)
        numbered = NUMBERED_KEY.match(text)
        if numbered and numbered.group(1).split()[0].lower() in CASE_WORDS:
            text = text[numbered.end():]  # "Event 7: motorcycle at a junction. ...": which event, no scene word
            titled = TITLE_CASED.match(text)
            if titled and (all(w[0].isupper() or w.lower() in TITLE_SMALL_WORDS for w in titled.group(1).split())
                           or _verbless(titled.group(1))):
                text = "\u00a7 " + text  # "Example 15: Right Turn With Oncoming Cyclist. The ego ...", "Exercise
                # 10: the occluded pedestrian. The ego drives ...": its title, named without a verb
        return _keyed_agents("\n".join(_without_outline_numbers([text])))
    out = []
    lines = _tables(_without_answer_choices(_without_outline_numbers(
        [line for line in text.strip().splitlines() if not EXERCISE_ITEM.match(line)])))
    staged = False
    phased = any((m := KEY_LINE.match(line)) and PHASE_KEY.fullmatch(m.group(1).strip().lower()) for line in lines)
    speakers = _speakers(lines)
    gherkin = any(line.lstrip().startswith(("Given ", "When ", "Then ")) for line in lines)
    for k, line in enumerate(lines):
        if not line.strip():
            continue
        line = line.replace("->", " and ").replace("\u2192", " and ")
        line = LABEL_COLUMN.sub(r"\1: ", line)  # "  TV1  car stopped ahead": a label in a column of its own
        m = KEY_LINE.match(line) or _dashed_agent_key(line)
        if k == 0 and m is None and _heading_line(lines):
            out.append("\u00a7 " + line.strip() + ".")  # a heading line over a blank line: the ticket's title
            continue
        if m is None:
            out.append(line.strip().lstrip("-*\u2022 ").rstrip(".") + ".")
            continue
        key, value = m.group(1).strip(), m.group(2).strip().rstrip(".")
        lowered = key.lower()
        if key in speakers:
            out.append(value + ".")  # "HOST B: Zebra, so the stripy one.": what was said, not who said it
            continue
        if lowered in THIRD_PARTY_KEYS and _verbless(value):
            continue  # "Third party vehicle: Vauxhall Astra": named again by the account of what happened
        if (lowered in OWN_VEHICLE_KEYS or lowered in LONE_VEHICLE_KEYS and _one_vehicle_keyed(lines) and
                _says_an_agent(re.sub(r"\b[A-Za-z]+-\d+\b", "", value))) and _verbless(value):  # (not "HGV-0412": a
            # fleet number, read as one below)
            article = "" if value.lower().split()[:1] in (["a"], ["an"], ["the"]) else "a "
            out.append(f"The ego is {article}{value}.")  # "Your vehicle: 44t artic (HGV)": what the claimant drove
            continue
        if lowered in ORACLE_KEYS or lowered.split()[0] in ("expected", "acceptance", "pass", "success", "kpi"):
            continue
        if value.split()[:1] and value.split()[0].lower() in CHECKING:
            continue  # "Notes: check EV does not assume Actor A will yield": what the test checks
        if PHASE_KEY.fullmatch(lowered):
            out.append(("then " if staged or lowered.split()[1] not in FIRST_PHASES and
                        any(not x.startswith("\u00a7") for x in out) else "") + value + ".")
            staged = True  # "Phase 1:" goes on with the setup above it; each later phase is a stage
            continue
        if phased and not staged:
            value = re.split(rf",?\s+(?:and\s+)?(?:{_later_words()})\b", value)[0]  # "Ego: follows HGV, then (after
            # that) pulls out": the phases
            # below tell what comes when; the line before them says who is there and how it starts
        if lowered.split()[0] in CASE_WORDS and NUMBERED_CASE.fullmatch(lowered) or lowered in TRIGGER_KEYS:
            out.append("\u00a7 " + value + "." if _verbless(value) else f"{key}: {value}.")  # "Exercise 10: the
            continue  # occluded pedestrian.": the case's name; "Hazard H-22: pedestrian emerging from behind parked
            # vehicles.", "Triggering condition: a child steps out": a heading over what it names
        told = ("ego" in [w.lower() for w in value.split()[:2]] and len(value.split()) >= 5 or
                lowered in ACCOUNT_KEYS and bool(
                    {"i", "me", "my"} & {w.lower().strip(",.") for w in value.split()}) or
                lowered in ("scene", "description") and len(value.split()) >= 8 and not _verbless(value)) and \
            not gherkin
        # "Scene: ego turning left at a signalised intersection, one oncoming sedan going straight": the scene
        # itself, no title (but a Gherkin scenario's name, told again by its steps); so "Scene: the subject
        # vehicle travels straight ..., and a pedestrian crosses", a scene told with its verbs
        if lowered.split()[0] in TITLE_KEYS and lowered not in PLAIN_KEYS and not told or \
                lowered.startswith("crossing type") or k == 0 and \
                CASE_NUMBER.fullmatch(key) and not _names_agent(key) and not line.rstrip().endswith((".", "!", "?")):
            out.append("\u00a7 " + value + ".")  # read for the road and the weather only
        elif lowered in PLAIN_KEYS or lowered.split()[0] in ROAD_KEYS:
            listed = value.split(", ")
            if lowered.split()[-1] in LIST_HEADINGS and len(listed) > 1 and all(
                    len(piece.split()) <= 4 and _agent_kinds(re.findall(r"[a-z]+", piece.lower())) for piece in listed):
                value = "; ".join(listed)  # "Actors: the ego, a truck": a list, no apposition ("the ego, a bus,")
            if lowered.split()[0] in ROAD_KEYS and not re.search(r"\blimit", value, re.I):
                value = BARE_SPEED.sub(r"\1 limit", value)  # "Road: urban street, 30 km/h": its speed limit
            out.append(value + ".")  # "Light: dusk, drizzle" is the weather, not a traffic light
        elif value.lower() in NOTHING:
            out.append(f"no {key}.")
        elif lowered.split()[-1] in LIST_HEADINGS and value:
            out.append(value + ".")  # "Traffic participants: the ego vehicle travels ...": what it lists, as said
        elif not value:
            continue
        elif _place_of_a_key(lowered) and _names_agent(value.split(", ")[0]):
            place = _place_of_a_key(lowered)  # "Oncoming: 1 sedan, 1 box truck": each of them oncoming
            out.append(", and ".join(f"{piece} {place}" for piece in value.split(", ")) + ".")
        else:
            out.append(f"{_keyed(_first_named(key, chr(10).join(lines[:k])), value)}.")
    return " ".join(out)


KEY_PLACES = {"oncoming": "oncoming", "opposite": "oncoming", "opposing": "oncoming", "behind": "behind",
              "rear": "behind", "ahead": "ahead", "front": "ahead", "in front": "ahead", "left": "on the left",
              "right": "on the right", "from left": "from the left", "from right": "from the right",
              "from the left": "from the left", "from the right": "from the right"}


def _place_of_a_key(key: str) -> str | None:
    """A key that says only where ('Oncoming', 'Traffic from the right', 'Behind'): the place of each agent its
    value lists."""
    words = [w for w in key.split() if w not in ("traffic", "vehicles", "vehicle", "cars", "agents", "actors",
                                                 "crossing", "other")]
    return KEY_PLACES.get(" ".join(words))


def _speakers(lines: list[str]) -> set[str]:
    """The speakers of a transcript ('HOST A:', 'Q:', 'Interviewer:'): keys that start two lines or more, each
    followed by a sentence, and that name no agent, stage or field."""
    keys: dict[str, int] = {}
    for line in lines:
        m = KEY_LINE.match(line)
        if m and re.search(r"[a-z]{2,}.*[ .!?,\u2014-]", m.group(2)):
            keys[m.group(1).strip()] = keys.get(m.group(1).strip(), 0) + 1
    plain = {key for key in keys if not _names_agent(key) and key.lower() not in PLAIN_KEYS | ORACLE_KEYS and
             key.lower().split()[0] not in TITLE_KEYS | {"stage", "step", "phase", "expected", "acceptance"} and
             not re.match(r"(?:[-*\u2022]\s*)?(?:in|on)\s", key, re.I)}  # ("In lane 3:" twice: a place, no speaker)
    repeated = {key for key in plain if keys[key] >= 2}
    return repeated | {key for key in plain if any(  # "HOST B: Together?" once, beside "HOST A" who speaks often
        key.split()[0] == other.split()[0] or key.isupper() and other.isupper() for other in repeated)}


LABEL_KEY = re.compile(r"(?:npc|actor|agent|target|obj|object|adversary|vru|ped|car|truck|bus|bike|v|sv|pov|tv|gvt|veh"
                       r"|vehicle|unit|participant)[ _#]?\d{1,2}")


def _key_words(key: str) -> tuple[str, tuple[str, ...], tuple | None]:
    """A key's name ('Ego (truck)': its type in brackets aside), its words, and the lexicon's entry for them."""
    name = re.sub(r"\s*\(.*\)", "", key).strip()
    words = tuple(_normalize(name).split())
    return name, words, lexicon().phrases.get(words) or lexicon().phrases.get(words[-1:]) if words else None


def _names_agent(key: str) -> bool:
    """'Van', 'ego', 'NPC2', 'Actor_1', 'lead car': a key that names an agent, not a title."""
    name, words, entry = _key_words(key)
    if LABEL_KEY.fullmatch(name.lower()):
        return True
    if words and words[-1] in LIST_HEADINGS:
        return False  # "Traffic participants: the ego vehicle travels ...; a passenger car ...": a list's heading
    return bool(entry) and entry[0] == "agents" and entry[1] != "none" and len(words) <= 3


LIST_HEADINGS = {"participants", "actors", "agents", "users", "objects", "entities", "vehicles", "others"}


NAMED_BEFORE = {"the", "a", "an", "my", "our", "your", "their", "his", "her", "its", "both", "other", "another", "this",
                "that", "each", "every"}


TYPE_ACRONYMS = {"SUV", "HGV", "LGV", "MPV"}  # written in capitals, and kinds of vehicle, not a role ('EV', 'POV')


def _first_named(key: str, before: str) -> str:
    """'SUV: behind. Truck: ahead': a key that names a kind of agent not named in the text before it introduces
    one ('a truck is ahead'), so it is never read as a loose second name of an earlier one; the ego, a label
    ('V2', 'Ped_1', 'EV'), a plural or a noun said before stays as written."""
    written, words, entry = _key_words(key)
    name = written.lower()
    if not words or not _names_agent(key) or LABEL_KEY.fullmatch(name) or words[0] in NAMED_BEFORE or \
            (entry is not None and entry[1] == "ego") or "ego" in words or lexicon().base(words[-1])[1] or \
            re.search(r"\d", name) or len(words[-1]) == 1 or written.isupper() and written not in TYPE_ACRONYMS or \
            re.search(rf"\b{re.escape(words[-1])}\b", re.sub(r"\(.*?\)", "", before), re.I):  # not "Ego (truck)"
        return key
    return f"a {key}"


EGO_KEYS = {"ego", "ego vehicle", "ego car", "subject vehicle"}


CELL_BAR = re.compile(r"[ \t]+\|[ \t]+")


def _keyed_agents(text: str) -> str:
    """'Ego: going straight. Van: stopped, front-right.' on one line: each key that names an agent is the
    subject of what follows it ('Van is stopped, front-right.'), when two keys do or the line opens with one;
    other keys are left to the title rule."""
    pieces = re.split(r"(?<=[.;|])\s+|\s+/\s+", text.strip())
    cells = CELL_BAR.search(text) is not None  # "Ego car, go straight | Actor 1: truck ahead, stop": a row's cells,
    # one keyed by an agent enough (the ego's key was read with its value before: "Ego: car" is "Ego car")
    if sum(1 for p in pieces if (m := KEY_LINE.match(p)) and _names_agent(m.group(1))) < 2 - cells and not (
            (m := KEY_LINE.match(pieces[0])) and _names_agent(m.group(1))
            and m.group(1).strip().lower().split()[0] not in TITLE_KEYS) and not any(
            (m := KEY_LINE.match(p)) and m.group(1).strip().lower() in EGO_KEYS for p in pieces):
        return text  # "Ego: a sedan. A van pulls out.", "Event: Harsh Braking. Ego: Ford Transit. Lead vehicle ..."
    out = []
    for k, piece in enumerate(pieces):
        m = KEY_LINE.match(piece)
        if m and _names_agent(m.group(1)) and m.group(2).strip():
            value = m.group(2).strip().rstrip('.;| ')  # (a table's cell ends at its bar)
            out.append(f"{_keyed(_first_named(m.group(1).strip(), ' '.join(pieces[:k])), value)}.")
        else:
            out.append(piece[:-1].rstrip() + ";" if piece.endswith("|") else piece)
    return " ".join(out)


NEWS_SOURCES = (r"(?:the |a |an |local |state |city |county |highway )*(?:police|officials?|witness(?:es)?|investigators?"
                r"|authorities|deputies|officers?|troopers?|sheriff|spokes(?:person|man|woman)|company|operator|firm"
                r"|bystanders?|residents?|parents?|onlookers?|passers ?by|reporters?|regulators?|prosecutors?"
                r"|(?:the )?(?:company|police|city|county|transit|fire) (?:said|spokes(?:person|man|woman)|statement))")
REPORTING = r"(?:said|say|says|told reporters|reported|report|reports|believe|believes|confirmed|confirm|stated|added)"
ATTRIBUTION = re.compile(rf"(?:\baccording to [^.;,!?]*|(?:^|(?<=[,.;:!?] )|(?<=\band )|(?<=\bbut )|(?<=\bas ))(?<!\w){NEWS_SOURCES} {REPORTING}(?: that)?\b)")


def _without_attribution(text: str) -> str:
    """'Police say a patrol car swerved', ', according to a witness who filmed it,': a news report names who
    told it; the teller is no agent of the scene."""
    return ATTRIBUTION.sub(" ", text)


BRACKETED = re.compile(r" ?\(([^()]{1,80})\)")
PLACED_BY = {"behind", "of", "to", "beside", "past", "alongside", "near", "ahead", "following", "passing"}
AT_THE_WHEEL = {"driving", "at the wheel", "behind the wheel", "driver", "drove", "older", "elderly", "young"}


def _agent_kinds(words: list[str]) -> list[str]:
    """The agent types the words name (a make, a model, a noun), longest phrase first."""
    lex, out, k = lexicon(), [], 0
    while k < len(words):
        for n in (3, 2, 1):
            span = words[k:k + n]
            entry = lex.phrases.get(tuple(lex.base(w)[0] for w in span)) or lex.phrases.get(tuple(span))
            if len(span) == n and entry is not None and entry[0] == "agents":
                out.append(entry[1])
                k += n
                break
        else:
            k += 1
    return out


BRACKETED_LABEL = re.compile(r"\s*(?:[a-z]{1,4}|actor|agent|target|object|participant|unit|npc)[ _-]?\d{1,2}\s*")


def _described_in_brackets(text: str) -> str:
    """'the car behind me (gray Ford Escape)', 'a pickup (silver Honda Civic, older gentleman driving)': a
    bracket after an agent that only says its make, colour or who drove it names no second agent."""
    lex = lexicon()

    def drop(m: re.Match) -> str:
        words = re.findall(r"[a-z]+", m.string[max(0, m.start() - 40):m.start()])[-4:]
        if len(words) >= 2 and words[-1] in ("me", "us", "you", "ego") and words[-2] in PLACED_BY:
            words = words[:-2]  # "the car behind me (...)": the bracket is the car's
        before = _agent_kinds(words)
        if BRACKETED_LABEL.fullmatch(m.group(1)):
            return m.group(0)  # "a white SUV (TV1)": the name it goes by after
        inside = re.findall(r"[a-z]+", m.group(1))
        kinds = [k for k in _agent_kinds(inside) if k not in ("pedestrian", "none")]  # the driver may be named
        if not before or before[-1] in ("ego", "none") or not kinds or any(
                k != before[-1] and not (before[-1] == "generic" and k == "car") for k in kinds):
            return m.group(0)
        verbs = [w for w in inside if w not in AT_THE_WHEEL and (lex.phrases.get((lex.base(w)[0],)) or ("",))[0]
                 == "actions"]
        return m.group(0) if verbs else ""

    return BRACKETED.sub(drop, text)
STORY_ROLE = re.compile(r"\bas an? [a-z0-9 /&'-]{1,60}?[,\s]+(?=(?:i|we)\s+(?:want|need|would like|wish)\b)")
TEST_PURPOSE = re.compile(r"[,\s]*\bso(?: that)? (?:(?:we|i|you|the team|engineers|testers) (?:can|could)\b|"
                          r"[a-z' -]{1,40}? (?:can|could) be (?:tested|checked|validated|verified|evaluated|"
                          r"measured|assessed|exercised|demonstrated|confirmed)\b)[^.;!?\n]*")


CORRECTION = re.compile(r"\s*(?:(?:actually|oh|and|also|wait|sorry|no|ok|okay|but|hmm)[, ]+)*(?:please )?"
                        r"(?:change|switch|turn|make|swap|replace) the ([a-z][a-z ]*?) (?:(?:in)?to |for |with )?"
                        r"(?:an?|the) ([a-z][a-z ]*?)(?: instead)?(?: please)?\s*[.!]*\s*")


def _as_corrected(text: str) -> str:
    """A request corrected in the same message ('... an oncoming van. Actually change the van to a pickup.'):
    the earlier mention is the one corrected, and the correction names no agent of its own."""
    for sentence in re.findall(r"[^.!?\n]+[.!?]*", text):
        m = CORRECTION.fullmatch(sentence)
        if m is None or not _agent_kinds(m.group(1).split()) or not _agent_kinds(m.group(2).split()):
            continue
        at = text.find(sentence)
        before = list(re.finditer(rf"\b{re.escape(m.group(1))}\b", text[:at]))
        if before:
            said = before[-1]
            text = text[:said.start()] + m.group(2) + text[said.end():at] + text[at + len(sentence):]
    return text


ASIDES = (  # (pattern, replacement): what a text says around its scene, read for what it is
    (r"\b(?:an? |the |any )?(?:lane[- ]change|overtake|overtaking manoeuvre|overtaking maneuver|swerve|evasive "
     r"(?:manoeuvre|maneuver|lane change))\b[^.;!?]{0,30}? (?:is|was|are|were) not (?:required|needed|necessary|"
     r"expected|wanted)\b", " "),  # "a lane change by the SV is not required": not made
    (r"\blane[- ]chang(?:e|ing) (planner|controller|module|logic|algorithm|policy|stack|behaviou?r|decision|"
     r"decisions|capability|performance|model)\b", r"\1"),  # "evaluates the lane-change planner": no lane change
    (r"\b(?:merge|merging|cut[- ]in|overtaking|braking)[- ](safety|review|team|kpis?|metrics?)\b", r"\1"),  # "for the
    # merge-safety review": what a review is about, no merge
    (r"\b(waiting|queuing|queueing) passengers\b", r"\1 people"),  # "three waiting passengers stand on the
    # pavement": people at the stop, not on board
    (r"\bpassengers(?= (?:are |were )?(?:standing|waiting|queuing|queueing|stand|wait|queue) (?:on|at) the "
     r"(?:pavement|sidewalk|kerb|curb|footway|stop|bus stop)\b)", "people"),
    (r"\b(an? [a-z]+(?: [a-z]+)?) (?:that |which )?(?:it|he|she|they|the officer|the police) "
     r"(?:has |had |have |is )?(?:just )?pulled over\b", r"\1 that has been pulled over"),  # "parked behind a
    # pickup it has pulled over": the pickup stands, pulled over; the patrol car made no lane change
    (r"\b((?:mis)?classif(?:y|ies|ied|ying)|mislabel(?:l?ed|s)?|detect(?:s|ed)?|track(?:s|ed)|"
     r"identif(?:y|ies|ied)|mistook|mistak(?:es|en))\b([^.;!?]{0,60}?) (?:as|for) an? [a-z]+\b", r"\1\2"),
    # "perception classified the jogger as a cyclist": what it was taken for is no one
    (r"(?:^|(?<=[.!?:]\s)|(?<=\bplease\s)|(?<=\bto\s))mine\b(?= (?:[a-z-]+ ){0,2}[a-z-]+s\b)", "collect"),
    # "Please mine highway cut-ins": the verb, not the speaker's
    (r"\bv?\d+(?:\.\d+){2,}\b", " "),  # "CARLA 0.9.14": a release, no sentence ends in it
    (r"(?:^|(?<=[.!?]\s))(?:please )?(?:label|tag|annotate|flag|mark|give) (?:actor|agent|object|track|this clip|"
     r"the clip)\b[^.!?\n]*[.!?]?", " "),  # "Give Actor 2 the emergency attribute.": the annotator's, no scene
    (r"(?<![\w.])\.(xodr|xosc|xml|tsg|py|json|yaml|yml|csv)\b", r"\1"),  # "the .xodr": no sentence ends
    (r"\b(?:leave|keep) (?:the |any |all )?([a-z]+s) out\b(?! of)", r"no \1"),  # "please leave pedestrians out"
    (r"\b(?:leave out|exclude|omit) (?:the |any |all )?([a-z]+s)\b", r"no \1"),
    (r"(?:^|(?<=[.!?]\s))(?:please )?(?:evaluate|assess|measure|verify|describe|discuss|explain)"
     r"\b(?!\s*:)[^.!?:\n]*[.!?:]?", " "),  # "Evaluate the distance at which your vehicle yields.": the task set
    # on the scene, no scene ("Describe what happened: I was ...": a form's question, what follows it the scene)
    (r"\bego[ _]?(?:type|class|kind)\s*(?:==?|:|is)\s*'?([a-z]+)'?", r"the ego is a \1,"),  # a query's "ego_type =
    # 'bus'": what the ego is
)


def _without_asides(text: str) -> str:
    """What a request, a note or a report says around its scene, said as what it is: a manoeuvre no one makes, a
    system named by its manoeuvre, what a road user was taken for, an annotator's instruction, a task set on the
    scene, a release number, a file's extension, road users asked to be left out; and words that read otherwise
    there ('please mine ...', passengers waiting at the stop, a vehicle pulled over by another)."""
    for pattern, replacement in ASIDES:
        text = re.sub(pattern, replacement, text)
    return text


def _without_story_frame(text: str) -> str:
    """A user story's frame says who asks and why, not what happens: 'As a safety engineer I want a scene
    where ... so that we can check the braking' is the scene between the two ('a scene where ...')."""
    framed = STORY_ROLE.sub("", text)
    if framed == text and not re.search(r"\b(?:i|we) (?:want|need|would like)\b", text):
        return text
    return TEST_PURPOSE.sub("", framed)


IDENTIFIER = re.compile(r"\b(?:[A-Za-z][A-Za-z0-9]*_[A-Za-z0-9_]*[A-Za-z0-9]"  # Car_1, Ped_1, moto_front
                        r"|[A-Z][a-z]+(?:[A-Z][a-z0-9]*|[0-9]+)+"  # TargetVehicle, LaneChangeAction, Car1
                        r"|[a-z]+(?:[A-Z][a-z0-9]*)+)\b")  # vehicleCategory, precipitationType
DECLARED = re.compile(r"\b([A-Z][A-Za-z0-9_]*[a-z][A-Za-z0-9_]*) \(\s*(?:[a-z]+Category\s+)?([a-z ]{2,20}?)\s*"
                      r"(?:\)|,)")  # "Lead (car)", "Bike_1 (vehicleCategory bicycle, ...)"; not "VRU (cyclist)"
ROLE_LABEL = re.compile(r"(?:npc|actor|agent|target|obj|object|adversary|vru|v|sv|pov|tv|gvt|veh|vehicle|unit"
                        r"|participant)[ _#]?\d{1,2}")
EMERGENCY_TYPES = {"ambulance", "police", "firetruck"}
ATTRIBUTE_NAMES = re.compile(r"\b[a-z]+Category\b")  # "(vehicleCategory truck)": the type that follows is all


def _identifier_words(name: str) -> list[str]:
    """'FireTruck_1' -> fire, truck, 1; 'LaneChangeAction' -> lane, change, action."""
    return [w.lower() for w in re.findall(r"[A-Z]+(?![a-z])|[A-Z]?[a-z]+|[0-9]+", name)]


def _agent_phrase(words: list[str] | tuple[str, ...]) -> tuple[str, ...] | None:
    """The agent noun an identifier or a declared type ends with ('TargetVehicle' -> vehicle, 'FireTruck' -> fire
    truck, 'motorbike' -> motorbike)."""
    lex = lexicon()
    for n in (2, 1):
        tail = tuple(words[-n:])
        if len(tail) == n and lex.phrases.get(tail, ("", ""))[0] == "agents" and lex.phrases[tail][1] == "none":
            return None  # "RoadRunner": a tool's name, no runner
        if len(tail) == n and lex.phrases.get(tail, ("", ""))[0] == "agents" and \
                lex.phrases[tail][1] not in ("none", "ego"):
            return tail
    return None


MEMBERS_DESCRIBED = re.compile(r",?\s+(?:one|two|three|four|both|all|some|most|\d) of (?:whom|them|which|those)"
                               r"(?:\s+(?:is|are|was|were|being))?\s+(?:an?\s+)?([a-z][a-z' -]{0,40}?)(?:\s*,(?=\s)|(?=\s*[.;:!?)]|$))",
                               re.I)


MEMBERS_PLACED = {"on", "in", "riding", "driving", "at", "from", "to", "into", "behind", "ahead", "beside", "near"}


def _without_members_described(text: str) -> str:
    """'two cyclists, one of whom is a child, ride ...', 'three pedestrians, two of them children,': what some
    of a group are, said in passing, is no agent beside the group; a member that does something or is somewhere
    ('one of which turns left', 'one of them on a scooter') is read as said."""
    def said_of_members(m: re.Match) -> str:
        said = m.group(1).lower().split()
        acts = any(w in _verbs() or lexicon().base(w)[0] in _verbs() for w in said)
        return m.group(0) if acts or said[:1] and said[0] in MEMBERS_PLACED else " "
    return MEMBERS_DESCRIBED.sub(said_of_members, text)


def _scenario_identifiers(text: str) -> str:
    """Scenario engineers name agents as program identifiers ('TargetVehicle', 'Car_1', 'FireTruck_1', or
    'Lead (car)' in an entities list) and re-mention them by that name: each becomes its agent noun carrying the
    name as a label, so every mention is the one agent. A type declared in brackets ('LeadVehicle (bus)') names
    the noun unless the name is the more specific ('FireTruck_1 (truck)'). Other identifiers
    ('LaneChangeAction', 'RelativeDistanceCondition', 'TimeOfDay') read as the words they are made of."""
    if not IDENTIFIER.search(text) and not DECLARED.search(text):
        return text
    text = re.sub(r"\b(Ego|[A-Z][A-Za-z0-9]*_[A-Za-z0-9]+|[A-Z][a-z]+(?:[A-Z][a-z0-9]*)+)-(?=[A-Z])", r"\1 and ",
                  text)  # "RelativeDistanceCondition Ego-StaticTruck": the two, not an ego that is a truck
    nouns: dict[str, tuple[str, ...]] = {}
    for m in DECLARED.finditer(text):
        name = m.group(1)
        declared = _agent_phrase(tuple(_normalize(m.group(2)).split()))
        own = _agent_phrase([w for w in _identifier_words(name) if not w.isdigit()])
        if declared is None or name.lower() in ("ego", "hero") or name in nouns or \
                name.lower() in lexicon().function_words or ROLE_LABEL.fullmatch(name.lower()):
            continue  # the ego, no name ("The (red) car"), or a label read as such ("NPC1 (car)")
        finer = own is not None and lexicon().phrases[own][1] in EMERGENCY_TYPES  # "FireTruck_1 (truck)"
        nouns[name] = own if finer else declared
        end = m.end() - (m.group(0)[-1] == ",")  # what the bracket says besides the type is still read
        text = text[:m.start()] + name + " " * (end - m.start() - len(name) - 1) + "," + text[end:]
    for name in nouns:
        if not IDENTIFIER.fullmatch(name):  # "Lead (car)" ... "Lead brakes": a plain word declared as a name
            text = re.sub(rf"\b{name}\b", f"@{name}@", text)
    text = ATTRIBUTE_NAMES.sub(" ", text)

    def labelled(name: str, phrase: tuple[str, ...]) -> str:
        label = "id" + re.sub(r"[^a-z]", "", name.lower()) + "".join("abcdefghij"[int(d)] for d in
                                                                      re.findall(r"[0-9]", name))
        return " ".join(phrase[:-1] + (f"{phrase[-1]}#{label}",))

    def read(m: re.Match) -> str:
        name = m.group(0)
        if name not in nouns and ROLE_LABEL.fullmatch(name.lower()):
            return name  # "NPC_1", "Actor_2": role labels, read as such where they are said
        words = _identifier_words(name)
        named = [w for w in words if not w.isdigit()]
        if len(named) > 1 and len(named[-1]) == 1 and "_" in name:
            named = named[:-1]  # "NPC_A", "Car_b": a letter for an id
        phrase = nouns.get(name) or (_agent_phrase(named) if named and named[-1] != "ego" else None)
        if phrase is None:  # "AbsoluteTargetSpeed": a keyword, whose agent nouns name no agent
            return " ".join(w for w in words if _agent_phrase([w]) is None)
        if name not in nouns and named[-1].endswith("s") and len(named) > 1:
            return " ".join(words)  # "TrafficVehicles": a group, counted where it is said
        return labelled(name, phrase)

    text = re.sub(r"@([A-Za-z0-9_]+)@", lambda m: labelled(m.group(1), nouns[m.group(1)]), text)
    return IDENTIFIER.sub(read, text)


def _agent_label(m: re.Match) -> str:
    """'bike1', 'moto2': an agent noun with a number joined to it is a name; other words keep their digits."""
    entry = lexicon().phrases.get((lexicon().base(m.group(1))[0],))
    return f"{m.group(1)}#{m.group(2)}" if entry and entry[0] == "agents" and entry[1] not in ("none", "ego") \
        else m.group(0)


EXCLAIMED_AGAIN = re.compile(r"(?:(?<=^)|(?<=[.!?] )|(?<=[.!?]\n)|(?<=, )|(?<=\band ))"
                             r"((?:(?:an?|the|this|that) )?)([a-z]+(?: [a-z]+){0,2})(?:!+ ?|, )"
                             r"(?:(?:an?|the|this|that) )?\2\b")
# "a cyclist! a cyclist coming across", "sirens! sirens!": an exclamation said again is one thing


HANDLE = re.compile(r"(?<![\w.@])@[A-Za-z_][A-Za-z0-9_]*")  # "@WestMidsPolice", not "a@b.com" nor "@ 30 mph"
HASHTAG = re.compile(r"(?<![\w#&])#([A-Za-z][A-Za-z0-9_]*)")  # "#baddriving", not "car #2"
TRAILING_TAGS = re.compile(r"(?:[ \t]*(?:#[A-Za-z][A-Za-z0-9_]+|@[A-Za-z_][A-Za-z0-9_]*)[.,!?]*)+[ \t]*$", re.M)
TAG_WORDS = re.compile(r"[A-Z]?[a-z]+|[A-Z]+(?![a-z])|[0-9]+")


def _weather_tags(m: re.Match) -> str:
    """Of the tags a post ends with, those that name its weather or its light ('#rain', '#night') are said of the
    scene, as a last sentence; the rest ('#dashcam', '#roadrage') file it under a topic."""
    said = []
    for tag in re.findall(r"#([A-Za-z][A-Za-z0-9_]*)", m.group(0)):
        words = tuple(w.lower() for w in TAG_WORDS.findall(tag))
        entry = lexicon().phrases.get(words)
        if entry is not None and entry[0] == "weather":
            said.append(" ".join(words))
    return (" " + ", ".join(said) + ".") if said else ""


MARKDOWN_EMPHASIS = re.compile(r"(\*\*|__)(?=\S)(.+?)(?<=\S)\1")  # "- **Ego vehicle:** Sedan": words, not bold


EMOJI = re.compile(r"[\U0001F000-\U0001FAFF\u2600-\u27BF\u2B00-\u2BFF][\uFE0F\u200D\U0001F3FB-\U0001F3FF"
                   r"\U0001F000-\U0001FAFF\u2600-\u27BF]*")
EMOJI_BETWEEN_WORDS = re.compile(rf"(?<=[A-Za-z0-9)])\s*(?:{EMOJI.pattern})(?:\s*(?:{EMOJI.pattern}))*\s+"
                                 r"(?!(?:and|while|but|as|when|so|because|then|until|before|after)\b)(?=[A-Za-z@#])")


@lru_cache(maxsize=1)
def _symbols() -> tuple[dict[str, str], re.Pattern]:
    words = {symbol: meaning for meaning, phrase in _entries("symbols") for symbol in phrase}
    alternatives = "|".join(re.escape(s) for s in sorted(words, key=len, reverse=True))
    return words, re.compile(rf"(?P<symbol>{alternatives})(?:[\uFE0F\U0001F3FB-\U0001F3FF]|\u200D\S)*")


def _entry_of(lex: Lexicon, words: str) -> tuple[str, str]:
    phrase = tuple(words.lower().split())
    entry = lex.phrases.get(phrase) or (lex.phrases.get((lex.base(phrase[0])[0],)) if len(phrase) == 1 else None)
    return entry or ("", "")


PICTURE_DETERMINERS = {"a", "an", "the", "my", "our", "your", "his", "her", "their", "this", "that", "another",
                       "other", "some", "one", "two", "three", "four", "five", "no", "every", "each"}


def _names_one(lex: Lexicon, before: str, after: str) -> bool:
    """Whether a road user's picture stands where its noun would: after a determiner or a count, perhaps with a
    word that describes it between ('a 🚶 steps', 'a slow 🚛', '2 🚗'), or opening what is said with more to come
    ('🚑 w/ sirens coming up'). Elsewhere it only shows what was said ('no helmet no lights 🚲', 'Think bike! 🏍️
    On Friday ...')."""
    words = re.findall(r"[a-z0-9']+|[^\sa-z0-9']", before.lower())[-2:]
    if not words or words[-1] in ".!?:;":
        return bool(re.match(r"\s*[a-z]", after))
    determiner = [w in PICTURE_DETERMINERS or w.isdigit() for w in words]
    signal = words[0] == "the" and words[-1] in ("red", "amber", "green", "yellow")  # 'against the red 🚒': a light
    return determiner[-1] or len(words) == 2 and determiner[0] and words[1].isalpha() and not signal and \
        _entry_of(lex, words[1])[0] not in ("agents", "road", "weather")


def _symbols_as_words(text: str) -> str:
    """'a 🚶 steps onto the zebra', 'at the 🚦': a picture written for a word is that word (symbols.txt). One
    that follows a word of its own kind only shows it ('2 kids 🚶🚶', 'a jogger 🏃 runs', 'rainy 🌧'), as does a
    road user's picture where no noun could stand (`_names_one`); a picture of the weather, a light or a sign
    stays after its word, so that it still ends what came before it, as any picture between words does."""
    words, symbol = _symbols()
    if not symbol.search(text):
        return text
    lex = lexicon()
    out, at, before = [], 0, ("", "")
    for m in symbol.finditer(text):
        between = text[at:m.start()]
        if between.strip():  # a word or a mark since the last picture: what it shows is that word's
            before = _entry_of(lex, re.findall(r"[A-Za-z']+|\S", between)[-1])
        said = words[m.group("symbol")]
        entry = _entry_of(lex, said)
        shown = entry[0] == before[0] == "agents" or (entry == before and entry[0] != "")
        out.append(between)
        line = text[:m.start()].rsplit("\n", 1)[-1]
        heading = not symbol.sub("", line).strip() and re.match(r"[\W\d_]*[A-Z]", symbol.sub("", text[m.end():]))
        if heading:  # '🚌🛑 Today on SR 50 a trooper ...': pictures before the first word of a line that opens
            out.append(m.group(0))  # with a capital are its banner, not words of it
        elif entry[0] == "sequence":  # "80 → 30 km/h", "lane 2 → lane 1": from one value to the next
            values = re.search(r"\d\s*$", text[:m.start()]) or re.match(r"\s*(?:\d|lane\b)", text[m.end():], re.I)
            out.append(" to " if values else f" {said} ")
        elif entry[0] == "agents":
            named = _names_one(lex, text[:m.start()], text[m.end():]) and not (  # "me and my 👩": kin, on board
                said in ("pedestrian", "child") and re.search(r"\b(?:my|our|his|her|their|the)\s*$", text[:m.start()],
                                                              re.I))
            out.append("" if shown else f" {said} " if named else m.group(0))
        else:
            out.append(m.group(0) if shown else f" {said} {m.group(0)}")
        at, before = m.end(), entry
    return re.sub(r"(?<=\S)  +(?=\S)", " ", "".join(out) + text[at:])


def _emoji_breaks(text: str) -> str:
    """'FSD handled a cut-in like a champ on my commute 🙌 semi in the right lane merged ...': a post's emoji
    between words ends what was said before it, as a full stop does (not before a word that links on: 'in front
    of us 😤 while two pedestrians ...')."""
    if not EMOJI.search(text):
        return text
    return EMOJI_BETWEEN_WORDS.sub(". ", text)


THREAD_NUMBER = re.compile(r"(?:^|(?<=\s))(\d{1,2})/(\d{1,2})?(?=\s)", re.M)


def _without_thread_numbers(text: str) -> str:
    """'1/ Bus-stop overtake ... 2/ The bus halts ...', '1/2 so this van ... 2/2 pouring with rain': a thread's post
    numbers, counting from 1, start its posts; they count no road users ('2/ The bus' is no two buses)."""
    found = THREAD_NUMBER.findall(text)
    if len(found) < 2 or found[0][0] != "1":
        return text
    return THREAD_NUMBER.sub("\n", text)


def _without_social_markup(text: str) -> str:
    """A post's handles ('@WestMidsPolice is it worth reporting') name whom it is addressed to, and the tags it
    ends with ('#cycling #schoolbus') file it under a topic: neither is a road user of the scene, whatever
    words they are made of. A tag inside a sentence ('a #Tesla cut me off') is the word it tags."""
    if "@" not in text and "#" not in text:
        return text
    text = TRAILING_TAGS.sub(_weather_tags, text)
    text = HANDLE.sub(" ", text)
    return HASHTAG.sub(lambda m: " ".join(TAG_WORDS.findall(m.group(1))).lower() if not m.group(1).isupper()
                       else m.group(1), text)


@lru_cache(maxsize=1)
def _tag_key_patterns() -> tuple[tuple[tuple[str, re.Pattern], ...], re.Pattern, re.Pattern]:
    by_meaning: dict[str, list[str]] = {}
    for meaning, words in _entries("tag_keys"):
        by_meaning.setdefault(meaning, []).append(r"[\s_-]*".join(map(re.escape, words)))
    keys = {meaning: "|".join(sorted(alternatives, key=len, reverse=True))
            for meaning, alternatives in by_meaning.items()}
    counts = tuple((meaning.split()[-1], re.compile(rf"(?<![\w=])(?:{alternatives})\s*[=:]\s*(\d+|[a-z]+)"
                                                    rf"(?=\s*(?:[,|;/#]|$))", re.I | re.M))
                   for meaning, alternatives in keys.items() if meaning.startswith("count "))
    label = re.compile(rf"(?<![\w=])({keys['label']})\s*=\s*(?=\S)", re.I)
    piped_label = re.compile(rf"(?<![\w=])({keys['label']})[ \t]*:[ \t]*(?=[^\s|])", re.I)
    return counts, label, piped_label


RECORD_SEPARATORS = (re.compile(r"\s*\|\|\s*"), re.compile(r"\s*;;\s*"), re.compile(r"\s*\}\s*\{\s*"),
                     re.compile(r"\s+\|\s+"), re.compile(r"\s*;\s*"))
FIELD_KEY = re.compile(r"^([A-Za-z][A-Za-z0-9 _#'-]{0,24}?)\s*(?::|=|->|\||\s[-\u2013\u2014]\s)\s*(?=\S)")
SPACED_TAG = re.compile(r"\s+(?=[A-Za-z][A-Za-z0-9_]*=)")
INNER_SEPARATORS = re.compile(r"\s+[/|]\s+|\s+[-\u2013\u2014]\s+|(?<=[a-z0-9]):(?=[a-z])|(?<=[a-z]{3})/(?=[a-z]{3})")
# ("ambulance/turn_left", "car:from opposite road:straight"; not "km/h", "a1/a2")


def _records_of_agents(fields: list[str]) -> bool:
    """Two fields or more keyed by an agent ('EGO:', 'NPC1:', 'a1='), one of them not the ego's with more than one
    thing said of it ('cyclist / from left road / straight'): a record per agent, not a list of tags ('ego: car |
    weather: fog')."""
    keyed = [(m.group(1), field[m.end():]) for field in fields if (m := FIELD_KEY.match(field))]
    agents = [(key, value) for key, value in keyed if key.lower().split()[0] == "ego" or _names_agent(key) or
              re.fullmatch(r"[a-z]{1,6}[ _#-]?\d{1,2}", key.lower())]  # ("a1", "npc_2", "veh1")
    return len(agents) >= 2 and any(key.lower().split()[0] != "ego" and len(re.split(r",|" + INNER_SEPARATORS.pattern,
                                                                                     value)) >= 2
                                    for key, value in agents)


def one_line_records(text: str) -> str:
    """'EGO: bus / turn right || NPC1: cyclist / from left road / straight', '{ego: bus, straight} {npc: car, ...}',
    'ego=car:turn_right; a1=car:from opposite road:straight', 'ego_type=truck npc_1=police,behind,straight': a
    record of keyed fields typed on one line reads as the same fields a line each ('NPC1: cyclist, from left road,
    straight'), the keys an ego is named by ('ego_type', 'ego_manoeuvre') one line."""
    line = text.strip().strip("{}").strip()
    if "\n" in line or len(line) > 600:
        return text
    if line.count(" / ") >= 2 and "||" not in line and sum(":" in part or part.count(",") >= 2
                                                           for part in line.split(" / ")) >= 2:
        return line.replace(" / ", "\n")  # "id,class,lane / ego,car,2 / lv1,truck,ahead", "SUT: sedan / POV: lorry":
        # lines pasted onto one, a slash between them
    fields: list[str] = []
    for separator in RECORD_SEPARATORS:
        pieces = [p.strip(" {}") for p in separator.split(line) if p.strip(" {}")]
        if len(pieces) >= 2 and all(len(p.split()) <= 16 for p in pieces) and _records_of_agents(pieces):
            fields = pieces
            break
    if not fields and len(SPACED_TAG.findall(" " + line)) >= 3 and FIELD_KEY.match(line) and \
            not re.search(r",\s*[A-Za-z][A-Za-z0-9_]*=", line) and _records_of_agents(SPACED_TAG.split(line)):
        fields = SPACED_TAG.split(line)  # "ego_type=truck ego_manoeuvre=straight npc_1=police,behind,straight" (tags
        # with commas between, "ego=truck, lead=bus", are read as tags)
    if not fields:
        return text
    lines: list[tuple[str, str]] = []
    for field in fields:
        m = FIELD_KEY.match(field)
        if m is None:
            lines.append(("", field))
            continue
        key = m.group(1).replace("_", " ").strip()
        value = re.sub(r"\s*\(([^()]*)\)", r", \1", field[m.end():])  # "van (straight)", "car(turn_left)"
        value = ", ".join(p for p in INNER_SEPARATORS.split(value) if p.strip())
        value = re.sub(r"\s*,\s*", ", ", value)
        if lines and key.lower().split()[0] == "ego" and lines[-1][0].lower().split()[:1] == ["ego"]:
            lines[-1] = ("Ego", lines[-1][1] + ", " + value)  # "ego_type=truck ego_manoeuvre=straight": one ego
            continue
        lines.append(("Ego" if key.lower().split()[0] == "ego" and len(key.split()) == 2 and
                      key.lower().split()[1] in ("type", "vehicle", "manoeuvre", "maneuver", "action") else key, value))
    return "\n".join(f"{key}: {value}" if key else value for key, value in lines)


def _without_tag_keys(text: str) -> str:
    """A scene typed as key=value tags ('ego=truck, lanes=2', 'weather: fog | lanes: 3') names each thing by its
    key: the pair reads as the tag it stands for ('the ego truck', '2 lanes'), not as a sentence the colon ends
    or a word glued to an '='."""
    if "=" not in text and ":" not in text:
        return text
    counts, label, piped_label = _tag_key_patterns()
    for noun, count in counts:
        text = count.sub(lambda m: f"{m.group(1)} {noun}", text)
    text = label.sub(lambda m: f"{m.group(1)} ", text)
    # 'Weather: fog' heading a line of a catalogue ends its sentence as well; between pipes it is one tag of many
    return "\n".join(piped_label.sub(lambda m: f"{m.group(1)} ", line) if "|" in line else line
                      for line in text.split("\n"))


LONGEST_SENTENCE = 100  # tokens; the corpus's longest sentence has 71. A run-on text ends a sentence at its next
# comma past this, or at twice this, so that what is read per sentence stays bounded


CAB_OWNER = {"his": "him", "her": "her", "my": "me", "our": "us"}  # whose lorry's cab, said by its driver
COMPASS_BOUND = {"n": "northbound", "s": "southbound", "e": "eastbound", "w": "westbound"}


COMMENT_MARK = re.compile(r"^[ \t]*(?:#+|//+)(?=[ \t]|$)[ \t]?")  # not "* ", "- ": a list's bullets


def _comment_block(text: str) -> str:
    """A scene told in a code comment ('# Ego is stopped at a red light; a fire engine from\n# the opposite
    direction turns left'), or in a docstring's quotes: the comment marks taken off and its wrapped lines
    joined, a blank comment line still parting paragraphs."""
    unquoted = re.sub(r'^\s*(?:"""|\'\'\')|(?:"""|\'\'\')\s*$', "", text.strip())
    lines = [line for line in unquoted.splitlines() if line.strip()]
    if len(lines) < 2 or not (unquoted != text.strip() or all(COMMENT_MARK.match(line) for line in lines)):
        return text
    text = unquoted
    out = [COMMENT_MARK.sub("", line).strip() for line in text.splitlines()]
    return "\n\n".join(" ".join(p.split("\n")) for p in "\n".join(out).split("\n\n")).strip()


CODE_SPAN = re.compile(r"`[^`\n]*[().=<>/\[\]{}][^`\n]*`")  # "`vehicle.apply_control()`": code quoted, no scene
CAMEL_CASE = re.compile(r"\b[a-z]{2,}(?:[A-Z][a-z0-9]*)+\b")  # "I tried changeLane via TraCI", "lcSpeedGain": an
# identifier of code, no words of the scene (not "vType passenger": its one letter names what follows)


AGENT_COMPOUND = re.compile(r"\b(?:peds?|pedestrians?|cyclists?|bikes?|cars?|vehicles?|trucks?|bus|buses|"
                            r"motorcycles?)-(safety|detection|following|friendly|free|heavy|related|focused|centric|"
                            r"based|avoidance|aware|awareness|yielding|collision|crash|protection)\b")

PERCEIVED = re.compile(r"\b(?:peds?|pedestrians?|cyclists?|cars?|vehicles?|trucks?|bus|buses|motorcycles?|"
                       r"motorbikes?|vrus?)\s(tracks?|track ids?|detections?|detector|tracker|bounding boxes|"
                       r"labels?|classifier|hypothes[ie]s)\b")  # what perception makes of road users


DEVICE_SWITCH = re.compile(r"\bturn(?:s|ed|ing)? (?:(on|off) )?((?:the |your |its |his |her |my |our )?"
                           r"(?:fog|rain|snow|head ?lights?|lights|wipers|hazards|hazard lights|high beams?|engine|"
                           r"ignition|radio|indicator|blinker))(?(1)| (?:on|off))\b")


SCENE_MARKER = re.compile(r"(?<=[.:)])\s+(?:an?\s+)?(?:illustrating\s+|example\s+|the\s+|illustrative\s+)?"
                          r"(?:scene|scenario)\s*:\s*(?=\S)", re.I)
RULE_WORDS = re.compile(r"\b(?:rule|handbook|highway code|law|means|must|may|should|shall)\b", re.I)


def rule_before_its_scene(text: str) -> str:
    """'Rule 227: in wet weather, stopping distances ... double. Illustrating scene: heavy rain ...': a rule of the
    road stated before the scene that illustrates it is no part of the scene; only what follows 'Scene:' is."""
    m = SCENE_MARKER.search(text)
    if m is None or not RULE_WORDS.search(text[:m.start()]):
        return text
    return text[m.end():]


RESTATED = re.compile(r"(?:^|(?<=[.!?]\s))(?:(?:ok|okay|right|so)[ ,]+)?(?:the |so the |this is the |here is the |"
                      r"here's the )?(?:(?:whole|full|complete|entire) (?:thing|scene|scenario|setup|set up|picture)"
                      r"|so|everything together|all together)\s*:\s*", re.I)


def _restated(text: str) -> str:
    """'and also add a scooter. the whole thing: ego car turns right ...': a chat message that says a change and
    then the whole scene again; the scene is what follows the last such 'whole thing:', with the weather the change
    asked for ('make it foggy at dawn. So: ...')."""
    found = list(RESTATED.finditer(text))
    if not found or found[-1].end() == len(text):
        return text
    words = re.findall(r"[a-z]+", text[:found[-1].start()].lower())
    phrases = lexicon().phrases
    weather = [" ".join(words[k:k + n]) for n in (3, 2, 1) for k in range(len(words) - n + 1)
               if phrases.get(tuple(words[k:k + n]), ("",))[0] == "weather"]
    said = [w for w in weather if not any(w != other and w in other for other in weather)]
    return (f"Weather: {', '.join(said)}. " if said else "") + text[found[-1].end():]


PROPER_NAME = re.compile(r"(?<=[a-z0-9,;] )([A-Z][a-z]{3,})\b")  # "near Kegworth": a place, not a Kenworth


INVERTED_VERBS = r"(drives|goes|turns|changes|continues|waits|enters|accelerates|brakes|starts|pulls|moves)"
VERB_FIRST = re.compile(r"((?:\bthen\s+|(?:^|[.!?;]\s*)(?:after that|afterwards|now|next|finally)\s+,?\s*|"
                        r"(?:^|[.!?;]\s*)(?:when|once|after|as soon as)\b[^.!?;,]{1,80},\s*(?:then\s+)?))"
                        + INVERTED_VERBS + r"\s+(the\s+ego(?:\s+car|\s+vehicle)?)\b"
                        r"(?!'s|\s+(?:lane|lanes|path|route|car's|vehicle's)\b)", re.M)
# "when the bus has passed, then drives the ego in", "after that changes the ego lane to the right": the verb put
# first, as in Swedish, German or Dutch, with the ego after it as its subject


BUS_STOPPING = re.compile(r"(^|[,.;:!?]\s*|\b(?:a|the|then|and|when|once|as|while|school|city)\s)bus stops "
                          r"(?=(?:at|for|to|in|behind|ahead|suddenly|abruptly|sharply|dead|short|right|just|outside|"
                          r"beside|next|and)\b|[,.;]|$)", re.M)  # a bus that stops, said after what opens a clause


ACCELERATION = re.compile(r"\b\d+(?:\.\d+)?\s*(?:m\s?/\s?s(?:\^?2|\u00b2|\s?/\s?s)|(?:metres|meters) per second "
                          r"(?:squared|per second))")
METRES_PER_SECOND = re.compile(r"\b(\d{1,3}(?:\.\d+)?)\s*(?:m\s?/\s?s|ms\^?-1|metres per second|meters per second)\b")
VERB_THEN = re.compile(r"\b(makes?|made|making|does|did|turns?|turned|changes?|changed) then "
                       r"(?=(?:a|an|the|left|right|lanes?)\b)")
PLACE_THEN_SUBJECT = re.compile(
    r"(^|[.;!?,]\s*|\band\s+|\bwhile\s+)((?:in front of|behind|ahead of|beside|next to|alongside|"
    r"to the (?:left|right) of|(?:to|on) (?:its|my|our|his|her|their|the ego's) (?:left|right))"
    r"(?: (?:the ego|me|us|it|him|her|them|the (?!wheel\b)[a-z]+))?)"
    r" (is|was|are|were) ((?:(?:a|an|the|one|two|three|another)\s+)?[a-z]+"
    r"(?:\s+(?!and\b|which\b|that\b|who\b|with\b)[a-z]+){0,3}?)"
    r"(?=\s*(?:[,.;!?]|$|\band\b|\bwhich\b|\bthat\b|\bwho\b|\bwith\b))")  # a place said before its subject
MOVERS_PLACE = (r"(?:in front of|behind|ahead of|beside|next to|alongside|from behind|from the (?:left|right)|"
                r"from (?:my|our|its|his|her) (?:left|right)|from the opposite (?:direction|side))"
                r"(?: (?:the ego|me|us|it|him|her|them))?")
MOVERS_VERB = r"(?:drove|drives|came|comes|stood|stands|sat|sits|rode|rides|ran|runs|was driving|was coming)"
MOVER = (r"((?:a|an|the|one|two|three|another)\s+[a-z]+(?:\s+(?!and\b|which\b|that\b|who\b|with\b)[a-z]+){0,3}?)"
         r"(?=\s*(?:[,.;!?]|$|\band\b|\bwhich\b|\bthat\b|\bwho\b|\bwith\b))")
PLACE_VERB_MOVER = re.compile(rf"(^|[.;!?,]\s*|\band\s+|\bwhile\s+|\bthen\s+)({MOVERS_PLACE}) ({MOVERS_VERB}) {MOVER}")
VERB_PLACE_MOVER = re.compile(rf"(^|[.;!?,]\s*|\band\s+|\bwhile\s+|\bthen\s+)({MOVERS_VERB}) ({MOVERS_PLACE}) {MOVER}")
# "behind me drove a police car", "then came from the right a scooter": a place, and the verb of one moving or
# standing, said before the one who does it (as in German, Dutch, Russian)
OWN_VEHICLE_MOVED = re.compile(
    r"\b(i|we|you) ((?:mov|eas|nos|edg|guid)(?:e|es|ed|ing)|(?:pull|steer|inch|roll)(?:s|es|ed|ing)?|swung|"
    r"swing(?:s|ing)?|drove|drive[sn]?|driving) (the|my|our|your) ((?:[a-z-]+ )?(?:car|truck|van|bus|lorry|rig|semi|motorbike|bike|"
    r"motorcycle|cab|taxi|coach|minibus|pickup|suv|hatchback|sedan|tractor|artic|hgv|tanker|jeep|estate|saloon|plow|"
    r"plough|ambulance|cruiser|shuttle|moped|scooter|vehicle|wagon))\s+(?=(?:over|across|out|into|onto|in|to|left|"
    r"right|back|through|round|around|up|off|forward|towards|toward|alongside|along|down|straight)\b)")
OWNED_BY = {"i": "my", "we": "our", "you": "your"}
ONLY_THEN_DID = re.compile(r"\bonly (?:(after|once|when) ([^.;!?]*?),?|then) did ((?:the |my |our |his |her )?[a-z]+) "
                           r"(?=[a-z])")
LOGGED_SPEED = re.compile(r"\bv\s?=\s?(\d{1,3}(?:\.\d+)?)(?!\s*(?:km|kph|mph|m\s?/|ms\b|[./]?\d))")  # "v=12"


HELD = re.compile(r"\b(?:stops|stopped|halts|halted|waits|waited|full stop|comes to a stop|came to a stop|comes to a "
                  r"halt|came to a halt|gives way|gave way|yields|yielded|is stationary|was stationary|is held|was "
                  r"held)\b")
RESUMED = re.compile(r"(^|[.;!?]\s+)((?:t=[\d.]+ s:?\s+)?)(the ego|ego|the av|the test car|i|we|subject|the subject)"
                     r"\s+(?:then\s+)?(?=(?:drives on|drove on|moves off|moved off|pulls away|pulled away|sets off|set off|proceeds|"
                     r"proceeded|continues|continued|carries on|carried on|moves on|moved on|goes on|went on|drives off|"
                     r"drove off)\b)", re.M)


def _resumed(text: str) -> str:
    """'... the ego brakes and stops; the pedestrian finishes crossing; the ego drives on': after a halt, the ego
    going on in a sentence of its own is the next stage, as if 'then' were said."""
    held = HELD.search(text)
    if held is None:
        return text
    return text[:held.end()] + RESUMED.sub(r"\1\2then \3 ", text[held.end():])


def tokenize(text: str) -> list[Token]:
    """Text -> tokens with base forms; commas (and brackets) stay as ',' tokens, for clause boundaries;
    the sentence number advances at . ; ! ? : and blank lines."""
    lex = lexicon()
    text = MARKDOWN_EMPHASIS.sub(r"\2", CAMEL_CASE.sub(" ", CODE_SPAN.sub(" ", _restated(_comment_block(text)))))
    text = _without_members_described(
        _scenario_identifiers(_lines(_screenplay(_without_services_asked(_without_tag_keys(_without_social_markup(
            _emoji_breaks(_symbols_as_words(_without_thread_numbers(text))))))))))
    text = LETTER_LABEL.sub(r"\1#\2", text)  # "Car A", "Actor B": a diagram's or a catalogue's names
    text = re.sub(r"\b([NSEW])B\b(?!:)", lambda m: COMPASS_BOUND[m.group(1).lower()], text)  # a log's "WB": westbound
    names = {w.lower() for w in PROPER_NAME.findall(text)}  # never read as a slip of a known word
    text = fold_letters(text.lower().replace("\u2019", "'").replace("`", "'"))
    text = _respectively(_without_calques(_hinglish(text)))
    text = re.sub(r"\(([^()]{1,60}?),\s*((?:the )?(?:ego|ego vehicle|ego car|subject vehicle|sv|vut))\s*\)", r"(\2, \1)",
                  text)  # "Vehicle 1 (silver hatchback, ego)": its role first, as "(ego, silver hatchback)"
    text = AGENT_COMPOUND.sub(r"\1", text)  # "the ped-safety task", "a car-following model": no one on the road
    text = PERCEIVED.sub(r"\1", text)  # "keep three separate pedestrian tracks": a tracker's, no one on the road
    text = DEVICE_SWITCH.sub(r"\2", text)  # "turn fog on in the simulator", "turn your headlights on": no turn
    text = re.sub(r"\b(oncoming|opposing|an?|the) through (?=(?:car|vehicle|motorcycle|motorbike|truck|bus|cyclist|van|"
                  r"sedan|suv|pickup|lorry)s?\b)", r"\1 ", text)  # "an opposing through motorcycle": going on
    text = re.sub(r"\blet (him|her|them|it) (in|merge|over|out)( in)? (?:ahead of|in front of) (?:me|us)\b",
                  r"let \1 \2\3", text)  # "braked and let him in ahead of me": where it goes, once let in
    text = BUS_STOPPING.sub(r"\1bus comes to a stop ", text)  # "bus stops at bus stop": the bus stops, no bus stops
    text = re.sub(r"\b([nsew])/b\b", lambda m: COMPASS_BOUND[m.group(1)], text)  # a report's "N/B": northbound
    text = re.sub(r"\b(in|wearing|wears|wore|sporting) (a|an|his|her|their) (?:[a-z0-9'-]+ ){1,2}(jersey|shirt|t-shirt|"
                  r"tee|hoodie|cap|beanie|jacket|raincoat|anorak|scarf|sweater|sweatshirt|jumper|vest|tracksuit)\b",
                  r"\1 \2 \3", text)  # "this guy in a Leafs jersey": what one wears, no Leaf or Harley on the road
    text = re.sub(r"\b(?:brakes|braked|braking|brake|decelerates|decelerated|decelerating)(?:\s+hard)?\s+(?:at|with\s+a\s+"
                  r"(?:constant\s+|uniform\s+|steady\s+)?deceleration\s+of)\s+(?=" + ACCELERATION.pattern + ")",
                  "slows down at ", text)  # "brakes at 7 m/s²": a rate of slowing in a word problem, no halt said
    text = ACCELERATION.sub(" ", text)  # "accelerating at 2.5 m/s²": how fast speed changes, no place or speed
    text = re.sub(r"\b(going|travell?ing|driving|riding|sitting|was|were|are|am|is|been) in (car|van|taxi)\b"
                  r"(?!\s*(?:\d|#|park|parks|wash|lot)\b)", r"\1 in my \2", text)  # "we was going in car": the
    # teller's own car, no second one
    text = re.sub(r"\b(in|on|driving|riding) one of (our|my|the company's|the firm's|the depot's) ([a-z]+?)(?:e?s)\b",
                  r"\1 \2 \3", text)  # "heading north in one of our HGVs": in our HGV
    text = re.sub(r"\b(guy|man|woman|lady|bloke|dude|lad|fella|chap|idiot|driver|person|someone|somebody)((?: [a-z]+)"
                  r"{0,4}), ((?:in|on) (?:an?|the|his|her|their) [a-z]+(?: [a-z]+)?),", r"\1\2 \3",
                  text)  # "the guy from the left, in a pickup, he just goes": the guy in the pickup
    text = re.sub(r"\b(?:\d{1,2}|four|six|eight|ten|twelve)[- ]wheel(?:ed)? (?=[a-z])", "", text)  # "an 8-wheel tipper
    # lorry": how many wheels, no count
    text = re.sub(r"\b(?:leaves|leave|leaving|exits|exit|exited|exiting) (?:at|by|via|through) the "
                  r"(first|second|third) exit\b", r"takes the \1 exit", text)  # "leaves at the first exit": the
    # exit is its manoeuvre
    text = re.sub(r"\bno,? there (is|are|was|were) (?:any |an? )?", r"there \1 no ", text)  # "No there is any
    # intersection here": there is none
    text = re.sub(r"\b(the|my|our|his|her|their) (?:year \d{1,2} )?twins\b", r"\1 two children",
                  text)  # "the Year 3 twins": two children
    text = re.sub(r"\b(the|a|an|my|our|this|that) \d{1,2}[.:][0-5]\d (?=(?:[a-z]+ )?(?:bus|coach|service|shuttle|"
                  r"minibus)\b)", r"\1 ", text)  # "the 8.15 school bus": the bus of that time, one bus
    text = re.sub(r"\broute (?:(\d+) )?(bus|coach)\b", lambda m: f"number {m.group(1)} {m.group(2)}" if m.group(1)
                  else m.group(2), text)  # "the ego is a route 7 bus": the bus of that service
    text = re.sub(r"(?<![\w.+])\+(\d+(?:\.\d+)?)(?:\s*(?:s|sec|secs|seconds)\b)?(?!\s*(?:km|kph|mph|m\b|metres|meters|"
                  r"ft|feet|%|lanes?\b|[.\d]))", r"t=\1 s", text)  # "+2.1 car stationary behind subject": a log line's
    # offset in seconds
    text = re.sub(r"\bt\s?=\s?(\d+(?:\.\d+)?)(?![\d.]|\s*(?:s|sec|secs|seconds)\b)", r"t=\1 s",
                  text)  # "t=3.5 car from the right turns": a log's time stamp in seconds, no count of cars
    text = LOGGED_SPEED.sub(r"at \1 m/s", text)  # "t=0.0 ego lane 2 v=12": a log's speed, in SI units
    text = METRES_PER_SECOND.sub(lambda m: f"{round(float(m.group(1)) * 3.6)} km/h", text)  # "at 22 m/s": a speed
    text = re.sub(r"\b(\d+(?:\.\d+)?)t\b", r"\1 tonne", text)  # "a 44t artic": its weight, no count
    text = re.sub(r"\b(\d)\s?\+(?=[- ]?lanes?\b)", r"\1", text)  # "a 3+ lane highway": at least three lanes
    text = re.sub(r"\blane (\d) of (\d)\b(?! lanes?\b)", r"lane \1 of \2 lanes", text)  # "Lane 2 of 3": one of three
    text = re.sub(r"\b(walks?|walked|walking|pushe?s?|pushed|pushing|wheels?|wheeled|wheeling) (his|her|their|a|the) "
                  r"(dog|pram|stroller|buggy|pushchair|trolley|cart) (across|over) (the|a) (road|street|crossing|zebra|"
                  r"crosswalk)\b", r"\1 \4 \5 \6 with \2 \3", text)  # "walks his dog across the road": he crosses
    text = re.sub(r"\bthe (?:extra|additional) (?=[a-z]+\b)", "another ", text)  # "and the extra car following
    # behind us": one more, not one named before
    text = re.sub(r"\b((?:street|road|side road|side street|avenue|lane) (?:that |which )?)(the ego|i|we|you) "
                  r"((?:is |am |are |was |were )?(?:turning|turns|turned|turn)) (left|right) (into|onto)\b",
                  r"\1\2 \3 \5, while \2 \3 \4", text)  # "into the same street the ego is turning left into":
    # the street the ego turns into, and the ego's turn
    text = re.sub(r"\b((?:road|street|side road|side street|avenue) )where ((?:i|we|you|the ego|ego) )"
                  r"(turn(?:s|ed|ing)?|enter(?:s|ed|ing)?)\b(?! (?:into|onto|in)\b)", lambda m: m.group(1) + m.group(2) + m.group(3) +
                  (" into" if m.group(3).startswith("turn") else ""), text)  # "on the road where I turn is standing
    # truck": the road turned into
    text = OWN_VEHICLE_MOVED.sub(lambda m: f"{m.group(1)}, in {OWNED_BY[m.group(1)]} {m.group(4)}, {m.group(2)} ",
                                 text)  # "I moved the truck over a lane to the left": the teller in their own
    # truck moves over (never the semi named before)
    text = re.sub(r"\b(it|that|there|he|she|what|who)'s (been|got|gotten|gone|had)\b", r"\1 has \2", text)
    text = re.sub(r"\b(it|that|he|she|who)'s (\w+ed)(?= (?:over |up |out |off )?(?:a|an|the|my|our|his|her|their|us|me)\b)",
                  r"\1 has \2", text)  # "it's pulled over a pickup", "he's blocked the lane": has, not is
    text = re.sub(r"\b(it|that|there|he|she|what|who|here|where)'s\b", r"\1 is", text)
    text = re.sub(r"\blet's\b", "let us", text)
    text = VERB_FIRST.sub(lambda m: f"{m.group(1)}{m.group(3)} {m.group(2)}", text)
    text = VERB_THEN.sub(r"then \1 ", text)  # "makes then a lane change" ("macht dann"): then makes it
    text = PLACE_THEN_SUBJECT.sub(lambda m: f"{m.group(1)}{m.group(4)} {m.group(3)} {m.group(2)}", text)
    # "in front of the ego is a stopped van": a stopped van is in front of the ego
    text = PLACE_VERB_MOVER.sub(lambda m: f"{m.group(1)}{m.group(4)} {m.group(3)} {m.group(2)}", text)
    text = VERB_PLACE_MOVER.sub(lambda m: f"{m.group(1)}{m.group(4)} {m.group(2)} {m.group(3)}", text)
    text = re.sub(r"(,|\band|\bso)\s+(had to|needed to|have to)\s+"
                  r"(?=[a-z' ]{0,30}\bmy (?:brakes?|horn|anchors|steering)\b)", r"\1 i \2 ", text)
    # "a bus came on from the right, had to stand on my brakes": an obligation with no subject, by the speaker's
    # own brakes, is the speaker's
    text = ONLY_THEN_DID.sub(lambda m: (f"{m.group(1)} {m.group(2)}, " if m.group(1) else "then ") + m.group(3) + " ",
                             text)  # "only after the cyclist had cleared did the ego turn": after it, the ego turns
    text = _without_attribution(text)
    text = re.sub(r"n't\b", " not", text).replace("can not", "cannot")
    text = re.sub(r"\b([a-z]+) (?:down|along|up|through) the ((?:left|right|middle|outside|inside|fast|slow|overtaking)"
                  r"(?:-hand| hand)? lane) past (me|us|the ego|ego)\b", r"\1 past \3 in the \2",
                  text)  # "came down the right lane past me": it passed me in that lane
    text = re.sub(r"\b(was|were) not ([a-z]+ing)\b([^.;!?]*?)\b(?:and )?(?:neither|nor) (?:was|were) "
                  r"((?:the|a|an|that|this|my|our) [a-z' ]+?)(?=\s*[.,;!?]|$)",
                  r"\1 not \2\3 and \4 \1 not \2", text)  # "I wasn't moving and neither was the car behind
    # me": the car behind was not moving either
    text = re.sub(r"'re\b", " are", text)
    text = re.sub(r"'ll\b", " will", text)
    text = re.sub(r"'ve\b", " have", text)
    text = re.sub(r"'m\b", " am", text)
    text = re.sub(r"'d (?=(?:already |just |never |not |finally )?(?:\w+(?<!e)ed|been|gone|got|gotten|done|seen|"
                  r"taken|driven|left|come through|ridden|run|made|pulled)\b)", " had ", text)  # "once he'd cleared",
    # "we'd already stopped": a past told in the past ("I'd need", "he'd stop": would)
    text = re.sub(r"'d\b", " would", text)
    text = re.sub(r"\b(lanes?(?: \w+)?), ((?:on|to) (?:its|his|her|their|our|my) (?:left|right)),", r"\1 \2",
                  text)  # "moves from lane 2 to lane 3, on its right, to clear the lane": the side of that lane
    text = re.sub(r"\bincl\.?(?=\s)", "including", text)  # a tester's notes: "3 cars incl. ego" (no sentence end)
    text = re.sub(r"\bapprox\.?(?=\s)", "about", text)
    text = re.sub(r"\b(footage|video|recording|clip|cctv|images?)\s+(?:is |was |has been |been )?(?:held|kept|retained|"
                  r"saved|secured|obtained|seized)\b", r"\1 on file", text)  # "footage held on dashcam": no one held
    if re.search(r"\b(?:hgvs?|lorry|lorries|artics?|articulated|semis?|tractor units?|wagon|big rig|18 wheeler)\b",
                 text) and not re.search(r"\b(?:taxis?|cabbie|minicab|(?:a|an|another)(?: [a-z]+)? cab)\b", text):
        text = re.sub(r"\b(ahead of|in front of|the front of|across|past|alongside|beside|behind) (his|her|my|our) cab\b"
                      r"(?! (?:driver|rank|office|firm|company))",
                      lambda m: f"{m.group(1)} {CAB_OWNER[m.group(2)]}", text)  # "darted in ahead of his cab": of him
    text = re.sub(r"(^|[.;!?\n]\s*)opposite (direction|side) from\b", r"\1from the opposite \2", text)  # "Opposite
    # direction from one lorry coming": a sentence opened word for word from another language
    text = re.sub(r"\b(before|until|till) (?:a|any|some|another|one of the|one of our) (?:child|kid|person|pedestrian|"
                  r"cyclist|rider|driver|one|body|pupil|student|old person|toddler)\s+(?:gets|is|will be|has been) (?:hurt|"
                  r"killed|injured|hit|run over|knocked down|badly hurt|seriously hurt)\b",
                  r"\1 someone gets hurt", text)  # "review this before a child gets hurt": one feared, not in the scene
    text = re.sub(r"\b(shouts?|abuse|cheers?|stares?|comments?|waves?|a wave|a shout|a thumbs up|jeers?|banter|grief|"
                  r"stick) from (?:the|some|a few|a couple of|a load of) (?:lads|guys|blokes|boys|crew|workers|men|team|"
                  r"gang|onlookers|locals|regulars)\b", r"\1", text)  # "got a few shouts from the lads": heard, no one on
    # the road
    text = re.sub(r"\bon (a|my|the|her|his|their|our) (?:bird|lime|voi|tier|dott)(?: scooter)?\b", r"on \1 scooter",
                  text)  # "me on a Bird turning left": a hired scooter by its operator's name
    text = re.sub(r"\b((?:around|round|past) (?:it|him|her|them|the [a-z]+)) (?:into|onto|through|via) the (?:oncoming|opposing)"
                  r" lane\b", r"\1", text)  # "went around it into the oncoming lane": round it, on the side one
    # passes on
    text = re.sub(r"\b(revers(?:e|es|ed|ing)|back(?:s|ed|ing)? up|roll(?:s|ed|ing)? back)( slowly| quickly)? (?:back )?"
                  r"(?:towards|toward|at) (?:me|us|the ego|my car|our car)\b", r"\1\2", text)  # "the lorry in front was
    # reversing towards me": backing up where it is, not coming the other way
    text = _resumed(text)
    text = re.sub(r"(?<!its )(?<!his )(?<!her )(?<!their )\b((?:junction|intersection|crossroad|crossing|traffic light|"
                  r"traffic signal|crosswalk|zebra|roundabout|stop sign|road marking|marking)s?) (?:not have|not has|no have|not there|not exist|not exists|"
                  r"there is not|there isn't|is not there)\b", r"no \1", text)  # "crossroad not have", "traffic
    # light there is not": the thing's absence, said in another language's order
    text = re.sub(r",\s*after (them|him|her|it),? ((?:one|a|an|another|two|three|some) [a-z]+(?: [a-z]+)?)"
                  r"(?=(?: also| too| as well)?\s*(?:[.,;!?]|$))", r", behind \1 \2", text)  # "two car, after them one
    # motorcycle also": a list's next one, following them
    text = re.sub(r"(^|[.;!?\n]\s*)(?:coming|approaching|arriving|driving|travelling|traveling|riding|walking)\s+"
                  r"(from [a-z' ]{1,40}):", r"\1\2:", text, flags=re.M)  # "Coming from opposite: two car": a key of
    # where those listed after it come from, as "From the left: a cyclist"
    text = re.sub(r"\bnot (?:even )?once\b", "never", text, flags=re.I)  # "not once looking our way": no "once" link
    text = re.sub(r"\b(?:adult|elderly|young|teenage|older) (male|female)\b(?= (?:riding|cycling|pedalling|pedaling|"
                  r"on an? (?:[a-z]+ )?(?:bike|bicycle|pushbike|scooter|moped|motorbike|motorcycle)))",
                  lambda m: "man" if m.group(1) == "male" else "woman", text)  # "adult male riding a mountain bike":
    # a rider, told as a report tells of people
    text = re.sub(r"\b[lp][- ](plates?)\b", r"\1", text)  # "a car with L plates": a learner's, no side
    text = re.sub(r"\bred[- ]light runner(s?)\b", r"light runner\1", text)  # "a red-light runner": a vehicle that
    # runs the red, no signal or runner on foot of its own
    text = re.sub(r"\b(?:single|double|solo|triple)[- ]?crewed\b ?", "", text)  # "I was single-crewed in a marked
    # police vehicle": how many rode in it, no more
    text = re.sub(r",\s*(?:then\s+)?aged\s+(\d{1,2})\s*,", lambda m: ", a child," if int(m.group(1)) < 18 else ",",
                  text)  # "the respondent, then aged 12, stepped off the pavement": a child then, no later stage
    text = re.sub(r"\b(son|daughter|wife|husband|partner|brother|sister|mum|mom|dad|friend|kid|boy|girl)\s*\("
                  r"(?:a |the )?learner(?: driver)?\)", r"\1", text)  # "my son (learner) was driving": who he is,
    # no learner car of his own
    text = re.sub(r"\b(it was|it's|it is)( clearly| definitely| obviously)? (?:my|our|your|his|her|their) "
                  r"turn\b(?! (?:left|right|into|onto|off))", r"\1\2 fine", text)  # "it was clearly my turn" (to go at
    # a four-way stop): whose go it was, no manoeuvre
    text = re.sub(r",? (?:like|as if|as though) (?:we|i|you|he|she|they|it|the ego)(?:'d| had)? (?:were|was|are|is|"
                  r"been) (?:standing still|stood still|parked|stationary|stopped|not moving|going backwards?)\b",
                  "", text)  # "went past like we were standing still": how fast it went, no halt of ours
    text = re.sub(r"\bcust\.?(?=\s)", "customer", text)  # a job card's "Cust. reports car was stopped"
    text = re.sub(r"\b(the (?:road|street|side road|lane)) (?:that |which )?(?:i|we|you|he|she|they|the car|"
                  r"the ego(?: vehicle| car)?|the (?:vut|sut|av|sv|host vehicle|subject vehicle|test vehicle))"
                  r"(?:'re|'m| are| am| is| was| were)? (?:(?:going|goes|go|turning(?: left| right)?|turns?"
                  r"(?: left| right)?|turned(?: left| right)?|heading|heads) (?:into|onto)|(?:joining|joins|entering|"
                  r"enters)(?: into| onto)?)\b",
                  r"\1 it turns into", text)  # "in the road you're going into", "crossing the road she turns
    # right into", "in the road the car is joining": where the ego goes, said by a relative clause
    text = re.sub(r"\btl(s?)\b", r"traffic light\1", text)  # "stopped at a red TL", "when the TL goes green"
    text = re.sub(r"\bu[\s-]*turn(s|ed|ing)?\b", "uturn", text)  # not "you turn"
    text = re.sub(r"\b(?:can|could|would|will)\s+(?:you|u)\s+(?:please\s+|pls\s+|plz\s+)?(?=(?:make|create|build|"
                  r"generate|give|show|simulate|set|write|do|add|put|design|produce|model|mock|spin|whip|knock|"
                  r"throw|come up|code|script|draft|prepare|include)\b)", " ", text)  # the addressee, not the ego
    text = re.sub(r"\b(?:i|we)\s+(?:want|need|would like|'d like)\s+(?:you|u)\s+to\b", " ", text)
    text = re.sub(r"\b(?:can|could|shall|should|let)\s+(?:we|us)\s+(?:please\s+|maybe\s+|also\s+)?(?=(?:show|see|have|"
                  r"get|make|create|build|add|include|simulate|test|try|put|set up|model|demo|do)\b"
                  r"(?!\s+(?:it|this|that|them|these|those)\b))", " ", text)
    # "can we show the car turning left?": the team asking, not the ego
    text = _without_story_frame(text)
    text = _without_asides(_as_corrected(text))
    text = re.sub(r"\b(?:one|two|three|some) of (?:them|those|these)[ ,]+(?:no|wait|sorry|i mean|no wait|actually)"
                  r"[ ,]+((?:both|all|two|three|four) of (?:them|those|these))\b", r"\1", text)
    # "one of them no both of them start walking": speech corrects itself, the last word stands
    text = re.sub(r"\b[abn]\d{2,4}\b", "road", text)  # "the A38", "on the B1234": a road, no count
    text = re.sub(r"\bm\d{2,3}\b|\b(?<=the )m\d\b", "motorway", text)  # "the M6", "on the M25"
    text = re.sub(r"\blv\b", "lead vehicle", text)  # "LV decelerates": the lead vehicle
    text = re.sub(r"\br\d{1,4}\b", " ", text)  # "R18 - T-junction": a run number, not a side
    text = re.sub(r"^\s*(?!(?:us|sr|cr|ca|fm|rt|rte|hwy|i|m|a|b|n|e|r|k|v)-)[a-z]{1,5}[-_]\d{1,5}\b", " case ",
                  text)  # "SC-07 Emergency vehicle approach ...": an identifier opening the text heads a case
    text = re.sub(r"\b(?!(?:us|sr|cr|ca|fm|rt|rte|hwy|i|m|a|b|n|e|r|k)-)[a-z]{2,5}-\d{1,5}\b", " ",
                  text)  # "SC-07", "REQ-104", "TC-3": a document's identifier, no count (not "I-95", "SR-99")
    text = re.sub(r"\b(?:v|ver|version)\s?\d+(?:\.\d+)+[a-z]?\b", " ", text)  # "FSD v12.5", "version 4.2.1": a
    # software version, no vehicle (V1, "vehicle 1" stay labels)
    text = re.sub(r"\b(\d{1,2})(?:st|nd|rd|th)\b",
                  lambda m: ORDINAL_WORDS.get(m.group(1), m.group(0)), text)  # "the 2nd car": the second
    text = re.sub(r"\b(l|r) to (l|r)\b", lambda m: " to ".join("left" if x == "l" else "right" for x in m.groups()),
                  text)  # "crossing L to R"
    text = re.sub(r"\b(turn\w*|lane|chang\w*|from|to|on|go|goes|going|went|merg\w*|mov\w*|swerv\w*|veer\w*|"
                  r"hard|unprotected|protected|pull\w*|cut\w*|head\w*|bear\w*|exit\w*|filter\w*|ego|sidewalk|"
                  r"pavement|shoulder|kerb|curb|side|lanes?|ahead|behind|front|rear|back|our|my|his|her|its|their) "
                  r"(l|r)\b(?![#\d])",
                  lambda m: f"{m.group(1)} {'left' if m.group(2) == 'l' else 'right'}", text)  # "changed lane L"
    text = re.sub(r"\b(l|r) (lane|turn|side|kerb|curb|arm|road)\b",
                  lambda m: f"{'left' if m.group(1) == 'l' else 'right'} {m.group(2)}", text)  # "R kerb", "L lane"
    text = re.sub(r"km\s*/\s*h|kmph|kph", " kmh ", text)
    text = re.sub(r"\bmiles? (?:an|a|per) hour\b", "mph", text)  # "a twenty mile an hour limit", as said aloud
    text = re.sub(r",?\s*after (?:a (?:reaction|thinking|perception[- ]reaction) time of|reacting for|a delay of) "
                  r"[\d.]+ ?s(?:ec(?:ond)?s?)?\b,?", " ", text)  # "notices it and, after a reaction time of 1.2 s,
    # moves over": a problem's timing, between a verb and its subject's next one
    text = re.sub(r"(^|[.!?]\s+)right (into|onto|through|across) (?=(?:my|me|our|us|his|her|him|its|their|them|the "
                  r"(?:back|rear|side))\b)", r"\1\2 ", text)  # "Bam. Right into my rear bumper.": said hard, no turn
    text = re.sub(r"\b(on|to|in|into|at|off|from|down|past) me (left|right|nearside|offside|inside|outside|lane)\b",
                  r"\1 my \2", text)  # "a bus in the bus lane on me left": my, as said in much of Britain and Ireland
    text = re.sub(r"\b(on|the) way back(?= (?:from|to|home|into|after)\b)", r"\1 way home", text)  # "on the way back
    # from the zoo": a journey, no place behind
    text = re.sub(r"\b(?:on|at|along|near) the (?:left|right|near|far|outer|inner) (?:edge|border|margin|rim) of the "
                  r"(?:road|street|lane|carriageway|roadway)\b", " ", text)  # riding at the road's edge: its own lane
    text = re.sub(r"\b([ap])\.\s?m\.?(?=\s|$|[,;!?)])", r"\1m", text)  # "after 10 p.m. and": no sentence end
    text = re.sub(r"\b\d{1,2}/\d{1,2}(?:/\d{2,4})?\b", " ", text)  # "on 6/14", "2/9/24": a date, no time or count
    text = re.sub(r"\b(\d{1,2}):(\d{2})\b", r"\1 \2", text)  # a clock time, not a sentence end
    text = re.sub(r"\s[-\u2013\u2014]+\s|[\u2013\u2014]", " , ", text)  # a dash between words is a pause
    text = re.sub(r"\b4\s?x\s?4s?\b", "four by four", text)  # "a 4x4"
    text = re.sub(r"(\d)(kmh|mph|m|s|km|metres|meters|seconds)\b", r"\1 \2", text)
    text = re.sub(r"\bcross-roads?\b", "crossroads", text)  # the junction, not "cross road"
    text = re.sub(r"(?<=[a-z0-9])-(?=[a-z0-9])", " ", text)
    text = re.sub(r"\n\s*\n", " . ", text)
    text = re.sub(r"s' ", "s's ", text)  # "the infants' school": a plural's possessive
    text = re.sub(r"(^|[.!?]\s+)(dude|man|bro|mate|guys|dude|lol|omg|ok|okay|well|yeah)\s*,\s*", r"\1", text)  # "dude, a cop..."
    text = EXCLAIMED_AGAIN.sub(r"\1\2", text)  # "a cyclist! a cyclist coming across ...": one cyclist, said twice
    text = re.sub(r"\bcouple\b(?! of)", "couple of people", text)  # "a couple were crossing": two people
    text = re.sub(r",? or (?:maybe|possibly|perhaps|probably) (?:an?|the|some) [a-z ]+?(?=[,.;!?]|$)", "",
                  text)  # "a truck, or maybe a van,": one agent, not an alternative as well
    text = re.sub(r"\b(left|right) hand\b", r"\1", text)  # "the right-hand lane"
    text = re.sub(r"\b(that|this|its|our|their) (left|right) lane", r"the \2 lane", text)
    text = re.sub(r"(\d)\s*%\s*(?:of\s+(?:the\s+)?(?:[a-z]+\s+)?(?:width|length|overlap)\b)?", r"\1 percent ", text)
    # "at 25% of the vehicle width": an offset, no count of vehicles
    text = re.sub(r"\bm/(?:cycle|c|bike)s?\b(?= +[a-z]|\))", "motorcycle", text)  # a police log's 'm/c', 'm/cycle'
    text = re.sub(r"\bt ?\+ ?\d+(?:\.\d+)? ?s?\b", " ", text)  # "T+4: UUT at standstill": a time line's stamp
    text = re.sub(r"\b(follow(?:s|ed)?) (it|him|her|them) (?:round|around|through)\b", r"\1 \2 and did the same",
                  text)  # "a police car followed it round": behind it, the way it went
    text = text.replace("+", " and ").replace("&", " and ").replace("w/o", "without").replace("w/", "with ")
    text = re.sub(r"\b(v\d|vehicle \d|unit \d) \(([^()]*)\)", r"\1 , \2 ,", text)  # "vehicle 1 (the AV)": apposition
    text = re.sub(r"\bthe subject (is|was|will be) (a|an) ", r"the ego \1 \2 ", text)  # "the subject is a bus": the
    # vehicle a brief is about
    text = re.sub(r"\b((?:insured|claimant|subject|host|third party|other|target) vehicle) \([a-z]{2,3}\)", r"\1",
                  text)  # "Insured vehicle (IV), a 2018 Toyota Camry,": its short name, said once
    text = re.sub(r"\b(?:a|an|the)\s+((?:[\w-]+\s+){0,3}?[\w-]+)\s*[-\u2013\u2014(,]\s*(?:we'?ll|we will|let'?s|"
                  r"i'?ll|i will)\s+call\s+(?:it|him|her|this one)\s+(?:the\s+)?(?:subject vehicle|subject|"
                  r"ego vehicle|ego|sv|vut|hero)\s*[-\u2013\u2014),]", r"the ego, a \1,", text)  # "A dark sedan - we'll
    # call it the subject vehicle - enters frame": the one named the ego
    text = re.sub(r" \((?:the |= ?)?(?:ego|hero|vut|sut|ego vehicle)\)", " ego", text)  # "the ALKS vehicle (ego)"
    text = re.sub(r" \((?:an? |the )?(?:npc|adversary|actor|agent|target|nonplayer|background)[ _#]?[a-z0-9]{0,3}"
                  r"(?:, [^()]*)?\)", "", text)  # "a bus (NPC1)", "fire engine (NPC, sirens on)": a role tag
    text = _described_in_brackets(text)
    text = re.sub(r"\bwe (were|are|was) ((?:two|three|four|five|six|\d) (?:cars|vehicles))\b", r"\2 including us \1",
                  text)  # "we were three cars stopped at the light": the ego one of them
    text = re.sub(r"\b((?:two|three|four|five|six|seven|eight|\d) [a-z]+s) ?, ((?:the |our |my )?(?:ego|hero)(?: car| vehicle)?)"
                  r" (?=[a-z]+ing\b)", r"\1 including \2 ,", text)  # "three cars, the ego bringing up the rear,"
    text = re.sub(r"\b([a-z]+) right (into|onto) (?=(?:the |my |our |his |her |its |their )?(?:back|rear|side|front|bumper)"
                  r"\b(?! road| street| turning| lane| entrance)|(?:me|us|him|her|it|them)\b)",
                  lambda m: m.group(0) if m.group(1) in TURNING_WORDS else f"{m.group(1)} {m.group(2)} ",
                  text)  # "rolled right into the back of me": no side ("turns right into the side road": its turn)
    text = re.sub(r" \((?:all |both )?(?:children|kids|pedestrians|people|adults|cars|vehicles|cyclists|pupils)\)",
                  "", text)  # "ped_1, ped_2, ped_3 (children)": what the listed ones are
    text = re.sub(r"\?\s+(?:whatever (?:it'?s|they'?re|that'?s) called|or whatever|or something|whatever you call "
                  r"(?:it|them))\b,?", ",", text)  # "a fire engine, sorry, fire truck? whatever its called, stopped
    # on the hard shoulder": a word wondered about, the sentence goes on
    text = re.sub(r"\s*=\s*", " is ", text)  # "Actor_1 = wheelchair user", "ego=car"
    text = re.sub(r"\b(\d{1,2})\s?x\b", r"\1", text)  # "2x pedestrians"
    text = re.sub(r" \(([a-z]{2,6}[a-z0-9]?)\)", r" , \1 ,", text)  # "a pedestrian target (EPTa)": its short name
    text = re.sub(r"\b(vehicle|car|agent|actor|road user|party|vru|target|pov|sv|ego|npc|adversary|hero)"
                  r" \((?:an? |the )?([a-z ]{2,30})"
                  r"((?:, [^()]*)?)\)", r"\1 , a \2 \3 ,", text)  # "third-party vehicle (silver hatchback)": what it is
    text = re.sub(r"\b(witness(?:es)?) (?:w ?)?\d\b", r"\1", text)  # "Witness W1 states": a statement's number
    text = re.sub(r"\b(?:vehicle|veh|unit) (\d)\b(?![.,]\d)(?! (?:km|mph|kph|m\b|metres|meters|seconds|s\b|lanes?))",
                  r"v\1", text)  # "vehicle 1 (the AV)", "Unit 2": police-report labels, as V1 and V2
    text = re.sub(r"\b(npc|actor|agent|target|obj|object|adversary|vru|ped|car|truck|bus|bike|veh|pov|sv|tv|"
                  r"pedestrian|walker|cyclist|van|lorry|motorcycle|motorbike|person)[ _-](\d)\b(?![.,]\d)"
                  r"(?! (?:km|mph|kph|m\b|metres|meters|seconds|s\b|lanes?|cars?))", r"\1\2",
                  text)  # "NPC_1", "Actor 2", "Walker 2" (a simulator's names)
    text = re.sub(r"\b(in|for|until|till) v\d{1,2}(?:\.\d{1,2})?\b", r"\1 this version", text)  # "left out in v1": a release
    text = re.sub(r"\b(?:l|level\s?)[2-5](?=\s+(?:automated\s+|autonomous\s+)?(?:vehicle|car|shuttle|truck|bus|taxi|"
                  r"robotaxi|av)s?\b)", "automated", text)  # "the L4 vehicle": its automation level, no label
    text = re.sub(r"\b([a-z]{1,3}|npc|actor|agent|target|object|adversary)(\d)\b", r"\1#\2", text)  # SV1, NPC2: labels
    text = re.sub(r"\b([a-z]{4,12})(\d{1,2})\b", _agent_label, text)  # "bike1", "lorry2": a table's names
    tokens: list[Token] = []
    sentence = 0
    raw = TOKEN.findall(text)
    asks, current = set(), 0
    for word in raw:  # which sentences are questions
        if word in SENTENCE_ENDS:
            if word == "?":
                asks.add(current)
            current += 1
    sentence_of_raw, current = [], 0
    for word in raw:
        sentence_of_raw.append(current)
        if word in SENTENCE_ENDS:
            current += 1
    titled = {sentence_of_raw[k] for k, w in enumerate(raw) if w == "\u00a7"}
    said = 0  # tokens in the sentence so far
    mark = ""  # the mark that ended the last sentence
    for position, word in enumerate(raw):
        question = sentence_of_raw[position] in asks
        if word == "\u00a7":
            continue
        if word in SENTENCE_ENDS or said >= LONGEST_SENTENCE and word == "," or said >= 2 * LONGEST_SENTENCE:
            if tokens and tokens[-1].sentence == sentence:
                sentence += 1
                said = 0
                mark = word if word in SENTENCE_ENDS else ""
            if word in SENTENCE_ENDS or word == ",":
                continue
        said += 1
        if word in "()":
            word = ","
        possessive = False
        if word.endswith("'s"):
            word, possessive = word[:-2], True
            if not word:
                continue
        label = ""
        if "#" in word:
            word, label = word.split("#")[0], word.replace("#", "")
        known = word in lex.spelling or lex.base(word)[0] in lex.vocabulary
        for part in (lex.spelling.get(word) or (None if known else _run_together(lex, word)) or word).split():
            base, inflected = lex.base(part)
            misspelt = ""
            if base not in lex.vocabulary and part.isalpha() and part not in names:
                guess = _corrected(lex, part)
                if guess is not None:  # "pedestrain", "interesection", "turing": read as the word meant
                    misspelt, part = part, guess
                    base, inflected = lex.base(part)
            plural = inflected and (part.endswith("s") or part in lex.irregular) and not part.endswith("ss") \
                and part not in ("is", "was", "has", "does", "goes", "bus", "police", "mrs", "ms")
            tokens.append(Token(part, base, len(tokens), sentence, plural, possessive, label, question,
                                sentence_of_raw[position] in titled, misspelt, mark))
    return tokens


def matches(tokens: list[Token], start: int = 0, stop: int | None = None) -> list[Match]:
    """The longest lexicon phrase at each place, left to right; tokens no phrase covers are left out."""
    lex = lexicon()
    stop = len(tokens) if stop is None else stop
    out, i = [], start
    while i < stop:
        found = None
        longest = max(lex.starts.get(tokens[i].word, 0), lex.starts.get(tokens[i].base, 0))
        if tokens[i].word != "," and longest:
            for n in range(min(longest, stop - i), 0, -1):
                span = tokens[i:i + n]
                if any(t.word == "," or t.sentence != span[0].sentence for t in span) or \
                        any(t.label for t in span[:-1]):  # "Bus_1 stops" is no "bus stops": a name ends its phrase
                    continue
                entry = _lookup(lex, span)
                if entry is not None and entry[0] == "road" and span[-1].word in SIGNAL_COLOURS and \
                        i + n < len(tokens) and tokens[i + n].sentence == span[0].sentence and (
                            _names_an_agent(lex, tokens[i + n]) or tokens[i + n].word.isalpha() and
                            tokens[i + n].base not in lex.vocabulary and not tokens[i + n].misspelt):
                    continue  # "the red car", "a green bus": the vehicle's colour; "by the Red Lion": a name
                if entry is not None:
                    found = Match(i, i + n, entry[0], entry[1], " ".join(t.word for t in span))
                    break
        if found:
            out.append(found)
            i = found.end
        else:
            i += 1
    return out


SIGNAL_COLOURS = {"red", "green", "amber", "yellow", "orange"}  # the colours a traffic light shows


def _names_an_agent(lex: Lexicon, token: Token) -> bool:
    """The word is a noun of an agent ('car', 'buses'), not one that names none."""
    entry = lex.phrases.get((token.word,)) or lex.phrases.get((token.base,))
    return entry is not None and entry[0] == "agents" and entry[1] != "none"


def _lookup(lex: Lexicon, span: list[Token]):
    """The entry of a phrase written with each word as written or in its base form ("dashed white lines")."""
    keys = [()]
    for t in span:
        forms = (t.word, t.base) + ((t.word + "'s",) if t.possessive else ())  # "from the driver's left"
        keys = [k + (w,) for k in keys for w in dict.fromkeys(forms)]
        if len(keys) > 16:
            keys = keys[:16]
    raw = keys[0]
    for key in keys:
        entry = lex.phrases.get(key)
        if entry is not None and (key == raw or entry[1] != "none") and not (
                entry[0] == "road" and key[0] != raw[0] and raw[0].endswith(("ed", "ing"))) and not (
                entry[0] == "agents" and any(k != w and w.endswith("ed") for k, w in zip(key, raw))):
            return entry  # "the bus stops" is no "bus stop"; "stopped on the road" is no STOP on the road; "the
            # lane assist jerked my vehicle" names no jerk
    return None
