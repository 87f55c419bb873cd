"""SUMO as a player: the network (netconvert of the scene's map, cached) and the executor that plays a Plan."""

from ttsgc.simulate.players.sumo.executor import NAME, play, unavailable

__all__ = ["NAME", "play", "unavailable"]
