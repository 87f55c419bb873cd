"""The paper's quality figures (TTSG appendix, "Metrics Definition"), and suites to measure them on.

AA, agent accuracy: agents matched on (type, action, position) / max(#gold, #predicted).
RA, road accuracy: road properties matched (lanes, junction, required and forbidden signals and objects)
/ max(#gold, #predicted).
WA, weather accuracy (ours, not the paper's): the weather's condition and time of day both right.
"""

from __future__ import annotations

import functools
import json
import statistics
import tempfile
import time
import tomllib
from collections import Counter
from dataclasses import asdict, dataclass, field
from pathlib import Path

from ttsgc.errors import TtsgcError, UsageError
from ttsgc.scenario import Scenario


def agent_keys(s: Scenario) -> Counter:
    return Counter((a.type, a.action, a.relative_to_ego or "ego") for a in s.agents())


def road_keys(s: Scenario) -> set[tuple]:
    r = s.road
    keys = {("lanes", r.lanes)}
    if r.junction is not None:
        keys.add(("junction", r.junction))
    keys |= {("has", w) for w in r.required_signals + r.required_objects}
    keys |= {("without", w) for w in r.without_signals + r.without_objects}
    return keys


def agent_accuracy(gold: Scenario, predicted: Scenario) -> float:
    g, p = agent_keys(gold), agent_keys(predicted)
    return sum((g & p).values()) / max(sum(g.values()), sum(p.values()), 1)


def road_accuracy(gold: Scenario, predicted: Scenario) -> float:
    g, p = road_keys(gold), road_keys(predicted)
    return len(g & p) / max(len(g), len(p), 1)


def weather_accuracy(gold: Scenario, predicted: Scenario) -> float:
    """WA: 1 when the weather is read right (condition and time of day), or left out where the gold has none."""
    key = lambda s: (s.weather.condition, s.weather.time) if s.weather is not None else None  # noqa: E731
    return float(key(gold) == key(predicted))


def load_gold(path: Path) -> Scenario:
    """A gold scene; where the language cannot yet say that the ego acts in a later stage, those later `ego`
    lines are left out (the lowering leaves them out too, with a note), so the rest can still be scored."""
    import re

    from ttsgc.language import ScenarioError, parse

    text = Path(path).read_text(encoding="utf-8")
    try:
        return parse(text, str(path))
    except ScenarioError:
        lines, block, stage = [], None, 0
        for line in text.splitlines():
            if re.match(r"\s*stage\b", line):
                stage += 1
                block = [line]
                continue
            if block is not None:
                if not (stage > 1 and re.match(r"\s*ego\b", line)):
                    block.append(line)
                if line.strip().startswith("}"):
                    if any(re.match(r"\s*[a-z]+\s+[A-Za-z_]", x) for x in block[1:-1]):
                        lines += block
                    block = None
                continue
            lines.append(line)
        return parse("\n".join(lines) + "\n", str(path))


# -- suites ---------------------------------------------------------------------------------------------

PAPER_BEST = {"AA": 0.975, "RA": 0.940, "SA": 0.800, "AD": 0.686, "RD": 0.975}
# The paper's diversity table (Table "Evaluation results for scene diversity"), per scenario.
PAPER_DIVERSITY = {"daily_traffic": (0.789, 1.0, 1.0), "intersection": (0.833, 1.0, 0.8),
                   "crushing": (0.5, 1.0, 0.4), "blocking": (0.75, 1.0, 0.8), "cut_off": (0.6, 1.0, 0.8),
                   "two_wheels": (0.714, 0.8, 0.6), "emergency": (0.5, 1.0, 1.0), "weather": (0.8, 1.0, 1.0)}
KINDS_OF_TTSG = {"blocking": "critical", "crushing": "critical", "cut_off": "critical", "daily_traffic": "normal",
                 "intersection": "normal", "two_wheels": "normal", "emergency": "conditional",
                 "weather": "conditional"}


@dataclass
class Case:
    name: str
    kind: str  # normal | critical | conditional
    group: str = ""  # the prompt it is a generation of (diversity is measured over a group)
    prompt: Path | None = None  # English, lowered
    plan: Path | None = None  # a TTSG plan, imported
    road_info: Path | None = None
    gold: Path | None = None  # the hand-written scene
    generation: int = 0  # its place among the cases of its group (TTSG plans: the kind's runs)


@dataclass
class Run:
    case: str
    kind: str
    seed: int
    group: str = ""
    ok: bool = False
    failed_at: str | None = None  # lower | compile | simulate
    reason: str = ""
    road: str | None = None  # map + approach
    agents: list = field(default_factory=list)
    aa: float | None = None
    ra: float | None = None
    seconds: dict = field(default_factory=dict)
    paper_road: str | None = None  # the TTSG plan's own road, and whether the scene fit it
    paper_road_fit: bool | None = None
    players: dict = field(default_factory=dict)  # player -> the scene proven in it (SA per player)
    synthesized: bool = False  # bound to a map synthesised for the scene (its road is that map's)


def load_suite(folder: Path) -> list[Case]:
    """A suite: prompts (*.txt, with a gold *.tsg beside where there is one) or TTSG plan folders."""
    folder = Path(folder)
    if not folder.is_dir():
        raise UsageError(f"{folder}: not a folder (a suite is a folder of prompts or TTSG plans)")
    kinds = {}
    if (folder / "suite.toml").is_file():
        try:
            kinds = tomllib.loads((folder / "suite.toml").read_text(encoding="utf-8")).get("kinds", {})
        except (tomllib.TOMLDecodeError, OSError, UnicodeDecodeError) as exc:
            raise UsageError(f"{folder / 'suite.toml'}: cannot be read: {exc}") from None
        if not isinstance(kinds, dict):
            raise UsageError(f"{folder / 'suite.toml'}: 'kinds' must be a table of case = kind")
    cases = []
    generations: Counter = Counter()
    for plan in sorted(folder.glob("**/agent_output.json")):
        group = plan.parent.parent.name
        info = plan.with_name("road_info.json")
        cases.append(Case(f"{group}/{plan.parent.name}", kinds.get(group, KINDS_OF_TTSG.get(group, "normal")),
                          group=group, plan=plan, road_info=info if info.is_file() else None,
                          generation=generations[group]))
        generations[group] += 1
    for prompt in sorted(folder.glob("*.txt")):
        gold = prompt.with_suffix(".tsg")
        cases.append(Case(prompt.stem, kinds.get(prompt.stem, "normal"), group=prompt.stem, prompt=prompt,
                          gold=gold if gold.is_file() else None))
    if not cases:
        raise UsageError(f"{folder}: no cases (prompts *.txt or TTSG plans agent_output.json)")
    return cases


def run_case(case: Case, seed: int, maps, method: str = "offline", simulate: bool = True,
             synthesize: str = "never") -> Run:
    """synthesize: as compile's --synthesize; the paper's own road is always tried on the library alone."""
    from ttsgc.language import parse_file
    from ttsgc.lowering import lower_prompt
    from ttsgc.pipeline import compile_and_prove, compile_scenario, is_synthesized
    from ttsgc.ttsg_import import import_plan

    run = Run(case.name, case.kind, seed, case.group)
    seed = generation_seed(case, seed)
    t = time.perf_counter()
    try:
        if case.plan is not None:
            imported = import_plan(case.plan, case.road_info)
            scenario, paper = imported.scenario, imported.paper_road
        else:
            scenario, paper = lower_prompt(case.prompt.read_text(), method, seed=seed).scenario, None
    except TtsgcError as exc:
        run.failed_at, run.reason = "lower", str(exc).splitlines()[0]
        return run
    run.seconds["lower"] = time.perf_counter() - t
    run.agents = [list(k) for k in agent_keys(scenario).elements()]
    if case.gold is not None:
        gold = parse_file(case.gold)
        run.aa, run.ra = agent_accuracy(gold, scenario), road_accuracy(gold, scenario)
    with tempfile.TemporaryDirectory(prefix="ttsgc-eval-") as scratch:
        out = Path(scratch) / "scene.xosc"

        def compile_run(only):
            synth = "never" if only else synthesize
            if simulate:
                return compile_and_prove(scenario, out, maps, seed, log=lambda m: None, only=only,
                                         tries=1 if only else 3, synthesize=synth)
            return compile_scenario(scenario, out, maps, seed, only=only, synthesize=synth), None
        t = time.perf_counter()
        outcome = None
        if paper is not None:
            run.paper_road = f"{paper.town} {paper.approach}"
            try:  # the road the paper chose, when its town is in the library and the scene is proven on it
                outcome = compile_run((paper.town, paper.approach))
                if outcome[1] is not None and not outcome[1].ok:
                    outcome = None
            except Exception:  # noqa: BLE001 - it does not fit there: the ranked roads are tried next
                outcome = None
            if outcome is None:
                t = time.perf_counter()
            run.paper_road_fit = outcome is not None
        try:
            compiled, report = outcome or compile_run(None)
        except TtsgcError as exc:
            run.failed_at, run.reason = "compile", str(exc).splitlines()[0]
            return run
        except Exception as exc:  # noqa: BLE001 - a fault of the player on one run is that run's failure
            run.failed_at, run.reason = "simulate", f"internal error: {type(exc).__name__}: {exc}"[:300]
            return run
        elapsed = time.perf_counter() - t
        run.road = f"{compiled.scene.map_name} {compiled.scene.approach}"
        run.synthesized = is_synthesized(compiled.scene)
        if report is None:
            run.seconds["compile"] = elapsed
            run.ok = True
            return run
        run.seconds["compile+simulate"] = elapsed
        run.ok = report.ok
        run.players.update({v.player: v.ok for v in report.verdicts})
        if not report.ok:
            failed = [f"{a.name}: {a.reason}" for a in report.agents if not a.achieved]
            failed += [f"collision {c.a}/{c.b}" for c in report.collisions if not c.asked_for] + report.problems
            run.failed_at, run.reason = "simulate", "; ".join(failed)[:300]
    return run


def generation_seed(case: Case, seed: int, per_group: int = 100) -> int:
    """The seed a run binds with. The TTSG plans of one kind are generations of one request: they take
    consecutive seeds (seed x 100 + their place in the group), so the ranking spreads them over equally good
    roads as it spreads the seeds of one prompt."""
    return seed * per_group + case.generation if case.plan is not None else seed


def road_of(road: str | None) -> str | None:
    """'MAP ROAD:DIRECTION' -> 'MAP ROAD': the paper counts two directions of one road as one road."""
    return road.rsplit(":", 1)[0] if road else None


def players_of(runs: list[Run]) -> list[str]:
    return sorted({p for r in runs for p in r.players})


def summarize(runs: list[Run]) -> dict:
    """AA, RA (first seed of each case against its gold), SA, failure rate, and AD, RD over the generations of
    each prompt (its seeds, or for TTSG plans the runs of one scenario kind)."""
    by_case: dict[str, list[Run]] = {}
    by_group: dict[str, list[Run]] = {}
    for r in runs:
        by_case.setdefault(r.case, []).append(r)
        by_group.setdefault(r.group or r.case, []).append(r)
    firsts = [rs[0] for rs in by_case.values()]
    aa = [r.aa for r in firsts if r.aa is not None]
    ra = [r.ra for r in firsts if r.ra is not None]
    ad, rd = [], []
    for rs in by_group.values():
        agents = [tuple(a) for r in rs for a in r.agents]
        if agents:
            ad.append(len(set(agents)) / len(agents))
        rd.append(len({road_of(r.road) for r in rs if r.road}) / len(rs))
    mean = lambda xs: round(statistics.mean(xs), 3) if xs else None  # noqa: E731
    return {"cases": len(by_case), "runs": len(runs), "AA": mean(aa), "RA": mean(ra),
            "SA": mean([1.0 if r.ok else 0.0 for r in runs]), "AD": mean(ad), "RD": mean(rd),
            "failure_rate": mean([0.0 if r.ok else 1.0 for r in runs]),
            "synthesized": sum(r.synthesized for r in runs),
            "SA_by_player": {p: mean([1.0 if r.players.get(p) else 0.0 for r in runs]) for p in players_of(runs)}}


def table(runs: list[Run]) -> str:
    kinds = sorted({r.kind for r in runs}, key=lambda k: ("normal", "critical", "conditional").index(k)
                   if k in ("normal", "critical", "conditional") else 9)
    rows = [(k, summarize([r for r in runs if r.kind == k])) for k in kinds] + [("all", summarize(runs))]
    lines = _metric_rows("kind", rows, runs)
    lines.append(f"{'paper, best':24} " + " ".join(f"{PAPER_BEST[m]:.3f}" for m in ("AA", "RA", "SA", "AD", "RD")))
    synthesized = sum(r.synthesized for r in runs)
    if synthesized:
        lines.append(f"{synthesized} of {len(runs)} run(s) bound to a map synthesised for the scene "
                     f"(no library road fit; RD counts each as its own road)")
    lines += ["", _by_group(runs)]
    times: dict[str, list[float]] = {}
    for r in runs:
        for stage, seconds in r.seconds.items():
            times.setdefault(stage, []).append(seconds)
    lines.append("median time per run: " + ", ".join(f"{stage} {statistics.median(v) * 1000:.0f} ms"
                                                      for stage, v in times.items()))
    return "\n".join(lines)


def _run_job(job: tuple) -> Run:
    return run_case(*job)


def _fmt(v) -> str:
    return "  -  " if v is None else f"{v:.3f}"


def _metric_rows(title: str, rows: list[tuple[str, dict]], runs: list[Run]) -> list[str]:
    """One row per kind; SA, then SA in each player that played the scenes (a column per player)."""
    players = players_of(runs)
    lines = [f"{title:12} {'cases':>5} {'runs':>5}   AA     RA     SA     AD     RD    fail"
             + "".join(f"  SA {p:>6}" for p in players), "-" * (72 + 11 * len(players))]
    for kind, s in rows:
        lines.append(f"{kind:12} {s['cases']:5} {s['runs']:5}  " + " ".join(
            _fmt(s[m]) for m in ("AA", "RA", "SA", "AD", "RD", "failure_rate"))
            + "".join(f"  {_fmt(s['SA_by_player'].get(p)):>9}" for p in players))
    return lines


def _by_group(runs: list[Run]) -> str:
    """AD, RD and SA side by side for each prompt (or each kind of TTSG plans), the paper's figure beside."""
    groups = list(dict.fromkeys(r.group or r.case for r in runs))
    width = max([len(g) for g in groups] + [12])
    lines = [f"{'generations of':{width}} {'runs':>4}   AD     RD     SA    paper AD  RD    SA",
             "-" * (width + 50)]
    for g in groups:
        s = summarize([r for r in runs if (r.group or r.case) == g])
        paper = PAPER_DIVERSITY.get(g)
        lines.append(f"{g:{width}} {s['runs']:4}  {_fmt(s['AD'])} {_fmt(s['RD'])} {_fmt(s['SA'])}"
                     + (f"   {paper[0]:.3f} {paper[1]:.3f} {paper[2]:.3f}" if paper else ""))
    return "\n".join(lines)


def evaluate(folder: Path, seeds: int = 5, maps=None, method: str = "offline", simulate: bool = True,
             progress=None, workers: int | None = None, synthesize: str = "never") -> list[Run]:
    """Every case and seed on the runner (every core by default); runs in case-then-seed order."""
    from ttsgc import runner

    cases = load_suite(folder)
    jobs = [(case, seed, maps, method, simulate, synthesize) for case in cases for seed in range(seeds)]
    runs: list[Run | None] = [None] * len(jobs)
    warm_up = functools.partial(runner.warm_pipeline, maps)
    outcomes = runner.run(_run_job, jobs, workers, warm_up=warm_up)
    try:
        for done, (index, run) in enumerate(outcomes, 1):
            runs[index] = run
            if progress:
                progress(done, len(jobs), jobs[index][0].name)
    finally:
        outcomes.close()
    return runs


def report_json(runs: list[Run]) -> str:
    kinds = sorted({r.kind for r in runs})
    return json.dumps({"summary": summarize(runs), "by_kind": {k: summarize([r for r in runs if r.kind == k])
                                                               for k in kinds},
                       "paper_best": PAPER_BEST, "runs": [asdict(r) for r in runs]}, indent=2)
