"""The `ttsgc` command: argument parsing and printing only; the work happens in the pipeline modules."""

from __future__ import annotations

import argparse
import functools
import json
import sys
import traceback
from pathlib import Path

from ttsgc import __version__
from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.files import (OutputError, check_outputs, protect_inputs, real_path, release_inputs, write_atomic,
                         write_output)

# Each command imports what it uses inside its function: `ttsgc validate` needs neither the language nor the
# compiler, `ttsgc check` no simulator; a start-up that loads everything costs every command.


def _check(args) -> int:
    from ttsgc.language import ScenarioError, parse_file

    results, failed = [], False
    for path in args.files:
        try:
            scenario = parse_file(path)
        except ScenarioError as exc:
            print(exc.render(), file=sys.stderr)
            failed = True
            continue
        results.append(scenario.to_json())
        if not args.json:
            agents = sum(len(stage.agents) for stage in scenario.stages)
            print(f"{path}: ok ({len(scenario.stages)} stage(s), {agents} agent(s))")
    if args.json and results:
        print(json.dumps(results[0] if len(args.files) == 1 else results, indent=2))
    return ExitCode.INVALID_SCENARIO if failed else ExitCode.OK


def _fmt(args) -> int:
    from ttsgc.language import ScenarioError, format_scenario, parse_file

    invalid = unformatted = False
    for path in args.files:
        try:
            scenario = parse_file(path)
        except ScenarioError as exc:
            print(exc.render(), file=sys.stderr)
            invalid = True
            continue
        canonical = format_scenario(scenario)
        current = Path(path).read_text(encoding="utf-8")
        if canonical == current:
            continue
        if args.check:
            print(f"{path}: not in the canonical layout (run 'ttsgc fmt {path}')", file=sys.stderr)
            unformatted = True
        else:
            try:
                write_output(path, canonical)
            except OutputError as exc:
                print(f"ttsgc: error: {exc}", file=sys.stderr)
                invalid = True
                continue
            print(f"{path}: formatted")
    if invalid:
        return ExitCode.INVALID_SCENARIO
    return ExitCode.NOT_FORMATTED if unformatted else ExitCode.OK


def _read_prompt(path: Path) -> str:
    from ttsgc.lowering import LoweringError

    try:
        return path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise LoweringError(f"{path}: cannot read the prompt: {exc}") from None


def _lower_file(args, source: Path, seed: int):
    from ttsgc.lowering import lower_prompt
    from ttsgc.lowering.llm import LlmSettings

    prompt = _read_prompt(source)
    settings = LlmSettings.from_env(args.model, args.temperature, args.max_tokens)
    lowering = lower_prompt(prompt, args.llm, seed=seed, settings=settings)
    if lowering.unknown:
        print(f"ttsgc: warning: {source}: words not understood: {', '.join(lowering.unknown)}", file=sys.stderr)
    for note in lowering.notes:  # every inference and repair of the plan inference, also in the .tsg
        print(f"ttsgc: note: {source}: {note}", file=sys.stderr)
    return prompt, lowering


def _lower(args) -> int:
    source = Path(args.input)
    protect_inputs(source)
    if args.output:
        check_outputs(args.output)
    prompt, lowering = _lower_file(args, source, args.seed or 0)
    text = lowering.tsg(prompt)
    if args.output:
        write_output(args.output, text)
        print(f"{args.output}: lowered ({lowering.method}, {lowering.tries} tr{'y' if lowering.tries == 1 else 'ies'})")
    else:
        print(text, end="")
    return ExitCode.OK


def _compile(args) -> int:
    from ttsgc.language import parse_file

    source = Path(args.input)
    kind = args.source_kind or ("text" if source.suffix.lower() in (".txt", ".prompt", ".md") else "tsg")
    out = Path(args.output) if args.output else source.with_suffix(".xosc")
    _protect_compile_inputs(source, args.maps)
    args.osc_version = _target_version(args)
    if args.distribution:
        return _compile_distribution(args, source, kind, out)
    targets = [out if args.variants == 1 else out.with_name(f"{out.stem}-{k + 1}{out.suffix}")
               for k in range(args.variants)]
    lowered_paths = [_lowered_path(target) if kind == "text" else None for target in targets]
    check_outputs(*targets, *filter(None, lowered_paths), *(_report_path(args, t) for t in targets if args.report))
    base_seed = args.seed
    status = ExitCode.OK
    for k, (target, lowered_path) in enumerate(zip(targets, lowered_paths)):
        seed = None if base_seed is None and args.variants == 1 else (base_seed or 0) + k
        lowering = lowered = None
        if kind == "text":
            prompt, lowering = _lower_file(args, source, seed or 0)
            scenario = lowering.scenario
            lowered = (lowered_path, lowering.tsg(prompt))  # to edit and compile again; written on success
        else:
            scenario = parse_file(source)
        status = max(status, _compile_one(args, scenario, target, seed, lowering, lowered))
    return status


def _compile_distribution(args, source: Path, kind: str, out: Path) -> int:
    """--variants N --distribution: one scenario with parameters, its distribution, N proven concrete files."""
    from ttsgc.language import parse_file
    from ttsgc.pipeline import compile_distribution, distribution_paths, write_distribution

    lowering = None
    if kind == "text":
        prompt, lowering = _lower_file(args, source, args.seed or 0)
        scenario = lowering.scenario
    else:
        scenario = parse_file(source)
    log = lambda message: print(message, file=sys.stderr)  # noqa: E731
    dist, failure = compile_distribution(scenario, out, args.variants, maps=args.maps, seed=args.seed,
                                         version=args.osc_version, simulate=not args.no_simulate, log=log,
                                         target=args.target, players=args.player)
    if failure is not None:
        print(failure.table(), file=sys.stderr)
        print(f"ttsgc: error: {out}: the scene or one of its variants does not do what it says; nothing was written",
              file=sys.stderr)
        return ExitCode.SIMULATION_FAILED
    if lowering is not None:
        write_output(_lowered_path(out), lowering.tsg(prompt))
    write_distribution(dist, out)
    dist_path, concrete = distribution_paths(out, args.variants)
    if args.report:
        data = {"parameters": dist.names, "variants": [
            {"file": str(path), "values": dict(zip(dist.names, row)),
             "report": report.model_dump(mode="json") if report is not None else None}
            for path, row, report in zip(concrete, dist.values, dist.reports)]}
        write_output(args.report, json.dumps(data, indent=2) + "\n")
    scene = dist.variants[0].scene
    proven = "; every variant proven" if not args.no_simulate else ""
    print(f"{out}: {scene.map_name} approach {scene.approach}, OpenSCENARIO {args.osc_version}, "
          f"{len(dist.names)} parameter(s) ({', '.join(dist.names)}); {dist_path}: {args.variants} variants "
          f"(Deterministic); concrete files {concrete[0].name} .. {concrete[-1].name}{proven}")
    return ExitCode.OK


def _protect_compile_inputs(source: Path, maps) -> None:
    """The scene or prompt and every map file named are inputs: no output may replace them."""
    from ttsgc.roads.opendrive import MapError
    from ttsgc.roads.retrieve import map_files

    protect_inputs(source)
    try:
        protect_inputs(*map_files(maps))
    except MapError:
        pass  # reported when the library is loaded


def _lowered_path(out: Path) -> Path:
    """Where the lowered scene goes: beside the output, unless a scene a person wrote is already there."""
    path = out.with_suffix(".tsg")
    if path == out:  # -o scene.tsg: the OpenSCENARIO takes that name
        return out.with_suffix(".lowered.tsg")
    if path.exists() and not path.read_text(encoding="utf-8", errors="replace").startswith("# Lowered ("):
        path = out.with_suffix(".lowered.tsg")
        print(f"ttsgc: note: {out.with_suffix('.tsg')} was not written by ttsgc; the lowered scene goes to {path}",
              file=sys.stderr)
    return path


def _report_path(args, out: Path) -> Path:
    """--report as given, or REPORT-k.json beside it for the k-th of several variants."""
    report_path = Path(args.report)
    if args.variants > 1:
        report_path = report_path.with_name(f"{report_path.stem}-{out.stem.rsplit('-', 1)[-1]}{report_path.suffix}")
    return report_path


def _compile_one(args, scenario, out: Path, seed, lowering, lowered: tuple[Path, str] | None = None) -> int:
    from ttsgc.pipeline import compile_and_prove, compile_scenario, write

    log = lambda message: print(message, file=sys.stderr)  # noqa: E731
    if args.no_simulate:
        compiled, report = compile_scenario(scenario, out, maps=args.maps, seed=seed, version=args.osc_version,
                                            target=args.target, synthesize=args.synthesize, log=log), None
    else:
        compiled, report = compile_and_prove(scenario, out, maps=args.maps, seed=seed, version=args.osc_version,
                                             log=log, players=args.player, target=args.target,
                                             synthesize=args.synthesize)
    scene = compiled.scene
    if args.explain:
        print(scene.explanation)
    if args.report:
        data = report.model_dump(mode="json") if report is not None else {"ok": None, "simulated": False}
        if lowering is not None:
            data["lowering"] = lowering.summary()
        write_output(_report_path(args, out), json.dumps(data, indent=2) + "\n")
    if report is not None and not report.ok:
        print(report.table(), file=sys.stderr)
        print(f"ttsgc: error: {out}: the scene does not do what it says on any of the roads tried; nothing was "
              f"written (--no-simulate writes it unchecked)", file=sys.stderr)
        return ExitCode.SIMULATION_FAILED
    write(compiled, out)
    if lowered is not None:
        write_output(*lowered)
    checked = f"; {_proven(report)}" if report is not None else ""
    print(f"{out}: {scene.map_name} approach {scene.approach} ({scene.score}/{scene.requirements} requirements, "
          f"seed {scene.seed}), OpenSCENARIO {args.osc_version}; map copied as {out.parent / compiled.map_name}"
          f"{checked}")
    if scene.unmet:
        print(f"ttsgc: warning: the chosen road does not meet: {', '.join(scene.unmet)}", file=sys.stderr)
    if getattr(args, "render", False):
        _render_file(out, out.with_suffix(".png"), "sumo" if args.player == "all" else args.player)
    return ExitCode.OK


def _target_version(args) -> str:
    from ttsgc.emit.xosc import DEFAULT_VERSION
    from ttsgc.targets import choose_version

    return choose_version(args.target, args.osc_version, DEFAULT_VERSION)


def _lint(args) -> int:
    from ttsgc.targets.coverage import coverage, errors, lint_file

    title = coverage(args.target).title
    failed = False
    for path in args.files:
        findings = lint_file(path, args.target)
        shown = findings if args.all else errors(findings)
        for finding in shown:
            print(finding.render(path, title))
        unsupported = len(errors(findings))
        failed = failed or unsupported > 0
        hidden = len(findings) - len(shown)
        print(f"{path}: {unsupported} element(s) {title} does not support"
              + (f" ({hidden} warning(s) and note(s) not shown; --all shows them)" if hidden else ""),
              file=sys.stderr)
    return ExitCode.UNSUPPORTED_BY_TARGET if failed else ExitCode.OK


def _synthesize_option(parser) -> None:
    """One --synthesize for every command that binds a scene to a road (compile, eval, import-ttsg --xosc)."""
    parser.add_argument("--synthesize", choices=["auto", "never", "always"], default="auto",
                        help="build an OpenDRIVE map for the scene: when no road of the library fits (auto, the "
                             "default), never (no fitting road is exit 4), or always (skip the library)")


def _eval(args) -> int:
    from ttsgc.evaluate import evaluate, report_json, table
    from ttsgc.runner import progress_bar
    from ttsgc.lowering import choose_method

    runs = evaluate(Path(args.suite), seeds=args.seeds, maps=args.maps, method=choose_method(args.llm),
                    simulate=not args.no_simulate, progress=progress_bar, workers=args.workers,
                    synthesize=args.synthesize)
    print(table(runs))
    failed = [r for r in runs if not r.ok]
    for r in failed[: args.show_failures]:
        print(f"  failed: {r.case} seed {r.seed} at {r.failed_at}: {r.reason}")
    if len(failed) > args.show_failures:
        print(f"  ... and {len(failed) - args.show_failures} more failed run(s) (see --report)")
    if args.report:
        write_output(args.report, report_json(runs) + "\n")
    return ExitCode.OK


def _import_ttsg(args) -> int:
    from ttsgc.language import format_scenario
    from ttsgc.pipeline import compile_and_prove, write
    from ttsgc.roads.retrieve import load_library
    from ttsgc.ttsg_import import import_plan

    protect_inputs(*filter(None, (args.plan, args.road_info)))
    check_outputs(*filter(None, (args.output, args.xosc)))
    imported = import_plan(args.plan, args.road_info)
    text = format_scenario(imported.scenario)
    for note in imported.notes:
        print(f"ttsgc: note: {note}", file=sys.stderr)

    def write_scene() -> None:  # only once everything asked for has succeeded
        write_output(args.output, text)
        print(f"{args.output}: imported" + (f" ({len(imported.notes)} repair(s) noted in the file)"
                                            if imported.notes else ""))

    if not args.xosc:
        write_scene()
        return ExitCode.OK
    out, only = Path(args.xosc), None
    paper = imported.paper_road
    if paper is not None:
        towns = {m.name for m in load_library(args.maps)}
        if paper.town not in towns:
            print(f"the paper's road: {paper.town} road {paper.road} ({paper.direction}); {paper.town} is not in the "
                  f"map library, ranking as usual")
        else:
            try:
                compiled, report = compile_and_prove(imported.scenario, out, args.maps, log=lambda m: None,
                                                     only=(paper.town, paper.approach), tries=1)
                fits = report.ok
                print(f"the paper's road: {paper.town} {paper.approach}: "
                      f"{'fits and validates' if fits else 'compiles but fails in simulation'}")
                only = (paper.town, paper.approach) if fits else None
            except TtsgcError as exc:
                print(f"the paper's road: {paper.town} {paper.approach}: does not fit ({str(exc).splitlines()[0]})")
    compiled, report = compile_and_prove(imported.scenario, out, args.maps, only=only,
                                         log=lambda m: print(m, file=sys.stderr),
                                         synthesize="never" if only else args.synthesize)
    if not report.ok:
        print(report.table(), file=sys.stderr)
        print(f"ttsgc: error: {out}: the scene does not do what it says on any of the roads tried; nothing was "
              f"written", file=sys.stderr)
        return ExitCode.SIMULATION_FAILED
    check_outputs(args.output, out)
    write(compiled, out)
    write_scene()
    print(f"{out}: {compiled.scene.map_name} {compiled.scene.approach}"
          f"{' (the paper' + chr(39) + 's road)' if only else ' (ranked)'}; {_proven(report)}")
    return ExitCode.OK


def _proven(report) -> str:
    """"proven in sumo, esmini (36 s played)", and which players were not run."""
    text = f"proven in {', '.join(report.players)} ({report.simulated_s:.0f} s played)"
    return text + "".join(f"; not run: {why}" for why in report.not_run)


def _validate(args) -> int:
    from ttsgc.simulate.validate import validate

    protect_inputs(args.scene)
    if args.report:
        check_outputs(args.report)
    report = validate(args.scene, args.player)
    print(report.table())
    if args.report:
        write_output(args.report, report.model_dump_json(indent=2) + "\n")
    return ExitCode.OK if report.ok else ExitCode.SIMULATION_FAILED


def _render_file(scene: Path, out: Path, player: str) -> None:
    from ttsgc.render import render_scene

    verdict = render_scene(scene, out, player)
    word = "not judged" if verdict.ok is None else ("ok" if verdict.ok else "FAILED")
    print(f"{out}: drawn ({verdict.player}, verdict {word})")


def _render(args) -> int:
    _render_file(Path(args.scene), Path(args.output) if args.output else Path(args.scene).with_suffix(".png"),
                 args.player)
    return ExitCode.OK


def _batch(args) -> int:
    from ttsgc.batch import plan_jobs, run_batch
    from ttsgc.lowering import choose_method
    from ttsgc.runner import progress_bar

    out = Path(args.output)
    jobs = plan_jobs(Path(args.prompts), out, variants=args.variants, maps=args.maps,
                     method=choose_method(args.llm), osc_version=args.osc_version, players=args.player)
    result = run_batch(jobs, out, workers=args.workers, ray_address=args.ray, progress=progress_bar)
    counts = {v: sum(r["verdict"] == v for r in result.rows) for v in ("ok", "failed", "error")}
    print(f"{out}: {len(result.rows)} scene(s): {counts['ok']} ok, {counts['failed']} failed in simulation, "
          f"{counts['error']} not compiled; {result.skipped} already finished; summary in "
          f"{out / 'summary.json'} and {out / 'summary.csv'}")
    if result.unfinished:
        print(f"ttsgc: error: {len(result.unfinished)} scene(s) met an internal fault and are left to the next run: "
              f"{', '.join(result.unfinished[:5])}", file=sys.stderr)
        return ExitCode.INTERNAL
    return ExitCode.OK


def _add_render_and_batch(commands, llm_options) -> None:
    render = commands.add_parser("render", help="draw a scene as the player played it: a bird's-eye .png, or an "
                                                "animation (.gif, .mp4)")
    render.add_argument("scene", metavar="SCENE.xosc")
    render.add_argument("-o", "--output", metavar="OUT.png|.gif|.mp4", help="default: the scene with .png")
    render.add_argument("--player", choices=["sumo", "esmini"], default="sumo", help="who plays it (default sumo)")
    render.set_defaults(run=_render)

    batch = commands.add_parser("batch", parents=[llm_options], help="compile and prove many scenes on every core "
                                                                     "(or a Ray cluster); resumes where it stopped")
    batch.add_argument("prompts", metavar="PROMPTS", help="a folder of .txt/.tsg, or a JSON Lines file of "
                                                          '{"prompt": ...} or {"tsg": ...}')
    batch.add_argument("-o", "--output", required=True, metavar="OUTDIR")
    batch.add_argument("--variants", type=_number(int, 1, 1000), default=1, metavar="N",
                       help="scenes per input (seeds 0..N-1)")
    batch.add_argument("--workers", type=_number(int, 1, 1024), metavar="N", help="processes at once (default: every core)")
    batch.add_argument("--ray", metavar="ADDRESS", help="run on a Ray cluster ('local' starts one on this machine; "
                                                        "needs pip install 'ttsgc[ray]')")
    batch.add_argument("--maps", action="append", metavar="PATH")
    batch.add_argument("--osc-version", choices=["1.0", "1.1", "1.2", "1.3"], default="1.3")
    _player_option(batch)
    batch.set_defaults(run=_batch)


def _serve(args) -> int:
    from ttsgc.server import run_command

    return run_command(args)


def _add_serve(commands) -> None:
    serve = commands.add_parser("serve", help="keep a warm ttsgc in the background: validate, compile and the other "
                                              "one-scene commands then start in milliseconds")
    action = serve.add_mutually_exclusive_group()
    action.add_argument("--stop", action="store_true", help="stop every server of this cache folder")
    action.add_argument("--status", action="store_true", help="list the servers that answer")
    action.add_argument("--foreground", action="store_true", help="serve in this process until Ctrl-C")
    serve.add_argument("--idle", type=_number(float, 0, 10**7), default=3 * 3600, metavar="SECONDS",
                       help="stop after this long without a command (default 3 hours; 0: never)")
    serve.set_defaults(run=_serve)


def table(headers: list[str], rows: list[list[str]]) -> str:
    """Plain aligned columns, for terminals and for pasting into notes."""
    widths = [max(len(str(x)) for x in column) for column in zip(headers, *rows)]
    lines = ["  ".join(str(x).ljust(w) for x, w in zip(row, widths)).rstrip() for row in [headers, *rows]]
    return "\n".join([lines[0], "  ".join("-" * w for w in widths), *lines[1:]])


def _approach_row(a) -> list[str]:
    turns = " ".join(f"{t.direction[0].upper() if t.direction != 'uturn' else 'U'}>{t.to_road}"
                     for t in a.turns if t.direction)
    edge = "+".join(x for x, present in (("shoulder", a.shoulder), ("sidewalk", a.sidewalk)) if present) or "-"
    return [a.map, a.id, str(a.lanes), str(a.opposite_lanes), f"{a.length:.0f}", edge, a.junction or "-",
            " ".join(dict.fromkeys(turns.split())) or "-", ",".join(a.signals) or "-", ",".join(a.objects) or "-",
            f"{a.speed_limit_kmh:g}" if a.speed_limit_kmh else "-"]


APPROACH_HEADERS = ["map", "approach", "lanes", "opp", "length", "edge", "junction", "turns", "signals", "objects",
                    "km/h"]


def _maps(args) -> int:
    from ttsgc.roads.retrieve import load_library, retrieve
    from ttsgc.scenario import RoadSpec

    library = load_library(args.maps)
    if args.maps_command == "list":
        rows = [[m.name, str(m.roads), str(m.junctions), str(len(m.approaches)),
                 str(sum(a.junction is not None for a in m.approaches)), m.path] for m in library]
        print(table(["map", "roads", "junctions", "approaches", "at junction", "file"], rows))
        return ExitCode.OK
    if args.maps_command == "show":
        chosen = [m for m in library if m.name == args.name or Path(m.path).stem == args.name]
        if not chosen:
            from ttsgc.roads.opendrive import MapError
            names = [m.name for m in library]
            from ttsgc.vocabulary import either, nearest
            hint = nearest(args.name, names)
            raise MapError(f"no map named '{args.name}' in the library"
                           + (f"; did you mean {either(hint)}?" if hint else f" (maps: {', '.join(names)})"))
        approaches = list(chosen[0].approaches)
    else:
        spec = RoadSpec(lanes=args.lanes, junction=args.junction,
                        required_signals=tuple(w for w in args.has if w in _signals()),
                        required_objects=tuple(w for w in args.has if w not in _signals()),
                        without_signals=tuple(w for w in args.without if w in _signals()),
                        without_objects=tuple(w for w in args.without if w not in _signals()))
        approaches = retrieve(library, spec)
    if args.json:
        print(json.dumps([a.model_dump(mode="json") for a in approaches], indent=2))
    else:
        print(table(APPROACH_HEADERS, [_approach_row(a) for a in approaches]))
        print(f"{len(approaches)} approach(es)")
    return ExitCode.OK


def _maps_synth(args) -> int:
    from ttsgc.language import parse_file
    from ttsgc.roads.index import load_index
    from ttsgc.roads.synth import chosen_seed, synthesize

    scenario = parse_file(args.scene)
    out = Path(args.output)
    if out.exists() and real_path(out) == real_path(args.scene):
        print(f"ttsgc: error: {out}: the map would overwrite the scene it is made from", file=sys.stderr)
        return ExitCode.INVALID_SCENARIO
    seed = chosen_seed(scenario, args.seed)
    design, data = synthesize(scenario, seed)
    write_atomic(out, data)
    approaches = load_index(out).approaches
    if args.json:
        print(json.dumps([a.model_dump(mode="json") for a in approaches], indent=2))
        return ExitCode.OK
    print(table(APPROACH_HEADERS, [_approach_row(a) for a in approaches]))
    arms = len(design.arms)
    print(f"{out}: {design.name}, {design.layout if design.layout == 'straight' else f'{design.layout} junction'} "
          f"({arms} road{'s' if arms > 1 else ''}), seed {seed}; the scene's approach is {design.ego_approach}")
    return ExitCode.OK


def _signals() -> set[str]:
    from ttsgc.vocabulary import SIGNALS
    return set(SIGNALS)


def _road_word(text: str) -> str:
    from ttsgc import vocabulary as V
    if text in V.SIGNALS or V.is_object(text):
        return text
    hint = V.nearest(text, list(V.SIGNALS) + V.object_words())
    raise argparse.ArgumentTypeError(f"unknown signal or object '{text}'"
                                     + (f"; did you mean {V.either(hint)}?" if hint else ""))


def _number(kind: type, low, high):
    """An argparse type reading a flag's number through the one bounded reader (nan, inf, 5000 digits and
    out-of-range values are usage errors, exit 2)."""
    from ttsgc.numbers import NumberError, parse_float, parse_int

    def read(text: str):
        try:
            return (parse_int if kind is int else parse_float)(text, low, high)
        except NumberError as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    read.__name__ = kind.__name__  # argparse names the type in its message
    return read


SEED = _number(int, 0, 2**32 - 1)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="ttsgc", description="A traffic-scenario compiler: English or the "
                                     "scenario language in, validated OpenSCENARIO out.")
    parser.add_argument("--version", action="version", version=f"ttsgc {__version__}")
    parser.add_argument("--debug", action="store_true", help="show a traceback on internal faults")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    check = commands.add_parser("check", help="validate .tsg files; all errors of a file at once")
    check.add_argument("files", nargs="+", metavar="FILE")
    check.add_argument("--json", action="store_true", help="print the scenario model as JSON")
    check.set_defaults(run=_check)

    fmt = commands.add_parser("fmt", help="rewrite .tsg files in the canonical layout, in place")
    fmt.add_argument("files", nargs="+", metavar="FILE")
    fmt.add_argument("--check", action="store_true", help="change nothing; exit 7 if a file would change")
    fmt.set_defaults(run=_fmt)

    llm_options = argparse.ArgumentParser(add_help=False)
    llm_options.add_argument("--llm", choices=["auto", "offline", "anthropic"], default="auto",
                             help="how English is lowered: the offline rules, or Claude through the anthropic SDK "
                                  "(auto: anthropic when ANTHROPIC_API_KEY is set, else offline)")
    llm_options.add_argument("--model", help="the LLM model (default: $TTSGC_MODEL, else a current Claude model)")
    llm_options.add_argument("--temperature", type=_number(float, 0.0, 2.0), help="LLM temperature (default: $TTSGC_TEMPERATURE, else 0)")
    llm_options.add_argument("--max-tokens", type=_number(int, 1, 128_000), help="LLM answer limit (default: $TTSGC_MAX_TOKENS, else 2048)")

    lower_ = commands.add_parser("lower", parents=[llm_options], help="lower an English prompt into a .tsg scene")
    lower_.add_argument("input", metavar="PROMPT.txt")
    lower_.add_argument("-o", "--output", metavar="SCENE.tsg", help="where to write (default: print it)")
    lower_.add_argument("--seed", type=SEED, help="picks among a scene kind's variants")
    lower_.set_defaults(run=_lower)

    compile_ = commands.add_parser("compile", parents=[llm_options],
                                   help="compile English (.txt) or a scene (.tsg) to OpenSCENARIO on a fitting road")
    compile_.add_argument("input", metavar="INPUT", help="a prompt (.txt) or a scene (.tsg)")
    compile_.add_argument("-o", "--output", metavar="OUT.xosc", help="where to write (default: INPUT with .xosc)")
    compile_.add_argument("--from", dest="source_kind", choices=["text", "tsg"],
                          help="the input's kind (default: by extension, .txt is English)")
    compile_.add_argument("--variants", type=_number(int, 1, 1000), default=1, metavar="N",
                          help="compile N different scenes (seeds N..N+k: other roads, other agent choices)")
    compile_.add_argument("--distribution", action="store_true",
                          help="with --variants N: the variants on one road (speeds, trigger distances, start "
                               "positions) as one scenario with parameters, OUT.dist.xosc (a Deterministic "
                               "ParameterValueDistribution) beside it, and the concrete OUT-1..N.xosc")
    compile_.add_argument("--maps", action="append", metavar="PATH",
                          help="an OpenDRIVE file or folder (repeatable); 'builtin' is the built-in library")
    compile_.add_argument("--seed", type=SEED, help="pins the choice among equally ranked roads "
                                                   "(default: the scene's seed, else 0)")
    compile_.add_argument("--explain", action="store_true", help="print the ranking table of candidate roads")
    compile_.add_argument("--osc-version", choices=["1.0", "1.1", "1.2", "1.3"],
                          help="OpenSCENARIO version (default 1.3; --target carla writes 1.0)")
    compile_.add_argument("--target", choices=["generic", "esmini", "carla"], default="generic",
                          help="the player the file is written for: generic OpenSCENARIO, esmini (held against its "
                               "coverage), carla (the 1.0 subset CARLA ScenarioRunner reads); default generic")
    compile_.add_argument("--no-simulate", action="store_true", help="skip the simulation check")
    compile_.add_argument("--report", metavar="REPORT.json", help="write the simulation report as JSON")
    compile_.add_argument("--render", action="store_true", help="also draw the scene, as a .png beside the .xosc")
    _player_option(compile_)
    _synthesize_option(compile_)
    compile_.set_defaults(run=_compile)

    validate = commands.add_parser("validate", help="play a .xosc (SUMO, esmini) and check that every agent "
                                                    "does what its intent says")
    validate.add_argument("scene", metavar="SCENE.xosc")
    _player_option(validate)
    validate.add_argument("--report", metavar="REPORT.json", help="write the report as JSON")
    validate.set_defaults(run=_validate)

    lint = commands.add_parser("lint", help="list every element of .xosc files that a player does not support, "
                                            "from its documented coverage")
    lint.add_argument("files", nargs="+", metavar="FILE.xosc")
    lint.add_argument("--target", choices=["carla", "esmini"], required=True, help="the player")
    lint.add_argument("--all", action="store_true", help="also list what is supported with a limit, or read past")
    lint.set_defaults(run=_lint)

    eval_ = commands.add_parser("eval", parents=[llm_options],
                                help="the paper's metrics (AA, RA, SA, AD, RD, failure rate) on a suite")
    eval_.add_argument("suite", metavar="SUITE", help="a folder of prompts (*.txt, gold *.tsg beside) or TTSG plans")
    eval_.add_argument("--seeds", type=_number(int, 1, 1000), default=5, help="generations per case (default 5)")
    eval_.add_argument("--maps", action="append", metavar="PATH", help="map files or folders ('builtin' for the "
                                                                       "built-in library)")
    eval_.add_argument("--report", metavar="EVAL.json", help="write every run and the summaries as JSON")
    eval_.add_argument("--no-simulate", action="store_true", help="compile only (SA then counts compiles)")
    eval_.add_argument("--show-failures", type=_number(int, 0, 1_000_000), default=10, metavar="N", help="list up to N failed runs")
    eval_.add_argument("--workers", type=_number(int, 1, 1024), metavar="N",
                       help="processes running cases at once (default: every core)")
    _synthesize_option(eval_)
    eval_.set_defaults(run=_eval)

    importer = commands.add_parser("import-ttsg", help="turn a TTSG plan (agent_output.json) into a .tsg scene")
    importer.add_argument("plan", metavar="agent_output.json")
    importer.add_argument("road_info", nargs="?", metavar="road_info.json", help="the road the paper chose")
    importer.add_argument("-o", "--output", required=True, metavar="SCENE.tsg")
    importer.add_argument("--xosc", metavar="OUT.xosc", help="also compile it: onto the paper's road when its town "
                                                              "is in --maps and the scene fits, else ranked")
    importer.add_argument("--maps", action="append", metavar="PATH")
    _synthesize_option(importer)
    importer.set_defaults(run=_import_ttsg)

    _add_render_and_batch(commands, llm_options)
    _add_serve(commands)

    maps_options = argparse.ArgumentParser(add_help=False)
    maps_options.add_argument("--maps", action="append", metavar="PATH",
                              help="an OpenDRIVE file or folder (repeatable); 'builtin' is the built-in library, "
                                   "the default when no --maps is given")
    maps_options.add_argument("--json", action="store_true", help="print JSON")
    maps = commands.add_parser("maps", help="the map library: list maps, show one, query approaches")
    maps_commands = maps.add_subparsers(dest="maps_command", required=True, metavar="SUBCOMMAND")
    maps_commands.add_parser("list", parents=[maps_options], help="the maps of the library")
    show = maps_commands.add_parser("show", parents=[maps_options], help="every approach of one map")
    show.add_argument("name", help="the map's name or file stem")
    query = maps_commands.add_parser("query", parents=[maps_options], help="the approaches that meet conditions")
    query.add_argument("--lanes", type=_number(int, 1, 100), default=1, help="at least this many lanes in the driving direction")
    junction = query.add_mutually_exclusive_group()
    junction.add_argument("--junction", dest="junction", action="store_true", default=None,
                          help="ends at a junction")
    junction.add_argument("--no-junction", dest="junction", action="store_false", help="leaves room for a scene well before any junction")
    query.add_argument("--has", action="append", default=[], type=_road_word, metavar="WORD",
                       help="a required signal or object (repeatable)")
    query.add_argument("--without", action="append", default=[], type=_road_word, metavar="WORD",
                       help="a forbidden signal or object (repeatable)")
    maps.set_defaults(run=_maps)
    synth = maps_commands.add_parser("synth", help="build an OpenDRIVE map with what a scene needs")
    synth.add_argument("scene", metavar="SCENE.tsg")
    synth.add_argument("-o", "--output", required=True, metavar="ROAD.xodr")
    synth.add_argument("--seed", type=int, help="varies angles, lengths and curvature (default: the scene's seed, "
                                                "else 0)")
    synth.add_argument("--json", action="store_true", help="print the map's approaches as JSON")
    synth.set_defaults(run=_maps_synth)
    return parser


@functools.cache
def cached_parser() -> argparse.ArgumentParser:
    """The parser, built once per process: a warm server builds it before forking its children."""
    return build_parser()


def _player_option(command) -> None:
    command.add_argument("--player", choices=["sumo", "esmini", "all"], default="all",
                         help="which player proves the scene (default all: every player available here; esmini is "
                              "found through $TTSGC_ESMINI or on PATH)")


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised like Ctrl-C so that every temporary folder and child process is cleaned up on the way out."""


def _on_sigterm(signum, frame):
    raise Terminated()


def main(argv: list[str] | None = None) -> int:
    """The command line of this process when argv is None (a warm server runs it if one is up), else argv."""
    import signal
    import threading

    if argv is None:
        from ttsgc.forward import forward

        forwarded = forward(sys.argv[1:])
        if forwarded is not None:
            return forwarded
    args = cached_parser().parse_args(argv)
    installed = threading.current_thread() is threading.main_thread()
    previous = signal.signal(signal.SIGTERM, _on_sigterm) if installed else None
    try:
        return int(args.run(args))
    except TtsgcError as exc:
        from ttsgc.language.diagnostics import ScenarioError

        text = exc.render()
        print(text if isinstance(exc, ScenarioError) else f"ttsgc: error: {text}", file=sys.stderr)  # has its own
        return int(exc.exit_code)
    except BrokenPipeError:  # the reader went away (| head): stop quietly, as a shell pipeline expects
        _silence_stdout()
        return 141
    except KeyboardInterrupt as exc:
        print("ttsgc: terminated" if isinstance(exc, Terminated) else "ttsgc: interrupted", file=sys.stderr)
        return 143 if isinstance(exc, Terminated) else 130
    except Exception as exc:  # noqa: BLE001 - the last line of defence: no traceback unless asked
        if args.debug:
            traceback.print_exc()
        else:
            print(f"ttsgc: internal error: {type(exc).__name__}: {exc} (run with --debug for a traceback)",
                  file=sys.stderr)
        return int(ExitCode.INTERNAL)
    finally:
        release_inputs()
        if installed:
            signal.signal(signal.SIGTERM, previous if previous is not None else signal.SIG_DFL)


def command() -> None:
    """The ttsgc command's entry point."""
    exit_process(main())


def exit_process(code: int) -> None:
    """End this process with code: at once, streams flushed, when an interrupted pool's thread is still running,
    as the interpreter would otherwise wait for it at exit without bound; else through the usual exit."""
    import os

    from ttsgc.runner import pool_left_running

    if pool_left_running():
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):
                pass
        os._exit(code)
    sys.exit(code)


def _silence_stdout() -> None:
    """Point stdout at /dev/null so the interpreter's last flush does not fail on the closed pipe again."""
    import os

    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError):
        pass


if __name__ == "__main__":
    sys.exit(main())
