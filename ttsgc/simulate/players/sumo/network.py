"""OpenDRIVE -> SUMO network with the netconvert of the eclipse-sumo wheel, cached by the map's content hash.

Edge "-R" carries road R's right lanes (driving along s), edge "R" its left lanes; lane sections add "#k".
--output.original-names keeps each lane's OpenDRIVE id ("road_lane"), and the net's offset maps OpenDRIVE
world coordinates to SUMO's. netconvert ignores stop signs: a second pass sets the junctions whose incoming
roads have them to allway_stop (all of them) or priority_stop (some), from the road index.
"""

from __future__ import annotations

import hashlib
import os
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from ttsgc.errors import TtsgcError
from ttsgc.files import write_atomic

NETWORK_VERSION = 1


def _sumo_home() -> Path:
    import sumo  # the eclipse-sumo wheel; importing it sets SUMO_HOME

    return Path(sumo.SUMO_HOME)


def netconvert_binary() -> str:
    from sumolib import checkBinary

    os.environ.setdefault("SUMO_HOME", str(_sumo_home()))
    return checkBinary("netconvert")


def _run(command: list[str], what: str) -> list[str]:
    done = subprocess.run(command, capture_output=True, text=True, timeout=600)
    lines = [line for line in (done.stdout + done.stderr).splitlines() if line.strip()]
    if done.returncode != 0:
        raise TtsgcError(f"netconvert failed on {what}: " + " | ".join(lines[-5:]))
    return [line for line in lines if line.startswith("Warning")]


def convert(xodr: str | Path, net: str | Path, pedestrians: bool = True, extra: list[str] | None = None) -> list[str]:
    """Convert a map; returns netconvert's warnings (lines), raises on failure."""
    typemap = _sumo_home() / "data" / "typemap"
    types = [typemap / "opendriveNetconvert.typ.xml"]
    if pedestrians:
        types.append(typemap / "opendriveNetconvertPedestrians.typ.xml")
    command = [netconvert_binary(), "--opendrive-files", str(xodr), "--type-files", ",".join(map(str, types)),
               "--output.original-names", "-o", str(net)]
    if pedestrians:
        command.append("--crossings.guess")
    return _run(command + (extra or []), str(xodr))


@dataclass(frozen=True)
class Network:
    path: Path
    offset: tuple[float, float]  # add to OpenDRIVE x, y to get SUMO x, y


def stop_controls(xodr: Path) -> dict[str, str]:
    """SUMO node types for the map's junctions that stop signs control and no traffic light does."""
    from ttsgc.roads.index import load_index

    incoming: dict[str, list] = {}
    for a in load_index(xodr).approaches:
        if a.junction is not None:
            incoming.setdefault(a.junction, []).append(a)
    types = {}
    for junction, approaches in incoming.items():
        if any("traffic_light" in a.signals for a in approaches):
            continue
        stops = sum("stop" in a.signals for a in approaches)
        if stops:
            types[junction] = "allway_stop" if stops == len(approaches) else "priority_stop"
    return types


def cache_dir() -> Path:
    from ttsgc.roads.index import cache_dir as index_cache

    return index_cache().parent / "net"


def network_for(xodr: str | Path) -> Network:
    """The SUMO network of a map: built once per map content, then read from the cache."""
    xodr = Path(xodr)
    data = xodr.read_bytes()
    sha = hashlib.sha256(data).hexdigest()
    net = cache_dir() / f"{sha}.v{NETWORK_VERSION}.net.xml"
    if not net.is_file():
        net.parent.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryDirectory(dir=net.parent) as work:
            first = Path(work) / "first.net.xml"
            convert(xodr, first)
            controls = stop_controls(xodr)
            if controls:
                nodes = Path(work) / "stops.nod.xml"
                root = etree.Element("nodes")
                for junction, kind in sorted(controls.items()):
                    etree.SubElement(root, "node", id=junction, type=kind)
                nodes.write_bytes(etree.tostring(root))
                second = Path(work) / "second.net.xml"
                _run([netconvert_binary(), "-s", str(first), "--node-files", str(nodes), "-o", str(second)],
                     f"{xodr} (stop signs)")
                first = second
            write_atomic(net, first.read_bytes())
    location = etree.parse(str(net)).find("location")
    dx, dy = (float(v) for v in location.get("netOffset", "0,0").split(","))
    return Network(net, (dx, dy))
