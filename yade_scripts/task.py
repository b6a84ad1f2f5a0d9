"""One task of a SLURM job array: one table line of a run folder, run to the
end across as many jobs as it takes, without a human.

    python -m yade_scripts.task FOLDER [--task K] [--requeues N]

``slurm.sh`` (:mod:`yade_scripts.slurm`) ``exec``s this on YADE's own
Python, so that SLURM's ``--signal=B:TERM@S`` reaches it. Task K (default
``$SLURM_ARRAY_TASK_ID``) is the K-th run line of ``FOLDER/table.txt``; it
runs in the line's own folder ``FOLDER/<description>/`` (made on its first
run, with relative links to the scene, ``pkg/`` and the shape library),
where its dump, its log ``triaxial.log`` and its attempts record go. The
task:

1. checks its line by name, type and range (:func:`yade_scripts.batch.table_lines`):
   a bad line fails at once with one line naming the line and the
   parameter, before YADE starts;
2. exits at once when the line's dump is complete;
3. runs the line through :func:`yade_scripts.pool.run_pool` (the one loop
   and rule of every run: every attempt appended to ``triaxial.log`` with a
   header, and to the run's ``STEM.attempts.json``; a crash with a
   checkpoint resumed in place);
4. on SIGTERM (the time limit's warning) stops YADE, which writes a
   checkpoint and exits 75, and requeues its own job (``scontrol requeue``)
   while it has been requeued fewer than ``--requeues`` times, so that the
   next job of the task resumes from the checkpoint.

Its final state and reason go to its output (lines ``task: ...``, the last
one ``task: FINAL ...``), to SLURM's accounting (the exit code, and the job's
``Comment``, which ``sacct --format=JobID,State,ExitCode,Comment`` shows
when the cluster stores job comments) and to the run's attempts record.

Exit codes: 0 complete; 2 invalid line or folder; 3 the run failed (a
blow-up, or it crashed past its resumes); 75 stopped and resumable but not
requeued (no SLURM, or ``--requeues`` used up): submit the task again.

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

from .batch import dump_of, table_lines
from .parameters import ConfigError
from .runstate import EXIT_CONFIG, EXIT_DONE, EXIT_FAILED, EXIT_TERM, now_utc, state_of

#: requeues of one task at most (``--requeues``): each is one job's time limit
DEFAULT_REQUEUES = 10


def say(message, err=False):
    print(f"task: {message}", file=sys.stderr if err else sys.stdout, flush=True)


def slurm_job():
    """The id of this job as scontrol takes it (``ARRAYJOB_TASK`` for an
    array task: its plain SLURM_JOB_ID may be the array's own id, which
    names every task) and how many times it was requeued; (None, 0)
    outside SLURM."""
    job = os.environ.get("SLURM_JOB_ID")
    if not job:
        return None, 0
    array, task = os.environ.get("SLURM_ARRAY_JOB_ID"), os.environ.get("SLURM_ARRAY_TASK_ID")
    return (f"{array}_{task}" if array and task else job), int(os.environ.get("SLURM_RESTART_COUNT") or 0)


def scontrol(*args):
    """Run scontrol; None when it worked, else its one-line complaint."""
    exe = shutil.which("scontrol")
    if exe is None:
        return "scontrol is not on the PATH"
    r = subprocess.run([exe, *args], capture_output=True, text=True)
    if r.returncode != 0:
        return (r.stderr.strip() or r.stdout.strip() or f"exit {r.returncode}").splitlines()[0]
    return None


def finish(code, state, job_id):
    """Say the task's final state, leave it as the job's comment; returns
    ``code``."""
    say(f"FINAL {state}", err=code not in (EXIT_DONE, EXIT_TERM))
    if job_id:
        why = scontrol("update", f"JobId={job_id}", f"Comment={state[:250]}")
        if why:
            say(f"the job's comment could not be set: {why}")
    return code


def line_folder(folder, line):
    """The folder of a table line's run: ``FOLDER/<description>``."""
    return os.path.join(folder, line.description)


def link_inputs(folder, own, line):
    """Make the line's folder with relative links to what its run reads:
    the scene, ``pkg/`` and, for polyhedra, the line's shape library."""
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
    """Run task ``task`` of the array in ``folder`` (module docstring);
    returns the exit code."""
    job_id, restarts = slurm_job()
    threads = threads or int(os.environ.get("SLURM_CPUS_PER_TASK") or 1)
    say(f"task {task} of {folder}, {now_utc()} on {os.uname().nodename}"
        + (f", SLURM job {job_id} (requeued {restarts} time(s) so far)" if job_id else ", outside SLURM"))
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
    before = state_of(dump)
    if before.finished:
        return finish(EXIT_DONE, f"done: {os.path.basename(dump)} is complete, nothing to do", job_id)
    say(f"table line {line.number} ({line.description}): {before.detail}; {threads} thread(s)")

    from .pool import Job, run_pool

    stop = []
    signal.signal(signal.SIGTERM, lambda *a: stop.append(1))
    try:
        link_inputs(folder, own, line)
    except OSError as exc:
        return finish(EXIT_CONFIG, f"failed: {own}: {exc.strerror or exc}", job_id)
    job = Job(own, line.number, line.description, dump, tag=os.path.basename(folder), threads=threads,
              log=os.path.join(own, "triaxial.log"), table=os.path.join(folder, "table.txt"))
    note = {"slurm_job": job_id, "requeued": restarts} if job_id else None
    try:
        run_pool([job], threads, echo=echo, stopping=lambda: bool(stop), note=note)
    except ConfigError as exc:
        return finish(EXIT_CONFIG, f"failed: {exc}", job_id)
    v = job.verdict
    if v is None:                       # stopped before YADE started
        return finish(EXIT_TERM, f"not finished: stopped before its run started ({state_of(dump).detail})", job_id)
    if v.action == "done":
        return finish(EXIT_DONE, f"done: {os.path.basename(dump)} complete", job_id)
    if v.action == "failed":
        return finish(EXIT_FAILED, f"failed: {v.reason}", job_id)
    where = state_of(dump).detail
    if job_id and restarts < requeues:
        state = f"requeued to resume ({where}; requeue {restarts + 1} of at most {requeues})"
        say(f"FINAL {state}")
        why = scontrol("update", f"JobId={job_id}", f"Comment={state}") or scontrol("requeue", job_id)
        if why is None:
            return EXIT_DONE           # SLURM ends this job as REQUEUED and starts the task again
        return finish(EXIT_TERM, f"not finished: {where}; the requeue failed ({why}): submit the task again",
                      job_id)
    if job_id:
        return finish(EXIT_TERM, f"not finished: {where}; {requeues} requeue(s) used up: submit the task again "
                      f"(sbatch --array={task} {os.path.join(folder, 'slurm.sh')})", job_id)
    return finish(EXIT_TERM, f"not finished ({where}): run the task again", job_id)


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m yade_scripts.task", description=__doc__.splitlines()[0])
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
