"""scenariogeneration's OpenSCENARIO half, imported without its OpenDRIVE half.

`import scenariogeneration` runs the package's __init__, which imports scenariogeneration.xodr and through it
scipy.integrate, and scenariogeneration.xosc's __init__ imports its file reader and through it xmlschema:
about 0.5 s of a compile that uses neither. Here both packages are made importable without running their
__init__ first: the OpenSCENARIO writer's own modules (actions, entities, ...) are imported as usual and
their public names placed in the package, as its __init__ would; the first time anything else is asked of
either package, its real __init__ runs in place, so any later user sees the whole library. The classes are
scenariogeneration's own, so the files written are the same bytes.
"""

from __future__ import annotations

import importlib
import importlib.util
import sys
from types import ModuleType

# scenariogeneration/xosc/__init__.py imports these, then xosc_reader (the one that needs xmlschema)
WRITER_MODULES = ("actions", "entities", "enumerations", "exceptions", "parameters", "position", "scenario",
                  "storyboard", "triggers", "utils")


def _deferred_package(name: str) -> ModuleType:
    """The package `name` with its __init__ not yet run: it runs, in place, on the first missing attribute."""
    if name in sys.modules:
        return sys.modules[name]
    spec = importlib.util.find_spec(name)
    package = importlib.util.module_from_spec(spec)

    def complete(attribute: str):
        del package.__getattr__
        spec.loader.exec_module(package)
        return getattr(package, attribute)

    package.__getattr__ = complete
    sys.modules[name] = package
    return package


def openscenario_writer() -> ModuleType:
    """scenariogeneration.xosc with everything but its reader, which is loaded when first asked for."""
    if "scenariogeneration.xosc" in sys.modules:
        return sys.modules["scenariogeneration.xosc"]
    parent = _deferred_package("scenariogeneration")
    xosc = _deferred_package("scenariogeneration.xosc")
    parent.xosc = xosc
    for name in WRITER_MODULES:
        module = importlib.import_module(f"scenariogeneration.xosc.{name}")
        public = getattr(module, "__all__", None) or [k for k in vars(module) if not k.startswith("_")]
        for key in public:
            setattr(xosc, key, getattr(module, key))
    return xosc
