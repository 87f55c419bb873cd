"""Import libsumo without numpy or urllib.request.

libsumo imports traci, traci imports sumolib, and sumolib's statistics module imports numpy for `sqrt` and
`set_printoptions` if it can (else math.sqrt): a tenth of a second or more of every simulation's start-up
for two functions the simulator never calls. Here numpy is hidden while libsumo loads, then the two names
are given back as stand-ins that import numpy when first called, so sumolib behaves as it would have.
sumolib's miscutils likewise imports urllib.request (http.client, ssl, email: another 15 ms) for `urlopen`,
which reads a network from a URL; it gets a stand-in that imports urllib.request when first called.
"""

from __future__ import annotations

import sys
from types import ModuleType


def _numpy_sqrt(value):
    import numpy

    return numpy.sqrt(value)


def _numpy_set_printoptions(*args, **kwargs):
    import numpy

    return numpy.set_printoptions(*args, **kwargs)


def _urlopen(*args, **kwargs):
    from urllib.request import urlopen

    return urlopen(*args, **kwargs)


def load_libsumo() -> ModuleType:
    """libsumo, loaded once per process."""
    if "libsumo" in sys.modules:
        return sys.modules["libsumo"]
    hidden = "numpy" not in sys.modules
    if hidden:
        sys.modules["numpy"] = None  # `import numpy` raises ImportError while this entry is None
    stand_in = None
    if "urllib.request" not in sys.modules:
        stand_in = sys.modules["urllib.request"] = ModuleType("urllib.request")
        stand_in.urlopen = _urlopen
    try:
        import libsumo
    finally:
        if hidden and sys.modules.get("numpy", ...) is None:
            del sys.modules["numpy"]
        if stand_in is not None and sys.modules.get("urllib.request") is stand_in:
            del sys.modules["urllib.request"]  # a later import gets the real module
    statistics = sys.modules.get("sumolib.statistics")
    if hidden and statistics is not None and not hasattr(statistics, "set_printoptions"):
        statistics.sqrt = _numpy_sqrt
        statistics.set_printoptions = _numpy_set_printoptions
    return libsumo
