"""Many scene runs on a fixed number of cores, with no core left idle.

    status = run_pool(jobs, cores=2, record="runs/study/schedule.json")

A job is one line of a generated run folder's ``table.txt`` (a seed of a
sample, :func:`yade_scripts.generate.write_seed_table`); it runs as
yade-batch would run it (``YADE_BATCH=table.txt:LINE yade -jT -n -x
triaxial.py``, log ``triaxial.py.<description>.log``), so the table, the
run's files and its resume are those of :mod:`yade_scripts.batch`.

The schedule:

* **Longest first.** Jobs start in decreasing order of their estimated
  core-seconds (:func:`yade_scripts.slurm.estimate`): the longest
  processing time rule (Graham 1969), which on identical cores finishes
  within 4/3 of the best possible makespan. Seeds of both samples are
  interleaved: the polyhedra seeds start first, the sphere seeds fill the
  cores they leave.
* **One thread per job while jobs wait** (or the job's ``threads``); each job whose contacts run in
  the compiled kernel (``widen``) can use more. Once no job waits, a
  core that frees up goes to the running widenable job with the most work
  left: it gets SIGTERM, writes a checkpoint and exits 75 (the scene's
  contract, :mod:`yade_scripts.attempt`), and is resumed at once with the
  freed cores added (the kernel's OpenMP threads are YADE's ``-j``). A job
  is widened only when its log does not give it less than
  :data:`WIDEN_MIN_SECONDS` left and it has run at least
  :data:`WIDEN_AFTER_SECONDS` (its SIGTERM handler is installed).
* Every PROGRESS_SECONDS the newest progress line of each running job is
  relayed (when it changed), with the sample in front.
* A job that crashes and left a checkpoint is resumed, up to
  :data:`yade_scripts.batch.MAX_RESUMES` times (stops for widening do
  not count); exit 3 (a blow-up) is never retried.

Every attempt (job, start, end, threads, exit) goes to ``record`` (JSON),
and :func:`idle_core_seconds` gives the idle core-time of the schedule:
cores x makespan minus the busy core-seconds.
"""
from __future__ import annotations

import json
import os
import re
import shutil
import signal
import subprocess
import time
from dataclasses import dataclass, field

from .batch import (EXIT_FAILED, EXIT_TERM, MAX_RESUMES, PROGRESS_SECONDS, clear_attempt, complete, has_checkpoint,
                    newest_progress, yade_env)
from .parameters import ConfigError

#: a running job is widened only after this many seconds (its SIGTERM
#: handler is installed well before: YADE starts in a few seconds)
WIDEN_AFTER_SECONDS = 30.0
#: ... and only when its log does not give it less than this left (a stop
#: and resume costs a checkpoint and a YADE start, a few seconds)
WIDEN_MIN_SECONDS = 120.0
#: seconds between two looks at the running jobs
POLL_SECONDS = 1.0
#: progress lines of the scene that give the time left
_TIME_LEFT = re.compile(r"(\d+(?:\.\d+)?) (s|min|h) left")


@dataclass
class Job:
    """One table line to run: ``folder`` (a generated run folder), ``line``
    (its line number in table.txt), ``description``, ``dump`` (path of the
    dump it writes), ``cost`` (estimated core-seconds: the order), ``widen``
    (True when more threads speed it up), ``tag`` (the sample, for the
    messages), ``threads`` (threads it starts on)."""
    folder: str
    line: int
    description: str
    dump: str
    cost: float
    widen: bool = False
    tag: str = ""
    threads: int = 1
    exits: list = field(default_factory=list)

    @property
    def log(self):
        return os.path.join(self.folder, f"triaxial.py.{self.description}.log")


def order(jobs):
    """The jobs in the order they start: largest ``cost`` first (stable)."""
    return sorted(jobs, key=lambda j: -j.cost)


def widen_choice(free, waiting, running, now, time_left):
    """Which running job gets the ``free`` cores, or None.

    free (int) idle cores; waiting (int) jobs not started; running
    [(job, threads, started)] with ``started`` in s; now (s); time_left
    {description: s or None} from the jobs' logs. Cores go to a job only
    when no job waits (a waiting job takes them on one thread), and only to
    a widenable job that has run WIDEN_AFTER_SECONDS and is not known to
    end within WIDEN_MIN_SECONDS; among those, the one with the most time
    left (unknown counts as most), then the fewest threads. Returns
    (job, new thread count)."""
    if free < 1 or waiting > 0:
        return None
    best = None
    for job, threads, started in running:
        left = time_left.get(job.description)
        if not job.widen or now - started < WIDEN_AFTER_SECONDS or (left is not None and left < WIDEN_MIN_SECONDS):
            continue
        key = (float("inf") if left is None else left, -threads)
        if best is None or key > best[0]:
            best = (key, job, threads)
    return None if best is None else (best[1], best[2] + free)


def time_left(log_path):
    """Seconds left that the newest progress line of a scene log gives
    (``... 12.3 min left``), or None (no such line yet, e.g. compaction)."""
    line = newest_progress(log_path, start="step")
    m = _TIME_LEFT.search(line) if line else None
    return float(m.group(1)) * {"s": 1, "min": 60, "h": 3600}[m.group(2)] if m else None


def idle_core_seconds(attempts, cores):
    """Idle core-time of a schedule (s): cores x (last end - first start)
    minus the sum of threads x duration over ``attempts`` (dicts with
    "start", "end" in s and "threads"). 0 for no attempts. Threads beyond
    the cores (an overloaded machine) make it negative."""
    if not attempts:
        return 0.0
    span = max(a["end"] for a in attempts) - min(a["start"] for a in attempts)
    return cores * span - sum(a["threads"] * (a["end"] - a["start"]) for a in attempts)


def summary(attempts, cores):
    """{"cores", "makespan_s", "busy_core_s", "idle_core_s", "idle_share"}
    of a schedule's attempts."""
    if not attempts:
        return {"cores": cores, "makespan_s": 0.0, "busy_core_s": 0.0, "idle_core_s": 0.0, "idle_share": 0.0}
    span = max(a["end"] for a in attempts) - min(a["start"] for a in attempts)
    idle = idle_core_seconds(attempts, cores)
    return {"cores": cores, "makespan_s": span, "busy_core_s": cores * span - idle, "idle_core_s": idle,
            "idle_share": idle / (cores * span) if span > 0 else 0.0}


def _start(job, threads, yade):
    env = yade_env()
    env["YADE_BATCH"] = f"table.txt:{job.line}"
    env["DISPLAY"] = ""
    log = open(job.log, "a")
    proc = subprocess.Popen([yade, "-j", str(threads), "-n", "-x", "triaxial.py"], cwd=job.folder, env=env,
                            stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
    log.close()
    return proc


def run_pool(jobs, cores, record=None, echo=print, yade=None):
    """Run ``jobs`` (:class:`Job`) on ``cores`` cores (module docstring);
    returns {description: exit status} (0 done or complete already; an int
    exit code; "no complete dump" when a job exited 0 without one). Each
    job's ``exits`` lists the exit codes of its attempts (stops for
    widening left out). ``record``: JSON file of every attempt and the
    schedule's :func:`summary`, rewritten as the schedule goes."""
    if cores < 1:
        raise ConfigError(f"cores must be >= 1, got {cores}")
    yade = yade or shutil.which("yade")
    if yade is None:
        raise ConfigError("yade is not installed (make installs Debian's yade)")
    status = {}
    waiting = []
    for job in order(jobs):
        if complete(job.dump):
            echo(f"[{job.tag}] {job.description} already complete, not run again")
            status[job.description] = 0
            continue
        if has_checkpoint(job.dump):
            echo(f"[{job.tag}] {job.description}: an unfinished run with a checkpoint, resuming it")
        else:
            clear_attempt(job.dump)
        waiting.append(job)
    attempts, running = [], {}      # description -> (job, threads, started, proc, widening)
    t0 = time.time()
    relayed, next_relay = {}, t0 + PROGRESS_SECONDS

    def write_record():
        if record:
            tmp = record + ".tmp"
            with open(tmp, "w") as fh:
                json.dump({"cores": cores, "attempts": attempts, "summary": summary(attempts, cores)}, fh, indent=1)
            os.replace(tmp, record)

    def launch(job, threads, why="started"):
        running[job.description] = (job, threads, time.time(), _start(job, threads, yade), False)
        echo(f"[{job.tag}] {job.description} {why} on {threads} thread(s)")

    while waiting or running:
        busy = sum(r[1] for r in running.values())
        while waiting and (busy + waiting[0].threads <= cores or not running):
            job = waiting.pop(0)
            launch(job, job.threads)
            busy += job.threads
        now = time.time()
        choice = widen_choice(cores - busy, len(waiting),
                              [(j, n, s) for j, n, s, _, w in running.values() if not w], now,
                              {d: time_left(r[0].log) for d, r in running.items()})
        if choice is not None:
            job, threads = choice
            j, n, s, proc, _ = running[job.description]
            running[job.description] = (j, threads, s, proc, True)      # the cores are promised to it
            proc.send_signal(signal.SIGTERM)
            echo(f"[{job.tag}] {job.description}: a core is free, stopping it to resume on {threads} threads")
        time.sleep(POLL_SECONDS)
        if time.time() >= next_relay:            # each running job's newest progress line, when it changed
            next_relay = time.time() + PROGRESS_SECONDS
            for d, r in running.items():
                line = newest_progress(r[0].log)
                if line and line != relayed.get(d):
                    relayed[d] = line
                    echo(f"[{r[0].tag}] {d}: {line}")
        for d in list(running):
            job, threads, started, proc, widening = running[d]
            code = proc.poll()
            if code is None:
                continue
            del running[d]
            end = time.time()
            ran_on = threads if not widening else _threads_of(proc)
            attempts.append({"job": d, "tag": job.tag, "start": started - t0, "end": end - t0,
                             "threads": ran_on, "exit": code, "widening": widening})
            write_record()
            if widening and code == EXIT_TERM and has_checkpoint(job.dump):
                launch(job, threads, why="resumed")
                continue
            job.exits.append(code)
            if code == 0:
                status[d] = 0 if complete(job.dump) else "no complete dump"
                echo(f"[{job.tag}] {d} done in {end - started:.0f} s")
            elif code != EXIT_FAILED and has_checkpoint(job.dump) and len(job.exits) <= MAX_RESUMES:
                echo(f"[{job.tag}] {d}: exit {code}, resuming from its checkpoint "
                     f"(resume {len(job.exits)} of at most {MAX_RESUMES})")
                launch(job, threads, why="resumed")
            else:
                status[d] = code
                echo(f"[{job.tag}] {d} FAILED (exit {code}, see {job.log})")
    write_record()
    s = summary(attempts, cores)
    if attempts:
        echo(f"[pool] {len(attempts)} attempt(s) in {s['makespan_s']:.0f} s on {cores} cores: "
             f"idle core-time {s['idle_core_s']:.0f} s ({100 * s['idle_share']:.1f} %)")
    return status


def _threads_of(proc):
    """The thread count a process was started with (its ``-j`` argument)."""
    args = proc.args
    return int(args[args.index("-j") + 1])
