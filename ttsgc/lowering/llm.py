"""English -> the scenario language through an LLM (Claude, via the anthropic SDK's Messages API).

The system prompt (language reference, the vocabulary from its one source, the reading conventions, worked
examples drawn from the lowering corpus's dev split) is rendered from templates/ with jinja2 and cached. An
answer goes through the same plan inference as the offline rules (implied road conditions, repairs, notes)
before the language's rules check it. The answer is parsed and checked like any .tsg file; on any error the
diagnostics are sent back and the model tries again, three tries in all. The answer is only ever parsed by the
language's grammar, never evaluated.
"""

from __future__ import annotations

import os
import time
from dataclasses import dataclass, field

from ttsgc import vocabulary as V
from ttsgc.language import ScenarioError, parse
from ttsgc.lowering.infer import infer_plan
from ttsgc.lowering.offline import LoweringError
from ttsgc.numbers import env_number
from ttsgc.resources import resource_dir
from ttsgc.scenario import Scenario

MAX_TRIES = 3
DEFAULT_MODEL = "claude-sonnet-5-5"  # a current model this SDK knows; --model or TTSGC_MODEL to change
# Every request has a deadline: connecting, each answer, and all tries together (the SDK's own default is 600 s
# a request, retried twice, with no word to the user meanwhile).
CONNECT_TIMEOUT_S = 10.0
DEFAULT_TOTAL_TIMEOUT_S = 300.0
NETWORK_TRIES = 3  # a request that fails on the way (connection, timeout, 429, 5xx) is sent again, in the deadline
OFFLINE_HINT = "check the network, ANTHROPIC_API_KEY and ANTHROPIC_BASE_URL, or use --llm offline"
EXAMPLES_FOLDER = "worked_examples"  # templates/worked_examples: prompts with gold scenes from the corpus's dev split


@dataclass(frozen=True)
class LlmSettings:
    model: str = DEFAULT_MODEL
    temperature: float | None = None  # None: the model's own default (not sent)
    max_tokens: int = 2048
    timeout_s: float = DEFAULT_TOTAL_TIMEOUT_S  # all requests of one lowering together

    @classmethod
    def from_env(cls, model: str | None = None, temperature: float | None = None, max_tokens: int | None = None):
        """Flags first, then TTSGC_MODEL / TTSGC_TEMPERATURE / TTSGC_MAX_TOKENS / TTSGC_LLM_TIMEOUT, then the
        defaults. A variable that is not a usable number is an error that names it."""
        if temperature is None:
            temperature = env_number("TTSGC_TEMPERATURE", float, 0.0, 2.0)
        max_tokens = max_tokens or env_number("TTSGC_MAX_TOKENS", int, 1, MAX_TOKENS_LIMIT) or cls.max_tokens
        timeout = env_number("TTSGC_LLM_TIMEOUT", float, 1.0, 3600.0) or DEFAULT_TOTAL_TIMEOUT_S
        return cls(model=model or os.environ.get("TTSGC_MODEL", DEFAULT_MODEL), temperature=temperature,
                   max_tokens=max_tokens, timeout_s=timeout)


MAX_TOKENS_LIMIT = 128_000


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
        client = anthropic.Anthropic(timeout=anthropic.Timeout(settings.timeout_s, connect=CONNECT_TIMEOUT_S),
                                     max_retries=0)  # retried in _ask, within the deadline
    deadline = time.monotonic() + settings.timeout_s
    system = [{"type": "text", "text": system_prompt(), "cache_control": {"type": "ephemeral"}}]
    messages: list[dict] = [{"role": "user", "content": f"Description: {prompt.strip()}"}]
    usage: dict[str, int] = {}
    diagnostics = ""
    for attempt in range(1, MAX_TRIES + 1):
        # The SDK has no sampling parameters of its own any more: a temperature someone asks for goes in
        # the request body as is, for the models that still take it.
        extra = {"temperature": settings.temperature} if settings.temperature is not None else None
        response = _ask(client, deadline, settings, model=settings.model, max_tokens=settings.max_tokens,
                        system=system, messages=messages, extra_body=extra)
        for key in ("input_tokens", "output_tokens", "cache_creation_input_tokens", "cache_read_input_tokens"):
            count = getattr(getattr(response, "usage", None), key, 0)
            usage[key] = usage.get(key, 0) + (count if isinstance(count, int) else 0)
        answer = answer_text(response)
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


def _ask(client, deadline: float, settings: LlmSettings, **request):
    """One Messages API request within the deadline; sent again (NETWORK_TRIES in all) when it fails on the way.
    Every failure is a LoweringError that says what happened and what to do next."""
    import anthropic

    last: Exception | None = None
    for attempt in range(NETWORK_TRIES):
        remaining = deadline - time.monotonic()
        if remaining <= 0.5:
            break
        timeout = anthropic.Timeout(remaining, connect=min(CONNECT_TIMEOUT_S, remaining))
        try:
            return client.with_options(timeout=timeout, max_retries=0).messages.create(**request)
        except (anthropic.APIConnectionError, anthropic.RateLimitError, anthropic.InternalServerError) as exc:
            last = exc  # on the way: worth another try while time is left
            if attempt + 1 < NETWORK_TRIES:
                time.sleep(min(0.5 * 2 ** attempt, max(0.0, deadline - time.monotonic() - 0.5)))
        except anthropic.APIStatusError as exc:  # the request itself is refused: another try changes nothing
            raise LoweringError(f"the LLM could not be asked: {exc} ({OFFLINE_HINT})") from None
        except (anthropic.APIError, ValueError) as exc:  # a reply that is not JSON, or not a Messages reply
            raise LoweringError(f"the LLM's reply is not a Messages API answer: {_short(exc)}") from None
    if isinstance(last, anthropic.APITimeoutError) or last is None:
        raise LoweringError(f"the LLM could not be asked: no answer within {settings.timeout_s:g} s "
                            f"(TTSGC_LLM_TIMEOUT sets the limit; {OFFLINE_HINT})")
    raise LoweringError(f"the LLM could not be asked: {_short(last)} ({OFFLINE_HINT})")


def answer_text(response) -> str:
    """The text of a Messages API reply; a reply of any other shape (HTML, {}, content null) is an error."""
    content = getattr(response, "content", None)
    if not isinstance(content, list):
        raise LoweringError(f"the LLM's reply is not a Messages API answer (its content is "
                            f"{_short(repr(content))}, not a list of blocks)")
    texts = [getattr(block, "text", None) for block in content if getattr(block, "type", "") == "text"]
    texts = [text for text in texts if isinstance(text, str)]
    if not texts:
        raise LoweringError("the LLM's reply holds no text" + (
            f" (stop reason: {response.stop_reason})" if getattr(response, "stop_reason", None) else ""))
    return "".join(texts)


def _short(value, limit: int = 200) -> str:
    text = " ".join(str(value).split())
    return text if len(text) <= limit else text[: limit - 3] + "..."
