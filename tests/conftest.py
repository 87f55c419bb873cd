"""Shared paths and fixtures. Tests that need ../shared (real maps, the paper's plans) skip without it."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "examples"
SHARED = ROOT.parent / "shared"


def asam_errors(tool: str, bundle: str, document: Path, folder: Path) -> list[str]:
    """Run an ASAM quality checker (qc_opendrive / xodrBundle, qc_openscenario / xoscBundle) on a file and
    return the descriptions of its error-level issues; skips when the checker is not installed."""
    import subprocess
    import sys

    from lxml import etree

    checker = Path(sys.executable).parent / tool
    if not checker.exists():
        pytest.skip(f"{tool} is not installed")
    report = folder / f"{document.stem}.{bundle}.xqar"
    config = folder / f"{document.stem}.{bundle}.xml"
    config.write_text(f'<?xml version="1.0" encoding="UTF-8"?><Config><Param name="InputFile" value="{document}"/>'
                      f'<CheckerBundle application="{bundle}"><Param name="resultFile" value="{report}"/>'
                      f'</CheckerBundle></Config>')
    subprocess.run([str(checker), "-c", str(config)], capture_output=True, check=True, cwd=folder)
    results = etree.parse(str(report))
    assert [c for c in results.iter("Checker") if c.get("status") == "completed"], "no check ran"
    return [i.get("description") or "" for i in results.iter("Issue") if i.get("level") == "1"]


def example_scenarios() -> list[Path]:
    return sorted(EXAMPLES.glob("*.tsg"))


@pytest.fixture
def shared() -> Path:
    if not SHARED.is_dir():
        pytest.skip("../shared is not present")
    return SHARED


@pytest.fixture(scope="session", autouse=True)
def _private_cache(tmp_path_factory):
    """Every test run indexes into a fresh cache of its own, never the user's; and a test plays in the players
    it asks for: esmini only through a fixture that names it, never because the user's environment or PATH
    has one (a test of SUMO's verdict, or a module's fixture, would otherwise get esmini's too)."""
    import os

    os.environ["TTSGC_CACHE_DIR"] = str(tmp_path_factory.mktemp("cache"))
    os.environ["TTSGC_ESMINI"] = str(tmp_path_factory.getbasetemp() / "no-esmini")
    yield


def pytest_addoption(parser):
    parser.addoption("--regen-golden", action="store_true",
                     help="rewrite examples/golden/*.xosc from the current compiler (review the diff!)")


@pytest.fixture
def regen_golden(request) -> bool:
    return request.config.getoption("--regen-golden")


def compiled_example(name: str, folder: Path, version: str = "1.3", only: tuple[str, str] | None = None) -> Path:
    """An example compiled onto its best-ranked road, or onto the road `only` names (for a test that needs a
    particular geometry, whatever the ranking's tie order), written with its map beside it."""
    from ttsgc.language import parse_file
    from ttsgc.pipeline import compile_scenario, write

    out = folder / f"{name}.xosc"
    write(compile_scenario(parse_file(EXAMPLES / f"{name}.tsg"), out, version=version, only=only), out)
    return out


def edit_xosc(path: Path, change) -> Path:
    """Apply change(root) to a scene file in place: a file edited the way a person (or an old emitter) would."""
    from lxml import etree

    tree = etree.parse(str(path))
    change(tree.getroot())
    tree.write(str(path))
    return path


class LocalHttpServer:
    """A server on 127.0.0.1 that answers every POST with reply(request body) -> (content type, bytes), after
    delay_s: the tests' stand-in for an LLM endpoint, since no network is reached from here."""

    def __init__(self, reply, delay_s: float = 0.0):
        import threading
        import time
        from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

        class Handler(BaseHTTPRequestHandler):
            def do_POST(self):  # noqa: N802 - the http.server API
                content_type, data = reply(self.rfile.read(int(self.headers["Content-Length"])))
                time.sleep(delay_s)
                self.send_response(200)
                self.send_header("Content-Type", content_type)
                self.send_header("Content-Length", str(len(data)))
                self.end_headers()
                self.wfile.write(data)

            def log_message(self, *args):
                pass

        class QuietServer(ThreadingHTTPServer):
            daemon_threads = True

            def handle_error(self, request, client_address):
                pass  # a client that gave up (a deadline test) is the point, not a fault

        self.server = QuietServer(("127.0.0.1", 0), Handler)
        self.thread = threading.Thread(target=self.server.serve_forever, daemon=True)

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.server.server_address[1]}"

    def __enter__(self):
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.server.shutdown()
        self.server.server_close()
