"""OpenDRIVE -> SUMO network with the netconvert of the eclipse-sumo wheel, cached by the map's content hash.

Edge "-R" carries road R's right lanes (driving along s), edge "R" its left lanes; lane sections add "#k".
--output.original-names keeps each lane's OpenDRIVE id ("road_lane"), and the net's offset maps OpenDRIVE
world coordinates to SUMO's. netconvert ignores stop signs: a second pass sets the junctions whose incoming
roads have them to allway_stop (all of them) or priority_stop (some), from the road index.
"""

from __future__ import annotations

import atexit
import hashlib
import os
import shutil
import signal
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from ttsgc.files import write_atomic
from ttsgc.roads.opendrive import MapError, load_opendrive

NETWORK_VERSION = 1


def _sumo_home() -> Path:
    import sumo  # the eclipse-sumo wheel; importing it sets SUMO_HOME

    return Path(sumo.SUMO_HOME)


def netconvert_binary() -> str:
    """The eclipse-sumo wheel's netconvert, else one on PATH (sumolib's checkBinary would import numpy)."""
    home = _sumo_home()
    os.environ.setdefault("SUMO_HOME", str(home))
    bundled = home / "bin" / "netconvert"
    return str(bundled) if bundled.is_file() else shutil.which("netconvert") or "netconvert"


NETCONVERT_TIMEOUT_S = 600


_STOP_SIGNALS = {signal.SIGINT, signal.SIGTERM}


def _child_setup() -> None:
    """In the child, before exec: ask Linux to kill it when ttsgc dies, however ttsgc dies (strictly: when the
    thread that started it ends; ttsgc starts children from its main thread only), and let it hear the stop
    signals the parent held back while it forked."""
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(1, 9)  # PR_SET_PDEATHSIG, SIGKILL
    except (OSError, AttributeError):
        pass  # not Linux: the child is still killed when ttsgc exits by an exception or a signal it handles
    signal.pthread_sigmask(signal.SIG_UNBLOCK, _STOP_SIGNALS)


def _run(command: list[str], what: str) -> list[str]:
    # Ctrl-C and SIGTERM are held back while the child is created: Python would otherwise run their handler
    # inside its after-fork hooks, where the exception is printed and dropped, and the signal lost.
    posix = hasattr(signal, "pthread_sigmask")
    held = signal.pthread_sigmask(signal.SIG_BLOCK, _STOP_SIGNALS) if posix else None
    try:
        process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                   errors="replace", preexec_fn=_child_setup if posix else None)
    finally:
        if posix:
            signal.pthread_sigmask(signal.SIG_SETMASK, held)
    with process:
        try:
            stdout, stderr = process.communicate(timeout=NETCONVERT_TIMEOUT_S)
        except subprocess.TimeoutExpired:
            process.kill()
            process.communicate()
            raise MapError(f"{what}: netconvert did not finish within {NETCONVERT_TIMEOUT_S} s") from None
        except BaseException:  # interrupted, terminated: the child goes with us
            process.kill()
            raise
    lines = [line for line in (stdout + stderr).splitlines() if line.strip()]
    if process.returncode != 0:
        raise MapError(f"{what}: netconvert cannot convert the map: " + " | ".join(lines[-5:]))
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


_TEMPORARY_CACHE: list[Path] = []  # when the cache cannot be written: one folder for this process, removed at exit


def _temporary_cache(reason: OSError) -> Path:
    if not _TEMPORARY_CACHE:
        folder = Path(tempfile.mkdtemp(prefix="ttsgc-net-"))
        atexit.register(shutil.rmtree, folder, True)
        _TEMPORARY_CACHE.append(folder)
        print(f"ttsgc: note: the network cache {cache_dir()} cannot be written ({reason.strerror or reason}); "
              f"using a temporary one (set TTSGC_CACHE_DIR to a writable folder to keep networks)", file=sys.stderr)
    return _TEMPORARY_CACHE[0]


def _read_network(net: Path) -> Network | None:
    """A cached network, checked: None when the entry is missing or not a usable network (truncated, garbage,
    an empty <net/>), so that it is built again rather than trusted. Only the head (the root, <location>, the
    first <edge>) and the last bytes are read: a whole parse would cost every simulation."""
    try:
        with net.open("rb") as file:
            file.seek(max(0, net.stat().st_size - 64))
            if not file.read().rstrip().endswith(b"</net>"):
                return None
        offset, tags = net_head(net)
    except (OSError, etree.XMLSyntaxError, ValueError):
        return None
    return Network(net, offset) if tags[:1] == ["net"] and {"location", "edge"} <= set(tags) else None


def net_head(net: Path) -> tuple[tuple[float, float], list[str]]:
    """The net's offset from its <location> element, and the tags met up to the first <edge>: both stand at the
    head of the file, so the rest is never parsed."""
    offset, tags = (0.0, 0.0), []
    for _, element in etree.iterparse(str(net), events=("start",), resolve_entities=False, no_network=True,
                                      load_dtd=False):
        tags.append(element.tag)
        if element.tag == "location":
            dx, dy = (float(v) for v in element.get("netOffset", "0,0").split(","))
            offset = (dx, dy)
        if element.tag == "edge":
            break
    return offset, tags


def network_for(xodr: str | Path) -> Network:
    """The SUMO network of a map: built once per map content, then read from the cache. The map goes through
    ttsgc's own safe reader before netconvert sees it; a cache entry is checked before it is used."""
    xodr = Path(xodr)
    load_opendrive(xodr)  # MapError for a file that is not a readable, acceptable OpenDRIVE map
    sha = hashlib.sha256(xodr.read_bytes()).hexdigest()
    name = f"{sha}.v{NETWORK_VERSION}.net.xml"
    for folder in [cache_dir(), *_TEMPORARY_CACHE]:
        network = _read_network(folder / name)
        if network is not None:
            return network
    net = cache_dir() / name
    with tempfile.TemporaryDirectory(prefix="ttsgc-net-") as work:
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
        built = first.read_bytes()
    try:
        write_atomic(net, built)
    except OSError as exc:  # a read-only cache, or a cache path that is a file
        net = _temporary_cache(exc) / name
        write_atomic(net, built)
    network = _read_network(net)
    if network is None:
        raise MapError(f"{xodr}: netconvert made no usable network of the map")
    return network
