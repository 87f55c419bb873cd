"""Property: whatever a map file says, `maps list` and `compile` end with a documented exit code other than 1
(an internal fault), in bounded time, touching no file but their output. The maps are valid built-in ones with
attribute values replaced (numbers at the extremes, words, nothing), children removed or repeated.

The default run tries a few dozen maps without simulation; `pytest -m slow` tries many more and simulates."""

from __future__ import annotations

import contextlib
import io
import signal
import time
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from lxml import etree

from conftest import ROOT
from ttsgc.cli import main
from ttsgc.errors import ExitCode

BASE_MAPS = [ROOT / "maps" / "tjunction_1lane_stop.xodr", ROOT / "maps" / "avenue_2lane.xodr"]
SCENE = 'scenario "fuzz"\nstage a {\n    ego car go_straight\n    car c1 at front stop\n}\n'
DOCUMENTED = {int(code) for code in ExitCode} - {int(ExitCode.INTERNAL)}
TIME_LIMIT_S = 30.0  # per command; a hang is minutes (the machine is shared, so the limit is generous)

EXTREMES = ["nan", "-nan", "inf", "-inf", "Infinity", "1e308", "-1e308", "1e-308", "5e-324", "1e300", "1e12",
            "-1e12", "0", "-0", "-1", "1", "0.0001", "9" * 400, "-" + "9" * 40, "abc", "", " ", "0x1F", "1,5",
            "1e", "12abc", "+", "\u0661\u0662", "1e999", "-1e999"]


def _elements(base: Path) -> list[etree._Element]:
    return list(etree.parse(str(base)).getroot().iter())


_BASE_SIZES = {path: len(_elements(path)) for path in BASE_MAPS}

attribute_values = st.one_of(st.sampled_from(EXTREMES),
                             st.floats(allow_nan=True, allow_infinity=True).map(repr),
                             st.integers(min_value=-10**30, max_value=10**30).map(str))

# (kind, which element or road, which attribute, value): "set" one attribute of any element; "remove" or
# "repeat" an element; "stretch" a road (its length and its geometries' lengths together); "retype" every lane;
# "spiral" turns a road's first geometry into a clothoid of the value's curvature.
mutation = st.tuples(st.sampled_from(["set", "set", "remove", "repeat", "stretch", "retype", "spiral"]),
                     st.integers(min_value=0), st.integers(min_value=0),
                     st.one_of(attribute_values, st.sampled_from(["1e300", "1e12", "1e6", "sidewalk", "none", "0.5"])))


def mutate(base: Path, mutations) -> bytes:
    """Apply (kind, element, attribute, value) mutations to a parsed copy of a base map."""
    tree = etree.parse(str(base))
    for kind, element_index, attribute_index, value in mutations:
        elements = list(tree.getroot().iter())
        element = elements[element_index % len(elements)]
        if kind == "set":
            names = list(element.attrib) or ["s"]
            element.set(names[attribute_index % len(names)], value)
        elif kind == "remove" and element.getparent() is not None:
            element.getparent().remove(element)
        elif kind == "repeat" and element.getparent() is not None:
            element.addnext(etree.fromstring(etree.tostring(element)))
        elif kind in ("stretch", "spiral"):
            roads = tree.getroot().findall("road")
            if not roads:
                continue
            road = roads[element_index % len(roads)]
            geometries = road.findall("planView/geometry")
            if kind == "stretch":
                for holder in [road, *geometries]:
                    holder.set("length", value)
            elif geometries:
                for shape in list(geometries[0]):
                    geometries[0].remove(shape)
                etree.SubElement(geometries[0], "spiral", curvStart="0.001", curvEnd=value)
        elif kind == "retype":
            for lane in tree.getroot().iter("lane"):
                lane.set("type", value)
    return etree.tostring(tree, xml_declaration=True, encoding="UTF-8")


def _snapshot(folder: Path, skip: Path) -> dict[str, tuple[int, int]]:
    return {str(p.relative_to(folder)): (p.stat().st_size, p.stat().st_mtime_ns) for p in folder.rglob("*")
            if p.is_file() and skip not in p.parents}


class _Hang(Exception):
    pass


def _alarm(signum, frame):
    raise _Hang(f"no answer within {TIME_LIMIT_S:g} s")  # main() reports it as an internal fault: exit 1


def _run(argv: list[str]) -> tuple[int, str, float]:
    """main() in this process, its output captured, interrupted as a fault when it runs past the time limit."""
    out, err = io.StringIO(), io.StringIO()
    previous = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, TIME_LIMIT_S)
    start = time.perf_counter()
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main(argv)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    return code, err.getvalue(), time.perf_counter() - start


def check_map(tmp_root: Path, data: bytes, simulate: bool) -> None:
    work = Path(tmp_root)
    inputs, output = work / "in", work / "out"
    inputs.mkdir(parents=True)
    (inputs / "fuzzed.xodr").write_bytes(data)
    (inputs / "scene.tsg").write_text(SCENE)
    before = _snapshot(work, output)
    code, err, seconds = _run(["maps", "list", "--maps", str(inputs / "fuzzed.xodr")])
    assert code in DOCUMENTED and seconds < TIME_LIMIT_S, (code, err, seconds)
    argv = ["compile", str(inputs / "scene.tsg"), "-o", str(output / "scene.xosc"), "--maps",
            str(inputs / "fuzzed.xodr")] + ([] if simulate else ["--no-simulate"])
    code, err, seconds = _run(argv)
    assert code in DOCUMENTED and seconds < TIME_LIMIT_S, (code, err, seconds)
    assert _snapshot(work, output) == before, "a file outside the output was touched"
    if code != ExitCode.OK:
        assert not output.exists(), f"exit {code} but the output folder was written: {err}"


maps_and_mutations = st.tuples(st.sampled_from(BASE_MAPS), st.lists(mutation, min_size=1, max_size=4))


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow], derandomize=True)
@given(case=maps_and_mutations)
def test_a_mutated_map_never_faults_hangs_or_touches_other_files(tmp_path_factory, case):
    base, mutations = case
    check_map(tmp_path_factory.mktemp("fuzz"), mutate(base, mutations), simulate=False)


@pytest.mark.slow
@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=maps_and_mutations)
def test_many_mutated_maps_compiled_and_simulated(tmp_path_factory, case):
    base, mutations = case
    check_map(tmp_path_factory.mktemp("fuzz"), mutate(base, mutations), simulate=True)


def test_the_mutations_reach_every_element():
    """The strategy can touch each element of the base maps (a mutation index wraps around the tree)."""
    for base, size in _BASE_SIZES.items():
        changed = {mutate(base, [("set", i, 0, "nan")]) for i in range(size)}
        assert len(changed) == size
