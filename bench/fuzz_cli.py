"""Hostile input against the command line: every case must end in a named error with a documented exit code
(never exit 1, a traceback or a hang), leave its inputs untouched and write nothing when it fails.

    python bench/fuzz_cli.py                 # the fixed hostile cases (about a minute)
    python bench/fuzz_cli.py --mutations 300 # also mutated .tsg scenes and English prompts, read in process

Prints one line a case (BAD when something is wrong) and the count of bad cases; exits 0 either way (it is a
measurement, like the other scripts here; tests/test_bad_input.py holds the cases that must never regress).
"""

from __future__ import annotations

import argparse
import contextlib
import hashlib
import io
import os
import random
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

LAUGHS = ('<?xml version="1.0"?><!DOCTYPE l [<!ENTITY a "aaaaaaaaaa">'
          + "".join(f'<!ENTITY {chr(98 + i)} "' + f"&{chr(97 + i)};" * 10 + '">' for i in range(8)) + "]><R>&i;</R>")
XXE = '<?xml version="1.0"?><!DOCTYPE r [<!ENTITY x SYSTEM "file:///etc/passwd">]><R><header/>&x;</R>'


def cases(folder: Path) -> list[tuple[str, list[str]]]:
    """(name, argv after `ttsgc`) for each hostile input, written into folder."""
    out = []

    def prompt(name: str, data: str | bytes, suffix: str = ".txt", command: str = "compile", extra=()):
        path = folder / (name + suffix)
        path.write_bytes(data if isinstance(data, bytes) else data.encode())
        argv = [command, str(path)] + (["-o", str(folder / f"{name}.out.xosc")] if command == "compile" else [])
        out.append((name, argv + list(extra)))

    rnd = random.Random(0)
    prompt("empty", "")
    prompt("binary", bytes(rnd.randrange(256) for _ in range(4000)))
    prompt("nul", "a car\x00 turns left")
    prompt("utf16", "a car turns left at the junction".encode("utf-16"))
    prompt("book", "a car goes straight. " * 200_000)
    prompt("one_long_word", "x" * 500_000)
    prompt("huge_numbers", "the ego drives at 99999999999999999999 km/h behind 1000 cars on a 1000000-lane road")
    prompt("emoji_rtl", "\u202e🚗 turns ⬅️ while 🚶 crosses\u202c")
    prompt("tsg_unclosed", 'scenario "x"\nstage main {\n ego car go_straight\n car c1 at front\n', ".tsg")
    prompt("tsg_nan", 'scenario "x"\nstage main {\n ego car go_straight speed nan km/h\n}\n', ".tsg")
    prompt("tsg_deep", 'scenario "x"\n' + "stage s {\n" * 5000 + "}" * 5000, ".tsg")
    prompt("tsg_many", 'scenario "x"\nstage main {\n ego car go_straight\n'
           + "".join(f" car c{i} at front go_straight\n" for i in range(3000)) + "}\n", ".tsg")
    good_map = (ROOT / "maps" / "fourway_1lane_stop.xodr").read_text()
    plain = folder / "plain.txt"
    plain.write_text("the ego car turns left at the junction")
    for name, data in (("map_empty", ""), ("map_truncated", good_map[: len(good_map) // 2]),
                       ("map_xxe", XXE.replace("R>", "OpenDRIVE>")), ("map_laughs", LAUGHS.replace("R>", "OpenDRIVE>")),
                       ("map_nan", good_map.replace('length="', 'length="nan', 1)),
                       ("map_huge", good_map.replace(' x="', ' x="1e300', 5))):
        path = folder / f"{name}.xodr"
        path.write_text(data)
        out.append((name, ["compile", str(plain), "-o", str(folder / f"{name}.out.xosc"), "--maps", str(path),
                           "--synthesize", "never"]))
    fifo = folder / "fifo.xodr"
    os.mkfifo(fifo)
    out.append(("map_fifo", ["compile", str(plain), "-o", str(folder / "fifo.out.xosc"), "--maps", str(fifo)]))
    (folder / "loop1.xodr").symlink_to("loop2.xodr")
    (folder / "loop2.xodr").symlink_to("loop1.xodr")
    out.append(("map_loop", ["compile", str(plain), "-o", str(folder / "loop.out.xosc"), "--maps",
                             str(folder / "loop1.xodr")]))
    out.append(("output_fifo", ["compile", str(plain), "-o", str(fifo), "--no-simulate"]))
    golden = (ROOT / "examples" / "golden" / "blocking.xosc").read_text()
    for name, data in (("xosc_empty", ""), ("xosc_truncated", golden[: len(golden) // 2]),
                       ("xosc_xxe", XXE.replace("R>", "OpenSCENARIO>")),
                       ("xosc_laughs", LAUGHS.replace("R>", "OpenSCENARIO>")),
                       ("xosc_map_fifo", re.sub(r'LogicFile filepath="[^"]+"', 'LogicFile filepath="fifo.xodr"', golden)),
                       ("xosc_map_loop", re.sub(r'LogicFile filepath="[^"]+"', 'LogicFile filepath="loop1.xodr"',
                                                golden))):
        for command, extra in (("validate", []), ("lint", ["--target", "esmini"]),
                               ("render", ["-o", str(folder / f"{name}.png")])):
            path = folder / f"{name}.xosc"
            path.write_text(data)
            out.append((f"{name}:{command}", [command, str(path)] + extra))
    return out


def run_case(name: str, argv: list[str], folder: Path) -> str | None:
    """What went wrong, or None."""
    inputs = {p: hashlib.sha256(p.read_bytes()).hexdigest() for p in folder.iterdir()
              if p.is_file() and not p.is_symlink()}
    env = dict(os.environ, PYTHONPATH=str(ROOT), TTSGC_CACHE_DIR=str(folder / "cache"))
    try:
        done = subprocess.run([sys.executable, "-m", "ttsgc", *argv], env=env, capture_output=True, timeout=120,
                              text=True, errors="replace")
    except subprocess.TimeoutExpired:
        return "hang (over 120 s)"
    problems = []
    if done.returncode in (1,) or done.returncode < 0:
        problems.append(f"exit {done.returncode}")
    if "Traceback" in done.stderr:
        problems.append("traceback")
    if any(p.exists() and hashlib.sha256(p.read_bytes()).hexdigest() != h for p, h in inputs.items()):
        problems.append("an input changed")
    if done.returncode != 0 and any(folder.glob(f"{name.split(':')[0]}.out.*")):
        problems.append("output written on failure")
    if list(folder.glob(".*.tmp")):
        problems.append("a temporary file left")
    last = (done.stderr.strip().splitlines() or [""])[-1][:120]
    print(f"{'BAD ' if problems else 'ok  '}{name:26} exit {done.returncode}  {' '.join(problems)} | {last}")
    return " ".join(problems) or None


def mutations(count: int, seed: int) -> int:
    """Mutated example scenes (check, then compile unproven) and mutated English (lowered, written, read back)."""
    from ttsgc.cli import main
    from ttsgc.errors import TtsgcError
    from ttsgc.language import parse
    from ttsgc.lowering import lower_prompt

    rnd = random.Random(seed)
    scenes = [p.read_text() for p in sorted((ROOT / "examples").glob("*.tsg"))]
    prompts = [p.read_text() for p in sorted((ROOT / "tests" / "corpus" / "dev").glob("*/*.txt"))]
    prompts += [p.read_text() for p in sorted((ROOT / "examples").glob("*.txt"))]
    words = sorted({w for s in scenes + prompts for w in s.split()}) + ["-1", "1e309", "nan", '"', "{", "}", "\x00",
                                                                       "9" * 40, "then", "it", "both", "\n"]

    def mutate(text: str) -> str:
        parts = re.split(r"(\s+)", text)
        for _ in range(rnd.randint(1, 6)):
            k, op = rnd.randrange(len(parts)), rnd.random()
            if op < .35:
                parts[k] = rnd.choice(words)
            elif op < .65:
                parts.insert(k, f" {rnd.choice(words)} ")
            elif op < .85:
                del parts[k]
            else:
                parts[k:k] = parts[rnd.randrange(len(parts)):][:5]
        return "".join(parts)

    bad = 0
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(count):
            path = Path(tmp) / f"m{i}.tsg"
            path.write_text(mutate(rnd.choice(scenes)))
            err = io.StringIO()
            with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
                code = main(["check", str(path)])
                if code == 0:
                    code = main(["compile", str(path), "-o", str(Path(tmp) / f"m{i}.xosc"), "--no-simulate"])
            if code == 1 or "Traceback" in err.getvalue():
                bad += 1
                print(f"BAD mutated scene {i}: exit {code}: {path.read_text()[:200]!r}")
    for i in range(count * 5):
        text = mutate(rnd.choice(prompts))
        try:
            lowered = lower_prompt(text, "offline", seed=rnd.randrange(5))
            again = parse(lowered.tsg(text))
            if again.model_dump(exclude={"comments"}) != lowered.scenario.model_dump(exclude={"comments"}):
                raise AssertionError("the written scene reads back differently")
        except TtsgcError:
            pass
        except Exception as exc:  # noqa: BLE001 - any other exception is what this looks for
            bad += 1
            print(f"BAD mutated prompt {i}: {type(exc).__name__}: {exc}: {text[:200]!r}")
    print(f"mutations: {count} scenes, {count * 5} prompts, {bad} bad")
    return bad


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mutations", type=int, default=0, help="mutated scenes (and five times as many prompts)")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        bad = sum(run_case(name, argv, folder) is not None for name, argv in cases(folder))
    print(f"hostile cases: {bad} bad, {time.perf_counter() - start:.0f} s")
    if args.mutations:
        mutations(args.mutations, args.seed)


if __name__ == "__main__":
    main()
