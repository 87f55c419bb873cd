"""The road library: reading OpenDRIVE safely, the index's facts on built-in and real maps, retrieval, cache."""

from __future__ import annotations

import math
from collections import Counter
from pathlib import Path

import pytest
from lxml import etree

from conftest import ROOT, asam_errors
from ttsgc import vocabulary as V
from ttsgc.roads import MapError, NoRoadError, load_index, load_library, read_opendrive, retrieve
from ttsgc.roads import index as index_module
from ttsgc.roads.opendrive import Geometry
from ttsgc.scenario import RoadSpec

MAPS = ROOT / "maps"


@pytest.fixture(scope="module")
def fourway():
    return load_index(MAPS / "fourway_2lane_lights.xodr")


# -- facts on the built-in library ----------------------------------------------------------------------

def test_fourway_turns_lead_where_the_geometry_says(fourway):
    # arms: road 1 east, 2 north, 3 west, 4 south; approaching from the east (heading west),
    # left is south, right is north, straight is west
    expected = {"1": ("4", "2", "3"), "2": ("1", "3", "4"), "3": ("2", "4", "1"), "4": ("3", "1", "2")}
    for road, (left, right, straight) in expected.items():
        a = fourway.by_id[f"{road}:bwd"]
        assert {t.to_road for t in a.turns_to("left")} == {left}
        assert {t.to_road for t in a.turns_to("right")} == {right}
        assert {t.to_road for t in a.turns_to("straight")} == {straight}
        assert a.entering == {"left": (f"{left}:bwd",), "right": (f"{right}:bwd",), "straight": (f"{straight}:bwd",)}
        assert a.junction == "1" and a.lanes == 2 and a.opposite_lanes == 2
        assert a.shoulder and a.sidewalk and "traffic_light" in a.signals
        assert {"continental_crosswalk", "crosswalk", "stop_line", "speed_40"} <= set(a.objects)
        left_turn = a.turns_to("left")[0]
        assert left_turn.heading_change_deg == pytest.approx(90, abs=1) and left_turn.from_lanes == (1,)
        assert a.turns_to("right")[0].from_lanes == (2,)
    assert fourway.by_id["1:fwd"].junction is None and not fourway.by_id["1:fwd"].turns


def test_tjunction_stem_turns_and_gives_way():
    t = load_index(MAPS / "tjunction_2lane_yield.xodr")
    stem = t.by_id["2:bwd"]
    assert stem.turn_kinds() == {"left", "right"} and "yield" in stem.signals
    assert t.by_id["1:bwd"].turn_kinds() == {"right", "straight"}
    assert t.by_id["1:bwd"].entering["left"] == ()


def test_lane_counts_match_the_file():
    for path in sorted(MAPS.glob("*.xodr")):
        tree = etree.parse(str(path))
        idx = load_index(path)
        for a in idx.approaches:
            road = tree.find(f"road[@id='{a.road}']")
            side = "right" if a.direction == "forward" else "left"
            counts = [len(sec.findall(f"{side}/lane[@type='driving']")) for sec in road.iter("laneSection")]
            assert a.lanes == min(counts), (path.name, a.id)


def test_every_road_word_of_the_vocabulary_is_satisfiable_in_the_builtin_library():
    library = load_library()
    for word in list(V.SIGNALS) + V.object_words():
        field = "required_signals" if word in V.SIGNALS else "required_objects"
        assert retrieve(library, RoadSpec(**{field: (word,)})), word
    for lanes in (1, 2, 3):
        assert retrieve(library, RoadSpec(lanes=lanes, junction=True))
    assert retrieve(library, RoadSpec(lanes=3, junction=False))
    kinds = Counter(len(set(a.entering) and [k for k, v in a.entering.items() if v]) for m in library
                    for a in m.approaches if a.junction)
    assert kinds[3] and kinds[2], "both 4-way and T junctions"


def test_the_town_offers_several_junctions_to_choose_from():
    town = load_index(MAPS / "town_row.xodr")
    assert town.junctions == 3
    assert len({a.junction for a in town.approaches if a.junction}) == 3
    assert {s for a in town.approaches for s in a.signals} >= {"traffic_light", "stop", "yield"}


def test_graph_has_turn_edges_and_routes_through_the_town():
    import networkx as nx

    town = load_index(MAPS / "town_row.xodr")
    g = town.graph
    assert g.edges["1:fwd", "11:fwd"]["direction"] == "left"
    assert nx.shortest_path(g, "1:fwd", "4:fwd") == ["1:fwd", "2:fwd", "3:fwd", "4:fwd"]


def test_generation_is_deterministic_and_matches_the_committed_maps(tmp_path):
    import importlib.util

    spec = importlib.util.spec_from_file_location("generate_maps", MAPS / "generate.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    for path in module.main(tmp_path):
        assert path.read_bytes() == (MAPS / path.name).read_bytes(), f"maps/{path.name} is stale"


def test_builtin_maps_convert_without_netconvert_warnings(tmp_path):
    from ttsgc.simulate.players.sumo.network import convert

    for path in sorted(MAPS.glob("*.xodr")):
        assert convert(path, tmp_path / f"{path.stem}.net.xml") == [], path.name


def test_builtin_maps_pass_the_asam_opendrive_checker(tmp_path):
    for path in sorted(MAPS.glob("*.xodr")):
        assert asam_errors("qc_opendrive", "xodrBundle", path, tmp_path) == [], path.name


# -- real maps (../shared) --------------------------------------------------------------------------------

def _net_connections(net_path: Path):
    """(from road, direction, to road, dir) for every connection between two OpenDRIVE roads."""
    def road_of(edge: str):
        base = edge.split("#")[0]
        return (base[1:], "forward") if base.startswith("-") else (base, "backward")
    for c in etree.parse(str(net_path)).iter("connection"):
        if c.get("from").startswith(":") or c.get("to").startswith(":"):
            continue
        (src, direction), (dst, _) = road_of(c.get("from")), road_of(c.get("to"))
        yield src, direction, dst, c.get("dir")


def _agreement(town_path: Path, tmp_path: Path) -> tuple[int, list]:
    from ttsgc.simulate.players.sumo.network import convert

    net = tmp_path / f"{town_path.stem}.net.xml"
    convert(town_path, net, pedestrians=False)
    idx = load_index(town_path)
    kinds = {"l": "left", "L": "left", "r": "right", "R": "right", "s": "straight", "t": "uturn"}
    agree, disagree = 0, []
    for src, direction, dst, sumo_dir in _net_connections(net):
        a = idx.by_id.get(index_module.approach_id(src, direction))
        if a is None or a.junction is None or (src == dst and sumo_dir == "s"):
            continue  # a road-to-road link or a lane-section split, not a junction
        ours = {t.direction for t in a.turns if t.to_road == dst}
        if kinds[sumo_dir] in ours:
            agree += 1
        else:
            disagree.append((src, direction, dst, sumo_dir, ours))
    return agree, disagree


@pytest.mark.parametrize("town", ["Town01", "Town02", "Town07", "Town10HD"])
def test_turns_agree_with_netconvert_on_every_connection(shared, town, tmp_path):
    agree, disagree = _agreement(shared / "maps" / "carla" / f"{town}.xodr", tmp_path)
    assert agree > 40 and disagree == []


@pytest.mark.parametrize("town", ["Town04", "Town06"])
def test_turns_mostly_agree_on_motorway_towns(shared, town, tmp_path):
    # Their few disagreements are motorway forks: an approach with an exit whose heading change is near 45
    # degrees, where netconvert measures its own reshaped edges and may call either branch partial.
    agree, disagree = _agreement(shared / "maps" / "carla" / f"{town}.xodr", tmp_path)
    assert agree / (agree + len(disagree)) >= 0.95
    idx = load_index(shared / "maps" / "carla" / f"{town}.xodr")
    for src, direction, dst, _, _ in disagree:
        a = idx.by_id[index_module.approach_id(src, direction)]
        assert any(30 <= abs(t.heading_change_deg) <= 55 for t in a.turns), (src, direction, dst)


def test_carla_signalised_junctions_give_lights_to_their_incoming_roads(shared):
    odr = read_opendrive(shared / "maps" / "carla" / "Town01.xodr")
    idx = load_index(shared / "maps" / "carla" / "Town01.xodr")
    controlled = {j.id for j in odr.junctions.values() if j.controllers}
    assert len(controlled) >= 4
    incoming = [a for a in idx.approaches if a.junction in controlled]
    assert incoming and all("traffic_light" in a.signals for a in incoming)


def test_town04_motorway_approaches_have_shoulders(shared):
    idx = load_index(shared / "maps" / "carla" / "Town04.xodr")
    motorway = [a for a in idx.approaches if a.lanes >= 4]
    assert len(motorway) >= 4 and all(a.shoulder for a in motorway)


def test_town07_has_stop_and_yield_signs(shared):
    idx = load_index(shared / "maps" / "carla" / "Town07.xodr")
    assert sum("stop" in a.signals for a in idx.approaches) >= 5
    assert sum("yield" in a.signals for a in idx.approaches) >= 5


def test_carla_lane_count_matches_the_file(shared):
    path = shared / "maps" / "carla" / "Town04.xodr"
    tree = etree.parse(str(path))
    idx = load_index(path)
    for a in idx.approaches[:40]:
        road = tree.find(f"road[@id='{a.road}']")
        side = "right" if a.direction == "forward" else "left"
        assert a.lanes == min(len(s.findall(f"{side}/lane[@type='driving']")) for s in road.iter("laneSection"))


def test_esmini_maps_index_and_their_junctions_turn(shared):
    for path in sorted((shared / "maps" / "esmini").glob("*.xodr")):
        idx = load_index(path)
        assert idx.approaches, path.name
    fabriksgatan = load_index(shared / "maps" / "esmini" / "fabriksgatan.xodr")
    at_junction = [a for a in fabriksgatan.approaches if a.junction]
    assert len(at_junction) == 4 and all(a.turn_kinds() == {"left", "right", "straight"} for a in at_junction)


# -- geometry -------------------------------------------------------------------------------------------

def test_arc_and_spiral_geometry():
    arc = Geometry(0, 0, 0, 0, math.pi * 10, "arc", (0.1,))  # half a circle of radius 10
    end = arc.at(math.pi * 10)
    assert (end.x, end.y, end.hdg) == pytest.approx((0, 20, math.pi), abs=1e-9)
    spiral = Geometry(0, 0, 0, 0.3, 50, "spiral", (0.0, 0.04))
    assert spiral.at(50).hdg == pytest.approx(0.3 + 0.5 * 0.04 * 50, abs=1e-12)
    # against a fine explicit integration
    x = y = 0.0
    n = 20000
    for i in range(n):
        u = (i + 0.5) * 50 / n
        h = 0.3 + 0.5 * 0.04 / 50 * u * u
        x += math.cos(h) * 50 / n
        y += math.sin(h) * 50 / n
    assert (spiral.at(50).x, spiral.at(50).y) == pytest.approx((x, y), abs=1e-3)


def test_param_poly3_follows_its_curve():
    # u = p, v = p^2 / 20 over arcLength p in 0..20; heading at the end: atan(2p/20) = atan(2)
    length = 20 * 0.5 * (math.sqrt(5) + math.asinh(2) / 2)  # arc length of y = x^2/20 for x in 0..20
    g = Geometry(0, 1, 2, 0, length, "paramPoly3", (0, 1, 0, 0, 0, 0, 1 / 20, 0), normalized=False)
    # pRange arcLength: p runs over 0..length, so the curve is followed to u = length
    end = g.at(length)
    assert (end.x, end.y, end.hdg) == pytest.approx((1 + length, 2 + length ** 2 / 20, math.atan(length / 10)),
                                                   abs=1e-6)
    normalized = Geometry(0, 0, 0, 0, length, "paramPoly3", (0, 20, 0, 0, 0, 0, 20, 0))
    p_end = normalized.at(length)
    assert (p_end.x, p_end.y, p_end.hdg) == pytest.approx((20, 20, math.atan(2)), abs=1e-6)


# -- hostile and malformed files ------------------------------------------------------------------------

BILLION_LAUGHS = b"""<?xml version="1.0"?>
<!DOCTYPE lolz [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
<!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">]>
<OpenDRIVE><header name="&lol3;"/></OpenDRIVE>"""
EXTERNAL_ENTITY = b"""<?xml version="1.0"?>
<!DOCTYPE r [<!ENTITY secret SYSTEM "file:///etc/passwd">]>
<OpenDRIVE><header name="&secret;"/></OpenDRIVE>"""


@pytest.mark.parametrize("content, message", [
    (BILLION_LAUGHS, "refused"),
    (EXTERNAL_ENTITY, "refused"),
    (b"<OpenDRIVE><road id='1' length='10'>", "not well-formed"),
    (b"<?xml version='1.0'?><map/>", "not <OpenDRIVE>"),
    (b"<OpenDRIVE/>", "has no <road>"),
    (b"<OpenDRIVE>\n<road id='1' length='ten'/></OpenDRIVE>", ":2: <road>: attribute length='ten' is not a number"),
    (b"<OpenDRIVE><road id='1' length='10'><planView/></road></OpenDRIVE>", "has no <geometry>"),
    (b"<OpenDRIVE><road id='1' length='nan'/></OpenDRIVE>", "not a finite number"),
    (b"\x00\xff\xfe garbage", "not well-formed"),
])
def test_hostile_and_malformed_maps_are_refused_clearly(tmp_path, content, message):
    path = tmp_path / "bad.xodr"
    path.write_bytes(content)
    with pytest.raises(MapError, match=None) as err:
        load_index(path)
    assert message in str(err.value) and str(path) in str(err.value)
    assert err.value.exit_code == 3


def test_a_map_over_the_size_limit_is_refused(tmp_path, monkeypatch):
    from ttsgc.roads import opendrive

    monkeypatch.setattr(opendrive, "MAX_MAP_BYTES", 100)
    with pytest.raises(MapError, match="the limit is 100"):
        read_opendrive(MAPS / "avenue_2lane.xodr")


def test_unknown_elements_and_vendor_extensions_are_tolerated(tmp_path):
    text = (MAPS / "avenue_2lane.xodr").read_text()
    text = text.replace("<planView>", "<userData code='x'><vendor:thing xmlns:vendor='urn:v'/></userData><planView>")
    path = tmp_path / "vendor.xodr"
    path.write_text(text)
    assert len(load_index(path).approaches) == 2


# -- retrieval and cache --------------------------------------------------------------------------------

def test_retrieval_names_the_condition_that_emptied_the_set():
    library = load_library()
    with pytest.raises(NoRoadError) as err:
        retrieve(library, RoadSpec(lanes=3, junction=True, required_signals=("stop",)))
    assert "'lanes >= 3' and 'at junction'" in str(err.value) and "none meets 'has stop'" in str(err.value)
    with pytest.raises(NoRoadError, match=r"most lanes there: 3"):
        retrieve(library, RoadSpec(lanes=5))
    found = retrieve(library, RoadSpec(lanes=1, junction=True, required_signals=("stop",),
                                       without_signals=("traffic_light",)))
    assert found and all("stop" in a.signals and "traffic_light" not in a.signals for a in found)


def test_cache_is_used_and_a_corrupt_entry_is_rebuilt(tmp_path, monkeypatch):
    monkeypatch.setenv("TTSGC_CACHE_DIR", str(tmp_path))
    first = load_index(MAPS / "fourway_1lane_stop.xodr")
    entries = list((tmp_path / "index").glob("*.json"))
    assert len(entries) == 1
    calls = []
    monkeypatch.setattr(index_module, "build_index", lambda *a: calls.append(a) or (_ for _ in ()).throw(
        AssertionError("rebuilt")))
    assert load_index(MAPS / "fourway_1lane_stop.xodr") == first  # from the cache, no rebuild
    monkeypatch.undo()
    monkeypatch.setenv("TTSGC_CACHE_DIR", str(tmp_path))
    entries[0].write_text('{"version": 1, "truncated')
    assert load_index(MAPS / "fourway_1lane_stop.xodr") == first
    entries[0].write_text(first.model_copy(update={"sha256": "0" * 64}).model_dump_json())
    rebuilt = load_index(MAPS / "fourway_1lane_stop.xodr")
    assert rebuilt.sha256 == first.sha256


def test_maps_cli(capsys):
    from ttsgc.cli import main

    assert main(["maps", "list"]) == 0
    assert "town_row" in capsys.readouterr().out
    assert main(["maps", "query", "--lanes", "2", "--has", "traffic_light", "--junction"]) == 0
    out = capsys.readouterr().out
    assert "fourway_2lane_lights" in out and "tjunction" not in out
    assert main(["maps", "query", "--lanes", "3", "--has", "stop"]) == 4
    assert "none meets 'has stop'" in capsys.readouterr().err
    assert main(["maps", "show", "fourway_2lane_lites"]) == 3
    assert "did you mean fourway_2lane_lights" in capsys.readouterr().err
