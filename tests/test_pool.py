"""The schedule of many runs (yade_scripts.launch.pool): longest first, a freed core
to a running kernel job, resumes, the idle core-time. The runs here are a
stand-in for YADE (a shell script with the scene's exit contract: it writes
a checkpoint and exits 75 on SIGTERM, a complete dump and 0 at the end), so
the tests need no YADE and take seconds."""
from __future__ import annotations

import json
import os
import signal
import stat
import subprocess
import sys
import textwrap
import time

import pytest

from yade_scripts.launch import pool
from yade_scripts.runs import runstate
from yade_scripts.launch.pool import Job, idle_core_seconds, order, run_pool, time_left, widen_choice

# a stand-in for yade: `fake -j N -n -x triaxial.py` in a run folder, table
# line from YADE_BATCH; runs WORK core-seconds (from the table) split over N
# threads, resumes from RUN.ckpt (the work done), exits 75 on SIGTERM with a
# checkpoint, 0 with a "complete" marker, or the table's exit code.
FAKE = textwrap.dedent("""\
    #!{python}
    import os, signal, sys, time
    threads = int(sys.argv[sys.argv.index("-j") + 1])
    table, line = os.environ["YADE_BATCH"].split(":")
    rows = open(table).read().splitlines()
    head, row = rows[0].split(), rows[int(line) - 1].split()
    r = dict(zip(head, row))
    out = r["out"].strip("'")
    stem = out[:-3]
    done = float(open(stem + ".ckpt").read()) if os.path.exists(stem + ".ckpt") else 0.0
    stop = []
    signal.signal(signal.SIGTERM, lambda *a: stop.append(1))
    open(stem + ".pid", "w").write(str(os.getpid()))
    with open(stem + ".threads", "a") as fh:
        fh.write(f"{{threads}}\\n")
    work, tick = float(r["work"]), 0.05
    while done < work:
        if stop:
            open(stem + ".ckpt", "w").write(str(done))
            sys.exit(75)
        if int(r.get("crash", 0)) and done > work / 2 and not os.path.exists(stem + ".crashed"):
            open(stem + ".ckpt", "w").write(str(done))
            open(stem + ".crashed", "w").write("1")
            sys.exit(-6 % 256)
        time.sleep(tick)
        done += tick * threads
        print(f"triaxial.py: step 1 shear: eps_1 0.1, {{(work - done) / threads:.1f}} s left", flush=True)
    if int(r.get("code", 0)):
        sys.exit(int(r["code"]))
    open(out, "w").write("complete")
""")


@pytest.fixture
def fake(tmp_path, monkeypatch):
    exe = tmp_path / "fake-yade"
    exe.write_text(FAKE.format(python=sys.executable))
    exe.chmod(exe.stat().st_mode | stat.S_IEXEC)
    # the stand-in's dumps are text files: "complete" when done (pool and rule alike)
    done = lambda dump: os.path.isfile(dump) and open(dump, "rb").read(9) == b"complete"   # noqa: E731
    real = runstate.dump_condition
    cond = lambda dump: ("complete", "complete") if done(dump) else real(dump)   # noqa: E731
    monkeypatch.setattr(pool, "dump_condition", cond)
    monkeypatch.setattr(runstate, "dump_condition", cond)
    monkeypatch.setattr(runstate, "complete", done)
    monkeypatch.setattr(pool, "POLL_SECONDS", 0.05)
    monkeypatch.setattr(pool, "WIDEN_AFTER_SECONDS", 0.2)
    monkeypatch.setattr(pool, "WIDEN_MIN_SECONDS", 0.3)
    return str(exe)


def jobs_in(folder, rows, widen=()):
    """A run folder with table.txt rows (description, work s[, code, crash])
    and its Jobs (cost = work)."""
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "table.txt"), "w") as fh:
        fh.write("description out work code crash\n")
        for d, work, *rest in rows:
            code, crash = (list(rest) + [0, 0])[:2]
            fh.write(f"{d} '{d}.h5' {work} {code} {crash}\n")
    return [Job(str(folder), k + 2, d, os.path.join(folder, f"{d}.h5"), float(work), widen=d in widen, tag="t")
            for k, (d, work, *rest) in enumerate(rows)]


def test_longest_first_and_stable():
    js = [Job("f", i, f"j{i}", "x", c) for i, c in enumerate([1.0, 5.0, 3.0, 5.0])]
    assert [j.description for j in order(js)] == ["j1", "j3", "j2", "j0"]


def test_widen_only_when_nothing_waits_and_to_the_longest():
    a, b, c = (Job("f", 2, "a", "x", 1, widen=True), Job("f", 3, "b", "x", 1, widen=True),
               Job("f", 4, "c", "x", 1, widen=False))
    running = [(a, 1, 0.0), (b, 1, 0.0), (c, 1, 0.0)]
    left = {"a": 500.0, "b": None, "c": 9999.0}
    assert widen_choice(1, 1, running, 100.0, left) is None           # a job waits: it takes the core
    assert widen_choice(0, 0, running, 100.0, left) is None           # no free core
    assert widen_choice(1, 0, running, 100.0, left) == (b, 2)         # unknown time left counts as most
    assert widen_choice(2, 0, [(a, 1, 0.0)], 100.0, left) == (a, 3)   # all free cores
    assert widen_choice(1, 0, [(a, 1, 90.0)], 100.0, left) is None    # just started
    assert widen_choice(1, 0, [(a, 1, 0.0)], 100.0, {"a": 60.0}) is None   # nearly done
    assert widen_choice(1, 0, [(c, 1, 0.0)], 100.0, left) is None     # not widenable


def test_time_left_from_the_progress_record(tmp_path):
    dump = str(tmp_path / "x.h5")
    assert time_left(dump) is None                               # no record yet
    (tmp_path / "x.progress.json").write_text(json.dumps({"step": 5, "stage": "compaction", "seconds_left": None}))
    assert time_left(dump) is None                               # compaction: not known
    (tmp_path / "x.progress.json").write_text(json.dumps({"step": 9, "stage": "shear", "seconds_left": 150.0}))
    assert time_left(dump) == 150.0
    (tmp_path / "x.progress.json").write_text('{"step": 9, "sec')  # half written: not a number
    assert time_left(dump) is None


def test_idle_core_seconds_exact():
    att = [{"start": 0.0, "end": 10.0, "threads": 1}, {"start": 0.0, "end": 4.0, "threads": 1},
           {"start": 4.0, "end": 8.0, "threads": 1}]
    assert idle_core_seconds(att, 2) == 2 * 10.0 - 18.0
    assert idle_core_seconds(att + [{"start": 8.0, "end": 10.0, "threads": 1}], 2) == 0.0
    assert idle_core_seconds([], 2) == 0.0


def test_a_freed_core_goes_to_the_long_kernel_job(tmp_path, fake):
    """Two cores, a 2 s kernel job and a 0.4 s job: after the short one the
    long one is stopped and resumed on 2 threads; it finishes its work
    (checkpointed) and the schedule is nearly free of idle time."""
    js = jobs_in(tmp_path / "f", [("long", 2.0), ("short", 0.4)], widen=("long",))
    rec = str(tmp_path / "schedule.json")
    st = run_pool(js, 2, record=rec, echo=lambda m: None, yade=fake)
    assert st == {"long": 0, "short": 0}
    assert open(tmp_path / "f" / "long.threads").read().split() == ["1", "2"]
    data = json.load(open(rec))
    long_attempts = [a for a in data["attempts"] if a["job"] == "long"]
    assert [a["threads"] for a in long_attempts] == [1, 2] and long_attempts[0]["widening"]
    assert js[0].exits == [0]                       # the stop for widening is not an exit of the run
    s = data["summary"]
    # idle: the short job's core between its end and the long one's restart
    # (polls and a process start). Not widened, the long job's rest would
    # have run on one thread for twice its widened attempt's duration, one
    # core idle all along: widening must leave less idle than that. The
    # bound is taken from the record, not the wall clock, so a loaded
    # machine stretches both sides alike.
    widened = long_attempts[1]
    unwidened_idle = 2 * (widened["end"] - widened["start"])
    assert 0 <= s["idle_core_s"] < unwidened_idle and s["idle_core_s"] == pytest.approx(
        idle_core_seconds(data["attempts"], 2))


def test_crash_resumes_and_failure_is_reported(tmp_path, fake):
    js = jobs_in(tmp_path / "f", [("crashes", 0.4, 0, 1), ("blows", 0.2, 3, 0), ("fine", 0.2)])
    st = run_pool(js, 2, echo=lambda m: None, yade=fake)
    assert st["crashes"] == 0 and st["fine"] == 0 and st["blows"] == 3
    by = {j.description: j.exits for j in js}
    assert by["crashes"] == [250, 0] and by["blows"] == [3]


def test_complete_jobs_are_not_run_again(tmp_path, fake):
    js = jobs_in(tmp_path / "f", [("a", 0.1)])
    (tmp_path / "f" / "a.h5").write_text("complete")
    msgs = []
    assert run_pool(js, 2, echo=msgs.append, yade=fake) == {"a": 0}
    assert not (tmp_path / "f" / "a.threads").exists() and any("already complete" in m for m in msgs)


def test_bad_core_count():
    with pytest.raises(pool.ConfigError, match="cores must be >= 1"):
        run_pool([], 0, yade="x")


def test_progress_lines_are_relayed(tmp_path, fake, monkeypatch):
    monkeypatch.setattr(pool, "PROGRESS_SECONDS", 0.2)
    js = jobs_in(tmp_path / "f", [("a", 0.6)])
    msgs = []
    assert run_pool(js, 1, echo=msgs.append, yade=fake) == {"a": 0}
    assert any(m.startswith("[t] a: step 1 shear:") and m.endswith("s left") for m in msgs), msgs


def _after(tmp_path, seconds=0.3, code=0):
    """A command after each job: sleeps, then writes AFTER-<job> with the
    time it started and exits ``code``."""
    def cmd(job):
        return [sys.executable, "-c", f"import time, sys; t = time.time(); time.sleep({seconds}); "
                f"open({str(tmp_path / ('after-' + job.description))!r}, 'w').write(str(t)); sys.exit({code})"]
    return cmd


def test_work_after_a_run_fills_a_free_core_and_not_one_a_run_waits_for(tmp_path, fake):
    """Two cores, three 0.6 s jobs and one 1.5 s kernel job: the work after
    the first short job waits for the third (a run waiting takes the core
    first), then runs while the long one goes, before widening it; the pool
    ends after every job's work, each recorded once as an "after" attempt;
    a job complete at the start gets its work too."""
    js = jobs_in(tmp_path / "f", [("long", 1.5), ("a", 0.6), ("b", 0.6), ("c", 0.6), ("old", 0.1)],
                 widen=("long",))
    (tmp_path / "f" / "old.h5").write_text("complete")
    rec = str(tmp_path / "schedule.json")
    msgs = []
    st = run_pool(js, 2, record=rec, echo=msgs.append, yade=fake, after=_after(tmp_path))
    assert st == {"long": 0, "a": 0, "b": 0, "c": 0, "old": 0}
    data = json.load(open(rec))
    runs = {a["job"]: a for a in data["attempts"] if a.get("kind") != "after"}
    after = {a["job"]: a for a in data["attempts"] if a.get("kind") == "after"}
    assert sorted(after) == ["after a", "after b", "after c", "after long", "after old"]
    assert all(a["exit"] == 0 and a["threads"] == 1 for a in after.values())
    for d in ("a", "b", "c", "long", "old"):
        assert (tmp_path / f"after-{d}").exists(), d
    # no work after a run started before the last run had started
    last_start = max(a["start"] for a in data["attempts"] if a.get("kind") != "after")
    assert min(a["start"] for a in after.values()) >= last_start - 1e-9
    assert runs["c"]["start"] >= runs["a"]["end"] - 1e-9
    assert any("the work after it started on a free core" in m for m in msgs)
    assert (tmp_path / "f" / "a.after.log").read_text().startswith("==== after a: ")
    assert data["summary"]["idle_core_s"] == pytest.approx(idle_core_seconds(data["attempts"], 2))


def test_work_after_a_run_first_takes_the_free_core_before_a_waiting_run(tmp_path, fake):
    """``after_first``: one core, two 0.4 s jobs and a job complete at the
    start: each job's work starts as soon as a core is free, before the next
    waiting run, so every run but the first starts after the work of the one
    before it has ended."""
    js = jobs_in(tmp_path / "f", [("a", 0.4), ("b", 0.4), ("old", 0.1)])
    (tmp_path / "f" / "old.h5").write_text("complete")
    rec = str(tmp_path / "schedule.json")
    st = run_pool(js, 1, record=rec, echo=lambda m: None, yade=fake, after=_after(tmp_path, 0.2), after_first=True)
    assert st == {"a": 0, "b": 0, "old": 0}
    data = json.load(open(rec))
    runs = {a["job"]: a for a in data["attempts"] if a.get("kind") != "after"}
    after = {a["job"]: a for a in data["attempts"] if a.get("kind") == "after"}
    assert sorted(after) == ["after a", "after b", "after old"]
    # one core: the work after "old" (complete at the start) goes before any run, a's before b starts
    assert after["after old"]["end"] <= runs["a"]["start"] + 1e-9
    assert after["after a"]["start"] >= runs["a"]["end"] - 1e-9
    assert after["after a"]["end"] <= runs["b"]["start"] + 1e-9


def test_failed_work_after_a_run_is_reported_and_the_run_stays_done(tmp_path, fake):
    js = jobs_in(tmp_path / "f", [("a", 0.1)])
    msgs = []
    assert run_pool(js, 1, echo=msgs.append, yade=fake, after=_after(tmp_path, 0.0, code=3)) == {"a": 0}
    assert any("the work after it failed (exit 3" in m and "a.after.log" in m for m in msgs), msgs


def test_stopping_stops_the_work_after_runs(tmp_path, fake):
    """A stop while the work after a run goes: it gets SIGTERM, the pool
    returns at once, and no other work starts."""
    js = jobs_in(tmp_path / "f", [("a", 0.1), ("b", 0.1)])
    stop = []
    t = []

    def echo(m):
        if "the work after it started" in m:
            stop.append(1)
            t.append(time.time())
    st = run_pool(js, 1, echo=echo, yade=fake, stopping=lambda: bool(stop), after=_after(tmp_path, 30.0))
    assert st == {"a": 0, "b": 0}                   # one core: both runs go before any work after them
    assert time.time() - t[0] < 10.0
    assert not (tmp_path / "after-a").exists() and not (tmp_path / "after-b").exists()


# a study or sweep: run_pool without ``stopping``, in a process of its own
POOL_ALONE = textwrap.dedent("""\
    import json, os, sys
    from yade_scripts.launch import pool
    pool.POLL_SECONDS, pool.STARTING_SECONDS = 0.05, 0.3
    folder, fake = sys.argv[1:3]
    job = pool.Job(folder, 2, "a", os.path.join(folder, "a.h5"), 30.0, tag="t")
    st = pool.run_pool([job], 1, yade=fake, echo=lambda m: print(m, flush=True))
    print("STATUS", json.dumps(st), flush=True)
""")


@pytest.mark.parametrize("how", ["SIGTERM to the pool", "Ctrl-C to its process group"])
def test_a_pool_on_its_own_stops_on_sigterm_or_ctrl_c_and_leaves_no_run_going(tmp_path, fake, how):
    """Without ``stopping``, the pool's SIGTERM, or a terminal's Ctrl-C
    (SIGINT to the whole foreground process group), makes it send SIGTERM
    to its run, which checkpoints and exits 75; the pool returns "stopped"
    and nothing it started is left running. The run is in a session of its
    own, so the Ctrl-C does not kill it before its checkpoint."""
    jobs_in(tmp_path / "f", [("a", 30.0)])
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    proc = subprocess.Popen([sys.executable, "-c", POOL_ALONE, str(tmp_path / "f"), fake], cwd=root,
                            stdout=subprocess.PIPE, text=True, start_new_session=True)
    lines = []
    for line in proc.stdout:
        lines.append(line)
        if "started on 1 thread(s)" in line:
            break
    pid_file = tmp_path / "f" / "a.pid"
    deadline = time.time() + 20
    while not pid_file.exists() and time.time() < deadline:
        time.sleep(0.05)
    time.sleep(0.3)                                   # the stand-in's SIGTERM handler is installed
    if how.startswith("SIGTERM"):
        proc.send_signal(signal.SIGTERM)
    else:
        os.killpg(proc.pid, signal.SIGINT)
    out, _ = proc.communicate(timeout=30)
    assert 'STATUS {"a": "stopped"}' in out, "".join(lines) + out
    assert 0 < float((tmp_path / "f" / "a.ckpt").read_text()) < 30.0     # checkpointed part-way
    with pytest.raises(ProcessLookupError):
        os.kill(int(pid_file.read_text()), 0)


def test_a_pool_on_its_own_puts_the_signal_handlers_back(tmp_path, fake):
    before = signal.getsignal(signal.SIGTERM), signal.getsignal(signal.SIGINT)
    assert run_pool(jobs_in(tmp_path / "f", [("a", 0.1)]), 1, echo=lambda m: None, yade=fake) == {"a": 0}
    assert (signal.getsignal(signal.SIGTERM), signal.getsignal(signal.SIGINT)) == before
