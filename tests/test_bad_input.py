"""Bad input is normal input: every class of hostile or broken input ends in a clear message and a documented
exit code, never a traceback (exit 1), a hang, a half-written file or an overwritten input."""

from __future__ import annotations

import json
import os
import re
import stat
import time
from pathlib import Path

import pytest

from conftest import EXAMPLES, ROOT, LocalHttpServer, compiled_example
from ttsgc.cli import main
from ttsgc.errors import ExitCode
from ttsgc.numbers import NumberError, clamped_int, parse_float, parse_int

BUILTIN_MAP = ROOT / "maps" / "fourway_1lane_stop.xodr"
HUGE = "9" * 5000


def _run(capsys, *argv) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def _map_with(tmp_path: Path, old: str, new: str, name: str = "m.xodr") -> Path:
    text = BUILTIN_MAP.read_text()
    assert old in text
    path = tmp_path / name
    path.write_text(text.replace(old, new, 1))
    return path


# -- one number reader with limits -------------------------------------------------------------------------

def test_the_number_reader_refuses_what_no_quantity_needs():
    start = time.perf_counter()
    for bad in (HUGE, "nan", "inf", "-Infinity", "1e308", "0x10", "abc", "", "1e999"):
        with pytest.raises(NumberError):
            parse_float(bad)
    with pytest.raises(NumberError, match="5000 digits"):
        parse_int(HUGE)
    with pytest.raises(NumberError, match="not an integer"):
        parse_int("2.5")
    assert time.perf_counter() - start < 0.5
    assert parse_float(" 2.5 ") == 2.5 and parse_int("-7", -10, 10) == -7
    assert clamped_int(HUGE, 99) == 99 and clamped_int("0042", 99) == 42


@pytest.mark.parametrize("line", [f"seed {HUGE}", f"road {{\n    lanes >= {HUGE}\n}}"])
def test_header_numbers_with_thousands_of_digits_are_diagnosed(tmp_path, capsys, line):
    scene = tmp_path / "s.tsg"
    scene.write_text(f'scenario "x"\n{line}\nstage a {{\n    ego car go_straight\n}}\n')
    code, _, err = _run(capsys, "check", scene)
    assert code == ExitCode.INVALID_SCENARIO
    assert err.count("error:") == 1 and "5000 digits" in err


def test_agent_numbers_with_thousands_of_digits_are_diagnosed(tmp_path, capsys):
    scene = tmp_path / "s.tsg"
    scene.write_text(f'scenario "x"\nstage a {{\n    ego car go_straight\n'
                     f'    car c at front stop order {HUGE} gap {HUGE}m speed {HUGE} km/h after {HUGE}s\n}}\n')
    code, _, err = _run(capsys, "check", scene)
    assert code == ExitCode.INVALID_SCENARIO and err.count("5000 digits") == 4


def test_english_with_a_400_digit_count_and_speed_limit_is_read_with_its_limits(tmp_path, capsys):
    """A number too large to read is clamped or left out, and said so: never an overflow."""
    prompt = tmp_path / "p.txt"
    n = "9" * 400
    prompt.write_text(f"There are {n} cars at a junction with a {n} km/h speed limit sign; one cuts in "
                      f"after {n} seconds at {n} km/h.")
    code, out, err = _run(capsys, "lower", prompt)
    assert code == ExitCode.OK and "internal error" not in err
    assert "a count too large to read for car; used 12" in err
    assert "a speed limit of a number too large to read is outside 5..200 km/h" in err and "speed_" not in out


@pytest.mark.parametrize("sentence, note", [
    ("the ego drives at 99999999999999999999 km/h", "left out: a speed of a number too large to read"),
    ("a car cuts in after 999999999999 seconds", "left out: a time of a number too large to read"),
    ("a pedestrian crosses when the ego is within 9000 m", "left out: a trigger distance of 9000 m is outside"),
    ("a car cuts in after 99999 seconds", "left out: a trigger time of 99999 s is above"),
])
def test_a_quantity_the_english_cannot_use_is_left_out_with_a_note(tmp_path, capsys, sentence, note):
    prompt = tmp_path / "p.txt"
    prompt.write_text(sentence)
    code, out, err = _run(capsys, "lower", prompt)
    assert code == ExitCode.OK and note in err and f"# {note}" in out


def test_a_book_given_as_the_prompt_is_refused_at_once(tmp_path, capsys):
    """Reading is quadratic in the worst case: four megabytes of prose used to take hours."""
    prompt = tmp_path / "p.txt"
    prompt.write_text("a car goes straight. " * 200_000)
    start = time.perf_counter()
    code, _, err = _run(capsys, "compile", prompt, "-o", tmp_path / "p.xosc", "--no-simulate")
    assert code == ExitCode.LOWERING_FAILED and time.perf_counter() - start < 5
    assert "the prompt is 4,200,000 characters" in err and "at most 20,000" in err
    assert not (tmp_path / "p.xosc").exists()


@pytest.mark.parametrize("unit", ["a ", "25 mph ", "a lorry\u2014 ", "the car then the bus and then the truck turns "])
def test_a_run_on_prompt_at_the_longest_allowed_is_read_in_bounded_time(tmp_path, capsys, unit):
    """Reading within a sentence was quadratic: one run-on sentence of 20,000 characters took 20 to 90 s."""
    prompt = tmp_path / "p.txt"
    prompt.write_text((unit * 20_000)[:19_900])
    start = time.perf_counter()
    code, _, _ = _run(capsys, "lower", prompt)
    assert code in (ExitCode.OK, ExitCode.LOWERING_FAILED) and time.perf_counter() - start < 15


def test_a_scene_of_thousands_of_agents_is_refused_naming_the_first_one_too_many(tmp_path, capsys):
    scene = tmp_path / "s.tsg"
    scene.write_text('scenario "x"\nstage a {\n    ego car go_straight\n'
                     + "".join(f"    car c{i} at front go_straight\n" for i in range(3000)) + "}\n")
    start = time.perf_counter()
    code, _, err = _run(capsys, "compile", scene, "-o", tmp_path / "s.xosc")
    assert code == ExitCode.INVALID_SCENARIO and time.perf_counter() - start < 10
    assert "s.tsg:503:" in err and "at most 500 agents, the ego included; this one has 3001" in err
    assert not (tmp_path / "s.xosc").exists()


@pytest.mark.parametrize("value", ["nan", "inf", "1e308", "1e300", "-5", "1e12"])
def test_map_lengths_out_of_bounds_are_refused(tmp_path, capsys, value):
    bad = _map_with(tmp_path, 'id="1" junction="-1" length="120.0"', f'id="1" junction="-1" length="{value}"')
    code, _, err = _run(capsys, "maps", "list", "--maps", bad)
    assert code == ExitCode.MAP_ERROR and f"{bad}:4: <road>: attribute length=" in err


def test_a_spiral_of_any_allowed_length_is_evaluated_in_bounded_time():
    from ttsgc.roads.opendrive import MAX_ROAD_LENGTH_M, Geometry

    spiral = Geometry(0.0, 0.0, 0.0, 0.0, MAX_ROAD_LENGTH_M, "spiral", (0.001, 0.5))
    start = time.perf_counter()
    for k in range(200):
        pose = spiral.at(MAX_ROAD_LENGTH_M * k / 200)
    assert time.perf_counter() - start < 1.0 and all(map(abs, (pose.x, pose.y))) < 2 * MAX_ROAD_LENGTH_M


def test_one_bad_map_in_a_folder_is_named_and_skipped(tmp_path, capsys):
    _map_with(tmp_path, '<line/>', '<spiral curvStart="0.001" curvEnd="0.5"/>', "bad.xodr")
    (tmp_path / "bad.xodr").write_text((tmp_path / "bad.xodr").read_text().replace(
        'length="120.0"', 'length="1e12"'))
    (tmp_path / "good.xodr").write_bytes((ROOT / "maps" / "avenue_2lane.xodr").read_bytes())
    start = time.perf_counter()
    code, out, err = _run(capsys, "maps", "list", "--maps", tmp_path)
    assert time.perf_counter() - start < 30
    assert code == ExitCode.OK and "avenue_2lane" in out and "bad.xodr" not in out
    assert f"warning: {tmp_path / 'bad.xodr'}:" in err and "skipped" in err
    code, _, err = _run(capsys, "maps", "list", "--maps", tmp_path / "bad.xodr")  # named by itself: an error
    assert code == ExitCode.MAP_ERROR and "bad.xodr" in err


def test_a_map_with_no_driving_lane_is_a_clear_error(tmp_path, capsys):
    sidewalks = tmp_path / "sidewalks.xodr"
    sidewalks.write_text(BUILTIN_MAP.read_text().replace('type="driving"', 'type="sidewalk"'))
    code, _, err = _run(capsys, "maps", "query", "--maps", sidewalks)
    assert code == ExitCode.NO_ROAD and "has a driving lane" in err
    code, _, err = _run(capsys, "compile", EXAMPLES / "boxed_in.tsg", "-o", tmp_path / "out" / "x.xosc",
                        "--maps", sidewalks, "--no-simulate", "--synthesize", "never")
    assert code == ExitCode.NO_ROAD and "has a driving lane" in err and not (tmp_path / "out").exists()


# -- the LLM: deadlines, replies of any shape, settings from the environment --------------------------------

class _RawServer(LocalHttpServer):
    """Answers every POST with one raw body (or never, when delay_s is long), counting the requests."""

    def __init__(self, body: bytes, content_type: str = "application/json", delay_s: float = 0.0):
        self.requests = 0

        def reply(_request: bytes):
            self.requests += 1
            return content_type, body

        super().__init__(reply, delay_s)


_MESSAGE = {"id": "m", "type": "message", "role": "assistant", "model": "m", "stop_reason": "end_turn",
            "usage": {"input_tokens": 1, "output_tokens": 1}}


@pytest.mark.parametrize("body, content_type", [
    (b"garbage !!", "application/json"),
    (b"<html><body>502 Bad Gateway</body></html>", "text/html"),
    (b'{"id": "m", "type": "message", "content": [{"type": "te', "application/json"),
    (b"{}", "application/json"),
    (json.dumps({**_MESSAGE, "content": None}).encode(), "application/json"),
    (json.dumps({**_MESSAGE, "content": [{"type": "text", "text": None}]}).encode(), "application/json"),
    (b"[1, 2]", "application/json"),
], ids=["garbage", "html", "truncated", "empty-object", "content-null", "text-null", "a-list"])
def test_an_llm_reply_of_any_shape_is_a_lowering_error(tmp_path, capsys, monkeypatch, body, content_type):
    prompt = tmp_path / "p.txt"
    prompt.write_text("the ego turns left")
    with _RawServer(body, content_type) as server:
        monkeypatch.setenv("ANTHROPIC_API_KEY", "test-key")
        monkeypatch.setenv("ANTHROPIC_BASE_URL", server.url)
        code, _, err = _run(capsys, "compile", prompt, "-o", tmp_path / "out" / "s.xosc")
    assert code == ExitCode.LOWERING_FAILED and "the LLM's reply" in err and "internal error" not in err
    assert not (tmp_path / "out").exists()


def test_an_llm_that_never_answers_is_given_up_on_at_the_deadline(tmp_path, capsys, monkeypatch):
    prompt = tmp_path / "p.txt"
    prompt.write_text("the ego turns left")
    with _RawServer(b"{}", delay_s=30) as server:
        monkeypatch.setenv("ANTHROPIC_API_KEY", "test-key")
        monkeypatch.setenv("ANTHROPIC_BASE_URL", server.url)
        monkeypatch.setenv("TTSGC_LLM_TIMEOUT", "2")
        start = time.perf_counter()
        code, _, err = _run(capsys, "lower", prompt)
    assert time.perf_counter() - start < 10  # the deadline plus start-up, on a busy machine
    assert code == ExitCode.LOWERING_FAILED and "no answer within 2 s" in err and "--llm offline" in err


def test_an_unreachable_llm_says_what_to_do_next(tmp_path, capsys, monkeypatch):
    prompt = tmp_path / "p.txt"
    prompt.write_text("the ego turns left")
    monkeypatch.setenv("ANTHROPIC_API_KEY", "test-key")
    monkeypatch.setenv("ANTHROPIC_BASE_URL", "http://127.0.0.1:9")
    code, _, err = _run(capsys, "lower", prompt)
    assert code == ExitCode.LOWERING_FAILED and "use --llm offline" in err


@pytest.mark.parametrize("name, value", [("TTSGC_TEMPERATURE", "abc"), ("TTSGC_MAX_TOKENS", "abc"),
                                         ("TTSGC_MAX_TOKENS", HUGE), ("TTSGC_TEMPERATURE", "nan"),
                                         ("TTSGC_LLM_TIMEOUT", "-1")])
def test_an_unusable_environment_variable_is_a_usage_error_naming_it(tmp_path, capsys, monkeypatch, name, value):
    prompt = tmp_path / "p.txt"
    prompt.write_text("the ego turns left")
    monkeypatch.setenv("ANTHROPIC_API_KEY", "test-key")
    monkeypatch.setenv("ANTHROPIC_BASE_URL", "http://127.0.0.1:9")
    monkeypatch.setenv(name, value)
    code, _, err = _run(capsys, "lower", prompt, "--llm", "anthropic")
    assert code == ExitCode.INVALID_SCENARIO and f"${name}:" in err


# -- usage errors ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("argv", [["compile", "{tsg}", "--variants", "0"], ["eval", "{empty}", "--seeds", "0"],
                                  ["compile", "{tsg}", "--seed", HUGE], ["lower", "{tsg}", "--temperature", "nan"],
                                  ["maps", "query", "--lanes", "-1"]])
def test_numbers_on_the_command_line_are_read_with_limits(tmp_path, capsys, argv):
    argv = [a.format(tsg=EXAMPLES / "boxed_in.tsg", empty=tmp_path) for a in argv]
    with pytest.raises(SystemExit) as exit_:
        main(argv)
    assert exit_.value.code == ExitCode.INVALID_SCENARIO and "error: argument" in capsys.readouterr().err


def test_eval_on_a_folder_with_no_cases_is_a_usage_error(tmp_path, capsys):
    code, _, err = _run(capsys, "eval", tmp_path)
    assert code == ExitCode.INVALID_SCENARIO and "no cases" in err
    (tmp_path / "case.txt").write_text("a car")
    (tmp_path / "suite.toml").write_text("kinds = [")
    code, _, err = _run(capsys, "eval", tmp_path)
    assert code == ExitCode.INVALID_SCENARIO and "suite.toml" in err


# -- outputs: never over an input or a read-only file, only on success, one message ----------------------------

@pytest.mark.parametrize("name", ["s.tsg", "p.txt"])
def test_compile_never_overwrites_its_input(tmp_path, capsys, name):
    source = tmp_path / name
    source.write_bytes((EXAMPLES / f"boxed_in{Path(name).suffix}").read_bytes())
    before = source.read_bytes()
    code, _, err = _run(capsys, "compile", source, "-o", source, "--no-simulate")
    assert code == ExitCode.INVALID_SCENARIO and "never overwrites its input" in err
    assert source.read_bytes() == before and sorted(p.name for p in tmp_path.iterdir()) == [name]


def test_an_output_that_is_a_device_or_pipe_is_refused_and_left_as_it_was(tmp_path, capsys):
    """Writing renames a finished file over the target: over /dev/null or a pipe that would replace it."""
    prompt = tmp_path / "p.txt"
    prompt.write_text("the ego turns left")
    pipe = tmp_path / "pipe.xosc"
    os.mkfifo(pipe)
    for out in (pipe, Path(os.devnull)):
        code, _, err = _run(capsys, "compile", prompt, "-o", out, "--no-simulate")
        assert code == ExitCode.INVALID_SCENARIO and "is not a regular file" in err
    assert stat.S_ISFIFO(pipe.stat().st_mode) and stat.S_ISCHR(Path(os.devnull).stat().st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.txt", "pipe.xosc"]


def test_a_symlink_loop_or_a_device_as_the_scenes_map_is_a_map_error(tmp_path, capsys):
    scene = compiled_example("ambulance_from_behind", tmp_path)
    text = scene.read_text()
    name = re.search(r'LogicFile filepath="([^"]+)"', text).group(1)
    (tmp_path / "a.xodr").symlink_to("b.xodr")
    (tmp_path / "b.xodr").symlink_to("a.xodr")
    for target, why in (("a.xodr", "does not exist"), (os.devnull, "is not a regular file")):
        scene.write_text(text.replace(f'filepath="{name}"', f'filepath="{target}"'))
        for command in (["validate", scene], ["render", scene, "-o", tmp_path / "s.png"]):
            code, _, err = _run(capsys, *command)
            assert code == ExitCode.MAP_ERROR and why in err, err


def test_lint_reads_a_scenario_as_validate_does_refusing_a_doctype(tmp_path, capsys):
    scene = tmp_path / "x.xosc"
    scene.write_text('<?xml version="1.0"?><!DOCTYPE r [<!ENTITY x SYSTEM "file:///etc/passwd">]>'
                     "<OpenSCENARIO><FileHeader/>&x;</OpenSCENARIO>")
    for command in (["lint", "--target", "esmini", scene], ["validate", scene]):
        code, _, err = _run(capsys, *command)
        assert code == ExitCode.INVALID_SCENARIO and "has a DOCTYPE" in err and "refused" in err


def test_an_output_that_is_a_folder_is_a_usage_error(tmp_path, capsys):
    code, _, err = _run(capsys, "compile", EXAMPLES / "boxed_in.tsg", "-o", tmp_path, "--no-simulate")
    assert code == ExitCode.INVALID_SCENARIO and "is a folder" in err and not list(tmp_path.iterdir())


def test_an_output_folder_that_cannot_be_written_is_a_usage_error(tmp_path, capsys):
    code, _, err = _run(capsys, "compile", EXAMPLES / "boxed_in.tsg", "-o", "/proc/ttsgc-test/s.xosc",
                        "--no-simulate")
    assert code == ExitCode.INVALID_SCENARIO and "/proc/ttsgc-test" in err and "cannot be written" in err


def test_a_read_only_output_folder_is_a_usage_error(tmp_path, capsys):
    import os

    folder = tmp_path / "ro"
    folder.mkdir()
    scene = folder / "s.tsg"
    scene.write_text('scenario "x"\nstage a {\n ego   car go_straight\n}\n')
    folder.chmod(0o555)
    try:
        if os.access(folder, os.W_OK):
            pytest.skip("permissions do not bind this user (root)")
        code, _, err = _run(capsys, "compile", scene, "-o", folder / "s.xosc", "--no-simulate")
        assert code == ExitCode.INVALID_SCENARIO and "cannot be written" in err
        code, _, err = _run(capsys, "fmt", scene)  # the file may be written, its folder may not
        assert code == ExitCode.INVALID_SCENARIO and "cannot be written" in err
        assert sorted(p.name for p in folder.iterdir()) == ["s.tsg"]
    finally:
        folder.chmod(0o755)


def test_fmt_refuses_a_read_only_file_and_leaves_it_as_it_was(tmp_path, capsys):
    scene = tmp_path / "s.tsg"
    scene.write_text('scenario "x"\nstage a {\n ego   car go_straight\n}\n')
    scene.chmod(0o444)
    before = scene.stat()
    code, _, err = _run(capsys, "fmt", scene)
    after = scene.stat()
    assert code == ExitCode.INVALID_SCENARIO and "read-only" in err
    assert (after.st_ino, after.st_mode, after.st_uid, after.st_mtime_ns) == \
        (before.st_ino, before.st_mode, before.st_uid, before.st_mtime_ns)


def test_the_lowered_scene_is_written_only_when_the_compile_succeeds(tmp_path, capsys):
    sidewalks = tmp_path / "sidewalks.xodr"
    sidewalks.write_text(BUILTIN_MAP.read_text().replace('type="driving"', 'type="sidewalk"'))
    out = tmp_path / "out"
    code, _, err = _run(capsys, "compile", EXAMPLES / "boxed_in.txt", "-o", out / "s.xosc", "--maps", sidewalks,
                        "--synthesize", "never")
    assert code == ExitCode.NO_ROAD and not out.exists()


def test_a_multi_line_prompt_gives_a_valid_scene_file(tmp_path, capsys):
    prompt = tmp_path / "p.txt"
    prompt.write_text("The ego turns left.\n\nThen a car\r\n stops in front # of it.\x0cquoted\u2028end\n")
    code, _, _ = _run(capsys, "lower", prompt, "-o", tmp_path / "s.tsg")
    assert code == ExitCode.OK
    text = (tmp_path / "s.tsg").read_text()
    assert text.startswith("# Lowered (offline) from: The ego turns left.\n# Then a car\n")
    assert _run(capsys, "check", tmp_path / "s.tsg")[0] == ExitCode.OK


def test_a_folder_given_as_the_scene_is_reported_once(tmp_path, capsys):
    code, _, err = _run(capsys, "compile", tmp_path)
    assert code == ExitCode.INVALID_SCENARIO and err.count("error:") == 1 and str(tmp_path) in err


def test_output_into_a_closed_pipe_ends_quietly():
    import subprocess
    import sys

    child = subprocess.Popen([sys.executable, "-m", "ttsgc", "maps", "list"], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, cwd=ROOT)
    child.stdout.close()  # as `| head` does once it has read enough
    err = child.stderr.read()
    assert child.wait(timeout=60) == 141 and err == b""


# -- the safe map reader before netconvert; netconvert's refusal; caches that check what they read -------------

def _compiled_unchecked(tmp_path: Path, capsys) -> Path:
    out = tmp_path / "scene" / "s.xosc"
    assert _run(capsys, "compile", EXAMPLES / "boxed_in.tsg", "-o", out, "--no-simulate")[0] == ExitCode.OK
    return out


@pytest.mark.parametrize("map_text", ['<?xml version="1.0"?>\n<!DOCTYPE x [<!ENTITY a "b">]>\n<OpenDRIVE/>\n',
                                      "root:x:0:0:root:/root:/bin/bash\n"], ids=["doctype", "system-file"])
def test_validate_reads_the_map_safely_before_netconvert_sees_it(tmp_path, capsys, monkeypatch, map_text):
    import ttsgc.simulate.players.sumo.network as network

    scene = _compiled_unchecked(tmp_path, capsys)
    hostile = tmp_path / "hostile.xodr"
    hostile.write_text(map_text)
    text, swapped = re.subn(r'(<LogicFile filepath=")[^"]*"', rf'\g<1>{hostile}"', scene.read_text())
    assert swapped == 1
    scene.write_text(text)
    monkeypatch.setattr(network, "netconvert_binary", lambda: pytest.fail("netconvert saw the file"))
    code, _, err = _run(capsys, "validate", scene)
    assert code == ExitCode.MAP_ERROR and f"{hostile}:" in err


def test_a_map_netconvert_refuses_is_a_map_error_naming_the_users_file(tmp_path, capsys, monkeypatch):
    import ttsgc.simulate.players.sumo.network as network

    monkeypatch.setenv("TTSGC_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setattr(network, "netconvert_binary", lambda: "false")  # a netconvert that refuses every map
    user_map = tmp_path / "mine.xodr"
    user_map.write_bytes(BUILTIN_MAP.read_bytes())
    code, _, err = _run(capsys, "compile", EXAMPLES / "boxed_in.tsg", "-o", tmp_path / "out" / "s.xosc",
                        "--maps", user_map)
    assert code == ExitCode.MAP_ERROR and f"{user_map.resolve()}: netconvert cannot convert the map" in err
    assert "ttsgc-" not in err and not (tmp_path / "out").exists()


@pytest.mark.parametrize("damage", [b"garbage", None, b"<net/>"], ids=["garbage", "truncated", "empty-net"])
def test_a_corrupt_network_cache_entry_is_rebuilt(tmp_path, monkeypatch, damage):
    from ttsgc.simulate.players.sumo.network import network_for

    monkeypatch.setenv("TTSGC_CACHE_DIR", str(tmp_path))
    good = network_for(BUILTIN_MAP)
    data = good.path.read_bytes()
    good.path.write_bytes(damage if damage is not None else data[: len(data) // 2])
    again = network_for(BUILTIN_MAP)
    assert again.path == good.path and again.offset == good.offset
    edges = lambda text: re.findall(rb'<edge id="([^"]+)"', text)  # noqa: E731 - netconvert stamps the time
    assert edges(good.path.read_bytes()) == edges(data) != []


def test_a_cache_path_that_is_a_file_falls_back_to_a_temporary_cache(tmp_path, capsys, monkeypatch):
    blocker = tmp_path / "cache-is-a-file"
    blocker.write_text("")
    monkeypatch.setenv("TTSGC_CACHE_DIR", str(blocker))
    code, _, err = _run(capsys, "compile", EXAMPLES / "boxed_in.tsg", "-o", tmp_path / "out" / "s.xosc")
    assert code == ExitCode.OK and "using a temporary one" in err and (tmp_path / "out" / "s.xosc").is_file()


# -- SIGTERM: no temporary folder and no child process outlives ttsgc -------------------------------------------

def _children(pid: int) -> set[int]:
    found = set()
    for task in Path(f"/proc/{pid}/task").glob("*"):
        try:
            found |= {int(c) for c in (task / "children").read_text().split()}
        except OSError:
            pass
    return found | {g for c in found for g in _children(c)}


def _alive(pid: int) -> bool:
    try:
        return Path(f"/proc/{pid}/stat").read_text().split(") ")[-1][0] not in "ZX"
    except OSError:
        return False


def test_sigterm_during_compile_leaves_no_temporary_folder_and_no_child(tmp_path):
    import os
    import signal
    import subprocess
    import sys

    if not Path("/proc/self/task").is_dir():
        pytest.skip("needs /proc")
    scratch = tmp_path / "tmp"
    scratch.mkdir()
    slow_netconvert = tmp_path / "netconvert"  # a netconvert that hangs, so the signal surely finds it running
    slow_netconvert.write_text("#!/bin/sh\nexec sleep 60\n")
    slow_netconvert.chmod(0o755)
    env = {**os.environ, "TMPDIR": str(scratch), "TTSGC_CACHE_DIR": str(tmp_path / "cache"), "PYTHONPATH": str(ROOT),
           "NETCONVERT_BINARY": str(slow_netconvert)}
    child = subprocess.Popen([sys.executable, "-m", "ttsgc", "compile", str(EXAMPLES / "boxed_in.tsg"), "-o",
                              str(tmp_path / "out" / "s.xosc")], env=env, stderr=subprocess.PIPE)
    seen: set[int] = set()
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and child.poll() is None:
        grandchildren = _children(child.pid)
        seen |= grandchildren
        if grandchildren and list(scratch.glob("ttsgc-*")):  # netconvert runs, inside the scratch folder's life
            break
        time.sleep(0.02)
    assert child.poll() is None and seen, "the compile ended before netconvert could be caught running"
    child.send_signal(signal.SIGTERM)
    err = child.stderr.read().decode()
    assert child.wait(timeout=60) == 143 and "terminated" in err and "Traceback" not in err, err
    time.sleep(0.2)
    assert not list(scratch.glob("ttsgc-*")) and not [pid for pid in seen if _alive(pid)]
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("lanes", ['"abc"', "Infinity", "1e308", '"9' + "9" * 400 + '"', "2.0"])
def test_a_plans_lane_count_of_any_shape_is_read_with_limits(tmp_path, capsys, shared, lanes):
    plan = tmp_path / "agent_output.json"
    original = (shared / "ttsg-plans" / "daily_traffic" / "3" / "agent_output.json").read_text()
    plan.write_text(re.sub(r'"number_of_lanes": \d+', f'"number_of_lanes": {lanes}', original))
    code, _, err = _run(capsys, "import-ttsg", plan, "-o", tmp_path / "s.tsg")
    assert code == ExitCode.OK and (lanes == "2.0" or "number_of_lanes" in err)
