"""The `ttsgc` command: argument parsing and printing only; the work happens in the pipeline modules."""

from __future__ import annotations

import argparse
import json
import sys
import traceback
from pathlib import Path

from ttsgc import __version__
from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.files import write_atomic

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
            write_atomic(path, canonical)
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
    return prompt, lowering


def _lower(args) -> int:
    source = Path(args.input)
    prompt, lowering = _lower_file(args, source, args.seed or 0)
    text = lowering.tsg(prompt)
    if args.output:
        write_atomic(args.output, text)
        print(f"{args.output}: lowered ({lowering.method}, {lowering.tries} tr{'y' if lowering.tries == 1 else 'ies'})")
    else:
        print(text, end="")
    return ExitCode.OK


def _compile(args) -> int:
    from ttsgc.language import parse_file

    source = Path(args.input)
    kind = args.source_kind or ("text" if source.suffix.lower() in (".txt", ".prompt", ".md") else "tsg")
    out = Path(args.output) if args.output else source.with_suffix(".xosc")
    base_seed = args.seed
    status = ExitCode.OK
    for k in range(args.variants):
        seed = None if base_seed is None and args.variants == 1 else (base_seed or 0) + k
        target = out if args.variants == 1 else out.with_name(f"{out.stem}-{k + 1}{out.suffix}")
        lowering = None
        if kind == "text":
            prompt, lowering = _lower_file(args, source, seed or 0)
            scenario = lowering.scenario
            write_atomic(_lowered_path(target), lowering.tsg(prompt))  # to edit and compile again
        else:
            scenario = parse_file(source)
        status = max(status, _compile_one(args, scenario, target, seed, lowering))
    return status


def _lowered_path(out: Path) -> Path:
    """Where the lowered scene goes: beside the output, unless a scene a person wrote is already there."""
    path = out.with_suffix(".tsg")
    if path.exists() and not path.read_text(encoding="utf-8", errors="replace").startswith("# Lowered ("):
        path = out.with_suffix(".lowered.tsg")
        print(f"ttsgc: note: {out.with_suffix('.tsg')} was not written by ttsgc; the lowered scene goes to {path}",
              file=sys.stderr)
    return path


def _compile_one(args, scenario, out: Path, seed, lowering) -> int:
    from ttsgc.pipeline import compile_and_prove, compile_scenario, write

    log = lambda message: print(message, file=sys.stderr)  # noqa: E731
    if args.no_simulate:
        compiled, report = compile_scenario(scenario, out, maps=args.maps, seed=seed,
                                            version=args.osc_version), None
    else:
        compiled, report = compile_and_prove(scenario, out, maps=args.maps, seed=seed,
                                             version=args.osc_version, log=log)
    scene = compiled.scene
    if args.explain:
        print(scene.explanation)
    if args.report:
        data = report.model_dump(mode="json") if report is not None else {"ok": None, "simulated": False}
        if lowering is not None:
            data["lowering"] = lowering.summary()
        report_path = Path(args.report)
        if args.variants > 1:
            report_path = report_path.with_name(f"{report_path.stem}-{out.stem.rsplit('-', 1)[-1]}{report_path.suffix}")
        write_atomic(report_path, json.dumps(data, indent=2) + "\n")
    if report is not None and not report.ok:
        print(report.table(), file=sys.stderr)
        print(f"ttsgc: error: {out}: the scene does not do what it says on any of the roads tried; nothing was "
              f"written (--no-simulate writes it unchecked)", file=sys.stderr)
        return ExitCode.SIMULATION_FAILED
    write(compiled, out)
    checked = f"; proven in SUMO ({report.simulated_s:.0f} s simulated)" if report is not None else ""
    print(f"{out}: {scene.map_name} approach {scene.approach} ({scene.score}/{scene.requirements} requirements, "
          f"seed {scene.seed}), OpenSCENARIO {args.osc_version}; map copied as {out.parent / compiled.map_name}"
          f"{checked}")
    if scene.unmet:
        print(f"ttsgc: warning: the chosen road does not meet: {', '.join(scene.unmet)}", file=sys.stderr)
    return ExitCode.OK


def _eval(args) -> int:
    from ttsgc.evaluate import evaluate, progress_bar, report_json, table
    from ttsgc.lowering import choose_method

    runs = evaluate(Path(args.suite), seeds=args.seeds, maps=args.maps, method=choose_method(args.llm),
                    simulate=not args.no_simulate, progress=progress_bar)
    print(table(runs))
    failed = [r for r in runs if not r.ok]
    for r in failed[: args.show_failures]:
        print(f"  failed: {r.case} seed {r.seed} at {r.failed_at}: {r.reason}")
    if len(failed) > args.show_failures:
        print(f"  ... and {len(failed) - args.show_failures} more failed run(s) (see --report)")
    if args.report:
        write_atomic(args.report, report_json(runs) + "\n")
    return ExitCode.OK


def _import_ttsg(args) -> int:
    from ttsgc.pipeline import compile_and_prove, write
    from ttsgc.roads.retrieve import load_library
    from ttsgc.language import format_scenario
    from ttsgc.ttsg_import import import_plan

    imported = import_plan(args.plan, args.road_info)
    text = format_scenario(imported.scenario)
    write_atomic(args.output, text)
    print(f"{args.output}: imported" + (f" ({len(imported.notes)} repair(s) noted in the file)"
                                        if imported.notes else ""))
    for note in imported.notes:
        print(f"ttsgc: note: {note}", file=sys.stderr)
    if not args.xosc:
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
                                         log=lambda m: print(m, file=sys.stderr))
    if not report.ok:
        print(report.table(), file=sys.stderr)
        return ExitCode.SIMULATION_FAILED
    write(compiled, out)
    print(f"{out}: {compiled.scene.map_name} {compiled.scene.approach}"
          f"{' (the paper' + chr(39) + 's road)' if only else ' (ranked)'}; proven in SUMO")
    return ExitCode.OK


def _validate(args) -> int:
    from ttsgc.simulate.sumo import simulate

    report = simulate(args.scene)
    print(report.table())
    if args.report:
        write_atomic(args.report, report.model_dump_json(indent=2) + "\n")
    return ExitCode.OK if report.ok else ExitCode.SIMULATION_FAILED


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
    llm_options.add_argument("--temperature", type=float, help="LLM temperature (default: $TTSGC_TEMPERATURE, else 0)")
    llm_options.add_argument("--max-tokens", type=int, help="LLM answer limit (default: $TTSGC_MAX_TOKENS, else 2048)")

    lower_ = commands.add_parser("lower", parents=[llm_options], help="lower an English prompt into a .tsg scene")
    lower_.add_argument("input", metavar="PROMPT.txt")
    lower_.add_argument("-o", "--output", metavar="SCENE.tsg", help="where to write (default: print it)")
    lower_.add_argument("--seed", type=int, help="picks among a scene kind's variants")
    lower_.set_defaults(run=_lower)

    compile_ = commands.add_parser("compile", parents=[llm_options],
                                   help="compile English (.txt) or a scene (.tsg) to OpenSCENARIO on a fitting road")
    compile_.add_argument("input", metavar="INPUT", help="a prompt (.txt) or a scene (.tsg)")
    compile_.add_argument("-o", "--output", metavar="OUT.xosc", help="where to write (default: INPUT with .xosc)")
    compile_.add_argument("--from", dest="source_kind", choices=["text", "tsg"],
                          help="the input's kind (default: by extension, .txt is English)")
    compile_.add_argument("--variants", type=int, default=1, metavar="N",
                          help="compile N different scenes (seeds N..N+k: other roads, other agent choices)")
    compile_.add_argument("--maps", action="append", metavar="PATH",
                          help="an OpenDRIVE file or folder (repeatable); 'builtin' is the built-in library")
    compile_.add_argument("--seed", type=int, help="pins the choice among equally ranked roads "
                                                   "(default: the scene's seed, else 0)")
    compile_.add_argument("--explain", action="store_true", help="print the ranking table of candidate roads")
    compile_.add_argument("--osc-version", choices=["1.0", "1.1", "1.2", "1.3"], default="1.3",
                          help="OpenSCENARIO version (1.0 is what CARLA ScenarioRunner reads; default 1.3)")
    compile_.add_argument("--no-simulate", action="store_true", help="skip the simulation check")
    compile_.add_argument("--report", metavar="REPORT.json", help="write the simulation report as JSON")
    compile_.set_defaults(run=_compile)

    validate = commands.add_parser("validate", help="run a .xosc in SUMO and check that every agent does "
                                                    "what its intent says")
    validate.add_argument("scene", metavar="SCENE.xosc")
    validate.add_argument("--report", metavar="REPORT.json", help="write the report as JSON")
    validate.set_defaults(run=_validate)

    eval_ = commands.add_parser("eval", parents=[llm_options],
                                help="the paper's metrics (AA, RA, SA, AD, RD, failure rate) on a suite")
    eval_.add_argument("suite", metavar="SUITE", help="a folder of prompts (*.txt, gold *.tsg beside) or TTSG plans")
    eval_.add_argument("--seeds", type=int, default=5, help="generations per case (default 5)")
    eval_.add_argument("--maps", action="append", metavar="PATH", help="map files or folders ('builtin' for the "
                                                                       "built-in library)")
    eval_.add_argument("--report", metavar="EVAL.json", help="write every run and the summaries as JSON")
    eval_.add_argument("--no-simulate", action="store_true", help="compile only (SA then counts compiles)")
    eval_.add_argument("--show-failures", type=int, default=10, metavar="N", help="list up to N failed runs")
    eval_.set_defaults(run=_eval)

    importer = commands.add_parser("import-ttsg", help="turn a TTSG plan (agent_output.json) into a .tsg scene")
    importer.add_argument("plan", metavar="agent_output.json")
    importer.add_argument("road_info", nargs="?", metavar="road_info.json", help="the road the paper chose")
    importer.add_argument("-o", "--output", required=True, metavar="SCENE.tsg")
    importer.add_argument("--xosc", metavar="OUT.xosc", help="also compile it: onto the paper's road when its town "
                                                              "is in --maps and the scene fits, else ranked")
    importer.add_argument("--maps", action="append", metavar="PATH")
    importer.set_defaults(run=_import_ttsg)

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
    query.add_argument("--lanes", type=int, default=1, help="at least this many lanes in the driving direction")
    junction = query.add_mutually_exclusive_group()
    junction.add_argument("--junction", dest="junction", action="store_true", default=None,
                          help="ends at a junction")
    junction.add_argument("--no-junction", dest="junction", action="store_false", help="leaves room for a scene well before any junction")
    query.add_argument("--has", action="append", default=[], type=_road_word, metavar="WORD",
                       help="a required signal or object (repeatable)")
    query.add_argument("--without", action="append", default=[], type=_road_word, metavar="WORD",
                       help="a forbidden signal or object (repeatable)")
    maps.set_defaults(run=_maps)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return int(args.run(args))
    except TtsgcError as exc:
        print(f"ttsgc: error: {exc.render()}", file=sys.stderr)
        return int(exc.exit_code)
    except KeyboardInterrupt:
        print("ttsgc: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # noqa: BLE001 - the last line of defence: no traceback unless asked
        if args.debug:
            traceback.print_exc()
        else:
            print(f"ttsgc: internal error: {type(exc).__name__}: {exc} (run with --debug for a traceback)",
                  file=sys.stderr)
        return int(ExitCode.INTERNAL)


if __name__ == "__main__":
    sys.exit(main())
