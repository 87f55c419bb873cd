"""What a player hands the judge: every body's path through time, in OpenDRIVE world coordinates.

Every player (SUMO, esmini, ...) produces the same Trace, so the judge and the pictures know no player.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Sample:
    t: float  # seconds since the start
    x: float  # the body's centre, OpenDRIVE world coordinates (m)
    y: float
    h: float  # heading, radians counter-clockwise from east
    speed: float  # m/s
    road: str = ""  # OpenDRIVE road id where the player knows it ("" when unknown)
    lane: int | None = None  # OpenDRIVE lane id where the player knows it
    s: float | None = None  # position along the road where the player knows it
    on_road: bool | None = None  # the player's word on whether the body is on a road or junction (None: unsaid)


@dataclass(frozen=True)
class Body:
    length: float
    width: float
    x_offset: float = 0.0  # the bounding box centre ahead of the reference point (m)


@dataclass
class Trace:
    player: str  # "sumo" | "esmini" | ...
    step_s: float
    bodies: dict[str, Body] = field(default_factory=dict)  # entity name -> its box
    samples: dict[str, list[Sample]] = field(default_factory=dict)  # entity name -> samples, time ascending
    started: dict[str, float] = field(default_factory=dict)  # storyboard element name -> time it started
    ended: dict[str, float] = field(default_factory=dict)  # storyboard element name -> time it ended
    end_time: float = 0.0
    stopped_by_trigger: bool = False  # the StopTrigger fired (else the player's time limit ended the run)
    problems: list[str] = field(default_factory=list)  # what the player could not carry out, in words
