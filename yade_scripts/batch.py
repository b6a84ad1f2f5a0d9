"""Run the lines of a yade-batch table in a generated run folder, skipping
the lines whose dump is already complete (seed ensembles, sweeps).

    run_batch(folder, jobs=2, tag="polyhedra")

The table is the folder's ``table.txt`` (written by
:func:`yade_scripts.generate.generate`): a header line, then one line per
run with a ``description`` column and an ``out`` column naming its dump.
yade-batch runs every job single-threaded (jobs share the cores; stock
polyhedra contacts also crashed with several threads per job), ``jobs`` at a time; its progress lines are relayed with
``tag`` in front, and each job's own log is ``triaxial.py.<description>.log``.
"""
from __future__ import annotations

import ast
import os
import shlex
import shutil
import subprocess
import threading

from .parameters import ConfigError, coerce

PROGRESS_SECONDS = 20.0
#: a run that crashed (or was stopped by SIGTERM) and left a checkpoint is
#: started again this many times at most; each start resumes from the newest
#: checkpoint (triaxial.py). Exit 3 (a blow-up, max_steps) is never retried:
#: it would replay the same steps.
MAX_RESUMES = 2
EXIT_FAILED, EXIT_TERM = 3, 75


def yade_env():
    """The environment for a YADE process: OpenMP threads sleep when idle
    (OMP_WAIT_POLICY=PASSIVE). With the default spinning, two YADE jobs on two
    cores made the polyhedra kernel's 2-thread steps 60 times slower
    (benchmarks/bench_kernel.py next to a running job: 24 ms against 0.35 ms).
    libgomp reads the variable when it loads, so it must be set here."""
    env = dict(os.environ)
    env.setdefault("OMP_WAIT_POLICY", "PASSIVE")
    return env


def read_table(folder):
    """[(file line number, {column: raw value})] of the folder's table.txt.

    Every column but ``description`` must be a scene parameter
    (:mod:`yade_scripts.parameters`) and every value a Python literal of its
    type and range (yade-batch evaluates the values as Python): a misspelt
    column or a wrong value raises :class:`ConfigError` naming the line,
    before any run starts."""
    path = os.path.join(folder, "table.txt")
    with open(path) as fh:
        lines = fh.read().splitlines()
    if not lines:
        raise ConfigError(f"{path} is empty")
    head = lines[0].split()
    rows = []
    for k, line in enumerate(lines[1:], start=2):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        vals = shlex.split(line, posix=False)
        if len(vals) != len(head):
            raise ConfigError(f"{path} line {k}: {len(vals)} values for {len(head)} columns")
        row = dict(zip(head, vals))
        for name, raw in row.items():
            if name == "description":
                continue
            try:
                value = ast.literal_eval(raw)
            except (ValueError, SyntaxError):
                raise ConfigError(f"{path} line {k}: {name} = {raw} is not a Python literal") from None
            try:
                coerce(name, value)
            except ConfigError as exc:
                raise ConfigError(f"{path} line {k}: {exc}") from None
        rows.append((k, row))
    return rows


def dump_of(folder, row):
    """Path of the dump a table row writes (its ``out`` column, unquoted)."""
    return os.path.join(folder, row.get("out", "'run.h5'").strip("'\""))


def complete(dump):
    """True when ``dump`` is a finished, packed dump (attribute complete=1)."""
    if not os.path.exists(dump):
        return False
    import h5py

    try:
        with h5py.File(dump, "r") as f:
            return bool(f.attrs.get("complete", 0))
    except OSError:
        return False


def has_checkpoint(dump):
    """True when the run writing ``dump`` (STEM.h5) left a checkpoint
    (STEM.ckpt or STEM.ckpt.prev) to resume from."""
    stem = os.path.splitext(dump)[0]
    return any(os.path.exists(stem + ext) for ext in (".ckpt", ".ckpt.prev"))


def resumable(code, dump):
    """True when a run that ended with exit ``code`` can be resumed: it did
    not finish or stop on a blow-up, and left a checkpoint."""
    return code not in (0, EXIT_FAILED) and has_checkpoint(dump)


def clear_attempt(dump):
    """Remove what an unfinished run writing ``dump`` (STEM.h5) left: the
    dump, its part files, STEM.info.json and STEM.log.csv (logs are kept)."""
    stem = os.path.splitext(dump)[0]
    for p in (stem + ".h5", stem + ".h5.parts", stem + ".info.json", stem + ".log.csv", stem + ".ckpt",
              stem + ".ckpt.prev"):
        if os.path.isdir(p):
            shutil.rmtree(p, ignore_errors=True)
        elif os.path.exists(p):
            os.remove(p)


def newest_progress(log_path, start=""):
    """The newest progress line of a scene log (``triaxial.py: ...``,
    without that prefix) that begins with ``start``, or None (no such line,
    or no log yet)."""
    try:
        with open(log_path, "rb") as fh:
            fh.seek(max(0, os.path.getsize(log_path) - 4096))
            tail = fh.read().decode("utf-8", "replace").splitlines()
    except OSError:
        return None
    lines = [x for x in tail if x.startswith("triaxial.py: " + start)]
    return lines[-1][len("triaxial.py: "):].strip() if lines else None


def _watch_logs(folder, descriptions, tag, echo, stop, every=PROGRESS_SECONDS):
    """Relay the newest progress line of each job's log every ``every`` s."""
    last = {}
    while not stop.wait(every):
        for d in descriptions:
            line = newest_progress(os.path.join(folder, f"triaxial.py.{d}.log"))
            if line and line != last.get(d):
                last[d] = line
                echo(f"[{tag}] {d}: {line}")


def run_batch(folder, jobs=2, tag="batch", echo=print, attempts=None, job_threads=1):
    """Run the unfinished lines of ``folder/table.txt`` with yade-batch; a
    line that crashed and left a checkpoint is run again (it resumes), up to
    MAX_RESUMES times.

    Returns {description: exit status} for every line of the table (0 for
    lines already complete, None when yade-batch did not report a line).
    ``attempts`` (a dict), when given, receives {description: [exit status
    of each attempt]} for the lines run. ``job_threads``: YADE threads
    (``yade -jN``, the polyhedra kernel's OpenMP threads) of each job.
    """
    rows = read_table(folder)
    todo = [(k, r) for k, r in rows if not complete(dump_of(folder, r))]
    status = {r["description"]: 0 for _, r in rows}
    for k, r in rows:
        if (k, r) not in todo:
            echo(f"[{tag}] {r['description']} already complete, not run again")
    for _, r in todo:              # an unfinished earlier attempt resumes if it can, else starts afresh
        if has_checkpoint(dump_of(folder, r)):
            echo(f"[{tag}] {r['description']}: an unfinished run with a checkpoint, resuming it")
        else:
            clear_attempt(dump_of(folder, r))
    tries = {r["description"]: [] for _, r in todo}
    while todo:
        got = _run_batch_lines(folder, todo, jobs, tag, echo, job_threads)
        for _, r in todo:
            tries[r["description"]].append(got[r["description"]])
        status.update(got)
        todo = [(k, r) for k, r in todo if isinstance(got[r["description"]], int)
                and resumable(got[r["description"]], dump_of(folder, r))
                and len(tries[r["description"]]) <= MAX_RESUMES]
        if todo:
            echo(f"[{tag}] resuming from their checkpoints: " + ", ".join(
                f"{r['description']} (exit {got[r['description']]})" for _, r in todo))
    if attempts is not None:
        attempts.update(tries)
    return status


def _run_batch_lines(folder, todo, jobs, tag, echo, job_threads=1):
    """One yade-batch over the table lines ``todo``; {description: status}."""
    exe = shutil.which("yade-batch")
    if exe is None:
        raise ConfigError("yade-batch is not installed (it comes with Debian's yade)")
    status = {r["description"]: None for _, r in todo}
    lines = ",".join(str(k) for k, _ in todo)
    cmd = [exe, "-j", str(jobs), "--job-threads", str(job_threads), "-l", lines, "--plot-update", "0",
           "table.txt", "triaxial.py"]
    echo(f"[{tag}] yade-batch: {len(todo)} run(s), {jobs} at a time: "
         + ", ".join(r["description"] for _, r in todo))
    proc = subprocess.Popen(cmd, cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            stdin=subprocess.DEVNULL, text=True, bufsize=1, env=yade_env())
    stop = threading.Event()
    watcher = threading.Thread(target=_watch_logs, daemon=True,
                               args=(folder, [r["description"] for _, r in todo], tag, echo, stop))
    watcher.start()
    with open(os.path.join(folder, "batch.out"), "a") as log:
        for line in proc.stdout:
            log.write(line)
            log.flush()
            s = line.strip()
            if s.startswith("#") and ("started" in s or "done" in s):
                echo(f"[{tag}] {s}")
                if "done" in s and "exit status" in s:
                    desc = s[s.index("(") + 1:s.index(")")]
                    code = s.split("exit status")[1].split(")")[0].strip()
                    if code.lstrip("-").isdigit():   # yade-batch prints the raw wait status
                        raw = int(code)
                        code = raw >> 8 if raw > 0 and raw & 0xFF == 0 else (-(raw & 0x7F) if raw > 0 else raw)
                    status[desc] = code
    proc.wait()
    stop.set()
    watcher.join()
    for _, r in todo:              # a job that ran but left no complete dump failed
        d = r["description"]
        if status[d] == 0 and not complete(dump_of(folder, r)):
            status[d] = "no complete dump"
    return status
