"""One task of a SLURM job array: one table line of a run folder, run to the
end across as many jobs as it takes, without a human.

    python -m yade_scripts.launch.task FOLDER [--task K] [--requeues N]

``slurm.sh`` (:mod:`yade_scripts.launch.slurm`) ``exec``s this on YADE's own
Python, so that SLURM's ``--signal=B:USR1@S`` reaches it. Task K (default
``$SLURM_ARRAY_TASK_ID``) is the K-th run line of ``FOLDER/table.txt``; it
runs in the line's own folder ``FOLDER/<description>/`` (made on its first
run, with relative links to the scene, ``pkg/`` and the shape library),
where its dump, its log ``triaxial.log`` and its attempts record go. The
task:

1. checks its line by name, type and range (:func:`yade_scripts.launch.batch.table_lines`):
   a bad line fails at once with one line naming the line and the
   parameter, before YADE starts;
2. takes the run's lock (:mod:`yade_scripts.runs.runlock`): when another
   process writes the run (the same line submitted twice, a study or a
   task by hand on it), it refuses at once, naming that process, touches
   nothing and exits 4;
3. checks the line's dump whole (:func:`yade_scripts.runs.runstate.dump_condition`:
   the ``complete`` flag and every snapshot against its index) and exits at
   once when it is complete; a dump that cannot be opened now (held open by
   another process, HDF5's file lock; an I/O error) may be finished, so the
   task refuses, touches nothing and exits 4; a dump that is truncated or
   does not verify (a packed dump that lost a snapshot) is moved aside as
   ``NAME.h5.truncated-<UTC stamp>`` (or ``.does-not-verify-…``), never
   removed, said in one line, and the line runs again;
4. runs the line through :func:`yade_scripts.launch.pool.run_pool` (the one loop
   and rule of every run: every attempt recorded in the run's
   ``STEM.attempts.json`` as it starts and when it ends, one killed with
   its job recorded as killed by the next; appended to ``triaxial.log``
   with a header; a crash resumed from its checkpoint, or started afresh
   when it had none, :data:`yade_scripts.runs.runstate.MAX_RESUMES` times at most);
5. on SIGUSR1 (the time limit's warning, ``--signal=B:USR1@S``; or
   ``scancel --batch --signal=USR1``, to stop it now and have it resume)
   stops YADE, which writes a checkpoint and exits 75, and requeues its own
   job (``scontrol requeue``) while it has requeued itself fewer than
   ``--requeues`` times (counted in the attempts record: SLURM's own
   requeues, after a node failure or a preemption, do not count), so that
   the next job of the task resumes from the checkpoint;
6. on SIGTERM stops YADE the same way and ends, not requeued by itself;
   SLURM sends the same SIGTERM for ``scancel`` (stop for good: the run
   stays resumable by submitting the task again) and for its own requeue
   (``scontrol requeue``, a preemption: the task starts again by itself and
   resumes). The task tells them apart by what SLURM records of the job
   first (its restart count and state, :func:`sigterm_cause`) and, when
   that does not tell, says "stopped by SLURM (scancel or requeue)" rather
   than guess.

Its final state and reason go to its output (lines ``task: ...``, the last
one, once per job, ``task: FINAL ...``), to SLURM's accounting (the exit
code, and the job's ``Comment``, which ``sacct
--format=JobID,State,ExitCode,Comment`` shows when the cluster stores job
comments) and to the run's attempts record.

Exit codes: 0 complete (or requeued); 2 invalid line or folder; 3 the run
failed (a blow-up, or it crashed past its resumes); 4 another process
writes the run, or its dump cannot be opened now (held open elsewhere); 75 stopped and resumable but not requeued (scancel, no
SLURM, or ``--requeues`` used up): submit the task again.

Standard library only outside the run (the pool and the table checks):
it runs on the Python YADE runs on.
"""
from __future__ import annotations

import argparse
import os
import shutil
import signal
import subprocess
import sys

from ..runs.runlock import RunBusy, RunLock, describe, lock_path
from ..runs.runstate import (EXIT_BUSY, EXIT_CONFIG, EXIT_DONE, EXIT_FAILED, EXIT_TERM, SET_ASIDE, DumpUnreadable, complete,
                             dump_condition, has_checkpoint, mark_requeued, now_utc, set_aside, state_of, task_requeues)
from ..scene.parameters import ConfigError
from .batch import dump_of, table_lines
from .pool import Job, run_pool
from .slurm import DEFAULT_REQUEUES, record_job

def say(message, err=False):
    """Print one line of the task, ``task: <message>``, at once (flushed):
    on stdout, or on stderr with ``err``; SLURM appends both to the task's
    ``slurm-<job>_<task>.out``.

    Parameters
    ----------
    message : str
        One line, without the ``task:`` prefix.
    err : bool
        True: on stderr (a failure), else on stdout.

    Returns
    -------
    None
    """
    print(f"task: {message}", file=sys.stderr if err else sys.stdout, flush=True)


def slurm_job():
    """The id of this job as scontrol takes it (``ARRAYJOB_TASK`` for an
    array task: its plain SLURM_JOB_ID may be the array's own id, which
    names every task) and how many times it was requeued; (None, 0)
    outside SLURM.

    Returns
    -------
    job : str or None
        ``ARRAYJOB_TASK`` (``SLURM_ARRAY_JOB_ID`` and
        ``SLURM_ARRAY_TASK_ID`` joined by ``_``) for an array task, else
        ``SLURM_JOB_ID``; None when ``SLURM_JOB_ID`` is unset or empty.
    restarts : int
        ``$SLURM_RESTART_COUNT`` (0 when unset or empty): how many times
        SLURM started the job again.
    """
    job = os.environ.get("SLURM_JOB_ID")
    if not job:
        return None, 0
    array, task = os.environ.get("SLURM_ARRAY_JOB_ID"), os.environ.get("SLURM_ARRAY_TASK_ID")
    return (f"{array}_{task}" if array and task else job), int(os.environ.get("SLURM_RESTART_COUNT") or 0)


def scontrol(*args):
    """Run scontrol; None when it worked, else its one-line complaint.

    Parameters
    ----------
    *args : str
        scontrol's arguments, e.g. ``"requeue", "123_4"``.

    Returns
    -------
    str or None
        None when it exited 0; else the first line of its stderr (or of
        its stdout, or ``exit N``), or "scontrol is not on the PATH".
    """
    exe = shutil.which("scontrol")
    if exe is None:
        return "scontrol is not on the PATH"
    r = subprocess.run([exe, *args], capture_output=True, text=True)
    if r.returncode != 0:
        return (r.stderr.strip() or r.stdout.strip() or f"exit {r.returncode}").splitlines()[0]
    return None


def sigterm_cause(show_job, restarts=0):
    """Who sent the task's SIGTERM, from ``scontrol show job -o JOB`` taken
    after it. SLURM sends the same SIGTERM for a ``scancel`` and for its
    requeue (``scontrol requeue``, a preemption), and marks the job first:
    a requeue counts one more restart (``Restarts``, above this job's
    ``$SLURM_RESTART_COUNT``) and leaves it REQUEUED (then PENDING); a
    scancel leaves it CANCELLED; ``scancel --batch --signal=TERM`` only
    signals, and the job stays RUNNING. While the job's processes end,
    scontrol may show COMPLETING for either: then, as with no answer, the
    cause is not known.

    Parameters
    ----------
    show_job : str or None
        scontrol's one-line record of the job (``Key=Value`` words), or None.
    restarts : int
        ``$SLURM_RESTART_COUNT`` of this job (0 on its first start).

    Returns
    -------
    str
        "requeue", "scancel" or "unknown".

    Examples
    --------
    >>> sigterm_cause("JobId=7 ArrayJobId=6 JobState=COMPLETING Reason=None Restarts=1", 0)
    'requeue'
    >>> sigterm_cause("JobId=7 JobState=CANCELLED Reason=None Restarts=0"), sigterm_cause(None)
    ('scancel', 'unknown')
    """
    fields = dict(w.split("=", 1) for w in (show_job or "").split() if "=" in w)
    state = fields.get("JobState", "").upper()
    counted = fields.get("Restarts", "")
    if (counted.isdigit() and int(counted) > restarts) or state.startswith(("REQUEUE", "PENDING")):
        return "requeue"
    if state.startswith(("CANCELLED", "RUNNING")):
        return "scancel"
    return "unknown"


#: the task's words for who sent its SIGTERM (:func:`sigterm_cause`)
SIGTERM_WORDS = {"requeue": "requeued by SLURM (SIGTERM of a requeue: SLURM starts the task again by itself, and "
                            "it resumes)",
                 "scancel": "stopped on request (SIGTERM, scancel)",
                 "unknown": "stopped by SLURM (SIGTERM: scancel or requeue; which one, SLURM did not say)"}


def show_job(job_id):
    """``scontrol show job -o JOB``'s one line, or None when it fails.

    Parameters
    ----------
    job_id : str
        The job as scontrol takes it (:func:`slurm_job`).

    Returns
    -------
    str or None
    """
    exe = shutil.which("scontrol")
    if exe is None:
        return None
    try:
        r = subprocess.run([exe, "show", "job", "-o", job_id], capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return None
    return r.stdout.strip().splitlines()[0] if r.returncode == 0 and r.stdout.strip() else None


def finish(code, state, job_id):
    """Leave the task's final state as the job's comment, then say it as
    the task's last line, ``task: FINAL <state>`` (one per job); returns
    ``code``. A job that ``scancel`` cancelled is finished for SLURM
    before its task ends, and takes no comment: said on the line before.

    Parameters
    ----------
    code : int
        The task's exit code (:mod:`yade_scripts.runs.runstate`'s EXIT_*); the
        final line goes to stderr unless it is 0 or 75.
    state : str
        The final state and reason, one line (the comment keeps its first
        250 characters).
    job_id : str or None
        The job as scontrol takes it (:func:`slurm_job`); None: outside
        SLURM, no comment.

    Returns
    -------
    int
        ``code``.
    """
    if job_id:
        why = scontrol("update", f"JobId={job_id}", f"Comment={state[:250]}")
        if why:
            say(f"the job's comment could not be set: {why}")
    say(f"FINAL {state}", err=code not in (EXIT_DONE, EXIT_TERM))
    return code


def line_folder(folder, line):
    """The folder of a table line's run: ``FOLDER/<description>``.

    Parameters
    ----------
    folder : str
        The generated run folder.
    line : yade_scripts.launch.batch.TableLine
        The table line.

    Returns
    -------
    str
        ``folder`` joined with the line's description (the folder may not
        exist yet).
    """
    return os.path.join(folder, line.description)


def link_inputs(folder, own, line):
    """Make the line's folder with relative links to what its run reads:
    the scene, ``pkg/`` and, for polyhedra, the line's shape library.

    The sample and the library are the line's columns, else those of the
    folder's ``params.json``. A link (or file) already there is kept.

    Parameters
    ----------
    folder : str
        The generated run folder (``params.json``, ``triaxial.py``,
        ``pkg/``).
    own : str
        The line's folder (:func:`line_folder`), made when missing.
    line : yade_scripts.launch.batch.TableLine
        The table line.

    Returns
    -------
    None

    Raises
    ------
    OSError
        ``params.json`` cannot be read, or the folder or a link cannot be
        made.
    """
    import json

    with open(os.path.join(folder, "params.json")) as fh:
        params = json.load(fh)
    sample = line.row.get("sample", repr(params.get("sample"))).strip("'\"")
    names = ["triaxial.py", "pkg"]
    if sample == "polyhedra":
        names.append(line.row.get("library", repr(params["library"])).strip("'\""))
    os.makedirs(own, exist_ok=True)
    for name in names:
        link = os.path.join(own, name)
        if not os.path.lexists(link):
            os.symlink(os.path.join("..", name), link)


def run_task(folder, task, requeues=DEFAULT_REQUEUES, threads=None, echo=say):
    """Run one task of a SLURM array: table line ``task`` of ``folder``, in
    its own folder ``FOLDER/<description>/`` (steps 1 to 6 of the module
    docstring).

    From its start to the end of the process, SIGTERM and SIGUSR1 are the
    task's (they ask the run to stop); inside a SLURM job it records its
    array's job id in the folder (:func:`yade_scripts.launch.slurm.record_job`)
    and leaves its final state as the job's comment. Its lines go to
    stdout (``task: ...``, the last ``task: FINAL <state>``; on stderr
    when it failed).

    Parameters
    ----------
    folder : str
        The generated run folder (``table.txt``, ``triaxial.py``,
        ``params.json``, ``pkg/``), an absolute path.
    task : int
        The run line of ``table.txt``, from 1 (a SLURM array task id).
    requeues : int
        Requeues of the task by itself at most (its own, counted in the
        run's attempts record).
    threads : int, optional
        YADE threads (default: ``$SLURM_CPUS_PER_TASK``, else 1).
    echo : callable
        Takes each message of the pool (one line).

    Returns
    -------
    int
        The exit code: 0 complete (or requeued); 2 invalid line or folder;
        3 the run failed; 4 another process writes the run; 75 stopped and
        resumable but not requeued.
    """
    job_id, restarts = slurm_job()
    threads = threads or int(os.environ.get("SLURM_CPUS_PER_TASK") or 1)
    say(f"task {task} of {folder}, {now_utc()} on {os.uname().nodename}"
        + (f", SLURM job {job_id} (started {restarts + 1} time(s) so far)" if job_id else ", outside SLURM"))
    stop = []                      # the signals that asked it to stop, in order
    for sig in (signal.SIGTERM, signal.SIGUSR1):
        signal.signal(sig, lambda num, frame: stop.append(num))
    missing = [f for f in ("table.txt", "triaxial.py", "params.json", "pkg")
               if not os.path.exists(os.path.join(folder, f))]
    if missing:
        return finish(EXIT_CONFIG, f"failed: {folder} has no {' and no '.join(missing)} (not a generated run folder)",
                      job_id)
    try:
        lines = table_lines(folder)
    except ConfigError as exc:
        return finish(EXIT_CONFIG, f"failed: {exc}", job_id)
    if not 1 <= task <= len(lines):
        return finish(EXIT_CONFIG, f"failed: task {task}: no such line (1..{len(lines)}) in {folder}/table.txt",
                      job_id)
    line = lines[task - 1]
    if line.error:
        return finish(EXIT_CONFIG, f"invalid line: {line.error}", job_id)
    own = line_folder(folder, line)
    dump = os.path.join(own, os.path.basename(dump_of(folder, line.row)))
    if job_id:        # the array's job, for --collect to ask SLURM about (an sbatch by hand is recorded so)

        record_job(folder, os.environ.get("SLURM_ARRAY_JOB_ID") or job_id.split("_")[0], "task")
    try:
        os.makedirs(own, exist_ok=True)
        lock = RunLock(lock_path(dump), "task", subject=f"task {task} ({line.description})").acquire()
    except RunBusy as exc:         # another writer: touch nothing
        return finish(EXIT_BUSY, f"refused: {exc}", job_id)
    except OSError as exc:
        return finish(EXIT_CONFIG, f"failed: {own}: {exc.strerror or exc}", job_id)
    if lock.took_over and not lock.took_over.get("unreadable"):
        say(f"taking over the run from {describe(lock.took_over)}, which is no longer running")
    try:
        return _run_line(folder, task, line, own, dump, job_id, threads, requeues, stop, echo)
    finally:
        lock.release()


def _run_line(folder, task, line, own, dump, job_id, threads, requeues, stop, echo):
    """The task's line, its run's lock held."""
    kind, why = dump_condition(dump)
    if kind == "unreadable":            # it may be finished: refuse, touch nothing
        return finish(EXIT_BUSY, f"refused: {DumpUnreadable(dump, why)}", job_id)
    if kind == "complete":              # verified whole, not only its flag
        return finish(EXIT_DONE, f"done: {os.path.basename(dump)} is complete and verifies, nothing to do", job_id)
    if kind in SET_ASIDE and (complete(dump) or not has_checkpoint(dump)):
        try:
            moved = set_aside(dump, kind)
        except OSError as exc:
            return finish(EXIT_CONFIG, f"failed: {dump}: {why}, and it could not be moved aside: "
                                       f"{exc.strerror or exc}", job_id)
        say(f"{os.path.basename(dump)}: {why}: moved aside to {os.path.basename(moved)}; the line runs again")
    before = state_of(dump)
    say(f"table line {line.number} ({line.description}): {before.detail}; {threads} thread(s)")

    try:
        link_inputs(folder, own, line)
    except OSError as exc:
        return finish(EXIT_CONFIG, f"failed: {own}: {exc.strerror or exc}", job_id)
    job = Job(own, line.number, line.description, dump, tag=os.path.basename(folder), threads=threads,
              log=os.path.join(own, "triaxial.log"), table=os.path.join(folder, "table.txt"))
    note = {"slurm_job": job_id, "job_start": int(os.environ.get("SLURM_RESTART_COUNT") or 0) + 1} if job_id else None
    try:
        run_pool([job], threads, echo=echo, stopping=lambda: bool(stop), note=note)
    except ConfigError as exc:
        return finish(EXIT_CONFIG, f"failed: {exc}", job_id)
    except RunBusy as exc:
        return finish(EXIT_BUSY, f"refused: {exc}", job_id)
    v = job.verdict
    resubmit = f"sbatch --array={task} {os.path.join(folder, 'slurm.sh')}" if job_id else "run the task again"
    if v is None:                       # stopped before YADE started
        return finish(EXIT_TERM, f"stopped before its run started ({state_of(dump).detail}); to resume: {resubmit}",
                      job_id)
    if v.action == "done":
        return finish(EXIT_DONE, f"done: {os.path.basename(dump)} complete", job_id)
    if v.action == "failed":
        return finish(EXIT_FAILED, f"failed: {v.reason}", job_id)
    where = state_of(dump).detail
    asked = signal.Signals(stop[0]).name if stop else "no signal"
    if not job_id:
        return finish(EXIT_TERM, f"stopped on request ({asked}) ({where}); to resume: {resubmit}", job_id)
    if stop and stop[0] == signal.SIGTERM:         # scancel or SLURM's requeue: SLURM marked the job first
        cause = sigterm_cause(show_job(job_id), int(os.environ.get("SLURM_RESTART_COUNT") or 0))
        if cause == "requeue":
            return finish(EXIT_TERM, f"{SIGTERM_WORDS[cause]} ({where})", job_id)
        return finish(EXIT_TERM, f"{SIGTERM_WORDS[cause]} ({where}); to resume"
                                 f"{' if it is not requeued' if cause == 'unknown' else ''}: {resubmit}", job_id)
    used = task_requeues(dump)           # its own requeues: SLURM's (node failure, preemption) not counted
    if used >= requeues:
        return finish(EXIT_TERM, f"stopped ({where}); its {requeues} requeue(s) are used up; to resume: {resubmit}",
                      job_id)
    state = f"requeued to resume ({where}; requeue {used + 1} of at most {requeues})"
    why = scontrol("update", f"JobId={job_id}", f"Comment={state[:250]}") or scontrol("requeue", job_id)
    if why is None:
        mark_requeued(dump, f"requeue {used + 1} of at most {requeues}")
        say(f"FINAL {state}")
        return EXIT_DONE               # SLURM ends this job as REQUEUED and starts the task again
    return finish(EXIT_TERM, f"stopped ({where}); the requeue failed ({why}); to resume: {resubmit}", job_id)


def main(argv=None):
    """``python -m yade_scripts.launch.task FOLDER [--task K] [--requeues N]``:
    :func:`run_task`, the task K by default ``$SLURM_ARRAY_TASK_ID``.

    Parameters
    ----------
    argv : list of str, optional
        The command line's arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        :func:`run_task`'s exit code; 2 when no task is given and
        ``SLURM_ARRAY_TASK_ID`` is unset or not a number.
    """
    ap = argparse.ArgumentParser(prog="python -m yade_scripts.launch.task", description=__doc__.splitlines()[0])
    ap.add_argument("folder", help="the generated run folder (table.txt, triaxial.py)")
    ap.add_argument("--task", type=int, help="the run line of table.txt, from 1 (default: $SLURM_ARRAY_TASK_ID)")
    ap.add_argument("--requeues", type=int, default=DEFAULT_REQUEUES,
                    help=f"requeue the task at most this many times (default {DEFAULT_REQUEUES})")
    args = ap.parse_args(argv)
    task = args.task
    if task is None:
        raw = os.environ.get("SLURM_ARRAY_TASK_ID", "")
        if not raw:
            say("SLURM_ARRAY_TASK_ID is not set (sbatch sets it; by hand: SLURM_ARRAY_TASK_ID=K bash slurm.sh)",
                err=True)
            return EXIT_CONFIG
        if not raw.isdigit():
            say(f"task {raw}: no such line (a task id is a number from 1)", err=True)
            return EXIT_CONFIG
        task = int(raw)
    return run_task(os.path.abspath(args.folder), task, max(0, args.requeues))


if __name__ == "__main__":
    sys.exit(main())
