"""The road library: OpenDRIVE in (opendrive), an index of approaches (index), retrieval by conditions."""

from ttsgc.roads.index import Approach, MapIndex, Turn, load_index
from ttsgc.roads.opendrive import MapError, read_opendrive
from ttsgc.roads.retrieve import NoRoadError, load_library, retrieve

__all__ = ["Approach", "MapError", "MapIndex", "NoRoadError", "Turn", "load_index", "load_library",
           "read_opendrive", "retrieve"]
