"""Diagnostics: every error as file:line:col, the source line, and a caret under the column."""

from __future__ import annotations

from dataclasses import asdict, dataclass

from ttsgc.errors import ExitCode, TtsgcError


@dataclass(frozen=True, order=True)
class Diagnostic:
    line: int
    column: int
    message: str
    width: int = 1  # how many characters the caret underlines
    file: str = "<input>"

    def render(self, source: str | None = None) -> str:
        head = f"{self.file}:{self.line}:{self.column}: error: {self.message}"
        if source is None:
            return head
        lines = source.splitlines()
        if not 1 <= self.line <= len(lines):
            return head
        text = lines[self.line - 1].replace("\t", " ")
        caret = " " * (self.column - 1) + "^" + "~" * max(0, self.width - 1)
        return f"{head}\n    {text}\n    {caret}"

    def to_json(self) -> dict:
        return asdict(self)


class ScenarioError(TtsgcError):
    """A .tsg that is not a valid scenario; carries all its diagnostics, in source order."""

    exit_code = ExitCode.INVALID_SCENARIO

    def __init__(self, diagnostics: list[Diagnostic], source: str | None = None):
        self.diagnostics = sorted(diagnostics)
        self.source = source
        super().__init__(self.render())

    def render(self) -> str:
        return "\n".join(d.render(self.source) for d in self.diagnostics)
