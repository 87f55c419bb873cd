"""`ttsgc serve`: a served command prints, writes and exits as the command run alone, Ctrl-C reaches it, and
a server that is absent, dead, stopped or of another installation is never a difference the user sees."""

from __future__ import annotations

import json
import os
import signal
import stat
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"

pytestmark = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the server passes descriptors "
                                "over a Unix socket; tested on Linux")


def environment(cache: Path, **extra: str) -> dict[str, str]:
    env = dict(os.environ, PYTHONPATH=str(ROOT), TTSGC_CACHE_DIR=str(cache), **extra)
    env.pop("TTSGC_NO_SERVER", None)
    env.pop("ANTHROPIC_API_KEY", None)
    return env


def ttsgc(args: list[str], env: dict, cwd: Path, stdin: bytes | None = None) -> tuple[int, bytes, bytes]:
    done = subprocess.run([sys.executable, "-m", "ttsgc", *args], env=env, cwd=cwd, input=stdin,
                          capture_output=True, timeout=300)
    return done.returncode, done.stdout, done.stderr


def servers(env: dict) -> list[dict]:
    """What `ttsgc serve --status` reports, read from the server's own answer."""
    code = ("import json, ttsgc.server as s\n"
            "print(json.dumps([dict(a, path=str(p)) for p, a in s.status()]))")
    done = subprocess.run([sys.executable, "-c", code], env=env, cwd=ROOT, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def served_count(env: dict) -> int:
    return sum(answer["served"] for answer in servers(env))


@pytest.fixture(scope="module")
def served(tmp_path_factory):
    """A server of this checkout on a cache folder of its own, stopped at the end."""
    cache = tmp_path_factory.mktemp("served-cache")
    env = environment(cache)
    code, out, err = ttsgc(["serve", "--idle", "600"], env, ROOT)
    assert code == 0, err
    assert b"started, pid" in out
    yield env
    code, out, err = ttsgc(["serve", "--stop"], env, ROOT)
    assert (code, out) == (0, b"1 server(s) stopped\n"), err
    assert servers(env) == [] and not list((cache / "server").glob("*.sock"))


def test_served_commands_print_write_and_exit_as_the_command_run_alone(served, tmp_path):
    scene = tmp_path / "shared-input" / "blocking.xosc"
    scene.parent.mkdir()
    code, _, err = ttsgc(["compile", str(EXAMPLES / "blocking.tsg"), "-o", str(scene), "--player", "sumo"],
                         dict(served, TTSGC_NO_SERVER="1"), tmp_path)
    assert code == 0, err
    cases = [  # relative paths: the served command runs in the client's folder
        ["validate", "--player", "sumo", str(scene), "--report", "report.json"],
        ["compile", str(EXAMPLES / "left_turn_oncoming.tsg"), "-o", "out/left.xosc", "--player", "sumo"],
        ["check", "missing.tsg"],  # an error: exit 2
        ["--debug", "validate", "--player", "sumo", "missing.xosc"],
        ["validate"],  # a usage error: argparse's exit 2
        ["validate", "--help"],  # argparse's exit 0
        ["check", "/dev/stdin"],  # reads its standard input
    ]
    stdin = (EXAMPLES / "blocking.tsg").read_bytes()
    before = served_count(served)
    for args in cases:
        results = {}
        for way, env in (("alone", dict(served, TTSGC_NO_SERVER="1")), ("served", served)):
            cwd = tmp_path / way / args[0].strip("-")
            cwd.mkdir(parents=True, exist_ok=True)
            code, out, err = ttsgc(args, env, cwd, stdin=stdin)
            files = {str(p.relative_to(cwd)): p.read_bytes() for p in sorted(cwd.rglob("*")) if p.is_file()}
            results[way] = (code, out, err, files)
        assert results["served"] == results["alone"], args
    assert served_count(served) == before + len(cases)  # every one was answered by the server


def _wait_for(condition, timeout: float = 30.0) -> None:
    deadline = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < deadline, "timed out"
        time.sleep(0.05)


def _server_children(env: dict) -> list[int]:
    pids = []
    for answer in servers(env):
        for task in Path(f"/proc/{answer['pid']}/task").iterdir():
            if not (task / "children").exists():
                pytest.skip("this kernel does not list a process's children in /proc")
            pids += [int(p) for p in (task / "children").read_text().split()]
    return pids


def test_ctrl_c_on_the_client_interrupts_the_served_command(served, tmp_path):
    before = served_count(served)
    out, err = tmp_path / "out", tmp_path / "err"
    with out.open("wb") as stdout, err.open("wb") as stderr:
        client = subprocess.Popen([sys.executable, "-m", "ttsgc", "check", "/dev/stdin"], env=served, cwd=tmp_path,
                                  stdin=subprocess.PIPE, stdout=stdout, stderr=stderr)
    try:
        _wait_for(lambda: served_count(served) > before)  # the command is running in the server, reading stdin
        time.sleep(0.5)
        client.send_signal(signal.SIGINT)  # its standard input stays open: only the signal can end the command
        client.wait(timeout=30)
    finally:
        client.kill()
        client.stdin.close()
    assert (client.returncode, out.read_bytes(), err.read_bytes()) == (130, b"", b"ttsgc: interrupted\n")
    _wait_for(lambda: not _server_children(served))


def test_a_client_that_dies_ends_its_command_in_the_server(served, tmp_path):
    before = served_count(served)
    client = subprocess.Popen([sys.executable, "-m", "ttsgc", "check", "/dev/stdin"], env=served, cwd=tmp_path,
                              stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        _wait_for(lambda: served_count(served) > before)
        _wait_for(lambda: bool(_server_children(served)))
        client.kill()
        client.wait()
        _wait_for(lambda: not _server_children(served))
    finally:
        client.kill()


def test_the_client_loads_only_the_standard_library_before_it_is_answered(served, tmp_path):
    code = """
import sys
baseline = set(sys.modules)
def foreign():
    return sorted(m for m in set(sys.modules) - baseline if m.split(".")[0] not in sys.stdlib_module_names)
from ttsgc.forward import forward
status = forward(["check", "missing.tsg"])  # exit 2, said on stderr
print(status, foreign())
import ttsgc.cli  # the console entry point's module, imported before its main() forwards
print(foreign())
"""
    for env, status in ((served, "2"), (dict(served, TTSGC_NO_SERVER="1"), "None")):
        done = subprocess.run([sys.executable, "-c", code], env=env, cwd=tmp_path, capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        first, console = done.stdout.splitlines()[-2:]
        answered, forwarding = first.split(" ", 1)
        assert answered == status
        assert eval(forwarding) == ["ttsgc", "ttsgc.forward"]  # python -m ttsgc
        assert [m for m in eval(console) if m.split(".")[0] != "ttsgc"] == []  # the console script: ttsgc's own,
        assert len(eval(console)) <= 6  # small modules of the standard library only (cli, errors, files, numbers)


def test_the_socket_is_private_to_its_user(served):
    folder = Path(served["TTSGC_CACHE_DIR"]) / "server"
    assert stat.S_IMODE(folder.stat().st_mode) == 0o700
    sockets = list(folder.glob("*.sock"))
    assert len(sockets) == 1 and stat.S_IMODE(sockets[0].stat().st_mode) == 0o600


def test_a_client_of_another_installation_is_refused_and_runs_the_command_itself(served, monkeypatch):
    from ttsgc import forward

    monkeypatch.setenv("TTSGC_CACHE_DIR", served["TTSGC_CACHE_DIR"])
    real = subprocess.run([sys.executable, "-c", "from ttsgc import forward; print(forward.socket_path())"],
                          env=served, cwd=ROOT, capture_output=True, text=True, check=True).stdout.strip()
    assert Path(real).exists()  # the server's own socket (this process may import an installed copy of ttsgc)
    monkeypatch.setattr(forward, "server_key", lambda: "0.0.0-another")
    monkeypatch.setattr(forward, "socket_path", lambda key=None: real)
    before = served_count(served)
    assert forward.forward(["validate", "--help"]) is None  # refused: nothing ran, the caller runs it
    assert served_count(served) == before


def _without_timings(summary: Path) -> list[dict]:
    return [{k: v for k, v in row.items() if not k.startswith("seconds")}
            for row in json.loads(summary.read_text())["rows"]]


def test_a_served_batch_forks_its_workers_warm_and_writes_what_the_batch_run_alone_writes(served, tmp_path):
    prompts = tmp_path / "prompts"
    prompts.mkdir()
    for name in ("blocking.tsg", "left_turn_oncoming.tsg", "crushing.txt"):
        (prompts / name).write_bytes((EXAMPLES / name).read_bytes())
    before = served_count(served)
    code, out, err = ttsgc(["batch", "prompts", "-o", "served", "--workers", "2"], served, tmp_path)
    assert code == 0, err
    assert served_count(served) == before + 1
    code, _, err = ttsgc(["batch", "prompts", "-o", "alone", "--workers", "2"], dict(served, TTSGC_NO_SERVER="1"),
                         tmp_path)
    assert code == 0, err
    scenes = sorted(p.name for p in (tmp_path / "alone").glob("*.xosc"))
    assert len(scenes) == 3 and scenes == sorted(p.name for p in (tmp_path / "served").glob("*.xosc"))
    for name in scenes:
        assert (tmp_path / "served" / name).read_bytes() == (tmp_path / "alone" / name).read_bytes()
    assert _without_timings(tmp_path / "served" / "summary.json") == _without_timings(tmp_path / "alone" / "summary.json")


def test_a_batch_on_ray_runs_in_the_client(served, monkeypatch):
    from ttsgc import forward

    monkeypatch.setenv("TTSGC_CACHE_DIR", served["TTSGC_CACHE_DIR"])
    before = served_count(served)
    for argv in (["batch", "in", "-o", "out", "--ray", "local"], ["eval", "examples", "--ray=local"], ["serve"]):
        assert forward.forward(argv) is None  # nothing was sent: the caller runs it
    assert served_count(served) == before


def test_a_dead_or_idle_server_is_never_a_difference_and_a_long_cache_path_works(tmp_path):
    cache = tmp_path / ("a-long-folder-name-" * 5) / "cache"  # past AF_UNIX's 107 bytes
    env = environment(cache)
    assert len(str(cache / "server" / "ttsgc-0.1.0-0123456789abcdef.sock")) > 108
    code, out, err = ttsgc(["serve", "--idle", "600"], env, tmp_path)
    assert code == 0, err
    [answer] = servers(env)
    args = ["compile", str(EXAMPLES / "blocking.tsg"), "-o", "b.xosc", "--no-simulate"]
    assert ttsgc(args, env, tmp_path)[0] == 0 and servers(env)[0]["served"] == 1
    os.kill(answer["pid"], signal.SIGKILL)  # its socket file stays behind
    _wait_for(lambda: servers(env) == [])
    (tmp_path / "b.xosc").unlink()
    assert ttsgc(args, env, tmp_path)[0] == 0 and (tmp_path / "b.xosc").is_file()  # run by the client itself
    code, out, err = ttsgc(["serve", "--idle", "1"], env, tmp_path)  # over the dead one's socket
    assert code == 0 and b"started" in out, err
    _wait_for(lambda: servers(env) == [], timeout=30)  # idle for a second: it stops by itself
    assert not list((cache / "server").glob("*.sock"))


def test_an_edited_checkout_is_another_installation(tmp_path):
    """The key (the socket's name) changes with any file of the package or its grammars, and with where it is."""
    import shutil

    for name in ("ttsgc", "grammar", "templates"):
        shutil.copytree(ROOT / name, tmp_path / "copy" / name, ignore=shutil.ignore_patterns("__pycache__"))

    def key(where: Path) -> str:
        done = subprocess.run([sys.executable, "-c", "from ttsgc.forward import server_key; print(server_key())"],
                              env=dict(os.environ, PYTHONPATH=str(where)), cwd=tmp_path, capture_output=True,
                              text=True)
        assert done.returncode == 0, done.stderr
        return done.stdout.strip()

    copy = tmp_path / "copy"
    first = key(copy)
    assert first == key(copy) and first != key(ROOT)
    grammar = copy / "grammar" / "scenario.lark"
    grammar.write_text(grammar.read_text(encoding="utf-8") + "\n", encoding="utf-8")
    edited = key(copy)
    assert edited != first
    stat_ = (copy / "ttsgc" / "cli.py").stat()
    os.utime(copy / "ttsgc" / "cli.py", ns=(stat_.st_atime_ns, stat_.st_mtime_ns + 1_000_000_000))
    assert key(copy) not in (first, edited)


def test_a_server_that_cannot_make_its_folder_says_where_and_exits_2(tmp_path):
    (tmp_path / "server").write_text("a file where the folder would go")
    code, out, err = ttsgc(["serve"], environment(tmp_path), tmp_path)
    assert (code, out) == (2, b"")
    assert err.startswith(f"ttsgc: error: {tmp_path / 'server'}: cannot make the server's folder".encode())
