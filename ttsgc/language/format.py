"""Scenario -> the canonical .tsg text (`ttsgc fmt`). parse(format_scenario(s)) == s for every scenario.

Canonical layout: header lines, then the road block, then the stages, separated by blank lines; four spaces
of indent; on an agent line the clauses in one fixed order; defaults (normal behaviour, the type's usual
road type, lanes >= 1) left out. Comments stay with the statement they were written above or beside.
"""

from __future__ import annotations

from ttsgc import vocabulary as V
from ttsgc.scenario import Agent, Comment, RoadSpec, Scenario, format_number

INDENT = "    "


def format_scenario(s: Scenario) -> str:
    out: list[str] = []
    emit = _Emitter(out, s.comments)
    emit.line("scenario", f'scenario "{s.name}"')
    if s.weather is not None:
        emit.line("weather", f"weather {s.weather.condition} {s.weather.time}")
    if s.seed is not None:
        emit.line("seed", f"seed {s.seed}")
    road_lines = _road_lines(s.road, s.comments)
    if road_lines or any(k == "road" or k.startswith("road.") for k in s.comments):
        out.append("")
        emit.line("road", "road {")
        for anchor, text in road_lines:
            emit.line(anchor, INDENT + text)
        emit.line("road.end", "}", indent=INDENT)
    for k, stage in enumerate(s.stages):
        out.append("")
        emit.line(f"stage.{stage.name}", f"stage {stage.name} {{")
        for agent in stage.agents:
            anchor = f"stage.{stage.name}.ego" if agent.is_ego and k > 0 else f"agent.{agent.name}"
            emit.line(anchor, INDENT + format_agent(agent))
        emit.line(f"stage.{stage.name}.end", "}", indent=INDENT)
    end = s.comments.get("end")
    if end is not None and (end.leading or end.trailing):
        out.append("")
        out.extend(_comment_text(c) for c in end.leading + ((end.trailing,) if end.trailing is not None else ()))
    return "\n".join(out) + "\n"


def format_agent(a: Agent) -> str:
    """One agent line, clauses in canonical order: type name at on action behaviour order gap speed trigger."""
    words = ["ego", a.type] if a.is_ego else [a.type, a.name]
    if a.relative_to_ego is not None:
        words += ["at", a.relative_to_ego]
    if a.road_type != V.default_road_type(a.type):
        words += ["on", a.road_type]
    words.append(a.action)
    if a.behavior != V.DEFAULT_BEHAVIOR:
        words.append(a.behavior)
    if a.behind is not None:
        words += ["behind", a.behind]
    if a.order is not None:
        words += ["order", str(a.order)]
    if a.gap_m is not None:
        words += ["gap", f"{format_number(a.gap_m)}m"]
    if a.speed is not None:
        words += ["speed", format_number(a.speed.value), a.speed.unit]
    if a.trigger is not None:
        if a.trigger.within_m is not None:
            words += ["when", a.trigger.of, "within", f"{format_number(a.trigger.within_m)}m"]
        if a.trigger.after_s is not None:
            words += ["after", f"{format_number(a.trigger.after_s)}s"]
    return " ".join(words)


def _road_lines(road: RoadSpec, comments: dict[str, Comment]) -> list[tuple[str, str]]:
    lines = []
    if road.lanes != RoadSpec().lanes or "road.lanes" in comments:  # a commented default stays written
        lines.append(("road.lanes", f"lanes >= {road.lanes}"))
    if road.junction is not None:
        lines.append(("road.junction", "at junction" if road.junction else "not at junction"))
    required = road.required_signals + road.required_objects
    if required:
        lines.append(("road.has", "has " + ", ".join(required)))
    forbidden = road.without_signals + road.without_objects
    if forbidden:
        lines.append(("road.without", "without " + ", ".join(forbidden)))
    return lines


def _comment_text(text: str) -> str:
    return f"# {text}" if text else "#"


class _Emitter:
    """Writes statement lines with the comments anchored to them."""

    def __init__(self, out: list[str], comments: dict[str, Comment]):
        self.out, self.comments = out, comments

    def line(self, anchor: str, text: str, indent: str | None = None) -> None:
        comment = self.comments.get(anchor, Comment())
        lead = indent if indent is not None else text[: len(text) - len(text.lstrip())]
        self.out.extend(lead + _comment_text(c) for c in comment.leading)
        self.out.append(text + (f"  {_comment_text(comment.trailing)}" if comment.trailing is not None else ""))
