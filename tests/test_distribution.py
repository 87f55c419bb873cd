"""compile --variants N --distribution: one scenario with parameters, a Deterministic ParameterValueDistribution
that expands to the N variants, and the concrete files; in esmini every permutation plays as its concrete file."""

from __future__ import annotations

import subprocess
from importlib import resources
from pathlib import Path

import pytest
import xmlschema
from lxml import etree

from conftest import EXAMPLES
from ttsgc.cli import main
from ttsgc.errors import ExitCode
from ttsgc.variation import expand

N = 3


def _canonical(data: bytes) -> bytes:
    return etree.tostring(etree.fromstring(data, etree.XMLParser(remove_blank_text=True)), method="c14n")


def _value_sets(dist: Path) -> list[dict[str, str]]:
    root = etree.parse(str(dist)).getroot()
    return [{a.get("parameterRef"): a.get("value") for a in value_set.iter("ParameterAssignment")}
            for value_set in root.iter("ParameterValueSet")]


@pytest.fixture(scope="module")
def distribution(tmp_path_factory):
    folder = tmp_path_factory.mktemp("dist")
    out = folder / "blocking.xosc"
    assert main(["compile", str(EXAMPLES / "blocking.tsg"), "-o", str(out), "--variants", str(N),
                 "--distribution", "--player", "sumo"]) == 0
    return out


def test_the_distribution_expands_to_the_concrete_files(distribution):
    dist = distribution.with_name("blocking.dist.xosc")
    schema = xmlschema.XMLSchema(str(resources.files("qc_openscenario") / "schema" / "1.3.0" / "OpenSCENARIO.xsd"))
    schema.validate(str(dist))
    schema.validate(str(distribution))
    root = etree.parse(str(dist)).getroot()
    assert root.find("ParameterValueDistribution/ScenarioFile").get("filepath") == distribution.name
    assert root.find("ParameterValueDistribution/Deterministic") is not None
    sets = _value_sets(dist)
    assert len(sets) == N and len({tuple(s.values()) for s in sets}) == N  # N different variants
    declared = {d.get("name"): d.get("value") for d in etree.parse(str(distribution)).iter("ParameterDeclaration")}
    assert set(declared) == set(sets[0]) and declared == sets[0]  # the nominal scene is the first variant
    kinds = {name.rsplit("_", 1)[-1] for name in declared}
    assert {"speed", "s", "distance"} <= kinds, declared  # speeds, start positions, the trigger distance
    template = distribution.read_bytes()
    for k, values in enumerate(sets, start=1):
        concrete = distribution.with_name(f"blocking-{k}.xosc")
        assert b"$" not in concrete.read_bytes()
        assert _canonical(expand(template, list(values), list(values.values()))) == _canonical(concrete.read_bytes())


def test_a_distribution_is_deterministic(distribution, tmp_path):
    out = tmp_path / "blocking.xosc"
    assert main(["compile", str(EXAMPLES / "blocking.tsg"), "-o", str(out), "--variants", str(N),
                 "--distribution", "--no-simulate"]) == 0
    for name in ("blocking.xosc", "blocking.dist.xosc", "blocking-2.xosc"):
        assert (tmp_path / name).read_bytes() == distribution.with_name(name).read_bytes(), name


@pytest.mark.parametrize("extra, code, says", [
    (["--target", "carla"], ExitCode.UNSUPPORTED_BY_TARGET, "no ParameterValueDistribution"),
    (["--osc-version", "1.0"], ExitCode.INVALID_SCENARIO, "1.1 or later"),
], ids=["carla", "osc-1.0"])
def test_a_distribution_needs_a_version_that_has_one(tmp_path, capsys, extra, code, says):
    out = tmp_path / "x.xosc"
    assert main(["compile", str(EXAMPLES / "blocking.tsg"), "-o", str(out), "--variants", "2", "--distribution",
                 "--no-simulate", *extra]) == code
    assert says in capsys.readouterr().err and list(tmp_path.iterdir()) == []


def test_a_distribution_needs_two_variants(tmp_path, capsys):
    assert main(["compile", str(EXAMPLES / "blocking.tsg"), "-o", str(tmp_path / "x.xosc"), "--distribution",
                 "--no-simulate"]) == ExitCode.INVALID_SCENARIO
    assert "--variants 2 or more" in capsys.readouterr().err


def _esmini_rows(esmini: Path, folder: Path, args: list[str], record: str) -> list[str]:
    subprocess.run([str(esmini), "--headless", "--fixed_timestep", "0.05", "--disable_log", "--record", record,
                    *args], cwd=folder, capture_output=True, timeout=120, check=True)
    written = sorted(folder.glob(f"{Path(record).stem}*.dat"))[-1]  # esmini names a permutation's run_k_of_n.dat
    subprocess.run([str(esmini.parent / "dat2csv"), "--file", written.name, "--extended"], cwd=folder,
                   capture_output=True, timeout=120, check=True)
    rows = written.with_suffix(".csv").read_text().splitlines()
    written.unlink()
    return [row for row in rows if row[:1].isdigit()]  # the samples, not the header naming the file


def test_every_permutation_plays_in_esmini_as_its_concrete_file_and_passes(shared, distribution, monkeypatch):
    from ttsgc.simulate.validate import validate

    esmini = shared / "tools" / "esmini" / "esmini"
    if not esmini.is_file() or not (esmini.parent / "dat2csv").is_file():
        pytest.skip("esmini is not in ../shared/tools/esmini")
    monkeypatch.setenv("TTSGC_ESMINI", str(esmini))
    folder = distribution.parent
    for k in range(N):
        concrete = folder / f"blocking-{k + 1}.xosc"
        permutation = _esmini_rows(esmini, folder, ["--osc", distribution.name, "--param_dist", "blocking.dist.xosc",
                                                   "--param_permutation", str(k)], f"perm{k}.dat")
        played = _esmini_rows(esmini, folder, ["--osc", concrete.name], f"concrete{k}.dat")
        assert len(permutation) > 10 and permutation == played, k  # the same run, sample for sample
        report = validate(concrete, "esmini")
        assert report.players == ["esmini"] and report.ok, report.table()
