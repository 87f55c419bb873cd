"""The evaluation harness and the TTSG plan importer."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from conftest import EXAMPLES
from ttsgc.cli import main
from ttsgc.evaluate import agent_accuracy, load_suite, road_accuracy, summarize, Run
from ttsgc.language import format_scenario, parse
from ttsgc.ttsg_import import import_plan, weather_of


def test_metrics_use_the_larger_count_as_denominator():
    gold = parse('scenario "g"\nroad {\n    lanes >= 2\n    has stop\n}\nstage s {\n    ego car go_straight\n'
                 '    car c1 at front stop\n    bus b1 at back go_straight\n}\n')
    predicted = parse('scenario "p"\nroad {\n    lanes >= 2\n}\nstage s {\n    ego car go_straight\n'
                      '    car c1 at front stop\n    car c2 at front stop\n    bus b1 at left go_straight\n}\n')
    assert agent_accuracy(gold, predicted) == pytest.approx(2 / 4)  # ego and c1 match, of max(3, 4)
    assert road_accuracy(gold, predicted) == pytest.approx(1 / 2)  # lanes match; 'has stop' missing


def test_diversity_counts_unique_agents_and_roads_over_the_generations():
    runs = [Run("a", "normal", k, "a", ok=True, road=road, agents=[["car", "go_straight", "ego"], agent])
            for k, (road, agent) in enumerate([("m 1:fwd", ["car", "stop", "front"]),
                                               ("m 2:fwd", ["car", "stop", "front"]),
                                               ("m 1:fwd", ["bus", "stop", "back"])])]
    summary = summarize(runs)
    assert summary["AD"] == pytest.approx(3 / 6, abs=1e-3) and summary["RD"] == pytest.approx(2 / 3, abs=1e-3)
    assert summary["SA"] == 1.0 and summary["failure_rate"] == 0.0


def test_eval_of_the_examples_prints_the_table_and_writes_json(tmp_path, capsys):
    report = tmp_path / "eval.json"
    assert main(["eval", str(EXAMPLES), "--seeds", "2", "--report", str(report)]) == 0
    out = capsys.readouterr().out
    for word in ("normal", "critical", "conditional", "all", "paper, best", "median time per run"):
        assert word in out
    data = json.loads(report.read_text())
    assert data["summary"]["cases"] == 18 and data["summary"]["runs"] == 36
    assert data["summary"]["AA"] == 1.0 and data["summary"]["SA"] == 1.0
    assert set(data["by_kind"]) == {"normal", "critical", "conditional"}


def test_suite_kinds_come_from_suite_toml():
    kinds = {c.name: c.kind for c in load_suite(EXAMPLES)}
    assert kinds["blocking"] == "critical" and kinds["emergency"] == "conditional"
    assert kinds["daily_traffic"] == "normal"


@pytest.mark.parametrize("preset, expected", [("ClearNoon", ("clear", "noon")),
                                              ("MidRainSunset", ("mid_rain", "sunset")),
                                              ("MidRainyNoon", ("mid_rain", "noon")),
                                              ("WetCloudyNight", ("wet_cloudy", "night"))])
def test_weather_presets(preset, expected):
    weather, note = weather_of(preset)
    assert (weather.condition, weather.time) == expected and note is None


def test_all_forty_ttsg_plans_import_with_their_repairs_noted(shared):
    plans = sorted((shared / "ttsg-plans").glob("*/*/agent_output.json"))
    assert len(plans) == 40
    for plan in plans:
        imported = import_plan(plan, plan.with_name("road_info.json"))
        assert parse(format_scenario(imported.scenario)) == imported.scenario
        assert imported.paper_road is not None
    crushing = import_plan(shared / "ttsg-plans" / "crushing" / "3" / "agent_output.json")
    assert any("also marked as the ego" in n for n in crushing.notes)
    assert [a.is_ego for a in crushing.scenario.agents()].count(True) == 1


def test_import_and_compile_on_the_papers_own_road(shared, tmp_path, capsys):
    plan = shared / "ttsg-plans" / "blocking" / "1"
    out = tmp_path / "b.tsg"
    assert main(["import-ttsg", str(plan / "agent_output.json"), str(plan / "road_info.json"), "-o", str(out),
                 "--xosc", str(tmp_path / "b.xosc"), "--maps", str(shared / "maps" / "carla")]) == 0
    printed = capsys.readouterr().out
    assert "the paper's road: Town07 52:bwd" in printed and (tmp_path / "b.xosc").is_file()
    assert main(["check", str(out)]) == 0


def test_ttsg_plans_suite_on_the_carla_towns(shared, tmp_path):
    report = tmp_path / "ttsg.json"
    assert main(["eval", str(shared / "ttsg-plans"), "--seeds", "1", "--maps", str(shared / "maps" / "carla"),
                 "--report", str(report)]) == 0
    summary = json.loads(report.read_text())["summary"]
    assert summary["runs"] == 40 and summary["SA"] >= 0.7


def _one_plan_suite(shared, tmp_path, kind: str, number: str):
    """A suite of one TTSG plan (a scratch copy: a suite is a folder of plan folders)."""
    import shutil

    source = shared / "ttsg-plans" / kind / number
    target = tmp_path / "suite" / kind / number
    target.mkdir(parents=True)
    for name in ("agent_output.json", "road_info.json"):
        shutil.copy(source / name, target / name)
    return tmp_path / "suite"


def test_eval_synthesises_a_road_when_no_library_road_fits_and_says_so(shared, tmp_path, capsys):
    """crushing/1 needs a crossing away from a junction, which no CARLA town has: with --synthesize never the
    run fails at compile; by default (auto, as compile) it is bound to a map built for it, and counted."""
    suite, carla = _one_plan_suite(shared, tmp_path, "crushing", "1"), str(shared / "maps" / "carla")
    report = tmp_path / "eval.json"
    assert main(["eval", str(suite), "--seeds", "1", "--maps", carla, "--synthesize", "never",
                 "--report", str(report)]) == 0
    run = json.loads(report.read_text())["runs"][0]
    assert run["failed_at"] == "compile" and "crosswalk" in run["reason"] and not run["synthesized"]
    capsys.readouterr()
    assert main(["eval", str(suite), "--seeds", "1", "--maps", carla, "--report", str(report)]) == 0
    assert "1 of 1 run(s) bound to a map synthesised for the scene" in capsys.readouterr().out
    data = json.loads(report.read_text())
    run = data["runs"][0]
    assert run["synthesized"] and run["road"].startswith("synth_") and data["summary"]["synthesized"] == 1
    assert run["ok"], run["reason"]


def test_import_ttsg_xosc_synthesises_a_road_unless_told_not_to(shared, tmp_path, capsys):
    plan = shared / "ttsg-plans" / "crushing" / "1"
    args = ["import-ttsg", str(plan / "agent_output.json"), str(plan / "road_info.json"), "-o",
            str(tmp_path / "c.tsg"), "--xosc", str(tmp_path / "c.xosc"), "--maps", str(shared / "maps" / "carla")]
    assert main(args + ["--synthesize", "never"]) == 4
    assert not (tmp_path / "c.xosc").exists() and not (tmp_path / "c.tsg").exists()
    capsys.readouterr()
    assert main(args) == 0
    assert "synthesised synth_" in capsys.readouterr().err
    assert (tmp_path / "c.xosc").is_file() and list(tmp_path.glob("synth_*.xodr"))


def test_every_rewrite_names_a_dev_prompt_with_its_gold():
    corpus = Path(__file__).parent / "corpus"
    keys = [line[len("KEY: "):] for path in sorted((corpus / "rewrites").glob("*.txt"))
            for line in path.read_text(encoding="utf-8").splitlines() if line.startswith("KEY: ")]
    assert len(keys) >= 600
    assert all(key.startswith("dev/") and (corpus / key).with_suffix(".tsg").is_file() for key in keys)
