"""The scenario language: parse (.tsg -> Scenario), format (Scenario -> canonical .tsg), diagnostics."""

from ttsgc.language.diagnostics import Diagnostic, ScenarioError
from ttsgc.language.format import format_scenario
from ttsgc.language.parse import parse, parse_file

__all__ = ["Diagnostic", "ScenarioError", "format_scenario", "parse", "parse_file"]
