"""The tool's error kinds and their exit codes: one code per kind of bad input, so scripts can tell them apart."""

from __future__ import annotations

from enum import IntEnum


class ExitCode(IntEnum):
    OK = 0
    INTERNAL = 1  # a fault in ttsgc itself (a traceback with --debug)
    INVALID_SCENARIO = 2  # a .tsg that is not a valid scenario, or a bad command line
    MAP_ERROR = 3  # an OpenDRIVE file that cannot be read, or is refused as hostile
    NO_ROAD = 4  # no road of the map library can host the scene
    SIMULATION_FAILED = 5  # the scene does not do what it says when run
    LOWERING_FAILED = 6  # the English could not be lowered into a valid scenario
    NOT_FORMATTED = 7  # `fmt --check`: a file is not in the canonical layout
    UNSUPPORTED_BY_TARGET = 8  # `lint`: the file uses what its player does not support; `compile --target`:
    # the scene needs what the target player cannot express


class TtsgcError(Exception):
    """An error the user can act on: printed as its message, never as a traceback."""

    exit_code: ExitCode = ExitCode.INTERNAL

    def render(self) -> str:
        return str(self)


class UsageError(TtsgcError):
    """A bad command line: a path, a number or an environment variable that is not what the command needs."""

    exit_code = ExitCode.INVALID_SCENARIO
