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
from ttsgc.language import ScenarioError, format_scenario, parse_file


def _check(args) -> int:
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
