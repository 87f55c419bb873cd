"""The players: each turns a Plan into a Trace (ttsgc.simulate.trace). A player is a module with
`available() -> str` (empty when it can run here, else why not) and `play(plan, seed) -> Trace`."""

from __future__ import annotations

import importlib

PLAYERS = ("sumo", "esmini")


def player(name: str):
    if name not in PLAYERS:
        raise ValueError(f"no player '{name}'; the players are {', '.join(PLAYERS)}")
    return importlib.import_module(f"ttsgc.simulate.players.{name}")


def why_unavailable(name: str) -> str:
    """Empty when the player can run here, else the reason it cannot."""
    return player(name).unavailable()
