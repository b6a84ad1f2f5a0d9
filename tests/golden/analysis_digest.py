"""The digest of every number the study's analyses write for two committed
tiny dumps (S1 and S2 of tests/data/old-layout/old-layout.tar.gz), under the
analysis code on ``sys.path``.

    python tests/golden/analysis_digest.py [WORKDIR]

prints ``{"digest": ..., "numbers": N, "files": [...]}``. The analyses are
the study's: the primary one of each dump (``AnalysisOptions(errors=True)``,
no figures) and, of the S1 dump, the ``lmgc90`` and ``lmgc90-2009`` counts
on claim 6's snapshots (:func:`postproc.study.counts.analyse_counts`), whose
tables carry the alert distance halved and doubled (``*_lo``/``*_hi``). Only
stable public entry points are used, so the same script runs against the
code of an older commit (``PYTHONPATH=<its tree>``) to tell whether that
code computed the same numbers. Every number of every ``*.csv`` and
``*.json`` file (but source.json, the provenance) enters the digest as
``%.12g`` (12 significant digits: above round-off of sums in another
order, far below any change an analysis edit makes); text cells enter as
they are.
"""
import hashlib
import json
import math
import os
import sys
import tarfile
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TARBALL = os.path.join(HERE, "..", "data", "old-layout", "old-layout.tar.gz")
#: the dumps analysed: (member of the tarball, is it S1)
DUMPS = (("study/polyhedra-ensemble/polyhedra-seed1.h5", True),
         ("study/spheres-ensemble/spheres-seed1.h5", False))
#: the study's contact counts beside the primary one (every one it offers)
COUNTS = ("lmgc90", "lmgc90-2009")
#: significant digits of each number in the digest
DIGITS = 12


def _num(x):
    """A number's text in the digest: ``%.12g``, nan/inf by name."""
    x = float(x)
    return repr(x) if not math.isfinite(x) else f"{x:.{DIGITS}g}"


def _walk(value, out):
    """Every leaf of a JSON value, in order, into ``out`` (numbers by :func:`_num`)."""
    if isinstance(value, dict):
        for k in sorted(value):
            out.append(str(k))
            _walk(value[k], out)
    elif isinstance(value, list):
        for v in value:
            _walk(v, out)
    elif isinstance(value, bool) or value is None or isinstance(value, str):
        out.append(repr(value))
    else:
        out.append(_num(value))


def file_tokens(path):
    """The tokens of one output file: a CSV's header and every cell (numbers
    by :func:`_num`), a JSON file's leaves."""
    import pandas as pd

    out = []
    if path.endswith(".json"):
        with open(path) as fh:
            _walk(json.load(fh), out)
        return out
    df = pd.read_csv(path, dtype=str, keep_default_na=False)
    out += list(df.columns)
    for row in df.itertuples(index=False):
        for cell in row:
            try:
                out.append(_num(cell))
            except ValueError:
                out.append(cell)
    return out


def analyse(work):
    """Extract the dumps into ``work`` and analyse them as the study does;
    the analysis folders, in order."""
    from postproc.pipeline import AnalysisOptions, analyze_path
    from postproc.study.counts import analyse_counts

    with tarfile.open(TARBALL) as tar:
        for member, _ in DUMPS:
            tar.extract(member, work)
    folders = []
    for member, s1 in DUMPS:
        dump = os.path.join(work, member)
        analysis = os.path.join(os.path.dirname(dump), "analysis-" + os.path.basename(dump)[:-3])
        analyze_path(dump, analysis, AnalysisOptions(errors=True, figures=False), progress=False)
        folders.append(analysis)
        if s1:
            done, problems = analyse_counts(dump, analysis, counts=COUNTS)
            if problems:
                raise RuntimeError("; ".join(problems))
            folders += [done[c] for c in COUNTS]
    return folders


def digest(work):
    """{"digest": SHA-256 hex, "numbers": tokens hashed, "files": [relative
    paths]} of every output number of :func:`analyse` run in ``work``."""
    h, n, files = hashlib.sha256(), 0, []
    for folder in analyse(work):
        for name in sorted(os.listdir(folder)):
            if not name.endswith((".csv", ".json")) or name == "source.json":
                continue
            rel = os.path.relpath(os.path.join(folder, name), work)
            tokens = file_tokens(os.path.join(folder, name))
            h.update(f"{rel}\n".encode())
            h.update("\n".join(tokens).encode())
            n += len(tokens)
            files.append(rel)
    return {"digest": h.hexdigest(), "numbers": n, "files": files}


if __name__ == "__main__":
    work = sys.argv[1] if len(sys.argv) > 1 else tempfile.mkdtemp(prefix="golden-")
    print(json.dumps(digest(work)))
