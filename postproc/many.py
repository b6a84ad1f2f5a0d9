"""Many inputs at once: ``postproc analyze A B C|FOLDER --out DIR --jobs N``.

Each input is analysed by :func:`postproc.pipeline.analyze_path` in its own
process (N at a time) into ``DIR/<name>/``; then ``DIR/summary.csv`` holds
every snapshot row of every input that could be analysed, with a first
column ``source`` (the input path). A bad file is reported (stderr and
``DIR/errors.txt``) and skipped; the others finish.
"""
from __future__ import annotations

import os
import sys
from concurrent.futures import ProcessPoolExecutor

import pandas as pd

from .errors import InputError
from .lammpsdump import sniff
from .pipeline import BAD_INPUT, AnalysisOptions, analyze_path

#: file endings a folder is searched for (LAMMPS-style dumps are recognised
#: by their header, whatever their name)
KNOWN_EXT = (".h5", ".csv", ".parquet", ".pq")


def expand_inputs(paths):
    """Files to analyse: each path as given, a folder replaced by its dumps,
    tables and LAMMPS/LIGGGHTS local dumps (sorted; atom dumps and other
    files are left out). A missing path is kept, to be reported."""

    out = []
    for p in paths:
        if os.path.isdir(p):
            for name in sorted(os.listdir(p)):
                f = os.path.join(p, name)
                if os.path.isfile(f) and (name.lower().endswith(KNOWN_EXT) or sniff(f)):
                    out.append(f)
        else:
            out.append(p)
    return out


def output_names(files):
    """One folder name per input: its base name without extension, made
    unique with the parent folder's name (then a number) on clashes."""
    base = [os.path.splitext(os.path.basename(f))[0] or "input" for f in files]
    names = []
    for f, b in zip(files, base):
        n = b if base.count(b) == 1 else \
            f"{os.path.basename(os.path.dirname(os.path.abspath(f)))}_{b}"
        k, cand = 2, n
        while cand in names:
            cand, k = f"{n}_{k}", k + 1
        names.append(cand)
    return names


def _one(path, out, options):
    """Worker: (path, n_snapshots, bad snapshot lines, file error or None)."""
    try:
        n, problems = analyze_path(path, out, options, progress=False)
        return path, n, problems, None
    except BAD_INPUT as exc:
        return path, 0, [], str(exc) if str(exc).startswith(path) else f"{path}: {exc}"
    except Exception as exc:  # a bug must not cost the other files their results
        return path, 0, [], f"{path}: unexpected {type(exc).__name__}: {exc}"


def analyze_many(paths, out, jobs=1, options=AnalysisOptions()):
    """Analyse every input into ``out/<name>/`` with ``jobs`` processes and
    write the combined ``out/summary.csv`` (column ``source`` first), each
    with the same :class:`postproc.pipeline.AnalysisOptions`. Returns
    (number of files analysed, list of one-line errors: bad files and bad
    snapshots)."""

    files = expand_inputs(paths)
    if not files:
        raise InputError("no input files (an empty folder?)")
    if jobs < 1:
        raise InputError(f"--jobs must be at least 1, got {jobs}")
    names = output_names(files)
    os.makedirs(out, exist_ok=True)
    tasks = [(f, os.path.join(out, n), options) for f, n in zip(files, names)]
    if jobs == 1 or len(files) == 1:
        results = [_one(*t) for t in tasks]
    else:
        with ProcessPoolExecutor(max_workers=min(jobs, len(files))) as pool:
            results = list(pool.map(_one, *zip(*tasks)))
    frames, errors, done = [], [], 0
    for (path, n, problems, fail), name in zip(results, names):
        if fail is not None:
            errors.append(fail)
            print(f"postproc: error: {fail} (skipped)", file=sys.stderr)
            continue
        done += 1
        errors += [f"{path}: {p}" for p in problems]
        df = pd.read_csv(os.path.join(out, name, "summary.csv"))
        df = pd.concat([pd.Series(path, index=df.index, name="source"), df], axis=1)
        frames.append(df)
    if not frames:
        raise InputError("no input could be analysed: " + "; ".join(errors[:3]))
    tmp = os.path.join(out, ".summary.csv.tmp")
    pd.concat(frames, ignore_index=True, sort=False).to_csv(tmp, index=False)
    os.replace(tmp, os.path.join(out, "summary.csv"))
    stale = os.path.join(out, "errors.txt")
    if errors:
        with open(stale, "w") as fh:
            fh.write("\n".join(errors) + "\n")
    elif os.path.exists(stale):
        os.remove(stale)
    return done, errors
