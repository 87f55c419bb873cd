"""Road retrieval: the approaches of a map library that meet a scene's road conditions.

Conditions apply one at a time, in the order a person reads the road block, so that when nothing is left the
error can name the condition that emptied the set and what the library offers instead.
"""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterable

from ttsgc import vocabulary as V
from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.files import real_path
from ttsgc.resources import resource_dir
from ttsgc.roads.index import Approach, MapIndex, load_index
from ttsgc.roads.opendrive import MapError
from ttsgc.scenario import RoadSpec


class NoRoadError(TtsgcError):
    """No road of the library can host the scene."""

    exit_code = ExitCode.NO_ROAD


@dataclass(frozen=True)
class Condition:
    text: str  # as the road block writes it
    test: Callable[[Approach], bool]


def builtin_maps() -> list[Path]:
    return sorted(resource_dir("maps").glob("*.xodr"))


BUILTIN = "builtin"


def map_files(maps: Iterable[str | Path] | None = None) -> list[Path]:
    """The OpenDRIVE files of a library: files and folders as given, the word 'builtin' standing for the
    built-in library; no list at all means the built-in library alone."""
    return list(_map_sources(maps))


def _map_sources(maps: Iterable[str | Path] | None) -> dict[Path, Path | None]:
    """Each map file of the library -> the folder it was found in (None when it was named itself)."""
    files: list[tuple[Path, Path | None]] = []
    for item in maps or (BUILTIN,):
        path = Path(item)
        if str(item) == BUILTIN:
            files += [(p, None) for p in builtin_maps()]
        elif path.is_dir():
            found = sorted(path.glob("*.xodr"))
            if not found:
                raise MapError(f"{path}: the folder holds no .xodr file")
            files += [(p, path) for p in found]
        elif path.is_file():
            files.append((path, None))
        else:
            raise MapError(f"{path}: " + ("is neither a map file nor a folder" if path.exists() else
                                         "no such map file or folder"))
    unique: dict[Path, Path | None] = {}
    for file, folder in files:
        resolved = real_path(file)
        unique[resolved] = None if resolved in unique and unique[resolved] is None else folder
    if not unique:
        raise MapError("the map library is empty")
    return unique


_REPORTED: set[str] = set()  # skipped maps already reported in this process


def load_library(maps: Iterable[str | Path] | None = None) -> list[MapIndex]:
    """The indexes of a library. A map named by itself must load; a bad map found in a folder is reported by
    name and skipped, so one broken file does not take the folder's other maps with it."""
    library, skipped = [], []
    for path, folder in _map_sources(maps).items():
        try:
            library.append(load_index(path))
        except MapError as exc:
            if folder is None:
                raise
            skipped.append(exc)
            if str(exc) not in _REPORTED:
                _REPORTED.add(str(exc))
                print(f"ttsgc: warning: {exc}; skipped", file=sys.stderr)
    if not library:
        raise MapError(f"no map of the library could be read: {skipped[0]}" + (
            f" (and {len(skipped) - 1} more)" if len(skipped) > 1 else ""))
    return library


# `not at junction`: a road that ends at a junction qualifies when it and the roads leading into it leave
# this much room before the junction (placement keeps the ego JUNCTION_CLEARANCE_M and more before it).
AWAY_FROM_JUNCTION_RUN_UP_M = 60.0
JUNCTION_CLEARANCE_M = 40.0


def away_from_junction(a: Approach) -> bool:
    """A road that ends at no junction, or leaves room for a scene well before its junction."""
    return a.junction is None or a.run_up >= AWAY_FROM_JUNCTION_RUN_UP_M


def _has(word: str) -> Callable[[Approach], bool]:
    if word in V.SIGNALS:
        return lambda a: word in a.signals
    return lambda a: word in a.objects


def conditions(road: RoadSpec) -> list[Condition]:
    """The road block as a list of tests, in reading order."""
    out = [Condition(f"lanes >= {road.lanes}", lambda a: a.lanes >= road.lanes)]
    if road.junction is True:
        out.append(Condition("at junction", lambda a: a.junction is not None))
    elif road.junction is False:  # the scene happens well before any junction (placement keeps it there)
        out.append(Condition("not at junction", away_from_junction))
    for word in road.required_signals + road.required_objects:
        out.append(Condition(f"has {word}", _has(word)))
    for word in road.without_signals + road.without_objects:
        test = _has(word)
        out.append(Condition(f"without {word}", lambda a, test=test: not test(a)))
    return out


def retrieve(library: list[MapIndex], road: RoadSpec) -> list[Approach]:
    """Every approach that meets all conditions; NoRoadError names the first condition that left none."""
    candidates = [a for index in library for a in index.approaches]
    total = len(candidates)
    if not total:
        raise NoRoadError(f"no road can host the scene: no road of {_library_name(library)} has a driving lane")
    passed: list[str] = []
    for condition in conditions(road):
        remaining = [a for a in candidates if condition.test(a)]
        if not remaining:
            before = f"{len(candidates)} of {total} approaches met {' and '.join(passed)}" if passed else \
                f"none of the {total} approaches of {_library_name(library)}"
            raise NoRoadError(f"no road can host the scene: {before}, but none meets '{condition.text}'"
                              f"{_offer(candidates, condition.text)}")
        passed.append(f"'{condition.text}'")
        candidates = remaining
    return candidates


def _library_name(library: list[MapIndex]) -> str:
    return f"the map {library[0].name}" if len(library) == 1 else f"the {len(library)} maps"


def _offer(candidates: list[Approach], text: str) -> str:
    """What the library has instead, for the condition that failed."""
    if text.startswith("lanes"):
        return f" (the most lanes there: {max(a.lanes for a in candidates)})"
    return ""
