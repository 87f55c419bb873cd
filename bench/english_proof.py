"""How many English prompts become scenes that do all they say: lower and prove every Nth dev prompt.

    python bench/english_proof.py                    # every 9th prompt of tests/corpus/dev, this checkout
    python bench/english_proof.py --every 5 --offset 2
    python bench/english_proof.py --code /other/checkout   # the same sample, another checkout's ttsgc
    python bench/english_proof.py --prompts list.txt      # the dev prompts a file names, one a line

Each prompt is compiled as `ttsgc compile PROMPT.txt` does (lowered, bound, played in SUMO and in esmini,
tried on the next-ranked roads); a prompt passes when that exits 0. Set TTSGC_ESMINI to prove in esmini too.
Prints the pass rate, each failure's exit code and first reason, and the median time per prompt (noisy on
a shared machine). Only the dev split: the test split is never compiled here.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DEV = ROOT / "tests" / "corpus" / "dev"


def sample(every: int, offset: int) -> list[Path]:
    return sorted(DEV.glob("*/*.txt"))[offset::every]


def first_reason(log: str) -> str:
    """The first line that says why: a road the scene failed on, else the error."""
    lines = log.splitlines()
    for marker in ("the scene failed:", "error:"):
        for line in lines:
            if marker in line:
                return line.split(marker, 1)[1].strip()[:300]
    return (lines[-1] if lines else "no output")[:300]


def prove(prompt: Path, code: Path, out_dir: Path, timeout: float) -> tuple[int, str, float]:
    env = dict(os.environ, PYTHONPATH=str(code))
    out = out_dir / f"{prompt.parent.name}_{prompt.stem}.xosc"
    start = time.perf_counter()
    try:
        done = subprocess.run([sys.executable, "-m", "ttsgc", "compile", str(prompt), "-o", str(out)],
                              capture_output=True, text=True, env=env, cwd=out_dir, timeout=timeout)
    except subprocess.TimeoutExpired:
        return -1, f"timed out after {timeout:.0f} s", time.perf_counter() - start
    return done.returncode, first_reason(done.stderr + done.stdout), time.perf_counter() - start


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--every", type=int, default=9)
    parser.add_argument("--offset", type=int, default=0)
    parser.add_argument("--code", type=Path, default=ROOT, help="the checkout whose ttsgc compiles (default: this)")
    parser.add_argument("--prompts", type=Path, help="a file naming dev prompts, one a line (instead of a sample)")
    parser.add_argument("--timeout", type=float, default=300.0)
    args = parser.parse_args()
    if not os.environ.get("TTSGC_ESMINI"):
        print("note: TTSGC_ESMINI is not set; esmini may not play", file=sys.stderr)
    prompts = sample(args.every, args.offset)
    if args.prompts is not None:
        prompts = [DEV / Path(line.strip()).relative_to(Path(line.strip()).parents[1])
                   for line in args.prompts.read_text().splitlines() if line.strip()]
        outside = [p for p in prompts if not p.is_file()]
        if outside:
            parser.error(f"{args.prompts}: no dev prompt {outside[0]}")
    passed, times = 0, []
    with tempfile.TemporaryDirectory() as tmp:
        for prompt in prompts:
            code, reason, took = prove(prompt, args.code.resolve(), Path(tmp), args.timeout)
            times.append(took)
            name = f"{prompt.parent.name}/{prompt.stem}"
            if code == 0:
                passed += 1
                print(f"ok    {name}", flush=True)
            else:
                print(f"FAIL  {name} (exit {code}): {reason}", flush=True)
    print(f"{passed}/{len(prompts)} proven ({100.0 * passed / max(len(prompts), 1):.1f}%), "
          f"median {statistics.median(times):.1f} s a prompt")
    return 0


if __name__ == "__main__":
    sys.exit(main())
