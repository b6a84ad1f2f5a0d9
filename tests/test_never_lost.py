"""No launcher loses a finished run: a dump that says complete is checked
whole before "nothing to do"; one held open by another process (HDF5's file
lock) is refused and left untouched; a truncated one, or a packed one that
lost a snapshot, is moved aside under a name that says why, never removed,
and its line runs again; the collect tells such a dump from an unfinished
run; the pool says when it clears an earlier attempt's leftovers; a SIGTERM
is named after what SLURM says sent it. No YADE: the runs are a stand-in or
never start."""
from __future__ import annotations

import glob
import os
import signal
import subprocess
import sys

import h5py
import pytest
from builders import lattice_snapshot, write_snapshot
from test_pool import fake, jobs_in  # noqa: F401  (the stand-in for YADE, a fixture)
from test_slurm import make, task

from postproc.schema import DumpWriter
from yade_scripts.runs import runstate
from yade_scripts.launch import task as task_mod
from yade_scripts.launch.pool import run_pool
from yade_scripts.runs.runstate import DumpUnreadable, clear_attempt, dump_condition, set_aside, state_of
from yade_scripts.campaign.study import main as study_main
from yade_scripts.launch.task import SIGTERM_WORDS, sigterm_cause

HOLD = ("import h5py, sys, time\n"
        "f = h5py.File(sys.argv[1], 'a')\n"
        "print('open', flush=True)\n"
        "time.sleep(120)\n")


def _run_task_keeping_signals(out):
    """``task.run_task(out, 1)`` in this process, its SIGTERM and SIGUSR1
    handlers put back after it (the task installs its own)."""
    handlers = {s: signal.getsignal(s) for s in (signal.SIGTERM, signal.SIGUSR1)}
    try:
        return task_mod.run_task(str(out), 1)
    finally:
        for s, h in handlers.items():
            signal.signal(s, h)


def finished_dump(path, n=3):
    """A complete, packed dump of ``n`` small snapshots; its bytes."""
    snap, _, _ = lattice_snapshot()
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with DumpWriter(str(path), "spheres", {"seed": 1}) as w:
        for k in range(n):
            write_snapshot(w, snap, step=10 * k, time=0.5 * k)
    with open(path, "rb") as fh:
        return fh.read()


def truncate(path):
    """Cut the file to half its length (a copy that stopped midway)."""
    data = open(path, "rb").read()
    with open(path, "wb") as fh:
        fh.write(data[: len(data) // 2])
    return data[: len(data) // 2]


def cut(path):
    """Take the middle snapshot out of a packed complete dump (its flag stays)."""
    with h5py.File(path, "a") as f:
        del f["snapshots/000001"]
    return open(path, "rb").read()


@pytest.fixture
def holder(monkeypatch):
    """Start a second process that holds a dump open in 'a' mode."""
    monkeypatch.delenv("HDF5_USE_FILE_LOCKING", raising=False)
    procs = []

    def hold(path):
        p = subprocess.Popen([sys.executable, "-c", HOLD, str(path)], stdout=subprocess.PIPE, text=True)
        procs.append(p)
        assert p.stdout.readline().strip() == "open"
        return p

    yield hold
    for p in procs:
        p.kill()
        p.wait()


def aside(path, why):
    return sorted(glob.glob(f"{path}.{why}-*"))


def test_the_condition_of_a_dump(tmp_path, holder):
    d = tmp_path / "run.h5"
    assert dump_condition(str(d)) == ("absent", "no dump")
    finished_dump(d)
    assert dump_condition(str(d)) == ("complete", "complete")
    p = holder(d)
    kind, why = dump_condition(str(d))
    assert kind == "unreadable" and "another process" in why
    p.kill(), p.wait()
    assert dump_condition(str(d))[0] == "complete"        # let go: it is fine
    cut(d)
    kind, why = dump_condition(str(d))
    assert kind == "does-not-verify" and "says 3 snapshots, holds 2" in why
    finished_dump(tmp_path / "t.h5")
    truncate(tmp_path / "t.h5")
    assert dump_condition(str(tmp_path / "t.h5"))[0] == "truncated"
    (tmp_path / "e.h5").write_bytes(b"")
    assert dump_condition(str(tmp_path / "e.h5"))[0] == "empty"


def test_clear_attempt_never_removes_a_finished_dump(tmp_path, holder):
    d = tmp_path / "run.h5"
    finished_dump(d)
    with pytest.raises(ValueError, match="is complete: not cleared"):
        clear_attempt(str(d))
    p = holder(d)
    data = d.read_bytes()           # as the holder left it on opening
    with pytest.raises(DumpUnreadable, match="cannot be opened now .*left untouched") as info:
        clear_attempt(str(d))
    assert "\n" not in str(info.value)
    p.kill(), p.wait()
    assert d.read_bytes() == data
    # truncated: moved aside with its parts' leftovers removed; a second one never over the first
    short = truncate(d)
    (tmp_path / "run.log.csv").write_text("x")
    said = clear_attempt(str(d))
    assert said[0].startswith("run.h5: truncated or damaged") and "moved aside to run.h5.truncated-" in said[0]
    assert said[1] == "removed the unfinished attempt (run.log.csv)"
    assert [open(f, "rb").read() for f in aside(d, "truncated")] == [short] and not d.exists()
    # a moved-aside file of the same name (same second) is never replaced: the new one is suffixed
    import datetime
    now = datetime.datetime.now(datetime.timezone.utc)
    blockers = [tmp_path / f"run.h5.cut-{(now + datetime.timedelta(seconds=k)).strftime('%Y%m%dT%H%M%SZ')}"
                for k in (0, 1, 2)]
    for b in blockers:
        b.write_bytes(b"earlier")
    d.write_bytes(b"other")
    new = set_aside(str(d), "cut")
    assert new.endswith("-2") and open(new, "rb").read() == b"other"
    assert all(b.read_bytes() == b"earlier" for b in blockers)


def test_the_pool_moves_a_damaged_dump_aside_refuses_a_locked_one_and_says_it_clears(tmp_path, fake, holder):
    js = jobs_in(tmp_path / "f", [("a", 0.1)])
    d = tmp_path / "f" / "a.h5"
    # leftovers of an earlier attempt, no checkpoint: cleared, said in one line
    (tmp_path / "f" / "a.log.csv").write_text("x")
    (tmp_path / "f" / "a.info.json").write_text("{}")
    msgs = []
    assert run_pool(js, 1, echo=msgs.append, yade=fake) == {"a": 0}
    assert sum("starting afresh: removed the unfinished attempt (a.log.csv, a.info.json)" in m for m in msgs) == 1
    # a truncated finished dump: moved aside, the line runs again
    os.remove(d)                    # the stand-in's own "complete" marker
    finished_dump(d)
    short = truncate(d)
    msgs = []
    assert run_pool(jobs_in(tmp_path / "f", [("a", 0.1)]), 1, echo=msgs.append, yade=fake) == {"a": 0}
    assert [open(f, "rb").read() for f in aside(d, "truncated")] == [short]
    assert sum("moved aside to a.h5.truncated-" in m for m in msgs) == 1
    # a dump another process holds open: refused, untouched, not run
    finished_dump(tmp_path / "g" / "b.h5")
    js = jobs_in(tmp_path / "g", [("b", 0.1)])
    holder(tmp_path / "g" / "b.h5")
    data = (tmp_path / "g" / "b.h5").read_bytes()
    msgs = []
    assert run_pool(js, 1, echo=msgs.append, yade=fake) == {"b": "unreadable dump"}
    assert (tmp_path / "g" / "b.h5").read_bytes() == data and not (tmp_path / "g" / "b.threads").exists()
    assert any("refused:" in m and "cannot be opened now" in m for m in msgs)


def test_a_task_refuses_a_locked_dump_and_leaves_it(tmp_path, holder):
    out = make(tmp_path, (1,))
    d = out / "spheres-seed1" / "spheres-seed1.h5"
    finished_dump(d)
    holder(d)
    data = d.read_bytes()
    r = task(out, 1, tmp_path)
    assert r.returncode == 4, r.stdout + r.stderr
    final = [x for x in r.stderr.splitlines() if x.startswith("task: FINAL")]
    assert len(final) == 1 and "cannot be opened now" in final[0] and "left untouched" in final[0]
    assert d.read_bytes() == data and not aside(d, "truncated") and not aside(d, "unreadable")


def test_a_task_checks_a_complete_dump_whole(tmp_path, monkeypatch, capsys):
    out = make(tmp_path, (1,))
    d = out / "spheres-seed1" / "spheres-seed1.h5"
    finished_dump(d)
    r = task(out, 1, tmp_path)
    assert r.returncode == 0 and "is complete and verifies, nothing to do" in r.stdout
    # a packed dump that lost a snapshot is not complete: moved aside, and the line runs again
    data = cut(d)
    ran = []

    def no_yade(jobs, cores, **kw):       # the run itself is another test's: here it never starts
        ran.append(os.path.exists(jobs[0].dump))
        jobs[0].verdict = None
        return {jobs[0].description: "stopped"}

    monkeypatch.setattr("yade_scripts.launch.task.run_pool", no_yade)
    code = _run_task_keeping_signals(out)
    said = capsys.readouterr().out
    assert code == runstate.EXIT_TERM and ran == [False]
    assert "nothing to do" not in said
    line = [x for x in said.splitlines() if "moved aside" in x]
    assert len(line) == 1 and "does not verify: says 3 snapshots, holds 2" in line[0] and "runs again" in line[0]
    assert [open(f, "rb").read() for f in aside(d, "does-not-verify")] == [data]


def test_the_collect_tells_a_truncated_dump_from_an_unfinished_run(tmp_path, capsys):
    out = make(tmp_path, (1, 2))
    d1 = out / "spheres-seed1" / "spheres-seed1.h5"
    finished_dump(d1)
    short = truncate(d1)
    d2 = out / "spheres-seed2" / "spheres-seed2.h5"
    os.makedirs(d2.parent)
    (out / "spheres-seed2" / "spheres-seed2.log.csv").write_text("x")     # killed before its first checkpoint
    assert state_of(str(d1)).state == "damaged" and "starts afresh" not in state_of(str(d1)).detail
    assert state_of(str(d2)).state == "unfinished"
    assert study_main(["--collect", str(out), "--no-figures"]) == 0
    err = capsys.readouterr().err
    one = [x for x in err.splitlines() if "spheres-seed1 (" in x]
    assert len(one) == 1 and "refused, not analysed" in one[0] and "truncated or damaged" in one[0]
    assert "starts afresh" not in one[0]
    assert "spheres-seed2 (unfinished, no checkpoint" in err
    assert f"resubmit the unfinished lines of arr: sbatch --array=2 {out}/slurm.sh" in err
    assert d1.read_bytes() == short                    # the collect moves nothing


@pytest.mark.parametrize("show, restarts, cause", [
    ("JobId=12 ArrayJobId=11 ArrayTaskId=1 JobState=COMPLETING Reason=None Restarts=2", 1, "requeue"),
    ("JobId=12 JobState=REQUEUED Reason=None Restarts=0", 0, "requeue"),
    ("JobId=12 JobState=PENDING Reason=BeginTime Restarts=0", 0, "requeue"),
    ("JobId=12 JobState=CANCELLED Reason=None Restarts=1", 1, "scancel"),
    ("JobId=12 JobState=RUNNING Reason=None Restarts=0", 0, "scancel"),      # scancel --batch --signal=TERM
    ("JobId=12 JobState=COMPLETING Reason=None Restarts=1", 1, "unknown"),
    ("", 0, "unknown"), (None, 3, "unknown")])
def test_a_sigterm_is_named_after_what_slurm_says(show, restarts, cause):
    assert sigterm_cause(show, restarts) == cause
    assert ("scancel" in SIGTERM_WORDS["unknown"] and "requeue" in SIGTERM_WORDS["unknown"]
            and "scancel" not in SIGTERM_WORDS["requeue"])


def test_the_scene_never_removes_a_dump_it_cannot_open_or_check(tmp_path, holder):
    """The scene's own start (yade_scripts.runs.attempt): a locked dump is refused
    as a busy run (exit 4 in triaxial.py), untouched; a cut one is moved
    aside and the attempt starts afresh."""
    from test_loading import new_attempt

    from yade_scripts.runs.runlock import RunBusy

    d = tmp_path / "run.h5"
    finished_dump(d)
    p = holder(d)
    data = d.read_bytes()
    said = []
    with pytest.raises(RunBusy, match="cannot be opened now"):
        new_attempt(str(d), {"seed": 1}, True, said)
    assert d.read_bytes() == data
    p.kill(), p.wait()
    assert new_attempt(str(d), {"seed": 1}, True, said).complete
    kept = cut(d)
    said = []
    run = new_attempt(str(d), {"seed": 1}, True, said)
    assert not run.complete and not d.exists()
    assert [open(f, "rb").read() for f in aside(d, "does-not-verify")] == [kept]
    assert len(said) == 1 and said[0].startswith("starting afresh: run.h5: does not verify: says 3 snapshots")


@pytest.mark.parametrize("show, final", [
    ("JobId=5 JobState=COMPLETING Restarts=1", "requeued by SLURM (SIGTERM of a requeue"),
    ("JobId=5 JobState=CANCELLED Restarts=0", "stopped on request (SIGTERM, scancel)"),
    (None, "stopped by SLURM (SIGTERM: scancel or requeue")])
def test_the_task_s_final_line_after_slurm_s_sigterm(tmp_path, monkeypatch, capsys, show, final):
    """A task inside SLURM stopped by SIGTERM: its FINAL line and comment say
    what SLURM recorded, never a scancel it cannot know of."""
    from yade_scripts.runs.runstate import Verdict

    out = make(tmp_path, (1,))
    comments = []

    def stopped_run(jobs, cores, **kw):     # the run asked to stop by SLURM's SIGTERM, resumable
        os.kill(os.getpid(), signal.SIGTERM)
        assert kw["stopping"]()
        jobs[0].verdict = Verdict("resume", "stopped on request")
        return {jobs[0].description: "stopped"}

    monkeypatch.setattr("yade_scripts.launch.task.run_pool", stopped_run)
    monkeypatch.setattr(task_mod, "show_job", lambda job: show)
    monkeypatch.setattr(task_mod, "scontrol", lambda *a: comments.append(a[-1]))
    for k, v in {"SLURM_JOB_ID": "5", "SLURM_ARRAY_JOB_ID": "4", "SLURM_ARRAY_TASK_ID": "1",
                 "SLURM_RESTART_COUNT": "0"}.items():
        monkeypatch.setenv(k, v)
    code = _run_task_keeping_signals(out)
    lines = [x for x in capsys.readouterr().out.splitlines() if x.startswith("task: FINAL")]
    assert code == runstate.EXIT_TERM and len(lines) == 1 and lines[0].startswith(f"task: FINAL {final}")
    assert comments[-1].startswith(f"Comment={final}")
    assert ("sbatch --array=1" in lines[0]) == (final != SIGTERM_WORDS["requeue"][:len(final)])
