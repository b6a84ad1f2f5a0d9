"""Runs of the scene on a fixed number of cores: the one loop that starts
YADE, applies the rule after each attempt and keeps every attempt's output.

    status = run_pool(jobs, cores=2, record="runs/study/schedule.json")

A job is one run (:class:`Job`): a line of a generated run folder's
``table.txt`` (``YADE_BATCH=table.txt:LINE yade -jT -n -x triaxial.py``, as
yade-batch runs it) or the folder's own scene (``line=None``). Every way of
running runs goes through here: the study's single seeds
(:func:`yade_scripts.campaign.study.run_samples`) and ensembles, sweeps
(:func:`yade_scripts.launch.batch.run_batch`) and SLURM array tasks
(:mod:`yade_scripts.launch.task`), and the CD study's runs of the LMGC90
scene (``lmgc90.study``: a job with its own ``command``, one thread).

* **Every attempt kept.** Each attempt appends to the job's log (a header
  line ``==== attempt K ...`` first) and to the run's record
  ``STEM.attempts.json`` (start, end, threads, exit, what the rule made of
  it; :mod:`yade_scripts.runs.runstate`).
* **One rule after each attempt** (:func:`yade_scripts.runs.runstate.judge`):
  done, resumed (a crash that left a checkpoint, up to
  :data:`~yade_scripts.runs.runstate.MAX_RESUMES` times; a stop that was asked
  for) or failed (a blow-up, exit 3, is never retried).
* **Longest first.** Jobs start in decreasing order of their estimated
  core-seconds (:func:`yade_scripts.launch.slurm.estimate`): the longest
  processing time rule (Graham 1969), which on identical cores finishes
  within 4/3 of the best possible makespan. Jobs of equal cost keep their
  order (a sweep's table order).
* **One thread per job while jobs wait** (or the job's ``threads``); each
  job whose contacts run in the compiled kernel (``widen``) can use more.
  Once no job waits, a core that frees up goes to the running widenable
  job with the most work left: it gets SIGTERM, writes a checkpoint and
  exits 75, and is resumed at once with the freed cores added (the
  kernel's OpenMP threads are YADE's ``-j``). A job is widened only when its
  progress record (``STEM.progress.json``, written by the scene) does not
  give it less than :data:`WIDEN_MIN_SECONDS` left and it has run at least
  :data:`WIDEN_AFTER_SECONDS` (its SIGTERM handler is installed).
* The scene's lines are relayed with the sample in front: every line of a
  job with ``echo_all`` (a study's single seeds), else each running job's
  newest line every PROGRESS_SECONDS, when it changed.
* **Work after a run** (``after``, e.g. the study's analysis of a dump):
  for each job that is complete, already at the start or once done,
  ``after(job)`` gives a command; it runs on one core of its own, only
  when no run waits, and before a freed core goes to widening, so the
  analyses of the finished runs fill the cores that the last runs leave
  idle, and the pool ends when they have (``after_first``: on the first
  free core, before the waiting runs, for a study that keeps its
  finished runs as it goes, :mod:`yade_scripts.campaign.archive`). Its output goes to
  ``STEM.after.log``; a failure is reported and loses nothing (the caller
  can do the work again).
* ``stopping()`` (e.g. a SLURM task's SIGTERM): every running job gets
  SIGTERM (it checkpoints and exits 75) as soon as its scene has started
  (its SIGTERM handler installed), no job starts any more, and the work
  after runs is stopped (SIGTERM) and not started any more. Without a
  ``stopping`` (the study, a sweep), the pool stops so on its own SIGTERM
  or Ctrl-C (SIGINT) while it runs, and its runs and work are started in
  sessions of their own, so that a terminal's Ctrl-C reaches the pool
  only and no run is left going without it.

Every attempt (job, start, end, threads, exit; ``"kind": "after"`` for the
work after a run) goes to ``record`` (JSON),
and :func:`idle_core_seconds` gives the idle core-time of the schedule:
cores x makespan minus the busy core-seconds.
"""
from __future__ import annotations

import json
import os
import platform
import shutil
import signal
import subprocess
import threading
import time
from dataclasses import dataclass, field

from .. import yadeplugin
from ..runs import noremote
from ..runs.runlock import RunBusy, RunLock, describe, lock_path
from ..runs.runstate import (EXIT_TERM, MAX_RESUMES, DumpUnreadable, RunFiles, Verdict, checkpoint_position, clear_attempt,
                             dump_condition, end_attempt,
                             has_checkpoint, judge, now_utc, reclaim_killed, start_attempt)
from ..scene.parameters import ConfigError

#: a running job is widened only after this many seconds (its SIGTERM
#: handler is installed well before: YADE starts in a few seconds)
WIDEN_AFTER_SECONDS = 30.0
#: ... and only when its progress record does not give it less than this
#: left (a stop and resume costs a checkpoint and a YADE start, a few seconds)
WIDEN_MIN_SECONDS = 120.0
#: seconds between two looks at the running jobs
POLL_SECONDS = 1.0
#: seconds between two relayed progress lines of a job (echo_all aside)
PROGRESS_SECONDS = 20.0
#: the prefix of the scene's own lines in its log
SCENE = "triaxial.py: "
#: a stop asked for while a run is still starting (YADE loading, before the
#: scene's SIGTERM handler) waits until the scene's progress record says it
#: has started, this long at most
STARTING_SECONDS = 60.0


def yade_env(folder=None):
    """The environment for a YADE process: OpenMP threads sleep when idle
    (OMP_WAIT_POLICY=PASSIVE). With the default spinning, two YADE jobs on two
    cores made the polyhedra kernel's 2-thread steps 60 times slower
    (benchmarks/bench_kernel.py next to a running job: 24 ms against 0.35 ms).
    libgomp reads the variable when it loads, so it must be set here. And
    YADE_PREFIX on the kernel plugin's build for the run folder ``folder``
    where there is one (:func:`yade_scripts.yadeplugin.environment`): YADE
    loads its plugins when it starts, so that too must be set here.

    Parameters
    ----------
    folder : str, optional
        The generated run folder whose own build of the kernel plugin YADE
        is to load (None: this package's build).

    Returns
    -------
    dict
        A copy of ``os.environ`` (str -> str), with ``YADE_PREFIX`` when
        there is a ready build, and ``OMP_WAIT_POLICY=PASSIVE`` unless the
        environment sets it already.
    """
    env = yadeplugin.environment(run_folder=folder)
    env.setdefault("OMP_WAIT_POLICY", "PASSIVE")
    return env


@dataclass
class Job:
    """One run for :func:`run_pool`.

    Parameters
    ----------
    folder : str
        The generated run folder; YADE runs its ``triaxial.py`` there.
    line : int or None
        The run's line in the table (its line number in the file, header
        included, as yade-batch counts), or None: the scene's own
        parameters.
    description : str
        The run's name (a table line's ``description``); unique in a pool.
    dump : str
        The dump the run writes (``STEM.h5``; its companions,
        :class:`~yade_scripts.runs.runstate.RunFiles`, beside it).
    cost : float
        Estimated core-seconds (:func:`yade_scripts.launch.slurm.estimate`): the
        larger, the earlier the job starts.
    widen : bool
        True when more threads speed it up (polyhedra on the compiled
        kernel): it may be stopped and resumed on cores that free up.
    tag : str
        The sample (or a sweep's name), in front of its messages.
    threads : int
        YADE threads (``yade -jN``) it starts on.
    log : str
        The log every attempt appends to (default
        ``triaxial.py.<description>.log`` in ``folder``, as yade-batch
        names it).
    echo_all : bool
        Relay every line of the scene (else the newest one every
        :data:`PROGRESS_SECONDS`).
    table : str
        The table ``line`` is in (default ``table.txt``, relative to
        ``folder``).
    command : list of str, optional
        The attempt's command instead of YADE (another scene that keeps the
        same contract, :mod:`yade_scripts.runs.runstate`: its exit codes, the
        dump and its companions, its checkpoint, the lock it takes over
        from the pool; the CD scene ``python -m lmgc90.triaxial``); run in
        ``folder``, the same command for every attempt (the scene resumes
        itself from its checkpoint). ``threads`` is then the cores it holds.
    prefix : str
        The prefix of the scene's own lines in its log (default
        :data:`SCENE`, the YADE scene's), the lines relayed.

    Attributes
    ----------
    exits : list of int
        After the pool: the exit code of each attempt, stops asked for
        left out.
    verdict : yade_scripts.runs.runstate.Verdict or None
        After the pool: the rule's word on its last attempt (None when it
        did not run).
    name : str
        ``[tag] description`` (``[tag]`` when they are the same), as the
        messages name it.

    Examples
    --------
    >>> job = Job("runs/t1", 2, "spheres-seed1", "runs/t1/spheres-seed1.h5", tag="spheres")
    >>> job.name, job.log
    ('[spheres] spheres-seed1', 'runs/t1/triaxial.py.spheres-seed1.log')
    """
    folder: str
    line: int | None
    description: str
    dump: str
    cost: float = 0.0
    widen: bool = False
    tag: str = ""
    threads: int = 1
    log: str = ""
    echo_all: bool = False
    table: str = "table.txt"
    command: list = None
    prefix: str = ""
    exits: list = field(default_factory=list)
    verdict: object = None

    def __post_init__(self):
        self.log = self.log or os.path.join(self.folder, f"triaxial.py.{self.description}.log")
        self.prefix = self.prefix or SCENE

    @property
    def name(self):
        """``[tag] description`` (``[tag]`` when they are the same)."""
        return f"[{self.tag}]" if self.description == self.tag else f"[{self.tag}] {self.description}"


def order(jobs):
    """The jobs in the order they start: largest ``cost`` first (stable).

    Parameters
    ----------
    jobs : iterable of Job
        The jobs.

    Returns
    -------
    list of Job
        A new list, by decreasing ``cost`` (core-seconds); jobs of equal
        cost keep their order.
    """
    return sorted(jobs, key=lambda j: -j.cost)


def widen_choice(free, waiting, running, now, time_left):
    """Which running job gets the ``free`` cores, or None.

    free (int) idle cores; waiting (int) jobs not started; running
    [(job, threads, started)] with ``started`` in s; now (s); time_left
    {description: s or None} from the jobs' progress records. Cores go to a job only
    when no job waits (a waiting job takes them on one thread), and only to
    a widenable job that has run WIDEN_AFTER_SECONDS and is not known to
    end within WIDEN_MIN_SECONDS; among those, the one with the most time
    left (unknown counts as most), then the fewest threads. Returns
    (job, new thread count).

    Parameters
    ----------
    free : int
        Idle cores.
    waiting : int
        Jobs (and work after runs) not started yet.
    running : list of tuple
        ``(job, threads, started)`` of each running job that may be
        stopped: the :class:`Job`, its YADE threads (int) and when it
        started (float, seconds since the epoch, as ``time.time()``).
    now : float
        The time now, seconds since the epoch.
    time_left : dict
        description (str) -> seconds left (float) by the job's progress
        record, or None when unknown (:func:`time_left`); a job missing
        from it counts as unknown.

    Returns
    -------
    tuple or None
        ``(job, threads)``: the :class:`Job` to stop and resume, and its
        new thread count (its threads + ``free``); None when ``free < 1``,
        a job waits, or no running job qualifies.
    """
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


def time_left(dump):
    """Seconds left that the newest progress record of the run writing
    ``dump`` gives (``seconds_left`` of STEM.progress.json), or None (no
    record yet, none in compaction, or a scene that writes none).

    Parameters
    ----------
    dump : str
        The run's dump (``STEM.h5``).

    Returns
    -------
    float or None
        Seconds of wall time left; None when the record cannot be read,
        is not a JSON object, or its ``seconds_left`` is missing or not a
        number.
    """
    try:
        with open(RunFiles(dump).progress) as fh:
            left = json.load(fh).get("seconds_left")
    except (OSError, ValueError, AttributeError):
        return None
    return float(left) if isinstance(left, (int, float)) else None


def idle_core_seconds(attempts, cores):
    """Idle core-time of a schedule (s): cores x (last end - first start)
    minus the sum of threads x duration over ``attempts`` (dicts with
    "start", "end" in s and "threads"). 0 for no attempts. Threads beyond
    the cores (an overloaded machine) make it negative.

    Parameters
    ----------
    attempts : list of dict
        One per attempt (as :func:`run_pool`'s record holds them): "start"
        and "end" (float, seconds from any common origin) and "threads"
        (int, cores it held); other keys are ignored.
    cores : int
        The cores of the schedule.

    Returns
    -------
    float
        Idle core-seconds (0.0 for no attempts).
    """
    if not attempts:
        return 0.0
    span = max(a["end"] for a in attempts) - min(a["start"] for a in attempts)
    return cores * span - sum(a["threads"] * (a["end"] - a["start"]) for a in attempts)


def summary(attempts, cores):
    """{"cores", "makespan_s", "busy_core_s", "idle_core_s", "idle_share"}
    of a schedule's attempts.

    Parameters
    ----------
    attempts : list of dict
        As :func:`idle_core_seconds` takes them ("start", "end" in s,
        "threads").
    cores : int
        The cores of the schedule.

    Returns
    -------
    dict
        "cores" (int, as given), "makespan_s" (last end - first start, s),
        "busy_core_s" (sum of threads x duration, core-seconds),
        "idle_core_s" (:func:`idle_core_seconds`, core-seconds) and
        "idle_share" (idle over cores x makespan, a fraction; 0.0 for a
        zero makespan); every number 0.0 for no attempts.
    """
    if not attempts:
        return {"cores": cores, "makespan_s": 0.0, "busy_core_s": 0.0, "idle_core_s": 0.0, "idle_share": 0.0}
    span = max(a["end"] for a in attempts) - min(a["start"] for a in attempts)
    idle = idle_core_seconds(attempts, cores)
    return {"cores": cores, "makespan_s": span, "busy_core_s": cores * span - idle, "idle_core_s": idle,
            "idle_share": idle / (cores * span) if span > 0 else 0.0}


class _Running:
    """A job's current attempt: its process, threads, start, whether a stop
    was asked for (and whether to widen it), and where its log was read to."""

    def __init__(self, job, threads, proc, number, offset):
        self.job, self.threads, self.proc, self.number = job, threads, proc, number
        self.started, self.start_utc = time.time(), now_utc()
        self.requested = False       # a stop asked for by us (SIGTERM sent, or due once it has started)
        self.term_sent = False
        self.widening = False        # ... to resume it on more threads
        self.offset = offset         # bytes of the log relayed so far
        self.newest = None           # the newest scene line not relayed yet (echo_all off)

    def started_scene(self):
        """True once the scene has started this attempt (its progress record
        is newer than the process): it then handles SIGTERM."""
        try:
            return os.path.getmtime(RunFiles(self.job.dump).progress) >= self.started - 1.0
        except OSError:
            return False

    def stop(self, now, at_once=False):
        """Send SIGTERM ``at_once``, or once the scene has started, or
        STARTING_SECONDS after the stop was asked for (a scene that writes
        no progress record)."""
        if self.term_sent or not (at_once or self.started_scene() or now - self.requested >= STARTING_SECONDS):
            return
        self.term_sent = True
        self.proc.send_signal(signal.SIGTERM)

    def new_lines(self):
        """The scene's lines (prefix removed) appended to the log since the
        last call."""
        try:
            with open(self.job.log, "rb") as fh:
                fh.seek(self.offset)
                data = fh.read()
        except OSError:
            return []
        end = data.rfind(b"\n") + 1
        self.offset += end
        prefix = self.job.prefix
        return [x[len(prefix):].strip() for x in data[:end].decode("utf-8", "replace").splitlines()
                if x.startswith(prefix)]


def _launch(job, threads, yade, number, note, own_session=False, lock=None):
    """Start an attempt: the header line in the job's log, then YADE (in a
    session of its own when ``own_session``), told that we hold its run's
    ``lock`` (:func:`yade_scripts.runs.runlock.inherited`)."""
    env = yade_env(job.folder)
    if lock is not None:
        env.update(lock.environment())
    if job.line is not None:
        env["YADE_BATCH"] = f"{job.table}:{job.line}"
    env["DISPLAY"] = ""
    if job.command:
        env.setdefault("OMP_NUM_THREADS", str(threads))
    where = checkpoint_position(job.dump)
    how = f"resumes from its checkpoint at step {where[0]} ({where[1]})" if where else "starts"
    if job.command:
        cmd = list(job.command)
    else:
        cmd = noremote.command(yade, ["-j", str(threads), "-n", "-x", "triaxial.py"])     # no remote servers
    offset = os.path.getsize(job.log) if os.path.exists(job.log) else 0
    with open(job.log, "a") as log:
        log.write(f"==== attempt {number} of {job.description}: {how}; {now_utc()} on {platform.node()}, "
                  f"{' '.join(os.path.basename(c) if k == 0 else c for k, c in enumerate(cmd))}"
                  f"{''.join(f', {k} {v}' for k, v in (note or {}).items())} ====\n")
        log.flush()
        proc = subprocess.Popen(cmd, cwd=job.folder, env=env, stdout=log, stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL, start_new_session=own_session)
    return proc, offset


class _After:
    """The work after a run (``after(job)``'s command) while it runs."""

    def __init__(self, job, cmd, own_session=False):
        self.job = job
        self.log = RunFiles(job.dump).stem + ".after.log"
        with open(self.log, "a") as fh:
            fh.write(f"==== after {job.description}: {now_utc()} on {platform.node()}, {' '.join(cmd)} ====\n")
            fh.flush()
            self.proc = subprocess.Popen(cmd, stdout=fh, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                         start_new_session=own_session)
        self.started = time.time()


def _catch_stop_signals(flag):
    """SIGTERM and SIGINT append to the list ``flag`` instead of ending the
    process (call from the main thread: Python sets handlers there);
    returns a function that puts the previous handlers back."""
    old = {s: signal.signal(s, lambda num, frame: flag.append(num)) for s in (signal.SIGTERM, signal.SIGINT)}
    return lambda: [signal.signal(s, h) for s, h in old.items()]


def run_pool(jobs, cores, record=None, echo=print, yade=None, stopping=None, note=None,
             max_resumes=MAX_RESUMES, after=None, after_first=False):
    """Run jobs on a fixed number of cores, each to its end: the one loop
    every launcher uses (the module docstring gives the schedule).

    First it takes the lock of every job's run, all or none
    (:func:`hold_runs`), and marks attempts that a dead launcher left as
    running as killed. A job whose dump is complete is not run; one with a
    checkpoint resumes; any other starts afresh (what an unfinished attempt
    left is removed). Each attempt is ``YADE -j THREADS -n -x triaxial.py``
    in the job's folder (with ``YADE_BATCH=TABLE:LINE`` for a table line),
    its output appended to the job's log, and is recorded in the run's
    ``STEM.attempts.json`` (or the job's own ``command``); after it ends,
    :func:`yade_scripts.runs.runstate.judge` decides: done, resumed or failed.

    Parameters
    ----------
    jobs : list of Job
        The runs; their descriptions must differ.
    cores : int
        Cores to fill (>= 1): the sum of the running jobs' threads and of
        the work after runs stays within it, but a job that alone needs
        more starts when nothing else runs.
    record : str, optional
        A JSON file of every attempt (job, start and end in s from the
        pool's start, threads, exit) and the schedule's :func:`summary`,
        rewritten as the schedule goes.
    echo : callable
        Takes each message (one line, the job's name in front).
    yade : str, optional
        The executable (default: ``yade`` on the PATH).
    stopping : callable, optional
        Returns True once the pool is to stop: every running job gets
        SIGTERM (it writes a checkpoint and exits 75), nothing more starts.
        Without it the pool's own SIGTERM or SIGINT stops it so (the
        handlers are installed while it runs, from the main thread).
    note : dict, optional
        key -> value added to each attempt's header line and record (a
        SLURM job id).
    max_resumes : int
        Crashes of a run started again at most
        (:data:`~yade_scripts.runs.runstate.MAX_RESUMES`).
    after : callable, optional
        job -> command (argv list) or None: the work after each complete
        job, run on a free core (its output in ``STEM.after.log``).
    after_first : bool, optional
        False (default): the work after runs waits until no run waits;
        True: it takes the first free core, before any waiting run (a study
        longer than its host, whose finished runs are to be analysed and
        kept while it goes: :mod:`yade_scripts.campaign.archive`).

    Returns
    -------
    dict
        description -> status: 0 done or complete already; the exit code
        of a failed run; "no complete dump" when it exited 0 without one;
        "stopped" when ``stopping()`` (or the pool's signal) stopped it,
        resumable, or it never started; "unreadable dump" when its dump
        could not be opened (held open by another process, an I/O error): it
        may be finished, so it was neither cleared nor run. A dump that says
        complete but is truncated or does not verify is moved aside (never
        removed) and its run starts afresh, said in one line. Each job's ``exits`` then lists the
        exit codes of its attempts (stops asked for left out) and
        ``verdict`` the rule's last word.

    Raises
    ------
    ConfigError
        ``cores < 1``, or no ``yade`` executable for a job without its own ``command``.
    yade_scripts.runs.runlock.RunBusy
        Another process holds the lock of one of the runs (one line naming
        it); nothing was touched.

    Examples
    --------
    A job whose dump is complete is not run again; the other runs here on
    the trivial command ``true`` in place of YADE: it exits 0 without
    writing a dump, which the rule calls a failure.

    >>> import os, shutil, tempfile
    >>> from postproc.schema import DumpWriter
    >>> d = tempfile.mkdtemp()
    >>> DumpWriter(os.path.join(d, "a.h5"), "spheres", {}).close()   # a complete (empty) dump
    >>> jobs = [Job(d, None, "a", os.path.join(d, "a.h5"), tag="a"),
    ...         Job(d, None, "b", os.path.join(d, "b.h5"), tag="b")]
    >>> run_pool(jobs, cores=1, yade=shutil.which("true"))
    [a] already complete, not run again
    [b] started on 1 thread(s)
    [b] FAILED (exit 0 without a complete dump; see .../triaxial.py.b.log)
    {'a': 0, 'b': 'no complete dump'}
    >>> jobs[1].exits, jobs[1].verdict.action
    ([0], 'failed')
    >>> from yade_scripts.runs.runstate import read_attempts
    >>> [(r["attempt"], r["exit"], r["action"]) for r in read_attempts(os.path.join(d, "b.h5"))]
    [(1, 0, 'failed')]
    """
    if stopping is not None or threading.current_thread() is not threading.main_thread():
        return _run_pool(jobs, cores, record, echo, yade, stopping or (lambda: False), note, max_resumes, after,
                         own_session=False, after_first=after_first)
    signals = []
    restore = _catch_stop_signals(signals)
    try:
        return _run_pool(jobs, cores, record, echo, yade, lambda: bool(signals), note, max_resumes, after,
                         own_session=True, after_first=after_first)
    finally:
        restore()


def hold_runs(jobs, what="launcher"):
    """Take the lock of every job's run (:mod:`yade_scripts.runs.runlock`), all
    or none: returns {description: RunLock}; raises
    :class:`~yade_scripts.runs.runlock.RunBusy` (one line naming the holder) when
    another process holds one, having released those it took and touched
    nothing. A stale lock (its holder died) is taken over, and the lock's
    ``took_over`` says so (:func:`run_pool` reports it).

    Parameters
    ----------
    jobs : iterable of Job
        The runs; each lock is ``lock_path(job.dump)``.
    what : str
        What holds the locks, as their records name it (e.g. "launcher",
        "run pool", "task").

    Returns
    -------
    dict
        description (str) -> the held :class:`~yade_scripts.runs.runlock.RunLock`
        (its ``took_over`` is the stale holder's record, or None); give
        them back with :func:`release_runs`.

    Raises
    ------
    yade_scripts.runs.runlock.RunBusy
        Another live process holds one of the locks (one line naming it);
        the locks taken before it are released.
    ConfigError
        A lock file cannot be made or opened (e.g. the run's folder is
        missing; one line naming the file); the locks taken before it are
        released, as after any other exception.
    """
    locks, path = {}, None
    try:
        for job in jobs:
            path = lock_path(job.dump)
            locks[job.description] = RunLock(path, what).acquire()
    except OSError as exc:
        release_runs(locks)
        raise ConfigError(f"{path}: cannot take the run's lock ({exc.strerror or exc}); nothing was touched") from None
    except BaseException:
        release_runs(locks)
        raise
    return locks


def release_runs(locks):
    """Give back the locks :func:`hold_runs` took.

    Parameters
    ----------
    locks : dict
        description -> :class:`~yade_scripts.runs.runlock.RunLock`.

    Returns
    -------
    None
    """
    for lock in locks.values():
        lock.release()


def _run_pool(jobs, cores, record, echo, yade, stopping, note, max_resumes, after, own_session, after_first):
    if cores < 1:
        raise ConfigError(f"cores must be >= 1, got {cores}")
    yade = yade or shutil.which("yade")
    if yade is None and any(not job.command for job in jobs):
        raise ConfigError("yade is not installed (make installs Debian's yade)")
    locks = hold_runs(jobs, what="task" if (note or {}).get("slurm_job") else "run pool")
    for job in jobs:
        stale = locks[job.description].took_over
        if stale and not stale.get("unreadable"):
            echo(f"{job.name}: taking over the run from {describe(stale)}, which is no longer running")
        killed = reclaim_killed(job.dump)
        if killed:
            echo(f"{job.name}: attempt(s) {', '.join(map(str, killed))} ended without a record (killed with their "
                 f"launcher): recorded as killed")
    try:
        return _run_locked(jobs, cores, record, echo, yade, stopping, note, max_resumes, after, own_session, locks,
                           after_first)
    finally:
        release_runs(locks)


def _run_locked(jobs, cores, record, echo, yade, stopping, note, max_resumes, after, own_session, locks,
                after_first):
    status, waiting, todo, doing = {}, [], [], []      # todo, doing: the work after runs

    def queue_after(job):
        cmd = after(job) if after is not None else None
        if cmd:
            todo.append((job, cmd))

    for job in order(jobs):
        kind, why = dump_condition(job.dump)
        if kind == "complete":
            echo(f"{job.name} already complete, not run again")
            status[job.description] = 0
            queue_after(job)
            continue
        if kind == "unreadable":        # it may be finished: never cleared, never run over
            echo(f"{job.name}: refused: {DumpUnreadable(job.dump, why)}")
            status[job.description] = "unreadable dump"
            continue
        if has_checkpoint(job.dump) and kind not in ("does-not-verify", "not-hdf5"):
            echo(f"{job.name}: an unfinished run with a checkpoint, resuming it")
        else:
            said = clear_attempt(job.dump)
            if said:
                echo(f"{job.name}: starting afresh: {'; '.join(said)}")
        waiting.append(job)
    attempts, running = [], {}      # description -> _Running
    t0 = time.time()
    next_relay, stop_sent = t0 + PROGRESS_SECONDS, False

    def write_record():
        if record:
            tmp = record + ".tmp"
            with open(tmp, "w") as fh:
                json.dump({"cores": cores, "attempts": attempts, "summary": summary(attempts, cores)}, fh, indent=1)
            os.replace(tmp, record)

    def launch(job, threads, why="started"):
        number = start_attempt(job.dump, start=now_utc(), threads=threads, log=os.path.basename(job.log),
                               host=platform.node(), **(note or {}))
        proc, offset = _launch(job, threads, yade, number, note, own_session, locks[job.description])
        running[job.description] = _Running(job, threads, proc, number, offset)
        echo(f"{job.name} {why} on {threads} thread(s)")

    def finish_after(a, code):
        attempts.append({"job": f"after {a.job.description}", "kind": "after", "tag": a.job.tag,
                         "start": a.started - t0, "end": time.time() - t0, "threads": 1, "exit": code})
        write_record()
        if code == 0:
            echo(f"{a.job.name}: the work after it done in {time.time() - a.started:.0f} s")
        elif not stop_sent:
            echo(f"{a.job.name}: the work after it failed (exit {code}; see {a.log})")

    while waiting or running or todo or doing:
        if stopping() and not stop_sent:
            stop_sent = True
            for r in running.values():
                r.requested = r.requested or time.time()
            for job in waiting:
                status[job.description] = "stopped"
                echo(f"{job.name}: not started (stopping)")
            waiting, todo = [], []
            for a in doing:
                a.proc.send_signal(signal.SIGTERM)
            if running:
                echo(f"[pool] stopping: SIGTERM to {len(running)} run(s), each writes a checkpoint")
        busy = sum(r.threads for r in running.values()) + len(doing)
        while todo and (after_first or not waiting) and busy < cores:
            job, cmd = todo.pop(0)
            doing.append(_After(job, cmd, own_session))
            echo(f"{job.name}: the work after it started on a free core (log {doing[-1].log})")
            busy += 1
        while waiting and (busy + waiting[0].threads <= cores or not (running or doing)):
            job = waiting.pop(0)
            launch(job, job.threads)
            busy += job.threads
        choice = None if stop_sent else widen_choice(
            cores - busy, len(waiting) + len(todo),
            [(r.job, r.threads, r.started) for r in running.values() if not r.requested],
            time.time(), {d: time_left(r.job.dump) for d, r in running.items()})
        if choice is not None:
            job, threads = choice
            r = running[job.description]
            r.requested, r.widening = time.time(), threads        # the cores are promised to it
            r.stop(time.time(), at_once=True)                     # it has run WIDEN_AFTER_SECONDS: started
            echo(f"{job.name}: a core is free, stopping it to resume on {threads} threads")
        for r in running.values():
            if r.requested:
                r.stop(time.time())
        time.sleep(POLL_SECONDS)
        relay = time.time() >= next_relay
        if relay:
            next_relay = time.time() + PROGRESS_SECONDS
        for r in running.values():           # the scene's lines
            for line in r.new_lines():
                if r.job.echo_all:
                    echo(f"[{r.job.tag}] {line}")
                else:
                    r.newest = line
            if relay and r.newest:
                echo(f"{r.job.name}: {r.newest}")
                r.newest = None
        for a in list(doing):
            code = a.proc.poll()
            if code is not None:
                doing.remove(a)
                finish_after(a, code)
        for d in list(running):
            r = running[d]
            code = r.proc.poll()
            if code is None:
                continue
            del running[d]
            job, end = r.job, time.time()
            for line in r.new_lines():
                if job.echo_all:
                    echo(f"[{job.tag}] {line}")
            attempts.append({"job": d, "tag": job.tag, "start": r.started - t0, "end": end - t0,
                             "threads": r.threads, "exit": code, "widening": bool(r.widening)})
            write_record()
            outside = code == EXIT_TERM and not r.requested   # SIGTERM sent to YADE itself (a scancel, a kill)
            v = judge(code, job.dump, resumes=sum(1 for c in job.exits if c != 0),
                      requested=bool(r.requested) or outside, max_resumes=max_resumes)
            if outside and v.action == "resume":
                v = Verdict("resume", v.reason.replace("stopped on request", "stopped by a SIGTERM sent to YADE"))
            job.verdict = v
            end_attempt(job.dump, r.number, start=r.start_utc, seconds=round(end - r.started, 3),
                        threads=r.threads, exit=code, requested=bool(r.requested), action=v.action, reason=v.reason,
                        log=os.path.basename(job.log), host=platform.node(), **(note or {}))
            if r.widening and v.action == "resume" and not stop_sent:
                launch(job, r.widening, why="resumed")
                continue
            if not (r.requested or outside):
                job.exits.append(code)
            if v.action == "done":
                status[d] = 0
                echo(f"{job.name} done in {end - r.started:.0f} s")
                if not stop_sent:
                    queue_after(job)
            elif v.action == "resume" and not stop_sent and not outside:
                echo(f"{job.name}: {v.reason}")
                launch(job, r.threads, why="resumed")
            elif v.action == "resume":
                status[d] = "stopped"
                echo(f"{job.name}: {v.reason}")
            else:
                status[d] = "no complete dump" if code == 0 else code
                echo(f"{job.name} FAILED ({v.reason}; see {job.log})")
    write_record()
    s = summary(attempts, cores)
    if attempts and record:
        echo(f"[pool] {len(attempts)} attempt(s) in {s['makespan_s']:.0f} s on {cores} cores: "
             f"idle core-time {s['idle_core_s']:.0f} s ({100 * s['idle_share']:.1f} %)")
    return status
