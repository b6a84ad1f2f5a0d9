"""A run and its attempts: the contract between the scene and whatever
starts it (a study, a sweep, a SLURM task, a user at the shell).

A *run* is one table line of a generated run folder (or the folder's own
scene); it writes the dump ``STEM.h5`` and its companions (:class:`RunFiles`).
An *attempt* is one YADE process on it. The scene (``triaxial.py``,
:mod:`yade_scripts.runs.attempt`) ends an attempt with one of the exit codes
below; whatever started it applies :func:`judge`, the one rule for what
comes next, and appends the attempt to the run's record
(``STEM.attempts.json``, :func:`record_attempt`). :func:`state_of` reads
what a run folder says about a run: complete, resumable at step N, failed
(and why), unfinished, or not started.

Exit codes of the scene:

* :data:`EXIT_DONE` (0): the dump is complete (now, or already);
* :data:`EXIT_CONFIG` (2): a parameter is invalid; nothing was run;
* :data:`EXIT_FAILED` (3): stopped on a blow-up or ``max_steps``; the
  snapshots are kept, the checkpoints removed (a blow-up replays
  identically from a checkpoint, so it is never retried);
* :data:`EXIT_BUSY` (4): another process holds the run (its lock,
  :mod:`yade_scripts.runs.runlock`); nothing was touched;
* :data:`EXIT_TERM` (75, EX_TEMPFAIL): stopped by SIGTERM after writing a
  checkpoint; run it again to resume;
* anything else is a crash: run it again to resume from the newest
  periodic checkpoint, if there is one.

Standard library only (h5py is imported to read a dump's ``complete``
flag), so YADE's Python, the venv and a SLURM task all use it.
"""
from __future__ import annotations

import datetime
import json
import os
import shutil
from dataclasses import dataclass

from . import checkpoint
from .runlock import RunBusy, describe, holds, lock_path, run_holder

EXIT_DONE, EXIT_CONFIG, EXIT_FAILED, EXIT_BUSY, EXIT_TERM = 0, 2, 3, 4, 75
#: a run that crashed and left a checkpoint is started again this many times
#: at most; stops asked for (SIGTERM by a scheduler, or to give a run more
#: cores) do not count
MAX_RESUMES = 2


@dataclass(frozen=True)
class RunFiles:
    """The files of the run that writes a dump (its properties are paths).

    Attributes
    ----------
    dump : str
        The dump, ``STEM.h5``.
    stem, parts, checkpoint, log_csv, info, progress, attempts : str
        Properties, the paths of its companions: ``STEM``,
        ``STEM.h5.parts``, ``STEM.ckpt``, ``STEM.log.csv``,
        ``STEM.info.json``, ``STEM.progress.json`` and
        ``STEM.attempts.json``.

    Examples
    --------
    >>> f = RunFiles("runs/s/run.h5")
    >>> f.checkpoint, f.attempts
    ('runs/s/run.ckpt', 'runs/s/run.attempts.json')
    """
    dump: str

    @property
    def stem(self):
        """The dump's path without ``.h5``."""
        return os.path.splitext(self.dump)[0]

    @property
    def parts(self):
        """The dump's parts folder while the run writes it."""
        return self.dump + ".parts"

    @property
    def checkpoint(self):
        """The newest checkpoint (the previous one is ``checkpoint + '.prev'``)."""
        return self.stem + ".ckpt"

    @property
    def log_csv(self):
        """The scene's log of the run (CSV rows)."""
        return self.stem + ".log.csv"

    @property
    def info(self):
        """The finished run's summary (JSON)."""
        return self.stem + ".info.json"

    @property
    def progress(self):
        """The scene's newest progress record (JSON, rewritten as it runs)."""
        return self.stem + ".progress.json"

    @property
    def attempts(self):
        """The record of every attempt (JSON list, kept across attempts)."""
        return self.stem + ".attempts.json"

    def written_by_an_attempt(self):
        """Every file an attempt writes, removed when a run starts afresh.

        Returns
        -------
        list of str
            The dump, its parts, the checkpoints, the CSV log, the info and
            progress records (the logs, the attempts record and the lock
            are not among them: they are kept).
        """
        ck = self.checkpoint
        return [self.dump, self.parts, ck, ck + ".prev", ck + ".tmp", self.log_csv, self.info, self.progress]


def complete(dump):
    """Whether a dump is finished.

    Parameters
    ----------
    dump : str
        The dump.

    Returns
    -------
    bool
        True when it is a readable HDF5 file with ``complete = 1`` (whether
        it adds up is :meth:`postproc.schema.DumpReader.verify`'s).

    Examples
    --------
    >>> complete("/nonexistent/run.h5")
    False
    """
    if not os.path.exists(dump):
        return False
    import h5py

    try:
        with h5py.File(dump, "r") as f:
            return bool(f.attrs.get("complete", 0))
    except OSError:
        return False


def has_checkpoint(dump):
    """Whether a run left a checkpoint to resume from.

    Parameters
    ----------
    dump : str
        The run's dump.

    Returns
    -------
    bool
        True when ``STEM.ckpt`` or ``STEM.ckpt.prev`` exists.

    Examples
    --------
    >>> has_checkpoint("/nonexistent/run.h5")
    False
    """
    ck = RunFiles(dump).checkpoint
    return os.path.exists(ck) or os.path.exists(ck + ".prev")


def checkpoint_position(dump):
    """Where a run would resume.

    Parameters
    ----------
    dump : str
        The run's dump.

    Returns
    -------
    tuple of (int, str) or None
        (step, stage) of the newest checkpoint whose header reads
        (:func:`yade_scripts.runs.checkpoint.header`; the payload is checked only
        when the run resumes), or None.

    Examples
    --------
    >>> checkpoint_position("/nonexistent/run.h5") is None
    True
    """
    for path in checkpoint.candidates(RunFiles(dump).checkpoint):
        try:
            h = checkpoint.header(path)
            return int(h["step"]), str(h["stage"])
        except (checkpoint.CheckpointError, KeyError, TypeError, ValueError):
            continue
    return None


class DumpUnreadable(RunBusy):
    """A dump that cannot be opened now (another process holds it open, so
    HDF5's file lock refuses it, or the file system fails to read it): it may
    hold a finished run, so nothing is touched. ``str()`` is one line.

    Attributes
    ----------
    path : str
        The dump.
    holder : dict
        Empty (the process that holds the file is not known).
    """

    def __init__(self, dump, why):
        self.path, self.holder = dump, {}
        RuntimeError.__init__(self, f"{dump} cannot be opened now ({why}); it may hold a finished run, so it is left "
                                    f"untouched: close what holds it open (or mend the file system), then run again")


#: the conditions of an existing dump (:func:`dump_condition`)
DUMP_CONDITIONS = ("absent", "empty", "unfinished", "complete", "unreadable", "truncated", "does-not-verify",
                   "not-hdf5")


def dump_condition(dump):
    """What a dump is, checked whole: the ``complete`` flag alone is not
    trusted.

    Parameters
    ----------
    dump : str
        The dump.

    Returns
    -------
    condition : str
        "absent"; "empty" (0 bytes); "unfinished" (it opens, ``complete``
        is not set); "complete" (``complete = 1`` and every snapshot reads
        against its index, :meth:`postproc.schema.DumpReader.verify`);
        "unreadable" (it cannot be opened now: held open by another process
        through HDF5's file lock, or an I/O error; it may be fine);
        "truncated" (an HDF5 file cut short or damaged); "does-not-verify"
        (it opens but its snapshots, count or index do not add up: e.g. a
        packed dump that lost a snapshot); "not-hdf5" (no HDF5 signature).
    detail : str
        One line: why.

    Examples
    --------
    >>> dump_condition("/nonexistent/run.h5")
    ('absent', 'no dump')
    """
    if not os.path.lexists(dump):
        return "absent", "no dump"
    try:
        size = os.path.getsize(dump)
        with open(dump, "rb") as fh:
            head = fh.read(8)
    except OSError as exc:
        return "unreadable", f"cannot be read: {exc.strerror or exc.__class__.__name__}"
    if size == 0:
        return "empty", "an empty file (0 bytes)"
    if head != b"\x89HDF\r\n\x1a\n":
        return "not-hdf5", f"not an HDF5 file ({size} bytes, no HDF5 signature)"
    import h5py

    try:
        with h5py.File(dump, "r") as f:
            flag = bool(f.attrs.get("complete", 0))
    except OSError as exc:
        text = str(exc).lower()
        if "unable to lock" in text or "errno = 11" in text or "temporarily unavailable" in text:
            return "unreadable", "held open by another process: HDF5 file lock"
        if "truncated" in text or "signature" in text or "eof" in text or "bad" in text or "corrupt" in text:
            return "truncated", f"truncated or damaged ({str(exc).splitlines()[0][:120]})"
        return "unreadable", f"cannot be opened: {str(exc).splitlines()[0][:120]}"
    if not flag:
        return "unfinished", "unfinished (complete is not set)"
    from postproc.schema import DumpFormatError, verify_dump

    try:
        verify_dump(dump)
    except DumpFormatError as exc:
        return "does-not-verify", "does not verify: " + str(exc).replace(dump + ": ", "", 1)
    except OSError as exc:
        return "unreadable", f"cannot be read whole: {str(exc).splitlines()[0][:120]}"
    return "complete", "complete"


def set_aside(path, why):
    """Move a file (or folder) aside as ``PATH.<why>-<UTC stamp>`` (a
    ``-2``, ``-3`` ... added when that name is taken): never removed, never
    over another moved-aside file.

    Parameters
    ----------
    path : str
        The file.
    why : str
        One word or hyphenated words, e.g. "truncated".

    Returns
    -------
    str
        The new path.

    Examples
    --------
    >>> import os, tempfile
    >>> d = tempfile.mkdtemp()
    >>> for _ in range(2):
    ...     _ = open(os.path.join(d, "run.h5"), "w").close()
    ...     _ = set_aside(os.path.join(d, "run.h5"), "truncated")
    >>> sorted(n.split("-", 1)[0] + ("-2" if n.endswith("-2") else "") for n in os.listdir(d))
    ['run.h5.truncated', 'run.h5.truncated-2']
    """
    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y%m%dT%H%M%SZ")
    base = f"{path}.{why}-{stamp}"
    new, k = base, 1
    while os.path.lexists(new):
        k += 1
        new = f"{base}-{k}"
    os.rename(path, new)        # same folder: atomic; the new name was found free just above
    return new


#: damaged finished dumps: moved aside, and the run starts again
SET_ASIDE = ("truncated", "does-not-verify", "not-hdf5")


def clear_attempt(dump):
    """Clear what an unfinished attempt left (:meth:`RunFiles.written_by_an_attempt`);
    its logs, attempts record and lock are kept. Call it holding the run's
    lock (:mod:`yade_scripts.runs.runlock`). A dump that may hold a finished run
    is never removed (:func:`dump_condition`): a complete one stays; one
    that cannot be opened now raises :class:`DumpUnreadable` and nothing is
    touched; a truncated, not-verifying or non-HDF5 one is moved aside
    (:func:`set_aside`) and its parts folder with it.

    Parameters
    ----------
    dump : str
        The run's dump.

    Returns
    -------
    list of str
        One line for each thing it did (what it removed; what it moved
        aside, where and why); empty when there was nothing to clear.

    Raises
    ------
    DumpUnreadable
        The dump cannot be opened now (nothing was touched).
    ValueError
        The dump is complete (nothing was touched).

    Examples
    --------
    >>> import tempfile
    >>> d = tempfile.mkdtemp()
    >>> open(os.path.join(d, "run.log.csv"), "w").close()
    >>> clear_attempt(os.path.join(d, "run.h5")); os.listdir(d)
    ['removed the unfinished attempt (run.log.csv)']
    []
    """
    said = []
    kind, why = dump_condition(dump)
    if kind == "unreadable":
        raise DumpUnreadable(dump, why)
    if kind == "complete":
        raise ValueError(f"{dump} is complete: not cleared")
    files = RunFiles(dump)
    if kind in SET_ASIDE:
        moved = set_aside(dump, kind)
        text = f"{os.path.basename(dump)}: {why}: moved aside to {os.path.basename(moved)}"
        if os.path.isdir(files.parts):
            text += f" (its parts to {os.path.basename(set_aside(files.parts, kind))})"
        said.append(text)
    left = [p for p in files.written_by_an_attempt() if os.path.lexists(p)]
    for p in left:
        if os.path.isdir(p):
            shutil.rmtree(p, ignore_errors=True)
        else:
            os.remove(p)
    if left:
        said.append(f"removed the unfinished attempt ({', '.join(map(os.path.basename, left))})")
    return said


# ------------------------------------------------------------ the rule
@dataclass(frozen=True)
class Verdict:
    """What comes after an attempt (:func:`judge`).

    Attributes
    ----------
    action : str
        "done" (the dump is complete), "resume" (start it again: it resumes
        from its checkpoint, or starts afresh when there is none) or "failed".
    reason : str
        One line.
    """
    action: str
    reason: str


def judge(code, dump, resumes=0, requested=False, max_resumes=MAX_RESUMES):
    """The one rule for what follows an attempt.

    0 with a complete dump is done (without one it failed); 2 (invalid
    parameters), 3 (a blow-up, ``max_steps``) and 4 (another writer) failed;
    a stop that was asked for resumes (from its checkpoint, or afresh when
    it came before its first one); any other end is a crash, resumed from
    its checkpoint, or started afresh when it had none, while ``resumes <
    max_resumes``, else failed.

    Parameters
    ----------
    code : int
        The attempt's exit code (negative: killed by that signal).
    dump : str
        The run's dump.
    resumes : int
        How many times the run was already started again after a crash.
    requested : bool
        True when whatever started the attempt asked it to stop (SIGTERM at
        a scheduler's time limit, or to resume it on more cores).
    max_resumes : int
        Crashes started again at most.

    Returns
    -------
    Verdict
        Its ``action`` ("done", "resume" or "failed") and one-line
        ``reason`` (the exit code, and the checkpoint's step where it
        resumes).

    Examples
    --------
    >>> judge(3, "/nonexistent/run.h5").action
    'failed'
    >>> judge(-9, "/nonexistent/run.h5", resumes=0).reason
    'crashed (exit -9) before its first checkpoint: it starts afresh (retry 1 of at most 2)'
    >>> judge(75, "/nonexistent/run.h5", requested=True).action
    'resume'
    """
    if code == EXIT_DONE:
        if complete(dump):
            return Verdict("done", "complete")
        return Verdict("failed", "exit 0 without a complete dump")
    if code == EXIT_FAILED:
        return Verdict("failed", "stopped on a blow-up or max_steps (exit 3; the scene's log says why)")
    if code == EXIT_CONFIG:
        return Verdict("failed", "invalid parameters (exit 2; the scene's log names it)")
    if code == EXIT_BUSY:
        return Verdict("failed", "another process holds the run (exit 4; the scene's log names it)")
    if not has_checkpoint(dump):
        if requested:
            return Verdict("resume", f"stopped on request (exit {code}) before its first checkpoint: it starts afresh")
        if resumes >= max_resumes:
            return Verdict("failed", f"crashed (exit {code}) before its first checkpoint, after {resumes} "
                           f"retry(ies)")
        return Verdict("resume", f"crashed (exit {code}) before its first checkpoint: it starts afresh "
                       f"(retry {resumes + 1} of at most {max_resumes})")
    where = checkpoint_position(dump)
    at = f" at step {where[0]} ({where[1]})" if where else ""
    if requested:
        return Verdict("resume", f"stopped on request (exit {code}); it resumes from its checkpoint{at}")
    if resumes >= max_resumes:
        return Verdict("failed", f"crashed (exit {code}) after {resumes} resume(s) from its checkpoint")
    return Verdict("resume", f"exit {code}: resuming from its checkpoint{at} (resume {resumes + 1} of at most "
                   f"{max_resumes})")


# ------------------------------------------------------------ the record
def read_attempts(dump):
    """The attempts recorded for a run (``STEM.attempts.json``).

    Parameters
    ----------
    dump : str
        The run's dump.

    Returns
    -------
    list of dict
        Oldest first: attempt, start, end, threads, exit, requested,
        action, reason, log, host (and slurm_job, job_start, requeued in a
        SLURM task); [] when none is recorded or the record is unreadable.

    Examples
    --------
    >>> read_attempts("/nonexistent/run.h5")
    []
    """
    try:
        with open(RunFiles(dump).attempts) as fh:
            data = json.load(fh)
    except (OSError, ValueError):
        return []
    return data if isinstance(data, list) else []


def _write_attempts(dump, rows):
    path = RunFiles(dump).attempts
    tmp = path + ".tmp"
    with open(tmp, "w") as fh:
        json.dump(rows, fh, indent=1)
    os.replace(tmp, path)
    return rows


def record_attempt(dump, **entry):
    """Append one ended attempt to the run's record, atomically.

    Parameters
    ----------
    dump : str
        The run's dump.
    **entry
        exit, action, reason, threads ...; ``end`` is set to now (UTC).

    Returns
    -------
    list of dict
        The record as written.

    Examples
    --------
    >>> import tempfile
    >>> dump = os.path.join(tempfile.mkdtemp(), "run.h5")
    >>> [r["exit"] for r in record_attempt(dump, exit=0, action="done")]
    [0]
    """
    return _write_attempts(dump, read_attempts(dump) + [{**entry, "end": now_utc()}])


def start_attempt(dump, **entry):
    """Record an attempt as it starts (``"action": "running"``, no end), so
    that an attempt killed with its launcher (a node failure, SIGKILL)
    still has its number and a record (:func:`reclaim_killed`).

    Parameters
    ----------
    dump : str
        The run's dump.
    **entry
        start, threads, log, host ...

    Returns
    -------
    int
        Its number: one more than the attempts recorded (1, 2, ...).

    Examples
    --------
    >>> import tempfile
    >>> dump = os.path.join(tempfile.mkdtemp(), "run.h5")
    >>> start_attempt(dump, threads=1), start_attempt(dump, threads=2)
    (1, 2)
    """
    rows = read_attempts(dump)
    number = len(rows) + 1
    _write_attempts(dump, rows + [{"attempt": number, **entry, "action": "running", "end": None}])
    return number


def end_attempt(dump, number, **entry):
    """Complete the record of an attempt with how it ended.

    Parameters
    ----------
    dump : str
        The run's dump.
    number : int
        The attempt's number (:func:`start_attempt`); appended when it was
        not recorded at its start.
    **entry
        exit, action, reason, seconds ...; ``end`` is set to now (UTC).

    Returns
    -------
    list of dict
        The record as written.

    Examples
    --------
    >>> import tempfile
    >>> dump = os.path.join(tempfile.mkdtemp(), "run.h5")
    >>> k = start_attempt(dump)
    >>> [(r["attempt"], r["action"]) for r in end_attempt(dump, k, exit=0, action="done")]
    [(1, 'done')]
    """
    rows = read_attempts(dump)
    for k, row in enumerate(rows):
        if row.get("attempt") == number and row.get("action") == "running":
            rows[k] = {**row, **entry, "attempt": number, "end": now_utc()}
            return _write_attempts(dump, rows)
    return _write_attempts(dump, rows + [{"attempt": number, **entry, "end": now_utc()}])


#: the reason recorded for an attempt that ended with its launcher
KILLED = ("killed with its launcher, no end recorded (a node failure, SIGKILL, or the end of a job "
          "that was not warned)")


def reclaim_killed(dump):
    """Mark every attempt still recorded as running as killed
    (:data:`KILLED`). Call it holding the run's lock
    (:mod:`yade_scripts.runs.runlock`), when no attempt of the run can be running.

    Parameters
    ----------
    dump : str
        The run's dump.

    Returns
    -------
    list of int
        The numbers of the attempts marked.

    Examples
    --------
    >>> import tempfile
    >>> dump = os.path.join(tempfile.mkdtemp(), "run.h5")
    >>> k = start_attempt(dump)          # its launcher then dies with it
    >>> reclaim_killed(dump), read_attempts(dump)[0]["action"]
    ([1], 'killed')
    """
    rows = read_attempts(dump)
    killed = [r.get("attempt") for r in rows if r.get("action") == "running"]
    if killed:
        _write_attempts(dump, [{**r, "action": "killed", "reason": KILLED} if r.get("action") == "running" else r
                               for r in rows])
    return killed


def mark_requeued(dump, note):
    """Note on the newest attempt that its SLURM task requeued itself.

    Parameters
    ----------
    dump : str
        The run's dump.
    note : str
        e.g. "requeue 2 of at most 10", stored as ``"requeued"``.

    Returns
    -------
    None

    Examples
    --------
    >>> import tempfile
    >>> dump = os.path.join(tempfile.mkdtemp(), "run.h5")
    >>> end_attempt(dump, start_attempt(dump), exit=75, action="resume") and None
    >>> mark_requeued(dump, "requeue 1 of at most 10"); task_requeues(dump)
    1
    """
    rows = read_attempts(dump)
    if rows:
        rows[-1] = {**rows[-1], "requeued": note}
        _write_attempts(dump, rows)


def task_requeues(dump):
    """How many times the run's SLURM task requeued itself.

    Parameters
    ----------
    dump : str
        The run's dump.

    Returns
    -------
    int
        The attempts marked ``requeued`` (:func:`mark_requeued`): a node
        failure or a preemption, which SLURM requeues on its own, is not
        among them.

    Examples
    --------
    >>> task_requeues("/nonexistent/run.h5")
    0
    """
    return sum(1 for r in read_attempts(dump) if r.get("requeued"))


def now_utc():
    """The time now.

    Returns
    -------
    str
        UTC, ISO 8601 to the second (``2026-11-27T16:25:53Z``).

    Examples
    --------
    >>> len(now_utc()), now_utc().endswith("Z")
    (20, True)
    """
    return datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")


# ------------------------------------------------------------ the state
@dataclass(frozen=True)
class RunState:
    """What a run folder says about one run (:func:`state_of`).

    Attributes
    ----------
    state : str
        "complete", "running", "unreadable" (the dump cannot be opened now),
        "damaged" (a dump that is truncated or does not verify),
        "resumable", "failed", "unfinished" or "not started".
    detail : str
        One line.
    step : int or None
        The checkpoint's step (resumable, and running when it has one).
    holder : dict or None
        The lock record of the process that runs it (running).
    finished : bool
        Property: True for a complete run.
    """
    state: str
    detail: str
    step: int | None = None
    holder: dict | None = None

    @property
    def finished(self):
        """True for a complete run."""
        return self.state == "complete"


def state_of(dump):
    """What a run's files say about it, in this order: a complete dump; a
    process holding the run's lock (running: named,
    :mod:`yade_scripts.runs.runlock`; never this process); a checkpoint
    (resumable at its step); the last recorded attempt failed (its reason);
    files of an attempt without either (unfinished: killed before its first
    checkpoint, it starts afresh); nothing (not started). A dump is complete
    here only when its ``complete`` flag is set and it verifies whole
    (:func:`dump_condition`); one that cannot be opened now is "unreadable"
    (after "running": a writer holds its dump open), one truncated or not
    verifying "damaged" (moved aside, never removed, when its line runs
    again).

    Parameters
    ----------
    dump : str
        The run's dump.

    Returns
    -------
    RunState
        Its ``state``, one-line ``detail``, ``step`` (resumable, or
        running with a checkpoint) and ``holder`` (running).

    Examples
    --------
    >>> state_of("/nonexistent/run.h5")
    RunState(state='not started', detail='not started', step=None, holder=None)
    """
    kind, why = dump_condition(dump)
    if kind == "complete":
        return RunState("complete", "complete")
    where = checkpoint_position(dump)
    try:
        holder = None if holds(lock_path(dump)) else run_holder(dump)       # not ourselves
    except OSError:
        holder = None
    if holder is not None:
        at = f", last checkpoint at step {where[0]} ({where[1]})" if where else ""
        return RunState("running", f"running: {describe(holder)}{at}", where and where[0], holder)
    if kind == "unreadable":
        return RunState("unreadable", f"the dump cannot be opened now ({why}): it may be a finished run; a task "
                        f"refuses it and leaves it untouched: look at it")
    if kind in SET_ASIDE and (where is None or complete(dump)):
        said = "complete but " if complete(dump) else ""
        return RunState("damaged", f"{said}{why}: maybe a finished run; moved aside (never removed) when its line "
                        f"runs again")
    if where is not None:
        return RunState("resumable", f"resumable at step {where[0]} ({where[1]})", where[0])
    tries = read_attempts(dump)
    if tries and tries[-1].get("action") == "failed":
        return RunState("failed", f"failed: {tries[-1].get('reason', 'no reason recorded')}")
    if any(os.path.exists(p) for p in RunFiles(dump).written_by_an_attempt()) or tries:
        return RunState("unfinished", "unfinished, no checkpoint (killed before its first checkpoint: it starts "
                        "afresh)")
    return RunState("not started", "not started")
