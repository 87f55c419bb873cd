"""Start-up and scaling: each command imports what it uses, and the lean imports still give whole libraries."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def fresh(code: str):
    """Run code in a fresh interpreter (the repository first on the path); the JSON of its last line."""
    done = subprocess.run([sys.executable, "-c", f"import sys, json\n{code}"], capture_output=True, text=True,
                          cwd=ROOT, env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"})
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.splitlines()[-1])


def modules_after(code: str) -> set[str]:
    """The modules a fresh interpreter holds after running code."""
    return set(fresh(f"{code}\nprint(json.dumps(sorted(sys.modules)))"))


HEAVY = ("scipy", "xmlschema", "networkx", "scenariogeneration.xodr", "qc_openscenario.checks")


def test_compiling_loads_neither_the_opendrive_writer_nor_scipy_xmlschema_networkx():
    loaded = modules_after("import ttsgc.cli, ttsgc.pipeline, ttsgc.emit.xosc, ttsgc.roads.retrieve")
    assert "scenariogeneration.xosc.actions" in loaded
    assert not [m for m in loaded if m.split(".")[0] in HEAVY or m in HEAVY]


def test_commands_that_do_not_simulate_do_not_load_sumo():
    loaded = modules_after("from ttsgc.cli import main\nmain(['check', 'examples/blocking.tsg'])")
    assert not {"libsumo", "ttsgc.pipeline", "ttsgc.emit.xosc", "lxml.etree"} & loaded


def test_the_lean_openscenario_writer_completes_to_the_whole_library_when_asked():
    code = """
import ttsgc.emit.xosc
from scenariogeneration import xosc
writer = {k for k in vars(xosc) if not k.startswith('__')}
assert 'xmlschema' not in sys.modules
xosc.ParseOpenScenario  # the reader: the package's own __init__ runs now
import scenariogeneration
assert scenariogeneration.ScenarioGenerator and scenariogeneration.xodr.OpenDrive
whole = {k for k in vars(xosc) if not k.startswith('__')}
assert writer < whole and 'CatalogLoader' in whole, whole - writer
"""
    assert "scenariogeneration.xodr" in modules_after(code)


def test_the_lean_writer_has_every_name_the_package_import_gives():
    names = "print(json.dumps(sorted(k for k in vars(xosc) if not k.startswith('__'))))"
    lean = fresh(f"import ttsgc.emit.xosc\nfrom scenariogeneration import xosc\nxosc.ParseOpenScenario\n{names}")
    plain = fresh(f"from scenariogeneration import xosc\n{names}")
    assert lean == plain and len(plain) > 200
