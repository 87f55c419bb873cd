"""Prove a scene file: read it once, play it in each player asked for, judge each trace, one Report.

"all" means every player that can run here; one that cannot is named in the report as not run."""

from __future__ import annotations

from pathlib import Path

from ttsgc.errors import ExitCode, TtsgcError
from ttsgc.roads.opendrive import load_opendrive
from ttsgc.simulate.judge import Report, judge, report
from ttsgc.simulate.plan import read_plan
from ttsgc.simulate.players import PLAYERS, player, why_unavailable

ALL = "all"


class PlayerUnavailable(TtsgcError):
    """A player asked for by name cannot run here (a command line asking for what is not there)."""

    exit_code = ExitCode.INVALID_SCENARIO


def chosen_players(choice: str = ALL) -> tuple[list[str], list[str]]:
    """(players to run, "player: why not" for those left out). A player named alone must be available."""
    if choice != ALL:
        why = why_unavailable(choice)
        if why:
            raise PlayerUnavailable(f"cannot validate with {choice}: {why}")
        return [choice], []
    run, skipped = [], []
    for name in PLAYERS:
        why = why_unavailable(name)
        if why:
            skipped.append(f"{name}: {why}")
        else:
            run.append(name)
    return run, skipped


def validate(xosc: str | Path, players: str = ALL, seed: int = 1) -> Report:
    plan = read_plan(Path(xosc))
    names, skipped = chosen_players(players)
    odr = load_opendrive(plan.xodr)
    verdicts = [judge(plan, player(name).play(plan, seed=seed), odr) for name in names]
    return report(plan, verdicts, skipped)
