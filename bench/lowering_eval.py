"""The lowering's quality by the paper's metrics: AA (agents), RA (road) and WA (weather), per split and voice.

    python bench/lowering_eval.py                 # offline rules on every suite
    python bench/lowering_eval.py --misses dev    # also list each prompt of the dev split that is not exact
    python bench/lowering_eval.py --only dev      # one suite only (repeatable)
    python bench/lowering_eval.py --only rewrites --misses rewrites  # dev prompts as other hands wrote them
    python bench/lowering_eval.py --only dev --rephrased dev  # also: dev read mirrored and rephrased (bench/rephrasings.py)
    python bench/lowering_eval.py --llm anthropic # the LLM lowering (ANTHROPIC_API_KEY), with tokens per scene

Suites: tests/corpus/{dev,test}/<voice>/*.txt with gold *.tsg beside (rules are written against dev only; test
is read only here, to measure), tests/corpus/paper/ (the paper's ten ablation prompts, shown beside the paper's
table), examples/, tests/paraphrases/, and tests/corpus/rewrites/ (dev prompts written again by other hands,
scored against the dev gold they rewrite: how far the rules hold on wordings they were not written against).
WA scores a scene's weather as one property: condition and time of day both right, or no weather where the gold
has none. Timings are medians over the prompts.
"""

from __future__ import annotations

import argparse
import re
import statistics
import sys
import time
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from ttsgc.errors import TtsgcError  # noqa: E402
from ttsgc.evaluate import agent_accuracy, agent_keys, load_gold, road_accuracy, weather_accuracy  # noqa: E402
from ttsgc.lowering import lower_prompt  # noqa: E402

sys.path.insert(0, str(ROOT / "bench"))
from rephrasings import REPHRASINGS as WRITERS_REWRITES, ego_named  # noqa: E402

PAPER = {"AA": 0.975, "RA": 0.940}  # GPT-4o with analysis and CoT, the paper's table "Results of plan quality"
SUITES = (("dev", ROOT / "tests" / "corpus" / "dev"), ("test", ROOT / "tests" / "corpus" / "test"),
          ("paper", ROOT / "tests" / "corpus" / "paper"), ("examples", ROOT / "examples"),
          ("paraphrases", ROOT / "tests" / "paraphrases"))


REWRITES = ROOT / "tests" / "corpus" / "rewrites"
REWRITE = re.compile(r"^KEY: (\S+)\nPROMPT: (.*)$", re.M)


def rewrites() -> list[tuple[str, str]]:
    """(dev key, prompt) of every rewrite; a written '\\n' is the writer's line break."""
    return [(key, text.replace("\\n", "\n")) for path in sorted(REWRITES.glob("*.txt"))
            for key, text in REWRITE.findall(path.read_text(encoding="utf-8"))]


def score(prompt: Path, method: str, text: str | None = None) -> dict:
    gold = load_gold(prompt.with_suffix(".tsg"))
    start = time.perf_counter()
    try:
        lowering = lower_prompt(prompt.read_text(encoding="utf-8") if text is None else text, method)
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


SWAP = {"left": "right", "right": "left", "Left": "Right", "Right": "Left", "LEFT": "RIGHT", "RIGHT": "LEFT"}
SIDE_BOUND = re.compile(r"nearside|offside|kerb|curb|undertak|inside|far ?side|near ?side|shoulder|verge|pavement"
                        r"|sidewalk|slow lane|fast lane|overtaking lane|\b[LR]\b", re.I)  # sides that do not mirror
REPHRASINGS = {  # meaning-preserving rewrites: the gold stays the gold
    "the ego named the AV": lambda t: re.sub(r"\b([Tt])he ego( vehicle| car)?\b", lambda m: m.group(1) + "he AV", t),
    "the ego named my car": ego_named("my car"),
    "lower case": lambda t: t.lower().rstrip(".!"),
    "articles dropped": lambda t: re.sub(r"\b(the|a|an) ", "", t),
    "verbs rephrased": lambda t: re.sub(r"\bturns (left|right)\b", r"makes a \1 turn",
                                        re.sub(r"\bgoes straight\b", "continues straight ahead",
                                               re.sub(r"\bstops\b", "comes to a halt", t))),
    **WRITERS_REWRITES,
}


def mirrored(text: str) -> str:
    return re.sub(r"\b(left|right|Left|Right|LEFT|RIGHT)\b", lambda m: SWAP[m.group(1)], text)


def mirrored_keys(scene) -> Counter:
    swap = lambda x: x.replace("left", "@").replace("right", "left").replace("@", "right")  # noqa: E731
    return Counter(tuple(swap(v) for v in key) for key in agent_keys(scene).elements())


def rephrased(folder: Path) -> None:
    """Each prompt read mirrored (left and right swapped, gold mirrored) and rephrased: how many read worse than
    the prompt as written. A reading rule that fits the words of the dev split, not English, shows up here."""
    prompts = sorted(p for p in folder.glob("**/*.txt") if p.with_suffix(".tsg").is_file())
    worse, total = 0, 0
    for p in prompts:
        text = p.read_text(encoding="utf-8")
        if not re.search(r"\b(left|right)\b", text, re.I) or SIDE_BOUND.search(text):
            continue
        total += 1
        try:
            worse += mirrored_keys(load_gold(p.with_suffix(".tsg"))) != agent_keys(
                lower_prompt(mirrored(text), "offline").scenario)
        except TtsgcError:
            worse += 1
    print(f"  {'mirrored':26} {worse:4} of {total} read otherwise than the mirrored gold")
    as_written: dict[Path, float] = {}
    for name, rewrite in REPHRASINGS.items():
        worse = total = 0
        for p in prompts:
            text = p.read_text(encoding="utf-8")
            if rewrite(text) == text:
                continue
            total += 1
            gold = load_gold(p.with_suffix(".tsg"))
            try:
                if p not in as_written:
                    as_written[p] = agent_accuracy(gold, lower_prompt(text, "offline").scenario)
                before = as_written[p]
                worse += agent_accuracy(gold, lower_prompt(rewrite(text), "offline").scenario) < before
            except TtsgcError:
                worse += 1
        print(f"  {name:26} {worse:4} of {total} read worse")


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
    parser.add_argument("--rephrased", action="append", default=[], metavar="SUITE",
                        help="also read this suite mirrored and rephrased (never use it on test)")
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
        if name in args.rephrased:
            rephrased(folder)
        if name in args.misses:
            for p, r in results.items():
                if "miss" in r:
                    print(f"    {p.relative_to(folder)}: {r['miss']}")
    if not args.only or "rewrites" in args.only:
        scored = [(key, score(ROOT / "tests" / "corpus" / key, args.llm, text)) for key, text in rewrites()]
        print(row("rewrites (of dev)", [r for _, r in scored]))
        for voice in sorted({key.split("/")[1] for key, _ in scored}):
            print(row(f"  {voice}", [r for key, r in scored if key.split("/")[1] == voice]))
        if "rewrites" in args.misses:
            for key, r in scored:
                if "miss" in r:
                    print(f"    {key}: {r['miss']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
