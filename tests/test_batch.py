"""Batches: the same scenes and summary whatever the number of workers, resumed after a kill, and on Ray."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import EXAMPLES, ROOT
from ttsgc.batch import BatchError, plan_jobs, read_inputs, run_batch
from ttsgc.cli import main

SCENES = ["blocking.tsg", "cut_off.txt", "crushing.tsg", "stop_sign_right_turn.tsg"]


def _prompts(folder: Path) -> Path:
    folder.mkdir()
    for name in SCENES:
        shutil.copy(EXAMPLES / name, folder / name)
    (folder / "broken.tsg").write_text('scenario "broken"\nstage s {\n    ego car fly_away\n}\n')
    return folder


def _without_timings(summary: dict) -> dict:
    rows = [{k: v for k, v in row.items() if not k.startswith("seconds")} for row in summary["rows"]]
    return {**{k: v for k, v in summary.items() if not k.startswith("seconds")}, "rows": rows}


def _scene_files(out: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(out.iterdir())
            if p.suffix in (".xosc", ".tsg", ".xodr") or p.name.endswith(".result.json")}


def _result_without_timings(data: bytes) -> dict:
    result = json.loads(data)
    result["row"] = {k: v for k, v in result["row"].items() if not k.startswith("seconds")}
    return result


def _same_outputs(a: Path, b: Path) -> None:
    files_a, files_b = _scene_files(a), _scene_files(b)
    assert sorted(files_a) == sorted(files_b)
    for name in files_a:
        if name.endswith(".result.json"):
            assert _result_without_timings(files_a[name]) == _result_without_timings(files_b[name]), name
        else:
            assert files_a[name] == files_b[name], name
    summary_a = json.loads((a / "summary.json").read_text())
    summary_b = json.loads((b / "summary.json").read_text())
    assert _without_timings(summary_a) == _without_timings(summary_b)


@pytest.fixture(scope="module")
def one_worker(tmp_path_factory):
    base = tmp_path_factory.mktemp("batch")
    prompts = _prompts(base / "prompts")
    out = base / "one"
    assert main(["batch", str(prompts), "-o", str(out), "--workers", "1"]) == 0
    return prompts, out


def test_a_batch_writes_every_scene_and_a_summary(one_worker):
    prompts, out = one_worker
    summary = json.loads((out / "summary.json").read_text())
    assert [r["id"] for r in summary["rows"]] == ["blocking", "broken", "crushing", "cut_off", "stop_sign_right_turn"]
    verdicts = {r["id"]: r["verdict"] for r in summary["rows"]}
    assert verdicts["broken"] == "error" and summary["rows"][1]["failed_at"] == "parse"
    assert "fly_away" in summary["rows"][1]["reason"]
    for row in summary["rows"]:
        if row["verdict"] == "ok":
            assert (out / row["xosc"]).is_file() and row["map"] and row["seconds_total"] > 0
        else:
            assert not (out / f"{row['id']}.xosc").exists()  # a scene that failed leaves no scene file
    assert summary["ok"] == sum(v == "ok" for v in verdicts.values()) >= 3
    csv_lines = (out / "summary.csv").read_text().splitlines()
    assert csv_lines[0].startswith("id,source,seed,verdict") and len(csv_lines) == 6
    assert (out / "cut_off.tsg").read_text().startswith("# Lowered (offline)")  # English is lowered first


def test_two_workers_give_the_same_scenes_and_summary(one_worker, tmp_path):
    prompts, out = one_worker
    assert main(["batch", str(prompts), "-o", str(tmp_path / "two"), "--workers", "2"]) == 0
    _same_outputs(out, tmp_path / "two")


def test_a_finished_batch_is_skipped(one_worker, tmp_path, capsys):
    prompts, out = one_worker
    copy = tmp_path / "again"
    shutil.copytree(out, copy)
    before = {p.name: p.stat().st_mtime_ns for p in copy.iterdir() if p.suffix == ".xosc"}
    assert main(["batch", str(prompts), "-o", str(copy), "--workers", "1"]) == 0
    assert "5 already finished" in capsys.readouterr().out
    assert before == {p.name: p.stat().st_mtime_ns for p in copy.iterdir() if p.suffix == ".xosc"}


@pytest.mark.parametrize("how, workers", [(signal.SIGKILL, "1"), (signal.SIGINT, "2")], ids=["kill", "ctrl-c"])
def test_an_interrupted_batch_resumes_to_the_same_summary(one_worker, tmp_path, how, workers):
    """SIGKILL: no chance to tidy up, the harshest interruption. SIGINT to the whole process group, as Ctrl-C
    sends it: the batch stops at once with exit 130 and no traceback."""
    prompts, out = one_worker
    resumed = tmp_path / "resumed"
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    command = [sys.executable, "-m", "ttsgc", "batch", str(prompts), "-o", str(resumed), "--workers", workers]
    process = subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                               start_new_session=True, preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.monotonic() + 120
    try:
        while time.monotonic() < deadline and process.poll() is None:
            if list(resumed.glob("*.result.json")):  # interrupted after the first scene: with two workers
                break  # and scenes handed out longest first, waiting for two could see the last ones end too
            time.sleep(0.05)
    finally:
        if process.poll() is None:
            os.killpg(process.pid, how)
        _, errors = process.communicate(timeout=60)
    if how == signal.SIGINT:
        assert process.returncode == 130 and "interrupted" in errors and "Traceback" not in errors
    finished = len(list(resumed.glob("*.result.json")))
    assert 1 <= finished < 5, "the batch was not caught part-way"
    assert not (resumed / "summary.json").exists()
    assert main(["batch", str(prompts), "-o", str(resumed), "--workers", "1"]) == 0
    assert not list(resumed.glob(".*.tmp"))
    _same_outputs(out, resumed)


def test_a_pool_thread_left_running_does_not_hold_the_exit():
    """The last guard after Ctrl-C: should an interrupted pool's thread not end in time, the process still
    exits at once with its code and what it printed, where the interpreter would wait for the thread forever."""
    program = ("import threading, sys\n"
               "from ttsgc import runner\n"
               "from ttsgc.cli import exit_process\n"
               "stuck = threading.Thread(target=threading.Event().wait)\n"
               "stuck.start()\n"
               "runner._LEFT_RUNNING.append(stuck)\n"
               "print('ttsgc: interrupted', file=sys.stderr)\n"
               "exit_process(130)\n")
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    done = subprocess.run([sys.executable, "-c", program], env=env, capture_output=True, text=True, timeout=60)
    assert (done.returncode, done.stderr) == (130, "ttsgc: interrupted\n")


def test_json_lines_inputs_and_their_errors(tmp_path):
    good = tmp_path / "prompts.jsonl"
    scene = (EXAMPLES / "blocking.tsg").read_text()
    good.write_text(json.dumps({"id": "a", "prompt": "A car cuts in front of the ego."}) + "\n\n"
                    + json.dumps({"tsg": scene}) + "\n")
    inputs = read_inputs(good)
    assert [(i[0], i[1], i[2]) for i in inputs] == [("a", "prompts.jsonl:1", "text"),
                                                    ("line-00003", "prompts.jsonl:3", "tsg")]
    jobs = plan_jobs(good, tmp_path / "out", variants=2)
    assert [(j.id, j.seed) for j in jobs] == [("a-1", 0), ("a-2", 1), ("line-00003-1", 0), ("line-00003-2", 1)]
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"prompt": "x"}\n{"prompt": "a", "tsg": "b"}\n')
    with pytest.raises(BatchError, match=r"bad.jsonl:2: expected an object"):
        read_inputs(bad)
    bad.write_text("{not json\n")
    with pytest.raises(BatchError, match=r"bad.jsonl:1: not JSON"):
        read_inputs(bad)
    assert main(["batch", str(tmp_path / "missing"), "-o", str(tmp_path / "o")]) == 2


def test_a_batch_never_writes_over_its_inputs(tmp_path, capsys):
    shutil.copy(EXAMPLES / "cut_off.txt", tmp_path / "cut_off.txt")
    shutil.copy(EXAMPLES / "cut_off.tsg", tmp_path / "cut_off.tsg")
    before = (tmp_path / "cut_off.tsg").read_bytes()
    assert main(["batch", str(tmp_path), "-o", str(tmp_path)]) == 2
    assert "is the prompts folder" in capsys.readouterr().err
    assert (tmp_path / "cut_off.tsg").read_bytes() == before and not list(tmp_path.glob("*.xosc"))
    (tmp_path / "file").write_text("")
    assert main(["batch", str(tmp_path), "-o", str(tmp_path / "file")]) == 2
    assert "must be a folder" in capsys.readouterr().err


def test_folder_inputs_of_one_stem_keep_apart(tmp_path):
    for suffix in (".txt", ".tsg"):
        shutil.copy(EXAMPLES / f"blocking{suffix}", tmp_path / f"blocking{suffix}")
    assert [i[0] for i in read_inputs(tmp_path)] == ["blocking-tsg", "blocking-txt"]


@pytest.mark.slow
def test_a_local_ray_instance_gives_the_same_verdicts_and_bytes(one_worker, tmp_path):
    pytest.importorskip("ray")
    prompts, out = one_worker
    jobs = plan_jobs(prompts, tmp_path / "ray")
    result = run_batch(jobs, tmp_path / "ray", workers=2, ray_address="local")
    assert result.made == 5
    _same_outputs(out, tmp_path / "ray")


def test_eval_runs_on_the_runner_with_the_same_runs_on_any_number_of_workers(tmp_path):
    reports = []
    for workers in ("1", "2"):
        report = tmp_path / f"eval-{workers}.json"
        assert main(["eval", str(EXAMPLES), "--seeds", "1", "--no-simulate", "--workers", workers,
                     "--report", str(report)]) == 0
        data = json.loads(report.read_text())
        for run in data["runs"]:
            run.pop("seconds")
        reports.append(data)
    assert reports[0] == reports[1]
    assert [r["case"] for r in reports[0]["runs"]] == sorted(r["case"] for r in reports[0]["runs"])


def test_scenes_go_out_longest_first_by_their_earlier_durations(one_worker, tmp_path):
    from ttsgc.batch import job_key, load_durations, longest_first

    prompts, _ = one_worker
    jobs = plan_jobs(prompts, tmp_path / "out")
    durations = load_durations()
    finished = [job for job in jobs if job.id != "broken"]  # an error is a finished scene too
    assert all(job_key(job) in durations for job in jobs)  # the one-worker batch recorded each of them
    timed = {job_key(job): float(n) for n, job in enumerate(finished, 1)}  # the last input took longest
    fresh = plan_jobs(prompts, tmp_path / "out", variants=2)[0]  # seed 0: other work, never timed
    order = longest_first([*finished, fresh], timed)
    assert order == [fresh, *reversed(finished)]
    assert job_key(jobs[0]) == job_key(plan_jobs(prompts, tmp_path / "elsewhere")[0])  # the folder is not the work
    assert longest_first(jobs, {job_key(job): 0.5 for job in jobs}) == jobs  # ties keep the input order


def test_workers_are_forked_only_while_no_other_thread_could_hold_a_lock(monkeypatch):
    """The threads of this process are set by the test (a test server's thread may outlive its test)."""
    import threading

    from ttsgc.runner import FORK_SAFE_THREAD, can_fork

    this = threading.current_thread()
    for name, forkable in (("busy", False), (f"{FORK_SAFE_THREAD}-watcher", True)):
        other = threading.Thread(name=name, daemon=True)  # never started: only its name counts
        monkeypatch.setattr(threading, "enumerate", lambda: [this])
        assert can_fork()
        monkeypatch.setattr(threading, "enumerate", lambda other=other: [this, other])
        assert can_fork() is forkable
