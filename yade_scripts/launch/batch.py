"""The table of a generated run folder, and running its lines.

    python -m yade_scripts.launch.batch FOLDER [--jobs 2] [--job-threads 1] [--only DESC ...]

A run folder's ``table.txt`` (written by :func:`yade_scripts.campaign.generate.generate`,
read as yade-batch reads it) has a header line, then one line per run with
a ``description`` column, an ``out`` column naming its dump and any scene
parameter as a column. :func:`table_lines` checks every line by name, type
and range (:mod:`yade_scripts.scene.parameters`) and says what is wrong with each
bad one in one line; :func:`read_table` refuses the table at its first bad
line. :func:`run_batch` runs the unfinished lines through the schedule of
:mod:`yade_scripts.launch.pool` (``jobs`` at a time, one thread each unless
``job_threads``, in table order), skipping complete dumps and resuming
checkpointed ones; each line's log is ``triaxial.py.<description>.log``.
"""
from __future__ import annotations

import argparse
import ast
import os
import shlex
import sys
from dataclasses import dataclass

from ..runs.runlock import RunBusy
from ..runs.runstate import EXIT_BUSY, EXIT_TERM
from ..scene.parameters import ConfigError, coerce
from .pool import Job, run_pool


@dataclass(frozen=True)
class TableLine:
    """One run line of a run folder's table (:func:`table_lines`).

    Parameters
    ----------
    number : int
        Its line in the file, from 1 with the header (what
        ``YADE_BATCH=table.txt:LINE`` names).
    task : int
        Its place among the run lines, from 1: its SLURM array task id.
    row : dict
        column -> the value's raw text (strings keep their quotes).
    error : str or None
        None, or one line naming the file, the line and the parameter that
        is wrong.

    Attributes
    ----------
    number : int
        As given.
    task : int
        As given.
    row : dict
        As given.
    error : str or None
        As given.
    description : str
        The ``description`` column (``line<number>`` without one).

    Examples
    --------
    >>> t = TableLine(2, 1, {"description": "spheres-seed1", "seed": "1", "out": "'spheres-seed1.h5'"})
    >>> t.description, t.error
    ('spheres-seed1', None)
    """
    number: int
    task: int
    row: dict
    error: str | None = None

    @property
    def description(self):
        """The ``description`` column, or ``line<number>`` when there is none."""
        return self.row.get("description", f"line{self.number}")


def table_lines(folder):
    """Every run line of a run folder's table, each checked.

    A line is checked for as many values as columns; every column but
    ``description`` a scene parameter (a misspelt one is named with the
    closest known one) and every value a Python literal of its type and
    range (yade-batch evaluates the values as Python); descriptions and
    dumps not repeated. A bad line does not stop the others: its
    ``error`` says what is wrong. Blank lines and lines starting with
    ``#`` are skipped.

    Parameters
    ----------
    folder : str
        The run folder, holding ``table.txt``.

    Returns
    -------
    list of TableLine
        In file order.

    Raises
    ------
    ConfigError
        One line, only when the table is missing or empty.

    Examples
    --------
    >>> import os, tempfile
    >>> d = tempfile.mkdtemp()
    >>> with open(os.path.join(d, "table.txt"), "w") as fh:
    ...     _ = fh.write("description kappa out\\n"
    ...                  "k300 300.0 'k300.h5'\\n"
    ...                  "k1e4 1e4 'k1e4.h5'\\n"
    ...                  "bad -5.0 'bad.h5'\\n")
    >>> lines = table_lines(d)
    >>> [(t.number, t.task, t.description) for t in lines]
    [(2, 1, 'k300'), (3, 2, 'k1e4'), (4, 3, 'bad')]
    >>> lines[2].error
    '.../table.txt line 4: kappa = -5.0 is outside [1, 1e+09]'
    """
    path = os.path.join(folder, "table.txt")
    try:
        with open(path) as fh:
            lines = fh.read().splitlines()
    except OSError as exc:
        raise ConfigError(f"{path}: cannot be read ({exc.strerror or exc})") from None
    if not lines or not lines[0].split():
        raise ConfigError(f"{path} is empty")
    head = lines[0].split()
    out, seen_desc, seen_dump = [], {}, {}
    for k, line in enumerate(lines[1:], start=2):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        try:
            vals = shlex.split(line, posix=False)
        except ValueError as exc:
            out.append(TableLine(k, len(out) + 1, {}, f"{path} line {k}: {exc}"))
            continue
        row = dict(zip(head, vals))
        error = None
        if len(vals) != len(head):
            error = f"{path} line {k}: {len(vals)} values for {len(head)} columns"
        else:
            for name, raw in row.items():
                if name == "description":
                    continue
                try:
                    value = ast.literal_eval(raw)
                except (ValueError, SyntaxError):
                    error = f"{path} line {k}: {name} = {raw} is not a Python literal"
                    break
                try:
                    coerce(name, value)
                except ConfigError as exc:
                    error = f"{path} line {k}: {exc}"
                    break
        if error is None:
            desc, dump = row.get("description"), dump_of(folder, row)
            if desc in seen_desc:
                error = f"{path} line {k}: description {desc} repeats line {seen_desc[desc]}"
            elif dump in seen_dump:
                error = f"{path} line {k}: out {os.path.basename(dump)} repeats line {seen_dump[dump]}"
            else:
                seen_desc[desc], seen_dump[dump] = k, k
        out.append(TableLine(k, len(out) + 1, row, error))
    return out


def read_table(folder):
    """The run lines of a run folder's table, refused at the first bad one
    (:func:`table_lines`), before any run starts.

    Parameters
    ----------
    folder : str
        The run folder, holding ``table.txt``.

    Returns
    -------
    list of (int, dict)
        (the line's number in the file, {column: raw text}) per run line.

    Raises
    ------
    ConfigError
        One line naming the first bad line and its problem, or a table
        that is missing or empty.

    Examples
    --------
    >>> import os, tempfile
    >>> d = tempfile.mkdtemp()
    >>> with open(os.path.join(d, "table.txt"), "w") as fh:
    ...     _ = fh.write("description seed out\\nspheres-seed1 1 'spheres-seed1.h5'\\n")
    >>> read_table(d)
    [(2, {'description': 'spheres-seed1', 'seed': '1', 'out': "'spheres-seed1.h5'"})]
    >>> with open(os.path.join(d, "table.txt"), "a") as fh:
    ...     _ = fh.write("spheres-seed2 1.5 'spheres-seed2.h5'\\n")
    >>> read_table(d)
    Traceback (most recent call last):
        ...
    yade_scripts.scene.parameters.ConfigError: .../table.txt line 3: seed = 1.5 is not an integer
    """
    rows = table_lines(folder)
    for t in rows:
        if t.error:
            raise ConfigError(t.error)
    return [(t.number, t.row) for t in rows]


def dump_of(folder, row):
    """The dump a table row writes.

    Parameters
    ----------
    folder : str
        The run folder.
    row : dict
        The row's {column: raw text}.

    Returns
    -------
    str
        ``folder`` joined with the row's ``out`` column, unquoted
        (``run.h5`` without one).

    Examples
    --------
    >>> dump_of("runs/t1", {"description": "spheres-seed1", "out": "'spheres-seed1.h5'"})
    'runs/t1/spheres-seed1.h5'
    """
    return os.path.join(folder, row.get("out", "'run.h5'").strip("'\""))


def run_batch(folder, jobs=2, tag="batch", echo=print, attempts=None, job_threads=1, only=None):
    """Run the unfinished lines of a run folder's table, ``jobs`` at a
    time in table order, through :func:`yade_scripts.launch.pool.run_pool`:
    complete dumps are not run again, a checkpointed line resumes, a
    crashed one is resumed as the pool's rule says. The table is checked
    first (:func:`read_table`): a bad line stops everything before any run
    starts.

    Parameters
    ----------
    folder : str
        A generated run folder (:func:`yade_scripts.campaign.generate.generate`).
    jobs : int
        Cores of the schedule (the runs at a time, on one thread each).
    tag : str
        In front of every message.
    echo : callable
        Takes each message (one line).
    attempts : dict, optional
        Receives {description: [exit status of each attempt]} for the
        lines run.
    job_threads : int
        YADE threads (``yade -jN``, the polyhedra kernel's OpenMP threads)
        of each job.
    only : list of str, optional
        The descriptions of the lines to run (default: all).

    Returns
    -------
    dict
        description -> status of :func:`yade_scripts.launch.pool.run_pool` for
        the lines asked for: 0 complete (now or already), else the exit
        code or the reason.

    Raises
    ------
    ConfigError
        A bad table line, a description of ``only`` the table lacks, or no
        ``yade`` on the PATH.
    yade_scripts.runs.runlock.RunBusy
        Another process writes one of the runs; nothing was touched.

    Examples
    --------
    A folder whose only line has a complete dump (here an empty one,
    closed by :class:`postproc.schema.DumpWriter`, standing in for a
    finished run): nothing is started, but ``yade`` must be on the PATH.

    >>> import os, tempfile
    >>> from postproc.schema import DumpWriter
    >>> from yade_scripts.campaign.generate import generate
    >>> out = os.path.join(tempfile.mkdtemp(), "t1")
    >>> _ = generate(out, "tiny", "spheres", seeds=[1])
    >>> DumpWriter(os.path.join(out, "spheres-seed1.h5"), "spheres", {}).close()
    >>> run_batch(out, tag="t1")
    [t1] spheres-seed1 already complete, not run again
    {'spheres-seed1': 0}
    >>> run_batch(out, only=["spheres-seed9"])
    Traceback (most recent call last):
        ...
    yade_scripts.scene.parameters.ConfigError: .../t1/table.txt has no line spheres-seed9
    """
    rows = read_table(folder)
    if only is not None:
        unknown = sorted(set(only) - {r["description"] for _, r in rows})
        if unknown:
            raise ConfigError(f"{folder}/table.txt has no line {', '.join(unknown)}")
        rows = [(k, r) for k, r in rows if r["description"] in only]
    pool = [Job(folder, k, r["description"], dump_of(folder, r), tag=tag, threads=job_threads) for k, r in rows]
    status = run_pool(pool, jobs, echo=echo)
    if attempts is not None:
        attempts.update({j.description: list(j.exits) for j in pool if j.exits})
    return status


def main(argv=None):
    """``python -m yade_scripts.launch.batch FOLDER [--jobs N] [--job-threads T]
    [--only DESC ...]``: :func:`run_batch` from the command line.

    Parameters
    ----------
    argv : list of str, optional
        The command line's arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit code: 0 every line asked for complete; 1 a line not
        finished (failed); 2 invalid options, folder or table; 4 another
        process writes a run; 75 stopped by SIGTERM or Ctrl-C (run the
        same command again to resume).
    """
    ap = argparse.ArgumentParser(prog="python -m yade_scripts.launch.batch",
                                 description="Run the unfinished lines of a run folder's table.txt.")
    ap.add_argument("folder")
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time (default 2)")
    ap.add_argument("--job-threads", type=int, default=1, help="YADE threads of each run (default 1)")
    ap.add_argument("--only", nargs="+", metavar="DESC", help="only the lines with these descriptions")
    args = ap.parse_args(argv)
    try:
        if args.jobs < 1 or args.job_threads < 1:
            raise ConfigError(f"--jobs and --job-threads must be >= 1, got {args.jobs} and {args.job_threads}")
        if not os.path.exists(os.path.join(args.folder, "triaxial.py")):
            raise ConfigError(f"{args.folder}: no triaxial.py (not a generated run folder)")
        status = run_batch(args.folder, args.jobs, tag=os.path.basename(os.path.abspath(args.folder)),
                           echo=lambda m: print(m, flush=True), job_threads=args.job_threads, only=args.only)
    except ConfigError as exc:
        print(f"batch: error: {exc}", file=sys.stderr)
        return 2
    except RunBusy as exc:
        print(f"batch: error: {exc}", file=sys.stderr)
        return EXIT_BUSY
    stopped = sorted(d for d, s in status.items() if s == "stopped")
    if stopped:
        print(f"batch: stopped (SIGTERM or Ctrl-C): {', '.join(stopped)} not finished, each run kept its "
              f"checkpoint; run the same command again to resume", file=sys.stderr)
        return EXIT_TERM
    bad = sorted(d for d, s in status.items() if s != 0)
    if bad:
        print(f"batch: not finished: {', '.join(bad)}", file=sys.stderr)
        return 1
    print(f"batch: every line of {args.folder}/table.txt is complete", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
