"""Where the top-level data folders (grammar/, templates/, maps/, examples/) are, installed or in a checkout.

A wheel carries them inside the package (ttsgc/grammar, ...); a source checkout or an editable install
finds them beside the package at the repository's top level.
"""

from __future__ import annotations

from pathlib import Path

_PACKAGE = Path(__file__).resolve().parent


def resource_dir(name: str) -> Path:
    """The folder `name` (grammar, templates, maps or examples), wherever this installation keeps it."""
    for candidate in (_PACKAGE / name, _PACKAGE.parent / name):
        if candidate.is_dir():
            return candidate
    raise FileNotFoundError(f"ttsgc is installed without its '{name}' folder (looked in {_PACKAGE})")
