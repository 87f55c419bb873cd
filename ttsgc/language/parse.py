""".tsg text -> Scenario, with every error of a file reported at once.

The lark grammar (grammar/scenario.lark) gives the structure; one Transformer pass classifies the words by
the vocabulary and builds the model; `find_problems` then applies the semantic rules, whose field paths are
mapped back to the tokens they came from. A syntax error stops the semantic pass (its guesses would mislead),
but the parse is retried with the offending line blanked so that the syntax errors of every line are shown.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from lark import Lark, Token, Transformer, v_args
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, VisitError

from ttsgc import vocabulary as V
from ttsgc.language.diagnostics import Diagnostic, ScenarioError
from ttsgc.numbers import NumberError, parse_float, parse_int
from ttsgc.scenario import Agent, Comment, RoadSpec, Scenario, Speed, Stage, Trigger, Weather, find_problems

MAX_SYNTAX_ERRORS = 20
MAX_FILE_BYTES = 1 << 20


class _CommentSink:
    """Collects COMMENT tokens during one parse (lark reports ignored tokens only through callbacks)."""

    def __init__(self) -> None:
        self.tokens: list[Token] = []

    def __call__(self, token: Token) -> Token:
        self.tokens.append(token)
        return token


_COMMENTS = _CommentSink()


@functools.cache
def grammar_parser() -> Lark:
    from ttsgc.grammars import lalr_parser  # the analysis cached on disk

    return lalr_parser("scenario.lark", propagate_positions=True, maybe_placeholders=False,
                       lexer_callbacks={"COMMENT": _COMMENTS})


def parse_file(path: str | Path) -> Scenario:
    """Read and parse a .tsg file; unreadable or non-UTF-8 files are a ScenarioError like any other."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise ScenarioError([Diagnostic(1, 1, f"cannot read the file: {exc.strerror or exc}", file=str(path))]) from None
    if len(data) > MAX_FILE_BYTES:
        raise ScenarioError([Diagnostic(1, 1, f"the file is {len(data)} bytes; a scenario is at most "
                                              f"{MAX_FILE_BYTES} bytes", file=str(path))])
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        column = exc.start - (data.rfind(b"\n", 0, exc.start) + 1) + 1
        raise ScenarioError([Diagnostic(line, column, "the file is not UTF-8 text", file=str(path))]) from None
    return parse(text, str(path))


def parse(text: str, file: str = "<input>", repair=None) -> Scenario:
    """Parse scenario text; raises ScenarioError with all diagnostics when it is not a valid scenario.
    `repair` (Scenario -> Scenario) may mend the unchecked model before the semantic rules run: a front end
    that reads scenes written by a model passes its plan inference here."""
    text = text.removeprefix("\ufeff")
    tree, comments, syntax = _parse_tree(text, file)
    if syntax:
        raise ScenarioError(syntax, text)
    builder = _Builder(file)
    try:
        draft = builder.transform(tree)
    except VisitError as exc:  # a bug in a transformer method, not in the input
        raise exc.orig_exc from exc
    scenario = Scenario.model_construct(**draft.fields, comments=_anchor_comments(builder.statements, comments))
    if repair is not None and not builder.diagnostics:
        scenario = repair(scenario)
    diagnostics = list(builder.diagnostics)
    for problem in find_problems(scenario):
        if problem.path not in builder.suppressed:
            diagnostics.append(builder.locate(problem.path, problem.message))
    if diagnostics:
        raise ScenarioError(diagnostics, text)
    return Scenario.model_validate(scenario.model_dump() | {"comments": scenario.comments})


def _parse_tree(text: str, file: str):
    """Parse to a tree; on syntax errors, blank the offending line and retry to find the next one."""
    lines = text.split("\n")
    diagnostics: list[Diagnostic] = []
    while True:
        _COMMENTS.tokens = []
        try:
            tree = grammar_parser().parse("\n".join(lines))
            return tree, list(_COMMENTS.tokens), diagnostics
        except UnexpectedInput as exc:
            diagnostics.append(_syntax_diagnostic(exc, lines, file))
            line = diagnostics[-1].line
            at_end = isinstance(exc, UnexpectedEOF) or getattr(getattr(exc, "token", None), "type", "") == "$END"
            if (at_end or len(diagnostics) >= MAX_SYNTAX_ERRORS or not 1 <= line <= len(lines)
                    or "{" in lines[line - 1] or "}" in lines[line - 1] or not lines[line - 1].strip()):
                return None, [], diagnostics
            lines[line - 1] = ""


def _describe_terminal(name: str) -> str:
    names = {"WORD": "a word", "INT": "a whole number", "NUMBER": "a number", "STRING": 'a quoted name ("...")',
             "_NL": "the end of the line", "$END": "the end of the file",
             "SPEED_UNIT": "a speed unit (km/h, m/s or mph)"}
    if name in names:
        return names[name]
    try:
        pattern = grammar_parser().get_terminal(name).pattern
    except KeyError:
        return name
    return f"'{pattern.value}'"


def _syntax_diagnostic(exc: UnexpectedInput, lines: list[str], file: str) -> Diagnostic:
    line, column = max(1, exc.line), max(1, exc.column)
    if isinstance(exc, UnexpectedCharacters):
        char = lines[line - 1][column - 1] if line <= len(lines) and column <= len(lines[line - 1]) else "?"
        return Diagnostic(line, column, f"unexpected character {char!r}", file=file)
    expected = sorted(getattr(exc, "expected", None) or getattr(exc, "accepts", None) or [])
    if len(expected) > 1:  # 'or a new line' is true almost everywhere and helps nobody
        expected = [name for name in expected if name != "_NL"]
    wanted = [_describe_terminal(name) for name in expected]
    wanted_text = wanted[0] if len(wanted) == 1 else "one of " + ", ".join(wanted)
    token = getattr(exc, "token", None)
    if token is None or token.type == "$END":
        last = len(lines)
        while last > 1 and not lines[last - 1].strip():
            last -= 1
        closing = " (is a '}' missing?)" if "RBRACE" in expected else ""
        return Diagnostic(last, len(lines[last - 1]) + 1, f"unexpected end of file; expected {wanted_text}{closing}",
                          file=file)
    found = "end of line" if token.type == "_NL" else f"'{token}'"
    if token.type == "_NL":
        line, column = token.line, token.column
    message = f"unexpected {found}; expected {wanted_text}"
    keywords = [k.strip("'") for k in wanted if k.startswith("'")]
    if token.type == "WORD" and keywords:
        suggestions = V.nearest(str(token), keywords)
        if suggestions:
            message += f"; did you mean {V.either(suggestions)}?"
    return Diagnostic(line, column, message, width=max(1, len(str(token).rstrip())), file=file)


@dataclass
class _Draft:
    fields: dict[str, Any]


@dataclass
class _AgentDraft:
    agent: Agent
    tokens: dict[Any, Token]
    suppressed: set[str]  # fields the parser already reported on


@dataclass
class _Clause:
    kind: str
    value: Any
    token: Token
    extra: dict[str, Any] = field(default_factory=dict)


@v_args(meta=True)
class _Builder(Transformer):
    """One pass over the tree: words classified by the vocabulary, the model assembled, tokens remembered."""

    def __init__(self, file: str):
        super().__init__()
        self.file = file
        self.diagnostics: list[Diagnostic] = []
        self.where: dict[tuple, Token] = {}
        self.suppressed: set[tuple] = set()
        self.statements: list[tuple[int, str]] = []  # (line, comment anchor)
        self._stages_seen = 0

    # -- reporting ---------------------------------------------------------------------------------------
    def error(self, token: Token, message: str) -> None:
        self.diagnostics.append(Diagnostic(token.line, token.column, message, width=len(str(token)), file=self.file))

    def locate(self, path: tuple, message: str) -> Diagnostic:
        for n in range(len(path), 0, -1):
            token = self.where.get(path[:n])
            if token is not None:
                return Diagnostic(token.line, token.column, message, width=len(str(token)), file=self.file)
        return Diagnostic(1, 1, message, file=self.file)

    def number(self, token: Token, placeholder: float, integer: bool = False):
        """A number through the one bounded reader; one unreadable is reported here and stands in as an
        in-range placeholder, so the range rules do not report it a second time."""
        try:
            return (parse_int if integer else parse_float)(str(token), None, None)
        except NumberError as exc:
            self.error(token, f"unusable number: {exc}")
            return placeholder

    # -- header ------------------------------------------------------------------------------------------
    def scenario_line(self, meta, children):
        self.statements.append((meta.line, "scenario"))
        token = children[0]
        self.where[("name",)] = token
        return ("name", token.value[1:-1], token)

    def weather(self, meta, children):
        self.statements.append((meta.line, "weather"))
        condition = time = None
        for token in children:
            word = str(token)
            if word in V.WEATHER_CONDITIONS or word in V.TIMES_OF_DAY:
                slot = "condition" if word in V.WEATHER_CONDITIONS else "time"
                if (condition if slot == "condition" else time) is not None:
                    self.error(token, f"a second {'weather condition' if slot == 'condition' else 'time of day'} "
                                      f"'{word}'; give one of each")
                elif slot == "condition":
                    condition = token
                else:
                    time = token
            else:
                self.error(token, _unknown_word(word, "weather condition or time of day",
                                                list(V.WEATHER_CONDITIONS) + list(V.TIMES_OF_DAY)))
        if not children:
            self.diagnostics.append(Diagnostic(meta.line, meta.column, "weather needs a condition and/or a time of "
                                               "day, e.g. 'weather mid_rain night'", width=7, file=self.file))
        if condition is not None:
            self.where[("weather", "condition")] = condition
        if time is not None:
            self.where[("weather", "time")] = time
        weather = Weather.model_construct(condition=str(condition or V.DEFAULT_CONDITION),
                                          time=str(time or V.DEFAULT_TIME))
        return ("weather", weather, children[0] if children else None)

    def seed(self, meta, children):
        self.statements.append((meta.line, "seed"))
        self.where[("seed",)] = children[0]
        return ("seed", self.number(children[0], 0, integer=True), children[0])

    # -- road --------------------------------------------------------------------------------------------
    def lanes(self, meta, children):
        self.statements.append((meta.line, "road.lanes"))
        return ("lanes", self.number(children[0], V.LANES_RANGE[0], integer=True), children[0])

    def at_junction(self, meta, children):
        self.statements.append((meta.line, "road.junction"))
        return ("junction", True, None)

    def not_at_junction(self, meta, children):
        self.statements.append((meta.line, "road.junction"))
        return ("junction", False, None)

    def has(self, meta, children):
        self.statements.append((meta.line, "road.has"))
        return ("has", children, None)

    def without(self, meta, children):
        self.statements.append((meta.line, "road.without"))
        return ("without", children, None)

    def road(self, meta, children):
        self.statements.append((meta.line, "road"))
        *items, rbrace = children
        self.statements.append((rbrace.line, "road.end"))
        fields: dict[str, Any] = {"required_signals": [], "without_signals": [], "required_objects": [],
                                  "without_objects": []}
        for kind, value, token in items:
            if kind in ("lanes", "junction"):
                if kind in fields:
                    self.error(token or rbrace, f"'{kind}' is given twice in the road block")
                fields[kind] = value
                if token is not None:
                    self.where[("road", kind)] = token
                continue
            prefix = "required" if kind == "has" else "without"
            for word_token in value:
                word = str(word_token)
                group = "signals" if word in V.SIGNALS else "objects" if V.is_object(word) else None
                if group is None:
                    self.error(word_token, _unknown_word(word, "signal or road object",
                                                         list(V.SIGNALS) + V.object_words()))
                    continue
                listed = fields[f"{prefix}_{group}"]
                if word in listed:
                    continue
                self.where[("road", f"{prefix}_{group}", len(listed))] = word_token
                listed.append(word)
        fields = {k: tuple(v) if isinstance(v, list) else v for k, v in fields.items()}
        return ("road", RoadSpec.model_construct(**{**RoadSpec().model_dump(), **fields}), None)

    # -- agents ------------------------------------------------------------------------------------------
    def position(self, meta, c):
        return _Clause("relative_to_ego", str(c[0]), c[0])

    def road_type(self, meta, c):
        return _Clause("road_type", str(c[0]), c[0])

    def behind(self, meta, c):
        return _Clause("behind", str(c[0]), c[0])

    def order(self, meta, c):
        return _Clause("order", self.number(c[0], V.ORDER_RANGE[0], integer=True), c[0])

    def gap(self, meta, c):
        return _Clause("gap_m", self.number(c[0], V.GAP_RANGE_M[0]), c[0])

    def speed(self, meta, c):
        return _Clause("speed", Speed.model_construct(value=self.number(c[0], 0.0), unit=str(c[1])), c[0])

    def after(self, meta, c):
        return _Clause("after_s", self.number(c[0], V.TRIGGER_TIME_RANGE_S[0]), c[0])

    def within(self, meta, c):
        return _Clause("within_m", self.number(c[1], V.TRIGGER_DISTANCE_RANGE_M[0]), c[1], {"of": c[0]})

    def word(self, meta, c):
        return _Clause("word", str(c[0]), c[0])

    def agent(self, meta, children):
        is_ego = children[0].type == "EGO"
        type_token, name_token = (children[1], children[0]) if is_ego else (children[0], children[1])
        name = "ego" if is_ego else str(name_token)
        tokens: dict[Any, Token] = {"name": name_token, "type": type_token}
        values: dict[str, Any] = {}
        unknown_words = False
        for clause in children[2:]:
            kind = clause.kind
            if kind == "word":
                kind = self._classify(clause, values)
                unknown_words |= kind == "unknown"
                if kind in (None, "unknown"):
                    continue
            elif kind in values:
                self.error(clause.token, f"'{_CLAUSE_WORDS[kind]}' is given twice for '{name}'")
                continue
            values[kind] = clause.value
            tokens[kind] = clause.token
            if kind == "within_m":
                values["of"] = str(clause.extra["of"])
                tokens["of"] = clause.extra["of"]
        suppressed = set()
        if "action" not in values:
            suppressed.add("action")
            if not unknown_words:  # a misspelt action was reported already
                self.error(name_token, f"'{name}' has no action; add one of: {', '.join(V.ACTIONS)}")
        trigger = None
        if "after_s" in values or "within_m" in values:
            trigger = Trigger.model_construct(after_s=values.pop("after_s", None), within_m=values.pop("within_m", None),
                                              of=values.pop("of", "ego"))
            tokens[("trigger", "after_s")] = tokens.pop("after_s", None)
            tokens[("trigger", "within_m")] = tokens.pop("within_m", None)
            tokens[("trigger", "of")] = tokens.pop("of", None)
            tokens["trigger"] = tokens[("trigger", "after_s")] or tokens[("trigger", "within_m")]
        agent_type = str(type_token)
        agent = Agent.model_construct(
            name=name, type=agent_type, is_ego=is_ego, action=values.get("action", ""),
            behavior=values.get("behavior", V.DEFAULT_BEHAVIOR), relative_to_ego=values.get("relative_to_ego"),
            road_type=values.get("road_type", V.default_road_type(agent_type)), behind=values.get("behind"),
            order=values.get("order"), gap_m=values.get("gap_m"), speed=values.get("speed"), trigger=trigger)
        self.statements.append((meta.line, f"agent.{name}"))
        return _AgentDraft(agent, tokens, suppressed)

    def _classify(self, clause: _Clause, values: dict[str, Any]) -> str | None:
        """A bare word on an agent line is its action or its behaviour; anything else gets a hint.

        Returns the field the word fills, None when it fills none, "unknown" for a word of no class."""
        word, token = clause.value, clause.token
        if word in V.ACTIONS or word in V.BEHAVIORS:
            kind = "action" if word in V.ACTIONS else "behavior"
            if kind in values:
                self.error(token, f"a second {'action' if kind == 'action' else 'behaviour'} '{word}'; an agent line "
                                  f"has one{' (put a later action in a new stage)' if kind == 'action' else ''}")
                return None
            return kind
        if word in V.POSITIONS or word in V.ROAD_TYPES:  # understood; taken, but the line must say it properly
            kind, keyword = ("relative_to_ego", "at") if word in V.POSITIONS else ("road_type", "on")
            self.error(token, f"a {'position' if keyword == 'at' else 'road type'} needs '{keyword}': "
                              f"write '{keyword} {word}'")
            if kind not in values:
                values[kind] = word
            return None
        self.error(token, _unknown_word(word, "action or behaviour", list(V.ACTIONS) + list(V.BEHAVIORS)))
        return "unknown"

    # -- stages and the whole ----------------------------------------------------------------------------
    def _later_ego_lines(self, stage: str, drafts: list) -> None:
        """The ego's action in a later stage: anchored to its stage (the first stage's line owns 'agent.ego'),
        and without 'on' (the rules see the road type, not whether the line wrote it)."""
        for draft in drafts:
            if not draft.agent.is_ego:
                continue
            line = draft.tokens["name"].line
            self.statements = [(n, f"stage.{stage}.ego" if (n, a) == (line, "agent.ego") else a)
                               for n, a in self.statements]
            if draft.tokens.get("road_type") is not None:
                self.error(draft.tokens["road_type"], "the ego's later action has no 'on': the ego keeps its one start")

    def stage(self, meta, children):
        name_token, *agents, rbrace = children
        if self._stages_seen:
            self._later_ego_lines(str(name_token), agents)
        self._stages_seen += 1
        self.statements.append((meta.line, f"stage.{name_token}"))
        self.statements.append((rbrace.line, f"stage.{name_token}.end"))
        return ("stage", name_token, agents)

    def start(self, meta, children):
        fields: dict[str, Any] = {"road": RoadSpec(), "weather": None, "seed": None}
        stages = []
        seen = set()
        for child in children:
            if child[0] == "stage":
                stages.append(child)
                continue
            kind, value, token = child
            if kind in seen:
                self.error(token or Token("X", "", line=meta.line, column=1), f"'{kind}' is given twice")
                continue
            seen.add(kind)
            fields[kind] = value
        built = []
        for i, (_, name_token, drafts) in enumerate(stages):
            self.where[("stages", i, "name")] = name_token
            for j, draft in enumerate(drafts):
                at = ("stages", i, "agents", j)
                self.where[at] = draft.tokens["name"]  # where a problem of the agent as a whole is shown
                for key, token in draft.tokens.items():
                    if token is not None:
                        self.where[at + (key if isinstance(key, tuple) else (key,))] = token
                self.suppressed.update(at + (key,) for key in draft.suppressed)
            built.append(Stage.model_construct(name=str(name_token), agents=tuple(d.agent for d in drafts)))
        fields["stages"] = tuple(built)
        return _Draft(fields)


_CLAUSE_WORDS = {"relative_to_ego": "at", "road_type": "on", "behind": "behind", "order": "order", "gap_m": "gap",
                 "speed": "speed", "after_s": "after", "within_m": "when ... within"}


def _unknown_word(word: str, kind: str, valid: list[str]) -> str:
    article = "an" if kind[0] in "aeiou" else "a"
    suggestions = V.nearest(word, valid)
    if suggestions:
        return f"unknown word '{word}', expected {article} {kind}; did you mean {V.either(suggestions)}?"
    return f"unknown word '{word}', expected {article} {kind}"


def _anchor_comments(statements: list[tuple[int, str]], comments: list[Token]) -> dict[str, Comment]:
    """Attach each comment to a statement: to the one on its line, else to the next one, else to the end."""
    starts = sorted(statements)
    first_on_line: dict[int, str] = {}
    for line, anchor in starts:
        first_on_line.setdefault(line, anchor)
    leading: dict[str, list[str]] = {}
    trailing: dict[str, str] = {}
    for token in comments:
        text = str(token)[1:].strip()
        anchor = first_on_line.get(token.line)
        if anchor is not None and anchor not in trailing:
            trailing[anchor] = text
            continue
        if anchor is not None:  # two statements merged into one (e.g. two 'has' lines): keep both comments
            leading.setdefault(anchor, []).append(text)
            continue
        anchor = next((a for line, a in starts if line > token.line), "end")
        leading.setdefault(anchor, []).append(text)
    return {anchor: Comment(leading=tuple(leading.get(anchor, ())), trailing=trailing.get(anchor))
            for anchor in sorted(set(leading) | set(trailing))}
