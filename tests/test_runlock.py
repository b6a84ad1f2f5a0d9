"""One writer per run (yade_scripts/runs/runlock.py) and the attempts record
that survives a killed launcher (yade_scripts/runs/runstate.py): real processes
and real POSIX locks, no YADE."""
import json
import os
import subprocess
import sys
import textwrap
import threading
import time

import pytest

from yade_scripts.runs import runlock
from yade_scripts.launch.pool import Job, hold_runs
from yade_scripts.runs.runlock import RunBusy, RunLock, holder, inherited, lock_path
from yade_scripts.runs.runstate import (KILLED, end_attempt, judge, mark_requeued, read_attempts, reclaim_killed,
                                        start_attempt, state_of, task_requeues)

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def child(code, *args, env=None):
    """Run ``code`` in another Python process (the repository on its path);
    returns (exit code, stdout)."""
    pre = f"import sys, os, json; sys.path.insert(0, {ROOT!r})\nfrom yade_scripts.runs import runlock\n"
    r = subprocess.run([sys.executable, "-c", pre + textwrap.dedent(code), *map(str, args)], capture_output=True,
                       text=True, env=env, timeout=60)
    return r.returncode, r.stdout.strip() + r.stderr.strip()


TRY = """
try:
    runlock.RunLock(sys.argv[1], "second").acquire()
    print("GOT")
except runlock.RunBusy as exc:
    print("BUSY", exc)
"""

#: another process that holds a lock (as a study: its record says so) until ``then`` returns
HOLD = ("import sys, time; sys.path.insert(0, {root!r}); from yade_scripts.runs import runlock; "
        "l = runlock.RunLock(sys.argv[1], 'study').acquire(); print('HELD', flush=True); {then}")


def test_a_second_process_is_refused_in_one_line_naming_the_holder(tmp_path):
    path = tmp_path / "run.lock"
    with RunLock(str(path), "task") as lock:
        assert lock.took_over is None
        code, out = child(TRY, path)
        assert code == 0 and out.startswith("BUSY") and "\n" not in out
        assert f"pid {os.getpid()} on {os.uname().nodename}" in out and "(a task)" in out
        assert "nothing was touched" in out
        # what another process sees, without taking it
        code, out = child("print(json.dumps(runlock.holder(sys.argv[1])))", path)
        assert json.loads(out)["pid"] == os.getpid()
    # released: the next one gets it, and no stale record is left
    assert path.read_text() == ""
    assert child(TRY, path) == (0, "GOT")


def test_a_waiting_taker_gets_the_lock_once_its_holder_lets_go_and_says_so_once(tmp_path):
    path = tmp_path / "run.lock"
    p = subprocess.Popen([sys.executable, "-c", HOLD.format(root=ROOT, then="sys.stdin.readline()"), str(path)],
                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    said, released = [], []
    try:
        assert p.stdout.readline().strip() == "HELD"
        t = threading.Timer(0.5, lambda: (released.append(time.monotonic()), p.communicate("\n")))
        t.start()
        try:
            lock = RunLock(str(path), "archive").acquire_waiting(0.02, said.append)
        finally:
            t.join()
        got = time.monotonic()
        try:
            assert lock.acquired and runlock.holds(str(path))        # held by this process
            assert holder(str(path))["pid"] == os.getpid() == json.loads(path.read_text())["pid"]
        finally:
            lock.release()
    finally:
        if p.poll() is None:
            p.communicate("\n")
    assert got >= released[0]
    assert len(said) == 1 and said[0]["pid"] == p.pid and said[0]["what"] == "study"   # ~25 tries, said once
    # a free lock is taken at once, with nothing said
    with RunLock(str(path), "archive").acquire_waiting(0.02, said.append):
        pass
    assert len(said) == 1


def test_a_dead_holder_s_lock_is_free_and_its_record_is_taken_over(tmp_path):
    path = tmp_path / "run.lock"
    code, _ = child("runlock.RunLock(sys.argv[1], 'dies').acquire(); os._exit(9)", path)
    assert code == 9
    assert json.loads(path.read_text())["what"] == "dies"          # its record is left...
    assert holder(str(path)) is None                               # ... but nobody holds the lock
    with RunLock(str(path), "next") as lock:
        assert lock.took_over["what"] == "dies" and lock.took_over["pid"] != os.getpid()


def test_reentrant_within_a_process_and_held_until_the_last_release(tmp_path):
    path = str(tmp_path / "run.lock")
    a = RunLock(path).acquire()
    b = RunLock(path).acquire()          # the same process: counted, not a second descriptor
    b.release()
    assert child(TRY, path)[1].startswith("BUSY")
    a.release()
    assert child(TRY, path) == (0, "GOT")


def test_the_child_of_the_holder_inherits_it_and_nobody_else_does(tmp_path):
    path = str(tmp_path / "run.lock")
    ask = "print(runlock.inherited(sys.argv[1]))"
    with RunLock(path) as lock:
        env = {**os.environ, **lock.environment()}
        assert child(ask, path, env=env) == (0, "True")
        # the variable of another holder (not our parent), or for another run
        fake = {**os.environ, runlock.INHERITED: json.dumps({"path": os.path.realpath(path), "pid": 1})}
        assert child(ask, path, env=fake) == (0, "False")
        assert child(ask, str(tmp_path / "other.lock"), env=env) == (0, "False")
    assert not inherited(path)
    # the parent said so but no longer holds it: False
    code, out = child("l = runlock.RunLock(sys.argv[1]).acquire(); env = dict(os.environ, **l.environment()); "
                      "l.release(); import subprocess; print(subprocess.run([sys.executable, '-c', "
                      "f'import sys; sys.path.insert(0, {sys.path[0]!r}); from yade_scripts.runs import runlock; "
                      "print(runlock.inherited(sys.argv[1]))', sys.argv[1]], env=env, capture_output=True, "
                      "text=True).stdout.strip())", path)
    assert (code, out) == (0, "False")


def test_a_launcher_takes_every_run_or_none(tmp_path):
    jobs = [Job(str(tmp_path), k, f"seed{k}", str(tmp_path / f"seed{k}.h5")) for k in (1, 2, 3)]
    # a holder that stays: a process that waits on stdin
    p = subprocess.Popen([sys.executable, "-c", f"import sys; sys.path.insert(0, {ROOT!r}); from yade_scripts.runs "
                          "import runlock; l = runlock.RunLock(sys.argv[1], 'task').acquire(); print('HELD', "
                          "flush=True); sys.stdin.read()", lock_path(jobs[1].dump)],
                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        assert p.stdout.readline().strip() == "HELD"
        with pytest.raises(RunBusy, match=r"seed2 is being written by pid \d+ .*\(a task\)"):
            hold_runs(jobs)
        assert not any(runlock.holds(lock_path(j.dump)) for j in jobs)     # the first one was given back
    finally:
        p.communicate("")
    locks = hold_runs(jobs)
    assert all(runlock.holds(lock_path(j.dump)) for j in jobs)
    for lock in locks.values():
        lock.release()


def test_a_launcher_that_cannot_make_a_lock_file_gives_back_those_it_took(tmp_path):
    from yade_scripts.launch.pool import ConfigError

    jobs = [Job(str(tmp_path), 1, "seed1", str(tmp_path / "seed1.h5")),
            Job(str(tmp_path), 2, "seed2", str(tmp_path / "gone" / "seed2.h5"))]     # its folder does not exist
    with pytest.raises(ConfigError, match=r"gone/seed2\.lock: cannot take the run's lock \(No such file"):
        hold_runs(jobs)
    assert not runlock.holds(lock_path(jobs[0].dump)) and holder(lock_path(jobs[0].dump)) is None
    assert not (tmp_path / "gone").exists()


def test_state_of_a_run_another_process_holds_is_running(tmp_path):
    dump = str(tmp_path / "run.h5")
    assert state_of(dump).state == "not started"
    p = subprocess.Popen([sys.executable, "-c", f"import sys; sys.path.insert(0, {ROOT!r}); from yade_scripts.runs "
                          "import runlock; l = runlock.RunLock(sys.argv[1], 'scene').acquire(); print('HELD', "
                          "flush=True); sys.stdin.read()", lock_path(dump)],
                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        assert p.stdout.readline().strip() == "HELD"
        st = state_of(dump)
        assert st.state == "running" and f"pid {p.pid}" in st.detail and "(a scene)" in st.detail
    finally:
        p.communicate("")
    assert state_of(dump).state == "not started"
    with RunLock(lock_path(dump)):          # our own lock is not "another writer"
        assert state_of(dump).state == "not started"


def test_every_attempt_has_its_own_number_and_a_killed_one_is_recorded(tmp_path):
    dump = str(tmp_path / "run.h5")
    n1 = start_attempt(dump, threads=1)
    end_attempt(dump, n1, exit=75, action="resume", reason="stopped on request")
    n2 = start_attempt(dump, threads=2)          # then its launcher dies with it: no end
    assert (n1, n2) == (1, 2)
    assert reclaim_killed(dump) == [2]
    n3 = start_attempt(dump, threads=2)
    end_attempt(dump, n3, exit=0, action="done", reason="complete")
    rows = read_attempts(dump)
    assert [(r["attempt"], r["action"]) for r in rows] == [(1, "resume"), (2, "killed"), (3, "done")]
    assert rows[1]["reason"] == KILLED and rows[1]["end"] is None
    assert reclaim_killed(dump) == []


def test_only_the_task_s_own_requeues_count(tmp_path):
    dump = str(tmp_path / "run.h5")
    for k in range(3):
        n = start_attempt(dump, slurm_job="7_1", job_start=k + 1)
        if k == 1:
            continue              # killed with its node; SLURM requeued it, not the task
        end_attempt(dump, n, exit=75, action="resume", reason="stopped on request")
        if k == 0:
            mark_requeued(dump, "requeue 1 of at most 10")
    reclaim_killed(dump)
    assert task_requeues(dump) == 1


def test_a_crash_before_the_first_checkpoint_starts_afresh_up_to_the_limit(tmp_path):
    dump = str(tmp_path / "run.h5")
    v = judge(-9, dump, resumes=0, max_resumes=2)
    assert v.action == "resume" and "before its first checkpoint: it starts afresh (retry 1 of at most 2)" in v.reason
    assert judge(-9, dump, resumes=2, max_resumes=2).action == "failed"
    assert judge(4, dump).action == "failed"               # another writer: never retried


def test_a_second_study_on_one_folder_refuses_before_touching_it(tmp_path, capsys):
    """The study holds OUT/study.lock: a second study on the folder (here:
    another process holds the lock, as the first study would) exits 4 at
    once, naming it, before it generates or sets aside anything."""
    from yade_scripts.campaign.study import main as study_main

    out = tmp_path / "study"
    out.mkdir()
    p = subprocess.Popen([sys.executable, "-c", HOLD.format(root=ROOT, then="sys.stdin.read()"),
                          str(out / "study.lock")], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        assert p.stdout.readline().strip() == "HELD"
        assert study_main(["--preset", "tiny", "--out", str(out)]) == 4
        err = capsys.readouterr().err.strip()
        assert err == (f"study: error: the study folder {out} is being written by "
                       f"{runlock.describe(holder(str(out / 'study.lock')))}; nothing was touched (stop that one "
                       f"first, or wait for it)")
        assert os.listdir(out) == ["study.lock"]
    finally:
        p.communicate("")



def test_collect_refuses_while_another_process_writes_the_manifest_and_report(tmp_path, capsys):
    """The manifest and report have one writer (OUT/report.lock): a
    ``--collect`` while a study's end (here: another process holding the
    lock) writes them exits 4 in one line naming it, and writes nothing;
    once it is free, the same collect writes both and leaves the lock
    free."""
    from yade_scripts.campaign.generate import generate
    from yade_scripts.campaign.study import REPORT_LOCK
    from yade_scripts.campaign.study import main as study_main

    out = tmp_path / "t1"
    generate(str(out), "tiny", "spheres", seeds=[1])
    before = sorted(os.listdir(out))
    p = subprocess.Popen([sys.executable, "-c", HOLD.format(root=ROOT, then="sys.stdin.read()"),
                          str(out / REPORT_LOCK)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        assert p.stdout.readline().strip() == "HELD"
        assert study_main(["--collect", str(out), "--no-figures"]) == 4
        err = capsys.readouterr().err.strip()
        assert err == (f"study: error: the report of {out} (manifest.json, report/) is being written by "
                       f"{runlock.describe(holder(str(out / REPORT_LOCK)))}; nothing was touched (stop that one "
                       f"first, or wait for it)")
        assert sorted(os.listdir(out)) == sorted(before + [REPORT_LOCK])
    finally:
        p.communicate("")
    assert study_main(["--collect", str(out), "--no-figures"]) == 0
    assert (out / "manifest.json").exists() and (out / "report" / "report.md").exists()
    assert (out / REPORT_LOCK).read_text() == "" and holder(str(out / REPORT_LOCK)) is None


def test_the_study_s_end_waits_for_the_report_lock(tmp_path, monkeypatch, capsys):
    """The study's own end does not give up its report to a ``--collect``:
    it waits, saying so once, until the other writer lets go, then
    analyses, writes and reads its manifest back (the study's runs and the
    analyses stubbed; the lock and the waiting are the real ones), while
    ``analyse_and_report`` alone, not waiting, is refused."""
    import argparse

    from yade_scripts.campaign import study

    out = tmp_path / "study"
    out.mkdir()
    wrote = []

    def analyses(out_, runs, *rest):
        wrote.append(time.monotonic())
        (out / "manifest.json").write_text(json.dumps({s: [{"status": "ok"}] for s in runs}))
        return []

    monkeypatch.setattr(study, "_analyse_and_report", analyses)
    monkeypatch.setattr(study, "run_samples", lambda *a, **k: {"polyhedra": 0, "spheres": 0})
    monkeypatch.setattr(study, "REPORT_WAIT_SECONDS", 0.05)
    args = argparse.Namespace(ensemble=1, out=str(out), preset="tiny", library=None, counts=None, no_figures=True,
                              set_aside=False, archive=None)
    p = subprocess.Popen([sys.executable, "-c", HOLD.format(root=ROOT, then="sys.stdin.readline()"),
                          str(out / study.REPORT_LOCK)], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    released = []
    try:
        assert p.stdout.readline().strip() == "HELD"
        with pytest.raises(RunBusy, match=r"\(a study\)"):       # without waiting: refused, nothing written
            study.analyse_and_report(str(out), {})
        assert wrote == []
        t = threading.Timer(0.5, lambda: (released.append(time.monotonic()), p.communicate("\n")))
        t.start()
        try:
            assert study._study(args, {}) == 0
        finally:
            t.join()
    finally:
        if p.poll() is None:
            p.communicate("\n")
    assert len(wrote) == 1 and wrote[0] >= released[0]
    said = [line for line in capsys.readouterr().out.splitlines() if "waiting for" in line]
    assert len(said) == 1 and f"to finish writing the manifest and report of {out}" in said[0]
    assert holder(str(out / study.REPORT_LOCK)) is None


def test_the_report_lock_is_let_go_when_the_report_fails(tmp_path, monkeypatch):
    """An analysis or report that raises leaves the lock free (a collect
    after it is not refused), and a collect that holds it is named so."""
    from yade_scripts.campaign import study

    def fails(*a):
        code, said = child(TRY, os.path.join(a[0], study.REPORT_LOCK))
        seen.append(said)
        raise OSError("disk full")

    seen = []
    monkeypatch.setattr(study, "_analyse_and_report", fails)
    with pytest.raises(OSError, match="disk full"):
        study.analyse_and_report(str(tmp_path), {})
    assert seen[0].startswith("BUSY") and "(a collect)" in seen[0]
    assert holder(str(tmp_path / study.REPORT_LOCK)) is None
    assert child(TRY, tmp_path / study.REPORT_LOCK) == (0, "GOT")
