"""A player's documented OpenSCENARIO coverage, kept as data (ttsgc/targets/<target>.toml), and the lint that
holds a file against it: every element or attribute the player does not support, with its line."""

from __future__ import annotations

import functools
import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

from lxml import etree

from ttsgc.errors import ExitCode, TtsgcError

LINTED_TARGETS = ("carla", "esmini")
STATUSES = ("supported", "unsupported", "partly", "ignored")
SEVERITY = {"unsupported": "error", "partly": "warning", "ignored": "note"}


class LintFindings(TtsgcError):
    """A file uses what its target player does not support."""

    exit_code = ExitCode.UNSUPPORTED_BY_TARGET


class LintInputError(TtsgcError):
    """The file to lint cannot be read as XML."""

    exit_code = ExitCode.INVALID_SCENARIO


@dataclass(frozen=True)
class Rule:
    elements: tuple[str, ...]
    status: str
    source: str
    inside: str | None = None
    attribute: str | None = None
    allowed: tuple[str, ...] | None = None
    note: str = ""
    certainty: str = ""


@dataclass(frozen=True)
class Coverage:
    target: str
    title: str
    default: str
    rules: tuple[Rule, ...]
    data: dict  # the whole file: tables a target's own module reads (carla: blueprints, towns)

    def element_status(self, element: etree._Element) -> tuple[str, Rule | None]:
        """The status of an element: a rule with a matching `inside` wins over one without."""
        tag = element.tag
        ancestors = {a.tag for a in element.iterancestors()}
        plain = scoped = None
        for rule in self.rules:
            if rule.attribute is not None or tag not in rule.elements:
                continue
            if rule.inside is None:
                plain = plain or rule
            elif rule.inside in ancestors:
                scoped = scoped or rule
        chosen = scoped or plain
        return (chosen.status, chosen) if chosen else (self.default, None)

    def attribute_findings(self, element: etree._Element):
        ancestors = None
        for rule in self.rules:
            if rule.attribute is None or element.tag not in rule.elements:
                continue
            if rule.inside is not None:
                ancestors = ancestors if ancestors is not None else {a.tag for a in element.iterancestors()}
                if rule.inside not in ancestors:
                    continue
            value = element.get(rule.attribute)
            if value is None or (rule.allowed is not None and value in rule.allowed):
                continue
            yield rule, f"{element.tag} {rule.attribute}=\"{value}\""


@dataclass(frozen=True)
class Finding:
    line: int
    what: str  # the element, or the element and its attribute
    status: str
    rule: Rule | None

    @property
    def severity(self) -> str:
        return SEVERITY[self.status]

    def render(self, path: str, title: str) -> str:
        why = {"unsupported": "not supported by", "partly": "supported with a limit by",
               "ignored": "read past by"}[self.status]
        text = f"{path}:{self.line}: {self.severity}: {self.what}: {why} {title}"
        if self.rule is None:
            return text + " (not in its documented coverage)"
        detail = f"{self.rule.note}; " if self.rule.note else ""
        certainty = f", {self.rule.certainty}" if self.rule.certainty == "recalled" else ""
        return text + f" ({detail}{self.rule.source}{certainty})"


@functools.cache
def coverage(target: str) -> Coverage:
    if target not in LINTED_TARGETS:
        raise TtsgcError(f"no coverage data for target '{target}'; choose one of {', '.join(LINTED_TARGETS)}")
    data = tomllib.loads((resources.files("ttsgc.targets") / f"{target}.toml").read_text(encoding="utf-8"))
    rules = []
    for raw in data.get("rule", []):
        if raw["status"] not in STATUSES:
            raise ValueError(f"{target}.toml: unknown status {raw['status']!r}")
        rules.append(Rule(tuple(raw["elements"]), raw["status"], raw["source"], raw.get("inside"),
                          raw.get("attribute"), tuple(raw["allowed"]) if "allowed" in raw else None,
                          raw.get("note", ""), raw.get("certainty", "")))
    return Coverage(data["target"], data["title"], data["default"], tuple(rules), data)


def lint_tree(root: etree._Element, target: str) -> list[Finding]:
    """Every element and attribute of the tree that the target does not fully support, in document order."""
    cov = coverage(target)
    findings = []
    for element in root.iter():
        if not isinstance(element.tag, str):  # comments, processing instructions
            continue
        status, rule = cov.element_status(element)
        if status != "supported":
            findings.append(Finding(element.sourceline or 0, element.tag, status, rule))
        for attr_rule, what in cov.attribute_findings(element):
            findings.append(Finding(element.sourceline or 0, what, attr_rule.status, attr_rule))
    return findings


def lint_file(path: str | Path, target: str) -> list[Finding]:
    """The findings of one .xosc file; a file that is not XML is an error naming it."""
    from ttsgc.simulate.xosc_check import read_xosc
    from ttsgc.xsd import XoscFileError

    try:
        root = read_xosc(Path(path))
    except XoscFileError as exc:  # the reader validate uses: one policy for a file's size, entities, DOCTYPE
        raise LintInputError(str(exc)) from None
    return lint_tree(root, target)


def errors(findings: list[Finding]) -> list[Finding]:
    return [f for f in findings if f.status == "unsupported"]
