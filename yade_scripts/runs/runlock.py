"""One writer per run: an exclusive lock held for as long as a process may
write a run's files.

    with RunLock(lock_path(dump), "task"):      # RunBusy (one line) when another process holds it
        ...

The lock is a POSIX record lock (``fcntl.lockf``) on the file ``STEM.lock``
beside the dump. POSIX locks are what NFS's lock manager (NLM, and NFSv4's
own locking) serves, so the lock holds across the nodes of a cluster that
share the run folder. The kernel drops it when its holder dies, however it
dies (a crash, SIGKILL, a node that reboots and whose locks the server
reclaims), so a lock is never left held by a dead process. The file holds
one JSON line naming its holder (host, pid, SLURM job, since, what), which
a refusal quotes; a holder that ends normally empties it, so a file that
still names someone while nobody holds the lock is a *stale* record of a
process that died, recognised and taken over (:attr:`RunLock.took_over`).

Who holds it:

* a launcher (:func:`yade_scripts.launch.pool.run_pool`, for the study, sweeps and
  SLURM tasks) holds the lock of every run it has, from before it looks at
  the run's files to after its last attempt; the YADE process it starts
  learns from the environment (:data:`INHERITED`) that its parent holds
  it, and checks that this is so (:func:`inherited`);
* a scene started by hand (``yade -x triaxial.py`` in a run folder) takes
  the lock itself (:class:`yade_scripts.runs.attempt.Attempt`);
* the study holds one more on its whole folder (``OUT/study.lock``), so that
  a second study on the folder refuses before it generates or sets aside
  anything.
* the writer of a folder's manifest and report holds ``FOLDER/report.lock``
  (:func:`yade_scripts.campaign.study.report_lock`): a study at its end, which waits
  for it, or a ``--collect``, which refuses while another holds it;
* the writer of an archive of analysed runs holds ``DEST/archive.lock``
  (:func:`yade_scripts.campaign.archive_store.save`), and a second one waits for it
  (:meth:`RunLock.acquire_waiting`).

POSIX locks belong to a process, and closing *any* descriptor of the file
releases them all; so a process opens each lock file once (a registry of
the locks it holds, counted), and :func:`holder` never opens a lock file
its own process holds.

Standard library only: YADE's Python, the venv and a SLURM task use it.
"""
from __future__ import annotations

import errno
import fcntl
import json
import os
import socket
import struct
import time

#: the environment variable by which a launcher tells the YADE process it
#: starts that it holds the run's lock: JSON {"path": lock file, "pid": the
#: launcher's pid}
INHERITED = "GRANULAR_RUN_LOCK"

#: struct flock of Linux (l_type, l_whence, l_start, l_len, l_pid), native alignment
_FLOCK = "hhqqi"
_held = {}       # real path -> [fd, count, record]: the locks this process holds


class RunBusy(RuntimeError):
    """The run is held by another process; ``str()`` is one line naming it.

    Attributes
    ----------
    path : str
        The lock file.
    holder : dict
        The holder's record (:func:`own_record` of that process; empty when
        it has not written it yet).
    """

    def __init__(self, path, holder, subject=None):
        self.path, self.holder = path, holder or {}
        super().__init__(f"{subject or describe_lock(path)} is being written by {describe(self.holder)}; "
                         f"nothing was touched (stop that one first, or wait for it)")


def lock_path(dump):
    """The lock file of the run that writes ``dump``.

    Parameters
    ----------
    dump : str
        The run's dump, ``STEM.h5``.

    Returns
    -------
    str
        ``STEM.lock``, beside the dump.

    Examples
    --------
    >>> lock_path("runs/study/polyhedra/run.h5")
    'runs/study/polyhedra/run.lock'
    """
    return os.path.splitext(dump)[0] + ".lock"


def describe_lock(path):
    """The run a lock file stands for, as a message names it.

    Parameters
    ----------
    path : str
        A lock file: ``STEM.lock`` of a run, or a study folder's ``study.lock``.

    Returns
    -------
    str
        ``folder/STEM`` for a run; ``the study folder FOLDER`` for a study.

    Examples
    --------
    >>> describe_lock("/scratch/arr/spheres-seed1/spheres-seed1.lock")
    'spheres-seed1/spheres-seed1'
    >>> describe_lock("/scratch/study/study.lock")
    'the study folder /scratch/study'
    """
    base = os.path.basename(path)
    stem = base[:-len(".lock")] if base.endswith(".lock") else base
    folder = os.path.basename(os.path.dirname(os.path.abspath(path)))
    return f"{folder}/{stem}" if stem != "study" else f"the study folder {os.path.dirname(os.path.abspath(path))}"


def describe(record):
    """One phrase naming the holder of a lock.

    Parameters
    ----------
    record : dict or None
        A holder's record (:func:`own_record`): pid, host, slurm_job,
        what, since; any may be missing.

    Returns
    -------
    str
        e.g. ``pid 123 on node1 (SLURM job 45_2, a task) since ...``.

    Examples
    --------
    >>> describe({"pid": 123, "host": "node1", "slurm_job": "45_2", "what": "task",
    ...           "since": "2026-11-27T16:25:53Z"})
    'pid 123 on node1 (SLURM job 45_2, a task) since 2026-11-27T16:25:53Z'
    >>> describe({})
    'another process (its record is not written yet)'
    """
    if not record:
        return "another process (its record is not written yet)"
    bits = [f"pid {record.get('pid', '?')} on {record.get('host', '?')}"]
    extra = [f"SLURM job {record['slurm_job']}"] if record.get("slurm_job") else []
    extra += [f"a {record['what']}"] if record.get("what") else []
    if extra:
        bits.append(f"({', '.join(extra)})")
    if record.get("since"):
        bits.append(f"since {record['since']}")
    return " ".join(bits)


def own_record(what):
    """The record this process writes into a lock it takes.

    Parameters
    ----------
    what : str
        The holder's role ("study", "task", "scene", "run pool" ...).

    Returns
    -------
    dict
        pid, host, slurm_job (``ARRAYJOB_TASK`` or the job id; None outside
        SLURM), what, since (UTC, ISO 8601).

    Examples
    --------
    >>> r = own_record("task")
    >>> r["pid"] == os.getpid() and r["what"] == "task"
    True
    """
    job = os.environ.get("SLURM_JOB_ID")
    array, task = os.environ.get("SLURM_ARRAY_JOB_ID"), os.environ.get("SLURM_ARRAY_TASK_ID")
    return {"pid": os.getpid(), "host": socket.gethostname(),
            "slurm_job": (f"{array}_{task}" if array and task else job) or None, "what": what,
            "since": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}


def _read(fd):
    os.lseek(fd, 0, os.SEEK_SET)
    data = b""
    while True:
        chunk = os.read(fd, 65536)
        if not chunk:
            break
        data += chunk
    try:
        rec = json.loads(data.decode("utf-8", "replace") or "{}")
    except ValueError:
        return {"unreadable": data[:200].decode("utf-8", "replace")}
    return rec if isinstance(rec, dict) else {}


def _write(fd, record):
    os.ftruncate(fd, 0)
    os.lseek(fd, 0, os.SEEK_SET)
    os.write(fd, (json.dumps(record) + "\n").encode())
    os.fsync(fd)


def _busy(exc):
    return exc.errno in (errno.EACCES, errno.EAGAIN)


class RunLock:
    """The exclusive lock on a lock file, taken by :meth:`acquire` (or
    ``with``): non-blocking, it raises :class:`RunBusy` naming the holder
    when another process holds it, and touches nothing then. Re-entrant
    within a process (counted).

    Parameters
    ----------
    path : str
        The lock file (:func:`lock_path` of a dump); made when missing.
    what : str
        The holder's role in its record ("study", "task", "scene" ...).
    subject : str, optional
        How a refusal names the run (default :func:`describe_lock`).

    Attributes
    ----------
    path : str
        The lock file, absolute.
    took_over : dict or None
        After :meth:`acquire`: the record of a holder that died without
        releasing (a stale lock), or None.
    acquired : bool
        True while this object holds the lock.

    Examples
    --------
    >>> import tempfile
    >>> folder = tempfile.mkdtemp()
    >>> with RunLock(os.path.join(folder, "run.lock"), "scene") as lock:
    ...     holds(lock.path), lock.took_over
    (True, None)
    >>> holds(os.path.join(folder, "run.lock"))
    False
    """

    def __init__(self, path, what="run", subject=None):
        self.path, self.what, self.subject = os.path.abspath(path), what, subject
        self.took_over, self.acquired = None, False

    @property
    def key(self):
        """The lock file's real path (the registry's key)."""
        return os.path.realpath(self.path)

    def acquire(self):
        """Take the lock now, or raise :class:`RunBusy`.

        Returns
        -------
        RunLock
            ``self``.
        """
        held = _held.get(self.key)
        if held is not None:
            held[1] += 1
            self.acquired = True
            return self
        fd = os.open(self.path, os.O_RDWR | os.O_CREAT, 0o666)     # the umask applies
        try:
            fcntl.lockf(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as exc:
            holder = _read(fd) if _busy(exc) else {}
            os.close(fd)
            if _busy(exc):
                raise RunBusy(self.path, holder, self.subject) from None
            raise
        previous = _read(fd)
        self.took_over = previous or None
        record = own_record(self.what)
        _write(fd, record)
        _held[self.key] = [fd, 1, record]
        self.acquired = True
        return self

    def release(self):
        """Give the lock back (its record emptied) once this process's last
        holder of it releases; a second call does nothing.

        Returns
        -------
        None
        """
        if not self.acquired:
            return
        self.acquired = False
        held = _held.get(self.key)
        if held is None:
            return
        held[1] -= 1
        if held[1] > 0:
            return
        del _held[self.key]
        fd = held[0]
        try:
            os.ftruncate(fd, 0)        # released normally: no record left to look stale
            fcntl.lockf(fd, fcntl.LOCK_UN)
        finally:
            os.close(fd)

    def acquire_waiting(self, poll_seconds, say):
        """Take the lock, waiting for as long as another process holds it.

        Parameters
        ----------
        poll_seconds : float
            Seconds between two tries, > 0.
        say : callable
            ``say(holder)``, called once, with the holder's record (dict,
            :func:`own_record` of that process), when the lock is first
            found held: how the caller tells its user that it waits.

        Returns
        -------
        RunLock
            ``self``, holding the lock.
        """
        said = False
        while True:
            try:
                return self.acquire()
            except RunBusy as exc:
                if not said:
                    say(exc.holder)
                    said = True
                time.sleep(poll_seconds)

    def __enter__(self):
        return self.acquire()

    def __exit__(self, *exc):
        self.release()

    def environment(self):
        """What a child process gets to know that this process holds the
        lock for it (:func:`inherited`).

        Returns
        -------
        dict
            ``{INHERITED: JSON {"path": lock file, "pid": this process}}``,
            to add to the child's environment.
        """
        return {INHERITED: json.dumps({"path": self.key, "pid": os.getpid()})}


def holds(path):
    """Whether this process holds a lock.

    Parameters
    ----------
    path : str
        The lock file.

    Returns
    -------
    bool
        True when this process holds it (:class:`RunLock`).

    Examples
    --------
    >>> holds("/nonexistent/run.lock")
    False
    """
    return os.path.realpath(path) in _held


def inherited(path, environ=None):
    """Whether the parent process holds the lock for us.

    Parameters
    ----------
    path : str
        The lock file.
    environ : dict, optional
        The environment to read (default ``os.environ``).

    Returns
    -------
    bool
        True when :data:`INHERITED` names this lock file and the parent's
        pid, and the lock file's record names that pid as its holder.

    Examples
    --------
    >>> inherited("/nonexistent/run.lock", environ={})
    False
    """
    raw = (os.environ if environ is None else environ).get(INHERITED)
    if not raw:
        return False
    try:
        said = json.loads(raw)
    except ValueError:
        return False
    if not isinstance(said, dict) or said.get("path") != os.path.realpath(path) or said.get("pid") != os.getppid():
        return False
    rec = holder(path)
    return bool(rec) and rec.get("pid") == said["pid"]


def holder(path):
    """Who holds a lock now, without taking it (``F_GETLK``).

    Parameters
    ----------
    path : str
        The lock file.

    Returns
    -------
    dict or None
        The holder's record (``{}`` when it has not written it yet), or
        None when nobody holds it (no file, or a free lock: a stale record
        is not a holder). This process's own locks are answered from its
        registry.

    Examples
    --------
    >>> holder("/nonexistent/run.lock") is None
    True
    """
    key = os.path.realpath(path)
    if key in _held:
        return dict(_held[key][2])
    try:
        fd = os.open(key, os.O_RDWR)
    except FileNotFoundError:
        return None
    try:       # F_GETLK asks who holds it, without taking it (a probe that took it could refuse a real writer)
        probe = struct.pack(_FLOCK, fcntl.F_WRLCK, os.SEEK_SET, 0, 0, 0)
        kind = struct.unpack(_FLOCK, fcntl.fcntl(fd, fcntl.F_GETLK, probe))[0]
        return None if kind == fcntl.F_UNLCK else _read(fd)
    finally:
        os.close(fd)


def run_holder(dump):
    """Who writes a run now.

    Parameters
    ----------
    dump : str
        The run's dump.

    Returns
    -------
    dict or None
        :func:`holder` of its :func:`lock_path`.

    Examples
    --------
    >>> run_holder("/nonexistent/run.h5") is None
    True
    """
    return holder(lock_path(dump))
