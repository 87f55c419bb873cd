"""Agent accuracy (AA) and road accuracy (RA) of the offline lowering against hand-written scenes.

    python bench/lowering_eval.py

Two suites: examples/ (the rules were written against these prompts) and tests/paraphrases/ (held out:
other wordings, their scenes written from the sentences). The paper reports AA .975 and RA .940 at best.
"""

from __future__ import annotations

import statistics
import sys
from pathlib import Path

from ttsgc.evaluate import agent_accuracy, road_accuracy
from ttsgc.language import parse_file
from ttsgc.lowering.offline import LoweringError, lower

ROOT = Path(__file__).resolve().parents[1]


def suite(folder: Path) -> tuple[float, float, list[str]]:
    aa, ra, misses = [], [], []
    for prompt in sorted(folder.glob("*.txt")):
        gold = parse_file(prompt.with_suffix(".tsg"))
        try:
            predicted = lower(prompt.read_text()).scenario
        except LoweringError as exc:
            aa.append(0.0)
            ra.append(0.0)
            misses.append(f"{prompt.stem}: {exc}")
            continue
        aa.append(agent_accuracy(gold, predicted))
        ra.append(road_accuracy(gold, predicted))
        if aa[-1] < 1 or ra[-1] < 1:
            misses.append(f"{prompt.stem}: AA {aa[-1]:.2f} RA {ra[-1]:.2f}")
    return statistics.mean(aa), statistics.mean(ra), misses


def main() -> int:
    for name, folder in (("examples (development)", ROOT / "examples"),
                         ("paraphrases (held out)", ROOT / "tests" / "paraphrases")):
        aa, ra, misses = suite(folder)
        print(f"{name:24} AA {aa:.3f}  RA {ra:.3f}  ({len(list(folder.glob('*.txt')))} prompts)")
        for miss in misses:
            print(f"    {miss}")
    print("paper, best: AA 0.975  RA 0.940")
    return 0


if __name__ == "__main__":
    sys.exit(main())
