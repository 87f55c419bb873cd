"""English -> the scenario language: the offline rules on the examples and on held-out paraphrases, unknown
words, unreadable prompts, the commands, and the LLM path against a local server speaking the Messages API."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import EXAMPLES, LocalHttpServer
from ttsgc.cli import main
from ttsgc.evaluate import agent_accuracy, road_accuracy, weather_accuracy
from ttsgc.language import parse, parse_file
from ttsgc.lowering import lower_prompt
from ttsgc.lowering.llm import LlmSettings, extract_scene, lower_with_llm, system_prompt
from ttsgc.lowering.offline import LoweringError, lower

PARAPHRASES = Path(__file__).parent / "paraphrases"
PROMPTS = sorted(EXAMPLES.glob("*.txt"))


def _same_scene(a, b) -> bool:
    strip = lambda s: s.model_copy(update={"name": "x", "comments": {}})  # noqa: E731
    return strip(a) == strip(b)


# Hand-written example scenes that predate the corpus's gold conventions, and what the conventions say instead.
CONVENTIONS_DIFFER = {
    "foggy_convoy": "a motorcycle overtaking on the left needs a second lane (lanes >= 2)",
}


@pytest.mark.parametrize("prompt", PROMPTS, ids=lambda p: p.stem)
def test_offline_lowering_of_each_example_scores_like_its_hand_written_scene(prompt):
    lowered = lower(prompt.read_text())
    gold = parse_file(prompt.with_suffix(".tsg"))
    exact = (agent_accuracy(gold, lowered.scenario), road_accuracy(gold, lowered.scenario),
             weather_accuracy(gold, lowered.scenario)) == (1, 1, 1)
    assert exact != (prompt.stem in CONVENTIONS_DIFFER), CONVENTIONS_DIFFER.get(prompt.stem, lowered.scenario)


def test_held_out_paraphrases_score_like_the_paper():
    aa, ra = [], []
    for prompt in sorted(PARAPHRASES.glob("*.txt")):
        gold = parse_file(prompt.with_suffix(".tsg"))
        predicted = lower(prompt.read_text()).scenario
        aa.append(agent_accuracy(gold, predicted))
        ra.append(road_accuracy(gold, predicted))
    assert len(aa) >= 10
    assert sum(aa) / len(aa) >= 0.9 and sum(ra) / len(ra) >= 0.8


@pytest.mark.parametrize("prompt, facts", [
    ("Three cars including the ego drive on a two-lane road.", {"agents": 3, "lanes": 2}),
    ("More than ten cars drive ahead of the ego", {"agents": 12}),
    ("A scene with daily traffic at dusk", {"kind": "daily_traffic", "time": "sunset"}),
    ("Only two-wheelers, please", {"kind": "two_wheels"}),
    ("There is no traffic light and no stop sign; a bus waits.", {"without": ("traffic_light", "stop")}),
    ("A car on the right swerves into its path.", {"action": ("c1", "change_lane_to_left")}),
    ("The van does not move while the ego turns left at the intersection.", {"action": ("c1", "stop")}),
    ("A reckless motorcyclist overtakes on the left.", {"behavior": ("m1", "aggressive"),
                                                        "position": ("m1", "back_left")}),
    ("A pedestrian walks along the sidewalk without a crosswalk in sight.", {"action": ("p1", "on_the_sidewalk"),
                                                                            "without": ("crosswalk",)}),
    ("The ego turns right; then a kid runs across the street.", {"stages": 2, "behavior": ("p1", "aggressive")}),
])
def test_the_rules_read_paraphrases(prompt, facts):
    lowered = lower(prompt)
    s = lowered.scenario
    agents = {a.name: a for a in s.agents()}
    for key, value in facts.items():
        if key == "agents":
            assert len(agents) == value
        elif key == "lanes":
            assert s.road.lanes == value
        elif key == "kind":
            assert lowered.kind == value
        elif key == "time":
            assert s.weather.time == value
        elif key == "without":
            assert set(value) <= set(s.road.without_signals + s.road.without_objects)
        elif key == "stages":
            assert len(s.stages) == value
        else:
            name, expected = value
            assert getattr(agents[name], {"position": "relative_to_ego"}.get(key, key)) == expected, (key, s)


def test_unknown_words_are_reported_not_dropped_with_the_nearest_known_word():
    lowered = lower("A car in front of the ego zigzags and then swervs")
    assert "zigzags" in lowered.unknown
    assert "swervs (read as swerves)" in lowered.unknown  # one slip: read as meant
    assert "zwerves (did you mean swerve?)" in lower("A car in front of the ego zwerves").unknown  # a first letter
    # changed is no slip the reader takes on itself


def test_a_prompt_with_nothing_readable_is_an_error_with_its_own_exit_code(tmp_path, capsys):
    path = tmp_path / "p.txt"
    path.write_text("lorem ipsum dolor")
    assert main(["lower", str(path)]) == 6
    err = capsys.readouterr().err
    assert "nothing in the prompt could be read" in err and "lorem" in err


def test_lower_command_writes_an_editable_scene(tmp_path, capsys):
    out = tmp_path / "scene.tsg"
    assert main(["lower", str(EXAMPLES / "left_turn_oncoming.txt"), "-o", str(out), "--llm", "offline"]) == 0
    text = out.read_text()
    assert text.startswith("# Lowered (offline) from: The ego car turns left")
    assert main(["check", str(out)]) == 0


def test_compile_of_a_prompt_writes_the_lowered_scene_beside_the_output(tmp_path):
    out = tmp_path / "scene.xosc"
    assert main(["compile", str(EXAMPLES / "stop_sign_right_turn.txt"), "-o", str(out), "--llm", "offline"]) == 0
    assert out.is_file() and (tmp_path / "scene.tsg").is_file()
    assert main(["compile", str(tmp_path / "scene.tsg"), "-o", str(tmp_path / "again.xosc")]) == 0


def test_a_hand_written_scene_beside_the_output_is_never_overwritten(tmp_path):
    prompt = tmp_path / "blocking.txt"
    prompt.write_text((EXAMPLES / "blocking.txt").read_text())
    mine = tmp_path / "blocking.tsg"
    mine.write_text('scenario "mine"\nstage s {\n    ego car go_straight\n}\n')
    assert main(["compile", str(prompt), "--no-simulate"]) == 0
    assert mine.read_text().startswith('scenario "mine"')
    assert (tmp_path / "blocking.lowered.tsg").read_text().startswith("# Lowered (offline)")


def test_variants_differ_in_roads_or_agents(tmp_path):
    out = tmp_path / "v.xosc"
    assert main(["compile", str(EXAMPLES / "daily_traffic.txt"), "-o", str(out), "--variants", "3"]) == 0
    scenes = [(tmp_path / f"v-{k}.xosc").read_bytes() for k in (1, 2, 3)]
    assert len(set(scenes)) == 3
    assert (tmp_path / "v-2.tsg").read_text() != (tmp_path / "v-1.tsg").read_text()  # another kind variant


# -- the LLM path ---------------------------------------------------------------------------------------

class _MessagesServer(LocalHttpServer):
    """Answers POST /v1/messages with scripted texts, recording every request."""

    def __init__(self, answers: list[str]):
        self.answers, self.requests = list(answers), []

        def reply(raw: bytes):
            body = json.loads(raw)
            self.requests.append(body)
            text = self.answers.pop(0) if self.answers else "still nothing"
            return "application/json", json.dumps({
                "id": f"msg_{len(self.requests)}", "type": "message", "role": "assistant", "model": body["model"],
                "content": [{"type": "text", "text": text}], "stop_reason": "end_turn", "stop_sequence": None,
                "usage": {"input_tokens": 1000, "output_tokens": 100, "cache_read_input_tokens": 900,
                          "cache_creation_input_tokens": 0}}).encode()

        super().__init__(reply)


GOOD = "```tsg\nscenario \"llm\"\nstage main {\n    ego car turn_left\n    car c1 at road_of_straight go_straight\n}\n```"
BAD = "```tsg\nscenario \"llm\"\nstage main {\n    ego car trun_left\n}\n```"


def _client(url: str):
    import anthropic

    return anthropic.Anthropic(api_key="test-key", base_url=url, max_retries=0)


def test_the_repair_loop_fixes_a_first_answer_with_an_error():
    with _MessagesServer([BAD, GOOD]) as server:
        result = lower_with_llm("the ego turns left", LlmSettings(model="test-model"), _client(server.url))
    assert result.tries == 2 and result.scenario.ego.action == "turn_left"
    assert result.usage["input_tokens"] == 2000 and result.usage["cache_read_input_tokens"] == 1800
    first, second = server.requests
    assert first["system"][0]["cache_control"] == {"type": "ephemeral"}
    assert "turn_left" in first["system"][0]["text"]  # the vocabulary is in the prompt
    assert second["messages"][-1]["role"] == "user" and "did you mean turn_left?" in second["messages"][-1]["content"]
    assert second["messages"][-2] == {"role": "assistant", "content": BAD}


def test_an_answer_that_never_becomes_valid_fails_after_three_tries():
    with _MessagesServer([BAD, BAD, BAD, GOOD]) as server:
        with pytest.raises(LoweringError, match="still invalid after 3 tries") as err:
            lower_with_llm("the ego turns left", LlmSettings(), _client(server.url))
    assert len(server.requests) == 3 and "trun_left" in str(err.value)


def test_the_command_uses_the_llm_when_a_key_is_set(tmp_path, monkeypatch, capsys):
    with _MessagesServer([GOOD]) as server:
        monkeypatch.setenv("ANTHROPIC_API_KEY", "test-key")
        monkeypatch.setenv("ANTHROPIC_BASE_URL", server.url)
        monkeypatch.setenv("TTSGC_MODEL", "model-from-env")
        prompt = tmp_path / "p.txt"
        prompt.write_text("the ego turns left while a car comes towards it")
        out = tmp_path / "s.xosc"
        report = tmp_path / "r.json"
        assert main(["compile", str(prompt), "-o", str(out), "--report", str(report), "--max-tokens", "900",
                     "--temperature", "0.3"]) == 0
    assert server.requests[0]["model"] == "model-from-env" and server.requests[0]["max_tokens"] == 900
    assert server.requests[0]["temperature"] == 0.3
    data = json.loads(report.read_text())
    assert data["lowering"]["method"] == "anthropic" and data["lowering"]["tries"] == 1
    assert (tmp_path / "s.tsg").read_text().startswith("# Lowered (anthropic)")


def test_an_unreachable_llm_is_a_lowering_error():
    with pytest.raises(LoweringError, match="could not be asked"):
        lower_with_llm("x", LlmSettings(), _client("http://127.0.0.1:9"))


def test_answers_are_parsed_never_run():
    assert extract_scene("Here:\n```tsg\nscenario \"a\"\n```\nthanks") == 'scenario "a"\n'
    hostile = "```tsg\n__import__('os').system('echo pwned')\n```"
    with _MessagesServer([hostile] * 3) as server:
        with pytest.raises(LoweringError):
            lower_with_llm("x", LlmSettings(), _client(server.url))


def test_the_system_prompt_is_rendered_from_templates_with_the_vocabulary():
    text = system_prompt()
    assert "road_of_left_turn" in text and "continental_crosswalk" in text and "Description:" in text
    examples = text[text.index("Description:"):]
    parse(extract_scene(examples[examples.index("```tsg"):]))  # its examples are valid scenes


def test_auto_method_is_offline_without_a_key(monkeypatch):
    monkeypatch.delenv("ANTHROPIC_API_KEY", raising=False)
    assert lower_prompt("a bus stops in front of the ego").method == "offline"


BLOCKING_PEDESTRIAN = ("```tsg\nscenario \"llm\"\nstage main {\n    ego car go_straight\n"
                       "    pedestrian p1 at front block_the_ego\n    car c1 at left go_straight\n}\n```")


def test_the_llm_answer_goes_through_the_same_plan_inference():
    with _MessagesServer([BLOCKING_PEDESTRIAN]) as server:
        lowering = lower_prompt("a pedestrian blocks the ego while a car drives beside it", "anthropic",
                                settings=LlmSettings(model="test-model"), client=_client(server.url))
    agents = {a.name: a for a in lowering.scenario.agents()}
    assert agents["p1"].action == "cross_the_road"  # repaired: a pedestrian steps into the path
    assert lowering.scenario.road.lanes == 2  # inferred: c1 drives beside the ego
    text = lowering.tsg("a pedestrian blocks the ego")
    assert "# repaired: a pedestrian cannot block_the_ego" in text and "# inferred: lanes >= 2" in text
    assert lowering.summary()["tokens"] == 1100
