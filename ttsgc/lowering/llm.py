"""English -> the scenario language through an LLM (Claude, via the anthropic SDK's Messages API).

The system prompt (language reference, the vocabulary from its one source, the reading conventions, worked
examples drawn from the lowering corpus's dev split) is rendered from templates/ with jinja2 and cached. A valid
answer goes through the same plan inference as the offline rules (implied road conditions, repairs, notes). The answer is parsed and checked like any .tsg file; on any error the
diagnostics are sent back and the model tries again, three tries in all. The answer is only ever parsed by the
language's grammar, never evaluated.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

from ttsgc import vocabulary as V
from ttsgc.language import ScenarioError, parse
from ttsgc.lowering.infer import infer_plan
from ttsgc.lowering.offline import LoweringError
from ttsgc.resources import resource_dir
from ttsgc.scenario import Scenario

MAX_TRIES = 3
DEFAULT_MODEL = "claude-sonnet-5-5"  # a current model this SDK knows; --model or TTSGC_MODEL to change
EXAMPLES_FOLDER = "worked_examples"  # templates/worked_examples: prompts with gold scenes from the corpus's dev split


@dataclass(frozen=True)
class LlmSettings:
    model: str = DEFAULT_MODEL
    temperature: float | None = None  # None: the model's own default (not sent)
    max_tokens: int = 2048

    @classmethod
    def from_env(cls, model: str | None = None, temperature: float | None = None, max_tokens: int | None = None):
        """Flags first, then TTSGC_MODEL / TTSGC_TEMPERATURE / TTSGC_MAX_TOKENS, then the defaults."""
        env_temperature = os.environ.get("TTSGC_TEMPERATURE")
        return cls(model=model or os.environ.get("TTSGC_MODEL", DEFAULT_MODEL),
                   temperature=temperature if temperature is not None else
                   (float(env_temperature) if env_temperature else None),
                   max_tokens=max_tokens or int(os.environ.get("TTSGC_MAX_TOKENS", "2048")))


@dataclass
class LlmLowered:
    scenario: Scenario
    text: str  # the accepted scene, as the model wrote it
    tries: int
    usage: dict[str, int] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)  # the plan inference's inferences and repairs


def _environment() -> jinja2.Environment:  # noqa: F821
    import jinja2  # here, not at the top: the offline lowering and every other command do without it

    return jinja2.Environment(loader=jinja2.FileSystemLoader(str(resource_dir("templates"))),
                              undefined=jinja2.StrictUndefined, keep_trailing_newline=True, autoescape=False)


def system_prompt() -> str:
    examples = []
    for prompt in sorted((resource_dir("templates") / EXAMPLES_FOLDER).glob("*.txt")):
        scene = prompt.with_suffix(".tsg")
        if scene.is_file():
            examples.append({"prompt": prompt.read_text(encoding="utf-8").strip(),
                             "scene": scene.read_text(encoding="utf-8")})
    return _environment().get_template("system.md.j2").render(
        types=V.AGENT_TYPES, actions=V.ACTIONS,
        actions_by_type={t: sorted(a) for t, a in V.ACTIONS_BY_TYPE.items()}, behaviors=list(V.BEHAVIORS),
        positions=V.POSITIONS, road_types=list(V.ROAD_TYPES), signals=list(V.SIGNALS), objects=V.object_words(),
        conditions=list(V.WEATHER_CONDITIONS), times=list(V.TIMES_OF_DAY), examples=examples)


def extract_scene(answer: str) -> str:
    """The scene from an answer: the first fenced block if there is one, else the whole answer."""
    start = answer.find("```")
    if start < 0:
        return answer.strip() + "\n"
    body_start = answer.find("\n", start) + 1
    end = answer.find("```", body_start)
    return answer[body_start: end if end >= 0 else len(answer)].strip() + "\n"


def lower_with_llm(prompt: str, settings: LlmSettings | None = None, client=None) -> LlmLowered:
    """Ask the model for a scene; resubmit with the diagnostics until it is valid (MAX_TRIES in all)."""
    import anthropic

    settings = settings or LlmSettings.from_env()
    if client is None:
        if not os.environ.get("ANTHROPIC_API_KEY"):
            raise LoweringError("the anthropic lowering needs ANTHROPIC_API_KEY (or use --llm offline)")
        client = anthropic.Anthropic()
    system = [{"type": "text", "text": system_prompt(), "cache_control": {"type": "ephemeral"}}]
    messages: list[dict] = [{"role": "user", "content": f"Description: {prompt.strip()}"}]
    usage: dict[str, int] = {}
    diagnostics = ""
    for attempt in range(1, MAX_TRIES + 1):
        try:
            # The SDK has no sampling parameters of its own any more: a temperature someone asks for goes in
            # the request body as is, for the models that still take it.
            extra = {"temperature": settings.temperature} if settings.temperature is not None else None
            response = client.messages.create(model=settings.model, max_tokens=settings.max_tokens, system=system,
                                              messages=messages, extra_body=extra)
        except (anthropic.APIError, anthropic.APIConnectionError) as exc:
            raise LoweringError(f"the LLM could not be asked: {exc}") from None
        for key in ("input_tokens", "output_tokens", "cache_creation_input_tokens", "cache_read_input_tokens"):
            usage[key] = usage.get(key, 0) + (getattr(response.usage, key, 0) or 0)
        answer = "".join(block.text for block in response.content if getattr(block, "type", "") == "text")
        scene = extract_scene(answer)
        notes: list[str] = []

        def infer(draft: Scenario) -> Scenario:  # the same inference and repairs as the offline rules
            inferred = infer_plan(draft)
            notes[:] = inferred.notes
            return inferred.scenario

        try:
            return LlmLowered(parse(scene, "<llm answer>", repair=infer), scene, attempt, usage, notes)
        except ScenarioError as exc:
            diagnostics = exc.render()
        messages += [{"role": "assistant", "content": answer},
                     {"role": "user", "content": _environment().get_template("repair.md.j2").render(
                         diagnostics=diagnostics)}]
    raise LoweringError(f"the LLM's scene was still invalid after {MAX_TRIES} tries; the last errors:\n{diagnostics}")
