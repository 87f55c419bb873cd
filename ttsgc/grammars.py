"""The package's grammars (grammar/*.lark) as LALR parsers, their analysis cached on disk.

Analysing a grammar (the LALR tables) takes lark 15-40 ms on every start of a process; loading the result
takes 2-5 ms. lark keeps the analysis itself when given a cache file, and checks on load that it is the
analysis of the same grammar text, options, lark and Python. The file goes in ttsgc's cache folder, named by
the same things, and is written under a name of its own and then renamed, so that processes starting at once
(a batch's workers) never read half of one. A cache that cannot be written only costs the analysis.
"""

from __future__ import annotations

import hashlib
import os
import sys
from pathlib import Path

from lark import Lark
from lark import __version__ as LARK_VERSION

from ttsgc.resources import resource_dir

_UNHASHED = ("lexer_callbacks",)  # objects of this process: given again on every load, not part of the key


def cache_folder() -> Path:
    """$TTSGC_CACHE_DIR/parsers, else the user cache folder's (the road indexes' policy, roads/index.py)."""
    from platformdirs import user_cache_dir

    return Path(os.environ.get("TTSGC_CACHE_DIR") or user_cache_dir("ttsgc")) / "parsers"


def lalr_parser(grammar_file: str, **options) -> Lark:
    """A Lark(parser="lalr") of grammar/GRAMMAR_FILE with these options, as if built from the text."""
    text = (resource_dir("grammar") / grammar_file).read_text(encoding="utf-8")
    hashed = repr(sorted((k, repr(v)) for k, v in options.items() if k not in _UNHASHED))
    key = hashlib.sha256(f"{text}\0{hashed}\0{LARK_VERSION}\0{sys.version_info[:2]}".encode()).hexdigest()[:20]
    final = cache_folder() / f"{Path(grammar_file).stem}-{key}.lark"
    if final.is_file():
        return Lark(text, parser="lalr", cache=str(final), **options)
    scratch = final.with_name(f".{final.name}.{os.getpid()}.tmp")
    try:
        final.parent.mkdir(parents=True, exist_ok=True)
        parser = Lark(text, parser="lalr", cache=str(scratch), **options)
        os.replace(scratch, final)
        return parser
    except OSError:
        scratch.unlink(missing_ok=True)
        return Lark(text, parser="lalr", **options)
