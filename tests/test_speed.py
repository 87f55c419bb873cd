"""Start-up and scaling: each command imports what it uses, and the lean imports still give whole libraries."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def fresh(code: str):
    """Run code in a fresh interpreter (the repository first on the path); the JSON of its last line."""
    done = subprocess.run([sys.executable, "-c", f"import sys, json\n{code}"], capture_output=True, text=True,
                          cwd=ROOT, env=dict(os.environ, PYTHONPATH=str(ROOT)))  # the test run's private cache too
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.splitlines()[-1])


def modules_after(code: str) -> set[str]:
    """The modules a fresh interpreter holds after running code."""
    return set(fresh(f"{code}\nprint(json.dumps(sorted(sys.modules)))"))


HEAVY = ("scipy", "xmlschema", "networkx", "numpy", "jinja2", "scenariogeneration.xodr", "qc_openscenario.checks")


def test_compiling_and_proving_loads_neither_the_opendrive_writer_nor_scipy_xmlschema_networkx_numpy(tmp_path):
    out = tmp_path / "blocking.xosc"
    compile_ = f"from ttsgc.cli import main\nassert main(['compile', 'examples/blocking.txt', '-o', {str(out)!r}]) == 0"
    modules_after(compile_)  # the first run builds the SUMO network with netconvert (through sumolib)
    loaded = modules_after(compile_)
    assert out.is_file() and {"scenariogeneration.xosc.actions", "libsumo"} <= loaded
    assert not [m for m in loaded if m.split(".")[0] in HEAVY or m in HEAVY]


def test_commands_that_do_not_simulate_do_not_load_sumo():
    loaded = modules_after("from ttsgc.cli import main\nmain(['check', 'examples/blocking.tsg'])")
    assert not {"libsumo", "ttsgc.pipeline", "ttsgc.emit.xosc", "lxml.etree"} & loaded


def test_the_lean_openscenario_writer_completes_to_the_whole_library_when_asked():
    code = """
import ttsgc.emit.xosc
from scenariogeneration import xosc
writer = {k for k in vars(xosc) if not k.startswith('__')}
assert 'xmlschema' not in sys.modules
xosc.ParseOpenScenario  # the reader: the package's own __init__ runs now
import scenariogeneration
assert scenariogeneration.ScenarioGenerator and scenariogeneration.xodr.OpenDrive
whole = {k for k in vars(xosc) if not k.startswith('__')}
assert writer < whole and 'CatalogLoader' in whole, whole - writer
"""
    assert "scenariogeneration.xodr" in modules_after(code)


def test_the_lean_writer_has_every_name_the_package_import_gives():
    names = "print(json.dumps(sorted(k for k in vars(xosc) if not k.startswith('__'))))"
    lean = fresh(f"import ttsgc.emit.xosc\nfrom scenariogeneration import xosc\nxosc.ParseOpenScenario\n{names}")
    plain = fresh(f"from scenariogeneration import xosc\n{names}")
    assert lean == plain and len(plain) > 200


# -- caches across processes ------------------------------------------------------------------------------

MAP = ROOT / "maps" / "town_row.xodr"


def _fresh_process_memory(monkeypatch):
    """Forget what this process parsed, as a new process would, and fail on any parse from the file."""
    from ttsgc.roads import opendrive

    monkeypatch.setattr(opendrive, "_PARSED", {})
    return opendrive


def test_a_parsed_map_is_cached_by_content_and_loads_without_parsing(tmp_path, monkeypatch):
    monkeypatch.setenv("TTSGC_CACHE_DIR", str(tmp_path))
    opendrive = _fresh_process_memory(monkeypatch)
    first = opendrive.load_opendrive(MAP)
    assert len(list((tmp_path / "index").glob("*.pickle"))) == 1
    _fresh_process_memory(monkeypatch)
    monkeypatch.setattr(opendrive, "read_opendrive", lambda *a: (_ for _ in ()).throw(AssertionError("parsed")))
    copy = tmp_path / "elsewhere.xodr"
    copy.write_bytes(MAP.read_bytes())
    again = opendrive.load_opendrive(copy)
    assert again == replace(first, path=str(copy))


def test_the_map_an_index_describes_is_found_by_its_hash_without_reading_the_file(tmp_path, monkeypatch):
    from ttsgc.roads.index import load_index

    monkeypatch.setenv("TTSGC_CACHE_DIR", str(tmp_path))
    opendrive = _fresh_process_memory(monkeypatch)
    index = load_index(MAP)  # indexing parses the map and caches the parse
    first = opendrive.load_opendrive(MAP)
    _fresh_process_memory(monkeypatch)
    read = opendrive.read_map_bytes
    monkeypatch.setattr(opendrive, "read_map_bytes", lambda *a: (_ for _ in ()).throw(AssertionError("read")))
    assert opendrive.load_opendrive(MAP, sha256=index.sha256) == first
    monkeypatch.setattr(opendrive, "read_map_bytes", read)
    assert opendrive.load_opendrive(MAP, sha256="0" * 64) == first  # a hash nobody cached: the file is read


def test_a_corrupt_parsed_map_entry_is_parsed_again_and_rewritten(tmp_path, monkeypatch):
    monkeypatch.setenv("TTSGC_CACHE_DIR", str(tmp_path))
    opendrive = _fresh_process_memory(monkeypatch)
    first = opendrive.load_opendrive(MAP)
    entry = next((tmp_path / "index").glob("*.pickle"))
    good = entry.read_bytes()
    for damaged in (b"", good[: len(good) // 2], b"not a pickle at all", good.replace(b"Road", b"Rope")):
        entry.write_bytes(damaged)
        _fresh_process_memory(monkeypatch)
        assert opendrive.load_opendrive(MAP) == first
        assert entry.read_bytes() == good  # rewritten


CALLED: list[str] = []


def _payload():
    CALLED.append("ran")


class _Hostile:
    def __reduce__(self):
        return _payload, ()


def test_a_cache_entry_cannot_make_the_loader_run_other_code(tmp_path, monkeypatch):
    import pickle

    monkeypatch.setenv("TTSGC_CACHE_DIR", str(tmp_path))
    opendrive = _fresh_process_memory(monkeypatch)
    first = opendrive.load_opendrive(MAP)
    entry = next((tmp_path / "index").glob("*.pickle"))
    sha = opendrive.hashlib.sha256(MAP.read_bytes()).hexdigest()
    entry.write_bytes(pickle.dumps((sha, _Hostile())))
    _fresh_process_memory(monkeypatch)
    assert opendrive.load_opendrive(MAP) == first
    assert CALLED == []


def test_the_net_offset_is_read_from_the_head_of_the_file(tmp_path):
    from ttsgc.simulate.players.sumo.network import net_head

    net = tmp_path / "x.net.xml"
    net.write_text('<?xml version="1.0"?>\n<net version="1.20"><location netOffset="116.00,-390.50" '
                   'convBoundary="0,0,1,1"/><edge id="e"><lane id="e_0" index="0" shape="0,0 1,1"/></edge>'
                   '<broken')  # past the first edge nothing is read
    assert net_head(net) == ((116.0, -390.5), ["net", "location", "edge"])
    net.write_text('<net version="1.20"><edge id="e"/></net>')
    assert net_head(net) == ((0.0, 0.0), ["net", "edge"])


def test_simulating_loads_libsumo_without_numpy_and_sumolib_keeps_its_numpy_functions():
    code = """
from ttsgc.simulate.players.sumo.executor import play
from ttsgc.simulate.lean_libsumo import load_libsumo
loaded = load_libsumo()
import libsumo
assert loaded is libsumo and libsumo.simulation is not None
assert 'numpy' not in sys.modules and 'ssl' not in sys.modules and 'urllib.request' not in sys.modules
import sumolib.miscutils, urllib.request
assert sumolib.miscutils.urlopen("data:,ttsgc").read() == b"ttsgc"  # the real urlopen, imported when called
assert urllib.request.urlopen is not sumolib.miscutils.urlopen and 'ssl' in sys.modules
import sumolib.statistics as st
assert st.sqrt(6.25) == 2.5 and 'numpy' in sys.modules  # numpy's own sqrt, imported when first called
st.set_printoptions(precision=2)
print(json.dumps(type(st.sqrt(4.0)).__module__))
"""
    assert fresh(code) == "numpy"


def test_a_grammar_analysis_cached_on_disk_parses_as_the_grammar_built_afresh(tmp_path, monkeypatch):
    from lark import Lark

    from ttsgc import grammars
    from ttsgc.resources import resource_dir

    monkeypatch.setenv("TTSGC_CACHE_DIR", str(tmp_path))
    text = (resource_dir("grammar") / "scenario.lark").read_text(encoding="utf-8")
    afresh = Lark(text, parser="lalr", propagate_positions=True, maybe_placeholders=False)
    scenes = [p.read_text(encoding="utf-8") for p in sorted((ROOT / "examples").glob("*.tsg"))]
    for attempt in ("written", "read", "corrupt"):
        if attempt == "corrupt":
            [cached] = (tmp_path / "parsers").glob("scenario-*.lark")
            cached.write_bytes(b"not a parser")
        parser = grammars.lalr_parser("scenario.lark", propagate_positions=True, maybe_placeholders=False)
        assert [parser.parse(s) for s in scenes] == [afresh.parse(s) for s in scenes], attempt
    assert sorted(p.name.split("-")[0] for p in (tmp_path / "parsers").iterdir()) == ["scenario"]  # no scratch left


def test_the_collision_check_skips_only_pairs_too_far_apart_to_touch():
    """The cheap reach test before the exact box distance never hides a contact: boxes that touch or overlap
    are within their two reaches, and boxes just past them are apart."""
    import math
    import random

    from ttsgc.simulate.judge import _reach, box_distance
    from ttsgc.simulate.trace import Body, Sample

    rng = random.Random(7)
    touching = 0
    for _ in range(4000):
        body_a = Body(length=rng.uniform(0.5, 12), width=rng.uniform(0.5, 3))
        body_b = Body(length=rng.uniform(0.5, 12), width=rng.uniform(0.5, 3))
        a = Sample(t=0.0, x=0.0, y=0.0, h=rng.uniform(-math.pi, math.pi), speed=0.0)
        reach = _reach(body_a) + _reach(body_b)
        d = rng.uniform(0, reach * 1.2)
        angle = rng.uniform(-math.pi, math.pi)
        b = Sample(t=0.0, x=d * math.cos(angle), y=d * math.sin(angle), h=rng.uniform(-math.pi, math.pi), speed=0.0)
        if box_distance(a, body_a, b, body_b) <= 0.0:
            touching += 1
            assert math.hypot(b.x - a.x, b.y - a.y) <= reach
        elif d > reach:
            assert box_distance(a, body_a, b, body_b) > 0.0
    assert touching > 500  # the draw does test contacts
