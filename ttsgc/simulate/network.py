"""OpenDRIVE -> SUMO network with the netconvert of the eclipse-sumo wheel.

Edge "-R" carries road R's right lanes (driving along s), edge "R" its left lanes; lane sections add "#k".
--output.original-names keeps each lane's OpenDRIVE id (road_lane) so positions map both ways.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

from ttsgc.errors import TtsgcError


def _sumo_home() -> Path:
    import sumo  # the eclipse-sumo wheel; importing it sets SUMO_HOME

    return Path(sumo.SUMO_HOME)


def netconvert_binary() -> str:
    from sumolib import checkBinary

    os.environ.setdefault("SUMO_HOME", str(_sumo_home()))
    return checkBinary("netconvert")


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
    command += extra or []
    done = subprocess.run(command, capture_output=True, text=True, timeout=600)
    lines = [line for line in (done.stdout + done.stderr).splitlines() if line.strip()]
    if done.returncode != 0:
        raise TtsgcError(f"netconvert failed on {xodr}: " + " | ".join(lines[-5:]))
    return [line for line in lines if line.startswith("Warning")]
