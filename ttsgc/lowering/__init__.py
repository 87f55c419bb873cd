"""English -> the scenario language: offline rules by default, an LLM through the anthropic SDK on request."""

from __future__ import annotations

import os
from dataclasses import dataclass, field

from ttsgc.language import format_scenario
from ttsgc.lowering.offline import LoweringError, lower
from ttsgc.scenario import Comment, Scenario

__all__ = ["LoweringError", "Lowering", "lower_prompt"]

# Ten times the longest prompt people wrote for the corpus; reading is quadratic in the worst case, and an LLM
# answer to a book is no scene either.
MAX_PROMPT_CHARS = 20_000


@dataclass
class Lowering:
    scenario: Scenario
    method: str  # offline | anthropic
    unknown: list[str] = field(default_factory=list)
    tries: int = 1
    usage: dict[str, int] = field(default_factory=dict)
    kind: str | None = None
    notes: list[str] = field(default_factory=list)  # every inference and repair of the plan inference

    def tsg(self, prompt: str) -> str:
        """The scene as an editable .tsg, headed by the prompt it came from and every inference and repair."""
        # One comment line per prompt line: a line break of any kind inside a comment would end it.
        prompt_lines = [" ".join(line.split()) for line in prompt.strip().splitlines()]
        prompt_lines = [line for line in prompt_lines if line] or [""]
        lines = [f"Lowered ({self.method}) from: {prompt_lines[0]}", *prompt_lines[1:]]
        if self.unknown:
            lines.append(f"Words not understood: {', '.join(self.unknown)}")
        lines += self.notes
        comments = dict(self.scenario.comments)
        comments["scenario"] = Comment(leading=tuple(lines))
        return format_scenario(self.scenario.model_copy(update={"comments": comments}))

    def summary(self) -> dict:
        return {"method": self.method, "tries": self.tries, "usage": self.usage, "unknown": self.unknown,
                "kind": self.kind, "notes": self.notes,
                "tokens": self.usage.get("input_tokens", 0) + self.usage.get("output_tokens", 0)}


def choose_method(requested: str) -> str:
    """auto: the LLM when ANTHROPIC_API_KEY is set, else the offline rules."""
    if requested == "auto":
        return "anthropic" if os.environ.get("ANTHROPIC_API_KEY") else "offline"
    return requested


def lower_prompt(prompt: str, method: str = "auto", seed: int = 0, settings=None, client=None) -> Lowering:
    if len(prompt) > MAX_PROMPT_CHARS:
        raise LoweringError(f"the prompt is {len(prompt):,} characters; a scene is described in at most "
                            f"{MAX_PROMPT_CHARS:,} (a paragraph or two)")
    method = choose_method(method)
    if method == "offline":
        result = lower(prompt, seed=seed)
        return Lowering(result.scenario, "offline", result.unknown, kind=result.kind, notes=result.notes)
    from ttsgc.lowering.llm import lower_with_llm

    result = lower_with_llm(prompt, settings, client)
    return Lowering(result.scenario, "anthropic", tries=result.tries, usage=result.usage, notes=result.notes)
