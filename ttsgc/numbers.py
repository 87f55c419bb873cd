"""Reading numbers wherever they enter ttsgc (the language, English, maps, scenes, environment variables), with
limits: no quantity ttsgc uses needs more than MAX_DIGITS digits or lies outside +-MAX_MAGNITUDE, and a number
that does is refused here, before int() hits Python's digit limit, float() turns it into inf or a loop runs
for its length.

The readers raise NumberError, whose message says what is wrong with the text; callers wrap it into their
own error kind with the file, line or variable it came from.
"""

from __future__ import annotations

import math
import os
import re

from ttsgc.errors import UsageError

MAX_DIGITS = 30  # significant digits of any number ttsgc reads (a seed < 2**32 has 10, a map coordinate ~15)
MAX_MAGNITUDE = 1e12  # larger than any distance, speed, time or count a scene or a map can mean

_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")  # ASCII digits only


class NumberError(ValueError):
    """A text that is not a number ttsgc can use; the message names the text and what is wrong."""


def _shown(text: str) -> str:
    return repr(text) if len(text) <= 24 else repr(text[:20] + "...")


def _checked_text(text: str) -> str:
    text = str(text).strip()
    if text.lower().lstrip("+-") in ("nan", "inf", "infinity"):
        raise NumberError(f"{_shown(text)} is not a finite number")
    if not _NUMBER.fullmatch(text):
        raise NumberError(f"{_shown(text)} is not a number")
    mantissa = re.split(r"[eE]", text)[0]
    digits = len(mantissa.lstrip("+-").replace(".", "").lstrip("0"))
    if digits > MAX_DIGITS:
        raise NumberError(f"{_shown(text)} has {digits} digits; at most {MAX_DIGITS} are read")
    return text


def _in_range(value, text: str, low, high):
    if (low is not None and value < low) or (high is not None and value > high):
        bounds = f"{'-inf' if low is None else f'{low:g}'}..{'inf' if high is None else f'{high:g}'}"
        raise NumberError(f"{_shown(text)} is out of range {bounds}")
    return value


def parse_float(text: str, low: float | None = -MAX_MAGNITUDE, high: float | None = MAX_MAGNITUDE) -> float:
    """A finite decimal within [low, high]; nan, inf, hex and words are refused."""
    text = _checked_text(text)
    value = float(text)
    if not math.isfinite(value):
        raise NumberError(f"{_shown(text)} is not a finite number")
    return _in_range(value, text, low, high)


def parse_int(text: str, low: int | None = -int(MAX_MAGNITUDE), high: int | None = int(MAX_MAGNITUDE)) -> int:
    """An integer (plain digits, optional sign) within [low, high]."""
    text = _checked_text(text)
    if not re.fullmatch(r"[+-]?[0-9]+", text):
        raise NumberError(f"{_shown(text)} is not an integer")
    return _in_range(int(text), text, low, high)


def clamped_int(text: str, high: int) -> int:
    """A non-negative integer read from prose, at most `high`: a count or a limit a person wrote with
    hundreds of digits means 'very many', which the scene's own rules then judge."""
    text = str(text).strip()
    if not text.isdecimal():
        raise NumberError(f"{_shown(text)} is not a whole number")
    if len(text.lstrip("0")) > len(str(high)):
        return high
    return min(int(text), high)


def env_number(name: str, kind: type = float, low=None, high=None):
    """An environment variable read as a number; None when unset or empty. The error names the variable."""
    raw = os.environ.get(name)
    if raw is None or not raw.strip():
        return None
    try:
        return (parse_int if kind is int else parse_float)(raw, low, high)
    except NumberError as exc:
        raise UsageError(f"${name}: {exc}") from None
