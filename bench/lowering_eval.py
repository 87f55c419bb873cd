"""The lowering's quality by the paper's metrics: AA (agents), RA (road) and WA (weather), per split and voice.

    python bench/lowering_eval.py                 # offline rules on every suite
    python bench/lowering_eval.py --misses dev    # also list each prompt of the dev split that is not exact
    python bench/lowering_eval.py --only dev      # one suite only (repeatable)
    python bench/lowering_eval.py --llm anthropic # the LLM lowering (ANTHROPIC_API_KEY), with tokens per scene

Suites: tests/corpus/{dev,test}/<voice>/*.txt with gold *.tsg beside (rules are written against dev only; test
is read only here, to measure), tests/corpus/paper/ (the paper's ten ablation prompts, shown beside the paper's
table), examples/ and tests/paraphrases/. WA scores a scene's weather as one property: condition and time of
day both right, or no weather where the gold has none. Timings are medians over the prompts.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from ttsgc.errors import TtsgcError  # noqa: E402
from ttsgc.evaluate import agent_accuracy, load_gold, road_accuracy, weather_accuracy  # noqa: E402
from ttsgc.lowering import lower_prompt  # noqa: E402

PAPER = {"AA": 0.975, "RA": 0.940}  # GPT-4o with analysis and CoT, the paper's table "Results of plan quality"
SUITES = (("dev", ROOT / "tests" / "corpus" / "dev"), ("test", ROOT / "tests" / "corpus" / "test"),
          ("paper", ROOT / "tests" / "corpus" / "paper"), ("examples", ROOT / "examples"),
          ("paraphrases", ROOT / "tests" / "paraphrases"))


def score(prompt: Path, method: str) -> dict:
    gold = load_gold(prompt.with_suffix(".tsg"))
    start = time.perf_counter()
    try:
        lowering = lower_prompt(prompt.read_text(encoding="utf-8"), method)
    except TtsgcError as exc:
        return {"AA": 0.0, "RA": 0.0, "WA": 0.0, "ms": 0.0, "miss": f"refused: {exc}", "tokens": 0}
    ms = (time.perf_counter() - start) * 1000
    scene = lowering.scenario
    result = {"AA": agent_accuracy(gold, scene), "RA": road_accuracy(gold, scene),
              "WA": weather_accuracy(gold, scene), "ms": ms,
              "tokens": sum(lowering.usage.get(k, 0) for k in ("input_tokens", "output_tokens"))}
    if min(result["AA"], result["RA"], result["WA"]) < 1:
        result["miss"] = f"AA {result['AA']:.2f} RA {result['RA']:.2f} WA {result['WA']:.0f}"
    return result


def row(name: str, results: list[dict]) -> str:
    if not results:
        return f"{name:28} (no prompts)"
    mean = lambda key: statistics.mean(r[key] for r in results)  # noqa: E731
    text = (f"{name:28} {len(results):4}  AA {mean('AA'):.3f}  RA {mean('RA'):.3f}  WA {mean('WA'):.3f}  "
            f"median {statistics.median(r['ms'] for r in results):.1f} ms")
    tokens = [r["tokens"] for r in results if r["tokens"]]
    return text + (f"  {statistics.mean(tokens):.0f} tokens/scene" if tokens else "")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--llm", default="offline", choices=("offline", "anthropic"))
    parser.add_argument("--misses", action="append", default=[], metavar="SUITE",
                        help="list the prompts of this suite that are not exact (never use it on test)")
    parser.add_argument("--only", action="append", default=[], metavar="SUITE",
                        help="score only these suites (default: all)")
    args = parser.parse_args(argv)
    print(f"{'suite':28} {'n':>4}  lowering: {args.llm}")
    for name, folder in SUITES:
        if args.only and name not in args.only:
            continue
        prompts = sorted(p for p in folder.glob("**/*.txt") if p.with_suffix(".tsg").is_file())
        if not prompts:
            continue
        results = {p: score(p, args.llm) for p in prompts}
        print(row(name, list(results.values())))
        voices = sorted({p.parent.name for p in prompts if p.parent != folder})
        for voice in voices:
            print(row(f"  {voice}", [r for p, r in results.items() if p.parent.name == voice]))
        if name == "paper":
            print(f"{'  the paper (GPT-4o, CoT)':28} {len(prompts):4}  AA {PAPER['AA']:.3f}  RA {PAPER['RA']:.3f}")
        if name in args.misses:
            for p, r in results.items():
                if "miss" in r:
                    print(f"    {p.relative_to(folder)}: {r['miss']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
