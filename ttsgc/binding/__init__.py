"""Binding: a Scenario with no spawn points becomes a BoundScene on a concrete road of a map."""

from ttsgc.binding.scene import BoundScene, bind

__all__ = ["BoundScene", "bind"]
